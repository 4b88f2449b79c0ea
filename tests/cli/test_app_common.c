/* test_app_common.c — the apps' shared plumbing (apps/common) on its own: strict number
 * parsing, the CSV reader's tolerances and messages, ball rows, the atomic writer, the
 * log-log slope fit and the option table's parse (ranges, wording, a rank that keeps
 * quiet), each with a case that must be rejected. */
#include <dirent.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rc_test.h"
#include "app.h"

static void test_parse_double(void)
{
    char err[APP_ERR_LEN];
    double x = 0;
    ENSURE(app_parse_double(" 1.5 ", 0, &x, err) == 0 && x == 1.5);
    ENSURE(app_parse_double("-2e-3", 0, &x, err) == 0 && x == -2e-3);
    ENSURE(app_parse_double("inf", 1, &x, err) == 0 && isinf(x) && x > 0);
    ENSURE(app_parse_double("+Infinity", 1, &x, err) == 0 && isinf(x));
    ENSURE(app_parse_double("inf", 0, &x, err) != 0 && strstr(err, "not finite"));
    ENSURE(app_parse_double("-inf", 1, &x, err) != 0);
    ENSURE(app_parse_double("nan", 1, &x, err) != 0 && strstr(err, "not finite"));
    ENSURE(app_parse_double("1e999", 0, &x, err) != 0 && strstr(err, "not finite"));
    ENSURE(app_parse_double("1.5x", 0, &x, err) != 0 && strstr(err, "not a number: '1.5x'"));
    ENSURE(app_parse_double("1 2", 0, &x, err) != 0);
    ENSURE(app_parse_double("", 0, &x, err) != 0 && strstr(err, "empty"));
    ENSURE(app_parse_double("   ", 0, &x, err) != 0);
    long l;
    ENSURE(app_parse_long("41", 3, 100, &l, err) == 0 && l == 41);
    ENSURE(app_parse_long("2", 3, 100, &l, err) != 0);
    ENSURE(app_parse_long("4.0", 3, 100, &l, err) != 0);
    uint64_t u;
    ENSURE(app_parse_u64("18446744073709551615", &u, err) == 0 && u == UINT64_MAX);
    ENSURE(app_parse_u64("18446744073709551616", &u, err) != 0);
    ENSURE(app_parse_u64("-1", &u, err) != 0);
    double v[3];
    int n;
    ENSURE(app_parse_list("1, 0.5", v, 3, &n, err) == 0 && n == 2 && v[1] == 0.5);
    ENSURE(app_parse_list("1,,2", v, 3, &n, err) != 0 && strstr(err, "component 2"));
    ENSURE(app_parse_list("1,2,3,4", v, 3, &n, err) != 0);
}

static void test_fmt(void)
{
    char b[APP_FMT_LEN];
    ENSURE(strcmp(app_fmt(0.6, b), "0.6") == 0);
    ENSURE(strcmp(app_fmt(10, b), "10") == 0);
    ENSURE(strtod(app_fmt(1.0 / 3.0, b), NULL) == 1.0 / 3.0); /* round trip */
    ENSURE(strcmp(app_fmt(INFINITY, b), "inf") == 0);
}

static int read_str(const char *s, app_table *t, char *err)
{
    FILE *f = fmemopen((void *)s, strlen(s), "r");
    int rc = app_table_read(f, t, err);
    fclose(f);
    return rc;
}

static void test_table(void)
{
    char err[APP_ERR_LEN];
    app_table t;
    /* CRLF, blanks around fields, a comment, trailing blank lines */
    ENSURE(read_str("# c\r\n m , vx \r\n1, 0.5\r\n\r\n 2 ,-1\r\n\r\n\n", &t, err) == 0);
    ENSURE(t.ncols == 2 && t.nrows == 2 && t.header_line == 2);
    ENSURE(app_table_col(&t, "vx") == 1 && app_table_col(&t, "vy") == -1);
    ENSURE(strcmp(app_table_cell(&t, 1, 0), "2") == 0 && t.line[1] == 5);
    double x;
    ENSURE(app_table_double(&t, 1, 1, "ball 1", 0, &x, err) == 0 && x == -1);
    app_table_free(&t);
    ENSURE(read_str("m,vx\n1,abc\n", &t, err) == 0);
    ENSURE(app_table_double(&t, 0, 1, "ball 0", 0, &x, err) != 0 &&
           strcmp(err, "line 2 (ball 0), column vx: not a number: 'abc'") == 0);
    app_table_free(&t);
    ENSURE(read_str("m,vx\n1\n", &t, err) != 0 && strstr(err, "line 2: 1 field"));
    ENSURE(read_str("m,m\n1,1\n", &t, err) != 0 && strstr(err, "repeated"));
    ENSURE(read_str("m,,vx\n", &t, err) != 0 && strstr(err, "empty name"));
    ENSURE(read_str("\n\n", &t, err) != 0 && strstr(err, "empty input"));
    /* a spreadsheet's export: byte order mark, CRLF, quoted header and fields (a comma,
     * a doubled quote, a line break inside quotes, blanks outside them) */
    ENSURE(read_str("\xEF\xBB\xBF\"m\",\"vx\",\"name\"\r\n\"1\", -0.5 ,\"a, \"\"b\"\"\"\r\n"
                    "2,\"0.25\" ,\"two\r\nlines\"\r\n", &t, err) == 0);
    ENSURE(t.ncols == 3 && t.nrows == 2 && app_table_col(&t, "m") == 0 &&
           app_table_col(&t, "name") == 2);
    ENSURE(strcmp(app_table_cell(&t, 0, 2), "a, \"b\"") == 0 &&
           strcmp(app_table_cell(&t, 1, 2), "two\nlines") == 0 && t.line[1] == 3);
    ENSURE(app_table_double(&t, 1, 1, "ball 1", 0, &x, err) == 0 && x == 0.25);
    ENSURE(app_table_double(&t, 0, 1, "ball 0", 0, &x, err) == 0 && x == -0.5);
    app_table_free(&t);
    ENSURE(read_str("m,vx\n1,\"0.5\n", &t, err) != 0 &&
           strcmp(err, "line 2: a quoted field is not closed (a '\"' missing)") == 0);
    ENSURE(read_str("m,vx\n1,\"0.5\"x\n", &t, err) != 0 &&
           strcmp(err, "line 2: field 2: text after its closing quote") == 0);
    ENSURE(read_str("\"m\",\"m\"\n1,1\n", &t, err) != 0 && strstr(err, "repeated"));
}

static void test_balls(void)
{
    char err[APP_ERR_LEN];
    app_table t;
    app_balls b;
    static const char *const extra[] = {"r", NULL};
    ENSURE(read_str("m,vx,vy,x,y,r\n1,0.6,0,0,0,1\n2,0,0,1,1,1\n", &t, err) == 0);
    ENSURE(app_balls_parse(&t, extra, 2, &b, err) == 0);
    ENSURE(b.dim == 2 && b.has_pos && !b.momentum && b.n == 2 && b.x[1].y == 1.0);
    rc_particle p[2];
    ENSURE(app_balls_particles(&b, 1.0, p, err) == 0);
    ENSURE_REL(p[0].p.x, 0.75, 1e-15); /* m gamma v = 1.25 * 0.6 */
    ENSURE(app_balls_particles(&b, 0.5, p, err) != 0 &&
           strcmp(err, "line 2 (ball 0), columns vx,vy: |v| = 0.6 >= c = 0.5") == 0);
    app_balls_free(&b);
    ENSURE(app_balls_parse(&t, NULL, 2, &b, err) != 0 && strstr(err, "column r: unknown"));
    ENSURE(app_balls_parse(&t, extra, 3, &b, err) != 0 && strstr(err, "found 2"));
    app_table_free(&t);
    ENSURE(read_str("m,py\n1,0\n1,0\n", &t, err) == 0);
    ENSURE(app_balls_parse(&t, NULL, 2, &b, err) != 0 && strstr(err, "py: present without px"));
    app_table_free(&t);
}

static int count_entries(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    if (d)
        closedir(d);
    return n;
}

static void test_atomic(void)
{
    char err[APP_ERR_LEN], dir[] = "/tmp/relcol-app-test-XXXXXX";
    ENSURE(mkdtemp(dir) != NULL);
    char *sub = app_path_join(dir, "a/b");
    ENSURE(app_mkdir_p(sub, err) == 0 && app_mkdir_p(sub, err) == 0);
    char *path = app_path_join(sub, "f.csv");
    app_atomic a;
    ENSURE(app_atomic_open(&a, path, err) == 0);
    fputs("old\n", a.f);
    ENSURE(app_atomic_commit(&a, err) == 0);
    /* an aborted rewrite leaves the old content and no temporary */
    ENSURE(app_atomic_open(&a, path, err) == 0);
    fputs("half", a.f);
    ENSURE(count_entries(sub) == 2); /* f.csv and the temporary */
    app_atomic_abort(&a);
    ENSURE(count_entries(sub) == 1);
    char buf[16] = "";
    FILE *f = fopen(path, "r");
    ENSURE(f && fgets(buf, sizeof buf, f) && strcmp(buf, "old\n") == 0);
    if (f)
        fclose(f);
    /* a file where a folder should be */
    ENSURE(app_mkdir_p(path, err) != 0 && strstr(err, "not a folder"));
    unlink(path);
    rmdir(sub);
    char *a_dir = app_path_join(dir, "a");
    rmdir(a_dir);
    rmdir(dir);
    free(a_dir);
    free(path);
    free(sub);
}

static void test_slope(void)
{
    double x[20], y[20], s = 0, sd = 1;
    size_t used;
    for (int i = 0; i < 20; i++) {
        x[i] = pow(10.0, 1 + 0.25 * i);
        y[i] = 3.0 * pow(x[i], -2.0);
    }
    y[5] = NAN; /* skipped, like eps = 1 rows */
    ENSURE(app_loglog_slope(x, y, 20, &s, NULL, &sd, &used) == 0 && used == 19);
    /* an exact power law: the fit is exact up to rounding in log10 (~1e-15 per point) */
    ENSURE_CLOSE(s, -2.0, 1e-12, 1.0);
    ENSURE(sd < 1e-12);
    ENSURE(app_loglog_slope(x, y, 2, &s, NULL, NULL, &used) != 0);
}

/* ---- the option table (opttab.c) ---------------------------------------------------- */

typedef struct topts {
    double x, l[4];
    int nl, flag;
} topts;

static const app_opt ttab[] = {
    {"--x", "X", APP_T_DOUBLE, offsetof(topts, x), "1", .valid = app_valid_positive,
     .help = "a positive number"},
    {"--l", "LIST", APP_T_LIST, offsetof(topts, l), "0.1", .hi = 4, .count = offsetof(topts, nl),
     .valid = app_valid_open_closed, .min = 0.0, .max = 0.7, .help = "numbers in (0, 0.7]"},
    {"--flag", NULL, APP_T_FLAG, offsetof(topts, flag), .help = "a flag"},
    {NULL},
};

static int quiet_rank(void) { return 0; }

/* app_opts_parse on args (NULL-ended, after the program name) with stdout and stderr
 * caught into out and err (each 1 KiB): its status */
static int tparse(const app_cli *cli, topts *o, const char *const *args, char *out, char *err)
{
    char *argv[16] = {"t"};
    int argc = 1;
    while (args[argc - 1] && argc < 15) {
        argv[argc] = (char *)args[argc - 1];
        argc++;
    }
    memset(o, 0, sizeof *o);
    char e[APP_ERR_LEN];
    app_opts_defaults(cli->tab, o, e);
    fflush(stdout);
    fflush(stderr);
    FILE *fo = tmpfile(), *fe = tmpfile();
    const int so = dup(1), se = dup(2);
    dup2(fileno(fo), 1);
    dup2(fileno(fe), 2);
    const int st = app_opts_parse(cli, argc, argv, o);
    fflush(stdout);
    fflush(stderr);
    dup2(so, 1);
    dup2(se, 2);
    close(so);
    close(se);
    FILE *f[2] = {fo, fe};
    char *b[2] = {out, err};
    for (int k = 0; k < 2; k++) {
        rewind(f[k]);
        const size_t n = fread(b[k], 1, 1023, f[k]);
        b[k][n] = '\0';
        fclose(f[k]);
    }
    return st;
}

static void test_opttab(void)
{
    app_cli cli = {.prog = "t", .tab = ttab, .stray_hint = "see --help", .bad = 7};
    topts o;
    char out[1024], err[1024];
    ENSURE(tparse(&cli, &o, (const char *[]){"--x", "2", "--l=0.2,0.7", "--flag", NULL}, out,
                  err) == 0);
    ENSURE(o.x == 2.0 && o.nl == 2 && o.l[1] == 0.7 && o.flag == 1 && !err[0]);
    /* each row's range as it is given, the first bad option's error (argv order) */
    ENSURE(tparse(&cli, &o, (const char *[]){"--x", "0", "--l", "0.9", NULL}, out, err) == 7);
    ENSURE_MSG(strcmp(err, "t: --x: 0 must be > 0\n") == 0, "%s", err);
    ENSURE(tparse(&cli, &o, (const char *[]){"--l", "0.1,0.9", "--x", "0", NULL}, out, err) == 7);
    ENSURE_MSG(strcmp(err, "t: --l: 0.9 outside (0, 0.7]\n") == 0, "%s", err);
    ENSURE(tparse(&cli, &o, (const char *[]){"--l", "0", NULL}, out, err) == 7);
    ENSURE_MSG(strcmp(err, "t: --l: 0 outside (0, 0.7]\n") == 0, "%s", err);
    ENSURE(tparse(&cli, &o, (const char *[]){"--x", NULL}, out, err) == 7);
    ENSURE_MSG(strcmp(err, "t: --x: missing value\n") == 0, "%s", err);
    /* --version and --list-options print and come back (no exit) */
    ENSURE(tparse(&cli, &o, (const char *[]){"--version", NULL}, out, err) == APP_PARSE_DONE);
    ENSURE_MSG(strstr(out, "(relcol) ") != NULL, "%s", out);
    ENSURE(tparse(&cli, &o, (const char *[]){"--list-options", NULL}, out, err) == APP_PARSE_DONE);
    ENSURE_MSG(strcmp(out, "--x\n--l\n--flag\n--help\n--version\n") == 0, "%s", out);
    ENSURE(tparse(&cli, &o, (const char *[]){"--help", NULL}, out, err) == APP_PARSE_HELP);
    /* relcol-sim's wording */
    cli.option_words = 1;
    ENSURE(tparse(&cli, &o, (const char *[]){"--x", NULL}, out, err) == 7);
    ENSURE_MSG(strcmp(err, "t: option --x: needs a value\n") == 0, "%s", err);
    ENSURE(tparse(&cli, &o, (const char *[]){"--x", "-1", NULL}, out, err) == 7);
    ENSURE_MSG(strcmp(err, "t: option --x: -1 must be > 0\n") == 0, "%s", err);
    ENSURE(tparse(&cli, &o, (const char *[]){"stray", NULL}, out, err) == 7);
    ENSURE_MSG(strcmp(err, "t: unknown option stray (see --help)\n") == 0, "%s", err);
    /* a rank that does not speak: the same statuses, nothing printed */
    cli.speaks = quiet_rank;
    const char *const *quiet_cases[] = {
        (const char *[]){"--x", "0", NULL}, (const char *[]){"--bogus", NULL},
        (const char *[]){"--x", NULL}, (const char *[]){"stray", NULL},
        (const char *[]){"--version", NULL}, (const char *[]){"--list-options", NULL}};
    const int want[] = {7, 7, 7, 7, APP_PARSE_DONE, APP_PARSE_DONE};
    for (int k = 0; k < 6; k++) {
        ENSURE_MSG(tparse(&cli, &o, quiet_cases[k], out, err) == want[k], "case %d", k);
        ENSURE_MSG(!out[0] && !err[0], "case %d printed '%s' '%s'", k, out, err);
    }
}

int main(void)
{
    RUN_TEST(test_parse_double);
    RUN_TEST(test_fmt);
    RUN_TEST(test_table);
    RUN_TEST(test_balls);
    RUN_TEST(test_atomic);
    RUN_TEST(test_slope);
    RUN_TEST(test_opttab);
    RC_TEST_MAIN_END();
}
