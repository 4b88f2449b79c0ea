/* shock.c — relcol-shock: the Riemann problem of hard balls. A long box walled at its
 * ends and periodic across holds two Juttner (Maxwell at c = inf) halves, the membrane
 * between them removed at t = 0; the profiles in bins of x at chosen times, over
 * independent seeds, go to profiles.csv beside the ideal fluid's exact solution (Euler at
 * c = inf, relativistic with the Synge equation of state at finite c) and free streaming
 * (Kn -> inf), with summary.json and a figure (papers/shock-tube.md). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "gif.h"
#include "kn_scan.h"
#include "shock_run.h"
#include "sweep.h"

static const char *const prog = "relcol-shock";

enum { EXIT_BAD = 2, SH_MAX_SWEEP = 16 };

typedef struct cli {
    sh_opts o;
    double length, width;
    const char *out;
    int quiet;
    int c_given;                 /* --c was given (refused beside --sweep-c) */
    int nsweep;                  /* --sweep-c's count (0: one run at --c) */
    double sweep[SH_MAX_SWEEP];  /* its speeds of light, inf allowed */
    int r_given;                 /* --radius was given (refused beside --kn-scan) */
    int nkn;                     /* --kn-scan's count (0: one run at --radius) */
    double kn[SH_MAX_KN];        /* its Knudsen numbers, increasing */
    int gif;                     /* --gif: the profiles over time as an animated GIF */
} cli;

/* --times: every time > 0 and each above the one before */
static int valid_times(const app_opt *o, const void *opts, char *err)
{
    (void)o;
    const sh_opts *so = &((const cli *)opts)->o;
    for (int j = 0; j < so->nt; j++)
        if (!(so->times[j] > 0.0) || (j && !(so->times[j] > so->times[j - 1]))) {
            app_errf(err, "times must be > 0 and increasing");
            return -1;
        }
    return 0;
}

/* --sweep-c: 1..SH_MAX_SWEEP comma-separated speeds of light, each finite > 0 or inf */
static int parse_sweep(const char *val, void *dst, void *opts, char *err)
{
    (void)dst;
    cli *c = opts;
    c->nsweep = 0;
    char tok[64];
    for (const char *s = val;;) {
        const char *e = strchr(s, ',');
        size_t l = e ? (size_t)(e - s) : strlen(s);
        if (l >= sizeof tok) {
            app_errf(err, "a value longer than %zu characters", sizeof tok - 1);
            return -1;
        }
        if (c->nsweep == SH_MAX_SWEEP) {
            app_errf(err, "more than %d speeds of light", SH_MAX_SWEEP);
            return -1;
        }
        memcpy(tok, s, l), tok[l] = '\0';
        double x;
        if (app_parse_double(tok, 1, &x, err) || app_check_c(x, err))
            return -1;
        c->sweep[c->nsweep++] = x;
        if (!e)
            return 0;
        s = e + 1;
    }
}

/* --kn-scan: 2..SH_MAX_KN comma-separated Knudsen numbers, finite, in (0, SH_KN_MAX],
 * increasing (the crossing is read between neighbours) */
static int parse_kn(const char *val, void *dst, void *opts, char *err)
{
    (void)dst;
    cli *c = opts;
    c->nkn = 0;
    char tok[64];
    for (const char *s = val;;) {
        const char *e = strchr(s, ',');
        size_t l = e ? (size_t)(e - s) : strlen(s);
        if (l >= sizeof tok) {
            app_errf(err, "a value longer than %zu characters", sizeof tok - 1);
            return -1;
        }
        if (c->nkn == SH_MAX_KN) {
            app_errf(err, "more than %d Knudsen numbers", SH_MAX_KN);
            return -1;
        }
        memcpy(tok, s, l), tok[l] = '\0';
        double x;
        if (app_parse_double(tok, 0, &x, err))
            return -1;
        if (!(x > 0.0) || x > SH_KN_MAX) {
            app_errf(err, "Kn = %s must be in (0, %g]", tok, SH_KN_MAX);
            return -1;
        }
        if (c->nkn && !(x > c->kn[c->nkn - 1])) {
            app_errf(err, "Kn = %s is not above the one before (the list must increase)", tok);
            return -1;
        }
        c->kn[c->nkn++] = x;
        if (!e)
            break;
        s = e + 1;
    }
    if (c->nkn < 2) {
        app_errf(err, "a scan needs at least two Knudsen numbers");
        return -1;
    }
    return 0;
}

#define OFF(field) offsetof(cli, field)
static const app_opt opts[] = {
    {"--dim", "D", APP_T_INT, OFF(o.tube.dim), "3", .lo = 2, .hi = 3, .help = "2 or 3 (default %D)"},
    {"--c", "C", APP_T_DOUBLE_INF, OFF(o.tube.c), "inf", .valid = app_valid_c,
     .given = APP_GIVEN(cli, c_given),
     .help = "speed of light (default %D)"},
    {"--n-left", "N", APP_T_DOUBLE, OFF(o.tube.n[0]), "0.004", .valid = app_valid_positive,
     .help = "balls per unit volume (area in 2-D), left (default %D)"},
    {"--n-right", "N", APP_T_DOUBLE, OFF(o.tube.n[1]), "0.002", .valid = app_valid_positive,
     .help = "right (default %D)"},
    {"--T-left", "T", APP_T_DOUBLE, OFF(o.tube.T[0]), "2", .valid = app_valid_positive,
     .help = "temperature, left (default %D)"},
    {"--T-right", "T", APP_T_DOUBLE, OFF(o.tube.T[1]), "1", .valid = app_valid_positive,
     .help = "right (default %D)"},
    {"--v-left", "V", APP_T_DOUBLE, OFF(o.tube.v[0]), "0",
     .help = "table-frame velocity along x, left (default %D)"},
    {"--v-right", "V", APP_T_DOUBLE, OFF(o.tube.v[1]), "0", .help = "right (default %D)"},
    {"--radius", "R", APP_T_DOUBLE, OFF(o.tube.r), "0.5", .valid = app_valid_positive,
     .given = APP_GIVEN(cli, r_given), .help = "ball radius (default %D)"},
    {"--length", "L", APP_T_DOUBLE, OFF(length), "4000", .valid = app_valid_positive,
     .help = "tube length (default %D)"},
    {"--width", "W", APP_T_DOUBLE, OFF(width), "12", .valid = app_valid_positive,
     .help = "across, >= 4 diameters (default %D)"},
    {"--times", "LIST", APP_T_LIST, OFF(o.times), "500,1000", .hi = SH_MAX_TIMES,
     .count = OFF(o.nt), .valid = valid_times, .help = "times of the profiles, increasing (default %D)"},
    {"--bins", "B", APP_T_INT, OFF(o.bins), "100", .lo = 1, .hi = 100000,
     .help = "bins of x (default %D)"},
    {"--seeds", "S", APP_T_INT, OFF(o.seeds), "4", .lo = 1, .hi = 100000,
     .help = "independent runs, >= 2 for error bars (default %D)"},
    {"--seed", "S0", APP_T_U64, OFF(o.seed), "1", .help = "first seed (default %D)"},
    {"--frame", "NAME", APP_T_CUSTOM, OFF(o.tube.frame), .parse = app_opt_toi_frame,
     .help = "contact frame (default: uncontracted spheres)"},
    {"--law", "NAME", APP_T_CUSTOM, OFF(o.tube.law), .parse = app_opt_law,
     .help = "collision law (default zmf)"},
    {"--sweep-c", "LIST", APP_T_CUSTOM, OFF(sweep), .parse = parse_sweep,
     .help = "the same tube at each c of LIST (inf allowed; at most 16) in place of --c:\n"
             "sweep.csv, sweep_profiles.csv and sweep.png (below)"},
    {"--kn-scan", "LIST", APP_T_CUSTOM, OFF(kn), .parse = parse_kn,
     .help = "the same tube at each Knudsen number of LIST (increasing, 2 to 16, each in\n"
             "(0, 1000]), the radius set for it, read at the last time: kn_scan.csv, .json,\n"
             "kn_scan_profiles.csv, kn_scan.png and kn_scan_profiles.png (below)"},
    {"--gif", NULL, APP_T_FLAG, OFF(gif),
     .help = "also profiles.gif: n, v, p against x, one frame per time (2 or more times)"},
    {"--out", "DIR", APP_T_CUSTOM, OFF(out), "shock-out", .parse = app_opt_dir,
     .help = "output folder (default %D)"},
    {"--quiet", NULL, APP_T_FLAG, OFF(quiet), .help = "no summary lines on stdout"},
    {NULL},
};

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-shock [--dim 2|3] [--c C] [--n-left N] [--n-right N] [--T-left T]\n"
"                    [--T-right T] [--v-left V] [--v-right V] [--radius R] [--length L]\n"
"                    [--width W] [--times T1,T2,...] [--bins B] [--seeds S] [--seed S0]\n"
"                    [--frame NAME] [--law NAME] [--sweep-c C1,C2,...]\n"
"                    [--kn-scan KN1,KN2,...] [--gif] [--out DIR] [--quiet]\n"
"\n"
"The shock tube of hard balls (rest mass 1, k_B = 1): a box [0, L] x [0, W] (x [0, W])\n"
"walled at x = 0 and L, periodic across, a membrane at x = L/2 removed at t = 0; each side\n"
"a Juttner gas (Maxwell at c = inf) at its rest-frame density n, temperature T and\n"
"velocity v along x. Writes DIR/profiles.csv (per time and bin of x: the measured\n"
"n, Eckart velocity v, pressure p = Pxx - v g, transverse pperp, temperatures Tp = p/n and\n"
"Te (from the rest-frame energy), the lab densities N0, Nx, g = T0x/c, K = T00 - N0 c^2,\n"
"Pxx, Pyy, each with its standard error over the seeds, then the ideal fluid's\n"
"(_fluid) and free streaming's (_free) values of each), DIR/summary.json and DIR/shock.png.\n"
"\n"
"options:\n");
    app_opts_help(f, opts, 18);
    fprintf(f,
"\n"
"--sweep-c writes instead, at the last time: DIR/sweep.csv, one row per c: the plateau's\n"
"p and v and the shock speed measured (with seed errors) beside the exact relativistic\n"
"solution at that c (_rel: Synge's gas) and Sod's (_sod: the Euler solution, c = inf);\n"
"DIR/sweep_profiles.csv, per c and bin: n, v, p measured, _rel and _sod; DIR/sweep.gp\n"
"and sweep.png, the profiles at each c on one page.\n"
"\n"
"--kn-scan writes instead, at the last time, for each Kn = (the fluid's right-plateau mean\n"
"free path) / (shock speed t) of the list (the radius set to give it): DIR/kn_scan.csv,\n"
"one row per Kn: the normalised L2 distance of n, v, p from the ideal fluid (d_fluid) and\n"
"from free streaming (d_free), 0 at the reference and 1 at the other, with errors;\n"
"kn_scan.json with the Kn where the two distances cross; kn_scan_profiles.csv;\n"
"kn_scan.png (the distances against Kn) and kn_scan_profiles.png (profiles at up to four\n"
"Kn beside both references).\n"
"\n"
"exit status: 0 done; 2 bad option (one line naming it); 1 a start it cannot place, a\n"
"failed run or write.\n");
}

/* the checks between options, then the tube's box */
static int check(void *vc)
{
    cli *c = vc;
    sh_tube *t = &c->o.tube;
    if (c->nsweep && c->c_given)
        return app_fail(prog, EXIT_BAD, "--sweep-c: not with --c (the sweep sets c)");
    if (c->nkn && c->nsweep)
        return app_fail(prog, EXIT_BAD, "--kn-scan: not with --sweep-c (a scan runs at one c)");
    if (c->nkn && c->r_given)
        return app_fail(prog, EXIT_BAD, "--kn-scan: not with --radius (the scan sets the radius)");
    if (c->gif && (c->nkn || c->nsweep))
        return app_fail(prog, EXIT_BAD, "--gif: not with %s (it animates one run's times)",
                        c->nkn ? "--kn-scan" : "--sweep-c");
    if (c->gif && c->o.nt < 2)
        return app_fail(prog, EXIT_BAD, "--gif: needs at least two --times (one frame each)");
    double cmin = c->nsweep ? INFINITY : t->c; /* (a sweep holds |v| below its every c) */
    for (int k = 0; k < c->nsweep; k++)
        cmin = fmin(cmin, c->sweep[k]);
    for (int s = 0; s < 2; s++)
        if (!(fabs(t->v[s]) < cmin))
            return app_fail(prog, EXIT_BAD, "--v-%s: |v| = %g must be < c", s ? "right" : "left",
                            fabs(t->v[s]));
    for (int k = 0; k < c->nkn; k++) { /* each Kn's radius, before any run */
        char e2[APP_ERR_LEN];
        double pk;
        if (sh_kn_radius(t, c->o.times[c->o.nt - 1], c->kn[k], &t->r, &pk, e2))
            return app_fail(prog, EXIT_BAD, "--kn-scan: %s", e2);
        if (c->width < 8.0 * t->r)
            return app_fail(prog, EXIT_BAD, "--kn-scan: Kn = %g needs radius %g, and --width %g "
                            "is below four of its diameters", c->kn[k], t->r, c->width);
    }
    if (c->width < 8.0 * t->r)
        return app_fail(prog, EXIT_BAD, "--width: %g is below four ball diameters (%g): the "
                        "periodic axes need four cells", c->width, 8.0 * t->r);
    t->box.x = c->length, t->box.y = c->width, t->box.z = t->dim == 3 ? c->width : 0.0;
    t->x0 = 0.5 * c->length;
    return 0;
}

static const app_cli shock_cli = {.prog = "relcol-shock", .tab = opts, .usage = usage,
                                  .stray_hint = "see --help", .bad = EXIT_BAD, .check = check};

static int write_csv(const char *dir, const sh_opts *o, const sh_result *r, char *err)
{
    app_atomic a;
    if (app_atomic_open_in(&a, dir, "profiles.csv", err))
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
    if (app_atomic_open_in(&a, dir, "summary.json", err))
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
    if (app_atomic_open_in(&a, dir, "shock.gp", err))
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
    cli c;
    memset(&c, 0, sizeof c);
    int rc = app_start(&shock_cli, argc, argv, &c);
    if (rc >= 0)
        return rc;
    char err[APP_ERR_LEN];
    if (app_mkdir_p(c.out, err))
        return app_fail(prog, 1, "--out: %s", err);
    if (c.nsweep) {
        if (sh_sweep(prog, &c.o, c.sweep, c.nsweep, c.out, !c.quiet, err))
            return app_fail(prog, 1, "%s", err);
        app_validity_warn(stderr, prog);
        return 0;
    }
    if (c.nkn) {
        if (sh_kn_scan(prog, &c.o, c.kn, c.nkn, c.out, !c.quiet, err))
            return app_fail(prog, 1, "%s", err);
        app_validity_warn(stderr, prog);
        return 0;
    }
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
    int made_gif = 0;
    if (c.gif && sh_gif(prog, c.out, &c.o, &r, &made_gif, err)) {
        sh_result_free(&r);
        return app_fail(prog, 1, "--gif: %s", err);
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
        printf("wrote %s/profiles.csv, summary.json, shock.gp%s%s%s\n", c.out, made ? ", shock.png" : "",
               c.gif ? ", profiles_gif.gp" : "", made_gif ? ", profiles.gif" : "");
    }
    sh_result_free(&r);
    return 0;
}
