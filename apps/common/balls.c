/* balls.c — ball rows of a table (m, vx.. or px.., optional x..) into rc_particle states:
 * the column conventions of every relcol app, checked with messages naming row and column. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"

/* NULL-terminated, so in_list() can scan them too */
static const char *const vel_names[4] = {"vx", "vy", "vz", NULL};
static const char *const mom_names[4] = {"px", "py", "pz", NULL};
static const char *const pos_names[4] = {"x", "y", "z", NULL};

/* Columns of a vector family: fills col[] (-1 if absent) and returns the dimension, or -1
 * with a message if a component is present without the earlier ones. */
static int vector_cols(const app_table *t, const char *const names[4], int col[3], char *err)
{
    int dim = 0;
    for (int i = 0; i < 3; i++)
        col[i] = app_table_col(t, names[i]);
    for (int i = 0; i < 3; i++) {
        if (col[i] >= 0) {
            if (dim != i) {
                app_errf(err, "line %ld (header), column %s: present without %s",
                         t->header_line, names[i], names[dim]);
                return -1;
            }
            dim = i + 1;
        }
    }
    return dim;
}

static int in_list(const char *name, const char *const *list)
{
    for (; list && *list; list++)
        if (strcmp(name, *list) == 0)
            return 1;
    return 0;
}

/* "vx,vy" from the first d names */
static const char *join_names(const char *const *names, int d, char *buf, size_t n)
{
    buf[0] = '\0';
    for (int i = 0; i < d; i++) {
        size_t len = strlen(buf);
        snprintf(buf + len, n - len, "%s%s", i ? "," : "", names[i]);
    }
    return buf;
}

const char *app_balls_colnames(const app_balls *b, int positions, char *buf, size_t n)
{
    return join_names(positions ? pos_names : (b->momentum ? mom_names : vel_names), b->dim,
                      buf, n);
}

void app_balls_free(app_balls *b)
{
    if (!b)
        return;
    free(b->m);
    free(b->q);
    free(b->x);
    memset(b, 0, sizeof *b);
}

int app_balls_parse(const app_table *t, const char *const *extra, size_t nrows_want,
                    app_balls *b, char *err)
{
    memset(b, 0, sizeof *b);
    b->table = t;
    const long hl = t->header_line;
    for (int i = 0; i < t->ncols; i++) {
        const char *nm = t->names[i];
        if (strcmp(nm, "m") == 0 || in_list(nm, vel_names) ||
            in_list(nm, mom_names) || in_list(nm, pos_names) ||
            in_list(nm, extra))
            continue;
        char more[128] = "";
        for (const char *const *e = extra; e && *e; e++) {
            size_t len = strlen(more);
            snprintf(more + len, sizeof more - len, ", %s", *e);
        }
        app_errf(err,
                 "line %ld (header), column %s: unknown column (expected m, vx[,vy[,vz]] or "
                 "px[,py[,pz]], optional x[,y[,z]]%s)",
                 hl, nm, more);
        return -1;
    }
    const int cm = app_table_col(t, "m");
    if (cm < 0) {
        app_errf(err, "line %ld (header), column m: missing column (rest mass)", hl);
        return -1;
    }
    int cv[3], cp[3], cx[3];
    const int dv = vector_cols(t, vel_names, cv, err);
    if (dv < 0)
        return -1;
    const int dp = vector_cols(t, mom_names, cp, err);
    if (dp < 0)
        return -1;
    int dx = 0;
    for (int i = 0; i < 3; i++)
        dx += (app_table_col(t, pos_names[i]) >= 0);
    if (dv > 0 && dp > 0) {
        app_errf(err, "line %ld (header), columns vx and px: mixed velocity and momentum "
                      "columns (give one kind)", hl);
        return -1;
    }
    if (dv == 0 && dp == 0) {
        app_errf(err, "line %ld (header), column vx: missing column (give velocities "
                      "vx[,vy[,vz]] or momenta px[,py[,pz]])", hl);
        return -1;
    }
    b->momentum = dp > 0;
    b->dim = b->momentum ? dp : dv;
    const int *cq = b->momentum ? cp : cv;
    if (dx > 0) {
        int d = vector_cols(t, pos_names, cx, err);
        if (d < 0)
            return -1;
        if (d != b->dim) {
            char names[32];
            join_names(pos_names, d, names, sizeof names);
            app_errf(err, "line %ld (header), column%s %s: %d position component%s, but the "
                          "%s columns give dimension %d", hl, d > 1 ? "s" : "", names, d,
                     d > 1 ? "s" : "", b->momentum ? "momentum" : "velocity", b->dim);
            return -1;
        }
        b->has_pos = 1;
    }
    if (t->nrows == 0 || (nrows_want > 0 && t->nrows != nrows_want)) {
        if (nrows_want > 0 && t->nrows > nrows_want)
            app_errf(err, "line %ld: wrong number of rows: expected exactly %zu data rows "
                          "(balls), found %zu", t->line[nrows_want], nrows_want, t->nrows);
        else if (nrows_want > 0)
            app_errf(err, "line %ld (header): wrong number of rows: expected exactly %zu "
                          "data rows (balls), found %zu", hl, nrows_want, t->nrows);
        else
            app_errf(err, "line %ld (header): no data rows", hl);
        return -1;
    }
    b->n = t->nrows;
    b->m = calloc(b->n, sizeof *b->m);
    b->q = calloc(b->n, sizeof *b->q);
    b->x = calloc(b->n, sizeof *b->x);
    if (!b->m || !b->q || !b->x) {
        app_errf(err, "out of memory");
        app_balls_free(b);
        return -1;
    }
    for (size_t r = 0; r < b->n; r++) {
        char label[32];
        snprintf(label, sizeof label, "ball %zu", r);
        if (app_table_double(t, r, cm, label, 0, &b->m[r], err) != 0)
            goto fail;
        if (!(b->m[r] > 0.0)) {
            char f[APP_FMT_LEN];
            app_errf(err, "line %ld (%s), column m: m = %s must be > 0", t->line[r], label,
                     app_fmt(b->m[r], f));
            goto fail;
        }
        if (app_table_scaled(t, r, cm, label, 1, &b->m[r], err) != 0)
            goto fail;
        for (int i = 0; i < b->dim; i++) {
            double v;
            if (app_table_scaled(t, r, cq[i], label, 0, &v, err) != 0)
                goto fail;
            rc_v3_set(&b->q[r], i, v);
            if (b->has_pos) {
                if (app_table_scaled(t, r, cx[i], label, 0, &v, err) != 0)
                    goto fail;
                rc_v3_set(&b->x[r], i, v);
            }
        }
    }
    return 0;
fail:
    app_balls_free(b);
    return -1;
}

int app_balls_particles(const app_balls *b, double c, rc_particle *out, char *err)
{
    double k;
    int st = rc_inv_c2(c, &k);
    if (st != RC_OK) {
        char f[APP_FMT_LEN];
        app_errf(err, "c = %s: %s", app_fmt(c, f), rc_strerror(st));
        return -1;
    }
    for (size_t r = 0; r < b->n; r++) {
        out[r].m = b->m[r];
        if (b->momentum) {
            out[r].p = b->q[r];
            st = RC_OK;
        } else {
            st = rc_momentum_from_velocity(b->m[r], b->q[r], k, &out[r].p);
        }
        /* the laws square M and p: a state whose M = sqrt(m^2 + p^2/c^2) or p^2
         * overflows cannot collide meaningfully in double precision */
        if (st == RC_OK && (!rc_v3_isfinite(out[r].p) ||
                            !isfinite(rc_v3_norm2(out[r].p)) ||
                            !isfinite(b->m[r] * b->m[r] + rc_v3_norm2(out[r].p) * k)))
            st = RC_ENONFINITE;
        if (st == RC_ENONFINITE) {
            char names[32], rn[48];
            app_balls_colnames(b, 0, names, sizeof names);
            app_errf(err, "%s, columns m,%s: too large: m^2 + p^2/c^2 overflows double "
                          "precision", app_row_name(b->table, r, rn, sizeof rn), names);
            return -1;
        }
        if (st != RC_OK) {
            char names[32], rn[48], f1[APP_FMT_LEN], f2[APP_FMT_LEN];
            app_balls_colnames(b, 0, names, sizeof names);
            app_row_name(b->table, r, rn, sizeof rn);
            if (st == RC_ESPEED)
                app_errf(err, "%s, column%s %s: |v| = %s >= c = %s", rn,
                         b->dim > 1 ? "s" : "", names, app_fmt(rc_v3_norm(b->q[r]), f1),
                         app_fmt(c, f2));
            else
                app_errf(err, "%s, column%s %s: %s", rn, b->dim > 1 ? "s" : "", names,
                         rc_strerror(st));
            return -1;
        }
    }
    return 0;
}
