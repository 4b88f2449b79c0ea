/* engine/contacts.h — the group rules' entry points shared by contacts.c (which dispatches)
 * and contacts_seq.c (the sequential rule); internal to the library. */
#ifndef RELCOL_ENGINE_CONTACTS_H
#define RELCOL_ENGINE_CONTACTS_H

#include <stddef.h>
#include "relcol/law.h"

/* The sequential rule (relcol/law.h, RC_GROUPS_SEQUENTIAL) on validated input, with the
 * zmf law's pair kernel and the wall law; ties go to rc_contacts_solve's simultaneous rule. */
int eng_contacts_sequential(const rc_collision_params *prm, size_t nballs, rc_particle *balls,
                            size_t k, const rc_contact *contacts, double *jout);

/* The total momentum *P and energy / c^2 *Mt of the balls that take part in the group's
 * contacts (the others are bystanders): the group's zero-momentum velocity is *P / *Mt. */
void eng_group_momentum(double inv_c2, size_t nballs, const rc_particle *balls, size_t k,
                        const rc_contact *contacts, rc_vec3 *P, double *Mt);

#endif
