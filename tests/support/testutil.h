/*
 * testutil.h - helpers shared by the accuracy, raster-rule, clipping and
 * hostile-input tests: a seeded PRNG, a device that draws triangles at
 * exact screen positions (tu_screen), a capture of the snapped triangles
 * mote hands to its rasteriser (the device's triangle_hook), and buffers
 * with canaries around them to catch out-of-bounds writes.
 */
#ifndef MOTE_TEST_UTIL_H
#define MOTE_TEST_UTIL_H

#include <mote/mote.h>
#include "ref/ref.h"
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* ---- seeded PRNG (splitmix64): the same numbers on every machine -------- */

typedef struct tu_rng { uint64_t s; } tu_rng;

tu_rng tu_rng_seed(uint64_t seed);
uint64_t tu_rand_u64(tu_rng *r);
/* uniform in [0, 1) with 53 bits */
double tu_rand01(tu_rng *r);
/* uniform in [lo, hi) */
double tu_rand_range(tu_rng *r, double lo, double hi);
/* uniform integer in [lo, hi] */
int64_t tu_rand_int(tu_rng *r, int64_t lo, int64_t hi);

/* ---- snapped triangles captured from mote (the triangle hook) ------------ */

typedef struct tu_tri {
    int32_t X[3], Y[3];
    float z[3], w[3];
} tu_tri;

typedef struct tu_capture {
    tu_tri *tris;
    size_t count, capacity;
} tu_capture;

/* The mote_triangle_hook_fn: user is a tu_capture. */
void tu_capture_hook(void *user, const int32_t x[3], const int32_t y[3], const float z[3],
                     const float w[3]);
void tu_capture_reset(tu_capture *c);
void tu_capture_free(tu_capture *c);

/* ---- a device for triangles placed in screen space ---------------------- */

/* Camera at the origin looking down +z (view space = world space), so a
 * world vertex (x, y, w) has clip w = w; tu_screen_vertex inverts the
 * projection so that a vertex lands on screen position (sx, sy) pixels.
 * Colour GREY8 (0 = not drawn), no depth buffer unless asked. */
typedef struct tu_screen {
    int width, height, subpixel_bits;
    mote_device dev;
    mote_frame_desc frame;
    float proj[16];
    uint8_t *color;               /* width * height, GREY8 */
    uint32_t *depth;              /* NULL without depth */
    tu_capture cap;               /* triangles of the last tu_screen_draw */
} tu_screen;

bool tu_screen_init(tu_screen *s, int width, int height, int subpixel_bits, bool with_depth);
void tu_screen_free(tu_screen *s);

/* World position of a vertex that projects to (sx, sy) pixels with clip w. */
void tu_screen_vertex(const tu_screen *s, double sx, double sy, double w, float out[3]);

/* Draws n triangles (3n screen positions and w's) in one frame, unlit,
 * white, no culling; the frame's colour is left in s->color and the
 * snapped triangles in s->cap. Returns mote_draw's result. */
mote_result tu_screen_draw(tu_screen *s, const double *sx, const double *sy, const double *w,
                           int n);

/* The same for a mesh already in tu_screen's world space (keeps its draw
 * desc; NULL = unlit white, no culling). */
mote_result tu_screen_draw_mesh(tu_screen *s, const mote_mesh *mesh, const mote_draw_desc *d);

/* Pixels drawn in the last frame (colour != 0) as 0/1 in out (w * h). */
void tu_screen_coverage(const tu_screen *s, uint8_t *out);

/* A sub-pixel grid position as a double pixel coordinate. */
double tu_grid(const tu_screen *s, int64_t fixed);

/* ---- guarded buffers ---------------------------------------------------- */

/* size bytes with 64 canary bytes before and after; tu_guard_ok checks them. */
void *tu_guard_alloc(size_t size);
bool tu_guard_ok(const void *p, size_t size);
void tu_guard_free(void *p);

/* ---- images ------------------------------------------------------------- */

/* RGBA8888 copy of a full-frame device's colour buffer (any format). */
void tu_read_rgba(const mote_device *dev, uint8_t *rgba);

/* Writes an RGBA image as binary PPM (for looking at failures); ignores errors. */
void tu_write_ppm(const char *path, const uint8_t *rgba, int width, int height);

/* ---- mote against the reference on a whole scene -------------------------- */

typedef struct tu_vs_opts {
    int width, height;
    int subpixel_bits;            /* 0 = 8 */
    mote_depth_format depth;      /* DEFAULT = 32-bit */
} tu_vs_opts;

typedef struct tu_vs_result {
    ref_metrics m;                /* mote (a) against the reference (b) */
    long unexplained;             /* coverage mismatches with no reference edge in their 3x3 */
} tu_vs_result;

/* Renders n meshes (draws[i], or draws[0] for all when one_desc) with mote
 * and with the reference, and compares. Mote's coverage is found by
 * rendering twice, over black and over white: drawn pixels are equal in
 * both. mote_image / ref_rgba (optional, w*h*4) receive the images over
 * black. Returns false when a device or buffer could not be set up or a
 * mote call failed. */
bool tu_vs_ref(const tu_vs_opts *o, const mote_frame_desc *frame, const mote_mesh *meshes, int n,
               const mote_draw_desc *draws, bool one_desc, tu_vs_result *out, uint8_t *mote_image,
               uint8_t *ref_rgba);

#endif
