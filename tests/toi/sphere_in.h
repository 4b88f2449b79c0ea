/* sphere_in.h — the classical reference the glued-tube tests check their limit against
 * (test_glue.c, test_glue_pair.c): two unit spheres moving apart or together at a constant
 * relative velocity over an interval, their first touch by the quadratic. */
#ifndef RELCOL_TEST_SPHERE_IN_H
#define RELCOL_TEST_SPHERE_IN_H

#include <math.h>

#include "relcol/relcol.h"

/* First t in [a, b) with |d + w (t - a)| = 2 (two unit spheres), d at a; INFINITY if none
 * (apart at a). The root taken as C / (-B + sqrt(disc)), which does not cancel. */
static inline double sphere_in(double a, double b, rc_vec3 d, rc_vec3 w)
{
    const double A = rc_v3_norm2(w), B = rc_v3_dot(d, w), C = rc_v3_norm2(d) - 4.0;
    const double disc = B * B - A * C;
    if (!(A > 0.0) || !(B < 0.0) || disc < 0.0)
        return INFINITY;
    const double q = C / (-B + sqrt(disc));
    return a + q < b ? a + q : INFINITY;
}

#endif
