/*
 * test_options.c - the core built with MOTE_ENABLE_* options turned off
 * (tests/options/options.mk builds this file against the core sources
 * compiled with some options at 0): asking for a feature left out gets
 * what docs/embedded.md's table says, MOTE_ERR_UNSUPPORTED with nothing
 * drawn, or the draw without the feature counted in
 * mote_stats.draws_simplified, or the draw without it uncounted;
 * everything else still draws, and the image of a draw that uses no
 * left-out feature is the same whatever is left out (tests/options/run.sh
 * compares its hash with the one this file prints when built with every
 * feature).
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

/* ---- features drawn without, counted or not ------------------------ */

/* What a frame drew: its image's hash and the draws counted as simplified. */
typedef struct drawn {
    uint32_t hash;
    uint32_t simplified;
} drawn;

static drawn draw_frame(const mote_frame_desc *frame, const mote_draw_desc *desc)
{
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, frame));
    for (int i = 0; i < scene.mesh_count; i++)
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &scene.meshes[i], desc));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_TRUE(mote_device_stats(&dev)->pixels_written > 0);
    drawn d = {frame_hash(), mote_device_stats(&dev)->draws_simplified};
    return d;
}

/* A frame that asks for a feature against the same frame without it:
 * with the feature built, it shows and nothing is counted; without it,
 * the same image, each draw counted when counted says so. */
static void check_drawn_without(bool enabled, bool counted, drawn asked, drawn plain)
{
    TEST_ASSERT_EQUAL_UINT32(0, plain.simplified);
    if (enabled) {
        TEST_ASSERT_TRUE(asked.hash != plain.hash);
        TEST_ASSERT_EQUAL_UINT32(0, asked.simplified);
    } else {
        TEST_ASSERT_EQUAL_HEX32(plain.hash, asked.hash);
        TEST_ASSERT_EQUAL_UINT32(counted ? (uint32_t)scene.mesh_count : 0, asked.simplified);
    }
}

static void set_alpha(mote_alpha_mode mode, bool alpha_set, float alpha)
{
    for (int i = 0; i < scene.mesh_count; i++) {
        scene.meshes[i].material.alpha_mode = mode;
        scene.meshes[i].material.alpha_set = alpha_set;
        scene.meshes[i].material.alpha = alpha;
    }
}

/* The scene's texture with holes in its alpha, for the alpha test. */
static uint8_t holed_px[64 * 64 * 4];
static mote_texture holed;

static void use_holed_texture(void)
{
    holed = *tu_scene_texture();
    memcpy(holed_px, holed.pixels, sizeof holed_px);
    for (size_t i = 0; i < sizeof holed_px; i += 4)
        holed_px[i + 3] = (uint8_t)((i / 4 % 64 / 8 + i / 4 / 64 / 8) % 2 ? 255 : 0);
    holed.pixels = holed_px;
    for (int i = 0; i < scene.mesh_count; i++)
        scene.meshes[i].material.texture = &holed;
}

void the_alpha_test_should_be_drawn_opaque_and_counted_without_its_option(void)
{
    use_holed_texture();
    drawn plain = draw_frame(&scene.frame, NULL);
    set_alpha(MOTE_ALPHA_TEST, false, 0.0f);
    check_drawn_without(MOTE_ENABLE_ALPHA_TEST, true, draw_frame(&scene.frame, NULL), plain);
}

void blending_should_be_drawn_opaque_and_counted_without_its_option(void)
{
    drawn plain = draw_frame(&scene.frame, NULL);
    set_alpha(MOTE_ALPHA_BLEND, true, 0.5f);
    check_drawn_without(MOTE_ENABLE_BLEND, true, draw_frame(&scene.frame, NULL), plain);
}

/* A depth pre-pass is two draws: depths only, then colour where equal. */
void a_depth_pre_pass_should_need_blending(void)
{
    mote_draw_desc pre, eq;
    memset(&pre, 0, sizeof pre);
    pre.no_color_write = true;
    memset(&eq, 0, sizeof eq);
    eq.depth_less_equal = true;
    const mote_result want = MOTE_ENABLE_BLEND ? MOTE_OK : MOTE_ERR_UNSUPPORTED;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &scene.frame));
    for (int i = 0; i < scene.mesh_count; i++) {
        TEST_ASSERT_EQUAL(want, mote_draw(&dev, &scene.meshes[i], &pre));
        TEST_ASSERT_EQUAL(want, mote_draw(&dev, &scene.meshes[i], &eq));
    }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    const mote_stats *st = mote_device_stats(&dev);
    if (MOTE_ENABLE_BLEND) {
        TEST_ASSERT_TRUE(st->pixels_written > 0);
    } else {
        TEST_ASSERT_EQUAL_UINT32(0, st->triangles_in);
        TEST_ASSERT_EQUAL_UINT64(0, st->pixels_written);
    }
}

void highlights_should_be_left_out_and_counted_without_their_option(void)
{
    drawn plain = draw_frame(&scene.frame, NULL);
    for (int i = 0; i < scene.mesh_count; i++)
        scene.meshes[i].material.specular = (mote_rgba){255, 255, 255, 255};
    check_drawn_without(MOTE_ENABLE_SPECULAR, true, draw_frame(&scene.frame, NULL), plain);
}

void fog_should_be_left_out_and_counted_without_its_option(void)
{
    drawn plain = draw_frame(&scene.frame, NULL);
    mote_frame_desc f = scene.frame;
    f.fog.mode = MOTE_FOG_LINEAR;
    f.fog.color[0] = f.fog.color[1] = f.fog.color[2] = 0.6f;
    f.fog.start = 2.0f;
    f.fog.end = 12.0f;
    check_drawn_without(MOTE_ENABLE_FOG, true, draw_frame(&f, NULL), plain);
}

void mipmaps_should_fall_back_to_level_0_and_count_without_their_option(void)
{
    static uint32_t mip_mem[64 * 64];   /* aligned to the texel */
    static mote_mipmaps mips;
    const mote_texture *t = tu_scene_texture();
    TEST_ASSERT_TRUE(mote_mipmaps_bytes(t) <= sizeof mip_mem);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_mipmaps_build(t, mip_mem, sizeof mip_mem, &mips));
    for (int i = 0; i < scene.mesh_count; i++)
        scene.meshes[i].material.mipmaps = &mips;
    drawn plain = draw_frame(&scene.frame, NULL);
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.mip = MOTE_MIP_PIXEL;
    check_drawn_without(MOTE_ENABLE_MIPMAPS, true, draw_frame(&scene.frame, &d), plain);
}

void an_emissive_colour_should_be_ignored_uncounted_without_its_option(void)
{
    drawn plain = draw_frame(&scene.frame, NULL);
    for (int i = 0; i < scene.mesh_count; i++)
        scene.meshes[i].material.emissive = (mote_rgba){90, 40, 10, 255};
    check_drawn_without(MOTE_ENABLE_EMISSIVE, false, draw_frame(&scene.frame, NULL), plain);
}

/* Texture layers: one of each role on every mesh, with highlights for the
 * specular one and blending (at alpha 1) for the opacity one to weigh. */
static const int roles[3] = {MOTE_LAYER_EMISSIVE, MOTE_LAYER_OPACITY, MOTE_LAYER_SPECULAR};
static const bool role_built[3] = {MOTE_ENABLE_EMISSIVE_MAP, MOTE_ENABLE_OPACITY_MAP,
                                   MOTE_ENABLE_SPECULAR_MAP && MOTE_ENABLE_SPECULAR};
/* whether the role's layer changes the image when drawn */
static const bool role_shows[3] = {true, MOTE_ENABLE_BLEND, true};
static mote_layer layers[3];

/* Every mesh gets the layers whose bit is set in mask. */
static void set_layers(unsigned mask)
{
    int n = 0;
    for (int r = 0; r < 3; r++) {
        if (!(mask >> r & 1))
            continue;
        memset(&layers[n], 0, sizeof layers[n]);
        layers[n].role = (mote_layer_role)roles[r];
        layers[n].texture = tu_scene_texture();
        layers[n].u_scale = 2.0f;
        layers[n].v_scale = 3.0f;
        layers[n].from_rgb = true;
        n++;
    }
    for (int i = 0; i < scene.mesh_count; i++) {
        scene.meshes[i].material.layers = layers;
        scene.meshes[i].material.layer_count = n;
        scene.meshes[i].material.specular = (mote_rgba){255, 255, 255, 255};
        scene.meshes[i].material.alpha_mode = MOTE_ALPHA_BLEND;
    }
}

void an_emissive_layer_alone_should_be_skipped_and_counted_without_its_option(void)
{
    /* nothing else asked for: in the build without any layer switch too,
     * the count is the layer's */
    drawn plain = draw_frame(&scene.frame, NULL);
    set_layers(1u);
    for (int i = 0; i < scene.mesh_count; i++) {
        scene.meshes[i].material.specular = (mote_rgba){0, 0, 0, 0};
        scene.meshes[i].material.alpha_mode = MOTE_ALPHA_DEFAULT;
    }
    check_drawn_without(MOTE_ENABLE_EMISSIVE_MAP, true, draw_frame(&scene.frame, NULL), plain);
}

void a_layer_should_be_skipped_and_counted_without_its_option(void)
{
    /* the rest of the material (highlights, blending) counts where left out */
    const uint32_t others = !MOTE_ENABLE_SPECULAR || !MOTE_ENABLE_BLEND ? (uint32_t)scene.mesh_count : 0;
    for (int r = 0; r < 3; r++) {
        set_layers(7u & ~(1u << r));
        drawn rest = draw_frame(&scene.frame, NULL);
        set_layers(7u);
        drawn all = draw_frame(&scene.frame, NULL);
        bool rest_whole = true;   /* every layer of the rest drawn */
        for (int k = 0; k < 3; k++)
            rest_whole = rest_whole && (k == r || role_built[k]);
        TEST_ASSERT_EQUAL_UINT32(rest_whole ? others : (uint32_t)scene.mesh_count, rest.simplified);
        if (role_built[r]) {
            TEST_ASSERT_EQUAL_UINT32(rest.simplified, all.simplified);
            if (role_shows[r]) {
                TEST_ASSERT_TRUE(all.hash != rest.hash);
            }
        } else {
            TEST_ASSERT_EQUAL_HEX32(rest.hash, all.hash);
            TEST_ASSERT_EQUAL_UINT32((uint32_t)scene.mesh_count, all.simplified);
        }
    }
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
    RUN_TEST(the_alpha_test_should_be_drawn_opaque_and_counted_without_its_option);
    RUN_TEST(blending_should_be_drawn_opaque_and_counted_without_its_option);
    RUN_TEST(a_depth_pre_pass_should_need_blending);
    RUN_TEST(highlights_should_be_left_out_and_counted_without_their_option);
    RUN_TEST(fog_should_be_left_out_and_counted_without_its_option);
    RUN_TEST(mipmaps_should_fall_back_to_level_0_and_count_without_their_option);
    RUN_TEST(an_emissive_colour_should_be_ignored_uncounted_without_its_option);
    RUN_TEST(an_emissive_layer_alone_should_be_skipped_and_counted_without_its_option);
    RUN_TEST(a_layer_should_be_skipped_and_counted_without_its_option);
    return UNITY_END();
}
