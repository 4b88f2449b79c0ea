/* toi_glue_pair.c — the first contact of two glued world tubes, both balls inside their
 * glue windows (papers/shape-change.md section 10). Each tube is the union of two convex
 * pieces of spacetime: its incoming cylinder on the side of its hyperplane H that H has
 * not reached (ell >= 0 below) and its outgoing cylinder on the other (ell <= 0). So the
 * two tubes meet in the union of four convex sets Q_ab = C_1a n C_2b n S_1a n S_2b (two
 * cylinders, two half-spaces), and the first contact is the least table time over them.
 *
 * Over one Q_ab the least time is a convex program, solved by its active sets: the
 * optimum is the optimum of the problem with its active half-spaces made equalities and
 * the others dropped, and every optimum of such a restricted problem that satisfies the
 * dropped ones is a point of Q_ab. So the least time is the least of the feasible
 * answers of four restricted problems (asked in the order extreme() gives, which convexity
 * lets stop at the first feasible one):
 *   none active:  the first contact of the two straight cylinders (rc_toi_shapes_rel);
 *   on H_1:       the least time over both cylinders' sections by H_1, two ellipsoids
 *                 (rc_glue_lin_min2_slope_; rc_glue_toi asks the same on H), checked
 *                 against S_2b;
 *   on H_2:       the same by H_2, checked against S_1a;
 *   on both:      the same on the plane where H_1 meets H_2, both ellipsoids restricted
 *                 to it (plane_min2).
 * On H_1 a point is in both of ball 1's cylinders (their sections there coincide), so
 * that answer is a's whichever a is. The latest time over Q_ab is the same program with
 * time reversed; it tells a Q_ab that began before t_from (an overlap now, if it lasts
 * past t_from) from one wholly past. The pairs are taken in the order of their straight
 * cylinders' first contacts, lower bounds of theirs: once that bound is no earlier than
 * the best contact found, no later pair can improve on it or overlap. */
#include <math.h>
#include <string.h>

#include "relcol/kinematics.h"
#include "relcol/status.h"
#include "relcol/toi.h"
#include "glue_section.h"
#include "toi_private.h"

/* A piece: its straight cylinder (shape, velocity; its centre line passes the tube's
 * kink (t_c, x_c)) and its side of H, sg * ell >= 0 (+1 incoming, -1 outgoing). */
typedef struct piece {
    const rc_glue *g;
    const rc_toi_shape *sh;
    rc_vec3 v;
    double sg;
    int id; /* 0 incoming, 1 outgoing */
} piece;

static piece piece_of(const rc_glue *g, int a)
{
    const piece p = {g, a ? &g->out : &g->in, a ? g->v_out : g->v_in, a ? -1.0 : 1.0, a};
    return p;
}

static rc_vec3 centre_at(const piece *p, double t)
{
    return rc_v3_axpy(p->g->x_c, t - p->g->t_c, p->v);
}

/* > 0 on the side of g's H it has not reached yet (rc_glue_inside's test) */
static double ell(const rc_glue *g, rc_vec3 y, double t)
{
    return rc_v3_dot(g->kappa, rc_v3_sub(y, g->x)) - (t - g->t_x);
}

/* An answer of a restricted problem: the event (T, Y), the normal from ball 1 to ball 2,
 * and where it lies on each tube (0 incoming, 1 outgoing, 2 on its H). */
typedef struct cand {
    double T;
    rc_vec3 Y, n;
    int p1, p2;
} cand;

/* None active: the extreme time (s = +1 first, -1 last) of contact of the straight
 * cylinders of pa and pb, asked from a reference where they are apart (4 (r1 + r2) on
 * the table's slice, beyond every overlap of two straight cylinders). 1 found; RC_MISS
 * the cylinders never meet (so neither do the pieces); 0 parallel cylinders that
 * overlap at all times (no extreme: the half-spaces bound the pieces). */
static int straight(const piece *pa, const piece *pb, double s, double tr,
                    const rc_toi_params *prm, rc_toi_workspace *ws, cand *c)
{
    const rc_vec3 w = rc_v3_scale(s, rc_v3_sub(pb->v, pa->v));
    const rc_vec3 d = rc_v3_sub(centre_at(pb, tr), centre_at(pa, tr));
    const double wn = rc_v3_norm(w);
    double tau;
    rc_vec3 y0, n;
    if (!(wn > 0.0)) {
        const int st = rc_toi_shapes_rel(pa->sh, pb->sh, d, w, prm, ws, &tau, NULL, &n);
        return st == RC_EOVERLAP || st == RC_OK ? 0 : st;
    }
    const double back = (rc_v3_norm(d) + 4.0 * (pa->sh->r + pb->sh->r)) / wn;
    const int st = rc_toi_shapes_rel(pa->sh, pb->sh, rc_v3_axpy(d, -back, w), w, prm, ws, &tau,
                                     &y0, &n);
    if (st != RC_OK)
        return st == RC_EOVERLAP ? RC_EINVAL : st; /* (apart there by construction) */
    c->T = s > 0.0 ? (tr - back) + tau : (tr + back) - tau;
    c->Y = rc_v3_add(centre_at(pa, c->T), y0);
    c->n = n;
    c->p1 = pa->id;
    c->p2 = pb->id;
    return 1;
}

/* The least k.z over two ellipsoids (z - m_i)^T A_i (z - m_i) <= 1 restricted to the
 * plane q.z = h: each restricted to the plane's coordinates (s1, s2) (z = p0 + s1 e1 +
 * s2 e2, p0 = h q / |q|^2) is an ellipse (s - c)^T B (s - c) <= 1 - e, given to
 * rc_glue_lin_min2_slope_ as the cylinder over it in (s1, s2, s3) (the third axis free: k
 * has no component along it, and a point of both cylinders at s3 is one at s3 = 0).
 * INFINITY if the restricted sets are empty, NAN if the problem is degenerate. */
static double plane_min2(const rc_sym3 *A1, rc_vec3 m1, const rc_sym3 *A2, rc_vec3 m2,
                         rc_vec3 k, rc_vec3 q, double h, rc_vec3 *z)
{
    const double q2 = rc_v3_norm2(q);
    if (!(q2 > 0.0))
        return INFINITY; /* parallel hyperplanes: their meeting is empty or all of H, whose
                            own answers stand */
    const rc_vec3 e3 = rc_v3_scale(1.0 / sqrt(q2), q);
    /* e1 across e3 from the axis e3 leans on least */
    const double ax = fabs(e3.x), ay = fabs(e3.y), az = fabs(e3.z);
    const rc_vec3 ax_least = ax <= ay && ax <= az ? rc_v3(1, 0, 0)
                             : ay <= az          ? rc_v3(0, 1, 0)
                                                 : rc_v3(0, 0, 1);
    rc_vec3 e1 = rc_v3_cross(e3, ax_least);
    e1 = rc_v3_scale(1.0 / rc_v3_norm(e1), e1);
    const rc_vec3 e2 = rc_v3_cross(e3, e1);
    const rc_vec3 p0 = rc_v3_scale(h / q2, q);
    const rc_sym3 *A[2] = {A1, A2};
    const rc_vec3 m[2] = {m1, m2};
    rc_sym3 R[2];
    rc_vec3 c[2];
    for (int i = 0; i < 2; i++) {
        const rc_vec3 a1 = rc_sym3_mul_(A[i], e1, 0), a2 = rc_sym3_mul_(A[i], e2, 0);
        const rc_vec3 dp = rc_v3_sub(p0, m[i]);
        const double b11 = rc_v3_dot(e1, a1), b12 = rc_v3_dot(e2, a1), b22 = rc_v3_dot(e2, a2);
        const double g1 = rc_v3_dot(a1, dp), g2 = rc_v3_dot(a2, dp);
        const double det = b11 * b22 - b12 * b12;
        if (!(det > 0.0))
            return NAN;
        /* the ellipse's centre c = -B^-1 g, and its form at c: f0 - g^T B^-1 g */
        const double c1 = -(b22 * g1 - b12 * g2) / det, c2 = -(b11 * g2 - b12 * g1) / det;
        const double e = rc_v3_dot(dp, rc_sym3_mul_(A[i], dp, 0)) + g1 * c1 + g2 * c2;
        if (!(e < 1.0))
            return INFINITY;
        const double f = 1.0 / (1.0 - e);
        const rc_sym3 Ri = {f * b11, f * b22, 1.0, f * b12, 0.0, 0.0};
        R[i] = Ri;
        c[i] = rc_v3(c1, c2, 0.0);
    }
    rc_vec3 sz;
    const rc_vec3 kp = rc_v3(rc_v3_dot(k, e1), rc_v3_dot(k, e2), 0.0);
    const double lo = rc_glue_lin_min2_slope_(&R[0], c[0], &R[1], c[1], kp, &sz);
    if (!isfinite(lo))
        return lo;
    *z = rc_v3_axpy(rc_v3_axpy(p0, sz.x, e1), sz.y, e2);
    return rc_v3_dot(k, p0) + lo;
}

/* On gh's H (and on go's too when both): the extreme time s T over gh's section and the
 * section of po's straight cylinder (po a piece of go), as rc_glue_toi finds it on H (in
 * H's turned frame when H is fast). 1 found, 0 empty, RC_EINVAL degenerate. */
static int on_h(const rc_glue *gh, const piece *po, double s, int both, cand *c)
{
    rc_sym3 Aa, Ak;
    rc_vec3 ma, mk, z, kh = gh->kappa;
    rc_glue_frame fr = {0};
    const int fast = rc_glue_frame_make(gh, &fr);
    if (fast) {
        rc_glue_section_fast(gh, &fr, &gh->in, gh->v_in, gh->x_c, gh->t_c, &Aa, &ma);
        rc_glue_section_fast(gh, &fr, po->sh, po->v, po->g->x_c, po->g->t_c, &Ak, &mk);
        kh = rc_v3(fr.kq, 0.0, 0.0);
    } else {
        rc_glue_section_plain(gh, &gh->in, gh->v_in, gh->x_c, gh->t_c, &Aa, &ma);
        rc_glue_section_plain(gh, po->sh, po->v, po->g->x_c, po->g->t_c, &Ak, &mk);
    }
    kh = rc_v3_scale(s, kh);
    double lo;
    if (both) {
        /* go's H in z = y - X_h on gh's H: (kappa_h - kappa_o).z = t_xo - t_xh +
         * kappa_o.(X_h - X_o) */
        const rc_glue *go = po->g;
        const rc_vec3 q = rc_v3_sub(gh->kappa, go->kappa);
        const double h = (go->t_x - gh->t_x) + rc_v3_dot(go->kappa, rc_v3_sub(gh->x, go->x));
        lo = plane_min2(&Aa, ma, &Ak, mk, kh, fast ? rc_glue_turn(&fr, q) : q, h, &z);
    } else if (rc_v3_norm2(kh) > 0.0) {
        lo = rc_glue_lin_min2_slope_(&Aa, ma, &Ak, mk, kh, &z);
    } else {
        /* (classical: H is the slice t = t_x, every point of it at one time; the dual
         * search, blind with k = 0, is given the centres' line to find the sections apart
         * where they are) */
        lo = rc_glue_lin_min2_slope_(&Aa, ma, &Ak, mk, rc_v3_sub(mk, ma), &z);
        lo = isfinite(lo) ? 0.0 : lo;
    }
    if (isnan(lo))
        return RC_EINVAL;
    if (lo == INFINITY)
        return 0;
    if (fast)
        z = rc_glue_turn_back(&fr, z);
    c->T = gh->t_x + s * lo;
    c->Y = rc_v3_add(gh->x, z);
    return 1;
}

/* The unit normal at Y (time T) of the piece p's shape, outward from its ball (the
 * gradient of its rest-frame form) */
static rc_vec3 piece_normal(const piece *p, double T, rc_vec3 Y)
{
    const rc_sym3 G = rc_glue_shape_metric(p->sh);
    const rc_vec3 gr = rc_sym3_mul_(&G, rc_v3_sub(Y, centre_at(p, T)), 0);
    return rc_v3_scale(1.0 / rc_v3_norm(gr), gr);
}

/* Keep c in *best if it is better in the direction s. */
static void keep(double s, const cand *c, cand *best, int *have)
{
    if (!*have || s * c->T < s * best->T) {
        *best = *c;
        *have = 1;
    }
}

/* The answers on the hyperplanes, shared by the pairs: on H_1 with ball 2's piece b, on
 * H_2 with ball 1's piece a, on both (one answer: there each ball's two cylinders have one
 * section), per direction s; asked once each. */
typedef struct h_memo {
    int st[2][5]; /* 0 not asked; else on_h's status + 1 */
    cand c[2][5]; /* [s < 0][H_1 b = 0, 1; H_2 a = 0, 1; both] */
} h_memo;

static int on_h_memo(h_memo *m, int slot, const rc_glue *gh, const piece *po, double s, int both,
                     cand *c)
{
    const int k = s < 0.0;
    if (!m->st[k][slot])
        m->st[k][slot] = on_h(gh, po, s, both, &m->c[k][slot]) + 1;
    *c = m->c[k][slot];
    return m->st[k][slot] - 1;
}

/* The extreme time s T over Q_ab (pa of tube 1, pb of tube 2), given the straight
 * cylinders' (st0, c0: straight's answer in the direction s), where it could beat bound
 * (s T < s bound; the caller has no use for it otherwise): 1 (*out), 0 empty or not
 * better, a negative code. An unbounded Q_ab (parallel cylinders overlapping always, both
 * pieces open in the direction s: incoming pieces reach back in time for ever, outgoing
 * ones forward) has T = -s INFINITY.
 *
 * Q_ab lies in C = C_1a n C_2b, so C's extreme x0 bounds Q_ab's: where x0 cannot beat
 * bound, nothing more is asked. Else the active sets, in the order convexity allows (a
 * linear objective over a convex set, x0 its unique extreme on C):
 *  - x0 in both half-spaces is Q_ab's extreme;
 *  - x0 outside S_1a: the extreme of C n S_1a lies on H_1 (off it, it would be a local and
 *    so the global extreme of C, x0), so it is the answer on H_1; where that lies in
 *    S_2b it is Q_ab's (the extreme of a superset, and in Q_ab). And Q_ab's extreme has
 *    S_1a active (else it would be the extreme of C n S_2b, which is x0 where x0 is in
 *    S_2b): so with x0 in S_2b the answer on H_2 alone is not asked;
 *  - the same with 1 and 2 swapped;
 *  - neither answer in the other half-space: Q_ab's extreme has both active (with S_2b
 *    inactive it would be the extreme of C n S_1a, the answer on H_1, which is not in
 *    S_2b): on the plane where H_1 meets H_2.
 * With no x0 (parallel cylinders, C unbounded in time) these shortcuts do not hold: every
 * answer is asked, and the least feasible one taken. */
static int extreme(const piece *pa, const piece *pb, double s, int st0, const cand *c0,
                   double bound, h_memo *m, cand *out)
{
    const rc_glue *g1 = pa->g, *g2 = pb->g;
    cand c = {0}, best = {0};
    int st, have = 0;
    if (st0 == 0 && pa->sg * s > 0.0 && pb->sg * s > 0.0) {
        out->T = -s * INFINITY;
        out->Y = out->n = rc_v3(0.0, 0.0, 0.0);
        out->p1 = pa->id;
        out->p2 = pb->id;
        return 1;
    }
    /* in S_1a, in S_2b (both 0 with no x0) */
    int in1 = 0, in2 = 0;
    if (st0 == 1) {
        if (!(s * c0->T < s * bound))
            return 0;
        in1 = pa->sg * ell(g1, c0->Y, c0->T) >= 0.0;
        in2 = pb->sg * ell(g2, c0->Y, c0->T) >= 0.0;
        if (in1 && in2) {
            *out = *c0;
            return 1;
        }
    }
    /* on H_1 (ball 1's crease): ball 2's normal there */
    if (!in1) {
        if ((st = on_h_memo(m, pb->id, g1, pb, s, 0, &c)) < 0)
            return st;
        if (st == 1 && pb->sg * ell(g2, c.Y, c.T) >= 0.0) {
            c.n = rc_v3_scale(-1.0, piece_normal(pb, c.T, c.Y));
            c.p1 = 2;
            c.p2 = pb->id;
            if (st0 == 1) {
                *out = c;
                return 1;
            }
            keep(s, &c, &best, &have);
        }
    }
    /* on H_2: ball 1's normal */
    if (!in2) {
        if ((st = on_h_memo(m, 2 + pa->id, g2, pa, s, 0, &c)) < 0)
            return st;
        if (st == 1 && pa->sg * ell(g1, c.Y, c.T) >= 0.0) {
            c.n = piece_normal(pa, c.T, c.Y);
            c.p1 = pa->id;
            c.p2 = 2;
            if (st0 == 1) {
                *out = c;
                return 1;
            }
            keep(s, &c, &best, &have);
        }
    }
    /* on both creases: the two balls' outgoing normals averaged (a choice: neither
     * surface is smooth there) */
    const piece o1 = piece_of(g1, 1), o2 = piece_of(g2, 1);
    if ((st = on_h_memo(m, 4, g1, &o2, s, 1, &c)) < 0)
        return st;
    if (st == 1) {
        const rc_vec3 nn = rc_v3_sub(piece_normal(&o1, c.T, c.Y), piece_normal(&o2, c.T, c.Y));
        const double nl = rc_v3_norm(nn);
        c.n = nl > 0.0 ? rc_v3_scale(1.0 / nl, nn) : rc_v3_scale(-1.0, piece_normal(&o2, c.T, c.Y));
        c.p1 = c.p2 = 2;
        keep(s, &c, &best, &have);
    }
    if (have)
        *out = best;
    return have;
}

int rc_glue_toi2(const rc_glue *g1, const rc_glue *g2, const rc_toi_params *prm,
                 rc_toi_workspace *ws, double t_from, double *t, rc_vec3 *y, rc_vec3 *n,
                 int *piece1, int *piece2)
{
    if (!g1 || !g2 || !prm || !ws || !t || !y || !n || !piece1 || !piece2 ||
        !isfinite(t_from) || !(g1->inv_c2 == g2->inv_c2))
        return RC_EINVAL;
    if (!(g1->r > 0.0) || !(g2->r > 0.0))
        return RC_ERADIUS;
    cand best = {0};
    int have = 0;
    h_memo memo;
    memset(&memo.st, 0, sizeof memo.st);
    /* the straight cylinders' first contacts, the pairs taken in their order: a pair
     * whose straight contact is no earlier than the best so far (itself no earlier than
     * t_from, less the tolerance) can neither improve on it nor overlap */
    cand c0[4];
    int st0[4], ord[4], no = 0;
    for (int i = 0; i < 4; i++) {
        const piece pa = piece_of(g1, i >> 1), pb = piece_of(g2, i & 1);
        st0[i] = straight(&pa, &pb, 1.0, t_from, prm, ws, &c0[i]);
        if (st0[i] == RC_MISS)
            continue;
        if (st0[i] < 0)
            return st0[i];
        /* (insertion by the straight time; parallel cylinders, no time, first) */
        const double ti = st0[i] == 1 ? c0[i].T : -INFINITY;
        int j = no++;
        for (; j > 0 && (st0[ord[j - 1]] == 1 ? c0[ord[j - 1]].T : -INFINITY) > ti; j--)
            ord[j] = ord[j - 1];
        ord[j] = i;
    }
    for (int q = 0; q < no; q++) {
        const int i = ord[q];
        const piece pa = piece_of(g1, i >> 1), pb = piece_of(g2, i & 1);
        cand lo, hi;
        int st = extreme(&pa, &pb, 1.0, st0[i], &c0[i], have ? best.T : INFINITY, &memo, &lo);
        if (st < 0)
            return st;
        if (st == 0)
            continue;
        /* touching within the frames' tolerance (touch_tol of the radii, crossed at
         * the pieces' relative speed) is not an overlap: a contact at t_from */
        const double wn = rc_v3_norm(rc_v3_sub(pb.v, pa.v));
        const double ttol = wn > 0.0 ? prm->touch_tol * (g1->r + g2->r) / wn : 0.0;
        if (lo.T >= t_from - ttol) {
            keep(1.0, &lo, &best, &have);
            continue;
        }
        cand ch;
        const int sh = straight(&pa, &pb, -1.0, t_from, prm, ws, &ch);
        if (sh == RC_MISS)
            continue;
        if (sh < 0)
            return sh;
        if ((st = extreme(&pa, &pb, -1.0, sh, &ch, t_from + ttol, &memo, &hi)) < 0)
            return st;
        if (st == 1 && hi.T > t_from + ttol)
            return RC_EOVERLAP; /* Q_ab spans t_from */
    }
    if (!have)
        return RC_MISS;
    *t = best.T;
    *y = best.Y;
    *n = best.n;
    *piece1 = best.p1;
    *piece2 = best.p2;
    return RC_OK;
}
