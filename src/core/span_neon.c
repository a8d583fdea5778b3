/*
 * span_neon.c - span_simd.h's fill functions, 4 pixels a step in NEON,
 * which every AArch64 processor has.
 */
#include "internal.h"

#if MOTE_SIMD && defined(__aarch64__)
#include <arm_neon.h>

#define MOTE__VN 4
#define MOTE__SIMD_TABLE mote__fill_neon
#define MOTE__SIMD_RECIP mote__recip_neon

typedef int32_t mote__vi4 __attribute__((vector_size(16)));

/* (int32)((int64) n r >> s): widening products, an arithmetic shift (a
 * left shift by -s), and the low halves */
static inline __attribute__((always_inline)) mote__vi4 mote__v_mulshift(mote__vi4 n, mote__vi4 r, int s)
{
    const int32x4_t nn = (int32x4_t)n, rr = (int32x4_t)r;
    const int64x2_t by = vdupq_n_s64(-s);
    const int64x2_t lo = vshlq_s64(vmull_s32(vget_low_s32(nn), vget_low_s32(rr)), by);
    const int64x2_t hi = vshlq_s64(vmull_high_s32(nn, rr), by);
    return (mote__vi4)vmovn_high_s64(vmovn_s64(lo), hi);
}

static inline __attribute__((always_inline)) unsigned mote__v_bits(mote__vi4 mask)
{
    const uint32x4_t bit = {1, 2, 4, 8};
    return vaddvq_u32(vandq_u32((uint32x4_t)mask, bit));
}

#include "span_simd.h"
#else
typedef int mote__span_neon_unused;   /* ISO C wants a declaration */
#endif
