/* engine/undo.c — per_ball frames: undoing a ball's last collision when a third ball
 * meets it before that kink along its tube, and solving the two contacts together
 * (papers/shape-change.md, section 7). The record is written by the single-contact path
 * (eng_write_undo), read here. */
#include <math.h>
#include <string.h>

#include "resolve.h"
#include "relcol/status.h"

/* per_ball frames: after a single contact of the model (model != 0) every member whose
 * line kinked cleanly gets the record that undoes it (eng_undo); any other collision
 * leaves the members' records stale (their counters moved) or clears them. */
void eng_write_undo(rc_sim *s, size_t nm, int32_t bp, int model, const rc_particle *P,
                    const rc_vec3 *vold, const eng_clock *cat, const eng_cov *gat,
                    const rc_glue *uat, const double *tx, const rc_vec3 *dX,
                    const int *kinked, int tc)
{
    const rc_vec3 n0 = s->grp_con[0].n;
    for (size_t j = 0; j < nm; j++) {
        const int32_t b = s->grp_ball[j];
        eng_undo *u = &s->und[b];
        const int32_t o = nm > 1 ? s->grp_ball[1 - j] : ENG_NONE;
        if (!model || !kinked[j] || (nm > 1 && !kinked[1 - j])) {
            u->partner = ENG_NONE;
            continue;
        }
        const double te = s->cov[b].t_k; /* (its kink E: X - E, the same on both lines) */
        u->in = P[j];
        u->cov = gat[j];
        u->glu = uat[j];
        u->tau_last = cat[j].tau_last;
        u->n = j == 0 ? n0 : rc_v3_scale(-1.0, n0);
        u->dt = tx[j] - te;
        u->dx = rc_v3_axpy(dX[j], tx[j] - te, vold[j]);
        u->partner = nm > 1 ? (int32_t)s->id[o] : bp;
        u->cnt = s->cnt[b];
        u->pcnt = nm > 1 ? s->cnt[o] : 0;
        u->tc = (uint32_t)(tc && j == 0) | (uint32_t)(j == 0) << 1;
    }
}

/* Ball b back on its incoming line: stored at its kink E (where the collision's moments
 * were taken), with the momentum, hyperplane, glued tube and clock it had before. *xe:
 * E's position. */
static void to_incoming(rc_sim *s, int32_t b, rc_vec3 *xe)
{
    const eng_undo *u = &s->und[b];
    eng_advance_ball(s, b, s->cov[b].t_k);
    *xe = s->b[b].x;
    s->a[b].m = u->in.m;
    s->a[b].p = u->in.p;
    s->b[b].v = rc_v3_scale(1.0 / eng_mass_rel(u->in.m, u->in.p, s->inv_c2), u->in.p);
    s->cov[b] = u->cov;
    s->glu[b] = u->glu;
    s->clk[b].tau_last = u->tau_last;
    if (s->slc_n) /* (a delayed slice at or after the undone kink: the incoming line) */
        eng_slice_undo(s, b);
}

/* Can ball w's last collision be undone for a contact with ball k: a single contact of
 * the model, neither w nor its partner (not k) has collided since. */
int eng_undoable(const rc_sim *s, int32_t w, int32_t k)
{
    const eng_undo *u = &s->und[w];
    if (u->partner == ENG_NONE || u->cnt != s->cnt[w])
        return 0;
    if (u->partner < 0)
        return 1;
    const int32_t j = (int32_t)s->slot[u->partner];
    return j != k && s->cnt[j] == u->pcnt && s->und[j].partner == (int32_t)s->id[w] &&
           s->und[j].cnt == s->cnt[j];
}

/* Ball w met ball k before its last kink along its tube (a tube conflict at the
 * prediction's X, table time tx; an overlap the frame reported: tx = inf). If that kink
 * was a single contact of the model (with ball j or a wall) and neither w nor j has
 * collided since, the collision is undone (its books too) and w's two contacts -- the one
 * with j as it was, the one with k as the frame finds it from w's incoming line -- are
 * solved together by the group rule (the scenario's, relcol/sim.h), each ball's velocity
 * changed at its own kink: j's and k's through their contact's event, w's through the
 * later of its two (so that both lie on its incoming piece, whose state the impulses act
 * on). The group's members get no undo record (a choice: it bounds the work, and a
 * conflict with one of them goes to the overlap policy). 1 when done; 0 when it does not
 * apply (nothing changed); the law's failure (negative). */
int eng_rollback(rc_sim *s, int32_t w, int32_t k, double T, double tx)
{
    if (!eng_undoable(s, w, k))
        return 0;
    const eng_undo uw = s->und[w];
    const int ball = uw.partner >= 0;
    const int32_t j = ball ? (int32_t)s->slot[uw.partner] : ENG_NONE;
    /* w on its incoming line (its records kept, to put back if there is no contact of the
     * model); the frame is asked from a pair's light-crossing time before both the
     * conflict's X and w's kink: from t0 = min(t_X, t_E) itself the pair's ZMF, whose
     * simultaneity tilts by up to that much across the pair, often found the two already
     * overlapping (papers/shape-change.md, section 7) */
    const eng_ball sb = s->b[w];
    const eng_aux sa = s->a[w];
    const eng_clock sc = s->clk[w];
    const eng_cov sg = s->cov[w];
    const rc_glue su = s->glu[w];
    const rc_particle out_w = {s->a[w].m, s->a[w].p};
    rc_vec3 xe_w, xe_j = rc_v3(0, 0, 0);
    const double te_w = s->cov[w].t_k;
    to_incoming(s, w, &xe_w);
    double t2;
    rc_vec3 dX2, n2;
    const double t0 = (tx < te_w ? tx : te_w) - (s->b[w].r + s->b[k].r) * s->inv_c;
    if (eng_pair_contact(s, w, k, t0, &t2, &dX2, &n2) != RC_OK) {
        s->b[w] = sb;
        s->a[w] = sa;
        s->clk[w] = sc;
        s->cov[w] = sg;
        s->glu[w] = su;
        if (s->slc_nd) /* (slices to_incoming moved: back on w's line before it kinks again) */
            eng_slice_flush(s);
        return 0;
    }
    s->bk.rollbacks++;
    /* the collision's books, taken back: its moments at the kinks it was taken at, in its
     * members' order; heat and momentum with the same operations, negated */
    rc_particle in[2] = {uw.in, uw.in}, out[2] = {out_w, out_w};
    double te_j = 0.0;
    int32_t mem[2] = {w, j};
    size_t n0 = 1;
    if (ball) {
        out[1] = (rc_particle){s->a[j].m, s->a[j].p};
        in[1] = s->und[j].in;
        te_j = s->cov[j].t_k;
        to_incoming(s, j, &xe_j);
        n0 = 2;
        if (!(uw.tc & 2u)) { /* (j was the event's first ball) */
            mem[0] = j;
            mem[1] = w;
            const rc_particle ti = in[0], to = out[0];
            in[0] = in[1];
            out[0] = out[1];
            in[1] = ti;
            out[1] = to;
        }
    }
    eng_moments_add(s, n0, mem, out, in);
    double k0 = 0.0, k1 = 0.0;
    rc_vec3 p0 = rc_v3(0, 0, 0), p1 = rc_v3(0, 0, 0);
    for (size_t m = 0; m < n0; m++) {
        k0 += eng_kinetic(&in[m], s->inv_c2);
        p0 = rc_v3_add(p0, in[m].p);
        k1 += eng_kinetic(&out[m], s->inv_c2);
        p1 = rc_v3_add(p1, out[m].p);
    }
    eng_kahan(&s->bk.heat, &s->bk.heat_c, -(k0 - k1));
    eng_kahan(&s->bk.wall[0], &s->bk.wall_c[0], -(p0.x - p1.x));
    eng_kahan(&s->bk.wall[1], &s->bk.wall_c[1], -(p0.y - p1.y));
    eng_kahan(&s->bk.wall[2], &s->bk.wall_c[2], -(p0.z - p1.z));
    size_t nm = 0, nc = 0;
    if (eng_member_of(s, &nm, w, T) < 0)
        return RC_ENOMEM;
    if (!ball) {
        if (eng_add_contact(s, &nc, 0, uw.partner, uw.n) != RC_OK)
            return RC_ENOMEM;
        eng_account_walls(s, 1, p1, p0, NULL); /* (taken: p1 - p0, the original's negated) */
        nc = 0;
    }
    /* the read-out's records of w and j (eng_pend) back to before the undone kinks, then
     * noted for the group's kinks like any event's balls */
    eng_pend_snap ps[3];
    size_t nps = 0;
    if (s->pend) {
        eng_pend_undo(&s->pend[w], te_w);
        ps[nps++] = eng_pend_take(s, w);
        if (ball) {
            eng_pend_undo(&s->pend[j], te_j);
            ps[nps++] = eng_pend_take(s, j);
        }
        ps[nps++] = eng_pend_take(s, k);
    }
    s->bk.events[ball ? RC_SIM_EV_BALL : RC_SIM_EV_WALL]--;
    s->bk.collisions--;
    s->bk.events[RC_SIM_EV_TC] -= (uw.tc | (ball ? s->und[j].tc : 0u)) & 1u; /* (the first
                                                                      ball's record has it) */
    s->und[w].partner = ENG_NONE;
    if (ball)
        s->und[j].partner = ENG_NONE;
    /* the group: w, j, k at T (w and j on their incoming lines) */
    const int mj = ball ? eng_member_of(s, &nm, j, T) : 0, mk = eng_member_of(s, &nm, k, T);
    if (mj < 0 || mk < 0)
        return RC_ENOMEM;
    const double tw[2] = {te_w + uw.dt, t2};
    const rc_vec3 xw[2] = {rc_v3_add(xe_w, uw.dx), rc_v3_add(rc_v3_axpy(xe_w, t2 - te_w, s->b[w].v), dX2)};
    if (eng_add_contact(s, &nc, 0, ball ? mj : uw.partner, uw.n) != RC_OK ||
        eng_add_contact(s, &nc, 0, mk, n2) != RC_OK)
        return RC_ENOMEM;
    for (size_t c = 0; c < 2; c++) { /* the events, in w's coordinates */
        s->grp_con[c].t = tw[c];
        s->grp_con[c].x = xw[c];
    }
    rc_particle *P = s->grp_part;
    rc_particle B[3];
    k0 = 0.0;
    p0 = rc_v3(0, 0, 0);
    for (size_t m = 0; m < nm; m++) {
        P[m] = (rc_particle){s->a[s->grp_ball[m]].m, s->a[s->grp_ball[m]].p};
        B[m] = P[m];
        k0 += eng_kinetic(&P[m], s->inv_c2);
        p0 = rc_v3_add(p0, P[m].p);
    }
    for (size_t c = 0; c < nc; c++)
        s->grp_con[c].eps = eng_contact_eps(s, &s->grp_con[c]);
    const double *J = NULL;
    int st = s->def.law->group ? s->def.law->group(&s->prm, nm, P, nc, s->grp_con, s->grp_j)
                               : RC_EINVAL;
    if (st == RC_OK) {
        J = s->grp_j;
    } else {
        /* no group solver, or none found: the two contacts one after the other, in the
         * order of their events' table times (a choice; counted) */
        if (s->def.law->group)
            s->bk.group_fallbacks++;
        else
            s->bk.group_sequential++;
        for (size_t m = 0; m < nm; m++)
            P[m] = B[m];
        const size_t first = tw[1] < tw[0];
        if ((st = eng_resolve_contact(s, P, &s->grp_con[first])) != RC_OK ||
            (st = eng_resolve_contact(s, P, &s->grp_con[1 - first])) != RC_OK)
            return st;
    }
    /* each member's kink through its contact's event (w: the later of its two) */
    for (size_t m = 0; m < nm; m++) {
        const int32_t b = s->grp_ball[m];
        if (P[m].m == B[m].m && memcmp(&P[m].p, &B[m].p, sizeof P[m].p) == 0)
            continue;
        size_t c = m == (size_t)mk ? 1 : 0;
        const eng_ball *bb = &s->b[b];
        rc_vec3 d[2];
        for (size_t q = 0; q < 2; q++)
            d[q] = eng_image(s, rc_v3_sub(xw[q], rc_v3_axpy(bb->x, tw[q] - bb->t, bb->v)));
        if (b == w) {
            rc_vec3 kap;
            c = eng_kink_time(s, b, &B[m], &P[m], tw[1], d[1], &kap) >
                eng_kink_time(s, b, &B[m], &P[m], tw[0], d[0], &kap);
        }
        eng_glue_kink(s, b, &B[m], &P[m], tw[c], d[c], 0);
    }
    for (size_t m = 0; m < nm; m++) {
        const int32_t b = s->grp_ball[m];
        s->a[b].m = P[m].m;
        s->a[b].p = P[m].p;
        s->b[b].v = rc_v3_scale(1.0 / eng_mass_rel(P[m].m, P[m].p, s->inv_c2), P[m].p);
        s->cnt[b]++;
        s->und[b].partner = ENG_NONE;
    }
    eng_moments_add(s, nm, s->grp_ball, B, P);
    for (size_t m = 0; m < nm; m++)
        eng_predict(s, s->grp_ball[m], 0);
    eng_finish(s, nm, nc, k0, p0, RC_SIM_EV_MULTI, 1, J);
    for (size_t q = 0; q < nps; q++)
        eng_pend_note(s, &ps[q]);
    return 1;
}

/* Which collision a conflict at ball i's event with partner bp can undo: a tube
 * conflict's X (the prediction's) on the incoming side of exactly one ball's hyperplane
 * names that ball; an overlap the frame reported (no X) tries the ball with the later
 * kink, then the other. 1 done, 0 none applies, or the law's failure. */
int eng_undo_conflict(rc_sim *s, int32_t i, int32_t bp, double T, int tube)
{
    if (tube) {
        const double tx = s->cov[i].ev_tx;
        const rc_vec3 dXi = s->cov[i].ev_dx;
        const eng_ball *bi = &s->b[i], *bq = &s->b[bp];
        const rc_vec3 sep = eng_image(s, rc_v3_sub(rc_v3_axpy(bq->x, tx - bq->t, bq->v),
                                                   rc_v3_axpy(bi->x, tx - bi->t, bi->v)));
        const int in_i = !eng_glue_side(&s->cov[i], &s->glu[i], s->b[i].v, tx, dXi),
                  in_q = !eng_glue_side(&s->cov[bp], &s->glu[bp], s->b[bp].v, tx,
                                        rc_v3_sub(dXi, sep));
        if (in_i == in_q) {
            return 0;
        }
        return in_i ? eng_rollback(s, i, bp, T, tx) : eng_rollback(s, bp, i, T, tx);
    }
    const int later = s->cov[bp].t_k > s->cov[i].t_k;
    const int32_t w0 = later ? bp : i, w1 = later ? i : bp;
    const int st = eng_rollback(s, w0, w1, T, INFINITY);
    return st != 0 ? st : eng_rollback(s, w1, w0, T, INFINITY);
}
