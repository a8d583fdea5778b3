/*
 * raster.c - exact scanline edge walking.
 *
 * For the row of pixel centres at Y = y * 2^F + 2^(F-1), an edge from
 * (xa, ya) to (xb, yb) with yb > ya crosses at X = xa + (Y - ya)(xb - xa)/dy.
 * A pixel x is inside on the left edge when its centre is >= X (left edges
 * own their pixels) and on the right edge when its centre is < X; both give
 * the same first-pixel formula ceil((N - 2^(F-1) dy) / (dy 2^F)) with
 * N = xa dy + (Y - ya) dx. Rows are those with ya <= Y < yc, which is the
 * top-left rule for horizontal edges. The walker steps that ceiling exactly
 * (quotient and remainder), and starts at any row with one division, so a
 * region that begins halfway down a triangle draws exactly the same pixels.
 * The row loop itself lives in span.c's fill functions (mote__walk_row in
 * internal.h), so that each specialised fill walks its own rows.
 */
#include "internal.h"

/* Speed builds compile the walk's set-up twice: for the default 8
 * sub-pixel bits, whose shifts are then constants (a tenth of a small
 * triangle's walk set-up was variable shifts and their count register),
 * and for any other. Size builds keep one copy. */
#if MOTE_SHORTCUTS && defined(__GNUC__)
#define MOTE__WALK_F8 1
#define MOTE__WALK_INLINE static inline __attribute__((always_inline))
#else
#define MOTE__WALK_F8 0
#define MOTE__WALK_INLINE static inline
#endif

MOTE__WALK_INLINE void mote__edge_init(mote__edge *e, int32_t xa, int32_t ya, int32_t xb, int32_t yb,
                            int y, int F)
{
    const int64_t one = (int64_t)1 << F, half = one >> 1;
    const int32_t dy = yb - ya, dx = xb - xa;   /* dy > 0; both below 2^(MOTE_GUARD_BITS + 10) */
    /* an edge shorter than 2^(30-F) rows, on a 32-bit core, shifts in 32
     * bits (a 64-bit shift by F is a libgcc call there) */
    const int32_t lim = (int32_t)1 << (30 - F);
    const bool short32 = MOTE__CORE32 && dy < lim;
    const int64_t den = short32 ? (int32_t)((uint32_t)dy << F) : (int64_t)dy << F;
    /* u in 32 bits: y is a row of the screen, ya within the guard band */
    const int64_t u = (int32_t)(((int32_t)y << F) + (int32_t)half - ya);
    /* the step dx 2^F / den: floor(dx / dy) = qs, remainder rs, in 32 bits */
    int32_t qs = dx / dy, rs = dx - qs * dy, neg = rs < 0;
    qs -= neg;
    rs += dy & -neg;
    e->den = den;
    e->qstep = qs;
    e->rstep = short32 ? (int32_t)((uint32_t)rs << F) : (int64_t)rs << F;   /* 0 <= rs < dy */
    /* x = ceil(num / den), num = (xa - 2^(F-1)) dy + u dx, err = x den - num.
     * With A = xa - 2^(F-1) + u qs = Aq 2^F + Ar (0 <= Ar < 2^F),
     * num = Aq den + n2, n2 = Ar dy + u rs >= 0. At the edge's first row
     * (u < 2^F: every edge of a region that holds the top of the triangle)
     * n2 < 2 den, and x needs no division; unless the edge is longer than
     * 2^(22-F) pixels it needs no 64-bit number either: |u qs| < 2^F
     * 2^(30-F), |xa| < 2^22, and Ar dy, u rs, den < 2^30 (MOTE__CORE32:
     * a 64-bit host ran its extra tests for nothing). */
    if (short32 && u < one && dx < lim && dx > -lim) {
        const int32_t a32 = xa - (int32_t)half + (int32_t)u * qs;
        const int32_t n32 = (a32 & ((int32_t)one - 1)) * dy + (int32_t)u * rs, c32 = (n32 > 0) + (n32 > (int32_t)den);
        e->x = mote__floor_shift32(a32, F) + c32;
        e->err = c32 * (int32_t)den - n32;
        return;
    }
    int64_t A = (int64_t)xa - half + u * qs, Aq = mote__floor_shift64(A, F);
    int64_t n2 = (int64_t)(int32_t)(A & (one - 1)) * dy + u * rs;   /* A - Aq 2^F */
    /* a region starting below the edge's first row (a band's) divides;
     * 32-bit cores without a libgcc 64-bit division (recip.c) */
    int64_t c = u < one          ? (n2 > 0) + (n2 > den)
              : MOTE__CORE32 ? (int64_t)mote__udiv64((uint64_t)(n2 + den - 1), (uint64_t)den)
                             : (n2 + den - 1) / den;
    e->x = Aq + c;
    e->err = c * den - n2;
}

static int mote__first_row(int32_t Yv, int F)
{
    /* smallest y with y * 2^F + 2^(F-1) >= Yv: ceil((Yv - 2^(F-1)) / 2^F) */
    return mote__floor_shift32(Yv + (1 << (F - 1)) - 1, F);   /* no overflow: |Yv| < 2^24 */
}

#if MOTE__WALK_F8
MOTE__WALK_INLINE bool mote__walk_begin_f(mote__walk *w, const mote__tri *t, mote__rect r, int F)
#else
bool mote__walk_begin(mote__walk *w, const mote__tri *t, mote__rect r, int F)
#endif
{
    /* the vertices sorted by y (then x) and the long edge's side: from setup */
    const int o = t->order, a = o & 3, b = (o >> 2) & 3, c = (o >> 4) & 3;
    const int32_t xa = t->X[a], ya = t->Y[a], xb = t->X[b], yb = t->Y[b], xc = t->X[c], yc = t->Y[c];
    const bool long_left = (o >> 6) & 1;
    w->short_left = !long_left;

    w->rx0 = MOTE__MAX(r.x0, t->xmin);
    w->rx1 = MOTE__MIN(r.x1, t->xmax + 1);
    int ry0 = MOTE__MAX(r.y0, t->ymin), ry1 = MOTE__MIN(r.y1, t->ymax + 1);
    if (w->rx0 >= w->rx1 || ry0 >= ry1)
        return false;
    w->y = MOTE__MAX(mote__first_row(ya, F), ry0);
    w->ymid = mote__first_row(yb, F);
    w->yend = MOTE__MIN(mote__first_row(yc, F), ry1);
    if (w->y >= w->yend)
        return false;
    w->xb = xb;
    w->yb = yb;
    w->xc = xc;
    w->yc = yc;
    w->subpixel_bits = F;
    mote__edge_init(long_left ? &w->left : &w->right, xa, ya, xc, yc, w->y, F);
    /* the short edge: a-b, or b-c when the region starts at or below b
     * (then no switch is to come: rows are >= 0); chosen without a branch */
    int upper = w->y < w->ymid, s0 = b ^ ((a ^ b) & -upper), s1 = c ^ ((b ^ c) & -upper);
    mote__edge_init(long_left ? &w->right : &w->left, t->X[s0], t->Y[s0], t->X[s1], t->Y[s1], w->y, F);
    w->ymid |= upper - 1;
    return true;
}

#if MOTE__WALK_F8
bool mote__walk_begin(mote__walk *w, const mote__tri *t, mote__rect r, int F)
{
    if (F == 8)
        return mote__walk_begin_f(w, t, r, 8);
    return mote__walk_begin_f(w, t, r, F);
}
#endif

void mote__walk_switch(mote__walk *w)
{
#if MOTE__WALK_F8
    if (w->subpixel_bits == 8) {
        mote__edge_init(w->short_left ? &w->left : &w->right, w->xb, w->yb, w->xc, w->yc, w->y, 8);
        return;
    }
#endif
    mote__edge_init(w->short_left ? &w->left : &w->right, w->xb, w->yb, w->xc, w->yc, w->y, w->subpixel_bits);
}
