/* engine/perball/zmf_group.c — per_ball frames: a group formed by simultaneity in its own ZMF
 * rather than at one table time (papers/simultaneous-contacts.md): a member's further contact
 * joins when its event lies within sim_tol light-crossing times of the first in the ZMF of the
 * group and the joining ball; solved by eng_solve_at_events. */
#include <math.h>

#include "../group.h"
#include "pair_zmf.h"
#include "../walk.h"
#include "../../toi_private.h"
#include "model.h"
#include "relcol/status.h"

/* A contact found: members a, b (local), normal from a to b, its event relative to ball
 * i's centre at T: time t - T and offset x */
typedef struct zcon {
    int a, b;
    rc_vec3 n;
    double t;
    rc_vec3 x;
} zcon;

/* The group so far: members, each centre at T relative to ball i's (nearest image), the
 * contacts, and the total four-momentum (P, M = E / c^2). */
typedef struct zgroup {
    size_t nm, nc;
    int32_t mem[ENG_EVGROUP_NMAX];
    rc_vec3 rel[ENG_EVGROUP_NMAX];
    zcon con[ENG_EVGROUP_NMAX + 1];
    rc_vec3 P;
    double M;
} zgroup;

static int local_of(const zgroup *g, int32_t k)
{
    for (size_t j = 0; j < g->nm; j++)
        if (g->mem[j] == k)
            return (int)j;
    return -1;
}

static int have(const zgroup *g, int a, int b)
{
    for (size_t j = 0; j < g->nc; j++)
        if ((g->con[j].a == a && g->con[j].b == b) || (g->con[j].a == b && g->con[j].b == a))
            return 1;
    return 0;
}

/* What every neighbour of member mi is tested with: its centre at T and velocity, and the
 * neighbour-free parts of try_join's bound (|t0 - T|, the reach, the group's speed). */
typedef struct zmem {
    int mi;
    rc_vec3 x, v;
    double r, beta_m, t0, reach, beta_g;
    double tb1; /* the same for any group velocity below c: the neighbours' broad phase */
    rc_toi_shape h; /* its table-frame shape */
} zmem;

static zmem member_ctx(const rc_sim *s, const zgroup *g, size_t mi, double T)
{
    const eng_ball *bm = &s->b[g->mem[mi]];
    zmem z;
    z.mi = (int)mi;
    z.x = rc_v3_axpy(bm->x, T - bm->t, bm->v);
    z.v = bm->v;
    z.r = bm->r;
    z.beta_m = rc_v3_norm(bm->v) * s->inv_c;
    z.t0 = fabs(g->con[0].t);
    z.reach = rc_v3_norm(rc_v3_sub(g->rel[mi], g->con[0].x)) + bm->r;
    z.beta_g = rc_v3_norm(g->P) / g->M * s->inv_c;
    /* (a cell is at least the largest diameter wide: r_k < its edge) */
    z.tb1 = (z.t0 + (z.reach + 2.0 * s->def.sim_tol * (bm->r + s->g.w[0])) * s->inv_c) /
            (1.0 - z.beta_m) * (1.0 + 1e-12);
    const eng_aux *am = &s->a[g->mem[mi]];
    z.h = rc_toi_shape_of(bm->r, am->m, am->p, s->inv_c2);
    return z;
}

/* Can X of member z and ball k be simultaneous with the first (try_join's |F| <= tol_f)?
 * Decided before asking the frame from the bounds engine/perball/pair_zmf.h proves of X; 0
 * only where F misses by more than a margin for the frame's tolerance and rounding, and no
 * outer contact is no verdict. */
static int can_join(const rc_sim *s, const zmem *z, int32_t m, const eng_ball *bk,
                    rc_vec3 dx, rc_vec3 P, double D, double A, double hPc, double tol_f,
                    double M, double T)
{
    eng_zpair zp;
    if (!eng_zpair_make(s, &s->b[m], bk, dx, &zp))
        return 1;
    const double k2 = zp.k2, delta = fabs(zp.gk - zp.gi) / zp.gi;
    const double ro = bk->r * (zp.gk > zp.gi ? 1.0 : zp.gi / zp.gk);
    const double ri = bk->r * (zp.gk > zp.gi ? zp.gi / zp.gk : 1.0);
    const double scale = (z->r + bk->r) * (1.0 / zp.wn + s->inv_c);
    double tau_lo, tau_hi = INFINITY;
    if (delta <= 1e-13) {
        if (!eng_zpair_entry(&zp, z->r + ri, &tau_hi))
            return 1;
        double t;
        rc_vec3 y;
        eng_zpair_point(&zp, z->r, z->r + ri, tau_hi, &t, &y);
        const double F = t * D - A - k2 * rc_v3_dot(P, rc_v3_axpy(y, -t, z->v));
        const double margin = M * (2.0 * (1e-6 + 8.0 * zp.gu * sqrt(delta)) * scale +
                                    1e-12 * (fabs(T) + fabs(tau_hi))) +
                              1e-12 * fabs(A);
        return fabs(F) <= tol_f + margin;
    }
    if (!eng_zpair_entry(&zp, z->r + ro, &tau_lo))
        return 1;
    if (!eng_zpair_entry(&zp, z->r + ri, &tau_hi))
        tau_hi = INFINITY;
    const double un = rc_v3_norm(zp.u);
    const double hu = un > 0.0 ? k2 * un * rc_toi_support_(&z->h, rc_v3_scale(1.0 / un, zp.u))
                               : 0.0;
    const double q = 1.0 - k2 * rc_v3_dot(zp.u, z->v);
    const double t_lo = (tau_lo / zp.gu - hu) / q, t_hi = (tau_hi / zp.gu + hu) / q;
    const double margin =
        M * (2e-6 * scale +
             1e-12 * (fabs(T) + fabs(tau_lo) + (tau_hi < INFINITY ? fabs(tau_hi) : 0.0))) +
        1e-12 * fabs(A);
    return !(t_lo * D - A - hPc > tol_f + margin || t_hi * D - A + hPc < -tol_f - margin);
}

/* Does ball k have a contact with member z.mi simultaneous with the group's first in the ZMF
 * of the group and k? Then added: 1; else 0 (nothing changed). */
static int try_join(rc_sim *s, zgroup *g, const zmem *z, int32_t k, double T)
{
    const eng_ball *bk = &s->b[k];
    const double ic2 = s->inv_c2, sig = z->r + bk->r;
    /* centres at T relative to m's; the bounding spheres must approach and touch by tb (a
     * bound of tau_max from the group's and k's speeds): the cheap test most neighbours fail */
    const rc_vec3 dx = eng_image(s, rc_v3_sub(rc_v3_axpy(bk->x, T - bk->t, bk->v), z->x));
    const rc_vec3 dv = rc_v3_sub(bk->v, z->v);
    const double b = rc_v3_dot(dx, dv), d2 = rc_v3_norm2(dx), dd = d2 - sig * sig;
    if (!(b < 0.0))
        return 0;
    const double dv2 = rc_v3_norm2(dv), disc = b * b - dv2 * dd;
    if (dd > 0.0) {
        if (!(disc > 0.0))
            return 0;
        const double bk2 = rc_v3_norm2(bk->v) * ic2;
        const double beta = bk2 > z->beta_g * z->beta_g ? sqrt(bk2) : z->beta_g;
        const double den = 1.0 - beta * z->beta_m;
        const double tb = (z->t0 + beta * z->reach * s->inv_c + 2.0 * s->def.sim_tol * sig *
                           s->inv_c) / den * (1.0 + 1e-12);
        if (!(dd + tb * (2.0 * b + tb * dv2) <= 0.0 || -b <= tb * dv2))
            return 0;
    }
    const int mi = z->mi;
    const int lk = local_of(g, k);
    if (lk >= 0 ? have(g, mi, lk) : g->nm == ENG_EVGROUP_NMAX)
        return 0;
    if (g->nc == ENG_EVGROUP_NMAX + 1)
        return 0;
    const int32_t m = g->mem[mi];
    /* the group with k: total momentum and relativistic mass */
    const eng_aux *ak = &s->a[k];
    rc_vec3 P = g->P;
    double M = g->M;
    if (lk < 0) {
        P = rc_v3_add(P, ak->p);
        M += eng_mass_rel(ak->m, ak->p, ic2);
    }
    /* When must X lie to be simultaneous with X0? M (t - t0) - P.(x - x0)/c^2 = (t - T) D - A
     * - P.e/c^2 vanishes no later than tau_max after T, and the frame's contact comes no
     * earlier than the spheres' and the centre line's: a pair that cannot meet by then (with
     * sim_tol) is not asked. */
    const zcon *c0 = &g->con[0];
    const rc_vec3 relm = g->rel[mi];
    const double D = M - rc_v3_dot(P, z->v) * ic2;
    const double A = M * c0->t + rc_v3_dot(P, rc_v3_sub(relm, c0->x)) * ic2;
    const double tol = s->def.sim_tol * sig * s->inv_c * M / D;
    const double pn = rc_v3_norm(P);
    const double hP = pn > 0.0 ? rc_toi_support_(&z->h, rc_v3_scale(1.0 / pn, P)) : 0.0;
    /* (1e-12: the support's rounding, far above it) */
    const double tau_max = (A + pn * hP * (1.0 + 1e-12) * ic2) / D + 2.0 * tol;
    const double ts = dd > 0.0 ? dd / (sqrt(disc) - b) : 0.0;
    if (!(ts <= tau_max))
        return 0;
    const double dn = sqrt(d2);
    if (dn > 0.0) {
        const rc_vec3 ax = rc_v3_scale(1.0 / dn, dx);
        const rc_toi_shape hk = rc_toi_shape_of(bk->r, ak->m, ak->p, ic2);
        const double hsum = rc_toi_support_(&z->h, ax) + rc_toi_support_(&hk, ax);
        /* (1e-12: the supports' and the centre line's rounding, far above it) */
        if (dn + tau_max * (b / dn) > hsum * (1.0 + 1e-12))
            return 0;
    }
    const double minv2 = M * M - rc_v3_norm2(P) * ic2;
    if (!(minv2 > 0.0))
        return 0;
    const double tol_f = s->def.sim_tol * sig * s->inv_c * sqrt(minv2);
    if (!can_join(s, z, m, bk, dx, P, D, A, pn * hP * ic2, tol_f, M, T))
        return 0;
    /* the frame's contact event from the stored lines, asked a light-crossing time early
     * (as an undo asks: the pair's ZMF simultaneity tilts by up to that across the pair) */
    double tk;
    rc_vec3 dxk, nk;
    if (eng_pair_contact(s, m, k, T - sig * s->inv_c, &tk, &dxk, &nk) != RC_OK)
        return 0;
    /* X relative to i's centre at T, and its ZMF time difference to X0 */
    const rc_vec3 xk = rc_v3_add(rc_v3_axpy(relm, tk - T, z->v), dxk);
    const double dt = (tk - T) - c0->t;
    const rc_vec3 dX = rc_v3_sub(xk, c0->x);
    const double dtp = (M * dt - rc_v3_dot(P, dX) * ic2) / sqrt(minv2);
    if (!(fabs(dtp) <= s->def.sim_tol * sig * s->inv_c))
        return 0;
    int b_loc = lk;
    if (lk < 0) {
        b_loc = (int)g->nm;
        g->mem[g->nm] = k;
        g->rel[g->nm] = rc_v3_add(relm, dx);
        g->nm++;
        g->P = P;
        g->M = M;
    }
    g->con[g->nc++] = (zcon){mi, b_loc, nk, tk - T, xk};
    return 1;
}

/* At i's event with bp at T (X0: tx0, dX0): grow the group through shared balls by try_join;
 * with a further contact, form and solve it (1, or the law's failure); else 0, nothing
 * changed. */
int eng_zmf_group(rc_sim *s, int32_t i, int32_t bp, double T, double tx0, rc_vec3 dX0)
{
    zgroup g;
    g.nm = 2;
    g.mem[0] = i;
    g.mem[1] = bp;
    g.rel[0] = rc_v3(0.0, 0.0, 0.0);
    g.rel[1] = eng_image(s, rc_v3_sub(s->b[bp].x, s->b[i].x));
    g.P = rc_v3_add(s->a[i].p, s->a[bp].p);
    g.M = eng_mass_rel(s->a[i].m, s->a[i].p, s->inv_c2) +
          eng_mass_rel(s->a[bp].m, s->a[bp].p, s->inv_c2);
    g.nc = 1;
    g.con[0] = (zcon){0, 1, s->grp_con[0].n, tx0 - T, rc_v3_axpy(dX0, tx0 - T, s->b[i].v)};
    /* (the engine's neighbour walk: rows of cells read together, records fetched ahead) */
    static const int lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    for (size_t mi = 0; mi < g.nm; mi++) {
        const int32_t m = g.mem[mi];
        const zmem zc = member_ctx(s, &g, mi, T);
        int c[3];
        cell_coords(&s->g, s->a[m].cell, c);
        eng_walk w;
        walk_init(&w, s, m, c, lo, hi);
        int32_t nb[NB_CAP];
        double tn[NB_CAP];
        while (!w.done) {
            /* the neighbours whose bounding spheres overlap or meet by tb1, in the engine's
             * lanes (the predictions' broad phase), then try_join's own tests */
            const size_t n = walk_gather(&w, nb);
            uint64_t hit[2], nearb[2];
            eng_lanes_of(s->simd)->sphere_times(s, m, nb, n, T + zc.tb1, tn, hit, nearb);
            for (size_t lw = 0; lw < 2; lw++)
                for (uint64_t bits = hit[lw] | nearb[lw]; bits; bits &= bits - 1u)
                    try_join(s, &g, &zc, nb[64 * lw + (size_t)__builtin_ctzll(bits)], T);
        }
    }
    if (g.nc == 1)
        return 0;
    /* the group in the engine's arrays: members at T on their incoming lines, contacts in i's
     * coordinates; the read-out records of members the event did not name noted after it */
    eng_pend_snap ps[ENG_EVGROUP_NMAX];
    size_t nps = 0, nm = 2, nc = 1;
    for (size_t q = 2; q < g.nm; q++) {
        if (s->pb)
            ps[nps++] = eng_pend_take(s, g.mem[q]);
        if (eng_member_of(s, &nm, g.mem[q], T) < 0)
            return RC_ENOMEM;
    }
    const rc_vec3 xi = s->b[i].x;
    s->grp_con[0].t = T + g.con[0].t;
    s->grp_con[0].x = rc_v3_add(xi, g.con[0].x);
    for (size_t j = 1; j < g.nc; j++) {
        if (eng_add_contact(s, &nc, g.con[j].a, g.con[j].b, g.con[j].n) != RC_OK)
            return RC_ENOMEM;
        s->grp_con[j].t = T + g.con[j].t;
        s->grp_con[j].x = rc_v3_add(xi, g.con[j].x);
    }
    /* the members' walls by the table's criterion at T (the wall's rest frame is the table):
     * left out, a member pushed into a wall would meet it at once, contact after contact */
    if (eng_group_walls(s, nm, &nc, ENG_EVGROUP_NMAX + 1) != RC_OK)
        return RC_ENOMEM;
    return eng_solve_at_events(s, nm, nc, ps, nps, 1, 0);
}
