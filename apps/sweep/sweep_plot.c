/* sweep_plot.c — relcol-sweep's figure: a panel per scenario with its deviations from the
 * classical limit against c / |v|max, the (|v|max/c)^2 reference, and the scenario's noise
 * floor (points at or below it are drawn grey: the fit leaves them out). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "app.h"
#include "sweep_plot.h"

/* (no yellow: it is faint on white) */
static const char *const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                      "#8c564b"};
static const int points[] = {7, 5, 9, 13, 11, 15};
enum { NCOLOURS = sizeof colours / sizeof *colours };

int sweep_plot_write(const char *path, const sweep_scenario *const *list, size_t ns,
                     const double *order, size_t norder, double eps, double stiffness,
                     char *err)
{
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0)
        return -1;
    FILE *f = a.f;
    const int cols = ns < 2 ? 1 : 2, lines = (int)((ns + (size_t)cols - 1) / (size_t)cols);
    char term[96];
    snprintf(term, sizeof term, "size %d,%d enhanced font 'Sans,12' linewidth 1.4",
             cols == 1 ? 700 : 1240, 420 * lines + 110);
    fprintf(f, "# relcol-sweep: deviation from the classical limit against c (run: gnuplot "
               "sweep.gp in this folder); one panel per scenario\n");
    app_gnuplot_head(f, "sweep.png", term, 0);
    fprintf(f,
"set logscale xy\nset format x '10^{%%L}'\nset format y '10^{%%L}'\n"
"set xlabel 'c / |v|_{max}'\nset ylabel 'relative deviation from c = ∞'\n"
"set grid lc rgb '#dddddd'\nset key bottom left font ',10' spacing 1.1 box opaque\n"
"set multiplot layout %d,%d title \"Classical-limit convergence of each scenario (ε = %g, "
"soft stiffness %g)\\n{/*0.8 dashed: (|v|_{max}/c)^2, the order the first relativistic "
"correction has}\\n{/*0.8 dotted: the scenario's noise floor; grey points at or below it are "
"left out of the fitted order}\"\n",
            lines, cols, eps, stiffness);
    size_t col = 0;
    for (size_t s = 0; s < ns; s++) {
        const sweep_scenario *sc = list[s];
        /* the name, and its summary below it in a smaller font (taken literally) */
        fprintf(f, "set title \"%s\\n{/*0.8 ", sc->name);
        for (const char *q = sc->summary; *q; q++) {
            if (*q == '"' || *q == '\\')
                fputc('\\', f);
            else if (strchr("^_@&~{}", *q))
                fputs("\\\\", f);
            fputc(*q, f);
        }
        fprintf(f, "}\"\n");
        fprintf(f, "plot 'sweep.csv' u 2:3 w l dt 2 lw 2 lc rgb '#555555' t '(|v|_{max}/c)^2', "
                   "\\\n     %g w l dt 3 lw 1.5 lc rgb '#888888' t 'noise floor %g'",
                sc->floor, sc->floor);
        for (int g = 0; g < sc->n_groups; g++, col++) {
            const int c = (int)(4 + col);
            const double p = col < norder ? order[col] : NAN;
            char fo[32];
            if (isnan(p))
                snprintf(fo, sizeof fo, "no fit");
            else
                snprintf(fo, sizeof fo, "fitted order %.3f", p);
            fprintf(f, ", \\\n     '' u 2:($%d > %g ? $%d : 1/0) w lp pt %d ps 0.9 lw 2 "
                       "lc rgb '%s' t '%s (%s)'",
                    c, sc->floor, c, points[g % NCOLOURS], colours[g % NCOLOURS],
                    sc->group[g], fo);
            fprintf(f, ", \\\n     '' u 2:($%d > 0 && $%d <= %g ? $%d : 1/0) w p pt %d ps 0.6 "
                       "lc rgb '#aaaaaa' notitle",
                    c, c, sc->floor, c, points[g % NCOLOURS]);
        }
        fprintf(f, "\n");
    }
    fprintf(f, "unset multiplot\n");
    return app_atomic_commit(&a, err);
}
