/*
 * test_hostile.c - numerically hostile input never crashes and never writes
 * out of bounds: NaN/Inf coordinates (the triangle is dropped), degenerate
 * and zero-area triangles (nothing drawn), w close to 0, extreme fov, near
 * and far, very large meshes, indices out of range (rejected at draw).
 *
 * Every buffer mote writes (colour, depth, arena) has canary bytes on both
 * sides (tu_guard_alloc); run with SAN=1 for ASan/UBSan on top. Seeded.
 */
#include "ref/ref.h"
#include "support/testutil.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 48
#define H 32

static char msg[256];

void setUp(void) {}
void tearDown(void) {}

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
    return UNITY_END();
}
