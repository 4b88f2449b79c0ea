/* sweep.c — relcol-sweep: the general sweep over c. For each scenario (collision law, time
 * of impact, soft reference, engine run) and each c of a log or linear grid it computes
 * named observables and their deviation from the classical limit, writes CSV + gnuplot
 * script + PNG atomically, and prints the fitted convergence order. Grid points run in
 * parallel with OpenMP, and in an MPI build (-Dmpi=enabled) are split across ranks; each
 * point is computed independently and deterministically, so the output is the same bits
 * whatever the thread or rank count. Exit: 0 done, 2 bad option, 1 failure. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#ifdef RELCOL_HAVE_MPI
#include <mpi.h>
#endif
#ifdef _OPENMP
#include <omp.h>
#endif

#include "app.h"
#include "observables.h"
#include "sweep_plot.h"

static const char *const prog = "relcol-sweep";
static int rank = 0, nranks = 1;

typedef struct options {
    const char *scen, *grid, *out_dir;
    double from, to;
    long points;
    int no_plot;
    sweep_setup su;
} options;

#define OFF(field) offsetof(options, field)
static const app_opt opts[] = {
    /* (the scenario's name and the grid are checked after the parse, with the numbers) */
    {"--scenario", "NAME", APP_T_STRING, OFF(scen), "all",
     .help = "one of the scenarios above, or all (default %D)"},
    {"--grid", "log|lin", APP_T_STRING, OFF(grid), "log",
     .help = "spacing of the c grid (default %D)"},
    {"--from", "F", APP_T_DOUBLE, OFF(from), "10",
     .help = "c from F times |v|max (default %D; F > 1)"},
    {"--to", "T", APP_T_DOUBLE, OFF(to), "1e6", .help = "to T times |v|max (default %D)"},
    {"--points", "N", APP_T_LONG, OFF(points), "25", 2, 100000,
     .help = "grid points (default %D)"},
    /* (the defaults of sweep_setup_default, observables.c) */
    {"--eps", "E", APP_T_DOUBLE, OFF(su.eps), "0.8",
     .help = "restitution (default %D; soft: in (0, 1])"},
    {"--stiffness", "K", APP_T_DOUBLE, OFF(su.stiffness), "1e8",
     .help = "soft-sphere stiffness (default %D)"},
    {"--out", "DIR", APP_T_STRING, OFF(out_dir), "out/sweep",
     .help = "output folder (default %D)"},
    {"--no-plots", NULL, APP_T_FLAG, OFF(no_plot), .help = "data and script only"},
    {NULL},
};

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-sweep [--scenario NAME|all] [--grid log|lin] [--from F] [--to T]\n"
"                    [--points N] [--eps E] [--stiffness K] [--out DIR] [--no-plots]\n"
"\n"
"Sweep the speed of light c over a grid of multiples of the fastest speed |v|max and\n"
"measure how far each scenario's observables are from their classical (c = inf) values.\n"
"\n"
"scenarios (default all):\n");
    for (size_t i = 0; sweep_scenarios[i]; i++)
        fprintf(f, "  %-9s %s\n", sweep_scenarios[i]->name, sweep_scenarios[i]->summary);
    fprintf(f, "options:\n");
    app_opts_help(f, opts, 18);
    fprintf(f,
"\n"
"Writes DIR/sweep.csv (c, c/|v|max, (|v|max/c)^2, then per scenario the deviation of each\n"
"observable group and the raw observables), DIR/sweep.gp and DIR/sweep.png, and prints\n"
"the fitted log-log order of each deviation (expect -2: the first relativistic\n"
"corrections are of order (v/c)^2). Parallel over grid points with OpenMP\n"
"(OMP_NUM_THREADS) and, in an MPI build, across ranks (mpirun -np N relcol-sweep ...;\n"
"MPI is started only under a launcher, or with RELCOL_MPI=1).\n"
"\n"
"exit status: 0 done; 2 bad option (one line naming it); 1 a point failed or an I/O\n"
"failure (one line naming the file).\n");
}

/* "relcol-sweep: message" on stderr, from rank 0 only (every rank fails alike) */
#define fail(code, ...) (rank == 0 ? app_fail(prog, (code), __VA_ARGS__) : (code))

typedef struct task_out {
    double obs[OBS_MAX];
    double status; /* 0 ok, 1 failed (a double so one MPI datatype carries the record) */
} task_out;

/* The checks after the table's parse (each rank alike; rank 0 words them): 0, else 2. */
static int check_options(void *opts)
{
    const options *o = opts;
    if (strcmp(o->grid, "log") && strcmp(o->grid, "lin"))
        return fail(2, "option --grid: must be log or lin (got '%s')", o->grid);
    if (!(o->from > 1))
        return fail(2, "option --from: must be > 1 (c above the fastest speed)");
    if (!(o->to > o->from))
        return fail(2, "option --to: must be > --from");
    if (!(o->su.eps > 0 && o->su.eps <= 1))
        return fail(2, "option --eps: restitution must be in (0, 1] (the soft reference's "
                       "dashpot never releases at 0)");
    if (!(o->su.stiffness > 0))
        return fail(2, "option --stiffness: must be > 0");
    if (strcmp(o->scen, "all") && !sweep_scenario_find(o->scen))
        return fail(2, "option --scenario: unknown scenario '%s' (see --help)", o->scen);
    return 0;
}

static int rank0(void) { return rank == 0; }

static const app_cli cli = {.prog = prog, .tab = opts, .usage = usage, .stray_hint = "see --help",
                            .bad = 2, .check = check_options, .option_words = 1,
                            .speaks = rank0};

static int run(const options *o)
{
    const char *grid = o->grid, *out_dir = o->out_dir;
    const double from = o->from, to = o->to;
    const int no_plot = o->no_plot;
    const sweep_setup su = o->su;
    char err[APP_ERR_LEN];
    const sweep_scenario *list[16];
    size_t ns = 0;
    if (!strcmp(o->scen, "all")) {
        for (size_t i = 0; sweep_scenarios[i] && ns < 16; i++)
            list[ns++] = sweep_scenarios[i];
    } else {
        list[ns++] = sweep_scenario_find(o->scen);
    }

    double vmax = fmax(rc_v3_norm(su.v[0]), rc_v3_norm(su.v[1]));
    size_t N = (size_t)o->points;
    double *cs = malloc(N * sizeof *cs);
    size_t ntask = ns * (N + 1); /* +1: the classical reference of each scenario */
    task_out *res = calloc(ntask, sizeof *res);
    if (!cs || !res) {
        free(cs);
        free(res);
        return fail(1, "out of memory");
    }
    for (size_t j = 0; j < N; j++) {
        double f = (double)j / (double)(N - 1);
        cs[j] = vmax * (!strcmp(grid, "log") ? from * pow(to / from, f) : from + (to - from) * f);
    }

    /* this rank's contiguous block of tasks */
    size_t lo = ntask * (size_t)rank / (size_t)nranks, hi = ntask * (size_t)(rank + 1) / (size_t)nranks;
    app_progress bar;
    app_progress_init(&bar, prog, hi - lo);
    size_t done = 0;
#pragma omp parallel for schedule(dynamic, 1)
    for (size_t t = lo; t < hi; t++) {
        size_t s = t / (N + 1), j = t % (N + 1);
        const double c = j == N ? INFINITY : cs[j];
        char e[APP_ERR_LEN];
        res[t].status = list[s]->eval(&su, c, res[t].obs, e) ? 1.0 : 0.0;
#pragma omp atomic
        done++;
#ifdef _OPENMP
        if (omp_get_thread_num() == 0)
#endif
            app_progress_update(&bar, done);
    }
    app_progress_done(&bar);
#ifdef RELCOL_HAVE_MPI
    if (nranks > 1) {
        int *counts = malloc((size_t)nranks * sizeof *counts), *displs = malloc((size_t)nranks * sizeof *displs);
        int rec = (int)(sizeof(task_out) / sizeof(double));
        for (int r = 0; r < nranks; r++) {
            size_t a = ntask * (size_t)r / (size_t)nranks, b = ntask * (size_t)(r + 1) / (size_t)nranks;
            counts[r] = (int)(b - a) * rec;
            displs[r] = (int)a * rec;
        }
        if (rank == 0)
            MPI_Gatherv(MPI_IN_PLACE, counts[0], MPI_DOUBLE, res, counts, displs, MPI_DOUBLE, 0,
                        MPI_COMM_WORLD);
        else
            MPI_Gatherv(res + lo, counts[rank], MPI_DOUBLE, NULL, NULL, NULL, MPI_DOUBLE, 0,
                        MPI_COMM_WORLD);
        free(counts);
        free(displs);
    }
#endif
    int rc = 0;
    if (rank != 0)
        goto done;
    for (size_t t = 0; t < ntask; t++)
        if (res[t].status != 0.0) {
            size_t s = t / (N + 1), j = t % (N + 1);
            const double c = j == N ? INFINITY : cs[j];
            double tmp[OBS_MAX];
            list[s]->eval(&su, c, tmp, err); /* again, serially, for the message */
            rc = fail(1, "scenario %s at c = %s: %s", list[s]->name,
                      j == N ? "inf" : app_fmt(cs[j], (char[APP_FMT_LEN]){0}), err);
            goto done;
        }

    /* deviations: per group, |a - a_inf| / |a_inf| over the group's components */
    size_t ncol = 0;
    for (size_t s = 0; s < ns; s++)
        ncol += (size_t)list[s]->n_groups;
    double *dev = calloc(N * ncol, sizeof *dev);
    if (!dev) {
        rc = fail(1, "out of memory");
        goto done;
    }
    size_t col = 0;
    for (size_t s = 0; s < ns; s++) {
        const sweep_scenario *sc = list[s];
        const double *ref = res[s * (N + 1) + N].obs;
        for (int g = 0; g < sc->n_groups; g++, col++)
            for (size_t j = 0; j < N; j++) {
                const double *o = res[s * (N + 1) + j].obs;
                double num = 0, den = 0;
                for (int q = 0; q < sc->n_obs; q++)
                    if (sc->group_of[q] == g) {
                        num += (o[q] - ref[q]) * (o[q] - ref[q]);
                        den += ref[q] * ref[q];
                    }
                dev[j * ncol + col] = den > 0 ? sqrt(num / den) : sqrt(num);
            }
    }

    if (app_mkdir_p(out_dir, err)) {
        free(dev);
        rc = fail(1, "%s", err);
        goto done;
    }
    char *csv = app_path_join(out_dir, "sweep.csv"), *gp = app_path_join(out_dir, "sweep.gp");
    app_atomic a;
    if (!csv || !gp || app_atomic_open(&a, csv, err)) {
        rc = fail(1, "%s", csv && gp ? err : "out of memory");
        goto files_done;
    }
    fprintf(a.f, "c,c_over_vmax,vmax2_over_c2");
    for (size_t s = 0; s < ns; s++)
        for (int g = 0; g < list[s]->n_groups; g++)
            fprintf(a.f, ",dev_%s_%s", list[s]->name, list[s]->group[g]);
    for (size_t s = 0; s < ns; s++)
        for (int q = 0; q < list[s]->n_obs; q++)
            fprintf(a.f, ",%s_%s", list[s]->name, list[s]->obs[q]);
    fputc('\n', a.f);
    for (size_t j = 0; j <= N; j++) { /* the last row is the classical reference */
        if (j < N)
            fprintf(a.f, "%.17g,%.17g,%.17g", cs[j], cs[j] / vmax, (vmax / cs[j]) * (vmax / cs[j]));
        else
            fprintf(a.f, "inf,inf,0");
        for (size_t c2 = 0; c2 < ncol; c2++)
            fprintf(a.f, ",%.17g", j < N ? dev[j * ncol + c2] : 0.0);
        for (size_t s = 0; s < ns; s++)
            for (int q = 0; q < list[s]->n_obs; q++)
                fprintf(a.f, ",%.17g", res[s * (N + 1) + j].obs[q]);
        fputc('\n', a.f);
    }
    if (app_atomic_commit(&a, err)) {
        rc = fail(1, "%s", err);
        goto files_done;
    }

    /* fitted orders */
    double *x = malloc(N * sizeof *x), *y = malloc(N * sizeof *y);
    double order[64];
    col = 0;
    printf("%s: %zu values of c from %g to %g x |v|max = %.6g (%s grid)\n", prog, N, from, to,
           vmax, grid);
    for (size_t s = 0; s < ns && x && y; s++)
        for (int g = 0; g < list[s]->n_groups; g++, col++) {
            size_t m = 0;
            for (size_t j = 0; j < N; j++)
                if (dev[j * ncol + col] > list[s]->floor) {
                    x[m] = cs[j] / vmax;
                    y[m] = dev[j * ncol + col];
                    m++;
                }
            double slope = NAN, sd = NAN;
            size_t used = 0;
            if (app_loglog_slope(x, y, m, &slope, NULL, &sd, &used) != 0)
                slope = NAN;
            if (col < 64)
                order[col] = slope;
            printf("order %-8s %-11s %8.4f +- %.2g (%zu points above the noise floor %g; "
                   "expect -2)\n", list[s]->name, list[s]->group[g], slope, sd, used,
                   list[s]->floor);
        }
    free(x);
    free(y);

    if (sweep_plot_write(gp, list, ns, order, col < 64 ? col : 64, su.eps, su.stiffness, err)) {
        rc = fail(1, "%s", err);
        goto files_done;
    }
    printf("wrote %s, %s", csv, gp);
    if (!no_plot) {
        int made = 0;
        if (app_gnuplot_run(prog, out_dir, "sweep.gp", "sweep.png", &made, err))
            rc = fail(1, "%s", err);
        else if (made)
            printf(", %s/sweep.png", out_dir);
    }
    printf("\n");
files_done:
    free(csv);
    free(gp);
    free(dev);
done:
    free(cs);
    free(res);
    return rc;
}

#ifdef RELCOL_HAVE_MPI
/* Was this process started by an MPI launcher? mpirun/mpiexec of Open MPI, MPICH's Hydra
 * and PMIx-based launchers set one of these in every rank's environment; RELCOL_MPI=1
 * asks for MPI regardless. Started on its own, relcol-sweep does not pay MPI_Init (a third
 * of a second, and the runtime's messages on stderr -- or its failures, when it cannot
 * write its session files) for a single rank. */
static int launched_by_mpi(void)
{
    static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMI_RANK",
                                       "PMIX_RANK"};
    const char *force = getenv("RELCOL_MPI");
    if (force && strcmp(force, "1") == 0)
        return 1;
    for (size_t i = 0; i < sizeof vars / sizeof *vars; i++)
        if (getenv(vars[i]))
            return 1;
    return 0;
}
#endif

int main(int argc, char **argv)
{
#ifdef RELCOL_HAVE_MPI
    const int mpi = launched_by_mpi();
    if (mpi) { /* (before the parse: MPI_Init may take its own arguments out of argv) */
        MPI_Init(&argc, &argv);
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Comm_size(MPI_COMM_WORLD, &nranks);
    }
#endif
    options o;
    memset(&o, 0, sizeof o);
    o.su = sweep_setup_default();
    int rc = app_start(&cli, argc, argv, &o);
    if (rc < 0)
        rc = run(&o);
    if (rc == 0) /* (under MPI, each rank for the runs it made) */
        app_validity_warn(stderr, prog);
#ifdef RELCOL_HAVE_MPI
    if (mpi) {
        /* every rank returns the same code: rank 0 decides */
        MPI_Bcast(&rc, 1, MPI_INT, 0, MPI_COMM_WORLD);
        MPI_Finalize();
    }
#endif
    return rc;
}
