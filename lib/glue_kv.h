/* glue_kv.h — 1 - kappa.v_in for a glued tube's hyperplane H (normal u_in + u_out,
 * kappa = (g0 v0 + g1 v1) / (c^2 (g0 + g1)), g = M / m; papers/shape-change.md): the
 * denominator of every time where H meets the incoming worldline (the centre's kink, the
 * glue window). Private to the library (toi_glue.c, the engine's kink time).
 *
 * When the ball moves near c before and after the same way, kappa.v_in is 1 - O(1/gamma^2)
 * and the plain difference keeps only the rounding of its terms: at gamma ~ 1e8 no digit.
 * Written per ball, 1 - kappa.v0 = (g0 (1 - v0.v0/c^2) + g1 (1 - v1.v0/c^2)) / (g0 + g1)
 * with 1 - v0.v0/c^2 = (m0/M0)^2 and M0 M1 (1 - v0.v1/c^2) = rc_pair_dot (pair_axis.h,
 * free of the cancellation), so
 *   1 - kappa.v0 = (m0 + rc_pair_dot(0, 1) / m1) / (M0 W0),  W0 = g0 + g1,
 * a sum of positive terms. */
#ifndef RELCOL_GLUE_KV_H
#define RELCOL_GLUE_KV_H

#include <math.h>

#include "relcol/kinematics.h"
#include "relcol/toi.h"
#include "pair_axis.h"

/* Below this kappa.v_in the plain form loses at most ten bits (a relative error ~1e-13)
 * and is kept with its bits; above it the form above (a few times the cost). */
#define RC_GLUE_KV_FAST (1.0 - 0x1p-10)

/* 1 - kappa.v_in, kv the plain kappa.v_in; M0, M1 the energies over c^2 of in and out,
 * W0 = M0/m0 + M1/m1, k = 1/c^2. */
static inline double rc_glue_one_minus_kv(double k, const rc_particle *in, double M0,
                                          const rc_particle *out, double M1, double W0,
                                          double kv)
{
    if (!(kv > RC_GLUE_KV_FAST))
        return 1.0 - kv;
    const double d01 = rc_pair_dot(in->m, in->p, M0, out->m, out->p, M1, k, sqrt(k));
    return (in->m + d01 / out->m) / (M0 * W0);
}

/* 1 - kappa.v_out for a tube's H from its table-frame shapes (g = 1/gamma, g2, beta =
 * v/c: relcol/toi.h), the ball's velocity after the kink: with x = out above,
 *   1 - kappa.v1 = (gamma0 (1 - beta0.beta1) + 1/gamma1) / (gamma0 + gamma1),
 *   1 - beta0.beta1 = (|beta0 - beta1|^2 + 1/gamma0^2 + 1/gamma1^2) / 2,
 * positive terms again. beta0 - beta1 is rounded to ~2^-53 in each component, which moves
 * |beta0 - beta1|^2 by no more than a rounding of the momenta would. */
static inline double rc_glue_omkv_out(const rc_toi_shape *in, const rc_toi_shape *out)
{
    const double G0 = 1.0 / in->g, G1 = 1.0 / out->g;
    const double d2 = rc_v3_norm2(rc_v3_sub(in->beta, out->beta));
    return (G0 * 0.5 * (d2 + in->g2 + out->g2) + out->g) / (G0 + G1);
}

#endif
