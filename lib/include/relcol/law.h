/* relcol/law.h — two-ball collision laws as a small table of function pointers.
 *
 * A law maps the pre-collision states of two balls (rest mass, momentum), a unit contact
 * normal n from ball 0 to ball 1 and the law's parameters to the post-collision states,
 * rest-mass change included. Laws are `const rc_law` objects (like GSL's
 * gsl_root_fsolver_brent) with declared properties; rc_laws[] lists the built-in ones by
 * name. The engine and the apps read the properties and never name a law. A law need not
 * live in the library: any `const rc_law` can be given to rc_collide() and
 * rc_sim_def.law (README "Adding a collision law"). To make it built-in: write one file
 * defining `const rc_law rc_law_mine = {.name = "mine", .summary = "...", .collide =
 * mine_collide, ...}`, declare it below and add its address to rc_laws[] in
 * lib/law_table.c; rc_law_find(), relcol-collide --law, relcol-sim's "law" key and the
 * law tests pick it up by name. */
#ifndef RELCOL_LAW_H
#define RELCOL_LAW_H

#include <stddef.h>
#include <stdint.h>
#include "relcol/kinematics.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Parameters shared by the laws. Make one with rc_collision_params_default(). */
typedef struct rc_collision_params {
    double c;       /* speed of light, > 0; INFINITY (the default) is the classical limit */
    double eps;     /* restitution in [0, 1] (zmf: normal ZMF momentum; cm-isotropic: R) */
    /* cm-isotropic only: impact angle alpha in (-pi/2, pi/2) between the ZMF direction
     * of motion of ball 0 and the ZMF contact normal (seed 002), and in 3-D the azimuth
     * of the normal about that direction. alpha = NAN: take the normal from n instead. */
    double alpha;
    double azimuth;
    /* How a law's group solver resolves simultaneous contacts (rc_group_rule below;
     * default RC_GROUPS_SIMULTANEOUS). Laws without a group solver do not read it. */
    int groups;
} rc_collision_params;

/* Rules for a group of contacts that the engine found simultaneous (touching and
 * approaching at one table time, or, the covariant frame's, simultaneous in the group's
 * ZMF; papers/simultaneous-contacts.md). Multiple impacts have
 * no unique answer, even classically: these are named models, compared with the soft
 * model's limit there. */
typedef enum rc_group_rule {
    /* all impulses together: J >= 0 on every contact, each contact with J > 0 meets its
     * restitution condition, each with J = 0 leaves no more approaching than restitution
     * allows (a complementarity problem, solved by principal pivoting around Newton) in
     * the group's zero-momentum frame; relativistically then the rest-mass step. The
     * default: classically, and with a wall, it has the drop rule's bits where no impulse
     * pulls. */
    RC_GROUPS_SIMULTANEOUS = 0,
    /* the contacts one after another in the order of their events' times in the group's
     * zero-momentum frame (a group with a wall: the wall's rest frame), each by the law's
     * pair kernel (the wall law), until none approaches; contacts whose times tie to
     * round-off (always classically, where table simultaneity is absolute) are resolved
     * together by the simultaneous rule */
    RC_GROUPS_SEQUENTIAL = 1,
    /* the rule before complementarity: a joint Newton solve from which the most pulling
     * contact is dropped until none pulls; a dropped contact is not re-checked */
    RC_GROUPS_DROP = 2
} rc_group_rule;

/* Name of a rule ("simultaneous", "sequential", "drop"), NULL if not one; its one-line
 * summary for --help (NULL if not one); a rule by name, -1 if unknown. */
const char *rc_group_rule_name(int rule);
const char *rc_group_rule_summary(int rule);
int rc_group_rule_find(const char *name);

/* Law kernel. On RC_OK, *a and *b hold the outcome. RC_NO_COLLISION (a and b untouched)
 * when the balls do not approach along n. Kernels assume validated input (finite, m > 0,
 * |n| = 1, eps in [0,1], c valid: 1/c^2 is rc_inv_c2_of(prm->c)): rc_collide() validates,
 * rc_collide_batch() trusts. */
typedef int (*rc_law_fn)(const rc_collision_params *prm, rc_particle *a, rc_particle *b,
                         rc_vec3 n);

/* A contact of a group: ball a against ball b (b >= 0) or against a wall (b < 0), with
 * unit normal n from a towards b (or into the wall) and restitution eps; t and x are its
 * event (time and point, in the frame the balls' states are given in), read only by the
 * sequential rule to order the contacts (left 0: every event the same, all tie). */
typedef struct rc_contact {
    int a, b;
    rc_vec3 n;
    double eps;
    double t;
    rc_vec3 x;
} rc_contact;

/* Group solver: resolve k simultaneous contacts among balls[0, nballs) together (each
 * contact's own eps; prm->eps is not used; walls infinitely massive). RC_OK when
 * resolved; any other code when it cannot (balls[] may then hold anything: the engine
 * reloads the states and resolves only the event's own contact, counted in
 * rc_sim_diag.group_fallbacks). Trusted input (unit normals, valid states). jout (may be
 * NULL, k entries): each contact's impulse along its normal, as far as the law defines
 * one (the engine shares the momentum of two walls of one axis by them). */
typedef int (*rc_law_group_fn)(const rc_collision_params *prm, size_t nballs,
                               rc_particle *balls, size_t k, const rc_contact *contacts,
                               double *jout);

/* A law: its kernel and its declared properties. Fields after collide that an
 * initialiser leaves out are 0 / NULL: the conservative choice for each. */
typedef struct rc_law {
    const char *name;    /* as on the command line */
    const char *summary; /* one line for --help */
    rc_law_fn collide;
    /* Optional (NULL: none): resolves a group of simultaneous contacts together, order
     * independent (zmf: rc_contacts_solve, relcol/contacts.h). Without one the engine
     * resolves a group's contacts one at a time with collide (and the wall law) in a fixed
     * order, which makes the outcome depend on that order (relcol/sim.h,
     * rc_sim_diag.group_sequential; papers/simultaneous-contacts.md). */
    rc_law_group_fn group;
    /* Whether the law reads prm->alpha and prm->azimuth (an impact angle given apart from
     * the normal: cm-isotropic); apps offer --alpha only for such laws. */
    int uses_angle;
    /* Whether each ball's energy in the pair's ZMF is kept, so that rc_pair_heat gives
     * the collision's heat (zmf, cm-isotropic). */
    int keeps_zmf_energy;
} rc_law;

/* The four-impulse law of shared/DESIGN.md: impulse J (u.n/c^2, n) with
 *   J = -(1+eps) (p0.n - M0 u.n) / (1 - (u.n)^2/c^2),
 * energy of each ball kept in the pair's ZMF, ZMF normal momentum scaled by -eps,
 * rest masses from m'^2 = m^2 + (1-eps^2) pbar_n^2 / c^2. */
extern const rc_law rc_law_zmf;
/* Seed 002's law made relativistic (papers/cm-isotropic.md): in the pair's ZMF reflect
 * the momenta about the ZMF contact normal, then scale the whole ZMF momentum by R=eps. */
extern const rc_law rc_law_cm_isotropic;

/* NULL-terminated table of the built-in laws. */
extern const rc_law *const rc_laws[];
/* Law by name, NULL if unknown. */
const rc_law *rc_law_find(const char *name);

/* c = inf, eps = 1, alpha NAN, groups RC_GROUPS_SIMULTANEOUS */
rc_collision_params rc_collision_params_default(void);

/* Validating entry point: checks the particles, c, eps and n (normalised here; a zero
 * normal is RC_EZERONORMAL), then calls law->collide. */
int rc_collide(const rc_law *law, const rc_collision_params *prm, rc_particle *a,
               rc_particle *b, rc_vec3 n);

/* rc_collide's checks of one pair, beyond rc_particle_check of each ball and those of the
 * parameters (rc_inv_c2 gives inv_c2): m^2 + p^2/c^2 and |p_a + p_b|^2 finite, n finite and
 * not zero, then n made unit as rc_collide makes it. For batches whose parameters are
 * checked once: rc_particle_check of a and b, this, then law->collide is rc_collide. */
int rc_pair_check(const rc_particle *a, const rc_particle *b, rc_vec3 *n, double inv_c2);

/* Batch: n_pairs collisions a[i] with b[i] along unit normals n[i] (trusted input).
 * status[i] (may be NULL) receives each kernel's code. Returns the number that collided. */
size_t rc_collide_batch(const rc_law *law, const rc_collision_params *prm, size_t n_pairs,
                        rc_particle *a, rc_particle *b, const rc_vec3 *n, int *status);

/* Batch with rc_collide's checks, over columns (for callers that cannot vouch for their
 * input and hold each quantity as one array, such as numpy in the Python package): pair i
 * is ball 0 of rest mass m0[i] and momentum p0[i] against ball 1 (m1[i], p1[i]) along
 * n[i]. The parameters are checked once, then each pair as rc_collide checks it (its
 * normal made unit), and collided in place. status[i] (may be NULL) gets RC_OK or
 * RC_NO_COLLISION; *hits (may be NULL) the number that collided. The first pair that
 * fails a check or whose kernel fails stops the batch: its code is returned and *bad (may
 * be NULL) gets its index; the pairs before it are done, it and those after it untouched.
 * RC_EINVAL for NULL law, prm or arrays (n_pairs > 0). */
int rc_collide_many(const rc_law *law, const rc_collision_params *prm, size_t n_pairs,
                    double *m0, rc_vec3 *p0, double *m1, rc_vec3 *p1, const rc_vec3 *n,
                    int *status, size_t *hits, size_t *bad);

/* Ball against an infinitely massive wall with outward normal n (pointing from the
 * ball into the wall): p_n' = -eps_w p_n, tangential kept, energy M kept, rest mass
 * m'^2 = m^2 + (1 - eps_w^2) p_n^2 / c^2. RC_NO_COLLISION if p.n <= 0. */
int rc_collide_wall(double inv_c2, double eps_w, rc_particle *a, rc_vec3 n);

/* Heat of a two-ball collision, sum over both balls of (m' - m) c^2, computed without
 * cancellation as sum (|pbar|^2 - |pbar'|^2) / (m' + m) from the momenta pbar, pbar' in the
 * zero-momentum frame of `before`. Valid only for laws that keep each ball's ZMF energy
 * (zmf, cm-isotropic): then m'^2 - m^2 = (|pbar|^2 - |pbar'|^2) / c^2. At inv_c2 = 0 it
 * is the classical kinetic energy lost.
 * q_ball (may be NULL) receives the two per-ball terms. NAN (and NAN in q_ball) for
 * invalid input: non-finite or negative inv_c2, or a particle failing rc_particle_check. */
double rc_pair_heat(const rc_particle before[2], const rc_particle after[2], double inv_c2,
                    double q_ball[2]);

/* Draw a cm-isotropic impact angle for uniformly distributed impact parameters:
 * 2-D sin(alpha) uniform in [-1, 1]; 3-D sin^2(alpha) uniform in [0, 1] and azimuth
 * uniform. u1, u2 are uniform deviates in [0, 1) (the caller owns the generator). */
void rc_impact_angle_draw(int dim, double u1, double u2, double *alpha, double *azimuth);

#ifdef __cplusplus
}
#endif
#endif
