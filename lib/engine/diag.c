/* engine/diag.c — the engine's diagnostics: conservation sums (wall impulses and
 * dissipated energy included), the state hash, memory. Balls are read by engine/readout.c. */
#include <math.h>
#include <string.h>

#include "private.h"
#include "path.h"
#include "relcol/status.h"

size_t rc_sim_count(const rc_sim *s) { return s ? s->n : 0; }
double rc_sim_time(const rc_sim *s) { return s ? s->now : NAN; }

/* Deepest overlap among ball i's neighbours at the engine's time, relative to ri + rk. */
static double overlap_around(const rc_sim *s, size_t i, const rc_vec3 xi)
{
    const eng_cells *g = &s->g;
    int32_t cell = s->a[i].cell;
    int c[3] = {cell % g->n[0], (cell / g->n[0]) % g->n[1], cell / (g->n[0] * g->n[1])};
    double worst = 0.0;
    for (int z = -1; z <= 1; z++)
        for (int y = -1; y <= 1; y++)
            for (int x = -1; x <= 1; x++) {
                const int32_t cl = cell_at(g, c, x, y, z); /* (wraps on periodic axes) */
                if (cl < 0)
                    continue;
                eng_cell_it it;
                for (int32_t k = cell_first(g, cl, &it); k >= 0; k = cell_next(g, &it)) {
                    if ((size_t)k <= i)
                        continue;
                    const eng_ball *bk = &s->b[k];
                    rc_vec3 xk = rc_v3_axpy(bk->x, s->now - bk->t, bk->v);
                    if (s->path->ball_at) { /* (a curved path: engine/path.h) */
                        rc_sim_ball o;
                        eng_ball_now(s, (size_t)k, &o, 0);
                        xk = o.x;
                    }
                    double sig = s->b[i].r + bk->r;
                    double d = rc_v3_norm(eng_image(s, rc_v3_sub(xk, xi)));
                    if ((sig - d) / sig > worst)
                        worst = (sig - d) / sig;
                }
            }
    return worst;
}

int rc_sim_diagnostics(const rc_sim *s, rc_sim_diag *d)
{
    if (!s || !d)
        return RC_EINVAL;
    memset(d, 0, sizeof *d);
    d->time = s->now;
    for (size_t i = 0; i < s->n; i++) {
        const eng_aux *a = &s->a[i];
        eng_aux now;
        if (s->path->ball_at) { /* (a curved path: the momentum at now, engine/path.h) */
            rc_sim_ball o;
            eng_ball_now(s, i, &o, 0);
            now = *a;
            now.p = o.p;
            a = &now;
        }
        double M = eng_mass_rel(a->m, a->p, s->inv_c2);
        d->mass_rel += M;
        d->kinetic += rc_v3_norm2(a->p) / (M + a->m);
        d->rest_mass += a->m;
        d->momentum = rc_v3_add(d->momentum, a->p);
        d->momentum_scale += rc_v3_norm(a->p);
        if (s->narrow)
            continue;
        rc_sim_ball b;
        eng_ball_now(s, i, &b, 1);
        double w = overlap_around(s, i, b.x);
        if (w > d->max_overlap)
            d->max_overlap = w;
    }
    if (s->narrow)
        d->max_overlap = NAN; /* bounding spheres may overlap legitimately: see overlaps */
    d->heat = s->bk.heat;
    d->energy = d->kinetic + s->bk.heat;
    d->wall_impulse = rc_v3(s->bk.wall[0], s->bk.wall[1], s->bk.wall[2]);
    d->overlaps = s->bk.overlaps;
    memcpy(d->overlaps_by_kind, s->bk.overlap_kind, sizeof d->overlaps_by_kind);
    for (int w = 0; w < 6; w++) {
        d->wall_impulse_by_wall[w] = s->bk.wallw[w];
        d->wall_heat_by_wall[w] = s->bk.wall_q[w];
        d->wall_momentum_by_wall[w] = rc_v3(s->bk.wall_pm[3 * w], s->bk.wall_pm[3 * w + 1], s->bk.wall_pm[3 * w + 2]);
    }
    d->wall_shared = s->bk.wall_shared;
    d->pinned = s->bk.pinned;
    memcpy(d->virial, s->bk.vir, sizeof d->virial);
    memcpy(d->virial_energy, s->bk.vir_e, sizeof d->virial_energy);
    if (s->def.gravity) /* the field's loop books no collisional transfer: NaN, not a silent 0 */
        for (int k = 0; k < 9; k++)
            d->virial[k] = NAN, d->virial_energy[k / 3] = NAN;
    memcpy(d->helfand_wrap, s->bk.wrap, sizeof d->helfand_wrap);
    memcpy(d->helfand_wrap_energy, s->bk.wrap_e, sizeof d->helfand_wrap_energy);
    d->collisions = s->bk.collisions;
    memcpy(d->events, s->bk.events, sizeof d->events);
    d->max_group = s->bk.max_group;
    d->group_fallbacks = s->bk.group_fallbacks;
    d->group_sequential = s->bk.group_sequential;
    d->tube_conflicts = s->bk.tube_conflicts;
    d->order_conflicts = s->bk.order_conflicts;
    d->rollbacks = s->bk.rollbacks;
    d->stall_ball = s->bk.stall_ball;
    d->stall_partner = s->bk.stall_partner;
    return RC_OK;
}

static uint64_t fnv(uint64_t h, double x)
{
    unsigned char c[sizeof x];
    memcpy(c, &x, sizeof x);
    for (size_t k = 0; k < sizeof x; k++) {
        h ^= c[k];
        h *= 0x100000001b3ULL;
    }
    return h;
}

uint64_t rc_sim_hash(const rc_sim *s)
{
    uint64_t h = 0xcbf29ce484222325ULL;
    if (!s)
        return h;
    h = fnv(h, s->now);
    for (size_t i = 0; i < s->n; i++) {
        /* (the stored lines: a fingerprint of the engine's state, the same in every
         * frame, not the table-time picture of per_ball frames) */
        rc_sim_ball b;
        eng_ball_now(s, s->slot[i], &b, 0);
        h = fnv(h, b.x.x);
        h = fnv(h, b.x.y);
        h = fnv(h, b.x.z);
        h = fnv(h, b.p.x);
        h = fnv(h, b.p.y);
        h = fnv(h, b.p.z);
        h = fnv(h, b.m);
        h = fnv(h, b.tau);
    }
    return h;
}

size_t rc_sim_bytes(const rc_sim *s)
{
    if (!s)
        return 0;
    return sizeof *s + s->n * (sizeof *s->b + sizeof *s->a + sizeof *s->clk + sizeof *s->g.next +
                               sizeof *s->id + sizeof *s->slot +
                               sizeof *s->cnt + (s->ev_n ? sizeof *s->ev_n : 0) +
                               (s->img ? 3 * sizeof *s->img : 0) +
                               (s->pb ? sizeof *s->pb->cov + sizeof *s->pb->glu + sizeof *s->pb->pend +
                                             sizeof *s->pb->und + sizeof *s->pb->undp
                                       : 0)) +
           eng_queue_bytes(&s->q) + eng_slice_bytes(s) +
           s->g.ncells * ENG_CELL_CAP * sizeof *s->g.slot +
           s->grp_ball_cap * (sizeof *s->grp_ball + sizeof *s->grp_part) +
           s->grp_con_cap * sizeof *s->grp_con;
}
