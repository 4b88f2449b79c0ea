/* engine/field.c — the event loop for balls on curved paths (a uniform field,
 * papers/gravity.md), reaching the path through engine/path.h's ops alone. It shares the
 * engine's state, queue and cells with engine/core.c (so checkpoints, readouts and the
 * hash are the same code), and differs where the straight line is built in there: a
 * ball's events are the plane times of the walls and its cell's faces and the pair times
 * of its 3^d block, each from the two stored states brought to one instant of the clock.
 *
 * Cells: a ball stays in its cell until its crossing, where it is brought to the face
 * (put on it exactly) and predicted afresh. A pair contact is looked for only up to the
 * asking ball's next crossing (or its best event): the contact of two balls in adjacent
 * cells at t is then found by the prediction of whichever ball had the later event before
 * t, for the cells do not change between that event and t.
 *
 * Contacts are resolved one at a time with the law at the contact, in the local inertial
 * frame: the table frame (newtonian) or the box's momentary rest frame K_tau
 * (equivalence), where the stored momenta are the local ones and the one box instant is
 * one instant. Contacts that fall at one instant are taken one after another in the
 * queue's order (no simultaneous group: relcol/sim.h). */
#include <math.h>
#include <string.h>

#include "path.h"
#include "resolve.h"
#include "relcol/status.h"

/* a path op's failure: the first one is kept and returned by the loop */
static void fail(rc_sim *s, int st)
{
    if (!s->fld_err)
        s->fld_err = st;
}

/* ball i's stored state taken to T >= its clock on its path */
static int advance_to(rc_sim *s, int32_t i, double T)
{
    eng_ball *b = &s->b[i];
    eng_aux *a = &s->a[i];
    const double h = T - b->t;
    if (!(h > 0.0))
        return RC_OK;
    rc_vec3 x = b->x, p = a->p;
    double dtau = 0.0;
    const int st = s->path->drift(s, a->m, &x, &p, h, &dtau);
    if (st != RC_OK)
        return st;
    b->x = x;
    a->p = p;
    b->v = rc_v3_scale(1.0 / eng_mass_rel(a->m, p, s->inv_c2), p);
    s->clk[i].tau += dtau;
    b->t = T;
    return RC_OK;
}

/* The time ball i (at now) reaches the plane x_d = X, from the side it is on; moving out
 * through it while already on or past it (a rounding past a face it is put on) is now. */
static double plane_at(rc_sim *s, int32_t i, int d, double X, int up)
{
    const eng_ball *b = &s->b[i];
    const double x = rc_v3_get(b->x, d), pd = rc_v3_get(s->a[i].p, d);
    if (up ? (x >= X && pd > 0.0) : (x <= X && pd < 0.0))
        return s->now;
    double dt;
    const int st = s->path->plane_time(s, s->a[i].m, b->x, s->a[i].p, d, X, &dt);
    if (st == RC_MISS)
        return INFINITY;
    if (st != RC_OK) {
        fail(s, st);
        return INFINITY;
    }
    return s->now + dt;
}

/* the next face of its cell ball i reaches that is not the box's wall: cross_t, code */
static void cross_time(rc_sim *s, int32_t i, const int c[3])
{
    const eng_cells *g = &s->g;
    double best = INFINITY;
    int32_t code = -1;
    for (int d = 0; d < s->def.dim; d++) {
        if (c[d] > g->dn_lim[d]) {
            const double t = plane_at(s, i, d, c[d] * g->w[d], 0);
            if (t < best)
                best = t, code = 2 * d;
        }
        if (c[d] < g->up_lim[d]) {
            const double t = plane_at(s, i, d, (c[d] + 1) * g->w[d], 1);
            if (t < best)
                best = t, code = 2 * d + 1;
        }
    }
    s->a[i].cross_t = best;
    s->a[i].cross_code = code;
}

/* the walls of the boundary cells: the centre at r from a wall */
static void wall_time(rc_sim *s, int32_t i, const int c[3], double *best, int32_t *bp)
{
    const double r = s->b[i].r;
    for (int d = 0; d < s->def.dim; d++) {
        if (!(s->walled >> d & 1u))
            continue;
        if (c[d] == 0) {
            const double t = plane_at(s, i, d, r, 0);
            if (t < *best)
                *best = t, *bp = ENG_WALL(2 * d);
        }
        if (c[d] == s->g.n[d] - 1) {
            const double t = plane_at(s, i, d, s->L[d] - r, 1);
            if (t < *best)
                *best = t, *bp = ENG_WALL(2 * d + 1);
        }
    }
}

/* balls i (at now) and k: the contact time, from both brought to now (k's copy), k as
 * its nearest image; INFINITY if none by horizon */
static double pair_at(rc_sim *s, int32_t i, int32_t k, double horizon)
{
    const eng_ball *bi = &s->b[i], *bk = &s->b[k];
    rc_vec3 xk = bk->x, pk = s->a[k].p;
    if (s->now > bk->t) {
        const int st = s->path->drift(s, s->a[k].m, &xk, &pk, s->now - bk->t, NULL);
        if (st != RC_OK) {
            fail(s, st);
            return INFINITY;
        }
    }
    const rc_toi_ball A = {bi->x, bi->r, s->a[i].m, s->a[i].p};
    const rc_toi_ball B = {rc_v3_add(bi->x, eng_image(s, rc_v3_sub(xk, bi->x))), bk->r,
                           s->a[k].m, pk};
    double dt;
    const int st = s->path->pair_time(s, &A, &B, horizon - s->now, &dt);
    /* a contact now (touching, or overlapping: the overlap policy along the centre line)
     * is one only if the law sees the pair approach: the slice's distance can shrink
     * while (v_k - v_i).n > 0 (the lapses differ), and the law would find nothing to
     * resolve, for ever at this instant. Such a pair parts within a rounding's depth. */
    if ((st == RC_OK && dt == 0.0) || st == RC_EOVERLAP) {
        const rc_vec3 dv = rc_v3_sub(rc_v3_scale(1.0 / eng_mass_rel(B.m, B.p, s->inv_c2), B.p),
                                     bi->v);
        return rc_v3_dot(rc_v3_sub(B.x, A.x), dv) < 0.0 ? s->now : INFINITY;
    }
    if (st == RC_OK)
        return s->now + dt;
    if (st != RC_MISS)
        fail(s, st);
    return INFINITY;
}

void eng_field_predict(rc_sim *s, int32_t i, int update_heap)
{
    const int st = advance_to(s, i, s->now); /* (a stale event's ball: at its own clock) */
    if (st != RC_OK)
        fail(s, st);
    int c[3];
    cell_coords(&s->g, s->a[i].cell, c);
    cross_time(s, i, c);
    double best = INFINITY;
    int32_t bp = ENG_NONE;
    wall_time(s, i, c, &best, &bp);
    const int dz = s->def.dim == 3 ? 1 : 0;
    for (int oz = -dz; oz <= dz; oz++)
        for (int oy = -1; oy <= 1; oy++)
            for (int ox = -1; ox <= 1; ox++) {
                const int32_t cell = cell_at(&s->g, c, ox, oy, oz);
                if (cell < 0)
                    continue;
                eng_cell_it it;
                for (int32_t k = cell_first(&s->g, cell, &it); k >= 0; k = cell_next(&s->g, &it)) {
                    if (k == i)
                        continue;
                    const double horizon = best < s->a[i].cross_t ? best : s->a[i].cross_t;
                    const double t = pair_at(s, i, k, horizon);
                    if (t < best)
                        best = t, bp = k;
                }
            }
    eng_aux *a = &s->a[i];
    a->ev_t = best;
    a->ev_partner = bp;
    a->ev_pcount = bp >= 0 ? s->cnt[bp] : 0;
    if (update_heap)
        eng_queue_update(&s->q, (uint32_t)i, key_of(a));
}

/* the energy a contact's members' change of weight books: g z dw each (papers/gravity.md
 * section 4) */
static void book_weight(rc_sim *s, int32_t b, const rc_particle *before, const rc_particle *after)
{
    const double z = rc_v3_get(s->b[b].x, s->fld_axis);
    const double dw = s->path->weight(s, after->m, after->p) - s->path->weight(s, before->m, before->p);
    eng_kahan(&s->fld_work[0], &s->fld_work[1], s->def.g * z * dw);
}

/* a member's new state written, its counter moved */
static void put_state(rc_sim *s, int32_t b, const rc_particle *q)
{
    s->a[b].m = q->m;
    s->a[b].p = q->p;
    s->b[b].v = rc_v3_scale(1.0 / eng_mass_rel(q->m, q->p, s->inv_c2), q->p);
    s->cnt[b]++;
    s->clk[b].tau_last = s->clk[b].tau;
}

/* the TC model's restitution for a contact of balls a (and b, or -1) */
static double contact_eps(rc_sim *s, int32_t a, int32_t b, double eps)
{
    const double tc = s->def.t_c;
    int elastic = tc > 0.0 && s->clk[a].tau - s->clk[a].tau_last < tc;
    if (b >= 0)
        elastic = elastic || (tc > 0.0 && s->clk[b].tau - s->clk[b].tau_last < tc);
    s->bk.events[RC_SIM_EV_TC] += (uint64_t)(elastic && eps != 1.0);
    return elastic ? 1.0 : eps;
}

static int collide_pair(rc_sim *s, int32_t i, int32_t k)
{
    int st = advance_to(s, i, s->now);
    if (st == RC_OK)
        st = advance_to(s, k, s->now);
    if (st != RC_OK)
        return st;
    const rc_vec3 dx = eng_image(s, rc_v3_sub(s->b[k].x, s->b[i].x));
    const double len = rc_v3_norm(dx), sig = s->b[i].r + s->b[k].r;
    if (len < sig * (1.0 - s->def.overlap_tol)) {
        s->bk.overlaps++;
        s->bk.overlap_kind[0]++;
    }
    const rc_vec3 n = len > 0.0 ? rc_v3_scale(1.0 / len, dx) : rc_v3(1.0, 0.0, 0.0);
    const rc_particle P[2] = {{s->a[i].m, s->a[i].p}, {s->a[k].m, s->a[k].p}};
    rc_particle Q[2] = {P[0], P[1]};
    s->prm.eps = contact_eps(s, i, k, s->def.eps_ball);
    st = s->def.law->collide(&s->prm, &Q[0], &Q[1], n);
    if (st != RC_OK && st != RC_NO_COLLISION)
        return st < 0 ? st : RC_EINVAL;
    if (st == RC_NO_COLLISION) { /* (nothing to resolve: predicted afresh) */
        eng_field_predict(s, i, 1);
        eng_field_predict(s, k, 1);
        return RC_OK;
    }
    const double k0 = eng_kinetic(&P[0], s->inv_c2) + eng_kinetic(&P[1], s->inv_c2);
    const double k1 = eng_kinetic(&Q[0], s->inv_c2) + eng_kinetic(&Q[1], s->inv_c2);
    eng_kahan(&s->bk.heat, &s->bk.heat_c, k0 - k1);
    book_weight(s, i, &P[0], &Q[0]);
    book_weight(s, k, &P[1], &Q[1]);
    put_state(s, i, &Q[0]);
    put_state(s, k, &Q[1]);
    s->bk.collisions++;
    s->bk.events[RC_SIM_EV_BALL]++;
    eng_field_predict(s, i, 1);
    eng_field_predict(s, k, 1);
    return RC_OK;
}

static int collide_wall(rc_sim *s, int32_t i, int w)
{
    const int st0 = advance_to(s, i, s->now);
    if (st0 != RC_OK)
        return st0;
    const int d = w / 2, far = w & 1;
    eng_ball *b = &s->b[i];
    /* on the wall exactly (the wall is at rest in the local frame) */
    rc_v3_set(&b->x, d, far ? s->L[d] - b->r : b->r);
    rc_vec3 n = rc_v3(0, 0, 0);
    rc_v3_set(&n, d, far ? 1.0 : -1.0);
    const rc_particle P = {s->a[i].m, s->a[i].p};
    rc_particle Q = P;
    const int st = rc_collide_wall(s->inv_c2, contact_eps(s, i, -1, s->def.eps_wall), &Q, n);
    if (st != RC_OK && st != RC_NO_COLLISION)
        return st < 0 ? st : RC_EINVAL;
    eng_kahan(&s->bk.heat, &s->bk.heat_c, eng_kinetic(&P, s->inv_c2) - eng_kinetic(&Q, s->inv_c2));
    const double dp = rc_v3_get(P.p, d) - rc_v3_get(Q.p, d);
    eng_kahan(&s->bk.wall[d], &s->bk.wall_c[d], dp);
    eng_kahan(&s->bk.wallw[w], &s->bk.wallw_c[w], dp);
    book_weight(s, i, &P, &Q);
    put_state(s, i, &Q);
    s->bk.collisions++;
    s->bk.events[RC_SIM_EV_WALL]++;
    eng_field_predict(s, i, 1);
    return RC_OK;
}

/* ball i onto the face it reaches (put on it exactly), into the next cell, predicted */
static int cross(rc_sim *s, int32_t i)
{
    const int st = advance_to(s, i, s->now);
    if (st != RC_OK)
        return st;
    eng_aux *a = &s->a[i];
    const int d = a->cross_code / 2, up = a->cross_code & 1;
    int c[3];
    cell_coords(&s->g, a->cell, c);
    rc_v3_set(&s->b[i].x, d, (c[d] + up) * s->g.w[d]);
    c[d] += up ? 1 : -1;
    if (c[d] < 0 || c[d] >= s->g.n[d]) { /* (a periodic face: cross_time) */
        const int dir = up ? 1 : -1;
        c[d] = c[d] < 0 ? s->g.n[d] - 1 : 0;
        rc_v3_set(&s->b[i].x, d, rc_v3_get(s->b[i].x, d) - dir * s->L[d]);
        s->img[3 * (size_t)i + (size_t)d] += dir;
    }
    eng_cells_remove(&s->g, s->a, i);
    eng_cells_insert(&s->g, s->a, i, (int32_t)(c[0] + s->g.n[0] * (c[1] + s->g.n[1] * c[2])));
    s->bk.events[RC_SIM_EV_CELL]++;
    eng_field_predict(s, i, 1);
    return RC_OK;
}

int eng_field_run(rc_sim *s, double t_end, uint64_t max_events)
{
    uint64_t done = 0;
    const uint64_t stall_limit = 10000 + 64 * (uint64_t)s->n; /* (engine/core.c's) */
    s->fld_err = 0;
    while (s->n > 0) {
        double top_t;
        uint32_t top;
        eng_queue_top(&s->q, &top_t, &top);
        if (!(top_t <= t_end) || top_t == INFINITY)
            break;
        if (max_events && done >= max_events)
            return RC_OK;
        const int32_t i = (int32_t)top;
        eng_aux *a = &s->a[i];
        const int stale = a->cross_t > a->ev_t && a->ev_partner >= 0 &&
                          s->cnt[a->ev_partner] != a->ev_pcount;
        if (!stale) {
            if (top_t == s->bk.still_t) {
                if (++s->bk.still_count > stall_limit) {
                    s->bk.stall_ball = s->id[i];
                    s->bk.stall_partner = a->ev_partner >= 0 ? (int64_t)s->id[a->ev_partner]
                                                             : (int64_t)a->ev_partner;
                    return RC_ESTALL;
                }
            } else {
                s->bk.still_t = top_t;
                s->bk.still_count = 0;
            }
        }
        s->now = top_t;
        done++;
        int st;
        if (a->cross_t <= a->ev_t) {
            st = cross(s, i);
        } else if (stale) {
            s->bk.events[RC_SIM_EV_STALE]++;
            eng_field_predict(s, i, 1);
            st = RC_OK;
        } else if (a->ev_partner >= 0) {
            st = collide_pair(s, i, a->ev_partner);
        } else {
            st = collide_wall(s, i, ENG_WALL_INDEX(a->ev_partner));
        }
        if (st == RC_OK && s->fld_err)
            st = s->fld_err;
        if (st != RC_OK) {
            s->fld_err = 0;
            return st;
        }
    }
    if (isfinite(t_end))
        s->now = t_end;
    return RC_OK;
}

int rc_sim_field_energy(const rc_sim *s, double *h, double *booked)
{
    if (!s || !h || !booked || !s->def.gravity)
        return RC_EINVAL;
    double sum = 0.0, comp = 0.0;
    for (size_t k = 0; k < s->n; k++) {
        rc_sim_ball b;
        eng_ball_now(s, k, &b, 0);
        double e;
        const int st = s->path->energy(s, b.m, b.x, b.p, &e);
        if (st != RC_OK)
            return st;
        eng_kahan(&sum, &comp, e);
    }
    *h = sum + s->bk.heat;
    *booked = s->fld_work[0];
    return RC_OK;
}
