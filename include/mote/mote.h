/*
 * mote.h - a small, fast and accurate 3D software renderer in C99.
 *
 * WHAT IT IS
 *   mote draws triangle meshes (points, wireframe, flat, Gouraud, textured)
 *   into a colour buffer and a depth buffer that you own. The core (this
 *   header, src/core) is freestanding: no malloc, no stdio, no OS, no global
 *   mutable state. It runs on a Cortex-M0+ and on a 64-core server and gives
 *   the same bytes on both. Host conveniences (scene files, textures, PNG)
 *   live in <mote/mote_io.h>.
 *
 * STEP BY STEP
 *   1. Describe the target and initialise a device:
 *        static uint8_t color[W * H * 4];
 *        static uint32_t depth[W * H];
 *        mote_device dev;
 *        mote_device_desc desc = {0};
 *        desc.width = W; desc.height = H;
 *        desc.color = color; desc.depth = depth;    (zero = defaults elsewhere)
 *        mote_result r = mote_device_init(&dev, &desc);
 *   2. Each frame: mote_begin(&dev, &frame) with a camera and lights (clears),
 *      mote_draw(&dev, &mesh, &draw) for every mesh, mote_end(&dev).
 *   3. The image is in your colour buffer (or, in band mode, was handed to
 *      your flush callback band by band).
 *
 * MEMORY
 *   The caller supplies every byte: the colour buffer, the depth buffer and,
 *   optionally, an arena for triangle binning. mote_device itself is a plain
 *   struct you may place anywhere. Nothing is allocated.
 *   - No arena: each mote_draw rasterises at once (full-frame mode) or is
 *     recorded (band mode, at most MOTE_MAX_DRAWS draws per frame) and replayed
 *     per band in mote_end. Mesh data must then stay valid until mote_end.
 *   - With an arena (desc.arena, desc.arena_size): triangles are set up once,
 *     binned into tiles, and rasterised in mote_end, tile by tile, through
 *     desc.parallel_for when given (the host's OpenMP loop is
 *     mote_parallel_openmp in <mote/mote_io.h>). With parallel_for (and no
 *     triangle_hook), mote_draw only records a triangle draw, and mote_end
 *     (or every MOTE_MAX_DRAWS-th draw) sets the recorded draws up in
 *     parallel groups: a frame of many meshes uses every thread for setup
 *     too, and so does one big mesh, whose triangles are cut into pieces
 *     (from 256 triangles; its vertices are transformed and lit first, in
 *     parallel, also those only back faces use). When the arena
 *     fills up, what is binned so far is rasterised and binning starts
 *     over: slower, never wrong. mote_arena_bytes_per_triangle() helps to
 *     size it. Mesh data and textures must stay valid until mote_end.
 *     With desc.clear_drawn_tiles_only, mote_begin clears only the tiles
 *     drawn into since their last clear (2 bytes per tile of the arena):
 *     the same bytes while mote is the only writer of the buffers.
 *   - Band mode (desc.band_height < desc.height): the colour and depth buffers
 *     hold only band_height rows; mote_end produces the frame band by band and
 *     calls desc.flush after each. Full frame and bands give the same bytes.
 *     With desc.band_bins (2 bytes a triangle) a band sets up only the
 *     triangles that touch it; with desc.color_back and desc.flush_wait the
 *     flush may send one buffer by DMA while the next band is drawn.
 *   What a frame in bands takes of RAM (docs/embedded.md has the figures of
 *   the firmware example, which `make bench-embedded` prints):
 *     band buffers  mote_band_bytes(width, band_height, format, depth_format)
 *                   (twice the colour part with desc.color_back)
 *     band bins     mote_band_bins_bytes(height, band_height, triangles)
 *     device        sizeof(mote_device): mostly MOTE_MAX_DRAWS recorded draws
 *     stack         about 9 KB at worst on 32-bit cores, 5.5 KB of it the
 *                   vertex cache of MOTE_VERTEX_CACHE entries (`make cross`
 *                   prints the bound, embedded/stack-usage.sh)
 *
 * ERRORS
 *   Every function that can fail returns a mote_result; mote_result_string()
 *   names it. Bad geometry never fails a frame: NaN/Inf vertices, indices out
 *   of range and degenerate triangles are dropped and counted in
 *   mote_stats. A device that failed to initialise draws nothing.
 *
 * CONVENTIONS
 *   World:      left-handed, y up (Babylon.js), units are yours.
 *   Camera:     look-at view; perspective with vertical fov (radians),
 *               aspect = width / height, near/far planes; depth maps
 *               near -> 0, far -> 1 (z/w, Direct3D style).
 *   Screen:     origin at the top-left pixel's top-left corner, x right,
 *               y down; pixel (x, y) has its centre at (x + 0.5, y + 0.5).
 *   Snapping:   after clipping and the divide, x and y are rounded to the
 *               nearest point of a grid of 1/2^subpixel_bits pixel (default
 *               8, as Direct3D 10+; 4 is the minimum). Coverage, culling and
 *               attribute setup all use the snapped positions.
 *   Coverage:   a pixel is drawn when its centre is inside the triangle; a
 *               centre exactly on an edge is inside only for a top edge
 *               (exactly horizontal, interior below) or a left edge. Two
 *               triangles sharing an edge never leave a gap and never both
 *               draw a pixel. Triangles with zero snapped area draw nothing.
 *   Winding:    front faces are those whose snapped screen-space vertices
 *               run counter-clockwise as seen on the screen (the tutorial's
 *               monkey.babylon and Babylon.js exports, checked by the tests
 *               on that file); see mote_draw_desc.front_face and .cull.
 *   Clipping:   in homogeneous space against near, far and a guard band of
 *               +-MOTE_GUARD_BAND pixels around the viewport, so that the
 *               fixed-point raster never overflows. Points and lines are
 *               clipped to the viewport and never write outside it.
 *   Attributes: colour and UV are perspective-correct by default (Vulkan's
 *               formula); affine and "exact every 2^k pixels" on request.
 *               Depth is linear in screen space.
 *   Lighting:   per light, n.l clamped at 0 (point and spot light: l from
 *               the surface point to the light; directional: l = -direction),
 *               times light colour and intensity, times Babylon.js's default
 *               falloff (point and spot light with a range: max(0, 1 -
 *               distance / range); spot light: 0 outside its cone, else
 *               cos(angle to the axis)^exponent), summed with the ambient colour,
 *               times the material colour, plus the material's emissive
 *               colour, clamped to [0,1] per channel (Babylon.js's
 *               StandardMaterial: clamp(lights x diffuse + emissive +
 *               ambient)), times the vertex colour when the mesh has them
 *               (mote_mesh.colors). Flat: one value per triangle from its
 *               geometric normal at its centroid (and the mean of its three
 *               vertex colours); Gouraud: per vertex from vertex normals.
 *   Colour:     shade S per channel in [0, 2^24] (2^24 = 1.0). Untextured
 *               channel = (S*255 + 2^23) >> 24; textured = (T*S + 2^23) >> 24
 *               where T is the texel channel (0..255).
 *   Textures:   texel (i, j) covers u in [i/w, (i+1)/w); nearest picks
 *               floor(u*w), bilinear weighs the four texels around
 *               u*w - 0.5 (weights in 1/256); repeat, mirror or clamp per
 *               axis. v = 0 addresses the top row unless
 *               material.v_origin_bottom is set.
 *   Depth test: a fragment passes when its depth is strictly less than the
 *               stored one. Depth z/w in [0,1] is D = round(z * (2^24 - 1))
 *               at the vertices, interpolated linearly in screen space;
 *               32-bit buffers store D, 16-bit buffers D >> 8.
 *
 * LIMITS
 *   width, height in [1, MOTE_MAX_SIZE]; vertex and index counts in
 *   [0, 2^31). Triangles are clipped (in float) to the guard band,
 *   +-2^MOTE_GUARD_BITS pixels around the viewport centre; float rounding
 *   may push a clipped vertex a little past it, so the hard bound, enforced
 *   at snapping, is |x|, |y| < 2^(MOTE_GUARD_BITS + 1) pixels from the
 *   origin: a vertex beyond it drops its triangle (counted invalid). All
 *   edge and plane arithmetic is 64-bit and cannot overflow inside that
 *   bound (the reasoning is at the top of src/core/setup.c).
 *
 * WHERE FLOAT IS USED
 *   The vertex stage (transform, lighting, clipping, perspective divide)
 *   uses single-precision float; triangle setup is integer (1/w reaches it
 *   as mantissa and exponent); there is no double anywhere in the core. Vertices and lights
 *   are taken relative to the camera's position (one subtraction of it
 *   from each mesh's translation and light position, exact when the two
 *   are close), so a scene far from the origin loses nothing beyond what
 *   its own float coordinates hold. Everything per pixel
 *   (edge walking, interpolation, texturing, depth, pixel formats) is
 *   integer. On a core without an FPU (Cortex-M0+, RV32IMAC) the vertex
 *   stage is integer too by default (MOTE_FIXED_VERTEX): float is left to
 *   a few dozen operations per draw (the matrices), done by libgcc's
 *   soft-float routines, never per vertex, triangle or pixel; they and 64-bit division add about 6 KB of flash there
 *   (`make cross` prints it), against 1 KB on a Cortex-M4F.
 */
#ifndef MOTE_H
#define MOTE_H

#include <stddef.h>
#include <stdint.h>
#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- compile-time options ---------------------------------------------- */

#ifndef MOTE_MAX_SIZE
/* Largest width and height of a device. */
#define MOTE_MAX_SIZE 4096
#endif

#ifndef MOTE_MAX_DRAWS
/* Draws that band mode (or a full-frame device without arena) can record
 * per frame. Each costs about 200 bytes inside mote_device. */
#define MOTE_MAX_DRAWS 64
#endif

#ifndef MOTE_VERTEX_CACHE
/* Entries of the vertex cache a draw keeps on the stack when it has no
 * arena (full frame without one, and band mode): a power of two, 2 or
 * more. Each entry is about 120 bytes with the float vertex stage and 170
 * with the integer one, so 32 take 3.8 or 5.4 KB of stack; 16 halve that
 * for some vertices transformed twice (docs/embedded.md measures both). */
#define MOTE_VERTEX_CACHE 32
#endif

#ifndef MOTE_GUARD_BITS
/* Guard band: geometry is clipped to +-2^MOTE_GUARD_BITS pixels around
 * the viewport centre before snapping. */
#define MOTE_GUARD_BITS 13
#endif

#ifndef MOTE_MAX_PARENTS
/* Parents a mesh's world matrix follows (mote_mesh.parent): a longer
 * chain is cut there, which also ends a cyclic one. The scene loader
 * refuses files whose chains are longer. */
#define MOTE_MAX_PARENTS 64
#endif

#ifndef MOTE_MAX_LIGHTS
/* Lights per frame. */
#define MOTE_MAX_LIGHTS 4
#endif

#ifndef MOTE_PIECE_MIN
/* Binned mode with parallel_for: a draw of at least twice this many
 * triangles (and more than its share of the frame's) is cut into pieces
 * that are set up on several threads, and each thread's group of draws
 * holds at least this many (fewer are set up on the calling thread). The
 * fuzz build lowers it, so that its small draws are cut too. */
#define MOTE_PIECE_MIN 128
#endif

/* Features a small build may leave out (stb-style: define to 0 before this
 * header is seen, for the library and its users alike; all default to 1).
 * Left out, a feature costs no flash, and asking for it at run time is
 * refused (MOTE_ERR_UNSUPPORTED, nothing drawn), or drawn without it and
 * counted in mote_stats.draws_simplified, or ignored, as each says below;
 * everything else draws the same bytes. docs/embedded.md gives the flash
 * each saves on a Cortex-M0+ (make switch-sizes). */
#ifndef MOTE_ENABLE_LINES
/* MOTE_MODE_WIREFRAME and MOTE_MODE_POINTS (mote_draw refuses them). */
#define MOTE_ENABLE_LINES 1
#endif
#ifndef MOTE_ENABLE_BINNING
/* desc.arena: tile binning and parallel setup (mote_device_init refuses
 * an arena). */
#define MOTE_ENABLE_BINNING 1
#endif
#ifndef MOTE_ENABLE_BILINEAR
/* MOTE_FILTER_BILINEAR (mote_draw refuses it). */
#define MOTE_ENABLE_BILINEAR 1
#endif
#ifndef MOTE_ENABLE_SUBSPAN
/* MOTE_PERSPECTIVE_SUBSPAN (mote_draw refuses it). */
#define MOTE_ENABLE_SUBSPAN 1
#endif
#ifndef MOTE_ENABLE_VERTEX_COLORS
/* mote_mesh.colors (mote_draw refuses any draw of a mesh that has them). */
#define MOTE_ENABLE_VERTEX_COLORS 1
#endif
#ifndef MOTE_ENABLE_LIGHT_FALLOFF
/* MOTE_LIGHT_SPOT and mote_light.range. The one exception to the rule
 * above: left out, a spot light lights nothing and a range is ignored
 * (the check that would refuse them costs more flash than the smallest
 * profile has to spare). */
#define MOTE_ENABLE_LIGHT_FALLOFF 1
#endif
#ifndef MOTE_ENABLE_ORTHOGRAPHIC
/* MOTE_PROJECTION_ORTHOGRAPHIC (mote_begin refuses it). */
#define MOTE_ENABLE_ORTHOGRAPHIC 1
#endif
#ifndef MOTE_ENABLE_ALPHA_TEST
/* MOTE_ALPHA_TEST: cut-outs from a texture's alpha. Left out, a material
 * asking for it draws opaque and mote_stats.draws_simplified counts it. */
#define MOTE_ENABLE_ALPHA_TEST 1
#endif
#ifndef MOTE_ENABLE_BLEND
/* MOTE_ALPHA_BLEND: colour = src a + dst (1 - a). Left out, a material
 * asking for it draws opaque and mote_stats.draws_simplified counts it. */
#define MOTE_ENABLE_BLEND 1
#endif
#ifndef MOTE_ENABLE_SPECULAR
/* mote_material.specular: Blinn-Phong highlights, per vertex. Left out, a
 * draw asking for them is drawn without and counted in
 * mote_stats.draws_simplified. */
#define MOTE_ENABLE_SPECULAR 1
#endif
#ifndef MOTE_ENABLE_FOG
/* mote_frame_desc.fog, per vertex. Left out, a fogged draw is drawn
 * without and counted in mote_stats.draws_simplified. */
#define MOTE_ENABLE_FOG 1
#endif
#ifndef MOTE_ENABLE_MIPMAPS
/* mote_material.mipmaps and mote_draw_desc.mip. Left out, a draw asking
 * for them samples level 0 and is counted in mote_stats.draws_simplified. */
#define MOTE_ENABLE_MIPMAPS 1
#endif
#ifndef MOTE_ENABLE_EMISSIVE
/* mote_material.emissive; left out, it is ignored, as the falloff is (a
 * check that refused it would cost as much as the feature). */
#define MOTE_ENABLE_EMISSIVE 1
#endif

#ifndef MOTE_ENABLE_EMISSIVE_MAP
/* MOTE_LAYER_EMISSIVE (mote_material.layers). Left out, such a layer is
 * skipped and the draw counted in mote_stats.draws_simplified; so are the
 * two below. */
#define MOTE_ENABLE_EMISSIVE_MAP 1
#endif
#ifndef MOTE_ENABLE_OPACITY_MAP
/* MOTE_LAYER_OPACITY. */
#define MOTE_ENABLE_OPACITY_MAP 1
#endif
#ifndef MOTE_ENABLE_SPECULAR_MAP
/* MOTE_LAYER_SPECULAR (with MOTE_ENABLE_SPECULAR). */
#define MOTE_ENABLE_SPECULAR_MAP 1
#endif

/* The vertex stage in integer arithmetic (src/core/vertex_fixed.c):
 * transform, normals and lighting, clipping, the divide and snapping with
 * no float operation per vertex, for cores without an FPU, where soft
 * float made most of a frame's instructions. 1 by default where the
 * compiler says there is no FPU (ARM without __ARM_FP, RISC-V without
 * __riscv_flen), else 0; define it either way, for the library and its
 * users alike. Pixels differ slightly from the float stage's (positions
 * are taken to 16 bits of the mesh's bounding sphere; docs/accuracy.md
 * gives the error), but one configuration gives the same bytes on every
 * target. Points, wireframe, vertex colours and frames with spot lights
 * or light ranges take the float stage, draw by draw. */
#ifndef MOTE_FIXED_VERTEX
#if (defined(__arm__) && !defined(__ARM_FP)) || (defined(__riscv) && !defined(__riscv_flen))
#define MOTE_FIXED_VERTEX 1
#else
#define MOTE_FIXED_VERTEX 0
#endif
#endif

/* ---- results ----------------------------------------------------------- */

#define MOTE__RESULTS(X)                                                    \
    X(MOTE_OK, "ok")                                                        \
    X(MOTE_ERR_INVALID_ARGUMENT, "invalid argument")                        \
    X(MOTE_ERR_OUT_OF_MEMORY, "out of memory")                              \
    X(MOTE_ERR_UNSUPPORTED, "unsupported")                                  \
    X(MOTE_ERR_IO, "input/output error")                                    \
    X(MOTE_ERR_PARSE, "malformed input")                                    \
    X(MOTE_ERR_RANGE, "value out of range")                                 \
    X(MOTE_ERR_LIMIT, "resource limit exceeded")                            \
    X(MOTE_ERR_TOO_MANY_DRAWS, "too many draws in one frame")               \
    X(MOTE_ERR_STATE, "call out of order")

typedef enum mote_result {
#define MOTE__ENUM(name, text) name,
    MOTE__RESULTS(MOTE__ENUM)
#undef MOTE__ENUM
    MOTE_RESULT_COUNT
} mote_result;

/* A short English name of a result ("out of memory"); never NULL. */
const char *mote_result_string(mote_result result);

/* ---- pixel formats ----------------------------------------------------- */

typedef enum mote_format {
    MOTE_FORMAT_DEFAULT = 0,      /* RGBA8888 */
    MOTE_FORMAT_RGBA8888,         /* bytes R, G, B, A in memory */
    MOTE_FORMAT_RGB565,           /* uint16_t, native byte order, R in bits 15..11 */
    MOTE_FORMAT_RGB565_SWAPPED,   /* RGB565 with the two bytes swapped (SPI LCDs) */
    MOTE_FORMAT_GREY8,            /* one byte, (77 R + 150 G + 29 B + 128) >> 8 */
    MOTE_FORMAT_COUNT
} mote_format;

typedef enum mote_depth_format {
    MOTE_DEPTH_FORMAT_DEFAULT = 0, /* 32-bit */
    MOTE_DEPTH_FORMAT_32,          /* uint32_t, 24 bits used */
    MOTE_DEPTH_FORMAT_16,          /* uint16_t */
    MOTE_DEPTH_FORMAT_NONE,        /* no depth buffer: depth test off */
    MOTE_DEPTH_FORMAT_COUNT
} mote_depth_format;

/* Bytes per pixel of a colour format (0 for an invalid one). */
int mote_format_bytes(mote_format format);
/* Bytes per pixel of a depth format (0 for NONE or invalid). */
int mote_depth_format_bytes(mote_depth_format format);
/* A colour format's name as the tools take it ("rgba8888", "rgb565",
 * "rgb565_swapped", "grey8"); NULL for an invalid one. */
const char *mote_format_name(mote_format format);
/* Whether a texture may have this format (RGBA8888, RGB565, GREY8). */
bool mote_format_is_texture(mote_format format);

typedef struct mote_rgba { uint8_t r, g, b, a; } mote_rgba;

/* ---- textures ---------------------------------------------------------- */

/* An image the caller owns. Any size from 1x1 to 65536x65536 (power of two
 * or not). stride 0 means width * bytes per pixel. */
typedef struct mote_texture {
    int width, height;
    mote_format format;           /* RGBA8888, RGB565 or GREY8 */
    int stride;                   /* bytes per row, a multiple of the texel size; 0 = packed */
    const void *pixels;           /* aligned to the texel size */
} mote_texture;

typedef enum mote_wrap {
    MOTE_WRAP_DEFAULT = 0,        /* repeat */
    MOTE_WRAP_REPEAT,
    MOTE_WRAP_CLAMP,
    MOTE_WRAP_MIRROR,
    MOTE_WRAP_COUNT
} mote_wrap;

/* A texture's mip chain: level 0 the texture, each next one half its
 * size (a 2x2 box filter), down to 1x1. Only power-of-two textures have
 * levels past 0. mote_mipmaps_build makes one in memory you give. */
#define MOTE_MAX_MIPS 17
typedef struct mote_mipmaps {
    int count;                    /* levels; 1: the texture alone */
    mote_texture level[MOTE_MAX_MIPS];
} mote_mipmaps;

/* Bytes mote_mipmaps_build needs for texture's levels past 0 (packed,
 * in its format); 0 for one that has none (not a power of two, 1x1, or
 * invalid). */
size_t mote_mipmaps_bytes(const mote_texture *texture);
/* Builds texture's chain into memory (size bytes, aligned to the texel
 * size) and *out; texture's pixels must stay valid while *out is used.
 * MOTE_ERR_INVALID_ARGUMENT for a bad texture or NULL out,
 * MOTE_ERR_OUT_OF_MEMORY when size is below mote_mipmaps_bytes. */
mote_result mote_mipmaps_build(const mote_texture *texture, void *memory, size_t size, mote_mipmaps *out);

typedef enum mote_mip {
    MOTE_MIP_DEFAULT = 0,         /* none */
    MOTE_MIP_NONE,                /* level 0 only */
    MOTE_MIP_TRIANGLE,            /* per triangle, the level nearest its texel-to-pixel
                                     scale: round(log2 sqrt(texel area / pixel area));
                                     every pixel loop */
    MOTE_MIP_PIXEL,               /* per pixel, the level nearest log2 of the largest
                                     texel step to the next pixel right or down (the
                                     screen-space derivative); the generic loop */
    MOTE_MIP_TRILINEAR,           /* per pixel, the two levels around that log2 L,
                                     blended (each sampled with the draw's filter):
                                     level floor(L) x (1 - f) + the next x f, f the
                                     step's mantissa below its leading bit, in 1/256
                                     (log2's linear approximation, as GPUs take it);
                                     Babylon.js's default; the generic loop */
    MOTE_MIP_COUNT
} mote_mip;

typedef enum mote_filter {
    MOTE_FILTER_DEFAULT = 0,      /* nearest */
    MOTE_FILTER_NEAREST,
    MOTE_FILTER_BILINEAR,
    MOTE_FILTER_COUNT
} mote_filter;

/* ---- meshes ------------------------------------------------------------ */

typedef struct mote_vertex {
    float position[3];
    float normal[3];
    float uv[2];
} mote_vertex;

/* How a material's alpha draws (Babylon.js's transparencyMode; glTF's
 * alphaMode). The test compares the texel's alpha (the texture's alpha
 * channel; 255 for formats without one, and nothing is cut without a
 * texture) with the cut-off, as Babylon.js's StandardMaterial does; the
 * blend weighs by the material's alpha, times the texel's when
 * use_texture_alpha is set (useAlphaFromDiffuseTexture); each 0..255. */
typedef enum mote_alpha_mode {
    MOTE_ALPHA_DEFAULT = 0,       /* opaque */
    MOTE_ALPHA_OPAQUE,            /* alpha ignored */
    MOTE_ALPHA_TEST,              /* a pixel whose texel alpha is below the
                                     cut-off is not drawn (no colour, no depth) */
    MOTE_ALPHA_BLEND,             /* colour = src a + dst (1 - a), on 8-bit
                                     channels (MOTE_ENABLE_BLEND) */
    MOTE_ALPHA_TEST_AND_BLEND,    /* both */
    MOTE_ALPHA_COUNT
} mote_alpha_mode;

/* Extra texture layers of a material (mote_material.layers), each with a
 * role, drawn by the generic pixel loop in Babylon.js StandardMaterial's
 * order. A layer reads the draw's texture coordinates (the mesh's uv)
 * through its own scale and offset; its texel is sampled at level 0 with
 * the draw's filter, as the draw's texture is.
 *   EMISSIVE  the texel's colour x factor is added to the lit colour
 *             before the draw's texture multiplies it: shade
 *             min(1, s + texel x factor), s the interpolated shade (with
 *             vertex colours this adds after they tint, unlike Babylon.js)
 *   OPACITY   alpha x= the texel's alpha (with from_rgb its luminance,
 *             (54 r + 183 g + 19 b + 128) >> 8) x factor[0]: both the
 *             alpha test's value and the blend's weight
 *   SPECULAR  the highlights (mote_material.specular, per vertex) x the
 *             texel's colour x factor per pixel; a fogged draw skips it
 *             (counted in mote_stats.draws_simplified)
 * A draw with no texture of its own takes layer 0's size and wrap for its
 * texture coordinates and draws as if its texture were white. */
typedef enum mote_layer_role {
    MOTE_LAYER_NONE = 0,          /* ignored */
    MOTE_LAYER_EMISSIVE,          /* MOTE_ENABLE_EMISSIVE_MAP */
    MOTE_LAYER_OPACITY,           /* MOTE_ENABLE_OPACITY_MAP */
    MOTE_LAYER_SPECULAR,          /* MOTE_ENABLE_SPECULAR_MAP */
    MOTE_LAYER_ROLE_COUNT
} mote_layer_role;

/* Layers one material may have; more are ignored. */
#define MOTE_MAX_LAYERS 3

/* mote_layer: one texture layer; zero is the default of each field.
 *   .role                   MOTE_LAYER_NONE (ignored)
 *   .texture                required (a layer without a valid one is ignored)
 *   .wrap_u, .wrap_v        MOTE_WRAP_REPEAT
 *   .u_scale, .v_scale      1; .u_offset, .v_offset 0 (over the mesh's uv,
 *                           as the material's own; v_origin_bottom is the
 *                           material's)
 *   .factor                 {1, 1, 1} when all three are 0; each 0..64
 *   .from_rgb               false: opacity from the texel's alpha */
typedef struct mote_layer {
    mote_layer_role role;
    const mote_texture *texture;
    mote_wrap wrap_u, wrap_v;
    float u_scale, v_scale;
    float u_offset, v_offset;
    float factor[3];
    bool from_rgb;
} mote_layer;

/* mote_material: a zeroed one is white, opaque, untextured.
 *   .color, .color_set      white
 *   .texture                none
 *   .wrap_u, .wrap_v        MOTE_WRAP_REPEAT
 *   .u_scale, .v_scale      1; .u_offset, .v_offset 0
 *   .v_origin_bottom        false: v = 0 is the top row
 *   .emissive               none
 *   .alpha_mode             MOTE_ALPHA_OPAQUE
 *   .alpha, .alpha_set      1 (opaque): alpha is read only with alpha_set
 *   .alpha_cutoff           0.4 (Babylon.js's alphaCutOff)
 *   .specular               none ({0}); .specular_power 64
 *   .use_texture_alpha      false: blending ignores the texel alpha
 *   .layers, .layer_count   none (see mote_layer)
 * Alpha needs MOTE_ENABLE_ALPHA_TEST / MOTE_ENABLE_BLEND; a build without
 * them draws such a material opaque and counts it (mote_stats.draws_simplified).
 * Blending is order-dependent: draw opaque meshes first, then alpha-tested
 * ones, then blended ones from the farthest to the nearest (Babylon.js's
 * order; mote_scene_draw_order in <mote/mote_io.h> sorts a scene so). */
typedef struct mote_material {
    mote_rgba color;              /* diffuse colour; alpha unused (see .alpha); {0} =
                                     white when color_set is false */
    bool color_set;               /* false: white (so a zeroed material is white) */
    const mote_texture *texture;  /* NULL: untextured; so is one of bad size, format, stride or alignment */
    mote_wrap wrap_u, wrap_v;
    float u_scale, v_scale;       /* 0 = 1 */
    float u_offset, v_offset;     /* uv' = uv * scale + offset */
    bool v_origin_bottom;         /* true: v = 0 addresses the bottom row */
    mote_rgba emissive;           /* added to the lit colour (see Lighting in
                                     CONVENTIONS); alpha unused; {0}: none */
    mote_alpha_mode alpha_mode;
    float alpha;                  /* the material's alpha, 0..1 (taken to 0..255,
                                     rounded); read only when alpha_set */
    bool alpha_set;
    bool use_texture_alpha;       /* blending: the alpha is x the texel's
                                     (Babylon.js's useAlphaFromDiffuseTexture,
                                     glTF's BLEND with a baseColor texture) */
    float alpha_cutoff;           /* TEST: texel alpha below it (0..1) is cut;
                                     0 = 0.4 */
    /* Blinn-Phong highlights (MOTE_ENABLE_SPECULAR), per vertex, added
     * after the lit colour x texture as Babylon.js's StandardMaterial
     * adds them: per light pow(max(0, n.h), specular_power) x the light's
     * specular colour x intensity x falloff, h halfway between the
     * directions to the light and to the eye; the sum x this colour.
     * Gouraud and textured draws only (flat draws have none). */
    mote_rgba specular;           /* {0}: none; alpha unused */
    float specular_power;         /* 0 = 64 (Babylon.js's specularPower) */
    /* texture's mip chain (mote_mipmaps_build), read when the draw's mip
     * asks for it; NULL: none */
    const mote_mipmaps *mipmaps;
    /* extra texture layers (mote_layer), layer_count of them, at most
     * MOTE_MAX_LAYERS read; NULL: none */
    const mote_layer *layers;
    int layer_count;
} mote_material;

/* A mesh's vertices and indices in little flash, as `mote-bake --compact`
 * writes them: integers that a draw dequantises by folding the scale and
 * offset into its matrices (and texture mapping), so that both vertex
 * stages draw them directly. Per vertex 14 bytes with 8-bit normals (16
 * with 16-bit ones) instead of mote_vertex's 32, and 2 bytes an index.
 *   positions  3 per vertex: position = positions x scale + offset, per axis
 *   normals    3 per vertex, int8 (normals8) or int16 (normals16), their
 *              direction only (each is normalised); both NULL: zero normals
 *   uvs        2 per vertex: uv = uvs x uv_scale + uv_offset; NULL: uv 0
 *   indices    3 per triangle, read when mote_mesh.indices is NULL
 * mote_mesh.vertex_count and index_count count them as for float meshes;
 * mote_mesh.vertices is ignored. */
typedef struct mote_compact {
    const int16_t *positions;
    const int8_t *normals8;
    const int16_t *normals16;
    const int16_t *uvs;
    const uint16_t *indices;
    float scale[3], offset[3];
    float uv_scale[2], uv_offset[2];
} mote_compact;

/* A mesh: vertices, triangles (3 indices each) and a transform.
 * world = parent's world * translate(position) * rotate * scale(scaling),
 * where rotate is rotation_quaternion (x, y, z, w) when use_quaternion is
 * set, else Euler angles applied z, then x, then y (Babylon's yaw-pitch-roll).
 * scaling {0,0,0} means {1,1,1}. Optionally a colour per vertex (colors,
 * last). */
typedef struct mote_mesh {
    const mote_vertex *vertices;
    uint32_t vertex_count;
    const uint32_t *indices;
    uint32_t index_count;         /* a multiple of 3; extra indices are ignored */
    float position[3];
    float rotation[3];
    float rotation_quaternion[4];
    bool use_quaternion;
    bool hidden;                  /* mote_draw draws nothing; still a parent */
    float scaling[3];
    const struct mote_mesh *parent;   /* followed up to MOTE_MAX_PARENTS levels */
    mote_material material;
    /* Bounding sphere in the mesh's own space, for whole-mesh frustum
     * rejection; radius <= 0 means unknown (never rejected). See
     * mote_mesh_update_bounds. */
    float bounds_center[3];
    float bounds_radius;
    /* One colour per vertex (vertex_count of them), or NULL for none. As in
     * Babylon.js's StandardMaterial, a vertex colour multiplies the
     * material colour (and the texture): a vertex of a lit Gouraud or
     * textured draw gets clamp(lighting) x material x colour, an unlit
     * draw material x colour, each interpolated across the triangle; a
     * flat draw gives a triangle the lighting at its centroid x material x
     * the mean of its three colours (unlit: material x that mean). Only
     * r, g, b count: alpha is ignored (mote does not blend). Points and
     * wireframe keep mote_draw_desc.point_color. A build with
     * MOTE_ENABLE_VERTEX_COLORS 0 refuses a draw of a mesh that has them.
     * Last, after the fields every draw reads (shorter code on cores with
     * short load offsets). */
    const mote_rgba *colors;
    /* The vertices and indices as integers (see mote_compact), or NULL:
     * vertices and indices above. */
    const mote_compact *compact;
} mote_mesh;

/* Computes bounds_center/bounds_radius from the vertices (skips NaN/Inf;
 * none finite, or no vertex array: radius 0, unknown). NULL: nothing. */
void mote_mesh_update_bounds(mote_mesh *mesh);

/* ---- camera and lights ------------------------------------------------- */

typedef enum mote_projection {
    MOTE_PROJECTION_PERSPECTIVE = 0,
    MOTE_PROJECTION_ORTHOGRAPHIC, /* parallel rays: no foreshortening (isometric views,
                                     Babylon.js's ORTHOGRAPHIC_CAMERA) */
    MOTE_PROJECTION_COUNT
} mote_projection;

typedef struct mote_camera {
    float position[3];
    float target[3];
    float up[3];                  /* {0,0,0} = {0,1,0} */
    float fov;                    /* perspective: vertical, radians; 0 = 0.8 */
    float znear, zfar;            /* 0 = 0.1, 100 (an orthographic camera takes znear
                                     as given: 0, or negative to see behind
                                     its position) */
    mote_projection projection;   /* perspective but for MOTE_PROJECTION_ORTHOGRAPHIC */
    /* orthographic: the view's left, right, bottom and top edges, in world
     * units about the line of sight (Babylon.js's orthoLeft, orthoRight,
     * orthoBottom, orthoTop: stretched when not of the image's aspect);
     * an empty box (left == right or bottom == top) is 2 units high,
     * centred, of the image's aspect */
    float ortho[4];
} mote_camera;

typedef enum mote_light_type {
    MOTE_LIGHT_NONE = 0,
    MOTE_LIGHT_POINT,             /* the tutorial's light */
    MOTE_LIGHT_DIRECTIONAL,
    MOTE_LIGHT_HEMISPHERIC,       /* weight 0.5 + 0.5 n.direction, color..ground */
    MOTE_LIGHT_SPOT,              /* a point light inside a cone along direction
                                     (MOTE_ENABLE_LIGHT_FALLOFF) */
    MOTE_LIGHT_TYPE_COUNT
} mote_light_type;

typedef struct mote_light {
    mote_light_type type;
    float position[3];            /* point */
    float direction[3];           /* directional: where light travels; hemispheric: up */
    float color[3];               /* {0,0,0} = white */
    float ground_color[3];        /* hemispheric only */
    float intensity;              /* 0 = 1 */
    /* Babylon.js's default falloff (MOTE_ENABLE_LIGHT_FALLOFF) */
    float range;                  /* point, spot: 0 = unlimited; else the light
                                     fades linearly to nothing at this distance */
    float spot_angle;             /* spot: the cone's full angle, radians */
    float spot_exponent;          /* spot: inside the cone, the light is scaled
                                     by cos(angle to the axis)^spot_exponent */
    float specular[3];            /* highlights' colour; {0,0,0} = white */
} mote_light;

typedef enum mote_fog_mode {
    MOTE_FOG_NONE = 0,
    MOTE_FOG_LINEAR,              /* f = (end - d) / (end - start) */
    MOTE_FOG_EXP,                 /* f = e^-(d density) */
    MOTE_FOG_EXP2,                /* f = e^-((d density)^2) */
    MOTE_FOG_COUNT
} mote_fog_mode;

/* Babylon.js's fog (MOTE_ENABLE_FOG): a pixel becomes colour x f +
 * fog colour x (1 - f), f clamped to [0, 1], d the distance from the
 * camera, worked out per vertex and interpolated. Gouraud and textured
 * draws only (flat draws are not fogged). */
typedef struct mote_fog {
    mote_fog_mode mode;
    float color[3];
    float density;                /* EXP, EXP2 */
    float start, end;             /* LINEAR */
} mote_fog;

/* ---- frames and draws -------------------------------------------------- */

/* mote_frame_desc: what mote_begin takes; zero is the default of each field.
 *   .camera                 see mote_camera (up {0,1,0}, fov 0.8, near 0.1, far 100)
 *   .lights, .light_count   none: only the ambient colour lights
 *   .ambient                {0,0,0}
 *   .fog                    none
 *   .keep_color             false: the colour buffer is cleared
 *   .keep_depth             false: the depth buffer is cleared
 */
typedef struct mote_frame_desc {
    mote_camera camera;
    mote_light lights[MOTE_MAX_LIGHTS];
    int light_count;
    float ambient[3];             /* added to every lit colour */
    mote_fog fog;
    bool keep_color;              /* true: do not clear the colour buffer */
    bool keep_depth;              /* true: do not clear the depth buffer
                                     (both: full-frame devices; band mode
                                     clears each band, as its buffer holds
                                     other rows between frames) */
} mote_frame_desc;

typedef enum mote_mode {
    MOTE_MODE_DEFAULT = 0,        /* gouraud, textured when the material has a texture */
    MOTE_MODE_POINTS,
    MOTE_MODE_WIREFRAME,
    MOTE_MODE_FLAT,
    MOTE_MODE_GOURAUD,
    MOTE_MODE_TEXTURED,           /* Gouraud x texture (material colour x texture when unlit;
                                     x vertex colours when the mesh has them) */
    MOTE_MODE_COUNT
} mote_mode;

typedef enum mote_perspective {
    MOTE_PERSPECTIVE_DEFAULT = 0, /* correct per pixel */
    MOTE_PERSPECTIVE_CORRECT,
    MOTE_PERSPECTIVE_AFFINE,      /* screen-linear: the retro "wobble" */
    MOTE_PERSPECTIVE_SUBSPAN,     /* 1/w exact every 2^subspan_log2 pixels from a row's
                                   * first and at its last, linear between */
    MOTE_PERSPECTIVE_COUNT
} mote_perspective;

typedef enum mote_front_face {
    MOTE_FRONT_DEFAULT = 0,       /* counter-clockwise on screen */
    MOTE_FRONT_CCW,
    MOTE_FRONT_CW,
    MOTE_FRONT_COUNT
} mote_front_face;

typedef enum mote_cull {
    MOTE_CULL_DEFAULT = 0,        /* back faces */
    MOTE_CULL_BACK,
    MOTE_CULL_NONE,
    MOTE_CULL_FRONT,
    MOTE_CULL_COUNT
} mote_cull;

/* mote_draw_desc: what mote_draw takes; a zeroed struct (or NULL) gives
 * the defaults.
 *   .mode                   MOTE_MODE_TEXTURED (Gouraud without a texture)
 *   .cull                   MOTE_CULL_BACK
 *   .front_face             MOTE_FRONT_CCW
 *   .perspective            MOTE_PERSPECTIVE_CORRECT
 *   .subspan_log2           3 (SUBSPAN: exact every 8 pixels; at most 6)
 *   .filter                 MOTE_FILTER_NEAREST
 *   .no_depth_test          false
 *   .no_depth_write         false
 *   .depth_less_equal       false
 *   .no_color_write         false
 *   .unlit                  false
 *   .point_color            the material colour (white without one)
 *   .mip                    MOTE_MIP_NONE (level 0)
 *   .lights_off             0: every light of the frame lights the draw
 *   .no_fog                 false
 */
typedef struct mote_draw_desc {
    mote_mode mode;
    mote_cull cull;
    mote_front_face front_face;   /* which screen winding is the front; a mesh
                                     whose world matrix mirrors (negative
                                     determinant) has the other one, as in
                                     Babylon.js, and its normals stay outward */
    mote_perspective perspective;
    int subspan_log2;             /* for SUBSPAN: 0 = 3 (8 pixels), at most 6 */
    mote_filter filter;
    bool no_depth_test;
    bool no_depth_write;
    bool unlit;                   /* colour = material (x vertex colour) (x texture),
                                     no lights */
    mote_rgba point_color;        /* points and wireframe, which ignore vertex
                                     colours; {0} = material colour */
    /* bit i set: the frame's light i does not light this draw (Babylon.js's
     * includedOnlyMeshes / excludedMeshes, a material's
     * maxSimultaneousLights) */
    uint32_t lights_off;
    bool no_fog;                  /* the frame's fog leaves this draw alone */
    /* A depth pre-pass (Babylon.js's needDepthPrePass) is two draws of a
     * mesh: no_color_write, which writes only its nearest depths, then
     * depth_less_equal, which passes where a pixel's depth equals the
     * stored one, so that only the nearest surface is drawn. They need
     * MOTE_ENABLE_BLEND (mote_draw refuses them without it). */
    bool depth_less_equal;
    bool no_color_write;
    mote_mip mip;                 /* with material.mipmaps (MOTE_ENABLE_MIPMAPS) */
} mote_draw_desc;

/* ---- device ------------------------------------------------------------ */

/* Called by a parallel executor: runs fn(task_arg, i) for i in [0, count),
 * in any order and on any threads, and returns when all are done. */
typedef void (*mote_task_fn)(void *task_arg, int index);
typedef void (*mote_parallel_for_fn)(void *user, int count,
                                     mote_task_fn fn, void *task_arg);

/* Band mode: called after each band with the band's first row y0, its row
 * count, and the colour buffer holding those rows (desc.color, or
 * desc.color_back for every other band when it is given). With flush_wait
 * set, the flush may start a transfer (DMA) and return at once: mote calls
 * flush_wait(user, color) before it draws into that buffer again. */
typedef void (*mote_flush_fn)(void *user, int y0, int rows,
                              const void *color, int stride);
typedef void (*mote_flush_wait_fn)(void *user, const void *color);

/* Testing aid: called for every triangle that reaches the rasteriser, after
 * clipping, snapping and culling, in submission order, with its snapped
 * screen vertices (fixed point, subpixel_bits fraction), their depth z/w
 * clamped to [0, 1] as the rasteriser uses it, and clip w, in the original
 * winding. Band mode calls it again for each band the triangle is drawn
 * in: every band without desc.band_bins, those it touches with them. */
typedef void (*mote_triangle_hook_fn)(void *user, const int32_t x[3],
                                      const int32_t y[3], const float z[3],
                                      const float w[3]);

/* mote_device_desc: what mote_device_init takes; zero is the default of
 * each field (mote_device_desc_defaults fills them in).
 *   .width, .height         required, 1..MOTE_MAX_SIZE
 *   .color_format           MOTE_FORMAT_RGBA8888
 *   .color                  required: band_height rows of color_stride bytes
 *   .color_stride           width x the format's bytes per pixel
 *   .depth_format           MOTE_DEPTH_FORMAT_32
 *   .depth                  required but with MOTE_DEPTH_FORMAT_NONE
 *   .clear_color            {0,0,0,0}
 *   .clear_depth            1.0 (far)
 *   .subpixel_bits          8 (4..8)
 *   .band_height            height: the whole frame at once
 *   .flush, .flush_user     none; required in band mode
 *   .arena, .arena_size     none: no binning
 *   .tile_size              64 (a power of two, 8..256)
 *   .clear_drawn_tiles_only false
 *   .parallel_for, .parallel_user          none: tiles in order on this thread
 *   .triangle_hook, .triangle_hook_user    none
 *   .no_tile_depth          false: binned tiles skip triangles behind their drawn depth
 */
typedef struct mote_device_desc {
    int width, height;
    mote_format color_format;
    void *color;                  /* band_height rows of stride bytes, aligned to the pixel size */
    int color_stride;             /* bytes per row, a multiple of the pixel size; 0 = packed */
    mote_depth_format depth_format;
    void *depth;                  /* band_height * width depth values, aligned to
                                     their size; may be NULL only with
                                     MOTE_DEPTH_FORMAT_NONE */
    mote_rgba clear_color;
    float clear_depth;            /* 0 = 1.0 (far) */
    int subpixel_bits;            /* 0 = 8; 4..8 */
    int band_height;              /* 0 = height (full frame) */
    mote_flush_fn flush;
    void *flush_user;
    /* Band mode, double buffering: a second colour buffer of color's size
     * and alignment (NULL: one buffer), and the wait for a flush's transfer
     * (NULL: flush returns when the buffer may be reused). */
    void *color_back;
    mote_flush_wait_fn flush_wait;
    /* Band mode, binning: memory for each triangle's band range,
     * mote_band_bins_bytes(height, band_height, triangles) bytes for a
     * frame of that many triangles (NULL: none). The first band records
     * which bands each triangle touches; the others then skip every draw
     * and triangle that does not touch them, instead of transforming and
     * setting up the whole frame again. Triangles past its size are
     * replayed in every band, as without it: slower, never wrong. */
    void *band_bins;
    size_t band_bins_size;
    void *arena;                  /* optional binning memory (full frame only), 8-byte aligned */
    size_t arena_size;            /* used in whole 8-byte words, up to 4 GiB */
    int tile_size;                /* 0 = 64; a power of two from 8 to 256 */
    /* Binned mode: mote_begin clears only the tiles drawn into since their
     * last clear, not the whole frame (a scene that covers part of the
     * screen saves most of the clear's memory traffic). Then mote must be
     * the only writer of color and depth between frames: draw into them
     * yourself and the next frame may keep it. A frame with keep_color or
     * keep_depth, points or wireframe makes the next clear a full one. */
    bool clear_drawn_tiles_only;
    mote_parallel_for_fn parallel_for; /* NULL = tiles in order on this thread
                                          (also best for one thread: a big
                                          draw is then not cut into pieces) */
    void *parallel_user;
    mote_triangle_hook_fn triangle_hook; /* NULL: none */
    void *triangle_hook_user;
    /* Binned mode keeps per tile a bound of the depths drawn in it (from
     * triangles that covered the whole tile) and skips, before walking
     * its edges, a triangle that is nowhere nearer: the same bytes, fewer
     * pixels tested. true turns that off (to measure it). */
    bool no_tile_depth;
} mote_device_desc;

/* Counters of the last frame: what was drawn and what was skipped. */
typedef struct mote_stats {
    uint32_t draws, meshes_culled;        /* whole meshes rejected by bounds */
    uint32_t triangles_in;                /* submitted */
    uint32_t triangles_invalid;           /* bad index or NaN/Inf */
    uint32_t triangles_clipped_away;      /* outside near/far/frustum */
    uint32_t triangles_backface;          /* culled by winding */
    uint32_t triangles_degenerate;        /* zero snapped area, or no pixel centre in its box */
    uint32_t triangles_drawn;             /* set up and rasterised */
    uint32_t triangles_black;             /* of those, unlit (zero shade): filled black, texture skipped */
    uint32_t tiles_empty, tiles_drawn;    /* binned mode */
    uint32_t tiles_clear_skipped;         /* clear_drawn_tiles_only: tiles still clear, not cleared */
    uint32_t arena_flushes;               /* binned mode: times the arena filled up */
    uint32_t tile_triangles_behind;       /* binned mode: a triangle's visits to tiles skipped
                                             as behind the depth drawn there */
    uint32_t draws_simplified;            /* asked for a feature the build left out
                                             (alpha test, blending, specular, fog,
                                             mipmaps, texture layers): drawn without it */
    uint64_t pixels_tested, pixels_written;
} mote_stats;

#include "mote_internal_types.h"  /* mote__draw, mote__bin: sizes only */

typedef struct mote_device {
    mote_device_desc desc;        /* with defaults filled in */
    bool ready;                   /* init succeeded */
    bool in_frame;
    bool clear_pending;           /* the frame's clear is to run beside the setup (bin.c) */
    mote_frame_desc frame;
    /* the camera's projection x view (column-major, as cglm's mat4),
     * without the camera's translation: the vertex stage works relative
     * to frame.camera.position, and frame's point and spot lights have it
     * subtracted (mote_begin) */
    float view_proj[16];
#if MOTE_ENABLE_LIGHT_FALLOFF
    /* per light of the frame, for a spot light's cone: 1 / |direction|
     * and cos(spot_angle / 2) (geometry.c's mote__falloff) */
    float spot_cone[MOTE_MAX_LIGHTS][2];
#endif
    mote_stats stats;
    /* recorded draws: band mode, and binned mode with parallel_for */
    int draw_count;
    mote__draw draws[MOTE_MAX_DRAWS];
    mote__bin bin;                /* binned mode state */
    mote__bands bands;            /* band mode state */
    int band_y0, band_rows;       /* region being drawn in direct mode */
} mote_device;

/* Checks desc, fills defaults and clears nothing yet. Returns
 * MOTE_ERR_INVALID_ARGUMENT for a missing or misaligned buffer, a size
 * outside [1, MOTE_MAX_SIZE], an unknown format, a band mode without flush,
 * or an arena in band mode; MOTE_ERR_UNSUPPORTED for an arena when the library
 * was built with MOTE_ENABLE_BINNING 0. */
mote_result mote_device_init(mote_device *dev, const mote_device_desc *desc);

/* The defaults mote_device_init fills in, for inspection. */
mote_device_desc mote_device_desc_defaults(const mote_device_desc *desc);

/* Starts a frame: sets camera and lights, clears colour and depth (full-frame
 * mode; band mode clears each band in mote_end). With parallel_for in binned
 * mode the clear runs beside the setup of the frame's first draws, before
 * any pixel is drawn: the buffers hold the frame only after mote_end.
 * Called again before mote_end, it abandons the frame's recorded draws. */
mote_result mote_begin(mote_device *dev, const mote_frame_desc *frame);

/* Draws (or records, or bins) one mesh; a hidden one is skipped (MOTE_OK).
 * draw may be NULL. Returns
 * MOTE_ERR_UNSUPPORTED, drawing nothing, for a mode, filter or perspective
 * that the library was built without (see MOTE_ENABLE_LINES, _BILINEAR,
 * _SUBSPAN), or for a mesh with colors in a build without
 * MOTE_ENABLE_VERTEX_COLORS. Band mode and binned mode with parallel_for
 * keep the mesh pointer until mote_end: the mote_mesh itself, not only its
 * arrays, must not change before then, so drawing one mesh at several
 * places in a frame takes one mote_mesh per draw. */
mote_result mote_draw(mote_device *dev, const mote_mesh *mesh,
                      const mote_draw_desc *draw);

/* Finishes the frame: rasterises binned tiles or renders the bands. */
mote_result mote_end(mote_device *dev);

/* Statistics of the current or last frame (NULL for a NULL device). */
const mote_stats *mote_device_stats(const mote_device *dev);

/* Arena bytes one binned triangle needs at most (setup record and bin
 * entry); 72 more for one with specular highlights or fog. */
size_t mote_arena_bytes_per_triangle(void);

/* Bytes a band-mode device needs for its buffers (colour + depth), so that
 * firmware can size static buffers: mote_band_bytes(320, 16, RGB565, 16);
 * 0 for a size no device can have (outside [1, MOTE_MAX_SIZE]). */
size_t mote_band_bytes(int width, int band_height, mote_format color,
                       mote_depth_format depth);

/* Bytes of desc.band_bins for a band-mode frame of up to triangles
 * triangles (2 a triangle); 0 when band binning does not apply: a full
 * frame, or more than 255 bands. */
size_t mote_band_bins_bytes(int height, int band_height, uint32_t triangles);

/* Reads pixel (x, y) of a full-frame colour buffer as RGBA, whatever the
 * format: alpha as stored in RGBA8888 (255 where triangles drew, the clear
 * colour's elsewhere), 255 in the others. Out-of-range coordinates give
 * {0,0,0,0}. */
mote_rgba mote_read_pixel(const mote_device *dev, int x, int y);

/* Converts one row of pixels between formats (any to RGBA8888 or from it);
 * an unknown format converts nothing. */
void mote_convert_row(const void *src, mote_format src_format,
                      void *dst, mote_format dst_format, int count);

/* ---- the vertex stage, exposed for tools and tests ------------------- */

/* Column-major 4x4 matrices (cglm layout: m[col][row] as float[16]).
 * mote_mesh_world_matrix of a NULL mesh is the identity, and so are the
 * view and projection matrices of a NULL camera; a NULL matrix is left
 * unwritten. */
void mote_mesh_world_matrix(const mote_mesh *mesh, float world[16]);
void mote_camera_view_matrix(const mote_camera *camera, float view[16]);
void mote_camera_projection_matrix(const mote_camera *camera, float aspect,
                                   float proj[16]);

/* Projects a world-space point to screen pixels (x, y) and depth z with
 * the device's camera: z is 0 on the near plane, 1 on the far one, above
 * 1 beyond it. Returns false behind the near plane, or for a NULL
 * argument. */
bool mote_project(const mote_device *dev, const float world_point[3],
                  float *x, float *y, float *z);

/* Deterministic sine and cosine (the same bits on every target), used for
 * all rotations so that host and firmware agree. */
float mote_sinf(float radians);
float mote_cosf(float radians);
float mote_tanf(float radians);

#ifdef __cplusplus
}
#endif

#endif /* MOTE_H */
