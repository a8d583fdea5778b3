/*
 * test_formats_bands.c - colour formats, depth formats and band rendering.
 *
 * What is asserted, and why it must hold exactly:
 *   - Formats: mote computes each pixel's R, G, B the same way whatever the
 *     target, and packs them only when it stores the pixel (clears too), so
 *     a render in RGB565, RGB565_SWAPPED or GREY8 equals the RGBA8888
 *     render of the same frame converted with mote_convert_row, byte for
 *     byte, in every mode.
 *   - RGB565_SWAPPED is RGB565 with the two bytes of each pixel swapped.
 *   - Bands: every band starts from the same set-up triangles and steps its
 *     edges and planes exactly, so the frame assembled from bands of any
 *     height equals the full-frame render, in every format, depth format
 *     and mode.
 *   - Depth 16 vs 32: a 16-bit buffer stores D >> 8, so two fragments whose
 *     24-bit depths differ can tie; on a tie the strict less-than test keeps
 *     the earlier fragment. The test predicts every pixel of two
 *     intersecting quads from each quad drawn alone (its colour and depth),
 *     for both buffers, and checks the renders against that: the two
 *     buffers may differ only at pixels where the quads' 16-bit depths tie,
 *     and there they must hold the quad drawn first.
 *   - The RAM budget of docs/embedded.md: a 320x240 RGB565 frame with 16-bit
 *     depth in bands of 30 rows fits in 48 KB with the device.
 */
#include <mote/mote.h>
#include "unity.h"

#include <stdlib.h>
#include <string.h>

#define W 80
#define H 72
#define MAX_BPP 4

void setUp(void) {}
void tearDown(void) {}

static const mote_format formats[] = {MOTE_FORMAT_RGBA8888, MOTE_FORMAT_RGB565,
                                      MOTE_FORMAT_RGB565_SWAPPED, MOTE_FORMAT_GREY8};
static const mote_depth_format depths[] = {MOTE_DEPTH_FORMAT_32, MOTE_DEPTH_FORMAT_16,
                                           MOTE_DEPTH_FORMAT_NONE};
static const char *const format_names[] = {"default", "RGBA8888", "RGB565", "RGB565_SWAPPED", "GREY8"};
static const char *const depth_names[] = {"default", "depth32", "depth16", "no depth"};

/* ---- the scene: a textured cube with a quad through it ------------------- */

static mote_vertex cube_v[24];
static uint32_t cube_i[36];
static mote_vertex quad_v[4];
static const uint32_t quad_i[6] = {0, 1, 2, 0, 2, 3};
static uint8_t tex_px[12 * 10 * 4];
static mote_texture tex = {12, 10, MOTE_FORMAT_RGBA8888, 0, tex_px}; /* not a power of two */

static void build_scene(void)
{
    static const float faces[6][3][3] = {
        {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, 1}, {-1, 0, 0}, {0, 1, 0}},
        {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},   {{-1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},   {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
    };
    static const float corners[4][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}};
    for (int f = 0; f < 6; f++) {
        for (int c = 0; c < 4; c++) {
            mote_vertex *v = &cube_v[f * 4 + c];
            for (int k = 0; k < 3; k++) {
                v->position[k] = faces[f][0][k] + corners[c][0] * faces[f][1][k] + corners[c][1] * faces[f][2][k];
                v->normal[k] = faces[f][0][k];
            }
            /* more than one repeat of the texture across a face */
            v->uv[0] = (corners[c][0] + 1.0f) * 0.75f;
            v->uv[1] = (1.0f - corners[c][1]) * 0.75f;
        }
        const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; k++)
            cube_i[f * 6 + k] = (uint32_t)(f * 4) + q[k];
    }
    for (int y = 0; y < tex.height; y++)
        for (int x = 0; x < tex.width; x++) {
            uint8_t *p = &tex_px[(y * tex.width + x) * 4];
            p[0] = (uint8_t)(x * 21);
            p[1] = (uint8_t)(y * 25);
            p[2] = (uint8_t)(((x ^ y) & 1) ? 230 : 40);
            p[3] = 255;
        }
}

/* A quad through the cube, tilted so that it cuts the cube's faces. */
static mote_mesh make_quad(float z0, float z1, mote_rgba color)
{
    const float p[4][3] = {{-2.0f, 1.6f, z0}, {2.0f, 1.6f, z1}, {2.0f, -1.6f, z1}, {-2.0f, -1.6f, z0}};
    for (int i = 0; i < 4; i++) {
        memset(&quad_v[i], 0, sizeof quad_v[i]);
        memcpy(quad_v[i].position, p[i], sizeof p[i]);
        quad_v[i].normal[2] = -1.0f;
    }
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = quad_v;
    m.vertex_count = 4;
    m.indices = quad_i;
    m.index_count = 6;
    m.material.color = color;
    m.material.color_set = true;
    return m;
}

static mote_frame_desc scene_frame(void)
{
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    const float eye[3] = {2.5f, 2.0f, -4.5f};
    memcpy(f.camera.position, eye, sizeof eye);
    f.camera.fov = 0.8f;
    f.camera.znear = 0.5f;
    f.camera.zfar = 20.0f;
    f.lights[0].type = MOTE_LIGHT_POINT;
    f.lights[0].position[0] = 3.0f;
    f.lights[0].position[1] = 5.0f;
    f.lights[0].position[2] = -6.0f;
    f.light_count = 1;
    f.ambient[0] = f.ambient[1] = f.ambient[2] = 0.2f;
    return f;
}

/* The draws under test: every mode, textured with either filter. */
typedef struct variant {
    const char *name;
    mote_mode mode;
    mote_filter filter;
} variant;

static const variant variants[] = {
    {"points", MOTE_MODE_POINTS, MOTE_FILTER_NEAREST},
    {"wireframe", MOTE_MODE_WIREFRAME, MOTE_FILTER_NEAREST},
    {"flat", MOTE_MODE_FLAT, MOTE_FILTER_NEAREST},
    {"gouraud", MOTE_MODE_GOURAUD, MOTE_FILTER_NEAREST},
    {"textured nearest", MOTE_MODE_TEXTURED, MOTE_FILTER_NEAREST},
    {"textured bilinear", MOTE_MODE_TEXTURED, MOTE_FILTER_BILINEAR},
};
#define VARIANTS (int)(sizeof variants / sizeof variants[0])

/* ---- rendering into a whole frame, directly or band by band ------------- */

/* A band's transfer as a DMA would make it: the flush only notes it, and
 * the rows are copied when mote waits for the buffer (or at the frame's
 * end), so a band drawn into a buffer still in flight would show. */
typedef struct transfer {
    const uint8_t *color;
    int y0, rows, stride;
} transfer;

typedef struct assembly {
    uint8_t *frame;               /* the whole image */
    int row_bytes;
    int next_row;
    bool in_order;
    bool deferred;                /* copy at flush_wait, not at flush */
    transfer pending[2];
    int waits;
} assembly;

static void copy_rows(assembly *a, const transfer *t)
{
    for (int y = 0; y < t->rows; y++)
        memcpy(a->frame + (size_t)(t->y0 + y) * (size_t)a->row_bytes,
               t->color + (size_t)y * (size_t)t->stride, (size_t)a->row_bytes);
}

static void flush_rows(void *user, int y0, int rows, const void *color, int stride)
{
    assembly *a = user;
    if (y0 != a->next_row)
        a->in_order = false;
    transfer t = {color, y0, rows, stride};
    a->next_row = y0 + rows;
    if (!a->deferred) {
        copy_rows(a, &t);
        return;
    }
    for (int i = 0; i < 2; i++)
        if (!a->pending[i].color) {
            a->pending[i] = t;
            return;
        }
    TEST_FAIL_MESSAGE("a third transfer started while two were in flight");
}

static void wait_rows(void *user, const void *color)
{
    assembly *a = user;
    a->waits++;
    for (int i = 0; i < 2; i++)
        if (a->pending[i].color == color) {
            copy_rows(a, &a->pending[i]);
            a->pending[i].color = NULL;
        }
}

static uint8_t band_color[W * H * MAX_BPP], band_back[W * H * MAX_BPP];
static uint32_t band_depth[W * H];
static uint16_t band_bins[64];

/* Band options of render(): band bins (large enough, or too small for the
 * frame's triangles), double buffering with deferred transfers. */
enum { BAND_BINS = 1, BAND_FEW_BINS = 2, BAND_DOUBLE = 4, BAND_OPTIONS = 8 };

/* Renders the cube and the quad with variant v into frame (W * H pixels of
 * fmt); band_height 0 renders the full frame into it, band_height H into a
 * separate buffer of H rows (a device is in band mode only below H). */
static void render_with(const variant *v, mote_format fmt, mote_depth_format dfmt, int band_height,
                        int options, uint8_t *frame)
{
    mote_device *dev = malloc(sizeof *dev);
    TEST_ASSERT_NOT_NULL(dev);
    assembly a = {frame, W * mote_format_bytes(fmt), 0, true, false, {{0}, {0}}, 0};
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = W;
    d.height = H;
    d.color_format = fmt;
    d.depth_format = dfmt;
    d.depth = dfmt == MOTE_DEPTH_FORMAT_NONE ? NULL : band_depth;
    d.clear_color = (mote_rgba){30, 60, 90, 255};
    if (band_height >= H) {
        d.color = band_color;
        d.band_height = H;
    } else if (band_height > 0) {
        d.color = band_color;
        d.band_height = band_height;
        d.flush = flush_rows;
        d.flush_user = &a;
        if (options & (BAND_BINS | BAND_FEW_BINS)) {
            d.band_bins = band_bins;
            d.band_bins_size = options & BAND_BINS ? sizeof band_bins : 10;
        }
        if (options & BAND_DOUBLE) {
            d.color_back = band_back;
            d.flush_wait = wait_rows;
            a.deferred = true;
        }
    } else {
        d.color = frame;
    }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(dev, &d));
    mote_frame_desc f = scene_frame();
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(dev, &f));

    mote_mesh cube;
    memset(&cube, 0, sizeof cube);
    cube.vertices = cube_v;
    cube.vertex_count = 24;
    cube.indices = cube_i;
    cube.index_count = 36;
    cube.rotation[1] = 0.6f;
    cube.rotation[0] = 0.3f;
    cube.material.texture = &tex;
    cube.material.color = (mote_rgba){255, 220, 200, 255};
    cube.material.color_set = true;
    mote_mesh quad = make_quad(-0.5f, 0.5f, (mote_rgba){120, 255, 90, 255});

    mote_draw_desc dd;
    memset(&dd, 0, sizeof dd);
    dd.mode = v->mode;
    dd.filter = v->filter;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(dev, &cube, &dd));
    dd.cull = MOTE_CULL_NONE;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(dev, &quad, &dd));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(dev));
    if (band_height >= H) {
        memcpy(frame, band_color, (size_t)(a.row_bytes * H));
    } else if (band_height > 0) {
        TEST_ASSERT_TRUE_MESSAGE(a.in_order, "bands were not flushed top to bottom");
        TEST_ASSERT_EQUAL_INT(H, a.next_row);
        /* the transfers still in flight land now, as the caller would wait */
        for (int i = 0; i < 2; i++) {
            if (a.pending[i].color)
                copy_rows(&a, &a.pending[i]);
        }
        if ((options & BAND_DOUBLE) && H / band_height > 2) {
            TEST_ASSERT_TRUE_MESSAGE(a.waits > 0, "no buffer was waited for");
        }
    }
    free(dev);
}

static void render(const variant *v, mote_format fmt, mote_depth_format dfmt, int band_height,
                   uint8_t *frame)
{
    render_with(v, fmt, dfmt, band_height, 0, frame);
}

static uint8_t frame_a[W * H * MAX_BPP], frame_b[W * H * MAX_BPP], frame_c[W * H * MAX_BPP];

/* How many pixels of an RGBA frame are not the clear colour. */
static int drawn_pixels(const uint8_t *rgba)
{
    int n = 0;
    for (int i = 0; i < W * H; i++)
        n += !(rgba[4 * i] == 30 && rgba[4 * i + 1] == 60 && rgba[4 * i + 2] == 90);
    return n;
}

/* ---- tests ----------------------------------------------------------------- */

void every_format_should_equal_the_rgba_render_converted_in_every_mode(void)
{
    char msg[128];
    for (int vi = 0; vi < VARIANTS; vi++) {
        render(&variants[vi], MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, 0, frame_a);
        snprintf(msg, sizeof msg, "%s draws something", variants[vi].name);
        TEST_ASSERT_TRUE_MESSAGE(drawn_pixels(frame_a) > (vi == 0 ? 10 : 300), msg);
        for (int fi = 1; fi < 4; fi++) {
            mote_format fmt = formats[fi];
            int row = W * mote_format_bytes(fmt);
            render(&variants[vi], fmt, MOTE_DEPTH_FORMAT_32, 0, frame_b);
            for (int y = 0; y < H; y++)
                mote_convert_row(frame_a + y * W * 4, MOTE_FORMAT_RGBA8888, frame_c + y * row, fmt, W);
            snprintf(msg, sizeof msg, "%s in %s", variants[vi].name, format_names[fmt]);
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(frame_c, frame_b, (size_t)(row * H), msg);
        }
    }
}

void rgb565_swapped_should_be_the_byte_swap_of_rgb565(void)
{
    for (int vi = 0; vi < VARIANTS; vi++) {
        render(&variants[vi], MOTE_FORMAT_RGB565, MOTE_DEPTH_FORMAT_16, 0, frame_a);
        render(&variants[vi], MOTE_FORMAT_RGB565_SWAPPED, MOTE_DEPTH_FORMAT_16, 0, frame_b);
        for (int i = 0; i < W * H; i++) {
            frame_c[2 * i] = frame_a[2 * i + 1];
            frame_c[2 * i + 1] = frame_a[2 * i];
        }
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(frame_c, frame_b, (size_t)(W * H * 2), variants[vi].name);
    }
}

void bands_of_any_height_should_equal_the_full_frame_in_every_format_depth_and_mode(void)
{
    static const int heights[] = {1, 2, 3, 7, 16, 64, H};
    char msg[160];
    for (int vi = 0; vi < VARIANTS; vi++)
        for (int fi = 0; fi < 4; fi++)
            for (int di = 0; di < 3; di++) {
                mote_format fmt = formats[fi];
                size_t bytes = (size_t)(W * H * mote_format_bytes(fmt));
                render(&variants[vi], fmt, depths[di], 0, frame_a);
                for (int hi = 0; hi < (int)(sizeof heights / sizeof heights[0]); hi++)
                    for (int o = 0; o < BAND_OPTIONS; o++) {
                        if ((o & BAND_BINS) && (o & BAND_FEW_BINS))
                            continue;
                        memset(frame_b, 0xa5, sizeof frame_b);
                        render_with(&variants[vi], fmt, depths[di], heights[hi], o, frame_b);
                        snprintf(msg, sizeof msg, "%s, %s, %s, bands of %d rows%s%s%s", variants[vi].name,
                                 format_names[fmt], depth_names[depths[di]], heights[hi],
                                 o & BAND_BINS ? ", band bins" : "", o & BAND_FEW_BINS ? ", too few bins" : "",
                                 o & BAND_DOUBLE ? ", double-buffered" : "");
                        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(frame_a, frame_b, bytes, msg);
                    }
            }
}

/* One quad of the depth test, drawn alone or after another. */
static void draw_quads(mote_depth_format dfmt, const mote_mesh *first, const mote_mesh *second,
                       uint8_t *rgba, uint32_t *depth_out)
{
    static mote_device dev;
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = W;
    d.height = H;
    d.color = rgba;
    d.depth_format = dfmt;
    d.depth = band_depth;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    mote_frame_desc f = scene_frame();
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
    mote_draw_desc dd;
    memset(&dd, 0, sizeof dd);
    dd.mode = MOTE_MODE_GOURAUD;
    dd.cull = MOTE_CULL_NONE;
    dd.unlit = true;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, first, &dd));
    if (second)
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, second, &dd));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    for (int i = 0; i < W * H; i++)
        depth_out[i] = dfmt == MOTE_DEPTH_FORMAT_16 ? ((const uint16_t *)(const void *)band_depth)[i]
                                                    : band_depth[i];
}

/* A 16-bit depth is the 24-bit one (rounded to nearest) rounded again. */
static uint32_t depth16_of(uint32_t d24)
{
    uint32_t d = (d24 + 128) >> 8;
    return d > 65535 ? 65535 : d;
}

void depth16_should_differ_from_depth32_only_where_16_bit_depths_tie(void)
{
    /* two quads crossing at a very shallow angle: a strip several pixels
     * wide where their 24-bit depths differ by less than 2^8 (a 16-bit tie) */
    static mote_vertex va[4], vb[4];
    mote_mesh a = make_quad(0.0f, 0.0f, (mote_rgba){255, 0, 0, 255});
    memcpy(va, quad_v, sizeof va);
    a.vertices = va;
    mote_mesh b = make_quad(0.002f, -0.002f, (mote_rgba){0, 0, 255, 255});
    memcpy(vb, quad_v, sizeof vb);
    b.vertices = vb;

    static uint8_t ca[W * H * 4], cb[W * H * 4], c32[W * H * 4], c16[W * H * 4];
    static uint32_t da[W * H], db[W * H], d32[W * H], d16[W * H];
    draw_quads(MOTE_DEPTH_FORMAT_32, &a, NULL, ca, da);
    draw_quads(MOTE_DEPTH_FORMAT_32, &b, NULL, cb, db);
    draw_quads(MOTE_DEPTH_FORMAT_32, &a, &b, c32, d32);
    draw_quads(MOTE_DEPTH_FORMAT_16, &a, &b, c16, d16);

    const uint32_t clear = (1u << 24) - 1u;
    int ties = 0, differing = 0, both = 0;
    for (int i = 0; i < W * H; i++) {
        bool in_a = da[i] < clear, in_b = db[i] < clear;
        both += in_a && in_b;
        /* b replaces a only when strictly nearer, at the buffer's precision;
         * where neither quad is, ca holds the clear colour */
        bool b32 = in_b && (!in_a || db[i] < da[i]);
        bool b16 = in_b && (!in_a || depth16_of(db[i]) < depth16_of(da[i]));
        TEST_ASSERT_EQUAL_MEMORY((b32 ? cb : ca) + 4 * i, c32 + 4 * i, 4);
        TEST_ASSERT_EQUAL_MEMORY((b16 ? cb : ca) + 4 * i, c16 + 4 * i, 4);
        TEST_ASSERT_EQUAL_UINT32(depth16_of(d32[i]), d16[i]); /* the nearest depth, at 16 bits */
        bool tie = in_a && in_b && depth16_of(da[i]) == depth16_of(db[i]);
        ties += tie;
        if (memcmp(c32 + 4 * i, c16 + 4 * i, 4) != 0) {
            TEST_ASSERT_TRUE_MESSAGE(tie, "depth 16 and 32 differ where 16-bit depths do not tie");
            differing++;
        }
    }
    /* the scene does exercise ties, and some of them do change the image */
    TEST_ASSERT_GREATER_THAN_INT(W * H / 4, both);
    TEST_ASSERT_GREATER_THAN_INT(0, ties);
    TEST_ASSERT_GREATER_THAN_INT(0, differing);
}

static void count_triangle(void *user, const int32_t x[3], const int32_t y[3], const float z[3], const float w[3])
{
    (void)x, (void)y, (void)z, (void)w;
    ++*(int *)user;
}

/* The triangles set up in a frame of 1-row bands: with band bins, each in
 * the bands it touches; without, each in every band. */
static int triangles_set_up(bool bins)
{
    static mote_device dev;
    int calls = 0;
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = W;
    d.height = H;
    d.color = band_color;
    d.depth = band_depth;
    d.band_height = 1;
    d.flush = flush_rows;
    assembly a = {frame_b, W * 4, 0, true, false, {{0}, {0}}, 0};
    d.flush_user = &a;
    d.band_bins = bins ? band_bins : NULL;
    d.band_bins_size = sizeof band_bins;
    d.triangle_hook = count_triangle;
    d.triangle_hook_user = &calls;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    mote_frame_desc f = scene_frame();
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
    mote_mesh quad = make_quad(-0.5f, 0.5f, (mote_rgba){120, 255, 90, 255});
    quad.scaling[0] = quad.scaling[1] = 0.2f;   /* a few rows high */
    quad.scaling[2] = 1.0f;
    mote_draw_desc dd;
    memset(&dd, 0, sizeof dd);
    dd.mode = MOTE_MODE_GOURAUD;
    dd.cull = MOTE_CULL_NONE;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &quad, &dd));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_EQUAL_UINT32(2, mote_device_stats(&dev)->triangles_drawn);
    return calls;
}

void band_bins_should_set_up_a_triangle_only_in_the_bands_it_touches(void)
{
    int replayed = triangles_set_up(false), binned = triangles_set_up(true);
    TEST_ASSERT_EQUAL_INT(2 * H, replayed);
    /* the quad covers a fifth of the rows: each triangle in its rows' bands
     * (one more at most at either end), plus the first band's visit */
    TEST_ASSERT_TRUE_MESSAGE(binned < replayed / 3, "band bins did not skip the bands a triangle misses");
    TEST_ASSERT_TRUE(binned >= 2);
}

void band_bins_bytes_should_be_two_a_triangle_in_band_mode_only(void)
{
    TEST_ASSERT_EQUAL_UINT64(2 * 966, mote_band_bins_bytes(240, 30, 966));
    TEST_ASSERT_EQUAL_UINT64(0, mote_band_bins_bytes(240, 240, 966));   /* full frame */
    TEST_ASSERT_EQUAL_UINT64(0, mote_band_bins_bytes(300, 1, 966));     /* more than 255 bands */
    TEST_ASSERT_EQUAL_UINT64(0, mote_band_bins_bytes(0, 1, 966));
}

void a_320x240_rgb565_depth16_frame_should_fit_in_48_kb_in_bands_of_30_rows(void)
{
    /* 30 rows: 240 / 30 = 8 bands; each band replays every draw, so the
     * tallest band that fits is the cheapest in time */
    size_t band = mote_band_bytes(320, 30, MOTE_FORMAT_RGB565, MOTE_DEPTH_FORMAT_16);
    TEST_ASSERT_EQUAL_UINT32(320u * 30u * (2u + 2u), (uint32_t)band);
    /* this build's device (64-bit pointers, MOTE_MAX_DRAWS as configured) is
     * at least as large as a 32-bit firmware's */
    TEST_ASSERT_LESS_OR_EQUAL_UINT32(48u * 1024u, (uint32_t)(band + sizeof(mote_device)));
    /* and two other layouts: bands of 16 rows, a whole RGBA8888 frame */
    TEST_ASSERT_EQUAL_UINT32(320u * 16u * 4u, (uint32_t)mote_band_bytes(320, 16, MOTE_FORMAT_RGB565,
                                                                        MOTE_DEPTH_FORMAT_16));
    TEST_ASSERT_EQUAL_UINT32(320u * 240u * 8u, (uint32_t)mote_band_bytes(320, 240, MOTE_FORMAT_RGBA8888,
                                                                         MOTE_DEPTH_FORMAT_32));
    TEST_ASSERT_EQUAL_UINT32(320u * 8u, (uint32_t)mote_band_bytes(320, 8, MOTE_FORMAT_GREY8,
                                                                  MOTE_DEPTH_FORMAT_NONE));
    TEST_ASSERT_EQUAL_UINT32(0u, (uint32_t)mote_band_bytes(0, 8, MOTE_FORMAT_GREY8, MOTE_DEPTH_FORMAT_16));
}

int main(void)
{
    build_scene();
    UNITY_BEGIN();
    RUN_TEST(every_format_should_equal_the_rgba_render_converted_in_every_mode);
    RUN_TEST(rgb565_swapped_should_be_the_byte_swap_of_rgb565);
    RUN_TEST(bands_of_any_height_should_equal_the_full_frame_in_every_format_depth_and_mode);
    RUN_TEST(depth16_should_differ_from_depth32_only_where_16_bit_depths_tie);
    RUN_TEST(band_bins_should_set_up_a_triangle_only_in_the_bands_it_touches);
    RUN_TEST(band_bins_bytes_should_be_two_a_triangle_in_band_mode_only);
    RUN_TEST(a_320x240_rgb565_depth16_frame_should_fit_in_48_kb_in_bands_of_30_rows);
    return UNITY_END();
}
