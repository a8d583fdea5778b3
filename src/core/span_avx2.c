/*
 * span_avx2.c - span_simd.h's fill functions, 8 pixels a step in AVX2,
 * compiled for AVX2 whatever the build's baseline: span_simd.c chooses
 * them only where the processor has AVX2.
 */
#include "internal.h"

#if MOTE_SIMD && defined(__x86_64__)
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
#include <immintrin.h>

#define MOTE__VN 8
#define MOTE__V_GATHER 1
#define MOTE__SIMD_TABLE mote__fill_avx2
#define MOTE__SIMD_RECIP mote__recip_avx2

typedef int32_t mote__vi8 __attribute__((vector_size(32)));

/* (int32)((int64) n r >> s): the signed products of the even and of the
 * odd lanes, shifted right logically by min(s, 32) (the low 32 bits are
 * the arithmetic shift's for s <= 32, and the product's high half for s
 * >= 32), then arithmetically by the rest. */
static inline __attribute__((always_inline)) mote__vi8 mote__v_mulshift(mote__vi8 n, mote__vi8 r, int s)
{
    const __m128i first = _mm_cvtsi32_si128(s < 32 ? s : 32), rest = _mm_cvtsi32_si128(s > 32 ? s - 32 : 0);
    const __m256i nn = (__m256i)n, rr = (__m256i)r;
    const __m256i even = _mm256_srl_epi64(_mm256_mul_epi32(nn, rr), first);
    const __m256i odd = _mm256_srl_epi64(_mm256_mul_epi32(_mm256_srli_epi64(nn, 32), _mm256_srli_epi64(rr, 32)), first);
    return (mote__vi8)_mm256_sra_epi32(_mm256_blend_epi32(even, _mm256_slli_epi64(odd, 32), 0xaa), rest);
}

static inline __attribute__((always_inline)) mote__vi8 mote__v_gather(const uint8_t *base, mote__vi8 off)
{
    return (mote__vi8)_mm256_i32gather_epi32((const int *)(const void *)base, (__m256i)off, 1);
}

static inline __attribute__((always_inline)) unsigned mote__v_bits(mote__vi8 mask)
{
    return (unsigned)_mm256_movemask_ps((__m256)mask);
}

#include "span_simd.h"

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
#else
typedef int mote__span_avx2_unused;   /* ISO C wants a declaration */
#endif
