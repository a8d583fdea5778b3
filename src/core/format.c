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
