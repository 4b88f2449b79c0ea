/* relcol/soft.h — the soft-sphere reference: balls with a stiff linear spring-dashpot on
 * their overlap, integrated under relativistic equations of motion (papers/soft-sphere.md).
 *
 * The contact force on ball i from ball j is the four-force -F (u.n/c^2, n), with n the
 * unit line of centres from i to j (spheres; see below for contracted shapes), u the
 * pair's zero-momentum velocity and
 *   F = kappa delta + eta d(delta)/dt,   delta = r_i + r_j - |x_j - x_i|  (while in contact).
 * It is orthogonal to the pair's total four-momentum, like the hard zmf law's impulse, so
 * the total four-momentum of the balls is conserved at every instant and the energy the
 * force takes from motion (elastic and dissipated) is internal energy U = (m - m_rest) c^2.
 * Equations of motion, per ball (state x, p, U):
 *   dx/dt = p / M,   dp/dt = sum -F n,   dU/dt = sum F a / m,
 *   a = p_i.n - M_i u.n,  m = m_rest + U/c^2,  M = sqrt(m^2 + p^2/c^2).
 * The integration runs in the zero-momentum frame of all the balls, where overlaps and
 * rates are measured (for two balls it is the pair's ZMF, in which the dynamics is exactly a
 * Newtonian oscillator with constant masses); the library boosts in and out. The dashpot is
 * set from the restitution eps by eta = 2 zeta sqrt(kappa mu*), zeta = rc_soft_damping_ratio
 * (eps), mu* the reduced mass of the pair's ZMF energies, so a two-ball head-on contact has
 * ZMF restitution exactly eps at any stiffness and the kappa -> inf limit is rc_law_zmf.
 *
 * Steppers are `const rc_soft_stepper` objects (CVODE BDF and GSL odeiv2 ones), listed in
 * rc_soft_steppers[] and found by name, as the collision laws are.
 *
 * Contact shapes (rc_soft_params.shape): RC_SOFT_SPHERE (default) takes each ball as the
 * uncontracted sphere of radius r in the integration frame. The contracted options take
 * it as the spheroid with semi-axis r/gamma along its own integration-frame velocity and r
 * across (for two balls: toi.h's "zmf" contact frame). Overlap and normal then come from
 * the Perram-Wertheim function of the two shapes: mu = scale factor to touch, n = the
 * common normal, delta = (n.d)(1 - mu)/mu = h_i(n) + h_j(n) - n.d (the normal depth;
 * r_i + r_j - |d| for spheres), rate (v_i - v_j).n. RC_SOFT_CONTRACTED_FROZEN keeps the
 * shapes a pair had at contact start: it converges to rc_law_zmf with the zmf-frame toi
 * normal, and is the reference. RC_SOFT_CONTRACTED lets the shapes follow the momenta
 * during the contact: it converges to a different limit, (v/c)^2 away, and for eps < 1
 * loses far more energy than eps says (papers/soft-sphere.md, section 7). At c = inf both
 * are the sphere model bit for bit. */
#ifndef RELCOL_SOFT_H
#define RELCOL_SOFT_H

#include <stddef.h>
#include "relcol/kinematics.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Shape of a ball in the integration frame (see the file comment). */
typedef enum rc_soft_shape {
    RC_SOFT_SPHERE = 0,    /* radius r: the uncontracted sphere (default) */
    RC_SOFT_CONTRACTED = 1, /* Lorentz-contracted along its integration-frame velocity */
    RC_SOFT_CONTRACTED_FROZEN = 2 /* contracted, but each contact keeps the shapes the
                                   * pair had when it started (the hard law's shapes) */
} rc_soft_shape;

/* Parameters of a soft run. Make one with rc_soft_params_default(). */
typedef struct rc_soft_params {
    double c;         /* speed of light, > 0; INFINITY (the default) is classical */
    double stiffness; /* kappa > 0: force per unit overlap (mass / time^2) */
    double eps;       /* restitution in (0, 1]: sets the dashpot (eps = 0 would never end) */
    double rtol;      /* relative tolerance of the stepper; absolute tolerances are rtol
                       * times the run's own scales (radius, momentum, kinetic energy) */
    double t_max;     /* stop after this much integration-frame time even if not done */
    long max_steps;   /* stepper steps allowed in the whole run (RC_ENOCONVERGE beyond) */
    rc_soft_shape shape; /* contact shapes; RC_EINVAL if not one of the enum's values */
} rc_soft_params;

/* What a run did and how well it kept its invariants. */
typedef struct rc_soft_result {
    int n_contacts;       /* contact starts (overlap became positive) */
    int n_shape_overlaps; /* of which started on an overlap made by a shape change
                           * (contracted shapes only; papers/soft-sphere.md 7.5) */
    int finished;         /* 1: no contact left and every pair receding; 0: hit t_max */
    rc_vec3 normal;       /* table-frame normal of the first contact, for the hard law
                           * (the spatial part of the boosted (0, n*), n* the
                           * integration-frame normal at contact start; zero if none) */
    double t_end;         /* common table time of the returned positions */
    double energy_error;  /* max over steps of |sum(K + U) - initial| / initial sum K,
                           * in the integration frame: the solver's energy error */
    double momentum_error;/* max over steps of |sum p| / sum |p|, integration frame */
    long n_steps;         /* stepper steps taken */
    long n_rhs;           /* right-hand-side evaluations */
    long n_pw;            /* Perram-Wertheim Newton evaluations (contracted shapes) */
} rc_soft_result;

struct rc_soft_sys; /* a run's private state (lib/soft_private.h) */

/* A stepper drives the integration of a run from start to finish (events included). */
typedef struct rc_soft_stepper {
    const char *name;    /* as on the command line */
    const char *summary; /* one line for --help */
    int (*integrate)(struct rc_soft_sys *sys);
} rc_soft_stepper;

/* SUNDIALS CVODE, BDF with the dense direct linear solver, contacts by CVodeRootInit. */
extern const rc_soft_stepper rc_soft_cvode_bdf;
/* GSL odeiv2 explicit Runge-Kutta (Prince-Dormand 8(9) and Fehlberg 4(5)), contacts
 * located by Illinois regula falsi on the overlap inside the step that crossed it. As for
 * any GSL use, the application calls gsl_set_error_handler_off() first (GSL's default
 * handler aborts on an allocation failure). */
extern const rc_soft_stepper rc_soft_gsl_rk8pd;
extern const rc_soft_stepper rc_soft_gsl_rkf45;

/* NULL-terminated table of the built-in steppers; rc_soft_stepper_find: NULL if unknown. */
extern const rc_soft_stepper *const rc_soft_steppers[];
const rc_soft_stepper *rc_soft_stepper_find(const char *name);

/* classical, kappa = 1e6, eps = 1, rtol = 1e-10, t_max = inf, max_steps = 1000000,
 * shape = RC_SOFT_SPHERE */
rc_soft_params rc_soft_params_default(void);

/* Damping ratio zeta of the linear spring-dashpot whose restitution is eps:
 * eps = exp(-pi zeta / sqrt(1 - zeta^2))  <=>  zeta = -ln eps / sqrt(pi^2 + ln^2 eps). */
double rc_soft_damping_ratio(double eps);

/* Run n >= 2 balls from table time 0: rest masses and momenta b[i], positions x[i], radii
 * r[i] (no overlap at the start). On return b[i] and x[i] hold the table-frame outcome at
 * table time res->t_end (rest masses raised by the heat), u_int[i] (may be NULL) the
 * internal energy each ball gained, U = (m' - m) c^2 (finite classically), and res (may
 * be NULL) the run's diagnostics. On any error the inputs are untouched.
 * Codes: RC_EINVAL, RC_ENONFINITE, RC_EMASS, RC_ERADIUS, RC_ESPEEDOFLIGHT,
 * RC_ERESTITUTION, RC_EOVERLAP (overlap at the start), RC_ENOMEM, RC_ENOCONVERGE. */
int rc_soft_collide(const rc_soft_stepper *stepper, const rc_soft_params *prm, size_t n,
                    rc_particle *b, rc_vec3 *x, const double *r, double *u_int,
                    rc_soft_result *res);

#ifdef __cplusplus
}
#endif
#endif
