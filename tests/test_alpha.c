/*
 * test_alpha.c - transparency: alpha test and blending (mote_material's
 * alpha_mode).
 *
 * What is asserted:
 *   - The arithmetic: a blended pixel is round((src a + dst (255 - a)) /
 *     255) per 8-bit channel, a = the material's alpha x the texel's; the
 *     rounding division is exact over its whole range.
 *   - Alpha test: a texel whose alpha is below the cut-off draws neither
 *     colour nor depth, so what lies behind shows through and can still be
 *     drawn later.
 *   - Against the double-precision reference (tests/ref): a backdrop, an
 *     alpha-tested quad and two blended quads, nearest and bilinear: at
 *     least 99.9% of the pixels within 1 LSB, as every other mode.
 *   - The same bytes whatever the path: direct, binned on 1..4 threads,
 *     and band mode, in every colour format (blending reads back the
 *     target, so tiles and bands must keep submission order).
 *   - An opaque material draws the same bytes as before the feature
 *     existed (the specialised loops still draw it).
 */
#include <mote/mote.h>
#include <mote/mote_io.h>
#include "core/format.h"
#include "ref/ref.h"
#include "unity.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 96
#define H 72

void setUp(void) {}
void tearDown(void) {}

static char msg[256];

/* ---- the scene ------------------------------------------------------------ */

static mote_vertex quad_v[4][4];
static const uint32_t quad_i[6] = {0, 2, 1, 0, 3, 2};   /* counter-clockwise on screen: front */
static uint8_t tex_px[16 * 16 * 4];
static mote_texture tex = {16, 16, MOTE_FORMAT_RGBA8888, 0, tex_px};

/* A quad facing the camera (at -z) between x0..x1, y0..y1, depth z. */
static mote_mesh quad(int slot, float x0, float y0, float x1, float y1, float z, float tilt)
{
    const float p[4][3] = {{x0, y1, z - tilt}, {x1, y1, z + tilt}, {x1, y0, z + tilt}, {x0, y0, z - tilt}};
    const float uv[4][2] = {{0, 0}, {1.5f, 0}, {1.5f, 1.5f}, {0, 1.5f}};
    for (int i = 0; i < 4; i++) {
        mote_vertex *v = &quad_v[slot][i];
        memset(v, 0, sizeof *v);
        memcpy(v->position, p[i], sizeof p[i]);
        v->normal[2] = -1.0f;
        memcpy(v->uv, uv[i], sizeof uv[i]);
    }
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = quad_v[slot];
    m.vertex_count = 4;
    m.indices = quad_i;
    m.index_count = 6;
    return m;
}

static void build_texture(void)
{
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            uint8_t *p = &tex_px[(y * 16 + x) * 4];
            p[0] = (uint8_t)(x * 16 + 8);
            p[1] = (uint8_t)(y * 16 + 8);
            p[2] = (uint8_t)(((x ^ y) & 1) ? 220 : 60);
            /* a smooth alpha ramp with a hole: cut-offs fall inside texels */
            int a = (x + y) * 8 + 10;
            if ((x - 8) * (x - 8) + (y - 8) * (y - 8) < 10)
                a = 0;
            p[3] = (uint8_t)(a > 255 ? 255 : a);
        }
}

/* highlights and fog on the scene (the same-bytes test) */
static bool with_look;
/* texture layers on the scene (mote_layer): emissive, opacity, specular */
static bool with_layers;
static uint8_t tex2_px[8 * 8 * 4];
static mote_texture tex2 = {8, 8, MOTE_FORMAT_RGBA8888, 0, tex2_px};
static mote_layer layers[4][MOTE_MAX_LAYERS];

static void build_layer_texture(void)
{
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            uint8_t *p = &tex2_px[(y * 8 + x) * 4];
            p[0] = (uint8_t)(((x + y) & 1) ? 250 : 30);
            p[1] = (uint8_t)(x * 32 + 10);
            p[2] = (uint8_t)(255 - y * 30);
            p[3] = (uint8_t)(y * 36);
        }
}

static mote_layer layer_of(mote_layer_role role, float scale, float offset, mote_wrap wrap)
{
    mote_layer l;
    memset(&l, 0, sizeof l);
    l.role = role;
    l.texture = &tex2;
    l.u_scale = scale;
    l.v_scale = scale * 0.5f;
    l.u_offset = offset;
    l.v_offset = -offset;
    l.wrap_u = l.wrap_v = wrap;
    return l;
}

/* Layers on the four meshes: an emissive map on the untextured backdrop
 * (its coordinates lent by the layer), an opacity map from luminance on
 * the cut-out, emissive and specular maps on the textured blended quad,
 * an opacity map from alpha, clamped, on the untextured blended one. */
static void add_layers(mote_mesh m[4])
{
    build_layer_texture();
    layers[0][0] = layer_of(MOTE_LAYER_EMISSIVE, 2.0f, 0.25f, MOTE_WRAP_REPEAT);
    layers[0][0].factor[0] = 0.6f;
    layers[0][0].factor[1] = 0.3f;
    layers[0][0].factor[2] = 0.1f;
    layers[1][0] = layer_of(MOTE_LAYER_OPACITY, 1.0f, 0.0f, MOTE_WRAP_MIRROR);
    layers[1][0].from_rgb = true;
    layers[2][0] = layer_of(MOTE_LAYER_EMISSIVE, 3.0f, 0.1f, MOTE_WRAP_REPEAT);
    layers[2][0].factor[0] = layers[2][0].factor[1] = layers[2][0].factor[2] = 0.4f;
    layers[2][1] = layer_of(MOTE_LAYER_SPECULAR, 1.0f, 0.5f, MOTE_WRAP_REPEAT);
    layers[3][0] = layer_of(MOTE_LAYER_OPACITY, 0.7f, 0.05f, MOTE_WRAP_CLAMP);
    layers[3][0].factor[0] = 1.5f;
    const int count[4] = {1, 1, 2, 1};
    for (int i = 0; i < 4; i++) {
        m[i].material.layers = layers[i];
        m[i].material.layer_count = count[i];
    }
    m[2].material.specular = (mote_rgba){255, 255, 255, 255};
    m[2].material.v_origin_bottom = true;
}

static mote_frame_desc frame_of(void)
{
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    f.camera.position[0] = 0.3f;
    f.camera.position[1] = 0.4f;
    f.camera.position[2] = -4.0f;
    f.camera.fov = 0.9f;
    f.camera.znear = 0.5f;
    f.camera.zfar = 20.0f;
    f.lights[0].type = MOTE_LIGHT_POINT;
    f.lights[0].position[0] = 1.0f;
    f.lights[0].position[1] = 2.0f;
    f.lights[0].position[2] = -5.0f;
    f.light_count = 1;
    f.ambient[0] = f.ambient[1] = f.ambient[2] = 0.1f;
    if (with_look)
        f.fog = (mote_fog){MOTE_FOG_EXP, {0.5f, 0.5f, 0.6f}, 0.15f, 0, 0};
    return f;
}

#define MESHES 4
/* backdrop (opaque, textured), a cut-out, two blended quads (one with the
 * texture's alpha, one with the material's alone) */
static void build_meshes(mote_mesh m[MESHES])
{
    build_texture();
    m[0] = quad(0, -6, -5, 6, 5, 3.0f, 0.0f);
    m[0].material.color = (mote_rgba){180, 200, 220, 255};
    m[0].material.color_set = true;
    m[1] = quad(1, -1.8f, -1.2f, 0.6f, 1.4f, 1.0f, 0.4f);
    m[1].material.texture = &tex;
    m[1].material.alpha_mode = MOTE_ALPHA_TEST;
    m[1].material.use_texture_alpha = true;
    m[2] = quad(2, -0.8f, -1.5f, 1.7f, 0.8f, 0.2f, -0.3f);
    m[2].material.texture = &tex;
    m[2].material.alpha_mode = MOTE_ALPHA_BLEND;
    m[2].material.use_texture_alpha = true;
    m[2].material.alpha = 0.8f;
    m[2].material.alpha_set = true;
    m[3] = quad(3, -1.5f, -0.4f, 1.0f, 1.6f, -0.5f, 0.2f);
    m[3].material.color = (mote_rgba){255, 60, 30, 255};
    m[3].material.color_set = true;
    m[3].material.alpha_mode = MOTE_ALPHA_BLEND;
    m[3].material.alpha = 0.35f;
    m[3].material.alpha_set = true;
    for (int i = 0; i < MESHES && with_look; i++)
        m[i].material.specular = (mote_rgba){255, 240, 200, 255};
    if (with_layers)
        add_layers(m);
}

/* ---- rendering through each path ----------------------------------------- */

typedef struct band_sink {
    uint8_t *frame;
    int stride;
} band_sink;

static void band_flush(void *user, int y0, int rows, const void *color, int stride)
{
    band_sink *s = (band_sink *)user;
    for (int y = 0; y < rows; y++)
        memcpy(s->frame + (size_t)(y0 + y) * (size_t)s->stride, (const uint8_t *)color + (size_t)y * (size_t)stride,
               (size_t)s->stride);
}

enum { PATH_DIRECT, PATH_BINNED, PATH_BANDS };

/* One mote_draw: a mesh and its options. */
typedef struct draw_call {
    const mote_mesh *mesh;
    const mote_draw_desc *desc;
} draw_call;

/* Renders the draws in format fmt into out (W x H pixels of the format)
 * by path, with threads for the binned one; returns the stats. */
static mote_stats render_calls(mote_format fmt, int path, int threads, const draw_call *calls, int n, uint8_t *out)
{
    const int bpp = mote_format_bytes(fmt);
    static uint8_t band_color[W * 8 * 4];
    static uint32_t depth[W * H];
    static uint8_t arena[1 << 20];
    band_sink sink = {out, W * bpp};
    mote_device dev;
    mote_device_desc desc;
    memset(&desc, 0, sizeof desc);
    desc.width = W;
    desc.height = H;
    desc.color_format = fmt;
    desc.color = out;
    desc.depth = depth;
    desc.clear_color = (mote_rgba){20, 30, 40, 255};
    if (path == PATH_BINNED) {
        desc.arena = arena;
        desc.arena_size = sizeof arena;
        desc.tile_size = 16;
        if (threads > 1) {
            desc.parallel_for = mote_parallel_openmp;
            desc.parallel_user = &threads;
        }
    } else if (path == PATH_BANDS) {
        desc.band_height = 8;
        desc.color = band_color;
        desc.flush = band_flush;
        desc.flush_user = &sink;
    }
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_device_init(&dev, &desc));
    mote_frame_desc f = frame_of();
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&dev, &f));
    for (int i = 0; i < n; i++)
        TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&dev, calls[i].mesh, calls[i].desc));
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&dev));
    return *mote_device_stats(&dev);
}

/* The meshes, each with d. */
static mote_stats render(mote_format fmt, int path, int threads, const mote_mesh *m, int n,
                         const mote_draw_desc *d, uint8_t *out)
{
    draw_call calls[MESHES];
    TEST_ASSERT_TRUE(n <= MESHES);
    for (int i = 0; i < n; i++)
        calls[i] = (draw_call){&m[i], d};
    return render_calls(fmt, path, threads, calls, n, out);
}

/* ---- tests ------------------------------------------------------------------ */

void rounding_division_by_255_should_be_exact_over_its_range(void)
{
    for (uint32_t x = 0; x <= 255u * 255u; x++)
        if (mote__div255(x) != (2 * x + 255) / 510)
            TEST_FAIL_MESSAGE("mote__div255 is not round(x / 255)");
}

void blending_should_mix_source_and_target_as_documented(void)
{
    mote_mesh m[2];
    m[0] = quad(0, -6, -5, 6, 5, 3.0f, 0.0f);
    m[0].material.color = (mote_rgba){200, 100, 50, 255};
    m[0].material.color_set = true;
    m[1] = quad(1, -6, -5, 6, 5, 1.0f, 0.0f);
    m[1].material.color = (mote_rgba){0, 0, 255, 255};
    m[1].material.color_set = true;
    m[1].material.alpha_mode = MOTE_ALPHA_BLEND;
    m[1].material.alpha = 0.5f;   /* 128 of 255 */
    m[1].material.alpha_set = true;
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.unlit = true;
    static uint8_t img[W * H * 4];
    render(MOTE_FORMAT_RGBA8888, PATH_DIRECT, 1, m, 2, &d, img);
    const uint8_t *p = &img[(H / 2 * W + W / 2) * 4];
    TEST_ASSERT_EQUAL_UINT8((200 * 127 + 127) / 255, p[0]);
    TEST_ASSERT_EQUAL_UINT8((100 * 127 + 127) / 255, p[1]);
    TEST_ASSERT_EQUAL_UINT8((255 * 128 + 50 * 127 + 127) / 255, p[2]);
    TEST_ASSERT_EQUAL_UINT8(255, p[3]);
}

void alpha_test_should_leave_cut_texels_undrawn_in_colour_and_depth(void)
{
    build_texture();
    mote_mesh m[2];
    /* the cut-out in front, drawn first: the backdrop behind it must
     * still show through its holes, as the depth buffer was not written */
    m[0] = quad(0, -6, -5, 6, 5, 1.0f, 0.0f);
    m[0].material.texture = &tex;
    m[0].material.alpha_mode = MOTE_ALPHA_TEST;
    m[0].material.use_texture_alpha = true;
    m[0].material.alpha_cutoff = 0.5f;
    m[1] = quad(1, -6, -5, 6, 5, 3.0f, 0.0f);
    m[1].material.color = (mote_rgba){0, 255, 0, 255};
    m[1].material.color_set = true;
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.unlit = true;
    static uint8_t img[W * H * 4];
    mote_stats st = render(MOTE_FORMAT_RGBA8888, PATH_DIRECT, 1, m, 2, &d, img);
    long green = 0, textured = 0;
    for (int i = 0; i < W * H; i++) {
        const uint8_t *p = &img[4 * i];
        if (p[0] == 0 && p[1] == 255 && p[2] == 0)
            green++;
        else
            textured++;
    }
    snprintf(msg, sizeof msg, "%ld backdrop pixels, %ld texture pixels", green, textured);
    TEST_ASSERT_TRUE_MESSAGE(green > W * H / 5 && textured > W * H / 5, msg);
    TEST_ASSERT_EQUAL_UINT32(0, st.draws_simplified);
}

/* mote against the reference over the whole image (the backdrop covers
 * it). draw_by_draw: each draw against the reference drawing it over
 * mote's own picture of the draws before it, its own error, where the
 * whole picture's adds up the errors of what it blends over (each within
 * 1 LSB, then rounded to 8 bits again, as in any 8-bit colour buffer;
 * docs/accuracy.md). */
static void compare_with_reference(mote_filter filter, const char *what, double within, bool draw_by_draw)
{
    mote_mesh m[MESHES];
    build_meshes(m);
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.filter = filter;
    d.cull = MOTE_CULL_NONE;
    static uint8_t before[W * H * 4], img[W * H * 4];
    ref_target t;
    TEST_ASSERT_TRUE(ref_target_init(&t, W, H, 8));
    mote_frame_desc f = frame_of();
    ref_begin(&t, &f, (mote_rgba){20, 30, 40, 255});
    for (int i = 0; i < MESHES; i++) {
        if (draw_by_draw && i > 0) {
            render(MOTE_FORMAT_RGBA8888, PATH_DIRECT, 1, m, i, &d, before);
            memcpy(t.rgba, before, sizeof before);   /* the reference's depth stays its own */
        }
        TEST_ASSERT_TRUE(ref_draw(&t, &m[i], &d));
        if (!draw_by_draw && i < MESHES - 1)
            continue;
        render(MOTE_FORMAT_RGBA8888, PATH_DIRECT, 1, m, i + 1, &d, img);
        ref_metrics r = ref_compare(img, NULL, t.rgba, NULL, W, H);
        printf("%-22s %s %d  max %3d  mean %.4f  PSNR %6.2f  >1 LSB %4ld  within 1 LSB %.3f%%\n", what,
               draw_by_draw ? "draw" : "draws", draw_by_draw ? i : MESHES, r.max_err, r.mean_err, r.psnr,
               r.off_by_more_than_1, 100.0 * r.within_1_fraction);
        snprintf(msg, sizeof msg, "%s, draw %d: %.3f%% within 1 LSB", what, i, 100.0 * r.within_1_fraction);
        TEST_ASSERT_TRUE_MESSAGE(r.within_1_fraction >= within, msg);
    }
    ref_target_free(&t);
}

void alpha_test_and_blending_should_be_within_1_lsb_of_the_reference(void)
{
    compare_with_reference(MOTE_FILTER_NEAREST, "alpha, nearest", 0.999, false);
    compare_with_reference(MOTE_FILTER_BILINEAR, "alpha, bilinear", 0.999, false);
}

void blending_should_give_the_same_bytes_on_every_path_and_format(void)
{
    static const mote_format formats[] = {MOTE_FORMAT_RGBA8888, MOTE_FORMAT_RGB565, MOTE_FORMAT_RGB565_SWAPPED,
                                          MOTE_FORMAT_GREY8};
    mote_mesh m[MESHES];
    build_meshes(m);
    static uint8_t want[W * H * 4], got[W * H * 4];
    for (int fi = 0; fi < 4; fi++)
        for (int filter = MOTE_FILTER_NEAREST; filter <= MOTE_FILTER_BILINEAR; filter++) {
            mote_draw_desc d;
            memset(&d, 0, sizeof d);
            d.filter = (mote_filter)filter;
            const size_t bytes = (size_t)W * H * (size_t)mote_format_bytes(formats[fi]);
            render(formats[fi], PATH_DIRECT, 1, m, MESHES, &d, want);
            const int paths[4][2] = {{PATH_BINNED, 1}, {PATH_BINNED, 2}, {PATH_BINNED, 4}, {PATH_BANDS, 1}};
            for (int p = 0; p < 4; p++) {
                memset(got, 0, sizeof got);
                render(formats[fi], paths[p][0], paths[p][1], m, MESHES, &d, got);
                snprintf(msg, sizeof msg, "format %d, filter %d, path %d x%d", (int)formats[fi], filter,
                         paths[p][0], paths[p][1]);
                TEST_ASSERT_EQUAL_MEMORY_MESSAGE(want, got, bytes, msg);
            }
        }
}

void highlights_and_fog_should_give_the_same_bytes_on_every_path_and_format(void)
{
    with_look = true;
    blending_should_give_the_same_bytes_on_every_path_and_format();
    with_look = false;
}

void an_opaque_material_should_draw_as_without_alpha(void)
{
    mote_mesh m[MESHES];
    build_meshes(m);
    static uint8_t plain[W * H * 4], marked[W * H * 4];
    for (int i = 1; i < MESHES; i++)
        m[i].material.alpha_mode = MOTE_ALPHA_OPAQUE;   /* alpha and texture alpha set, ignored */
    render(MOTE_FORMAT_RGBA8888, PATH_DIRECT, 1, m, MESHES, NULL, marked);
    for (int i = 1; i < MESHES; i++) {
        m[i].material.alpha_mode = MOTE_ALPHA_DEFAULT;
        m[i].material.alpha_set = false;
        m[i].material.use_texture_alpha = false;
    }
    render(MOTE_FORMAT_RGBA8888, PATH_DIRECT, 1, m, MESHES, NULL, plain);
    TEST_ASSERT_EQUAL_MEMORY(plain, marked, sizeof plain);
}

void texture_layers_should_be_within_1_lsb_of_the_reference(void)
{
    with_layers = true;
    compare_with_reference(MOTE_FILTER_NEAREST, "layers, nearest", 0.999, false);
    compare_with_reference(MOTE_FILTER_BILINEAR, "layers, bilinear", 0.999, true);
    /* three blended layers deep: the errors of what lies behind add up */
    compare_with_reference(MOTE_FILTER_BILINEAR, "layers, bilinear", 0.995, false);
    with_layers = false;
}

void texture_layers_should_give_the_same_bytes_on_every_path_and_format(void)
{
    with_layers = true;
    blending_should_give_the_same_bytes_on_every_path_and_format();
    with_look = true;             /* fog: the specular map is skipped, and counted */
    mote_mesh m[MESHES];
    build_meshes(m);
    static uint8_t img[W * H * 4];
    mote_stats st = render(MOTE_FORMAT_RGBA8888, PATH_DIRECT, 1, m, MESHES, NULL, img);
    TEST_ASSERT_EQUAL_UINT32(MOTE_ENABLE_SPECULAR_MAP && MOTE_ENABLE_SPECULAR && MOTE_ENABLE_FOG ? 1 : 0,
                             st.draws_simplified);
    with_look = with_layers = false;
}

void an_emissive_layer_should_light_what_no_light_reaches(void)
{
    /* unlit by any light (no ambient either): black without the layer,
     * the emissive texel x factor with it */
    build_layer_texture();
    mote_mesh m = quad(0, -6, -5, 6, 5, 3.0f, 0.0f);
    mote_layer l = layer_of(MOTE_LAYER_EMISSIVE, 1.0f, 0.0f, MOTE_WRAP_REPEAT);
    l.u_scale = l.v_scale = 1.0f;
    l.u_offset = l.v_offset = 0.0f;
    m.material.layers = &l;
    m.material.layer_count = 1;
    m.material.color = (mote_rgba){0, 0, 0, 255};
    m.material.color_set = true;
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.unlit = true;
    static uint8_t img[W * H * 4];
    render(MOTE_FORMAT_RGBA8888, PATH_DIRECT, 1, &m, 1, &d, img);
    long lit = 0;
    for (int i = 0; i < W * H; i++)
        lit += img[4 * i] > 40 || img[4 * i + 1] > 40;
    snprintf(msg, sizeof msg, "%ld pixels lit by the emissive map", lit);
    TEST_ASSERT_TRUE_MESSAGE(lit > W * H / 4, msg);
}

/* The paths and formats the same-bytes tests walk: direct, binned on 1
 * and 3 threads, bands. */
static const int path_of[4] = {PATH_DIRECT, PATH_BINNED, PATH_BINNED, PATH_BANDS};
static const int threads_of[4] = {1, 1, 3, 1};
static const mote_format formats[3] = {MOTE_FORMAT_RGBA8888, MOTE_FORMAT_RGB565, MOTE_FORMAT_GREY8};

void depth_less_equal_should_draw_over_the_same_depths(void)
{
    mote_mesh m[2];
    m[0] = quad(0, -1.5f, -1.2f, 1.3f, 1.0f, 1.0f, 0.4f);
    m[0].material.color = (mote_rgba){255, 0, 0, 255};
    m[0].material.color_set = true;
    m[1] = m[0];                  /* the same triangles, so the same depths */
    m[1].material.color = (mote_rgba){0, 255, 0, 255};
    mote_draw_desc d, equal;
    memset(&d, 0, sizeof d);
    d.unlit = true;
    equal = d;
    equal.depth_less_equal = true;
    static uint8_t less[W * H * 4], lequal[W * H * 4];
    const draw_call strict[2] = {{&m[0], &d}, {&m[1], &d}}, passes[2] = {{&m[0], &d}, {&m[1], &equal}};
    for (int p = 0; p < 4; p++) {
        render_calls(MOTE_FORMAT_RGBA8888, path_of[p], threads_of[p], strict, 2, less);
        render_calls(MOTE_FORMAT_RGBA8888, path_of[p], threads_of[p], passes, 2, lequal);
        long red = 0, green = 0, other = 0;
        for (int i = 0; i < W * H; i++) {
            const uint8_t *a = &less[4 * i], *b = &lequal[4 * i];
            bool quad_pixel = a[0] == 255 && a[1] == 0;
            red += quad_pixel;
            green += quad_pixel && b[0] == 0 && b[1] == 255;
            other += !quad_pixel && memcmp(a, b, 4) != 0;
        }
        snprintf(msg, sizeof msg, "path %d: %ld pixels of the first quad, %ld of them redrawn, %ld others changed",
                 p, red, green, other);
        TEST_ASSERT_TRUE_MESSAGE(red > W * H / 8 && green == red && other == 0, msg);
    }
}

/* Two overlapping quads in one mesh, the farther one first. */
static mote_vertex layered_v[8];
static const uint32_t layered_i[2][12] = {{0, 2, 1, 0, 3, 2, 4, 6, 5, 4, 7, 6}, {4, 6, 5, 4, 7, 6, 0, 2, 1, 0, 3, 2}};

static mote_mesh layered(int order)
{
    mote_mesh far = quad(0, -1.8f, -1.4f, 0.8f, 1.2f, 1.5f, 0.3f);
    mote_mesh near = quad(1, -0.9f, -1.0f, 1.7f, 1.5f, 0.5f, -0.2f);
    memcpy(layered_v, far.vertices, 4 * sizeof layered_v[0]);
    memcpy(layered_v + 4, near.vertices, 4 * sizeof layered_v[0]);
    mote_mesh m = far;
    m.vertices = layered_v;
    m.vertex_count = 8;
    m.indices = layered_i[order];
    m.index_count = 12;
    m.material.texture = &tex;
    m.material.alpha_mode = MOTE_ALPHA_BLEND;
    m.material.use_texture_alpha = true;
    m.material.alpha = 0.7f;
    m.material.alpha_set = true;
    return m;
}

void a_depth_pre_pass_should_blend_only_the_nearest_surface(void)
{
    build_texture();
    mote_mesh backdrop = quad(2, -6, -5, 6, 5, 3.0f, 0.0f);
    backdrop.material.color = (mote_rgba){180, 200, 220, 255};
    backdrop.material.color_set = true;
    /* the mesh drawn twice: depth alone, then colour where the depth is
     * its nearest; as drawing the near quad first, whose depth hides the
     * far one's pixels behind it */
    mote_mesh back_first = layered(0), near_first = layered(1);
    mote_draw_desc d, depth_only, colour;
    memset(&d, 0, sizeof d);
    depth_only = colour = d;
    depth_only.no_color_write = true;
    colour.depth_less_equal = true;
    const draw_call pre_pass[3] = {{&backdrop, &d}, {&back_first, &depth_only}, {&back_first, &colour}};
    const draw_call sorted[2] = {{&backdrop, &d}, {&near_first, &d}};
    const draw_call plain[2] = {{&backdrop, &d}, {&back_first, &d}};
    static uint8_t a[W * H * 4], b[W * H * 4], c[W * H * 4];
    for (int f = 0; f < 3; f++)
        for (int p = 0; p < 4; p++) {
            const size_t bytes = (size_t)W * H * (size_t)mote_format_bytes(formats[f]);
            render_calls(formats[f], path_of[p], threads_of[p], pre_pass, 3, a);
            render_calls(formats[f], path_of[p], threads_of[p], sorted, 2, b);
            snprintf(msg, sizeof msg, "format %d, path %d", f, p);
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(b, a, bytes, msg);
            /* without it, the overlap is blended twice */
            render_calls(formats[f], path_of[p], threads_of[p], plain, 2, c);
            TEST_ASSERT_TRUE_MESSAGE(memcmp(a, c, bytes) != 0, msg);
        }
}

void a_depth_only_draw_should_write_no_colour(void)
{
    mote_mesh m[2];
    m[0] = quad(0, -1.5f, -1.2f, 1.3f, 1.0f, 1.0f, 0.4f);
    m[1] = quad(1, -6, -5, 6, 5, 3.0f, 0.0f);
    m[1].material.color = (mote_rgba){0, 255, 0, 255};
    m[1].material.color_set = true;
    mote_draw_desc d, depth_only;
    memset(&d, 0, sizeof d);
    d.unlit = true;
    depth_only = d;
    depth_only.no_color_write = true;
    static uint8_t img[W * H * 4];
    const draw_call calls[2] = {{&m[0], &depth_only}, {&m[1], &d}};
    for (int p = 0; p < 4; p++) {
        render_calls(MOTE_FORMAT_RGBA8888, path_of[p], threads_of[p], calls, 2, img);
        /* the near quad's pixels keep the clear colour, the rest are green */
        long clear = 0, green = 0;
        for (int i = 0; i < W * H; i++) {
            clear += img[4 * i] == 20 && img[4 * i + 1] == 30 && img[4 * i + 2] == 40;
            green += img[4 * i] == 0 && img[4 * i + 1] == 255;
        }
        snprintf(msg, sizeof msg, "path %d: %ld clear, %ld green", p, clear, green);
        TEST_ASSERT_TRUE_MESSAGE(clear > W * H / 8 && clear + green == W * H, msg);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(rounding_division_by_255_should_be_exact_over_its_range);
    RUN_TEST(blending_should_mix_source_and_target_as_documented);
    RUN_TEST(alpha_test_should_leave_cut_texels_undrawn_in_colour_and_depth);
    RUN_TEST(alpha_test_and_blending_should_be_within_1_lsb_of_the_reference);
    RUN_TEST(blending_should_give_the_same_bytes_on_every_path_and_format);
    RUN_TEST(highlights_and_fog_should_give_the_same_bytes_on_every_path_and_format);
    RUN_TEST(an_opaque_material_should_draw_as_without_alpha);
    RUN_TEST(texture_layers_should_be_within_1_lsb_of_the_reference);
    RUN_TEST(texture_layers_should_give_the_same_bytes_on_every_path_and_format);
    RUN_TEST(an_emissive_layer_should_light_what_no_light_reaches);
    RUN_TEST(depth_less_equal_should_draw_over_the_same_depths);
    RUN_TEST(a_depth_pre_pass_should_blend_only_the_nearest_surface);
    RUN_TEST(a_depth_only_draw_should_write_no_colour);
    return UNITY_END();
}
