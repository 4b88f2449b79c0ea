/* toi_private.h — helpers shared by the time-of-impact files (not installed). */
#ifndef RELCOL_TOI_PRIVATE_H
#define RELCOL_TOI_PRIVATE_H

#include <math.h>

#include "relcol/toi.h"
#include "pair_axis.h"
#include "shape_math.h"

/* The zmf frame's kernel (lib/toi_zmf.c), shared with the covariant frame, whose pair
 * contact is the same event. */
int rc_toi_zmf_(const rc_toi_params *prm, const rc_toi_ball *a, const rc_toi_ball *b,
                rc_toi_workspace *ws, rc_toi_contact *out);

/* 1 when the pair's ZMF moves so fast that the plain boost into it cancels (pair_axis.h,
 * RC_PAIR_FAST: |P|^2/c^2 > 0.9 Mt^2); slower pairs keep the plain forms and their bits. */
static inline int rc_toi_zmf_is_fast_(const rc_toi_ball *a, const rc_toi_ball *b, double k,
                                      double M0, double M1)
{
    const double Mt = M0 + M1;
    return rc_v3_norm2(rc_v3_add(a->p, b->p)) * k > RC_PAIR_FAST * Mt * Mt;
}

/* A fast pair in its ZMF without the gamma^2 cancellation of the plain boost
 * p + [(g - 1) p.uhat - g M |u|] uhat (papers/time-of-impact.md, "Accuracy near c"): ball
 * 0's ZMF momentum t0 + g dl uhat from the pair's split along its total momentum
 * (pair_axis.h, rc_pair_split_of: the transverse part from p0 x p1, the longitudinal one
 * a rapidity difference, g from a sum of positive terms), ball 1's its negative; the ZMF
 * energies M0z, M1z from those. For rc_toi_zmf_is_fast_ pairs (|P| > 0). */
static inline void rc_toi_zmf_fast_(const rc_toi_ball *a, const rc_toi_ball *b, double k,
                                    double M0, double M1, double *g, rc_vec3 *p0z,
                                    double *M0z, double *M1z)
{
    const rc_particle pa = {a->m, a->p}, pb = {b->m, b->p};
    rc_pair_split z;
    rc_pair_split_of(&pa, &pb, M0, M1, k, sqrt(k), &z);
    *g = z.g;
    *p0z = rc_v3_axpy(z.t0, z.g * z.dl, z.uhat);
    const double q2 = rc_v3_norm2(*p0z) * k;
    *M0z = sqrt(a->m * a->m + q2);
    *M1z = sqrt(b->m * b->m + q2);
}

/* Shape of a ball state whose relativistic mass M = sqrt(m^2 + p^2/c^2) is known, given
 * 1/c (sqrt(inv_c2)) as well (for callers that make many shapes). */
static inline rc_toi_shape rc_toi_shape_Mc_(double r, double m, rc_vec3 p, double inv_c,
                                            double M)
{
    rc_toi_shape s;
    s.r = r;
    s.g = m / M; /* exactly 1 when inv_c2 = 0 (M = m) */
    s.g2 = s.g * s.g;
    s.beta = rc_v3_scale(inv_c / M, p);
    return s;
}

/* Shape of a ball state whose relativistic mass M = sqrt(m^2 + p^2/c^2) is known. */
static inline rc_toi_shape rc_toi_shape_M_(double r, double m, rc_vec3 p, double inv_c2,
                                           double M)
{
    return rc_toi_shape_Mc_(r, m, p, sqrt(inv_c2), M);
}

/* Table-frame contact point: ball 0's centre at time t plus the contact offset y0.
 * Every frame assembles the point with this one expression so that frames that agree
 * on (t, y0) agree bit for bit on the point (c = inf tests compare with ==). */
static inline rc_vec3 rc_toi_point_(rc_vec3 x0, rc_vec3 v0, double t, rc_vec3 y0)
{
    return rc_v3_add(rc_v3_axpy(x0, t, v0), y0);
}

/* Support distance along unit n (rc_toi_support's body, inline for the contracted solver,
 * which takes four per call): r sqrt(1 - (beta.n)^2), shape_math.h's form. */
static inline double rc_toi_support_(const rc_toi_shape *s, rc_vec3 n)
{
    return s->r * sqrt(rc_shape_form_(s->g2, s->beta, n, 1.0));
}

/* The same along any u, times |u| (u2 = |u|^2): no normalising square root. */
static inline double rc_toi_support_scaled_(const rc_toi_shape *s, rc_vec3 u, double u2)
{
    return s->r * sqrt(rc_shape_form_(s->g2, s->beta, u, u2));
}

/* Support point of a shape along unit n, relative to its centre: P n / h(n). */
static inline rc_vec3 rc_toi_support_point_(const rc_toi_shape *s, rc_vec3 n, double h)
{
    return rc_v3_scale(s->r * s->r / h, rc_shape_form_mul_(s->g2, s->beta, n));
}

/* The matrix P of a shape (shape_math.h) given its radius r in the caller's length unit
 * (s->r itself, or s->r scaled by the caller to keep the products in range). */
static inline rc_sym3 rc_toi_shape_matrix_(const rc_toi_shape *s, double r)
{
    return rc_shape_matrix_(r * r, s->g2, s->beta);
}

#endif
