/*
 * vertex_fixed.h - the integer vertex stage (MOTE_FIXED_VERTEX, see mote.h).
 *
 * draw.c builds a draw's context in float as always (matrices, bounds
 * rejection, raster state), then hands the draw here when
 * mote__fixed_handles says this stage can do all of it; the triangles come
 * back through emit, snapped and in setup's units, as the float stage makes
 * them. Number formats and error bounds: docs/accuracy.md.
 */
#ifndef MOTE_CORE_VERTEX_FIXED_H
#define MOTE_CORE_VERTEX_FIXED_H

#include "internal.h"

/* floor(sum_k a_k p_k / 2^s) modulo 2^32 (0 < s <= 32) from the 16-bit
 * halves of each factor, x = xh 2^16 + xl with xl in [0, 2^16): four
 * 16x16-bit products a term and 32-bit sums, where a 32x32->64-bit
 * product is a call (ARMv6-M). Exact for |a_k| < 2^27 and |p_k| < 2^24:
 * every partial sum then fits in 31 bits. */
static inline int32_t mote__fx_dot3_halves(const int32_t ah[3], const uint32_t al[3], const int32_t ph[3],
                                           const uint32_t pl[3], int s)
{
    /* in separate sums, which keep ARMv6-M's eight registers enough */
    const int32_t hh = ah[0] * ph[0] + ah[1] * ph[1] + ah[2] * ph[2];
    const int32_t mid = ah[0] * (int32_t)pl[0] + ah[1] * (int32_t)pl[1] + ah[2] * (int32_t)pl[2]
                      + (int32_t)al[0] * ph[0] + (int32_t)al[1] * ph[1] + (int32_t)al[2] * ph[2];
    const uint32_t l0 = al[0] * pl[0], l1 = al[1] * pl[1], l2 = al[2] * pl[2];
    const uint32_t llo = (l0 & 0xffffu) + (l1 & 0xffffu) + (l2 & 0xffffu);
    /* the sum is hh 2^32 + t 2^16 + (llo mod 2^16), the last below 2^16 */
    const int32_t t = (int32_t)((uint32_t)mid + (l0 >> 16) + (l1 >> 16) + (l2 >> 16) + (llo >> 16));
    const uint32_t high = (uint32_t)hh << (32 - s);
    if (s >= 16)
        return (int32_t)(high + (uint32_t)mote__floor_shift32(t, s - 16));
    return (int32_t)(high + ((uint32_t)t << (16 - s)) + ((llo & 0xffffu) >> s));
}

#if MOTE_FIXED_VERTEX

/* assemble.c: a triangle of the draw whose context is cx, in two steps
 * (its mote__emit): what needs no shade (band range, hook, the band's
 * test; true when that ends it), then setup and the sink. Direct calls,
 * not pointers: the stack bound (embedded/stack-usage.sh) follows them. */
bool mote__fixed_emit_begin(void *cx, const int32_t X[3], const int32_t Y[3], const mote__svert *const v[3]);
void mote__fixed_emit(void *cx, const int32_t X[3], const int32_t Y[3], int64_t area2,
                      const mote__svert *const v[3]);

/* assemble.c: whether triangle i misses the band being drawn (band bins,
 * which the first band records through mote__fixed_emit). */
bool mote__fixed_skip(void *cx, uint32_t i);

/* What the float context of a draw gives this stage (draw.c's mote__ctx). */
typedef struct mote__fixed_draw {
    const float *mvp, *world;     /* column-major, camera-relative */
    const float *nrm;             /* normal matrix, row-major 3x3 */
    float uscale, vscale, uoff, voff;
    bool lit, flat, cull_cw, cull_ccw;
    const mote__raster_state *rs;
    void *cx;                     /* mote__fixed_emit's */
    uint32_t lights_off;          /* mote_draw_desc.lights_off */
    /* band bins after the first band (NULL otherwise): each triangle's
     * first and last band, read here so that a band skips the triangles
     * that miss it in a few instructions, not two calls */
    const unsigned char *bins;
    unsigned band;
} mote__fixed_draw;

/* Whether this stage draws the draw: triangles (points and wireframe stay
 * on the float path), without vertex colours, specular highlights or fog,
 * in a frame without spot lights or light ranges. A constant true in a build that leaves those out
 * (the firmware profile), so that the float per-vertex code is not linked. */
static inline bool mote__fixed_handles(const mote_device *dev, const mote_mesh *mesh, const mote_draw_desc *d)
{
    if (MOTE_ENABLE_LINES && (d->mode == MOTE_MODE_POINTS || d->mode == MOTE_MODE_WIREFRAME))
        return false;
    if (MOTE_ENABLE_VERTEX_COLORS && mesh->colors)
        return false;
    if (MOTE_ENABLE_SPECULAR && mesh->material.specular.r | mesh->material.specular.g | mesh->material.specular.b)
        return false;
    if (MOTE_ENABLE_FOG && dev->frame.fog.mode != MOTE_FOG_NONE && !d->no_fog)
        return false;
#if MOTE_ENABLE_LIGHT_FALLOFF
    if (!d->unlit)
        for (int i = 0; i < dev->frame.light_count && i < MOTE_MAX_LIGHTS; i++) {
            const mote_light *l = &dev->frame.lights[i];
            if (l->type == MOTE_LIGHT_SPOT || (l->type == MOTE_LIGHT_POINT && l->range > 0.0f))
                return false;
        }
#else
    (void)dev;
#endif
    return true;
}

/* Triangles [first, end) of the mesh through the integer stage. */
void mote__fixed_triangles(mote_device *dev, const mote_mesh *mesh, const mote__fixed_draw *fd,
                           uint32_t first, uint32_t end);

#endif
#endif
