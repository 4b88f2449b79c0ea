/* opttab.c — the apps' option tables: each option once (name, type, destination, default,
 * range, help), one parser walking the table through app_opts_next, and the options
 * section of --help printed from the same table, so that help and parser cannot drift. */
#include <stdlib.h>
#include <string.h>

#include "app.h"

/* the most options a table holds (app_opts_parse refuses a longer one) */
#define MAX_OPTS 64

static const app_opt *find(const app_opt *tab, const char *name)
{
    for (const app_opt *o = tab; o->name; o++)
        if (strcmp(o->name, name) == 0)
            return o;
    return NULL;
}

/* "a, b or c" from a NULL-terminated list */
static void or_list(const char *const *names, char *buf, size_t n)
{
    buf[0] = '\0';
    for (size_t k = 0; names[k]; k++) {
        size_t l = strlen(buf);
        snprintf(buf + l, n - l, "%s%s", k == 0 ? "" : names[k + 1] ? ", " : " or ", names[k]);
    }
}

/* Parse val into the option's destination; -1 with the reason in err (without the name). */
static int set_value(const app_opt *o, const char *val, void *opts, char *err)
{
    char *dst = (char *)opts + o->off;
    long l;
    switch (o->type) {
    case APP_T_DOUBLE:
    case APP_T_DOUBLE_INF:
        return app_parse_double(val, o->type == APP_T_DOUBLE_INF, (double *)dst, err);
    case APP_T_INT:
        if (app_parse_long(val, (long)o->lo, (long)o->hi, &l, err) != 0)
            return -1;
        *(int *)dst = (int)l;
        return 0;
    case APP_T_LONG:
        return app_parse_long(val, (long)o->lo, (long)o->hi, (long *)dst, err);
    case APP_T_U64:
        return app_parse_u64(val, (uint64_t *)dst, err);
    case APP_T_STRING:
        *(const char **)dst = val;
        return 0;
    case APP_T_CHOICE:
        for (int k = 0; o->choices[k]; k++)
            if (strcmp(val, o->choices[k]) == 0) {
                *(int *)dst = k;
                return 0;
            }
        char list[256];
        or_list(o->choices, list, sizeof list);
        app_errf(err, "unknown %s '%s' (%s)", o->what, val, list);
        return -1;
    case APP_T_LIST:
        return app_parse_list(val, (double *)dst, (int)o->hi, (int *)((char *)opts + o->count),
                              err);
    case APP_T_CUSTOM:
        return o->parse(val, dst, opts, err);
    case APP_T_FLAG:
        break;
    }
    return 0;
}

int app_opts_defaults(const app_opt *tab, void *opts, char *err)
{
    for (const app_opt *o = tab; o->name; o++)
        if (o->deflt && o->type != APP_T_FLAG &&
            set_value(o, o->deflt, opts, err) != 0)
            return -1;
    return 0;
}

static void list_options(const app_opt *tab)
{
    for (const app_opt *o = tab; o->name; o++)
        printf("%s\n", o->name);
    printf("--help\n--version\n");
}

static int speaks(const app_cli *cli) { return !cli->speaks || cli->speaks(); }

int app_opts_parse(const app_cli *cli, int argc, char **argv, void *opts)
{
    const char *valued[MAX_OPTS + 1], *flags[MAX_OPTS + 2];
    int nv = 0, nf = 0;
    for (const app_opt *o = cli->tab; o->name; o++) {
        if (nv == MAX_OPTS || nf == MAX_OPTS)
            return app_fail(cli->prog, 1, "internal: more than %d options in the table",
                            MAX_OPTS);
        if (o->type == APP_T_FLAG)
            flags[nf++] = o->name;
        else
            valued[nv++] = o->name;
    }
    flags[nf++] = "--list-options"; /* (hidden: the test that help and table agree) */
    valued[nv] = flags[nf] = NULL;
    char err[APP_ERR_LEN];
    app_opts it;
    app_opts_init(&it, cli->prog, argc, argv, valued, flags, cli->stray_hint);
    it.positional = cli->arg != NULL;
    it.option_words = cli->option_words;
    it.quiet = !speaks(cli);
    it.no_exit = 1;
    const char *name, *val;
    for (int kind; (kind = app_opts_next(&it, &name, &val)) != APP_OPT_END;) {
        if (kind == APP_OPT_HELP)
            return APP_PARSE_HELP;
        if (kind == APP_OPT_ERROR)
            return cli->bad;
        if (kind == APP_OPT_VERSION) {
            if (!it.quiet)
                app_version();
            return APP_PARSE_DONE;
        }
        int st;
        if (kind == APP_OPT_ARG && (st = cli->arg(val, opts)) != 0)
            return st;
        if (kind == APP_OPT_ARG)
            continue;
        if (strcmp(name, "--list-options") == 0) {
            if (!it.quiet)
                list_options(cli->tab);
            return APP_PARSE_DONE;
        }
        const app_opt *o = find(cli->tab, name);
        if (o->given)
            *(int *)((char *)opts + o->given - 1) = 1;
        if (o->type == APP_T_FLAG)
            *(int *)((char *)opts + o->off) = 1;
        else if (set_value(o, val, opts, err) != 0 || (o->valid && o->valid(o, opts, err) != 0))
            return it.quiet ? cli->bad
                            : app_fail(cli->prog, cli->bad, "%s%s: %s",
                                       cli->option_words ? "option " : "", name, err);
    }
    return 0;
}

void app_opts_help(FILE *f, const app_opt *tab, int col)
{
    for (const app_opt *o = tab; o->name; o++) {
        char head[128];
        snprintf(head, sizeof head, "%s%s%s", o->name, o->meta ? " " : "", o->meta ? o->meta : "");
        /* (two blanks at least after a long head: help2man ends the option at them) */
        fprintf(f, "  %-*s %s", col - 3, head, (int)strlen(head) >= col - 3 ? " " : "");
        if (!o->help) { /* (help_more words the whole entry) */
            if (o->help_more)
                o->help_more(f);
            else
                fputc('\n', f);
            continue;
        }
        /* the help's lines, continuation lines under the first; "%D" is the default */
        for (const char *s = o->help; s && *s; s++) {
            if (s[0] == '%' && s[1] == 'D' && o->deflt) {
                fputs(o->deflt, f);
                s++;
            } else {
                fputc(*s, f);
                if (*s == '\n')
                    fprintf(f, "%*s", col, "");
            }
        }
        fputc('\n', f);
        if (o->help_more)
            o->help_more(f);
    }
    /* (every table's last line, so that no app's help can leave it out) */
    fprintf(f, "  %-*s this text\n", col - 3, "--help");
}

int app_start(const app_cli *cli, int argc, char **argv, void *opts)
{
    app_init(cli->prog);
    char err[APP_ERR_LEN];
    if (app_opts_defaults(cli->tab, opts, err) != 0)
        return app_fail(cli->prog, 1, "internal: a default of the option table: %s", err);
    int st = app_opts_parse(cli, argc, argv, opts);
    if (st == APP_PARSE_HELP)
        return speaks(cli) ? app_help(cli->usage) : 0;
    if (st == APP_PARSE_DONE)
        return 0;
    if (st == 0 && cli->check)
        st = cli->check(opts);
    return st == 0 ? -1 : st;
}

int app_opt_law(const char *val, void *dst, void *opts, char *err)
{
    (void)opts;
    if ((*(const rc_law **)dst = rc_law_find(val)))
        return 0;
    char list[256];
    app_errf(err, "unknown law '%s' (known: %s)", val, app_law_list(list, sizeof list));
    return -1;
}

int app_opt_toi_frame(const char *val, void *dst, void *opts, char *err)
{
    (void)opts;
    if ((*(const rc_toi_frame **)dst = rc_toi_frame_find(val)))
        return 0;
    char list[256];
    app_errf(err, "unknown frame '%s' (known: %s)", val, app_toi_frame_list(list, sizeof list));
    return -1;
}

int app_opt_dir(const char *val, void *dst, void *opts, char *err)
{
    (void)opts;
    if (!*val) {
        app_errf(err, "empty folder name");
        return -1;
    }
    *(const char **)dst = val;
    return 0;
}

/* the numbers a row's destination holds: one double, or an APP_T_LIST's count of them */
static const double *numbers(const app_opt *o, const void *opts, int *n)
{
    *n = o->type == APP_T_LIST ? *(const int *)((const char *)opts + o->count) : 1;
    return (const double *)((const char *)opts + o->off);
}

/* every number of the row > 0 (or >= 0): "-1 must be > 0" */
static int above_zero(const app_opt *o, const void *opts, int or_zero, char *err)
{
    int n;
    const double *x = numbers(o, opts, &n);
    char f[APP_FMT_LEN];
    for (int k = 0; k < n; k++)
        if (!(x[k] > 0.0 || (or_zero && x[k] == 0.0))) {
            app_errf(err, "%s must be %s 0", app_fmt(x[k], f), or_zero ? ">=" : ">");
            return -1;
        }
    return 0;
}

int app_valid_positive(const app_opt *o, const void *opts, char *err)
{
    return above_zero(o, opts, 0, err);
}

int app_valid_nonneg(const app_opt *o, const void *opts, char *err)
{
    return above_zero(o, opts, 1, err);
}

int app_valid_open_closed(const app_opt *o, const void *opts, char *err)
{
    int n;
    const double *x = numbers(o, opts, &n);
    char f[APP_FMT_LEN];
    for (int k = 0; k < n; k++)
        if (!(x[k] > o->min && x[k] <= o->max)) {
            app_errf(err, "%s outside (%g, %g]", app_fmt(x[k], f), o->min, o->max);
            return -1;
        }
    return 0;
}

int app_valid_c(const app_opt *o, const void *opts, char *err)
{
    int n;
    return app_check_c(*numbers(o, opts, &n), err);
}
