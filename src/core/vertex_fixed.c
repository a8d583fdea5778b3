/*
 * vertex_fixed.c - the vertex stage in integer arithmetic, for cores
 * without an FPU (MOTE_FIXED_VERTEX): transform, normals and lighting,
 * clipping, the perspective divide, snapping and the conversion to setup's
 * units, with no float operation per vertex. A draw's float matrices and
 * lights are converted once, by their bits.
 *
 * Formats (each exponent chosen per draw so that nothing overflows):
 *   positions  P: a float mesh's rounded to 2^-ep of a unit about its
 *              bounding sphere's centre (the radius at 2^22 to 2^23
 *              units), a compact mesh's int16 as stored
 *   clip       X, Y, Z, W = mvp' P, |.| < 2^29.5, mvp' the draw's matrix
 *              with the centre or the dequantisation folded in, scaled by
 *              2^eo; coefficients of 27 bits, products and sums exact
 *   normals    unit vectors in Q14; lighting sums in Q16; shades 2^24
 *   snapping   round_half_up(X hw / W) exactly: a reciprocal of W
 *              (recip.c's), then the remainder
 *   depth      round(Z (2^24 - 1) / W), exactly, the same reciprocal
 * Products that need 64 bits are built from 16x16 ones where the core has
 * no 32x32->64 multiply (ARMv6-M), so no libgcc routine runs per vertex.
 * Divisions start from recip.c's reciprocal, the pixel stage's.
 */
#include "vertex_fixed.h"

#if MOTE_FIXED_VERTEX

/* ---- integer helpers ------------------------------------------------------ */

static inline uint32_t mote__fx_abs(int32_t a)
{
    return a < 0 ? 0u - (uint32_t)a : (uint32_t)a;
}

/* a b, exact, for |a b| < 2^63 */
MOTE__SPEED_INLINE int64_t mote__fx_smul(int32_t a, int32_t b)
{
#if MOTE__NO_UMULL
    /* a factor below 2^16 (the screen's sizes, most of lighting's
     * factors) takes two 16x16-bit products, not four */
    const uint32_t ua = mote__fx_abs(a), ub = mote__fx_abs(b);
    int64_t p = (int64_t)(ub >> 16 == 0   ? mote__umul64_short(ua, ub)
                          : ua >> 16 == 0 ? mote__umul64_short(ub, ua)
                                          : mote__umul64(ua, ub));
    return (a < 0) != (b < 0) ? -p : p;
#else
    return (int64_t)a * b;
#endif
}

static inline int mote__fx_clz(uint32_t x)    /* x != 0 */
{
#if defined(__GNUC__)
    return __builtin_clz(x);
#else
    int n = 0;
    while (!(x & 0x80000000u)) {
        x <<= 1;
        n++;
    }
    return n;
#endif
}

/* x 2^s for s >= 0 without shifting a negative number (undefined in C99) */
static inline int32_t mote__fx_shl(int32_t x, int s)
{
    return (int32_t)((uint32_t)x << s);
}

/* floor(n / d) (recip.c); false when it is 2^31 or more */
static bool mote__fx_udiv(uint64_t n, const mote__divisor *v, uint32_t *out)
{
    uint32_t q;
    if (!mote__divide(n, v, &q) || q >> 31)
        return false;
    *out = q;
    return true;
}

/* floor(a / d) (recip.c); false when its magnitude is 2^31 or more */
static bool mote__fx_sdiv(int64_t a, const mote__divisor *v, int32_t *out)
{
    int64_t q;
    if (!mote__divide_floor(a, v, &q) || q >= ((int64_t)1 << 31) || q <= -((int64_t)1 << 31))
        return false;
    *out = (int32_t)q;
    return true;
}

/* floor(a / d + 1/2) for a divisor d2 = 2 d: round half up, as the float
 * stage's snap rounds */
static bool mote__fx_round_div(int64_t a, uint32_t d, const mote__divisor *d2, int32_t *out)
{
    return mote__fx_sdiv(2 * a + (int64_t)d, d2, out);
}

/* 2^seed: 2^18 / sqrt(i + 1/2) for i in [16, 64), the seed of 2^31 /
 * sqrt(s) for s in [2^30, 2^32) from s >> 26 */
static const uint16_t mote__fx_rsqrt_seed[48] = {
    64535, 62664, 60947, 59364, 57898, 56535, 55265, 54076, 52961, 51912, 50923, 49989,
    49104, 48265, 47467, 46707, 45983, 45292, 44630, 43997, 43390, 42808, 42248, 41710,
    41192, 40693, 40211, 39746, 39297, 38863, 38443, 38036, 37642, 37260, 36889, 36529,
    36179, 35840, 35509, 35188, 34875, 34571, 34274, 33985, 33703, 33427, 33159, 32897};

/* v / |v| in Q14 (zero for zero): the largest component shifted to 15
 * bits, the sum of squares' reciprocal square root from a table and two
 * Newton steps */
static void mote__fx_normalize(const int32_t v[3], int32_t out[3])
{
    uint32_t m = MOTE__MAX(MOTE__MAX(mote__fx_abs(v[0]), mote__fx_abs(v[1])), mote__fx_abs(v[2]));
    if (m == 0) {
        out[0] = out[1] = out[2] = 0;
        return;
    }
    int sh = mote__fx_clz(m) - 17;    /* m 2^sh in [2^14, 2^15) */
    int32_t a[3];
    uint32_t s = 0;
    for (int k = 0; k < 3; k++) {
        a[k] = sh >= 0 ? mote__fx_shl(v[k], sh) : mote__floor_shift32(v[k], -sh);
        s += (uint32_t)(a[k] * a[k]);             /* < 3 2^30 */
    }
    int j = mote__fx_clz(s) >> 1;                 /* s 4^j in [2^30, 2^32) */
    uint32_t sn = s << (2 * j);
    uint32_t y = mote__fx_rsqrt_seed[(sn >> 26) - 16];   /* 2^31 / sqrt(sn), about 6 bits */
    for (int i = 0; i < 2; i++) {
        /* y (3 - sn y^2 / 2^62) / 2 */
        uint32_t t = (uint32_t)(mote__umul64(sn, y * y) >> 32);   /* about 2^30 */
        y = (uint32_t)(mote__umul64_short(3u * (1u << 30) - t, y) >> 31);   /* y <= 0xffff */
        y = y > 0xffffu ? 0xffffu : y;            /* y^2 stays in 32 bits */
    }
    /* 2^29 / sqrt(s) = y 2^(j - 2), j <= 1 as s >= 2^28 */
    y >>= 2 - j;
    for (int k = 0; k < 3; k++)
        out[k] = mote__floor_shift32(a[k] * (int32_t)y, 15);   /* |a y| <= 2^30 */
}

/* floor(log2 |f|) from the bits; -200 for zero and denormals, 128 for NaN and Inf */
static int mote__fx_exp(float f)
{
    int ex = (int)((mote__float_bits(f) >> 23) & 0xff);
    return ex == 0 ? -200 : ex - 127;
}

/* round(f 2^e), halves away from zero, when within +-lim (lim < 2^31);
 * false otherwise and for NaN and Inf. Denormals give 0. */
static bool mote__fx_round(float f, int e, int32_t lim, int32_t *out)
{
    uint32_t b = mote__float_bits(f);
    int ex = (int)((b >> 23) & 0xff);
    if (ex == 0xff)
        return false;
    uint32_t v = 0;
    if (ex != 0) {
        uint32_t m = (b & 0x7fffffu) | 0x800000u;
        int s = ex - 150 + e;
        if (s >= 0) {
            if (s > 7)
                return false;
            v = m << s;
        } else if (s > -26) {
            v = (m + (1u << (-s - 1))) >> -s;
        }
    }
    if (v > (uint32_t)lim)
        return false;
    *out = b >> 31 ? -(int32_t)v : (int32_t)v;
    return true;
}

/* round(f 2^e) clamped to +-lim (NaN: 0) */
static int32_t mote__fx_round_sat(float f, int e, int32_t lim)
{
    int32_t v;
    if (mote__fx_round(f, e, lim, &v))
        return v;
    if ((mote__float_bits(f) & 0x7fffffffu) > 0x7f800000u)
        return 0;
    return mote__float_bits(f) >> 31 ? -lim : lim;
}

/* 2^e as a float, e in [-126, 127] */
static float mote__fx_pow2(int e)
{
    union { float f; uint32_t u; } b;
    b.u = (uint32_t)(e + 127) << 23;
    return b.f;
}

/* v 2^-e as a float (v >= 0), for setup's w and the triangle hook's
 * depth: bits, not a conversion (a library call without an FPU); the
 * exponent is kept in float's normal range */
static float mote__fx_to_float(uint32_t v, int e)
{
    if (v == 0)
        return 0.0f;
    int top = 31 - mote__fx_clz(v);               /* v in [2^top, 2^(top+1)) */
    uint32_t m = top > 23 ? (v + (1u << (top - 24))) >> (top - 23) : v << (23 - top);
    if (m >> 24) {                                /* rounding carried */
        m >>= 1;
        top++;
    }
    int ex = top - e + 127;
    ex = ex < 1 ? 1 : ex > 254 ? 254 : ex;
    union { float f; uint32_t u; } b;
    b.u = ((uint32_t)ex << 23) | (m & 0x7fffffu);
    return b.f;
}

/* round(c 2^24 / 255) for a colour byte c: c 65793 + c 0.0039..., whose
 * fraction rounds up from c = 128 on */
static int32_t mote__fx_byte_shade(uint32_t c)
{
    return (int32_t)(c * 65793u + (c >> 7));
}

/* ---- a draw's fixed-point form ------------------------------------------------ */

/* Positions: |P| < 2^23 + 2^21, 2^23 and a margin for bounds a hair small;
 * the bits P has (MOTE__FX_PBITS, a compact mesh's 15) scale the rows. */
#define MOTE__FX_PBITS 23
#define MOTE__FX_PLIM ((1 << MOTE__FX_PBITS) + (1 << (MOTE__FX_PBITS - 2)))

/* Rows of a matrix for out_r = b_r + floor(sum_k A_rk P_k / 2^pbits),
 * |A| < 2^27 and |b| < 2^28, so |out| < 2^29.5: each product is 64-bit,
 * the sum exact (on ARMv6-M from 16-bit halves, mote__fx_dot3_halves). */
typedef struct mote__fx_rows {
#if MOTE__NO_UMULL
    int32_t ah[4][3];             /* A's 16-bit halves (mote__fx_dot3_halves) */
    uint32_t al[4][3];
#else
    int32_t a[4][3];
#endif
    int32_t b[4];
    int pbits;
} mote__fx_rows;

/* The largest exponent of the coefficients (k < 3) and of the
 * translations of rows [0, n) of a column-major m. */
static void mote__fx_row_exps(const float m[16], int n, int *ea, int *eb)
{
    *ea = *eb = -200;
    for (int r = 0; r < n; r++) {
        for (int k = 0; k < 3; k++)
            *ea = MOTE__MAX(*ea, mote__fx_exp(m[k * 4 + r]));
        *eb = MOTE__MAX(*eb, mote__fx_exp(m[12 + r]));
    }
}

/* rows [0, n) of m scaled by 2^e, for P of pbits bits; e as
 * mote__fx_scale chooses it keeps the bounds above */
static void mote__fx_rows_init(mote__fx_rows *o, const float m[16], int n, int e, int pbits)
{
    o->pbits = pbits;
    for (int r = 0; r < n; r++) {
        for (int k = 0; k < 3; k++) {
            const int32_t a = mote__fx_round_sat(m[k * 4 + r], e + pbits, (1 << 27) - 1);
#if MOTE__NO_UMULL
            o->al[r][k] = (uint32_t)a & 0xffffu;
            o->ah[r][k] = mote__floor_shift32(a, 16);
#else
            o->a[r][k] = a;
#endif
        }
        o->b[r] = mote__fx_round_sat(m[12 + r], e, (1 << 28) - 1);
    }
}

/* the largest e for which rows of coefficients and translations of
 * exponents ea and eb stay within the bounds, kept in float's range */
static int mote__fx_scale(int ea, int eb, int pbits)
{
    int e = MOTE__MIN(26 - pbits - ea, 27 - eb);  /* |A| < 2^(ea+1+e+pbits) <= 2^27, |b| < 2^28 */
    return MOTE__MAX(MOTE__MIN(e, 120), -120);
}

/* out_r for rows [0, n) */
static inline void mote__fx_rows_apply(const mote__fx_rows *o, int n, const int32_t P[3], int32_t *out)
{
#if MOTE__NO_UMULL
    int32_t ph[3];
    uint32_t pl[3];
    for (int k = 0; k < 3; k++) {
        pl[k] = (uint32_t)P[k] & 0xffffu;
        ph[k] = mote__floor_shift32(P[k], 16);
    }
    for (int r = 0; r < n; r++)
        out[r] = o->b[r] + mote__fx_dot3_halves(o->ah[r], o->al[r], ph, pl, o->pbits);
#else
    for (int r = 0; r < n; r++) {
        int64_t v = mote__fx_smul(o->a[r][0], P[0]) + mote__fx_smul(o->a[r][1], P[1])
                  + mote__fx_smul(o->a[r][2], P[2]);
        out[r] = o->b[r] + (int32_t)mote__floor_shift64(v, o->pbits);
    }
#endif
}

/* A light as the integer lighting reads it. */
typedef struct mote__fx_light {
    mote_light_type type;
    int32_t at[3];                /* point: position (world units 2^ew); else the unit vector toward the light, Q14 */
    int32_t kcol[3], kground[3];  /* intensity x colour, Q12 */
} mote__fx_lamp;

typedef struct mote__fvert mote__fvert;

typedef struct mote__fx {
    mote_device *dev;
    const mote_mesh *mesh;
    const mote__fixed_draw *fd;
    mote__fvert *cache;
    bool textured, gouraud, need_world, bottom;
    int32_t width, height;        /* the device's */
    int F;
    int32_t hw, hh, lim;          /* snap: half the size in sub-pixels, the limit */
    mote__divisor wdiv, hdiv;     /* width, height (clipping onto the guard band) */
    int ep;                       /* positions: P = round(p 2^ep) - C */
    int pbits;                    /* P's bits: MOTE__FX_PBITS, or 15 for a compact mesh */
    int32_t C[3];
    int eo, ew;                   /* clip and world scales */
    mote__fx_rows clip, world;
    int32_t N[3][3];              /* normal matrix, Q13 or less */
    int32_t amb[3];               /* ambient, Q16 */
    int32_t c8[3];                /* material colour, 255 = 1 */
    int32_t emissive[3];          /* 2^24 = 1 */
    int32_t unlit[3];             /* the shade of an unlit vertex */
    /* texels 16.16 = uv m 2^(e + 16) + b16, m a 24-bit mantissa */
    uint32_t tm[2];
    int te[2];
    bool tneg[2];
    int64_t tb[2];
    int lights;
    mote__fx_lamp light[MOTE_MAX_LIGHTS];
} mote__fx;

/* ---- vertices ----------------------------------------------------------------- */

/* A vertex of the draw's cache, transformed and, once a drawn triangle
 * uses it, finished (lit, in setup's units). */
struct mote__fvert {
    uint32_t index;               /* UINT32_MAX: empty */
    uint8_t state;                /* 1 valid, 2 invalid */
    bool ready;                   /* lit, sv set */
    uint16_t outcode;
    int32_t X, Y;                 /* snapped, when the outcode says so */
    int32_t c[4];                 /* clip x, y, z, w */
    int32_t wp[3];                /* world position (2^ew), once ready, where lighting needs it */
    int32_t n[3];                 /* unit normal Q14, once ready, lit draws */
    mote__svert sv;               /* texels from the transform; z, depth, w with the snap */
};

/* What clipping interpolates. */
typedef struct mote__fx_cvert {
    int32_t c[4];
    int32_t s[3];
    int64_t t[2];
} mote__fx_cvert;

#define MOTE__FX_CACHE MOTE_VERTEX_CACHE   /* direct-mapped, a power of two (mote.h) */

#define MOTE__OC_CLIP 0x3fu
#define MOTE__OC_REJECT 0xf3fu
#define MOTE__OC_NO_SNAP 0x1000u
#define MOTE__OC_INVALID 0x2000u
#define MOTE__CLIP_PLANES 6
#define MOTE__MAX_POLY (3 + MOTE__CLIP_PLANES)

/* Signed distances to the clip planes (inside >= 0), the guard band's
 * scaled by the size: x width + w 2^(G+1) >= 0 is x / w >= -2^G / (width / 2). */
static void mote__fx_dists(const mote__fx *f, const int32_t c[4], int64_t d[MOTE__CLIP_PLANES])
{
    int64_t gw = mote__fx_smul(c[3], 1 << (MOTE_GUARD_BITS + 1));
    int64_t xs = mote__fx_smul(c[0], f->width), ys = mote__fx_smul(c[1], f->height);
    d[0] = c[2];
    d[1] = (int64_t)c[3] - c[2];
    d[2] = xs + gw;
    d[3] = gw - xs;
    d[4] = ys + gw;
    d[5] = gw - ys;
}

static unsigned mote__fx_outcode(const mote__fx *f, const int32_t c[4])
{
    int64_t d[MOTE__CLIP_PLANES];
    mote__fx_dists(f, c, d);
    unsigned oc = 0;
    for (int p = 0; p < MOTE__CLIP_PLANES; p++)
        oc |= (unsigned)(d[p] < 0) << p;
    oc |= (unsigned)(c[0] > c[3]) << 8;
    oc |= (unsigned)(c[0] < -c[3]) << 9;
    oc |= (unsigned)(c[1] > c[3]) << 10;
    oc |= (unsigned)(c[1] < -c[3]) << 11;
    return oc;
}

/* Snapped position and setup's depth and w of a clip position: the
 * float stage's round_half_up(x / w hw) + hw, from the exact quotient.
 * False when w <= 0 or the position is past the snap's limit. */
static bool mote__fx_project(const mote__fx *f, const int32_t c[4], int32_t *X, int32_t *Y, mote__svert *sv)
{
    if (c[3] <= 0)
        return false;
    uint32_t w = (uint32_t)c[3];
    mote__divisor w2;
    /* setup's 1/w (mote__svert.qm, qe) from all of w's bits: with
     * m = 2 w 2^sh / 2 = w 2^sh in [2^30, 2^31), w 2^-eo is
     * 1/w = (2^61 / m) 2^(eo + sh - 61), the reciprocal 2w's divisor took */
    sv->qm = mote__divisor_init(&w2, 2 * w);
    sv->qe = 157 - f->eo - w2.sh;
    int32_t qx, qy;
    if (!mote__fx_round_div(mote__fx_smul(c[0], f->hw), w, &w2, &qx)
        || !mote__fx_round_div(mote__fx_smul(-c[1], f->hh), w, &w2, &qy))
        return false;
    qx += f->hw;
    qy += f->hh;
    if (qx <= -f->lim || qx >= f->lim || qy <= -f->lim || qy >= f->lim)
        return false;
    *X = qx;
    *Y = qy;
    /* z / w in [0, 1] as round(z (2^24 - 1) / w), half up */
    uint32_t z = 0;
    if (c[2] >= c[3])
        z = MOTE__DEPTH_MAX;
    else if (c[2] > 0)
        /* z (2^24 - 1) by a shift: a product is a call on ARMv6-M */
        mote__fx_udiv(2 * (((uint64_t)(uint32_t)c[2] << 24) - (uint32_t)c[2]) + w, &w2, &z);   /* < 2^24 */
    sv->z = (int32_t)z;
    /* only the triangle hook (a testing aid) reads it: a float division
     * there, none per vertex otherwise */
    sv->depth = f->dev->desc.triangle_hook ? (float)z / (float)MOTE__DEPTH_MAX : 0.0f;
    sv->w = f->dev->desc.triangle_hook ? mote__fx_to_float(w, f->eo) : 0.0f;
    return true;
}

/* a float as m 2^e, m a 24-bit mantissa (0 for zero and denormals);
 * false for NaN and Inf */
static bool mote__fx_split(float x, uint32_t *m, int *e, bool *neg)
{
    uint32_t b = mote__float_bits(x);
    int ex = (int)((b >> 23) & 0xff);
    *neg = (b >> 31) != 0;
    *m = ex ? (b & 0x7fffffu) | 0x800000u : 0;
    *e = ex - 150;
    return ex != 0xff;
}

/* round(m 2^e tm 2^te) + tb in 16.16 texels (m < 2^24); false past 2^30 texels */
static bool mote__fx_texel(const mote__fx *f, int a, uint32_t m, int e, bool neg, int64_t *out)
{
    uint64_t p = mote__umul64(m, f->tm[a]);      /* < 2^48 */
    int s = e + f->te[a];
    uint64_t v;
    /* the shifts by 32-bit halves: by a variable count, a 64-bit one is a
     * libgcc call on 32-bit cores */
    const uint32_t lo = (uint32_t)p, hi = (uint32_t)(p >> 32);
    if (p == 0) {
        v = 0;
    } else if (s >= 0) {
        if (s > 16 || (s <= 14 ? hi >> (14 - s) : hi | lo >> (46 - s)) != 0)   /* p 2^s < 2^46 */
            return false;
        v = s ? (uint64_t)(hi << s | lo >> (32 - s)) << 32 | (uint32_t)(lo << s) : p;
    } else if (-s < 50) {         /* p < 2^48: from 49 bits on the rounded value is 0 */
        const int h = -s - 1;     /* half a unit: 2^h */
        const uint64_t half = h < 32 ? (uint64_t)((uint32_t)1 << h) : (uint64_t)((uint32_t)1 << (h - 32)) << 32;
        v = (uint64_t)mote__floor_shift64((int64_t)(p + half), -s);
    } else {
        v = 0;
    }
    int64_t t = neg != f->tneg[a] ? -(int64_t)v : (int64_t)v;
    t += f->tb[a];
    const int64_t lim = (int64_t)1 << 46;
    if (t <= -lim || t >= lim)
        return false;
    *out = t;
    return true;
}

/* The vertex's position as P (false: NaN, Inf, or outside the draw's range) */
static bool mote__fx_position(const mote__fx *f, uint32_t index, int32_t P[3])
{
    if (f->mesh->compact) {
        for (int k = 0; k < 3; k++)
            P[k] = f->mesh->compact->positions[3 * index + k];
        return true;
    }
    const float *p = f->mesh->vertices[index].position;
    for (int k = 0; k < 3; k++) {
        int32_t v;
        if (!mote__fx_round(p[k], f->ep, (1 << 30) - 1, &v))
            return false;
        v -= f->C[k];
        if (v > MOTE__FX_PLIM || v < -MOTE__FX_PLIM)
            return false;
        P[k] = v;
    }
    return true;
}

static void mote__fx_transform(const mote__fx *f, uint32_t index, mote__fvert *v)
{
    v->index = index;
    v->ready = false;
    v->state = 2;
    v->outcode = MOTE__OC_INVALID;
    int32_t P[3];
    if (!mote__fx_position(f, index, P))
        return;
    mote__fx_rows_apply(&f->clip, 4, P, v->c);
    v->sv.texel[0] = v->sv.texel[1] = 0;
    if (f->textured) {
        const mote_compact *c = f->mesh->compact;
        for (int a = 0; a < 2; a++) {
            uint32_t m = 0;
            int e = 0;
            bool neg = false;
            if (c) {              /* an integer: m 2^0 */
                int32_t q = c->uvs ? c->uvs[2 * index + a] : 0;
                neg = q < 0;
                m = mote__fx_abs(q);
            } else if (!mote__fx_split(f->mesh->vertices[index].uv[a], &m, &e, &neg)) {
                return;
            }
            if (!mote__fx_texel(f, a, m, e, neg, &v->sv.texel[a]))
                return;
        }
    }
    v->state = 1;
    unsigned oc = mote__fx_outcode(f, v->c);
    /* only triangles with no vertex outside a clip plane use this snap */
    if (!(oc & MOTE__OC_CLIP) && !mote__fx_project(f, v->c, &v->X, &v->Y, &v->sv))
        oc |= MOTE__OC_NO_SNAP;
    v->outcode = (uint16_t)oc;
}

/* ---- lighting ------------------------------------------------------------------ */

/* q sat(a b / 2^10), a Q12 intensity, b Q14: a Q16 term, saturated */
static int32_t mote__fx_term(int32_t a, int32_t b)
{
    int64_t t = mote__floor_shift64(mote__fx_smul(a, b), 10);
    return t > (1 << 24) ? 1 << 24 : t < -(1 << 24) ? -(1 << 24) : (int32_t)t;
}

static int32_t mote__fx_clamp_acc(int32_t v)
{
    return v > (1 << 23) ? 1 << 23 : v < -(1 << 23) ? -(1 << 23) : v;
}

/* The light model of light.h's mote__light, in integers: wp the world
 * position (2^ew), n the unit normal (Q14); out in 2^24. */
static void mote__fx_light(const mote__fx *f, const int32_t wp[3], const int32_t n[3], int32_t out[3])
{
    int32_t acc[3] = {f->amb[0], f->amb[1], f->amb[2]};
    for (int i = 0; i < f->lights; i++) {
        const mote__fx_lamp *l = &f->light[i];
        int32_t L[3];
        if (l->type == MOTE_LIGHT_POINT) {
            int32_t d[3] = {l->at[0] - wp[0], l->at[1] - wp[1], l->at[2] - wp[2]};
            mote__fx_normalize(d, L);
        } else {
            memcpy(L, l->at, sizeof L);
        }
        int32_t ndl = mote__floor_shift32(n[0] * L[0] + n[1] * L[1] + n[2] * L[2], 14);
        if (l->type == MOTE_LIGHT_HEMISPHERIC) {
            int32_t w = mote__floor_shift32(ndl + (1 << 14), 1);   /* 0.5 + 0.5 n.l, Q14 */
            for (int c = 0; c < 3; c++)
                acc[c] = mote__fx_clamp_acc(acc[c] + mote__fx_clamp_acc(mote__fx_term(l->kcol[c], w)
                                                                        + mote__fx_term(l->kground[c], (1 << 14) - w)));
        } else if (ndl > 0) {
            for (int c = 0; c < 3; c++)
                acc[c] = mote__fx_clamp_acc(acc[c] + mote__fx_term(l->kcol[c], ndl));
        }
    }
    for (int c = 0; c < 3; c++) {
        /* acc x colour: (acc c8) 2^8 / 255 = t + t / 255 */
        int32_t t = acc[c] * f->c8[c];            /* |t| < 2^31 */
        if (t >= MOTE__SHADE_ONE || t <= -2 * MOTE__SHADE_ONE) {   /* saturated whatever follows */
            out[c] = t > 0 ? MOTE__SHADE_ONE : 0;
            continue;
        }
        int32_t v = t + mote__floor_shift32(t + mote__floor_shift32(t, 8) + mote__floor_shift32(t, 16), 8);
        v += f->emissive[c];
        out[c] = v < 0 ? 0 : v > MOTE__SHADE_ONE ? MOTE__SHADE_ONE : v;
    }
}

/* the vertex's world position (2^ew) */
static void mote__fx_world(const mote__fx *f, uint32_t index, int32_t wp[3])
{
    int32_t P[3];
    if (!mote__fx_position(f, index, P))          /* a valid vertex's is */
        P[0] = P[1] = P[2] = 0;
    mote__fx_rows_apply(&f->world, 3, P, wp);
}

/* the vertex's unit world normal, Q14 */
static void mote__fx_normal(const mote__fx *f, uint32_t index, int32_t n[3])
{
    const mote_compact *c = f->mesh->compact;
    int32_t q[3], w[3];                           /* |q| <= 2^13 */
    if (c) {
        for (int k = 0; k < 3; k++)
            q[k] = c->normals8 ? c->normals8[3 * index + k] * 32
                 : c->normals16 ? mote__floor_shift32(c->normals16[3 * index + k], 2) : 0;
    } else {
        const float *in = f->mesh->vertices[index].normal;
        int e = MOTE__MAX(MOTE__MAX(mote__fx_exp(in[0]), mote__fx_exp(in[1])), mote__fx_exp(in[2]));
        for (int k = 0; k < 3; k++)
            q[k] = mote__fx_round_sat(in[k], 12 - e, 1 << 13);
    }
    for (int r = 0; r < 3; r++)
        w[r] = f->N[r][0] * q[0] + f->N[r][1] * q[1] + f->N[r][2] * q[2];
    mote__fx_normalize(w, n);
}

/* What only drawn triangles need of a vertex: lighting and setup's shade. */
static void mote__fx_finish(const mote__fx *f, mote__fvert *v)
{
    if (v->ready)
        return;
    v->ready = true;
    if (!f->fd->lit) {
        memcpy(v->sv.s, f->unlit, sizeof v->sv.s);
        return;
    }
    if (f->need_world)
        mote__fx_world(f, v->index, v->wp);
    mote__fx_normal(f, v->index, v->n);
    if (f->gouraud)
        mote__fx_light(f, v->wp, v->n, v->sv.s);
    else
        memcpy(v->sv.s, f->unlit, sizeof v->sv.s);
}

/* ---- triangles ------------------------------------------------------------------ */

/* twice the signed area, 0 (counted) for a degenerate or culled one */
static int64_t mote__fx_facing(const mote__fx *f, const int32_t X[3], const int32_t Y[3])
{
    /* mote__area2 with this file's products (no libgcc call on ARMv6-M) */
    int64_t area = mote__fx_smul(X[1] - X[0], Y[2] - Y[0]) - mote__fx_smul(Y[1] - Y[0], X[2] - X[0]);
    if (area == 0) {
        f->dev->stats.triangles_degenerate++;
        return 0;
    }
    if (area > 0 ? f->fd->cull_cw : f->fd->cull_ccw) {
        f->dev->stats.triangles_backface++;
        return 0;
    }
    return area;
}

/* floor(s / 3) */
static int32_t mote__fx_third(int64_t s)
{
    static const mote__divisor three = {3, 0xaaaaaaabu, 30};   /* 2^63 / 3 2^30, rounded up */
    int32_t q = 0;
    mote__fx_sdiv(s, &three, &q);
    return q;
}

/* A flat triangle's shade: the lighting at its centroid, from its
 * geometric normal turned like its vertex normals. */
static void mote__fx_flat_shade(const mote__fx *f, mote__fvert *const tv[3], int32_t s[3])
{
    int32_t e[2][3], n[3], c[3], vsum[3], u[2][3];
    for (int k = 0; k < 3; k++) {
        e[0][k] = tv[1]->wp[k] - tv[0]->wp[k];
        e[1][k] = tv[2]->wp[k] - tv[0]->wp[k];
        c[k] = mote__fx_third((int64_t)tv[0]->wp[k] + tv[1]->wp[k] + tv[2]->wp[k]);
        vsum[k] = tv[0]->n[k] + tv[1]->n[k] + tv[2]->n[k];
    }
    /* the edges as unit vectors: their cross product's direction is the
     * normal's, and its parts fit 32 bits */
    mote__fx_normalize(e[0], u[0]);
    mote__fx_normalize(e[1], u[1]);
    n[0] = u[0][1] * u[1][2] - u[0][2] * u[1][1];
    n[1] = u[0][2] * u[1][0] - u[0][0] * u[1][2];
    n[2] = u[0][0] * u[1][1] - u[0][1] * u[1][0];
    if (mote__fx_smul(n[0], vsum[0]) + mote__fx_smul(n[1], vsum[1]) + mote__fx_smul(n[2], vsum[2]) < 0)
        for (int k = 0; k < 3; k++)
            n[k] = -n[k];
    mote__fx_normalize(n, n);
    mote__fx_light(f, c, n, s);
}

/* one triangle of a fan (or the whole one) on to setup */
static void mote__fx_emit(const mote__fx *f, mote__fvert *const tv[3], const mote__svert *const v[3],
                          const int32_t X[3], const int32_t Y[3])
{
    int64_t area = mote__fx_facing(f, X, Y);
    if (area == 0 || mote__fixed_emit_begin(f->fd->cx, X, Y, v))
        return;
    /* lit only now: a band that does not draw the triangle needs no shade */
    for (int k = 0; k < 3; k++)
        mote__fx_finish(f, tv[k]);
    if (f->fd->flat && f->fd->lit) {
        mote__svert own[3];
        int32_t s[3];
        mote__fx_flat_shade(f, tv, s);
        for (int k = 0; k < 3; k++) {
            own[k] = *v[k];
            memcpy(own[k].s, s, sizeof s);
        }
        const mote__svert *const ov[3] = {&own[0], &own[1], &own[2]};
        mote__fixed_emit(f->fd->cx, X, Y, area, ov);
        return;
    }
    mote__fixed_emit(f->fd->cx, X, Y, area, v);
}

/* a + floor((b - a) t / 2^30), t in [0, 2^30] */
static int32_t mote__fx_lerp32(int32_t a, int32_t b, int32_t t)
{
    return a + (int32_t)mote__floor_shift64(mote__fx_smul(b - a, t), 30);
}

static int64_t mote__fx_lerp64(int64_t a, int64_t b, int32_t t)
{
    int64_t d = b - a;                            /* |d| < 2^47 */
    int32_t dh = (int32_t)mote__floor_shift64(d, 16);
    uint32_t dl = (uint32_t)d & 0xffffu;
    return a + mote__floor_shift64(mote__fx_smul(dh, t), 14) + (int64_t)(mote__umul64(dl, (uint32_t)t) >> 30);
}

/* the point of a-b where plane p's distance da (>= 0) ... db (< 0) is 0 */
static void mote__fx_intersect(const mote__fx *f, const mote__fx_cvert *a, const mote__fx_cvert *b, int64_t da,
                               int64_t db, int p, mote__fx_cvert *out)
{
    uint64_t num = (uint64_t)da, den = (uint64_t)(da - db);
    while (den >> 31) {
        num >>= 1;
        den >>= 1;
    }
    mote__divisor dv;
    mote__divisor_init(&dv, (uint32_t)den);
    uint32_t t = 0;
    mote__fx_udiv(num << 30, &dv, &t);            /* <= 2^30 */
    for (int k = 0; k < 4; k++)
        out->c[k] = mote__fx_lerp32(a->c[k], b->c[k], (int32_t)t);
    for (int k = 0; k < 3; k++)
        out->s[k] = mote__fx_lerp32(a->s[k], b->s[k], (int32_t)t);
    for (int k = 0; k < 2; k++)
        out->t[k] = mote__fx_lerp64(a->t[k], b->t[k], (int32_t)t);
    /* exactly on the plane, on its inner side: near z = 0, far z = w, the
     * guard band at floor(w 2^(G+1) / size) */
    int32_t w = out->c[3] > 0 ? out->c[3] : 0;
    if (p < 2) {
        out->c[2] = p ? w : 0;
    } else {
        uint32_t g = 0x3fffffffu;                 /* past any clip x or y when the quotient is */
        mote__fx_udiv(mote__umul64((uint32_t)w, 1u << (MOTE_GUARD_BITS + 1)), p < 4 ? &f->wdiv : &f->hdiv, &g);
        out->c[p < 4 ? 0 : 1] = p & 1 ? (int32_t)g : -(int32_t)g;
    }
}

/* Sutherland-Hodgman as clip.c's mote__clip: the intersection always
 * from the inside vertex toward the outside one, so that both triangles
 * sharing an edge get the same point. */
static int mote__fx_clip(const mote__fx *f, mote__fx_cvert *poly, int n, unsigned planes)
{
    mote__fx_cvert tmp[MOTE__MAX_POLY];
    for (int p = 0; p < MOTE__CLIP_PLANES && n > 0; p++) {
        if (!(planes & (1u << p)))
            continue;
        int m = 0;
        for (int i = 0; i < n; i++) {
            const mote__fx_cvert *a = &poly[i], *b = &poly[i + 1 < n ? i + 1 : 0];
            int64_t da[MOTE__CLIP_PLANES], db[MOTE__CLIP_PLANES];
            mote__fx_dists(f, a->c, da);
            mote__fx_dists(f, b->c, db);
            bool ain = da[p] >= 0, bin = db[p] >= 0;
            if (ain && m < MOTE__MAX_POLY)
                tmp[m++] = *a;
            if (ain != bin && m < MOTE__MAX_POLY) {
                if (ain)
                    mote__fx_intersect(f, a, b, da[p], db[p], p, &tmp[m++]);
                else
                    mote__fx_intersect(f, b, a, db[p], da[p], p, &tmp[m++]);
            }
        }
        n = m;
        memcpy(poly, tmp, (size_t)n * sizeof *poly);
    }
    return n;
}

static void mote__fx_clip_polygon(const mote__fx *f, mote__fvert *const tv[3], unsigned planes)
{
    mote__fx_cvert poly[MOTE__MAX_POLY];
    for (int k = 0; k < 3; k++) {
        mote__fx_finish(f, tv[k]);                /* clipping interpolates the lit colour */
        memcpy(poly[k].c, tv[k]->c, sizeof poly[k].c);
        memcpy(poly[k].s, tv[k]->sv.s, sizeof poly[k].s);
        memcpy(poly[k].t, tv[k]->sv.texel, sizeof poly[k].t);
    }
    int n = mote__fx_clip(f, poly, 3, planes);
    if (n < 3) {
        f->dev->stats.triangles_clipped_away++;
        return;
    }
    int32_t X[MOTE__MAX_POLY], Y[MOTE__MAX_POLY];
    mote__svert sv[MOTE__MAX_POLY];
    for (int k = 0; k < n; k++) {
        if (!mote__fx_project(f, poly[k].c, &X[k], &Y[k], &sv[k])) {
            f->dev->stats.triangles_invalid++;
            return;
        }
        memcpy(sv[k].s, poly[k].s, sizeof sv[k].s);
        memcpy(sv[k].texel, poly[k].t, sizeof sv[k].texel);
    }
    for (int k = 1; k + 1 < n; k++) {
        const int32_t tx[3] = {X[0], X[k], X[k + 1]}, ty[3] = {Y[0], Y[k], Y[k + 1]};
        const mote__svert *const v[3] = {&sv[0], &sv[k], &sv[k + 1]};
        mote__fx_emit(f, tv, v, tx, ty);
    }
}

/* the cache's entry for a vertex, transformed */
static mote__fvert *mote__fx_vertex(const mote__fx *f, uint32_t index)
{
    mote__fvert *v = &f->cache[index & (MOTE__FX_CACHE - 1)];
    if (v->index != index)
        mote__fx_transform(f, index, v);
    return v;
}

static void mote__fx_triangle(const mote__fx *f, const uint32_t idx[3])
{
    mote_device *dev = f->dev;
    uint32_t nv = f->mesh->vertex_count;
    if (idx[0] >= nv || idx[1] >= nv || idx[2] >= nv) {
        dev->stats.triangles_invalid++;
        return;
    }
    mote__fvert *tv[3], own[3];
    for (int k = 0; k < 3; k++)
        tv[k] = mote__fx_vertex(f, idx[k]);
    /* two of them in one entry: the earlier one again, apart */
    for (int k = 0; k < 2; k++)
        if (tv[k]->index != idx[k]) {
            mote__fx_transform(f, idx[k], &own[k]);
            tv[k] = &own[k];
        }
    unsigned oc0 = tv[0]->outcode, oc1 = tv[1]->outcode, oc2 = tv[2]->outcode, any = oc0 | oc1 | oc2;
    if (any & MOTE__OC_INVALID) {
        dev->stats.triangles_invalid++;
        return;
    }
    if (oc0 & oc1 & oc2 & MOTE__OC_REJECT) {
        dev->stats.triangles_clipped_away++;
        return;
    }
    if (any & MOTE__OC_CLIP) {
        mote__fx_clip_polygon(f, tv, any & MOTE__OC_CLIP);
        return;
    }
    if (any & MOTE__OC_NO_SNAP) {
        dev->stats.triangles_invalid++;
        return;
    }
    const int32_t X[3] = {tv[0]->X, tv[1]->X, tv[2]->X}, Y[3] = {tv[0]->Y, tv[1]->Y, tv[2]->Y};
    const mote__svert *const v[3] = {&tv[0]->sv, &tv[1]->sv, &tv[2]->sv};
    mote__fx_emit(f, tv, v, X, Y);
}

/* ---- the draw ----------------------------------------------------------------------- */

/* ep and C: the positions' scale and centre (see the top of the file) */
static void mote__fx_positions(mote__fx *f)
{
    const mote_mesh *mesh = f->mesh;
    if (mesh->compact) {          /* P is the stored integer; draw.c folded the rest */
        f->pbits = 15;
        f->ep = 0;
        return;
    }
    int er = mote__fx_exp(mesh->bounds_radius), ec = -200;
    bool known = mesh->bounds_radius > 0.0f && er < 128;
    for (int k = 0; k < 3 && known; k++) {
        ec = MOTE__MAX(ec, mote__fx_exp(mesh->bounds_center[k]));
        known = ec < 128;
    }
    if (!known) {
        /* no bounds: about the origin, from the largest exponent there is */
        er = -200;
        for (uint32_t i = 0; i < mesh->vertex_count; i++)
            for (int k = 0; k < 3; k++) {
                int e = mote__fx_exp(mesh->vertices[i].position[k]);
                if (e < 128)
                    er = MOTE__MAX(er, e);
            }
        ec = -200;
    }
    f->ep = MOTE__MIN(MOTE__FX_PBITS - 1 - er, 28 - ec);
    f->ep = MOTE__MAX(MOTE__MIN(f->ep, 120), -120);
    for (int k = 0; k < 3; k++)
        f->C[k] = known ? mote__fx_round_sat(mesh->bounds_center[k], f->ep, (1 << 30) - 1) : 0;
}

/* the light i of the frame for the integer lighting; false: it lights nothing */
static bool mote__fx_light_init(mote__fx *f, const mote_light *l, mote__fx_lamp *o)
{
    if (l->type != MOTE_LIGHT_POINT && l->type != MOTE_LIGHT_DIRECTIONAL && l->type != MOTE_LIGHT_HEMISPHERIC)
        return false;
    o->type = l->type;
    float col[3];
    memcpy(col, l->color, sizeof col);
    if (mote__zero3(col))
        col[0] = col[1] = col[2] = 1.0f;
    float k = mote__or(l->intensity, 1.0f);
    for (int c = 0; c < 3; c++) {
        o->kcol[c] = mote__fx_round_sat(k * col[c], 12, 0x7fffffff);
        o->kground[c] = mote__fx_round_sat(k * l->ground_color[c], 12, 0x7fffffff);
    }
    if (l->type == MOTE_LIGHT_POINT) {
        for (int c = 0; c < 3; c++)
            o->at[c] = mote__fx_round_sat(l->position[c], f->ew, (1 << 28) - 1);
        return true;
    }
    /* the direction toward the light, as a unit vector */
    int e = MOTE__MAX(MOTE__MAX(mote__fx_exp(l->direction[0]), mote__fx_exp(l->direction[1])),
                      mote__fx_exp(l->direction[2]));
    int32_t d[3];
    for (int c = 0; c < 3; c++) {
        d[c] = mote__fx_round_sat(l->direction[c], 28 - e, 1 << 29);
        if (l->type == MOTE_LIGHT_DIRECTIONAL)
            d[c] = -d[c];
    }
    mote__fx_normalize(d, o->at);
    return true;
}

void mote__fixed_triangles(mote_device *dev, const mote_mesh *mesh, const mote__fixed_draw *fd, uint32_t first,
                           uint32_t end)
{
    mote__fx f;
    mote__fvert cache[MOTE__FX_CACHE];
    memset(&f, 0, sizeof f);
    f.dev = dev;
    f.mesh = mesh;
    f.fd = fd;
    f.cache = cache;
    for (int i = 0; i < MOTE__FX_CACHE; i++)
        cache[i].index = UINT32_MAX;
    const mote__raster_state *rs = fd->rs;
    f.textured = rs->tex != MOTE__TEX_NONE;
    f.gouraud = rs->gouraud;
    f.width = dev->desc.width;
    f.height = dev->desc.height;
    f.F = dev->desc.subpixel_bits;
    f.hw = f.width << (f.F - 1);
    f.hh = f.height << (f.F - 1);
    f.lim = (int32_t)1 << (MOTE_GUARD_BITS + 1 + f.F);
    mote__divisor_init(&f.wdiv, (uint32_t)f.width);
    mote__divisor_init(&f.hdiv, (uint32_t)f.height);

    /* positions, then the clip rows with them folded in */
    f.pbits = MOTE__FX_PBITS;
    mote__fx_positions(&f);
    const float unit = mote__fx_pow2(-f.ep);
    const float scale[3] = {unit, unit, unit};
    const float centre[3] = {(float)f.C[0] * unit, (float)f.C[1] * unit, (float)f.C[2] * unit};
    float m[16];
    int ea, eb;
    mote__compact_fold(fd->mvp, centre, scale, m);
    mote__fx_row_exps(m, 4, &ea, &eb);
    f.eo = mote__fx_scale(ea, eb, f.pbits);
    mote__fx_rows_init(&f.clip, m, 4, f.eo, f.pbits);

    const mote_material *mat = &mesh->material;
    for (int c = 0; c < 3; c++) {
        f.c8[c] = mat->color_set ? (&mat->color.r)[c] : 255;
#if MOTE_ENABLE_EMISSIVE
        f.emissive[c] = mote__fx_byte_shade((&mat->emissive.r)[c]);
#endif
        f.unlit[c] = mote__fx_byte_shade(f.c8[c]);
    }

    if (f.textured) {
        /* texel = uv a + b: u (uscale u + uoff) w, v likewise, or (1 - that) h */
        f.bottom = mat->v_origin_bottom;
        const float size[2] = {(float)rs->tex_w, (float)rs->tex_h};
        float a[2] = {fd->uscale * size[0], fd->vscale * size[1]};
        float b[2] = {fd->uoff * size[0], fd->voff * size[1]};
        if (f.bottom) {
            a[1] = -a[1];
            b[1] = size[1] - b[1];
        }
        for (int k = 0; k < 2; k++) {
            int e;
            if (!mote__fx_split(a[k], &f.tm[k], &e, &f.tneg[k]))
                f.tm[k] = 0;              /* texels of NaN: every vertex invalid, below */
            f.te[k] = e + 16;
            int32_t hi;
            /* b 2^16 as 2^16 hi + lo, within 2^46 */
            if (!mote__fx_round(b[k], 0, (1 << 30) - 1, &hi))
                f.tb[k] = (int64_t)1 << 47;   /* out of range: invalid */
            else
                f.tb[k] = (int64_t)mote__fx_round_sat(b[k] - (float)hi, 16, 1 << 17) + (int64_t)hi * 65536;
        }
    }

    if (fd->lit) {
        const mote_frame_desc *fr = &dev->frame;
        f.need_world = fd->flat;
        int el = -200;
        for (int i = 0; i < fr->light_count && i < MOTE_MAX_LIGHTS; i++)
            if (fr->lights[i].type == MOTE_LIGHT_POINT && !(fd->lights_off >> i & 1)) {
                f.need_world = true;
                for (int k = 0; k < 3; k++)
                    el = MOTE__MAX(el, mote__fx_exp(fr->lights[i].position[k]));
            }
        if (f.need_world) {
            mote__compact_fold(fd->world, centre, scale, m);
            mote__fx_row_exps(m, 3, &ea, &eb);
            f.ew = mote__fx_scale(ea, MOTE__MAX(eb, el), f.pbits);
            mote__fx_rows_init(&f.world, m, 3, f.ew, f.pbits);
        }
        int en = -200;
        for (int k = 0; k < 9; k++)
            en = MOTE__MAX(en, mote__fx_exp(fd->nrm[k]));
        for (int r = 0; r < 3; r++)
            for (int k = 0; k < 3; k++)
                f.N[r][k] = mote__fx_round_sat(fd->nrm[r * 3 + k], 12 - en, 1 << 13);
        for (int c = 0; c < 3; c++)
            f.amb[c] = mote__fx_round_sat(fr->ambient[c], 16, 1 << 23);
        for (int i = 0; i < fr->light_count && i < MOTE_MAX_LIGHTS; i++)
            if (!(fd->lights_off >> i & 1))   /* mote_draw_desc.lights_off */
                f.lights += mote__fx_light_init(&f, &fr->lights[i], &f.light[f.lights]);
    }

    const unsigned char *bins = fd->bins;
    for (uint32_t i = first; i < end && !(MOTE_ENABLE_BINNING && dev->bin.overflowed); i++) {
        if (bins ? fd->band < bins[2 * i] || fd->band > bins[2 * i + 1] : mote__fixed_skip(fd->cx, i))
            continue;
        uint32_t idx[3];
        mote__mesh_triangle(mesh, i, idx);
        mote__fx_triangle(&f, idx);
    }
}

#else
typedef int mote__vertex_fixed_unused;   /* ISO C: no empty translation unit */
#endif
