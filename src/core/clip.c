/*
 * clip.c - clipping and snapping: a vertex's outcode against the clip
 * planes (near, far and the guard band) and the viewport, Sutherland-
 * Hodgman clipping of a triangle that crosses a plane, and the snap of a
 * vertex to the sub-pixel grid, exact and the same on every target.
 */
#include "vertex.h"

/* Signed distances to the clip planes (inside >= 0). */
static void mote__plane_dists(const mote__ctx *cx, const mote__cvert *v, float d[MOTE__CLIP_PLANES])
{
    float gx = cx->guard_x * v->w, gy = cx->guard_y * v->w;
    d[0] = v->z;                  /* near: z >= 0 */
    d[1] = v->w - v->z;           /* far: z <= w */
    d[2] = v->x + gx;             /* guard band left */
    d[3] = gx - v->x;             /* right */
    d[4] = v->y + gy;             /* bottom */
    d[5] = gy - v->y;             /* top */
}

static float mote__plane_dist(const mote__ctx *cx, const mote__cvert *v, int p)
{
    float d[MOTE__CLIP_PLANES];
    mote__plane_dists(cx, v, d);
    return d[p];
}

/* every field of a vertex, as one array of floats */
#define MOTE__CVERT_FLOATS (sizeof(mote__cvert) / sizeof(float))
typedef char mote__cvert_is_floats[sizeof(mote__cvert) == (9 + 3 * MOTE__ADD_ENABLED) * sizeof(float) ? 1 : -1];

static void mote__lerp(const mote__cvert *a, const mote__cvert *b, float t, mote__cvert *out)
{
    float fa[MOTE__CVERT_FLOATS], fb[MOTE__CVERT_FLOATS];
    memcpy(fa, a, sizeof fa);
    memcpy(fb, b, sizeof fb);
    for (size_t k = 0; k < MOTE__CVERT_FLOATS; k++)
        fa[k] += (fb[k] - fa[k]) * t;
    memcpy(out, fa, sizeof fa);
}

/* Puts a vertex made by clipping against plane p exactly on it. The
 * interpolation alone can miss a guard-band plane by more than the guard
 * band when the edge runs from far outside (beyond about 1e10 pixels in
 * float), and the vertex would then fail to snap, or a later plane would
 * drop the polygon. Each plane's distance is then exactly 0. */
MOTE__SPEED_INLINE void mote__on_plane(const mote__ctx *cx, mote__cvert *v, int p)
{
    /* near z = 0, far z = w, then x and y at -+ the guard band */
    float g = p == 1 ? 1.0f : p == 0 ? 0.0f : p < 4 ? cx->guard_x : cx->guard_y;
    float *c = p < 2 ? &v->z : p < 4 ? &v->x : &v->y;
    *c = (p & 1 ? g : -g) * v->w;
}

/* Sutherland-Hodgman in homogeneous space. orig[i] tells whether the edge
 * from vertex i to i+1 is part of the original triangle (wireframe draws
 * only those). The intersection is always computed from the inside vertex
 * toward the outside one, so both triangles sharing an edge get the same
 * point. Returns the vertex count (0 when nothing is left). */
int mote__clip(const mote__ctx *cx, mote__cvert *poly, bool *orig, int n, unsigned planes)
{
    mote__cvert tmp[MOTE__MAX_POLY];
    bool torig[MOTE__MAX_POLY];
    for (int p = 0; p < MOTE__CLIP_PLANES && n > 0; p++) {
        if (!(planes & (1u << p)))
            continue;
        int m = 0;
        for (int i = 0; i < n; i++) {
            const mote__cvert *a = &poly[i], *b = &poly[(i + 1) % n];
            float da = mote__plane_dist(cx, a, p), db = mote__plane_dist(cx, b, p);
            bool ain = da >= 0.0f, bin = db >= 0.0f;
            /* float rounding can leave the polygon a hair from convex,
             * and a plane may then cut it more than twice: past
             * MOTE__MAX_POLY vertices, an input vertex is dropped too */
            if (ain && m < MOTE__MAX_POLY) {
                tmp[m] = *a;
                torig[m++] = orig[i];
            }
            if (ain != bin && m < MOTE__MAX_POLY) {
                if (ain)
                    mote__lerp(a, b, da / (da - db), &tmp[m]);
                else
                    mote__lerp(b, a, db / (db - da), &tmp[m]);
                mote__on_plane(cx, &tmp[m], p);
                torig[m++] = ain ? false : orig[i];
            }
        }
        n = m;
        memcpy(poly, tmp, (size_t)n * sizeof *poly);
        if (MOTE_ENABLE_LINES)    /* the edges' origins: only wireframe reads them */
            memcpy(orig, torig, (size_t)n * sizeof *orig);
    }
    return n;
}


/* Outcode bits: the clip planes a vertex is outside of (0..5), the sides of
 * the viewport proper it is outside of (8..11, for trivial rejection),
 * whether a vertex inside every clip plane failed to snap, and (alone)
 * whether it is invalid (state 2), so that one test of the three
 * vertices' outcodes finds an invalid one. */
unsigned mote__outcode(const mote__ctx *cx, const mote__cvert *v)
{
    float d[MOTE__CLIP_PLANES];
    mote__plane_dists(cx, v, d);
    unsigned c = 0;
    for (int p = 0; p < MOTE__CLIP_PLANES; p++)
        c |= (unsigned)(d[p] < 0.0f) << p;
    c |= (unsigned)(v->x > v->w) << 8;
    c |= (unsigned)(v->x < -v->w) << 9;
    c |= (unsigned)(v->y > v->w) << 10;
    c |= (unsigned)(v->y < -v->w) << 11;
    return c;
}

/* ---- snapping ------------------------------------------------------------ */

/* round_half_up(n * h + h) exactly, for a float n and an integer h: the
 * float is split into its 24-bit mantissa and exponent, so the product is
 * an exact 64-bit integer; no double arithmetic (costly without an FPU) and
 * the same answer on every target. False when |n * h| is out of range. */
bool mote__snap_axis(float n, int64_t h, int64_t lim, int32_t *out)
{
    union { float f; uint32_t u; } b;
    b.f = n;
    /* |n| = m * 2^-k with the 24-bit mantissa m; zero and denormals (exponent
     * field 0) give k = 150, far enough to round to 0 like any k >= 62 */
    int k = 150 - (int)((b.u >> 23) & 0xff);
    int64_t p = (int64_t)((b.u & 0x7fffffu) | 0x800000u) * h;  /* < 2^24 * 2^20 */
    int64_t neg = (int64_t)(b.u >> 31);
    int64_t v;                    /* round_half_up(n * h) */
    if (k > 0) {
        k = k < 62 ? k : 62;
        /* half up for n >= 0; for n < 0, -round_half_down(|n| h), hence the -1 */
        int64_t m = (p + ((int64_t)1 << (k - 1)) - neg) >> k;
        v = neg ? -m : m;
    } else {
        if (k < -16)
            return false;         /* |n| >= 2^40: far outside the guard band */
        v = neg ? -(p << -k) : p << -k;
    }
    v += h;
    if (v <= -lim || v >= lim)
        return false;
    *out = (int32_t)v;
    return true;
}

/* The snapped position of normalised device coordinates nx = x / w and
 * ny = -(y / w) */
bool mote__snap_ndc(const mote__ctx *cx, float nx, float ny, int32_t *X, int32_t *Y)
{
    const mote_device *dev = cx->dev;
    int F = dev->desc.subpixel_bits;
    int64_t hw = (int64_t)dev->desc.width << (F - 1), hh = (int64_t)dev->desc.height << (F - 1);
    /* the guard band bounds these; the limit only catches float rounding */
    int64_t lim = (int64_t)1 << (MOTE_GUARD_BITS + 1 + F);
    return mote__snap_axis(nx, hw, lim, X) && mote__snap_axis(ny, hh, lim, Y);
}

bool mote__snap(const mote__ctx *cx, const mote__cvert *v, int32_t *X, int32_t *Y)
{
    return v->w > 0.0f && mote__snap_ndc(cx, v->x / v->w, -(v->y / v->w), X, Y);
}
