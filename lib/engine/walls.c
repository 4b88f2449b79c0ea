/* engine/walls.c — the walls' rules (relcol/wall.h) as the engine calls them: one op per
 * wall contact, and what each wall took from the balls, noted contact by contact and
 * booked when the event is done (so an event taken back books nothing). */
#include <string.h>

#include "private.h"
#include "resolve.h"
#include "relcol/status.h"

void eng_walls_init(rc_sim *s)
{
    s->walls_rigid = 1;
    for (int w = 0; w < 6; w++) {
        s->wrule[w] = s->def.wall_rule[w] ? s->def.wall_rule[w] : &rc_wall_reflecting;
        s->walls_rigid &= s->wrule[w]->rigid != 0;
    }
    s->wev_mask = 0;
}

int eng_wall_collide(rc_sim *s, int w, rc_particle *a, rc_vec3 n, double eps)
{
    const rc_wall_env env = {s->def.dim, s->def.c, s->inv_c2, eps, s->def.wall_kT[w], &s->bk.rng};
    const rc_particle in = *a;
    const int st = s->wrule[w]->collide(&env, a, n);
    if (st != RC_OK)
        return st;
    if (!(s->wev_mask >> w & 1u)) {
        s->wev_q[w] = 0.0;
        s->wev_p[w] = rc_v3(0, 0, 0);
        s->wev_mask |= 1u << w;
    }
    s->wev_q[w] += eng_kinetic(&in, s->inv_c2) - eng_kinetic(a, s->inv_c2);
    s->wev_p[w] = rc_v3_add(s->wev_p[w], rc_v3_sub(in.p, a->p));
    return RC_OK;
}

void eng_walls_book(rc_sim *s)
{
    for (int w = 0; w < 6; w++) {
        if (!(s->wev_mask >> w & 1u))
            continue;
        eng_kahan(&s->bk.wall_q[w], &s->bk.wall_q_c[w], s->wev_q[w]);
        for (int d = 0; d < 3; d++)
            eng_kahan(&s->bk.wall_pm[3 * w + d], &s->bk.wall_pm_c[3 * w + d], rc_v3_get(s->wev_p[w], d));
    }
    s->wev_mask = 0;
}

int eng_walls_soft_in(const rc_sim *s, size_t nc)
{
    if (s->walls_rigid)
        return 0;
    for (size_t j = 0; j < nc; j++)
        if (s->grp_con[j].b < 0 && !s->wrule[ENG_WALL_INDEX(s->grp_con[j].b)]->rigid)
            return 1;
    return 0;
}
