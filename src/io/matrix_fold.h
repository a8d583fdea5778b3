/*
 * matrix_fold.h - node transforms as the core draws them (T R S under a
 * parent), for loaders of scene formats that say more: a right-handed
 * file loaded mirrored in z, and a node's affine matrix (a pre-transform
 * or a pivot, sheared or not) folded into T R S. Not API.
 */
#ifndef MOTE_IO_MATRIX_FOLD_H
#define MOTE_IO_MATRIX_FOLD_H

#include <mote/mote.h>

#include <stdbool.h>
#include <stdint.h>

/* A node's own transform as the core composes a mesh's (mote_mesh):
 * T(position) R S(scaling), R the quaternion quat (x, y, z, w) when
 * use_quat, else the Euler angles `rotation` applied z, then x, then y;
 * scaling {0,0,0} is 1. */
typedef struct mote__trs {
    float position[3];
    float rotation[3];
    float quat[4];
    bool use_quat;
    float scaling[3];
} mote__trs;

/* t's matrix (column-major), exactly as mote_mesh_world_matrix makes it. */
void mote__trs_matrix(const mote__trs *t, float w[16]);

/* ---- right-handed files ------------------------------------------------ */

/* mote's core is left-handed. A right-handed scene is loaded mirrored in
 * z, S = diag(1, 1, -1): every point and direction p becomes S p and
 * every transform M becomes S M S. Then P_LH V_LH(S eye, S target, S up)
 * = P_RH V_RH(eye, target, up) S, so the mirrored scene through the
 * mirrored camera lands on the pixels the right-handed view gives; only
 * the triangles' order is reversed (mote__flip_winding), so that their
 * front faces stay front faces. */
void mote__mirror_point(float p[3]);
/* S R S for a rotation R: a quaternion (x, y, z, w) becomes (-x, -y, z,
 * w), Euler angles (rx, ry, rz), applied z, then x, then y, become (-rx,
 * -ry, rz): S Ry(a) S = Ry(-a), S Rx(a) S = Rx(-a), S Rz(a) S = Rz(a). */
void mote__mirror_rotation(float euler[3], float quat[4]);
/* S M S for a column-major 4x4 M: the elements of row 2 and of column 2,
 * but not both, change sign. */
void mote__mirror_matrix(float m[16]);
/* Swaps the last two corners of each whole triangle of idx[0..n). */
void mote__flip_winding(uint32_t *idx, uint32_t n);

/* ---- folding a matrix into T R S --------------------------------------- */

typedef enum mote__fold {
    MOTE__FOLDED,                 /* *t is the whole transform */
    MOTE__FOLDED_SHEARED,         /* *outer, then *t under it */
    MOTE__FOLD_SINGULAR           /* a pivot with no inverse; *t unchanged */
} mote__fold;

/* Folds the affine matrix P (column-major; its last row 0 0 0 1) into the
 * node transform *t = T R S: as a pre-transform (pivot false), L = T R S P,
 * or as a pivot (pivot true), L = T P^-1 R S P (R S about the pivot). The
 * core's transforms are T R S only: L = T U S' V^T (an SVD) is one when
 * V^T is the identity (no shear: the common case, a pivot that only
 * moves, or turns with an even scale), and *t becomes it. Else *outer
 * gets T U S', for a hidden helper node in the node's place under its
 * parent, and *t keeps only the turn V^T. Either way vertices and
 * children land where L puts them (normals too: the core's normal matrix
 * is the chain's inverse transpose), and no vertex array is touched. */
mote__fold mote__fold_matrix(mote__trs *t, const float matrix[16], bool pivot,
                             mote__trs *outer);

#endif
