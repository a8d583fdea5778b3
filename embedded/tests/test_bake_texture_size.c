/*
 * test_bake_texture_size.c - mote-bake --texture-size: the firmware
 * example's cube (embedded/scene/cube.babylon, a 64x64 texture) baked at
 * 16x16 ("quarter": each texel the rounded mean of a 4x4 block) and at
 * 128x16 ("wide": each source column twice, four rows a texel), in
 * RGBA8888, against the texture the loader reads.
 */
#include <mote/mote.h>
#include <mote/mote_io.h>

#include <stdio.h>

#include "unity.h"

#include "quarter.h"
#include "wide.h"

static mote_scene scene;
static const mote_texture *loaded;
static char msg[512];

void setUp(void)
{
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MOTE_BAKE_CUBE, NULL, &scene, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_INT(1, scene.texture_count);
    loaded = &scene.textures[0];
    TEST_ASSERT_EQUAL_INT(64, loaded->width);
    TEST_ASSERT_EQUAL_INT(64, loaded->height);
    TEST_ASSERT_EQUAL_INT(MOTE_FORMAT_RGBA8888, loaded->format);
}

void tearDown(void)
{
    mote_scene_free(&scene);
}

/* the rounded mean of channel c over the source texels [x0, x1) x [y0, y1) */
static int box_mean(int x0, int x1, int y0, int y1, int c)
{
    const uint8_t *p = loaded->pixels;
    int stride = loaded->stride ? loaded->stride : loaded->width * 4;
    int sum = 0, n = (x1 - x0) * (y1 - y0);
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            sum += p[y * stride + x * 4 + c];
    return (sum + n / 2) / n;
}

static void check_baked(const mote_texture *t, int width, int height, int x_scale_num, int x_scale_den)
{
    TEST_ASSERT_EQUAL_INT(width, t->width);
    TEST_ASSERT_EQUAL_INT(height, t->height);
    TEST_ASSERT_EQUAL_INT(width * 4, t->stride);
    const uint8_t *baked = t->pixels;
    int rows = loaded->height / height;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++)
            for (int c = 0; c < 4; c++) {
                int x0 = x * x_scale_num / x_scale_den;
                int x1 = x0 + (x_scale_num >= x_scale_den ? x_scale_num / x_scale_den : 1);
                int want = box_mean(x0, x1, y * rows, (y + 1) * rows, c);
                if (baked[(y * width + x) * 4 + c] != want) {
                    snprintf(msg, sizeof msg, "texel (%d, %d) channel %d: %d, want %d", x, y, c,
                             baked[(y * width + x) * 4 + c], want);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
}

static void texture_size_should_average_whole_blocks(void)
{
    check_baked(&quarter_textures[0], 16, 16, 4, 1);
    TEST_ASSERT_EQUAL_PTR(&quarter_textures[0], quarter_meshes[0].material.texture);
}

static void texture_size_should_repeat_texels_when_larger(void)
{
    check_baked(&wide_textures[0], 128, 16, 1, 2);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(texture_size_should_average_whole_blocks);
    RUN_TEST(texture_size_should_repeat_texels_when_larger);
    return UNITY_END();
}
