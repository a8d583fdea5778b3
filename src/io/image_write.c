/*
 * image_write.c - PNG (stb_image_write, implementation from libstb) and
 * binary PPM (P6, written here) from an RGBA8888 buffer or from a device's
 * colour buffer in any format, written as file.c writes (a new file
 * renamed over the target).
 */
#include "io_internal.h"

#include <errno.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <stb_image_write.h>

typedef enum { MOTE__IMG_PNG, MOTE__IMG_PPM } mote__img_kind;

static mote_result mote__write_ppm_rgba(const char *path, const uint8_t *rgba, int width,
                                        int height, int stride, char *message,
                                        size_t message_size)
{
    char name[160];
    mote__io_clean_name(name, sizeof name, path);
    uint8_t *row = mote__io_malloc((size_t)width * 3);
    if (!row)
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "%s: out of memory", name);
    mote__io_output out;
    mote_result r = mote__io_output_open(path, &out, message, message_size);
    if (r != MOTE_OK) {
        mote__io_free(row);
        return r;
    }
    FILE *f = out.stream;
    bool ok = fprintf(f, "P6\n%d %d\n255\n", width, height) > 0;
    for (int y = 0; ok && y < height; y++) {
        const uint8_t *src = rgba + (size_t)y * (size_t)stride;
        for (int x = 0; x < width; x++)
            memcpy(row + (size_t)x * 3, src + (size_t)x * 4, 3);
        ok = fwrite(row, 3, (size_t)width, f) == (size_t)width;
    }
    mote__io_free(row);
    return mote__io_output_close(&out, ok, path, message, message_size);
}

/* stb_image_write hands the encoded PNG to this: written here, so that a
 * short write is seen (stbi_write_png ignores fwrite's result and reports
 * success on a full disk). */
typedef struct mote__png_sink {
    FILE *f;
    bool ok;
} mote__png_sink;

static void mote__png_write(void *context, void *data, int size)
{
    mote__png_sink *sink = context;
    if (sink->ok && size > 0)
        sink->ok = fwrite(data, 1, (size_t)size, sink->f) == (size_t)size;
}

static mote_result mote__write_png_rgba(const char *path, const uint8_t *rgba, int width,
                                        int height, int stride, char *message,
                                        size_t message_size)
{
    char name[160];
    mote__io_clean_name(name, sizeof name, path);
    /* stb_image_write sizes its filter buffer as the int (width * 4 + 1)
     * * height: past INT_MAX that wraps, and it writes past the end */
    if ((size_t)width * 4 + 1 > (size_t)INT_MAX / (size_t)height)
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                              "%s: %d x %d is too large for a PNG written by stb_image_write "
                              "(2 GiB of rows at the most)", name, width, height);
    mote__io_output out;
    mote_result r = mote__io_output_open(path, &out, message, message_size);
    if (r != MOTE_OK)
        return r;
    mote__png_sink sink = {out.stream, true};
    if (!stbi_write_png_to_func(mote__png_write, &sink, width, height, 4, rgba, stride)) {
        mote__io_output_discard(&out);    /* nothing was written */
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "%s: out of memory encoding the PNG", name);
    }
    return mote__io_output_close(&out, sink.ok, path, message, message_size);
}

static mote_result mote__write_rgba_as(mote__img_kind kind, const char *path,
                                       const uint8_t *rgba, int width, int height,
                                       int stride, char *message, size_t message_size)
{
    if (!path || !rgba || width <= 0 || height <= 0)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "write image: no path, no pixels or an empty size (%d x %d)",
                              width, height);
    if (width > INT32_MAX / 4)
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                              "write image: width %d is too large", width);
    if (stride == 0)
        stride = width * 4;
    if (stride < width * 4)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "write image: stride %d is less than width * 4", stride);
    if (kind == MOTE__IMG_PPM)
        return mote__write_ppm_rgba(path, rgba, width, height, stride, message, message_size);
    return mote__write_png_rgba(path, rgba, width, height, stride, message, message_size);
}

static int mote__kind_of(const char *path)
{
    size_t n = path ? strlen(path) : 0;
    if (n >= 4) {
        const char *e = path + n - 4;
        char lower[5];
        for (int i = 0; i < 4; i++)
            lower[i] = (char)((e[i] >= 'A' && e[i] <= 'Z') ? e[i] - 'A' + 'a' : e[i]);
        lower[4] = '\0';
        if (strcmp(lower, ".png") == 0)
            return MOTE__IMG_PNG;
        if (strcmp(lower, ".ppm") == 0)
            return MOTE__IMG_PPM;
    }
    return -1;
}

mote_result mote_write_rgba(const char *path, const uint8_t *rgba, int width, int height,
                            int stride, char *message, size_t message_size)
{
    int kind = mote__kind_of(path);
    if (kind < 0) {
        char name[160];
        mote__io_clean_name(name, sizeof name, path);
        return mote__io_error(message, message_size, MOTE_ERR_UNSUPPORTED,
                              "%s: unknown image type (use .png or .ppm)", name);
    }
    return mote__write_rgba_as((mote__img_kind)kind, path, rgba, width, height, stride,
                               message, message_size);
}

static mote_result mote__write_device(mote__img_kind kind, const char *path,
                                      const mote_device *dev, char *message,
                                      size_t message_size)
{
    if (!path || !dev || !dev->ready || !dev->desc.color)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "write image: no path or no initialised device");
    const mote_device_desc *d = &dev->desc;
    int w = d->width, h = d->height;
    if (d->band_height > 0 && d->band_height < h)
        return mote__io_error(message, message_size, MOTE_ERR_UNSUPPORTED,
                              "write image: a band-mode device holds only %d of %d rows; "
                              "write the bands from the flush callback",
                              d->band_height, h);
    int bpp = mote_format_bytes(d->color_format);
    if (w <= 0 || h <= 0 || bpp <= 0)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "write image: device has size %d x %d, format %d", w, h,
                              (int)d->color_format);
    int stride = d->color_stride ? d->color_stride : w * bpp;
    if ((size_t)w * 4 > SIZE_MAX / (size_t)h)
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT, "write image: too large");
    uint8_t *rgba = mote__io_malloc((size_t)w * 4 * (size_t)h);
    if (!rgba)
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "write image: out of memory converting %d x %d", w, h);
    bool rgba_src = d->color_format == MOTE_FORMAT_RGBA8888 ||
                    d->color_format == MOTE_FORMAT_DEFAULT;
    for (int y = 0; y < h; y++) {
        const uint8_t *src = (const uint8_t *)d->color + (size_t)y * (size_t)stride;
        uint8_t *dst = rgba + (size_t)y * (size_t)w * 4;
        if (rgba_src)
            memcpy(dst, src, (size_t)w * 4);
        else
            mote_convert_row(src, d->color_format, dst, MOTE_FORMAT_RGBA8888, w);
        /* the colour buffer's alpha is not coverage: write opaque images */
        for (int x = 0; x < w; x++)
            dst[x * 4 + 3] = 255;
    }
    mote_result r = mote__write_rgba_as(kind, path, rgba, w, h, w * 4, message, message_size);
    mote__io_free(rgba);
    return r;
}

mote_result mote_write_png(const char *path, const mote_device *dev, char *message,
                           size_t message_size)
{
    return mote__write_device(MOTE__IMG_PNG, path, dev, message, message_size);
}

mote_result mote_write_ppm(const char *path, const mote_device *dev, char *message,
                           size_t message_size)
{
    return mote__write_device(MOTE__IMG_PPM, path, dev, message, message_size);
}

mote_result mote_write_image(const char *path, const mote_device *dev, char *message,
                             size_t message_size)
{
    int kind = mote__kind_of(path);
    if (kind < 0) {
        char name[160];
        mote__io_clean_name(name, sizeof name, path);
        return mote__io_error(message, message_size, MOTE_ERR_UNSUPPORTED,
                              "%s: unknown image type (use .png or .ppm)", name);
    }
    return mote__write_device((mote__img_kind)kind, path, dev, message, message_size);
}
