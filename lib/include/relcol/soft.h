/* relcol/soft.h — the soft-sphere reference (papers/soft-sphere.md): a stiff linear
 * spring-dashpot on the overlap delta, the four-force -F (u.n/c^2, n) with
 * F = kappa delta + eta d(delta)/dt, orthogonal to the pair's four-momentum (so total
 * four-momentum is kept and the work becomes internal energy U = (m - m_rest) c^2),
 * integrated in the balls' ZMF. eta makes a head-on pair's ZMF restitution exactly eps,
 * so kappa -> inf is rc_law_zmf. Steppers are table entries (rc_soft_steppers[]) that see
 * a run only through the rc_soft_sys calls below. Contact shapes: rc_soft_shape. */
#ifndef RELCOL_SOFT_H
#define RELCOL_SOFT_H

#include <stddef.h>
#include "relcol/kinematics.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Shape of a ball in the integration frame (overlap and normal of contracted shapes from the Perram-Wertheim function); at c = inf all are the sphere model bit for bit.
typedef enum rc_soft_shape {
    RC_SOFT_SPHERE = 0,           ///< radius r: the uncontracted sphere (default)
    RC_SOFT_CONTRACTED = 1,       ///< contracted along its integration-frame velocity, following the momenta in contact: another limit, (v/c)^2 away (papers/soft-sphere.md section 7)
    RC_SOFT_CONTRACTED_FROZEN = 2 ///< contracted, each contact keeping the shapes it started with: converges to rc_law_zmf with the zmf frame's normal (the reference)
} rc_soft_shape;

/// Parameters of a soft run: make one with rc_soft_params_default().
typedef struct rc_soft_params {
    double c;            ///< speed of light, > 0; INFINITY (the default) is classical
    double stiffness;    ///< kappa > 0: force per unit overlap (mass / time^2)
    double eps;          ///< restitution in (0, 1]: sets the dashpot (eps = 0 would never end)
    double rtol;         ///< the stepper's relative tolerance; absolute ones are rtol times the run's scales (radius, momentum, kinetic energy)
    double t_max;        ///< stop after this much integration-frame time even if not done
    long max_steps;      ///< stepper steps allowed in the whole run (RC_ENOCONVERGE beyond)
    rc_soft_shape shape; ///< contact shapes; RC_EINVAL if not one of the enum's values
} rc_soft_params;

/// What a run did and how well it kept its invariants.
typedef struct rc_soft_result {
    int n_contacts;        ///< contact starts (overlap became positive)
    int n_shape_overlaps;  ///< of which started on an overlap a shape change made (contracted shapes; papers/soft-sphere.md 7.5)
    int finished;          ///< 1: no contact left and every pair receding; 0: hit t_max
    rc_vec3 normal;        ///< table-frame normal of the first contact, for the hard law (zero if none)
    double t_end;          ///< common table time of the returned positions
    double energy_error;   ///< max over steps of |sum(K + U) - initial| / initial sum K (integration frame)
    double momentum_error; ///< max over steps of |sum p| / sum |p| (integration frame)
    long n_steps;          ///< stepper steps taken
    long n_rhs;            ///< right-hand-side evaluations
    long n_pw;             ///< Perram-Wertheim Newton evaluations (contracted shapes)
} rc_soft_result;

/* ---- a run as its stepper sees it: the piecewise smooth ODE y' = f(y) from time 0, one
 * switching function (overlap) and one contact switch per pair; the library owns the
 * equations and switches, the stepper the loop ---- */

/// A run's state (opaque).
typedef struct rc_soft_sys rc_soft_sys;

/// What a stepper needs to know of a run.
typedef struct rc_soft_sys_info {
    size_t ny;               ///< state components
    size_t npair;            ///< pairs: switching functions
    double rtol;             ///< relative tolerance
    const double *abs_scale; ///< per component: absolute tolerance / rtol
    double t_max;            ///< stop when t reaches it (INFINITY: only when done)
    double h0;               ///< a first step: a hundredth of the fastest ball's time to cross the smallest radius (1 if none moves)
    int ghosts;              ///< 1 if a pair can overlap out of contact (contracted shapes: rc_soft_shape_overlaps), so a positive overlap at a step's start has no contact start in it
} rc_soft_sys_info;

/// The run's sizes and tolerances.
void rc_soft_sys_get_info(const rc_soft_sys *s, rc_soft_sys_info *info);
/// The state y (ny values): the start on entry, integrated in place; on return it holds the state at rc_soft_sys_finish's time.
double *rc_soft_sys_state(rc_soft_sys *s);
/// 1 while fewer steps than max_steps were counted (a stepper returns RC_ENOCONVERGE once it is spent).
int rc_soft_sys_budget_left(const rc_soft_sys *s);
/// Count one step taken.
void rc_soft_sys_count_step(rc_soft_sys *s);
/// Pair q's contact switch: 1 while its force is on.
int rc_soft_sys_contact(const rc_soft_sys *s, size_t q);
/// The stepper ends at integration time t (the state is rc_soft_sys_state's).
void rc_soft_sys_finish(rc_soft_sys *s, double t);
/// dy/dt at y with the current contact switches.
void rc_soft_rhs(rc_soft_sys *s, const double *y, double *dy);
/// Overlap of every pair (npair values, > 0 overlapping): the switching functions.
void rc_soft_overlap(rc_soft_sys *s, const double *y, double *g);
/// 1 if pair q's centres approach at y: at a zero of its overlap the contact is on exactly then (from the state, not the root's reported direction).
int rc_soft_approaching(rc_soft_sys *s, size_t q, const double *y);
/// Contact of pair q starts (start = 1) or ends (0) at state y.
void rc_soft_switch(rc_soft_sys *s, size_t q, int start, const double *y);
/// Count pairs that came to overlap out of contact by a shape change (no force until it ends: switching on would release energy never stored); call after every accepted step and event.
void rc_soft_shape_overlaps(rc_soft_sys *s, const double *y);
/// Largest step that cannot carry an approaching pair through a whole contact unseen (gap over closing speed, floored at rtol times the radius crossing time; half 1/omega in contact); INFINITY if none approaches.
double rc_soft_max_step(rc_soft_sys *s, const double *y);
/// 1 when no pair is in contact and every pair is receding: nothing more can happen.
int rc_soft_done(rc_soft_sys *s, const double *y);
/// Record the conservation errors at y and release the frozen shapes of pairs apart in their current shapes too (at the start and after every accepted step and event).
void rc_soft_observe(rc_soft_sys *s, const double *y);

/// A stepper: drives a run from start to finish, events included.
typedef struct rc_soft_stepper {
    const char *name;    ///< as on the command line
    const char *summary; ///< one line for --help
    int (*integrate)(rc_soft_sys *sys); ///< RC_OK, or RC_ENOCONVERGE / RC_ENOMEM
} rc_soft_stepper;

/// SUNDIALS CVODE, BDF with the dense direct linear solver, contacts by CVodeRootInit.
extern const rc_soft_stepper rc_soft_cvode_bdf;
/// GSL odeiv2 Prince-Dormand 8(9), contacts by Illinois regula falsi in the step that crossed them (the application calls gsl_set_error_handler_off() first).
extern const rc_soft_stepper rc_soft_gsl_rk8pd;
/// GSL odeiv2 Fehlberg 4(5), contacts as rk8pd's.
extern const rc_soft_stepper rc_soft_gsl_rkf45;

/// The built-in steppers, NULL-terminated.
extern const rc_soft_stepper *const rc_soft_steppers[];
/// A built-in stepper by name, NULL if unknown.
const rc_soft_stepper *rc_soft_stepper_find(const char *name);

/// Classical, kappa = 1e6, eps = 1, rtol = 1e-10, t_max = inf, max_steps = 1000000, RC_SOFT_SPHERE.
rc_soft_params rc_soft_params_default(void);

/// Damping ratio of the spring-dashpot of restitution eps: zeta = -ln eps / sqrt(pi^2 + ln^2 eps).
double rc_soft_damping_ratio(double eps);

/// Run n >= 2 balls (b, x, radii r; no overlap) from table time 0: b, x the table-frame outcome at res->t_end, u_int (may be NULL) each ball's internal energy gained, res (may be NULL); inputs untouched on error (RC_EINVAL, RC_ENONFINITE, RC_EMASS, RC_ERADIUS, RC_ESPEEDOFLIGHT, RC_ERESTITUTION, RC_EOVERLAP, RC_ENOMEM, RC_ENOCONVERGE).
int rc_soft_collide(const rc_soft_stepper *stepper, const rc_soft_params *prm, size_t n,
                    rc_particle *b, rc_vec3 *x, const double *r, double *u_int,
                    rc_soft_result *res);

#ifdef __cplusplus
}
#endif
#endif
