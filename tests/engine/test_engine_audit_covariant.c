/* test_engine_audit_covariant.c — an all-pairs audit of the covariant frame (per_ball kinks
 * on glued world tubes, papers/covariant-frame.md section 5) in a 2-D walled gas at c = 1, independent
 * of the engine's contact code. The engine is stepped one event at a time; after each
 * event the audit rebuilds every ball's worldline from what the engine reports (its lines
 * and, per kink, its glued tube: rc_sim_get_ball_latest, rc_sim_get_glue) and checks every
 * pair whose bounding discs meet on the table-time slice ta = now - W, W twice the longest
 * glue window a ball as fast as any so far can have: the engine processes collisions in the
 * table time of their contact events, and a kink (and its window) can come up to a window
 * before it, so only slices that far back are final (read at now, the audit found pairs
 * overlapping before their collision was processed: not a fault, the slice was not
 * complete). A ball's section at ta is its contracted disc on its line there, or inside
 * the window of a kink the incoming disc's part not yet reached by the kink's hyperplane H
 * and the outgoing disc's part reached (inside two windows, three parts); the depth of an
 * overlap is this file's own: the largest d such that some point lies at depth d in both
 * sections, depth in a disc being 1 - (rest-frame distance from the centre) / r and in a
 * half-plane its distance / r (for two whole discs 1 - mu, mu the Perram-Wertheim scale of
 * test_engine_audit), found by nested golden sections (the depth is concave on each convex
 * part). A new overlap is allowed near an event the engine counted (overlap policy, tube or
 * order conflicts, a group: rc_sim_diag) that changed one of the two balls; a section the
 * model leaves undefined (the order rule's kinks, three windows at once, hyperplanes
 * sweeping a ball out of order) is not judged, and counted. Any other new overlap is a
 * fault, printed with seed, event, slice time and balls.
 * Beside it, after every event, rc_sim_get_ball of every ball is compared with the rebuilt
 * worldline at the engine's time: a ball whose kink (or two) lies ahead must be read on
 * the line it is still on.
 * AUDIT_NO_GLUE=1 reads every ball as the disc of its line (the shape jumps at its kink):
 * the audit then finds 142 and 59 faults in the two runs, so it sees what the glue does. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine_util.h"

/* An overlap deeper than this (relative to the radius) is one: the engine's overlap_tol.
 * Contact events and kinks carry round-off of ~1e-13 of r (root finds to touch_tol 1e-12 in
 * the ZMF, the hyperplane through X computed from rounded velocities), so two sections that
 * touched at a contact may come out 1e-13..1e-12 inside each other; 1e-9 is far above that
 * and far below any overlap the overlap policy resolves (the frame's touch_tol and the
 * policy's own threshold are overlap_tol). */
#define OVERLAP 1e-9
/* golden-section steps per axis: 0.618^80 of a diameter is below the round-off of the
 * coordinates */
#define GOLDEN 80

/* One convex piece of a section: the contracted disc (centre c, rest radius r, velocity v
 * in units of c) cut to the half-planes k[j].y >= h[j], j < cut (k unit). */
typedef struct piece {
    double cx, cy, r, bx, by, g2;
    int cut;
    double kx[2], ky[2], h[2];
} piece;

static piece disc(double cx, double cy, double r, double vx, double vy)
{
    piece p;
    memset(&p, 0, sizeof p);
    p.cx = cx;
    p.cy = cy;
    p.r = r;
    p.bx = vx;
    p.by = vy;
    p.g2 = 1.0 - (vx * vx + vy * vy);
    return p;
}

/* The half-plane of the points not yet reached by g's hyperplane at time t (side 0) or
 * reached (side 1), added to p's cuts. 0 if kappa = 0 (no plane to cut by). */
static int add_cut(piece *p, const rc_glue *g, double t, int side)
{
    const double kn = hypot(g->kappa.x, g->kappa.y);
    if (!(kn > 0.0) || p->cut >= 2)
        return 0;
    const double kx = g->kappa.x / kn, ky = g->kappa.y / kn;
    const double h = (t - g->t_x + g->kappa.x * g->x.x + g->kappa.y * g->x.y) / kn;
    p->kx[p->cut] = side ? -kx : kx;
    p->ky[p->cut] = side ? -ky : ky;
    p->h[p->cut] = side ? -h : h;
    p->cut++;
    return 1;
}

/* Depth of (x, y) in p relative to r: the rest-frame length of the offset is
 * sqrt(|d|^2 + gamma^2 (beta.d)^2). */
static double depth(const piece *p, double x, double y)
{
    const double dx = x - p->cx, dy = y - p->cy, bd = p->bx * dx + p->by * dy;
    double f = 1.0 - sqrt(dx * dx + dy * dy + bd * bd / p->g2) / p->r;
    for (int j = 0; j < p->cut; j++) {
        const double s = (p->kx[j] * x + p->ky[j] * y - p->h[j]) / p->r;
        f = s < f ? s : f;
    }
    return f;
}

static double both(const piece *a, const piece *b, double x, double y)
{
    const double fa = depth(a, x, y), fb = depth(b, x, y);
    return fa < fb ? fa : fb;
}

/* max over [lo, hi] of a function concave there, f(ctx, u): golden section */
typedef struct two_pieces {
    const piece *a, *b;
    double x, y0, y1;
} two_pieces;

static double golden_max(double (*f)(const two_pieces *, double), const two_pieces *ctx,
                         double lo, double hi)
{
    const double gr = 0.5 * (sqrt(5.0) - 1.0);
    double u = hi - gr * (hi - lo), w = lo + gr * (hi - lo);
    double fu = f(ctx, u), fw = f(ctx, w);
    for (int it = 0; it < GOLDEN; it++) {
        if (fu < fw) {
            lo = u;
            u = w;
            fu = fw;
            w = lo + gr * (hi - lo);
            fw = f(ctx, w);
        } else {
            hi = w;
            w = u;
            fw = fu;
            u = hi - gr * (hi - lo);
            fu = f(ctx, u);
        }
    }
    return fu > fw ? fu : fw;
}

static double both_at_y(const two_pieces *c, double y) { return both(c->a, c->b, c->x, y); }

/* max over y in [y0, y1] of both(a, b, x, y) (concave in y) */
static double best_y_at_x(const two_pieces *c, double x)
{
    const two_pieces at = {c->a, c->b, x, c->y0, c->y1};
    return golden_max(both_at_y, &at, c->y0, c->y1);
}

/* The overlap depth of two pieces (negative: apart), over the box where both bounding
 * discs lie. */
static double overlap2(const piece *a, const piece *b)
{
    const double x0 = fmax(a->cx - a->r, b->cx - b->r), x1 = fmin(a->cx + a->r, b->cx + b->r);
    const double y0 = fmax(a->cy - a->r, b->cy - b->r), y1 = fmin(a->cy + a->r, b->cy + b->r);
    if (!(x0 < x1 && y0 < y1))
        return -1.0;
    const two_pieces c = {a, b, 0.0, y0, y1};
    return golden_max(best_y_at_x, &c, x0, x1);
}

/* The pieces of a ball's section at time t inside the windows of its kinks g[0 .. ng)
 * (ng 1 or 2, in order along its worldline): the incoming disc of g[0] not yet reached by
 * any of the hyperplanes, each line between two kinks reached by the one before it and not
 * by the one after, and the last outgoing disc reached by the last. -1 if a hyperplane
 * has no tilt. */
static int glue_pieces(const rc_glue *const *g, int ng, double t, piece *out)
{
    int np = 0;
    for (int k = 0; k <= ng; k++) {
        const rc_glue *a = k < ng ? g[k] : g[ng - 1];
        const rc_vec3 v = k < ng ? a->v_in : a->v_out;
        const rc_vec3 c = rc_v3_axpy(a->x_c, t - a->t_c, v);
        piece p = disc(c.x, c.y, a->r, v.x, v.y);
        if (k > 0 && !add_cut(&p, g[k - 1], t, 1))
            return -1;
        if (k < ng && !add_cut(&p, g[k], t, 0))
            return -1;
        out[np++] = p;
    }
    return np;
}

static int in_window(const rc_glue *g, double t) { return g->r > 0.0 && t > g->t_first && t < g->t_last; }

static int same_glue(const rc_glue *a, const rc_glue *b)
{
    return a->r == b->r && a->t_x == b->t_x && a->t_c == b->t_c &&
           memcmp(&a->v_out, &b->v_out, sizeof a->v_out) == 0;
}

/* A ball's worldline as the audit rebuilds it from what the engine reports after each
 * event: a list of lines, each from its kink (ts, xs) with velocity v; a line that began
 * with a glued tube keeps it (tube.r > 0); a kink the order rule put at the previous one
 * (the engine reports no tube for it) starts a line at the same point, and the tube it
 * supersedes is not defined (und_lo .. und_hi). */
typedef struct line {
    double ts, tr; /* its kink's time (-inf: the start), and the time of its point xs */
    rc_vec3 xs, v;
    rc_glue tube;
    double und_lo, und_hi;
} line;

typedef struct hist {
    line *l;
    size_t n, cap;
    /* counted events that changed the ball: event number, and the interval of table time
     * their geometry can reach (the event's time -+ the ball's longest window then) */
    double *counted;
    long *cev;
    size_t nc, ccap;
    double r;
} hist;

static void push_line(hist *h, line l)
{
    if (h->n == h->cap) {
        h->cap = h->cap ? 2 * h->cap : 8;
        h->l = realloc(h->l, h->cap * sizeof *h->l);
    }
    h->l[h->n++] = l;
}

static void push_counted(hist *h, double lo, double hi, long ev)
{
    if (h->nc == h->ccap) {
        h->ccap = h->ccap ? 2 * h->ccap : 8;
        h->counted = realloc(h->counted, 2 * h->ccap * sizeof *h->counted);
        h->cev = realloc(h->cev, h->ccap * sizeof *h->cev);
    }
    h->counted[2 * h->nc] = lo;
    h->counted[2 * h->nc + 1] = hi;
    h->cev[h->nc++] = ev;
}

/* The section of a ball at time t from its history: 1 or 2 pieces, or 0 if the model
 * leaves it undefined there (two windows overlap, a tube superseded by the order rule, a
 * tube whose incoming line is not the line before it). */
/* why sections were undefined: order rule, three windows, a tube not continuing its line,
 * crossing hyperplanes, no tilt (printed with the results) */
static long why[5];

static int section_at(const hist *h, double t, piece out[3])
{
    size_t e = 0; /* the last line begun by t (a later one begun at the same kink wins) */
    for (size_t k = 0; k < h->n; k++) {
        if (t >= h->l[k].und_lo && t <= h->l[k].und_hi) {
            why[0]++;
            return 0;
        }
        if (h->l[k].ts <= t)
            e = k;
    }
    int nw = 0;
    size_t w[2] = {0, 0};
    for (size_t k = 0; k < h->n; k++)
        if (in_window(&h->l[k].tube, t)) {
            if (nw < 2)
                w[nw] = k;
            nw++;
        }
    if (nw > 2 || (nw == 2 && w[1] != w[0] + 1)) {
        why[1]++;
        return 0;
    }
    /* a later kink whose window has begun (and ended: else it would be counted here)
     * while an earlier one still sweeps: parts reached by its hyperplane first */
    for (size_t k = nw ? w[nw > 2 ? 1 : nw - 1] + 1 : h->n; k < h->n; k++)
        if (h->l[k].tube.r > 0.0 && h->l[k].tube.t_first <= t) {
            why[3]++;
            return 0;
        }
    if (nw >= 1 && !getenv("AUDIT_NO_GLUE")) {
        const rc_glue *g[2];
        for (int k = 0; k < nw; k++) {
            const size_t q = w[k];
            g[k] = &h->l[q].tube;
            /* each tube continues the line before it, and is not superseded */
            if (q == 0 || rc_v3_norm(rc_v3_sub(g[k]->v_in, h->l[q - 1].v)) > 1e-12 ||
                (q + 1 < h->n && h->l[q + 1].ts == h->l[q].ts)) {
                why[2]++;
                return 0;
            }
        }
        if (nw == 2) {
            /* the tube is defined only if every part of the section reached by the later
             * hyperplane has been reached by the earlier one: no point of any of the three
             * discs (incoming, between, outgoing) lies after H[1] but before H[0] (they
             * cross inside the tube, or the later one sweeps part of it first: the order
             * rule's case, which the engine checks at the centre only) */
            const rc_vec3 vs[3] = {g[0]->v_in, g[0]->v_out, g[1]->v_out};
            for (int q = 0; q < 3; q++) {
                const rc_glue *a = q < 2 ? g[0] : g[1];
                const rc_vec3 c = rc_v3_axpy(a->x_c, t - a->t_c, vs[q]);
                piece dq = disc(c.x, c.y, a->r, vs[q].x, vs[q].y);
                if (!add_cut(&dq, g[1], t, 1) || !add_cut(&dq, g[0], t, 0) ||
                    overlap2(&dq, &dq) > -1e-3) {
                    why[3]++;
                    return 0;
                }
            }
        }
        const int np = glue_pieces(g, nw, t, out);
        if (np < 0)
            why[4]++;
        return np < 0 ? 0 : np;
    }
    const line *l = &h->l[e];
    const rc_vec3 c = rc_v3_axpy(l->xs, t - l->tr, l->v);
    out[0] = disc(c.x, c.y, h->r, l->v.x, l->v.y);
    return 1;
}

typedef struct audit_out {
    long events, slices, pairs, counted, counted_pair, undefined, faults;
    long reads_ahead, reads_two_ahead, read_bad;
    /* delayed slices (rc_sim_slice_*): ball-states compared with the rebuilt worldline when
     * final and again three delays later, proper times compared, wrong ones, late changes,
     * slices the engine refused (three kinks ahead of ts) */
    long slice_reads, slice_tau, slice_bad, slice_late, slice_refused, slices_done;
    double slice_err, slice_use; /* slice_use: the largest reach / W (rc_sim_slice_info) */
    long undone; /* kinks the engine undid (their lines dropped from the history) */
    double read_err;
    double worst, worst_fault, span;
} audit_out;

/* Every ball of delayed slice id at ts against the rebuilt worldlines: the line begun by
 * the last kink at or before ts, where the model defines it (not inside the void windows
 * of the order rule's kinks). 1e-9 of r and of c: the same lines through the same kinks,
 * computed in another order (round-off ~1e-13). Where that line is the ball's latest
 * segment, its proper time at ts is the latest read-out's taken back along it, to 1e-9
 * relative (times ~50, round-off ~1e-14 relative). The slice's sums are not compared with
 * the conserved ones: its balls are taken at one table time, while a collision exchanges
 * momentum across its hyperplanes, so a slice between a pair's two kinks holds one ball
 * before and the other after (relcol/sim.h). */
static void check_slice(rc_sim *s, const hist *H, size_t n, uint32_t id, double ts, double now,
                        audit_out *res)
{
    for (size_t i = 0; i < n; i++) {
        const hist *h = &H[i];
        size_t last = 0;
        int void_ = 0;
        for (size_t k = 0; k < h->n; k++) {
            if (h->l[k].ts <= ts)
                last = k;
            void_ |= !(h->l[k].und_lo > h->l[k].und_hi) && ts >= h->l[k].und_lo &&
                     ts <= h->l[k].und_hi;
        }
        if (void_)
            continue;
        rc_sim_ball b, w;
        ENSURE(rc_sim_slice_get(s, id, i, &b) == RC_OK);
        const line *l = &h->l[last];
        const rc_vec3 x = rc_v3_axpy(l->xs, ts - l->tr, l->v);
        const double M = sqrt(b.m * b.m + rc_v3_norm2(b.p));
        double err = fmax(rc_v3_norm(rc_v3_sub(b.x, x)) / h->r,
                          rc_v3_norm(rc_v3_sub(rc_v3_scale(1.0 / M, b.p), l->v)));
        res->slice_reads++;
        if (last == h->n - 1) {
            rc_sim_get_ball_latest(s, i, &w);
            const double tau = w.tau - (now - ts) * w.m / sqrt(w.m * w.m + rc_v3_norm2(w.p));
            err = fmax(err, fabs(b.tau - tau) / fmax(1.0, fabs(tau)));
            res->slice_tau++;
        }
        res->slice_err = fmax(res->slice_err, err);
        res->slice_bad += err > 1e-9;
    }
}

static void audit(size_t n, double packing, double v_rms, double eps, long events, uint64_t seed,
                  audit_out *res)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.c = 1.0;
    d.frame = &rc_toi_frame_covariant;
    d.eps_ball = eps;
    d.t_c = eps < 1.0 ? 0.05 : 0.0;
    rc_sim *s = util_gas(d, n, packing, v_rms, seed);
    if (!s)
        return;
    hist *H = calloc(n, sizeof *H);
    rc_glue *G = calloc(n, sizeof *G);
    rc_sim_ball *L = calloc(n, sizeof *L);
    double *R = calloc(n, sizeof *R);
    piece *P = calloc(3 * n, sizeof *P);
    int *np = calloc(n, sizeof *np);
    unsigned char *ov = calloc(n * n, 1);
    double vmax = 0.0;
    const double t0 = rc_sim_time(s);
    for (size_t i = 0; i < n; i++) {
        rc_sim_get_ball_latest(s, i, &L[i]);
        const double M = sqrt(L[i].m * L[i].m + rc_v3_norm2(L[i].p));
        line l0;
        memset(&l0, 0, sizeof l0);
        l0.ts = -INFINITY;
        l0.tr = t0;
        l0.xs = L[i].x;
        l0.v = rc_v3_scale(1.0 / M, L[i].p);
        l0.und_lo = 1.0;
        push_line(&H[i], l0);
        H[i].r = R[i] = L[i].r;
        vmax = fmax(vmax, rc_v3_norm(l0.v));
    }
    rc_sim_diag dg;
    rc_sim_diagnostics(s, &dg);
    uint64_t counted_before = dg.overlaps + dg.tube_conflicts + dg.order_conflicts +
                              dg.events[RC_SIM_EV_MULTI] + dg.group_fallbacks;
    memset(res, 0, sizeof *res);
    res->worst = res->worst_fault = -1.0;
    int printed = 0;
    double t_last_audit = -INFINITY;
    /* delayed slices held: id, table time, checked once final */
    enum { NSLICE = 32 };
    uint32_t sid[NSLICE];
    double sts[NSLICE];
    int sck[NSLICE];
    int nsl = 0;
    for (long e = 0; e < events; e++) {
        /* a slice asked for every 20 events, at the engine's time or a little ahead */
        if (e % 20 == 0 && nsl < NSLICE) {
            const double ts = rc_sim_time(s) + (e % 40 == 0 ? 0.0 : 0.3);
            const int st = rc_sim_slice_request(s, ts, &sid[nsl]);
            ENSURE(st == RC_OK || st == RC_EINVAL);
            if (st == RC_OK) {
                sts[nsl] = ts;
                sck[nsl++] = 0;
            } else {
                res->slice_refused++;
            }
        }
        if (rc_sim_advance(s, INFINITY, 1) != RC_OK)
            break;
        res->events++;
        const double now = rc_sim_time(s);
        rc_sim_diagnostics(s, &dg);
        const uint64_t counted_now = dg.overlaps + dg.tube_conflicts + dg.order_conflicts +
                                     dg.events[RC_SIM_EV_MULTI] + dg.group_fallbacks;
        const int counted = counted_now > counted_before;
        counted_before = counted_now;
        /* the event's kinks */
        for (size_t i = 0; i < n; i++) {
            rc_glue g;
            rc_sim_ball b;
            ENSURE(rc_sim_get_glue(s, i, &g) == RC_OK);
            rc_sim_get_ball_latest(s, i, &b);
            const int moved = memcmp(&b.p, &L[i].p, sizeof b.p) != 0 || b.m != L[i].m;
            if (!moved && same_glue(&g, &G[i]))
                continue;
            const double M = sqrt(b.m * b.m + rc_v3_norm2(b.p));
            const rc_vec3 v = rc_v3_scale(1.0 / M, b.p);
            vmax = fmax(vmax, rc_v3_norm(v));
            line l;
            memset(&l, 0, sizeof l);
            l.v = v;
            l.und_lo = 1.0; /* (empty) */
            /* a collision undone (papers/covariant-frame.md section 2): the new kink's
             * incoming line is the one before the last (the same momentum, so the same
             * velocity to round-off), whose kink is gone -- or, a chain undone (section 8),
             * the one before the last two */
            if (g.r > 0.0 && !same_glue(&g, &G[i]) && H[i].n >= 2 &&
                rc_v3_norm(rc_v3_sub(g.v_in, H[i].l[H[i].n - 1].v)) > 1e-14) {
                if (rc_v3_norm(rc_v3_sub(g.v_in, H[i].l[H[i].n - 2].v)) <= 1e-14) {
                    H[i].n--;
                    res->undone++;
                } else if (H[i].n >= 3 &&
                           rc_v3_norm(rc_v3_sub(g.v_in, H[i].l[H[i].n - 3].v)) <= 1e-14) {
                    H[i].n -= 2;
                    res->undone += 2;
                }
            }
            if (g.r > 0.0 && !same_glue(&g, &G[i])) { /* a kink on its glued tube */
                l.ts = l.tr = g.t_c;
                l.xs = g.x_c;
                l.tube = g;
            } else if (H[i].l[H[i].n - 1].ts > now) {
                /* a policy's or a group's kink at the event's time before a kink still
                 * pending overtakes it (core.c glue_kink_at, at_event): the pending lines are
                 * gone, the new one starts now from the stored line's centre */
                while (H[i].n > 1 && H[i].l[H[i].n - 1].ts > now)
                    H[i].n--;
                l.ts = l.tr = now;
                l.xs = b.x;
            } else { /* the order rule: at the previous kink, whose tube is void */
                const line *p = &H[i].l[H[i].n - 1];
                l.ts = p->ts;
                l.tr = p->tr;
                l.xs = p->xs;
                if (p->tube.r > 0.0) {
                    l.und_lo = p->tube.t_first;
                    l.und_hi = p->tube.t_last;
                }
                if (!(l.ts > -INFINITY)) { /* (no kink before: at the event, to be safe) */
                    l.ts = l.tr = now;
                    l.xs = b.x;
                    l.und_lo = now - 1.0;
                    l.und_hi = now + 1.0;
                }
            }
            push_line(&H[i], l);
            if (counted) {
                /* the ball's window: centre kink and half-width each within r / (c - v)
                 * of the event, for both its speeds (before and after) */
                const double vin = rc_v3_norm(H[i].l[H[i].n - 2].v), vo = rc_v3_norm(v);
                const double w = 2.0 * H[i].r / (1.0 - fmax(vin, vo));
                push_counted(&H[i], now - w, now + w, e);
            }
            G[i] = g;
            L[i] = b;
        }
        /* rc_sim_get_ball at now against the rebuilt worldline there (the line begun by
         * the last kink at or before now): the read-out of a ball whose kinks lie ahead
         * (one or two) is the line it is on. 1e-9 of r: the two are the same lines
         * through the same kinks, computed in other orders (round-off ~1e-13 r) */
        for (size_t i = 0; i < n; i++) {
            const hist *h = &H[i];
            size_t last = 0, ahead_n = 0;
            int void_ = 0;
            for (size_t k = 0; k < h->n; k++)
                if (h->l[k].ts <= now)
                    last = k;
            /* (a line begun later that a line after it in the history superseded -- a
             * kink overtaken at an event's time -- is not ahead) */
            for (size_t k = last + 1; k < h->n; k++)
                ahead_n += h->l[k].ts > now && h->l[k].ts != h->l[k - 1].ts;
            for (size_t k = 0; k < h->n; k++) {
                void_ |= !(h->l[k].und_lo > h->l[k].und_hi) && now >= h->l[k].und_lo &&
                         now <= h->l[k].und_hi;
            }
            const int ka = rc_sim_kink_ahead(s, i);
            if (ka == 2 || void_)
                continue;
            rc_sim_ball b;
            rc_sim_get_ball(s, i, &b);
            const line *l = &h->l[last];
            const rc_vec3 x = rc_v3_axpy(l->xs, now - l->tr, l->v);
            const double M = sqrt(b.m * b.m + rc_v3_norm2(b.p));
            const double err = fmax(rc_v3_norm(rc_v3_sub(b.x, x)) / h->r,
                                    rc_v3_norm(rc_v3_sub(rc_v3_scale(1.0 / M, b.p), l->v)));
            res->reads_ahead += ka == 1;
            res->reads_two_ahead += ka == 1 && ahead_n >= 2;
            res->read_err = fmax(res->read_err, err);
            res->read_bad += err > 1e-9 || (ka == 1) != (ahead_n > 0);
        }
        for (int q = 0; q < nsl; q++) {
            rc_sim_slice_info inf;
            if (rc_sim_slice_ready(s, sid[q], &inf) != 1)
                continue;
            if (!sck[q]) {
                check_slice(s, H, n, sid[q], sts[q], now, res);
                sck[q] = 1;
            } else if (now >= inf.t_final + 3.0 * (inf.t_final - inf.ts)) {
                check_slice(s, H, n, sid[q], sts[q], now, res);
                res->slice_late += (long)inf.late;
                res->slice_use = fmax(res->slice_use, inf.reach / (inf.t_final - inf.ts));
                res->slices_done++;
                ENSURE(rc_sim_slice_release(s, sid[q]) == RC_OK);
                sid[q] = sid[nsl - 1];
                sts[q] = sts[nsl - 1];
                sck[q] = sck[nsl - 1];
                nsl--;
                q--;
            }
        }
        /* The slice at ta = now - W is final: no collision processed later (contact
         * event at or after now) has a glue window reaching back before now - W, W twice
         * the longest window a ball as fast as any so far can have (its centre's kink and
         * the window's half-width are each at most r / (c - v) from the contact event). */
        const double W = 2.0 * 2.0 * 0.5 / (1.0 - vmax);
        const double ta = now - W;
        if (!(ta > t_last_audit) || ta < t0)
            continue;
        t_last_audit = ta;
        res->slices++;
        res->span = ta - t0;
        for (size_t i = 0; i < n; i++)
            np[i] = section_at(&H[i], ta, &P[3 * i]);
        for (size_t i = 0; i < n; i++)
            for (size_t j = i + 1; j < n; j++) {
                const piece *a0 = &P[3 * i], *b0 = &P[3 * j];
                const double rr = R[i] + R[j], dx = b0->cx - a0->cx, dy = b0->cy - a0->cy;
                if (np[i] && np[j] && dx * dx + dy * dy > 4.0 * rr * rr) {
                    ov[i * n + j] = 0;
                    continue;
                }
                if (!np[i] || !np[j]) { /* unknown: not new when it is known again */
                    res->undefined += !ov[i * n + j];
                    ov[i * n + j] = 1;
                    continue;
                }
                double f = -1.0;
                for (int a = 0; a < np[i]; a++)
                    for (int b = 0; b < np[j]; b++) {
                        const double fab = overlap2(&P[3 * i + a], &P[3 * j + b]);
                        f = fab > f ? fab : f;
                    }
                res->pairs++;
                res->worst = fmax(res->worst, f);
                const int over = f > OVERLAP;
                if (over && !ov[i * n + j]) {
                    /* a counted event of both balls (the engine's own pair) whose reach
                     * holds the slice, else one of either ball */
                    int both_ = 0, one = 0;
                    const hist *hi = &H[i], *hj = &H[j];
                    for (size_t k = 0; k < hi->nc; k++) {
                        if (!(ta >= hi->counted[2 * k] && ta <= hi->counted[2 * k + 1]))
                            continue;
                        one = 1;
                        for (size_t q = 0; q < hj->nc && !both_; q++)
                            both_ = hj->cev[q] == hi->cev[k];
                    }
                    for (size_t k = 0; k < hj->nc && !one; k++)
                        one = ta >= hj->counted[2 * k] && ta <= hj->counted[2 * k + 1];
                    if (both_ || one) {
                        res->counted++;
                        res->counted_pair += both_;
                    } else {
                        res->faults++;
                        res->worst_fault = fmax(res->worst_fault, f);
                        if (printed++ < 10)
                            printf("    fault: seed %llu event %ld slice t %.17g balls %zu %zu: "
                                   "depth %.3g (pieces %d, %d)\n", (unsigned long long)seed,
                                   e + 1, ta, i, j, f, np[i], np[j]);
                    }
                }
                ov[i * n + j] = (unsigned char)over;
            }
    }
    for (size_t i = 0; i < n; i++) {
        free(H[i].l);
        free(H[i].counted);
        free(H[i].cev);
    }
    free(H);
    free(G);
    free(L);
    free(R);
    free(P);
    free(np);
    free(ov);
    rc_sim_free(&s);
}

/* The faults the audit found were all of one class: a ball meets a neighbour while one of
 * its earlier glue windows is open -- collisions less than a glue window apart whose
 * centre kinks come in order (so the order rule lets them through) but whose hyperplanes
 * cross inside the ball, where the glued tube of the two is not defined. Before
 * collisions were undone (papers/covariant-frame.md section 2) each run had one:
 *  - seed 1, eps 1: event 2974, slice t = 44.889, balls 12 and 30, depth 4.8e-4: ball 12
 *    met balls 7 and 30 at one table time (44.972583, two events in a row, not one group),
 *    its two windows overlapping, and ball 30's window holding both;
 *  - seed 2, eps 0.5: event 381, slice t = 1.680, balls 1 and 3, depth 7.9e-4: ball 1 met
 *    ball 3 (contact 1.6448) with the window of its previous kink (1.479..1.605) and this
 *    one's (1.573..1.864) overlapping.
 * Undoing tube and centre-order conflicts alone left five in the first run (worst depth
 * 0.021, e.g. event 2445, balls 0 and 27: ball 0's kink at 32.576 and its next window
 * from 32.203). Undoing also where the new hyperplane would reach any point of the ball
 * before the last one (core.c kinks_cross) leaves none in either run. Asserted as it is:
 * a change of the engine that adds one shows up here. */
static void run(size_t n, double packing, double v_rms, double eps, long events, uint64_t seed,
                long known_faults)
{
    audit_out r;
    memset(why, 0, sizeof why);
    audit(n, packing, v_rms, eps, events, seed, &r);
    printf("  n %zu packing %.2f v_rms %.2f eps %.2f seed %llu: %ld events, %ld slices audited "
           "over t = %.1f, %ld pair checks, worst depth %.3g; new overlaps: %ld near counted "
           "events (%ld of the pair's own), %ld faults (worst %.3g); pairs with a section the "
           "model leaves undefined %ld\n",
           n, packing, v_rms, eps, (unsigned long long)seed, r.events, r.slices, r.span, r.pairs,
           r.worst, r.counted, r.counted_pair, r.faults, r.worst_fault, r.undefined);
    printf("    ball sections left undefined (ball-slices): order rule %ld, three windows %ld, "
           "tube not continuing its line %ld, hyperplanes sweeping out of order %ld\n",
           why[0], why[1], why[2], why[3] + why[4]);
    printf("    collisions undone by the engine (their lines dropped from the history): %ld\n",
           r.undone);
    printf("    read-out at the engine's time: %ld reads with a kink ahead (%ld with two), "
           "worst difference from the rebuilt worldline %.2g, %ld wrong\n", r.reads_ahead,
           r.reads_two_ahead, r.read_err, r.read_bad);
    printf("    delayed slices: %ld read final and %ld three delays later (%ld refused), %ld "
           "ball-states and %ld proper times against the rebuilt worldlines, worst %.2g, %ld "
           "wrong, %ld changed after read; the latest change came %.2f W after ts\n", r.slices_done,
           r.slices_done, r.slice_refused, r.slice_reads, r.slice_tau, r.slice_err, r.slice_bad,
           r.slice_late, r.slice_use);
    ENSURE(r.read_bad == 0 && r.reads_ahead > 0);
    ENSURE(r.slice_bad == 0 && r.slice_late == 0 && r.slices_done > 20 && r.slice_tau > 0);
    ENSURE(r.slice_use > 0.0 && r.slice_use < 1.0); /* (changes were followed, within W) */
    /* (a slice per event at most, fewer where the lag W grows with the fastest ball: the
     * audit must still have looked at most of the run, some 1400-2600 slices of 3000) */
    ENSURE(r.events == events && r.slices > events / 3);
    ENSURE_MSG(r.faults == known_faults, "%ld overlaps the engine did not count (worst depth "
               "%.3g), %ld known", r.faults, r.worst_fault, known_faults);
}

static void test_covariant_elastic(void) { run(40, 0.2, 0.6, 1.0, 3000, 1, 0); }
static void test_covariant_tc(void) { run(40, 0.2, 0.6, 0.5, 3000, 2, 0); }
/* A contact with a ball's incoming piece was judged approaching or not with the stored
 * (outgoing) lines; where those part, the pair got no event while the incoming piece went
 * on into its neighbour. At 519cbdc this run had one such overlap nothing counted (event
 * 2600, slice t = 44.52, balls 6 and 14, depth 0.0157: a contact of ball 14 with ball 6's
 * incoming piece at 44.494, predicted at 44.085, the outgoing lines parting there). The
 * pieces' own velocities judge it now (engine/predict.c pieces_approach). */
static void test_covariant_pieces(void) { run(60, 0.1, 0.6, 1.0, 4000, 3, 0); }

int main(void)
{
    RUN_TEST(test_covariant_elastic);
    RUN_TEST(test_covariant_tc);
    RUN_TEST(test_covariant_pieces);
    RC_TEST_MAIN_END();
}
