/*
 * test_recip.c - the reciprocals of src/core/recip.c: the table, the first
 * guess, the exact lookup over every mantissa, the pixel loop's reciprocal
 * by table against a division, 1/w as mantissa and exponent, and division
 * by a reciprocal (mote__divide).
 *
 * This file takes the table path of mote__recip_k (MOTE_RECIP_BY_TABLE 1),
 * which 32-bit cores run; 64-bit hosts divide, and the division is the
 * reference here. Thresholds: 0 differences anywhere.
 */
#define MOTE_RECIP_BY_TABLE 1
#include "core/internal.h"
#include "support/testutil.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static uint32_t floor_2_61_over(uint64_t m)
{
    return (uint32_t)(((uint64_t)1 << 61) / m);
}

static void table_should_hold_the_reciprocals_less_the_bias(void)
{
    for (uint64_t i = 0; i <= 256; i++)
        TEST_ASSERT_EQUAL_UINT32(floor_2_61_over(((uint64_t)1 << 30) + (i << 22)) - 12288u, mote__recip_table[i]);
}

/* The guess errs low, never high (the Newton step needs e >= 0), and by
 * less than 2^-16 of its value (so that e >> 13 fits in 32 bits and one
 * correction suffices): on a sample of 2^24 mantissas, ends included. */
static void guess_should_err_low_by_less_than_2_to_minus_16(void)
{
    double worst = 0.0;
    for (uint64_t m = (uint64_t)1 << 30; m < (uint64_t)1 << 31; m += 61) {
        const uint32_t want = floor_2_61_over(m), got = mote__recip_guess((uint32_t)m);
        TEST_ASSERT_TRUE(got <= want);
        const double rel = (double)(want - got) / want;
        worst = rel > worst ? rel : worst;
    }
    const uint32_t last = ((uint32_t)1 << 31) - 1;
    TEST_ASSERT_TRUE(mote__recip_guess(last) <= floor_2_61_over(last));
    printf("largest relative error of the guess: 2^%.2f\n", log2(worst));
    TEST_ASSERT_TRUE(worst < 1.0 / 65536.0);
}

/* all 2^30 mantissas (a few seconds) */
static void lookup_should_be_the_exact_floor_for_every_mantissa(void)
{
    uint64_t wrong = 0, first = 0;
    for (uint64_t m = (uint64_t)1 << 30; m < (uint64_t)1 << 31; m++)
        if (mote__recip_lookup((uint32_t)m) != floor_2_61_over(m) && wrong++ == 0)
            first = m;
    char msg[64];
    snprintf(msg, sizeof msg, "first wrong mantissa %llu", (unsigned long long)first);
    TEST_ASSERT_EQUAL_UINT64_MESSAGE(0, wrong, msg);
}

static int32_t recip_by_divide(int32_t q, int k)
{
    const uint64_t d = q > 1 ? (uint64_t)q : 1u, r = ((uint64_t)1 << k) / d;
    return r < INT32_MAX ? (int32_t)r : INT32_MAX;
}

/* every k, q of every bit length and sign, powers of two and their
 * neighbours, and random ones */
static void recip_by_table_should_equal_recip_by_divide(void)
{
    tu_rng g = tu_rng_seed(38);
    uint64_t compared = 0;
    for (int k = 30; k <= 61; k++) {
        const int32_t edges[] = {INT32_MIN, -5, -1, 0, 1, 2, 3, INT32_MAX, INT32_MAX - 1};
        for (size_t i = 0; i < sizeof edges / sizeof edges[0]; i++, compared++)
            TEST_ASSERT_EQUAL_INT32(recip_by_divide(edges[i], k), mote__recip_k(edges[i], k));
        for (int b = 0; b < 31; b++)
            for (int d = -2; d <= 2; d++, compared++) {
                const int32_t q = (int32_t)(((int64_t)1 << b) + d);
                TEST_ASSERT_EQUAL_INT32(recip_by_divide(q, k), mote__recip_k(q, k));
            }
        for (int n = 0; n < 200000; n++, compared++) {
            const int32_t q = (int32_t)(tu_rand_u64(&g) >> (33 + n % 31));
            if (mote__recip_k(q, k) != recip_by_divide(q, k)) {
                char msg[64];
                snprintf(msg, sizeof msg, "q %ld, k %d", (long)q, k);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    }
    TEST_ASSERT_TRUE(compared > 6000000);
}

/* qm 2^(96 - qe) is 1/w within 2^-30 of it, for normal positive floats of
 * every exponent */
static void inverse_w_should_give_one_over_w(void)
{
    tu_rng g = tu_rng_seed(1038);
    for (int n = 0; n < 1000000; n++) {
        uint32_t bits = (uint32_t)(tu_rand_u64(&g) >> 33) % (254u << 23) + (1u << 23);
        float w;
        memcpy(&w, &bits, 4);
        mote__svert v;
        mote__inverse_w(w, &v);
        TEST_ASSERT_TRUE(v.qm > (1u << 30) && v.qm <= (1u << 31));
        const double got = ldexp((double)v.qm, 96 - v.qe), want = 1.0 / (double)w;
        TEST_ASSERT_TRUE(fabs(got - want) <= want * ldexp(1.0, -30));
    }
}

/* mote__divide against a division: exact at multiples of the divisor and
 * one either side (where its correction decides), for divisors of every
 * size up to 2^32 - 1 and quotients up to 2^32 - 2^8, which it must
 * accept; quotients of 2^32 and more it must refuse. */
static void divide_should_be_the_floor_and_refuse_past_32_bits(void)
{
    const uint32_t divisors[] = {1, 2, 3, 7, 255, 65535, 65536, 65537, 1000003, (1u << 31) - 1, 1u << 31,
                                 (1u << 31) + 1, 0xfffffffeu, 0xffffffffu};
    const int named = (int)(sizeof divisors / sizeof divisors[0]);
    const uint64_t most = ((uint64_t)1 << 32) - 257;   /* the largest quotient it must accept */
    tu_rng rng = tu_rng_seed(32);
    int misses = 0, refused = 0, accepted_past = 0;
    for (int i = 0; i < named + 4000; i++) {
        const uint32_t d = i < named ? divisors[i] : (uint32_t)tu_rand_int(&rng, 1, 0xffffffffLL >> tu_rand_int(&rng, 0, 31));
        mote__divisor dv;
        mote__divisor_init(&dv, d);
        for (int j = 0; j < 48; j++) {
            const uint64_t q = j < 8 ? (uint64_t)j : j < 16 ? most - (uint64_t)(j - 8) : (uint64_t)tu_rand_int(&rng, 0, (int64_t)most);
            for (int e = -1; e <= 1; e++) {
                if ((q == 0 && e < 0) || (q == most && e > 0 && d == 1))
                    continue;
                const uint64_t n = q * d + (uint64_t)(int64_t)e;
                uint32_t got;
                if (!mote__divide(n, &dv, &got))
                    refused++;
                else
                    misses += got != n / d;
            }
        }
        uint32_t got;
        const uint64_t past[] = {((uint64_t)1 << 32) * d, ((uint64_t)1 << 32) * d + d - 1, UINT64_MAX};
        for (int k = 0; k < 3; k++)
            accepted_past += past[k] / d >= ((uint64_t)1 << 32) && mote__divide(past[k], &dv, &got);
    }
    TEST_ASSERT_EQUAL_INT(0, refused);
    TEST_ASSERT_EQUAL_INT(0, accepted_past);
    TEST_ASSERT_EQUAL_INT(0, misses);
}

/* mote__udiv64 against C's division: divisors of every bit length up to
 * 2^63 - 1 (the reciprocal's below 2^32, the bit loop's above), dividends
 * of every length, each quotient's neighbours included. */
static void udiv64_should_be_the_floor_for_every_size(void)
{
    tu_rng rng = tu_rng_seed(64);
    int misses = 0;
    for (int i = 0; i < 20000; i++) {
        const uint64_t d = (tu_rand_u64(&rng) >> tu_rand_int(&rng, 1, 63)) | 1u;
        const uint64_t n = tu_rand_u64(&rng) >> tu_rand_int(&rng, 0, 63);
        const uint64_t q = n / d, at[] = {n, q * d, q * d + d - 1, q ? q * d - 1 : 0};
        for (int k = 0; k < 4; k++)
            misses += mote__udiv64(at[k], d) != at[k] / d;
    }
    const uint64_t edge[][2] = {{UINT64_MAX, 1}, {UINT64_MAX, 3}, {0, 7}, {((uint64_t)1 << 63) - 1, ((uint64_t)1 << 63) - 1},
                                {UINT64_MAX, 0xffffffffu}, {((uint64_t)1 << 32) * 0xffffffffu, 0xffffffffu}};
    for (int k = 0; k < (int)(sizeof edge / sizeof edge[0]); k++)
        misses += mote__udiv64(edge[k][0], edge[k][1]) != edge[k][0] / edge[k][1];
    TEST_ASSERT_EQUAL_INT(0, misses);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(table_should_hold_the_reciprocals_less_the_bias);
    RUN_TEST(guess_should_err_low_by_less_than_2_to_minus_16);
    RUN_TEST(lookup_should_be_the_exact_floor_for_every_mantissa);
    RUN_TEST(recip_by_table_should_equal_recip_by_divide);
    RUN_TEST(inverse_w_should_give_one_over_w);
    RUN_TEST(divide_should_be_the_floor_and_refuse_past_32_bits);
    RUN_TEST(udiv64_should_be_the_floor_for_every_size);
    return UNITY_END();
}
