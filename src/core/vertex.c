/*
 * vertex.c - the per-vertex work of a draw: transform to clip space, the
 * outcode and snap of an unclipped vertex, lighting (the model of
 * light.h), vertex colours and the conversion to setup's integer units.
 * On SSE2 hosts a full cache is transformed, and lit Gouraud vertices are
 * finished, four at a time, with the scalar code's bits.
 */
#include "vertex.h"

/* The light model for one vertex at a time, on every target. */
#define MOTE__LT float
#define MOTE__LT_MASK int
#define MOTE__LT_SPLAT(x) (x)
#define MOTE__LT_SELECT(m, a, b) ((m) ? (a) : (b))
#define MOTE__LT_ANY(m) (m)
#define MOTE__LT_RSQRT mote__rsqrtf
#define MOTE__LT_LANES 1
#define MOTE__LT_LANE(v, j) (v)
#define MOTE__LT_SET mote__lights
#define MOTE__LT_LIGHT mote__light_term
#define MOTE__LT_PREPARE mote__lights_prepare
#define MOTE__LT_EVAL mote__light
#include "light.h"

void mote__vertex_begin(mote__ctx *cx)
{
    mote__lights_prepare(&cx->lights, cx->dev, cx->color, cx->emissive, cx->d.lights_off);
}

void mote__light_at(const mote__ctx *cx, const float p[3], const float n[3], float out[3])
{
    mote__light(&cx->lights, p, n, out);
}

void mote__normalize(float v[3])
{
    float k = mote__rsqrtf(mote__dot3(v, v));
    v[0] *= k;
    v[1] *= k;
    v[2] *= k;
}

/* ---- vertex colours -------------------------------------------------------- */

/* s x the mean colour of n vertices (r, g, b; 255 = 1): one vertex's own,
 * or a flat triangle's three */
void mote__tint(const mote__ctx *cx, mote__tvert *const tv[], int n, float s[3])
{
    for (int c = 0; c < 3; c++) {
        unsigned sum = 0;
        for (int i = 0; i < n; i++)
            sum += (&cx->mesh->colors[tv[i]->index].r)[c];
        s[c] *= (float)sum / ((float)n * 255.0f);
    }
}


/* ---- setup's units -------------------------------------------------------- */

/* A colour in [0,1] as 2^24 fixed point, clamped before the conversion:
 * lights and materials can take a lit colour far past 1 (or to NaN). */
void mote__shade_fixed(const float s[3], int32_t out[3])
{
    for (int c = 0; c < 3; c++) {
        const float f = s[c] * (float)MOTE__SHADE_ONE + 0.5f;
        out[c] = !(f > 0.0f) ? 0 : f >= (float)MOTE__SHADE_ONE ? MOTE__SHADE_ONE : (int32_t)f;
    }
}

/* round(f 2^s), halves away from zero, for s >= 0 and |f 2^s| < 2^62,
 * exactly: from the float's 24-bit mantissa and exponent (zero and
 * denormals give 0), as a float converted to a 64-bit integer would cost a
 * core without an FPU libgcc's double-precision routines */
static int64_t mote__round_scaled(float f, int s)
{
    uint32_t bits = mote__float_bits(f);
    /* |f| 2^s = m 2^-r, the mantissa placed at bit 39 so that r >= 1 */
    int r = 189 - s - (int)((bits >> 23) & 0xff);
    uint64_t m = (uint64_t)((bits & 0x7fffffu) | 0x800000u) << 39;
    uint64_t mag = r < 64 ? (m + ((uint64_t)1 << (r - 1))) >> r : 0;
    uint64_t neg = 0u - (uint64_t)(bits >> 31);
    return (int64_t)((mag ^ neg) - neg);
}

/* A final vertex (as transformed, or made by clipping) in setup's units.
 * Any valid vertex converts (texels within 1e9, see mote__transform), also
 * one that clipping will drop. */
void mote__to_setup(const mote__cvert *v, mote__svert *out)
{
    mote__shade_fixed(v->s, out->s);
#if MOTE__ADD_ENABLED
    mote__shade_fixed(v->a, out->a);
#endif
    for (int k = 0; k < 2; k++)
        out->texel[k] = mote__round_scaled(k ? v->v : v->u, 16);
    /* clipping's float rounding can leave z/w a hair outside [0, 1]; NaN
     * (0/0, at a vertex behind the eye, which clipping drops) gives 0 */
    float d = v->z / v->w;
    out->depth = d > 0.0f ? (d < 1.0f ? d : 1.0f) : 0.0f;
    out->z = (int32_t)mote__round_scaled(out->depth * (float)MOTE__DEPTH_MAX, 0);
    out->w = v->w;
    mote__inverse_w(v->w, out);
}


/* ---- vertices ------------------------------------------------------------ */

static void mote__transform(mote__ctx *cx, uint32_t index, mote__tvert *tv)
{
    mote_vertex tmp;
    const mote_vertex *in = mote__mesh_vertex(cx->mesh, index, &tmp);
    tv->index = index;
    float out[4];
    mote__mat4_point(cx->mvp, in->position, out);
    memcpy(&tv->c, out, sizeof out);        /* x, y, z, w */
    tv->state = 1;
    for (int k = 0; k < 4; k++)
        if (!mote__finite(out[k]))
            tv->state = 2;
    tv->ready = false;
    memcpy(tv->c.s, cx->color, sizeof tv->c.s);
    if (cx->rs->tex != MOTE__TEX_NONE) {
        float u = in->uv[0] * cx->uscale + cx->uoff;
        float v = in->uv[1] * cx->vscale + cx->voff;
        if (cx->mesh->material.v_origin_bottom)
            v = 1.0f - v;
        tv->c.u = u * cx->tex_w;
        tv->c.v = v * cx->tex_h;
        /* also false for NaN and +-Inf */
        if (!(tv->c.u >= -1e9f && tv->c.u <= 1e9f && tv->c.v >= -1e9f && tv->c.v <= 1e9f))
            tv->state = 2;
    } else {
        tv->c.u = tv->c.v = 0.0f;
    }
    tv->outcode = MOTE__OC_INVALID;
    if (tv->state == 1) {
        unsigned oc = mote__outcode(cx, &tv->c);
        /* only triangles with no vertex outside a clip plane use this snap */
        if (!(oc & MOTE__OC_CLIP) && !mote__snap(cx, &tv->c, &tv->X, &tv->Y))
            oc |= MOTE__OC_NO_SNAP;
        tv->outcode = (uint16_t)oc;
    }
}

#if MOTE__ADD_ENABLED
/* The additive colour of a vertex, lit and tinted: Babylon.js's
 * highlights x the material's specular colour, then its fog, which scales
 * both and adds the fog colour: colour f + fog (1 - f) with
 * colour = texel x s + a. */
static void mote__additive(const mote__ctx *cx, mote__tvert *tv)
{
    float a[3] = {0.0f, 0.0f, 0.0f};
#if MOTE_ENABLE_SPECULAR
    if (cx->spec_on) {
        mote__specular(cx->dev, cx->d.lights_off, tv->world, tv->normal, cx->spec_power, a);
        for (int c = 0; c < 3; c++)
            a[c] *= cx->spec[c];
    }
#endif
#if MOTE_ENABLE_FOG
    if (cx->fog_on) {
        const mote_fog *fog = &cx->dev->frame.fog;
        const float f = mote__fog_factor(fog, mote__sqrtf(mote__dot3(tv->world, tv->world)));
        for (int c = 0; c < 3; c++) {
            tv->c.s[c] *= f;
            a[c] = a[c] * f + fog->color[c] * (1.0f - f);
        }
    }
#endif
    memcpy(tv->c.a, a, sizeof a);
}
#endif

/* What only drawn triangles need of a vertex: its world position and
 * normal (lighting's inputs, read here by Gouraud and after this by flat
 * shading), Gouraud lighting, the costliest per-vertex step, and the
 * conversion to setup's units. None of it can make a vertex invalid, so
 * with the full cache it waits until a triangle using the vertex survives
 * culling: about half of a closed mesh's vertices are only on back faces. */
void mote__finish(const mote__ctx *cx, mote__tvert *tv)
{
    if (tv->ready)
        return;
    tv->ready = true;
    if (cx->lit || cx->additive) {
        mote_vertex tmp;
        const mote_vertex *in = mote__mesh_vertex(cx->mesh, tv->index, &tmp);
        float wp[4];
        mote__mat4_point(cx->world, in->position, wp);
        for (int k = 0; k < 3; k++) {
            tv->world[k] = wp[k];
            tv->normal[k] = mote__dot3(&cx->nrm[k * 3], in->normal);
        }
        mote__normalize(tv->normal);
    }
    if (cx->rs->gouraud) {
        /* an unlit draw has per-vertex shades only for its vertex colours */
        if (!MOTE_ENABLE_VERTEX_COLORS || cx->lit)
            mote__light(&cx->lights, tv->world, tv->normal, tv->c.s);
        if (MOTE_ENABLE_VERTEX_COLORS && cx->mesh->colors)
            mote__tint(cx, &tv, 1, tv->c.s);
    }
#if MOTE__ADD_ENABLED
    /* here, not at transform: the scalar and vector transforms share it */
    if (cx->additive)
        mote__additive(cx, tv);
    else
        tv->c.a[0] = tv->c.a[1] = tv->c.a[2] = 0.0f;
#endif
    mote__to_setup(&tv->c, &tv->sv);
}

#if MOTE__VECTOR_VERTEX

/* The light model for four vertices at a time. */
#define MOTE__LT mote__v4f
#define MOTE__LT_MASK mote__v4i
#define MOTE__LT_SPLAT mote__v4_splat
#define MOTE__LT_SELECT mote__v4_select
#define MOTE__LT_ANY(m) 1
#define MOTE__LT_RSQRT mote__v4_rsqrt
#define MOTE__LT_LANES 4
#define MOTE__LT_LANE(v, j) ((v)[j])
#define MOTE__LT_SET mote__v4_lights
#define MOTE__LT_LIGHT mote__v4_light
#define MOTE__LT_PREPARE mote__v4_lights_prepare
#define MOTE__LT_EVAL mote__light4
#include "light.h"

/* Four vertices' fields in and out by rows: a row is 16 bytes of one
 * vertex, four rows turned into four lanes and back (_MM_TRANSPOSE4_PS,
 * which moves bits and computes nothing), where GCC moved lanes one float
 * at a time. These are the fields read and written as rows. */
typedef char mote__vertex_rows[offsetof(mote_vertex, normal) == 12 && offsetof(mote_vertex, uv) == 24
                               && sizeof(mote_vertex) == 32 ? 1 : -1];
typedef char mote__tvert_rows[offsetof(mote__tvert, ready) == 1 && offsetof(mote__tvert, outcode) == 2
                              && offsetof(mote__tvert, index) == 4 && offsetof(mote__tvert, X) == 8
                              && offsetof(mote__tvert, Y) == 12 && offsetof(mote__tvert, c) == 16 ? 1 : -1];
typedef char mote__cvert_rows[offsetof(mote__cvert, s) == 16 && offsetof(mote__cvert, u) == 28
                              && offsetof(mote__cvert, v) == 32 ? 1 : -1];
typedef char mote__svert_rows[offsetof(mote__svert, z) == offsetof(mote__svert, s) + 12
                              && offsetof(mote__svert, w) == offsetof(mote__svert, depth) + 4 ? 1 : -1];

static inline __m128 mote__row(const void *p)
{
    return _mm_loadu_ps((const float *)p);
}

/* Columns a, b, c, d (lane i of each) as vertex i's row, stored at dst[i]
 * + offset; 16 bytes each. */
static inline void mote__store_rows(mote__tvert *const dst[4], size_t offset, mote__v4f a, mote__v4f b,
                                    mote__v4f c, mote__v4f d)
{
    __m128 r0 = (__m128)a, r1 = (__m128)b, r2 = (__m128)c, r3 = (__m128)d;
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    _mm_storeu_ps((float *)(void *)((char *)dst[0] + offset), r0);
    _mm_storeu_ps((float *)(void *)((char *)dst[1] + offset), r1);
    _mm_storeu_ps((float *)(void *)((char *)dst[2] + offset), r2);
    _mm_storeu_ps((float *)(void *)((char *)dst[3] + offset), r3);
}


/* mote__to_setup's texels of c: round(x 2^16), halves away from zero,
 * as mote__round_scaled(x, 16) gives, for u and v at once. x 2^16 is
 * exact in double, and so is x 2^16 +- 1/2 where |x 2^16| >= 1/2 (at most
 * 25 significant bits); below that the sum stays inside (-1, 1) and
 * truncates to 0 as it should. Valid texels are within 1e9, so
 * |x 2^16| < 2^46. Compared with mote__round_scaled on every float within
 * 1e9: none differ. With the depth below, it replaces
 * mote__round_scaled's three calls. (The 64-bit conversion is x86-64's.) */
static inline void mote__texels_fixed(const mote__cvert *c, int64_t out[2])
{
#if defined(__x86_64__)
    const __m128 uv = _mm_castsi128_ps(_mm_loadu_si64(&c->u));   /* u, v */
    const __m128d x = _mm_mul_pd(_mm_cvtps_pd(uv), _mm_set1_pd(65536.0));
    const __m128d half = _mm_or_pd(_mm_and_pd(x, _mm_set1_pd(-0.0)), _mm_set1_pd(0.5));  /* +-1/2 as x */
    const __m128d y = _mm_add_pd(x, half);
    out[0] = _mm_cvttsd_si64(y);
    out[1] = _mm_cvttsd_si64(_mm_unpackhi_pd(y, y));
#else
    out[0] = mote__round_scaled(c->u, 16);
    out[1] = mote__round_scaled(c->v, 16);
#endif
}

/* mote__round_scaled(x, 0) in each lane, for 0 <= x < 2^24 (a depth in
 * the buffer's units): x - trunc(x) is exact in float, and rounding half
 * up is rounding half away from zero for x >= 0 (every float there
 * compared: none differ) */
static inline mote__v4i mote__v4_round_depth(mote__v4f x)
{
    const mote__v4i t = (mote__v4i)_mm_cvttps_epi32((__m128)x);
    const mote__v4f frac = x - (mote__v4f)_mm_cvtepi32_ps((__m128i)t);
    return t - (mote__v4i)(frac >= 0.5f);   /* the mask is -1 */
}

/* mote__finish of four vertices (not yet ready; the same one twice is

 * fine) of a lit Gouraud draw */
void mote__finish4(const mote__ctx *cx, mote__tvert *const tv[4])
{
    mote__v4f pos[3], nin[3], world[3], normal[3], shade[3];
    {
        const mote_vertex *const vx = cx->mesh->vertices;
        const mote_vertex *const in[4] = {&vx[tv[0]->index], &vx[tv[1]->index], &vx[tv[2]->index],
                                          &vx[tv[3]->index]};
        /* rows of position and normal x, and of normal y and z, u, v */
        __m128 a0 = mote__row(in[0]), a1 = mote__row(in[1]), a2 = mote__row(in[2]), a3 = mote__row(in[3]);
        _MM_TRANSPOSE4_PS(a0, a1, a2, a3);
        pos[0] = (mote__v4f)a0;
        pos[1] = (mote__v4f)a1;
        pos[2] = (mote__v4f)a2;
        nin[0] = (mote__v4f)a3;
        const __m128 b0 = mote__row(in[0]->normal + 1), b1 = mote__row(in[1]->normal + 1);
        const __m128 b2 = mote__row(in[2]->normal + 1), b3 = mote__row(in[3]->normal + 1);
        const __m128 t01 = _mm_unpacklo_ps(b0, b1), t23 = _mm_unpacklo_ps(b2, b3);
        nin[1] = (mote__v4f)_mm_movelh_ps(t01, t23);
        nin[2] = (mote__v4f)_mm_movehl_ps(t23, t01);
    }
    /* mote__mat4_point's rows, and mote__dot3 with the normal matrix */
    const mote__v4f *m = cx->v4.world, *nrm = cx->v4.nrm;
    for (int k = 0; k < 3; k++) {
        world[k] = m[0 * 4 + k] * pos[0] + m[1 * 4 + k] * pos[1] + m[2 * 4 + k] * pos[2] + m[3 * 4 + k];
        normal[k] = nrm[k * 3 + 0] * nin[0] + nrm[k * 3 + 1] * nin[1] + nrm[k * 3 + 2] * nin[2];
    }
    const mote__v4f scale = mote__v4_rsqrt(mote__v4_dot3(normal, normal));
    for (int k = 0; k < 3; k++)
        normal[k] *= scale;
    mote__light4(&cx->v4.lights, world, normal, shade);
    /* mote__to_setup's shades and depth, in vectors */
    mote__v4i fixed[3];
    for (int c = 0; c < 3; c++) {
        const mote__v4i v = __builtin_convertvector(shade[c] * (float)MOTE__SHADE_ONE + 0.5f, mote__v4i);
        const mote__v4i low = v < 0, high = v > MOTE__SHADE_ONE;
        fixed[c] = (v & ~(low | high)) | (high & MOTE__SHADE_ONE);
    }
    /* rows of the clip position: its last two columns are z and w */
    const __m128 c0 = mote__row(&tv[0]->c), c1 = mote__row(&tv[1]->c), c2 = mote__row(&tv[2]->c),
                 c3 = mote__row(&tv[3]->c);
    const __m128 zw01 = _mm_unpackhi_ps(c0, c1), zw23 = _mm_unpackhi_ps(c2, c3);
    const mote__v4f z = (mote__v4f)_mm_movelh_ps(zw01, zw23), w = (mote__v4f)_mm_movehl_ps(zw23, zw01);
    mote__v4f d = z / w;
    d = mote__v4_select(d > 0.0f, mote__v4_select(d < 1.0f, d, mote__v4_splat(1.0f)), mote__v4_splat(0.0f));
    const mote__v4i zfixed = mote__v4_round_depth(d * (float)MOTE__DEPTH_MAX);
    /* out by rows: w (unchanged) and the lit shade; the fixed shades and
     * z; depth and w in pairs; the texels of each vertex (world and
     * normal stay unset: only flat shading reads them) */
    mote__store_rows(tv, offsetof(mote__tvert, c.w), w, shade[0], shade[1], shade[2]);
    mote__store_rows(tv, offsetof(mote__tvert, sv.s), (mote__v4f)fixed[0], (mote__v4f)fixed[1],
                     (mote__v4f)fixed[2], (mote__v4f)zfixed);
    const __m128 dw01 = _mm_unpacklo_ps((__m128)d, (__m128)w), dw23 = _mm_unpackhi_ps((__m128)d, (__m128)w);
    _mm_storel_pi((__m64 *)(void *)&tv[0]->sv.depth, dw01);
    _mm_storeh_pi((__m64 *)(void *)&tv[1]->sv.depth, dw01);
    _mm_storel_pi((__m64 *)(void *)&tv[2]->sv.depth, dw23);
    _mm_storeh_pi((__m64 *)(void *)&tv[3]->sv.depth, dw23);
    for (int i = 0; i < 4; i++) {
        tv[i]->ready = true;
        mote__texels_fixed(&tv[i]->c, tv[i]->sv.texel);
        mote__inverse_w(tv[i]->c.w, &tv[i]->sv);
    }
    if (MOTE_ENABLE_VERTEX_COLORS && cx->mesh->colors)
        for (int i = 0; i < 4; i++) {
            /* an invalid vertex, which mote__prepare_vertices lights too,
             * is never read, and its texels may be NaN or beyond what
             * mote__to_setup converts */
            if (tv[i]->state != 1)
                continue;
            /* from the lit shade again: a vertex may be here twice */
            for (int k = 0; k < 3; k++)
                tv[i]->c.s[k] = shade[k][i];
            mote__tint(cx, &tv[i], 1, tv[i]->c.s);
            mote__to_setup(&tv[i]->c, &tv[i]->sv);
        }
}

/* mote__transform of vertices index to index + 3 into tv[0..3]: the clip
 * position, texels, validity, outcode and the quotients x / w and y / w in
 * vectors, each lane the scalar code's operations in the same order, and
 * the snap (mote__v4_snap_by, or per vertex), the fields in and out by
 * rows and the draw's constants splatted once (mote__v4_draw). */
MOTE__VERTEX_INLINE void mote__transform4(mote__ctx *cx, uint32_t index, mote__tvert tv[4])
{
    const mote_vertex *in = &cx->mesh->vertices[index];
    mote__tvert *const out[4] = {&tv[0], &tv[1], &tv[2], &tv[3]};
    mote__v4f p[3], c[4], tex[2] = {mote__v4_splat(0.0f), mote__v4_splat(0.0f)};
    {
        /* rows of position and normal x: the first three columns are p */
        __m128 r0 = mote__row(&in[0]), r1 = mote__row(&in[1]), r2 = mote__row(&in[2]), r3 = mote__row(&in[3]);
        _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
        p[0] = (mote__v4f)r0;
        p[1] = (mote__v4f)r1;
        p[2] = (mote__v4f)r2;
    }
    /* mote__mat4_point's rows */
    const mote__v4_draw *v4 = &cx->v4;
    const mote__v4f *m = v4->mvp;
    for (int row = 0; row < 4; row++)
        c[row] = m[0 * 4 + row] * p[0] + m[1 * 4 + row] * p[1] + m[2 * 4 + row] * p[2] + m[3 * 4 + row];
    mote__v4i invalid = (mote__v4i)mote__v4_splat(0.0f);
    for (int row = 0; row < 4; row++)   /* mote__finite */
        invalid |= (mote__v4i)(((mote__v4u)c[row] & 0x7f800000u) == 0x7f800000u);
    if (cx->rs->tex != MOTE__TEX_NONE) {
        /* rows of normal y and z, u, v: u and v are the last two columns */
        const __m128 r0 = mote__row(in[0].normal + 1), r1 = mote__row(in[1].normal + 1);
        const __m128 r2 = mote__row(in[2].normal + 1), r3 = mote__row(in[3].normal + 1);
        const __m128 t01 = _mm_unpackhi_ps(r0, r1), t23 = _mm_unpackhi_ps(r2, r3);
        mote__v4f u = (mote__v4f)_mm_movelh_ps(t01, t23), v = (mote__v4f)_mm_movehl_ps(t23, t01);
        u = u * v4->uscale + v4->uoff;
        v = v * v4->vscale + v4->voff;
        if (cx->mesh->material.v_origin_bottom)
            v = 1.0f - v;
        tex[0] = u * v4->tex_w;
        tex[1] = v * v4->tex_h;
        /* also set for NaN and +-Inf */
        invalid |= ~((tex[0] >= -1e9f) & (tex[0] <= 1e9f) & (tex[1] >= -1e9f) & (tex[1] <= 1e9f));
    }
    /* mote__outcode, from mote__plane_dists */
    const mote__v4f x = c[0], y = c[1], z = c[2], w = c[3];
    const mote__v4f gx = v4->guard_x * w, gy = v4->guard_y * w;
    const mote__v4i oc = ((z < 0.0f) & 1) | (((w - z) < 0.0f) & 2) | (((x + gx) < 0.0f) & 4)
                       | (((gx - x) < 0.0f) & 8) | (((y + gy) < 0.0f) & 16) | (((gy - y) < 0.0f) & 32)
                       | ((x > w) & 0x100) | ((x < -w) & 0x200) | ((y > w) & 0x400) | ((y < -w) & 0x800);
    /* mote__snap's quotients */
    const mote__v4f nx = x / w, ny = -(y / w);
    /* the clip position; the shade (the material colour until lit) and u */
    mote__store_rows(out, offsetof(mote__tvert, c), x, y, z, w);
    mote__store_rows(out, offsetof(mote__tvert, c.s), v4->color[0], v4->color[1], v4->color[2], tex[0]);
    for (int i = 0; i < 4; i++)
        tv[i].c.v = tex[1][i];
#if MOTE__VECTOR_SNAP
    mote__v4i xok, yok;
    const mote__v4i sx = mote__v4_snap_by(nx, v4->snap_h[0], v4->snap_hi[0], v4->snap_lim, &xok);
    const mote__v4i sy = mote__v4_snap_by(ny, v4->snap_h[1], v4->snap_hi[1], v4->snap_lim, &yok);
    const mote__v4i snapped = (w > 0.0f) & xok & yok;
    /* state (1 valid, 2 invalid), ready (0) and outcode in one int each,
     * the index, and X and Y, which are read only where the outcode says
     * they snapped (so a lane that did not keeps whatever it got) */
    const mote__v4i no_snap = ((oc & MOTE__OC_CLIP) == 0) & ~snapped & MOTE__OC_NO_SNAP;
    const mote__v4i code = (invalid & MOTE__OC_INVALID) | (~invalid & (oc | no_snap));
    const mote__v4i head = (1 - invalid) | (code << 16);
    const mote__v4i idx = (int32_t)index + (mote__v4i){0, 1, 2, 3};
    mote__store_rows(out, 0, (mote__v4f)head, (mote__v4f)idx, (mote__v4f)sx, (mote__v4f)sy);
#else
    for (int i = 0; i < 4; i++) {
        mote__tvert *t = &tv[i];
        t->index = index + (uint32_t)i;
        t->ready = false;
        t->state = invalid[i] ? 2 : 1;
        t->outcode = MOTE__OC_INVALID;
        if (!invalid[i]) {
            unsigned code = (unsigned)oc[i];
            if (!(code & MOTE__OC_CLIP) && !(w[i] > 0.0f && mote__snap_ndc(cx, nx[i], ny[i], &t->X, &t->Y)))
                code |= MOTE__OC_NO_SNAP;
            t->outcode = (uint16_t)code;
        }
    }
#endif
}
#endif

#if MOTE__VECTOR_VERTEX
/* cx->v4's part for mote__transform4, from the rest of cx; set once the
 * draw has four vertices to transform, so that a draw of fewer (a
 * one-triangle mesh) does not pay for it */
static void mote__v4_transform_init(mote__ctx *cx)
{
    mote__v4_draw *v4 = &cx->v4;
    for (int k = 0; k < 16; k++)
        v4->mvp[k] = mote__v4_splat(cx->mvp[k]);
    v4->uscale = mote__v4_splat(cx->uscale);
    v4->vscale = mote__v4_splat(cx->vscale);
    v4->uoff = mote__v4_splat(cx->uoff);
    v4->voff = mote__v4_splat(cx->voff);
    v4->tex_w = mote__v4_splat(cx->tex_w);
    v4->tex_h = mote__v4_splat(cx->tex_h);
    v4->guard_x = mote__v4_splat(cx->guard_x);
    v4->guard_y = mote__v4_splat(cx->guard_y);
    for (int c = 0; c < 3; c++)
        v4->color[c] = mote__v4_splat(cx->color[c]);
    const mote_device *dev = cx->dev;
    const int F = dev->desc.subpixel_bits;
    const int32_t h[2] = {dev->desc.width << (F - 1), dev->desc.height << (F - 1)};
    const int32_t lim = (int32_t)1 << (MOTE_GUARD_BITS + 1 + F);
    for (int a = 0; a < 2; a++) {
        v4->snap_h[a] = _mm_set1_pd((double)h[a]);
        v4->snap_hi[a] = (mote__v4i){h[a], h[a], h[a], h[a]};
    }
    v4->snap_lim = (mote__v4i){lim, lim, lim, lim};
}

/* cx->v4's part for mote__finish4, from the rest of cx and the frame's
 * lights; set by the draws that finish vertices in fours */
void mote__v4_light_init(mote__ctx *cx)
{
    mote__v4_draw *v4 = &cx->v4;
    for (int k = 0; k < 16; k++)
        v4->world[k] = mote__v4_splat(cx->world[k]);
    for (int k = 0; k < 9; k++)
        v4->nrm[k] = mote__v4_splat(cx->nrm[k]);
    for (int c = 0; c < 3; c++)
        v4->color[c] = mote__v4_splat(cx->color[c]);
    mote__v4_lights_prepare(&v4->lights, cx->dev, cx->color, cx->emissive, cx->d.lights_off);
}
#endif

/* The vertices [first, end) of a full cache, transformed (not finished):
 * four at a time where the host has vectors. */
void mote__transform_range(mote__ctx *cx, mote__tvert *tv, uint32_t first, uint32_t end)
{
    uint32_t i = first;
#if MOTE__VECTOR_VERTEX
    /* (a compact mesh's vertices are not rows of floats) */
    if (i + 4 <= end && !cx->mesh->compact)
        mote__v4_transform_init(cx);
    for (; i + 4 <= end && !cx->mesh->compact; i += 4)
        mote__transform4(cx, i, &tv[i]);
#endif
    for (; i < end; i++)
        mote__transform(cx, i, &tv[i]);
}

/* A vertex transformed and, when valid, finished at once (an invalid one
 * is never drawn, nor converts). */
static void mote__transform_finished(mote__ctx *cx, uint32_t index, mote__tvert *tv)
{
    mote__transform(cx, index, tv);
    if (tv->state == 1)
        mote__finish(cx, tv);
}

/* The full cache is filled before the draw's triangles and finished on
 * use; the small one is filled and finished on demand (its entries are
 * copied and may be evicted by the next lookup, so finishing later would
 * not stick). */
mote__tvert *mote__vertex(mote__ctx *cx, uint32_t index)
{
    if (!cx->cache_mask)
        return &cx->cache[index];
    mote__tvert *tv = &cx->cache[index & cx->cache_mask];
    if (tv->state == 0 || tv->index != index)
        mote__transform_finished(cx, index, tv);
    return tv;
}
