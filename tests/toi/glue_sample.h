/* glue_sample.h — the boundary samples of a contracted shape that the glued-tube tests
 * scan with rc_glue_inside (test_glue.c, test_glue_pair.c): nb directions on a circle
 * (2-D) or 6 nb on a Fibonacci lattice on the sphere (3-D), and the boundary point along
 * each; and the scan in time that finds the first contact from them. */
#ifndef RELCOL_TEST_GLUE_SAMPLE_H
#define RELCOL_TEST_GLUE_SAMPLE_H

#include <math.h>

#include "relcol/relcol.h"

/* the number of samples for nb in dimension dim */
static inline int glue_sample_count(int dim, int nb) { return dim == 3 ? 6 * nb : nb; }

/* the j-th of m unit directions */
static inline rc_vec3 glue_sample_dir(int dim, int j, int m)
{
    if (dim == 3) {
        const double z = 1.0 - (2.0 * j + 1.0) / m, a = j * M_PI * (3.0 - sqrt(5.0));
        const double q = sqrt(1.0 - z * z);
        return rc_v3(q * cos(a), q * sin(a), z);
    }
    const double a = 2.0 * M_PI * j / m;
    return rc_v3(cos(a), sin(a), 0.0);
}

/* the distance along unit u from the centre of shape sh to its boundary: the rest-frame
 * length of s u equals r */
static inline double glue_sample_reach(const rc_toi_shape *sh, rc_vec3 u)
{
    const double bu = rc_v3_dot(sh->beta, u);
    return sh->r / sqrt(1.0 + bu * bu / sh->g2);
}

/* The first time in (t0, T) at which meets(t, ctx) holds, found by a scan in steps of dt
 * and 30 bisections inside the first step that meets (to dt / 2^30); INFINITY if none.
 * The reference both glued-tube tests check their solvers' times against. */
static inline double glue_first_meet(double t0, double T, double dt,
                                     int (*meets)(double t, void *ctx), void *ctx)
{
    for (double s = t0 + dt; s < T; s += dt)
        if (meets(s, ctx)) {
            double lo = s - dt, hi = s;
            for (int b = 0; b < 30; b++) {
                const double mid = 0.5 * (lo + hi);
                if (meets(mid, ctx))
                    hi = mid;
                else
                    lo = mid;
            }
            return hi;
        }
    return INFINITY;
}

#endif
