/* law_heat.c — heat of a two-ball collision, sum (m' - m) c^2, computed without the
 * cancellation of subtracting nearly equal rest masses, from zero-momentum-frame momenta. */
#include <math.h>
#include "relcol/law.h"
#include "relcol/status.h"
#include "pair_axis.h"

/* For a law that keeps each ball's energy in the pair's ZMF (zmf, cm-isotropic, elastic),
 * m'^2 - m^2 = (|pbar|^2 - |pbar'|^2) / c^2, hence
 *   (m' - m) c^2 = (|pbar|^2 - |pbar'|^2) / (m' + m),
 * a difference of O(1) momenta instead of O(c^2) times a difference of masses. The ZMF is
 * the one of `before` (the same as after's when momentum and energy are conserved). */
double rc_pair_heat(const rc_particle before[2], const rc_particle after[2], double inv_c2,
                    double q_ball[2])
{
    double q = 0.0, qi[2] = {NAN, NAN};
    rc_vec3 u;
    if (!(inv_c2 >= 0.0 && isfinite(inv_c2)))
        goto out;
    for (int i = 0; i < 2; i++)
        if (rc_particle_check(&before[i]) != RC_OK || rc_particle_check(&after[i]) != RC_OK)
            goto out;
    if (rc_zmf(before, 2, inv_c2, &u, NULL) != RC_OK)
        goto out;
    if (rc_v3_norm2(u) * inv_c2 > RC_PAIR_FAST) {
        /* A ZMF moving near c: the boost's p - gamma M u + ... cancels to order gamma^2 (and
         * rc_boost refuses |u| >= c, which the rounded u reaches by gamma ~ 1e8). Both balls'
         * ZMF momenta have one length, |t0|^2 + (gamma dl)^2 (pair_axis.h, rc_pair_split_of),
         * formed without it; the after states in their own ZMF, the before states' when
         * energy and momentum are conserved. */
        const double sk = sqrt(inv_c2);
        double pb2[2];
        for (int s = 0; s < 2; s++) {
            const rc_particle *x = s ? after : before;
            rc_pair_split z;
            rc_pair_split_of(&x[0], &x[1], rc_mass_rel(x[0].m, x[0].p, inv_c2),
                             rc_mass_rel(x[1].m, x[1].p, inv_c2), inv_c2, sk, &z);
            pb2[s] = rc_v3_norm2(z.t0) + (z.g * z.dl) * (z.g * z.dl);
        }
        for (int i = 0; i < 2; i++) {
            qi[i] = (pb2[0] - pb2[1]) / (after[i].m + before[i].m);
            q += qi[i];
        }
        if (q_ball) {
            q_ball[0] = qi[0];
            q_ball[1] = qi[1];
        }
        return q;
    }
    for (int i = 0; i < 2; i++) {
        rc_four a = rc_particle_four(&before[i], inv_c2), b = rc_particle_four(&after[i], inv_c2);
        if (rc_boost(u, inv_c2, &a) != RC_OK || rc_boost(u, inv_c2, &b) != RC_OK)
            goto out;
        qi[i] = (rc_v3_norm2(a.x) - rc_v3_norm2(b.x)) / (after[i].m + before[i].m);
        q += qi[i];
    }
    if (q_ball) {
        q_ball[0] = qi[0];
        q_ball[1] = qi[1];
    }
    return q;
out:
    if (q_ball)
        q_ball[0] = q_ball[1] = NAN;
    return NAN;
}
