/* soft_model.c — the soft-sphere model: four-force of a linear spring-dashpot orthogonal to
 * the pair's four-momentum, run in the balls' zero-momentum frame (papers/soft-sphere.md).
 * This file owns the equations and the frame changes; the steppers only integrate them. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "relcol/soft.h"
#include "relcol/status.h"
#include "kinematics_private.h"
#include "soft_private.h"
#include "toi_private.h"

const rc_soft_stepper *const rc_soft_steppers[] = {
    &rc_soft_cvode_bdf,
    &rc_soft_gsl_rk8pd,
    &rc_soft_gsl_rkf45,
    NULL,
};

const rc_soft_stepper *rc_soft_stepper_find(const char *name)
{
    if (!name)
        return NULL;
    for (size_t i = 0; rc_soft_steppers[i]; i++)
        if (strcmp(rc_soft_steppers[i]->name, name) == 0)
            return rc_soft_steppers[i];
    return NULL;
}

rc_soft_params rc_soft_params_default(void)
{
    rc_soft_params p = {INFINITY, 1e6, 1.0, 1e-10, INFINITY, 1000000L, RC_SOFT_SPHERE};
    return p;
}

double rc_soft_damping_ratio(double eps)
{
    if (!(eps > 0.0 && eps <= 1.0))
        return NAN;
    const double l = log(eps);
    return -l / sqrt(M_PI * M_PI + l * l);
}

static rc_vec3 vget(const double *y) { return rc_v3(y[0], y[1], y[2]); }

/* Rest mass, relativistic mass and momentum of ball i in state y. */
static void ball(const rc_soft_sys *s, const double *y, size_t i, double *m, double *M,
                 rc_vec3 *p)
{
    const double *yi = y + RC_SOFT_NY * i;
    *p = vget(yi + 3);
    *m = s->m0[i] + yi[6] * s->inv_c2;
    *M = sqrt(*m * *m + rc_v3_norm2(*p) * s->inv_c2);
}

void rc_soft_rhs(rc_soft_sys *s, const double *y, double *dy)
{
    const size_t n = s->n;
    const double k = s->inv_c2;
    s->n_rhs++;
    for (size_t i = 0; i < n; i++) {
        double m, M;
        rc_vec3 p;
        ball(s, y, i, &m, &M, &p);
        double *d = dy + RC_SOFT_NY * i;
        d[0] = p.x / M;
        d[1] = p.y / M;
        d[2] = p.z / M;
        d[3] = d[4] = d[5] = d[6] = 0.0;
    }
    size_t q = 0;
    for (size_t i = 0; i < n; i++) {
        for (size_t j = i + 1; j < n; j++, q++) {
            if (!s->on[q])
                continue;
            double mi, Mi, mj, Mj;
            rc_vec3 pi, pj;
            ball(s, y, i, &mi, &Mi, &pi);
            ball(s, y, j, &mj, &Mj, &pj);
            /* overlap depth and normal of the current shapes (contracted ones change
             * with the momenta during the contact) */
            double delta, mu_gauge;
            rc_vec3 nn;
            (void)rc_soft_geometry(s, q, i, j, y, &delta, &nn, &mu_gauge);
            const double Mt = Mi + Mj;
            const rc_vec3 P = rc_v3_add(pi, pj);
            /* a = p_i.n - M_i u.n = mu (v_i - v_j).n: the pair's ZMF normal momentum (times
             * sqrt(1 - (u.n)^2/c^2)), and the overlap rate (v_i - v_j).n = a / mu with
             * mu = M_i M_j / Mt: d(delta)/dt for spheres; for contracted shapes the normal
             * approach speed of the surfaces (papers/soft-sphere.md, section 7.2) */
            const double a = (Mj * rc_v3_dot(pi, nn) - Mi * rc_v3_dot(pj, nn)) / Mt;
            const double ddelta = a * Mt / (Mi * Mj);
            double F = s->kappa * delta;
            if (s->zeta > 0.0) {
                /* mu* from the pair's ZMF energies E_i* = (M_i Mt - p_i.P/c^2)/Minv: the
                 * constant inertia of the pair's normal motion in its ZMF */
                const double pc = sqrt(rc_v3_norm2(P) * k);
                const double Minv = sqrt((Mt - pc) * (Mt + pc));
                const double Ei = (Mi * Mt - rc_v3_dot(pi, P) * k) / Minv;
                const double Ej = (Mj * Mt - rc_v3_dot(pj, P) * k) / Minv;
                const double mu = Ei * Ej / Minv;
                F += 2.0 * s->zeta * sqrt(s->kappa * mu) * ddelta;
            }
            double *di = dy + RC_SOFT_NY * i, *dj = dy + RC_SOFT_NY * j;
            di[3] -= F * nn.x;
            di[4] -= F * nn.y;
            di[5] -= F * nn.z;
            dj[3] += F * nn.x;
            dj[4] += F * nn.y;
            dj[5] += F * nn.z;
            /* m dm/dt = F a / c^2 for both balls: dU/dt = c^2 dm/dt = F a / m */
            di[6] += F * a / mi;
            dj[6] += F * a / mj;
        }
    }
}

void rc_soft_overlap(rc_soft_sys *s, const double *y, double *g)
{
    size_t q = 0;
    for (size_t i = 0; i < s->n; i++)
        for (size_t j = i + 1; j < s->n; j++, q++) {
            rc_vec3 n;
            double mu;
            (void)rc_soft_geometry(s, q, i, j, y, &g[q], &n, &mu);
        }
}

/* The direction whose sign against the relative velocity w = v_j - v_i decides approach:
 * the line of centres d for spheres (unnormalised, exactly today's test), the common
 * normal for contracted shapes. For spheroids moving freely the gauge mu(d + w t) is
 * convex in t (a norm along a line) with slope mu n.w/(n.d) at t = 0, n.d > 0: n.w >= 0
 * means mu never decreases again, so the pair cannot touch in free flight. *mu: gauge. */
static rc_vec3 approach_dir(rc_soft_sys *s, size_t q, size_t i, size_t j, const double *y,
                            double *mu)
{
    const rc_vec3 d = rc_v3_sub(vget(y + RC_SOFT_NY * j), vget(y + RC_SOFT_NY * i));
    double delta;
    rc_vec3 n;
    if (rc_soft_geometry(s, q, i, j, y, &delta, &n, mu))
        return n;
    return d;
}

/* pair q -> (i, j): row i holds the n - 1 - i pairs (i, i+1 .. n-1) */
static void pair_of(const rc_soft_sys *s, size_t q, size_t *i, size_t *j)
{
    size_t a = 0, first = 0;
    while (q >= first + (s->n - 1 - a)) {
        first += s->n - 1 - a;
        a++;
    }
    *i = a;
    *j = a + 1 + (q - first);
}

int rc_soft_approaching(rc_soft_sys *s, size_t q, const double *y)
{
    size_t i, j;
    pair_of(s, q, &i, &j);
    double mi, Mi, mj, Mj, mu;
    rc_vec3 pi, pj;
    ball(s, y, i, &mi, &Mi, &pi);
    ball(s, y, j, &mj, &Mj, &pj);
    const rc_vec3 w = rc_v3_sub(rc_v3_scale(1.0 / Mj, pj), rc_v3_scale(1.0 / Mi, pi));
    return rc_v3_dot(approach_dir(s, q, i, j, y, &mu), w) < 0.0;
}

void rc_soft_switch(rc_soft_sys *s, size_t q, int start, const double *y)
{
    s->on[q] = start;
    if (!start)
        return;
    s->n_contacts++;
    size_t i, j;
    pair_of(s, q, &i, &j);
    if (s->shape == RC_SOFT_CONTRACTED_FROZEN && !s->held[q]) {
        /* freeze the shapes the pair touches with (a pair still held from its last
         * contact keeps those: its overlap function stays continuous) */
        s->held[q] = 1;
        for (int e = 0; e < 2; e++) {
            const size_t b = e ? j : i;
            double m, M;
            rc_vec3 p;
            ball(s, y, b, &m, &M, &p);
            s->frozen[2 * q + (size_t)e] = rc_toi_shape_M_(s->r[b], m, p, s->inv_c2, M);
        }
    }
    if (s->have_normal)
        return;
    double delta, mu;
    (void)rc_soft_geometry(s, q, i, j, y, &delta, &s->normal_zmf, &mu);
    s->have_normal = 1;
}

void rc_soft_shape_overlaps(rc_soft_sys *s, const double *y)
{
    if (s->shape == RC_SOFT_SPHERE)
        return;
    size_t q = 0;
    for (size_t i = 0; i < s->n; i++)
        for (size_t j = i + 1; j < s->n; j++, q++) {
            if (s->on[q]) {
                s->ghost[q] = 0;
                continue;
            }
            double delta, mu;
            rc_vec3 n;
            (void)rc_soft_geometry(s, q, i, j, y, &delta, &n, &mu);
            if (delta > 0.0 && !s->ghost[q])
                s->n_shape_overlaps++;
            s->ghost[q] = delta > 0.0;
        }
}

int rc_soft_done(rc_soft_sys *s, const double *y)
{
    size_t q = 0;
    for (size_t i = 0; i < s->n; i++) {
        double mi, Mi;
        rc_vec3 pi;
        ball(s, y, i, &mi, &Mi, &pi);
        for (size_t j = i + 1; j < s->n; j++, q++) {
            if (s->on[q])
                return 0;
            double mj, Mj;
            rc_vec3 pj;
            ball(s, y, j, &mj, &Mj, &pj);
            const rc_vec3 d =
                rc_v3_sub(vget(y + RC_SOFT_NY * j), vget(y + RC_SOFT_NY * i));
            const rc_vec3 w = rc_v3_sub(rc_v3_scale(1.0 / Mj, pj), rc_v3_scale(1.0 / Mi, pi));
            const int receding = rc_v3_dot(d, w) >= 0.0;
            /* contracted shapes: bounding spheres apart and receding never meet, else the
             * common normal decides (approach_dir) */
            if (s->shape != RC_SOFT_SPHERE &&
                !(receding && rc_v3_norm(d) > s->r[i] + s->r[j])) {
                double mu;
                if (rc_v3_dot(approach_dir(s, q, i, j, y, &mu), w) < 0.0)
                    return 0;
            } else if (!receding)
                return 0;
        }
    }
    return 1;
}

/* Step cap in contact, in units of 1/omega (the half period is pi/omega): a guard only,
 * the tolerance keeps real steps far smaller. */
#define RC_SOFT_CONTACT_STEP 0.5
/* Step cap in a contracted contact, in units of the inverse shape-feedback rate (see
 * rc_soft_max_step). BDF damps an unstable mode it steps over instead of following it:
 * measured against gsl-rk8pd (c = 1, kappa = 1e8, oblique, rtol 1e-11), the outcome is off
 * by 1.3e-6 with a cap of 0.5, 4e-7 with 0.2 and 1e-10 with 0.05 (for 1.7x the steps). */
#define RC_SOFT_FLIP_STEP 0.05

double rc_soft_max_step(rc_soft_sys *s, const double *y)
{
    double h = INFINITY;
    size_t q = 0;
    for (size_t i = 0; i < s->n; i++) {
        double mi, Mi;
        rc_vec3 pi;
        ball(s, y, i, &mi, &Mi, &pi);
        for (size_t j = i + 1; j < s->n; j++, q++) {
            double mj, Mj;
            rc_vec3 pj;
            ball(s, y, j, &mj, &Mj, &pj);
            if (s->on[q]) {
                /* in contact: at most RC_SOFT_CONTACT_STEP / omega, omega^2 = kappa / mu
                 * with the rest masses (the smallest inertia), so a restarted stepper
                 * cannot guess a step longer than the contact */
                h = fmin(h, RC_SOFT_CONTACT_STEP * sqrt(mi * mj / ((mi + mj) * s->kappa)));
                if (s->shape == RC_SOFT_CONTRACTED) {
                    /* contracted shapes change with the momenta: the overlap also grows
                     * at the rate kappa |d sigma/dp| ~ kappa sqrt(k) sum r beta / M
                     * (sigma: contact distance; papers/soft-sphere.md, section 7.4), a
                     * fast unstable mode BDF must resolve, not step over */
                    const double rate = s->kappa * sqrt(s->inv_c2) *
                                        (s->r[i] * rc_v3_norm(pi) / (Mi * Mi) +
                                         s->r[j] * rc_v3_norm(pj) / (Mj * Mj));
                    if (rate > 0.0)
                        h = fmin(h, RC_SOFT_FLIP_STEP / rate);
                }
                continue;
            }
            const rc_vec3 d =
                rc_v3_sub(vget(y + RC_SOFT_NY * j), vget(y + RC_SOFT_NY * i));
            const rc_vec3 w = rc_v3_sub(rc_v3_scale(1.0 / Mj, pj), rc_v3_scale(1.0 / Mi, pi));
            const double wn = rc_v3_norm(w), rsum = s->r[i] + s->r[j];
            const double gap = rc_v3_norm(d) - rsum;
            if (s->shape != RC_SOFT_SPHERE && !(gap > 0.0)) {
                /* bounding spheres overlap: the shapes need a translation of at least
                 * (mu - 1) R_in to touch (mu is a norm whose unit ball contains the
                 * sphere of radius R_in = r_i/gamma_i + r_j/gamma_j) */
                double mu;
                const rc_vec3 dir = approach_dir(s, q, i, j, y, &mu);
                if (!(rc_v3_dot(dir, w) < 0.0))
                    continue; /* gauge not decreasing: cannot touch in free flight */
                if (mu < 1.0)
                    continue; /* overlapping out of contact (a shape change): its next
                               * event is the overlap's end, found as a root */
                const double rin = s->r[i] * mi / Mi + s->r[j] * mj / Mj;
                h = fmin(h, fmax((mu - 1.0) * rin, s->rtol * rsum) / wn);
                continue;
            }
            if (!(rc_v3_dot(d, w) < 0.0))
                continue; /* receding: cannot touch while no force acts */
            h = fmin(h, fmax(gap, s->rtol * rsum) / wn);
        }
    }
    return h;
}

/* Total kinetic plus internal energy sum (K + U), K = p^2 / (M + m): finite classically. */
static double energy(const rc_soft_sys *s, const double *y)
{
    double e = 0.0;
    for (size_t i = 0; i < s->n; i++) {
        double m, M;
        rc_vec3 p;
        ball(s, y, i, &m, &M, &p);
        e += rc_v3_norm2(p) / (M + m) + y[RC_SOFT_NY * i + 6];
    }
    return e;
}

void rc_soft_observe(rc_soft_sys *s, const double *y)
{
    if (s->shape == RC_SOFT_CONTRACTED_FROZEN) {
        /* a pair out of contact goes back to its current shapes once they are apart too:
         * the root function then changes value but not sign (no false event). The
         * current shapes can overlap right after a contact (the momenta changed them):
         * the pair stays held until they separate. */
        size_t q = 0;
        for (size_t i = 0; i < s->n; i++)
            for (size_t j = i + 1; j < s->n; j++, q++) {
                if (!s->held[q] || s->on[q])
                    continue;
                s->held[q] = 0;
                double delta, mu;
                rc_vec3 n;
                (void)rc_soft_geometry(s, q, i, j, y, &delta, &n, &mu);
                if (!(delta < 0.0))
                    s->held[q] = 1;
            }
    }
    rc_vec3 P = rc_v3(0, 0, 0);
    for (size_t i = 0; i < s->n; i++)
        P = rc_v3_add(P, vget(y + RC_SOFT_NY * i + 3));
    const double de = fabs(energy(s, y) - s->e0) / s->e_scale;
    const double dp = rc_v3_norm(P) / s->p_scale;
    if (de > s->energy_error)
        s->energy_error = de;
    if (dp > s->momentum_error)
        s->momentum_error = dp;
}

static int check_params(const rc_soft_params *prm)
{
    double k;
    if (rc_inv_c2(prm->c, &k) != RC_OK)
        return RC_ESPEEDOFLIGHT;
    if (!(prm->eps > 0.0 && prm->eps <= 1.0))
        return RC_ERESTITUTION;
    if (!isfinite(prm->stiffness) || !isfinite(prm->rtol) || isnan(prm->t_max))
        return RC_ENONFINITE;
    /* rtol below ~100 ulp cannot be met by any stepper; above 0.1 is no reference */
    if (!(prm->stiffness > 0.0) || !(prm->rtol >= 1e-14 && prm->rtol <= 0.1) ||
        !(prm->t_max > 0.0) || prm->max_steps <= 0)
        return RC_EINVAL;
    if (prm->shape != RC_SOFT_SPHERE && prm->shape != RC_SOFT_CONTRACTED &&
        prm->shape != RC_SOFT_CONTRACTED_FROZEN)
        return RC_EINVAL;
    return RC_OK;
}

int rc_soft_collide(const rc_soft_stepper *stepper, const rc_soft_params *prm, size_t n,
                    rc_particle *b, rc_vec3 *x, const double *r, double *u_int,
                    rc_soft_result *res)
{
    if (!stepper || !prm || !b || !x || !r || n < 2)
        return RC_EINVAL;
    int st = check_params(prm);
    if (st != RC_OK)
        return st;
    for (size_t i = 0; i < n; i++) {
        if ((st = rc_particle_check(&b[i])) != RC_OK)
            return st;
        if (!rc_v3_isfinite(x[i]) || !isfinite(r[i]))
            return RC_ENONFINITE;
        if (!(r[i] > 0.0))
            return RC_ERADIUS;
    }
    const double k = rc_inv_c2_of(prm->c);
    const size_t ny = RC_SOFT_NY * n, npair = n * (n - 1) / 2;
    double *buf = calloc(3 * n + 2 * ny + 2 * npair, sizeof *buf);
    int *on = calloc(3 * npair, sizeof *on);
    rc_toi_shape *frozen = calloc(2 * npair, sizeof *frozen);
    if (!buf || !on || !frozen) {
        free(buf);
        free(on);
        free(frozen);
        return RC_ENOMEM;
    }
    double *m0 = buf, *y = buf + n, *abs_scale = buf + n + ny, *tstar = abs_scale + ny;
    double *rr = tstar + n, *gap = rr + n, *lam = gap + npair;
    for (size_t q = 0; q < npair; q++)
        lam[q] = NAN;

    /* Into the ZMF of all balls: four-momenta and the start events (0, x_i) boosted by u,
     * then each ball moved freely to the latest of its boosted times (no force acts
     * before the first contact, which must lie after that time: checked by the overlap). */
    rc_vec3 u;
    double g = 1.0;
    rc_zmf(b, n, k, &u, NULL);
    st = rc_gamma_from_velocity(u, k, &g);
    double t0 = -INFINITY;
    for (size_t i = 0; st == RC_OK && i < n; i++) {
        rc_four pm = rc_particle_four(&b[i], k), ev = {0.0, x[i]};
        rc_boost_g(u, g, k, &pm);
        rc_boost_g(u, g, k, &ev);
        double *yi = y + RC_SOFT_NY * i;
        m0[i] = b[i].m;
        rr[i] = r[i];
        yi[0] = ev.x.x;
        yi[1] = ev.x.y;
        yi[2] = ev.x.z;
        yi[3] = pm.x.x;
        yi[4] = pm.x.y;
        yi[5] = pm.x.z;
        yi[6] = 0.0;
        tstar[i] = ev.t;
        if (ev.t > t0)
            t0 = ev.t;
    }
    rc_soft_sys s;
    memset(&s, 0, sizeof s);
    s.n = n;
    s.npair = npair;
    s.ny = ny;
    s.inv_c2 = k;
    s.kappa = prm->stiffness;
    s.zeta = rc_soft_damping_ratio(prm->eps);
    s.rtol = prm->rtol;
    s.t_max = prm->t_max;
    s.max_steps = prm->max_steps;
    s.shape = prm->shape;
    s.lam = lam;
    s.frozen = frozen;
    s.held = on + npair;
    s.ghost = on + 2 * npair;
    s.m0 = m0;
    s.r = rr;
    s.on = on;
    s.y = y;
    s.abs_scale = abs_scale;
    double rmin = INFINITY, pmax = 0.0, ekin = 0.0;
    for (size_t i = 0; st == RC_OK && i < n; i++) {
        double *yi = y + RC_SOFT_NY * i;
        const rc_vec3 p = vget(yi + 3);
        const double M = rc_mass_rel(m0[i], p, k);
        const double dt = (t0 - tstar[i]) / M;
        yi[0] += p.x * dt;
        yi[1] += p.y * dt;
        yi[2] += p.z * dt;
        rmin = fmin(rmin, r[i]);
        pmax = fmax(pmax, rc_v3_norm(p));
        ekin += rc_v3_norm2(p) / (M + m0[i]);
        s.p_scale += rc_v3_norm(p);
    }
    if (st == RC_OK) {
        rc_soft_overlap(&s, y, gap);
        for (size_t q = 0; q < npair; q++)
            if (!(gap[q] < 0.0))
                st = RC_EOVERLAP;
    }
    if (st != RC_OK) {
        free(buf);
        free(on);
        free(frozen);
        return st;
    }
    /* Nothing moves in the ZMF: the scales only need to be positive. */
    if (!(pmax > 0.0)) {
        pmax = 1.0;
        ekin = 1.0;
        s.p_scale = 1.0;
    }
    s.e_scale = ekin;
    s.e0 = ekin;
    for (size_t i = 0; i < n; i++) {
        double *a = abs_scale + RC_SOFT_NY * i;
        a[0] = a[1] = a[2] = rmin;
        a[3] = a[4] = a[5] = pmax;
        a[6] = ekin;
    }

    st = stepper->integrate(&s);

    if (st == RC_OK) {
        /* Back to the table frame: final four-momenta and end events boosted by -u, then
         * each ball moved freely to the latest table time (no contact is left). */
        const rc_vec3 mu = rc_v3_scale(-1.0, u);
        double t1 = -INFINITY;
        for (size_t i = 0; i < n; i++) {
            const double *yi = y + RC_SOFT_NY * i;
            const double m = m0[i] + yi[6] * k;
            rc_four pm = {rc_mass_rel(m, vget(yi + 3), k), vget(yi + 3)};
            rc_four ev = {t0 + s.t, vget(yi)};
            rc_boost_g(mu, g, k, &pm);
            rc_boost_g(mu, g, k, &ev);
            b[i].m = m;
            b[i].p = pm.x;
            x[i] = ev.x;
            tstar[i] = ev.t;
            if (ev.t > t1)
                t1 = ev.t;
            if (u_int)
                u_int[i] = yi[6];
        }
        for (size_t i = 0; i < n; i++)
            x[i] = rc_v3_axpy(x[i], t1 - tstar[i], rc_velocity(b[i].m, b[i].p, k));
        if (res) {
            memset(res, 0, sizeof *res);
            res->n_contacts = s.n_contacts;
            res->n_shape_overlaps = s.n_shape_overlaps;
            res->finished = rc_soft_done(&s, y);
            res->t_end = t1;
            if (s.have_normal) {
                rc_four nv = {0.0, s.normal_zmf};
                rc_boost_g(mu, g, k, &nv);
                res->normal = rc_v3_scale(1.0 / rc_v3_norm(nv.x), nv.x);
            }
            res->energy_error = s.energy_error;
            res->momentum_error = s.momentum_error;
            res->n_steps = s.n_steps;
            res->n_rhs = s.n_rhs;
            res->n_pw = s.n_pw;
        }
    }
    free(buf);
    free(on);
    free(frozen);
    return st;
}
