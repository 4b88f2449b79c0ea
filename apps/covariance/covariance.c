/* covariance.c — relcol-covariance: the many-body frame dependence of the engine (issue 16,
 * item 3), swept over the cluster's density and c. For each (frame, density, c) an open
 * cluster is run from the table frame and from a frame moving along x, and the final
 * momenta and outgoing worldlines, transformed back, are compared; beside them the same
 * comparison for a start moved by 1e-15 relative, the round-off the dynamics amplifies.
 * The harness is cluster.h (shared with the covariance_cluster benchmark). */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "cluster.h"
#include "covariance_plot.h"

static const char *const prog = "relcol-covariance";

enum { EXIT_BAD_INPUT = 2 };
#define MAXLIST 64
#define MAXFRAMES 32

/* The shell's inner radius as a fraction of its outer one (the benchmark's ring, 16..30,
 * is about this), and the velocity recipe: inwards plus isotropic noise in the benchmark's
 * proportion (0.35 and 0.15), then scaled to the rms speed. */
#define SHELL_INNER 0.5
#define V_IN 0.35
#define V_NOISE 0.15
/* Densest shell offered: random placement COV_MIN_SEP_RADII apart jams near 0.55 (2-D)
 * and 0.38 (3-D) of the exclusion discs' or spheres' share, 4 and 8 times the balls'; the
 * draw is denser at the inner rim, so a margin below those. */
/* The box holds the cluster's whole run from both frames, about 40 R |U| / v_rms wide:
 * these keep it within a few digits of the ball radius (positions keep their round-off
 * near 1e-12 of r), and v_rms where the engine's times and distances are of order r. */
#define BOOST_RATIO_MAX 1e3
#define V_RMS_MIN 1e-6
#define V_RMS_MAX 1e6
#define DENSITY_MAX_2D 0.08
/* The runs end at T_END_RADII R / v_rms of their own frames, long after the cluster has
 * flown apart, but a pair of neighbours flying out nearly together may meet much later,
 * and the two runs' ends are different hyperplanes: a contact between them would count
 * in one run only. So the end is doubled, up to T_END_DOUBLINGS times, until in every run
 * no pair may still meet (cov_result.open). */
#define T_END_RADII 10.0
#define T_END_DOUBLINGS 3
#define DENSITY_MAX_3D 0.025

#define fail(...) app_fail(prog, EXIT_BAD_INPUT, __VA_ARGS__)

typedef struct options {
    const rc_toi_frame *frames[MAXFRAMES];
    int nframes;
    long n, dim;
    double density[MAXLIST], c[MAXLIST];
    int ndensity, nc, density_given;
    double boost, v_rms;
    uint64_t seed;
    const char *out;
} options;

/* --frames: comma-separated names, each once */
static int parse_frames(const char *val, void *dst, void *opts, char *err)
{
    (void)dst;
    options *o = opts;
    char *copy = strdup(val), *save = NULL, list[256];
    if (!copy) {
        app_errf(err, "out of memory");
        return -1;
    }
    o->nframes = 0;
    int rc = 0;
    for (char *tok = strtok_r(copy, ",", &save); tok && rc == 0; tok = strtok_r(NULL, ",", &save)) {
        while (*tok == ' ')
            tok++;
        const rc_toi_frame *fr = rc_toi_frame_find(tok);
        if (!fr) {
            app_errf(err, "unknown frame '%s' (known: %s)", tok,
                     app_toi_frame_list(list, sizeof list));
            rc = -1;
            break;
        }
        for (int j = 0; j < o->nframes && rc == 0; j++)
            if (o->frames[j] == fr) {
                app_errf(err, "'%s' given twice", tok);
                rc = -1;
            }
        if (rc == 0 && o->nframes == MAXFRAMES) {
            app_errf(err, "more than %d frames", MAXFRAMES);
            rc = -1;
        }
        if (rc == 0)
            o->frames[o->nframes++] = fr;
    }
    free(copy);
    if (rc == 0 && o->nframes == 0) {
        app_errf(err, "no frame named in '%s'", val);
        rc = -1;
    }
    return rc;
}

/* --c: comma-separated speeds of light, inf too (app_parse_list takes finite numbers
 * only: the items one by one) */
static int parse_c(const char *val, void *dst, void *opts, char *err)
{
    (void)dst;
    options *o = opts;
    char *copy = strdup(val), *save = NULL;
    if (!copy) {
        app_errf(err, "out of memory");
        return -1;
    }
    o->nc = 0;
    int rc = 0;
    for (char *tok = strtok_r(copy, ",", &save); tok && rc == 0;
         tok = strtok_r(NULL, ",", &save)) {
        double c;
        if (o->nc == MAXLIST) {
            app_errf(err, "more than %d values", MAXLIST);
            rc = -1;
        } else if (app_parse_double(tok, 1, &c, err) != 0 || app_check_c(c, err) != 0)
            rc = -1;
        else
            o->c[o->nc++] = c;
    }
    free(copy);
    if (rc == 0 && o->nc == 0) {
        app_errf(err, "no value in '%s'", val);
        rc = -1;
    }
    return rc;
}

static int parse_seed(const char *val, void *dst, void *opts, char *err)
{
    (void)opts;
    uint64_t *seed = dst;
    if (app_parse_u64(val, seed, err) != 0)
        return -1;
    if (*seed > UINT_MAX) {
        app_errf(err, "%s is above %u (the draw's state is an unsigned int)", val, UINT_MAX);
        return -1;
    }
    return 0;
}

static void frames_help(FILE *f)
{
    /* (the default frame list, as the library's table has it) */
    char names[256] = "";
    for (size_t i = 0; rc_toi_frames[i]; i++) {
        const rc_toi_frame *fr = rc_toi_frames[i];
        if (!(fr->contracted || fr->pointlike))
            continue;
        if (*names)
            strncat(names, ",", sizeof names - strlen(names) - 1);
        strncat(names, fr->name, sizeof names - strlen(names) - 1);
    }
    fprintf(f, "contact frames, comma-separated (default: every frame of the library\n"
               "                  that declares contracted or pointlike contact: %s)\n", names);
}

static void density_help(FILE *f)
{
    fprintf(f,
"packing fractions of the shell: N ball volumes over the shell's\n"
"                  volume, which fixes R (default 0.002,0.005,0.01,0.02,0.04 in 2-D,\n"
"                  0.001,0.002,0.005,0.01 in 3-D; at most %g in 2-D, %g in 3-D)\n",
            DENSITY_MAX_2D, DENSITY_MAX_3D);
}

#define OFF(field) offsetof(options, field)
static const app_opt opts[] = {
    {"--frames", "LIST", APP_T_CUSTOM, OFF(frames), .parse = parse_frames,
     .help_more = frames_help},
    /* (the cluster: at least 50 balls, so a few collisions per ball) */
    {"--n", "N", APP_T_LONG, OFF(n), "64", 50, 1000000,
     .help = "balls, at least 50 (default %D)"},
    {"--dim", "D", APP_T_LONG, OFF(dim), "2", 2, 3,
     .help = "2 (discs; default) or 3 (spheres)"},
    {"--density", "LIST", APP_T_LIST, OFF(density), .hi = MAXLIST, .count = OFF(ndensity),
     .given = APP_GIVEN(options, density_given), .help_more = density_help},
    {"--c", "LIST", APP_T_CUSTOM, OFF(c), "1,1.5,3,inf", .parse = parse_c,
     .help = "speeds of light, 'inf' for classical (default %D); each\n"
             "above U and above every ball's speed"},
    {"--boost", "U", APP_T_DOUBLE, OFF(boost), "0.6",
     .help = "the moving frame's speed along x (default %D; 0 < |U| < every c,\n"
             "|U| <= 1000 V)"},
    {"--v-rms", "V", APP_T_DOUBLE, OFF(v_rms), "0.5",
     .help = "rms table speed of the balls, in [1e-6, 1e6] (default %D, that is\n"
             "0.5c at c = 1)"},
    {"--seed", "S", APP_T_CUSTOM, OFF(seed), "16", .parse = parse_seed,
     .help = "seed of the draw (default %D: with --n 64 --dim 2 the ring of the\n"
             "covariance_cluster benchmark's recipe)"},
    {"--out", "DIR", APP_T_CUSTOM, OFF(out), "out/covariance", .parse = app_opt_dir,
     .help = "output folder (default %D)"},
    {NULL},
};

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sort a list in increasing order (the figures draw lines through it; inf last) and
 * name a value given twice. */
static int sort_list(const char *opt, double *v, int n)
{
    char f[APP_FMT_LEN];
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    for (int i = 1; i < n; i++)
        if (v[i] == v[i - 1])
            return fail("%s: %s given twice", opt, isinf(v[i]) ? "inf" : app_fmt(v[i], f));
    return 0;
}

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-covariance [--frames LIST] [--n N] [--dim 2|3] [--density LIST]\n"
"                         [--c LIST] [--boost U] [--v-rms V] [--seed S] [--out DIR]\n"
"How much the engine's many-body dynamics depends on the inertial frame it is run in.\n"
"An open cluster of N balls (rest radius 0.5, rest mass 1, elastic) is drawn on a shell\n"
"(2-D ring, 3-D spherical shell) between radii R/2 and R around the centre of a box they\n"
"never reach, moving inwards plus isotropic noise, and run from the table frame and from\n"
"a frame moving at U along x whose initial data are the same worldlines cut at its\n"
"t' = 0 (a draw is taken only if both runs start before any collision). The moving\n"
"run's final state is transformed back and compared ball by ball with the table run's.\n"
"The same balls (table velocities) at every c, so that U/c and v/c are what changes.\n");
    app_opts_help(f, opts, 18);
    /* (two calls: one string would pass the length a C compiler must support) */
    fprintf(f,
"Each run ends at time 10 R / V of its own frame, long after the cluster has flown\n"
"apart, and after its last contact: if in any run a pair of balls may still meet (their\n"
"lines come within a diameter later, in that run's frame or the pair's ZMF), the end is\n"
"doubled, up to %d times, so that no contact counts in one run only (the two runs' ends\n"
"are different hyperplanes). Per (frame, density, c) one row of DIR/covariance.csv:\n"
"  frame,covariant,c,c_index,density,radius,n,dim,boost,v_rms,draws\n"
"      frame, its declared covariant property, the row's c (and its place in --c),\n"
"      density, shell radius R, draws made to find a collision-free start\n"
"  collisions_table,collisions_moving,collisions_roundoff  contacts in each run\n"
"  overlaps_table,overlaps_moving  contacts decided by the overlap policy\n"
"  dp_frames    max_i |p_i(table) - p_i(moving, boosted back)| / rms |p|\n"
"  dp_roundoff  the same for the table run against itself with every position moved by\n"
"               -1, 0 or +1 times 1e-15 relative: how much the dynamics amplifies\n"
"               round-off. dp_frames far above it is a frame dependence of the model,\n"
"               at or below it chaos amplifying round-off\n"
"  dx_frames, dx_roundoff  the same for the outgoing worldlines: each ball's final event\n"
"               of the moving run, transformed back and flown freely to the table run's\n"
"               end time, against the table run's position, over the rest radius (the\n"
"               engine does not expose its contact events: these worldlines carry where\n"
"               and when each ball last changed velocity)\n"
"  conflicts_table,conflicts_moving  contacts the per-ball (covariant) frame's rules\n"
"               decided: tube and order conflicts and collisions undone (0 in the\n"
"               other frames)\n"
"  note         empty, or why the row has no differences: which run the engine refused\n"
"               or failed, and why (e.g. shapes that overlap on the moving frame's\n"
"               slice); a collision before the moving frame's start; a wall reached;\n"
"               pairs that may still meet at the longest end\n"
"and DIR/covariance.gp and, if gnuplot is installed, DIR/covariance.png: dp against\n"
"density, one panel per c, one colour per frame (solid: frames, dashed: round-off;\n"
"ringed: dp_frames within 10 times dp_roundoff; an x with a number: a row without\n"
"differences, its note in the heading; frames offset sideways so equal values show);\n"
"with two finite c or more also DIR/covariance-c.gp and covariance-c.png: dp against\n"
"c / V, one panel per frame, one colour per density. Both lists are sorted (rows go\n"
"density by density, then c, then frame); a value given twice is refused.\n"
"exit status: 0 ok; 2 bad input (one line naming the option); 1 I/O error.\n",
            T_END_DOUBLINGS);
}

/* The checks between options, after the table's parse: 0, else an exit code. */
static int check_options(void *opts)
{
    options *o = opts;
    char f1[APP_FMT_LEN], f2[APP_FMT_LEN];
    const double dmax = o->dim == 2 ? DENSITY_MAX_2D : DENSITY_MAX_3D;
    if (!o->density_given) {
        const double d2[] = {0.002, 0.005, 0.01, 0.02, 0.04}, d3[] = {0.001, 0.002, 0.005, 0.01};
        o->ndensity = o->dim == 2 ? 5 : 4;
        memcpy(o->density, o->dim == 2 ? d2 : d3, (size_t)o->ndensity * sizeof(double));
    }
    if (sort_list("--density", o->density, o->ndensity) != 0 ||
        sort_list("--c", o->c, o->nc) != 0)
        return EXIT_BAD_INPUT;
    for (int i = 0; i < o->ndensity; i++)
        if (!(o->density[i] > 0.0 && o->density[i] <= dmax))
            return fail("--density: %s outside (0, %s] in %ld-D (random placement %g radii "
                        "apart fills no more)", app_fmt(o->density[i], f1), app_fmt(dmax, f2),
                        o->dim, COV_MIN_SEP_RADII);
    /* (only the ratios U / v_rms and c / v_rms matter; the bounds keep the box, which
     * holds the whole run from either frame, within digits of the ball radius) */
    if (!(o->v_rms >= V_RMS_MIN && o->v_rms <= V_RMS_MAX))
        return fail("--v-rms: %s outside [%g, %g] (table units: the ball radius is 0.5)",
                    app_fmt(o->v_rms, f1), V_RMS_MIN, V_RMS_MAX);
    if (o->boost == 0.0)
        return fail("--boost: 0 must be nonzero (the moving frame must move)");
    if (!(fabs(o->boost) <= BOOST_RATIO_MAX * o->v_rms))
        return fail("--boost: |U| = %s is more than %g times --v-rms %s (the cluster would "
                    "drift too far in the moving frame)", app_fmt(fabs(o->boost), f1),
                    BOOST_RATIO_MAX, app_fmt(o->v_rms, f2));
    for (int k = 0; k < o->nc; k++) {
        if (!(fabs(o->boost) < o->c[k]))
            return fail("--boost: |U| = %s is not below c = %s", app_fmt(fabs(o->boost), f1),
                        app_fmt(o->c[k], f2));
        if (!(o->v_rms < o->c[k]))
            return fail("--v-rms: %s is not below c = %s", app_fmt(o->v_rms, f1),
                        app_fmt(o->c[k], f2));
    }
    return 0;
}

static const app_cli cli = {.prog = prog, .tab = opts, .usage = usage,
                            .stray_hint = "see --help",
                            .bad = EXIT_BAD_INPUT, .check = check_options};

/* The cluster of one density at one c, its runs' end doubled dbl times. */
static cov_def cluster_def(const options *o, double density, double c, int dbl)
{
    const double r = 0.5;
    /* N ball volumes = density x shell volume, the shell between R/2 and R */
    const double R = o->dim == 2
        ? r * sqrt((double)o->n / (density * (1.0 - SHELL_INNER * SHELL_INNER)))
        : r * cbrt((double)o->n / (density * (1.0 - SHELL_INNER * SHELL_INNER * SHELL_INNER)));
    cov_def d = {.dim = (int)o->dim, .n = (size_t)o->n, .r = r, .inner = SHELL_INNER * R,
                 .outer = R, .v_in = V_IN, .v_noise = V_NOISE, .v_rms = o->v_rms, .c = c,
                 .u = o->boost, .seed = (unsigned)o->seed};
    d.t_end = T_END_RADII * R / o->v_rms * (double)(1 << dbl);
    /* no wall within reach: the fastest ball (the noise and the scaling to v_rms give at
     * most about 1.7 v_rms) plus the moving frame's drift, with a factor 2 to spare, for
     * the whole run (reached anyway: the row says so). (Not wider: the positions' round-off
     * grows with the box, and the 1e-15 run's with them.) */
    d.box = 2.0 * (R + 2.0 * (2.0 * o->v_rms + fabs(o->boost)) * d.t_end);
    return d;
}

typedef struct row {
    const rc_toi_frame *frame;
    int ci, di;
    double radius;
    int draws;
    cov_result r;
    int have;          /* r holds differences */
    char note[160];
} row;

static const char *fmt_c(double c, char *buf)
{
    return isinf(c) ? "inf" : app_fmt(c, buf);
}

static int write_csv(const char *path, const options *o, const row *rows, size_t nrows,
                     char *err)
{
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0)
        return -1;
    fprintf(a.f, "frame,covariant,c,c_index,density,radius,n,dim,boost,v_rms,draws,"
                 "collisions_table,collisions_moving,collisions_roundoff,overlaps_table,"
                 "overlaps_moving,dp_frames,dp_roundoff,dx_frames,dx_roundoff,conflicts_table,"
                 "conflicts_moving,note\n");
    for (size_t k = 0; k < nrows; k++) {
        const row *w = &rows[k];
        char fc[APP_FMT_LEN], fd[APP_FMT_LEN], fb[APP_FMT_LEN], fv[APP_FMT_LEN];
        fprintf(a.f, "%s,%d,%s,%d,%s,%.17g,%ld,%ld,%s,%s,%d,", w->frame->name,
                w->frame->covariant ? 1 : 0, fmt_c(o->c[w->ci], fc), w->ci,
                app_fmt(o->density[w->di], fd), w->radius, o->n, o->dim,
                app_fmt(o->boost, fb), app_fmt(o->v_rms, fv), w->draws);
        /* (a row without differences has empty fields: missing to gnuplot, numpy and
         * pandas alike) */
        if (w->have)
            fprintf(a.f, "%llu,%llu,%llu,%llu,%llu,%.17g,%.17g,%.17g,%.17g,%llu,%llu,",
                    (unsigned long long)w->r.coll[0], (unsigned long long)w->r.coll[1],
                    (unsigned long long)w->r.coll[2], (unsigned long long)w->r.overlaps[0],
                    (unsigned long long)w->r.overlaps[1], w->r.dp_frames, w->r.dp_roundoff,
                    w->r.dx_frames, w->r.dx_roundoff,
                    (unsigned long long)(w->r.tube[0] + w->r.order[0] + w->r.undone[0]),
                    (unsigned long long)(w->r.tube[1] + w->r.order[1] + w->r.undone[1]));
        else
            fprintf(a.f, ",,,,,,,,,,,");
        fprintf(a.f, "%s\n", w->note);
    }
    return app_atomic_commit(&a, err);
}

/* The figures' view of the sweep (covariance_plot.c): the rows in the CSV's order. */
static int write_scripts(const char *gp, const char *gpc, const options *o, const row *rows,
                         size_t nrows, int nfin, char *err)
{
    cov_plot_row *pr = malloc((nrows ? nrows : 1) * sizeof *pr);
    if (!pr) {
        app_errf(err, "out of memory");
        return -1;
    }
    for (size_t i = 0; i < nrows; i++)
        pr[i] = (cov_plot_row){rows[i].have, rows[i].r.dp_frames, rows[i].r.dp_roundoff,
                               rows[i].note};
    const cov_plot p = {o->frames, o->nframes, o->density, o->ndensity, o->c, o->nc,
                        o->n, o->dim, o->boost, o->v_rms};
    int st = cov_plot_density(gp, &p, pr, err);
    if (st == 0 && gpc)
        st = cov_plot_c(gpc, &p, pr, nfin, err);
    free(pr);
    return st;
}

int main(int argc, char **argv)
{
    options o;
    memset(&o, 0, sizeof o);
    /* (the default frames, as the library's table has them) */
    for (size_t i = 0; rc_toi_frames[i] && o.nframes < MAXFRAMES; i++)
        if (rc_toi_frames[i]->contracted || rc_toi_frames[i]->pointlike)
            o.frames[o.nframes++] = rc_toi_frames[i];
    int st = app_start(&cli, argc, argv, &o);
    if (st >= 0)
        return st;

    char err[APP_ERR_LEN];
    const size_t nrows = (size_t)o.nframes * (size_t)o.ndensity * (size_t)o.nc;
    row *rows = calloc(nrows, sizeof *rows);
    char *csv = app_path_join(o.out, "covariance.csv"), *gp = app_path_join(o.out, "covariance.gp");
    int rc = 1;
    if (!rows || !csv || !gp) {
        fail("out of memory");
        goto out;
    }
    app_progress bar;
    app_progress_init(&bar, prog, (size_t)o.ndensity * (size_t)o.nc);
    size_t k = 0;
    for (int di = 0; di < o.ndensity; di++) {
        for (int ci = 0; ci < o.nc; ci++) {
            const cov_def d = cluster_def(&o, o.density[di], o.c[ci], 0);
            cov_cluster cl;
            /* (the start is checked with the first frame asked for: every frame's own
             * table run says if it collides before the moving frame's start) */
            const int e = cov_cluster_make(&d, o.frames[0], &cl);
            char f1[APP_FMT_LEN], f2[APP_FMT_LEN], f3[APP_FMT_LEN];
            if (e == COV_EPLACE) {
                rc = fail("--density: %s: %ld balls do not fit %g radii apart in the %ld-D "
                          "shell (take a lower density)", app_fmt(o.density[di], f1), o.n,
                          COV_MIN_SEP_RADII, o.dim);
                goto out;
            }
            if (e == COV_ESPEED) {
                rc = fail("--c: at c = %s a ball of the draw at density %s is not slower than "
                          "c (--v-rms %s: its fastest balls move at about 1.5 times it)",
                          app_fmt(o.c[ci], f1), app_fmt(o.density[di], f2),
                          app_fmt(o.v_rms, f3));
                goto out;
            }
            if (e == COV_ENOMEM) {
                fail("out of memory");
                goto out;
            }
            for (int j = 0; j < o.nframes; j++, k++) {
                row *w = &rows[k];
                w->frame = o.frames[j];
                w->ci = ci;
                w->di = di;
                w->radius = d.outer;
                w->draws = e == COV_OK ? cl.draws : COV_MAX_DRAWS;
                if (e != COV_OK) {
                    snprintf(w->note, sizeof w->note, "no draw starts collision-free in both frames");
                    continue;
                }
                /* (a longer run is drawn again in its wider box: the same balls, but for
                 * round-off, which is why the first box is kept when it is enough) */
                int cmp = cov_compare(&d, w->frame, &cl, &w->r), dbl = 0;
                while (cmp == 0 && w->r.open[0] + w->r.open[1] + w->r.open[2] != 0 &&
                       dbl < T_END_DOUBLINGS) {
                    const cov_def dk = cluster_def(&o, o.density[di], o.c[ci], ++dbl);
                    cov_cluster ck;
                    const int ek = cov_cluster_make(&dk, o.frames[0], &ck);
                    if (ek == COV_ENOMEM) {
                        cov_cluster_free(&cl);
                        fail("out of memory");
                        goto out;
                    }
                    if (ek != COV_OK) {
                        snprintf(w->note, sizeof w->note, "the draw for the run to t = %s: %s",
                                 app_fmt(dk.t_end, f1), cov_strerror(ek));
                        break;
                    }
                    cmp = cov_compare(&dk, w->frame, &ck, &w->r);
                    w->draws = ck.draws;
                    cov_cluster_free(&ck);
                }
                if (*w->note)
                    continue;
                if (cmp != 0) {
                    if (w->r.status == RC_ENOMEM) {
                        cov_cluster_free(&cl);
                        fail("out of memory");
                        goto out;
                    }
                    static const char *const run_name[] = {"table", "moving", "round-off"};
                    snprintf(w->note, sizeof w->note, "the %s run: %s: %s",
                             run_name[w->r.which], w->r.running ? "the engine failed"
                                                                : "the engine refused the start",
                             rc_strerror(w->r.status));
                    /* (a CSV field: the library's text keeps no comma here) */
                    for (char *q = w->note; *q; q++)
                        if (*q == ',')
                            *q = ';';
                    continue;
                }
                for (int k = 0; k < 3; k++)
                    app_validity_note_report(&w->r.val[k]);
                if (w->r.early[0] != 0) {
                    snprintf(w->note, sizeof w->note, "a collision before the moving frame's start (table run)");
                    continue;
                }
                if (w->r.open[0] + w->r.open[1] + w->r.open[2] != 0) {
                    char ft[APP_FMT_LEN];
                    snprintf(w->note, sizeof w->note, "pairs may still meet after t = %s "
                             "(table/moving/round-off runs: %llu/%llu/%llu)",
                             app_fmt(cluster_def(&o, o.density[di], o.c[ci], dbl).t_end, ft), (unsigned long long)w->r.open[0],
                             (unsigned long long)w->r.open[1], (unsigned long long)w->r.open[2]);
                    continue;
                }
                if (w->r.walls) {
                    snprintf(w->note, sizeof w->note, "a ball reached a wall");
                    continue;
                }
                w->have = 1;
            }
            cov_cluster_free(&cl);
            app_progress_update(&bar, (size_t)(di * o.nc + ci + 1));
        }
    }
    app_progress_done(&bar);

    if (app_mkdir_p(o.out, err) != 0) {
        fail("--out: %s", err);
        rc = 1;
        goto out;
    }
    rc = 1;
    int made = 0, made_c = 0, nfin = 0;
    while (nfin < o.nc && isfinite(o.c[nfin]))
        nfin++;
    char *gpc = nfin >= 2 ? app_path_join(o.out, "covariance-c.gp") : NULL;
    if (nfin >= 2 && !gpc) {
        fprintf(stderr, "%s: out of memory\n", prog);
        goto out;
    }
    if (write_csv(csv, &o, rows, nrows, err) != 0 ||
        write_scripts(gp, gpc, &o, rows, nrows, nfin, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        free(gpc);
        goto out;
    }
    if (app_gnuplot_run(prog, o.out, "covariance.gp", "covariance.png", &made, err) != 0 ||
        (gpc && app_gnuplot_run(prog, o.out, "covariance-c.gp", "covariance-c.png", &made_c,
                                err) != 0)) {
        fprintf(stderr, "%s: %s\n", prog, err);
        free(gpc);
        goto out;
    }

    char fb[APP_FMT_LEN], fv[APP_FMT_LEN];
    printf("%s: %ld-D cluster of %ld balls, moving frame %s, v_rms %s, seed %llu; dp = max "
           "|dp| / rms |p|, dx = max |dx| / r\n", prog, o.dim, o.n, app_fmt(o.boost, fb),
           app_fmt(o.v_rms, fv), (unsigned long long)o.seed);
    printf("%-10s %6s %9s %11s %16s %12s %12s %12s %12s\n", "frame", "c", "density",
           "radius", "coll.tab/mov", "dp_frames", "dp_roundoff", "dx_frames", "dx_roundoff");
    for (size_t i = 0; i < nrows; i++) {
        const row *w = &rows[i];
        char fc[APP_FMT_LEN], fd[APP_FMT_LEN], cc[48];
        printf("%-10s %6s %9s %11.4g ", w->frame->name, fmt_c(o.c[w->ci], fc),
               app_fmt(o.density[w->di], fd), w->radius);
        if (w->have) {
            snprintf(cc, sizeof cc, "%llu/%llu", (unsigned long long)w->r.coll[0],
                     (unsigned long long)w->r.coll[1]);
            printf("%16s %12.3e %12.3e %12.3e %12.3e\n", cc, w->r.dp_frames, w->r.dp_roundoff,
                   w->r.dx_frames, w->r.dx_roundoff);
        } else {
            printf("%s\n", w->note);
        }
    }
    if (made)
        printf("wrote %s, %s, %s/covariance.png\n", csv, gp, o.out);
    else
        printf("wrote %s, %s (no figure: gnuplot is not installed)\n", csv, gp);
    if (gpc && made_c)
        printf("wrote %s, %s/covariance-c.png (against c)\n", gpc, o.out);
    else if (gpc)
        printf("wrote %s (no figure: gnuplot is not installed)\n", gpc);
    free(gpc);
    rc = fflush(stdout) == 0 ? 0 : 1;
    app_validity_warn(stderr, prog);
out:
    free(rows);
    free(csv);
    free(gp);
    return rc;
}
