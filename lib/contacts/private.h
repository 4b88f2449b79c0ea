/* contacts/private.h — what the group solver's files share (internal to the library):
 * the joint solve, the sequential rule, the group's zero-momentum frame, the input check.
 * Floors, from the ground: ddouble.h, lu.c, rest_masses.c; joint.c, frame.c; sequential.c;
 * solve.c (the entry points). */
#ifndef RELCOL_CONTACTS_PRIVATE_H
#define RELCOL_CONTACTS_PRIVATE_H

#include <stddef.h>
#include "relcol/law.h"
#include "ddouble.h"

/* A rule as the group's frame runs it: on validated states and contacts given in the frame
 * it is run in. law: the pair kernel of the sequential rule's single contacts. */
typedef struct ctc_rule ctc_rule;
struct ctc_rule {
    int (*run)(const ctc_rule *r, size_t nballs, rc_particle *balls, size_t k,
               const rc_contact *contacts, double *jout);
    const rc_law *law;
    const rc_collision_params *prm;
    double inv_c2;
};

/* The rules, each in the frame of the states it is given (joint.c, sequential.c). */
int ctc_simultaneous(const ctc_rule *r, size_t nballs, rc_particle *balls, size_t k,
                     const rc_contact *contacts, double *jout);
int ctc_sequential(const ctc_rule *r, size_t nballs, rc_particle *balls, size_t k,
                   const rc_contact *contacts, double *jout);

/* The joint solve of the zmf law's restitution conditions: pivot = 1 the simultaneous rule
 * (principal pivoting until the impulses are complementary), 0 the drop rule. */
int ctc_joint(int pivot, double inv_c2, size_t nballs, rc_particle *balls, size_t k,
              const rc_contact *contacts, double *jout);

/* The rest-mass step after a relativistic joint solve (rest_masses.c; papers/
 * simultaneous-contacts.md, "Rest masses"): Mp, pp (and, for a fast pair, Mpd, ppd and
 * m2d, the post rest masses squared) the impulse-only post states; on RC_OK Mp, pp hold
 * the touched balls' final states and mstar[i] their rest masses (0: ball untouched). */
int ctc_keep_rest_masses(double inv_c2, size_t nb, const rc_particle *b0, size_t k,
                         const rc_contact *c, const int *active, double *Mp, rc_vec3 *pp,
                         const ctc_dd *Mpd, const ctc_ddv *ppd, const double *m2d,
                         double *mstar);

/* Dense LU with partial pivoting of the m x m row-major A in place, and the solve with
 * it (lu.c): GSL's arithmetic, a zero pivot a status. */
int ctc_lu_factor(double *A, size_t m, size_t *piv);
void ctc_lu_solve(const double *LU, size_t m, const size_t *piv, double *x);

/* Run rule r in the group's zero-momentum frame (frame.c): states, normals (as their
 * four-vectors q) and events boosted there, the outcome boosted back and the impulses
 * rescaled to the given normals; a group with a wall, or a classical one, in the given
 * frame. */
int ctc_in_group_zmf(const ctc_rule *r, size_t nballs, rc_particle *balls, size_t k,
                     const rc_contact *contacts, double *jout);

/* The total momentum *P and energy / c^2 *Mt of the balls that take part in the group's
 * contacts (the others are bystanders): the group's zero-momentum velocity is *P / *Mt. */
void ctc_group_momentum(double inv_c2, size_t nballs, const rc_particle *balls, size_t k,
                        const rc_contact *contacts, rc_vec3 *P, double *Mt);

/* Validation shared by the entry points and the sequential rule's ties (check.c). */
int ctc_check_input(double inv_c2, size_t nballs, const rc_particle *balls, size_t k,
                    const rc_contact *contacts);

#endif
