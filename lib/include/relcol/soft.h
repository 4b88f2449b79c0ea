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
 * rc_soft_steppers[] and found by name, as the collision laws are. A stepper sees a run
 * only through the public rc_soft_sys functions below, so one can be written outside the
 * library and given to rc_soft_collide.
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

/* ---- a run as its stepper sees it ---------------------------------------------------
 * The piecewise smooth ODE y' = f(y) (ny components, the integration frame, from time 0)
 * with one switching function per pair of balls (its overlap) and one contact switch per
 * pair: the force of a pair is on exactly while its switch is. The model (the library)
 * owns the equations and the switches; the stepper owns the loop: */
typedef struct rc_soft_sys rc_soft_sys; /* opaque: a run's state */

typedef struct rc_soft_sys_info {
    size_t ny;               /* state components */
    size_t npair;            /* pairs: switching functions */
    double rtol;             /* relative tolerance */
    const double *abs_scale; /* per component: absolute tolerance / rtol */
    double t_max;            /* stop when t reaches it (INFINITY: only when done) */
    /* A first step: a hundredth of the time the fastest ball takes to cross the smallest
     * radius (1 if no ball moves); an adaptive controller adapts it at once. */
    double h0;
    /* 1 if a pair can overlap while out of contact (contracted shapes: a shape change
     * made it, see rc_soft_shape_overlaps): a pair out of contact whose overlap was
     * already positive at a step's start has no contact start to locate in that step. */
    int ghosts;
} rc_soft_sys_info;

void rc_soft_sys_get_info(const rc_soft_sys *s, rc_soft_sys_info *info);
/* The state y (ny values): the start on entry, integrated in place by the stepper; on
 * return from integrate it must hold the state at the time given to rc_soft_sys_finish. */
double *rc_soft_sys_state(rc_soft_sys *s);
/* The step budget: 1 while fewer steps than rc_soft_params.max_steps were counted. A
 * stepper counts every step it takes with rc_soft_sys_count_step and returns
 * RC_ENOCONVERGE when the budget is spent. */
int rc_soft_sys_budget_left(const rc_soft_sys *s);
void rc_soft_sys_count_step(rc_soft_sys *s);
/* Pair q's contact switch: 1 while its force is on. */
int rc_soft_sys_contact(const rc_soft_sys *s, size_t q);
/* The stepper ends at integration time t (the state is rc_soft_sys_state's). */
void rc_soft_sys_finish(rc_soft_sys *s, double t);
/* dy/dt at y with the current contact switches. */
void rc_soft_rhs(rc_soft_sys *s, const double *y, double *dy);
/* Overlap of every pair (npair values, > 0 overlapping): the switching functions. */
void rc_soft_overlap(rc_soft_sys *s, const double *y, double *g);
/* 1 if pair q's centres approach at y: at a zero of its overlap the contact is on exactly
 * when they approach (decided from the state, not from a root's reported direction,
 * which is unreliable for a root found again at the restart point). */
int rc_soft_approaching(rc_soft_sys *s, size_t q, const double *y);
/* Contact of pair q starts (start = 1) or ends (0) at state y. */
void rc_soft_switch(rc_soft_sys *s, size_t q, int start, const double *y);
/* Contracted shapes change with the momenta, so a pair out of contact can come to
 * overlap without approaching (another contact changed a ball's shape). Such a pair feels
 * no force until its overlap has ended (switching it on would release at once an elastic
 * energy kappa delta^2/2 that was never stored); counts each such episode (call after
 * every accepted step and event). */
void rc_soft_shape_overlaps(rc_soft_sys *s, const double *y);
/* Largest step that cannot carry an approaching pair that is not in contact through a
 * whole contact unseen: its gap over its closing speed (free flight), floored at rtol
 * times the radius crossing time; for a pair in contact, half its 1/omega.
 * INFINITY when no pair approaches or touches. Cap every step with it. */
double rc_soft_max_step(rc_soft_sys *s, const double *y);
/* 1 when no pair is in contact and every pair is receding: nothing more can happen. */
int rc_soft_done(rc_soft_sys *s, const double *y);
/* Record the conservation errors at y and release the frozen shapes of pairs that are
 * apart in their current shapes too (call at the start and after every accepted step and
 * event). */
void rc_soft_observe(rc_soft_sys *s, const double *y);

/* A stepper drives the integration of a run from start to finish (events included):
 * RC_OK, or RC_ENOCONVERGE / RC_ENOMEM. */
typedef struct rc_soft_stepper {
    const char *name;    /* as on the command line */
    const char *summary; /* one line for --help */
    int (*integrate)(rc_soft_sys *sys);
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
