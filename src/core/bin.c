/*
 * bin.c - binned mode: set-up triangles are stored in the caller's arena and
 * listed per screen tile; mote_end (or a full arena) rasterises the tiles,
 * each tile on one thread, its triangles in submission order. A pixel
 * belongs to exactly one tile, and every triangle is rasterised the same
 * way whatever region it is cut to, so the bytes do not depend on the
 * thread count, the tile size or how often the arena filled up.
 *
 * Arena layout: [tiles][raster states, triangles, list blocks ->   <- per-draw scratch]
 */
#include "internal.h"

#define MOTE__BLOCK 30

typedef struct mote__tile {
    uint32_t head, tail;          /* arena offsets of list blocks; 0 = none */
    mote__counts counts;
} mote__tile;

typedef struct mote__block {
    uint32_t next, count;
    uint32_t tri[MOTE__BLOCK];    /* arena offsets of mote__tri */
} mote__block;

static size_t mote__align(size_t n) { return (n + 7u) & ~(size_t)7u; }

size_t mote_arena_bytes_per_triangle(void)
{
    /* the triangle, plus list space for a typical few tiles */
    return mote__align(sizeof(mote__tri)) + 4 * sizeof(uint32_t) + sizeof(mote__block) / 4;
}

#if MOTE_ENABLE_BINNING
size_t mote__bin_table_bytes(const mote_device *dev)
{
    return mote__align((size_t)dev->bin.tiles_x * (size_t)dev->bin.tiles_y * sizeof(mote__tile));
}

void mote__bin_reset(mote_device *dev)
{
    mote__bin *b = &dev->bin;
    b->tiles = b->base;
    b->used = b->batch_start = mote__bin_table_bytes(dev);
    b->top = b->size;
    b->triangles = 0;
    memset(b->base, 0, b->batch_start);
}

/* The tile jobs read the triangles on other cores, which leaves the
 * arena's lines shared between caches; the next frame's setup writes the
 * same bytes and then waited for each line's ownership one store at a
 * time. With 2 threads on a 2-core VM where a line takes 200-650 ns to
 * move between cores, the serial draw phase took 145 against 107 us
 * (Suzanne at 1080p; 10x10 Suzannes: 12-13 against 10 ms). A memset of
 * those bytes, whose stores overlap, takes the lines back for 3 us (0.3
 * ms), and the draw phase is as fast as on one thread again. */
void mote__bin_begin(mote_device *dev)
{
    mote__bin *b = &dev->bin;
    size_t shared = b->shared;
    mote__bin_reset(dev);
    if (shared > b->batch_start)
        memset(b->base + b->batch_start, 0, shared - b->batch_start);
    b->shared = 0;
}

void *mote__bin_alloc(mote_device *dev, size_t bytes)
{
    mote__bin *b = &dev->bin;
    bytes = mote__align(bytes);
    if (bytes > b->top - b->used)
        return NULL;
    void *p = b->base + b->used;
    b->used += bytes;
    return p;
}

void *mote__bin_top_alloc(mote_device *dev, size_t bytes)
{
    mote__bin *b = &dev->bin;
    bytes = mote__align(bytes);
    /* leave the bottom at least half of what is free, for triangles */
    if (bytes > (b->top - b->used) / 2)
        return NULL;
    b->top -= bytes;
    return b->base + b->top;
}

void mote__bin_top_release(mote_device *dev, size_t bytes)
{
    dev->bin.top += mote__align(bytes);
}

bool mote__bin_triangle(mote_device *dev, const mote__tri *t)
{
    mote__bin *b = &dev->bin;
    int s = b->tile_shift;
    int tx0 = t->xmin >> s, tx1 = t->xmax >> s, ty0 = t->ymin >> s, ty1 = t->ymax >> s;
    size_t ntiles = (size_t)(tx1 - tx0 + 1) * (size_t)(ty1 - ty0 + 1);
    /* worst case first, so a triangle is never half binned */
    size_t need = mote__align(sizeof *t) + ntiles * mote__align(sizeof(mote__block));
    if (need > b->top - b->used)
        return false;
    mote__tri *copy = (mote__tri *)mote__bin_alloc(dev, sizeof *t);
    *copy = *t;
    uint32_t off = (uint32_t)((unsigned char *)copy - b->base);
    mote__tile *tiles = (mote__tile *)b->tiles;
    for (int ty = ty0; ty <= ty1; ty++) {
        for (int tx = tx0; tx <= tx1; tx++) {
            mote__tile *tile = &tiles[ty * b->tiles_x + tx];
            mote__block *blk = tile->tail ? (mote__block *)(void *)(b->base + tile->tail) : NULL;
            if (!blk || blk->count == MOTE__BLOCK) {
                mote__block *nb = (mote__block *)mote__bin_alloc(dev, sizeof *nb);
                nb->next = 0;
                nb->count = 0;
                uint32_t noff = (uint32_t)((unsigned char *)nb - b->base);
                if (blk)
                    blk->next = noff;
                else
                    tile->head = noff;
                tile->tail = noff;
                blk = nb;
            }
            blk->tri[blk->count++] = off;
        }
    }
    b->triangles++;
    return true;
}

static void mote__raster_tile(void *arg, int index)
{
    mote_device *dev = (mote_device *)arg;
    mote__bin *b = &dev->bin;
    mote__tile *tile = &((mote__tile *)b->tiles)[index];
    if (!tile->head)
        return;
    int ts = 1 << b->tile_shift;
    int tx = index % b->tiles_x, ty = index / b->tiles_x;
    mote__rect r = {tx * ts, ty * ts, MOTE__MIN((tx + 1) * ts, dev->desc.width),
                    MOTE__MIN((ty + 1) * ts, dev->desc.height)};
    mote__target tg;
    mote__counts count = {0, 0};
    mote__full_target(dev, &tg, &count);
    for (uint32_t off = tile->head; off;) {
        const mote__block *blk = (const mote__block *)(const void *)(b->base + off);
        for (uint32_t i = 0; i < blk->count; i++)
            mote__raster_tri((const mote__tri *)(const void *)(b->base + blk->tri[i]), &tg, r,
                             dev->desc.subpixel_bits);
        off = blk->next;
    }
    tile->counts = count;
}

void mote__bin_flush(mote_device *dev)
{
    mote__bin *b = &dev->bin;
    int n = b->tiles_x * b->tiles_y;
    if (b->triangles > 0) {
        if (dev->desc.parallel_for) {
            dev->desc.parallel_for(dev->desc.parallel_user, n, mote__raster_tile, dev);
            b->shared = MOTE__MAX(b->shared, b->used);
        } else {
            for (int i = 0; i < n; i++)
                mote__raster_tile(dev, i);
        }
        const mote__tile *tiles = (const mote__tile *)b->tiles;
        for (int i = 0; i < n; i++) {
            if (tiles[i].head) {
                dev->stats.tiles_drawn++;
                mote__add_counts(dev, &tiles[i].counts);
            } else {
                dev->stats.tiles_empty++;
            }
        }
    }
    size_t top = b->top;
    mote__bin_reset(dev);
    b->top = top;                 /* a draw in progress keeps its scratch */
}

#endif /* MOTE_ENABLE_BINNING */
