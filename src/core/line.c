/*
 * line.c - points and Bresenham lines.
 *
 * A line from (x0, y0) to (x1, y1) (pixel indices) lights, for each step
 * along its major axis, the pixel nearest to the ideal line, ties rounded
 * toward +infinity on the minor axis - the set Bresenham's algorithm draws.
 * Each pixel is computed from the endpoints, not from the previous one, so
 * the line can be clipped to any region (viewport, band, tile) and still
 * light exactly the same pixels; nothing outside the region is written.
 */
#include "internal.h"

#if MOTE_ENABLE_LINES

/* Endpoints come from snapped vertices, |coordinate| < 2^(MOTE_GUARD_BITS
 * + 1), so a step along the major axis times the minor extent is under
 * 2^(2 MOTE_GUARD_BITS + 4): 32-bit with the default guard band (no 64-bit
 * division on a small core), 64-bit past it. */
#if MOTE_GUARD_BITS <= 13
typedef int32_t mote__line_int;
#else
typedef int64_t mote__line_int;
#endif

void mote__draw_pixel(const mote__target *tg, mote__rect r, int x, int y, mote_rgba color)
{
    if (x < r.x0 || x >= r.x1 || y < r.y0 || y >= r.y1)
        return;
    uint8_t *row = tg->color + (size_t)(y - tg->y0) * (size_t)tg->stride;
    mote__write_rgb(row, x, tg->format, color.r, color.g, color.b);
    tg->counts->tested++;
    tg->counts->written++;
}

void mote__draw_line(const mote__target *tg, mote__rect r, int x0, int y0, int x1, int y1,
                     mote_rgba color)
{
    /* One walk along the major axis a, the minor axis b following it:
     * b = b0 + round(n / d) with n = (a - a0) * db * sign(da), d = |da|
     * (d = 1 for a single point, where n is 0). */
    mote__line_int dx = (mote__line_int)x1 - x0, dy = (mote__line_int)y1 - y0;
    mote__line_int adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    bool ymajor = ady > adx;
    mote__line_int a0 = ymajor ? y0 : x0, a1 = ymajor ? y1 : x1, b0 = ymajor ? x0 : y0;
    mote__line_int da = ymajor ? dy : dx, db = ymajor ? dx : dy;
    mote__line_int d = ymajor ? ady : adx;
    if (da < 0)
        db = -db;
    if (d == 0)
        d = 1;
    mote__line_int lo = MOTE__MIN(a0, a1), hi = MOTE__MAX(a0, a1);
    lo = MOTE__MAX(lo, ymajor ? r.y0 : r.x0);
    hi = MOTE__MIN(hi, (ymajor ? r.y1 : r.x1) - 1);
    for (mote__line_int a = lo; a <= hi; a++) {
        /* round half up: floor division, then up when 2 * rest >= d */
        mote__line_int n = (a - a0) * db, q = n / d, rest = n - q * d;
        if (rest < 0) {
            q--;
            rest += d;
        }
        mote__line_int b = b0 + q + (2 * rest >= d);
        if (ymajor)
            mote__draw_pixel(tg, r, (int)b, (int)a, color);
        else
            mote__draw_pixel(tg, r, (int)a, (int)b, color);
    }
}

#endif /* MOTE_ENABLE_LINES */
