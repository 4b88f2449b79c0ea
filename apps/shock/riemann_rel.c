/* riemann_rel.c — the exact relativistic Riemann solution (c = 1) for an ideal gas
 * p = rho theta with any h(theta) (rs_eos), after Marti & Mueller (J. Fluid Mech. 258,
 * 317, 1994), zero tangential velocity (papers/shock-tube.md, section 3):
 *  - a rarefaction is isentropic: d ln rho = (h' - 1) d ln theta, and carries the Riemann
 *    invariant atanh v +- Int c_s d ln rho: both integrals by quadrature in s = ln theta;
 *  - a shock obeys the Taub adiabat h_b^2 - h_a^2 = (h_b/rho_b + h_a/rho_a)(p_b - p_a)
 *    (a root in theta_b), and its states move apart at
 *    v_rel^2 = (p_b - p_a)(e_b - e_a)/((e_a + p_b)(e_b + p_a)); its speed conserves the
 *    particle flux, V = [rho W v]/[rho W];
 *  - the plateau: p and v continuous at the contact, the root of v_L*(p) - v_R*(p). */
#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "riemann.h"
#include "riemann_private.h"

#define RS_QUAD_INTERVALS 256

typedef struct {
    const rs_eos *e;
    int with_cs; /* 0: h' - 1 (ln rho); 1: c_s (h' - 1) (rapidity) */
} isen_prm;

static double isen_integrand(double s, void *v)
{
    const isen_prm *q = v;
    const double th = exp(s);
    const double d = q->e->ops->dh(q->e, th) - 1.0;
    return q->with_cs ? sqrt(rs_eos_cs2(q->e, th)) * d : d;
}

/* Int_{s0}^{s1} of the isentrope's integrand (1: with c_s) */
static int isen_int(const rs_eos *e, int with_cs, double s0, double s1, double *out)
{
    if (s0 == s1) {
        *out = 0.0;
        return RS_OK;
    }
    isen_prm q = {e, with_cs};
    if (fabs(s1 - s0) < 1e-6) { /* Simpson: error ~ (s1 - s0)^5, below round-off here */
        *out = (s1 - s0) / 6.0 * (isen_integrand(s0, &q) + 4.0 * isen_integrand(0.5 * (s0 + s1), &q) +
                                  isen_integrand(s1, &q));
        return RS_OK;
    }
    gsl_function F = {isen_integrand, &q};
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(RS_QUAD_INTERVALS);
    if (!w)
        return RS_ENOCONV;
    double r, err;
    int st = gsl_integration_qag(&F, s0, s1, 0.0, 1e-13, RS_QUAD_INTERVALS, GSL_INTEG_GAUSS41,
                                 w, &r, &err);
    gsl_integration_workspace_free(w);
    *out = r;
    /* GSL_EROUND: the target is below the integrand's own round-off (an equation of state
     * switching between two forms that agree to 1e-12 inside the interval); the error
     * estimate says how far it got */
    if (st == GSL_EROUND && err <= 1e-11 * fabs(r))
        st = GSL_SUCCESS;
    return st == GSL_SUCCESS ? RS_OK : RS_ENOCONV;
}

/* rest-mass density at s = ln theta on the isentrope through state a */
static int isen_rho(const rs_eos *e, rs_state a, double s, double *rho)
{
    double I;
    int rc = isen_int(e, 0, log(a.p / a.rho), s, &I);
    *rho = a.rho * exp(I);
    return rc;
}

typedef struct {
    const rs_eos *e;
    rs_state a;
    double lnp;
} pth_prm;

static double pth_fn(double s, void *v)
{
    const pth_prm *q = v;
    double rho;
    if (isen_rho(q->e, q->a, s, &rho))
        return NAN;
    return log(rho) + s - q->lnp;
}

/* the isentrope's theta at pressure p <= a.p (d ln p / d ln theta = h' >= 1 brackets it) */
static int isen_theta_at_p(const rs_eos *e, rs_state a, double p, double *s)
{
    const double sa = log(a.p / a.rho);
    if (p == a.p) {
        *s = sa;
        return RS_OK;
    }
    pth_prm q = {e, a, log(p)};
    return rs_brent_(pth_fn, &q, sa + log(p / a.p) - 1e-12, sa + 1e-12, s);
}

typedef struct {
    const rs_eos *e;
    rs_state a;
    double pb;
} taub_prm;

/* Taub adiabat as a function of ln theta_b, written in h - 1 (no cancellation as theta->0) */
static double taub_fn(double s, void *v)
{
    const taub_prm *q = v;
    const double th = exp(s);
    const double ga = q->e->ops->hm1(q->e, q->a.p / q->a.rho), gb = q->e->ops->hm1(q->e, th);
    const double rhob = q->pb / th;
    return (gb - ga) * (2.0 + ga + gb) - ((1.0 + gb) / rhob + (1.0 + ga) / q->a.rho) * (q->pb - q->a.p);
}

int rs_rel_shock(const rs_eos *e, rs_state a, double pb, double *rhob, double *vrel)
{
    const double sa = log(a.p / a.rho);
    taub_prm q = {e, a, pb};
    double hi = sa + 1.0;
    while (taub_fn(hi, &q) < 0.0 && hi < 700.0)
        hi += 1.0;
    double s;
    /* below theta_a the adiabat is negative (h_b < h_a); theta_a itself may round either
     * way when pb is a round-off above pa */
    int rc = rs_brent_(taub_fn, &q, sa - 1e-6, hi, &s);
    if (rc)
        return rc;
    const double th = exp(s);
    *rhob = pb / th;
    const double ea = a.rho * (1.0 + e->ops->hm1(e, a.p / a.rho)) - a.p;
    const double eb = *rhob * (1.0 + e->ops->hm1(e, th)) - pb;
    /* a pressure a round-off above pa can round eb below ea: the weak shock's v_rel is 0 */
    *vrel = sqrt(fmax(0.0, (pb - a.p) * (eb - ea)) / ((ea + pb) * (eb + a.p)));
    return RS_OK;
}

/* the velocity behind side k's wave at pressure p (sign -1 left, +1 right); rho behind */
static int rel_wave(const rs_eos *e, rs_state k, int sign, double p, double *v, double *rho)
{
    if (p > k.p) {
        double vr;
        int rc = rs_rel_shock(e, k, p, rho, &vr);
        if (rc)
            return rc;
        *v = (k.v + sign * vr) / (1.0 + sign * k.v * vr);
        return RS_OK;
    }
    double s, dphi;
    int rc = isen_theta_at_p(e, k, p, &s);
    if (!rc)
        rc = isen_int(e, 1, s, log(k.p / k.rho), &dphi);
    if (rc)
        return rc;
    *rho = p / exp(s);
    *v = tanh(atanh(k.v) - sign * dphi);
    return RS_OK;
}

typedef struct {
    const rs_eos *e;
    rs_state L, R;
    int fail;
} rel_prm;

static double rel_root_fn(double lnp, void *v)
{
    rel_prm *q = v;
    const double p = exp(lnp);
    double vl, vr, rl, rr;
    if (rel_wave(q->e, q->L, -1, p, &vl, &rl) || rel_wave(q->e, q->R, +1, p, &vr, &rr)) {
        q->fail = 1;
        return NAN;
    }
    return vl - vr;
}

static int state_ok(rs_state s)
{
    return s.rho > 0.0 && isfinite(s.rho) && s.p > 0.0 && isfinite(s.p) && fabs(s.v) < 1.0;
}

static double sig_speed(double v, double cs, int sign)
{
    return (v + sign * cs) / (1.0 + sign * v * cs);
}

int rs_rel_solve(const rs_eos *e, rs_state L, rs_state R, rs_solution *sol)
{
    if (!state_ok(L) || !state_ok(R))
        return RS_EINVAL;
    rel_prm q = {e, L, R, 0};
    double lo = log(fmin(L.p, R.p)) - 1.0, hi = log(fmax(L.p, R.p));
    while (rel_root_fn(lo, &q) < 0.0 && lo > -60.0)
        lo -= 5.0;
    if (rel_root_fn(lo, &q) < 0.0)
        return q.fail ? RS_ENOCONV : RS_EVACUUM;
    while (rel_root_fn(hi, &q) > 0.0 && hi < 700.0)
        hi += 1.0;
    if (q.fail)
        return RS_ENOCONV;
    double lnp;
    int rc = rs_brent_(rel_root_fn, &q, lo, hi, &lnp);
    if (rc || q.fail)
        return rc ? rc : RS_ENOCONV;
    const double p = exp(lnp);
    double vl, vr;
    if ((rc = rel_wave(e, L, -1, p, &vl, &sol->rho_starL)) ||
        (rc = rel_wave(e, R, +1, p, &vr, &sol->rho_starR)))
        return rc;
    sol->L = L;
    sol->R = R;
    sol->c = 1.0;
    sol->eos = *e;
    sol->p_star = p;
    sol->v_star = 0.5 * (vl + vr);
    const double v = sol->v_star;
    for (int side = 0; side < 2; side++) {
        const rs_state k = side ? R : L;
        const int sign = side ? 1 : -1;
        const double rhos = side ? sol->rho_starR : sol->rho_starL;
        double head, tail;
        int wave;
        if (p > k.p) {
            const double Dk = k.rho / sqrt(1.0 - k.v * k.v), Ds = rhos / sqrt(1.0 - v * v);
            wave = RS_SHOCK;
            head = tail = (Ds * v - Dk * k.v) / (Ds - Dk);
        } else {
            wave = RS_RAREFACTION;
            head = sig_speed(k.v, sqrt(rs_eos_cs2(e, k.p / k.rho)), sign);
            tail = sig_speed(v, sqrt(rs_eos_cs2(e, p / rhos)), sign);
        }
        if (side) {
            sol->waveR = wave, sol->headR = head, sol->tailR = tail;
        } else {
            sol->waveL = wave, sol->headL = head, sol->tailL = tail;
        }
    }
    return RS_OK;
}

typedef struct {
    const rs_eos *e;
    rs_state a;
    int sign;
    double xi;
    int fail;
} fan_prm;

/* inside side a's fan at s = ln theta: the state and its characteristic's xi */
static int fan_state(const rs_eos *e, rs_state a, int sign, double s, rs_state *out, double *xi)
{
    double rho, dphi;
    int rc = isen_rho(e, a, s, &rho);
    if (!rc)
        rc = isen_int(e, 1, s, log(a.p / a.rho), &dphi);
    if (rc)
        return rc;
    out->rho = rho;
    out->p = rho * exp(s);
    out->v = tanh(atanh(a.v) - sign * dphi);
    *xi = sig_speed(out->v, sqrt(rs_eos_cs2(e, exp(s))), sign);
    return RS_OK;
}

static double fan_fn(double s, void *v)
{
    fan_prm *q = v;
    rs_state st;
    double xi;
    if (fan_state(q->e, q->a, q->sign, s, &st, &xi)) {
        q->fail = 1;
        return NAN;
    }
    return xi - q->xi;
}

int rs_rel_sample(const rs_solution *s, double xi, rs_state *out)
{
    const int right = xi > s->v_star;
    const rs_state a = right ? s->R : s->L;
    const double head = right ? s->headR : s->headL, tail = right ? s->tailR : s->tailL;
    const double rhos = right ? s->rho_starR : s->rho_starL;
    const int sign = right ? 1 : -1;
    if (right ? xi >= head : xi <= head) {
        *out = a;
        return RS_OK;
    }
    if (right ? xi <= tail : xi >= tail) {
        out->rho = rhos, out->v = s->v_star, out->p = s->p_star;
        return RS_OK;
    }
    fan_prm q = {&s->eos, a, sign, xi, 0};
    double th;
    int rc = rs_brent_(fan_fn, &q, log(s->p_star / rhos), log(a.p / a.rho), &th);
    if (rc || q.fail)
        return rc ? rc : RS_ENOCONV;
    double x;
    return fan_state(&s->eos, a, sign, th, out, &x);
}
