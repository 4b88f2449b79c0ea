/* engine/group.c — a group of contacts at one event: its members and contacts (the
 * event's own, the simultaneous ones by the gap rule, the members' walls), restitution
 * (TC model, jammed walls), the one law-or-wall dispatch, and the books after it. Below
 * both the event loop (engine/core.c) and the per-ball model's undo and groups
 * (engine/perball/), which build their groups with the same calls. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "approach.h"
#include "group.h"
#include "model.h"
#include "relcol/status.h"

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
int eng_member_of(rc_sim *s, size_t *nm, int32_t k, double T)
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

int eng_add_contact(rc_sim *s, size_t *nc, int a, int b, rc_vec3 n)
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
        if (eng_add_contact(s, nc, (int)mi, ENG_WALL(w), n) != RC_OK)
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
int eng_grow_group(rc_sim *s, size_t *nm, size_t *nc, double T)
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
                        int mk = eng_member_of(s, nm, k, T);
                        if (mk < 0)
                            return RC_ENOMEM;
                        if (have_contact(s, *nc, (int)mi, mk))
                            continue;
                        if (eng_add_contact(s, nc, (int)mi, mk, n) != RC_OK)
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
void eng_count_overlaps(rc_sim *s, size_t from, size_t nc)
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
        eng_note_overlap(s, kind);
    }
}

/* The one law-or-wall dispatch: contact c of the group among P[] with restitution c->eps,
 * by the run's law (ball-ball) or the wall law. RC_OK and RC_NO_COLLISION (not
 * approaching along n: the states are left as they were) are outcomes; any other code is
 * the law's failure, which ends the event loop with that status (rc_sim_advance) rather
 * than leaving a state the law did not stand behind. */
int eng_resolve_contact(rc_sim *s, rc_particle *P, const rc_contact *c)
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
double eng_contact_eps(rc_sim *s, const rc_contact *c)
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

/* The momentum the walls took in this event, wall by wall (s->bk.wallw). Per axis the total
 * is exact: the ball contacts of a group pass momentum only between its balls. It goes to
 * the one wall of that axis in the group; only a group touching both walls of an axis (a
 * chain of balls across the box) needs the solver's impulses J to share it: each wall
 * its own J n_d, and what the relativistic rest-mass step adds to the total shared
 * equally -- counted in wall_shared, since that split is a choice. */
void eng_account_walls(rc_sim *s, size_t nc, rc_vec3 p0, rc_vec3 p1, const double *J)
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

void eng_finish(rc_sim *s, size_t nm, size_t nc, double k0, rc_vec3 p0, int kind, int single,
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
    for (size_t j = 0; j < nm; j++) {
        if (single)
            eng_queue_update(&s->q, (uint32_t)s->grp_ball[j], key_of(&s->a[s->grp_ball[j]]));
        else
            eng_predict(s, s->grp_ball[j], 1);
    }
}
