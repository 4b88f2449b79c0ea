/* gas.c — relcol-gas: run a relativistic gas from a far-from-equilibrium start (every
 * speed equal) to equilibrium and read its temperature theta = kT/(m c^2) two ways, from
 * <gamma> through the Jüttner law and from equipartition <p.v> = d kT; histogram gamma
 * from snapshots at common table times against Jüttner and Maxwell–Boltzmann. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "app.h"
#include "gas_moving.h"
#include "gas_run.h"
#include "gas_stats.h"
#include "gas_summary.h"
#include "gas_thermal.h"
#include "juttner.h"
#include "pressure_blocks.h"

static const char *const prog = GAS_PROG;

enum { EXIT_BAD_INPUT = 2 };
/* Statistics (the blocks: gas_run.h): NCELL equiprobable cells for the chi-square, NHIST
 * bins for the figure. */
enum { NCELL = 20, NHIST = 60 };
/* Memory cap on the stored samples (balls x snapshots doubles, 400 MB). */
#define MAX_SAMPLES 5e7
/* The figure spans gamma - 1 up to where Jüttner's survival falls below this. */
#define HIST_TAIL 2e-4

/* Temperatures theta = kT/(m c^2) the app accepts. Below 1e-3 its readings fail: at 1e-4
 * the two thermometers already disagree by 6 sigma and the histogram's chi2 is 36 times
 * its cells' variance, and at 1e-8 no cell is resolved, while theta is printed to five
 * decimals; above 1e3 the Maxwell-Boltzmann law has no weight where the balls are. */
#define THETA_MIN 1e-3
#define THETA_MAX 1e3

/* per_ball frames (covariant): which state a snapshot reads (--readout; READ_*) */
static const char *const readout_name[] = {"slice", "latest", "now"};

static int parse_readout(const char *val, void *dst, void *opts, char *err)
{
    (void)opts;
    for (int k = 0; k < 3; k++)
        if (strcmp(val, readout_name[k]) == 0) {
            *(int *)dst = k;
            return 0;
        }
    app_errf(err, "'%s' is not slice, latest or now", val);
    return -1;
}

static int parse_boundary(const char *val, void *dst, void *opts, char *err)
{
    (void)opts;
    if (strcmp(val, "walls") && strcmp(val, "periodic")) {
        app_errf(err, "'%s' is not walls or periodic", val);
        return -1;
    }
    *(int *)dst = strcmp(val, "periodic") == 0;
    return 0;
}

/* --c: a speed of light, and finite */
static int valid_c(const app_opt *opt, const void *opts, char *err)
{
    if (app_valid_c(opt, opts, err) != 0)
        return -1;
    if (isinf(((const options *)opts)->c)) {
        app_errf(err, "must be finite (theta = kT/(m c^2) is 0 at c = inf)");
        return -1;
    }
    return 0;
}

/* --theta-start: within the temperatures the app resolves */
static int valid_theta(const app_opt *opt, const void *opts, char *err)
{
    (void)opt;
    const double x = ((const options *)opts)->theta_start;
    char f1[APP_FMT_LEN];
    if (x >= THETA_MIN && x <= THETA_MAX)
        return 0;
    app_errf(err, "%s outside [%g, %g], the temperatures whose gamma histogram and "
             "thermometers the app resolves", app_fmt(x, f1), THETA_MIN, THETA_MAX);
    return -1;
}

static void snapshots_help(FILE *f)
{
    fprintf(f, "snapshots spread evenly over the sample, >= %d (default 100)\n", 2 * NBLOCK);
}

static void frame_help(FILE *f)
{
    fprintf(f,
"contact frame (2-D/3-D; default %s; a warning on stderr names a\n"
"                   frame whose stationary state is not Jüttner, notebook 08):\n",
            gas_default_frame()->name);
    for (size_t i = 0; rc_toi_frames[i]; i++)
        fprintf(f, "                     %-9s %s\n", rc_toi_frames[i]->name,
                rc_toi_frames[i]->summary);
}

#define OFF(field) offsetof(options, field)
#define GIVEN(field) APP_GIVEN(options, field)
static const app_opt opts[] = {
    {"--dim", "D", APP_T_INT, OFF(dim), "2", 1, 3, .help = "1, 2 or 3 (default %D)"},
    {"--n", "N", APP_T_LONG, OFF(n), "1000", 2, 10000000,
     .help = "number of balls (default %D)"},
    {"--c", "C", APP_T_DOUBLE_INF, OFF(c), "1", .valid = valid_c,
     .help = "speed of light, finite (default %D); lengths in ball diameters"},
    {"--theta-start", "T", APP_T_DOUBLE, OFF(theta_start), "0.75", .given = GIVEN(theta_given),
     .valid = valid_theta,
     .help = "start with every speed equal and the energy of Jüttner's <gamma> at\n"
             "theta = T (1-D: of the light species), so the gas settles at T\n"
             "(default %D)"},
    {"--v-rms", "V", APP_T_DOUBLE, OFF(v_start), .given = GIVEN(v_given),
     .valid = app_valid_positive,
     .help = "instead: every starting speed is V (0 < V < c)\n"
             "(theta_start and the theta V settles at: within [1e-3, 1e3])"},
    {"--packing", "P", APP_T_DOUBLE, OFF(packing), .given = GIVEN(packing_given),
     .valid = app_valid_positive,
     .help = "area / volume fraction (default 0.25 in 2-D, 0.2 in 3-D; not 1-D)"},
    {"--t-equil", "T", APP_T_DOUBLE, OFF(t_equil), .given = GIVEN(tequil_given),
     .valid = app_valid_nonneg,
     .help = "table time run before sampling (default 50/c; 1-D 500/c)"},
    {"--t-sample", "T", APP_T_DOUBLE, OFF(t_sample), .given = GIVEN(tsample_given),
     .valid = app_valid_positive,
     .help = "table time sampled after it (default 400/c; 1-D 1000/c, with\n"
             "--observer-velocity 20000/c)"},
    {"--snapshots", "K", APP_T_LONG, OFF(snapshots), "100", 2 * NBLOCK, 100000000,
     .help_more = snapshots_help},
    {"--seed", "S", APP_T_U64, OFF(seed), "1",
     .help = "random seed of positions, species and directions (default %D)"},
    /* (the default, gas_default_frame(), is set by main) */
    {"--frame", "NAME", APP_T_CUSTOM, OFF(frame), .parse = app_opt_toi_frame,
     .given = GIVEN(frame_given), .help_more = frame_help},
    {"--boundary", "B", APP_T_CUSTOM, OFF(periodic), .parse = parse_boundary,
     .given = GIVEN(boundary_given),
     .help = "2-D/3-D: walls (default) or periodic on every axis (periodic in the\n"
             "box frame; the balls start in pairs of opposite momenta, so the\n"
             "total momentum is zero and the gas settles at rest)"},
    {"--observer-velocity", "V", APP_T_DOUBLE, OFF(v_obs), .given = GIVEN(obs_given),
     .help = "1-D, or 2-D with walls: also sample the gas as seen by an\n"
             "observer moving at V along x (|V| < c): every ball's momentum where\n"
             "its worldline crosses the observer's simultaneity hyperplanes (one\n"
             "per snapshot, a second run of the same gas, worldlines rebuilt\n"
             "exactly; 1-D: followed event by event), chi2 against the boosted\n"
             "Jüttner law at theta from <gamma> (1-D: each species'); writes\n"
             "DIR/observer.csv, observer.gp, observer.png"},
    {"--readout", "R", APP_T_CUSTOM, OFF(readout), .parse = parse_readout,
     .given = GIVEN(readout_given),
     .help = "a frame that changes each ball's velocity at its own kink\n"
             "(covariant): what a snapshot at table time t reads -- slice (the\n"
             "default): every ball's state at t on its worldline, read once the\n"
             "engine is a bound W past t, beyond which a collision or a tube\n"
             "conflict's undo cannot move a kink to or from before t\n"
             "(rc_sim_slice_get), held a further W and counted if it changed\n"
             "after the read (stdout, summary.json); latest: each ball's latest\n"
             "segment at t, every change at its contact event's table time\n"
             "(rc_sim_get_ball_latest); now: the state at t of the collisions\n"
             "processed by t (rc_sim_get_ball, which misses those whose contact\n"
             "lies after t but whose kink lies before it)"},
    {"--out", "DIR", APP_T_CUSTOM, OFF(out), "out/gas", .parse = app_opt_dir,
     .help = "output folder, created if missing (default %D)"},
    {"--sensitivity", NULL, APP_T_FLAG, OFF(sensitivity),
     .help = "instead of the outputs (2-D/3-D): the gas run again with its start\n"
             "moved by 1e-15 of a radius and under each other rule its frame offers\n"
             "(group rule; other contracted frames), each theta's and the pressure's\n"
             "shift in units of its error, flagged above 3 errors; sensitivity.csv\n"
             "and sensitivity.json in --out"},
    {NULL},
};

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-gas [--dim 1|2|3] [--n N] [--c C] [--theta-start T | --v-rms V]\n"
"                  [--packing P] [--t-equil T] [--t-sample T] [--snapshots K]\n"
"                  [--seed S] [--frame NAME] [--boundary walls|periodic]\n"
"                  [--observer-velocity V] [--readout slice|latest|now] [--out DIR]\n"
"                  [--sensitivity]\n"
"\n"
"Run a relativistic gas from a far-from-equilibrium start (every speed equal, random\n"
"directions) to equilibrium, and read its temperature theta = kT/(m c^2) two ways:\n"
"  from <gamma>, inverting Jüttner's <gamma>(theta) = K_(d-1)/2(1/theta)/K_(d+1)/2(1/theta)\n"
"    + d theta  (2-D: (1 + 2 theta + 2 theta^2)/(1 + theta));\n"
"  from equipartition, <p.v> = d kT (holds for any law of energy E(p): it presumes\n"
"    nothing about the shape of the distribution).\n"
"Then histogram gamma from snapshots of all balls at common table times and compare it\n"
"with the Jüttner and Maxwell–Boltzmann laws at the equipartition temperature.\n"
"\n"
"gases:\n"
"  --dim 2|3   discs / balls of rest radius 1/2, rest mass 1, in a square / cubic box\n"
"              with elastic walls or periodic: the event-driven engine (relcol/sim.h),\n"
"              elastic collisions, contact geometry --frame (default: uncontracted\n"
"              shapes, the frame whose gas is Jüttner at every density)\n"
"  --dim 1     the exact 1-D point gas (relcol/gas1d.h) on [0, N] with elastic walls, a\n"
"              mixture of rest masses 1 and 2 (one species would never thermalise: equal\n"
"              masses only swap momenta); theta_start and reported theta are per species,\n"
"              kT = m theta is common\n"
"options:\n");
    app_opts_help(f, opts, 19);
    fprintf(f,
"\n"
"error bars: the K snapshots are cut into %d consecutive blocks and each figure is the\n"
"mean of the block means +- their standard error. Blocks are independent when they are\n"
"much longer than the snapshots' correlation time: the app measures that time (the\n"
"integrated autocorrelation time of the per-snapshot <p.v>) and prints it, with a\n"
"warning when a block is shorter than 4 of them. In 2-D and 3-D one species' <gamma> is\n"
"fixed by the conserved energy, so its error bar is round-off (not with --readout slice\n"
"or now); the <p.v> one is not.\n"
"The chi-square per species uses %d cells equiprobable under Jüttner, divided by the\n"
"variance inflation phi measured from the block-to-block scatter of the cell counts.\n"
"\n"
"writes, atomically, DIR/gas.csv (the gamma histogram per species: density +- block\n"
"error, Jüttner and Maxwell–Boltzmann bin averages), DIR/summary.json (every measured\n"
"quantity as {value, err}: theta_gamma, theta_pv, mean_gamma, mean_pv, collision_rate;\n"
"chi2 with dof and p-values; the parameters; top level: species 0, in 1-D the light one;\n"
"\"species\": all), DIR/gas.gp and, if gnuplot is installed, DIR/gas.png (linear and\n"
"log scale).\n"
"exit status: 0 ok; 2 bad input; 1 I/O or engine error.\n",
            NBLOCK, NCELL);
}

#define fail(...) app_fail(prog, EXIT_BAD_INPUT, __VA_ARGS__)

/* The checks between options, after the table's parse, and the defaults that depend on
 * other options: 0, else an exit code. */
static int check_options(void *opts)
{
    options *o = opts;
    char err[APP_ERR_LEN], f1[APP_FMT_LEN];
    if (o->theta_given && o->v_given)
        return fail("--v-rms: conflicts with --theta-start (give one)");
    if (o->v_given && !(o->v_start < o->c))
        return fail("--v-rms: %s must be below c = %s", app_fmt(o->v_start, f1),
                    app_fmt(o->c, err));
    if (o->v_given) {
        /* the temperature that start settles at, within the range --theta-start takes */
        const double b = o->v_start / o->c, g = 1.0 / sqrt((1.0 - b) * (1.0 + b));
        const int d = o->dim;
        if (!(g >= jt_mean_gamma(d, THETA_MIN) && g <= jt_mean_gamma(d, THETA_MAX)))
            return fail("--v-rms: %s gives every ball gamma = %.17g, a gas that settles %s "
                        "theta = %g, outside the temperatures the app resolves (see "
                        "--theta-start)", app_fmt(o->v_start, f1), g,
                        g < jt_mean_gamma(d, THETA_MIN) ? "below" : "above",
                        g < jt_mean_gamma(d, THETA_MIN) ? THETA_MIN : THETA_MAX);
    }
    if (o->obs_given && o->dim == 3)
        return fail("--observer-velocity: 1-D and 2-D only");
    if (o->obs_given && o->boundary_given && o->periodic)
        return fail("--observer-velocity: needs walls (a hyperplane cuts a walled box's "
                    "world-tube once per ball)");
    if (o->obs_given && !(fabs(o->v_obs) < o->c))
        return fail("--observer-velocity: %s must be below c = %s in size",
                    app_fmt(o->v_obs, f1), app_fmt(o->c, err));
    if (o->dim == 1 && o->packing_given)
        return fail("--packing: not used with --dim 1 (point particles at unit density)");
    if (o->dim == 1 && o->frame_given)
        return fail("--frame: not used with --dim 1 (point particles have no shape)");
    if (o->readout_given && (o->dim == 1 || !o->frame->per_ball))
        return fail("--readout: only with a frame that changes each ball's velocity at its "
                    "own kink (covariant); in every other the three read-outs are one");
    if (o->dim == 1 && o->boundary_given)
        return fail("--boundary: not used with --dim 1 (the 1-D gas has walls)");
    const double pmax = o->dim == 3 ? 0.52 : 0.78; /* rc_sim_gas_init's lattice start */
    if (!o->packing_given)
        o->packing = o->dim == 3 ? 0.2 : 0.25;
    else if (o->dim >= 2 && !(o->packing < pmax))
        return fail("--packing: %s must be below %g in %d-D (lattice start)",
                    app_fmt(o->packing, f1), pmax, o->dim);
    if (!o->tequil_given)
        o->t_equil = (o->dim == 1 ? 500.0 : 50.0) / o->c;
    /* a 1-D hyperplane's energy carries the gas's slow collective modes (correlated over
     * a few hundred time units, the walls' sound crossing), so its observer needs blocks of
     * hyperplanes far apart */
    if (!o->tsample_given)
        o->t_sample = (o->dim == 1 ? (o->obs_given ? 20000.0 : 1000.0) : 400.0) / o->c;
    if ((double)o->n * (double)o->snapshots > MAX_SAMPLES)
        return fail("--snapshots: n x snapshots = %.3g exceeds %.3g stored samples",
                    (double)o->n * (double)o->snapshots, MAX_SAMPLES);
    if (o->dim == 1 && o->sensitivity)
        return fail("--sensitivity: 2-D and 3-D gases only (the 1-D gas has no rules to vary)");
    if (o->dim >= 2) /* a valid run in a frame that is not thermal: said before it starts */
        gas_frame_warn(stderr, prog, o->frame, o->dim, o->packing);
    return 0;
}

static const app_cli cli = {.prog = prog, .tab = opts, .usage = usage,
                            .stray_hint = "see --help",
                            .bad = EXIT_BAD_INPUT, .check = check_options};

/* ---- statistics ------------------------------------------------------------------- */

typedef struct species_stats {
    double mass;
    size_t count;                          /* balls of this species */
    double th_g, se_g, th_pv, se_pv, se_diff;
    double mg, se_mg, mpv, se_mpv;         /* <gamma>, <p.v>/(m c^2) */
    double chi2_j, chi2_mb, phi, dof;
    double hist_lo[NHIST + 1];             /* bin edges in gamma */
    double dens[NHIST], dens_se[NHIST], pj[NHIST], pmb[NHIST];
} species_stats;

static void gamma_edges_equiprobable(int d, double theta, double *edge,
                                     gsl_integration_workspace *ws)
{
    edge[0] = 1.0;
    edge[NCELL] = INFINITY;
    for (int c = 1; c < NCELL; c++)
        edge[c] = jt_quantile_upper(d, theta, 1.0 - (double)c / NCELL, ws);
}

/* Thermometers, chi-squares and histogram of species q. */
static void analyse(int d, const samples *S, int q, species_stats *ss, double *tau,
                    gsl_integration_workspace *ws)
{
    const size_t n = S->n, ns = S->ns, per = ns / NBLOCK;
    double bg[NBLOCK], bpv[NBLOCK], bd[NBLOCK], bmg[NBLOCK], bmpv[NBLOCK];
    double *series = malloc(ns * sizeof *series);
    ss->count = 0;
    for (size_t i = 0; i < n; i++)
        ss->count += S->spec[i] == q;
    for (int k = 0; k < NBLOCK; k++) {
        double sg = 0.0, spv = 0.0, cnt = 0.0;
        for (size_t j = (size_t)k * per; j < (size_t)(k + 1) * per; j++) {
            double sj = 0.0;
            for (size_t i = 0; i < n; i++) {
                if (S->spec[i] != q)
                    continue;
                const double u = S->u[j * n + i], g = sqrt(1.0 + u);
                sg += g;
                sj += u / g; /* p.v / (m c^2) = (gamma^2 - 1)/gamma */
                cnt += 1.0;
            }
            spv += sj;
            if (series)
                series[j] = sj;
        }
        bg[k] = jt_theta_from_gamma(d, sg / cnt);
        bpv[k] = spv / cnt / d;
        bmg[k] = sg / cnt;
        bmpv[k] = spv / cnt;
        bd[k] = bpv[k] - bg[k];
    }
    *tau = series ? gs_tau_int(series, per * NBLOCK) : NAN;
    free(series);
    ss->th_g = gs_mean_se(bg, NBLOCK, &ss->se_g);
    ss->th_pv = gs_mean_se(bpv, NBLOCK, &ss->se_pv);
    gs_mean_se(bd, NBLOCK, &ss->se_diff);
    ss->mg = gs_mean_se(bmg, NBLOCK, &ss->se_mg);
    ss->mpv = gs_mean_se(bmpv, NBLOCK, &ss->se_mpv);

    /* chi-square in NCELL cells equiprobable under Jüttner at the <p.v> theta */
    const double th = ss->th_pv;
    double edge[NCELL + 1], pj[NCELL], pmb[NCELL];
    gamma_edges_equiprobable(d, th, edge, ws);
    for (int c = 0; c < NCELL; c++) {
        const double hi_j = c == NCELL - 1 ? 0.0 : jt_sf(d, th, edge[c + 1], ws);
        const double hi_mb = c == NCELL - 1 ? 0.0 : mb_sf(d, th, edge[c + 1]);
        pj[c] = jt_sf(d, th, edge[c], ws) - hi_j;
        pmb[c] = mb_sf(d, th, edge[c]) - hi_mb;
    }
    /* figure bins: uniform in gamma - 1 up to Jüttner's HIST_TAIL quantile */
    const double gmax = jt_quantile_upper(d, th, HIST_TAIL, ws);
    for (int h = 0; h <= NHIST; h++)
        ss->hist_lo[h] = 1.0 + (gmax - 1.0) * h / NHIST;
    double cc[NBLOCK][NCELL], hc[NBLOCK][NHIST];
    memset(cc, 0, sizeof cc);
    memset(hc, 0, sizeof hc);
    double nsamp = 0.0;
    for (int k = 0; k < NBLOCK; k++)
        for (size_t j = (size_t)k * per; j < (size_t)(k + 1) * per; j++)
            for (size_t i = 0; i < n; i++) {
                if (S->spec[i] != q)
                    continue;
                const double u = S->u[j * n + i], g = sqrt(1.0 + u);
                cc[k][gs_find_cell(edge, NCELL, g)] += 1.0;
                const double gm1 = u / (g + 1.0);
                const int h = (int)floor(gm1 / (gmax - 1.0) * NHIST);
                if (h >= 0 && h < NHIST)
                    hc[k][h] += 1.0;
                nsamp += 1.0;
            }
    const double nb = nsamp / NBLOCK;
    ss->phi = gs_chi2_two_models(&cc[0][0], NBLOCK, NCELL, nsamp, pj, pmb, &ss->chi2_j,
                                 &ss->chi2_mb);
    ss->dof = NCELL - 2; /* total fixed, theta fitted */
    for (int h = 0; h < NHIST; h++) {
        const double w = ss->hist_lo[h + 1] - ss->hist_lo[h];
        double bd2[NBLOCK];
        for (int k = 0; k < NBLOCK; k++)
            bd2[k] = hc[k][h] / nb / w;
        ss->dens[h] = gs_mean_se(bd2, NBLOCK, &ss->dens_se[h]);
        /* model bin averages (exact for every d, also where the 1-D density diverges) */
        ss->pj[h] = (jt_sf(d, th, ss->hist_lo[h], ws) - jt_sf(d, th, ss->hist_lo[h + 1], ws)) / w;
        ss->pmb[h] = (mb_sf(d, th, ss->hist_lo[h]) - mb_sf(d, th, ss->hist_lo[h + 1])) / w;
    }
}

/* Pair collisions per unit table time over the sample: the mean of the NBLOCK blocks'
 * rates +- their standard error. */
static void collision_rate(const samples *S, double t_sample, double *rate, double *se)
{
    const size_t per = S->ns / NBLOCK;
    const double tb = t_sample * (double)per / (double)S->ns;
    double b[NBLOCK];
    for (int k = 0; k < NBLOCK; k++)
        b[k] = (double)(S->coll[(size_t)(k + 1) * per] - S->coll[(size_t)k * per]) / tb;
    *rate = gs_mean_se(b, NBLOCK, se);
}

/* ---- output ----------------------------------------------------------------------- */

/* What summary.json says: the options, the run's counts, every species' measurements. */
static void fill_summary(const options *o, const samples *S, int nspec,
                         const species_stats *ss, const double *tau, double rate,
                         double rate_se, gas_summary *g)
{
    memset(g, 0, sizeof *g);
    g->prog = prog;
    g->dim = o->dim;
    g->n = o->n;
    g->c = o->c;
    g->theta_start = o->v_given ? NAN : o->theta_start;
    g->v_rms = o->v_given ? o->v_start : NAN;
    g->packing = o->dim == 1 ? NAN : o->packing;
    g->t_equil = o->t_equil;
    g->t_sample = o->t_sample;
    g->snapshots = (long)S->ns;
    g->blocks = NBLOCK;
    g->seed = o->seed;
    g->frame = o->dim == 1 ? NULL : o->frame->name;
    g->readout = o->dim >= 2 && o->frame->per_ball ? readout_name[o->readout] : NULL;
    g->thermal = o->dim == 1 ? -1 : gas_frame_thermal(o->frame, o->dim);
    g->boundary = o->periodic ? "periodic" : "walls";
    g->gamma_start = S->gamma0;
    g->theta_energy = S->theta_energy;
    g->box = S->box;
    g->collisions = S->events;
    g->overlaps = S->overlaps;
    g->slices_read = S->slices_read;
    g->slices_late = S->slices_late;
    g->mass_drift = S->mass_drift;
    g->energy_drift = S->energy_drift;
    g->rate = rate;
    g->rate_err = rate_se;
    g->nspec = nspec;
    for (int q = 0; q < nspec; q++) {
        const species_stats *s = &ss[q];
        gas_summary_species *p = &g->sp[q];
        p->mass = s->mass;
        p->count = s->count;
        p->theta_gamma = s->th_g;
        p->theta_gamma_err = s->se_g;
        p->theta_pv = s->th_pv;
        p->theta_pv_err = s->se_pv;
        p->theta_diff_err = s->se_diff;
        p->mean_gamma = s->mg;
        p->mean_gamma_err = s->se_mg;
        p->mean_pv = s->mpv;
        p->mean_pv_err = s->se_mpv;
        p->theta_micro = o->dim == 2 && s->count <= 1000000
                             ? jt_theta_micro_2d((double)s->count, S->gamma0)
                             : NAN;
        p->cells = NCELL;
        p->dof = s->dof;
        p->phi = s->phi;
        p->chi2_juttner = s->chi2_j / s->phi;
        p->chi2_mb = s->chi2_mb / s->phi;
        p->tau = tau[q];
    }
}

static int write_csv(const char *path, int nspec, const species_stats *ss, char *err)
{
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0)
        return -1;
    fprintf(a.f, "species,mass,gamma_lo,gamma_hi,gamma_mid,density,density_err,juttner,"
                 "maxwell_boltzmann\n");
    for (int q = 0; q < nspec; q++)
        for (int h = 0; h < NHIST; h++)
            fprintf(a.f, "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", q,
                    ss[q].mass, ss[q].hist_lo[h], ss[q].hist_lo[h + 1],
                    0.5 * (ss[q].hist_lo[h] + ss[q].hist_lo[h + 1]), ss[q].dens[h],
                    ss[q].dens_se[h], ss[q].pj[h], ss[q].pmb[h]);
    return app_atomic_commit(&a, err);
}

static int write_script(const char *path, const options *o, int nspec,
                        const species_stats *ss, char *err)
{
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0)
        return -1;
    FILE *f = a.f;
    char fc[APP_FMT_LEN];
    fprintf(f,
"# gas.gp — written by relcol-gas; run `gnuplot gas.gp` in this folder.\n"
"# Histogram of gamma (density per unit gamma, from snapshots at common table times,\n"
"# error bars from independent blocks) against the Jüttner and Maxwell–Boltzmann laws at\n"
"# the equipartition temperature; left linear, right logarithmic.\n");
    app_gnuplot_head(f, "gas.png", "size 1400,620 enhanced font 'Sans,12' linewidth 1.4", 0);
    char sub[256];
    if (o->dim == 1)
        snprintf(sub, sizeof sub, "1-D mixture, m = 1 and 2, N = %ld, c = %s; θ_{⟨p·v⟩} = "
                 "%.4f (m = 1), %.4f (m = 2)", o->n, app_fmt(o->c, fc), ss[0].th_pv,
                 ss[1].th_pv);
    else
        snprintf(sub, sizeof sub, "%d-D, N = %ld, packing %g, c = %s, frame %s; "
                 "θ_{⟨p·v⟩} = %.4f, θ_{⟨γ⟩} = %.4f", o->dim, o->n, o->packing,
                 app_fmt(o->c, fc), o->frame->name, ss[0].th_pv, ss[0].th_g);
    fprintf(f,
"set multiplot layout 1,2 title \"Relativistic gas: γ histogram against Jüttner and "
"Maxwell–Boltzmann\\n{/*0.8 %s}\"\n"
"set xlabel 'γ'\n"
"set ylabel 'probability density per unit γ'\n"
"set grid lc rgb '#dddddd'\n"
"set key top right box opaque\n",
            sub);
    double ymin = INFINITY;
    for (int q = 0; q < nspec; q++)
        ymin = fmin(ymin, ss[q].pj[NHIST - 1]);
    static const char *const col[MAXSPEC][3] = {{"#1f77b4", "#d62728", "#2ca02c"},
                                                {"#9467bd", "#ff7f0e", "#17becf"}};
    for (int panel = 0; panel < 2; panel++) {
        if (panel == 0)
            fprintf(f, "set yrange [0:*]\n");
        else /* down to a tenth of Jüttner's last bin: Maxwell–Boltzmann's tail is far lower */
            fprintf(f, "set logscale y\nset format y '10^{%%T}'\nset yrange [%.3g:*]\n"
                       "set key bottom left box opaque\n", 0.1 * ymin);
        fprintf(f, "plot ");
        for (int q = 0; q < nspec; q++) {
            char lab[32] = "";
            if (nspec > 1)
                snprintf(lab, sizeof lab, " m = %g", ss[q].mass);
            fprintf(f,
"%s'gas.csv' skip 1 using ($1 == %d && $6 > 0 ? $5 : 1/0):6:7 with yerrorbars pt 7 ps 0.5 "
"lc rgb '%s' title 'simulation%s', \\\n"
"     '' skip 1 using ($1 == %d ? $5 : 1/0):8 with lines lw 2 lc rgb '%s' "
"title 'Jüttner%s', \\\n"
"     '' skip 1 using ($1 == %d ? $5 : 1/0):9 with lines lw 2 dt 2 lc rgb '%s' "
"title 'Maxwell–Boltzmann%s'%s\n",
                    q == 0 ? "" : "     ", q, col[q][0], lab, q, col[q][1], lab, q, col[q][2],
                    lab, q + 1 < nspec ? ", \\" : "");
        }
    }
    fprintf(f, "unset multiplot\n");
    return app_atomic_commit(&a, err);
}

/* --sensitivity: the gas of *ctx (options) under variant v; observables theta from
 * <gamma>, theta from <p.v>, their difference and the pressure, with their block errors */
static int sens_run(void *ctx, const app_sens_variant *v, double *x, double *se, char *err)
{
    options o = *(const options *)ctx;
    o.frame = v->frame;
    o.groups = v->groups;
    o.sens_move = v->move;
    samples S;
    memset(&S, 0, sizeof S);
    S.n = (size_t)o.n;
    S.ns = (size_t)o.snapshots / NBLOCK * NBLOCK;
    S.gamma0 = gas_start_gamma(&o);
    S.theta_energy = NAN;
    S.spec = malloc(S.n);
    S.u = malloc(S.n * S.ns * sizeof *S.u);
    S.coll = calloc(S.ns + 1, sizeof *S.coll);
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
    int r = -1;
    if (!S.spec || !S.u || !S.coll || !ws)
        app_errf(err, "out of memory");
    else if (gas_run_sim(&o, &S, err) == 0) {
        species_stats ss;
        double tau;
        ss.mass = 1.0;
        analyse(o.dim, &S, 0, &ss, &tau, ws);
        x[0] = ss.th_g;
        se[0] = ss.se_g;
        x[1] = ss.th_pv;
        se[1] = ss.se_pv;
        x[2] = ss.th_pv - ss.th_g;
        se[2] = ss.se_diff;
        x[3] = pb_result(&S.pres, &se[3]);
        r = 0;
    }
    gsl_integration_workspace_free(ws);
    free(S.spec);
    free(S.u);
    free(S.coll);
    return r;
}

int main(int argc, char **argv)
{
    options o;
    memset(&o, 0, sizeof o);
    o.frame = gas_default_frame();
    int st = app_start(&cli, argc, argv, &o);
    if (st >= 0)
        return st;
    static const char *const sens_names[4] = {"theta_gamma", "theta_pv",
                                              "theta_pv_minus_gamma", "pressure"};
    if (o.sensitivity)
        return app_sensitivity_main(prog, o.out, o.frame, o.groups, o.c, o.dim, 4, sens_names,
                                    sens_run, &o);

    char err[APP_ERR_LEN];
    int rc = 1;
    samples S;
    memset(&S, 0, sizeof S);
    S.n = (size_t)o.n;
    S.ns = (size_t)o.snapshots / NBLOCK * NBLOCK; /* whole blocks */
    S.gamma0 = gas_start_gamma(&o);
    S.theta_energy = NAN;
    S.spec = malloc(S.n);
    S.u = malloc(S.n * S.ns * sizeof *S.u);
    S.coll = calloc(S.ns + 1, sizeof *S.coll);
    species_stats ss[MAXSPEC];
    double tau[MAXSPEC];
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
    char *csv = app_path_join(o.out, "gas.csv"), *gp = app_path_join(o.out, "gas.gp");
    char *js = app_path_join(o.out, "summary.json");
    if (!S.spec || !S.u || !S.coll || !ws || !csv || !gp || !js) {
        fprintf(stderr, "%s: out of memory\n", prog);
        goto out;
    }
    if (app_mkdir_p(o.out, err) != 0) {
        fail("--out: %s", err);
        rc = EXIT_BAD_INPUT;
        goto out;
    }
    if ((o.dim == 1 ? gas_run_1d(&o, &S, err) : gas_run_sim(&o, &S, err)) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        rc = strncmp(err, "--", 2) == 0 ? EXIT_BAD_INPUT : 1;
        goto out;
    }
    const int nspec = o.dim == 1 ? 2 : 1;
    for (int q = 0; q < nspec; q++) {
        ss[q].mass = o.dim == 1 ? gas_mix_mass[q] : 1.0;
        analyse(o.dim, &S, q, &ss[q], &tau[q], ws);
    }
    gas_moving_result mv;
    memset(&mv, 0, sizeof mv);
    if (o.obs_given && o.dim == 1) {
        /* a second run of the same gas, followed event by event */
        rc_gas1d *g2 = NULL;
        double e0;
        int r2 = gas_1d_start(&o, &S, &g2, &e0, err);
        if (r2 == 0 && rc_gas1d_advance(g2, o.t_equil, 0) != RC_OK) {
            app_errf(err, "1-D gas: cannot reach t = %g", o.t_equil);
            r2 = -1;
        }
        /* each species' theta from <gamma>, as in 2-D: one run's species share their
         * energy slowly (a wander of ~1 % over the run), which the gas's common kT of
         * its energy would count against the boosted law */
        const double th[MAXSPEC] = {ss[0].th_g, ss[1].th_g};
        if (r2 == 0)
            r2 = gas_moving_run_1d(prog, g2, S.n, S.spec, gas_mix_mass, th, o.c, o.v_obs,
                                   o.t_equil, o.t_sample / (double)S.ns, (long)S.ns, S.box,
                                   o.out, &mv, err);
        rc_gas1d_free(&g2);
        if (r2 != 0) {
            fprintf(stderr, "%s: %s\n", prog, err);
            goto out;
        }
    } else if (o.obs_given) {
        rc_sim *s2 = NULL;
        int r2 = gas_sim_start(&o, &S, &s2, err);
        if (r2 == 0 && rc_sim_advance(s2, o.t_equil, 0) != RC_OK) {
            app_errf(err, "engine: cannot reach t = %g", o.t_equil);
            r2 = -1;
        }
        const rc_vec3 box = rc_v3(S.box, S.box, S.box);
        if (r2 == 0)
            r2 = gas_moving_run(prog, s2, S.n, o.c, o.v_obs, ss[0].th_g, o.t_equil,
                                o.t_sample / (double)S.ns, (long)S.ns, box, o.out, &mv, err);
        rc_sim_free(&s2);
        if (r2 != 0) {
            fprintf(stderr, "%s: %s\n", prog, err);
            goto out;
        }
    }
    double rate, rate_se;
    collision_rate(&S, o.t_sample, &rate, &rate_se);
    gas_summary sum;
    fill_summary(&o, &S, nspec, ss, tau, rate, rate_se, &sum);
    sum.pressure = sum.pressure_err = NAN;
    sum.pressure_kind = NULL;
    if (o.dim != 1) {
        sum.pressure = pb_result(&S.pres, &sum.pressure_err);
        sum.pressure_kind = o.periodic ? "momentum flux (papers/pressure.md)"
                                       : "the walls' momentum flux";
    }
    if (o.obs_given) {
        sum.observer = 1;
        sum.obs_v = mv.v;
        sum.obs_sampled = mv.sampled;
        sum.obs_lost = mv.lost;
        sum.obs_chi2 = mv.chi2;
        sum.obs_chi2_rest = mv.chi2_rest;
        sum.obs_phi = mv.phi;
        sum.obs_dof = mv.dof;
        sum.obs_nspec = mv.nspec;
        sum.obs_tau = mv.tau;
        for (int q = 0; q < mv.nspec; q++) {
            sum.obs_sp[q].mass = mv.sp_mass[q];
            sum.obs_sp[q].theta = mv.sp_theta[q];
            sum.obs_sp[q].chi2 = mv.sp_chi2[q];
            sum.obs_sp[q].chi2_rest = mv.sp_chi2_rest[q];
            sum.obs_sp[q].phi = mv.sp_phi[q];
            sum.obs_sp[q].dof = mv.sp_dof[q];
        }
    }
    if (write_csv(csv, nspec, ss, err) != 0 || write_script(gp, &o, nspec, ss, err) != 0 ||
        gas_summary_write(js, &sum, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto out;
    }
    int made = 0;
    if (app_gnuplot_run(prog, o.out, "gas.gp", "gas.png", &made, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto out;
    }

    char f1[APP_FMT_LEN];
    const double dsnap = o.t_sample / (double)S.ns;
    if (o.dim == 1)
        printf("%s: 1-D mixture (m = 1, 2), N = %ld on [0, %ld], c = %s; start: every "
               "gamma = %.6g\n", prog, o.n, o.n, app_fmt(o.c, f1), S.gamma0);
    else
        printf("%s: %d-D, N = %ld, packing %g (box %.4g%s), c = %s, frame %s; start: every "
               "gamma = %.6g\n", prog, o.dim, o.n, o.packing, S.box,
               o.periodic ? ", periodic" : "", app_fmt(o.c, f1), o.frame->name, S.gamma0);
    printf("equilibration to t = %g, then %zu snapshots every %g (%d blocks of %zu); "
           "%llu collisions%s",
           o.t_equil, S.ns, dsnap, NBLOCK, S.ns / NBLOCK, (unsigned long long)S.events,
           o.dim == 1 ? "\n" : "");
    if (o.dim != 1)
        printf(", %llu overlaps (shape change)\n", (unsigned long long)S.overlaps);
    if (o.dim != 1 && S.have_end && !app_validity_warn(stderr, prog)) /* (one line) */
        app_rules_warn(stderr, prog, &S.end, NULL);
    if (S.slices_read > 0) {
        printf("slices: %llu read final, %llu changed after the read (each held a further "
               "W after it)\n", (unsigned long long)S.slices_read,
               (unsigned long long)S.slices_late);
        if (S.slices_late > 0)
            fprintf(stderr, "%s: warning: %llu of the %llu slices changed after they were "
                            "read (an undo reached back further than W, relcol/sim.h): those "
                            "snapshots are off\n", prog, (unsigned long long)S.slices_late,
                    (unsigned long long)S.slices_read);
    }
    if (o.dim == 1)
        printf("kT of the gas's energy (canonical, both species; the light mass's theta) = "
               "%.5f\n", S.theta_energy);
    printf("conservation: max rest-mass drift %.2g (relative), energy drift %.2g\n",
           S.mass_drift, S.energy_drift);
    double p_se, p_mean = o.dim != 1 ? pb_result(&S.pres, &p_se) : NAN;
    if (o.dim != 1)
        printf("pressure P = %.6g +- %.2g (%s)\n", p_mean, p_se,
               o.periodic ? "momentum flux, papers/pressure.md" : "the walls' momentum flux");
    printf("collision rate over the sample: %.6g +- %.2g per unit time (%.5g per ball)\n",
           rate, rate_se, 2.0 * rate / (double)o.n);
    for (int q = 0; q < nspec; q++) {
        const species_stats *s = &ss[q];
        if (nspec > 1)
            printf("species m = %g (%zu particles): kT = m theta\n", s->mass, s->count);
        /* (a per_ball frame's slice or read at now takes each ball at one table time, not
         * across the hyperplanes collisions exchange energy on: its sum is not conserved) */
        const int conserved = o.dim != 1 && (!o.frame->per_ball || o.readout == READ_LATEST);
        printf("theta from <gamma>  (Jüttner)       = %.5f +- %.5f%s\n", s->th_g, s->se_g,
               conserved      ? "  (fixed by the conserved energy)"
               : o.dim != 1   ? "  (not fixed: a table-time read-out, see --readout)"
                              : "");
        printf("theta from <p.v>/%d (equipartition) = %.5f +- %.5f\n", o.dim, s->th_pv,
               s->se_pv);
        /* (no spread between the blocks: no significance to state, rather than +-inf) */
        char sig[64];
        if (s->se_diff > 0.0)
            snprintf(sig, sizeof sig, "%.1f sigma", (s->th_pv - s->th_g) / s->se_diff);
        else
            snprintf(sig, sizeof sig, "sigma n/a: the blocks do not differ");
        printf("difference <p.v> - <gamma>          = %+.5f +- %.5f (%s)\n",
               s->th_pv - s->th_g, s->se_diff, sig);
        if (o.dim == 2 && s->count <= 1000000) { /* an O(N) sum of log-gammas */
            printf("theta microcanonical (exact for uncontracted discs at this energy) = %.5f\n",
                   jt_theta_micro_2d((double)s->count, S.gamma0));
        }
        /* a law that puts (numerically) no weight in a cell the balls fill has no finite
         * chi2: said in words, not as inf or nan */
        char cj[64], cm[64];
        const double xj = s->chi2_j / s->phi, xm = s->chi2_mb / s->phi;
        snprintf(cj, sizeof cj, isfinite(xj) ? "%.1f" : "n/a (no weight where the balls are)", xj);
        snprintf(cm, sizeof cm, isfinite(xm) ? "%.4g" : "n/a (no weight where the balls are)", xm);
        char pj[32] = "", pm[32] = "";
        if (isfinite(xj))
            snprintf(pj, sizeof pj, " (p = %.2g)", gs_chi2_p(xj, s->dof));
        if (isfinite(xm))
            snprintf(pm, sizeof pm, " (p = %.2g)", gs_chi2_p(xm, s->dof));
        printf("chi2/phi of the gamma histogram (%d cells, dof %g, phi %.2f): Jüttner %s%s, "
               "Maxwell–Boltzmann %s%s; 5 sigma bound (p = 2.9e-7) %.1f\n",
               NCELL, s->dof, s->phi, cj, pj, cm, pm, gs_chi2_sigma_bound(s->dof, 5.0));
        printf("block check: <p.v> snapshot correlation time %.2f snapshots, blocks of %zu\n",
               tau[q], S.ns / NBLOCK);
        if ((double)(S.ns / NBLOCK) < 4.0 * tau[q])
            fprintf(stderr, "%s: warning: blocks are shorter than 4 correlation times: error "
                            "bars may be understated (raise --t-sample)\n", prog);
    }
    if (o.obs_given && o.dim == 1) {
        printf("observer at %g c along x: %llu particles sampled on %zu hyperplanes, %llu "
               "lost (worldlines followed event by event)\n", mv.v,
               (unsigned long long)mv.sampled, S.ns, (unsigned long long)mv.lost);
        for (int q = 0; q < mv.nspec; q++)
            printf("species m = %g: chi2/phi of its momenta (%d cells, dof %g, phi %.2f) "
                   "against the boosted Jüttner law at theta = %.5f: %.1f (p = %.2g); "
                   "Jüttner at rest %.4g\n", mv.sp_mass[q], (int)mv.sp_dof[q] + 1,
                   mv.sp_dof[q], mv.sp_phi[q], mv.sp_theta[q], mv.sp_chi2[q],
                   gs_chi2_p(mv.sp_chi2[q], mv.sp_dof[q]), mv.sp_chi2_rest[q]);
        printf("both species (dof %g): boosted Jüttner %.1f (p = %.2g), Jüttner at rest "
               "%.4g; 5 sigma bound %.1f\n", mv.dof, mv.chi2, gs_chi2_p(mv.chi2, mv.dof),
               mv.chi2_rest, gs_chi2_sigma_bound(mv.dof, 5.0));
        printf("block check: energy on a hyperplane, correlation time %.2f hyperplanes, "
               "blocks of %zu\n", mv.tau, S.ns / NBLOCK);
        if ((double)(S.ns / NBLOCK) < 4.0 * mv.tau)
            fprintf(stderr, "%s: warning: the observer's blocks are shorter than 4 "
                            "correlation times: its phi is understated and its chi2 "
                            "overstated (raise --t-sample)\n", prog);
    } else if (o.obs_given) {
        printf("observer at %g c along x: %llu balls sampled on %zu hyperplanes, %llu lost "
               "(two collisions in one step of %.3g)\n", mv.v, (unsigned long long)mv.sampled,
               S.ns, (unsigned long long)mv.lost, mv.step);
        printf("chi2/phi of its momenta (%d cells, dof %g, phi %.2f): boosted Jüttner %.1f "
               "(p = %.2g), Jüttner at rest %.4g; 5 sigma bound %.1f\n", (int)mv.dof + 1, mv.dof, mv.phi,
               mv.chi2, gs_chi2_p(mv.chi2, mv.dof), mv.chi2_rest,
               gs_chi2_sigma_bound(mv.dof, 5.0));
    }
    if (o.obs_given) {
        if (mv.made_png)
            printf("wrote %s/observer.csv, %s/observer.gp, %s/observer.png\n", o.out, o.out,
                   o.out);
        else
            printf("wrote %s/observer.csv, %s/observer.gp\n", o.out, o.out);
    }
    if (made)
        printf("wrote %s, %s, %s, %s/gas.png\n", csv, gp, js, o.out);
    else
        printf("wrote %s, %s, %s\n", csv, gp, js);
    rc = fflush(stdout) == 0 ? 0 : 1;
out:
    free(S.spec);
    free(S.u);
    free(csv);
    free(gp);
    free(js);
    free(S.coll);
    gsl_integration_workspace_free(ws);
    return rc;
}
