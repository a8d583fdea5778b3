/*
 * test_setup_portable.c - setup's 128-bit products without __int128.
 *
 * Setup forms its attribute planes from 64x64-bit products shifted right
 * (mote__mul_shift). Hosts with __int128 take that path; 32-bit targets
 * (every microcontroller) take a portable one built from 32-bit halves,
 * which only the emulated-board check (make test-embedded) ran before.
 * This file compiles setup.c a second time with MOTE_NO_INT128 (and the
 * 32-bit cores' MOTE__CORE32 paths, with ARMv6-M's MOTE__NO_UMULL ones:
 * products from 16-bit halves, the depth plane's division by a
 * reciprocal) and holds
 * the two to the same bits: the products on edge values, the division
 * against C's at multiples of the divisor and either side of them, and
 * whole triangles from a pixel's sliver to the guard band's size, compared
 * field by field with the library's setup.
 *
 * Thresholds: 0 differing products, 0 differing quotients (some 2,000
 * divisors, 380 dividends each) and 0 differing triangles over 300,000
 * seeded random triangles (affine and perspective-correct).
 */
#define MOTE__CORE32 1              /* before any header: setup's 32-bit paths too */
#define MOTE__NO_UMULL 1            /* and ARMv6-M's: 16-bit products, divisions by a reciprocal */
#include "core/internal.h"          /* declares the library's mote__setup */
#define MOTE_NO_INT128 1
#define mote__setup mote__setup_portable
#define mote__setup_box mote__setup_box_portable
#include "core/setup.c"
#undef mote__setup
#undef mote__setup_box

#include "support/testutil.h"
#include "unity.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static tu_rng rng;

static int32_t in_range(int32_t lo, int32_t hi)
{
    return (int32_t)tu_rand_int(&rng, lo, hi);
}

static void test_portable_product_should_match_int128_on_edge_values(void)
{
#if defined(__SIZEOF_INT128__)
    __extension__ typedef __int128 i128;
    const int64_t v[] = {0, 1, -1, 2, -2, 255, -256, INT32_MAX, INT32_MIN, (int64_t)1 << 40,
                         -((int64_t)1 << 47), INT64_MAX, INT64_MIN, INT64_MAX - 1, INT64_MIN + 1};
    const int shifts[] = {1, 10, 31, 32, 33, 55, 63};
    const int n = (int)(sizeof v / sizeof v[0]);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            for (int s = 0; s < (int)(sizeof shifts / sizeof shifts[0]); s++) {
                int64_t want = (int64_t)(uint64_t)(((i128)v[i] * v[j]) >> shifts[s]);
                char msg[160];
                snprintf(msg, sizeof msg, "%lld * %lld >> %d", (long long)v[i], (long long)v[j], shifts[s]);
                TEST_ASSERT_EQUAL_INT64_MESSAGE(want, mote__mul_shift(v[i], v[j], shifts[s]), msg);
            }
#else
    TEST_IGNORE_MESSAGE("no __int128 on this host: the library's setup is the portable one");
#endif
}

/* floor(a / d), by C's truncating division */
static int64_t floor_div(int64_t a, int64_t d)
{
    int64_t q = a / d;
    return q - (a % d != 0 && (a < 0) != (d < 0));
}

/* the depth plane's division by a reciprocal (mote__divide_floor) against a
 * division: floors of either sign exact at multiples of the divisor and
 * one either side, at every divisor size, for quotients up to 2^32 - 2^8
 * (it must accept them: recip.c's mote__divide is tested there), and
 * refused from 2^32 */
static void test_reciprocal_division_should_match_a_division(void)
{
    const int64_t divisors[] = {1, 2, 3, 7, 255, 65535, 65536, 65537, 1000003, ((int64_t)1 << 31) - 1,
                                (int64_t)1 << 31, ((int64_t)1 << 32) - 1};
    const int named = (int)(sizeof divisors / sizeof divisors[0]);
    const int64_t most = ((int64_t)1 << 32) - 258;   /* |quotient| + 1 <= 2^32 - 2^8: accepted */
    rng = tu_rng_seed(62);
    int misses = 0, refused = 0, accepted_past = 0;
    for (int i = 0; i < named + 2000; i++) {
        const int64_t d = i < named ? divisors[i] : tu_rand_int(&rng, 1, ((int64_t)1 << 32) - 1);
        mote__divisor dv;
        mote__divisor_init(&dv, (uint32_t)d);
        /* and |a| = q d + 1 within int64 */
        const int64_t qmost = MOTE__MIN(most, (INT64_MAX - 1) / d);
        for (int j = 0; j < 64; j++) {
            int64_t q = j < 8 ? (int64_t)j : j < 16 ? qmost - (j - 8) : tu_rand_int(&rng, 0, qmost);
            for (int e = -1; e <= 1; e++)
                for (int sign = -1; sign <= 1; sign += 2) {
                    int64_t a = sign * (q * d + e), got;
                    if (!mote__divide_floor(a, &dv, &got))
                        refused++;
                    else
                        misses += got != floor_div(a, d);
                }
        }
        int64_t got;
        if (d < ((int64_t)1 << 30))
            accepted_past += mote__divide_floor(((int64_t)1 << 32) * d, &dv, &got)
                           + mote__divide_floor(-((int64_t)1 << 32) * d - 1, &dv, &got);
    }
    TEST_ASSERT_EQUAL_INT(0, refused);
    TEST_ASSERT_EQUAL_INT(0, accepted_past);
    TEST_ASSERT_EQUAL_INT(0, misses);
}

/* setup's floor division (its 32-bit cores' form, without libgcc's
 * 64-bit division) against C's, for both signs and every size */
static void test_floor_division_should_match_a_division(void)
{
    rng = tu_rng_seed(164);
    int misses = 0;
    for (int i = 0; i < 100000; i++) {
        int64_t b = (int64_t)(tu_rand_u64(&rng) >> tu_rand_int(&rng, 1, 63)) | 1;
        int64_t a = (int64_t)(tu_rand_u64(&rng) >> tu_rand_int(&rng, 1, 63));
        if (i & 1)
            a = -a;
        if (i & 2)
            b = -b;
        misses += mote__floor_div64(a, b) != floor_div(a, b);
    }
    misses += mote__floor_div64(INT64_MIN, 1) != INT64_MIN;
    misses += mote__floor_div64(INT64_MIN, 3) != floor_div(INT64_MIN, 3);
    misses += mote__floor_div64(INT64_MAX, -7) != floor_div(INT64_MAX, -7);
    TEST_ASSERT_EQUAL_INT(0, misses);
}

static void test_portable_setup_should_match_the_library_bit_for_bit(void)
{
    mote__raster_state rs;
    memset(&rs, 0, sizeof rs);
    rs.tex_w = rs.tex_h = 512;
    rs.tex_stride = 2048;
    rs.wrap_u = rs.wrap_v = MOTE_WRAP_REPEAT;
    rs.tex = MOTE__TEX_NEAREST;
    rs.gouraud = true;
    rs.depth_test = rs.depth_write = true;
    rs.depth_half = 1 << 15;
    const int F = 8, lim = 1 << 21;   /* the guard band's reach at 8 sub-pixel bits */
    long drawn = 0;
    rng = tu_rng_seed(20);
    for (int it = 0; it < 300000; it++) {
        /* a centre on or off the screen, and corners up to 2^reach sub-pixels from it */
        int reach = in_range(2, 21);
        int32_t cx = in_range(-300, 2200) * (1 << F), cy = in_range(-300, 1400) * (1 << F), X[3], Y[3];
        mote__svert V[3];
        for (int i = 0; i < 3; i++) {
            X[i] = MOTE__MAX(-lim, MOTE__MIN(lim, cx + in_range(-(1 << reach), 1 << reach)));
            Y[i] = MOTE__MAX(-lim, MOTE__MIN(lim, cy + in_range(-(1 << reach), 1 << reach)));
            V[i].texel[0] = (int64_t)in_range(-(1 << 30), 1 << 30) * in_range(1, 64);
            V[i].texel[1] = in_range(-(1 << 28), 1 << 28);
            for (int c = 0; c < 3; c++)
                V[i].s[c] = in_range(0, MOTE__SHADE_ONE);
            V[i].z = in_range(0, MOTE__DEPTH_MAX);
            V[i].depth = 0.5f;
            V[i].w = 0.01f + (float)in_range(0, 1 << 20) / 64.0f;
            mote__inverse_w(V[i].w, &V[i]);
        }
        int64_t area2 = mote__area2(X, Y);
        if (area2 == 0)
            continue;
        rs.persp = it % 4 == 0 ? MOTE__PERSP_AFFINE : MOTE__PERSP_CORRECT;
        const mote__svert *v[3] = {&V[0], &V[1], &V[2]};
        mote__tri want, got;
        memset(&want, 0, sizeof want);
        memset(&got, 0, sizeof got);
        mote__setup_result rw = mote__setup(&want, &rs, X, Y, area2, v, F, 1920, 1080);
        mote__setup_result rg = mote__setup_portable(&got, &rs, X, Y, area2, v, F, 1920, 1080);
        char msg[200];
        snprintf(msg, sizeof msg, "triangle %d: (%d,%d) (%d,%d) (%d,%d)", it, X[0], Y[0], X[1], Y[1], X[2], Y[2]);
        TEST_ASSERT_EQUAL_INT_MESSAGE(rw, rg, msg);
        if (rw != MOTE__SETUP_DRAWN)
            continue;
        drawn++;
        for (int a = 0; a < MOTE__ATTRS; a++)
            TEST_ASSERT_EQUAL_INT64_ARRAY_MESSAGE(want.n[a], got.n[a], 3, msg);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&want, &got, sizeof want, msg);
    }
    /* most of them must reach the planes, or the comparison proves little */
    TEST_ASSERT_GREATER_THAN_INT64(100000, drawn);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_portable_product_should_match_int128_on_edge_values);
    RUN_TEST(test_reciprocal_division_should_match_a_division);
    RUN_TEST(test_floor_division_should_match_a_division);
    RUN_TEST(test_portable_setup_should_match_the_library_bit_for_bit);
    return UNITY_END();
}
