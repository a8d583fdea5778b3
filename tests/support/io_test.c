/*
 * io_test.c - helpers of the src/io tests (io_test.h).
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include "support/io_test.h"

static char load_message[512];
static char tmp_dir[64];

long io_test_begin(void)
{
    mote__io_set_alloc_failure_after(-1);
    return mote__io_live_allocations();
}

void io_load_json_in(const char *json, const char *name, const char *dir, mote_scene *s)
{
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(json, strlen(json), name, dir, NULL,
                                                              s, load_message,
                                                              sizeof load_message),
                              load_message);
}

void io_load_json(const char *json, const char *name, mote_scene *s)
{
    io_load_json_in(json, name, NULL, s);
}

static void remove_tmp_dir(void)
{
    char cmd[96];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp_dir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", tmp_dir);
}

const char *io_tmp_dir(void)
{
    if (!tmp_dir[0]) {
        snprintf(tmp_dir, sizeof tmp_dir, "/tmp/mote-test-io-XXXXXX");
        TEST_ASSERT_NOT_NULL_MESSAGE(mkdtemp(tmp_dir), "mkdtemp");
        atexit(remove_tmp_dir);
    }
    return tmp_dir;
}

const char *io_tmp_path(const char *name)
{
    static char path[512];
    snprintf(path, sizeof path, "%s/%s", io_tmp_dir(), name);
    return path;
}

bool io_file_exists(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f)
        fclose(f);
    return f != NULL;
}

void io_init_color_device(mote_device *dev, uint8_t *color, int width, int height)
{
    mote_device_desc dd;
    memset(&dd, 0, sizeof dd);
    dd.width = width;
    dd.height = height;
    dd.color = color;
    dd.depth_format = MOTE_DEPTH_FORMAT_NONE;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(dev, &dd));
}

void io_begin_small_frame(mote_device *dev, uint8_t *color, int size)
{
    io_init_color_device(dev, color, size, size);
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    f.camera.position[2] = -3.0f;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(dev, &f));
}

void io_world_origin(const mote_mesh *m, float out[3])
{
    float w[16];
    mote_mesh_world_matrix(m, w);
    memcpy(out, &w[12], 3 * sizeof *out);
}

void io_render_scene(const mote_scene *s, uint8_t *rgba, int width, int height)
{
    uint32_t *depth = malloc((size_t)width * (size_t)height * sizeof *depth);
    TEST_ASSERT_NOT_NULL(depth);
    mote_device dev;
    mote_device_desc dd = {.width = width, .height = height, .color = rgba, .depth = depth,
                           .clear_color = s->clear_color};
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &dd));
    mote_frame_desc frame;
    mote_scene_frame(s, (float)width / (float)height, &frame);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    /* Babylon.js's order: opaque, alpha-tested, blended back to front */
    int *order = malloc((size_t)(s->mesh_count > 0 ? s->mesh_count : 1) * sizeof *order);
    TEST_ASSERT_NOT_NULL(order);
    TEST_ASSERT_EQUAL_INT(s->mesh_count > 0 ? s->mesh_count : 0, mote_scene_draw_order(s, s->meshes, &frame.camera, order));
    for (int k = 0; k < s->mesh_count; k++)
        TEST_ASSERT_EQUAL(MOTE_OK, mote_scene_draw(&dev, s, s->meshes, order[k], NULL));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    free(order);
    free(depth);
}
