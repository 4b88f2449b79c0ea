/* gas_moving.c — relcol-gas --observer-velocity (gas_moving.h): the engine stepped on a
 * grid of table times fine enough that a ball rarely collides twice in one step, every
 * ball's worldline rebuilt and sampled where it crosses the observer's hyperplanes; the
 * observer's p'_x histogram beside the boosted and the unboosted Jüttner laws. The 1-D
 * mixture is followed event by event instead (exact: nothing lost), per species. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "boosted.h"
#include "gas_moving.h"
#include "gas_observer.h"
#include "gas_stats.h"

enum { MB = 10, MR = 8, MA = 8, MH = 50 };

/* Marginal density of p'_x of the law at (theta, V): Int f' dp'_y, normalised by norm. */
static double px_density(double theta, double V, double px, double norm)
{
    const double ymax = bj_umax(theta, V);
    enum { K = 400 };
    double s = 0.0;
    for (int k = 0; k < K; k++) { /* midpoint rule, the density is smooth and decays */
        const double y = ymax * (k + 0.5) / K;
        s += bj_density(theta, V, px, y);
    }
    return 2.0 * s * ymax / K / norm;
}

/* px_density as a gsl_function; par: theta, V, norm */
static double px_density_fn(double px, void *par)
{
    const double *q = par;
    return px_density(q[0], q[1], px, q[2]);
}

static double law_norm(double theta, double V)
{
    const double u = bj_umax(theta, V);
    enum { K = 800 };
    double s = 0.0;
    for (int k = 0; k < K; k++) {
        const double px = -u + 2.0 * u * (k + 0.5) / K;
        s += px_density(theta, V, px, 1.0);
    }
    return s * 2.0 * u / K;
}

static int write_files(const char *prog, const char *dir, const double *mom, size_t rows,
                       size_t n, double theta, double V, gas_moving_result *r, char *err)
{
    /* histogram range: where the boosted law's p'_x lives (both tails to ~1e-4) */
    const double gV = 1.0 / sqrt((1.0 - V) * (1.0 + V));
    const double w = 8.0 * gV * sqrt(theta * (1.0 + theta)) + 2.0;
    const double lo = -gV * V * (1.0 + 2.0 * theta) - w, hi = lo + 2.0 * w;
    double h[MH] = {0}, tot = 0.0;
    for (size_t k = 0; k < rows * n; k++) {
        if (isnan(mom[2 * k]))
            continue;
        tot += 1.0;
        const int b = (int)floor((mom[2 * k] - lo) / (hi - lo) * MH);
        if (b >= 0 && b < MH)
            h[b] += 1.0;
    }
    const double nb = law_norm(theta, V), n0 = law_norm(theta, 0.0), bw = (hi - lo) / MH;
    char *csv = app_path_join(dir, "observer.csv"), *gp = app_path_join(dir, "observer.gp");
    int rc = -1;
    app_atomic a;
    if (!csv || !gp) {
        app_errf(err, "out of memory");
        goto out;
    }
    if (app_atomic_open(&a, csv, err) != 0)
        goto out;
    fprintf(a.f, "px_lo,px_hi,px_mid,density,density_err,boosted_juttner,juttner_at_rest\n");
    /* the laws as bin means, as the histogram is */
    gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc(20);
    double qb[3] = {theta, V, nb}, q0[3] = {theta, 0.0, n0};
    const gsl_function Fb = {px_density_fn, qb}, F0 = {px_density_fn, q0};
    if (!gl) {
        app_atomic_abort(&a);
        app_errf(err, "out of memory");
        goto out;
    }
    for (int b = 0; b < MH; b++) {
        const double x0 = lo + bw * b, xm = x0 + 0.5 * bw;
        fprintf(a.f, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", x0, x0 + bw, xm,
                h[b] / tot / bw, sqrt(h[b] * r->phi) / tot / bw,
                bj_bin_mean(&Fb, x0, x0 + bw, gl), bj_bin_mean(&F0, x0, x0 + bw, gl));
    }
    gsl_integration_glfixed_table_free(gl);
    if (app_atomic_commit(&a, err) != 0)
        goto out;
    if (app_atomic_open(&a, gp, err) != 0)
        goto out;
    fprintf(a.f, "# observer.gp — written by relcol-gas --observer-velocity; run `gnuplot "
                 "observer.gp` in this folder.\n# The x momentum seen by an observer moving "
                 "at V along x, sampled on its simultaneity hyperplanes, against the boosted "
                 "Jüttner law and the law at rest.\n");
    app_gnuplot_head(a.f, "observer.png", "size 900,620 enhanced font 'Sans,12' linewidth 1.4", 0);
    fprintf(a.f,
            "set title \"Gas seen by an observer moving at %g c: p'_x on its hyperplanes\\n"
            "{/*0.8 θ = %.4f, χ²/φ = %.1f for %g dof against boosted Jüttner}\"\n"
            "set xlabel \"p'_x / (m c)\"\nset ylabel 'probability density'\nset grid\n"
            "set key top right box opaque\n"
            "plot 'observer.csv' skip 1 using 3:4:5 with yerrorbars pt 7 ps 0.5 lc rgb "
            "'#1f77b4' title 'balls on the hyperplanes', \\\n"
            "     '' skip 1 using 3:6 with lines lw 2 lc rgb '#d62728' title 'boosted Jüttner', \\\n"
            "     '' skip 1 using 3:7 with lines lw 2 dt 2 lc rgb '#2ca02c' title 'Jüttner at rest'\n",
            V, theta, r->chi2, r->dof);
    if (app_atomic_commit(&a, err) != 0)
        goto out;
    rc = app_gnuplot_run(prog, dir, "observer.gp", "observer.png", &r->made_png, err);
out:
    free(csv);
    free(gp);
    return rc;
}

int gas_moving_run(const char *prog, rc_sim *s, size_t n, double c, double V, double theta,
                   double t0, double dtau, long nplanes, rc_vec3 box, const char *dir,
                   gas_moving_result *res, char *err)
{
    memset(res, 0, sizeof *res);
    res->v = V / c;
    rc_sim_ball *b = malloc(n * sizeof *b);
    /* the first hyperplane reaches into the box at t0 for either sign of V */
    const double tau0 = t0 - fmin(0.0, V * box.x / (c * c));
    gas_obs *o = gas_obs_create(n, c, V, tau0, dtau, (size_t)nplanes);
    int rc = -1, st = RC_OK;
    if (!b || !o) {
        app_errf(err, "out of memory (observer)");
        goto out;
    }
    /* the grid: a fortieth of a ball's mean time between collisions over the run so far */
    rc_sim_diag dg;
    if ((st = rc_sim_diagnostics(s, &dg)) != RC_OK)
        goto engine;
    const double nu = 2.0 * (double)dg.collisions / ((double)n * rc_sim_time(s));
    if (!(nu > 0.0)) {
        app_errf(err, "--observer-velocity: no collisions before the sample: nothing to "
                      "rebuild worldlines from (raise --t-equil)");
        goto out;
    }
    res->step = 0.025 / nu;
    double ta, tb;
    gas_obs_window(o, box.x, &ta, &tb);
    const double L[3] = {box.x, box.y, box.z};
    const long nstep = (long)ceil((tb - ta) / res->step) + 1;
    for (long k = 0; k <= nstep; k++) {
        if ((st = rc_sim_advance(s, ta + res->step * (double)k, 0)) != RC_OK)
            goto engine;
        for (size_t i = 0; i < n; i++)
            rc_sim_get_ball(s, i, &b[i]);
        if (gas_obs_record(o, ta + res->step * (double)k, b, L) != 0) {
            app_errf(err, "observer: a worldline contradicts the engine's state");
            goto out;
        }
    }
    gas_obs_counts(o, &res->sampled, &res->lost);
    /* chi-square in blocks of consecutive hyperplanes */
    double edge[MR + 1], prob[MR * MA], edge0[MR + 1], prob0[MR * MA];
    if (bj_cells(theta, res->v, MR, MA, edge, prob) != 0 ||
        bj_cells(theta, 0.0, MR, MA, edge0, prob0) != 0) {
        app_errf(err, "out of memory (observer)");
        goto out;
    }
    static double cnt[MB][MR * MA], cnt0[MB][MR * MA];
    memset(cnt, 0, sizeof cnt);
    memset(cnt0, 0, sizeof cnt0);
    const double *mom = gas_obs_momenta(o);
    const size_t per = (size_t)nplanes / MB;
    double ntot = 0.0;
    for (size_t j = 0; j < per * MB; j++)
        for (size_t i = 0; i < n; i++) {
            const double *m = mom + 2 * (j * n + i);
            if (isnan(m[0]))
                continue;
            cnt[j / per][bj_cell_of(edge, MR, MA, m[0], m[1])] += 1.0;
            cnt0[j / per][bj_cell_of(edge0, MR, MA, m[0], m[1])] += 1.0;
            ntot += 1.0;
        }
    double x, y, x0, y0;
    res->phi = gs_chi2_two_models(&cnt[0][0], MB, MR * MA, ntot, prob, prob, &x, &y);
    const double phi0 = gs_chi2_two_models(&cnt0[0][0], MB, MR * MA, ntot, prob0, prob0, &x0, &y0);
    (void)phi0;
    res->chi2 = x / res->phi;
    res->chi2_rest = x0 / res->phi;
    res->dof = MR * MA - 1;
    rc = write_files(prog, dir, mom, (size_t)nplanes, n, theta, res->v, res, err);
    goto out;
engine:
    app_errf(err, "engine: %s", rc_strerror(st));
out:
    gas_obs_free(o);
    free(b);
    return rc;
}

/* ---- 1-D: the mixture, event by event ------------------------------------------------ */

enum { MC1 = 20, MH1 = 80 }; /* cells per species, equiprobable under its boosted law;
                               * figure bins per species */

static int write_files_1d(const char *prog, const char *dir, const double *mom, size_t rows,
                          size_t n, const unsigned char *spec, gas_moving_result *r, char *err)
{
    /* histogram range per species: the laws' rapidities to e^-8 of their peaks */
    double lo[2], hi[2], h[2][MH1], tot[2] = {0.0, 0.0};
    memset(h, 0, sizeof h);
    for (int q = 0; q < r->nspec; q++) {
        const double Y = acosh(1.0 + 8.0 * r->sp_theta[q]), eta = atanh(r->v);
        lo[q] = sinh(fmin(-eta, 0.0) - Y); /* both laws, boosted and at rest */
        hi[q] = sinh(fmax(-eta, 0.0) + Y);
    }
    for (size_t k = 0; k < rows * n; k++) {
        const int q = spec[k % n];
        if (isnan(mom[2 * k]))
            continue;
        tot[q] += 1.0;
        const int b = (int)floor((mom[2 * k] - lo[q]) / (hi[q] - lo[q]) * MH1);
        if (b >= 0 && b < MH1)
            h[q][b] += 1.0;
    }
    char *csv = app_path_join(dir, "observer.csv"), *gp = app_path_join(dir, "observer.gp");
    int rc = -1;
    app_atomic a;
    if (!csv || !gp) {
        app_errf(err, "out of memory");
        goto out;
    }
    if (app_atomic_open(&a, csv, err) != 0)
        goto out;
    fprintf(a.f, "species,mass,theta,p_lo,p_hi,p_mid,density,density_err,boosted_juttner,"
                 "juttner_at_rest\n");
    /* the laws as bin means, as the histogram is */
    gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc(20);
    if (!gl) {
        app_atomic_abort(&a);
        app_errf(err, "out of memory");
        goto out;
    }
    for (int q = 0; q < r->nspec; q++) {
        const double bw = (hi[q] - lo[q]) / MH1;
        double tb[2] = {r->sp_theta[q], r->v}, t0[2] = {r->sp_theta[q], 0.0};
        const gsl_function Fb = {bj1_density_fn, tb}, F0 = {bj1_density_fn, t0};
        for (int b = 0; b < MH1; b++) {
            const double x0 = lo[q] + bw * b, xm = x0 + 0.5 * bw;
            fprintf(a.f, "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", q,
                    r->sp_mass[q], r->sp_theta[q], x0, x0 + bw, xm, h[q][b] / tot[q] / bw,
                    sqrt(h[q][b] * r->sp_phi[q]) / tot[q] / bw,
                    bj_bin_mean(&Fb, x0, x0 + bw, gl), bj_bin_mean(&F0, x0, x0 + bw, gl));
        }
    }
    gsl_integration_glfixed_table_free(gl);
    if (app_atomic_commit(&a, err) != 0)
        goto out;
    if (app_atomic_open(&a, gp, err) != 0)
        goto out;
    fprintf(a.f, "# observer.gp — written by relcol-gas --dim 1 --observer-velocity; run "
                 "`gnuplot observer.gp` in this folder.\n# The momentum p'/(m c) of each "
                 "species seen by an observer moving at V, sampled on its simultaneity "
                 "hyperplanes, against the boosted Jüttner law and the law at rest.\n");
    app_gnuplot_head(a.f, "observer.png", "size 1400,620 enhanced font 'Sans,12' linewidth 1.4",
                     0);
    fprintf(a.f,
            "set multiplot layout 1,2 title \"1-D mixture seen by an observer moving at %g c: "
            "p' on its hyperplanes\\n{/*0.8 χ²/φ = %.1f for %g dof against boosted Jüttner "
            "(both species)}\"\n"
            "set xlabel \"p' / (m c)\"\nset ylabel 'probability density'\nset grid\n"
            "set yrange [0:*]\nset key top %s box opaque\n", r->v, r->chi2, r->dof,
            r->v > 0.0 ? "left" : "right"); /* the side the law leans away from */
    for (int q = 0; q < r->nspec; q++)
        fprintf(a.f,
                "set title 'm = %g, θ = %.4f'\n"
                "plot 'observer.csv' skip 1 using ($1 == %d ? $6 : 1/0):7:8 with yerrorbars "
                "pt 7 ps 0.5 lc rgb '#1f77b4' title 'particles on the hyperplanes', \\\n"
                "     '' skip 1 using ($1 == %d ? $6 : 1/0):9 with lines lw 2 lc rgb '#d62728' "
                "title 'boosted Jüttner', \\\n"
                "     '' skip 1 using ($1 == %d ? $6 : 1/0):10 with lines lw 2 dt 2 lc rgb "
                "'#2ca02c' title 'Jüttner at rest'\n",
                r->sp_mass[q], r->sp_theta[q], q, q, q);
    fprintf(a.f, "unset multiplot\n");
    if (app_atomic_commit(&a, err) != 0)
        goto out;
    rc = app_gnuplot_run(prog, dir, "observer.gp", "observer.png", &r->made_png, err);
out:
    free(csv);
    free(gp);
    return rc;
}

int gas_moving_run_1d(const char *prog, rc_gas1d *g, size_t n, const unsigned char *spec,
                      const double *mass, const double *theta, double c, double V,
                      double t0, double dtau, long nplanes, double L, const char *dir,
                      gas_moving_result *res, char *err)
{
    memset(res, 0, sizeof *res);
    res->v = V / c;
    res->step = NAN;
    res->phi = NAN;
    res->nspec = 2;
    const double tau0 = t0 - fmin(0.0, V * L / (c * c));
    gas_obs *o = gas_obs_create(n, c, V, tau0, dtau, (size_t)nplanes);
    int rc = -1;
    if (!o) {
        app_errf(err, "out of memory (observer)");
        return -1;
    }
    if (gas_obs_follow_gas1d(o, g, L) != 0) {
        app_errf(err, "observer: a 1-D worldline contradicts the engine's events");
        goto out;
    }
    gas_obs_counts(o, &res->sampled, &res->lost);
    const double *mom = gas_obs_momenta(o);
    const size_t per = (size_t)nplanes / MB;
    double *series = malloc((size_t)nplanes * sizeof *series);
    if (!series) {
        app_errf(err, "out of memory (observer)");
        goto out;
    }
    for (size_t j = 0; j < (size_t)nplanes; j++) {
        series[j] = 0.0;
        for (size_t i = 0; i < n; i++) {
            const double u = mom[2 * (j * n + i)];
            series[j] += mass[spec[i]] * sqrt(1.0 + u * u);
        }
    }
    res->tau = gs_tau_int(series, per * MB);
    free(series);
    for (int q = 0; q < res->nspec; q++) {
        res->sp_mass[q] = mass[q];
        res->sp_theta[q] = theta[q];
        double edge[MC1 + 1], prob[MC1], edge0[MC1 + 1], prob0[MC1];
        if (bj1_cells(res->sp_theta[q], res->v, MC1, edge, prob) != 0 ||
            bj1_cells(res->sp_theta[q], 0.0, MC1, edge0, prob0) != 0) {
            app_errf(err, "observer: the boosted law's cells failed (theta %g)",
                     res->sp_theta[q]);
            goto out;
        }
        double cnt[MB][MC1], cnt0[MB][MC1], ntot = 0.0;
        memset(cnt, 0, sizeof cnt);
        memset(cnt0, 0, sizeof cnt0);
        for (size_t j = 0; j < per * MB; j++)
            for (size_t i = 0; i < n; i++) {
                const double u = mom[2 * (j * n + i)];
                if (spec[i] != q || isnan(u))
                    continue;
                cnt[j / per][bj1_cell_of(edge, MC1, u)] += 1.0;
                cnt0[j / per][bj1_cell_of(edge0, MC1, u)] += 1.0;
                ntot += 1.0;
            }
        double x, y, x0, y0;
        res->sp_phi[q] = gs_chi2_two_models(&cnt[0][0], MB, MC1, ntot, prob, prob, &x, &y);
        gs_chi2_two_models(&cnt0[0][0], MB, MC1, ntot, prob0, prob0, &x0, &y0);
        res->sp_chi2[q] = x / res->sp_phi[q];
        res->sp_chi2_rest[q] = x0 / res->sp_phi[q];
        res->sp_dof[q] = MC1 - 1; /* the species' total fixed; theta from the resting gas */
        res->chi2 += res->sp_chi2[q];
        res->chi2_rest += res->sp_chi2_rest[q];
        res->dof += res->sp_dof[q];
    }
    rc = write_files_1d(prog, dir, mom, (size_t)nplanes, n, spec, res, err);
out:
    gas_obs_free(o);
    return rc;
}
