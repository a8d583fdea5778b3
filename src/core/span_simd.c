/*
 * span_simd.c - which of a draw's fills run in vector registers
 * (span_simd.h: span_sse2.c, span_avx2.c, span_neon.c), and on which
 * instruction set: AVX2 where the processor has it, else SSE2 on x86-64,
 * NEON on AArch64. Their bytes are the scalar loops', so the choice
 * changes only the speed.
 */
#include "internal.h"

#if MOTE_SIMD
/* The best set this processor runs. */
static int mote__isa_best(void)
{
#if defined(__x86_64__)
    return __builtin_cpu_supports("avx2") ? MOTE__ISA_AVX2 : MOTE__ISA_SSE2;
#else
    return MOTE__ISA_NEON;
#endif
}

static const mote__fill_fn *mote__isa_table(int isa)
{
#if defined(__x86_64__)
    return isa == MOTE__ISA_AVX2 ? mote__fill_avx2 : isa == MOTE__ISA_SSE2 ? mote__fill_sse2 : NULL;
#else
    return isa == MOTE__ISA_NEON ? mote__fill_neon : NULL;
#endif
}

/* Whether the vector loops read this draw's texels: nearest, from an
 * RGBA8888 texture addressed by masks and shifts whose bytes a 32-bit
 * offset reaches. */
static bool mote__simd_texture(const mote__raster_state *rs)
{
    return rs->tex == MOTE__TEX_NEAREST && rs->pow2_repeat && rs->texture->format == MOTE_FORMAT_RGBA8888
        && (int64_t)rs->tex_h << rs->tex_stride_log2 <= INT32_MAX;
}
#endif

bool mote__simd_select(mote__raster_state *rs, mote_format format, mote_depth_format depth_format, int isa)
{
#if MOTE_SIMD
    const mote__fill_fn *table = mote__isa_table(isa == MOTE__ISA_BEST ? mote__isa_best() : isa);
    const int f = format == MOTE_FORMAT_RGBA8888 ? 0 : format == MOTE_FORMAT_RGB565 ? 1 : -1;
    const int dsel = depth_format == MOTE_DEPTH_FORMAT_16 ? 1 : depth_format == MOTE_DEPTH_FORMAT_32 ? 2 : 0;
    const bool depth_on = rs->depth_test && rs->depth_write, depth_off = !rs->depth_test && !rs->depth_write;
    /* alpha tests and blending, mip levels and layers are the generic loop's
     * alone (span.c) */
    if (!table || f < 0 || rs->mips || mote__generic_only(rs) || !(depth_on || depth_off || dsel == 0))
        return false;
    const int d = depth_on ? dsel : 0;
    bool any = false;
    for (int s = 0; s < MOTE__SHADE_COUNT; s++) {
        /* a black triangle is filled as an untextured flat one (span.c) */
        if (s == MOTE__SHADE_ADD)
            continue;             /* additive colour: the generic loop's alone */
        const bool black = s == MOTE__SHADE_BLACK;
        const int shade = black ? MOTE__SHADE_FLAT : s, tex = black || rs->tex == MOTE__TEX_NONE ? 0 : 1;
        const bool varying = tex || shade != MOTE__SHADE_FLAT;
        if ((tex && !mote__simd_texture(rs)) || (varying && rs->persp == MOTE__PERSP_SUBSPAN))
            continue;
        const int p = varying && rs->persp == MOTE__PERSP_AFFINE ? 0 : 1;
        rs->fill[s] = table[(((tex * 3 + shade) * 2 + p) * 3 + d) * 2 + f];
        any = true;
    }
    return any;
#else
    (void)rs;
    (void)format;
    (void)depth_format;
    (void)isa;
    return false;
#endif
}
