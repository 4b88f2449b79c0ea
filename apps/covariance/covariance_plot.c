/* covariance_plot.c — relcol-covariance's gnuplot scripts. Each figure says what it shows:
 * which frame is which kind (from the frames' declared properties), which points are not
 * resolved from their round-off control (ringed), where a value is missing and why (an ×
 * and a numbered note), and coinciding frames stay visible (points offset sideways). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "covariance_plot.h"

static const char *const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                      "#8c564b", "#e377c2", "#17becf"};
enum { NCOLOURS = sizeof colours / sizeof *colours, MAXNOTES = 9 };

static const char *colour(int i) { return colours[i % NCOLOURS]; }

/* The sideways factor of curve i of n on the log x axis: ±4 % steps, centred, so that
 * frames (or densities) with equal values show side by side instead of one on another. */
static double offset(int i, int n) { return exp(0.04 * (i - 0.5 * (n - 1))); }

/* What kind of contact rule a frame is, from its declared properties (the figure names
 * them; "(covariant)" alone said nothing of the difference between zmf and covariant). */
static const char *frame_kind(const rc_toi_frame *fr)
{
    if (fr->per_ball)
        return "frame-independent contact event, each ball changed at its own event";
    if (fr->covariant)
        return "frame-independent contact event, both balls changed at one table instant";
    return "contact at one table-frame instant";
}

/* s into a double-quoted gnuplot string in enhanced text: quotes and backslashes
 * escaped, and the enhanced-text operators taken literally. */
static void put_text(FILE *f, const char *s)
{
    for (; *s; s++) {
        if (*s == '"' || *s == '\\')
            fputc('\\', f);
        else if (strchr("^_@&~{}", *s))
            fputs("\\\\", f);
        fputc(*s, f);
    }
}

/* The distinct notes of the rows without differences that the figure shows (keep(i)),
 * numbered in order of first appearance; note_of[i] is row i's number (0: has a value). */
typedef struct notes {
    const char *text[MAXNOTES];
    int n, more;
} notes;

static int note_number(notes *ns, const char *s)
{
    for (int k = 0; k < ns->n; k++)
        if (!strcmp(ns->text[k], s))
            return k + 1;
    if (ns->n == MAXNOTES) {
        ns->more = 1;
        return MAXNOTES; /* (the last number stands for "and others") */
    }
    ns->text[ns->n++] = s;
    return ns->n;
}

/* The figure's heading: the encodings, the frames' kinds, and the notes of the ×s. */
static void heading(FILE *f, const cov_plot *p, int lines, int cols, const char *what,
                    const char *sideways, const notes *ns)
{
    char fb[APP_FMT_LEN], fv[APP_FMT_LEN];
    fprintf(f, "set multiplot layout %d,%d title \"Many-body frame dependence%s: %ld-D "
               "cluster, N = %ld, moving frame U = %s, v_{rms} = %s\\n{/*0.8 solid, filled: "
               "the table run against the moving run boosted back;   dashed, open: against a "
               "start moved by 10^{-15} (the round-off the dynamics amplifies)}\\n{/*0.8 "
               "ringed: within %g× of its round-off control, not told apart from round-off;"
               "   points offset sideways by %s}",
            lines, cols, what, p->dim, p->n, app_fmt(p->boost, fb), app_fmt(p->v_rms, fv),
            COV_PLOT_RESOLVED, sideways);
    /* the kinds, each with its frames */
    const char *kinds[3] = {0};
    int nk = 0;
    for (int j = 0; j < p->nframes; j++) {
        const char *k = frame_kind(p->frames[j]);
        int seen = 0;
        for (int i = 0; i < nk; i++)
            seen |= kinds[i] == k;
        if (!seen && nk < 3)
            kinds[nk++] = k;
    }
    for (int i = 0; i < nk; i++) {
        fprintf(f, "\\n{/*0.8 ");
        for (int j = 0, first = 1; j < p->nframes; j++)
            if (frame_kind(p->frames[j]) == kinds[i]) {
                fprintf(f, "%s%s", first ? "" : ", ", p->frames[j]->name);
                first = 0;
            }
        fprintf(f, ": %s}", kinds[i]);
    }
    for (int k = 0; k < ns->n; k++) {
        fprintf(f, "\\n{/*0.8 ×%d no value: ", k + 1);
        put_text(f, ns->text[k]);
        fprintf(f, "%s}", ns->more && k + 1 == ns->n ? " (and other reasons: see the note "
                                                       "column of covariance.csv)" : "");
    }
    fprintf(f, "\"\n");
}

/* A panel's curves: for each of its ncurve curves (frame or density) its rows first,
 * first + step, ..., first + (count - 1) step of rows; x of row (density or c / v_rms).
 * Curves without a value are left out (gnuplot warns on a curve without a point), and a
 * missing row is an × on the panel's floor with its note's number. */
typedef struct curve {
    size_t first, step;
    int count;
    const char *title;
    int every_stride, every_first, every_last; /* the CSV rows, for `every` */
} curve;

static void panel(FILE *f, const cov_plot_row *rows, const curve *cv,
                  int ncurve, const char *xexpr, const double *xs, const int *note_of,
                  const char *title)
{
    fprintf(f, "unset label\nset title '%s'\n", title);
    int any = 0, tag = 10;
    for (int i = 0; i < ncurve; i++)
        for (int m = 0; m < cv[i].count; m++)
            any += rows[cv[i].first + (size_t)m * cv[i].step].have;
    /* the ×s of each x: one grey × when every curve misses it for the same reason, else
     * one per curve in its colour, stacked up from the floor */
    for (int m = 0; m < cv[0].count; m++) {
        int nmiss = 0, same = 1, note = 0;
        for (int i = 0; i < ncurve; i++) {
            const size_t r = cv[i].first + (size_t)m * cv[i].step;
            if (rows[r].have)
                continue;
            same &= !nmiss || note_of[r] == note;
            note = note_of[r];
            nmiss++;
        }
        if (!nmiss)
            continue;
        if (nmiss == ncurve && same) {
            fprintf(f, "set label %d '%d' at first %.9g, graph 0.035 point pt 2 ps 1.4 lw 2 "
                       "lc rgb '#444444' offset 0.5,0.45 font ',8' tc rgb '#444444' front\n",
                    tag++, note, xs[m]);
            continue;
        }
        for (int i = 0, h = 0; i < ncurve; i++) {
            const size_t r = cv[i].first + (size_t)m * cv[i].step;
            if (rows[r].have)
                continue;
            fprintf(f, "set label %d '%d' at first %.9g, graph %.3f point pt 2 ps 1.4 lw 2 "
                       "lc rgb '%s' offset 0.5,0.45 font ',8' tc rgb '%s' front\n",
                    tag++, note_of[r], xs[m] * offset(i, ncurve), 0.035 + 0.055 * h++,
                    colour(i), colour(i));
        }
    }
    if (!any) {
        /* gnuplot fails on a panel without a single point */
        fprintf(f, "set yrange [1e-16:10]\n"
                   "set label 1 'no value at all here (see the × notes above)' at graph 0.5,0.5 center\n"
                   "plot NaN notitle\n"
                   "set autoscale y\n");
        return;
    }
    fprintf(f, "plot \\\n");
    /* the curves, then the rings over them (so the key lists them last) */
    int done = 0, rings = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < ncurve; i++) {
            int have = 0, ringed = 0;
            for (int m = 0; m < cv[i].count; m++) {
                const cov_plot_row *w = &rows[cv[i].first + (size_t)m * cv[i].step];
                have += w->have;
                ringed += w->have && w->dp_frames <= COV_PLOT_RESOLVED * w->dp_roundoff;
            }
            if (!have || (pass == 1 && !ringed))
                continue;
            char every[64];
            if (cv[i].every_last >= 0)
                snprintf(every, sizeof every, "%d::%d::%d", cv[i].every_stride,
                         cv[i].every_first, cv[i].every_last);
            else
                snprintf(every, sizeof every, "%d::%d", cv[i].every_stride, cv[i].every_first);
            const double k = offset(i, ncurve);
            if (pass == 0)
                fprintf(f, "%s  'covariance.csv' skip 1 every %s using (%s*%.9g):17 with "
                           "linespoints pt 7 ps 0.9 lw 2 lc rgb '%s' title '%s', \\\n"
                           "  '' skip 1 every %s using (%s*%.9g):18 with linespoints dt 2 pt 6 "
                           "ps 0.7 lw 1.2 lc rgb '%s' notitle",
                        done++ ? ", \\\n" : "", every, xexpr, k, colour(i), cv[i].title, every,
                        xexpr, k, colour(i));
            else
                fprintf(f, ", \\\n  '' skip 1 every %s using (%s*%.9g):($17 <= %g*$18 ? $17 : "
                           "1/0) with points pt 6 ps 2.1 lw 1.2 lc rgb '#222222' %s",
                        every, xexpr, k, COV_PLOT_RESOLVED,
                        rings++ ? "notitle" : "title 'not resolved'");
        }
    fprintf(f, "\n");
}

static void layout(int panels, int *cols, int *lines)
{
    *cols = panels < 3 ? panels : (panels == 4 ? 2 : 3);
    *lines = (panels + *cols - 1) / *cols;
}

int cov_plot_density(const char *path, const cov_plot *p, const cov_plot_row *rows,
                     char *err)
{
    const size_t nrows = (size_t)p->nframes * (size_t)p->ndensity * (size_t)p->nc;
    int *note_of = malloc(nrows * sizeof *note_of);
    notes ns = {.n = 0};
    if (!note_of) {
        app_errf(err, "out of memory");
        return -1;
    }
    for (size_t r = 0; r < nrows; r++)
        note_of[r] = rows[r].have ? 0 : note_number(&ns, rows[r].note);
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0) {
        free(note_of);
        return -1;
    }
    FILE *f = a.f;
    int cols, lines;
    layout(p->nc, &cols, &lines);
    char term[128];
    snprintf(term, sizeof term, "size %d,%d enhanced font 'Sans,12' linewidth 1.5",
             620 * cols + 40, 440 * lines + 140 + 16 * ns.n);
    fprintf(f,
"# covariance.gp — written by relcol-covariance; run `gnuplot covariance.gp` in this folder.\n"
"# The engine's many-body frame dependence: final momenta of the run from a moving frame,\n"
"# boosted back, against the table frame's run (solid), and the round-off the dynamics\n"
"# amplifies (dashed: a start moved by 1e-15), against the cluster's density, per c.\n"
"# Ringed: a frame difference within %g times its round-off control; ×: no value.\n",
            COV_PLOT_RESOLVED);
    app_gnuplot_head(f, "covariance.png", term, 1);
    double dlo = p->density[0], dhi = p->density[p->ndensity - 1];
    /* (the x range given: gnuplot warns on one density's empty range) */
    fprintf(f, "set xrange [%.6g:%.6g]\nset format x '%%g'\nset xtics (", dlo / 1.5, dhi * 1.5);
    for (int i = 0; i < p->ndensity; i++) {
        char fd[APP_FMT_LEN];
        fprintf(f, "%s%s", i ? ", " : "", app_fmt(p->density[i], fd));
    }
    fprintf(f, ")\n"
"set grid xtics ytics lc rgb '#dddddd' lw 0.8\n"
"set xlabel 'density (packing fraction of the shell)'\n"
"set ylabel 'max_i |Δp_i| / rms |p|'\n"
"set key below vertical maxrows 2 font ',10' spacing 1.1 width 1\n");
    heading(f, p, lines, cols, "", "frame, so that equal values stay visible", &ns);
    /* The rows go density by density, then c, then frame: frame j at the k-th c is every
     * (nc nframes)-th row from k nframes + j (`every` keeps the line through them; a row
     * without differences has empty fields, which gnuplot skips). Columns: 5 density,
     * 17 dp_frames, 18 dp_roundoff. */
    const int stride = p->nc * p->nframes;
    for (int k = 0; k < p->nc; k++) {
        curve cv[64];
        for (int j = 0; j < p->nframes; j++)
            cv[j] = (curve){.first = (size_t)(k * p->nframes + j), .step = (size_t)stride,
                            .count = p->ndensity, .title = p->frames[j]->name,
                            .every_stride = stride, .every_first = k * p->nframes + j,
                            .every_last = -1};
        char title[64], fc[APP_FMT_LEN];
        snprintf(title, sizeof title, "c = %s",
                 isinf(p->c[k]) ? "∞ (classical)" : app_fmt(p->c[k], fc));
        panel(f, rows, cv, p->nframes, "$5", p->density, note_of, title);
    }
    fprintf(f, "unset multiplot\n");
    free(note_of);
    return app_atomic_commit(&a, err);
}

int cov_plot_c(const char *path, const cov_plot *p, const cov_plot_row *rows, int nfin,
               char *err)
{
    const size_t nrows = (size_t)p->nframes * (size_t)p->ndensity * (size_t)p->nc;
    int *note_of = malloc(nrows * sizeof *note_of);
    notes ns = {.n = 0};
    if (!note_of) {
        app_errf(err, "out of memory");
        return -1;
    }
    /* (only the finite c are shown, so only their notes) */
    for (size_t r = 0; r < nrows; r++) {
        const int ci = (int)(r / (size_t)p->nframes % (size_t)p->nc);
        note_of[r] = rows[r].have || ci >= nfin ? 0 : note_number(&ns, rows[r].note);
    }
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0) {
        free(note_of);
        return -1;
    }
    FILE *f = a.f;
    int cols, lines;
    layout(p->nframes, &cols, &lines);
    char term[128];
    snprintf(term, sizeof term, "size %d,%d enhanced font 'Sans,12' linewidth 1.5",
             620 * cols + 40, 440 * lines + 140 + 16 * ns.n);
    fprintf(f,
"# covariance-c.gp — written by relcol-covariance; run `gnuplot covariance-c.gp` in this\n"
"# folder. The same differences as covariance.gp against c / v_rms (finite c only), one\n"
"# panel per frame, one colour per density.\n");
    app_gnuplot_head(f, "covariance-c.png", term, 1);
    fprintf(f,
"set xrange [%.6g:%.6g]\n"
"set grid xtics ytics lc rgb '#dddddd' lw 0.8\n"
"set xlabel 'c / v_{rms}'\n"
"set ylabel 'max_i |Δp_i| / rms |p|'\n"
"set key below vertical maxrows 2 font ',10' spacing 1.1 width 1\n",
            p->c[0] / p->v_rms / 1.5, p->c[nfin - 1] / p->v_rms * 1.5);
    fprintf(f, "set format x '%%g'\nset xtics (");
    double xs[64];
    for (int k = 0; k < nfin; k++) {
        xs[k] = p->c[k] / p->v_rms;
        fprintf(f, "%s%.6g", k ? ", " : "", xs[k]);
    }
    fprintf(f, ")\n");
    heading(f, p, lines, cols, " against c", "density, so that equal values stay visible", &ns);
    /* rows go density, c, frame: frame j at density di is every nframes-th row from
     * di (nc nframes) + j, its finite c the first nfin of them */
    const int stride = p->nc * p->nframes;
    char dens[64][APP_FMT_LEN + 16];
    for (int j = 0; j < p->nframes; j++) {
        curve cv[64];
        for (int di = 0; di < p->ndensity; di++) {
            char fd[APP_FMT_LEN];
            snprintf(dens[di], sizeof dens[di], "density %s", app_fmt(p->density[di], fd));
            const int first = di * stride + j;
            cv[di] = (curve){.first = (size_t)first, .step = (size_t)p->nframes, .count = nfin,
                             .title = dens[di], .every_stride = p->nframes,
                             .every_first = first, .every_last = first + (nfin - 1) * p->nframes};
        }
        panel(f, rows, cv, p->ndensity, "($3/$10)", xs, note_of, p->frames[j]->name);
    }
    fprintf(f, "unset multiplot\n");
    free(note_of);
    return app_atomic_commit(&a, err);
}
