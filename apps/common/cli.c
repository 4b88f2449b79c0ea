/* cli.c — the apps' command-line plumbing, written once so that every app words its
 * errors alike: "prog: message" on stderr, the "--name value" / "--name=value" option
 * loop, --help, --version, the check of --c, and the lists of names that unknown-name
 * errors show. */
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>

#include "app.h"

static const char *app_prog = "relcol";

/* At exit: stdout flushed and closed, or the failure reported and the exit status made 1
 * (an exit handler can only change it by _exit). */
static void close_stdout(void)
{
    errno = 0;
    const int flushed = fflush(stdout) == 0;
    const int err = errno;
    const int bad = !flushed || ferror(stdout);
    if (fclose(stdout) != 0 || bad) {
        /* (a write that failed earlier left only the error flag, not its reason) */
        fprintf(stderr, "%s: cannot write to standard output: %s\n", app_prog,
                !flushed && err ? strerror(err) : "a write failed");
        _exit(1);
    }
}

void app_init(const char *prog)
{
    gsl_set_error_handler_off();
    app_prog = prog;
    atexit(close_stdout);
    app_interrupt_install();
}

int app_vfail(const char *prog, int code, const char *fmt, va_list ap)
{
    fprintf(stderr, "%s: ", prog);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    return code;
}

int app_fail(const char *prog, int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    app_vfail(prog, code, fmt, ap);
    va_end(ap);
    return code;
}

int app_help(void (*usage)(FILE *))
{
    usage(stdout);
    /* (one line for every app, so that no app's help can leave it out) */
    printf("\n  --version         print the version (relcol %s) and exit\n", rc_version());
    return 0; /* (a failed write is reported at exit: app_init) */
}

int app_version(void)
{
    /* the GNU form "program (package) version", which help2man reads; the library's own
     * version too when it is not the one the app was built with */
    if (strcmp(rc_version(), RELCOL_VERSION) == 0)
        printf("%s (relcol) %s\n", app_prog, RELCOL_VERSION);
    else
        printf("%s (relcol) %s, running with librelcol %s\n", app_prog, RELCOL_VERSION,
               rc_version());
    return 0; /* (a failed write is reported at exit: app_init) */
}

void app_opts_init(app_opts *it, const char *prog, int argc, char **argv,
                   const char *const *valued, const char *const *flags, const char *stray_hint)
{
    memset(it, 0, sizeof *it);
    it->prog = prog;
    it->argc = argc;
    it->argv = argv;
    it->i = 1;
    it->valued = valued;
    it->flags = flags;
    it->stray_hint = stray_hint;
}

static int listed(const char *const *list, const char *s)
{
    int found = 0;
    for (const char *const *k = list; k && *k; k++)
        found |= strcmp(s, *k) == 0;
    return found;
}

/* an app_opts_next error: "prog: message" unless the iterator is quiet */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static int opt_error(const app_opts *it, const char *fmt, ...)
{
    if (!it->quiet) {
        va_list ap;
        va_start(ap, fmt);
        app_vfail(it->prog, 0, fmt, ap);
        va_end(ap);
    }
    return APP_OPT_ERROR;
}

int app_opts_next(app_opts *it, const char **name, const char **value)
{
    *name = NULL;
    *value = NULL;
    if (it->i >= it->argc)
        return APP_OPT_END;
    const char *a = it->argv[it->i++];
    if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0)
        return APP_OPT_HELP;
    if (strcmp(a, "--version") == 0 && it->no_exit)
        return APP_OPT_VERSION;
    if (strcmp(a, "--version") == 0)
        exit(app_version());
    if (listed(it->flags, a)) {
        *name = a;
        return APP_OPT_FLAG;
    }
    if (it->positional && (a[0] != '-' || !a[1])) {
        *value = a;
        return APP_OPT_ARG;
    }
    if (strncmp(a, "--", 2) != 0 && !it->positional)
        return it->option_words ? opt_error(it, "unknown option %s (%s)", a, it->stray_hint)
                                : opt_error(it, "unexpected argument '%s' (%s)", a, it->stray_hint);
    const char *eq = strchr(a, '=');
    size_t len = eq ? (size_t)(eq - a) : strlen(a);
    if (len >= sizeof it->name) /* too long to be any option: show its start only */
        return opt_error(it, "unknown option %.40s (see --help)", a);
    memcpy(it->name, a, len);
    it->name[len] = '\0';
    if (!listed(it->valued, it->name))
        return opt_error(it, "unknown option %s (see --help)", it->name);
    if (eq)
        *value = eq + 1;
    else if (it->i < it->argc)
        *value = it->argv[it->i++];
    else
        return opt_error(it, it->option_words ? "option %s: needs a value" : "%s: missing value",
                         it->name);
    *name = it->name;
    return APP_OPT_VALUE;
}

int app_check_c(double c, char *err)
{
    char f[APP_FMT_LEN];
    double k;
    if (!(c > 0.0)) {
        app_errf(err, "c = %s must be > 0", app_fmt(c, f));
        return -1;
    }
    if (rc_inv_c2(c, &k) != RC_OK) {
        app_errf(err, "c = %s is out of range (1/c^2 under- or overflows; use inf)",
                 app_fmt(c, f));
        return -1;
    }
    return 0;
}

/* "a, b, c" from name(0), name(1), ... up to the first NULL, truncated to n - 1 chars. */
static const char *join_names(char *buf, size_t n, const char *(*name)(size_t))
{
    if (n == 0)
        return buf;
    buf[0] = '\0';
    for (size_t k = 0; name(k); k++) {
        size_t l = strlen(buf);
        snprintf(buf + l, n - l, "%s%s", k ? ", " : "", name(k));
    }
    return buf;
}

static const char *law_name(size_t k)
{
    return rc_laws[k] ? rc_laws[k]->name : NULL;
}

static const char *toi_frame_name(size_t k)
{
    return rc_toi_frames[k] ? rc_toi_frames[k]->name : NULL;
}

const char *app_law_list(char *buf, size_t n)
{
    return join_names(buf, n, law_name);
}

const char *app_toi_frame_list(char *buf, size_t n)
{
    return join_names(buf, n, toi_frame_name);
}
