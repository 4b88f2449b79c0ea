/* soft_shape.c — contact geometry of two soft balls in the integration frame: overlap depth
 * and normal of uncontracted spheres, or of Lorentz-contracted spheroids by maximising the
 * Perram-Wertheim function over lambda (papers/soft-sphere.md, section 7). */
#include <math.h>

#include "relcol/toi.h"
#include "soft_private.h"
#include "toi_private.h"

/* Newton on dF/dlambda stops when its step is below this (dimensionless, lambda is in
 * (0, 1)). mu^2 = F is stationary in lambda, so its error is O(step^2), far below
 * rounding; the normal's is O(step) ~ 1e-14, below the steppers' 1e-14 smallest rtol
 * by the margin the right-hand side needs to look smooth to the BDF Jacobian. */
#define RC_SOFT_PW_LAMBDA_TOL 1e-14
/* Newton iterations per call: warm-started from the previous call it takes 2-3; a cold
 * start with bisection safeguards ~10. 100 is a guard against a non-finite input only. */
#define RC_SOFT_PW_MAXIT 100

static rc_vec3 vget(const double *y) { return rc_v3(y[0], y[1], y[2]); }

/* At lambda: F = k d^T M d (k = lambda (1 - lambda), M = C^-1, C = (1-lambda) P0 +
 * lambda P1), f = dF/dlambda = (1 - 2 lambda) d.y - k y.dP y with y = M d, and
 *   f' = -2 d.y - 2 (1 - 2 lambda) y.dP y + 2 k (dP y).M (dP y)
 * (dM/dlambda = -M dP M). F is concave in lambda (a minimum of functions affine in
 * lambda, Perram & Wertheim), so f is decreasing and f' < 0. */
static void pw_eval(const rc_sym3 *P0, const rc_sym3 *dP, rc_vec3 d, double lam, double *F,
                    double *f, double *fp, rc_vec3 *y)
{
    const rc_sym3 C = rc_sym3_axpy_(P0, lam, dP);
    rc_sym3 A;
    const double det = rc_sym3_adj_(&C, &A, 0);
    const rc_vec3 yy = rc_v3_scale(1.0 / det, rc_sym3_mul_(&A, d, 0));
    const rc_vec3 dy = rc_sym3_mul_(dP, yy, 0);
    const double k = lam * (1.0 - lam), dMd = rc_v3_dot(d, yy), ydy = rc_v3_dot(yy, dy);
    const double dyMdy = rc_v3_dot(dy, rc_sym3_mul_(&A, dy, 0)) / det;
    *F = k * dMd;
    *f = (1.0 - 2.0 * lam) * dMd - k * ydy;
    *fp = -2.0 * dMd - 2.0 * (1.0 - 2.0 * lam) * ydy + 2.0 * k * dyMdy;
    *y = yy;
}

int rc_soft_geometry(rc_soft_sys *s, size_t q, size_t i, size_t j, const double *y,
                     double *delta, rc_vec3 *n, double *mu)
{
    const double *yi = y + RC_SOFT_NY * i, *yj = y + RC_SOFT_NY * j;
    const rc_vec3 d = rc_v3_sub(vget(yj), vget(yi));
    const double dist = rc_v3_norm(d), R = s->r[i] + s->r[j];
    if (s->shape != RC_SOFT_SPHERE) {
        const double k = s->inv_c2;
        const rc_vec3 pi = vget(yi + 3), pj = vget(yj + 3);
        const double mi = s->m0[i] + yi[6] * k, mj = s->m0[j] + yj[6] * k;
        const double Mi = sqrt(mi * mi + rc_v3_norm2(pi) * k);
        const double Mj = sqrt(mj * mj + rc_v3_norm2(pj) * k);
        rc_toi_shape si = rc_toi_shape_M_(s->r[i], mi, pi, k, Mi);
        rc_toi_shape sj = rc_toi_shape_M_(s->r[j], mj, pj, k, Mj);
        if (s->shape == RC_SOFT_CONTRACTED_FROZEN && s->held[q]) {
            si = s->frozen[2 * q];
            sj = s->frozen[2 * q + 1];
        }
        /* lambda* = h_i(n)/(h_i(n) + h_j(n)) with r g <= h <= r: the bracket of the
         * inscribed and bounding spheres (toi_contracted.c). Zero width <=> both shapes
         * are exact spheres (always so at c = inf): then fall through to the sphere
         * formulas below, so c = inf is today's sphere model bit for bit. */
        double lo = (s->r[i] * si.g) / (s->r[i] * si.g + s->r[j]);
        double hi = s->r[i] / (s->r[i] + s->r[j] * sj.g);
        if (lo < hi) {
            /* lengths in units of R: P and d of order 1 whatever the user's units */
            const rc_sym3 P0 = rc_toi_shape_matrix_(&si, si.r / R);
            const rc_sym3 P1 = rc_toi_shape_matrix_(&sj, sj.r / R);
            const rc_sym3 dP = rc_sym3_sub_(&P1, &P0);
            const rc_vec3 dd = rc_v3_scale(1.0 / R, d);
            double lam = s->lam[q];
            if (!(lam > lo && lam < hi)) {
                /* cold start: lambda* predicted from the supports along d */
                const rc_vec3 e = rc_v3_scale(1.0 / dist, d);
                const double hi_ = rc_toi_support(&si, e), hj_ = rc_toi_support(&sj, e);
                lam = hi_ / (hi_ + hj_);
                if (!(lam > lo && lam < hi))
                    lam = 0.5 * (lo + hi);
            }
            double F = NAN, f, fp;
            rc_vec3 yv = dd;
            for (int it = 0; it < RC_SOFT_PW_MAXIT; it++) {
                pw_eval(&P0, &dP, dd, lam, &F, &f, &fp, &yv);
                s->n_pw++;
                /* keep the bracket: f decreasing, root where f changes sign */
                if (f > 0.0)
                    lo = lam;
                else
                    hi = lam;
                double next = lam - f / fp;
                if (!(fp < 0.0) || !(next > lo && next < hi))
                    next = 0.5 * (lo + hi); /* safeguard: bisect the bracket */
                const double step = next - lam;
                if (fabs(step) <= RC_SOFT_PW_LAMBDA_TOL || !(lo < hi))
                    break;
                lam = next;
            }
            s->lam[q] = lam;
            /* mu: gauge of the Minkowski sum K (1 at contact); n: normal of K at d/mu;
             * delta = h_K(n) - n.d = (n.d)(1 - mu)/mu with h_K(n) = n.d/mu = h_i(n) +
             * h_j(n) the support of K: the normal depth, r_i + r_j - |d| for spheres,
             * whose rate at contact is -n.w exactly (papers/soft-sphere.md 7.2).
             * Computed as h_i(n) + h_j(n) - n.d, not from 1 - mu: the supports are
             * cancellation-free (rc_toi_support), so delta has the absolute error of
             * r_i + r_j - |d| for spheres, and an error in n enters only at second
             * order (d/mu is the support point of K along n: d h_K/dn = d/mu). From
             * 1 - mu the relative error grew as 1e-16 R/delta and cost CVODE accuracy at
             * kappa >= 1e11 (measured: outcomes off by up to 1e-5 at rtol 1e-11). */
            const double m = sqrt(F);
            *mu = m;
            *n = rc_v3_scale(1.0 / rc_v3_norm(yv), yv);
            *delta = rc_toi_support(&si, *n) + rc_toi_support(&sj, *n) - rc_v3_dot(*n, d);
            return 1;
        }
    }
    *mu = dist / R;
    *delta = R - dist;
    *n = rc_v3_scale(1.0 / dist, d);
    return 0;
}
