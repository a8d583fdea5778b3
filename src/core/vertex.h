/*
 * vertex.h - what the files of the vertex stage share (draw.c, vertex.c,
 * clip.c, assemble.c): a draw's context, the cached vertex, the light sets
 * (light.h), the four-vertex vector types of SSE2 hosts, and the stage's
 * functions. Not seen by the pixel stage, the binner or the device.
 */
#ifndef MOTE_CORE_VERTEX_H
#define MOTE_CORE_VERTEX_H

#include "internal.h"
#include "light.h"

/* The per-vertex steps inlined into each vertex's path in speed builds
 * (GCC otherwise kept them as calls); size builds keep one copy. */
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

/* the light model's sets (light.h), one float per value */
MOTE__LIGHT_TYPES(float, mote__lights, mote__light_term)

#if MOTE__VECTOR_VERTEX
#include <emmintrin.h>
typedef float mote__v4f __attribute__((vector_size(16)));
typedef int32_t mote__v4i __attribute__((vector_size(16)));
typedef uint32_t mote__v4u __attribute__((vector_size(16)));

/* and in four lanes */
MOTE__LIGHT_TYPES(mote__v4f, mote__v4_lights, mote__v4_light)

/* What the four-vertex code reads of a draw, each value in all four lanes
 * (mote__v4_transform_init, mote__v4_light_init): splatted once a draw
 * rather than in every call. */
typedef struct mote__v4_draw {
    mote__v4f mvp[16], world[16], nrm[9];
    mote__v4f uscale, vscale, uoff, voff, tex_w, tex_h;
    mote__v4f guard_x, guard_y, color[3];
    __m128d snap_h[2];            /* the snap's h of x and y (mote__v4_snap_by) */
    mote__v4i snap_hi[2], snap_lim;  /* h as an int; the snap's limit */
    mote__v4_lights lights;
} mote__v4_draw;

static inline mote__v4f mote__v4_splat(float x)
{
    return (mote__v4f){x, x, x, x};
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
#endif /* MOTE__VECTOR_VERTEX */


/* The vertex cache of a draw without an arena (MOTE_VERTEX_CACHE, mote.h) */
#define MOTE__SMALL_CACHE MOTE_VERTEX_CACHE
typedef char mote__vertex_cache_check[MOTE_VERTEX_CACHE >= 2 && (MOTE_VERTEX_CACHE & (MOTE_VERTEX_CACHE - 1)) == 0
                                      ? 1 : -1];

/* Scalars first: Thumb-1 loads reach only small offsets, so this order
 * keeps the M0+ code shorter. */
typedef struct mote__ctx {
    mote_device *dev;
    const mote_mesh *mesh;
    mote__raster_state *rs;       /* the draw's features (its triangles point at sink->rs) */
    mote__tvert *cache;
    uint32_t cache_mask;          /* 0: full cache indexed by vertex, filled up front */
    bool lit, flat;
    bool cull_cw, cull_ccw;       /* which screen windings are culled */
    float guard_x, guard_y;       /* guard band in NDC units */
    float color[3];               /* material colour 0..1 */
    float emissive[3];            /* the material's emissive colour 0..1 (lit draws add it) */
    bool simplified;              /* a feature asked for, left out of the build: drawn without */
    bool additive;                /* specular or fog: the additive colour c.a is set */
    float spec[3], spec_power;    /* the material's specular colour (0..1) and power */
    bool spec_on, fog_on;         /* what the additive colour holds */
    float uscale, vscale, uoff, voff;
    float tex_w, tex_h;
    mote__sink *sink;             /* where triangles go */
    mote_draw_desc d;
    float nrm[9], mvp[16], world[16];
    struct mote__lit_queue *queue; /* not NULL: front faces wait for their vertices (MOTE__VECTOR_VERTEX) */
    unsigned char *band_bins;     /* band bins of the draw's triangles (see mote__triangles) */
    unsigned char *band_range;    /* the first band: the triangle's range of bands to widen */
    mote__lights lights;          /* lit draws (mote__vertex_begin) */
#if MOTE__VECTOR_VERTEX
    mote__v4_draw v4;             /* last: mote__draw_context leaves it to the code that reads it */
#endif
} mote__ctx;

/* ---- clip.c: clipping and snapping ---------------------------------------- */

#define MOTE__CLIP_PLANES 6
#define MOTE__MAX_POLY (3 + MOTE__CLIP_PLANES)

/* Outcode bits: the clip planes a vertex is outside of (0..5), the sides of
 * the viewport proper it is outside of (8..11, for trivial rejection),
 * whether a vertex inside every clip plane failed to snap, and (alone)
 * whether it is invalid (state 2), so that one test of the three
 * vertices' outcodes finds an invalid one. */
#define MOTE__OC_CLIP 0x3fu
#define MOTE__OC_REJECT 0xf3fu
#define MOTE__OC_NO_SNAP 0x1000u
#define MOTE__OC_INVALID 0x2000u

unsigned mote__outcode(const mote__ctx *cx, const mote__cvert *v);
/* Sutherland-Hodgman in homogeneous space against the planes set in
 * planes; orig[i] tells whether edge i..i+1 is one of the triangle's.
 * Returns the vertex count (0 when nothing is left). */
int mote__clip(const mote__ctx *cx, mote__cvert *poly, bool *orig, int n, unsigned planes);
/* round_half_up(n * h + h) within (-lim, lim), exactly; false outside */
bool mote__snap_axis(float n, int64_t h, int64_t lim, int32_t *out);
/* The snapped position of normalised device coordinates nx = x / w and
 * ny = -(y / w) */
bool mote__snap_ndc(const mote__ctx *cx, float nx, float ny, int32_t *X, int32_t *Y);
bool mote__snap(const mote__ctx *cx, const mote__cvert *v, int32_t *X, int32_t *Y);

/* ---- vertex.c: vertices ---------------------------------------------------- */

/* Sets up what a lit draw's vertices read of the frame's lights. */
void mote__vertex_begin(mote__ctx *cx);
/* The lit colour at world position p with unit normal n (light.h). */
void mote__light_at(const mote__ctx *cx, const float p[3], const float n[3], float out[3]);
void mote__normalize(float v[3]);
/* s x the mean colour of n vertices: one vertex's own, or a flat triangle's */
void mote__tint(const mote__ctx *cx, mote__tvert *const tv[], int n, float s[3]);
/* A colour in [0,1] as 2^24 fixed point. */
void mote__shade_fixed(const float s[3], int32_t out[3]);
/* A final vertex (as transformed, or made by clipping) in setup's units. */
void mote__to_setup(const mote__cvert *v, mote__svert *out);
/* What only drawn triangles need of a vertex: lighting and setup's units. */
void mote__finish(const mote__ctx *cx, mote__tvert *tv);
/* The vertices [first, end) of a full cache, transformed (not finished). */
void mote__transform_range(mote__ctx *cx, mote__tvert *tv, uint32_t first, uint32_t end);
/* A vertex of the draw's cache: the full cache's, or the small one's,
 * transformed and finished on demand. */
mote__tvert *mote__vertex(mote__ctx *cx, uint32_t index);
#if MOTE__VECTOR_VERTEX
/* mote__finish of four vertices (not yet ready; the same one twice is
 * fine) of a lit Gouraud draw, after mote__v4_light_init */
void mote__finish4(const mote__ctx *cx, mote__tvert *const tv[4]);
void mote__v4_light_init(mote__ctx *cx);
/* Whether mote__finish4 can finish this draw's vertices: lit Gouraud ones. */
static inline bool mote__finish_in_fours(const mote__ctx *cx)
{
    return cx->lit && cx->rs->gouraud && !cx->mesh->compact && !cx->additive;
}
#endif

/* ---- assemble.c: triangles ------------------------------------------------- */


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

/* The triangles [first, end) of the draw's indices: each rejected,
 * clipped, culled, shaded and handed to the sink, in order. prepared: the
 * cache was finished by mote__prepare_vertices. */
void mote__triangles(mote__ctx *cx, uint32_t first, uint32_t end, bool prepared);

#endif
