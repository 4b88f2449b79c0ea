/* gravity_gas.h — a dilute gas in a uniform field without ball-ball collisions, shared by
 * test_gravity_equilibrium and notebook 09: balls drawn from the equilibrium exp(-H/kT0)
 * of papers/gravity.md section 5 (m = 1, k = 1, box height H_BOX, kT = KT0 at the floor in the table's units, so that
 * theta0 = KT0/c^2), moved
 * by a coupling's drift and plane times between an elastic floor and ceiling, and the
 * profiles it predicts (density, local temperature). */
#ifndef GRAVITY_GAS_H
#define GRAVITY_GAS_H

#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>

#include "gravity_util.h"

enum { NB = 10, NBALL = 20000 };
static const double H_BOX = 1.0, KT0 = 1.0; /* m = 1, k = 1: kT in units of m (length/time)^2 */

typedef struct model {
    const rc_gravity_coupling *cp;
    rc_gravity f;
    int equivalence;
} model;

/* the local kT(z): Tolman's KT0/(1 + g z/c^2) for equivalence, KT0 for newtonian */
static double theta_at(const model *md, double z)
{
    return md->equivalence ? KT0 / (1.0 + md->f.g * z * md->f.inv_c2) : KT0;
}

/* the density n(z) up to a constant: the momentum integral of exp(-H/kT0) */
static double density_at(double z, void *par)
{
    const model *md = par;
    if (md->f.inv_c2 == 0.0 || !md->equivalence)
        return exp(-md->f.g * z / KT0); /* m g z / kT0, m = 1 */
    const double th = theta_at(md, z) * md->f.inv_c2, th0 = KT0 * md->f.inv_c2;
    /* theta K2(1/theta) with theta = kT/(m c^2), scaled by exp(1/theta0) to stay finite */
    return th * gsl_sf_bessel_Kn_scaled(2, 1.0 / th) * exp(-1.0 / th + 1.0 / th0);
}

static double density_theta(double z, void *par) { return density_at(z, par) * theta_at(par, z); }

static double integral(double (*fn)(double, void *), const model *md, double a, double b)
{
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(200);
    gsl_function F = {fn, (void *)md};
    double r, err;
    gsl_integration_qag(&F, a, b, 0, 1e-12, 200, GSL_INTEG_GAUSS41, w, &r, &err);
    gsl_integration_workspace_free(w);
    return r;
}

/* |p|/(m c) from u^2 exp(-sqrt(1 + u^2)/theta) by rejection. theta >= 0.4: a Gamma(3, theta)
 * proposal in u, accepted with exp(-(sqrt(1 + u^2) - u)/theta) (at least exp(-2.5)). theta
 * < 0.4 (the proposal's scale below 1): in the kinetic energy k = gamma - 1 the density is (1 + k) sqrt(k (k + 2)) e^(-k/theta)
 * <= sqrt(2 k) e^(3k/2) e^(-k/theta), a Gamma(3/2, 1/(1/theta - 3/2)) proposal accepted with
 * (1 + k) sqrt(k + 2) / (sqrt 2 e^(3k/2)) <= 1, near 1 for a cold gas. */
static double juttner_u(rc_test_rng *r, double th)
{
    for (;;) {
        if (th >= 0.4) {
            const double u = -th * log((1.0 - rc_test_uniform(r)) * (1.0 - rc_test_uniform(r)) *
                                       (1.0 - rc_test_uniform(r)));
            if (rc_test_uniform(r) < exp(-1.0 / (sqrt(1.0 + u * u) + u) / th))
                return u;
        } else {
            const double u1 = 1.0 - rc_test_uniform(r), u2 = rc_test_uniform(r);
            const double gauss = sqrt(-2.0 * log(u1)) * cos(2.0 * M_PI * u2);
            const double e = -log(1.0 - rc_test_uniform(r));
            const double k = (e + 0.5 * gauss * gauss) / (1.0 / th - 1.5);
            if (rc_test_uniform(r) * sqrt(2.0) * exp(1.5 * k) < (1.0 + k) * sqrt(k + 2.0))
                return sqrt(k * (k + 2.0));
        }
    }
}

static rc_vec3 iso(rc_test_rng *r, double len)
{
    const double cz = rc_test_range(r, -1, 1), ph = rc_test_range(r, 0, 2 * M_PI);
    const double s = sqrt(1 - cz * cz);
    return rc_v3(len * s * cos(ph), len * s * sin(ph), len * cz);
}

static void draw(const model *md, rc_test_rng *r, rc_vec3 *x, rc_vec3 *p)
{
    const double top = density_at(0.0, (void *)md); /* n falls with height */
    double z;
    do
        z = rc_test_range(r, 0, H_BOX);
    while (rc_test_uniform(r) * top > density_at(z, (void *)md));
    *x = rc_v3(rc_test_range(r, 0, 1), rc_test_range(r, 0, 1), z);
    const double th = theta_at(md, z);
    if (md->f.inv_c2 == 0.0) { /* Maxwell at kT = th */
        const double s = sqrt(th);
        double q[3];
        for (int k = 0; k < 3; k++) { /* Box-Muller */
            const double u1 = 1.0 - rc_test_uniform(r), u2 = rc_test_uniform(r);
            q[k] = s * sqrt(-2 * log(u1)) * cos(2 * M_PI * u2);
        }
        *p = rc_v3(q[0], q[1], q[2]);
    } else /* |p| = u m c */
        *p = iso(r, juttner_u(r, th * md->f.inv_c2) / sqrt(md->f.inv_c2));
}

/* free flight for tau between the elastic floor z = 0 and ceiling z = H_BOX */
static int fly(const model *md, rc_vec3 *x, rc_vec3 *p, double tau, long *bounces)
{
    while (tau > 0.0) {
        double t0 = INFINITY, t1 = INFINITY;
        if (md->cp->plane_time(&md->f, 1.0, *x, *p, 2, 0.0, &t0) != RC_OK)
            t0 = INFINITY;
        if (md->cp->plane_time(&md->f, 1.0, *x, *p, 2, H_BOX, &t1) != RC_OK)
            t1 = INFINITY;
        const double t = fmin(t0, t1);
        if (!(t < tau))
            return md->cp->drift(&md->f, 1.0, x, p, tau);
        if (md->cp->drift(&md->f, 1.0, x, p, t) != RC_OK)
            return RC_EINVAL;
        /* the wall is at rest in the box's momentary frame: reflect, on the wall exactly */
        x->z = t0 < t1 ? 0.0 : H_BOX;
        p->z = t0 < t1 ? fabs(p->z) : -fabs(p->z);
        tau -= t;
        (*bounces)++;
    }
    return RC_OK;
}

/* One run: nball balls drawn and flown for tau, binned by height at the end: counts, the
 * p.v thermometer (<p.v> = 3 kT for Juttner and Maxwell) and the same times the lapse
 * 1 + g z/c^2 (equivalence; 1 for newtonian), with the predicted counts and bin averages
 * of theta beside them. */
typedef struct grav_profile {
    long cnt[NB], bounces, nball, bad;
    double theta[NB], theta_var[NB]; /* bin mean of p.v/3 and the variance of that mean */
    double lapse_theta[NB], lapse_var[NB], z[NB];
    double expect_n[NB], expect_theta[NB];
} grav_profile;

static void grav_measure(const model *md, uint64_t seed, int nball, double tau, grav_profile *pr)
{
    rc_test_rng r = {seed};
    double s1[NB] = {0}, s2[NB] = {0}, l1[NB] = {0}, l2[NB] = {0};
    memset(pr, 0, sizeof *pr);
    pr->nball = nball;
    for (int i = 0; i < nball; i++) {
        rc_vec3 x, p;
        draw(md, &r, &x, &p);
        const int b = fly(md, &x, &p, tau, &pr->bounces) == RC_OK ? (int)(x.z / H_BOX * NB) : -1;
        if (b < 0 || b >= NB) {
            pr->bad++;
            continue;
        }
        const double pv = rc_v3_dot(p, p) / rc_mass_rel(1.0, p, md->f.inv_c2) / 3.0;
        const double lp = pv * (md->equivalence ? 1.0 + md->f.g * x.z * md->f.inv_c2 : 1.0);
        pr->cnt[b]++;
        s1[b] += pv, s2[b] += pv * pv, l1[b] += lp, l2[b] += lp * lp, pr->z[b] += x.z;
    }
    const double norm = integral(density_at, md, 0, H_BOX);
    for (int b = 0; b < NB; b++) {
        const double lo = H_BOX * b / NB, hi = H_BOX * (b + 1) / NB, n = (double)pr->cnt[b];
        const double nb = integral(density_at, md, lo, hi);
        pr->expect_n[b] = nball * nb / norm;
        pr->expect_theta[b] = integral(density_theta, md, lo, hi) / nb;
        pr->theta[b] = s1[b] / n;
        pr->theta_var[b] = (s2[b] / n - pr->theta[b] * pr->theta[b]) / n;
        pr->lapse_theta[b] = l1[b] / n;
        pr->lapse_var[b] = (l2[b] / n - pr->lapse_theta[b] * pr->lapse_theta[b]) / n;
        pr->z[b] /= n;
    }
}

/* the weighted least-squares slope of y(z) over the bins, and its standard error */
static void grav_slope(const double *z, const double *y, const double *var, double *slope,
                       double *err)
{
    double sw = 0, swz = 0, swzz = 0, swy = 0, swzy = 0;
    for (int b = 0; b < NB; b++) {
        const double w = 1.0 / var[b];
        sw += w, swz += w * z[b], swzz += w * z[b] * z[b], swy += w * y[b], swzy += w * z[b] * y[b];
    }
    const double det = sw * swzz - swz * swz;
    *slope = (sw * swzy - swz * swy) / det;
    *err = sqrt(sw / det);
}

#endif
