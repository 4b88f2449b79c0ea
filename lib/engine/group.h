/* engine/group.h — building and resolving a group of contacts at one event
 * (engine/group.c), shared by the event loop and the per-ball model's files. Members are
 * local indices into rc_sim.grp_ball, contacts into rc_sim.grp_con. */
#ifndef RELCOL_ENGINE_GROUP_H
#define RELCOL_ENGINE_GROUP_H

#include "resolve.h"

/// Member index of ball k in the group, adding it (advanced to T) if new; -1 on ENOMEM.
int eng_member_of(rc_sim *s, size_t *nm, int32_t k, double T);
/// Add contact a-b (members; b < 0 a wall code) with normal n from a to b, its event at a's rest radius; RC_ENOMEM.
int eng_add_contact(rc_sim *s, size_t *nc, int a, int b, rc_vec3 n);
/// Members 0 .. nm's wall contacts by the table's gap rule, each event on the ball's shape, while fewer than nc_max are held; RC_ENOMEM.
int eng_group_walls(rc_sim *s, size_t nm, size_t *nc, size_t nc_max);
/// Grow the group through shared balls with every contact simultaneous by the gap rule (sim_tol, approaching); members at T; RC_ENOMEM.
int eng_grow_group(rc_sim *s, size_t *nm, size_t *nc, double T);
/// Count contacts from .. nc that the overlap policy decides (shapes deeper than overlap_tol), on the states before the collision.
void eng_count_overlaps(rc_sim *s, size_t from, size_t nc);
/// The law's (ball-ball) or the wall law's outcome of contact c among P[]: RC_OK, or the law's failure.
int eng_resolve_contact(rc_sim *s, rc_particle *P, const rc_contact *c);
/// Restitution of contact c: elastic under the TC model, plastic for a jammed wall (counted), else the definition's.
double eng_contact_eps(rc_sim *s, const rc_contact *c);
/// The walls' shares of the momentum p0 - p1 taken in an event (contacts 0 .. nc; J the solver's impulses or NULL).
void eng_account_walls(rc_sim *s, size_t nc, rc_vec3 p0, rc_vec3 p1, const double *J);
/// Write the group's new states (grp_part) back, book heat and wall impulse, and predict every member (single: states and predictions already done, the queue updated).
void eng_finish(rc_sim *s, size_t nm, size_t nc, double k0, rc_vec3 p0, int kind, int single,
                const double *J);

/// A contact the overlap policy decides, by kind: 0 the event's own ball contact, 1 a wall contact, 2 a group's other ball contact.
static inline void eng_note_overlap(rc_sim *s, int kind)
{
    s->bk.overlaps++;
    s->bk.overlap_kind[kind]++;
}

#endif
