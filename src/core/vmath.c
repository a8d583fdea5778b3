/*
 * vmath.c - the vertex stage's arithmetic: matrices, camera, trig.
 *
 * Matrices are column-major float[16] (cglm's mat4 layout, m[col * 4 + row]).
 * Everything is plain scalar float in a fixed operation order and the build
 * disables fused multiply-add, so every target computes the same bits; that
 * is also why sin/cos/tan are our own polynomials rather than libm's.
 */
#define MOTE__VMATH_DEFINE     /* size builds: the one copy of internal.h's vertex helpers */
#include "internal.h"


float mote__sqrtf(float x)
{
    /* Newton with division, for the per-frame and per-mesh uses (camera
     * axes, bounds), where exact results for exact squares matter: a unit
     * view direction stays exactly unit. Per-vertex code uses rsqrt. */
    if (!mote__positive_finite(x))
        return x > 0.0f ? x : 0.0f;
    union { float f; uint32_t u; } g;
    g.f = x;
    g.u = (g.u >> 1) + 0x1fc00000u;
    float r = g.f;
    for (int i = 0; i < 4; i++)
        r = 0.5f * (r + x / r);
    return r;
}

/* sin and cos on [-pi/4, pi/4], minimax-style Taylor terms in x^2, highest
 * first: sin = x * P(x^2), cos = P(x^2), evaluated by Horner's rule. */
static const float mote__sin_terms[5] = {2.7525562e-6f, -1.9840874e-4f, 8.3333310e-3f, -1.6666667e-1f, 1.0f};
static const float mote__cos_terms[5] = {2.4390449e-5f, -1.3888378e-3f, 4.1666638e-2f, -0.5f, 1.0f};

static float mote__poly(const float terms[5], float x2)
{
    float p = terms[0];
    for (int i = 1; i < 5; i++)
        p = terms[i] + x2 * p;
    return p;
}

/* Reduces x to r in [-pi/4, pi/4] and a quadrant, in double-float steps. */
static int mote__reduce(float x, float *r)
{
    const float two_over_pi = 0.63661977236758134f;
    const float pio2_hi = 1.5707963705062866f;   /* float(pi/2) */
    const float pio2_lo = -4.3711388286737929e-8f; /* pi/2 - pio2_hi */
    if (!mote__finite(x) || x > 1e6f || x < -1e6f) {
        *r = 0.0f;
        return 0;
    }
    float k = x * two_over_pi;
    int q = (int)(k >= 0.0f ? k + 0.5f : k - 0.5f);
    float fq = (float)q;
    *r = (x - fq * pio2_hi) - fq * pio2_lo;
    return q & 3;
}

/* sin(x + shift * pi/2): cos is sin a quadrant on */
static float mote__sin_quadrant(float x, int shift)
{
    float r;
    int q = (mote__reduce(x, &r) + shift) & 3;
    float x2 = r * r;
    float v = (q & 1) ? mote__poly(mote__cos_terms, x2) : r * mote__poly(mote__sin_terms, x2);
    return (q & 2) ? -v : v;
}

float mote_sinf(float x)
{
    return mote__sin_quadrant(x, 0);
}

float mote_cosf(float x)
{
    return mote__sin_quadrant(x, 1);
}

float mote_tanf(float x)
{
    float c = mote_cosf(x);
    return mote__float_bits(c) << 1 ? mote_sinf(x) / c : 1e30f;   /* c == 0: a bit test */
}

void mote__mat4_identity(float m[16])
{
    memset(m, 0, 16 * sizeof(float));
    m[0] = m[5] = m[10] = m[15] = 1.0f;
}

void mote__mat4_mul(const float a[16], const float b[16], float out[16])
{
    float r[16];
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++)
            r[c * 4 + row] = a[0 * 4 + row] * b[c * 4 + 0] + a[1 * 4 + row] * b[c * 4 + 1]
                           + a[2 * 4 + row] * b[c * 4 + 2] + a[3 * 4 + row] * b[c * 4 + 3];
    memcpy(out, r, sizeof r);
}

void mote__normal_matrix(const float m[16], bool mirrors, float out[9])
{
    /* cofactors of the upper 3x3 = inverse-transpose times the determinant;
     * the scale does not matter because normals are normalised afterwards,
     * but the sign does: for a mirroring matrix (negative determinant) the
     * products are subtracted the other way round, or every normal would
     * point inward. Row r of the cofactors is the cross product of rows
     * r + 1 and r + 2 (indices taken cyclically); crossed the other way
     * round, it is negated bit for bit. */
    float rows[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            rows[r][c] = m[c * 4 + r];
    for (int r = 0, r1 = 1, r2 = 2; r < 3; r1 = r2, r2 = r, r++)
        mote__cross3(rows[mirrors ? r2 : r1], rows[mirrors ? r1 : r2], out + 3 * r);
}

static void mote__quat_matrix(const float q[4], float m[16])
{
    float w = q[3];
    float n = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + w * w;
    float s = n > 0.0f ? 2.0f / n : 0.0f;
    mote__mat4_identity(m);
    /* axis i with the next two j, k (cyclically) */
    for (int i = 0, j = 1, k = 2; i < 3; j = k, k = i, i++) {
        float ij = q[i] * q[j], kw = q[k] * w;
        m[i * 5] = 1.0f - s * (q[j] * q[j] + q[k] * q[k]);
        m[i * 4 + j] = s * (ij + kw);
        m[j * 4 + i] = s * (ij - kw);
    }
}

/* Babylon's Quaternion.RotationYawPitchRoll(yaw = ry, pitch = rx, roll = rz). */
static void mote__euler_quat(const float r[3], float q[4])
{
    float sc[2][3];               /* cosines, sines of the half angles */
    for (int i = 0; i < 3; i++) {
        sc[1][i] = mote_sinf(r[i] * 0.5f);
        sc[0][i] = mote_cosf(r[i] * 0.5f);
    }
    /* q[i] = fy fp fr +- gy gp gr: each f a sine (bit set in pick[i], bits
     * y, p, r from high to low) or a cosine, each g the other one */
    static const uint8_t pick[4] = {2, 4, 1, 0}, minus = 6;
    for (int i = 0; i < 4; i++) {
        int y = pick[i] >> 2, p = (pick[i] >> 1) & 1, z = pick[i] & 1;
        float f = sc[y][1] * sc[p][0] * sc[z][2], g = sc[!y][1] * sc[!p][0] * sc[!z][2];
        q[i] = f + (((minus >> i) & 1) ? -g : g);     /* a - b is a + (-b), exactly */
    }
}

/* translate(position) * rotate * scale(scaling) of one mesh; returns
 * whether it mirrors: an odd number of negative scale factors (a rotation
 * never does), read from the sign bits */
static bool mote__local_matrix(const mote_mesh *mesh, float m[16])
{
    float q[4];
    if (mesh->use_quaternion)
        memcpy(q, mesh->rotation_quaternion, sizeof q);
    else
        mote__euler_quat(mesh->rotation, q);
    mote__quat_matrix(q, m);
    const float *sc = mesh->scaling;
    bool unset = mote__zero3(sc);
    for (int c = 0; c < 3; c++)
        for (int r = 0; r < 3; r++)
            m[c * 4 + r] *= unset ? 1.0f : sc[c];
    m[12] = mesh->position[0];
    m[13] = mesh->position[1];
    m[14] = mesh->position[2];
    return !unset && (mote__float_bits(sc[0]) ^ mote__float_bits(sc[1]) ^ mote__float_bits(sc[2])) >> 31;
}

bool mote__world_matrix(const mote_mesh *mesh, float world[16])
{
    bool mirrors = mote__local_matrix(mesh, world);
    /* Parents are applied iteratively (bounded) so a cyclic chain cannot recurse forever. */
    const mote_mesh *p = mesh->parent;
    for (int depth = 0; p && depth < MOTE_MAX_PARENTS; depth++, p = p->parent) {
        float pm[16];
        mirrors ^= mote__local_matrix(p, pm);
        mote__mat4_mul(pm, world, world);
    }
    return mirrors;
}

void mote_mesh_world_matrix(const mote_mesh *mesh, float world[16])
{
    if (!world)
        return;
    if (!mesh)
        mote__mat4_identity(world);
    else
        mote__world_matrix(mesh, world);
}

/* v / |v| (a zero vector stays as it is). The square of a vector longer
 * than about 1.8e19 overflows, and that of one shorter than about 1e-19
 * loses bits or vanishes (a target far away, a tiny up vector, a camera
 * looking a hair from its up, whose x axis is then a tiny cross
 * product): such a vector is first scaled by 2^-100 or 2^100, which is
 * exact, so its direction survives. Any other is divided as it is. */
static void mote__normalize3(float v[3])
{
    float dd = mote__dot3(v, v);
    uint32_t e = mote__float_bits(dd) >> 23;   /* dd >= 0, or NaN */
    if (e - 16u > 220u) {                        /* dd < 2^-111 or dd >= 2^110 */
        for (int k = 0; k < 3; k++)
            v[k] *= e < 16u ? 0x1p100f : 0x1p-100f;
        dd = mote__dot3(v, v);
    }
    float len = mote__sqrtf(dd);
    if (len > 0.0f) {
        v[0] /= len;
        v[1] /= len;
        v[2] /= len;
    }
}

void mote__sub3(float a[3], const float b[3])
{
    for (int k = 0; k < 3; k++)
        a[k] -= b[k];
}

void mote__cross3(const float a[3], const float b[3], float out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

void mote__view_rotation(const mote_camera *camera, float view[16])
{
    /* Left-handed look-at (Babylon's LookAtLH): z toward the target. */
    float up[3] = {camera->up[0], camera->up[1], camera->up[2]};
    if (mote__zero3(up))
        up[1] = 1.0f;
    float z[3];
    memcpy(z, camera->target, sizeof z);
    mote__sub3(z, camera->position);
    mote__normalize3(z);
    float x[3], y[3];
    mote__cross3(up, z, x);
    if (mote__zero3(x)) {
        /* up parallel to the view direction: pick another up */
        float alt[3] = {0.0f, 0.0f, 1.0f};
        if (z[2] > 0.9f || z[2] < -0.9f) {
            alt[1] = 1.0f;
            alt[2] = 0.0f;
        }
        mote__cross3(alt, z, x);
    }
    mote__normalize3(x);
    mote__cross3(z, x, y);
    mote__mat4_identity(view);
    for (int i = 0; i < 3; i++) {
        view[i * 4 + 0] = x[i];
        view[i * 4 + 1] = y[i];
        view[i * 4 + 2] = z[i];
    }
}

void mote_camera_view_matrix(const mote_camera *camera, float view[16])
{
    if (!camera || !view) {
        if (view)
            mote__mat4_identity(view);
        return;
    }
    mote__view_rotation(camera, view);
    for (int i = 0; i < 3; i++) {   /* minus the position along each axis */
        const float axis[3] = {view[i], view[4 + i], view[8 + i]};
        view[12 + i] = -mote__dot3(axis, camera->position);
    }
}

void mote_camera_projection_matrix(const mote_camera *camera, float aspect, float proj[16])
{
    if (!camera || !proj) {
        if (proj)
            mote__mat4_identity(proj);
        return;
    }
    mote__projection(camera, aspect, proj);
}

/* mote_camera_projection_matrix of a camera and matrix the frame holds
 * (no checks: a firmware that never calls the public one links none) */
void mote__projection(const mote_camera *camera, float aspect, float proj[16])
{
    /* Depth 0 at near and 1 at far. Defaults for zeros. */
    float n = camera->znear > 0.0f ? camera->znear : 0.1f;
    float f = camera->zfar > 0.0f ? camera->zfar : 100.0f;
    if (aspect <= 0.0f)
        aspect = 1.0f;
    memset(proj, 0, 16 * sizeof(float));
#if MOTE_ENABLE_ORTHOGRAPHIC
    if (camera->projection == MOTE_PROJECTION_ORTHOGRAPHIC) {
        /* OrthoOffCenterLH: the box's edges to -1..1, w stays 1; near
         * as given (0 or behind the camera: no division by z here) */
        n = camera->znear;
        if (f <= n)
            f = n + 1.0f;
        float l = -aspect, r = aspect, b = -1.0f, t = 1.0f;
        const float *o = camera->ortho;
        if (o[0] != o[1] && o[2] != o[3]) {
            l = o[0];
            r = o[1];
            b = o[2];
            t = o[3];
        }
        proj[0] = 2.0f / (r - l);
        proj[5] = 2.0f / (t - b);
        proj[10] = 1.0f / (f - n);
        proj[12] = (l + r) / (l - r);
        proj[13] = (b + t) / (b - t);
        proj[14] = -n / (f - n);
        proj[15] = 1.0f;
        return;
    }
#endif
    /* PerspectiveFovLH */
    float fov = camera->fov > 0.0f ? camera->fov : 0.8f;
    if (fov > 3.1f)
        fov = 3.1f;
    if (f <= n)
        f = n * 2.0f;
    float ys = 1.0f / mote_tanf(fov * 0.5f);
    proj[0] = ys / aspect;
    proj[5] = ys;
    proj[10] = f / (f - n);
    proj[11] = 1.0f;
    proj[14] = -n * f / (f - n);
}

bool mote_project(const mote_device *dev, const float p[3], float *x, float *y, float *z)
{
    if (!dev || !p || !x || !y || !z)
        return false;
    float c[4];
    memcpy(c, p, 3 * sizeof *c);
    mote__sub3(c, dev->frame.camera.position);   /* as the vertex stage does (mote_begin) */
    mote__mat4_point(dev->view_proj, c, c);
    if (!(c[3] > 0.0f) || c[2] < 0.0f)
        return false;
    float W = (float)dev->desc.width, H = (float)dev->desc.height;
    *x = (c[0] / c[3] + 1.0f) * 0.5f * W;
    *y = (1.0f - c[1] / c[3]) * 0.5f * H;
    *z = c[2] / c[3];
    return true;
}

static bool mote__finite3(const float p[3])
{
    return mote__finite(p[0]) && mote__finite(p[1]) && mote__finite(p[2]);
}

const mote_vertex *mote__compact_vertex(const mote_compact *c, uint32_t i, mote_vertex *tmp)
{
    memset(tmp, 0, sizeof *tmp);
    for (int k = 0; k < 3; k++) {
        tmp->position[k] = (float)c->positions[3 * i + k];
        if (c->normals8 || c->normals16)
            tmp->normal[k] = (float)(c->normals8 ? c->normals8[3 * i + k] : c->normals16[3 * i + k]);
    }
    if (c->uvs)
        for (int k = 0; k < 2; k++)
            tmp->uv[k] = (float)c->uvs[2 * i + k];
    return tmp;
}

void mote__compact_fold(const float m[16], const float offset[3], const float scale[3], float out[16])
{
    float r[16];                  /* out may be m */
    for (int row = 0; row < 4; row++) {
        float t = m[12 + row];
        for (int k = 0; k < 3; k++) {
            r[k * 4 + row] = m[k * 4 + row] * scale[k];
            t += m[k * 4 + row] * offset[k];
        }
        r[12 + row] = t;
    }
    memcpy(out, r, sizeof r);
}

void mote_mesh_update_bounds(mote_mesh *mesh)
{
    if (!mesh)
        return;
    /* two passes over the finite vertices (one loop, less flash): their
     * box, whose centre is the sphere's, then the farthest from it; no
     * vertex array means no vertex, whatever vertex_count says */
    float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, r2 = 0.0f;
    bool any = false;
    const uint32_t count = mote__mesh_has_vertices(mesh) ? mesh->vertex_count : 0;
    for (int pass = 0; pass < 2; pass++) {
        for (uint32_t i = 0; i < count; i++) {
            mote_vertex tmp;
            float p[3];
            memcpy(p, mote__mesh_vertex(mesh, i, &tmp)->position, sizeof p);
            if (mesh->compact)    /* dequantised: the bounds are in the mesh's space */
                for (int k = 0; k < 3; k++)
                    p[k] = p[k] * mesh->compact->scale[k] + mesh->compact->offset[k];
            if (!mote__finite3(p))
                continue;
            if (pass == 0) {
                for (int k = 0; k < 3; k++) {
                    if (!any || p[k] < lo[k]) lo[k] = p[k];
                    if (!any || p[k] > hi[k]) hi[k] = p[k];
                }
                any = true;
            } else {
                float d[3];
                memcpy(d, p, sizeof d);
                mote__sub3(d, mesh->bounds_center);
                float dd = mote__dot3(d, d);
                if (dd > r2)
                    r2 = dd;
            }
        }
        for (int k = 0; k < 3 && pass == 0; k++)
            mesh->bounds_center[k] = 0.5f * (lo[k] + hi[k]);
    }
    /* a hair larger so float rounding in the test never rejects a visible mesh */
    mesh->bounds_radius = any ? mote__sqrtf(r2) * 1.0001f + 1e-6f : 0.0f;
}
