/* relcol/contacts.h — the group solver: simultaneous contacts resolved together by a rule
 * (relcol/law.h, rc_group_rule), on the law side of the library (lib/contacts/). The zmf
 * law's group solver is rc_contacts_solve; a law of one's own may use the same rules
 * through rc_contacts_solve_law, whose sequential rule runs that law's pair kernel. */
#ifndef RELCOL_CONTACTS_H
#define RELCOL_CONTACTS_H

#include <stddef.h>
#include "relcol/kinematics.h"
#include "relcol/law.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The drop rule (RC_GROUPS_DROP) in the frame of the given states.
 * Resolve k contacts among balls[] together (papers/simultaneous-contacts.md): contact
 * j gives ball b the four-impulse J_j q_j and ball a -J_j q_j, q_j = (u_j.n_j/c^2, n_j)
 * with u_j the pair's zero-momentum velocity before the group (q = (0, n) for a wall), and
 * the J_j solve, by Newton's method, the k restitution conditions of the zmf law: each
 * pair's post-group ZMF-normal approach a_j' = -eps_j a_j. Classically (inv_c2 = 0) this
 * is the k x k linear system, solved exactly in one step; k = 1 is the zmf law itself.
 * A contact whose impulse comes out pulling (J < 0) is dropped and the rest re-solved.
 * Then, relativistically with two or more contacts, the rest masses: the balls that took
 * an impulse have their momenta scaled by one factor in their common zero-momentum frame,
 * total energy kept, so that a ball whose contacts were all elastic keeps its rest mass
 * and no rest mass falls (no negative heat).
 * jout (may be NULL, k entries) receives the impulses of the first step. prm->eps is not
 * used. RC_ENOCONVERGE if Newton fails or no such scaling exists (the caller may then
 * resolve the contacts one at a time), RC_EMASS if a rest mass would become imaginary. */
int rc_contacts_resolve(double inv_c2, size_t nballs, rc_particle *balls, size_t k,
                        const rc_contact *contacts, double *jout);

/* The zmf law's group solver with the rule prm->groups (relcol/law.h, rc_group_rule;
 * prm->c the speed of light, prm->eps not used): RC_GROUPS_DROP is rc_contacts_resolve
 * above, in the frame of the given states. The other two rules run in the group's
 * zero-momentum frame (states, normals as their four-vectors q and events boosted there and
 * back; with a wall, or classically, in the given frame), so that their outcome does not
 * depend on the frame the states are given in. RC_GROUPS_SIMULTANEOUS replaces the
 * dropping by principal pivoting, so that on
 * return every impulse jout[j] >= 0, a contact with an impulse meets its restitution
 * condition and one without approaches no more than restitution allows (to round-off,
 * before the rest-mass step, which moves them by O((v/c)^2)); RC_GROUPS_SEQUENTIAL
 * resolves the contacts one after another in the order of their events' times
 * (rc_contact.t, .x) in the group's zero-momentum frame (jout: each contact's impulses
 * summed). RC_EINVAL for a rule that is not one. Other codes as rc_contacts_resolve. */
int rc_contacts_solve(const rc_collision_params *prm, size_t nballs, rc_particle *balls,
                      size_t k, const rc_contact *contacts, double *jout);

/* rc_contacts_solve with the pair kernel of `law` (law->collide, each contact's eps) in the
 * sequential rule's one-contact steps; the simultaneous and drop rules, and the sequential
 * rule's ties, are the zmf law's conditions whatever the law (they are its complementarity
 * problem). rc_contacts_solve is this with rc_law_zmf. RC_EINVAL for a NULL law or one
 * without a kernel; otherwise as rc_contacts_solve. */
int rc_contacts_solve_law(const rc_law *law, const rc_collision_params *prm, size_t nballs,
                          rc_particle *balls, size_t k, const rc_contact *contacts,
                          double *jout);

#ifdef __cplusplus
}
#endif
#endif
