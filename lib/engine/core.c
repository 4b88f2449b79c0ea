/* engine/core.c — the event loop: pop events in (time, ball) order, drop stale ones by
 * counters, and resolve each collision together with every contact simultaneous to it
 * (papers/simultaneous-contacts.md). Predicting events: engine/predict.c; creating and
 * filling an engine: engine/setup.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "approach.h"
#include "pairs.h"
#include "private.h"
#include "group.h"
#include "perball/model.h"
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

/* The common case: the event's own contact alone. Resolve it, then predict both balls
 * while checking that no other contact was simultaneous with it; if one was, take it
 * back (SINGLE_GROUP). undo_order: a member whose new kink would cross its last one may
 * ask for that collision to be undone (SINGLE_UNDO). */
static single_result try_single(rc_sim *s, size_t nm, int32_t bp, double T, const double *tx,
                                const rc_vec3 *dX, int model, int undo_order)
{
    rc_particle *P = s->grp_part;
    rc_vec3 vold[2];
    /* per_ball frames: the records at T before the kinks, to undo and to check from */
    eng_ball bat[2];
    eng_clock cat[2];
    eng_cov gat[2];
    rc_glue uat[2];
    int kinked[2] = {0, 0};
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
    const int st = eng_resolve_contact(s, Q, c);
    if (st != RC_OK) {
        s->bk.events[RC_SIM_EV_TC] = tc_before;
        return single_failed(st);
    }
    /* per_ball frames: each changed member's kink (time, H's normal), once, and whether
     * its hyperplane would reach some point of the ball before the last one did
     * (eng_kinks_cross; the centre's order is the order rule's). (A member's kink moves only
     * its own record, so the other's is the same before and after it.) */
    int changed[2] = {0, 0}, cross[2] = {0, 0};
    double te[2] = {0.0, 0.0};
    rc_vec3 kap[2] = {rc_v3(0, 0, 0), rc_v3(0, 0, 0)};
    for (size_t j = 0; j < nm; j++) {
        changed[j] = Q[j].m != P[j].m || memcmp(&Q[j].p, &P[j].p, sizeof Q[j].p) != 0;
        if (s->glue && changed[j]) {
            const int32_t b = s->grp_ball[j];
            te[j] = eng_kink_time(s, b, &P[j], &Q[j], tx[j], dX[j], &kap[j]);
            cross[j] = eng_kinks_cross(s, b, te[j], kap[j], &P[j], &Q[j]);
        }
    }
    /* such a ball met its new partner within its last kink's window: the last collision
     * is undone if it can be (2 + the member: the caller's rollback), else the order rule
     * (glue_kink_at) */
    for (size_t j = 0; j < nm && s->glue && model && undo_order && nm > 1; j++) {
        if (changed[j] && cross[j] && eng_undoable(s, s->grp_ball[j], s->grp_ball[1 - j])) {
            s->bk.events[RC_SIM_EV_TC] = tc_before;
            return single_is(SINGLE_UNDO, j);
        }
    }
    for (size_t j = 0; j < nm; j++) {
        int32_t b = s->grp_ball[j];
        if (s->glue) {
            bat[j] = s->b[b];
            cat[j] = s->clk[b];
            gat[j] = s->pb->cov[b];
            uat[j] = s->pb->glu[b];
            /* (no change, no kink: a contact the law found nothing to resolve keeps the
             * ball's line and its hyperplane) */
            kinked[j] = 0;
            if (changed[j]) {
                /* hyperplanes crossing inside the ball though the centres' kinks come in
                 * order (not undone above): the tube of the two is not defined there,
                 * counted with the order conflicts (the collision can still be undone:
                 * its kink is where the model puts it) */
                if (te[j] >= s->pb->cov[b].t_k && cross[j])
                    s->bk.order_conflicts++;
                const uint64_t oc = s->bk.order_conflicts;
                eng_glue_kink_at(s, b, &P[j], &Q[j], tx[j], dX[j], te[j], kap[j], !model);
                kinked[j] = s->bk.order_conflicts == oc && s->pb->glu[b].r > 0.0;
            }
        }
        s->a[b].m = Q[j].m;
        s->a[b].p = Q[j].p;
        s->b[b].v = rc_v3_scale(1.0 / eng_mass_rel(Q[j].m, Q[j].p, s->inv_c2), Q[j].p);
        s->cnt[b]++;
    }
    int conflict = 0;
    for (size_t j = 0; j < nm && !conflict; j++) {
        int32_t b = s->grp_ball[j];
        int32_t partner = nm > 1 ? s->grp_ball[1 - j] : bp;
        const eng_check chk = {P[j], vold[j], partner, s->glue ? &bat[j] : NULL,
                               s->glue && model && bp >= 0};
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
            if (s->glue) {
                s->b[b] = bat[j];
                s->clk[b] = cat[j];
                s->pb->cov[b] = gat[j];
                s->pb->glu[b] = uat[j];
            }
        }
        s->bk.events[RC_SIM_EV_TC] = tc_before;
        s->bk.order_conflicts = oc_before;
        return single_is(SINGLE_GROUP, 0);
    }
    eng_moments_add(s, nm, s->grp_ball, P, Q);
    if (s->glue) {
        /* An overlap-policy decision between two balls leaves a record too, so that a
         * later conflict with either ball's tube before its kink undoes it and solves it
         * with the new contact (one decision, still counted once) instead of handing that
         * conflict to the policy as well (papers/shape-change.md section 8). Its contact
         * event, for the undo's group: one event for both, on the centre line at T where
         * spheres of the rest radii would touch. */
        const int policy_pair = !model && nm == 2;
        rc_vec3 dXp[2];
        if (policy_pair) {
            const int32_t b0 = s->grp_ball[0], b1 = s->grp_ball[1];
            const rc_vec3 d = eng_image(s, rc_v3_sub(bat[1].x, bat[0].x));
            dXp[0] = rc_v3_scale(s->b[b0].r / (s->b[b0].r + s->b[b1].r), d);
            dXp[1] = rc_v3_sub(dXp[0], d);
        }
        eng_write_undo(s, nm, bp, model || policy_pair, policy_pair, P, vold, cat, gat, uat,
                       tx, policy_pair ? dXp : dX, kinked,
                       s->bk.events[RC_SIM_EV_TC] != tc_before);
    }
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
    /* per_ball frames: each ball's contact event (time, offset from its centre), read
     * before the balls are advanced (the stored states the prediction saw); the overlap
     * policy's kinks are at T, through the centre */
    double tx[2] = {T, T};
    rc_vec3 dX[2] = {rc_v3(0, 0, 0), rc_v3(0, 0, 0)};
    int have_x = 0, wall_tube = 0;
    if (s->glue) {
        if (bp >= 0) {
            const rc_vec3 n = s->ev_n[i];
            if (!isnan(n.x)) { /* (as the prediction found it) */
                tx[0] = s->pb->cov[i].ev_tx;
                dX[0] = s->pb->cov[i].ev_dx;
                have_x = 1;
            }
            else {
                const int st = eng_undo_conflict(s, i, bp, T, n.y == 1.0);
                if (st != 0)
                    return st > 0 ? RC_OK : st;
                if (n.y == 1.0)
                    s->bk.tube_conflicts++;
            }
        } else {
            have_x = eng_wall_event_point(s, i, ENG_WALL_INDEX(bp), &tx[0], &dX[0]);
            wall_tube = !have_x;
            if (wall_tube) {
                /* the shape met the wall on the incoming side of the ball's hyperplane:
                 * its last collision undone and solved with the wall's contact, as a
                 * ball's (engine/undo.c), else the overlap policy */
                const int st = eng_undo_wall(s, i, bp, T, tx[0]);
                if (st != 0)
                    return st > 0 ? RC_OK : st;
                s->bk.tube_conflicts++;
                tx[0] = T;
                dX[0] = rc_v3(0, 0, 0);
            }
        }
    }
    if (bp >= 0 && s->narrow) {
        /* The frame's normal at contact: the one its call that predicted this event
         * returned with the time (both stored states are unchanged since, the counters
         * say so), so not asked again -- right also for frames (zmf) whose contact is
         * not simultaneous in the table frame. NAN: the frame said RC_EOVERLAP, the
         * shape-change policy, resolved along the centre line and counted. */
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
        if (have_x) { /* X from bp's centre at tx: both are at T now */
            tx[1] = tx[0];
            dX[1] = rc_v3_sub(dX[0], rc_v3_axpy(dx, tx[0] - T, rc_v3_sub(s->b[bp].v, s->b[i].v)));
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
        if (wall_tube && s->bk.overlaps == ov) { /* (the overlap policy decides it) */
            eng_note_overlap(s, 1);
        }
    }
    /* per_ball frames, a contact of the model between two balls: the group is formed by
     * simultaneity in its own ZMF, with each member kinked at its own event (a wall's
     * contacts keep the table's: the wall's rest frame) */
    if (have_x && bp >= 0 && s->def.sim_tol > 0.0) {
        const int st = eng_zmf_group(s, i, bp, T, tx[0], dX[0]);
        if (st != 0)
            return st > 0 ? RC_OK : st;
    }
    single_result single = try_single(s, nm, bp, T, tx, dX, have_x, 1);
    if (single.status == RC_OK && single.verdict == SINGLE_UNDO) {
        /* (an order conflict that undoing the member's last collision resolves) */
        const size_t j = single.member;
        const int st = eng_rollback(s, s->grp_ball[j], s->grp_ball[1 - j], T, tx[0]);
        if (st != 0)
            return st > 0 ? RC_OK : st;
        single = try_single(s, nm, bp, T, tx, dX, have_x, 0);
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
    } else if (!s->def.law->group) {
        /* a law without a group solver: the contacts one at a time, in the group's order
         * (the event's own first, then as grow_group found them), each on the states the
         * previous ones left -- the outcome depends on that order (relcol/sim.h) */
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
            for (size_t j = 0; j < nm; j++) {
                P[j].m = s->a[s->grp_ball[j]].m;
                P[j].p = s->a[s->grp_ball[j]].p;
            }
            if ((st = eng_resolve_contact(s, P, &s->grp_con[0])) != RC_OK)
                return st;
            nm = bp >= 0 ? 2 : 1;
            nc = 1;
            kind = bp >= 0 ? RC_SIM_EV_BALL : RC_SIM_EV_WALL;
            /* the books before the event cover only the balls that take part now (the
             * others' momentum would otherwise pass for a wall impulse, their energy
             * for heat) */
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

/* per_ball frames: a collision reads ball b's cold records -- its hyperplane, its glued
 * tube (copied whole for the undo record), whether its undo record is live, the read-out's
 * record -- in that order as it goes; asked for at once, their lines come in parallel
 * instead of one miss after another. (Always inlined: out of line GCC finds the function
 * free of side effects and drops its calls.) */
__attribute__((always_inline)) static inline void glue_prefetch(const rc_sim *s, int32_t b)
{
    const char *g = (const char *)&s->pb->glu[b];
    __builtin_prefetch(&s->pb->cov[b]);
    /* (five lines: the array is line-aligned, so a record starts at most 56 bytes into
     * its first line) */
    for (size_t o = 0; o < sizeof(rc_glue); o += 64)
        __builtin_prefetch(g + o);
    __builtin_prefetch(&s->pb->und[b].partner);
    /* (the record a new one shifts into the previous one: whole, written at once) */
    const char *u = (const char *)&s->pb->und[b], *up = (const char *)&s->pb->undp[b];
    for (size_t o = 0; o < sizeof(eng_undo); o += 64) {
        __builtin_prefetch(u + o);
        __builtin_prefetch(up + o, 1);
    }
    __builtin_prefetch(&s->pb->pend[b].depth);
}

/* Events a run may have at one instant before it is called stalled: every contact of a
 * touching configuration may resolve a few times over (a cascade through a rack, a
 * lattice), far fewer than this; a chain of balls jammed across the box, or a clock so large
 * that a step rounds to nothing, passes it at once and for ever. */
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
            if (s->glue) {
                glue_prefetch(s, i);
                if (a->ev_partner >= 0)
                    glue_prefetch(s, a->ev_partner);
            }
            eng_pend_snap ps[2];
            const int np = !s->pb ? 0 : a->ev_partner >= 0 ? 2 : 1;
            if (np)
                ps[0] = eng_pend_take(s, i);
            if (np == 2)
                ps[1] = eng_pend_take(s, a->ev_partner);
            const uint64_t rb = s->bk.rollbacks;
            int st = collide(s, i, a->ev_partner, top_t);
            if (s->slc_nd) /* (delayed slices follow the event's kinks: engine/slice.c) */
                eng_slice_flush(s);
            if (st != RC_OK)
                return st;
            for (int j = 0; j < np && s->bk.rollbacks == rb; j++) /* (a rollback notes its
                                                                      own three) */
                eng_pend_note(s, &ps[j]);
        }
    }
    if (isfinite(t_end))
        s->now = t_end;
    return RC_OK;
}
