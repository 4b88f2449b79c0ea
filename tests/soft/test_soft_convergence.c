/* test_soft_convergence.c — the soft-sphere reference converges to the hard zmf law as the
 * stiffness grows: exactly (any stiffness) for head-on impacts, where the restitution
 * matching is exact, and at the measured order kappa^(-1/2) for oblique ones, where the
 * line of centres turns during a contact of duration ~ kappa^(-1/2). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>

#include "rc_test.h"
#include "soft_cases.h"

/* rtol of every run here: the solver's own error (~1e-9 relative, see
 * test_soft_conservation) then sits far below the errors being fitted */
#define RTOL 1e-11

static rc_soft_params params(double c, double eps, double kappa)
{
    rc_soft_params prm = rc_soft_params_default();
    prm.c = c;
    prm.eps = eps;
    prm.stiffness = kappa;
    prm.rtol = RTOL;
    return prm;
}

/* Velocities as fractions of c (of 1 classically), so finite c is strongly relativistic
 * (gamma up to 1.9) while c = inf is the same numbers classically. */
static rc_vec3 beta(double c, double bx, double by, double bz)
{
    const double unit = isinf(c) ? 1.0 : c;
    return rc_v3(bx * unit, by * unit, bz * unit);
}

/* Head-on in every frame (centre worldlines intersect): the pair's ZMF motion is a linear
 * damped oscillator with constant inertia, whose restitution is exactly eps for the
 * matched damping ratio, and the hard law is covariant: the outcomes agree to the solver
 * error for any stiffness, even one so soft that the
 * overlap reaches ~20% of the sum of the radii (kappa = 1e3 at c = 3). */
static void test_head_on_exact_at_any_stiffness(void)
{
    const double cs[] = {INFINITY, 3.0, 1.0};
    const double epss[] = {1.0, 0.7, 0.2};
    const double kappas[] = {1e3, 1e5, 1e7};
    for (int ic = 0; ic < 3; ic++)
        for (int ie = 0; ie < 3; ie++)
            for (int ik = 0; ik < 3; ik++) {
                rc_soft_params prm = params(cs[ic], epss[ie], kappas[ik]);
                rc_particle p[2], out[2] = {{0, {0, 0, 0}}, {0, {0, 0, 0}}};
                rc_vec3 x[2];
                ENSURE(soft_case(rc_inv_c2_of(prm.c), beta(cs[ic], 0.7, 0.3, -0.2),
                                 beta(cs[ic], -0.5, 0.1, 0.4), 0.0, p, x) == 0);
                double err = NAN;
                rc_soft_result res;
                ENSURE(soft_vs_hard(&rc_soft_cvode_bdf, &prm, p, x, out, &err, &res) == RC_OK);
                /* 3e-8: measured at most 3.1e-9 over these 27 cases (the solver's global
                 * error at RTOL); a wrong eps matching or rest-mass split is an O(1 - eps)
                 * or O(v^2/c^2) error, orders of magnitude above */
                ENSURE_MSG(err < 3e-8, "c=%g eps=%g kappa=%g err=%.3g", cs[ic], epss[ie],
                           kappas[ik], err);
                ENSURE(res.n_contacts == 1 && res.finished == 1);
                /* eps < 1 must raise both rest masses at finite c, and keep them at c=inf */
                if (epss[ie] < 1.0 && !isinf(cs[ic]))
                    ENSURE(out[0].m > p[0].m && out[1].m > p[1].m);
                if (isinf(cs[ic]))
                    ENSURE(out[0].m == p[0].m && out[1].m == p[1].m);
            }
}

/* Least-squares slope of log(err) against log(kappa). */
static double fit_order(const double *kappa, const double *err, int n)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int i = 0; i < n; i++) {
        const double lx = log(kappa[i]), ly = log(err[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/* Oblique impacts: error against stiffness over four decades, fitted order. Measured
 * (cvode-bdf, rtol 1e-11): slopes -0.5008 to -0.5023 for every c and eps below. The bound
 * |order + 1/2| < 0.03 fails for a limit other than the zmf law (the error would level
 * off: order -> 0) and for a different mechanism (order -1 if the normal's turn cancelled
 * at first order). */
static void test_oblique_converges_at_order_half(void)
{
    const double cs[] = {INFINITY, 2.0, 1.0};
    const double epss[] = {1.0, 0.5};
    enum { NK = 5 };
    const double kappas[NK] = {1e4, 1e5, 1e6, 1e7, 1e8};
    for (int ic = 0; ic < 3; ic++)
        for (int ie = 0; ie < 2; ie++) {
            double err[NK];
            for (int ik = 0; ik < NK; ik++) {
                rc_soft_params prm = params(cs[ic], epss[ie], kappas[ik]);
                rc_particle p[2];
                rc_vec3 x[2];
                soft_case(rc_inv_c2_of(prm.c), beta(cs[ic], 0.6, 0.1, 0.0), beta(cs[ic], -0.3, 0.05, 0.1),
                          0.3, p, x);
                err[ik] = NAN;
                ENSURE(soft_vs_hard(&rc_soft_cvode_bdf, &prm, p, x, NULL, &err[ik], NULL) ==
                       RC_OK);
            }
            const double order = fit_order(kappas, err, NK);
            printf("  c=%-4g eps=%-4g err(kappa=1e4..1e8) = %.3e %.3e %.3e %.3e %.3e  "
                   "order %.4f\n",
                   cs[ic], epss[ie], err[0], err[1], err[2], err[3], err[4], order);
            ENSURE_MSG(fabs(order + 0.5) < 0.03, "order %.4f", order);
            /* each decade must gain close to sqrt(10) = 3.16: between 2.8 and 3.5 */
            for (int ik = 1; ik < NK; ik++)
                ENSURE_MSG(err[ik - 1] / err[ik] > 2.8 && err[ik - 1] / err[ik] < 3.5,
                           "decade %d ratio %.3f", ik, err[ik - 1] / err[ik]);
        }
}

/* The GSL stepper sees the same limit: same oblique errors as CVODE at each stiffness. */
static void test_gsl_stepper_same_limit(void)
{
    for (double kappa = 1e4; kappa <= 1e8; kappa *= 100) {
        rc_soft_params prm = params(1.0, 0.5, kappa);
        rc_particle p[2];
        rc_vec3 x[2];
        soft_case(rc_inv_c2_of(prm.c), beta(1.0, 0.6, 0.1, 0.0), beta(1.0, -0.3, 0.05, 0.1), 0.3, p, x);
        double ec = NAN, eg = NAN;
        ENSURE(soft_vs_hard(&rc_soft_cvode_bdf, &prm, p, x, NULL, &ec, NULL) == RC_OK);
        ENSURE(soft_vs_hard(&rc_soft_gsl_rk8pd, &prm, p, x, NULL, &eg, NULL) == RC_OK);
        /* the two errors differ by the solvers' own errors (< 1e-7): 1% of err >= 1e-5 */
        ENSURE_REL(eg, ec, 1e-2);
    }
}

/* c is a parameter of the same code: at c = 1e3 with speeds ~0.6 the soft outcome is the
 * classical one up to O(v^2/c^2) ~ 4e-7 (measured 1.1e-7), and not identical to it (the
 * relativistic terms are really there). */
static void test_large_c_approaches_classical(void)
{
    rc_particle out[2][2];
    for (int ic = 0; ic < 2; ic++) {
        rc_soft_params prm = params(ic ? 1e3 : INFINITY, 0.5, 1e6);
        rc_particle p[2];
        rc_vec3 x[2];
        soft_case(rc_inv_c2_of(prm.c), rc_v3(0.6, 0.1, 0.0), rc_v3(-0.3, 0.05, 0.1), 0.3, p, x);
        double err;
        ENSURE(soft_vs_hard(&rc_soft_cvode_bdf, &prm, p, x, out[ic], &err, NULL) == RC_OK);
    }
    const double d = soft_diff(out[1], out[0], 1.0);
    ENSURE_MSG(d < 4e-7 && d > 1e-9, "diff %.3g", d);
}

int main(void)
{
    gsl_set_error_handler_off();
    RUN_TEST(test_head_on_exact_at_any_stiffness);
    RUN_TEST(test_oblique_converges_at_order_half);
    RUN_TEST(test_gsl_stepper_same_limit);
    RUN_TEST(test_large_c_approaches_classical);
    RC_TEST_MAIN_END();
}
