/* law_util.h — helpers shared by the tests in tests/law: random vectors in 1-3 D, random
 * speeds of light, and an independent boost into a pair's ZMF (the tests' own reference
 * arithmetic, written from the textbook formula rather than calling rc_boost). */
#ifndef RC_LAW_UTIL_H
#define RC_LAW_UTIL_H

#include <float.h>
#include <math.h>

#include "rc_test.h"
#include "relcol/relcol.h"

/* A random unit vector in the first `dim` components (the rest exactly 0). */
static inline rc_vec3 lu_unit(rc_test_rng *r, int dim)
{
    for (;;) {
        rc_vec3 v = rc_v3(rc_test_range(r, -1, 1), dim > 1 ? rc_test_range(r, -1, 1) : 0.0,
                          dim > 2 ? rc_test_range(r, -1, 1) : 0.0);
        double n2 = rc_v3_norm2(v);
        if (n2 > 1e-4 && n2 <= 1.0)
            return rc_v3_scale(1.0 / sqrt(n2), v);
    }
}

/* A random vector of length in [0, len) in the first `dim` components. */
static inline rc_vec3 lu_vec(rc_test_rng *r, int dim, double len)
{
    return rc_v3_scale(len * rc_test_uniform(r), lu_unit(r, dim));
}

/* Log-uniform in [lo, hi]. */
static inline double lu_logu(rc_test_rng *r, double lo, double hi)
{
    return lo * exp(log(hi / lo) * rc_test_uniform(r));
}

static inline double lu_max(double a, double b) { return a > b ? a : b; }

/* Reference boost of the four-momentum (M, p) into the frame moving at u, in long double,
 * by the textbook formula  pbar = p + [(gamma-1)(p.u)/u^2 - gamma M] u,  Mbar = gamma
 * (M - p.u/c^2) — independent of the library's rc_boost. Classically pbar = p - M u. */
static inline void lu_boost_ref(rc_vec3 u, double inv_c2, double M, rc_vec3 p, double *Mbar,
                                rc_vec3 *pbar)
{
    long double k = inv_c2;
    long double ux = u.x, uy = u.y, uz = u.z, px = p.x, py = p.y, pz = p.z;
    long double u2 = ux * ux + uy * uy + uz * uz;
    long double g = 1.0L / sqrtl(1.0L - u2 * k);
    long double pu = px * ux + py * uy + pz * uz;
    /* (gamma - 1)/u^2 = gamma^2 k / (gamma + 1): exact at u = 0 and k = 0 */
    long double f = g * g * k / (g + 1.0L) * pu - g * (long double)M;
    *Mbar = (double)(g * ((long double)M - pu * k));
    *pbar = rc_v3((double)(px + f * ux), (double)(py + f * uy), (double)(pz + f * uz));
}

/* A random pair: masses log-uniform in [0.2, 5], speeds below 1 in `dim` dimensions, a
 * contact normal along which the balls approach at >= 0.1 of the faster speed (so heat
 * and deviations stay away from accidental zeros), restitution in [0.1, 0.9]. The
 * momenta b[].p are left for the caller to set at its c. */
typedef struct {
    rc_particle b[2];
    rc_vec3 v[2], n;
    double eps, vmax;
} lu_pair;

static inline void lu_random_pair(rc_test_rng *r, lu_pair *p, int dim)
{
    for (;;) {
        p->vmax = 0.0;
        for (int j = 0; j < 2; j++) {
            p->b[j].m = lu_logu(r, 0.2, 5.0);
            p->v[j] = lu_vec(r, dim, 1.0);
            p->vmax = lu_max(p->vmax, rc_v3_norm(p->v[j]));
        }
        p->n = lu_unit(r, dim);
        double dvn = rc_v3_dot(rc_v3_sub(p->v[0], p->v[1]), p->n);
        if (fabs(dvn) < 0.1 * p->vmax)
            continue; /* keep the heat and the deviations well away from accidental zeros */
        if (dvn < 0.0)
            p->n = rc_v3_scale(-1.0, p->n);
        p->eps = rc_test_range(r, 0.1, 0.9);
        return;
    }
}

#endif
