/* toi_contracted.c — first contact of two Lorentz-contracted balls (ellipses/spheroids)
 * by Brent root finding on the Perram-Wertheim parameter lambda.
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
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "relcol/status.h"
#include "relcol/toi.h"
#include "toi_private.h"

/* Half-width of the first bracket around the predicted lambda, as a fraction of the
 * sphere bracket (dimensionless; tuned on the benchmark's cases with GSL's solver: 6.1
 * evaluations per call on average, against 6.5 without a prediction and 6.2 with 0.02;
 * 5.3 (2-D) and 5.45 (3-D) with the solver and stopping rule below). */
#define RC_TOI_GUESS_WIDTH 0.05

/* Brent stops without evaluating its next point when that accepted interpolation step
 * is below this fraction of lambda_tol (dimensionless): near the root the step is the
 * predicted distance to it, so b already meets the tolerance, and the evaluation would
 * only confirm it. At 1 the brute-force normal error grows; at 0.1 it is unchanged and
 * most of the saved evaluations remain (tests/toi/test_toi_brute.c holds the error). */
#define RC_TOI_STOP_FRACTION 0.1

/* Relative margin by which the centre-line separating-axis test must clear the touching
 * band before it replaces the Perram-Wertheim solve for mu (dimensionless): above the
 * few-ulp round-off of both the supports and the computed mu, so the shortcut takes
 * only cases the solve would also call separated. */
#define RC_TOI_SEP_MARGIN (64.0 * DBL_EPSILON)

/* The root finder is written out below (no state between calls), so the workspace holds
 * nothing; it stays in the API so that a future solver may keep scratch memory. */
struct rc_toi_workspace {
    int unused;
};

int rc_toi_workspace_create(rc_toi_workspace **out)
{
    if (!out)
        return RC_EINVAL;
    *out = calloc(1, sizeof(rc_toi_workspace));
    return *out ? RC_OK : RC_ENOMEM;
}

void rc_toi_workspace_free(rc_toi_workspace **ws)
{
    if (!ws || !*ws)
        return;
    free(*ws);
    *ws = NULL;
}

/* frexp's exponent of a finite x > 0 and exact powers of two, read from and written into
 * the IEEE bits: the same values as frexp / ldexp without two library calls per use
 * (the solver uses them on every pair); the rare subnormal or out-of-range cases fall
 * back to the library. */
static inline int exponent_of(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    const int biased = (int)((u >> 52) & 0x7ff);
    if (biased == 0) { /* subnormal */
        int e;
        (void)frexp(x, &e);
        return e;
    }
    return biased - 1022;
}

static inline double pow2(int k)
{
    if (k < -1022 || k > 1023)
        return ldexp(1.0, k);
    const uint64_t u = (uint64_t)(k + 1023) << 52;
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

/* State of one contact problem: the shapes, the relative motion, and the best (smallest
 * |h|) evaluation so far, so the converged lambda needs no extra evaluation. */
typedef struct pw_problem {
    rc_sym3 P0, P1, dP; /* dP = P1 - P0 */
    rc_vec3 d, w, dxw;
    double q0, q1; /* (dxw)^T P0 (dxw), (dxw)^T P1 (dxw): 3-D only */
    int planar;   /* all z components zero: use the 2x2 formulas */
    int at_rest;  /* 1: the point d itself (overlap test), 0: the moving point d + w t */
    int miss;     /* some E_lambda is missed by the line: certified miss */
    int bad;      /* an evaluation overflowed: give up with RC_ENOCONVERGE */
    /* best evaluation: t = best_num / best_den (moving case), F = k dAd / det (rest
     * case), best_y parallel to adj(C) r, itself parallel to the outward normal */
    double best_abs_h, best_lam, best_num, best_den, best_k, best_dad, best_det;
    rc_vec3 best_y;
} pw_problem;

/* Adjugate and determinant of C = (1-lam) P0 + lam P1.
 * Not polynomial forms in lambda: adj C d, adj C w (and det C) can be written in the
 * Bernstein basis of (1 - lam, lam), whose coefficients (adj P0, the mixed adjugate,
 * adj P1; mixed discriminants) are PSD / non-negative, so that form is as accurate as
 * this one (more, for det of thin shapes). It saves a little per evaluation but its
 * per-call set-up (six coefficient vectors, four det coefficients) costs more than the
 * few evaluations of a solve save. Forms quadratic in y (y.(P1-P0)y as a polynomial in
 * den, num) would also square the cancellation in den d + num w. */
static inline double pw_matrix(const pw_problem *p, double lam, rc_sym3 *C, rc_sym3 *A,
                               const int planar)
{
    *C = rc_sym3_blend_(&p->P0, &p->P1, lam, planar);
    return rc_sym3_adj_(C, A, planar);
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
__attribute__((always_inline)) static inline double pw_eval(pw_problem *p, double lam,
                                                            const int planar)
{
    rc_sym3 C, A;
    const double det = pw_matrix(p, lam, &C, &A, planar);
    const double k = lam * (1.0 - lam);
    const rc_vec3 Ad = rc_sym3_mul_(&A, p->d, planar);
    const double dad = rc_v3_dot(p->d, Ad);
    double num = 0.0, den = 1.0, h;
    rc_vec3 y = Ad;
    if (!p->at_rest) {
        const rc_vec3 Aw = rc_sym3_mul_(&A, p->w, planar);
        const double waw = rc_v3_dot(p->w, Aw);
        const double daw = rc_v3_dot(p->d, Aw);
        /* (dxw)^T C (dxw) is linear in lambda like C: from the two end values, both
         * >= 0, so the blend has no cancellation (2-D: det C' = det C, q = (dxw)_z^2) */
        const double q =
            planar ? p->dxw.z * p->dxw.z : (1.0 - lam) * p->q0 + lam * p->q1;
        const double D = waw - k * q;
        if (!(D >= 0.0)) {
            p->miss = 1;
            return 1.0; /* the caller stops on miss */
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
        const double ydy = rc_v3_dot(y, rc_sym3_mul_(&p->dP, y, planar));
        const double kdd = k / (det * den);
        h = (1.0 - 2.0 * lam) - kdd * kdd * ydy;
    } else {
        const double ydy = rc_v3_dot(y, rc_sym3_mul_(&p->dP, y, planar));
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

/* One evaluation body, compiled once per dimension so the 2-D evaluations skip the z
 * terms without testing for them. The 3-D body stays out of line: inlined into the
 * solver loop it runs out of registers; the small 2-D body is inlined. */
__attribute__((noinline)) static double pw_h3(pw_problem *p, double lam)
{
    return pw_eval(p, lam, 0);
}

/* h at lam: planar is a compile-time constant in each solver instance */
__attribute__((always_inline)) static inline double pw_h(pw_problem *p, double lam,
                                                         const int planar)
{
    return planar ? pw_eval(p, lam, 1) : pw_h3(p, lam);
}

/* Make lam the best evaluation (a root pinned to a bracket end). */
__attribute__((always_inline)) static inline void pw_pin(pw_problem *p, double lam,
                                                         const int planar)
{
    p->best_abs_h = INFINITY;
    (void)pw_h(p, lam, planar);
}

/* Brent's method (Brent 1973, "Algorithms for minimization without derivatives", ch. 4:
 * inverse quadratic / secant steps safeguarded by bisection) on the bracket [a, b] with
 * h(a) > 0 > h(b), written out here instead of calling GSL's solver: at ~10^6 calls per
 * second GSL's per-call set-up, function-pointer calls and finiteness checks cost more
 * than the algorithm. The steps are GSL's brent's (minimum step eps/2 |b|). Converged:
 * the bracket [b, c] is narrower than lambda_tol, or the last step was (the superlinear
 * steps have converged; saves Brent's final step, which only closes the far end of the
 * bracket), or the next accepted interpolation step is below RC_TOI_STOP_FRACTION
 * lambda_tol, or h = 0 was hit. */
__attribute__((always_inline)) static inline int
pw_brent(pw_problem *p, double a, double fa, double b, double fb, const rc_toi_params *prm,
         const int planar)
{
    double c = a, fc = fa, d = b - a, e = d;
    double prev = 0.5 * (a + b); /* last evaluated point (at first: the mid-point) */
    for (int it = 0; it < prm->max_iter; it++) {
        if ((fb < 0.0 && fc < 0.0) || (fb > 0.0 && fc > 0.0)) {
            c = a; /* keep the root between b and c */
            fc = fa;
            d = e = b - a;
        }
        if (fabs(fc) < fabs(fb)) { /* b: the best end */
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        const double tol = 0.5 * DBL_EPSILON * fabs(b);
        const double m = 0.5 * (c - b);
        if (fb == 0.0 || fabs(m) <= tol)
            return RC_OK;
        if (fabs(e) < tol || fabs(fa) <= fabs(fb)) {
            d = e = m; /* bisection */
        } else {
            const double s = fb / fa;
            double pp, q;
            if (a == c) { /* secant */
                pp = 2.0 * m * s;
                q = 1.0 - s;
            } else { /* inverse quadratic interpolation */
                const double qa = fa / fc, r = fb / fc;
                pp = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if (pp > 0.0)
                q = -q;
            else
                pp = -pp;
            /* accept the interpolation only if it falls well inside the bracket and
             * shrinks faster than the step before last */
            const double lim1 = 3.0 * m * q - fabs(tol * q), lim2 = fabs(e * q);
            if (2.0 * pp < (lim1 < lim2 ? lim1 : lim2)) {
                e = d;
                d = pp / q;
                /* the accepted interpolation step predicts b's distance to the root */
                if (fabs(d) <= RC_TOI_STOP_FRACTION * prm->lambda_tol)
                    return RC_OK;
            } else {
                d = e = m;
            }
        }
        a = b;
        fa = fb;
        b += fabs(d) > tol ? d : (m > 0.0 ? tol : -tol);
        fb = pw_h(p, b, planar);
        if (p->miss)
            return RC_MISS;
        if (p->bad)
            return RC_ENOCONVERGE;
        const double far = ((fb < 0.0 && fc < 0.0) || (fb > 0.0 && fc > 0.0)) ? a : c;
        if (fabs(far - b) <= prm->lambda_tol || fabs(b - prev) <= prm->lambda_tol ||
            p->best_abs_h == 0.0)
            return RC_OK;
        prev = b;
    }
    return RC_ENOCONVERGE;
}

/* Root of h on [lo, hi] (h(lo) >= 0 >= h(hi) in exact arithmetic). guess (NAN: none)
 * is a predicted root: the bracket is first narrowed to guess -/+ guess_width, which
 * saves Brent iterations when the prediction is good and costs one evaluation when it
 * is not. On RC_OK the best evaluation is in p->best_*. */
__attribute__((always_inline)) static inline int
pw_solve_dim(pw_problem *p, double lo, double hi, double guess, const rc_toi_params *prm,
             const int planar)
{
    p->best_abs_h = INFINITY;
    double a = lo, b = hi, ha = NAN, hb = NAN;
    if (guess > lo && guess < hi) {
        const double width = RC_TOI_GUESS_WIDTH * (hi - lo);
        const double gl = guess - width > lo ? guess - width : lo;
        const double gh = guess + width < hi ? guess + width : hi;
        const double h1 = pw_h(p, gl, planar);
        if (p->miss)
            return RC_MISS;
        if (p->bad)
            return RC_ENOCONVERGE;
        if (h1 > 0.0) {
            a = gl;
            ha = h1;
            const double h2 = pw_h(p, gh, planar);
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
        ha = pw_h(p, a, planar);
        if (p->miss)
            return RC_MISS;
        if (p->bad)
            return RC_ENOCONVERGE;
        if (!(ha > 0.0)) { /* root at (or within round-off of) a = lo */
            pw_pin(p, a, planar);
            return RC_OK;
        }
    }
    if (isnan(hb)) {
        hb = pw_h(p, b, planar);
        if (p->miss)
            return RC_MISS;
        if (p->bad)
            return RC_ENOCONVERGE;
        if (!(hb < 0.0)) { /* root at (or within round-off of) b = hi */
            pw_pin(p, b, planar);
            return RC_OK;
        }
    }
    if (p->bad)
        return RC_ENOCONVERGE;
    if (a == b)
        return RC_OK;
    return pw_brent(p, a, ha, b, hb, prm, planar);
}

/* The solver compiled once per dimension: the dimension is a constant inside, so no
 * evaluation tests it or goes through a second call (pw_h2/pw_h3 wrappers before), and
 * the 2-D evaluation is inlined, with the support distances inline too. Same arithmetic
 * either way, bit for bit. */
static int pw_solve2(pw_problem *p, double lo, double hi, double guess,
                     const rc_toi_params *prm)
{
    return pw_solve_dim(p, lo, hi, guess, prm, 1);
}

static int pw_solve3(pw_problem *p, double lo, double hi, double guess,
                     const rc_toi_params *prm)
{
    return pw_solve_dim(p, lo, hi, guess, prm, 0);
}

static int pw_solve(pw_problem *p, double lo, double hi, double guess,
                    const rc_toi_params *prm)
{
    return p->planar ? pw_solve2(p, lo, hi, guess, prm) : pw_solve3(p, lo, hi, guess, prm);
}

int rc_toi_shapes_rel(const rc_toi_shape *s0, const rc_toi_shape *s1, rc_vec3 d,
                      rc_vec3 w, const rc_toi_params *prm, rc_toi_workspace *ws,
                      double *t, rc_vec3 *y0, rc_vec3 *n)
{
    (void)ws; /* the solver keeps no state */
    const double r0 = s0->r, r1 = s1->r, R = r0 + r1;
    const double g0 = s0->g, g1 = s1->g;
    /* lambda* = h0/(h0 + h1) with r g <= h <= r: the bracket from the bounding (r) and
     * inscribed (r/gamma) spheres. Zero width <=> both shapes are exact spheres: then
     * the contact problem IS the sphere problem (this is how c = inf collapses). */
    const double lam_lo = (r0 * g0) / (r0 * g0 + r1);
    const double lam_hi = r0 / (r0 + r1 * g1);
    if (!(lam_lo < lam_hi)) {
        int st = rc_toi_sphere_rel(R, d, w, prm, t, n);
        if (st == RC_OK && y0)
            *y0 = rc_v3_scale(r0, *n);
        return st;
    }
    /* The evaluations multiply up to the 16th power of a length: work in units of a
     * power of two near R (lengths) and near |w| (speeds). Scaling by powers of two is
     * exact, and lambda and the sign of h do not change; t scales back exactly. */
    const double sw = rc_v3_norm(w);
    const int eL = exponent_of(R), eW = exponent_of(sw > 0.0 ? sw : 1.0);
    const double sl = pow2(-eL), sv = pow2(-eW);
    rc_toi_shape u0 = *s0, u1 = *s1;
    u0.r *= sl;
    u1.r *= sl;
    pw_problem p;
    p.P0 = rc_toi_shape_matrix_(&u0, u0.r);
    p.P1 = rc_toi_shape_matrix_(&u1, u1.r);
    p.dP = rc_sym3_sub_(&p.P1, &p.P0);
    p.d = rc_v3_scale(sl, d);
    p.w = rc_v3_scale(sv, w);
    p.dxw = rc_v3_cross(p.d, p.w);
    p.planar = d.z == 0.0 && w.z == 0.0 && s0->beta.z == 0.0 && s1->beta.z == 0.0;
    p.q0 = p.planar ? 0.0 : rc_v3_dot(p.dxw, rc_sym3_mul_(&p.P0, p.dxw, 0));
    p.q1 = p.planar ? 0.0 : rc_v3_dot(p.dxw, rc_sym3_mul_(&p.P1, p.dxw, 0));
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
        /* Separating axis along the centre line: d/mu lies in K, whose support along
         * dhat is h0 + h1, so mu >= |d| / (h0 + h1). Clear of the touching band by more
         * than the round-off of the mu the solve would compute, that proves what the
         * solve would decide (separated), and it is the common case in a dense gas. */
        const rc_vec3 dhat = rc_v3_scale(1.0 / dn, d);
        const double hd0 = rc_toi_support_(s0, dhat), hd1 = rc_toi_support_(s1, dhat);
        guess = hd0 / (hd0 + hd1); /* lambda* if the shapes touched along dhat */
        if (!(dn > (hd0 + hd1) * (1.0 + prm->touch_tol) * (1.0 + RC_TOI_SEP_MARGIN))) {
            p.at_rest = 1;
            st = pw_solve(&p, lam_lo, lam_hi, guess, prm);
            if (st != RC_OK)
                return st;
            const double mu = sqrt(p.best_k * p.best_dad / p.best_det);
            if (mu < 1.0 - prm->touch_tol)
                return RC_EOVERLAP;
            if (mu <= 1.0 + prm->touch_tol) {
                const rc_vec3 nn = rc_v3_scale(1.0 / rc_v3_norm(p.best_y), p.best_y);
                if (!(-rc_v3_dot(w, nn) > prm->graze_tol * sw))
                    return RC_MISS; /* touching but separating (or sliding) */
                *t = 0.0;
                *n = nn;
                if (y0) {
                    const double h0 = rc_toi_support_(s0, nn), h1 = rc_toi_support_(s1, nn);
                    const rc_vec3 ya = rc_toi_support_point_(s0, nn, h0);
                    const rc_vec3 yb = rc_v3_sub(d, rc_toi_support_point_(s1, nn, h1));
                    *y0 = rc_v3_scale(0.5, rc_v3_add(ya, yb));
                }
                return RC_OK;
            }
            /* the shapes scaled by mu touch with this lambda; contact comes soon (the
             * bounding spheres overlap), along a nearby normal */
            guess = p.best_lam;
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
        const double hs0 = rc_toi_support_(s0, ns), hs1 = rc_toi_support_(s1, ns);
        guess = hs0 / (hs0 + hs1);
    }
    p.at_rest = 0;
    p.miss = 0;
    st = pw_solve(&p, lam_lo, lam_hi, guess, prm);
    if (st != RC_OK)
        return st;
    /* times 2^(eL - eW): one rounding, as ldexp (2^k itself must be representable) */
    const int et = eL - eW;
    double tc = p.best_num / p.best_den;
    tc = et >= -1022 && et <= 1023 ? tc * pow2(et) : ldexp(tc, et);
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
    *t = tc;
    *n = nn;
    if (y0) {
        const double h0 = rc_toi_support_(s0, nn), h1 = rc_toi_support_(s1, nn);
        const rc_vec3 rc = rc_v3_axpy(d, tc, w);
        /* the contact point seen from each surface; they agree to O(lambda error) */
        const rc_vec3 ya = rc_toi_support_point_(s0, nn, h0);
        const rc_vec3 yb = rc_v3_sub(rc, rc_toi_support_point_(s1, nn, h1));
        *y0 = rc_v3_scale(0.5, rc_v3_add(ya, yb));
    }
    return RC_OK;
}
