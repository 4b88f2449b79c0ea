/* test_wall_relax — a gas in a box whose walls are all thermal at kT relaxes to the Jüttner
 * law at kT (Maxwell's at c = inf), whatever it starts from (issue 39 item 5): started much
 * colder and much hotter than the walls, its balls' kinetic energies after a warm-up, from
 * snapshots far apart, against the exact law's CDF by chi^2 with its p-value (20 bins of
 * equal probability), and the mean kinetic energy against the law's within 4 standard
 * errors. The start itself fails the same test (p < 1e-6: the test can tell). The law is
 * the density e^(-E/kT) d^3p, whose kinetic energy K has density ~ p E e^(-K/kT) (c = 1,
 * m = 1; p dp = E dE), integrated here by GSL; classically Gamma(3/2, kT). In 2-D (hard
 * discs) the law is e^(-E/kT) d^2p, K's density ~ E e^(-K/kT): classically exponential,
 * <K> = kT (2 kT + c^2)/(kT + c^2). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_integration.h>

#include "rc_test.h"
#include "relcol/relcol.h"

enum { NBALL = 256, NBIN = 20, NSNAP = 48 };

typedef struct { double kT, c; int dim; } law_par;

/* K's density up to a constant, m = 1: p(K) E(K) e^(-K/kT), p = sqrt(K (K + 2 c^2))/c */
static double dens(double K, void *vp)
{
    const law_par *q = vp;
    const double c2 = q->c * q->c;
    if (q->dim == 2)
        return (K + c2) * exp(-K / q->kT);
    return sqrt(K * (K + 2.0 * c2)) / q->c * (K + c2) * exp(-K / q->kT);
}

static double cdf(const law_par *q, double x)
{
    if (isinf(q->c))
        return gsl_cdf_gamma_P(x, 0.5 * q->dim, q->kT);
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    gsl_function f = {dens, (void *)q};
    double a, b, e;
    gsl_integration_qags(&f, 0.0, x, 0.0, 1e-11, 1000, ws, &a, &e);
    gsl_integration_qagiu(&f, 0.0, 0.0, 1e-11, 1000, ws, &b, &e);
    gsl_integration_workspace_free(ws);
    return a / b;
}

static double mean_k(const law_par *q)
{
    if (isinf(q->c))
        return 0.5 * q->dim * q->kT;
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    gsl_function f = {dens, (void *)q};
    double z, e, zk;
    gsl_integration_qagiu(&f, 0.0, 0.0, 1e-12, 1000, ws, &z, &e);
    /* (K times the density, by the same rule) */
    double acc = 0.0;
    const int nq = 4000;
    const double top = 60.0 * q->kT;
    for (int i = 0; i < nq; i++) { /* midpoint rule on [0, 60 kT]: the tail is e^-60 */
        const double K = (i + 0.5) * top / nq;
        acc += K * dens(K, (void *)q);
    }
    zk = acc * top / nq;
    gsl_integration_workspace_free(ws);
    return zk / z;
}

static double kin(const rc_sim_ball *b, double c)
{
    const double p2 = rc_v3_norm2(b->p);
    if (isinf(c))
        return p2 / (2.0 * b->m);
    const double M = sqrt(b->m * b->m + p2 / (c * c));
    return p2 / (M + b->m);
}

/* chi^2 p-value of the kinetic energies K[0 .. n) against the law q (bins edge[]) */
static double pvalue(const double *K, size_t n, const double *edge, double *chi2)
{
    long cnt[NBIN] = {0};
    for (size_t i = 0; i < n; i++) {
        int b = 0;
        while (b + 1 < NBIN && K[i] >= edge[b + 1])
            b++;
        cnt[b]++;
    }
    double x = 0.0, e = (double)n / NBIN;
    for (int b = 0; b < NBIN; b++)
        x += (cnt[b] - e) * (cnt[b] - e) / e;
    *chi2 = x;
    return gsl_cdf_chisq_Q(x, NBIN - 1);
}

static void relax(int dim, double c, double kT, double v_rms, uint64_t seed)
{
    const law_par q = {kT, c, dim};
    double edge[NBIN + 1];
    edge[0] = 0.0;
    edge[NBIN] = INFINITY;
    for (int b = 1; b < NBIN; b++) {
        double lo = 0.0, hi = 60.0 * kT;
        for (int it = 0; it < 60; it++) {
            const double mid = 0.5 * (lo + hi);
            *(cdf(&q, mid) < (double)b / NBIN ? &lo : &hi) = mid;
        }
        edge[b] = 0.5 * (lo + hi);
    }
    /* radius 0.5, rest mass 1 (density 8: r^3 in 2-D too), packing 0.05: a dilute gas that
     * collides */
    rc_sim_gas_def g = {dim, NBALL, 0.5, 0.05, v_rms, c, 8.0, seed};
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    d.c = c;
    for (int w = 0; w < 2 * dim; w++) {
        d.wall_rule[w] = &rc_wall_thermal;
        d.wall_kT[w] = kT;
    }
    d.wall_seed = seed * 7 + 1;
    rc_sim_ball *b = malloc(NBALL * sizeof *b);
    double *K = malloc(NBALL * NSNAP * sizeof *K);
    rc_sim *s = NULL;
    ENSURE(rc_sim_gas_init(&g, &d.box, b) == RC_OK);
    ENSURE(rc_sim_create(&d, &s) == RC_OK && rc_sim_set_balls(s, NBALL, b, NULL) == RC_OK);
    if (!s)
        goto out;
    double chi2;
    for (size_t i = 0; i < NBALL; i++)
        K[i] = kin(&b[i], c);
    const double p0 = pvalue(K, NBALL, edge, &chi2);
    ENSURE_MSG(p0 < 1e-6, "the start passes for the law (p = %g): the test cannot tell", p0);
    /* a transit of the box L ~ 14 takes ~ 14 / v; warm-up 40 transits, snapshots 3 apart */
    const double vt = isinf(c) ? sqrt(dim * kT) : fmin(1.0, sqrt(dim * kT));
    const double L = d.box.x, dt = 3.0 * L / vt;
    double t = 40.0 * L / vt, sum = 0.0, sum2 = 0.0;
    for (int k = 0; k < NSNAP; k++, t += dt) {
        ENSURE(rc_sim_advance(s, t, 0) == RC_OK);
        ENSURE(rc_sim_get_balls(s, NBALL, b, 0, NULL) == RC_OK);
        double ks = 0.0;
        for (size_t i = 0; i < NBALL; i++)
            ks += K[(size_t)k * NBALL + i] = kin(&b[i], c);
        sum += ks / NBALL;
        sum2 += (ks / NBALL) * (ks / NBALL);
    }
    const double p = pvalue(K, (size_t)NBALL * NSNAP, edge, &chi2);
    const double mk = sum / NSNAP, se = sqrt(fmax(sum2 / NSNAP - mk * mk, 0.0) / (NSNAP - 1));
    const double mk_law = mean_k(&q);
    rc_sim_diag dg;
    rc_sim_diagnostics(s, &dg);
    printf("%d-D c %g kT %g start v_rms %g (p %.2g): chi2 %.1f / %d, p = %.3f; <K> %.4f +- %.4f vs %.4f; "
           "%llu ball, %llu wall events\n", dim, c, kT, v_rms, p0, chi2, NBIN - 1, p, mk, se, mk_law,
           (unsigned long long)dg.events[RC_SIM_EV_BALL], (unsigned long long)dg.events[RC_SIM_EV_WALL]);
    ENSURE_MSG(p > 1e-3, "not the law at kT = %g: p = %g", kT, p);
    ENSURE_MSG(fabs(mk - mk_law) < 4.0 * se, "<K> %g +- %g vs %g", mk, se, mk_law);
    ENSURE(dg.events[RC_SIM_EV_BALL] > 10 * NBALL); /* (the balls collide, too) */
out:
    rc_sim_free(&s);
    free(b);
    free(K);
}

int main(void)
{
    relax(3, INFINITY, 1.0, 0.1, 1);  /* Maxwell, started 100 times colder (K ~ v^2/2 m) */
    relax(3, INFINITY, 1.0, 5.0, 2);  /* ... and 25 times hotter */
    relax(3, 1.0, 1.0, 0.05, 3);      /* Juttner at theta = 1, started almost at rest */
    relax(3, 1.0, 0.2, 0.95, 4);      /* theta = 0.2, started ultra-hot */
    relax(2, INFINITY, 1.0, 0.1, 5);  /* hard discs: Maxwell's exponential K */
    relax(2, 1.0, 1.0, 0.05, 6);      /* ... and 2-D Juttner at theta = 1 */
    RC_TEST_MAIN_END();
}
