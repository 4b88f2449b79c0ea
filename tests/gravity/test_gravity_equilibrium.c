/* test_gravity_equilibrium — each coupling's dilute equilibrium (papers/gravity.md section
 * 5) is stationary under its own dynamics: balls drawn from exp(-H/kT0) between an elastic
 * floor and ceiling, moved by the coupling's drift and plane times for several bounce
 * times, still have the predicted profiles (chi^2 p-values). equivalence: local Juttner at
 * theta(z) = theta0/(1 + g z/c^2) (Tolman-Ehrenfest), n(z) ~ theta K2(1/theta); theta(z)
 * itself falls with height by many standard errors while theta(z)(1 + g z/c^2) stays
 * theta0. newtonian: uniform theta0 and n(z) ~ exp(-m g z/kT0) at any c. No ball-ball
 * collisions: this checks the paths and walls, not the collision rules. */
#include <gsl/gsl_cdf.h>

#include "gravity_gas.h"

static void check(const model *md, uint64_t seed, int want_gradient)
{
    grav_profile pr;
    grav_measure(md, seed, NBALL, 7.3, &pr);
    double chi_n = 0, chi_t = 0, chi_l = 0;
    for (int b = 0; b < NB; b++) {
        const double dn = pr.cnt[b] - pr.expect_n[b], dt = pr.theta[b] - pr.expect_theta[b];
        const double dl = pr.lapse_theta[b] - KT0;
        chi_n += dn * dn / pr.expect_n[b];
        chi_t += dt * dt / pr.theta_var[b];
        chi_l += dl * dl / pr.lapse_var[b];
    }
    double slope, slope_err;
    grav_slope(pr.z, pr.theta, pr.theta_var, &slope, &slope_err);
    const double pn = gsl_cdf_chisq_Q(chi_n, NB - 1), pt = gsl_cdf_chisq_Q(chi_t, NB);
    const double pl = gsl_cdf_chisq_Q(chi_l, NB);
    printf("  %s c %g g %g: %ld bounces; n(z) p %.3f, theta(z) p %.3f, "
           "theta sqrt(g00) p %.3f, d theta/dz %.4f +- %.4f\n",
           md->cp->name, md->f.inv_c2 > 0 ? 1 / sqrt(md->f.inv_c2) : INFINITY, md->f.g,
           pr.bounces, pn, pt, pl, slope, slope_err);
    ENSURE(pr.bad == 0);
    ENSURE(pr.bounces > 3 * NBALL); /* several crossings of the box per ball */
    ENSURE_MSG(pn > 1e-3, "density profile chi^2 %.1f for %d dof", chi_n, NB - 1);
    ENSURE_MSG(pt > 1e-3, "temperature profile chi^2 %.1f for %d dof", chi_t, NB);
    ENSURE_MSG(pl > 1e-3, "theta sqrt(g00) chi^2 %.1f for %d dof", chi_l, NB);
    if (want_gradient)
        ENSURE_MSG(slope < -5 * slope_err, "gradient %.4g +- %.4g", slope, slope_err);
    else
        ENSURE_MSG(fabs(slope) < 4 * slope_err, "gradient %.4g +- %.4g", slope, slope_err);
}

/* the sampler against <gamma> = K1(1/theta)/K2(1/theta) + 3 theta, both of its branches */
static void test_juttner_sampler(void)
{
    const double ths[] = {0.02, 0.3, 0.39, 0.41, 1.0, 5.0};
    rc_test_rng r = {0x705};
    for (size_t i = 0; i < sizeof ths / sizeof ths[0]; i++) {
        const double th = ths[i], x = 1.0 / th;
        const double want = gsl_sf_bessel_Kn_scaled(1, x) / gsl_sf_bessel_Kn_scaled(2, x) + 3 * th;
        double s1 = 0, s2 = 0;
        const int n = 100000;
        for (int k = 0; k < n; k++) {
            const double u = juttner_u(&r, th), g = sqrt(1 + u * u);
            s1 += g, s2 += g * g;
        }
        const double mean = s1 / n, err = sqrt((s2 / n - mean * mean) / n);
        ENSURE_MSG(fabs(mean - want) < 4 * err, "theta %g: <gamma> %.6f +- %.6f, want %.6f", th,
                   mean, err, want);
    }
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
    RUN_TEST(test_juttner_sampler);
    RUN_TEST(test_tolman);
    RUN_TEST(test_newtonian_uniform);
    RUN_TEST(test_classical_barometric);
    RC_TEST_MAIN_END();
}
