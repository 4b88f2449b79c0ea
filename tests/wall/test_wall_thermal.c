/* test_wall_thermal — the thermal wall's re-emission law (lib/wall_thermal.c, issue 39
 * item 5) against its exact marginals: the kinetic energy's and the angle to the normal's,
 * by chi^2 with its p-value, in 2-D and 3-D, classical and at c = 1 from theta = 0.1 to
 * 10 (papers/transport.md, section 8). The marginals come from the density
 * (p_n/E) e^(-E/kT) d^dp directly: 3-D by the Gamma CDFs, 2-D by GSL quadrature. */
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "rc_test.h"
#include "relcol/relcol.h"
#include "relcol/wall_thermal.h"

enum { NBIN = 24, NSAMP = 200000 };

typedef struct {
    double m, k, kT; /* k = 1/c^2 */
} kin_par;

/* K's density in 2-D, unnormalised: p(K) e^(-K/kT), p^2 = K (2 m + k K) (d^2p = p dp da,
 * p_n/E = cos a p/E, p dp = E dE). */
static double dens2(double K, void *vp)
{
    const kin_par *q = vp;
    return sqrt(K * (2.0 * q->m + q->k * K)) * exp(-K / q->kT);
}

/* P(K < x): 3-D from the Gamma mixture the density (K^2 + 2 m c^2 K) e^(-K/kT) is;
 * 2-D by quadrature of dens2, normalised by its integral to infinity. */
static double cdf_k(int dim, const kin_par *q, double x)
{
    if (dim == 3) {
        const double w3 = q->kT * q->k / (q->kT * q->k + q->m);
        return w3 * gsl_cdf_gamma_P(x, 3.0, q->kT) + (1.0 - w3) * gsl_cdf_gamma_P(x, 2.0, q->kT);
    }
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    gsl_function f = {dens2, (void *)q};
    double a, b, e;
    gsl_integration_qags(&f, 0.0, x, 0.0, 1e-11, 1000, ws, &a, &e);
    gsl_integration_qagiu(&f, 0.0, 0.0, 1e-11, 1000, ws, &b, &e);
    gsl_integration_workspace_free(ws);
    return a / b;
}

static void check_case(int dim, double c, double kT)
{
    const kin_par q = {1.0, isinf(c) ? 0.0 : 1.0 / (c * c), kT};
    const rc_vec3 normal = dim == 3 ? rc_v3(0.3, -0.5, 0.8) : rc_v3(0.6, -0.8, 0.0);
    const double nn = rc_v3_norm(normal);
    rc_rng r = {(uint64_t)(1000 * kT) + 7 * dim};
    /* bins: equal probability under the exact law (edges by bisection of the CDF) */
    double edge[NBIN + 1];
    edge[0] = 0.0;
    edge[NBIN] = INFINITY;
    for (int b = 1; b < NBIN; b++) {
        double lo = 0.0, hi = 60.0 * kT;
        for (int it = 0; it < 60; it++) {
            const double mid = 0.5 * (lo + hi);
            *(cdf_k(dim, &q, mid) < (double)b / NBIN ? &lo : &hi) = mid;
        }
        edge[b] = 0.5 * (lo + hi);
    }
    long nk[NBIN] = {0}, na[NBIN] = {0}, bad = 0;
    for (int i = 0; i < NSAMP; i++) {
        rc_vec3 p;
        if (rc_wall_thermal_emit(&r, dim, 1.0, c, kT, normal, &p) != RC_OK) {
            bad++;
            continue;
        }
        const double p2 = rc_v3_dot(p, p), pn = rc_v3_dot(p, normal) / nn;
        /* K = p^2 / (gamma + 1) with m = 1: c^2 (gamma - 1) without the cancellation */
        const double Kx = p2 / (sqrt(1.0 + q.k * p2) + 1.0);
        int b = 0;
        while (b + 1 < NBIN && Kx >= edge[b + 1])
            b++;
        nk[b]++;
        if (!(pn > 0.0) || (dim == 2 && p.z != 0.0))
            bad++;
        /* angle: 3-D cos^2 a is uniform; 2-D (sin a + 1)/2 is */
        const double ca = pn / sqrt(p2);
        const double u = dim == 3 ? ca * ca : 0.5 * (1.0 + copysign(sqrt(fmax(0.0, 1.0 - ca * ca)),
                                                                   rc_v3_dot(p, rc_v3(-normal.y, normal.x, 0.0))));
        int a = (int)(u * NBIN);
        na[a < NBIN ? a : NBIN - 1]++;
    }
    double ck = 0.0, cang = 0.0;
    const double expct = (double)NSAMP / NBIN;
    for (int b = 0; b < NBIN; b++) {
        ck += (nk[b] - expct) * (nk[b] - expct) / expct;
        cang += (na[b] - expct) * (na[b] - expct) / expct;
    }
    const double pk = gsl_cdf_chisq_Q(ck, NBIN - 1), pa = gsl_cdf_chisq_Q(cang, NBIN - 1);
    printf("  %d-D c %-4g kT %-4g: K chi2 %.1f (p %.3f), angle chi2 %.1f (p %.3f)\n", dim, c, kT,
           ck, pk, cang, pa);
    ENSURE(bad == 0);
    /* a fixed-seed check: each p-value falls below 1e-4 for a correct sampler one run in
     * 10^4; a wrong marginal at this sample size drives it to ~0 */
    ENSURE_MSG(pk > 1e-4 && pa > 1e-4, "%d-D c %g kT %g", dim, c, kT);
}

static void test_marginals(void)
{
    static const double kts[] = {0.1, 1.0, 10.0};
    for (int dim = 2; dim <= 3; dim++) {
        for (int i = 0; i < 3; i++)
            check_case(dim, 1.0, kts[i]);
        check_case(dim, INFINITY, 1.0);
    }
}

/* The energy a 3-D wall emits per ball: <K> = kT (3 kT + 2 m c^2)/(kT + m c^2), from the
 * flux's moments (classically 2 kT, massless 3 kT); the sample mean within 4 of its
 * errors. */
static void test_energy_per_ball(void)
{
    rc_rng r = {5};
    static const double kts[] = {0.1, 1.0, 10.0};
    for (int i = 0; i < 3; i++) {
        const double kT = kts[i];
        double s = 0.0, s2 = 0.0;
        for (int k = 0; k < NSAMP; k++) {
            rc_vec3 p;
            ENSURE(rc_wall_thermal_emit(&r, 3, 1.0, 1.0, kT, rc_v3(0, 0, 1), &p) == RC_OK);
            const double K = sqrt(1.0 + rc_v3_dot(p, p)) - 1.0;
            s += K, s2 += K * K;
        }
        const double mean = s / NSAMP, se = sqrt((s2 / NSAMP - mean * mean) / NSAMP);
        ENSURE_CLOSE(mean, kT * (3.0 * kT + 2.0) / (kT + 1.0), 4.0, se);
    }
}

static void test_bad_input(void)
{
    rc_rng r = {1};
    rc_vec3 p = rc_v3(7, 7, 7);
    const rc_vec3 n = rc_v3(0, 0, 1);
    ENSURE(rc_wall_thermal_emit(&r, 3, 0.0, 1.0, 1.0, n, &p) == RC_EMASS);
    ENSURE(rc_wall_thermal_emit(&r, 3, 1.0, 0.0, 1.0, n, &p) == RC_ESPEEDOFLIGHT);
    ENSURE(rc_wall_thermal_emit(&r, 3, 1.0, 1.0, NAN, n, &p) == RC_ENONFINITE);
    ENSURE(rc_wall_thermal_emit(&r, 3, 1.0, 1.0, -1.0, n, &p) == RC_EINVAL);
    ENSURE(rc_wall_thermal_emit(&r, 4, 1.0, 1.0, 1.0, n, &p) == RC_EINVAL);
    ENSURE(rc_wall_thermal_emit(&r, 2, 1.0, 1.0, 1.0, n, &p) == RC_EINVAL); /* z normal in 2-D */
    ENSURE(rc_wall_thermal_emit(&r, 3, 1.0, 1.0, 1.0, rc_v3(0, 0, 0), &p) == RC_EZERONORMAL);
    ENSURE(p.x == 7 && p.y == 7 && p.z == 7);
}

int main(void)
{
    gsl_set_error_handler_off();
    RUN_TEST(test_marginals);
    RUN_TEST(test_energy_per_ball);
    RUN_TEST(test_bad_input);
    RC_TEST_MAIN_END();
}
