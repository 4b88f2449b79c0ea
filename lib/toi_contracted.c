/* toi_contracted.c — first contact of two Lorentz-contracted balls (ellipses/spheroids)
 * by GSL Brent root finding on the Perram-Wertheim parameter lambda.
 *
 * Why lambda and not t (papers/time-of-impact.md): for each lambda in (0, 1) the set
 *   E_lambda = { r : lambda (1-lambda) r^T C^-1 r <= 1 },  C = (1-lambda) P0 + lambda P1,
 * is an ellipsoid containing the Minkowski sum K of the two shapes, and K is their
 * intersection (Perram & Wertheim). The centre separation d + w t enters K at
 *   t_c = max over lambda of tau(lambda),  tau = entry time into E_lambda,
 * and tau is a closed-form quadratic root. tau is unimodal with its stationary point
 * exactly at contact, so t_c is the root of h(lambda) ~ dtau/dlambda: one bracketed
 * root find with closed-form evaluations, no nested iteration, and the time error is
 * quadratic in the lambda error. lambda* = h0/(h0 + h1) (support distances along the
 * normal), and r/gamma <= h <= r, so the bounding spheres (radius r) and inscribed
 * spheres (r/gamma) bracket lambda*. A lambda where the line misses E_lambda proves a
 * miss (K is inside every E_lambda). */
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "relcol/status.h"
#include "relcol/toi.h"
#include "toi_private.h"

/* Half-width of the first bracket around the predicted lambda, as a fraction of the
 * sphere bracket (dimensionless; tuned on the benchmark's cases: 6.1 evaluations per call
 * on average, against 6.5 without a prediction and 6.2 with 0.02). */
#define RC_TOI_GUESS_WIDTH 0.05

struct rc_toi_workspace {
    gsl_root_fsolver *brent;
};

rc_toi_workspace *rc_toi_workspace_alloc(void)
{
    /* The solver is assembled from its public struct (gsl_roots.h) rather than with
     * gsl_root_fsolver_alloc, whose out-of-memory path calls the GSL error handler, which
     * aborts by default: the library must return RC_ENOMEM-style NULL instead.
     * gsl_root_fsolver_free frees exactly these two blocks. */
    rc_toi_workspace *ws = malloc(sizeof *ws);
    gsl_root_fsolver *s = malloc(sizeof *s);
    void *state = malloc(gsl_root_fsolver_brent->size);
    if (!ws || !s || !state) {
        free(ws);
        free(s);
        free(state);
        return NULL;
    }
    s->type = gsl_root_fsolver_brent;
    s->function = NULL;
    s->root = s->x_lower = s->x_upper = 0.0;
    s->state = state;
    ws->brent = s;
    return ws;
}

void rc_toi_workspace_free(rc_toi_workspace **ws)
{
    if (!ws || !*ws)
        return;
    gsl_root_fsolver_free((*ws)->brent);
    free(*ws);
    *ws = NULL;
}

/* Symmetric 3x3 matrix: xx, yy, zz, xy, xz, yz. */
typedef struct sym3 {
    double xx, yy, zz, xy, xz, yz;
} sym3;

static sym3 shape_matrix(const rc_toi_shape *s)
{
    /* P = r^2 (g2 I + beta^2 I - beta beta^T): diagonal terms are sums of squares. */
    const rc_vec3 b = s->beta;
    const double r2 = s->r * s->r;
    sym3 P = {r2 * (s->g2 + b.y * b.y + b.z * b.z), r2 * (s->g2 + b.x * b.x + b.z * b.z),
              r2 * (s->g2 + b.x * b.x + b.y * b.y), -r2 * b.x * b.y, -r2 * b.x * b.z,
              -r2 * b.y * b.z};
    return P;
}

static inline rc_vec3 sym_mul(const sym3 *A, rc_vec3 v, int planar)
{
    if (planar)
        return rc_v3(A->xx * v.x + A->xy * v.y, A->xy * v.x + A->yy * v.y, 0.0);
    return rc_v3(A->xx * v.x + A->xy * v.y + A->xz * v.z,
                 A->xy * v.x + A->yy * v.y + A->yz * v.z,
                 A->xz * v.x + A->yz * v.y + A->zz * v.z);
}

/* State of one contact problem: the shapes, the relative motion, and the best (smallest
 * |h|) evaluation so far, so the converged lambda needs no extra evaluation. */
typedef struct pw_problem {
    sym3 P0, P1, dP; /* dP = P1 - P0 */
    rc_vec3 d, w, dxw;
    int planar;   /* all z components zero: use the 2x2 formulas */
    int at_rest;  /* 1: the point d itself (overlap test), 0: the moving point d + w t */
    int miss;     /* some E_lambda is missed by the line: certified miss */
    int bad;      /* an evaluation overflowed: give up with RC_ENOCONVERGE */
    double end_lam[2], end_h[2]; /* bracket ends already evaluated (gsl set re-asks) */
    /* best evaluation: t = best_num / best_den (moving case), F = k dAd / det (rest
     * case), best_y parallel to adj(C) r, itself parallel to the outward normal */
    double best_abs_h, best_lam, best_num, best_den, best_k, best_dad, best_det;
    rc_vec3 best_y;
} pw_problem;

/* Adjugate and determinant of C = (1-lam) P0 + lam P1. */
static double pw_matrix(const pw_problem *p, double lam, sym3 *C, sym3 *A)
{
    const double l1 = 1.0 - lam;
    C->xx = l1 * p->P0.xx + lam * p->P1.xx;
    C->yy = l1 * p->P0.yy + lam * p->P1.yy;
    C->xy = l1 * p->P0.xy + lam * p->P1.xy;
    if (p->planar) {
        C->zz = C->xz = C->yz = 0.0;
        A->xx = C->yy;
        A->yy = C->xx;
        A->xy = -C->xy;
        A->zz = A->xz = A->yz = 0.0;
        return C->xx * C->yy - C->xy * C->xy;
    }
    C->zz = l1 * p->P0.zz + lam * p->P1.zz;
    C->xz = l1 * p->P0.xz + lam * p->P1.xz;
    C->yz = l1 * p->P0.yz + lam * p->P1.yz;
    A->xx = C->yy * C->zz - C->yz * C->yz;
    A->yy = C->xx * C->zz - C->xz * C->xz;
    A->zz = C->xx * C->yy - C->xy * C->xy;
    A->xy = C->xz * C->yz - C->xy * C->zz;
    A->xz = C->xy * C->yz - C->xz * C->yy;
    A->yz = C->xy * C->xz - C->xx * C->yz;
    return C->xx * A->xx + C->xy * A->xy + C->xz * A->xz;
}

/* dF/dlambda, F = k r^T C^-1 r, k = lambda (1 - lambda), at the point r on E_lambda's
 * boundary (moving case: r = d + w tau(lambda)) or at r = d (rest case):
 *   F_lambda = (1 - 2 lambda) r^T M r - k (M r)^T (P1 - P0) (M r),   M = adj(C)/det,
 * times a positive factor, arranged so an evaluation costs one square root and one
 * division (the value keeps the sign and the root of F_lambda, all that Brent uses, and
 * stays O(1), which keeps Brent's interpolation steps good). Moving case: the entry
 * time tau = num/den (den > 0) solves
 *   k (w.Aw) t^2 + 2 k (d.Aw) t + (k d.Ad - det) = 0     (k r^T M r = 1, times det),
 * whose discriminant, by the Gram identity (d.Ad)(w.Aw) - (d.Aw)^2 = det (dxw)^T C (dxw),
 * is k det [w.Aw - k (dxw)^T C (dxw)]: no cancellation of large terms. On the boundary
 * r^T M r = 1/k, and with y = den A r = den A d + num A w:
 *   k F_lambda = (1 - 2 lambda) - (k / (det den))^2 y.(P1 - P0) y.
 * Rest case (y = A d): det^2 F_lambda = (1 - 2 lambda) det (d.Ad) - k y.(P1 - P0) y. */
static double pw_h(double lam, void *vp)
{
    pw_problem *p = vp;
    if (lam == p->end_lam[0])
        return p->end_h[0];
    if (lam == p->end_lam[1])
        return p->end_h[1];
    sym3 C, A;
    const double det = pw_matrix(p, lam, &C, &A);
    const double k = lam * (1.0 - lam);
    const rc_vec3 Ad = sym_mul(&A, p->d, p->planar);
    const double dad = rc_v3_dot(p->d, Ad);
    double num = 0.0, den = 1.0, h;
    rc_vec3 y = Ad;
    if (!p->at_rest) {
        const rc_vec3 Aw = sym_mul(&A, p->w, p->planar);
        const double waw = rc_v3_dot(p->w, Aw);
        const double daw = rc_v3_dot(p->d, Aw);
        const double q = p->planar ? p->dxw.z * p->dxw.z
                                   : rc_v3_dot(p->dxw, sym_mul(&C, p->dxw, 0));
        const double D = waw - k * q;
        if (!(D >= 0.0)) {
            p->miss = 1;
            return 1.0; /* finite: GSL must not see NaN; the caller stops on miss */
        }
        const double sq = sqrt(k * det * D);
        /* smaller root in the form that does not cancel; den > 0 */
        if (daw < 0.0) {
            num = k * dad - det;
            den = sq - k * daw;
        } else {
            num = -(k * daw + sq);
            den = k * waw;
        }
        y = rc_v3_axpy(rc_v3_scale(den, Ad), num, Aw);
        const double ydy = rc_v3_dot(y, sym_mul(&p->dP, y, p->planar));
        const double kdd = k / (det * den);
        h = (1.0 - 2.0 * lam) - kdd * kdd * ydy;
    } else {
        const double ydy = rc_v3_dot(y, sym_mul(&p->dP, y, p->planar));
        h = (1.0 - 2.0 * lam) * det * dad - k * ydy;
    }
    if (!isfinite(h)) { /* only for inputs beyond double range (gamma ~ 1e150) */
        p->bad = 1;
        return 1.0;
    }
    if (fabs(h) < p->best_abs_h) {
        p->best_abs_h = fabs(h);
        p->best_lam = lam;
        p->best_num = num;
        p->best_den = den;
        p->best_k = k;
        p->best_dad = dad;
        p->best_det = det;
        p->best_y = y;
    }
    return h;
}

/* Make lam the best evaluation (a root pinned to a bracket end). */
static void pw_pin(pw_problem *p, double lam)
{
    p->best_abs_h = INFINITY;
    p->end_lam[0] = p->end_lam[1] = NAN;
    (void)pw_h(lam, p);
}

/* Root of h on [lo, hi] (h(lo) >= 0 >= h(hi) in exact arithmetic). guess (NAN: none)
 * is a predicted root: the bracket is first narrowed to guess -/+ guess_width, which
 * saves Brent iterations when the prediction is good and costs one evaluation when it
 * is not. On RC_OK the best evaluation is in p->best_*. */
static int pw_solve(pw_problem *p, double lo, double hi, double guess,
                    const rc_toi_params *prm, rc_toi_workspace *ws)
{
    p->best_abs_h = INFINITY;
    p->end_lam[0] = p->end_lam[1] = NAN;
    double a = lo, b = hi, ha = NAN, hb = NAN;
    if (guess > lo && guess < hi) {
        const double width = RC_TOI_GUESS_WIDTH * (hi - lo);
        const double gl = fmax(lo, guess - width), gh = fmin(hi, guess + width);
        const double h1 = pw_h(gl, p);
        if (p->miss)
            return RC_MISS;
        if (p->bad)
            return RC_ENOCONVERGE;
        if (h1 > 0.0) {
            a = gl;
            ha = h1;
            const double h2 = pw_h(gh, p);
            if (p->miss)
                return RC_MISS;
            if (p->bad)
                return RC_ENOCONVERGE;
            if (h2 < 0.0) {
                b = gh;
                hb = h2;
            } else {
                a = gh;
                ha = h2;
            }
        } else {
            b = gl;
            hb = h1;
        }
    }
    if (isnan(ha)) {
        ha = pw_h(a, p);
        if (p->miss)
            return RC_MISS;
        if (p->bad)
            return RC_ENOCONVERGE;
        if (!(ha > 0.0)) { /* root at (or within round-off of) a = lo */
            pw_pin(p, a);
            return RC_OK;
        }
    }
    if (isnan(hb)) {
        hb = pw_h(b, p);
        if (p->miss)
            return RC_MISS;
        if (p->bad)
            return RC_ENOCONVERGE;
        if (!(hb < 0.0)) { /* root at (or within round-off of) b = hi */
            pw_pin(p, b);
            return RC_OK;
        }
    }
    if (p->bad)
        return RC_ENOCONVERGE;
    if (a == b)
        return RC_OK;
    p->end_lam[0] = a;
    p->end_h[0] = ha;
    p->end_lam[1] = b;
    p->end_h[1] = hb;
    gsl_function F = {pw_h, p};
    /* Endpoints straddle zero and are finite, so set/iterate cannot call the GSL error
     * handler (which aborts by default; the library must not). */
    if (gsl_root_fsolver_set(ws->brent, &F, a, b) != GSL_SUCCESS)
        return RC_ENOCONVERGE;
    double prev = gsl_root_fsolver_root(ws->brent);
    for (int it = 0; it < prm->max_iter; it++) {
        int st = gsl_root_fsolver_iterate(ws->brent);
        if (p->miss)
            return RC_MISS;
        if (p->bad || st != GSL_SUCCESS)
            return RC_ENOCONVERGE;
        const double xa = gsl_root_fsolver_x_lower(ws->brent);
        const double xb = gsl_root_fsolver_x_upper(ws->brent);
        const double x = gsl_root_fsolver_root(ws->brent);
        /* converged: the bracket is narrow, or the superlinear steps have become
         * smaller than lambda_tol (GSL's delta test; saves Brent's final step, which
         * only closes the far end of the bracket) */
        if (xb - xa <= prm->lambda_tol || fabs(x - prev) <= prm->lambda_tol ||
            p->best_abs_h == 0.0)
            return RC_OK;
        prev = x;
    }
    return RC_ENOCONVERGE;
}

int rc_toi_shapes_rel(const rc_toi_shape *s0, const rc_toi_shape *s1, rc_vec3 d,
                      rc_vec3 w, const rc_toi_params *prm, rc_toi_workspace *ws,
                      double *t, rc_vec3 *y0, rc_vec3 *n)
{
    const double r0 = s0->r, r1 = s1->r, R = r0 + r1;
    const double g0 = s0->g, g1 = s1->g;
    /* lambda* = h0/(h0 + h1) with r g <= h <= r: the bracket from the bounding (r) and
     * inscribed (r/gamma) spheres. Zero width <=> both shapes are exact spheres: then
     * the contact problem IS the sphere problem (this is how c = inf collapses). */
    const double lam_lo = (r0 * g0) / (r0 * g0 + r1);
    const double lam_hi = r0 / (r0 + r1 * g1);
    if (!(lam_lo < lam_hi)) {
        int st = rc_toi_sphere_rel(R, d, w, prm, t, n);
        if (st == RC_OK)
            *y0 = rc_v3_scale(r0, *n);
        return st;
    }
    /* The evaluations multiply up to the 16th power of a length: work in units of a
     * power of two near R (lengths) and near |w| (speeds). Scaling by powers of two is
     * exact, and lambda and the sign of h do not change; t scales back exactly. */
    const double sw = rc_v3_norm(w);
    int eL, eW;
    (void)frexp(R, &eL);
    (void)frexp(sw > 0.0 ? sw : 1.0, &eW);
    const double sl = ldexp(1.0, -eL), sv = ldexp(1.0, -eW);
    rc_toi_shape u0 = *s0, u1 = *s1;
    u0.r *= sl;
    u1.r *= sl;
    pw_problem p;
    p.P0 = shape_matrix(&u0);
    p.P1 = shape_matrix(&u1);
    p.dP.xx = p.P1.xx - p.P0.xx;
    p.dP.yy = p.P1.yy - p.P0.yy;
    p.dP.zz = p.P1.zz - p.P0.zz;
    p.dP.xy = p.P1.xy - p.P0.xy;
    p.dP.xz = p.P1.xz - p.P0.xz;
    p.dP.yz = p.P1.yz - p.P0.yz;
    p.d = rc_v3_scale(sl, d);
    p.w = rc_v3_scale(sv, w);
    p.dxw = rc_v3_cross(p.d, p.w);
    p.planar = d.z == 0.0 && w.z == 0.0 && s0->beta.z == 0.0 && s1->beta.z == 0.0;
    p.miss = 0;
    p.bad = 0;
    const double dn = rc_v3_norm(d);
    const double Rin = r0 * g0 + r1 * g1;
    double t_lo = 0.0, guess = NAN;
    int st;
    if (dn <= R * (1.0 + prm->touch_tol)) {
        /* Bounding spheres touch or overlap: decide on the shapes themselves with the
         * Perram-Wertheim scale factor mu^2 = max_lambda F(lambda; d). */
        if (dn < Rin * (1.0 - prm->touch_tol))
            return RC_EOVERLAP; /* even the inscribed spheres overlap */
        p.at_rest = 1;
        st = pw_solve(&p, lam_lo, lam_hi, NAN, prm, ws);
        if (st != RC_OK)
            return st;
        const double mu = sqrt(p.best_k * p.best_dad / p.best_det);
        if (mu < 1.0 - prm->touch_tol)
            return RC_EOVERLAP;
        if (mu <= 1.0 + prm->touch_tol) {
            const rc_vec3 nn = rc_v3_scale(1.0 / rc_v3_norm(p.best_y), p.best_y);
            if (!(-rc_v3_dot(w, nn) > prm->graze_tol * sw))
                return RC_MISS; /* touching but separating (or sliding) */
            const double h0 = rc_toi_support(s0, nn), h1 = rc_toi_support(s1, nn);
            const rc_vec3 ya = rc_toi_support_point_(s0, nn, h0);
            const rc_vec3 yb = rc_v3_sub(d, rc_toi_support_point_(s1, nn, h1));
            *t = 0.0;
            *n = nn;
            *y0 = rc_v3_scale(0.5, rc_v3_add(ya, yb));
            return RC_OK;
        }
        if (!(sw > 0.0))
            return RC_MISS;
    } else {
        /* Broad phase: the shapes lie inside their bounding spheres, so no sphere hit
         * means no hit, and the sphere time is a lower bound. */
        double ts;
        rc_vec3 ns;
        st = rc_toi_sphere_rel(R, d, w, prm, &ts, &ns);
        if (st != RC_OK)
            return st;
        t_lo = ts;
        /* lambda* = h0/(h0 + h1) along the contact normal; the bounding spheres' contact
         * normal predicts it (exactly, in the limit of small contraction). */
        const double hs0 = rc_toi_support(s0, ns), hs1 = rc_toi_support(s1, ns);
        guess = hs0 / (hs0 + hs1);
    }
    p.at_rest = 0;
    p.miss = 0;
    st = pw_solve(&p, lam_lo, lam_hi, guess, prm, ws);
    if (st != RC_OK)
        return st;
    double tc = ldexp(p.best_num / p.best_den, eL - eW);
    /* Separated now (mu > 1 + touch_tol) and the line's entry into K lies in the past:
     * it has passed through K already, separating. */
    if (!(tc >= 0.0))
        return RC_MISS;
    /* the shapes lie inside their bounding spheres: round-off only can put tc before
     * the spheres' contact, by a few ulp */
    if (tc < t_lo)
        tc = t_lo;
    const rc_vec3 nn = rc_v3_scale(1.0 / rc_v3_norm(p.best_y), p.best_y);
    if (!(-rc_v3_dot(w, nn) > prm->graze_tol * sw))
        return RC_MISS; /* grazing: tangent contact, no impulse */
    const double h0 = rc_toi_support(s0, nn), h1 = rc_toi_support(s1, nn);
    const rc_vec3 rc = rc_v3_axpy(d, tc, w);
    /* the contact point seen from each surface; they agree to O(lambda error) */
    const rc_vec3 ya = rc_toi_support_point_(s0, nn, h0);
    const rc_vec3 yb = rc_v3_sub(rc, rc_toi_support_point_(s1, nn, h1));
    *t = tc;
    *n = nn;
    *y0 = rc_v3_scale(0.5, rc_v3_add(ya, yb));
    return RC_OK;
}
