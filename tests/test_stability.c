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
    const mote_draw_desc dd = {.mode = MOTE_MODE_GOURAUD, .cull = MOTE_CULL_NONE};
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
    const mote_draw_desc d = {.mode = mode, .cull = MOTE_CULL_NONE};
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

/* everything in the scene scaled by k about the origin (near and far too) */
static void scale_scene(tu_scene *s, double k)
{
    mote_camera *c = &s->frame.camera;
    for (int j = 0; j < 3; j++) {
        c->position[j] = (float)(c->position[j] * k);
        c->target[j] = (float)(c->target[j] * k);
        for (int l = 0; l < s->frame.light_count; l++)
            s->frame.lights[l].position[j] = (float)(s->frame.lights[l].position[j] * k);
        for (int m = 0; m < s->mesh_count; m++) {
            s->meshes[m].position[j] = (float)(s->meshes[m].position[j] * k);
            s->meshes[m].scaling[j] = (float)((s->meshes[m].scaling[j] != 0.0f ? s->meshes[m].scaling[j] : 1.0f) * k);
        }
    }
    c->znear = (float)(c->znear * k);
    c->zfar = (float)(c->zfar * k);
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

/* The same scenes scaled about the origin by 1e-8 to 1e9 (near and far
 * planes too): nothing but the units changes, and so the image must not.
 * Mesh scaling enters the normals squared (the cofactor matrix) and then
 * squared again (their length), so lighting holds for scaling factors
 * from about 3e-10 to 4e9: the rows at 1e-10 and 1e10 are printed, not
 * held. */
void tiny_and_huge_scenes_should_render_as_at_unit_scale(void)
{
    static const double scales[] = {1e-8, 1e-6, 1e-4, 1e3, 1e6, 1e9, 1e-10, 1e10};
    for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        const bool held = i < 6;
        tu_scene s;
        tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, &s);
        scale_scene(&s, scales[i]);
        double err = vertex_error(&s.frame, &s.meshes[1]);
        printf("scene scaled by %.0e%s: cube's vertex error %.4f px\n", scales[i], held ? "" : " (not held)", err);
        tu_scene_build(TU_SCENE_GOURAUD, MOTE_WRAP_REPEAT, &s);
        scale_scene(&s, scales[i]);
        tu_vs_result r = versus("lit spheres", &s, MOTE_MODE_GOURAUD, MOTE_DEPTH_FORMAT_32);
        snprintf(msg, sizeof msg, "scaled by %.0e: vertex error %.4f px", scales[i], err);
        TEST_ASSERT_TRUE_MESSAGE(err <= 0.005, msg);
        if (held)
            assert_close(msg, &r);
    }
}

/* ---- depth ---------------------------------------------------------------------- */

/* Two quads facing the camera (fov 0.8, 64x48) at distance d and d + sep,
 * the farther drawn first: the fraction of the pixels the nearer wins
 * (ties go to the farther: the test is strictly less). */
static double nearer_wins(float n, float f, double d, double sep, mote_depth_format format)
{
    enum { DW = 64, DH = 48 };
    static uint8_t color[DW * DH * 4];
    static uint32_t depth[DW * DH];
    static mote_vertex v[2][4];
    static const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
    mote_device dev;
    const mote_device_desc desc = {.width = DW, .height = DH, .color = color, .depth = depth,
                                   .depth_format = format};
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_device_init(&dev, &desc));
    const mote_frame_desc fr = {.camera = {.target = {0, 0, 1}, .fov = 0.8f, .znear = n, .zfar = f}};
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&dev, &fr));
    const mote_draw_desc dd = {.mode = MOTE_MODE_FLAT, .unlit = true, .cull = MOTE_CULL_NONE};
    for (int q = 0; q < 2; q++) {   /* farther (red), then nearer (green) */
        static const float corner[4][2] = {{-1, -1}, {-1, 1}, {1, 1}, {1, -1}};
        memset(v[q], 0, sizeof v[q]);
        for (int k = 0; k < 4; k++) {
            v[q][k].position[0] = (float)(corner[k][0] * d);
            v[q][k].position[1] = (float)(corner[k][1] * d);
            v[q][k].position[2] = (float)(q ? d : d + sep);
        }
        mote_mesh m = tu_mesh_of(v[q], 4, idx, 6);
        m.material.color_set = true;
        m.material.color = q ? (mote_rgba){0, 255, 0, 255} : (mote_rgba){255, 0, 0, 255};
        TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&dev, &m, &dd));
    }
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&dev));
    long green = 0;
    for (int i = 0; i < DW * DH; i++)
        green += color[4 * i + 1] == 255;
    return (double)green / (DW * DH);
}

/* Depth is z/w rounded to 24 bits (16 for a 16-bit buffer), so two
 * surfaces at distance d resolve when they are about one step,
 * d^2 (f - n) / (n f 2^bits), apart (f: the far plane, n: the near one);
 * the far plane hardly matters once it is 100 times the near one, the
 * near one does. Printed: the smallest separation, in steps, at which the
 * nearer of two quads wins every pixel (searched in quarter steps), and
 * the step as a fraction of d; each must resolve at 2 steps. */
void the_depth_buffer_should_resolve_surfaces_a_few_steps_apart(void)
{
    static const struct { float n, f; double d; } cases[] = {
        {0.1f, 100.0f, 10}, {0.1f, 1e4f, 10}, {0.1f, 1e8f, 10}, {0.1f, 1677721.6f, 10},
        {0.01f, 1e3f, 10}, {1.0f, 1e4f, 100}, {1e-4f, 1e3f, 1}, {0.1f, 1e4f, 1000},
    };
    for (int bits16 = 0; bits16 < 2; bits16++)
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            const float n = cases[i].n, f = cases[i].f;
            const double d = cases[i].d;
            const double step = d * d * (f - n) / ((double)n * f * (bits16 ? 65536.0 : 16777216.0));
            const mote_depth_format fmt = bits16 ? MOTE_DEPTH_FORMAT_16 : MOTE_DEPTH_FORMAT_32;
            double worst = 0.0;   /* over 16 distances from d to 1.4 d: where the steps fall varies */
            for (int j = 0; j < 16; j++) {
                const double dj = d * (1.0 + j / 40.0), sj = step * (1.0 + j / 40.0) * (1.0 + j / 40.0);
                double k = 0.25;
                while (k < 3.0 && nearer_wins(n, f, dj, k * sj, fmt) < 1.0)
                    k += 0.25;
                worst = fmax(worst, k);
                snprintf(msg, sizeof msg, "near %g far %g distance %g, %s", n, f, dj, bits16 ? "16-bit" : "32-bit");
                TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(1.0, nearer_wins(n, f, dj, 2.0 * sj, fmt), msg);
            }
            printf("%s depth, near %-6g far %-10g at %-5g: resolved %.2f steps apart (a step: %.3g of the "
                   "distance)\n", bits16 ? "16-bit" : "32-bit", n, f, d, worst, step / d);
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

/* A narrow field of view magnifies the camera's turn: its axes are
 * floats, good to about 2^-24 radian, which a field of view of fov
 * radians spreads over H pixels, so vertices may be off by about
 * H 2^-24 / fov pixels (inherent in a float rotation). The camera moves
 * back to keep the textured scene's framing; the cube's vertex error
 * must stay within 1/256 + H 2^-24 / fov. */
void narrow_fields_of_view_should_stay_within_the_float_turn(void)
{
    static const float fovs[] = {1e-2f, 1e-3f, 1e-4f, 1e-5f};
    for (size_t i = 0; i < sizeof fovs / sizeof fovs[0]; i++) {
        tu_scene s;
        tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, &s);
        mote_camera *c = &s.frame.camera;
        const double k = tan(0.5 * c->fov) / tan(0.5 * fovs[i]);
        for (int j = 0; j < 3; j++)
            c->position[j] = (float)(c->target[j] + (c->position[j] - c->target[j]) * k);
        c->fov = fovs[i];
        c->znear = (float)(c->znear * k);
        c->zfar = (float)(c->zfar * k);
        const double err = vertex_error(&s.frame, &s.meshes[1]), bound = 1.0 / 256 + H / (fovs[i] * 16777216.0);
        printf("fov %.0e rad (camera %.3g units away): cube's vertex error %.4f px (bound %.4f)\n", fovs[i],
               6.3 * k, err, bound);
        snprintf(msg, sizeof msg, "fov %g: vertex error %.4f px, bound %.4f", fovs[i], err, bound);
        TEST_ASSERT_TRUE_MESSAGE(err <= bound, msg);
    }
}

/* ---- lighting ------------------------------------------------------------------- */

/* The lit spheres with normals of any length (each is normalised per
 * vertex; a zero normal lights nothing, in the reference too), a point
 * light on a vertex, far away or with a huge range, a spot light with a
 * huge exponent, a huge intensity (clamped): each within 1 LSB of the
 * reference. The squares of normals, light vectors and directions leave
 * float's range beyond about 1e-19 and 1.8e19: printed, not held. */
void lighting_should_hold_up_at_extreme_values(void)
{
    static mote_vertex v[17 * 33];
    static const struct { const char *what; float normal, light, range, exponent, intensity; bool held; } cases[] = {
        {"normals x 1e-15", 1e-15f, 0, 0, 0, 0, true},          {"normals x 1e15", 1e15f, 0, 0, 0, 0, true},
        {"normals zero", 0, 0, 0, 0, 0, true},                  {"light on a vertex", 1, -1, 0, 0, 0, true},
        {"point light 1e18 away", 1, 1e18f, 0, 0, 0, true},     {"light range 1e30", 1, 0, 1e30f, 0, 0, true},
        {"light range just past the spheres", 1, 0, 9, 0, 0, true},
        {"spot exponent 1e4", 1, 0, 0, 1e4f, 0, true},          {"spot exponent 1e6", 1, 0, 0, 1e6f, 0, true},
        {"intensity 1e30", 1, 0, 0, 0, 1e30f, true},
        {"normals x 1e-20 (not held)", 1e-20f, 0, 0, 0, 0, false}, {"point light 1e20 away (not held)", 1, 1e20f, 0, 0, 0, false},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        tu_scene s;
        tu_scene_build(TU_SCENE_GOURAUD, MOTE_WRAP_REPEAT, &s);
        memcpy(v, s.meshes[0].vertices, sizeof v);
        for (int j = 0; j < 17 * 33; j++)
            for (int k = 0; k < 3; k++)
                v[j].normal[k] *= cases[i].normal;
        s.meshes[0].vertices = v;
        mote_light *l = &s.frame.lights[0];
        if (cases[i].light < 0)   /* on vertex 100 of the first sphere */
            for (int k = 0; k < 3; k++)
                l->position[k] = v[100].position[k] + s.meshes[0].position[k];
        else if (cases[i].light > 0)
            for (int k = 0; k < 3; k++)
                l->position[k] *= cases[i].light / 8.775f;   /* |(4, 6, -5)| = 8.775 */
        l->range = cases[i].range;
        if (cases[i].exponent > 0) {   /* a spot light from the camera, its cone's edge on the spheres */
            l->type = MOTE_LIGHT_SPOT;
            memcpy(l->position, s.frame.camera.position, sizeof l->position);
            const float dir[3] = {0.05f, -0.2f, 1.0f};
            memcpy(l->direction, dir, sizeof dir);
            l->spot_angle = 1.2f;
            l->spot_exponent = cases[i].exponent;
        }
        l->intensity = cases[i].intensity;
        tu_vs_result r = versus(cases[i].what, &s, MOTE_MODE_GOURAUD, MOTE_DEPTH_FORMAT_32);
        if (cases[i].held)
            assert_close(cases[i].what, &r);
    }
}

/* ---- texel coordinates ------------------------------------------------------------ */

/* The textured scene's floor (64-texel texture, repeated or mirrored)
 * with its uv moved by a whole number of periods: the same image, ideally.
 * Texel coordinates are floats of magnitude |u| x 64, good to about
 * |u| 64 2^-24 texels (the uv itself is no better), so nearest texels
 * flip at their edges and bilinear weights move as |u| grows; each row
 * against the reference, held up to 256 periods (16,384 texels) nearest
 * and 1024 (65,536 texels) bilinear. */
void texel_coordinates_far_from_zero_should_stay_within_1_lsb(void)
{
    static const float periods[] = {0, 16, 64, 256, 1024, 16384};
    static mote_vertex v[4];
    for (int filter = 0; filter < 2; filter++)
        for (int mirror = 0; mirror < 2; mirror++)
            for (size_t i = 0; i < sizeof periods / sizeof periods[0]; i++) {
                tu_scene s;
                tu_scene_build(TU_SCENE_TEXTURED, mirror ? MOTE_WRAP_MIRROR : MOTE_WRAP_REPEAT, &s);
                s.mesh_count = 1;
                memcpy(v, s.meshes[0].vertices, sizeof v);
                for (int k = 0; k < 4; k++) {
                    v[k].uv[0] += periods[i];
                    v[k].uv[1] -= periods[i];
                }
                s.meshes[0].vertices = v;
                const mote_draw_desc d = {.mode = MOTE_MODE_TEXTURED,
                                          .filter = filter ? MOTE_FILTER_BILINEAR : MOTE_FILTER_NEAREST};
                tu_vs_opts o = {W, H, 8, MOTE_DEPTH_FORMAT_32};
                tu_vs_result r;
                TEST_ASSERT_TRUE(tu_vs_ref(&o, &s.frame, s.meshes, 1, &d, true, &r, NULL, NULL));
                const bool held = periods[i] <= (filter ? 1024 : 256);
                printf("  %-8s %-6s uv + %-6.0f periods: max err %3d, within 1 LSB %7.3f%%%s\n",
                       filter ? "bilinear" : "nearest", mirror ? "mirror" : "repeat", periods[i], r.m.max_err,
                       100.0 * r.m.within_1_fraction, held ? "" : " (not held)");
                snprintf(msg, sizeof msg, "%s, uv + %g", filter ? "bilinear" : "nearest", periods[i]);
                if (held)
                    assert_close(msg, &r);
            }
}

/* One quad of ground, 1000 x 1000 units, its 256-texel texture repeated
 * n times across it, seen from 1 unit above (the lower half of the image
 * magnifies the texels). Each texel holds its own coordinates, so a pixel
 * says which texel mote sampled; the reference says which it should be.
 * The texel coordinates are exact floats here; what moves a texel's edge
 * by a pixel or so is the float perspective weights (a texel off, up to
 * 1000 repeats), and past that the per-pixel reciprocal, which keeps a
 * bit less for each doubling of a triangle's texel range past 2^11
 * texels (setup.c's K, for a 64-bit product): at 10000 repeats 45% of
 * the pixels are more than a texel off (with a 128-bit product and K at
 * 54, tried and left out, none was). Held: within one texel up to 100
 * repeats (25,600 texels); 1000 and 10000 are printed. Tessellate large
 * tiled planes. */
void a_large_tiled_quad_should_sample_within_a_texel_up_to_100_repeats(void)
{
    static uint8_t texels[256 * 256 * 4], mote_img[W * H * 4], ref_img[W * H * 4];
    static const mote_texture tex = {256, 256, MOTE_FORMAT_RGBA8888, 0, texels};
    for (int y = 0; y < 256; y++)
        for (int x = 0; x < 256; x++) {
            uint8_t *p = &texels[4 * (y * 256 + x)];
            p[0] = (uint8_t)x;
            p[1] = (uint8_t)y;
            p[2] = 0;
            p[3] = 255;
        }
    static const float repeats[] = {10, 100, 1000, 10000};
    static mote_vertex v[4];
    static const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
    for (size_t i = 0; i < sizeof repeats / sizeof repeats[0]; i++) {
        static const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int k = 0; k < 4; k++) {
            memset(&v[k], 0, sizeof v[k]);
            v[k].position[0] = corner[k][0] * 500.0f;
            v[k].position[1] = -1.0f;
            v[k].position[2] = corner[k][1] * 500.0f;
            v[k].normal[1] = 1.0f;
            v[k].uv[0] = (corner[k][0] + 1.0f) * 0.5f * repeats[i];
            v[k].uv[1] = (corner[k][1] + 1.0f) * 0.5f * repeats[i];
        }
        mote_mesh m = tu_mesh_of(v, 4, idx, 6);
        m.material.texture = &tex;
        const mote_frame_desc f = {.camera = {.position = {3.3f, 0, 7.1f}, .target = {3.3f, -0.6f, 8.1f},
                                              .fov = 0.9f, .znear = 0.1f, .zfar = 2000.0f}};
        const mote_draw_desc d = {.mode = MOTE_MODE_TEXTURED, .unlit = true, .cull = MOTE_CULL_NONE};
        const tu_vs_opts o = {W, H, 8, MOTE_DEPTH_FORMAT_32};
        tu_vs_result r;
        TEST_ASSERT_TRUE(tu_vs_ref(&o, &f, &m, 1, &d, true, &r, mote_img, ref_img));
        long off[2][3] = {{0}};   /* lower half, upper half: texels off by 0, 1, more */
        int worst = 0;
        for (int p = 0; p < W * H; p++) {
            int e = 0;
            for (int c = 0; c < 2; c++) {   /* texel differences modulo 256 */
                const int ec = abs((int8_t)(uint8_t)(mote_img[4 * p + c] - ref_img[4 * p + c]));
                e = ec > e ? ec : e;
            }
            off[p < W * H / 2][e < 2 ? e : 2]++;
            worst = e > worst ? e : worst;
        }
        printf("%5.0f repeats: texels off by 0 / 1 / more: lower half %ld / %ld / %ld, upper half %ld / %ld / %ld"
               "%s\n", repeats[i], off[0][0], off[0][1], off[0][2], off[1][0], off[1][1], off[1][2],
               repeats[i] <= 100 ? "" : " (not held)");
        snprintf(msg, sizeof msg, "%g repeats: a texel off by %d", repeats[i], worst);
        if (repeats[i] <= 100) {
            TEST_ASSERT_TRUE_MESSAGE(worst <= 1, msg);
        }
    }
}

/* ---- turning ---------------------------------------------------------------------- */

/* An animation that turns a mesh by multiplying its quaternion by a small
 * turn every frame, in float, lets the quaternion's length drift; mote
 * divides by the squared length (mote__quat_matrix), so a drifted
 * quaternion turns without scaling: its world matrix is within float
 * rounding of the rotation of the normalised quaternion (computed in
 * double), frame after frame. mote-render's --spin sets each frame's angle
 * afresh (spin x frame), so nothing accumulates there. */
void a_quaternion_turned_frame_after_frame_should_not_scale_its_mesh(void)
{
    const double a = 0.013, ax[3] = {0.36, 0.48, 0.8};   /* a unit axis */
    const float dq[4] = {(float)(ax[0] * sin(a / 2)), (float)(ax[1] * sin(a / 2)), (float)(ax[2] * sin(a / 2)),
                         (float)cos(a / 2)};
    float q[4] = {0, 0, 0, 1};
    double worst = 0.0, drift = 0.0;
    for (int frame = 1; frame <= 200000; frame++) {
        const float p[4] = {q[0], q[1], q[2], q[3]};   /* q = dq p (x, y, z, w) */
        q[0] = dq[3] * p[0] + dq[0] * p[3] + dq[1] * p[2] - dq[2] * p[1];
        q[1] = dq[3] * p[1] - dq[0] * p[2] + dq[1] * p[3] + dq[2] * p[0];
        q[2] = dq[3] * p[2] + dq[0] * p[1] - dq[1] * p[0] + dq[2] * p[3];
        q[3] = dq[3] * p[3] - dq[0] * p[0] - dq[1] * p[1] - dq[2] * p[2];
        if (frame % 20000)
            continue;
        mote_mesh m;
        memset(&m, 0, sizeof m);
        memcpy(m.rotation_quaternion, q, sizeof q);
        m.use_quaternion = true;
        float wm[16];
        mote_mesh_world_matrix(&m, wm);
        double n = sqrt((double)q[0] * q[0] + (double)q[1] * q[1] + (double)q[2] * q[2] + (double)q[3] * q[3]);
        const double x = q[0] / n, y = q[1] / n, z = q[2] / n, w = q[3] / n;
        const double rot[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w),
                               2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                               2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)};
        for (int c = 0; c < 3; c++)
            for (int r = 0; r < 3; r++)
                worst = fmax(worst, fabs(wm[c * 4 + r] - rot[c * 3 + r]));
        drift = fmax(drift, fabs(n - 1.0));
    }
    printf("200,000 frames turned by float quaternion products: length drifted by %.2e, world matrix within "
           "%.2e of the normalised turn\n", drift, worst);
    TEST_ASSERT_TRUE(drift > 1e-5);        /* the drift is real... */
    TEST_ASSERT_TRUE(worst < 1e-6);        /* ...and does not scale the mesh */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(a_scene_far_from_the_origin_should_render_as_at_the_origin);
    RUN_TEST(the_camera_should_keep_its_axes_for_vectors_of_any_length);
    RUN_TEST(tiny_and_huge_scenes_should_render_as_at_unit_scale);
    RUN_TEST(the_depth_buffer_should_resolve_surfaces_a_few_steps_apart);
    RUN_TEST(narrow_fields_of_view_should_stay_within_the_float_turn);
    RUN_TEST(lighting_should_hold_up_at_extreme_values);
    RUN_TEST(texel_coordinates_far_from_zero_should_stay_within_1_lsb);
    RUN_TEST(a_large_tiled_quad_should_sample_within_a_texel_up_to_100_repeats);
    RUN_TEST(a_quaternion_turned_frame_after_frame_should_not_scale_its_mesh);
    return UNITY_END();
}
