/* heat.c — relcol-heat: a hard-ball gas conducting heat between two thermal walls (issue 39
 * item 5; Ghodrat & Montakhab's set-up, arXiv:1302.5137): the wall x = 0 at kT_hot, the wall
 * x = L at kT_cold (relcol/wall.h's thermal rule), y and z periodic. After a warm-up it
 * samples the steady state in bins along x and writes the profiles of the density, the
 * temperature by two thermometers, the energy flux T^0x and the kinetic pressure, with
 * batch-means errors; the walls' temperature jumps; and the heat conductivity from
 * Fourier's law next to the Chapman–Enskog one (apps/eos/ce_rel.c). papers/transport.md,
 * section 9. Exit status: 0 done, 2 bad option, 1 a run or I/O failure. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>
#include <gsl/gsl_sf_bessel.h>

#include "app.h"
#include "ce_rel.h"

static const char *const prog = "relcol-heat";

enum { EXIT_BAD = 2, NBLOCK = 16, MAXBIN = 200, CE_ORDER = 12 };
#define RADIUS 0.5 /* every ball: d = 1, sigma_T = pi d^2 = pi */
#define MASS 1.0

#define fail(...) app_fail(prog, EXIT_BAD, __VA_ARGS__)

typedef struct options {
    double c, packing, hot, cold, aspect, warmup, time, every;
    long n;
    int bins;
    uint64_t seed;
    const char *out;
    const rc_toi_frame *frame; /* NULL: the engine's sphere kernel */
} options;

#define OFF(field) offsetof(options, field)
static const app_opt opts[] = {
    {"--c", "C|inf", APP_T_DOUBLE_INF, OFF(c), "inf",
     .help = "speed of light, > 0 (default %D: classical)"},
    {"--n", "N", APP_T_LONG, OFF(n), "1000", .lo = 16, .hi = 10000000,
     .help = "balls, rest mass 1, radius 0.5 (default %D)"},
    {"--packing", "PHI", APP_T_DOUBLE, OFF(packing), "0.02",
     .help = "packing fraction in (0, 0.3] (default %D: a dilute gas)"},
    {"--hot", "KT", APP_T_DOUBLE, OFF(hot), "1.2",
     .help = "temperature kT of the wall x = 0 (default %D)"},
    {"--cold", "KT", APP_T_DOUBLE, OFF(cold), "0.8",
     .help = "temperature kT of the wall x = L, below --hot (default %D)"},
    {"--aspect", "A", APP_T_DOUBLE, OFF(aspect), "8",
     .help = "box length along x over its periodic y and z edges, >= 1 (default %D)"},
    {"--bins", "B", APP_T_INT, OFF(bins), "20", .lo = 4, .hi = MAXBIN,
     .help = "bins along x of the profiles (default %D)"},
    {"--warmup", "T", APP_T_DOUBLE, OFF(warmup), "3000",
     .help = "time before sampling, >= 0 (default %D)"},
    {"--time", "T", APP_T_DOUBLE, OFF(time), "6000",
     .help = "time sampled after the warm-up, > 0 (default %D)"},
    {"--every", "DT", APP_T_DOUBLE, OFF(every), "5",
     .help = "time between snapshots, > 0; at least 32 of them (default %D)"},
    {"--frame", "NAME", APP_T_CUSTOM, OFF(frame), .parse = app_opt_toi_frame,
     .help = "contact frame (relcol/toi.h; default: the engine's sphere kernel); not a\n"
             "per-ball one (covariant), whose rollbacks would take back the walls' draws"},
    {"--seed", "N", APP_T_U64, OFF(seed), "1", .help = "seed of the start and of the walls (default %D)"},
    {"--out", "DIR", APP_T_CUSTOM, OFF(out), "out/heat", .parse = app_opt_dir,
     .help = "output folder (default %D)"},
    {NULL},
};

static void usage(FILE *f)
{
    fprintf(f,
"usage: relcol-heat [--c C|inf] [--n N] [--packing PHI] [--hot KT] [--cold KT]\n"
"                   [--aspect A] [--bins B] [--warmup T] [--time T] [--every DT]\n"
"                   [--frame NAME] [--seed N] [--out DIR]\n"
"\n"
"A 3-D hard-ball gas between a thermal wall at x = 0 (kT = --hot) and one at x = L\n"
"(kT = --cold), y and z periodic: each ball meeting a wall leaves it with a momentum\n"
"drawn from the wall-flux Juttner law at the wall's temperature. After --warmup the\n"
"steady state is sampled every --every for --time, in --bins bins along x, errors from\n"
"16 blocks. Units: ball mass 1, radius 0.5 (sigma_T = pi), k = 1.\n"
"\n"
"options:\n");
    app_opts_help(f, opts, 19);
    fprintf(f,
"\n"
"outputs in DIR (each written to a temporary name, then renamed):\n"
"  profile.csv   per bin of the centres' range [0.5, L - 0.5]: x, n, theta_pv (kT\n"
"                from <p.v> = 3 kT), theta_k (kT whose Juttner <K> is the bin's; the\n"
"                same as theta_pv classically), T0x (energy flux), p_kin (n <p_x v_x>),\n"
"                each with its error (_err)\n"
"  summary.json  the run, the walls' heat rates per area (hot gives, cold takes), the\n"
"                pressure on each wall, the temperature jumps at the walls (the wall's kT\n"
"                minus the central half's linear fit there), lambda from Fourier's law\n"
"                (-q / dT/dx over the central half, both thermometers) next to the dilute\n"
"                Chapman-Enskog lambda (the invariant Boltzmann gas, apps/eos/ce_rel.c, at\n"
"                the fit's mid temperature; classically with Enskog's dense factor too),\n"
"                and the validity report (model: the rigid-ball model's verdict)\n"
"  heat.gp, heat.png  the profiles (with gnuplot)\n"
"stdout: one line, lambda measured and Chapman-Enskog's.\n"
"\n"
"exit status: 0 done; 2 bad option (one line naming it); 1 a failed run or write.\n");
}

/* the box: V = N (4/3) pi r^3 / phi, L_y = L_z = (V / aspect)^(1/3), L_x = aspect L_y */
static void box_of(const options *o, double *Lx, double *Ly)
{
    const double V = (double)o->n * (4.0 / 3.0) * M_PI * RADIUS * RADIUS * RADIUS / o->packing;
    *Ly = cbrt(V / o->aspect);
    *Lx = o->aspect * *Ly;
}

static int check_options(void *vo)
{
    const options *o = vo;
    char err[APP_ERR_LEN], f[APP_FMT_LEN];
    if (app_check_c(o->c, err) != 0)
        return fail("--c: %s", err);
    if (!(o->packing > 0.0 && o->packing <= 0.3))
        return fail("--packing: %s must be in (0, 0.3]", app_fmt(o->packing, f));
    if (!(o->hot > 0.0))
        return fail("--hot: kT = %s must be > 0", app_fmt(o->hot, f));
    if (!(o->cold > 0.0))
        return fail("--cold: kT = %s must be > 0", app_fmt(o->cold, f));
    if (!(o->hot > o->cold))
        return fail("--hot: kT = %s must be above --cold's %s (heat flows from x = 0)",
                    app_fmt(o->hot, f), app_fmt(o->cold, err));
    if (!(o->aspect >= 1.0 && o->aspect <= 1e4))
        return fail("--aspect: %s must be in [1, 1e4]", app_fmt(o->aspect, f));
    if (!(o->warmup >= 0.0))
        return fail("--warmup: %s must be >= 0", app_fmt(o->warmup, f));
    if (!(o->time > 0.0))
        return fail("--time: %s must be > 0", app_fmt(o->time, f));
    if (!(o->every > 0.0))
        return fail("--every: %s must be > 0", app_fmt(o->every, f));
    if (!(o->time / o->every >= 2.0 * NBLOCK))
        return fail("--every: --time / --every = %s snapshots, fewer than %d (2 per block)",
                    app_fmt(floor(o->time / o->every), f), 2 * NBLOCK);
    if (o->time / o->every > 1e8)
        return fail("--every: more than 1e8 snapshots");
    if (o->frame && o->frame->per_ball)
        return fail("--frame: %s is a per-ball frame: its rollbacks would take back the "
                    "thermal walls' draws", o->frame->name);
    double Lx, Ly;
    box_of(o, &Lx, &Ly);
    /* periodic y and z need four cells of a diameter (and a margin for the cells' round-off) */
    if (!(Ly >= 4.0 * 2.0 * RADIUS * (1.0 + 1e-6)))
        return fail("--aspect: the periodic edges L_y = L_z = %s are under 4 ball diameters: "
                    "raise --n or lower --aspect", app_fmt(Ly, f));
    return 0;
}

static const app_cli cli = {.prog = prog, .tab = opts, .usage = usage,
                            .stray_hint = "relcol-heat takes no arguments; see --help",
                            .bad = EXIT_BAD, .check = check_options};

/* ---- thermometers and references ------------------------------------------------- */

/* <K> / kT of the Juttner law at z = m c^2 / kT: 3/2 classically; K1/K2 + 3/z - 1 times z
 * where that does not cancel (z < 50), else ce_rel's quadrature. NAN on failure. */
static double mean_k_over_kT(double z)
{
    if (isinf(z))
        return 1.5;
    if (z < 50.0) {
        gsl_sf_result k1, k2;
        if (gsl_sf_bessel_Kn_scaled_e(1, z, &k1) || gsl_sf_bessel_Kn_scaled_e(2, z, &k2))
            return NAN;
        return z * (k1.val / k2.val - 1.0) + 3.0;
    }
    ce_rel_juttner j;
    const char *why;
    return ce_rel_juttner_moments(z, &j, &why) == 0 ? j.mean_k : NAN;
}

/* The kT whose Juttner <K> is mk (bisection: <K> grows with kT). */
static double theta_of_k(double mk, double c)
{
    if (isinf(c))
        return mk / 1.5;
    if (!(mk > 0.0))
        return NAN;
    double lo = mk / 3.0 * 0.5, hi = mk / 1.5 * 2.0; /* (<K>/kT is in [3/2, 3]) */
    for (int it = 0; it < 80; it++) {
        const double mid = 0.5 * (lo + hi);
        const double g = mid * mean_k_over_kT(MASS * c * c / mid);
        if (isnan(g))
            return NAN;
        *(g < mk ? &lo : &hi) = mid;
    }
    return 0.5 * (lo + hi);
}

/* Dilute Chapman–Enskog lambda at kT (order CE_ORDER = 12: 2.5e-5 from order 16 at z = 1;
 * papers/transport.md section 6), in k c / sigma_T times c / sigma_T; classically the
 * z -> inf limit lambda sqrt(z) sqrt(kT / m) from z = 1e4 (its 1/z correction 1e-4). */
static double lambda_ce(double kT, double c, const char **why)
{
    const double sigma = M_PI * (2.0 * RADIUS) * (2.0 * RADIUS);
    ce_rel_coeffs co;
    if (isinf(c)) {
        const double zb = 1e4;
        if (ce_rel_compute(zb, CE_ORDER, NULL, &co, why) != 0)
            return NAN;
        return co.lambda * sqrt(zb) * sqrt(kT / MASS) / sigma;
    }
    if (ce_rel_compute(MASS * c * c / kT, CE_ORDER, NULL, &co, why) != 0)
        return NAN;
    return co.lambda * c / sigma;
}

/* Enskog's dense-gas factor of lambda (Chapman & Cowling 16.5): 1/chi + (6/5) b rho +
 * 0.7575 (b rho)^2 chi, b rho = 4 phi, chi Carnahan–Starling's contact value. */
static double enskog_factor(double phi)
{
    const double chi = (1.0 - phi / 2.0) / ((1.0 - phi) * (1.0 - phi) * (1.0 - phi));
    const double br = 4.0 * phi;
    return 1.0 / chi + 1.2 * br + 0.7575 * br * br * chi;
}

/* ---- sampling --------------------------------------------------------------------- */

typedef struct stat {
    double mean, err;
} stat;

static stat batch(const double *x, int nb)
{
    double s = 0.0, s2 = 0.0;
    int k = 0;
    for (int b = 0; b < nb; b++)
        if (isfinite(x[b])) {
            s += x[b];
            s2 += x[b] * x[b];
            k++;
        }
    if (k < 2)
        return (stat){k ? s : NAN, NAN};
    const double m = s / k;
    return (stat){m, sqrt(fmax(s2 / k - m * m, 0.0) / (k - 1))};
}

/* least-squares line through (x[i], y[i]), i in [lo, hi): slope and value at x0 */
static void line_fit(const double *x, const double *y, int lo, int hi, double *slope, double *a0)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const int k = hi - lo;
    for (int i = lo; i < hi; i++) {
        sx += x[i];
        sy += y[i];
        sxx += x[i] * x[i];
        sxy += x[i] * y[i];
    }
    *slope = (k * sxy - sx * sy) / (k * sxx - sx * sx);
    *a0 = (sy - *slope * sx) / k;
}

typedef struct block {
    double n[MAXBIN], th_pv[MAXBIN], th_k[MAXBIN], t0x[MAXBIN], pkin[MAXBIN];
    double q_hot, q_cold, p_hot, p_cold;      /* per area and time */
    double lam_pv, lam_k, jump_hot, jump_cold, t_mid;
} block;

typedef struct result {
    stat n[MAXBIN], th_pv[MAXBIN], th_k[MAXBIN], t0x[MAXBIN], pkin[MAXBIN];
    stat q_hot, q_cold, p_hot, p_cold, lam_pv, lam_k, jump_hot, jump_cold, t_mid;
    double lam_ce, lam_enskog, mfp, Lx, Ly;
    double fit_slope, fit_a0; /* the mean profile's line (theta_pv) over the central half */
    uint64_t collisions, wall_events;
    size_t snapshots;
    rc_validity v; /* where the run stands against the rigid-ball model (relcol/validity.h) */
    int have_v;
} result;

static double kinetic(const rc_sim_ball *b, double c, double *M)
{
    const double p2 = rc_v3_norm2(b->p);
    *M = isinf(c) ? b->m : sqrt(b->m * b->m + p2 / (c * c));
    return p2 / (*M + b->m);
}

/* Run the gas and fill r; 0, or -1 with the reason in err. */
static int run(const options *o, result *r, char *err)
{
    double Lx, Ly;
    box_of(o, &Lx, &Ly);
    r->Lx = Lx;
    r->Ly = Ly;
    const size_t n = (size_t)o->n;
    const int B = o->bins;
    rc_sim_def d = rc_sim_def_default();
    d.dim = 3;
    d.c = o->c;
    d.box = rc_v3(Lx, Ly, Ly);
    d.boundary[1] = d.boundary[2] = RC_SIM_PERIODIC;
    d.frame = o->frame;
    d.wall_rule[0] = d.wall_rule[1] = &rc_wall_thermal;
    d.wall_kT[0] = o->hot;
    d.wall_kT[1] = o->cold;
    rc_rng sr = {o->seed ^ 0x68656174ULL}; /* (the walls' stream apart from the start's) */
    d.wall_seed = rc_rng_next(&sr);
    /* the start: a simple cubic grid filling the box, momenta Gaussian at the mean kT */
    const long ny = (long)ceil(cbrt((double)n / o->aspect)), nx = (long)ceil((double)n / (double)(ny * ny));
    const double ax = Lx / (double)nx, ay = Ly / (double)ny;
    if (!(ax > 2.0 * RADIUS * (1.0 + 1e-9) && ay > 2.0 * RADIUS * (1.0 + 1e-9))) {
        app_errf(err, "--packing: %g leaves no room for a grid start of %ld balls (spacing %g "
                 "x %g, diameter 1)", o->packing, o->n, ax, ay);
        return -1;
    }
    rc_sim_ball *b = calloc(n, sizeof *b);
    block *blk = calloc(NBLOCK, sizeof *blk);
    double *acc = calloc(5 * (size_t)B, sizeof *acc);
    rc_sim *s = NULL;
    int rc = -1, st;
    if (!b || !blk || !acc) {
        app_errf(err, "out of memory");
        goto out;
    }
    rc_rng rr = {o->seed};
    const double sp = sqrt(MASS * 0.5 * (o->hot + o->cold));
    for (size_t i = 0; i < n; i++) {
        const long ix = (long)i / (ny * ny), iy = ((long)i / ny) % ny, iz = (long)i % ny;
        b[i].x = rc_v3((ix + 0.5) * ax, (iy + 0.5) * ay, (iz + 0.5) * ay);
        b[i].r = RADIUS;
        b[i].m = MASS;
        b[i].p = rc_v3(sp * rc_rng_gauss(&rr), sp * rc_rng_gauss(&rr), sp * rc_rng_gauss(&rr));
    }
    if ((st = rc_sim_create(&d, &s)) != RC_OK || (st = rc_sim_set_balls(s, n, b, NULL)) != RC_OK) {
        app_errf(err, "the engine refused the start: %s", rc_strerror(st));
        goto out;
    }
    if ((st = rc_sim_advance(s, o->warmup, 0)) != RC_OK) {
        app_errf(err, "warm-up: %s", rc_strerror(st));
        goto out;
    }
    const size_t nsnap = (size_t)floor(o->time / o->every), per = nsnap / NBLOCK;
    r->snapshots = per * NBLOCK;
    /* bins over the centres' range [r, L - r], so that each holds its whole volume */
    const double A = Ly * Ly, dx = (Lx - 2.0 * RADIUS) / B, Vbin = dx * A;
    double t = o->warmup;
    rc_sim_diag d0, d1;
    rc_sim_diagnostics(s, &d0);
    const rc_sim_diag dstart = d0;
    double xc[MAXBIN];
    for (int k = 0; k < B; k++)
        xc[k] = RADIUS + (k + 0.5) * dx;
    const int lo = B / 4, hi = B - B / 4; /* the central half: the walls' Knudsen layers out */
    for (int q = 0; q < NBLOCK; q++) {
        memset(acc, 0, 5 * (size_t)B * sizeof *acc);
        const double t0 = t;
        for (size_t j = 0; j < per; j++) {
            t = o->warmup + o->every * (double)(q * per + j + 1);
            if ((st = rc_sim_advance(s, t, 0)) != RC_OK ||
                (st = rc_sim_get_balls(s, n, b, 0, NULL)) != RC_OK) {
                app_errf(err, "at t = %g: %s", t, rc_strerror(st));
                goto out;
            }
            for (size_t i = 0; i < n; i++) {
                double M;
                const double K = kinetic(&b[i], o->c, &M);
                int k = (int)((b[i].x.x - RADIUS) / dx);
                k = k < 0 ? 0 : k >= B ? B - 1 : k;
                const double vx = b[i].p.x / M;
                acc[5 * k] += 1.0;
                acc[5 * k + 1] += K;
                acc[5 * k + 2] += rc_v3_norm2(b[i].p) / M; /* p.v */
                acc[5 * k + 3] += K * vx;
                acc[5 * k + 4] += b[i].p.x * vx;
            }
        }
        block *bl = &blk[q];
        for (int k = 0; k < B; k++) {
            const double cnt = acc[5 * k];
            bl->n[k] = cnt / (Vbin * per);
            bl->th_pv[k] = cnt > 0 ? acc[5 * k + 2] / (3.0 * cnt) : NAN;
            bl->th_k[k] = cnt > 0 ? theta_of_k(acc[5 * k + 1] / cnt, o->c) : NAN;
            bl->t0x[k] = acc[5 * k + 3] / (Vbin * per);
            bl->pkin[k] = acc[5 * k + 4] / (Vbin * per);
        }
        rc_sim_diagnostics(s, &d1);
        const double span = (t - t0) * A;
        bl->q_hot = -(d1.wall_heat_by_wall[0] - d0.wall_heat_by_wall[0]) / span;
        bl->q_cold = (d1.wall_heat_by_wall[1] - d0.wall_heat_by_wall[1]) / span;
        bl->p_hot = -(d1.wall_impulse_by_wall[0] - d0.wall_impulse_by_wall[0]) / span;
        bl->p_cold = (d1.wall_impulse_by_wall[1] - d0.wall_impulse_by_wall[1]) / span;
        d0 = d1;
        const double qm = 0.5 * (bl->q_hot + bl->q_cold);
        double sl, a0;
        line_fit(xc, bl->th_k, lo, hi, &sl, &a0);
        bl->lam_k = -qm / sl;
        line_fit(xc, bl->th_pv, lo, hi, &sl, &a0);
        bl->lam_pv = -qm / sl;
        bl->jump_hot = o->hot - a0;
        bl->jump_cold = (a0 + sl * Lx) - o->cold;
        bl->t_mid = a0 + sl * 0.5 * Lx;
    }
    /* per quantity: the blocks' mean and batch error */
    double col[NBLOCK];
#define BATCH(field, dst)                                                                  \
    do {                                                                                   \
        for (int q_ = 0; q_ < NBLOCK; q_++)                                                \
            col[q_] = blk[q_].field;                                                       \
        dst = batch(col, NBLOCK);                                                          \
    } while (0)
    for (int k = 0; k < B; k++) {
        BATCH(n[k], r->n[k]);
        BATCH(th_pv[k], r->th_pv[k]);
        BATCH(th_k[k], r->th_k[k]);
        BATCH(t0x[k], r->t0x[k]);
        BATCH(pkin[k], r->pkin[k]);
    }
    BATCH(q_hot, r->q_hot);
    BATCH(q_cold, r->q_cold);
    BATCH(p_hot, r->p_hot);
    BATCH(p_cold, r->p_cold);
    BATCH(lam_pv, r->lam_pv);
    BATCH(lam_k, r->lam_k);
    BATCH(jump_hot, r->jump_hot);
    BATCH(jump_cold, r->jump_cold);
    BATCH(t_mid, r->t_mid);
#undef BATCH
    double mean_th[MAXBIN];
    for (int k = 0; k < B; k++)
        mean_th[k] = r->th_pv[k].mean;
    line_fit(xc, mean_th, lo, hi, &r->fit_slope, &r->fit_a0);
    const char *why = NULL;
    r->lam_ce = lambda_ce(r->t_mid.mean, o->c, &why);
    if (isnan(r->lam_ce)) {
        app_errf(err, "Chapman-Enskog lambda: %s", why ? why : "failed");
        goto out;
    }
    r->lam_enskog = isinf(o->c) ? r->lam_ce * enskog_factor(o->packing) : NAN;
    const double nd = (double)n / (Lx * A);
    r->mfp = 1.0 / (sqrt(2.0) * nd * M_PI * (2.0 * RADIUS) * (2.0 * RADIUS));
    rc_sim_diagnostics(s, &d1);
    r->collisions = d1.events[RC_SIM_EV_BALL] + d1.events[RC_SIM_EV_MULTI] -
                    dstart.events[RC_SIM_EV_BALL] - dstart.events[RC_SIM_EV_MULTI];
    r->wall_events = d1.events[RC_SIM_EV_WALL] - dstart.events[RC_SIM_EV_WALL];
    r->have_v = rc_sim_validity(s, &r->v) == RC_OK;
    app_validity_note(s);
    app_rules_warn(stderr, prog, &d1, NULL);
    rc = 0;
out:
    rc_sim_free(&s);
    free(b);
    free(blk);
    free(acc);
    return rc;
}

/* ---- outputs ---------------------------------------------------------------------- */

static int write_profile(const char *path, const options *o, const result *r, char *err)
{
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0)
        return -1;
    fprintf(a.f, "x,n,n_err,theta_pv,theta_pv_err,theta_k,theta_k_err,T0x,T0x_err,p_kin,p_kin_err\n");
    for (int k = 0; k < o->bins; k++)
        fprintf(a.f, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                RADIUS + (k + 0.5) * (r->Lx - 2.0 * RADIUS) / o->bins, r->n[k].mean, r->n[k].err, r->th_pv[k].mean,
                r->th_pv[k].err, r->th_k[k].mean, r->th_k[k].err, r->t0x[k].mean, r->t0x[k].err,
                r->pkin[k].mean, r->pkin[k].err);
    return app_atomic_commit(&a, err);
}

static cJSON *num(double x)
{
    if (!isfinite(x))
        return cJSON_CreateNull();
    char b[32];
    snprintf(b, sizeof b, "%.17g", x);
    return cJSON_CreateRaw(b);
}

static void put_stat(cJSON *o, const char *key, stat s)
{
    cJSON *x = cJSON_CreateObject();
    cJSON_AddItemToObject(x, "value", num(s.mean));
    cJSON_AddItemToObject(x, "err", num(s.err));
    cJSON_AddItemToObject(o, key, x);
}

static int write_summary(const char *path, const options *o, const result *r, char *err)
{
    cJSON *j = cJSON_CreateObject();
    if (!j) {
        app_errf(err, "out of memory");
        return -1;
    }
    cJSON_AddStringToObject(j, "program", prog);
    cJSON_AddItemToObject(j, "c", num(o->c));
    if (isinf(o->c))
        cJSON_ReplaceItemInObject(j, "c", cJSON_CreateString("inf"));
    cJSON_AddStringToObject(j, "contact_frame", o->frame ? o->frame->name : "sphere kernel");
    cJSON_AddItemToObject(j, "n", num((double)o->n));
    cJSON_AddItemToObject(j, "packing", num(o->packing));
    cJSON_AddItemToObject(j, "kT_hot", num(o->hot));
    cJSON_AddItemToObject(j, "kT_cold", num(o->cold));
    cJSON *bx = cJSON_CreateArray();
    cJSON_AddItemToArray(bx, num(r->Lx));
    cJSON_AddItemToArray(bx, num(r->Ly));
    cJSON_AddItemToArray(bx, num(r->Ly));
    cJSON_AddItemToObject(j, "box", bx);
    cJSON_AddItemToObject(j, "mean_free_path", num(r->mfp));
    cJSON_AddItemToObject(j, "knudsen_number", num(r->mfp / r->Lx));
    cJSON_AddItemToObject(j, "warmup", num(o->warmup));
    cJSON_AddItemToObject(j, "time", num(o->time));
    cJSON_AddItemToObject(j, "snapshots", num((double)r->snapshots));
    cJSON_AddItemToObject(j, "ball_collisions", num((double)r->collisions));
    cJSON_AddItemToObject(j, "wall_collisions", num((double)r->wall_events));
    put_stat(j, "heat_flux_hot_wall", r->q_hot);
    put_stat(j, "heat_flux_cold_wall", r->q_cold);
    put_stat(j, "pressure_hot_wall", r->p_hot);
    put_stat(j, "pressure_cold_wall", r->p_cold);
    put_stat(j, "temperature_jump_hot", r->jump_hot);
    put_stat(j, "temperature_jump_cold", r->jump_cold);
    put_stat(j, "kT_mid", r->t_mid);
    put_stat(j, "lambda_fourier_theta_pv", r->lam_pv);
    put_stat(j, "lambda_fourier_theta_k", r->lam_k);
    cJSON_AddItemToObject(j, "lambda_chapman_enskog_dilute", num(r->lam_ce));
    cJSON_AddItemToObject(j, "lambda_enskog", num(r->lam_enskog));
    cJSON_AddStringToObject(j, "lambda_reference_model",
                            isinf(o->c) ? "classical hard spheres: Chapman-Enskog (dilute, converged) "
                                          "and Enskog's dense factor"
                                        : "the invariant Boltzmann gas (Moller flux, isotropic "
                                          "cross-section sigma_T = pi): not the engine's sphere "
                                          "kernel, whose rate is sigma_T |v0 - v1|");
    if (r->have_v) {
        cJSON *m = cJSON_CreateObject();
        cJSON_AddStringToObject(m, "verdict", r->v.verdict_name);
        cJSON_AddItemToObject(m, "threshold_p_model", num(r->v.threshold));
        cJSON_AddItemToObject(m, "p_model", num(r->v.p_model));
        cJSON_AddItemToObject(m, "nu_r_c", num(r->v.nu_r_c));
        cJSON_AddItemToObject(m, "policy_share", num(r->v.policy_share));
        cJSON_AddItemToObject(m, "collisions", num((double)r->v.collisions));
        cJSON_AddItemToObject(j, "model", m);
    }
    char *text = cJSON_Print(j);
    cJSON_Delete(j);
    if (!text) {
        app_errf(err, "out of memory");
        return -1;
    }
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0) {
        free(text);
        return -1;
    }
    fprintf(a.f, "%s\n", text);
    free(text);
    return app_atomic_commit(&a, err);
}

static int write_script(const char *path, const options *o, const result *r, char *err)
{
    app_atomic a;
    if (app_atomic_open(&a, path, err) != 0)
        return -1;
    FILE *f = a.f;
    char fc[APP_FMT_LEN];
    fprintf(f,
"# heat.gp — written by relcol-heat; run `gnuplot heat.gp` in this folder.\n"
"# Left: the temperature along x by two thermometers, the walls' temperatures and the\n"
"# central half's line; right: the energy flux T^0x and the kinetic pressure.\n");
    app_gnuplot_head(f, "heat.png", "size 1400,620 enhanced font 'Sans,12' linewidth 1.4", 0);
    fprintf(f,
"set multiplot layout 1,2 title \"Heat conduction between thermal walls: N = %ld, packing %g, "
"c = %s, Kn = %.3g\\n{/*0.8 λ_{Fourier} = %.4g ± %.2g, λ_{CE, dilute} = %.4g}\"\n"
"set xlabel 'x'\n"
"set xrange [0:%.17g]\n"
"set grid lc rgb '#dddddd'\n"
"set key top right box opaque\n"
"set ylabel 'kT'\n"
"plot 'profile.csv' skip 1 using 1:4:5 with yerrorbars pt 7 ps 0.6 lc rgb '#1f77b4' title 'θ from ⟨p·v⟩ = 3kT', \\\n"
"     '' skip 1 using 1:6:7 with yerrorbars pt 6 ps 0.8 lc rgb '#d62728' title 'θ from ⟨K⟩', \\\n"
"     %.17g + %.17g * x with lines dt 2 lc rgb '#555555' title 'central half, fitted', \\\n"
"     '-' using 1:2 with points pt 5 ps 1.2 lc rgb 'black' title 'walls'\n"
"0,%.17g\n%.17g,%.17g\ne\n"
"set ylabel 'energy flux T^{0x}'\n"
"set y2label 'kinetic pressure n⟨p_x v_x⟩'\n"
"set y2tics\n"
"set ytics nomirror\n"
"set key center right\n"
"plot 'profile.csv' skip 1 using 1:8:9 with yerrorbars pt 7 ps 0.6 lc rgb '#2ca02c' title 'T^{0x}', \\\n"
"     %.17g with lines dt 2 lc rgb '#2ca02c' title 'heat per area, walls', \\\n"
"     '' skip 1 using 1:10:11 axes x1y2 with yerrorbars pt 6 ps 0.8 lc rgb '#9467bd' title 'n⟨p_x v_x⟩ (right)'\n"
"unset multiplot\n",
            o->n, o->packing, app_fmt(o->c, fc), r->mfp / r->Lx, r->lam_pv.mean, r->lam_pv.err,
            r->lam_ce, r->Lx, r->fit_a0, r->fit_slope, o->hot, r->Lx, o->cold,
            0.5 * (r->q_hot.mean + r->q_cold.mean));
    return app_atomic_commit(&a, err);
}

int main(int argc, char **argv)
{
    options o;
    memset(&o, 0, sizeof o);
    int st = app_start(&cli, argc, argv, &o);
    if (st >= 0)
        return st;
    char err[APP_ERR_LEN];
    if (app_mkdir_p(o.out, err) != 0)
        return app_fail(prog, 1, "--out: %s", err);
    result *r = calloc(1, sizeof *r);
    if (!r)
        return app_fail(prog, 1, "out of memory");
    int code = 1;
    char *csv = app_path_join(o.out, "profile.csv"), *js = app_path_join(o.out, "summary.json"),
         *gp = app_path_join(o.out, "heat.gp");
    if (!csv || !js || !gp) {
        fprintf(stderr, "%s: out of memory\n", prog);
        goto done;
    }
    if (run(&o, r, err) != 0 || write_profile(csv, &o, r, err) != 0 ||
        write_summary(js, &o, r, err) != 0 || write_script(gp, &o, r, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto done;
    }
    int made = 0;
    if (app_gnuplot_run(prog, o.out, "heat.gp", "heat.png", &made, err) != 0) {
        fprintf(stderr, "%s: %s\n", prog, err);
        goto done;
    }
    printf("%s: lambda (Fourier, theta_pv) = %.5g +- %.2g, (theta_K) = %.5g +- %.2g; "
           "Chapman-Enskog dilute %.5g%s at kT = %.4g; jumps %.3g +- %.1g (hot), %.3g +- %.1g "
           "(cold); heat per area %.5g +- %.2g; Kn = %.3g; %s\n",
           prog, r->lam_pv.mean, r->lam_pv.err, r->lam_k.mean, r->lam_k.err, r->lam_ce,
           isinf(o.c) ? "" : " (invariant Boltzmann gas)", r->t_mid.mean, r->jump_hot.mean,
           r->jump_hot.err, r->jump_cold.mean, r->jump_cold.err, 0.5 * (r->q_hot.mean + r->q_cold.mean),
           r->q_hot.err, r->mfp / r->Lx, o.out);
    app_validity_warn(stderr, prog);
    code = 0;
done:
    free(csv);
    free(js);
    free(gp);
    free(r);
    return code;
}
