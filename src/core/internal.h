/*
 * internal.h - shared declarations of the mote core's stages.
 *
 * A frame, by file. Each file calls functions only of the files below it
 * (tests/core/layers.sh holds this), so the order is also the way to read
 * the pipeline from the API down to a pixel:
 *   device.c    the public device API: frames, draws, the direct and the
 *               band paths, which rasterise through a sink at once
 *   bin.c       binned mode: the sink that keeps triangles in the arena,
 *               tiles, parallel setup in groups
 *   target.c    render targets, pixel counts, the clear
 *   draw.c      per draw: its description, context and vertex cache
 *   vertex_fixed.c  the integer vertex stage, for cores without an FPU:
 *               a draw's vertices and triangles, handed to assemble.c
 *   assemble.c  per triangle: rejection, clipping into a fan, culling,
 *               flat shading, face queues -> setup -> the sink
 *   vertex.c    per vertex: transform, lighting (light.h), setup's units;
 *               four at a time on SSE2 hosts (vertex.h: the stage's types)
 *   clip.c      outcodes, homogeneous clipping, snapping to sub-pixels
 *   vmath.c     matrices, deterministic trig (float)
 *   setup.c     per triangle: edge functions and attribute planes (integer)
 *   line.c      points and wireframe (Bresenham, exact under clipping)
 *   span.c      fill functions: rows of the walk x pixel loops, specialised
 *               from one inline body
 *   span_simd.c which fills run in vector registers, on which instruction set
 *   span_avx2.c the vector fills (span_simd.h), 8 pixels a step in AVX2,
 *   span_sse2.c 4 in SSE2,
 *   span_neon.c 4 in NEON: the scalar loops' bytes
 *   span_fw.c   the firmware's fast pixel loop (MOTE_FIRMWARE_SPANS)
 *   raster.c    exact scanline edge walking over a region
 *   format.c    colour and depth formats (format.h): conversion, reading
 *               pixels back
 *   recip.c     exact reciprocals by table (1/w for setup, per pixel on
 *               32-bit cores)
 *   shared.c    size builds' one copy of the small helpers every stage
 *               shares (this file's and plane.h's)
 */
#ifndef MOTE_CORE_INTERNAL_H
#define MOTE_CORE_INTERNAL_H

#include <mote/mote.h>
#include <string.h>

/* Shortcuts in setup and the walk that skip work for common (small)
 * triangles give the same results as the general code they bypass, but
 * cost flash: size builds (-Os) leave them out unless told otherwise. */
#ifndef MOTE_SHORTCUTS
#if defined(__OPTIMIZE_SIZE__)
#define MOTE_SHORTCUTS 0
#else
#define MOTE_SHORTCUTS 1
#endif
#endif

#define MOTE__MIN(a, b) ((a) < (b) ? (a) : (b))
#define MOTE__MAX(a, b) ((a) > (b) ? (a) : (b))

#include "format.h"

/* Shade and weights fixed-point units (see CONVENTIONS in mote.h). */
#define MOTE__SHADE_ONE (1 << 24)
#define MOTE__DEPTH_MAX ((1u << 24) - 1u)
#define MOTE__DEPTH_FRAC 16
/* Fraction bits of texel coordinates; setup drops some for a triangle
 * whose texels lie 2^12 texels or more from their nearest period */
#define MOTE__TEXEL_BITS 16

/* Small helpers called from several places: inline in speed builds, one
 * out-of-line copy in size builds (-Os), where each inlined copy is a long
 * 64-bit sequence on a 32-bit core. */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__)
#define MOTE__SPEED_INLINE static __attribute__((unused, noinline))
#else
#define MOTE__SPEED_INLINE static inline
#endif

/* The helpers several files share: in size builds declared here and
 * defined once, by shared.c (MOTE__DEFINE_SHARED); inline elsewhere. */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__)
#define MOTE__SHARED_COPY 1
#else
#define MOTE__SHARED_COPY 0
#endif
#if defined(MOTE__DEFINE_SHARED) || !MOTE__SHARED_COPY
#define MOTE__SHARED_BODIES 1
#else
#define MOTE__SHARED_BODIES 0
#endif
#ifdef MOTE__DEFINE_SHARED
#define MOTE__SHARED
#else
#define MOTE__SHARED static inline
#endif

/* Cores with 32-bit registers, where each 64-bit operation is several
 * instructions or a library call: setup and the edge walk take 32-bit
 * paths there where the ranges allow (tests/test_edge32.c and
 * tests/test_setup_portable.c set it to run those on the host). */
#ifndef MOTE__CORE32
#if defined(__SIZEOF_POINTER__) && __SIZEOF_POINTER__ >= 8
#define MOTE__CORE32 0
#else
#define MOTE__CORE32 1
#endif
#endif

/* floor(v / 2^k) for 0 <= k < 63, without relying on how >> treats
 * negative numbers (implementation-defined in C99): a negative v is
 * complemented, shifted and complemented back, through a mask rather than
 * a branch (setup and the walk take it of numbers of either sign). Where
 * the compiler defines >> as the arithmetic shift (GCC and Clang), one
 * instruction where registers are 64 bits wide (the pixel loops take four
 * a row), two 32-bit shifts where they are not. */
#if MOTE__SHARED_BODIES
MOTE__SHARED int64_t mote__floor_shift64(int64_t v, int k)
{
#if defined(__GNUC__) && !MOTE__CORE32
    return v >> k;
#elif defined(__GNUC__)
    /* by 32-bit halves: a 64-bit shift by a variable is a libgcc call */
    const int32_t hi = (int32_t)(uint32_t)((uint64_t)v >> 32);
    if (k >= 32)
        return (int64_t)(hi >> (k - 32));
    if (k == 0)
        return v;
    const uint32_t lo = (uint32_t)(uint64_t)v >> k | (uint32_t)hi << (32 - k);
    return (int64_t)((uint64_t)(uint32_t)(hi >> k) << 32 | lo);
#else
    uint64_t neg = 0u - (uint64_t)(v < 0);
    return (int64_t)((((uint64_t)v ^ neg) >> k) ^ neg);
#endif
}
#else
int64_t mote__floor_shift64(int64_t v, int k);
#endif

/* the same for a 32-bit v, 0 <= k < 31: one instruction where the
 * compiler defines >> of a negative number as the arithmetic shift (GCC
 * and Clang do), so that size builds inline it too */
static inline int32_t mote__floor_shift32(int32_t v, int k)
{
#if defined(__GNUC__)
    return v >> k;
#else
    uint32_t neg = 0u - (uint32_t)(v < 0);
    return (int32_t)((((uint32_t)v ^ neg) >> k) ^ neg);
#endif
}

/* ---- vertex stage -------------------------------------------------------- */

void mote__mat4_identity(float m[16]);
void mote__mat4_mul(const float a[16], const float b[16], float out[16]);
/* Inverse-transpose of the upper 3x3 up to a positive scale (the cofactor
 * matrix, negated when the matrix mirrors, so normals stay outward), for
 * normals, row-major: n'[r] = sum_c out[r * 3 + c] n[c]. */
void mote__normal_matrix(const float m[16], bool mirrors, float out[9]);
/* mote_mesh_world_matrix; returns whether it mirrors (negative determinant) */
bool mote__world_matrix(const mote_mesh *mesh, float world[16]);
void mote__cross3(const float a[3], const float b[3], float out[3]);
/* a -= b */
void mote__sub3(float a[3], const float b[3]);
/* mote_camera_projection_matrix without its NULL checks */
void mote__projection(const mote_camera *camera, float aspect, float proj[16]);
/* mote_camera_view_matrix without its translation: the camera's turn */
void mote__view_rotation(const mote_camera *camera, float view[16]);
float mote__sqrtf(float x);

/* A float's bits: tests on them spare soft-float targets a library call. */
static inline uint32_t mote__float_bits(float x)
{
    union { float f; uint32_t u; } b;
    b.f = x;
    return b.u;
}

/* false for NaN and +-Inf; a bit test, as it runs several times per vertex */
static inline bool mote__finite(float x)
{
    return (mote__float_bits(x) & 0x7f800000u) != 0x7f800000u;
}

/* v, or def when v is zero (either sign): the "unset" of a scalar */
static inline float mote__or(float v, float def)
{
    return mote__float_bits(v) << 1 ? v : def;
}

/* whether all three are zero (either sign): the "unset" of a vector */
static inline bool mote__zero3(const float v[3])
{
    return ((mote__float_bits(v[0]) | mote__float_bits(v[1]) | mote__float_bits(v[2])) << 1) == 0;
}

/* x > 0 and finite, from the bits: no library call on soft-float cores */
static inline bool mote__positive_finite(float x)
{
    return mote__float_bits(x) - 1u < 0x7f7fffffu;
}

/* The helpers every vertex calls, inline for speed: as calls into
 * vmath.c the vertex stage spilled registers around each. Where flash
 * counts, one shared copy, which vmath.c defines (MOTE__VMATH_DEFINE). */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__) && !defined(MOTE__VMATH_DEFINE)
float mote__dot3(const float a[3], const float b[3]);
float mote__rsqrtf(float x);
void mote__mat4_point(const float m[16], const float p[3], float out[4]);
#else
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__)
#define MOTE__VMATH_FN
#else
#define MOTE__VMATH_FN static inline
#endif
MOTE__VMATH_FN float mote__dot3(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* 1/sqrt(x), 0 for 0, negative, NaN, Inf: the classic exponent-halving
 * guess and three Newton steps (no division); about 1 ulp, and identical
 * on every target. */
MOTE__VMATH_FN float mote__rsqrtf(float x)
{
    if (!mote__positive_finite(x))
        return 0.0f;
    union { float f; uint32_t u; } g;
    g.f = x;
    g.u = 0x5f375a86u - (g.u >> 1);
    float y = g.f, h = 0.5f * x;
    for (int i = 0; i < 3; i++)
        y = y * (1.5f - h * y * y);
    return y;
}

/* m (column-major) times the point (p, 1) */
MOTE__VMATH_FN void mote__mat4_point(const float m[16], const float p[3], float out[4])
{
    /* into a local first: out may alias p, and with the stores last the
     * four rows can run as one vector operation */
    float x = p[0], y = p[1], z = p[2], r[4];
    for (int row = 0; row < 4; row++)
        r[row] = m[0 * 4 + row] * x + m[1 * 4 + row] * y + m[2 * 4 + row] * z + m[3 * 4 + row];
    memcpy(out, r, sizeof r);
}
#undef MOTE__VMATH_FN
#endif

/* ---- mesh data ------------------------------------------------------------ */

/* Whether a mesh has an index array (float or compact). */
static inline bool mote__mesh_has_indices(const mote_mesh *m)
{
    return m->indices || (m->compact && m->compact->indices);
}

/* Whether a mesh has vertex data (float or compact positions). */
static inline bool mote__mesh_has_vertices(const mote_mesh *m)
{
    return m->compact ? m->compact->positions != NULL : m->vertices != NULL;
}

/* The indices of triangle t (mote__mesh_has_indices). */
static inline void mote__mesh_triangle(const mote_mesh *m, uint32_t t, uint32_t idx[3])
{
    for (int k = 0; k < 3; k++)
        idx[k] = m->indices ? m->indices[3 * t + k] : m->compact->indices[3 * t + k];
}

/* vmath.c: a compact mesh's vertex i converted into *tmp as stored (its
 * scale and offset are folded into the draw's matrices: mote__compact_fold) */
const mote_vertex *mote__compact_vertex(const mote_compact *c, uint32_t i, mote_vertex *tmp);

/* Vertex i as floats: a pointer into mesh->vertices, or a compact mesh's
 * in *tmp (inline: the float stage reads every vertex through it). */
static inline const mote_vertex *mote__mesh_vertex(const mote_mesh *mesh, uint32_t i, mote_vertex *tmp)
{
    return mesh->compact ? mote__compact_vertex(mesh->compact, i, tmp) : &mesh->vertices[i];
}
/* m x (a translation to offset, then a scale), column-major: a compact
 * mesh's positions into m's space */
void mote__compact_fold(const float m[16], const float offset[3], const float scale[3], float out[16]);

/* A vertex after the vertex stage: clip position and the attributes that
 * clipping interpolates. */
/* Specular highlights or fog: an additive colour per vertex, three more
 * planes (MOTE__SHADE_ADD). A build with neither has none of it. */
#define MOTE__ADD_ENABLED (MOTE_ENABLE_SPECULAR || MOTE_ENABLE_FOG)

typedef struct mote__cvert {
    float x, y, z, w;
    float s[3];                   /* lit colour, 0..1 */
    float u, v;                   /* texture coordinates in texels */
#if MOTE__ADD_ENABLED
    float a[3];                   /* additive colour (highlights, fog), 0..1 */
#endif
} mote__cvert;

/* A vertex as setup reads it: its attributes in the pixel stage's integer
 * units, converted once per vertex rather than at every corner of every
 * triangle sharing it. */
typedef struct mote__svert {
    int64_t texel[2];             /* u and v, 16.16 texels */
    int32_t s[3];                 /* lit colour, MOTE__SHADE_ONE = 1 */
    int32_t z;                    /* depth, 0..MOTE__DEPTH_MAX */
    float depth;                  /* what z rounds: z/w clamped to [0, 1] (the triangle hook's) */
    float w;                      /* clip w (the triangle hook's) */
    uint32_t qm;                  /* 1/w ~ qm 2^(96 - qe), qm in (2^30, 2^31] */
    int32_t qe;                   /* (mote__inverse_w): setup's weights by shifts */
#if MOTE__ADD_ENABLED
    int32_t a[3];                 /* additive colour, MOTE__SHADE_ONE = 1 (after s..z: the
                                     four-vertex path stores those as rows) */
#endif
} mote__svert;

/* ---- reciprocals (recip.c) ------------------------------------------------ */

/* Cores without a 32x32->64-bit multiply (ARMv6-M: no UMULL), where C's
 * 64-bit product is a call into libgcc of some 40 instructions. */
#ifndef MOTE__NO_UMULL
#if defined(__ARM_ARCH_6M__) || defined(__ARM_ARCH_8M_BASE__)
#define MOTE__NO_UMULL 1
#else
#define MOTE__NO_UMULL 0
#endif
#endif

/* a b, exact: four 16x16-bit products where there is no UMULL */
#if MOTE__SHARED_BODIES
MOTE__SHARED uint64_t mote__umul64(uint32_t a, uint32_t b)
{
#if MOTE__NO_UMULL
    uint32_t al = a & 0xffffu, ah = a >> 16, bl = b & 0xffffu, bh = b >> 16;
    uint32_t ll = al * bl, lh = al * bh, hl = ah * bl;
    uint32_t mid = (ll >> 16) + (lh & 0xffffu) + (hl & 0xffffu);
    uint32_t hi = ah * bh + (lh >> 16) + (hl >> 16) + (mid >> 16);
    return ((uint64_t)hi << 32) | ((ll & 0xffffu) | (mid << 16));
#else
    return (uint64_t)a * b;
#endif
}
#else
uint64_t mote__umul64(uint32_t a, uint32_t b);
#endif

/* a b, exact, for b < 2^16: two 16x16-bit products (the pixel loops'
 * steps from a plane's origin, which stay within the guard band) */
static inline uint64_t mote__umul64_short(uint32_t a, uint32_t b)
{
    const uint32_t ll = (a & 0xffffu) * b, hl = (a >> 16) * b, lo = ll + (hl << 16);
    return ((uint64_t)((hl >> 16) + (lo < ll)) << 32) | lo;
}

/* Number of significant bits of a 32-bit v (0 for 0). */
static inline int mote__bitlen32(uint32_t v)
{
#if defined(__GNUC__)
    return v ? 32 - __builtin_clz(v) : 0;
#else
    int n = 0;
    while (v >> n)
        n++;
    return n;
#endif
}

/* The pixel loop's reciprocal from a table and a Newton step rather than
 * a divide: 1 on cores without a 64-bit divide instruction (32-bit ones),
 * 0 on 64-bit hosts. Both give the same bits. */
#ifndef MOTE_RECIP_BY_TABLE
#if defined(__SIZEOF_POINTER__) && __SIZEOF_POINTER__ >= 8
#define MOTE_RECIP_BY_TABLE 0
#else
#define MOTE_RECIP_BY_TABLE 1
#endif
#endif

extern const uint32_t mote__recip_table[257];
/* mote__recip_lookup's first guess at floor(2^61 / m): below it by less
 * than 2^-16 of it (see recip.c) */
static inline uint32_t mote__recip_guess(uint32_t m)
{
    const uint32_t i = (m >> 22) - 256, f = m & ((1u << 22) - 1);
    const uint32_t t0 = mote__recip_table[i], d = t0 - mote__recip_table[i + 1];
    /* (d f) / 2^22 with both cut to 16 bits: a 32-bit product, an error
     * of a few hundred units, far below the chord's */
    return t0 - (((d >> 7) * (f >> 6)) >> 9);
}
/* floor(2^61 / m) for m in [2^30, 2^31), exactly */
uint32_t mote__recip_lookup(uint32_t m);
/* out->qm and out->qe from w (> 0, finite; any other w gives some value) */
void mote__inverse_w(float w, mote__svert *out);

/* A divisor d > 0 with its reciprocal, for dividing where a 64-bit
 * division is a libgcc routine (a few hundred instructions on a
 * Cortex-M0+): r is within a few units of 2^63 / (d 2^sh), d 2^sh in
 * [2^31, 2^32). */
typedef struct mote__divisor {
    uint32_t d, r;
    int sh;
} mote__divisor;
/* returns the reciprocal it took: floor(2^61 / m), m = d 2^sh / 2 */
uint32_t mote__divisor_init(mote__divisor *v, uint32_t d);
/* floor(n / d), exact; false (divide another way) when it is 2^32 or
 * more, and perhaps within 2^8 below that */
bool mote__divide(uint64_t n, const mote__divisor *v, uint32_t *q);
/* floor(a / d) for either sign of a (a negative a's is minus the ceiling
 * of |a| / d); false as mote__divide, for that magnitude */
bool mote__divide_floor(int64_t a, const mote__divisor *v, int64_t *q);
/* floor(n / d) for 0 < d < 2^63 without a 64-bit division (a libgcc
 * routine on 32-bit cores): by a reciprocal where d and the quotient fit
 * 32 bits, bit by bit otherwise */
uint64_t mote__udiv64(uint64_t n, uint64_t d);

/* Number of significant bits of v (0 for 0). */
#if MOTE__SHARED_BODIES
MOTE__SHARED int mote__bitlen(uint64_t v)
{
#if defined(__GNUC__)
    return v ? 64 - __builtin_clzll(v) : 0;
#else
    int n = 0;
    for (int step = 32; step > 0; step >>= 1)
        if (v >> step) {
            v >>= step;
            n += step;
        }
    return n + (int)v;
#endif
}
#else
int mote__bitlen(uint64_t v);
#endif

/* min(floor(2^k / max(q, 1)), 2^31 - 1) for 30 <= k <= 61: the pixel
 * loop's one reciprocal, exact whichever way it is found, and a signed
 * 32-bit factor (a 32x32-bit product on cores that have one). */
#if MOTE__SHARED_BODIES
MOTE__SHARED int32_t mote__recip_k(int32_t q, int k)
{
    const uint32_t d = q > 1 ? (uint32_t)q : 1u, most = ((uint32_t)1 << 31) - 1;
#if MOTE_RECIP_BY_TABLE
    /* 2^k / d = (2^61 / m) 2^(k + s - 61) with m = d 2^s in [2^30, 2^31),
     * and the floor of a floor divided by a power of two is the floor */
    const int s = 31 - mote__bitlen32(d), down = 61 - k - s;
    if (down <= 0)                /* 2^k / d >= 2^61 / m > 2^30, and 2^31 at most when down is 0 */
        return down < 0 ? (int32_t)most : (int32_t)MOTE__MIN(mote__recip_lookup(d << s), most);
    return down < 32 ? (int32_t)(mote__recip_lookup(d << s) >> down) : 0;
#else
    const uint64_t r = ((uint64_t)1 << k) / d;
    return (int32_t)(r < most ? r : most);
#endif
}
#else
int32_t mote__recip_k(int32_t q, int k);
#endif

/* ---- pixel stage --------------------------------------------------------- */

typedef enum mote__tex_kind { MOTE__TEX_NONE, MOTE__TEX_NEAREST, MOTE__TEX_BILINEAR } mote__tex_kind;
typedef enum mote__persp_kind { MOTE__PERSP_AFFINE, MOTE__PERSP_CORRECT, MOTE__PERSP_SUBSPAN } mote__persp_kind;
/* How a triangle's shade varies, decided per triangle by setup: one value
 * (flat draws, or all three vertices alike), one grey value interpolated
 * (white or grey light on a grey material: the usual case), three
 * channels, or zero everywhere (unlit, no ambient), which makes every
 * pixel black whatever the texture holds: filled as an untextured flat
 * triangle, with no weights set up. All give the same bytes; the cheaper
 * ones skip work. The first three index the specialised fill table. */
/* MOTE__SHADE_ADD: three channels and an additive colour (specular
 * highlights, fog), drawn by the generic loop alone. */
typedef enum mote__shade_kind {
    MOTE__SHADE_FLAT, MOTE__SHADE_MONO, MOTE__SHADE_RGB, MOTE__SHADE_BLACK, MOTE__SHADE_ADD, MOTE__SHADE_COUNT
} mote__shade_kind;

struct mote__tri;
struct mote__target;
struct mote__rect;
/* Fills the pixels of one triangle inside a region of the screen: the edge
 * walk of raster.c with one of span.c's pixel loops inside. */
typedef void (*mote__fill_fn)(const struct mote__tri *t, const struct mote__target *tg,
                              struct mote__rect r, int subpixel_bits);

/* Texture layers (mote_material.layers): in a build with any role, the
 * generic pixel loop alone draws them. */
#define MOTE__LAYERS_ENABLED (MOTE_ENABLE_EMISSIVE_MAP || MOTE_ENABLE_OPACITY_MAP || MOTE_ENABLE_SPECULAR_MAP)

/* A layer as the pixel loop reads it: its texture, and the map from the
 * draw's texel coordinates (level 0) to its own, in 1/2^MOTE__LAYER_BITS
 * texels, per axis: L = ((T << level) mul >> (sh + tb - MOTE__LAYER_BITS))
 * + add, T with tb fraction bits (draw.c's mote__layers_select). */
#define MOTE__LAYER_BITS 12
typedef struct mote__layer {
    const mote_texture *texture;
    int stride;                   /* bytes per row */
    mote_wrap wrap_u, wrap_v;
    uint8_t role;                 /* mote_layer_role */
    bool from_rgb;
    int8_t sh[2];
    int32_t mul[2];
    int64_t add[2];
    /* emissive: shade units a texel unit, round(factor 2^24 / 255);
     * specular: 2^16 = 1, per channel; opacity: [0] in 1/256 */
    uint32_t factor[3];
} mote__layer;

/* What the pixel stage needs of a draw; lives as long as its triangles. */
typedef struct mote__raster_state {
    mote__fill_fn fill[MOTE__SHADE_COUNT]; /* by the triangle's shade kind */
    const mote_texture *texture;
    int tex_w, tex_h;
    int tex_stride;               /* bytes per texture row */
    mote_wrap wrap_u, wrap_v;
    bool pow2_repeat;             /* texels by masks and shifts (mote__fill_select) */
    int tex_stride_log2;          /* log2 of tex_stride when pow2_repeat */
    mote__tex_kind tex;
    mote__persp_kind persp;
    int subspan_log2;
    bool gouraud;                 /* false: one shade per triangle */
    bool depth_test, depth_write;
    bool depth_equal;             /* the test passes on equal depths too */
    bool no_color;                /* depth only: no colour written */
    int32_t depth_half;           /* half a unit of the depth buffer, in the depth plane's 1/65536 */
    /* alpha (mote_material.alpha_mode), all off for an opaque draw: the
     * generic pixel loop alone reads them (mote__fill_select) */
    uint8_t alpha;                /* MOTE__ALPHA_* flags */
    uint8_t alpha8;               /* the material's alpha, 0..255 */
    uint16_t cutoff;              /* alpha test: a texel alpha below it is cut (0..256) */
    bool additive;                /* triangles are MOTE__SHADE_ADD */
    const mote_mipmaps *mips;     /* the chain: setup picks a level (MOTE_MIP_TRIANGLE), */
    bool mip_pixel;               /* or the generic loop, pixel by pixel */
    bool mip_blend;               /* per pixel, two levels blended (MOTE_MIP_TRILINEAR) */
#if MOTE__LAYERS_ENABLED
    uint8_t layer_count;          /* 0: none; else the generic loop's alone */
    bool base_white;              /* the draw has no texture: layer 0's coordinates, white */
    bool texel_absolute;          /* setup keeps texel coordinates whole (no period taken off) */
    mote__layer layer[MOTE_MAX_LAYERS];
#endif
} mote__raster_state;

/* Whether a draw has texture layers (which the generic loop alone draws). */
static inline bool mote__has_layers(const mote__raster_state *rs)
{
#if MOTE__LAYERS_ENABLED
    return rs->layer_count != 0;
#else
    (void)rs;
    return false;
#endif
}

/* Whether only the generic pixel loop draws this: alpha, texture layers,
 * a depth-only draw or one whose test passes on equal depths. */
static inline bool mote__generic_only(const mote__raster_state *rs)
{
    return rs->alpha || mote__has_layers(rs) || rs->depth_equal || rs->no_color;
}

/* mote__raster_state.alpha: what a draw does with alpha: cut by the
 * texel's alpha, blend, and blend with the texel's alpha times alpha8 */
enum { MOTE__ALPHA_TEST = 1, MOTE__ALPHA_BLEND = 2, MOTE__ALPHA_TEXEL = 4 };
/* a build without either keeps no alpha code in its pixel loop */
#define MOTE__ALPHA_ENABLED (MOTE_ENABLE_ALPHA_TEST || MOTE_ENABLE_BLEND)

/* Interpolated attributes of a triangle, by index. A binned triangle's
 * record ends after the last plane it has (mote__plane_count): red, the
 * texels, then green and blue, so that a grey textured triangle, a lit
 * textured mesh's, keeps three planes of five (208 bytes, not 256). */
enum { MOTE__A_R, MOTE__A_U, MOTE__A_V, MOTE__A_G, MOTE__A_B, MOTE__A_AR, MOTE__A_AG, MOTE__A_AB };
/* the additive colour's planes only where a build can have them */
#define MOTE__ATTRS (MOTE__ADD_ENABLED ? MOTE__A_AB + 1 : MOTE__A_B + 1)

/* Whether a triangle of this shade kind, with or without a texture, has a
 * plane for attribute a: red alone for one grey shade, all three for RGB,
 * none for a constant one, the texels with a texture; none at all for a
 * black one. Setup makes only those; the pixel loops read only those. */
static inline bool mote__has_plane(int a, mote__shade_kind shade, bool textured)
{
    if (shade == MOTE__SHADE_BLACK)
        return false;
    if (a == MOTE__A_U || a == MOTE__A_V)
        return textured;
    if (a >= MOTE__A_AR)
        return shade == MOTE__SHADE_ADD;
    return shade >= MOTE__SHADE_RGB || (shade == MOTE__SHADE_MONO && a == MOTE__A_R);
}

/* How many planes, from the first, a triangle of this kind keeps: up to
 * its last one (mote__has_plane); those before it that it lacks are 0. */
static inline int mote__plane_count(int shade, bool textured)
{
    if (shade == MOTE__SHADE_BLACK)
        return 0;
    if (shade == MOTE__SHADE_ADD)
        return MOTE__ATTRS;
    if (shade == MOTE__SHADE_RGB)
        return MOTE__A_B + 1;
    if (textured)
        return MOTE__A_V + 1;
    return shade == MOTE__SHADE_MONO ? MOTE__A_R + 1 : 0;
}

/* A set-up triangle. Planes are evaluated at pixel centres relative to the
 * origin pixel (ox, oy) so that values stay small; stepping is exact integer
 * addition, so any region of the triangle gives the same pixels.
 *
 * The pixel loops step 32-bit copies of the planes: each row is cut into
 * blocks of MOTE__BLOCK pixels counted from its own first pixel, and at a
 * block's first pixel q = Q plane >> d, n = N plane >> (d + n_extra)
 * (about 2^30 or less in magnitude inside the triangle), their steps
 * rounded; d is q_drop, or chosen per block. Then r = mote__recip_k(q, K)
 * (below 2^30 inside) and an attribute is a0 + (n r >> (K - 20 - n_extra)),
 * a 32x32-bit product. */
typedef struct mote__tri {
    const mote__raster_state *rs;
    int32_t X[3], Y[3];           /* snapped, from the top vertex (see setup.c), original winding */
    int16_t xmin, ymin, xmax, ymax; /* pixel bounding box, inclusive, clamped to the viewport */
    int16_t ox, oy;
    uint8_t shade;                /* mote__shade_kind */
    int8_t rbits;                 /* K of the reciprocal r = 2^K / q, 30..60 (q_drop >= 0) */
    int8_t q_drop;                /* q = Q plane >> q_drop for the whole triangle; -1: per block */
    int8_t n_extra;               /* numerator planes to 32 bits: N >> (10 + n_extra) */
    int8_t texel_bits;            /* fraction bits of texel coordinates, 0..16 */
    uint8_t order;                /* walk order (raster.c): bits 0-1, 2-3, 4-5 the top,
                                   * middle and bottom vertex; bit 6: long edge on the left */
    uint8_t level;                /* mip level its texels come from (rs->mips) */
    int64_t q, qdx, qdy;          /* Q 2^(10 - shift), Q = sum Ei qi, qi ~ 1/wi (see setup.c) */
    int64_t z, zdx, zdy;          /* depth, 24.16 */
    /* attributes: values at vertex 0 (shades in 2^24, texels in 16.16) and
     * numerator planes N (value, x step, y step): A = a0 + N r / 2^(K-10);
     * only the planes the shade kind reads are made (red alone for MONO,
     * none for FLAT, texels with a texture), the others are 0 */
    int64_t a0[MOTE__ATTRS];
    int64_t n[MOTE__ATTRS][3];    /* last: a binned copy ends after its planes (mote__tri_bytes) */
} mote__tri;

/* The bytes of t that its pixel loops read, in one of three sizes (each
 * a copy the compiler unrolls): the record without planes, up to the
 * texels', or all of it. */
#define MOTE__TRI_BYTES(planes) (offsetof(mote__tri, n) + (planes) * sizeof(int64_t[3]))
static inline size_t mote__tri_bytes(const mote__tri *t)
{
    int planes = mote__plane_count(t->shade, t->rs->tex != MOTE__TEX_NONE);
    return planes == 0 ? MOTE__TRI_BYTES(0) : planes <= MOTE__A_V + 1 ? MOTE__TRI_BYTES(MOTE__A_V + 1)
         : planes <= MOTE__A_B + 1 ? MOTE__TRI_BYTES(MOTE__A_B + 1) : sizeof(mote__tri);
}

/* Pixels a region tested (reached the depth test) and wrote. */
typedef struct mote__counts { uint64_t tested, written; } mote__counts;

typedef struct mote__target {
    uint8_t *color;               /* row y is at color + (y - y0) * stride */
    int stride;
    void *depth;                  /* row y at depth + (y - y0) * width elements */
    int width;
    int y0;
    mote_format format;
    mote_depth_format depth_format;
    mote__counts *counts;         /* owned by the caller of the region */
} mote__target;

/* Region of the screen being drawn: [x0, x1) x [y0, y1). */
typedef struct mote__rect { int x0, y0, x1, y1; } mote__rect;

/* raster.c: exact scanline edge walking. An edge holds, for the current
 * row, the first pixel at or right of its crossing, with the remainder of
 * that ceiling so that stepping a row is exact integer addition. */
typedef struct mote__edge {
    int64_t x;                    /* first pixel index at or right of the crossing */
    int64_t err;                  /* x * den - num, in [0, den) */
    int64_t den, qstep, rstep;
} mote__edge;

/* A triangle's rows inside a region: rows [y, yend), between the left
 * and the right edge; one is the long edge a-c, the other the short one,
 * which changes from a-b to b-c at row ymid. */
typedef struct mote__walk {
    mote__edge left, right;
    int y, ymid, yend;
    int rx0, rx1;                 /* the region's columns, cut to the triangle's box */
    bool short_left;              /* the short edge is the left one */
    int32_t xb, yb, xc, yc;       /* vertices b and c (sorted by y) */
    int subpixel_bits;
} mote__walk;

/* false when the triangle has no rows in the region */
bool mote__walk_begin(mote__walk *w, const struct mote__tri *t, mote__rect r, int subpixel_bits);
/* at row ymid: the short edge becomes b-c */
void mote__walk_switch(mote__walk *w);

#if MOTE__SHARED_BODIES
MOTE__SHARED void mote__edge_step(mote__edge *e)
{
    /* without a branch: whether the remainder wraps changes from row to
     * row in no pattern a predictor can learn */
    e->err -= e->rstep;
    int64_t wrap = -(int64_t)(e->err < 0);   /* all ones or zero */
    e->x += e->qstep - wrap;
    e->err += e->den & wrap;
}
#else
void mote__edge_step(mote__edge *e);
#endif

/* The pixels [*x0, *x1) of row w->y (empty when *x0 >= *x1), and in
 * *span the row's own pixels before the cut to the region, then the walk
 * moves to the next row. */
static inline void mote__walk_row(mote__walk *w, int *x0, int *x1, int64_t span[2])
{
    if (w->y == w->ymid)
        mote__walk_switch(w);
    span[0] = w->left.x;
    span[1] = w->right.x;
    /* cut to the region; an empty row stays empty (x0 >= x1) */
    *x0 = (int)MOTE__MAX(w->left.x, w->rx0);
    *x1 = (int)MOTE__MIN(w->right.x, w->rx1);
    mote__edge_step(&w->left);
    mote__edge_step(&w->right);
    w->y++;
}

/* Where a fill draws next: pixels [from, x1) of a row, cut into blocks
 * of 2^k pixels counted from the row's own first pixel (the pixel loops'
 * 32-bit planes start afresh at each: see mote__tri); bx is the block
 * holding from, last the row's last pixel before the cut to the region. */
typedef struct mote__span_blocks {
    ptrdiff_t from, x1, bx, last;
    /* the pixels of the rows so far, counted as a row starts: after the
     * pixel loop, x0 and x1 would have to outlive a loop that needs every
     * register */
    uint64_t tested;
} mote__span_blocks;

/* Row w->y's pixels into *b, then the walk moves to the next row: false
 * when the row has none. */
static inline bool mote__span_begin(mote__walk *w, mote__span_blocks *b, int k)
{
    int x0, x1;
    int64_t span[2];
    mote__walk_row(w, &x0, &x1, span);
    if (x0 >= x1) {
        b->from = b->x1 = 0;
        return false;
    }
    b->tested += (uint64_t)(x1 - x0);
    b->from = x0;
    b->x1 = x1;
    b->last = (ptrdiff_t)span[1] - 1;
    b->bx = (ptrdiff_t)(span[0] + ((x0 - span[0]) & -((int64_t)1 << k)));
    return true;
}

/* Twice the signed area of a triangle of snapped vertices (positive:
 * clockwise on screen, y growing downward); 0 for a degenerate one. */
static inline int64_t mote__area2(const int32_t X[3], const int32_t Y[3])
{
    return (int64_t)(X[1] - X[0]) * (Y[2] - Y[0]) - (int64_t)(Y[1] - Y[0]) * (X[2] - X[0]);
}

/* setup.c: fills t from snapped vertices, their doubled signed area (not
 * 0: the vertex stage drops degenerate triangles) and their attributes,
 * unless the triangle has no pixels: off the viewport, or no pixel centre
 * within its vertices' box (then t is not filled). */
typedef enum mote__setup_result { MOTE__SETUP_DRAWN, MOTE__SETUP_OUTSIDE, MOTE__SETUP_EMPTY } mote__setup_result;
/* setup.c: mote__setup's first test, alone: what it would return but for
 * DRAWN's planes, and the rows and columns of pixels it would draw,
 * box = {x0, y0, x1, y1}, inclusive (set for DRAWN only). */
mote__setup_result mote__setup_box(const int32_t X[3], const int32_t Y[3], int subpixel_bits, int width, int height,
                                   int box[4]);
mote__setup_result mote__setup(mote__tri *t, const mote__raster_state *rs, const int32_t X[3],
                 const int32_t Y[3], int64_t area2, const mote__svert *const v[3],
                 int subpixel_bits, int width, int height);

/* Fills a set-up triangle's pixels inside region r with the pixel loop
 * its draw and shade kind select (inline: a tile of small triangles calls
 * it for each). */
static inline void mote__raster_tri(const mote__tri *t, const mote__target *tg, mote__rect r,
                                    int subpixel_bits)
{
    t->rs->fill[t->shade](t, tg, r, subpixel_bits);
}

/* span_fw.c: the firmware's pixel loop (Gouraud, nearest RGB565 texels or
 * none, RGB565 with 16-bit depth), in place of the generic one for the
 * draws it fits. Small (about a kilobyte) and several times faster on
 * 32-bit cores: on by default where the specialised loops are off (size
 * builds, MOTE_SPECIALISE_SPANS 0 in span.c); define it to 0 to leave it out,
 * or to 1 to have it in any build. Same bytes either way. */
#ifndef MOTE_FIRMWARE_SPANS
#if defined(__OPTIMIZE_SIZE__)
#define MOTE_FIRMWARE_SPANS 1
#else
#define MOTE_FIRMWARE_SPANS 0
#endif
#endif
/* Whether the firmware loop draws the Gouraud triangles of a draw. */
bool mote__fill_fw_fits(const mote__raster_state *rs, mote_format format, mote_depth_format depth_format);
/* The firmware loop, for a triangle of such a draw with q_drop >= 0. */
void mote__fill_fw(const struct mote__tri *t, const struct mote__target *tg, struct mote__rect r, int subpixel_bits);

/* span.c */
/* Fills rs->fill[] for the draw's features and the target's formats, and
 * how texels are addressed (rs->pow2_repeat). */
void mote__fill_select(mote__raster_state *rs, mote_format format, mote_depth_format depth_format);
void mote__fill_generic(const mote__tri *t, const mote__target *tg, mote__rect r, int subpixel_bits);

/* The pixel loops in vector registers (span_simd.c): SSE2 or AVX2 on
 * x86-64, NEON on AArch64, with the scalar loops' bytes. MOTE_SIMD 0
 * keeps the scalar loops alone; size builds (-Os) and other processors
 * have no vector loops. */
#ifndef MOTE_SIMD
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__) && !(defined(MOTE_SPECIALISE_SPANS) && !MOTE_SPECIALISE_SPANS) \
    && ((defined(__x86_64__) && defined(__SSE2__)) || (defined(__aarch64__) && defined(__ARM_NEON)))
#define MOTE_SIMD 1
#else
#define MOTE_SIMD 0
#endif
#endif
enum { MOTE__ISA_SCALAR, MOTE__ISA_SSE2, MOTE__ISA_AVX2, MOTE__ISA_NEON, MOTE__ISA_BEST };
/* span_simd.h's variants, in the order of mote__simd_select's index */
#define MOTE__SIMD_VARIANTS (2 * 3 * 2 * 3 * 2)
extern const mote__fill_fn mote__fill_sse2[MOTE__SIMD_VARIANTS], mote__fill_avx2[MOTE__SIMD_VARIANTS],
    mote__fill_neon[MOTE__SIMD_VARIANTS];
/* span.c's specialised scalar fills, texture (none, nearest, bilinear) x
 * shade (flat, mono, RGB) x perspective (affine, exact, sub-span) x depth
 * (none, 16, 32) x format (RGBA8888, RGB565): what a vector fill hands a
 * triangle too narrow to fill a vector */
extern const mote__fill_fn mote__fill_table[3 * 3 * 3 * 3 * 2];
/* Their reciprocals min(floor(2^k / max(q, 1)), 2^31 - 1) of 4 (SSE2,
 * NEON) or 8 (AVX2) values, for the tests */
void mote__recip_sse2(const int32_t *q, int k, int32_t *out);
void mote__recip_avx2(const int32_t *q, int k, int32_t *out);
void mote__recip_neon(const int32_t *q, int k, int32_t *out);
/* Puts the vector fills of instruction set isa (MOTE__ISA_BEST: the best
 * this processor runs) into rs->fill[] where they draw the draw's
 * features; true when it did for any shade kind. Called by
 * mote__fill_select after the scalar choice (pow2_repeat is set). */
bool mote__simd_select(mote__raster_state *rs, mote_format format, mote_depth_format depth_format, int isa);
/* mote__fill_select with the vector fills of isa (MOTE__ISA_SCALAR: none),
 * for the tests to hold each set to the scalar loops */
void mote__fill_select_isa(mote__raster_state *rs, mote_format format, mote_depth_format depth_format, int isa);

/* line.c: points and lines in screen pixels, clipped to the region. */
void mote__draw_line(const mote__target *tg, mote__rect r, int x0, int y0, int x1, int y1,
                     mote_rgba color);
void mote__draw_pixel(const mote__target *tg, mote__rect r, int x, int y, mote_rgba color);

/* The sink of a draw: where the vertex stage hands its triangles, set
 * up. Without callbacks (the direct path, device.c) each is rasterised at
 * once into region of tg; the binner (bin.c) gives callbacks that keep
 * them in its arena for the tiles. The vertex stage knows nothing of
 * either. */
typedef struct mote__sink mote__sink;
struct mote__sink {
    const mote__target *tg;       /* the direct path's target: triangles, points */
    mote__rect region;            /* and lines are drawn into this part of it */
    /* Takes the draw's raster state for its triangles to point at, for as
     * long as they live, and sets rs; false when it has no room (the draw
     * ends: MOTE_ERR_OUT_OF_MEMORY, or MOTE_OK when full is set). NULL:
     * the triangles point at the draw's own, which lives as long as it. */
    bool (*begin)(mote__sink *s, const mote__raster_state *rs);
    /* Memory for a full vertex cache of bytes, or NULL (the draw then uses
     * a small one on the stack). NULL: never. */
    void *(*vertices)(mote__sink *s, size_t bytes);
    /* Where setup may write the next triangle, or NULL for anywhere. NULL:
     * anywhere. */
    mote__tri *(*place)(mote__sink *s);
    /* Takes a set-up triangle. NULL: rasterised into region of tg. */
    void (*triangle)(mote__sink *s, mote__tri *t);
    const mote__raster_state *rs; /* what the draw's triangles point at (begin) */
    bool full;                    /* takes no more: the draw stops */
};

/* draw.c: a draw (its desc resolved by mote__resolve_draw_desc) through
 * the vertex stage into a sink.
 * Part of a binned draw, set up apart from the rest (bin.c): its triangles
 * [tri0, tri1), and the draw's vertex cache, which mote__prepare_vertices
 * filled and which the draw's pieces share (NULL: the piece fills its own). */
typedef struct mote__piece {
    uint32_t tri0, tri1;
    const void *vertices;
} mote__piece;
/* piece NULL: the whole draw. */
mote_result mote__process_draw(mote_device *dev, const mote_mesh *mesh, const mote_draw_desc *desc,
                               mote__sink *sink, const mote__piece *piece);
/* Arena bytes of a binned draw's vertex cache. */
size_t mote__vertex_cache_bytes(const mote_mesh *mesh);
/* Transforms and lights vertices [first, end) of a draw into its vertex
 * cache (mote__vertex_cache_bytes), for the pieces of the draw to share.
 * Reads dev only, so pieces of vertices run in parallel. */
void mote__prepare_vertices(mote_device *dev, const mote_mesh *mesh, const mote_draw_desc *desc,
                            void *cache, uint32_t first, uint32_t end);
/* Fills the defaults in; MOTE_ERR_UNSUPPORTED for a feature left out of
 * the build. */
mote_result mote__resolve_draw_desc(const mote_draw_desc *in, const mote_mesh *mesh,
                                    mote_draw_desc *out);

/* bin.c */
/* Bytes of the tile table at the arena's start (tiles_x, tiles_y set). */
size_t mote__bin_table_bytes(const mote_device *dev);
/* mote_begin's reset (see bin.c). */
void mote__bin_begin(mote_device *dev);
void mote__bin_flush(mote_device *dev);
/* clear_drawn_tiles_only: pixels were drawn outside the tiles (points,
 * wireframe): the next clear is a full one. */
void mote__bin_mark_all_drawn(mote_device *dev);
/* Whether mote_draw records binned draws for mote__bin_run_draws, which
 * bins them in parallel groups (see bin.c). */
bool mote__bin_defers(const mote_device *dev);
mote_result mote__bin_run_draws(mote_device *dev);
/* Bins one draw now. */
mote_result mote__bin_draw(mote_device *dev, const mote_mesh *mesh, const mote_draw_desc *desc);

/* target.c */
static inline bool mote__band_mode(const mote_device *dev)
{
    return dev->desc.band_height < dev->desc.height;
}

static inline bool mote__binned(const mote_device *dev)
{
    return dev->bin.enabled && !mote__band_mode(dev);
}

void mote__full_target(const mote_device *dev, mote__target *tg, mote__counts *counts);
void mote__add_counts(mote_device *dev, const mote__counts *counts);
void mote__clear_rect(const mote_device *dev, const mote__target *tg, mote__rect r);
/* The full-frame clear of mote_begin: stripe index of MOTE__CLEAR_STRIPES
 * of whole rows, or all of them now. 32, not 8: when only the tiles drawn
 * into are cleared, the work lies where the scene is, and with few
 * stripes one of them may hold most of it (docs/performance.md). */
#define MOTE__CLEAR_STRIPES 32
void mote__clear_stripe(const mote_device *dev, int index);
void mote__clear_frame(mote_device *dev);

#endif
