/* relcol/gravity.h — a ball's free path in a uniform gravitational field, one table entry
 * per coupling of the field to the ball (papers/gravity.md).
 *
 * The field points along -e_axis with acceleration g at the floor (coordinate 0 on that
 * axis). `newtonian`: dp/dt = -m g e_axis in the table frame, clock t, conserved
 * H = E + m g z. `equivalence`: the box frame of a floor with proper acceleration g
 * (Rindler), clock tau = the floor's proper time, conserved H = (1 + g z/c^2) E with E
 * the local energy. Classically (inv_c2 = 0) both are the same parabola. A coupling need
 * not live in the library: any `const rc_gravity_coupling` with these three operations
 * serves. Every operation checks its inputs and returns a status code. */
#ifndef RELCOL_GRAVITY_H
#define RELCOL_GRAVITY_H

#include "relcol/kinematics.h"
#include "relcol/toi.h"
#include "relcol/vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/// The field: acceleration at the floor, its axis, and 1/c^2.
typedef struct rc_gravity {
    double g;      ///< acceleration at the floor, > 0 and finite (length / time^2)
    int axis;      ///< the field's axis, 0..2; the field points along -e_axis
    double inv_c2; ///< 1/c^2 >= 0 (rc_inv_c2); 0 is classical
} rc_gravity;

/// A coupling: free motion, plane crossings and the conserved energy of one ball.
typedef struct rc_gravity_coupling {
    const char *name;    ///< "newtonian", "equivalence"
    const char *summary; ///< one line for listings
    /// Moves the ball (rest mass m, position x, momentum p) along its free path for dt >= 0
    /// of the coupling's clock; x and p are changed only on RC_OK.
    int (*drift)(const rc_gravity *f, double m, rc_vec3 *x, rc_vec3 *p, double dt);
    /// Earliest dt > 0 at which coordinate k of the ball equals X (RC_MISS: never).
    int (*plane_time)(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p, int k, double X,
                      double *dt);
    /// The conserved energy minus the rest energy m c^2 (finite classically), in *h.
    int (*energy)(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p, double *h);
    /// Earliest dt in [0, t_max] at which two balls touch as spheres of their rest radii at
    /// one instant of the coupling's clock (0: touching and approaching now). RC_MISS: none
    /// by t_max; RC_EOVERLAP: overlapping by more than 1e-12 of r_a + r_b now.
    int (*pair_time)(const rc_gravity *f, const rc_toi_ball *a, const rc_toi_ball *b,
                     double t_max, double *dt);
} rc_gravity_coupling;

extern const rc_gravity_coupling rc_gravity_newtonian;
extern const rc_gravity_coupling rc_gravity_equivalence;
/// The built-in couplings, NULL-terminated.
extern const rc_gravity_coupling *const rc_gravity_couplings[];
/// Coupling by name; NULL if unknown.
const rc_gravity_coupling *rc_gravity_find(const char *name);

#ifdef __cplusplus
}
#endif
#endif
