/* riemann_hs.c — the exact Riemann solution of the Euler equations (c = inf) for the dense
 * hard-sphere gas, P = n T Z(phi), e = (3/2) T per ball (papers/shock-tube.md, section 2):
 * rarefactions by quadrature of u +- int c_s dn/n along the isentrope
 * T = T_K (n/n_K)^(2/3) exp((2/3) int_(phi_K)^phi (Z - 1)/phi' dphi'), shocks by the
 * Hugoniot, the contact by Brent's method in ln p (GSL). m = 1. */
#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "riemann.h"
#include "riemann_private.h"

static double z_kolafa(const rs_hs *g, double phi)
{
    (void)g;
    const double d = 1.0 - phi;
    return (1.0 + phi + phi * phi - 2.0 / 3.0 * phi * phi * phi * (1.0 + phi)) / (d * d * d);
}
static double dz_kolafa(const rs_hs *g, double phi)
{
    (void)g;
    const double d = 1.0 - phi, p2 = phi * phi;
    const double num = 1.0 + phi + p2 - 2.0 / 3.0 * p2 * phi * (1.0 + phi);
    const double dnum = 1.0 + 2.0 * phi - 2.0 * p2 - 8.0 / 3.0 * p2 * phi;
    return dnum / (d * d * d) + 3.0 * num / (d * d * d * d);
}
/* (Z - 1)/phi = (4 - 2 phi + phi^2/3 - 2/3 phi^3)/(1 - phi)^3, free of Z - 1's cancellation */
static double zm1p_kolafa(const rs_hs *g, double phi)
{
    (void)g;
    const double d = 1.0 - phi;
    return (4.0 - 2.0 * phi + phi * phi / 3.0 - 2.0 / 3.0 * phi * phi * phi) / (d * d * d);
}
static double zm1p_const(const rs_hs *g, double phi) { return (g->z0 - 1.0) / phi; }
static double z_const(const rs_hs *g, double phi) { (void)phi; return g->z0; }
static double dz_const(const rs_hs *g, double phi) { (void)g, (void)phi; return 0.0; }

rs_hs rs_hs_kolafa(double vball) { return (rs_hs){z_kolafa, dz_kolafa, zm1p_kolafa, vball, 1.0}; }
rs_hs rs_hs_constz(double vball, double z0) { return (rs_hs){z_const, dz_const, zm1p_const, vball, z0}; }

typedef struct {
    const rs_hs *g;
    double n, T;  /* the side's state (the isentrope's anchor) */
    double p;     /* a target pressure */
} side;

static double zm1_over_phi(double phi, void *v)
{
    const rs_hs *g = v;
    return g->zm1p(g, phi);
}

/* int_(phi_a)^(phi_b) (Z - 1)/phi dphi (GSL QAG; 0 if equal) */
static int excess(const rs_hs *g, double pa, double pb, double *out)
{
    *out = 0.0;
    if (pa == pb)
        return 0;
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(200);
    if (!w)
        return RS_ENOCONV;
    gsl_function f = {zm1_over_phi, (void *)g};
    double err;
    int rc = gsl_integration_qag(&f, pa, pb, 0.0, 1e-13, 200, GSL_INTEG_GAUSS41, w, out, &err);
    gsl_integration_workspace_free(w);
    return rc ? RS_ENOCONV : 0;
}

/* the temperature on side s's isentrope at density n */
static double isen_T(const side *s, double n)
{
    double a;
    if (excess(s->g, s->n * s->g->vball, n * s->g->vball, &a))
        return NAN;
    return s->T * pow(n / s->n, 2.0 / 3.0) * exp(2.0 / 3.0 * a);
}

double rs_hs_cs2(const rs_hs *g, double n, double T)
{
    const double phi = n * g->vball, z = g->z(g, phi);
    return T * (z + phi * g->dz(g, phi) + 2.0 / 3.0 * z * z);
}

static double isen_p_gap(double lnn, void *v)
{
    const side *s = v;
    const double n = exp(lnn), T = isen_T(s, n);
    return log(n * T * s->g->z(s->g, n * s->g->vball)) - log(s->p);
}

static double cs_dlnn(double lnn, void *v)
{
    const side *s = v;
    const double n = exp(lnn);
    return sqrt(rs_hs_cs2(s->g, n, isen_T(s, n)));
}

/* the Hugoniot from (n_a, T_a, p_a) to pressure s->p, as a function of ln n_b */
static double hugoniot(double lnn, void *v)
{
    const side *s = v;
    const double nb = exp(lnn), pa = s->n * s->T * s->g->z(s->g, s->n * s->g->vball);
    const double Tb = s->p / (nb * s->g->z(s->g, nb * s->g->vball));
    return 1.5 * (Tb - s->T) - 0.5 * (pa + s->p) * (1.0 / s->n - 1.0 / nb);
}

/* Toro's f_K(p) for side K and the density behind its wave */
static int wave(const rs_hs *g, double nK, double TK, double p, double *f, double *nstar)
{
    side s = {g, nK, TK, p};
    const double pK = nK * TK * g->z(g, nK * g->vball);
    if (p > pK) {
        /* the post-shock density lies between n_K and close packing (Z -> inf) */
        const double hi = log(fmin(0.999 / g->vball, nK * 1e6));
        double lnb;
        int rc = rs_brent_(hugoniot, &s, log(nK), hi, &lnb);
        if (rc)
            return rc;
        *nstar = exp(lnb);
        *f = sqrt((p - pK) * (1.0 / nK - 1.0 / *nstar));
        return 0;
    }
    double lnn = log(nK);
    if (p < pK) {
        int rc = rs_brent_(isen_p_gap, &s, log(nK) - 60.0, log(nK), &lnn);
        if (rc)
            return rc;
    }
    *nstar = exp(lnn);
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(200);
    if (!w)
        return RS_ENOCONV;
    gsl_function fn = {cs_dlnn, &s};
    double I = 0.0, err;
    int rc = lnn < log(nK) ? gsl_integration_qag(&fn, lnn, log(nK), 0.0, 1e-12, 200,
                                                 GSL_INTEG_GAUSS41, w, &I, &err)
                           : 0;
    gsl_integration_workspace_free(w);
    *f = -I;
    return rc ? RS_ENOCONV : 0;
}

typedef struct {
    const rs_hs *g;
    double nL, TL, nR, TR, dv;
} star;

static double star_fn(double lnp, void *v)
{
    const star *q = v;
    double fl, fr, n;
    if (wave(q->g, q->nL, q->TL, exp(lnp), &fl, &n) || wave(q->g, q->nR, q->TR, exp(lnp), &fr, &n))
        return NAN;
    return fl + fr + q->dv;
}

int rs_hs_solve(const rs_hs *g, rs_state L, rs_state R, rs_hs_solution *sol)
{
    const rs_state st[2] = {L, R};
    for (int k = 0; k < 2; k++)
        if (!(st[k].rho > 0.0) || !(st[k].p > 0.0) || !isfinite(st[k].v) ||
            !(st[k].rho * g->vball < 0.7)) /* beyond phi 0.7: no fluid (Z's pole at 1) */
            return RS_EINVAL;
    star q = {g, L.rho, 0.0, R.rho, 0.0, R.v - L.v};
    q.TL = L.p / (L.rho * g->z(g, L.rho * g->vball));
    q.TR = R.p / (R.rho * g->z(g, R.rho * g->vball));
    const double lo = log(fmin(L.p, R.p)) - 40.0, hi = log(fmax(L.p, R.p)) + 20.0;
    if (!(star_fn(lo, &q) < 0.0))
        return RS_EVACUUM;
    double lnp;
    int rc = rs_brent_(star_fn, &q, lo, hi, &lnp);
    if (rc)
        return rc;
    const double p = exp(lnp);
    double fl, fr;
    if ((rc = wave(g, L.rho, q.TL, p, &fl, &sol->rho_starL)) ||
        (rc = wave(g, R.rho, q.TR, p, &fr, &sol->rho_starR)))
        return rc;
    sol->p_star = p;
    sol->v_star = 0.5 * (L.v + R.v) + 0.5 * (fr - fl);
    sol->T_starL = p / (sol->rho_starL * g->z(g, sol->rho_starL * g->vball));
    sol->T_starR = p / (sol->rho_starR * g->z(g, sol->rho_starR * g->vball));
    sol->waveL = p > L.p ? RS_SHOCK : RS_RAREFACTION;
    sol->waveR = p > R.p ? RS_SHOCK : RS_RAREFACTION;
    if (sol->waveL == RS_SHOCK)
        sol->headL = sol->tailL = L.v - sqrt((p - L.p) / (1.0 / L.rho - 1.0 / sol->rho_starL)) / L.rho;
    else
        sol->headL = L.v - sqrt(rs_hs_cs2(g, L.rho, q.TL)),
        sol->tailL = sol->v_star - sqrt(rs_hs_cs2(g, sol->rho_starL, sol->T_starL));
    if (sol->waveR == RS_SHOCK)
        sol->headR = sol->tailR = R.v + sqrt((p - R.p) / (1.0 / R.rho - 1.0 / sol->rho_starR)) / R.rho;
    else
        sol->headR = R.v + sqrt(rs_hs_cs2(g, R.rho, q.TR)),
        sol->tailR = sol->v_star + sqrt(rs_hs_cs2(g, sol->rho_starR, sol->T_starR));
    return RS_OK;
}
