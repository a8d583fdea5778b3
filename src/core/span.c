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
#define MOTE__UNROLL _Pragma("GCC unroll 8")
#else
#define MOTE__UNROLL
#define MOTE__INLINE static
/* a few 64-bit steps the pixel loop repeats per attribute: one copy */
#define MOTE__SMALL MOTE__SPEED_INLINE
#endif
#define MOTE__PLANE_FN MOTE__SMALL
#include "plane.h"

/* Depth buffer selector inside the body, and what a draw does with it. */
enum { MOTE__D_NONE = 0, MOTE__D_16 = 1, MOTE__D_32 = 2 };
enum { MOTE__D_TEST = 1, MOTE__D_WRITE = 2, MOTE__D_EQUAL = 4, MOTE__D_ONLY = 8 };

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

/* The texel nearest to (u, v), texel coordinates with tb fraction bits:
 * its row, and its column in *col. */
MOTE__INLINE const uint8_t *mote__nearest(const mote__tex_view *tx, bool pow2_repeat, int32_t u, int32_t v,
                                          int tb, size_t *col)
{
    const int iu = u >> tb, iv = v >> tb;
    size_t tv;
    if (pow2_repeat) {
        *col = (size_t)(iu & (tx->w - 1));
        tv = (size_t)(iv & (tx->h - 1));
    } else {
        *col = (size_t)mote__wrap(iu, tx->w, tx->wrap_u);
        tv = (size_t)mote__wrap(iv, tx->h, tx->wrap_v);
    }
    return mote__texel_row(tx, pow2_repeat, tv);
}

/* The four texels bilinear filtering blends at (u, v), texel coordinates
 * with tb fraction bits: columns u0 and u1 of rows row0 and row1, weighted
 * by fu and fv, the 8-bit fractions of the way from u0 to u1 and row0 to
 * row1. The pixel loop keeps a nearest texel in row0 and u0. */
typedef struct mote__taps {
    const uint8_t *row0, *row1;
    size_t u0, u1;
    uint32_t fu, fv;
} mote__taps;

/* the 8 bits below the point of x, a coordinate with tb fraction bits */
MOTE__INLINE uint32_t mote__frac8(int32_t x, int tb)
{
    return (tb >= 8 ? (uint32_t)x >> (tb - 8) : (uint32_t)x << (8 - tb)) & 0xff;
}

MOTE__INLINE mote__taps mote__bilinear_taps(const mote__tex_view *tx, bool pow2_repeat, int32_t u, int32_t v, int tb)
{
    /* half a texel back, modular: garbage texels (a hostile texel range)
     * may lie anywhere */
    const uint32_t half = tb > 0 ? (uint32_t)1 << (tb - 1) : 0u;
    u = (int32_t)((uint32_t)u - half);
    v = (int32_t)((uint32_t)v - half);
    /* the next column and row in 64 bits: iu + 1 overflowed int where
     * garbage made iu INT_MAX */
    const int iu = u >> tb, iv = v >> tb, iu1 = (int)(int32_t)(uint32_t)((int64_t)iu + 1),
              iv1 = (int)(int32_t)(uint32_t)((int64_t)iv + 1);
    mote__taps t;
    t.fu = mote__frac8(u, tb);
    t.fv = mote__frac8(v, tb);
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

/* Bilinear's blend of the four taps' texel alphas, unrounded (16
 * fraction bits). */
MOTE__INLINE uint32_t mote__blend_alpha_wide(mote_format format, const mote__taps *t)
{
    const uint32_t fu = t->fu, fv = t->fv;
    return mote__texel_alpha(format, t->row0, t->u0) * (256 - fu) * (256 - fv)
         + mote__texel_alpha(format, t->row0, t->u1) * fu * (256 - fv)
         + mote__texel_alpha(format, t->row1, t->u0) * (256 - fu) * fv
         + mote__texel_alpha(format, t->row1, t->u1) * fu * fv;
}

/* the same rounded, as mote__blend's channels */
MOTE__INLINE uint32_t mote__blend_alpha(mote_format format, const mote__taps *t)
{
    return (mote__blend_alpha_wide(format, t) + 32768) >> 16;
}

#if MOTE_ENABLE_BLEND
/* Source channels src (0..255) over pixel x of row with alpha a (0..255):
 * src a + dst (255 - a), rounded, per 8-bit channel, the destination read
 * back as 8 bits (RGB565 widened as its texels are), then packed. */
static uint32_t mote__blend_over(const uint8_t *row, ptrdiff_t x, mote_format fmt, const uint32_t src[3], uint32_t a)
{
    uint8_t d[4];
    mote__read_rgba(row, (int)x, fmt, d);
    uint32_t c[3];
    for (int k = 0; k < 3; k++)
        c[k] = mote__div255(src[k] * a + d[k] * (255 - a));
    return mote__pack(fmt, c[0], c[1], c[2]);
}
#endif

/* The next pixel's value, modular for the same reason: a plane may leave
 * 64 bits past a row's last pixel, or inside a hostile triangle whose
 * texel range makes its numerator planes wrap (its texels are garbage
 * then, by design, but the loop stays defined). */
MOTE__INLINE int64_t mote__plane_next(int64_t value, int64_t step)
{
    return (int64_t)((uint64_t)value + (uint64_t)step);
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

/* An interpolated shade, clamped. */
MOTE__SMALL uint32_t mote__shade_at(int32_t a0, int32_t n, int32_t r, int shift)
{
    return mote__clamp_shade(mote__attr(a0, n, r, shift));
}

/* The rows are cut into blocks of MOTE__BLOCK pixels, counted from each
 * row's own first pixel, whatever region draws it: the pixel loop steps
 * 32-bit copies of the planes taken afresh at each block's first pixel
 * (see mote__tri). */
#define MOTE__BLOCK_LOG2 6
#define MOTE__BLOCK (1 << MOTE__BLOCK_LOG2)

/* A block's scale for its 32-bit planes: the x steps of q and the
 * numerators, rounded, K of its reciprocals and the shift of its
 * attributes (see mote__block_begin); the triangle's for every block
 * where it has one (q_drop >= 0). */
typedef struct mote__block {
    int32_t qdx, ndx[MOTE__ATTRS];
    int k, ash;
#if MOTE_ENABLE_MIPMAPS
    int32_t qdy, nudy, nvdy;      /* per-pixel mip levels: the y steps, rounded */
#endif
} mote__block;

/* A block's 32-bit planes at its first pixel to be drawn: q and the
 * numerators, in its scale. */
typedef struct mote__block_at {
    int32_t q, n[MOTE__ATTRS];
} mote__block_at;

/* What the pixel loop needs of a triangle, read once per triangle into
 * locals (see the top of the file). */
typedef struct mote__fill_ctx {
    int64_t zdx, qdx;             /* the 64-bit x steps, to each block's first pixel */
    /* the numerator planes: origin value, x and y steps (0 for those the
     * triangle lacks: a binned record ends after its last plane) */
    int64_t n0[MOTE__ATTRS], ndx[MOTE__ATTRS], ndy[MOTE__ATTRS];
    int32_t a0[MOTE__ATTRS];
    int n_extra;                  /* the triangle's (mote__tri) */
    int tb;                       /* fraction bits of texel coordinates */
    uint32_t flat_px;             /* the pixel when nothing varies */
    uint32_t sr, sg, sb;          /* the shade when it does not vary */
    mote__tex_view tx;
    int seg_log2;                 /* sub-span: segments of 2^seg_log2 columns */
    int32_t affine_r;             /* affine: all qi alike, Q constant: one r */
    int q_drop;                   /* the triangle's (mote__tri) ... */
    mote__block steps;            /* ... and when >= 0, every block's scale (zero when nothing varies) */
    uint32_t alpha8, cutoff;      /* the draw's (mote__raster_state) */
#if MOTE_ENABLE_MIPMAPS
    /* per-pixel mip levels: the chain's views, and the 64-bit y steps */
    int levels;                   /* 0: none */
    bool blend_levels;            /* trilinear: two levels a pixel */
    mote__tex_view level[MOTE_MAX_MIPS];
    int64_t qdy, nudy, nvdy;
#endif
#if MOTE__LAYERS_ENABLED
    /* texture layers (the generic loop): their maps and views */
    int layers;                   /* 0: none */
    bool base_white;              /* the draw's own texture is white */
    int tri_level;                /* the triangle's mip level */
    const mote__layer *layer;
    mote__tex_view lview[MOTE_MAX_LAYERS];
#endif
} mote__fill_ctx;

#if MOTE__ADD_ENABLED
/* Channels t (0..255) of a pixel with an additive colour (highlights,
 * fog): t s + 255 a, one rounding, at most 255; a from its numerators n
 * at the pixel's reciprocal r. */
static void mote__modulate_add(const mote__fill_ctx *c, const int32_t n[3], int32_t r, int ash, uint32_t t[3],
                               uint32_t sr, uint32_t sg, uint32_t sb, const uint32_t *scale)
{
    const uint32_t s[3] = {sr, sg, sb};
    for (int k = 0; k < 3; k++) {
        uint64_t a = mote__shade_at(c->a0[MOTE__A_AR + k], n[k], r, ash);
        if (scale)                /* a specular layer's, 2^16 = 1 */
            a = (a * scale[k] + 32768) >> 16;
        const uint64_t v = ((uint64_t)t[k] * s[k] + 255 * a + (1u << 23)) >> 24;
        t[k] = v < 255 ? (uint32_t)v : 255u;
    }
}
#endif

#if MOTE_ENABLE_MIPMAPS
/* The y steps a block's per-pixel mip levels take, in its scale. */
static void mote__block_dy(const mote__fill_ctx *c, mote__block *b, int d, int nsh)
{
    b->qdy = mote__step32(c->qdy, d);
    b->nudy = mote__step32(c->nudy, nsh);
    b->nvdy = mote__step32(c->nvdy, nsh);
}

/* The level of a pixel at (u, v) (its q and numerators nu, nv): log2 of
 * the largest texel step to the pixel right of it or below it, rounded,
 * within the chain. */
static int mote__pixel_level(const mote__fill_ctx *c, const mote__block *b, int32_t q, int32_t nu, int32_t nv,
                             int32_t u, int32_t v, uint32_t *frac)
{
    const int32_t rx = mote__recip_k(mote__add32(q, b->qdx, 1), b->k);
    const int32_t ry = mote__recip_k(mote__add32(q, b->qdy, 1), b->k);
    const int32_t step[4] = {
        (int32_t)((uint32_t)mote__attr(c->a0[MOTE__A_U], mote__add32(nu, b->ndx[MOTE__A_U], 1), rx, b->ash) - (uint32_t)u),
        (int32_t)((uint32_t)mote__attr(c->a0[MOTE__A_V], mote__add32(nv, b->ndx[MOTE__A_V], 1), rx, b->ash) - (uint32_t)v),
        (int32_t)((uint32_t)mote__attr(c->a0[MOTE__A_U], mote__add32(nu, b->nudy, 1), ry, b->ash) - (uint32_t)u),
        (int32_t)((uint32_t)mote__attr(c->a0[MOTE__A_V], mote__add32(nv, b->nvdy, 1), ry, b->ash) - (uint32_t)v)};
    uint32_t most = 0;
    for (int i = 0; i < 4; i++) {
        const uint32_t m = step[i] < 0 ? 0u - (uint32_t)step[i] : (uint32_t)step[i];
        most = m > most ? m : most;
    }
    if (c->blend_levels) {
        /* floor(log2(most / 2^tb)), and the next level's weight: the
         * 8 bits below most's leading one */
        const int bl = mote__bitlen(most), level = bl - 1 - c->tb;
        const uint32_t f = (bl >= 9 ? most >> (bl - 9) : most << (9 - bl)) & 0xffu;
        *frac = level < 0 || level >= c->levels - 1 ? 0u : f;
        return level < 0 ? 0 : level >= c->levels ? c->levels - 1 : level;
    }
    /* round(log2(most / 2^tb)): the floor of log2(most sqrt 2) */
    const int level = mote__bitlen(((uint64_t)most * 181) >> 7) - 1 - c->tb;
    *frac = 0;
    return level < 0 ? 0 : level >= c->levels ? c->levels - 1 : level;
}

/* A texel of one level, the draw's filter, for trilinear's second level:
 * its colour into t, and its alpha. */
static uint32_t mote__level_texel(const mote__tex_view *tx, int32_t u, int32_t v, int tb, bool bilinear, uint32_t t[3])
{
    mote__taps p;
    if (bilinear) {
        p = mote__bilinear_taps(tx, false, u, v, tb);
        mote__blend(tx->format, &p, t);
        return mote__blend_alpha(tx->format, &p);
    }
    p.row0 = mote__nearest(tx, false, u, v, tb, &p.u0);
    mote__texel(tx->format, p.row0, p.u0, t);
    return mote__texel_alpha(tx->format, p.row0, p.u0);
}
#endif

#if MOTE__LAYERS_ENABLED
/* What a pixel's texture layers give: shade to add (emissive), the
 * highlights' scale per channel (specular, 2^16 = 1) and an opacity
 * (0..MOTE__OPAQUE, 1/256 of the alpha's unit: rounded once, late). */
#define MOTE__OPAQUE (255u * 256u)
typedef struct mote__layer_px {
    uint32_t e[3], m[3], o;
    bool emit, spec;
} mote__layer_px;

/* A layer's coordinate on one axis (mote__layer's map) from the draw's t
 * (tb fraction bits, level lv), wrapped to one period (clamped: near the
 * texture), in 1/2^MOTE__LAYER_BITS texels. Modular: hostile
 * coordinates give garbage texels, never undefined behaviour. */
static int32_t mote__layer_coord(const mote__layer *l, int k, int32_t t, int tb, int lv, int size, mote_wrap wrap)
{
    const int64_t prod = (int64_t)t * l->mul[k];
    const int s = l->sh[k] + tb - MOTE__LAYER_BITS - lv;
    int64_t x = s >= 0 ? mote__floor_shift64(prod, s) : (int64_t)((uint64_t)prod << -s);
    x = (int64_t)((uint64_t)x + (uint64_t)l->add[k]);
    if (wrap == MOTE_WRAP_CLAMP) {
        const int64_t hi = ((int64_t)size + 1) << MOTE__LAYER_BITS;
        return (int32_t)(x < -hi ? -hi : x > hi ? hi : x);
    }
    const int64_t period = ((int64_t)size << MOTE__LAYER_BITS) * (wrap == MOTE_WRAP_MIRROR ? 2 : 1);
    x %= period;
    return (int32_t)(x < 0 ? x + period : x);
}

/* The layers at the draw's texel coordinates (u, v), tb fraction bits of
 * level lv. */
static void mote__layers_at(const mote__fill_ctx *c, int32_t u, int32_t v, int tb, int lv, bool bilinear,
                            mote__layer_px *out)
{
    for (int k = 0; k < 3; k++) {
        out->e[k] = 0;
        out->m[k] = 65536;
    }
    out->o = MOTE__OPAQUE;
    out->emit = out->spec = false;
    for (int i = 0; i < c->layers; i++) {
        const mote__layer *l = &c->layer[i];
        const mote__tex_view *tx = &c->lview[i];
        const int32_t lu = mote__layer_coord(l, 0, u, tb, lv, tx->w, tx->wrap_u);
        const int32_t lw = mote__layer_coord(l, 1, v, tb, lv, tx->h, tx->wrap_v);
        mote__taps p;
        uint32_t t[3], a = 255;
        if (bilinear) {
            p = mote__bilinear_taps(tx, false, lu, lw, MOTE__LAYER_BITS);
            mote__blend(tx->format, &p, t);
        } else {
            p.row0 = mote__nearest(tx, false, lu, lw, MOTE__LAYER_BITS, &p.u0);
            mote__texel(tx->format, p.row0, p.u0, t);
        }
        if (l->role == MOTE_LAYER_EMISSIVE) {
            out->emit = true;
            for (int k = 0; k < 3; k++)
                out->e[k] += t[k] * l->factor[k];
        } else if (l->role == MOTE_LAYER_SPECULAR) {
            out->spec = true;
            for (int k = 0; k < 3; k++)   /* texel / 255 x factor, in 2^16 */
                out->m[k] = (uint32_t)(((uint64_t)t[k] * l->factor[k] * out->m[k] / 65536 + 127) / 255);
        } else {                  /* in 1/256 */
            if (l->from_rgb)      /* Babylon.js's luminance weights */
                a = 54 * t[0] + 183 * t[1] + 19 * t[2];
            else
                a = bilinear ? (mote__blend_alpha_wide(tx->format, &p) + 128) >> 8
                             : mote__texel_alpha(tx->format, p.row0, p.u0) << 8;
            a = (uint32_t)(((uint64_t)a * l->factor[0] + 128) >> 8);
            out->o = (uint32_t)(((uint64_t)out->o * MOTE__MIN(a, MOTE__OPAQUE) + MOTE__OPAQUE / 2) / MOTE__OPAQUE);
        }
    }
}
#endif

/* Pixels [x0, x1) of a row, all in one block of scale b, given the planes'
 * values at x0 (the exact depth plane z, q and the numerators in *at); bx is the
 * block's first pixel and last the row's last one (sub-span segments).
 * Adds the pixels the depth test rejects to *rejected (rare: counted
 * rather than the written ones). */
MOTE__INLINE void mote__pixels(const mote__fill_ctx *c, const mote__block *b, const mote__block_at *at,
                               uint8_t *crow, uint16_t *d16,
                               uint32_t *d32, ptrdiff_t x0, ptrdiff_t x1, ptrdiff_t bx, ptrdiff_t last, int64_t z,
                               uint32_t *rejected, const int tex, const mote_format tfmt,
                               const bool pow2, const int shade, const int persp, const int dsel, const int dmode,
                               const mote_format fmt, const int amode)
{
    const bool varying = shade != MOTE__SHADE_FLAT || tex;
    const int64_t zdx = c->zdx;
    const int32_t qdx = b->qdx;
    int32_t q = at->q, nr = at->n[MOTE__A_R], ng = at->n[MOTE__A_G], nb = at->n[MOTE__A_B], nu = at->n[MOTE__A_U],
            nv = at->n[MOTE__A_V];
    const int32_t nrdx = b->ndx[MOTE__A_R], ngdx = b->ndx[MOTE__A_G], nbdx = b->ndx[MOTE__A_B];
    const int32_t nudx = b->ndx[MOTE__A_U], nvdx = b->ndx[MOTE__A_V];
    const int k = b->k, ash = b->ash, tb = c->tb;
#if MOTE__ADD_ENABLED
    /* the additive colour's numerators (MOTE__SHADE_ADD: the generic loop) */
    int32_t na[3] = {at->n[MOTE__A_AR], at->n[MOTE__A_AG], at->n[MOTE__A_AB]};
    const int32_t nadx[3] = {b->ndx[MOTE__A_AR], b->ndx[MOTE__A_AG], b->ndx[MOTE__A_AB]};
#endif
    uint32_t sr = c->sr, sg = c->sg, sb = c->sb;
    /* sub-span: r exact at the first pixel of each segment of 2^seg_log2
     * counted from the row's first pixel, and at the row's last pixel,
     * linear between, so where a region starts a row changes nothing */
    int32_t seg_r0 = 0, seg_r1 = 0, seg_step = 0;
    ptrdiff_t seg_x0 = 0, seg_x1 = 0, seg_next = x0;   /* r's ends; where the next segment starts */
    bool seg_exact = true;        /* until a segment with both ends valid: no r1 to reuse */
    /* Speed builds index the buffers from the end, i = x - x1 < 0: one
     * counter for both and no end to compare with, a register fewer in a
     * loop that spills. The generic-only build indexes from the start
     * (base 0: less code on a 32-bit core). */
    const ptrdiff_t base = MOTE_SPECIALISE_SPANS ? x1 : 0;
    uint8_t *const cb = crow + base * mote__format_bytes(fmt);
    uint16_t *const d16b = MOTE_SPECIALISE_SPANS && dsel == MOTE__D_16 ? d16 + base : d16;   /* NULL unless used */
    uint32_t *const d32b = MOTE_SPECIALISE_SPANS && dsel == MOTE__D_32 ? d32 + base : d32;

    for (ptrdiff_t i = x0 - base; i < x1 - base; i++, z = mote__plane_next(z, zdx),
                                                   q = mote__add32(q, qdx, 1), nr = mote__add32(nr, nrdx, 1),
                                                   ng = mote__add32(ng, ngdx, 1), nb = mote__add32(nb, nbdx, 1),
                                                   nu = mote__add32(nu, nudx, 1), nv = mote__add32(nv, nvdx, 1)) {
        uint32_t depth = 0;
#if MOTE__ADD_ENABLED
        /* stepped here, as the loop's continue would skip it at the end */
        int32_t add_n[3] = {0, 0, 0};
        if (shade == MOTE__SHADE_ADD)
            for (int j = 0; j < 3; j++) {
                add_n[j] = na[j];
                na[j] = mote__add32(na[j], nadx[j], 1);
            }
#endif
        if (dsel != MOTE__D_NONE) {
            /* z is a convex combination of in-range depths: only rounding
             * at an edge can take it a unit outside, so test before clamping */
            const int64_t zz = z >> MOTE__DEPTH_FRAC;
            depth = (uint32_t)zz;
            if ((uint64_t)zz > MOTE__DEPTH_MAX)
                depth = zz < 0 ? 0u : MOTE__DEPTH_MAX;
            if (dsel == MOTE__D_16)
                depth >>= 8;      /* the top 16 bits of the exact 24-bit depth */
            const uint32_t stored = dsel == MOTE__D_16 ? (uint32_t)d16b[i] : d32b[i];
            if ((dmode & MOTE__D_TEST) && depth >= stored + ((dmode & MOTE__D_EQUAL) ? 1u : 0u)) {
                (*rejected)++;
                continue;
            }
        }
        uint32_t px = c->flat_px;
        /* with alpha (the generic loop only): the source channels before
         * packing, and the texel's alpha */
        uint32_t src[3] = {0, 0, 0}, ta = 255;
#if MOTE__LAYERS_ENABLED
        uint32_t op = MOTE__OPAQUE;   /* texture layers' opacity */
#endif
        if (amode && !varying) {
            src[0] = mote__modulate(255, sr);
            src[1] = mote__modulate(255, sg);
            src[2] = mote__modulate(255, sb);
        }
        if (varying) {
            int32_t r;
            if (MOTE_ENABLE_SUBSPAN && persp == MOTE__PERSP_SUBSPAN) {
                const ptrdiff_t x = base + i;
                if (x >= seg_next) {
                    /* r is exact at the segment's ends, cut to the row's
                     * last pixel: past the triangle's edge q may be
                     * anything (across a sliver's edge it moves by far
                     * more than its whole range inside, within a pixel).
                     * The start's r is the last segment's end's, unless
                     * depth-rejected pixels skipped a segment. Segments
                     * tile blocks (2^seg_log2 <= MOTE__BLOCK). */
                    const ptrdiff_t len = (ptrdiff_t)1 << c->seg_log2, start = bx + ((x - bx) & -len);
                    const bool reuse = !seg_exact && start == seg_x1;
                    seg_next = start + len;
                    seg_x0 = start;
                    seg_x1 = seg_next < last ? seg_next : last;
                    seg_exact = seg_x1 <= seg_x0;
                    if (!seg_exact) {
                        seg_r0 = reuse ? seg_r1 : mote__recip_k(mote__add32(q, qdx, (int32_t)(seg_x0 - x)), k);
                        seg_r1 = mote__recip_k(mote__add32(q, qdx, (int32_t)(seg_x1 - x)), k);
                        /* (r1 - r0) / length, rounded toward zero: by a
                         * shift for a whole segment */
                        const int32_t d = seg_r1 - seg_r0;
                        seg_step = seg_x1 - seg_x0 == len
                                 ? mote__floor_shift32(d + ((int32_t)(len - 1) & -(int32_t)(d < 0)), c->seg_log2)
                                 : d / (int32_t)(seg_x1 - seg_x0);
                    }
                }
                r = seg_exact ? mote__recip_k(q, k) : seg_r0 + seg_step * (int32_t)(x - seg_x0);
            } else {
                r = persp == MOTE__PERSP_AFFINE ? c->affine_r : mote__recip_k(q, k);
            }
            if (shade == MOTE__SHADE_MONO) {
                sr = sg = sb = mote__shade_at(c->a0[MOTE__A_R], nr, r, ash);
            } else if (shade == MOTE__SHADE_RGB || shade == MOTE__SHADE_ADD) {
                sr = mote__shade_at(c->a0[MOTE__A_R], nr, r, ash);
                sg = mote__shade_at(c->a0[MOTE__A_G], ng, r, ash);
                sb = mote__shade_at(c->a0[MOTE__A_B], nb, r, ash);
            }
            if (tex) {
                /* where the texel lies, or bilinear's four (nearest: row0, u0) */
                const bool bilinear = MOTE_ENABLE_BILINEAR && tex == MOTE__TEX_BILINEAR;
                int32_t u = mote__attr(c->a0[MOTE__A_U], nu, r, ash), v = mote__attr(c->a0[MOTE__A_V], nv, r, ash);
                const mote__tex_view *tx = &c->tx;
#if MOTE_ENABLE_MIPMAPS
                /* trilinear: the next level's weight, and its texel */
                uint32_t mip_f = 0, mip_t[3] = {0, 0, 0}, mip_a = 255;
                /* the generic loop's per-pixel level (tfmt unknown): the
                 * variants never have one (mote__fill_select), and a test
                 * a pixel is worth dropping there */
                if (tfmt == MOTE_FORMAT_DEFAULT && c->levels) {
                    const int lv = mote__pixel_level(c, b, q, nu, nv, u, v, &mip_f);
                    tx = &c->level[lv];
                    if (mip_f)
                        mip_a = mote__level_texel(&c->level[lv + 1], mote__floor_shift32(u, lv + 1),
                                                  mote__floor_shift32(v, lv + 1), tb, bilinear, mip_t);
                    u = mote__floor_shift32(u, lv);
                    v = mote__floor_shift32(v, lv);
                }
#endif
                /* texture layers (the generic loop: tfmt is not known) */
                bool white = false;
#if MOTE__LAYERS_ENABLED
                const bool layered = tfmt == MOTE_FORMAT_DEFAULT && c->layers;
                mote__layer_px lp;
                if (layered) {
                    int lv = c->tri_level;
#if MOTE_ENABLE_MIPMAPS
                    if (c->levels)
                        lv = (int)(tx - c->level);
#endif
                    mote__layers_at(c, u, v, tb, lv, bilinear, &lp);
                    white = c->base_white;
                    op = lp.o;
                    if (lp.emit) {  /* before the texture multiplies: Babylon.js's order */
                        if (shade == MOTE__SHADE_FLAT) {   /* the triangle's, not the last pixel's */
                            sr = c->sr;
                            sg = c->sg;
                            sb = c->sb;
                        }
                        sr = MOTE__MIN(sr + lp.e[0], (uint32_t)MOTE__SHADE_ONE);
                        sg = MOTE__MIN(sg + lp.e[1], (uint32_t)MOTE__SHADE_ONE);
                        sb = MOTE__MIN(sb + lp.e[2], (uint32_t)MOTE__SHADE_ONE);
                    }
                }
#endif
                mote__taps p;
                if (white)
                    memset(&p, 0, sizeof p);
                else if (bilinear)
                    p = mote__bilinear_taps(tx, pow2, u, v, tb);
                else
                    p.row0 = mote__nearest(tx, pow2, u, v, tb, &p.u0);
                if (amode & (MOTE__ALPHA_TEST | MOTE__ALPHA_TEXEL)) {
                    if (!white)
                        ta = bilinear ? mote__blend_alpha(tx->format, &p) : mote__texel_alpha(tx->format, p.row0, p.u0);
#if MOTE_ENABLE_MIPMAPS
                    if (mip_f)
                        ta = (ta * (256 - mip_f) + mip_a * mip_f + 128) >> 8;
#endif
                    uint32_t tv = ta;
#if MOTE__LAYERS_ENABLED
                    if (op < MOTE__OPAQUE)
                        tv = (ta * op + MOTE__OPAQUE / 2) / MOTE__OPAQUE;
#endif
                    if (MOTE_ENABLE_ALPHA_TEST && (amode & MOTE__ALPHA_TEST) && tv < c->cutoff) {
                        (*rejected)++;   /* cut out: neither colour nor depth */
                        continue;
                    }
                }
                /* vector registers only where the texture's format is a
                 * constant: the specialised variants, not their oracle,
                 * the generic loop */
                if (MOTE__VECTOR_COLOR && !amode && tfmt == MOTE_FORMAT_RGBA8888 && fmt == MOTE_FORMAT_RGBA8888) {
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
                    uint32_t t[3] = {255, 255, 255};
                    if (white) {
                    } else if (bilinear)
                        mote__blend(tx->format, &p, t);
                    else
                        mote__texel(tx->format, p.row0, p.u0, t);
#if MOTE_ENABLE_MIPMAPS
                    if (mip_f)    /* trilinear: the two levels, weighed */
                        for (int ch = 0; ch < 3; ch++)
                            t[ch] = (t[ch] * (256 - mip_f) + mip_t[ch] * mip_f + 128) >> 8;
#endif
                    /* a flat shade takes three products: testing for grey
                     * at every pixel costs what the shared product saves */
#if MOTE__ADD_ENABLED
                    if (shade == MOTE__SHADE_ADD) {
                        const uint32_t *scale = NULL;
#if MOTE__LAYERS_ENABLED
                        scale = layered && lp.spec ? lp.m : NULL;
#endif
                        mote__modulate_add(c, add_n, r, ash, t, sr, sg, sb, scale);
                    } else
#endif
#if MOTE__LAYERS_ENABLED
                    if (MOTE__WIDE_REGISTERS && shade == MOTE__SHADE_MONO && !layered) {
#else
                    if (MOTE__WIDE_REGISTERS && shade == MOTE__SHADE_MONO) {
#endif
                        mote__modulate_grey(t, sr);
                    } else {
                        t[0] = mote__modulate(t[0], sr);
                        t[1] = mote__modulate(t[1], sg);
                        t[2] = mote__modulate(t[2], sb);
                    }
                    if (amode)
                        memcpy(src, t, sizeof src);
                    px = mote__pack(fmt, t[0], t[1], t[2]);
                }
            } else {
                src[0] = src[1] = src[2] = 255;
#if MOTE__ADD_ENABLED
                if (shade == MOTE__SHADE_ADD) {
                    mote__modulate_add(c, add_n, r, ash, src, sr, sg, sb, NULL);
                } else
#endif
                {
                    src[0] = mote__modulate(255, sr);
                    src[1] = mote__modulate(255, sg);
                    src[2] = mote__modulate(255, sb);
                }
                px = mote__pack(fmt, src[0], src[1], src[2]);
            }
        }
#if MOTE_ENABLE_BLEND
        if (amode & MOTE__ALPHA_BLEND) {
            uint32_t a = amode & MOTE__ALPHA_TEXEL ? mote__div255(c->alpha8 * ta) : c->alpha8;
#if MOTE__LAYERS_ENABLED
            if (op < MOTE__OPAQUE)   /* an opacity layer's: the three factors, rounded once */
                a = (uint32_t)(((uint64_t)c->alpha8 * (amode & MOTE__ALPHA_TEXEL ? ta : 255u) * op
                                + 255u * MOTE__OPAQUE / 2) / (255u * MOTE__OPAQUE));
#endif
            px = mote__blend_over(crow, base + i, fmt, src, a);
        }
#endif
        if (!(dmode & MOTE__D_ONLY))
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

/* A block's 32-bit planes (*at) from the 64-bit ones at its first pixel,
 * q64 and n64[], given where its last pixel (or the row's, if nearer)
 * lies, len pixels on, and where drawing starts, off pixels on; and its
 * scale: the triangle's (q_drop >= 0), else its own, made in *own. q is
 * taken down only as far as keeps it below 2^30 at both ends (Q is
 * linear, so inside), and the numerators as far again past n_extra, so
 * that a far block (small q) keeps as many bits as a near one; K makes
 * r = 2^K / q at most 2^30 at the smaller end. */
MOTE__INLINE const mote__block *mote__block_begin(const mote__fill_ctx *c, mote__block *own, mote__block_at *at,
                                                  int64_t q64, const uint64_t n64[MOTE__ATTRS], int32_t len,
                                                  int32_t off, const int shade, const int tex)
{
    const mote__block *b = &c->steps;
    int d = c->q_drop;
    if (d < 0) {
        const int64_t q64e = mote__plane_at(q64, c->qdx, len);
        const mote__block_scale sc = mote__block_scale_of(q64, q64e, c->n_extra);
        d = sc.d;
        own->qdx = mote__step32(c->qdx, d);
        own->k = sc.k;
        own->ash = sc.ash;
#if MOTE_ENABLE_MIPMAPS
        if (c->levels)
            mote__block_dy(c, own, d, d + c->n_extra);
#endif
        MOTE__UNROLL
        for (int a = 0; a < MOTE__ATTRS; a++)
            own->ndx[a] = mote__reads_plane(a, shade, tex) ? mote__step32(c->ndx[a], d + c->n_extra) : 0;
        b = own;
    }
    const int nsh = d + c->n_extra;
    at->q = mote__add32(mote__to32(q64, d), b->qdx, off);
    MOTE__UNROLL
    for (int a = 0; a < MOTE__ATTRS; a++)
        at->n[a] = mote__reads_plane(a, shade, tex) ? mote__add32(mote__to32((int64_t)n64[a], nsh), b->ndx[a], off) : 0;
    return b;
}

/* Row by row: the edge walk, then the pixel loop over the row's span,
 * block by block. The 64-bit planes are stepped down from their values at
 * column ox of the first row (unsigned: exact modulo 2^64, see
 * mote__plane_at), and taken to 32 bits at each block's first pixel. */
MOTE__INLINE void mote__rows(const mote__fill_ctx *c, mote__walk *w, const mote__tri *t, const mote__target *tg,
                             const int tex, const mote_format tfmt, const bool pow2, const int shade,
                             const int persp, const int dsel, const int dmode, const mote_format fmt, const int amode)
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
    uint32_t rejected = 0;
    mote__block own;              /* a block's scale, where the triangle has none */
    /* One loop, a turn a block: a row's later blocks (rare on small
     * triangles) are turns of the same loop, not of a loop inside the
     * row's, whose values the compiler copied to the stack afresh for
     * every row. */
    mote__span_blocks sb = {0};
    for (bool first = true;; first = false) {
        if (sb.from >= sb.x1) {
            /* the row is drawn (or empty): the next one */
            if (!first) {
                zr += (uint64_t)zdy;
                qr += (uint64_t)qdy;
                MOTE__UNROLL
                for (int a = 0; a < MOTE__ATTRS; a++)
                    if (mote__reads_plane(a, shade, tex))
                        nrow[a] += (uint64_t)c->ndy[a];
                crow += stride;
                /* a constant test in the variants; the shortest code in
                 * the generic-only build (flash) */
                if (MOTE_SPECIALISE_SPANS ? dsel != MOTE__D_NONE : zrow != NULL)
                    zrow += zstride;
            }
            if (w->y >= w->yend)
                break;
            if (!mote__span_begin(w, &sb, MOTE__BLOCK_LOG2))
                continue;
        }
        const ptrdiff_t from = sb.from, bx = sb.bx, last = sb.last;
        const ptrdiff_t to = MOTE__MIN(bx + MOTE__BLOCK, sb.x1);
        const int32_t off = (int32_t)(from - bx);
        /* the 64-bit planes at the block's first pixel, from the row's
         * (modulo 2^64, as stepping block by block would give them) */
        const mote__block *b = &c->steps;   /* zero: read by no pixel of a flat loop */
        mote__block_at at = {0};
        if (varying) {
            const int64_t d = bx - ox;
            uint64_t nb[MOTE__ATTRS] = {0};
            MOTE__UNROLL
            for (int a = 0; a < MOTE__ATTRS; a++)
                if (mote__reads_plane(a, shade, tex))
                    nb[a] = (uint64_t)mote__plane_at((int64_t)nrow[a], c->ndx[a], d);
            b = mote__block_begin(c, &own, &at, mote__plane_at((int64_t)qr, c->qdx, d), nb,
                                  (int32_t)(MOTE__MIN(bx + MOTE__BLOCK, last) - bx), off, shade, tex);
        }
        mote__pixels(c, b, &at, crow, dsel == MOTE__D_16 ? (uint16_t *)(void *)zrow : NULL,
                     dsel == MOTE__D_32 ? (uint32_t *)(void *)zrow : NULL, from, to, bx, last,
                     dsel != MOTE__D_NONE ? mote__plane_at((int64_t)zr, c->zdx, (int32_t)(from - ox)) : 0,
                     &rejected, tex, tfmt, pow2, shade, persp, dsel, dmode, fmt, amode);
        sb.from = to;
        sb.bx = bx + MOTE__BLOCK;
    }
    const uint64_t tested = sb.tested;
    tg->counts->tested += tested;
    tg->counts->written += tested - rejected;
}

/* A whole triangle inside region r: its constants once, then the rows.
 * tfmt: the texture's format when known at compile time (the specialised
 * variants take RGBA8888 textures), MOTE_FORMAT_DEFAULT to read it. */
MOTE__INLINE void mote__fill_body(const mote__tri *t, const mote__target *tg, mote__rect r, int F,
                                  const int tex, const mote_format tfmt, const int shade, const int persp,
                                  const int dsel, const int dmode, const mote_format fmt, const int amode)
{
    mote__walk w;
    if (!mote__walk_begin(&w, t, r, F))
        return;
    const mote__raster_state *rs = t->rs;
    const bool varying = shade != MOTE__SHADE_FLAT || tex;
    /* field by field: a memset of the whole context was 3.5% of the dense
     * grid's instructions, whose triangles have a dozen pixels each */
    mote__fill_ctx c;
    c.zdx = t->zdx;
    c.qdx = t->qdx;
    c.n_extra = t->n_extra;
    c.tb = t->texel_bits;
    /* only binned records are cut short: drawn directly, t has them all */
    const int planes = MOTE_ENABLE_BINNING ? mote__plane_count(shade, tex != MOTE__TEX_NONE) : MOTE__ATTRS;
    for (int a = 0; a < MOTE__ATTRS; a++) {
        c.a0[a] = (int32_t)t->a0[a];
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
    if (!tex) {
        const mote__tex_view none = {0};
        c.tx = none;
    } else {
        c.tx.pixels = (const uint8_t *)rs->texture->pixels;
        c.tx.format = tfmt != MOTE_FORMAT_DEFAULT ? tfmt : rs->texture->format;
        c.tx.stride = rs->tex_stride;
        c.tx.w = rs->tex_w;
        c.tx.h = rs->tex_h;
#if MOTE_ENABLE_MIPMAPS
        if (t->level) {           /* a packed level of the chain */
            const mote_texture *lv = &rs->mips->level[t->level];
            c.tx.pixels = (const uint8_t *)lv->pixels;
            c.tx.w = lv->width;
            c.tx.h = lv->height;
            c.tx.stride = lv->stride;
        }
#endif
        c.tx.wrap_u = rs->wrap_u;
        c.tx.wrap_v = rs->wrap_v;
        c.tx.pow2_repeat = rs->pow2_repeat;
        c.tx.stride_log2 = rs->tex_stride_log2;
#if MOTE_ENABLE_MIPMAPS
        if (t->level) {
            c.tx.stride_log2 = 0;
            while ((1 << c.tx.stride_log2) < c.tx.stride)
                c.tx.stride_log2++;
        }
#endif
    }
    c.seg_log2 = MOTE_ENABLE_SUBSPAN ? rs->subspan_log2 : 0;
    c.alpha8 = rs->alpha8;
    c.cutoff = rs->cutoff;
#if MOTE_ENABLE_MIPMAPS
    c.levels = 0;
    if (tex && rs->mip_pixel && varying) {
        c.levels = rs->mips->count;
        c.blend_levels = rs->mip_blend;
        for (int l = 0; l < c.levels; l++) {
            c.level[l] = c.tx;
            if (l) {
                const mote_texture *lv = &rs->mips->level[l];
                c.level[l].pixels = (const uint8_t *)lv->pixels;
                c.level[l].w = lv->width;
                c.level[l].h = lv->height;
                c.level[l].stride = lv->stride;
                c.level[l].stride_log2 = 0;
                while ((1 << c.level[l].stride_log2) < lv->stride)
                    c.level[l].stride_log2++;
            }
        }
        c.qdy = t->qdy;
        c.nudy = c.ndy[MOTE__A_U];
        c.nvdy = c.ndy[MOTE__A_V];
    }
#endif
#if MOTE__LAYERS_ENABLED
    c.layers = tex ? rs->layer_count : 0;
    c.base_white = rs->base_white;
    c.tri_level = t->level;
    c.layer = rs->layer;
    for (int i = 0; i < c.layers; i++) {
        const mote__layer *l = &rs->layer[i];
        mote__tex_view *v = &c.lview[i];
        v->pixels = (const uint8_t *)l->texture->pixels;
        v->stride = l->stride;
        v->w = l->texture->width;
        v->h = l->texture->height;
        v->stride_log2 = 0;
        v->format = l->texture->format;
        v->wrap_u = l->wrap_u;
        v->wrap_v = l->wrap_v;
        v->pow2_repeat = false;
    }
#endif
    c.q_drop = t->q_drop;
    c.affine_r = 0;
    if (varying && c.q_drop >= 0) {
        const int d = c.q_drop;
        c.steps.qdx = mote__step32(t->qdx, d);
        c.steps.k = t->rbits;
        /* below 0 only for absurd texel ranges: keeps the shift defined */
        c.steps.ash = MOTE__MAX(t->rbits - 20 - t->n_extra, 0);
        MOTE__UNROLL
        for (int a = 0; a < MOTE__ATTRS; a++)
            c.steps.ndx[a] = mote__reads_plane(a, shade, tex) ? mote__step32(c.ndx[a], d + t->n_extra) : 0;
#if MOTE_ENABLE_MIPMAPS
        if (c.levels)
            mote__block_dy(&c, &c.steps, d, d + t->n_extra);
#endif
        /* affine: all qi alike (so q_drop >= 0), Q without steps */
        if (persp == MOTE__PERSP_AFFINE)
            c.affine_r = mote__recip_k(mote__to32(t->q, d), t->rbits);
    } else {
        memset(&c.steps, 0, sizeof c.steps);
    }
#if MOTE_SPECIALISE_SPANS
    /* a power-of-two repeating texture: its own loop, texel addresses by masks */
    if (tex && c.tx.pow2_repeat) {
        mote__rows(&c, &w, t, tg, tex, tfmt, true, shade, persp, dsel, dmode, fmt, amode);
        return;
    }
#endif
    mote__rows(&c, &w, t, tg, tex, tfmt, c.tx.pow2_repeat, shade, persp, dsel, dmode, fmt, amode);
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
                    (rs->depth_test ? MOTE__D_TEST : 0) | (rs->depth_write ? MOTE__D_WRITE : 0)
                        | (MOTE_ENABLE_BLEND && rs->depth_equal ? MOTE__D_EQUAL : 0)
                        | (MOTE_ENABLE_BLEND && rs->no_color ? MOTE__D_ONLY : 0), tg->format,
                    MOTE__ALPHA_ENABLED ? rs->alpha : 0);
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
        mote__fill_body(t, tg, r, bits, T, MOTE_FORMAT_RGBA8888, S, P, D, MOTE__D_TEST | MOTE__D_WRITE, MOTE_FORMAT_##F, 0); \
    }
MOTE__ALL(MOTE__DEFINE)
#undef MOTE__DEFINE

#define MOTE__ENTRY(T, S, P, D, F) mote__fill_##T##S##P##D##_##F,
const mote__fill_fn mote__fill_table[] = {MOTE__ALL(MOTE__ENTRY)};
#undef MOTE__ENTRY
typedef char mote__fill_table_size_check[sizeof mote__fill_table / sizeof mote__fill_table[0]
                                         == 3 * MOTE__TABLE_SHADES * 3 * 3 * 2 ? 1 : -1];
#endif

#if MOTE_FIRMWARE_SPANS
/* span_fw.c's loop, but for a triangle whose planes need a scale per
 * block (q_drop < 0), which the generic loop takes */
static void mote__fill_firmware(const mote__tri *t, const mote__target *tg, mote__rect r, int F)
{
    if (t->q_drop < 0)
        mote__fill_generic(t, tg, r, F);
    else
        mote__fill_fw(t, tg, r, F);
}
#endif

/* Whether texels can be addressed by masks and shifts: both axes repeat,
 * with power-of-two sizes and, in the specialised build, a power-of-two
 * stride up to 2^18 (rows by a shift). */
static void mote__address_select(mote__raster_state *rs)
{
    rs->pow2_repeat = false;
    if (rs->tex == MOTE__TEX_NONE || rs->wrap_u != MOTE_WRAP_REPEAT || rs->wrap_v != MOTE_WRAP_REPEAT)
        return;
    const int w = rs->tex_w, h = rs->tex_h, stride = rs->tex_stride;
    rs->pow2_repeat = (w & (w - 1)) == 0 && (h & (h - 1)) == 0;
#if MOTE_SPECIALISE_SPANS
    rs->pow2_repeat = rs->pow2_repeat && (stride & (stride - 1)) == 0 && stride <= 1 << 18;
    rs->tex_stride_log2 = 0;
    while (rs->pow2_repeat && (1 << rs->tex_stride_log2) < stride)
        rs->tex_stride_log2++;
#else
    (void)stride;
#endif
}

void mote__fill_select(mote__raster_state *rs, mote_format format, mote_depth_format depth_format)
{
    mote__fill_select_isa(rs, format, depth_format, MOTE__ISA_BEST);
}

void mote__fill_select_isa(mote__raster_state *rs, mote_format format, mote_depth_format depth_format, int isa)
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
        if (s == MOTE__SHADE_ADD)
            continue;             /* the generic loop's alone */
        bool tex_ok = tex == MOTE__TEX_NONE || rs->texture->format == MOTE_FORMAT_RGBA8888;
        if (f >= 0 && tex_ok && !rs->mip_pixel && !mote__generic_only(rs) && (depth_on || depth_off || dsel == MOTE__D_NONE)) {
            int d = depth_on ? dsel : MOTE__D_NONE;
            int idx = (((tex * MOTE__TABLE_SHADES + shade) * 3 + (int)rs->persp) * 3 + d) * 2 + f;
            rs->fill[s] = mote__fill_table[idx];
        }
#else
        (void)format;
        (void)depth_format;
#endif
    }
#if MOTE_FIRMWARE_SPANS
    if (mote__fill_fw_fits(rs, format, depth_format))
        for (int s = MOTE__SHADE_FLAT; s <= MOTE__SHADE_BLACK; s++)
            rs->fill[s] = mote__fill_firmware;
#endif
    if (isa != MOTE__ISA_SCALAR)
        mote__simd_select(rs, format, depth_format, isa);
}
