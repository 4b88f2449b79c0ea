/* engine/predict.c — predicting a ball's earliest event from its stored state: walls,
 * the neighbours of its 3^d cells (gathered by engine/walk.h, sphere times in the
 * engine's lanes, engine/lanes.h, then the contact frame's narrow phase for contracted
 * shapes, pruned by engine/shapes.h), its next cell crossing; the cheaper update when
 * it crosses into a cell; the table frame's deferred events, settled when they come up;
 * and the prediction that also looks for a contact simultaneous with the one just
 * resolved. Resolving events: engine/core.c. */
#include <math.h>
#include <stdlib.h>

#include "approach.h"
#include "lanes.h"
#include "pairs.h"
#include "shapes.h"
#include "walk.h"
#include "private.h"
#include "model.h"
#include "relcol/status.h"

/* ---- event prediction ------------------------------------------------------------ */


/* Bounding-sphere (and, if plugged in, contracted) contact time of balls i and k, as an
 * absolute time >= now, INFINITY if none before `best`. It depends only on the two stored
 * states (reference time max(t_i, t_k)), so the same pair gives the same bits whichever
 * ball asks, and a continued run predicts what an uninterrupted one did. */
static inline double pair_time_dx(const rc_sim *s, const eng_ball *bi, const eng_ball *bk,
                                  rc_vec3 dx, double d2, double tref, double best,
                                  int use_narrow, rc_vec3 *n);

/* (*n: the frame's contact normal when the narrow phase returns a time, NAN on overlap) */
/* (always inline: grown by the parting path, it is past GCC's inlining limit, and out of
 * line in scan_block_narrow's loop it costs a call per neighbour) */
__attribute__((always_inline)) static inline double pair_time(const rc_sim *s,
                                                              const eng_ball *bi,
                                                              const eng_ball *bk, double best,
                                                              rc_vec3 *n)
{
    double tref;
    rc_vec3 dx = pair_sep(s, bi, bk, &tref);
    return pair_time_dx(s, bi, bk, dx, rc_v3_norm2(dx), tref, best, s->narrow, n);
}

/* The same from the separation dx (and its square d2) at time tref. */
__attribute__((always_inline)) static inline double pair_time_dx(
    const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx, double d2, double tref,
    double best, int use_narrow, rc_vec3 *n)
{
    double ta = sphere_time_dx(s, bi, bk, dx, d2, tref, best);
    int parting = 0;
    if (!(ta < best)) {
        /* Bounding spheres that already overlap and do not approach can still hold
         * contracted shapes that meet later: a flat shape's flank sweeps into its
         * neighbour while the centres part. Such a pair goes to the narrow phase with
         * the lower bound now (test_engine_audit). */
        const double sig = bi->r + bk->r;
        if (!use_narrow || !(d2 <= sig * sig))
            return INFINITY;
        ta = tref > s->now ? tref : s->now;
        if (!(ta < best))
            return INFINITY;
        const rc_toi_shape shi = shape_of(s, bi);
        if (!parting_open(s, &shi, bi, bk, dx, d2, tref, best))
            return INFINITY;
        parting = 1;
    }
    if (use_narrow && s->model->pair_time) {
        /* the model's narrow phase (per-ball frames: checked against both hyperplanes) */
        return s->model->pair_time(s, bi, bk, dx, tref, best, parting, n);
    } else if (use_narrow) {
        /* narrow phase: the contracted shapes inside the bounding spheres. The frames'
         * root finds are not symmetric in their two shapes (about half of all pairs get
         * other bits with the roles swapped), so the pair is put to the frame in one
         * orientation whichever ball asks: the first shape is the one from which dx
         * points lexicographically up (pair_sep from the other ball is exactly -dx). */
        const int flip = dx.x < 0.0 || (dx.x == 0.0 && (dx.y < 0.0 || (dx.y == 0.0 && dx.z < 0.0)));
        const eng_ball *b0 = flip ? bk : bi, *b1 = flip ? bi : bk;
        const eng_aux *a0 = &s->a[b0 - s->b], *a1 = &s->a[b1 - s->b];
        const rc_vec3 d01 = flip ? rc_v3_scale(-1.0, dx) : dx;
        rc_toi_contact out;
        int st;
        if (s->table) {
            /* the frame's direct solver, from the states as stored: the same bits as
             * through its toi (its masses, velocities and shapes are these), without the
             * contact point, which the engine does not use */
            const rc_toi_shape h0 = shape_of(s, b0), h1 = shape_of(s, b1);
            st = s->shapes(&h0, &h1, d01, rc_v3_sub(b1->v, b0->v), &s->toi, s->ws,
                           &out.t, NULL, &out.n);
        } else {
            rc_toi_ball A = {rc_v3(0, 0, 0), b0->r, a0->m, a0->p};
            rc_toi_ball B = {d01, b1->r, a1->m, a1->p};
            st = s->def.frame->toi(&s->toi, &A, &B, s->ws, &out);
        }
        if (flip)
            out.n = rc_v3_scale(-1.0, out.n);
        if (st == RC_EOVERLAP) {
            if (parting)
                return INFINITY; /* overlap policy: a pair whose bounding spheres part is
                                    left to separate */
            *n = rc_v3(NAN, NAN, NAN);
            return s->now; /* approaching bounding spheres: overlap policy, resolve now */
        }
        if (st != RC_OK)
            return INFINITY;
        *n = out.n;
        ta = tref + out.t;
        if (ta < s->now)
            ta = s->now;
        if (!(ta < best))
            return INFINITY;
    }
    return ta;
}

/* Support distance of a shape along the wall normal e_d (the shape's own support). */
static inline double axis_support(const rc_toi_shape *h, int d)
{
    rc_vec3 e = rc_v3(0, 0, 0);
    rc_v3_set(&e, d, 1.0);
    return rc_toi_support_(h, e);
}

/* Support distance of ball i's shape along the wall normal e_d: r, or contracted. */
static inline double wall_support(const rc_sim *s, int32_t i, int d)
{
    if (!s->wall_contracted)
        return s->b[i].r;
    const rc_toi_shape h = shape_of(s, &s->b[i]);
    return axis_support(&h, d);
}

/* Walls and cell crossings below are written without branches on the direction of
 * motion (a coin toss per dimension for the branch predictor); the times are the same
 * expressions, so the same bits. */
/* Dimensions in which cell c touches the box (bit d): only there can a ball reach a wall
 * before it leaves its cell, since cells are at least one bounding diameter wide and a
 * wall is touched with the centre at most r from it. Elsewhere the wall test is skipped;
 * the crossing into a boundary cell computes it (cross). */
static inline unsigned boundary_dims(const rc_sim *s, const int c[3])
{
    unsigned m = 0;
    const int dim = s->def.dim < 3 ? s->def.dim : 3; /* (says so to the compiler) */
    for (int d = 0; d < dim; d++)
        m |= (unsigned)((c[d] == 0) | (c[d] == s->g.n[d] - 1)) << d;
    return m & s->walled; /* (a periodic axis has no wall) */
}

static void wall_event(const rc_sim *s, int32_t i, unsigned dims, double *best, int32_t *bp)
{
    if (!dims) /* (most cells) */
        return;
    const eng_ball *bi = &s->b[i];
    double bt = *best;
    int32_t bw = *bp;
    for (int d = 0; d < s->def.dim; d++) {
        if (!(dims >> d & 1u))
            continue;
        const double v = rc_v3_get(bi->v, d), x = rc_v3_get(bi->x, d);
        const double h = wall_support(s, i, d);
        const int up = v > 0.0, moving = v != 0.0;
        const double num = up ? s->L[d] - h - x : x - h;
        const double den = up ? v : (moving ? -v : 1.0);
        double t = bi->t + num / den;
        t = t < s->now ? s->now : t;
        const int take = moving & (t < bt);
        bt = take ? t : bt;
        bw = take ? ENG_WALL(2 * d + up) : bw;
    }
    *best = bt;
    *bp = bw;
}

/* The neighbour scans and the cell crossing run in the engine's lanes (engine/lanes.h:
 * AVX-512, AVX2 or plain C by s->simd, the same bits every way). */
static inline int test_list(const rc_sim *s, int32_t i, int32_t *nb, size_t m, double *best,
                            int32_t *bp, const eng_check *chk, double T, int latest,
                            int per)
{
    return eng_lanes_of(s->simd)->test_list(s, i, nb, m, best, bp, chk, T, latest, per);
}

static inline void sphere_lanes(const rc_sim *s, int32_t i, int32_t *nb, size_t m, double best,
                                double *t, uint64_t hit[2], uint64_t near[2])
{
    eng_lanes_of(s->simd)->sphere_times(s, i, nb, m, best, t, hit, near);
}

static inline void cross_event(rc_sim *s, int32_t i, const int c[3])
{
    eng_lanes_of(s->simd)->cross_event(s, i, c);
}

/* 1 if neighbour bk of bi is in contact with bi's old shape within sim_tol and approaching
 * it: bounding spheres within sim_tol, approaching, not separated along the centre line,
 * and the frame's contact time within sim_tol of now (grow_group's tests, in its order).
 * dx, d2: pair_sep's separation and its square; *normal (if asked): the frame's normal. */
static int narrow_conflict(rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                           double d2, const eng_check *chk, rc_vec3 *normal)
{
    const double stol = s->def.sim_tol, atol = s->def.approach_tol;
    const double sig = bi->r + bk->r, lim = sig * (1.0 + stol);
    if (!(d2 <= lim * lim))
        return 0;
    /* approaching: grow_group's test (engine/approach.h), ball i with its old state */
    const eng_aux *ak = &s->a[bk - s->b];
    const rc_particle pk = {ak->m, ak->p};
    double dv2;
    if (!eng_approaching(s->inv_c2, &chk->old, chk->vold, &pk, bk->v, dx, sig, atol, &dv2))
        return 0;
    const rc_vec3 n = rc_v3_scale(1.0 / sqrt(d2), dx);
    /* supports along n: ball i's old shape (its state before the collision), k's as is */
    const rc_toi_shape ho = rc_toi_shape_of(bi->r, chk->old.m, chk->old.p, s->inv_c2);
    const rc_toi_shape hk = shape_of(s, bk);
    const double hsum = rc_toi_support_(&ho, n) + rc_toi_support_(&hk, n);
    if (d2 > hsum * hsum * (1.0 + stol) * (1.0 + stol) * (1.0 + 1e-12))
        return 0;
    rc_toi_contact out;
    int st;
    if (s->table) { /* (as in pair_time_dx; chk->vold is the old p / M, as stored) */
        st = s->shapes(&ho, &hk, dx, rc_v3_sub(bk->v, chk->vold), &s->toi, s->ws,
                       &out.t, NULL, &out.n);
    } else {
        rc_toi_ball A = {rc_v3(0, 0, 0), bi->r, chk->old.m, chk->old.p};
        rc_toi_ball B = {dx, bk->r, ak->m, ak->p};
        st = s->def.frame->toi(&s->toi, &A, &B, s->ws, &out);
    }
    if (!(st == RC_OK && out.t * out.t * dv2 <= stol * stol * sig * sig))
        return 0;
    if (normal)
        *normal = out.n;
    return 1;
}

/* Table frame: a pair about to be put to the frame at once (no bound puts its contact
 * ahead of now: the bounding spheres overlap and the centre line does not separate the
 * shapes) whose shapes overlap now -- in a contracted gas about half the pairs asked at
 * once are such shape-change overlaps. pw_certify finds them in a step or two, where the
 * frame's test that says RC_EOVERLAP costs a root find. Only for approaching bounding
 * spheres: pair_time_dx's path that answers an overlap with now and a NAN normal (a
 * parting pair is left to separate). 1: overlapping. */
static int overlap_now(const rc_sim *s, const rc_toi_shape *shi, const eng_ball *bi,
                       const eng_ball *bk, double best)
{
    double tref;
    const rc_vec3 dx = pair_sep(s, bi, bk, &tref);
    const double d2 = rc_v3_norm2(dx), sig = bi->r + bk->r;
    if (!(d2 <= sig * sig && d2 > 0.0) ||
        !(sphere_time_dx(s, bi, bk, dx, d2, tref, best) < best))
        return 0;
    const rc_toi_shape shk = shape_of(s, bk);
    const double hi = rc_toi_support_scaled_(shi, dx, d2);
    const double hk = rc_toi_support_scaled_(&shk, dx, d2);
    double bound;
    return pw_certify(s, bi, bk, dx, d2, tref, hi / (hi + hk), &bound) == PW_OVERLAP;
}

/* Contracted frames: the root finding is the cost, so first collect the neighbours whose
 * bounding spheres can touch before `best`, then ask the frame in order of a lower bound
 * of the contracted contact (the bounding spheres', for the table frame also the
 * centre line's separating axis) and stop as soon as the next bound is no earlier than
 * the best contracted contact. Ordered by sphere time alone, the frame was asked 1.26
 * times per scan that asked it, by the tighter bound (then with the balls' directions of
 * motion as axes too) 1.07 times (bench_engine rel:3000); the first
 * answer is then mostly the earliest, and later candidates are pruned by their bounds.
 * With df (the table frame, eng_defer) the frame is not asked at all about a candidate
 * whose bound lies ahead: the least such bound is stored as the event, with the next
 * least as the bound of the others (eng_settle asks the frame when it comes up).
 * Candidates bounded by now (touching or parting bounding spheres) are still asked at
 * once, and an incoming deferred event (a crossing's scan) is merged with the new ones. */
static int scan_block_narrow(const rc_sim *cs, int32_t i, eng_walk *w, double *best,
                             int32_t *bp, rc_vec3 *bn, const eng_check *chk, eng_defer *df)
{
    rc_sim *s = (rc_sim *)cs; /* the candidate buffer is scratch */
    const eng_ball *bi = &s->b[i];
    size_t nc = 0;
    int32_t nb[NB_CAP];
    double t[NB_CAP];
    const int table = s->table;
    const rc_toi_shape shi = shape_of(s, bi); /* (the scanning ball's, for every pair) */
    /* what a candidate must beat to matter: the best event, or with one deferred the bound
     * of the others (a candidate below it can lower that bound) */
    const double cut0 = df && df->on ? df->lb2 : *best;
    eng_rows rows = {0, {NULL}, {0}}; /* (the model's records of a candidate, prefetched) */
    if (s->model->candidate_rows)
        s->model->candidate_rows(s, &rows);
    while (!w->done) {
        /* gather a chunk of neighbours ... */
        const size_t m = walk_gather(w, nb);
        /* ... then the bounding spheres in lanes, and the candidates that can beat best
         * (only the live neighbours: the others have no time and are not near) */
        uint64_t hit[2], nearb[2];
        sphere_lanes(s, i, nb, m, cut0, t, hit, nearb);
        for (size_t lw = 0; lw < 2; lw++)
        for (uint64_t bits = hit[lw] | nearb[lw]; bits; bits &= bits - 1u) {
            const size_t j = 64 * lw + (size_t)__builtin_ctzll(bits);
            const int near = (int)(nearb[lw] >> (j % 64) & 1u);
            const int32_t kk = nb[j];
            if (chk && near && kk != chk->partner && !chk->zmf) {
                double tref;
                const eng_ball *bc = chk->at ? chk->at : bi; /* (at T, before the kink) */
                const rc_vec3 dx = pair_sep(s, bc, &s->b[kk], &tref);
                if (narrow_conflict(s, bc, &s->b[kk], dx, rc_v3_norm2(dx), chk, NULL))
                    return 1;
            }
            double tj = t[j];
            /* near and no bounding-sphere time: overlapping bounding spheres that part
             * may still hold shapes that meet (pair_time_dx); now is their lower bound */
            if (!(tj < cut0)) {
                if (!near || !parting_candidate(s, &shi, bi, &s->b[kk], cut0))
                    continue;
                tj = s->now;
            }
            if (!(tj < cut0))
                continue;
            if (nc == s->cand_cap) {
                size_t cap = s->cand_cap ? 2 * s->cand_cap : 64;
                eng_cand *c = realloc(s->cand, cap * sizeof *c);
                if (!c) { /* no memory: ask the frame at once */
                    rc_vec3 n;
                    double tn = pair_time(s, bi, &s->b[kk], cut0, &n);
                    if (df && df->on && !(tn < *best)) {
                        df->lb2 = tn < df->lb2 ? tn : df->lb2; /* (an event, so a bound) */
                    } else if (tn < *best) {
                        *best = tn;
                        *bp = kk;
                        *bn = n;
                        s->bx_tx = s->sc_tx;
                        s->bx_dx = s->sc_dx;
                        if (df)
                            df->on = 0;
                    }
                    continue;
                }
                s->cand = c;
                s->cand_cap = cap;
            }
            s->cand[nc].t = tj;
            s->cand[nc].k = kk;
            nc++;
            __builtin_prefetch(&s->a[kk]); /* (the frame will want its momentum and mass) */
            for (int q = 0; q < rows.n; q++)
                __builtin_prefetch(rows.base[q] + (size_t)kk * rows.stride[q]);
        }
    }
    for (size_t a = 1; a < nc; a++) { /* insertion sort by (t, k): lists are short */
        eng_cand c = s->cand[a];
        size_t b = a;
        while (b > 0 && (s->cand[b - 1].t > c.t ||
                         (s->cand[b - 1].t == c.t && s->cand[b - 1].k > c.k))) {
            s->cand[b] = s->cand[b - 1];
            b--;
        }
        s->cand[b] = c;
    }
    /* Best first, the bounds computed lazily: cand[0, nr) holds the candidates whose lower
     * bound lb (sphere time, and the centre line's for the table frame) is known, by
     * (lb, k); cand[u, nc) the others, by sphere time. The next is refined while its
     * sphere time could still put it first; else the frame is asked about the least lb. */
    size_t u = 0, nr = 0;
    for (;;) {
        const double cut = df && df->on ? df->lb2 : *best;
        size_t rb = nr;
        for (size_t q = 0; q < nr; q++)
            if (rb == nr || s->cand[q].t < s->cand[rb].t ||
                (s->cand[q].t == s->cand[rb].t && s->cand[q].k < s->cand[rb].k))
                rb = q;
        const double lr = rb < nr ? s->cand[rb].t : INFINITY;
        if (u < nc && s->cand[u].t < cut && s->cand[u].t <= lr) {
            eng_cand c = s->cand[u++];
            if (table) {
                const double ta = line_bound(s, &shi, bi, &s->b[c.k]);
                c.t = ta > c.t ? ta : c.t;
            }
            if (c.t < cut)
                s->cand[nr++] = c;
            continue;
        }
        if (!(lr < cut))
            break;
        const int32_t k = s->cand[rb].k;
        s->cand[rb] = s->cand[--nr];
        if (df && df->on) { /* a second bound below the deferred one's others' */
            if (lr < *best) {
                df->lb2 = *best;
                *best = lr;
                *bp = k;
            } else {
                df->lb2 = lr;
            }
            continue;
        }
        if (df && lr > s->now) { /* the least bound: defer asking the frame (eng_settle) */
            df->on = 1;
            df->lb2 = *best;
            *best = lr;
            *bp = k;
            /* the others' bound: the least left, refined or not (refining it costs more
             * than the rare settle it would spare) */
            size_t r2 = nr;
            for (size_t q = 0; q < nr; q++)
                if (r2 == nr || s->cand[q].t < s->cand[r2].t)
                    r2 = q;
            if (r2 < nr && s->cand[r2].t < df->lb2)
                df->lb2 = s->cand[r2].t;
            if (u < nc && s->cand[u].t < df->lb2)
                df->lb2 = s->cand[u].t;
            break;
        }
        rc_vec3 n;
        double t;
        if (table && lr <= s->now && overlap_now(s, &shi, bi, &s->b[k], *best)) {
            t = s->now; /* (pair_time's answer, without the frame) */
            n = rc_v3(NAN, NAN, NAN);
        } else {
            t = pair_time(s, bi, &s->b[k], *best, &n);
        }
        if (t < *best) {
            *best = t;
            *bp = k;
            *bn = n;
            s->bx_tx = s->sc_tx;
            s->bx_dx = s->sc_dx;
        }
    }
    return 0;
}

/* Scan the cells around c with offsets lo[d]..hi[d] (clipped to the grid). *bn: the
 * contact normal of a ball event found by a contracted frame. */
static int scan_block(const rc_sim *s, int32_t i, const int c[3], const int lo[3],
                      const int hi[3], double *best, int32_t *bp, rc_vec3 *bn,
                      const eng_check *chk, eng_defer *df)
{
    eng_walk w;
    walk_init(&w, s, i, c, lo, hi);
    if (s->narrow)
        return scan_block_narrow(s, i, &w, best, bp, bn, chk, df);
    int32_t nb[NB_CAP];
    while (!w.done) {
        const size_t m = walk_gather(&w, nb);
        test_list(s, i, nb, m, best, bp, NULL, 0.0, 0, w.image);
    }
    return 0;
}

static inline void store_event(rc_sim *s, int32_t i, double best, int32_t bp, rc_vec3 bn,
                               const eng_defer *df)
{
    eng_aux *a = &s->a[i];
    a->ev_t = best;
    a->ev_partner = bp;
    a->ev_pcount = bp >= 0 ? s->cnt[bp] : 0;
    if (s->ev_n) /* (a deferred event displaced by a wall leaves its mark in bn) */
        s->ev_n[i] = df && df->on && bp >= 0 ? ev_deferred_mark(df->lb2)
                     : ev_is_deferred(bn)    ? rc_v3(0.0, 0.0, 0.0)
                                             : bn;
    if (s->model->event_keep && bp >= 0 && (!isnan(bn.x) || bn.y == 1.0))
        s->model->event_keep(s, i); /* (the event's X, a tube conflict's too) */
}

/* Walls (dims) for a deferred event too: a wall before its bound is the event, one
 * before the bound of the others lowers that. */
static void wall_event_defer(const rc_sim *s, int32_t i, unsigned dims, double *best,
                             int32_t *bp, eng_defer *df)
{
    if (!df->on) {
        wall_event(s, i, dims, best, bp);
        return;
    }
    double tw = df->lb2;
    int32_t pw = ENG_NONE;
    wall_event(s, i, dims, &tw, &pw);
    if (pw == ENG_NONE)
        return;
    if (tw < *best) {
        *best = tw;
        *bp = pw;
        df->on = 0;
    } else {
        df->lb2 = tw;
    }
}

/* Full prediction for ball i: walls, the 3^d cells around it, its next cell crossing.
 * defer: a contracted frame's ball event may be stored deferred (its bound). */
static void predict(rc_sim *s, int32_t i, int update_heap, int defer)
{
    double best = INFINITY;
    int32_t bp = ENG_NONE;
    rc_vec3 bn = rc_v3(0, 0, 0);
    eng_defer df = {0, INFINITY};
    int c[3];
    cell_coords(&s->g, s->a[i].cell, c);
    wall_event(s, i, boundary_dims(s, c), &best, &bp);
    static const int lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    scan_block(s, i, c, lo, hi, &best, &bp, &bn, NULL, defer && s->defer ? &df : NULL);
    store_event(s, i, best, bp, bn, &df);
    cross_event(s, i, c);
    if (update_heap)
        eng_queue_update(&s->q, (uint32_t)i, key_of(&s->a[i]));
}

void eng_predict(rc_sim *s, int32_t i, int update_heap)
{
    predict(s, i, update_heap, 1);
}

/* Ball i's deferred event is due (s->now is its bound, both balls unchanged since): ask
 * the frame about its pair. Contact before the bound of every other candidate: that is
 * the event, stored with its normal. Else (later, or no contact) a full prediction that
 * asks the frame at once. The queue is updated. */
void eng_settle(rc_sim *s, int32_t i)
{
    eng_aux *a = &s->a[i];
    const double lb2 = s->ev_n[i].x;
    rc_vec3 n;
    const double t = pair_time(s, &s->b[i], &s->b[a->ev_partner], lb2, &n);
    if (t < lb2) {
        a->ev_t = t;
        s->ev_n[i] = n;
        eng_queue_update(&s->q, (uint32_t)i, key_of(a));
    } else {
        predict(s, i, 1, 0);
    }
}

/* eng_predict for a ball of a contracted frame that has just collided, looking for
 * another simultaneous contact as it scans (walls too, with its old shape): 1 on one
 * (nothing stored: the caller resolves the whole group), else the events are stored
 * (the heap is not updated) and 0. */
int eng_predict_checked_narrow(rc_sim *s, int32_t i, const eng_check *chk)
{
    const eng_ball *bi = chk->at ? chk->at : &s->b[i]; /* (for the checks: at T) */
    int c[3];
    cell_coords(&s->g, s->a[i].cell, c);
    const unsigned walls = boundary_dims(s, c);
    const int check = s->def.sim_tol > 0.0;
    for (int d = 0; d < s->def.dim && check && walls; d++) {
        const double v = rc_v3_get(chk->vold, d), x = rc_v3_get(bi->x, d);
        const int w = 2 * d + (v > 0.0);
        if (v == 0.0 || ENG_WALL(w) == chk->partner)
            continue;
        double h = bi->r; /* the old shape's support along e_d, as wall_support */
        if (s->wall_contracted) {
            const rc_toi_shape ho = rc_toi_shape_of(bi->r, chk->old.m, chk->old.p, s->inv_c2);
            h = axis_support(&ho, d);
        }
        const double gap = v > 0.0 ? s->L[d] - h - x : x - h;
        if (gap <= s->def.sim_tol * bi->r)
            return 1;
    }
    double best = INFINITY;
    int32_t bp = ENG_NONE;
    rc_vec3 bn = rc_v3(0, 0, 0);
    eng_defer df = {0, INFINITY};
    wall_event(s, i, walls, &best, &bp);
    static const int lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    if (scan_block(s, i, c, lo, hi, &best, &bp, &bn, check ? chk : NULL, s->defer ? &df : NULL))
        return 1;
    store_event(s, i, best, bp, bn, &df);
    cross_event(s, i, c);
    return 0;
}

/* Full prediction for member i of a tentatively resolved single contact (i is at time T,
 * chk->old its state before, chk->vold its velocity): while scanning, look with the old
 * state for any other contact simultaneous with the resolved one (gap <= sim_tol,
 * approaching) -- the same test as grow_group, at no extra distance computation. Returns
 * 1 on such a contact (the caller then undoes and resolves the whole group), else stores
 * the event and returns 0. */
int eng_predict_checked(rc_sim *s, int32_t i, const eng_check *chk, double T)
{
    const rc_vec3 vold = chk->vold;
    const int32_t partner = chk->partner;
    const double stol = s->def.sim_tol;
    const eng_ball *bi = &s->b[i];
    /* sim_tol = 0: no grouping asked for, no check */
    const int check = stol > 0.0;
    int c[3];
    cell_coords(&s->g, s->a[i].cell, c);
    const unsigned walls = boundary_dims(s, c);
    for (int d = 0; d < s->def.dim && check && walls; d++) {
        double v = rc_v3_get(vold, d), x = rc_v3_get(bi->x, d);
        if (v == 0.0)
            continue;
        int w = 2 * d + (v > 0.0);
        if (ENG_WALL(w) == partner)
            continue;
        double h = wall_support(s, i, d);
        double gap = v > 0.0 ? s->L[d] - h - x : x - h;
        if (gap <= stol * bi->r)
            return 1;
    }
    double best = INFINITY;
    int32_t bp = ENG_NONE;
    wall_event(s, i, walls, &best, &bp);
    static const int lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    eng_walk w;
    walk_init(&w, s, i, c, lo, hi);
    int32_t nb[NB_CAP];
    while (!w.done) {
        const size_t m = walk_gather(&w, nb);
        if (test_list(s, i, nb, m, &best, &bp, check ? chk : NULL, T, 1, w.image))
            return 1;
    }
    store_event(s, i, best, bp, rc_v3(0, 0, 0), NULL);
    cross_event(s, i, c);
    return 0;
}

/* A periodic engine brings a crossing ball's state to the crossing (position and proper
 * time): every stored position then lies in its ball's current cell at every time from
 * its clock to its next crossing, so a pair's separation at the later of their clocks
 * is that of two balls in their current cells -- less than two cells apart along an axis
 * when they are neighbours, less than L / 2 with four cells or more, where the nearest
 * image is the copy they can meet (taken at an older time, after a long flight through
 * several cells, it could be the other one). If the crossing is through a periodic face
 * the ball then moves by -dir L_d and its image counter keeps the unwrapped position. */
static void periodic_cross(rc_sim *s, int32_t i, int d, int dir, int wrap)
{
    eng_ball *b = &s->b[i];
    const eng_aux *a = &s->a[i];
    const double h = s->now - b->t;
    if (h != 0.0) {
        b->x = rc_v3_axpy(b->x, h, b->v);
        s->clk[i].tau += s->inv_c2 == 0.0 ? h : h * (a->m / eng_mass_rel(a->m, a->p, s->inv_c2));
        b->t = s->now;
    }
    if (wrap) {
        rc_v3_set(&b->x, d, rc_v3_get(b->x, d) - dir * s->L[d]);
        s->img[3 * (size_t)i + (size_t)d] += dir;
    }
}

/* Ball i enters the next cell: the balls that became neighbours are one slab of cells. */
void eng_cross(rc_sim *s, int32_t i)
{
    eng_aux *a = &s->a[i];
    int d = a->cross_code / 2, dir = (a->cross_code & 1) ? 1 : -1;
    int c[3];
    cell_coords(&s->g, a->cell, c);
    c[d] += dir;
    const int wrap = c[d] < 0 || c[d] >= s->g.n[d]; /* (only on a periodic axis: cross_event) */
    if (wrap)
        c[d] = c[d] < 0 ? s->g.n[d] - 1 : 0;
    if (s->periodic)
        periodic_cross(s, i, d, dir, wrap);
    eng_cells_remove(&s->g, s->a, i);
    eng_cells_insert(&s->g, s->a, i, (int32_t)(c[0] + s->g.n[0] * (c[1] + s->g.n[1] * c[2])));
    s->bk.events[RC_SIM_EV_CELL]++;
    if (a->ev_partner >= 0 && s->cnt[a->ev_partner] != a->ev_pcount) {
        eng_predict(s, i, 1); /* the kept event went stale: full scan */
        return;
    }
    double best = a->ev_t;
    int32_t bp = a->ev_partner;
    rc_vec3 bn = s->ev_n ? s->ev_n[i] : rc_v3(0, 0, 0);
    if (s->model->event_recall) /* (the kept event's X, unless a scan finds a better one) */
        s->model->event_recall(s, i);
    eng_defer df = {s->defer && bp >= 0 && ev_is_deferred(bn), bn.x};
    int lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    lo[d] = hi[d] = dir;
    if (s->def.dim == 2)
        lo[2] = hi[2] = 0;
    scan_block(s, i, c, lo, hi, &best, &bp, &bn, NULL, s->defer ? &df : NULL);
    if ((s->walled >> d & 1u) && (c[d] == 0 || c[d] == s->g.n[d] - 1))
        /* a boundary cell: its wall is now in reach */
        wall_event_defer(s, i, 1u << d, &best, &bp, &df);
    if (bp != a->ev_partner || best != a->ev_t || df.on)
        store_event(s, i, best, bp, bn, &df);
    cross_event(s, i, c);
    eng_queue_update(&s->q, (uint32_t)i, key_of(a));
}

/* For engine/core.c (the functions above stay static so that their callers here inline
 * them: an exported function of a shared library is called through the PLT). */
double eng_wall_support(const rc_sim *s, int32_t i, int d) { return wall_support(s, i, d); }

int eng_narrow_conflict(rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                           double d2, const eng_check *chk, rc_vec3 *normal)
{
    return narrow_conflict(s, bi, bk, dx, d2, chk, normal);
}
