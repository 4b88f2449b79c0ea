/* app.h — the relcol apps' shared plumbing (internal static library, never part of
 * librelcol): strict number parsing, a CSV table reader, ball rows -> rc_particle, an
 * atomic file writer, a gnuplot runner, a log-log slope fit, a TTY-only progress bar and
 * the command-line plumbing (errors, the option loop, --help, --c, name lists).
 *
 * Error convention: functions that can fail return 0 on success and -1 on failure, and
 * write one line of text (no program name, no newline) into the caller's buffer `err` of
 * size APP_ERR_LEN; the app prefixes its name and prints it (app_fail). Nothing here
 * prints, except app_fail, app_help, app_opts_next and app_opts_parse (their own errors,
 * --version, --list-options; under app_cli.speaks only where it says so), app_gnuplot_run
 * (a note when gnuplot is absent), the progress bar and the --sensitivity mode. */
#ifndef RELCOL_APP_H
#define RELCOL_APP_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "relcol/relcol.h"

#define APP_ERR_LEN 512

/* printf into an error buffer of APP_ERR_LEN bytes (truncating). */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void app_errf(char *err, const char *fmt, ...);

/* ---- command line ----------------------------------------------------------------- */

/* Every app's first call: turns GSL's default error handler (which prints and aborts) off,
 * so that a GSL failure in the app's own numerics (fits, roots, special functions) comes
 * back as a status code the app reports, as relcol's own functions do; and has standard
 * output checked at exit: an app whose output could not be written (a full disk, a closed
 * file) says so, "prog: cannot write to standard output: reason", and exits 1 instead of
 * 0 (as coreutils' close_stdout). */
void app_init(const char *prog);

/* Print "prog: message\n" on stderr (fmt as printf, no newline) and return code, so that
 * an app's error paths read `return app_fail(prog, 2, "--eps: %s", err);`. */
#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
int app_fail(const char *prog, int code, const char *fmt, ...);
int app_vfail(const char *prog, int code, const char *fmt, va_list ap);
/* Print usage(stdout) for --help, and the --version line every app shares; returns the
 * exit status 0 (a failed write makes it 1 at exit: app_init). */
int app_help(void (*usage)(FILE *));
/* Print "prog (relcol) VERSION" on stdout for --version (with the library's version when it
 * differs from the headers the app was built with); returns the exit status 0. */
int app_version(void);

/* The option loop shared by the apps: each argument is "--help" or "-h"; "--version" (it
 * prints the version line, app_version, and exits 0 at once: no app has anything to do
 * after it, and so none needs its own case for it; with it->no_exit it comes back as
 * APP_OPT_VERSION instead, for an MPI rank that must finalize); a flag from the
 * list `flags` (exact match, no value); or "--name value" / "--name=value" with --name
 * from the list `valued`. Anything else is an error, printed by app_opts_next itself as
 * one app_fail line (so that no message is cut to a buffer; nothing with it->quiet):
 *   "unexpected argument 'X' (STRAY_HINT)"       X does not start with "--"
 *   "unknown option --NAME (see --help)"         (at most 40 chars of a very long one)
 *   "--NAME: missing value"                      the last argument wants a value
 * Use:
 *   app_opts it;
 *   app_opts_init(&it, prog, argc, argv, valued, NULL, "see --help");
 *   while ((k = app_opts_next(&it, &name, &val)) != APP_OPT_END) { switch (k) ... } */
/* With it->positional set (relcol-sim's scenario file), an argument that does not start
 * with '-' (or is "-") comes back as APP_OPT_ARG in *value, and "-x" is an unknown option. */
enum { APP_OPT_END = 0, APP_OPT_VALUE, APP_OPT_FLAG, APP_OPT_HELP, APP_OPT_ERROR, APP_OPT_ARG,
       APP_OPT_VERSION };
typedef struct app_opts {
    const char *prog;
    int argc;
    char **argv;
    int i;                      /* the next argument */
    const char *const *valued;  /* NULL-terminated "--name"s that take a value */
    const char *const *flags;   /* NULL-terminated "--name"s without a value, or NULL */
    const char *stray_hint;     /* e.g. "see --help" */
    char name[32];              /* the current option's name (without "=value") */
    int positional;             /* arguments that are not options are the app's (above) */
    int option_words;           /* "option --NAME: needs a value", and a stray argument
                                 * "unknown option X (see --help)" (relcol-sim's wording) */
    int quiet;                  /* print nothing: an MPI app's ranks but one (app_cli.speaks) */
    int no_exit;                /* --version comes back as APP_OPT_VERSION, unprinted */
} app_opts;
void app_opts_init(app_opts *it, const char *prog, int argc, char **argv,
                   const char *const *valued, const char *const *flags,
                   const char *stray_hint);
/* The next argument: APP_OPT_VALUE (*name, *value set), APP_OPT_FLAG (*name), APP_OPT_HELP,
 * APP_OPT_ARG, APP_OPT_VERSION, APP_OPT_ERROR (already printed) or APP_OPT_END. *name stays
 * valid until the next call. */
int app_opts_next(app_opts *it, const char **name, const char **value);

/* ---- option tables ---------------------------------------------------------------- */

/* An app's options as data: one app_opt per option, in help order, ended by {NULL}. The
 * parser (app_opts_parse) and the options section of --help (app_opts_help) both walk it,
 * so the help cannot name an option the parser lacks, nor the reverse. A value's error is
 * "--NAME: reason" (exit status cli->bad), its range checked by the row's `valid` as it is
 * given (argv order, as a hand parser); checks between options stay in the app. */
typedef enum app_opt_type {
    APP_T_DOUBLE,     /* double, finite */
    APP_T_DOUBLE_INF, /* double, finite or inf */
    APP_T_INT,        /* int in [lo, hi] (app_parse_long's wording) */
    APP_T_LONG,       /* long in [lo, hi] */
    APP_T_U64,        /* uint64_t */
    APP_T_STRING,     /* const char *, pointing into argv */
    APP_T_CHOICE,     /* int: the index in choices; "unknown WHAT 'x' (a, b or c)" */
    APP_T_FLAG,       /* int set to 1; no value */
    APP_T_LIST,       /* double[hi], 1..hi comma-separated numbers, the count in int `count` */
    APP_T_CUSTOM,     /* parse(value, destination, opts, err): 0, or -1 with the reason in
                       * err; opts (the whole struct) for an option that sets two fields */
} app_opt_type;
typedef struct app_opt {
    const char *name;   /* "--c" */
    const char *meta;   /* the value's name in the help ("C|inf"), NULL for none */
    app_opt_type type;
    size_t off;         /* offsetof the destination in the app's options struct */
    const char *deflt;  /* the default as command-line text, parsed before argv (NULL: none) */
    double lo, hi;      /* APP_T_INT's range; APP_T_LIST: hi = the most numbers */
    const char *help;   /* help lines ('\n' between them); "%D" prints deflt */
    void (*help_more)(FILE *f); /* further help lines (a list of laws), or NULL; with
                                 * help NULL it prints the entry's text from its first line */
    const char *const *choices; /* APP_T_CHOICE: NULL-terminated names */
    const char *what;   /* APP_T_CHOICE: "format" in "unknown format 'x' (csv or json)" */
    int (*parse)(const char *val, void *dst, void *opts, char *err); /* APP_T_CUSTOM */
    size_t count;       /* APP_T_LIST: offsetof the int count */
    size_t given;       /* offsetof + 1 of an int set to 1 when the option is given (0: none) */
    /* the value's range (NULL: any): 0, or -1 with the reason in err, e.g. "0 must be > 0";
     * it reads the destination (and count) of the row o in opts */
    int (*valid)(const struct app_opt *o, const void *opts, char *err);
    double min, max;    /* app_valid_open_closed's range (min, max] */
} app_opt;
#define APP_GIVEN(type, field) (offsetof(type, field) + 1)

/* Ranges for app_opt.valid. A double (APP_T_DOUBLE*) or every number of an APP_T_LIST:
 * > 0 ("-1 must be > 0"), >= 0 ("-1 must be >= 0"), in (min, max] ("0.8 outside (0, 0.7]");
 * a speed of light (app_check_c: "c = 0 must be > 0"). */
int app_valid_positive(const app_opt *o, const void *opts, char *err);
int app_valid_nonneg(const app_opt *o, const void *opts, char *err);
int app_valid_open_closed(const app_opt *o, const void *opts, char *err);
int app_valid_c(const app_opt *o, const void *opts, char *err);

/* What app_start needs of an app: its name, its table, its whole help (which prints the
 * options with app_opts_help), the hint for stray arguments, the exit status of a bad
 * option and the app's checks between options after the parse (0, or an exit status
 * after its error line; NULL for none). */
typedef struct app_cli {
    const char *prog;
    const app_opt *tab;
    void (*usage)(FILE *f);
    const char *stray_hint;
    int bad;
    int (*check)(void *opts);
    /* NULL, or the app's plain arguments (a scenario file): 0, or an exit status after its
     * error line */
    int (*arg)(const char *arg, void *opts);
    /* 1: relcol-sim's wording, "option --NAME: reason", "option --NAME: needs a value" */
    int option_words;
    /* NULL, or whether this process prints (help, --version, the parser's errors): under
     * MPI only rank 0 does, while every rank parses alike and returns the same status */
    int (*speaks)(void);
} app_cli;

/* The table's defaults into opts (-1 with the reason in err: a table's own bug). */
int app_opts_defaults(const app_opt *tab, void *opts, char *err);
/* Parse argv into opts: 0, APP_PARSE_HELP for --help, APP_PARSE_DONE after --version or
 * the hidden --list-options (the table's names and --version, one a line) were printed,
 * else cli->bad after one error line. Nothing exits: an MPI rank returns to finalize. */
enum { APP_PARSE_HELP = -1, APP_PARSE_DONE = -2 };
int app_opts_parse(const app_cli *cli, int argc, char **argv, void *opts);
/* The options section of --help: "  --NAME META  help" per entry, the help from column
 * col (0-based; continuation lines too), help_more after; last the --help line every app
 * has (no table holds it; --list-options names it). */
void app_opts_help(FILE *f, const app_opt *tab, int col);
/* APP_T_CUSTOM parsers of a law (const rc_law *) and a contact frame
 * (const rc_toi_frame *) by name: "unknown law 'x' (known: zmf, ...)". */
int app_opt_law(const char *val, void *dst, void *opts, char *err);
int app_opt_toi_frame(const char *val, void *dst, void *opts, char *err);
/* APP_T_CUSTOM: an output folder (const char *), not empty: "empty folder name". */
int app_opt_dir(const char *val, void *dst, void *opts, char *err);
/* Every app's main() prologue: app_init, the defaults, the parse, --help, cli->check.
 * Returns -1 to go on, else the status main returns at once (0 after --help, --version). */
int app_start(const app_cli *cli, int argc, char **argv, void *opts);

/* A usable speed of light: c > 0 and 1/c^2 representable (c = inf is fine). Errors:
 * "c = -1 must be > 0", "c = 1e-200 is out of range (1/c^2 under- or overflows; use inf)". */
int app_check_c(double c, char *err);
/* The names of the library's collision laws (rc_laws) or contact frames (rc_toi_frames)
 * as "zmf, cm-isotropic, ..." for "unknown law" messages; truncated to n - 1 chars. */
const char *app_law_list(char *buf, size_t n);
const char *app_toi_frame_list(char *buf, size_t n);

/* ---- numbers ---------------------------------------------------------------------- */

/* Parse the whole token s (surrounding blanks allowed) as a finite double. With
 * allow_inf, "inf"/"infinity" (any case, optional '+') gives +INFINITY; NaN, hex floats
 * with trailing junk, empty strings, overflow ("1e999") are rejected with the reason in
 * err (e.g. "not a number: '1.5x'"). */
int app_parse_double(const char *s, int allow_inf, double *out, char *err);
/* The shortest %g form of x that reads back as x (for messages: "0.6", not
 * "0.59999999999999998"); buf needs APP_FMT_LEN bytes. */
#define APP_FMT_LEN 32
const char *app_fmt(double x, char *buf);
/* Whole-token integer in [lo, hi]. */
int app_parse_long(const char *s, long lo, long hi, long *out, char *err);
/* Whole-token unsigned 64-bit integer (seeds). */
int app_parse_u64(const char *s, uint64_t *out, char *err);
/* Comma-separated list of 1..max finite numbers ("1,0.5"): *n gets the count. */
int app_parse_list(const char *s, double *out, int max, int *n, char *err);

/* ---- CSV tables ------------------------------------------------------------------- */

/* A CSV table: a header line of column names, then rows of fields, as spreadsheets export
 * them: a UTF-8 byte order mark is skipped, CR of CRLF files dropped, a field may be
 * quoted (RFC 4180: "a, b", "say ""x""", a quoted field may span lines). Unquoted fields
 * are trimmed of blanks; blank lines are skipped (trailing or not), lines starting with
 * '#' are comments. */
typedef struct app_table {
    int ncols;
    char **names;    /* ncols column names */
    size_t nrows;
    char **cells;    /* nrows * ncols field strings, row-major */
    long *line;      /* the 1-based file line number of each row, for messages */
    long header_line;
} app_table;

/* Read a whole table from f. Errors name the line, e.g. "line 4: 3 fields, header has 4";
 * a header with an empty or repeated name is an error too. On failure *t is empty. */
int app_table_read(FILE *f, app_table *t, char *err);
void app_table_free(app_table *t);
/* Index of the column called name, or -1. */
int app_table_col(const app_table *t, const char *name);
static inline const char *app_table_cell(const app_table *t, size_t row, int col)
{
    return t->cells[row * (size_t)t->ncols + (size_t)col];
}
/* The range of magnitudes a ball's inputs (rest mass, radius, position and velocity or
 * momentum components, box edges) may take: zero, or between APP_SCALE_MIN and
 * APP_SCALE_MAX, so that their squares and products -- every distance, energy and contact
 * time is made of them -- are finite, normal doubles (a radius of 1e300 or a mass of
 * 1e-170 would otherwise give NaN or silently wrong numbers). */
#define APP_SCALE_MIN 1e-150
#define APP_SCALE_MAX 1e150
/* 0 if x is 0 (allowed only when !positive) or a magnitude in that range; else -1 with
 * the reason in why (APP_ERR_LEN), e.g. "1e+300 is too large: ...". */
int app_check_scale(double x, int positive, char *why);
/* app_table_double, then app_check_scale, the error naming line, row label and column. */
int app_table_scaled(const app_table *t, size_t row, int col, const char *row_label,
                     int positive, double *out, char *err);

/* The field (row, col) as a finite number (or inf if allowed). The error names the line,
 * the row label (e.g. "ball 1"; NULL for none) and the column:
 * "line 3 (ball 1), column vx: not a number: 'abc'". */
int app_table_double(const app_table *t, size_t row, int col, const char *row_label,
                     int allow_inf, double *out, char *err);
/* "line L (ball i)" for messages: writes into buf of size n and returns buf. */
const char *app_row_name(const app_table *t, size_t row, char *buf, size_t n);

/* ---- ball rows -------------------------------------------------------------------- */

/* Balls as given in a table, before c is known. Column conventions: `m` (rest mass),
 * then either velocity columns vx[,vy[,vz]] or momentum columns px[,py[,pz]] (never both;
 * the dimension is their number, and a component needs all earlier ones), optional
 * positions x[,y[,z]] of the same dimension. Each row is one ball, numbered from 0. */
typedef struct app_balls {
    int dim;           /* 1..3 */
    int momentum;      /* 1: the table gives p; 0: it gives v */
    int has_pos;
    size_t n;
    double *m;         /* n rest masses (checked > 0) */
    rc_vec3 *q;        /* n velocities or momenta as given, unused components 0 */
    rc_vec3 *x;        /* n positions (zeros if !has_pos) */
    const app_table *table; /* for messages; must outlive this struct */
} app_balls;

/* Parse ball rows. `extra` is a NULL-terminated list of further column names the caller
 * accepts (e.g. {"r", NULL}; NULL for none): any other unknown column is an error. The
 * caller reads extra columns itself with app_table_double. nrows_want > 0 demands that
 * exactly many rows. All numbers must be finite and within app_check_scale's range, and
 * m > 0; |v| < c is checked later, by app_balls_particles, since it depends on c. */
int app_balls_parse(const app_table *t, const char *const *extra, size_t nrows_want,
                    app_balls *b, char *err);
void app_balls_free(app_balls *b);
/* States at speed of light c (inf allowed): momentum input is taken as is; velocity input
 * goes through rc_momentum_from_velocity, with "line 3 (ball 1), column vx: |v| = 1.5 >=
 * c = 1" on failure. out has b->n entries. */
int app_balls_particles(const app_balls *b, double c, rc_particle *out, char *err);
/* Column names of the given vector columns ("vx", "vx,vy", ...) for messages. */
const char *app_balls_colnames(const app_balls *b, int positions, char *buf, size_t n);

/* ---- files ------------------------------------------------------------------------ */

/* Atomic writer: the content goes to a temporary file beside `path`; commit flushes,
 * fsyncs, renames it over path and fsyncs the folder, so readers see the old file or the
 * whole new one, never half. abort (or a failed commit) removes the temporary. */
typedef struct app_atomic {
    FILE *f;
    char *path;
    char *tmp;
} app_atomic;
int app_atomic_open(app_atomic *a, const char *path, char *err);
/* app_atomic_open of DIR/NAME */
int app_atomic_open_in(app_atomic *a, const char *dir, const char *name, char *err);
int app_atomic_commit(app_atomic *a, char *err);
void app_atomic_abort(app_atomic *a);

/* A temporary file's mkstemp template beside dir/base: ".base.relcol-PID.XXXXXX" (malloc'ed,
 * NULL on ENOMEM); and the removal of such temporaries of base (NULL: of any name) in dir
 * whose writing process no longer exists (a run that was killed, or a disk that filled):
 * every writer of an output file calls it first, so stale temporaries never pile up. */
char *app_temp_template(const char *dir, const char *base);
void app_clean_stale(const char *dir, const char *base);
/* fsync a folder, so that renames in it are durable (best effort: some file systems
 * refuse it); and remove a file, or a folder with everything in it (no symlink is
 * followed). */
void app_fsync_dir(const char *dir);
void app_remove_tree(const char *path);

/* mkdir -p (mode 0777 before umask). */
int app_mkdir_p(const char *dir, char *err);
/* dir + "/" + name, malloc'ed (NULL on ENOMEM). */
char *app_path_join(const char *dir, const char *name);

/* ---- gnuplot ---------------------------------------------------------------------- */

/* Is `gnuplot` an executable on PATH? */
int app_have_gnuplot(void);
/* Run `gnuplot -e "outfile='TMP'" script` in folder dir, then fsync and rename TMP to
 * dir/out_name, so the figure appears atomically too. Scripts should start with
 *   if (!exists("outfile")) outfile = 'NAME.png'
 * so that they also run by hand. Without gnuplot on PATH it prints one note on stderr
 * (prefixed by prog) and returns 0: the data and the script are the product. Returns -1
 * with the reason in err if gnuplot ran and failed. *made (may be NULL) is set to 1 if
 * the figure was written. */
int app_gnuplot_run(const char *prog, const char *dir, const char *script_name,
                    const char *out_name, int *made, char *err);
/* The opening lines of an app's PNG script: the outfile default above, utf8, `set terminal
 * pngcairo TERMINAL` (e.g. "size 1100,760 enhanced font 'Sans,13' linewidth 1.5"), the
 * output and the CSV separator; with loglog also log x and y axes labelled 10^{n}. */
void app_gnuplot_head(FILE *f, const char *png_name, const char *terminal, int loglog);

/* ---- fits ------------------------------------------------------------------------- */

/* Least-squares slope of log10(y) against log10(x) over the points where both are
 * finite and > 0 (gsl_fit_linear). *used gets the number of points used; -1 if < 3.
 * slope_sd (may be NULL) gets the slope's standard error from the fit's residuals. */
int app_loglog_slope(const double *x, const double *y, size_t n, double *slope,
                     double *intercept, double *slope_sd, size_t *used);

/* ---- progress --------------------------------------------------------------------- */

/* A progress bar on stderr that draws only when stderr is a terminal (pipes, CI logs and
 * tests stay clean) and only when the whole percentage changes. */
typedef struct app_progress {
    const char *label;
    size_t total;
    int tty;
    int last_pct;
} app_progress;
void app_progress_init(app_progress *p, const char *label, size_t total);
void app_progress_update(app_progress *p, size_t done);
void app_progress_done(app_progress *p);
/* An interrupted run's bar: ends the line where the bar stands (not at 100 %). */
void app_progress_stop(app_progress *p);

/* ---- interrupts (interrupt.c) ----------------------------------------------------- */

/* SIGINT and SIGTERM (even when started ignored, as `cmd &` in a script does) remove the
 * guarded temporary files and end the process by the signal; app_init installs it. The
 * atomic writer guards its temporary from open to commit or abort. */
void app_interrupt_install(void);
void app_interrupt_guard(const char *tmp);
void app_interrupt_forget(const char *tmp);

/* ---- how much of a run its rules decided ------------------------------------------ */

/* The share of a run's collisions above which app_rules_warn speaks: issue 16's bound on
 * the overlap policy (apps/common/rules.c says why). */
#define APP_RULES_SHARE 1e-3
/* Between diagnostics d0 (NULL: the start of the engine) and d: when the overlap policy's
 * share of the collisions, or the order rule's kinks per collision (per_ball frames),
 * exceeds APP_RULES_SHARE, one warning line "prog: warning: ..." on f naming both; 1 if
 * it warned, else 0. */
int app_rules_warn(FILE *f, const char *prog, const rc_sim_diag *d, const rc_sim_diag *d0);

/* ---- where a run stands against the model's regime (validity.c) ------------------- */

/* Note run s's validity report (call before freeing it; thread-safe). */
void app_validity_note(const rc_sim *s);
/* ... or its report, read already (rc_sim_validity). */
void app_validity_note_report(const rc_validity *v);
/* The runs noted so far that were `outside`. */
size_t app_validity_outside(void);
/* One line "prog: warning: ... outside the rigid-ball model's regime ..." on f when a
 * noted run was outside (the numbers of the run of largest p_model); 1 if it warned. */
int app_validity_warn(FILE *f, const char *prog);

/* ---- --sensitivity: which results move with the model's rules (sensitivity.c) ------ */

/* One rerun of a scenario: positions moved by `move` of a radius (app_sens_move), the
 * group rule and the contact frame to use. */
typedef struct app_sens_variant {
    char name[48];
    double move;
    int groups;
    const rc_toi_frame *frame;
} app_sens_variant;
/* An app's run of its scenario under variant v: its nobs observables into x[] and their
 * statistical errors into se[] (0 where it has none); 0, or -1 with err set. */
typedef int (*app_sens_run_fn)(void *ctx, const app_sens_variant *v, double *x, double *se,
                               char *err);
/* The variants a run offers (at most cap): the base run, the 1e-15 move, the other group
 * rule, and the other contracted frames when the run's frame is contracted at finite c
 * (sensitivity.c says why these). Returns how many. */
size_t app_sens_variants(const rc_toi_frame *frame, int groups, double c, int dim,
                         app_sens_variant *v, size_t cap);
/* Move each ball's coordinates by +-move times its radius (a fixed pattern of signs). */
void app_sens_move(rc_sim_ball *b, size_t n, int dim, double move);
/* Run every variant (v[0] the base, v[1] the move), print the table on f and write
 * dir/sensitivity.csv and dir/sensitivity.json (each written whole, then renamed): the
 * number of observables flagged (a shift above 3 errors), or -1 with err set. */
int app_sensitivity(FILE *f, const char *dir, const app_sens_variant *v, size_t nv, size_t nobs,
                    const char *const *names, app_sens_run_fn run, void *ctx, char *err);
/* An app's whole --sensitivity mode (relcol-eos, relcol-gas): dir made, the variants of
 * (frame, groups, c, dim) run by app_sensitivity on stdout, "prog: wrote DIR/sensitivity.csv,
 * DIR/sensitivity.json", the validity warning; the exit status: 0, 2 ("prog: --out: reason":
 * the folder cannot be made) or 1 (a run or a file failed), after its line. */
int app_sensitivity_main(const char *prog, const char *dir, const rc_toi_frame *frame, int groups,
                         double c, int dim, size_t nobs, const char *const *names,
                         app_sens_run_fn run, void *ctx);

#endif
