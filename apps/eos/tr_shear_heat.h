/* tr_shear_heat.h — first Chapman–Enskog shear viscosity and thermal conductivity of
 * relcol's uncontracted-sphere (and disc) kernel at any c, by Monte Carlo over independent
 * Jüttner pairs: the method of tr_first_order.h (self-diffusion) for the one-component
 * gas. The deviation f0 phi solves the linearised Boltzmann equation; for any test
 * function psi its weak form is exact whatever the rate (f0 stationary is all it needs):
 *     <psi, L phi> = -(n^2/2) < R (Psi' - Psi) Phi >,   Psi = psi(p0) + psi(p1),
 * R = sigma_T |v0 - v1| (the sphere frame's non-invariant rate, sigma_T = pi sigma^2, or
 * sigma in 2-D) and ' the zmf law along the table-frame normal. On trial functions
 * psi_i (Galerkin): coefficient = (2 / kT^s) b^T M^-1 b, with
 *     M_ij = sigma_T < |v0 - v1| Psi_j . (Psi_i - Psi_i') >,   b_i = < psi_i . S >
 * per Cartesian component (isotropy), S the source:
 *     shear (s = 1): S = p_x v_y,  trial {p_x v_y, K p_x v_y};
 *     heat  (s = 2): S = (K - h) v_x, h = <K> + kT the enthalpy per particle less the rest
 *                    energy (Eckart's force grad T - T grad P / (n h)), trial
 *                    {(K - h) v_x, (K - h)^2 v_x minus its p_x part},
 * K = E - m c^2. Relativistically {p v, K p v} spans {p_x p_y / E, p_x p_y}, and E v = c^2 p
 * makes (K - h) v = c^2 p - (h + m c^2) v: heat is carried by v_x off the momentum, and
 * every heat trial function must be orthogonal to p_x (b is; M ignores it when the pair
 * measure is preserved, checked as `heat_inv`). Classically the first functions give
 * Chapman & Cowling's first approximations, both functions their second. Units: sigma =
 * m = 1; papers/transport.md, section 4. */
#ifndef RELCOL_TR_SHEAR_HEAT_H
#define RELCOL_TR_SHEAR_HEAT_H

#include <math.h>
#include <stdint.h>

#include "juttner.h"
#include "tr_first_order.h"

/* A d-D Jüttner (finite c) or Maxwell (c = inf) momentum, m = 1. In 2-D d^2 p ~ E dE:
 * K/c^2 has density ~ (1 + K/c^2) e^(-K/kT), a mixture of Gamma(1) and Gamma(2) draws. */
static inline rc_vec3 tr_draw_momentum_d(rc_rng *r, int dim, double c, double kT)
{
    if (dim == 3)
        return tr_draw_momentum(r, c, kT);
    double q;
    if (isinf(c)) {
        const double gx = rc_rng_gauss(r), gy = rc_rng_gauss(r);
        q = sqrt(kT * (gx * gx + gy * gy));
    } else {
        const double theta = kT / (c * c);
        double K = -log(1.0 - rc_rng_uniform(r));
        if (rc_rng_uniform(r) * (1.0 + theta) < theta)
            K -= log(1.0 - rc_rng_uniform(r));
        K *= theta;
        q = c * sqrt(K * (K + 2.0));
    }
    const double ph = 2.0 * M_PI * rc_rng_uniform(r);
    return rc_v3(q * cos(ph), q * sin(ph), 0.0);
}

/* Kinetic energy of a unit-mass ball without cancellation: p^2 / (gamma + 1). */
static inline double tr_kinetic(rc_vec3 p, double inv_c2)
{
    const double p2 = rc_v3_dot(p, p);
    return p2 / (sqrt(1.0 + inv_c2 * p2) + 1.0);
}

typedef struct tr_shear_heat {
    double eta, eta_se;               /* (2/kT) b^T M^-1 b: independent of n when dilute */
    double lambda, lambda_se;         /* (2/kT^2) b^T M^-1 b */
    /* sigma_T <|v0 - v1| P^ . (Psi_1 - Psi_1')> / M_11, P^ the pair momentum p0 + p1
     * scaled to the norm of heat's first function: zero when the collision preserves the
     * pair measure (then the drifting Jüttner is an equilibrium and the momentum part of
     * phi drops out); the fraction of M_11 a momentum part would carry otherwise */
    double heat_inv, heat_inv_se;
} tr_shear_heat;

/* The trial functions at momentum p: shear tensors s[k][9] (traceless p v and K times it)
 * and heat vectors q[k] ((K - h) v and (K - h)^2 v - a2 p). */
static inline void tr_sh_trial(int dim, rc_vec3 p, double inv_c2, double h, double a2,
                               double s[2][9], rc_vec3 q[2])
{
    const rc_vec3 v = rc_velocity(1.0, p, inv_c2);
    const double K = tr_kinetic(p, inv_c2), pv = rc_v3_dot(p, v) / dim;
    const double pa[3] = {p.x, p.y, p.z}, va[3] = {v.x, v.y, v.z};
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            const double t = a < dim && b < dim ? pa[a] * va[b] - (a == b ? pv : 0.0) : 0.0;
            s[0][3 * a + b] = t;
            s[1][3 * a + b] = K * t;
        }
    const double e = K - h;
    q[0] = rc_v3_scale(e, v);
    q[1] = rc_v3_sub(rc_v3_scale(e * e, v), rc_v3_scale(a2, p));
}

/* mean and standard error of k batch estimates */
static inline double tr_mean_se(const double *x, int k, double *se)
{
    double m = 0.0, v = 0.0;
    for (int i = 0; i < k; i++)
        m += x[i] / k;
    for (int i = 0; i < k; i++)
        v += (x[i] - m) * (x[i] - m);
    *se = sqrt(v / (k * (k - 1.0)));
    return m;
}

/* b^T A^-1 b on one function (A_00) or two */
static inline double tr_sh_galerkin(int nfun, const double A[2][2], const double b[2])
{
    if (nfun == 1)
        return b[0] * b[0] / A[0][0];
    const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
    return (b[0] * (A[1][1] * b[0] - A[0][1] * b[1]) + b[1] * (-A[1][0] * b[0] + A[0][0] * b[1])) /
           det;
}

/* eta and lambda of the dilute gas of unit spheres (dim 3) or discs (dim 2) colliding by
 * the zmf law at the sphere frame's rate, at speed of light c (INFINITY: classical) and
 * temperature kT, from `samples` pairs in 10 batches (errors: the batches' standard
 * error). nfun = 1: first functions alone (the first approximation); 2: both. Returns 0,
 * or -1 on bad arguments or a failed collision. Dense gas: times Enskog's factors. */
static inline int tr_shear_heat_sphere(int dim, double c, double kT, int nfun, long samples,
                                       uint64_t seed, tr_shear_heat *out)
{
    enum { NBATCH = 10, NPILOT = 20000 };
    if ((dim != 2 && dim != 3) || nfun < 1 || nfun > 2 || samples < 10 * NBATCH ||
        !(kT > 0.0) || !(c > 0.0))
        return -1;
    rc_rng r = {seed};
    rc_collision_params prm = rc_collision_params_default();
    prm.c = c;
    const double k = isinf(c) ? 0.0 : 1.0 / (c * c);
    /* <K>: d kT / 2 classically, (<gamma> - 1) c^2 of the Jüttner law otherwise */
    const double meanK = isinf(c) ? 0.5 * dim * kT
                                  : c * c * (jt_mean_gamma(dim, kT / (c * c)) - 1.0);
    const double h = meanK + kT;
    /* the p part of (K - h)^2 v, <(K - h)^2 v.p> / <p.p>, from a pilot sample: any constant
     * is exact (b and M do not see p), the right one only lowers the variance */
    double num = 0.0, den = 0.0;
    for (long i = 0; i < NPILOT; i++) {
        const rc_vec3 p = tr_draw_momentum_d(&r, dim, c, kT);
        const double e = tr_kinetic(p, k) - h;
        num += e * e * rc_v3_dot(rc_velocity(1.0, p, k), p);
        den += rc_v3_dot(p, p);
    }
    const double a2 = num / den, pp = den / (NPILOT * (double)dim); /* <p_x^2> */
    const double sig = dim == 3 ? M_PI : 2.0; /* sigma_T: pi sigma^2, or 2 sigma in 2-D */
    const double nt = dim == 3 ? 10.0 : 4.0, nv = dim;  /* isotropic contractions */
    const long per = samples / NBATCH;
    double est_e[NBATCH], est_l[NBATCH], est_i[NBATCH];
    for (int bt = 0; bt < NBATCH; bt++) {
        double As[2][2] = {{0}}, Aq[2][2] = {{0}}, bs[2] = {0}, bq[2] = {0}, inv = 0.0;
        for (long i = 0; i < per; i++) {
            rc_particle a = {1.0, tr_draw_momentum_d(&r, dim, c, kT)};
            rc_particle b = {1.0, tr_draw_momentum_d(&r, dim, c, kT)};
            double s0[2][9], s1[2][9], S[2][9], Sp[2][9];
            rc_vec3 q0[2], q1[2], Q[2], Qp[2];
            tr_sh_trial(dim, a.p, k, h, a2, s0, q0);
            tr_sh_trial(dim, b.p, k, h, a2, s1, q1);
            for (int f = 0; f < 2; f++) {
                for (int t = 0; t < 9; t++) {
                    bs[f] += 0.5 * (s0[f][t] * s0[0][t] + s1[f][t] * s1[0][t]);
                    S[f][t] = s0[f][t] + s1[f][t];
                }
                bq[f] += 0.5 * (rc_v3_dot(q0[f], q0[0]) + rc_v3_dot(q1[f], q1[0]));
                Q[f] = rc_v3_add(q0[f], q1[f]);
            }
            const rc_vec3 P = rc_v3_add(a.p, b.p);
            const rc_vec3 w = rc_v3_sub(rc_velocity(1.0, a.p, k), rc_velocity(1.0, b.p, k));
            const double g = rc_v3_norm(w);
            if (!(g > 0.0))
                continue;
            /* impact point uniform across w (the unit disc in 3-D, [-1, 1] in 2-D) */
            const rc_vec3 e = rc_v3_scale(1.0 / g, w);
            rc_vec3 nrm;
            if (dim == 3) {
                const rc_vec3 t0 = fabs(e.x) < 0.9 ? rc_v3(1, 0, 0) : rc_v3(0, 1, 0);
                const rc_vec3 c1 = rc_v3_cross(e, t0);
                const rc_vec3 u1 = rc_v3_unit(c1, rc_v3_norm(c1)), u2 = rc_v3_cross(e, u1);
                const double rb = sqrt(rc_rng_uniform(&r)), ph = 2.0 * M_PI * rc_rng_uniform(&r);
                const rc_vec3 bv = rc_v3_add(rc_v3_scale(rb * cos(ph), u1),
                                             rc_v3_scale(rb * sin(ph), u2));
                nrm = rc_v3_add(bv, rc_v3_scale(sqrt(fmax(0.0, 1.0 - rb * rb)), e));
            } else {
                const double bb = 2.0 * rc_rng_uniform(&r) - 1.0;
                nrm = rc_v3_add(rc_v3_scale(bb, rc_v3(-e.y, e.x, 0.0)),
                                rc_v3_scale(sqrt(fmax(0.0, 1.0 - bb * bb)), e));
            }
            if (rc_collide(&rc_law_zmf, &prm, &a, &b, nrm) != 0)
                return -1;
            tr_sh_trial(dim, a.p, k, h, a2, s0, q0);
            tr_sh_trial(dim, b.p, k, h, a2, s1, q1);
            for (int f = 0; f < 2; f++) {
                for (int t = 0; t < 9; t++)
                    Sp[f][t] = s0[f][t] + s1[f][t];
                Qp[f] = rc_v3_add(q0[f], q1[f]);
            }
            for (int i2 = 0; i2 < 2; i2++)
                for (int j = 0; j < 2; j++) {
                    double ts = 0.0;
                    for (int t = 0; t < 9; t++)
                        ts += S[j][t] * (S[i2][t] - Sp[i2][t]);
                    As[i2][j] += g * ts;
                    Aq[i2][j] += g * rc_v3_dot(Q[j], rc_v3_sub(Q[i2], Qp[i2]));
                }
            inv += g * rc_v3_dot(P, rc_v3_sub(Q[0], Qp[0])); /* scaled below */
        }
        for (int i2 = 0; i2 < 2; i2++) {
            bs[i2] /= nt * (double)per;
            bq[i2] /= nv * (double)per;
            for (int j = 0; j < 2; j++) {
                As[i2][j] *= sig / (nt * (double)per);
                Aq[i2][j] *= sig / (nv * (double)per);
            }
        }
        est_e[bt] = 2.0 / kT * tr_sh_galerkin(nfun, (const double(*)[2])As, bs);
        est_l[bt] = 2.0 / (kT * kT) * tr_sh_galerkin(nfun, (const double(*)[2])Aq, bq);
        est_i[bt] = inv * sqrt(bq[0] / pp) * sig / (nv * (double)per) / Aq[0][0];
    }
    out->eta = tr_mean_se(est_e, NBATCH, &out->eta_se);
    out->lambda = tr_mean_se(est_l, NBATCH, &out->lambda_se);
    out->heat_inv = tr_mean_se(est_i, NBATCH, &out->heat_inv_se);
    return 0;
}

#endif
