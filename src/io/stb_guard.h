/*
 * stb_guard.h - what the formats of the stb_image guard (stb_guard.c,
 * stb_guard_jpeg.c, stb_guard_png.c) share: bytes read as stb_image reads
 * them, and what a check concludes. Not API.
 */
#ifndef MOTE_IO_STB_GUARD_H
#define MOTE_IO_STB_GUARD_H

#include "io_internal.h"

#include <stdbool.h>
#include <stdint.h>

/* A byte source over memory: past the end it reads 0 and stays there, as
 * stb_image's memory reader does. */
typedef struct mote__src {
    const unsigned char *d;
    size_t n, pos;
} mote__src;

static inline unsigned mote__get8(mote__src *s)
{
    return s->pos < s->n ? s->d[s->pos++] : 0;
}

static inline unsigned mote__get16be(mote__src *s)
{
    unsigned hi = mote__get8(s);
    return hi << 8 | mote__get8(s);
}

/* stbi__skip: forward k bytes, no further than the end. */
static inline void mote__skip(mote__src *s, size_t k)
{
    s->pos = k < s->n - s->pos ? s->pos + k : s->n;
}

static inline unsigned mote__byte_at(const unsigned char *d, size_t n, size_t i)
{
    return i < n ? d[i] : 0;
}

static inline uint32_t mote__le16(const unsigned char *d, size_t n, size_t i)
{
    return mote__byte_at(d, n, i) | mote__byte_at(d, n, i + 1) << 8;
}

static inline uint32_t mote__le32(const unsigned char *d, size_t n, size_t i)
{
    return mote__le16(d, n, i) | mote__le16(d, n, i + 2) << 16;
}

static inline uint32_t mote__be32(const unsigned char *d, size_t n, size_t i)
{
    return (uint32_t)mote__byte_at(d, n, i) << 24 | (uint32_t)mote__byte_at(d, n, i + 1) << 16 |
           (uint32_t)mote__byte_at(d, n, i + 2) << 8 | mote__byte_at(d, n, i + 3);
}


/* What a check concludes: go on, stb_image will fail here by itself, or
 * the image must be refused (the message is written). */
typedef enum mote__verdict { MOTE__GO, MOTE__STB_FAILS, MOTE__REFUSE } mote__verdict;


/* A canonical Huffman code from the number of codes of each length 1..max:
 * the first code of each length and the index of its symbol. False where
 * the counts overfill a length, which both of stb_image's builders (JPEG
 * and zlib) refuse. */
bool mote__huffman_canonical(const uint16_t *count, int max, uint32_t *first, int *offset);

/* The JPEG and PNG checks: MOTE_ERR_PARSE with a message for an image
 * that reaches a known fault (a PNG whose palette stb_image would read
 * past gets a padded copy in *fixed); MOTE_OK otherwise. */
mote_result mote__stb_guard_jpeg(const unsigned char *d, size_t n, const mote_limits *limits,
                                 char *message, size_t message_size);
mote_result mote__stb_guard_png(const unsigned char *d, size_t n, unsigned char **fixed,
                                size_t *fixed_size, char *message, size_t message_size);

#endif
