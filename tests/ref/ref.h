/*
 * ref.h - the reference renderer: the oracle that tests and benchmarks
 * measure mote against. Deliberately simple and slow, written from
 * mote.h's CONVENTIONS (and the Direct3D 11 / Vulkan rules they cite), not
 * from mote's raster code, sharing only the public structs.
 *
 *   Coverage   per-pixel centre test with exact 64-bit edge functions on
 *              snapped vertices and the top-left rule (D3D11 §3.4.2.1).
 *   Pipeline   double precision: world -> clip, clipping in homogeneous
 *              space (near, far, the same guard band), divide, snapping to
 *              the device's sub-pixel grid (round half up), culling on the
 *              snapped area, perspective-correct barycentrics (Vulkan's
 *              formula) from the snapped positions, depth linear in screen
 *              space compared in double, lighting and vertex colours in
 *              double, texture addressing and colour rounding as
 *              CONVENTIONS state them (bilinear with exact, not 1/256,
 *              weights), mip levels from exact texel derivatives.
 *   Metrics    coverage mismatches, max / mean channel error, PSNR and the
 *              count of pixels off by more than 1 LSB between two images.
 *
 * Limits: snapped coordinates must stay within +-2^30 (true after the
 * guard band); points and wireframe are not rendered (ref_draw says so).
 */
#ifndef MOTE_TEST_REF_H
#define MOTE_TEST_REF_H

#include <mote/mote.h>
#include <stdbool.h>
#include <stdint.h>

/* ---- exact coverage ------------------------------------------------------ */

/* Is the centre of pixel (px, py) inside the triangle with snapped vertices
 * X, Y (fixed point, F fractional bits), either winding? Zero area: never. */
bool ref_inside(const int32_t X[3], const int32_t Y[3], int F, int px, int py);

/* Adds 1 (saturating at 255) to count[py * width + px] for every pixel of a
 * width x height viewport that the triangle covers; returns how many. */
long ref_cover(const int32_t X[3], const int32_t Y[3], int F, int width, int height,
               uint8_t *count);

/* ---- a target image ------------------------------------------------------- */

typedef struct ref_target {
    int width, height;
    int subpixel_bits;            /* 4..8, as the device compared with */
    uint8_t *rgba;                /* width * height * 4, alpha 255 where drawn */
    uint8_t *cov;                 /* fragments written per pixel (saturating) */
    double *depth;                /* z/w of the nearest fragment; 1 = clear */
    double *lod;                  /* NULL, or (the caller's, width * height) each written
                                     fragment's exact level of detail log2 rho (mip draws) */
    bool mip_step;                /* ref_draw: ref_shading.mip_step */
    /* set by ref_begin */
    mote_frame_desc frame;
    double view_proj[16];         /* column-major like mote's */
    /* counters of ref_draw */
    long triangles_drawn, triangles_culled, triangles_degenerate, triangles_invalid;
} ref_target;

bool ref_target_init(ref_target *t, int width, int height, int subpixel_bits);
void ref_target_free(ref_target *t);
/* Clears colour (alpha of clear kept), coverage counts and depth. */
void ref_clear(ref_target *t, mote_rgba color, double depth);

/* ---- one snapped triangle ------------------------------------------------- */

typedef struct ref_vert {
    double z;                     /* z/w, depth in [0,1] */
    double w;                     /* clip w (> 0) */
    double s[3];                  /* shade per channel in [0,1] (light x material x vertex colour) */
    double u, v;                  /* texture coordinates in texels */
    double a[3];                  /* additive colour in [0,1] (highlights, fog): a pixel is
                                     texel x s + 255 a, clamped */
    double muv[2];                /* the mesh's own uv, for texture layers */
} ref_vert;

typedef struct ref_shading {
    const mote_texture *texture;  /* NULL: untextured */
    mote_wrap wrap_u, wrap_v;     /* DEFAULT = repeat */
    bool bilinear;
    bool affine;                  /* screen-linear attributes (for comparisons only) */
    bool depth_test, depth_write;
    /* alpha (mote_material.alpha_mode): the texel's alpha read (exactly
     * filtered with bilinear), a pixel cut where it is below cutoff x 255,
     * blended as src a + dst (1 - a) with a = alpha (x texel alpha / 255
     * with texel_alpha) */
    bool alpha_test, blend, texel_alpha;
    double alpha, cutoff;
    /* texture layers (mote_layer), as mote.h states them: each samples at
     * the mesh's uv x its scale + offset (v flipped with v_bottom), with
     * the draw's filter; emissive adds texel / 255 x factor to the
     * clamped shade (at most 1), specular scales the additive colour by
     * texel / 255 x factor, opacity multiplies the test's and the blend's
     * alpha by min(255, texel alpha (or luminance, (54 r + 183 g + 19 b) /
     * 256) x factor) / 255 */
    const mote_layer *layers[MOTE_MAX_LAYERS];
    int layer_count;
    bool v_bottom;
    /* mip selection (mote_draw_desc.mip) over mips, a chain whose level 0
     * is texture; NULL: level 0 only. The level of detail L is log2 rho in
     * level-0 texels per pixel, exactly: per triangle rho^2 the texel area
     * over the pixel area; per pixel (and trilinear) rho the largest of
     * |du/dx|, |dv/dx|, |du/dy|, |dv/dy|, the perspective-correct
     * derivatives at the pixel centre. Nearest level: round(L) within the
     * chain; trilinear: levels floor(L) and the next, the next weighed by
     * rho / 2^floor(L) - 1 (exact, not in 1/256), each sampled at u / 2^k. */
    const mote_mipmaps *mips;
    mote_mip mip;
    bool mip_step;                /* per pixel: rho from the texel steps to the next pixel
                                     right and down (mote.h's words) instead */
} ref_shading;

/* Rasterises one triangle with snapped vertices X, Y (the target's
 * subpixel_bits), shading each covered pixel from v; returns pixels written. */
long ref_triangle(ref_target *t, const ref_shading *sh, const int32_t X[3],
                  const int32_t Y[3], const ref_vert v[3]);

/* Texel lookup as CONVENTIONS define it; u, v in texels; out RGB 0..255
 * (bilinear: exact weights, not rounded to 1/256; result not rounded). */
void ref_sample(const mote_texture *tex, mote_wrap wu, mote_wrap wv, bool bilinear,
                double u, double v, double out[3]);
/* The same for the texel alpha (255 for textures without alpha). */
double ref_sample_alpha(const mote_texture *tex, mote_wrap wu, mote_wrap wv, bool bilinear,
                        double u, double v);

/* ---- the whole pipeline ----------------------------------------------------- */

/* Starts a frame: camera matrices in double, clears (unless the frame keeps
 * colour / depth) to clear_color and depth 1. */
void ref_begin(ref_target *t, const mote_frame_desc *frame, mote_rgba clear_color);

/* Draws a mesh as mote_draw would, in double. Returns false (drawing
 * nothing) for points and wireframe, which the reference does not render. */
bool ref_draw(ref_target *t, const mote_mesh *mesh, const mote_draw_desc *draw);

/* ---- error metrics ---------------------------------------------------------- */

typedef struct ref_metrics {
    long pixels;                  /* width * height */
    long covered_a, covered_b;    /* pixels drawn by each image */
    long coverage_mismatch;       /* drawn by one and not the other */
    long compared;                /* drawn by both: colour statistics are over these */
    int max_err;                  /* largest absolute channel error */
    double mean_err;              /* mean absolute channel error (R, G, B) */
    double psnr;                  /* dB over R, G, B of the compared pixels; inf when equal */
    double psnr_image;            /* dB over the whole image, coverage mismatches included */
    long off_by_more_than_1;      /* compared pixels with a channel error > 1 */
    double within_1_fraction;     /* 1 - off_by_more_than_1 / compared (1 when none) */
} ref_metrics;

/* Compares two RGBA8888 images (tightly packed rows). cov_a / cov_b say
 * which pixels each image drew (non-zero = drawn); NULL: every pixel. */
ref_metrics ref_compare(const uint8_t *rgba_a, const uint8_t *cov_a, const uint8_t *rgba_b,
                        const uint8_t *cov_b, int width, int height);

#endif
