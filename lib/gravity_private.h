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

/* A time step: RC_ENONFINITE for NaN or infinite, RC_EINVAL for a negative one. */
int rc_gravity_arg_dt_(double dt);
/* A plane x_k = X and the output: RC_EINVAL for k outside 0..2 or no output, RC_ENONFINITE
 * for an X that is not finite. */
int rc_gravity_arg_plane_(int k, double X, const double *dt);
/* A drift's result into *x, *p when it is finite (RC_ENONFINITE, nothing written, if not). */
int rc_gravity_put_(rc_vec3 *x, rc_vec3 *p, rc_vec3 xn, rc_vec3 pn);

/* The smallest root > 0 of a t^2 + b t + c0 = 0 (a != 0), without the cancellation of the
 * textbook formula; RC_MISS when there is none. */
int rc_gravity_first_root_(double a, double b, double c0, double *t);

/* The balls of a pair query, the field and the horizon: RC_ERADIUS for a radius <= 0,
 * RC_EINVAL for t_max < 0 or NaN (t_max may be INFINITY) or no output. */
int rc_gravity_pair_check_(const rc_gravity *f, const rc_toi_ball *a, const rc_toi_ball *b,
                           double t_max, const double *dt);

/* Overlap beyond this share of (r_a + r_b)^2 at the start is RC_EOVERLAP; within it, a pair
 * counts as touching (the engine's positions are themselves computed). */
#define RC_GRAVITY_TOUCH 1e-12

/* The smallest s in (lo, hi] where the polynomial c[0] + c[1] s + ... + c[deg] s^deg
 * (deg <= 4) falls from > 0 to <= 0, by its monotone pieces between the roots of its
 * derivatives; RC_MISS when it does not fall there. */
int rc_gravity_poly_first_fall_(const double *c, int deg, double lo, double hi, double *s);

/* The engine's proper-time books (lib/engine/path.c): newtonian, the integral of dt/M
 * over a drift of dt (x_perp moves by p_perp times it); equivalence, the time t' the drift
 * spends on the ball's straight line in the box's momentary rest frame at its start. The
 * same expressions as the drifts'; the field and ball already checked. */
double rc_gravity_newton_flight_(const rc_gravity *f, double m, rc_vec3 p, double dt);
double rc_gravity_equiv_flight_(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p, double dt);

#endif
