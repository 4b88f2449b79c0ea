/* test_law_heat.c — rc_pair_heat, the cancellation-free heat sum (m' - m) c^2 of a pair:
 * the classical kinetic-energy loss at c = inf, the naive rest-mass sum at moderate c,
 * zero for elastic collisions, and convergence to the classical heat like (v/c)^2. */
#include <float.h>
#include <math.h>

#include <gsl/gsl_fit.h>

#include "law_util.h"

#define N_CONFIG 24
#define K_MIN 1
#define K_MAX 6
/* Slope tolerance as in test_law_limits: the deviation is exactly second order in v/c,
 * the fourth-order term bends the k = 1 point by ~1e-2 decades; rc_pair_heat has no
 * cancellation, so round-off (~1e-16 relative) stays 4 decades under the k = 6 deviation. */
#define TOL_SLOPE 0.05
/* Classical heat vs kinetic-energy loss (relative to the kinetic energy before, as the
 * loss K0 - K1 is itself a difference): both are a few roundings of O(K) terms. */
#define TOL_CLASSICAL 1e-13
/* Naive sum (m' - m) c^2: m' - m is known only to ~1 ulp of m, so its error is
 * ~1e-16 (m0 + m1) c^2; allow 1e-13 of that scale (a wrong formula is off by O(heat),
 * i.e. ~1e-2 of the scale at c = 3 vmax). */
#define TOL_NAIVE 1e-13
/* Elastic: |pbar'| = |pbar| up to rounding of O(|pbar|^2/m) terms. */
#define TOL_ELASTIC 1e-13

/* The pair before (in) and after (out) the collision with law at speed of light c. */
static void run(const rc_law *law, const lu_pair *p, double eps, double c, rc_particle in[2],
                rc_particle out[2], double *k)
{
    ENSURE(rc_inv_c2(c, k) == RC_OK);
    for (int j = 0; j < 2; j++) {
        in[j].m = p->b[j].m;
        ENSURE(rc_momentum_from_velocity(in[j].m, p->v[j], *k, &in[j].p) == RC_OK);
        out[j] = in[j];
    }
    rc_collision_params prm = rc_collision_params_default();
    prm.c = rc_test_c_of(*k);
    prm.eps = eps;
    ENSURE(rc_collide(law, &prm, &out[0], &out[1], p->n) == RC_OK);
}

/* Run check on N_CONFIG random pairs (1-D, 2-D, 3-D in turn) for every built-in law. */
static void each_pair(uint64_t seed, void (*check)(const rc_law *, const lu_pair *))
{
    rc_test_rng r = {seed};
    for (size_t l = 0; rc_laws[l]; l++)
        for (int cfg = 0; cfg < N_CONFIG; cfg++) {
            lu_pair p;
            lu_random_pair(&r, &p, 1 + cfg % 3);
            check(rc_laws[l], &p);
        }
}

/* c = inf: the heat is the classical kinetic energy lost, sum p^2/(2m) before - after. */
static void check_classical(const rc_law *law, const lu_pair *p)
{
    rc_particle in[2], out[2];
    double k, qb[2];
    run(law, p, p->eps, INFINITY, in, out, &k);
    ENSURE(k == 0.0);
    double K0 = 0.0, K1 = 0.0;
    for (int j = 0; j < 2; j++) {
        K0 += rc_v3_norm2(in[j].p) / (2.0 * in[j].m);
        K1 += rc_v3_norm2(out[j].p) / (2.0 * out[j].m);
    }
    double q = rc_pair_heat(in, out, 0.0, qb);
    ENSURE(q > 0.0);
    ENSURE_CLOSE(q, K0 - K1, TOL_CLASSICAL, K0);
    ENSURE(q == qb[0] + qb[1]); /* the same two terms, added in the same order */
}

/* Moderate c (3 times the fastest speed): the naive sum (m' - m) c^2 agrees to its own
 * precision, per ball and summed. */
static void check_naive(const rc_law *law, const lu_pair *p)
{
    const double c = 3.0 * p->vmax;
    rc_particle in[2], out[2];
    double k, qb[2];
    run(law, p, p->eps, c, in, out, &k);
    double q = rc_pair_heat(in, out, k, qb);
    const double scale = (in[0].m + in[1].m) * c * c;
    double naive = 0.0;
    for (int j = 0; j < 2; j++) {
        const double nj = (out[j].m - in[j].m) * c * c;
        ENSURE_CLOSE(qb[j], nj, TOL_NAIVE, scale);
        naive += nj;
    }
    ENSURE(q > 0.0);
    ENSURE_CLOSE(q, naive, TOL_NAIVE, scale);
}

/* eps = 1 makes no heat at any c; an unchanged pair makes exactly none. */
static void check_elastic(const rc_law *law, const lu_pair *p)
{
    const double cs[] = {INFINITY, 100.0, 10.0, 3.0, 1.5};
    for (size_t ic = 0; ic < sizeof cs / sizeof cs[0]; ic++) {
        rc_particle in[2], out[2];
        double k;
        run(law, p, 1.0, cs[ic] * p->vmax, in, out, &k);
        /* ZMF kinetic scale sum |pbar|^2 / m, bounded by sum |p|^2 / m */
        double scale = 0.0;
        for (int j = 0; j < 2; j++)
            scale += rc_v3_norm2(in[j].p) / in[j].m;
        ENSURE_CLOSE(rc_pair_heat(in, out, k, NULL), 0.0, TOL_ELASTIC, scale);
        ENSURE(rc_pair_heat(in, in, k, NULL) == 0.0);
    }
}

/* The heat converges to the classical one like (v/c)^2: log-log slope -2 over five
 * decades of c, which the naive sum cannot resolve beyond c ~ 1e3 v (test_law_limits). */
static double worst_slope;
static void check_convergence(const rc_law *law, const lu_pair *p)
{
    rc_particle in[2], out[2];
    double k;
    run(law, p, p->eps, INFINITY, in, out, &k);
    const double q_inf = rc_pair_heat(in, out, k, NULL);
    double x[K_MAX], y[K_MAX];
    size_t n = 0;
    for (int kk = K_MIN; kk <= K_MAX; kk++, n++) {
        const double c = pow(10.0, kk) * p->vmax;
        run(law, p, p->eps, c, in, out, &k);
        x[n] = log10(c / p->vmax);
        y[n] = log10(fabs(rc_pair_heat(in, out, k, NULL) - q_inf) / q_inf);
    }
    double c0, c1, cov00, cov01, cov11, sumsq;
    ENSURE(gsl_fit_linear(x, 1, y, 1, n, &c0, &c1, &cov00, &cov01, &cov11, &sumsq) == 0);
    ENSURE_MSG(fabs(c1 + 2.0) < TOL_SLOPE, "%s: heat slope %.4f", law->name, c1);
    worst_slope = lu_max(worst_slope, fabs(c1 + 2.0));
}

static void test_classical(void) { each_pair(511, check_classical); }
static void test_naive(void) { each_pair(512, check_naive); }
static void test_elastic(void) { each_pair(513, check_elastic); }
static void test_convergence(void)
{
    each_pair(514, check_convergence);
    printf("worst |slope + 2| = %.3g\n", worst_slope);
}

/* Invalid input: NAN, also in the per-ball output. */
static void test_invalid(void)
{
    rc_particle in[2] = {{1.0, rc_v3(1, 0, 0)}, {2.0, rc_v3(-1, 0, 0)}};
    rc_particle bad[2] = {{NAN, rc_v3(1, 0, 0)}, {2.0, rc_v3(-1, 0, 0)}};
    double qb[2] = {0.0, 0.0};
    ENSURE(isnan(rc_pair_heat(in, bad, 0.0, qb)) && isnan(qb[0]) && isnan(qb[1]));
    ENSURE(isnan(rc_pair_heat(in, in, -1.0, NULL)));
    ENSURE(isnan(rc_pair_heat(in, in, INFINITY, NULL)));
    ENSURE(rc_pair_heat(in, in, 0.01, NULL) == 0.0);
}

int main(void)
{
    RUN_TEST(test_classical);
    RUN_TEST(test_naive);
    RUN_TEST(test_elastic);
    RUN_TEST(test_convergence);
    RUN_TEST(test_invalid);
    RC_TEST_MAIN_END();
}
