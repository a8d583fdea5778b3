/*
 * test_core.c - the tutorial pipeline, stage by stage: projection, lines,
 * coverage of a triangulated square, depth order, flat and Gouraud values,
 * vertex colours, texel placement, back-face culling.
 */
#include <mote/mote.h>
#include "core/internal.h"
#include "support/scenes.h"
#include "unity.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 48

static uint8_t color[W * H * 4];
static uint32_t depth[W * H];
static mote_device dev;
static mote_frame_desc frame;

void setUp(void)
{
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = W;
    d.height = H;
    d.color = color;
    d.depth = depth;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    memset(&frame, 0, sizeof frame);
    frame.camera.target[2] = 1.0f;   /* eye at the origin looking down +z */
    frame.camera.fov = 1.5707964f;   /* 90 degrees: tan(fov/2) = 1 */
    frame.camera.znear = 1.0f;
    frame.camera.zfar = 100.0f;
}

void tearDown(void) {}

/* A quad in the plane z, corners given in view space, wound counter-clockwise
 * on screen (front facing, as Babylon files are). */
static mote_vertex quad_v[4];
static uint32_t quad_i[6] = {0, 2, 1, 0, 3, 2};

static mote_mesh make_quad(float x0, float y0, float x1, float y1, float z)
{
    memset(quad_v, 0, sizeof quad_v);
    float p[4][3] = {{x0, y1, z}, {x1, y1, z}, {x1, y0, z}, {x0, y0, z}};
    float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; i++) {
        memcpy(quad_v[i].position, p[i], sizeof p[i]);
        quad_v[i].normal[2] = -1.0f;
        memcpy(quad_v[i].uv, uv[i], sizeof uv[i]);
    }
    return tu_mesh_of(quad_v, 4, quad_i, 6);
}

/* The quad that exactly fills the screen at depth z (fov 90 degrees). */
static mote_mesh screen_quad(float z)
{
    float ax = (float)W / (float)H * z;
    return make_quad(-ax, -z, ax, z, z);
}

/* One triangle over the screen's top-left half, with its corners (0,0),
 * (W,0), (0,H) in pixels, counter-clockwise on screen, at constant depth,
 * so that perspective-correct interpolation equals screen-linear there;
 * normals zero. */
static mote_vertex tri_v[3];
static const uint32_t tri_i[3] = {0, 2, 1};

static mote_mesh half_screen_triangle(void)
{
    memset(tri_v, 0, sizeof tri_v);
    float z = 5.0f, ax = (float)W / H * z;
    float p[3][3] = {{-ax, z, z}, {ax, z, z}, {-ax, -z, z}};
    for (int i = 0; i < 3; i++)
        memcpy(tri_v[i].position, p[i], sizeof p[i]);
    return tu_mesh_of(tri_v, 3, tri_i, 3);
}

/* Every third pixel of that triangle (but those near its long edge) holds,
 * within 1, 255 x the blend of the vertex values value[i][c] by the pixel
 * centre's barycentric weights, in its first `channels` channels. */
static void assert_half_screen_blends(const double value[3][3], int channels)
{
    int checked = 0;
    for (int y = 0; y < H; y += 3)
        for (int x = 0; x < W; x += 3) {
            double b[3] = {0.0, (x + 0.5) / W, (y + 0.5) / H};
            b[0] = 1.0 - b[1] - b[2];
            if (b[0] <= 0.01)
                continue;
            for (int c = 0; c < channels; c++) {
                double expect = 255.0 * (b[0] * value[0][c] + b[1] * value[1][c] + b[2] * value[2][c]);
                TEST_ASSERT_UINT8_WITHIN(1, (uint8_t)(expect + 0.5), color[4 * (y * W + x) + c]);
            }
            checked++;
        }
    TEST_ASSERT_TRUE(checked > 50);
}

void projection_should_map_known_points_to_pixels(void)
{
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    float x, y, z;
    float centre[3] = {0, 0, 5};
    TEST_ASSERT_TRUE(mote_project(&dev, centre, &x, &y, &z));
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, W / 2.0f, x);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, H / 2.0f, y);
    /* at z = 4 the top of the view is y = 4 and the right edge x = 4 * aspect */
    float top_right[3] = {4.0f * W / H, 4.0f, 4.0f};
    TEST_ASSERT_TRUE(mote_project(&dev, top_right, &x, &y, &z));
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, (float)W, x);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 0.0f, y);
    float near_pt[3] = {0, 0, 1}, far_pt[3] = {0, 0, 100};
    TEST_ASSERT_TRUE(mote_project(&dev, near_pt, &x, &y, &z));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.0f, z);
    TEST_ASSERT_TRUE(mote_project(&dev, far_pt, &x, &y, &z));
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 1.0f, z);
    float behind[3] = {0, 0, -3};
    TEST_ASSERT_FALSE(mote_project(&dev, behind, &x, &y, &z));
}

void projection_should_follow_the_left_handed_look_at(void)
{
    /* camera on +x looking back at the origin: in a left-handed world the
     * right vector is up x forward = (0,1,0) x (-1,0,0) = +z */
    frame.camera.position[0] = 10.0f;
    frame.camera.target[2] = 0.0f;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    float x, y, z, p[3] = {0, 0, 1};
    TEST_ASSERT_TRUE(mote_project(&dev, p, &x, &y, &z));
    TEST_ASSERT_TRUE(x > W / 2.0f);
}

/* pixels with some red */
static int count_lit(const uint8_t *buf, int w, int h)
{
    int n = 0;
    for (int i = 0; i < w * h; i++)
        n += buf[4 * i] != 0;
    return n;
}

/* An orthographic camera maps its box's edges to the image's edges and
 * near..far to depth 0..1, whatever the distance; a near plane behind the
 * camera's position is allowed; an empty box is 2 units high, centred. */
void orthographic_projection_should_map_its_box_to_the_image(void)
{
    frame.camera.projection = MOTE_PROJECTION_ORTHOGRAPHIC;
    const float box[4] = {-3.0f, 5.0f, -1.0f, 2.0f};   /* off centre */
    memcpy(frame.camera.ortho, box, sizeof box);
    frame.camera.znear = -2.0f;
    frame.camera.zfar = 8.0f;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    float x, y, z;
    for (int d = 0; d < 3; d++) {
        const float at = d == 0 ? -2.0f : d == 1 ? 3.0f : 8.0f;   /* near, between, far */
        float corner[3] = {-3.0f, 2.0f, at}, other[3] = {5.0f, -1.0f, at};
        TEST_ASSERT_TRUE(mote_project(&dev, corner, &x, &y, &z));
        TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.0f, x);
        TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.0f, y);
        TEST_ASSERT_FLOAT_WITHIN(1e-6f, (at + 2.0f) / 10.0f, z);
        TEST_ASSERT_TRUE(mote_project(&dev, other, &x, &y, &z));
        TEST_ASSERT_FLOAT_WITHIN(1e-4f, (float)W, x);
        TEST_ASSERT_FLOAT_WITHIN(1e-4f, (float)H, y);
    }
    float beyond[3] = {0.0f, 0.0f, 8.5f}, behind[3] = {0.0f, 0.0f, -2.5f};
    TEST_ASSERT_TRUE(mote_project(&dev, beyond, &x, &y, &z));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.05f, z);
    TEST_ASSERT_FALSE(mote_project(&dev, behind, &x, &y, &z));
    /* an empty box: 2 units high, of the image's aspect */
    frame.camera.ortho[1] = frame.camera.ortho[0];
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    float top_right[3] = {(float)W / H, 1.0f, 0.0f};
    TEST_ASSERT_TRUE(mote_project(&dev, top_right, &x, &y, &z));
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, (float)W, x);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.0f, y);
}

/* No foreshortening: the same square drawn near and far covers the same
 * pixels (perspective would shrink the far one to a quarter), and the
 * nearer one wins the depth test, also behind the camera's position. */
void orthographic_cameras_should_draw_sizes_independent_of_distance(void)
{
    frame.camera.projection = MOTE_PROJECTION_ORTHOGRAPHIC;
    const float box[4] = {-4.0f, 4.0f, -3.0f, 3.0f};   /* 64 x 48 px: 8 px a unit */
    memcpy(frame.camera.ortho, box, sizeof box);
    frame.camera.znear = -5.0f;
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.mode = MOTE_MODE_FLAT;
    d.unlit = true;
    int count[2];
    for (int k = 0; k < 2; k++) {
        TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
        mote_mesh q = make_quad(-1.0f, -1.0f, 1.5f, 2.0f, k ? 80.0f : 2.0f);
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &q, &d));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
        count[k] = count_lit(color, W, H);
    }
    TEST_ASSERT_EQUAL_INT(20 * 24, count[0]);
    TEST_ASSERT_EQUAL_INT(count[0], count[1]);
    /* behind the camera (z = -3, inside znear = -5) in front of a square
     * at z = 4 (a device without arena draws at once: quad_v is free again) */
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    mote_mesh back = make_quad(-4.0f, -3.0f, 4.0f, 3.0f, 4.0f);
    back.material.color = (mote_rgba){0, 0, 255, 255};
    back.material.color_set = true;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &back, &d));
    mote_mesh front = make_quad(-1.0f, -1.0f, 1.5f, 2.0f, -3.0f);
    front.material.color = (mote_rgba){255, 0, 0, 255};
    front.material.color_set = true;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &front, &d));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_EQUAL_INT(20 * 24, count_lit(color, W, H));
}

/* ---- lines ------------------------------------------------------------- */

void bresenham_lines_should_hit_both_endpoints_and_stay_connected(void)
{
    mote_rgba white = {255, 255, 255, 255};
    mote__counts counter = {0, 0};
    mote__target tg = {color, W * 4, NULL, W, 0, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_NONE, &counter};
    mote__rect all = {0, 0, W, H};
    srand(7);
    for (int iter = 0; iter < 500; iter++) {
        memset(color, 0, sizeof color);
        int x0 = rand() % W, y0 = rand() % H, x1 = rand() % W, y1 = rand() % H;
        mote__draw_line(&tg, all, x0, y0, x1, y1, white);
        TEST_ASSERT_EQUAL_UINT8(255, color[4 * (y0 * W + x0)]);
        TEST_ASSERT_EQUAL_UINT8(255, color[4 * (y1 * W + x1)]);
        int dx = abs(x1 - x0), dy = abs(y1 - y0);
        int major = dx > dy ? dx : dy;
        TEST_ASSERT_EQUAL_INT(major + 1, count_lit(color, W, H));
        /* every lit pixel has one per major-axis step: connected, no gaps */
        if (dx >= dy) {
            for (int x = (x0 < x1 ? x0 : x1); x <= (x0 < x1 ? x1 : x0); x++) {
                int hits = 0;
                for (int y = 0; y < H; y++)
                    hits += color[4 * (y * W + x)] != 0;
                TEST_ASSERT_EQUAL_INT(1, hits);
            }
        }
    }
}

void lines_clipped_to_a_region_should_draw_the_same_pixels_inside_it(void)
{
    static uint8_t full[W * H * 4];
    mote_rgba white = {255, 255, 255, 255};
    mote__counts counter = {0, 0};
    mote__target tg = {color, W * 4, NULL, W, 0, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_NONE, &counter};
    srand(11);
    for (int iter = 0; iter < 300; iter++) {
        /* endpoints far outside the buffer too */
        int x0 = rand() % 4000 - 2000, y0 = rand() % 4000 - 2000;
        int x1 = rand() % (3 * W) - W, y1 = rand() % (3 * H) - H;
        mote__rect all = {0, 0, W, H};
        memset(full, 0, sizeof full);
        tg.color = full;
        mote__draw_line(&tg, all, x0, y0, x1, y1, white);
        memset(color, 0, sizeof color);
        tg.color = color;
        mote__rect parts[4] = {{0, 0, W / 2, H / 2}, {W / 2, 0, W, H / 2}, {0, H / 2, W / 2, H}, {W / 2, H / 2, W, H}};
        for (int k = 0; k < 4; k++)
            mote__draw_line(&tg, parts[k], x0, y0, x1, y1, white);
        TEST_ASSERT_EQUAL_MEMORY(full, color, sizeof color);
    }
}

/* ---- coverage ------------------------------------------------------------ */

void a_triangulated_square_should_cover_every_pixel_exactly_once(void)
{
    frame.camera.zfar = 100.0f;
    mote_mesh q = screen_quad(5.0f);
    q.material.color = (mote_rgba){200, 100, 50, 255};
    q.material.color_set = true;
    mote_draw_desc dd = {0};
    dd.unlit = true;
    dd.mode = MOTE_MODE_FLAT;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &q, &dd));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    /* every pixel written once: W*H writes in total and all pixels coloured */
    TEST_ASSERT_EQUAL_UINT64((uint64_t)W * H, mote_device_stats(&dev)->pixels_written);
    for (int i = 0; i < W * H; i++) {
        TEST_ASSERT_EQUAL_UINT8(200, color[4 * i]);
        TEST_ASSERT_EQUAL_UINT8(100, color[4 * i + 1]);
    }
}

void a_random_fan_over_the_screen_should_cover_every_pixel_exactly_once(void)
{
    /* a fan of triangles around a random interior point, edges at random
     * sub-pixel positions along the border: no gaps, no double hits */
    static mote_vertex v[130];
    static uint32_t idx[128 * 3];
    srand(3);
    for (int iter = 0; iter < 20; iter++) {
        float z = 5.0f, ax = (float)W / H * z;
        memset(v, 0, sizeof v);
        v[0].position[0] = ((float)rand() / RAND_MAX - 0.5f) * ax;
        v[0].position[1] = ((float)rand() / RAND_MAX - 0.5f) * z;
        v[0].position[2] = z;
        /* border points clockwise: top edge, right, bottom, left */
        int n = 0;
        float t = 0.0f;
        while (t < 4.0f && n < 128) {
            float s = t - (float)(int)t;
            int side = (int)t;
            float x = side == 0 ? -ax + 2 * ax * s : side == 1 ? ax : side == 2 ? ax - 2 * ax * s : -ax;
            float y = side == 0 ? z : side == 1 ? z - 2 * z * s : side == 2 ? -z : -z + 2 * z * s;
            v[1 + n].position[0] = x;
            v[1 + n].position[1] = y;
            v[1 + n].position[2] = z;
            n++;
            t += 0.05f + 0.2f * (float)rand() / RAND_MAX;
            if ((int)t != side && side < 4)
                t = (float)(int)t; /* hit each corner exactly */
        }
        for (int k = 0; k < n; k++) {
            idx[3 * k] = 0;
            idx[3 * k + 1] = 1 + (uint32_t)k;
            idx[3 * k + 2] = 1 + (uint32_t)((k + 1) % n);
        }
        mote_mesh m;
        memset(&m, 0, sizeof m);
        m.vertices = v;
        m.vertex_count = (uint32_t)n + 1;
        m.indices = idx;
        m.index_count = (uint32_t)n * 3;
        mote_draw_desc dd = {0};
        dd.unlit = true;
        dd.cull = MOTE_CULL_NONE;
        dd.no_depth_test = true;
        TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &m, &dd));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
        TEST_ASSERT_EQUAL_UINT64((uint64_t)W * H, mote_device_stats(&dev)->pixels_written);
        for (int i = 0; i < W * H; i++)
            TEST_ASSERT_EQUAL_UINT8(255, color[4 * i]);
    }
}

/* ---- depth ---------------------------------------------------------------- */

static void draw_two_crossing_quads(bool reverse, uint8_t *out)
{
    static mote_vertex va[4], vb[4];
    static uint32_t ii[6] = {0, 1, 2, 0, 2, 3};
    /* A tilts from z=4 (left) to z=8 (right), B from z=8 to z=4: they cross */
    float pa[4][3] = {{-4, 3, 4}, {4, 3, 8}, {4, -3, 8}, {-4, -3, 4}};
    float pb[4][3] = {{-4, 3, 8}, {4, 3, 4}, {4, -3, 4}, {-4, -3, 8}};
    memset(va, 0, sizeof va);
    memset(vb, 0, sizeof vb);
    for (int i = 0; i < 4; i++) {
        memcpy(va[i].position, pa[i], sizeof pa[i]);
        memcpy(vb[i].position, pb[i], sizeof pb[i]);
    }
    mote_mesh a, b;
    memset(&a, 0, sizeof a);
    a.vertices = va;
    a.vertex_count = 4;
    a.indices = ii;
    a.index_count = 6;
    b = a;
    b.vertices = vb;
    a.material.color = (mote_rgba){255, 0, 0, 255};
    a.material.color_set = true;
    b.material.color = (mote_rgba){0, 0, 255, 255};
    b.material.color_set = true;
    mote_draw_desc dd = {0};
    dd.unlit = true;
    dd.cull = MOTE_CULL_NONE;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    mote_draw(&dev, reverse ? &b : &a, &dd);
    mote_draw(&dev, reverse ? &a : &b, &dd);
    mote_end(&dev);
    memcpy(out, color, sizeof color);
}

void the_depth_test_should_not_depend_on_draw_order(void)
{
    static uint8_t ab[sizeof color], ba[sizeof color];
    draw_two_crossing_quads(false, ab);
    draw_two_crossing_quads(true, ba);
    /* left half: A is nearer (red); right half: B (blue) */
    TEST_ASSERT_EQUAL_UINT8(255, ab[4 * (H / 2 * W + W / 4)]);
    TEST_ASSERT_EQUAL_UINT8(255, ab[4 * (H / 2 * W + 3 * W / 4) + 2]);
    /* the crossing column may tie; everything else must agree */
    int diff = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            if (memcmp(&ab[4 * (y * W + x)], &ba[4 * (y * W + x)], 4) != 0) {
                diff++;
                TEST_ASSERT_INT_WITHIN(1, W / 2, x);
            }
    TEST_ASSERT_TRUE(diff <= 2 * H);
}

/* The statistics count a depth-rejected pixel as tested, not written: the
 * screen quad drawn again at its own depth loses every pixel, a nearer one
 * wins every pixel (with and without an arena, flat and Gouraud). */
void depth_rejected_pixels_should_be_tested_but_not_written(void)
{
    static uint8_t arena[1 << 16];
    for (int binned = 0; binned < 2; binned++)
        for (int gouraud = 0; gouraud < 2; gouraud++) {
            mote_device_desc d = dev.desc;
            d.arena = binned ? arena : NULL;
            d.arena_size = binned ? sizeof arena : 0;
            TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
            mote_draw_desc dd = {0};
            dd.unlit = !gouraud;
            dd.mode = gouraud ? MOTE_MODE_GOURAUD : MOTE_MODE_FLAT;
            frame.light_count = 1;
            frame.lights[0].position[2] = -1.0f;
            frame.lights[0].intensity = 1.0f;
            TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
            mote_mesh far = screen_quad(5.0f);
            TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &far, &dd));
            TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &far, &dd));
            mote_mesh near = screen_quad(4.0f);
            TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &near, &dd));
            TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
            const mote_stats *st = mote_device_stats(&dev);
            TEST_ASSERT_EQUAL_UINT64(3 * (uint64_t)W * H, st->pixels_tested);
            TEST_ASSERT_EQUAL_UINT64(2 * (uint64_t)W * H, st->pixels_written);
        }
}

/* ---- lighting --------------------------------------------------------------- */

void flat_shading_should_use_the_face_normal_against_the_light(void)
{
    mote_mesh q = screen_quad(5.0f);
    frame.light_count = 1;
    frame.lights[0].type = MOTE_LIGHT_DIRECTIONAL;
    /* light travelling away from the camera, 60 degrees off the normal: n.l = 0.5 */
    frame.lights[0].direction[0] = 0.8660254f;
    frame.lights[0].direction[2] = 0.5f;
    mote_draw_desc dd = {0};
    dd.mode = MOTE_MODE_FLAT;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    mote_draw(&dev, &q, &dd);
    mote_end(&dev);
    /* 0.5 * 255 = 127.5 rounds to 128 (CONVENTIONS: (S*255 + 2^23) >> 24) */
    for (int i = 0; i < W * H; i += 37)
        TEST_ASSERT_UINT8_WITHIN(1, 128, color[4 * i]);
    /* a light behind the face gives black, never negative */
    frame.lights[0].direction[2] = -0.5f;
    mote_begin(&dev, &frame);
    mote_draw(&dev, &q, &dd);
    mote_end(&dev);
    TEST_ASSERT_EQUAL_UINT8(0, color[4 * (H / 2 * W + W / 2)]);
}

/* The flat shade (red, 0..255) of a triangle at z = 5 facing the camera,
 * whose centroid, where flat shading lights it, is on the view axis, lit
 * by light alone (no ambient). */
static int flat_shade_on_axis(const mote_light *light)
{
    static mote_vertex v[3];
    static const uint32_t idx[3] = {0, 1, 2};
    const float s = 0.6f, p[3][3] = {{0, 2 * s, 5}, {-s, -s, 5}, {s, -s, 5}};
    memset(v, 0, sizeof v);
    for (int i = 0; i < 3; i++) {
        memcpy(v[i].position, p[i], sizeof p[i]);
        v[i].normal[2] = -1.0f;   /* outside is toward the camera */
    }
    mote_mesh m = tu_mesh_of(v, 3, idx, 3);
    frame.light_count = 1;
    frame.lights[0] = *light;
    mote_draw_desc dd = {0};
    dd.mode = MOTE_MODE_FLAT;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &m, &dd));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_TRUE(mote_device_stats(&dev)->pixels_written > 0);
    const int centre = H / 2 * W + W / 2;
    TEST_ASSERT_TRUE(depth[centre] < 0xffffffu);   /* the triangle covers it */
    return color[4 * centre];
}

/* Babylon.js's default falloff (StandardMaterial): a range fades a point or
 * spot light linearly to nothing at that distance; a spot light lights
 * only its cone, by cos(angle to its axis)^exponent. Expected shades
 * worked out here: the triangle's centroid is 2 from a light at z = 3. */
void spot_lights_and_ranges_should_fall_off_as_in_babylon(void)
{
    mote_light l;
    memset(&l, 0, sizeof l);
    l.type = MOTE_LIGHT_POINT;
    l.position[2] = 3.0f;
    TEST_ASSERT_INT_WITHIN(1, 255, flat_shade_on_axis(&l));
    l.range = 4.0f;               /* 1 - 2/4 = 0.5: 127.5 */
    TEST_ASSERT_INT_WITHIN(1, 128, flat_shade_on_axis(&l));
    l.range = 1.5f;               /* beyond its range */
    TEST_ASSERT_EQUAL_INT(0, flat_shade_on_axis(&l));
    l.type = MOTE_LIGHT_SPOT;     /* straight down its axis */
    l.range = 0.0f;
    l.direction[2] = 1.0f;
    l.spot_angle = 1.0f;
    TEST_ASSERT_INT_WITHIN(1, 255, flat_shade_on_axis(&l));
    l.range = 8.0f;               /* 0.75: 191.25 */
    TEST_ASSERT_INT_WITHIN(1, 191, flat_shade_on_axis(&l));
    /* from x = 1: the centroid atan(1/2) = 0.4636 off the axis, n.l =
     * cos of that = 0.894427 */
    l.range = 0.0f;
    l.position[0] = 1.0f;
    l.direction[2] = 3.0f;        /* not unit: only its direction counts */
    l.spot_exponent = 2.0f;       /* 0.8 x 0.894427 x 255 = 182.46 */
    TEST_ASSERT_INT_WITHIN(1, 182, flat_shade_on_axis(&l));
    l.spot_exponent = 2.5f;       /* 0.8^1.25 x 0.894427 x 255 = 172.56 */
    TEST_ASSERT_INT_WITHIN(1, 173, flat_shade_on_axis(&l));
    l.spot_angle = 0.9f;          /* half angle 0.45: outside the cone */
    TEST_ASSERT_EQUAL_INT(0, flat_shade_on_axis(&l));
    l.spot_angle = 0.95f;         /* 0.475: inside again */
    TEST_ASSERT_INT_WITHIN(1, 173, flat_shade_on_axis(&l));
    l.direction[2] = -1.0f;       /* pointing away */
    TEST_ASSERT_EQUAL_INT(0, flat_shade_on_axis(&l));
}

/* Babylon.js's StandardMaterial composes clamp(lights x diffuse + emissive
 * + ambient): the material colour multiplies the lights before the clamp,
 * so lights summing past 1 still brighten a grey material, and the
 * emissive colour adds to the lit colour. mote does the same, per vertex
 * (Gouraud: the four-lane path on a quad) and per face (flat). */
static void draw_lit_quad(mote_mode mode, const mote_material *mat, int lights, float intensity, bool unlit)
{
    mote_mesh q = screen_quad(5.0f);
    q.material = *mat;
    frame.light_count = lights;
    for (int i = 0; i < lights; i++) {
        memset(&frame.lights[i], 0, sizeof frame.lights[i]);
        frame.lights[i].type = MOTE_LIGHT_DIRECTIONAL;
        frame.lights[i].direction[2] = 1.0f;   /* straight into the quad: n.l = 1 */
        frame.lights[i].intensity = intensity;
    }
    mote_draw_desc dd = {0};
    dd.mode = mode;
    dd.unlit = unlit;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &q, &dd));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
}

static void assert_every_pixel(uint8_t r, uint8_t g, uint8_t b)
{
    for (int i = 0; i < W * H; i += 7) {
        TEST_ASSERT_UINT8_WITHIN(1, r, color[4 * i]);
        TEST_ASSERT_UINT8_WITHIN(1, g, color[4 * i + 1]);
        TEST_ASSERT_UINT8_WITHIN(1, b, color[4 * i + 2]);
    }
}

void the_material_colour_should_multiply_the_lights_before_the_clamp_and_emissive_add(void)
{
    mote_material grey;
    memset(&grey, 0, sizeof grey);
    grey.color = (mote_rgba){102, 102, 102, 255};   /* 0.4 */
    grey.color_set = true;
    const mote_mode modes[2] = {MOTE_MODE_GOURAUD, MOTE_MODE_FLAT};
    for (int m = 0; m < 2; m++) {
        /* two lights of 1: 2 x 0.4 = 0.8 (clamped first, 0.4) */
        draw_lit_quad(modes[m], &grey, 2, 1.0f, false);
        assert_every_pixel(204, 204, 204);
        /* three of 1: 1.2, clamped */
        draw_lit_quad(modes[m], &grey, 3, 1.0f, false);
        assert_every_pixel(255, 255, 255);
        /* emissive 0.2 red: 0.4 + 0.2 in red */
        mote_material glow = grey;
        glow.emissive = (mote_rgba){51, 0, 0, 0};
        draw_lit_quad(modes[m], &glow, 1, 1.0f, false);
        assert_every_pixel(153, 102, 102);
        /* no light: the emissive colour alone */
        draw_lit_quad(modes[m], &glow, 0, 1.0f, false);
        assert_every_pixel(51, 0, 0);
        /* half a light and a strong emissive: 0.2 + 0.9, clamped */
        glow.emissive = (mote_rgba){230, 230, 0, 0};
        draw_lit_quad(modes[m], &glow, 1, 0.5f, false);
        assert_every_pixel(255, 255, 51);
        /* unlit draws show the material colour, without the emissive */
        draw_lit_quad(modes[m], &glow, 1, 0.5f, true);
        assert_every_pixel(102, 102, 102);
    }
}

void gouraud_shading_should_interpolate_vertex_intensities(void)
{
    /* one triangle with n.l = 1, 0.5, 0 at its vertices; check the values at
     * pixels against barycentric interpolation computed here */
    mote_mesh m = half_screen_triangle();
    float nx[3] = {0.0f, 0.8660254f, 1.0f};
    for (int i = 0; i < 3; i++) {
        tri_v[i].normal[0] = nx[i];
        tri_v[i].normal[2] = -mote__sqrtf(1.0f - nx[i] * nx[i]);
    }
    frame.light_count = 1;
    frame.lights[0].type = MOTE_LIGHT_DIRECTIONAL;
    frame.lights[0].direction[2] = 1.0f;  /* l = (0,0,-1) */
    mote_draw_desc dd = {0};
    dd.mode = MOTE_MODE_GOURAUD;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    mote_draw(&dev, &m, &dd);
    mote_end(&dev);
    const double intensity[3][3] = {{1.0}, {0.5}, {0.0}};   /* red: a white material */
    assert_half_screen_blends(intensity, 1);
}

void lighting_should_follow_the_mesh_rotation(void)
{
    /* a quad built facing -x, rotated 90 degrees about y to face the camera,
     * must be lit like the same quad built facing the camera */
    static mote_vertex v[4];
    static uint32_t ii[6] = {0, 2, 1, 0, 3, 2};
    float z = 5.0f, ax = (float)W / H * z;
    /* rotation about y by +90 degrees maps local (x, y, z) to world
     * (z, y, -x), so a world corner (X, Y, Z) is local (-Z, Y, X) */
    float world[4][3] = {{-ax, z, z}, {ax, z, z}, {ax, -z, z}, {-ax, -z, z}};
    memset(v, 0, sizeof v);
    for (int i = 0; i < 4; i++) {
        v[i].position[0] = -world[i][2];
        v[i].position[1] = world[i][1];
        v[i].position[2] = world[i][0];
        v[i].normal[0] = 1.0f;        /* world normal (0, 0, -1) */
    }
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = v;
    m.vertex_count = 4;
    m.indices = ii;
    m.index_count = 6;
    m.rotation[1] = 1.5707964f;
    frame.light_count = 1;
    frame.lights[0].type = MOTE_LIGHT_DIRECTIONAL;
    frame.lights[0].direction[0] = 0.8660254f;
    frame.lights[0].direction[2] = 0.5f;
    mote_draw_desc dd = {0};
    dd.mode = MOTE_MODE_GOURAUD;
    mote_begin(&dev, &frame);
    mote_draw(&dev, &m, &dd);
    mote_end(&dev);
    TEST_ASSERT_EQUAL_UINT32(2, mote_device_stats(&dev)->triangles_drawn);
    TEST_ASSERT_UINT8_WITHIN(1, 128, color[4 * (H / 2 * W + W / 2)]);
}

/* ---- vertex colours ------------------------------------------------------------ */

/* Every pixel of the screen quad drawn with d has (r, g, b), within 1. */
static void assert_screen_is(const mote_mesh *q, const mote_draw_desc *d, int r, int g, int b,
                             const char *what)
{
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, q, d));
    mote_end(&dev);
    for (int i = 0; i < W * H; i += 13) {
        TEST_ASSERT_UINT8_WITHIN_MESSAGE(1, r, color[4 * i], what);
        TEST_ASSERT_UINT8_WITHIN_MESSAGE(1, g, color[4 * i + 1], what);
        TEST_ASSERT_UINT8_WITHIN_MESSAGE(1, b, color[4 * i + 2], what);
    }
}

void vertex_colours_should_multiply_the_lit_material_colour_in_every_mode(void)
{
    static const mote_rgba orange[4] = {{255, 128, 0, 255}, {255, 128, 0, 0},
                                        {255, 128, 0, 9}, {255, 128, 0, 255}};
    static uint8_t white[4] = {255, 255, 255, 255};
    static const mote_texture tex = {1, 1, MOTE_FORMAT_RGBA8888, 4, white};
    mote_mesh q = screen_quad(5.0f);
    q.colors = orange;                /* alpha differs per vertex: ignored */
    q.material.color = (mote_rgba){128, 255, 64, 255};
    q.material.color_set = true;
    q.material.texture = &tex;
    mote_draw_desc d = {0};
    d.unlit = true;
    /* material x colour: 128 x 1, 255 x 128/255, 64 x 0 */
    static const mote_mode modes[] = {MOTE_MODE_FLAT, MOTE_MODE_GOURAUD, MOTE_MODE_TEXTURED};
    for (int k = 0; k < 3; k++) {
        d.mode = modes[k];
        assert_screen_is(&q, &d, 128, 128, 0, "unlit");
    }
    /* lit with n.l = 0.5: half of that */
    frame.light_count = 1;
    frame.lights[0].type = MOTE_LIGHT_DIRECTIONAL;
    frame.lights[0].direction[0] = 0.8660254f;
    frame.lights[0].direction[2] = 0.5f;
    d.unlit = false;
    for (int k = 0; k < 3; k++) {
        d.mode = modes[k];
        assert_screen_is(&q, &d, 64, 64, 0, "lit");
    }
}

/* A textured quad whose light falls on its back, with no ambient: its
 * shade is zero everywhere, so every pixel is black whatever the texture,
 * and setup files both triangles as black (filled without the texture).
 * An ambient too dim to move a channel makes them ordinary textured
 * triangles: the same bytes, colour and depth. */
void unlit_textured_triangles_should_be_black_and_the_same_as_textured(void)
{
    static uint8_t texels[4 * 4 * 4];
    for (int i = 0; i < (int)sizeof texels; i++)
        texels[i] = (uint8_t)(37 * i + 11);
    static const mote_texture tex = {4, 4, MOTE_FORMAT_RGBA8888, 16, texels};
    static uint8_t black_color[sizeof color];
    static uint32_t black_depth[W * H];
    mote_mesh q = make_quad(-3.0f, -2.0f, 4.0f, 3.0f, 5.0f);
    q.material.texture = &tex;
    quad_v[1].position[2] = 9.0f; /* tilted: perspective matters */
    frame.light_count = 1;
    frame.lights[0].type = MOTE_LIGHT_DIRECTIONAL;
    frame.lights[0].direction[2] = -1.0f; /* toward the camera: lights the back */
    mote_draw_desc d = {0};
    d.mode = MOTE_MODE_TEXTURED;
    for (int dim = 0; dim < 2; dim++) {
        frame.ambient[0] = frame.ambient[1] = frame.ambient[2] = dim ? 1e-4f : 0.0f;
        memset(color, 7, sizeof color);
        TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &q, &d));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
        const mote_stats *s = mote_device_stats(&dev);
        TEST_ASSERT_EQUAL_UINT32(2, s->triangles_drawn);
        TEST_ASSERT_EQUAL_UINT32(dim ? 0 : 2, s->triangles_black);
        if (!dim) {
            int covered = 0;
            for (int i = 0; i < W * H; i++) {
                if (depth[i] == 0xffffffu)
                    continue;
                covered++;
                TEST_ASSERT_EQUAL_HEX32(0xff000000u, (uint32_t)color[4 * i] | (uint32_t)color[4 * i + 1] << 8
                                        | (uint32_t)color[4 * i + 2] << 16 | (uint32_t)color[4 * i + 3] << 24);
            }
            TEST_ASSERT_GREATER_THAN_INT(W * H / 8, covered);
            memcpy(black_color, color, sizeof color);
            memcpy(black_depth, depth, sizeof black_depth);
        } else {
            TEST_ASSERT_EQUAL_MEMORY(black_color, color, sizeof color);
            TEST_ASSERT_EQUAL_MEMORY(black_depth, depth, sizeof black_depth);
        }
    }
}

void unlit_vertex_colours_should_be_interpolated_and_averaged_when_flat(void)
{
    /* red, green and blue at the corners of the half-screen triangle */
    static const mote_rgba rgb[3] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
    mote_mesh m = half_screen_triangle();
    m.colors = rgb;
    mote_draw_desc dd = {0};
    dd.mode = MOTE_MODE_GOURAUD;
    dd.unlit = true;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    mote_draw(&dev, &m, &dd);
    mote_end(&dev);
    const double unit[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    assert_half_screen_blends(unit, 3);
    /* flat: the mean of the three, 255/3 = 85 each, everywhere */
    dd.mode = MOTE_MODE_FLAT;
    mote_begin(&dev, &frame);
    mote_draw(&dev, &m, &dd);
    mote_end(&dev);
    for (int c = 0; c < 3; c++) {
        TEST_ASSERT_EQUAL_UINT8(85, color[4 * (2 * W + 2) + c]);
        TEST_ASSERT_EQUAL_UINT8(85, color[4 * ((H / 2) * W + W / 4) + c]);
    }
}

void points_and_wireframe_should_keep_their_colour_over_vertex_colours(void)
{
    static const mote_rgba red[4] = {{255, 0, 0, 255}, {255, 0, 0, 255}, {255, 0, 0, 255},
                                     {255, 0, 0, 255}};
    mote_mesh q = make_quad(-1.0f, -1.0f, 1.0f, 1.0f, 5.0f);
    q.colors = red;
    q.material.color = (mote_rgba){0, 0, 200, 255};
    q.material.color_set = true;
    mote_draw_desc d = {0};
    static const mote_mode modes[] = {MOTE_MODE_POINTS, MOTE_MODE_WIREFRAME};
    for (int k = 0; k < 2; k++) {
        d.mode = modes[k];
        TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &q, &d));
        mote_end(&dev);
        int drawn = 0;
        for (int i = 0; i < W * H; i++) {
            if (color[4 * i] == 0 && color[4 * i + 1] == 0 && color[4 * i + 2] == 0)
                continue;
            TEST_ASSERT_EQUAL_UINT8(0, color[4 * i]);
            TEST_ASSERT_EQUAL_UINT8(200, color[4 * i + 2]);
            drawn++;
        }
        TEST_ASSERT_TRUE(drawn >= 4);
    }
}

/* ---- textures --------------------------------------------------------------- */

void each_texel_should_land_on_its_pixels(void)
{
    /* a 4x4 texture on the full-screen quad: pixel (x, y) shows texel
     * (x * 4 / W, y * 4 / H); v = 0 is the top row by default */
    static uint8_t texels[4 * 4 * 4];
    for (int i = 0; i < 16; i++) {
        texels[4 * i] = (uint8_t)(i * 16);
        texels[4 * i + 1] = (uint8_t)(255 - i * 16);
        texels[4 * i + 2] = (uint8_t)(i * 7);
        texels[4 * i + 3] = 255;
    }
    mote_texture tex = {4, 4, MOTE_FORMAT_RGBA8888, 16, texels};
    mote_mesh q = screen_quad(5.0f);
    q.material.texture = &tex;
    mote_draw_desc dd = {0};
    dd.unlit = true;
    for (int flip = 0; flip < 2; flip++) {
        q.material.v_origin_bottom = flip != 0;
        TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
        mote_draw(&dev, &q, &dd);
        mote_end(&dev);
        for (int y = 1; y < H; y += 2)
            for (int x = 1; x < W; x += 2) {
                int tx = x * 4 / W, ty = y * 4 / H;
                /* skip pixels whose centre sits on a texel boundary */
                if ((x * 4) % W == 0 || (y * 4) % H == 0)
                    continue;
                if (flip)
                    ty = 3 - ty;
                TEST_ASSERT_EQUAL_UINT8(texels[4 * (ty * 4 + tx)], color[4 * (y * W + x)]);
                TEST_ASSERT_EQUAL_UINT8(texels[4 * (ty * 4 + tx) + 1], color[4 * (y * W + x) + 1]);
            }
    }
}

void uvs_outside_zero_one_should_wrap_around(void)
{
    static uint8_t texels[2 * 1 * 4] = {255, 0, 0, 255, 0, 255, 0, 255};
    mote_texture tex = {2, 1, MOTE_FORMAT_RGBA8888, 8, texels};
    mote_mesh q = screen_quad(5.0f);
    q.material.texture = &tex;
    q.material.u_scale = 3.0f;    /* three repeats: six columns alternating */
    mote_draw_desc dd = {0};
    dd.unlit = true;
    mote_begin(&dev, &frame);
    mote_draw(&dev, &q, &dd);
    mote_end(&dev);
    for (int k = 0; k < 6; k++) {
        int x = k * W / 6 + W / 12;
        TEST_ASSERT_EQUAL_UINT8(k % 2 == 0 ? 255 : 0, color[4 * (H / 2 * W + x)]);
    }
}

/* ---- culling ---------------------------------------------------------------- */

static mote_vertex cube_v[8];
static uint32_t cube_i[36];

static mote_mesh make_cube(void)
{
    /* faces wound counter-clockwise seen from outside (Babylon's front faces) */
    static const uint32_t faces[6][4] = {
        {3, 2, 1, 0}, {6, 7, 4, 5}, {7, 3, 0, 4}, {2, 6, 5, 1}, {0, 1, 5, 4}, {7, 6, 2, 3}};
    for (int i = 0; i < 8; i++) {
        cube_v[i].position[0] = (i == 1 || i == 2 || i == 5 || i == 6) ? 1.0f : -1.0f;
        cube_v[i].position[1] = (i == 0 || i == 1 || i == 4 || i == 5) ? 1.0f : -1.0f;
        cube_v[i].position[2] = i < 4 ? -1.0f : 1.0f;
        for (int k = 0; k < 3; k++)
            cube_v[i].normal[k] = cube_v[i].position[k];
    }
    for (int f = 0; f < 6; f++) {
        uint32_t *o = &cube_i[6 * f];
        o[0] = faces[f][0];
        o[1] = faces[f][1];
        o[2] = faces[f][2];
        o[3] = faces[f][0];
        o[4] = faces[f][2];
        o[5] = faces[f][3];
    }
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = cube_v;
    m.vertex_count = 8;
    m.indices = cube_i;
    m.index_count = 36;
    return m;
}

void backface_culling_should_keep_exactly_the_faces_that_face_the_eye(void)
{
    mote_mesh cube = make_cube();
    srand(5);
    for (int iter = 0; iter < 200; iter++) {
        /* eyes all around, some close enough for strong perspective */
        double th = 6.2831853 * rand() / RAND_MAX, ph = 3.1 * rand() / RAND_MAX - 1.55;
        double dist = 2.2 + 8.0 * rand() / RAND_MAX;
        float eye[3] = {(float)(dist * cos(ph) * cos(th)), (float)(dist * sin(ph)), (float)(dist * cos(ph) * sin(th))};
        memcpy(frame.camera.position, eye, sizeof eye);
        memset(frame.camera.target, 0, sizeof frame.camera.target);
        frame.camera.znear = 0.1f;
        frame.camera.fov = 2.0f;  /* wide, so the whole cube is in view */
        /* seen edge-on, a face's snapped winding may go either way (as on
         * any rasteriser that culls on snapped positions): keep the eye at
         * least 0.05 from every face plane */
        if (fabsf(fabsf(eye[0]) - 1.0f) < 0.05f || fabsf(fabsf(eye[1]) - 1.0f) < 0.05f
            || fabsf(fabsf(eye[2]) - 1.0f) < 0.05f)
            continue;
        /* expected: a triangle is front when the eye is on its outer side */
        int front = 0;
        for (int t = 0; t < 12; t++) {
            const float *a = cube_v[cube_i[3 * t]].position, *b = cube_v[cube_i[3 * t + 1]].position,
                        *c = cube_v[cube_i[3 * t + 2]].position;
            double e1[3], e2[3], n[3], out = 0.0, side = 0.0;
            for (int k = 0; k < 3; k++) {
                e1[k] = b[k] - a[k];
                e2[k] = c[k] - a[k];
            }
            n[0] = e1[1] * e2[2] - e1[2] * e2[1];
            n[1] = e1[2] * e2[0] - e1[0] * e2[2];
            n[2] = e1[0] * e2[1] - e1[1] * e2[0];
            for (int k = 0; k < 3; k++) {
                out += n[k] * a[k];            /* > 0: n points outward */
                side += n[k] * (eye[k] - a[k]);
            }
            front += (out > 0.0) == (side > 0.0);
        }
        TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
        mote_draw(&dev, &cube, NULL);
        mote_end(&dev);
        const mote_stats *s = mote_device_stats(&dev);
        TEST_ASSERT_EQUAL_UINT32(12, s->triangles_in);
        TEST_ASSERT_EQUAL_UINT32(12 - front, s->triangles_backface);
        /* a front face seen so nearly edge-on that it holds no pixel
         * centre counts as degenerate */
        TEST_ASSERT_EQUAL_UINT32(front, s->triangles_drawn + s->triangles_degenerate);
    }
}

void the_tutorials_view_space_normal_test_would_fail_where_winding_does_not(void)
{
    /* eye close to the plane of the +x face, looking at the cube's -x side at
     * a grazing angle: the view-space normal's z and the real visibility
     * disagree for the +z face; the winding test gets it right */
    mote_mesh cube = make_cube();
    float eye[3] = {0.5f, 0.0f, -4.0f};
    memcpy(frame.camera.position, eye, sizeof eye);
    frame.camera.target[0] = -3.0f;
    frame.camera.target[2] = 0.0f;
    frame.camera.znear = 0.1f;
    frame.camera.fov = 2.5f;
    mote_begin(&dev, &frame);
    mote_draw(&dev, &cube, NULL);
    mote_end(&dev);
    /* only the -z face (z = -1 side) faces this eye: 2 triangles */
    TEST_ASSERT_EQUAL_UINT32(2, mote_device_stats(&dev)->triangles_drawn);
}

void invalid_indices_and_nan_vertices_should_drop_triangles_not_the_frame(void)
{
    mote_mesh q = screen_quad(5.0f);
    static uint32_t bad[9] = {0, 2, 1, 0, 99, 2, 0, 3, 2};
    q.indices = bad;
    q.index_count = 9;
    mote_begin(&dev, &frame);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &q, NULL));
    mote_end(&dev);
    TEST_ASSERT_EQUAL_UINT32(1, mote_device_stats(&dev)->triangles_invalid);
    TEST_ASSERT_EQUAL_UINT32(2, mote_device_stats(&dev)->triangles_drawn);
    quad_v[1].position[0] = NAN;
    mote_begin(&dev, &frame);
    mote_draw(&dev, &q, NULL);
    mote_end(&dev);
    TEST_ASSERT_EQUAL_UINT32(2, mote_device_stats(&dev)->triangles_invalid);
    TEST_ASSERT_EQUAL_UINT32(1, mote_device_stats(&dev)->triangles_drawn);
}

void meshes_outside_the_frustum_should_be_rejected_whole_and_only_those(void)
{
    static uint8_t with_bounds[sizeof color];
    mote_mesh cube = make_cube();
    frame.camera.znear = 0.5f;
    srand(9);
    int culled = 0, kept = 0;
    for (int iter = 0; iter < 300; iter++) {
        cube.position[0] = (float)(rand() % 4000) / 100.0f - 20.0f;
        cube.position[1] = (float)(rand() % 4000) / 100.0f - 20.0f;
        cube.position[2] = (float)(rand() % 4000) / 100.0f - 10.0f;
        cube.rotation[1] = (float)iter;
        cube.scaling[0] = cube.scaling[1] = cube.scaling[2] = 0.5f + (float)(iter % 5);
        /* with bounds */
        mote_mesh_update_bounds(&cube);
        mote_begin(&dev, &frame);
        mote_draw(&dev, &cube, NULL);
        mote_end(&dev);
        memcpy(with_bounds, color, sizeof color);
        uint32_t rejected = mote_device_stats(&dev)->meshes_culled;
        /* without: the same pixels, whatever the rejection decided */
        cube.bounds_radius = 0.0f;
        mote_begin(&dev, &frame);
        mote_draw(&dev, &cube, NULL);
        mote_end(&dev);
        TEST_ASSERT_EQUAL_UINT32(0, mote_device_stats(&dev)->meshes_culled);
        TEST_ASSERT_EQUAL_MEMORY(color, with_bounds, sizeof color);
        if (rejected) {
            culled++;
            TEST_ASSERT_EQUAL_UINT32(0, mote_device_stats(&dev)->triangles_drawn);
        } else {
            kept++;
        }
    }
    /* both outcomes occurred, so the test exercised the rejection */
    TEST_ASSERT_TRUE(culled > 50);
    TEST_ASSERT_TRUE(kept > 20);
}

void device_init_should_reject_bad_descriptors(void)
{
    mote_device d2;
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_device_init(&d2, &d));
    d.width = W;
    d.height = H;
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_device_init(&d2, &d)); /* no buffers */
    d.color = color;
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_device_init(&d2, &d)); /* no depth */
    d.depth_format = MOTE_DEPTH_FORMAT_NONE;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&d2, &d));
    d.width = MOTE_MAX_SIZE + 1;
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_device_init(&d2, &d));
    /* with stride 0 the default stride of a width past the limit must
     * not overflow first (UBSan, SAN=1) */
    d.width = INT_MAX;
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_device_init(&d2, &d));
    d.height = INT_MAX;
    d.width = INT_MAX / 2 + 1;
    d.color_format = MOTE_FORMAT_RGB565;
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_device_init(&d2, &d));
    d.color_format = MOTE_FORMAT_DEFAULT;
    d.height = H;
    d.width = W;
    d.band_height = 8;            /* band mode needs a flush callback */
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_device_init(&d2, &d));
    d.band_height = 0;
    d.subpixel_bits = 3;
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_device_init(&d2, &d));
    TEST_ASSERT_EQUAL_STRING("invalid argument", mote_result_string(MOTE_ERR_INVALID_ARGUMENT));
    TEST_ASSERT_EQUAL_STRING("unknown result", mote_result_string((mote_result)999));
    /* drawing on a device that failed to initialise is refused */
    TEST_ASSERT_EQUAL(MOTE_ERR_STATE, mote_begin(&d2, &frame));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(projection_should_map_known_points_to_pixels);
    RUN_TEST(projection_should_follow_the_left_handed_look_at);
    RUN_TEST(orthographic_projection_should_map_its_box_to_the_image);
    RUN_TEST(orthographic_cameras_should_draw_sizes_independent_of_distance);
    RUN_TEST(bresenham_lines_should_hit_both_endpoints_and_stay_connected);
    RUN_TEST(lines_clipped_to_a_region_should_draw_the_same_pixels_inside_it);
    RUN_TEST(a_triangulated_square_should_cover_every_pixel_exactly_once);
    RUN_TEST(a_random_fan_over_the_screen_should_cover_every_pixel_exactly_once);
    RUN_TEST(the_depth_test_should_not_depend_on_draw_order);
    RUN_TEST(depth_rejected_pixels_should_be_tested_but_not_written);
    RUN_TEST(flat_shading_should_use_the_face_normal_against_the_light);
    RUN_TEST(spot_lights_and_ranges_should_fall_off_as_in_babylon);
    RUN_TEST(the_material_colour_should_multiply_the_lights_before_the_clamp_and_emissive_add);
    RUN_TEST(gouraud_shading_should_interpolate_vertex_intensities);
    RUN_TEST(lighting_should_follow_the_mesh_rotation);
    RUN_TEST(vertex_colours_should_multiply_the_lit_material_colour_in_every_mode);
    RUN_TEST(unlit_textured_triangles_should_be_black_and_the_same_as_textured);
    RUN_TEST(unlit_vertex_colours_should_be_interpolated_and_averaged_when_flat);
    RUN_TEST(points_and_wireframe_should_keep_their_colour_over_vertex_colours);
    RUN_TEST(each_texel_should_land_on_its_pixels);
    RUN_TEST(uvs_outside_zero_one_should_wrap_around);
    RUN_TEST(backface_culling_should_keep_exactly_the_faces_that_face_the_eye);
    RUN_TEST(the_tutorials_view_space_normal_test_would_fail_where_winding_does_not);
    RUN_TEST(invalid_indices_and_nan_vertices_should_drop_triangles_not_the_frame);
    RUN_TEST(meshes_outside_the_frustum_should_be_rejected_whole_and_only_those);
    RUN_TEST(device_init_should_reject_bad_descriptors);
    return UNITY_END();
}
