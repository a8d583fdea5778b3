/*
 * test_raster_rules.c - coverage: mote against the reference's exact
 * per-pixel centre test, watertightness with a per-pixel hit counter, and
 * the exact cases of piglit and dEQP (see docs/accuracy.md).
 *
 * Thresholds (all seeded, reproducible): 0 mismatched pixels against the
 * reference over 100,000 random triangles per sub-pixel precision (4 and 8
 * bits) on a 64x64 viewport; 0 double hits and 0 holes in every watertight
 * case; bit-exact coverage for the grid-aligned piglit cases.
 *
 * Triangles are placed with tu_screen (camera at the origin, so a vertex
 * lands where asked); the snapped vertices mote actually rasterised come
 * from the device's triangle hook, and the reference covers exactly those.
 * Where the positions are on the sub-pixel grid, the test also checks that
 * mote snapped them where they were put.
 */
#include "ref/ref.h"
#include "support/testutil.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 64

static tu_screen scr;
static uint8_t got[W * H], want[W * H];
static char msg[512];

void setUp(void) {}
void tearDown(void) { tu_screen_free(&scr); }

static void screen(int w, int h, int bits)
{
    tu_screen_free(&scr);
    TEST_ASSERT_TRUE_MESSAGE(tu_screen_init(&scr, w, h, bits, false), "device init");
}

static void describe_tri(char *out, size_t size, const tu_tri *t, int F)
{
    snprintf(out, size, "(%d,%d) (%d,%d) (%d,%d) [1/%d px]", t->X[0], t->Y[0], t->X[1], t->Y[1],
             t->X[2], t->Y[2], 1 << F);
}

/* Reference coverage of everything mote hooked in the last draw. */
static void ref_of_capture(uint8_t *out)
{
    memset(out, 0, (size_t)scr.width * (size_t)scr.height);
    for (size_t i = 0; i < scr.cap.count; i++)
        ref_cover(scr.cap.tris[i].X, scr.cap.tris[i].Y, scr.subpixel_bits, scr.width, scr.height, out);
}

/* First pixel where a and b differ, or -1. */
static long first_diff(const uint8_t *a, const uint8_t *b, long n)
{
    for (long i = 0; i < n; i++)
        if (a[i] != b[i])
            return i;
    return -1;
}

/* Draws one triangle given in pixels; compares mote's pixels with the
 * reference over the hooked triangles. Returns false with msg set. */
static bool one_triangle_matches(const double sx[3], const double sy[3], const double w[3])
{
    mote_result r = tu_screen_draw(&scr, sx, sy, w, 1);
    if (r != MOTE_OK) {
        snprintf(msg, sizeof msg, "mote_draw: %s", mote_result_string(r));
        return false;
    }
    tu_screen_coverage(&scr, got);
    ref_of_capture(want);
    long n = (long)scr.width * scr.height;
    long i = first_diff(got, want, n);
    if (i < 0)
        return true;
    char tri[160] = "(no triangle reached the rasteriser)";
    if (scr.cap.count)
        describe_tri(tri, sizeof tri, &scr.cap.tris[0], scr.subpixel_bits);
    snprintf(msg, sizeof msg, "pixel (%ld,%ld): reference %s, mote %s; triangle %s of %zu hooked; "
             "input px (%.6f,%.6f) (%.6f,%.6f) (%.6f,%.6f)",
             i % scr.width, i / scr.width, want[i] ? "covers" : "does not cover",
             got[i] ? "drew it" : "did not", tri, scr.cap.count, sx[0], sy[0], sx[1], sy[1], sx[2], sy[2]);
    return false;
}

/* ---- random triangles of every shape ------------------------------------- */

enum { K_GENERAL, K_SLIVER, K_NEEDLE, K_HUGE, K_SUBPIXEL, K_AXIS, K_CENTRES, K_KINDS };

/* A random triangle of a kind, on the sub-pixel grid (fixed point). */
static void random_tri(tu_rng *g, int kind, int F, int64_t X[3], int64_t Y[3])
{
    const int64_t one = (int64_t)1 << F;
    switch (kind) {
    case K_SLIVER: {            /* third vertex within a few grid steps of the line */
        for (int i = 0; i < 2; i++) {
            X[i] = tu_rand_int(g, -8 * one, (W + 8) * one);
            Y[i] = tu_rand_int(g, -8 * one, (H + 8) * one);
        }
        double t = tu_rand01(g);
        X[2] = (int64_t)llround(X[0] + t * (double)(X[1] - X[0])) + tu_rand_int(g, -2, 2);
        Y[2] = (int64_t)llround(Y[0] + t * (double)(Y[1] - Y[0])) + tu_rand_int(g, -2, 2);
        break;
    }
    case K_NEEDLE: {            /* long and at most a pixel or two wide */
        double a = tu_rand_range(g, 0, 6.283185307179586), len = tu_rand_range(g, 20, 120);
        double cx = tu_rand_range(g, 0, W), cy = tu_rand_range(g, 0, H);
        double dx = cos(a) * len / 2, dy = sin(a) * len / 2, wid = tu_rand_range(g, 0, 2);
        X[0] = llround((cx - dx) * one);
        Y[0] = llround((cy - dy) * one);
        X[1] = llround((cx + dx) * one);
        Y[1] = llround((cy + dy) * one);
        X[2] = llround((cx + dx + (-sin(a)) * wid) * one);
        Y[2] = llround((cy + dy + cos(a) * wid) * one);
        break;
    }
    case K_HUGE:                /* up to and beyond the guard band (clipped) */
        for (int i = 0; i < 3; i++) {
            X[i] = tu_rand_int(g, -12000 * one, 12000 * one);
            Y[i] = tu_rand_int(g, -12000 * one, 12000 * one);
        }
        break;
    case K_SUBPIXEL: {          /* inside a box of at most 2 pixels */
        int64_t bx = tu_rand_int(g, 0, W * one), by = tu_rand_int(g, 0, H * one);
        int64_t s = tu_rand_int(g, 1, 2 * one);
        for (int i = 0; i < 3; i++) {
            X[i] = bx + tu_rand_int(g, 0, s);
            Y[i] = by + tu_rand_int(g, 0, s);
        }
        break;
    }
    case K_AXIS: {              /* right angle, edges through pixel centres half the time */
        int64_t half = tu_rand_int(g, 0, 1) ? one / 2 : 0;
        int64_t x0 = tu_rand_int(g, -4, W + 4) * one + half, y0 = tu_rand_int(g, -4, H + 4) * one + half;
        int64_t x1 = tu_rand_int(g, -4, W + 4) * one + half, y1 = tu_rand_int(g, -4, H + 4) * one + half;
        if (tu_rand_int(g, 0, 3) == 0) {  /* and at random grid points otherwise */
            x1 += tu_rand_int(g, 0, one - 1);
            y1 += tu_rand_int(g, 0, one - 1);
        }
        int corner = (int)tu_rand_int(g, 0, 3);
        X[0] = x0; Y[0] = y0;
        X[1] = x1; Y[1] = y0;
        X[2] = corner & 1 ? x1 : x0;
        Y[2] = y1;
        if (corner & 2) {       /* the other orientation */
            X[1] = x0; Y[1] = y1;
            X[2] = x1; Y[2] = corner & 1 ? y0 : y1;
        }
        break;
    }
    case K_CENTRES:             /* vertices on pixel centres: many samples exactly on edges */
        for (int i = 0; i < 3; i++) {
            X[i] = tu_rand_int(g, -2, W + 2) * one + one / 2;
            Y[i] = tu_rand_int(g, -2, H + 2) * one + one / 2;
        }
        break;
    default:
        for (int i = 0; i < 3; i++) {
            X[i] = tu_rand_int(g, -16 * one, (W + 16) * one);
            Y[i] = tu_rand_int(g, -16 * one, (H + 16) * one);
        }
        break;
    }
}

static void random_triangles_match_the_reference(int F, uint64_t seed)
{
    screen(W, H, F);
    tu_rng g = tu_rng_seed(seed);
    const long count = 100000;
    long snapped_elsewhere = 0, drawn = 0;
    for (long k = 0; k < count; k++) {
        int kind = (int)(k % K_KINDS);
        int64_t X[3], Y[3];
        random_tri(&g, kind, F, X, Y);
        double sx[3], sy[3], w[3];
        bool persp = tu_rand_int(&g, 0, 1);
        for (int i = 0; i < 3; i++) {
            sx[i] = tu_grid(&scr, X[i]);
            sy[i] = tu_grid(&scr, Y[i]);
            w[i] = persp ? tu_rand_range(&g, 0.1, 4.0) : 1.0;
        }
        if (!one_triangle_matches(sx, sy, w)) {
            char full[700];
            snprintf(full, sizeof full, "F=%d triangle #%ld (kind %d): %s", F, k, kind, msg);
            TEST_FAIL_MESSAGE(full);
        }
        drawn += scr.cap.count > 0;
        /* away from the guard band the float vertex stage is exact to well
         * under half a grid step: mote must snap where the test put it */
        if (kind != K_HUGE && scr.cap.count == 1) {
            const tu_tri *t = &scr.cap.tris[0];
            for (int i = 0; i < 3; i++)
                if (t->X[i] != X[i] || t->Y[i] != Y[i])
                    snapped_elsewhere++;
        }
    }
    printf("F=%d: %ld random triangles, %ld reached the rasteriser, 0 coverage mismatches\n", F,
           count, drawn);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, snapped_elsewhere, "vertices not snapped where placed");
    TEST_ASSERT_TRUE(drawn > count / 2);
}

void coverage_should_equal_the_reference_on_100000_random_triangles_at_8_subpixel_bits(void)
{
    random_triangles_match_the_reference(8, 0x5eed0008u);
}

void coverage_should_equal_the_reference_on_100000_random_triangles_at_4_subpixel_bits(void)
{
    random_triangles_match_the_reference(4, 0x5eed0004u);
}

/* ---- per-pixel hit counting ------------------------------------------------- */

static uint8_t hits[W * H * 4], refhits[W * H * 4];

/* Draws each triangle of a mesh in a frame of its own and adds its pixels to
 * hits (and the reference's, over the hooked triangles, to refhits).
 * front/back (optional) count pixels of clockwise / counter-clockwise
 * snapped triangles separately. */
static void count_hits(const mote_mesh *mesh, const mote_draw_desc *d, int *front, int *back)
{
    long n = (long)scr.width * scr.height;
    memset(hits, 0, (size_t)n);
    memset(refhits, 0, (size_t)n);
    if (front)
        memset(front, 0, (size_t)n * sizeof *front);
    if (back)
        memset(back, 0, (size_t)n * sizeof *back);
    mote_mesh one = *mesh;
    one.index_count = 3;
    for (uint32_t t = 0; t + 3 <= mesh->index_count; t += 3) {
        one.indices = mesh->indices + t;
        TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw_mesh(&scr, &one, d));
        tu_screen_coverage(&scr, got);
        ref_of_capture(want);
        bool cw = false;
        if (scr.cap.count) {
            const tu_tri *h = &scr.cap.tris[0];
            int64_t a = ((int64_t)h->X[1] - h->X[0]) * ((int64_t)h->Y[2] - h->Y[0])
                      - ((int64_t)h->Y[1] - h->Y[0]) * ((int64_t)h->X[2] - h->X[0]);
            cw = a > 0;
        }
        for (long i = 0; i < n; i++) {
            if (got[i] && hits[i] < 255)
                hits[i]++;
            if (want[i] && refhits[i] < 255)
                refhits[i]++;
            if (got[i] && cw && front)
                front[i]++;
            if (got[i] && !cw && back)
                back[i]++;
        }
    }
}

static void assert_hits_equal_reference(const char *what)
{
    long n = (long)scr.width * scr.height, i = first_diff(hits, refhits, n);
    if (i >= 0) {
        snprintf(msg, sizeof msg, "%s: pixel (%ld,%ld) hit %d times, reference %d", what,
                 i % scr.width, i / scr.width, hits[i], refhits[i]);
        TEST_FAIL_MESSAGE(msg);
    }
}

/* A mesh whose vertices are given in screen pixels (shared by index). */
typedef struct smesh {
    mote_vertex v[512];
    uint32_t idx[3 * 1024];
    int nv, ni;
} smesh;

static smesh sm;

static int sm_vertex(double sx, double sy, double w)
{
    memset(&sm.v[sm.nv], 0, sizeof sm.v[sm.nv]);
    tu_screen_vertex(&scr, sx, sy, w, sm.v[sm.nv].position);
    return sm.nv++;
}

static void sm_tri(int a, int b, int c)
{
    sm.idx[sm.ni++] = (uint32_t)a;
    sm.idx[sm.ni++] = (uint32_t)b;
    sm.idx[sm.ni++] = (uint32_t)c;
}

static mote_mesh sm_mesh(void)
{
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = sm.v;
    m.vertex_count = (uint32_t)sm.nv;
    m.indices = sm.idx;
    m.index_count = (uint32_t)sm.ni;
    return m;
}

/* Strictly inside a polygon of snapped points (any winding), exactly. */
static bool poly_contains_strictly(const int64_t *px, const int64_t *py, int n, int64_t x, int64_t y)
{
    int wind = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        int64_t c = (px[j] - px[i]) * (y - py[i]) - (py[j] - py[i]) * (x - px[i]);
        bool between = (x >= (px[i] < px[j] ? px[i] : px[j])) && (x <= (px[i] > px[j] ? px[i] : px[j]))
                    && (y >= (py[i] < py[j] ? py[i] : py[j])) && (y <= (py[i] > py[j] ? py[i] : py[j]));
        if (c == 0 && between)
            return false;       /* on the boundary */
        if (py[i] <= y) {
            if (py[j] > y && c > 0)
                wind++;
        } else if (py[j] <= y && c < 0) {
            wind--;
        }
    }
    return wind != 0;
}

/* dEQP fill_rules: a 4x4 grid of rotated two-triangle quads sharing edges. */
static void quad_grid(int F, uint64_t seed, bool reverse, bool projected)
{
    screen(W, H, F);
    tu_rng g = tu_rng_seed(seed);
    for (int rep = 0; rep < 8; rep++) {
        sm.nv = sm.ni = 0;
        double a = tu_rand_range(&g, 0, 6.283185307179586), size = tu_rand_range(&g, 10, 17);
        double cx = W / 2.0 + tu_rand_range(&g, -2, 2), cy = H / 2.0 + tu_rand_range(&g, -2, 2);
        int id[5][5];
        for (int j = 0; j < 5; j++)
            for (int i = 0; i < 5; i++) {
                double u = (i - 2) * size, v = (j - 2) * size;
                double w = projected ? tu_rand_range(&g, 0.1, 4.0) : 1.0;
                /* on the grid, so that the outline below is where mote snaps it */
                double one = (double)(1 << F);
                double px = floor((cx + u * cos(a) - v * sin(a)) * one + 0.5) / one;
                double py = floor((cy + u * sin(a) + v * cos(a)) * one + 0.5) / one;
                id[j][i] = sm_vertex(px, py, w);
            }
        for (int j = 0; j < 4; j++)
            for (int i = 0; i < 4; i++) {
                int p = id[j][i], q = id[j][i + 1], r = id[j + 1][i + 1], s = id[j + 1][i];
                bool diag = tu_rand_int(&g, 0, 1);
                int t1[3] = {p, q, diag ? r : s}, t2[3] = {diag ? p : q, r, s};
                if (reverse) {
                    sm_tri(t1[0], t1[2], t1[1]);
                    sm_tri(t2[0], t2[2], t2[1]);
                } else {
                    sm_tri(t1[0], t1[1], t1[2]);
                    sm_tri(t2[0], t2[1], t2[2]);
                }
            }
        mote_mesh m = sm_mesh();
        count_hits(&m, NULL, NULL, NULL);
        assert_hits_equal_reference("quad grid");
        /* the outline: the ring of lattice points, where they were put */
        int64_t bx[16], by[16], one = (int64_t)1 << F;
        int nb = 0, ring[16][2];
        for (int i = 0; i < 4; i++) { ring[nb][0] = 0; ring[nb++][1] = i; }
        for (int j = 0; j < 4; j++) { ring[nb][0] = j; ring[nb++][1] = 4; }
        for (int i = 4; i > 0; i--) { ring[nb][0] = 4; ring[nb++][1] = i; }
        for (int j = 4; j > 0; j--) { ring[nb][0] = j; ring[nb++][1] = 0; }
        for (int k = 0; k < 16; k++) {
            const float *p = sm.v[id[ring[k][0]][ring[k][1]]].position;
            /* invert tu_screen_vertex: back to pixels, then to the grid */
            double sx = ((double)p[0] * scr.proj[0] / p[2] + 1.0) * W / 2.0;
            double sy = (1.0 - (double)p[1] * scr.proj[5] / p[2]) * H / 2.0;
            bx[k] = (int64_t)floor(sx * (double)one + 0.5);
            by[k] = (int64_t)floor(sy * (double)one + 0.5);
        }
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int c = hits[y * W + x];
                bool in = poly_contains_strictly(bx, by, 16, x * one + one / 2, y * one + one / 2);
                if (c > 1 || (in && c != 1)) {
                    snprintf(msg, sizeof msg, "quad grid rep %d: pixel (%d,%d) drawn %d times (%s)", rep,
                             x, y, c, in ? "inside" : "outside");
                    TEST_FAIL_MESSAGE(msg);
                }
            }
    }
}

void a_grid_of_rotated_quads_should_draw_every_inside_pixel_exactly_once(void)
{
    quad_grid(8, 11, false, false);
    quad_grid(4, 12, false, false);
}

void a_grid_of_rotated_quads_in_reverse_winding_should_draw_every_inside_pixel_exactly_once(void)
{
    quad_grid(8, 21, true, false);
    quad_grid(4, 22, true, false);
}

void a_projected_grid_of_quads_with_random_w_should_draw_every_inside_pixel_exactly_once(void)
{
    quad_grid(8, 31, false, true);
    quad_grid(4, 32, true, true);
}

void a_rotated_quad_larger_than_the_viewport_should_leave_no_pixel_undrawn(void)
{
    tu_rng g = tu_rng_seed(41);
    for (int rep = 0; rep < 24; rep++) {
        screen(W, H, rep % 2 ? 4 : 8);
        sm.nv = sm.ni = 0;
        double a = tu_rand_range(&g, 0, 6.283185307179586), r = tu_rand_range(&g, 50, 4000);
        int id[4];
        for (int k = 0; k < 4; k++) {
            double t = a + k * 1.5707963267948966;
            id[k] = sm_vertex(W / 2.0 + r * cos(t), H / 2.0 + r * sin(t), tu_rand_range(&g, 0.1, 4.0));
        }
        if (rep % 4 < 2) {
            sm_tri(id[0], id[1], id[2]);
            sm_tri(id[0], id[2], id[3]);
        } else {
            sm_tri(id[0], id[2], id[1]);
            sm_tri(id[0], id[3], id[2]);
        }
        mote_mesh m = sm_mesh();
        count_hits(&m, NULL, NULL, NULL);
        for (int i = 0; i < W * H; i++)
            if (hits[i] != 1) {
                snprintf(msg, sizeof msg, "rep %d (radius %.1f): pixel (%d,%d) drawn %d times", rep, r,
                         i % W, i / W, hits[i]);
                TEST_FAIL_MESSAGE(msg);
            }
    }
}

/* piglit triangle-rasterization-overdraw: a fan from an inside point to
 * points walked around a rectangle with random sub-pixel steps. */
void a_fan_with_random_subpixel_steps_around_a_rectangle_should_draw_it_exactly_once(void)
{
    tu_rng g = tu_rng_seed(51);
    for (int rep = 0; rep < 16; rep++) {
        int F = rep % 2 ? 4 : 8;
        screen(W, H, F);
        sm.nv = sm.ni = 0;
        int x0 = (int)tu_rand_int(&g, 0, 20), y0 = (int)tu_rand_int(&g, 0, 20);
        int x1 = (int)tu_rand_int(&g, 40, W), y1 = (int)tu_rand_int(&g, 40, H);
        double w = rep % 4 >= 2 ? 0 : 1;   /* 0: random w per vertex */
        int centre = sm_vertex(tu_rand_range(&g, x0 + 1, x1 - 1), tu_rand_range(&g, y0 + 1, y1 - 1),
                               w ? 1.0 : tu_rand_range(&g, 0.1, 4.0));
        /* walk the perimeter: corners always included */
        double cx[4] = {x0, x1, x1, x0}, cy[4] = {y0, y0, y1, y1};
        int first = -1, prev = -1;
        for (int side = 0; side < 4; side++) {
            double ax = cx[side], ay = cy[side], bx = cx[(side + 1) % 4], by = cy[(side + 1) % 4];
            double len = fabs(bx - ax) + fabs(by - ay), t = 0;
            while (t < len) {
                int v = sm_vertex(ax + (bx - ax) * t / len, ay + (by - ay) * t / len,
                                  w ? 1.0 : tu_rand_range(&g, 0.1, 4.0));
                if (prev >= 0)
                    sm_tri(centre, prev, v);
                else
                    first = v;
                prev = v;
                /* random sub-pixel step, on the grid */
                t += (double)tu_rand_int(&g, 1, 3 << F) / (double)(1 << F);
            }
        }
        sm_tri(centre, prev, first);
        mote_mesh m = sm_mesh();
        count_hits(&m, NULL, NULL, NULL);
        assert_hits_equal_reference("fan");
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int want_hits = x >= x0 && x < x1 && y >= y0 && y < y1;
                if (hits[y * W + x] != want_hits) {
                    snprintf(msg, sizeof msg, "fan rep %d [%d,%d)x[%d,%d): pixel (%d,%d) drawn %d times",
                             rep, x0, x1, y0, y1, x, y, hits[y * W + x]);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
    }
}

/* A jittered grid over an integer rectangle with random diagonals (the
 * jitter keeps every quad convex, so either diagonal splits it cleanly). */
void a_random_triangulation_of_a_rectangle_should_draw_it_exactly_once(void)
{
    tu_rng g = tu_rng_seed(61);
    for (int rep = 0; rep < 12; rep++) {
        int F = rep % 2 ? 4 : 8;
        screen(W, H, F);
        sm.nv = sm.ni = 0;
        const int N = 9;
        int x0 = (int)tu_rand_int(&g, 0, 8), y0 = (int)tu_rand_int(&g, 0, 8);
        int x1 = (int)tu_rand_int(&g, 56, W), y1 = (int)tu_rand_int(&g, 56, H);
        double cw = (double)(x1 - x0) / (N - 1), ch = (double)(y1 - y0) / (N - 1);
        int id[9][9];
        for (int j = 0; j < N; j++)
            for (int i = 0; i < N; i++) {
                double jx = (i == 0 || i == N - 1) ? 0 : tu_rand_range(&g, -0.25, 0.25) * cw;
                double jy = (j == 0 || j == N - 1) ? 0 : tu_rand_range(&g, -0.25, 0.25) * ch;
                id[j][i] = sm_vertex(x0 + i * cw + jx, y0 + j * ch + jy, tu_rand_range(&g, 0.1, 4.0));
            }
        for (int j = 0; j + 1 < N; j++)
            for (int i = 0; i + 1 < N; i++) {
                int p = id[j][i], q = id[j][i + 1], r = id[j + 1][i + 1], s = id[j + 1][i];
                bool flip = tu_rand_int(&g, 0, 1), rev = tu_rand_int(&g, 0, 1);
                int t[2][3] = {{p, q, flip ? r : s}, {flip ? p : q, r, s}};
                for (int k = 0; k < 2; k++) {
                    if (rev)
                        sm_tri(t[k][0], t[k][2], t[k][1]);
                    else
                        sm_tri(t[k][0], t[k][1], t[k][2]);
                }
            }
        mote_mesh m = sm_mesh();
        count_hits(&m, NULL, NULL, NULL);
        assert_hits_equal_reference("triangulation");
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int want_hits = x >= x0 && x < x1 && y >= y0 && y < y1;
                if (hits[y * W + x] != want_hits) {
                    snprintf(msg, sizeof msg, "triangulation rep %d: pixel (%d,%d) drawn %d times", rep,
                             x, y, hits[y * W + x]);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
    }
}

/* ---- closed meshes from random viewpoints --------------------------------- */

static mote_vertex sphere_v[2 + 14 * 24];
static uint32_t sphere_i[6 * 14 * 24];

static mote_mesh uv_sphere(void)
{
    const int R = 14, S = 24;    /* rings between the poles, segments */
    int nv = 0, ni = 0;
    memset(sphere_v, 0, sizeof sphere_v);
    sphere_v[nv].position[1] = 1;
    sphere_v[nv++].normal[1] = 1;
    for (int r = 0; r < R; r++)
        for (int s = 0; s < S; s++) {
            double th = 3.141592653589793 * (r + 1) / (R + 1), ph = 6.283185307179586 * s / S;
            float p[3] = {(float)(sin(th) * cos(ph)), (float)cos(th), (float)(sin(th) * sin(ph))};
            memcpy(sphere_v[nv].position, p, sizeof p);
            memcpy(sphere_v[nv++].normal, p, sizeof p);
        }
    sphere_v[nv].position[1] = -1;
    sphere_v[nv++].normal[1] = -1;
    int south = nv - 1;
#define RS(r, s) (1 + (r) * S + ((s) % S))
    /* consistently oriented (which way does not matter for these checks) */
    for (int s = 0; s < S; s++) {
        sphere_i[ni++] = 0; sphere_i[ni++] = (uint32_t)RS(0, s + 1); sphere_i[ni++] = (uint32_t)RS(0, s);
        sphere_i[ni++] = (uint32_t)south; sphere_i[ni++] = (uint32_t)RS(R - 1, s);
        sphere_i[ni++] = (uint32_t)RS(R - 1, s + 1);
    }
    for (int r = 0; r + 1 < R; r++)
        for (int s = 0; s < S; s++) {
            uint32_t a = (uint32_t)RS(r, s), b = (uint32_t)RS(r, s + 1), c = (uint32_t)RS(r + 1, s + 1),
                     d = (uint32_t)RS(r + 1, s);
            sphere_i[ni++] = a; sphere_i[ni++] = b; sphere_i[ni++] = c;
            sphere_i[ni++] = a; sphere_i[ni++] = c; sphere_i[ni++] = d;
        }
#undef RS
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = sphere_v;
    m.vertex_count = (uint32_t)nv;
    m.indices = sphere_i;
    m.index_count = (uint32_t)ni;
    return m;
}

static int front_px[W * H], back_px[W * H];

void a_closed_mesh_from_random_viewpoints_should_cover_its_silhouette_exactly_once(void)
{
    tu_rng g = tu_rng_seed(71);
    mote_mesh sphere = uv_sphere();
    for (int rep = 0; rep < 6; rep++) {
        screen(W, H, rep % 2 ? 4 : 8);
        /* random viewpoint around a squashed, rotated sphere */
        double th = tu_rand_range(&g, 0, 3.141592653589793), ph = tu_rand_range(&g, 0, 6.283185307179586);
        double dist = tu_rand_range(&g, 2.5, 6);
        mote_camera *cam = &scr.frame.camera;
        cam->position[0] = (float)(dist * sin(th) * cos(ph));
        cam->position[1] = (float)(dist * cos(th));
        cam->position[2] = (float)(dist * sin(th) * sin(ph));
        cam->target[0] = cam->target[1] = cam->target[2] = 0;
        cam->fov = 0.9f;
        sphere.scaling[0] = (float)tu_rand_range(&g, 0.6, 1.2);
        sphere.scaling[1] = (float)tu_rand_range(&g, 0.6, 1.2);
        sphere.scaling[2] = (float)tu_rand_range(&g, 0.6, 1.2);
        sphere.rotation[0] = (float)tu_rand_range(&g, 0, 6.28);
        sphere.rotation[1] = (float)tu_rand_range(&g, 0, 6.28);
        mote_draw_desc d;
        memset(&d, 0, sizeof d);
        d.mode = MOTE_MODE_FLAT;
        d.unlit = true;
        d.cull = MOTE_CULL_NONE;
        count_hits(&sphere, &d, front_px, back_px);
        assert_hits_equal_reference("sphere");
        long silhouette = 0, once = 0;
        for (int i = 0; i < W * H; i++) {
            /* a closed surface winds zero times around every sample */
            if (front_px[i] != back_px[i]) {
                snprintf(msg, sizeof msg, "view %d: pixel (%d,%d) in %d front and %d back triangles",
                         rep, i % W, i / W, front_px[i], back_px[i]);
                TEST_FAIL_MESSAGE(msg);
            }
            silhouette += hits[i] > 0;
            once += front_px[i] == 1;
        }
        /* a convex surface: front faces cover the silhouette exactly once */
        TEST_ASSERT_TRUE(silhouette > 100);
        TEST_ASSERT_EQUAL_INT(silhouette, once);
    }
}

/* ---- exact cases ---------------------------------------------------------- */

/* Draws a triangle given on the grid and compares with the reference on the
 * same grid coordinates (not only the hooked ones). */
static void grid_triangle_is_exact(const int64_t X[3], const int64_t Y[3], const double w[3],
                                   const char *what)
{
    double sx[3], sy[3];
    int32_t x32[3], y32[3];
    for (int i = 0; i < 3; i++) {
        sx[i] = tu_grid(&scr, X[i]);
        sy[i] = tu_grid(&scr, Y[i]);
        x32[i] = (int32_t)X[i];
        y32[i] = (int32_t)Y[i];
    }
    TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw(&scr, sx, sy, w, 1));
    tu_screen_coverage(&scr, got);
    memset(want, 0, (size_t)scr.width * scr.height);
    long n = ref_cover(x32, y32, scr.subpixel_bits, scr.width, scr.height, want);
    long i = first_diff(got, want, (long)scr.width * scr.height);
    if (i >= 0) {
        snprintf(msg, sizeof msg, "%s: (%d,%d) (%d,%d) (%d,%d) [1/%d px], %ld pixels: pixel (%ld,%ld) "
                 "reference %d mote %d", what, x32[0], y32[0], x32[1], y32[1], x32[2], y32[2],
                 1 << scr.subpixel_bits, n, i % scr.width, i / scr.width, want[i], got[i]);
        TEST_FAIL_MESSAGE(msg);
    }
}

void random_grid_triangles_of_every_size_should_match_the_integer_reference(void)
{
    tu_rng g = tu_rng_seed(81);
    for (int F = 4; F <= 8; F += 4) {
        screen(W, H, F);
        int64_t one = (int64_t)1 << F;
        for (int size = 1; size <= W; size++)
            for (int rep = 0; rep < 30; rep++) {
                int64_t X[3], Y[3];
                int64_t bx = tu_rand_int(&g, 0, (W - size) * one), by = tu_rand_int(&g, 0, (H - size) * one);
                for (int i = 0; i < 3; i++) {
                    X[i] = bx + tu_rand_int(&g, 0, size * one);
                    Y[i] = by + tu_rand_int(&g, 0, size * one);
                }
                double w[3] = {1, 1, 1};
                if (rep % 2)
                    for (int i = 0; i < 3; i++)
                        w[i] = tu_rand_range(&g, 0.1, 4.0);
                grid_triangle_is_exact(X, Y, w, "piglit random");
            }
    }
}

void tiny_diamonds_shifted_around_a_pixel_centre_should_match_the_integer_reference(void)
{
    for (int F = 4; F <= 8; F += 4) {
        screen(16, 16, F);
        int64_t one = (int64_t)1 << F, cx = 8 * one + one / 2, cy = 8 * one + one / 2;
        const int radii[] = {1, 2, 3, (int)one / 4, (int)one / 2 - 1, (int)one / 2, (int)one / 2 + 1,
                             (int)one};
        for (size_t r = 0; r < sizeof radii / sizeof radii[0]; r++)
            for (int dy = -3; dy <= 3; dy++)
                for (int dx = -3; dx <= 3; dx++) {
                    int64_t R = radii[r], x = cx + dx, y = cy + dy;
                    int64_t top[2] = {x, y - R}, right[2] = {x + R, y}, bottom[2] = {x, y + R}, left[2] = {x - R, y};
                    double w[3] = {1, 1, 1};
                    int64_t X1[3] = {top[0], right[0], bottom[0]}, Y1[3] = {top[1], right[1], bottom[1]};
                    int64_t X2[3] = {top[0], bottom[0], left[0]}, Y2[3] = {top[1], bottom[1], left[1]};
                    grid_triangle_is_exact(X1, Y1, w, "diamond right half");
                    grid_triangle_is_exact(X2, Y2, w, "diamond left half");
                    /* the whole diamond: the pixel centre is drawn iff strictly inside or on a top-left edge */
                    double sx[6], sy[6];
                    for (int i = 0; i < 3; i++) {
                        sx[i] = tu_grid(&scr, X1[i]);
                        sy[i] = tu_grid(&scr, Y1[i]);
                        sx[3 + i] = tu_grid(&scr, X2[i]);
                        sy[3 + i] = tu_grid(&scr, Y2[i]);
                    }
                    TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw(&scr, sx, sy, NULL, 2));
                    int64_t adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
                    /* centre (cx, cy) relative to the diamond centre is (-dx, -dy) */
                    int64_t l1 = adx + ady;
                    /* on the boundary: the two edges left of the diamond's
                     * centre are left edges (interior to their right), the
                     * left vertex lies only on those; the other two edges,
                     * the top and the bottom vertex are on a right edge */
                    bool expect = l1 < R || (l1 == R && -dx < 0);
                    int drawn = 0;
                    for (int i = 0; i < 16 * 16; i++)
                        drawn += scr.color[i] != 0;
                    bool centre = scr.color[8 * 16 + 8] != 0;
                    if (centre != expect) {
                        snprintf(msg, sizeof msg, "F=%d diamond radius %d at offset (%d,%d): centre %s, expected %s",
                                 F, (int)R, dx, dy, centre ? "drawn" : "not drawn", expect ? "drawn" : "not drawn");
                        TEST_FAIL_MESSAGE(msg);
                    }
                    if (R <= one / 2) {
                        TEST_ASSERT_TRUE(drawn == (int)centre);
                    }
                }
    }
}

void an_integer_rectangle_should_cover_exactly_its_pixels(void)
{
    tu_rng g = tu_rng_seed(91);
    for (int rep = 0; rep < 400; rep++) {
        screen(W, H, rep % 2 ? 4 : 8);
        int x0 = (int)tu_rand_int(&g, -10, W), x1 = (int)tu_rand_int(&g, x0 + 1, W + 10);
        int y0 = (int)tu_rand_int(&g, -10, H), y1 = (int)tu_rand_int(&g, y0 + 1, H + 10);
        double sx[6] = {x0, x1, x1, x0, x1, x0}, sy[6] = {y0, y0, y1, y0, y1, y1}, w[6];
        for (int i = 0; i < 6; i++)
            w[i] = rep % 3 ? tu_rand_range(&g, 0.1, 4.0) : 1.0;
        w[3] = w[0];
        w[4] = w[2];
        if (rep % 4 == 1) {     /* the other diagonal, reversed winding */
            double ax[6] = {x0, x0, x1, x0, x1, x1}, ay[6] = {y0, y1, y1, y0, y1, y0};
            memcpy(sx, ax, sizeof sx);
            memcpy(sy, ay, sizeof sy);
        }
        TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw(&scr, sx, sy, w, 2));
        long count = 0, outside = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                bool in = x >= x0 && x < x1 && y >= y0 && y < y1;
                bool d = scr.color[y * W + x] != 0;
                count += d;
                outside += d && !in;
            }
        int cx0 = x0 < 0 ? 0 : x0, cx1 = x1 > W ? W : x1, cy0 = y0 < 0 ? 0 : y0, cy1 = y1 > H ? H : y1;
        long expect = (long)(cx1 > cx0 ? cx1 - cx0 : 0) * (cy1 > cy0 ? cy1 - cy0 : 0);
        if (count != expect || outside) {
            snprintf(msg, sizeof msg, "[%d,%d)x[%d,%d): %ld pixels (%ld outside), expected %ld", x0, x1,
                     y0, y1, count, outside, expect);
            TEST_FAIL_MESSAGE(msg);
        }
    }
}

/* Depth (Vulkan, D3D): screen-linear z/w, converted to the buffer round to
 * nearest; and within the vertices' range at every covered pixel, also in
 * slivers whose depth gradient is far too steep to step (their depth then
 * comes from a vertex). The exact value is interpolated in double from the
 * snapped vertices mote drew and their depths at 24 bits. */
void depth_should_round_to_nearest_and_stay_within_the_vertices_range(void)
{
    tu_rng g = tu_rng_seed(55);
    enum { S = 64 };
    tu_screen_free(&scr);
    TEST_ASSERT_TRUE(tu_screen_init(&scr, S, S, 8, true));
    long pixels = 0, nearest = 0, off = 0, slivers = 0;
    for (int k = 0; k < 20000; k++) {
        bool sliver = k & 1;
        double sx[3], sy[3], w[3];
        for (int i = 0; i < 3; i++) {
            sx[i] = tu_rand_range(&g, -10, S + 10);
            sy[i] = tu_rand_range(&g, -10, S + 10);
            w[i] = tu_rand_range(&g, 0.05, 5);
        }
        if (sliver) {             /* the third vertex near the first edge */
            double t = tu_rand01(&g);
            sx[2] = sx[0] + t * (sx[1] - sx[0]) + tu_rand_range(&g, -0.05, 0.05);
            sy[2] = sy[0] + t * (sy[1] - sy[0]) + tu_rand_range(&g, -0.05, 0.05);
        }
        TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw(&scr, sx, sy, w, 1));
        if (scr.cap.count != 1)
            continue;
        slivers += sliver;
        const tu_tri *h = &scr.cap.tris[0];
        double area = (double)((int64_t)(h->X[1] - h->X[0]) * (h->Y[2] - h->Y[0])
                               - (int64_t)(h->Y[1] - h->Y[0]) * (h->X[2] - h->X[0]));
        double D[3], lo = 1e30, hi = -1e30;
        for (int i = 0; i < 3; i++) {
            D[i] = floor((double)h->z[i] * 16777215.0 + 0.5);
            lo = fmin(lo, D[i]);
            hi = fmax(hi, D[i]);
        }
        for (int y = 0; y < S; y++)
            for (int x = 0; x < S; x++) {
                if (!scr.color[y * S + x])
                    continue;
                uint32_t got_d = scr.depth[y * S + x];
                if (got_d < lo - 1 || got_d > hi + 1) {
                    snprintf(msg, sizeof msg, "triangle %d, pixel (%d,%d): depth %u outside [%.0f, %.0f]",
                             k, x, y, (unsigned)got_d, lo, hi);
                    TEST_FAIL_MESSAGE(msg);
                }
                if (sliver)
                    continue;
                int64_t px = x * 256 + 128, py = y * 256 + 128;
                double exact = 0.0;
                for (int i = 0; i < 3; i++) {
                    int a = (i + 1) % 3, b = (i + 2) % 3;
                    exact += D[i] * (double)((int64_t)(h->X[b] - h->X[a]) * (py - h->Y[a])
                                             - (int64_t)(h->Y[b] - h->Y[a]) * (px - h->X[a])) / area;
                }
                if (fabs(exact - floor(exact) - 0.5) < 0.01)
                    continue;     /* too close to a half to call */
                pixels++;
                nearest += got_d == (uint32_t)floor(exact + 0.5);
                off += fabs((double)got_d - exact) > 1.0;
            }
    }
    tu_screen_free(&scr);
    printf("depth: %ld pixels, %.4f%% rounded to nearest, %ld off by more than 1; %ld slivers in range\n",
           pixels, 100.0 * (double)nearest / (double)pixels, off, slivers);
    TEST_ASSERT_TRUE(pixels > 1000000);
    TEST_ASSERT_TRUE(slivers > 5000);
    TEST_ASSERT_EQUAL(0, off);
    TEST_ASSERT_TRUE_MESSAGE(nearest * 1000 >= pixels * 999, "depth is not rounded to nearest");
}

void moving_a_triangle_by_whole_pixels_should_move_its_coverage_exactly(void)
{
    tu_rng g = tu_rng_seed(101);
    static uint8_t base[W * H];
    for (int rep = 0; rep < 300; rep++) {
        int F = rep % 2 ? 4 : 8;
        screen(W, H, F);
        int64_t one = (int64_t)1 << F;
        int64_t X[3], Y[3];
        for (int i = 0; i < 3; i++) {
            X[i] = tu_rand_int(&g, 16 * one, 32 * one);
            Y[i] = tu_rand_int(&g, 16 * one, 32 * one);
        }
        double sx[3], sy[3], w[3];
        for (int i = 0; i < 3; i++) {
            sx[i] = tu_grid(&scr, X[i]);
            sy[i] = tu_grid(&scr, Y[i]);
            w[i] = rep % 3 ? tu_rand_range(&g, 0.1, 4.0) : 1.0;
        }
        TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw(&scr, sx, sy, w, 1));
        tu_screen_coverage(&scr, base);
        int dx = (int)tu_rand_int(&g, -16, 31), dy = (int)tu_rand_int(&g, -16, 31);
        for (int i = 0; i < 3; i++) {
            sx[i] += dx;
            sy[i] += dy;
        }
        TEST_ASSERT_EQUAL_INT(MOTE_OK, tu_screen_draw(&scr, sx, sy, w, 1));
        tu_screen_coverage(&scr, got);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int ox = x - dx, oy = y - dy;
                int was = (ox >= 0 && ox < W && oy >= 0 && oy < H) ? base[oy * W + ox] : 0;
                if (got[y * W + x] != was) {
                    snprintf(msg, sizeof msg, "moved by (%d,%d): pixel (%d,%d) %d, before at (%d,%d) %d",
                             dx, dy, x, y, got[y * W + x], ox, oy, was);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(coverage_should_equal_the_reference_on_100000_random_triangles_at_8_subpixel_bits);
    RUN_TEST(coverage_should_equal_the_reference_on_100000_random_triangles_at_4_subpixel_bits);
    RUN_TEST(a_grid_of_rotated_quads_should_draw_every_inside_pixel_exactly_once);
    RUN_TEST(a_grid_of_rotated_quads_in_reverse_winding_should_draw_every_inside_pixel_exactly_once);
    RUN_TEST(a_projected_grid_of_quads_with_random_w_should_draw_every_inside_pixel_exactly_once);
    RUN_TEST(a_rotated_quad_larger_than_the_viewport_should_leave_no_pixel_undrawn);
    RUN_TEST(a_fan_with_random_subpixel_steps_around_a_rectangle_should_draw_it_exactly_once);
    RUN_TEST(a_random_triangulation_of_a_rectangle_should_draw_it_exactly_once);
    RUN_TEST(a_closed_mesh_from_random_viewpoints_should_cover_its_silhouette_exactly_once);
    RUN_TEST(random_grid_triangles_of_every_size_should_match_the_integer_reference);
    RUN_TEST(tiny_diamonds_shifted_around_a_pixel_centre_should_match_the_integer_reference);
    RUN_TEST(an_integer_rectangle_should_cover_exactly_its_pixels);
    RUN_TEST(moving_a_triangle_by_whole_pixels_should_move_its_coverage_exactly);
    RUN_TEST(depth_should_round_to_nearest_and_stay_within_the_vertices_range);
    return UNITY_END();
}
