/*
 * test_edge32.c - the edge walk's 32-bit first row against the 64-bit one.
 *
 * On 32-bit cores raster.c starts an edge at its first row in 32-bit
 * numbers (MOTE__CORE32), where a 64-bit host keeps 64-bit ones; only the
 * emulated boards ran that path before. This file compiles raster.c a
 * second time with MOTE__CORE32 set and walks random triangles, from a
 * pixel's sliver to the guard band's size, at every sub-pixel precision,
 * through random regions (a region that starts below a triangle's top
 * takes the general path), comparing every row with the library's walk.
 *
 * Thresholds: 0 differing rows over 200,000 seeded random triangles (some
 * 90,000 of which hold pixels and are walked).
 */
#define MOTE__CORE32 1              /* before any header: raster.c's 32-bit path */
#include "core/internal.h"          /* declares the library's walk */
#define mote__walk_begin mote__walk_begin_edge32
#define mote__walk_switch mote__walk_switch_edge32
#include "core/raster.c"
#undef mote__walk_begin
#undef mote__walk_switch

#include "support/testutil.h"
#include "unity.h"

#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

/* the rows of a walk, as mote__walk_row gives them, with the switch chosen */
static int walk_rows(const mote__tri *t, mote__rect r, int F, bool edge32, int64_t rows[][4], int max)
{
    mote__walk w;
    if (!(edge32 ? mote__walk_begin_edge32(&w, t, r, F) : mote__walk_begin(&w, t, r, F)))
        return 0;
    int n = 0;
    while (w.y < w.yend && n < max) {
        if (w.y == w.ymid) {
            if (edge32)
                mote__walk_switch_edge32(&w);
            else
                mote__walk_switch(&w);
        }
        rows[n][0] = w.y;
        rows[n][1] = w.left.x;
        rows[n][2] = w.right.x;
        rows[n][3] = w.left.err ^ (w.right.err << 1);
        n++;
        mote__edge_step(&w.left);
        mote__edge_step(&w.right);
        w.y++;
    }
    return n;
}

static void test_edge32_walk_should_match_the_library_row_for_row(void)
{
    mote__raster_state rs;
    memset(&rs, 0, sizeof rs);      /* no weights, no depth: setup gives the walk's fields */
    mote__svert V;
    memset(&V, 0, sizeof V);
    const mote__svert *const vp[3] = {&V, &V, &V};
    static int64_t want[2048][4], got[2048][4];
    tu_rng rng = tu_rng_seed(38);
    long walks = 0, rows = 0;
    for (int it = 0; it < 200000; it++) {
        const int F = (int)tu_rand_int(&rng, 4, 8), width = 640, height = 480;
        const int reach = (int)tu_rand_int(&rng, 1, 12 + F);
        const int32_t cx = (int32_t)tu_rand_int(&rng, -100, width + 100) * (1 << F);
        const int32_t cy = (int32_t)tu_rand_int(&rng, -100, height + 100) * (1 << F);
        int32_t X[3], Y[3];
        for (int k = 0; k < 3; k++) {
            X[k] = cx + (int32_t)tu_rand_int(&rng, -((int64_t)1 << reach), (int64_t)1 << reach);
            Y[k] = cy + (int32_t)tu_rand_int(&rng, -((int64_t)1 << reach), (int64_t)1 << reach);
        }
        const int64_t area2 = mote__area2(X, Y);
        mote__tri t;
        if (area2 == 0 || mote__setup(&t, &rs, X, Y, area2, vp, F, width, height) != MOTE__SETUP_DRAWN)
            continue;
        /* the whole screen (every edge starts at its first row), or a band or tile */
        mote__rect r = {0, 0, width, height};
        if (it & 1) {
            r.x0 = (int)tu_rand_int(&rng, 0, width - 1);
            r.y0 = (int)tu_rand_int(&rng, 0, height - 1);
            r.x1 = (int)tu_rand_int(&rng, r.x0 + 1, width);
            r.y1 = (int)tu_rand_int(&rng, r.y0 + 1, height);
        }
        const int n = walk_rows(&t, r, F, false, want, 2048), m = walk_rows(&t, r, F, true, got, 2048);
        char msg[200];
        snprintf(msg, sizeof msg, "walk %d: F %d, (%d %d) (%d %d) (%d %d), region %d %d %d %d", it, F,
                 (int)X[0], (int)Y[0], (int)X[1], (int)Y[1], (int)X[2], (int)Y[2], r.x0, r.y0, r.x1, r.y1);
        TEST_ASSERT_EQUAL_INT_MESSAGE(n, m, msg);
        if (n > 0)
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(want, got, sizeof want[0] * (size_t)n, msg);
        walks++;
        rows += n;
    }
    printf("edge32: %ld walks, %ld rows compared\n", walks, rows);
    TEST_ASSERT_TRUE(walks > 50000);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_edge32_walk_should_match_the_library_row_for_row);
    return UNITY_END();
}
