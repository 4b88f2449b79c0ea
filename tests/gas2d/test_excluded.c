/* test_excluded.c — the excluded area / volume of two Lorentz-contracted balls and the
 * first-order-in-density split of the thermometers it predicts (apps/gas/excluded.h,
 * papers/finite-density.md; issue 17 item 3). The support-function quadrature is checked
 * against its exact limits (spheres: pi (r1 + r2)^2 and 4/3 pi (r1 + r2)^3; equal shapes:
 * K + K = 2K) and against an independent method, Monte Carlo hit-or-miss with the
 * Perram-Wertheim overlap criterion; the Jüttner pair rule against the exact means and
 * its own refinement; the correction vanishes for uncontracted spheres (c = inf).
 * `test_excluded --table` prints the predicted slopes for a few theta (papers/). */
#include <string.h>

#include <gsl/gsl_errno.h>

#include "excluded.h"
#include "rc_test.h"

static rc_test_rng rng = {1717};

/* A velocity of Lorentz factor gamma in a random direction (2-D in the (x, y) plane). */
static void random_beta(int d, double gamma, double b[3])
{
    const double s = sqrt((gamma - 1.0) * (gamma + 1.0)) / gamma;
    double u[3] = {0.0, 0.0, 0.0}, n2;
    do {
        for (int i = 0; i < d; i++)
            u[i] = rc_test_range(&rng, -1.0, 1.0);
        n2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    } while (!(n2 > 1e-4 && n2 < 1.0));
    for (int i = 0; i < 3; i++)
        b[i] = s * u[i] / sqrt(n2);
}

/* Limits the quadrature must meet to round-off: two spheres (radii 0.5 and 0.8), one shape
 * and itself or its mirror (K + K = 2K: 2^d times the shape's area / volume, the area
 * pi r^2/gamma, the volume 4/3 pi r^3/gamma). The 2-D rule converges geometrically:
 * 512 nodes resolve gamma = 6 to round-off. The 3-D product rule with 48 nodes: a
 * sphere to round-off summed over 4600 nodes (1e-11); a gamma = 6 pancake, whose
 * curvature peak (width ~1/gamma) its nodes barely resolve, to 1e-5 -- below 1e-6 over
 * the Jüttner pairs of theta <= 1 (test_coefficients), whose weight above gamma = 6 is
 * small. */
static void test_limits(void)
{
    gsl_integration_glfixed_table *glt = gsl_integration_glfixed_table_alloc(48);
    const double z[3] = {0.0, 0.0, 0.0};
    ENSURE_REL(ex_area_2d(0.5, z, 0.8, z, 64), M_PI * 1.3 * 1.3, 1e-14);
    ENSURE_REL(ex_volume_3d(0.5, z, 0.8, z, glt), 4.0 / 3.0 * M_PI * 1.3 * 1.3 * 1.3, 1e-11);
    const double gam[] = {1.01, 1.5, 2.5, 6.0};
    for (int k = 0; k < 4; k++)
        for (int d = 2; d <= 3; d++) {
            double b[3], mb[3];
            random_beta(d, gam[k], b);
            for (int i = 0; i < 3; i++)
                mb[i] = -b[i];
            const double one = d == 2 ? M_PI / gam[k] : 4.0 / 3.0 * M_PI / gam[k]; /* r = 1 */
            const double tol = d == 2 ? 1e-13 : 1e-5;
            const ex_quad q = {512, glt, 0};
            ENSURE_REL(ex_excluded(d, 1.0, b, b, &q), (1 << d) * one, tol);
            ENSURE_REL(ex_excluded(d, 1.0, b, mb, &q), (1 << d) * one, tol);
        }
    gsl_integration_glfixed_table_free(glt);
}

/* The zmf contact's forbidden area (ex_area_zmf_2d) where it is known: spheres (c = inf)
 * pi (r1 + r2)^2; a pair at rest in its ZMF (equal velocities) or with the ZMF at rest
 * in the table (opposite velocities): the two simultaneities agree and it is the
 * table-frame sum, its intersection with that sum all of it. Tolerance 1e-4: the gauge is
 * a maximum over 256 scanned normals, which overestimates the radius by O(dphi^2). And a
 * crossing pair, whose events are not simultaneous in its ZMF: the area grows. */
static void test_zmf_area(void)
{
    const double z[3] = {0.0, 0.0, 0.0}, b[3] = {0.6, 0.3, 0.0}, mb[3] = {-0.6, -0.3, 0.0};
    double tab;
    ENSURE_REL(ex_area_zmf_2d(0.5, z, z, 256, &tab), M_PI, 1e-12);
    ENSURE_REL(tab, M_PI, 1e-12);
    const double t = ex_area_2d(1.0, b, 1.0, b, 512);
    ENSURE_REL(ex_area_zmf_2d(1.0, b, b, 256, &tab), t, 1e-4);
    ENSURE_REL(tab, t, 1e-4);
    ENSURE_REL(ex_area_zmf_2d(1.0, b, mb, 256, &tab), ex_area_2d(1.0, b, 1.0, mb, 512), 1e-4);
    const double c1[3] = {0.8, 0.0, 0.0}, c2[3] = {0.0, 0.5, 0.0};
    const double a = ex_area_zmf_2d(1.0, c1, c2, 256, &tab), at = ex_area_2d(1.0, c1, 1.0, c2, 512);
    ENSURE(a > 1.1 * at && tab < at && tab > 0.99 * at);
}

/* Against Monte Carlo: n relative positions uniform in the cube of half-side r1 + r2
 * (which holds the Minkowski sum), the fraction the Perram-Wertheim criterion calls
 * overlapping; the binomial standard error sets the tolerance (4 sigma: a fixed-seed
 * check, and the quadrature's own error is below 1e-9). Pairs of random directions,
 * slow and fast (gamma up to 5), unequal radii. */
static void test_monte_carlo(void)
{
    gsl_integration_glfixed_table *glt = gsl_integration_glfixed_table_alloc(48);
    const ex_quad q = {512, glt, 0};
    const double g1[] = {1.2, 3.0, 5.0, 2.0}, g2[] = {1.0 + 1e-9, 2.0, 5.0, 4.0};
    const double r1[] = {1.0, 1.0, 0.7, 1.0}, r2[] = {1.0, 1.0, 1.0, 0.6};
    for (int d = 2; d <= 3; d++)
        for (int k = 0; k < 4; k++) {
            double b1[3], b2[3], P1[3][3], P2[3][3];
            random_beta(d, g1[k], b1);
            random_beta(d, g2[k], b2);
            ex_shape(r1[k], b1, P1);
            ex_shape(r2[k], b2, P2);
            const double L = r1[k] + r2[k], cube = pow(2.0 * L, d);
            const long n = d == 2 ? 200000 : 100000;
            long hit = 0;
            for (long t = 0; t < n; t++) {
                double x[3] = {0.0, 0.0, 0.0};
                for (int i = 0; i < d; i++)
                    x[i] = rc_test_range(&rng, -L, L);
                hit += ex_pw_overlap(d, P1, P2, x);
            }
            const double p = (double)hit / n, se = sqrt(p * (1.0 - p) / n) * cube;
            const double vq = d == 2 ? ex_area_2d(r1[k], b1, r2[k], b2, q.nphi)
                                     : ex_volume_3d(r1[k], b1, r2[k], b2, glt);
            ENSURE_CLOSE(p * cube, vq, 4.0, se);
            if (k == 2)
                printf("  %d-D, gamma 5 and 5: quadrature %.5f, Monte Carlo %.5f +- %.5f\n", d,
                       vq, p * cube, se);
        }
    gsl_integration_glfixed_table_free(glt);
}

/* The Jüttner pair rule: its means are the exact <gamma> and <p.v> = d theta (the
 * Laguerre nodes integrate the law to round-off in 2-D, where its weight is a polynomial
 * times e^(-x/theta)); refining it moves the slope by < 1e-3 relative (the engine's
 * slopes are measured to a few percent at best); the correction
 * vanishes for spheres; the pair mean <V>/v_d lies between 0 and 2^d, the spheres'. */
static void test_coefficients(void)
{
    gsl_integration_glfixed_table *g36 = gsl_integration_glfixed_table_alloc(36);
    gsl_integration_glfixed_table *g48 = gsl_integration_glfixed_table_alloc(48);
    for (int d = 2; d <= 3; d++) {
        const ex_quad q0 = {256, g36, 0}, q1 = {512, g48, 0};
        ex_coef a, b, s;
        ENSURE(ex_coefficients(d, 0.75, 1, 10, d == 2 ? 32 : 10, &q0, &a) == 0);
        ENSURE(ex_coefficients(d, 0.75, 1, 12, d == 2 ? 64 : 12, &q1, &b) == 0);
        ENSURE(ex_coefficients(d, 0.75, 0, 12, d == 2 ? 32 : 12, &q0, &s) == 0);
        ENSURE_REL(b.mean_gamma, jt_mean_gamma(d, 0.75), d == 2 ? 1e-13 : 1e-9);
        ENSURE_REL(b.mean_pv, d * 0.75, d == 2 ? 1e-13 : 1e-9);
        ENSURE_REL(a.slope, b.slope, 1e-3);
        ENSURE(a.mean_v > 0.0 && a.mean_v < (1 << d));
        ENSURE_REL(s.mean_v, (double)(1 << d), 1e-13);
        ENSURE(fabs(s.c_gamma) < 1e-13 && fabs(s.c_pv) < 1e-13 && fabs(s.slope) < 1e-13);
        /* fast balls exclude less: both covariances negative, both thermometers rise */
        ENSURE(a.c_gamma < 0.0 && a.c_pv < 0.0 && a.dtheta_gamma > 0.0 && a.dtheta_pv > 0.0);
        printf("  %d-D theta 0.75: <V>/v_d %.5f, d theta_gamma/d eta %.6f, "
               "d theta_pv/d eta %.6f, slope of the difference %.6f\n",
               d, b.mean_v, b.dtheta_gamma, b.dtheta_pv, b.slope);
    }
    ex_coef bad;
    const ex_quad q = {256, g36, 0};
    ENSURE(ex_coefficients(4, 0.75, 1, 12, 12, &q, &bad) == -1 && isnan(bad.slope));
    ENSURE(ex_coefficients(2, -1.0, 1, 12, 12, &q, &bad) == -1);
    gsl_integration_glfixed_table_free(g36);
    gsl_integration_glfixed_table_free(g48);
}

/* The c -> inf limit at fixed kT is theta -> 0, and the split vanishes there fast: the
 * O(beta^2) part of V(p1, p2), -a (beta1^2 + beta2^2), reweights J by e^(n a beta^2),
 * and at small theta (beta^2 = p^2/m^2 c^2) that is a Maxwellian at a shifted
 * temperature, which moves both thermometers alike; what splits them is higher order. The
 * slope falls like theta^4 (ratio 16 when theta halves, to O(theta): 14 to 17). */
static void test_classical_limit(void)
{
    gsl_integration_glfixed_table *glt = gsl_integration_glfixed_table_alloc(24);
    const ex_quad q = {256, glt, 0};
    for (int d = 2; d <= 3; d++) {
        ex_coef a, b;
        ENSURE(ex_coefficients(d, 0.01, 1, 12, d == 2 ? 32 : 12, &q, &a) == 0);
        ENSURE(ex_coefficients(d, 0.005, 1, 12, d == 2 ? 32 : 12, &q, &b) == 0);
        ENSURE_MSG(a.slope / b.slope > 14.0 && a.slope / b.slope < 17.0, "%d-D ratio %g", d,
                   a.slope / b.slope);
        ENSURE(a.slope > 0.0 && b.slope > 0.0);
    }
    gsl_integration_glfixed_table_free(glt);
}

/* `--table`: the slopes for papers/finite-density.md, at two resolutions. */
static void table(void)
{
    const double th[] = {0.1, 0.25, 0.5, 0.75, 1.0, 2.0};
    gsl_integration_glfixed_table *g48 = gsl_integration_glfixed_table_alloc(48);
    gsl_integration_glfixed_table *g64 = gsl_integration_glfixed_table_alloc(64);
    printf("d theta <V>/v_d dtheta_gamma/deta dtheta_pv/deta slope slope/theta slope(finer)\n");
    for (int d = 2; d <= 3; d++)
        for (size_t k = 0; k < sizeof th / sizeof *th; k++) {
            const ex_quad q0 = {1024, g48, 0}, q1 = {2048, g64, 0};
            ex_coef a, b;
            ex_coefficients(d, th[k], 1, 16, d == 2 ? 64 : 16, &q0, &a);
            ex_coefficients(d, th[k], 1, 24, d == 2 ? 128 : 20, &q1, &b);
            printf("%d %g %.5f %.6f %.6f %.6f %.6f %.6f\n", d, th[k], a.mean_v, a.dtheta_gamma,
                   a.dtheta_pv, a.slope, a.slope / th[k], b.slope);
        }
    gsl_integration_glfixed_table_free(g48);
    gsl_integration_glfixed_table_free(g64);
    /* 2-D, the area the zmf contact forbids free pairs (ex_area_zmf_2d): a coarser rule,
     * each point costs ~1e4 times a table-frame area (slope converged to ~1 %) */
    printf("2-D, zmf contact's forbidden area:\nd theta <V>/v_d dtheta_gamma/deta dtheta_pv/deta slope\n");
    const double thz[] = {0.25, 0.75, 2.0};
    for (size_t k = 0; k < 3; k++) {
        const ex_quad qz = {128, NULL, 1};
        ex_coef a;
        ex_coefficients(2, thz[k], 1, 8, 16, &qz, &a);
        printf("2 %g %.4f %.5f %.5f %.5f\n", thz[k], a.mean_v, a.dtheta_gamma, a.dtheta_pv, a.slope);
    }
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    if (argc > 1 && strcmp(argv[1], "--table") == 0) {
        table();
        return 0;
    }
    RUN_TEST(test_limits);
    RUN_TEST(test_monte_carlo);
    RUN_TEST(test_zmf_area);
    RUN_TEST(test_coefficients);
    RUN_TEST(test_classical_limit);
    RC_TEST_MAIN_END();
}
