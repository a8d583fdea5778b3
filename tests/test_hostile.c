/*
 * test_hostile.c - numerically hostile input never crashes and never writes
 * out of bounds: NaN/Inf coordinates (the triangle is dropped), degenerate
 * and zero-area triangles (nothing drawn), w close to 0, extreme fov, near
 * and far, very large meshes, indices out of range (rejected at draw).
 *
 * Every buffer mote writes (colour, depth, arena) has canary bytes on both
 * sides (tu_guard_alloc); run with SAN=1 for ASan/UBSan on top. Seeded.
 *
 * Hostile files too: a scene's folder holding links that lead out of it
 * (to a file, a folder, /proc) or a FIFO swapped in under a texture's
 * name, one texture under many names, more textures than the limit on
 * all of them, and outputs that are links, devices, FIFOs or cannot be
 * written completely. The tree is made in a temporary folder.
 */
#define _POSIX_C_SOURCE 200809L   /* mkdtemp, symlink, mkfifo, fork, setrlimit */
#include "ref/ref.h"
#include "support/testutil.h"
#include "unity.h"
#include "io/io_internal.h"
#include <mote/mote_io.h>

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 48
#define H 32

static char msg[256];

static char fsdir[256];           /* a temporary tree for the file tests: scene/, outside/ */
static void fs_remove_tree(void);

void setUp(void) {}

void tearDown(void)
{
    mote__io_resolve_by_walk(0);
    if (fsdir[0])
        fs_remove_tree();
}

typedef struct guarded {
    mote_device dev;
    void *color, *depth, *arena;
    size_t color_bytes, depth_bytes, arena_bytes;
} guarded;

static void guarded_init(guarded *g, mote_format cf, mote_depth_format df, size_t arena, int band)
{
    memset(g, 0, sizeof *g);
    int rows = band ? band : H;
    g->color_bytes = (size_t)W * rows * (size_t)mote_format_bytes(cf);
    g->depth_bytes = (size_t)W * rows * (size_t)(mote_depth_format_bytes(df) ? mote_depth_format_bytes(df) : 1);
    g->color = tu_guard_alloc(g->color_bytes);
    g->depth = tu_guard_alloc(g->depth_bytes);
    g->arena_bytes = arena;
    if (arena)
        g->arena = tu_guard_alloc(arena);
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = W;
    d.height = H;
    d.color_format = cf;
    d.color = g->color;
    d.depth_format = df;
    d.depth = df == MOTE_DEPTH_FORMAT_NONE ? NULL : g->depth;
    d.arena = g->arena;
    d.arena_size = arena;
    if (band) {
        d.band_height = band;
        d.flush = NULL;
    }
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_device_init(&g->dev, &d));
}

static void flush_nothing(void *user, int y0, int rows, const void *color, int stride)
{
    (void)user;
    (void)y0;
    (void)rows;
    (void)color;
    (void)stride;
}

static void guarded_check_free(guarded *g)
{
    TEST_ASSERT_TRUE_MESSAGE(tu_guard_ok(g->color, g->color_bytes), "colour buffer overrun");
    TEST_ASSERT_TRUE_MESSAGE(tu_guard_ok(g->depth, g->depth_bytes), "depth buffer overrun");
    if (g->arena) {
        TEST_ASSERT_TRUE_MESSAGE(tu_guard_ok(g->arena, g->arena_bytes), "arena overrun");
    }
    tu_guard_free(g->color);
    tu_guard_free(g->depth);
    tu_guard_free(g->arena);
}

static mote_frame_desc plain_frame(void)
{
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    f.camera.position[2] = -5;
    f.camera.fov = 0.8f;
    f.light_count = 1;
    f.lights[0].type = MOTE_LIGHT_POINT;
    f.lights[0].position[2] = -5;
    return f;
}

/* Both windings: these tests are about bad input, not culling. */
static const mote_draw_desc *no_cull(void)
{
    static mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.cull = MOTE_CULL_NONE;
    return &d;
}

static long count_drawn(const mote_device *dev)
{
    long n = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            mote_rgba c = mote_read_pixel(dev, x, y);
            n += c.r || c.g || c.b;
        }
    return n;
}

static mote_vertex tri_v[9];
static uint32_t tri_i[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};

/* p: three vertices' x, y, z */
static void set_tri(int t, const float *p)
{
    for (int k = 0; k < 3; k++) {
        memset(&tri_v[3 * t + k], 0, sizeof tri_v[0]);
        memcpy(tri_v[3 * t + k].position, p + 3 * k, 3 * sizeof *p);
        tri_v[3 * t + k].normal[2] = -1;
    }
}

static mote_mesh tri_mesh(int n)
{
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = tri_v;
    m.vertex_count = (uint32_t)(3 * n);
    m.indices = tri_i;
    m.index_count = (uint32_t)(3 * n);
    return m;
}

void nan_and_inf_vertices_should_drop_their_triangle_and_keep_the_others(void)
{
    const float good[3][3] = {{-1, -1, 0}, {0, 1, 0}, {1, -1, 0}};
    const float bad_values[] = {NAN, INFINITY, -INFINITY, FLT_MAX};
    static uint8_t alone[W * H * 4], with_bad[W * H * 4];
    guarded g;
    guarded_init(&g, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, 0, 0);
    mote_frame_desc f = plain_frame();
    set_tri(0, &good[0][0]);
    mote_mesh m = tri_mesh(1);
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&g.dev, &f));
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&g.dev, &m, no_cull()));
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&g.dev));
    tu_read_rgba(&g.dev, alone);
    TEST_ASSERT_TRUE(count_drawn(&g.dev) > 50);
    for (size_t b = 0; b < 3; b++)   /* FLT_MAX is finite: not "invalid", just far */
        for (int corner = 0; corner < 9; corner++) {
            float bad[3][3];
            memcpy(bad, good, sizeof bad);
            bad[corner / 3][corner % 3] = bad_values[b];
            set_tri(0, &bad[0][0]);
            set_tri(1, &good[0][0]);
            set_tri(2, &bad[0][0]);
            m = tri_mesh(3);
            TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&g.dev, &f));
            TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&g.dev, &m, no_cull()));
            TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&g.dev));
            tu_read_rgba(&g.dev, with_bad);
            const mote_stats *s = mote_device_stats(&g.dev);
            TEST_ASSERT_EQUAL_UINT32(2, s->triangles_invalid);
            TEST_ASSERT_EQUAL_UINT32(1, s->triangles_drawn);
            TEST_ASSERT_EQUAL_MEMORY(alone, with_bad, sizeof alone);
        }
    guarded_check_free(&g);
}

void degenerate_triangles_should_draw_nothing(void)
{
    guarded g;
    guarded_init(&g, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, 0, 0);
    mote_frame_desc f = plain_frame();
    const float cases[][3][3] = {
        {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}},             /* a point */
        {{-1, -1, 0}, {1, 1, 0}, {-1, -1, 0}},         /* two equal vertices */
        {{-1, -1, 0}, {0, 0, 0}, {1, 1, 0}},           /* collinear */
        {{-1, -1, 0}, {-1, -1, 5}, {-1, -1, -2}},      /* a line toward the eye */
        {{0, -1, -4}, {0, 1, 0}, {0, 0, 3}},           /* edge-on: x = 0 plane seen from x = 0 */
        {{-1, 0.3f, 0}, {1, 0.3f, 0}, {0.5f, 0.3000001f, 0}}, /* thinner than the grid */
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        set_tri(0, &cases[k][0][0]);
        mote_mesh m = tri_mesh(1);
        mote_draw_desc d;
        memset(&d, 0, sizeof d);
        d.cull = MOTE_CULL_NONE;
        d.mode = MOTE_MODE_FLAT;
        d.unlit = true;
        TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&g.dev, &f));
        TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&g.dev, &m, &d));
        TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&g.dev));
        snprintf(msg, sizeof msg, "case %zu", k);
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, count_drawn(&g.dev), msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(0, mote_device_stats(&g.dev)->triangles_drawn, msg);
    }
    guarded_check_free(&g);
}

void indices_out_of_range_should_be_rejected_at_draw(void)
{
    guarded g;
    guarded_init(&g, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, 0, 0);
    const float good[3][3] = {{-1, -1, 0}, {0, 1, 0}, {1, -1, 0}};
    set_tri(0, &good[0][0]);
    static uint32_t idx[] = {0, 1, 2, 0, 1, 3, 0xffffffffu, 1, 2, 2, 0x80000000u, 1, 0, 1, 2, 7, 7};
    mote_mesh m = tri_mesh(1);
    m.indices = idx;
    m.index_count = 17;   /* not a multiple of 3: the two extra indices are ignored */
    mote_frame_desc f = plain_frame();
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&g.dev, &f));
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&g.dev, &m, no_cull()));
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&g.dev));
    const mote_stats *s = mote_device_stats(&g.dev);
    TEST_ASSERT_EQUAL_UINT32(5, s->triangles_in);
    TEST_ASSERT_EQUAL_UINT32(3, s->triangles_invalid);
    TEST_ASSERT_EQUAL_UINT32(2, s->triangles_drawn);
    /* a mesh claiming indices it does not have is an argument error */
    mote_mesh no_idx = m;
    no_idx.indices = NULL;
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&g.dev, &f));
    TEST_ASSERT_EQUAL_INT(MOTE_ERR_INVALID_ARGUMENT, mote_draw(&g.dev, &no_idx, no_cull()));
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&g.dev));
    guarded_check_free(&g);
}

/* Random hostile scenes through every device configuration. */
static float hostile_float(tu_rng *r)
{
    switch (tu_rand_int(r, 0, 11)) {
    case 0: return NAN;
    case 1: return INFINITY;
    case 2: return -INFINITY;
    case 3: return FLT_MAX;
    case 4: return -FLT_MAX;
    case 5: return FLT_MIN;
    case 6: return 0.0f;
    case 7: return (float)tu_rand_range(r, -1e-30, 1e-30);
    case 8: { uint32_t bits = (uint32_t)tu_rand_u64(r); float f; memcpy(&f, &bits, 4); return f; }
    case 9: return (float)tu_rand_range(r, -1e6, 1e6);
    default: return (float)tu_rand_range(r, -3, 3);
    }
}

void random_hostile_scenes_should_never_crash_or_write_out_of_bounds(void)
{
    tu_rng r = tu_rng_seed(0xbad5eed);
    static mote_vertex v[64];
    static uint32_t idx[96];
    static uint8_t texels[5 * 3 * 4];
    mote_texture tex = {5, 3, MOTE_FORMAT_RGBA8888, 20, texels};
    for (int iter = 0; iter < 1500; iter++) {
        int config = iter % 6;
        mote_format cf = config == 1 ? MOTE_FORMAT_RGB565 : config == 2 ? MOTE_FORMAT_GREY8 : MOTE_FORMAT_RGBA8888;
        mote_depth_format df = config == 3 ? MOTE_DEPTH_FORMAT_16 : config == 4 ? MOTE_DEPTH_FORMAT_NONE : MOTE_DEPTH_FORMAT_32;
        guarded g;
        size_t arena = config == 5 ? 64 * 1024 : 0;
        int band = config == 2 ? 7 : 0;
        guarded_init(&g, cf, df, arena, 0);
        if (band) {     /* band mode needs its flush: set it up again */
            guarded_check_free(&g);
            memset(&g, 0, sizeof g);
            g.color_bytes = (size_t)W * band;
            g.depth_bytes = (size_t)W * band * 4;
            g.color = tu_guard_alloc(g.color_bytes);
            g.depth = tu_guard_alloc(g.depth_bytes);
            mote_device_desc d;
            memset(&d, 0, sizeof d);
            d.width = W;
            d.height = H;
            d.color_format = cf;
            d.color = g.color;
            d.depth = g.depth;
            d.band_height = band;
            d.flush = flush_nothing;
            TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_device_init(&g.dev, &d));
        }
        /* mostly sane geometry with hostile values sprinkled in */
        int nv = (int)tu_rand_int(&r, 3, 64), ni = 3 * (int)tu_rand_int(&r, 1, 32);
        for (int i = 0; i < nv; i++)
            for (int k = 0; k < 8; k++) {
                float *fv = k < 3 ? &v[i].position[k] : k < 6 ? &v[i].normal[k - 3] : &v[i].uv[k - 6];
                *fv = tu_rand_int(&r, 0, 9) == 0 ? hostile_float(&r) : (float)tu_rand_range(&r, -2, 2);
            }
        for (int i = 0; i < ni; i++)
            idx[i] = tu_rand_int(&r, 0, 30) == 0 ? (uint32_t)tu_rand_u64(&r) : (uint32_t)tu_rand_int(&r, 0, nv - 1);
        mote_mesh m;
        memset(&m, 0, sizeof m);
        m.vertices = v;
        m.vertex_count = (uint32_t)nv;
        m.indices = idx;
        m.index_count = (uint32_t)ni;
        for (int k = 0; k < 3; k++) {
            if (tu_rand_int(&r, 0, 4) == 0)
                m.position[k] = hostile_float(&r);
            if (tu_rand_int(&r, 0, 4) == 0)
                m.rotation[k] = hostile_float(&r);
            if (tu_rand_int(&r, 0, 4) == 0)
                m.scaling[k] = hostile_float(&r);
        }
        if (tu_rand_int(&r, 0, 2) == 0) {
            m.material.texture = &tex;
            m.material.wrap_u = (mote_wrap)tu_rand_int(&r, 0, 3);
            m.material.wrap_v = (mote_wrap)tu_rand_int(&r, 0, 3);
            m.material.u_scale = tu_rand_int(&r, 0, 3) == 0 ? hostile_float(&r) : 1.0f;
            m.material.v_offset = tu_rand_int(&r, 0, 3) == 0 ? hostile_float(&r) : 0.0f;
        }
        if (tu_rand_int(&r, 0, 3) == 0)
            mote_mesh_update_bounds(&m);
        mote_frame_desc f = plain_frame();
        float *cam[] = {&f.camera.fov, &f.camera.znear, &f.camera.zfar, &f.camera.position[0],
                        &f.camera.target[1], &f.camera.up[0], &f.lights[0].position[1], &f.ambient[0]};
        for (size_t k = 0; k < sizeof cam / sizeof cam[0]; k++)
            if (tu_rand_int(&r, 0, 5) == 0)
                *cam[k] = hostile_float(&r);
        mote_draw_desc d;
        memset(&d, 0, sizeof d);
        d.mode = (mote_mode)tu_rand_int(&r, 0, MOTE_MODE_COUNT - 1);
        d.cull = (mote_cull)tu_rand_int(&r, 0, MOTE_CULL_COUNT - 1);
        d.perspective = (mote_perspective)tu_rand_int(&r, 0, MOTE_PERSPECTIVE_COUNT - 1);
        d.filter = (mote_filter)tu_rand_int(&r, 0, MOTE_FILTER_COUNT - 1);
        d.subspan_log2 = (int)tu_rand_int(&r, -2, 9);
        d.unlit = tu_rand_int(&r, 0, 1);
        TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&g.dev, &f));
        mote_result rd = mote_draw(&g.dev, &m, &d);
        TEST_ASSERT_TRUE(rd == MOTE_OK);
        TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&g.dev));
        snprintf(msg, sizeof msg, "iteration %d (config %d)", iter, config);
        TEST_ASSERT_TRUE_MESSAGE(tu_guard_ok(g.color, g.color_bytes), msg);
        TEST_ASSERT_TRUE_MESSAGE(tu_guard_ok(g.depth, g.depth_bytes), msg);
        guarded_check_free(&g);
    }
}

void w_close_to_zero_and_extreme_cameras_should_stay_in_bounds(void)
{
    static const float fovs[] = {1e-30f, 1e-6f, 0.001f, 1.0f, 3.0f, 3.1f, 3.14159265f, 6.3f, 100.0f, -1.0f};
    static const float nears[] = {1e-30f, 1e-6f, 0.1f, 50.0f, 1e30f};
    static const float fars[] = {1e-20f, 1.0f, 100.0f, 1e30f, FLT_MAX};
    /* vertices on, just in front of and just behind the camera plane */
    const float tris[][3][3] = {
        {{-1, -1, 1e-30f}, {0, 1, 1e-30f}, {1, -1, 1e-30f}},
        {{-1, -1, -1e-30f}, {0, 1, 1e-7f}, {1, -1, 5}},
        {{-1e-3f, -1, 0}, {0, 1e-3f, 0}, {1, -1, 1e-38f}},
        {{-1, -1, 2}, {0, 1, 2}, {1, -1, 2}},
    };
    guarded g;
    guarded_init(&g, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_16, 0, 0);
    for (size_t a = 0; a < sizeof fovs / sizeof fovs[0]; a++)
        for (size_t b = 0; b < sizeof nears / sizeof nears[0]; b++)
            for (size_t c = 0; c < sizeof fars / sizeof fars[0]; c++) {
                mote_frame_desc f = plain_frame();
                f.camera.position[2] = 0;
                f.camera.target[2] = 1;
                f.camera.fov = fovs[a];
                f.camera.znear = nears[b];
                f.camera.zfar = fars[c];
                for (int t = 0; t < 3; t++)
                    set_tri(t, &tris[t][0][0]);
                mote_mesh m = tri_mesh(3);
                mote_draw_desc d;
                memset(&d, 0, sizeof d);
                d.cull = MOTE_CULL_NONE;
                TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&g.dev, &f));
                TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&g.dev, &m, &d));
                set_tri(0, &tris[3][0][0]);
                m = tri_mesh(1);
                TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&g.dev, &m, &d));
                TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&g.dev));
                TEST_ASSERT_TRUE(tu_guard_ok(g.color, g.color_bytes));
                TEST_ASSERT_TRUE(tu_guard_ok(g.depth, g.depth_bytes));
            }
    guarded_check_free(&g);
}

/* Texel coordinates at the vertex stage's limit (+-1e9 texels) make the
 * numerator planes wrap modulo 2^64 inside the triangle: the texels are
 * then garbage by design, but stepping the planes must stay defined
 * (UBSan, SAN=1) and nothing may be written out of bounds. */
void texel_ranges_at_the_limit_should_stay_defined(void)
{
    static uint8_t texels[5 * 3 * 4];
    mote_texture tex = {5, 3, MOTE_FORMAT_RGBA8888, 0, texels};
    const float big = 1e9f / 5;        /* uv 1 is 5 texels wide */
    const float uvs[][3][2] = {
        {{-big, -big}, {big, big}, {big, -big}},
        {{0, 0}, {big, 0}, {0, big}},
        {{-big, 3}, {-big, 3}, {big, -big}},
    };
    const float tri[3][3] = {{-3, -3, 0}, {0, 3, 4}, {3, -3, 1}};
    guarded g;
    guarded_init(&g, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, 0, 0);
    mote_frame_desc f = plain_frame();
    for (size_t u = 0; u < sizeof uvs / sizeof uvs[0]; u++)
        for (int persp = 0; persp < MOTE_PERSPECTIVE_COUNT; persp++)
            for (int filter = 0; filter < MOTE_FILTER_COUNT; filter++)
                for (int wrap = 0; wrap < MOTE_WRAP_COUNT; wrap++) {   /* mirror too */
                    set_tri(0, &tri[0][0]);
                    for (int k = 0; k < 3; k++)
                        memcpy(tri_v[k].uv, uvs[u][k], sizeof tri_v[k].uv);
                    mote_mesh m = tri_mesh(1);
                    m.material.texture = &tex;
                    m.material.wrap_u = m.material.wrap_v = (mote_wrap)wrap;
                    mote_draw_desc d;
                    memset(&d, 0, sizeof d);
                    d.cull = MOTE_CULL_NONE;
                    d.perspective = (mote_perspective)persp;
                    d.filter = (mote_filter)filter;
                    d.mode = MOTE_MODE_TEXTURED;
                    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&g.dev, &f));
                    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&g.dev, &m, &d));
                    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&g.dev));
                    snprintf(msg, sizeof msg, "uv set %zu, perspective %d, filter %d, wrap %d", u, persp,
                             filter, wrap);
                    TEST_ASSERT_TRUE_MESSAGE(mote_device_stats(&g.dev)->pixels_written > 100, msg);
                    TEST_ASSERT_TRUE_MESSAGE(tu_guard_ok(g.color, g.color_bytes), msg);
                    TEST_ASSERT_TRUE_MESSAGE(tu_guard_ok(g.depth, g.depth_bytes), msg);
                }
    guarded_check_free(&g);
}

void a_very_large_mesh_should_be_drawn_completely(void)
{
    /* 2^20 triangles tiling the screen: a 1024 x 512 grid of quads */
    const int nx = 1024, ny = 512;
    uint32_t nv = (uint32_t)((nx + 1) * (ny + 1));
    mote_vertex *v = (mote_vertex *)calloc(nv, sizeof *v);
    uint32_t *idx = (uint32_t *)malloc((size_t)nx * ny * 6 * sizeof *idx);
    TEST_ASSERT_NOT_NULL(v);
    TEST_ASSERT_NOT_NULL(idx);
    tu_screen s;
    TEST_ASSERT_TRUE(tu_screen_init(&s, W, H, 8, false));
    for (int j = 0; j <= ny; j++)
        for (int i = 0; i <= nx; i++)
            tu_screen_vertex(&s, (double)i * W / nx, (double)j * H / ny, 1.0 + (i + j) % 3,
                             v[j * (nx + 1) + i].position);
    size_t k = 0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            uint32_t a = (uint32_t)(j * (nx + 1) + i), b = a + 1, c = a + (uint32_t)nx + 2, d = a + (uint32_t)nx + 1;
            idx[k++] = a; idx[k++] = b; idx[k++] = c;
            idx[k++] = a; idx[k++] = c; idx[k++] = d;
        }
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = v;
    m.vertex_count = nv;
    m.indices = idx;
    m.index_count = (uint32_t)k;
    s.dev.desc.triangle_hook = NULL;   /* no capture of a million triangles */
    TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw_mesh(&s, &m, NULL));
    TEST_ASSERT_EQUAL_UINT32((uint32_t)(k / 3), mote_device_stats(&s.dev)->triangles_in);
    for (int i = 0; i < W * H; i++)
        TEST_ASSERT_TRUE_MESSAGE(s.color[i] != 0, "hole in a tiled screen");
    tu_screen_free(&s);
    free(v);
    free(idx);
}

/* mote_device_init enables binning only where the arena holds the tile
 * table and some triangles. It counted 16 bytes a tile, fewer than a
 * table entry takes: arenas just over that passed, and mote_begin then
 * cleared the table past the arena's end (1920x1080 in 16-pixel tiles:
 * 195840 table bytes, arenas from 154112 bytes on). */
void an_arena_just_large_enough_to_bin_should_hold_its_tile_table(void)
{
    enum { BW = 640, BH = 320 };  /* 3200 tiles of 8 x 8 */
    uint8_t *color = (uint8_t *)tu_guard_alloc((size_t)BW * BH);
    int binned = 0;
    for (int tile = 8; tile <= 16; tile *= 2)
        for (size_t bytes = 16u << 10; bytes <= 128u << 10; bytes += 2u << 10) {
            void *arena = tu_guard_alloc(bytes);
            mote_device dev;
            mote_device_desc d;
            memset(&d, 0, sizeof d);
            d.width = BW;
            d.height = BH;
            d.color_format = MOTE_FORMAT_GREY8;
            d.color = color;
            d.depth_format = MOTE_DEPTH_FORMAT_NONE;
            d.arena = arena;
            d.arena_size = bytes;
            d.tile_size = tile;
            TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_device_init(&dev, &d));
            binned += dev.bin.enabled;
            mote_frame_desc f;
            memset(&f, 0, sizeof f);
            f.camera.position[2] = -3.0f;
            TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&dev, &f));
            TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&dev));
            TEST_ASSERT_TRUE_MESSAGE(tu_guard_ok(arena, bytes), "arena overrun");
            tu_guard_free(arena);
        }
    TEST_ASSERT_TRUE(binned > 0);
    TEST_ASSERT_TRUE(tu_guard_ok(color, (size_t)BW * BH));
    tu_guard_free(color);
}

/* A parallel_for that runs the tasks in order on this thread. */
static void tasks_in_order(void *user, int count, mote_task_fn fn, void *task_arg)
{
    (void)user;
    for (int i = 0; i < count; i++)
        fn(task_arg, i);
}

/* A binned draw cut into pieces (with parallel_for) has all its vertices
 * transformed and lit in fours first, invalid ones too. With vertex
 * colours each was then converted to setup's units again, also one whose
 * texels are NaN or past 1e9, which that conversion does not take: a
 * shift by a negative count (UBSan, SAN=1). The frame must stay the one
 * the serial path draws. */
void invalid_vertices_of_a_draw_cut_into_pieces_should_stay_defined(void)
{
    enum { N = 16 };              /* 16 x 16 quads: 512 triangles, cut in pieces */
    static mote_vertex v[(N + 1) * (N + 1)];
    static mote_rgba colors[(N + 1) * (N + 1)];
    static uint32_t idx[N * N * 6];
    static uint8_t texels[5 * 3 * 4];
    static uint8_t serial[W * H * 4], pieces[W * H * 4];
    mote_texture tex = {5, 3, MOTE_FORMAT_RGBA8888, 0, texels};
    for (size_t i = 0; i < sizeof texels; i++)
        texels[i] = (uint8_t)(i * 37 + 11);
    const float bad_uv[] = {NAN, INFINITY, 1e30f, -3e8f};
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++) {
            int k = j * (N + 1) + i;
            memset(&v[k], 0, sizeof v[k]);
            v[k].position[0] = -2.0f + 4.0f * (float)i / N;
            v[k].position[1] = -2.0f + 4.0f * (float)j / N;
            v[k].normal[2] = -1.0f;
            v[k].uv[0] = (float)i / N;
            v[k].uv[1] = (float)j / N;
            if (k % 7 == 3)
                v[k].uv[k % 2] = bad_uv[(k / 7) % 4];
            colors[k] = (mote_rgba){(uint8_t)(k * 13), (uint8_t)(200 - k), (uint8_t)(k * 5 + 40), 255};
        }
    size_t n = 0;
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            uint32_t a = (uint32_t)(j * (N + 1) + i), b = a + 1, c = a + N + 2, d = a + N + 1;
            const uint32_t quad[6] = {a, b, c, a, c, d};
            memcpy(&idx[n], quad, sizeof quad);
            n += 6;
        }
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = v;
    m.vertex_count = (N + 1) * (N + 1);
    m.indices = idx;
    m.index_count = (uint32_t)n;
    m.colors = colors;
    m.material.texture = &tex;
    mote_frame_desc f = plain_frame();
    mote_stats stats[2];
    for (int way = 0; way < 2; way++) {
        guarded g;
        guarded_init(&g, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, 1u << 20, 0);
        mote_device_desc d = g.dev.desc;
        d.parallel_for = way ? tasks_in_order : NULL;
        TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_device_init(&g.dev, &d));
        TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&g.dev, &f));
        TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&g.dev, &m, no_cull()));
        TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&g.dev));
        stats[way] = *mote_device_stats(&g.dev);
        memcpy(way ? pieces : serial, g.color, sizeof serial);
        guarded_check_free(&g);
    }
    TEST_ASSERT_TRUE(stats[0].triangles_invalid > 0);
    TEST_ASSERT_TRUE(stats[0].triangles_drawn > 100);
    TEST_ASSERT_EQUAL_UINT32(stats[0].triangles_invalid, stats[1].triangles_invalid);
    TEST_ASSERT_EQUAL_UINT32(stats[0].triangles_drawn, stats[1].triangles_drawn);
    TEST_ASSERT_EQUAL_MEMORY(serial, pieces, sizeof serial);
}

/* ---- files a scene names ------------------------------------------------- */

static const char *fs_path(const char *name)
{
    static char path[2][600];
    static int turn;
    turn ^= 1;
    snprintf(path[turn], sizeof path[turn], "%s/%s", fsdir, name);
    return path[turn];
}

/* A w x 1 PNG of one colour at fs_path(name). */
static void fs_png(const char *name, uint8_t r, uint8_t g, uint8_t b, int w)
{
    uint8_t px[64 * 4];
    for (int i = 0; i < w; i++) {
        px[4 * i] = r;
        px[4 * i + 1] = g;
        px[4 * i + 2] = b;
        px[4 * i + 3] = 255;
    }
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_rgba(fs_path(name), px, w, 1, 0, msg, sizeof msg),
                              msg);
}

static void fs_link(const char *target, const char *name)
{
    TEST_ASSERT_EQUAL_MESSAGE(0, symlink(target, fs_path(name)), name);
}

/* A scene in fs_path("scene") whose n materials name the textures names[]. */
static mote_result fs_load(const char *const *names, int n, const mote_limits *lim,
                           mote_scene *sc)
{
    static char json[8192];
    int k = snprintf(json, sizeof json, "{\"materials\":[");
    for (int i = 0; i < n; i++)
        k += snprintf(json + k, sizeof json - (size_t)k,
                      "%s{\"id\":\"m%d\",\"diffuseTexture\":{\"name\":\"%s\"}}", i ? "," : "", i,
                      names[i]);
    snprintf(json + k, sizeof json - (size_t)k, "]}");
    msg[0] = '\0';
    return mote_scene_load_memory(json, strlen(json), "s", fs_path("scene"), lim, sc, msg,
                                  sizeof msg);
}

/* The first texel's red byte of the scene's first texture. */
static int fs_red(const mote_scene *sc)
{
    TEST_ASSERT_TRUE(sc->texture_count > 0);
    return ((const uint8_t *)sc->textures[0].pixels)[0];
}

static void fs_make_tree(void)
{
    snprintf(fsdir, sizeof fsdir, "/tmp/mote-hostile-XXXXXX");
    TEST_ASSERT_NOT_NULL(mkdtemp(fsdir));
    TEST_ASSERT_EQUAL(0, mkdir(fs_path("scene"), 0700));
    TEST_ASSERT_EQUAL(0, mkdir(fs_path("scene/sub"), 0700));
    TEST_ASSERT_EQUAL(0, mkdir(fs_path("outside"), 0700));
    fs_png("outside/outside.png", 200, 0, 0, 1);    /* red: read from outside */
    fs_png("scene/in.png", 0, 200, 0, 1);           /* green: inside */
}

static void fs_remove_tree(void)
{
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", fsdir);
    fsdir[0] = '\0';
    TEST_ASSERT_EQUAL(0, system(cmd));
}

/* Links in the scene's folder that lead out of it, as an uploaded archive
 * may carry them: to a file, through a folder, up past the folder, an
 * absolute one, through /proc/self/root, to /proc/self/environ. None is
 * opened, by openat2 or by the walk one component at a time; the name
 * as written is refused as before. */
void links_leading_out_of_the_scene_folder_should_not_be_followed(void)
{
    fs_make_tree();
    char outside_abs[600], in_abs[600], root_path[700];
    snprintf(outside_abs, sizeof outside_abs, "%s", fs_path("outside/outside.png"));
    snprintf(in_abs, sizeof in_abs, "%s", fs_path("scene/in.png"));
    fs_link("../outside/outside.png", "scene/link.png");
    fs_link("../outside", "scene/out");
    fs_link("../../../../../../../../../../../..", "scene/up");
    fs_link(outside_abs, "scene/abs.png");
    fs_link(in_abs, "scene/abs_in.png");            /* absolute, even to inside */
    fs_link("/proc/self/root", "scene/root");
    fs_link("/proc/self/environ", "scene/env.png");
    fs_link("sub/../../outside/outside.png", "scene/sub_up.png");
    fs_link("../link.png", "scene/sub/chain.png");   /* a link to a link out */
    snprintf(root_path, sizeof root_path, "root%s", outside_abs);
    const char *const escapes[] = {"link.png", "out/outside.png", "abs.png", "abs_in.png",
                                   root_path, "env.png", "sub_up.png", "sub/chain.png",
                                   "up/tmp/x.png", "sub\\\\chain.png"};
    for (int walk = 0; walk < 2; walk++) {
        mote__io_resolve_by_walk(walk);
        for (size_t i = 0; i < sizeof escapes / sizeof escapes[0]; i++) {
            mote_scene sc;
            char what[900];
            snprintf(what, sizeof what, "%s (walk %d): %s", escapes[i], walk, msg);
            mote_result r = fs_load(&escapes[i], 1, NULL, &sc);
            snprintf(what, sizeof what, "%s (walk %d): %s", escapes[i], walk, msg);
            TEST_ASSERT_EQUAL_MESSAGE(MOTE_ERR_RANGE, r, what);
            TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "leads out of the scene's folder through a "
                                                     "symbolic link"), what);
            TEST_ASSERT_EQUAL(0, sc.texture_count);
        }
    }
    mote__io_resolve_by_walk(0);
    /* limits.allow_any_texture_path follows them, as before */
    mote_limits lim = mote_limits_default();
    lim.allow_any_texture_path = true;
    mote_scene sc;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, fs_load(&escapes[0], 1, &lim, &sc), msg);
    TEST_ASSERT_EQUAL(200, fs_red(&sc));
    mote_scene_free(&sc);
}

/* Links that stay inside the folder are followed, by both resolvers: to a
 * file beside them, through a linked sub-folder, up and down again
 * inside, and a chain of them. */
void links_staying_inside_the_scene_folder_should_be_followed(void)
{
    fs_make_tree();
    fs_link("in.png", "scene/same.png");
    fs_link("../in.png", "scene/sub/up.png");
    fs_link("sub", "scene/sublink");
    fs_link("sublink/up.png", "scene/chain.png");
    fs_link("./sub/../in.png", "scene/dots.png");
    const char *const names[] = {"same.png", "sub/up.png", "sublink/up.png", "chain.png",
                                 "dots.png", "./in.png"};
    for (int walk = 0; walk < 2; walk++) {
        mote__io_resolve_by_walk(walk);
        for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
            mote_scene sc;
            TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, fs_load(&names[i], 1, NULL, &sc), msg);
            TEST_ASSERT_EQUAL(0, fs_red(&sc));
            mote_scene_free(&sc);
        }
    }
    mote__io_resolve_by_walk(0);
}

#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
/* This program's stat() stands in for the C library's (glibc 2.33 has a
 * stat symbol to stand in for): once armed with a path, it swaps the FIFO
 * at fifo_swap.from in under that name just after looking, which is the
 * moment a look-then-open race needs. */
static struct {
    char path[600], from[600];
} fifo_swap;

int stat(const char *restrict path, struct stat *restrict st)
{
    int r = fstatat(AT_FDCWD, path, st, 0);
    if (fifo_swap.path[0] && strcmp(path, fifo_swap.path) == 0) {
        fifo_swap.path[0] = '\0';
        rename(fifo_swap.from, path);
    }
    return r;
}
#define FIFO_SWAP_AFTER_STAT 1
#endif

/* Swapped in between a look at the name and the open, a FIFO made the
 * load wait for a writer for ever. Where stat() can be stood in for, the
 * FIFO is swapped in just after any look at the name: the load reads the
 * file, or refuses the FIFO. Then the name b.png is turned from a regular
 * file to a FIFO and back as fast as a child process can while the scene
 * is loaded 300 times: each load either reads the file or refuses the
 * FIFO, and none waits (the alarm would end the test). */
void a_fifo_swapped_in_under_a_texture_name_should_never_block_a_load(void)
{
    fs_make_tree();
    fs_png("scene/b.png", 0, 200, 0, 1);
#ifdef FIFO_SWAP_AFTER_STAT
    {
        snprintf(fifo_swap.from, sizeof fifo_swap.from, "%s", fs_path("scene/swap.fifo"));
        snprintf(fifo_swap.path, sizeof fifo_swap.path, "%s", fs_path("scene/b.png"));
        TEST_ASSERT_EQUAL(0, mkfifo(fifo_swap.from, 0600));
        const char *b = "b.png";
        mote_scene sc;
        alarm(30);
        mote_result r = fs_load(&b, 1, NULL, &sc);
        alarm(0);
        mote_scene_free(&sc);
        fifo_swap.path[0] = '\0';
        TEST_ASSERT_TRUE_MESSAGE(r == MOTE_OK || strstr(msg, "a FIFO, not a regular file"), msg);
        remove(fs_path("scene/b.png"));
        remove(fifo_swap.from);
        fs_png("scene/b.png", 0, 200, 0, 1);
    }
#endif
    TEST_ASSERT_EQUAL(0, link(fs_path("scene/b.png"), fs_path("scene/good.png")));
    char good[600], reg[600], fifo[600], target[600];
    snprintf(good, sizeof good, "%s", fs_path("scene/good.png"));
    snprintf(reg, sizeof reg, "%s", fs_path("scene/x.reg"));
    snprintf(fifo, sizeof fifo, "%s", fs_path("scene/x.fifo"));
    snprintf(target, sizeof target, "%s", fs_path("scene/b.png"));
    pid_t parent = getpid(), child = fork();
    TEST_ASSERT_TRUE(child >= 0);
    if (child == 0) {
        while (getppid() == parent) {
            if (mkfifo(fifo, 0600) == 0)
                rename(fifo, target);
            if (link(good, reg) == 0)
                rename(reg, target);
        }
        _exit(0);
    }
    alarm(60);
    const char *name = "b.png";
    int read_file = 0, refused = 0;
    char other[sizeof msg] = "";
    for (int i = 0; i < 300; i++) {
        mote_scene sc;
        mote_result r = fs_load(&name, 1, NULL, &sc);
        mote_scene_free(&sc);
        if (r == MOTE_OK)
            read_file++;
        else if (r == MOTE_ERR_IO && strstr(msg, "a FIFO, not a regular file"))
            refused++;
        else
            memcpy(other, msg, sizeof other);
    }
    alarm(0);
    kill(child, SIGKILL);
    waitpid(child, NULL, 0);
    TEST_ASSERT_EQUAL_STRING("", other);
    TEST_ASSERT_EQUAL(300, read_file + refused);
    TEST_ASSERT_TRUE(read_file > 0);
}

/* One file under many names ("b.png", "./b.png", "././b.png", a link, a
 * hard link) is one texture, decoded once: the names once made 330 MB
 * each of a 65 KB PNG claiming 8192 x 8192. */
void a_texture_under_many_names_should_be_decoded_once(void)
{
    fs_make_tree();
    fs_png("scene/b.png", 0, 200, 0, 4);
    fs_link("b.png", "scene/link.png");
    TEST_ASSERT_EQUAL(0, link(fs_path("scene/b.png"), fs_path("scene/hard.png")));
    const char *const names[] = {"b.png", "./b.png", "././b.png", ".//./b.png", "link.png",
                                 "sub/../b.png%3F", "hard.png", "b.png?v=2"};
    mote_scene sc;
    /* "sub/../b.png%3F" leaves by '..' when decoded: the name as written
     * is looked for, and missing, fails the load */
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, fs_load(names, 8, NULL, &sc));
    const char *const fine[] = {"b.png", "./b.png", "././b.png", ".//./b.png", "link.png",
                                "hard.png", "b.png?v=2"};
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, fs_load(fine, 7, NULL, &sc), msg);
    TEST_ASSERT_EQUAL(1, sc.texture_count);
    TEST_ASSERT_TRUE(mote_scene_reads_file(&sc, fs_path("scene/hard.png")));
    TEST_ASSERT_FALSE(mote_scene_reads_file(&sc, fs_path("scene/in.png")));
    mote_scene_free(&sc);
}

/* A scene of many distinct textures is held to
 * limits.max_total_texture_bytes, from each image's header: the texture
 * past the limit is refused without being decoded (its pixel data here
 * is not even valid), files and embedded images alike. */
void the_textures_of_a_scene_should_be_held_to_the_total_limit(void)
{
    TEST_ASSERT_EQUAL((size_t)512 << 20, mote_limits_default().max_total_texture_bytes);
    fs_make_tree();
    fs_png("scene/a.png", 1, 0, 0, 64);
    fs_png("scene/b.png", 2, 0, 0, 64);
    /* a PNG header claiming 64 x 1, and no image data */
    static const uint8_t header_only[] = {
        0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
        0, 0, 0, 64, 0, 0, 0, 1, 8, 6, 0, 0, 0, 0x5e, 0x1d, 0x2c, 0x8a};
    FILE *f = fopen(fs_path("scene/c.png"), "wb");
    TEST_ASSERT_NOT_NULL(f);
    fwrite(header_only, 1, sizeof header_only, f);
    fclose(f);
    mote_limits lim = mote_limits_default();
    lim.max_total_texture_bytes = 2 * 64 * 4;
    const char *const names[] = {"a.png", "b.png", "c.png", "a.png"};
    mote_scene sc;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, fs_load(names, 2, &lim, &sc), msg);
    TEST_ASSERT_EQUAL(2, sc.texture_count);
    mote_scene_free(&sc);
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, fs_load(names, 3, &lim, &sc));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "c.png: 64 x 1 needs 256 bytes, more than the 0 "
                                             "left of the limit of 512 on all of a scene's "
                                             "textures"), msg);
    /* with the limit one texture larger, c.png is decoded, and fails so */
    lim.max_total_texture_bytes = 3 * 64 * 4;
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, fs_load(names, 3, &lim, &sc));
    /* an embedded image counts too */
    static const char data_url[] = "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAA"
                                   "fFcSJAAAADUlEQVR4nGNgYPj/HwADAgH/eK9dXAAAAABJRU5ErkJggg==";
    const char *const with_url[] = {"a.png", "b.png", data_url};
    lim.max_total_texture_bytes = 2 * 64 * 4 + 3;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, fs_load(with_url, 3, &lim, &sc));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "embedded image: 1 x 1 needs 4 bytes, more than the 3 "
                                             "left"), msg);
    lim.max_total_texture_bytes = 2 * 64 * 4 + 4;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, fs_load(with_url, 3, &lim, &sc), msg);
    TEST_ASSERT_EQUAL(3, sc.texture_count);
    mote_scene_free(&sc);
}

void camera_matrices_of_a_null_camera_should_be_the_identity(void)
{
    float m[16], identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    memset(m, 0x7f, sizeof m);
    mote_camera_view_matrix(NULL, m);
    TEST_ASSERT_EQUAL_MEMORY(identity, m, sizeof m);
    memset(m, 0x7f, sizeof m);
    mote_camera_projection_matrix(NULL, 1.5f, m);
    TEST_ASSERT_EQUAL_MEMORY(identity, m, sizeof m);
    mote_camera cam;
    memset(&cam, 0, sizeof cam);
    mote_camera_view_matrix(&cam, NULL);
    mote_camera_projection_matrix(&cam, 1.0f, NULL);
}

/* ---- files written ------------------------------------------------------- */

/* Whether a new file beside the target was left in dir ("." names). */
static bool fs_temp_left(const char *dir)
{
    char cmd[700];
    snprintf(cmd, sizeof cmd, "ls -a '%s' | grep -q '^\\..*\\.tmp$'", dir);
    return system(cmd) == 0;
}

static long fs_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

/* A file written is complete, or the target is as it was: a write that
 * fails half way (a file size limit: EFBIG) leaves the old file, says
 * why, and leaves no new file behind. Through a link, the file it names
 * is replaced and the link stays. */
void an_output_should_be_replaced_whole_or_left_as_it_was(void)
{
    fs_make_tree();
    static uint8_t big[16384];
    memset(big, 'x', sizeof big);
    char out[600];
    snprintf(out, sizeof out, "%s", fs_path("scene/out.h"));
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_file(out, "old", 3, msg, sizeof msg), msg);
    struct rlimit old_limit, small;
    TEST_ASSERT_EQUAL(0, getrlimit(RLIMIT_FSIZE, &old_limit));
    small = old_limit;
    small.rlim_cur = 4096;
    void (*old_handler)(int) = signal(SIGXFSZ, SIG_IGN);
    TEST_ASSERT_EQUAL(0, setrlimit(RLIMIT_FSIZE, &small));
    mote_result r = mote_write_file(out, big, sizeof big, msg, sizeof msg);
    /* an image too: noise does not compress below the limit */
    static uint8_t noise[64 * 64 * 4];
    tu_rng rng = tu_rng_seed(7);
    for (size_t i = 0; i < sizeof noise; i++)
        noise[i] = (uint8_t)tu_rand_u64(&rng);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_file(fs_path("scene/old.png"), "old", 3, msg, sizeof msg));
    mote_result r_png = mote_write_rgba(fs_path("scene/old.png"), noise, 64, 64, 0, msg, sizeof msg);
    setrlimit(RLIMIT_FSIZE, &old_limit);
    signal(SIGXFSZ, old_handler);
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, r_png);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "write error: File too large"), msg);
    TEST_ASSERT_EQUAL(3, fs_size(fs_path("scene/old.png")));
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, r);
    TEST_ASSERT_EQUAL(3, fs_size(out));
    TEST_ASSERT_FALSE(fs_temp_left(fs_path("scene")));
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_file(out, big, sizeof big, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL((long)sizeof big, fs_size(out));
    /* through a link: the file replaced, the link kept */
    fs_link("out.h", "scene/link.h");
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_file(fs_path("scene/link.h"), "new", 3, msg,
                                                       sizeof msg), msg);
    struct stat st;
    TEST_ASSERT_EQUAL(0, lstat(fs_path("scene/link.h"), &st));
    TEST_ASSERT_TRUE(S_ISLNK(st.st_mode));
    TEST_ASSERT_EQUAL(3, fs_size(out));
    fs_link("nothing.h", "scene/dangling.h");
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_write_file(fs_path("scene/dangling.h"), "x", 1, msg,
                                                   sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "a symbolic link to nothing"), msg);
    TEST_ASSERT_FALSE(fs_temp_left(fs_path("scene")));
}

/* What is no regular file is never removed: a device is written in place
 * (/dev/full, through a link, says why it failed, and it and the link
 * stay), a FIFO is written when someone reads it and refused at once
 * when no one does, a directory is refused. */
void an_output_that_is_no_regular_file_should_be_written_in_place_or_refused(void)
{
    fs_make_tree();
    struct stat st;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_file("/dev/null", "x", 1, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(0, stat("/dev/null", &st));
    TEST_ASSERT_TRUE(S_ISCHR(st.st_mode));
    if (stat("/dev/full", &st) == 0) {
        fs_link("/dev/full", "scene/full.png");
        uint8_t px[4 * 4 * 4] = {0};
        TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_write_rgba(fs_path("scene/full.png"), px, 4, 4, 0,
                                                       msg, sizeof msg));
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "write error: No space left on device"), msg);
        TEST_ASSERT_EQUAL(0, lstat(fs_path("scene/full.png"), &st));
        TEST_ASSERT_EQUAL(0, stat("/dev/full", &st));
        TEST_ASSERT_TRUE(S_ISCHR(st.st_mode));
    }
    char fifo[600];
    snprintf(fifo, sizeof fifo, "%s", fs_path("scene/fifo.h"));
    TEST_ASSERT_EQUAL(0, mkfifo(fifo, 0600));
    alarm(30);
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_write_file(fifo, "x", 1, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "a FIFO that no one reads"), msg);
    int reader = open(fifo, O_RDONLY | O_NONBLOCK);
    TEST_ASSERT_TRUE(reader >= 0);
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_file(fifo, "hello", 5, msg, sizeof msg), msg);
    char got[8] = "";
    TEST_ASSERT_EQUAL(5, read(reader, got, sizeof got));
    TEST_ASSERT_EQUAL_MEMORY("hello", got, 5);
    close(reader);
    alarm(0);
    TEST_ASSERT_EQUAL(0, lstat(fifo, &st));
    TEST_ASSERT_TRUE(S_ISFIFO(st.st_mode));
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_write_file(fs_path("scene/sub"), "x", 1, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "not written: a directory"), msg);
    TEST_ASSERT_FALSE(fs_temp_left(fs_path("scene")));
}

/* mote_scene_reads_file knows the scene file and its textures by what
 * they are, not by name, so that tools can refuse to write over them. */
void a_scene_should_know_the_files_it_was_read_from(void)
{
    fs_make_tree();
    const char *scene = "{\"materials\":[{\"id\":\"m\",\"diffuseTexture\":{\"name\":\"in.png\"}}]}";
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_file(fs_path("scene/s.babylon"), scene, strlen(scene),
                                               msg, sizeof msg));
    fs_link("scene/s.babylon", "s_link.babylon");
    mote_scene sc;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(fs_path("scene/s.babylon"), NULL, &sc, msg,
                                                       sizeof msg), msg);
    TEST_ASSERT_TRUE(mote_scene_reads_file(&sc, fs_path("s_link.babylon")));
    TEST_ASSERT_TRUE(mote_scene_reads_file(&sc, fs_path("scene/./in.png")));
    TEST_ASSERT_FALSE(mote_scene_reads_file(&sc, fs_path("outside/outside.png")));
    TEST_ASSERT_FALSE(mote_scene_reads_file(&sc, fs_path("scene/none.png")));
    TEST_ASSERT_FALSE(mote_scene_reads_file(&sc, NULL));
    TEST_ASSERT_FALSE(mote_scene_reads_file(NULL, fs_path("scene/s.babylon")));
    mote_scene_free(&sc);
    TEST_ASSERT_FALSE(mote_scene_reads_file(&sc, fs_path("scene/s.babylon")));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(nan_and_inf_vertices_should_drop_their_triangle_and_keep_the_others);
    RUN_TEST(degenerate_triangles_should_draw_nothing);
    RUN_TEST(indices_out_of_range_should_be_rejected_at_draw);
    RUN_TEST(random_hostile_scenes_should_never_crash_or_write_out_of_bounds);
    RUN_TEST(w_close_to_zero_and_extreme_cameras_should_stay_in_bounds);
    RUN_TEST(texel_ranges_at_the_limit_should_stay_defined);
    RUN_TEST(a_very_large_mesh_should_be_drawn_completely);
    RUN_TEST(an_arena_just_large_enough_to_bin_should_hold_its_tile_table);
    RUN_TEST(invalid_vertices_of_a_draw_cut_into_pieces_should_stay_defined);
    RUN_TEST(links_leading_out_of_the_scene_folder_should_not_be_followed);
    RUN_TEST(links_staying_inside_the_scene_folder_should_be_followed);
    RUN_TEST(a_fifo_swapped_in_under_a_texture_name_should_never_block_a_load);
    RUN_TEST(a_texture_under_many_names_should_be_decoded_once);
    RUN_TEST(the_textures_of_a_scene_should_be_held_to_the_total_limit);
    RUN_TEST(camera_matrices_of_a_null_camera_should_be_the_identity);
    RUN_TEST(an_output_should_be_replaced_whole_or_left_as_it_was);
    RUN_TEST(an_output_that_is_no_regular_file_should_be_written_in_place_or_refused);
    RUN_TEST(a_scene_should_know_the_files_it_was_read_from);
    return UNITY_END();
}
