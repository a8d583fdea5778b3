/*
 * test_accuracy.c - attributes against the double-precision reference
 * (tests/ref): perspective-correct colour and UVs, nearest and bilinear,
 * repeat / clamp / mirror, the depth test on intersecting triangles, and
 * the error of each approximate mode (reported, not bounded).
 *
 * Thresholds (scenes from tests/support/scenes.c, 160x120, deterministic):
 *   - perspective-correct textured (nearest and bilinear, every wrap mode),
 *     Gouraud and vertex-coloured scenes (every mode, lit and unlit): >=
 *     99.9% of the pixels both draw within 1 LSB of the reference; the
 *     largest error is printed;
 *   - coverage: mismatches only next to a reference edge (mote snaps from
 *     float, the reference from double), at most 0.2% of the drawn pixels;
 *   - depth: pixels off by more than 1 LSB only along the intersection
 *     line (at most 2 per image column).
 */
#include "ref/ref.h"
#include "support/scenes.h"
#include "support/testutil.h"
#include "unity.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 160
#define H 120

static char msg[256];

void setUp(void) {}
void tearDown(void) {}

static tu_vs_result run(const char *what, const tu_scene *s, const mote_draw_desc *d, int bits,
                        mote_depth_format depth)
{
    tu_vs_opts o = {W, H, bits, depth};
    tu_vs_result r;
    TEST_ASSERT_TRUE_MESSAGE(tu_vs_ref(&o, &s->frame, s->meshes, s->mesh_count, d, true, &r, NULL, NULL),
                             "render");
    printf("%-44s drawn %5ld  cov.mismatch %3ld (%ld off-edge)  max %3d  mean %.4f  PSNR %6.2f  "
           ">1 LSB %4ld  within 1 LSB %.3f%%\n", what, r.m.covered_b, r.m.coverage_mismatch,
           r.unexplained, r.m.max_err, r.m.mean_err, r.m.psnr, r.m.off_by_more_than_1,
           100.0 * r.m.within_1_fraction);
    return r;
}

static void assert_close(const char *what, const tu_vs_result *r)
{
    snprintf(msg, sizeof msg, "%s: %ld coverage mismatches away from edges", what, r->unexplained);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, r->unexplained, msg);
    snprintf(msg, sizeof msg, "%s: %ld coverage mismatches of %ld", what, r->m.coverage_mismatch, r->m.covered_b);
    TEST_ASSERT_TRUE_MESSAGE(r->m.coverage_mismatch * 500 <= r->m.covered_b, msg);
    snprintf(msg, sizeof msg, "%s: %.4f%% within 1 LSB, max error %d", what, 100.0 * r->m.within_1_fraction,
             r->m.max_err);
    TEST_ASSERT_TRUE_MESSAGE(r->m.within_1_fraction >= 0.999, msg);
    TEST_ASSERT_TRUE(r->m.compared > W * H / 4);
}

static mote_draw_desc draw_desc(mote_mode mode, mote_filter filter, mote_perspective p)
{
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.mode = mode;
    d.filter = filter;
    d.perspective = p;
    d.cull = MOTE_CULL_NONE;
    return d;
}

void perspective_correct_textures_should_be_within_1_lsb_of_the_reference(void)
{
    static const mote_wrap wraps[] = {MOTE_WRAP_REPEAT, MOTE_WRAP_CLAMP, MOTE_WRAP_MIRROR};
    static const char *names[] = {"repeat", "clamp", "mirror"};
    for (int w = 0; w < 3; w++)
        for (int f = 0; f < 2; f++) {
            tu_scene s;
            tu_scene_build(TU_SCENE_TEXTURED, wraps[w], &s);
            mote_draw_desc d = draw_desc(MOTE_MODE_TEXTURED, f ? MOTE_FILTER_BILINEAR : MOTE_FILTER_NEAREST,
                                         MOTE_PERSPECTIVE_CORRECT);
            char what[64];
            snprintf(what, sizeof what, "textured %s %s", f ? "bilinear" : "nearest", names[w]);
            tu_vs_result r = run(what, &s, &d, 8, MOTE_DEPTH_FORMAT_32);
            assert_close(what, &r);
        }
}

void unlit_textures_should_be_within_1_lsb_of_the_reference(void)
{
    tu_scene s;
    tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, &s);
    mote_draw_desc d = draw_desc(MOTE_MODE_TEXTURED, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_CORRECT);
    d.unlit = true;
    tu_vs_result r = run("textured nearest unlit", &s, &d, 8, MOTE_DEPTH_FORMAT_32);
    assert_close("textured nearest unlit", &r);
}

void gouraud_shading_should_be_within_1_lsb_of_the_reference(void)
{
    tu_scene s;
    tu_scene_build(TU_SCENE_GOURAUD, MOTE_WRAP_REPEAT, &s);
    mote_draw_desc d = draw_desc(MOTE_MODE_GOURAUD, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_CORRECT);
    tu_vs_result r = run("Gouraud", &s, &d, 8, MOTE_DEPTH_FORMAT_32);
    assert_close("Gouraud", &r);
    d.mode = MOTE_MODE_FLAT;
    r = run("flat", &s, &d, 8, MOTE_DEPTH_FORMAT_32);
    assert_close("flat", &r);
    r = run("Gouraud, 4 sub-pixel bits", &s, &d, 4, MOTE_DEPTH_FORMAT_32);
    assert_close("Gouraud, 4 sub-pixel bits", &r);
}

/* An orthographic camera, its box off centre and its near plane behind
 * its position: every w is 1, so the perspective-correct weights are the
 * screen-linear ones, as the reference's double-precision weights are.
 * Textured (nearest and bilinear) and Gouraud. */
void orthographic_cameras_should_be_within_1_lsb_of_the_reference(void)
{
    for (int k = 0; k < 3; k++) {
        tu_scene s;
        tu_scene_build(k == 2 ? TU_SCENE_GOURAUD : TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, &s);
        mote_camera *c = &s.frame.camera;
        c->projection = MOTE_PROJECTION_ORTHOGRAPHIC;
        const float box[4] = {-3.3f, 4.1f, -2.4f, 3.1f};
        for (int i = 0; i < 4; i++)   /* the Gouraud scene is smaller */
            c->ortho[i] = k == 2 ? 0.4f * box[i] : box[i];
        c->znear = -1.5f;
        mote_draw_desc d = draw_desc(k == 2 ? MOTE_MODE_GOURAUD : MOTE_MODE_TEXTURED,
                                     k == 1 ? MOTE_FILTER_BILINEAR : MOTE_FILTER_NEAREST,
                                     MOTE_PERSPECTIVE_CORRECT);
        const char *what = k == 0 ? "orthographic, textured nearest"
                         : k == 1 ? "orthographic, textured bilinear" : "orthographic, Gouraud";
        tu_vs_result r = run(what, &s, &d, 8, MOTE_DEPTH_FORMAT_32);
        assert_close(what, &r);
    }
}

/* Babylon's falloff: the point light given a range that ends inside the
 * scene, and a spot light whose cone edge crosses the spheres, with a
 * fractional exponent; each against the reference's double-precision
 * formula. The cone's edge is a step from cos(angle / 2)^exponent to 0, so
 * a vertex that lies on it in one precision and off it in the other would
 * shade its triangles otherwise: within 1 LSB still holds for 99.9%. */
void spot_lights_and_ranges_should_be_within_1_lsb_of_the_reference(void)
{
    tu_scene s;
    tu_scene_build(TU_SCENE_GOURAUD, MOTE_WRAP_REPEAT, &s);
    s.frame.lights[0].range = 14.0f;
    s.frame.light_count = 3;
    mote_light *spot = &s.frame.lights[2];
    spot->type = MOTE_LIGHT_SPOT;
    spot->position[0] = -2.0f;
    spot->position[1] = 3.0f;
    spot->position[2] = -4.0f;
    spot->direction[0] = 0.5f;
    spot->direction[1] = -0.6f;
    spot->direction[2] = 1.0f;
    spot->color[2] = 1.0f;
    spot->spot_angle = 0.7f;
    spot->spot_exponent = 1.7f;
    spot->range = 12.0f;
    mote_draw_desc d = draw_desc(MOTE_MODE_GOURAUD, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_CORRECT);
    tu_vs_result r = run("Gouraud, spot light and ranges", &s, &d, 8, MOTE_DEPTH_FORMAT_32);
    assert_close("Gouraud, spot light and ranges", &r);
    /* the falloff shows: lit as plain point lights, a good part of the
     * image differs by more than a few levels */
    static uint8_t with[W * H * 4], without[W * H * 4];
    tu_vs_opts o = {W, H, 8, MOTE_DEPTH_FORMAT_32};
    tu_vs_result unused;
    TEST_ASSERT_TRUE(tu_vs_ref(&o, &s.frame, s.meshes, s.mesh_count, &d, true, &unused, with, NULL));
    tu_scene plain = s;
    plain.frame.lights[0].range = plain.frame.lights[2].range = 0.0f;
    plain.frame.lights[2].type = MOTE_LIGHT_POINT;
    TEST_ASSERT_TRUE(tu_vs_ref(&o, &plain.frame, s.meshes, s.mesh_count, &d, true, &unused, without, NULL));
    int moved = 0;
    for (int i = 0; i < W * H * 4; i++)
        moved += abs(with[i] - without[i]) > 8;
    snprintf(msg, sizeof msg, "%d channels moved by the falloff", moved);
    TEST_ASSERT_TRUE_MESSAGE(moved > W * H / 4, msg);
    d.mode = MOTE_MODE_FLAT;
    r = run("flat, spot light and ranges", &s, &d, 8, MOTE_DEPTH_FORMAT_32);
    assert_close("flat, spot light and ranges", &r);
}

/* A mesh scaled by -1 along one axis (or all three) is mirrored: its front
 * faces wind the other way on screen and its normals must stay outward.
 * The spheres of the Gouraud scene are their own mirror images, so each
 * mirrored render must also look like the plain one (up to the diagonals
 * of its quads, which the mirror swaps); two negative factors are a
 * rotation, and must not count as a mirror. */
void mirrored_meshes_should_cull_and_light_like_their_mirror_images(void)
{
    static uint8_t plain_img[W * H * 4], img[W * H * 4];
    static const float scales[3][3] = {{-1, 1, 1}, {-1, -1, -1}, {1, -1, -1}};
    static const char *const names[3] = {"mirrored in x", "mirrored through the centre",
                                          "turned about x (two negative factors)"};
    tu_scene s;
    tu_scene_build(TU_SCENE_GOURAUD, MOTE_WRAP_REPEAT, &s);
    mote_draw_desc d = draw_desc(MOTE_MODE_GOURAUD, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_CORRECT);
    tu_vs_opts o = {W, H, 8, MOTE_DEPTH_FORMAT_32};
    tu_vs_result plain;
    TEST_ASSERT_TRUE(tu_vs_ref(&o, &s.frame, s.meshes, s.mesh_count, &d, true, &plain, plain_img, NULL));
    for (int i = 0; i < 3; i++) {
        tu_scene_build(TU_SCENE_GOURAUD, MOTE_WRAP_REPEAT, &s);
        for (int m = 0; m < s.mesh_count; m++)
            for (int k = 0; k < 3; k++)
                s.meshes[m].scaling[k] = (s.meshes[m].scaling[k] != 0.0f ? s.meshes[m].scaling[k] : 1.0f)
                                       * scales[i][k];
        tu_vs_result r = run(names[i], &s, &d, 8, MOTE_DEPTH_FORMAT_32);
        assert_close(names[i], &r);
        TEST_ASSERT_TRUE(tu_vs_ref(&o, &s.frame, s.meshes, s.mesh_count, &d, true, &r, img, NULL));
        long differ = 0, sum = 0;
        for (int p = 0; p < W * H * 4; p++) {
            int e = abs((int)img[p] - (int)plain_img[p]);
            sum += e;
            differ += e > 16;
        }
        printf("%-44s against the plain render: mean abs %.4f, %ld channels off by more than 16\n",
               names[i], (double)sum / (W * H * 3), differ);
        snprintf(msg, sizeof msg, "%s: %ld channels differ from the plain render by more than 16", names[i],
                 differ);
        TEST_ASSERT_TRUE_MESSAGE(differ * 200 <= W * H * 3, msg);
        TEST_ASSERT_TRUE_MESSAGE(sum * 2 <= W * H * 3, names[i]);
    }
}

void vertex_colours_should_be_within_1_lsb_of_the_reference_in_every_mode(void)
{
    static uint8_t plain[W * H * 4], colored[W * H * 4];
    static const struct { mote_mode mode; mote_filter filter; const char *name; } modes[] = {
        {MOTE_MODE_GOURAUD, MOTE_FILTER_NEAREST, "Gouraud"},
        {MOTE_MODE_FLAT, MOTE_FILTER_NEAREST, "flat"},
        {MOTE_MODE_TEXTURED, MOTE_FILTER_NEAREST, "textured nearest"},
        {MOTE_MODE_TEXTURED, MOTE_FILTER_BILINEAR, "textured bilinear"},
    };
    tu_scene s;
    tu_scene_build(TU_SCENE_COLORS, MOTE_WRAP_REPEAT, &s);
    tu_vs_opts o = {W, H, 8, MOTE_DEPTH_FORMAT_32};
    for (size_t k = 0; k < sizeof modes / sizeof modes[0]; k++)
        for (int unlit = 0; unlit < 2; unlit++) {
            mote_draw_desc d = draw_desc(modes[k].mode, modes[k].filter, MOTE_PERSPECTIVE_CORRECT);
            d.unlit = unlit;
            char what[64];
            snprintf(what, sizeof what, "vertex colours, %s%s", modes[k].name, unlit ? ", unlit" : "");
            tu_vs_result r;
            TEST_ASSERT_TRUE(tu_vs_ref(&o, &s.frame, s.meshes, s.mesh_count, &d, true, &r, colored, NULL));
            printf("%-44s max %3d  PSNR %6.2f  within 1 LSB %.3f%%\n", what, r.m.max_err, r.m.psnr,
                   100.0 * r.m.within_1_fraction);
            assert_close(what, &r);
            /* and the colours show: most drawn pixels differ from the same
             * scene without them */
            tu_scene bare = s;
            for (int i = 0; i < bare.mesh_count; i++)
                bare.meshes[i].colors = NULL;
            TEST_ASSERT_TRUE(tu_vs_ref(&o, &bare.frame, bare.meshes, bare.mesh_count, &d, true, &r, plain,
                                       NULL));
            long differ = 0;
            for (int i = 0; i < W * H; i++)
                differ += memcmp(&plain[4 * i], &colored[4 * i], 3) != 0;
            snprintf(msg, sizeof msg, "%s: %ld pixels changed by the colours", what, differ);
            TEST_ASSERT_TRUE_MESSAGE(differ > W * H / 4, msg);
        }
}

void approximate_perspective_modes_should_report_their_error(void)
{
    tu_scene s;
    tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, &s);
    mote_draw_desc d = draw_desc(MOTE_MODE_TEXTURED, MOTE_FILTER_BILINEAR, MOTE_PERSPECTIVE_CORRECT);
    tu_vs_result correct = run("bilinear, perspective-correct", &s, &d, 8, MOTE_DEPTH_FORMAT_32);
    d.perspective = MOTE_PERSPECTIVE_SUBSPAN;
    d.subspan_log2 = 3;
    tu_vs_result sub8 = run("bilinear, correct every 8 px", &s, &d, 8, MOTE_DEPTH_FORMAT_32);
    d.subspan_log2 = 5;
    tu_vs_result sub32 = run("bilinear, correct every 32 px", &s, &d, 8, MOTE_DEPTH_FORMAT_32);
    d.perspective = MOTE_PERSPECTIVE_AFFINE;
    tu_vs_result affine = run("bilinear, affine", &s, &d, 8, MOTE_DEPTH_FORMAT_32);
    /* the modes must do what they say: coarser is worse, and none changes coverage */
    TEST_ASSERT_TRUE(affine.m.mean_err > sub32.m.mean_err);
    TEST_ASSERT_TRUE(sub32.m.mean_err >= sub8.m.mean_err);
    TEST_ASSERT_TRUE(sub8.m.mean_err >= correct.m.mean_err);
    TEST_ASSERT_EQUAL_INT(correct.m.coverage_mismatch, affine.m.coverage_mismatch);
    TEST_ASSERT_EQUAL_INT(correct.m.coverage_mismatch, sub8.m.coverage_mismatch);
}

void the_depth_test_should_resolve_intersecting_triangles_like_the_reference(void)
{
    tu_scene s;
    tu_scene_build(TU_SCENE_DEPTH, MOTE_WRAP_REPEAT, &s);
    mote_draw_desc d = draw_desc(MOTE_MODE_FLAT, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_CORRECT);
    d.unlit = true;
    static const mote_depth_format formats[] = {MOTE_DEPTH_FORMAT_32, MOTE_DEPTH_FORMAT_16};
    for (int k = 0; k < 2; k++) {
        tu_vs_result r = run(k ? "intersecting quads, 16-bit depth" : "intersecting quads, 32-bit depth", &s, &d,
                             8, formats[k]);
        TEST_ASSERT_EQUAL_INT(0, r.unexplained);
        /* both colours visible, and wrong ones only along the intersection */
        snprintf(msg, sizeof msg, "%ld pixels of the wrong quad", r.m.off_by_more_than_1);
        TEST_ASSERT_TRUE_MESSAGE(r.m.off_by_more_than_1 <= 2 * W, msg);
        TEST_ASSERT_TRUE(r.m.compared > W * H / 2);
    }
    /* and the image does not depend on the order of the draws */
    tu_scene rev = s;
    rev.meshes[0] = s.meshes[1];
    rev.meshes[1] = s.meshes[0];
    tu_vs_result a = run("intersecting quads, reversed order", &rev, &d, 8, MOTE_DEPTH_FORMAT_32);
    TEST_ASSERT_TRUE(a.m.off_by_more_than_1 <= 2 * W);
}

void a_texture_with_stride_0_should_read_rows_width_times_pixel_size_apart(void)
{
    /* mote.h: "stride 0 means width * bytes per pixel": the same image as
     * with the stride spelled out */
    static uint8_t explicit_stride[W * H * 4], zero_stride[W * H * 4];
    tu_scene s;
    tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, &s);
    mote_texture t = *tu_scene_texture();
    for (int i = 0; i < s.mesh_count; i++)
        s.meshes[i].material.texture = &t;
    mote_draw_desc d = draw_desc(MOTE_MODE_TEXTURED, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_CORRECT);
    tu_vs_opts o = {W, H, 8, MOTE_DEPTH_FORMAT_32};
    tu_vs_result r;
    TEST_ASSERT_TRUE(tu_vs_ref(&o, &s.frame, s.meshes, s.mesh_count, &d, true, &r, explicit_stride, NULL));
    t.stride = 0;
    TEST_ASSERT_TRUE(tu_vs_ref(&o, &s.frame, s.meshes, s.mesh_count, &d, true, &r, zero_stride, NULL));
    TEST_ASSERT_EQUAL_MEMORY(explicit_stride, zero_stride, sizeof zero_stride);
}

/* Blinn-Phong highlights (mote_material.specular), per vertex, lit
 * Gouraud and textured, each against the reference's double-precision
 * formula; then with the first light switched off for the draws
 * (lights_off). */
void specular_highlights_should_be_within_1_lsb_of_the_reference(void)
{
    for (int k = 0; k < 3; k++) {
        tu_scene s;
        tu_scene_build(k == 1 ? TU_SCENE_TEXTURED : TU_SCENE_GOURAUD, MOTE_WRAP_REPEAT, &s);
        for (int i = 0; i < s.mesh_count; i++) {
            s.meshes[i].material.specular = (mote_rgba){230, 200, 150, 255};
            s.meshes[i].material.specular_power = i ? 12.0f : 40.0f;
        }
        s.frame.lights[0].specular[1] = 0.5f;   /* a tinted light */
        s.frame.lights[0].specular[0] = s.frame.lights[0].specular[2] = 1.0f;
        mote_draw_desc d = draw_desc(k == 1 ? MOTE_MODE_TEXTURED : MOTE_MODE_GOURAUD, MOTE_FILTER_NEAREST,
                                     MOTE_PERSPECTIVE_CORRECT);
        if (k == 2)
            d.lights_off = 1;
        const char *what = k == 0 ? "specular, Gouraud" : k == 1 ? "specular, textured" : "specular, light 0 off";
        tu_vs_result r = run(what, &s, &d, 8, MOTE_DEPTH_FORMAT_32);
        assert_close(what, &r);
    }
}

/* Fog, linear, exponential and squared exponential, per vertex, over
 * lit Gouraud and textured scenes, with highlights. */
void fog_should_be_within_1_lsb_of_the_reference(void)
{
    static const mote_fog_mode modes[3] = {MOTE_FOG_LINEAR, MOTE_FOG_EXP, MOTE_FOG_EXP2};
    for (int m = 0; m < 3; m++)
        for (int k = 0; k < 2; k++) {
            tu_scene s;
            tu_scene_build(k ? TU_SCENE_TEXTURED : TU_SCENE_GOURAUD, MOTE_WRAP_REPEAT, &s);
            s.frame.fog = (mote_fog){modes[m], {0.6f, 0.7f, 0.8f}, 0.12f, 2.0f, 12.0f};
            s.meshes[0].material.specular = (mote_rgba){255, 255, 255, 255};
            mote_draw_desc d = draw_desc(k ? MOTE_MODE_TEXTURED : MOTE_MODE_GOURAUD, MOTE_FILTER_NEAREST,
                                         MOTE_PERSPECTIVE_CORRECT);
            char what[64];
            snprintf(what, sizeof what, "fog %s, %s", m == 0 ? "linear" : m == 1 ? "exp" : "exp2",
                     k ? "textured" : "Gouraud");
            tu_vs_result r = run(what, &s, &d, 8, MOTE_DEPTH_FORMAT_32);
            assert_close(what, &r);
        }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(perspective_correct_textures_should_be_within_1_lsb_of_the_reference);
    RUN_TEST(unlit_textures_should_be_within_1_lsb_of_the_reference);
    RUN_TEST(specular_highlights_should_be_within_1_lsb_of_the_reference);
    RUN_TEST(fog_should_be_within_1_lsb_of_the_reference);
    RUN_TEST(gouraud_shading_should_be_within_1_lsb_of_the_reference);
    RUN_TEST(spot_lights_and_ranges_should_be_within_1_lsb_of_the_reference);
    RUN_TEST(orthographic_cameras_should_be_within_1_lsb_of_the_reference);
    RUN_TEST(mirrored_meshes_should_cull_and_light_like_their_mirror_images);
    RUN_TEST(vertex_colours_should_be_within_1_lsb_of_the_reference_in_every_mode);
    RUN_TEST(approximate_perspective_modes_should_report_their_error);
    RUN_TEST(the_depth_test_should_resolve_intersecting_triangles_like_the_reference);
    RUN_TEST(a_texture_with_stride_0_should_read_rows_width_times_pixel_size_apart);
    return UNITY_END();
}
