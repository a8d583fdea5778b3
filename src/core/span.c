/*
 * span.c - the pixel loops: each fill function walks the rows of one
 * triangle inside a region (raster.c's exact edge walk) and runs the pixel
 * loop over each row's span.
 *
 * There is one body, mote__fill_body() with mote__pixels() inside, with its
 * features as parameters. Each specialised variant calls it with constants,
 * so the compiler drops what a draw does not use (no UV work for an
 * untextured draw, no depth reads without a depth test, one shade instead
 * of three for grey light); mote__fill_generic() passes the same features
 * at run time and is both the fallback and the test oracle for every
 * variant (tests/test_spans.c compares them pixel for pixel).
 *
 * A triangle's constants are read once into locals: the colour stores go
 * through a byte pointer, which may alias the triangle, the texture
 * descriptor and the target, and would otherwise force the compiler to
 * reload them after every pixel. Row by row only the plane values at the
 * row start change.
 *
 * On SSE2 hosts the variants do a textured pixel's colour arithmetic in
 * vector registers (MOTE__VECTOR_COLOR): the same sums, on units the
 * integer pixel loop leaves idle. The generic loop stays scalar.
 *
 * MOTE_SPECIALISE_SPANS 0 keeps only the generic loop (small flash): the
 * default of size builds (-Os) and of x86 without SSE2.
 */
#include "internal.h"

#ifndef MOTE_SPECIALISE_SPANS
/* Specialised variants are hundreds of KB of code: worth it where speed
 * is asked for on a host that can run them well, not in a size build
 * (-Os) or on an x86 without SSE2. Define it to 1 to have them anyway. */
#if defined(__OPTIMIZE_SIZE__) || ((defined(__i386__) || defined(__x86_64__)) && !defined(__SSE2__))
#define MOTE_SPECIALISE_SPANS 0
#else
#define MOTE_SPECIALISE_SPANS 1
#endif
#endif

/* Specialised variants need the body inlined with constant features; the
 * generic-only build lets the compiler keep helpers out of line (smaller). */
#if defined(__GNUC__) && MOTE_SPECIALISE_SPANS
#define MOTE__INLINE static inline __attribute__((always_inline))
#define MOTE__SMALL MOTE__INLINE
/* per-attribute loops unrolled, so that a variant keeps only the planes it reads */
#define MOTE__UNROLL _Pragma("GCC unroll 5")
#else
#define MOTE__UNROLL
#define MOTE__INLINE static
/* a few 64-bit steps the pixel loop repeats per attribute: one copy */
#define MOTE__SMALL MOTE__SPEED_INLINE
#endif

/* What the host is, for faster forms with the same results (and
 * format.h's MOTE__LITTLE_ENDIAN): two channels in one multiplication
 * where registers are 64 bits wide (not on 32-bit microcontrollers, where a
 * 64-bit product is a library call). */
#if defined(__SIZEOF_POINTER__) && __SIZEOF_POINTER__ >= 8
#define MOTE__WIDE_REGISTERS 1
#else
#define MOTE__WIDE_REGISTERS 0
#endif

/* Depth buffer selector inside the body, and what a draw does with it. */
enum { MOTE__D_NONE = 0, MOTE__D_16 = 1, MOTE__D_32 = 2 };
enum { MOTE__D_TEST = 1, MOTE__D_WRITE = 2 };

MOTE__INLINE int mote__wrap(int i, int n, mote_wrap mode)
{
    switch (mode) {
    case MOTE_WRAP_CLAMP:
        return i < 0 ? 0 : i >= n ? n - 1 : i;
    case MOTE_WRAP_MIRROR: {
        int m = i % (2 * n);
        if (m < 0)
            m += 2 * n;
        return m < n ? m : 2 * n - 1 - m;
    }
    default:
        if ((n & (n - 1)) == 0)
            return i & (n - 1);
        i %= n;
        return i < 0 ? i + n : i;
    }
}

/* What the loop needs of a texture, in locals (see the top of the file). */
typedef struct mote__tex_view {
    const uint8_t *pixels;
    int stride, w, h;
    int stride_log2;              /* with pow2_repeat: rows by a shift */
    int row_shift;                /* mote__texel_pow2: K - 4 - stride_log2 */
    mote_format format;
    mote_wrap wrap_u, wrap_v;
    bool pow2_repeat;
} mote__tex_view;

/* Row y of a texture. */
MOTE__INLINE const uint8_t *mote__texel_row(const mote__tex_view *tx, bool pow2_repeat, size_t y)
{
    /* the generic-only build keeps the one multiplication (less flash) */
    bool shift = MOTE_SPECIALISE_SPANS && pow2_repeat;
    return tx->pixels + (shift ? y << tx->stride_log2 : y * (size_t)tx->stride);
}

/* The texel nearest to (u, v), in 16.16 texels: its row, and its column in *col. */
MOTE__INLINE const uint8_t *mote__nearest(const mote__tex_view *tx, bool pow2_repeat, int64_t u, int64_t v,
                                          size_t *col)
{
    size_t tv;
    if (pow2_repeat) {
        *col = (size_t)(u >> 16) & (size_t)(tx->w - 1);
        tv = (size_t)(v >> 16) & (size_t)(tx->h - 1);
    } else {
        *col = (size_t)mote__wrap((int)(u >> 16), tx->w, tx->wrap_u);
        tv = (size_t)mote__wrap((int)(v >> 16), tx->h, tx->wrap_v);
    }
    return mote__texel_row(tx, pow2_repeat, tv);
}

/* The four texels bilinear filtering blends at (u, v), in 16.16 texels:
 * columns u0 and u1 of rows row0 and row1, weighted by fu and fv, the
 * 8-bit fractions of the way from u0 to u1 and row0 to row1. The pixel
 * loop keeps a nearest texel in row0 and u0. */
typedef struct mote__taps {
    const uint8_t *row0, *row1;
    size_t u0, u1;
    uint32_t fu, fv;
} mote__taps;

MOTE__INLINE mote__taps mote__bilinear_taps(const mote__tex_view *tx, bool pow2_repeat, int64_t u, int64_t v)
{
    u -= 0x8000;
    v -= 0x8000;
    /* the next column and row from the 64-bit value: iu + 1 overflowed int
     * where garbage texels (a hostile texel range) made iu INT_MAX */
    int iu = (int)(u >> 16), iv = (int)(v >> 16), iu1 = (int)((u >> 16) + 1), iv1 = (int)((v >> 16) + 1);
    mote__taps t;
    t.fu = (uint32_t)(u >> 8) & 0xff;
    t.fv = (uint32_t)(v >> 8) & 0xff;
    int u0, u1, v0, v1;
    if (pow2_repeat) {
        u0 = iu & (tx->w - 1);
        u1 = iu1 & (tx->w - 1);
        v0 = iv & (tx->h - 1);
        v1 = iv1 & (tx->h - 1);
    } else {
        u0 = mote__wrap(iu, tx->w, tx->wrap_u);
        u1 = mote__wrap(iu1, tx->w, tx->wrap_u);
        v0 = mote__wrap(iv, tx->h, tx->wrap_v);
        v1 = mote__wrap(iv1, tx->h, tx->wrap_v);
    }
    t.u0 = (size_t)u0;
    t.u1 = (size_t)u1;
    t.row0 = mote__texel_row(tx, pow2_repeat, (size_t)v0);
    t.row1 = mote__texel_row(tx, pow2_repeat, (size_t)v1);
    return t;
}

/* Bilinear's blend of the four taps' texels, channel by channel. */
MOTE__INLINE void mote__blend(mote_format format, const mote__taps *t, uint32_t c[3])
{
    uint32_t a[3], b[3], d[3], e[3];
    mote__texel(format, t->row0, t->u0, a);
    mote__texel(format, t->row0, t->u1, b);
    mote__texel(format, t->row1, t->u0, d);
    mote__texel(format, t->row1, t->u1, e);
    const uint32_t fu = t->fu, fv = t->fv;
    for (int k = 0; k < 3; k++)
        c[k] = (a[k] * (256 - fu) * (256 - fv) + b[k] * fu * (256 - fv) + d[k] * (256 - fu) * fv
                + e[k] * fu * fv + 32768) >> 16;
}

/* A plane's value d steps (of one axis) from base. The value at a pixel of
 * the triangle fits in 64 bits, but d * step alone may not (the origin can
 * lie far outside the viewport, and the row and column terms then nearly
 * cancel), so the sum is formed in modular unsigned arithmetic, which is
 * exact whenever the result fits. */
MOTE__INLINE int64_t mote__plane_at(int64_t base, int64_t step, int64_t d)
{
    return (int64_t)((uint64_t)base + (uint64_t)step * (uint64_t)d);
}

/* The next pixel's value, modular for the same reason: a plane may leave
 * 64 bits past a row's last pixel, or inside a hostile triangle whose
 * texel range makes its numerator planes wrap (its texels are garbage
 * then, by design, but the loop stays defined). */
MOTE__INLINE int64_t mote__plane_next(int64_t value, int64_t step)
{
    return (int64_t)((uint64_t)value + (uint64_t)step);
}

/* 2^k / (q >> 10), for q a value of the triangle's Q plane (setup.c's
 * mote__q_plane: q >> 10 is Q >> shift): the one division per pixel. */
MOTE__SMALL uint64_t mote__recip_k(int64_t q, int k)
{
    uint64_t qs = (uint64_t)(q >> 10);
    if (qs == 0)                  /* never inside a sane triangle: a branch, not a select */
        return (uint64_t)1 << k;
    return ((uint64_t)1 << k) / qs;
}

/* An attribute from its numerator plane value n and r (see setup.c): one
 * multiplication. Modular, so a hostile triangle gives garbage, not UB. */
MOTE__SMALL int64_t mote__attr(int64_t a0, int64_t n, uint64_t r, int k)
{
    return a0 + ((int64_t)((uint64_t)(n >> 10) * r) >> (k - 20));
}

/* The nearest texel of a repeating power-of-two texture, from the texel
 * coordinates' numerator planes: its row, and its column in *col.
 * u = a0 + P / 2^(k-20) with P = (n >> 10) r (mote__attr), and the texel
 * column is (u >> 16) & (w - 1): that is bits k-4 and up of
 * a0 2^(k-20) + P, which in modular 64-bit arithmetic are right as long as
 * they lie below bit 64, w <= 2^(68-k) (the raster state keeps pow2_repeat
 * for textures up to that). One addition and one shift instead of two
 * shifts, and the row's byte offset straight from v's sum. */
MOTE__INLINE const uint8_t *mote__texel_pow2(const mote__tex_view *tx, const uint64_t origin[2], int64_t nu,
                                             int64_t nv, uint64_t r, int k, size_t *col)
{
    uint64_t su = origin[0] + (uint64_t)(nu >> 10) * r, sv = origin[1] + (uint64_t)(nv >> 10) * r;
    *col = (size_t)(su >> (k - 4)) & (size_t)(tx->w - 1);
    /* the row's offset (v's texel << stride_log2) is those bits of sv moved down less far */
    return tx->pixels + ((size_t)(sv >> tx->row_shift) & ((size_t)(tx->h - 1) << tx->stride_log2));
}

/* (c * s + 2^23) >> 24 for a channel c <= 255 and a shade s in [0, 2^24]
 * (callers clamp an interpolated shade: rounding can take it a little out
 * of range); unsigned, since 255 * 2^24 does not fit in int32. */
MOTE__INLINE uint32_t mote__modulate(uint32_t c, uint32_t s)
{
    return (c * s + (1u << 23)) >> 24;
}

/* mote__modulate of three channels by one shade, for 64-bit registers: r
 * and b share one product in 32-bit lanes (c s + 2^23 < 2^32, so no lane
 * carries into the next, and each lane's bits 24..31 are its result). */
MOTE__INLINE void mote__modulate_grey(uint32_t c[3], uint32_t s)
{
    uint64_t rb = ((uint64_t)c[2] << 32 | c[0]) * s + ((uint64_t)1 << 55 | 1u << 23);
    c[0] = (uint32_t)(rb >> 24) & 0xff;
    c[1] = mote__modulate(c[1], s);
    c[2] = (uint32_t)(rb >> 56);
}

/* MOTE__VECTOR_COLOR: vector registers (SSE2) for the colour arithmetic
 * of textured pixels with RGBA8888 texels and target: the pixel loop runs
 * short of integer ALUs, not of vector ones (Suzanne textured, nearest:
 * 0.93x the time at 640x480, 0.86x at 1920x1080; bilinear 0.77x and
 * 0.65x). A texel's channels r, g, b, a are lanes of one register, and
 * each result is the scalar code's, channel by channel. Only the
 * specialised variants use them: the generic loop stays their oracle. */
#if MOTE_SPECIALISE_SPANS && MOTE__LITTLE_ENDIAN && defined(__SSE2__)
#include <emmintrin.h>
#define MOTE__VECTOR_COLOR 1

/* A texel word's channels, as 16-bit lanes 0-3. */
MOTE__INLINE __m128i mote__word_channels(uint32_t texel)
{
    return _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)texel), _mm_setzero_si128());
}

/* mote__blend's sums for texel words a, b (row 0) and d, e
 * (row 1): each row's a (256 - fu) + b fu < 2^16 by one pmaddwd of 16-bit
 * lanes a_r b_r a_g b_g ..., then the rows weighted by 256 - fv and fv in
 * 64-bit lanes (red and blue, then green and alpha); the channels as the
 * 16-bit lanes 0-3, as mote__word_channels gives them. */
MOTE__INLINE __m128i mote__blend_channels(uint32_t a, uint32_t b, uint32_t d, uint32_t e, uint32_t fu, uint32_t fv)
{
    const __m128i zero = _mm_setzero_si128(), wu = _mm_set1_epi32((int)(fu << 16 | (256 - fu)));
    const __m128i wv0 = _mm_set1_epi32((int)(256 - fv)), wv1 = _mm_set1_epi32((int)fv);
    const __m128i half = _mm_set1_epi64x(32768);
    __m128i ab = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)a), _mm_cvtsi32_si128((int)b));
    __m128i de = _mm_unpacklo_epi8(_mm_cvtsi32_si128((int)d), _mm_cvtsi32_si128((int)e));
    __m128i top = _mm_madd_epi16(_mm_unpacklo_epi8(ab, zero), wu);   /* 32-bit lanes r, g, b, a */
    __m128i bottom = _mm_madd_epi16(_mm_unpacklo_epi8(de, zero), wu);
    __m128i rb = _mm_add_epi64(_mm_add_epi64(_mm_mul_epu32(top, wv0), _mm_mul_epu32(bottom, wv1)), half);
    top = _mm_srli_epi64(top, 32);
    bottom = _mm_srli_epi64(bottom, 32);
    __m128i ga = _mm_add_epi64(_mm_add_epi64(_mm_mul_epu32(top, wv0), _mm_mul_epu32(bottom, wv1)), half);
    const __m128i c32 = _mm_or_si128(_mm_srli_epi64(rb, 16), _mm_slli_epi64(_mm_srli_epi64(ga, 16), 32));
    return _mm_packs_epi32(c32, c32);
}

/* Channels c (16-bit lanes 0-3) modulated by shades s (mote__modulate) and
 * packed as an RGBA8888 pixel, alpha 255, in 16-bit lanes: with
 * s = sh 2^16 + sl (sh <= 256, and sl = 0 when sh = 256),
 *     c s + 2^23 = 2^16 (c sh + (c sl >> 16) + 2^7) + (c sl mod 2^16),
 * so (c s + 2^23) >> 24 = (c sh + (c sl >> 16) + 128) >> 8, a sum below
 * 2^16 (c sh <= 65025 when sl > 0): one pmullw and one pmulhuw. */
MOTE__INLINE uint32_t mote__modulate_channels(__m128i c, __m128i sh, __m128i sl)
{
    __m128i sum = _mm_add_epi16(_mm_mullo_epi16(c, sh), _mm_mulhi_epu16(c, sl));
    sum = _mm_srli_epi16(_mm_add_epi16(sum, _mm_set1_epi16(128)), 8);
    return (uint32_t)_mm_cvtsi128_si32(_mm_packus_epi16(sum, sum)) | 0xff000000u;
}

/* The shade lanes mote__modulate_channels multiplies by: each shade's high
 * and low 16 bits. A shade's 32 bits are its two halves as 16-bit lanes
 * (sl, sh), so one shade is spread by word shuffles. */
MOTE__INLINE void mote__shade_lanes(int shade, uint32_t sr, uint32_t sg, uint32_t sb, __m128i *sh, __m128i *sl)
{
    if (shade == MOTE__SHADE_MONO) {
        __m128i s = _mm_cvtsi32_si128((int)sr);
        *sh = _mm_shufflelo_epi16(s, 0x55);
        *sl = _mm_shufflelo_epi16(s, 0x00);
    } else {
        /* 32-bit lanes sr, sg, sb, split into halves and packed to
         * 16-bit lanes 0-2: the low halves sign-extended, so that the
         * signed pack keeps their bits */
        __m128i s = _mm_unpacklo_epi64(_mm_unpacklo_epi32(_mm_cvtsi32_si128((int)sr), _mm_cvtsi32_si128((int)sg)),
                                       _mm_cvtsi32_si128((int)sb));
        __m128i lo = _mm_srai_epi32(_mm_slli_epi32(s, 16), 16), hi = _mm_srli_epi32(s, 16);
        *sl = _mm_packs_epi32(lo, lo);
        *sh = _mm_packs_epi32(hi, hi);
    }
}

/* The RGBA8888 word at column x of a texture row. */
MOTE__INLINE uint32_t mote__word(const uint8_t *row, size_t x)
{
    uint32_t v;
    memcpy(&v, row + 4 * x, 4);
    return v;
}
#else
#define MOTE__VECTOR_COLOR 0
#endif

MOTE__SMALL uint32_t mote__clamp_shade(int64_t v)
{
    /* one test for the usual in-range value, as for depth */
    if ((uint64_t)v > MOTE__SHADE_ONE)
        return v < 0 ? 0u : (uint32_t)MOTE__SHADE_ONE;
    return (uint32_t)v;
}

/* An interpolated shade, clamped. */
MOTE__SMALL uint32_t mote__shade_at(int64_t a0, int64_t n, uint64_t r, int k)
{
    return mote__clamp_shade(mote__attr(a0, n, r, k));
}

/* What the pixel loop needs of a triangle, read once per triangle into
 * locals (see the top of the file). */
typedef struct mote__fill_ctx {
    int64_t zdx, qdx;
    /* the numerator planes: origin value, x and y steps (0 for those the
     * triangle lacks: a binned record ends after its last plane) */
    int64_t n0[MOTE__ATTRS], ndx[MOTE__ATTRS], ndy[MOTE__ATTRS];
    int64_t a0[MOTE__ATTRS];
    uint32_t flat_px;             /* the pixel when nothing varies */
    uint32_t sr, sg, sb;          /* the shade when it does not vary */
    mote__tex_view tx;
    uint64_t tex_origin[2];       /* mote__texel_pow2: a0 of u and v, times 2^(k-20) */
    int seg_log2;                 /* sub-span: segments of 2^seg_log2 columns */
    uint64_t affine_r;            /* affine: all qi are 1, Q is (nearly) constant: one r */
} mote__fill_ctx;

/* One row: pixels [x0, x1) given the planes' values at x0 (z, Q and the
 * numerator planes n[]). Adds the pixels the depth test rejects to
 * *rejected (rare: counted rather than the written ones). */
MOTE__INLINE void mote__pixels(const mote__fill_ctx *c, uint8_t *crow, uint16_t *d16, uint32_t *d32,
                               ptrdiff_t x0, ptrdiff_t x1, int64_t z, int64_t q, const int64_t n[MOTE__ATTRS],
                               const int64_t span[2], uint32_t *rejected, const int tex, const mote_format tfmt, const bool pow2,
                               const int shade, const int persp, const int dsel, const int dmode,
                               const mote_format fmt, const int k)
{
    const bool varying = shade != MOTE__SHADE_FLAT || tex;
    const int64_t zdx = c->zdx, qdx = c->qdx;
    int64_t nr = n[MOTE__A_R], ng = n[MOTE__A_G], nb = n[MOTE__A_B], nu = n[MOTE__A_U], nv = n[MOTE__A_V];
    const int64_t nrdx = c->ndx[MOTE__A_R], ngdx = c->ndx[MOTE__A_G], nbdx = c->ndx[MOTE__A_B];
    const int64_t nudx = c->ndx[MOTE__A_U], nvdx = c->ndx[MOTE__A_V];
    uint32_t sr = c->sr, sg = c->sg, sb = c->sb;
    /* sub-span: r exact at screen columns that are multiples of 2^seg_log2
     * and at the row's ends, linear between, so where a region starts a
     * row changes nothing */
    uint64_t seg_r0 = 0, seg_r1 = 0;
    int64_t seg_step = 0;
    ptrdiff_t seg_x0 = 0, seg_x1 = 0, seg_next = x0;   /* r's ends; where the next segment starts */
    bool seg_exact = true;        /* until a segment with both ends valid: no r1 to reuse */
    /* Speed builds index the buffers from the row's end, i = x - x1 < 0:
     * one counter for both and no end to compare with, a register fewer
     * in a loop that spills. The generic-only build indexes from the row's
     * start (base 0: less code on a 32-bit core). */
    const ptrdiff_t base = MOTE_SPECIALISE_SPANS ? x1 : 0;
    uint8_t *const cb = crow + base * mote__format_bytes(fmt);
    uint16_t *const d16b = MOTE_SPECIALISE_SPANS && dsel == MOTE__D_16 ? d16 + base : d16;   /* NULL unless used */
    uint32_t *const d32b = MOTE_SPECIALISE_SPANS && dsel == MOTE__D_32 ? d32 + base : d32;

    for (ptrdiff_t i = x0 - base; i < x1 - base; i++, z = mote__plane_next(z, zdx), q = mote__plane_next(q, qdx),
                                                   nr = mote__plane_next(nr, nrdx), ng = mote__plane_next(ng, ngdx),
                                                   nb = mote__plane_next(nb, nbdx), nu = mote__plane_next(nu, nudx),
                                                   nv = mote__plane_next(nv, nvdx)) {
        uint32_t depth = 0;
        if (dsel != MOTE__D_NONE) {
            /* z is a convex combination of in-range depths: only rounding
             * at an edge can take it a unit outside, so test before clamping */
            int64_t zz = z >> MOTE__DEPTH_FRAC;
            depth = (uint32_t)zz;
            if ((uint64_t)zz > MOTE__DEPTH_MAX)
                depth = zz < 0 ? 0u : MOTE__DEPTH_MAX;
            if (dsel == MOTE__D_16)
                depth >>= 8;
            if ((dmode & MOTE__D_TEST) && depth >= (dsel == MOTE__D_16 ? (uint32_t)d16b[i] : d32b[i])) {
                (*rejected)++;
                continue;
            }
        }
        uint32_t px = c->flat_px;
        if (varying) {
            uint64_t r;
            if (MOTE_ENABLE_SUBSPAN && persp == MOTE__PERSP_SUBSPAN) {
                const ptrdiff_t x = base + i;
                if (x >= seg_next) {
                    /* r is exact at the segment's ends, cut to the
                     * triangle's own row: past its edges Q may be
                     * anything (across a sliver's edge it moves by far
                     * more than its whole range inside, within a pixel),
                     * and r from it garbage. The row's span, not the
                     * region's cut of it, so that a region changes
                     * nothing. The start's r is the last segment's end's,
                     * unless depth-rejected pixels skipped a segment. */
                    const ptrdiff_t len = (ptrdiff_t)1 << c->seg_log2, start = x & -len;
                    const ptrdiff_t first = start > span[0] ? start : (ptrdiff_t)span[0];
                    const bool reuse = !seg_exact && first == seg_x1;
                    seg_next = start + len;
                    seg_x0 = first;
                    seg_x1 = seg_next < span[1] - 1 ? seg_next : (ptrdiff_t)span[1] - 1;
                    seg_exact = seg_x1 <= seg_x0;
                    if (!seg_exact) {
                        seg_r0 = reuse ? seg_r1 : mote__recip_k(mote__plane_at(q, qdx, seg_x0 - x), k);
                        seg_r1 = mote__recip_k(mote__plane_at(q, qdx, seg_x1 - x), k);
                        /* (r1 - r0) / length, rounded toward zero: by a
                         * shift for a whole segment */
                        int64_t d = (int64_t)seg_r1 - (int64_t)seg_r0;
                        seg_step = seg_x1 - seg_x0 == len
                                 ? mote__floor_shift64(d + ((len - 1) & -(int64_t)(d < 0)), c->seg_log2)
                                 : d / (int64_t)(seg_x1 - seg_x0);
                    }
                }
                r = seg_exact ? mote__recip_k(q, k) : seg_r0 + (uint64_t)(seg_step * (x - seg_x0));
            } else {
                r = persp == MOTE__PERSP_AFFINE ? c->affine_r : mote__recip_k(q, k);
            }
            if (shade == MOTE__SHADE_MONO) {
                sr = sg = sb = mote__shade_at(c->a0[MOTE__A_R], nr, r, k);
            } else if (shade == MOTE__SHADE_RGB) {
                sr = mote__shade_at(c->a0[MOTE__A_R], nr, r, k);
                sg = mote__shade_at(c->a0[MOTE__A_G], ng, r, k);
                sb = mote__shade_at(c->a0[MOTE__A_B], nb, r, k);
            }
            if (tex) {
                /* where the texel lies, or bilinear's four (nearest: row0, u0) */
                const bool bilinear = MOTE_ENABLE_BILINEAR && tex == MOTE__TEX_BILINEAR;
                mote__taps p;
                if (MOTE_SPECIALISE_SPANS && !bilinear && pow2) {
                    p.row0 = mote__texel_pow2(&c->tx, c->tex_origin, nu, nv, r, k, &p.u0);
                } else {
                    const int64_t u = mote__attr(c->a0[MOTE__A_U], nu, r, k), v = mote__attr(c->a0[MOTE__A_V], nv, r, k);
                    if (bilinear)
                        p = mote__bilinear_taps(&c->tx, pow2, u, v);
                    else
                        p.row0 = mote__nearest(&c->tx, pow2, u, v, &p.u0);
                }
                /* vector registers only where the texture's format is a
                 * constant: the specialised variants, not their oracle,
                 * the generic loop */
                if (MOTE__VECTOR_COLOR && tfmt == MOTE_FORMAT_RGBA8888 && fmt == MOTE_FORMAT_RGBA8888) {
#if MOTE__VECTOR_COLOR
                    __m128i t = bilinear ? mote__blend_channels(mote__word(p.row0, p.u0), mote__word(p.row0, p.u1),
                                                                mote__word(p.row1, p.u0), mote__word(p.row1, p.u1),
                                                                p.fu, p.fv)
                                         : mote__word_channels(mote__word(p.row0, p.u0));
                    __m128i sh, sl;
                    mote__shade_lanes(shade, sr, sg, sb, &sh, &sl);
                    px = mote__modulate_channels(t, sh, sl);
#endif
                } else {
                    uint32_t t[3];
                    if (bilinear)
                        mote__blend(c->tx.format, &p, t);
                    else
                        mote__texel(c->tx.format, p.row0, p.u0, t);
                    /* a flat shade takes three products: testing for grey
                     * at every pixel costs what the shared product saves */
                    if (MOTE__WIDE_REGISTERS && shade == MOTE__SHADE_MONO) {
                        mote__modulate_grey(t, sr);
                    } else {
                        t[0] = mote__modulate(t[0], sr);
                        t[1] = mote__modulate(t[1], sg);
                        t[2] = mote__modulate(t[2], sb);
                    }
                    px = mote__pack(fmt, t[0], t[1], t[2]);
                }
            } else {
                px = mote__pack(fmt, mote__modulate(255, sr), mote__modulate(255, sg), mote__modulate(255, sb));
            }
        }
        mote__store(cb, i, fmt, px);
        if (dsel != MOTE__D_NONE && (dmode & MOTE__D_WRITE)) {
            if (dsel == MOTE__D_16)
                d16b[i] = (uint16_t)depth;
            else
                d32b[i] = depth;
        }
    }
}

/* Whether a pixel loop of this kind steps attribute a's plane: the ones
 * setup made (constant arguments drop the rest at compile time). */
MOTE__INLINE bool mote__reads_plane(int a, int shade, int tex)
{
    if (!MOTE_SPECIALISE_SPANS)   /* one loop for all: fewer tests, less flash */
        return shade != MOTE__SHADE_FLAT || tex != MOTE__TEX_NONE;
    return mote__has_plane(a, (mote__shade_kind)shade, tex != MOTE__TEX_NONE);
}

/* Row by row: the edge walk, then the pixel loop over the row's span. The
 * planes are stepped down from their values at column ox of the first
 * row (unsigned: exact modulo 2^64, see mote__plane_at). */
MOTE__INLINE void mote__rows(const mote__fill_ctx *c, mote__walk *w, const mote__tri *t, const mote__target *tg,
                             const int tex, const mote_format tfmt, const bool pow2, const int shade,
                             const int persp, const int dsel, const int dmode, const mote_format fmt, const int k)
{
    const bool varying = shade != MOTE__SHADE_FLAT || tex;
    /* the rows' colour and depth, stepped row by row (a product a row
     * cost more) */
    const size_t stride = (size_t)tg->stride, zstride = (size_t)tg->width * (dsel == MOTE__D_16 ? 2 : 4);
    uint8_t *crow = tg->color + (size_t)(w->y - tg->y0) * stride;
    uint8_t *zrow = dsel != MOTE__D_NONE ? (uint8_t *)tg->depth + (size_t)(w->y - tg->y0) * zstride : NULL;
    const int64_t dy0 = w->y - t->oy;
    const int64_t zdy = t->zdy, qdy = t->qdy;
    uint64_t zr = (uint64_t)mote__plane_at(t->z, zdy, dy0);
    uint64_t qr = 0, nrow[MOTE__ATTRS] = {0};
    if (varying) {
        qr = (uint64_t)mote__plane_at(t->q, qdy, dy0);
        MOTE__UNROLL
        for (int a = 0; a < MOTE__ATTRS; a++)
            if (mote__reads_plane(a, shade, tex))
                nrow[a] = (uint64_t)mote__plane_at(c->n0[a], c->ndy[a], dy0);
    }
    const int ox = t->ox;
    /* written = tested - rejected, once per call: counted row by row, it
     * cost 0.8% of the grid's instructions */
    uint64_t tested = 0;
    uint32_t rejected = 0;
    for (; w->y < w->yend; zr += (uint64_t)zdy, qr += (uint64_t)qdy, crow += stride) {
        int x0, x1;
        int64_t span[2];
        mote__walk_row(w, &x0, &x1, span);
        if (x0 < x1) {
            const int64_t dx0 = x0 - ox;
            int64_t n[MOTE__ATTRS] = {0};
            MOTE__UNROLL
            for (int a = 0; a < MOTE__ATTRS; a++)
                if (mote__reads_plane(a, shade, tex))
                    n[a] = mote__plane_at((int64_t)nrow[a], c->ndx[a], dx0);
            /* counted before the pixel loop: after it, x0 and x1 would
             * have to outlive a loop that needs every register */
            tested += (uint64_t)(x1 - x0);
            mote__pixels(c, crow, dsel == MOTE__D_16 ? (uint16_t *)(void *)zrow : NULL,
                         dsel == MOTE__D_32 ? (uint32_t *)(void *)zrow : NULL, x0, x1,
                         mote__plane_at((int64_t)zr, c->zdx, dx0),
                         varying ? mote__plane_at((int64_t)qr, c->qdx, dx0) : 0, n, span, &rejected,
                         tex, tfmt, pow2, shade, persp, dsel, dmode, fmt, k);
        }
        MOTE__UNROLL
        for (int a = 0; a < MOTE__ATTRS; a++)
            if (mote__reads_plane(a, shade, tex))
                nrow[a] += (uint64_t)c->ndy[a];
        /* a constant test in the variants; the shortest code in the
         * generic-only build (flash) */
        if (MOTE_SPECIALISE_SPANS ? dsel != MOTE__D_NONE : zrow != NULL)
            zrow += zstride;
    }
    tg->counts->tested += tested;
    tg->counts->written += tested - rejected;
}

/* A whole triangle inside region r: its constants once, then the rows.
 * tfmt: the texture's format when known at compile time (the specialised
 * variants take RGBA8888 textures), MOTE_FORMAT_DEFAULT to read it.
 * fixed_k: the reciprocal's K when known at compile time (the specialised
 * variants take MOTE__RBITS, what all but huge-range triangles have), 0 to
 * read it. */
MOTE__INLINE void mote__fill_body(const mote__tri *t, const mote__target *tg, mote__rect r, int F,
                                  const int tex, const mote_format tfmt, const int shade, const int persp,
                                  const int dsel, const int dmode, const mote_format fmt, const int fixed_k)
{
    if (fixed_k && t->rbits != fixed_k) {
        mote__fill_generic(t, tg, r, F);
        return;
    }
    mote__walk w;
    if (!mote__walk_begin(&w, t, r, F))
        return;
    const mote__raster_state *rs = t->rs;
    const bool varying = shade != MOTE__SHADE_FLAT || tex;
    const int k = fixed_k ? fixed_k : t->rbits;
    /* field by field: a memset of the whole context was 3.5% of the dense
     * grid's instructions, whose triangles have a dozen pixels each */
    mote__fill_ctx c;
    c.zdx = t->zdx;
    c.qdx = t->qdx;
    /* only binned records are cut short: drawn directly, t has them all */
    const int planes = MOTE_ENABLE_BINNING ? mote__plane_count(shade, tex != MOTE__TEX_NONE) : MOTE__ATTRS;
    for (int a = 0; a < MOTE__ATTRS; a++) {
        c.a0[a] = t->a0[a];
        /* the generic loop reads every plane the record holds */
        const bool has = a < planes && (!MOTE_SPECIALISE_SPANS || mote__reads_plane(a, shade, tex));
        c.n0[a] = has ? t->n[a][0] : 0;
        c.ndx[a] = has ? t->n[a][1] : 0;
        c.ndy[a] = has ? t->n[a][2] : 0;
    }
    /* without Gouraud the shade is the triangle's; without a texture too,
     * the pixel value is one constant */
    c.sr = mote__clamp_shade(c.a0[MOTE__A_R]);
    c.sg = mote__clamp_shade(c.a0[MOTE__A_G]);
    c.sb = mote__clamp_shade(c.a0[MOTE__A_B]);
    c.flat_px = mote__pack(fmt, mote__modulate(255, c.sr), mote__modulate(255, c.sg), mote__modulate(255, c.sb));
    c.tex_origin[0] = c.tex_origin[1] = 0;
    if (!tex) {
        const mote__tex_view none = {0};
        c.tx = none;
    } else {
        c.tx.pixels = (const uint8_t *)rs->texture->pixels;
        c.tx.format = tfmt != MOTE_FORMAT_DEFAULT ? tfmt : rs->texture->format;
        c.tx.stride = rs->tex_stride;
        c.tx.w = rs->tex_w;
        c.tx.h = rs->tex_h;
        c.tx.wrap_u = rs->wrap_u;
        c.tx.wrap_v = rs->wrap_v;
        c.tx.pow2_repeat = rs->pow2_repeat;
        c.tx.stride_log2 = rs->tex_stride_log2;
        if (MOTE_SPECIALISE_SPANS) {
            /* once a triangle: worked out in the row loop, it took a
             * register the pixel loop then lacked */
            c.tx.row_shift = k - 4 - c.tx.stride_log2;
            c.tex_origin[0] = (uint64_t)c.a0[MOTE__A_U] << (k - 20);
            c.tex_origin[1] = (uint64_t)c.a0[MOTE__A_V] << (k - 20);
        }
    }
    c.seg_log2 = MOTE_ENABLE_SUBSPAN ? rs->subspan_log2 : 0;
    c.affine_r = varying && persp == MOTE__PERSP_AFFINE ? mote__recip_k(t->q, k) : 0;
#if MOTE_SPECIALISE_SPANS
    /* a power-of-two repeating texture: its own loop, texel addresses by masks */
    if (tex && c.tx.pow2_repeat) {
        mote__rows(&c, &w, t, tg, tex, tfmt, true, shade, persp, dsel, dmode, fmt, k);
        return;
    }
#endif
    mote__rows(&c, &w, t, tg, tex, tfmt, c.tx.pow2_repeat, shade, persp, dsel, dmode, fmt, k);
}

static int mote__dsel(mote_depth_format f)
{
    return f == MOTE_DEPTH_FORMAT_16 ? MOTE__D_16 : f == MOTE_DEPTH_FORMAT_32 ? MOTE__D_32 : MOTE__D_NONE;
}

/* The texture and shade a fill of this shade kind draws with: a black
 * triangle is drawn as an untextured flat one (for the table and the
 * generic loop alike). */
static inline void mote__fill_kinds(int shade_kind, int draw_tex, int *tex, int *shade)
{
    bool black = shade_kind == MOTE__SHADE_BLACK;
    *tex = black ? MOTE__TEX_NONE : draw_tex;
    *shade = black ? MOTE__SHADE_FLAT : shade_kind;
}

void mote__fill_generic(const mote__tri *t, const mote__target *tg, mote__rect r, int F)
{
    const mote__raster_state *rs = t->rs;
    int dsel = (rs->depth_test || rs->depth_write) ? mote__dsel(tg->depth_format) : MOTE__D_NONE;
    int tex, shade;
    mote__fill_kinds(t->shade, (int)rs->tex, &tex, &shade);
    mote__fill_body(t, tg, r, F, tex, MOTE_FORMAT_DEFAULT, shade, rs->persp, dsel,
                    (rs->depth_test ? MOTE__D_TEST : 0) | (rs->depth_write ? MOTE__D_WRITE : 0), tg->format, 0);
}

#if MOTE_SPECIALISE_SPANS
/* The specialised table: texture x shade (flat, mono, RGB; a black
 * triangle takes the untextured flat entry) x perspective x depth x format,
 * with depth test and write both on (the common case) and RGBA8888
 * textures (what the loader makes). Anything else uses the generic loop. */
enum { MOTE__TABLE_SHADES = MOTE__SHADE_BLACK };   /* flat, mono, RGB */
#define MOTE__FORMATS(X, T, S, P, D) X(T, S, P, D, RGBA8888) X(T, S, P, D, RGB565)
#define MOTE__DEPTHS(X, T, S, P) MOTE__FORMATS(X, T, S, P, 0) MOTE__FORMATS(X, T, S, P, 1) MOTE__FORMATS(X, T, S, P, 2)
#define MOTE__PERSPS(X, T, S) MOTE__DEPTHS(X, T, S, 0) MOTE__DEPTHS(X, T, S, 1) MOTE__DEPTHS(X, T, S, 2)
#define MOTE__SHADES(X, T) MOTE__PERSPS(X, T, 0) MOTE__PERSPS(X, T, 1) MOTE__PERSPS(X, T, 2)
#define MOTE__ALL(X) MOTE__SHADES(X, 0) MOTE__SHADES(X, 1) MOTE__SHADES(X, 2)

/* A triangle whose 1/w is the same at its three corners (every triangle
 * an orthographic camera sees, and faces parallel to the image) has a Q
 * plane without steps: each pixel's reciprocal is the one of Q's value at
 * the origin, which the affine variant works out once. So an exact
 * variant hands such a triangle to its affine sibling (P 0, defined just
 * before it): the same bytes, without a division a pixel. */
#define MOTE__DEFINE(T, S, P, D, F)                                                         \
    static void mote__fill_##T##S##P##D##_##F(const mote__tri *t, const mote__target *tg,   \
                                              mote__rect r, int bits)                       \
    {                                                                                       \
        if (P == MOTE__PERSP_CORRECT && (T || S) && (t->qdx | t->qdy) == 0) {               \
            mote__fill_##T##S##0##D##_##F(t, tg, r, bits);                                  \
            return;                                                                         \
        }                                                                                   \
        mote__fill_body(t, tg, r, bits, T, MOTE_FORMAT_RGBA8888, S, P, D, MOTE__D_TEST | MOTE__D_WRITE, MOTE_FORMAT_##F, MOTE__RBITS); \
    }
MOTE__ALL(MOTE__DEFINE)
#undef MOTE__DEFINE

#define MOTE__ENTRY(T, S, P, D, F) mote__fill_##T##S##P##D##_##F,
static const mote__fill_fn mote__fill_table[] = {MOTE__ALL(MOTE__ENTRY)};
#undef MOTE__ENTRY
typedef char mote__fill_table_size_check[sizeof mote__fill_table / sizeof mote__fill_table[0]
                                         == 3 * MOTE__TABLE_SHADES * 3 * 3 * 2 ? 1 : -1];
#endif

/* Whether texels can be addressed by masks and shifts: both axes repeat,
 * with power-of-two sizes up to 2^(68 - K) (mote__texel_pow2) and, in the
 * specialised build, a power-of-two stride up to 2^18 (rows by a shift). */
static void mote__address_select(mote__raster_state *rs)
{
    rs->pow2_repeat = false;
    if (rs->tex == MOTE__TEX_NONE || rs->wrap_u != MOTE_WRAP_REPEAT || rs->wrap_v != MOTE_WRAP_REPEAT)
        return;
    const int max = 1 << (68 - MOTE__RBITS), w = rs->tex_w, h = rs->tex_h, stride = rs->tex_stride;
    rs->pow2_repeat = (w & (w - 1)) == 0 && (h & (h - 1)) == 0;
#if MOTE_SPECIALISE_SPANS
    rs->pow2_repeat = rs->pow2_repeat && w <= max && h <= max && (stride & (stride - 1)) == 0 && stride <= 1 << 18;
    rs->tex_stride_log2 = 0;
    while (rs->pow2_repeat && (1 << rs->tex_stride_log2) < stride)
        rs->tex_stride_log2++;
#else
    (void)max;
    (void)stride;
#endif
}

void mote__fill_select(mote__raster_state *rs, mote_format format, mote_depth_format depth_format)
{
    mote__address_select(rs);
    for (int s = 0; s < MOTE__SHADE_COUNT; s++) {
        rs->fill[s] = mote__fill_generic;
#if MOTE_SPECIALISE_SPANS
        int dsel = mote__dsel(depth_format);
        bool depth_on = rs->depth_test && rs->depth_write;
        bool depth_off = !rs->depth_test && !rs->depth_write;
        int f = format == MOTE_FORMAT_RGBA8888 ? 0 : format == MOTE_FORMAT_RGB565 ? 1 : -1;
        int tex, shade;
        mote__fill_kinds(s, (int)rs->tex, &tex, &shade);
        bool tex_ok = tex == MOTE__TEX_NONE || rs->texture->format == MOTE_FORMAT_RGBA8888;
        if (f >= 0 && tex_ok && (depth_on || depth_off || dsel == MOTE__D_NONE)) {
            int d = depth_on ? dsel : MOTE__D_NONE;
            int idx = (((tex * MOTE__TABLE_SHADES + shade) * 3 + (int)rs->persp) * 3 + d) * 2 + f;
            rs->fill[s] = mote__fill_table[idx];
        }
#else
        (void)format;
        (void)depth_format;
#endif
    }
}
