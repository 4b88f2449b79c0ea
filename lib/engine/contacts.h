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

/* A group whose zero-momentum frame moves fast (|P|^2/c^2 > RC_PAIR_FAST Mt^2, pair_axis.h),
 * of nm balls S (all in its contacts, no wall) and nc contacts C0 indexing S: B gets the
 * states in the group's ZMF, Cz the contacts there (normal the unit spatial part of the
 * boosted four-vector q = (u_ab.n/c^2, n), f its length, event boosted), *u and *g the
 * frame's velocity P/Mt and Lorentz factor Mt/minv for the boost back (rc_boost_g), all
 * without the gamma^2 cancellation of the plain boost (contacts_frame.c). */
int eng_group_zmf_fast(double inv_c2, size_t nm, const rc_particle *S, size_t nc,
                       const rc_contact *C0, rc_particle *B, rc_contact *Cz, double *f,
                       rc_vec3 *u, double *g);

#endif
