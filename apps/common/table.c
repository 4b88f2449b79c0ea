/* table.c — the CSV reader every app uses for its input tables: a header of column names,
 * rows of fields, and errors that name the file line and the column. */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"

/* Trim blanks (and the CR of CRLF files) in place; returns the trimmed start. */
static char *trim(char *s)
{
    while (*s && isspace((unsigned char)*s))
        s++;
    size_t len = strlen(s);
    while (len > 0 && isspace((unsigned char)s[len - 1]))
        s[--len] = '\0';
    return s;
}

/* Split a record at commas into malloc'ed fields, as spreadsheets write CSV (RFC 4180):
 * a field may be quoted ("a, b" holds a comma, "say ""x""" a quote, and a quoted field
 * may span lines); unquoted fields are trimmed of blanks, quoted ones kept as quoted
 * (blanks outside the quotes dropped). Returns the count, -1 out of memory, or -2 with
 * the reason in why (text after a closing quote). */
static int split(const char *line, char ***out, char *why)
{
    size_t len = strlen(line);
    int n = 1;
    for (const char *p = line; *p; p++)
        n += (*p == ','); /* (a bound: commas inside quotes make fewer fields) */
    char **f = calloc((size_t)n, sizeof *f);
    char *buf = malloc(len + 1);
    if (!f || !buf) {
        free(f);
        free(buf);
        return -1;
    }
    int k = 0;
    const char *p = line;
    for (;;) {
        while (*p == ' ' || *p == '\t')
            p++;
        size_t b = 0;
        if (*p == '"') {
            for (p++; *p; p++) {
                if (*p == '"' && p[1] == '"')
                    buf[b++] = *++p;
                else if (*p == '"')
                    break;
                else
                    buf[b++] = *p;
            }
            if (*p == '"')
                p++;
            while (*p && isspace((unsigned char)*p))
                p++;
            if (*p && *p != ',') {
                app_errf(why, "field %d: text after its closing quote", k + 1);
                buf[b] = '\0';
                goto bad;
            }
        } else {
            while (*p && *p != ',')
                buf[b++] = *p++;
            while (b > 0 && isspace((unsigned char)buf[b - 1]))
                b--;
        }
        buf[b] = '\0';
        if (!(f[k++] = strdup(buf))) {
            k--;
            goto nomem;
        }
        if (*p != ',')
            break;
        p++;
    }
    free(buf);
    *out = f;
    return k;
nomem:
    why[0] = '\0';
bad:
    for (int j = 0; j < k; j++)
        free(f[j]);
    free(f);
    free(buf);
    return why[0] ? -2 : -1;
}

/* Whether s ends inside a quoted field (an odd number of quotes: "" inside a quoted field
 * counts two, so the parity says where a record ends). */
static int open_quote(const char *s)
{
    int q = 0;
    for (; *s; s++)
        q ^= (*s == '"');
    return q;
}

/* The first column (in header order) whose name an earlier column has, -1 if none, -2 out
 * of memory: the names sorted, in n log n (a pairwise check took 36 s for 1e5 columns). */
static char **sort_names;
static int by_name(const void *a, const void *b)
{
    const int i = *(const int *)a, j = *(const int *)b;
    const int c = strcmp(sort_names[i], sort_names[j]);
    return c ? c : (i > j) - (i < j);
}

static int first_repeat(char **names, int n)
{
    int *ix = malloc((size_t)(n ? n : 1) * sizeof *ix);
    if (!ix)
        return -2;
    for (int i = 0; i < n; i++)
        ix[i] = i;
    sort_names = names;
    qsort(ix, (size_t)n, sizeof *ix, by_name);
    int rep = -1;
    for (int k = 1; k < n; k++)
        if (strcmp(names[ix[k]], names[ix[k - 1]]) == 0 && (rep < 0 || ix[k] < rep))
            rep = ix[k]; /* (equal names sort by position: ix[k] is a later one) */
    free(ix);
    return rep;
}

static void free_fields(char **f, int n)
{
    if (!f)
        return;
    for (int i = 0; i < n; i++)
        free(f[i]);
    free(f);
}

void app_table_free(app_table *t)
{
    if (!t)
        return;
    free_fields(t->names, t->ncols);
    if (t->cells)
        for (size_t i = 0; i < t->nrows * (size_t)t->ncols; i++)
            free(t->cells[i]);
    free(t->cells);
    free(t->line);
    memset(t, 0, sizeof *t);
}

int app_table_read(FILE *f, app_table *t, char *err)
{
    memset(t, 0, sizeof *t);
    char *buf = NULL;
    size_t cap = 0, rows_cap = 0;
    long lineno = 0, rec_line = 0;
    ssize_t got;
    int rc = -1;
    char *rec = NULL; /* a record: one line, or more when a quoted field spans lines */
    size_t rec_len = 0;
    int quote = 0; /* open_quote(rec), kept line by line (a rescan per line is quadratic) */
    while ((got = getline(&buf, &cap, f)) >= 0) {
        lineno++;
        if (memchr(buf, '\0', (size_t)got)) {
            app_errf(err, "line %ld: NUL byte (binary input?)", lineno);
            goto out;
        }
        char *line = buf;
        /* a UTF-8 byte order mark (spreadsheets' "CSV UTF-8") is not part of the text */
        if (lineno == 1 && (unsigned char)line[0] == 0xEF && (unsigned char)line[1] == 0xBB &&
            (unsigned char)line[2] == 0xBF)
            line += 3;
        if (rec) { /* continuing a quoted field: keep the line end, as LF */
            size_t l = strlen(line);
            char *r2 = realloc(rec, rec_len + l + 1);
            if (!r2) {
                app_errf(err, "out of memory");
                goto out;
            }
            rec = r2;
            memcpy(rec + rec_len, line, l + 1);
            rec_len += l;
            quote ^= open_quote(line);
        } else {
            char *s0 = trim(line);
            if (*s0 == '\0' || *s0 == '#')
                continue; /* blank lines (trailing ones too) and comments */
            if (!(rec = strdup(s0))) {
                app_errf(err, "out of memory");
                goto out;
            }
            rec_len = strlen(rec);
            rec_line = lineno;
            quote = open_quote(rec);
        }
        if (quote) {
            /* (CRLF inside a quoted field becomes LF) */
            if (rec_len > 0 && rec[rec_len - 1] == '\n')
                rec[--rec_len] = '\0';
            if (rec_len > 0 && rec[rec_len - 1] == '\r')
                rec[--rec_len] = '\0';
            char *r2 = realloc(rec, rec_len + 2);
            if (!r2) {
                app_errf(err, "out of memory");
                goto out;
            }
            rec = r2;
            rec[rec_len++] = '\n';
            rec[rec_len] = '\0';
            continue;
        }
        char *s = trim(rec);
        char **fields;
        char why[APP_ERR_LEN];
        int n = split(s, &fields, why);
        free(rec);
        rec = NULL;
        if (n == -2) {
            app_errf(err, "line %ld: %s", rec_line, why);
            goto out;
        }
        if (n < 0) {
            app_errf(err, "out of memory");
            goto out;
        }
        if (!t->names) {
            t->names = fields;
            t->ncols = n;
            t->header_line = rec_line;
            for (int i = 0; i < n; i++) {
                if (fields[i][0] == '\0') {
                    app_errf(err, "line %ld (header): column %d has an empty name", rec_line,
                             i + 1);
                    goto out;
                }
            }
            const int rep = first_repeat(fields, n);
            if (rep == -2) {
                app_errf(err, "out of memory");
                goto out;
            }
            if (rep >= 0) {
                app_errf(err, "line %ld (header), column %s: repeated column", rec_line,
                         fields[rep]);
                goto out;
            }
            continue;
        }
        if (n != t->ncols) {
            app_errf(err, "line %ld: %d field%s, but the header (line %ld) has %d columns",
                     rec_line, n, n == 1 ? "" : "s", t->header_line, t->ncols);
            free_fields(fields, n);
            goto out;
        }
        if (t->nrows == rows_cap) {
            size_t nc = rows_cap ? 2 * rows_cap : 8;
            char **cells = realloc(t->cells, nc * (size_t)t->ncols * sizeof *cells);
            if (cells)
                t->cells = cells;
            long *lines = realloc(t->line, nc * sizeof *lines);
            if (lines)
                t->line = lines;
            if (!cells || !lines) {
                app_errf(err, "out of memory");
                free_fields(fields, n);
                goto out;
            }
            rows_cap = nc;
        }
        memcpy(t->cells + t->nrows * (size_t)t->ncols, fields, (size_t)n * sizeof *fields);
        free(fields); /* the strings now belong to cells */
        t->line[t->nrows++] = rec_line;
    }
    if (ferror(f)) {
        app_errf(err, "read error after line %ld", lineno);
        goto out;
    }
    if (rec) {
        app_errf(err, "line %ld: a quoted field is not closed (a '\"' missing)", rec_line);
        goto out;
    }
    if (!t->names) {
        app_errf(err, "empty input: expected a header line of column names");
        goto out;
    }
    rc = 0;
out:
    free(rec);
    free(buf);
    if (rc != 0)
        app_table_free(t);
    return rc;
}

int app_table_col(const app_table *t, const char *name)
{
    for (int i = 0; i < t->ncols; i++)
        if (strcmp(t->names[i], name) == 0)
            return i;
    return -1;
}

const char *app_row_name(const app_table *t, size_t row, char *buf, size_t n)
{
    snprintf(buf, n, "line %ld (ball %zu)", t->line[row], row);
    return buf;
}

int app_check_scale(double x, int positive, char *why)
{
    const double a = fabs(x);
    if (x == 0.0 && !positive)
        return 0;
    if (a >= APP_SCALE_MIN && a <= APP_SCALE_MAX)
        return 0;
    char f[APP_FMT_LEN];
    if (positive && !(x > 0.0))
        app_errf(why, "%s must be > 0", app_fmt(x, f));
    else
        app_errf(why, "%s is too %s: magnitudes must lie in [1e-150, 1e150], where their "
                 "squares and products are finite, normal doubles", app_fmt(x, f),
                 a > APP_SCALE_MAX ? "large" : "small");
    return -1;
}

int app_table_scaled(const app_table *t, size_t row, int col, const char *row_label,
                     int positive, double *out, char *err)
{
    if (app_table_double(t, row, col, row_label, 0, out, err))
        return -1;
    char why[APP_ERR_LEN];
    if (app_check_scale(*out, positive, why) == 0)
        return 0;
    if (row_label)
        app_errf(err, "line %ld (%s), column %s: %s", t->line[row], row_label, t->names[col],
                 why);
    else
        app_errf(err, "line %ld, column %s: %s", t->line[row], t->names[col], why);
    return -1;
}

int app_table_double(const app_table *t, size_t row, int col, const char *row_label,
                     int allow_inf, double *out, char *err)
{
    char why[APP_ERR_LEN];
    if (app_parse_double(app_table_cell(t, row, col), allow_inf, out, why) == 0)
        return 0;
    if (row_label)
        app_errf(err, "line %ld (%s), column %s: %s", t->line[row], row_label,
                 t->names[col], why);
    else
        app_errf(err, "line %ld, column %s: %s", t->line[row], t->names[col], why);
    return -1;
}
