/* soft_cases.h — two-ball scenarios shared by the soft tests and benchmark, and the
 * distance of a soft outcome from the hard zmf law. */
#ifndef SOFT_CASES_H
#define SOFT_CASES_H

#include <math.h>
#include "relcol/relcol.h"

/* Radii and rest masses used throughout (unequal on purpose: equal masses hide the
 * rest-mass split and the asymmetry of the ZMF energies). */
static const double soft_r[2] = {0.3, 0.4};
static const double soft_m[2] = {1.0, 2.0};

/* Two balls with table velocities v0, v1 whose centre lines pass at distance b (impact
 * parameter) at their closest approach, placed so that first touch comes at table time
 * ~1: x_i = x_E + v_i (t - t_E) with the meeting event moved sideways by b along a unit
 * vector orthogonal to v1 - v0. b = 0 makes the centre worldlines intersect, a head-on
 * collision in every frame. Returns 0 on success. */
static inline int soft_case(double inv_c2, rc_vec3 v0, rc_vec3 v1, double b, rc_particle p[2],
                     rc_vec3 x[2])
{
    p[0].m = soft_m[0];
    p[1].m = soft_m[1];
    if (rc_momentum_from_velocity(soft_m[0], v0, inv_c2, &p[0].p) != RC_OK ||
        rc_momentum_from_velocity(soft_m[1], v1, inv_c2, &p[1].p) != RC_OK)
        return 1;
    rc_vec3 w = rc_v3_sub(v1, v0);
    /* a unit vector orthogonal to w: w x z, or w x y if w is along z */
    rc_vec3 s = rc_v3_cross(w, rc_v3(0, 0, 1));
    if (rc_v3_norm(s) < 1e-3 * rc_v3_norm(w))
        s = rc_v3_cross(w, rc_v3(0, 1, 0));
    s = rc_v3_scale(1.0 / rc_v3_norm(s), s);
    /* centres meet (offset b) at table time tE = 1 + (r0 + r1)/|w| */
    const double tE = 1.0 + (soft_r[0] + soft_r[1]) / rc_v3_norm(w);
    x[0] = rc_v3_scale(-tE, v0);
    x[1] = rc_v3_axpy(rc_v3_scale(-tE, v1), b, s);
    return 0;
}

/* Largest relative difference of the outcomes a and h: momenta against the sum of the
 * incoming |p| (a momentum scale that does not vanish in the ZMF), rest masses against
 * themselves. */
static inline double soft_diff(const rc_particle a[2], const rc_particle h[2], double pscale)
{
    double e = 0.0;
    for (int i = 0; i < 2; i++) {
        e = fmax(e, rc_v3_norm(rc_v3_sub(a[i].p, h[i].p)) / pscale);
        e = fmax(e, fabs(a[i].m - h[i].m) / h[i].m);
    }
    return e;
}

/* Run the soft collision of (p, x) and the hard zmf law with the soft run's first contact
 * normal; *err = soft_diff. Returns the soft status (RC_OK), or RC_MISS if no contact. */
static inline int soft_vs_hard(const rc_soft_stepper *st, const rc_soft_params *prm,
                        const rc_particle p[2], const rc_vec3 x[2], rc_particle out[2],
                        double *err, rc_soft_result *res)
{
    rc_particle s[2] = {p[0], p[1]}, h[2] = {p[0], p[1]};
    rc_vec3 xx[2] = {x[0], x[1]};
    rc_soft_result rr;
    int code = rc_soft_collide(st, prm, 2, s, xx, soft_r, NULL, &rr);
    if (res)
        *res = rr;
    if (code != RC_OK)
        return code;
    if (rr.n_contacts == 0)
        return RC_MISS;
    rc_collision_params cp = rc_collision_params_default();
    cp.c = prm->c;
    cp.eps = prm->eps;
    code = rc_collide(&rc_law_zmf, &cp, &h[0], &h[1], rr.normal);
    if (code != RC_OK)
        return code;
    if (out) {
        out[0] = s[0];
        out[1] = s[1];
    }
    *err = soft_diff(s, h, rc_v3_norm(p[0].p) + rc_v3_norm(p[1].p));
    return RC_OK;
}

#endif
