/*
 * test_clip.c - clipping (src/core/clip.c): triangles crossing the near
 * plane, the far plane and the camera's own plane, huge coordinates
 * handled by the guard band, and the largest framebuffer and coordinate
 * range at their edges.
 *
 * Whole scenes are compared with the double-precision reference pipeline
 * (tests/ref), which clips in homogeneous space on its own. mote's float
 * vertex stage may snap a vertex one grid step away from the reference's
 * double one, so coverage may differ along edges; the thresholds are:
 *   - 0 mismatched pixels that are not next to a reference edge (a wrapped
 *     or exploded triangle would leave many),
 *   - coverage mismatches <= 0.5% of the pixels the reference draws,
 *   - colour within 1 LSB on >= 99.5% of the pixels both draw (smooth
 *     textures and lighting: no texel-boundary flips).
 * The fixed-size cases use the triangle hook and must match exactly.
 */
#include "ref/ref.h"
#include "support/scenes.h"
#include "support/testutil.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 96
#define H 64

static char msg[512];
static uint8_t gradient[32 * 32 * 4];
static mote_texture grad_tex = {32, 32, MOTE_FORMAT_RGBA8888, 32 * 4, gradient};

void setUp(void)
{
    /* smooth in both directions; mirrored, so repeats stay continuous */
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++) {
            uint8_t *p = &gradient[4 * (y * 32 + x)];
            p[0] = (uint8_t)(x * 8);
            p[1] = (uint8_t)(y * 8);
            p[2] = (uint8_t)(128 + (x - y) * 2);
            p[3] = 255;
        }
}

void tearDown(void) {}

static mote_vertex quad_v[4];
static uint32_t quad_i[12] = {0, 1, 2, 0, 2, 3, 0, 2, 1, 0, 3, 2};

/* A textured quad (both sides) from four world corners. */
static mote_mesh quad(const float c[4][3])
{
    static const float uv[4][2] = {{0, 0}, {6, 0}, {6, 6}, {0, 6}};
    memset(quad_v, 0, sizeof quad_v);
    for (int i = 0; i < 4; i++) {
        memcpy(quad_v[i].position, c[i], sizeof c[i]);
        quad_v[i].normal[1] = 1;
        quad_v[i].uv[0] = uv[i][0];
        quad_v[i].uv[1] = uv[i][1];
    }
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = quad_v;
    m.vertex_count = 4;
    m.indices = quad_i;
    m.index_count = 12;
    m.material.texture = &grad_tex;
    m.material.wrap_u = m.material.wrap_v = MOTE_WRAP_MIRROR;
    return m;
}

static mote_frame_desc camera(float px, float py, float pz, float tx, float ty, float tz)
{
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    f.camera.position[0] = px;
    f.camera.position[1] = py;
    f.camera.position[2] = pz;
    f.camera.target[0] = tx;
    f.camera.target[1] = ty;
    f.camera.target[2] = tz;
    f.camera.fov = 1.0f;
    f.camera.znear = 0.1f;
    f.camera.zfar = 100.0f;
    f.light_count = 1;
    f.lights[0].type = MOTE_LIGHT_POINT;
    f.lights[0].position[1] = 3;
    f.ambient[0] = f.ambient[1] = f.ambient[2] = 0.2f;
    return f;
}

static tu_vs_result check_scene(const char *what, const mote_frame_desc *f, const mote_mesh *m, int n,
                                const mote_draw_desc *d)
{
    tu_vs_opts o = {W, H, 8, MOTE_DEPTH_FORMAT_DEFAULT};
    tu_vs_result r;
    TEST_ASSERT_TRUE_MESSAGE(tu_vs_ref(&o, f, m, n, d, true, &r, NULL, NULL), "render");
    printf("%-34s ref %5ld px, coverage mismatches %ld (%ld away from edges), max err %d, "
           "within 1 LSB %.4f%%\n", what, r.m.covered_b, r.m.coverage_mismatch, r.unexplained,
           r.m.max_err, 100.0 * r.m.within_1_fraction);
    snprintf(msg, sizeof msg, "%s: %ld coverage mismatches away from any reference edge", what, r.unexplained);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, r.unexplained, msg);
    snprintf(msg, sizeof msg, "%s: %ld coverage mismatches of %ld", what, r.m.coverage_mismatch, r.m.covered_b);
    TEST_ASSERT_TRUE_MESSAGE(r.m.coverage_mismatch * 200 <= r.m.covered_b, msg);
    snprintf(msg, sizeof msg, "%s: only %.4f%% within 1 LSB", what, 100.0 * r.m.within_1_fraction);
    TEST_ASSERT_TRUE_MESSAGE(r.m.within_1_fraction >= 0.995, msg);
    return r;
}

static mote_draw_desc desc(mote_mode mode, bool unlit)
{
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.mode = mode;
    d.unlit = unlit;
    d.filter = MOTE_FILTER_BILINEAR;
    d.cull = MOTE_CULL_NONE;
    return d;
}

void a_floor_through_the_near_and_camera_planes_should_match_the_reference(void)
{
    /* the floor runs from behind the camera to far ahead */
    const float c[4][3] = {{-40, -1, -40}, {40, -1, -40}, {40, -1, 40}, {-40, -1, 40}};
    mote_mesh m = quad(c);
    mote_frame_desc f = camera(0, 0, 0, 0, -0.3f, 1);
    mote_draw_desc d = desc(MOTE_MODE_TEXTURED, true);
    tu_vs_result r = check_scene("floor, textured", &f, &m, 1, &d);
    TEST_ASSERT_TRUE(r.m.covered_b > W * H / 3);
    d = desc(MOTE_MODE_GOURAUD, false);
    check_scene("floor, Gouraud", &f, &m, 1, &d);
}

void a_floor_should_cover_below_the_horizon_and_nothing_above_it(void)
{
    const float c[4][3] = {{-400, -1, -400}, {400, -1, -400}, {400, -1, 400}, {-400, -1, 400}};
    mote_mesh m = quad(c);
    mote_frame_desc f = camera(0, 0, 0, 0, 0, 1);   /* level: horizon at mid-height */
    f.camera.zfar = 1000;
    mote_draw_desc d = desc(MOTE_MODE_FLAT, true);
    static uint8_t img[W * H * 4];
    tu_vs_opts o = {W, H, 8, MOTE_DEPTH_FORMAT_DEFAULT};
    tu_vs_result r;
    TEST_ASSERT_TRUE(tu_vs_ref(&o, &f, &m, 1, &d, true, &r, img, NULL));
    TEST_ASSERT_EQUAL_INT(0, r.unexplained);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            bool drawn = img[4 * (y * W + x)] != 0;
            /* the floor's far edge is at 400 units: it ends a pixel or two below the horizon */
            if ((y < H / 2 && drawn) || (y >= H / 2 + 2 && !drawn)) {
                snprintf(msg, sizeof msg, "pixel (%d,%d) %s", x, y, drawn ? "drawn above the horizon" : "hole below it");
                TEST_FAIL_MESSAGE(msg);
            }
        }
}

void triangles_with_vertices_behind_the_camera_should_match_the_reference(void)
{
    tu_rng g = tu_rng_seed(7);
    static mote_vertex v[3 * 64];
    static uint32_t idx[3 * 64];
    for (int rep = 0; rep < 4; rep++) {
        int n = 0;
        for (int t = 0; t < 64; t++) {
            /* one or two vertices behind the camera (z <= 0), some exactly on its plane */
            int behind = (int)tu_rand_int(&g, 1, 2);
            for (int k = 0; k < 3; k++) {
                mote_vertex *p = &v[n];
                memset(p, 0, sizeof *p);
                p->position[0] = (float)tu_rand_range(&g, -6, 6);
                p->position[1] = (float)tu_rand_range(&g, -4, 4);
                p->position[2] = k < behind ? (t % 5 == 0 ? 0.0f : (float)tu_rand_range(&g, -8, 0))
                                            : (float)tu_rand_range(&g, 1, 12);
                p->normal[2] = -1;
                p->uv[0] = (float)tu_rand_range(&g, 0, 2);
                p->uv[1] = (float)tu_rand_range(&g, 0, 2);
                idx[n] = (uint32_t)n;
                n++;
            }
        }
        mote_mesh m;
        memset(&m, 0, sizeof m);
        m.vertices = v;
        m.vertex_count = (uint32_t)n;
        m.indices = idx;
        m.index_count = (uint32_t)n;
        m.material.texture = &grad_tex;
        m.material.wrap_u = m.material.wrap_v = MOTE_WRAP_MIRROR;
        mote_frame_desc f = camera(0, 0, 0, 0, 0, 1);
        f.lights[0].position[2] = -2;
        mote_draw_desc d = desc(rep % 2 ? MOTE_MODE_TEXTURED : MOTE_MODE_GOURAUD, false);
        char what[64];
        snprintf(what, sizeof what, "behind the camera, set %d", rep);
        check_scene(what, &f, &m, 1, &d);
    }
}

void a_strip_beyond_the_far_plane_should_be_cut_there(void)
{
    const float c[4][3] = {{-2, -1, 2}, {2, -1, 2}, {2, -1, 300}, {-2, -1, 300}};
    mote_mesh m = quad(c);
    mote_frame_desc f = camera(0, 0.5f, 0, 0, 0, 10);
    f.camera.zfar = 40;
    mote_draw_desc d = desc(MOTE_MODE_TEXTURED, true);
    tu_vs_result cut = check_scene("strip through the far plane", &f, &m, 1, &d);
    f.camera.zfar = 1000;
    tu_vs_result whole = check_scene("the same strip, far plane beyond", &f, &m, 1, &d);
    TEST_ASSERT_TRUE(whole.m.covered_a > cut.m.covered_a);
}

void huge_coordinates_should_be_handled_by_the_guard_band(void)
{
    /* vertices far outside the viewport (up to 1e36, inside FLT_MAX/16) */
    static const float far_out[][3][3] = {
        {{-1e6f, -1e6f, 5}, {1e6f, -1e6f, 5}, {0, 1e6f, 5}},
        {{-1e30f, -1, 5}, {1e30f, -1, 5}, {0, 2, 5}},
        {{-1e36f, -1e36f, 1e36f}, {1e36f, -1e36f, 1e36f}, {0, 1e36f, 1e36f}},
        {{0, 0, 5}, {1e20f, 1, 5}, {1, 1e20f, 5}},
        {{-3, -2, 4}, {1e7f, 3e6f, 9}, {2, 5e7f, 6}},
    };
    for (size_t k = 0; k < sizeof far_out / sizeof far_out[0]; k++) {
        static mote_vertex v[3];
        static uint32_t idx[3] = {0, 1, 2};
        memset(v, 0, sizeof v);
        for (int i = 0; i < 3; i++) {
            memcpy(v[i].position, far_out[k][i], sizeof v[i].position);
            v[i].normal[2] = -1;
        }
        mote_mesh m;
        memset(&m, 0, sizeof m);
        m.vertices = v;
        m.vertex_count = 3;
        m.indices = idx;
        m.index_count = 3;
        mote_frame_desc f = camera(0, 0, 0, 0, 0, 1);
        f.camera.zfar = 1e37f;
        f.lights[0].position[2] = -3;
        /* unlit: this is about clipping (mote's float lighting overflows
         * at 1e36 units, see test_accuracy) */
        mote_draw_desc d = desc(MOTE_MODE_FLAT, true);
        /* at 1e36 units z/w rounds to the far plane in 24 bits: not what this tests */
        d.no_depth_test = true;
        char what[64];
        snprintf(what, sizeof what, "huge triangle %zu", k);
#if MOTE_FIXED_VERTEX
        /* the integer stage holds a mesh's vertices to 24 bits across it:
         * a triangle 1e30 wide keeps no detail near the viewport
         * (docs/accuracy.md); drawn all the same (the sanitizers watch) */
        tu_vs_opts o = {W, H, 8, MOTE_DEPTH_FORMAT_DEFAULT};
        tu_vs_result r;
        TEST_ASSERT_TRUE_MESSAGE(tu_vs_ref(&o, &f, &m, 1, &d, true, &r, NULL, NULL), what);
#else
        tu_vs_result r = check_scene(what, &f, &m, 1, &d);
        TEST_ASSERT_TRUE_MESSAGE(r.m.covered_b > 0, what);
#endif
    }
#if MOTE_FIXED_VERTEX
    TEST_IGNORE_MESSAGE("drawn, not compared: beyond the integer vertex stage's range");
#endif
}

/* One triangle around the whole viewport, its vertices 1e4 to 1e20 pixels
 * away (far inside FLT_MAX/16 in clip space), at random turns and w: every
 * pixel is drawn. Clipping against the guard band from that far out once
 * missed the planes by more than the band (float interpolation), and from
 * about 3e10 pixels on such triangles were dropped whole. */
void a_triangle_around_the_viewport_should_cover_it_at_any_size(void)
{
    enum { SW = 61, SH = 47 };
    static uint8_t cov[SW * SH];
    tu_screen s;
    TEST_ASSERT_TRUE(tu_screen_init(&s, SW, SH, 8, false));
    tu_rng g = tu_rng_seed(404);
    for (int e = 4; e <= 20; e++)
        for (int k = 0; k < 40; k++) {
            double r = pow(10.0, e + tu_rand01(&g)), turn = tu_rand_range(&g, 0.0, 6.283185307179586);
            double sx[3], sy[3], w[3];
            for (int i = 0; i < 3; i++) {
                sx[i] = SW / 2.0 + r * cos(turn + i * 2.0943951023931957);
                sy[i] = SH / 2.0 + r * sin(turn + i * 2.0943951023931957);
                w[i] = k % 2 ? tu_rand_range(&g, 0.1, 4.0) : 1.0;
            }
            TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw(&s, sx, sy, w, 1));
            if (MOTE_FIXED_VERTEX)    /* drawn, not compared, as above */
                continue;
            tu_screen_coverage(&s, cov);
            int drawn = 0;
            for (int i = 0; i < SW * SH; i++)
                drawn += cov[i];
            snprintf(msg, sizeof msg, "radius %.3g px, turn %.3f: %d of %d pixels drawn", r, turn, drawn,
                     SW * SH);
            TEST_ASSERT_EQUAL_INT_MESSAGE(SW * SH, drawn, msg);
        }
    tu_screen_free(&s);
#if MOTE_FIXED_VERTEX
    TEST_IGNORE_MESSAGE("drawn, not compared: beyond the integer vertex stage's range");
#endif
}

/* ---- the largest framebuffer and coordinate range ---------------------------- */

static bool screen_matches_reference(tu_screen *s, uint8_t *cov, uint8_t *ref, long *count)
{
    size_t n = (size_t)s->width * (size_t)s->height;
    tu_screen_coverage(s, cov);
    memset(ref, 0, n);
    for (size_t i = 0; i < s->cap.count; i++)
        ref_cover(s->cap.tris[i].X, s->cap.tris[i].Y, s->subpixel_bits, s->width, s->height, ref);
    *count = 0;
    for (size_t i = 0; i < n; i++) {
        *count += cov[i] != 0;
        if (cov[i] != (ref[i] != 0)) {   /* the triangles of one draw may overlap */
            snprintf(msg, sizeof msg, "%dx%d: pixel (%zu,%zu) mote %d reference %d", s->width, s->height,
                     i % (size_t)s->width, i / (size_t)s->width, cov[i], ref[i]);
            return false;
        }
    }
    return true;
}

void the_largest_framebuffer_should_be_drawn_exactly_to_its_edges(void)
{
    static const int sizes[][2] = {{MOTE_MAX_SIZE, MOTE_MAX_SIZE}, {MOTE_MAX_SIZE, 1}, {1, MOTE_MAX_SIZE}};
    for (size_t k = 0; k < 3; k++) {
        int w = sizes[k][0], h = sizes[k][1];
        for (int F = 4; F <= 8; F += 4) {
            tu_screen s;
            TEST_ASSERT_TRUE(tu_screen_init(&s, w, h, F, false));
            size_t n = (size_t)w * (size_t)h;
            uint8_t *cov = (uint8_t *)malloc(n), *ref = (uint8_t *)malloc(n);
            TEST_ASSERT_NOT_NULL(cov);
            TEST_ASSERT_NOT_NULL(ref);
            long count;
            /* the whole framebuffer as two triangles: every pixel once */
            double sx[6] = {0, w, w, 0, w, 0}, sy[6] = {0, 0, h, 0, h, h};
            TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw(&s, sx, sy, NULL, 2));
            TEST_ASSERT_TRUE_MESSAGE(screen_matches_reference(&s, cov, ref, &count), msg);
            TEST_ASSERT_EQUAL_INT64((int64_t)n, (int64_t)count);
            /* a triangle reaching to the guard band on every side */
            double g = (double)(1 << MOTE_GUARD_BITS);
            double gx[3] = {w / 2.0 - g, w / 2.0 + g, w / 2.0}, gy[3] = {h / 2.0 - g + 1, h / 2.0 - g + 1, h / 2.0 + g};
            TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw(&s, gx, gy, NULL, 1));
            TEST_ASSERT_TRUE_MESSAGE(screen_matches_reference(&s, cov, ref, &count), msg);
            TEST_ASSERT_TRUE(count > 0);
            /* and beyond it (clipped), with thin slivers along the last row and column */
            double bx[9] = {-3 * g, 5 * g, w - 0.5, w - 1 + 0.25, w - 0.25, w - 0.5, 0, w, 0};
            double by[9] = {h - 0.5, h - 0.5, -3 * g, 0, h, h - 1 + 0.5, h - 0.75, h - 0.25, h - 0.125};
            TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw(&s, bx, by, NULL, 3));
            TEST_ASSERT_TRUE_MESSAGE(screen_matches_reference(&s, cov, ref, &count), msg);
            free(cov);
            free(ref);
            tu_screen_free(&s);
        }
    }
}

/* Clipping's float rounding can leave a polygon a hair from convex, and
 * the last plane then cut it more than twice: this triangle (found by a
 * random search; near the near plane, past the far one, reaching to the
 * guard band) came out of the six planes with 10 vertices, one more than
 * the clipper's arrays hold, which it wrote past (ASan, SAN=1) and then
 * fanned into 8 triangles. At most 9 vertices, 7 triangles, remain. */
void a_polygon_cut_more_than_twice_by_a_plane_should_stay_in_its_arrays(void)
{
    enum { CW = 64, CH = 48 };
    static uint8_t color[CW * CH * 4];
    static uint32_t depth[CW * CH];
    mote_device dev;
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = CW;
    d.height = CH;
    d.color = color;
    d.depth = depth;
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_device_init(&dev, &d));
    mote_frame_desc f = camera(0, 0, 0, 0, 0, 1);
    f.camera.fov = 0.8f;
    f.camera.znear = 0x1.3f9608p-5f;
    f.camera.zfar = 0x1.dc451p+4f;
    static const float p[3][3] = {{0x1.68511p+2f, -0x1.685112p+2f, 0x1.3f95fcp-5f},
                                  {0x1.6131fap+12f, 0x1.fb5a54p+12f, 0x1.3944eap+5f},
                                  {-0x1.552fc8p+12f, -0x1.2e752p+10f, 0x1.a36e52p+4f}};
    static mote_vertex v[3];
    static const uint32_t idx[3] = {0, 1, 2};
    memset(v, 0, sizeof v);
    for (int k = 0; k < 3; k++)
        memcpy(v[k].position, p[k], sizeof p[k]);
    mote_mesh m = tu_mesh_of(v, 3, idx, 3);
    mote_draw_desc dd = desc(MOTE_MODE_GOURAUD, true);
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_begin(&dev, &f));
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_draw(&dev, &m, &dd));
    TEST_ASSERT_EQUAL_INT(MOTE_OK, mote_end(&dev));
    const mote_stats *s = mote_device_stats(&dev);
    uint32_t fan = s->triangles_clipped_away + s->triangles_degenerate + s->triangles_backface
                 + s->triangles_drawn + s->triangles_invalid;
    TEST_ASSERT_TRUE(fan >= 1);
    TEST_ASSERT_TRUE(fan <= 7);
    TEST_ASSERT_EQUAL_UINT64(CW * CH, s->pixels_written);   /* it covers the screen */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(a_floor_through_the_near_and_camera_planes_should_match_the_reference);
    RUN_TEST(a_floor_should_cover_below_the_horizon_and_nothing_above_it);
    RUN_TEST(triangles_with_vertices_behind_the_camera_should_match_the_reference);
    RUN_TEST(a_strip_beyond_the_far_plane_should_be_cut_there);
    RUN_TEST(huge_coordinates_should_be_handled_by_the_guard_band);
    RUN_TEST(a_triangle_around_the_viewport_should_cover_it_at_any_size);
    RUN_TEST(the_largest_framebuffer_should_be_drawn_exactly_to_its_edges);
    RUN_TEST(a_polygon_cut_more_than_twice_by_a_plane_should_stay_in_its_arrays);
    return UNITY_END();
}
