/* relcol/kinematics.h — special-relativistic kinematics with c as a parameter: every
 * formula takes inv_c2 = 1/c^2, and inv_c2 = 0 is the exact classical case of the same
 * expression. A state is rest mass m and momentum p; M = sqrt(m^2 + p^2/c^2) and v = p/M
 * follow, so |v| < c by construction and nothing computes 1 - v^2/c^2. */
#ifndef RELCOL_KINEMATICS_H
#define RELCOL_KINEMATICS_H

#include <stddef.h>
#include "relcol/vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/// A ball's dynamical state.
typedef struct rc_particle {
    double m;  ///< rest mass > 0
    rc_vec3 p; ///< momentum
} rc_particle;

/// A four-vector as (time component / c, spatial part), so that c enters only through inv_c2.
typedef struct rc_four {
    double t;  ///< four-momentum: M = E/c^2; event: time; zmf contact normal: (u.n)/c^2
    rc_vec3 x; ///< four-momentum: p; event: position; zmf contact normal: n
} rc_four;

/// inv_c2 = 1/c^2 from c (INFINITY gives 0); RC_ESPEEDOFLIGHT unless c > 0 and 1/c^2 a finite non-zero double (or c = INFINITY).
int rc_inv_c2(double c, double *inv_c2);
/// The same 1/c^2 for a c already checked by an entry point (what kernels use).
double rc_inv_c2_of(double c);

/// M = E/c^2 = sqrt(m^2 + p^2/c^2); m when inv_c2 = 0.
double rc_mass_rel(double m, rc_vec3 p, double inv_c2);
/// gamma - 1 = (p^2/c^2) / (m (M + m)): no cancellation, exact 0 classically.
double rc_gamma_m1(double m, rc_vec3 p, double inv_c2);
/// gamma = M / m.
double rc_gamma(double m, rc_vec3 p, double inv_c2);
/// Kinetic energy (gamma - 1) m c^2 = p^2 / (M + m); p^2 / 2m classically.
double rc_kinetic_energy(double m, rc_vec3 p, double inv_c2);
/// Rapidity artanh(|v|/c) = asinh(|p| / (m c)), in units of c: 0 classically.
double rc_rapidity(double m, rc_vec3 p, double inv_c2);
/// Velocity p / M.
rc_vec3 rc_velocity(double m, rc_vec3 p, double inv_c2);

/// Lorentz factor of a velocity: RC_ESPEED if |v| >= c, RC_ENONFINITE for NaN/inf.
int rc_gamma_from_velocity(rc_vec3 v, double inv_c2, double *gamma);
/// p = m gamma(v) v; RC_ESPEED if |v| >= c, RC_EMASS if m <= 0.
int rc_momentum_from_velocity(double m, rc_vec3 v, double inv_c2, rc_vec3 *p);

/// Lorentz boost into the frame moving at w (|w| < c): t' = gamma (t - w.x/c^2), x' = x + [(gamma-1)/w^2 (x.w) - gamma t] w, exact as w -> 0 and c -> inf (Galilean classically).
int rc_boost(rc_vec3 w, double inv_c2, rc_four *a);
/// Velocity, seen from a frame moving at w, of a body moving at v (relativistic subtraction); RC_ESPEED if |v| or |w| >= c.
int rc_velocity_boost(rc_vec3 v, rc_vec3 w, double inv_c2, rc_vec3 *out);
/// The inverse: the table velocity of a body moving at v' in the frame moving at w.
int rc_velocity_add(rc_vec3 w, rc_vec3 vprime, double inv_c2, rc_vec3 *out);

/// Four-momentum (M, p) of a particle.
rc_four rc_particle_four(const rc_particle *b, double inv_c2);

/// ZMF velocity u = sum p / sum M and invariant mass (either may be NULL) of n particles, the mass free of cancellation when the ZMF moves near c.
int rc_zmf(const rc_particle *b, size_t n, double inv_c2, rc_vec3 *u, double *minv);
/// Invariant mass of two particles, sqrt(m0^2 + m1^2 + 2 m0 m1 gamma_rel), a few roundings at any Lorentz factor (papers/zmf-law.md section 10).
double rc_pair_invariant_mass(const rc_particle *a, const rc_particle *b, double inv_c2);

/// Validate a particle: finite momentum, 0 < m < inf.
int rc_particle_check(const rc_particle *b);

#ifdef __cplusplus
}
#endif
#endif
