/* engine/diag.c — reading the engine's state: balls at the engine's time, conservation
 * diagnostics (wall impulses and dissipated energy included), a state hash, memory. */
#include <math.h>
#include <string.h>

#include "private.h"
#include "relcol/status.h"

size_t rc_sim_count(const rc_sim *s) { return s ? s->n : 0; }
double rc_sim_time(const rc_sim *s) { return s ? s->now : NAN; }

/* per_ball frames: ball i's state at now (t >= now) where its latest kink lies ahead of
 * it, from the lines eng_pend recorded: 1 (*x in the wrap coordinates *img, p, m, tau, TC
 * memory set), 2 if the line it is on then was not recorded, 0 if the ball is on its
 * stored line. */
static int before_kink(const rc_sim *s, size_t i, double now, rc_sim_ball *o,
                       const int32_t **img)
{
    if (!s->pb || !(s->pb->cov[i].t_k > now))
        return 0;
    const eng_pend *r = &s->pb->pend[i];
    int k = 0;
    while (k < r->depth && !(now < r->l[k].t))
        k++;
    if (k == r->depth)
        return 2;
    /* line k: from the first recorded kink (k = 0: back from it), else along the lines
     * between to kink k - 1 */
    double t0 = r->l[0].t, tau0 = r->tau, tau_last = r->tau_last;
    rc_vec3 x0 = r->x;
    for (int q = 1; q < k; q++) {
        const double M = eng_mass_rel(r->l[q].m, r->l[q].p, s->inv_c2), h = r->l[q].t - t0;
        x0 = rc_v3_axpy(x0, h, rc_v3_scale(1.0 / M, r->l[q].p));
        tau0 += h * (r->l[q].m / M);
        t0 = r->l[q].t;
    }
    if (k >= 1)
        tau_last = tau0;
    const rc_vec3 p = r->l[k].p;
    const double m = r->l[k].m;
    const double h = now - t0, M = eng_mass_rel(m, p, s->inv_c2);
    o->x = rc_v3_axpy(x0, h, rc_v3_scale(1.0 / M, p));
    o->p = p;
    o->m = m;
    o->tau = tau0 + h * (m / M);
    o->collided = isfinite(tau_last);
    o->tau_last = o->collided ? tau_last : 0.0;
    *img = r->img;
    return 1;
}

int eng_ball_now(const rc_sim *s, size_t i, rc_sim_ball *o, int truth)
{
    return eng_ball_at(s, i, s->now, o, truth);
}

int eng_ball_at(const rc_sim *s, size_t i, double t, rc_sim_ball *o, int truth)
{
    const eng_ball *b = &s->b[i];
    const eng_aux *a = &s->a[i];
    double h = t - b->t;
    o->x = h == 0.0 ? b->x : rc_v3_axpy(b->x, h, b->v);
    o->p = a->p;
    o->r = b->r;
    o->m = a->m;
    const eng_clock *k = &s->clk[i];
    o->tau = k->tau;
    o->collided = isfinite(k->tau_last);
    o->tau_last = o->collided ? k->tau_last : 0.0;
    if (h != 0.0)
        o->tau += s->inv_c2 == 0.0 ? h : h * (a->m / eng_mass_rel(a->m, a->p, s->inv_c2));
    const int32_t *img = s->img ? s->img + 3 * i : NULL;
    const int ahead = truth ? before_kink(s, i, t, o, &img) : 0;
    for (int d = 0; d < 3; d++) {
        o->image[d] = 0;
        if (!s->img || s->walled >> d & 1u || d >= s->def.dim)
            continue;
        /* periodic: in [0, L) (a ball exactly at its wrap, not yet processed, may lie a
         * rounding error outside), with the wrap counted */
        int32_t im = img[d];
        double x = rc_v3_get(o->x, d);
        const double L = s->L[d];
        if (x >= L) {
            x -= L;
            im++;
        } else if (x < 0.0) {
            const double y = x + L;
            if (y < L) {
                x = y;
                im--;
            } else {
                x = 0.0; /* (within half an ulp of L below 0) */
            }
        }
        rc_v3_set(&o->x, d, x);
        o->image[d] = im;
    }
    return ahead;
}

int rc_sim_get_ball(const rc_sim *s, size_t i, rc_sim_ball *out)
{
    if (!s || !out || i >= s->n)
        return RC_EINVAL;
    eng_ball_now(s, s->slot[i], out, 1);
    return RC_OK;
}

int rc_sim_get_ball_latest(const rc_sim *s, size_t i, rc_sim_ball *out)
{
    if (!s || !out || i >= s->n)
        return RC_EINVAL;
    eng_ball_now(s, s->slot[i], out, 0);
    return RC_OK;
}

int rc_sim_get_glue(const rc_sim *s, size_t i, rc_glue *out)
{
    if (!s || !out || i >= s->n || !s->pb)
        return RC_EINVAL;
    const size_t k = s->slot[i];
    *out = s->pb->glu[k];
    if (out->r > 0.0) {
        /* kept with the contact event at the origin: shifted so that its centre at t_c is
         * the stored line's there (its kink) */
        const eng_ball *b = &s->b[k];
        const rc_vec3 shift = rc_v3_sub(rc_v3_axpy(b->x, out->t_c - b->t, b->v), out->x_c);
        out->x = rc_v3_add(out->x, shift);
        out->x_c = rc_v3_add(out->x_c, shift);
    }
    return RC_OK;
}

int rc_sim_kink_ahead(const rc_sim *s, size_t i)
{
    if (!s || i >= s->n)
        return RC_EINVAL;
    rc_sim_ball b;
    return eng_ball_now(s, s->slot[i], &b, 1);
}

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
    for (int w = 0; w < 6; w++)
        d->wall_impulse_by_wall[w] = s->bk.wallw[w];
    d->wall_shared = s->bk.wall_shared;
    d->pinned = s->bk.pinned;
    memcpy(d->virial, s->bk.vir, sizeof d->virial);
    memcpy(d->virial_energy, s->bk.vir_e, sizeof d->virial_energy);
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
