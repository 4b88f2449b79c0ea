/* profiles.c — relcol-sim's profiles of a gas in a uniform field (profiles.h). The
 * temperature is measured two ways in each slab: kT = <p_z v_z> along the field and
 * <p_perp . v_perp>/(d - 1) across it, each exactly kT in local Juttner (or Maxwell)
 * equilibrium; with the equivalence coupling the column kT_sqrt_g00 is (1 + g z/c^2) times
 * <p . v>/d, Tolman's constant. Errors: the count's Poisson error, and the standard error
 * of a slab's mean over every ball gathered in it (samples taken far apart in time are
 * independent; close ones make these errors too small). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "profiles.h"

static int axis_of(const scn_scenario *s) { return s->dim - 1; }

static double height(const scn_scenario *s)
{
    return rc_v3_get(s->box, axis_of(s));
}

void profiles_sample(sim_profiles *p, const scn_scenario *s, const rc_sim *sim)
{
    const int ax = axis_of(s), d = s->dim;
    const double H = height(s), ic2 = isinf(s->c) ? 0.0 : 1.0 / (s->c * s->c);
    double cnt[SIM_PROFILE_SLABS] = {0};
    for (size_t i = 0; i < rc_sim_count(sim); i++) {
        rc_sim_ball b;
        if (rc_sim_get_ball(sim, i, &b) != RC_OK)
            continue;
        const double z = rc_v3_get(b.x, ax);
        int k = (int)(z / H * SIM_PROFILE_SLABS);
        k = k < 0 ? 0 : k >= SIM_PROFILE_SLABS ? SIM_PROFILE_SLABS - 1 : k;
        const rc_vec3 v = rc_velocity(b.m, b.p, ic2);
        const double pv = rc_v3_dot(b.p, v), pz = rc_v3_get(b.p, ax) * rc_v3_get(v, ax);
        const double across = (pv - pz) / (d - 1);
        const double lp = (s->gravity == &rc_gravity_equivalence ? 1.0 + s->g * z * ic2 : 1.0) *
                          pv / d;
        cnt[k]++;
        p->along[k] += pz, p->along2[k] += pz * pz;
        p->across[k] += across, p->across2[k] += across * across;
        p->lapse[k] += lp, p->lapse2[k] += lp * lp;
    }
    for (int k = 0; k < SIM_PROFILE_SLABS; k++)
        p->n[k] += cnt[k], p->n2[k] += cnt[k] * cnt[k];
    p->samples++;
}

/* a slab's mean of a per-ball quantity and its standard error (NAN: no ball there) */
static void mean_err(double sum, double sum2, double n, double *m, double *e)
{
    *m = n > 0 ? sum / n : NAN;
    *e = n > 1 ? sqrt(fmax(sum2 / n - *m * *m, 0.0) / (n - 1)) : NAN;
}

int profiles_write(const sim_profiles *p, const scn_scenario *s, const char *prog,
                   const char *dir, char *err)
{
    char *path = app_path_join(dir, "profiles.csv");
    app_atomic a;
    if (!path || app_atomic_open(&a, path, err)) {
        free(path);
        if (!path)
            app_errf(err, "out of memory");
        return -1;
    }
    free(path);
    const double H = height(s), S = p->samples > 0 ? p->samples : 1;
    double slab_vol = H / SIM_PROFILE_SLABS;
    for (int d = 0; d < s->dim; d++)
        if (d != axis_of(s))
            slab_vol *= rc_v3_get(s->box, d);
    fprintf(a.f, "# relcol-sim: profiles of the gas in the field (coupling %s, g %.17g, c %.17g), "
            "%d states gathered; z the slab's centre; n balls per state in the slab, density "
            "n per volume; kT two ways (along: <p_z v_z>, across: <p_perp.v_perp>/(d-1)); "
            "kT_sqrt_g00 = (1 + g z/c^2) <p.v>/d (equivalence; else <p.v>/d); *_err standard "
            "errors\n",
            s->gravity->name, s->g, s->c, p->samples);
    fprintf(a.f, "z,n,n_err,density,density_err,kT_along,kT_along_err,kT_across,kT_across_err,"
            "kT_sqrt_g00,kT_sqrt_g00_err\n");
    for (int k = 0; k < SIM_PROFILE_SLABS; k++) {
        const double N = p->n[k], n = N / S, ne = sqrt(N) / S;
        double ta, tae, tc, tce, tl, tle;
        mean_err(p->along[k], p->along2[k], N, &ta, &tae);
        mean_err(p->across[k], p->across2[k], N, &tc, &tce);
        mean_err(p->lapse[k], p->lapse2[k], N, &tl, &tle);
        fprintf(a.f, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n",
                H * (k + 0.5) / SIM_PROFILE_SLABS, n, ne, n / slab_vol, ne / slab_vol, ta, tae,
                tc, tce, tl, tle);
    }
    if (app_atomic_commit(&a, err))
        return -1;
    char *gp = app_path_join(dir, "profiles.gp");
    if (!gp || app_atomic_open(&a, gp, err)) {
        free(gp);
        if (!gp)
            app_errf(err, "out of memory");
        return -1;
    }
    free(gp);
    fprintf(a.f,
            "# relcol-sim: density and temperature against height in the field (profiles.csv)\n"
            "if (!exists(\"outfile\")) outfile = 'profiles.png'\n"
            "set terminal pngcairo size 1100,500 enhanced font ',11'\n"
            "set output outfile\nset datafile separator ','\nset key top right\n"
            "set multiplot layout 1,2 title 'relcol-sim: %s coupling, g = %g, c = %g'\n"
            "set xlabel 'z'\nset ylabel 'density'\n"
            "plot 'profiles.csv' u 1:4:5 w yerrorbars pt 7 ps 0.6 t 'n(z)'\n"
            "set ylabel 'kT'\n"
            "plot 'profiles.csv' u 1:6:7 w yerrorbars pt 7 ps 0.6 t 'kT along the field', \\\n"
            "     '' u 1:8:9 w yerrorbars pt 6 ps 0.6 t 'kT across', \\\n"
            "     '' u 1:10:11 w yerrorbars pt 5 ps 0.5 t 'kT (1 + g z/c^2)'\n"
            "unset multiplot\n",
            s->gravity->name, s->g, s->c);
    if (app_atomic_commit(&a, err))
        return -1;
    if (!s->out.plots)
        return 0;
    return app_gnuplot_run(prog, dir, "profiles.gp", "profiles.png", NULL, err);
}
