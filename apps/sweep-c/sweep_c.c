/* sweep_c.c — relcol-sweep-c: the same two-ball collision at c from 10 to 10^6 times the
 * fastest speed, and how fast its outcome approaches the c = inf (classical) one: the
 * final velocities and the heat (rest-mass gain x c^2) should deviate like (v/c)^2. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app.h"

static const char *const prog = "relcol-sweep-c";

enum { EXIT_BAD_INPUT = 2, EXIT_NO_COLLISION = 3 };

/* The built-in example: an oblique 2-D collision, speeds about 1, ball 1 twice as heavy;
 * the positions make the contact normal (1.8, 1)/|.|, along which the balls approach. */
static const char example_csv[] = "m,vx,vy,x,y\n"
                                  "1,1,0.2,0,0\n"
                                  "2,-0.6,0.5,1.8,1\n";
static const double example_eps = 0.8;

/* every input error: "relcol-sweep-c: message" and exit status 2 */
#define fail(...) app_fail(prog, EXIT_BAD_INPUT, __VA_ARGS__)

typedef struct options {
    const char *input, *out;
    int example, eps_given;
    int points;
    double from, to, eps;
    const rc_law *law;
} options;

static int parse_law(const char *val, void *dst, void *opts, char *err)
{
    (void)opts;
    if ((*(const rc_law **)dst = rc_law_find(val)))
        return 0;
    char list[256];
    app_errf(err, "unknown law '%s' (expected %s)", val, app_law_list(list, sizeof list));
    return -1;
}

#define OFF(field) offsetof(options, field)
static const app_opt opts[] = {
    {"--input", "FILE", APP_T_STRING, OFF(input), .help = "the input CSV (default stdin)"},
    {"--example", NULL, APP_T_FLAG, OFF(example), .help = "the built-in example above"},
    {"--out", "DIR", APP_T_CUSTOM, OFF(out), "out/sweep-c", .parse = app_opt_dir,
     .help = "output folder, created if missing (default %D)"},
    {"--points", "N", APP_T_INT, OFF(points), "41", 3, 1000000,
     .help = "number of values of c, log-spaced (default %D, at least 3)"},
    {"--from", "F", APP_T_DOUBLE, OFF(from), "10",
     .help = "smallest c as a multiple of the fastest speed, > 1 (default %D)"},
    {"--to", "T", APP_T_DOUBLE, OFF(to), "1e6",
     .help = "largest c as a multiple of the fastest speed (default %D)"},
    /* (the default 1 is the app's: 0.8 for the example) */
    {"--eps", "E", APP_T_DOUBLE, OFF(eps), "1", .given = APP_GIVEN(options, eps_given),
     .help = "restitution in [0, 1] (default 0.8 for the example, else %D)"},
    {"--law", "LAW", APP_T_CUSTOM, OFF(law), "zmf", .parse = parse_law,
     .help = "collision law, as in relcol-collide (default %D)"},
    {NULL},
};

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-sweep-c [--input FILE | --example] [--out DIR] [--points N]\n"
"                      [--from F] [--to T] [--eps E] [--law LAW]\n"
"\n"
"Collide two balls at many values of the speed of light c and measure how the outcome\n"
"approaches the classical (c = inf) one.\n"
"\n"
"input: the CSV of relcol-collide (header; two rows; m, vx[,vy[,vz]] or px[,py[,pz]],\n"
"  optional x[,y[,z]] giving the normal from ball 0 to ball 1, else +x), in table units,\n"
"  from --input FILE or stdin. With --example, or with no --input and stdin a terminal,\n"
"  a built-in oblique 2-D example (eps = 0.8):\n"
"%s"
"options:\n",
            example_csv);
    app_opts_help(f, opts, 16);
    fprintf(f,
"\n"
"per c it computes\n"
"  dev_velocity  max over balls |v'(c) - v'(inf)| / max over balls |v'(inf)|\n"
"  dev_heat      |Q(c) - dK| / dK: Q(c) = sum (m' - m) c^2 is the heat that became rest\n"
"                mass, computed without cancellation as (m'^2 - m^2) c^2 / (m' + m) with\n"
"                (m'^2 - m^2) c^2 = |pbar|^2 - |pbar'|^2 (ZMF momenta; for laws that keep\n"
"                each ball's ZMF energy, as zmf and cm-isotropic declare, else directly);\n"
"                dK is the kinetic energy lost at c = inf. With eps = 1 both are 0: the\n"
"                column is empty and not plotted.\n"
"and writes, atomically, DIR/sweep-c.csv, DIR/sweep-c.gp and, if gnuplot is installed,\n"
"DIR/sweep-c.png; then prints the fitted log-log slopes (expect -2).\n"
"exit status: 0 ok; 2 bad input; 3 the balls do not collide; 1 I/O error.\n");
}

/* The checks between options, after the table's parse: 0, else an exit code. */
static int check_options(void *opts)
{
    const options *o = opts;
    char f[APP_FMT_LEN];
    if (o->example && o->input)
        return fail("--example: conflicts with --input");
    if (!(o->from > 1.0))
        return fail("--from: %s must be > 1 (c must exceed every speed)", app_fmt(o->from, f));
    if (!(o->to > o->from))
        return fail("--to: %s must be larger than --from", app_fmt(o->to, f));
    if (!(o->eps >= 0.0 && o->eps <= 1.0))
        return fail("--eps: eps = %s outside [0, 1]", app_fmt(o->eps, f));
    return 0;
}

static const app_cli cli = {.prog = prog, .tab = opts, .usage = usage,
                            .stray_hint = "see --help",
                            .bad = EXIT_BAD_INPUT, .check = check_options};

/* One collision at c; outputs the final states. Returns an rc_status. */
static int collide_at(const options *o, const app_balls *b, rc_vec3 n, double c,
                      rc_particle in[2], rc_particle outp[2], char *err)
{
    if (app_balls_particles(b, c, in, err) != 0)
        return RC_EINVAL;
    rc_collision_params prm = rc_collision_params_default();
    prm.c = c;
    prm.eps = o->eps;
    outp[0] = in[0];
    outp[1] = in[1];
    int st = rc_collide(o->law, &prm, &outp[0], &outp[1], n);
    if (st != RC_OK && st != RC_NO_COLLISION)
        app_errf(err, "c = %g: %s", c, rc_strerror(st));
    return st;
}

static int write_script(const char *path, const options *o, const app_balls *b,
                        double vmax, int have_heat, double s_v, double s_q, char *err)
{
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0)
        return -1;
    FILE *f = a.f;
    char fe[APP_FMT_LEN], slope_v[48], slope_q[48];
    /* (no fitted slope: the quantity stayed at round-off, independent of c) */
    snprintf(slope_v, sizeof slope_v, isfinite(s_v) ? "(slope %.3f)" : "(round-off at every c)",
             s_v);
    snprintf(slope_q, sizeof slope_q, isfinite(s_q) ? "(slope %.3f)" : "(round-off at every c)",
             s_q);
    fprintf(f,
"# sweep-c.gp — written by relcol-sweep-c; run `gnuplot sweep-c.gp` in this folder.\n"
"# Deviation of a two-ball collision's outcome at speed of light c from the classical\n"
"# (c = inf) outcome, against c / |v|max; both should fall like (|v|max / c)^2.\n");
    app_gnuplot_head(f, "sweep-c.png", "size 1100,760 enhanced font 'Sans,13' linewidth 1.5",
                     1);
    fprintf(f,
"set mxtics 10\n"
"set grid xtics ytics mxtics lc rgb '#dddddd' lw 0.8, lc rgb '#f0f0f0' lw 0.5\n"
"set xlabel 'c / |v|_{max}'\n"
"set ylabel 'relative deviation from the classical result (c = ∞)'\n"
"set title \"How a collision approaches classical mechanics as c grows\\n"
"{/*0.75 law %s, ε = %s, %d-D, %s input, |v|_{max} = %.4g}\"\n"
"set key top right box opaque spacing 1.3\n",
            o->law->name, app_fmt(o->eps, fe), b->dim, b->momentum ? "momentum" : "velocity",
            vmax);
    fprintf(f,
"plot 'sweep-c.csv' skip 1 using 2:3 with lines dt 2 lw 2 lc rgb '#555555' \\\n"
"       title '(|v|_{max}/c)^2 reference', \\\n"
"     '' skip 1 using 2:4 with linespoints pt 7 ps 0.9 lw 2 lc rgb '#1f77b4' \\\n"
"       title 'final velocities  max|v′(c) − v′(∞)| / max|v′(∞)|   %s'%s\n",
            slope_v, have_heat ? ", \\" : "");
    if (have_heat)
        fprintf(f,
"     '' skip 1 using 2:5 with linespoints pt 5 ps 0.8 lw 2 lc rgb '#d62728' \\\n"
"       title 'heat  |Σ(m′ − m)c² − ΔK_{c=∞}| / ΔK_{c=∞}   %s'\n",
                slope_q);
    else
        fprintf(f, "# eps = 1: no heat at any c, so the heat deviation (empty) is not plotted\n");
    return app_atomic_commit(&a, err);
}

int main(int argc, char **argv)
{
    options o;
    memset(&o, 0, sizeof o);
    int st = app_start(&cli, argc, argv, &o);
    if (st >= 0)
        return st;

    char err[APP_ERR_LEN];
    const char *src = "stdin";
    FILE *in = stdin;
    int use_example = o.example || (!o.input && isatty(STDIN_FILENO));
    if (use_example) {
        src = "example";
        in = fmemopen((void *)example_csv, sizeof example_csv - 1, "r");
        if (!o.eps_given)
            o.eps = example_eps;
        if (!o.example)
            fprintf(stderr, "%s: stdin is a terminal: using the built-in example (see "
                            "--help)\n", prog);
    } else if (o.input) {
        src = o.input;
        in = fopen(o.input, "r");
        if (!in)
            return fail("--input: cannot open %s", o.input);
    }
    if (!in)
        return fail("cannot read the example");
    app_table t;
    int rt = app_table_read(in, &t, err);
    if (in != stdin)
        fclose(in);
    if (rt != 0)
        return fail("%s: %s", src, err);
    app_balls b;
    if (app_balls_parse(&t, NULL, 2, &b, err) != 0) {
        app_table_free(&t);
        return fail("%s: %s", src, err);
    }

    int rc = EXIT_BAD_INPUT;
    const size_t N = (size_t)o.points;
    double *cs = calloc(N, sizeof *cs), *ratio = calloc(N, sizeof *ratio);
    double *dv = calloc(N, sizeof *dv), *dq = calloc(N, sizeof *dq);
    double *q = calloc(N, sizeof *q), *qd = calloc(N, sizeof *qd);
    char *csv = app_path_join(o.out, "sweep-c.csv"), *gp = app_path_join(o.out, "sweep-c.gp");
    if (!cs || !ratio || !dv || !dq || !q || !qd || !csv || !gp) {
        fail("out of memory");
        rc = 1;
        goto out;
    }

    rc_vec3 n = rc_v3(1.0, 0.0, 0.0);
    if (b.has_pos) {
        n = rc_v3_sub(b.x[1], b.x[0]);
        if (!(rc_v3_norm(n) > 0.0)) {
            fail("%s: zero normal: ball 1 is at the position of ball 0", src);
            goto out;
        }
    }
    /* the speed scale: table speeds, or |p|/m (the classical speed) for momentum input */
    double vmax = 0.0;
    for (size_t i = 0; i < 2; i++)
        vmax = fmax(vmax, rc_v3_norm(b.q[i]) / (b.momentum ? b.m[i] : 1.0));
    if (!(vmax > 0.0)) {
        fail("%s: both balls are at rest: nothing collides", src);
        rc = EXIT_NO_COLLISION;
        goto out;
    }

    rc_particle in0[2], ref[2], pin[2], pout[2];
    st = collide_at(&o, &b, n, INFINITY, in0, ref, err);
    if (st == RC_NO_COLLISION) {
        fprintf(stderr, "%s: no collision: the balls are separating along the normal\n", prog);
        rc = EXIT_NO_COLLISION;
        goto out;
    }
    if (st != RC_OK) {
        fail("%s: %s", src, err);
        goto out;
    }
    double vscale = 0.0, dK = 0.0;
    for (int i = 0; i < 2; i++) {
        vscale = fmax(vscale, rc_v3_norm(rc_velocity(ref[i].m, ref[i].p, 0.0)));
        dK += rc_kinetic_energy(in0[i].m, in0[i].p, 0.0) - rc_kinetic_energy(ref[i].m, ref[i].p, 0.0);
    }
    /* "no heat": eps = 1 keeps rest masses at every c, so there is nothing to compare */
    const int have_heat = o.eps < 1.0 && dK > 0.0;

    app_progress bar;
    app_progress_init(&bar, prog, N);
    for (size_t j = 0; j < N; j++) {
        ratio[j] = o.from * pow(o.to / o.from, (double)j / (double)(N - 1));
        cs[j] = ratio[j] * vmax;
        st = collide_at(&o, &b, n, cs[j], pin, pout, err);
        if (st != RC_OK) {
            if (st == RC_NO_COLLISION) {
                fprintf(stderr, "%s: no collision at c = %g\n", prog, cs[j]);
                rc = EXIT_NO_COLLISION;
            } else {
                fail("%s", err);
            }
            goto out;
        }
        const double k = 1.0 / (cs[j] * cs[j]);
        double d = 0.0;
        for (int i = 0; i < 2; i++) {
            rc_vec3 v = rc_velocity(pout[i].m, pout[i].p, k);
            rc_vec3 vr = rc_velocity(ref[i].m, ref[i].p, 0.0);
            d = fmax(d, rc_v3_norm(rc_v3_sub(v, vr)));
        }
        dv[j] = d / vscale;
        qd[j] = ((pout[0].m - pin[0].m) + (pout[1].m - pin[1].m)) * cs[j] * cs[j];
        /* the cancellation-free form only for a law that declares it keeps each ball's
         * ZMF energy (rc_pair_heat's premise); else the direct difference */
        q[j] = o.law->keeps_zmf_energy ? rc_pair_heat(pin, pout, k, NULL) : qd[j];
        dq[j] = have_heat ? fabs(q[j] - dK) / dK : NAN;
        app_progress_update(&bar, j + 1);
    }
    app_progress_done(&bar);

    /* Deviations at the law's round-off (a few ulps of the relative result) carry no
     * c-dependence: they are left out of the fits, and a quantity that never rises above
     * them (equal masses swap their velocities exactly at every c) has no slope to claim. */
    const double floor_rel = 1e-14;
    double *dv_fit = malloc(N * sizeof *dv_fit), *dq_fit = malloc(N * sizeof *dq_fit);
    if (!dv_fit || !dq_fit) {
        free(dv_fit);
        free(dq_fit);
        fail("out of memory");
        goto out;
    }
    double dv_max = 0.0;
    for (size_t j = 0; j < N; j++) {
        dv_fit[j] = dv[j] > floor_rel ? dv[j] : NAN;
        dq_fit[j] = dq[j] > floor_rel ? dq[j] : NAN;
        dv_max = fmax(dv_max, dv[j]);
    }
    double s_v = NAN, s_q = NAN, sd_v = NAN, sd_q = NAN;
    size_t used_v = 0, used_q = 0;
    const int fit_v = app_loglog_slope(ratio, dv_fit, N, &s_v, NULL, &sd_v, &used_v) == 0;
    const int fit_q = have_heat && app_loglog_slope(ratio, dq_fit, N, &s_q, NULL, &sd_q, &used_q) == 0;
    free(dv_fit);
    free(dq_fit);

    rc = 1;
    if (app_mkdir_p(o.out, err) != 0) {
        fail("--out: %s", err);
        rc = 1;
        goto out;
    }
    app_atomic a;
    if (app_atomic_open(&a, csv, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto out;
    }
    fprintf(a.f, "c,c_over_vmax,vmax2_over_c2,dev_velocity,dev_heat,heat,heat_direct,"
                 "heat_classical\n");
    for (size_t j = 0; j < N; j++) {
        /* (an undefined dev_heat, eps = 1, is an empty field: missing to gnuplot, numpy
         * and pandas alike, where "nan" is a word to some readers) */
        char heat[32] = "";
        if (isfinite(dq[j]))
            snprintf(heat, sizeof heat, "%.17g", dq[j]);
        fprintf(a.f, "%.17g,%.17g,%.17g,%.17g,%s,%.17g,%.17g,%.17g\n", cs[j], ratio[j],
                1.0 / (ratio[j] * ratio[j]), dv[j], heat, q[j], qd[j], dK);
    }
    if (app_atomic_commit(&a, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto out;
    }
    if (write_script(gp, &o, &b, vmax, have_heat, s_v, s_q, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto out;
    }
    int made = 0;
    if (app_gnuplot_run(prog, o.out, "sweep-c.gp", "sweep-c.png", &made, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto out;
    }

    char f1[APP_FMT_LEN], f2[APP_FMT_LEN], f3[APP_FMT_LEN], f4[APP_FMT_LEN];
    printf("%s: %s, law %s, eps %s, %d-D; %zu values of c from %s to %s x |v|max = %s\n",
           prog, use_example ? "built-in example" : src, o.law->name, app_fmt(o.eps, f1),
           b.dim, N, app_fmt(o.from, f2), app_fmt(o.to, f3), app_fmt(vmax, f4));
    if (made)
        printf("wrote %s, %s, %s/sweep-c.png\n", csv, gp, o.out);
    else
        printf("wrote %s, %s (no figure: gnuplot is not installed)\n", csv, gp);
    if (fit_v)
        printf("slope velocities: %.4f +- %.2g (expect -2)\n", s_v, sd_v);
    else
        printf("slope velocities: none (%zu of %zu points above the round-off floor %g; the "
               "largest deviation from c = inf is %.2g: the outcome does not depend on c)\n",
               used_v, N, floor_rel, dv_max);
    if (fit_q)
        printf("slope heat: %.4f +- %.2g (expect -2)\n", s_q, sd_q);
    else if (have_heat)
        printf("slope heat: none (%zu of %zu points above the round-off floor %g)\n", used_q,
               N, floor_rel);
    else
        printf("slope heat: none (eps = 1: no rest-mass change at any c; dev_heat is left empty)\n");
    rc = fflush(stdout) == 0 ? 0 : 1;
out:
    free(cs);
    free(ratio);
    free(dv);
    free(dq);
    free(q);
    free(qd);
    free(csv);
    free(gp);
    app_balls_free(&b);
    app_table_free(&t);
    return rc;
}
