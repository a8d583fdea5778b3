/*
 * geometry.c - the vertex stage of one draw: transform, light, clip, snap,
 * cull, and hand each surviving triangle to setup and then to the sink
 * (rasterise now, or bin for mote_end).
 */
#include "internal.h"

/* Lighting, snapping and the conversion to setup's units, inlined into
 * each vertex's path in speed builds, and a triangle's culling and
 * emission into each triangle's: GCC kept them as calls, and the dense
 * grid ran 2% and 1% faster without them. Size builds keep one copy. */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define MOTE__VERTEX_INLINE static inline __attribute__((always_inline))
#else
#define MOTE__VERTEX_INLINE static
#endif

/* A transformed vertex as cached per draw, with what every triangle using
 * it would otherwise recompute per corner: its outcode and, when it is
 * inside every clip plane, its snapped screen position. */
typedef struct mote__tvert {
    /* small fields first, within reach of Thumb-1's short load offsets */
    uint8_t state;                /* 0 empty, 1 valid, 2 invalid (NaN/Inf) */
    bool ready;                   /* c.s is lit and sv set (see mote__finish) */
    uint16_t outcode;             /* see mote__outcode; MOTE__OC_INVALID alone when invalid */
    uint32_t index;
    int32_t X, Y;                 /* snapped; set when outcode has no clip bit and no MOTE__OC_NO_SNAP */
    mote__cvert c;
    float world[3];               /* lit draws, once ready; flat shading's (mote__finish4 leaves it) */
    float normal[3];              /* world-space, normalised; likewise */
    mote__svert sv;               /* c in setup's units, once ready */
} mote__tvert;

/* On SSE2 hosts a full cache is transformed four vertices at a time
 * (mote__transform4) and lit Gouraud vertices are finished four at a time
 * (mote__finish4): GCC's vector types, each lane the same float
 * operations in the same order as the scalar code, so the same bits. */
#if defined(__SSE2__) && defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define MOTE__VECTOR_VERTEX 1
#else
#define MOTE__VECTOR_VERTEX 0
#endif
struct mote__lit_queue;

#if MOTE__VECTOR_VERTEX
#include <emmintrin.h>
typedef float mote__v4f __attribute__((vector_size(16)));
typedef int32_t mote__v4i __attribute__((vector_size(16)));
typedef uint32_t mote__v4u __attribute__((vector_size(16)));

/* What the four-vertex code reads of a draw, each value in all four
 * lanes (mote__v4_transform_init, mote__v4_light_init): an operand each,
 * where a float splatted in every call took two instructions, some 60 a
 * call of mote__transform4 or mote__finish4. The lights are those that
 * light (mote__light_terms), in order. */
typedef struct mote__v4_light {
    mote_light_type type;
    bool positional;              /* point or spot: shines from at */
    int index;                    /* in the frame's lights (its falloff) */
    mote__v4f at[3];              /* point: its position; else the direction toward the light */
    mote__v4f kcol[3];            /* intensity x colour */
    mote__v4f k, col[3], ground[3];   /* hemispheric */
} mote__v4_light;

typedef struct mote__v4_draw {
    mote__v4f mvp[16], world[16], nrm[9];
    mote__v4f uscale, vscale, uoff, voff, tex_w, tex_h;
    mote__v4f guard_x, guard_y, color[3], emissive[3], ambient[3];
    __m128d snap_h[2];            /* the snap's h of x and y (mote__v4_snap_by) */
    mote__v4i snap_hi[2], snap_lim;  /* h as an int; the snap's limit */
    int lights;
    mote__v4_light light[MOTE_MAX_LIGHTS];
} mote__v4_draw;
#endif

/* Direct-mapped vertex cache used without an arena (a power of two; each
 * entry is about 120 bytes of stack). */
#ifndef MOTE_VERTEX_CACHE
#define MOTE_VERTEX_CACHE 32
#endif
#define MOTE__SMALL_CACHE MOTE_VERTEX_CACHE

/* Scalars first: Thumb-1 loads reach only small offsets, so this order
 * keeps the M0+ code shorter. */
typedef struct mote__ctx {
    mote_device *dev;
    const mote_mesh *mesh;
    mote__raster_state *rs;
    mote__tvert *cache;
    uint32_t cache_mask;          /* 0: full cache indexed by vertex, filled up front */
    bool lit, flat;
    bool cull_cw, cull_ccw;       /* which screen windings are culled */
    float guard_x, guard_y;       /* guard band in NDC units */
    float color[3];               /* material colour 0..1 */
    float emissive[3];            /* the material's emissive colour 0..1 (lit draws add it) */
    float uscale, vscale, uoff, voff;
    float tex_w, tex_h;
    mote__sink_kind sink;
    const mote__target *tg;
    mote__rect region;
    mote_draw_desc d;
    float nrm[9], mvp[16], world[16];
    struct mote__lit_queue *queue; /* not NULL: front faces wait for their vertices (MOTE__VECTOR_VERTEX) */
    unsigned char *band_range;    /* the first band: the triangle's range of bands to widen */
#if MOTE__VECTOR_VERTEX
    mote__v4_draw v4;             /* last: mote__draw_context leaves it to the code that reads it */
#endif
} mote__ctx;

/* ---- lighting ------------------------------------------------------------ */

/* What lighting takes of light l: its colour (white when unset), its
 * intensity (1 when unset) and the sign that turns a directional or
 * hemispheric light's direction toward the light. False for a type that
 * lights nothing. */
MOTE__VERTEX_INLINE bool mote__light_terms(const mote_light *l, float col[3], float *k, float *s)
{
    if (l->type != MOTE_LIGHT_POINT && l->type != MOTE_LIGHT_DIRECTIONAL && l->type != MOTE_LIGHT_HEMISPHERIC
        && !(MOTE_ENABLE_LIGHT_FALLOFF && l->type == MOTE_LIGHT_SPOT))
        return false;
    memcpy(col, l->color, 3 * sizeof *col);
    if (mote__zero3(col))
        col[0] = col[1] = col[2] = 1.0f;
    *k = mote__or(l->intensity, 1.0f);
    *s = l->type == MOTE_LIGHT_DIRECTIONAL ? -1.0f : 1.0f;
    return true;
}

/* Whether a light shines from its position (else along its direction). */
MOTE__VERTEX_INLINE bool mote__positional(const mote_light *l)
{
    return l->type == MOTE_LIGHT_POINT || (MOTE_ENABLE_LIGHT_FALLOFF && l->type == MOTE_LIGHT_SPOT);
}

#if MOTE_ENABLE_LIGHT_FALLOFF
/* x^e for x in [0, 1] and e >= 0, as 2^(e log2 x), in float operations of
 * a fixed order (libm's powf differs between targets); relative error
 * about 1e-6. */
static float mote__powf01(float x, float e)
{
    if (!(x > 0.0f))
        return e > 0.0f ? 0.0f : 1.0f;
    if (!(e > 0.0f) || x >= 1.0f)
        return 1.0f;              /* e NaN: a cone without falloff */
    /* x = m 2^ex with m in [sqrt(1/2), sqrt(2)); log2 m = 2 atanh(t) / ln 2,
     * t = (m - 1) / (m + 1), |t| < 0.172 */
    uint32_t b = mote__float_bits(x);
    int ex = (int)(b >> 23) - 127;
    if (ex == -127)               /* subnormal: as good as 0 for light */
        return 0.0f;
    union { float f; uint32_t u; } m;
    m.u = (b & 0x007fffffu) | 0x3f800000u;
    if (m.f > 1.41421356f) {
        m.f *= 0.5f;
        ex++;
    }
    float t = (m.f - 1.0f) / (m.f + 1.0f), t2 = t * t;
    float series = 1.0f + t2 * (1.0f / 3 + t2 * (1.0f / 5 + t2 * (1.0f / 7 + t2 * (1.0f / 9))));
    float y = e * ((float)ex + 2.88539008f * t * series);   /* e log2 x < 0, or -inf */
    if (y < -126.0f)
        return 0.0f;
    /* 2^y = 2^i 2^f, i = round(y), |f| <= 1/2: e^(f ln 2) by its series */
    int i = (int)(y - 0.5f);
    i += (y - (float)i) >= 0.5f;
    float g = (y - (float)i) * 0.693147181f;
    float p = 1.0f + g * (1.0f + g * (0.5f + g * (1.0f / 6 + g * (1.0f / 24 + g * (1.0f / 120 + g * (1.0f / 720))))));
    union { float f; uint32_t u; } scale;
    scale.u = (uint32_t)(i + 127) << 23;
    return p * scale.f;
}

/* Babylon.js's default falloff of the frame's light i, a point or spot
 * light (StandardMaterial: max(0, 1 - distance / range); a spot light's
 * cos(angle to its axis), 0 outside the cone and raised to its exponent
 * inside), for L from the surface point to the light and inv = 1 / |L| as
 * the lighting took it. Scalar for both lighting paths (mote__light4 calls
 * it per lane), so the two give the same bits. */
static float mote__falloff(const mote_device *dev, int i, const float L[3], float inv)
{
    const mote_light *l = &dev->frame.lights[i];
    const float *cone = dev->spot_cone[i];   /* mote_begin's */
    float att = 1.0f;
    if (l->range > 0.0f) {
        att = 1.0f - mote__dot3(L, L) * inv / l->range;
        att = att > 0.0f ? att : 0.0f;
    }
    if (l->type == MOTE_LIGHT_SPOT) {
        float c = -(mote__dot3(l->direction, L) * cone[0]) * inv;
        c = c > 0.0f ? c : 0.0f;
        if (!(c >= cone[1]))
            return 0.0f;
        att *= mote__powf01(c, l->spot_exponent);
    }
    return att;
}

static bool mote__has_falloff(const mote_light *l)
{
    return l->type == MOTE_LIGHT_SPOT || (l->type == MOTE_LIGHT_POINT && l->range > 0.0f);
}
#endif

MOTE__VERTEX_INLINE void mote__light(const mote__ctx *cx, const float p[3], const float n[3], float out[3])
{
    const mote_frame_desc *f = &cx->dev->frame;
    float acc[3] = {f->ambient[0], f->ambient[1], f->ambient[2]};
    for (int i = 0; i < f->light_count && i < MOTE_MAX_LIGHTS; i++) {
        const mote_light *l = &f->lights[i];
        float col[3], k, s, L[3];
        if (!mote__light_terms(l, col, &k, &s))
            continue;
        for (int c = 0; c < 3; c++)
            L[c] = mote__positional(l) ? l->position[c] - p[c] : s * l->direction[c];
        float inv = mote__rsqrtf(mote__dot3(L, L)), ndl = mote__dot3(n, L) * inv;
        if (l->type == MOTE_LIGHT_HEMISPHERIC) {
            float w = 0.5f + 0.5f * ndl;
            for (int c = 0; c < 3; c++)
                acc[c] += k * (col[c] * w + l->ground_color[c] * (1.0f - w));
        } else if (ndl > 0.0f) {
            float att = 1.0f;     /* times 1: the same bits as without */
#if MOTE_ENABLE_LIGHT_FALLOFF
            if (mote__has_falloff(l))
                att = mote__falloff(cx->dev, i, L, inv);
#endif
            for (int c = 0; c < 3; c++)
                acc[c] += k * col[c] * ndl * att;
        }
    }
    /* the material colour times the lights, plus its emissive colour,
     * then clamped: Babylon.js's StandardMaterial, clamp(diffuseBase x
     * diffuseColor + emissive + ambient) */
    for (int c = 0; c < 3; c++) {
        float v = acc[c] * cx->color[c];
#if MOTE_ENABLE_EMISSIVE
        v += cx->emissive[c];
#endif
        out[c] = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; /* also maps NaN to 0 */
    }
}

static void mote__normalize(float v[3])
{
    float k = mote__rsqrtf(mote__dot3(v, v));
    v[0] *= k;
    v[1] *= k;
    v[2] *= k;
}

/* ---- vertex colours -------------------------------------------------------- */

/* s x the mean colour of n vertices (r, g, b; 255 = 1): one vertex's own,
 * or a flat triangle's three */
static void mote__tint(const mote__ctx *cx, mote__tvert *const tv[], int n, float s[3])
{
    for (int c = 0; c < 3; c++) {
        unsigned sum = 0;
        for (int i = 0; i < n; i++)
            sum += (&cx->mesh->colors[tv[i]->index].r)[c];
        s[c] *= (float)sum / ((float)n * 255.0f);
    }
}

/* ---- clipping ------------------------------------------------------------ */

#define MOTE__CLIP_PLANES 6
#define MOTE__MAX_POLY (3 + MOTE__CLIP_PLANES)

/* Signed distances to the clip planes (inside >= 0). */
static void mote__plane_dists(const mote__ctx *cx, const mote__cvert *v, float d[MOTE__CLIP_PLANES])
{
    float gx = cx->guard_x * v->w, gy = cx->guard_y * v->w;
    d[0] = v->z;                  /* near: z >= 0 */
    d[1] = v->w - v->z;           /* far: z <= w */
    d[2] = v->x + gx;             /* guard band left */
    d[3] = gx - v->x;             /* right */
    d[4] = v->y + gy;             /* bottom */
    d[5] = gy - v->y;             /* top */
}

static float mote__plane_dist(const mote__ctx *cx, const mote__cvert *v, int p)
{
    float d[MOTE__CLIP_PLANES];
    mote__plane_dists(cx, v, d);
    return d[p];
}

/* every field of a vertex, as one array of floats */
#define MOTE__CVERT_FLOATS (sizeof(mote__cvert) / sizeof(float))
typedef char mote__cvert_is_floats[sizeof(mote__cvert) == 9 * sizeof(float) ? 1 : -1];

static void mote__lerp(const mote__cvert *a, const mote__cvert *b, float t, mote__cvert *out)
{
    float fa[MOTE__CVERT_FLOATS], fb[MOTE__CVERT_FLOATS];
    memcpy(fa, a, sizeof fa);
    memcpy(fb, b, sizeof fb);
    for (size_t k = 0; k < MOTE__CVERT_FLOATS; k++)
        fa[k] += (fb[k] - fa[k]) * t;
    memcpy(out, fa, sizeof fa);
}

/* Puts a vertex made by clipping against plane p exactly on it. The
 * interpolation alone can miss a guard-band plane by more than the guard
 * band when the edge runs from far outside (beyond about 1e10 pixels in
 * float), and the vertex would then fail to snap, or a later plane would
 * drop the polygon. Each plane's distance is then exactly 0. */
MOTE__SPEED_INLINE void mote__on_plane(const mote__ctx *cx, mote__cvert *v, int p)
{
    /* near z = 0, far z = w, then x and y at -+ the guard band */
    float g = p == 1 ? 1.0f : p == 0 ? 0.0f : p < 4 ? cx->guard_x : cx->guard_y;
    float *c = p < 2 ? &v->z : p < 4 ? &v->x : &v->y;
    *c = (p & 1 ? g : -g) * v->w;
}

/* Sutherland-Hodgman in homogeneous space. orig[i] tells whether the edge
 * from vertex i to i+1 is part of the original triangle (wireframe draws
 * only those). The intersection is always computed from the inside vertex
 * toward the outside one, so both triangles sharing an edge get the same
 * point. Returns the vertex count (0 when nothing is left). */
static int mote__clip(const mote__ctx *cx, mote__cvert *poly, bool *orig, int n, unsigned planes)
{
    mote__cvert tmp[MOTE__MAX_POLY];
    bool torig[MOTE__MAX_POLY];
    for (int p = 0; p < MOTE__CLIP_PLANES && n > 0; p++) {
        if (!(planes & (1u << p)))
            continue;
        int m = 0;
        for (int i = 0; i < n; i++) {
            const mote__cvert *a = &poly[i], *b = &poly[(i + 1) % n];
            float da = mote__plane_dist(cx, a, p), db = mote__plane_dist(cx, b, p);
            bool ain = da >= 0.0f, bin = db >= 0.0f;
            /* float rounding can leave the polygon a hair from convex,
             * and a plane may then cut it more than twice: past
             * MOTE__MAX_POLY vertices, an input vertex is dropped too */
            if (ain && m < MOTE__MAX_POLY) {
                tmp[m] = *a;
                torig[m++] = orig[i];
            }
            if (ain != bin && m < MOTE__MAX_POLY) {
                if (ain)
                    mote__lerp(a, b, da / (da - db), &tmp[m]);
                else
                    mote__lerp(b, a, db / (db - da), &tmp[m]);
                mote__on_plane(cx, &tmp[m], p);
                torig[m++] = ain ? false : orig[i];
            }
        }
        n = m;
        memcpy(poly, tmp, (size_t)n * sizeof *poly);
        if (MOTE_ENABLE_LINES)    /* the edges' origins: only wireframe reads them */
            memcpy(orig, torig, (size_t)n * sizeof *orig);
    }
    return n;
}

/* Outcode bits: the clip planes a vertex is outside of (0..5), the sides of
 * the viewport proper it is outside of (8..11, for trivial rejection),
 * whether a vertex inside every clip plane failed to snap, and (alone)
 * whether it is invalid (state 2), so that one test of the three
 * vertices' outcodes finds an invalid one. */
#define MOTE__OC_CLIP 0x3fu
#define MOTE__OC_REJECT 0xf3fu
#define MOTE__OC_NO_SNAP 0x1000u
#define MOTE__OC_INVALID 0x2000u

static unsigned mote__outcode(const mote__ctx *cx, const mote__cvert *v)
{
    float d[MOTE__CLIP_PLANES];
    mote__plane_dists(cx, v, d);
    unsigned c = 0;
    for (int p = 0; p < MOTE__CLIP_PLANES; p++)
        c |= (unsigned)(d[p] < 0.0f) << p;
    c |= (unsigned)(v->x > v->w) << 8;
    c |= (unsigned)(v->x < -v->w) << 9;
    c |= (unsigned)(v->y > v->w) << 10;
    c |= (unsigned)(v->y < -v->w) << 11;
    return c;
}

/* ---- snapping ------------------------------------------------------------ */

/* round_half_up(n * h + h) exactly, for a float n and an integer h: the
 * float is split into its 24-bit mantissa and exponent, so the product is
 * an exact 64-bit integer; no double arithmetic (costly without an FPU) and
 * the same answer on every target. False when |n * h| is out of range. */
static bool mote__snap_axis(float n, int64_t h, int64_t lim, int32_t *out)
{
    union { float f; uint32_t u; } b;
    b.f = n;
    /* |n| = m * 2^-k with the 24-bit mantissa m; zero and denormals (exponent
     * field 0) give k = 150, far enough to round to 0 like any k >= 62 */
    int k = 150 - (int)((b.u >> 23) & 0xff);
    int64_t p = (int64_t)((b.u & 0x7fffffu) | 0x800000u) * h;  /* < 2^24 * 2^20 */
    int64_t neg = (int64_t)(b.u >> 31);
    int64_t v;                    /* round_half_up(n * h) */
    if (k > 0) {
        k = k < 62 ? k : 62;
        /* half up for n >= 0; for n < 0, -round_half_down(|n| h), hence the -1 */
        int64_t m = (p + ((int64_t)1 << (k - 1)) - neg) >> k;
        v = neg ? -m : m;
    } else {
        if (k < -16)
            return false;         /* |n| >= 2^40: far outside the guard band */
        v = neg ? -(p << -k) : p << -k;
    }
    v += h;
    if (v <= -lim || v >= lim)
        return false;
    *out = (int32_t)v;
    return true;
}

/* The snapped position of normalised device coordinates nx = x / w and
 * ny = -(y / w) */
MOTE__VERTEX_INLINE bool mote__snap_ndc(const mote__ctx *cx, float nx, float ny, int32_t *X, int32_t *Y)
{
    const mote_device *dev = cx->dev;
    int F = dev->desc.subpixel_bits;
    int64_t hw = (int64_t)dev->desc.width << (F - 1), hh = (int64_t)dev->desc.height << (F - 1);
    /* the guard band bounds these; the limit only catches float rounding */
    int64_t lim = (int64_t)1 << (MOTE_GUARD_BITS + 1 + F);
    return mote__snap_axis(nx, hw, lim, X) && mote__snap_axis(ny, hh, lim, Y);
}

MOTE__VERTEX_INLINE bool mote__snap(const mote__ctx *cx, const mote__cvert *v, int32_t *X, int32_t *Y)
{
    return v->w > 0.0f && mote__snap_ndc(cx, v->x / v->w, -(v->y / v->w), X, Y);
}

/* ---- setup's units -------------------------------------------------------- */

/* A colour in [0,1] as 2^24 fixed point; clipping's lerp may overshoot by an ulp. */
static void mote__shade_fixed(const float s[3], int32_t out[3])
{
    for (int c = 0; c < 3; c++) {
        int32_t v = (int32_t)(s[c] * (float)MOTE__SHADE_ONE + 0.5f);
        out[c] = v < 0 ? 0 : v > MOTE__SHADE_ONE ? MOTE__SHADE_ONE : v;
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
MOTE__VERTEX_INLINE void mote__to_setup(const mote__cvert *v, mote__svert *out)
{
    mote__shade_fixed(v->s, out->s);
    for (int k = 0; k < 2; k++)
        out->texel[k] = mote__round_scaled(k ? v->v : v->u, 16);
    /* clipping's float rounding can leave z/w a hair outside [0, 1]; NaN
     * (0/0, at a vertex behind the eye, which clipping drops) gives 0 */
    float d = v->z / v->w;
    out->depth = d > 0.0f ? (d < 1.0f ? d : 1.0f) : 0.0f;
    out->z = (int32_t)mote__round_scaled(out->depth * (float)MOTE__DEPTH_MAX, 0);
    out->w = v->w;
}

/* ---- vertices ------------------------------------------------------------ */

static void mote__transform(mote__ctx *cx, uint32_t index, mote__tvert *tv)
{
    const mote_vertex *in = &cx->mesh->vertices[index];
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

/* What only drawn triangles need of a vertex: its world position and
 * normal (lighting's inputs, read here by Gouraud and after this by flat
 * shading), Gouraud lighting, the costliest per-vertex step, and the
 * conversion to setup's units. None of it can make a vertex invalid, so
 * with the full cache it waits until a triangle using the vertex survives
 * culling: about half of a closed mesh's vertices are only on back faces
 * (grid, tex-nearest: 11.6 -> 10.8 ms of draws for the lighting; the world
 * position and normal too: 1.5% fewer instructions). */
static void mote__finish(const mote__ctx *cx, mote__tvert *tv)
{
    if (tv->ready)
        return;
    tv->ready = true;
    if (cx->lit) {
        const mote_vertex *in = &cx->mesh->vertices[tv->index];
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
            mote__light(cx, tv->world, tv->normal, tv->c.s);
        if (MOTE_ENABLE_VERTEX_COLORS && cx->mesh->colors)
            mote__tint(cx, &tv, 1, tv->c.s);
    }
    mote__to_setup(&tv->c, &tv->sv);
}

#if MOTE__VECTOR_VERTEX

static inline mote__v4f mote__v4_splat(float x)
{
    return (mote__v4f){x, x, x, x};
}

/* Four vertices' fields in and out by rows: a row is 16 bytes of one
 * vertex, four rows turned into four lanes and back (_MM_TRANSPOSE4_PS,
 * which moves bits and computes nothing). Where GCC moved lanes one float
 * at a time, about 40 instructions a vertex went into loading and storing
 * (the dense grid transforms 89,000 vertices a frame and lights 52,000).
 * These are the fields read and written as rows. */
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

/* a where m is set, b elsewhere, bit for bit */
static inline mote__v4f mote__v4_select(mote__v4i m, mote__v4f a, mote__v4f b)
{
    return (mote__v4f)((m & (mote__v4i)a) | (~m & (mote__v4i)b));
}

static inline mote__v4f mote__v4_dot3(const mote__v4f a[3], const mote__v4f b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* mote__rsqrtf in each lane */
static inline mote__v4f mote__v4_rsqrt(mote__v4f x)
{
    const mote__v4u bits = (mote__v4u)x;
    const mote__v4i finite = (mote__v4i)(bits - 1u < 0x7f7fffffu);   /* mote__positive_finite */
    mote__v4f y = (mote__v4f)(0x5f375a86u - (bits >> 1)), h = 0.5f * x;
    for (int i = 0; i < 3; i++)
        y = y * (1.5f - h * y * y);
    return (mote__v4f)(finite & (mote__v4i)y);
}

/* mote__light in each lane: p and n the lanes' world positions and
 * normals; the lights' terms as mote__v4_light_init took them (k x col is
 * the product that mote__light's k * col[c] * ndl starts with) */
static void mote__light4(const mote__ctx *cx, const mote__v4f p[3], const mote__v4f n[3], mote__v4f out[3])
{
    const mote__v4_draw *v4 = &cx->v4;
    mote__v4f acc[3] = {v4->ambient[0], v4->ambient[1], v4->ambient[2]};
    for (int i = 0; i < v4->lights; i++) {
        const mote__v4_light *l = &v4->light[i];
        mote__v4f L[3];
        for (int c = 0; c < 3; c++)
            L[c] = l->positional ? l->at[c] - p[c] : l->at[c];
        mote__v4f inv = mote__v4_rsqrt(mote__v4_dot3(L, L)), ndl = mote__v4_dot3(n, L) * inv;
        if (l->type == MOTE_LIGHT_HEMISPHERIC) {
            mote__v4f w = 0.5f + 0.5f * ndl;
            for (int c = 0; c < 3; c++)
                acc[c] += l->k * (l->col[c] * w + l->ground[c] * (1.0f - w));
        } else {
            const mote__v4i lit = ndl > 0.0f;
            mote__v4f att = mote__v4_splat(1.0f);
#if MOTE_ENABLE_LIGHT_FALLOFF
            if (mote__has_falloff(&cx->dev->frame.lights[l->index]))
                for (int j = 0; j < 4; j++) {
                    const float Lj[3] = {L[0][j], L[1][j], L[2][j]};
                    att[j] = mote__falloff(cx->dev, l->index, Lj, inv[j]);
                }
#endif
            for (int c = 0; c < 3; c++)
                acc[c] = mote__v4_select(lit, acc[c] + l->kcol[c] * ndl * att, acc[c]);
        }
    }
    for (int c = 0; c < 3; c++) {
        mote__v4f v = acc[c] * v4->color[c] + v4->emissive[c];
        out[c] = mote__v4_select(v > 0.0f, mote__v4_select(v < 1.0f, v, mote__v4_splat(1.0f)), mote__v4_splat(0.0f));
    }
}

/* mote__to_setup's texels of c: round(x 2^16), halves away from zero,
 * as mote__round_scaled(x, 16) gives, for u and v at once. x 2^16 is
 * exact in double, and so is x 2^16 +- 1/2 where |x 2^16| >= 1/2 (at most
 * 25 significant bits); below that the sum stays inside (-1, 1) and
 * truncates to 0 as it should. Valid texels are within 1e9, so
 * |x 2^16| < 2^46. Compared with mote__round_scaled on every float within
 * 1e9: none differ. With the depth below, some 70 instructions a vertex
 * fewer than mote__round_scaled's three calls. (The 64-bit conversion is
 * x86-64's.) */
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
static void mote__finish4(const mote__ctx *cx, mote__tvert *const tv[4])
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
    mote__light4(cx, world, normal, shade);
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

/* mote__snap_axis in each lane, *ok where it succeeds. n h (a 24-bit
 * mantissa times h <= 2^23) is exact in double, and so is n h + 1/2 while
 * |n h| < 2^30, so floor(n h + 1/2) is the scalar's rounding (half up),
 * found by truncation and a correction; beyond 2^30 (and for NaN) the
 * scalar fails too, its limit being below. */
#if MOTE_GUARD_BITS + 1 + 8 <= 29 && MOTE_MAX_SIZE <= 65536
#define MOTE__VECTOR_SNAP 1
/* with h as a double and as an int, and lim, in every lane */
static inline mote__v4i mote__v4_snap_by(mote__v4f n, __m128d hd, mote__v4i hi, mote__v4i lim, mote__v4i *ok)
{
    const __m128d half = _mm_set1_pd(0.5), range = _mm_set1_pd(1073741824.0);
    const __m128 nf = (__m128)n;
    const __m128d y[2] = {_mm_add_pd(_mm_mul_pd(_mm_cvtps_pd(nf), hd), half),
                          _mm_add_pd(_mm_mul_pd(_mm_cvtps_pd(_mm_movehl_ps(nf, nf)), hd), half)};
    __m128i floor2[2], in2[2];
    for (int i = 0; i < 2; i++) {
        const __m128i t = _mm_cvttpd_epi32(y[i]);   /* toward zero, in lanes 0 and 1 */
        const __m128d magnitude = _mm_andnot_pd(_mm_set1_pd(-0.0), y[i]);
        /* 64-bit masks to the 32-bit lanes 0 and 1 */
        const __m128i below = _mm_shuffle_epi32(_mm_castpd_si128(_mm_cmplt_pd(y[i], _mm_cvtepi32_pd(t))), 0x08);
        in2[i] = _mm_shuffle_epi32(_mm_castpd_si128(_mm_cmplt_pd(magnitude, range)), 0x08);
        floor2[i] = _mm_add_epi32(t, below);          /* below: -1 */
    }
    const __m128i v = _mm_add_epi32(_mm_unpacklo_epi64(floor2[0], floor2[1]), (__m128i)hi);
    const __m128i in = _mm_unpacklo_epi64(in2[0], in2[1]);
    const __m128i nlim = _mm_sub_epi32(_mm_setzero_si128(), (__m128i)lim);
    *ok = (mote__v4i)_mm_and_si128(in, _mm_and_si128(_mm_cmpgt_epi32(v, nlim), _mm_cmplt_epi32(v, (__m128i)lim)));
    return (mote__v4i)v;
}
#else
#define MOTE__VECTOR_SNAP 0
#endif

/* mote__transform of vertices index to index + 3 into tv[0..3]: the clip
 * position, texels, validity, outcode and the quotients x / w and y / w in
 * vectors, each lane the scalar code's operations in the same order, and
 * the snap (mote__v4_snap_by, or per vertex). With the vector snap about
 * 130 instructions a vertex instead of 250 (the dense grid transforms
 * 89,000 a frame), and about 80 with the fields in and out by rows and
 * the draw's constants splatted once (mote__v4_draw). */
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
static void mote__v4_light_init(mote__ctx *cx)
{
    mote__v4_draw *v4 = &cx->v4;
    for (int k = 0; k < 16; k++)
        v4->world[k] = mote__v4_splat(cx->world[k]);
    for (int k = 0; k < 9; k++)
        v4->nrm[k] = mote__v4_splat(cx->nrm[k]);
    const mote_frame_desc *f = &cx->dev->frame;
    for (int c = 0; c < 3; c++) {
        v4->color[c] = mote__v4_splat(cx->color[c]);
        v4->emissive[c] = mote__v4_splat(cx->emissive[c]);
        v4->ambient[c] = mote__v4_splat(f->ambient[c]);
    }
    v4->lights = 0;
    for (int i = 0; i < f->light_count && i < MOTE_MAX_LIGHTS; i++) {
        const mote_light *l = &f->lights[i];
        float col[3], k, s;
        if (!mote__light_terms(l, col, &k, &s))
            continue;
        mote__v4_light *o = &v4->light[v4->lights++];
        o->type = l->type;
        o->positional = mote__positional(l);
        o->index = i;
        o->k = mote__v4_splat(k);
        for (int c = 0; c < 3; c++) {
            o->at[c] = mote__v4_splat(o->positional ? l->position[c] : s * l->direction[c]);
            o->kcol[c] = mote__v4_splat(k * col[c]);
            o->col[c] = mote__v4_splat(col[c]);
            o->ground[c] = mote__v4_splat(l->ground_color[c]);
        }
    }
}
#endif

/* The vertices [first, end) of a full cache, transformed (not finished):
 * four at a time where the host has vectors. */
static void mote__transform_range(mote__ctx *cx, mote__tvert *tv, uint32_t first, uint32_t end)
{
    uint32_t i = first;
#if MOTE__VECTOR_VERTEX
    if (i + 4 <= end)
        mote__v4_transform_init(cx);
    for (; i + 4 <= end; i += 4)
        mote__transform4(cx, i, &tv[i]);
#endif
    for (; i < end; i++)
        mote__transform(cx, i, &tv[i]);
}

#if MOTE__VECTOR_VERTEX
/* Whether mote__finish4 can finish this draw's vertices: lit Gouraud ones. */
static bool mote__finish_in_fours(const mote__ctx *cx)
{
    return cx->lit && cx->rs->gouraud;
}
#endif

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
static mote__tvert *mote__vertex(mote__ctx *cx, uint32_t index)
{
    if (!cx->cache_mask)
        return &cx->cache[index];
    mote__tvert *tv = &cx->cache[index & cx->cache_mask];
    if (tv->state == 0 || tv->index != index)
        mote__transform_finished(cx, index, tv);
    return tv;
}

/* ---- triangles ----------------------------------------------------------- */

/* true when a triangle of this signed screen area is culled */
static bool mote__culled(const mote__ctx *cx, int64_t area2)
{
    return area2 > 0 ? cx->cull_cw : cx->cull_ccw;   /* y grows downward */
}

#if MOTE_ENABLE_BINNING && MOTE_SHORTCUTS
/* Where mote__bin_triangle will keep the next triangle: the arena's first
 * free bytes (bin.c allocates from there), when a whole record fits
 * between them and the scratch above; NULL otherwise. Set up there, a
 * binned triangle is not copied (17 fewer instructions a triangle on the
 * dense grid); its record ends where its planes do, and what setup wrote
 * past that is free space again. */
static mote__tri *mote__bin_place(mote_device *dev)
{
    mote__bin *b = &dev->bin;
    return b->top - b->used >= sizeof(mote__tri) ? (mote__tri *)(void *)(b->base + b->used) : NULL;
}
#endif

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

static void mote__emit(mote__ctx *cx, const int32_t X[3], const int32_t Y[3], int64_t area2,
                       const mote__svert *const v[3])
{
    mote_device *dev = cx->dev;
    if (cx->band_range)
        mote__band_note(cx, Y);
    if (dev->desc.triangle_hook) {
        float z[3] = {v[0]->depth, v[1]->depth, v[2]->depth};
        float w[3] = {v[0]->w, v[1]->w, v[2]->w};
        dev->desc.triangle_hook(dev->desc.triangle_hook_user, X, Y, z, w);
    }
    mote__tri local, *t = &local;
#if MOTE_ENABLE_BINNING && MOTE_SHORTCUTS
    if (cx->sink == MOTE__SINK_BIN && !(t = mote__bin_place(dev)))
        t = &local;
#endif
    mote__setup_result set = mote__setup(t, cx->rs, X, Y, area2, v, dev->desc.subpixel_bits,
                                         dev->desc.width, dev->desc.height);
    if (set != MOTE__SETUP_DRAWN) {
        if (set == MOTE__SETUP_EMPTY)
            dev->stats.triangles_degenerate++;
        else
            dev->stats.triangles_clipped_away++;
        return;
    }
    dev->stats.triangles_drawn++;
    dev->stats.triangles_black += t->shade == MOTE__SHADE_BLACK;
    if (!MOTE_ENABLE_BINNING || cx->sink == MOTE__SINK_RASTER) {
        mote__raster_tri(t, cx->tg, cx->region, dev->desc.subpixel_bits);
    } else {
        if (!mote__bin_triangle(dev, t)) {
            if (dev->bin.group) {  /* a group's slice is full: the batch goes serial */
                dev->bin.overflowed = true;
                return;
            }
            /* out of the arena before the flush reuses it */
            if (t != &local) {
                local = *t;
                t = &local;
            }
            /* arena full: draw what is binned, then bin this one afresh */
            mote__bin_flush(dev);
            dev->stats.arena_flushes++;
            mote__raster_state *rs = (mote__raster_state *)mote__bin_alloc(dev, sizeof *rs);
            if (rs) {
                *rs = *cx->rs;
                cx->rs = rs;
                t->rs = rs;
            }
            if (!rs || !mote__bin_triangle(dev, t)) {
                /* a single triangle does not fit: draw it directly */
                mote__target tg;
                mote__counts count = {0, 0};
                mote__full_target(dev, &tg, &count);
                mote__rect all = {0, 0, dev->desc.width, dev->desc.height};
                mote__raster_tri(t, &tg, all, dev->desc.subpixel_bits);
                mote__add_counts(dev, &count);
                mote__bin_mark_all_drawn(dev);   /* not through the tiles */
            }
        }
    }
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
/* Front faces waiting for their vertices: a vertex is marked ready when
 * queued and lit with the next four; the faces queued before then go on,
 * in order, once it is. Faces that clipping cuts wait for none (the queue
 * is emptied first), so triangles reach setup in submission order. A face
 * is its vertices, which hold its snapped corners, and its area. */
#define MOTE__QUEUED_FACES 8
typedef struct mote__lit_queue {
    mote__tvert *batch[4];
    int vertices, faces;
    struct {
        mote__tvert *tv[3];
        int64_t area;
    } face[MOTE__QUEUED_FACES];
} mote__lit_queue;

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
    mote__light(cx, c, n, s);
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
        mote__draw_line(cx->tg, cx->region, X[k] >> F, Y[k] >> F, X[j] >> F, Y[j] >> F, col);
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
 * mote__triangle's arrays and the draw's flags on the stack: about 90
 * instructions a triangle before it reached the queue, against about 55
 * here, for each of the dense grid's 96,600 triangles a frame. */
static void mote__queue_triangles(mote__ctx *cx, const uint32_t *indices, uint32_t first, uint32_t end)
{
    mote_device *dev = cx->dev;
    mote__tvert *const cache = cx->cache;
    const uint32_t nv = cx->mesh->vertex_count;
    for (uint32_t i = first; i < end && !(MOTE_ENABLE_BINNING && dev->bin.overflowed); i++) {
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

/* ---- the draw -------------------------------------------------------------- */

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
          && (t->format == MOTE_FORMAT_RGBA8888 || t->format == MOTE_FORMAT_RGB565
              || t->format == MOTE_FORMAT_GREY8)))
        return false;
    /* texels are read as whole 16- and 32-bit words (a core without
     * unaligned access faults on others), and rows must hold a row */
    const int bpp = mote_format_bytes(t->format);   /* 1, 2 or 4 */
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

#if MOTE_ENABLE_BINNING
size_t mote__vertex_cache_bytes(const mote_mesh *mesh)
{
    size_t bytes = (size_t)mesh->vertex_count * sizeof(mote__tvert);
    return bytes / sizeof(mote__tvert) == mesh->vertex_count ? bytes : 0;   /* 0: overflow */
}
#endif

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
                       : mat->texture->width * mote_format_bytes(mat->texture->format);
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
                               mote__sink_kind sink, const mote__target *tg, mote__rect region,
                               const mote__piece *piece)
{
    /* a draw cut into pieces is counted once, by its first */
    bool first_piece = !MOTE_ENABLE_BINNING || !piece || piece->tri0 == 0;
    dev->stats.draws += first_piece;
    mote__ctx cx;
    mote__raster_state rs_local;
    /* band bins: the first band records where each triangle goes, the
     * others read it (see mote_device_desc.band_bins) */
    mote__draw *rec = sink == MOTE__SINK_RASTER && dev->bands.bins ? dev->bands.draw : NULL;
    const bool recording = rec && dev->bands.index == 0;
    if (recording) {
        rec->band_first = 255;
        rec->band_last = 0;
        rec->band_known = false;
    }
    if (!mote__draw_context(&cx, &rs_local, dev, mesh, desc)) {
        dev->stats.meshes_culled += first_piece;
        if (recording)
            rec->band_known = true;   /* in no band */
        return MOTE_OK;
    }
    cx.sink = sink;
    cx.tg = tg;
    cx.region = region;
    int F = dev->desc.subpixel_bits;
    mote_mode mode = cx.d.mode;

    size_t cache_bytes = 0;
    mote__tvert small_cache[MOTE__SMALL_CACHE];
    if (MOTE_ENABLE_BINNING && sink == MOTE__SINK_BIN) {
        mote__raster_state *rs = (mote__raster_state *)mote__bin_alloc(dev, sizeof *rs);
        if (!rs && dev->bin.group) {
            dev->bin.overflowed = true;
            return MOTE_OK;
        }
        if (!rs) {
            mote__bin_flush(dev);
            rs = (mote__raster_state *)mote__bin_alloc(dev, sizeof *rs);
        }
        if (!rs)
            return MOTE_ERR_OUT_OF_MEMORY;
        *rs = rs_local;
        cx.rs = rs;
        cache_bytes = mote__vertex_cache_bytes(mesh);
        const bool prepared = piece && piece->vertices;
        if (prepared) {
            /* transformed and finished by mote__prepare_vertices, and shared
             * with the draw's other pieces: from here on only read */
            cx.cache = (mote__tvert *)(uintptr_t)piece->vertices;
            cache_bytes = 0;
        } else if (dev->bin.group) {  /* its own cache, so that its slice holds triangles only */
            if (cache_bytes > 0 && cache_bytes <= dev->bin.cache_size)
                cx.cache = (mote__tvert *)(void *)dev->bin.cache;
            cache_bytes = 0;
        } else if (cache_bytes > 0) {
            cx.cache = (mote__tvert *)mote__bin_top_alloc(dev, cache_bytes);
        }
        if (!cx.cache)
            cache_bytes = 0;
        else if (!prepared)
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
                mote__draw_pixel(tg, region, tv->X >> F, tv->Y >> F, cx.d.point_color);
        }
    } else {
        uint32_t tris = mesh->index_count / 3, first = 0;
        if (!mesh->indices)
            tris = 0;
        if (MOTE_ENABLE_BINNING && piece) {
            first = MOTE__MIN(piece->tri0, tris);
            tris = MOTE__MIN(piece->tri1, tris);
        }
        dev->stats.triangles_in += tris - first;
#if MOTE__VECTOR_VERTEX
        /* a full cache this draw fills itself (a shared one is finished
         * already): front faces queue for their vertices, lit in fours */
        mote__lit_queue queue;
        if (mote__finish_in_fours(&cx) && !cx.cache_mask && !(MOTE_ENABLE_BINNING && piece && piece->vertices)) {
            queue.vertices = queue.faces = 0;
            cx.queue = &queue;
            mote__v4_light_init(&cx);
        }
#endif
        uint32_t i = first;
#if MOTE__VECTOR_VERTEX
        if (cx.queue) {
            mote__queue_triangles(&cx, mesh->indices, first, tris);
            mote__queue_flush(&cx);
            i = tris;             /* all done */
        }
#endif
        unsigned char *bins = NULL;
        const bool triangles = mode != MOTE_MODE_POINTS && !(MOTE_ENABLE_LINES && mode == MOTE_MODE_WIREFRAME);
        if (recording && triangles && !cx.queue && first == 0 && tris <= dev->bands.capacity - dev->bands.used) {
            rec->bin_first = dev->bands.used;
            dev->bands.used += tris;
            bins = dev->bands.bins + 2 * (size_t)rec->bin_first;
        } else if (rec && !recording && rec->band_known) {
            bins = dev->bands.bins + 2 * (size_t)rec->bin_first;
        }
        const int band = dev->bands.index;
        for (; i < tris && !(MOTE_ENABLE_BINNING && dev->bin.overflowed); i++) {
            if (bins) {
                unsigned char *range = bins + 2 * (size_t)i;
                if (recording) {
                    range[0] = 255;   /* none until emitted */
                    range[1] = 0;
                    cx.band_range = range;
                } else if (band < range[0] || band > range[1]) {
                    continue;
                }
            }
            mote__triangle(&cx, &mesh->indices[3 * i]);
        }
        if (recording && bins) {
            for (uint32_t k = 0; k < tris; k++) {
                rec->band_first = MOTE__MIN(rec->band_first, bins[2 * k]);
                rec->band_last = MOTE__MAX(rec->band_last, bins[2 * k + 1]);
            }
            rec->band_known = true;
        }
    }
    if (MOTE_ENABLE_BINNING && cache_bytes)
        mote__bin_top_release(dev, cache_bytes);
    return MOTE_OK;
}
