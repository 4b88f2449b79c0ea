/* riemann_euler.c — the exact Riemann solution of the Euler equations of the ideal gas
 * (adiabatic index gamma), Toro's method: the star pressure is the root of
 * f_L(p) + f_R(p) + (v_R - v_L), each f_K the velocity change across a shock (the
 * Rankine-Hugoniot curve) or a rarefaction (the Riemann invariant) from state K to p,
 * found here by Brent's method in ln p; the solution is then sampled at xi = x/t
 * (papers/shock-tube.md, section 2). */
#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "riemann.h"
#include "riemann_private.h"

typedef struct {
    double g;
    rs_state L, R;
} eu_prm;

static double sound(double g, rs_state s) { return sqrt(g * s.p / s.rho); }

/* velocity change from state k to pressure p across its wave (> 0 for a shock) */
static double eu_f(double g, rs_state k, double p)
{
    if (p > k.p) {
        const double A = 2.0 / ((g + 1.0) * k.rho), B = (g - 1.0) / (g + 1.0) * k.p;
        return (p - k.p) * sqrt(A / (p + B));
    }
    const double a = sound(g, k);
    /* (p/pk)^((g-1)/(2g)) - 1 written with expm1 so that p -> pk keeps its digits */
    return 2.0 * a / (g - 1.0) * expm1((g - 1.0) / (2.0 * g) * log(p / k.p));
}

static double eu_root_fn(double lnp, void *v)
{
    const eu_prm *q = v;
    const double p = exp(lnp);
    return eu_f(q->g, q->L, p) + eu_f(q->g, q->R, p) + (q->R.v - q->L.v);
}

/* the root of fn in [lo, hi] (a sign change) to 1e-14 relative, 1e-15 absolute (a few
 * round-offs of the quadratures inside fn: a tighter interval would never close) */
int rs_brent_(double (*fn)(double, void *), void *prm, double lo, double hi, double *root)
{
    gsl_function F = {fn, prm};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s)
        return RS_ENOCONV;
    if (gsl_root_fsolver_set(s, &F, lo, hi) != GSL_SUCCESS) {
        gsl_root_fsolver_free(s);
        return RS_ENOCONV;
    }
    int status = GSL_CONTINUE;
    for (int it = 0; it < 300 && status == GSL_CONTINUE; it++) {
        if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS)
            break;
        status = gsl_root_test_interval(gsl_root_fsolver_x_lower(s),
                                        gsl_root_fsolver_x_upper(s), 1e-15, 1e-14);
    }
    *root = gsl_root_fsolver_root(s);
    gsl_root_fsolver_free(s);
    return status == GSL_SUCCESS ? RS_OK : RS_ENOCONV;
}

static int state_ok(rs_state s, double vmax)
{
    return s.rho > 0.0 && isfinite(s.rho) && s.p > 0.0 && isfinite(s.p) && isfinite(s.v) &&
           fabs(s.v) < vmax;
}

int rs_euler_solve(double g, rs_state L, rs_state R, rs_solution *sol)
{
    if (!(g > 1.0) || !state_ok(L, INFINITY) || !state_ok(R, INFINITY))
        return RS_EINVAL;
    const double aL = sound(g, L), aR = sound(g, R);
    /* vacuum generation: the rarefactions' full velocity range does not close the gap */
    if (2.0 * (aL + aR) / (g - 1.0) <= R.v - L.v)
        return RS_EVACUUM;
    eu_prm q = {g, L, R};
    double lo = log(fmin(L.p, R.p)) - 1.0, hi = log(fmax(L.p, R.p));
    while (eu_root_fn(lo, &q) > 0.0 && lo > -700.0)
        lo -= 10.0;
    while (eu_root_fn(hi, &q) < 0.0 && hi < 700.0)
        hi += 2.0;
    double lnp;
    int rc = rs_brent_(eu_root_fn, &q, lo, hi, &lnp);
    if (rc)
        return rc;
    const double p = exp(lnp);
    sol->L = L;
    sol->R = R;
    sol->c = INFINITY;
    sol->eos = rs_eos_ideal(g);
    sol->p_star = p;
    sol->v_star = 0.5 * (L.v + R.v) + 0.5 * (eu_f(g, R, p) - eu_f(g, L, p));
    const double gr = (g - 1.0) / (g + 1.0);
    if (p > L.p) {
        sol->waveL = RS_SHOCK;
        sol->rho_starL = L.rho * (p / L.p + gr) / (gr * p / L.p + 1.0);
        sol->headL = sol->tailL = L.v - aL * sqrt((g + 1.0) / (2.0 * g) * p / L.p +
                                                  (g - 1.0) / (2.0 * g));
    } else {
        sol->waveL = RS_RAREFACTION;
        sol->rho_starL = L.rho * pow(p / L.p, 1.0 / g);
        sol->headL = L.v - aL;
        sol->tailL = sol->v_star - aL * pow(p / L.p, (g - 1.0) / (2.0 * g));
    }
    if (p > R.p) {
        sol->waveR = RS_SHOCK;
        sol->rho_starR = R.rho * (p / R.p + gr) / (gr * p / R.p + 1.0);
        sol->headR = sol->tailR = R.v + aR * sqrt((g + 1.0) / (2.0 * g) * p / R.p +
                                                  (g - 1.0) / (2.0 * g));
    } else {
        sol->waveR = RS_RAREFACTION;
        sol->rho_starR = R.rho * pow(p / R.p, 1.0 / g);
        sol->headR = R.v + aR;
        sol->tailR = sol->v_star + aR * pow(p / R.p, (g - 1.0) / (2.0 * g));
    }
    return RS_OK;
}

int rs_euler_sample(const rs_solution *s, double xi, rs_state *out)
{
    const double g = s->eos.gamma;
    const double gm = (g - 1.0) / (g + 1.0);
    if (xi <= s->v_star) {
        const rs_state L = s->L;
        const double aL = sound(g, L);
        if (xi <= s->headL) {
            *out = L;
        } else if (xi >= s->tailL) {
            out->rho = s->rho_starL, out->v = s->v_star, out->p = s->p_star;
        } else { /* inside the left fan: the characteristic xi = v - a through the origin */
            const double f = 2.0 / (g + 1.0) + gm / aL * (L.v - xi);
            out->rho = L.rho * pow(f, 2.0 / (g - 1.0));
            out->v = 2.0 / (g + 1.0) * (aL + 0.5 * (g - 1.0) * L.v + xi);
            out->p = L.p * pow(f, 2.0 * g / (g - 1.0));
        }
    } else {
        const rs_state R = s->R;
        const double aR = sound(g, R);
        if (xi >= s->headR) {
            *out = R;
        } else if (xi <= s->tailR) {
            out->rho = s->rho_starR, out->v = s->v_star, out->p = s->p_star;
        } else {
            const double f = 2.0 / (g + 1.0) - gm / aR * (R.v - xi);
            out->rho = R.rho * pow(f, 2.0 / (g - 1.0));
            out->v = 2.0 / (g + 1.0) * (-aR + 0.5 * (g - 1.0) * R.v + xi);
            out->p = R.p * pow(f, 2.0 * g / (g - 1.0));
        }
    }
    return RS_OK;
}
