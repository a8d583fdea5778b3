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

void mote__draw_pixel(const mote__target *tg, mote__rect r, int x, int y, mote_rgba color)
{
    if (x < r.x0 || x >= r.x1 || y < r.y0 || y >= r.y1)
        return;
    uint8_t *row = tg->color + (size_t)(y - tg->y0) * (size_t)tg->stride;
    mote__write_rgb(row, x, tg->format, color.r, color.g, color.b);
    tg->counts->tested++;
    tg->counts->written++;
}

/* round(n / d) for d > 0, halves toward +infinity */
static int64_t mote__round_div(int64_t n, int64_t d)
{
    int64_t a = 2 * n + d, b = 2 * d;
    int64_t q = a / b;
    if ((a % b != 0) && (a < 0))
        q--;
    return q;
}

void mote__draw_line(const mote__target *tg, mote__rect r, int x0, int y0, int x1, int y1,
                     mote_rgba color)
{
    int64_t dx = (int64_t)x1 - x0, dy = (int64_t)y1 - y0;
    int64_t adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    if (adx == 0 && ady == 0) {
        mote__draw_pixel(tg, r, x0, y0, color);
        return;
    }
    if (adx >= ady) {
        /* x-major: walk x over the part of the line inside the region */
        int64_t lo = MOTE__MIN(x0, x1), hi = MOTE__MAX(x0, x1);
        lo = MOTE__MAX(lo, r.x0);
        hi = MOTE__MIN(hi, r.x1 - 1);
        for (int64_t x = lo; x <= hi; x++) {
            int64_t y = y0 + (dx > 0 ? mote__round_div((x - x0) * dy, dx) : mote__round_div((x0 - x) * dy, -dx));
            mote__draw_pixel(tg, r, (int)x, (int)y, color);
        }
    } else {
        int64_t lo = MOTE__MIN(y0, y1), hi = MOTE__MAX(y0, y1);
        lo = MOTE__MAX(lo, r.y0);
        hi = MOTE__MIN(hi, r.y1 - 1);
        for (int64_t y = lo; y <= hi; y++) {
            int64_t x = x0 + (dy > 0 ? mote__round_div((y - y0) * dx, dy) : mote__round_div((y0 - y) * dx, -dy));
            mote__draw_pixel(tg, r, (int)x, (int)y, color);
        }
    }
}
