/* kinematics_private.h — internal helpers shared by the library's own files. */
#ifndef RELCOL_KINEMATICS_PRIVATE_H
#define RELCOL_KINEMATICS_PRIVATE_H

#include "relcol/kinematics.h"

/* Boost with a precomputed Lorentz factor g of w (no |w| < c check). */
void rc_boost_g(rc_vec3 w, double g, double inv_c2, rc_four *a);

#endif
