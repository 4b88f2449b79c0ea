/* sim.c — relcol-sim: runs a scenario with the event-driven engine and writes what the
 * scenario asks for: CSV snapshots, an extended-XYZ trajectory (OVITO, ASE) and an H5MD one, a
 * summary, the final state as a scenario (continuing from it is bit-identical to not
 * stopping), trajectory and animation figures through gnuplot. Ctrl-C writes the restart
 * state and exits cleanly. Every file is written atomically (temporary name, rename).
 * Exit status: 0 done, 2 bad scenario or option, 1 run or I/O failure, 130 interrupted. */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "app.h"
#include "scenario.h"
#include "clock.h"
#include "simout.h"

static const char *const prog = "relcol-sim";
static volatile sig_atomic_t interrupted;

static void on_sigint(int sig)
{
    (void)sig;
    interrupted = 1;
}

typedef struct options {
    const char *file, *builtin, *out_dir, *frame;
    double t_end;
    int t_end_given, no_plots, dump, sens;
} options;

#define OFF(field) offsetof(options, field)
static const app_opt opts[] = {
    {"--builtin", "NAME", APP_T_STRING, OFF(builtin),
     .help = "rack: a billiard break (15 balls in a triangle and a cue ball);\n"
             "gas: 400 discs at packing 0.2, rms speed 0.5 c, c = 1"},
    {"--out", "DIR", APP_T_STRING, OFF(out_dir),
     .help = "output folder (overrides outputs.dir)"},
    {"--t-end", "T", APP_T_DOUBLE, OFF(t_end), .given = APP_GIVEN(options, t_end_given),
     .help = "run until T (overrides t_end)"},
    /* (checked once the scenario is read: its errors come first) */
    {"--frame", "NAME", APP_T_STRING, OFF(frame),
     .help = "contact frame (overrides contact_frame; listed below)"},
    {"--no-plots", NULL, APP_T_FLAG, OFF(no_plots), .help = "write data only, no gnuplot figures"},
    {"--dump", NULL, APP_T_FLAG, OFF(dump),
     .help = "print the scenario as relcol reads it (JSON) and exit"},
    {"--sensitivity", NULL, APP_T_FLAG, OFF(sens),
     .help = "instead of the outputs: the scenario run again with its positions moved\n"
             "by 1e-15 of a radius and under each other rule its frame offers (group\n"
             "rule; other contracted frames), each final momentum (8 balls at most)\n"
             "and total's shift in units of its error, flagged above 3 errors;\n"
             "sensitivity.csv and sensitivity.json in the output folder"},
    {NULL},
};

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-sim SCENARIO.json | --builtin rack|gas  [--out DIR] [--t-end T]\n"
"                  [--frame NAME] [--no-plots] [--dump] [--sensitivity]\n"
"\n"
"Run an event-driven simulation of hard balls at any c. The scenario format is\n"
"SCENARIO.md (installed as share/relcol/SCENARIO.md, in the source apps/sim/); the\n"
"scenarios in share/relcol/scenarios/ are examples, --builtin NAME runs one of them.\n"
"\n");
    app_opts_help(f, opts, 18);
    fprintf(f,
"\n"
"Writes into the output folder: snapshots/snap-NNNN.csv at the scenario's snapshot times,\n"
"trajectory.xyz (extended XYZ, when outputs.xyz_every > 0), trajectory.h5 (H5MD, when\n"
"outputs.h5md_every > 0), summary.txt, summary.json (the same for programs), final.json\n"
"(the final state as a scenario) and final.ckpt (the engine's whole state, which\n"
"final.json names): `relcol-sim DIR/final.json` continues the run, writing into DIR.1,\n"
"then DIR.2, ... (the run it continues keeps its files),\n"
"and with gnuplot trajectories.png and, for 2-D runs, table.gif. A progress bar shows on\n"
"a terminal. Ctrl-C stops at the next event batch, writes final.json and the files so far.\n"
"\n"
"Exact: the run's trajectory, every bit, does not depend on the outputs written nor on\n"
"where it was stopped and continued (at its end or by Ctrl-C); a continued run's frames\n"
"lie on the uninterrupted run's time grid.\n"
"\n"
"exit status: 0 done; 2 bad scenario or option (one line naming the JSON path and the\n"
"reason); 1 run or I/O failure; 3 simulated time stands still (the balls and the time\n"
"named, the state written); 130 interrupted (restart state written).\n");
    fprintf(f, "\nSimultaneous contacts (scenario key \"groups\"; found in the table frame):\n");
    for (int r = 0; rc_group_rule_name(r); r++)
        fprintf(f, "  %-13s %s\n", rc_group_rule_name(r), rc_group_rule_summary(r));
    fprintf(f, "\nContact frames (scenario key \"contact_frame\", option --frame):\n");
    for (size_t i = 0; rc_toi_frames[i]; i++)
        fprintf(f, "  %-13s %s\n", rc_toi_frames[i]->name, rc_toi_frames[i]->summary);
}

/* "relcol-sim: message" on stderr, returning the exit status code */
#define fail(code, ...) app_fail(prog, (code), __VA_ARGS__)

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* --sensitivity: the scenario run to t_end under variant v; observables: each ball's final
 * momentum (up to 8 balls), the rms momentum, the collisions, the heat and the kinetic
 * energy. A single run has no statistical error: its error is a round-off allowance,
 * 64 ulp of the run's momentum (energy) scale per collision, so that a conserved total
 * rounded otherwise is not called a rule's effect. */
#define SENS_BALLS 8
typedef struct sens_ctx {
    const scn_scenario *s;
    size_t nobs;
    char names[3 * SENS_BALLS + 4][24];
    const char *name[3 * SENS_BALLS + 4];
} sens_ctx;

static int sens_run(void *ctx, const app_sens_variant *v, double *x, double *se, char *err)
{
    const sens_ctx *k = ctx;
    scn_scenario s = *k->s;
    s.frame = v->frame;
    s.groups = v->groups;
    rc_sim_def def = scn_sim_def(&s);
    rc_sim_ball *b = malloc((s.n ? s.n : 1) * sizeof *b);
    rc_sim *sim = NULL;
    if (!b) {
        app_errf(err, "out of memory");
        return -1;
    }
    memcpy(b, s.balls, s.n * sizeof *b);
    app_sens_move(b, s.n, s.dim, v->move);
    int st = rc_sim_create(&def, &sim);
    if (st == RC_OK)
        st = rc_sim_set_time(sim, s.time);
    if (st == RC_OK)
        st = rc_sim_set_balls(sim, s.n, b, NULL);
    if (st == RC_OK)
        st = rc_sim_advance(sim, s.t_end, 0);
    rc_sim_diag d;
    if (st == RC_OK)
        st = rc_sim_diagnostics(sim, &d);
    size_t j = 0;
    double p2 = 0.0;
    for (size_t i = 0; st == RC_OK && i < s.n; i++) {
        rc_sim_ball o;
        rc_sim_get_ball(sim, i, &o);
        p2 += rc_v3_norm2(o.p);
        for (int a = 0; i < SENS_BALLS && a < s.dim; a++)
            x[j++] = rc_v3_get(o.p, a);
    }
    if (st == RC_OK) {
        x[j++] = sqrt(p2 / (double)(s.n ? s.n : 1));
        x[j++] = (double)d.collisions;
        x[j++] = d.heat;
        x[j++] = d.kinetic;
    }
    const double ulp = 64.0 * DBL_EPSILON * (1.0 + (st == RC_OK ? (double)d.collisions : 0.0));
    for (size_t q = 0; q < k->nobs; q++)
        se[q] = q + 3 < k->nobs ? ulp * sqrt(p2) : q + 3 == k->nobs ? 0.0
                                                                   : ulp * fabs(d.energy);
    rc_sim_free(&sim);
    free(b);
    if (st != RC_OK) {
        app_errf(err, "engine: %s", rc_strerror(st));
        return -1;
    }
    return 0;
}

static int sensitivity(const scn_scenario *s, char *err)
{
    sens_ctx k;
    k.s = s;
    k.nobs = 0;
    for (size_t i = 0; i < s->n && i < SENS_BALLS; i++)
        for (int a = 0; a < s->dim; a++)
            snprintf(k.names[k.nobs++], sizeof k.names[0], "p%zu.%c", i, "xyz"[a]);
    static const char *const agg[4] = {"p_rms", "collisions", "heat", "kinetic_energy"};
    for (int a = 0; a < 4; a++)
        snprintf(k.names[k.nobs++], sizeof k.names[0], "%s", agg[a]);
    for (size_t q = 0; q < k.nobs; q++)
        k.name[q] = k.names[q];
    app_sens_variant v[16];
    const size_t nv = app_sens_variants(s->frame, s->groups, s->c, s->dim, v, 16);
    if (app_mkdir_p(s->out.dir, err) != 0)
        return 1;
    const int fl = app_sensitivity(stdout, s->out.dir, v, nv, k.nobs, k.name, sens_run, &k, err);
    if (fl < 0)
        return 1;
    printf("%s: wrote %s/sensitivity.csv, %s/sensitivity.json\n", prog, s->out.dir, s->out.dir);
    return 0;
}

/* the scenario file: one */
static int scenario_arg(const char *a, void *opts)
{
    options *o = opts;
    if (o->file)
        return fail(2, "more than one scenario file given: %s and %s", o->file, a);
    o->file = a;
    return 0;
}

static int check_options(void *opts)
{
    const options *o = opts;
    if (!!o->file == !!o->builtin)
        return fail(2, "give one scenario: a file or --builtin rack|gas (see --help)");
    return 0;
}

static const app_cli cli = {.prog = prog, .tab = opts, .usage = usage, .stray_hint = "see --help",
                            .bad = 2, .check = check_options, .arg = scenario_arg,
                            .option_words = 1};

int main(int argc, char **argv)
{
    options opt;
    memset(&opt, 0, sizeof opt);
    int st0 = app_start(&cli, argc, argv, &opt);
    if (st0 >= 0)
        return st0;
    const char *file = opt.file, *builtin = opt.builtin, *out_dir = opt.out_dir;
    const char *frame = opt.frame;
    const double t_end = opt.t_end_given ? opt.t_end : NAN;
    const int no_plots = opt.no_plots, dump = opt.dump, sens = opt.sens;
    char err[APP_ERR_LEN];

    scn_scenario s;
    if (builtin ? scn_builtin(builtin, &s, err) : scn_load(file, &s, err))
        return fail(2, "%s", err);
    if (!isnan(t_end)) {
        if (!(t_end > s.time)) {
            scn_free(&s);
            return fail(2, "option --t-end: must be later than the start time %g", s.time);
        }
        s.t_end = t_end;
    }
    if (frame) {
        const rc_toi_frame *fr = rc_toi_frame_find(frame);
        if (!fr) {
            scn_free(&s);
            return fail(2, "option --frame: unknown contact frame '%s' (see --help)", frame);
        }
        s.frame = fr;
    }
    if (out_dir) {
        free(s.out.dir);
        s.out.dir = strdup(out_dir);
    }
    if (no_plots)
        s.out.plots = s.out.gif = 0;
    if (sens) {
        if (s.checkpoint) {
            scn_free(&s);
            return fail(2, "option --sensitivity: a scenario that continues a checkpoint "
                           "cannot be moved or rerun under other rules (give its balls)");
        }
        const int r = sensitivity(&s, err);
        scn_free(&s);
        return r ? fail(1, "%s", err) : 0;
    }
    if (dump) {
        scn_write(stdout, &s, s.time, s.t_end, s.n, s.balls);
        scn_free(&s);
        return 0;
    }

    if (sim_check_clock(&s, err)) {
        scn_free(&s);
        return fail(2, "%s: %s", builtin ? builtin : file, err);
    }
    rc_sim_def def = scn_sim_def(&s);
    rc_sim *sim = NULL;
    int st = rc_sim_create(&def, &sim);
    if (st != RC_OK) {
        scn_free(&s);
        return fail(2, "cannot create the simulation: %s", rc_strerror(st));
    }
    if (scn_start(sim, &s, builtin ? builtin : file, err)) {
        rc_sim_free(&sim);
        scn_free(&s);
        return fail(2, "%s", err);
    }

    sim_output o;
    /* set before the staging folder exists: once it does, a Ctrl-C is seen (and one during
     * the opening stops the run at its start, the state written) */
    signal(SIGINT, on_sigint);
    signal(SIGTERM, on_sigint);
    if (simout_open(&o, &s, prog, err)) {
        rc_sim_free(&sim);
        scn_free(&s);
        return fail(1, "%s", err);
    }

    if (simout_at(&o, sim, err)) { /* the state at the start: frame 0, snapshots due */
        simout_close(&o, sim, 0.0, 0, err);
        rc_sim_free(&sim);
        scn_free(&s);
        return fail(1, "%s", err);
    }
    app_progress bar;
    app_progress_init(&bar, "relcol-sim", 1000);
    double wall0 = now();
    int rc = 0;
    /* Advance from one output time to the next; within a stretch, in batches of events
     * so that Ctrl-C is seen promptly (batching does not change the event sequence). */
    const uint64_t batch = 200000;
    while (rc_sim_time(sim) < s.t_end && !interrupted) {
        double next = simout_next_time(&o, rc_sim_time(sim));
        while (rc_sim_time(sim) < next && !interrupted) {
            st = rc_sim_advance(sim, next, batch);
            if (st == RC_ESTALL) {
                rc_sim_diag d;
                rc_sim_diagnostics(sim, &d);
                char partner[48];
                if (d.stall_partner >= 0)
                    snprintf(partner, sizeof partner, "ball %lld", (long long)d.stall_partner);
                else if (d.stall_partner >= -6)
                    snprintf(partner, sizeof partner, "the wall %c%c",
                             "xyz"[(-1 - d.stall_partner) / 2],
                             (-1 - d.stall_partner) % 2 ? '+' : '-');
                else
                    snprintf(partner, sizeof partner, "a cell boundary");
                rc = fail(3, "engine stopped at t = %.17g: simulated time stands still: ball "
                          "%lld and %s keep meeting at that instant (a chain of touching balls "
                          "exactly as wide as the box, pushed against both walls; or a "
                          "clock so large that a step rounds to nothing); the state at that "
                          "time is written", rc_sim_time(sim), (long long)d.stall_ball,
                          partner);
                break;
            }
            if (st != RC_OK) {
                rc = fail(1, "engine stopped at t = %.17g: %s", rc_sim_time(sim), rc_strerror(st));
                break;
            }
            app_progress_update(&bar, (size_t)(1000.0 * (rc_sim_time(sim) - s.time) / (s.t_end - s.time)));
        }
        if (rc)
            break;
        /* an output time: outputs only read the engine (the run's bits do not depend on
         * them) */
        if (rc_sim_time(sim) >= next && simout_at(&o, sim, err)) {
            rc = fail(1, "%s", err);
            break;
        }
    }
    /* read once: a SIGINT landing between the reads (final.json written as finished, the exit
     * saying interrupted) made a continuation run on past t_end; a run that reached t_end is done */
    const int stopped = interrupted && rc_sim_time(sim) < s.t_end;
    if (stopped || rc) /* the bar stays where the run stopped */
        app_progress_stop(&bar);
    else
        app_progress_done(&bar);
    double wall = now() - wall0;
    if (stopped && !rc)
        fprintf(stderr, "%s: interrupted at t = %.17g: writing the restart state\n", prog,
                rc_sim_time(sim));
    if (simout_close(&o, sim, wall, stopped, err)) {
        if (!rc)
            rc = fail(1, "%s", err);
        else
            fprintf(stderr, "%s: %s\n", prog, err);
    }
    if (!rc)
        printf("%s: t = %.9g, %s\n", prog, rc_sim_time(sim), o.line);
    app_validity_note(sim);
    if (!rc && !app_validity_warn(stderr, prog) && o.have_d0) { /* (one warning line) */
        rc_sim_diag d;
        if (rc_sim_diagnostics(sim, &d) == RC_OK)
            app_rules_warn(stderr, prog, &d, &o.d0);
    }
    rc_sim_free(&sim);
    scn_free(&s);
    return rc ? rc : (stopped ? 130 : 0);
}
