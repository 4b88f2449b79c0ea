/* toi_glue.c — a ball's world tube through one collision: the incoming and outgoing world
 * cylinders glued on the hyperplane H through the contact event with normal u_in + u_out,
 * where their sections coincide, so the tube is continuous and the table-frame shape
 * changes while H sweeps the ball (papers/shape-change.md). */
#include <float.h>
#include <math.h>

#include "relcol/kinematics.h"
#include "relcol/status.h"
#include "relcol/toi.h"
#include "glue_kv.h"
#include "glue_section.h"
#include "toi_private.h"

int rc_glue_make(double inv_c2, double r, const rc_particle *in, const rc_particle *out,
                 double t_x, rc_vec3 xc, rc_vec3 X, rc_glue *g)
{
    if (!in || !out || !g || !(inv_c2 >= 0.0) || isinf(inv_c2) || !isfinite(t_x) ||
        !rc_v3_isfinite(xc) || !rc_v3_isfinite(X))
        return RC_EINVAL;
    if (!(r > 0.0) || !isfinite(r))
        return RC_ERADIUS;
    int st;
    if ((st = rc_particle_check(in)) != RC_OK || (st = rc_particle_check(out)) != RC_OK)
        return st;
    const double M0 = rc_mass_rel(in->m, in->p, inv_c2), M1 = rc_mass_rel(out->m, out->p, inv_c2);
    g->inv_c2 = inv_c2;
    g->r = r;
    g->in = rc_toi_shape_M_(r, in->m, in->p, inv_c2, M0);
    g->out = rc_toi_shape_M_(r, out->m, out->p, inv_c2, M1);
    g->v_in = rc_v3_scale(1.0 / M0, in->p);
    g->v_out = rc_v3_scale(1.0 / M1, out->p);
    g->t_x = t_x;
    g->x = X;
    /* w = u_in + u_out = (c (g0 + g1), g0 v0 + g1 v1) with g v = p / m, g = M / m; the
     * plane w.(Y - X) = 0 in the table frame: t - t_x = (g0 v0 + g1 v1).(y - X) / (c^2
     * (g0 + g1)) */
    const double W0 = M0 / in->m + M1 / out->m;
    const rc_vec3 Wv = rc_v3_add(rc_v3_scale(1.0 / in->m, in->p), rc_v3_scale(1.0 / out->m, out->p));
    g->kappa = rc_v3_scale(inv_c2 / W0, Wv);
    /* the centre's event on H: (t_c - t_x)(1 - kappa.v_in) = kappa.(xc - X) */
    /* (1 - kappa.v_in without the cancellation of a ball fast before and after: glue_kv.h) */
    const double omkv = rc_glue_one_minus_kv(inv_c2, in, M0, out, M1, W0,
                                             rc_v3_dot(g->kappa, g->v_in));
    const double dt = rc_v3_dot(g->kappa, rc_v3_sub(xc, X)) / omkv;
    g->t_c = t_x + dt;
    g->x_c = rc_v3_axpy(xc, dt, g->v_in);
    /* H meets the incoming section first and last where it is tangent to it:
     * t - t_c = -+ h_in(kappa) / (1 - kappa.v_in), h the support times |kappa| (the same
     * from the outgoing side: the sections on H coincide; papers/shape-change.md) */
    const double k2 = rc_v3_norm2(g->kappa);
    const double h = k2 > 0.0 ? rc_toi_support_scaled_(&g->in, g->kappa, k2) : 0.0;
    const double D = h / omkv;
    g->t_first = g->t_c - D;
    g->t_last = g->t_c + D;
    return RC_OK;
}

rc_vec3 rc_glue_centre(const rc_glue *g, double t)
{
    return rc_v3_axpy(g->x_c, t - g->t_c, t < g->t_c ? g->v_in : g->v_out);
}

/* Inside the shape s centred at the origin: the rest-frame length of d, |d|^2 +
 * gamma^2 (beta.d)^2, at most r^2. */
static int inside_shape(const rc_toi_shape *s, rc_vec3 d)
{
    const double bd = rc_v3_dot(s->beta, d);
    return rc_v3_norm2(d) + bd * bd / s->g2 <= s->r * s->r;
}

int rc_glue_inside(const rc_glue *g, double t, rc_vec3 y)
{
    /* reached by H (its future side) once t - t_x > kappa.(y - X) */
    const int after = t - g->t_x > rc_v3_dot(g->kappa, rc_v3_sub(y, g->x));
    if (after)
        return inside_shape(&g->out, rc_v3_sub(y, rc_v3_axpy(g->x_c, t - g->t_c, g->v_out)));
    return inside_shape(&g->in, rc_v3_sub(y, rc_v3_axpy(g->x_c, t - g->t_c, g->v_in)));
}

/* ---- first contact with the glued tube ------------------------------------------- */

/* The dual value at lam of min k.z over {(z - m1)^T A1 (z - m1) <= 1} and the same for
 * 2: the minimum of k.z over the blended ellipsoid (1 - lam) q1 + lam q2 <= 1, a lower
 * bound of the minimum over the intersection, INFINITY if the blend is empty (then so is
 * the intersection). *z its minimiser. */
static double dual_at(const rc_sym3 *A1, rc_vec3 b1, double c1, const rc_sym3 *A2, rc_vec3 b2,
                      double c2, rc_vec3 k, double lam, rc_vec3 *z)
{
    const rc_sym3 A = rc_sym3_blend_(A1, A2, lam, 0);
    rc_sym3 adj;
    const double det = rc_sym3_adj_(&A, &adj, 0);
    if (!(det > 0.0))
        return NAN;
    const rc_vec3 b = rc_v3_add(rc_v3_scale(1.0 - lam, b1), rc_v3_scale(lam, b2));
    const rc_vec3 m = rc_v3_scale(1.0 / det, rc_sym3_mul_(&adj, b, 0));
    const double e = (1.0 - lam) * c1 + lam * c2 - rc_v3_dot(b, m);
    if (e > 1.0)
        return INFINITY;
    const rc_vec3 aik = rc_v3_scale(1.0 / det, rc_sym3_mul_(&adj, k, 0)); /* A^-1 k */
    const double s = rc_v3_dot(k, aik);
    const double f = s > 0.0 ? sqrt((1.0 - e) / s) : 0.0;
    *z = rc_v3_axpy(m, -f, aik);
    return rc_v3_dot(k, m) - f * s;
}

/* Golden-section steps on lam in [0, 1]: the dual value is quasi-concave in lam (the
 * best scale of a concave dual along each direction), so it is unimodal; 90 steps narrow
 * the bracket below the round-off of lam. */
#define DUAL_STEPS 90

/* min k.z over the intersection of two ellipsoids {(z - m_i)^T A_i (z - m_i) <= 1}:
 * strong duality of the convex problem makes it the largest dual value. INFINITY if
 * the intersection is empty; *z the minimiser. (Also toi_glue_pair.c's, glue_section.h.) */
double rc_glue_lin_min2_(const rc_sym3 *A1, rc_vec3 m1, const rc_sym3 *A2, rc_vec3 m2, rc_vec3 k,
                       rc_vec3 *z)
{
    const rc_vec3 b1 = rc_sym3_mul_(A1, m1, 0), b2 = rc_sym3_mul_(A2, m2, 0);
    const double c1 = rc_v3_dot(m1, b1), c2 = rc_v3_dot(m2, b2);
    const double gr = 0.5 * (sqrt(5.0) - 1.0);
    double lo = 0.0, hi = 1.0;
    double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo);
    rc_vec3 z1, z2, zb = m1;
    double f1 = dual_at(A1, b1, c1, A2, b2, c2, k, x1, &z1);
    double f2 = dual_at(A1, b1, c1, A2, b2, c2, k, x2, &z2);
    for (int it = 0; it < DUAL_STEPS; it++) {
        if (f1 == INFINITY || f2 == INFINITY)
            return INFINITY;
        if (isnan(f1) || isnan(f2))
            return NAN;
        if (f1 < f2) {
            lo = x1;
            x1 = x2;
            f1 = f2;
            z1 = z2;
            x2 = lo + gr * (hi - lo);
            f2 = dual_at(A1, b1, c1, A2, b2, c2, k, x2, &z2);
        } else {
            hi = x2;
            x2 = x1;
            f2 = f1;
            z2 = z1;
            x1 = hi - gr * (hi - lo);
            f1 = dual_at(A1, b1, c1, A2, b2, c2, k, x1, &z1);
        }
    }
    /* the ends: one ellipsoid's own minimiser may lie inside the other */
    double best = f1 > f2 ? f1 : f2;
    zb = f1 > f2 ? z1 : z2;
    rc_vec3 ze;
    for (int e = 0; e < 2; e++) {
        const double fe = dual_at(A1, b1, c1, A2, b2, c2, k, (double)e, &ze);
        if (fe == INFINITY)
            return INFINITY;
        if (fe > best) {
            best = fe;
            zb = ze;
        }
    }
    *z = zb;
    return best;
}

/* ---- deciding rc_glue_lin_min2_'s comparison without converging it --------------- */

/* The two ellipsoids of rc_glue_lin_min2_, with the terms dual_at wants. */
typedef struct dual_pb {
    const rc_sym3 *A1, *A2;
    rc_vec3 m1, m2, b1, b2, k;
    double c1, c2;
} dual_pb;

static dual_pb dual_pb_make(const rc_sym3 *A1, rc_vec3 m1, const rc_sym3 *A2, rc_vec3 m2,
                            rc_vec3 k)
{
    dual_pb p = {A1, A2, m1, m2, rc_sym3_mul_(A1, m1, 0), rc_sym3_mul_(A2, m2, 0), k, 0.0, 0.0};
    p.c1 = rc_v3_dot(m1, p.b1);
    p.c2 = rc_v3_dot(m2, p.b2);
    return p;
}

static double pb_dual(const dual_pb *p, double lam, rc_vec3 *z)
{
    return dual_at(p->A1, p->b1, p->c1, p->A2, p->b2, p->c2, p->k, lam, z);
}

/* (z - m)^T A (z - m): at most 1 inside the ellipsoid */
static double form_at(const rc_sym3 *A, rc_vec3 m, rc_vec3 z)
{
    const rc_vec3 d = rc_v3_sub(z, m);
    return rc_v3_dot(d, rc_sym3_mul_(A, d, 0));
}

/* Bisection steps on lam for inner_point's minimax search: each halves the distance to the
 * deepest point's lam; a point inside both is usually found in a few. */
#define INNER_STEPS 12

/* A point strictly inside both ellipsoids: the middle of the part of the centres'
 * segment inside both (the forms there are s^2 a1 and (1 - s)^2 a2), or else the centre
 * of a blend (1 - lam) q1 + lam q2, walked towards the deepest point of the intersection,
 * min over z of max(q1, q2): the blend's least value e(lam) is concave with slope
 * q2 - q1 at its centre, and at its largest q1 = q2 there. 0 if neither finds one. *q1,
 * *q2 the point's forms. */
static int inner_point(const dual_pb *p, rc_vec3 *w, double *q1, double *q2)
{
    const rc_vec3 d = rc_v3_sub(p->m2, p->m1);
    const double a1 = rc_v3_dot(d, rc_sym3_mul_(p->A1, d, 0));
    const double a2 = rc_v3_dot(d, rc_sym3_mul_(p->A2, d, 0));
    if (!(a1 > 0.0) || !(a2 > 0.0))
        return 0;
    const double s1 = fmin(1.0, 1.0 / sqrt(a1)), s2 = fmax(0.0, 1.0 - 1.0 / sqrt(a2));
    if (s2 < s1) {
        *w = rc_v3_axpy(p->m1, 0.5 * (s1 + s2), d);
        *q1 = form_at(p->A1, p->m1, *w);
        *q2 = form_at(p->A2, p->m2, *w);
        if (*q1 < 1.0 && *q2 < 1.0)
            return 1;
    }
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < INNER_STEPS; it++) {
        const double lam = 0.5 * (lo + hi);
        const rc_sym3 A = rc_sym3_blend_(p->A1, p->A2, lam, 0);
        rc_sym3 adj;
        const double det = rc_sym3_adj_(&A, &adj, 0);
        if (!(det > 0.0))
            return 0;
        const rc_vec3 b = rc_v3_add(rc_v3_scale(1.0 - lam, p->b1), rc_v3_scale(lam, p->b2));
        *w = rc_v3_scale(1.0 / det, rc_sym3_mul_(&adj, b, 0));
        *q1 = form_at(p->A1, p->m1, *w);
        *q2 = form_at(p->A2, p->m2, *w);
        if (*q1 < 1.0 && *q2 < 1.0)
            return 1;
        if (*q2 > *q1)
            lo = lam;
        else
            hi = lam;
    }
    return 0;
}

/* A point of both ellipsoids near z: z moved towards the inner point w just far enough
 * that both forms, convex along the segment, are at most 1; checked on the point itself
 * (its computed forms), so rounding cannot admit a point outside. 0 if none. */
static int repaired(const dual_pb *p, rc_vec3 z, double q1, double q2, rc_vec3 w, double w1,
                    double w2, rc_vec3 *y)
{
    double s = 0.0;
    if (q1 > 1.0)
        s = fmax(s, (q1 - 1.0) / (q1 - w1));
    if (q2 > 1.0)
        s = fmax(s, (q2 - 1.0) / (q2 - w2));
    /* a little further in than convexity asks, for the rounding of the forms */
    s = fmin(1.0, s * (1.0 + 1e-6) + 1e-12);
    *y = rc_v3_axpy(z, s, rc_v3_sub(w, z));
    return form_at(p->A1, p->m1, *y) <= 1.0 && form_at(p->A2, p->m2, *y) <= 1.0;
}

/* The bracket [a, b] of lam around the sign change of the dual's slope (h(a) > 0 > h(b)),
 * narrowed by Illinois false position: lin_below's search and rc_glue_lin_min2_slope_'s.
 * ha, hb: the ends' slopes, the stale end's halved; side: the end moved last. */
typedef struct slope_bracket {
    double a, b, ha, hb;
    int side;
} slope_bracket;

/* The next lam: false position, or the midpoint where that leaves the bracket (or bisect
 * asks for it); NAN when no double lies inside. */
static double bracket_next(const slope_bracket *s, int bisect)
{
    double lam = s->a - s->ha * (s->b - s->a) / (s->hb - s->ha);
    if (!(lam > s->a && lam < s->b) || bisect)
        lam = 0.5 * (s->a + s->b);
    return lam > s->a && lam < s->b ? lam : NAN;
}

/* The slope h at lam narrows the bracket: 1 the lower end moved, -1 the upper one, 0 h is
 * zero or NaN (lam is the maximum, or nothing can be said). */
static int bracket_take(slope_bracket *s, double lam, double h)
{
    if (h > 0.0) {
        s->a = lam;
        s->ha = h;
        if (s->side == 1)
            s->hb *= 0.5; /* Illinois: the stale end's value halved */
        s->side = 1;
        return 1;
    }
    if (h < 0.0) {
        s->b = lam;
        s->hb = h;
        if (s->side == -1)
            s->ha *= 0.5;
        s->side = -1;
        return -1;
    }
    return 0;
}

/* Cap on the evaluations of lin_below's search: it converges superlinearly; a case it
 * does not settle by then goes to rc_glue_lin_min2_. */
#define BELOW_STEPS 40

/* Whether rc_glue_lin_min2_'s minimum of k.z over the intersection is below theta, from
 * certificates rather than a converged minimum: 0 (not below) when a dual value, a lower bound
 * of the minimum, is >= theta + margin, or a blend is empty (so is the intersection:
 * rc_glue_lin_min2_ says INFINITY); 1 (below) when a point of both ellipsoids has k.z < theta -
 * margin (only looked for if want_below); -1 when neither is found, then rc_glue_lin_min2_
 * itself decides. rc_glue_lin_min2_'s answer lies within its round-off of the true minimum (its
 * last brackets are below the resolution of lam), so a margin of many round-offs makes the
 * certified verdict rc_glue_lin_min2_'s. The search: the dual's slope in lam has the sign of
 * q2(z) - q1(z) at the blend's minimiser z (its multiplier times the forms' difference:
 * envelope theorem), one change of sign since the dual is unimodal; regula falsi (Illinois)
 * with bisection as a safeguard finds it. */
static int lin_below(const dual_pb *p, double theta, double margin, int want_below)
{
    const double hi_cut = theta + margin, lo_cut = theta - margin;
    rc_vec3 w = p->m1;
    double w1 = 0.0, w2 = 0.0;
    const int have_w = want_below && inner_point(p, &w, &w1, &w2);
    if (have_w && rc_v3_dot(p->k, w) < lo_cut)
        return 1;
    slope_bracket br = {0.0, 1.0, 0.0, 0.0, 0};
    for (int it = 0; it < BELOW_STEPS; it++) {
        double lam;
        if (it < 2) {
            lam = (double)it;
        } else {
            /* (bisected when false position leaves the bracket or crawls) */
            lam = bracket_next(&br, it % 4 == 3);
            if (isnan(lam))
                return -1;
        }
        rc_vec3 z;
        const double f = pb_dual(p, lam, &z);
        if (f == INFINITY)
            return 0;
        if (isnan(f))
            return -1;
        if (f >= hi_cut)
            return 0;
        const double q1 = form_at(p->A1, p->m1, z), q2 = form_at(p->A2, p->m2, z);
        if (q1 <= 1.0 && q2 <= 1.0) {
            /* a point of both: the minimum is within round-off of f */
            if (want_below && rc_v3_dot(p->k, z) < lo_cut)
                return 1;
            return -1;
        }
        if (have_w && f < lo_cut) {
            rc_vec3 y;
            if (repaired(p, z, q1, q2, w, w1, w2, &y) && rc_v3_dot(p->k, y) < lo_cut)
                return 1;
        }
        const double h = q2 - q1;
        if (it == 0) {
            br.ha = h;
            if (!(h > 0.0))
                return -1;
        } else if (it == 1) {
            br.hb = h;
            if (!(h < 0.0))
                return -1;
        } else if (bracket_take(&br, lam, h) == 0) {
            return -1; /* at the maximum: f is the minimum, within the margin of theta */
        }
    }
    return -1;
}

/* Cap on the evaluations of rc_glue_lin_min2_slope_'s search (it ends far sooner: the
 * slope is smooth and changes sign once); a case not settled by then is given to the
 * golden section. */
#define SLOPE_STEPS 64

/* rc_glue_lin_min2_'s minimum, found by the dual's slope rather than its values: the
 * sign change of q2 - q1 at the blend's minimiser (lin_below's search, Illinois false
 * position with bisection when it leaves the bracket) followed until the bracket of lam is
 * within a few round-offs. Near its maximum the dual is flat in lam, so the golden section,
 * which compares values, takes 92 evaluations to the same answer; the slope is not flat
 * there, and about a dozen settle it (test_glue_dual: the two agree to 1e-12 of the terms'
 * size, and on which intersections are empty). rc_glue_toi2's; rc_glue_toi keeps the
 * golden section's bits (test_glue_reference). */
double rc_glue_lin_min2_slope_(const rc_sym3 *A1, rc_vec3 m1, const rc_sym3 *A2, rc_vec3 m2,
                               rc_vec3 k, rc_vec3 *z)
{
    const dual_pb p = dual_pb_make(A1, m1, A2, m2, k);
    rc_vec3 za, zb;
    /* the ends: one ellipsoid's own minimiser inside the other is the minimum */
    double fa = pb_dual(&p, 0.0, &za);
    if (fa == INFINITY || isnan(fa))
        return fa;
    const double ha = form_at(A2, m2, za) - form_at(A1, m1, za);
    if (!(ha > 0.0)) {
        *z = za;
        return fa;
    }
    double fb = pb_dual(&p, 1.0, &zb);
    if (fb == INFINITY || isnan(fb))
        return fb;
    const double hb = form_at(A2, m2, zb) - form_at(A1, m1, zb);
    if (!(hb < 0.0)) {
        *z = zb;
        return fb;
    }
    slope_bracket br = {0.0, 1.0, ha, hb, 0};
    for (int it = 0;; it++) {
        if (it == SLOPE_STEPS)
            return rc_glue_lin_min2_(A1, m1, A2, m2, k, z);
        if (br.b - br.a <= 8.0 * DBL_EPSILON * br.b)
            break;
        const double lam = bracket_next(&br, 0);
        if (isnan(lam))
            break;
        rc_vec3 zl;
        const double f = pb_dual(&p, lam, &zl);
        if (f == INFINITY || isnan(f))
            return f;
        const int moved = bracket_take(&br, lam, form_at(A2, m2, zl) - form_at(A1, m1, zl));
        if (moved == 0) {
            *z = zl;
            return f;
        }
        if (moved > 0) {
            fa = f;
            za = zl;
        } else {
            fb = f;
            zb = zl;
        }
    }
    /* both ends are dual values, lower bounds of the minimum: the larger */
    *z = fa > fb ? za : zb;
    return fa > fb ? fa : fb;
}

/* Margins of the certified verdicts (dimensionless, relative): far above the round-off
 * of the terms compared (~1e-16) and of the old search's answers, far below any
 * difference that is not a tie; a verdict inside them goes to the old search. Of the dual
 * problem's terms; of a lower bound of a time, measured from t_from; of absolute times
 * (their differences lose digits of this size). */
#define CERT_REL 1e-10
#define BOUND_REL 1e-9
#define TIME_REL 1e-13

/* The margin for lin_below's verdicts on theta: of k.z over points at m1 and m2 and of
 * the times theta is made of (tscale: their size). */
static double below_margin(const dual_pb *p, double theta, double tscale)
{
    const double zs = rc_v3_norm(p->k) * (rc_v3_norm(p->m1) + rc_v3_norm(p->m2));
    return CERT_REL * (zs + fabs(theta)) + TIME_REL * tscale;
}

/* Whether a contact no earlier than lb after t_from is certainly not before bt. */
static int not_before(double t_from, double lb, double bt)
{
    return t_from + lb * (1.0 - BOUND_REL) - TIME_REL * (fabs(t_from) + fabs(bt)) >= bt;
}

/* A lower bound of the time from now at which shape a and shape k (centre separation d,
 * relative velocity w) can first meet: the time to close their gap across a plane normal
 * to u (their supports along u), INFINITY if that gap opens, 0 if u separates nothing
 * beyond round-off (a gap below BOUND_REL of the supports). */
static double plane_bound(const rc_toi_shape *a, const rc_toi_shape *k, rc_vec3 d, rc_vec3 w,
                          rc_vec3 u)
{
    const double u2 = rc_v3_norm2(u);
    if (!(u2 > 0.0))
        return 0.0;
    const double h = rc_toi_support_scaled_(a, u, u2) + rc_toi_support_scaled_(k, u, u2);
    const double gap = rc_v3_dot(u, d) - h;
    if (!(gap > BOUND_REL * h))
        return 0.0;
    const double uw = rc_v3_dot(u, w);
    return uw < 0.0 ? gap / -uw : INFINITY;
}

int rc_glue_toi(const rc_glue *g, const rc_toi_params *prm, rc_toi_workspace *ws,
                double t_from, const rc_toi_ball *k, double *t, rc_vec3 *y, rc_vec3 *n,
                int *piece)
{
    if (!g || !prm || !ws || !k || !t || !y || !n || !piece || !isfinite(t_from))
        return RC_EINVAL;
    if (!rc_v3_isfinite(k->x) || !isfinite(k->r))
        return RC_ENONFINITE;
    if (!(k->r > 0.0))
        return RC_ERADIUS;
    const rc_particle kp = {k->m, k->p};
    int st = rc_particle_check(&kp);
    if (st != RC_OK)
        return st;
    const double ic2 = g->inv_c2;
    const double Mk = rc_mass_rel(k->m, k->p, ic2);
    const rc_toi_shape sk = rc_toi_shape_M_(k->r, k->m, k->p, ic2, Mk);
    const rc_vec3 vk = rc_v3_scale(1.0 / Mk, k->p);
    const rc_sym3 Gk = rc_glue_shape_metric(&sk);
    /* which side of H a point is on: ell > 0 not yet reached (incoming), < 0 reached */
#define ELL(Y, T) (rc_v3_dot(g->kappa, rc_v3_sub((Y), g->x)) - ((T) - g->t_x))
    double bt = INFINITY;
    rc_vec3 by = rc_v3(0, 0, 0), bn = by;
    int bp = -1, need_h = 0;
    double ta_max = 0.0; /* the latest first contact of a straight cylinder, from t_from */
    for (int pc = 0; pc < 2; pc++) {
        const rc_toi_shape *sa = pc ? &g->out : &g->in;
        const rc_vec3 va = pc ? g->v_out : g->v_in;
        const rc_vec3 ca = rc_v3_axpy(g->x_c, t_from - g->t_c, va);
        const rc_vec3 dk = rc_v3_sub(k->x, ca), wk = rc_v3_sub(vk, va);
        if (pc == 1 && bp == 0) {
            /* the incoming piece is met at bt: the outgoing cylinder matters only if it
             * overlaps k now or meets it before bt, and a contact on H would be one of
             * this cylinder too (H's section lies in both), so at or after its contact.
             * A plane separating the two now (along the first contact's normal or the
             * centre line) that k cannot cross before bt rules out all three. */
            const double lb =
                fmax(plane_bound(sa, &sk, dk, wk, bn), plane_bound(sa, &sk, dk, wk, dk));
            if (not_before(t_from, lb, bt))
                continue;
        }
        double ta;
        rc_vec3 ya, na;
        st = rc_toi_shapes_rel(sa, &sk, dk, wk, prm, ws, &ta, &ya, &na);
        if (st == RC_MISS)
            continue; /* the whole cylinders never meet: neither does the piece */
        if (st == RC_EOVERLAP) {
            /* overlapping whole shapes now: the piece overlaps k if the common part reaches
             * its side of H; else its first contact is on H */
            const rc_sym3 Ga = rc_glue_shape_metric(sa);
            rc_vec3 z;
            const rc_vec3 dir = rc_v3_scale(pc ? 1.0 : -1.0, g->kappa);
            const rc_vec3 m1 = rc_v3_sub(ca, g->x), m2 = rc_v3_sub(k->x, g->x);
            /* (pc 0: the largest ell over the common part, > 0 reaches the incoming side;
             * pc 1: the least, < 0 reaches the outgoing side; a tolerance of touch_tol
             * radii of H's travel, as rc_toi's own overlap verdict) */
            const double tol = prm->touch_tol * g->r * rc_v3_norm(g->kappa);
            /* side < -tol (pc 1) or > tol (pc 0): lo below theta */
            const double dt = t_from - g->t_x, theta = (pc ? dt : -dt) - tol;
            const dual_pb pb = dual_pb_make(&Ga, m1, &Gk, m2, dir);
            const double margin = below_margin(&pb, theta, fabs(t_from) + fabs(g->t_x));
            int below = lin_below(&pb, theta, margin, 1);
            if (below < 0) {
                const double lo = rc_glue_lin_min2_(&Ga, m1, &Gk, m2, dir, &z);
                const double side = pc ? lo - dt : -lo - dt;
                below = lo != INFINITY && (pc ? side < -tol : side > tol);
            }
            if (below)
                return RC_EOVERLAP;
            need_h = 1;
            continue;
        }
        if (st != RC_OK)
            return st;
        const double tc = t_from + ta;
        ta_max = fmax(ta_max, ta);
        const rc_vec3 Y = rc_v3_add(rc_v3_axpy(ca, ta, va), ya);
        const double ell = ELL(Y, tc);
        if (pc ? ell <= 0.0 : ell >= 0.0) {
            if (tc < bt) {
                bt = tc;
                by = Y;
                bn = na;
                bp = pc;
            }
        } else {
            need_h = 1;
        }
    }
    if (need_h) {
        /* on H: min of t_x + kappa.z over both cylinders' sections (the incoming and the
         * outgoing cylinder have the same one) */
        rc_sym3 Aa, Ak;
        rc_vec3 ma, mk, z, kh = g->kappa;
        /* on a fast H the sections in its turned frame, where they keep their digits
         * (glue_section.h); the minimiser turned back below */
        rc_glue_frame fr = {0}; /* (read only when fast: -O3 cannot see it) */
        const int fast = rc_glue_frame_make(g, &fr);
        if (fast) {
            rc_glue_section_fast(g, &fr, &g->in, g->v_in, g->x_c, g->t_c, &Aa, &ma);
            rc_glue_section_fast(g, &fr, &sk, vk, k->x, t_from, &Ak, &mk);
            kh = rc_v3(fr.kq, 0.0, 0.0);
        } else {
            rc_glue_section_plain(g, &g->in, g->v_in, g->x_c, g->t_c, &Aa, &ma);
            rc_glue_section_plain(g, &sk, vk, k->x, t_from, &Ak, &mk);
        }
        /* Only a contact on H before bt would be taken. It is a contact of each cylinder
         * too (their sections on H coincide), so not before either's first contact: none
         * if that is at bt or later; else lin_below may certify the minimum not below bt.
         * rc_glue_lin_min2_ finds the minimum where it is needed. */
        int later = 0;
        if (bt < INFINITY) {
            if (not_before(t_from, ta_max, bt)) {
                later = 1;
            } else {
                const dual_pb pb = dual_pb_make(&Aa, ma, &Ak, mk, kh);
                const double theta = bt - g->t_x;
                const double margin = below_margin(&pb, theta, fabs(bt) + fabs(g->t_x));
                later = lin_below(&pb, theta, margin, 0) == 0;
            }
        }
        double lo = INFINITY;
        if (!later && rc_v3_norm2(kh) > 0.0) {
            lo = rc_glue_lin_min2_(&Aa, ma, &Ak, mk, kh, &z);
        } else if (!later) {
            /* (classical: H is the slice t = t_x, every point of it at one time; the dual
             * search, blind with k = 0 -- every blend's value is 0 -- is given the centres'
             * line, along which it finds the sections apart where they are) */
            lo = rc_glue_lin_min2_(&Aa, ma, &Ak, mk, rc_v3_sub(mk, ma), &z);
            lo = isfinite(lo) ? 0.0 : lo;
        }
        if (isnan(lo))
            return RC_EINVAL;
        if (fast && lo != INFINITY)
            z = rc_glue_turn_back(&fr, z);
        const double th = g->t_x + lo;
        if (lo != INFINITY && th >= t_from && th < bt) {
            bt = th;
            by = rc_v3_add(g->x, z);
            /* k's outward normal at the point, reversed: from the glued ball to k */
            const rc_vec3 ck = rc_v3_axpy(k->x, th - t_from, vk);
            const rc_vec3 gr = rc_sym3_mul_(&Gk, rc_v3_sub(ck, by), 0);
            bn = rc_v3_scale(1.0 / rc_v3_norm(gr), gr);
            bp = 2;
        }
    }
#undef ELL
    if (bp < 0)
        return RC_MISS;
    *t = bt;
    *y = by;
    *n = bn;
    *piece = bp;
    return RC_OK;
}
