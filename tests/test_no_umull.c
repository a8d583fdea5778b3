/*
 * test_no_umull.c - the arithmetic of cores without a 32x32->64-bit
 * multiply (ARMv6-M: Cortex-M0+) against plain 64-bit products.
 *
 * There the integer vertex stage forms its matrix rows from the 16-bit
 * halves of each factor (mote__fx_dot3_halves), and the pixel loops step
 * a plane from its origin with a product of two 16x16-bit ones
 * (mote__umul64_short), where a host multiplies in 64 bits. The emulated
 * Cortex-M0+ compares whole frames with the host (make test-embedded);
 * this file holds each to the 64-bit result on the values where carries
 * and floors are decided: each factor's extremes, halves of all ones and
 * all zeros, negative values whose low half is zero, and seeded random
 * values, at every shift the stage uses and the bounds' edges (1, 15, 16,
 * 23, 31, 32).
 *
 * Threshold: 0 differing rows, 0 differing products.
 */
#include "core/vertex_fixed.h"

#include "support/testutil.h"
#include "unity.h"

#include <stdio.h>

void setUp(void) {}
void tearDown(void) {}

/* the bounds mote__fx_dot3_halves is exact within */
#define A_LIMIT ((1 << 27) - 1)
#define P_LIMIT ((1 << 24) - 1)

static int32_t floor_shift64_low32(int64_t v, int s)
{
    /* floor division by 2^s, taken modulo 2^32 as the row keeps it */
    int64_t q = v >= 0 ? v / ((int64_t)1 << s) : -((-v + ((int64_t)1 << s) - 1) / ((int64_t)1 << s));
    return (int32_t)(uint32_t)(uint64_t)q;
}

/* whether the halves' row equals the 64-bit one; prints the first miss */
static bool row_matches(const int32_t a[3], const int32_t p[3], int s)
{
    int32_t ah[3], ph[3];
    uint32_t al[3], pl[3];
    int64_t sum = 0;
    for (int k = 0; k < 3; k++) {
        al[k] = (uint32_t)a[k] & 0xffffu;
        ah[k] = mote__floor_shift32(a[k], 16);
        pl[k] = (uint32_t)p[k] & 0xffffu;
        ph[k] = mote__floor_shift32(p[k], 16);
        sum += (int64_t)a[k] * p[k];
    }
    const int32_t want = floor_shift64_low32(sum, s), got = mote__fx_dot3_halves(ah, al, ph, pl, s);
    if (want != got)
        printf("a %ld %ld %ld p %ld %ld %ld s %d: %ld, not %ld\n", (long)a[0], (long)a[1], (long)a[2],
               (long)p[0], (long)p[1], (long)p[2], s, (long)got, (long)want);
    return want == got;
}

static const int shifts[] = {1, 15, 16, 23, 31, 32};
#define SHIFTS ((int)(sizeof shifts / sizeof shifts[0]))

static void test_halves_row_should_match_the_64_bit_row_on_edge_values(void)
{
    const int32_t av[] = {0, 1, -1, 0xffff, 0x10000, -0x10000, -0xffff, A_LIMIT, -A_LIMIT, 0x7ff0000, -0x7ff0000};
    const int32_t pv[] = {0, 1, -1, 0xffff, 0x10000, -0x10000, -0xffff, P_LIMIT, -P_LIMIT, 0xff0000, -0xff0000};
    const int na = (int)(sizeof av / sizeof av[0]), np = (int)(sizeof pv / sizeof pv[0]);
    int misses = 0;
    for (int i = 0; i < na * na * na; i++)
        for (int j = 0; j < np; j++)
            for (int s = 0; s < SHIFTS; s++) {
                /* all three terms alike in p, every mix of coefficients */
                const int32_t a[3] = {av[i % na], av[i / na % na], av[i / (na * na)]};
                const int32_t p[3] = {pv[j], pv[(j + 1) % np], pv[(j + 7) % np]};
                misses += !row_matches(a, p, shifts[s]);
            }
    TEST_ASSERT_EQUAL_INT(0, misses);
}

static void test_halves_row_should_match_the_64_bit_row_on_random_values(void)
{
    tu_rng rng = tu_rng_seed(0x6d30u);
    int misses = 0;
    for (int n = 0; n < 200000; n++) {
        int32_t a[3], p[3];
        for (int k = 0; k < 3; k++) {
            /* magnitudes of every size up to the bounds */
            const int abits = (int)tu_rand_int(&rng, 0, 27), pbits = (int)tu_rand_int(&rng, 0, 24);
            a[k] = (int32_t)tu_rand_int(&rng, -(((int64_t)1 << abits) - 1), ((int64_t)1 << abits) - 1);
            p[k] = (int32_t)tu_rand_int(&rng, -(((int64_t)1 << pbits) - 1), ((int64_t)1 << pbits) - 1);
        }
        misses += !row_matches(a, p, shifts[n % SHIFTS]);
    }
    TEST_ASSERT_EQUAL_INT(0, misses);
}

static void test_short_product_should_match_the_64_bit_product(void)
{
    const uint32_t av[] = {0, 1, 0xffffu, 0x10000u, 0x7fffffffu, 0x80000000u, 0xffff0000u, 0xffffffffu};
    const uint32_t bv[] = {0, 1, 2, 0x7fffu, 0x8000u, 0xfffeu, 0xffffu};
    int misses = 0;
    for (int i = 0; i < (int)(sizeof av / sizeof av[0]); i++)
        for (int j = 0; j < (int)(sizeof bv / sizeof bv[0]); j++)
            misses += mote__umul64_short(av[i], bv[j]) != (uint64_t)av[i] * bv[j];
    tu_rng rng = tu_rng_seed(0x5a17u);
    for (int n = 0; n < 200000; n++) {
        const uint32_t a = (uint32_t)tu_rand_int(&rng, 0, 0xffffffff), b = (uint32_t)tu_rand_int(&rng, 0, 0xffff);
        misses += mote__umul64_short(a, b) != (uint64_t)a * b;
    }
    TEST_ASSERT_EQUAL_INT(0, misses);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_halves_row_should_match_the_64_bit_row_on_edge_values);
    RUN_TEST(test_halves_row_should_match_the_64_bit_row_on_random_values);
    RUN_TEST(test_short_product_should_match_the_64_bit_product);
    return UNITY_END();
}
