/* sim.c — relcol-sim: runs a scenario with the event-driven engine and writes what the
 * scenario asks for: CSV snapshots, an extended-XYZ trajectory (OVITO, ASE) and an H5MD one, a
 * summary, the final state as a scenario (continuing from it is bit-identical to not
 * stopping), trajectory and animation figures through gnuplot. Ctrl-C writes the restart
 * state and exits cleanly. Every file is written atomically (temporary name, rename).
 * Exit status: 0 done, 2 bad scenario or option, 1 run or I/O failure, 130 interrupted. */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "app.h"
#include "scenario.h"
#include "simout.h"

static const char *const prog = "relcol-sim";
static volatile sig_atomic_t interrupted;

static void on_sigint(int sig)
{
    (void)sig;
    interrupted = 1;
}

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-sim SCENARIO.json | --builtin rack|gas  [--out DIR] [--t-end T]\n"
"                  [--frame NAME] [--no-plots] [--dump]\n"
"\n"
"Run an event-driven simulation of hard balls at any c (see apps/sim/SCENARIO.md for the\n"
"scenario format; data/scenarios/ has examples, --builtin NAME runs one of them).\n"
"\n"
"  --builtin NAME  rack: a billiard break (15 balls in a triangle and a cue ball);\n"
"                  gas: 400 discs at packing 0.2, rms speed 0.5 c, c = 1\n"
"  --out DIR       output folder (overrides outputs.dir)\n"
"  --t-end T       run until T (overrides t_end)\n"
"  --frame NAME    contact frame (overrides contact_frame; listed below)\n"
"  --no-plots      write data only, no gnuplot figures\n"
"  --dump          print the scenario as relcol reads it (JSON) and exit\n"
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

/* The whole file at path, malloc'ed (*bytes its length); NULL with errno on failure. */
static unsigned char *read_file(const char *path, size_t *bytes)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 1 << 20, n = 0;
    unsigned char *buf = malloc(cap);
    while (buf) {
        n += fread(buf + n, 1, cap - n, f);
        if (n < cap || ferror(f))
            break;
        unsigned char *nb = cap < ((size_t)1 << 40) ? realloc(buf, cap *= 2) : NULL;
        if (!nb) {
            free(buf);
            errno = ENOMEM;
        }
        buf = nb;
    }
    if (buf && ferror(f)) {
        free(buf);
        buf = NULL;
        errno = EIO;
    }
    fclose(f);
    *bytes = n;
    return buf;
}

/* Continue from the checkpoint the scenario names (beside the scenario file): the engine
 * takes the whole state it holds, which must be the state of the scenario's balls, to the
 * bit (the balls are the readable copy; the checkpoint alone carries the scheduled events
 * that make the continuation exact). 0, or -1 with the reason in err. */
static int load_checkpoint(rc_sim *sim, const scn_scenario *s, const char *file, char *err)
{
    const char *slash = strrchr(file, '/');
    char *dir = slash ? strndup(file, (size_t)(slash - file) + (slash == file)) : strdup(".");
    char *path = dir ? app_path_join(dir, s->checkpoint) : NULL;
    free(dir);
    if (!path) {
        app_errf(err, "out of memory");
        return -1;
    }
    size_t bytes = 0;
    unsigned char *buf = read_file(path, &bytes);
    int r = -1;
    if (!buf) {
        app_errf(err, "%s: checkpoint: cannot read %s: %s", file, path, strerror(errno));
        goto done;
    }
    int st = rc_sim_checkpoint_read(sim, buf, bytes);
    if (st != RC_OK) {
        app_errf(err, "%s: checkpoint: %s: %s", file, path, rc_strerror(st));
        goto done;
    }
    if (rc_sim_count(sim) != s->n || rc_sim_time(sim) != s->time) {
        app_errf(err, "%s: checkpoint: %s holds %zu balls at t = %.17g, the scenario %zu at "
                 "t = %.17g: not this run's state", file, path, rc_sim_count(sim),
                 rc_sim_time(sim), s->n, s->time);
        goto done;
    }
    for (size_t i = 0; i < s->n; i++) {
        rc_sim_ball b;
        const rc_sim_ball *w = &s->balls[i];
        rc_sim_get_ball(sim, i, &b);
        if (memcmp(&b.x, &w->x, sizeof b.x) || memcmp(&b.p, &w->p, sizeof b.p) ||
            b.r != w->r || b.m != w->m || b.tau != w->tau) {
            app_errf(err, "%s: balls[%zu]: differs from the state in the checkpoint %s (edit "
                     "the balls and delete the \"checkpoint\" key to start afresh from them)",
                     file, i, path);
            goto done;
        }
    }
    r = 0;
done:
    free(buf);
    free(path);
    return r;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    app_init(prog);
    const char *file = NULL, *builtin = NULL, *out_dir = NULL, *frame = NULL;
    double t_end = NAN;
    int no_plots = 0, dump = 0;
    char err[APP_ERR_LEN];
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            return app_help(usage);
        } else if (!strcmp(a, "--version")) {
            return app_version();
        } else if (!strcmp(a, "--builtin") || !strcmp(a, "--out") || !strcmp(a, "--t-end") ||
                   !strcmp(a, "--frame")) {
            if (i + 1 >= argc)
                return fail(2, "option %s: needs a value", a);
            const char *v = argv[++i];
            if (!strcmp(a, "--frame"))
                frame = v;
            else if (!strcmp(a, "--builtin"))
                builtin = v;
            else if (!strcmp(a, "--out"))
                out_dir = v;
            else if (app_parse_double(v, 0, &t_end, err))
                return fail(2, "option --t-end: %s", err);
        } else if (!strcmp(a, "--no-plots")) {
            no_plots = 1;
        } else if (!strcmp(a, "--dump")) {
            dump = 1;
        } else if (a[0] == '-' && a[1]) {
            return fail(2, "unknown option %s (see --help)", a);
        } else if (file) {
            return fail(2, "more than one scenario file given: %s and %s", file, a);
        } else {
            file = a;
        }
    }
    if (!!file == !!builtin)
        return fail(2, "give one scenario: a file or --builtin rack|gas (see --help)");

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
    if (dump) {
        scn_write(stdout, &s, s.time, s.t_end, s.n, s.balls);
        scn_free(&s);
        return 0;
    }

    rc_sim_def def = scn_sim_def(&s);
    rc_sim *sim = NULL;
    int st = rc_sim_create(&def, &sim);
    if (st != RC_OK) {
        scn_free(&s);
        return fail(2, "cannot create the simulation: %s", rc_strerror(st));
    }
    size_t badi = 0;
    if (s.checkpoint) {
        /* (a builtin has none: only a file can name one) */
        if (load_checkpoint(sim, &s, file, err)) {
            rc_sim_free(&sim);
            scn_free(&s);
            return fail(2, "%s", err);
        }
        st = RC_OK;
    } else {
        st = rc_sim_set_time(sim, s.time);
        if (st == RC_OK)
            st = rc_sim_set_balls(sim, s.n, s.balls, &badi);
    }
    if (st != RC_OK) {
        rc_sim_free(&sim);
        scn_free(&s);
        return fail(2, "%s: balls[%zu]: %s", builtin ? builtin : file, badi,
                    st == RC_EOVERLAP  ? "overlaps another ball"
                    : st == RC_EINVAL ? "the ball's shape is not inside the box"
                                      : rc_strerror(st));
    }

    sim_output o;
    if (simout_open(&o, &s, prog, err)) {
        rc_sim_free(&sim);
        scn_free(&s);
        return fail(1, "%s", err);
    }
    signal(SIGINT, on_sigint);
    signal(SIGTERM, on_sigint);

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
    if (interrupted || rc) /* the bar stays where the run stopped */
        app_progress_stop(&bar);
    else
        app_progress_done(&bar);
    double wall = now() - wall0;
    if (interrupted && !rc)
        fprintf(stderr, "%s: interrupted at t = %.17g: writing the restart state\n", prog,
                rc_sim_time(sim));
    if (simout_close(&o, sim, wall, interrupted, err)) {
        if (!rc)
            rc = fail(1, "%s", err);
        else
            fprintf(stderr, "%s: %s\n", prog, err);
    }
    if (!rc)
        printf("%s: t = %.9g, %s\n", prog, rc_sim_time(sim), o.line);
    if (!rc && o.have_d0) {
        rc_sim_diag d;
        if (rc_sim_diagnostics(sim, &d) == RC_OK)
            app_rules_warn(stderr, prog, &d, &o.d0);
    }
    rc_sim_free(&sim);
    scn_free(&s);
    return rc ? rc : (interrupted ? 130 : 0);
}
