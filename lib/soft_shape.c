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

/* Symmetric 3x3 matrix: xx, yy, zz, xy, xz, yz. */
typedef struct sym3 {
    double xx, yy, zz, xy, xz, yz;
} sym3;

static sym3 shape_matrix(const rc_toi_shape *sh, double scale)
{
    /* P = r^2 (g2 I + beta^2 I - beta beta^T), lengths in units of `scale`: diagonal
     * entries are sums of squares (no 1 - beta^2 by subtraction), as in toi_contracted.c */
    const rc_vec3 b = sh->beta;
    const double r = sh->r / scale, r2 = r * r;
    sym3 P = {r2 * (sh->g2 + b.y * b.y + b.z * b.z), r2 * (sh->g2 + b.x * b.x + b.z * b.z),
              r2 * (sh->g2 + b.x * b.x + b.y * b.y), -r2 * b.x * b.y, -r2 * b.x * b.z,
              -r2 * b.y * b.z};
    return P;
}

static rc_vec3 sym_mul(const sym3 *A, rc_vec3 v)
{
    return rc_v3(A->xx * v.x + A->xy * v.y + A->xz * v.z,
                 A->xy * v.x + A->yy * v.y + A->yz * v.z,
                 A->xz * v.x + A->yz * v.y + A->zz * v.z);
}

/* At lambda: F = k d^T M d (k = lambda (1 - lambda), M = C^-1, C = (1-lambda) P0 +
 * lambda P1), f = dF/dlambda = (1 - 2 lambda) d.y - k y.dP y with y = M d, and
 *   f' = -2 d.y - 2 (1 - 2 lambda) y.dP y + 2 k (dP y).M (dP y)
 * (dM/dlambda = -M dP M). F is concave in lambda (a minimum of functions affine in
 * lambda, Perram & Wertheim), so f is decreasing and f' < 0. */
static void pw_eval(const sym3 *P0, const sym3 *dP, rc_vec3 d, double lam, double *F,
                    double *f, double *fp, rc_vec3 *y)
{
    sym3 C, A;
    C.xx = P0->xx + lam * dP->xx;
    C.yy = P0->yy + lam * dP->yy;
    C.zz = P0->zz + lam * dP->zz;
    C.xy = P0->xy + lam * dP->xy;
    C.xz = P0->xz + lam * dP->xz;
    C.yz = P0->yz + lam * dP->yz;
    A.xx = C.yy * C.zz - C.yz * C.yz;
    A.yy = C.xx * C.zz - C.xz * C.xz;
    A.zz = C.xx * C.yy - C.xy * C.xy;
    A.xy = C.xz * C.yz - C.xy * C.zz;
    A.xz = C.xy * C.yz - C.xz * C.yy;
    A.yz = C.xy * C.xz - C.xx * C.yz;
    const double det = C.xx * A.xx + C.xy * A.xy + C.xz * A.xz;
    const rc_vec3 yy = rc_v3_scale(1.0 / det, sym_mul(&A, d));
    const rc_vec3 dy = sym_mul(dP, yy);
    const double k = lam * (1.0 - lam), dMd = rc_v3_dot(d, yy), ydy = rc_v3_dot(yy, dy);
    const double dyMdy = rc_v3_dot(dy, sym_mul(&A, dy)) / det;
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
            const sym3 P0 = shape_matrix(&si, R), P1 = shape_matrix(&sj, R);
            const sym3 dP = {P1.xx - P0.xx, P1.yy - P0.yy, P1.zz - P0.zz,
                             P1.xy - P0.xy, P1.xz - P0.xz, P1.yz - P0.yz};
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
