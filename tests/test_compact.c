/*
 * test_compact.c - compact meshes (mote_compact: int16 positions and uvs,
 * int8 or int16 normals, 16-bit indices), which a draw dequantises through
 * its matrices. Built twice by `make test`: with the float vertex stage and
 * with the integer one (tests/fixed/fixed.mk).
 */
#include <mote/mote.h>

#include "support/scenes.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 160, H = 120, MAXV = 4096, MAXI = 3 * 8192 };

static char msg[256];

void setUp(void)
{
}

void tearDown(void)
{
}

/* One mesh's compact arrays and the float mesh of the values they stand for. */
typedef struct compact_mesh {
    int16_t positions[3 * MAXV], uvs[2 * MAXV], normals16[3 * MAXV];
    int8_t normals8[3 * MAXV];
    uint16_t indices[MAXI];
    mote_vertex dequantised[MAXV];
    mote_compact c;
    mote_mesh mesh, as_floats;
} compact_mesh;

static long quantise(double x, double scale, double offset)
{
    double q = scale > 0 ? floor((x - offset) / scale + 0.5) : 0;
    return q > 32767 ? 32767 : q < -32767 ? -32767 : (long)q;
}

/* scale and offset of n values: the box in 32767ths of its half (power:
 * a power of two scale about 0, so that the dequantised floats are exact) */
static void quantiser(const float *v, uint32_t n, int stride, bool power, float *scale, float *offset)
{
    double lo = v[0], hi = v[0];
    for (uint32_t i = 1; i < n; i++) {
        double x = v[(size_t)i * (size_t)stride];
        lo = x < lo ? x : lo;
        hi = x > hi ? x : hi;
    }
    if (power) {
        double m = fmax(fabs(lo), fabs(hi));
        *offset = 0.0f;
        *scale = m > 0 ? (float)ldexp(1.0, (int)ceil(log2(m / 32767.0))) : 0.0f;
    } else {
        *offset = (float)(0.5 * (lo + hi));
        *scale = (float)((hi - lo) * 0.5 * (1 + 1e-6) / 32767.0);
    }
}

/* m as a compact mesh, 8- or 16-bit normals; as_floats is m with the
 * compact values' vertices (positions and uvs dequantised in double,
 * normals as the stored integers). */
static void make_compact(const mote_mesh *m, bool power, bool normals16, compact_mesh *out)
{
    TEST_ASSERT_TRUE(m->vertex_count <= MAXV && m->index_count <= MAXI);
    memset(&out->c, 0, sizeof out->c);
    const uint32_t n = m->vertex_count;
    for (int k = 0; k < 3; k++)
        quantiser(&m->vertices[0].position[k], n, 8, power, &out->c.scale[k], &out->c.offset[k]);
    for (int k = 0; k < 2; k++)
        quantiser(&m->vertices[0].uv[k], n, 8, power, &out->c.uv_scale[k], &out->c.uv_offset[k]);
    const double nmax = normals16 ? 32767.0 : 127.0;
    for (uint32_t i = 0; i < n; i++) {
        const mote_vertex *v = &m->vertices[i];
        mote_vertex *d = &out->dequantised[i];
        double len = sqrt((double)v->normal[0] * v->normal[0] + (double)v->normal[1] * v->normal[1]
                          + (double)v->normal[2] * v->normal[2]);
        for (int k = 0; k < 3; k++) {
            long q = quantise(v->position[k], out->c.scale[k], out->c.offset[k]);
            out->positions[3 * i + k] = (int16_t)q;
            d->position[k] = (float)((double)q * out->c.scale[k] + out->c.offset[k]);
            long nq = len > 0 ? (long)floor(v->normal[k] / len * nmax + 0.5) : 0;
            out->normals8[3 * i + k] = (int8_t)(normals16 ? 0 : nq);
            out->normals16[3 * i + k] = (int16_t)(normals16 ? nq : 0);
            d->normal[k] = (float)nq;
        }
        for (int k = 0; k < 2; k++) {
            long q = quantise(v->uv[k], out->c.uv_scale[k], out->c.uv_offset[k]);
            out->uvs[2 * i + k] = (int16_t)q;
            d->uv[k] = (float)((double)q * out->c.uv_scale[k] + out->c.uv_offset[k]);
        }
    }
    for (uint32_t i = 0; i < m->index_count; i++)
        out->indices[i] = (uint16_t)m->indices[i];
    out->c.positions = out->positions;
    out->c.uvs = out->uvs;
    if (normals16)
        out->c.normals16 = out->normals16;
    else
        out->c.normals8 = out->normals8;
    out->c.indices = out->indices;
    out->mesh = *m;
    out->mesh.vertices = NULL;
    out->mesh.indices = NULL;
    out->mesh.compact = &out->c;
    out->as_floats = *m;
    out->as_floats.vertices = out->dequantised;
}

/* Renders n meshes with the scene's frame, over a transparent clear (so
 * alpha says which pixels were drawn). */
static void render(const tu_scene *s, const mote_mesh *meshes, mote_mode mode, uint8_t *rgba)
{
    static uint32_t depth[W * H];
    static mote_device dev;
    mote_device_desc desc = {.width = W, .height = H, .color = rgba, .depth = depth};
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &desc));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &s->frame));
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.mode = mode;
    d.cull = MOTE_CULL_NONE;
    for (int i = 0; i < s->mesh_count; i++)
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &meshes[i], &d));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
}

static compact_mesh store[TU_SCENE_MAX_MESHES];

/* The scenes without vertex colours (compact meshes have none here), each
 * mesh made compact; *drawn and *far count the pixels drawn by both and
 * those of them more than 2 LSB apart, *cover those drawn by one only. */
static void compare_scenes(bool power, bool normals16, bool expect_same)
{
    static uint8_t a[W * H * 4], b[W * H * 4];
    static const mote_mode modes[] = {MOTE_MODE_FLAT, MOTE_MODE_GOURAUD, MOTE_MODE_TEXTURED};
    for (int k = 0; k < TU_SCENE_COUNT; k++) {
        if (k == TU_SCENE_COLORS)
            continue;
        tu_scene s;
        tu_scene_build(k, MOTE_WRAP_REPEAT, &s);
        mote_mesh compact[TU_SCENE_MAX_MESHES], floats[TU_SCENE_MAX_MESHES];
        for (int i = 0; i < s.mesh_count; i++) {
            make_compact(&s.meshes[i], power, normals16, &store[i]);
            compact[i] = store[i].mesh;
            floats[i] = store[i].as_floats;
        }
        for (size_t mi = 0; mi < sizeof modes / sizeof modes[0]; mi++) {
            render(&s, floats, modes[mi], a);
            render(&s, compact, modes[mi], b);
            long drawn = 0, far = 0, cover = 0;
            for (int p = 0; p < W * H; p++) {
                bool da = a[4 * p + 3] != 0, db = b[4 * p + 3] != 0;
                cover += da != db;
                if (!(da && db))
                    continue;
                drawn++;
                for (int c = 0; c < 3; c++)
                    if (abs(a[4 * p + c] - b[4 * p + c]) > 2) {
                        far++;
                        break;
                    }
            }
            snprintf(msg, sizeof msg, "%s, mode %d: %ld drawn, %ld more than 2 LSB apart, %ld drawn by one only",
                     s.name, (int)modes[mi], drawn, far, cover);
            if (expect_same) {
                TEST_ASSERT_EQUAL_MEMORY_MESSAGE(a, b, sizeof a, msg);
            } else {
                TEST_ASSERT_TRUE_MESSAGE(drawn > 1000, msg);
                TEST_ASSERT_TRUE_MESSAGE(far * 200 <= drawn, msg);    /* 0.5% */
                TEST_ASSERT_TRUE_MESSAGE(cover * 200 <= drawn, msg);
            }
        }
    }
}

/* With powers of two for scales, the compact values are exact floats: the
 * float stage, which folds the scale into the matrix, draws the same bytes
 * as the float mesh of those values. The integer stage reads the two at
 * different precisions (16 and 24 bits): pixels along edges may differ. */
void a_compact_mesh_should_draw_as_the_float_mesh_of_its_values(void)
{
    compare_scenes(true, false, !MOTE_FIXED_VERTEX);
}

/* Scaled to each axis's box, as mote-bake does, with 8- and 16-bit normals. */
void a_compact_mesh_should_draw_within_2_lsb_of_its_dequantised_mesh(void)
{
    compare_scenes(false, false, false);
    compare_scenes(false, true, false);
}

/* No normals and no uvs: zero normals and uv 0, drawn without fault. */
void a_compact_mesh_without_normals_or_uvs_should_draw(void)
{
    static uint8_t a[W * H * 4];
    tu_scene s;
    tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, &s);
    mote_mesh compact[TU_SCENE_MAX_MESHES];
    for (int i = 0; i < s.mesh_count; i++) {
        make_compact(&s.meshes[i], false, false, &store[i]);
        store[i].c.normals8 = NULL;
        store[i].c.uvs = NULL;
        compact[i] = store[i].mesh;
    }
    render(&s, compact, MOTE_MODE_TEXTURED, a);
    long drawn = 0;
    for (int p = 0; p < W * H; p++)
        drawn += a[4 * p + 3] != 0;
    TEST_ASSERT_TRUE(drawn > 1000);
}

/* mote_mesh_update_bounds reads a compact mesh's dequantised positions. */
void bounds_of_a_compact_mesh_should_be_in_its_own_space(void)
{
    tu_scene s;
    tu_scene_build(TU_SCENE_GOURAUD, MOTE_WRAP_REPEAT, &s);
    make_compact(&s.meshes[0], false, false, &store[0]);
    mote_mesh c = store[0].mesh, f = store[0].as_floats;
    mote_mesh_update_bounds(&c);
    mote_mesh_update_bounds(&f);
    TEST_ASSERT_TRUE(c.bounds_radius > 0.0f);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f * f.bounds_radius, f.bounds_radius, c.bounds_radius);
    for (int k = 0; k < 3; k++)
        TEST_ASSERT_FLOAT_WITHIN(1e-5f * f.bounds_radius, f.bounds_center[k], c.bounds_center[k]);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(a_compact_mesh_should_draw_as_the_float_mesh_of_its_values);
    RUN_TEST(a_compact_mesh_should_draw_within_2_lsb_of_its_dequantised_mesh);
    RUN_TEST(a_compact_mesh_without_normals_or_uvs_should_draw);
    RUN_TEST(bounds_of_a_compact_mesh_should_be_in_its_own_space);
    return UNITY_END();
}
