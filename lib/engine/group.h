/* engine/group.h — building and resolving a group of contacts at one event
 * (engine/group.c), shared by the event loop and the per-ball model's files. Members are
 * local indices into rc_sim.grp_ball, contacts into rc_sim.grp_con. */
#ifndef RELCOL_ENGINE_GROUP_H
#define RELCOL_ENGINE_GROUP_H

#include <stdlib.h>

#include "relcol/status.h"
#include "model.h"
#include "resolve.h"

/* (the small steps inline: the event loop calls them for every collision) */

/// Grow the array *p of *cap elements to hold need (doubling); RC_ENOMEM.
static inline int eng_grow(void **p, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap)
        return RC_OK;
    size_t nc = *cap ? *cap : 16;
    while (nc < need)
        nc *= 2;
    void *q = realloc(*p, nc * elem);
    if (!q)
        return RC_ENOMEM;
    *p = q;
    *cap = nc;
    return RC_OK;
}

/// Member index of ball k in the group, adding it (advanced to T) if new; -1 on ENOMEM.
static inline int eng_member_of(rc_sim *s, size_t *nm, int32_t k, double T)
{
    for (size_t j = 0; j < *nm; j++)
        if (s->grp_ball[j] == k)
            return (int)j;
    size_t cap = s->grp_ball_cap;
    if (eng_grow((void **)&s->grp_ball, &cap, *nm + 1, sizeof *s->grp_ball) != RC_OK)
        return -1;
    if (eng_grow((void **)&s->grp_part, &s->grp_ball_cap, *nm + 1, sizeof *s->grp_part) != RC_OK)
        return -1;
    eng_advance_ball(s, k, T);
    s->grp_ball[*nm] = k;
    return (int)(*nm)++;
}

/// Has the group a contact between members a and b (either way)?
static inline int eng_have_contact(const rc_sim *s, size_t nc, int a, int b)
{
    for (size_t j = 0; j < nc; j++) {
        const rc_contact *c = &s->grp_con[j];
        if ((c->a == a && c->b == b) || (c->a == b && c->b == a))
            return 1;
    }
    return 0;
}

/// Add contact a-b (members; b < 0 a wall code) with normal n from a to b, its event at a's rest radius; RC_ENOMEM.
static inline int eng_add_contact(rc_sim *s, size_t *nc, int a, int b, rc_vec3 n)
{
    size_t cap = s->grp_con_cap;
    if (eng_grow((void **)&s->grp_j, &cap, *nc + 1, sizeof *s->grp_j) != RC_OK ||
        eng_grow((void **)&s->grp_con, &s->grp_con_cap, *nc + 1, sizeof *s->grp_con) != RC_OK)
        return RC_ENOMEM;
    rc_contact *c = &s->grp_con[(*nc)++];
    c->a = a;
    c->b = b;
    c->n = n;
    c->eps = 0.0;
    /* the event, for a rule that orders the contacts (members are at the group's time):
     * the point at ball a's rest radius along n (on a periodic axis a's own image) */
    const eng_ball *ba = &s->b[s->grp_ball[a]];
    c->t = ba->t;
    c->x = rc_v3_axpy(ba->x, ba->r, n);
    return RC_OK;
}

/// Surface gap of member mi to wall w at the members' time over its rest radius (negative: the shape crosses the wall).
static inline double eng_wall_gap_rel(const rc_sim *s, int mi, int w)
{
    const int32_t i = s->grp_ball[mi];
    const int d = w / 2;
    const double x = rc_v3_get(s->b[i].x, d), h = eng_wall_support(s, i, d);
    return ((w & 1) ? s->L[d] - h - x : x - h) / s->b[i].r;
}

/// The one law-or-wall-rule dispatch of contact c among P[] (restitution c->eps): RC_OK (RC_NO_COLLISION included: states unchanged), or the law's failure, which ends the event loop.
static inline int eng_resolve_contact(rc_sim *s, rc_particle *P, const rc_contact *c)
{
    int st;
    if (c->b >= 0) {
        s->prm.eps = c->eps;
        st = s->def.law->collide(&s->prm, &P[c->a], &P[c->b], c->n);
    } else {
        st = eng_wall_collide(s, ENG_WALL_INDEX(c->b), &P[c->a], c->n, c->eps);
    }
    return st == RC_OK || st == RC_NO_COLLISION ? RC_OK : (st < 0 ? st : RC_EINVAL);
}


/// Is wall contact c jammed (the shape as wide as the box, touching the opposite wall): it cannot separate (a chain of balls is the stall detector's: papers/relcol.md, "Limits").
static inline int eng_wall_jammed(const rc_sim *s, const rc_contact *c)
{
    return eng_wall_gap_rel(s, c->a, ENG_WALL_INDEX(c->b) ^ 1) <= s->def.sim_tol;
}

/// Restitution of contact c: elastic under the TC model; a jammed wall contact perfectly plastic (the rigid-wall limit, a model choice, counted in pinned); else the definition's.
static inline double eng_contact_eps(rc_sim *s, const rc_contact *c)
{
    const eng_clock *aa = &s->clk[s->grp_ball[c->a]];
    int wall = c->b < 0;
    if (wall && eng_wall_jammed(s, c)) {
        s->bk.pinned += rc_v3_dot(s->a[s->grp_ball[c->a]].p, c->n) > 0.0;
        return 0.0;
    }
    /* (t_c > 0: a per_ball ball may be at a time before its last kink, its proper time
     * since it negative) */
    int tc = s->def.t_c > 0.0 && aa->tau - aa->tau_last < s->def.t_c;
    if (!wall) {
        const eng_clock *ab = &s->clk[s->grp_ball[c->b]];
        tc = tc || (s->def.t_c > 0.0 && ab->tau - ab->tau_last < s->def.t_c);
    }
    const double eps = wall ? s->def.eps_wall : s->def.eps_ball;
    s->bk.events[RC_SIM_EV_TC] += (uint64_t)(tc && eps != 1.0);
    return tc ? 1.0 : eps;
}


/// Members 0 .. nm's wall contacts by the table's gap rule, each event on the ball's shape, while fewer than nc_max are held; RC_ENOMEM.
int eng_group_walls(rc_sim *s, size_t nm, size_t *nc, size_t nc_max);
/// Grow the group through shared balls with every contact simultaneous by the gap rule (sim_tol, approaching); members at T; RC_ENOMEM.
int eng_grow_group(rc_sim *s, size_t *nm, size_t *nc, double T);
/// Count contacts from .. nc that the overlap policy decides (shapes deeper than overlap_tol), on the states before the collision.
void eng_count_overlaps(rc_sim *s, size_t from, size_t nc);
/// The walls' shares of the momentum p0 - p1 taken in an event (contacts 0 .. nc; J the solver's impulses or NULL).
void eng_account_walls(rc_sim *s, size_t nc, rc_vec3 p0, rc_vec3 p1, const double *J);
/// Write the group's new states (grp_part) back, book heat and wall impulse, and predict every member (single: states and predictions already done, the queue updated).
static inline void eng_finish(rc_sim *s, size_t nm, size_t nc, double k0, rc_vec3 p0, int kind, int single,
                   const double *J)
{
    const rc_particle *P = s->grp_part;
    s->bk.events[kind]++;
    s->bk.collisions += nc;
    if (nc > s->bk.max_group)
        s->bk.max_group = nc;
    double k1 = 0.0;
    rc_vec3 p1 = rc_v3(0, 0, 0);
    for (size_t j = 0; j < nm; j++) {
        int32_t b = s->grp_ball[j];
        eng_aux *a = &s->a[b];
        k1 += eng_kinetic(&P[j], s->inv_c2);
        p1 = rc_v3_add(p1, P[j].p);
        if (!single && s->model->group_member) { /* (a group at one table time: the
                                                    model's kinks) */
            const rc_particle in = {a->m, a->p};
            s->model->group_member(s, b, &in, &P[j]);
        }
        s->clk[b].tau_last = s->clk[b].tau;
        if (!single) {
            a->m = P[j].m;
            a->p = P[j].p;
            s->b[b].v = rc_v3_scale(1.0 / eng_mass_rel(a->m, a->p, s->inv_c2), a->p);
            s->cnt[b]++;
        }
    }
    eng_kahan(&s->bk.heat, &s->bk.heat_c, k0 - k1);
    eng_kahan(&s->bk.wall[0], &s->bk.wall_c[0], p0.x - p1.x);
    eng_kahan(&s->bk.wall[1], &s->bk.wall_c[1], p0.y - p1.y);
    eng_kahan(&s->bk.wall[2], &s->bk.wall_c[2], p0.z - p1.z);
    eng_account_walls(s, nc, p0, p1, J);
    if (s->wev_mask)
        eng_walls_book(s);
    for (size_t j = 0; j < nm; j++) {
        if (single)
            eng_queue_update(&s->q, (uint32_t)s->grp_ball[j], key_of(&s->a[s->grp_ball[j]]));
        else
            eng_predict(s, s->grp_ball[j], 1);
    }
}

/// A contact the overlap policy decides, by kind: 0 the event's own ball contact, 1 a wall contact, 2 a group's other ball contact.
static inline void eng_note_overlap(rc_sim *s, int kind)
{
    s->bk.overlaps++;
    eng_validity_policy(s);
    s->bk.overlap_kind[kind]++;
}

#endif
