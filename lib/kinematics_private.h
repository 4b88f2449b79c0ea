/* kinematics_private.h — internal helpers shared by the library's own files. */
#ifndef RELCOL_KINEMATICS_PRIVATE_H
#define RELCOL_KINEMATICS_PRIVATE_H

#include "relcol/kinematics.h"

/* Boost with a precomputed Lorentz factor g of w (no |w| < c check). */
void rc_boost_g(rc_vec3 w, double g, double inv_c2, rc_four *a);

/* The same, inlined for the contact frames' kernels (which boost several events of one
 * pair): rc_boost_g is this, so both give the same bits. */
static inline void rc_boost_g_(rc_vec3 w, double g, double inv_c2, rc_four *a)
{
    /* (g - 1)/w^2 = g^2 inv_c2 / (g + 1): exact at w = 0 and for inv_c2 = 0 */
    const double k = g * g * inv_c2 / (g + 1.0);
    const double xw = rc_v3_dot(a->x, w);
    const double t = a->t;
    a->t = g * (t - xw * inv_c2);
    a->x = rc_v3_axpy(a->x, k * xw - g * t, w);
}

#endif
