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
#include "resolve.h"
#include "relcol/status.h"

/* ---- resolving events ------------------------------------------------------------ */

static int grow(void **p, size_t *cap, size_t need, size_t elem)
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

/* Group member index of ball k, adding it (advanced to T) if new; -1 on ENOMEM. */
static int member_of(rc_sim *s, size_t *nm, int32_t k, double T)
{
    for (size_t j = 0; j < *nm; j++)
        if (s->grp_ball[j] == k)
            return (int)j;
    size_t cap = s->grp_ball_cap;
    if (grow((void **)&s->grp_ball, &cap, *nm + 1, sizeof *s->grp_ball) != RC_OK)
        return -1;
    if (grow((void **)&s->grp_part, &s->grp_ball_cap, *nm + 1, sizeof *s->grp_part) != RC_OK)
        return -1;
    eng_advance_ball(s, k, T);
    s->grp_ball[*nm] = k;
    return (int)(*nm)++;
}

static int have_contact(const rc_sim *s, size_t nc, int a, int b)
{
    for (size_t j = 0; j < nc; j++) {
        const rc_contact *c = &s->grp_con[j];
        if ((c->a == a && c->b == b) || (c->a == b && c->b == a))
            return 1;
    }
    return 0;
}

static int add_contact(rc_sim *s, size_t *nc, int a, int b, rc_vec3 n)
{
    size_t cap = s->grp_con_cap;
    if (grow((void **)&s->grp_j, &cap, *nc + 1, sizeof *s->grp_j) != RC_OK ||
        grow((void **)&s->grp_con, &s->grp_con_cap, *nc + 1, sizeof *s->grp_con) != RC_OK)
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

/* Member mi's wall contacts (it is at the group's time): touching within sim_tol of its
 * radius and moving into the wall -- the table's criterion, the wall's rest frame --
 * while fewer than nc_max contacts are held. at_support != 0: each one's event is the
 * point of the ball's shape on the wall, not the point at its rest radius (a per_ball
 * frame's kinks are placed through their contacts' events). */
static int add_walls(rc_sim *s, size_t mi, size_t *nc, size_t nc_max, int at_support)
{
    const int32_t i = s->grp_ball[mi];
    for (int d = 0; d < s->def.dim && *nc < nc_max; d++) {
        if (!(s->walled >> d & 1u))
            continue; /* (a periodic axis) */
        const eng_ball *bi = &s->b[i];
        double v = rc_v3_get(bi->v, d), x = rc_v3_get(bi->x, d);
        if (v == 0.0)
            continue;
        double h = eng_wall_support(s, i, d);
        double gap = v > 0.0 ? s->L[d] - h - x : x - h;
        if (!(gap <= s->def.sim_tol * bi->r))
            continue;
        int w = 2 * d + (v > 0.0);
        if (have_contact(s, *nc, (int)mi, ENG_WALL(w)))
            continue;
        rc_vec3 n = rc_v3(0, 0, 0);
        rc_v3_set(&n, d, v > 0.0 ? 1.0 : -1.0);
        if (add_contact(s, nc, (int)mi, ENG_WALL(w), n) != RC_OK)
            return RC_ENOMEM;
        if (at_support)
            s->grp_con[*nc - 1].x = rc_v3_axpy(bi->x, h, n);
    }
    return RC_OK;
}

int eng_group_walls(rc_sim *s, size_t nm, size_t *nc, size_t nc_max)
{
    for (size_t mi = 0; mi < nm; mi++)
        if (add_walls(s, mi, nc, nc_max, 1) != RC_OK)
            return RC_ENOMEM;
    return RC_OK;
}

/* Find every contact simultaneous with the group's so far (gap <= sim_tol, approaching),
 * growing the group through shared balls. Members are at time T. */
static int grow_group(rc_sim *s, size_t *nm, size_t *nc, double T)
{
    const double stol = s->def.sim_tol, atol = s->def.approach_tol;
    for (size_t mi = 0; mi < *nm; mi++) {
        const int32_t i = s->grp_ball[mi];
        if (add_walls(s, mi, nc, SIZE_MAX, 0) != RC_OK)
            return RC_ENOMEM;
        int c[3];
        cell_coords(&s->g, s->a[i].cell, c);
        const eng_cells *g = &s->g;
        for (int z = -1; z <= 1; z++)
            for (int y = -1; y <= 1; y++)
                for (int x = -1; x <= 1; x++) {
                    const int32_t cell = cell_at(g, c, x, y, z); /* (wrapped if periodic) */
                    if (cell < 0)
                        continue;
                    eng_cell_it it;
                    for (int32_t k = cell_first(g, cell, &it); k >= 0; k = cell_next(g, &it)) {
                        if (k == i)
                            continue;
                        const eng_ball *bi = &s->b[i], *bk = &s->b[k];
                        rc_vec3 dx = eng_image(s, rc_v3_sub(rc_v3_axpy(bk->x, T - bk->t, bk->v),
                                                            bi->x));
                        double sig = bi->r + bk->r, lim = sig * (1.0 + stol);
                        double d2 = rc_v3_norm2(dx);
                        if (!(d2 <= lim * lim))
                            continue;
                        /* approaching (engine/approach.h: from the momenta for a pair
                         * moving together near c, whose stored velocities differ below
                         * their rounding along the motion) */
                        const rc_particle pi = {s->a[i].m, s->a[i].p};
                        const rc_particle pk = {s->a[k].m, s->a[k].p};
                        if (!eng_approaching(s->inv_c2, &pi, bi->v, &pk, bk->v, dx, sig, atol,
                                             NULL))
                            continue;
                        /* a contact the group already has (the event's own pair is met
                         * from both its balls): skip it before any costly test */
                        int known = 0;
                        for (size_t j = 0; j < *nm && !known; j++)
                            known = s->grp_ball[j] == k && have_contact(s, *nc, (int)mi, (int)j);
                        if (known)
                            continue;
                        rc_vec3 n = rc_v3_scale(1.0 / sqrt(d2), dx);
                        if (s->narrow) {
                            /* contracted shapes: the same contact test as the
                             * single-contact path's, on the states as they are */
                            const eng_check now = {{s->a[i].m, s->a[i].p}, bi->v, ENG_NONE, NULL, 0};
                            if (!eng_narrow_conflict(s, bi, bk, dx, d2, &now, &n))
                                continue;
                        }
                        int mk = member_of(s, nm, k, T);
                        if (mk < 0)
                            return RC_ENOMEM;
                        if (have_contact(s, *nc, (int)mi, mk))
                            continue;
                        if (add_contact(s, nc, (int)mi, mk, n) != RC_OK)
                            return RC_ENOMEM;
                    }
                }
    }
    return RC_OK;
}



/* Surface gap of group member mi to wall w at the members' time (negative: the shape
 * crosses the wall), relative to the ball's rest radius. */
static double wall_gap_rel(const rc_sim *s, int mi, int w)
{
    const int32_t i = s->grp_ball[mi];
    const int d = w / 2;
    const double x = rc_v3_get(s->b[i].x, d), h = eng_wall_support(s, i, d);
    return ((w & 1) ? s->L[d] - h - x : x - h) / s->b[i].r;
}

/* Count the contacts of the group that the overlap policy decides (shapes deeper in
 * each other or in a wall than overlap_tol), contacts from .. nc, on the states before
 * the collision: the event's own ball contact is counted by collide() from the frame's
 * verdict; here its wall contact and the other contacts of a group, by kind. A
 * contracted frame's group contacts are never overlapping ones (narrow_conflict asks the frame for a contact within sim_tol of now). */
static void count_overlaps(rc_sim *s, size_t from, size_t nc)
{
    const double tol = s->def.overlap_tol;
    for (size_t j = from; j < nc; j++) {
        const rc_contact *c = &s->grp_con[j];
        int kind = j == 0 ? 1 : 2;
        if (c->b < 0) {
            if (!(wall_gap_rel(s, c->a, ENG_WALL_INDEX(c->b)) < -tol))
                continue;
        } else {
            if (j == 0 || s->narrow)
                continue;
            const eng_ball *ba = &s->b[s->grp_ball[c->a]], *bb = &s->b[s->grp_ball[c->b]];
            const double sig = (ba->r + bb->r) * (1.0 - tol);
            if (!(rc_v3_norm2(rc_v3_sub(bb->x, ba->x)) < sig * sig))
                continue;
        }
        s->bk.overlaps++;
        eng_validity_policy(s);
        s->bk.overlap_kind[kind]++;
    }
}

static double contact_eps(rc_sim *s, const rc_contact *c);
static void finish(rc_sim *s, size_t nm, size_t nc, double k0, rc_vec3 p0, int kind, int single,
                   const double *J);

/* The one law-or-wall dispatch: contact c of the group among P[] with restitution c->eps,
 * by the run's law (ball-ball) or the wall law. RC_OK and RC_NO_COLLISION (not
 * approaching along n: the states are left as they were) are outcomes; any other code is
 * the law's failure, which ends the event loop with that status (rc_sim_advance) rather
 * than leaving a state the law did not stand behind. */
static int resolve_contact(rc_sim *s, rc_particle *P, const rc_contact *c)
{
    int st;
    if (c->b >= 0) {
        s->prm.eps = c->eps;
        st = s->def.law->collide(&s->prm, &P[c->a], &P[c->b], c->n);
    } else {
        st = rc_collide_wall(s->inv_c2, c->eps, &P[c->a], c->n);
    }
    return st == RC_OK || st == RC_NO_COLLISION ? RC_OK : (st < 0 ? st : RC_EINVAL);
}


/* The common case: the event's own contact alone. Resolve it, then predict both balls
 * while checking that no other contact was simultaneous with it; if one was, undo
 * (return 0) so the caller resolves the whole group. 1 when done; the law's failure
 * (negative, nothing written back). */
static int try_single(rc_sim *s, size_t nm, int32_t bp, double T, const double *tx,
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
    c->eps = contact_eps(s, c);
    rc_particle Q[2] = {P[0], nm > 1 ? P[1] : P[0]};
    const int st = resolve_contact(s, Q, c);
    if (st != RC_OK) {
        s->bk.events[RC_SIM_EV_TC] = tc_before;
        return st;
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
            return 2 + (int)j;
        }
    }
    for (size_t j = 0; j < nm; j++) {
        int32_t b = s->grp_ball[j];
        if (s->glue) {
            bat[j] = s->b[b];
            cat[j] = s->clk[b];
            gat[j] = s->cov[b];
            uat[j] = s->glu[b];
            /* (no change, no kink: a contact the law found nothing to resolve keeps the
             * ball's line and its hyperplane) */
            kinked[j] = 0;
            if (changed[j]) {
                /* hyperplanes crossing inside the ball though the centres' kinks come in
                 * order (not undone above): the tube of the two is not defined there,
                 * counted with the order conflicts (the collision can still be undone:
                 * its kink is where the model puts it) */
                if (te[j] >= s->cov[b].t_k && cross[j])
                    s->bk.order_conflicts++;
                const uint64_t oc = s->bk.order_conflicts;
                eng_glue_kink_at(s, b, &P[j], &Q[j], tx[j], dX[j], te[j], kap[j], !model);
                kinked[j] = s->bk.order_conflicts == oc && s->glu[b].r > 0.0;
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
                s->cov[b] = gat[j];
                s->glu[b] = uat[j];
            }
        }
        s->bk.events[RC_SIM_EV_TC] = tc_before;
        s->bk.order_conflicts = oc_before;
        return 0;
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
    finish(s, nm, 1, k0, p0, bp >= 0 ? RC_SIM_EV_BALL : RC_SIM_EV_WALL, 1, NULL);
    return 1;
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
                tx[0] = s->cov[i].ev_tx;
                dX[0] = s->cov[i].ev_dx;
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
            s->bk.overlaps++;
            eng_validity_policy(s);
            s->bk.overlap_kind[0]++;
        } else {
            n0 = n;
            frame_normal = 1;
        }
    }
    if (member_of(s, &nm, i, T) < 0)
        return RC_ENOMEM;
    if (bp >= 0) {
        if (member_of(s, &nm, bp, T) < 0)
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
            s->bk.overlaps++;
            eng_validity_policy(s);
            s->bk.overlap_kind[0]++;
        }
        if (add_contact(s, &nc, 0, 1, n0) != RC_OK)
            return RC_ENOMEM;
    } else {
        int w = ENG_WALL_INDEX(bp), d = w / 2;
        n0 = rc_v3(0, 0, 0);
        rc_v3_set(&n0, d, (w & 1) ? 1.0 : -1.0);
        if (add_contact(s, &nc, 0, bp, n0) != RC_OK)
            return RC_ENOMEM;
        const uint64_t ov = s->bk.overlaps;
        count_overlaps(s, 0, 1); /* (before the collision changes the shape) */
        if (wall_tube && s->bk.overlaps == ov) { /* (the overlap policy decides it) */
            s->bk.overlaps++;
            eng_validity_policy(s);
            s->bk.overlap_kind[1]++;
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
    int single = try_single(s, nm, bp, T, tx, dX, have_x, 1);
    if (single >= 2) { /* (an order conflict that undoing w's last collision resolves) */
        const int st = eng_rollback(s, s->grp_ball[single - 2], s->grp_ball[3 - single], T, tx[0]);
        if (st != 0)
            return st > 0 ? RC_OK : st;
        single = try_single(s, nm, bp, T, tx, dX, have_x, 0);
    }
    if (single != 0)
        return single > 0 ? RC_OK : single;
    if (s->def.sim_tol > 0.0) {
        int st = grow_group(s, &nm, &nc, T);
        if (st != RC_OK)
            return st;
        count_overlaps(s, 1, nc);
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
        s->grp_con[j].eps = contact_eps(s, &s->grp_con[j]);
    int kind;
    const double *J = NULL; /* the group solver's impulses, once it has solved */
    if (nc == 1) {
        const rc_contact *c = &s->grp_con[0];
        const int st = resolve_contact(s, P, c);
        if (st != RC_OK)
            return st;
        kind = c->b >= 0 ? RC_SIM_EV_BALL : RC_SIM_EV_WALL;
    } else if (!s->def.law->group) {
        /* a law without a group solver: the contacts one at a time, in the group's order
         * (the event's own first, then as grow_group found them), each on the states the
         * previous ones left -- the outcome depends on that order (relcol/sim.h) */
        kind = RC_SIM_EV_MULTI;
        for (size_t j = 0; j < nc; j++) {
            const int st = resolve_contact(s, P, &s->grp_con[j]);
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
            if ((st = resolve_contact(s, P, &s->grp_con[0])) != RC_OK)
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
    finish(s, nm, nc, k0, p0, kind, 0, J);
    return RC_OK;
}

/* Is wall contact c jammed along its axis: its ball's shape exactly as wide as the box,
 * touching the opposite wall within sim_tol of its radius? Such a contact cannot separate:
 * resolved with any restitution it sends the ball into the opposite wall at the same
 * instant, for ever. (A chain of touching balls across the box is left to the stall
 * detector: whether it is rigid along the axis depends on its geometry, papers/relcol.md,
 * "Limits".) */
static int wall_jammed(const rc_sim *s, const rc_contact *c)
{
    return wall_gap_rel(s, c->a, ENG_WALL_INDEX(c->b) ^ 1) <= s->def.sim_tol;
}

/* Restitution of a contact, elastic under the TC model when a ball's proper time since
 * its previous collision is below t_c. A wall contact jammed along its axis is perfectly
 * plastic whatever the walls' restitution and the TC model say: the rigid-wall limit of
 * the complementarity problem (the only outcome that does not push through the opposite
 * wall) -- a model choice: the motion along the axis stops, and its kinetic energy
 * becomes heat (rest mass at finite c), counted in rc_sim_diag.pinned. */
static double contact_eps(rc_sim *s, const rc_contact *c)
{
    const eng_clock *aa = &s->clk[s->grp_ball[c->a]];
    int wall = c->b < 0;
    if (wall && wall_jammed(s, c)) {
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

/* Write the group's new states (P) back, account heat and wall impulse, and predict
 * every member. In the single-contact path states, counters and predictions are done. */
/* The momentum the walls took in this event, wall by wall (s->bk.wallw). Per axis the total
 * is exact: the ball contacts of a group pass momentum only between its balls. It goes to
 * the one wall of that axis in the group; only a group touching both walls of an axis (a
 * chain of balls across the box) needs the solver's impulses J to share it: each wall
 * its own J n_d, and what the relativistic rest-mass step adds to the total shared
 * equally -- counted in wall_shared, since that split is a choice. */
static void account_walls(rc_sim *s, size_t nc, rc_vec3 p0, rc_vec3 p1, const double *J)
{
    unsigned sides[3] = {0, 0, 0};
    for (size_t j = 0; j < nc; j++)
        if (s->grp_con[j].b < 0) {
            const int w = ENG_WALL_INDEX(s->grp_con[j].b);
            sides[w / 2] |= 1u << (w & 1);
        }
    for (int d = 0; d < 3; d++) {
        const double taken = rc_v3_get(p0, d) - rc_v3_get(p1, d);
        if (sides[d] == 1u || sides[d] == 2u) {
            const int w = 2 * d + (sides[d] == 2u);
            eng_kahan(&s->bk.wallw[w], &s->bk.wallw_c[w], taken);
        } else if (sides[d] == 3u) {
            double rest = taken;
            for (size_t j = 0; j < nc; j++) {
                const rc_contact *c = &s->grp_con[j];
                if (c->b >= 0 || ENG_WALL_INDEX(c->b) / 2 != d)
                    continue;
                const double part = J ? J[j] * rc_v3_get(c->n, d) : 0.0;
                eng_kahan(&s->bk.wallw[ENG_WALL_INDEX(c->b)], &s->bk.wallw_c[ENG_WALL_INDEX(c->b)], part);
                rest -= part;
            }
            eng_kahan(&s->bk.wallw[2 * d], &s->bk.wallw_c[2 * d], 0.5 * rest);
            eng_kahan(&s->bk.wallw[2 * d + 1], &s->bk.wallw_c[2 * d + 1], 0.5 * rest);
            s->bk.wall_shared++;
        }
    }
}

static void finish(rc_sim *s, size_t nm, size_t nc, double k0, rc_vec3 p0, int kind, int single,
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
        if (!single && s->glue) { /* a group: every kink at the group's time (members are
                                     there), through the centre */
            const rc_particle in = {a->m, a->p};
            eng_glue_kink(s, b, &in, &P[j], s->b[b].t, rc_v3(0, 0, 0), 1);
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
    account_walls(s, nc, p0, p1, J);
    for (size_t j = 0; j < nm; j++) {
        if (single)
            eng_queue_update(&s->q, (uint32_t)s->grp_ball[j], key_of(&s->a[s->grp_ball[j]]));
        else
            eng_predict(s, s->grp_ball[j], 1);
    }
}


/* per_ball frames: a collision reads ball b's cold records -- its hyperplane, its glued
 * tube (copied whole for the undo record), whether its undo record is live, the read-out's
 * record -- in that order as it goes; asked for at once, their lines come in parallel
 * instead of one miss after another. (Always inlined: out of line GCC finds the function
 * free of side effects and drops its calls.) */
__attribute__((always_inline)) static inline void glue_prefetch(const rc_sim *s, int32_t b)
{
    const char *g = (const char *)&s->glu[b];
    __builtin_prefetch(&s->cov[b]);
    /* (five lines: the array is line-aligned, so a record starts at most 56 bytes into
     * its first line) */
    for (size_t o = 0; o < sizeof(rc_glue); o += 64)
        __builtin_prefetch(g + o);
    __builtin_prefetch(&s->und[b].partner);
    /* (the record a new one shifts into the previous one: whole, written at once) */
    const char *u = (const char *)&s->und[b], *up = (const char *)&s->undp[b];
    for (size_t o = 0; o < sizeof(eng_undo); o += 64) {
        __builtin_prefetch(u + o);
        __builtin_prefetch(up + o, 1);
    }
    __builtin_prefetch(&s->pend[b].depth);
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
            const int np = !s->pend ? 0 : a->ev_partner >= 0 ? 2 : 1;
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

/* ---- for engine/undo.c (resolve.h): the same functions, kept static above so that the
 * event loop's own calls stay direct and inlinable ------------------------------------ */

int eng_member_of(rc_sim *s, size_t *nm, int32_t k, double T) { return member_of(s, nm, k, T); }

int eng_add_contact(rc_sim *s, size_t *nc, int a, int b, rc_vec3 n)
{
    return add_contact(s, nc, a, b, n);
}

double eng_contact_eps(rc_sim *s, const rc_contact *c) { return contact_eps(s, c); }

int eng_resolve_contact(rc_sim *s, rc_particle *P, const rc_contact *c)
{
    return resolve_contact(s, P, c);
}

void eng_finish(rc_sim *s, size_t nm, size_t nc, double k0, rc_vec3 p0, int kind, int single,
                const double *J)
{
    finish(s, nm, nc, k0, p0, kind, single, J);
}

void eng_account_walls(rc_sim *s, size_t nc, rc_vec3 p0, rc_vec3 p1, const double *J)
{
    account_walls(s, nc, p0, p1, J);
}
