/*
 * test_options.c - the core built with MOTE_ENABLE_* options turned off
 * (tests/options/options.mk builds this file once per option, against the
 * core sources compiled with that option at 0): asking for a feature left
 * out gets MOTE_ERR_UNSUPPORTED and draws nothing; everything else still
 * draws, and the image of a draw that uses no left-out feature is the
 * same whatever is left out (tests/options/run.sh compares its hash with
 * the one this file prints when built with every feature).
 */
#include <mote/mote.h>
#include "support/scenes.h"
#include "unity.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 48

static uint8_t color[W * H * 4];
static uint32_t depth[W * H];
static uint8_t arena[1 << 16];
static mote_device dev;
static tu_scene scene;            /* a textured floor and cube in strong perspective */

static void init_device(void *arena_mem, size_t arena_size)
{
    mote_device_desc d = {.width = W, .height = H, .color = color, .depth = depth,
                          .arena = arena_mem, .arena_size = arena_size};
    TEST_ASSERT_EQUAL(arena_mem && !MOTE_ENABLE_BINNING ? MOTE_ERR_UNSUPPORTED : MOTE_OK,
                      mote_device_init(&dev, &d));
}

void setUp(void)
{
    init_device(NULL, 0);
    tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, &scene);
}

void tearDown(void) {}

static uint32_t frame_hash(void)
{
    uint32_t h = 2166136261u;
    for (size_t i = 0; i < sizeof color; i++)
        h = (h ^ color[i]) * 16777619u;
    return h;
}

/* Draws the scene once with desc; returns what mote_draw said (the same
 * for every mesh). */
static mote_result draw_once(const mote_draw_desc *desc)
{
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &scene.frame));
    mote_result r = MOTE_OK;
    for (int i = 0; i < scene.mesh_count; i++)
        r = mote_draw(&dev, &scene.meshes[i], desc);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    return r;
}

static void check_feature(bool enabled, const mote_draw_desc *desc)
{
    mote_result r = draw_once(desc);
    if (enabled) {
        TEST_ASSERT_EQUAL(MOTE_OK, r);
        TEST_ASSERT_TRUE(mote_device_stats(&dev)->pixels_written > 0);
    } else {
        TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED, r);
        TEST_ASSERT_EQUAL_UINT32(0, mote_device_stats(&dev)->triangles_in);
        TEST_ASSERT_EQUAL_UINT64(0, mote_device_stats(&dev)->pixels_written);
    }
}

void a_plain_textured_draw_should_work_in_every_build(void)
{
    TEST_ASSERT_EQUAL(MOTE_OK, draw_once(NULL));
    TEST_ASSERT_TRUE(mote_device_stats(&dev)->triangles_drawn > 0);
    /* the same bytes as the full build: run.sh passes its hash */
    const char *full = getenv("MOTE_OPTIONS_HASH");
    printf("options: plain textured frame hash %08x\n", (unsigned)frame_hash());
    if (full && *full)
        TEST_ASSERT_EQUAL_HEX32((uint32_t)strtoul(full, NULL, 16), frame_hash());
}

void wireframe_and_points_should_need_lines(void)
{
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.mode = MOTE_MODE_WIREFRAME;
    check_feature(MOTE_ENABLE_LINES, &d);
    d.mode = MOTE_MODE_POINTS;
    check_feature(MOTE_ENABLE_LINES, &d);
}

void bilinear_filtering_should_need_its_option(void)
{
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.filter = MOTE_FILTER_BILINEAR;
    check_feature(MOTE_ENABLE_BILINEAR, &d);
}

void subspan_perspective_should_need_its_option(void)
{
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.perspective = MOTE_PERSPECTIVE_SUBSPAN;
    check_feature(MOTE_ENABLE_SUBSPAN, &d);
}

void vertex_colours_should_need_their_option(void)
{
    tu_scene_build(TU_SCENE_COLORS, MOTE_WRAP_REPEAT, &scene);   /* every mesh has colors */
    check_feature(MOTE_ENABLE_VERTEX_COLORS, NULL);
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.mode = MOTE_MODE_FLAT;
    d.unlit = true;
    check_feature(MOTE_ENABLE_VERTEX_COLORS, &d);
    /* without colours the same meshes draw in every build */
    for (int i = 0; i < scene.mesh_count; i++)
        scene.meshes[i].colors = NULL;
    check_feature(true, &d);
}

/* Left out, a spot light lights nothing and a range is ignored (mote.h:
 * the one feature not refused, for want of flash). Lit by one light and
 * no ambient, the scene is black where nothing lights it. */
static uint64_t lit_channels(const mote_light *light)
{
    mote_frame_desc f = scene.frame;
    f.light_count = 1;
    f.lights[0] = *light;
    f.ambient[0] = f.ambient[1] = f.ambient[2] = 0.0f;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
    for (int i = 0; i < scene.mesh_count; i++)
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &scene.meshes[i], NULL));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_TRUE(mote_device_stats(&dev)->pixels_written > 0);
    uint64_t lit = 0;
    for (size_t i = 0; i < sizeof color; i += 4)
        lit += color[i] > 0 || color[i + 1] > 0 || color[i + 2] > 0;
    return lit;
}

void spot_lights_and_ranges_should_light_only_with_falloff(void)
{
    mote_light l;
    memset(&l, 0, sizeof l);
    l.type = MOTE_LIGHT_POINT;
    l.position[1] = 20.0f;        /* high above the floor */
    uint64_t plain = lit_channels(&l);
    TEST_ASSERT_TRUE(plain > 0);
    l.range = 1.0f;               /* reaches nothing */
    TEST_ASSERT_EQUAL_UINT64(MOTE_ENABLE_LIGHT_FALLOFF ? 0 : plain, lit_channels(&l));
    l.range = 0.0f;
    l.type = MOTE_LIGHT_SPOT;     /* down onto the scene, a wide cone */
    l.direction[1] = -1.0f;
    l.spot_angle = 3.0f;
    uint64_t spot = lit_channels(&l);
    TEST_ASSERT_TRUE(MOTE_ENABLE_LIGHT_FALLOFF ? spot > 0 : spot == 0);
}

void orthographic_cameras_should_need_their_option(void)
{
    mote_frame_desc f = scene.frame;
    f.camera.projection = MOTE_PROJECTION_ORTHOGRAPHIC;
    if (!MOTE_ENABLE_ORTHOGRAPHIC) {
        TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED, mote_begin(&dev, &f));
        return;
    }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
    for (int i = 0; i < scene.mesh_count; i++)
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &scene.meshes[i], NULL));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_TRUE(mote_device_stats(&dev)->pixels_written > 0);
}

void an_arena_should_need_binning(void)
{
    /* init_device checks the result: MOTE_ERR_UNSUPPORTED without binning */
    init_device(arena, sizeof arena);
    if (!MOTE_ENABLE_BINNING) {
        TEST_ASSERT_EQUAL(MOTE_ERR_STATE, mote_begin(&dev, &scene.frame));
        return;
    }
    TEST_ASSERT_EQUAL(MOTE_OK, draw_once(NULL));
    TEST_ASSERT_TRUE(mote_device_stats(&dev)->pixels_written > 0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(a_plain_textured_draw_should_work_in_every_build);
    RUN_TEST(wireframe_and_points_should_need_lines);
    RUN_TEST(bilinear_filtering_should_need_its_option);
    RUN_TEST(subspan_perspective_should_need_its_option);
    RUN_TEST(vertex_colours_should_need_their_option);
    RUN_TEST(spot_lights_and_ranges_should_light_only_with_falloff);
    RUN_TEST(orthographic_cameras_should_need_their_option);
    RUN_TEST(an_arena_should_need_binning);
    return UNITY_END();
}
