/* engine/shapes.h — the table frame's contracted shapes, cheaply: their supports (in a
 * form that keeps its precision as v -> c), the centre line's separating-axis bound of a
 * contact time, and the certificates that settle a pair whose bounding spheres overlap while its
 * centres part without asking the frame (apart for good, or overlapping). Every decision
 * keeps a margin far above the frame's touch_tol, so it agrees with the frame; when in
 * doubt the frame is asked. Included by engine/predict.c. */
#ifndef RELCOL_ENGINE_SHAPES_H
#define RELCOL_ENGINE_SHAPES_H

#include <math.h>

#include "pairs.h"
#include "private.h"
#include "../shape_math.h"
#include "../toi_private.h"

/* A ball's table-frame shape (relcol/toi.h's, r, g = 1/gamma, beta = v/c), from its
 * stored state: its supports are toi_private.h's, r sqrt(g^2 + |beta x n|^2), which keep
 * their precision as v -> c (r sqrt(1 - (v.n)^2/c^2) cancels: past gamma ~ 1e8 it is wrong
 * by more than the margins of the callers below; test_engine_shapes). */
static inline rc_toi_shape shape_of(const rc_sim *s, const eng_ball *b)
{
    const eng_aux *a = &s->a[b - s->b];
    return rc_toi_shape_Mc_(b->r, a->m, a->p, s->inv_c, eng_mass_rel(a->m, a->p, s->inv_c2));
}

/* Distance from a ball's centre to the edge of its table-frame shape (contracted by
 * 1/gamma along v) along the unit vector u: r / sqrt(1 + gamma^2 (u.v)^2 / c^2), and
 * gamma^2 (u.v)^2 = (u.p)^2 / m^2. */
static inline double table_radius_along(const rc_sim *s, const eng_ball *b, rc_vec3 u)
{
    const eng_aux *a = &s->a[b - s->b];
    const double up = rc_v3_dot(u, a->p);
    return b->r / sqrt(1.0 + up * up * s->inv_c2 / (a->m * a->m));
}

/* Margin (relative to the centres' distance) by which the shapes' extents along the
 * centre line must clear or cover it before parting_settled decides: far above the
 * frame's touch_tol (1e-12) and round-off, so that it agrees with the frame. */
#define LINE_MARGIN 1e-9

/* For the table frame, a pair whose bounding spheres overlap while the centres part
 * (dx.dv >= 0) is settled without asking the frame when, along the centre line u,
 *  - the shapes' projections are apart (d - h_i(u) - h_k(u) > margin, h the support
 *    r sqrt(1 - (u.v)^2/c^2)): separated along u and not closing, they never meet; or
 *  - their extents from the centres cover it (rho_i(u) + rho_k(u) > d (1 + margin)): the
 *    shapes overlap, and the overlap policy leaves a parting pair to separate.
 * 1 if settled (no event), 0 if the frame must look. Other frames: 0. *lam (if not
 * NULL, and 0 returned): h_i(u) / (h_i(u) + h_k(u)), the Perram-Wertheim lambda if the
 * shapes touched along u (parting_pw's start). */
static inline int parting_settled(const rc_sim *s, const rc_toi_shape *shi, const eng_ball *bi,
                                  const eng_ball *bk, rc_vec3 dx, double d2, double *lam)
{
    if (!s->table)
        return 0;
    if (!(d2 > 0.0))
        return 1; /* coincident centres: overlapping */
    /* the supports times d (no square root of d2 for the common case) */
    const rc_toi_shape shk = shape_of(s, bk);
    const double hi = rc_toi_support_scaled_(shi, dx, d2);
    const double hk = rc_toi_support_scaled_(&shk, dx, d2);
    const double h = hi + hk;
    /* d - h_i(u) - h_k(u) > margin d: apart along the centre line, and never meeting if
     * not closing along it (a pair that approaches too slowly to count as approaching
     * for the bounding spheres still closes here: left to the checks below) */
    if (d2 - h > LINE_MARGIN * d2 && rc_v3_dot(dx, rc_v3_sub(bk->v, bi->v)) >= 0.0)
        return 1;
    const double d = sqrt(d2);
    const rc_vec3 u = rc_v3_scale(1.0 / d, dx);
    if (table_radius_along(s, bi, u) + table_radius_along(s, bk, u) > d * (1.0 + LINE_MARGIN))
        return 1;
    if (lam)
        *lam = h > 0.0 ? hi / h : 0.5;
    return 0;
}

/* Margin (relative) by which parting_pw's certificates must clear the touching band: as
 * LINE_MARGIN, far above the frame's touch_tol (1e-12) and round-off. */
#define PW_MARGIN 1e-9
/* Closing speed added to the computed one (relative to |w|) before it bounds the time:
 * covers the round-off of w.n (a few ulp), so the bound stays a lower bound. */
#define PW_CLOSE_TOL 1e-12
/* lambda steps of parting_pw before it gives the pair to the frame. */
#define PW_STEPS 3

/* A table-frame shape for parting_pw: a = gamma beta = p / (m c) and w = 1/gamma^2 =
 * 1/(1 + a^2); its matrix P = r^2 (I - beta beta^T) = r^2 w ((1 + a^2) I - a a^T) (the
 * shape is { x : x^T P^-1 x <= 1 }, P^-1 = (I + a a^T)/r^2). */
typedef struct pw_shape {
    rc_vec3 a;
    double r, r2w;
} pw_shape;

static inline pw_shape pw_shape_of(const rc_sim *s, const eng_ball *b, double sc)
{
    const eng_aux *x = &s->a[b - s->b];
    pw_shape q;
    q.a = rc_v3_scale(sc / x->m, x->p);
    q.r = b->r;
    q.r2w = b->r * b->r / (1.0 + rc_v3_norm2(q.a));
    return q;
}

/* y^T P y = r^2 w (|y|^2 + |a x y|^2): squared support distance along y times |y|^2, as
 * a sum of non-negative terms (no cancellation for flat shapes) */
static inline double pw_quad_P(const pw_shape *q, rc_vec3 y)
{
    return q->r2w * rc_shape_form_(1.0, q->a, y, rc_v3_norm2(y));
}

/* x^T P^-1 x = (|x|^2 + (a.x)^2) / r^2: < 1 inside the shape */
static inline double pw_quad_Q(const pw_shape *q, rc_vec3 x)
{
    const double ax = rc_v3_dot(q->a, x);
    return (rc_v3_norm2(x) + ax * ax) / (q->r * q->r);
}

static inline rc_vec3 pw_mul_P(const pw_shape *q, rc_vec3 y)
{
    /* r^2 w ((1 + a^2) y - (a.y) a) */
    return rc_v3_scale(q->r2w, rc_shape_form_mul_(1.0, q->a, y));
}

/* A parting pair that the centre line left open (parting_settled), settled from the
 * Perram-Wertheim function the frame maximises, at a few lambda without a root find:
 * for C = (1 - lambda) P_i + lambda P_k and y = C^-1 dx (the normal of the contact the
 * shapes scaled about their centres would make at this lambda),
 *  - separated along y (dx.y - h_i(y) - h_k(y) > margin): the shapes are rigid and
 *    translate, so the gap along y closes at most at the speed -w.y: no contact before
 *    tref + gap / speed (never if the speed is <= 0); settled if that is >= best;
 *  - x = (1 - lambda) P_i y lies inside both shapes by a margin: they overlap now, and
 *    the overlap policy leaves a parting pair to separate (the frame says RC_EOVERLAP);
 *  - else lambda <- h_i(y) / (h_i(y) + h_k(y)), whose fixed point is the frame's lambda*
 *    (there both tests are decided unless the shapes touch within the margin).
 * Both certificates are checked directly on the computed y and x, so round-off in the
 * solve only makes them fail (then the frame decides): a settled pair is one the frame
 * gives no event before best. Nearly every pair the centre line leaves is settled in one
 * to three steps, so the frame's root find is left for the few that are neither apart nor
 * overlapping (the counts are in papers/relcol.md, section 7). */
enum { PW_OPEN = 0, PW_APART, PW_OVERLAP };

/* The steps above, for any pair whose bounding spheres overlap: PW_APART (separated
 * along y; *bound: no contact before it, INFINITY if the gap does not close), PW_OVERLAP
 * (overlapping now: the frame says RC_EOVERLAP) or PW_OPEN (undecided: the frame
 * decides). lam: the start, h_i / (h_i + h_k) along the centre line. */
static int pw_certify(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                      double d2, double tref, double lam, double *bound)
{
    const double sc = sqrt(s->inv_c2);
    const pw_shape q0 = pw_shape_of(s, bi, sc), q1 = pw_shape_of(s, bk, sc);
    const double d = sqrt(d2);
    const double inside = 1.0 - 2.0 * PW_MARGIN;
    const rc_sym3 P0 = rc_shape_matrix_(q0.r2w, 1.0, q0.a);
    const rc_sym3 P1 = rc_shape_matrix_(q1.r2w, 1.0, q1.a);
    for (int it = 0; it < PW_STEPS; it++) {
        const double l1 = 1.0 - lam;
        const rc_sym3 C = rc_sym3_blend_(&P0, &P1, lam, 0);
        rc_sym3 A;
        const double det = rc_sym3_adj_(&C, &A, 0);
        if (!(det > 0.0))
            return PW_OPEN;
        /* y = adj(C) dx = det C^-1 dx (the scale cancels in the tests below) */
        const rc_vec3 y = rc_sym3_mul_(&A, dx, 0);
        const double ny = rc_v3_norm(y);
        const double h0 = sqrt(pw_quad_P(&q0, y)), h1 = sqrt(pw_quad_P(&q1, y));
        const double gap = rc_v3_dot(dx, y) - h0 - h1; /* times |y| */
        if (!(ny > 0.0) || !isfinite(gap))
            return PW_OPEN;
        if (gap > PW_MARGIN * d * ny) {
            const rc_vec3 w = rc_v3_sub(bk->v, bi->v);
            const double close = -rc_v3_dot(w, y) / ny + PW_CLOSE_TOL * rc_v3_norm(w);
            /* separated along y and not closing: never */
            *bound = close > 0.0 ? tref + (gap / ny - PW_MARGIN * d) / close : INFINITY;
            return PW_APART;
        }
        const rc_vec3 x = rc_v3_scale(l1 / det, pw_mul_P(&q0, y));
        if (pw_quad_Q(&q0, x) < inside && pw_quad_Q(&q1, rc_v3_sub(x, dx)) < inside)
            return PW_OVERLAP; /* overlapping now */
        lam = h0 / (h0 + h1);
    }
    return PW_OPEN;
}

static int parting_pw(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                      double d2, double tref, double best, double lam)
{
    double bound = INFINITY;
    const int r = pw_certify(s, bi, bk, dx, d2, tref, lam, &bound);
    return r == PW_OVERLAP || (r == PW_APART && bound >= best);
}

/* 1 if the frame must look at a pair whose bounding spheres overlap while not bound to
 * touch before best (parting_settled, then parting_pw for the table frame), 0 if it
 * would give no event before best. */
static inline int parting_open(const rc_sim *s, const rc_toi_shape *shi, const eng_ball *bi,
                               const eng_ball *bk, rc_vec3 dx, double d2, double tref,
                               double best)
{
    double lam = 0.5;
    if (parting_settled(s, shi, bi, bk, dx, d2, &lam))
        return 0;
    if (s->table && parting_pw(s, bi, bk, dx, d2, tref, best, lam))
        return 0;
    return 1;
}

/* parting_open for a neighbour without a bounding-sphere time (scan_block_narrow; out of
 * line, as the loop rarely needs it) */
__attribute__((noinline, unused)) static int parting_candidate(const rc_sim *s,
                                                               const rc_toi_shape *shi,
                                                               const eng_ball *bi,
                                                               const eng_ball *bk, double best)
{
    double tref;
    const rc_vec3 dx = pair_sep(s, bi, bk, &tref);
    const double d2 = rc_v3_norm2(dx), sig = bi->r + bk->r;
    return d2 <= sig * sig && parting_open(s, shi, bi, bk, dx, d2, tref, best);
}

/* The separating axis along the centre line for the table frame's shapes: separated along
 * the fixed axis u = dx / |dx| by a gap g closing at speed w (the shapes keep their form
 * between collisions), they cannot touch before g / w (never, if w <= 0). As an absolute
 * time (-INFINITY: the axis does not separate them, INFINITY: never) -- a lower bound of
 * the contact time, often well above the bounding spheres', by which the candidates are
 * ordered, pruned and deferred. The margin AXIS_MARGIN (relative to ri + rk, far above
 * the frame's touch_tol of 1e-12 and round-off) keeps every pair the frame could still
 * call touching. The balls' directions of motion were axes too (the latest of the three
 * bounds): with the frame's root finds deferred they cost more than they spared, so the
 * centre line is the only axis (the same bits in the reference runs). */
#define AXIS_MARGIN 1e-9

static inline double line_bound(const rc_sim *s, const rc_toi_shape *shi, const eng_ball *bi,
                                const eng_ball *bk)
{
    double tref;
    const rc_vec3 dx = pair_sep(s, bi, bk, &tref);
    const double d2 = rc_v3_norm2(dx);
    if (!(d2 > 0.0))
        return -INFINITY;
    const rc_vec3 u = rc_v3_scale(1.0 / sqrt(d2), dx);
    const rc_toi_shape hk = shape_of(s, bk);
    const double h = rc_toi_support_(shi, u) + rc_toi_support_(&hk, u);
    double gap = fabs(rc_v3_dot(dx, u)) - h;
    gap -= AXIS_MARGIN * (bi->r + bk->r);
    if (!(gap > 0.0))
        return -INFINITY;
    const double close = -rc_v3_dot(rc_v3_sub(bk->v, bi->v), u);
    if (!(close > 0.0))
        return INFINITY; /* separated along u and not closing: never */
    return tref + gap / close;
}

#endif
