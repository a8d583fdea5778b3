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
#include "plane.h"

#define MOTE__BLOCK 30

typedef struct mote__tile {
    uint32_t head, tail;          /* arena offsets of list blocks; 0 = none */
    mote__counts counts;
    uint32_t behind;              /* triangles skipped as behind its drawn depth */
} mote__tile;

typedef struct mote__block {
    uint32_t next, count;
    uint32_t tri[MOTE__BLOCK];    /* arena offsets of mote__tri */
} mote__block;

static size_t mote__align(size_t n) { return (n + 7u) & ~(size_t)7u; }

size_t mote_arena_bytes_per_triangle(void)
{
    /* the triangle, plus list space for a typical few tiles (one with
     * an additive colour takes its three more planes: mote.h says so) */
    return mote__align(MOTE__TRI_BYTES(MOTE__A_B + 1)) + 4 * sizeof(uint32_t) + sizeof(mote__block) / 4;
}

#if MOTE_ENABLE_BINNING
size_t mote__bin_table_bytes(const mote_device *dev)
{
    return mote__align((size_t)dev->bin.tiles_x * (size_t)dev->bin.tiles_y * sizeof(mote__tile));
}

static void mote__bin_reset(mote_device *dev)
{
    mote__bin *b = &dev->bin;
    b->tiles = b->base;
    b->used = b->batch_start = mote__bin_table_bytes(dev);
    b->top = b->size;
    b->triangles = 0;
    b->groups_linked = false;
    memset(b->base, 0, b->batch_start);
}

/* The tile jobs read the triangles on other cores, which leaves the
 * arena's lines shared between caches; the next frame's setup writes the
 * same bytes and would wait for each line's ownership one store at a
 * time. A memset of those bytes, whose stores overlap, takes the lines
 * back at once (docs/performance.md). */
void mote__bin_begin(mote_device *dev)
{
    mote__bin *b = &dev->bin;
    if (b->drawn_now) {
        /* clear_drawn_tiles_only: this frame's clear covers the tiles drawn
         * into since the last one (all that is not clear). A frame keeping
         * a buffer leaves it unknown: the next clear is a full one. */
        size_t n = (size_t)b->tiles_x * (size_t)b->tiles_y;
        unsigned char *before = b->drawn_now;
        b->drawn_now = b->drawn_before;
        b->drawn_before = before;
        memset(b->drawn_now, dev->frame.keep_color || dev->frame.keep_depth, n);
        for (size_t i = 0; i < n; i++)
            dev->stats.tiles_clear_skipped += !before[i];
    }
    size_t shared = b->shared;
    mote__bin_reset(dev);
    if (shared > b->batch_start)
        memset(b->base + b->batch_start, 0, shared - b->batch_start);
    b->shared = 0;
}

void mote__bin_mark_all_drawn(mote_device *dev)
{
    mote__bin *b = &dev->bin;
    if (b->drawn_now)
        memset(b->drawn_now, 1, (size_t)b->tiles_x * (size_t)b->tiles_y);
}

static void *mote__bin_alloc(mote_device *dev, size_t bytes)
{
    mote__bin *b = &dev->bin;
    bytes = mote__align(bytes);
    if (bytes > b->top - b->used)
        return NULL;
    void *p = b->base + b->used;
    b->used += bytes;
    return p;
}

static void *mote__bin_top_alloc(mote_device *dev, size_t bytes)
{
    mote__bin *b = &dev->bin;
    bytes = mote__align(bytes);
    /* leave the bottom at least half of what is free, for triangles */
    if (bytes > (b->top - b->used) / 2)
        return NULL;
    b->top -= bytes;
    return b->base + b->top;
}

static void mote__bin_top_release(mote_device *dev, size_t bytes)
{
    dev->bin.top += mote__align(bytes);
}

static bool mote__bin_triangle(mote_device *dev, const mote__tri *t)
{
    mote__bin *b = &dev->bin;
    int s = b->tile_shift;
    int tx0 = t->xmin >> s, tx1 = t->xmax >> s, ty0 = t->ymin >> s, ty1 = t->ymax >> s;
    size_t ntiles = (size_t)(tx1 - tx0 + 1) * (size_t)(ty1 - ty0 + 1);
    /* worst case first, so a triangle is never half binned */
    const size_t bytes = mote__tri_bytes(t);
    size_t need = mote__align(bytes) + ntiles * mote__align(sizeof(mote__block));
    if (need > b->top - b->used)
        return false;
    mote__tri *copy = (mote__tri *)mote__bin_alloc(dev, bytes);
    /* nothing to copy when it was set up in place (mote__bin_sink_place,
     * in speed builds); else by its size's constant, which a memcpy of a
     * variable size cannot unroll */
    if (!MOTE_SHORTCUTS || copy != t) {
        if (bytes == MOTE__TRI_BYTES(0))
            memcpy(copy, t, MOTE__TRI_BYTES(0));
        else if (bytes == MOTE__TRI_BYTES(MOTE__A_V + 1))
            memcpy(copy, t, MOTE__TRI_BYTES(MOTE__A_V + 1));
        else if (bytes == MOTE__TRI_BYTES(MOTE__A_B + 1))
            memcpy(copy, t, MOTE__TRI_BYTES(MOTE__A_B + 1));
        else
            *copy = *t;
    }
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

/* Asks the cache for a busy tile's colour and depth rows, a prefetch per
 * line, before its triangles: the frame's clear has pushed them out, and
 * a tile of small triangles otherwise waits for each line at the triangle
 * that first touches it. Only on hosts with data caches and a
 * prefetch instruction; on a microcontroller it is nothing. */
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__) || defined(__aarch64__) \
                          || (defined(__ARM_ARCH_PROFILE) && __ARM_ARCH_PROFILE == 'A'))
#define MOTE__PREFETCH 1
#else
#define MOTE__PREFETCH 0
#endif

static void mote__warm_tile(const mote__target *tg, mote__rect r)
{
#if MOTE__PREFETCH
    const size_t cbytes = (size_t)mote__format_bytes(tg->format);
    const size_t dbytes = (size_t)mote__depth_format_bytes(tg->depth_format);
    const size_t cw = cbytes * (size_t)(r.x1 - r.x0), dw = dbytes * (size_t)(r.x1 - r.x0);
    for (int y = r.y0; y < r.y1; y++) {
        const uint8_t *c = tg->color + (size_t)(y - tg->y0) * (size_t)tg->stride + cbytes * (size_t)r.x0;
        for (size_t i = 0; i < cw; i += 64)
            __builtin_prefetch(c + i, 1);
        if (dbytes) {
            const uint8_t *d = (const uint8_t *)tg->depth
                             + dbytes * ((size_t)(y - tg->y0) * (size_t)tg->width + (size_t)r.x0);
            for (size_t i = 0; i < dw; i += 64)
                __builtin_prefetch(d + i, 1);
        }
    }
#else
    (void)tg;
    (void)r;
#endif
}

/* ---- coarse depth per tile ----------------------------------------------
 * A tile keeps an upper bound of the depths in it: the farthest depth of
 * a triangle that covered every pixel centre of the tile and wrote its
 * depth there (after it, no pixel of the tile is farther). A later
 * triangle whose nearest depth in the tile is not nearer than that bound
 * fails the depth test at every pixel, so it is skipped before its edges
 * are walked: the same bytes. The depth of a pixel is clamp(z >> 16) of
 * the triangle's plane (span.c), monotonic in z, so the plane's extremes
 * over a rectangle, at its corners, bound every pixel's depth. Speed
 * builds only (MOTE_SHORTCUTS). */

/* The depth buffer's value for plane value z at pixel (x, y). */
static uint32_t mote__depth_at(const mote__tri *t, int x, int y, bool d16)
{
    int64_t zz = mote__plane_at(mote__plane_at(t->z, t->zdy, y - t->oy), t->zdx, x - t->ox) >> MOTE__DEPTH_FRAC;
    uint32_t depth = zz < 0 ? 0u : zz > (int64_t)MOTE__DEPTH_MAX ? MOTE__DEPTH_MAX : (uint32_t)zz;
    return d16 ? depth >> 8 : depth;
}

/* The smallest (near) or largest depth t can write in r's pixels. */
static uint32_t mote__depth_bound(const mote__tri *t, mote__rect r, bool d16, bool near)
{
    uint32_t b = mote__depth_at(t, r.x0, r.y0, d16);
    const int xs[2] = {r.x0, r.x1 - 1}, ys[2] = {r.y0, r.y1 - 1};
    for (int i = 1; i < 4; i++) {
        uint32_t d = mote__depth_at(t, xs[i & 1], ys[i >> 1], d16);
        b = near ? MOTE__MIN(b, d) : MOTE__MAX(b, d);
    }
    return b;
}

/* Whether every pixel centre of r lies strictly inside t (on no edge,
 * whatever the fill rule says there). Most triangles of a tile do not
 * even box it: that test first, inline, before the edges'. */
static bool mote__covers_edges(const mote__tri *t, mote__rect r, int F)
{
    const int64_t half = (int64_t)1 << (F - 1);
    const int64_t area = (int64_t)(t->X[1] - t->X[0]) * (t->Y[2] - t->Y[0])
                       - (int64_t)(t->Y[1] - t->Y[0]) * (t->X[2] - t->X[0]);
    if (area == 0)
        return false;
    for (int i = 0; i < 4; i++) {
        const int64_t px = ((int64_t)(i & 1 ? r.x1 - 1 : r.x0) << F) + half;
        const int64_t py = ((int64_t)(i >> 1 ? r.y1 - 1 : r.y0) << F) + half;
        for (int e = 0; e < 3; e++) {
            const int a = e, b = e == 2 ? 0 : e + 1;
            const int64_t c = (int64_t)(t->X[b] - t->X[a]) * (py - t->Y[a])
                            - (int64_t)(t->Y[b] - t->Y[a]) * (px - t->X[a]);
            if (c == 0 || (c > 0) != (area > 0))
                return false;
        }
    }
    return true;
}

static inline bool mote__covers(const mote__tri *t, mote__rect r, int F)
{
    return t->xmin <= r.x0 && t->ymin <= r.y0 && t->xmax >= r.x1 - 1 && t->ymax >= r.y1 - 1
        && mote__covers_edges(t, r, F);
}

static void mote__raster_tile(void *arg, int index)
{
    mote_device *dev = (mote_device *)arg;
    mote__bin *b = &dev->bin;
    mote__tile *tile = &((mote__tile *)b->tiles)[index];
    if (!tile->head)
        return;
    if (b->drawn_now)
        b->drawn_now[index] = 1;
    int ts = 1 << b->tile_shift;
    int tx = index % b->tiles_x, ty = index / b->tiles_x;
    mote__rect r = {tx * ts, ty * ts, MOTE__MIN((tx + 1) * ts, dev->desc.width),
                    MOTE__MIN((ty + 1) * ts, dev->desc.height)};
    mote__target tg;
    mote__counts count = {0, 0};
    mote__full_target(dev, &tg, &count);
    mote__warm_tile(&tg, r);
    /* a shortcut: size builds leave it out (the same bytes) */
    const bool coarse = MOTE_SHORTCUTS && !dev->desc.no_tile_depth && tg.depth_format != MOTE_DEPTH_FORMAT_NONE;
    const bool d16 = tg.depth_format == MOTE_DEPTH_FORMAT_16;
    uint32_t farthest = UINT32_MAX;   /* no bound yet: the buffer's depths are any */
    uint32_t behind = 0;
    for (uint32_t off = tile->head; off;) {
        const mote__block *blk = (const mote__block *)(const void *)(b->base + off);
        for (uint32_t i = 0; i < blk->count; i++) {
            const mote__tri *t = (const mote__tri *)(const void *)(b->base + blk->tri[i]);
            const mote__raster_state *rs = t->rs;
            /* the pixels t may touch here (the tile lists it: some) */
            const mote__rect in = {MOTE__MAX(r.x0, t->xmin), MOTE__MAX(r.y0, t->ymin),
                                   MOTE__MIN(r.x1, t->xmax + 1), MOTE__MIN(r.y1, t->ymax + 1)};
            if (farthest != UINT32_MAX && rs->depth_test && mote__depth_bound(t, in, d16, true) >= farthest + (uint32_t)rs->depth_equal) {
                behind++;
                continue;
            }
            mote__raster_tri(t, &tg, r, dev->desc.subpixel_bits);
            if (!coarse || !rs->depth_write)
                continue;
            if (!rs->depth_test) {  /* it may have written farther depths */
                if (mote__covers(t, r, dev->desc.subpixel_bits))
                    farthest = mote__depth_bound(t, r, d16, false);
                else if (farthest != UINT32_MAX)
                    farthest = MOTE__MAX(farthest, mote__depth_bound(t, in, d16, false));
            } else if (!rs->alpha && mote__covers(t, r, dev->desc.subpixel_bits)) {
                farthest = MOTE__MIN(farthest, mote__depth_bound(t, r, d16, false));
            }
        }
        off = blk->next;
    }
    tile->counts = count;
    tile->behind = behind;
}

void mote__bin_flush(mote_device *dev)
{
    mote__bin *b = &dev->bin;
    int n = b->tiles_x * b->tiles_y;
    if (b->triangles > 0) {
        if (dev->desc.parallel_for) {
            dev->desc.parallel_for(dev->desc.parallel_user, n, mote__raster_tile, dev);
            /* groups set up on other cores and will again: no line to take back */
            if (!b->groups_linked)
                b->shared = MOTE__MAX(b->shared, b->used);
        } else {
            for (int i = 0; i < n; i++)
                mote__raster_tile(dev, i);
        }
        const mote__tile *tiles = (const mote__tile *)b->tiles;
        for (int i = 0; i < n; i++) {
            if (tiles[i].head) {
                dev->stats.tiles_drawn++;
                dev->stats.tile_triangles_behind += tiles[i].behind;
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

/* ---- the sink: triangles into the arena ----------------------------------- */

/* The binner's side of a draw: the device it bins for, and the scratch it
 * took from the top of the arena for the draw's vertex cache. */
typedef struct mote__bin_sink {
    mote__sink sink;              /* first: the stage sees only this */
    mote_device *dev;
    size_t scratch;
} mote__bin_sink;

/* A group's slice is full: the whole batch goes serial (mote__bin_run_draws). */
static void mote__bin_overflow(mote__bin_sink *bs)
{
    bs->dev->bin.overflowed = true;
    bs->sink.full = true;
}

static bool mote__bin_sink_begin(mote__sink *s, const mote__raster_state *local)
{
    mote__bin_sink *bs = (mote__bin_sink *)(void *)s;
    mote_device *dev = bs->dev;
    mote__raster_state *rs = (mote__raster_state *)mote__bin_alloc(dev, sizeof *rs);
    if (!rs && dev->bin.group) {
        mote__bin_overflow(bs);
        return false;
    }
    if (!rs) {
        mote__bin_flush(dev);
        rs = (mote__raster_state *)mote__bin_alloc(dev, sizeof *rs);
    }
    if (!rs)
        return false;
    *rs = *local;
    s->rs = rs;
    return true;
}

/* The draw's vertex cache: a group's own (so that its slice holds
 * triangles only), or the top of the arena. */
static void *mote__bin_sink_vertices(mote__sink *s, size_t bytes)
{
    mote__bin_sink *bs = (mote__bin_sink *)(void *)s;
    mote__bin *b = &bs->dev->bin;
    if (b->group)
        return bytes <= b->cache_size ? b->cache : NULL;
    void *p = mote__bin_top_alloc(bs->dev, bytes);
    bs->scratch = p ? bytes : 0;
    return p;
}

#if MOTE_SHORTCUTS
/* Where mote__bin_triangle will keep the next triangle: the arena's first
 * free bytes, when a whole record fits between them and the scratch
 * above; NULL otherwise. Set up there, a binned triangle is not copied;
 * its record ends where its planes do, and what setup wrote past that is
 * free space again. */
static mote__tri *mote__bin_sink_place(mote__sink *s)
{
    mote__bin *b = &((mote__bin_sink *)(void *)s)->dev->bin;
    return b->top - b->used >= sizeof(mote__tri) ? (mote__tri *)(void *)(b->base + b->used) : NULL;
}
#endif

static void mote__bin_sink_triangle(mote__sink *s, mote__tri *t)
{
    mote__bin_sink *bs = (mote__bin_sink *)(void *)s;
    mote_device *dev = bs->dev;
    if (mote__bin_triangle(dev, t))
        return;
    if (dev->bin.group) {
        mote__bin_overflow(bs);
        return;
    }
    /* out of the arena before the flush reuses it */
    mote__tri local = *t;
    /* arena full: draw what is binned, then bin this one afresh, with a
     * fresh copy of the draw's raster state for it and the draw's next
     * triangles */
    mote__bin_flush(dev);
    dev->stats.arena_flushes++;
    mote__raster_state *rs = (mote__raster_state *)mote__bin_alloc(dev, sizeof *rs);
    if (rs) {
        *rs = *s->rs;
        s->rs = rs;
        local.rs = rs;
    }
    if (!rs || !mote__bin_triangle(dev, &local)) {
        /* a single triangle does not fit: draw it directly */
        mote__target tg;
        mote__counts count = {0, 0};
        mote__full_target(dev, &tg, &count);
        mote__rect all = {0, 0, dev->desc.width, dev->desc.height};
        mote__raster_tri(&local, &tg, all, dev->desc.subpixel_bits);
        mote__add_counts(dev, &count);
        mote__bin_mark_all_drawn(dev);   /* not through the tiles */
    }
}

/* Bins a draw, or a piece of one, into dev's arena. */
static mote_result mote__bin_piece(mote_device *dev, const mote_mesh *mesh, const mote_draw_desc *desc,
                                   const mote__piece *piece)
{
    mote__bin_sink bs;
    memset(&bs, 0, sizeof bs);
    bs.sink.begin = mote__bin_sink_begin;
    bs.sink.vertices = mote__bin_sink_vertices;
#if MOTE_SHORTCUTS
    bs.sink.place = mote__bin_sink_place;
#endif
    bs.sink.triangle = mote__bin_sink_triangle;
    bs.dev = dev;
    mote_result r = mote__process_draw(dev, mesh, desc, &bs.sink, piece);
    if (bs.scratch)
        mote__bin_top_release(dev, bs.scratch);
    return r;
}

mote_result mote__bin_draw(mote_device *dev, const mote_mesh *mesh, const mote_draw_desc *desc)
{
    return mote__bin_piece(dev, mesh, desc, NULL);
}

/* ---- binning in parallel ------------------------------------------------ */

/* With desc.parallel_for (and no triangle hook), mote_draw records binned
 * draws and mote__bin_run_draws sets them up in parallel groups, one task
 * each. The frame's draws are cut into parts: a draw whole, or one larger
 * than a group's share of the frame in pieces of its triangles, so that a
 * frame of one big mesh is set up on every core too. A group bins a run of
 * parts through a private copy of the device: its own slice of the free
 * arena, its own tile table, its statistics from zero. Then each tile's
 * group lists are linked in group order after the device's, so every tile
 * lists its triangles in submission order and the bytes are those of the
 * serial path, for any thread count. The vertices of a draw in pieces are
 * transformed and lit first, in parallel chunks, into one cache that its
 * pieces only read. A group whose slice runs out stops, and the whole
 * batch is binned serially instead, which flushes a full arena as usual.
 * The parts depend on the draws alone, and a group gets at least
 * MOTE_PIECE_MIN triangles: a batch smaller than that (one small draw, or
 * many tiny ones) is binned serially, or as one group when the frame's
 * clear is still to run: its stripes are tasks of the first parallel
 * step, beside the setup, which touches no pixel (a group never
 * flushes). */
#define MOTE__BIN_GROUPS 16
/* A cut draw's vertices are prepared in tasks of at least this many. Its
 * pieces have at least MOTE_PIECE_MIN triangles (mote.h). */
#define MOTE__VERTEX_CHUNK 256

typedef struct mote__part {
    int draw;
    mote__piece piece;
} mote__part;

typedef struct mote__group {
    mote_device dev;
    int first, end;               /* parts [first, end) */
    mote_result result;
} mote__group;

/* A draw in pieces: its shared vertex cache, prepared in `chunks` tasks. */
typedef struct mote__cut {
    int draw, chunks;
    void *cache;
} mote__cut;

typedef struct mote__batch {
    mote_device *dev;
    mote__group *groups;
    mote__part *parts;
    mote__cut *cuts;              /* their chunks are the first step's tasks */
    int tasks;                    /* a step's tasks past these are clear stripes */
} mote__batch;

bool mote__bin_defers(const mote_device *dev)
{
    return dev->desc.parallel_for && !dev->desc.triangle_hook;
}

static uint32_t mote__draw_triangles(const mote__draw *d)
{
    return mote__mesh_has_indices(d->mesh) ? d->mesh->index_count / 3 : 0;
}

/* Bins a draw or a piece of it through target (dev itself, or a group's
 * copy, which stops when its slice is full). */
static mote_result mote__bin_part(mote_device *target, const mote_device *dev, int draw, const mote__piece *piece)
{
    return mote__bin_piece(target, dev->draws[draw].mesh, &dev->draws[draw].desc, piece);
}

/* A step's task index past its own tasks: a stripe of the frame's clear. */
static bool mote__stripe_task(const mote__batch *batch, int index)
{
    if (index < batch->tasks)
        return false;
    mote__clear_stripe(batch->dev, index - batch->tasks);
    return true;
}

static void mote__prepare_task(void *arg, int index)
{
    const mote__batch *batch = (const mote__batch *)arg;
    if (mote__stripe_task(batch, index))
        return;
    const mote__cut *c = batch->cuts;
    while (index >= c->chunks)
        index -= c++->chunks;
    const mote__draw *d = &batch->dev->draws[c->draw];
    uint32_t n = d->mesh->vertex_count, k = (uint32_t)index, chunks = (uint32_t)c->chunks;
    mote__prepare_vertices(batch->dev, d->mesh, &d->desc, c->cache, (uint32_t)((uint64_t)n * k / chunks),
                           (uint32_t)((uint64_t)n * (k + 1) / chunks));
}

static void mote__bin_group(void *arg, int g)
{
    const mote__batch *batch = (const mote__batch *)arg;
    if (mote__stripe_task(batch, g))
        return;
    mote__group *gr = &batch->groups[g];
    gr->result = MOTE_OK;
    for (int p = gr->first; p < gr->end && !gr->dev.bin.overflowed; p++) {
        const mote__part *part = &batch->parts[p];
        mote_result r = mote__bin_part(&gr->dev, batch->dev, part->draw, &part->piece);
        if (r != MOTE_OK && gr->result == MOTE_OK)
            gr->result = r;
    }
}

static void mote__stats_add(mote_stats *to, const mote_stats *from)
{
    to->draws += from->draws;
    to->meshes_culled += from->meshes_culled;
    to->triangles_in += from->triangles_in;
    to->triangles_invalid += from->triangles_invalid;
    to->triangles_clipped_away += from->triangles_clipped_away;
    to->triangles_backface += from->triangles_backface;
    to->triangles_degenerate += from->triangles_degenerate;
    to->triangles_drawn += from->triangles_drawn;
    to->triangles_black += from->triangles_black;
    to->tiles_empty += from->tiles_empty;
    to->tiles_drawn += from->tiles_drawn;
    to->arena_flushes += from->arena_flushes;
    to->tile_triangles_behind += from->tile_triangles_behind;
    to->draws_simplified += from->draws_simplified;
    to->pixels_tested += from->pixels_tested;
    to->pixels_written += from->pixels_written;
}

/* What cutting a batch's draws gives: parts, cuts and their vertex tasks,
 * the cuts' caches, the largest cache of a draw not cut (a group's
 * private one), and the batch's triangles. */
typedef struct mote__cut_sizes {
    int parts, cuts, chunks;
    size_t cut_bytes, uncut_cache;
    uint64_t triangles;
} mote__cut_sizes;

/* Cuts the draws [0, n) into parts, in pieces of at least a group's share
 * of the batch's triangles and at most MOTE__BIN_GROUPS per draw. With
 * parts not NULL it also writes them and the cuts, whose caches it places
 * one after another from caches. */
static mote__cut_sizes mote__bin_cut(const mote_device *dev, int n, mote__part *parts, mote__cut *cuts,
                                     unsigned char *caches)
{
    mote__cut_sizes sz = {0, 0, 0, 0, 0, 0};
    uint64_t total = 0;
    for (int i = 0; i < n; i++)
        total += mote__draw_triangles(&dev->draws[i]);
    sz.triangles = total;
    uint64_t share = (total + MOTE__BIN_GROUPS - 1) / MOTE__BIN_GROUPS;
    share = MOTE__MAX(share, (uint64_t)MOTE__MAX(MOTE_PIECE_MIN, 1));
    for (int i = 0; i < n; i++) {
        const mote__draw *d = &dev->draws[i];
        uint32_t tris = mote__draw_triangles(d);
        size_t cache = mote__align(mote__vertex_cache_bytes(d->mesh));
        uint32_t pieces = (uint32_t)MOTE__MIN(tris / share, (uint64_t)MOTE__BIN_GROUPS);
        void *shared = NULL;      /* the cut's cache */
        if (pieces < 2 || cache == 0) {   /* 0: a cache too large to count */
            pieces = 1;
            sz.uncut_cache = MOTE__MAX(sz.uncut_cache, cache);
        } else {
            int chunks = (int)MOTE__MIN(MOTE__MAX(d->mesh->vertex_count / MOTE__VERTEX_CHUNK, 1u),
                                        (uint32_t)MOTE__BIN_GROUPS);
            if (parts) {
                shared = caches + sz.cut_bytes;
                cuts[sz.cuts].draw = i;
                cuts[sz.cuts].chunks = chunks;
                cuts[sz.cuts].cache = shared;
            }
            sz.cuts++;
            sz.chunks += chunks;
            sz.cut_bytes += cache;
        }
        for (uint32_t k = 0; k < pieces; k++, sz.parts++) {
            if (!parts)
                continue;
            parts[sz.parts].draw = i;
            parts[sz.parts].piece.tri0 = (uint32_t)((uint64_t)tris * k / pieces);
            parts[sz.parts].piece.tri1 = (uint32_t)((uint64_t)tris * (k + 1) / pieces);
            parts[sz.parts].piece.vertices = shared;
        }
    }
    return sz;
}

/* Arena bytes a part's triangles take, about (a typical few tiles each):
 * what the slices are sized by. */
static size_t mote__part_bytes(const mote__part *p)
{
    return (size_t)(p->piece.tri1 - p->piece.tri0) * mote_arena_bytes_per_triangle()
         + mote__align(sizeof(mote__raster_state));
}

/* Splits parts [0, n) into groups of about equal arena bytes, each with at
 * least one part, and gives each a slice of [from, to): its estimate plus
 * a list block per tile when all fit so, else a share of the space in
 * proportion. A slice's unused end stays unused until the next flush, so
 * the slices are no larger than that. */
static void mote__bin_plan(const mote_device *dev, const mote__part *parts, mote__group *gr, int groups, int n,
                           size_t from, size_t to)
{
    size_t total = 0, est[MOTE__BIN_GROUPS], sum = 0;
    for (int i = 0; i < n; i++)
        total += mote__part_bytes(&parts[i]);
    size_t done = 0, blocks = (size_t)dev->bin.tiles_x * (size_t)dev->bin.tiles_y * sizeof(mote__block);
    int i = 0;
    for (int g = 0; g < groups; g++) {
        size_t target = total / (size_t)groups * (size_t)(g + 1);
        gr[g].first = i;
        est[g] = blocks;
        while (i < n - (groups - 1 - g) && (i == gr[g].first || g == groups - 1 || done < target)) {
            size_t bytes = mote__part_bytes(&parts[i]);
            done += bytes;
            est[g] += bytes;
            i++;
        }
        gr[g].end = i;
        sum += est[g];
    }
    size_t space = to - from;
    for (int g = 0; g < groups; g++) {
        size_t cap = est[g];
        if (sum > space) {        /* space * est / sum, in 1/65536ths of space */
            uint64_t part = (uint64_t)est[g] * 65536u / sum;
            cap = (size_t)((uint64_t)space / 65536u * part + (uint64_t)space % 65536u * part / 65536u);
        }
        cap = MOTE__MIN(cap, to - from);  /* estimates that wrapped around stay inside */
        mote_device *gd = &gr[g].dev;
        gd->bin.used = from;
        gd->bin.top = from + (cap & ~(size_t)7u);
        from = gd->bin.top;
    }
}

mote_result mote__bin_run_draws(mote_device *dev)
{
    int n = dev->draw_count;
    dev->draw_count = 0;
    mote__bin *b = &dev->bin;
    mote__cut_sizes sz = mote__bin_cut(dev, n, NULL, NULL, NULL);
    /* a group gets at least a piece's worth of triangles: batches of
     * tiny draws (60,000 one-triangle meshes: a parallel step every 64
     * draws) each set up in a step of their own cost more than their
     * triangles, and on a loaded machine, where a step waits for a thread
     * the system has put aside, over ten times the one-thread time */
    uint64_t fill = sz.triangles / (uint64_t)MOTE__MAX(MOTE_PIECE_MIN, 1);
    int groups = (int)MOTE__MIN((uint64_t)MOTE__MIN(sz.parts, MOTE__BIN_GROUPS), MOTE__MAX(fill, 1u));
    size_t table = mote__bin_table_bytes(dev), cache = sz.uncut_cache;
    /* the groups, parts and cuts; per group its device, tile table and
     * vertex cache; the cuts' caches */
    size_t gbytes = mote__align((size_t)groups * sizeof(mote__group));
    size_t pbytes = mote__align((size_t)sz.parts * sizeof(mote__part));
    size_t head = gbytes + pbytes + mote__align((size_t)sz.cuts * sizeof(mote__cut)) + sz.cut_bytes;
    size_t free = b->top - b->used, each = table + cache, scratch = 0;
    unsigned char *mem = NULL;
    /* a single group is worth its copy when the frame's clear runs beside it */
    int least = dev->clear_pending ? 1 : 2;
    if (groups >= least && head < free && cache < free && each <= (free - head) / (size_t)groups) {
        scratch = head + (size_t)groups * each;
        mem = (unsigned char *)mote__bin_top_alloc(dev, scratch);
    }
    mote_result result = MOTE_OK;
    if (mem) {
        mote__group *gr = (mote__group *)(void *)mem;
        mote__batch batch = {dev, gr, (mote__part *)(void *)(mem + gbytes),
                             (mote__cut *)(void *)(mem + gbytes + pbytes), 0};
        mote__bin_cut(dev, n, batch.parts, batch.cuts, mem + head - sz.cut_bytes);
        unsigned char *place = mem + head;
        for (int g = 0; g < groups; g++, place += each) {
            mote_device *gd = &gr[g].dev;
            *gd = *dev;
            memset(&gd->stats, 0, sizeof gd->stats);
            gd->bin.tiles = place;
            memset(place, 0, table);
            gd->bin.cache = place + table;
            gd->bin.cache_size = cache;
            gd->bin.triangles = 0;
            gd->bin.group = true;
            gd->bin.overflowed = false;
        }
        mote__bin_plan(dev, batch.parts, gr, groups, sz.parts, b->used, b->top);
        int stripes = dev->clear_pending ? MOTE__CLEAR_STRIPES : 0;
        dev->clear_pending = false;
        if (sz.chunks > 0) {      /* the cuts' vertices first, the clear beside them */
            batch.tasks = sz.chunks;
            dev->desc.parallel_for(dev->desc.parallel_user, sz.chunks + stripes, mote__prepare_task, &batch);
            stripes = 0;
        }
        batch.tasks = groups;
        dev->desc.parallel_for(dev->desc.parallel_user, groups + stripes, mote__bin_group, &batch);
        bool overflowed = false;
        for (int g = 0; g < groups; g++)
            overflowed |= gr[g].dev.bin.overflowed;
        if (!overflowed) {
            mote__tile *tiles = (mote__tile *)b->tiles;
            int count = b->tiles_x * b->tiles_y;
            for (int g = 0; g < groups; g++) {
                const mote__tile *tl = (const mote__tile *)gr[g].dev.bin.tiles;
                for (int t = 0; t < count; t++) {
                    if (!tl[t].head)
                        continue;
                    if (tiles[t].tail)
                        ((mote__block *)(void *)(b->base + tiles[t].tail))->next = tl[t].head;
                    else
                        tiles[t].head = tl[t].head;
                    tiles[t].tail = tl[t].tail;
                }
                mote__stats_add(&dev->stats, &gr[g].dev.stats);
                b->triangles += gr[g].dev.bin.triangles;
                if (result == MOTE_OK)
                    result = gr[g].result;
            }
            b->used = gr[groups - 1].dev.bin.used;
            b->groups_linked = true;
            mote__bin_top_release(dev, scratch);
            return result;
        }
        mote__bin_top_release(dev, scratch);
    }
    if (dev->clear_pending)       /* before any triangle reaches a pixel */
        mote__clear_frame(dev);
    for (int i = 0; i < n; i++) {
        mote_result r = mote__bin_part(dev, dev, i, NULL);
        if (r != MOTE_OK && result == MOTE_OK)
            result = r;
    }
    return result;
}

#endif /* MOTE_ENABLE_BINNING */
