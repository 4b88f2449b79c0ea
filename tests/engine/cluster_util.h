/* cluster_util.h — the open cluster of the many-body covariance measurement and test
 * (covariance_cluster, test_engine_covariant): n discs (rest radius 0.5, m = 1) on a ring
 * of radii 16..outer around the centre C of a 2-D box of side L far too large to reach,
 * moving inwards at 0.35c plus isotropic noise; the same worldlines cut at the t' = 0 of a
 * frame moving at U along x (origin of the boost at C); both runs start before any
 * collision (checked by a table-frame run, else the next draw). */
#ifndef CLUSTER_UTIL_H
#define CLUSTER_UTIL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "relcol/relcol.h"

typedef struct cl_def {
    int n;
    double L, U, c, ic2; /* box side, boost speed, c and 1/c^2 */
} cl_def;

static inline double cl_urand(unsigned *s) { return (double)rand_r(s) / ((double)RAND_MAX + 1.0); }

/* Run the balls b (at time t0) in frame fr to t_end: final momenta and rest masses, the
 * contacts before t_quiet (*early) and in all (*nc), the diagnostics at the end (g, may
 * be NULL). quiet: no message on a refusal. */
static inline int cl_run(const cl_def *k, const rc_toi_frame *fr, const rc_sim_ball *b, double t0,
                  double t_quiet, double t_end, rc_vec3 *p, double *m, uint64_t *nc,
                  uint64_t *early, rc_sim_diag *gout, int quiet)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.box = rc_v3(k->L, k->L, 0.0);
    d.c = k->c;
    d.frame = fr;
    rc_sim *s = NULL;
    int st = rc_sim_create(&d, &s);
    if (st == RC_OK)
        st = rc_sim_set_time(s, t0);
    if (st == RC_OK)
        st = rc_sim_set_balls(s, (size_t)k->n, b, NULL);
    if (st == RC_OK)
        st = rc_sim_advance(s, t_quiet, 0);
    rc_sim_diag g;
    if (st == RC_OK) {
        rc_sim_diagnostics(s, &g);
        *early = g.collisions;
        st = rc_sim_advance(s, t_end, 0);
    }
    if (st == RC_OK) {
        rc_sim_diagnostics(s, &g);
        *nc = g.collisions;
        if (gout)
            *gout = g;
        for (size_t i = 0; i < (size_t)k->n; i++) {
            rc_sim_ball o;
            rc_sim_get_ball(s, i, &o);
            p[i] = o.p;
            m[i] = o.m;
        }
    }
    rc_sim_free(&s);
    if (st != RC_OK && !quiet)
        fprintf(stderr, "cluster: %s: %s\n", fr->name, rc_strerror(st));
    return st;
}

/* Draw the cluster: b0 the table-frame data at time *tmin (every ball flown back freely
 * to it), bp the moving frame's at its t' = 0 (its positions and momenta in its own
 * coordinates); t' = 0 spans table times [*tmin, *tmax]. 0, or 1 if no draw in 200 was
 * free of collisions before the moving frame's start. */
static inline int cl_draw(const cl_def *k, double outer, unsigned seed, rc_sim_ball *b0,
                   rc_sim_ball *bp, double *tmin, double *tmax)
{
    const int N = k->n;
    const double ic2 = k->ic2;
    const rc_vec3 C = rc_v3(0.5 * k->L, 0.5 * k->L, 0.0), Uv = rc_v3(k->U, 0.0, 0.0);
    rc_sim_ball *b = calloc((size_t)N, sizeof *b);
    rc_vec3 *pq = malloc((size_t)N * sizeof *pq);
    double *mq = malloc((size_t)N * sizeof *mq);
    int found = 0;
    for (int draw = 0; draw < 200 && b && pq && mq && !found; draw++) {
        memset(b, 0, (size_t)N * sizeof *b);
        for (int i = 0; i < N; i++) {
            for (int tries = 0;; tries++) {
                const double a = 2.0 * M_PI * cl_urand(&seed);
                const double rr = 16.0 + (outer - 16.0) * cl_urand(&seed);
                const rc_vec3 x = rc_v3_axpy(C, rr, rc_v3(cos(a), sin(a), 0.0));
                int ok = 1;
                for (int j = 0; j < i && ok; j++)
                    ok = rc_v3_norm(rc_v3_sub(x, b[j].x)) > 2.0;
                if (ok || tries > 100000) {
                    b[i].x = x;
                    break;
                }
            }
            const rc_vec3 in = rc_v3_scale(-1.0 / rc_v3_norm(rc_v3_sub(b[i].x, C)),
                                           rc_v3_sub(b[i].x, C));
            rc_vec3 v = rc_v3_scale(0.35, in);
            v = rc_v3_add(v, rc_v3(0.15 * (2 * cl_urand(&seed) - 1),
                                   0.15 * (2 * cl_urand(&seed) - 1), 0));
            b[i].r = 0.5;
            b[i].m = 1.0;
            b[i].p = rc_v3_scale(1.0 / sqrt(1.0 - rc_v3_norm2(v)), v);
        }
        /* ball i's event with t' = 0 on its free worldline through (0, x_i), at table
         * time t_i */
        *tmin = *tmax = 0.0;
        int bad = 0;
        for (int i = 0; i < N; i++) {
            const double M = sqrt(1.0 + rc_v3_norm2(b[i].p) * ic2);
            const rc_vec3 v = rc_v3_scale(1.0 / M, b[i].p);
            const double ti = k->U * ic2 * (b[i].x.x - C.x) / (1.0 - k->U * ic2 * v.x);
            *tmin = fmin(*tmin, ti);
            *tmax = fmax(*tmax, ti);
            rc_four e = {ti, rc_v3_sub(rc_v3_axpy(b[i].x, ti, v), C)};
            rc_four f = {M, b[i].p};
            bad |= rc_boost(Uv, ic2, &e) != RC_OK || rc_boost(Uv, ic2, &f) != RC_OK;
            bp[i] = b[i];
            bp[i].p = f.x;
            /* (e.t is round-off: fly the last bit to t' = 0) */
            bp[i].x = rc_v3_add(C, rc_v3_axpy(e.x, -e.t, rc_v3_scale(1.0 / f.t, f.x)));
        }
        if (bad)
            break;
        for (int i = 0; i < N; i++) {
            const double M = sqrt(1.0 + rc_v3_norm2(b[i].p) * ic2);
            b0[i] = b[i];
            b0[i].x = rc_v3_axpy(b[i].x, *tmin, rc_v3_scale(1.0 / M, b[i].p));
        }
        uint64_t nq, eq, nr, er;
        found = cl_run(k, rc_toi_frames[0], b0, *tmin, *tmax, *tmax, pq, mq, &nq, &eq, NULL, 1) ==
                    RC_OK &&
                eq == 0 && cl_run(k, rc_toi_frames[0], bp, 0.0, 0.0, 1.0, pq, mq, &nr, &er, NULL, 1) == RC_OK;
    }
    free(b);
    free(pq);
    free(mq);
    return found ? 0 : 1;
}

/* The moving run's final momenta (and rest masses m) boosted back to the table frame. */
static inline int cl_back(const cl_def *k, rc_vec3 *p, const double *m)
{
    for (int i = 0; i < k->n; i++) {
        rc_four q = {sqrt(m[i] * m[i] + rc_v3_norm2(p[i]) * k->ic2), p[i]};
        if (rc_boost(rc_v3(-k->U, 0.0, 0.0), k->ic2, &q) != RC_OK)
            return 1;
        p[i] = q.x;
    }
    return 0;
}

/* max_i |p_i - q_i| / rms |p| */
static inline double cl_pdiff(int n, const rc_vec3 *p, const rc_vec3 *q)
{
    double mx = 0.0, s2 = 0.0;
    for (int i = 0; i < n; i++) {
        mx = fmax(mx, rc_v3_norm(rc_v3_sub(p[i], q[i])));
        s2 += rc_v3_norm2(p[i]);
    }
    return mx / sqrt(s2 / n);
}

#endif
