/*
 * span_sse2.c - span_simd.h's fill functions, 4 pixels a step in SSE2,
 * which every x86-64 processor has: what span_simd.c chooses where AVX2
 * is absent.
 */
#include "internal.h"

#if MOTE_SIMD && defined(__x86_64__)
#include <emmintrin.h>

#define MOTE__VN 4
#define MOTE__SIMD_TABLE mote__fill_sse2
#define MOTE__SIMD_RECIP mote__recip_sse2

typedef int32_t mote__vi4 __attribute__((vector_size(16)));

/* (int32)((int64) n r >> s) for r >= 0: SSE2 multiplies unsigned, so a
 * negative n's product is corrected by r 2^32; then span_avx2.c's two
 * shifts. */
static inline __attribute__((always_inline)) mote__vi4 mote__v_mulshift(mote__vi4 n, mote__vi4 r, int s)
{
    const __m128i first = _mm_cvtsi32_si128(s < 32 ? s : 32), rest = _mm_cvtsi32_si128(s > 32 ? s - 32 : 0);
    const __m128i nn = (__m128i)n, rr = (__m128i)r, fix = _mm_and_si128(_mm_srai_epi32(nn, 31), rr);
    const __m128i high = _mm_set_epi32(-1, 0, -1, 0);
    __m128i even = _mm_sub_epi64(_mm_mul_epu32(nn, rr), _mm_slli_epi64(fix, 32));
    __m128i odd = _mm_sub_epi64(_mm_mul_epu32(_mm_srli_epi64(nn, 32), _mm_srli_epi64(rr, 32)), _mm_and_si128(fix, high));
    even = _mm_srl_epi64(even, first);
    odd = _mm_srl_epi64(odd, first);
    return (mote__vi4)_mm_sra_epi32(_mm_or_si128(_mm_andnot_si128(high, even), _mm_slli_epi64(odd, 32)), rest);
}

static inline __attribute__((always_inline)) unsigned mote__v_bits(mote__vi4 mask)
{
    return (unsigned)_mm_movemask_ps((__m128)mask);
}

#include "span_simd.h"
#else
typedef int mote__span_sse2_unused;   /* ISO C wants a declaration */
#endif
