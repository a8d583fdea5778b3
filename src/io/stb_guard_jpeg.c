/*
 * stb_guard_jpeg.c - a JPEG walked as stb_image will decode it (its
 * markers, tables, frame and scans, its entropy reader step for step), to
 * refuse the files that reach its known faults (stb_guard.c).
 */
#include "stb_guard.h"

#include <limits.h>
#include <string.h>

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

/* The JPEG table from its counts, refused as stb_image refuses it. */
static bool mote__jhuff_build(mote__jhuff *h, bool ac)
{
    if (!mote__huffman_canonical(h->count, 16, h->first, h->offset))
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
     * which takes as long as a huge header says even when the file is short */
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

mote_result mote__stb_guard_jpeg(const unsigned char *d, size_t n, const mote_limits *limits,
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

