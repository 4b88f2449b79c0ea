/* toi.c — relcol-toi: the first contact of two Lorentz-contracted balls (or of one ball
 * with the walls of a box) from a CSV table on stdin; the command-line face of rc_toi()
 * and rc_toi_box(). Exit status: 0 contact or "miss", 2 bad input or overlapping
 * shapes (one line on stderr), 1 I/O error. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "table_extra.h"

static const char *const prog = "relcol-toi";

enum { EXIT_BAD_INPUT = 2 };

/* every input error: "relcol-toi: message" and exit status 2 */
#define fail(...) app_fail(prog, EXIT_BAD_INPUT, __VA_ARGS__)

typedef struct options {
    double c;
    const rc_toi_frame *frame;
    double wall[6];
    int n_wall; /* 0: no --wall */
} options;

static void frame_lines(FILE *f)
{
    for (size_t i = 0; rc_toi_frames[i]; i++)
        fprintf(f, "                      %-9s %s\n", rc_toi_frames[i]->name,
                rc_toi_frames[i]->summary);
}

#define OFF(field) offsetof(options, field)
static const app_opt opts[] = {
    {"--c", "C|inf", APP_T_DOUBLE_INF, OFF(c), "inf",
     .help = "speed of light, > 0 (default %D: no contraction)"},
    /* (table: the default of every app) */
    {"--frame", "FRAME", APP_T_CUSTOM, OFF(frame), "table", .parse = app_opt_toi_frame,
     .help = "where contact is decided (default %D):", .help_more = frame_lines},
    {"--wall", "X0,X1[,Y0,Y1[,Z0,Z1]]", APP_T_LIST, OFF(wall), .hi = 6, .count = OFF(n_wall),
     .help = "box walls x = X0, x = X1, ... (X0 < X1); axes not\n"
             "given are open. The ball must start inside. Walls see the\n"
             "contracted ball in frames table and zmf (a wall's rest frame is\n"
             "the table and the ball-wall ZMF), the sphere in frame sphere."},
    {NULL},
};

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-toi [--c C|inf] [--frame FRAME] [--wall X0,X1[,Y0,Y1[,Z0,Z1]]]\n"
"\n"
"Time, point and normal of the first contact of two balls of rest radius r that move\n"
"uniformly and are Lorentz-contracted along their velocities (semi-axis r/gamma along\n"
"v, r across), or of one ball with the walls of a box (--wall).\n"
"\n"
"stdin: CSV with a header line and exactly two data rows (ball 0, ball 1), or one row\n"
"with --wall. Columns:\n"
"  r                 rest radius (> 0)\n"
"  x[,y[,z]]         centre at time 0\n"
"  vx[,vy[,vz]]      velocity (|v| < c), or\n"
"  px[,py[,pz]]      momentum, with m the rest mass (> 0); m is optional with\n"
"                    velocities (the contact geometry depends on v only).\n"
"The dimension (1, 2 or 3) is the number of velocity or momentum columns; positions\n"
"must have as many. Columns may come in any order; spaces, CRLF, blank lines and lines\n"
"starting with # are ignored.\n"
"\n"
"options:\n");
    app_opts_help(f, opts, 20);
    fprintf(f,
"\n"
"stdout: header t,cx[,cy[,cz]],nx[,ny[,nz]] (with --wall: plus side, one of x0 x1 y0 y1\n"
"  z0 z1) and one row, numbers %%.17g: the table-frame time and point of the contact\n"
"  event and the unit normal from ball 0 to ball 1 (into the wall). With frame zmf the\n"
"  event is found in the pair's ZMF and boosted back, so t may precede 0 slightly\n"
"  (relativity of simultaneity; the centres' contact events are in the future). If\n"
"  there is no contact in the future, stdout is the single line: miss. Touching but\n"
"  separating, and grazing (tangent) contacts, are misses.\n"
"\n"
"exit status: 0 contact or miss; 2 bad input or option, or shapes overlapping at time\n"
"0 (one line on stderr naming the row, column or option and the reason); 1 I/O error.\n");
}

/* The checks after the table's parse: 0, else an exit code. */
static int check_options(void *opts)
{
    const options *o = opts;
    char err[APP_ERR_LEN], f1[APP_FMT_LEN], f2[APP_FMT_LEN];
    if (o->n_wall % 2 != 0)
        return fail("--wall: %d numbers; give pairs X0,X1[,Y0,Y1[,Z0,Z1]]", o->n_wall);
    for (int k = 0; k < o->n_wall; k += 2)
        if (!(o->wall[k] < o->wall[k + 1]))
            return fail("--wall: %c0 = %s must be < %c1 = %s", 'x' + k / 2,
                        app_fmt(o->wall[k], f1), 'x' + k / 2, app_fmt(o->wall[k + 1], f2));
    if (app_check_c(o->c, err) != 0)
        return fail("--c: %s", err);
    return 0;
}

static const app_cli cli = {.prog = prog, .tab = opts, .usage = usage,
                            .stray_hint = "input is read from stdin; see --help",
                            .bad = EXIT_BAD_INPUT, .check = check_options};

static void print_row(int dim, double t, rc_vec3 x, rc_vec3 n)
{
    printf("%.17g", t);
    for (int i = 0; i < dim; i++)
        printf(",%.17g", rc_v3_get(x, i));
    for (int i = 0; i < dim; i++)
        printf(",%.17g", rc_v3_get(n, i));
}

static void print_header(int dim, int wall)
{
    static const char *const cn[3] = {"cx", "cy", "cz"}, *const nn[3] = {"nx", "ny", "nz"};
    printf("t");
    for (int i = 0; i < dim; i++)
        printf(",%s", cn[i]);
    for (int i = 0; i < dim; i++)
        printf(",%s", nn[i]);
    printf("%s\n", wall ? ",side" : "");
}

int main(int argc, char **argv)
{
    options o;
    memset(&o, 0, sizeof o);
    int st = app_start(&cli, argc, argv, &o);
    if (st >= 0)
        return st;

    char err[APP_ERR_LEN], f[APP_FMT_LEN], rn[48];
    app_table t;
    if (app_table_read(stdin, &t, err) != 0)
        return fail("stdin: %s", err);
    int rc = EXIT_BAD_INPUT;
    app_balls b;
    memset(&b, 0, sizeof b);
    rc_toi_workspace *ws = NULL;
    const int wall = o.n_wall > 0;
    /* m only matters through v = p/M: optional with velocity input */
    if (app_table_col(&t, "m") < 0) {
        if (app_table_col(&t, "px") >= 0) {
            fail("line %ld (header), column m: missing column (rest mass, needed with "
                 "momentum input)", t.header_line);
            app_table_free(&t);
            return EXIT_BAD_INPUT;
        }
        if (app_table_add_const_col(&t, "m", "1", err) != 0) {
            app_table_free(&t);
            return fail("%s", err);
        }
    }
    static const char *const extra[] = {"r", NULL};
    if (app_balls_parse(&t, extra, wall ? 1 : 2, &b, err) != 0) {
        app_table_free(&t);
        return fail("%s", err);
    }
    const int dim = b.dim;
    const int cr = app_table_col(&t, "r");
    if (cr < 0) {
        fail("line %ld (header), column r: missing column (rest radius)", t.header_line);
        goto out;
    }
    if (!b.has_pos) {
        fail("line %ld (header), column x: missing column (positions x[,y[,z]] of the "
             "centres at time 0)", t.header_line);
        goto out;
    }
    if (o.n_wall / 2 > dim) {
        fail("--wall: %d axes, but the input is %d-D", o.n_wall / 2, dim);
        goto out;
    }
    rc_particle pt[2];
    if (app_balls_particles(&b, o.c, pt, err) != 0) {
        fail("%s", err);
        goto out;
    }
    rc_toi_ball ball[2];
    for (size_t i = 0; i < b.n; i++) {
        char label[32];
        snprintf(label, sizeof label, "ball %zu", i);
        if (app_table_double(&t, i, cr, label, 0, &ball[i].r, err) != 0) {
            fail("%s", err);
            goto out;
        }
        if (!(ball[i].r > 0.0)) {
            fail("%s, column r: r = %s must be > 0", app_row_name(&t, i, rn, sizeof rn),
                 app_fmt(ball[i].r, f));
            goto out;
        }
        if (app_table_scaled(&t, i, cr, label, 1, &ball[i].r, err) != 0) {
            fail("%s", err);
            goto out;
        }
        ball[i].x = b.x[i];
        ball[i].m = pt[i].m;
        ball[i].p = pt[i].p;
    }
    rc_toi_params prm = rc_toi_params_default();
    prm.c = o.c;

    if (wall) {
        /* the first n_wall/2 axes are walled; the others are open */
        double lo[3], hi[3];
        for (int i = 0; i < o.n_wall / 2; i++) {
            lo[i] = o.wall[2 * i];
            hi[i] = o.wall[2 * i + 1];
        }
        double tt;
        int side;
        rc_vec3 n, x;
        st = rc_toi_box(&prm, o.frame->wall_contracted, &ball[0], o.n_wall / 2, lo, hi,
                        &tt, &side, &n, &x);
        if (st == RC_EOVERLAP) {
            fail("%s: the ball sticks out of the box at time 0 (its %s reaches past a "
                 "wall)", app_row_name(&t, 0, rn, sizeof rn),
                 o.frame->wall_contracted && !isinf(o.c) ? "contracted shape" : "sphere");
            goto out;
        }
        if (st == RC_MISS) {
            printf("miss\n");
            rc = 0;
            goto out;
        }
        if (st != RC_OK) {
            fail("%s", rc_strerror(st));
            goto out;
        }
        static const char *const sides[6] = {"x0", "x1", "y0", "y1", "z0", "z1"};
        print_header(dim, 1);
        print_row(dim, tt, x, n);
        printf(",%s\n", sides[side]);
        rc = 0;
        goto out;
    }

    if (rc_toi_workspace_create(&ws) != RC_OK) {
        fail("out of memory");
        rc = 1;
        goto out;
    }
    rc_toi_contact c;
    st = rc_toi(o.frame, &prm, &ball[0], &ball[1], ws, &c);
    if (st == RC_EOVERLAP) {
        fail("lines %ld and %ld (balls 0 and 1): the %s overlap at time 0", t.line[0],
             t.line[1], !isinf(o.c) && o.frame->contracted ? "contracted shapes" : "balls");
        goto out;
    }
    if (st == RC_MISS) {
        printf("miss\n");
        rc = 0;
        goto out;
    }
    if (st == RC_ESCALE) {
        const double far = fmax(rc_v3_norm(ball[0].x), rc_v3_norm(ball[1].x));
        fail("lines %ld and %ld (balls 0 and 1): the contact cannot be resolved: the centres "
             "lie %g from the origin (or reach farther before they meet), where doubles are "
             "coarser than a thousandth of the radii %g and %g (shift the origin near the "
             "balls, or scale the lengths)", t.line[0], t.line[1], far, ball[0].r, ball[1].r);
        goto out;
    }
    if (st != RC_OK) {
        fail("%s", rc_strerror(st));
        goto out;
    }
    print_header(dim, 0);
    print_row(dim, c.t, c.x, c.n);
    printf("\n");
    rc = 0;
out:
    rc_toi_workspace_free(&ws);
    app_balls_free(&b);
    app_table_free(&t);
    if (rc == 0 && fflush(stdout) != 0)
        rc = 1;
    return rc;
}
