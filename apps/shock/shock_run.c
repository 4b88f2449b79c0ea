/* shock_run.c — the seeds, the profiles, the references and what is read from them
 * (papers/shock-tube.md, sections 5-6). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_cdf.h>

#include "app.h"
#include "front.h"
#include "shock_run.h"

const char *const sh_q_names[SH_NQ] = {"n", "v", "p", "pperp", "Tp", "Te",
                                       "N0", "Nx", "g", "K", "Pxx", "Pyy"};

static void mom_to_q(int dim, double c, const sh_mom *m, double *q)
{
    sh_derive(dim, c, m, q);
    q[SH_RAW + 0] = m->N0, q[SH_RAW + 1] = m->Nx, q[SH_RAW + 2] = m->g;
    q[SH_RAW + 3] = m->K, q[SH_RAW + 4] = m->Pxx, q[SH_RAW + 5] = m->Pyy;
}

void sh_result_free(sh_result *r)
{
    free(r->xc), free(r->mean), free(r->err), free(r->fluid), free(r->freestr);
    memset(r, 0, sizeof *r);
}

/* one seed's bins at one time: raw moments from the balls */
static int seed_bins(rc_sim *s, const sh_tube *tb, int nb, sh_mom *m, char *err)
{
    const size_t n = rc_sim_count(s);
    const double dx = tb->box.x / nb;
    const double vb = dx * (tb->dim == 3 ? tb->box.y * tb->box.z : tb->box.y);
    memset(m, 0, (size_t)nb * sizeof *m);
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball b;
        int rc = rc_sim_get_ball(s, i, &b);
        if (rc) {
            app_errf(err, "engine: %s", rc_strerror(rc));
            return -1;
        }
        int k = (int)(b.x.x / dx);
        k = k < 0 ? 0 : k >= nb ? nb - 1 : k;
        const double p2 = b.p.x * b.p.x + b.p.y * b.p.y + b.p.z * b.p.z;
        const double M = isinf(tb->c) ? b.m : sqrt(b.m * b.m + p2 / (tb->c * tb->c));
        const double vx = b.p.x / M, vy = b.p.y / M;
        m[k].N0 += 1.0;
        m[k].Nx += vx;
        m[k].g += b.p.x;
        m[k].K += p2 / (M + b.m); /* E - m c^2 without cancellation */
        m[k].Pxx += b.p.x * vx;
        m[k].Pyy += b.p.y * vy;
    }
    for (int k = 0; k < nb; k++) {
        m[k].N0 /= vb, m[k].Nx /= vb, m[k].g /= vb;
        m[k].K /= vb, m[k].Pxx /= vb, m[k].Pyy /= vb;
    }
    return 0;
}

typedef struct {
    const sh_result *r;
    const sh_tube *tb;
    double t;
} fluid_ctx;

static int fluid_at(double x, void *v, sh_mom *out)
{
    const fluid_ctx *q = v;
    rs_state st;
    int rc = rs_sample(&q->r->sol, (x - q->tb->x0) / q->t, &st);
    if (!rc)
        sh_fluid_moments(q->tb->dim, q->tb->c, &q->r->eos, st, out);
    return rc;
}

/* the fluid's moments averaged over a bin */
static int fluid_bin(const sh_result *r, const sh_tube *tb, double xa, double xb, double t,
                     sh_mom *out)
{
    fluid_ctx q = {r, tb, t};
    return sh_mom_bin(fluid_at, &q, xa, xb, out);
}

/* mean free path of a dilute hard-ball gas at rest density n (Boltzmann's, table units):
 * 1 / (sqrt 2 n sigma), sigma = pi (2r)^2 in 3-D, 2 (2r) in 2-D */
static double mfp(int dim, double r, double n)
{
    const double sigma = dim == 3 ? M_PI * 4.0 * r * r : 4.0 * r;
    return 1.0 / (M_SQRT2 * n * sigma);
}

/* the jackknife error of x[S * stride + j] from its leave-one-out values x[s * stride + j] */
static double jackknife(const double *x, int S, int stride, int j)
{
    double m = 0.0, v = 0.0;
    for (int s = 0; s < S; s++)
        m += x[(size_t)s * stride + j] / S;
    for (int s = 0; s < S; s++)
        v += (x[(size_t)s * stride + j] - m) * (x[(size_t)s * stride + j] - m);
    return S > 1 ? sqrt((S - 1.0) / S * v) : NAN;
}

static void mean_err(const double *x, int n, double *mean, double *err)
{
    double s = 0.0, s2 = 0.0;
    int k = 0;
    for (int i = 0; i < n; i++)
        if (isfinite(x[i])) {
            s += x[i];
            k++;
        }
    *mean = k ? s / k : NAN;
    for (int i = 0; i < n; i++)
        if (isfinite(x[i]))
            s2 += (x[i] - *mean) * (x[i] - *mean);
    *err = k > 1 ? sqrt(s2 / (k - 1) / k) : NAN;
}

int sh_run(const sh_opts *o, sh_result *r, int progress, char *err)
{
    const sh_tube *tb = &o->tube;
    const int nt = o->nt, nb = o->bins, S = o->seeds;
    memset(r, 0, sizeof *r);
    r->nt = nt, r->nb = nb, r->seeds = S;
    r->eos = isinf(tb->c) ? rs_eos_ideal(1.0 + 2.0 / tb->dim) : rs_eos_synge(tb->dim);
    const size_t cells = (size_t)nt * nb * SH_NQ;
    r->xc = malloc((size_t)nb * sizeof *r->xc);
    r->mean = calloc(cells, sizeof *r->mean);
    r->err = calloc(cells, sizeof *r->err);
    r->fluid = calloc(cells, sizeof *r->fluid);
    r->freestr = calloc(cells, sizeof *r->freestr);
    double *per = malloc((size_t)S * cells * sizeof *per);      /* [seed][t][bin][q] */
    double *xs = malloc((size_t)(S + 1) * nt * sizeof *xs);     /* shock positions */
    double *pp = malloc((size_t)S * nt * 2 * sizeof *pp);       /* plateau p, v */
    sh_mom *m = malloc((size_t)nb * sizeof *m);
    double *col = malloc((size_t)(S > nb ? S : nb) * sizeof *col);
    if (!r->xc || !r->mean || !r->err || !r->fluid || !r->freestr || !per || !xs || !pp || !m || !col) {
        app_errf(err, "out of memory for the profiles");
        goto fail;
    }
    const double dx = tb->box.x / nb;
    for (int k = 0; k < nb; k++)
        r->xc[k] = (k + 0.5) * dx;

    /* the references first: a state with no fluid solution is an input error */
    rs_state L = {tb->n[0], tb->v[0], tb->n[0] * tb->T[0]}, R = {tb->n[1], tb->v[1], tb->n[1] * tb->T[1]};
    int rc = rs_solve(&r->eos, tb->c, L, R, &r->sol);
    if (rc) {
        app_errf(err, "the ideal-fluid Riemann solution: %s", rs_strerror(rc));
        goto fail;
    }
    const fs_def fd = {tb->dim, tb->c, tb->box.x, tb->x0, {tb->n[0], tb->n[1]}, {tb->T[0], tb->T[1]},
                       {tb->v[0], tb->v[1]}};
    for (int j = 0; j < nt; j++)
        for (int k = 0; k < nb; k++) {
            sh_mom fm, sm;
            if ((rc = fluid_bin(r, tb, k * dx, (k + 1) * dx, o->times[j], &fm))) {
                app_errf(err, "sampling the fluid solution: %s", rs_strerror(rc));
                goto fail;
            }
            mom_to_q(tb->dim, tb->c, &fm, &r->fluid[sh_idx(r, j, k, 0)]);
            if ((rc = fs_moments_bin(&fd, k * dx, (k + 1) * dx, o->times[j], &sm))) {
                app_errf(err, "the free-streaming reference: %s", rs_strerror(rc));
                goto fail;
            }
            mom_to_q(tb->dim, tb->c, &sm, &r->freestr[sh_idx(r, j, k, 0)]);
        }

    app_progress bar;
    app_progress_init(&bar, "seeds", (size_t)S);
    for (int s = 0; s < S; s++) {
        rc_sim_ball *balls = NULL;
        size_t n = 0;
        rc_sim *sim = NULL;
        if (sh_tube_balls(tb, o->seed + (uint64_t)s, &balls, &n, err) ||
            sh_tube_sim(tb, n, balls, &sim, err)) {
            free(balls);
            goto fail;
        }
        free(balls);
        r->nballs = n;
        for (int j = 0; j < nt; j++) {
            rc = rc_sim_advance(sim, o->times[j], 0);
            if (rc) {
                app_errf(err, "engine, seed %llu: %s", (unsigned long long)(o->seed + s), rc_strerror(rc));
                rc_sim_free(&sim);
                goto fail;
            }
            if (seed_bins(sim, tb, nb, m, err)) {
                rc_sim_free(&sim);
                goto fail;
            }
            for (int k = 0; k < nb; k++)
                mom_to_q(tb->dim, tb->c, &m[k], &per[(size_t)s * cells + sh_idx(r, j, k, 0)]);
        }
        rc_validity v;
        if (rc_sim_validity(sim, &v) == RC_OK) {
            app_validity_note_report(&v); /* for the app's one warning line */
            r->seeds_outside += v.verdict == RC_VERDICT_OUTSIDE;
            if (!r->model_ok || v.p_model > r->model.p_model)
                r->model = v;
            r->model_ok = 1;
        }
        rc_sim_diag d;
        rc_sim_diagnostics(sim, &d);
        r->collisions += d.events[RC_SIM_EV_BALL] + d.events[RC_SIM_EV_MULTI];
        rc_sim_free(&sim);
        if (progress)
            app_progress_update(&bar, (size_t)s + 1);
    }
    if (progress)
        app_progress_done(&bar);

    for (size_t i = 0; i < cells; i++) {
        for (int s = 0; s < S; s++)
            col[s] = per[(size_t)s * cells + i];
        mean_err(col, S, &r->mean[i], &r->err[i]);
    }

    /* free streaming: each raw moment's bins, t_{S-1} of the seed mean -> normal quantile */
    static const int chi_q[3] = {SH_RAW + 0, SH_RAW + 2, SH_RAW + 4};
    for (int j = 0; j < nt; j++)
        for (int a = 0; a < 3; a++) {
            double chi = 0.0;
            int used = 0;
            for (int k = 0; k < nb && S > 1; k++) {
                const size_t i = sh_idx(r, j, k, chi_q[a]);
                if (!(r->err[i] > 0.0) || !isfinite(r->freestr[i]))
                    continue;
                const double tt = (r->mean[i] - r->freestr[i]) / r->err[i];
                const double u = gsl_cdf_tdist_P(tt, S - 1.0);
                const double z = tt > 0 ? gsl_cdf_ugaussian_Qinv(gsl_cdf_tdist_Q(tt, S - 1.0))
                                        : gsl_cdf_ugaussian_Pinv(u);
                chi += z * z;
                used++;
            }
            r->chi2[j][a] = used ? chi : NAN;
            r->dof[j][a] = used;
            r->pval[j][a] = used ? gsl_cdf_chisq_Q(chi, used) : NAN;
        }

    /* the fluid: the plateau's p and v per seed from the moments pooled over its bins (a
     * bin's own p = Pxx - v g is low by ~1/(balls in it), the sample variance's bias),
     * the shock's position from the seeds' mean N0 profile, errors by the jackknife */
    const rs_solution *so = &r->sol;
    const double w = so->headR - so->tailL;
    sh_mom mr, behind;
    sh_fluid_moments(tb->dim, tb->c, &r->eos, R, &mr);
    const rs_state star_r = {so->rho_starR, so->v_star, so->p_star};
    sh_fluid_moments(tb->dim, tb->c, &r->eos, star_r, &behind);
    double *prof = malloc((size_t)nb * sizeof *prof), *tmp = malloc((size_t)(S + 1) * sizeof *tmp);
    double *wt = malloc((size_t)nb * sizeof *wt);
    if (!prof || !tmp || !wt) {
        free(prof), free(tmp), free(wt);
        app_errf(err, "out of memory");
        goto fail;
    }
    for (int j = 0; j < nt; j++) {
        const double t = o->times[j];
        const double lo = tb->x0 + (so->tailL + 0.2 * w) * t, hi = tb->x0 + (so->headR - 0.2 * w) * t;
        for (int s = 0; s < S; s++) {
            sh_mom pool = {0};
            int nbin = 0;
            for (int k = 0; k < nb; k++)
                if (k * dx >= lo && (k + 1) * dx <= hi) {
                    const double *q = &per[(size_t)s * cells + sh_idx(r, j, k, SH_RAW)];
                    pool.N0 += q[0], pool.Nx += q[1], pool.g += q[2];
                    pool.K += q[3], pool.Pxx += q[4], pool.Pyy += q[5];
                    nbin++;
                }
            double dq[SH_NDERIVED];
            sh_derive(tb->dim, tb->c, &pool, dq); /* a sum of densities: p and v are ratios */
            pp[((size_t)s * nt + j) * 2] = nbin ? dq[SH_P] / nbin : NAN;
            pp[((size_t)s * nt + j) * 2 + 1] = nbin ? dq[SH_V] : NAN;
            r->plat_bins[j] = nbin;
        }
        for (int a = 0; a < 2; a++) {
            for (int s = 0; s < S; s++)
                tmp[s] = pp[((size_t)s * nt + j) * 2 + a];
            double mu, e;
            mean_err(tmp, S, &mu, &e);
            if (a == 0)
                r->plat_p[j] = mu, r->plat_p_err[j] = e;
            else
                r->plat_v[j] = mu, r->plat_v_err[j] = e;
        }
        /* the right shock's mid-level point (front.h) between the fluid's two states, in
         * a window half the contact-shock distance either side of the fluid's shock;
         * Poisson weights 1/N0; leave-one-out (s_out = 0..S-1) and all (s_out = S) */
        const double expect = tb->x0 + so->headR * t, xcon = tb->x0 + so->v_star * t;
        const double h = 0.5 * (expect - xcon);
        const sh_front fr = {behind.N0, mr.N0, expect - h, fmin(expect + h, tb->box.x), expect,
                             fmax(0.05 * h, dx)};
        for (int k = 0; k < nb; k++) {
            const double nf = r->fluid[sh_idx(r, j, k, SH_RAW)];
            wt[k] = nf > 0.0 ? 1.0 / nf : 0.0;
        }
        r->wshock[j] = NAN;
        for (int so_ = 0; so_ <= S; so_++) {
            for (int k = 0; k < nb; k++) {
                double acc = 0.0;
                for (int s = 0; s < S; s++)
                    if (s != so_)
                        acc += per[(size_t)s * cells + sh_idx(r, j, k, SH_RAW)];
                prof[k] = acc / (so_ < S ? S - 1 : S);
            }
            xs[(size_t)so_ * nt + j] = NAN;
            if (so->waveR == RS_SHOCK) /* a rarefaction on the right has no front to fit */
                sh_front_fit(&fr, r->xc, prof, wt, nb, &xs[(size_t)so_ * nt + j],
                             so_ == S ? &r->wshock[j] : NULL);
        }
        r->xshock[j] = xs[(size_t)S * nt + j];
        r->xshock_err[j] = jackknife(xs, S, nt, j);
    }
    /* the shock speed: its mean since the membrane opened, (x_s - x0)/t at the last time,
     * the self-similar solution's x/t (the front's offset from the fluid's shock stays
     * bounded while it forms, so this converges as 1/t); and its local speed, the
     * least-squares slope of x_s over all the times, which also reads the approach */
    r->vshock = (r->xshock[nt - 1] - tb->x0) / o->times[nt - 1];
    r->vshock_err = r->xshock_err[nt - 1] / o->times[nt - 1];
    r->vshock_local = r->vshock_local_err = NAN;
    if (nt > 2) {
        double tm = 0.0, tt = 0.0;
        for (int j = 0; j < nt; j++)
            tm += o->times[j] / nt;
        for (int j = 0; j < nt; j++)
            tt += (o->times[j] - tm) * (o->times[j] - tm);
        for (int so_ = 0; so_ <= S; so_++) {
            double xm = 0.0, tx = 0.0;
            for (int j = 0; j < nt; j++)
                xm += xs[(size_t)so_ * nt + j] / nt;
            for (int j = 0; j < nt; j++)
                tx += (o->times[j] - tm) * (xs[(size_t)so_ * nt + j] - xm);
            tmp[so_] = tx / tt;
        }
        r->vshock_local = tmp[S];
        r->vshock_local_err = jackknife(tmp, S, 1, 0);
    }
    free(prof), free(tmp), free(wt);
    r->lambda[0] = mfp(tb->dim, tb->r, tb->n[0]);
    r->lambda[1] = mfp(tb->dim, tb->r, tb->n[1]);
    r->lambda_star = mfp(tb->dim, tb->r, so->rho_starR);
    r->kn = r->lambda_star / (so->headR * o->times[nt - 1]);
    free(per), free(xs), free(pp), free(m), free(col);
    return 0;
fail:
    free(per), free(xs), free(pp), free(m), free(col);
    sh_result_free(r);
    return -1;
}
