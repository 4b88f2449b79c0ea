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

/// The drop rule in the frame of the given states (papers/simultaneous-contacts.md): contact j gives b J_j q_j and a -J_j q_j, the J_j by Newton on the zmf law's restitution conditions, pulling contacts dropped, then (relativistic, k >= 2) one momentum scale in the common ZMF so no rest mass falls; jout (may be NULL) the first step's impulses; RC_ENOCONVERGE, RC_EMASS.
int rc_contacts_resolve(double inv_c2, size_t nballs, rc_particle *balls, size_t k,
                        const rc_contact *contacts, double *jout);

/// The zmf law's group solver with the rule prm->groups (prm->eps unused): DROP is rc_contacts_resolve; SIMULTANEOUS (principal pivoting: every jout[j] >= 0, restitution met where J > 0) and SEQUENTIAL (contacts in the order of their events, jout summed) run in the group's ZMF, so the outcome is frame independent; RC_EINVAL for an unknown rule.
int rc_contacts_solve(const rc_collision_params *prm, size_t nballs, rc_particle *balls,
                      size_t k, const rc_contact *contacts, double *jout);

/// rc_contacts_solve with law->collide in the sequential rule's one-contact steps (the simultaneous and drop rules, and the sequential rule's ties, are the zmf law's conditions); RC_EINVAL for a NULL law or one without a kernel.
int rc_contacts_solve_law(const rc_law *law, const rc_collision_params *prm, size_t nballs,
                          rc_particle *balls, size_t k, const rc_contact *contacts,
                          double *jout);

#ifdef __cplusplus
}
#endif
#endif
