/*
 * stb_guard.c - an image's bytes looked at as the stb_image mote links will
 * read them, before it reads them: the guard of the system stb_image.
 *
 * Debian 12's libstb is stb_image 2.27 with upstream fixes to September
 * 2022. It has known faults that a crafted texture reaches through the two
 * calls mote makes (stbi_info_from_memory, then stbi_load_from_memory with 4
 * channels): a JPEG Huffman table of more than 256 codes overruns its arrays
 * (CVE-2022-28042), JPEG DC sums overflow (CVE-2022-28041), and JPEG, PNG,
 * BMP, TGA and PNM files can make it return pixels it never wrote, heap or
 * stack memory of the process (CVE-2023-45663 and its kin). mote cannot
 * patch the library, so each construct is found here and the image refused,
 * or, for the palettes stb_image reads past, padded with black in a copy.
 * docs/security.md ("Image decoding") lists what is handled and what is not.
 *
 * Each check follows stb_image's own reading of the bytes (which format it
 * takes a file for, where its reader stands), so that what is checked is
 * what stb_image will meet. Where stb_image will fail on its own before the
 * construct matters, the image is left to it, so its messages stay as they
 * were.
 */
#include "stb_guard.h"

#include <limits.h>
#include <stdint.h>
#include <string.h>

/* ---- which decoder stb_image will pick --------------------------------- */

/* stb_image's TGA test: no magic number, so a run of header fields. */
static bool mote__is_tga(const unsigned char *d, size_t n)
{
    unsigned cmap = mote__byte_at(d, n, 1), type = mote__byte_at(d, n, 2);
    if (cmap > 1)
        return false;
    if (cmap == 1) {
        unsigned bits = mote__byte_at(d, n, 7);
        if ((type != 1 && type != 9) ||
            (bits != 8 && bits != 15 && bits != 16 && bits != 24 && bits != 32))
            return false;
    } else if (type != 2 && type != 3 && type != 10 && type != 11) {
        return false;
    }
    unsigned bpp = mote__byte_at(d, n, 16);
    if (mote__le16(d, n, 12) < 1 || mote__le16(d, n, 14) < 1)
        return false;
    if (cmap == 1 && bpp != 8 && bpp != 16)
        return false;
    return bpp == 8 || bpp == 15 || bpp == 16 || bpp == 24 || bpp == 32;
}

mote__image_format mote__stb_image_format(const unsigned char *d, size_t n)
{
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (n >= 8 && memcmp(d, png, 8) == 0)
        return MOTE__IMAGE_PNG;
    if (mote__byte_at(d, n, 0) == 'B' && mote__byte_at(d, n, 1) == 'M') {
        uint32_t hsz = mote__le32(d, n, 14);
        if (hsz == 12 || hsz == 40 || hsz == 56 || hsz == 108 || hsz == 124)
            return MOTE__IMAGE_BMP;
    }
    if (n >= 6 && memcmp(d, "GIF8", 4) == 0 && (d[4] == '7' || d[4] == '9') && d[5] == 'a')
        return MOTE__IMAGE_GIF;
    if (n >= 4 && memcmp(d, "8BPS", 4) == 0)
        return MOTE__IMAGE_PSD;
    if (n >= 92 && memcmp(d, "\x53\x80\xF6\x34", 4) == 0 && memcmp(d + 88, "PICT", 4) == 0)
        return MOTE__IMAGE_PIC;
    if (mote__byte_at(d, n, 0) == 0xff) {
        size_t i = 1;
        while (i < n && d[i] == 0xff)
            i++;
        if (mote__byte_at(d, n, i) == 0xd8)
            return MOTE__IMAGE_JPEG;
    }
    if (mote__byte_at(d, n, 0) == 'P' &&
        (mote__byte_at(d, n, 1) == '5' || mote__byte_at(d, n, 1) == '6'))
        return MOTE__IMAGE_PNM;
    if ((n >= 11 && memcmp(d, "#?RADIANCE\n", 11) == 0) || (n >= 7 && memcmp(d, "#?RGBE\n", 7) == 0))
        return MOTE__IMAGE_HDR; /* refused by texture.c */
    return mote__is_tga(d, n) ? MOTE__IMAGE_TGA : MOTE__IMAGE_NONE;
}

bool mote__huffman_canonical(const uint16_t *count, int max, uint32_t *first, int *offset)
{
    uint32_t code = 0;
    int k = 0;
    for (int len = 1; len <= max; len++) {
        first[len] = code;
        offset[len] = k;
        code += count[len];
        k += count[len];
        if (count[len] && code - 1 >= (1u << len))
            return false;
        code <<= 1;
    }
    return true;
}

/* ---- BMP ---------------------------------------------------------------- */

/* stb_image's BMP loader keeps the palette in an uninitialised stack array
 * too: it fills the entries between the header and the pixel offset and
 * looks every index up (nothings/stb#1929, open), and it takes an offset
 * inside the header for a palette of a negative number of entries, so that
 * none is filled. The first is padded with black entries in a copy, the
 * second refused. */
static mote_result mote__guard_bmp(const unsigned char *d, size_t n, unsigned char **fixed,
                                   size_t *fixed_size, char *message, size_t message_size)
{
    uint32_t offset = mote__le32(d, n, 10), hsz = mote__le32(d, n, 14);
    size_t at = hsz == 12 ? 24 : 28;
    if ((hsz == 12 ? mote__le16(d, n, 22) : mote__le16(d, n, 26)) != 1)
        return MOTE_OK; /* stb_image: "bad BMP" */
    uint32_t bpp = mote__le16(d, n, at);
    /* stb_image refuses compression 1, 2 and 4 up, and 3 (bitfields) below
     * 16 bits a pixel; it reads a negative one (as an int) as none */
    if (hsz != 12 && (int32_t)mote__le32(d, n, 30) > 0)
        return MOTE_OK;
    if (bpp != 1 && bpp != 4 && bpp != 8)
        return MOTE_OK;
    if (offset > INT_MAX)
        return MOTE_OK; /* a negative offset: stb_image fails */
    /* stb_image's palette size: (offset - 38) / 3 entries of 3 bytes for
     * the 12-byte header (sic), (offset - 14 - hsz) / 4 of 4 bytes else */
    size_t entry = hsz == 12 ? 3 : 4, before = hsz == 12 ? 38 : 14 + hsz;
    if (offset < before + entry) {
        if (offset >= before || (hsz == 12 && offset + 2 >= before))
            return MOTE_OK; /* no entry: stb_image fails ("invalid") */
        return mote__io_error(message, message_size, MOTE_ERR_PARSE,
                              "texture: corrupt BMP: its pixels start at byte %lu, inside its "
                              "%lu-byte header (stb_image would read an uninitialised palette)",
                              (unsigned long)offset, (unsigned long)(14 + hsz));
    }
    size_t entries = (offset - before) / entry;
    if (entries > 256 || entries >= (1u << bpp))
        return MOTE_OK;
    size_t where = 14 + hsz + entries * entry, add = ((1u << bpp) - entries) * entry;
    if (where > n)
        return MOTE_OK; /* the pixels are past the end: stb_image reads index 0 */
    unsigned char *out = mote__io_malloc(n + add);
    if (!out)
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "texture: out of memory padding a BMP palette");
    memcpy(out, d, where);
    memset(out + where, 0, add);
    memcpy(out + where + add, d + where, n - where);
    uint32_t moved = offset + (uint32_t)add;
    for (int k = 0; k < 4; k++)
        out[10 + k] = (unsigned char)(moved >> (8 * k));
    *fixed = out;
    *fixed_size = n + add;
    return MOTE_OK;
}

/* ---- TGA and PNM -------------------------------------------------------- */

/* stb_image reads an uncompressed, unpaletted TGA's rows with stbi__getn
 * and does not look at its result: rows past the end of the file are
 * malloc'd memory as it was (CVE-2023-45663). */
static mote_result mote__guard_tga(const unsigned char *d, size_t n, char *message,
                                   size_t message_size)
{
    unsigned indexed = d[1], type = d[2], bpp = mote__byte_at(d, n, 16);
    if (indexed || (type != 2 && type != 3))
        return MOTE_OK; /* palette and run-length data go through stb_image's get8 */
    unsigned comp = bpp == 8 ? 1 : bpp == 16 && type == 3 ? 2 : bpp == 24 ? 3 : bpp == 32 ? 4 : 0;
    if (!comp)
        return MOTE_OK; /* 15/16-bit colour: read pixel by pixel too */
    size_t need = 18 + (size_t)d[0] + (size_t)mote__le16(d, n, 12) * mote__le16(d, n, 14) * comp;
    if (n >= need)
        return MOTE_OK;
    return mote__io_error(message, message_size, MOTE_ERR_PARSE,
                          "texture: truncated TGA: %zu bytes where its header needs %zu "
                          "(stb_image would show uninitialised memory, CVE-2023-45663)", n, need);
}

/* stb_image's PNM reader: the header's numbers (which it accumulates in an
 * int that overflows, oss-fuzz 22620) and then the pixels, read with
 * stbi__getn unchecked as for TGA. */
static mote_result mote__guard_pnm(const unsigned char *d, size_t n, char *message,
                                   size_t message_size)
{
    mote__src s = {d, n, 2};
    unsigned c = mote__get8(&s);
    unsigned long v[3];
    for (int k = 0; k < 3; k++) {
        for (;;) { /* white space and # comments, as stb_image skips them */
            while (s.pos < n && (c == ' ' || (c >= '\t' && c <= '\r')))
                c = mote__get8(&s);
            if (s.pos >= n || c != '#')
                break;
            while (s.pos < n && c != '\n' && c != '\r')
                c = mote__get8(&s);
        }
        v[k] = 0;
        while (s.pos < n && c >= '0' && c <= '9') {
            if (v[k] > (unsigned long)(INT_MAX - (int)(c - '0')) / 10)
                return mote__io_error(message, message_size, MOTE_ERR_PARSE,
                                      "texture: corrupt PNM: a header number over %d (stb_image "
                                      "reads it into an int that overflows)", INT_MAX);
            v[k] = v[k] * 10 + (c - '0');
            c = mote__get8(&s);
        }
    }
    if (v[2] > 255 || v[0] > 1u << 24 || v[1] > 1u << 24)
        return MOTE_OK; /* 16-bit: texture.c refuses it; the rest stb_image does */
    size_t need = (size_t)v[0] * v[1] * (d[1] == '6' ? 3 : 1);
    if (n - s.pos >= need)
        return MOTE_OK;
    return mote__io_error(message, message_size, MOTE_ERR_PARSE,
                          "texture: truncated PNM: %zu bytes of pixels where its header needs "
                          "%zu (stb_image would show uninitialised memory)", n - s.pos, need);
}

mote_result mote__stb_guard(const unsigned char *data, size_t size, const mote_limits *limits,
                            unsigned char **fixed, size_t *fixed_size, char *message,
                            size_t message_size)
{
    *fixed = NULL;
    *fixed_size = 0;
    switch (mote__stb_image_format(data, size)) {
    case MOTE__IMAGE_JPEG:
        return mote__stb_guard_jpeg(data, size, limits, message, message_size);
    case MOTE__IMAGE_PNG:
        return mote__stb_guard_png(data, size, fixed, fixed_size, message, message_size);
    case MOTE__IMAGE_BMP:
        return mote__guard_bmp(data, size, fixed, fixed_size, message, message_size);
    case MOTE__IMAGE_TGA:
        return mote__guard_tga(data, size, message, message_size);
    case MOTE__IMAGE_PNM:
        return mote__guard_pnm(data, size, message, message_size);
    default:
        return MOTE_OK;
    }
}
