/* shape_math.h — the arithmetic of a Lorentz-contracted ball's shape, written once for time
 * of impact, the soft reference and the engine (not installed): its matrix, the adjugate of
 * a blend of two, its support distance and support point. Every form keeps the
 * cancellation-free arrangement (sums of non-negative squares), so a fast ball's thin side
 * keeps full precision; callers that must agree bit for bit (the engine's certificates
 * with the table frame's solver) agree because they share these expressions. */
#ifndef RELCOL_SHAPE_MATH_H
#define RELCOL_SHAPE_MATH_H

#include "relcol/vec.h"

#define RC_SHAPE_INLINE __attribute__((always_inline)) static inline

/* Symmetric 3x3 matrix: xx, yy, zz, xy, xz, yz. */
typedef struct rc_sym3 {
    double xx, yy, zz, xy, xz, yz;
} rc_sym3;

/* f (s I + |v|^2 I - v v^T), the matrix P of the shape { x : x^T P^-1 x <= 1 }:
 * f = r^2, s = 1/gamma^2, v = beta (relcol/toi.h's shape), or f = r^2/gamma^2, s = 1,
 * v = gamma beta (the engine's). Diagonal entries are sums of squares, not 1 - beta^2. */
RC_SHAPE_INLINE rc_sym3 rc_shape_matrix_(double f, double s, rc_vec3 v)
{
    rc_sym3 P = {f * (s + v.y * v.y + v.z * v.z), f * (s + v.x * v.x + v.z * v.z),
                 f * (s + v.x * v.x + v.y * v.y), -f * v.x * v.y, -f * v.x * v.z,
                 -f * v.y * v.z};
    return P;
}

/* (1 - lam) P0 + lam P1; planar (a compile-time constant where it matters): the z terms
 * are zero. */
RC_SHAPE_INLINE rc_sym3 rc_sym3_blend_(const rc_sym3 *P0, const rc_sym3 *P1, double lam,
                                       const int planar)
{
    const double l1 = 1.0 - lam;
    rc_sym3 C;
    C.xx = l1 * P0->xx + lam * P1->xx;
    C.yy = l1 * P0->yy + lam * P1->yy;
    C.xy = l1 * P0->xy + lam * P1->xy;
    if (planar) {
        C.zz = C.xz = C.yz = 0.0;
        return C;
    }
    C.zz = l1 * P0->zz + lam * P1->zz;
    C.xz = l1 * P0->xz + lam * P1->xz;
    C.yz = l1 * P0->yz + lam * P1->yz;
    return C;
}

/* A - B */
RC_SHAPE_INLINE rc_sym3 rc_sym3_sub_(const rc_sym3 *A, const rc_sym3 *B)
{
    rc_sym3 D = {A->xx - B->xx, A->yy - B->yy, A->zz - B->zz,
                 A->xy - B->xy, A->xz - B->xz, A->yz - B->yz};
    return D;
}

/* A + lam D (a blend written from one end and the difference) */
RC_SHAPE_INLINE rc_sym3 rc_sym3_axpy_(const rc_sym3 *A, double lam, const rc_sym3 *D)
{
    rc_sym3 C = {A->xx + lam * D->xx, A->yy + lam * D->yy, A->zz + lam * D->zz,
                 A->xy + lam * D->xy, A->xz + lam * D->xz, A->yz + lam * D->yz};
    return C;
}

/* Adjugate A of C and its determinant (planar: of C's xy block, z terms of A zero).
 * A v = det C^-1 v without a division, which the callers' tests need only up to scale. */
RC_SHAPE_INLINE double rc_sym3_adj_(const rc_sym3 *C, rc_sym3 *A, const int planar)
{
    if (planar) {
        A->xx = C->yy;
        A->yy = C->xx;
        A->xy = -C->xy;
        A->zz = A->xz = A->yz = 0.0;
        return C->xx * C->yy - C->xy * C->xy;
    }
    A->xx = C->yy * C->zz - C->yz * C->yz;
    A->yy = C->xx * C->zz - C->xz * C->xz;
    A->zz = C->xx * C->yy - C->xy * C->xy;
    A->xy = C->xz * C->yz - C->xy * C->zz;
    A->xz = C->xy * C->yz - C->xz * C->yy;
    A->yz = C->xy * C->xz - C->xx * C->yz;
    return C->xx * A->xx + C->xy * A->xy + C->xz * A->xz;
}

/* A v (planar: the xy block, z of the result zero) */
RC_SHAPE_INLINE rc_vec3 rc_sym3_mul_(const rc_sym3 *A, rc_vec3 v, const int planar)
{
    if (planar)
        return rc_v3(A->xx * v.x + A->xy * v.y, A->xy * v.x + A->yy * v.y, 0.0);
    return rc_v3(A->xx * v.x + A->xy * v.y + A->xz * v.z,
                 A->xy * v.x + A->yy * v.y + A->yz * v.z,
                 A->xz * v.x + A->yz * v.y + A->zz * v.z);
}

/* y^T (s I + |v|^2 I - v v^T) y = s |y|^2 + |v x y|^2 (y2 = |y|^2, or 1 for a unit y):
 * the squared support distance along y times |y|^2, over f. Both terms are non-negative,
 * so 1 - (beta.n)^2 = g2 + |beta x n|^2 keeps full precision for a flat shape. */
RC_SHAPE_INLINE double rc_shape_form_(double s, rc_vec3 v, rc_vec3 y, double y2)
{
    return s * y2 + rc_v3_norm2(rc_v3_cross(v, y));
}

/* (s I + |v|^2 I - v v^T) y = P y / f: the support point along y is P y / h(y). */
RC_SHAPE_INLINE rc_vec3 rc_shape_form_mul_(double s, rc_vec3 v, rc_vec3 y)
{
    return rc_v3_axpy(rc_v3_scale(s + rc_v3_norm2(v), y), -rc_v3_dot(v, y), v);
}

#endif
