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
 *   raster.c    exact scanline edge walking over a region
 *   format.c    colour and depth formats (format.h): conversion, reading
 *               pixels back
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
/* K of the reciprocal 2^K / (Q >> shift) for all but triangles whose
 * attributes span more than 2^27 units (setup.c) */
#define MOTE__RBITS 54

/* Small helpers called from several places: inline in speed builds, one
 * out-of-line copy in size builds (-Os), where each inlined copy is a long
 * 64-bit sequence on a 32-bit core. */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__)
#define MOTE__SPEED_INLINE static __attribute__((unused, noinline))
#else
#define MOTE__SPEED_INLINE static inline
#endif

/* floor(v / 2^k) for 0 <= k < 63, without relying on how >> treats
 * negative numbers (implementation-defined in C99): a negative v is
 * complemented, shifted and complemented back, through a mask rather than
 * a branch (setup and the walk take it of numbers of either sign). */
MOTE__SPEED_INLINE int64_t mote__floor_shift64(int64_t v, int k)
{
    uint64_t neg = 0u - (uint64_t)(v < 0);
    return (int64_t)((((uint64_t)v ^ neg) >> k) ^ neg);
}

/* the same for a 32-bit v, 0 <= k < 31 (short enough to inline anywhere) */
static inline int32_t mote__floor_shift32(int32_t v, int k)
{
    uint32_t neg = 0u - (uint32_t)(v < 0);
    return (int32_t)((((uint32_t)v ^ neg) >> k) ^ neg);
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

/* A vertex after the vertex stage: clip position and the attributes that
 * clipping interpolates. */
typedef struct mote__cvert {
    float x, y, z, w;
    float s[3];                   /* lit colour, 0..1 */
    float u, v;                   /* texture coordinates in texels */
} mote__cvert;

/* A vertex as setup reads it: its attributes in the pixel stage's integer
 * units, converted once per vertex rather than at every corner of every
 * triangle sharing it. */
typedef struct mote__svert {
    int64_t texel[2];             /* u and v, 16.16 texels */
    int32_t s[3];                 /* lit colour, MOTE__SHADE_ONE = 1 */
    int32_t z;                    /* depth, 0..MOTE__DEPTH_MAX */
    float depth;                  /* what z rounds: z/w clamped to [0, 1] (the triangle hook's) */
    float w;                      /* clip w: setup's perspective ratios */
} mote__svert;

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
typedef enum mote__shade_kind {
    MOTE__SHADE_FLAT, MOTE__SHADE_MONO, MOTE__SHADE_RGB, MOTE__SHADE_BLACK, MOTE__SHADE_COUNT
} mote__shade_kind;

struct mote__tri;
struct mote__target;
struct mote__rect;
/* Fills the pixels of one triangle inside a region of the screen: the edge
 * walk of raster.c with one of span.c's pixel loops inside. */
typedef void (*mote__fill_fn)(const struct mote__tri *t, const struct mote__target *tg,
                              struct mote__rect r, int subpixel_bits);

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
    int32_t depth_half;           /* half a unit of the depth buffer, in the depth plane's 1/65536 */
} mote__raster_state;

/* Interpolated attributes of a triangle, by index. A binned triangle's
 * record ends after the last plane it has (mote__plane_count): red, the
 * texels, then green and blue, so that a grey textured triangle, a lit
 * textured mesh's, keeps three planes of five (208 bytes, not 256). */
enum { MOTE__A_R, MOTE__A_U, MOTE__A_V, MOTE__A_G, MOTE__A_B, MOTE__ATTRS };

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
    return shade == MOTE__SHADE_RGB || (shade == MOTE__SHADE_MONO && a == MOTE__A_R);
}

/* How many planes, from the first, a triangle of this kind keeps: up to
 * its last one (mote__has_plane); those before it that it lacks are 0. */
static inline int mote__plane_count(int shade, bool textured)
{
    if (shade == MOTE__SHADE_BLACK)
        return 0;
    if (shade == MOTE__SHADE_RGB)
        return MOTE__A_B + 1;
    if (textured)
        return MOTE__A_V + 1;
    return shade == MOTE__SHADE_MONO ? MOTE__A_R + 1 : 0;
}

/* A set-up triangle. Planes are evaluated at pixel centres relative to the
 * origin pixel (ox, oy) so that values stay small; stepping is exact integer
 * addition, so any region of the triangle gives the same pixels. */
typedef struct mote__tri {
    const mote__raster_state *rs;
    int32_t X[3], Y[3];           /* snapped, from the top vertex (see setup.c), original winding */
    int16_t xmin, ymin, xmax, ymax; /* pixel bounding box, inclusive, clamped to the viewport */
    int16_t ox, oy;
    uint8_t shade;                /* mote__shade_kind */
    int8_t rbits;                 /* K of the reciprocal r = 2^K / (q >> 10) */
    uint8_t order;                /* walk order (raster.c): bits 0-1, 2-3, 4-5 the top,
                                   * middle and bottom vertex; bit 6: long edge on the left */
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
    return planes == 0 ? MOTE__TRI_BYTES(0) : planes <= MOTE__A_V + 1 ? MOTE__TRI_BYTES(MOTE__A_V + 1) : sizeof(mote__tri);
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

MOTE__SPEED_INLINE void mote__edge_step(mote__edge *e)
{
    /* without a branch: whether the remainder wraps changes from row to
     * row in no pattern a predictor can learn */
    e->err -= e->rstep;
    int64_t wrap = -(int64_t)(e->err < 0);   /* all ones or zero */
    e->x += e->qstep - wrap;
    e->err += e->den & wrap;
}

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

/* span.c */
/* Fills rs->fill[] for the draw's features and the target's formats, and
 * how texels are addressed (rs->pow2_repeat). */
void mote__fill_select(mote__raster_state *rs, mote_format format, mote_depth_format depth_format);
void mote__fill_generic(const mote__tri *t, const mote__target *tg, mote__rect r, int subpixel_bits);

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
