/*
 * draw.c - one draw through the vertex stage: its description resolved,
 * its context set up (matrices relative to the camera, material, the
 * features that choose the pixel loop), the whole mesh rejected by its
 * bounding sphere, its vertices cached, then its points or triangles
 * handed on (assemble.c) to the sink the caller gives.
 */
#include "vertex.h"
#include "vertex_fixed.h"

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
    out->mip = (mote_mip)mote__enum_or(out->mip, MOTE_MIP_COUNT, MOTE_MIP_NONE);
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
        || (!MOTE_ENABLE_VERTEX_COLORS && mesh->colors)
        || (!MOTE_ENABLE_BLEND && (out->depth_less_equal || out->no_color_write)))
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


/* A draw texture's size and row stride into rs and cx. */
static void mote__texture_dims(mote__raster_state *rs, mote__ctx *cx, const mote_texture *t)
{
    rs->tex_w = t->width;
    rs->tex_h = t->height;
    cx->tex_w = (float)rs->tex_w;
    cx->tex_h = (float)rs->tex_h;
    rs->tex_stride = t->stride > 0 ? t->stride : t->width * mote__format_bytes(t->format);
}

/* The draw's alpha (mote_material.alpha_mode) into rs: what changes
 * nothing is dropped (an alpha test without a texture, blending at alpha
 * 255 without the texture's), and what the build left out is drawn opaque and counted. */
static void mote__alpha_select(mote__raster_state *rs, const mote_material *mat, mote__ctx *cx)
{
    const mote_alpha_mode mode = mat->alpha_mode;
    const bool test = mode == MOTE_ALPHA_TEST || mode == MOTE_ALPHA_TEST_AND_BLEND;
    const bool blend = mode == MOTE_ALPHA_BLEND || mode == MOTE_ALPHA_TEST_AND_BLEND;
    if (!test && !blend)
        return;
#if !MOTE__ALPHA_ENABLED
    (void)rs;
    cx->simplified = true;           /* the whole check, in the least flash */
    return;
#endif
    if ((test && !MOTE_ENABLE_ALPHA_TEST) || (blend && !MOTE_ENABLE_BLEND))
        cx->simplified = true;
    /* an opacity layer weighs both the test and the blend */
    bool opacity = false, textured = rs->tex != MOTE__TEX_NONE;
#if MOTE__LAYERS_ENABLED
    for (int i = 0; i < rs->layer_count; i++)
        opacity = opacity || rs->layer[i].role == MOTE_LAYER_OPACITY;
    textured = textured && !rs->base_white;
#endif
    const bool texel = textured && mat->use_texture_alpha;
    uint32_t a8 = 255;
    if (mat->alpha_set) {
        const float a = mat->alpha * 255.0f + 0.5f;
        a8 = a >= 255.0f ? 255u : a > 0.0f ? (uint32_t)a : 0u;   /* NaN: 0 */
    }
    rs->alpha8 = (uint8_t)a8;
    if (MOTE_ENABLE_ALPHA_TEST && test && (textured || opacity)) {
        /* a / 255 < cut  <=>  a < ceil(255 cut), for integer a */
        const float cut = 255.0f * mote__or(mat->alpha_cutoff, 0.4f);
        uint32_t c = cut >= 256.0f ? 256u : cut > 0.0f ? (uint32_t)cut : 0u;
        c += c < 256u && (float)c < cut;
        rs->cutoff = (uint16_t)c;
        rs->alpha |= MOTE__ALPHA_TEST;
    }
    if (MOTE_ENABLE_BLEND && blend && (a8 < 255 || texel || opacity))
        rs->alpha |= MOTE__ALPHA_BLEND | (texel ? MOTE__ALPHA_TEXEL : 0);
}

#if MOTE__LAYERS_ENABLED
/* Whether the build draws layers of this role. */
static bool mote__role_built(int role)
{
    return (role == MOTE_LAYER_EMISSIVE && MOTE_ENABLE_EMISSIVE_MAP)
        || (role == MOTE_LAYER_OPACITY && MOTE_ENABLE_OPACITY_MAP)
        || (role == MOTE_LAYER_SPECULAR && MOTE_ENABLE_SPECULAR_MAP && MOTE_ENABLE_SPECULAR);
}

/* One axis of a layer's map L = T a + b (texels of the layer from the
 * draw's, mote__layer): a as mul 2^-sh with mul in [2^29, 2^30], b in
 * 1/2^MOTE__LAYER_BITS texels. false for a scale out of [2^-20, 2^20]. */
static bool mote__layer_axis(float a, float b, mote__layer *l, int k)
{
    float m = a < 0.0f ? -a : a;
    if (!(m >= 1.0f / 1048576.0f && m <= 1048576.0f) || !mote__finite(b))
        return false;
    int sh = 0;
    while (m < 536870912.0f) {
        m *= 2.0f;
        sh++;
    }
    while (m >= 1073741824.0f) {
        m *= 0.5f;
        sh--;
    }
    const int32_t mul = (int32_t)(m + 0.5f);
    l->mul[k] = a < 0.0f ? -mul : mul;
    l->sh[k] = (int8_t)sh;
    const float add = b * (float)(1 << MOTE__LAYER_BITS);
    if (!(add > -4.0e18f && add < 4.0e18f))
        return false;
    l->add[k] = (int64_t)(add < 0.0f ? add - 0.5f : add + 0.5f);
    return true;
}

/* Whether taking whole periods of the draw's texture off its texel
 * coordinates (setup does, for repeat and mirror) moves a layer by whole
 * periods of its own: a shift of one period (two for mirror) is ratio of
 * the layer's uv units. */
static bool mote__layer_period_ok(float ratio, mote_wrap base, mote_wrap layer)
{
    const float unit = ratio * (base == MOTE_WRAP_MIRROR ? 2.0f : 1.0f);
    if (layer == MOTE_WRAP_CLAMP || !(unit > -16777216.0f && unit < 16777216.0f))
        return false;
    const int32_t whole = (int32_t)unit;
    return (float)whole == unit && (layer != MOTE_WRAP_MIRROR || (whole & 1) == 0);
}

/* The material's layers (mote_layer) into rs, after the texture: a draw
 * without one takes layer 0's coordinates and draws as white. What the
 * build left out, and highlights' layers on a fogged draw, are skipped
 * and counted. smooth: Gouraud or textured. */
static void mote__layers_select(mote__raster_state *rs, const mote_material *mat, mote__ctx *cx, bool smooth)
{
    rs->layer_count = 0;
    if (!mat->layers || mat->layer_count <= 0 || cx->d.mode != MOTE_MODE_TEXTURED)
        return;
    const bool spec = smooth && cx->lit && (mat->specular.r | mat->specular.g | mat->specular.b);
    const mote_fog_mode fm = cx->dev->frame.fog.mode;
    const bool fog = smooth && fm > MOTE_FOG_NONE && fm < MOTE_FOG_COUNT && !cx->d.no_fog;
    const int n = MOTE__MIN(mat->layer_count, MOTE_MAX_LAYERS);
    for (int i = 0; i < n; i++) {
        const mote_layer *in = &mat->layers[i];
        const int role = (int)in->role;
        if (role <= MOTE_LAYER_NONE || role >= MOTE_LAYER_ROLE_COUNT || !mote__texture_ok(in->texture))
            continue;
        if (!mote__role_built(role) || (role == MOTE_LAYER_SPECULAR && spec && fog)) {
            cx->simplified = true;
            continue;
        }
        if (role == MOTE_LAYER_SPECULAR && !spec)
            continue;             /* no highlights to scale */
        if (rs->tex == MOTE__TEX_NONE) {   /* layer 0 lends the draw its coordinates */
            rs->tex = MOTE_ENABLE_BILINEAR && cx->d.filter == MOTE_FILTER_BILINEAR ? MOTE__TEX_BILINEAR
                                                                                     : MOTE__TEX_NEAREST;
            rs->base_white = true;
            rs->texture = in->texture;
            rs->wrap_u = (mote_wrap)mote__enum_or(in->wrap_u, MOTE_WRAP_COUNT, MOTE_WRAP_REPEAT);
            rs->wrap_v = (mote_wrap)mote__enum_or(in->wrap_v, MOTE_WRAP_COUNT, MOTE_WRAP_REPEAT);
            mote__texture_dims(rs, cx, in->texture);
        }
        mote__layer *l = &rs->layer[rs->layer_count];
        const mote_texture *tx = in->texture;
        l->texture = tx;
        l->stride = tx->stride > 0 ? tx->stride : tx->width * mote__format_bytes(tx->format);
        l->wrap_u = (mote_wrap)mote__enum_or(in->wrap_u, MOTE_WRAP_COUNT, MOTE_WRAP_REPEAT);
        l->wrap_v = (mote_wrap)mote__enum_or(in->wrap_v, MOTE_WRAP_COUNT, MOTE_WRAP_REPEAT);
        l->role = (uint8_t)role;
        l->from_rgb = in->from_rgb;
        /* L = T a + b per axis: T = (uv ms + mo) TW (v: (1 - that) TH),
         * L = (uv ls + lo) LW likewise, so a = LW ls / (TW ms) */
        bool ok = true;
        const bool bottom = mat->v_origin_bottom;
        for (int k = 0; k < 2; k++) {
            const float ms = mote__or(k ? mat->v_scale : mat->u_scale, 1.0f), mo = k ? mat->v_offset : mat->u_offset;
            const float ls = mote__or(k ? in->v_scale : in->u_scale, 1.0f), lo = k ? in->v_offset : in->u_offset;
            const float tsize = (float)(k ? rs->tex_h : rs->tex_w), lsize = (float)(k ? tx->height : tx->width);
            const float ratio = ls / ms;
            const float b = k && bottom ? (1.0f - ((1.0f - mo) * ratio + lo)) * lsize : (lo - mo * ratio) * lsize;
            ok = ok && mote__layer_axis(lsize * ratio / tsize, b, l, k);
            if (!mote__layer_period_ok(ratio, k ? rs->wrap_v : rs->wrap_u, k ? l->wrap_v : l->wrap_u))
                rs->texel_absolute = true;
        }
        if (!ok)
            continue;
        const bool white = mote__zero3(in->factor);
        for (int k = 0; k < 3; k++) {
            float f = white ? 1.0f : in->factor[k];
            f = f > 0.0f ? (f < 64.0f ? f : 64.0f) : 0.0f;   /* NaN: 0 */
            const float unit = role == MOTE_LAYER_EMISSIVE ? (float)MOTE__SHADE_ONE / 255.0f
                             : role == MOTE_LAYER_SPECULAR ? 65536.0f : 256.0f;
            l->factor[k] = (uint32_t)(f * unit + 0.5f);
        }
        rs->layer_count++;
    }
}
#endif

/* Specular highlights and fog (an additive colour per vertex, and per
 * vertex shades) for Gouraud and textured draws: asked for by a specular
 * colour on a lit draw, or by the frame's fog unless the draw says no_fog.
 * What the build left out is drawn without and counted. */
static void mote__additive_select(mote__raster_state *rs, const mote_material *mat, mote__ctx *cx, bool smooth)
{
    const bool spec = smooth && cx->lit && (mat->specular.r | mat->specular.g | mat->specular.b);
    const mote_fog_mode fm = cx->dev->frame.fog.mode;
    const bool fog = smooth && fm > MOTE_FOG_NONE && fm < MOTE_FOG_COUNT && !cx->d.no_fog;
    if ((spec && !MOTE_ENABLE_SPECULAR) || (fog && !MOTE_ENABLE_FOG))
        cx->simplified = true;
#if MOTE__ADD_ENABLED
    cx->spec_on = MOTE_ENABLE_SPECULAR && spec;
    cx->fog_on = MOTE_ENABLE_FOG && fog;
    cx->additive = cx->spec_on || cx->fog_on;
    for (int k = 0; k < 3; k++)
        cx->spec[k] = (float)(&mat->specular.r)[k] / 255.0f;
    cx->spec_power = mote__or(mat->specular_power, 64.0f);
    rs->additive = cx->additive;
    if (cx->additive)             /* its values are per vertex */
        rs->gouraud = true;
#else
    (void)rs;
#endif
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
    if (mesh->compact) {          /* its integers into the mesh's space */
        mote__compact_fold(cx->world, mesh->compact->offset, mesh->compact->scale, cx->world);
        mote__compact_fold(cx->mvp, mesh->compact->offset, mesh->compact->scale, cx->mvp);
    }
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
    if (mesh->compact) {          /* uv = uvs x uv_scale + uv_offset, then the material's */
        cx->uoff += mesh->compact->uv_offset[0] * cx->uscale;
        cx->voff += mesh->compact->uv_offset[1] * cx->vscale;
        cx->uscale *= mesh->compact->uv_scale[0];
        cx->vscale *= mesh->compact->uv_scale[1];
    }
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
        mote__texture_dims(rs, cx, mat->texture);
        rs->wrap_u = (mote_wrap)mote__enum_or(mat->wrap_u, MOTE_WRAP_COUNT, MOTE_WRAP_REPEAT);
        rs->wrap_v = (mote_wrap)mote__enum_or(mat->wrap_v, MOTE_WRAP_COUNT, MOTE_WRAP_REPEAT);
    }
#if MOTE__LAYERS_ENABLED
    mote__layers_select(rs, mat, cx, tri_mode && mode != MOTE_MODE_FLAT);
#else
    /* a build without any layer draws the rest, and says so */
    if (mat->layers && mat->layer_count > 0 && cx->d.mode == MOTE_MODE_TEXTURED)
        cx->simplified = true;
#endif
    mote__alpha_select(rs, mat, cx);
    mote__additive_select(rs, mat, cx, tri_mode && mode != MOTE_MODE_FLAT);
    /* a mip chain of the draw's texture (level 0 its pixels) */
    if (rs->tex != MOTE__TEX_NONE && (!MOTE__LAYERS_ENABLED || rs->texture == mat->texture) && cx->d.mip >= MOTE_MIP_TRIANGLE && mat->mipmaps && mat->mipmaps->count > 1
        && mat->mipmaps->count <= MOTE_MAX_MIPS && mat->mipmaps->level[0].pixels == mat->texture->pixels
        && mat->mipmaps->level[0].width == rs->tex_w && mat->mipmaps->level[0].height == rs->tex_h) {
        if (MOTE_ENABLE_MIPMAPS) {
            rs->mips = mat->mipmaps;
            rs->mip_pixel = cx->d.mip >= MOTE_MIP_PIXEL;
            rs->mip_blend = cx->d.mip == MOTE_MIP_TRILINEAR;
        } else
            cx->simplified = true;
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
    rs->depth_equal = rs->depth_test && cx->d.depth_less_equal;
    rs->no_color = cx->d.no_color_write;
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
#if MOTE_FIXED_VERTEX
    if (mote__fixed_handles(dev, mesh, desc))   /* its pieces transform their own */
        return;
#endif
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

/* The triangles [*first, return) of the draw: a piece's, or all. */
static uint32_t mote__tri_range(mote__ctx *cx, const mote__piece *piece, uint32_t *first)
{
    const mote_mesh *mesh = cx->mesh;
    uint32_t tris = mote__mesh_has_indices(mesh) ? mesh->index_count / 3 : 0;
    *first = 0;
    if (MOTE_ENABLE_BINNING && piece) {
        *first = MOTE__MIN(piece->tri0, tris);
        tris = MOTE__MIN(piece->tri1, tris);
    }
    cx->dev->stats.triangles_in += tris - *first;
    return tris;
}

/* Band bins for the draw's triangles (mote_device_desc.band_bins): in the
 * first band (recording), room for them if there is some; in the others,
 * the ranges the first recorded. */
static void mote__bins_open(mote__ctx *cx, mote__draw *rec, bool recording, uint32_t first, uint32_t tris)
{
    mote__bands *bb = &cx->dev->bands;
    if (recording && first == 0 && tris <= bb->capacity - bb->used) {
        rec->bin_first = bb->used;
        bb->used += tris;
        cx->band_bins = bb->bins + 2 * (size_t)rec->bin_first;
    } else if (rec && !recording && rec->band_known) {
        cx->band_bins = bb->bins + 2 * (size_t)rec->bin_first;
    }
}

/* The first band: the draw's bands, from its triangles' */
static void mote__bins_close(const mote__ctx *cx, mote__draw *rec, bool recording, uint32_t tris)
{
    if (!recording || !cx->band_bins)
        return;
    for (uint32_t k = 0; k < tris; k++) {
        rec->band_first = MOTE__MIN(rec->band_first, cx->band_bins[2 * k]);
        rec->band_last = MOTE__MAX(rec->band_last, cx->band_bins[2 * k + 1]);
    }
    rec->band_known = true;
}

#if MOTE_FIXED_VERTEX
/* The draw's triangles through the integer vertex stage (vertex_fixed.c). */
static mote_result mote__fixed_run(mote__ctx *cx, const mote__piece *piece, mote__draw *rec, bool recording)
{
    uint32_t first, tris = mote__tri_range(cx, piece, &first);
    mote__bins_open(cx, rec, recording, first, tris);
    const mote__fixed_draw fd = {cx->mvp, cx->world, cx->nrm, cx->uscale, cx->vscale, cx->uoff, cx->voff,
                                 cx->lit, cx->flat, cx->cull_cw, cx->cull_ccw, cx->rs, cx, cx->d.lights_off,
                                 recording ? NULL : cx->band_bins, (unsigned)cx->dev->bands.index};
    mote__fixed_triangles(cx->dev, cx->mesh, &fd, first, tris);
    mote__bins_close(cx, rec, recording, tris);
    return MOTE_OK;
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
    dev->stats.draws_simplified += first_piece && cx.simplified;
    cx.sink = sink;
    if (MOTE_ENABLE_BINNING && sink->begin && !sink->begin(sink, &rs))
        return sink->full ? MOTE_OK : MOTE_ERR_OUT_OF_MEMORY;
#if MOTE_FIXED_VERTEX
    if (mote__fixed_handles(dev, mesh, &cx.d))
        return mote__fixed_run(&cx, piece, rec, recording);
#endif
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
    uint32_t first, tris = mote__tri_range(&cx, piece, &first);
    /* wireframe draws no triangle through mote__emit, which records bands */
    const bool triangles = !(MOTE_ENABLE_LINES && mode == MOTE_MODE_WIREFRAME);
    mote__bins_open(&cx, rec, recording && triangles && cx.cache_mask, first, tris);
    mote__triangles(&cx, first, tris, MOTE_ENABLE_BINNING && piece && piece->vertices);
    mote__bins_close(&cx, rec, recording, tris);
    return MOTE_OK;
}
