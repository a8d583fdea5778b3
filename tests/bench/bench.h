/*
 * bench.h - what the benchmark (bench.c) and its llvmpipe harness (gl.c)
 * share: a scene as plain mote structs, posed per frame, and a mode.
 */
#ifndef MOTE_BENCH_H
#define MOTE_BENCH_H

#include <mote/mote.h>
#include <mote/mote_io.h>

typedef struct bench_scene {
    char name[32];
    int width, height;
    int frames;                   /* frames asked for (the time cap may stop earlier) */
    mote_mesh *meshes;            /* drawn in this order (order 0) or reversed (order 1) */
    int mesh_count;
    float *base_rotation;         /* 3 per mesh: the pose at frame 0 */
    float *spin;                  /* 3 per mesh: radians added per frame */
    mote_frame_desc frame;
    mote_rgba clear_color;
    uint32_t triangles;           /* submitted per frame */
    /* ownership */
    mote_scene loaded;
    bool has_loaded;
    mote_vertex *gen_vertices;
    uint32_t *gen_indices;
    uint8_t *gen_texels;
    mote_texture gen_texture;
} bench_scene;

typedef struct bench_mode {
    const char *name;
    mote_draw_desc draw;
    int subpixel_bits;            /* 0 = 8 */
    mote_depth_format depth;      /* DEFAULT = 32 */
} bench_mode;

/* Rotates every mesh of the scene to its pose at frame f. */
void bench_pose(bench_scene *s, int f);

typedef struct bench_err {
    bool valid;
    double psnr;                  /* dB over RGB of the whole image; INFINITY when identical */
    int max_err;                  /* largest channel difference over pixels both cover */
    long mismatch;                /* pixels covered by one image only */
} bench_err;

/* ---- the reference renderer (bench_ref.c, built only beside tests/ref) ---- */

/* Fills rgba (RGBA8888, top row first) and cov (1 = covered) with the
 * reference image of frame f in mode m; returns a one-line description. */
const char *bench_ref_render(bench_scene *s, const bench_mode *m, int f, uint8_t *rgba, uint8_t *cov);
/* Error of image a against b with tests/ref's metrics (ref_compare). */
bench_err bench_ref_compare(const uint8_t *a, const uint8_t *ca, const uint8_t *b, const uint8_t *cb,
                            int w, int h);

/* ---- llvmpipe through OSMesa (gl.c) ------------------------------------- */

typedef struct bench_gl bench_gl;

/* Creates an OSMesa context of the scene's size and uploads its meshes and
 * textures; NULL with a reason in why when OSMesa is not there. */
bench_gl *bench_gl_create(const bench_scene *s, char *why, size_t why_size);
/* Draws frame f; true when the mode is one GL can draw (fixed-function:
 * flat, Gouraud, textured nearest or bilinear, perspective-correct). The
 * colour is in rgba (top row first, RGBA8888) after the call, depth < 1
 * marks covered pixels in cov (when cov is not NULL). */
bool bench_gl_frame(bench_gl *g, bench_scene *s, const bench_mode *m, int f,
                    const uint8_t **rgba, uint8_t *cov);
const char *bench_gl_renderer(const bench_gl *g);
void bench_gl_destroy(bench_gl *g);

#endif
