/*
 * format.c - colour and depth formats as the API exposes them: sizes,
 * names, reading pixels back and converting rows, from format.h's
 * packing, storing and texel reads.
 */
#include "internal.h"

int mote_format_bytes(mote_format format)
{
    return mote__format_bytes(format);
}

int mote_depth_format_bytes(mote_depth_format format)
{
    return mote__depth_format_bytes(format);
}

size_t mote_band_bytes(int width, int band_height, mote_format color, mote_depth_format depth)
{
    /* no device is larger: the product then fits a 32-bit size_t */
    if (width <= 0 || band_height <= 0 || width > MOTE_MAX_SIZE || band_height > MOTE_MAX_SIZE)
        return 0;
    return (size_t)width * (size_t)band_height
         * (size_t)(mote_format_bytes(color) + mote_depth_format_bytes(depth));
}

const char *mote_format_name(mote_format format)
{
    switch (format) {
    case MOTE_FORMAT_RGBA8888: return "rgba8888";
    case MOTE_FORMAT_RGB565: return "rgb565";
    case MOTE_FORMAT_RGB565_SWAPPED: return "rgb565_swapped";
    case MOTE_FORMAT_GREY8: return "grey8";
    default: return NULL;
    }
}

bool mote_format_is_texture(mote_format format)
{
    return mote__texture_format(format);
}

void mote__read_rgba(const uint8_t *row, int x, mote_format format, uint8_t out[4])
{
    uint32_t c[3];
    if (format == MOTE_FORMAT_RGB565_SWAPPED) {
        uint16_t v = ((const uint16_t *)(const void *)row)[x];
        v = (uint16_t)((v & 0xff) << 8 | v >> 8);   /* the bytes the other way round */
        mote__texel(MOTE_FORMAT_RGB565, (const uint8_t *)(const void *)&v, 0, c);
    } else {
        mote__texel(format, row, (size_t)x, c);
    }
    for (int k = 0; k < 3; k++)
        out[k] = (uint8_t)c[k];
    out[3] = format == MOTE_FORMAT_RGBA8888 ? row[4 * x + 3] : 255;
}

void mote__write_rgb(uint8_t *row, int x, mote_format format, uint32_t r, uint32_t g, uint32_t b)
{
    mote__store(row, x, format, mote__pack(format, r, g, b));
}

mote_rgba mote_read_pixel(const mote_device *dev, int x, int y)
{
    mote_rgba c = {0, 0, 0, 0};
    if (!dev || !dev->ready || x < 0 || y < 0 || x >= dev->desc.width || y >= dev->desc.band_height)
        return c;
    const uint8_t *row = (const uint8_t *)dev->bands.color + (size_t)y * (size_t)dev->desc.color_stride;
    uint8_t v[4];
    mote__read_rgba(row, x, dev->desc.color_format, v);
    memcpy(&c, v, sizeof c);      /* r, g, b, a */
    return c;
}

void mote_convert_row(const void *src, mote_format src_format, void *dst, mote_format dst_format, int count)
{
    if (src_format == MOTE_FORMAT_DEFAULT)
        src_format = MOTE_FORMAT_RGBA8888;
    if (dst_format == MOTE_FORMAT_DEFAULT)
        dst_format = MOTE_FORMAT_RGBA8888;
    /* an unknown format: no pixel has a size to convert */
    if ((unsigned)src_format >= MOTE_FORMAT_COUNT || (unsigned)dst_format >= MOTE_FORMAT_COUNT)
        return;
    for (int x = 0; x < count; x++) {
        uint8_t v[4];
        mote__read_rgba((const uint8_t *)src, x, src_format, v);
        mote__write_rgb((uint8_t *)dst, x, dst_format, v[0], v[1], v[2]);
        if (dst_format == MOTE_FORMAT_RGBA8888)
            ((uint8_t *)dst)[4 * x + 3] = v[3];
    }
}

/* ---- mip chains ------------------------------------------------------------ */

/* Levels past 0 of a power-of-two texture: their count and bytes. */
static int mote__mip_levels(const mote_texture *t, size_t *bytes)
{
    *bytes = 0;
    if (!t || !t->pixels || !mote__texture_format(t->format) || t->width <= 0 || t->height <= 0
        || (t->width & (t->width - 1)) || (t->height & (t->height - 1)))
        return 0;
    int n = 0;
    for (int w = t->width, h = t->height; (w > 1 || h > 1) && n + 1 < MOTE_MAX_MIPS; n++) {
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        *bytes += (size_t)w * (size_t)h * (size_t)mote__format_bytes(t->format);
    }
    return n;
}

size_t mote_mipmaps_bytes(const mote_texture *texture)
{
    size_t bytes;
    mote__mip_levels(texture, &bytes);
    return bytes;
}

mote_result mote_mipmaps_build(const mote_texture *texture, void *memory, size_t size, mote_mipmaps *out)
{
    size_t bytes;
    const int n = mote__mip_levels(texture, &bytes);
    if (!out || !texture || !texture->pixels || !mote__texture_format(texture->format) || texture->width <= 0
        || texture->height <= 0)
        return MOTE_ERR_INVALID_ARGUMENT;
    if (n > 0 && (!memory || size < bytes))
        return MOTE_ERR_OUT_OF_MEMORY;
    const int bpp = mote__format_bytes(texture->format);
    if (n > 0 && ((uintptr_t)memory & (uintptr_t)(bpp - 1)))
        return MOTE_ERR_INVALID_ARGUMENT;
    memset(out, 0, sizeof *out);
    out->count = n + 1;
    out->level[0] = *texture;
    uint8_t *dst = (uint8_t *)memory;
    for (int l = 1; l <= n; l++) {
        const mote_texture *src = &out->level[l - 1];
        const int sw = src->width, sh = src->height, w = sw > 1 ? sw / 2 : 1, h = sh > 1 ? sh / 2 : 1;
        const size_t sstride = src->stride > 0 ? (size_t)src->stride : (size_t)sw * (size_t)bpp;
        mote_texture *lv = &out->level[l];
        *lv = (mote_texture){w, h, texture->format, w * bpp, dst};
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                /* the 2x2 box (2x1 or 1x2 along an axis of 1), rounded */
                uint32_t sum[4] = {0, 0, 0, 0}, c[3];
                const int xs[2] = {2 * x, sw > 1 ? 2 * x + 1 : 2 * x}, ys[2] = {2 * y, sh > 1 ? 2 * y + 1 : 2 * y};
                for (int j = 0; j < 2; j++)
                    for (int i = 0; i < 2; i++) {
                        const uint8_t *row = (const uint8_t *)src->pixels + (size_t)ys[j] * sstride;
                        mote__texel(texture->format, row, (size_t)xs[i], c);
                        for (int k = 0; k < 3; k++)
                            sum[k] += c[k];
                        sum[3] += mote__texel_alpha(texture->format, row, (size_t)xs[i]);
                    }
                uint8_t *p = dst + ((size_t)y * (size_t)w + (size_t)x) * (size_t)bpp;
                if (texture->format == MOTE_FORMAT_RGBA8888) {
                    for (int k = 0; k < 4; k++)
                        p[k] = (uint8_t)((sum[k] + 2) >> 2);
                } else {
                    mote__store(p, 0, texture->format,
                                mote__pack(texture->format, (sum[0] + 2) >> 2, (sum[1] + 2) >> 2, (sum[2] + 2) >> 2));
                }
            }
        dst += (size_t)w * (size_t)h * (size_t)bpp;
    }
    return MOTE_OK;
}
