/* eos_run.h — one equation-of-state and transport point of a periodic hard-ball gas:
 * start, melt, then read the flux moments (relcol/moments.h) at regular times and turn
 * them into the compressibility factor, the temperature and the Einstein–Helfand
 * transport coefficients, each with a standard error from independent blocks of the run
 * (papers/pressure.md, papers/transport.md). Shared by relcol-eos and its tests. */
#ifndef RELCOL_EOS_RUN_H
#define RELCOL_EOS_RUN_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eos_flux.h"
#include "eos_lattice.h"
#include "eos_theory.h"
#include "juttner.h"
#include "relcol/relcol.h"

typedef struct eos_in {
    int dim;                  /* 2 or 3 */
    size_t n;
    double packing;           /* rest-frame packing fraction */
    double theta;             /* kT / (m c^2) at finite c; kT at c = inf */
    double c;
    const rc_toi_frame *frame;
    uint64_t seed;
    double t_equil;           /* melting time, in mean free times (Enskog estimate) */
    double t_run;             /* measured time, in mean free times */
    int blocks;               /* independent blocks for the errors (>= 2) */
    int per_block;            /* moment readings per block (>= 4) */
    int transport;            /* also D, eta, lambda (stores the positions) */
    double lag;               /* transport: the lag, in mean free times, at which the
                                 moments' variance growth is read (<= the block length) */
    int groups;               /* rule for simultaneous contacts (rc_group_rule; default 0) */
    double move;              /* --sensitivity: the start moved by move_balls(b, n, dim,
                                 move) when move_balls is set */
    void (*move_balls)(rc_sim_ball *b, size_t n, int dim, double move);
    double *curve_eta, *curve_lambda; /* NULL, or 2 (per_block + 1) values: the running
                                         Green–Kubo integrals and errors (eos_flux.h) */
} eos_in;

typedef struct eos_out {
    double box, volume, tau_free;  /* box edge, volume, mean free time used as unit */
    double kT, kT_se;              /* <p.v> / d, time-averaged exactly */
    double z, z_se;                /* P V / (N kT) */
    double p, p_se;                /* pressure */
    double d, d_se, eta, eta_se, lambda, lambda_se;  /* eta, lambda: eta_f.eh, lambda_f.eh */
    eos_flux_est eta_f, lambda_f;  /* both estimators of each (eos_flux.h) */
    size_t lag_readings;           /* the lag L in readings (the curves' length L + 1) */
    double dt;                     /* time between readings */
    uint64_t collisions, overlaps;
    double seconds_engine;         /* (the caller times; kept for reports) */
    rc_validity val;               /* the run's validity report (relcol/validity.h) */
} eos_out;

static inline double eos_mean_se(const double *x, int k, double *se)
{
    double m = 0.0, v = 0.0;
    for (int i = 0; i < k; i++)
        m += x[i];
    m /= k;
    for (int i = 0; i < k; i++)
        v += (x[i] - m) * (x[i] - m);
    *se = k > 1 ? sqrt(v / (k - 1) / k) : NAN;
    return m;
}

/* The start rc_sim_gas_init cannot place: the close-packed lattice (eos_lattice.h) in the
 * periodic cube of the same edge, balls of radius 1/2 at rest. */
static inline int eos_start_close_packed(const eos_in *in, rc_sim_ball *b, rc_vec3 *box)
{
    const double vball = in->dim == 3 ? M_PI / 6.0 : M_PI / 4.0;
    const double L = pow((double)in->n * vball / in->packing, 1.0 / in->dim);
    rc_vec3 *x = malloc(in->n * sizeof *x);
    double nn;
    if (!x)
        return RC_ENOMEM;
    /* (the clearance of rc_sim_gas_init's lattice: no two balls touch at the start) */
    const int st = eos_lattice(in->dim, in->n, L, 1.0 + 1e-6, in->seed, x, &nn);
    for (size_t i = 0; st == 0 && i < in->n; i++) {
        memset(&b[i], 0, sizeof b[i]);
        b[i].x = x[i];
        b[i].r = 0.5;
        b[i].m = 1.0;
    }
    free(x);
    *box = rc_v3(L, L, in->dim == 3 ? L : 0.0);
    return st == 0 ? RC_OK : RC_EOVERLAP;
}

/* The gas start: equal balls (m = 1, r = 1/2) on the lattice of rc_sim_gas_init (or, where
 * it has no room, the close-packed one), every
 * |p| the same -- relativistically the Jüttner mean energy at theta, classically
 * equipartition -- in pairs of opposite momenta (zero total momentum). */
static inline int eos_start(const eos_in *in, rc_sim **out, double *box_edge, char *err)
{
    rc_sim_ball *b = malloc(in->n * sizeof *b);
    if (!b) {
        snprintf(err, 256, "out of memory");
        return -1;
    }
    rc_sim_gas_def g = {in->dim, in->n, 0.5, in->packing, 0.0, in->c, 8.0, in->seed};
    rc_vec3 box;
    int st = rc_sim_gas_init(&g, &box, b);
    if (st == RC_EOVERLAP) /* its cubic lattice has no room: the close-packed one has */
        st = eos_start_close_packed(in, b, &box);
    if (st != RC_OK) {
        snprintf(err, 256, "cannot place %zu balls at packing %g: %s", in->n, in->packing,
                 rc_strerror(st));
        free(b);
        return -1;
    }
    double p0;
    if (isinf(in->c)) {
        p0 = sqrt(in->dim * in->theta);
    } else {
        const double g0 = jt_mean_gamma(in->dim, in->theta);
        p0 = in->c * sqrt((g0 - 1.0) * (g0 + 1.0));
    }
    rc_rng z = {in->seed ^ 0x5eedULL};
    for (size_t i = 0; i < in->n; i++) {
        /* isotropic directions: points uniform in a ball, normalised */
        double u[3];
        double nn = 0.0;
        do {
            nn = 0.0;
            for (int k = 0; k < 3; k++) {
                const double r1 = rc_rng_uniform(&z); /* (drawn for every k: same stream) */
                u[k] = k < in->dim ? r1 - 0.5 : 0.0;
                nn += u[k] * u[k];
            }
        } while (nn > 0.25 || nn < 1e-6); /* uniform in the ball: isotropic */
        nn = sqrt(nn);
        b[i].p = rc_v3(p0 * u[0] / nn, p0 * u[1] / nn, p0 * u[2] / nn);
        b[i].m = 1.0;
        b[i].image[0] = b[i].image[1] = b[i].image[2] = 0;
    }
    for (size_t i = 1; i + (in->n % 2) < in->n; i += 2)
        b[i].p = rc_v3_scale(-1.0, b[i - 1].p);
    if (in->n % 2) { /* the last three at 120 degrees in the xy plane */
        for (size_t k = 0; k < 3; k++) {
            const double a = 2.0 * M_PI * (double)k / 3.0;
            b[in->n - 3 + k].p = rc_v3(p0 * cos(a), p0 * sin(a), 0.0);
        }
    }
    rc_sim_def d = rc_sim_def_default();
    d.dim = in->dim;
    d.box = box;
    d.c = in->c;
    d.frame = in->frame;
    d.groups = in->groups;
    if (in->move_balls && in->move != 0.0)
        in->move_balls(b, in->n, in->dim, in->move);
    for (int k = 0; k < 3; k++)
        d.boundary[k] = RC_SIM_PERIODIC;
    rc_sim *s = NULL;
    st = rc_sim_create(&d, &s);
    if (st == RC_OK)
        st = rc_sim_set_balls(s, in->n, b, NULL);
    free(b);
    if (st != RC_OK) {
        snprintf(err, 256, "engine: %s", rc_strerror(st));
        rc_sim_free(&s);
        return -1;
    }
    *out = s;
    *box_edge = box.x;
    return 0;
}

/* Mean free time of the Enskog gas (classical speeds at kT = theta m c^2 capped at c):
 * the time unit of the run lengths, so that they mean the same at every density. */
static inline double eos_tau_free(const eos_in *in)
{
    const double eta = in->packing, chi = eos_chi(in->dim, eta);
    const double n = in->dim == 3 ? 6.0 * eta / M_PI : 4.0 * eta / M_PI;
    double vbar = sqrt(8.0 * in->theta / M_PI); /* mean speed, 3-D Maxwell */
    if (!isinf(in->c) && vbar > in->c)
        vbar = in->c;
    /* collision frequency per ball: n sigma_tot sqrt(2) vbar chi; sigma_tot = pi (3-D),
     * 2 (2-D, the cross-section length) */
    const double cross = in->dim == 3 ? M_PI : 2.0;
    return 1.0 / (n * cross * sqrt(2.0) * vbar * chi);
}

/* Einstein–Helfand slope: (<dX(lag)^2> - <dX(lag/2)^2>) / (lag / 2) over readings
 * x[k * stride] (k = 0 .. m-1), every origin, for a lag of L readings (L even). */
static inline double eos_helfand_slope(const double *x, size_t stride, size_t m, size_t L,
                                       double dt)
{
    double s2 = 0.0, s1 = 0.0;
    size_t c2 = 0, c1 = 0;
    for (size_t k = 0; k + L < m; k++) {
        const double a = x[(k + L) * stride] - x[k * stride];
        s2 += a * a;
        c2++;
    }
    for (size_t k = 0; k + L / 2 < m; k++) {
        const double a = x[(k + L / 2) * stride] - x[k * stride];
        s1 += a * a;
        c1++;
    }
    return (s2 / (double)c2 - s1 / (double)c1) / (0.5 * (double)L * dt);
}

/* eos_measure, telling tick (when not NULL) the fraction of its run done, for a bar */
static inline int eos_measure_ticked(const eos_in *in, eos_out *o, char *err,
                                     void (*tick)(void *ctx, double done), void *ctx)
{
    memset(o, 0, sizeof *o);
    rc_sim *s = NULL;
    if (eos_start(in, &s, &o->box, err) != 0)
        return -1;
    const int dim = in->dim;
    /* the equation of state needs the moments only at the blocks' ends (they are exact
     * time integrals); transport reads them per_block times a block */
    const size_t n = in->n, nb = (size_t)in->blocks,
                 pb = in->transport ? (size_t)in->per_block : 1;
    const size_t m = nb * pb + 1;
    o->tau_free = eos_tau_free(in);
    const double t0 = in->t_equil * o->tau_free, dt = in->t_run * o->tau_free / (double)(m - 1);
    rc_sim_moments *M = malloc(m * sizeof *M);
    double *X = in->transport ? malloc((pb + 1) * n * 3 * sizeof *X) : NULL;
    double *zb = malloc(nb * sizeof *zb), *kb = malloc(nb * sizeof *kb),
           *pbk = malloc(nb * sizeof *pbk), *db = malloc(nb * sizeof *db);
    int rc = -1;
    if (!M || (in->transport && !X) || !zb || !kb || !pbk || !db) {
        snprintf(err, 256, "out of memory");
        goto out;
    }
    /* the lag in readings, even, within a block */
    size_t L = (size_t)(in->lag * o->tau_free / dt + 0.5);
    L += L % 2;
    if (L < 2)
        L = 2;
    if (L > pb)
        L = pb - pb % 2;
    o->lag_readings = L;
    o->dt = dt;
    int st = rc_sim_advance(s, t0, 0);
    const double t_all = t0 + in->t_run * o->tau_free;
    for (size_t k = 0; k < m && st == RC_OK; k++) {
        if ((st = rc_sim_advance(s, t0 + dt * (double)k, 0)) == RC_OK)
            st = rc_sim_moments_get(s, &M[k]);
        if (tick)
            tick(ctx, (t0 + dt * (double)k) / t_all);
        if (!in->transport || st != RC_OK)
            continue;
        /* the unwrapped positions of this block's readings: the mean square
         * displacement over every origin of the block at the end of it */
        const size_t j = k == 0 ? 0 : (k - 1) % pb + 1;
        for (size_t i = 0; i < n && st == RC_OK; i++) {
            rc_sim_ball q;
            st = rc_sim_get_ball(s, i, &q);
            double *x = X + (j * n + i) * 3;
            x[0] = q.x.x + q.image[0] * o->box;
            x[1] = q.x.y + q.image[1] * o->box;
            x[2] = q.x.z + q.image[2] * o->box;
        }
        if (k == 0 || j != pb)
            continue;
        double msd = 0.0;
        for (size_t i = 0; i < n; i++)
            for (int a = 0; a < dim; a++)
                msd += eos_helfand_slope(X + i * 3 + (size_t)a, n * 3, pb + 1, L, dt);
        db[(k - 1) / pb] = msd / (double)n / (2.0 * dim);
        memcpy(X, X + pb * n * 3, n * 3 * sizeof *X); /* the next block's first reading */
    }
    if (st != RC_OK) {
        snprintf(err, 256, "engine: %s", rc_strerror(st));
        goto out;
    }
    o->volume = M[0].volume;
    const double V = o->volume;
    /* pressure and temperature per block, exact time averages over it */
    for (size_t b = 0; b < nb; b++) {
        const rc_sim_moments *A = &M[b * pb], *B = &M[(b + 1) * pb];
        const double T = B->time - A->time;
        double g = 0.0, w = 0.0;
        for (int a = 0; a < dim; a++) {
            g += B->helfand[4 * a] - A->helfand[4 * a];
            w += B->virial[4 * a] - A->virial[4 * a];
        }
        kb[b] = (g - w) / ((double)n * dim * T);
        pbk[b] = g / (dim * V * T);
        zb[b] = g / (g - w);
    }
    o->kT = eos_mean_se(kb, (int)nb, &o->kT_se);
    o->p = eos_mean_se(pbk, (int)nb, &o->p_se);
    o->z = eos_mean_se(zb, (int)nb, &o->z_se);
    rc_sim_diag dg;
    rc_sim_diagnostics(s, &dg);
    o->collisions = dg.collisions;
    o->overlaps = dg.overlaps;
    if (in->transport) {
        o->d = eos_mean_se(db, (int)nb, &o->d_se);
        /* shear: the five (2-D: two) independent traceless components; heat (Eckart):
         * energy moment minus h times the position moment, h the enthalpy per ball
         * (kinetic energy and P V over N); every time origin of the run */
        const int ns = eos_flux_shear_count(dim);
        /* calloc: gcc -O3 cannot see that the series fill every entry */
        double *xs = calloc((size_t)(ns > dim ? ns : dim) * m, sizeof *xs);
        if (!xs) {
            snprintf(err, 256, "out of memory");
            goto out;
        }
        eos_flux_shear_series(M, m, dim, xs);
        const int se = eos_flux_estimate(xs, ns, m, nb, pb, L, dt,
                                         1.0 / (2.0 * V * o->kT), &o->eta_f,
                                         in->curve_eta);
        const double h = (M[0].energy + o->p * V) / (double)n;
        eos_flux_heat_series(M, m, dim, h, xs);
        const int sl = eos_flux_estimate(xs, dim, m, nb, pb, L, dt,
                                         1.0 / (2.0 * V * o->kT * o->kT), &o->lambda_f,
                                         in->curve_lambda);
        free(xs);
        if (se != 0 || sl != 0) {
            snprintf(err, 256, "transport estimators: lag %zu readings, %zu a block", L, pb);
            goto out;
        }
        o->eta = o->eta_f.eh;
        o->eta_se = o->eta_f.eh_se;
        o->lambda = o->lambda_f.eh;
        o->lambda_se = o->lambda_f.eh_se;
    }
    rc = 0;
out:
    free(M);
    free(X);
    free(zb);
    free(kb);
    free(pbk);
    free(db);
    if (s)
        rc_sim_validity(s, &o->val);
    rc_sim_free(&s);
    return rc;
}

static inline int eos_measure(const eos_in *in, eos_out *o, char *err)
{
    return eos_measure_ticked(in, o, err, NULL, NULL);
}

#endif
