/*
 * texture_screen.c - an image's bytes looked at as the stb_image mote links
 * will read them, before it reads them.
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
 * README "Hostile input" lists what is handled and what is not.
 *
 * Each check follows stb_image's own reading of the bytes (which format it
 * takes a file for, where its reader stands), so that what is checked is
 * what stb_image will meet. Where stb_image will fail on its own before the
 * construct matters, the image is left to it, so its messages stay as they
 * were.
 */
#include "io_internal.h"

#include <limits.h>
#include <stdint.h>
#include <string.h>

/* ---- reading bytes as stb_image does ----------------------------------- */

/* A byte source over memory: past the end it reads 0 and stays there, as
 * stb_image's memory reader does. */
typedef struct mote__src {
    const unsigned char *d;
    size_t n, pos;
} mote__src;

static unsigned mote__get8(mote__src *s)
{
    return s->pos < s->n ? s->d[s->pos++] : 0;
}

static unsigned mote__get16be(mote__src *s)
{
    unsigned hi = mote__get8(s);
    return hi << 8 | mote__get8(s);
}

/* stbi__skip: forward k bytes, no further than the end. */
static void mote__skip(mote__src *s, size_t k)
{
    s->pos = k < s->n - s->pos ? s->pos + k : s->n;
}

static unsigned mote__byte_at(const unsigned char *d, size_t n, size_t i)
{
    return i < n ? d[i] : 0;
}

static uint32_t mote__le16(const unsigned char *d, size_t n, size_t i)
{
    return mote__byte_at(d, n, i) | mote__byte_at(d, n, i + 1) << 8;
}

static uint32_t mote__le32(const unsigned char *d, size_t n, size_t i)
{
    return mote__le16(d, n, i) | mote__le16(d, n, i + 2) << 16;
}

static uint32_t mote__be32(const unsigned char *d, size_t n, size_t i)
{
    return (uint32_t)mote__byte_at(d, n, i) << 24 | (uint32_t)mote__byte_at(d, n, i + 1) << 16 |
           (uint32_t)mote__byte_at(d, n, i + 2) << 8 | mote__byte_at(d, n, i + 3);
}

/* ---- which decoder stb_image will pick --------------------------------- */

typedef enum mote__kind {
    MOTE__OTHER, MOTE__PNG, MOTE__BMP, MOTE__JPEG, MOTE__PNM, MOTE__TGA
} mote__kind;

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

/* The decoder stbi_load_from_memory will use: its tests in its order (PNG,
 * BMP, GIF, PSD, PIC, JPEG, PNM, HDR, TGA), the first that passes. Only
 * the ones with something to check are told apart. */
static mote__kind mote__image_kind(const unsigned char *d, size_t n)
{
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (n >= 8 && memcmp(d, png, 8) == 0)
        return MOTE__PNG;
    if (mote__byte_at(d, n, 0) == 'B' && mote__byte_at(d, n, 1) == 'M') {
        uint32_t hsz = mote__le32(d, n, 14);
        if (hsz == 12 || hsz == 40 || hsz == 56 || hsz == 108 || hsz == 124)
            return MOTE__BMP;
    }
    if (n >= 6 && memcmp(d, "GIF8", 4) == 0 && (d[4] == '7' || d[4] == '9') && d[5] == 'a')
        return MOTE__OTHER;
    if (n >= 4 && memcmp(d, "8BPS", 4) == 0)
        return MOTE__OTHER;
    if (n >= 92 && memcmp(d, "\x53\x80\xF6\x34", 4) == 0 && memcmp(d + 88, "PICT", 4) == 0)
        return MOTE__OTHER;
    if (mote__byte_at(d, n, 0) == 0xff) {
        size_t i = 1;
        while (i < n && d[i] == 0xff)
            i++;
        if (mote__byte_at(d, n, i) == 0xd8)
            return MOTE__JPEG;
    }
    if (mote__byte_at(d, n, 0) == 'P' &&
        (mote__byte_at(d, n, 1) == '5' || mote__byte_at(d, n, 1) == '6'))
        return MOTE__PNM;
    if ((n >= 11 && memcmp(d, "#?RADIANCE\n", 11) == 0) || (n >= 7 && memcmp(d, "#?RGBE\n", 7) == 0))
        return MOTE__OTHER; /* refused by texture.c */
    return mote__is_tga(d, n) ? MOTE__TGA : MOTE__OTHER;
}

/* ---- JPEG --------------------------------------------------------------- */

/* What a check concludes: go on, stb_image will fail here by itself, or
 * the image must be refused (the message is written). */
typedef enum mote__verdict { MOTE__GO, MOTE__STB_FAILS, MOTE__REFUSE } mote__verdict;

#define MOTE__NO_MARKER 0xffu /* stb_image's "no marker" */

typedef struct mote__jhuff {
    bool defined;
    uint16_t count[17];  /* codes of each length, 1..16 */
    uint8_t value[256];  /* symbols in code order */
    uint32_t first[17];  /* first (canonical) code of each length */
    int offset[17];      /* index in value of that code */
    /* codes of up to 9 bits by the 9 bits at the top of the reader: length
     * (0: none) and index in value, as stb_image's lookup table */
    uint8_t fast_len[512];
    uint8_t fast_index[512];
    /* for AC tables, the bits stb_image's combined AC lookup takes at once
     * (0: not in that table) and the zero run it skips */
    uint8_t fac_bits[512];
    uint8_t fac_run[512];
} mote__jhuff;

typedef struct mote__jcomp {
    int id, h, v, tq, td, ta;
    int x, y;       /* samples, as stb_image counts them */
    int32_t pred;   /* DC prediction */
    bool coded;     /* some scan wrote every block of it */
} mote__jcomp;

typedef struct mote__jpeg {
    mote__src s;
    mote__jhuff dc[4], ac[4];
    uint16_t q0[4];  /* each quantisation table's DC step */
    bool qdef[4];
    int restart;
    bool progressive;
    int ncomp, width, height, hmax, vmax, mcux, mcuy;
    mote__jcomp comp[4];
    int scans;
    size_t scan_data; /* where the scan's entropy-coded data starts */
    /* the scan being read */
    int scan_n, order[4], ss, se, ah, al;
    /* stb_image's entropy reader, step for step */
    uint32_t buf;
    int bits;
    bool nomore;
    unsigned marker;
    int todo;
    const mote_limits *limits;
    char *message;
    size_t message_size;
} mote__jpeg;

static mote__verdict mote__jrefuse(mote__jpeg *j, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static mote__verdict mote__jrefuse(mote__jpeg *j, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    mote__io_verror(j->message, j->message_size, MOTE_ERR_PARSE, fmt, ap);
    va_end(ap);
    return MOTE__REFUSE;
}

/* stb_image's get_marker: a marker is 0xff (repeated) and a byte. */
static unsigned mote__jmarker(mote__jpeg *j)
{
    unsigned x = mote__get8(&j->s);
    if (x != 0xff)
        return MOTE__NO_MARKER;
    while (x == 0xff)
        x = mote__get8(&j->s);
    return x;
}

/* A canonical Huffman code from the number of codes of each length 1..max:
 * the first code of each length and the index of its symbol. False where
 * the counts overfill a length, which both of stb_image's builders (JPEG
 * and zlib) refuse. */
static bool mote__canonical(const uint16_t *count, int max, uint32_t *first, int *offset)
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

/* The JPEG table from its counts, refused as stb_image refuses it. */
static bool mote__jhuff_build(mote__jhuff *h, bool ac)
{
    if (!mote__canonical(h->count, 16, h->first, h->offset))
        return false;
    memset(h->fast_len, 0, sizeof h->fast_len);
    memset(h->fac_bits, 0, sizeof h->fac_bits);
    for (int len = 1; len <= 9; len++)
        for (int i = 0; i < h->count[len]; i++) {
            uint32_t base = (h->first[len] + (uint32_t)i) << (9 - len);
            for (uint32_t j = 0; j < (1u << (9 - len)); j++) {
                h->fast_len[base + j] = (uint8_t)len;
                h->fast_index[base + j] = (uint8_t)(h->offset[len] + i);
            }
        }
    if (!ac)
        return true;
    /* stb_image takes a short AC code and the value bits after it in one
     * step when both fit in 9 bits and the value in a signed byte; it then
     * consumes them without asking whether the reader holds that many */
    for (int c = 0; c < 512; c++) {
        int len = h->fast_len[c];
        if (!len)
            continue;
        int rs = h->value[h->fast_index[c]], mag = rs & 15;
        if (!mag || len + mag > 9)
            continue;
        int v = ((c << len) & 511) >> (9 - mag);
        if (v < 1 << (mag - 1))
            v -= (1 << mag) - 1;
        if (v >= -128 && v <= 127) {
            h->fac_bits[c] = (uint8_t)(len + mag);
            h->fac_run[c] = (uint8_t)(rs >> 4);
        }
    }
    return true;
}

/* stb_image's grow_buffer: bytes into the top of a 32-bit reader until it
 * holds more than 24 bits, zeros once a marker has been met. */
static void mote__jgrow(mote__jpeg *j)
{
    do {
        unsigned b = j->nomore ? 0 : mote__get8(&j->s);
        if (b == 0xff) {
            unsigned c = mote__get8(&j->s);
            while (c == 0xff)
                c = mote__get8(&j->s);
            if (c != 0) {
                j->marker = c;
                j->nomore = true;
                return;
            }
        }
        /* b is 0 once bits can be negative (after a marker), where
         * stb_image shifts that 0 by 32 or more (#1293) */
        if (b)
            j->buf |= (uint32_t)b << (24 - j->bits);
        j->bits += 8;
    } while (j->bits <= 24);
}

/* stb_image's Huffman decode: a symbol, or -1 where it reports a bad code. */
static int mote__jdecode(mote__jpeg *j, const mote__jhuff *h)
{
    if (j->bits < 16)
        mote__jgrow(j);
    unsigned c = j->buf >> 23;
    if (h->fast_len[c]) {
        int len = h->fast_len[c];
        if (len > j->bits)
            return -1;
        j->buf <<= len;
        j->bits -= len;
        return h->value[h->fast_index[c]];
    }
    for (int len = 10; len <= 16; len++) {
        uint32_t code = j->buf >> (32 - len);
        if (code >= h->first[len] && code < h->first[len] + h->count[len]) {
            if (len > j->bits)
                return -1;
            /* stb_image tests only the upper bound: a code below
             * first[len] starts with a shorter code, found above */
            int index = h->offset[len] + (int)(code - h->first[len]);
            j->buf <<= len;
            j->bits -= len;
            return h->value[index];
        }
    }
    j->bits -= 16;
    return -1;
}

/* stb_image's extend_receive: n bits (1..15) as a signed JPEG value. */
static int32_t mote__jextend(mote__jpeg *j, int n)
{
    if (j->bits < n)
        mote__jgrow(j);
    uint32_t negative = !(j->buf >> 31);
    uint32_t mask = (1u << n) - 1;
    uint32_t k = j->buf << n | j->buf >> (32 - n);
    j->buf = k & ~mask;
    k &= mask;
    j->bits -= n;
    return (int32_t)k - (negative ? (int32_t)mask : 0);
}

static void mote__jreset(mote__jpeg *j)
{
    j->buf = 0;
    j->bits = 0;
    j->nomore = false;
    for (int i = 0; i < 4; i++)
        j->comp[i].pred = 0;
    j->marker = MOTE__NO_MARKER;
    j->todo = j->restart ? j->restart : 0x7fffffff;
}

/* One block of a baseline scan or of a progressive first DC scan: the bits
 * stb_image takes for it, and the DC arithmetic it does in int. */
static mote__verdict mote__jblock(mote__jpeg *j, int ci)
{
    mote__jcomp *c = &j->comp[ci];
    if (j->progressive && j->se != 0)
        return MOTE__STB_FAILS;
    if (j->bits < 16)
        mote__jgrow(j);
    int t = mote__jdecode(j, &j->dc[c->td]);
    if (t < 0 || t > 15)
        return MOTE__STB_FAILS;
    int64_t dc = (int64_t)c->pred + (t ? mote__jextend(j, t) : 0);
    int64_t scaled = dc * (j->progressive ? (int64_t)1 << j->al : (int64_t)j->q0[c->tq]);
    if (dc < INT_MIN || dc > INT_MAX || scaled < INT_MIN || scaled > INT_MAX)
        return mote__jrefuse(j, "texture: corrupt JPEG: a DC coefficient of component %d "
                             "overflows (stb_image's int arithmetic, CVE-2022-28041)", ci + 1);
    c->pred = (int32_t)dc;
    if (j->progressive)
        return MOTE__GO;
    const mote__jhuff *h = &j->ac[c->ta];
    int k = 1;
    do {
        if (j->bits < 16)
            mote__jgrow(j);
        unsigned top = j->buf >> 23;
        if (h->fac_bits[top]) {
            k += h->fac_run[top] + 1;
            j->buf <<= h->fac_bits[top];
            j->bits -= h->fac_bits[top];
            continue;
        }
        int rs = mote__jdecode(j, h);
        if (rs < 0)
            return MOTE__STB_FAILS;
        int s = rs & 15, r = rs >> 4;
        if (s == 0) {
            if (rs != 0xf0)
                break;
            k += 16;
        } else {
            k += r + 1;
            (void)mote__jextend(j, s); /* |value| < 2^15: its product fits */
        }
    } while (k < 64);
    return MOTE__GO;
}

/* After a unit (a block, or an MCU of an interleaved scan): stb_image's
 * restart countdown. False: it ends the scan here. */
static bool mote__jrestart(mote__jpeg *j)
{
    if (--j->todo > 0)
        return true;
    if (j->bits < 24)
        mote__jgrow(j);
    if (j->marker < 0xd0 || j->marker > 0xd7)
        return false;
    mote__jreset(j);
    return true;
}

/* A baseline scan, or a progressive first DC scan, read as stb_image reads
 * it. A scan that stb_image ends early (a restart interval not followed by
 * a restart marker) leaves the blocks it did not reach as malloc left them,
 * and stb_image shows them. */
static mote__verdict mote__jscan(mote__jpeg *j)
{
    bool complete = true;
    mote__jreset(j);
    if (j->scan_n == 1) {
        int ci = j->order[0];
        int w = (j->comp[ci].x + 7) >> 3, h = (j->comp[ci].y + 7) >> 3;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                mote__verdict v = mote__jblock(j, ci);
                if (v != MOTE__GO)
                    return v;
                if (!mote__jrestart(j)) {
                    complete = y == h - 1 && x == w - 1;
                    goto done;
                }
            }
    } else {
        for (int my = 0; my < j->mcuy; my++)
            for (int mx = 0; mx < j->mcux; mx++) {
                for (int k = 0; k < j->scan_n; k++) {
                    int ci = j->order[k];
                    for (int b = 0; b < j->comp[ci].h * j->comp[ci].v; b++) {
                        mote__verdict v = mote__jblock(j, ci);
                        if (v != MOTE__GO)
                            return v;
                    }
                }
                if (!mote__jrestart(j)) {
                    complete = my == j->mcuy - 1 && mx == j->mcux - 1;
                    goto done;
                }
            }
    }
done:
    if (complete)
        for (int k = 0; k < j->scan_n; k++)
            j->comp[j->order[k]].coded = true;
    return MOTE__GO;
}

/* The marker that ends a scan's entropy-coded data: the first 0xff, 0xff...
 * and a byte that is neither a stuffed 0 nor a restart marker. Where
 * stb_image goes on after a scan, this is the marker it goes on from. */
static unsigned mote__jafter_scan(mote__jpeg *j, size_t start)
{
    const unsigned char *d = j->s.d;
    size_t i = start, n = j->s.n;
    while (i < n) {
        if (d[i++] != 0xff)
            continue;
        while (i < n && d[i] == 0xff)
            i++;
        if (i >= n)
            break;
        unsigned c = d[i++];
        if (c != 0 && (c < 0xd0 || c > 0xd7)) {
            j->s.pos = i;
            return c;
        }
    }
    j->s.pos = n;
    return MOTE__NO_MARKER;
}

/* stb_image's process_marker for the tables, restart interval, APPn and
 * COM segments; anything else fails there. */
static mote__verdict mote__jsegment(mote__jpeg *j, unsigned m)
{
    mote__src *s = &j->s;
    long len;
    switch (m) {
    case 0xdd:
        if (mote__get16be(s) != 4)
            return MOTE__STB_FAILS;
        j->restart = (int)mote__get16be(s);
        return MOTE__GO;
    case 0xdb:
        len = (long)mote__get16be(s) - 2;
        while (len > 0) {
            unsigned q = mote__get8(s), p = q >> 4, t = q & 15;
            if (p > 1 || t > 3)
                return MOTE__STB_FAILS;
            j->q0[t] = (uint16_t)(p ? mote__get16be(s) : mote__get8(s));
            mote__skip(s, 63 * (p + 1));
            j->qdef[t] = true;
            len -= p ? 129 : 65;
        }
        return len == 0 ? MOTE__GO : MOTE__STB_FAILS;
    case 0xc4:
        len = (long)mote__get16be(s) - 2;
        while (len > 0) {
            unsigned q = mote__get8(s), tc = q >> 4, th = q & 15;
            if (tc > 1 || th > 3)
                return MOTE__STB_FAILS;
            mote__jhuff *h = tc ? &j->ac[th] : &j->dc[th];
            int total = 0;
            for (int i = 1; i <= 16; i++)
                total += h->count[i] = (uint16_t)mote__get8(s);
            if (total > 256)
                return mote__jrefuse(j, "texture: corrupt JPEG: Huffman table %s%u holds %d codes, "
                                     "more than 256 (stb_image writes past its tables, "
                                     "CVE-2022-28042)", tc ? "AC" : "DC", th, total);
            if (!mote__jhuff_build(h, false))
                return MOTE__STB_FAILS;
            for (int i = 0; i < total; i++)
                h->value[i] = (uint8_t)mote__get8(s);
            if (tc)
                (void)mote__jhuff_build(h, true);
            h->defined = true;
            len -= 17 + total;
        }
        return len == 0 ? MOTE__GO : MOTE__STB_FAILS;
    default:
        if ((m >= 0xe0 && m <= 0xef) || m == 0xfe) {
            len = (long)mote__get16be(s);
            if (len < 2)
                return MOTE__STB_FAILS;
            mote__skip(s, (size_t)(len - 2));
            return MOTE__GO;
        }
        return MOTE__STB_FAILS;
    }
}

/* stb_image's process_frame_header, as far as the scans need it. */
static mote__verdict mote__jframe(mote__jpeg *j)
{
    mote__src *s = &j->s;
    unsigned lf = mote__get16be(s);
    if (lf < 11 || mote__get8(s) != 8)
        return MOTE__STB_FAILS;
    j->height = (int)mote__get16be(s);
    j->width = (int)mote__get16be(s);
    j->ncomp = (int)mote__get8(s);
    if (!j->height || !j->width || (j->ncomp != 1 && j->ncomp != 3 && j->ncomp != 4) ||
        lf != 8 + 3 * (unsigned)j->ncomp)
        return MOTE__STB_FAILS;
    j->hmax = j->vmax = 1;
    for (int i = 0; i < j->ncomp; i++) {
        mote__jcomp *c = &j->comp[i];
        c->id = (int)mote__get8(s);
        unsigned hv = mote__get8(s);
        c->h = (int)(hv >> 4);
        c->v = (int)(hv & 15);
        c->tq = (int)mote__get8(s);
        if (c->h < 1 || c->h > 4 || c->v < 1 || c->v > 4 || c->tq > 3)
            return MOTE__STB_FAILS;
        j->hmax = c->h > j->hmax ? c->h : j->hmax;
        j->vmax = c->v > j->vmax ? c->v : j->vmax;
    }
    for (int i = 0; i < j->ncomp; i++) {
        mote__jcomp *c = &j->comp[i];
        if (j->hmax % c->h || j->vmax % c->v)
            return MOTE__STB_FAILS;
        c->x = (j->width * c->h + j->hmax - 1) / j->hmax;
        c->y = (j->height * c->v + j->vmax - 1) / j->vmax;
    }
    j->mcux = (j->width + 8 * j->hmax - 1) / (8 * j->hmax);
    j->mcuy = (j->height + 8 * j->vmax - 1) / (8 * j->vmax);
    return MOTE__GO;
}

/* stb_image's process_scan_header, the tables the scan will use, and the
 * scan itself where its bits matter (see mote__jscan). */
static mote__verdict mote__jsos(mote__jpeg *j)
{
    mote__src *s = &j->s;
    unsigned ls = mote__get16be(s);
    j->scan_n = (int)mote__get8(s);
    j->scans++;
    if (j->scan_n < 1 || j->scan_n > 4 || j->scan_n > j->ncomp ||
        ls != 6 + 2 * (unsigned)j->scan_n)
        return MOTE__STB_FAILS;
    for (int i = 0; i < j->scan_n; i++) {
        int id = (int)mote__get8(s), q = (int)mote__get8(s), which = 0;
        while (which < j->ncomp && j->comp[which].id != id)
            which++;
        if (which == j->ncomp || q >> 4 > 3 || (q & 15) > 3)
            return MOTE__STB_FAILS;
        j->comp[which].td = q >> 4;
        j->comp[which].ta = q & 15;
        j->order[i] = which;
    }
    j->ss = (int)mote__get8(s);
    j->se = (int)mote__get8(s);
    unsigned a = mote__get8(s);
    j->ah = (int)(a >> 4);
    j->al = (int)(a & 15);
    if (j->progressive) {
        if (j->ss > 63 || j->se > 63 || j->ss > j->se || j->ah > 13 || j->al > 13)
            return MOTE__STB_FAILS;
    } else {
        if (j->ss != 0 || j->ah != 0 || j->al != 0)
            return MOTE__STB_FAILS;
        j->se = 63;
    }
    /* stb_image does not clear its decoder state: a table no DHT or DQT
     * segment defined is whatever malloc returned */
    bool first_dc = j->progressive && j->ss == 0 && j->ah == 0;
    bool uses_dc = !j->progressive || first_dc, uses_ac = !j->progressive || j->ss != 0;
    for (int i = 0; i < j->scan_n; i++) {
        mote__jcomp *c = &j->comp[j->order[i]];
        bool no_dc = uses_dc && !j->dc[c->td].defined, no_ac = uses_ac && !j->ac[c->ta].defined;
        if (no_dc || no_ac)
            return mote__jrefuse(j, "texture: corrupt JPEG: scan %d uses Huffman table %s%d, which "
                                 "no DHT segment defines (stb_image would read uninitialised "
                                 "memory)", j->scans, no_ac ? "AC" : "DC", no_ac ? c->ta : c->td);
        if (!j->progressive && !j->qdef[c->tq])
            return mote__jrefuse(j, "texture: corrupt JPEG: component %d uses quantisation "
                                 "table %d, which no DQT segment defines (stb_image would read "
                                 "uninitialised memory)", j->order[i] + 1, c->tq);
    }
    j->scan_data = s->pos;
    return !j->progressive || first_dc ? mote__jscan(j) : MOTE__GO;
}

/* stb_image's decode_jpeg_header and decode_jpeg_image, marker by marker. */
static mote__verdict mote__jwalk(mote__jpeg *j)
{
    mote__verdict v;
    (void)mote__jmarker(j); /* SOI: mote__image_kind saw it */
    unsigned m = mote__jmarker(j);
    while (m != 0xc0 && m != 0xc1 && m != 0xc2) {
        if ((v = mote__jsegment(j, m)) != MOTE__GO)
            return v;
        m = mote__jmarker(j);
        while (m == MOTE__NO_MARKER) { /* stb_image skips bytes between segments */
            if (j->s.pos >= j->s.n)
                return MOTE__STB_FAILS;
            m = mote__jmarker(j);
        }
    }
    j->progressive = m == 0xc2;
    if ((v = mote__jframe(j)) != MOTE__GO)
        return v;
    /* An image over the limits is refused by its size before stb_image
     * decodes it (texture.c): its scans are not walked, a block at a time,
     * which for 65528 x 63738 pixels of data past the end of the file took
     * longer than the fuzzer's 15 s */
    if (mote__texture_over_limits(j->limits, (size_t)j->width, (size_t)j->height))
        return MOTE__STB_FAILS;
    m = mote__jmarker(j);
    while (m != 0xd9) {
        if (m == 0xda) {
            if ((v = mote__jsos(j)) != MOTE__GO)
                return v;
            m = mote__jafter_scan(j, j->scan_data);
            if (m == MOTE__NO_MARKER)
                return MOTE__STB_FAILS;
            continue;
        }
        if (m == 0xdc) {
            if (mote__get16be(&j->s) != 4 || (int)mote__get16be(&j->s) != j->height)
                return MOTE__STB_FAILS;
        } else if ((v = mote__jsegment(j, m)) != MOTE__GO) {
            return v;
        }
        m = mote__jmarker(j);
    }
    /* stb_image decodes only what the scans give and then converts every
     * component: one no scan wrote in full is uninitialised memory */
    for (int i = 0; i < j->ncomp; i++) {
        if (!j->comp[i].coded)
            return mote__jrefuse(j, "texture: corrupt JPEG: no scan codes every block of "
                                 "component %d (stb_image would show uninitialised memory)", i + 1);
        if (!j->qdef[j->comp[i].tq])
            return mote__jrefuse(j, "texture: corrupt JPEG: component %d uses quantisation "
                                 "table %d, which no DQT segment defines (stb_image would read "
                                 "uninitialised memory)", i + 1, j->comp[i].tq);
    }
    return MOTE__GO;
}

static mote_result mote__screen_jpeg(const unsigned char *d, size_t n, const mote_limits *limits,
                                     char *message, size_t message_size)
{
    mote__jpeg *j = mote__io_malloc(sizeof *j);
    if (!j)
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "texture: out of memory checking a JPEG");
    memset(j, 0, sizeof *j);
    j->s.d = d;
    j->s.n = n;
    j->limits = limits;
    j->message = message;
    j->message_size = message_size;
    mote__verdict v = mote__jwalk(j);
    mote__io_free(j);
    return v == MOTE__REFUSE ? MOTE_ERR_PARSE : MOTE_OK;
}

/* ---- PNG ---------------------------------------------------------------- */

/* The zlib stream of a PNG (its IDAT chunks end to end), read by the rules
 * of stb_image's inflater without writing the output, only counting it. */
typedef struct mote__zin {
    const unsigned char *z, *end;
    uint32_t buf;
    int bits;
    bool corrupt; /* stb_image's reader met a state it calls corrupt */
    size_t out;
} mote__zin;

typedef struct mote__zhuff {
    uint16_t count[16];
    uint32_t first[16];
    int offset[16];
    uint16_t symbol[288];
    /* codes of up to 9 bits by the next 9 bits of the stream: length << 9 | symbol */
    uint16_t fast[512];
} mote__zhuff;

static unsigned mote__zget8(mote__zin *z)
{
    return z->z < z->end ? *z->z++ : 0;
}

static void mote__zfill(mote__zin *z)
{
    do {
        if (z->bits < 0 || z->buf >> z->bits) {
            /* stb_image sees bits above the count: corrupt, it stops reading
             * (and with a negative count its own test is undefined) */
            z->corrupt = true;
            z->z = z->end;
            return;
        }
        z->buf |= (uint32_t)mote__zget8(z) << z->bits;
        z->bits += 8;
    } while (z->bits <= 24);
}

static unsigned mote__zbits(mote__zin *z, int n)
{
    if (z->bits < n)
        mote__zfill(z);
    unsigned k = z->buf & ((1u << n) - 1);
    z->buf >>= n;
    z->bits -= n;
    return k;
}

/* Canonical codes from lengths, refused as stb_image refuses them. */
static bool mote__zbuild(mote__zhuff *h, const uint8_t *lengths, int num)
{
    memset(h->count, 0, sizeof h->count);
    memset(h->fast, 0, sizeof h->fast);
    for (int i = 0; i < num; i++)
        h->count[lengths[i]]++;
    if (!mote__canonical(h->count, 15, h->first, h->offset))
        return false;
    int next[16];
    for (int len = 1; len < 16; len++)
        next[len] = h->offset[len];
    for (int i = 0; i < num; i++) {
        int len = lengths[i];
        if (!len)
            continue;
        int index = next[len]++;
        h->symbol[index] = (uint16_t)i;
        if (len <= 9) {
            /* the code's bits arrive lowest first: reversed */
            uint32_t c = h->first[len] + (uint32_t)(index - h->offset[len]), r = 0;
            for (int b = 0; b < len; b++)
                r |= ((c >> b) & 1) << (len - 1 - b);
            for (uint32_t j = r; j < 512; j += 1u << len)
                h->fast[j] = (uint16_t)(len << 9 | i);
        }
    }
    return true;
}

/* A symbol, or -1 where stb_image reports a bad code. */
static int mote__zdecode(mote__zin *z, const mote__zhuff *h)
{
    if (z->bits < 16) {
        if (z->z >= z->end)
            return -1;
        mote__zfill(z);
    }
    unsigned f = h->fast[z->buf & 511];
    if (f) {
        z->buf >>= f >> 9;
        z->bits -= (int)(f >> 9);
        return (int)(f & 511);
    }
    uint32_t code = 0;
    for (int len = 1; len < 16; len++) {
        code = code << 1 | ((z->buf >> (len - 1)) & 1);
        if (len > 9 && code < h->first[len] + h->count[len]) {
            z->buf >>= len;
            z->bits -= len;
            return h->symbol[h->offset[len] + (int)(code - h->first[len])];
        }
    }
    return -1;
}

static mote__verdict mote__zcodes(mote__zin *z, mote__zhuff *lit, mote__zhuff *dist)
{
    static const uint8_t order[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    uint8_t lengths[286 + 32 + 137], cl[19] = {0};
    int hlit = (int)mote__zbits(z, 5) + 257, hdist = (int)mote__zbits(z, 5) + 1;
    int hclen = (int)mote__zbits(z, 4) + 4, total = hlit + hdist;
    for (int i = 0; i < hclen; i++)
        cl[order[i]] = (uint8_t)mote__zbits(z, 3);
    if (!mote__zbuild(lit, cl, 19))
        return MOTE__STB_FAILS;
    int n = 0;
    while (n < total) {
        int c = mote__zdecode(z, lit);
        if (c < 0 || c >= 19)
            return MOTE__STB_FAILS;
        if (c < 16) {
            lengths[n++] = (uint8_t)c;
            continue;
        }
        uint8_t fill = 0;
        if (c == 16) {
            c = (int)mote__zbits(z, 2) + 3;
            if (n == 0)
                return MOTE__STB_FAILS;
            fill = lengths[n - 1];
        } else {
            c = c == 17 ? (int)mote__zbits(z, 3) + 3 : (int)mote__zbits(z, 7) + 11;
        }
        if (total - n < c)
            return MOTE__STB_FAILS;
        memset(lengths + n, fill, (size_t)c);
        n += c;
    }
    if (!mote__zbuild(lit, lengths, hlit) || !mote__zbuild(dist, lengths + hlit, hdist))
        return MOTE__STB_FAILS;
    return MOTE__GO;
}

/* The inflate of stb_image up to where it fails or ends; refused where it
 * would meet a length code 286-287 or a distance code 30-31, which DEFLATE
 * forbids: stb_image 2.27 reads a distance of 0 for those and copies the
 * output byte onto itself, so bytes malloc never initialised become
 * pixels (fixed upstream in 2.28). */
static mote__verdict mote__zcheck(mote__zin *z, mote__zhuff *lit, mote__zhuff *dist, bool header,
                                  char *message, size_t message_size)
{
    static const uint16_t len_base[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                          31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
    static const uint8_t len_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                          2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
    static const uint16_t dist_base[30] = {1,    2,    3,    4,    5,    7,     9,     13,    17,  25,
                                           33,   49,   65,   97,   129,  193,   257,   385,   513, 769,
                                           1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
    mote__verdict v = MOTE__STB_FAILS;
    if (header) {
        unsigned cmf = mote__zget8(z), flg = mote__zget8(z);
        if (z->z >= z->end || (cmf * 256 + flg) % 31 || (flg & 32) || (cmf & 15) != 8)
            goto out;
    }
    bool final;
    do {
        final = mote__zbits(z, 1);
        unsigned type = mote__zbits(z, 2);
        if (type == 0) {
            uint8_t head[4];
            int k = 0;
            if (z->bits & 7)
                (void)mote__zbits(z, z->bits & 7);
            while (z->bits > 0) {
                head[k++] = (uint8_t)z->buf;
                z->buf >>= 8;
                z->bits -= 8;
            }
            if (z->bits < 0)
                goto out;
            while (k < 4)
                head[k++] = (uint8_t)mote__zget8(z);
            unsigned len = head[1] * 256u + head[0], nlen = head[3] * 256u + head[2];
            if (nlen != (len ^ 0xffff) || len > (size_t)(z->end - z->z))
                goto out;
            z->z += len;
            z->out += len;
            continue;
        }
        if (type == 3)
            goto out;
        if (type == 1) {
            uint8_t fixed[288];
            memset(fixed, 8, 144);
            memset(fixed + 144, 9, 112);
            memset(fixed + 256, 7, 24);
            memset(fixed + 280, 8, 8);
            (void)mote__zbuild(lit, fixed, 288);
            memset(fixed, 5, 32);
            (void)mote__zbuild(dist, fixed, 32);
        } else if ((v = mote__zcodes(z, lit, dist)) != MOTE__GO) {
            goto out;
        }
        v = MOTE__STB_FAILS;
        for (;;) {
            int c = mote__zdecode(z, lit);
            if (c < 0)
                goto out;
            if (c < 256) {
                z->out++;
                continue;
            }
            if (c == 256)
                break;
            if (c >= 286)
                goto forbidden;
            c -= 257;
            size_t len = len_base[c] + (len_extra[c] ? mote__zbits(z, len_extra[c]) : 0);
            c = mote__zdecode(z, dist);
            if (c < 0)
                goto out;
            if (c >= 30)
                goto forbidden;
            int extra = c < 4 ? 0 : c / 2 - 1;
            size_t back = dist_base[c] + (extra ? mote__zbits(z, extra) : 0);
            if (z->out < back)
                goto out; /* stb_image: "bad dist" */
            z->out += len;
        }
    } while (!final);
    v = MOTE__GO;
    goto out;
forbidden:
    mote__io_error(message, message_size, MOTE_ERR_PARSE,
                   "texture: corrupt PNG: its deflate stream uses a length or distance code that "
                   "DEFLATE forbids (stb_image 2.27 would copy uninitialised memory into the "
                   "pixels)");
    v = MOTE__REFUSE;
out:
    if (z->corrupt && v != MOTE__REFUSE) {
        /* past that state stb_image's reader depends on undefined shifts:
         * refuse rather than guess */
        mote__io_error(message, message_size, MOTE_ERR_PARSE,
                       "texture: corrupt PNG: its deflate stream runs past its end");
        v = MOTE__REFUSE;
    }
    return v;
}

static uint32_t mote__crc32(const unsigned char *p, size_t n, uint32_t crc)
{
    crc = ~crc;
    while (n--) {
        crc ^= *p++;
        for (int k = 0; k < 8; k++)
            crc = crc >> 1 ^ (0xedb88320u & (0u - (crc & 1)));
    }
    return ~crc;
}

/* The PNG's chunks as stb_image's parse_png_file takes them. Checked: the
 * zlib stream (mote__zcheck). Padded: the palette of a colour type 3 image
 * to all 2^depth entries, black, in a copy (*fixed): stb_image keeps the
 * palette in an uninitialised stack array and looks every index up there,
 * so an index past the PLTE chunk's entries shows stack memory (upstream
 * issue #1861, open). Out-of-range indices draw black, as browsers draw
 * them. */
static mote_result mote__screen_png(const unsigned char *d, size_t n, unsigned char **fixed,
                                    size_t *fixed_size, char *message, size_t message_size)
{
    size_t p = 8, idat = 0, short_plte = 0;
    unsigned depth = 0, color = 0, pal_len = 0;
    bool first = true, iphone = false;
    for (;;) {
        if (n - p < 8)
            return MOTE_OK; /* stb_image reads zeros: an unknown critical chunk */
        uint32_t len = mote__be32(d, n, p), type = mote__be32(d, n, p + 4);
        bool whole = len <= n - p - 8 && n - p - 8 - len >= 4;
        if (type == 0x49454e44u) /* IEND */
            break;
        if (type == 0x49444154u && len > n - p - 8)
            /* stb_image fails on it, but first reallocates its buffer to the
             * length the chunk claims, up to 2 GiB for a file of a few bytes */
            return mote__io_error(message, message_size, MOTE_ERR_PARSE,
                                  "texture: truncated PNG: an IDAT chunk of %lu bytes with %zu "
                                  "left in the file", (unsigned long)len, n - p - 8);
        if (!whole)
            return MOTE_OK; /* a chunk cut short: stb_image fails after it */
        const unsigned char *body = d + p + 8;
        if (type == 0x43674249u) { /* CgBI: a raw deflate stream */
            iphone = true;
        } else if (type == 0x49484452u) { /* IHDR */
            if (!first || len != 13)
                return MOTE_OK;
            first = false;
            depth = body[8];
            color = body[9];
            if ((depth != 1 && depth != 2 && depth != 4 && depth != 8 && depth != 16) || color > 6)
                return MOTE_OK; /* stb_image fails */
        } else if (first) {
            return MOTE_OK;
        } else if (type == 0x504c5445u) { /* PLTE */
            if (len > 768 || len % 3)
                return MOTE_OK;
            pal_len = len / 3;
            if (color == 3 && pal_len && pal_len < (1u << depth))
                short_plte++;
        } else if (type == 0x74524e53u) { /* tRNS */
            if (color == 3 && (idat || !pal_len || len > pal_len))
                return MOTE_OK; /* stb_image fails: do not pad it into passing */
        } else if (type == 0x49444154u) { /* IDAT */
            if (color == 3 && !pal_len)
                return MOTE_OK;
            idat += len;
        } else if (!(type & 0x20000000u)) {
            return MOTE_OK; /* an unknown critical chunk */
        }
        p += 12 + (size_t)len;
    }
    if (first || !idat || (color == 3 && depth > 8))
        return MOTE_OK;

    /* the IDAT chunks end to end, as stb_image inflates them */
    mote__zhuff *tables = idat <= SIZE_MAX - 2 * sizeof *tables
                              ? mote__io_malloc(2 * sizeof *tables + idat) : NULL;
    if (!tables)
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "texture: out of memory checking a PNG");
    unsigned char *z = (unsigned char *)(tables + 2);
    size_t at = 0;
    for (size_t q = 8; q < p; q += 12 + (size_t)mote__be32(d, n, q))
        if (mote__be32(d, n, q + 4) == 0x49444154u) {
            memcpy(z + at, d + q + 8, mote__be32(d, n, q));
            at += mote__be32(d, n, q);
        }
    mote__zin in = {z, z + idat, 0, 0, false, 0};
    mote__verdict v = mote__zcheck(&in, tables, tables + 1, !iphone, message, message_size);
    mote__io_free(tables);
    if (v == MOTE__REFUSE)
        return MOTE_ERR_PARSE;
    if (v == MOTE__STB_FAILS || !short_plte)
        return MOTE_OK;

    size_t full = 3u << depth, size = n + short_plte * 768;
    unsigned char *out = mote__io_malloc(size);
    if (!out)
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "texture: out of memory padding a PNG palette");
    size_t o = 0;
    for (size_t q = 0; q < n;) {
        if (q < 8 || q >= p || mote__be32(d, n, q + 4) != 0x504c5445u ||
            mote__be32(d, n, q) >= full || mote__be32(d, n, q) == 0) {
            size_t step = q < 8 ? 8 : q >= p ? n - q : 12 + (size_t)mote__be32(d, n, q);
            memcpy(out + o, d + q, step);
            o += step;
            q += step;
            continue;
        }
        uint32_t len = mote__be32(d, n, q);
        unsigned char *c = out + o;
        c[0] = (unsigned char)(full >> 24);
        c[1] = (unsigned char)(full >> 16);
        c[2] = (unsigned char)(full >> 8);
        c[3] = (unsigned char)full;
        memcpy(c + 4, d + q + 4, 4 + (size_t)len);
        memset(c + 8 + len, 0, full - len);
        uint32_t crc = mote__crc32(c + 4, 4 + full, 0);
        for (int k = 0; k < 4; k++)
            c[8 + full + (size_t)k] = (unsigned char)(crc >> (24 - 8 * k));
        o += 12 + full;
        q += 12 + (size_t)len;
    }
    *fixed = out;
    *fixed_size = o;
    return MOTE_OK;
}

/* ---- BMP ---------------------------------------------------------------- */

/* stb_image's BMP loader keeps the palette in an uninitialised stack array
 * too: it fills the entries between the header and the pixel offset and
 * looks every index up (upstream issue #1929, open), and it takes an offset
 * inside the header for a palette of a negative number of entries, so that
 * none is filled. The first is padded with black entries in a copy, the
 * second refused. */
static mote_result mote__screen_bmp(const unsigned char *d, size_t n, unsigned char **fixed,
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
static mote_result mote__screen_tga(const unsigned char *d, size_t n, char *message,
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
static mote_result mote__screen_pnm(const unsigned char *d, size_t n, char *message,
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

mote_result mote__texture_screen(const unsigned char *data, size_t size, const mote_limits *limits,
                                 unsigned char **fixed, size_t *fixed_size, char *message,
                                 size_t message_size)
{
    *fixed = NULL;
    *fixed_size = 0;
    switch (mote__image_kind(data, size)) {
    case MOTE__JPEG:
        return mote__screen_jpeg(data, size, limits, message, message_size);
    case MOTE__PNG:
        return mote__screen_png(data, size, fixed, fixed_size, message, message_size);
    case MOTE__BMP:
        return mote__screen_bmp(data, size, fixed, fixed_size, message, message_size);
    case MOTE__TGA:
        return mote__screen_tga(data, size, message, message_size);
    case MOTE__PNM:
        return mote__screen_pnm(data, size, message, message_size);
    default:
        return MOTE_OK;
    }
}
