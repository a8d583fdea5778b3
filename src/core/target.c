/*
 * target.c - where pixels go: the full-frame target of a device, pixel
 * counts, and the clear of a rectangle, a stripe or the whole frame (or,
 * with clear_drawn_tiles_only, of the tiles drawn into since).
 */
#include "internal.h"

void mote__add_counts(mote_device *dev, const mote__counts *counts)
{
    dev->stats.pixels_tested += counts->tested;
    dev->stats.pixels_written += counts->written;
}

void mote__full_target(const mote_device *dev, mote__target *tg, mote__counts *counts)
{
    tg->color = (uint8_t *)dev->desc.color;
    tg->stride = dev->desc.color_stride;
    tg->depth = dev->desc.depth;
    tg->width = dev->desc.width;
    tg->y0 = 0;
    tg->format = dev->desc.color_format;
    tg->depth_format = dev->desc.depth_format;
    tg->counts = counts;
}

/* Fills rows x row_bytes at p (rows stride bytes apart) with copies of the
 * element of elem_bytes already at p; rows that touch are one block. Each
 * memcpy doubles what is filled, up to MOTE__FILL_BLOCK bytes, and then
 * copies that much from the start, which stays in the L1 cache: nearly a
 * memset's speed, where doubling over the whole block reads back as much
 * as it writes (docs/performance.md). */
#define MOTE__FILL_BLOCK 16384u

static void mote__fill_rows(uint8_t *p, size_t elem_bytes, size_t row_bytes, size_t stride, int rows)
{
    size_t total = stride == row_bytes ? row_bytes * (size_t)rows : row_bytes;
    for (size_t done = elem_bytes; done < total;) {
        size_t n = MOTE__MIN(MOTE__MIN(done, (size_t)MOTE__FILL_BLOCK), total - done);
        memcpy(p + done, p, n);
        done += n;
    }
    if (stride != row_bytes)
        for (int y = 1; y < rows; y++)
            memcpy(p + (size_t)y * stride, p, row_bytes);
}

void mote__clear_rect(const mote_device *dev, const mote__target *tg, mote__rect r)
{
    const mote_device_desc *d = &dev->desc;
    int w = r.x1 - r.x0, rows = r.y1 - r.y0;
    if (w <= 0 || rows <= 0)
        return;
    if (!dev->frame.keep_color) {
        size_t bpp = (size_t)mote__format_bytes(d->color_format);
        uint8_t *row0 = tg->color + (size_t)(r.y0 - tg->y0) * (size_t)tg->stride;
        mote__write_rgb(row0, r.x0, d->color_format, d->clear_color.r, d->clear_color.g, d->clear_color.b);
        if (d->color_format == MOTE_FORMAT_RGBA8888)
            row0[4 * r.x0 + 3] = d->clear_color.a;
        mote__fill_rows(row0 + (size_t)r.x0 * bpp, bpp, (size_t)w * bpp, (size_t)tg->stride, rows);
    }
    if (!dev->frame.keep_depth && d->depth_format != MOTE_DEPTH_FORMAT_NONE) {
        /* clear_depth is in (0, 1]: fv is at most 2^24, which converts
         * exactly; the clamp in integers costs a soft-float core no call */
        float fv = d->clear_depth * (float)MOTE__DEPTH_MAX + 0.5f;
        uint32_t v = (uint32_t)fv;
        v = v > MOTE__DEPTH_MAX ? MOTE__DEPTH_MAX : v;
        size_t off = (size_t)(r.y0 - tg->y0) * (size_t)d->width + (size_t)r.x0;
        size_t bytes = (size_t)mote__depth_format_bytes(d->depth_format);
        mote__depth_store(d->depth, off, d->depth_format, v);
        uint8_t *p = (uint8_t *)d->depth + off * bytes;
        mote__fill_rows(p, bytes, (size_t)w * bytes, (size_t)d->width * bytes, rows);
    }
}

void mote__clear_stripe(const mote_device *dev, int index)
{
    int h = dev->desc.height;
    mote__target tg;
    mote__counts count = {0, 0};
    mote__full_target(dev, &tg, &count);
    mote__rect r = {0, h * index / MOTE__CLEAR_STRIPES, dev->desc.width, h * (index + 1) / MOTE__CLEAR_STRIPES};
    const unsigned char *drawn = dev->bin.drawn_before;
    if (!MOTE_ENABLE_BINNING || !drawn || !mote__binned(dev)) {
        mote__clear_rect(dev, &tg, r);
        return;
    }
    /* only the tiles drawn into since the last clear: runs of them per
     * row of tiles (the stripe's rows need not start a tile row) */
    const int s = dev->bin.tile_shift, tiles_x = dev->bin.tiles_x;
    for (int y = r.y0; y < r.y1;) {
        const int ty = y >> s, y1 = MOTE__MIN(r.y1, (ty + 1) << s);
        const unsigned char *row = drawn + (size_t)ty * (size_t)tiles_x;
        for (int tx = 0; tx < tiles_x;) {
            if (!row[tx]) {
                tx++;
                continue;
            }
            int t0 = tx;
            while (tx < tiles_x && row[tx])
                tx++;
            mote__rect run = {t0 << s, y, MOTE__MIN(r.x1, tx << s), y1};
            mote__clear_rect(dev, &tg, run);
        }
        y = y1;
    }
}

static void mote__clear_task(void *arg, int index)
{
    mote__clear_stripe((const mote_device *)arg, index);
}

void mote__clear_frame(mote_device *dev)
{
    dev->clear_pending = false;
    if (dev->desc.parallel_for)
        dev->desc.parallel_for(dev->desc.parallel_user, MOTE__CLEAR_STRIPES, mote__clear_task, dev);
    else
        for (int i = 0; i < MOTE__CLEAR_STRIPES; i++)
            mote__clear_stripe(dev, i);
}

