/*
 * ref.c - the reference renderer (see ref.h). Clarity over speed: every
 * pixel of a triangle's bounding box is tested on its own with exact
 * integer edge functions, and every value is a double until the final
 * rounding to 8 bits that CONVENTIONS prescribe.
 */
#include "ref/ref.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- exact coverage ------------------------------------------------------ */

/* Edge function of the directed edge a -> b at p: positive on its left in
 * y-down screen space once the triangle is ordered so that its area is
 * positive (see orient()). */
static int64_t edge_fn(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py)
{
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/* D3D11 §3.4.2.1, derived for E = dx (py - ay) - dy (px - ax) > 0 inside:
 * the interior lies along E's gradient (-dy, dx). A top edge is exactly
 * horizontal with the interior below (dy == 0, dx > 0); a left edge has the
 * interior to its right (-dy > 0). Samples exactly on those are inside. */
static bool top_left(int64_t dx, int64_t dy)
{
    return dy < 0 || (dy == 0 && dx > 0);
}

/* Orders the vertices so that the area (and each edge function inside) is
 * positive; returns the doubled area, 0 for a degenerate triangle. perm
 * receives the original index of each ordered vertex. */
static int64_t orient(const int32_t X[3], const int32_t Y[3], int64_t x[3], int64_t y[3], int perm[3])
{
    for (int i = 0; i < 3; i++) {
        x[i] = X[i];
        y[i] = Y[i];
        perm[i] = i;
    }
    int64_t area = edge_fn(x[0], y[0], x[1], y[1], x[2], y[2]);
    if (area < 0) {
        int64_t tx = x[1], ty = y[1];
        x[1] = x[2];
        y[1] = y[2];
        x[2] = tx;
        y[2] = ty;
        perm[1] = 2;
        perm[2] = 1;
        area = -area;
    }
    return area;
}

/* The three edge functions at a sample; e[i] is the edge opposite vertex i,
 * so e[i] / area is vertex i's barycentric weight. */
static bool sample_inside(const int64_t x[3], const int64_t y[3], int64_t px, int64_t py, int64_t e[3])
{
    for (int i = 0; i < 3; i++) {
        int a = (i + 1) % 3, b = (i + 2) % 3;
        e[i] = edge_fn(x[a], y[a], x[b], y[b], px, py);
        if (e[i] < 0 || (e[i] == 0 && !top_left(x[b] - x[a], y[b] - y[a])))
            return false;
    }
    return true;
}

bool ref_inside(const int32_t X[3], const int32_t Y[3], int F, int px, int py)
{
    int64_t x[3], y[3], e[3];
    int perm[3];
    if (orient(X, Y, x, y, perm) == 0)
        return false;
    int64_t one = (int64_t)1 << F;
    return sample_inside(x, y, px * one + one / 2, py * one + one / 2, e);
}

/* Pixel range whose centres can lie in [lo, hi] (fixed point), clamped to [0, n). */
static void centre_range(int64_t lo, int64_t hi, int F, int n, int *first, int *last)
{
    int64_t one = (int64_t)1 << F, half = one / 2;
    /* centre c = p * one + half >= lo  <=>  p >= ceil((lo - half) / one) */
    int64_t a = lo - half, b = hi - half;
    int64_t p0 = a >= 0 ? (a + one - 1) / one : -((-a) / one);
    int64_t p1 = b >= 0 ? b / one : -((-b + one - 1) / one);
    if (p0 < 0)
        p0 = 0;
    if (p1 > n - 1)
        p1 = n - 1;
    *first = (int)p0;
    *last = (int)p1;
}

/* Calls fn for every covered pixel of the viewport with the edge values. */
typedef void (*cover_fn)(void *user, int px, int py, const int64_t e[3], int64_t area,
                         const int perm[3]);

static long cover_each(const int32_t X[3], const int32_t Y[3], int F, int width, int height,
                       cover_fn fn, void *user)
{
    int64_t x[3], y[3], e[3];
    int perm[3];
    int64_t area = orient(X, Y, x, y, perm);
    if (area == 0)
        return 0;
    int64_t minx = x[0], maxx = x[0], miny = y[0], maxy = y[0];
    for (int i = 1; i < 3; i++) {
        minx = x[i] < minx ? x[i] : minx;
        maxx = x[i] > maxx ? x[i] : maxx;
        miny = y[i] < miny ? y[i] : miny;
        maxy = y[i] > maxy ? y[i] : maxy;
    }
    int px0, px1, py0, py1;
    centre_range(minx, maxx, F, width, &px0, &px1);
    centre_range(miny, maxy, F, height, &py0, &py1);
    int64_t one = (int64_t)1 << F;
    long n = 0;
    for (int py = py0; py <= py1; py++)
        for (int px = px0; px <= px1; px++)
            if (sample_inside(x, y, px * one + one / 2, py * one + one / 2, e)) {
                fn(user, px, py, e, area, perm);
                n++;
            }
    return n;
}

typedef struct count_ctx {
    uint8_t *count;
    int width;
} count_ctx;

static void count_pixel(void *user, int px, int py, const int64_t e[3], int64_t area, const int perm[3])
{
    count_ctx *c = (count_ctx *)user;
    (void)e;
    (void)area;
    (void)perm;
    uint8_t *p = &c->count[(size_t)py * (size_t)c->width + (size_t)px];
    if (*p < 255)
        (*p)++;
}

long ref_cover(const int32_t X[3], const int32_t Y[3], int F, int width, int height, uint8_t *count)
{
    count_ctx c = {count, width};
    return cover_each(X, Y, F, width, height, count_pixel, &c);
}

/* ---- target ---------------------------------------------------------------- */

bool ref_target_init(ref_target *t, int width, int height, int subpixel_bits)
{
    memset(t, 0, sizeof *t);
    if (width < 1 || height < 1)
        return false;
    size_t n = (size_t)width * (size_t)height;
    t->width = width;
    t->height = height;
    t->subpixel_bits = subpixel_bits ? subpixel_bits : 8;
    t->rgba = (uint8_t *)calloc(n, 4);
    t->cov = (uint8_t *)calloc(n, 1);
    t->depth = (double *)malloc(n * sizeof(double));
    if (!t->rgba || !t->cov || !t->depth) {
        ref_target_free(t);
        return false;
    }
    mote_rgba black = {0, 0, 0, 255};
    ref_clear(t, black, 1.0);
    return true;
}

void ref_target_free(ref_target *t)
{
    free(t->rgba);
    free(t->cov);
    free(t->depth);
    memset(t, 0, sizeof *t);
}

void ref_clear(ref_target *t, mote_rgba color, double depth)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++) {
        t->rgba[4 * i + 0] = color.r;
        t->rgba[4 * i + 1] = color.g;
        t->rgba[4 * i + 2] = color.b;
        t->rgba[4 * i + 3] = color.a;
        t->depth[i] = depth;
    }
    memset(t->cov, 0, n);
}

/* ---- texturing ------------------------------------------------------------- */

static int64_t wrap_index(int64_t i, int64_t n, mote_wrap mode)
{
    switch (mode) {
    case MOTE_WRAP_CLAMP:
        return i < 0 ? 0 : i >= n ? n - 1 : i;
    case MOTE_WRAP_MIRROR: {
        int64_t m = ((i % (2 * n)) + 2 * n) % (2 * n);
        return m < n ? m : 2 * n - 1 - m;
    }
    default:
        return ((i % n) + n) % n;
    }
}

static void texel(const mote_texture *tex, int64_t x, int64_t y, double out[3])
{
    int bpp = mote_format_bytes(tex->format);
    size_t stride = tex->stride ? (size_t)tex->stride : (size_t)tex->width * (size_t)bpp;
    const uint8_t *p = (const uint8_t *)tex->pixels + (size_t)y * stride + (size_t)x * (size_t)bpp;
    if (tex->format == MOTE_FORMAT_RGB565) {
        uint16_t v;
        memcpy(&v, p, 2);
        /* 5 and 6 bits to 8, to nearest */
        out[0] = floor((double)(v >> 11) * 255.0 / 31.0 + 0.5);
        out[1] = floor((double)((v >> 5) & 63) * 255.0 / 63.0 + 0.5);
        out[2] = floor((double)(v & 31) * 255.0 / 31.0 + 0.5);
    } else if (tex->format == MOTE_FORMAT_GREY8) {
        out[0] = out[1] = out[2] = p[0];
    } else {
        out[0] = p[0];
        out[1] = p[1];
        out[2] = p[2];
    }
}

void ref_sample(const mote_texture *tex, mote_wrap wu, mote_wrap wv, bool bilinear, double u,
                double v, double out[3])
{
    int64_t w = tex->width, h = tex->height;
    if (!bilinear) {
        /* texel i covers [i, i + 1) */
        texel(tex, wrap_index((int64_t)floor(u), w, wu), wrap_index((int64_t)floor(v), h, wv), out);
        return;
    }
    /* the four texels around (u - 1/2, v - 1/2), weighted exactly */
    double uu = u - 0.5, vv = v - 0.5;
    double fu0 = floor(uu), fv0 = floor(vv);
    double fu = uu - fu0, fv = vv - fv0;
    int64_t i0 = (int64_t)fu0, j0 = (int64_t)fv0;
    double a[3], b[3], c[3], d[3];
    texel(tex, wrap_index(i0, w, wu), wrap_index(j0, h, wv), a);
    texel(tex, wrap_index(i0 + 1, w, wu), wrap_index(j0, h, wv), b);
    texel(tex, wrap_index(i0, w, wu), wrap_index(j0 + 1, h, wv), c);
    texel(tex, wrap_index(i0 + 1, w, wu), wrap_index(j0 + 1, h, wv), d);
    for (int k = 0; k < 3; k++)
        out[k] = (a[k] * (1 - fu) + b[k] * fu) * (1 - fv) + (c[k] * (1 - fu) + d[k] * fu) * fv;
}

static double texel_alpha(const mote_texture *tex, int64_t x, int64_t y)
{
    if (tex->format != MOTE_FORMAT_RGBA8888)
        return 255.0;
    size_t stride = tex->stride ? (size_t)tex->stride : (size_t)tex->width * 4;
    return ((const uint8_t *)tex->pixels)[(size_t)y * stride + (size_t)x * 4 + 3];
}

double ref_sample_alpha(const mote_texture *tex, mote_wrap wu, mote_wrap wv, bool bilinear, double u,
                        double v)
{
    int64_t w = tex->width, h = tex->height;
    if (!bilinear)
        return texel_alpha(tex, wrap_index((int64_t)floor(u), w, wu), wrap_index((int64_t)floor(v), h, wv));
    double uu = u - 0.5, vv = v - 0.5;
    double fu0 = floor(uu), fv0 = floor(vv);
    double fu = uu - fu0, fv = vv - fv0;
    int64_t i0 = (int64_t)fu0, j0 = (int64_t)fv0;
    int64_t a = wrap_index(i0, w, wu), b = wrap_index(i0 + 1, w, wu);
    int64_t c = wrap_index(j0, h, wv), d = wrap_index(j0 + 1, h, wv);
    return (texel_alpha(tex, a, c) * (1 - fu) + texel_alpha(tex, b, c) * fu) * (1 - fv)
         + (texel_alpha(tex, a, d) * (1 - fu) + texel_alpha(tex, b, d) * fu) * fv;
}

/* ---- one triangle ------------------------------------------------------------ */

typedef struct shade_ctx {
    ref_target *t;
    const ref_shading *sh;
    const ref_vert *v;
    long written;
    /* mip selection: the triangle's level of detail, and the screen
     * derivatives (per pixel) of the linear barycentrics */
    double tri_lod, dlx[3], dly[3];
} shade_ctx;

static double clamp01(double x)
{
    return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0;
}

static void ref_layer_sample(const ref_shading *sh, const mote_layer *l, const double muv[2], double e[3],
                             double m[3], double *op)
{
    const mote_texture *tx = l->texture;
    double u = muv[0] * (l->u_scale != 0.0f ? l->u_scale : 1.0) + l->u_offset;
    double v = muv[1] * (l->v_scale != 0.0f ? l->v_scale : 1.0) + l->v_offset;
    if (sh->v_bottom)
        v = 1.0 - v;
    u *= tx->width;
    v *= tx->height;
    mote_wrap wu = l->wrap_u > MOTE_WRAP_DEFAULT && l->wrap_u < MOTE_WRAP_COUNT ? l->wrap_u : MOTE_WRAP_REPEAT;
    mote_wrap wv = l->wrap_v > MOTE_WRAP_DEFAULT && l->wrap_v < MOTE_WRAP_COUNT ? l->wrap_v : MOTE_WRAP_REPEAT;
    double rgb[3];
    ref_sample(tx, wu, wv, sh->bilinear, u, v, rgb);
    bool white = l->factor[0] == 0.0f && l->factor[1] == 0.0f && l->factor[2] == 0.0f;
    double f[3];
    for (int k = 0; k < 3; k++)
        f[k] = white ? 1.0 : fmin(64.0, fmax(0.0, l->factor[k]));
    if (l->role == MOTE_LAYER_EMISSIVE) {
        for (int k = 0; k < 3; k++)
            e[k] += rgb[k] / 255.0 * f[k];
    } else if (l->role == MOTE_LAYER_SPECULAR) {
        for (int k = 0; k < 3; k++)
            m[k] *= rgb[k] / 255.0 * f[k];
    } else {
        double a = l->from_rgb ? (54.0 * rgb[0] + 183.0 * rgb[1] + 19.0 * rgb[2]) / 256.0
                               : ref_sample_alpha(tx, wu, wv, sh->bilinear, u, v);
        *op *= fmin(255.0, a * f[0]) / 255.0;
    }
}

/* The level of detail of a pixel with perspective barycentrics b: log2
 * of the largest texel derivative, exactly (from the quotient rule on
 * sum(lam_i u_i / w_i) / sum(lam_i / w_i)); the triangle's for
 * MOTE_MIP_TRIANGLE. */
static double pixel_lod(const shade_ctx *c, const double b[3])
{
    if (c->sh->mip == MOTE_MIP_TRIANGLE)
        return c->tri_lod;
    double u = 0.0, v = 0.0, q = 0.0, rho = 0.0;
    for (int i = 0; i < 3; i++) {
        u += b[i] * c->v[i].u;
        v += b[i] * c->v[i].v;
    }
    double lw[3];
    for (int i = 0; i < 3; i++) {
        lw[i] = c->sh->affine ? 1.0 : 1.0 / c->v[i].w;
        q += b[i] / lw[i];          /* sum b_i w_i = 1 / sum(lam_i / w_i) */
    }
    for (int axis = 0; axis < 2; axis++) {
        const double *dl = axis ? c->dly : c->dlx;
        double nu = 0.0, nv = 0.0, nq = 0.0;
        for (int i = 0; i < 3; i++) {
            nu += dl[i] * lw[i] * c->v[i].u;
            nv += dl[i] * lw[i] * c->v[i].v;
            nq += dl[i] * lw[i];
        }
        if (c->sh->mip_step) {
            /* the next pixel's N / D less this one's: lam_i = b_i w_i q' */
            double n = 0.0, su = 0.0, sv = 0.0;
            for (int i = 0; i < 3; i++) {
                const double l = (b[i] / lw[i] / q + dl[i]) * lw[i];
                n += l;
                su += l * c->v[i].u;
                sv += l * c->v[i].v;
            }
            rho = fmax(rho, fmax(fabs(su / n - u), fabs(sv / n - v)));
            continue;
        }
        /* d(N / D) = (dN - (N / D) dD) / D, D = sum lam_i / w_i = 1 / q */
        rho = fmax(rho, fabs((nu - u * nq) * q));
        rho = fmax(rho, fabs((nv - v * nq) * q));
    }
    return rho > 0.0 ? log2(rho) : -HUGE_VAL;
}

/* The texel (and its alpha) at level-0 texel coordinates (u, v) of a
 * triangle with the mip chain sh->mips, at level of detail lod. */
static void mip_sample(const ref_shading *sh, double lod, double u, double v, double out[3], double *alpha)
{
    const int last = sh->mips->count - 1;
    int k0, k1 = -1;
    double f = 0.0;
    if (sh->mip == MOTE_MIP_TRILINEAR) {
        k0 = lod < 0.0 ? 0 : lod >= last ? last : (int)floor(lod);
        if (lod >= 0.0 && k0 < last) {
            k1 = k0 + 1;
            f = exp2(lod - k0) - 1.0;   /* the mantissa: log2's linear approximation */
        }
    } else {
        const double r = floor(lod + 0.5);
        k0 = r < 0.0 ? 0 : r > last ? last : (int)r;
    }
    const mote_texture *t0 = &sh->mips->level[k0];
    ref_sample(t0, sh->wrap_u, sh->wrap_v, sh->bilinear, ldexp(u, -k0), ldexp(v, -k0), out);
    if (alpha)
        *alpha = ref_sample_alpha(t0, sh->wrap_u, sh->wrap_v, sh->bilinear, ldexp(u, -k0), ldexp(v, -k0));
    if (k1 < 0)
        return;
    const mote_texture *t1 = &sh->mips->level[k1];
    double next[3];
    ref_sample(t1, sh->wrap_u, sh->wrap_v, sh->bilinear, ldexp(u, -k1), ldexp(v, -k1), next);
    for (int k = 0; k < 3; k++)
        out[k] = out[k] * (1.0 - f) + next[k] * f;
    if (alpha)
        *alpha = *alpha * (1.0 - f)
               + ref_sample_alpha(t1, sh->wrap_u, sh->wrap_v, sh->bilinear, ldexp(u, -k1), ldexp(v, -k1)) * f;
}

static void shade_pixel(void *user, int px, int py, const int64_t e[3], int64_t area, const int perm[3])
{
    shade_ctx *c = (shade_ctx *)user;
    ref_target *t = c->t;
    const ref_shading *sh = c->sh;
    /* screen-space barycentrics of the original vertices */
    double lam[3];
    for (int i = 0; i < 3; i++)
        lam[perm[i]] = (double)e[i] / (double)area;
    size_t idx = (size_t)py * (size_t)t->width + (size_t)px;
    /* relative to vertex 0, so that a constant depth stays exactly constant */
    double z = c->v[0].z + lam[1] * (c->v[1].z - c->v[0].z) + lam[2] * (c->v[2].z - c->v[0].z);
    if (sh->depth_test && !(z < t->depth[idx]))
        return;
    /* Vulkan: b_i = (lam_i / w_i) / sum(lam_j / w_j) */
    double b[3];
    if (sh->affine) {
        for (int i = 0; i < 3; i++)
            b[i] = lam[i];
    } else {
        double q = 0.0;
        for (int i = 0; i < 3; i++) {
            b[i] = lam[i] / c->v[i].w;
            q += b[i];
        }
        for (int i = 0; i < 3; i++)
            b[i] /= q;
    }
    double s[3];
    for (int k = 0; k < 3; k++) {
        if (c->v[0].s[k] == c->v[1].s[k] && c->v[0].s[k] == c->v[2].s[k])
            s[k] = c->v[0].s[k];  /* flat: exactly the triangle's shade */
        else
            s[k] = b[0] * c->v[0].s[k] + b[1] * c->v[1].s[k] + b[2] * c->v[2].s[k];
        s[k] = clamp01(s[k]);
    }
    /* texture layers: emissive shade, the highlights' scale, opacity */
    double lay_e[3] = {0, 0, 0}, lay_m[3] = {1, 1, 1}, op = 1.0;
    if (sh->layer_count) {
        double muv[2];
        for (int k = 0; k < 2; k++)
            muv[k] = b[0] * c->v[0].muv[k] + b[1] * c->v[1].muv[k] + b[2] * c->v[2].muv[k];
        for (int i = 0; i < sh->layer_count; i++)
            ref_layer_sample(sh, sh->layers[i], muv, lay_e, lay_m, &op);
        for (int k = 0; k < 3; k++)
            s[k] = fmin(1.0, s[k] + lay_e[k]);
    }
    uint8_t *out = &t->rgba[4 * idx];
    double src[3], ta = 255.0;
    if (sh->alpha_test && !sh->texture && ta * op < sh->cutoff * 255.0)
        return;
    if (sh->texture) {
        double u = b[0] * c->v[0].u + b[1] * c->v[1].u + b[2] * c->v[2].u;
        double v = b[0] * c->v[0].v + b[1] * c->v[1].v + b[2] * c->v[2].v;
        double tx[3];
        if (sh->mips) {
            const double lod = pixel_lod(c, b);
            mip_sample(sh, lod, u, v, tx, &ta);
            if (t->lod)
                t->lod[idx] = lod;
        } else {
            ref_sample(sh->texture, sh->wrap_u, sh->wrap_v, sh->bilinear, u, v, tx);
            if (sh->texel_alpha || sh->alpha_test)
                ta = ref_sample_alpha(sh->texture, sh->wrap_u, sh->wrap_v, sh->bilinear, u, v);
        }
        if (sh->alpha_test && ta * op < sh->cutoff * 255.0)
            return;
        for (int k = 0; k < 3; k++)
            src[k] = tx[k] * s[k];
    } else {
        for (int k = 0; k < 3; k++)
            src[k] = s[k] * 255.0;
    }
    for (int k = 0; k < 3; k++) {
        double a = b[0] * c->v[0].a[k] + b[1] * c->v[1].a[k] + b[2] * c->v[2].a[k];
        src[k] = fmin(255.0, src[k] + 255.0 * clamp01(a) * lay_m[k]);
    }
    if (sh->blend) {
        double a = sh->alpha * (sh->texel_alpha ? ta / 255.0 : 1.0) * op;
        for (int k = 0; k < 3; k++)
            src[k] = src[k] * a + out[k] * (1.0 - a);
    }
    for (int k = 0; k < 3; k++)
        out[k] = (uint8_t)floor(src[k] + 0.5);
    out[3] = 255;
    if (t->cov[idx] < 255)
        t->cov[idx]++;
    if (sh->depth_write)
        t->depth[idx] = z;
    c->written++;
}

long ref_triangle(ref_target *t, const ref_shading *sh, const int32_t X[3], const int32_t Y[3],
                  const ref_vert v[3])
{
    shade_ctx c = {t, sh, v, 0, 0.0, {0, 0, 0}, {0, 0, 0}};
    if (sh->mips) {
        /* in pixels; lam_1 = ((x - x0) dy2 - dx2 (y - y0)) / a2 and so on */
        double x[3], y[3];
        for (int i = 0; i < 3; i++) {
            x[i] = ldexp((double)X[i], -t->subpixel_bits);
            y[i] = ldexp((double)Y[i], -t->subpixel_bits);
        }
        const double a2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
        if (a2 == 0.0)
            return 0;
        c.dlx[1] = (y[2] - y[0]) / a2;
        c.dly[1] = -(x[2] - x[0]) / a2;
        c.dlx[2] = -(y[1] - y[0]) / a2;
        c.dly[2] = (x[1] - x[0]) / a2;
        c.dlx[0] = -c.dlx[1] - c.dlx[2];
        c.dly[0] = -c.dly[1] - c.dly[2];
        const double texels = fabs((v[1].u - v[0].u) * (v[2].v - v[0].v) - (v[2].u - v[0].u) * (v[1].v - v[0].v));
        c.tri_lod = texels > 0.0 ? 0.5 * log2(texels / fabs(a2)) : -HUGE_VAL;
    }
    cover_each(X, Y, t->subpixel_bits, t->width, t->height, shade_pixel, &c);
    return c.written;
}

/* ---- the pipeline in double ---------------------------------------------------- */

/* column-major: m[col * 4 + row] */
static void mat_mul(const double a[16], const double b[16], double out[16])
{
    double r[16];
    for (int c = 0; c < 4; c++)
        for (int rr = 0; rr < 4; rr++) {
            double s = 0.0;
            for (int k = 0; k < 4; k++)
                s += a[k * 4 + rr] * b[c * 4 + k];
            r[c * 4 + rr] = s;
        }
    memcpy(out, r, sizeof r);
}

static void mat_point(const double m[16], const double p[3], double out[4])
{
    for (int r = 0; r < 4; r++)
        out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
}

static void normalize3(double v[3])
{
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 0.0)
        for (int k = 0; k < 3; k++)
            v[k] /= len;
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

void ref_begin(ref_target *t, const mote_frame_desc *frame, mote_rgba clear_color)
{
    t->frame = *frame;
    if (t->frame.light_count < 0)
        t->frame.light_count = 0;
    if (t->frame.light_count > MOTE_MAX_LIGHTS)
        t->frame.light_count = MOTE_MAX_LIGHTS;
    const mote_camera *cam = &frame->camera;
    /* left-handed look-at: z toward the target, x = up x z, y = z x x */
    double up[3] = {cam->up[0], cam->up[1], cam->up[2]};
    if (up[0] == 0.0 && up[1] == 0.0 && up[2] == 0.0)
        up[1] = 1.0;
    double z[3], x[3], y[3];
    for (int k = 0; k < 3; k++)
        z[k] = (double)cam->target[k] - (double)cam->position[k];
    normalize3(z);
    cross3(up, z, x);
    if (x[0] == 0.0 && x[1] == 0.0 && x[2] == 0.0) {
        /* up along the view direction: mote picks another up the same way */
        double alt[3] = {0.0, 0.0, 1.0};
        if (z[2] > 0.9 || z[2] < -0.9) {
            alt[1] = 1.0;
            alt[2] = 0.0;
        }
        cross3(alt, z, x);
    }
    normalize3(x);
    cross3(z, x, y);
    double view[16] = {0};
    for (int i = 0; i < 3; i++) {
        view[i * 4 + 0] = x[i];
        view[i * 4 + 1] = y[i];
        view[i * 4 + 2] = z[i];
    }
    const float *e = cam->position;
    view[12] = -(x[0] * e[0] + x[1] * e[1] + x[2] * e[2]);
    view[13] = -(y[0] * e[0] + y[1] * e[1] + y[2] * e[2]);
    view[14] = -(z[0] * e[0] + z[1] * e[1] + z[2] * e[2]);
    view[15] = 1.0;
    /* mote's documented defaults */
    double n = cam->znear > 0.0f ? cam->znear : 0.1;
    double f = cam->zfar > 0.0f ? cam->zfar : 100.0;
    double aspect = (double)t->width / (double)t->height;
    double proj[16] = {0};
    if (cam->projection == MOTE_PROJECTION_ORTHOGRAPHIC) {
        /* OrthoOffCenterLH: the box's edges to -1..1, depth 0..1 from
         * near (as given, 0 or behind the camera too) to far */
        n = cam->znear;
        if (f <= n)
            f = n + 1.0;
        double l = -aspect, r = aspect, b = -1.0, top = 1.0;
        const float *o = cam->ortho;
        if (o[0] != o[1] && o[2] != o[3]) {
            l = o[0];
            r = o[1];
            b = o[2];
            top = o[3];
        }
        proj[0] = 2.0 / (r - l);
        proj[5] = 2.0 / (top - b);
        proj[10] = 1.0 / (f - n);
        proj[12] = (l + r) / (l - r);
        proj[13] = (b + top) / (b - top);
        proj[14] = -n / (f - n);
        proj[15] = 1.0;
    } else {
        /* PerspectiveFovLH, with mote's fov cap */
        double fov = cam->fov > 0.0f ? cam->fov : 0.8;
        if (fov > 3.1)
            fov = 3.1;
        if (f <= n)
            f = n * 2.0;
        double ys = 1.0 / tan(fov * 0.5);
        proj[0] = ys / aspect;
        proj[5] = ys;
        proj[10] = f / (f - n);
        proj[11] = 1.0;
        proj[14] = -n * f / (f - n);
    }
    mat_mul(proj, view, t->view_proj);
    bool keep_c = frame->keep_color, keep_d = frame->keep_depth;
    size_t count = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < count; i++) {
        if (!keep_c) {
            t->rgba[4 * i + 0] = clear_color.r;
            t->rgba[4 * i + 1] = clear_color.g;
            t->rgba[4 * i + 2] = clear_color.b;
            t->rgba[4 * i + 3] = clear_color.a;
            t->cov[i] = 0;
        }
        if (!keep_d)
            t->depth[i] = 1.0;
    }
    t->triangles_drawn = t->triangles_culled = t->triangles_degenerate = t->triangles_invalid = 0;
}

typedef struct cvert {
    double p[4];                  /* clip x, y, z, w */
    double s[3], u, v;
    double a[3];                  /* additive colour (highlights, fog) */
    double muv[2];                /* the mesh's uv (texture layers) */
} cvert;

typedef struct draw_ctx {
    ref_target *t;
    const mote_mesh *mesh;
    double world[16], mvp[16], nrm[9];
    double color[3], emissive[3];
    bool lit, flat, textured;
    bool smooth;                  /* Gouraud or textured: highlights and fog */
    mote_draw_desc d;
    ref_shading sh;
    double gx, gy;                /* guard band in NDC units */
} draw_ctx;

static bool finite3(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return false;
    return true;
}

/* Babylon.js's default falloff (StandardMaterial's computeLighting and
 * computeSpotLighting): max(0, 1 - distance / range) for a point or spot
 * light with a range; a spot light's max(0, cos(angle to the axis)), 0
 * outside the cone (cos below cos(angle / 2)), else to the power exponent.
 * L runs from the surface point to the light, len = |L|. */
static double falloff(const mote_light *l, const double L[3], double len)
{
    double att = 1.0;
    if (l->type != MOTE_LIGHT_POINT && l->type != MOTE_LIGHT_SPOT)
        return att;
    if (l->range > 0.0f)
        att = fmax(0.0, 1.0 - len / l->range);
    if (l->type == MOTE_LIGHT_SPOT) {
        const double *d = (const double[3]){l->direction[0], l->direction[1], l->direction[2]};
        double dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        double c = fmax(0.0, -(d[0] * L[0] + d[1] * L[1] + d[2] * L[2]) / (dl * len));
        if (!(c >= cos(0.5 * l->spot_angle)))
            return 0.0;
        att *= l->spot_exponent > 0.0f ? pow(c, l->spot_exponent) : 1.0;
    }
    return att;
}

static void light(const draw_ctx *c, const double p[3], const double nrm[3], double out[3])
{
    const mote_frame_desc *f = &c->t->frame;
    double acc[3] = {f->ambient[0], f->ambient[1], f->ambient[2]};
    for (int i = 0; i < f->light_count; i++) {
        const mote_light *l = &f->lights[i];
        if (c->d.lights_off >> i & 1)
            continue;
        double col[3] = {l->color[0], l->color[1], l->color[2]};
        if (col[0] == 0.0 && col[1] == 0.0 && col[2] == 0.0)
            col[0] = col[1] = col[2] = 1.0;
        double k = l->intensity != 0.0f ? l->intensity : 1.0;
        double L[3];
        if (l->type == MOTE_LIGHT_POINT || l->type == MOTE_LIGHT_SPOT) {
            for (int j = 0; j < 3; j++)
                L[j] = (double)l->position[j] - p[j];
        } else if (l->type == MOTE_LIGHT_DIRECTIONAL) {
            for (int j = 0; j < 3; j++)
                L[j] = -(double)l->direction[j];
        } else if (l->type == MOTE_LIGHT_HEMISPHERIC) {
            for (int j = 0; j < 3; j++)
                L[j] = l->direction[j];
        } else {
            continue;
        }
        double len = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
        double ndl = len > 0.0 ? (nrm[0] * L[0] + nrm[1] * L[1] + nrm[2] * L[2]) / len : 0.0;
        if (l->type == MOTE_LIGHT_HEMISPHERIC) {
            double w = 0.5 + 0.5 * ndl;
            for (int j = 0; j < 3; j++)
                acc[j] += k * (col[j] * w + (double)l->ground_color[j] * (1.0 - w));
        } else if (ndl > 0.0) {
            double att = falloff(l, L, len);
            for (int j = 0; j < 3; j++)
                acc[j] += k * col[j] * ndl * att;
        }
    }
    /* lights x material colour + emissive, clamped (mote.h, Lighting) */
    for (int j = 0; j < 3; j++) {
        double v = acc[j] * c->color[j] + c->emissive[j];
        out[j] = clamp01(isnan(v) ? 0.0 : v);
    }
}

/* Blinn-Phong highlights at world position p with unit normal nrm, as
 * mote.h states them (mote_material.specular), in double. */
static void specular(const draw_ctx *c, const double p[3], const double nrm[3], double out[3])
{
    const mote_frame_desc *f = &c->t->frame;
    const mote_material *m = &c->mesh->material;
    double power = m->specular_power != 0.0f ? m->specular_power : 64.0;
    double V[3];
    for (int j = 0; j < 3; j++) {
        V[j] = (double)f->camera.position[j] - p[j];
        out[j] = 0.0;
    }
    normalize3(V);
    for (int i = 0; i < f->light_count; i++) {
        const mote_light *l = &f->lights[i];
        if (c->d.lights_off >> i & 1)
            continue;
        double L[3];
        for (int j = 0; j < 3; j++)
            L[j] = l->type == MOTE_LIGHT_POINT || l->type == MOTE_LIGHT_SPOT ? (double)l->position[j] - p[j]
                 : l->type == MOTE_LIGHT_DIRECTIONAL                         ? -(double)l->direction[j]
                                                                             : (double)l->direction[j];
        if (l->type == MOTE_LIGHT_NONE || l->type >= MOTE_LIGHT_TYPE_COUNT)
            continue;
        double len = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]), H[3];
        for (int j = 0; j < 3; j++)
            H[j] = L[j] / len + V[j];
        normalize3(H);
        double h = nrm[0] * H[0] + nrm[1] * H[1] + nrm[2] * H[2];
        if (!(h > 0.0))
            continue;
        double k = (l->intensity != 0.0f ? l->intensity : 1.0) * pow(h, power > 1.0 ? power : 1.0)
                 * falloff(l, L, len);
        bool white = l->specular[0] == 0.0f && l->specular[1] == 0.0f && l->specular[2] == 0.0f;
        for (int j = 0; j < 3; j++)
            out[j] += k * (white ? 1.0 : l->specular[j]) * (&m->specular.r)[j] / 255.0;
    }
}

/* The fog factor at world position p (mote_fog), in double. */
static double fog_factor(const draw_ctx *c, const double p[3])
{
    const mote_frame_desc *f = &c->t->frame;
    double d = 0.0;
    for (int j = 0; j < 3; j++)
        d += (p[j] - f->camera.position[j]) * (p[j] - f->camera.position[j]);
    d = sqrt(d);
    const mote_fog *fog = &f->fog;
    double x = d * fog->density, v = 1.0;
    if (fog->mode == MOTE_FOG_LINEAR)
        v = (fog->end - d) / (fog->end - fog->start);
    else if (fog->mode == MOTE_FOG_EXP)
        v = exp(-x);
    else if (fog->mode == MOTE_FOG_EXP2)
        v = exp(-x * x);
    return clamp01(v);
}

/* s x the mean colour of the n vertices listed (mote.h, mote_mesh.colors) */
static void tint(const draw_ctx *c, const uint32_t *index, int n, double s[3])
{
    for (int k = 0; k < 3; k++) {
        double sum = 0.0;
        for (int i = 0; i < n; i++)
            sum += (&c->mesh->colors[index[i]].r)[k];
        s[k] *= sum / (255.0 * n);
    }
}

/* A vertex through the vertex stage; false when it is not finite. */
static bool vertex(const draw_ctx *c, uint32_t index, cvert *out, double wpos[3], double wnrm[3])
{
    const mote_vertex *in = &c->mesh->vertices[index];
    double p[3] = {in->position[0], in->position[1], in->position[2]};
    mat_point(c->mvp, p, out->p);
    double w4[4];
    mat_point(c->world, p, w4);
    memcpy(wpos, w4, 3 * sizeof(double));
    for (int k = 0; k < 3; k++)
        wnrm[k] = c->nrm[k * 3 + 0] * in->normal[0] + c->nrm[k * 3 + 1] * in->normal[1]
                + c->nrm[k * 3 + 2] * in->normal[2];
    normalize3(wnrm);
    if (!finite3(out->p, 4))
        return false;
    if (c->lit && !c->flat)
        light(c, wpos, wnrm, out->s);
    else
        memcpy(out->s, c->color, sizeof out->s);
    if (c->mesh->colors && !c->flat)
        tint(c, &index, 1, out->s);
    out->a[0] = out->a[1] = out->a[2] = 0.0;
    if (c->smooth && c->lit && MOTE_ENABLE_SPECULAR) {
        const mote_rgba sp = c->mesh->material.specular;
        if (sp.r | sp.g | sp.b)
            specular(c, wpos, wnrm, out->a);
    }
    const mote_fog_mode fm = c->t->frame.fog.mode;
    if (c->smooth && MOTE_ENABLE_FOG && fm > MOTE_FOG_NONE && fm < MOTE_FOG_COUNT && !c->d.no_fog) {
        double f = fog_factor(c, wpos);
        for (int k = 0; k < 3; k++) {
            out->s[k] *= f;
            out->a[k] = out->a[k] * f + c->t->frame.fog.color[k] * (1.0 - f);
        }
    }
    for (int k = 0; k < 3; k++)
        out->a[k] = clamp01(out->a[k]);
    out->u = out->v = 0.0;
    out->muv[0] = in->uv[0];
    out->muv[1] = in->uv[1];
    if (c->textured) {
        const mote_material *m = &c->mesh->material;
        double u = (double)in->uv[0] * (m->u_scale != 0.0f ? m->u_scale : 1.0) + m->u_offset;
        double v = (double)in->uv[1] * (m->v_scale != 0.0f ? m->v_scale : 1.0) + m->v_offset;
        if (m->v_origin_bottom)
            v = 1.0 - v;
        out->u = u * m->texture->width;
        out->v = v * m->texture->height;
        if (!isfinite(out->u) || !isfinite(out->v))
            return false;
    }
    return true;
}

static double plane_dist(const draw_ctx *c, const cvert *v, int plane)
{
    const double *p = v->p;
    switch (plane) {
    case 0: return p[2];                 /* near: z >= 0 */
    case 1: return p[3] - p[2];          /* far: z <= w */
    case 2: return p[0] + c->gx * p[3];  /* guard band */
    case 3: return c->gx * p[3] - p[0];
    case 4: return p[1] + c->gy * p[3];
    default: return c->gy * p[3] - p[1];
    }
}

static void lerp(const cvert *a, const cvert *b, double s, cvert *out)
{
    for (int k = 0; k < 4; k++)
        out->p[k] = a->p[k] + (b->p[k] - a->p[k]) * s;
    for (int k = 0; k < 3; k++) {
        out->s[k] = a->s[k] + (b->s[k] - a->s[k]) * s;
        out->a[k] = a->a[k] + (b->a[k] - a->a[k]) * s;
    }
    out->u = a->u + (b->u - a->u) * s;
    out->v = a->v + (b->v - a->v) * s;
    for (int k = 0; k < 2; k++)
        out->muv[k] = a->muv[k] + (b->muv[k] - a->muv[k]) * s;
}

#define MAXPOLY 12

/* Sutherland-Hodgman against the six planes, in homogeneous space. */
static int clip_poly(const draw_ctx *c, cvert *poly, int n)
{
    cvert tmp[MAXPOLY];
    for (int plane = 0; plane < 6 && n > 0; plane++) {
        int m = 0;
        for (int i = 0; i < n; i++) {
            const cvert *a = &poly[i], *b = &poly[(i + 1) % n];
            double da = plane_dist(c, a, plane), db = plane_dist(c, b, plane);
            if (da >= 0.0)
                tmp[m++] = *a;
            /* from the inside vertex: t is then small and the point accurate
             * even when the outside vertex is 1e20 away */
            if (da >= 0.0 && db < 0.0)
                lerp(a, b, da / (da - db), &tmp[m++]);
            else if (da < 0.0 && db >= 0.0)
                lerp(b, a, db / (db - da), &tmp[m++]);
        }
        n = m;
        memcpy(poly, tmp, (size_t)n * sizeof *poly);
    }
    return n;
}

static void snap(const ref_target *t, const cvert *v, int32_t *X, int32_t *Y)
{
    double one = (double)(1 << t->subpixel_bits);
    double sx = (v->p[0] / v->p[3] + 1.0) * 0.5 * t->width * one;
    double sy = (1.0 - v->p[1] / v->p[3]) * 0.5 * t->height * one;
    *X = (int32_t)floor(sx + 0.5);   /* nearest, halves up */
    *Y = (int32_t)floor(sy + 0.5);
}

static void to_ref_vert(const cvert *c, ref_vert *r)
{
    double z = c->p[2] / c->p[3];
    r->z = z < 0.0 ? 0.0 : z > 1.0 ? 1.0 : z;
    r->w = c->p[3];
    memcpy(r->s, c->s, sizeof r->s);
    memcpy(r->a, c->a, sizeof r->a);
    r->u = c->u;
    r->v = c->v;
    memcpy(r->muv, c->muv, sizeof r->muv);
}

static void flat_shade(const draw_ctx *c, const uint32_t index[3], double wp[3][3], double wn[3][3],
                       double out[3])
{
    if (!c->lit) {                /* flat and unlit: only for vertex colours */
        memcpy(out, c->color, 3 * sizeof *out);
        tint(c, index, 3, out);
        return;
    }
    double e1[3], e2[3], n[3], ctr[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = wp[1][k] - wp[0][k];
        e2[k] = wp[2][k] - wp[0][k];
        ctr[k] = (wp[0][k] + wp[1][k] + wp[2][k]) / 3.0;
    }
    cross3(e1, e2, n);
    /* the geometric normal, on the side the vertex normals call outside */
    double vn = 0.0;
    for (int k = 0; k < 3; k++)
        vn += n[k] * (wn[0][k] + wn[1][k] + wn[2][k]);
    if (vn < 0.0)
        for (int k = 0; k < 3; k++)
            n[k] = -n[k];
    normalize3(n);
    light(c, ctr, n, out);
    if (c->mesh->colors)
        tint(c, index, 3, out);
}

static bool texture_ok(const mote_texture *t)
{
    return t && t->pixels && t->width > 0 && t->height > 0 && t->width <= 65536 && t->height <= 65536
        && (t->format == MOTE_FORMAT_RGBA8888 || t->format == MOTE_FORMAT_RGB565
            || t->format == MOTE_FORMAT_GREY8);
}

/* The material's layers that draw (mote.h, mote_layer). */
static void select_layers(draw_ctx *c, const mote_material *mat, mote_mode mode)
{
    c->sh.layer_count = 0;
    c->sh.v_bottom = mat->v_origin_bottom;
    if (mode != MOTE_MODE_TEXTURED || !mat->layers)
        return;
    const mote_rgba sp = mat->specular;
    const bool spec = c->smooth && c->lit && MOTE_ENABLE_SPECULAR && (sp.r | sp.g | sp.b);
    const mote_fog_mode fm = c->t->frame.fog.mode;
    const bool fog = c->smooth && MOTE_ENABLE_FOG && fm > MOTE_FOG_NONE && fm < MOTE_FOG_COUNT && !c->d.no_fog;
    for (int i = 0; i < mat->layer_count && i < MOTE_MAX_LAYERS; i++) {
        const mote_layer *l = &mat->layers[i];
        bool built = (l->role == MOTE_LAYER_EMISSIVE && MOTE_ENABLE_EMISSIVE_MAP)
                  || (l->role == MOTE_LAYER_OPACITY && MOTE_ENABLE_OPACITY_MAP)
                  || (l->role == MOTE_LAYER_SPECULAR && MOTE_ENABLE_SPECULAR_MAP && spec && !fog);
        if (built && texture_ok(l->texture))
            c->sh.layers[c->sh.layer_count++] = l;
    }
}

bool ref_draw(ref_target *t, const mote_mesh *mesh, const mote_draw_desc *draw)
{
    draw_ctx c;
    memset(&c, 0, sizeof c);
    c.t = t;
    c.mesh = mesh;
    if (draw)
        c.d = *draw;
    mote_mode mode = c.d.mode;
    if (mode <= MOTE_MODE_DEFAULT || mode >= MOTE_MODE_COUNT)
        mode = MOTE_MODE_TEXTURED;
    if (mode == MOTE_MODE_POINTS || mode == MOTE_MODE_WIREFRAME)
        return false;
    mote_cull cull = c.d.cull;
    if (cull <= MOTE_CULL_DEFAULT || cull >= MOTE_CULL_COUNT)
        cull = MOTE_CULL_BACK;

    /* world matrix: mote's public function (float, as the mesh defines it), then double */
    float wf[16];
    mote_mesh_world_matrix(mesh, wf);
    for (int i = 0; i < 16; i++)
        c.world[i] = wf[i];
    mat_mul(t->view_proj, c.world, c.mvp);
    /* normals: cofactor matrix of the linear part (inverse transpose up to scale) */
    const double *m = c.world;
#define M(r, col) m[(col) * 4 + (r)]
    for (int r = 0; r < 3; r++)
        for (int col = 0; col < 3; col++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (col + 1) % 3, c2 = (col + 2) % 3;
            c.nrm[r * 3 + col] = M(r1, c1) * M(r2, c2) - M(r1, c2) * M(r2, c1);
        }
    /* a mirroring matrix (negative determinant): the cofactors point
     * normals inward, and front faces have the other screen winding */
    double det = M(0, 0) * c.nrm[0] + M(0, 1) * c.nrm[1] + M(0, 2) * c.nrm[2];
#undef M
    bool mirrored = det < 0.0;
    if (mirrored)
        for (int i = 0; i < 9; i++)
            c.nrm[i] = -c.nrm[i];
    const mote_material *mat = &mesh->material;
    for (int k = 0; k < 3; k++) {
        c.color[k] = mat->color_set ? (double)(&mat->color.r)[k] / 255.0 : 1.0;
        c.emissive[k] = MOTE_ENABLE_EMISSIVE ? (double)(&mat->emissive.r)[k] / 255.0 : 0.0;
    }
    c.lit = !c.d.unlit;
    c.smooth = mode == MOTE_MODE_GOURAUD || mode == MOTE_MODE_TEXTURED;
    /* unlit flat is one colour per mesh, or per triangle with vertex colours */
    c.flat = mode == MOTE_MODE_FLAT && (c.lit || mesh->colors);
    c.textured = mode == MOTE_MODE_TEXTURED && texture_ok(mat->texture);
    c.sh.texture = c.textured ? mat->texture : NULL;
    c.sh.wrap_u = (mat->wrap_u > MOTE_WRAP_DEFAULT && mat->wrap_u < MOTE_WRAP_COUNT) ? mat->wrap_u : MOTE_WRAP_REPEAT;
    c.sh.wrap_v = (mat->wrap_v > MOTE_WRAP_DEFAULT && mat->wrap_v < MOTE_WRAP_COUNT) ? mat->wrap_v : MOTE_WRAP_REPEAT;
    c.sh.bilinear = c.d.filter == MOTE_FILTER_BILINEAR;
    c.sh.affine = false;         /* the reference is always perspective-correct */
    c.sh.depth_test = !c.d.no_depth_test;
    c.sh.depth_write = !c.d.no_depth_write;
    /* alpha, as mote.h's mote_material states it */
    mote_alpha_mode am = mat->alpha_mode;
    bool texel_alpha = c.textured && mat->use_texture_alpha;
    c.sh.alpha = mat->alpha_set ? floor(clamp01(mat->alpha) * 255.0 + 0.5) / 255.0 : 1.0;
    c.sh.alpha_test = MOTE_ENABLE_ALPHA_TEST && c.textured && (am == MOTE_ALPHA_TEST || am == MOTE_ALPHA_TEST_AND_BLEND);
    c.sh.cutoff = mat->alpha_cutoff != 0.0f ? mat->alpha_cutoff : 0.4;
    c.sh.blend = MOTE_ENABLE_BLEND && (am == MOTE_ALPHA_BLEND || am == MOTE_ALPHA_TEST_AND_BLEND);
    c.sh.texel_alpha = texel_alpha;
    /* a mip chain of the draw's texture, as mote_draw takes one */
    const mote_mipmaps *mm = mat->mipmaps;
    if (MOTE_ENABLE_MIPMAPS && c.textured && c.d.mip >= MOTE_MIP_TRIANGLE && c.d.mip < MOTE_MIP_COUNT && mm
        && mm->count > 1 && mm->count <= MOTE_MAX_MIPS && mm->level[0].pixels == mat->texture->pixels
        && mm->level[0].width == mat->texture->width && mm->level[0].height == mat->texture->height) {
        c.sh.mips = mm;
        c.sh.mip = c.d.mip;
        c.sh.mip_step = t->mip_step;
    }
    select_layers(&c, mat, mode);
    bool opacity = false;
    for (int i = 0; i < c.sh.layer_count; i++)
        opacity = opacity || c.sh.layers[i]->role == MOTE_LAYER_OPACITY;
    c.sh.alpha_test = c.sh.alpha_test || (MOTE_ENABLE_ALPHA_TEST && opacity
                                          && (am == MOTE_ALPHA_TEST || am == MOTE_ALPHA_TEST_AND_BLEND));
    c.gx = (double)(1 << MOTE_GUARD_BITS) / (t->width * 0.5);
    c.gy = (double)(1 << MOTE_GUARD_BITS) / (t->height * 0.5);

    uint32_t tris = mesh->indices ? mesh->index_count / 3 : 0;
    for (uint32_t i = 0; i < tris; i++) {
        const uint32_t *ix = &mesh->indices[3 * i];
        if (ix[0] >= mesh->vertex_count || ix[1] >= mesh->vertex_count || ix[2] >= mesh->vertex_count) {
            t->triangles_invalid++;
            continue;
        }
        cvert poly[MAXPOLY];
        double wp[3][3], wn[3][3];
        bool ok = true;
        for (int k = 0; k < 3; k++)
            ok = vertex(&c, ix[k], &poly[k], wp[k], wn[k]) && ok;
        if (!ok) {
            t->triangles_invalid++;
            continue;
        }
        if (c.flat) {
            double s[3];
            flat_shade(&c, ix, wp, wn, s);
            for (int k = 0; k < 3; k++)
                memcpy(poly[k].s, s, sizeof s);
        }
        int n = clip_poly(&c, poly, 3);
        if (n < 3)
            continue;
        int32_t X[MAXPOLY], Y[MAXPOLY];
        for (int k = 0; k < n; k++)
            snap(t, &poly[k], &X[k], &Y[k]);
        for (int k = 1; k + 1 < n; k++) {
            int32_t tx[3] = {X[0], X[k], X[k + 1]}, ty[3] = {Y[0], Y[k], Y[k + 1]};
            int64_t area = ((int64_t)tx[1] - tx[0]) * ((int64_t)ty[2] - ty[0])
                         - ((int64_t)ty[1] - ty[0]) * ((int64_t)tx[2] - tx[0]);
            if (area == 0) {
                t->triangles_degenerate++;
                continue;
            }
            bool clockwise = area > 0;    /* y down */
            bool front = (c.d.front_face == MOTE_FRONT_CW) != mirrored ? clockwise : !clockwise;
            if ((cull == MOTE_CULL_BACK && !front) || (cull == MOTE_CULL_FRONT && front)) {
                t->triangles_culled++;
                continue;
            }
            ref_vert rv[3];
            to_ref_vert(&poly[0], &rv[0]);
            to_ref_vert(&poly[k], &rv[1]);
            to_ref_vert(&poly[k + 1], &rv[2]);
            ref_triangle(t, &c.sh, tx, ty, rv);
            t->triangles_drawn++;
        }
    }
    return true;
}

/* ---- metrics ------------------------------------------------------------------ */

ref_metrics ref_compare(const uint8_t *a, const uint8_t *cov_a, const uint8_t *b, const uint8_t *cov_b,
                        int width, int height)
{
    ref_metrics r;
    memset(&r, 0, sizeof r);
    long n = (long)width * (long)height;
    r.pixels = n;
    double sum = 0.0, se = 0.0, se_all = 0.0;
    for (long i = 0; i < n; i++) {
        bool ia = !cov_a || cov_a[i], ib = !cov_b || cov_b[i];
        r.covered_a += ia;
        r.covered_b += ib;
        int worst = 0;
        for (int k = 0; k < 3; k++) {
            int d = abs((int)a[4 * i + k] - (int)b[4 * i + k]);
            se_all += (double)d * d;
            if (ia && ib) {
                sum += d;
                se += (double)d * d;
                worst = d > worst ? d : worst;
            }
        }
        if (ia != ib) {
            r.coverage_mismatch++;
        } else if (ia) {
            r.compared++;
            r.max_err = worst > r.max_err ? worst : r.max_err;
            if (worst > 1)
                r.off_by_more_than_1++;
        }
    }
    r.mean_err = r.compared ? sum / (3.0 * (double)r.compared) : 0.0;
    double mse = r.compared ? se / (3.0 * (double)r.compared) : 0.0;
    r.psnr = mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
    double mse_all = n ? se_all / (3.0 * (double)n) : 0.0;
    r.psnr_image = mse_all > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse_all) : INFINITY;
    r.within_1_fraction = r.compared ? 1.0 - (double)r.off_by_more_than_1 / (double)r.compared : 1.0;
    return r;
}
