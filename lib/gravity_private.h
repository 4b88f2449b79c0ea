/* gravity_private.h — the checks and the small even functions that both couplings of a
 * uniform field share (papers/gravity.md section 2). */
#ifndef RELCOL_GRAVITY_PRIVATE_H
#define RELCOL_GRAVITY_PRIVATE_H

#include <math.h>

#include "relcol/gravity.h"
#include "relcol/status.h"

/* sinh(x)/x, tanh(x)/x, asinh(x)/x, atanh(x)/x: 1 at x = 0, where c = INFINITY puts them */
static inline double grav_sinhc(double x) { return x == 0.0 ? 1.0 : sinh(x) / x; }
static inline double grav_tanhc(double x) { return x == 0.0 ? 1.0 : tanh(x) / x; }
static inline double grav_asinhc(double x) { return x == 0.0 ? 1.0 : asinh(x) / x; }
static inline double grav_atanhc(double x) { return x == 0.0 ? 1.0 : atanh(x) / x; }

/* The field and one ball: RC_EINVAL for a field that is not one (g <= 0, axis outside
 * 0..2, inv_c2 < 0), RC_EMASS for m <= 0, RC_ENONFINITE for a NaN or infinite input. */
int rc_gravity_check_(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p);

/* The smallest root > 0 of a t^2 + b t + c0 = 0 (a != 0), without the cancellation of the
 * textbook formula; RC_MISS when there is none. */
int rc_gravity_first_root_(double a, double b, double c0, double *t);

#endif
