/* engine/group.c — a group of contacts at one event (the event's own, the simultaneous ones,
 * the members' walls), its restitution, the one law-or-wall dispatch and the books; below both
 * the event loop and the per-ball model, which build their groups with it. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "approach.h"
#include "group.h"
#include "model.h"
#include "relcol/status.h"

/* Member mi's wall contacts within sim_tol of touching and moving in (the wall's rest frame),
 * up to nc_max; at_support: each event at the shape's point on the wall, where a per_ball
 * frame's kink goes through it. */
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
        if (eng_have_contact(s, *nc, (int)mi, ENG_WALL(w)))
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
                        /* approaching (engine/approach.h: from the momenta, for a pair moving
                         * together near c) */
                        const rc_particle pi = {s->a[i].m, s->a[i].p};
                        const rc_particle pk = {s->a[k].m, s->a[k].p};
                        if (!eng_approaching(s->inv_c2, &pi, bi->v, &pk, bk->v, dx, sig, atol,
                                             NULL))
                            continue;
                        /* a contact the group already has (the event's own pair is met
                         * from both its balls): skip it before any costly test */
                        int known = 0;
                        for (size_t j = 0; j < *nm && !known; j++)
                            known = s->grp_ball[j] == k && eng_have_contact(s, *nc, (int)mi, (int)j);
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
                        if (eng_have_contact(s, *nc, (int)mi, mk))
                            continue;
                        if (eng_add_contact(s, nc, (int)mi, mk, n) != RC_OK)
                            return RC_ENOMEM;
                    }
                }
    }
    return RC_OK;
}



/* Count the group's contacts the overlap policy decides, by kind, on the states before the
 * collision (the event's own ball contact is collide()'s to count). */
void eng_count_overlaps(rc_sim *s, size_t from, size_t nc)
{
    const double tol = s->def.overlap_tol;
    for (size_t j = from; j < nc; j++) {
        const rc_contact *c = &s->grp_con[j];
        int kind = j == 0 ? 1 : 2;
        if (c->b < 0) {
            if (!(eng_wall_gap_rel(s, c->a, ENG_WALL_INDEX(c->b)) < -tol))
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

/* The momentum the walls took, wall by wall: exact per axis, since ball contacts pass it only
 * between balls; a group touching both walls of an axis shares it by the solver's J, a choice
 * counted in wall_shared. */
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
