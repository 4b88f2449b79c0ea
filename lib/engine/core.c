/* engine/core.c — the event loop: events in (time, ball) order, stale ones dropped by
 * counters, each collision resolved with every contact simultaneous to it
 * (papers/simultaneous-contacts.md). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "approach.h"
#include "pairs.h"
#include "private.h"
#include "group.h"
#include "model.h"
#include "path.h"
#include "relcol/status.h"

/* ---- resolving events ------------------------------------------------------------ */

/* What the single-contact path decided. */
typedef enum single_verdict {
    SINGLE_DONE,  /* resolved, books and predictions done */
    SINGLE_GROUP, /* another contact was simultaneous: nothing changed, the caller resolves
                     the whole group */
    SINGLE_UNDO   /* a member met its partner within its last kink's window: nothing
                     changed, the caller undoes that member's last collision first */
} single_verdict;
typedef struct single_result {
    int status;          /* RC_OK, or the law's failure (negative: nothing written back) */
    single_verdict verdict; /* with RC_OK */
    size_t member;       /* SINGLE_UNDO: the member (0 or 1) whose collision to undo */
} single_result;

static single_result single_failed(int st) { return (single_result){st, SINGLE_DONE, 0}; }
static single_result single_is(single_verdict v, size_t member)
{
    return (single_result){RC_OK, v, member};
}

/* The common case, the event's own contact alone: resolved, then both balls predicted with a
 * check for a simultaneous contact, which takes it back (SINGLE_GROUP) or asks for an undo
 * first (SINGLE_UNDO). */
static single_result try_single(rc_sim *s, size_t nm, int32_t bp, double T,
                                const eng_event_x *ev, int undo_order)
{
    const eng_model_ops *mo = s->model;
    rc_particle *P = s->grp_part;
    rc_vec3 vold[2];
    const uint64_t oc_before = s->bk.order_conflicts;
    double k0 = 0.0;
    rc_vec3 p0 = rc_v3(0, 0, 0);
    for (size_t j = 0; j < nm; j++) {
        int32_t b = s->grp_ball[j];
        P[j].m = s->a[b].m;
        P[j].p = s->a[b].p;
        vold[j] = s->b[b].v;
        k0 += eng_kinetic(&P[j], s->inv_c2);
        p0 = rc_v3_add(p0, P[j].p);
    }
    rc_contact *c = &s->grp_con[0];
    const uint64_t tc_before = s->bk.events[RC_SIM_EV_TC];
    c->eps = eng_contact_eps(s, c);
    rc_particle Q[2] = {P[0], nm > 1 ? P[1] : P[0]};
    const rc_rng rng_before = s->bk.rng; /* (a wall rule's draws, taken back with the event) */
    const int st = eng_resolve_contact(s, Q, c);
    if (st != RC_OK) {
        s->bk.events[RC_SIM_EV_TC] = tc_before;
        s->bk.rng = rng_before;
        eng_walls_forget(s);
        return single_failed(st);
    }
    int changed[2] = {0, 0};
    for (size_t j = 0; j < nm; j++)
        changed[j] = Q[j].m != P[j].m || memcmp(&Q[j].p, &P[j].p, sizeof Q[j].p) != 0;
    if (mo->before_resolve) {
        const int u = mo->before_resolve(s, nm, P, Q, changed, ev, undo_order);
        if (u >= 0) {
            s->bk.events[RC_SIM_EV_TC] = tc_before;
            s->bk.rng = rng_before;
            eng_walls_forget(s);
            return single_is(SINGLE_UNDO, (size_t)u);
        }
    }
    for (size_t j = 0; j < nm; j++) {
        int32_t b = s->grp_ball[j];
        if (mo->resolve_member)
            mo->resolve_member(s, j, P, Q, changed[j], ev);
        s->a[b].m = Q[j].m;
        s->a[b].p = Q[j].p;
        s->b[b].v = rc_v3_scale(1.0 / eng_mass_rel(Q[j].m, Q[j].p, s->inv_c2), Q[j].p);
        s->cnt[b]++;
    }
    int conflict = 0;
    for (size_t j = 0; j < nm && !conflict; j++) {
        int32_t b = s->grp_ball[j];
        int32_t partner = nm > 1 ? s->grp_ball[1 - j] : bp;
        const eng_check chk = {P[j], vold[j], partner,
                               mo->member_before ? mo->member_before(s, j) : NULL,
                               ev->model && bp >= 0};
        conflict = s->narrow ? eng_predict_checked_narrow(s, b, &chk)
                             : eng_predict_checked(s, b, &chk, T);
    }
    if (conflict) {
        for (size_t j = 0; j < nm; j++) {
            int32_t b = s->grp_ball[j];
            s->a[b].m = P[j].m;
            s->a[b].p = P[j].p;
            s->b[b].v = vold[j];
            s->cnt[b]--;
            if (mo->take_back)
                mo->take_back(s, j);
        }
        s->bk.events[RC_SIM_EV_TC] = tc_before;
        s->bk.order_conflicts = oc_before;
        s->bk.rng = rng_before;
        eng_walls_forget(s);
        return single_is(SINGLE_GROUP, 0);
    }
    eng_moments_add(s, nm, s->grp_ball, P, Q);
    if (mo->after_resolve)
        mo->after_resolve(s, nm, bp, P, vold, ev, s->bk.events[RC_SIM_EV_TC] != tc_before);
    for (size_t j = 0; j < nm; j++)
        P[j] = Q[j];
    eng_finish(s, nm, 1, k0, p0, bp >= 0 ? RC_SIM_EV_BALL : RC_SIM_EV_WALL, 1, NULL);
    return single_is(SINGLE_DONE, 0);
}

/* Resolve the collision of ball i with partner bp (ball or wall) at time T, with every
 * simultaneous contact. */
static int collide(rc_sim *s, int32_t i, int32_t bp, double T)
{
    size_t nm = 0, nc = 0;
    rc_vec3 n0;
    int frame_normal = 0;
    /* each ball's contact event as the model places it, from the stored states the prediction
     * saw (default: at T, through the centres) */
    eng_event_x ev = {{T, T}, {rc_v3(0, 0, 0), rc_v3(0, 0, 0)}, 0, 0};
    eng_walls_forget(s); /* (a failed event's notes, left behind) */
    if (s->model->contact_event) {
        const int st = s->model->contact_event(s, i, bp, T, &ev);
        if (st != 0)
            return st > 0 ? RC_OK : st;
    }
    if (bp >= 0 && s->narrow) {
        /* the normal the predicting call returned (both states unchanged since), not asked
         * again: right also where contact is not simultaneous in the table frame (zmf); NAN:
         * the overlap policy, along the centre line */
        const rc_vec3 n = s->ev_n[i];
        if (isnan(n.x)) {
            eng_note_overlap(s, 0);
        } else {
            n0 = n;
            frame_normal = 1;
        }
    }
    if (eng_member_of(s, &nm, i, T) < 0)
        return RC_ENOMEM;
    if (bp >= 0) {
        if (eng_member_of(s, &nm, bp, T) < 0)
            return RC_ENOMEM;
        rc_vec3 dx = eng_image(s, rc_v3_sub(s->b[bp].x, s->b[i].x));
        double len = rc_v3_norm(dx);
        if (ev.model) { /* X from bp's centre at tx: both are at T now */
            ev.tx[1] = ev.tx[0];
            ev.dX[1] = rc_v3_sub(ev.dX[0], rc_v3_axpy(dx, ev.tx[0] - T, rc_v3_sub(s->b[bp].v, s->b[i].v)));
        }
        if (!frame_normal)
            n0 = len > 0.0 ? rc_v3_scale(1.0 / len, dx) : rc_v3(1.0, 0.0, 0.0);
        if (!s->narrow && len < (s->b[i].r + s->b[bp].r) * (1.0 - s->def.overlap_tol)) {
            eng_note_overlap(s, 0);
        }
        if (eng_add_contact(s, &nc, 0, 1, n0) != RC_OK)
            return RC_ENOMEM;
    } else {
        int w = ENG_WALL_INDEX(bp), d = w / 2;
        n0 = rc_v3(0, 0, 0);
        rc_v3_set(&n0, d, (w & 1) ? 1.0 : -1.0);
        if (eng_add_contact(s, &nc, 0, bp, n0) != RC_OK)
            return RC_ENOMEM;
        const uint64_t ov = s->bk.overlaps;
        eng_count_overlaps(s, 0, 1); /* (before the collision changes the shape) */
        if (ev.wall_tube && s->bk.overlaps == ov) { /* (the overlap policy decides it) */
            eng_note_overlap(s, 1);
        }
    }
    /* a contact of the model between two balls: the model's own group (a wall's contacts keep
     * the table's) */
    if (ev.model && bp >= 0 && s->def.sim_tol > 0.0 && s->model->group_of_model) {
        const int st = s->model->group_of_model(s, i, bp, T, &ev);
        if (st != 0)
            return st > 0 ? RC_OK : st;
    }
    single_result single = try_single(s, nm, bp, T, &ev, 1);
    if (single.status == RC_OK && single.verdict == SINGLE_UNDO) {
        /* (an order conflict that undoing the member's last collision resolves) */
        const size_t j = single.member;
        const int st = s->model->undo_member(s, s->grp_ball[j], s->grp_ball[1 - j], T, &ev);
        if (st != 0)
            return st > 0 ? RC_OK : st;
        single = try_single(s, nm, bp, T, &ev, 0);
    }
    if (single.status != RC_OK)
        return single.status;
    if (single.verdict == SINGLE_DONE)
        return RC_OK;
    if (s->def.sim_tol > 0.0) {
        int st = eng_grow_group(s, &nm, &nc, T);
        if (st != RC_OK)
            return st;
        eng_count_overlaps(s, 1, nc);
    }
    /* states before, TC model per contact */
    rc_particle *P = s->grp_part;
    double k0 = 0.0;
    rc_vec3 p0 = rc_v3(0, 0, 0);
    for (size_t j = 0; j < nm; j++) {
        const eng_aux *a = &s->a[s->grp_ball[j]];
        P[j].m = a->m;
        P[j].p = a->p;
        k0 += eng_kinetic(&P[j], s->inv_c2);
        p0 = rc_v3_add(p0, a->p);
    }
    for (size_t j = 0; j < nc; j++)
        s->grp_con[j].eps = eng_contact_eps(s, &s->grp_con[j]);
    int kind;
    const double *J = NULL; /* the group solver's impulses, once it has solved */
    if (nc == 1) {
        const rc_contact *c = &s->grp_con[0];
        const int st = eng_resolve_contact(s, P, c);
        if (st != RC_OK)
            return st;
        kind = c->b >= 0 ? RC_SIM_EV_BALL : RC_SIM_EV_WALL;
    } else if (!s->def.law->group || eng_walls_soft_in(s, nc)) {
        /* a law without a group solver, or a wall that is not rigid (the joint solvers know
         * none): one contact at a time in the group's order, so the outcome depends on it */
        kind = RC_SIM_EV_MULTI;
        for (size_t j = 0; j < nc; j++) {
            const int st = eng_resolve_contact(s, P, &s->grp_con[j]);
            if (st != RC_OK)
                return st;
        }
        s->bk.group_sequential++;
    } else {
        /* members may be many: the solver works on the group's local indices */
        kind = RC_SIM_EV_MULTI;
        int st = s->def.law->group(&s->prm, nm, P, nc, s->grp_con, s->grp_j);
        J = st == RC_OK ? s->grp_j : NULL;
        if (st != RC_OK) {
            /* dependent normals (or no convergence): resolve the event's own contact,
             * the others become events of their own at the same time */
            s->bk.group_fallbacks++;
            eng_walls_forget(s);
            for (size_t j = 0; j < nm; j++) {
                P[j].m = s->a[s->grp_ball[j]].m;
                P[j].p = s->a[s->grp_ball[j]].p;
            }
            if ((st = eng_resolve_contact(s, P, &s->grp_con[0])) != RC_OK)
                return st;
            nm = bp >= 0 ? 2 : 1;
            nc = 1;
            kind = bp >= 0 ? RC_SIM_EV_BALL : RC_SIM_EV_WALL;
            /* books before the event over the balls taking part only, or the others' momentum
             * and energy pass for wall impulse and heat */
            k0 = 0.0;
            p0 = rc_v3(0, 0, 0);
            for (size_t j = 0; j < nm; j++) {
                const rc_particle before = {s->a[s->grp_ball[j]].m, s->a[s->grp_ball[j]].p};
                k0 += eng_kinetic(&before, s->inv_c2);
                p0 = rc_v3_add(p0, before.p);
            }
        }
    }
    eng_moments_add(s, nm, s->grp_ball, NULL, P);
    eng_finish(s, nm, nc, k0, p0, kind, 0, J);
    return RC_OK;
}

/* Events at one instant before a run is stalled: a touching cascade resolves a few times over,
 * far fewer; a jam across the box or a clock too large to step passes it at once. */
static uint64_t stall_limit(const rc_sim *s) { return 10000 + 64 * (uint64_t)s->n; }

/* The run cannot advance: note the event that would come next (its balls, by the caller's
 * numbers) and say so. The state is the one before that event, whole. */
static int stalled(rc_sim *s, int32_t i)
{
    const int32_t p = s->a[i].ev_partner;
    const int cross = s->a[i].cross_t <= s->a[i].ev_t;
    s->bk.stall_ball = s->id[i];
    s->bk.stall_partner = cross || p == ENG_NONE ? -((int64_t)1 << 62)
                          : p >= 0               ? (int64_t)s->id[p]
                                                 : (int64_t)p; /* -1 - w: wall w */
    return RC_ESTALL;
}

int rc_sim_advance(rc_sim *s, double t_end, uint64_t max_events)
{
    if (!s || isnan(t_end))
        return RC_EINVAL;
    if (t_end < s->now)
        return RC_EINVAL;
    if (isinf(t_end) && max_events == 0)
        return RC_EINVAL;
    if (s->path->run) /* (paths with a loop of their own: engine/path.h) */
        return s->path->run(s, t_end, max_events);
    uint64_t done = 0;
    while (s->n > 0) {
        if (s->since_reorder >= ENG_REORDER_EVERY * (uint64_t)s->n) {
            s->since_reorder = 0;
            eng_reorder(s);
        }
        double top_t;
        uint32_t top_ball;
        eng_queue_top(&s->q, &top_t, &top_ball);
        if (top_t > s->slc_due) /* (other frames: delayed slices the engine now passes) */
            eng_slice_take(s, top_t);
        /* nothing will ever happen again (every ball at rest or alone): done */
        if (!(top_t <= t_end) || top_t == INFINITY)
            break;
        if (max_events && done >= max_events)
            return RC_OK;
        const int32_t i = (int32_t)top_ball;
        eng_aux *a = &s->a[i];
        if (s->defer && a->ev_partner >= 0 && a->ev_t < a->cross_t &&
            ev_is_deferred(s->ev_n[i]) && s->cnt[a->ev_partner] == a->ev_pcount) {
            /* a deferred event's bound: settle it (not an event, and the time of the
             * last event stays as it was) */
            const double was = s->now;
            s->now = top_t;
            eng_settle(s, i);
            s->now = was;
            continue;
        }
        /* the next event's records, while this one is resolved: in a large gas they come
         * from L3 or memory */
        const int32_t nx = eng_queue_next(&s->q);
        if (nx >= 0) {
            __builtin_prefetch(&s->b[nx]);
            __builtin_prefetch(&s->a[nx]);
        }
        /* time must move on: count the events that come at one instant (stale entries,
         * mere bookkeeping, do not count) */
        if (!(a->ev_partner >= 0 && a->cross_t > a->ev_t && s->cnt[a->ev_partner] != a->ev_pcount)) {
            if (top_t == s->bk.still_t) {
                if (++s->bk.still_count > stall_limit(s)) {
                    s->now = top_t;
                    return stalled(s, i);
                }
            } else {
                s->bk.still_t = top_t;
                s->bk.still_count = 0;
            }
        }
        s->now = top_t;
        done++;
        if (a->ev_partner >= 0) {
            /* the partner's state is needed next (stale check, then the collision): load
             * it alongside its counter rather than after it */
            __builtin_prefetch(&s->b[a->ev_partner]);
            __builtin_prefetch(&s->a[a->ev_partner]);
        }
        if (a->cross_t <= a->ev_t) {
            s->since_reorder++;
            eng_cross(s, i);
        } else if (a->ev_partner >= 0 && s->cnt[a->ev_partner] != a->ev_pcount) {
            s->bk.events[RC_SIM_EV_STALE]++;
            eng_predict(s, i, 1);
        } else {
            s->since_reorder++;
            if (s->model->event_begin)
                s->model->event_begin(s, i, a->ev_partner);
            int st = collide(s, i, a->ev_partner, top_t);
            if (s->slc_nd) /* (delayed slices follow the event's kinks: engine/slice.c) */
                eng_slice_flush(s);
            if (st != RC_OK)
                return st;
            if (s->model->event_end)
                s->model->event_end(s);
        }
    }
    if (isfinite(t_end))
        s->now = t_end;
    return RC_OK;
}
