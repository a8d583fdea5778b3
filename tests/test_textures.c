/*
 * test_textures.c - textures of every format mote lets through to the
 * system stb_image, written here: the ordinary shapes of each still load to
 * the right pixels past mote's guard (src/io/stb_guard*.c), and what
 * the guard pads or bounds does what it should. The crafted files that
 * reach stb_image's known faults, refused by the guard, are in
 * tests/data/bad/ (make_stb_textures.py, EXPECTED.txt).
 */
#include <mote/mote.h>
#include <mote/mote_io.h>
#include "io/io_internal.h"
#include "support/io_test.h"
#include "unity.h"

#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image_write.h>

static char msg[512];
static long live_before;

void setUp(void)
{
    msg[0] = '\0';
    live_before = mote__io_live_allocations();
    mote__io_set_alloc_failure_after(-1);
}

void tearDown(void) {}

/* ---- a byte buffer and a bit writer ------------------------------------ */

typedef struct bytes {
    unsigned char d[1 << 16];
    size_t n;
} bytes;

static bytes file, part;

static void put8(bytes *b, unsigned v)
{
    TEST_ASSERT_TRUE(b->n < sizeof b->d);
    b->d[b->n++] = (unsigned char)v;
}

static void put16le(bytes *b, unsigned v)
{
    put8(b, v & 255);
    put8(b, v >> 8 & 255);
}

static void put32le(bytes *b, uint32_t v)
{
    put16le(b, v & 0xffff);
    put16le(b, v >> 16);
}

static void put16be(bytes *b, unsigned v)
{
    put8(b, v >> 8 & 255);
    put8(b, v & 255);
}

static void put32be(bytes *b, uint32_t v)
{
    put16be(b, v >> 16);
    put16be(b, v & 0xffff);
}

static void put_all(bytes *b, const void *p, size_t n)
{
    TEST_ASSERT_TRUE(b->n + n <= sizeof b->d);
    memcpy(b->d + b->n, p, n);
    b->n += n;
}

/* JPEG entropy-coded bits, highest first, 0xff followed by a stuffed 0 */
typedef struct bitwriter {
    bytes *b;
    uint32_t acc;
    int count;
} bitwriter;

static void put_bits(bitwriter *w, uint32_t v, int n)
{
    for (int i = n - 1; i >= 0; i--) {
        w->acc = w->acc << 1 | (v >> i & 1);
        if (++w->count == 8) {
            put8(w->b, w->acc);
            if (w->acc == 0xff)
                put8(w->b, 0);
            w->acc = 0;
            w->count = 0;
        }
    }
}

static void flush_bits(bitwriter *w)
{
    while (w->count)
        put_bits(w, 1, 1);
}

static void stb_sink(void *context, void *data, int size)
{
    put_all(context, data, (size_t)size);
}

/* Decodes the file through mote (guard and stb_image). */
static mote_texture load(const bytes *b)
{
    mote_texture t;
    mote_result r = mote_texture_load_memory(b->d, b->n, NULL, &t, msg, sizeof msg);
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, r, msg);
    return t;
}

static const uint8_t *texel(const mote_texture *t, int x, int y)
{
    return (const uint8_t *)t->pixels + y * t->stride + x * 4;
}

static void assert_rgba(const uint8_t want[4], const uint8_t *got, int tolerance, const char *what)
{
    char where[128];
    snprintf(where, sizeof where, "%s: got %d %d %d %d, expected %d %d %d %d", what, got[0],
             got[1], got[2], got[3], want[0], want[1], want[2], want[3]);
    for (int c = 0; c < 4; c++)
        TEST_ASSERT_TRUE_MESSAGE(abs(got[c] - want[c]) <= tolerance, where);
}

/* ---- JPEG -------------------------------------------------------------- */

static void jpeg_segment(bytes *b, unsigned marker, const bytes *body)
{
    put8(b, 0xff);
    put8(b, marker);
    put16be(b, (unsigned)body->n + 2);
    put_all(b, body->d, body->n);
}

/* A progressive 32 x 32 YCbCr JPEG shaped as libjpeg writes one: 4:2:0,
 * a restart interval of two MCUs, a first DC scan with a point transform,
 * its refinement, and one AC scan per component that is a single run of
 * empty blocks. Each 16 x 16 MCU is flat, of ycc[mcu]. */
static void progressive_jpeg(bytes *b, const int ycc[4][3])
{
    static const int blocks[3] = {4, 1, 1}; /* per MCU: Y 2 x 2, Cb, Cr */
    b->n = 0;
    put8(b, 0xff);
    put8(b, 0xd8);
    part.n = 0; /* quantisation: 8 at DC, so a coefficient is sample - 128 */
    for (unsigned t = 0; t < 2; t++) {
        put8(&part, t);
        put8(&part, 8);
        for (int i = 1; i < 64; i++)
            put8(&part, 1);
    }
    jpeg_segment(b, 0xdb, &part);
    part.n = 0;
    put8(&part, 8);
    put16be(&part, 32);
    put16be(&part, 32);
    put8(&part, 3);
    static const unsigned comp[3][3] = {{1, 0x22, 0}, {2, 0x11, 1}, {3, 0x11, 1}};
    for (int c = 0; c < 3; c++)
        for (int k = 0; k < 3; k++)
            put8(&part, comp[c][k]);
    jpeg_segment(b, 0xc2, &part);
    part.n = 0;
    put16be(&part, 2);
    jpeg_segment(b, 0xdd, &part);
    part.n = 0; /* DC table 0: sizes 0..11, each a 4-bit code */
    put8(&part, 0x00);
    for (int len = 1; len <= 16; len++)
        put8(&part, len == 4 ? 12 : 0);
    for (unsigned s = 0; s < 12; s++)
        put8(&part, s);
    jpeg_segment(b, 0xc4, &part);

    for (int refine = 0; refine < 2; refine++) {
        part.n = 0;
        put8(&part, 3);
        for (unsigned c = 1; c <= 3; c++) {
            put8(&part, c);
            put8(&part, 0x00);
        }
        put8(&part, 0);
        put8(&part, 0);
        put8(&part, refine ? 0x10 : 0x01);
        jpeg_segment(b, 0xda, &part);
        bitwriter w = {b, 0, 0};
        int pred[3] = {0, 0, 0};
        for (int mcu = 0; mcu < 4; mcu++) {
            if (mcu == 2) { /* the end of the first interval */
                flush_bits(&w);
                put8(b, 0xff);
                put8(b, 0xd0);
                pred[0] = pred[1] = pred[2] = 0;
            }
            for (int c = 0; c < 3; c++)
                for (int k = 0; k < blocks[c]; k++) {
                    int dc = ycc[mcu][c] - 128;
                    if (refine) {
                        put_bits(&w, (uint32_t)dc & 1, 1);
                        continue;
                    }
                    int diff = (dc >> 1) - pred[c], mag = abs(diff), size = 0;
                    pred[c] = dc >> 1;
                    while (mag >> size)
                        size++;
                    put_bits(&w, (uint32_t)size, 4);
                    put_bits(&w, (uint32_t)(diff < 0 ? diff - 1 : diff) & ((1u << size) - 1), size);
                }
        }
        flush_bits(&w);
    }
    part.n = 0;
    put16be(&part, 0); /* no restarts in the AC scans */
    jpeg_segment(b, 0xdd, &part);
    part.n = 0; /* AC table 0: end-of-band runs of 4 (code 00) and 16 (01) */
    put8(&part, 0x10);
    for (int len = 1; len <= 16; len++)
        put8(&part, len == 2 ? 2 : 0);
    put8(&part, 0x20);
    put8(&part, 0x40);
    jpeg_segment(b, 0xc4, &part);
    for (unsigned c = 1; c <= 3; c++) {
        part.n = 0;
        put8(&part, 1);
        put8(&part, c);
        put8(&part, 0x00);
        put8(&part, 1);
        put8(&part, 63);
        put8(&part, 0);
        jpeg_segment(b, 0xda, &part);
        bitwriter w = {b, 0, 0};
        put_bits(&w, c == 1 ? 1 : 0, 2);
        put_bits(&w, 0, c == 1 ? 4 : 2);
        flush_bits(&w);
    }
    put8(b, 0xff);
    put8(b, 0xd9);
}

static void ycc_to_rgba(const int ycc[3], uint8_t out[4])
{
    double y = ycc[0], cb = ycc[1] - 128.0, cr = ycc[2] - 128.0;
    double rgb[3] = {y + 1.402 * cr, y - 0.344136 * cb - 0.714136 * cr, y + 1.772 * cb};
    for (int c = 0; c < 3; c++)
        out[c] = (uint8_t)(rgb[c] < 0 ? 0 : rgb[c] > 255 ? 255 : rgb[c] + 0.5);
    out[3] = 255;
}

void textures_should_load_baseline_and_progressive_jpegs(void)
{
    static const int ycc[4][3] = {{76, 85, 255}, {150, 44, 21}, {29, 255, 107}, {200, 128, 128}};
    progressive_jpeg(&file, ycc);
    mote_texture t = load(&file);
    TEST_ASSERT_EQUAL(32, t.width);
    TEST_ASSERT_EQUAL(32, t.height);
    for (int mcu = 0; mcu < 4; mcu++) {
        uint8_t want[4];
        ycc_to_rgba(ycc[mcu], want);
        assert_rgba(want, texel(&t, 8 + 16 * (mcu & 1), 8 + 16 * (mcu >> 1)), 3, "progressive");
    }
    mote_texture_free(&t);

    /* baseline, as stb_image_write encodes: 4:2:0 at quality 90, 4:4:4 at
     * 100, and grey */
    static uint8_t src[40 * 24 * 3];
    for (int y = 0; y < 24; y++)
        for (int x = 0; x < 40; x++) {
            uint8_t *p = src + (y * 40 + x) * 3;
            p[0] = (uint8_t)(x * 6);
            p[1] = (uint8_t)(y * 10);
            p[2] = (uint8_t)(200 - x * 2 - y * 3);
        }
    static const int quality[3] = {90, 100, 95}, comps[3] = {3, 3, 1};
    for (int k = 0; k < 3; k++) {
        file.n = 0;
        static uint8_t grey[40 * 24];
        for (int i = 0; i < 40 * 24; i++)
            grey[i] = src[i * 3 + 1];
        TEST_ASSERT_TRUE(stbi_write_jpg_to_func(stb_sink, &file, 40, 24, comps[k],
                                                comps[k] == 1 ? (const void *)grey : src,
                                                quality[k]));
        t = load(&file);
        TEST_ASSERT_EQUAL(40, t.width);
        long error = 0;
        for (int y = 0; y < 24; y++)
            for (int x = 0; x < 40; x++)
                for (int c = 0; c < 3; c++)
                    error += abs(texel(&t, x, y)[c] - (comps[k] == 1 ? grey[y * 40 + x]
                                                                     : src[(y * 40 + x) * 3 + c]));
        TEST_ASSERT_TRUE_MESSAGE(error < 40 * 24 * 3 * 4, "baseline JPEG far from its source");
        mote_texture_free(&t);
    }
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* ---- PNG ---------------------------------------------------------------- */

static uint32_t crc32_of(const unsigned char *p, size_t n)
{
    uint32_t crc = 0xffffffffu;
    while (n--) {
        crc ^= *p++;
        for (int k = 0; k < 8; k++)
            crc = crc >> 1 ^ (0xedb88320u & (0u - (crc & 1)));
    }
    return ~crc;
}

static void png_chunk(bytes *b, const char *type, const bytes *body)
{
    put32be(b, (uint32_t)body->n);
    size_t start = b->n;
    put_all(b, type, 4);
    put_all(b, body->d, body->n);
    put32be(b, crc32_of(b->d + start, b->n - start));
}

/* A PNG of the given rows (each a filter byte and its samples), in stored
 * deflate blocks; plte/trns may be NULL. */
static void png(bytes *b, int w, int h, int depth, int color, const bytes *rows,
                const bytes *plte, const bytes *trns)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static bytes z;
    b->n = 0;
    put_all(b, sig, 8);
    part.n = 0;
    put32be(&part, (uint32_t)w);
    put32be(&part, (uint32_t)h);
    put8(&part, (unsigned)depth);
    put8(&part, (unsigned)color);
    put8(&part, 0);
    put8(&part, 0);
    put8(&part, 0);
    png_chunk(b, "IHDR", &part);
    if (plte)
        png_chunk(b, "PLTE", plte);
    if (trns)
        png_chunk(b, "tRNS", trns);
    z.n = 0;
    put8(&z, 0x78);
    put8(&z, 0x01);
    uint32_t a = 1, s = 0;
    size_t at = 0;
    do {
        size_t len = rows->n - at < 40 ? rows->n - at : 40; /* several blocks */
        put8(&z, at + len == rows->n);
        put16le(&z, (unsigned)len);
        put16le(&z, (unsigned)len ^ 0xffff);
        put_all(&z, rows->d + at, len);
        for (size_t i = 0; i < len; i++) {
            a = (a + rows->d[at + i]) % 65521;
            s = (s + a) % 65521;
        }
        at += len;
    } while (at < rows->n);
    put32be(&z, s << 16 | a);
    png_chunk(b, "IDAT", &z);
    part.n = 0;
    png_chunk(b, "IEND", &part);
}

/* Sample i of a row of `bits`-bit samples. */
static unsigned sample(const unsigned char *row, int bits, int i)
{
    if (bits == 16)
        return (unsigned)row[2 * i] << 8 | row[2 * i + 1];
    int bit = i * bits;
    return row[bit / 8] >> (8 - bits - bit % 8) & ((1u << bits) - 1);
}

void textures_should_load_png_of_every_colour_type_and_depth(void)
{
    static const struct { int color, depth; bool trns; } kinds[] = {
        {0, 1, false}, {0, 2, false}, {0, 4, true}, {0, 8, false}, {0, 16, true},
        {2, 8, true},  {2, 16, false}, {3, 1, false}, {3, 2, true}, {3, 4, false},
        {3, 8, true},  {4, 8, false},  {4, 16, false}, {6, 8, false}, {6, 16, false},
    };
    static const int channels[7] = {1, 0, 3, 1, 2, 0, 4};
    const int w = 5, h = 3;
    static bytes rows, plte, trns;
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        int color = kinds[k].color, depth = kinds[k].depth, n = channels[color];
        int stride = (w * n * depth + 7) / 8;
        rows.n = 0;
        for (int y = 0; y < h; y++) {
            put8(&rows, 0);
            for (int i = 0; i < stride; i++)
                put8(&rows, (unsigned)(37 * (y * stride + i) + 11 * k) & 255);
        }
        plte.n = trns.n = 0;
        if (color == 3) {
            for (int e = 0; e < 1 << depth; e++) {
                put8(&plte, (unsigned)(e * 16 + 3) & 255);
                put8(&plte, (unsigned)(250 - e * 7) & 255);
                put8(&plte, (unsigned)(e * 29) & 255);
            }
            if (kinds[k].trns)
                for (int e = 0; e < 2; e++)
                    put8(&trns, e ? 128u : 0u);
        } else if (kinds[k].trns) { /* the colour of the first pixel is transparent */
            for (int c = 0; c < n; c++)
                put16be(&trns, sample(rows.d + 1, depth, c));
        }
        png(&file, w, h, depth, color, &rows, color == 3 ? &plte : NULL,
            trns.n ? &trns : NULL);
        mote_texture t = load(&file);
        const unsigned char *first = rows.d + 1;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                const unsigned char *row = rows.d + y * (stride + 1) + 1;
                uint8_t want[4] = {0, 0, 0, 255};
                unsigned max = (1u << depth) - 1;
                unsigned v[4];
                bool key = kinds[k].trns && color != 3;
                for (int c = 0; c < n; c++) {
                    v[c] = sample(row, depth, x * n + c);
                    key = key && v[c] == sample(first, depth, c);
                }
                if (color == 3) {
                    memcpy(want, plte.d + 3 * v[0], 3);
                    if (v[0] < trns.n)
                        want[3] = trns.d[v[0]];
                } else {
                    uint8_t s8[4];
                    for (int c = 0; c < n; c++)
                        s8[c] = (uint8_t)(depth == 16 ? v[c] >> 8 : v[c] * 255 / max);
                    if (n <= 2)
                        want[0] = want[1] = want[2] = s8[0];
                    else
                        memcpy(want, s8, 3);
                    if (n == 2 || n == 4)
                        want[3] = s8[n - 1];
                    if (key)
                        want[3] = 0;
                }
                char what[64];
                snprintf(what, sizeof what, "colour type %d, %d bits, pixel %d,%d", color, depth,
                         x, y);
                assert_rgba(want, texel(&t, x, y), 0, what);
            }
        mote_texture_free(&t);
    }
    /* and as stb_image_write writes them (filtered, zlib-compressed) */
    static uint8_t src[9 * 7 * 4];
    for (int i = 0; i < 9 * 7 * 4; i++)
        src[i] = (uint8_t)(i * 7 % 251);
    for (int comp = 1; comp <= 4; comp++) {
        file.n = 0;
        TEST_ASSERT_TRUE(stbi_write_png_to_func(stb_sink, &file, 9, 7, comp, src, 9 * comp));
        mote_texture t = load(&file);
        for (int i = 0; i < 9 * 7; i++) {
            const uint8_t *p = src + i * comp;
            uint8_t want[4] = {p[0], comp >= 3 ? p[1] : p[0], comp >= 3 ? p[2] : p[0],
                               comp == 2 ? p[1] : comp == 4 ? p[3] : 255};
            assert_rgba(want, texel(&t, i % 9, i / 9), 0, "stb_image_write PNG");
        }
        mote_texture_free(&t);
    }
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* ---- BMP, TGA, GIF ------------------------------------------------------ */

/* A palette BMP of w x h `bits`-bit indices from index(x, y). */
static void palette_bmp(bytes *b, int w, int h, int bits, int entries,
                        unsigned (*index)(int x, int y))
{
    int stride = ((w * bits + 31) / 32) * 4;
    uint32_t offset = 14 + 40 + 4 * (uint32_t)entries;
    b->n = 0;
    put8(b, 'B');
    put8(b, 'M');
    put32le(b, offset + (uint32_t)(stride * h));
    put32le(b, 0);
    put32le(b, offset);
    put32le(b, 40);
    put32le(b, (uint32_t)w);
    put32le(b, (uint32_t)h); /* bottom-up, as most writers do */
    put16le(b, 1);
    put16le(b, (unsigned)bits);
    put32le(b, 0);
    put32le(b, (uint32_t)(stride * h));
    put32le(b, 2835);
    put32le(b, 2835);
    put32le(b, (uint32_t)entries);
    put32le(b, 0);
    for (int e = 0; e < entries; e++) {
        put8(b, (unsigned)(e * 40) & 255); /* blue, green, red, 0 */
        put8(b, (unsigned)(255 - e * 30) & 255);
        put8(b, (unsigned)(e * 90 + 20) & 255);
        put8(b, 0);
    }
    for (int y = h - 1; y >= 0; y--) {
        unsigned char row[64] = {0};
        for (int x = 0; x < w; x++) {
            int bit = x * bits;
            row[bit / 8] |= (unsigned char)(index(x, y) << (8 - bits - bit % 8));
        }
        put_all(b, row, (size_t)stride);
    }
}

static unsigned index_in_4(int x, int y)
{
    return (unsigned)(x + 2 * y) % 4;
}

static unsigned index_in_2(int x, int y)
{
    return (unsigned)(x ^ y) & 1;
}

static unsigned index_to_15(int x, int y)
{
    return (unsigned)(x + 5 * y) % 16;
}

static void want_palette_entry(int e, int entries, uint8_t want[4])
{
    bool inside = e < entries; /* past the palette: black (mote pads it) */
    want[0] = inside ? (uint8_t)(e * 90 + 20) : 0;
    want[1] = inside ? (uint8_t)(255 - e * 30) : 0;
    want[2] = inside ? (uint8_t)(e * 40) : 0;
    want[3] = 255;
}

void textures_should_load_bmp_tga_and_the_first_gif_frame(void)
{
    static const struct { int bits, entries; unsigned (*index)(int, int); } bmps[] = {
        {1, 2, index_in_2}, {4, 16, index_to_15}, {8, 4, index_in_4}, {8, 256, index_to_15},
    };
    for (size_t k = 0; k < sizeof bmps / sizeof bmps[0]; k++) {
        palette_bmp(&file, 7, 3, bmps[k].bits, bmps[k].entries, bmps[k].index);
        mote_texture t = load(&file);
        for (int y = 0; y < 3; y++)
            for (int x = 0; x < 7; x++) {
                uint8_t want[4];
                want_palette_entry((int)bmps[k].index(x, y), bmps[k].entries, want);
                assert_rgba(want, texel(&t, x, y), 0, "palette BMP");
            }
        mote_texture_free(&t);
    }
    /* 24-bit BMP and raw and run-length TGA, as stb_image_write writes them */
    static uint8_t src[6 * 5 * 4];
    for (int i = 0; i < 6 * 5 * 4; i++)
        src[i] = (uint8_t)(i < 40 ? 99 : i * 13 % 256); /* a run, then noise */
    for (int k = 0; k < 5; k++) {
        int comp = k == 0 ? 3 : k % 2 ? 3 : 4;
        file.n = 0;
        stbi_write_tga_with_rle = k >= 3;
        TEST_ASSERT_TRUE(k == 0 ? stbi_write_bmp_to_func(stb_sink, &file, 6, 5, comp, src)
                                : stbi_write_tga_to_func(stb_sink, &file, 6, 5, comp, src));
        mote_texture t = load(&file);
        for (int i = 0; i < 6 * 5; i++) {
            const uint8_t *p = src + i * comp;
            uint8_t want[4] = {p[0], p[1], p[2], comp == 4 ? p[3] : 255};
            assert_rgba(want, texel(&t, i % 6, i / 6), 0, k ? "TGA" : "BMP");
        }
        mote_texture_free(&t);
    }
    stbi_write_tga_with_rle = 1;

    /* a paletted TGA: 8-bit indices into a 24-bit colour map, top-down */
    file.n = 0;
    const uint8_t head[18] = {0, 1, 1, 0, 0, 4, 0, 24, 0, 0, 0, 0, 3, 0, 2, 0, 8, 0x20};
    put_all(&file, head, sizeof head);
    for (int e = 0; e < 4; e++) { /* blue, green, red */
        put8(&file, (unsigned)e * 60);
        put8(&file, 200u - (unsigned)e * 50);
        put8(&file, (unsigned)e * 20 + 5);
    }
    for (int i = 0; i < 6; i++)
        put8(&file, (unsigned)i % 4);
    mote_texture t = load(&file);
    for (int i = 0; i < 6; i++) {
        unsigned e = (unsigned)i % 4;
        uint8_t want[4] = {(uint8_t)(e * 20 + 5), (uint8_t)(200 - e * 50), (uint8_t)(e * 60), 255};
        assert_rgba(want, texel(&t, i % 3, i / 3), 0, "paletted TGA");
    }
    mote_texture_free(&t);

    /* a GIF of two frames, 4 colours, 2-bit LZW with a clear code every two
     * pixels; mote takes the first frame */
    file.n = 0;
    const uint8_t gif[13] = {'G', 'I', 'F', '8', '9', 'a', 4, 0, 3, 0, 0x81, 0, 0};
    put_all(&file, gif, sizeof gif);
    static const uint8_t colours[4][3] = {{250, 10, 10}, {10, 250, 10}, {10, 10, 250}, {90, 90, 90}};
    put_all(&file, colours, sizeof colours);
    for (int frame = 0; frame < 2; frame++) {
        const uint8_t gce[8] = {0x21, 0xf9, 4, 0, 10, 0, 0, 0};
        const uint8_t desc[10] = {0x2c, 0, 0, 0, 0, 4, 0, 3, 0, 0};
        put_all(&file, gce, sizeof gce);
        put_all(&file, desc, sizeof desc);
        put8(&file, 2); /* LZW minimum code size */
        unsigned codes[19];
        int k = 0;
        for (int i = 0; i < 12; i += 2) { /* clear, two pixels: the codes stay 3 bits */
            codes[k++] = 4;
            codes[k++] = (unsigned)(i + frame) % 4;
            codes[k++] = (unsigned)(i + 1 + frame) % 4;
        }
        codes[k++] = 5; /* end of data */
        unsigned char data[16] = {0};
        for (int c = 0; c < k; c++)
            for (int bit = 0; bit < 3; bit++)
                data[(c * 3 + bit) / 8] |= (unsigned char)((codes[c] >> bit & 1) << (c * 3 + bit) % 8);
        size_t n = (size_t)(k * 3 + 7) / 8;
        put8(&file, (unsigned)n);
        put_all(&file, data, n);
        put8(&file, 0);
    }
    put8(&file, 0x3b);
    t = load(&file);
    TEST_ASSERT_EQUAL(4, t.width);
    for (int i = 0; i < 12; i++) {
        const uint8_t *c = colours[i % 4];
        uint8_t want[4] = {c[0], c[1], c[2], 255};
        assert_rgba(want, texel(&t, i % 4, i / 4), 0, "GIF");
    }
    mote_texture_free(&t);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* ---- what the guard pads and bounds ------------------------------------ */

/* Fills a stretch of the stack below this frame with 0x5a, where the
 * frames of the decode that follows will lie: stb_image's palettes are
 * uninitialised stack arrays, so without mote's padding the test sees 0x5a
 * (where it would otherwise see whatever happened to be there, often 0). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void dirty_the_stack(void)
{
    volatile unsigned char junk[64 * 1024];
    for (size_t i = 0; i < sizeof junk; i++)
        junk[i] = 0x5a;
}

void textures_should_draw_indices_past_a_short_palette_black(void)
{
    /* BMP: 4 entries, indices up to 15 (stb_image's palette is on the stack) */
    palette_bmp(&file, 7, 3, 8, 4, index_to_15);
    dirty_the_stack();
    mote_texture t = load(&file);
    for (int y = 0; y < 3; y++)
        for (int x = 0; x < 7; x++) {
            uint8_t want[4];
            want_palette_entry((int)index_to_15(x, y), 4, want);
            assert_rgba(want, texel(&t, x, y), 0, "short BMP palette");
        }
    mote_texture_free(&t);
    /* PNG: 3 entries and a tRNS of 2, 4-bit indices up to 15 */
    static bytes rows, plte, trns;
    rows.n = plte.n = trns.n = 0;
    for (int y = 0; y < 2; y++) {
        put8(&rows, 0);
        for (int i = 0; i < 4; i++)
            put8(&rows, (unsigned)(y * 4 + i) * 0x22 + 0x01);
    }
    for (int e = 0; e < 9; e++)
        put8(&plte, 200u + (unsigned)e);
    put8(&trns, 10);
    put8(&trns, 20);
    png(&file, 8, 2, 4, 3, &rows, &plte, &trns);
    dirty_the_stack();
    t = load(&file);
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 8; x++) {
            unsigned e = sample(rows.d + y * 5 + 1, 4, x);
            uint8_t want[4] = {0, 0, 0, e < 2 ? (uint8_t)(e ? 20 : 10) : 255};
            if (e < 3)
                for (int c = 0; c < 3; c++)
                    want[c] = (uint8_t)(200 + 3 * e + (unsigned)c);
            assert_rgba(want, texel(&t, x, y), 0, "short PNG palette");
        }
    mote_texture_free(&t);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* stb_image's 16-bit conversions size their buffers in int or unsigned
 * arithmetic: a grey 16-bit PNG of 23171 x 23171 asked for 4 channels
 * wraps 4 x 23171^2 x 2 to 194,632 bytes, written 4 GiB past (upstream
 * nothings/stb#1860). Whatever the limits allow, mote refuses such a size from
 * the header. */
void textures_should_refuse_more_pixels_than_stb_image_converts_safely(void)
{
    static bytes rows;
    rows.n = 0;
    put8(&rows, 0);
    put16be(&rows, 0);
    png(&file, 1, 1, 16, 0, &rows, NULL, NULL);
    file.d[16 + 2] = 0x5a; /* IHDR width and height: 23171 */
    file.d[16 + 3] = 0x83;
    file.d[20 + 2] = 0x5a;
    file.d[20 + 3] = 0x83;
    mote_limits lim = mote_limits_default();
    lim.max_texture_width = lim.max_texture_height = 32768;
    lim.max_texture_bytes = SIZE_MAX;
    mote_texture t;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_texture_load_memory(file.d, file.n, &lim, &t, msg,
                                                               sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "23171 x 23171 is more pixels than stb_image "
                                             "converts safely"), msg);
    TEST_ASSERT_NULL(t.pixels);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* A JPEG larger than the limits is refused by its size, before the guard
 * walks its scans a block at a time: a 65528 x 63738 header over 300
 * bytes took the fuzzer past its 15 s (tests/fuzz/regressions/texture).
 * Here the scan uses a Huffman table no DHT segment defines, which the
 * guard refuses when it walks the scan: a limit error shows it did not. */
void textures_should_refuse_a_jpeg_over_the_limits_before_walking_its_scans(void)
{
    file.n = 0;
    put8(&file, 0xff);
    put8(&file, 0xd8);
    part.n = 0;
    put8(&part, 0);
    for (int i = 0; i < 64; i++)
        put8(&part, 1);
    jpeg_segment(&file, 0xdb, &part);
    for (int small = 0; small < 2; small++) {
        bytes *b = &file;
        size_t sof = b->n;
        part.n = 0; /* baseline, 20000 x 20000 (or 16 x 16), one component */
        put8(&part, 8);
        put16be(&part, small ? 16 : 20000);
        put16be(&part, small ? 16 : 20000);
        put8(&part, 1);
        put8(&part, 1);
        put8(&part, 0x11);
        put8(&part, 0);
        jpeg_segment(b, 0xc0, &part);
        part.n = 0; /* a scan with DC and AC table 0, never defined */
        put8(&part, 1);
        put8(&part, 1);
        put8(&part, 0x00);
        put8(&part, 0);
        put8(&part, 63);
        put8(&part, 0);
        jpeg_segment(b, 0xda, &part);
        put8(b, 0x00);
        put8(b, 0xff);
        put8(b, 0xd9);
        mote_texture t;
        mote_result r = mote_texture_load_memory(file.d, file.n, NULL, &t, msg, sizeof msg);
        if (!small) {
            TEST_ASSERT_EQUAL_MESSAGE(MOTE_ERR_LIMIT, r, msg);
            TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "20000 x 20000 is larger than the limit"), msg);
        } else { /* the same file within the limits: the guard walks it and refuses */
            TEST_ASSERT_EQUAL_MESSAGE(MOTE_ERR_PARSE, r, msg);
            TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "which no DHT segment defines"), msg);
        }
        TEST_ASSERT_NULL(t.pixels);
        TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
        file.n = sof; /* the second time, the frame again with a small size */
    }
}

/* The guard's own allocations (a copy of a PNG's IDAT data, its padded
 * copies, a JPEG's tables) fail cleanly. */
void textures_should_free_everything_when_each_allocation_fails(void)
{
    static const int ycc[4][3] = {{76, 85, 255}, {150, 44, 21}, {29, 255, 107}, {200, 128, 128}};
    for (int kind = 0; kind < 3; kind++) {
        if (kind == 0)
            progressive_jpeg(&file, ycc);
        else if (kind == 1)
            palette_bmp(&file, 7, 3, 8, 4, index_to_15);
        else {
            static bytes rows, plte;
            rows.n = plte.n = 0;
            put8(&rows, 0);
            put8(&rows, 0x12);
            put8(&plte, 1);
            put8(&plte, 2);
            put8(&plte, 3);
            png(&file, 2, 1, 4, 3, &rows, &plte, NULL);
        }
        int failed = 0;
        for (int n = 0; n < 20; n++) {
            mote__io_set_alloc_failure_after(n);
            mote_texture t;
            mote_result r = mote_texture_load_memory(file.d, file.n, NULL, &t, msg, sizeof msg);
            bool pending = mote__io_failure_pending();
            mote__io_set_alloc_failure_after(-1);
            if (r == MOTE_OK) {
                mote_texture_free(&t);
                TEST_ASSERT_TRUE(pending); /* only once nothing failed */
                break;
            }
            failed++;
            TEST_ASSERT_EQUAL_MESSAGE(MOTE_ERR_OUT_OF_MEMORY, r, msg);
            TEST_ASSERT_NULL(t.pixels);
            TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
        }
        TEST_ASSERT_TRUE(failed >= 2); /* the guard's and the decode's */
    }
}

/* ---- mote_texture_load --------------------------------------------------- */

void texture_should_round_trip_a_png_exactly(void)
{
    enum { TW = 7, TH = 5 };
    uint8_t px[TW * TH * 4];
    for (int i = 0; i < TW * TH * 4; i++)
        px[i] = (uint8_t)(i * 37 + 11);
    const char *path = io_tmp_path("round.png");
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_rgba(path, px, TW, TH, 0, msg, sizeof msg), msg);
    mote_texture t;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_texture_load(path, NULL, &t, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(TW, t.width);
    TEST_ASSERT_EQUAL(TH, t.height);
    TEST_ASSERT_EQUAL(MOTE_FORMAT_RGBA8888, t.format);
    TEST_ASSERT_EQUAL(TW * 4, t.stride);
    TEST_ASSERT_EQUAL_UINT8_ARRAY(px, t.pixels, TW * TH * 4);
    mote_texture_free(&t);
    TEST_ASSERT_NULL(t.pixels);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void texture_should_refuse_dimensions_over_the_limit_before_decoding(void)
{
    uint8_t px[16 * 4 * 4];
    memset(px, 200, sizeof px);
    const char *path = io_tmp_path("wide.png");
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_rgba(path, px, 16, 4, 0, msg, sizeof msg));
    mote_limits lim = mote_limits_default();
    lim.max_texture_width = 8;
    mote_texture t;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_texture_load(path, &lim, &t, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "16 x 4 is larger than the limit of 8 x 16384"));
    TEST_ASSERT_NULL(t.pixels);
    lim = mote_limits_default();
    lim.max_texture_bytes = 16 * 4 * 4 - 1;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_texture_load(path, &lim, &t, msg, sizeof msg));
    lim = mote_limits_default();
    lim.max_file_bytes = 10;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_texture_load(path, &lim, &t, msg, sizeof msg));
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_texture_load(io_tmp_path("none.png"), NULL, &t, msg,
                                                     sizeof msg));
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, mote_texture_load_memory("not an image", 12, NULL, &t,
                                                               msg, sizeof msg));
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* The decoders of Debian's stb_image 2.27 that have known faults are not
 * run: a truncated run-length HDR scanline looped for ever in
 * stbi_load_from_memory (CVE-2021-42715), and a 16-bit PGM was read past
 * the end of its buffer (CVE-2021-42716). An 8-bit PPM, as mote writes
 * them, still loads. */
void texture_should_refuse_the_hdr_and_16_bit_pnm_that_stb_mishandles(void)
{
    mote_texture t;
    /* the PNM first: without the check it fails here, not in a loop */
    unsigned char pgm[64] = "P5\n4 4\n65535\n";
    size_t head = strlen((const char *)pgm);
    TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED,
                      mote_texture_load_memory(pgm, head + 4 * 4 * 2, NULL, &t, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "16-bit PNM"), msg);
    TEST_ASSERT_NULL(t.pixels);
    static const char hdr[] = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n\x02\x02\x00\x08";
    TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED, mote_texture_load_memory(hdr, sizeof hdr - 1, NULL, &t,
                                                                     msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "Radiance HDR"), msg);
    TEST_ASSERT_NULL(t.pixels);
    static const uint8_t px[2 * 4] = {10, 20, 30, 255, 40, 50, 60, 255};
    const char *path = io_tmp_path("eight.ppm");
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_rgba(path, px, 2, 1, 0, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_texture_load(path, NULL, &t, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(2, t.width);
    TEST_ASSERT_EQUAL_UINT8_ARRAY(px, t.pixels, sizeof px);
    mote_texture_free(&t);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(textures_should_load_baseline_and_progressive_jpegs);
    RUN_TEST(textures_should_load_png_of_every_colour_type_and_depth);
    RUN_TEST(textures_should_load_bmp_tga_and_the_first_gif_frame);
    RUN_TEST(textures_should_draw_indices_past_a_short_palette_black);
    RUN_TEST(textures_should_refuse_more_pixels_than_stb_image_converts_safely);
    RUN_TEST(textures_should_refuse_a_jpeg_over_the_limits_before_walking_its_scans);
    RUN_TEST(textures_should_free_everything_when_each_allocation_fails);
    RUN_TEST(texture_should_round_trip_a_png_exactly);
    RUN_TEST(texture_should_refuse_dimensions_over_the_limit_before_decoding);
    RUN_TEST(texture_should_refuse_the_hdr_and_16_bit_pnm_that_stb_mishandles);
    return UNITY_END();
}
