/* engine/pairs.h — the separation of two balls and the contact time of their bounding
 * spheres, for one pair: the narrow phase's broad test and its simultaneity checks. The
 * scan over a ball's neighbours does the same operations in lanes (engine/kernels.h:
 * pair_lanes), so that a pair's time is the same bits whichever path asks. */
#ifndef RELCOL_ENGINE_PAIRS_H
#define RELCOL_ENGINE_PAIRS_H

#include <math.h>
#include <stdint.h>

#include "private.h"

/* Separation bk - bi at the later of the two balls' clocks, *tref: the earlier ball is
 * advanced, so the result depends only on the two stored states. The nearest image in a
 * periodic box. */
static inline rc_vec3 pair_sep(const rc_sim *s, const eng_ball *bi, const eng_ball *bk,
                               double *tref)
{
    if (bi->t >= bk->t) {
        *tref = bi->t;
        return eng_image(s, rc_v3_sub(rc_v3_axpy(bk->x, bi->t - bk->t, bk->v), bi->x));
    }
    *tref = bk->t;
    return eng_image(s, rc_v3_sub(bk->x, rc_v3_axpy(bi->x, bk->t - bi->t, bi->v)));
}

/* Contact time of the bounding spheres of bi and bk, from their separation dx (d2 = |dx|^2)
 * at time tref, as an absolute time >= now; INFINITY on a miss or when it cannot beat
 * `best`. It depends only on the two stored states (the same bits whichever ball asks). */
static inline double sphere_time_dx(const rc_sim *s, const eng_ball *bi, const eng_ball *bk,
                                    rc_vec3 dx, double d2, double tref, double best)
{
    const rc_vec3 dv = rc_v3_sub(bk->v, bi->v);
    const double b = rc_v3_dot(dx, dv);
    const double sig = bi->r + bk->r;
    const double dd = d2 - sig * sig;
    const double dv2 = rc_v3_norm2(dv);
    const double disc = b * b - dv2 * dd;
    const double tol = s->def.approach_tol * sig;
    /* One combined, mostly-taken test rejects most neighbours before the sqrt and the
     * division: not approaching (b >= 0); touching but not really approaching; roots not
     * real; or not able to beat `best` (sqrt(disc) <= -b gives t >= dd / (-2 b)). The
     * root itself is dd / (-b + sqrt(disc)), free of cancellation. */
    const int touching = dd <= 0.0;
    const int hit = (b < 0.0) & (touching ? b * b > tol * tol * dv2
                                          : (disc > 0.0) & (dd < -2.0 * b * (best - tref)));
    if (!hit)
        return INFINITY;
    const double t = touching ? 0.0 : dd / (sqrt(disc) - b);
    double ta = tref + t;
    if (ta < s->now)
        ta = s->now;
    return ta < best ? ta : INFINITY;
}

#endif
