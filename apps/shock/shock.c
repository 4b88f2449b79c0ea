/* shock.c — relcol-shock: the Riemann problem of hard balls. A long box walled at its
 * ends and periodic across holds two Juttner (Maxwell at c = inf) halves, the membrane
 * between them removed at t = 0; the profiles in bins of x at chosen times, over
 * independent seeds, go to profiles.csv beside the ideal fluid's exact solution (Euler at
 * c = inf, relativistic with the Synge equation of state at finite c) and free streaming
 * (Kn -> inf), with summary.json and a figure (papers/shock-tube.md). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "shock_run.h"

static const char *prog = "relcol-shock";

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-shock [--dim 2|3] [--c C] [--n-left N] [--n-right N] [--T-left T]\n"
"                    [--T-right T] [--v-left V] [--v-right V] [--radius R] [--length L]\n"
"                    [--width W] [--times T1,T2,...] [--bins B] [--seeds S] [--seed S0]\n"
"                    [--frame NAME] [--law NAME] [--out DIR] [--quiet]\n"
"The shock tube of hard balls (rest mass 1, k_B = 1): a box [0, L] x [0, W] (x [0, W])\n"
"walled at x = 0 and L, periodic across, a membrane at x = L/2 removed at t = 0; each side\n"
"a Juttner gas (Maxwell at c = inf) at its rest-frame density n, temperature T and\n"
"velocity v along x. Writes DIR/profiles.csv (per time and bin of x: the measured\n"
"n, Eckart velocity v, pressure p = Pxx - v g, transverse pperp, temperatures Tp = p/n and\n"
"Te (from the rest-frame energy), the lab densities N0, Nx, g = T0x/c, K = T00 - N0 c^2,\n"
"Pxx, Pyy, each with its standard error over the seeds, then the ideal fluid's\n"
"(_fluid) and free streaming's (_free) values of each), DIR/summary.json and DIR/shock.png.\n"
"  --dim D        2 or 3 (default 3)\n"
"  --c C          speed of light (default inf)\n"
"  --n-left N     balls per unit volume (area in 2-D), left (default 0.004)\n"
"  --n-right N    right (default 0.002)\n"
"  --T-left T     temperature, left (default 2)\n"
"  --T-right T    right (default 1)\n"
"  --v-left V     table-frame velocity along x, left (default 0)\n"
"  --v-right V    right (default 0)\n"
"  --radius R     ball radius (default 0.5)\n"
"  --length L     tube length (default 4000)\n"
"  --width W      across, >= 4 diameters (default 12)\n"
"  --times LIST   times of the profiles, increasing (default 500,1000)\n"
"  --bins B       bins of x (default 100)\n"
"  --seeds S      independent runs, >= 2 for error bars (default 4)\n"
"  --seed S0      first seed (default 1)\n"
"  --frame NAME   contact frame (default: uncontracted spheres)\n"
"  --law NAME     collision law (default zmf)\n"
"  --out DIR      output folder (default shock-out)\n"
"  --quiet        no summary lines on stdout\n");
}

typedef struct cli {
    sh_opts o;
    const char *out;
    int quiet;
} cli;

static int parse(int argc, char **argv, cli *c)
{
    static const char *const valued[] = {"--dim", "--c", "--n-left", "--n-right", "--T-left",
        "--T-right", "--v-left", "--v-right", "--radius", "--length", "--width", "--times",
        "--bins", "--seeds", "--seed", "--frame", "--law", "--out", NULL};
    static const char *const flags[] = {"--quiet", NULL};
    sh_opts *o = &c->o;
    memset(c, 0, sizeof *c);
    sh_tube *t = &o->tube;
    t->dim = 3, t->c = INFINITY, t->r = 0.5;
    t->n[0] = 0.004, t->n[1] = 0.002, t->T[0] = 2.0, t->T[1] = 1.0;
    double length = 4000.0, width = 12.0;
    o->nt = 2, o->times[0] = 500.0, o->times[1] = 1000.0;
    o->bins = 100, o->seeds = 4, o->seed = 1;
    c->out = "shock-out";
    app_opts it;
    app_opts_init(&it, prog, argc, argv, valued, flags, "see --help");
    const char *name, *val;
    char err[APP_ERR_LEN], buf[512];
    int k;
    while ((k = app_opts_next(&it, &name, &val)) != APP_OPT_END) {
        if (k == APP_OPT_ERROR)
            return 2;
        if (k == APP_OPT_HELP)
            return app_help(usage) ? 1 : -1;
        if (k == APP_OPT_FLAG) {
            c->quiet = 1;
            continue;
        }
        double x = 0.0;
        long l = 0;
        int bad = 0;
        if (!strcmp(name, "--dim")) {
            bad = app_parse_long(val, 2, 3, &l, err);
            t->dim = (int)l;
        } else if (!strcmp(name, "--bins")) {
            bad = app_parse_long(val, 1, 100000, &l, err);
            o->bins = (int)l;
        } else if (!strcmp(name, "--seeds")) {
            bad = app_parse_long(val, 1, 100000, &l, err);
            o->seeds = (int)l;
        } else if (!strcmp(name, "--seed")) {
            bad = app_parse_u64(val, &o->seed, err);
        } else if (!strcmp(name, "--times")) {
            bad = app_parse_list(val, o->times, SH_MAX_TIMES, &o->nt, err);
            for (int j = 0; !bad && j < o->nt; j++)
                if (!(o->times[j] > 0.0) || (j && !(o->times[j] > o->times[j - 1]))) {
                    app_errf(err, "times must be > 0 and increasing");
                    bad = -1;
                }
        } else if (!strcmp(name, "--frame")) {
            t->frame = rc_toi_frame_find(val);
            if (!t->frame)
                return app_fail(prog, 2, "--frame: unknown frame '%s' (known: %s)", val,
                                app_toi_frame_list(buf, sizeof buf));
        } else if (!strcmp(name, "--law")) {
            t->law = rc_law_find(val);
            if (!t->law)
                return app_fail(prog, 2, "--law: unknown law '%s' (known: %s)", val,
                                app_law_list(buf, sizeof buf));
        } else if (!strcmp(name, "--out")) {
            c->out = val;
        } else {
            bad = app_parse_double(val, !strcmp(name, "--c"), &x, err);
            if (!bad && !strcmp(name, "--c"))
                bad = app_check_c(x, err);
            else if (!bad && (!strncmp(name, "--v-", 4) ? 0 : !(x > 0.0))) {
                app_errf(err, "%s must be > 0", val);
                bad = -1;
            }
            if (!bad) {
                if (!strcmp(name, "--c")) t->c = x;
                else if (!strcmp(name, "--n-left")) t->n[0] = x;
                else if (!strcmp(name, "--n-right")) t->n[1] = x;
                else if (!strcmp(name, "--T-left")) t->T[0] = x;
                else if (!strcmp(name, "--T-right")) t->T[1] = x;
                else if (!strcmp(name, "--v-left")) t->v[0] = x;
                else if (!strcmp(name, "--v-right")) t->v[1] = x;
                else if (!strcmp(name, "--radius")) t->r = x;
                else if (!strcmp(name, "--length")) length = x;
                else if (!strcmp(name, "--width")) width = x;
            }
        }
        if (bad)
            return app_fail(prog, 2, "%s: %s", name, err);
    }
    for (int s = 0; s < 2; s++)
        if (!(fabs(t->v[s]) < t->c))
            return app_fail(prog, 2, "--v-%s: |v| = %g must be < c", s ? "right" : "left", fabs(t->v[s]));
    if (width < 8.0 * t->r)
        return app_fail(prog, 2, "--width: %g is below four ball diameters (%g): the periodic "
                        "axes need four cells", width, 8.0 * t->r);
    t->box.x = length, t->box.y = width, t->box.z = t->dim == 3 ? width : 0.0;
    t->x0 = 0.5 * length;
    return 0;
}

/* dir/name opened for an atomic write */
static int open_out(const char *dir, const char *name, app_atomic *a, char *err)
{
    char *path = app_path_join(dir, name);
    if (!path) {
        app_errf(err, "out of memory");
        return -1;
    }
    int rc = app_atomic_open(a, path, err);
    free(path);
    return rc;
}

static int write_csv(const char *dir, const sh_opts *o, const sh_result *r, char *err)
{
    app_atomic a;
    if (open_out(dir, "profiles.csv", &a, err))
        return -1;
    fprintf(a.f, "t,x,xi");
    for (int q = 0; q < SH_NQ; q++)
        fprintf(a.f, ",%s,%s_err", sh_q_names[q], sh_q_names[q]);
    for (int q = 0; q < SH_NQ; q++)
        fprintf(a.f, ",%s_fluid", sh_q_names[q]);
    for (int q = 0; q < SH_NQ; q++)
        fprintf(a.f, ",%s_free", sh_q_names[q]);
    fputc('\n', a.f);
    for (int j = 0; j < r->nt; j++)
        for (int k = 0; k < r->nb; k++) {
            const double t = o->times[j];
            fprintf(a.f, "%.17g,%.17g,%.17g", t, r->xc[k], (r->xc[k] - o->tube.x0) / t);
            for (int q = 0; q < SH_NQ; q++)
                fprintf(a.f, ",%.10g,%.4g", r->mean[sh_idx(r, j, k, q)], r->err[sh_idx(r, j, k, q)]);
            for (int q = 0; q < SH_NQ; q++)
                fprintf(a.f, ",%.10g", r->fluid[sh_idx(r, j, k, q)]);
            for (int q = 0; q < SH_NQ; q++)
                fprintf(a.f, ",%.10g", r->freestr[sh_idx(r, j, k, q)]);
            fputc('\n', a.f);
        }
    return app_atomic_commit(&a, err);
}

static void jnum(FILE *f, const char *key, double x, int comma)
{
    if (isfinite(x))
        fprintf(f, "\"%s\": %.17g%s", key, x, comma ? ", " : "");
    else
        fprintf(f, "\"%s\": null%s", key, comma ? ", " : "");
}

static void jve(FILE *f, const char *key, double v, double e, double ref, int comma)
{
    fprintf(f, "\"%s\": {", key);
    jnum(f, "value", v, 1);
    jnum(f, "err", e, 1);
    jnum(f, "fluid", ref, 1);
    jnum(f, "rel_diff", v / ref - 1.0, 0);
    fprintf(f, "}%s", comma ? ",\n    " : "");
}

/* summary.json: parameters, the references' waves, where the seeds stand against the
 * rigid-ball model's regime ("model", relcol/validity.h: the seed of largest p_model,
 * with the fields relcol-sim writes), per time the comparisons. */
static int write_summary(const char *dir, const cli *c, const sh_result *r, char *err)
{
    const sh_opts *o = &c->o;
    const sh_tube *t = &o->tube;
    app_atomic a;
    if (open_out(dir, "summary.json", &a, err))
        return -1;
    FILE *f = a.f;
    fprintf(f, "{\n  \"relcol\": 1, \"program\": \"%s\",\n  \"parameters\": {", prog);
    fprintf(f, "\"dim\": %d, ", t->dim);
    jnum(f, "c", isinf(t->c) ? NAN : t->c, 1);
    fprintf(f, "\"c_infinite\": %s, ", isinf(t->c) ? "true" : "false");
    jnum(f, "n_left", t->n[0], 1), jnum(f, "n_right", t->n[1], 1);
    jnum(f, "T_left", t->T[0], 1), jnum(f, "T_right", t->T[1], 1);
    jnum(f, "v_left", t->v[0], 1), jnum(f, "v_right", t->v[1], 1);
    jnum(f, "radius", t->r, 1), jnum(f, "length", t->box.x, 1), jnum(f, "width", t->box.y, 1);
    fprintf(f, "\"bins\": %d, \"seeds\": %d, \"seed\": %llu, \"balls\": %zu, \"frame\": \"%s\", "
               "\"law\": \"%s\", \"velocity\": \"Eckart\"},\n",
            o->bins, o->seeds, (unsigned long long)o->seed, r->nballs,
            t->frame ? t->frame->name : "sphere", t->law ? t->law->name : "zmf");
    const rs_solution *s = &r->sol;
    fprintf(f, "  \"fluid\": {\"eos\": \"%s\", ", isinf(t->c) ? "ideal gas, gamma = 1 + 2/d" :
            (t->dim == 3 ? "Synge, h = K3/K2" : "Synge (discs), h = K_5/2/K_3/2"));
    jnum(f, "p_star", s->p_star, 1), jnum(f, "v_star", s->v_star, 1);
    jnum(f, "n_star_left", s->rho_starL, 1), jnum(f, "n_star_right", s->rho_starR, 1);
    fprintf(f, "\"wave_left\": \"%s\", \"wave_right\": \"%s\", ",
            s->waveL == RS_SHOCK ? "shock" : "rarefaction", s->waveR == RS_SHOCK ? "shock" : "rarefaction");
    jnum(f, "head_left", s->headL, 1), jnum(f, "tail_left", s->tailL, 1);
    jnum(f, "head_right", s->headR, 1), jnum(f, "tail_right", s->tailR, 0);
    fprintf(f, "},\n  \"knudsen\": {");
    jnum(f, "mfp_left", r->lambda[0], 1), jnum(f, "mfp_right", r->lambda[1], 1);
    jnum(f, "mfp_plateau", r->lambda_star, 1), jnum(f, "kn", r->kn, 0);
    fprintf(f, "},\n  \"collisions\": %llu,\n", (unsigned long long)r->collisions);
    if (r->model_ok) {
        const rc_validity *v = &r->model;
        fprintf(f, "  \"model\": {\"verdict\": \"%s\", \"seeds\": %d, \"seeds_outside\": %d, "
                   "\"covariant\": %s, ", v->verdict_name, r->seeds, r->seeds_outside,
                v->covariant ? "true" : "false");
        jnum(f, "threshold_p_model", v->threshold, 1), jnum(f, "p_model", v->p_model, 1);
        jnum(f, "p_all", v->p_all, 1), jnum(f, "largest_cluster", v->largest_model, 1);
        jnum(f, "largest_cluster_all", v->largest_all, 1), jnum(f, "nu_r_c", v->nu_r_c, 1);
        jnum(f, "policy_share", v->policy_share, 1);
        fprintf(f, "\"policy\": %llu, \"collisions\": %llu, \"tube_conflicts\": %llu, "
                   "\"order_conflicts\": %llu, \"undone\": %llu, \"kink_events\": %llu, "
                   "\"kink_pairs\": %llu, \"kink_pairs_model\": %llu, \"crossing\": %llu, "
                   "\"crossing_model\": %llu},\n",
                (unsigned long long)v->policy, (unsigned long long)v->collisions,
                (unsigned long long)v->tube_conflicts, (unsigned long long)v->order_conflicts,
                (unsigned long long)v->undone, (unsigned long long)v->kink_events,
                (unsigned long long)v->kink_pairs, (unsigned long long)v->kink_pairs_model,
                (unsigned long long)v->crossing, (unsigned long long)v->crossing_model);
    }
    fprintf(f, "  \"shock_speed\": {");
    jnum(f, "value", r->vshock, 1), jnum(f, "err", r->vshock_err, 1);
    jnum(f, "fluid", s->headR, 1), jnum(f, "rel_diff", r->vshock / s->headR - 1.0, 1);
    fprintf(f, "\"estimator\": \"(x_s - x0)/t at the last time, x_s the logistic front's "
               "mid-level point\"},\n  \"shock_speed_local\": {");
    jnum(f, "value", r->vshock_local, 1), jnum(f, "err", r->vshock_local_err, 1);
    jnum(f, "fluid", s->headR, 1), jnum(f, "rel_diff", r->vshock_local / s->headR - 1.0, 1);
    fprintf(f, "\"estimator\": \"least-squares slope of x_s over the times\"},\n  \"times\": [");
    static const char *const cn[3] = {"N0", "g", "Pxx"};
    for (int j = 0; j < r->nt; j++) {
        fprintf(f, "%s\n   {", j ? "," : "");
        jnum(f, "t", o->times[j], 1);
        fprintf(f, "\"plateau_bins\": %d,\n    ", r->plat_bins[j]);
        jve(f, "plateau_p", r->plat_p[j], r->plat_p_err[j], s->p_star, 1);
        jve(f, "plateau_v", r->plat_v[j], r->plat_v_err[j], s->v_star, 1);
        jve(f, "shock_x", r->xshock[j], r->xshock_err[j], t->x0 + s->headR * o->times[j], 1);
        jnum(f, "shock_width", r->wshock[j], 1);
        fprintf(f, "\"free_streaming_chi2\": {");
        for (int q = 0; q < 3; q++) {
            fprintf(f, "\"%s\": {", cn[q]);
            jnum(f, "chi2", r->chi2[j][q], 1);
            fprintf(f, "\"bins\": %d, ", r->dof[j][q]);
            jnum(f, "p", r->pval[j][q], 0);
            fprintf(f, "}%s", q < 2 ? ", " : "");
        }
        fprintf(f, "}}");
    }
    fprintf(f, "\n  ]\n}\n");
    return app_atomic_commit(&a, err);
}

/* the column of a quantity in profiles.csv (1-based): 3 + 2q + 1 measured, +1 its error */
static int col_meas(int q) { return 4 + 2 * q; }
static int col_fluid(int q) { return 4 + 2 * SH_NQ + q; }
static int col_free(int q) { return 4 + 3 * SH_NQ + q; }

static int write_gp(const char *dir, const sh_opts *o, char *err)
{
    app_atomic a;
    if (open_out(dir, "shock.gp", &a, err))
        return -1;
    FILE *f = a.f;
    app_gnuplot_head(f, "shock.png", "size 1500,900 enhanced font 'Sans,11' linewidth 1.3", 0);
    static const int panels[6] = {SH_N, SH_V, SH_P, SH_TP, SH_RAW + 3, SH_RAW + 2};
    static const char *const ylab[6] = {"rest density n", "Eckart velocity v", "pressure p = P_{xx} - v g",
                                        "T_p = p/n (points), T_e (open)", "K = T^{00} - N^0 m c^2",
                                        "g = T^{0x}/c"};
    fprintf(f, "set multiplot layout 2,3 title 'relcol-shock: %d-D, c = %g; points: balls (seed "
               "errors), lines: ideal fluid, dashed: free streaming'\n",
            o->tube.dim, o->tube.c);
    fprintf(f, "set xlabel 'x'\nset key top right font ',9'\n");
    for (int p = 0; p < 6; p++) {
        const int q = panels[p];
        fprintf(f, "set ylabel '%s'\nplot ", ylab[p]);
        for (int j = 0; j < o->nt; j++) {
            const double t = o->times[j];
            fprintf(f, "%s'profiles.csv' skip 1 using 2:($1==%.17g?$%d:1/0):%d with yerrorbars "
                       "pt 7 ps 0.4 lc %d title 't = %g', "
                       "'' skip 1 using 2:($1==%.17g?$%d:1/0) with lines lc %d notitle, "
                       "'' skip 1 using 2:($1==%.17g?$%d:1/0) with lines dt 2 lc %d notitle",
                    j ? ", " : "", t, col_meas(q), col_meas(q) + 1, j + 1, t, t, col_fluid(q),
                    j + 1, t, col_free(q), j + 1);
            if (q == SH_TP)
                fprintf(f, ", '' skip 1 using 2:($1==%.17g?$%d:1/0) with points pt 6 ps 0.5 lc %d notitle",
                        t, col_meas(SH_TE), j + 1);
        }
        fputc('\n', f);
    }
    fprintf(f, "unset multiplot\n");
    return app_atomic_commit(&a, err);
}

int main(int argc, char **argv)
{
    app_init(prog);
    cli c;
    int rc = parse(argc, argv, &c);
    if (rc)
        return rc < 0 ? 0 : rc;
    char err[APP_ERR_LEN];
    if (app_mkdir_p(c.out, err))
        return app_fail(prog, 1, "--out: %s", err);
    sh_result r;
    if (sh_run(&c.o, &r, !c.quiet, err))
        return app_fail(prog, 1, "%s", err);
    if (write_csv(c.out, &c.o, &r, err) || write_summary(c.out, &c, &r, err) ||
        write_gp(c.out, &c.o, err)) {
        sh_result_free(&r);
        return app_fail(prog, 1, "%s", err);
    }
    app_validity_warn(stderr, prog); /* one line, when a seed was outside the model's regime */
    int made = 0;
    if (app_gnuplot_run(prog, c.out, "shock.gp", "shock.png", &made, err)) {
        sh_result_free(&r);
        return app_fail(prog, 1, "gnuplot: %s", err);
    }
    if (!c.quiet) {
        const rs_solution *s = &r.sol;
        printf("%zu balls, %d seeds, %llu collisions; Kn = %.3g (plateau mean free path %.4g)\n",
               r.nballs, r.seeds, (unsigned long long)r.collisions, r.kn, r.lambda_star);
        for (int j = 0; j < r.nt; j++)
            printf("t = %g: plateau p = %.5g +- %.2g (fluid %.5g), v = %.5g +- %.2g (fluid %.5g); "
                   "free-streaming chi2/bins N0 %.1f/%d g %.1f/%d Pxx %.1f/%d\n",
                   c.o.times[j], r.plat_p[j], r.plat_p_err[j], s->p_star, r.plat_v[j],
                   r.plat_v_err[j], s->v_star, r.chi2[j][0], r.dof[j][0], r.chi2[j][1],
                   r.dof[j][1], r.chi2[j][2], r.dof[j][2]);
        printf("shock speed %.5g +- %.2g (fluid %.5g; mean since t = 0), local %.5g +- %.2g\n",
               r.vshock, r.vshock_err, s->headR, r.vshock_local, r.vshock_local_err);
        printf("wrote %s/profiles.csv, summary.json, shock.gp%s\n", c.out, made ? ", shock.png" : "");
    }
    sh_result_free(&r);
    return 0;
}
