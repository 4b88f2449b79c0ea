/* gif.c — relcol-shock --gif: the profiles over time as an animated GIF (gnuplot's gif
 * terminal, libgd; each frame one multiplot). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "app.h"
#include "gif.h"

int sh_gif(const char *prog, const char *dir, const sh_opts *o, const sh_result *r, int *made,
           char *err)
{
    static const int qs[3] = {SH_N, SH_V, SH_P};
    static const char *const ylab[3] = {"rest density n", "Eckart velocity v", "pressure p = P_{xx} - v g"};
    /* one y range per panel over every time, so that the frames share their axes */
    double lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = INFINITY, hi[a] = -INFINITY;
        for (int j = 0; j < r->nt; j++)
            for (int k = 0; k < r->nb; k++) {
                const size_t i = sh_idx(r, j, k, qs[a]);
                const double e = isfinite(r->err[i]) ? r->err[i] : 0.0;
                const double v[4] = {r->mean[i] - e, r->mean[i] + e, r->fluid[i], r->freestr[i]};
                for (int u = 0; u < 4; u++)
                    if (isfinite(v[u]))
                        lo[a] = fmin(lo[a], v[u]), hi[a] = fmax(hi[a], v[u]);
            }
        if (!(hi[a] >= lo[a])) /* no finite value at any time */
            lo[a] = 0.0, hi[a] = 1.0;
        /* (a flat panel still gets a range gnuplot accepts) */
        const double pad = 0.05 * (hi[a] - lo[a]) + 1e-6 * fabs(hi[a]) + 1e-300;
        lo[a] -= pad, hi[a] += pad;
    }
    char *path = app_path_join(dir, "profiles_gif.gp");
    if (!path) {
        app_errf(err, "out of memory");
        return -1;
    }
    app_atomic at;
    int rc = app_atomic_open(&at, path, err);
    free(path);
    if (rc)
        return -1;
    FILE *f = at.f;
    char cs[32];
    if (isinf(o->tube.c))
        snprintf(cs, sizeof cs, "inf");
    else
        snprintf(cs, sizeof cs, "%g", o->tube.c);
    fprintf(f, "if (!exists(\"outfile\")) outfile = 'profiles.gif'\n"
               "set encoding utf8\n"
               "set terminal gif animate delay 60 loop 0 size 1500,520 font ',10'\n"
               "set output outfile\nset datafile separator ','\n"
               "set xlabel 'x'\nset xrange [0:%.17g]\nset key top right font ',8'\n",
            o->tube.box.x);
    const double t_last = o->times[r->nt - 1];
    for (int j = 0; j < r->nt; j++) {
        const double t = o->times[j];
        fprintf(f, "set multiplot layout 1,3 title 'relcol-shock: %d-D, t = %g, c = %s, Kn = %.3g "
                   "(plateau mean free path / shock travel), %zu balls, %d seeds; points: balls "
                   "(seed errors), line: ideal fluid, dashed: free streaming'\n",
                o->tube.dim, t, cs, r->kn * t_last / t, r->nballs, r->seeds);
        for (int a = 0; a < 3; a++) {
            const int cm = 4 + 2 * qs[a], cf = 4 + 2 * SH_NQ + qs[a], cfs = 4 + 3 * SH_NQ + qs[a];
            fprintf(f, "set ylabel '%s'\nset yrange [%.10g:%.10g]\n", ylab[a], lo[a], hi[a]);
            fprintf(f, "plot 'profiles.csv' skip 1 using 2:($1==%.17g?$%d:1/0):%d with yerrorbars "
                       "pt 7 ps 0.4 lc 1 title 'balls', '' skip 1 using 2:($1==%.17g?$%d:1/0) "
                       "with lines lc 2 title 'ideal fluid', '' skip 1 using 2:($1==%.17g?$%d:1/0) "
                       "with lines dt 2 lc 3 title 'free streaming'\n",
                    t, cm, cm + 1, t, cf, t, cfs);
        }
        fprintf(f, "unset multiplot\n");
    }
    if (app_atomic_commit(&at, err))
        return -1;
    return app_gnuplot_run(prog, dir, "profiles_gif.gp", "profiles.gif", made, err);
}
