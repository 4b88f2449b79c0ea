/* engine/approach.h — whether two balls at separation dx (from ball i to ball k) approach
 * each other, as group forming and the simultaneity checks ask it: dx.(vk - vi) < 0, by
 * more than approach_tol times the radius sum per unit of relative speed (a grazing pair
 * is not a contact). */
#ifndef RELCOL_ENGINE_APPROACH_H
#define RELCOL_ENGINE_APPROACH_H

#include <math.h>

#include "relcol/kinematics.h"
#include "../pair_axis.h"

/* Ball i (rest mass and momentum bi, stored velocity vi = p/M) and ball k; k = 1/c^2,
 * sig the radius sum, atol approach_tol. 1 when approaching; *dv2 (if asked) |vk - vi|^2.
 *
 * For two balls moving fast the same way (both Lorentz factors above RC_GAMMA_FAST, a ZMF
 * above RC_PAIR_FAST: pair_axis.h's test) the stored velocities differ along their motion
 * by 1/gamma^2 of either, below their rounding, and with a row of balls along the motion
 * the approach's sign is lost. There vi - vk = d / mu, mu = Mi Mk/Mt, with d = (Mk pi -
 * Mi pk)/Mt from the momenta without cancellation (rc_pair_split_of) and its part along
 * n = dx/|dx| the zmf law's a0 (rc_pair_a0_fast): the test dx.(vk - vi) < 0 with
 * (dx.(vk - vi))^2 > atol^2 sig^2 |vk - vi|^2 is |dx| a0 > 0 with |dx|^2 a0^2 > atol^2
 * sig^2 |d|^2 (mu cancels). Other pairs keep the plain form and its bits.
 *
 * eng_approach_fast: the verdict for such a pair, -1 for any other (the caller keeps its
 * plain form); eng_approaching: either. */
static inline int eng_approach_fast(double k, const rc_particle *bi, rc_vec3 vi,
                                    const rc_particle *bk, rc_vec3 vk, rc_vec3 dx, double sig,
                                    double atol, double *dv2)
{
    /* (a cheap first test on the stored velocities: a Lorentz factor above 3 is a speed
     * above 0.94 c) */
    const int fast = rc_v3_norm2(vi) * k > 0.8 && rc_v3_norm2(vk) * k > 0.8;
    const double Mi = fast ? sqrt(bi->m * bi->m + rc_v3_norm2(bi->p) * k) : 0.0;
    const double Mk = fast ? sqrt(bk->m * bk->m + rc_v3_norm2(bk->p) * k) : 0.0;
    const double Mt = Mi + Mk, d2 = rc_v3_norm2(dx);
    if (!(fast && Mi > RC_GAMMA_FAST * bi->m && Mk > RC_GAMMA_FAST * bk->m &&
          rc_v3_dot(bi->p, bk->p) > 0.0 &&
          rc_v3_norm2(rc_v3_add(bi->p, bk->p)) * k > RC_PAIR_FAST * Mt * Mt && d2 > 0.0))
        return -1;
    const double sqrt_k = sqrt(k);
    rc_pair_split z;
    rc_pair_split_of(bi, bk, Mi, Mk, k, sqrt_k, &z);
    const double z2 = rc_v3_norm2(z.d);
    if (dv2) {
        const double f = Mt / (Mi * Mk);
        *dv2 = z2 * f * f;
    }
    const rc_vec3 n = rc_v3_scale(1.0 / sqrt(d2), dx);
    const double pni = rc_v3_dot(bi->p, n), pnk = rc_v3_dot(bk->p, n);
    const rc_axis ax = rc_axis_along(bi, bk, n, k, Mi, Mk, pni, pnk);
    const double a0 = rc_pair_a0_fast(bi, bk, n, k, sqrt_k, &ax);
    return a0 > 0.0 && d2 * a0 * a0 > atol * atol * sig * sig * z2;
}

static inline int eng_approaching(double k, const rc_particle *bi, rc_vec3 vi,
                                  const rc_particle *bk, rc_vec3 vk, rc_vec3 dx, double sig,
                                  double atol, double *dv2)
{
    const int f = eng_approach_fast(k, bi, vi, bk, vk, dx, sig, atol, dv2);
    if (f >= 0)
        return f;
    const rc_vec3 dv = rc_v3_sub(vk, vi);
    const double bb = rc_v3_dot(dx, dv), w2 = rc_v3_norm2(dv);
    if (dv2)
        *dv2 = w2;
    return bb < 0.0 && bb * bb > atol * atol * sig * sig * w2;
}

#endif
