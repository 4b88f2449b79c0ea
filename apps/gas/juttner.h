/* juttner.h — the d-dimensional Jüttner and Maxwell–Boltzmann laws of a gas at
 * theta = kT/(m c^2), written in gamma (header only; shared by relcol-gas, the 2-D
 * reproduction test and notebook 07). Uses GSL's Bessel and incomplete-gamma functions.
 *
 * Jüttner in d dimensions: f(gamma) = gamma (gamma^2 - 1)^((d-2)/2) e^(-gamma/theta) / Z,
 *   Z = Gamma(d/2)/sqrt(pi) 2^((d-1)/2) theta^((d-1)/2) K_((d+1)/2)(1/theta)
 * (differentiate K_nu(x) = sqrt(pi) (x/2)^nu / Gamma(nu + 1/2) Int_1^inf e^(-x t)
 * (t^2 - 1)^(nu - 1/2) dt in x, nu = (d-1)/2), so <gamma> = -d ln Z / d(1/theta) =
 *   K_((d-1)/2)(1/theta) / K_((d+1)/2)(1/theta) + d theta,
 * which in 2-D (K_1/2, K_3/2 elementary) is (1 + 2 theta + 2 theta^2)/(1 + theta), with
 * f(gamma) = gamma e^(-(gamma-1)/theta) / (theta (1 + theta)). Equipartition:
 * <p.v> = d kT, i.e. <(gamma^2 - 1)/gamma> = d theta.
 * Maxwell–Boltzmann at the same kT (Newtonian momentum law, f(p) ~ exp(-p^2/(2 m kT))):
 * (gamma^2 - 1)/(2 theta) = p^2/(2 m^2 c^2 theta) is Gamma(d/2, 1) distributed. */
#ifndef RELCOL_GAS_JUTTNER_H
#define RELCOL_GAS_JUTTNER_H

#include <math.h>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>

/* Bracket of the theta inversions (dimensionless): far colder and hotter than any gas
 * relcol simulates; bisection in log theta to round-off. */
#define JT_THETA_MIN 1e-8
#define JT_THETA_MAX 1e6

/* <gamma> from the Bessel functions (any d >= 1; scaled K keep small theta finite). */
static inline double jt_mean_gamma_bessel(int d, double theta)
{
    const double x = 1.0 / theta;
    return gsl_sf_bessel_Knu_scaled(0.5 * (d - 1), x) / gsl_sf_bessel_Knu_scaled(0.5 * (d + 1), x) +
           d * theta;
}

/* <gamma> of the d-D Jüttner law: closed form in 2-D, Bessel functions otherwise. */
static inline double jt_mean_gamma(int d, double theta)
{
    if (d == 2)
        return (1.0 + 2.0 * theta + 2.0 * theta * theta) / (1.0 + theta);
    return jt_mean_gamma_bessel(d, theta);
}

/* theta with jt_mean_gamma(d, theta) = g (NAN if g <= 1 or not finite). In 2-D the root
 * of 2 theta^2 + (2 - g) theta + (1 - g) = 0, written without cancellation; otherwise
 * bisection (<gamma> increases with theta). */
static inline double jt_theta_from_gamma(int d, double g)
{
    if (!(g > 1.0) || !isfinite(g))
        return NAN;
    if (d == 2) {
        /* theta = ((g - 2) + sqrt(g^2 + 4g - 4))/4 = 2(g - 1)/((2 - g) + sqrt(g^2 + 4g - 4)) */
        const double s = sqrt(g * g + 4.0 * g - 4.0);
        return g >= 2.0 ? 0.25 * ((g - 2.0) + s) : 2.0 * (g - 1.0) / ((2.0 - g) + s);
    }
    double lo = log(JT_THETA_MIN), hi = log(JT_THETA_MAX);
    for (int k = 0; k < 200 && hi - lo > 1e-15 * fmax(1.0, fabs(lo)); k++) {
        const double mid = 0.5 * (lo + hi);
        if (jt_mean_gamma(d, exp(mid)) < g)
            lo = mid;
        else
            hi = mid;
    }
    return exp(0.5 * (lo + hi));
}

/* ln of Z e^(1/theta) (the normalisation of f, scaled by e^(1/theta)). */
static inline double jt_log_norm(int d, double theta)
{
    return gsl_sf_lngamma(0.5 * d) - 0.5 * log(M_PI) + 0.5 * (d - 1) * log(2.0 * theta) +
           log(gsl_sf_bessel_Knu_scaled(0.5 * (d + 1), 1.0 / theta));
}

/* Jüttner density in gamma (normalised); d = 1 diverges like (gamma - 1)^(-1/2) at 1. */
static inline double jt_pdf(int d, double theta, double gamma)
{
    const double gm1 = gamma - 1.0;
    if (!(gm1 >= 0.0))
        return 0.0;
    if (d == 2)
        return gamma * exp(-gm1 / theta) / (theta * (1.0 + theta));
    return gamma * pow(gm1 * (gamma + 1.0), 0.5 * (d - 2)) *
           exp(-gm1 / theta - jt_log_norm(d, theta));
}

typedef struct {
    int d;
    double theta;
} jt_rap;

/* The Jüttner weight over the rapidity y (gamma = cosh y, |p|/mc = sinh y): smooth for
 * every d, including the d = 1 endpoint. */
static inline double jt_rap_integrand(double y, void *v)
{
    const jt_rap *q = v;
    const double a = 2.0 * sinh(0.5 * y) * sinh(0.5 * y) / q->theta; /* (cosh y - 1)/theta */
    if (!(a < 700.0))
        return 0.0;
    return cosh(y) * pow(sinh(y), q->d - 1) * exp(-a);
}

/* P(gamma' > gamma) by quadrature over the rapidity (any d; gamma >= 1). */
static inline double jt_sf_rapidity(int d, double theta, double gamma,
                                    gsl_integration_workspace *ws)
{
    jt_rap q = {d, theta};
    gsl_function F = {jt_rap_integrand, &q};
    double r, err;
    /* acosh(gamma) loses half the digits near gamma = 1: use log1p form */
    const double x = gamma - 1.0;
    const double y0 = log1p(x + sqrt(x * (x + 2.0)));
    gsl_integration_qagiu(&F, y0, 0.0, 1e-12, 200, ws, &r, &err);
    return r / exp(jt_log_norm(d, theta));
}

/* P(gamma' > gamma) under Jüttner. 2-D: e^(-x/theta)(1 + theta + x)/(1 + theta),
 * x = gamma - 1; other d: adaptive quadrature over the rapidity (relative 1e-12; ws holds
 * >= 200 intervals). */
static inline double jt_sf(int d, double theta, double gamma, gsl_integration_workspace *ws)
{
    const double x = gamma - 1.0;
    if (!(x > 0.0))
        return 1.0;
    if (!isfinite(x))
        return 0.0;
    if (d == 2)
        return exp(-x / theta) * (1.0 + theta + x) / (1.0 + theta);
    return jt_sf_rapidity(d, theta, gamma, ws);
}

/* gamma with P(gamma' > gamma) = q under Jüttner (0 < q < 1): bisection on ln(gamma - 1)
 * (the survival function decreases), to round-off. */
static inline double jt_quantile_upper(int d, double theta, double q, gsl_integration_workspace *ws)
{
    /* bracket in x = gamma - 1: widened until it holds (sf(lo) > q > sf(hi)) */
    double lo = log(1e-12 * theta), hi = log(50.0 * theta + 50.0);
    while (jt_sf(d, theta, 1.0 + exp(lo), ws) <= q && lo > -700.0)
        lo -= 5.0;
    while (jt_sf(d, theta, 1.0 + exp(hi), ws) >= q && hi < 700.0)
        hi += 1.0;
    for (int k = 0; k < 200 && hi - lo > 1e-14; k++) {
        const double mid = 0.5 * (lo + hi);
        if (jt_sf(d, theta, 1.0 + exp(mid), ws) > q)
            lo = mid;
        else
            hi = mid;
    }
    return 1.0 + exp(0.5 * (lo + hi));
}

/* Maxwell–Boltzmann at the same theta: P(gamma' > gamma) and the density in gamma. */
static inline double mb_sf(int d, double theta, double gamma)
{
    const double u = (gamma - 1.0) * (gamma + 1.0) / (2.0 * theta);
    if (!(u > 0.0))
        return 1.0;
    return gsl_sf_gamma_inc_Q(0.5 * d, u);
}

static inline double mb_pdf(int d, double theta, double gamma)
{
    const double u = (gamma - 1.0) * (gamma + 1.0) / (2.0 * theta);
    if (!(u >= 0.0))
        return 0.0;
    /* du/dgamma = gamma/theta; Gamma(d/2, 1) density u^(d/2-1) e^-u / Gamma(d/2) */
    return gamma / theta * exp((0.5 * d - 1.0) * log(u) - u - gsl_sf_lngamma(0.5 * d));
}

/* The exact microcanonical temperature of N free particles (c = 1, m = 1) in 2-D at
 * total kinetic energy N (g - 1), g the mean gamma, with no momentum constraint (a box
 * with walls). Hard discs with uncontracted shapes have an energy-independent
 * configuration integral, so their momenta are those of the free gas. The one-particle
 * Laplace transform Int d^2p e^(-beta E) = 2 pi e^(-beta) (1 + beta)/beta^2 makes the
 * N-particle phase volume an exact finite sum, with eps = N (g - 1):
 *   Phi(eps) = sum_k C(N, k) eps^(2N-k) / (2N-k)!,  Omega = dPhi/deps,
 * and microcanonical equipartition gives <p.v> = 2 Phi/Omega per particle: returns
 * theta_micro = Phi/Omega, to compare with <p.v>/2 (it differs from the canonical
 * jt_theta_from_gamma(2, g) by O(theta/N)). Sums in logs (N up to ~1e7). */
static inline double jt_theta_micro_2d(double N, double g)
{
    const double eps = N * (g - 1.0);
    if (!(eps > 0.0) || !(N >= 1.0))
        return NAN;
    const long n = (long)N;
    const double le = log(eps);
    double mphi = -INFINITY, mom = -INFINITY;
    for (int pass = 0; pass < 2; pass++) {
        double sphi = 0.0, som = 0.0;
        for (long k = 0; k <= n; k++) {
            const double lc = gsl_sf_lnchoose((unsigned)n, (unsigned)k);
            const double a = 2.0 * n - k;
            const double lphi = lc + a * le - gsl_sf_lngamma(a + 1.0);
            const double lom = lc + (a - 1.0) * le - gsl_sf_lngamma(a);
            if (pass == 0) {
                mphi = fmax(mphi, lphi);
                mom = fmax(mom, lom);
            } else {
                sphi += exp(lphi - mphi);
                som += exp(lom - mom);
            }
        }
        if (pass == 1)
            return exp(mphi - mom) * sphi / som;
    }
    return NAN;
}

#endif
