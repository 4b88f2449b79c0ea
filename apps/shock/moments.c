/* moments.c — from a bin's lab-frame densities to the named fluid variables, and the
 * same densities of an ideal fluid state (papers/shock-tube.md, section 5). */
#include <math.h>

#include "moments.h"
#include "../gas/juttner.h"

const char *const sh_derived_names[SH_NDERIVED] = {"n", "v", "p", "pperp", "Tp", "Te"};

/* 1 - 1/W = beta^2/(1 + 1/W), no cancellation as c -> inf */
static double inv_w(double c, double v) { return isinf(c) ? 1.0 : sqrt((1.0 - v / c) * (1.0 + v / c)); }

double sh_T_from_eint(int dim, double c, double eint)
{
    if (!(eint > 0.0))
        return NAN;
    if (isinf(c))
        return 2.0 * eint / dim;
    const double c2 = c * c, x = eint / c2; /* <gamma> - 1 */
    /* small x: the Bessel forms lose digits as 1e-16/x; the Maxwell value is exact to
     * O(theta), and Juttner's <gamma> - 1 = (d/2) theta (1 + O(theta)) is inverted by
     * bisection in log theta on x itself */
    double lo = log(1e-12), hi = log(1e6);
    for (int k = 0; k < 200 && hi - lo > 1e-14; k++) {
        const double mid = 0.5 * (lo + hi), th = exp(mid);
        double gm1;
        if (dim == 2)
            gm1 = th * (1.0 + 2.0 * th) / (1.0 + th);
        else if (th < 0.02) {
            rs_eos e = rs_eos_synge(3);
            gm1 = e.ops->hm1(&e, th) - th; /* <gamma> = h - theta */
        } else
            gm1 = jt_mean_gamma(dim, th) - 1.0;
        if (gm1 < x)
            lo = mid;
        else
            hi = mid;
    }
    return exp(0.5 * (lo + hi)) * c2;
}

void sh_derive(int dim, double c, const sh_mom *m, double *d)
{
    for (int k = 0; k < SH_NDERIVED; k++)
        d[k] = NAN;
    if (!(m->N0 > 0.0))
        return;
    const double v = m->Nx / m->N0, iw = inv_w(c, v);
    const double n = m->N0 * iw;
    const double p = m->Pxx - v * m->g;
    d[SH_N] = n;
    d[SH_V] = v;
    d[SH_P] = p;
    d[SH_PPERP] = m->Pyy;
    d[SH_TP] = p / n;
    /* eps_int = K - v g + N0 m v^2 / (1 + 1/W), the rest frame's T^00 - n m c^2 */
    const double eint = m->K - v * m->g + m->N0 * v * v / (1.0 + iw);
    d[SH_TE] = sh_T_from_eint(dim, c, eint / n);
}

void sh_fluid_moments(int dim, double c, const rs_eos *e, rs_state s, sh_mom *m)
{
    (void)dim;
    const double iw = inv_w(c, s.v), W = 1.0 / iw;
    /* rho c^2 (h - 1): classically gamma p / (gamma - 1) */
    const double rhoc2hm1 = isinf(c) ? e->gamma / (e->gamma - 1.0) * s.p
                                     : s.rho * c * c * e->ops->hm1(e, s.p / (s.rho * c * c));
    const double rhoh = isinf(c) ? s.rho : s.rho + rhoc2hm1 / (c * c); /* rho h (mass units) */
    m->N0 = s.rho * W;
    m->Nx = s.rho * W * s.v;
    m->g = rhoh * W * W * s.v;
    m->Pxx = rhoh * W * W * s.v * s.v + s.p;
    m->Pyy = s.p;
    /* K = rho c^2 (h - 1) W^2 + rho v^2 W^3/(W + 1) - p */
    m->K = rhoc2hm1 * W * W + s.rho * s.v * s.v * W * W * W / (W + 1.0) - s.p;
}

int sh_mom_bin(sh_mom_at at, void *ctx, double xa, double xb, sh_mom *out)
{
    static const double gx[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                 0.9602898564975363};
    static const double gw[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                 0.1012285362903763};
    sh_mom s = {0};
    const double mid = 0.5 * (xa + xb), half = 0.5 * (xb - xa);
    for (int i = 0; i < 8; i++) {
        const double x = mid + (i < 4 ? -1.0 : 1.0) * half * gx[i % 4], w = 0.5 * gw[i % 4];
        sh_mom m;
        int rc = at(x, ctx, &m);
        if (rc)
            return rc;
        s.N0 += w * m.N0, s.Nx += w * m.Nx, s.g += w * m.g;
        s.K += w * m.K, s.Pxx += w * m.Pxx, s.Pyy += w * m.Pyy;
    }
    *out = s;
    return 0;
}
