/* glue_section.h — the section of a ball's world cylinder by a glued tube's hyperplane H
 * (t - t_x = kappa.z, z = y - X; papers/shape-change.md), as the ellipsoid
 * (z - m)^T A (z - m) <= 1 on which rc_glue_toi finds contacts on H. Private to the
 * library (toi_glue.c) and its white-box tests.
 *
 * The plain form A = L^T G L (L = I - v kappa^T, G the shape's rest-frame metric) is
 * kept where it is accurate. For a ball moving near c the same way as H (kappa nearly
 * light-like, a = c kappa, 1 - |a|^2 ~ 1/gamma^2) the section is ~gamma r long along
 * kappa and r across: A has eigenvalues ~1/(gamma r)^2 and ~1/r^2 while G's entries are
 * ~gamma^2 / r^2, and the plain form keeps only the rounding of its terms. Then:
 *   r^2 A = I - a a^T + gamma^2 d d^T,   d = a - beta
 * (the rest-frame distance from the cylinder's axis of a point of H, by Minkowski
 * products), written in a frame turned by the reflection Q (Q a = alpha e1) so that the
 * small eigenvalue stands alone in A_11 = (s + gamma^2 d1^2) / r^2, s = 1 - |a|^2: a graded
 * matrix whose entries each carry their own rounding, free of the gamma^2 cancellation.
 * s, d1 = alpha - beta1 and 1 - kappa.v are sums of positive terms or differences of
 * such of size 1/gamma^2 (each below). Any matrix with eigenvalues 1 and 1/gamma^2 stored
 * in table coordinates would carry the loss; in the turned frame it does not. */
#ifndef RELCOL_GLUE_SECTION_H
#define RELCOL_GLUE_SECTION_H

#include <math.h>

#include "relcol/toi.h"
#include "shape_math.h"

/* Above this c^2 |kappa|^2 (H's Lorentz factor above 8) the turned frame; below it the
 * plain form loses some gamma^4 < 2^12 roundings and is kept with its bits. */
#define RC_GLUE_SEC_FAST (1.0 - 0x1p-6)

/* The turned frame of a fast H: the Householder reflection Q = I - 2 w w^T / (w.w) taking
 * kappa onto the axis e_j of its largest component (w = khat + sign(khat_j) e_j, so that
 * no component of a reflected velocity is a difference of two near-equal ones), then the
 * axes cycled so that e_j comes first: kappa turned is (kq, 0, 0); s = 1 - c^2 |kappa|^2. */
typedef struct rc_glue_frame {
    rc_vec3 w;
    double ww;
    int j; /* the axis kappa is reflected onto */
    double kq; /* kappa's one component when turned: -+ |kappa| */
    double alpha; /* a = c kappa's, c kq */
    double s;
} rc_glue_frame;

static inline double rc_glue_cmp_(rc_vec3 x, int j) { return j == 0 ? x.x : j == 1 ? x.y : x.z; }

/* x in the turned frame */
static inline rc_vec3 rc_glue_turn(const rc_glue_frame *f, rc_vec3 x)
{
    const rc_vec3 y = rc_v3_axpy(x, -2.0 * rc_v3_dot(f->w, x) / f->ww, f->w);
    return f->j == 0 ? y : f->j == 1 ? rc_v3(y.y, y.z, y.x) : rc_v3(y.z, y.x, y.y);
}

/* zeta of the turned frame back in table coordinates */
static inline rc_vec3 rc_glue_turn_back(const rc_glue_frame *f, rc_vec3 z)
{
    const rc_vec3 y = f->j == 0 ? z : f->j == 1 ? rc_v3(z.z, z.x, z.y) : rc_v3(z.y, z.z, z.x);
    return rc_v3_axpy(y, -2.0 * rc_v3_dot(f->w, y) / f->ww, f->w);
}

/* 1 on a fast H (and *f its frame), 0 where the plain form is kept. s from the tube's
 * shapes: a = (G0 beta0 + G1 beta1) / (G0 + G1), G = 1/g, so
 *   s = (2 + G0 G1 (|beta0 - beta1|^2 + g0^2 + g1^2)) / (G0 + G1)^2,
 * with 1 - beta0.beta1 written as in glue_kv.h: positive terms. */
static inline int rc_glue_frame_make(const rc_glue *g, rc_glue_frame *f)
{
    const double k2 = rc_v3_norm2(g->kappa);
    if (!(g->inv_c2 > 0.0) || !(k2 > RC_GLUE_SEC_FAST * g->inv_c2))
        return 0;
    const double kn = sqrt(k2);
    const rc_vec3 kh = rc_v3_scale(1.0 / kn, g->kappa);
    const double ax = fabs(kh.x), ay = fabs(kh.y), az = fabs(kh.z);
    f->j = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    const double kj = rc_glue_cmp_(kh, f->j), sg = kj >= 0.0 ? 1.0 : -1.0;
    f->w = rc_v3(kh.x + (f->j == 0 ? sg : 0.0), kh.y + (f->j == 1 ? sg : 0.0),
                 kh.z + (f->j == 2 ? sg : 0.0));
    f->ww = rc_v3_norm2(f->w);
    f->kq = -sg * kn;
    f->alpha = f->kq / sqrt(g->inv_c2);
    const double G0 = 1.0 / g->in.g, G1 = 1.0 / g->out.g;
    const double d2 = rc_v3_norm2(rc_v3_sub(g->in.beta, g->out.beta));
    f->s = (2.0 + G0 * G1 * (d2 + g->in.g2 + g->out.g2)) / ((G0 + G1) * (G0 + G1));
    return 1;
}

/* The section in the turned frame: zeta = Q z, A and m in zeta. For shape sh (velocity v,
 * centre ca at table time ta): b = Q beta; d = (alpha - b1, -b2, -b3) with
 *   alpha - b1 = ((1 - b1^2) - (1 - alpha^2)) / (alpha + b1),  1 - b1^2 = g^2 + b2^2 + b3^2
 * when b1 is near alpha (both terms ~1/gamma^2, each to its rounding), plainly otherwise;
 * 1 - kappa.v = 1 - a.beta = (|d|^2 + s + g^2) / 2; the centre m = -(e + v kappa.e /
 * (1 - kappa.v)), e = X - ca(t_x) (Sherman-Morrison on L). */
static inline void rc_glue_section_fast(const rc_glue *g, const rc_glue_frame *f,
                                        const rc_toi_shape *sh, rc_vec3 v, rc_vec3 ca, double ta,
                                        rc_sym3 *A, rc_vec3 *m)
{
    const rc_vec3 b = rc_glue_turn(f, sh->beta);
    const double al = f->alpha;
    double d1;
    if (al * b.x > 0.5 * al * al)
        d1 = (sh->g2 + b.y * b.y + b.z * b.z - f->s) / (al + b.x);
    else
        d1 = al - b.x;
    const rc_vec3 d = rc_v3(d1, -b.y, -b.z);
    const double omkv = 0.5 * (rc_v3_norm2(d) + f->s + sh->g2);
    const double G2 = 1.0 / sh->g2, ir2 = 1.0 / (sh->r * sh->r);
    const rc_vec3 gd = rc_v3_scale(G2, d);
    A->xx = ir2 * (f->s + gd.x * d.x);
    A->yy = ir2 * (1.0 + gd.y * d.y);
    A->zz = ir2 * (1.0 + gd.z * d.z);
    A->xy = ir2 * gd.x * d.y;
    A->xz = ir2 * gd.x * d.z;
    A->yz = ir2 * gd.y * d.z;
    if (sh == &g->in) {
        /* the glued ball's own centre on H is its kink (t_c, x_c), found to its
         * conditioning by rc_glue_make: the formula below would amplify x_c's rounding
         * (~gamma r from X) by 1/(1 - kappa.v) */
        *m = rc_glue_turn(f, rc_v3_sub(g->x_c, g->x));
        return;
    }
    const rc_vec3 e = rc_v3_sub(g->x, rc_v3_axpy(ca, g->t_x - ta, v));
    const double ke = rc_v3_dot(g->kappa, e) / omkv;
    *m = rc_glue_turn(f, rc_v3_scale(-1.0, rc_v3_axpy(e, ke, v)));
}

/* Rest-frame metric of a shape: d is inside iff d^T G d <= 1, G = (I + u u^T) / r^2 with
 * u = gamma beta (the shape's rest-frame length of d over r, squared). */
static inline rc_sym3 rc_glue_shape_metric(const rc_toi_shape *s)
{
    const rc_vec3 u = rc_v3_scale(1.0 / s->g, s->beta);
    const double f = 1.0 / (s->r * s->r);
    const rc_sym3 G = {f * (1.0 + u.x * u.x), f * (1.0 + u.y * u.y), f * (1.0 + u.z * u.z),
                       f * u.x * u.y,         f * u.x * u.z,         f * u.y * u.z};
    return G;
}

/* L^T G L for L = I - v k^T: G - k (G v)^T - (G v) k^T + (v^T G v) k k^T. */
static inline rc_sym3 rc_glue_pull_back(const rc_sym3 *G, rc_vec3 v, rc_vec3 k)
{
    const rc_vec3 w = rc_sym3_mul_(G, v, 0);
    const double q = rc_v3_dot(v, w);
    rc_sym3 A;
    A.xx = G->xx - 2.0 * k.x * w.x + q * k.x * k.x;
    A.yy = G->yy - 2.0 * k.y * w.y + q * k.y * k.y;
    A.zz = G->zz - 2.0 * k.z * w.z + q * k.z * k.z;
    A.xy = G->xy - k.x * w.y - w.x * k.y + q * k.x * k.y;
    A.xz = G->xz - k.x * w.z - w.x * k.z + q * k.x * k.z;
    A.yz = G->yz - k.y * w.z - w.y * k.z + q * k.y * k.z;
    return A;
}

/* The plain section in z (ordinary speeds): A = L^T G L, m = -L^-1 e. */
static inline void rc_glue_section_plain(const rc_glue *g, const rc_toi_shape *s, rc_vec3 v,
                                         rc_vec3 ca, double ta, rc_sym3 *A, rc_vec3 *m)
{
    const rc_sym3 G = rc_glue_shape_metric(s);
    *A = rc_glue_pull_back(&G, v, g->kappa);
    const rc_vec3 e = rc_v3_sub(g->x, rc_v3_axpy(ca, g->t_x - ta, v));
    const double ke = rc_v3_dot(g->kappa, e) / (1.0 - rc_v3_dot(g->kappa, v));
    *m = rc_v3_scale(-1.0, rc_v3_axpy(e, ke, v));
}

/* min k.z over the intersection of two ellipsoids (z - m_i)^T A_i (z - m_i) <= 1, by
 * its dual (toi_glue.c): INFINITY if the intersection is empty, NAN if a blend of the two
 * is degenerate; *z the minimiser. rc_glue_toi's on H, and rc_glue_toi2's. */
double rc_glue_lin_min2_(const rc_sym3 *A1, rc_vec3 m1, const rc_sym3 *A2, rc_vec3 m2, rc_vec3 k,
                         rc_vec3 *z);

/* The same minimum by the dual's slope (toi_glue.c): about a dozen evaluations where the
 * golden section takes 92; rc_glue_toi2's. */
double rc_glue_lin_min2_slope_(const rc_sym3 *A1, rc_vec3 m1, const rc_sym3 *A2, rc_vec3 m2,
                               rc_vec3 k, rc_vec3 *z);

#endif
