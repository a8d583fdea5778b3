/*
 * format.h - colour and depth formats, in one place: bytes per pixel, a
 * colour packed into a pixel and stored, a texel read back as channels,
 * and a depth value as a buffer stores it. Inline, so that the pixel
 * loops (span.c), where the format is a constant, keep one store per
 * pixel; format.c has the public functions built on them (conversion,
 * reading pixels back). A new format is a case in each function here,
 * its enum in mote.h, and its tests (tests/test_format.c).
 */
#ifndef MOTE_CORE_FORMAT_H
#define MOTE_CORE_FORMAT_H

#include <mote/mote.h>
#include <string.h>

/* What the host is, for faster forms with the same results: a pixel or
 * texel moved as one word on little-endian machines. */
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define MOTE__LITTLE_ENDIAN 1
#else
#define MOTE__LITTLE_ENDIAN 0
#endif

/* mote_format_bytes */
static inline int mote__format_bytes(mote_format format)
{
    switch (format) {
    case MOTE_FORMAT_DEFAULT:
    case MOTE_FORMAT_RGBA8888: return 4;
    case MOTE_FORMAT_RGB565:
    case MOTE_FORMAT_RGB565_SWAPPED: return 2;
    case MOTE_FORMAT_GREY8: return 1;
    default: return 0;
    }
}

/* mote_depth_format_bytes */
static inline int mote__depth_format_bytes(mote_depth_format format)
{
    switch (format) {
    case MOTE_DEPTH_FORMAT_DEFAULT:
    case MOTE_DEPTH_FORMAT_32: return 4;
    case MOTE_DEPTH_FORMAT_16: return 2;
    default: return 0;
    }
}

/* mote_format_is_texture: the formats the texel reads below know */
static inline bool mote__texture_format(mote_format format)
{
    return format == MOTE_FORMAT_RGBA8888 || format == MOTE_FORMAT_RGB565 || format == MOTE_FORMAT_GREY8;
}

/* r, g, b (0..255) as a pixel of the format, in the low bits of the word
 * mote__store writes; RGBA8888's alpha is 255. */
static inline uint32_t mote__pack(mote_format fmt, uint32_t r, uint32_t g, uint32_t b)
{
    if (fmt == MOTE_FORMAT_RGBA8888) {
#if MOTE__LITTLE_ENDIAN
        return r | g << 8 | b << 16 | 0xff000000u;
#else
        uint8_t px[4] = {(uint8_t)r, (uint8_t)g, (uint8_t)b, 255};
        uint32_t v;
        memcpy(&v, px, 4);
        return v;
#endif
    }
    if (fmt == MOTE_FORMAT_GREY8)
        return (77 * r + 150 * g + 29 * b + 128) >> 8;
    uint32_t v = ((r * 31 + 127) / 255) << 11 | ((g * 63 + 127) / 255) << 5 | ((b * 31 + 127) / 255);
    return fmt == MOTE_FORMAT_RGB565_SWAPPED ? ((v & 0xff) << 8) | (v >> 8) : v;
}

/* A packed pixel v stored as pixel x of row. */
static inline void mote__store(uint8_t *row, ptrdiff_t x, mote_format fmt, uint32_t v)
{
    if (fmt == MOTE_FORMAT_RGBA8888)
        memcpy(row + 4 * x, &v, 4);
    else if (fmt == MOTE_FORMAT_GREY8)
        row[x] = (uint8_t)v;
    else
        ((uint16_t *)(void *)row)[x] = (uint16_t)v;
}

/* Texel x of a texture row (a texture format) as three channels 0..255:
 * RGB565's 5 and 6 bits widened to the nearest 8-bit value. */
static inline void mote__texel(mote_format format, const uint8_t *row, size_t x, uint32_t c[3])
{
    switch (format) {
    case MOTE_FORMAT_RGB565: {
        uint32_t v = ((const uint16_t *)(const void *)row)[x];
        c[0] = ((v >> 11) * 527 + 23) >> 6;
        c[1] = (((v >> 5) & 63) * 259 + 33) >> 6;
        c[2] = ((v & 31) * 527 + 23) >> 6;
        break;
    }
    case MOTE_FORMAT_GREY8:
        c[0] = c[1] = c[2] = row[x];
        break;
    default: {
#if MOTE__LITTLE_ENDIAN
        uint32_t v;                   /* one load instead of three */
        memcpy(&v, row + 4 * x, 4);
        c[0] = v & 0xff;
        c[1] = (v >> 8) & 0xff;
        c[2] = (v >> 16) & 0xff;
#else
        c[0] = row[4 * x];
        c[1] = row[4 * x + 1];
        c[2] = row[4 * x + 2];
#endif
        break;
    }
    }
}

/* Texel x's alpha (0..255): RGBA8888's fourth byte, 255 in the formats
 * without alpha. */
static inline uint32_t mote__texel_alpha(mote_format format, const uint8_t *row, size_t x)
{
    return format == MOTE_FORMAT_RGBA8888 ? row[4 * x + 3] : 255u;
}

/* round(x / 255) for x in [0, 255 * 255], without a division: x / 255
 * never lies half-way between integers (255 is odd). */
static inline uint32_t mote__div255(uint32_t x)
{
    x += 128;
    return (x + (x >> 8)) >> 8;
}

/* A depth D in 0..2^24-1 as element i of a depth buffer of the format
 * (not NONE): 32-bit buffers keep D, 16-bit ones D >> 8. */
static inline void mote__depth_store(void *depth, size_t i, mote_depth_format format, uint32_t d)
{
    if (format == MOTE_DEPTH_FORMAT_16)
        ((uint16_t *)depth)[i] = (uint16_t)(d >> 8);
    else
        ((uint32_t *)depth)[i] = d;
}

/* format.c: pixel x of row as r, g, b, a (any colour format; alpha 255
 * but in RGBA8888), and r, g, b stored there. */
void mote__read_rgba(const uint8_t *row, int x, mote_format format, uint8_t out[4]);
void mote__write_rgb(uint8_t *row, int x, mote_format format, uint32_t r, uint32_t g, uint32_t b);

#endif
