/* sweep.c — relcol-shock --sweep-c (issue 40 item 4): the same initial state at each c,
 * so that the measured plateau can be held to Sod's values and to the relativistic ones
 * at once; papers/shock-tube.md, section 6. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "sweep.h"

/* per c and bin: n, v, p measured and their errors, then _rel and _sod */
enum { PQ = 12, SWEEP_MAX = 64 };
static const int meas_q[3] = {SH_N, SH_V, SH_P};

typedef struct row {
    double c, kn, p, pe, v, ve, s, se;
    size_t balls;
    unsigned long long collisions;
    rs_solution rel;
} row;

static void cnum(FILE *f, double x) { isinf(x) ? fputs("inf", f) : fprintf(f, "%.10g", x); }

static int write_rows(const char *dir, const sh_opts *o, const row *rw, int n,
                      const rs_solution *sod, char *err)
{
    app_atomic a;
    if (app_atomic_open_in(&a, dir, "sweep.csv", err))
        return -1;
    fprintf(a.f, "c,balls,collisions,t,kn,p,p_err,p_rel,p_sod,v,v_err,v_rel,v_sod,"
                 "shock,shock_err,shock_rel,shock_sod\n");
    for (int k = 0; k < n; k++) {
        const row *r = &rw[k];
        cnum(a.f, r->c);
        fprintf(a.f, ",%zu,%llu,%.10g,%.4g,%.10g,%.4g,%.10g,%.10g,%.10g,%.4g,%.10g,%.10g,"
                     "%.10g,%.4g,%.10g,%.10g\n",
                r->balls, r->collisions, o->times[o->nt - 1], r->kn, r->p, r->pe,
                r->rel.p_star, sod->p_star, r->v, r->ve, r->rel.v_star, sod->v_star, r->s,
                r->se, r->rel.headR, sod->headR);
    }
    return app_atomic_commit(&a, err);
}

static int write_profiles(const char *dir, const double *cs, int n, int nb, const double *xc,
                          const double *prof, char *err)
{
    app_atomic a;
    if (app_atomic_open_in(&a, dir, "sweep_profiles.csv", err))
        return -1;
    fprintf(a.f, "k,c,x,n,n_err,v,v_err,p,p_err,n_rel,v_rel,p_rel,n_sod,v_sod,p_sod\n");
    for (int k = 0; k < n; k++)
        for (int b = 0; b < nb; b++) {
            fprintf(a.f, "%d,", k);
            cnum(a.f, cs[k]);
            fprintf(a.f, ",%.10g", xc[b]);
            for (int q = 0; q < PQ; q++)
                fprintf(a.f, ",%.10g", prof[((size_t)k * nb + b) * PQ + q]);
            fputc('\n', a.f);
        }
    return app_atomic_commit(&a, err);
}

/* The fitted order of the balls' approach to their own c = inf value (issue 40 item 4):
 * the weighted least-squares slope of ln|q(c)/q(inf) - 1| on ln c over the finite c whose
 * deviation exceeds three of its errors (the two runs' seed errors in quadrature), its
 * error from those; beside it the exact relativistic solution's slope over the same c (the
 * local order falls below 2 as v/c grows, so -2 is the reference only at large c). */
typedef struct order {
    double slope, err, exact;
    int used;
} order;

static order fit_order(const row *rw, int n, int q)
{
    order o = {NAN, NAN, NAN, 0};
    int k0 = -1;
    for (int k = 0; k < n; k++)
        if (isinf(rw[k].c))
            k0 = k;
    if (k0 < 0)
        return o;
    double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, ex[SWEEP_MAX], ey[SWEEP_MAX];
    const double x0 = q == 0 ? rw[k0].p : q == 1 ? rw[k0].v : rw[k0].s;
    const double e0 = q == 0 ? rw[k0].pe : q == 1 ? rw[k0].ve : rw[k0].se;
    const double r0 = q == 0 ? rw[k0].rel.p_star : q == 1 ? rw[k0].rel.v_star : rw[k0].rel.headR;
    for (int k = 0; k < n; k++) {
        if (isinf(rw[k].c))
            continue;
        const double x = q == 0 ? rw[k].p : q == 1 ? rw[k].v : rw[k].s;
        const double e = q == 0 ? rw[k].pe : q == 1 ? rw[k].ve : rw[k].se;
        const double rr = q == 0 ? rw[k].rel.p_star : q == 1 ? rw[k].rel.v_star : rw[k].rel.headR;
        const double r = x / x0, dev = r - 1.0, er = fabs(r) * hypot(e / x, e0 / x0);
        if (!(fabs(dev) > 3.0 * er) || !(er > 0.0))
            continue;
        const double lx = log(rw[k].c), ly = log(fabs(dev)), sg = er / fabs(dev), w = 1.0 / (sg * sg);
        sw += w, sx += w * lx, sy += w * ly, sxx += w * lx * lx, sxy += w * lx * ly;
        ex[o.used] = lx, ey[o.used] = log(fabs(rr / r0 - 1.0));
        o.used++;
    }
    if (o.used < 2)
        return o;
    const double d = sw * sxx - sx * sx;
    o.slope = (sw * sxy - sx * sy) / d;
    o.err = sqrt(sw / d);
    double mx = 0, my = 0, cxx = 0, cxy = 0;
    for (int i = 0; i < o.used; i++)
        mx += ex[i] / o.used, my += ey[i] / o.used;
    for (int i = 0; i < o.used; i++)
        cxx += (ex[i] - mx) * (ex[i] - mx), cxy += (ex[i] - mx) * (ey[i] - my);
    o.exact = cxy / cxx;
    return o;
}

static void jnum(FILE *f, double x) { isfinite(x) ? fprintf(f, "%.6g", x) : fputs("null", f); }

static int write_summary(const char *dir, const row *rw, int n, char *err)
{
    app_atomic a;
    if (app_atomic_open_in(&a, dir, "summary.json", err))
        return -1;
    static const char *const qn[3] = {"p_star", "v_star", "shock"};
    fprintf(a.f, "{\n  \"relcol\": 1, \"program\": \"relcol-shock --sweep-c\",\n  \"order\": {\n");
    for (int q = 0; q < 3; q++) {
        const order o = fit_order(rw, n, q);
        fprintf(a.f, "    \"%s\": {\"slope\": ", qn[q]);
        jnum(a.f, o.slope);
        fputs(", \"err\": ", a.f);
        jnum(a.f, o.err);
        fputs(", \"exact_slope_same_c\": ", a.f);
        jnum(a.f, o.exact);
        fprintf(a.f, ", \"points\": %d}%s\n", o.used, q < 2 ? "," : "");
    }
    fprintf(a.f, "  }\n}\n");
    return app_atomic_commit(&a, err);
}

/* rows: one per c; columns: n, v, p with the balls' points, the relativistic solution's
 * line and Sod's dashed */
static int write_gp(const char *dir, const sh_opts *o, const double *cs, int n, char *err)
{
    app_atomic a;
    if (app_atomic_open_in(&a, dir, "sweep.gp", err))
        return -1;
    FILE *f = a.f;
    char term[96];
    snprintf(term, sizeof term, "size 1500,%d enhanced font 'Sans,10' linewidth 1.2", 80 + 260 * n);
    app_gnuplot_head(f, "sweep.png", term, 0);
    fprintf(f, "set multiplot layout %d,3 title 'relcol-shock --sweep-c: %d-D, t = %g; points: "
               "balls (seed errors), line: relativistic ideal fluid at c, dashed: Sod (c = inf)'\n",
            n, o->tube.dim, o->times[o->nt - 1]);
    fprintf(f, "set key top right font ',8'\nset xlabel 'x'\n");
    static const char *const ylab[3] = {"rest density n", "Eckart velocity v", "pressure p"};
    for (int k = 0; k < n; k++)
        for (int q = 0; q < 3; q++) {
            char cs_txt[32];
            if (isinf(cs[k]))
                snprintf(cs_txt, sizeof cs_txt, "inf");
            else
                snprintf(cs_txt, sizeof cs_txt, "%g", cs[k]);
            fprintf(f, "set ylabel '%s'\nset title 'c = %s'\n", ylab[q], cs_txt);
            const int cm = 4 + 2 * q, cr = 10 + q, csd = 13 + q;
            fprintf(f, "plot 'sweep_profiles.csv' skip 1 using 3:($1==%d?$%d:1/0):%d with "
                       "yerrorbars pt 7 ps 0.4 lc 1 title 'balls', '' skip 1 using "
                       "3:($1==%d?$%d:1/0) with lines lc 2 title 'relativistic', '' skip 1 "
                       "using 3:($1==%d?$%d:1/0) with lines dt 2 lc 3 title 'Sod'\n",
                    k, cm, cm + 1, k, cr, k, csd);
        }
    fprintf(f, "unset multiplot\n");
    return app_atomic_commit(&a, err);
}

int sh_sweep(const char *prog, const sh_opts *o, const double *cs, int n, const char *dir,
             int verbose, char *err)
{
    const sh_tube *tb = &o->tube;
    const int nb = o->bins, j = o->nt - 1;
    rs_solution sod;
    const rs_eos ideal = rs_eos_ideal(1.0 + 2.0 / tb->dim);
    rs_state L = {tb->n[0], tb->v[0], tb->n[0] * tb->T[0]}, R = {tb->n[1], tb->v[1], tb->n[1] * tb->T[1]};
    int rc = rs_solve(&ideal, INFINITY, L, R, &sod);
    if (rc) {
        app_errf(err, "Sod's (Euler) Riemann solution: %s", rs_strerror(rc));
        return -1;
    }
    row *rw = calloc((size_t)n, sizeof *rw);
    double *prof = calloc((size_t)n * nb * PQ, sizeof *prof), *xc = malloc((size_t)nb * sizeof *xc);
    if (!rw || !prof || !xc) {
        free(rw), free(prof), free(xc);
        app_errf(err, "out of memory for the sweep");
        return -1;
    }
    int st = 0;
    for (int k = 0; k < n && !st; k++) {
        sh_opts ok = *o;
        ok.tube.c = cs[k];
        sh_result r;
        char e2[APP_ERR_LEN];
        if (sh_run(&ok, &r, verbose, e2)) {
            char cf[APP_FMT_LEN];
            app_errf(err, "c = %s: %s", app_fmt(cs[k], cf), e2);
            st = -1;
            break;
        }
        row *w = &rw[k];
        w->c = cs[k], w->kn = r.kn, w->balls = r.nballs, w->collisions = r.collisions;
        w->p = r.plat_p[j], w->pe = r.plat_p_err[j], w->v = r.plat_v[j], w->ve = r.plat_v_err[j];
        w->s = r.vshock, w->se = r.vshock_err, w->rel = r.sol;
        for (int b = 0; b < nb; b++) {
            double *pr = prof + ((size_t)k * nb + b) * PQ;
            xc[b] = r.xc[b];
            for (int q = 0; q < 3; q++) {
                pr[2 * q] = r.mean[sh_idx(&r, j, b, meas_q[q])];
                pr[2 * q + 1] = r.err[sh_idx(&r, j, b, meas_q[q])];
                pr[6 + q] = r.fluid[sh_idx(&r, j, b, meas_q[q])];
            }
            rs_state s;
            if ((rc = rs_sample(&sod, (r.xc[b] - tb->x0) / o->times[j], &s))) {
                app_errf(err, "sampling Sod's solution: %s", rs_strerror(rc));
                st = -1;
                break;
            }
            pr[9] = s.rho, pr[10] = s.v, pr[11] = s.p;
        }
        sh_result_free(&r);
        if (!st && verbose) {
            char cf[APP_FMT_LEN];
            printf("c = %s: %zu balls, Kn %.3g; plateau p %.5g +- %.2g (relativistic %.5g, Sod "
                   "%.5g), v %.5g +- %.2g (%.5g, %.5g), shock %.5g +- %.2g (%.5g, %.5g)\n",
                   app_fmt(cs[k], cf), w->balls, w->kn, w->p, w->pe, w->rel.p_star, sod.p_star,
                   w->v, w->ve, w->rel.v_star, sod.v_star, w->s, w->se, w->rel.headR, sod.headR);
            fflush(stdout);
        }
    }
    int made = 0;
    if (!st && (write_rows(dir, o, rw, n, &sod, err) || write_summary(dir, rw, n, err) || write_profiles(dir, cs, n, nb, xc, prof, err) ||
                write_gp(dir, o, cs, n, err) ||
                app_gnuplot_run(prog, dir, "sweep.gp", "sweep.png", &made, err)))
        st = -1;
    if (!st && verbose)
        printf("wrote %s/sweep.csv, summary.json, sweep_profiles.csv, sweep.gp%s\n", dir, made ? ", sweep.png" : "");
    free(rw), free(prof), free(xc);
    return st;
}
