/* gravity_util.h — what the gravity tests share: random balls in a field, and Hamilton's
 * equations of each coupling integrated by GSL's rk8pd, a reference that knows nothing of
 * the closed forms it checks. */
#ifndef GRAVITY_UTIL_H
#define GRAVITY_UTIL_H

#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "rc_test.h"
#include "relcol/relcol.h"
#include "relcol/gravity.h"

typedef struct grav_ode {
    const rc_gravity *f;
    double m;
    int equivalence; /* 0: dp/dt = -m g; 1: H = (1 + g z/c^2) c^2 M(p) */
} grav_ode;

static int grav_rhs(double t, const double y[], double dy[], void *par)
{
    (void)t;
    const grav_ode *o = par;
    const double i2 = o->f->inv_c2, g = o->f->g;
    const rc_vec3 p = rc_v3(y[3], y[4], y[5]);
    const double M = rc_mass_rel(o->m, p, i2);
    const double z = y[o->f->axis];
    const double l = o->equivalence ? 1.0 + g * z * i2 : 1.0;
    for (int k = 0; k < 3; k++) {
        dy[k] = l * y[3 + k] / M;
        dy[3 + k] = 0.0;
    }
    dy[3 + o->f->axis] = o->equivalence ? -g * M : -o->m * g;
    return GSL_SUCCESS;
}

/* The reference path: x, p after dt, by rk8pd to a relative 1e-14 per step. */
static inline int grav_integrate(const rc_gravity *f, int equivalence, double m, rc_vec3 *x,
                                 rc_vec3 *p, double dt)
{
    grav_ode o = {f, m, equivalence};
    gsl_odeiv2_system sys = {grav_rhs, NULL, 6, &o};
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, 1e-16, 1e-14);
    double y[6] = {x->x, x->y, x->z, p->x, p->y, p->z}, t = 0.0;
    const int st = gsl_odeiv2_driver_apply(d, &t, dt, y);
    gsl_odeiv2_driver_free(d);
    *x = rc_v3(y[0], y[1], y[2]);
    *p = rc_v3(y[3], y[4], y[5]);
    return st;
}

/* a vector with each component uniform in [-h, h] */
static inline rc_vec3 grav_cube(rc_test_rng *r, double h)
{
    return rc_v3(rc_test_range(r, -h, h), rc_test_range(r, -h, h), rc_test_range(r, -h, h));
}

/* Brute force: the first t in (0, tmax] where fn changes sign from its sign at 0, found on
 * `samples` equal steps and bisected to a rounding; -1 when it does not. */
static inline double grav_first_change(double (*fn)(double t, void *ctx), void *ctx,
                                       double tmax, int samples)
{
    const int pos0 = fn(0.0, ctx) > 0.0;
    double lo = 0.0;
    for (int i = 1; i <= samples; i++) {
        const double t = tmax * i / samples, s = fn(t, ctx);
        if ((s > 0.0) != pos0 || s == 0.0) {
            double hi = t;
            for (int j = 0; j < 200 && hi - lo > 1e-16 * hi; j++) {
                const double mid = 0.5 * (lo + hi), sm = fn(mid, ctx);
                if ((sm > 0.0) == pos0 && sm != 0.0)
                    lo = mid;
                else
                    hi = mid;
            }
            return hi;
        }
        lo = t;
    }
    return -1.0;
}

/* A ball above the floor: height in (0, zmax), momentum up to pmax in each component. */
static inline void grav_random_ball(rc_test_rng *r, int axis, double zmax, double pmax,
                                    double *m, rc_vec3 *x, rc_vec3 *p)
{
    *m = rc_test_range(r, 0.5, 2.0);
    *x = grav_cube(r, 3.0);
    rc_v3_set(x, axis, rc_test_range(r, 0.01, zmax));
    *p = rc_v3_scale(*m, grav_cube(r, pmax));
}

#endif
