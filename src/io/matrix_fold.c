/*
 * matrix_fold.c - node transforms for the loaders (matrix_fold.h): the
 * mirroring of right-handed files, and affine matrices folded into T R S
 * through a 3x3 SVD. The fold is worked in double, not with cglm's float
 * mat4 (mul, inv, quat): float rounding would change the folded
 * transforms, and cglm's SIMD and scalar builds sum in different orders.
 */
#include "matrix_fold.h"

#include <math.h>
#include <string.h>

void mote__trs_matrix(const mote__trs *t, float w[16])
{
    mote_mesh m;
    memset(&m, 0, sizeof m);
    memcpy(m.position, t->position, sizeof m.position);
    memcpy(m.rotation, t->rotation, sizeof m.rotation);
    memcpy(m.rotation_quaternion, t->quat, sizeof m.rotation_quaternion);
    m.use_quaternion = t->use_quat;
    memcpy(m.scaling, t->scaling, sizeof m.scaling);
    mote_mesh_world_matrix(&m, w);
}

void mote__mirror_point(float p[3])
{
    p[2] = 0.0f - p[2];   /* exactly -p[2], but a zero stays +0 */
}

void mote__mirror_rotation(float euler[3], float quat[4])
{
    euler[0] = 0.0f - euler[0];
    euler[1] = 0.0f - euler[1];
    quat[0] = 0.0f - quat[0];
    quat[1] = 0.0f - quat[1];
}

void mote__mirror_matrix(float m[16])
{
    static const int row_or_column_2[6] = {2, 6, 14, 8, 9, 11};
    for (int k = 0; k < 6; k++)
        m[row_or_column_2[k]] = 0.0f - m[row_or_column_2[k]];
}

void mote__flip_winding(uint32_t *idx, uint32_t n)
{
    for (uint32_t t = 0; t + 2 < n; t += 3) {
        uint32_t k = idx[t + 1];
        idx[t + 1] = idx[t + 2];
        idx[t + 2] = k;
    }
}

/* out = a b, column-major 4x4 (out may be a or b). */
static void mote__mul4(const double a[16], const double b[16], double out[16])
{
    double r[16];
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++) {
            double sum = 0.0;
            for (int k = 0; k < 4; k++)
                sum += a[k * 4 + row] * b[c * 4 + k];
            r[c * 4 + row] = sum;
        }
    memcpy(out, r, sizeof r);
}

/* The inverse of the affine m; false when it has none. The 3x3 part's
 * inverse is its adjugate over the determinant (cofactors with indices
 * taken cyclically carry their own signs), the translation -inverse t. */
static bool mote__affine_inverse(const double m[16], double out[16])
{
#define M(r, c) m[(c) * 4 + (r)]
    double cof[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            cof[r][c] = M(r1, c1) * M(r2, c2) - M(r1, c2) * M(r2, c1);
        }
    double det = M(0, 0) * cof[0][0] + M(0, 1) * cof[0][1] + M(0, 2) * cof[0][2];
    if (!(fabs(det) > 0.0) || !isfinite(1.0 / det))
        return false;
    memset(out, 0, 16 * sizeof *out);
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++)
            out[c * 4 + r] = cof[c][r] / det;
        out[12 + r] = -(out[r] * M(0, 3) + out[4 + r] * M(1, 3) + out[8 + r] * M(2, 3));
    }
    out[15] = 1.0;
#undef M
    return true;
}

/* Eigenvalues w and eigenvectors (the columns of v, a rotation) of the
 * symmetric a, by cyclic Jacobi rotations (each zeroes one off-diagonal
 * element; a few sweeps leave them at rounding). a is consumed. */
static void mote__symmetric_eigen3(double a[3][3], double w[3], double v[3][3])
{
    static const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    memset(v, 0, 9 * sizeof **v);
    v[0][0] = v[1][1] = v[2][2] = 1.0;
    for (int sweep = 0; sweep < 50; sweep++) {
        double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (!(off > 1e-32 * diag))
            break;
        for (int k = 0; k < 3; k++) {
            int p = pairs[k][0], q = pairs[k][1];
            if (a[p][q] == 0.0)
                continue;
            /* the rotation J in the (p, q) plane with (J^T a J)[p][q] = 0 */
            double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            double t = (theta >= 0.0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
            double c = 1.0 / sqrt(t * t + 1.0), s = t * c;
            for (int i = 0; i < 3; i++) {   /* a J, and v J */
                double aip = a[i][p], aiq = a[i][q], vip = v[i][p], viq = v[i][q];
                a[i][p] = c * aip - s * aiq;
                a[i][q] = s * aip + c * aiq;
                v[i][p] = c * vip - s * viq;
                v[i][q] = s * vip + c * viq;
            }
            for (int j = 0; j < 3; j++) {   /* J^T (a J) */
                double apj = a[p][j], aqj = a[q][j];
                a[p][j] = c * apj - s * aqj;
                a[q][j] = s * apj + c * aqj;
            }
        }
    }
    for (int i = 0; i < 3; i++)
        w[i] = a[i][i];
}

static void mote__cross3d(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* a = U diag(sigma) V^T, U and V rotations, given as the arrays
 * mote__rotation_quat takes for U and for V^T: ut, whose rows are U's
 * columns, and v, whose rows are V^T's. V holds the eigenvectors of a^T a,
 * sigma the roots of its eigenvalues, U's columns a V / sigma; a negative
 * sigma where a mirrors. A sigma of 0 (a flattened axis) gets a U column
 * that completes the rotation. */
static void mote__svd3(double a[3][3], double ut[3][3], double sigma[3], double v[3][3])
{
    double ata[3][3], most = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            ata[i][j] = a[0][i] * a[0][j] + a[1][i] * a[1][j] + a[2][i] * a[2][j];
    /* columns of a orthogonal but for float rounding (the cosine of their
     * angle within 1e-6) are taken as orthogonal: V stays the identity,
     * where rounding would turn it as it pleases between equal sigmas */
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (fabs(ata[i][j]) <= 1e-6 * sqrt(ata[i][i] * ata[j][j]))
                ata[i][j] = ata[j][i] = 0.0;
    mote__symmetric_eigen3(ata, sigma, v);
    for (int j = 0; j < 3; j++) {
        sigma[j] = sigma[j] > 0.0 ? sqrt(sigma[j]) : 0.0;
        most = sigma[j] > most ? sigma[j] : most;
    }
    int flat = 0, kept = 0;
    for (int j = 0; j < 3; j++) {
        if (!(sigma[j] > 1e-12 * most)) {
            flat++;
            memset(ut[j], 0, sizeof ut[j]);
            continue;
        }
        kept = j;
        for (int i = 0; i < 3; i++)
            ut[j][i] = (a[i][0] * v[0][j] + a[i][1] * v[1][j] + a[i][2] * v[2][j]) / sigma[j];
    }
    if (flat == 3) {
        memset(ut, 0, 9 * sizeof **ut);
        ut[0][0] = ut[1][1] = ut[2][2] = 1.0;
    } else if (flat == 2) {
        /* the one kept column, then any unit vector across it */
        int j1 = (kept + 1) % 3, j2 = (kept + 2) % 3, axis = 0;
        for (int i = 1; i < 3; i++)
            if (fabs(ut[kept][i]) < fabs(ut[kept][axis]))
                axis = i;
        double e[3] = {0.0, 0.0, 0.0};
        e[axis] = 1.0;
        mote__cross3d(ut[kept], e, ut[j1]);
        double len = sqrt(ut[j1][0] * ut[j1][0] + ut[j1][1] * ut[j1][1] + ut[j1][2] * ut[j1][2]);
        for (int i = 0; i < 3; i++)
            ut[j1][i] /= len;
        mote__cross3d(ut[kept], ut[j1], ut[j2]);
    } else if (flat == 1) {
        for (int j = 0; j < 3; j++)
            if (!(sigma[j] > 1e-12 * most))
                mote__cross3d(ut[(j + 1) % 3], ut[(j + 2) % 3], ut[j]);
    }
    double c[3];
    mote__cross3d(ut[1], ut[2], c);
    if (ut[0][0] * c[0] + ut[0][1] * c[1] + ut[0][2] * c[2] < 0.0) {
        /* a mirrors: the core's transform takes it as a negative scale */
        sigma[0] = -sigma[0];
        for (int i = 0; i < 3; i++)
            ut[0][i] = -ut[0][i];
    }
}

/* The quaternion (x, y, z, w) of the rotation whose columns are the rows
 * of rt (Shepperd's method: divides by the largest of 4w^2, 4x^2, 4y^2,
 * 4z^2). */
static void mote__rotation_quat(double rt[3][3], float q[4])
{
#define R(i, j) rt[j][i]
    double tr = R(0, 0) + R(1, 1) + R(2, 2), x, y, z, w, s;
    if (tr > 0.0) {
        s = 2.0 * sqrt(tr + 1.0);
        w = 0.25 * s;
        x = (R(2, 1) - R(1, 2)) / s;
        y = (R(0, 2) - R(2, 0)) / s;
        z = (R(1, 0) - R(0, 1)) / s;
    } else if (R(0, 0) > R(1, 1) && R(0, 0) > R(2, 2)) {
        s = 2.0 * sqrt(1.0 + R(0, 0) - R(1, 1) - R(2, 2));
        w = (R(2, 1) - R(1, 2)) / s;
        x = 0.25 * s;
        y = (R(0, 1) + R(1, 0)) / s;
        z = (R(0, 2) + R(2, 0)) / s;
    } else if (R(1, 1) > R(2, 2)) {
        s = 2.0 * sqrt(1.0 + R(1, 1) - R(0, 0) - R(2, 2));
        w = (R(0, 2) - R(2, 0)) / s;
        x = (R(0, 1) + R(1, 0)) / s;
        y = 0.25 * s;
        z = (R(1, 2) + R(2, 1)) / s;
    } else {
        s = 2.0 * sqrt(1.0 + R(2, 2) - R(0, 0) - R(1, 1));
        w = (R(1, 0) - R(0, 1)) / s;
        x = (R(0, 2) + R(2, 0)) / s;
        y = (R(1, 2) + R(2, 1)) / s;
        z = 0.25 * s;
    }
#undef R
    q[0] = (float)x;
    q[1] = (float)y;
    q[2] = (float)z;
    q[3] = (float)w;
}

/* *t set to a turn, scale and position (the scale of a
 * flattened node never all 0, which the core reads as 1). */
static void mote__set_trs(mote__trs *t, const double position[3], double rt[3][3],
                          const double scaling[3])
{
    for (int k = 0; k < 3; k++) {
        t->position[k] = (float)position[k];
        t->scaling[k] = (float)scaling[k];
        t->rotation[k] = 0.0f;
    }
    if (t->scaling[0] == 0.0f && t->scaling[1] == 0.0f && t->scaling[2] == 0.0f)
        t->scaling[0] = t->scaling[1] = t->scaling[2] = 1e-30f;
    mote__rotation_quat(rt, t->quat);
    t->use_quat = true;
}


mote__fold mote__fold_matrix(mote__trs *t, const float matrix[16], bool pivot,
                             mote__trs *outer)
{
    float f[16];
    double l[16], p[16], undo[16];
    mote__trs_matrix(t, f);
    for (int k = 0; k < 16; k++) {
        l[k] = f[k];
        p[k] = matrix[k];
    }
    if (pivot) {
        /* T P^-1 (R S) P: the position taken out, put back last */
        if (!mote__affine_inverse(p, undo))
            return MOTE__FOLD_SINGULAR;
        double position[3] = {l[12], l[13], l[14]};
        l[12] = l[13] = l[14] = 0.0;
        mote__mul4(undo, l, l);
        for (int k = 0; k < 3; k++)
            l[12 + k] += position[k];
    }
    mote__mul4(l, p, l);
    double a[3][3], ut[3][3], sigma[3], v[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            a[r][c] = l[c * 4 + r];
    mote__svd3(a, ut, sigma, v);
    bool sheared = false;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            sheared = sheared || fabs(v[r][c] - (r == c ? 1.0 : 0.0)) > 1e-6;
    if (!sheared) {
        mote__set_trs(t, &l[12], ut, sigma);
        return MOTE__FOLDED;
    }
    static const double origin[3] = {0.0, 0.0, 0.0}, unit[3] = {1.0, 1.0, 1.0};
    mote__set_trs(outer, &l[12], ut, sigma);
    mote__set_trs(t, origin, v, unit);
    return MOTE__FOLDED_SHEARED;
}
