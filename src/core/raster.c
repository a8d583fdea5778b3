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

static int64_t mote__floor_div(int64_t a, int64_t b)
{
    int64_t q = a / b;
    if ((a % b != 0) && ((a < 0) != (b < 0)))
        q--;
    return q;
}

static void mote__edge_init(mote__edge *e, int32_t xa, int32_t ya, int32_t xb, int32_t yb,
                            int y, int F)
{
    const int64_t one = (int64_t)1 << F, half = one >> 1;
    int64_t dy = (int64_t)yb - ya, dx = (int64_t)xb - xa;
    int64_t Y = (int64_t)y * one + half;
    int64_t num = (int64_t)xa * dy + (Y - ya) * dx - half * dy;
    e->den = dy * one;
    /* x = ceil(num / den) */
    e->x = -mote__floor_div(-num, e->den);
    e->err = e->x * e->den - num;
    int64_t step = dx * one;
    e->qstep = mote__floor_div(step, e->den);
    e->rstep = step - e->qstep * e->den;
}

static int mote__first_row(int32_t Yv, int F)
{
    /* smallest y with y * 2^F + 2^(F-1) >= Yv: ceil((Yv - 2^(F-1)) / 2^F) */
    return (int)mote__floor_shift64((int64_t)Yv - ((int64_t)1 << (F - 1)) + ((int64_t)1 << F) - 1, F);
}

bool mote__walk_begin(mote__walk *w, const mote__tri *t, mote__rect r, int F)
{
    /* the vertices sorted by y (then x) and the long edge's side: from setup */
    const int o = t->order, a = o & 3, b = (o >> 2) & 3, c = (o >> 4) & 3;
    const int32_t xa = t->X[a], ya = t->Y[a], xb = t->X[b], yb = t->Y[b], xc = t->X[c], yc = t->Y[c];
    w->long_left = (o >> 6) & 1;

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
    mote__edge_init(&w->longe, xa, ya, xc, yc, w->y, F);
    if (w->y < w->ymid) {
        mote__edge_init(&w->shorte, xa, ya, xb, yb, w->y, F);
    } else {
        mote__edge_init(&w->shorte, xb, yb, xc, yc, w->y, F);
        w->ymid = -1;             /* rows are >= 0: no switch to come */
    }
    return true;
}

void mote__walk_switch(mote__walk *w)
{
    mote__edge_init(&w->shorte, w->xb, w->yb, w->xc, w->yc, w->y, w->subpixel_bits);
}

void mote__raster_tri(const mote__tri *t, const mote__target *tg, mote__rect r, int F)
{
    t->rs->fill[t->shade](t, tg, r, F);
}
