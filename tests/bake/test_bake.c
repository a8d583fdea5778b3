/*
 * test_bake.c - what mote-bake writes is the scene the loader reads: the
 * header baked from tests/data/vertex_colors.babylon (tests/bake/bake.mk)
 * against the same file loaded with mote_scene_load, field by field, with
 * its vertex colours (one array per vertex array, shared by sub-meshes),
 * and rendered to the same bytes; the one baked from
 * tests/data/bake_hidden.babylon, whose hidden meshes stay hidden and
 * whose disableLighting sign stays unlit; and a
 * scene seen by an orthographic camera (tests/data/ortho_camera.babylon),
 * baked as "ortho"; the textured assets/cube.babylon in each texture
 * format ("cube_rgb565"...); gen_gltf's lines.gltf, points and lines
 * in their modes ("lines"); and tests/data/transparency.babylon and
 * fog.babylon ("glass", "fogged"), whose draw options and order, drawn as
 * firmware would, give mote_scene_draw's picture. The others are baked in
 * the vertex cache's order: assets/torus.babylon ("torus") and
 * tests/bake/reorder.babylon ("reorder", and "reorder_compact"), whose
 * vertices and triangles are the loaded ones, reordered, so that a
 * direct-mapped cache transforms fewer of them, and render as loaded.
 */
#include <mote/mote.h>
#include <mote/mote_io.h>
#include "unity.h"

#include "baked.h"
#include "ortho.h"
#include "baked_hidden.h"
#include "cube_rgb565.h"
#include "cube_rgba8888.h"
#include "cube_grey8.h"
#include "cube_compact.h"
#include "lines.h"
#include "glass.h"
#include "fogged.h"
#include "prepass.h"
#include "torus.h"
#include "reorder.h"
#include "reorder_compact.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define W BAKED_WIDTH
#define H BAKED_HEIGHT

static mote_scene scene;
static char msg[512];

void setUp(void)
{
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MOTE_BAKE_SCENE, NULL, &scene, msg, sizeof msg), msg);
}

void tearDown(void)
{
    mote_scene_free(&scene);
}

void baked_meshes_should_hold_the_loaded_arrays_and_vertex_colours(void)
{
    TEST_ASSERT_EQUAL(scene.mesh_count, BAKED_MESH_COUNT);
    for (int i = 0; i < scene.mesh_count; i++) {
        const mote_mesh *a = &scene.meshes[i], *b = &baked_meshes[i];
        TEST_ASSERT_EQUAL_UINT32(a->vertex_count, b->vertex_count);
        TEST_ASSERT_EQUAL_UINT32(a->index_count, b->index_count);
        TEST_ASSERT_EQUAL_MEMORY(a->vertices, b->vertices, a->vertex_count * sizeof *a->vertices);
        TEST_ASSERT_EQUAL_MEMORY(a->indices, b->indices, a->index_count * sizeof *a->indices);
        TEST_ASSERT_EQUAL_MEMORY(a->position, b->position, sizeof a->position);
        TEST_ASSERT_EQUAL(a->colors == NULL, b->colors == NULL);
        if (a->colors)
            TEST_ASSERT_EQUAL_MEMORY(a->colors, b->colors, a->vertex_count * sizeof *a->colors);
    }
    /* the file's first mesh has two sub-meshes: one colour array for both */
    TEST_ASSERT_NOT_NULL(baked_meshes[0].colors);
    TEST_ASSERT_EQUAL_PTR(baked_meshes[0].colors, baked_meshes[1].colors);
}

static void render(const mote_mesh *meshes, int n, const mote_frame_desc *frame, mote_rgba clear,
                   mote_draw_desc d, uint8_t *out)
{
    static uint32_t depth[W * H];
    static mote_device dev;
    mote_device_desc desc = {.width = W, .height = H, .color = out, .depth = depth, .clear_color = clear};
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &desc));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, frame));
    for (int i = 0; i < n; i++)
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &meshes[i], &d));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
}

/* The same with each mesh's own draw options, descs[i]. */
static void render_each(const mote_mesh *meshes, int n, const mote_frame_desc *frame,
                        const mote_draw_desc *descs, uint8_t *out)
{
    static uint32_t depth[W * H];
    static mote_device dev;
    mote_device_desc desc = {.width = W, .height = H, .color = out, .depth = depth};
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &desc));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, frame));
    for (int i = 0; i < n; i++)
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &meshes[i], &descs[i]));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
}

/* Renders a loaded scene's meshes and the baked ones, each n, with their
 * frames and clear colours and the draw options d; checks that the bytes
 * are the same and returns the pixels drawn (not black). */
static int render_as_loaded(const mote_scene *s, const mote_mesh *meshes, int n,
                            const mote_frame_desc *frame_as_baked, mote_rgba clear, mote_draw_desc d)
{
    static uint8_t loaded[W * H * 4], baked[W * H * 4];
    mote_frame_desc frame;
    mote_scene_frame(s, (float)W / (float)H, &frame);
    TEST_ASSERT_EQUAL(s->mesh_count, n);
    render(s->meshes, n, &frame, s->clear_color, d, loaded);
    render(meshes, n, frame_as_baked, clear, d, baked);
    TEST_ASSERT_EQUAL_MEMORY(loaded, baked, sizeof loaded);
    int drawn = 0;
    for (int i = 0; i < W * H; i++)
        drawn += loaded[4 * i] || loaded[4 * i + 1] || loaded[4 * i + 2];
    return drawn;
}

void a_baked_scene_should_render_the_same_bytes_as_the_loaded_one(void)
{
    static const mote_mode modes[] = {MOTE_MODE_FLAT, MOTE_MODE_GOURAUD};
    for (int k = 0; k < 2; k++) {
        mote_draw_desc d;
        memset(&d, 0, sizeof d);
        d.mode = modes[k];
        d.cull = MOTE_CULL_NONE;
        TEST_ASSERT_TRUE(render_as_loaded(&scene, baked_meshes, BAKED_MESH_COUNT, &baked_frame,
                                          baked_clear_color, d) > 100);
    }
}

/* The orthographic camera's projection and box are baked: the same
 * bytes as the loaded scene, and not those of a perspective camera. */
void a_baked_orthographic_camera_should_render_as_loaded(void)
{
    mote_scene iso;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MOTE_BAKE_ORTHO, NULL, &iso, msg, sizeof msg), msg);
    mote_frame_desc frame;
    mote_scene_frame(&iso, (float)W / (float)H, &frame);
    TEST_ASSERT_EQUAL(MOTE_PROJECTION_ORTHOGRAPHIC, ortho_frame.camera.projection);
    TEST_ASSERT_EQUAL_MEMORY(frame.camera.ortho, ortho_frame.camera.ortho, sizeof frame.camera.ortho);
    static uint8_t loaded[W * H * 4], baked[W * H * 4];
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.mode = MOTE_MODE_GOURAUD;
    render(iso.meshes, iso.mesh_count, &frame, iso.clear_color, d, loaded);
    render(ortho_meshes, ORTHO_MESH_COUNT, &ortho_frame, ortho_clear_color, d, baked);
    TEST_ASSERT_EQUAL_MEMORY(loaded, baked, sizeof loaded);
    mote_frame_desc seen_in_perspective = ortho_frame;
    seen_in_perspective.camera.projection = MOTE_PROJECTION_PERSPECTIVE;
    render(ortho_meshes, ORTHO_MESH_COUNT, &seen_in_perspective, ortho_clear_color, d, baked);
    TEST_ASSERT_TRUE(memcmp(loaded, baked, sizeof loaded) != 0);
    mote_scene_free(&iso);
}

/* A mesh whose material has backFaceCulling false is baked as two-sided
 * (the scene's grey material says so, for the sub-mesh drawn with it). */
void baked_meshes_should_keep_which_are_two_sided(void)
{
    TEST_ASSERT_NOT_NULL(scene.two_sided);
    int two = 0;
    for (int i = 0; i < scene.mesh_count; i++) {
        TEST_ASSERT_EQUAL(scene.two_sided[i], baked_two_sided[i]);
        two += baked_two_sided[i];
    }
    TEST_ASSERT_TRUE(two > 0 && two < scene.mesh_count);
}

/* A glTF scene's points and lines keep their modes: drawn with the baked
 * modes (lines without culling) they render as the loaded scene drawn
 * through mote_scene_draw_desc. */
void baked_points_and_lines_should_keep_their_modes(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MOTE_BAKE_LINES, NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(s.mesh_count, LINES_MESH_COUNT);
    int lines = 0, points = 0;
    for (int i = 0; i < s.mesh_count; i++) {
        TEST_ASSERT_EQUAL(s.modes[i], lines_modes[i]);
        lines += lines_modes[i] == MOTE_MODE_WIREFRAME;
        points += lines_modes[i] == MOTE_MODE_POINTS;
    }
    TEST_ASSERT_EQUAL(4, lines);
    TEST_ASSERT_EQUAL(2, points);
    mote_draw_desc as_loaded[LINES_MESH_COUNT], as_baked[LINES_MESH_COUNT];
    for (int i = 0; i < s.mesh_count; i++) {
        mote_scene_draw_desc(&s, i, NULL, &as_loaded[i]);
        as_baked[i] = (mote_draw_desc){.mode = lines_modes[i]};
        if (lines_modes[i] == MOTE_MODE_WIREFRAME)
            as_baked[i].cull = MOTE_CULL_NONE;
    }
    static uint8_t loaded[W * H * 4], baked[W * H * 4];
    mote_frame_desc frame;
    mote_scene_frame(&s, (float)W / (float)H, &frame);
    render_each(s.meshes, s.mesh_count, &frame, as_loaded, loaded);
    render_each(lines_meshes, LINES_MESH_COUNT, &lines_frame, as_baked, baked);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL_MEMORY(loaded, baked, sizeof loaded);
    int green = 0;
    for (int i = 0; i < W * H; i++)
        green += baked[4 * i + 1] == 255;
    TEST_ASSERT_TRUE(green > 20);
}

/* A mesh the loader hides (isVisible false, or under a disabled node) is
 * baked hidden: the firmware draws what the loaded scene draws. The hidden
 * meshes are red quads in front of the green triangle, over the whole
 * frame. */
void baked_meshes_should_keep_which_are_hidden(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MOTE_BAKE_HIDDEN, NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(s.mesh_count, BAKED_HIDDEN_MESH_COUNT);
    int hidden = 0;
    for (int i = 0; i < s.mesh_count; i++) {
        TEST_ASSERT_EQUAL(s.meshes[i].hidden, baked_hidden_meshes[i].hidden);
        hidden += baked_hidden_meshes[i].hidden;
    }
    TEST_ASSERT_TRUE(hidden >= 2);
    static uint8_t loaded[W * H * 4], baked[W * H * 4];
    mote_frame_desc frame;
    mote_scene_frame(&s, (float)W / (float)H, &frame);
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.mode = MOTE_MODE_GOURAUD;
    d.cull = MOTE_CULL_NONE;
    render(s.meshes, s.mesh_count, &frame, s.clear_color, d, loaded);
    render(baked_hidden_meshes, BAKED_HIDDEN_MESH_COUNT, &baked_hidden_frame,
           baked_hidden_clear_color, d, baked);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL_MEMORY(loaded, baked, sizeof loaded);
    int green = 0;
    for (int i = 0; i < W * H; i++) {
        TEST_ASSERT_EQUAL_UINT8(0, baked[4 * i]);
        green += baked[4 * i + 1] > 0;
    }
    TEST_ASSERT_TRUE(green > 100);
}

/* A mesh whose material says disableLighting is baked unlit, and drawn
 * with the baked flags it renders as the loaded scene drawn through
 * mote_scene_draw_desc: its emissive blue (0.5: 128) exactly, lights or
 * not (the hidden scene's sign, in a corner of the frame). A lit
 * material's emissive colour is baked too (the shown mesh's blue glow). */
void baked_meshes_should_keep_which_are_unlit_and_their_emissive_colours(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MOTE_BAKE_HIDDEN, NULL, &s, msg, sizeof msg), msg);
    int unlit = 0, glowing = 0;
    for (int i = 0; i < s.mesh_count; i++) {
        TEST_ASSERT_EQUAL(s.unlit[i], baked_hidden_unlit[i]);
        unlit += baked_hidden_unlit[i];
        const mote_rgba e = baked_hidden_meshes[i].material.emissive;
        TEST_ASSERT_EQUAL_MEMORY(&s.meshes[i].material.emissive, &e, sizeof e);
        glowing += e.b != 0;
    }
    TEST_ASSERT_EQUAL(1, unlit);
    TEST_ASSERT_EQUAL(1, glowing);
    static uint8_t loaded[W * H * 4], baked[W * H * 4];
    static uint32_t depth[W * H];
    mote_frame_desc frame;
    mote_scene_frame(&s, (float)W / (float)H, &frame);
    for (int lights = 0; lights < 2; lights++) {
        if (!lights)
            frame.light_count = 0;
        for (int b = 0; b < 2; b++) {
            mote_device dev;
            mote_device_desc desc = {.width = W, .height = H, .color = b ? baked : loaded, .depth = depth};
            TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &desc));
            TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
            for (int i = 0; i < s.mesh_count; i++) {
                mote_draw_desc d = {0};
                if (b) {
                    d.cull = baked_hidden_two_sided[i] ? MOTE_CULL_NONE : MOTE_CULL_DEFAULT;
                    d.unlit = baked_hidden_unlit[i];
                } else {
                    mote_scene_draw_desc(&s, i, NULL, &d);
                }
                TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, b ? &baked_hidden_meshes[i] : &s.meshes[i], &d));
            }
            TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
        }
        TEST_ASSERT_EQUAL_MEMORY(loaded, baked, sizeof loaded);
        int sign = 0;
        for (int i = 0; i < W * H; i++)
            sign += baked[4 * i] == 0 && baked[4 * i + 1] == 0 && baked[4 * i + 2] == 128;
        TEST_ASSERT_TRUE(sign > 10);
    }
    mote_scene_free(&s);
}

/* A textured scene baked in each format (assets/cube.babylon, its
 * checker.png): each texture declared as long as it is and aligned (in
 * RGBA8888 it was declared a quarter of its length), holding the loaded
 * texture converted to the format, and drawn to the same bytes as the
 * loaded scene drawn with that converted texture. */
static void check_textured_bake(const mote_mesh *baked, int count, const mote_frame_desc *frame,
                                mote_rgba clear, mote_format format, const void *pixels,
                                size_t pixel_bytes, size_t alignment)
{
    mote_scene cube;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MOTE_BAKE_CUBE, NULL, &cube, msg, sizeof msg),
                              msg);
    TEST_ASSERT_EQUAL(cube.mesh_count, count);
    TEST_ASSERT_EQUAL(1, cube.texture_count);
    const mote_texture *t = &cube.textures[0];
    const int bpp = mote_format_bytes(format);
    TEST_ASSERT_EQUAL((size_t)t->width * (size_t)t->height * (size_t)bpp, pixel_bytes);
    TEST_ASSERT_EQUAL(0, (uintptr_t)pixels % alignment);
    static uint8_t converted[256 * 128 * 4];
    TEST_ASSERT_TRUE(pixel_bytes <= sizeof converted);
    for (int y = 0; y < t->height; y++)
        mote_convert_row((const uint8_t *)t->pixels + (size_t)y * (size_t)t->stride, t->format,
                         converted + (size_t)y * (size_t)t->width * (size_t)bpp, format, t->width);
    TEST_ASSERT_EQUAL_MEMORY(converted, pixels, pixel_bytes);
    mote_texture as_baked = {t->width, t->height, format, t->width * bpp, converted};
    static mote_mesh loaded[8];
    TEST_ASSERT_TRUE(count <= 8);
    for (int i = 0; i < count; i++) {
        loaded[i] = cube.meshes[i];
        if (loaded[i].material.texture)
            loaded[i].material.texture = &as_baked;
        TEST_ASSERT_EQUAL(loaded[i].material.texture != NULL, baked[i].material.texture != NULL);
    }
    static uint8_t a[W * H * 4], b[W * H * 4];
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    mote_frame_desc f;
    mote_scene_frame(&cube, (float)W / (float)H, &f);
    render(loaded, count, &f, cube.clear_color, d, a);
    render(baked, count, frame, clear, d, b);
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
    /* and the texture shows: drawn without it, the image differs */
    for (int i = 0; i < count; i++)
        loaded[i].material.texture = NULL;
    render(loaded, count, &f, cube.clear_color, d, a);
    TEST_ASSERT_TRUE(memcmp(a, b, sizeof a) != 0);
    mote_scene_free(&cube);
}

void a_textured_scene_baked_in_rgb565_should_render_as_loaded(void)
{
    check_textured_bake(cube_rgb565_meshes, CUBE_RGB565_MESH_COUNT, &cube_rgb565_frame,
                        cube_rgb565_clear_color, MOTE_FORMAT_RGB565, cube_rgb565_texture0.pixels,
                        sizeof cube_rgb565_texture0.pixels, 2);
}

void a_textured_scene_baked_in_rgba8888_should_render_as_loaded(void)
{
    check_textured_bake(cube_rgba8888_meshes, CUBE_RGBA8888_MESH_COUNT, &cube_rgba8888_frame,
                        cube_rgba8888_clear_color, MOTE_FORMAT_RGBA8888,
                        cube_rgba8888_texture0.pixels, sizeof cube_rgba8888_texture0.pixels, 4);
}

void a_textured_scene_baked_in_grey8_should_render_as_loaded(void)
{
    check_textured_bake(cube_grey8_meshes, CUBE_GREY8_MESH_COUNT, &cube_grey8_frame,
                        cube_grey8_clear_color, MOTE_FORMAT_GREY8, cube_grey8_texture0.pixels,
                        sizeof cube_grey8_texture0.pixels, 1);
}

/* --compact: the cube's vertices as integers in under half the bytes,
 * drawn within 2 LSB of the loaded cube but for the odd edge pixel. */
void a_compact_bake_should_be_small_and_render_as_loaded(void)
{
    mote_scene cube;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MOTE_BAKE_CUBE, NULL, &cube, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(cube.mesh_count, CUBE_COMPACT_MESH_COUNT);
    const mote_mesh *m = &cube_compact_meshes[0];
    TEST_ASSERT_NOT_NULL(m->compact);
    TEST_ASSERT_NULL(m->vertices);
    TEST_ASSERT_NULL(m->indices);
    size_t compact = sizeof cube_compact_positions0 + sizeof cube_compact_normals0 + sizeof cube_compact_uvs0
                   + sizeof cube_compact_indices0;
    size_t floats = m->vertex_count * sizeof(mote_vertex) + m->index_count * sizeof(uint32_t);
    snprintf(msg, sizeof msg, "compact %zu bytes, floats %zu", compact, floats);
    TEST_ASSERT_TRUE_MESSAGE(2 * compact < floats, msg);
    static uint8_t a[W * H * 4], b[W * H * 4];
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    mote_frame_desc f;
    mote_scene_frame(&cube, (float)W / (float)H, &f);
    const mote_rgba clear = {0, 0, 0, 0};
    render(cube.meshes, cube.mesh_count, &f, clear, d, a);
    render(cube_compact_meshes, CUBE_COMPACT_MESH_COUNT, &cube_compact_frame, clear, d, b);
    long drawn = 0, far = 0, cover = 0;
    for (int p = 0; p < W * H; p++) {
        bool da = a[4 * p + 3] != 0, db = b[4 * p + 3] != 0;
        cover += da != db;
        drawn += da && db;
        for (int c = 0; c < 3 && da && db; c++)
            if (abs(a[4 * p + c] - b[4 * p + c]) > 2) {
                far++;
                break;
            }
    }
    snprintf(msg, sizeof msg, "%ld drawn, %ld more than 2 LSB apart, %ld drawn by one", drawn, far, cover);
    TEST_ASSERT_TRUE_MESSAGE(drawn > 100 && far * 100 <= drawn && cover * 100 <= drawn, msg);
    mote_scene_free(&cube);
}

/* A baked scene's draw options, as the header names them */
typedef struct baked_options {
    const bool *two_sided, *unlit, *no_depth_write, *no_fog, *depth_pre_pass;
    const mote_mode *modes;
    const uint32_t *lights_off;
    const int *draw_order;
    mote_result (*draw)(mote_device *dev);   /* the header's NAME_draw */
} baked_options;
#define BAKED_OPTIONS(name)                                                                     \
    {name##_two_sided, name##_unlit,  name##_no_depth_write, name##_no_fog, name##_depth_pre_pass, \
     name##_modes,     name##_lights_off, name##_draw_order, name##_draw}

/* The baked options hold the loaded scene's, and the header's NAME_draw,
 * which firmware calls, gives the picture of the loaded scene drawn by
 * mote_scene_draw in mote_scene_draw_order's order. */
static void check_baked_draw_options(const char *path, int n,
                                     const mote_frame_desc *frame_as_baked, baked_options o)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(path, NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(s.mesh_count, n);
    mote_frame_desc frame;
    mote_scene_frame(&s, (float)W / (float)H, &frame);
    int order[64];
    TEST_ASSERT_TRUE(n <= 64);
    TEST_ASSERT_EQUAL(n, mote_scene_draw_order(&s, s.meshes, &frame.camera, order));
    for (int i = 0; i < n; i++) {
        TEST_ASSERT_EQUAL(s.two_sided && s.two_sided[i], o.two_sided[i]);
        TEST_ASSERT_EQUAL(s.unlit && s.unlit[i], o.unlit[i]);
        TEST_ASSERT_EQUAL(s.modes ? s.modes[i] : MOTE_MODE_DEFAULT, o.modes[i]);
        TEST_ASSERT_EQUAL(s.no_depth_write && s.no_depth_write[i], o.no_depth_write[i]);
        TEST_ASSERT_EQUAL(s.no_fog && s.no_fog[i], o.no_fog[i]);
        TEST_ASSERT_EQUAL(s.depth_pre_pass && s.depth_pre_pass[i], o.depth_pre_pass[i]);
        TEST_ASSERT_EQUAL_UINT32(s.lights_off ? s.lights_off[i] : 0, o.lights_off[i]);
        TEST_ASSERT_EQUAL(order[i], o.draw_order[i]);
    }
    static uint8_t loaded[W * H * 4], baked[W * H * 4];
    static uint32_t depth[W * H];
    static mote_device dev;
    mote_device_desc desc = {.width = W, .height = H, .color = loaded, .depth = depth,
                             .clear_color = s.clear_color};
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &desc));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    for (int k = 0; k < n; k++)
        TEST_ASSERT_EQUAL(MOTE_OK, mote_scene_draw(&dev, &s, s.meshes, order[k], NULL));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    desc.color = baked;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &desc));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, frame_as_baked));
    TEST_ASSERT_EQUAL(MOTE_OK, o.draw(&dev));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL_MEMORY(loaded, baked, sizeof loaded);
}

/* Blended glass behind a cut-out fence: the order matters */
void a_baked_transparent_scene_should_keep_its_draw_order(void)
{
    const baked_options o = BAKED_OPTIONS(glass);
    check_baked_draw_options(MOTE_BAKE_GLASS, GLASS_MESH_COUNT, &glass_frame, o);
}

/* Fog, and lights that light only some meshes */
void a_baked_foggy_scene_should_keep_its_fog_and_light_lists(void)
{
    const baked_options o = BAKED_OPTIONS(fogged);
    int lit_apart = 0;
    for (int i = 0; i < FOGGED_MESH_COUNT; i++)
        lit_apart += fogged_lights_off[i] != 0;
    TEST_ASSERT_TRUE(lit_apart > 0);
    TEST_ASSERT_TRUE(fogged_frame.fog.mode != MOTE_FOG_NONE);
    check_baked_draw_options(MOTE_BAKE_FOG, FOGGED_MESH_COUNT, &fogged_frame, o);
}

/* Two blended layers of one mesh with a depth pre-pass: the header's
 * draw gives its depth first, so that only the nearer layer blends */
void a_baked_pre_pass_mesh_should_be_drawn_depth_first(void)
{
    const baked_options o = BAKED_OPTIONS(prepass);
    TEST_ASSERT_TRUE(prepass_depth_pre_pass[0]);
    check_baked_draw_options(MOTE_BAKE_PREPASS, PREPASS_MESH_COUNT, &prepass_frame, o);
}

/* ---- the vertex cache's order ------------------------------------------ */

/* A vertex as a triangle draws it: its record and its colour. */
typedef struct vertex_record {
    mote_vertex v;
    mote_rgba c;
} vertex_record;

static vertex_record record(const mote_mesh *m, uint32_t i)
{
    vertex_record r;
    memset(&r, 0, sizeof r);
    r.v = m->vertices[i];
    if (m->colors)
        r.c = m->colors[i];
    return r;
}

static int compare_records(const void *a, const void *b)
{
    return memcmp(a, b, sizeof(vertex_record));
}

static int compare_triangles(const void *a, const void *b)
{
    return memcmp(a, b, 3 * sizeof(vertex_record));
}

/* Mesh m's vertex records, sorted. */
static vertex_record *sorted_vertices(const mote_mesh *m)
{
    vertex_record *out = malloc(m->vertex_count * sizeof *out + 1);
    TEST_ASSERT_NOT_NULL(out);
    for (uint32_t i = 0; i < m->vertex_count; i++)
        out[i] = record(m, i);
    qsort(out, m->vertex_count, sizeof *out, compare_records);
    return out;
}

/* Mesh m's triangles as their vertex records, each turned to start at its
 * least (so its winding is kept), sorted. */
static vertex_record *sorted_triangles(const mote_mesh *m)
{
    const uint32_t n = m->index_count / 3;
    vertex_record *out = malloc(3 * n * sizeof *out + 1);
    TEST_ASSERT_NOT_NULL(out);
    for (uint32_t t = 0; t < n; t++) {
        vertex_record r[3];
        int least = 0;
        for (int k = 0; k < 3; k++) {
            r[k] = record(m, m->indices[3 * t + (uint32_t)k]);
            if (compare_records(&r[k], &r[least]) < 0)
                least = k;
        }
        for (int k = 0; k < 3; k++)
            out[3 * t + (uint32_t)k] = r[(least + k) % 3];
    }
    qsort(out, n, 3 * sizeof *out, compare_triangles);
    return out;
}

/* The vertices a direct-mapped cache of 32 entries (the core's default
 * MOTE_VERTEX_CACHE) transforms drawing mesh m. */
static long cache_transforms(const mote_mesh *m)
{
    uint32_t tag[32];
    long n = 0;
    for (int k = 0; k < 32; k++)
        tag[k] = UINT32_MAX;
    for (uint32_t i = 0; i < m->index_count / 3 * 3; i++) {
        uint32_t *t = &tag[m->indices[i] & 31];
        if (*t != m->indices[i]) {
            *t = m->indices[i];
            n++;
        }
    }
    return n;
}

/* Each mesh of a reordered bake against the loaded one: the same vertex
 * records as a set and the same triangles of them as a multiset, and no
 * more vertices transformed; *before and *after add up the transforms of
 * all the meshes. */
static void check_reordered(const char *path, const mote_mesh *baked, int n, long *before, long *after)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(path, NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(s.mesh_count, n);
    *before = *after = 0;
    for (int i = 0; i < n; i++) {
        const mote_mesh *a = &s.meshes[i], *b = &baked[i];
        TEST_ASSERT_EQUAL_UINT32(a->vertex_count, b->vertex_count);
        TEST_ASSERT_EQUAL_UINT32(a->index_count, b->index_count);
        TEST_ASSERT_EQUAL(a->colors == NULL, b->colors == NULL);
        vertex_record *va = sorted_vertices(a), *vb = sorted_vertices(b);
        TEST_ASSERT_EQUAL_MEMORY(va, vb, a->vertex_count * sizeof *va);
        free(va);
        free(vb);
        vertex_record *ta = sorted_triangles(a), *tb = sorted_triangles(b);
        TEST_ASSERT_EQUAL_MEMORY(ta, tb, a->index_count / 3 * 3 * sizeof *ta);
        free(ta);
        free(tb);
        const long ca = cache_transforms(a), cb = cache_transforms(b);
        snprintf(msg, sizeof msg, "mesh %d: %ld vertices transformed in the file's order, %ld baked", i,
                 ca, cb);
        TEST_ASSERT_TRUE_MESSAGE(cb <= ca, msg);
        *before += ca;
        *after += cb;
    }
    mote_scene_free(&s);
}

void a_reordered_bake_should_keep_every_vertex_and_triangle(void)
{
    long before, after;
    check_reordered(MOTE_BAKE_TORUS, torus_meshes, TORUS_MESH_COUNT, &before, &after);
    check_reordered(MOTE_BAKE_REORDER, reorder_meshes, REORDER_MESH_COUNT, &before, &after);
}

/* The shuffled grids and the torus: a quarter fewer vertices transformed
 * at least (figures in the header's comments) */
void a_reordered_bake_should_transform_fewer_vertices(void)
{
    long before, after;
    check_reordered(MOTE_BAKE_TORUS, torus_meshes, TORUS_MESH_COUNT, &before, &after);
    snprintf(msg, sizeof msg, "torus: %ld vertices transformed in the file's order, %ld baked", before, after);
    TEST_ASSERT_TRUE_MESSAGE(4 * after < 3 * before, msg);
    check_reordered(MOTE_BAKE_REORDER, reorder_meshes, REORDER_MESH_COUNT, &before, &after);
    snprintf(msg, sizeof msg, "grids: %ld vertices transformed in the file's order, %ld baked", before, after);
    TEST_ASSERT_TRUE_MESSAGE(4 * after < 3 * before, msg);
}

/* The grid and its instance share one reordered vertex, colour and index
 * array; the sub-meshes of "split" (two index arrays on one vertex array)
 * have their triangles reordered, each, but share the file's vertices and
 * colours. */
void reordered_instances_and_sub_meshes_should_keep_sharing_their_arrays(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MOTE_BAKE_REORDER, NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(4, s.mesh_count);
    /* the loaded scene: grid, split's two sub-meshes, the instance */
    TEST_ASSERT_EQUAL_PTR(s.meshes[0].vertices, s.meshes[3].vertices);
    TEST_ASSERT_EQUAL_PTR(s.meshes[1].vertices, s.meshes[2].vertices);
    TEST_ASSERT_TRUE(s.meshes[1].indices != s.meshes[2].indices);
    const mote_mesh *m = reorder_meshes;
    TEST_ASSERT_EQUAL_PTR(m[0].vertices, m[3].vertices);
    TEST_ASSERT_EQUAL_PTR(m[0].indices, m[3].indices);
    TEST_ASSERT_EQUAL_PTR(m[0].colors, m[3].colors);
    TEST_ASSERT_TRUE(memcmp(s.meshes[0].vertices, m[0].vertices, m[0].vertex_count * sizeof *m[0].vertices));
    TEST_ASSERT_EQUAL_PTR(m[1].vertices, m[2].vertices);
    TEST_ASSERT_EQUAL_PTR(m[1].colors, m[2].colors);
    TEST_ASSERT_EQUAL_MEMORY(s.meshes[1].vertices, m[1].vertices, m[1].vertex_count * sizeof *m[1].vertices);
    TEST_ASSERT_EQUAL_MEMORY(s.meshes[1].colors, m[1].colors, m[1].vertex_count * sizeof *m[1].colors);
    for (int i = 1; i < 3; i++)
        TEST_ASSERT_TRUE(memcmp(s.meshes[i].indices, m[i].indices, m[i].index_count * sizeof *m[i].indices));
    mote_scene_free(&s);
}

/* Reordered triangles cover the same pixels with the same colours: these
 * scenes have no two triangles at one depth on a pixel. */
void a_reordered_bake_should_render_as_loaded(void)
{
    const char *paths[2] = {MOTE_BAKE_TORUS, MOTE_BAKE_REORDER};
    const mote_mesh *meshes[2] = {torus_meshes, reorder_meshes};
    const int counts[2] = {TORUS_MESH_COUNT, REORDER_MESH_COUNT};
    const mote_frame_desc *frames[2] = {&torus_frame, &reorder_frame};
    const mote_rgba clears[2] = {torus_clear_color, reorder_clear_color};
    for (int k = 0; k < 2; k++) {
        mote_scene s;
        TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(paths[k], NULL, &s, msg, sizeof msg), msg);
        mote_draw_desc d;
        memset(&d, 0, sizeof d);
        d.cull = MOTE_CULL_NONE;
        const int drawn = render_as_loaded(&s, meshes[k], counts[k], frames[k], clears[k], d);
        mote_scene_free(&s);
        TEST_ASSERT_TRUE(drawn > 300);
    }
}

/* --compact follows the same order: its integers are the reordered float
 * bake's vertices, within their quantisation step, and its 16-bit indices
 * the same. */
void a_reordered_compact_bake_should_follow_the_vertex_order(void)
{
    TEST_ASSERT_EQUAL(REORDER_MESH_COUNT, REORDER_COMPACT_MESH_COUNT);
    for (int i = 0; i < REORDER_MESH_COUNT; i++) {
        const mote_mesh *f = &reorder_meshes[i], *c = &reorder_compact_meshes[i];
        const mote_compact *q = c->compact;
        TEST_ASSERT_NOT_NULL(q);
        TEST_ASSERT_EQUAL_UINT32(f->vertex_count, c->vertex_count);
        TEST_ASSERT_EQUAL_UINT32(f->index_count, c->index_count);
        for (uint32_t k = 0; k < f->index_count; k++)
            TEST_ASSERT_EQUAL_UINT32(f->indices[k], q->indices[k]);
        for (uint32_t v = 0; v < f->vertex_count; v++)
            for (int a = 0; a < 3; a++) {
                const float back = (float)q->positions[3 * v + (uint32_t)a] * q->scale[a] + q->offset[a];
                TEST_ASSERT_FLOAT_WITHIN(q->scale[a] + 1e-6f, f->vertices[v].position[a], back);
            }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(baked_meshes_should_hold_the_loaded_arrays_and_vertex_colours);
    RUN_TEST(a_baked_scene_should_render_the_same_bytes_as_the_loaded_one);
    RUN_TEST(baked_meshes_should_keep_which_are_two_sided);
    RUN_TEST(baked_points_and_lines_should_keep_their_modes);
    RUN_TEST(a_baked_orthographic_camera_should_render_as_loaded);
    RUN_TEST(baked_meshes_should_keep_which_are_hidden);
    RUN_TEST(baked_meshes_should_keep_which_are_unlit_and_their_emissive_colours);
    RUN_TEST(a_textured_scene_baked_in_rgb565_should_render_as_loaded);
    RUN_TEST(a_textured_scene_baked_in_rgba8888_should_render_as_loaded);
    RUN_TEST(a_textured_scene_baked_in_grey8_should_render_as_loaded);
    RUN_TEST(a_compact_bake_should_be_small_and_render_as_loaded);
    RUN_TEST(a_baked_transparent_scene_should_keep_its_draw_order);
    RUN_TEST(a_baked_foggy_scene_should_keep_its_fog_and_light_lists);
    RUN_TEST(a_baked_pre_pass_mesh_should_be_drawn_depth_first);
    RUN_TEST(a_reordered_bake_should_keep_every_vertex_and_triangle);
    RUN_TEST(a_reordered_bake_should_transform_fewer_vertices);
    RUN_TEST(reordered_instances_and_sub_meshes_should_keep_sharing_their_arrays);
    RUN_TEST(a_reordered_bake_should_render_as_loaded);
    RUN_TEST(a_reordered_compact_bake_should_follow_the_vertex_order);
    return UNITY_END();
}
