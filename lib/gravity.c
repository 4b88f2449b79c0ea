/* gravity.c — the table of field couplings, and the checks every coupling's entry points
 * share (relcol/gravity.h). */
#include <float.h>
#include <string.h>

#include "gravity_private.h"

const rc_gravity_coupling *const rc_gravity_couplings[] = {&rc_gravity_newtonian,
                                                           &rc_gravity_equivalence, NULL};

const rc_gravity_coupling *rc_gravity_find(const char *name)
{
    if (!name)
        return NULL;
    for (size_t i = 0; rc_gravity_couplings[i]; i++)
        if (strcmp(rc_gravity_couplings[i]->name, name) == 0)
            return rc_gravity_couplings[i];
    return NULL;
}

int rc_gravity_check_(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p)
{
    if (!f)
        return RC_EINVAL;
    if (!isfinite(f->g) || !isfinite(f->inv_c2) || !isfinite(m) || !rc_v3_isfinite(x) ||
        !rc_v3_isfinite(p))
        return RC_ENONFINITE;
    if (!(f->g > 0.0) || f->axis < 0 || f->axis > 2 || !(f->inv_c2 >= 0.0))
        return RC_EINVAL;
    if (!(m > 0.0))
        return RC_EMASS;
    return RC_OK;
}

int rc_gravity_arg_dt_(double dt)
{
    if (!isfinite(dt))
        return RC_ENONFINITE;
    return dt >= 0.0 ? RC_OK : RC_EINVAL;
}

int rc_gravity_arg_plane_(int k, double X, const double *dt)
{
    if (k < 0 || k > 2 || !dt)
        return RC_EINVAL;
    return isfinite(X) ? RC_OK : RC_ENONFINITE;
}

int rc_gravity_put_(rc_vec3 *x, rc_vec3 *p, rc_vec3 xn, rc_vec3 pn)
{
    if (!rc_v3_isfinite(xn) || !rc_v3_isfinite(pn))
        return RC_ENONFINITE;
    *x = xn;
    *p = pn;
    return RC_OK;
}

int rc_gravity_first_root_(double a, double b, double c0, double *t)
{
    const double d = b * b - 4.0 * a * c0;
    if (!(d >= 0.0))
        return RC_MISS;
    const double q = -0.5 * (b + copysign(sqrt(d), b));
    const double r1 = q / a, r2 = q != 0.0 ? c0 / q : r1;
    double best = INFINITY;
    if (r1 > 0.0)
        best = r1;
    if (r2 > 0.0 && r2 < best)
        best = r2;
    if (!isfinite(best))
        return RC_MISS;
    *t = best;
    return RC_OK;
}

int rc_gravity_pair_check_(const rc_gravity *f, const rc_toi_ball *a, const rc_toi_ball *b,
                           double t_max, const double *dt)
{
    if (!a || !b || !dt)
        return RC_EINVAL;
    int st = rc_gravity_check_(f, a->m, a->x, a->p);
    if (st == RC_OK)
        st = rc_gravity_check_(f, b->m, b->x, b->p);
    if (st != RC_OK)
        return st;
    if (!isfinite(a->r) || !isfinite(b->r))
        return RC_ENONFINITE;
    if (!(a->r > 0.0) || !(b->r > 0.0))
        return RC_ERADIUS;
    return t_max >= 0.0 ? RC_OK : RC_EINVAL;
}

static double poly_at(const double *c, int deg, double s)
{
    double v = c[deg];
    for (int k = deg - 1; k >= 0; k--)
        v = v * s + c[k];
    return v;
}

/* the one root of a polynomial monotone on [lo, hi] with a sign change there, bisected
 * until the bracket is a few roundings wide */
static double bisect(const double *c, int deg, double lo, double hi, int rising)
{
    for (int i = 0; i < 400 && hi - lo > 4.0 * DBL_EPSILON * fmax(fabs(lo), fabs(hi)); i++) {
        const double mid = 0.5 * (lo + hi), v = poly_at(c, deg, mid);
        if ((v > 0.0) == rising)
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

/* every point in (lo, hi) where the polynomial changes sign, in order (at most deg) */
static int poly_sign_changes(const double *c, int deg, double lo, double hi, double *out)
{
    while (deg > 0 && c[deg] == 0.0)
        deg--;
    if (deg == 0)
        return 0;
    double bound = 0.0; /* Cauchy's: every root has |s| <= 1 + max |c_k / c_deg| */
    for (int k = 0; k < deg; k++)
        bound = fmax(bound, fabs(c[k] / c[deg]));
    hi = fmin(hi, 1.0 + bound);
    if (!(hi > lo))
        return 0;
    double cuts[6], d[4];
    int n = 0;
    cuts[n++] = lo;
    for (int k = 1; k <= deg; k++)
        d[k - 1] = k * c[k];
    n += poly_sign_changes(d, deg - 1, lo, hi, cuts + 1);
    cuts[n++] = hi;
    int m = 0;
    for (int i = 0; i + 1 < n; i++) { /* monotone on each piece */
        const double a = poly_at(c, deg, cuts[i]), b = poly_at(c, deg, cuts[i + 1]);
        if ((a > 0.0) != (b > 0.0))
            out[m++] = bisect(c, deg, cuts[i], cuts[i + 1], b > 0.0);
    }
    return m;
}

/* 1 when the polynomial stays above its evaluation's rounding on [0, hi] (hi >= 0
 * finite), by a lower bound: the quadratic part's minimum there, and each higher term at
 * its most negative, c_k hi^k when c_k < 0. The margin, 1e-12 of sum |c_k| hi^k, is far
 * above the rounding of poly_at (a few units of 1e-16 of it), so a polynomial this passes
 * has no evaluated sign change for the root isolation to find. It costs a few products,
 * where the isolation costs its derivatives' roots and bisections. */
static int poly_stays_above(const double *c, int deg, double hi)
{
    if (!(hi >= 0.0) || !isfinite(hi))
        return 0;
    double q = fmin(c[0], c[0] + hi * (c[1] + hi * (deg >= 2 ? c[2] : 0.0)));
    if (deg >= 2 && c[2] > 0.0 && c[1] < 0.0 && -c[1] < 2.0 * c[2] * hi)
        q = fmin(q, c[0] - c[1] * c[1] / (4.0 * c[2])); /* (the vertex inside) */
    double size = 0.0, hk = 1.0;
    for (int k = 0; k <= deg; k++) {
        size += fabs(c[k]) * hk;
        if (k >= 3 && c[k] < 0.0)
            q += c[k] * hk;
        hk *= hi;
    }
    return q > 1e-12 * size;
}

int rc_gravity_poly_first_fall_(const double *c, int deg, double lo, double hi, double *s)
{
    double r[4];
    if (!(hi > lo))
        return RC_MISS;
    if (lo >= 0.0 && poly_stays_above(c, deg, hi))
        return RC_MISS;
    const int n = poly_sign_changes(c, deg, lo, hi, r);
    for (int i = 0; i < n; i++) {
        const double before = i ? 0.5 * (r[i - 1] + r[i]) : lo;
        if (poly_at(c, deg, before) > 0.0) {
            *s = r[i];
            return RC_OK;
        }
    }
    return RC_MISS;
}
