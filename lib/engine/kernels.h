/* engine/kernels.h — the engine's lane kernels, written once over the lanes of
 * engine/wide.h: the sphere contact test of a ball against its gathered neighbours (the
 * prediction's largest cost), the gathering of a walk's rows of slots, and the next cell
 * crossing. Included by lanes_<back end>.c after ENG_W, which then fills its
 * table of engine/lanes.h; the same operations in every back end, so the same bits. */
#ifndef RELCOL_ENGINE_KERNELS_H
#define RELCOL_ENGINE_KERNELS_H

#include <math.h>
#include <stdint.h>

#include "approach.h"
#include "lanes.h"
#include "private.h"
#include "walk.h"
#include "wide.h"

/* ---- the sphere contact test ---------------------------------------------------------- */

/* The touching lanes `cand` of a chunk (the centres closer than the radius sum) in which
 * ball i and the lane's ball both move near c: their approach verdict from the momenta
 * (engine/approach.h) where the plain one, dx.(vk - vi) on the stored velocities, has lost
 * its sign to their rounding (it would miss the collision of a touching pair, or resolve
 * a parting one). One scalar function for every back end, called per lane, so the same
 * verdicts in each. Returns the chunk's hit bits with those lanes' replaced where the pair
 * is of approach.h's fast kind. dx, dy, dz: the lanes' separations. */
__attribute__((noinline)) static unsigned touching_fast(const rc_sim *s, const eng_ball *bi,
                                                        const double *const k[ENG_W],
                                                        const double *dx, const double *dy,
                                                        const double *dz, unsigned hit,
                                                        unsigned cand)
{
    const eng_aux *ai = &s->a[bi - s->b];
    const rc_particle pi = {ai->m, ai->p};
    for (int l = 0; l < ENG_W; l++) {
        if (!(cand >> l & 1u))
            continue;
        const eng_ball *bk = (const eng_ball *)(const void *)k[l];
        const eng_aux *ak = &s->a[bk - s->b];
        const rc_particle pk = {ak->m, ak->p};
        const int v = eng_approach_fast(s->inv_c2, &pi, bi->v, &pk, bk->v,
                                        rc_v3(dx[l], dy[l], dz[l]), bi->r + bk->r,
                                        s->def.approach_tol, NULL);
        if (v >= 0)
            hit = (hit & ~(1u << l)) | (unsigned)v << l;
    }
    return hit;
}

/* Lane l: the contact time of the bounding spheres of bi and k[l] (the balls' records as
 * doubles: x, v, t, r), absolute and >= now, into out[l] -- INFINITY on a miss or when it
 * cannot beat `best`; bit l of *nears: the centres within lim = (r_i + r_k)(1 + stol) at
 * the later clock (the simultaneity check's proximity). Returned: bit l set if out[l] is
 * finite. It is engine/pairs.h's pair_sep and sphere_time_dx, the same operations in the
 * same order: the separation at the later of the two clocks (the earlier ball advanced),
 * its nearest image, then the root dd / (sqrt(disc) - b), free of cancellation, behind
 * one combined test (not approaching; touching but not really approaching; roots not
 * real; not able to beat best: sqrt(disc) <= -b gives t >= dd / (-2 b)).
 * three, latest, per: compile-time constants at every call. latest: the caller knows bi's
 * clock is the later one (a ball that has just collided, at the engine's time), so only
 * that branch is computed. three == 0 (2-D, every z component 0): the z terms add +0 and
 * are left out (the sums are the same bits unless one is -0, which no comparison below
 * can tell from +0). A touching pair of two balls near c has its approach decided from the
 * momenta (touching_fast), only looked at when ball i moves above 0.89 c. */
ENG_INLINE unsigned pair_lanes(const rc_sim *s, const eng_ball *bi,
                               const double *const k[ENG_W], double best, double stol,
                               double out[ENG_W], unsigned *nears, const int three,
                               const int latest, const int per)
{
    eng_wd f[8];
    eng_load_records(k, f);
    const eng_wd xkx = f[0], xky = f[1], xkz = f[2], vkx = f[3], vky = f[4], vkz = f[5];
    const eng_wd tk = f[6], rk = f[7];
    const eng_wd xix = eng_set1(bi->x.x), xiy = eng_set1(bi->x.y), xiz = eng_set1(bi->x.z);
    const eng_wd vix = eng_set1(bi->v.x), viy = eng_set1(bi->v.y), viz = eng_set1(bi->v.z);
    const eng_wd ti = eng_set1(bi->t), ri = eng_set1(bi->r);
    const eng_wd hk = eng_sub(ti, tk);
    eng_wd dx = eng_sub(eng_add(xkx, eng_mul(hk, vkx)), xix);
    eng_wd dy = eng_sub(eng_add(xky, eng_mul(hk, vky)), xiy);
    eng_wd dz = eng_sub(eng_add(xkz, eng_mul(hk, vkz)), xiz);
    eng_wd tref = ti;
    if (!latest) {
        const eng_wm ge = eng_ge(ti, tk);
        const eng_wd hi = eng_sub(tk, ti);
        dx = eng_select(ge, dx, eng_sub(xkx, eng_add(xix, eng_mul(hi, vix))));
        dy = eng_select(ge, dy, eng_sub(xky, eng_add(xiy, eng_mul(hi, viy))));
        dz = eng_select(ge, dz, eng_sub(xkz, eng_add(xiz, eng_mul(hi, viz))));
        tref = eng_select(ge, ti, tk);
    }
    if (per) { /* the nearest image, as eng_image (eng_rint's two operations) */
        const eng_wd big = eng_set1(0x1.8p52);
        const eng_wd ix = eng_sub(eng_add(eng_mul(dx, eng_set1(s->inv_L[0])), big), big);
        const eng_wd iy = eng_sub(eng_add(eng_mul(dy, eng_set1(s->inv_L[1])), big), big);
        dx = eng_sub(dx, eng_mul(eng_set1(s->L[0]), ix));
        dy = eng_sub(dy, eng_mul(eng_set1(s->L[1]), iy));
        if (three) {
            const eng_wd iz = eng_sub(eng_add(eng_mul(dz, eng_set1(s->inv_L[2])), big), big);
            dz = eng_sub(dz, eng_mul(eng_set1(s->L[2]), iz));
        }
    }
    const eng_wd dvx = eng_sub(vkx, vix), dvy = eng_sub(vky, viy);
    eng_wd d2 = eng_add(eng_mul(dx, dx), eng_mul(dy, dy));
    eng_wd b = eng_add(eng_mul(dx, dvx), eng_mul(dy, dvy));
    eng_wd dv2 = eng_add(eng_mul(dvx, dvx), eng_mul(dvy, dvy));
    if (three) {
        const eng_wd dvz = eng_sub(vkz, viz);
        d2 = eng_add(d2, eng_mul(dz, dz));
        b = eng_add(b, eng_mul(dz, dvz));
        dv2 = eng_add(dv2, eng_mul(dvz, dvz));
    }
    const eng_wd sig = eng_add(ri, rk);
    const eng_wd dd = eng_sub(d2, eng_mul(sig, sig));
    const eng_wd disc = eng_sub(eng_mul(b, b), eng_mul(dv2, dd));
    const eng_wd tol = eng_mul(eng_set1(s->def.approach_tol), sig);
    const eng_wd lim = eng_mul(sig, eng_set1(1.0 + stol));
    const eng_wd zero = eng_zero(), inf = eng_set1(INFINITY);
    const eng_wm touching = eng_le(dd, zero);
    const eng_wm slow = eng_gt(eng_mul(b, b), eng_mul(eng_mul(tol, tol), dv2));
    const eng_wd bound = eng_mul(eng_mul(eng_set1(-2.0), b), eng_sub(eng_set1(best), tref));
    const eng_wm flying = eng_and(eng_gt(disc, zero), eng_lt(dd, bound));
    eng_wm hit = eng_and(eng_lt(b, zero), eng_select_m(touching, slow, flying));
    /* (a touching lane is rare: the partner just after a collision; 0.8 c^2: approach.h's
     * first test of a Lorentz factor above 3) */
    if (__builtin_expect(eng_bits(touching) != 0, 0) && rc_v3_norm2(bi->v) * s->inv_c2 > 0.8) {
        eng_wd vk2 = eng_add(eng_mul(vkx, vkx), eng_mul(vky, vky));
        if (three)
            vk2 = eng_add(vk2, eng_mul(vkz, vkz));
        const unsigned cand = eng_bits(eng_and(
            touching, eng_gt(eng_mul(vk2, eng_set1(s->inv_c2)), eng_set1(0.8))));
        if (cand) {
            double ax[ENG_W], ay[ENG_W], az[ENG_W];
            eng_store(ax, dx);
            eng_store(ay, dy);
            eng_store(az, three ? dz : zero);
            hit = eng_mask_bits(touching_fast(s, bi, k, ax, ay, az, eng_bits(hit), cand));
        }
    }
    *nears = eng_bits(eng_le(d2, eng_mul(lim, lim)));
    if (!eng_bits(hit)) { /* (most chunks) */
        eng_store(out, inf);
        return 0;
    }
    const eng_wd safe = eng_select(hit, disc, eng_set1(1.0)); /* (no sqrt of a miss's disc) */
    const eng_wd root = eng_div(dd, eng_sub(eng_sqrt(safe), b));
    eng_wd ta = eng_add(tref, eng_select(touching, zero, root));
    const eng_wd now = eng_set1(s->now);
    ta = eng_select(eng_lt(ta, now), now, ta);
    const eng_wm keep = eng_and(hit, eng_lt(ta, eng_set1(best)));
    eng_store(out, eng_select(keep, ta, inf));
    return eng_bits(keep);
}

/* Pad the m gathered indices to a multiple of the lanes' width with ball i itself (its
 * lanes are masked off), so that every neighbour goes through the lanes; returns the
 * padded count. (Eight stored whatever the width: no loop to mispredict.) */
_Static_assert(NB_CAP >= GATHER_MAX + 8, "room to pad");
ENG_INLINE size_t pad_lanes(int32_t *nb, size_t m, int32_t i)
{
    for (size_t l = 0; l < 8; l++)
        nb[m + l] = i;
    return (m + ENG_W - 1) / ENG_W * ENG_W;
}

/* The records of the neighbours nb[0..ENG_W) into k. */
ENG_INLINE void lane_records(const rc_sim *s, const int32_t *nb, const double *k[ENG_W])
{
    for (int l = 0; l < ENG_W; l++)
        k[l] = &s->b[nb[l]].x.x;
}

/* Simultaneity check of a prediction for neighbour k of ball i (at time T, its state
 * before the collision chk->old, velocity chk->vold): approaching within approach_tol, so
 * in contact now. grow_group's test (engine/approach.h), from the momenta: for two balls
 * moving fast together the stored velocities no longer hold the sign of their approach.
 * One scalar function for every back end (the lanes call it one neighbour at a time), so
 * the verdicts are the same bits in each. */
static int approaching_with(const rc_sim *s, const eng_ball *bi, int32_t k, double T,
                            const eng_check *chk)
{
    const eng_ball *bk = &s->b[k];
    const double atol = s->def.approach_tol, sig = bi->r + bk->r;
    const rc_vec3 dx = eng_image(s, rc_v3_sub(rc_v3_axpy(bk->x, T - bk->t, bk->v), bi->x));
    const rc_particle pk = {s->a[k].m, s->a[k].p};
    return eng_approaching(s->inv_c2, &chk->old, chk->vold, &pk, bk->v, dx, sig, atol, NULL);
}

/* One neighbour's verdict, in scan order: 1 if it is a simultaneous contact (see
 * test_list), else keep it if it is the earliest so far (ties: the first). */
ENG_INLINE int visit(const rc_sim *s, const eng_ball *bi, int32_t k, double t, int near,
                     int check, const eng_check *chk, double T, double *bt, int32_t *bk)
{
    /* one rarely taken branch (&, not &&: the parts are cheap) */
    if (check & near & (k != chk->partner) && approaching_with(s, bi, k, T, chk))
        return 1;
    const int take = t < *bt;
    *bt = take ? t : *bt;
    *bk = take ? k : *bk;
    return 0;
}

/* Bit l set if lane l of a chunk holds the partner. A chunk with a near lane is visited
 * lane by lane for the simultaneity check, and the partner, the contact just resolved, is
 * always near but never a conflict (visit passes it over): its lane alone need not send
 * the chunk the slow way (the same choice either way). */
ENG_INLINE unsigned partner_lanes(const int32_t *nb, int32_t partner)
{
    unsigned m = 0;
    for (int l = 0; l < ENG_W; l++)
        m |= (unsigned)(nb[l] == partner) << l;
    return m;
}

/* eng_lanes.test_list with three, latest and per constants. Only when checking, and a
 * lane of the chunk other than the partner's is near, are the lanes visited one by one;
 * else the chunk's earliest lane (the first of equals) replaces the best if strictly
 * earlier -- visit's choice. */
ENG_INLINE int test_list_dim(const rc_sim *s, int32_t i, int32_t *nb, size_t m,
                             double *best, int32_t *bp, const eng_check *chk, double T,
                             const int three, const int latest, const int per)
{
    const eng_ball *bi = &s->b[i];
    const int check = chk && s->def.sim_tol > 0.0;
    double bt = *best;
    int32_t bk = *bp;
    const size_t mw = pad_lanes(nb, m, i);
    for (size_t j = 0; j < mw; j += ENG_W) {
        const double *k[ENG_W];
        lane_records(s, nb + j, k);
        double t[ENG_W];
        unsigned nears;
        pair_lanes(s, bi, k, bt, s->def.sim_tol, t, &nears, three, latest, per);
        const size_t left = m - j < ENG_W ? m - j : ENG_W;
        unsigned near_in = nears & ((1u << left) - 1u);
        if (check && near_in)
            near_in &= ~partner_lanes(nb + j, chk->partner);
        if (check && near_in) {
            for (size_t l = 0; l < left; l++)
                if (visit(s, bi, nb[j + l], t[l], near_in >> l & 1, check, chk, T, &bt, &bk))
                    return 1;
            continue;
        }
        unsigned at;
        const double tmin = eng_min_lane(eng_load(t), &at);
        const int take = tmin < bt;
        const int32_t kmin = nb[j + at];
        bt = take ? tmin : bt;
        bk = take ? kmin : bk;
    }
    *best = bt;
    *bp = bk;
    return 0;
}

/* (each combination of the constants gets its own copy, 2-D one without z; per without
 * the image -- exactly the identity for neighbours in a block that does not wrap) */
static int test_list(const rc_sim *s, int32_t i, int32_t *nb, size_t m, double *best,
                     int32_t *bp, const eng_check *chk, double T, int latest, int per)
{
    if (s->def.dim == 3) {
        if (per)
            return latest ? test_list_dim(s, i, nb, m, best, bp, chk, T, 1, 1, 1)
                          : test_list_dim(s, i, nb, m, best, bp, chk, T, 1, 0, 1);
        return latest ? test_list_dim(s, i, nb, m, best, bp, chk, T, 1, 1, 0)
                      : test_list_dim(s, i, nb, m, best, bp, chk, T, 1, 0, 0);
    }
    if (per)
        return latest ? test_list_dim(s, i, nb, m, best, bp, chk, T, 0, 1, 1)
                      : test_list_dim(s, i, nb, m, best, bp, chk, T, 0, 0, 1);
    return latest ? test_list_dim(s, i, nb, m, best, bp, chk, T, 0, 1, 0)
                  : test_list_dim(s, i, nb, m, best, bp, chk, T, 0, 0, 0);
}

/* eng_lanes.sphere_times with three and per constants. */
ENG_INLINE void sphere_times_dim(const rc_sim *s, const eng_ball *bi, int32_t *nb,
                                 size_t m, double best, double *t, uint64_t *hit,
                                 uint64_t *near, const int three, const int per)
{
    const size_t mw = pad_lanes(nb, m, (int32_t)(bi - s->b));
    for (size_t j = 0; j < mw; j += ENG_W) {
        const double *k[ENG_W];
        lane_records(s, nb + j, k);
        unsigned nears;
        const unsigned h = pair_lanes(s, bi, k, best, s->def.sim_tol, &t[j], &nears, three, 0,
                                      per);
        hit[j / 64] |= (uint64_t)h << (j % 64);
        near[j / 64] |= (uint64_t)nears << (j % 64);
    }
}

_Static_assert(GATHER_MAX <= 128, "the bit sets hold two words");
_Static_assert(64 % ENG_W == 0, "a chunk of lanes within one word of bits");
static void sphere_times(const rc_sim *s, int32_t i, int32_t *nb, size_t m, double best,
                         double *t, uint64_t hit[2], uint64_t near[2])
{
    const eng_ball *bi = &s->b[i];
    hit[0] = hit[1] = near[0] = near[1] = 0;
    if (s->periodic) {
        if (s->def.dim == 3)
            sphere_times_dim(s, bi, nb, m, best, t, hit, near, 1, 1);
        else
            sphere_times_dim(s, bi, nb, m, best, t, hit, near, 0, 1);
    } else if (s->def.dim == 3) {
        sphere_times_dim(s, bi, nb, m, best, t, hit, near, 1, 0);
    } else {
        sphere_times_dim(s, bi, nb, m, best, t, hit, near, 0, 0);
    }
    /* (the padding lanes past m are ball i itself, near: masked off) */
    if (m < 64) {
        near[0] &= (UINT64_C(1) << m) - 1u;
        near[1] = 0;
    } else if (m < 128) {
        near[1] &= (UINT64_C(1) << (m - 64)) - 1u;
    }
}

/* ---- the walk's rows of slots ---------------------------------------------------------- */

/* Every row of the walk's block (at most 3 cells of ENG_CELL_CAP slots: one load each; the
 * slot array has ENG_SLOT_PAD more, so a load may reach past the last row). */
_Static_assert(3 * ENG_CELL_CAP <= 8, "a row of slots fits one load");
static size_t gather_rows(eng_walk *w, int32_t *nb)
{
    const int32_t *slot = w->s->g.slot;
    const unsigned valid = (1u << w->nslots) - 1u;
    /* (read before the loop: the chains' stores into w could alias them) */
    const int32_t skip = w->skip;
    const int nrows = w->nrows;
    size_t m = 0;
    for (int r = 0; r < nrows; r++) {
        const int32_t *sl = slot + w->row[r];
        const eng_slots v = eng_slots_load(sl);
        const unsigned chains = eng_slots_chains(v, valid);
        if (__builtin_expect(chains != 0, 0)) {
            for (int l = 0; l < 8; l++)
                if (chains >> l & 1u)
                    w->chain[w->nchain++] = ENG_CHAIN_HEAD(sl[l]);
        }
        m += eng_slots_compress(nb + m, v, eng_slots_balls(v, skip, valid));
    }
    return m;
}

/* ---- the next cell crossing ------------------------------------------------------------ */

/* Ball i's next cell crossing: the earliest time its centre reaches a face of its cell
 * that is not the box's wall (ties: the lower dimension), code 2 d + (direction > 0); a
 * periodic face is a crossing (eng_cross wraps the ball). One lane a dimension: the
 * direction of motion is a coin toss per dimension, which a branch mispredicts, and a
 * lane takes both ways at once. (Inlined into the table's function of the back ends
 * that use it: see engine/lanes_avx512.c.) */
ENG_INLINE void cross_event(rc_sim *s, int32_t i, const int c[3])
{
    const eng_ball *bi = &s->b[i];
    const eng_cells *g = &s->g;
    const int dim = s->def.dim < 3 ? s->def.dim : 3; /* (says so to the compiler: wide
                                                        lanes take one pass) */
    const eng_wd zero = eng_zero(), one = eng_set1(1.0), now = eng_set1(s->now);
    double best = INFINITY;
    int32_t code = -1;
    for (int d0 = 0; d0 < dim; d0 += ENG_W) {
        /* (lanes past the last dimension do not move: no crossing) */
        const eng_wd v = eng_axes(bi->v.x, bi->v.y, dim == 3 ? bi->v.z : 0.0, 0.0, d0);
        const eng_wd x = eng_axes(bi->x.x, bi->x.y, bi->x.z, 0.0, d0);
        const eng_wd cd = eng_axes(c[0], c[1], c[2], 0.0, d0);
        const eng_wd up_lim = eng_axes(g->up_lim[0], g->up_lim[1], g->up_lim[2], 0.0, d0);
        const eng_wd dn_lim = eng_axes(g->dn_lim[0], g->dn_lim[1], g->dn_lim[2], 0.0, d0);
        const eng_wd w = eng_axes(g->w[0], g->w[1], g->w[2], 1.0, d0);
        const eng_wm up = eng_gt(v, zero);
        /* a face to cross: not the box's own wall (a periodic face is one) */
        const eng_wm valid = eng_or(eng_and(up, eng_lt(cd, up_lim)),
                                    eng_and(eng_lt(v, zero), eng_gt(cd, dn_lim)));
        const eng_wd edge = eng_mul(eng_add(cd, eng_select(up, one, zero)), w);
        eng_wd t = eng_add(eng_set1(bi->t),
                           eng_div(eng_sub(edge, x), eng_select(valid, v, one)));
        t = eng_select(eng_lt(t, now), now, t);
        t = eng_select(valid, t, eng_set1(INFINITY));
        unsigned at;
        const double tmin = eng_min_lane(t, &at);
        const int take = tmin < best;
        best = take ? tmin : best;
        code = take ? 2 * (d0 + (int)at) + (int)(eng_bits(up) >> at & 1u) : code;
    }
    s->a[i].cross_t = best;
    s->a[i].cross_code = code;
}

#endif
