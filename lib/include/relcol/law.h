/* relcol/law.h — two-ball collision laws, each a `const rc_law` table entry (GSL style)
 * with declared properties that the engine and the apps read, never a law's name. A law
 * maps two balls' states (rest mass, momentum) and a unit normal n from ball 0 to ball 1
 * to their states after, rest-mass change included. Adding one: README "Adding a
 * collision law" (one file, declared here, listed in rc_laws[] in lib/law_table.c). */
#ifndef RELCOL_LAW_H
#define RELCOL_LAW_H

#include <stddef.h>
#include <stdint.h>
#include "relcol/kinematics.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Parameters shared by the laws: make one with rc_collision_params_default().
typedef struct rc_collision_params {
    double c;       ///< speed of light, > 0; INFINITY (the default) is the classical limit
    double eps;     ///< restitution in [0, 1] (zmf: normal ZMF momentum; cm-isotropic: R)
    double alpha;   ///< cm-isotropic only: impact angle in (-pi/2, pi/2) between ball 0's ZMF direction and the ZMF normal; NAN: the normal from n
    double azimuth; ///< cm-isotropic only, 3-D: the normal's azimuth about that direction
    int groups;     ///< how a group solver resolves simultaneous contacts (rc_group_rule; default RC_GROUPS_SIMULTANEOUS)
} rc_collision_params;

/// Rules for a group of contacts found simultaneous (at one table time, or in the group's ZMF for the covariant frame): named models, since multiple impacts have no unique answer (papers/simultaneous-contacts.md).
typedef enum rc_group_rule {
    RC_GROUPS_SIMULTANEOUS = 0, ///< all impulses together, a complementarity problem in the group's ZMF (J >= 0, restitution met where J > 0), then the rest-mass step; the drop rule's bits where no impulse pulls
    RC_GROUPS_SEQUENTIAL = 1,   ///< one contact after another in the order of their events in the group's ZMF (the wall's rest frame with a wall), each by the pair kernel, until none approaches; ties to round-off go to the simultaneous rule
    RC_GROUPS_DROP = 2          ///< a joint Newton solve from which the most pulling contact is dropped until none pulls (not re-checked)
} rc_group_rule;

/// A rule's name ("simultaneous", "sequential", "drop"), NULL if not one.
const char *rc_group_rule_name(int rule);
/// A rule's one-line summary for --help, NULL if not one.
const char *rc_group_rule_summary(int rule);
/// A rule by name, -1 if unknown.
int rc_group_rule_find(const char *name);

/// Law kernel: RC_OK with the outcome in *a, *b; RC_NO_COLLISION (untouched) when they do not approach along n; validated input (rc_collide validates, rc_collide_batch trusts).
typedef int (*rc_law_fn)(const rc_collision_params *prm, rc_particle *a, rc_particle *b,
                         rc_vec3 n);

/// A contact of a group.
typedef struct rc_contact {
    int a, b;   ///< ball a against ball b (b >= 0) or a wall (b < 0)
    rc_vec3 n;  ///< unit normal from a towards b (or into the wall)
    double eps; ///< its restitution
    double t;   ///< its event's time ...
    rc_vec3 x;  ///< ... and point, read only by the sequential rule to order contacts (all 0: they tie)
} rc_contact;

/// Group solver: resolve k contacts among balls[0, nballs) together (each contact's eps; walls infinitely massive; trusted input); RC_OK, else the engine resolves only the event's own contact (group_fallbacks); jout (may be NULL): each contact's normal impulse.
typedef int (*rc_law_group_fn)(const rc_collision_params *prm, size_t nballs,
                               rc_particle *balls, size_t k, const rc_contact *contacts,
                               double *jout);

/// A law: its kernel and its declared properties (fields an initialiser leaves out are 0 / NULL: the conservative choice).
typedef struct rc_law {
    const char *name;      ///< as on the command line
    const char *summary;   ///< one line for --help
    rc_law_fn collide;     ///< the pair kernel
    rc_law_group_fn group; ///< optional, order independent (zmf: rc_contacts_solve); without it a group goes one contact at a time, its outcome then depending on the order (group_sequential)
    int uses_angle;        ///< reads prm->alpha and prm->azimuth (cm-isotropic): apps offer --alpha
    int keeps_zmf_energy;  ///< keeps each ball's ZMF energy, so rc_pair_heat gives the heat (zmf, cm-isotropic)
} rc_law;

/// The four-impulse law (shared/DESIGN.md): J = -(1+eps) (p0.n - M0 u.n) / (1 - (u.n)^2/c^2), ZMF energies kept, ZMF normal momentum scaled by -eps, m'^2 = m^2 + (1-eps^2) pbar_n^2 / c^2.
extern const rc_law rc_law_zmf;
/// Seed 002's law made relativistic (papers/cm-isotropic.md): momenta reflected about the ZMF normal, then the ZMF momentum scaled by R = eps.
extern const rc_law rc_law_cm_isotropic;

/// The built-in laws, NULL-terminated.
extern const rc_law *const rc_laws[];
/// A built-in law by name, NULL if unknown.
const rc_law *rc_law_find(const char *name);

/// c = inf, eps = 1, alpha NAN, groups RC_GROUPS_SIMULTANEOUS.
rc_collision_params rc_collision_params_default(void);

/// Validating entry point: checks the particles, c, eps and n (normalised; zero: RC_EZERONORMAL), then calls law->collide.
int rc_collide(const rc_law *law, const rc_collision_params *prm, rc_particle *a,
               rc_particle *b, rc_vec3 n);

/// rc_collide's checks of one pair beyond rc_particle_check of each ball and the parameters' (inv_c2 from rc_inv_c2): m^2 + p^2/c^2 and |p_a + p_b|^2 finite, n finite and nonzero, n made unit as rc_collide makes it.
int rc_pair_check(const rc_particle *a, const rc_particle *b, rc_vec3 *n, double inv_c2);

/// Batch of trusted pairs a[i], b[i] along unit n[i]: status[i] (may be NULL) each kernel's code; returns how many collided.
size_t rc_collide_batch(const rc_law *law, const rc_collision_params *prm, size_t n_pairs,
                        rc_particle *a, rc_particle *b, const rc_vec3 *n, int *status);

/// Batch over columns with rc_collide's checks (numpy): pair i is (m0[i], p0[i]) against (m1[i], p1[i]) along n[i], in place; status (may be NULL), *hits; the first failing pair stops it (its code, *bad its index; those before done, the rest untouched); RC_EINVAL for NULL arrays.
int rc_collide_many(const rc_law *law, const rc_collision_params *prm, size_t n_pairs,
                    double *m0, rc_vec3 *p0, double *m1, rc_vec3 *p1, const rc_vec3 *n,
                    int *status, size_t *hits, size_t *bad);

/// rc_collide_many over strided columns of dim (1..3) components, read and written apart (numpy's layout): pair i is (m0[i * m0_stride], p0 + i * p0_stride) against (m1, p1 likewise) along nrm + i * n_stride (components past dim taken as 0; stride 0: one value for every pair), c and eps from prm; out m0o, m1o (n_pairs) and p0o, p1o (n_pairs x dim, row-major), status (may be NULL), *hits; rc_collide's checks and bits, the checks of a block of pairs in one branch-free pass before its kernels; the first failing pair stops it (its code, *bad its index; those before written).
int rc_collide_columns(const rc_law *law, const rc_collision_params *prm, size_t n_pairs,
                       int dim, const double *m0, size_t m0_stride, const double *p0,
                       size_t p0_stride, const double *m1, size_t m1_stride, const double *p1,
                       size_t p1_stride, const double *nrm, size_t n_stride, double *m0o,
                       double *p0o, double *m1o, double *p1o, int *status, size_t *hits,
                       size_t *bad);

/// Ball against an infinitely massive wall, n from the ball into it: p_n' = -eps_w p_n, tangential and M kept, m'^2 = m^2 + (1 - eps_w^2) p_n^2 / c^2; RC_NO_COLLISION if p.n <= 0.
int rc_collide_wall(double inv_c2, double eps_w, rc_particle *a, rc_vec3 n);

/// Heat of a two-ball collision, sum of (m' - m) c^2, free of cancellation from the ZMF momenta of `before` (laws with keeps_zmf_energy only; classical: kinetic energy lost); q_ball (may be NULL) the two terms; NAN for bad input.
double rc_pair_heat(const rc_particle before[2], const rc_particle after[2], double inv_c2,
                    double q_ball[2]);

/// A cm-isotropic impact angle for uniform impact parameters from uniform u1, u2 in [0, 1): 2-D sin(alpha) uniform in [-1, 1]; 3-D sin^2(alpha) uniform in [0, 1], azimuth uniform.
void rc_impact_angle_draw(int dim, double u1, double u2, double *alpha, double *azimuth);

#ifdef __cplusplus
}
#endif
#endif
