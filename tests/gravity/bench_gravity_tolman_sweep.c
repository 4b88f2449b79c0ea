/* bench_gravity_tolman_sweep — issue 41 item 3: the Tolman gradient of a colliding gas
 * (equivalence coupling, field_gas.h's box, g = 0.5, N balls of radius 0.005, one speed
 * 0.8 at the start) at c = 1, 1.5, 2, 3, inf. After t_relax, NSNAP snapshots 2 apart give
 * theta per slab (both thermometers, <p_z v_z> and <p_perp . v_perp>/2) and its weighted
 * least-squares slope d theta/dz; the closed form (papers/gravity.md section 5) is
 * theta0 / (1 + g z/c^2), theta0 the pooled lapse-weighted theta, its slope taken the same
 * way on the same slabs. chi^2 of the five slopes against the closed form (p-value), and
 * the order k of |slope| ~ c^k over the finite c fitted against the closed form's order
 * (about -2). Writes gravity_tolman_sweep.dat and .gp (gnuplot) in the working directory.
 * A benchmark, not a test: minutes of CPU. Usage: bench_gravity_tolman_sweep [N [t_relax]]. */
#include <stdio.h>

#include <gsl/gsl_cdf.h>

#include "field_gas.h"

enum { NBIN = 10, NSNAP = 40, NC = 5 };

typedef struct sweep_pt {
    double c, slope, err, cf_slope, theta0;
} sweep_pt;

/* weighted least-squares slope of y[k] +- sqrt(v[k]) against z[k] */
static void wls(const double *z, const double *y, const double *v, double *slope, double *err)
{
    double sw = 0, swz = 0, swzz = 0, swy = 0, swzy = 0;
    for (int k = 0; k < NBIN; k++)
        sw += 1 / v[k], swz += z[k] / v[k], swzz += z[k] * z[k] / v[k], swy += y[k] / v[k],
            swzy += z[k] * y[k] / v[k];
    const double det = sw * swzz - swz * swz;
    *slope = (sw * swzy - swz * swy) / det;
    *err = sqrt(sw / det);
}

static int sweep_one(double c, double g, size_t n, double t_relax, sweep_pt *out)
{
    field_cell = 0.05;
    rc_sim *s = field_gas(&rc_gravity_equivalence, c, g, n, 0.005, 0.8, 0xa02);
    if (!s)
        return RC_EINVAL;
    const double ic2 = isinf(c) ? 0.0 : 1.0 / (c * c);
    double S[3][NBIN] = {{0}}, S2[3][NBIN] = {{0}}, zs[NBIN] = {0};
    long zn[NBIN] = {0};
    int st = rc_sim_advance(s, t_relax, 0);
    for (int q = 0; q < NSNAP && st == RC_OK; q++) {
        st = rc_sim_advance(s, t_relax + 2.0 * (q + 1), 0);
        double cnt[NBIN] = {0}, th[NBIN] = {0}, lt[NBIN] = {0};
        for (size_t i = 0; i < rc_sim_count(s); i++) {
            rc_sim_ball b;
            rc_sim_get_ball(s, i, &b);
            const int k = (int)(b.x.z * NBIN);
            if (k < 0 || k >= NBIN)
                continue;
            const rc_vec3 v = rc_velocity(b.m, b.p, ic2);
            const double pv = rc_v3_dot(b.p, v) / 3.0; /* (p_z v_z + p_perp . v_perp)/3 */
            cnt[k]++, th[k] += pv, lt[k] += (1.0 + g * b.x.z * ic2) * pv;
            zs[k] += b.x.z, zn[k]++;
        }
        for (int k = 0; k < NBIN; k++) {
            const double a[2] = {th[k] / cnt[k], lt[k] / cnt[k]};
            for (int j = 0; j < 2; j++)
                S[j][k] += a[j], S2[j][k] += a[j] * a[j];
        }
    }
    rc_sim_free(&s);
    if (st != RC_OK)
        return st;
    double z[NBIN], y[NBIN], v[NBIN], lw = 0, lwy = 0;
    for (int k = 0; k < NBIN; k++) {
        z[k] = zs[k] / (double)zn[k];
        y[k] = S[0][k] / NSNAP;
        v[k] = (S2[0][k] / NSNAP - y[k] * y[k]) / (NSNAP - 1);
        const double ml = S[1][k] / NSNAP, vl = (S2[1][k] / NSNAP - ml * ml) / (NSNAP - 1);
        lw += 1 / vl, lwy += ml / vl;
    }
    out->c = c;
    out->theta0 = lwy / lw;
    wls(z, y, v, &out->slope, &out->err);
    double cf[NBIN], e;
    for (int k = 0; k < NBIN; k++)
        cf[k] = out->theta0 / (1.0 + g * z[k] * ic2);
    wls(z, cf, v, &out->cf_slope, &e);
    return RC_OK;
}

/* weighted fit of log|s| = a + k log c over the finite c; *ke its error (NULL: unweighted) */
static double order_of(const sweep_pt *P, int np, int closed, double *ke)
{
    double sw = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
    for (int j = 0; j < np; j++) {
        if (isinf(P[j].c))
            continue;
        const double x = log(P[j].c), s = closed ? P[j].cf_slope : P[j].slope;
        const double w = closed ? 1.0 : (s / P[j].err) * (s / P[j].err);
        const double yv = log(fabs(s));
        sw += w, sx += w * x, sxx += w * x * x, sy += w * yv, sxy += w * x * yv;
    }
    const double det = sw * sxx - sx * sx;
    if (ke)
        *ke = sqrt(sw / det);
    return (sw * sxy - sx * sy) / det;
}

int main(int argc, char **argv)
{
    const size_t n = argc > 1 ? (size_t)atol(argv[1]) : 2000;
    const double t_relax = argc > 2 ? atof(argv[2]) : 40.0, g = 0.5;
    const double cs[NC] = {1.0, 1.5, 2.0, 3.0, INFINITY};
    sweep_pt P[NC];
    double chi = 0;
    printf("Tolman sweep: equivalence, g %g, N %zu, relax %g, %d snapshots 2 apart\n", g, n,
           t_relax, NSNAP);
    for (int j = 0; j < NC; j++) {
        const int st = sweep_one(cs[j], g, n, t_relax, &P[j]);
        if (st != RC_OK) {
            fprintf(stderr, "c %g: %s\n", cs[j], rc_strerror(st));
            return 1;
        }
        const double d = (P[j].slope - P[j].cf_slope) / P[j].err;
        chi += d * d;
        printf("  c %-4g theta0 %.4f  d theta/dz %.4f +- %.4f (%.1f sigma from 0); closed form "
               "%.4f (%+.1f sigma)\n", cs[j], P[j].theta0, P[j].slope, P[j].err,
               -P[j].slope / P[j].err, P[j].cf_slope, d);
        fflush(stdout);
    }
    double ke;
    const double k = order_of(P, NC, 0, &ke), kc = order_of(P, NC, 1, NULL);
    printf("  slopes against the closed form: chi^2 %.2f for %d values, p %.3f\n", chi, NC,
           gsl_cdf_chisq_Q(chi, NC));
    printf("  order in c of |d theta/dz| (c 1..3): %.2f +- %.2f; closed form's %.2f "
           "(%+.1f sigma); -2 at large c\n", k, ke, kc, (k - kc) / ke);
    FILE *f = fopen("gravity_tolman_sweep.dat.tmp", "w");
    if (f) {
        fprintf(f, "# c  inv_c2  slope  err  closed_form_slope  theta0\n");
        for (int j = 0; j < NC; j++)
            fprintf(f, "%g %.9g %.9g %.9g %.9g %.9g\n", P[j].c, isinf(P[j].c) ? 0.0 : 1 / (P[j].c * P[j].c),
                    P[j].slope, P[j].err, P[j].cf_slope, P[j].theta0);
        if (fclose(f) == 0)
            rename("gravity_tolman_sweep.dat.tmp", "gravity_tolman_sweep.dat");
    }
    f = fopen("gravity_tolman_sweep.gp.tmp", "w");
    if (f) {
        fprintf(f, "set terminal pngcairo size 800,560\nset output 'gravity_tolman_sweep.png'\n"
                   "set xlabel '1/c^2'\nset ylabel '-d theta/dz'\nset key top left\n"
                   "plot 'gravity_tolman_sweep.dat' u 2:(-$3):4 w yerrorbars t 'colliding gas', "
                   "'' u 2:(-$5) w lp t 'Tolman closed form'\n");
        if (fclose(f) == 0)
            rename("gravity_tolman_sweep.gp.tmp", "gravity_tolman_sweep.gp");
    }
    (void)rc_test_checks, (void)rc_test_failures;
    return 0;
}
