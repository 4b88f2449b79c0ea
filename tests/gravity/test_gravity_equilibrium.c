/* test_gravity_equilibrium — each coupling's dilute equilibrium (papers/gravity.md section
 * 5) is stationary under its own dynamics: balls drawn from exp(-H/kT0) between an elastic
 * floor and ceiling, moved by the coupling's drift and plane times for several bounce
 * times, still have the predicted profiles (chi^2 p-values). equivalence: local Juttner at
 * theta(z) = theta0/(1 + g z/c^2) (Tolman-Ehrenfest), n(z) ~ theta K2(1/theta); theta(z)
 * itself falls with height by many standard errors while theta(z)(1 + g z/c^2) stays
 * theta0. newtonian: uniform theta0 and n(z) ~ exp(-m g z/kT0) at any c. No ball-ball
 * collisions: this checks the paths and walls, not the collision rules. */
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>

#include "gravity_util.h"

enum { NB = 10, NBALL = 20000 };
static const double H_BOX = 1.0, THETA0 = 1.0; /* m = 1, k = 1; c = 1 unless classical */

typedef struct model {
    const rc_gravity_coupling *cp;
    rc_gravity f;
    int equivalence;
} model;

/* the local temperature kT(z) / (m c^2) (c = 1 units; classically kT) */
static double theta_at(const model *md, double z)
{
    return md->equivalence ? THETA0 / (1.0 + md->f.g * z * md->f.inv_c2) : THETA0;
}

/* the density n(z) up to a constant: the momentum integral of exp(-H/kT0) */
static double density_at(double z, void *par)
{
    const model *md = par;
    if (md->f.inv_c2 == 0.0 || !md->equivalence)
        return exp(-md->f.g * z / THETA0); /* m g z / kT0, m = 1 */
    const double th = theta_at(md, z);
    /* theta K2(1/theta), scaled by exp(1/theta0) so that it stays finite */
    return th * gsl_sf_bessel_Kn_scaled(2, 1.0 / th) * exp(-1.0 / th + 1.0 / THETA0);
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

/* |p|/(m c) from u^2 exp(-sqrt(1 + u^2)/theta): a Gamma(3, theta) proposal, accepted with
 * exp(-(sqrt(1 + u^2) - u)/theta) */
static double juttner_u(rc_test_rng *r, double th)
{
    for (;;) {
        const double u = -th * log((1.0 - rc_test_uniform(r)) * (1.0 - rc_test_uniform(r)) *
                                   (1.0 - rc_test_uniform(r)));
        if (rc_test_uniform(r) < exp(-1.0 / (sqrt(1.0 + u * u) + u) / th))
            return u;
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
    } else
        *p = iso(r, juttner_u(r, th));
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

static void check(const model *md, uint64_t seed, int want_gradient)
{
    rc_test_rng r = {seed};
    long cnt[NB] = {0}, bounces = 0;
    double s1[NB] = {0}, s2[NB] = {0}, l1[NB] = {0}, l2[NB] = {0}, zs[NB] = {0};
    for (int i = 0; i < NBALL; i++) {
        rc_vec3 x, p;
        draw(md, &r, &x, &p);
        ENSURE(fly(md, &x, &p, 7.3, &bounces) == RC_OK);
        const int b = (int)(x.z / H_BOX * NB);
        ENSURE(b >= 0 && b < NB);
        if (b < 0 || b >= NB)
            continue;
        /* the p.v thermometer: <p.v> = 3 kT for Juttner (and Maxwell) */
        const double pv = rc_v3_dot(p, p) / rc_mass_rel(1.0, p, md->f.inv_c2) / 3.0;
        const double lp = pv * (md->equivalence ? 1.0 + md->f.g * x.z * md->f.inv_c2 : 1.0);
        cnt[b]++;
        s1[b] += pv, s2[b] += pv * pv, l1[b] += lp, l2[b] += lp * lp, zs[b] += x.z;
    }
    const double norm = integral(density_at, md, 0, H_BOX);
    double chi_n = 0, chi_t = 0, chi_l = 0;
    double sw = 0, swz = 0, swzz = 0, swt = 0, swzt = 0; /* weighted fit theta = a + b z */
    for (int b = 0; b < NB; b++) {
        const double lo = H_BOX * b / NB, hi = H_BOX * (b + 1) / NB;
        const double nb = integral(density_at, md, lo, hi);
        const double expect = NBALL * nb / norm;
        chi_n += (cnt[b] - expect) * (cnt[b] - expect) / expect;
        const double mt = s1[b] / cnt[b], vt = (s2[b] / cnt[b] - mt * mt) / cnt[b];
        const double tb = integral(density_theta, md, lo, hi) / nb;
        chi_t += (mt - tb) * (mt - tb) / vt;
        const double ml = l1[b] / cnt[b], vl = (l2[b] / cnt[b] - ml * ml) / cnt[b];
        chi_l += (ml - THETA0) * (ml - THETA0) / vl;
        const double z = zs[b] / cnt[b], w = 1.0 / vt;
        sw += w, swz += w * z, swzz += w * z * z, swt += w * mt, swzt += w * z * mt;
    }
    const double det = sw * swzz - swz * swz;
    const double slope = (sw * swzt - swz * swt) / det, slope_err = sqrt(sw / det);
    const double pn = gsl_cdf_chisq_Q(chi_n, NB - 1), pt = gsl_cdf_chisq_Q(chi_t, NB);
    const double pl = gsl_cdf_chisq_Q(chi_l, NB);
    printf("  %s c %g g %g: %ld bounces; n(z) p %.3f, theta(z) p %.3f, "
           "theta sqrt(g00) p %.3f, d theta/dz %.4f +- %.4f\n",
           md->cp->name, md->f.inv_c2 > 0 ? 1 / sqrt(md->f.inv_c2) : INFINITY, md->f.g,
           bounces, pn, pt, pl, slope, slope_err);
    ENSURE(bounces > 3 * NBALL); /* several crossings of the box per ball */
    ENSURE_MSG(pn > 1e-3, "density profile chi^2 %.1f for %d dof", chi_n, NB - 1);
    ENSURE_MSG(pt > 1e-3, "temperature profile chi^2 %.1f for %d dof", chi_t, NB);
    ENSURE_MSG(pl > 1e-3, "theta sqrt(g00) chi^2 %.1f for %d dof", chi_l, NB);
    if (want_gradient)
        ENSURE_MSG(slope < -5 * slope_err, "gradient %.4g +- %.4g", slope, slope_err);
    else
        ENSURE_MSG(fabs(slope) < 4 * slope_err, "gradient %.4g +- %.4g", slope, slope_err);
}

static void test_tolman(void)
{
    model md = {&rc_gravity_equivalence, {0.5, 2, 1.0}, 1};
    check(&md, 0x701, 1);
}

static void test_newtonian_uniform(void)
{
    model md = {&rc_gravity_newtonian, {0.5, 2, 1.0}, 0};
    check(&md, 0x702, 0);
}

static void test_classical_barometric(void)
{
    model md = {&rc_gravity_equivalence, {0.5, 2, 0.0}, 1};
    check(&md, 0x703, 0);
    model mn = {&rc_gravity_newtonian, {0.5, 2, 0.0}, 0};
    check(&mn, 0x704, 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    RUN_TEST(test_tolman);
    RUN_TEST(test_newtonian_uniform);
    RUN_TEST(test_classical_barometric);
    RC_TEST_MAIN_END();
}
