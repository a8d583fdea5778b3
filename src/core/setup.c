/*
 * setup.c - from three snapped vertices to a mote__tri: bounding box, edge
 * functions and the attribute planes the span loops step through.
 *
 * Interpolation uses perspective-correct barycentrics built from the exact
 * integer edge functions E_i (value at a pixel centre, sub-pixel^2 units):
 *     P1 = E1 q1,  P2 = E2 q2,  Q = E0 q0 + E1 q1 + E2 q2,  qi ~ 1/wi
 * so that b1 = P1/Q and b2 = P2/Q are Vulkan's perspective weights. All three
 * are linear in x and y with integer coefficients: stepping is exact.
 * Overflow: snapped coordinates are within +-2^(GUARD+1+8) = 2^22, so an
 * edge function over the bounding box is below 2^46; qbits is chosen per
 * triangle so that |Q| < 2^62. Depth is linear in screen space; its plane is
 * exact to rounding (24.16 fixed point), computed in 64-bit integers.
 *
 * The planes' origin is the pixel holding vertex 0, where E1 and E2 are
 * small (both vanish at vertex 0), so the depth products fit in 64 bits.
 * The weights qi come from each vertex's 1/w as mantissa and exponent
 * (mote__inverse_w) by shifts: no float arithmetic at all.
 *
 * The pixel loops (span.c) take these 64-bit planes down to 32 bits a
 * block of pixels at a time; what they need for it is set here: the
 * reciprocal's K (rbits), n_extra and texel_bits (see mote__tri).
 */
#include "internal.h"

/* floor(a b / 2^s) for 0 < s < 64 (setup's shifts are 10 and more),
 * exact (128-bit product), modulo 2^64 when it does not fit: the same bits
 * on every target. MOTE_NO_INT128 selects the portable path on a host
 * that has __int128 (tests/test_setup_portable.c compares the two). */
static int64_t mote__mul_shift(int64_t a, int64_t b, int s)
{
#if defined(__SIZEOF_INT128__) && !defined(MOTE_NO_INT128)
    __extension__ typedef __int128 mote__i128;
    /* the low half as a 64-bit product (the same bits signed or not):
     * split from one 128-bit value, GCC passed it through the stack */
    uint64_t lo = (uint64_t)a * (uint64_t)b, hi = (uint64_t)(((mote__i128)a * b) >> 64);
    /* the low 64 bits of hi:lo shifted by s, by two plain shifts: with a
     * 128-bit shift by a variable count GCC emits x86's slow shrd and a
     * test for s >= 64 (1.75 against 1.15 ns a product in a loop, on the
     * CI machine's AMD EPYC) */
    return (int64_t)((lo >> s) | (hi << (64 - s)));
#else
    /* |a| |b| as hi:lo from 32x32-bit products (mote__umul64: four 16-bit
     * ones where the core has no long multiply; a's high half is 0 for
     * the attribute differences setup passes, so two of them are skipped),
     * floored by s; a negative product's floor is minus the magnitude's
     * ceiling, which the bits shifted out decide */
    const bool neg = (a < 0) != (b < 0);
    const uint64_t x = a < 0 ? 0u - (uint64_t)a : (uint64_t)a, y = b < 0 ? 0u - (uint64_t)b : (uint64_t)b;
    const uint32_t xl = (uint32_t)x, xh = (uint32_t)(x >> 32), yl = (uint32_t)y, yh = (uint32_t)(y >> 32);
    const uint64_t ll = mote__umul64(xl, yl), lh = mote__umul64(xl, yh);
    uint64_t mid = (ll >> 32) + (uint32_t)lh, hi = lh >> 32;
    if (xh != 0) {                /* the other two, and their sums, only then */
        const uint64_t hl = mote__umul64(xh, yl);
        mid += (uint32_t)hl;
        hi += mote__umul64(xh, yh) + (hl >> 32);
    }
    hi += mid >> 32;
    /* bits [s, s + 64) of the 128-bit product by 32-bit words: a shift of
     * a 64-bit number by a variable count is a libgcc call on 32-bit cores */
    const bool up = s >= 32;      /* the words from 1 (mid) on, else from 0 */
    const uint32_t w0 = up ? (uint32_t)mid : (uint32_t)ll, w1 = up ? (uint32_t)hi : (uint32_t)mid,
                   w2 = up ? (uint32_t)(hi >> 32) : (uint32_t)hi;
    const int bit = s & 31;
    const uint32_t rl = bit ? w0 >> bit | w1 << (32 - bit) : w0;
    const uint32_t rh = bit ? w1 >> bit | w2 << (32 - bit) : w1;
    const uint64_t r = (uint64_t)rh << 32 | rl;
    const bool dropped = (up && (uint32_t)ll != 0) || (w0 & ((1u << bit) - 1u)) != 0;
    return (int64_t)(neg ? 0u - r - dropped : r);
#endif
}

/* Shortcuts: the same bits as the code they stand in for, in fewer
 * instructions on a 64-bit host. They need GCC's or Clang's definitions
 * (>> of a negative number is the arithmetic shift; __builtin_mul_overflow),
 * and size builds leave them out (MOTE_SHORTCUTS). */
#if MOTE_SHORTCUTS && defined(__GNUC__)
#define MOTE__SETUP_FAST 1
#define MOTE__SETUP_INLINE static inline __attribute__((always_inline))

/* floor(v / 2^k) in one instruction, where mote__floor_shift64 takes
 * four */
static inline int64_t mote__sar64(int64_t v, int k) { return v >> k; }

/* mote__floor_div64 for b > 0: the remainder's sign alone corrects */
static inline int64_t mote__floor_div_pos(int64_t a, int64_t b) { return a / b - (a % b < 0); }

/* mote__mul_shift(a1, b1, s) + mote__mul_shift(a2, b2, s) modulo 2^64 (a
 * component of a numerator plane), m being 2^(64-s): the two high halves
 * join before they move into place, by a multiply, where each product's
 * shift left by 64 - s took x86 a second count in cl (the grid's setup: 5%
 * fewer instructions) */
static inline int64_t mote__mul_shift2(int64_t a1, int64_t b1, int64_t a2, int64_t b2, int s, uint64_t m)
{
#if defined(__SIZEOF_INT128__) && !defined(MOTE_NO_INT128)
    __extension__ typedef unsigned __int128 mote__u128;
    __extension__ typedef __int128 mote__i128;
    (void)mote__mul_shift;        /* the general code's, which this replaces */
    /* the second low half as a 64-bit product: taken from the 128-bit
     * value too, it went through the stack */
    mote__u128 p1 = (mote__u128)((mote__i128)a1 * b1);
    uint64_t lo = (uint64_t)p1 >> s, hi = (uint64_t)(p1 >> 64);
    lo += (uint64_t)a2 * (uint64_t)b2 >> s;
    hi += (uint64_t)((mote__u128)((mote__i128)a2 * b2) >> 64);
    return (int64_t)(lo + hi * m);
#else
    (void)m;
    return (int64_t)((uint64_t)mote__mul_shift(a1, b1, s) + (uint64_t)mote__mul_shift(a2, b2, s));
#endif
}
#else
#define MOTE__SETUP_FAST 0
#define MOTE__SETUP_INLINE static inline
#define mote__floor_div_pos mote__floor_div64
#endif

MOTE__SPEED_INLINE int64_t mote__abs64(int64_t v) { return v < 0 ? -v : v; }
static inline uint32_t mote__abs32u(int32_t v) { return v < 0 ? 0u - (uint32_t)v : (uint32_t)v; }

/* mote__floor_shift64, skipped for the usual k = 0 (mip level 0, no
 * texel bits dropped): a size build calls it, a 64-bit shift in libgcc */
static inline int64_t mote__floor_shift_k(int64_t v, int k) { return k != 0 ? mote__floor_shift64(v, k) : v; }

MOTE__SPEED_INLINE int64_t mote__floor_div64(int64_t a, int64_t b)
{
#if MOTE__CORE32
    /* by the magnitudes, without libgcc's 64-bit division (recip.c); a
     * negative quotient's floor is minus the magnitudes' ceiling */
    const uint64_t ua = a < 0 ? 0u - (uint64_t)a : (uint64_t)a, ub = b < 0 ? 0u - (uint64_t)b : (uint64_t)b;
    const bool neg = (a < 0) != (b < 0);
    const uint64_t q = mote__udiv64(neg ? ua + ub - 1 : ua, ub);
    return (int64_t)(neg ? 0u - q : q);
#else
    int64_t q = a / b, r = a - q * b;   /* r has a's sign */
    return q - ((r != 0) & ((r < 0) != (b < 0)));
#endif
}

/* Cores without a divide instruction (ARMv6-M, where MOTE__NO_UMULL is
 * set) divide the depth plane's three numerators by one reciprocal of
 * twice the area (recip.c's mote__divide_floor), where a 64-bit division
 * is a libgcc routine (some 400 instructions on Cortex-M0+). Cores that divide in hardware gain nothing
 * from it (Cortex-M4F, `make bench-embedded`). */
#define MOTE__DIVIDE_BY_RECIP (MOTE__CORE32 && MOTE__NO_UMULL)


/* floor(a / d) for d > 0; dv, when not NULL, is d's mote__divisor */
static inline int64_t mote__depth_div(int64_t a, int64_t d, const mote__divisor *dv)
{
#if MOTE__DIVIDE_BY_RECIP
    int64_t q;
    if (dv && mote__divide_floor(a, dv, &q))
        return q;
#else
    (void)dv;
#endif
    return mote__floor_div_pos(a, d);
}

/* round(n * 2^16 / d) for |n| < 2^58 and 0 < d < 2^47; beyond +-2^44
 * (16x the whole depth range per pixel: only slivers far thinner than a
 * pixel reach that) it sets *huge and returns 0, so that stepping can
 * never overflow. */
static inline int64_t mote__scaled_div(int64_t n, int64_t d, const mote__divisor *dv, bool *huge)
{
    const int64_t cap = (int64_t)1 << 44, big = (int64_t)1 << 46;
    int64_t q = 0;
    if (n >= big || n <= -big) {  /* rare: n * 2^16 would not fit; whole part first */
        q = mote__floor_div_pos(n, d);
        if (q >= cap >> 16 || q < -(cap >> 16)) {
            *huge = true;
            return 0;
        }
        n -= q * d;               /* now in [0, d) */
    }
    int64_t v = q * 65536 + mote__depth_div(n * 65536 + (d >> 1), d, dv);   /* d > 0 */
    if (v > cap || v < -cap) {
        *huge = true;
        return 0;
    }
    return v;
}

/* A coefficient of the Q plane as the triangle keeps it: Q 2^(10 - shift),
 * floored, so that the pixel loops' Q >> shift is Q's plane shifted by a
 * constant (by the triangle's count, it took them a register and four
 * instructions a pixel). Ten more bits keep the floored steps' drift to
 * 2^-10 of a unit of Q >> shift a pixel; below shift 10 nothing is lost.
 * Modulo 2^64: at the triangle's pixels Q >> shift < 2^31, so the values
 * the loops divide by are right whatever a coefficient wraps to. */
MOTE__SPEED_INLINE int64_t mote__q_plane(int64_t v, int shift)
{
    return shift >= 10 ? mote__floor_shift64(v, shift - 10) : (int64_t)((uint64_t)v << (10 - shift));
}

/* v rounded down to a multiple of period (> 0); a shift and a mask for the
 * usual power-of-two texture */
static int64_t mote__floor_multiple(int64_t v, int64_t period)
{
    if ((period & (period - 1)) == 0)
        return (int64_t)((uint64_t)v & ~(uint64_t)(period - 1));
    return mote__floor_div64(v, period) * period;
}

/* whether vertex i comes before vertex j in the walk: by y, then x */
MOTE__SPEED_INLINE int mote__before(const int32_t X[3], const int32_t Y[3], int i, int j)
{
    return (Y[i] < Y[j]) | ((Y[i] == Y[j]) & (X[i] < X[j]));
}

#if MOTE_ENABLE_MIPMAPS
/* The mip level of a triangle (MOTE_MIP_TRIANGLE): round(log2 rho), rho^2
 * the texel area (level 0, vertices' 16.16 texels) over the pixel area
 * (a2, twice the area in units of 2^-F pixel), clamped to the chain. In
 * float: texel differences reach 2^45, their products past 64 bits. */
static int mote__mip_level(const mote__raster_state *rs, const mote__svert *const v[3], int64_t a2, int F)
{
    const float du1 = (float)(v[1]->texel[0] - v[0]->texel[0]), dv1 = (float)(v[1]->texel[1] - v[0]->texel[1]);
    const float du2 = (float)(v[2]->texel[0] - v[0]->texel[0]), dv2 = (float)(v[2]->texel[1] - v[0]->texel[1]);
    float texels = du1 * dv2 - du2 * dv1;
    texels = texels < 0.0f ? -texels : texels;
    /* rho^2 = texels 2^-32 / (a2 2^-2F): level L when rho^2 >= 2 4^(L-1) */
    float r = texels / ((float)a2 * (float)((int64_t)1 << (32 - 2 * F)));
    int level = 0;
    for (float at = 2.0f; r >= at && level + 1 < rs->mips->count; at *= 4.0f)
        level++;
    return level;
}
#endif

/* Pixel bounding box: the pixels whose centre lies in the vertices'
 * box, x from ceil((minx - half) / one) to floor((maxx - half) / one).
 * Clamped to the viewport, it holds every pixel the planes are evaluated
 * at. A triangle that holds no pixel centre (about 2% of a dense mesh's)
 * ends here, and a box no wider than its pixels puts a triangle in no
 * tile it does not touch. */
/* mote__setup_box, with the vertices' extents {minx, miny, maxx, maxy}
 * for setup (inline there: the call and the extents taken again cost a
 * dense mesh 10% of setup) */
MOTE__SETUP_INLINE mote__setup_result mote__box(const int32_t X[3], const int32_t Y[3], int F, int width,
                                                int height, int box[4], int32_t ext[4])
{
    const int32_t one = (int32_t)1 << F, h32 = one >> 1, up = one - 1 - h32;
    const int32_t minx = MOTE__MIN(X[0], MOTE__MIN(X[1], X[2])), maxx = MOTE__MAX(X[0], MOTE__MAX(X[1], X[2]));
    const int32_t miny = MOTE__MIN(Y[0], MOTE__MIN(Y[1], Y[2])), maxy = MOTE__MAX(Y[0], MOTE__MAX(Y[1], Y[2]));
    ext[0] = minx;
    ext[1] = miny;
    ext[2] = maxx;
    ext[3] = maxy;
    int x0 = mote__floor_shift32(minx + up, F), x1 = mote__floor_shift32(maxx - h32, F);
    int y0 = mote__floor_shift32(miny + up, F), y1 = mote__floor_shift32(maxy - h32, F);
    if (x0 > x1 || y0 > y1)
        return MOTE__SETUP_EMPTY;
    box[0] = MOTE__MAX(x0, 0);
    box[1] = MOTE__MAX(y0, 0);
    box[2] = MOTE__MIN(x1, width - 1);
    box[3] = MOTE__MIN(y1, height - 1);
    return box[0] > box[2] || box[1] > box[3] ? MOTE__SETUP_OUTSIDE : MOTE__SETUP_DRAWN;
}

mote__setup_result mote__setup_box(const int32_t X[3], const int32_t Y[3], int F, int width, int height, int box[4])
{
    int32_t ext[4];
    return mote__box(X, Y, F, width, height, box, ext);
}

/* mote__setup for F sub-pixel bits: speed builds make a copy for the
 * default 8, where every shift by F is by a constant */
MOTE__SETUP_INLINE mote__setup_result mote__setup_f(mote__tri *t, const mote__raster_state *rs, const int32_t Xin[3],
                                                    const int32_t Yin[3], int64_t area2,
                                                    const mote__svert *const vin[3], int F, int width, int height)
{
    const int64_t one = (int64_t)1 << F, half = one >> 1;

    /* Vertex 0, where the planes are anchored, is the first in the walk's
     * order (by y, then x), whatever order the mesh lists the vertices in.
     * The other two enter every plane alike, so a pixel's rounding of depth
     * and attributes does not depend on that order either (with vertex 0
     * as given, about 2% of depths moved by a unit). A rotation keeps the
     * winding. */
    /* first the box, the same in any order: a triangle with no pixel
     * ends before the rest */
    int box[4];
    int32_t ext[4];
    const mote__setup_result inside = mote__box(Xin, Yin, F, width, height, box, ext);
    if (inside != MOTE__SETUP_DRAWN)
        return inside;
    int top = mote__before(Xin, Yin, 1, 0);
    top = mote__before(Xin, Yin, 2, top) ? 2 : top;
    const mote__svert *v[3];
    for (int i = 0; i < 3; i++) {
        int j = i + top < 3 ? i + top : i + top - 3;
        t->X[i] = Xin[j];
        t->Y[i] = Yin[j];
        v[i] = vin[j];
    }
    const int32_t *const X = t->X, *const Y = t->Y;

    const int x0 = box[0], y0 = box[1], x1 = box[2], y1 = box[3];
    const int32_t minx = ext[0], miny = ext[1], maxx = ext[2], maxy = ext[3];
    /* every field is written below: no memset of the whole record */
    t->rs = rs;
    t->xmin = (int16_t)x0;
    t->xmax = (int16_t)x1;
    t->ymin = (int16_t)y0;
    t->ymax = (int16_t)y1;
    /* origin: the pixel holding vertex 0 (in the guard band, so int16 fits) */
    const int ox = mote__floor_shift32(X[0], F), oy = mote__floor_shift32(Y[0], F);
    t->ox = (int16_t)ox;
    t->oy = (int16_t)oy;

    /* Edge function of vertex i (zero on the opposite edge j-k, 2*area at
     * vertex i), at the origin pixel centre, and its steps per pixel; the
     * winding's sign is folded into the edge vector. */
    /* in 32 bits: coordinates and their differences are below 2^24, and
     * the origin pixel's centre is vertex 0 with its low F bits replaced */
    const int32_t cx = (X[0] & -(int32_t)one) + (int32_t)half, cy = (Y[0] & -(int32_t)one) + (int32_t)half;
    /* ed[3 j + i]: edge i's value (j = 0), x step (1), y step (2) */
    int64_t ed[9], *const e = ed, *const edx = ed + 3, *const edy = ed + 6;
    /* within 2^14 sub-pixels each way, E and its steps fit 32 bits: |ax|,
     * |ay| <= 2^14, |cx - X[j]|, |cy - Y[j]| <= 2^14 + 2^(F-1), so each
     * product is below 2^29; a 32-bit core then needs no 64-bit product */
    const bool small = MOTE__CORE32 && maxx - minx <= (1 << 14) && maxy - miny <= (1 << 14);
    for (int i = 0, j = 1, k = 2; i < 3; j = k, k = i, i++) {
        int32_t ax = X[k] - X[j], ay = Y[k] - Y[j];
        if (area2 < 0) {
            ax = -ax;
            ay = -ay;
        }
        if (small) {
            e[i] = ax * (cy - Y[j]) - ay * (cx - X[j]);
            edx[i] = -ay * (int32_t)one;
            edy[i] = ax * (int32_t)one;
            continue;
        }
        e[i] = (int64_t)ax * (cy - Y[j]) - (int64_t)ay * (cx - X[j]);
        edx[i] = (int64_t)((uint64_t)-(int64_t)ay << F);
        edy[i] = (int64_t)((uint64_t)(int64_t)ax << F);
    }
    int64_t a2 = area2 < 0 ? -area2 : area2;

    /* Rows are walked from the top vertex a (vertex 0, above), via b, to c:
     * their order, and whether the long edge a-c is on the left, which is
     * the winding of (a, b, c): area2's sign, flipped when 2 comes before 1. */
    {
        int swap = mote__before(X, Y, 2, 1);
        t->order = (uint8_t)((swap ? 2 << 2 | 1 << 4 : 1 << 2 | 2 << 4) | ((area2 > 0) != swap) << 6);
    }

    /* any pixel loop stays defined (N = 0: A = a0) */
    t->rbits = 30;
    t->q_drop = 0;
    t->n_extra = 0;
    t->texel_bits = MOTE__TEXEL_BITS;
    t->q = t->qdx = t->qdy = 0;
    /* The shade: vertex 0's, and the differences to it (shades and their
     * differences fit in 32 bits). It is grey when its three channels agree
     * at every vertex, constant when no channel changes, and black when it
     * is also zero (shades are >= 0): mote__modulate(c, 0) is 0 for any
     * texel, so a black triangle needs no weights. Tested with bits. */
    int64_t d1[MOTE__ATTRS], d2[MOTE__ATTRS];
    uint32_t differ = 0, vary = 0, lit = 0, dmag = 0;
    static const int channel_attr[3] = {MOTE__A_R, MOTE__A_G, MOTE__A_B};
    for (int c = 0; c < 3; c++) {
        int32_t s0 = v[0]->s[c];
        int32_t e1 = v[1]->s[c] - s0, e2 = v[2]->s[c] - s0;
        const int a = channel_attr[c];
        t->a0[a] = s0;
        d1[a] = e1;
        d2[a] = e2;
        differ |= (uint32_t)(s0 ^ (int32_t)t->a0[MOTE__A_R]) | (uint32_t)(e1 ^ (int32_t)d1[MOTE__A_R])
                | (uint32_t)(e2 ^ (int32_t)d2[MOTE__A_R]);
        vary |= (uint32_t)(e1 | e2);
        lit |= (uint32_t)s0;
        dmag |= mote__abs32u(e1) | mote__abs32u(e2);
    }
    if (!rs->gouraud)             /* one shade per triangle: vertex 0's */
        vary = 0;
    /* a black triangle whose texels' alpha cuts or blends still reads
     * them: flat, at shade 0 */
    t->shade = vary != 0 ? (differ == 0 ? MOTE__SHADE_MONO : MOTE__SHADE_RGB)
             : lit != 0 || (rs->alpha & (MOTE__ALPHA_TEST | MOTE__ALPHA_TEXEL)) || mote__has_layers(rs) ? MOTE__SHADE_FLAT
             : MOTE__SHADE_BLACK;
#if MOTE__ADD_ENABLED
    /* an additive colour (highlights, fog): three planes more, and all
     * three shade channels, for the generic loop */
    if (rs->additive)
        t->shade = MOTE__SHADE_ADD;
    for (int c = 0; c < 3; c++) {
        const int a = MOTE__A_AR + c;
        t->a0[a] = d1[a] = d2[a] = 0;
        if (rs->additive) {
            t->a0[a] = v[0]->a[c];
            d1[a] = v[1]->a[c] - v[0]->a[c];
            d2[a] = v[2]->a[c] - v[0]->a[c];
            dmag |= mote__abs32u((int32_t)d1[a]) | mote__abs32u((int32_t)d2[a]);
        }
    }
#endif
    t->a0[MOTE__A_U] = t->a0[MOTE__A_V] = 0;
    bool needs_weights = t->shade != MOTE__SHADE_BLACK && (rs->gouraud || rs->tex != MOTE__TEX_NONE);
    if (!needs_weights)
        memset(t->n, 0, sizeof t->n);
    else {
        /* Precision: each qi ~ 1/wi needs many bits, the far vertex's most
         * (its qi is smallest). |E| qi must stay below 2^61, so big
         * triangles drop up to F low bits of E first: the steps are
         * multiples of 2^F and stay exact, only the origin value rounds.
         * E then keeps >= 33 bits and qi gets up to 28.
         * The largest |E| over the box decides. It is at most
         * 2 Sx Sy + 2^F (Sx + Sy) (Sx, Sy: the triangle's extents; the
         * box's centres lie within 2^F of them); while that and 2 area stay
         * below 2^31 - 1, k is 0 and qbits 28 whatever the exact value,
         * which only larger triangles compute. */
        const int64_t sx = maxx - minx, sy = maxy - miny;
        int64_t emax = 2 * sx * sy + one * (sx + sy);
        if (MOTE__MAX(emax, a2) > ((int64_t)1 << 31) - 2) {
            /* E is linear: its largest and smallest values over the box
             * take each axis's term at its larger and smaller end */
            const int32_t b0[2] = {x0 - ox, y0 - oy}, b1[2] = {x1 - ox, y1 - oy};
            emax = 0;
            for (int i = 0; i < 3; i++) {
                int64_t hi = e[i], lo = e[i];
                for (int j = 0; j < 2; j++) {
                    /* b0 <= b1: the step's sign says which end is larger */
                    int64_t step = ed[3 * j + 3 + i], pa = step * b0[j], pb = step * b1[j];
                    if (step < 0) {
                        int64_t tmp = pa;
                        pa = pb;
                        pb = tmp;
                    }
                    hi += pb;
                    lo += pa;
                }
                emax = MOTE__MAX(emax, MOTE__MAX(hi, -lo));
            }
        }
        int eb = mote__bitlen((uint64_t)MOTE__MAX(emax, a2));
        int k = MOTE__MIN(MOTE__MAX(eb - 33, 0), F);
        /* pd: ed >> k (steps are multiples of 2^F >= 2^k: exact), ed itself
         * for the usual k = 0 */
        int64_t shifted[9];
        const int64_t *pd = ed;
        if (k != 0) {
            for (int i = 0; i < 9; i++)
                shifted[i] = mote__floor_shift64(ed[i], k);
            pd = shifted;
        }
        int64_t a2k = (a2 >> k) + 1;
        int qbits = 61 - 2 - mote__bitlen((uint64_t)MOTE__MAX((emax >> k) + 1, a2k));
        qbits = MOTE__MIN(qbits, 28);
        qbits = MOTE__MAX(qbits, 0);
        int64_t q[3];
        if (rs->persp == MOTE__PERSP_AFFINE) {
            /* equal weights, as large as perspective's: Q keeps as many bits */
            q[0] = q[1] = q[2] = (int64_t)1 << qbits;
        } else {
            /* qi = 1/wi 2^qbits / max(1/w), rounded, from the mantissas
             * (in (2^30, 2^31]) shifted by the exponents' differences: the
             * largest is at most 2^qbits (qbits <= 28: shifts of 3 and up) */
            const int32_t emin = MOTE__MIN(v[0]->qe, MOTE__MIN(v[1]->qe, v[2]->qe));
            for (int i = 0; i < 3; i++) {
                const int32_t sh = 31 - qbits + (v[i]->qe - emin);
                q[i] = sh < 32 ? (v[i]->qm + ((uint32_t)1 << (sh - 1))) >> sh : 0;
                if (q[i] < 1)
                    q[i] = 1;
            }
        }
        int64_t p1[3], p2[3];     /* P1 and P2: value, x step, y step */
        for (int j = 0; j < 3; j++) {
            p1[j] = pd[3 * j + 1] * q[1];
            p2[j] = pd[3 * j + 2] * q[2];
        }
        /* Q straight into the triangle: through an array, GCC copied two
         * of its values as one 16-byte load of what it had just stored as
         * 8-byte halves, which stalls (about 5% of setup's time) */
        int s = mote__bitlen((uint64_t)a2k) + qbits - 30;
        const int shift = MOTE__MAX(s, 0);
        t->q = mote__q_plane(pd[0] * q[0] + p1[0] + p2[0], shift);
        t->qdx = mote__q_plane(pd[3] * q[0] + p1[1] + p2[1], shift);
        t->qdy = mote__q_plane(pd[6] * q[0] + p1[2] + p2[2], shift);

        /* Inside the triangle the Q plane (t->q's units) lies between the
         * smallest and the largest qi times 2 area (Q is a sum of the Ei,
         * >= 0 there and adding up to 2 area, weighted by the qi). When the
         * qi are within 4x of each other, one shift q_drop takes it below
         * 2^30 everywhere, and K = bitlen(least) + 29 keeps r = 2^K / q
         * below 2^30 (with q >= 2^28 it keeps 28 bits); otherwise the pixel
         * loops choose both per block, so that the far end keeps its bits. */
        {
            const int64_t qmin = MOTE__MIN(q[0], MOTE__MIN(q[1], q[2]));
            const int64_t qmax = MOTE__MAX(q[0], MOTE__MAX(q[1], q[2]));
            const int64_t most = mote__q_plane((a2 >> k) * qmax, shift);
            const int d = MOTE__MAX(mote__bitlen((uint64_t)most) - 30, 0);
            const int64_t least = mote__q_plane((a2 >> k) * qmin, shift) >> d;
            t->q_drop = (int8_t)(qmax <= 4 * qmin ? d : -1);
            t->rbits = (int8_t)(mote__bitlen((uint64_t)MOTE__MAX(least, 1)) + 29);
        }

        /* n_extra (below): the bit length of the largest attribute
         * difference, the shades' and the texels' magnitudes or-ed (the
         * shades' gathered as they were taken, in 32 bits) */
        uint64_t dbits = t->shade != MOTE__SHADE_FLAT ? dmag : 0;
        d1[MOTE__A_U] = d2[MOTE__A_U] = d1[MOTE__A_V] = d2[MOTE__A_V] = 0;
        t->level = 0;
        if (rs->tex != MOTE__TEX_NONE) {
#if MOTE_ENABLE_MIPMAPS
            if (rs->mips && !rs->mip_pixel)
                t->level = (uint8_t)mote__mip_level(rs, v, a2, F);
#endif
            const int lv = t->level;
            const int64_t tw = MOTE__MAX(rs->tex_w >> lv, 1), th = MOTE__MAX(rs->tex_h >> lv, 1);
            /* texels in 16.16; whole periods removed so numbers stay small,
             * then as many fraction bits dropped (texel_bits) as keep them
             * below 2^28: the pixel loops address texels with 32-bit ones */
            int64_t T[2][3];
            uint64_t mag = 0;
            for (int a = MOTE__A_U; a <= MOTE__A_V; a++) {
                int64_t *const Ta = T[a - MOTE__A_U];
                for (int i = 0; i < 3; i++)   /* in the level's texels */
                    Ta[i] = mote__floor_shift_k(v[i]->texel[a - MOTE__A_U], lv);
                mote_wrap wrap = a == MOTE__A_U ? rs->wrap_u : rs->wrap_v;
                int64_t base = 0;
                /* texture layers that whole periods of this texture would move
                 * (mote__layers_select): the coordinates stay whole */
#if MOTE__LAYERS_ENABLED
                const bool whole = rs->texel_absolute;
#else
                const bool whole = false;
#endif
#if MOTE_SHORTCUTS
                if (rs->pow2_repeat && !whole)  /* both axes repeat a power of two: a mask */
                    base = (int64_t)((uint64_t)MOTE__MIN(Ta[0], MOTE__MIN(Ta[1], Ta[2]))
                                     & ~(((uint64_t)(a == MOTE__A_U ? tw : th) << 16) - 1));
                else
#endif
                if (wrap != MOTE_WRAP_CLAMP && !whole) {
                    /* a mirror's period is two sizes: a shift, not a
                     * product (a libgcc call on 32-bit cores) */
                    const int64_t period = (int64_t)(uint64_t)(a == MOTE__A_U ? tw : th)
                                           << (16 + (wrap == MOTE_WRAP_MIRROR));
                    base = mote__floor_multiple(MOTE__MIN(Ta[0], MOTE__MIN(Ta[1], Ta[2])), period);
                }
                for (int i = 0; i < 3; i++) {
                    Ta[i] -= base;
                    mag |= (uint64_t)mote__abs64(Ta[i]);
                }
            }
            const int drop = MOTE__MIN(MOTE__MAX(mote__bitlen(mag) - 28, 0), MOTE__TEXEL_BITS);
            t->texel_bits = (int8_t)(MOTE__TEXEL_BITS - drop);
            for (int a = MOTE__A_U; a <= MOTE__A_V; a++) {
                const int64_t *const Ta = T[a - MOTE__A_U];
                const int64_t t0 = mote__floor_shift_k(Ta[0], drop);
                t->a0[a] = t0;
                d1[a] = mote__floor_shift_k(Ta[1], drop) - t0;
                d2[a] = mote__floor_shift_k(Ta[2], drop) - t0;
                dbits |= (uint64_t)mote__abs64(d1[a]) | (uint64_t)mote__abs64(d2[a]);
            }
        }
        t->n_extra = (int8_t)MOTE__MAX(mote__bitlen(dbits) - 20, 0);
        /* Numerator planes: A = a0 + (d1 P1 + d2 P2) / Q. With
         * N = (d1 P1 + d2 P2) / 2^(shift + 10) as an integer plane (so a
         * pixel gets the same value whatever row or region reaches it; its
         * floored steps drift under 2 units a pixel, 2^11 / (Q >> shift) of
         * an attribute unit) and r = 2^K / (Q >> shift),
         * A = a0 + (N >> 10) r / 2^(K - 20), which the pixel loops take to
         * 32 bits (see mote__tri). Only the planes the pixel loops read
         * are made (mote__has_plane); the rest are 0. */
        const int ps = shift + 10;
#if MOTE__SETUP_FAST
        /* 2^(64-ps) for mote__mul_shift2, written so: from 1 << (64 - ps)
         * GCC made its multiply a shift again */
        const uint64_t pm = ((uint64_t)1 << 63) >> (ps - 1);
        /* The steps in 64 bits where they fit: E's steps are multiples of
         * 2^F, so a step of P1 is w 2^(F-k), w being the edge's x or y
         * difference times q1, and floor(d1 w 2^(F-k) / 2^ps) =
         * floor(d1 w / 2^(ps-F+k)): exact unless d1 w overflows, which the
         * multiply reports (0.04% of the grid's planes, 5% of Suzanne's at
         * 1080p). The value at the origin is no such multiple: 128 bits. */
        const int ws = F - k, cs = ps - ws;
        const int64_t w1x = mote__sar64(p1[1], ws), w1y = mote__sar64(p1[2], ws);
        const int64_t w2x = mote__sar64(p2[1], ws), w2y = mote__sar64(p2[2], ws);
#pragma GCC unroll 8              /* as GCC unrolled the loop before it grew */
#endif
        for (int a = 0; a < MOTE__ATTRS; a++) {
            int64_t *n = t->n[a];
            if (!mote__has_plane(a, (mote__shade_kind)t->shade, rs->tex != MOTE__TEX_NONE)) {
                n[0] = n[1] = n[2] = 0;
                continue;
            }
#if MOTE__SETUP_FAST
            n[0] = mote__mul_shift2(d1[a], p1[0], d2[a], p2[0], ps, pm);
            int64_t x1s, x2s, y1s, y2s;
            if (!__builtin_mul_overflow(d1[a], w1x, &x1s) && !__builtin_mul_overflow(d2[a], w2x, &x2s)
                && !__builtin_mul_overflow(d1[a], w1y, &y1s) && !__builtin_mul_overflow(d2[a], w2y, &y2s)) {
                n[1] = mote__sar64(x1s, cs) + mote__sar64(x2s, cs);
                n[2] = mote__sar64(y1s, cs) + mote__sar64(y2s, cs);
                continue;
            }
            for (int j = 1; j < 3; j++)
                n[j] = mote__mul_shift2(d1[a], p1[j], d2[a], p2[j], ps, pm);
#else
            for (int j = 0; j < 3; j++)
                n[j] = (int64_t)((uint64_t)mote__mul_shift(d1[a], p1[j], ps)
                                 + (uint64_t)mote__mul_shift(d2[a], p2[j], ps));
#endif
        }
    }

    t->z = t->zdx = t->zdy = 0;
    if (rs->depth_test || rs->depth_write) {
        const int64_t d[3] = {v[0]->z, v[1]->z, v[2]->z};
        /* D(x, y) = D0 + (E1 (D1 - D0) + E2 (D2 - D0)) / (2 area); E1, E2 at
         * the origin are below 2^32 (both vanish at vertex 0), steps below
         * 2^32, depth differences below 2^25: all products fit */
        int64_t dz1 = d[1] - d[0], dz2 = d[2] - d[0];
        int64_t zp[3];
        bool huge = false;
        /* cores without a divide: a2's reciprocal for the three divisions */
        const mote__divisor *dv = NULL;
#if MOTE__DIVIDE_BY_RECIP
        mote__divisor dv_own;
        if (a2 < ((int64_t)1 << 32)) {
            mote__divisor_init(&dv_own, (uint32_t)a2);
            dv = &dv_own;
        }
#endif
#if MOTE__SETUP_FAST
        /* |n| <= lim (2^46 - 1, or (2^28 - 1) d where d < 2^18) keeps
         * n 2^16 in range and the rounded quotient within 2^44: then
         * mote__scaled_div's checks pass, and its value is this one */
        const int64_t lim = a2 < ((int64_t)1 << 18) ? a2 * (((int64_t)1 << 28) - 1) : ((int64_t)1 << 46) - 1;
#endif
        for (int j = 0; j < 3; j++) {
            int64_t n = ed[3 * j + 1] * dz1 + ed[3 * j + 2] * dz2;
#if MOTE__SETUP_FAST
            if ((uint64_t)(n + lim) <= 2 * (uint64_t)lim) {
                zp[j] = mote__depth_div(n * 65536 + (a2 >> 1), a2, dv);
                continue;
            }
#endif
            zp[j] = mote__scaled_div(n, a2, dv, &huge);
        }
        /* such a sliver has no usable plane (a clamped gradient would be
         * wrong by far some pixels along it): it takes vertex 0's depth,
         * which at least lies within its vertices' range */
        if (huge)
            zp[0] = zp[1] = zp[2] = 0;
        t->z = d[0] * 65536 + zp[0] + rs->depth_half;
        t->zdx = zp[1];
        t->zdy = zp[2];
    }
    return MOTE__SETUP_DRAWN;
}

mote__setup_result mote__setup(mote__tri *t, const mote__raster_state *rs, const int32_t X[3],
                 const int32_t Y[3], int64_t area2, const mote__svert *const v[3], int F,
                 int width, int height)
{
#if MOTE__SETUP_FAST
    if (F == 8)
        return mote__setup_f(t, rs, X, Y, area2, v, 8, width, height);
#endif
    return mote__setup_f(t, rs, X, Y, area2, v, F, width, height);
}
