/*
 * test_vertex.c - the vertex stage's four-vertex path (vertex.c on SSE2
 * hosts) against the scalar one, value by value: the snap, the rounding
 * of texels and depths, and the light model (light.h) in both
 * instantiations.
 *
 * On SSE2 hosts a full vertex cache is transformed four vertices at a
 * time (vertex.c, mote__transform4), and the snap to sub-pixels goes
 * through double arithmetic (mote__v4_snap_axis) where the scalar path,
 * the one every microcontroller runs, splits the float into mantissa and
 * exponent (clip.c, mote__snap_axis). Frames compare the two only on the
 * values a scene happens to produce; this file compiles vertex.c a second time
 * and holds them to the same answer on the values where rounding is
 * decided: exact ties (n h = j + 1/2), their neighbouring floats, every
 * exponent, zero, denormals, NaN, infinities and the limit's edges, for
 * each sub-pixel precision and several viewport sizes.
 *
 * Threshold: 0 differences (whether the snap succeeds, and its value).
 */
#include "core/internal.h"
/* its functions under other names: the library has them too */
#define mote__vertex_begin vertex_test_vertex_begin
#define mote__light_at vertex_test_light_at
#define mote__normalize vertex_test_normalize
#define mote__tint vertex_test_tint
#define mote__shade_fixed vertex_test_shade_fixed
#define mote__to_setup vertex_test_to_setup
#define mote__finish vertex_test_finish
#define mote__finish4 vertex_test_finish4
#define mote__v4_light_init vertex_test_v4_light_init
#define mote__transform_range vertex_test_transform_range
#define mote__vertex vertex_test_vertex
#include "core/vertex.c"

#include "support/testutil.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#if MOTE__VECTOR_VERTEX && MOTE__VECTOR_SNAP
static float float_from_bits(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* mote__v4_snap_by with one h and lim in every lane, as a draw sets them */
static mote__v4i mote__v4_snap_axis(mote__v4f n, int32_t h, int32_t lim, mote__v4i *ok)
{
    return mote__v4_snap_by(n, _mm_set1_pd((double)h), (mote__v4i){h, h, h, h}, (mote__v4i){lim, lim, lim, lim}, ok);
}

/* Snaps four values both ways; returns the lanes that differ. */
static int compare_four(const float n[4], int32_t h, int32_t lim)
{
    mote__v4i ok;
    mote__v4i v = mote__v4_snap_axis((mote__v4f){n[0], n[1], n[2], n[3]}, h, lim, &ok);
    int differ = 0;
    for (int i = 0; i < 4; i++) {
        int32_t s = 0;
        bool sok = mote__snap_axis(n[i], h, lim, &s);
        differ += sok != (ok[i] != 0) || (sok && s != v[i]);
    }
    return differ;
}

void vector_snap_should_match_the_scalar_snap(void)
{
    tu_rng rng = tu_rng_seed(20261124);
    const int sizes[] = {1, 97, 640, 1920, 4095, MOTE_MAX_SIZE};
    long compared = 0, differ = 0, ties = 0;
    for (int F = 4; F <= 8; F++) {
        const int32_t lim = (int32_t)1 << (MOTE_GUARD_BITS + 1 + F);
        for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
            const int32_t h = sizes[si] << (F - 1);
            float n[4];
            int lane = 0;
            for (int k = 0; k < 40000; k++) {
                float f;
                switch (k % 4) {
                case 0:   /* any bits: every exponent, NaN, infinities, denormals */
                    f = float_from_bits((uint32_t)tu_rand_u64(&rng));
                    break;
                case 1: { /* a tie n h = j + 1/2 where a float holds it, or the float nearest */
                    int64_t j = tu_rand_int(&rng, -(int64_t)lim - 2 * h, (int64_t)lim);
                    f = (float)(((double)j + 0.5) / (double)h);
                    ties += (double)f * (double)h == (double)j + 0.5;
                    break;
                }
                case 2: { /* a neighbour of a tie, one or two floats away */
                    int64_t j = tu_rand_int(&rng, -(int64_t)lim - 2 * h, (int64_t)lim);
                    f = (float)(((double)j + 0.5) / (double)h);
                    uint32_t u;
                    memcpy(&u, &f, sizeof u);
                    u += (uint32_t)tu_rand_int(&rng, -2, 2);
                    f = float_from_bits(u);
                    break;
                }
                default:  /* around the limit: where the snap starts failing */
                    f = (float)((double)((tu_rand_u64(&rng) & 1) ? lim : -lim) / (double)h
                                + tu_rand_range(&rng, -2.0, 2.0) / (double)h) - 1.0f;
                    break;
                }
                n[lane++] = f;
                if (lane == 4) {
                    differ += compare_four(n, h, lim);
                    compared += 4;
                    lane = 0;
                }
            }
        }
        /* the edge values themselves */
        const float special[] = {0.0f, -0.0f, 1e-45f, -1e-45f, 1.17549435e-38f, 0.5f, -0.5f, 1.0f, -1.0f,
                                 INFINITY, -INFINITY, NAN, 3.4028235e38f, -3.4028235e38f, 1073741824.0f,
                                 -1073741824.0f};
        for (size_t i = 0; i + 4 <= sizeof special / sizeof special[0]; i += 4)
            for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
                differ += compare_four(&special[i], sizes[si] << (F - 1), lim);
                compared += 4;
            }
    }
    TEST_ASSERT_EQUAL_INT(0, differ);
    TEST_ASSERT_GREATER_THAN_INT(1000000, compared);
    TEST_ASSERT_GREATER_THAN_INT(10000, ties);   /* exact ties were really met */
}
#else
void vector_snap_should_match_the_scalar_snap(void)
{
    TEST_IGNORE_MESSAGE("no vector snap on this host (SSE2 with GCC or clang)");
}
#endif

#if MOTE__VECTOR_VERTEX
/* A float near x: x itself, or one or two floats to either side. */
static float near_float(tu_rng *rng, double x)
{
    float f = (float)x;
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    u += (uint32_t)tu_rand_int(rng, -2, 2);
    return float_from_bits(u);
}

/* The four-vertex finish rounds texels (16.16, halves away from zero) in
 * double and depths (halves up) in float lanes; every microcontroller
 * runs mote__round_scaled. Held to the same answer on random values of
 * the ranges they take (texels within 1e9, depths in [0, 2^24)), on the
 * ties and on their neighbouring floats. */
void vector_texel_and_depth_rounding_should_match_the_scalar_rounding(void)
{
    tu_rng rng = tu_rng_seed(20261125);
    long compared = 0, differ = 0;
    for (int k = 0; k < 400000; k++) {
        mote__cvert c;
        memset(&c, 0, sizeof c);
        float d[4];
        for (int lane = 0; lane < 2; lane++) {
            float x;
            if (k % 3 == 0) {     /* any magnitude up to 1e9 */
                x = (float)(tu_rand_range(&rng, -1.0, 1.0) * pow(10.0, tu_rand_range(&rng, -12.0, 9.0)));
            } else {              /* a tie j + 1/2 in 16.16 units, or a float next to it */
                int64_t j = tu_rand_int(&rng, -((int64_t)1 << 40), (int64_t)1 << 40) >> tu_rand_int(&rng, 0, 40);
                x = near_float(&rng, ((double)j + 0.5) / 65536.0);
            }
            if (lane == 0)
                c.u = x;
            else
                c.v = x;
        }
        int64_t t[2];
        mote__texels_fixed(&c, t);
        differ += t[0] != mote__round_scaled(c.u, 16) || t[1] != mote__round_scaled(c.v, 16);
        for (int lane = 0; lane < 4; lane++) {
            int64_t j = tu_rand_int(&rng, 0, ((int64_t)1 << 24) - 2);
            d[lane] = (k + lane) % 2 ? (float)tu_rand_range(&rng, 0.0, 16777215.0)
                                     : near_float(&rng, (double)j + 0.5);
            d[lane] = d[lane] < 0.0f ? 0.0f : d[lane];
        }
        mote__v4i z = mote__v4_round_depth((mote__v4f){d[0], d[1], d[2], d[3]});
        for (int lane = 0; lane < 4; lane++)
            differ += z[lane] != mote__round_scaled(d[lane], 0);
        compared += 6;
    }
    TEST_ASSERT_EQUAL_INT(0, differ);
    TEST_ASSERT_GREATER_THAN_INT(2000000, compared);
}
#else
void vector_texel_and_depth_rounding_should_match_the_scalar_rounding(void)
{
    TEST_IGNORE_MESSAGE("no four-vertex finish on this host (SSE2 with GCC or clang)");
}
#endif

#if MOTE__VECTOR_VERTEX
/* One definition of the light model (light.h), instantiated for one
 * vertex and for four: every lane must give the scalar bits, for every
 * light type, ranges, cones, hemispheric ground colours, emissive colours,
 * normals facing away and degenerate light vectors. */
void light_model_in_four_lanes_should_match_the_scalar_model(void)
{
    tu_rng rng = tu_rng_seed(20260317);
    static mote_device dev;
    long compared = 0, differ = 0;
    for (int k = 0; k < 2000; k++) {
        memset(&dev, 0, sizeof dev);
        mote_frame_desc *f = &dev.frame;
        f->light_count = (int)tu_rand_int(&rng, 0, MOTE_MAX_LIGHTS);
        for (int c = 0; c < 3; c++)
            f->ambient[c] = (float)tu_rand_range(&rng, 0.0, 0.3);
        for (int i = 0; i < f->light_count; i++) {
            mote_light *l = &f->lights[i];
            l->type = (mote_light_type)tu_rand_int(&rng, 0, MOTE_LIGHT_TYPE_COUNT - 1);
            for (int c = 0; c < 3; c++) {
                l->position[c] = (float)tu_rand_range(&rng, -5.0, 5.0);
                l->direction[c] = (float)tu_rand_range(&rng, -1.0, 1.0);
                l->color[c] = k % 5 ? (float)tu_rand_range(&rng, 0.0, 1.0) : 0.0f;
                l->ground_color[c] = (float)tu_rand_range(&rng, 0.0, 0.5);
            }
            l->intensity = k % 7 ? (float)tu_rand_range(&rng, 0.0, 2.0) : 0.0f;
            l->range = k % 3 ? (float)tu_rand_range(&rng, 0.0, 8.0) : 0.0f;
            l->spot_angle = (float)tu_rand_range(&rng, 0.1, 3.0);
            l->spot_exponent = (float)tu_rand_range(&rng, 0.0, 4.0);
#if MOTE_ENABLE_LIGHT_FALLOFF
            dev.spot_cone[i][0] = mote__rsqrtf(mote__dot3(l->direction, l->direction));
            dev.spot_cone[i][1] = mote_cosf(0.5f * l->spot_angle);
#endif
        }
        float color[3], emissive[3];
        for (int c = 0; c < 3; c++) {
            color[c] = (float)tu_rand_range(&rng, 0.0, 1.0);
            emissive[c] = k % 2 ? (float)tu_rand_range(&rng, 0.0, 0.4) : 0.0f;
        }
        mote__lights one;
        mote__v4_lights four;
        mote__lights_prepare(&one, &dev, color, emissive, 0);
        mote__v4_lights_prepare(&four, &dev, color, emissive, 0);
        float p[4][3], n[4][3];
        for (int v = 0; v < 4; v++) {
            for (int c = 0; c < 3; c++) {
                p[v][c] = (float)tu_rand_range(&rng, -6.0, 6.0);
                n[v][c] = (float)tu_rand_range(&rng, -1.0, 1.0);
            }
            if (k % 11 == 0 && v == 0 && f->light_count > 0)   /* on the light itself */
                memcpy(p[v], f->lights[0].position, sizeof p[v]);
            mote__normalize(n[v]);
        }
        mote__v4f P[3], N[3], out4[3];
        for (int c = 0; c < 3; c++) {
            P[c] = (mote__v4f){p[0][c], p[1][c], p[2][c], p[3][c]};
            N[c] = (mote__v4f){n[0][c], n[1][c], n[2][c], n[3][c]};
        }
        mote__light4(&four, P, N, out4);
        for (int v = 0; v < 4; v++) {
            float out1[3];
            mote__light(&one, p[v], n[v], out1);
            for (int c = 0; c < 3; c++) {
                float lane = out4[c][v];
                differ += memcmp(&lane, &out1[c], sizeof lane) != 0;
                compared++;
            }
        }
    }
    TEST_ASSERT_EQUAL_INT(0, differ);
    TEST_ASSERT_GREATER_THAN_INT(20000, compared);
}
#else
void light_model_in_four_lanes_should_match_the_scalar_model(void)
{
    TEST_IGNORE_MESSAGE("no four-vertex lighting on this host (SSE2 with GCC or clang)");
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(vector_snap_should_match_the_scalar_snap);
    RUN_TEST(vector_texel_and_depth_rounding_should_match_the_scalar_rounding);
    RUN_TEST(light_model_in_four_lanes_should_match_the_scalar_model);
    return UNITY_END();
}
