/* tr_shear_heat.h — first Chapman–Enskog shear viscosity and thermal conductivity of
 * relcol's uncontracted-sphere (and disc) kernel at any c, by Monte Carlo over independent
 * Jüttner pairs: the method of tr_first_order.h (self-diffusion) for the one-component
 * gas. The deviation f0 phi solves the linearised Boltzmann equation; for any test
 * function psi its weak form is exact whatever the rate (f0 stationary is all it needs):
 *     <psi, L phi> = -(n^2/2) < R (Psi' - Psi) Phi >,   Psi = psi(p0) + psi(p1),
 * R = sigma_T |v0 - v1| (the sphere frame's non-invariant rate, sigma_T = pi sigma^2, or
 * 2 sigma in 2-D) and ' the zmf law along the table-frame normal. On trial functions
 * psi_i (Galerkin): coefficient = (2 / kT^s) b^T M^-1 b, with
 *     M_ij = sigma_T < |v0 - v1| Psi_j . (Psi_i - Psi_i') >,   b_i = < psi_i . S >
 * per Cartesian component (isotropy), S the source:
 *     shear (s = 1): S = p_x v_y,  trial x^j p_x v_y,  x = K / kT;
 *     heat  (s = 2): S = (K - h) v_x, h = <K> + kT the enthalpy per particle less the rest
 *                    energy (Eckart's force grad T - T grad P / (n h)), trial
 *                    (K - h) y^j v_x minus its p_x part,  y = (K - h) / kT,
 * j = 0 .. nfun - 1, K = E - m c^2. Relativistically {p v, K p v} spans {p_x p_y / E,
 * p_x p_y}, and E v = c^2 p makes (K - h) v = c^2 p - (h + m c^2) v: heat is carried by
 * v_x off the momentum, and every heat trial function must be orthogonal to p_x (b is; M
 * ignores it when the pair measure is preserved, checked as `heat_inv`). Classically the
 * first functions give Chapman & Cowling's first approximations, two functions their
 * second. Units: sigma = m = 1; papers/transport.md, section 4. */
#ifndef RELCOL_TR_SHEAR_HEAT_H
#define RELCOL_TR_SHEAR_HEAT_H

#include <math.h>
#include <stdint.h>

#include "eos_theory.h"
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
    /* Enskog's linear density term, alpha: the collisional transfer (momentum, energy
     * moved by sigma n at each collision) that the kinetic deviation phi drives, over
     * b n times the kinetic value (b n = 2 pi n sigma^3 / 3, pi n sigma^2 / 2 in 2-D).
     * Enskog's factor is 1/chi + 2 alpha b n + O((b n)^2); classically alpha = 2/5 (eta)
     * and 3/5 (lambda) */
    double alpha_eta, alpha_eta_se, alpha_lambda, alpha_lambda_se;
} tr_shear_heat;

enum { TR_SH_NFUN = 3 }; /* the most trial functions per coefficient */

/* The trial functions at momentum p: shear tensors s[j][9] (x^j times traceless p v) and
 * heat vectors q[j] ((K - h) y^j v - ap[j] p). */
static inline void tr_sh_trial(int dim, rc_vec3 p, double inv_c2, double kT, double h,
                               const double ap[TR_SH_NFUN], double s[TR_SH_NFUN][9],
                               rc_vec3 q[TR_SH_NFUN])
{
    const rc_vec3 v = rc_velocity(1.0, p, inv_c2);
    const double K = tr_kinetic(p, inv_c2), pv = rc_v3_dot(p, v) / dim;
    const double pa[3] = {p.x, p.y, p.z}, va[3] = {v.x, v.y, v.z};
    const double x = K / kT, e = K - h, y = e / kT;
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            double t = a < dim && b < dim ? pa[a] * va[b] - (a == b ? pv : 0.0) : 0.0;
            for (int j = 0; j < TR_SH_NFUN; j++, t *= x)
                s[j][3 * a + b] = t;
        }
    double w = e;
    for (int j = 0; j < TR_SH_NFUN; j++, w *= y)
        q[j] = rc_v3_sub(rc_v3_scale(w, v), rc_v3_scale(ap[j], p));
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

/* b^T A^-1 b on the first nfun functions (Gaussian elimination with partial pivoting);
 * x = A^-1 b */
static inline double tr_sh_galerkin(int nfun, const double A[TR_SH_NFUN][TR_SH_NFUN],
                                    const double b[TR_SH_NFUN], double x[TR_SH_NFUN])
{
    double M[TR_SH_NFUN][TR_SH_NFUN + 1];
    for (int i = 0; i < nfun; i++) {
        for (int j = 0; j < nfun; j++)
            M[i][j] = A[i][j];
        M[i][nfun] = b[i];
    }
    for (int c = 0; c < nfun; c++) {
        int piv = c;
        for (int i = c + 1; i < nfun; i++)
            if (fabs(M[i][c]) > fabs(M[piv][c]))
                piv = i;
        for (int j = 0; j <= nfun; j++) {
            const double t = M[c][j];
            M[c][j] = M[piv][j];
            M[piv][j] = t;
        }
        for (int i = c + 1; i < nfun; i++) {
            const double f = M[i][c] / M[c][c];
            for (int j = c; j <= nfun; j++)
                M[i][j] -= f * M[c][j];
        }
    }
    double r = 0.0;
    for (int i = nfun - 1; i >= 0; i--) {
        double t = M[i][nfun];
        for (int j = i + 1; j < nfun; j++)
            t -= M[i][j] * x[j];
        x[i] = t / M[i][i];
        r += b[i] * x[i];
    }
    return r;
}

/* eta and lambda of the dilute gas of unit spheres (dim 3) or discs (dim 2) colliding by
 * the zmf law at the sphere frame's rate, at speed of light c (INFINITY: classical) and
 * temperature kT, from `samples` pairs in 10 batches (errors: the batches' standard
 * error). nfun = 1: first functions alone (the first approximation); 2, 3: the Galerkin
 * solutions on more (relcol-eos uses 2; 3 measures how far 2 is from converged). Returns 0,
 * or -1 on bad arguments or a failed collision. Dense gas: tr_shear_heat_enskog. */
static inline int tr_shear_heat_sphere(int dim, double c, double kT, int nfun, long samples,
                                       uint64_t seed, tr_shear_heat *out)
{
    enum { NBATCH = 10, NPILOT = 20000 };
    if ((dim != 2 && dim != 3) || nfun < 1 || nfun > TR_SH_NFUN || samples < 10 * NBATCH ||
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
    /* the p part of (K - h) y^j v, <(K - h) y^j v.p> / <p.p>, from a pilot sample: any
     * constant is exact (b and M do not see p), the right one only lowers the variance;
     * (K - h) v itself has none */
    double num[TR_SH_NFUN] = {0}, den = 0.0, ap[TR_SH_NFUN] = {0};
    for (long i = 0; i < NPILOT; i++) {
        const rc_vec3 p = tr_draw_momentum_d(&r, dim, c, kT);
        const double e = tr_kinetic(p, k) - h, vp = rc_v3_dot(rc_velocity(1.0, p, k), p);
        double w = e;
        for (int j = 0; j < TR_SH_NFUN; j++, w *= e / kT)
            num[j] += w * vp;
        den += rc_v3_dot(p, p);
    }
    for (int j = 1; j < TR_SH_NFUN; j++)
        ap[j] = num[j] / den;
    const double pp = den / (NPILOT * (double)dim); /* <p_x^2> */
    const double sig = dim == 3 ? M_PI : 2.0; /* sigma_T: pi sigma^2, or 2 sigma in 2-D */
    const double nt = dim == 3 ? 10.0 : 4.0, nv = dim;  /* isotropic contractions */
    const long per = samples / NBATCH;
    double est_e[NBATCH], est_l[NBATCH], est_i[NBATCH], est_ae[NBATCH], est_al[NBATCH];
    /* b n / n: the second virial coefficient of unit spheres or discs */
    const double bvir = dim == 3 ? 2.0 * M_PI / 3.0 : M_PI / 2.0;
    for (int bt = 0; bt < NBATCH; bt++) {
        double As[TR_SH_NFUN][TR_SH_NFUN] = {{0}}, Aq[TR_SH_NFUN][TR_SH_NFUN] = {{0}};
        double bs[TR_SH_NFUN] = {0}, bq[TR_SH_NFUN] = {0}, inv = 0.0;
        double ts_[TR_SH_NFUN] = {0}, tq_[TR_SH_NFUN] = {0}; /* collisional transfer */
        for (long i = 0; i < per; i++) {
            rc_particle a = {1.0, tr_draw_momentum_d(&r, dim, c, kT)};
            rc_particle b = {1.0, tr_draw_momentum_d(&r, dim, c, kT)};
            double s0[TR_SH_NFUN][9], s1[TR_SH_NFUN][9], S[TR_SH_NFUN][9], Sp[TR_SH_NFUN][9];
            rc_vec3 q0[TR_SH_NFUN], q1[TR_SH_NFUN], Q[TR_SH_NFUN], Qp[TR_SH_NFUN];
            tr_sh_trial(dim, a.p, k, kT, h, ap, s0, q0);
            tr_sh_trial(dim, b.p, k, kT, h, ap, s1, q1);
            for (int f = 0; f < nfun; f++) {
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
            const rc_vec3 pb0 = b.p;
            const double kb0 = tr_kinetic(b.p, k);
            if (rc_collide(&rc_law_zmf, &prm, &a, &b, nrm) != 0)
                return -1;
            /* what ball 1, a diameter along nrm from ball 0, gained */
            const rc_vec3 dp = rc_v3_sub(b.p, pb0);
            const double dE = tr_kinetic(b.p, k) - kb0;
            const double na[3] = {nrm.x, nrm.y, nrm.z}, da[3] = {dp.x, dp.y, dp.z};
            for (int j = 0; j < nfun; j++) {
                double t = 0.0;
                for (int a2 = 0; a2 < 3; a2++)
                    for (int b2 = 0; b2 < 3; b2++)
                        t += na[a2] * da[b2] * S[j][3 * a2 + b2];
                ts_[j] += g * t;
                tq_[j] += g * dE * rc_v3_dot(nrm, Q[j]);
            }
            tr_sh_trial(dim, a.p, k, kT, h, ap, s0, q0);
            tr_sh_trial(dim, b.p, k, kT, h, ap, s1, q1);
            for (int f = 0; f < nfun; f++) {
                for (int t = 0; t < 9; t++)
                    Sp[f][t] = s0[f][t] + s1[f][t];
                Qp[f] = rc_v3_add(q0[f], q1[f]);
            }
            for (int i2 = 0; i2 < nfun; i2++)
                for (int j = 0; j < nfun; j++) {
                    double ts = 0.0;
                    for (int t = 0; t < 9; t++)
                        ts += S[j][t] * (S[i2][t] - Sp[i2][t]);
                    As[i2][j] += g * ts;
                    Aq[i2][j] += g * rc_v3_dot(Q[j], rc_v3_sub(Q[i2], Qp[i2]));
                }
            inv += g * rc_v3_dot(P, rc_v3_sub(Q[0], Qp[0])); /* scaled below */
        }
        for (int i2 = 0; i2 < nfun; i2++) {
            bs[i2] /= nt * (double)per;
            bq[i2] /= nv * (double)per;
            ts_[i2] *= sig / (nt * (double)per);
            tq_[i2] *= sig / (nv * (double)per);
            for (int j = 0; j < nfun; j++) {
                As[i2][j] *= sig / (nt * (double)per);
                Aq[i2][j] *= sig / (nv * (double)per);
            }
        }
        /* phi = (2/n) sum_j x_j psi_j: kinetic (2/kT^s) b.x, collisional n T.x / kT^s */
        double xs[TR_SH_NFUN], xq[TR_SH_NFUN], cs = 0.0, cq = 0.0;
        const double ks = tr_sh_galerkin(nfun, (const double(*)[TR_SH_NFUN])As, bs, xs);
        const double kq = tr_sh_galerkin(nfun, (const double(*)[TR_SH_NFUN])Aq, bq, xq);
        for (int j = 0; j < nfun; j++) {
            cs += ts_[j] * xs[j];
            cq += tq_[j] * xq[j];
        }
        est_e[bt] = 2.0 / kT * ks;
        est_l[bt] = 2.0 / (kT * kT) * kq;
        est_ae[bt] = cs / (2.0 * ks * bvir);
        est_al[bt] = cq / (2.0 * kq * bvir);
        est_i[bt] = inv * sqrt(bq[0] / pp) * sig / (nv * (double)per) / Aq[0][0];
    }
    out->eta = tr_mean_se(est_e, NBATCH, &out->eta_se);
    out->lambda = tr_mean_se(est_l, NBATCH, &out->lambda_se);
    out->heat_inv = tr_mean_se(est_i, NBATCH, &out->heat_inv_se);
    out->alpha_eta = tr_mean_se(est_ae, NBATCH, &out->alpha_eta_se);
    out->alpha_lambda = tr_mean_se(est_al, NBATCH, &out->alpha_lambda_se);
    return 0;
}

/* The dilute values o carried to packing fraction eta (3-D spheres) as relcol-eos measures
 * them: Enskog's factors with the kernel's own linear terms,
 *     eta:    1/chi + 2 alpha_eta b n + 0.7614 (b n)^2 chi,
 *     lambda: r^2/chi + 2 r alpha_lambda b n + 0.7574 (b n)^2 chi,
 * r = h'/h: the measured heat moment subtracts the gas's enthalpy h' = <E> + Z kT (its
 * measured pressure), the dilute theory h = <E> + kT, and modulo the (zero) total momentum
 * the single-ball current (E - h') v = c^2 p - h' v is h'/h times (E - h) v -- at finite c
 * v is no collision invariant, so the enthalpy's density correction scales the kinetic
 * part (classically r = 1). The (b n)^2 terms are the classical ones (below 1 % at
 * packing 0.02). papers/transport.md, section 4. */
static inline void tr_shear_heat_enskog(const tr_shear_heat *o, double c, double kT,
                                        double eta, double *eta_s, double *lambda)
{
    const double bn = 4.0 * eta, chi = eos_chi(3, eta), z = eos_z_kolafa(eta);
    double r = 1.0;
    if (!isinf(c)) {
        const double e = c * c * jt_mean_gamma(3, kT / (c * c)); /* <E>, rest energy in */
        r = (e + z * kT) / (e + kT);
    }
    *eta_s = o->eta * (1.0 / chi + 2.0 * o->alpha_eta * bn + 0.7614 * bn * bn * chi);
    *lambda = o->lambda * (r * r / chi + 2.0 * r * o->alpha_lambda * bn + 0.7574 * bn * bn * chi);
}

#endif
