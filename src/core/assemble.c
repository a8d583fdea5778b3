/*
 * assemble.c - a draw's triangles, from its indices to the sink: invalid
 * and trivially outside ones rejected by outcodes, crossing ones clipped
 * into a fan, back faces culled on the snapped winding, flat shading,
 * wireframe polygons, and (SSE2 hosts) front faces queued until their
 * vertices are lit four at a time. Each surviving triangle is set up
 * (setup.c) and handed to the sink in submission order.
 */
#include "vertex.h"
#include "vertex_fixed.h"


/* true when a triangle of this signed screen area is culled */
static bool mote__culled(const mote__ctx *cx, int64_t area2)
{
    return area2 > 0 ? cx->cull_cw : cx->cull_ccw;   /* y grows downward */
}


/* Widens the triangle's range of bands to its rows (band bins). */
static void mote__band_note(const mote__ctx *cx, const int32_t Y[3])
{
    const mote_device *dev = cx->dev;
    const int F = dev->desc.subpixel_bits, last = dev->desc.height - 1;
    int32_t lo = MOTE__MIN(Y[0], MOTE__MIN(Y[1], Y[2])), hi = MOTE__MAX(Y[0], MOTE__MAX(Y[1], Y[2]));
    uint32_t r0 = lo <= 0 ? 0u : (uint32_t)MOTE__MIN(lo >> F, last);
    uint32_t r1 = hi <= 0 ? 0u : (uint32_t)MOTE__MIN(hi >> F, last);
    uint32_t b0 = (r0 * dev->bands.scale_lo) >> 16, b1 = MOTE__MIN((r1 * dev->bands.scale_hi) >> 16, 254u);
    unsigned char *r = cx->band_range;
    r[0] = (unsigned char)MOTE__MIN(r[0], b0);
    r[1] = (unsigned char)MOTE__MAX(r[1], b1);
}

/* Band bins (mote_device_desc.band_bins): whether triangle i misses the
 * band being drawn. The first band visits every triangle and records the
 * bands it touches (mote__band_note, as it is emitted); the others skip
 * those that miss them before any of their vertices is transformed. */
static bool mote__band_skip(mote__ctx *cx, uint32_t i)
{
    const int band = cx->dev->bands.index;
    unsigned char *range = cx->band_bins + 2 * (size_t)i;
    if (band == 0) {
        range[0] = 255;           /* none until emitted */
        range[1] = 0;
        cx->band_range = range;
        return false;
    }
    return band < range[0] || band > range[1];
}

/* Counts what setup made of a triangle. */
static void mote__count_setup(mote_device *dev, mote__setup_result set, bool black)
{
    dev->stats.triangles_degenerate += set == MOTE__SETUP_EMPTY;
    dev->stats.triangles_clipped_away += set == MOTE__SETUP_OUTSIDE;
    dev->stats.triangles_drawn += set == MOTE__SETUP_DRAWN;
    dev->stats.triangles_black += black;
}

/* A band's early end for a triangle with no row of pixels in it (there is
 * no y test in setup): counted as setup would count it, which the first
 * band's figures, the frame's, need; whether it is black is counted by
 * the band that holds its first row (mote__emit_setup), so that a band
 * that does not draw the triangle needs no shade: the integer vertex
 * stage lights its vertices only after this test. */
static bool mote__band_rejects(mote__ctx *cx, const int32_t X[3], const int32_t Y[3])
{
    mote_device *dev = cx->dev;
    const mote__rect *band = &cx->sink->region;
    int box[4];
    mote__setup_result set = mote__setup_box(X, Y, dev->desc.subpixel_bits, dev->desc.width, dev->desc.height, box);
    if (set == MOTE__SETUP_DRAWN && box[3] >= band->y0 && box[1] < band->y1)
        return false;
    mote__count_setup(dev, set, false);
    return true;
}

/* What every triangle meets before its shades are needed: its band range
 * noted (band bins), the hook, and in band mode the band's test. true
 * when that ends it. */
static bool mote__emit_begin(mote__ctx *cx, const int32_t X[3], const int32_t Y[3], const mote__svert *const v[3])
{
    mote_device *dev = cx->dev;
    if (cx->band_range)
        mote__band_note(cx, Y);
    if (dev->desc.triangle_hook) {
        float z[3] = {v[0]->depth, v[1]->depth, v[2]->depth};
        float w[3] = {v[0]->w, v[1]->w, v[2]->w};
        dev->desc.triangle_hook(dev->desc.triangle_hook_user, X, Y, z, w);
    }
    return mote__band_mode(dev) && mote__band_rejects(cx, X, Y);
}

/* Setup, counted, and on to the sink. */
static void mote__emit_setup(mote__ctx *cx, const int32_t X[3], const int32_t Y[3], int64_t area2,
                             const mote__svert *const v[3])
{
    mote_device *dev = cx->dev;
    mote__sink *sink = cx->sink;
    mote__tri local, *t = MOTE_ENABLE_BINNING && sink->place ? sink->place(sink) : NULL;
    if (!t)
        t = &local;
    /* the state the sink keeps for the draw, or the draw's own */
    const mote__raster_state *rs = MOTE_ENABLE_BINNING && sink->rs ? sink->rs : cx->rs;
    mote__setup_result set = mote__setup(t, rs, X, Y, area2, v, dev->desc.subpixel_bits,
                                         dev->desc.width, dev->desc.height);
    bool black = set == MOTE__SETUP_DRAWN && t->shade == MOTE__SHADE_BLACK;
    /* in bands, black once: by the band holding the triangle's first row */
    if (black && mote__band_mode(dev))
        black = t->ymin >= sink->region.y0;
    mote__count_setup(dev, set, black);
    if (set != MOTE__SETUP_DRAWN)
        return;
    if (MOTE_ENABLE_BINNING && sink->triangle)
        sink->triangle(sink, t);
    else
        mote__raster_tri(t, sink->tg, sink->region, dev->desc.subpixel_bits);
}

static void mote__emit(mote__ctx *cx, const int32_t X[3], const int32_t Y[3], int64_t area2,
                       const mote__svert *const v[3])
{
    if (!mote__emit_begin(cx, X, Y, v))
        mote__emit_setup(cx, X, Y, area2, v);
}


/* Twice the signed screen area of a triangle that goes on, 0 (counted)
 * for a degenerate or culled one. */
MOTE__VERTEX_INLINE int64_t mote__facing_area(mote__ctx *cx, const int32_t X[3], const int32_t Y[3])
{
    int64_t area = mote__area2(X, Y);
    if (area == 0) {
        cx->dev->stats.triangles_degenerate++;
        return 0;
    }
    if (mote__culled(cx, area)) {
        cx->dev->stats.triangles_backface++;
        return 0;
    }
    return area;
}

#if MOTE__VECTOR_VERTEX
/* an unclipped face of the cache on to setup */
static void mote__emit_face(mote__ctx *cx, mote__tvert *const tv[3], int64_t area)
{
    const int32_t X[3] = {tv[0]->X, tv[1]->X, tv[2]->X}, Y[3] = {tv[0]->Y, tv[1]->Y, tv[2]->Y};
    const mote__svert *const v[3] = {&tv[0]->sv, &tv[1]->sv, &tv[2]->sv};
    mote__emit(cx, X, Y, area, v);
}

static void mote__queue_emit(mote__ctx *cx)
{
    mote__lit_queue *q = cx->queue;
    for (int f = 0; f < q->faces; f++)
        mote__emit_face(cx, q->face[f].tv, q->face[f].area);
    q->faces = 0;
}

/* lights the queued vertices (repeating the first to make four) and lets
 * every queued face go on */
static void mote__queue_flush(mote__ctx *cx)
{
    mote__lit_queue *q = cx->queue;
    if (q->vertices > 0) {
        for (int i = q->vertices; i < 4; i++)
            q->batch[i] = q->batch[0];
        mote__finish4(cx, q->batch);
        q->vertices = 0;
    }
    mote__queue_emit(cx);
}

/* mote__fan_triangle of an unclipped front face of the draw's cache, of
 * this area */
static void mote__queue_face(mote__ctx *cx, mote__tvert *const tv[3], int64_t area)
{
    mote__lit_queue *q = cx->queue;
    for (int k = 0; k < 3; k++) {
        if (tv[k]->ready)
            continue;
        tv[k]->ready = true;
        q->batch[q->vertices++] = tv[k];
        if (q->vertices == 4)
            mote__queue_flush(cx);
    }
    if (q->vertices == 0 && q->faces == 0) {  /* its vertices are lit: on at once */
        mote__emit_face(cx, tv, area);
        return;
    }
    for (int k = 0; k < 3; k++)
        q->face[q->faces].tv[k] = tv[k];
    q->face[q->faces++].area = area;
    if (q->faces == MOTE__QUEUED_FACES)
        mote__queue_flush(cx);
}
#endif


/* A flat triangle's colour: the lighting at its centroid (lit draws) x
 * the material colour x the mean of its vertex colours (when it has them). */
static void mote__flat_shade(const mote__ctx *cx, mote__tvert *const tv[3], float s[3])
{
    if (MOTE_ENABLE_VERTEX_COLORS && cx->mesh->colors && !cx->lit) {
        memcpy(s, cx->color, 3 * sizeof *s);
        mote__tint(cx, tv, 3, s);
        return;
    }
    float e1[3], e2[3], n[3], c[3], vsum[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = tv[1]->world[k] - tv[0]->world[k];
        e2[k] = tv[2]->world[k] - tv[0]->world[k];
        c[k] = (tv[0]->world[k] + tv[1]->world[k] + tv[2]->world[k]) / 3.0f;
        vsum[k] = tv[0]->normal[k] + tv[1]->normal[k] + tv[2]->normal[k];
    }
    mote__cross3(e1, e2, n);
    /* orient like the vertex normals, which say where outside is */
    if (mote__dot3(n, vsum) < 0.0f)
        for (int k = 0; k < 3; k++)
            n[k] = -n[k];
    mote__normalize(n);
    mote__light_at(cx, c, n, s);
    if (MOTE_ENABLE_VERTEX_COLORS && cx->mesh->colors)
        mote__tint(cx, tv, 3, s);
}


/* A triangle, or one of the fan a clipped one became: counted and dropped
 * when degenerate or culled, else finished and emitted. tv is the original
 * triangle, whose vertices are finished (v may point into them: it is set
 * only then). Flat shading writes the triangle's colour into v's shades,
 * which nothing else reads in that mode: setup takes them at once, and
 * the next triangle sharing a vertex writes its own (into copies where a
 * binned draw's cache may be shared). */
MOTE__VERTEX_INLINE void mote__fan_triangle(mote__ctx *cx, mote__tvert *const tv[3], mote__svert *v0,
                                            mote__svert *v1, mote__svert *v2, const int32_t X[3],
                                            const int32_t Y[3])
{
    int64_t area = mote__facing_area(cx, X, Y);
    if (area == 0)
        return;
    for (int i = 0; i < 3; i++)
        mote__finish(cx, tv[i]);
#if MOTE_ENABLE_BINNING
    mote__svert own[3];
#endif
    if (cx->flat) {
        float s[3];
        mote__flat_shade(cx, tv, s);
#if MOTE_ENABLE_BINNING
        /* into copies: a vertex cache shared by a draw's pieces is only read */
        own[0] = *v0;
        own[1] = *v1;
        own[2] = *v2;
        v0 = &own[0];
        v1 = &own[1];
        v2 = &own[2];
#endif
        mote__shade_fixed(s, v0->s);
        memcpy(v1->s, v0->s, sizeof v0->s);
        memcpy(v2->s, v0->s, sizeof v0->s);
    }
    const mote__svert *const v[3] = {v0, v1, v2};
    mote__emit(cx, X, Y, area, v);
}


#if MOTE_ENABLE_LINES
/* Wireframe: a polygon (the triangle, or what clipping left of it) culled
 * as a whole, then its original edges (orig[k]: edge k..k+1) drawn. */
static void mote__wire_polygon(mote__ctx *cx, const int32_t X[], const int32_t Y[], const bool orig[], int n)
{
    mote_device *dev = cx->dev;
    int64_t area = 0;
    for (int k = 0; k < n; k++) {
        int j = (k + 1) % n;
        area += (int64_t)X[k] * Y[j] - (int64_t)X[j] * Y[k];
    }
    if (area != 0 && mote__culled(cx, area)) {
        dev->stats.triangles_backface++;
        return;
    }
    mote_rgba col = cx->d.point_color;
    int F = dev->desc.subpixel_bits;
    dev->stats.triangles_drawn++;
    for (int k = 0; k < n; k++) {
        if (!orig[k])
            continue;
        int j = (k + 1) % n;
        mote__draw_line(cx->sink->tg, cx->sink->region, X[k] >> F, Y[k] >> F, X[j] >> F, Y[j] >> F, col);
    }
}
#endif

static void mote__clip_polygon(mote__ctx *cx, mote__tvert *const tv[3], unsigned planes)
{
    mote__cvert poly[MOTE__MAX_POLY];
    bool orig[MOTE__MAX_POLY] = {true, true, true};
    for (int k = 0; k < 3; k++) {
        mote__finish(cx, tv[k]);  /* clipping interpolates the lit colour */
        poly[k] = tv[k]->c;
    }
    int n = mote__clip(cx, poly, orig, 3, planes);
    if (n < 3) {
        cx->dev->stats.triangles_clipped_away++;
        return;
    }
    int32_t X[MOTE__MAX_POLY], Y[MOTE__MAX_POLY];
    for (int k = 0; k < n; k++) {
        if (!mote__snap(cx, &poly[k], &X[k], &Y[k])) {
            cx->dev->stats.triangles_invalid++;
            return;
        }
    }
#if MOTE_ENABLE_LINES
    if (cx->d.mode == MOTE_MODE_WIREFRAME) {
        mote__wire_polygon(cx, X, Y, orig, n);
        return;
    }
#endif
    mote__svert sv[MOTE__MAX_POLY];
    for (int k = 0; k < n; k++)
        mote__to_setup(&poly[k], &sv[k]);
    for (int k = 1; k + 1 < n; k++) {
        int32_t tx[3] = {X[0], X[k], X[k + 1]}, ty[3] = {Y[0], Y[k], Y[k + 1]};
        mote__fan_triangle(cx, tv, &sv[0], &sv[k], &sv[k + 1], tx, ty);
    }
}

static void mote__triangle(mote__ctx *cx, const uint32_t idx[3])
{
    mote_device *dev = cx->dev;
    uint32_t nv = cx->mesh->vertex_count;
    if (idx[0] >= nv || idx[1] >= nv || idx[2] >= nv) {
        dev->stats.triangles_invalid++;
        return;
    }
    mote__tvert *tv[3];
    mote__tvert keep[3];
    for (int k = 0; k < 3; k++) {
        if (!cx->cache_mask) {
            tv[k] = &cx->cache[idx[k]];
        } else {
            /* the small cache's next lookup may evict this entry */
            keep[k] = *mote__vertex(cx, idx[k]);
            tv[k] = &keep[k];
        }
    }
    unsigned oc0 = tv[0]->outcode, oc1 = tv[1]->outcode, oc2 = tv[2]->outcode;
    unsigned any = oc0 | oc1 | oc2;
    if (any & MOTE__OC_INVALID) {
        dev->stats.triangles_invalid++;
        return;
    }
    if ((oc0 & oc1 & oc2 & MOTE__OC_REJECT) != 0) {  /* all outside one plane (or one viewport side) */
        dev->stats.triangles_clipped_away++;
        return;
    }
    if ((any & MOTE__OC_CLIP) || (MOTE_ENABLE_LINES && cx->d.mode == MOTE_MODE_WIREFRAME)) {
        /* wireframe takes the polygon path even unclipped (clipping to no
         * plane leaves the triangle as it is): lines are not worth a second path */
#if MOTE__VECTOR_VERTEX
        if (cx->queue)
            mote__queue_flush(cx);
#endif
        mote__clip_polygon(cx, tv, any & MOTE__OC_CLIP);
        return;
    }
    if (any & MOTE__OC_NO_SNAP) {
        dev->stats.triangles_invalid++;
        return;
    }
    /* no clipping: the cached snapped points, culled before anything else */
    int32_t X[3] = {tv[0]->X, tv[1]->X, tv[2]->X}, Y[3] = {tv[0]->Y, tv[1]->Y, tv[2]->Y};
#if MOTE__VECTOR_VERTEX
    if (cx->queue) {
        int64_t area = mote__facing_area(cx, X, Y);
        if (area != 0)
            mote__queue_face(cx, tv, area);
        return;
    }
#endif
    mote__fan_triangle(cx, tv, &tv[0]->sv, &tv[1]->sv, &tv[2]->sv, X, Y);
}

#if MOTE__VECTOR_VERTEX
/* The triangles [first, end) of a draw whose front faces queue (its own
 * full cache, lit Gouraud, never wireframe): mote__triangle's path for an
 * unclipped face, the face's corners and area taken straight from its
 * vertices; any other triangle goes through mote__triangle. GCC kept
 * mote__triangle's arrays and the draw's flags on the stack, which cost
 * the common face most of its work before the queue. */
static void mote__queue_triangles(mote__ctx *cx, const uint32_t *indices, uint32_t first, uint32_t end)
{
    mote__tvert *const cache = cx->cache;
    const uint32_t nv = cx->mesh->vertex_count;
    for (uint32_t i = first; i < end && !cx->sink->full; i++) {
        const uint32_t *idx = &indices[3 * i];
        if (idx[0] >= nv || idx[1] >= nv || idx[2] >= nv) {
            mote__triangle(cx, idx);
            continue;
        }
        mote__tvert *const tv[3] = {&cache[idx[0]], &cache[idx[1]], &cache[idx[2]]};
        const unsigned oc0 = tv[0]->outcode, oc1 = tv[1]->outcode, oc2 = tv[2]->outcode;
        if (((oc0 | oc1 | oc2) & (MOTE__OC_INVALID | MOTE__OC_CLIP | MOTE__OC_NO_SNAP))
            || (oc0 & oc1 & oc2 & MOTE__OC_REJECT)) {
            mote__triangle(cx, idx);
            continue;
        }
        const int32_t X[3] = {tv[0]->X, tv[1]->X, tv[2]->X}, Y[3] = {tv[0]->Y, tv[1]->Y, tv[2]->Y};
        const int64_t area = mote__facing_area(cx, X, Y);
        if (area != 0)
            mote__queue_face(cx, tv, area);
    }
}
#endif

void mote__triangles(mote__ctx *cx, uint32_t first, uint32_t end, bool prepared)
{
    uint32_t i = first;
#if MOTE__VECTOR_VERTEX
    /* a full cache this draw fills itself (a prepared one is finished
     * already): front faces queue for their vertices, lit in fours */
    mote__lit_queue queue;
    if (mote__finish_in_fours(cx) && !cx->cache_mask && !prepared) {
        queue.vertices = queue.faces = 0;
        cx->queue = &queue;
        mote__v4_light_init(cx);
        mote__queue_triangles(cx, cx->mesh->indices, first, end);
        mote__queue_flush(cx);
        cx->queue = NULL;
        return;
    }
#else
    (void)prepared;
#endif
    for (; i < end && !cx->sink->full; i++) {
        if (cx->band_bins && mote__band_skip(cx, i))
            continue;
        uint32_t idx[3];
        mote__mesh_triangle(cx->mesh, i, idx);
        mote__triangle(cx, idx);
    }
}

#if MOTE_FIXED_VERTEX
bool mote__fixed_skip(void *cx, uint32_t i)
{
    mote__ctx *c = (mote__ctx *)cx;
    return c->band_bins && mote__band_skip(c, i);
}

bool mote__fixed_emit_begin(void *cx, const int32_t X[3], const int32_t Y[3], const mote__svert *const v[3])
{
    return mote__emit_begin((mote__ctx *)cx, X, Y, v);
}

void mote__fixed_emit(void *cx, const int32_t X[3], const int32_t Y[3], int64_t area2,
                      const mote__svert *const v[3])
{
    mote__emit_setup((mote__ctx *)cx, X, Y, area2, v);
}
#endif
