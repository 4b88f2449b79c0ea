/* kn_scan.c — relcol-shock --kn-scan (issue 40 item 5): the Knudsen transition at one state,
 * one c and one read time, the mean free path set by the ball radius; papers/shock-tube.md,
 * section 7. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "distance.h"
#include "kn_scan.h"

enum { PQ = 12, SH_KN_SHOWN = 4 };
static const int meas_q[3] = {SH_N, SH_V, SH_P};

typedef struct row {
    double kn, r, packing, cpb;
    size_t balls;
    sh_dist fl, fr;
} row;

int sh_kn_radius(const sh_tube *t, double tread, double kn, double *r, double *packing, char *err)
{
    const rs_eos eos = isinf(t->c) ? rs_eos_ideal(1.0 + 2.0 / t->dim) : rs_eos_synge(t->dim);
    rs_state L = {t->n[0], t->v[0], t->n[0] * t->T[0]}, R = {t->n[1], t->v[1], t->n[1] * t->T[1]};
    rs_solution s;
    int rc = rs_solve(&eos, t->c, L, R, &s);
    if (rc) {
        app_errf(err, "the ideal-fluid Riemann solution: %s", rs_strerror(rc));
        return -1;
    }
    if (s.waveR != RS_SHOCK || !(s.headR > 0.0)) {
        app_errf(err, "the right wave is not a shock moving right (Kn is read from its travel)");
        return -1;
    }
    /* lambda = 1 / (sqrt 2 n sigma), sigma = 4 pi r^2 (3-D) or 4 r (2-D), = kn headR t */
    const double lam = kn * s.headR * tread, a = M_SQRT2 * s.rho_starR * lam;
    *r = t->dim == 3 ? sqrt(1.0 / (4.0 * M_PI * a)) : 1.0 / (4.0 * a);
    const double vol = t->dim == 3 ? 4.0 / 3.0 * M_PI * *r * *r * *r : M_PI * *r * *r;
    *packing = 0.0;
    for (int k = 0; k < 2; k++) {
        const double W = isinf(t->c) ? 1.0 : 1.0 / sqrt(1.0 - t->v[k] * t->v[k] / (t->c * t->c));
        *packing = fmax(*packing, t->n[k] * W * vol);
    }
    if (*packing > SH_KN_MAX_PACKING) {
        char kf[APP_FMT_LEN];
        app_errf(err, "Kn = %s needs radius %.4g, a start %.3g %% packed (above %g %%: the "
                 "kinetic pressure misses the virial); raise Kn or the read time, or lower "
                 "the densities", app_fmt(kn, kf), *r, 100.0 * *packing, 100.0 * SH_KN_MAX_PACKING);
        return -1;
    }
    return 0;
}

/* Kn where D_fluid - D_free changes sign from - to + between neighbours (linear in ln Kn);
 * NAN if it never does. *lo, *hi: the bracketing entries. */
static double crossing(const row *rw, int n, int *lo, int *hi)
{
    *lo = *hi = -1;
    for (int k = 0; k + 1 < n; k++) {
        const double a = rw[k].fl.d - rw[k].fr.d, b = rw[k + 1].fl.d - rw[k + 1].fr.d;
        if (a <= 0.0 && b > 0.0) {
            *lo = k, *hi = k + 1;
            const double la = log(rw[k].kn), lb = log(rw[k + 1].kn);
            return exp(la + (lb - la) * a / (a - b));
        }
    }
    return NAN;
}

static void cfmt(double c, char *buf, size_t len)
{
    if (isinf(c))
        snprintf(buf, len, "inf");
    else
        snprintf(buf, len, "%g", c);
}

static int write_rows(const char *dir, const sh_opts *o, const row *rw, int n, char *err)
{
    app_atomic a;
    if (app_atomic_open_in(&a, dir, "kn_scan.csv", err))
        return -1;
    fprintf(a.f, "kn,radius,packing,balls,seeds,collisions_per_ball,t,bins,d_fluid,d_fluid_err,"
                 "d_free,d_free_err,dn_fluid,dv_fluid,dp_fluid,dn_free,dv_free,dp_free\n");
    for (int k = 0; k < n; k++) {
        const row *r = &rw[k];
        fprintf(a.f, "%.10g,%.10g,%.4g,%zu,%d,%.6g,%.10g,%d,%.6g,%.4g,%.6g,%.4g,%.6g,%.6g,%.6g,"
                     "%.6g,%.6g,%.6g\n",
                r->kn, r->r, r->packing, r->balls, o->seeds, r->cpb, o->times[o->nt - 1],
                r->fl.bins, r->fl.d, r->fl.err, r->fr.d, r->fr.err, r->fl.dq[0], r->fl.dq[1],
                r->fl.dq[2], r->fr.dq[0], r->fr.dq[1], r->fr.dq[2]);
    }
    return app_atomic_commit(&a, err);
}

static int write_profiles(const char *dir, const row *rw, int n, int nb, const double *xc,
                          const double *prof, char *err)
{
    app_atomic a;
    if (app_atomic_open_in(&a, dir, "kn_scan_profiles.csv", err))
        return -1;
    fprintf(a.f, "k,kn,x,n,n_err,v,v_err,p,p_err,n_fluid,v_fluid,p_fluid,n_free,v_free,p_free\n");
    for (int k = 0; k < n; k++)
        for (int b = 0; b < nb; b++) {
            fprintf(a.f, "%d,%.10g,%.10g", k, rw[k].kn, xc[b]);
            for (int q = 0; q < PQ; q++)
                fprintf(a.f, ",%.10g", prof[((size_t)k * nb + b) * PQ + q]);
            fputc('\n', a.f);
        }
    return app_atomic_commit(&a, err);
}

static void jnum(FILE *f, const char *key, double x, const char *sep)
{
    if (isfinite(x))
        fprintf(f, "\"%s\": %.10g%s", key, x, sep);
    else
        fprintf(f, "\"%s\": null%s", key, sep);
}

static int write_json(const char *dir, const sh_opts *o, const row *rw, int n, double kx,
                      int lo, int hi, const rs_solution *s, char *err)
{
    const sh_tube *t = &o->tube;
    app_atomic a;
    if (app_atomic_open_in(&a, dir, "kn_scan.json", err))
        return -1;
    FILE *f = a.f;
    fprintf(f, "{\n  \"relcol\": 1, \"program\": \"relcol-shock --kn-scan\",\n  \"parameters\": {");
    fprintf(f, "\"dim\": %d, ", t->dim);
    jnum(f, "c", isinf(t->c) ? NAN : t->c, ", ");
    fprintf(f, "\"c_infinite\": %s, ", isinf(t->c) ? "true" : "false");
    jnum(f, "n_left", t->n[0], ", "), jnum(f, "n_right", t->n[1], ", ");
    jnum(f, "T_left", t->T[0], ", "), jnum(f, "T_right", t->T[1], ", ");
    jnum(f, "v_left", t->v[0], ", "), jnum(f, "v_right", t->v[1], ", ");
    jnum(f, "length", t->box.x, ", "), jnum(f, "width", t->box.y, ", ");
    jnum(f, "t", o->times[o->nt - 1], ", ");
    fprintf(f, "\"bins\": %d, \"seeds\": %d, \"balls\": %zu},\n", o->bins, o->seeds, rw[0].balls);
    fprintf(f, "  \"knudsen\": \"lambda*_R / (shock speed t): the fluid's right plateau's mean "
               "free path 1/(sqrt 2 n*_R sigma) over the shock's travel\",\n");
    fprintf(f, "  \"distance\": \"sqrt(mean over n, v, p of sum_bins[(q - q_ref)^2 - err^2] / "
               "sum_bins (q_fluid - q_free)^2), bins at xi in [headL - w/4, headR + w/4]\",\n  ");
    jnum(f, "n_star_right", s->rho_starR, ", "), jnum(f, "shock_speed", s->headR, ",\n  ");
    jnum(f, "crossing_kn", kx, ", ");
    if (lo >= 0)
        fprintf(f, "\"crossing_between\": [%.10g, %.10g]\n}\n", rw[lo].kn, rw[hi].kn);
    else
        fprintf(f, "\"crossing_between\": null\n}\n");
    (void)n;
    return app_atomic_commit(&a, err);
}

/* the title's state: dimension, c, densities, temperatures, balls, seeds, time */
static void state_txt(const sh_opts *o, size_t balls, char *buf, size_t len)
{
    const sh_tube *t = &o->tube;
    char cs[32];
    cfmt(t->c, cs, sizeof cs);
    snprintf(buf, len, "%d-D, c = %s, n %g | %g, T %g | %g, v %g | %g; %zu balls, %d seeds, t = %g",
             t->dim, cs, t->n[0], t->n[1], t->T[0], t->T[1], t->v[0], t->v[1], balls, o->seeds,
             o->times[o->nt - 1]);
}

static int write_gp(const char *dir, const sh_opts *o, const row *rw, int n, double kx, char *err)
{
    app_atomic a;
    if (app_atomic_open_in(&a, dir, "kn_scan.gp", err))
        return -1;
    FILE *f = a.f;
    char st[256];
    state_txt(o, rw[0].balls, st, sizeof st);
    app_gnuplot_head(f, "kn_scan.png", "size 1100,720 enhanced font 'Sans,12' linewidth 1.4", 0);
    fprintf(f, "set title \"relcol-shock --kn-scan: the Knudsen transition\\n%s\" font ',11'\n", st);
    fprintf(f, "set logscale x\nset xlabel 'Kn = {/Symbol l}*_R / (shock speed t)'\n"
               "set ylabel 'normalised L2 distance of n, v, p (0: the reference, 1: the other)'\n"
               "set yrange [0:*]\nset key outside bottom center horizontal font ',10'\nset grid\n");
    fprintf(f, "set arrow from 0.5, graph 0 to 0.5, graph 1 nohead dt 3 lc rgb 'gray40'\n"
               "set label 'Bouras et al.: Kn = 1/2 (their Kn)' at 0.5, graph 0.04 left offset 0.5,0 "
               "font ',9' tc rgb 'gray40'\n");
    if (isfinite(kx))
        fprintf(f, "set arrow from %.6g, graph 0 to %.6g, graph 1 nohead dt 2 lc rgb 'black'\n"
                   "set label 'crossing Kn = %.3g' at %.6g, graph 0.88 left offset 0.5,0 font ',10'\n",
                kx, kx, kx, kx);
    fprintf(f, "plot 'kn_scan.csv' skip 1 using 1:9:10 with yerrorlines pt 7 lc 1 title "
               "'from the ideal fluid (errors: seed noise)', '' skip 1 using 1:11:12 with "
               "yerrorlines pt 5 lc 2 title 'from free streaming'\n");
    (void)n;
    return app_atomic_commit(&a, err);
}

/* up to SH_KN_SHOWN entries spread over the list, always the first and the last */
static int shown(int n, int *idx)
{
    int m = 0;
    for (int i = 0; i < SH_KN_SHOWN && i < n; i++) {
        const int k = n <= SH_KN_SHOWN ? i : (int)lround((double)i * (n - 1) / (SH_KN_SHOWN - 1));
        if (!m || idx[m - 1] != k)
            idx[m++] = k;
    }
    return m;
}

static int write_gp_profiles(const char *dir, const sh_opts *o, const row *rw, int n, char *err)
{
    app_atomic a;
    if (app_atomic_open_in(&a, dir, "kn_scan_profiles.gp", err))
        return -1;
    FILE *f = a.f;
    int idx[SH_KN_SHOWN];
    const int m = shown(n, idx);
    char st[256], term[96];
    state_txt(o, rw[0].balls, st, sizeof st);
    snprintf(term, sizeof term, "size 1500,%d enhanced font 'Sans,10' linewidth 1.2", 100 + 260 * m);
    app_gnuplot_head(f, "kn_scan_profiles.png", term, 0);
    fprintf(f, "set multiplot layout %d,3 title \"relcol-shock --kn-scan: %s\\npoints: balls "
               "(seed errors), line: ideal fluid, dashed: free streaming\"\n", m, st);
    fprintf(f, "set key top right font ',8'\nset xlabel 'x'\n");
    static const char *const ylab[3] = {"rest density n", "Eckart velocity v", "pressure p"};
    for (int i = 0; i < m; i++)
        for (int q = 0; q < 3; q++) {
            const int k = idx[i], cm = 4 + 2 * q, cf = 10 + q, cs = 13 + q;
            fprintf(f, "set ylabel '%s'\nset title 'Kn = %.3g (radius %.3g)'\n", ylab[q], rw[k].kn, rw[k].r);
            fprintf(f, "plot 'kn_scan_profiles.csv' skip 1 using 3:($1==%d?$%d:1/0):%d with "
                       "yerrorbars pt 7 ps 0.4 lc 1 title 'balls', '' skip 1 using "
                       "3:($1==%d?$%d:1/0) with lines lc 2 title 'ideal fluid', '' skip 1 "
                       "using 3:($1==%d?$%d:1/0) with lines dt 2 lc 3 title 'free streaming'\n",
                    k, cm, cm + 1, k, cf, k, cs);
        }
    fprintf(f, "unset multiplot\n");
    return app_atomic_commit(&a, err);
}

int sh_kn_scan(const char *prog, const sh_opts *o, const double *kn, int n, const char *dir,
               int verbose, char *err)
{
    const int nb = o->bins, j = o->nt - 1;
    const double tread = o->times[j];
    row *rw = calloc((size_t)n, sizeof *rw);
    double *prof = calloc((size_t)n * nb * PQ, sizeof *prof), *xc = malloc((size_t)nb * sizeof *xc);
    if (!rw || !prof || !xc) {
        free(rw), free(prof), free(xc);
        app_errf(err, "out of memory for the scan");
        return -1;
    }
    rs_solution sol;
    memset(&sol, 0, sizeof sol);
    int st = 0;
    for (int k = 0; k < n && !st; k++) {
        sh_opts ok = *o;
        row *w = &rw[k];
        w->kn = kn[k];
        if (sh_kn_radius(&o->tube, tread, kn[k], &w->r, &w->packing, err)) {
            st = -1;
            break;
        }
        ok.tube.r = w->r;
        sh_result r;
        char e2[APP_ERR_LEN], kf[APP_FMT_LEN];
        if (sh_run(&ok, &r, verbose, e2)) {
            app_errf(err, "Kn = %s: %s", app_fmt(kn[k], kf), e2);
            st = -1;
            break;
        }
        sol = r.sol;
        w->balls = r.nballs;
        w->cpb = 2.0 * (double)r.collisions / ((double)r.nballs * r.seeds); /* two balls each */
        int k0, k1;
        sh_dist_span(&r, ok.tube.x0, tread, &k0, &k1);
        if (sh_distance(&r, j, k0, k1, SH_REF_FLUID, &w->fl) ||
            sh_distance(&r, j, k0, k1, SH_REF_FREE, &w->fr)) {
            app_errf(err, "the two references coincide over the tube: no waves to measure");
            sh_result_free(&r);
            st = -1;
            break;
        }
        for (int b = 0; b < nb; b++) {
            double *pr = prof + ((size_t)k * nb + b) * PQ;
            xc[b] = r.xc[b];
            for (int q = 0; q < 3; q++) {
                const size_t i = sh_idx(&r, j, b, meas_q[q]);
                pr[2 * q] = r.mean[i], pr[2 * q + 1] = r.err[i];
                pr[6 + q] = r.fluid[i], pr[9 + q] = r.freestr[i];
            }
        }
        sh_result_free(&r);
        if (verbose) {
            printf("Kn = %s (radius %.4g, packing %.2g %%, %.3g collisions a ball): distance "
                   "from the fluid %.4f +- %.2g, from free streaming %.4f +- %.2g\n",
                   app_fmt(kn[k], kf), w->r, 100.0 * w->packing, w->cpb, w->fl.d, w->fl.err,
                   w->fr.d, w->fr.err);
            fflush(stdout);
        }
    }
    int lo = -1, hi = -1, made = 0, made2 = 0;
    const double kx = st ? NAN : crossing(rw, n, &lo, &hi);
    if (!st && (write_rows(dir, o, rw, n, err) || write_profiles(dir, rw, n, nb, xc, prof, err) ||
                write_json(dir, o, rw, n, kx, lo, hi, &sol, err) || write_gp(dir, o, rw, n, kx, err) ||
                write_gp_profiles(dir, o, rw, n, err) ||
                app_gnuplot_run(prog, dir, "kn_scan.gp", "kn_scan.png", &made, err) ||
                app_gnuplot_run(prog, dir, "kn_scan_profiles.gp", "kn_scan_profiles.png", &made2, err)))
        st = -1;
    if (!st && verbose) {
        if (lo >= 0)
            printf("the distances cross at Kn = %.3g (between %g and %g)\n", kx, rw[lo].kn, rw[hi].kn);
        else
            printf("the distances do not cross from fluid-nearer to free-nearer inside the list\n");
        printf("wrote %s/kn_scan.csv, kn_scan_profiles.csv, kn_scan.json, kn_scan.gp, "
               "kn_scan_profiles.gp%s\n", dir, made && made2 ? ", kn_scan.png, kn_scan_profiles.png" : "");
    }
    free(rw), free(prof), free(xc);
    return st;
}
