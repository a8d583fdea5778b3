/*
 * test_mini_libc.c - the firmware's mini libc (embedded/firmware/mini_libc.c,
 * built here with its functions renamed mini_*) against the host's C
 * library: every source and destination alignment within two words and
 * every length up to 300 bytes, and nothing written outside the bytes
 * asked for.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "unity.h"

void *mini_memcpy(void *dst, const void *src, size_t n);
void *mini_memmove(void *dst, const void *src, size_t n);
void *mini_memset(void *dst, int c, size_t n);
int mini_memcmp(const void *a, const void *b, size_t n);

#define MAX_LEN 300
#define ALIGNS 8
#define GUARD 16
#define BUF (GUARD + ALIGNS + MAX_LEN + GUARD)

/* word-aligned buffers, so that offsets 0..7 are every alignment */
static union { uint32_t align; unsigned char b[BUF]; } src_buf, got_buf, want_buf;

static void fill_pattern(unsigned char *p, size_t n, unsigned seed)
{
    for (size_t i = 0; i < n; i++)
        p[i] = (unsigned char)(seed * 131u + i * 7u + (i >> 3));
}

void setUp(void)
{
}

void tearDown(void)
{
}

static void memcpy_should_copy_every_alignment_and_length(void)
{
    fill_pattern(src_buf.b, BUF, 1);
    for (size_t sa = 0; sa < ALIGNS; sa++)
        for (size_t da = 0; da < ALIGNS; da++)
            for (size_t n = 0; n <= MAX_LEN; n++) {
                fill_pattern(got_buf.b, BUF, 2);
                fill_pattern(want_buf.b, BUF, 2);
                unsigned char *src = src_buf.b + GUARD + sa;
                unsigned char *got = got_buf.b + GUARD + da;
                memcpy(want_buf.b + GUARD + da, src, n);
                void *ret = mini_memcpy(got, src, n);
                if (ret != got || memcmp(got_buf.b, want_buf.b, BUF) != 0) {
                    char msg[80];
                    snprintf(msg, sizeof msg, "source offset %zu, destination offset %zu, %zu bytes",
                             sa, da, n);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
}

static void memset_should_fill_every_alignment_and_length(void)
{
    static const int values[] = {0, 0xff, 0x80, 0x5a, 0x1234, -1};
    for (size_t v = 0; v < sizeof values / sizeof values[0]; v++)
        for (size_t da = 0; da < ALIGNS; da++)
            for (size_t n = 0; n <= MAX_LEN; n++) {
                fill_pattern(got_buf.b, BUF, 3);
                fill_pattern(want_buf.b, BUF, 3);
                unsigned char *got = got_buf.b + GUARD + da;
                memset(want_buf.b + GUARD + da, values[v], n);
                void *ret = mini_memset(got, values[v], n);
                if (ret != got || memcmp(got_buf.b, want_buf.b, BUF) != 0) {
                    char msg[80];
                    snprintf(msg, sizeof msg, "value %d, offset %zu, %zu bytes", values[v], da, n);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
}

static void memmove_should_copy_overlapping_bytes_either_way(void)
{
    for (size_t from = 0; from < 40; from++)
        for (size_t to = 0; to < 40; to++)
            for (size_t n = 0; n <= 64; n++) {
                fill_pattern(got_buf.b, BUF, 4);
                fill_pattern(want_buf.b, BUF, 4);
                memmove(want_buf.b + GUARD + to, want_buf.b + GUARD + from, n);
                void *ret = mini_memmove(got_buf.b + GUARD + to, got_buf.b + GUARD + from, n);
                TEST_ASSERT_EQUAL_PTR(got_buf.b + GUARD + to, ret);
                TEST_ASSERT_EQUAL_MEMORY(want_buf.b, got_buf.b, BUF);
            }
}

static int sign(int v)
{
    return (v > 0) - (v < 0);
}

static void memcmp_should_order_as_unsigned_bytes(void)
{
    const unsigned char a[] = {1, 2, 3, 0x80, 5};
    const unsigned char b[] = {1, 2, 3, 0x7f, 6};
    for (size_t n = 0; n <= sizeof a; n++) {
        TEST_ASSERT_EQUAL_INT(sign(memcmp(a, b, n)), sign(mini_memcmp(a, b, n)));
        TEST_ASSERT_EQUAL_INT(sign(memcmp(b, a, n)), sign(mini_memcmp(b, a, n)));
        TEST_ASSERT_EQUAL_INT(0, mini_memcmp(a, a, n));
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(memcpy_should_copy_every_alignment_and_length);
    RUN_TEST(memset_should_fill_every_alignment_and_length);
    RUN_TEST(memmove_should_copy_overlapping_bytes_either_way);
    RUN_TEST(memcmp_should_order_as_unsigned_bytes);
    return UNITY_END();
}
