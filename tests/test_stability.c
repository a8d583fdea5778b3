/*
 * test_stability.c - numerical stress: scenes far from the origin, tiny
 * and huge scenes, extreme cameras, depth precision, lighting and texel
 * coordinates at their limits, each against the double-precision
 * reference (tests/ref) or an invariant, with the figures printed.
 *
 * "Vertex error" is the largest distance, in pixels along x or y, between
 * mote's snapped vertices (the triangle hook) and the same float inputs
 * projected in double; snapping alone gives up to 1/512 pixel.
 */
#include "ref/ref.h"
#include "support/scenes.h"
#include "support/testutil.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 160
#define H 120

static char msg[256];

void setUp(void) {}
void tearDown(void) {}

/* ---- helpers ---------------------------------------------------------------- */

/* The largest vertex error of mesh m drawn alone (cull none, Gouraud);
 * every triangle must reach the rasteriser, so m must be in view,
 * unclipped and without degenerate triangles. */
static double vertex_error(const mote_frame_desc *f, const mote_mesh *m)
{
    static uint8_t color[W * H * 4];
    static uint32_t depth[W * H];
    static tu_capture cap;
    mote_device dev;
    const mote_device_desc d = {.width = W, .height = H, .color = color, .depth = depth,
                                .triangle_hook = tu_capture_hook, .triangle_hook_user = &cap};
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_device_init(&dev, &d));
    tu_capture_reset(&cap);
    mote_draw_desc dd;
    memset(&dd, 0, sizeof dd);
    dd.mode = MOTE_MODE_GOURAUD;
    dd.cull = MOTE_CULL_NONE;
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&dev, f));
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&dev, m, &dd));
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(m->index_count / 3, (uint32_t)cap.count, "every triangle reaches the rasteriser");
    /* the reference's camera in double, times mote's float world matrix */
    ref_target t;
    TEST_ASSERT_TRUE(ref_target_init(&t, W, H, 8));
    ref_begin(&t, f, (mote_rgba){0, 0, 0, 255});
    float wf[16];
    mote_mesh_world_matrix(m, wf);
    double mvp[16];
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++) {
            double s = 0.0;
            for (int k = 0; k < 4; k++)
                s += t.view_proj[k * 4 + r] * (double)wf[c * 4 + k];
            mvp[c * 4 + r] = s;
        }
    ref_target_free(&t);
    double worst = 0.0;
    for (size_t i = 0; i < cap.count; i++)
        for (int v = 0; v < 3; v++) {
            const float *p = m->vertices[m->indices[3 * i + v]].position;
            double o[4];
            for (int r = 0; r < 4; r++)
                o[r] = mvp[r] * p[0] + mvp[4 + r] * p[1] + mvp[8 + r] * p[2] + mvp[12 + r];
            double sx = (o[0] / o[3] + 1.0) * 0.5 * W, sy = (1.0 - o[1] / o[3]) * 0.5 * H;
            worst = fmax(worst, fmax(fabs(cap.tris[i].X[v] / 256.0 - sx), fabs(cap.tris[i].Y[v] / 256.0 - sy)));
        }
    return worst;
}

/* mote against the reference on a whole scene, printed as one row */
static tu_vs_result versus(const char *what, const tu_scene *s, mote_mode mode, mote_depth_format depth)
{
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.mode = mode;
    d.cull = MOTE_CULL_NONE;
    tu_vs_opts o = {W, H, 8, depth};
    tu_vs_result r;
    TEST_ASSERT_TRUE_MESSAGE(tu_vs_ref(&o, &s->frame, s->meshes, s->mesh_count, &d, true, &r, NULL, NULL),
                             what);
    printf("  %-40s coverage mismatches %4ld (%ld off-edge), max err %3d, within 1 LSB %7.3f%%\n", what,
           r.m.coverage_mismatch, r.unexplained, r.m.max_err, 100.0 * r.m.within_1_fraction);
    return r;
}

/* as test_accuracy.c holds the ordinary scenes */
static void assert_close(const char *what, const tu_vs_result *r)
{
    static char line[512];
    snprintf(line, sizeof line, "%s: %ld coverage mismatches (%ld off-edge) of %ld, %.3f%% within 1 LSB", what,
             r->m.coverage_mismatch, r->unexplained, r->m.covered_b, 100.0 * r->m.within_1_fraction);
    TEST_ASSERT_TRUE_MESSAGE(r->unexplained == 0 && r->m.coverage_mismatch * 500 <= r->m.covered_b
                             && r->m.within_1_fraction >= 0.999 && r->m.compared > 0, line);
}

/* everything in the scene (camera, target, lights, meshes) moved by off */
static void move_scene(tu_scene *s, const double off[3])
{
    mote_camera *c = &s->frame.camera;
    for (int k = 0; k < 3; k++) {
        c->position[k] = (float)(c->position[k] + off[k]);
        c->target[k] = (float)(c->target[k] + off[k]);
        for (int l = 0; l < s->frame.light_count; l++)
            s->frame.lights[l].position[k] = (float)(s->frame.lights[l].position[k] + off[k]);
        for (int m = 0; m < s->mesh_count; m++)
            s->meshes[m].position[k] = (float)(s->meshes[m].position[k] + off[k]);
    }
}

/* ---- world-space scale -------------------------------------------------------- */

/* The textured scene's cube and the lit, intersecting spheres, camera,
 * lights and all, 1e3 to 1e7 units from the origin (inputs are the
 * floats nearest the moved positions; the reference renders the same
 * floats). The vertex stage works relative to the camera, so vertices
 * land where the reference puts them wherever the scene is. Composed as
 * view x world, the view's translation and the mesh's cancelled after
 * each was rounded at its own magnitude: the cube's vertex error was
 * 0.018 pixel at 1e4, 0.30 at 1e5 and 2.3 at 1e6, and the spheres were
 * within 1 LSB on 98.6% of their pixels at 1e5, 26% at 1e6. */
void a_scene_far_from_the_origin_should_render_as_at_the_origin(void)
{
    static const double distances[] = {0, 1e3, 1e4, 1e5, 1e6, 1e7};
    for (size_t i = 0; i < sizeof distances / sizeof distances[0]; i++) {
        const double off[3] = {distances[i], -0.5 * distances[i], 0.3 * distances[i]};
        tu_scene s;
        tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, &s);
        move_scene(&s, off);
        double err = vertex_error(&s.frame, &s.meshes[1]);
        printf("scene %.0e units from the origin: cube's vertex error %.4f px\n", distances[i], err);
        tu_scene_build(TU_SCENE_GOURAUD, MOTE_WRAP_REPEAT, &s);
        move_scene(&s, off);
        tu_vs_result r = versus("lit spheres", &s, MOTE_MODE_GOURAUD, MOTE_DEPTH_FORMAT_32);
        snprintf(msg, sizeof msg, "%.0e from the origin: vertex error %.4f px", distances[i], err);
        TEST_ASSERT_TRUE_MESSAGE(err <= 0.005, msg);
        assert_close(msg, &r);
    }
}

/* ---- cameras ------------------------------------------------------------------ */

/* The look-at's axes are normalised vectors, whose squares leave float's
 * range for a target more than about 1.8e19 units away, an up vector of
 * such a length or below 1e-19, and a camera looking a hair from its up
 * (its x axis is then a tiny cross product): those drew nothing, or a
 * squeezed image. Each case against the double projection of the same
 * floats (the reference normalises in double). */
void the_camera_should_keep_its_axes_for_vectors_of_any_length(void)
{
    static const struct { const char *what; double target, up, down; } cases[] = {
        {"target 1e20 away", 1e20, 1, 0},        {"target 1e30 away", 1e30, 1, 0},
        {"up 1e-30 long", 0, 1e-30, 0},           {"up 1e30 long", 0, 1e30, 0},
        {"looking down, 1e-20 off vertical", 0, 1, 1e-20},
        {"looking down, 1e-30 off vertical", 0, 1, 1e-30},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        tu_scene s;
        tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, &s);
        mote_camera *c = &s.frame.camera;
        if (cases[i].target > 0) {   /* the same view, the target along it far away */
            double d[3], n = 0.0;
            for (int k = 0; k < 3; k++) {
                d[k] = (double)c->target[k] - c->position[k];
                n += d[k] * d[k];
            }
            for (int k = 0; k < 3; k++)
                c->target[k] = (float)(c->position[k] + d[k] / sqrt(n) * cases[i].target);
        }
        c->up[1] = (float)cases[i].up;
        if (cases[i].down > 0) {     /* from 8 units above, a hair off the vertical */
            const float eye[3] = {0, 8, 0}, at[3] = {(float)cases[i].down, 0, (float)(0.5 * cases[i].down)};
            memcpy(c->position, eye, sizeof eye);
            memcpy(c->target, at, sizeof at);
        }
        double err = vertex_error(&s.frame, &s.meshes[1]);
        printf("%-36s cube's vertex error %.4f px\n", cases[i].what, err);
        snprintf(msg, sizeof msg, "%s: vertex error %.4f px", cases[i].what, err);
        TEST_ASSERT_TRUE_MESSAGE(err <= 0.005, msg);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(a_scene_far_from_the_origin_should_render_as_at_the_origin);
    RUN_TEST(the_camera_should_keep_its_axes_for_vectors_of_any_length);
    return UNITY_END();
}
