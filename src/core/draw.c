/*
 * draw.c - one draw through the vertex stage: its description resolved,
 * its context set up (matrices relative to the camera, material, the
 * features that choose the pixel loop), the whole mesh rejected by its
 * bounding sphere, its vertices cached, then its points or triangles
 * handed on (assemble.c) to the sink the caller gives.
 */
#include "vertex.h"

/* An enum value of a desc: v when it is a valid non-default one (in
 * (0, count)), else def. */
static int mote__enum_or(int v, int count, int def)
{
    return v > 0 && v < count ? v : def;
}

mote_result mote__resolve_draw_desc(const mote_draw_desc *in, const mote_mesh *mesh, mote_draw_desc *out)
{
    if (in)
        *out = *in;
    else
        memset(out, 0, sizeof *out);
    out->mode = (mote_mode)mote__enum_or(out->mode, MOTE_MODE_COUNT, MOTE_MODE_TEXTURED);
    out->cull = (mote_cull)mote__enum_or(out->cull, MOTE_CULL_COUNT, MOTE_CULL_BACK);
    out->perspective = (mote_perspective)mote__enum_or(out->perspective, MOTE_PERSPECTIVE_COUNT,
                                                       MOTE_PERSPECTIVE_CORRECT);
    if (MOTE_ENABLE_SUBSPAN && out->subspan_log2 <= 0)   /* a build without it refuses it */
        out->subspan_log2 = 3;
    if (MOTE_ENABLE_SUBSPAN && out->subspan_log2 > 6)
        out->subspan_log2 = 6;
    out->filter = (mote_filter)mote__enum_or(out->filter, MOTE_FILTER_COUNT, MOTE_FILTER_NEAREST);
    /* only points and wireframe read it, which a build without lines refuses */
    if (MOTE_ENABLE_LINES && out->point_color.r == 0 && out->point_color.g == 0
        && out->point_color.b == 0 && out->point_color.a == 0) {
        if (mesh->material.color_set)
            out->point_color = mesh->material.color;
        else
            out->point_color.r = out->point_color.g = out->point_color.b = 255;
        out->point_color.a = 255;
    }
    /* features the build left out (MOTE_ENABLE_* in mote.h) */
    if ((!MOTE_ENABLE_LINES && (out->mode == MOTE_MODE_POINTS || out->mode == MOTE_MODE_WIREFRAME))
        || (!MOTE_ENABLE_BILINEAR && out->filter == MOTE_FILTER_BILINEAR)
        || (!MOTE_ENABLE_SUBSPAN && out->perspective == MOTE_PERSPECTIVE_SUBSPAN)
        || (!MOTE_ENABLE_VERTEX_COLORS && mesh->colors))
        return MOTE_ERR_UNSUPPORTED;
    return MOTE_OK;
}

static bool mote__texture_ok(const mote_texture *t)
{
    if (!(t && t->pixels && t->width > 0 && t->height > 0 && t->width <= 65536 && t->height <= 65536
          && mote__texture_format(t->format)))
        return false;
    /* texels are read as whole 16- and 32-bit words (a core without
     * unaligned access faults on others), and rows must hold a row */
    const int bpp = mote__format_bytes(t->format);   /* 1, 2 or 4 */
    return (((uintptr_t)t->pixels | (uintptr_t)t->stride) & (uintptr_t)(bpp - 1)) == 0
        && (t->stride == 0 || t->stride >= t->width * bpp);
}

/* Whole-mesh rejection: the bounding sphere against the view frustum. For a
 * plane P (P . clip >= 0 inside) and a point c + d with |d| <= r,
 * P . clip = P . (M c) + (P M') d where M' is the 3x4 linear part, so the
 * sphere is outside when P . (M c) < -r |P M'| (Cauchy-Schwarz). */
static bool mote__mesh_outside(const mote__ctx *cx)
{
    const mote_mesh *m = cx->mesh;
    if (!(m->bounds_radius > 0.0f))
        return false;
    static const float planes[6][4] = {
        {1, 0, 0, 1}, {-1, 0, 0, 1}, {0, 1, 0, 1}, {0, -1, 0, 1}, {0, 0, 1, 0}, {0, 0, -1, 1}};
    float c[4];
    mote__mat4_point(cx->mvp, m->bounds_center, c);
    for (int p = 0; p < 6; p++) {
        const float *P = planes[p];
        float f = mote__dot3(P, c) + P[3] * c[3];
        float g2 = 0.0f;
        for (int j = 0; j < 3; j++) {
            float g = 0.0f;
            for (int k = 0; k < 4; k++)
                g += P[k] * cx->mvp[j * 4 + k];
            g2 += g * g;
        }
        float reach = m->bounds_radius * mote__sqrtf(g2);
        if (!mote__finite(f) || !mote__finite(reach))
            return false;
        if (f < -reach * 1.0001f)
            return true;
    }
    return false;
}

/* Arena bytes of a binned draw's vertex cache; 0 when too large to count. */
size_t mote__vertex_cache_bytes(const mote_mesh *mesh)
{
    size_t bytes = (size_t)mesh->vertex_count * sizeof(mote__tvert);
    return bytes / sizeof(mote__tvert) == mesh->vertex_count ? bytes : 0;
}


/* A draw's context and raster state: matrices, material, features.
 * false: the mesh lies outside the view frustum. */
static bool mote__draw_context(mote__ctx *cx, mote__raster_state *rs, mote_device *dev, const mote_mesh *mesh,
                               const mote_draw_desc *desc)
{
#if MOTE__VECTOR_VERTEX
    memset(cx, 0, offsetof(mote__ctx, v4));   /* v4 is set where it is used */
#else
    memset(cx, 0, sizeof *cx);
#endif
    cx->dev = dev;
    cx->mesh = mesh;
    cx->d = *desc;                /* resolved by mote_draw (also when recorded) */

    /* a mirroring transform reverses the screen winding of front faces
     * (as Babylon.js and three.js take it): culling follows */
    bool mirrored = mote__world_matrix(mesh, cx->world);
    mote__sub3(cx->world + 12, dev->frame.camera.position);   /* relative to the camera (mote_begin) */
    mote__mat4_mul(dev->view_proj, cx->world, cx->mvp);
    mote__normal_matrix(cx->world, mirrored, cx->nrm);
    if (mote__mesh_outside(cx))
        return false;
    const mote_material *mat = &mesh->material;
    for (int k = 0; k < 3; k++) {
        cx->color[k] = mat->color_set ? (float)(&mat->color.r)[k] / 255.0f : 1.0f;
#if MOTE_ENABLE_EMISSIVE          /* else 0, as the memset above left it */
        cx->emissive[k] = (float)(&mat->emissive.r)[k] / 255.0f;
#endif
    }
    cx->uscale = mote__or(mat->u_scale, 1.0f);
    cx->vscale = mote__or(mat->v_scale, 1.0f);
    cx->uoff = mat->u_offset;
    cx->voff = mat->v_offset;
    cx->guard_x = (float)(1 << MOTE_GUARD_BITS) / ((float)dev->desc.width * 0.5f);
    cx->guard_y = (float)(1 << MOTE_GUARD_BITS) / ((float)dev->desc.height * 0.5f);

    memset(rs, 0, sizeof *rs);
    cx->rs = rs;
    mote_mode mode = cx->d.mode;
    bool tri_mode = mode == MOTE_MODE_FLAT || mode == MOTE_MODE_GOURAUD || mode == MOTE_MODE_TEXTURED;
    cx->lit = tri_mode && !cx->d.unlit;
    /* vertex colours tint triangles' shades (points and wireframe draw in
     * point_color); a constant false when the build leaves them out */
    bool colored = MOTE_ENABLE_VERTEX_COLORS && tri_mode && mesh->colors;
    /* unlit flat without vertex colours is one colour anyway */
    cx->flat = mode == MOTE_MODE_FLAT && (cx->lit || colored);
    /* per-vertex shades: lit, or vertex colours even unlit */
    rs->gouraud = (cx->lit || colored) && !cx->flat;
    bool front_cw = (cx->d.front_face == MOTE_FRONT_CW) != mirrored;
    cx->cull_cw = cx->d.cull == (front_cw ? MOTE_CULL_FRONT : MOTE_CULL_BACK);
    cx->cull_ccw = cx->d.cull == (front_cw ? MOTE_CULL_BACK : MOTE_CULL_FRONT);
    rs->tex = MOTE__TEX_NONE;
    if (mode == MOTE_MODE_TEXTURED && mote__texture_ok(mat->texture)) {
        rs->tex = MOTE_ENABLE_BILINEAR && cx->d.filter == MOTE_FILTER_BILINEAR ? MOTE__TEX_BILINEAR
                                                                                 : MOTE__TEX_NEAREST;
        rs->texture = mat->texture;
        rs->tex_w = mat->texture->width;
        rs->tex_h = mat->texture->height;
        cx->tex_w = (float)rs->tex_w;
        cx->tex_h = (float)rs->tex_h;
        rs->tex_stride = mat->texture->stride > 0 ? mat->texture->stride
                       : mat->texture->width * mote__format_bytes(mat->texture->format);
        rs->wrap_u = (mote_wrap)mote__enum_or(mat->wrap_u, MOTE_WRAP_COUNT, MOTE_WRAP_REPEAT);
        rs->wrap_v = (mote_wrap)mote__enum_or(mat->wrap_v, MOTE_WRAP_COUNT, MOTE_WRAP_REPEAT);
    }
    /* features that change nothing are dropped before choosing the span */
    bool varying = rs->gouraud || rs->tex != MOTE__TEX_NONE;
    rs->persp = !varying ? MOTE__PERSP_CORRECT
              : cx->d.perspective == MOTE_PERSPECTIVE_AFFINE ? MOTE__PERSP_AFFINE
              : MOTE_ENABLE_SUBSPAN && cx->d.perspective == MOTE_PERSPECTIVE_SUBSPAN ? MOTE__PERSP_SUBSPAN
              : MOTE__PERSP_CORRECT;
    rs->subspan_log2 = cx->d.subspan_log2;
    bool has_depth = dev->desc.depth_format != MOTE_DEPTH_FORMAT_NONE;
    rs->depth_test = has_depth && !cx->d.no_depth_test;
    rs->depth_write = has_depth && !cx->d.no_depth_write;
    /* the pixel loops truncate (z >> 16, then >> 8 for 16 bits): the plane
     * starts half a unit up, so each pixel's 24-bit depth is rounded to
     * nearest, and a 16-bit one is that rounded again: (d24 + 128) >> 8 */
    rs->depth_half = (1 << 15) + (dev->desc.depth_format == MOTE_DEPTH_FORMAT_16 ? 1 << 23 : 0);
    mote__fill_select(rs, dev->desc.color_format, dev->desc.depth_format);
    if (cx->lit)
        mote__vertex_begin(cx);
    return true;
}

#if MOTE_ENABLE_BINNING
void mote__prepare_vertices(mote_device *dev, const mote_mesh *mesh, const mote_draw_desc *desc, void *cache,
                            uint32_t first, uint32_t end)
{
    mote__ctx cx;
    mote__raster_state rs;
    if (!mote__draw_context(&cx, &rs, dev, mesh, desc))
        return;
    mote__tvert *tv = (mote__tvert *)cache;
    mote__transform_range(&cx, tv, first, end);
    uint32_t i = first;
#if MOTE__VECTOR_VERTEX
    if (mote__finish_in_fours(&cx) && i + 4 <= end) {
        mote__v4_light_init(&cx);
        for (; i + 4 <= end; i += 4) {
            /* an invalid vertex is lit too, harmlessly: nothing reads it */
            mote__tvert *const four[4] = {&tv[i], &tv[i + 1], &tv[i + 2], &tv[i + 3]};
            mote__finish4(&cx, four);
        }
    }
#endif
    for (; i < end; i++)
        if (tv[i].state == 1)
            mote__finish(&cx, &tv[i]);
}
#endif

mote_result mote__process_draw(mote_device *dev, const mote_mesh *mesh, const mote_draw_desc *desc,
                               mote__sink *sink, const mote__piece *piece)
{
    /* a draw cut into pieces is counted once, by its first */
    bool first_piece = !MOTE_ENABLE_BINNING || !piece || piece->tri0 == 0;
    dev->stats.draws += first_piece;
    mote__ctx cx;
    mote__raster_state rs;
    /* band bins (mote_device_desc.band_bins): the draw being drawn in a
     * band, recorded in the first */
    mote__draw *rec = dev->bands.bins ? dev->bands.draw : NULL;
    const bool recording = rec && dev->bands.index == 0;
    if (recording) {
        rec->band_first = 255;
        rec->band_last = 0;
        rec->band_known = false;
    }
    if (!mote__draw_context(&cx, &rs, dev, mesh, desc)) {
        dev->stats.meshes_culled += first_piece;
        if (recording)
            rec->band_known = true;   /* in no band */
        return MOTE_OK;
    }
    cx.sink = sink;
    if (MOTE_ENABLE_BINNING && sink->begin && !sink->begin(sink, &rs))
        return sink->full ? MOTE_OK : MOTE_ERR_OUT_OF_MEMORY;
    int F = dev->desc.subpixel_bits;
    mote_mode mode = cx.d.mode;

    mote__tvert small_cache[MOTE__SMALL_CACHE];
    if (MOTE_ENABLE_BINNING && piece && piece->vertices) {
        /* transformed and finished by mote__prepare_vertices, and shared
         * with the draw's other pieces: from here on only read */
        cx.cache = (mote__tvert *)(uintptr_t)piece->vertices;
    } else if (MOTE_ENABLE_BINNING && sink->vertices) {
        size_t bytes = mote__vertex_cache_bytes(mesh);
        cx.cache = bytes ? (mote__tvert *)sink->vertices(sink, bytes) : NULL;
        if (cx.cache)
            mote__transform_range(&cx, cx.cache, 0, mesh->vertex_count);
    }
    if (!cx.cache) {
        memset(small_cache, 0, sizeof small_cache);
        cx.cache = small_cache;
        cx.cache_mask = MOTE__SMALL_CACHE - 1;
    }

    if (MOTE_ENABLE_LINES && mode == MOTE_MODE_POINTS) {
        for (uint32_t i = 0; i < mesh->vertex_count; i++) {
            const mote__tvert *tv = mote__vertex(&cx, i);
            /* valid, inside the viewport and every clip plane, and snapped */
            if (tv->outcode == 0)
                mote__draw_pixel(sink->tg, sink->region, tv->X >> F, tv->Y >> F, cx.d.point_color);
        }
        return MOTE_OK;
    }
    {
        uint32_t tris = mesh->index_count / 3, first = 0;
        if (!mesh->indices)
            tris = 0;
        if (MOTE_ENABLE_BINNING && piece) {
            first = MOTE__MIN(piece->tri0, tris);
            tris = MOTE__MIN(piece->tri1, tris);
        }
        dev->stats.triangles_in += tris - first;
        const bool triangles = !(MOTE_ENABLE_LINES && mode == MOTE_MODE_WIREFRAME);
        if (recording && triangles && cx.cache_mask && first == 0 && tris <= dev->bands.capacity - dev->bands.used) {
            rec->bin_first = dev->bands.used;
            dev->bands.used += tris;
            cx.band_bins = dev->bands.bins + 2 * (size_t)rec->bin_first;
        } else if (rec && !recording && rec->band_known) {
            cx.band_bins = dev->bands.bins + 2 * (size_t)rec->bin_first;
        }
        mote__triangles(&cx, first, tris, MOTE_ENABLE_BINNING && piece && piece->vertices);
        if (recording && cx.band_bins) {
            for (uint32_t k = 0; k < tris; k++) {
                rec->band_first = MOTE__MIN(rec->band_first, cx.band_bins[2 * k]);
                rec->band_last = MOTE__MAX(rec->band_last, cx.band_bins[2 * k + 1]);
            }
            rec->band_known = true;
        }
    }
    return MOTE_OK;
}
