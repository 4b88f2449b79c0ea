/* frames.c — relcol-frames: how much a rigid-ball prediction depends on the frame in which
 * contact is decided. A family of oblique 2-D collisions (impact parameter from head-on to
 * grazing) is run at many c with each contact frame of the library's table (rc_toi_frames)
 * feeding its normal to the zmf law; the app plots how far the outcomes differ and fits
 * the order p of |difference| ~ (v/c)^p as c -> inf. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"

static const char *const prog = "relcol-frames";

enum { EXIT_BAD_INPUT = 2 };
enum { NOBS = 3 };

/* impact parameters b/R: head-on to grazing (R = r0 + r1 = 2) */
static const double impacts[] = {0.0, 0.25, 0.5, 0.75, 0.9, 0.99};
enum { NB = sizeof impacts / sizeof impacts[0] };
static const char *const obs_name[NOBS] = {"angle", "vel", "heat"};
/* fits use c/v >= FIT_FROM: the asymptotic regime (the next order is (v/c)^2 smaller,
 * 1% at c/v = 10) */
#define FIT_FROM 10.0
/* ... and differences above FIT_FLOOR (dimensionless, like the observables, which are
 * O(1)): the outcomes carry ~1e-16 of round-off, so a difference of 1e-12 is still known
 * to 1e-4 relative; smaller ones drift towards the round-off floor and bias the slope. */
#define FIT_FLOOR 1e-12

/* every option error: "relcol-frames: message" and exit status 2 */
#define fail(...) app_fail(prog, EXIT_BAD_INPUT, __VA_ARGS__)

typedef struct options {
    const char *out;
    int points;
    double from, to, eps;
} options;

#define OFF(field) offsetof(options, field)
static const app_opt opts[] = {
    {"--out", "DIR", APP_T_CUSTOM, OFF(out), "out/frames", .parse = app_opt_dir,
     .help = "output folder, created if missing (default %D)"},
    {"--points", "N", APP_T_INT, OFF(points), "33", 5, 100000,
     .help = "number of values of c (default %D, at least 5)"},
    {"--from", "F", APP_T_DOUBLE, OFF(from), "1.25", .help = "smallest c / v, > 1 (default %D)"},
    {"--to", "T", APP_T_DOUBLE, OFF(to), "1e4", .help = "largest c / v, >= 100 (default %D)"},
    {"--eps", "E", APP_T_DOUBLE, OFF(eps), "0.5", .help = "restitution in [0, 1] (default %D)"},
    {NULL},
};

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-frames [--out DIR] [--points N] [--from F] [--to T] [--eps E]\n"
"\n"
"How far the outcome of a rigid-ball collision depends on the frame in which contact is\n"
"decided. Ball 0 (r = 1, m = 1) moves at speed v = 1 along +x onto ball 1 (r = 1, m = 1)\n"
"at rest, with impact parameter b = %g ... %g R (R = 2: head-on to grazing). For each c\n"
"(log-spaced from F v to T v) and each contact frame\n",
            impacts[0], impacts[NB - 1]);
    for (size_t i = 0; rc_toi_frames[i]; i++)
        if (!rc_toi_frames[i]->per_ball) /* (its pair contact is another frame's) */
            fprintf(f, "  %-9s %s\n", rc_toi_frames[i]->name, rc_toi_frames[i]->summary);
    fprintf(f,
"the contact normal found by relcol-toi's routine is fed to the zmf collision law\n"
"(restitution E), and the outcomes are compared between frames, pair by pair:\n"
"  angle  |theta_A - theta_B|, theta = deflection of ball 0 (radians)\n"
"  vel    max over balls |v'_A - v'_B| / v\n"
"  heat   max over balls |Q_A - Q_B| / (m v^2 / 2), Q = (m' - m) c^2 the heat that became\n"
"         rest mass (computed without cancellation from ZMF momenta; 0 when E = 1)\n"
"\n"
"options:\n");
    app_opts_help(f, opts, 16);
    fprintf(f,
"\n"
"writes, atomically, DIR/frames.csv, DIR/frames.gp and (with gnuplot) DIR/frames.png,\n"
"then prints, per impact parameter, observable and pair of frames, the fitted order p\n"
"of |difference| ~ (v/c)^p over c >= %g v (differences above %g, clear of round-off),\n"
"and per pair of frames the range of p.\n"
"exit status: 0 ok; 2 bad option; 1 I/O or computation error.\n",
            FIT_FROM, FIT_FLOOR);
}

/* The checks between options, after the table's parse: 0, else an exit code. */
static int check_options(void *opts)
{
    const options *o = opts;
    char f[APP_FMT_LEN];
    if (!(o->from > 1.0))
        return fail("--from: %s must be > 1 (c must exceed the speed)", app_fmt(o->from, f));
    if (!(o->to >= 100.0) || !(o->to > o->from))
        return fail("--to: %s must be >= 100 and > --from (the fit needs c >= %g v)",
                    app_fmt(o->to, f), FIT_FROM);
    if (!(o->eps >= 0.0 && o->eps <= 1.0))
        return fail("--eps: eps = %s outside [0, 1]", app_fmt(o->eps, f));
    return 0;
}

static const app_cli cli = {.prog = prog, .tab = opts, .usage = usage,
                            .stray_hint = "see --help",
                            .bad = EXIT_BAD_INPUT, .check = check_options};

/* The outcome of one collision with one contact frame. */
typedef struct outcome {
    double theta;   /* deflection of ball 0 */
    rc_vec3 v[2];   /* final velocities */
    double q[2];    /* heat (m' - m) c^2 per ball */
} outcome;

static int run_one(const rc_toi_frame *fr, double c, double bR, double eps,
                   rc_toi_workspace *ws, outcome *res, char *err)
{
    rc_toi_params prm = rc_toi_params_default();
    prm.c = c;
    const double k = rc_inv_c2_of(c);
    rc_toi_ball a = {rc_v3(-6.0, 2.0 * bR, 0.0), 1.0, 1.0, rc_v3(0, 0, 0)};
    rc_toi_ball b = {rc_v3(0.0, 0.0, 0.0), 1.0, 1.0, rc_v3(0, 0, 0)};
    if (rc_momentum_from_velocity(1.0, rc_v3(1.0, 0.0, 0.0), k, &a.p) != RC_OK) {
        app_errf(err, "c = %g: speed 1 not below c", c);
        return -1;
    }
    rc_toi_contact con;
    int st = rc_toi(fr, &prm, &a, &b, ws, &con);
    if (st != RC_OK) {
        app_errf(err, "frame %s, c = %g, b/R = %g: %s", fr->name, c, bR, rc_strerror(st));
        return -1;
    }
    rc_particle in[2] = {{a.m, a.p}, {b.m, b.p}}, outp[2] = {in[0], in[1]};
    rc_collision_params cp = rc_collision_params_default();
    cp.c = c;
    cp.eps = eps;
    st = rc_collide(&rc_law_zmf, &cp, &outp[0], &outp[1], con.n);
    if (st != RC_OK) {
        app_errf(err, "frame %s, c = %g, b/R = %g: law: %s", fr->name, c, bR, rc_strerror(st));
        return -1;
    }
    /* the zmf law keeps each ball's ZMF energy, so rc_pair_heat's formula holds */
    rc_pair_heat(in, outp, k, res->q);
    for (int i = 0; i < 2; i++)
        res->v[i] = rc_velocity(outp[i].m, outp[i].p, k);
    res->theta = atan2(res->v[0].y, res->v[0].x);
    return 0;
}

static void differences(const outcome *A, const outcome *B, double d[NOBS])
{
    d[0] = fabs(A->theta - B->theta);
    d[1] = fmax(rc_v3_norm(rc_v3_sub(A->v[0], B->v[0])), rc_v3_norm(rc_v3_sub(A->v[1], B->v[1])));
    d[2] = fmax(fabs(A->q[0] - B->q[0]), fabs(A->q[1] - B->q[1])) / 0.5; /* m v^2/2 = 1/2 */
}

/* The frames compared: the library's table without the per_ball ones, whose pair contact
 * is another frame's event (they differ in where the engine puts each ball's change, which
 * a two-ball outcome does not see). At most 32 frames. */
static const rc_toi_frame *pair_frames[33];
static size_t pair_frames_fill(void)
{
    size_t nf = 0;
    for (size_t i = 0; rc_toi_frames[i] && nf < 32; i++)
        if (!rc_toi_frames[i]->per_ball)
            pair_frames[nf++] = rc_toi_frames[i];
    pair_frames[nf] = NULL;
    return nf;
}

/* Every pair of the nf frames, a < b, in table order: (0, 1), (0, 2), ..., (1, 2), ... */
static size_t pair_count(size_t nf) { return nf * (nf - 1) / 2; }
static void pair_of(size_t nf, size_t pr, size_t *a, size_t *b)
{
    size_t i = 0;
    while (pr >= nf - 1 - i) {
        pr -= nf - 1 - i;
        i++;
    }
    *a = i;
    *b = i + 1 + pr;
}

/* The figure shows frame 0 against each other frame: one hue per pair of frames (solid
 * against frames that ignore the contraction, dashed against contracting ones), light to
 * dark with the impact parameter. */
static int line_dash(size_t fi) { return pair_frames[fi]->contracted ? 2 : 1; }

/* Pair fi's hue at impact parameter ib (1 .. NB-1): from a tint (mixed with white) at the
 * smallest b/R to a shade (mixed with black) at the largest, so each pair is one family. */
static void pair_colour(size_t fi, int ib, char out[8])
{
    static const unsigned base[] = {0x1f77b4, 0xd62728, 0x2ca02c, 0x9467bd, 0xff7f0e, 0x8c564b};
    const unsigned rgb = base[(fi - 1) % (sizeof base / sizeof base[0])];
    const double t = (double)(ib - 1) / (NB - 2); /* 0 lightest .. 1 darkest */
    int ch[3];
    for (int k = 0; k < 3; k++) {
        const double c = (double)((rgb >> (16 - 8 * k)) & 0xff);
        /* tint 55 % white at t = 0, base at t = 0.6, shade 35 % black at t = 1 */
        const double v = t < 0.6 ? c + (255.0 - c) * 0.55 * (1.0 - t / 0.6)
                                 : c * (1.0 - 0.35 * (t - 0.6) / 0.4);
        ch[k] = (int)lround(v);
    }
    snprintf(out, 8, "#%02x%02x%02x", ch[0], ch[1], ch[2]);
}

static int write_script(const char *path, const options *o, size_t nf, char *err)
{
    const size_t npair = pair_count(nf);
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0)
        return -1;
    FILE *f = a.f;
    char fe[APP_FMT_LEN];
    fprintf(f,
"# frames.gp — written by relcol-frames; run `gnuplot frames.gp` in this folder.\n"
"# How much a rigid-ball collision's outcome depends on the frame in which contact is\n"
"# decided: differences between frames against c/v, for several impact parameters.\n"
"# One colour per pair of frames, light to dark with b/R; grey dotted: (v/c)^2, (v/c)^4.\n");
    /* eps = 1: no heat at any c in any frame, so its differences are round-off only and
     * get no panel */
    const int nobs = o->eps == 1.0 ? NOBS - 1 : NOBS;
    app_gnuplot_head(f, "frames.png",
                     nobs == NOBS ? "size 1650,680 enhanced font 'Sans,12' linewidth 1.4"
                                  : "size 1200,680 enhanced font 'Sans,12' linewidth 1.4",
                     1);
    fprintf(f,
"set grid xtics ytics lc rgb '#dddddd' lw 0.8\n"
"set xlabel 'c / v'\n"
"set key top right spacing 1.05 font ',10' samplen 2.5\n"
"set multiplot layout 1,%d title \"Contact frame dependence of a rigid-ball collision"
" (v = 1 onto a ball at rest, zmf law, ε = %s%s)\\n{/*0.8 one colour per pair of frames,"
" light to dark: b/R = ",
            nobs, app_fmt(o->eps, fe), nobs == NOBS ? "" : ": no heat, no heat panel");
    for (int ib = 1; ib < NB; ib++)
        fprintf(f, "%g%s", impacts[ib], ib + 1 < NB ? ", " : "");
    fprintf(f, " (head-on, b = 0, has no frame difference)}\\n{/*0.8"
               " solid: one frame of the pair ignores the contraction, dashed: both contract}\"\n");
    static const char *const ylab[NOBS] = {
        "|Δθ| deflection of ball 0 (rad)", "max |Δv′| / v", "max |ΔQ| / (m v^2/2)"};
    for (int ob = 0; ob < nobs; ob++) {
        fprintf(f, "set ylabel '%s'\n", ylab[ob]);
        /* references over the first block of rows only (one pass over c) */
        fprintf(f, "plot 'frames.csv' skip 1 every ::0::%d using 3:(1/$3**2) with lines lw 2 "
                   "dt 3 lc rgb '#777777' title '(v/c)^2', \\\n     '' skip 1 every ::0::%d using "
                   "3:(1/$3**4) with lines lw 2 dt 4 lc rgb '#777777' title '(v/c)^4'",
                o->points - 1, o->points - 1);
        /* frame 0 against frame fi is pair fi - 1; the key names each pair once, on its
         * b/R = 0.9 line (the family's own colour) */
        for (size_t fi = 1; fi < nf; fi++)
            for (int ib = 1; ib < NB; ib++) {
                const int dt = line_dash(fi);
                const int col = 4 + ob * (int)npair + (int)(fi - 1);
                char key[96] = "notitle", rgb[8];
                pair_colour(fi, ib, rgb);
                if (ib == NB - 2)
                    snprintf(key, sizeof key, "title '%s vs %s%s'", pair_frames[0]->name,
                             pair_frames[fi]->name,
                             pair_frames[fi]->contracted ? "" : " (no contraction)");
                fprintf(f, ", \\\n     '' skip 1 using 3:($1 == %g && $%d > 0 ? $%d : 1/0) "
                           "with lines lw 2 dt %d lc rgb '%s' %s",
                        impacts[ib], col, col, dt, rgb, key);
            }
        fprintf(f, "\n");
    }
    fprintf(f, "unset multiplot\n");
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
    const size_t N = (size_t)o.points;
    /* the library's frames, however many its table holds */
    const size_t nf = pair_frames_fill();
    const size_t npair = pair_count(nf);
    int rc = 1;
    double *cs = malloc(N * sizeof *cs);
    /* d[((ib * N + j) * NOBS + ob) * npair + pr] */
    double *d = malloc(NB * N * NOBS * npair * sizeof *d);
    double *th = malloc(NB * N * nf * sizeof *th);
    double *xs = malloc(N * sizeof *xs), *ys = malloc(N * sizeof *ys);
    char *csv = app_path_join(o.out, "frames.csv"), *gp = app_path_join(o.out, "frames.gp");
    rc_toi_workspace *ws = NULL;
    (void)rc_toi_workspace_create(&ws); /* NULL on failure: checked below */
    outcome *res = malloc(nf * sizeof *res);
    size_t *pair_a = malloc((npair + 1) * sizeof *pair_a);
    size_t *pair_b = malloc((npair + 1) * sizeof *pair_b);
    double *pmin = malloc((npair + 1) * sizeof *pmin), *pmax = malloc((npair + 1) * sizeof *pmax);
    int *nfit = malloc((npair + 1) * sizeof *nfit);
    if (!cs || !d || !th || !xs || !ys || !csv || !gp || !ws || !res || !pair_a || !pair_b ||
        !pmin || !pmax || !nfit) {
        fprintf(stderr, "%s: out of memory\n", prog);
        goto out;
    }
    const rc_toi_frame *const *frames = pair_frames;
    for (size_t pr = 0; pr < npair; pr++)
        pair_of(nf, pr, &pair_a[pr], &pair_b[pr]);
    app_progress bar;
    app_progress_init(&bar, "frames", NB * N);
    for (size_t j = 0; j < N; j++)
        cs[j] = o.from * pow(o.to / o.from, (double)j / (double)(N - 1));
    for (int ib = 0; ib < NB; ib++)
        for (size_t j = 0; j < N; j++) {
            for (size_t fi = 0; fi < nf; fi++) {
                if (run_one(frames[fi], cs[j], impacts[ib], o.eps, ws, &res[fi], err) != 0) {
                    fprintf(stderr, "%s: %s\n", prog, err);
                    goto out;
                }
                th[(ib * N + j) * nf + fi] = res[fi].theta;
            }
            for (size_t pr = 0; pr < npair; pr++) {
                double dd[NOBS];
                differences(&res[pair_a[pr]], &res[pair_b[pr]], dd);
                for (int ob = 0; ob < NOBS; ob++)
                    d[((ib * N + j) * NOBS + ob) * npair + pr] = dd[ob];
            }
            app_progress_update(&bar, ib * N + j + 1);
        }
    app_progress_done(&bar);

    if (app_mkdir_p(o.out, err) != 0) {
        fprintf(stderr, "%s: --out: %s\n", prog, err);
        goto out;
    }
    app_atomic a;
    if (app_atomic_open(&a, csv, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto out;
    }
    fprintf(a.f, "b_over_R,c,c_over_v");
    for (int ob = 0; ob < NOBS; ob++)
        for (size_t pr = 0; pr < npair; pr++)
            fprintf(a.f, ",d_%s_%s_%s", obs_name[ob], frames[pair_a[pr]]->name,
                    frames[pair_b[pr]]->name);
    for (size_t fi = 0; fi < nf; fi++)
        fprintf(a.f, ",theta_%s", frames[fi]->name);
    fprintf(a.f, "\n");
    for (int ib = 0; ib < NB; ib++)
        for (size_t j = 0; j < N; j++) {
            fprintf(a.f, "%g,%.17g,%.17g", impacts[ib], cs[j], cs[j]);
            for (size_t k = 0; k < NOBS * npair; k++)
                fprintf(a.f, ",%.17g", d[(ib * N + j) * NOBS * npair + k]);
            for (size_t fi = 0; fi < nf; fi++)
                fprintf(a.f, ",%.17g", th[(ib * N + j) * nf + fi]);
            fprintf(a.f, "\n");
        }
    if (app_atomic_commit(&a, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto out;
    }
    if (write_script(gp, &o, nf, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto out;
    }
    int made = 0;
    if (app_gnuplot_run(prog, o.out, "frames.gp", "frames.png", &made, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto out;
    }

    char f1[APP_FMT_LEN], f2[APP_FMT_LEN], f3[APP_FMT_LEN];
    printf("%s: 2-D, v = 1 onto a ball at rest, zmf law, eps %s; %zu values of c from %s to "
           "%s v\n", prog, app_fmt(o.eps, f1), N, app_fmt(o.from, f2), app_fmt(o.to, f3));
    if (made)
        printf("wrote %s, %s, %s/frames.png\n", csv, gp, o.out);
    else
        printf("wrote %s, %s (no figure: gnuplot is not installed)\n", csv, gp);
    printf("fitted order p of |difference| ~ (v/c)^p (least squares on log-log, c >= %g v, "
           "differences > %g):\n", FIT_FROM, FIT_FLOOR);
    printf("  b/R   observable");
    for (size_t pr = 0; pr < npair; pr++)
        printf("%*s%s-%s", 3, "", frames[pair_a[pr]]->name, frames[pair_b[pr]]->name);
    printf("\n");
    for (size_t pr = 0; pr < npair; pr++) {
        pmin[pr] = INFINITY;
        pmax[pr] = -INFINITY;
        nfit[pr] = 0;
    }
    for (int ib = 0; ib < NB; ib++)
        for (int ob = 0; ob < NOBS; ob++) {
            printf("  %-5g %-10s", impacts[ib], obs_name[ob]);
            for (size_t pr = 0; pr < npair; pr++) {
                size_t n = 0;
                int zero = 1;
                for (size_t j = 0; j < N; j++) {
                    const double y = d[((ib * N + j) * NOBS + ob) * npair + pr];
                    zero &= y == 0.0;
                    if (cs[j] >= FIT_FROM && y > FIT_FLOOR) {
                        xs[n] = cs[j];
                        ys[n] = y;
                        n++;
                    }
                }
                double slope = NAN, sd = NAN;
                size_t used = 0;
                /* right-aligned under "  A-B" */
                const int width = (int)(strlen(frames[pair_a[pr]]->name) +
                                        strlen(frames[pair_b[pr]]->name) + 3);
                if (app_loglog_slope(xs, ys, n, &slope, NULL, &sd, &used) == 0) {
                    printf("%*.3f", width, -slope);
                    pmin[pr] = fmin(pmin[pr], -slope);
                    pmax[pr] = fmax(pmax[pr], -slope);
                    nfit[pr]++;
                } else {
                    /* exactly 0 at every c (head-on; heat with eps = 1), or fewer than 3
                     * points above the floor */
                    printf("%*s", width, zero ? "exact 0" : "<3 pts");
                }
            }
            printf("\n");
        }
    for (size_t pr = 0; pr < npair; pr++) {
        if (nfit[pr] > 0)
            printf("%s vs %s: frame differences vanish as (v/c)^p, p in [%.3f, %.3f] "
                   "(%d fits)\n", frames[pair_a[pr]]->name, frames[pair_b[pr]]->name,
                   pmin[pr], pmax[pr], nfit[pr]);
        else
            printf("%s vs %s: no fit (differences exactly 0 or below the floor)\n",
                   frames[pair_a[pr]]->name, frames[pair_b[pr]]->name);
    }
    rc = fflush(stdout) == 0 ? 0 : 1;
out:
    rc_toi_workspace_free(&ws);
    free(cs);
    free(d);
    free(th);
    free(xs);
    free(ys);
    free(csv);
    free(gp);
    free(res);
    free(pair_a);
    free(pair_b);
    free(pmin);
    free(pmax);
    free(nfit);
    return rc;
}
