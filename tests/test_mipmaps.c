/*
 * test_mipmaps.c - mip chains (mote_mipmaps_build) and the level a draw
 * samples (mote_draw_desc.mip).
 *
 * What is asserted:
 *   - The chain: sizes and bytes, each level the rounded 2x2 box of the
 *     one before, in each texture format; no levels for a texture that is
 *     not a power of two; errors for missing or short memory.
 *   - Selection, exactly: a textured quad seen by an orthographic camera
 *     at a quarter of its texels' size samples level 2, per triangle and
 *     per pixel, so it draws the same bytes as the quad drawn with level
 *     2 itself as its texture; at its texels' size, level 0.
 *   - What mipmaps are for: a checkerboard floor receding to the horizon
 *     varies far less in its far rows with per-pixel levels than without
 *     (it no longer aliases into noise).
 *   - Against the double-precision reference (tests/ref), a receding floor
 *     in each mip mode and filter: within 1 LSB on 99.9% of the pixels
 *     (99.8% trilinear bilinear) of the reference taking mote.h's
 *     one-pixel texel steps; against exact derivatives the same where
 *     the levels agree, and the pixels where they do not counted apart
 *     and bounded (docs/accuracy.md).
 */
#include <mote/mote.h>
#include "ref/ref.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define W 64
#define H 64

static uint8_t checker_px[64 * 64 * 4];
static mote_texture checker = {64, 64, MOTE_FORMAT_RGBA8888, 0, checker_px};

static void build_checker(void)
{
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            uint8_t *p = &checker_px[(y * 64 + x) * 4];
            const uint8_t c = ((x / 2) ^ (y / 2)) & 1 ? 230 : 20;
            p[0] = c;
            p[1] = (uint8_t)(x * 4);
            p[2] = (uint8_t)(y * 4);
            p[3] = 255;
        }
}

void a_chain_should_halve_each_level_with_a_rounded_box_filter(void)
{
    build_checker();
    TEST_ASSERT_EQUAL_UINT64((32 * 32 + 16 * 16 + 8 * 8 + 4 * 4 + 2 * 2 + 1) * 4, (uint64_t)mote_mipmaps_bytes(&checker));
    static uint8_t memory[64 * 64 * 4];
    mote_mipmaps m;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_mipmaps_build(&checker, memory, sizeof memory, &m));
    TEST_ASSERT_EQUAL_INT(7, m.count);
    TEST_ASSERT_EQUAL_INT(1, m.level[6].width);
    const uint8_t *l1 = (const uint8_t *)m.level[1].pixels;
    for (int k = 0; k < 4; k++) {   /* texel (1, 0) of level 1: texels (2..3, 0..1) of level 0 */
        const uint8_t *a = &checker_px[2 * 4], *b = &checker_px[3 * 4], *c = &checker_px[(64 + 2) * 4],
                      *d = &checker_px[(64 + 3) * 4];
        TEST_ASSERT_EQUAL_UINT8((a[k] + b[k] + c[k] + d[k] + 2) / 4, l1[4 + k]);
    }
    /* grey and RGB565 texels, and textures without levels */
    static uint8_t grey_px[4] = {10, 20, 30, 41}, grey_mem[1];
    const mote_texture grey = {2, 2, MOTE_FORMAT_GREY8, 0, grey_px};
    TEST_ASSERT_EQUAL(MOTE_OK, mote_mipmaps_build(&grey, grey_mem, 1, &m));
    TEST_ASSERT_EQUAL_UINT8((10 + 20 + 30 + 41 + 2) / 4, grey_mem[0]);
    const mote_texture npot = {3, 2, MOTE_FORMAT_RGBA8888, 0, checker_px};
    TEST_ASSERT_EQUAL_UINT64(0, (uint64_t)mote_mipmaps_bytes(&npot));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_mipmaps_build(&npot, NULL, 0, &m));
    TEST_ASSERT_EQUAL_INT(1, m.count);
    TEST_ASSERT_EQUAL(MOTE_ERR_OUT_OF_MEMORY, mote_mipmaps_build(&checker, memory, 100, &m));
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_mipmaps_build(NULL, memory, sizeof memory, &m));
}

/* ---- drawing ------------------------------------------------------------- */

static mote_vertex quad_v[4];
static const uint32_t quad_i[6] = {0, 2, 1, 0, 3, 2};

/* The mesh of quad_v. */
static mote_mesh quad_mesh(void)
{
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = quad_v;
    m.vertex_count = 4;
    m.indices = quad_i;
    m.index_count = 6;
    return m;
}

/* A quad of half-size s facing an orthographic camera that sees [-1, 1]:
 * s = 1 fills the 64x64 image. */
static mote_mesh quad(float s, float uv)
{
    const float p[4][2] = {{-s, s}, {s, s}, {s, -s}, {-s, -s}};
    const float t[4][2] = {{0, 0}, {uv, 0}, {uv, uv}, {0, uv}};
    for (int i = 0; i < 4; i++) {
        memset(&quad_v[i], 0, sizeof quad_v[i]);
        quad_v[i].position[0] = p[i][0];
        quad_v[i].position[1] = p[i][1];
        quad_v[i].position[2] = 1.0f;
        quad_v[i].normal[2] = -1.0f;
        quad_v[i].uv[0] = t[i][0];
        quad_v[i].uv[1] = t[i][1];
    }
    mote_mesh m = quad_mesh();
    return m;
}

#define FW 160
#define FH 120

/* Draws m into out, a w x h image (at most FW x FH). */
static void render_at(const mote_frame_desc *f, const mote_mesh *m, const mote_draw_desc *d, uint8_t *out, int w,
                      int h)
{
    static uint32_t depth[FW * FH];
    mote_device dev;
    mote_device_desc desc;
    memset(&desc, 0, sizeof desc);
    desc.width = w;
    desc.height = h;
    desc.color = out;
    desc.depth = depth;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &desc));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, f));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, m, d));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
}

static void render(const mote_frame_desc *f, const mote_mesh *m, const mote_draw_desc *d, uint8_t *out)
{
    render_at(f, m, d, out, W, H);
}

/* The camera low over a floor 200 deep, looking along it. */
static mote_frame_desc floor_frame(void)
{
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    f.camera.position[1] = 1.5f;
    f.camera.position[2] = -1.0f;
    f.camera.target[1] = 1.0f;
    f.camera.target[2] = 10.0f;
    f.camera.zfar = 300.0f;
    return f;
}

/* The checker's chain in memory, and an orthographic camera that sees
 * [-1, 1] (quad's frame). */
static void ortho_setup(uint8_t *memory, size_t size, mote_mipmaps *chain, mote_frame_desc *f)
{
    build_checker();
    TEST_ASSERT_EQUAL(MOTE_OK, mote_mipmaps_build(&checker, memory, size, chain));
    memset(f, 0, sizeof *f);
    f->camera.projection = MOTE_PROJECTION_ORTHOGRAPHIC;
    f->camera.position[2] = -2.0f;
    f->camera.ortho[0] = f->camera.ortho[2] = -1.0f;
    f->camera.ortho[1] = f->camera.ortho[3] = 1.0f;
}

void trilinear_should_blend_the_two_levels_around_the_pixel_scale(void)
{
    static uint8_t memory[64 * 64 * 4];
    mote_mipmaps chain;
    mote_frame_desc f;
    ortho_setup(memory, sizeof memory, &chain, &f);
    /* 64 texels over 64 / 2.5 pixels: log2 2.5 between levels 1 and 2,
     * the weight of level 2 the mantissa 0.25 (64 of 256) */
    static uint8_t one[W * H * 4], two[W * H * 4], got[W * H * 4];
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.unlit = true;
    const float s = 1.0f / 2.5f;
    mote_mesh m = quad(s, 1.0f);
    m.material.texture = &chain.level[1];
    render(&f, &m, &d, one);
    m = quad(s, 1.0f);
    m.material.texture = &chain.level[2];
    render(&f, &m, &d, two);
    m = quad(s, 1.0f);
    m.material.texture = &checker;
    m.material.mipmaps = &chain;
    d.mip = MOTE_MIP_TRILINEAR;
    render(&f, &m, &d, got);
    long off = 0, drawn = 0;
    for (int i = 0; i < W * H; i++) {
        if (got[4 * i + 3] != 255)
            continue;
        drawn++;
        for (int k = 0; k < 3; k++) {
            const int want = (one[4 * i + k] * 192 + two[4 * i + k] * 64 + 128) >> 8;
            off += abs(got[4 * i + k] - want) > 2;
        }
    }
    printf("trilinear at log2 2.5: %ld of %ld pixels' channels off by more than 2\n", off, drawn);
    TEST_ASSERT_TRUE(drawn > 500);
    TEST_ASSERT_TRUE(off * 100 < drawn);
}

void a_quarter_size_quad_should_sample_level_2_per_triangle_and_per_pixel(void)
{
    static uint8_t memory[64 * 64 * 4];
    mote_mipmaps chain;
    mote_frame_desc f;
    ortho_setup(memory, sizeof memory, &chain, &f);
    static uint8_t want[W * H * 4], got[W * H * 4];
    for (int filter = MOTE_FILTER_NEAREST; filter <= MOTE_FILTER_BILINEAR; filter++)
        for (int level = 0; level <= 2; level += 2) {
            /* 64 texels across 64 >> level pixels */
            mote_mesh direct = quad(1.0f / (float)(1 << level), 1.0f);
            direct.material.texture = &chain.level[level];
            mote_draw_desc d;
            memset(&d, 0, sizeof d);
            d.unlit = true;
            d.filter = (mote_filter)filter;
            render(&f, &direct, &d, want);
            for (int mip = MOTE_MIP_TRIANGLE; mip <= MOTE_MIP_PIXEL; mip++) {
                mote_mesh m = quad(1.0f / (float)(1 << level), 1.0f);
                m.material.texture = &checker;
                m.material.mipmaps = &chain;
                d.mip = (mote_mip)mip;
                render(&f, &m, &d, got);
                char msg[96];
                snprintf(msg, sizeof msg, "level %d, mip mode %d, filter %d", level, mip, filter);
                TEST_ASSERT_EQUAL_MEMORY_MESSAGE(want, got, sizeof want, msg);
            }
        }
}

/* Variance of the grey values of rows [y0, y1) of an RGBA image. */
static double row_variance(const uint8_t *img, int y0, int y1)
{
    double sum = 0.0, sum2 = 0.0;
    long n = 0;
    for (int y = y0; y < y1; y++)
        for (int x = 0; x < W; x++, n++) {
            double g = img[(y * W + x) * 4];
            sum += g;
            sum2 += g * g;
        }
    const double mean = sum / (double)n;
    return sum2 / (double)n - mean * mean;
}

void a_receding_checkerboard_should_fade_to_grey_with_per_pixel_levels(void)
{
    build_checker();
    static uint8_t memory[64 * 64 * 4];
    mote_mipmaps chain;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_mipmaps_build(&checker, memory, sizeof memory, &chain));
    /* a floor 200 long, the camera low over it */
    static const float fp[4][3] = {{-20, 0, 200}, {20, 0, 200}, {20, 0, 0}, {-20, 0, 0}};
    static const float ft[4][2] = {{0, 0}, {4, 0}, {4, 20}, {0, 20}};
    for (int i = 0; i < 4; i++) {
        memset(&quad_v[i], 0, sizeof quad_v[i]);
        memcpy(quad_v[i].position, fp[i], sizeof fp[i]);
        quad_v[i].normal[1] = 1.0f;
        memcpy(quad_v[i].uv, ft[i], sizeof ft[i]);
    }
    mote_mesh m = quad_mesh();
    m.material.texture = &checker;
    m.material.mipmaps = &chain;
    const mote_frame_desc f = floor_frame();
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.unlit = true;
    d.cull = MOTE_CULL_NONE;
    static uint8_t plain[W * H * 4], mipped[W * H * 4], blended[W * H * 4];
    render(&f, &m, &d, plain);
    d.mip = MOTE_MIP_TRILINEAR;
    render(&f, &m, &d, blended);
    d.mip = MOTE_MIP_PIXEL;
    render(&f, &m, &d, mipped);
    /* the far rows: just below the horizon */
    int y0 = 0;
    while (y0 < H && plain[(y0 * W + W / 2) * 4 + 3] != 255)
        y0++;
    const double v_plain = row_variance(plain, y0, y0 + 6), v_mip = row_variance(mipped, y0, y0 + 6);
    const double v_tri = row_variance(blended, y0, y0 + 6);
    printf("far rows from %d: variance %.1f without mipmaps, %.1f with per-pixel levels, %.1f trilinear\n", y0,
           v_plain, v_mip, v_tri);
    TEST_ASSERT_TRUE(y0 < H - 6);
    TEST_ASSERT_TRUE(v_mip * 4.0 < v_plain);
    TEST_ASSERT_TRUE(v_tri * 4.0 < v_plain);
    /* trilinear has no seams where the level changes: down the middle
     * column, from row to row, its largest jump is below nearest-mip's */
    int jump_mip = 0, jump_tri = 0;
    for (int y = y0 + 1; y < H; y++) {
        const int a = (y * W + W / 2) * 4, b = ((y - 1) * W + W / 2) * 4;
        jump_mip = abs(mipped[a + 1] - mipped[b + 1]) > jump_mip ? abs(mipped[a + 1] - mipped[b + 1]) : jump_mip;
        jump_tri = abs(blended[a + 1] - blended[b + 1]) > jump_tri ? abs(blended[a + 1] - blended[b + 1]) : jump_tri;
    }
    printf("largest row-to-row step of green: %d nearest level, %d trilinear\n", jump_mip, jump_tri);
    TEST_ASSERT_TRUE(jump_tri <= jump_mip);
}

/* ---- against the double-precision reference ------------------------------ */

#define GX 4
#define GZ 24

static mote_vertex floor_v[(GX + 1) * (GZ + 1)];
static uint32_t floor_i[GX * GZ * 6];

/* A floor 40 wide and 200 deep as a grid of GX x GZ cells (so that its
 * triangles take different levels), the checker repeated 4 x 20 times. */
static mote_mesh floor_mesh(const mote_mipmaps *chain)
{
    for (int z = 0; z <= GZ; z++)
        for (int x = 0; x <= GX; x++) {
            mote_vertex *p = &floor_v[z * (GX + 1) + x];
            memset(p, 0, sizeof *p);
            p->position[0] = -20.0f + 40.0f * (float)x / GX;
            p->position[2] = 200.0f * (float)z / GZ;
            p->normal[1] = 1.0f;
            p->uv[0] = 4.0f * (float)x / GX;
            p->uv[1] = 20.0f * (float)z / GZ;
        }
    uint32_t *ix = floor_i;
    for (int z = 0; z < GZ; z++)
        for (int x = 0; x < GX; x++) {
            const uint32_t a = (uint32_t)(z * (GX + 1) + x), b = a + 1, c = a + GX + 1, d = c + 1;
            const uint32_t q[6] = {a, c, b, b, c, d};
            memcpy(ix, q, sizeof q);
            ix += 6;
        }
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = floor_v;
    m.vertex_count = (GX + 1) * (GZ + 1);
    m.indices = floor_i;
    m.index_count = GX * GZ * 6;
    m.material.texture = &checker;
    m.material.mipmaps = chain;
    return m;
}

/* How mote's pixels compare with the reference's in one mip mode: with
 * levels from the one-pixel texel steps mote.h states (step_*), and from
 * the exact derivatives (the rest). */
typedef struct mip_compare {
    long drawn, mismatch;
    long step_off;               /* more than 1 LSB from the reference taking the steps */
    int step_max;
    long off;                    /* more than 1 LSB from the exact reference, where the two
                                    references agree within 1 LSB */
    int max_err;                 /* the largest error of those and the pixels within 1 LSB */
    long level;                  /* more than 1 LSB from the exact reference, where the two
                                    references differ: the step's level of detail is not the
                                    derivative's */
    long level_inside;           /* of those, nearest-level modes: the exact level of detail
                                    farther than BAND from a rounding boundary k + 1/2 */
    int level_max;
} mip_compare;

#define BAND 0.1

/* The largest channel error of pixel i between two RGBA images. */
static int pixel_err(const uint8_t *a, const uint8_t *b, int i)
{
    int e = 0;
    for (int k = 0; k < 3; k++)
        e = abs(a[4 * i + k] - b[4 * i + k]) > e ? abs(a[4 * i + k] - b[4 * i + k]) : e;
    return e;
}

/* The floor drawn by the reference, its levels from the steps or exact. */
static void ref_floor(ref_target *t, const mote_mesh *m, const mote_frame_desc *f, const mote_draw_desc *d,
                      bool step, double *lod)
{
    TEST_ASSERT_TRUE(ref_target_init(t, FW, FH, 8));
    t->lod = lod;
    t->mip_step = step;
    const mote_rgba clear = {0, 0, 0, 0};
    ref_begin(t, f, clear);
    TEST_ASSERT_TRUE(ref_draw(t, m, d));
}

static mip_compare compare_floor(mote_mip mip, mote_filter filter)
{
    static uint8_t memory[64 * 64 * 4];
    mote_mipmaps chain;
    build_checker();
    TEST_ASSERT_EQUAL(MOTE_OK, mote_mipmaps_build(&checker, memory, sizeof memory, &chain));
    const mote_mesh m = floor_mesh(&chain);
    const mote_frame_desc f = floor_frame();
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.unlit = true;
    d.cull = MOTE_CULL_NONE;
    d.filter = filter;
    d.mip = mip;

    static uint8_t got[FW * FH * 4];
    render_at(&f, &m, &d, got, FW, FH);

    ref_target exact, step;
    static double lod[FW * FH];
    ref_floor(&exact, &m, &f, &d, false, lod);
    ref_floor(&step, &m, &f, &d, true, NULL);

    mip_compare r;
    memset(&r, 0, sizeof r);
    for (int i = 0; i < FW * FH; i++) {
        const bool a = got[4 * i + 3] == 255, b = exact.cov[i] != 0;
        r.mismatch += a != b;
        if (!a || !b)
            continue;
        r.drawn++;
        const int es = pixel_err(got, step.rgba, i), e = pixel_err(got, exact.rgba, i);
        r.step_off += es > 1;
        r.step_max = es > r.step_max ? es : r.step_max;
        if (e > 1 && pixel_err(step.rgba, exact.rgba, i) > 0) {
            r.level++;
            r.level_max = e > r.level_max ? e : r.level_max;
            const double near = fabs(lod[i] - floor(lod[i]) - 0.5);
            r.level_inside += mip != MOTE_MIP_TRILINEAR && !(near < BAND);
        } else {
            r.off += e > 1;
            r.max_err = e > r.max_err ? e : r.max_err;
        }
    }
    ref_target_free(&exact);
    ref_target_free(&step);
    printf("mip mode %d, filter %d: %ld px, %ld coverage mismatches; from the steps' levels %ld px off > 1 LSB "
           "(max %d); from the exact levels %ld off (max %d), %ld more where the levels differ (max %d, %ld "
           "away from a boundary)\n",
           (int)mip, (int)filter, r.drawn, r.mismatch, r.step_off, r.step_max, r.off, r.max_err, r.level,
           r.level_max, r.level_inside);
    return r;
}

void a_receding_floor_should_match_the_reference_in_each_mip_mode(void)
{
    for (int filter = MOTE_FILTER_NEAREST; filter <= MOTE_FILTER_BILINEAR; filter++)
        for (int mip = MOTE_MIP_TRIANGLE; mip <= MOTE_MIP_TRILINEAR; mip++) {
            const mip_compare r = compare_floor((mote_mip)mip, (mote_filter)filter);
            TEST_ASSERT_TRUE(r.drawn > FW * FH / 3);
            TEST_ASSERT_EQUAL_INT(0, r.mismatch);
            /* the rule mote.h states: within 1 LSB on 99.9% of the pixels
             * (ACCURACY), 99.8% where trilinear blends two rounded
             * bilinear texels with a weight in 1/256 */
            const long per_mille = mip == MOTE_MIP_TRILINEAR && filter == MOTE_FILTER_BILINEAR ? 2 : 1;
            TEST_ASSERT_TRUE(r.step_off * 1000 <= r.drawn * per_mille);
            TEST_ASSERT_TRUE(r.step_max <= 2);
            /* the exact derivatives: the same where they give the same
             * levels and weights */
            TEST_ASSERT_TRUE(r.off * 1000 <= r.drawn * per_mille);
            TEST_ASSERT_TRUE(r.max_err <= 2);
            /* where they do not: a nearest level only next to a rounding
             * boundary; measured 0, 4.7% and 21.2% of the pixels per
             * triangle, per pixel and trilinear, trilinear's error at
             * most 19 */
            TEST_ASSERT_EQUAL_INT(0, r.level_inside);
            const long percent = mip == MOTE_MIP_TRIANGLE ? 0 : mip == MOTE_MIP_PIXEL ? 6 : 25;
            TEST_ASSERT_TRUE(r.level * 100 <= r.drawn * percent);
            TEST_ASSERT_TRUE(mip != MOTE_MIP_TRILINEAR || r.level_max <= 24);
        }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(a_chain_should_halve_each_level_with_a_rounded_box_filter);
    RUN_TEST(a_quarter_size_quad_should_sample_level_2_per_triangle_and_per_pixel);
    RUN_TEST(a_receding_checkerboard_should_fade_to_grey_with_per_pixel_levels);
    RUN_TEST(trilinear_should_blend_the_two_levels_around_the_pixel_scale);
    RUN_TEST(a_receding_floor_should_match_the_reference_in_each_mip_mode);
    return UNITY_END();
}
