/*
 * texture.c - images to RGBA8888 textures through stb_image (the
 * implementation comes from Debian's libstb). The bytes are first checked
 * for the constructs that reach that stb_image's known faults
 * (stb_guard.c); the header is then read with stbi_info_from_memory so
 * that a file claiming 100000 x 100000 pixels is refused before anything is
 * decoded. Images embedded in scene files as
 * base64 data: URLs (Babylon.js's SceneSerializer) are decoded here too and
 * go through the same checks, and so are the textures a scene gathers
 * (mote__texture_set: one decode per file, a limit on all together).
 */
#include "io_internal.h"

#include <limits.h>
#include <stdint.h>
#include <string.h>

#include <stb_image.h>

/* PNG width and height straight from the IHDR chunk: stb_image refuses to
 * even describe images over 2^30 bytes, and such a header deserves a limit
 * error rather than "unknown image type". */
static bool mote__png_size(const unsigned char *d, size_t size, uint32_t *w, uint32_t *h)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size < 24 || memcmp(d, sig, 8) != 0 || memcmp(d + 12, "IHDR", 4) != 0)
        return false;
    *w = (uint32_t)d[16] << 24 | (uint32_t)d[17] << 16 | (uint32_t)d[18] << 8 | d[19];
    *h = (uint32_t)d[20] << 24 | (uint32_t)d[21] << 16 | (uint32_t)d[22] << 8 | d[23];
    return true;
}

static mote_result mote__texture_decode(const unsigned char *d, size_t size,
                                        const mote_limits *limits, size_t budget,
                                        mote_texture *out, char *message, size_t message_size);

/* mote_texture_load_memory with the limits filled in, and the image
 * refused from its header when its decoded bytes are over budget (what is
 * left of a scene's max_total_texture_bytes). */
static mote_result mote__texture_load_within(const void *data, size_t size,
                                             const mote_limits *lim, size_t budget,
                                             mote_texture *out, char *message,
                                             size_t message_size)
{
    memset(out, 0, sizeof *out);
    if (size == 0)
        return mote__io_error(message, message_size, MOTE_ERR_PARSE, "texture: empty image");
    if (size > (size_t)INT_MAX)
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                              "texture: %zu bytes is more than stb_image can read", size);
    uint32_t pw, ph;
    if (mote__png_size(data, size, &pw, &ph) &&
        (pw > (uint32_t)lim->max_texture_width || ph > (uint32_t)lim->max_texture_height))
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                              "texture: %lu x %lu is larger than the limit of %d x %d",
                              (unsigned long)pw, (unsigned long)ph, lim->max_texture_width,
                              lim->max_texture_height);
    /* over budget, the screen passes the image by as over the limits,
     * for the decode to refuse it by its size */
    mote_limits screened = *lim;
    if (budget < screened.max_texture_bytes)
        screened.max_texture_bytes = budget;
    unsigned char *fixed = NULL;
    size_t fixed_size = 0;
    mote_result r = mote__stb_guard(data, size, &screened, &fixed, &fixed_size, message,
                                         message_size);
    if (r != MOTE_OK)
        return r;
    if (fixed && fixed_size > (size_t)INT_MAX)
        r = mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                           "texture: %zu bytes is more than stb_image can read", fixed_size);
    else
        r = mote__texture_decode(fixed ? fixed : data, fixed ? fixed_size : size, lim, budget,
                                 out, message, message_size);
    mote__io_free(fixed);
    return r;
}

mote_result mote_texture_load_memory(const void *data, size_t size,
                                     const mote_limits *limits, mote_texture *out,
                                     char *message, size_t message_size)
{
    if (!out)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "texture: no output texture given");
    memset(out, 0, sizeof *out);
    if (!data && size > 0)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "texture: no data given");
    mote_limits lim = mote__io_limits(limits);
    return mote__texture_load_within(data, size, &lim, SIZE_MAX, out, message, message_size);
}

bool mote__texture_over_limits(const mote_limits *limits, size_t w, size_t h)
{
    return w > (size_t)limits->max_texture_width || h > (size_t)limits->max_texture_height ||
           (h > 0 && w > limits->max_texture_bytes / 4 / h);
}

/* The decode proper, once mote__stb_guard has passed the bytes. Its size
 * checks refuse whatever mote__texture_over_limits says is over (the
 * guard counts on it). */
static mote_result mote__texture_decode(const unsigned char *d, size_t size,
                                        const mote_limits *limits, size_t budget,
                                        mote_texture *out, char *message, size_t message_size)
{
    const mote_limits lim = *limits;
    /* Two of stb_image's decoders are refused before they see the bytes,
     * as the libstb mote links (Debian's, stb_image 2.27) has their known
     * faults: its Radiance HDR decoder loops for ever on a truncated
     * run-length scanline (CVE-2021-42715), and its PNM decoder reads past
     * its buffer on a 16-bit PGM or PPM (CVE-2021-42716). Neither is a
     * format exporters give a diffuse texture; 8-bit PNM still loads. */
    if (stbi_is_hdr_from_memory(d, (int)size))
        return mote__io_error(message, message_size, MOTE_ERR_UNSUPPORTED,
                              "texture: a Radiance HDR image, which mote does not read");
    if (size >= 2 && d[0] == 'P' && (d[1] == '5' || d[1] == '6') &&
        stbi_is_16_bit_from_memory(d, (int)size))
        return mote__io_error(message, message_size, MOTE_ERR_UNSUPPORTED,
                              "texture: a 16-bit PNM image, which mote does not read (8-bit "
                              "ones it does)");
    int w = 0, h = 0, comp = 0;
    if (!stbi_info_from_memory(d, (int)size, &w, &h, &comp))
        return mote__io_error(message, message_size, MOTE_ERR_PARSE,
                              "texture: not a readable image (%s)", stbi_failure_reason());
    if (w <= 0 || h <= 0)
        return mote__io_error(message, message_size, MOTE_ERR_PARSE,
                              "texture: image has no pixels (%d x %d)", w, h);
    if (w > lim.max_texture_width || h > lim.max_texture_height)
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                              "texture: %d x %d is larger than the limit of %d x %d", w, h,
                              lim.max_texture_width, lim.max_texture_height);
    if ((size_t)w > SIZE_MAX / 4 / (size_t)h || (size_t)w * 4 > (size_t)INT_MAX)
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                              "texture: %d x %d overflows the size of a buffer", w, h);
    size_t bytes = (size_t)w * (size_t)h * 4;
    if (bytes > lim.max_texture_bytes)
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                              "texture: %d x %d needs %zu bytes, more than the limit of %zu",
                              w, h, bytes, lim.max_texture_bytes);
    if (bytes > budget)
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                              "texture: %d x %d needs %zu bytes, more than the %zu left of the "
                              "limit of %zu on all of a scene's textures", w, h, bytes, budget,
                              lim.max_total_texture_bytes);
    /* stb_image sizes its 16-bit conversions (16-bit PNG and PSD to 8 bits,
     * 1-3 channels to 4) in int or unsigned arithmetic it does not check:
     * past 2^28 pixels the buffer wraps small and it writes past it (upstream
     * issues #1860, #1936, open). Whatever the limits say, 8 bytes a pixel
     * must fit an int. */
    if ((size_t)w * (size_t)h > (size_t)INT_MAX / 8)
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                              "texture: %d x %d is more pixels than stb_image converts safely "
                              "(%d)", w, h, INT_MAX / 8);
    if (mote__io_should_fail())
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "texture: out of memory decoding %d x %d", w, h);
    int dw = 0, dh = 0, dc = 0;
    stbi_uc *pixels = stbi_load_from_memory(d, (int)size, &dw, &dh, &dc, 4);
    if (!pixels) {
        const char *why = stbi_failure_reason();
        bool oom = why && strstr(why, "outofmem") != NULL;
        return mote__io_error(message, message_size,
                              oom ? MOTE_ERR_OUT_OF_MEMORY : MOTE_ERR_PARSE,
                              "texture: cannot decode the image (%s)", why ? why : "unknown");
    }
    if (dw != w || dh != h) {
        /* the header and the decoder disagree: do not trust either */
        stbi_image_free(pixels);
        return mote__io_error(message, message_size, MOTE_ERR_PARSE,
                              "texture: decoded %d x %d but the header says %d x %d", dw,
                              dh, w, h);
    }
    mote__io_track(1);
    out->width = w;
    out->height = h;
    out->format = MOTE_FORMAT_RGBA8888;
    out->stride = w * 4;
    out->pixels = pixels;
    return MOTE_OK;
}

/* "texture: why" -> "why": callers put their own place in front. */
static const char *mote__why(const char *inner)
{
    return strncmp(inner, "texture: ", 9) == 0 ? inner + 9 : inner;
}

/* Reads an open file and decodes it within budget; the message starts
 * with the file's name. */
static mote_result mote__texture_read(mote__io_file *file, const mote_limits *lim, size_t budget,
                                      mote_texture *out, char *message, size_t message_size)
{
    char *data = NULL;
    size_t size = 0;
    mote_result r = mote__io_read_open(file, lim->max_file_bytes, &data, &size, message,
                                       message_size);
    if (r != MOTE_OK)
        return r;
    char inner[256];
    r = mote__texture_load_within(data, size, lim, budget, out, inner, sizeof inner);
    mote__io_free(data);
    if (r != MOTE_OK)
        mote__io_error(message, message_size, r, "%s: %s", file->name, mote__why(inner));
    return r;
}

mote_result mote_texture_load(const char *path, const mote_limits *limits,
                              mote_texture *out, char *message, size_t message_size)
{
    if (!out || !path)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "texture: no path or no output texture given");
    memset(out, 0, sizeof *out);
    mote_limits lim = mote__io_limits(limits);
    mote__io_file file;
    mote_result r = mote__io_open(path, &file, message, message_size);
    if (r != MOTE_OK)
        return r;
    return mote__texture_read(&file, &lim, SIZE_MAX, out, message, message_size);
}

/* ---- embedded images (data: URLs) ------------------------------------ */

/* The value of one base64 character, or -1. */
static int mote__b64_value(unsigned char c)
{
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

bool mote__io_base64_decode(const char *in, size_t len, unsigned char *out, size_t *out_len,
                             size_t *bad)
{
    size_t pad = 0;
    while (pad < 2 && len > pad && in[len - 1 - pad] == '=')
        pad++;
    if (pad && len % 4) {
        *bad = len - pad;       /* padding that does not end a group */
        return false;
    }
    size_t n = len - pad;
    if (n % 4 == 1) {
        *bad = n - 1;           /* 6 bits cannot make a byte */
        return false;
    }
    size_t o = 0;
    uint32_t acc = 0;
    for (size_t i = 0; i < n; i++) {
        int v = mote__b64_value((unsigned char)in[i]);
        if (v < 0) {
            *bad = i;
            return false;
        }
        acc = acc << 6 | (uint32_t)v;
        if (i % 4 == 3) {
            out[o++] = (unsigned char)(acc >> 16);
            out[o++] = (unsigned char)(acc >> 8);
            out[o++] = (unsigned char)acc;
            acc = 0;
        }
    }
    if (n % 4 == 2) {
        out[o++] = (unsigned char)(acc >> 4);
    } else if (n % 4 == 3) {
        out[o++] = (unsigned char)(acc >> 10);
        out[o++] = (unsigned char)(acc >> 2);
    }
    *out_len = o;
    return true;
}

bool mote__io_is_data_url(const char *s)
{
    static const char prefix[] = "data:";
    for (size_t i = 0; i < sizeof prefix - 1; i++)
        if (!s[i] || (s[i] | 0x20) != prefix[i])
            return false;
    return true;
}

/* mote__io_texture_load_data_url within budget (see mote__texture_load_within). */
static mote_result mote__data_url_load(const char *url, const mote_limits *limits, size_t budget,
                                       mote_texture *out, char *message, size_t message_size)
{
    memset(out, 0, sizeof *out);
    mote_limits lim = mote__io_limits(limits);
    /* data:[<media type>][;base64],<data>: only base64 carries an image */
    const char *comma = mote__io_is_data_url(url) ? strchr(url, ',') : NULL;
    if (!comma)
        return mote__io_error(message, message_size, MOTE_ERR_PARSE,
                              "not a data: URL (expected \"data:image/...;base64,...\")");
    size_t head = (size_t)(comma - url);
    if (head < 12 || strncmp(comma - 7, ";base64", 7) != 0)
        return mote__io_error(message, message_size, MOTE_ERR_PARSE,
                              "a data: URL without \";base64\" (only base64 images are read)");
    const char *b64 = comma + 1;
    size_t len = strlen(b64);
    /* decoded, the image counts against the limit on files, as a texture
     * file would; checked before anything is allocated */
    size_t cap = len / 4 * 3 + 2;
    if (cap - 2 > lim.max_file_bytes)
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                              "an embedded image of about %zu bytes, more than the limit of %zu",
                              cap - 2, lim.max_file_bytes);
    unsigned char *data = mote__io_malloc(cap);
    if (!data)
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "out of memory decoding an embedded image of %zu characters", len);
    size_t size = 0, bad = 0;
    mote_result r;
    if (!mote__io_base64_decode(b64, len, data, &size, &bad)) {
        unsigned char c = bad < len ? (unsigned char)b64[bad] : 0;
        r = mote__io_error(message, message_size, MOTE_ERR_PARSE,
                           "invalid base64 at character %zu of %zu (0x%02x)", bad, len, c);
    } else {
        char inner[256];
        r = mote__texture_load_within(data, size, &lim, budget, out, inner, sizeof inner);
        if (r != MOTE_OK)
            mote__io_error(message, message_size, r, "embedded image: %s", mote__why(inner));
    }
    mote__io_free(data);
    return r;
}

mote_result mote__io_texture_load_data_url(const char *url, const mote_limits *limits,
                                           mote_texture *out, char *message,
                                           size_t message_size)
{
    return mote__data_url_load(url, limits, SIZE_MAX, out, message, message_size);
}

/* ---- the textures of a scene ------------------------------------------- */

/* Adds the texture set->textures[set->count], just decoded, to the set. */
static void mote__set_add(mote__texture_set *set, mote__io_file_id file, const char *url,
                          int *index)
{
    const mote_texture *t = &set->textures[set->count];
    set->files[set->count] = file;
    set->urls[set->count] = url;
    set->bytes += (size_t)t->stride * (size_t)t->height;
    *index = set->count++;
}

static mote_result mote__set_full(const mote__texture_set *set, char *message,
                                  size_t message_size)
{
    return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                          "more than %d textures, one per material", set->cap);
}

/* What is left of limits->max_total_texture_bytes. */
static size_t mote__set_budget(const mote__texture_set *set, const mote_limits *lim)
{
    return set->bytes < lim->max_total_texture_bytes ? lim->max_total_texture_bytes - set->bytes
                                                      : 0;
}

mote_result mote__texture_set_file(mote__texture_set *set, const char *folder, const char *name,
                                   const mote_limits *limits, int *index, char *message,
                                   size_t message_size)
{
    *index = -1;
    mote_limits lim = mote__io_limits(limits);
    mote__io_file file;
    mote_result r = mote__io_open_in_folder(folder, name, lim.allow_any_texture_path, &file,
                                            message, message_size);
    if (r != MOTE_OK)
        return r;
    for (int i = 0; i < set->count; i++)
        if (mote__io_same_file(set->files[i], file.id)) {
            mote__io_close(&file);
            *index = i;
            return MOTE_OK;
        }
    if (set->count >= set->cap) {
        mote__io_close(&file);
        return mote__set_full(set, message, message_size);
    }
    r = mote__texture_read(&file, &lim, mote__set_budget(set, &lim), &set->textures[set->count],
                           message, message_size);
    if (r == MOTE_OK)
        mote__set_add(set, file.id, NULL, index);
    return r;
}

mote_result mote__texture_set_data_url(mote__texture_set *set, const char *url,
                                       const mote_limits *limits, int *index, char *message,
                                       size_t message_size)
{
    *index = -1;
    for (int i = 0; i < set->count; i++)
        if (set->urls[i] && strcmp(set->urls[i], url) == 0) {
            *index = i;
            return MOTE_OK;
        }
    if (set->count >= set->cap)
        return mote__set_full(set, message, message_size);
    mote_limits lim = mote__io_limits(limits);
    const mote__io_file_id none = {0, 0};
    mote_result r = mote__data_url_load(url, &lim, mote__set_budget(set, &lim),
                                        &set->textures[set->count], message, message_size);
    if (r == MOTE_OK)
        mote__set_add(set, none, url, index);
    return r;
}

mote_result mote__texture_set_memory(mote__texture_set *set, const void *data, size_t size,
                                     const mote_limits *limits, int *index, char *message,
                                     size_t message_size)
{
    *index = -1;
    if (set->count >= set->cap)
        return mote__set_full(set, message, message_size);
    mote_limits lim = mote__io_limits(limits);
    const mote__io_file_id none = {0, 0};
    char inner[256];
    mote_result r = mote__texture_load_within(data, size, &lim, mote__set_budget(set, &lim),
                                              &set->textures[set->count], inner, sizeof inner);
    if (r != MOTE_OK)
        return mote__io_error(message, message_size, r, "embedded image: %s", mote__why(inner));
    mote__set_add(set, none, NULL, index);
    return MOTE_OK;
}

void mote_texture_free(mote_texture *texture)
{
    if (!texture)
        return;
    if (texture->pixels) {
        stbi_image_free((void *)(uintptr_t)texture->pixels);
        mote__io_track(-1);
    }
    memset(texture, 0, sizeof *texture);
}
