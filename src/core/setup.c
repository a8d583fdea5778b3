/*
 * setup.c - from three snapped vertices to a mote__tri: bounding box, edge
 * functions and the attribute planes the span loops step through.
 *
 * Interpolation uses perspective-correct barycentrics built from the exact
 * integer edge functions E_i (value at a pixel centre, sub-pixel^2 units):
 *     P1 = E1 q1,  P2 = E2 q2,  Q = E0 q0 + E1 q1 + E2 q2,  qi ~ 1/wi
 * so that b1 = P1/Q and b2 = P2/Q are Vulkan's perspective weights. All three
 * are linear in x and y with integer coefficients: stepping is exact.
 * Overflow: snapped coordinates are within +-2^(GUARD+1+8) = 2^22, so an
 * edge function over the bounding box is below 2^46; qbits is chosen per
 * triangle so that |Q| < 2^62. Depth is linear in screen space; its plane is
 * computed in double (53 bits) and stepped as 24.16 fixed point.
 */
#include "internal.h"

static int mote__bitlen(uint64_t v)
{
    int n = 0;
    while (v) {
        n++;
        v >>= 1;
    }
    return n;
}

static int64_t mote__abs64(int64_t v) { return v < 0 ? -v : v; }

static int64_t mote__round_d(double d)
{
    return (int64_t)(d >= 0.0 ? d + 0.5 : d - 0.5);
}

/* floor(a / 2^s) for signed a */
static int32_t mote__floor_shift(int32_t a, int s)
{
    return a >= 0 ? a >> s : -(int32_t)((-(int64_t)a + (1 << s) - 1) >> s);
}

/* A shade in [0,1] as 2^24 fixed point; clipping's lerp may overshoot by an ulp. */
static int32_t mote__shade_fixed(float s)
{
    int32_t v = (int32_t)(s * (float)MOTE__SHADE_ONE + 0.5f);
    return v < 0 ? 0 : v > MOTE__SHADE_ONE ? MOTE__SHADE_ONE : v;
}

bool mote__setup(mote__tri *t, const mote__raster_state *rs, const int32_t X[3],
                 const int32_t Y[3], const mote__cvert *v[3], int F,
                 int width, int height)
{
    const int64_t one = (int64_t)1 << F, half = one >> 1;
    int64_t area2 = (int64_t)(X[1] - X[0]) * (Y[2] - Y[0]) - (int64_t)(Y[1] - Y[0]) * (X[2] - X[0]);
    if (area2 == 0)
        return false;

    /* Pixel bounding box: pixels whose centre can be inside. */
    int32_t minx = MOTE__MIN(X[0], MOTE__MIN(X[1], X[2])), maxx = MOTE__MAX(X[0], MOTE__MAX(X[1], X[2]));
    int32_t miny = MOTE__MIN(Y[0], MOTE__MIN(Y[1], Y[2])), maxy = MOTE__MAX(Y[0], MOTE__MAX(Y[1], Y[2]));
    int x0 = mote__floor_shift(minx - (int32_t)half, F), x1 = mote__floor_shift(maxx - (int32_t)half, F) + 1;
    int y0 = mote__floor_shift(miny - (int32_t)half, F), y1 = mote__floor_shift(maxy - (int32_t)half, F) + 1;
    x0 = MOTE__MAX(x0, 0);
    y0 = MOTE__MAX(y0, 0);
    x1 = MOTE__MIN(x1, width - 1);
    y1 = MOTE__MIN(y1, height - 1);
    if (x0 > x1 || y0 > y1)
        return false;
    t->rs = rs;
    for (int i = 0; i < 3; i++) {
        t->X[i] = X[i];
        t->Y[i] = Y[i];
    }
    t->xmin = (int16_t)x0;
    t->xmax = (int16_t)x1;
    t->ymin = (int16_t)y0;
    t->ymax = (int16_t)y1;
    t->ox = (int16_t)x0;
    t->oy = (int16_t)y0;

    /* Edge function of vertex i (zero on the opposite edge, 2*area at vertex
     * i), at the origin pixel centre, and its steps per pixel. */
    const int64_t sign = area2 > 0 ? 1 : -1;
    const int64_t cx = (int64_t)x0 * one + half, cy = (int64_t)y0 * one + half;
    int64_t e[3], edx[3], edy[3], emax = 0;
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        int64_t ax = X[k] - X[j], ay = Y[k] - Y[j];
        e[i] = sign * (ax * (cy - Y[j]) - ay * (cx - X[j]));
        edx[i] = -sign * ay * one;
        edy[i] = sign * ax * one;
        /* largest |E| over the box: at one of its corners (E is linear) */
        int64_t w = (int64_t)(x1 - x0), h = (int64_t)(y1 - y0);
        int64_t c0 = e[i], c1 = e[i] + edx[i] * w, c2 = e[i] + edy[i] * h, c3 = c1 + edy[i] * h;
        emax = MOTE__MAX(emax, MOTE__MAX(MOTE__MAX(mote__abs64(c0), mote__abs64(c1)),
                                         MOTE__MAX(mote__abs64(c2), mote__abs64(c3))));
    }
    int64_t a2 = area2 * sign;

    bool needs_weights = rs->gouraud || rs->tex != MOTE__TEX_NONE;
    if (needs_weights) {
        /* qi = 2^qbits * wmin / wi, or 1 for affine interpolation */
        int qbits = 61 - 2 - mote__bitlen((uint64_t)MOTE__MAX(emax, a2));
        qbits = MOTE__MIN(qbits, 24);
        qbits = MOTE__MAX(qbits, 0);
        int64_t q[3];
        if (rs->persp == MOTE__PERSP_AFFINE) {
            q[0] = q[1] = q[2] = 1;
            qbits = 0;
        } else {
            float wmin = MOTE__MIN(v[0]->w, MOTE__MIN(v[1]->w, v[2]->w));
            for (int i = 0; i < 3; i++) {
                q[i] = mote__round_d((double)((int64_t)1 << qbits) * (double)wmin / (double)v[i]->w);
                if (q[i] < 1)
                    q[i] = 1;
            }
        }
        t->p1 = e[1] * q[1];
        t->p1dx = edx[1] * q[1];
        t->p1dy = edy[1] * q[1];
        t->p2 = e[2] * q[2];
        t->p2dx = edx[2] * q[2];
        t->p2dy = edy[2] * q[2];
        t->q = e[0] * q[0] + t->p1 + t->p2;
        t->qdx = edx[0] * q[0] + t->p1dx + t->p2dx;
        t->qdy = edy[0] * q[0] + t->p1dy + t->p2dy;
        int s = mote__bitlen((uint64_t)a2) + qbits - 30;
        t->shift = (int8_t)MOTE__MAX(s, 0);

        for (int c = 0; c < 3; c++) {
            int32_t s0 = mote__shade_fixed(v[0]->s[c]);
            int32_t s1 = mote__shade_fixed(v[1]->s[c]);
            int32_t s2 = mote__shade_fixed(v[2]->s[c]);
            t->s0[c] = s0;
            t->ds1[c] = s1 - s0;
            t->ds2[c] = s2 - s0;
        }
        if (rs->tex != MOTE__TEX_NONE) {
            /* texels in 16.16; whole periods removed so numbers stay small */
            double u[3], vv[3];
            double umin = 1e300, vmin = 1e300;
            for (int i = 0; i < 3; i++) {
                u[i] = (double)v[i]->u * 65536.0;
                vv[i] = (double)v[i]->v * 65536.0;
                if (u[i] < umin) umin = u[i];
                if (vv[i] < vmin) vmin = vv[i];
            }
            double pu = 0.0, pv = 0.0;
            if (rs->wrap_u == MOTE_WRAP_REPEAT || rs->wrap_u == MOTE_WRAP_MIRROR) {
                double period = 65536.0 * rs->tex_w * (rs->wrap_u == MOTE_WRAP_MIRROR ? 2 : 1);
                pu = period * (double)(int64_t)(umin / period - (umin < 0 ? 1 : 0));
            }
            if (rs->wrap_v == MOTE_WRAP_REPEAT || rs->wrap_v == MOTE_WRAP_MIRROR) {
                double period = 65536.0 * rs->tex_h * (rs->wrap_v == MOTE_WRAP_MIRROR ? 2 : 1);
                pv = period * (double)(int64_t)(vmin / period - (vmin < 0 ? 1 : 0));
            }
            int64_t U[3], V[3];
            for (int i = 0; i < 3; i++) {
                U[i] = mote__round_d(u[i] - pu);
                V[i] = mote__round_d(vv[i] - pv);
            }
            t->u0 = U[0];
            t->du1 = U[1] - U[0];
            t->du2 = U[2] - U[0];
            t->v0 = V[0];
            t->dv1 = V[1] - V[0];
            t->dv2 = V[2] - V[0];
        }
    } else {
        for (int c = 0; c < 3; c++) {
            t->s0[c] = mote__shade_fixed(v[0]->s[c]);
            t->ds1[c] = t->ds2[c] = 0;
        }
    }

    if (rs->depth_test || rs->depth_write) {
        double d[3];
        for (int i = 0; i < 3; i++) {
            double z = (double)v[i]->z / (double)v[i]->w;
            z = z < 0.0 ? 0.0 : z > 1.0 ? 1.0 : z;
            d[i] = (double)mote__round_d(z * (double)MOTE__DEPTH_MAX);
        }
        const double scale = (double)(1 << MOTE__DEPTH_FRAC) / (double)a2;
        double d1 = d[1] - d[0], d2 = d[2] - d[0];
        t->z = mote__round_d(d[0] * (1 << MOTE__DEPTH_FRAC) + ((double)e[1] * d1 + (double)e[2] * d2) * scale);
        t->zdx = mote__round_d(((double)edx[1] * d1 + (double)edx[2] * d2) * scale);
        t->zdy = mote__round_d(((double)edy[1] * d1 + (double)edy[2] * d2) * scale);
    }
    return true;
}
