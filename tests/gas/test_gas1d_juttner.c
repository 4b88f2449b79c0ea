/* test_gas1d_juttner.c — reproduction of Cubero et al., PRL 99, 170601 (2007): a 1-D
 * relativistic gas relaxes to the Juttner distribution and <p v> = kT is its thermometer
 * (data/reproductions/cubero2007.md). Usage: test_gas1d_juttner TABLE.csv (the test);
 * test_gas1d_juttner --table (prints the reference table from the Bessel functions). */
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>
#include <stdlib.h>
#include <string.h>

#include "gas1d_util.h"
#include "gas_stats.h"

/* ================================================================ 1-D Juttner (c = 1)
 * f(p) = exp(-E/kT) / (2 m K1(m/kT)), E = sqrt(m^2 + p^2); theta = kT/m. With
 * p = m sinh y: f dp = exp(-cosh(y)/theta) cosh(y) dy / (2 K1(1/theta)). Scaled Bessel
 * functions (e^x K(x)) keep small theta finite. Moments:
 *   <gamma>   = K0(1/theta)/K1(1/theta) + theta      (-d ln Z / d beta, Z = 2 m K1(beta m))
 *   <p v>     = kT                                   (equipartition, integrate by parts)
 *   <p^2>/m^2 = theta (<gamma> + theta)              (<p^2> = kT (<E> + <p v>)) */

static double juttner_mean_gamma(double theta)
{
    const double x = 1.0 / theta;
    return gsl_sf_bessel_K0_scaled(x) / gsl_sf_bessel_K1_scaled(x) + theta;
}

static double juttner_mean_p2(double theta)
{
    return theta * (juttner_mean_gamma(theta) + theta);
}

typedef struct {
    double theta;
    int power; /* integrand exp(-(cosh y - 1)/theta) cosh(y)^power (gamma = cosh y) */
} jparams;

static double jintegrand(double y, void *v)
{
    const jparams *q = v;
    const double c = cosh(y);
    const double a = (c - 1.0) / q->theta;
    if (!(a < 745.0)) /* exp underflows to 0 while cosh may overflow: 0 * inf */
        return 0.0;
    return exp(-a) * pow(c, q->power);
}

static gsl_integration_workspace *ws;

/* integral over [0, y] (y = INFINITY: [0, inf)) */
static double jint(double theta, int power, double y)
{
    jparams q = {theta, power};
    gsl_function F = {jintegrand, &q};
    double r, err;
    if (isinf(y))
        gsl_integration_qagiu(&F, 0.0, 0.0, 1e-13, 1000, ws, &r, &err);
    else
        gsl_integration_qag(&F, 0.0, y, 0.0, 1e-13, 1000, GSL_INTEG_GAUSS31, ws, &r, &err);
    return r;
}

/* CDF of the momentum of a particle of rest mass m at temperature kT.
 * model 0: 1-D Juttner at c = 1; model 1: Maxwell-Boltzmann (Gaussian, variance m kT). */
static double model_cdf(int model, double p, double m, double kT)
{
    if (model == 1)
        return gsl_cdf_gaussian_P(p, sqrt(m * kT));
    const double theta = kT / m;
    const double g = jint(theta, 1, asinh(fabs(p) / m)) / gsl_sf_bessel_K1_scaled(1.0 / theta);
    return p >= 0.0 ? 0.5 + 0.5 * g : 0.5 - 0.5 * g;
}

/* p with model_cdf = q (bisection: both CDFs are increasing). */
static double model_quantile(int model, double q, double m, double kT)
{
    double hi = m * sinh(acosh(1.0 + 60.0 * kT / m)) + 12.0 * sqrt(m * kT), lo = -hi;
    for (int k = 0; k < 200 && hi - lo > 1e-15 * (fabs(lo) + fabs(hi)); k++) {
        const double mid = 0.5 * (lo + hi);
        if (model_cdf(model, mid, m, kT) < q)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* theta with juttner_mean_gamma(theta) = g (increasing in theta); NAN if g <= 1. */
static double juttner_theta_from_gamma(double g)
{
    if (!(g > 1.0))
        return NAN;
    double lo = log(1e-6), hi = log(1e4);
    for (int k = 0; k < 200 && hi - lo > 1e-15; k++) {
        const double mid = 0.5 * (lo + hi);
        if (juttner_mean_gamma(exp(mid)) < g)
            lo = mid;
        else
            hi = mid;
    }
    return exp(0.5 * (lo + hi));
}

/* ================================================================ reference table */

static const double table_theta[] = {0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.3, 0.4, 0.5,
                                     0.6, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0,
                                     10.0};
enum { TABLE_ROWS = sizeof table_theta / sizeof table_theta[0] };

static void print_table(void)
{
    printf("# 1-D Juttner moments at c = 1, theta = kT/(m c^2), from the Bessel functions "
           "(GSL gsl_sf_bessel_K{0,1}_scaled):\n"
           "# mean_gamma = K0(1/theta)/K1(1/theta) + theta; mean_pv_over_mc2 = theta; "
           "mean_p2_over_m2c2 = theta (mean_gamma + theta)\n"
           "theta,mean_gamma,mean_pv_over_mc2,mean_p2_over_m2c2\n");
    for (int i = 0; i < TABLE_ROWS; i++) {
        const double t = table_theta[i];
        printf("%.17g,%.17g,%.17g,%.17g\n", t, juttner_mean_gamma(t), t, juttner_mean_p2(t));
    }
}

/* The table in data/ is what the formulas give (guards the data file), and the formulas
 * are what direct quadrature of the distribution gives (guards the formulas). */
static void test_reference_table(const char *path)
{
    FILE *f = fopen(path, "r");
    ENSURE_MSG(f != NULL, "cannot open %s", path);
    if (!f)
        return;
    char line[512];
    int rows = 0;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#' || strncmp(line, "theta", 5) == 0)
            continue;
        double t, g, pv, p2;
        if (sscanf(line, "%lf,%lf,%lf,%lf", &t, &g, &pv, &p2) != 4) {
            ENSURE_MSG(0, "bad row: %s", line);
            continue;
        }
        rows++;
        /* %.17g round-trips: only the libm/GSL differences between machines remain */
        ENSURE_REL(g, juttner_mean_gamma(t), 1e-13);
        ENSURE_REL(p2, juttner_mean_p2(t), 1e-13);
        ENSURE(pv == t);
        /* quadrature over the rapidity y (weight exp(-cosh y/theta) cosh y): the norm is
         * K1, <gamma> = <cosh y>, <p^2>/m^2 = <sinh^2 y> = <gamma^2> - 1 */
        const double norm = jint(t, 1, INFINITY);
        ENSURE_REL(norm, gsl_sf_bessel_K1_scaled(1.0 / t), 1e-10);
        ENSURE_REL(jint(t, 2, INFINITY) / norm, g, 1e-10);
        ENSURE_REL(jint(t, 3, INFINITY) / norm - 1.0, p2, 1e-10);
    }
    fclose(f);
    ENSURE_MSG(rows == TABLE_ROWS, "%d rows", rows);
    /* limits: theta -> 0 gives <gamma> ~ 1 + theta/2 (1-D equipartition of p^2/2m);
     * theta -> inf gives <gamma> ~ theta (ultra-relativistic, E = |p| c, <E> = kT) */
    ENSURE_REL(juttner_mean_gamma(1e-4) - 1.0, 0.5e-4, 1e-3);
    ENSURE_REL(juttner_mean_gamma(1e4) / 1e4, 1.0, 1e-3);
    /* and the inverse used below */
    ENSURE_REL(juttner_theta_from_gamma(juttner_mean_gamma(0.7)), 0.7, 1e-12);
}

static const char *table_path;
static void test_table(void) { test_reference_table(table_path); }

/* ================================================================ the gas */

enum { NSPEC = 2, NBLOCK = 20, NBIN = 20 };

typedef struct {
    /* inputs */
    double inv_c2, m[NSPEC], frac_heavy, kT_target;
    size_t n;
    int n_snap;
    double t_eq, dt_snap;
    uint64_t seed;
    /* outputs: per species, block means and the pooled estimate +- standard error */
    double kT_pv[NSPEC], se_pv[NSPEC];       /* <p v> */
    double kT_g[NSPEC], se_g[NSPEC];         /* from <gamma> through Juttner (c = 1) */
    double se_g_minus_pv[NSPEC], se_l_minus_h;
    double kT_fit;                           /* pooled <p v>: the fitted temperature */
    double chi2[2], phi, dof;                /* chi2 against model 0/1, inflation phi */
    uint64_t events;
} gas_run;

/* Initial |v|: equal speeds whose total energy is the canonical one at kT_target, so the
 * gas should settle at kT_target (to O(1/N), the microcanonical correction). */
static double start_speed(const gas_run *r)
{
    const double fr[NSPEC] = {1.0 - r->frac_heavy, r->frac_heavy};
    double e = 0.0, msum = 0.0;
    for (int s = 0; s < NSPEC; s++) {
        msum += fr[s] * r->m[s];
        if (r->inv_c2 > 0.0)
            e += fr[s] * r->m[s] * juttner_mean_gamma(r->kT_target / r->m[s]);
        else
            e += fr[s] * 0.5 * r->kT_target;
    }
    if (r->inv_c2 > 0.0) {
        const double g = e / msum; /* common gamma */
        return sqrt(1.0 - 1.0 / (g * g));
    }
    return sqrt(2.0 * e / msum);
}

/* Runs NBLOCK independent replicas of the gas (seeds seed, seed + 1, ...: their own
 * species order, positions and signs), samples each at common table times t_eq,
 * t_eq + dt_snap, ..., and treats each replica as one block. Independent replicas give
 * honest error bars: one long run's consecutive blocks share the gas's slow collective
 * modes (sound crossing the box, energy drifting between the species) and understate
 * them. Estimates kT two ways per species, and the chi-square of the momentum histogram
 * against the Juttner (model 0) and Maxwell-Boltzmann (model 1) laws at the fitted kT. */
static int run_gas(gas_run *r)
{
    const size_t n = r->n, ns = (size_t)r->n_snap;
    const double m_light = r->m[0], m_heavy = r->m[1];
    int *spec = malloc(NBLOCK * n * sizeof(int));
    double *ps = malloc(NBLOCK * ns * n * sizeof(double));
    if (!spec || !ps) {
        free(spec), free(ps);
        return RC_ENOMEM;
    }
    int st = RC_OK;
    r->events = 0;
    for (int b = 0; b < NBLOCK && st == RC_OK; b++) {
        gas_setup s;
        rc_gas1d *g = NULL;
        st = gas_setup_mixture(&s, n, r->inv_c2, m_light, m_heavy, r->frac_heavy,
                               start_speed(r), r->seed + (uint64_t)b);
        if (st == RC_OK)
            st = gas_setup_create(&s, &g);
        /* particles keep their order and (elastic) their rest masses: species by index */
        for (size_t i = 0; i < n && st == RC_OK; i++)
            spec[b * n + i] = s.m[i] == m_heavy && m_heavy != m_light;
        double t = r->t_eq;
        for (size_t k = 0; k < ns && st == RC_OK; k++, t += r->dt_snap) {
            st = rc_gas1d_advance(g, t, 0);
            rc_gas1d_get(g, NULL, NULL, ps + (b * ns + k) * n);
        }
        rc_gas1d_stats gs;
        if (st == RC_OK && rc_gas1d_stats_get(g, &gs) == RC_OK)
            r->events += gs.pair_events + gs.wall_events[0] + gs.wall_events[1];
        rc_gas1d_free(&g);
        gas_setup_free(&s);
    }
    if (st != RC_OK) {
        free(spec), free(ps);
        return st;
    }

    /* temperatures per replica */
    double bpv[NSPEC][NBLOCK], bg[NSPEC][NBLOCK], bd[NSPEC][NBLOCK], blh[NBLOCK],
        ball[NBLOCK];
    for (int b = 0; b < NBLOCK; b++) {
        double spv[NSPEC] = {0, 0}, sg[NSPEC] = {0, 0}, cnt[NSPEC] = {0, 0};
        for (size_t k = 0; k < ns; k++)
            for (size_t i = 0; i < n; i++) {
                const int q = spec[b * n + i];
                const double p = ps[(b * ns + k) * n + i], mi = r->m[q];
                const double M = sqrt(mi * mi + p * p * r->inv_c2);
                spv[q] += p * p / M; /* p v */
                sg[q] += M / mi;     /* gamma (c = 1) */
                cnt[q] += 1.0;
            }
        for (int q = 0; q < NSPEC; q++) {
            bpv[q][b] = spv[q] / cnt[q];
            /* classically gamma = 1: <p v> = <p^2/m> is then the only thermometer */
            bg[q][b] = r->inv_c2 > 0.0 ? r->m[q] * juttner_theta_from_gamma(sg[q] / cnt[q])
                                       : NAN;
            bd[q][b] = bg[q][b] - bpv[q][b];
        }
        blh[b] = bpv[0][b] - bpv[1][b];
        ball[b] = (spv[0] + spv[1]) / (cnt[0] + cnt[1]);
    }
    double se_all;
    for (int q = 0; q < NSPEC; q++) {
        r->kT_pv[q] = gs_mean_se(bpv[q], NBLOCK, &r->se_pv[q]);
        r->kT_g[q] = gs_mean_se(bg[q], NBLOCK, &r->se_g[q]);
        gs_mean_se(bd[q], NBLOCK, &r->se_g_minus_pv[q]);
    }
    gs_mean_se(blh, NBLOCK, &r->se_l_minus_h);
    r->kT_fit = gs_mean_se(ball, NBLOCK, &se_all);

    /* histograms: NBIN equiprobable cells per species under the model tested first
     * (Juttner at c = 1, Maxwell-Boltzmann classically) at kT_fit */
    const int model0 = r->inv_c2 > 0.0 ? 0 : 1;
    double edge[NSPEC][NBIN + 1], prob[2][NSPEC][NBIN];
    for (int q = 0; q < NSPEC; q++) {
        edge[q][0] = -INFINITY;
        edge[q][NBIN] = INFINITY;
        for (int k = 1; k < NBIN; k++)
            edge[q][k] = model_quantile(model0, (double)k / NBIN, r->m[q], r->kT_fit);
        for (int md = 0; md < 2; md++)
            for (int k = 0; k < NBIN; k++)
                prob[md][q][k] =
                    (k == NBIN - 1 ? 1.0 : model_cdf(md, edge[q][k + 1], r->m[q], r->kT_fit)) -
                    (k == 0 ? 0.0 : model_cdf(md, edge[q][k], r->m[q], r->kT_fit));
    }
    static double cnt[NBLOCK][NSPEC][NBIN];
    memset(cnt, 0, sizeof cnt);
    double ntot[NSPEC] = {0, 0};
    for (int b = 0; b < NBLOCK; b++)
        for (size_t k = 0; k < ns; k++)
            for (size_t i = 0; i < n; i++) {
                const int q = spec[b * n + i];
                const double p = ps[(b * ns + k) * n + i];
                cnt[b][q][gs_find_cell(edge[q], NBIN, p)] += 1.0;
                ntot[q] += 1.0;
            }
    /* Pearson chi-square of the pooled counts, and the variance inflation phi: the
     * replica-to-replica variance of the counts over the multinomial variance (1 for
     * independent samples; the snapshots of one replica are correlated, so phi > 1) */
    double phi_sum = 0.0;
    int nspec = 0;
    r->chi2[0] = r->chi2[1] = 0.0;
    for (int q = 0; q < NSPEC; q++) {
        if (ntot[q] == 0.0) /* one-species run */
            continue;
        nspec++;
        const double nb = ntot[q] / NBLOCK;
        for (int k = 0; k < NBIN; k++) {
            double var;
            const double tot = gs_pooled_count((const double *)cnt + q * NBIN + k, NBLOCK,
                                                NSPEC * NBIN, &var);
            phi_sum += gs_phi_term(var, nb, prob[model0][q][k]);
            for (int md = 0; md < 2; md++)
                r->chi2[md] += gs_pearson_term(tot, ntot[q] * prob[md][q][k]);
        }
    }
    r->phi = phi_sum / (nspec * NBIN);
    r->dof = nspec * (NBIN - 1) - 1; /* per-species totals fixed, kT fitted */
    free(spec), free(ps);
    return RC_OK;
}

static void print_run(const char *name, const gas_run *r)
{
    printf("  %s: %d replicas of N = %zu, each %d snapshots every %g from t = %g, "
           "%llu events\n", name, NBLOCK, r->n, r->n_snap, r->dt_snap, r->t_eq,
           (unsigned long long)r->events);
    for (int q = 0; q < NSPEC; q++) {
        printf("    m = %g: kT from <p v> = %.5f +- %.5f", r->m[q], r->kT_pv[q], r->se_pv[q]);
        if (r->inv_c2 > 0.0)
            printf(", from <gamma> = %.5f +- %.5f (difference +- %.5f)", r->kT_g[q],
                   r->se_g[q], r->se_g_minus_pv[q]);
        printf("\n");
    }
    printf("    light - heavy (<p v>): %.5f +- %.5f\n", r->kT_pv[0] - r->kT_pv[1],
           r->se_l_minus_h);
    printf("    kT_fit %.5f; chi2/phi vs %s = %.1f, vs %s = %.4g (dof %g, phi %.2f)\n",
           r->kT_fit, r->inv_c2 > 0 ? "Juttner" : "MB", r->chi2[r->inv_c2 > 0 ? 0 : 1] / r->phi,
           r->inv_c2 > 0 ? "MB" : "Juttner(c=1)", r->chi2[r->inv_c2 > 0 ? 1 : 0] / r->phi,
           r->dof, r->phi);
}

/* The reproduction: binary mixture m = 1 and 2 (equal numbers), c = 1, every |v| equal
 * at the start, hot (theta = 1 for the light species, 0.5 for the heavy one). */
static void test_relaxes_to_juttner(void)
{
    gas_run r = {.inv_c2 = 1.0, .m = {1.0, 2.0}, .frac_heavy = 0.5, .kT_target = 1.0,
                 .n = 1000, .n_snap = 100, .t_eq = 500.0, .dt_snap = 10.0, .seed = 2007};
    ENSURE(run_gas(&r) == RC_OK);
    print_run("c = 1 mixture", &r);
    for (int q = 0; q < NSPEC; q++) {
        /* the two thermometers agree within 4 standard errors of their difference (the
         * per-replica differences carry the correlation of the two estimates) plus
         * 2 kT/N: each replica is microcanonical (fixed energy), where <p v> = kT holds
         * exactly but the canonical <gamma>(theta) only to O(1/N) (measured: ~0.5/N) */
        const double fin = 2.0 * r.kT_target / (double)r.n;
        ENSURE_CLOSE(r.kT_g[q], r.kT_pv[q], 1.0, 4.0 * r.se_g_minus_pv[q] + fin);
        /* and are precise enough for that to mean something: the two differ by
         * ~ 0.1 kT between Juttner and a Maxwell-Boltzmann reading of <gamma> */
        ENSURE(r.se_pv[q] < 0.005 && r.se_g[q] < 0.005);
        /* the energy fixes kT = 1 up to the O(1/N) microcanonical shift */
        ENSURE_CLOSE(r.kT_pv[q], r.kT_target, 1.0, 4.0 * r.se_pv[q] + fin);
    }
    /* both species give the same temperature */
    ENSURE_CLOSE(r.kT_pv[0], r.kT_pv[1], 4.0, r.se_l_minus_h);
    /* the histogram fits Juttner and rejects Maxwell-Boltzmann at the same kT */
    ENSURE_MSG(r.chi2[0] / r.phi <= gs_chi2_bound(r.dof), "chi2 %g", r.chi2[0] / r.phi);
    ENSURE_MSG(r.chi2[1] / r.phi >= 100.0 * gs_chi2_bound(r.dof), "chi2 MB %g",
               r.chi2[1] / r.phi);
    /* phi is an honest correction, not a fudge that swallows misfits: the effective
     * sample n/phi stays > 1e5, so a misfit of ~2 % in a cell would still show */
    ENSURE(r.phi > 0.5 && r.phi < 20.0);
}

/* Negative control: one species (equal masses only exchange momenta) never thermalises:
 * every |p| stays the initial one, the Juttner test fails. */
static void test_equal_masses_do_not_relax(void)
{
    gas_run r = {.inv_c2 = 1.0, .m = {1.0, 1.0}, .frac_heavy = 0.0, .kT_target = 1.0,
                 .n = 500, .n_snap = 5, .t_eq = 200.0, .dt_snap = 10.0, .seed = 3007};
    ENSURE(run_gas(&r) == RC_OK);
    printf("  equal masses: chi2/phi vs Juttner = %.4g (phi %.2f), kT from <p v> %.4f, "
           "from <gamma> %.4f\n", r.chi2[0] / r.phi, r.phi, r.kT_pv[0], r.kT_g[0]);
    ENSURE(r.chi2[0] > 100.0 * gs_chi2_bound(r.dof));
    /* all |v| equal: <p v> = gamma m v^2 while <gamma>-theta follows Juttner: they differ */
    ENSURE(fabs(r.kT_pv[0] - r.kT_g[0]) > 0.05);
}

/* Classical counterpart (c = inf): the same mixture relaxes to Maxwell-Boltzmann, and
 * the c = 1 Juttner law at that kT is rejected (it is not the classical equilibrium). */
static void test_classical_relaxes_to_mb(void)
{
    gas_run r = {.inv_c2 = 0.0, .m = {1.0, 2.0}, .frac_heavy = 0.5, .kT_target = 1.0,
                 .n = 500, .n_snap = 40, .t_eq = 400.0, .dt_snap = 20.0, .seed = 4007};
    ENSURE(run_gas(&r) == RC_OK);
    print_run("c = inf mixture", &r);
    ENSURE_CLOSE(r.kT_pv[0], r.kT_pv[1], 4.0, r.se_l_minus_h);
    ENSURE_MSG(r.chi2[1] / r.phi <= gs_chi2_bound(r.dof), "chi2 %g", r.chi2[1] / r.phi);
    ENSURE(r.chi2[0] / r.phi >= 100.0 * gs_chi2_bound(r.dof));
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    ws = gsl_integration_workspace_alloc(1000);
    if (argc > 1 && strcmp(argv[1], "--table") == 0) {
        print_table();
        gsl_integration_workspace_free(ws);
        return 0;
    }
    table_path = argc > 1 ? argv[1] : "data/reproductions/cubero2007-juttner-1d.csv";
    RUN_TEST(test_table);
    RUN_TEST(test_relaxes_to_juttner);
    RUN_TEST(test_equal_masses_do_not_relax);
    RUN_TEST(test_classical_relaxes_to_mb);
    gsl_integration_workspace_free(ws);
    RC_TEST_MAIN_END();
}
