/*
 * plane.h - stepping the 32-bit pixel stage's planes, shared by every pixel
 * loop: span.c's generic and specialised ones, span_simd.h's vector ones
 * and span_fw.c's firmware one. The includer defines MOTE__PLANE_FN (how
 * its loop wants small helpers inlined) before including this file.
 *
 * Each helper is modular, so a hostile triangle gives garbage texels, not
 * undefined behaviour. Where registers are 32 bits wide (microcontrollers)
 * the 64-bit steps are built from 32-bit halves: a 64-bit shift by a
 * variable or a 64-bit product is a libgcc call there.
 */
#ifndef MOTE_CORE_PLANE_H
#define MOTE_CORE_PLANE_H

#include "internal.h"

#if MOTE__SHARED_COPY
/* size builds: declared for every loop, defined once by shared.c */
#undef MOTE__PLANE_FN
#define MOTE__PLANE_FN MOTE__SHARED
int64_t mote__plane_at(int64_t base, int64_t step, int32_t d);
int32_t mote__to32(int64_t v, int s);
int32_t mote__step32(int64_t v, int s);
int32_t mote__attr(int32_t a0, int32_t n, int32_t r, int shift);
uint32_t mote__clamp_shade(int32_t v);
#elif !defined(MOTE__PLANE_FN)
#define MOTE__PLANE_FN static inline
#endif

/* Two channels in one multiplication, and 64-bit steps done natively,
 * where registers are 64 bits wide. */
#if defined(__SIZEOF_POINTER__) && __SIZEOF_POINTER__ >= 8
#define MOTE__WIDE_REGISTERS 1
#else
#define MOTE__WIDE_REGISTERS 0
#endif

#if MOTE__SHARED_BODIES
/* A plane's value d steps (of one axis, |d| < 2^31) from base. The value
 * at a pixel of the triangle fits in 64 bits, but d * step alone may not
 * (the origin can lie far outside the viewport, and the row and column
 * terms then nearly cancel), so the sum is formed modulo 2^64, which is
 * exact whenever the result fits. */
MOTE__PLANE_FN int64_t mote__plane_at(int64_t base, int64_t step, int32_t d)
{
#if MOTE__WIDE_REGISTERS
    return (int64_t)((uint64_t)base + (uint64_t)step * (uint64_t)(int64_t)d);
#else
    const uint32_t ad = d < 0 ? 0u - (uint32_t)d : (uint32_t)d;
    const uint64_t s = (uint64_t)step;
    /* without a long multiply, the usual step from the origin (within
     * the guard band: below 2^16) takes two 16x16-bit products */
    uint64_t p = MOTE__NO_UMULL && ad >> 16 == 0 ? mote__umul64_short((uint32_t)s, ad) : mote__umul64((uint32_t)s, ad);
    p += (uint64_t)((uint32_t)(s >> 32) * ad) << 32;
    if (d < 0)
        p = 0u - p;
    return (int64_t)((uint64_t)base + p);
#endif
}

/* The low 32 bits of floor(v / 2^s), 0 <= s < 63: a plane's value at a
 * block's first pixel (in range inside the triangle). */
MOTE__PLANE_FN int32_t mote__to32(int64_t v, int s)
{
#if MOTE__WIDE_REGISTERS
    return (int32_t)(uint32_t)(uint64_t)mote__floor_shift64(v, s);
#else
    const uint32_t lo = (uint32_t)(uint64_t)v, hi = (uint32_t)((uint64_t)v >> 32);
    if (s >= 32)
        return mote__floor_shift32((int32_t)hi, s - 32);
    return s ? (int32_t)((lo >> s) | (hi << (32 - s))) : (int32_t)lo;
#endif
}

/* A plane's step v / 2^s rounded, in 32 bits (0 <= s < 63): the drift
 * over a block is then at most half a unit a pixel. */
MOTE__PLANE_FN int32_t mote__step32(int64_t v, int s)
{
#if MOTE__WIDE_REGISTERS
    return mote__to32((int64_t)((uint64_t)v + (((uint64_t)1 << s) >> 1)), s);
#else
    /* half a unit from a 32-bit shift: a 64-bit one by a variable is a
     * libgcc call */
    const uint64_t half = s == 0 ? 0u : s <= 32 ? (uint64_t)((uint32_t)1 << (s - 1)) : (uint64_t)((uint32_t)1 << (s - 33)) << 32;
    return mote__to32((int64_t)((uint64_t)v + half), s);
#endif
}

#endif

/* A block whose Q runs from q64 to q64e (its ends): the shift d that takes
 * Q to 30 bits, Q's 32-bit ends qa and qe, the reciprocal's precision k
 * and the attributes' shift ash (below 0 only for absurd texel ranges:
 * clamped to keep the shift defined). */
typedef struct mote__block_scale {
    int d, k, ash;
    int32_t qa, qe;
} mote__block_scale;

static inline mote__block_scale mote__block_scale_of(int64_t q64, int64_t q64e, int n_extra)
{
    mote__block_scale s;
    s.d = MOTE__MAX(mote__bitlen((uint64_t)MOTE__MAX(MOTE__MAX(q64, q64e), 1)) - 30, 0);
    s.qa = mote__to32(q64, s.d);
    s.qe = mote__to32(q64e, s.d);
    s.k = mote__bitlen((uint64_t)MOTE__MAX(MOTE__MIN(s.qa, s.qe), 1)) + 29;
    s.ash = MOTE__MAX(s.k - 20 - n_extra, 0);
    return s;
}

/* v + d w in 32 bits, modular (the planes' stepping); short enough to
 * inline everywhere */
static inline int32_t mote__add32(int32_t v, int32_t w, int32_t d)
{
    return (int32_t)((uint32_t)v + (uint32_t)w * (uint32_t)d);
}

#if MOTE__SHARED_BODIES
/* An attribute from its numerator n and reciprocal r >= 0 (see mote__tri):
 * a0 + (n r >> shift), one 32x32-bit product. */
MOTE__PLANE_FN int32_t mote__attr(int32_t a0, int32_t n, int32_t r, int shift)
{
#if MOTE__WIDE_REGISTERS
    return (int32_t)((uint32_t)a0 + (uint32_t)(((int64_t)n * r) >> shift));
#else
    const uint32_t an = n < 0 ? 0u - (uint32_t)n : (uint32_t)n;
    uint64_t p = mote__umul64(an, (uint32_t)r);
    if (n < 0)
        p = 0u - p;
    return (int32_t)((uint32_t)a0 + (uint32_t)mote__to32((int64_t)p, shift));
#endif
}

/* An interpolated shade clamped to [0, 1] (rounding can take it a little
 * out): one test for the usual in-range value. */
MOTE__PLANE_FN uint32_t mote__clamp_shade(int32_t v)
{
    if ((uint32_t)v > MOTE__SHADE_ONE)
        return v < 0 ? 0u : (uint32_t)MOTE__SHADE_ONE;
    return (uint32_t)v;
}
#endif

#endif
