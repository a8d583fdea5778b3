/*
 * test_spans.c - every specialised span loop against the generic one, and
 * the same bytes from every way of executing a frame: direct, binned with
 * any thread count / tile size / arena size, and band by band.
 */
#include <mote/mote.h>
#include <mote/mote_io.h>
#include "core/internal.h"
#include "unity.h"

#include <stdlib.h>
#include <string.h>

#define W 97                       /* odd sizes: partial tiles and bands */
#define H 71

static uint32_t rng;
void setUp(void)
{
    rng = 12345u;   /* each test its own stream, whatever ran before */
}
void tearDown(void) {}

static uint32_t next_u32(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}
static float frand(float lo, float hi) { return lo + (hi - lo) * (float)(next_u32() & 0xffffff) / 16777216.0f; }

/* A w x h RGBA8888 texture of random texels in texels (4 w h bytes). */
/* A W x H target over colour and depth, counting into *n (the two
 * targets a comparison draws into share one count). */
static mote__target whole_target(uint8_t *color, uint32_t *depth, mote_format format,
                                 mote_depth_format depth_format, mote__counts *n)
{
    mote__target t = {color, W * 4, depth, W, 0, format, depth_format, n};
    return t;
}

static mote_texture random_texture(uint8_t *texels, int w, int h)
{
    for (int i = 0; i < 4 * w * h; i++)
        texels[i] = (uint8_t)next_u32();
    return (mote_texture){w, h, MOTE_FORMAT_RGBA8888, 4 * w, texels};
}

/* A raster state sampling tex (u repeats, v as given); the rest zero. */
static mote__raster_state texture_state(mote__tex_kind kind, const mote_texture *tex, mote_wrap wrap_v)
{
    mote__raster_state rs;
    memset(&rs, 0, sizeof rs);
    rs.tex = kind;
    rs.texture = tex;
    rs.tex_w = tex->width;
    rs.tex_h = tex->height;
    rs.tex_stride = tex->stride;
    rs.wrap_u = MOTE_WRAP_REPEAT;
    rs.wrap_v = wrap_v;
    return rs;
}

/* A random shade in (0, 1]; with edges, one in three at a value whose
 * 16-bit halves are extreme (the vector colour arithmetic splits a shade
 * into them). */
static int32_t random_shade(bool edges_too)
{
    static const int32_t edges[] = {MOTE__SHADE_ONE, MOTE__SHADE_ONE - 1, 0xffff, 0x10000, 0xff0000 | 0xffff, 1};
    if (edges_too && next_u32() % 3 == 0)
        return edges[next_u32() % (sizeof edges / sizeof edges[0])];
    return (int32_t)(frand(1e-6f, 1.0f) * MOTE__SHADE_ONE);
}

/* A random triangle over the W x H target and a little past its edges,
 * with random w, depth and texel coordinates (u within +-uv_range, v half
 * that), shaded as shade kind sk makes shades: flat, one shade for all
 * (grey when grey); mono, grey vertices; RGB, any; black, zero. Only
 * vertex 0 takes extreme shades, so that shades still vary. */
static void random_triangle(int32_t X[3], int32_t Y[3], mote__svert v[3], int sk, bool grey, float uv_range)
{
    /* one in four with one w at its corners, as an orthographic camera
     * sees every triangle: the exact variants hand those to the affine ones */
    const bool one_w = next_u32() % 4 == 0;
    for (int k = 0; k < 3; k++) {
        X[k] = (int32_t)(next_u32() % ((W + 20) << 8)) - (10 << 8);
        Y[k] = (int32_t)(next_u32() % ((H + 20) << 8)) - (10 << 8);
        v[k].w = one_w && k > 0 ? v[0].w : frand(0.2f, 5.0f);
        mote__inverse_w(v[k].w, &v[k]);
        v[k].depth = frand(0.0f, 1.0f);
        v[k].z = (int32_t)(v[k].depth * (float)MOTE__DEPTH_MAX);
        for (int c = 0; c < 3; c++)
            v[k].s[c] = sk == MOTE__SHADE_FLAT && k > 0 ? v[0].s[c]
                      : (sk == MOTE__SHADE_MONO || (sk == MOTE__SHADE_FLAT && grey)) && c > 0
                      ? v[k].s[0] : sk == MOTE__SHADE_BLACK ? 0 : random_shade(k == 0);
        v[k].texel[0] = (int64_t)(frand(-uv_range, uv_range) * 65536.0f);
        v[k].texel[1] = (int64_t)(frand(-uv_range / 2.0f, uv_range / 2.0f) * 65536.0f);
    }
}

/* A random triangle (random_triangle's) set up with rs into *tri: false
 * when it has no pixels or no area. */
static bool setup_random_triangle(mote__tri *tri, const mote__raster_state *rs, int sk, bool grey, float uv_range)
{
    mote__svert v[3];
    int32_t X[3], Y[3];
    random_triangle(X, Y, v, sk, grey, uv_range);
    const mote__svert *const vp[3] = {&v[0], &v[1], &v[2]};
    int64_t area2 = mote__area2(X, Y);
    return area2 != 0 && mote__setup(tri, rs, X, Y, area2, vp, 8, W, H) == MOTE__SETUP_DRAWN;
}

/* rs with the generic loop for every shade kind (the oracle), and the two
 * W x H targets cleared: colour 0, depth all ones */
static mote__raster_state generic_twin(const mote__raster_state *rs, uint8_t *ca, uint8_t *cb, uint32_t *da,
                                       uint32_t *db)
{
    mote__raster_state gen = *rs;
    for (int k = 0; k < MOTE__SHADE_COUNT; k++)
        gen.fill[k] = mote__fill_generic;
    memset(ca, 0, W * H * 4);
    memset(cb, 0, W * H * 4);
    memset(da, 0xff, W * H * 4);
    memset(db, 0xff, W * H * 4);
    return gen;
}

void every_specialised_span_should_match_the_generic_span(void)
{
#if defined(MOTE_SPECIALISE_SPANS) && !MOTE_SPECIALISE_SPANS
    TEST_IGNORE_MESSAGE("MOTE_SPECIALISE_SPANS is 0 in this build (the main build runs it)");
#endif
    static uint8_t ca[W * H * 4], cb[W * H * 4];
    static uint32_t da[W * H], db[W * H];
    static uint8_t texels[16 * 8 * 4];
    mote_texture tex = random_texture(texels, 16, 8);
    int variants = 0, wide = 0, constant_q = 0;
    /* texture addressing: 0 = repeat x mirror (any size), 1 = power-of-two
     * repeat (its own loop), 2 = the same with texel ranges so wide that
     * setup drops fraction bits of the texel coordinates */
    for (int addr = 0; addr < 3; addr++)
    for (int fmt = 0; fmt < 2; fmt++)
    for (int dfmt = 0; dfmt < 3; dfmt++)
    for (int texk = 0; texk < 3; texk++)
    for (int sk = 0; sk < MOTE__SHADE_ADD; sk++)   /* ADD: the generic loop alone */
    for (int p = 0; p < 3; p++) {
        mote_format format = fmt ? MOTE_FORMAT_RGB565 : MOTE_FORMAT_RGBA8888;
        mote_depth_format depthf = dfmt == 0 ? MOTE_DEPTH_FORMAT_NONE : dfmt == 1 ? MOTE_DEPTH_FORMAT_16 : MOTE_DEPTH_FORMAT_32;
        mote__raster_state rs = texture_state((mote__tex_kind)texk, &tex,
                                               addr == 0 ? MOTE_WRAP_MIRROR : MOTE_WRAP_REPEAT);
        float uv_range = addr == 2 ? 5000.0f : 40.0f;
        /* black: from a Gouraud draw, and from a flat one (affine runs) */
        rs.gouraud = sk == MOTE__SHADE_BLACK ? p != 0 : sk != MOTE__SHADE_FLAT;
        rs.persp = (mote__persp_kind)p;
        rs.subspan_log2 = 3;
        rs.depth_test = rs.depth_write = depthf != MOTE_DEPTH_FORMAT_NONE;
        mote__fill_select(&rs, format, depthf);
        mote__fill_fn special = rs.fill[sk];
        TEST_ASSERT_NOT_NULL(special);
        variants += addr == 0 && special != mote__fill_generic;
        mote__raster_state gen = generic_twin(&rs, ca, cb, da, db);
        mote__counts n = {0, 0};
        mote__target ta = whole_target(ca, da, format, depthf, &n);
        mote__target tb = whole_target(cb, db, format, depthf, &n);
        for (int t = 0; t < 40; t++) {
            mote__tri tri;
            if (!setup_random_triangle(&tri, &rs, sk, (t & 1) != 0, uv_range))
                continue;
            TEST_ASSERT_EQUAL_INT(sk, tri.shade);
            wide += tri.texel_bits < MOTE__TEXEL_BITS;
            constant_q += p == MOTE__PERSP_CORRECT && sk != MOTE__SHADE_BLACK && tri.qdx == 0 && tri.qdy == 0;
            mote__rect all = {0, 0, W, H};
            /* as binned: the record's bytes only (mote__tri_bytes), garbage after them */
            mote__tri binned;
            memset(&binned, 0xa5, sizeof binned);
            memcpy(&binned, &tri, mote__tri_bytes(&tri));
            mote__raster_tri(&binned, &ta, all, 8);
            /* the oracle: the generic loop, interpolating all three channels
             * (setup makes only red's plane for one grey shade: the three
             * are the same plane) */
            tri.rs = &gen;
            if (tri.shade == MOTE__SHADE_MONO)
                for (int j = 0; j < 3; j++)
                    tri.n[MOTE__A_G][j] = tri.n[MOTE__A_B][j] = tri.n[MOTE__A_R][j];
            tri.shade = MOTE__SHADE_RGB;
            mote__raster_tri(&tri, &tb, all, 8);
        }
        TEST_ASSERT_EQUAL_MEMORY(cb, ca, sizeof ca);
        TEST_ASSERT_EQUAL_MEMORY(db, da, sizeof da);
    }
    /* the wide-range triangles really dropped texel bits */
    TEST_ASSERT_GREATER_THAN_INT(100, wide);
    /* and exact triangles with one w really have a constant Q (and so
     * went to the affine variants) */
    TEST_ASSERT_GREATER_THAN_INT(100, constant_q);
    /* the table really is used for these combinations */
    TEST_ASSERT_EQUAL_INT(2 * 3 * 3 * MOTE__SHADE_ADD * 3, variants);
}

/* The firmware's pixel loop (span_fw.c, MOTE_FIRMWARE_SPANS: the fixed
 * build's suites, tests/fixed/) against the generic one: Gouraud, flat and
 * black triangles, nearest RGB565 texels or none, RGB565 and its byte-swapped form, 16-bit depth,
 * texel ranges narrow and wide, binned records. */
void firmware_span_should_match_the_generic_span(void)
{
#if MOTE_FIRMWARE_SPANS
    static uint8_t ca[W * H * 4], cb[W * H * 4];
    static uint32_t da[W * H], db[W * H];
    static uint16_t texels[16 * 8];
    for (int i = 0; i < 16 * 8; i++)
        texels[i] = (uint16_t)next_u32();
    const mote_texture tex = {16, 8, MOTE_FORMAT_RGB565, 32, texels};
    int taken = 0;
    for (int wide = 0; wide < 2; wide++)
    for (int fmt = 0; fmt < 2; fmt++)
    for (int texk = 0; texk < 2; texk++)
    for (int sk = MOTE__SHADE_FLAT; sk <= MOTE__SHADE_BLACK; sk++) {
        const mote_format format = fmt ? MOTE_FORMAT_RGB565_SWAPPED : MOTE_FORMAT_RGB565;
        mote__raster_state rs = texture_state((mote__tex_kind)texk, &tex, MOTE_WRAP_REPEAT);
        rs.gouraud = true;
        rs.persp = MOTE__PERSP_CORRECT;
        rs.depth_test = rs.depth_write = true;
        mote__fill_select(&rs, format, MOTE_DEPTH_FORMAT_16);
        mote__raster_state gen = generic_twin(&rs, ca, cb, da, db);
        mote__counts na = {0, 0}, nb = {0, 0};
        mote__target ta = whole_target(ca, da, format, MOTE_DEPTH_FORMAT_16, &na);
        mote__target tb = whole_target(cb, db, format, MOTE_DEPTH_FORMAT_16, &nb);
        for (int t = 0; t < 60; t++) {
            mote__tri tri;
            if (!setup_random_triangle(&tri, &rs, sk, (t & 1) != 0, wide ? 5000.0f : 40.0f))
                continue;
            taken += tri.q_drop >= 0;
            const mote__rect all = {0, 0, W, H};
            mote__tri binned;
            memset(&binned, 0xa5, sizeof binned);
            memcpy(&binned, &tri, mote__tri_bytes(&tri));
            mote__raster_tri(&binned, &ta, all, 8);
            tri.rs = &gen;
            mote__raster_tri(&tri, &tb, all, 8);
        }
        TEST_ASSERT_EQUAL_MEMORY(cb, ca, sizeof ca);
        TEST_ASSERT_EQUAL_MEMORY(db, da, sizeof da);
        TEST_ASSERT_EQUAL_UINT64(nb.tested, na.tested);
        TEST_ASSERT_EQUAL_UINT64(nb.written, na.written);
    }
    TEST_ASSERT_GREATER_THAN_INT(200, taken);
#else
    TEST_IGNORE_MESSAGE("MOTE_FIRMWARE_SPANS is 0 in this build (tests/fixed/ runs it)");
#endif
}

/* The vector loops' reciprocal (a double division, truncated and
 * corrected) against the scalar one, where the double quotient of 2^k / q
 * rounds up to the next integer: about one q in 2^23 when the quotient
 * is near 2^30, so q is scanned just below 2^31 with K 61, and around
 * every other K and the ends of q's range. */
void the_vector_reciprocal_should_match_the_scalar_one(void)
{
#if MOTE_SIMD
    void (*recip[2])(const int32_t *, int, int32_t *);
    int lanes[2], count = 0;
#if defined(__x86_64__)
    recip[count] = mote__recip_sse2;
    lanes[count++] = 4;
    if (__builtin_cpu_supports("avx2")) {
        recip[count] = mote__recip_avx2;
        lanes[count++] = 8;
    }
#else
    recip[count] = mote__recip_neon;
    lanes[count++] = 4;
#endif
    for (int i = 0; i < count; i++) {
        int rounded_up = 0, checked = 0;
        for (int k = 30; k <= 61; k++) {
            const int32_t edges[] = {INT32_MIN, -1, 0, 1, 2, 3, 1 << (k - 31 > 0 ? k - 31 : 0), INT32_MAX, INT32_MAX - 1};
            const int span = k == 61 ? 1 << 23 : 1 << 12;
            for (int n = -(int)(sizeof edges / sizeof edges[0]); n < span; n += lanes[i]) {
                int32_t q[8], got[8];
                for (int j = 0; j < lanes[i]; j++) {
                    const int m = n + j;
                    q[j] = m < 0 ? edges[-m - 1] : k == 61 ? INT32_MAX - m : (int32_t)(next_u32() >> (next_u32() % 32));
                }
                recip[i](q, k, got);
                for (int j = 0; j < lanes[i]; j++) {
                    const int32_t want = mote__recip_k(q[j], k);
                    if (got[j] != want)
                        TEST_FAIL_MESSAGE("a vector reciprocal differs from mote__recip_k");
                    const double x = (double)((uint64_t)1 << k) / (q[j] > 1 ? q[j] : 1);
                    rounded_up += x < 2147483647.0 && (int64_t)x != want;
                    checked++;
                }
            }
        }
        /* the correction really was needed somewhere */
        TEST_ASSERT_GREATER_THAN_INT(0, rounded_up);
        TEST_ASSERT_GREATER_THAN_INT(1 << 23, checked);
    }
#else
    TEST_IGNORE_MESSAGE("this build has no vector spans");
#endif
}

/* The vector fills (span_simd.h) against the scalar ones, for each
 * instruction set this processor runs: the same bytes for every variant
 * they take, over random triangles on depth buffers of random depths (so
 * that tests fail in every pattern), as records cut short as binned. */
void every_vector_span_should_match_the_scalar_span(void)
{
    int isas[2], count = 0;
#if MOTE_SIMD && defined(__x86_64__)
    isas[count++] = MOTE__ISA_SSE2;
    if (__builtin_cpu_supports("avx2"))
        isas[count++] = MOTE__ISA_AVX2;
#elif MOTE_SIMD && defined(__aarch64__)
    isas[count++] = MOTE__ISA_NEON;
#endif
    if (count == 0)
        TEST_IGNORE_MESSAGE("this build has no vector spans (MOTE_SIMD 0, or not x86-64 or AArch64)");
    static uint8_t ca[W * H * 4], cb[W * H * 4];
    static uint32_t da[W * H], db[W * H];
    static uint8_t texels[64 * 32 * 4];
    mote_texture tex = random_texture(texels, 64, 32);
    int vector = 0, drawn = 0;
    for (int i = 0; i < count; i++)
    for (int fmt = 0; fmt < 2; fmt++)
    for (int dfmt = 0; dfmt < 3; dfmt++)
    for (int texk = 0; texk < 2; texk++)
    for (int sk = 0; sk < MOTE__SHADE_COUNT; sk++)
    for (int p = 0; p < 2; p++) {
        if (sk == MOTE__SHADE_ADD)
            continue;             /* additive colour: the generic loop's alone */
        mote_format format = fmt ? MOTE_FORMAT_RGB565 : MOTE_FORMAT_RGBA8888;
        mote_depth_format depthf = dfmt == 0 ? MOTE_DEPTH_FORMAT_NONE : dfmt == 1 ? MOTE_DEPTH_FORMAT_16 : MOTE_DEPTH_FORMAT_32;
        mote__raster_state vs = texture_state((mote__tex_kind)texk, &tex, MOTE_WRAP_REPEAT);
        vs.gouraud = sk == MOTE__SHADE_BLACK ? p != 0 : sk != MOTE__SHADE_FLAT;
        vs.persp = (mote__persp_kind)p;
        vs.depth_test = vs.depth_write = depthf != MOTE_DEPTH_FORMAT_NONE;
        mote__raster_state ss = vs;
        mote__fill_select_isa(&vs, format, depthf, isas[i]);
        mote__fill_select_isa(&ss, format, depthf, MOTE__ISA_SCALAR);
        vector += vs.fill[sk] != ss.fill[sk];
        memset(ca, 0, sizeof ca);
        memset(cb, 0, sizeof cb);
        for (int k = 0; k < W * H; k++)
            da[k] = next_u32() >> (next_u32() % 2 ? 8 : 0);
        memcpy(db, da, sizeof db);
        mote__counts na = {0, 0}, nb = {0, 0};
        mote__target ta = whole_target(ca, da, format, depthf, &na);
        mote__target tb = whole_target(cb, db, format, depthf, &nb);
        for (int t = 0; t < 60; t++) {
            mote__tri tri;
            if (!setup_random_triangle(&tri, &vs, sk, (t & 1) != 0, t % 3 ? 40.0f : 5000.0f))
                continue;
            mote__rect all = {0, 0, W, H};
            mote__tri binned;
            memset(&binned, 0xa5, sizeof binned);
            memcpy(&binned, &tri, mote__tri_bytes(&tri));
            mote__raster_tri(&binned, &ta, all, 8);
            tri.rs = &ss;
            mote__raster_tri(&tri, &tb, all, 8);
            drawn++;
        }
        TEST_ASSERT_EQUAL_MEMORY(cb, ca, sizeof ca);
        TEST_ASSERT_EQUAL_MEMORY(db, da, sizeof da);
        TEST_ASSERT_EQUAL_UINT64(nb.tested, na.tested);
        TEST_ASSERT_EQUAL_UINT64(nb.written, na.written);
    }
    /* every variant here was a vector one */
    TEST_ASSERT_EQUAL_INT(count * 2 * 3 * 2 * (MOTE__SHADE_COUNT - 1) * 2, vector);
    TEST_ASSERT_GREATER_THAN_INT(1000, drawn);
}

/* A binned record keeps its planes up to the last one its kind has
 * (mote__plane_count, written out for speed and flash) and none after:
 * the count must be what mote__has_plane says, for every kind. */
void a_record_should_keep_planes_up_to_its_last_one(void)
{
    for (int shade = 0; shade < MOTE__SHADE_COUNT; shade++)
        for (int textured = 0; textured < 2; textured++) {
            int last = 0;
            for (int a = 0; a < MOTE__ATTRS; a++)
                if (mote__has_plane(a, (mote__shade_kind)shade, textured))
                    last = a + 1;
            TEST_ASSERT_EQUAL_INT(last, mote__plane_count(shade, textured));
        }
}

/* A raster state drawing tex nearest with Gouraud RGB shades, sub-span
 * perspective in segments of 2^log2 pixels and a 32-bit depth test, by
 * the specialised loops or by the generic one. */
static mote__raster_state subspan_state(const mote_texture *tex, int log2, bool specialised)
{
    mote__raster_state rs = texture_state(MOTE__TEX_NEAREST, tex, MOTE_WRAP_REPEAT);
    rs.gouraud = true;
    rs.persp = MOTE__PERSP_SUBSPAN;
    rs.subspan_log2 = log2;
    rs.depth_test = rs.depth_write = true;
    mote__fill_select(&rs, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32);
    for (int k = 0; k < MOTE__SHADE_COUNT && !specialised; k++)
        rs.fill[k] = mote__fill_generic;
    return rs;
}

/* Sub-span perspective: r is exact at the columns that are multiples of
 * the segment length and linear between them, so a pixel must not depend
 * on which pixels before it in its row failed the depth test. (The loop
 * takes a segment's starting r from the last segment's end, which holds
 * only when no rejected run skipped a whole segment.) */
void subspan_pixels_should_not_depend_on_the_depth_rejected_pixels_before_them(void)
{
    static uint8_t ca[W * H * 4], cb[W * H * 4];
    static uint32_t da[W * H], db[W * H];
    static bool hidden[W * H];
    static uint8_t texels[16 * 8 * 4];
    mote_texture tex = random_texture(texels, 16, 8);
    /* runs of 13 hidden columns, longer than a segment of 8, in every third run */
    for (int i = 0; i < W * H; i++)
        hidden[i] = ((i % W) / 13 + i / W) % 3 == 0;
    long compared = 0, differ = 0;
    for (int specialised = 0; specialised < 2; specialised++) {
        mote__raster_state rs = subspan_state(&tex, 3, specialised);
        mote__counts n = {0, 0};
        mote__target ta = whole_target(ca, da, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, &n);
        mote__target tb = whole_target(cb, db, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, &n);
        for (int t = 0; t < 60; t++) {
            memset(ca, 0, sizeof ca);
            memset(cb, 0, sizeof cb);
            memset(da, 0xff, sizeof da);
            for (int i = 0; i < W * H; i++)
                db[i] = hidden[i] ? 0u : 0xffffffffu;
            mote__tri tri;
            if (!setup_random_triangle(&tri, &rs, MOTE__SHADE_RGB, false, 40.0f))
                continue;
            mote__rect all = {0, 0, W, H};
            mote__raster_tri(&tri, &ta, all, 8);
            mote__raster_tri(&tri, &tb, all, 8);
            for (int i = 0; i < W * H; i++) {
                if (hidden[i] || da[i] == 0xffffffffu)
                    continue;
                compared++;
                differ += memcmp(&ca[4 * i], &cb[4 * i], 4) != 0 || da[i] != db[i];
            }
        }
    }
    TEST_ASSERT_GREATER_THAN_INT(W * H, compared);
    TEST_ASSERT_EQUAL_INT(0, differ);
}

/* Sub-span perspective: r is exact at a segment's ends and linear between,
 * and an attribute is a0 + N r with a0 one vertex's value (setup's). If Q
 * goes from Q0 to Q1 = rho Q0 (rho >= 1) over a segment, Q r_linear - 1 =
 * (rho - 1)^2 / rho t (1 - t) at fraction t of it, at most (rho - 1)^2 /
 * (4 rho); so a channel is off by at most that times |f - a0|, which is at
 * most the channel's range over the vertices. rho is at most the ratio of
 * the vertices' w (Q is a convex combination of their 1/w), and a sliver's
 * row may cross all of it within one segment. Plus one unit for each
 * image's rounding. */
static double subspan_bound(const mote__svert v[3])
{
    float wmin = v[0].w, wmax = v[0].w;
    int32_t range = 0;
    for (int k = 1; k < 3; k++) {
        wmin = v[k].w < wmin ? v[k].w : wmin;
        wmax = v[k].w > wmax ? v[k].w : wmax;
    }
    for (int c = 0; c < 3; c++)
        for (int k = 0; k < 3; k++) {
            const int32_t d = abs(v[k].s[c] - v[(k + 1) % 3].s[c]);
            range = d > range ? d : range;
        }
    const double rho = (double)wmax / (double)wmin;
    return 255.0 * range / MOTE__SHADE_ONE * (rho - 1.0) * (rho - 1.0) / (4.0 * rho) + 2.0;
}

/* The largest channel difference between the triangle drawn with
 * sub-span perspective into ca and exactly into cb (RGBA8888, Gouraud, no
 * depth); -1 when it is not drawn. Adds the pixels drawn to *compared. */
static int subspan_error(const int32_t X[3], const int32_t Y[3], const mote__svert v[3], uint8_t *ca,
                         uint8_t *cb, long *compared)
{
    static uint32_t da[W * H], db[W * H];
    mote__raster_state rs;
    memset(&rs, 0, sizeof rs);
    rs.gouraud = true;
    rs.subspan_log2 = 3;
    mote__raster_state exact = rs;
    rs.persp = MOTE__PERSP_SUBSPAN;
    exact.persp = MOTE__PERSP_CORRECT;
    mote__fill_select(&rs, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_NONE);
    mote__fill_select(&exact, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_NONE);
    memset(ca, 0, W * H * 4);
    memset(cb, 0, W * H * 4);
    const mote__svert *const vp[3] = {&v[0], &v[1], &v[2]};
    int64_t area2 = mote__area2(X, Y);
    mote__tri ta_tri, tb_tri;
    if (area2 == 0 || mote__setup(&ta_tri, &rs, X, Y, area2, vp, 8, W, H) != MOTE__SETUP_DRAWN
        || mote__setup(&tb_tri, &exact, X, Y, area2, vp, 8, W, H) != MOTE__SETUP_DRAWN)
        return -1;
    mote__counts n = {0, 0};
    mote__target ta = whole_target(ca, da, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_NONE, &n);
    mote__target tb = whole_target(cb, db, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_NONE, &n);
    mote__rect all = {0, 0, W, H};
    mote__raster_tri(&ta_tri, &ta, all, 8);
    mote__raster_tri(&tb_tri, &tb, all, 8);
    int worst = 0;
    for (int i = 0; i < 4 * W * H; i++) {
        int d = abs((int)ca[i] - (int)cb[i]);
        worst = d > worst ? d : worst;
        *compared += (i & 3) == 3 && ca[i] != 0;
    }
    return worst;
}

/* Sub-span perspective on slivers: a segment's end past a triangle's edge
 * may hold a Q plane value that is no pixel's of the triangle (a sliver's
 * plane spans far more than 64 bits allow over its box). Such a segment
 * must be drawn exactly, not from a reciprocal of garbage: each pixel
 * within subspan_bound of the exact perspective's. */
void subspan_slivers_should_stay_close_to_the_exact_perspective(void)
{
    static uint8_t ca[W * H * 4], cb[W * H * 4];
    long compared = 0;
    int worst = 0;
    double most = 0.0;            /* the largest error's share of its bound */
    for (int t = 0; t < 4000; t++) {
        mote__svert v[3];
        int32_t X[3], Y[3];
        random_triangle(X, Y, v, MOTE__SHADE_RGB, false, 40.0f);
        /* vertex 2 within a fraction of a pixel of the line from 0 to 1 */
        int32_t f = (int32_t)(next_u32() % 256);
        X[2] = X[0] + (int32_t)(((int64_t)(X[1] - X[0]) * f) >> 8) + (int32_t)(next_u32() % 64) - 32;
        Y[2] = Y[0] + (int32_t)(((int64_t)(Y[1] - Y[0]) * f) >> 8) + (int32_t)(next_u32() % 64) - 32;
        for (int k = 0; k < 3; k++) {   /* a perspective sub-spans approximate well */
            v[k].w = frand(0.7f, 1.4f);
            mote__inverse_w(v[k].w, &v[k]);
        }
        const int e = subspan_error(X, Y, v, ca, cb, &compared);
        const double share = e / subspan_bound(v);
        worst = e > worst ? e : worst;
        most = share > most ? share : most;
    }
    TEST_ASSERT_GREATER_THAN_INT(1000, compared);
    TEST_ASSERT_TRUE(worst > 0);
    TEST_ASSERT_TRUE(most <= 1.0);
}

/* The worst of 11 million slivers of that test's kind (17 units): a row
 * of three pixels whose Q falls from 1.38 to 0.76, one segment, the
 * middle pixel's green 43 where the exact perspective gives 60 (a0 is
 * 248: 188 units from it, times 0.09). Within subspan_bound (29). */
void subspan_worst_sliver_should_stay_within_its_bound(void)
{
    static uint8_t ca[W * H * 4], cb[W * H * 4];
    const int32_t X[3] = {25780, 6972, 21287}, Y[3] = {7290, 6277, 7078};
    const float w[3] = {1.39631021f, 1.2422111f, 0.708224952f};
    const int32_t s[3][3] = {{9681058, 5295346, 8778196}, {4383287, 16352936, 12007683},
                             {10596322, 1385696, 7070944}};
    mote__svert v[3];
    memset(v, 0, sizeof v);
    for (int k = 0; k < 3; k++) {
        v[k].w = w[k];
        mote__inverse_w(w[k], &v[k]);
        memcpy(v[k].s, s[k], sizeof v[k].s);
    }
    long compared = 0;
    const int e = subspan_error(X, Y, v, ca, cb, &compared);
    TEST_ASSERT_GREATER_THAN_INT(4, e);     /* the bound of 4 units once assumed */
    TEST_ASSERT_TRUE(e <= subspan_bound(v));
}

/* Sub-span segments are cut to a triangle's own rows, never to the region
 * drawn: a triangle drawn in 8x8 tiles gives the bytes it gives whole, in
 * the specialised loops and in the generic one. */
void subspan_pixels_should_not_depend_on_the_region(void)
{
    static uint8_t ca[W * H * 4], cb[W * H * 4];
    static uint32_t da[W * H], db[W * H];
    static uint8_t texels[16 * 8 * 4];
    mote_texture tex = random_texture(texels, 16, 8);
    long covered = 0;
    for (int specialised = 0; specialised < 2; specialised++) {
        /* long segments: where one is cut shows */
        mote__raster_state rs = subspan_state(&tex, 6, specialised);
        mote__counts n = {0, 0};
        mote__target ta = whole_target(ca, da, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, &n);
        mote__target tb = whole_target(cb, db, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, &n);
        memset(ca, 0, sizeof ca);
        memset(cb, 0, sizeof cb);
        memset(da, 0xff, sizeof da);
        memset(db, 0xff, sizeof db);
        for (int t = 0; t < 200; t++) {
            mote__tri tri;
            if (!setup_random_triangle(&tri, &rs, MOTE__SHADE_RGB, false, 400.0f))
                continue;
            mote__rect all = {0, 0, W, H};
            mote__raster_tri(&tri, &ta, all, 8);
            for (int y = 0; y < H; y += 8)
                for (int x = 0; x < W; x += 8) {
                    mote__rect tile = {x, y, MOTE__MIN(x + 8, W), MOTE__MIN(y + 8, H)};
                    mote__raster_tri(&tri, &tb, tile, 8);
                }
        }
        for (int i = 0; i < W * H; i++)
            covered += da[i] != 0xffffffffu;
        TEST_ASSERT_EQUAL_MEMORY(ca, cb, sizeof ca);
        TEST_ASSERT_EQUAL_MEMORY(da, db, sizeof da);
    }
    TEST_ASSERT_GREATER_THAN_INT(W * H, covered);
}

/* ---- determinism ------------------------------------------------------------ */

#define NV 600
#define NT 900
static mote_vertex verts[NV];
static uint32_t indices[NT * 3];
static uint8_t tex_pixels[32 * 32 * 4];
static mote_texture tex32 = {32, 32, MOTE_FORMAT_RGBA8888, 128, tex_pixels};

static void make_scene(mote_mesh meshes[3])
{
    for (int i = 0; i < NV; i++) {
        for (int k = 0; k < 3; k++) {
            verts[i].position[k] = frand(-2.0f, 2.0f);
            verts[i].normal[k] = frand(-1.0f, 1.0f);
        }
        verts[i].uv[0] = frand(-1.0f, 2.0f);
        verts[i].uv[1] = frand(-1.0f, 2.0f);
    }
    for (int i = 0; i < NT * 3; i++)
        indices[i] = next_u32() % NV;
    for (size_t i = 0; i < sizeof tex_pixels; i++)
        tex_pixels[i] = (uint8_t)next_u32();
    for (int m = 0; m < 3; m++) {
        memset(&meshes[m], 0, sizeof meshes[m]);
        meshes[m].vertices = verts;
        meshes[m].vertex_count = NV;
        meshes[m].indices = indices + m * NT;
        meshes[m].index_count = NT;
        meshes[m].position[0] = (float)m - 1.0f;
        meshes[m].rotation[1] = 0.3f * (float)m;
        meshes[m].material.texture = m == 1 ? NULL : &tex32;
        meshes[m].material.color = (mote_rgba){(uint8_t)(100 + 70 * m), 200, 150, 255};
        meshes[m].material.color_set = true;
        mote_mesh_update_bounds(&meshes[m]);
    }
}

typedef struct band_sink { uint8_t *frame; int stride; } band_sink;
static void band_flush(void *user, int y0, int rows, const void *color, int stride)
{
    band_sink *s = (band_sink *)user;
    for (int r = 0; r < rows; r++)
        memcpy(s->frame + (size_t)(y0 + r) * (size_t)s->stride, (const uint8_t *)color + (size_t)r * (size_t)stride,
               (size_t)s->stride);
}

/* A W x H device's description: RGBA colour, 32-bit depth, clear colour
 * (10, 20, 30); binned in arena when given, through mote_parallel_openmp
 * with *threads threads when that is not 0. */
static mote_device_desc test_desc(uint8_t *color, uint32_t *depth, void *arena, size_t arena_size, int tile,
                                  int *threads)
{
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = W;
    d.height = H;
    d.color = color;
    d.depth = depth;
    d.clear_color = (mote_rgba){10, 20, 30, 255};
    d.arena = arena;
    d.arena_size = arena_size;
    d.tile_size = tile;
    d.parallel_for = *threads ? mote_parallel_openmp : NULL;
    d.parallel_user = threads;
    return d;
}

/* The camera in front of the scene and every type of light, with falloff:
 * binned draws transform and light their vertices four at a time on SSE2
 * hosts (geometry.c), direct ones and bands one by one. */
static void lit_frame(mote_frame_desc *f)
{
    memset(f, 0, sizeof *f);
    f->camera.position[2] = -5.0f;
    f->camera.position[1] = 1.0f;
    f->camera.znear = 0.5f;
    f->light_count = 3;
    f->lights[0].type = MOTE_LIGHT_POINT;
    f->lights[0].position[1] = 4.0f;
    f->lights[1].type = MOTE_LIGHT_DIRECTIONAL;
    f->lights[1].direction[0] = 1.0f;
    f->lights[1].color[0] = 0.3f;
    f->lights[1].color[1] = 0.1f;
    f->lights[1].color[2] = 0.1f;
    f->lights[2].type = MOTE_LIGHT_HEMISPHERIC;
    f->lights[2].direction[1] = 1.0f;
    f->lights[2].intensity = 0.4f;
    f->lights[2].ground_color[2] = 0.5f;
    /* Babylon's falloff: a range on the point light, a spot light with a
     * range and a fractional exponent whose cone edge crosses the scene */
    f->lights[0].range = 9.0f;
    f->light_count = 4;
    f->lights[3].type = MOTE_LIGHT_SPOT;
    f->lights[3].position[0] = -1.0f;
    f->lights[3].position[1] = 2.0f;
    f->lights[3].position[2] = -3.0f;
    f->lights[3].direction[0] = 0.4f;
    f->lights[3].direction[1] = -0.8f;
    f->lights[3].direction[2] = 1.0f;
    f->lights[3].color[1] = 0.7f;
    f->lights[3].spot_angle = 0.9f;
    f->lights[3].spot_exponent = 2.5f;
    f->lights[3].range = 7.0f;
}

/* Renders the scene with the given execution setup into out (RGBA). */
static void render(const mote_mesh meshes[3], int band, void *arena, size_t arena_size, int tile,
                   int threads, mote_draw_desc dd, uint8_t *out)
{
    static uint8_t color[W * H * 4];
    static uint32_t depth[W * H];
    band_sink sink = {out, W * 4};
    mote_device dev;
    mote_device_desc d = test_desc(band ? color : out, depth, arena, arena_size, tile, &threads);
    d.band_height = band;
    d.flush = band_flush;
    d.flush_user = &sink;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    mote_frame_desc f;
    lit_frame(&f);
    /* two frames: the second begins on an arena the first one's tile jobs
     * read (mote_begin takes those bytes back) */
    for (int frame = 0; frame < 2; frame++) {
        TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
        for (int m = 0; m < 3; m++)
            TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &meshes[m], &dd));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    }
}

/* The scene drawn with dd directly, binned with every tile size and
 * thread count, with an arena that fills up, and in bands: the same bytes
 * each way. */
static void check_every_way_of_executing(const mote_mesh meshes[3], mote_draw_desc dd)
{
    static uint8_t ref[W * H * 4], got[W * H * 4];
    static uint64_t arena_big[(8u << 20) / 8], arena_small[(96u << 10) / 8];
    render(meshes, 0, NULL, 0, 64, 0, dd, ref);
    /* something was drawn */
    int lit = 0;
    for (int i = 0; i < W * H; i++)
        lit += ref[4 * i] != 10;
    TEST_ASSERT_TRUE(lit > W * H / 20);
    int tiles[] = {8, 16, 64, 256};
    int threads[] = {0, 1, 2, 3, 4, 17};   /* 17: more than the host's runs on the stack */
    for (int ti = 0; ti < 4; ti++)
        for (int th = 0; th < 6; th++) {
            memset(got, 0, sizeof got);
            render(meshes, 0, arena_big, sizeof arena_big, tiles[ti], threads[th], dd, got);
            TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
        }
    /* an arena that fills up several times per frame */
    memset(got, 0, sizeof got);
    render(meshes, 0, arena_small, sizeof arena_small, 16, 2, dd, got);
    TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
    int bands[] = {1, 2, 3, 7, 16, 70};
    for (int b = 0; b < 6; b++) {
        memset(got, 0, sizeof got);
        render(meshes, bands[b], NULL, 0, 64, 0, dd, got);
        TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
    }
}

void frames_should_be_the_same_bytes_for_any_threads_tiles_arena_and_bands(void)
{
    mote_mesh meshes[3];
    make_scene(meshes);
    mote_mode modes[] = {MOTE_MODE_TEXTURED, MOTE_MODE_FLAT, MOTE_MODE_GOURAUD, MOTE_MODE_WIREFRAME, MOTE_MODE_POINTS};
    for (size_t mi = 0; mi < sizeof modes / sizeof modes[0]; mi++) {
        mote_draw_desc dd;
        memset(&dd, 0, sizeof dd);
        dd.mode = modes[mi];
        dd.cull = MOTE_CULL_NONE;
        dd.filter = mi == 0 ? MOTE_FILTER_BILINEAR : MOTE_FILTER_NEAREST;
        check_every_way_of_executing(meshes, dd);
    }
}

void vertex_colours_should_be_the_same_bytes_for_any_threads_tiles_arena_and_bands(void)
{
    /* from the index, not the generator, so the other tests' scenes stay as they were */
    static mote_rgba colors[NV];
    for (int i = 0; i < NV; i++)
        colors[i] = (mote_rgba){(uint8_t)(i * 97), (uint8_t)(i * 57 + 80), (uint8_t)(255 - i * 31), 255};
    mote_mesh meshes[3];
    make_scene(meshes);
    for (int m = 0; m < 3; m++)
        meshes[m].colors = colors;
    mote_mode modes[] = {MOTE_MODE_TEXTURED, MOTE_MODE_FLAT, MOTE_MODE_GOURAUD};
    for (size_t mi = 0; mi < sizeof modes / sizeof modes[0]; mi++)
        for (int unlit = 0; unlit < 2; unlit++) {
            mote_draw_desc dd;
            memset(&dd, 0, sizeof dd);
            dd.mode = modes[mi];
            dd.cull = MOTE_CULL_NONE;
            dd.unlit = unlit;
            check_every_way_of_executing(meshes, dd);
        }
}

/* Renders SEQ_DRAWS draws of the scene (more than MOTE_MAX_DRAWS, a points
 * draw among them, depth test off for every third) into out. */
#define SEQ_DRAWS (MOTE_MAX_DRAWS + 9)
static void render_sequence(const mote_mesh meshes[3], void *arena, size_t arena_size, int threads,
                            uint8_t *out, mote_stats *stats)
{
    static uint32_t depth[W * H];
    mote_device dev;
    mote_device_desc d = test_desc(out, depth, arena, arena_size, 16, &threads);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    f.camera.position[2] = -5.0f;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
    for (int k = 0; k < SEQ_DRAWS; k++) {
        mote_draw_desc dd;
        memset(&dd, 0, sizeof dd);
        dd.cull = MOTE_CULL_NONE;
        dd.no_depth_test = k % 3 == 0;
        dd.mode = k == SEQ_DRAWS - 4 ? MOTE_MODE_POINTS : k % 2 ? MOTE_MODE_TEXTURED : MOTE_MODE_FLAT;
        dd.point_color = (mote_rgba){255, 0, 255, 255};
        mote_mesh m = meshes[k % 3];
        m.position[0] += 0.01f * (float)k;
        /* mote_draw keeps the pointer until mote_end: one mesh per draw */
        static mote_mesh kept[SEQ_DRAWS];
        kept[k] = m;
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &kept[k], &dd));
    }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    *stats = *mote_device_stats(&dev);
}

static void assert_same_counts(const mote_stats *a, const mote_stats *b, bool tiles)
{
    TEST_ASSERT_EQUAL_UINT32(a->draws, b->draws);
    TEST_ASSERT_EQUAL_UINT32(a->meshes_culled, b->meshes_culled);
    TEST_ASSERT_EQUAL_UINT32(a->triangles_in, b->triangles_in);
    TEST_ASSERT_EQUAL_UINT32(a->triangles_invalid, b->triangles_invalid);
    TEST_ASSERT_EQUAL_UINT32(a->triangles_clipped_away, b->triangles_clipped_away);
    TEST_ASSERT_EQUAL_UINT32(a->triangles_backface, b->triangles_backface);
    TEST_ASSERT_EQUAL_UINT32(a->triangles_degenerate, b->triangles_degenerate);
    TEST_ASSERT_EQUAL_UINT32(a->triangles_drawn, b->triangles_drawn);
    /* binned tiles skip the pixel tests of triangles behind their drawn depth */
    if (!a->tile_triangles_behind && !b->tile_triangles_behind)
        TEST_ASSERT_EQUAL_UINT64(a->pixels_tested, b->pixels_tested);
    TEST_ASSERT_EQUAL_UINT64(a->pixels_written, b->pixels_written);
    if (tiles) {
        TEST_ASSERT_EQUAL_UINT32(a->tile_triangles_behind, b->tile_triangles_behind);
        TEST_ASSERT_EQUAL_UINT64(a->pixels_tested, b->pixels_tested);
        TEST_ASSERT_EQUAL_UINT32(a->tiles_empty, b->tiles_empty);
        TEST_ASSERT_EQUAL_UINT32(a->tiles_drawn, b->tiles_drawn);
        TEST_ASSERT_EQUAL_UINT32(a->arena_flushes, b->arena_flushes);
    }
}

/* With parallel_for, binned draws are set up in parallel groups (bin.c):
 * the bytes and counts must be the serial path's, whatever the threads,
 * with a points draw between binned ones, more draws than one record
 * holds, and arenas that fill up (too small for the groups' slices, so
 * the batch goes serial, and then for the frame, which flushes). */
void binned_draws_set_up_in_groups_should_match_the_serial_path(void)
{
    static uint8_t ref[W * H * 4], got[W * H * 4];
    static uint64_t arena_big[(8u << 20) / 8], arena_mid[(160u << 10) / 8], arena_small[(96u << 10) / 8];
    mote_mesh meshes[3];
    make_scene(meshes);
    mote_stats direct, serial, st;
    render_sequence(meshes, NULL, 0, 0, ref, &direct);
    int magenta = 0;
    for (int i = 0; i < W * H; i++)
        magenta += ref[4 * i] == 255 && ref[4 * i + 1] == 0 && ref[4 * i + 2] == 255;
    TEST_ASSERT_TRUE(magenta > 0);         /* the points draw shows */
    render_sequence(meshes, arena_big, sizeof arena_big, 0, got, &serial);
    TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
    assert_same_counts(&direct, &serial, false);
    TEST_ASSERT_EQUAL_UINT32(SEQ_DRAWS, serial.draws);
    int threads[] = {1, 2, 3, 17};
    for (int th = 0; th < 4; th++) {
        memset(got, 0, sizeof got);
        render_sequence(meshes, arena_big, sizeof arena_big, threads[th], got, &st);
        TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
        assert_same_counts(&serial, &st, true);
    }
    void *small[2] = {arena_mid, arena_small};
    size_t small_size[2] = {sizeof arena_mid, sizeof arena_small};
    for (int a = 0; a < 2; a++)
        for (int th = 0; th <= 2; th += 2) {
            memset(got, 0, sizeof got);
            render_sequence(meshes, small[a], small_size[a], th, got, &st);
            TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
            assert_same_counts(&direct, &st, false);
            TEST_ASSERT_TRUE(st.arena_flushes > 0);   /* and says so */
            TEST_ASSERT_TRUE(st.tiles_drawn > 0);
        }
}

/* A parallel_for that runs the tasks in order and counts its steps. */
static int steps_taken;
static void counting_parallel_for(void *user, int count, mote_task_fn fn, void *arg)
{
    (void)user;
    steps_taken++;
    for (int i = 0; i < count; i++)
        fn(arg, i);
}

/* Many one-triangle draws (a scene of small meshes): a batch of them is
 * set up on the calling thread, not in a parallel step of its own, which
 * would cost more than its triangles (and, on a loaded machine, waits
 * for a thread the system has put aside). Only the frame's first batch,
 * beside the clear, and the tiles take a step; the bytes are the serial
 * path's. */
void batches_of_tiny_draws_should_not_take_a_parallel_step_each(void)
{
    enum { DRAWS = 4 * MOTE_MAX_DRAWS + 5 };
    static uint8_t ref[W * H * 4], got[W * H * 4];
    static uint32_t depth[W * H];
    static uint64_t arena[(8u << 20) / 8];
    static mote_mesh tiny[DRAWS];
    mote_mesh meshes[3];
    make_scene(meshes);
    for (int k = 0; k < DRAWS; k++) {
        tiny[k] = meshes[k % 3];
        tiny[k].indices = indices + 3 * k;
        tiny[k].index_count = 3;
        mote_mesh_update_bounds(&tiny[k]);
    }
    for (int run = 0; run < 2; run++) {   /* serial, then with the counting hook */
        int threads = 0;
        mote_device dev;
        mote_device_desc d = test_desc(run ? got : ref, depth, arena, sizeof arena, 16, &threads);
        d.parallel_for = run ? counting_parallel_for : NULL;
        TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
        mote_frame_desc f;
        memset(&f, 0, sizeof f);
        f.camera.position[2] = -5.0f;
        mote_draw_desc dd;
        memset(&dd, 0, sizeof dd);
        dd.cull = MOTE_CULL_NONE;
        dd.mode = MOTE_MODE_TEXTURED;
        steps_taken = 0;
        TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
        for (int k = 0; k < DRAWS; k++)
            TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &tiny[k], &dd));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
        TEST_ASSERT_EQUAL(DRAWS, mote_device_stats(&dev)->draws);
    }
    TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
    /* the first batch beside the clear, then the tiles (five batches) */
    TEST_ASSERT_EQUAL(2, steps_taken);
}

/* A binned draw transforms its vertices four at a time on SSE2 hosts, a
 * direct one one at a time: vertices behind the eye, on its plane, far
 * outside the guard band, in it, NaN, infinite, denormal or with texels
 * out of range among ordinary ones (and a count that is no multiple of
 * four) must give the same bytes and counts either way. */
void vertices_transformed_four_at_a_time_should_match_one_at_a_time(void)
{
    enum { HV = NV + 3 };
    static mote_vertex hostile[HV];
    static uint32_t hostile_indices[NT * 3];
    static uint8_t ref[W * H * 4], got[W * H * 4];
    static uint32_t depth[W * H];
    static uint64_t arena[(8u << 20) / 8];
    mote_mesh meshes[3];
    make_scene(meshes);
    for (int i = 0; i < HV; i++) {
        hostile[i] = verts[i % NV];
        if (i % 5)
            continue;
        float *p = hostile[i].position;
        switch (i / 5 % 8) {
        case 0: p[2] = -5.0f; p[1] = 1.0f; break;   /* on the eye's plane: w = 0 */
        case 1: p[2] = -9.0f; break;                /* behind the eye */
        case 2: p[0] = 1e6f; break;                 /* far outside the guard band */
        case 3: p[0] = 40.0f; break;                /* outside the view, inside the band */
        case 4: p[1] = 0.0f / 0.0f; break;
        case 5: p[0] = 1.0f / 0.0f; break;
        case 6: p[0] = p[1] = 1e-40f; break;        /* denormal */
        default: hostile[i].uv[0] = 1e12f; break;   /* texels out of range */
        }
    }
    for (int i = 0; i < NT * 3; i++)
        hostile_indices[i] = next_u32() % HV;
    mote_mesh mesh = meshes[0];
    mesh.vertices = hostile;
    mesh.vertex_count = HV;
    mesh.indices = hostile_indices;
    mesh.index_count = NT * 3;
    mote_mode modes[] = {MOTE_MODE_TEXTURED, MOTE_MODE_GOURAUD, MOTE_MODE_FLAT};
    for (int mi = 0; mi < 3; mi++) {
        mote_stats direct, st;
        for (int run = 0; run < 3; run++) {   /* direct, binned serially, binned on 2 threads */
            int threads = run == 2 ? 2 : 0;
            mote_device dev;
            mote_device_desc d = test_desc(run ? got : ref, depth, run ? arena : NULL, run ? sizeof arena : 0, 16,
                                           &threads);
            TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
            mote_frame_desc f;
            lit_frame(&f);
            mote_draw_desc dd;
            memset(&dd, 0, sizeof dd);
            dd.mode = modes[mi];
            dd.cull = MOTE_CULL_NONE;
            TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
            TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &mesh, &dd));
            TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
            st = *mote_device_stats(&dev);
            if (run == 0) {
                direct = st;
                /* every kind of vertex was met */
                TEST_ASSERT_TRUE(st.triangles_invalid > 0);
                TEST_ASSERT_TRUE(st.triangles_clipped_away > 0);
                TEST_ASSERT_TRUE(st.triangles_drawn > NT / 4);
                continue;
            }
            TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
            assert_same_counts(&direct, &st, false);
        }
    }
}

/* A draw larger than its share of the frame is set up in pieces, on
 * several cores, from one vertex cache prepared first (bin.c). One big
 * draw between two small ones, the camera inside the scene so that
 * triangles are clipped at the near plane, both windings culled in turn:
 * the bytes and counts must be those of direct drawing, whatever the
 * threads, also when the arena is too small for the pieces' slices. */
void a_draw_cut_into_pieces_should_match_drawing_it_whole(void)
{
    enum { BIG = 2400 };
    static uint32_t big_indices[BIG * 3];
    static uint8_t ref[W * H * 4], got[W * H * 4];
    static uint32_t depth[W * H];
    static uint64_t arena_big[(8u << 20) / 8], arena_small[(160u << 10) / 8];
    mote_mesh meshes[3];
    make_scene(meshes);
    for (int i = 0; i < BIG * 3; i++)
        big_indices[i] = next_u32() % NV;
    meshes[1].indices = big_indices;
    meshes[1].index_count = BIG * 3;
    mote_mode modes[] = {MOTE_MODE_TEXTURED, MOTE_MODE_FLAT, MOTE_MODE_GOURAUD};
    for (int mi = 0; mi < 3; mi++) {
        mote_draw_desc dd;
        memset(&dd, 0, sizeof dd);
        dd.mode = modes[mi];
        dd.cull = mi == 2 ? MOTE_CULL_FRONT : MOTE_CULL_BACK;
        mote_stats direct, st;
        for (int run = 0; run < 7; run++) {
            /* direct, then 1, 2, 3 and 17 threads, then small arenas on 0 and 2 */
            static const int run_threads[7] = {0, 1, 2, 3, 17, 0, 2};
            int threads = run_threads[run];
            void *arena = run == 0 ? NULL : run < 5 ? (void *)arena_big : (void *)arena_small;
            size_t arena_size = run == 0 ? 0 : run < 5 ? sizeof arena_big : sizeof arena_small;
            uint8_t *out = run == 0 ? ref : got;
            memset(got, 0, sizeof got);
            mote_device dev;
            mote_device_desc d = test_desc(out, depth, arena, arena_size, 16, &threads);
            TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
            mote_frame_desc f;
            memset(&f, 0, sizeof f);
            f.camera.position[2] = -2.2f;
            f.camera.znear = 0.3f;
            f.light_count = 1;
            f.lights[0].type = MOTE_LIGHT_POINT;
            f.lights[0].position[1] = 3.0f;
            TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
            for (int m = 0; m < 3; m++)
                TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &meshes[m], &dd));
            TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
            st = *mote_device_stats(&dev);
            if (run == 0) {
                direct = st;
                TEST_ASSERT_TRUE(direct.triangles_clipped_away > 0 && direct.triangles_backface > 0);
                TEST_ASSERT_TRUE(direct.triangles_drawn > 1000);
                continue;
            }
            TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
            assert_same_counts(&direct, &st, false);
            TEST_ASSERT_EQUAL_UINT32(3, st.draws);
        }
    }
}

/* With parallel setup the frame's clear waits for the draws and runs beside
 * their setup: a frame with nothing to set up, or whose first draw is
 * points (drawn at once), must still start from a cleared frame. */
void the_clear_beside_parallel_setup_should_run_without_triangles_and_before_points(void)
{
    static uint8_t color[W * H * 4];
    static uint32_t depth[W * H];
    static uint64_t arena[(1u << 20) / 8];
    mote_mesh meshes[3];
    make_scene(meshes);
    for (int threads = 1; threads <= 2; threads++)
        for (int points = 0; points < 2; points++) {
            mote_device dev;
            mote_device_desc d = test_desc(color, depth, arena, sizeof arena, 0, &threads);
            TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
            memset(color, 0xab, sizeof color);
            memset(depth, 0, sizeof depth);
            mote_frame_desc f;
            memset(&f, 0, sizeof f);
            f.camera.position[2] = -5.0f;
            f.camera.znear = 0.5f;
            TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
            mote_draw_desc dd;
            memset(&dd, 0, sizeof dd);
            dd.mode = MOTE_MODE_POINTS;
            dd.point_color = (mote_rgba){255, 255, 255, 255};
            if (points) {
                TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &meshes[0], &dd));
            }
            TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
            int cleared = 0, white = 0;
            for (int i = 0; i < W * H; i++) {
                cleared += color[4 * i] == 10 && color[4 * i + 1] == 20 && color[4 * i + 2] == 30;
                white += color[4 * i] == 255 && color[4 * i + 1] == 255 && color[4 * i + 2] == 255;
            }
            TEST_ASSERT_EQUAL_INT(W * H, cleared + white);
            TEST_ASSERT_TRUE(points ? white > 0 : white == 0);
            for (int i = 0; i < W * H; i++)
                TEST_ASSERT_EQUAL_HEX32(MOTE__DEPTH_MAX, depth[i]);
        }
}

/* ---- vertex order ------------------------------------------------------- */

/* One triangle, its vertices listed in any of the six orders (culling is
 * not setup's business): the same pixels, colours and depths. The planes
 * are anchored at one vertex, so a different anchor could round a pixel's
 * depth or texel differently; setup picks the same vertex every time. */
void a_triangle_should_draw_the_same_bytes_whatever_order_its_vertices_come_in(void)
{
    static uint8_t c0[W * H * 4], c1[W * H * 4];
    static uint32_t d0[W * H], d1[W * H];
    static uint8_t texels[16 * 16 * 4];
    mote_texture tex = random_texture(texels, 16, 16);
    static const int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    long pixels = 0;
    for (int t = 0; t < 3000; t++) {
        mote__raster_state rs = texture_state((mote__tex_kind)(t % 3), &tex,
                                               t % 2 ? MOTE_WRAP_MIRROR : MOTE_WRAP_REPEAT);
        rs.gouraud = true;
        rs.persp = (mote__persp_kind)(t / 3 % 3);
        rs.subspan_log2 = 3;
        rs.depth_test = rs.depth_write = true;
        rs.depth_half = 1 << 15;
        mote__fill_select(&rs, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32);
        mote__svert v[3];
        int32_t X[3], Y[3];
        for (int k = 0; k < 3; k++) {
            /* small ones too, where a unit of rounding is a visible share */
            int span = t % 4 ? W + 20 : 12;
            X[k] = (int32_t)(next_u32() % (uint32_t)(span << 8)) - (10 << 8);
            Y[k] = (int32_t)(next_u32() % (uint32_t)(span << 8)) - (10 << 8);
            v[k].w = frand(0.2f, 5.0f);
            mote__inverse_w(v[k].w, &v[k]);
            v[k].depth = frand(0.0f, 1.0f);
            v[k].z = (int32_t)(v[k].depth * (float)MOTE__DEPTH_MAX);
            for (int c = 0; c < 3; c++)
                v[k].s[c] = (int32_t)(frand(0.0f, 1.0f) * MOTE__SHADE_ONE);
            v[k].texel[0] = (int64_t)(frand(-40.0f, 40.0f) * 65536.0f);
            v[k].texel[1] = (int64_t)(frand(-20.0f, 20.0f) * 65536.0f);
        }
        if (mote__area2(X, Y) == 0)
            continue;
        for (int p = 0; p < 6; p++) {
            uint8_t *c = p ? c1 : c0;
            uint32_t *d = p ? d1 : d0;
            memset(c, 0, sizeof c0);
            memset(d, 0xff, sizeof d0);
            mote__counts n = {0, 0};
            mote__target tg = {c, W * 4, d, W, 0, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, &n};
            int32_t PX[3], PY[3];
            const mote__svert *pv[3];
            for (int k = 0; k < 3; k++) {
                PX[k] = X[perm[p][k]];
                PY[k] = Y[perm[p][k]];
                pv[k] = &v[perm[p][k]];
            }
            mote__tri tri;
            if (mote__setup(&tri, &rs, PX, PY, mote__area2(PX, PY), pv, 8, W, H) != MOTE__SETUP_DRAWN)
                break;
            mote__rect all = {0, 0, W, H};
            mote__raster_tri(&tri, &tg, all, 8);
            pixels += p == 0 ? (long)n.written : 0;
            if (p > 0) {
                TEST_ASSERT_EQUAL_MEMORY(c0, c1, sizeof c0);
                TEST_ASSERT_EQUAL_MEMORY(d0, d1, sizeof d0);
            }
        }
    }
    TEST_ASSERT_GREATER_THAN(500000, pixels);
}

/* floor(v / 2^8), for the test's own box arithmetic */
static int floor_px(int32_t v) { return v >= 0 ? v / 256 : -((-v + 255) / 256); }

void setup_should_box_a_triangle_by_the_pixel_centres_its_vertices_span(void)
{
    static uint8_t c[W * H * 4];
    static uint32_t d[W * H];
    static const mote_texture none = {1, 1, MOTE_FORMAT_RGBA8888, 4, NULL};
    mote__raster_state rs = texture_state(MOTE__TEX_NONE, &none, MOTE_WRAP_REPEAT);
    rs.depth_test = rs.depth_write = true;
    mote__fill_select(&rs, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32);
    mote__svert v[3];
    memset(v, 0, sizeof v);
    const mote__svert *pv[3] = {&v[0], &v[1], &v[2]};
    int dropped = 0, empty = 0, kept = 0;
    long pixels = 0;
    for (int t = 0; t < 20000; t++) {
        int32_t X[3], Y[3];
        int span = 1 + t % 6;     /* pixels: many hold no centre, or one */
        int32_t bx = (int32_t)(next_u32() % ((W + 8) << 8)) - (4 << 8);
        int32_t by = (int32_t)(next_u32() % ((H + 8) << 8)) - (4 << 8);
        for (int k = 0; k < 3; k++) {
            X[k] = bx + (int32_t)(next_u32() % (uint32_t)(span << 8));
            Y[k] = by + (int32_t)(next_u32() % (uint32_t)(span << 8));
        }
        int64_t area2 = mote__area2(X, Y);
        if (area2 == 0)
            continue;
        /* the pixels whose centre (x + 1/2) lies within the vertices' extent, on screen */
        int32_t minx = MOTE__MIN(X[0], MOTE__MIN(X[1], X[2])), maxx = MOTE__MAX(X[0], MOTE__MAX(X[1], X[2]));
        int32_t miny = MOTE__MIN(Y[0], MOTE__MIN(Y[1], Y[2])), maxy = MOTE__MAX(Y[0], MOTE__MAX(Y[1], Y[2]));
        int x0 = floor_px(minx - 128 + 255), x1 = floor_px(maxx - 128);
        int y0 = floor_px(miny - 128 + 255), y1 = floor_px(maxy - 128);
        bool empty_box = x0 > x1 || y0 > y1;
        x0 = MOTE__MAX(x0, 0);
        y0 = MOTE__MAX(y0, 0);
        x1 = MOTE__MIN(x1, W - 1);
        y1 = MOTE__MIN(y1, H - 1);
        memset(c, 0, sizeof c);
        memset(d, 0xff, sizeof d);
        mote__tri tri;
        mote__setup_result set = mote__setup(&tri, &rs, X, Y, area2, pv, 8, W, H);
        if (x0 > x1 || y0 > y1) {
            /* between pixel centres (wherever it is), or off the screen */
            TEST_ASSERT_EQUAL_INT(empty_box ? MOTE__SETUP_EMPTY : MOTE__SETUP_OUTSIDE, set);
            dropped++;
            empty += empty_box;
            continue;
        }
        TEST_ASSERT_EQUAL_INT(MOTE__SETUP_DRAWN, set);
        kept++;
        TEST_ASSERT_EQUAL_INT(x0, tri.xmin);
        TEST_ASSERT_EQUAL_INT(x1, tri.xmax);
        TEST_ASSERT_EQUAL_INT(y0, tri.ymin);
        TEST_ASSERT_EQUAL_INT(y1, tri.ymax);
        mote__counts n = {0, 0};
        mote__target tg = {c, W * 4, d, W, 0, MOTE_FORMAT_RGBA8888, MOTE_DEPTH_FORMAT_32, &n};
        mote__rect all = {0, 0, W, H};
        mote__raster_tri(&tri, &tg, all, 8);
        pixels += (long)n.written;
    }
    /* both ends were reached, and the kept ones drew */
    TEST_ASSERT_GREATER_THAN(1000, dropped);
    TEST_ASSERT_GREATER_THAN(500, empty);
    TEST_ASSERT_GREATER_THAN(5000, kept);
    TEST_ASSERT_GREATER_THAN(10000, pixels);
}

/* clear_drawn_tiles_only: frame after frame, a scene moving across the
 * screen (so the tiles drawn into change), with an empty frame, frames
 * that keep colour or depth and a points draw, gives the colour and depth
 * bytes of a device that clears everything; for tile sizes, threads and an
 * arena that fills up. And it does skip tiles, except right after a frame
 * that leaves them unknown. */
#define CLEAR_FRAMES 12
void clearing_only_the_drawn_tiles_should_give_the_frames_of_a_full_clear(void)
{
    static uint8_t ref[W * H * 4], got[W * H * 4];
    static uint32_t ref_depth[W * H], got_depth[W * H];
    static uint64_t arena_big[(8u << 20) / 8], arena_small[(96u << 10) / 8];
    mote_mesh meshes[3];
    make_scene(meshes);
    int tiles[] = {8, 64}, threads[] = {0, 2};
    void *arenas[] = {arena_big, arena_small};
    size_t arena_sizes[] = {sizeof arena_big, sizeof arena_small};
    for (int ti = 0; ti < 2; ti++)
    for (int th = 0; th < 2; th++)
    for (int ai = 0; ai < 2; ai++) {
        int none = 0;
        mote_device full, lazy;
        mote_device_desc fd = test_desc(ref, ref_depth, NULL, 0, 64, &none);
        mote_device_desc ld = test_desc(got, got_depth, arenas[ai], arena_sizes[ai], tiles[ti], &threads[th]);
        ld.clear_drawn_tiles_only = true;
        TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&full, &fd));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&lazy, &ld));
        uint32_t skipped = 0;
        for (int frame = 0; frame < CLEAR_FRAMES; frame++) {
            mote_frame_desc f;
            memset(&f, 0, sizeof f);
            f.camera.position[2] = -6.0f;
            f.keep_color = frame == 5;
            f.keep_depth = frame == 9;
            mote_mesh m = meshes[frame % 3];
            m.position[0] = -3.0f + 0.5f * (float)frame;
            m.scaling[0] = m.scaling[1] = m.scaling[2] = 0.5f;
            mote_draw_desc dd;
            memset(&dd, 0, sizeof dd);
            dd.cull = MOTE_CULL_NONE;
            mote_draw_desc points = dd;
            points.mode = MOTE_MODE_POINTS;
            mote_device *devs[2] = {&full, &lazy};
            for (int k = 0; k < 2; k++) {
                TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(devs[k], &f));
                if (frame != 3)   /* an empty frame */
                    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(devs[k], &m, &dd));
                if (frame == 7)
                    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(devs[k], &meshes[(frame + 1) % 3], &points));
                TEST_ASSERT_EQUAL(MOTE_OK, mote_end(devs[k]));
            }
            TEST_ASSERT_EQUAL_MEMORY(ref, got, sizeof ref);
            TEST_ASSERT_EQUAL_MEMORY(ref_depth, got_depth, sizeof ref_depth);
            uint32_t s = mote_device_stats(&lazy)->tiles_clear_skipped;
            if (frame == 0 || frame == 6 || frame == 8 || frame == 10)   /* the first, or after keep or points */
                TEST_ASSERT_EQUAL_UINT32(0, s);
            skipped += s;
            TEST_ASSERT_EQUAL_UINT32(0, mote_device_stats(&full)->tiles_clear_skipped);
        }
        TEST_ASSERT_TRUE(skipped > 0);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(every_specialised_span_should_match_the_generic_span);
    RUN_TEST(every_vector_span_should_match_the_scalar_span);
    RUN_TEST(the_vector_reciprocal_should_match_the_scalar_one);
    RUN_TEST(a_record_should_keep_planes_up_to_its_last_one);
    RUN_TEST(firmware_span_should_match_the_generic_span);
    RUN_TEST(subspan_pixels_should_not_depend_on_the_depth_rejected_pixels_before_them);
    RUN_TEST(subspan_slivers_should_stay_close_to_the_exact_perspective);
    RUN_TEST(subspan_worst_sliver_should_stay_within_its_bound);
    RUN_TEST(subspan_pixels_should_not_depend_on_the_region);
    RUN_TEST(a_triangle_should_draw_the_same_bytes_whatever_order_its_vertices_come_in);
    RUN_TEST(setup_should_box_a_triangle_by_the_pixel_centres_its_vertices_span);
    RUN_TEST(frames_should_be_the_same_bytes_for_any_threads_tiles_arena_and_bands);
    RUN_TEST(vertex_colours_should_be_the_same_bytes_for_any_threads_tiles_arena_and_bands);
    RUN_TEST(binned_draws_set_up_in_groups_should_match_the_serial_path);
    RUN_TEST(batches_of_tiny_draws_should_not_take_a_parallel_step_each);
    RUN_TEST(vertices_transformed_four_at_a_time_should_match_one_at_a_time);
    RUN_TEST(a_draw_cut_into_pieces_should_match_drawing_it_whole);
    RUN_TEST(the_clear_beside_parallel_setup_should_run_without_triangles_and_before_points);
    RUN_TEST(clearing_only_the_drawn_tiles_should_give_the_frames_of_a_full_clear);
    return UNITY_END();
}
