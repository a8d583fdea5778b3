/*
 * test_tile_depth.c - binned tiles skip triangles behind the depth drawn
 * in them (bin.c's coarse depth per tile): the same colour and depth
 * bytes as with it off and as drawn directly, for both depth formats,
 * several tile sizes, threads, and triangles that are partly in front,
 * tilted through the others or drawn without a depth test.
 */
#include "unity.h"

#include <mote/mote.h>
#include <mote/mote_io.h>

#include <stdint.h>
#include <string.h>

enum { W = 150, H = 100, QUADS = 7 };

void setUp(void) {}
void tearDown(void) {}

static mote_vertex quad_v[QUADS][4];
static const uint32_t quad_i[6] = {0, 1, 2, 0, 2, 3};

/* The quads in drawing order: z, half-size, tilt (z change across it),
 * x offset, and whether it is drawn without a depth test. Screen-covering
 * ones near to far; one far without a depth test, which moves the tile's
 * depths farther, before a nearer one that must be drawn; a small one
 * tilted through the others; and a far one without a depth test last. */
static const struct { float z, s, tilt, dx; bool no_test; } quads[QUADS] = {
    {0.0f, 6.0f, 0.0f, 0.0f, false}, {2.0f, 6.0f, 0.0f, 0.0f, false}, {3.0f, 6.0f, 0.0f, 0.0f, true},
    {1.0f, 6.0f, 0.0f, 0.0f, false}, {2.5f, 6.0f, 0.0f, 0.0f, false}, {1.5f, 1.2f, 2.5f, 0.4f, false},
    {2.8f, 1.2f, 0.0f, -0.8f, true},
};

static void build_quads(mote_mesh meshes[QUADS])
{
    for (int k = 0; k < QUADS; k++) {
        const float s = quads[k].s;
        const float xy[4][2] = {{-s, -s}, {-s, s}, {s, s}, {s, -s}};
        for (int i = 0; i < 4; i++) {
            mote_vertex *v = &quad_v[k][i];
            memset(v, 0, sizeof *v);
            v->position[0] = xy[i][0] + quads[k].dx;
            v->position[1] = xy[i][1] * 0.9f;
            v->position[2] = quads[k].z + quads[k].tilt * xy[i][0] / s;
            v->normal[2] = -1.0f;
        }
        mote_mesh *m = &meshes[k];
        memset(m, 0, sizeof *m);
        m->vertices = quad_v[k];
        m->vertex_count = 4;
        m->indices = quad_i;
        m->index_count = 6;
        m->material.color = (mote_rgba){(uint8_t)(40 * k), (uint8_t)(255 - 30 * k), (uint8_t)(90 + 20 * k), 255};
        m->material.color_set = true;
    }
}

typedef struct way {
    int tile;                     /* 0: no arena (drawn directly) */
    int threads;
    bool off;
} way;

/* Draws the quads and returns the stats. */
static mote_stats render(way w, mote_depth_format df, uint8_t *color, uint32_t *depth)
{
    static unsigned char arena[1 << 20];
    mote_mesh meshes[QUADS];
    build_quads(meshes);
    mote_pool *pool = NULL;
    mote_pool_desc pd = {w.threads, NULL, NULL};
    if (w.threads > 1)
        TEST_ASSERT_EQUAL(MOTE_OK, mote_pool_create(&pd, &pool, NULL, 0));
    const mote_device_desc d = {.width = W, .height = H, .color = color, .depth = depth, .depth_format = df,
                                .clear_color = {5, 6, 7, 255}, .arena = w.tile ? arena : NULL,
                                .arena_size = w.tile ? sizeof arena : 0, .tile_size = w.tile,
                                .parallel_for = pool ? mote_parallel_pool : NULL, .parallel_user = pool,
                                .no_tile_depth = w.off};
    mote_device dev;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    f.camera.position[2] = -5.0f;
    f.camera.target[2] = 0.0f;
    f.light_count = 1;
    f.lights[0].type = MOTE_LIGHT_DIRECTIONAL;
    f.lights[0].direction[2] = 1.0f;
    f.lights[0].direction[1] = -0.3f;
    mote_draw_desc dd;
    memset(&dd, 0, sizeof dd);
    dd.mode = MOTE_MODE_GOURAUD;
    dd.cull = MOTE_CULL_NONE;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
    for (int k = 0; k < QUADS; k++) {
        mote_draw_desc dk = dd;
        dk.no_depth_test = quads[k].no_test;
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &meshes[k], &dk));
    }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    mote_pool_destroy(pool);
    return *mote_device_stats(&dev);
}

static uint8_t ref_c[W * H * 4], got_c[W * H * 4];
static uint32_t ref_d[W * H], got_d[W * H];

void test_tile_depth_skips_hidden_triangles_and_draws_the_same_bytes(void)
{
    static const mote_depth_format formats[] = {MOTE_DEPTH_FORMAT_32, MOTE_DEPTH_FORMAT_16};
    static const way ways[] = {{8, 1, false}, {16, 1, false}, {64, 1, false}, {16, 3, false}, {16, 1, true}};
    for (int fi = 0; fi < 2; fi++) {
        memset(ref_c, 0, sizeof ref_c);
        memset(ref_d, 0, sizeof ref_d);
        mote_stats direct = render((way){0, 1, false}, formats[fi], ref_c, ref_d);
        TEST_ASSERT_EQUAL_UINT32(0, direct.tile_triangles_behind);
        for (size_t w = 0; w < sizeof ways / sizeof ways[0]; w++) {
            memset(got_c, 0, sizeof got_c);
            memset(got_d, 0, sizeof got_d);
            mote_stats st = render(ways[w], formats[fi], got_c, got_d);
            TEST_ASSERT_EQUAL_MEMORY(ref_c, got_c, sizeof ref_c);
            TEST_ASSERT_EQUAL_MEMORY(ref_d, got_d, formats[fi] == MOTE_DEPTH_FORMAT_16 ? sizeof ref_d / 2 : sizeof ref_d);
            if (ways[w].off) {
                TEST_ASSERT_EQUAL_UINT32(0, st.tile_triangles_behind);
            } else {
                /* the far quads were skipped in most tiles, and their pixels not tested */
                TEST_ASSERT_TRUE(st.tile_triangles_behind > 0);
                TEST_ASSERT_TRUE(st.pixels_tested < direct.pixels_tested);
            }
            TEST_ASSERT_EQUAL_UINT64(direct.pixels_written, st.pixels_written);
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tile_depth_skips_hidden_triangles_and_draws_the_same_bytes);
    return UNITY_END();
}
