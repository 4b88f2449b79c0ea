/* collide.c — relcol-collide: one two-ball collision from a CSV table on stdin, at any c,
 * with any law of the library's table; the command-line face of rc_collide(). Exit status:
 * 0 collided, 2 bad input (one line on stderr), 3 no collision (separating), 1 I/O error. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <stdio_ext.h>
#include <string.h>

#include <cjson/cJSON.h>
#include <gsl/gsl_rng.h>

#include "app.h"

static const char *const prog = "relcol-collide";

enum { EXIT_BAD_INPUT = 2, EXIT_NO_COLLISION = 3 };

/* "a or b": the laws of the table that read an impact angle (rc_law.uses_angle) */
static const char *angle_laws(char *buf, size_t n)
{
    buf[0] = '\0';
    for (size_t i = 0; rc_laws[i]; i++)
        if (rc_laws[i]->uses_angle) {
            size_t l = strlen(buf);
            snprintf(buf + l, n - l, "%s%s", l ? " or --law " : "", rc_laws[i]->name);
        }
    return buf[0] ? buf : "(none)";
}

/* every input error: "relcol-collide: message" and exit status 2 */
#define fail(...) app_fail(prog, EXIT_BAD_INPUT, __VA_ARGS__)

/* --alpha: a number, or 'random' */
struct angle {
    double a;
    int random;
};

typedef struct options {
    double c, eps, azimuth;
    struct angle alpha;
    const rc_law *law;
    double normal[3];
    int n_normal; /* 0: not given */
    int alpha_given, azimuth_given, seed_given, json;
    uint64_t seed;
} options;

static int parse_alpha(const char *val, void *dst, void *opts, char *err)
{
    (void)opts;
    char why[APP_ERR_LEN];
    struct angle *alpha = dst;
    alpha->random = strcmp(val, "random") == 0;
    if (alpha->random || app_parse_double(val, 0, &alpha->a, why) == 0)
        return 0;
    app_errf(err, "%s (radians, or 'random')", why);
    return -1;
}

static void law_lines(FILE *f)
{
    for (size_t i = 0; rc_laws[i]; i++)
        fprintf(f, "                      %-13s %s\n", rc_laws[i]->name, rc_laws[i]->summary);
}

static void alpha_help(FILE *f)
{
    char al[256];
    fprintf(f,
"--law %s only (laws that take an impact angle): impact\n"
"                    angle in radians, |A| < pi/2, between ball 0's ZMF direction of\n"
"                    motion and the ZMF normal (replaces the normal); 'random' draws it\n"
"                    for a uniform impact parameter (rc_impact_angle_draw) from --seed N\n"
"                    (default 1). Must be 0 in 1-D.\n", angle_laws(al, sizeof al));
}

static const char *const formats[] = {"csv", "json", NULL};
#define OFF(field) offsetof(options, field)
static const app_opt opts[] = {
    {"--c", "C|inf", APP_T_DOUBLE_INF, OFF(c), "inf",
     .help = "speed of light, > 0 (default %D: exact classical mechanics)"},
    {"--eps", "E", APP_T_DOUBLE, OFF(eps), "1",
     .help = "restitution in [0, 1] (default %D: elastic)"},
    {"--law", "LAW", APP_T_CUSTOM, OFF(law), "zmf", .parse = app_opt_law,
     .help = "collision law (default %D):", .help_more = law_lines},
    {"--normal", "X[,Y[,Z]]", APP_T_LIST, OFF(normal), .hi = 3, .count = OFF(n_normal),
     .help = "contact normal from ball 0 to ball 1 (any length > 0; missing\n"
             "components are 0, more than the dimension is an error)"},
    {"--alpha", "A", APP_T_CUSTOM, OFF(alpha), .parse = parse_alpha,
     .given = APP_GIVEN(options, alpha_given), .help_more = alpha_help},
    {"--seed", "N", APP_T_U64, OFF(seed), "1", .given = APP_GIVEN(options, seed_given),
     .help = "with --alpha random: the seed of the draw (default %D)"},
    {"--azimuth", "PHI", APP_T_DOUBLE, OFF(azimuth), .given = APP_GIVEN(options, azimuth_given),
     .help = "3-D only, with a numeric --alpha: azimuth of the normal (radians)"},
    {"--format", "csv|json", APP_T_CHOICE, OFF(json), "csv", .choices = formats,
     .what = "format", .help = "output format (default %D)"},
    {NULL},
};

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-collide [--c C|inf] [--eps E] [--law LAW] [--normal X[,Y[,Z]]]\n"
"                      [--alpha A|random [--seed N] [--azimuth PHI]] [--format csv|json]\n"
"\n"
"Collide two balls read from stdin and print their states after the collision.\n"
"\n"
"stdin: CSV with a header line and exactly two data rows (ball 0, ball 1). Columns:\n"
"  m                 rest mass (> 0)\n"
"  vx[,vy[,vz]]      velocity (|v| < c), or\n"
"  px[,py[,pz]]      momentum (any finite value); never both kinds.\n"
"  x[,y[,z]]         optional positions, same dimension: the default normal is then\n"
"                    the unit vector from ball 0 to ball 1 (else +x).\n"
"The dimension (1, 2 or 3) is the number of velocity or momentum columns. Columns may\n"
"come in any order; spaces around fields, CRLF line ends, blank lines and lines\n"
"starting with # are ignored.\n"
"\n"
"options:\n");
    app_opts_help(f, opts, 20);
    fprintf(f,
"\n"
"stdout (csv): header ball,m,px[,py[,pz]],vx[,vy[,vz]],E then two rows, numbers %%.17g.\n"
"  m is the rest mass after the collision (it grows when eps < 1 and c is finite);\n"
"  E is the total energy M c^2 = sqrt(m^2 c^4 + p^2 c^2). With c = inf, where that is\n"
"  infinite, E is the kinetic energy p^2/2m instead.\n"
"stdout (json): {\"c\": C or \"inf\", \"law\", \"eps\", \"dimension\",\n"
"  \"balls\": [{\"ball\", \"m\", \"p\": [...], \"v\": [...], \"E\"}, ...]}\n"
"\n"
"exit status: 0 collided; 2 bad input or option (one line on stderr naming the row,\n"
"column or option and the reason); 3 no collision: the balls are separating (or\n"
"tangent) along the normal, nothing printed on stdout; 1 I/O error.\n");
}

/* The checks between options, after the table's parse: 0, else an exit code. */
static int check_options(void *opts)
{
    const options *o = opts;
    char err[APP_ERR_LEN];
    char f[APP_FMT_LEN];
    if (app_check_c(o->c, err) != 0)
        return fail("--c: %s", err);
    if (!(o->eps >= 0.0 && o->eps <= 1.0))
        return fail("--eps: eps = %s outside [0, 1]", app_fmt(o->eps, f));
    char al[256];
    if (o->alpha_given && !o->law->uses_angle)
        return fail("--alpha: only with --law %s (law is %s)", angle_laws(al, sizeof al),
                    o->law->name);
    if (o->alpha_given && o->n_normal > 0)
        return fail("--alpha: conflicts with --normal (the impact angle fixes the normal)");
    if (o->alpha_given && !o->alpha.random && !(fabs(o->alpha.a) < M_PI / 2))
        return fail("--alpha: |alpha| = %s must be < pi/2 (radians)", app_fmt(fabs(o->alpha.a), f));
    if (o->seed_given && !o->alpha.random)
        return fail("--seed: only with --alpha random");
    if (o->azimuth_given && (!o->alpha_given || o->alpha.random))
        return fail("--azimuth: only with a numeric --alpha (random draws the azimuth too)");
    return 0;
}

static const app_cli cli = {.prog = prog, .tab = opts, .usage = usage,
                            .stray_hint = "input is read from stdin; see --help",
                            .bad = EXIT_BAD_INPUT, .check = check_options};

static cJSON *json_num(double x)
{
    char b[32];
    snprintf(b, sizeof b, "%.17g", x);
    return cJSON_CreateRaw(b);
}

static cJSON *json_vec(rc_vec3 v, int dim)
{
    cJSON *a = cJSON_CreateArray();
    for (int d = 0; a && d < dim; d++)
        cJSON_AddItemToArray(a, json_num(rc_v3_get(v, d)));
    return a;
}

static void print_vec(FILE *out, rc_vec3 v, int dim, const char *sep)
{
    for (int i = 0; i < dim; i++)
        fprintf(out, "%s%.17g", i ? sep : "", rc_v3_get(v, i));
}

int main(int argc, char **argv)
{
    options o;
    memset(&o, 0, sizeof o);
    int st = app_start(&cli, argc, argv, &o);
    if (st >= 0)
        return st;

    char err[APP_ERR_LEN], f[APP_FMT_LEN];
    app_table t;
    if (app_table_read(stdin, &t, err) != 0)
        return fail("stdin: %s", err);
    app_balls b;
    if (app_balls_parse(&t, NULL, 2, &b, err) != 0) {
        app_table_free(&t);
        return fail("%s", err);
    }
    int rc = EXIT_BAD_INPUT;
    const int dim = b.dim;
    rc_particle ball[2];
    rc_vec3 n = rc_v3(1.0, 0.0, 0.0);
    rc_collision_params prm = rc_collision_params_default();
    prm.c = o.c;
    prm.eps = o.eps;

    if (o.n_normal > dim) {
        fail("--normal: %d components, but the input is %d-D", o.n_normal, dim);
        goto out;
    }
    if (o.alpha_given && !o.alpha.random && dim == 1 && o.alpha.a != 0.0) {
        fail("--alpha: alpha = %s, but a 1-D collision is head-on (alpha must be 0)",
             app_fmt(o.alpha.a, f));
        goto out;
    }
    if (o.azimuth_given && dim != 3) {
        fail("--azimuth: only in 3-D (the input is %d-D)", dim);
        goto out;
    }
    if (app_balls_particles(&b, o.c, ball, err) != 0) {
        fail("%s", err);
        goto out;
    }
    if (o.n_normal > 0) {
        n = rc_v3(0.0, 0.0, 0.0);
        for (int i = 0; i < o.n_normal; i++)
            rc_v3_set(&n, i, o.normal[i]);
        if (!(rc_v3_norm_safe(n) > 0.0)) {
            fail("--normal: zero normal");
            goto out;
        }
    } else if (b.has_pos && !o.alpha_given) {
        n = rc_v3_sub(b.x[1], b.x[0]);
        if (!(rc_v3_norm_safe(n) > 0.0)) {
            char rn[48], cols[32];
            fail("%s, column%s %s: zero normal: ball 1 is at the position of ball 0 (line "
                 "%ld)", app_row_name(&t, 1, rn, sizeof rn), dim > 1 ? "s" : "",
                 app_balls_colnames(&b, 1, cols, sizeof cols), t.line[0]);
            goto out;
        }
    }
    if (o.alpha_given) {
        if (o.alpha.random) {
            gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
            if (!r) {
                fail("out of memory");
                rc = 1;
                goto out;
            }
            /* gsl_rng_set takes an unsigned long: fold the 64-bit seed so all bits count */
            gsl_rng_set(r, (unsigned long)(o.seed ^ (o.seed >> 32)));
            const double u1 = gsl_rng_uniform(r), u2 = gsl_rng_uniform(r);
            gsl_rng_free(r);
            rc_impact_angle_draw(dim, u1, u2, &prm.alpha, &prm.azimuth);
        } else {
            prm.alpha = o.alpha.a;
            prm.azimuth = o.azimuth_given ? o.azimuth : 0.0;
        }
    }

    st = rc_collide(o.law, &prm, &ball[0], &ball[1], n);
    if (st == RC_NO_COLLISION) {
        fprintf(stderr, "%s: no collision: the balls are separating (or tangent) along the "
                        "normal n = (", prog);
        print_vec(stderr, rc_v3_scale(1.0 / rc_v3_norm(n), n), dim, ", ");
        fprintf(stderr, ")%s\n", o.alpha_given ? " (from --alpha)" :
                                 (o.n_normal ? " (--normal)" :
                                  (b.has_pos ? " (from the positions)" : " (default +x)")));
        rc = EXIT_NO_COLLISION;
        goto out;
    }
    if (st != RC_OK) {
        fail("%s", rc_strerror(st));
        goto out;
    }

    FILE *out = stdout;
    const double k = rc_inv_c2_of(prm.c);
    double E[2];
    rc_vec3 v[2];
    for (int i = 0; i < 2; i++) {
        v[i] = rc_velocity(ball[i].m, ball[i].p, k);
        E[i] = isinf(o.c) ? rc_kinetic_energy(ball[i].m, ball[i].p, 0.0)
                          : rc_mass_rel(ball[i].m, ball[i].p, k) * o.c * o.c;
    }
    for (int i = 0; i < 2; i++)
        if (!isfinite(E[i]) || !isfinite(ball[i].m) || !rc_v3_isfinite(ball[i].p) ||
            !rc_v3_isfinite(v[i])) {
            fail("the result overflows double precision (momenta or masses too large for c "
                 "= %s)", app_fmt(o.c, f));
            goto out;
        }
    if (o.json) {
        /* printed by cJSON, each ball on a line; numbers raw %.17g (cJSON's own printer
         * keeps 15 digits whenever they read back within an epsilon, not to the bit) */
        cJSON *j = cJSON_CreateObject();
        cJSON_AddItemToObject(j, "c", isinf(o.c) ? cJSON_CreateString("inf") : json_num(o.c));
        cJSON_AddItemToObject(j, "law", cJSON_CreateString(o.law->name));
        cJSON_AddItemToObject(j, "eps", json_num(o.eps));
        cJSON_AddItemToObject(j, "dimension", json_num(dim));
        if (o.alpha_given)
            cJSON_AddItemToObject(j, "alpha", json_num(prm.alpha));
        char *head = j ? cJSON_PrintUnformatted(j) : NULL;
        cJSON_Delete(j);
        char *row[2] = {NULL, NULL};
        for (int i = 0; i < 2; i++) {
            cJSON *b = cJSON_CreateObject();
            cJSON_AddItemToObject(b, "ball", json_num(i));
            cJSON_AddItemToObject(b, "m", json_num(ball[i].m));
            cJSON_AddItemToObject(b, "p", json_vec(ball[i].p, dim));
            cJSON_AddItemToObject(b, "v", json_vec(v[i], dim));
            cJSON_AddItemToObject(b, "E", json_num(E[i]));
            row[i] = b ? cJSON_PrintUnformatted(b) : NULL;
            cJSON_Delete(b);
        }
        size_t hl = head ? strlen(head) : 0;
        if (hl >= 2 && row[0] && row[1]) {
            head[hl - 1] = '\0'; /* the balls go inside the object */
            fprintf(out, "%s,\"balls\":[\n  %s,\n  %s\n]}\n", head, row[0], row[1]);
        }
        free(head);
        free(row[0]);
        free(row[1]);
        if (hl < 2 || !row[0] || !row[1]) {
            rc = app_fail(prog, 1, "out of memory");
            goto out;
        }
    } else {
        static const char *const pn[3] = {"px", "py", "pz"}, *const vn[3] = {"vx", "vy", "vz"};
        fprintf(out, "ball,m");
        for (int i = 0; i < dim; i++)
            fprintf(out, ",%s", pn[i]);
        for (int i = 0; i < dim; i++)
            fprintf(out, ",%s", vn[i]);
        fprintf(out, ",E\n");
        for (int i = 0; i < 2; i++) {
            fprintf(out, "%d,%.17g,", i, ball[i].m);
            print_vec(out, ball[i].p, dim, ",");
            fputc(',', out);
            print_vec(out, v[i], dim, ",");
            fprintf(out, ",%.17g\n", E[i]);
        }
    }
    errno = 0;
    if (fflush(out) != 0 || ferror(out)) {
        fprintf(stderr, "%s: cannot write to standard output: %s\n", prog,
                errno ? strerror(errno) : "a write failed");
        /* (said once: what is left unwritten dropped, so that the exit handler's check of
         * stdout has nothing to fail on again) */
        __fpurge(out);
        clearerr(out);
        rc = 1;
        goto out;
    }
    rc = 0;
out:
    app_balls_free(&b);
    app_table_free(&t);
    return rc;
}
