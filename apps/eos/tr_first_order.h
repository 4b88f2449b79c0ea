/* tr_first_order.h — Chapman–Enskog self-diffusion of relcol's uncontracted-sphere kernel
 * at any c, by Monte Carlo over independent Jüttner pairs. The tagged ball's deviation
 * phi solves L phi = v_x (L its collision operator); on the trial function p_x alone
 *     D_1 = <p_x v_x>^2 / <p_x L p_x> = (kT)^2 / ((n/3) <sigma_T |v0 - v1| p0.(p0 - p0')>),
 * sigma_T = pi sigma^2 swept by the table-frame relative velocity (the sphere frame's
 * rate) and p0' from the zmf law along the table-frame contact normal: classically this is
 * Chapman & Cowling's first approximation 3/(8 n sigma^2) sqrt(kT/(pi m)). On {p_x, v_x}
 * (Galerkin) the second function carries the speed dependence that p_x lacks at finite c
 * (as theta -> 0, v - p ~ p^3: the second Sonine term). This is the model's own kinetic
 * theory, not the constant-cross-section hard sphere of Cercignani & Kremer, whose rate is
 * the invariant Møller flux: papers/transport.md, section 4. Units: sigma = m = 1. */
#ifndef RELCOL_TR_FIRST_ORDER_H
#define RELCOL_TR_FIRST_ORDER_H

#include <math.h>
#include <stdint.h>

#include "relcol/kinematics.h"
#include "relcol/law.h"
#include "relcol/rng.h"

/* A Jüttner (finite c) or Maxwell (c = inf) momentum at temperature kT, m = 1. Finite c:
 * the kinetic energy K = gamma - 1 has density ~ (K + 1) sqrt(K (K + 2)) e^(-K/theta),
 * below 2 (sqrt K + K^2) e^(-K/theta): draw from that mixture of Gamma(3/2, theta) and
 * Gamma(3, theta) and accept by the ratio (at least half the draws, at every theta). */
static inline rc_vec3 tr_draw_momentum(rc_rng *r, double c, double kT)
{
    if (isinf(c))
        return rc_v3(sqrt(kT) * rc_rng_gauss(r), sqrt(kT) * rc_rng_gauss(r),
                     sqrt(kT) * rc_rng_gauss(r));
    const double theta = kT / (c * c);
    const double w1 = 0.5 * sqrt(M_PI) * theta * sqrt(theta), w2 = 2.0 * theta * theta * theta;
    double K;
    for (;;) {
        if (rc_rng_uniform(r) * (w1 + w2) < w1) {
            const double z = rc_rng_gauss(r);
            K = theta * (-log(1.0 - rc_rng_uniform(r)) + 0.5 * z * z);
        } else {
            K = -theta * log((1.0 - rc_rng_uniform(r)) * (1.0 - rc_rng_uniform(r)) *
                             (1.0 - rc_rng_uniform(r)));
        }
        if (K > 0.0 && rc_rng_uniform(r) * 2.0 * (sqrt(K) + K * K) <=
                           (K + 1.0) * sqrt(K * (K + 2.0)))
            break;
    }
    const double q = sqrt(K * (K + 2.0));
    const double z = 2.0 * rc_rng_uniform(r) - 1.0, ph = 2.0 * M_PI * rc_rng_uniform(r);
    const double s = sqrt(1.0 - z * z);
    return rc_v3(q * c * s * cos(ph), q * c * s * sin(ph), q * c * z);
}

/* n D for the sphere kernel and the zmf law at speed of light c (INFINITY: classical) and
 * temperature kT, from `samples` independent pairs in 10 batches (*se: the batches'
 * standard error). nfun = 1: the trial function p_x alone (the first approximation
 * above); nfun = 2: the Galerkin solution on {p_x, v_x}, D = b^T A^-1 b with
 * A_ij = <psi_i L psi_j>, b_i = <psi_i v_x> -- the two agree classically (v = p / m), and
 * their difference at finite c measures how far one moment is from converged. Returns 0,
 * or -1 on a failed collision or bad arguments. D = result / n, / chi at finite density. */
static inline int tr_nd_sphere(double c, double kT, int nfun, long samples, uint64_t seed,
                               double *nd, double *se)
{
    enum { NBATCH = 10 };
    if (nfun < 1 || nfun > 2 || samples < 10 * NBATCH || !(kT > 0.0))
        return -1;
    if (isinf(c))
        nfun = 1; /* v = p / m: the second function adds nothing and A is singular */
    rc_rng r = {seed};
    rc_collision_params prm = rc_collision_params_default();
    prm.c = c;
    const double k = isinf(c) ? 0.0 : 1.0 / (c * c);
    const long per = samples / NBATCH;
    double est[NBATCH];
    for (int bt = 0; bt < NBATCH; bt++) {
        double A[2][2] = {{0.0, 0.0}, {0.0, 0.0}}, vv = 0.0;
        for (long i = 0; i < per; i++) {
            rc_particle a = {1.0, tr_draw_momentum(&r, c, kT)};
            rc_particle b = {1.0, tr_draw_momentum(&r, c, kT)};
            const rc_vec3 v0 = rc_velocity(a.m, a.p, k);
            const rc_vec3 w = rc_v3_sub(v0, rc_velocity(b.m, b.p, k));
            vv += rc_v3_dot(v0, v0);
            const double g = rc_v3_norm(w);
            if (!(g > 0.0))
                continue;
            /* impact point uniform on the unit disc across w; contact normal from a to b */
            const rc_vec3 e = rc_v3_scale(1.0 / g, w);
            const rc_vec3 t0 = fabs(e.x) < 0.9 ? rc_v3(1, 0, 0) : rc_v3(0, 1, 0);
            const rc_vec3 c1 = rc_v3_cross(e, t0);
            const rc_vec3 u1 = rc_v3_unit(c1, rc_v3_norm(c1)), u2 = rc_v3_cross(e, u1);
            const double rb = sqrt(rc_rng_uniform(&r)), ph = 2.0 * M_PI * rc_rng_uniform(&r);
            const rc_vec3 bv = rc_v3_add(rc_v3_scale(rb * cos(ph), u1), rc_v3_scale(rb * sin(ph), u2));
            const rc_vec3 nrm = rc_v3_add(bv, rc_v3_scale(sqrt(fmax(0.0, 1.0 - rb * rb)), e));
            const rc_vec3 p0 = a.p;
            if (rc_collide(&rc_law_zmf, &prm, &a, &b, nrm) != 0)
                return -1;
            const rc_vec3 psi[2] = {p0, v0};
            const rc_vec3 dpsi[2] = {rc_v3_sub(p0, a.p), rc_v3_sub(v0, rc_velocity(a.m, a.p, k))};
            for (int i = 0; i < 2; i++)
                for (int j = 0; j < 2; j++)
                    A[i][j] += g * rc_v3_dot(psi[i], dpsi[j]);
        }
        /* per unit density, per Cartesian component: sigma_T / 3 */
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++)
                A[i][j] *= M_PI / 3.0 / (double)per;
        const double b0 = kT, b1 = vv / (3.0 * (double)per);
        if (nfun == 1) {
            est[bt] = b0 * b0 / A[0][0];
        } else {
            const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
            /* b^T A^-1 b */
            est[bt] = (b0 * (A[1][1] * b0 - A[0][1] * b1) + b1 * (-A[1][0] * b0 + A[0][0] * b1)) / det;
        }
    }
    double m = 0.0, s2 = 0.0;
    for (int bt = 0; bt < NBATCH; bt++)
        m += est[bt] / NBATCH;
    for (int bt = 0; bt < NBATCH; bt++)
        s2 += (est[bt] - m) * (est[bt] - m);
    *nd = m;
    *se = sqrt(s2 / (NBATCH * (NBATCH - 1.0)));
    return 0;
}

#endif
