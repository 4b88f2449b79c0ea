/* riemann_eos.c — the ideal gases' specific enthalpies h(theta) (c = 1, m = 1) the
 * relativistic Riemann solver asks for: constant Gamma, and the Synge (Juttner) gas of
 * balls and discs (papers/shock-tube.md, section 3). Every entry gives h - 1 and h'
 * without cancellation as theta -> 0, where the classical gas is the limit. */
#include <math.h>

#include <gsl/gsl_sf_bessel.h>

#include "riemann.h"

static double ideal_hm1(const rs_eos *e, double th) { return e->gamma / (e->gamma - 1.0) * th; }
static double ideal_dh(const rs_eos *e, double th)
{
    (void)th;
    return e->gamma / (e->gamma - 1.0);
}
static const rs_eos_ops ideal_ops = {"ideal", ideal_hm1, ideal_dh};

/* 3-D: h = K3(x)/K2(x), x = 1/theta. Below SYNGE_SERIES_THETA the two Bessel functions'
 * large-x series S_nu(t) = sum_k a_k(nu) t^k (t = theta, a common sqrt(pi/2x) e^-x dropped)
 * give h - 1 = (S3 - S2)/S2 and h' = (S3' S2 - S3 S2')/S2^2 with no cancellation; above,
 * the scaled Bessel functions and h' = (1 + 5 theta h - h^2)/theta^2 lose at most
 * eps/theta^2 = 1e-13 relative. */
#define SYNGE_SERIES_THETA 0.02
static void synge3_series(double t, double *hm1, double *dh)
{
    double s2 = 1.0, s3 = 1.0, d2 = 0.0, d3 = 0.0, diff = 0.0, ddiff = 0.0;
    double a2 = 1.0, a3 = 1.0, tk = 1.0; /* a_k(nu) and t^k */
    for (int k = 1; k < 60; k++) {
        const double odd = (2.0 * k - 1.0) * (2.0 * k - 1.0);
        a2 *= (16.0 - odd) / (8.0 * k);
        a3 *= (36.0 - odd) / (8.0 * k);
        const double tkm1 = tk;
        tk *= t;
        s2 += a2 * tk;
        s3 += a3 * tk;
        diff += (a3 - a2) * tk;
        d2 += k * a2 * tkm1;
        d3 += k * a3 * tkm1;
        ddiff += k * (a3 - a2) * tkm1;
        if (fabs(a3 * tk) < 1e-18 * s3 && fabs(k * a3 * tkm1) < 1e-18 * fabs(d3) && k > 2)
            break;
    }
    (void)s3;
    *hm1 = diff / s2;
    /* h' = (S3' S2 - S3 S2')/S2^2 with S3 = S2 + diff: (diff' S2 - diff S2')/S2^2 */
    *dh = (ddiff * s2 - diff * d2) / (s2 * s2);
}
static double synge3_hm1(double th)
{
    if (th < SYNGE_SERIES_THETA) {
        double g, d;
        synge3_series(th, &g, &d);
        return g;
    }
    const double x = 1.0 / th;
    return gsl_sf_bessel_Kn_scaled(3, x) / gsl_sf_bessel_Kn_scaled(2, x) - 1.0;
}
static double synge3_dh(double th)
{
    if (th < SYNGE_SERIES_THETA) {
        double g, d;
        synge3_series(th, &g, &d);
        return d;
    }
    const double h = 1.0 + synge3_hm1(th);
    return (1.0 + 5.0 * th * h - h * h) / (th * th);
}
/* 2-D: h = K_{5/2}/K_{3/2}(1/theta) = (1 + 3 theta + 3 theta^2)/(1 + theta), elementary */
static double synge2_hm1(double th) { return th * (2.0 + 3.0 * th) / (1.0 + th); }
static double synge2_dh(double th)
{
    return (2.0 + 6.0 * th + 3.0 * th * th) / ((1.0 + th) * (1.0 + th));
}
static double synge_hm1(const rs_eos *e, double th)
{
    return e->dim == 2 ? synge2_hm1(th) : synge3_hm1(th);
}
static double synge_dh(const rs_eos *e, double th)
{
    return e->dim == 2 ? synge2_dh(th) : synge3_dh(th);
}
static const rs_eos_ops synge_ops = {"synge", synge_hm1, synge_dh};

rs_eos rs_eos_ideal(double gamma)
{
    rs_eos e = {&ideal_ops, gamma, 0};
    return e;
}

rs_eos rs_eos_synge(int dim)
{
    rs_eos e = {&synge_ops, 1.0 + 2.0 / dim, dim};
    return e;
}

double rs_eos_cs2(const rs_eos *e, double th)
{
    const double h = 1.0 + e->ops->hm1(e, th), dh = e->ops->dh(e, th);
    return th * dh / (h * (dh - 1.0));
}
