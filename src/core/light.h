/*
 * light.h - the light model, written once (CONVENTIONS, Lighting, in
 * mote.h): Babylon.js's StandardMaterial, diffuse only.
 *
 * The model is a template over the number type T: vertex.c instantiates
 * it with float (every target, and flat shading) and, on SSE2 hosts, with
 * four-lane vectors (four vertices at a time). Each lane performs the
 * float operations of the scalar code in the same order, so both give the
 * same bits. Per light, a point p with unit normal n gets
 *   L    = the light's position - p (point, spot), or -direction
 *   ndl  = n . L / |L|
 *   hemispheric:   k (col w + ground (1 - w)), w = 0.5 + 0.5 ndl
 *   others, ndl>0: k col ndl falloff
 * summed with the ambient colour; then clamp(sum x material + emissive).
 *
 * To instantiate, define before including this file:
 *   MOTE__LT          the number type (float, or a vector of floats)
 *   MOTE__LT_MASK     the type of a comparison of two MOTE__LT
 *   MOTE__LT_SPLAT(x) a float as MOTE__LT
 *   MOTE__LT_SELECT(m, a, b)  a where m is set, b elsewhere
 *   MOTE__LT_ANY(m)   whether any lane of m is set (may be 1: a shortcut)
 *   MOTE__LT_RSQRT(x) mote__rsqrtf of each lane
 *   MOTE__LT_LANES, MOTE__LT_LANE(v, j)  lane j of v, as an lvalue
 *   MOTE__LT_SET, MOTE__LT_LIGHT  the set and light types (MOTE__LIGHT_TYPES)
 *   MOTE__LT_PREPARE, MOTE__LT_EVAL   the names of the two functions
 * and include it; it undefines them.
 */
#ifndef MOTE_CORE_LIGHT_H
#define MOTE_CORE_LIGHT_H

#include "internal.h"

/* A draw's lights as the model reads them, in numbers of type T: the
 * frame's lights that light, each with what every point would otherwise
 * work out again (its colour and intensity resolved, the direction toward
 * a directional light), the ambient colour and the material's. */
#define MOTE__LIGHT_TYPES(T, set_type, light_type)                                           \
    typedef struct light_type {                                                                \
        mote_light_type type;                                                                  \
        bool positional;          /* point or spot: shines from at */                          \
        bool falloff;             /* a range or a cone (mote__falloff) */                      \
        int index;                /* in the frame's lights */                                  \
        T at[3];                  /* the position, or the direction toward the light */        \
        T kcol[3];                /* intensity x colour */                                     \
        T k, col[3], ground[3];   /* hemispheric */                                            \
    } light_type;                                                                              \
    typedef struct set_type {                                                                  \
        int count;                                                                             \
        T ambient[3], color[3], emissive[3];                                                   \
        const mote_device *dev;   /* the frame's lights, for their falloff */                  \
        light_type light[MOTE_MAX_LIGHTS];                                                     \
    } set_type;

#endif /* MOTE_CORE_LIGHT_H */

#ifdef MOTE__LT
#ifndef MOTE__LIGHT_HELPERS
#define MOTE__LIGHT_HELPERS

/* What lighting takes of light l: its colour (white when unset), its
 * intensity (1 when unset) and the sign that turns a directional light's
 * direction toward the light. False for a type that lights nothing. */
static bool mote__light_terms(const mote_light *l, float col[3], float *k, float *s)
{
    if (l->type != MOTE_LIGHT_POINT && l->type != MOTE_LIGHT_DIRECTIONAL && l->type != MOTE_LIGHT_HEMISPHERIC
        && !(MOTE_ENABLE_LIGHT_FALLOFF && l->type == MOTE_LIGHT_SPOT))
        return false;
    memcpy(col, l->color, 3 * sizeof *col);
    if (mote__zero3(col))
        col[0] = col[1] = col[2] = 1.0f;
    *k = mote__or(l->intensity, 1.0f);
    *s = l->type == MOTE_LIGHT_DIRECTIONAL ? -1.0f : 1.0f;
    return true;
}

#if MOTE_ENABLE_LIGHT_FALLOFF || MOTE__ADD_ENABLED
/* x^e for x in [0, 1] and e >= 0, as 2^(e log2 x), in float operations of
 * a fixed order (libm's powf differs between targets); relative error
 * about 1e-6. */
static float mote__powf01(float x, float e)
{
    if (!(x > 0.0f))
        return e > 0.0f ? 0.0f : 1.0f;
    if (!(e > 0.0f) || x >= 1.0f)
        return 1.0f;              /* e NaN: a cone without falloff */
    /* x = m 2^ex with m in [sqrt(1/2), sqrt(2)); log2 m = 2 atanh(t) / ln 2,
     * t = (m - 1) / (m + 1), |t| < 0.172 */
    uint32_t b = mote__float_bits(x);
    int ex = (int)(b >> 23) - 127;
    if (ex == -127)               /* subnormal: as good as 0 for light */
        return 0.0f;
    union { float f; uint32_t u; } m;
    m.u = (b & 0x007fffffu) | 0x3f800000u;
    if (m.f > 1.41421356f) {
        m.f *= 0.5f;
        ex++;
    }
    float t = (m.f - 1.0f) / (m.f + 1.0f), t2 = t * t;
    float series = 1.0f + t2 * (1.0f / 3 + t2 * (1.0f / 5 + t2 * (1.0f / 7 + t2 * (1.0f / 9))));
    float y = e * ((float)ex + 2.88539008f * t * series);   /* e log2 x < 0, or -inf */
    if (y < -126.0f)
        return 0.0f;
    /* 2^y = 2^i 2^f, i = round(y), |f| <= 1/2: e^(f ln 2) by its series */
    int i = (int)(y - 0.5f);
    i += (y - (float)i) >= 0.5f;
    float g = (y - (float)i) * 0.693147181f;
    float p = 1.0f + g * (1.0f + g * (0.5f + g * (1.0f / 6 + g * (1.0f / 24 + g * (1.0f / 120 + g * (1.0f / 720))))));
    union { float f; uint32_t u; } scale;
    scale.u = (uint32_t)(i + 127) << 23;
    return p * scale.f;
}
#endif

#if MOTE_ENABLE_LIGHT_FALLOFF

/* Babylon.js's default falloff of the frame's light i, a point or spot
 * light (StandardMaterial: max(0, 1 - distance / range); a spot light's
 * cos(angle to its axis), 0 outside the cone and raised to its exponent
 * inside), for L from the surface point to the light and inv = 1 / |L| as
 * the lighting took it. Scalar in every instantiation (a vector one calls
 * it per lane), so that all give the same bits. */
static float mote__falloff(const mote_device *dev, int i, const float L[3], float inv)
{
    const mote_light *l = &dev->frame.lights[i];
    const float *cone = dev->spot_cone[i];   /* mote_begin's */
    float att = 1.0f;
    if (l->range > 0.0f) {
        att = 1.0f - mote__dot3(L, L) * inv / l->range;
        att = att > 0.0f ? att : 0.0f;
    }
    if (l->type == MOTE_LIGHT_SPOT) {
        float c = -(mote__dot3(l->direction, L) * cone[0]) * inv;
        c = c > 0.0f ? c : 0.0f;
        if (!(c >= cone[1]))
            return 0.0f;
        att *= mote__powf01(c, l->spot_exponent);
    }
    return att;
}
#endif

#if MOTE_ENABLE_SPECULAR
/* Blinn-Phong highlights at camera-relative position p with unit normal n,
 * as Babylon.js's StandardMaterial sums them (no n.l test): per light not
 * in off, pow(max(0, n.h), max(1, power)) x intensity x its specular
 * colour x its falloff, h = normalize(l + v), v toward the eye; a
 * hemispheric light's l is its direction, without falloff. */
static void mote__specular(const mote_device *dev, uint32_t off, const float p[3], const float n[3], float power,
                           float out[3])
{
    out[0] = out[1] = out[2] = 0.0f;
    float V[3] = {-p[0], -p[1], -p[2]};
    const float iv = mote__rsqrtf(mote__dot3(V, V));
    const mote_frame_desc *f = &dev->frame;
    for (int i = 0; i < f->light_count && i < MOTE_MAX_LIGHTS; i++) {
        const mote_light *l = &f->lights[i];
        float col[3], k, s;
        if ((off >> i & 1) || !mote__light_terms(l, col, &k, &s))
            continue;
        const bool positional = l->type == MOTE_LIGHT_POINT || l->type == MOTE_LIGHT_SPOT;
        float L[3], H[3];
        for (int c = 0; c < 3; c++)
            L[c] = positional ? l->position[c] - p[c] : s * l->direction[c];
        const float inv = mote__rsqrtf(mote__dot3(L, L));
        for (int c = 0; c < 3; c++)
            H[c] = L[c] * inv + V[c] * iv;
        const float h = mote__dot3(n, H) * mote__rsqrtf(mote__dot3(H, H));
        if (!(h > 0.0f))
            continue;
        float att = mote__powf01(h, power > 1.0f ? power : 1.0f) * k;
#if MOTE_ENABLE_LIGHT_FALLOFF
        if (l->type == MOTE_LIGHT_SPOT || (l->type == MOTE_LIGHT_POINT && l->range > 0.0f))
            att *= mote__falloff(dev, i, L, inv);
#endif
        for (int c = 0; c < 3; c++)
            out[c] += att * (mote__zero3(l->specular) ? 1.0f : l->specular[c]);
    }
}
#endif

#if MOTE_ENABLE_FOG
/* Babylon.js's fog factor at distance d from the camera: 1 clear, 0 all
 * fog. */
static float mote__fog_factor(const mote_fog *fog, float d)
{
    float f = 1.0f;
    if (fog->mode == MOTE_FOG_LINEAR) {
        const float span = fog->end - fog->start;
        f = span != 0.0f ? (fog->end - d) / span : (d < fog->end ? 1.0f : 0.0f);
    } else if (fog->mode == MOTE_FOG_EXP || fog->mode == MOTE_FOG_EXP2) {
        const float x = d * fog->density;
        f = mote__powf01(0.367879441f, fog->mode == MOTE_FOG_EXP ? x : x * x);   /* e^-x */
    }
    return f > 0.0f ? (f < 1.0f ? f : 1.0f) : 0.0f;   /* NaN: all fog */
}
#endif
#endif /* MOTE__LIGHT_HELPERS */

/* The set of a draw: the frame's lights but those whose bit is set in off
 * (mote_draw_desc.lights_off) and its ambient colour, the material's
 * colour and emissive colour (0..1). */
static void MOTE__LT_PREPARE(MOTE__LT_SET *set, const mote_device *dev, const float color[3],
                             const float emissive[3], uint32_t off)
{
    const mote_frame_desc *f = &dev->frame;
    set->dev = dev;
    for (int c = 0; c < 3; c++) {
        set->ambient[c] = MOTE__LT_SPLAT(f->ambient[c]);
        set->color[c] = MOTE__LT_SPLAT(color[c]);
        set->emissive[c] = MOTE__LT_SPLAT(emissive[c]);
    }
    set->count = 0;
    for (int i = 0; i < f->light_count && i < MOTE_MAX_LIGHTS; i++) {
        const mote_light *l = &f->lights[i];
        float col[3], k, s;
        if ((off >> i & 1) || !mote__light_terms(l, col, &k, &s))
            continue;
        MOTE__LT_LIGHT *o = &set->light[set->count++];
        o->type = l->type;
        o->positional = l->type == MOTE_LIGHT_POINT || (MOTE_ENABLE_LIGHT_FALLOFF && l->type == MOTE_LIGHT_SPOT);
        o->falloff = MOTE_ENABLE_LIGHT_FALLOFF
                  && (l->type == MOTE_LIGHT_SPOT || (l->type == MOTE_LIGHT_POINT && l->range > 0.0f));
        o->index = i;
        o->k = MOTE__LT_SPLAT(k);
        for (int c = 0; c < 3; c++) {
            o->at[c] = MOTE__LT_SPLAT(o->positional ? l->position[c] : s * l->direction[c]);
            o->kcol[c] = MOTE__LT_SPLAT(k * col[c]);
            o->col[c] = MOTE__LT_SPLAT(col[c]);
            o->ground[c] = MOTE__LT_SPLAT(l->ground_color[c]);
        }
    }
}

/* The lit colour, clamped to [0, 1], at world position p with unit normal n. */
MOTE__VERTEX_INLINE void MOTE__LT_EVAL(const MOTE__LT_SET *set, const MOTE__LT p[3], const MOTE__LT n[3],
                                       MOTE__LT out[3])
{
    MOTE__LT acc[3] = {set->ambient[0], set->ambient[1], set->ambient[2]};
    for (int i = 0; i < set->count; i++) {
        const MOTE__LT_LIGHT *l = &set->light[i];
        MOTE__LT L[3];
        for (int c = 0; c < 3; c++)
            L[c] = l->positional ? l->at[c] - p[c] : l->at[c];
        const MOTE__LT inv = MOTE__LT_RSQRT(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
        const MOTE__LT ndl = (n[0] * L[0] + n[1] * L[1] + n[2] * L[2]) * inv;
        if (l->type == MOTE_LIGHT_HEMISPHERIC) {
            const MOTE__LT w = 0.5f + 0.5f * ndl;
            for (int c = 0; c < 3; c++)
                acc[c] += l->k * (l->col[c] * w + l->ground[c] * (1.0f - w));
            continue;
        }
        const MOTE__LT_MASK lit = ndl > 0.0f;
        if (!MOTE__LT_ANY(lit))
            continue;
        MOTE__LT att = MOTE__LT_SPLAT(1.0f);   /* times 1: the same bits as without */
#if MOTE_ENABLE_LIGHT_FALLOFF
        if (l->falloff)
            for (int j = 0; j < MOTE__LT_LANES; j++) {
                const float Lj[3] = {MOTE__LT_LANE(L[0], j), MOTE__LT_LANE(L[1], j), MOTE__LT_LANE(L[2], j)};
                MOTE__LT_LANE(att, j) = mote__falloff(set->dev, l->index, Lj, MOTE__LT_LANE(inv, j));
            }
#endif
        for (int c = 0; c < 3; c++)
            acc[c] = MOTE__LT_SELECT(lit, acc[c] + l->kcol[c] * ndl * att, acc[c]);
    }
    /* the material colour times the lights, plus its emissive colour,
     * then clamped: clamp(diffuseBase x diffuseColor + emissive + ambient) */
    for (int c = 0; c < 3; c++) {
        MOTE__LT v = acc[c] * set->color[c];
#if MOTE_ENABLE_EMISSIVE
        v += set->emissive[c];
#endif
        /* also maps NaN to 0 */
        out[c] = MOTE__LT_SELECT(v > 0.0f, MOTE__LT_SELECT(v < 1.0f, v, MOTE__LT_SPLAT(1.0f)), MOTE__LT_SPLAT(0.0f));
    }
}

#undef MOTE__LT
#undef MOTE__LT_MASK
#undef MOTE__LT_SPLAT
#undef MOTE__LT_SELECT
#undef MOTE__LT_ANY
#undef MOTE__LT_RSQRT
#undef MOTE__LT_LANES
#undef MOTE__LT_LANE
#undef MOTE__LT_SET
#undef MOTE__LT_LIGHT
#undef MOTE__LT_PREPARE
#undef MOTE__LT_EVAL
#endif /* MOTE__LT */
