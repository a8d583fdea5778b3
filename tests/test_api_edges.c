/*
 * test_api_edges.c - the device API at its edges, where an audit with
 * hostile and careless callers found bugs: buffers mote would store into
 * unaligned, arenas of odd or huge sizes, frames begun twice, a triangle
 * too big for the arena under clear_drawn_tiles_only, keep_color in band
 * mode, texture strides, NULL pointers and a file limit of SIZE_MAX.
 */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen */
#include "support/scenes.h"
#include "unity.h"

#include <mote/mote.h>
#include <mote/mote_io.h>

#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 64, H = 64 };

void setUp(void) {}
void tearDown(void) {}

static mote_vertex vtx(float x, float y, float u, float v)
{
    mote_vertex r;
    memset(&r, 0, sizeof r);
    r.position[0] = x;
    r.position[1] = y;
    r.normal[2] = -1.0f;
    r.uv[0] = u;
    r.uv[1] = v;
    return r;
}

/* A square of half-size s facing the camera at z = -3. */
static mote_vertex quad_v[4];
static const uint32_t quad_i[6] = {0, 1, 2, 0, 2, 3};
static mote_mesh quad(float s)
{
    quad_v[0] = vtx(-s, -s, 0, 0);
    quad_v[1] = vtx(-s, s, 0, 1);
    quad_v[2] = vtx(s, s, 1, 1);
    quad_v[3] = vtx(s, -s, 1, 0);
    return tu_mesh_of(quad_v, 4, quad_i, 6);
}

/* A full-frame device's description: RGBA colour, 32-bit depth. */
static mote_device_desc desc_of(int width, int height, void *color, void *depth)
{
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = width;
    d.height = height;
    d.color = color;
    d.depth = depth;
    return d;
}

static mote_frame_desc frame_desc(void)
{
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    f.camera.position[2] = -3.0f;
    return f;
}

static mote_draw_desc unlit(void)
{
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.cull = MOTE_CULL_NONE;
    d.unlit = true;
    return d;
}

/* Pixels whose red differs from the clear colour's (0). */
static int lit_pixels(const uint8_t *rgba, int n)
{
    int lit = 0;
    for (int i = 0; i < n; i++)
        lit += rgba[4 * i] != 0;
    return lit;
}

static void draw_frame(mote_device *dev, const mote_mesh *m)
{
    mote_frame_desc f = frame_desc();
    mote_draw_desc d = unlit();
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(dev, &f));
    if (m)
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(dev, m, &d));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(dev));
}

static void serial_parallel_for(void *user, int count, mote_task_fn fn, void *arg)
{
    (void)user;
    for (int i = 0; i < count; i++)
        fn(arg, i);
}

/* 16- and 32-bit pixels and depth values are stored as whole words: a
 * buffer off their alignment is refused (a Cortex-M0+ faults on it). */
void buffers_off_their_alignment_should_be_refused(void)
{
    static uint32_t color_words[W * H + 1], depth_words[W * H + 1];
    uint8_t *color = (uint8_t *)color_words, *depth = (uint8_t *)depth_words;
    mote_device dev;
    mote_device_desc d = desc_of(W, H, color + 1, depth);
    d.color_format = MOTE_FORMAT_RGB565;
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_device_init(&dev, &d));
    d.color = color + 2;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    d.depth = depth + 2;          /* 32-bit depth (the default) */
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_device_init(&dev, &d));
    d.depth_format = MOTE_DEPTH_FORMAT_16;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    d.depth = depth + 1;
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_device_init(&dev, &d));
    d.depth_format = MOTE_DEPTH_FORMAT_NONE;   /* not used: not checked */
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    d.color_format = MOTE_FORMAT_GREY8;
    d.color = color + 1;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
}

/* The arena is used in whole 8-byte words (its records are aligned from
 * both ends) and no further than its 32-bit offsets reach; an odd size
 * renders what a rounded one does. */
void arena_sizes_should_be_cut_to_what_the_arena_can_use(void)
{
    static uint64_t arena[(256u << 10) / 8 + 1];
    static uint8_t a[W * H * 4], b[W * H * 4];
    static uint32_t depth[W * H];
    mote_device dev;
    mote_device_desc d = desc_of(W, H, a, depth);
    d.arena = arena;
    mote_mesh m = quad(1.0f);
    d.arena_size = (256u << 10) + 5;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    TEST_ASSERT_EQUAL(0, dev.bin.size % 8);
    draw_frame(&dev, &m);
    d.color = b;
    d.arena_size = 256u << 10;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    draw_frame(&dev, &m);
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
    TEST_ASSERT_TRUE(lit_pixels(a, W * H) > 0);
    if (sizeof(size_t) > 4) {     /* init reads the size only: no byte past 256 KB is touched */
        d.arena_size = (size_t)((uint64_t)1 << 33) + 3;
        TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
        TEST_ASSERT_EQUAL_UINT64(UINT32_MAX & ~(uint64_t)7, (uint64_t)dev.bin.size);
    }
}

/* clear_drawn_tiles_only: a triangle that does not fit in the arena is
 * drawn directly, past the tiles, and the next frame must still clear
 * where it drew. */
void a_triangle_drawn_past_the_tiles_should_be_cleared_the_next_frame(void)
{
    enum { BW = 256, BH = 256 };
    static uint8_t color[BW * BH * 4];
    static uint32_t depth[BW * BH];
    static uint64_t arena[100000 / 8];
    mote_device dev;
    mote_device_desc d = desc_of(BW, BH, color, depth);
    d.arena = arena;
    d.arena_size = sizeof arena;
    d.tile_size = 8;              /* a screen-filling quad needs more list blocks than fit */
    d.clear_drawn_tiles_only = true;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    mote_mesh m = quad(5.0f);
    draw_frame(&dev, &m);
    TEST_ASSERT_EQUAL(BW * BH, lit_pixels(color, BW * BH));
    draw_frame(&dev, NULL);
    TEST_ASSERT_EQUAL(0, lit_pixels(color, BW * BH));
}

/* A frame begun again before mote_end is abandoned; with the clear put off
 * until the first draws are set up (parallel_for), that clear is still
 * owed to the tiles the frame before drew. */
void a_frame_begun_twice_should_still_clear_what_the_last_one_drew(void)
{
    static uint8_t color[W * H * 4];
    static uint32_t depth[W * H];
    static uint64_t arena[(1u << 20) / 8];
    for (int hook = 0; hook < 2; hook++) {
        mote_device dev;
        mote_device_desc d = desc_of(W, H, color, depth);
        d.arena = arena;
        d.arena_size = sizeof arena;
        d.clear_drawn_tiles_only = true;
        d.parallel_for = hook ? serial_parallel_for : NULL;
        TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
        mote_mesh m = quad(1.0f);
        draw_frame(&dev, &m);
        TEST_ASSERT_TRUE(lit_pixels(color, W * H) > 0);
        mote_frame_desc f = frame_desc();
        TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));   /* abandoned */
        draw_frame(&dev, NULL);
        TEST_ASSERT_EQUAL(0, lit_pixels(color, W * H));
    }
}

typedef struct band_out {
    uint8_t rgba[W * H * 4];
} band_out;

static void band_flush(void *user, int y0, int rows, const void *color, int stride)
{
    band_out *o = (band_out *)user;
    for (int r = 0; r < rows; r++)
        memcpy(o->rgba + (size_t)(y0 + r) * W * 4, (const uint8_t *)color + (size_t)r * (size_t)stride, W * 4);
}

/* Band mode clears every band: a band's buffer holds other rows between
 * frames, so keep_color and keep_depth have nothing to keep there (they
 * gave the previous band's rows). */
void band_mode_should_clear_every_band_even_when_asked_to_keep(void)
{
    enum { BAND = 8 };
    static uint8_t color[W * BAND * 4];
    static uint32_t depth[W * BAND];
    static band_out out;
    mote_device dev;
    mote_device_desc d = desc_of(W, H, color, depth);
    d.band_height = BAND;
    d.flush = band_flush;
    d.flush_user = &out;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    mote_mesh m = quad(0.5f);
    draw_frame(&dev, &m);
    TEST_ASSERT_TRUE(lit_pixels(out.rgba, W * H) > 0);
    mote_frame_desc f = frame_desc();
    f.keep_color = f.keep_depth = true;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_EQUAL(0, lit_pixels(out.rgba, W * H));
}

/* A texture whose stride is no multiple of its texel size, shorter than a
 * row, or whose texels are off their alignment is not sampled (16-bit
 * texels would be read unaligned): the mesh is drawn untextured. */
void textures_with_bad_strides_should_draw_untextured(void)
{
    static uint16_t texels[17 * 16 + 8];   /* room for the padded stride below (34 bytes a row) */
    static uint8_t plain[W * H * 4], got[W * H * 4];
    static uint32_t depth[W * H];
    for (size_t i = 0; i < sizeof texels / sizeof texels[0]; i++)
        texels[i] = (uint16_t)(i * 2654435761u >> 7);
    mote_texture bad[3] = {{16, 16, MOTE_FORMAT_RGB565, 33, texels},
                           {16, 16, MOTE_FORMAT_RGB565, 16, texels},
                           {16, 16, MOTE_FORMAT_RGB565, 0, (const uint8_t *)texels + 1}};
    mote_device dev;
    mote_device_desc d = desc_of(W, H, plain, depth);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    mote_mesh m = quad(1.0f);
    m.material.color = (mote_rgba){200, 100, 50, 255};
    m.material.color_set = true;
    draw_frame(&dev, &m);
    TEST_ASSERT_TRUE(lit_pixels(plain, W * H) > 0);
    d.color = got;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    for (int k = 0; k < 3; k++) {
        m.material.texture = &bad[k];
        draw_frame(&dev, &m);
        TEST_ASSERT_EQUAL_MEMORY(plain, got, sizeof plain);
    }
    mote_texture good = {16, 16, MOTE_FORMAT_RGB565, 34, texels};   /* a padded stride is fine */
    m.material.texture = &good;
    draw_frame(&dev, &m);
    TEST_ASSERT_TRUE(memcmp(plain, got, sizeof plain) != 0);
}

/* NULL pointers give a failed projection and no statistics, not a crash. */
void null_pointers_should_fail_without_a_crash(void)
{
    static uint8_t color[W * H * 4];
    static uint32_t depth[W * H];
    mote_device dev;
    mote_device_desc d = desc_of(W, H, color, depth);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    draw_frame(&dev, NULL);
    const float origin[3] = {0, 0, 0};
    float x = -1.0f, y = -1.0f, z = -1.0f;
    TEST_ASSERT_TRUE(mote_project(&dev, origin, &x, &y, &z));
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, W / 2.0f, x);
    TEST_ASSERT_TRUE(z > 0.0f && z < 1.0f);
    TEST_ASSERT_FALSE(mote_project(&dev, origin, NULL, NULL, NULL));
    TEST_ASSERT_FALSE(mote_project(NULL, origin, &x, &y, &z));
    TEST_ASSERT_FALSE(mote_project(&dev, NULL, &x, &y, &z));
    TEST_ASSERT_NULL(mote_device_stats(NULL));
}

/* The mesh helpers take NULL too: no mesh has the identity as its world
 * matrix, and a mesh without a vertex array has no vertices, whatever
 * vertex_count says: an unknown bound (never rejected). */
void mesh_helpers_should_take_null_pointers(void)
{
    float w[16];
    memset(w, 0xab, sizeof w);
    mote_mesh_world_matrix(NULL, w);
    for (int i = 0; i < 16; i++)
        TEST_ASSERT_EQUAL_FLOAT(i % 5 == 0 ? 1.0f : 0.0f, w[i]);
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.position[0] = 3.0f;
    mote_mesh_world_matrix(&m, NULL);
    mote_mesh_update_bounds(NULL);
    m.vertex_count = 5;
    m.bounds_center[1] = 7.0f;
    m.bounds_radius = 2.0f;
    mote_mesh_update_bounds(&m);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, m.bounds_radius);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, m.bounds_center[1]);
}

/* Sizes and formats no device can have: no size, and no bytes written. */
void sizes_and_formats_no_device_has_should_give_nothing(void)
{
    TEST_ASSERT_EQUAL_UINT64(0, (uint64_t)mote_band_bytes(INT_MAX, INT_MAX, MOTE_FORMAT_RGBA8888,
                                                          MOTE_DEPTH_FORMAT_32));
    TEST_ASSERT_EQUAL_UINT64(0, (uint64_t)mote_band_bytes(MOTE_MAX_SIZE + 1, 1, MOTE_FORMAT_GREY8,
                                                          MOTE_DEPTH_FORMAT_NONE));
    TEST_ASSERT_EQUAL_UINT64((uint64_t)MOTE_MAX_SIZE * MOTE_MAX_SIZE * 8,
                             (uint64_t)mote_band_bytes(MOTE_MAX_SIZE, MOTE_MAX_SIZE, MOTE_FORMAT_RGBA8888,
                                                       MOTE_DEPTH_FORMAT_32));
    const uint8_t src[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    uint8_t dst[16];
    memset(dst, 0xab, sizeof dst);
    mote_convert_row(src, MOTE_FORMAT_RGBA8888, dst, MOTE_FORMAT_COUNT, 2);
    mote_convert_row(src, (mote_format)99, dst, MOTE_FORMAT_RGBA8888, 2);
    for (size_t i = 0; i < sizeof dst; i++)
        TEST_ASSERT_EQUAL_HEX8(0xab, dst[i]);
}

/* max_file_bytes = SIZE_MAX means no limit: the file's one-past-the-limit
 * check must not wrap to a limit of 0. */
void a_file_limit_of_size_max_should_be_no_limit(void)
{
    const char *json = "{\"meshes\":[{\"id\":\"t\",\"positions\":[0,0,0,1,0,0,0,1,0],\"indices\":[0,1,2]}]}";
    char path[] = "/tmp/mote_api_edges_XXXXXX";
    FILE *f = NULL;
    int fd = mkstemp(path);
    TEST_ASSERT_TRUE(fd >= 0);
    f = fdopen(fd, "wb");
    TEST_ASSERT_NOT_NULL(f);
    fputs(json, f);
    fclose(f);
    mote_limits lim = mote_limits_default();
    lim.max_file_bytes = SIZE_MAX;
    mote_scene s;
    char msg[256];
    mote_result r = mote_scene_load(path, &lim, &s, msg, sizeof msg);
    remove(path);
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, r, msg);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    mote_scene_free(&s);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(buffers_off_their_alignment_should_be_refused);
    RUN_TEST(arena_sizes_should_be_cut_to_what_the_arena_can_use);
    RUN_TEST(a_triangle_drawn_past_the_tiles_should_be_cleared_the_next_frame);
    RUN_TEST(a_frame_begun_twice_should_still_clear_what_the_last_one_drew);
    RUN_TEST(band_mode_should_clear_every_band_even_when_asked_to_keep);
    RUN_TEST(textures_with_bad_strides_should_draw_untextured);
    RUN_TEST(null_pointers_should_fail_without_a_crash);
    RUN_TEST(mesh_helpers_should_take_null_pointers);
    RUN_TEST(sizes_and_formats_no_device_has_should_give_nothing);
    RUN_TEST(a_file_limit_of_size_max_should_be_no_limit);
    return UNITY_END();
}
