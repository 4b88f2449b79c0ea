/* relcol-eos — the equation of state and the transport coefficients of a hard-ball gas in
 * a periodic box, swept over packing fraction x temperature at any c and contact frame:
 * compressibility factor Z = P V / (N kT) from the exact flux moments (pressure tensor =
 * momentum flux: kinetic part plus collisional transfer), and with --transport the
 * self-diffusion, shear viscosity and thermal conductivity from Einstein–Helfand moments.
 * Writes a CSV and a gnuplot figure against theory (papers/pressure.md,
 * papers/transport.md). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app.h"
#include "ce_rel.h"
#include "eos_theory.h"
#include "eos_run.h"
#include "tr_first_order.h"
#include "tr_shear_heat.h"

static const char *const prog = "relcol-eos";
#define EXIT_BAD_INPUT 2
#define MAXLIST 64

typedef struct options {
    eos_in in;
    double packing[MAXLIST], theta[MAXLIST];
    int npack, ntheta;
    const char *out;
    int sensitivity;
} options;

/* --n: a size_t */
static int parse_n(const char *val, void *dst, void *opts, char *err)
{
    (void)opts;
    long l;
    if (app_parse_long(val, 4, 10000000, &l, err) != 0)
        return -1;
    *(size_t *)dst = (size_t)l;
    return 0;
}

#define OFF(field) offsetof(options, field)
static const app_opt opts[] = {
    {"--dim", NULL, APP_T_INT, OFF(in.dim), "3", 2, 3,
     .help = "2 (discs) or 3 (spheres; default)"},
    {"--n", NULL, APP_T_CUSTOM, OFF(in.n), "1000", .parse = parse_n,
     .help = "balls (default %D)"},
    {"--packing", "LIST", APP_T_LIST, OFF(packing), "0.05,0.1,0.2,0.3,0.4", .hi = MAXLIST,
     .count = OFF(npack), .valid = app_valid_open_closed, .min = 0.0, .max = 0.7,
     .help = "rest-frame packing fractions (default %D)"},
    {"--theta", "LIST", APP_T_LIST, OFF(theta), "1", .hi = MAXLIST, .count = OFF(ntheta),
     .valid = app_valid_open_closed, .min = 1e-3, .max = 1e3,
     .help = "kT / (m c^2) at finite c, kT at c = inf (default %D)"},
    {"--c", NULL, APP_T_DOUBLE_INF, OFF(in.c), "inf", .valid = app_valid_c,
     .help = "speed of light (default %D: classical)"},
    {"--frame", "NAME", APP_T_CUSTOM, OFF(in.frame), "sphere", .parse = app_opt_toi_frame,
     .help = "contact frame (default %D: uncontracted, thermal at any density)"},
    {"--t-equil", "T", APP_T_DOUBLE, OFF(in.t_equil), "50", .valid = app_valid_positive,
     .help = "melting time in mean free times (default %D)"},
    {"--t-run", "T", APP_T_DOUBLE, OFF(in.t_run), "2000", .valid = app_valid_positive,
     .help = "measured time in mean free times (default %D)"},
    {"--blocks", "B", APP_T_INT, OFF(in.blocks), "20", 2, 100000,
     .help = "independent blocks for the standard errors (default %D)"},
    {"--per-block", "K", APP_T_INT, OFF(in.per_block), "100", 4, 100000,
     .help = "moment readings per block with --transport (default %D)"},
    {"--transport", NULL, APP_T_FLAG, OFF(in.transport),
     .help = "also D, eta, lambda (Einstein–Helfand; reads every position)"},
    {"--lag", "T", APP_T_DOUBLE, OFF(in.lag), "20", .valid = app_valid_positive,
     .help = "Helfand lag in mean free times (default %D, within a block;\n"
             "D of a dense gas needs about 100 to take in the long-time tail)"},
    {"--seed", "S", APP_T_U64, OFF(in.seed), "1",
     .help = "seed of the gas drawn and of the theory integrals (default %D)"},
    {"--out", "DIR", APP_T_CUSTOM, OFF(out), "out/eos", .parse = app_opt_dir,
     .help = "output folder (default %D): eos.csv, eos.gp, eos.png"},
    {"--sensitivity", NULL, APP_T_FLAG, OFF(sensitivity),
     .help = "instead of eos.csv: every point run again with the start moved by\n"
             "1e-15 of a radius and under each other rule its frame offers (group\n"
             "rule; other contracted frames), each Z, kT, P (and D, eta, lambda)\n"
             "shift in units of its error, flagged above 3 errors;\n"
             "sensitivity.csv and sensitivity.json in --out"},
    {NULL},
};

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-eos [--dim 2|3] [--n N] [--packing LIST] [--theta LIST] [--c C|inf]\n"
"                  [--frame NAME] [--t-equil T] [--t-run T] [--blocks B] [--per-block K]\n"
"                  [--transport] [--lag T] [--seed S] [--out DIR] [--sensitivity]\n"
"Equation of state (and transport coefficients) of N equal hard balls (m = 1, diameter\n"
"1) in a periodic box, for every packing x theta of the comma-separated lists.\n");
    app_opts_help(f, opts, 19);
    fprintf(f,
"Theory columns: 3-D Kolafa and Carnahan–Starling, 2-D Luding (2001) and Santos et al.;\n"
"transport (3-D): Enskog, and Speedy's D (a fit to 500-sphere\n"
"runs) moved to this box by Yeh & Hummer's finite-size law, and for uncontracted\n"
"spheres at any c their own Chapman-Enskog D, eta and lambda (D_chapman_enskog,\n"
"eta_chapman_enskog, lambda_chapman_enskog: dilute values times Enskog-type factors;\n"
"classically D_chapman_enskog is the first Sonine approximation, about 2 %% below the\n"
"converged value); for the frames that collide at the invariant rate (table, zmf,\n"
"covariant, transport) at finite c, eta and lambda of the invariant Boltzmann gas\n"
"(converged, dilute) instead, and no D. Fields without a measurement or a theory in\n"
"this run are empty.\n"
"Z, kT, P, D, eta, lambda each with a standard error from the blocks.\n");
}

/* The checks between options, after the table's parse: 0, else an exit code. */
static int check_options(void *opts)
{
    const options *o = opts;
    const eos_in *in = &o->in;
    char f1[APP_FMT_LEN];
    /* the fluid ends near 0.494 (spheres) and 0.70 (discs): beyond it the lattice start
     * would not melt */
    for (int k = 0; k < o->npack; k++)
        if (in->dim == 3 && o->packing[k] > 0.49)
            return app_fail(prog, EXIT_BAD_INPUT, "--packing: %s beyond the sphere fluid "
                            "(<= 0.49 in 3-D)", app_fmt(o->packing[k], f1));
    if (in->transport && in->lag * (double)in->blocks > in->t_run)
        return app_fail(prog, EXIT_BAD_INPUT, "--lag: %s longer than a block (--t-run / "
                        "--blocks = %g mean free times)", app_fmt(in->lag, f1),
                        in->t_run / in->blocks);
    return 0;
}

static const app_cli cli = {.prog = prog, .tab = opts, .usage = usage,
                            .stray_hint = "see --help",
                            .bad = EXIT_BAD_INPUT, .check = check_options};

/* ",value", or "," alone for a value that is not there (NaN): an empty CSV field */
static void csv_field(FILE *f, const char *fmt, double x)
{
    fputc(',', f);
    if (!isnan(x))
        fprintf(f, fmt, x);
}

/* Frames that collide at the invariant (Møller) rate, at finite c in 3-D: contracted shapes
 * (table, zmf, covariant) and the transport codes' points (papers/transport.md, section 7).
 * Their reference is the invariant Boltzmann gas's Chapman–Enskog, not the sphere kernel's. */
static int eos_invariant_rate(const eos_in *in)
{
    return in->dim == 3 && !isinf(in->c) && in->frame &&
           (in->frame->contracted || in->frame->pointlike);
}

/* The invariant Boltzmann gas's converged (CE_REL_MAX_ORDER functions) dilute eta and
 * lambda (apps/eos/ce_rel.c, papers/transport.md, section 6) in relcol-eos's units: diameter
 * 1, so sigma_T = pi, m = 1, z = c^2/kT; eta comes in kT/(sigma_T c), lambda in
 * k c/sigma_T. lambda carries r^2, r = (<E> + Z kT)/(<E> + kT) with the run's own Z: the
 * measured heat moment subtracts the dense enthalpy (section 4). No density factor: these
 * frames' contact value of g is not the spheres' (section 12). 0, or -1. */
static int ce_invariant(double c, double kT, double z_meas, double *eta_s, double *lambda)
{
    const double z = c * c / kT;
    ce_rel_coeffs co;
    ce_rel_juttner ju;
    const char *why;
    if (ce_rel_compute(z, CE_REL_MAX_ORDER, NULL, &co, &why) != 0 ||
        ce_rel_juttner_moments(z, &ju, &why) != 0)
        return -1;
    const double e = z + ju.mean_k, r = (e + z_meas) / (e + 1.0); /* in kT */
    *eta_s = co.eta * kT / (M_PI * c);
    *lambda = co.lambda * c / M_PI * r * r;
    return 0;
}

static double z_theory(int dim, double eta) { return dim == 3 ? eos_z_kolafa(eta) : eos_z_disc(eta); }

static int write_script(const char *path, const options *o, char *err)
{
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0)
        return -1;
    FILE *f = a.f;
    char fc[APP_FMT_LEN];
    const eos_in *in = &o->in;
    /* explicit x ranges: a single packing or theta would leave gnuplot an empty range */
    double pmax = 0.0, tmin = INFINITY, tmax = 0.0;
    for (int k = 0; k < o->npack; k++)
        pmax = fmax(pmax, o->packing[k]);
    for (int k = 0; k < o->ntheta; k++) {
        tmin = fmin(tmin, o->theta[k]);
        tmax = fmax(tmax, o->theta[k]);
    }
    fprintf(f, "# eos.gp — written by relcol-eos; run `gnuplot eos.gp` in this folder.\n");
    if (!in->transport) {
        /* Both panels against the theories; the right one relative to the first theory
         * (Kolafa, or Luding in 2-D), where the second is a curve against it, not a
         * point. A run of one point also gets its numbers written by it. */
        const char *t1 = in->dim == 3 ? "Kolafa" : "Luding 2001",
                   *t2 = in->dim == 3 ? "Carnahan–Starling" : "Santos et al. 1995";
        app_gnuplot_head(f, "eos.png", "size 1300,600 enhanced font 'Sans,12' linewidth 1.4", 0);
        fprintf(f,
"%s\n"
"stats 'eos.csv' skip 1 using 8 nooutput\n"
"npts = STATS_records\n"
"if (npts == 1) { stats 'eos.csv' skip 1 using 4 nooutput; e1 = STATS_mean; "
"stats 'eos.csv' skip 1 using 8 nooutput; z = STATS_mean; "
"stats 'eos.csv' skip 1 using 9 nooutput; zse = STATS_mean }\n"
"set multiplot layout 1,2 title \"Equation of state of %d-D hard balls, N = %zu, c = %s, "
"frame %s\\n{/*0.8 relcol: Z from the exact flux moments, error bars one standard error over "
"blocks of the run}\"\n"
"set xlabel 'packing fraction η'\nset grid lc rgb '#dddddd'\nset key top left box opaque\n"
"set xrange [0:%.4g]\n"
"set offsets 0, 0, graph 0.08, graph 0.08\n"
"set ylabel 'Z = PV/(NkT)'\n"
"set title 'Z against the equations of state'\n"
"if (npts == 1) { set label 1 sprintf(\"relcol at η = %%.3g: Z = %%.5f ± %%.5f\\n%s: %%.5f\\n%s: %%.5f\", "
"e1, z, zse, z1(e1), z2(e1)) at first e1, first z right offset -1.5,-1.2 front }\n"
"plot z1(x) with lines lw 2 lc rgb '#d62728' title '%s', \\\n"
"     z2(x) with lines lw 2 dt 2 lc rgb '#2ca02c' title '%s', \\\n"
"     'eos.csv' skip 1 using 4:8:9 with yerrorbars pt 7 ps 1.3 lw 1.5 lc rgb '#1f77b4' title 'relcol'\n"
"unset label 1\n"
"set ylabel '100 (Z / Z_{%s} − 1)  (%%)'\n"
"set title 'relative to %s'\n"
"set key bottom left box opaque\n"
"plot 0 with lines lw 2 lc rgb '#d62728' title '%s (the reference, 0)', \\\n"
"     100 * (z2(x) / z1(x) - 1) with lines lw 2 dt 2 lc rgb '#2ca02c' title '%s against %s', \\\n"
"     'eos.csv' skip 1 using 4:(100*($8/$10-1)):(100*$9/$10) with yerrorbars pt 7 ps 1.3 lw 1.5 lc rgb '#1f77b4' "
"title 'relcol against %s'\n"
"unset multiplot\n",
                in->dim == 3
                    ? "z1(x) = (1 + x + x**2 - 2./3 * x**3 * (1 + x)) / (1 - x)**3\n"
                      "z2(x) = (1 + x + x**2 - x**3) / (1 - x)**3"
                    : "z1(x) = (1 + x**2 / 8) / (1 - x)**2 - 0.043 * x**4 / (1 - x)**3\n"
                      "z2(x) = 1 / (1 - 2 * x + (2 * pi / (2 * sqrt(3)) - 1) / (pi / (2 * "
                      "sqrt(3)))**2 * x**2)",
                in->dim, in->n, app_fmt(in->c, fc), in->frame ? in->frame->name : "sphere",
                pmax + 0.05, t1, t2, t1, t2, in->dim == 3 ? "Kolafa" : "Luding",
                in->dim == 3 ? "Kolafa" : "Luding", t1, t2, in->dim == 3 ? "Kolafa" : "Luding",
                in->dim == 3 ? "Kolafa" : "Luding");
    } else {
        /* against packing when theta is one value (the common run), else against theta;
         * theories joined by lines only along the one list that varies (the rows go
         * packing by packing, so a line along theta would jump between packings) */
        const int by_pack = o->ntheta == 1, joined = o->npack == 1 || o->ntheta == 1;
        const int xc = by_pack ? 4 : 5;
        const char *with = joined ? "linespoints" : "points";
        char xr[96];
        if (by_pack)
            snprintf(xr, sizeof xr, "set xrange [0:%.4g]\nset logscale y", pmax + 0.05);
        else
            snprintf(xr, sizeof xr, "set xrange [%.4g:%.4g]\nset logscale xy", 0.5 * tmin,
                     2.0 * tmax);
        app_gnuplot_head(f, "eos.png", "size 1500,600 enhanced font 'Sans,12' linewidth 1.4", 0);
        fprintf(f,
"set multiplot layout 1,3 title \"Transport coefficients of %d-D hard balls (Einstein–Helfand), "
"N = %zu, c = %s, frame %s\\n{/*0.8 {/:Bold blue points}: relcol, error bars one standard "
"error over blocks;   {/:Bold red}: Enskog (classical) at the same kT}\\n{/*0.8 {/:Bold violet, "
"dotted}: %s;   {/:Bold green, dashed} (D): Speedy's "
"N = 500 fit moved to this box}\"\n"
"set xlabel '%s'\nset grid lc rgb '#dddddd'\nunset key\n"
"%s\n"
"set ylabel 'D'\n"
"plot 'eos.csv' skip 1 using %d:20 with %s lc rgb '#d62728' title 'Enskog', \\\n"
"     '' skip 1 using %d:23 with %s dt 2 lc rgb '#2ca02c' title 'Speedy (N = 500) moved to this box', \\\n"
"     '' skip 1 using %d:27 with %s dt 3 lc rgb '#9467bd' title 'Chapman–Enskog', \\\n"
"     '' skip 1 using %d:14:15 with yerrorbars pt 7 ps 1.2 lc rgb '#1f77b4' title 'relcol'\n"
"set ylabel 'η_s'\n"
"plot 'eos.csv' skip 1 using %d:21 with %s lc rgb '#d62728' title 'Enskog', \\\n"
"     '' skip 1 using %d:28 with %s dt 3 lc rgb '#9467bd' title 'Chapman–Enskog', \\\n"
"     '' skip 1 using %d:16:17 with yerrorbars pt 7 ps 1.2 lc rgb '#1f77b4' title 'relcol'\n"
"set ylabel 'λ'\n"
"plot 'eos.csv' skip 1 using %d:22 with %s lc rgb '#d62728' title 'Enskog', \\\n"
"     '' skip 1 using %d:29 with %s dt 3 lc rgb '#9467bd' title 'Chapman–Enskog', \\\n"
"     '' skip 1 using %d:18:19 with yerrorbars pt 7 ps 1.2 lc rgb '#1f77b4' title 'relcol'\n"
"unset multiplot\n",
                in->dim, in->n, app_fmt(in->c, fc), in->frame ? in->frame->name : "sphere",
                eos_invariant_rate(in) ? "the invariant Boltzmann gas's converged Chapman–Enskog "
                                         "(dilute; no D)"
                                       : "the sphere kernel's own Chapman–Enskog",
                by_pack ? "packing fraction η" : isinf(in->c) ? "θ (kT at c = ∞)" : "θ = kT/(mc^2)", xr, xc, with, xc, with, xc,
                with, xc, xc, with, xc, with, xc, xc, with, xc, with, xc);
    }
    return app_atomic_commit(&a, err);
}

/* --sensitivity: every packing x theta point under variant v; per point Z, kT, P (and
 * with --transport D, eta, lambda), with their block errors */
static int sens_run(void *ctx, const app_sens_variant *v, double *x, double *se, char *err)
{
    const options *o = ctx;
    const int per = o->in.transport ? 6 : 3;
    size_t j = 0;
    for (int ip = 0; ip < o->npack; ip++)
        for (int it = 0; it < o->ntheta; it++) {
            eos_in in = o->in;
            in.packing = o->packing[ip];
            in.theta = o->theta[it];
            in.frame = v->frame;
            in.groups = v->groups;
            in.move = v->move;
            in.move_balls = app_sens_move;
            eos_out r;
            if (eos_measure(&in, &r, err) != 0)
                return -1;
            app_validity_note_report(&r.val);
            const double val[6] = {r.z, r.kT, r.p, r.d, r.eta, r.lambda};
            const double ser[6] = {r.z_se, r.kT_se, r.p_se, r.d_se, r.eta_se, r.lambda_se};
            for (int q = 0; q < per; q++, j++) {
                x[j] = val[q];
                se[j] = ser[q];
            }
        }
    return 0;
}

static int eos_sensitivity(options *o)
{
    static const char *const q[6] = {"Z", "kT", "P", "D", "eta", "lambda"};
    const int per = o->in.transport ? 6 : 3;
    const size_t nobs = (size_t)(o->npack * o->ntheta * per);
    char (*nm)[96] = malloc(nobs * sizeof *nm);
    const char **names = malloc(nobs * sizeof *names);
    if (!nm || !names) {
        free(nm);
        free(names);
        return app_fail(prog, 1, "out of memory");
    }
    size_t j = 0;
    for (int ip = 0; ip < o->npack; ip++)
        for (int it = 0; it < o->ntheta; it++)
            for (int k = 0; k < per; k++, j++) {
                snprintf(nm[j], sizeof nm[j], "%s@packing=%g;theta=%g", q[k], o->packing[ip],
                         o->theta[it]);
                names[j] = nm[j];
            }
    const int rc = app_sensitivity_main(prog, o->out, o->in.frame, 0, o->in.c, o->in.dim, nobs,
                                        names, sens_run, o);
    free(nm);
    free(names);
    return rc;
}

/* the bar over all points: point `at` of `of`, a fraction done of it */
typedef struct eos_bar {
    app_progress bar;
    size_t at, of;
} eos_bar;

static void eos_tick(void *ctx, double done)
{
    eos_bar *b = ctx;
    app_progress_update(&b->bar, (size_t)(1000.0 * ((double)b->at + done) / (double)b->of));
}

int main(int argc, char **argv)
{
    options o;
    memset(&o, 0, sizeof o);
    int st = app_start(&cli, argc, argv, &o);
    if (st >= 0)
        return st;
    if (o.sensitivity)
        return eos_sensitivity(&o);
    char err[APP_ERR_LEN], fc[APP_FMT_LEN];
    if (app_mkdir_p(o.out, err) != 0)
        return app_fail(prog, EXIT_BAD_INPUT, "--out: %s", err);
    char *csv = app_path_join(o.out, "eos.csv"), *gp = app_path_join(o.out, "eos.gp");
    if (!csv || !gp)
        return app_fail(prog, 1, "out of memory");
    app_atomic a;
    if (app_atomic_open(&a, csv, err) != 0) {
        free(csv);
        free(gp);
        return app_fail(prog, 1, "%s", err);
    }
    fprintf(a.f, "dim,c,n,packing,theta,kT,kT_se,Z,Z_se,Z_theory,Z_theory2,P,P_se,D,D_se,"
                 "eta,eta_se,lambda,lambda_se,D_enskog,eta_enskog,lambda_enskog,D_speedy_box,"
                 "collisions,overlaps,seconds,D_chapman_enskog,eta_chapman_enskog,"
                 "lambda_chapman_enskog\n");
    printf("%s: %d-D, N = %zu, c = %s, frame %s, periodic box; Z against %s\n", prog,
           o.in.dim, o.in.n, app_fmt(o.in.c, fc), o.in.frame ? o.in.frame->name : "sphere",
           o.in.dim == 3 ? "Kolafa (Z_theory) and Carnahan–Starling"
                         : "Luding (2001) and Santos et al.");
    int rc = 0;
    eos_bar bar = {.of = (size_t)o.npack * (size_t)o.ntheta};
    app_progress_init(&bar.bar, prog, 1000);
    for (int ip = 0; ip < o.npack && rc == 0; ip++)
        for (int it = 0; it < o.ntheta && rc == 0; it++) {
            eos_in in = o.in;
            in.packing = o.packing[ip];
            in.theta = o.theta[it];
            bar.at = (size_t)ip * (size_t)o.ntheta + (size_t)it;
            eos_out r;
            struct timespec t0, t1;
            clock_gettime(CLOCK_MONOTONIC, &t0);
            if (eos_measure_ticked(&in, &r, err, eos_tick, &bar) != 0) {
                rc = app_fail(prog, 1, "packing %g theta %g: %s", in.packing, in.theta, err);
                break;
            }
            clock_gettime(CLOCK_MONOTONIC, &t1);
            app_validity_note_report(&r.val);
            const double sec = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
            const double eta = in.packing;
            const double zt = z_theory(in.dim, eta),
                         zt2 = in.dim == 3 ? eos_z_cs(eta) : eos_z_disc_shy(eta);
            double de = NAN, ee = NAN, le = NAN, ds = NAN;
            if (in.dim == 3) {
                de = tr_d_enskog(eta, r.kT);
                ee = tr_eta_enskog(eta, r.kT);
                le = tr_lambda_enskog(eta, r.kT);
                ds = tr_d_speedy_box(eta, r.kT, ee, r.box);
            }
            /* the uncontracted-sphere kernel's own Chapman–Enskog D (tr_first_order.h):
             * Galerkin on {p_x, v_x}, over Enskog's chi; other kernels have none here */
            const int inv = eos_invariant_rate(&in);
            double dce = NAN, dce_se;
            if (in.dim == 3 && in.transport && !(in.frame && in.frame->contracted) && !inv &&
                tr_nd_sphere(in.c, r.kT, 2, 200000, in.seed, &dce, &dce_se) == 0)
                dce /= 6.0 * eta / M_PI * eos_chi(3, eta);
            /* and its eta, lambda (tr_shear_heat.h): Galerkin on two functions each, the
             * dilute values carried to this packing by Enskog's factors with the kernel's
             * own collisional transfer and the measured heat moment's enthalpy */
            double ece = NAN, lce = NAN;
            tr_shear_heat sh;
            if (in.dim == 3 && in.transport && !(in.frame && in.frame->contracted) && !inv &&
                tr_shear_heat_sphere(3, in.c, r.kT, 2, 200000, in.seed, &sh) == 0)
                tr_shear_heat_enskog(&sh, in.c, r.kT, eta, &ece, &lce);
            /* invariant-rate frames: the invariant Boltzmann gas's, dilute */
            if (in.transport && inv && ce_invariant(in.c, r.kT, r.z, &ece, &lce) != 0)
                ece = lce = NAN;
            fprintf(a.f, "%d,%s,%zu,%.6g,%.6g,%.8g,%.3g,%.8g,%.3g,%.8g,%.8g,%.8g,%.3g", in.dim,
                    app_fmt(in.c, fc), in.n, eta, in.theta, r.kT, r.kT_se, r.z, r.z_se, zt, zt2,
                    r.p, r.p_se);
            /* what was not measured or has no theory here is an empty field, not 0 or nan */
            const double tr = in.transport ? 1.0 : NAN;
            const double tail1[] = {tr * r.d, tr * r.d_se, tr * r.eta, tr * r.eta_se,
                                    tr * r.lambda, tr * r.lambda_se, de, ee, le, ds};
            for (size_t q = 0; q < sizeof tail1 / sizeof *tail1; q++)
                csv_field(a.f, q % 2 && q < 6 ? "%.3g" : "%.6g", tail1[q]);
            fprintf(a.f, ",%llu,%llu,%.3f", (unsigned long long)r.collisions,
                    (unsigned long long)r.overlaps, sec);
            csv_field(a.f, "%.6g", dce);
            csv_field(a.f, "%.6g", ece);
            csv_field(a.f, "%.6g", lce);
            fputc('\n', a.f);
            if (bar.bar.tty && bar.bar.last_pct >= 0) { /* the results below the bar */
                fputc('\n', stderr);
                bar.bar.last_pct = -1;
            }
            printf("packing %.4g theta %.4g: kT = %.5f +- %.5f  Z = %.5f +- %.5f  (theory %.5f: "
                   "%+.3f %% +- %.3f %%)  %llu collisions, %.1f s\n",
                   eta, in.theta, r.kT, r.kT_se, r.z, r.z_se, zt, 100.0 * (r.z / zt - 1.0),
                   100.0 * r.z_se / zt, (unsigned long long)r.collisions, sec);
            if (in.transport)
                printf("    D = %.5f +- %.5f (Enskog %.5f, Speedy in this box %.5f, Chapman-Enskog "
                       "of this kernel %.5f)  eta = %.5f +- %.5f (Enskog %.5f, Chapman-Enskog %.5f)  "
                       "lambda = %.5f +- %.5f (Enskog %.5f, Chapman-Enskog %.5f)\n", r.d, r.d_se,
                       de, ds, dce, r.eta, r.eta_se, ee, ece, r.lambda, r.lambda_se, le, lce);
            fflush(stdout);
        }
    if (rc != 0) {
        app_atomic_abort(&a);
    } else if (app_atomic_commit(&a, err) != 0 || write_script(gp, &o, err) != 0) {
        rc = app_fail(prog, 1, "%s", err);
    } else {
        int made = 0;
        if (app_gnuplot_run(prog, o.out, "eos.gp", "eos.png", &made, err) != 0)
            rc = app_fail(prog, 1, "%s", err);
        else if (made)
            printf("wrote %s, %s, %s/eos.png\n", csv, gp, o.out);
        else
            printf("wrote %s, %s\n", csv, gp);
    }
    free(csv);
    free(gp);
    if (rc == 0)
        app_validity_warn(stderr, prog);
    return rc == 0 && fflush(stdout) != 0 ? 1 : rc;
}
