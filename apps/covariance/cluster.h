/* cluster.h — the many-body covariance measurement (issue 16, item 3), shared by
 * relcol-covariance and the covariance_cluster benchmark: an open cluster of balls
 * converging from a shell in a box they never reach, run from the table frame and from a
 * frame moving at u along x whose initial data are the same worldlines cut at its t' = 0;
 * the final momenta and outgoing worldlines of the moving run, transformed back, are
 * compared ball by ball with the table run's. Beside it, the table run against itself
 * with the positions moved by 1e-15 relative: how much the dynamics amplifies round-off,
 * the floor below which no frame comparison can go. Header-only (static functions): the
 * apps' code, not librelcol's. */
#ifndef RELCOL_COV_CLUSTER_H
#define RELCOL_COV_CLUSTER_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "relcol/relcol.h"

/* The cluster and the two frames. */
typedef struct cov_def {
    int dim;             /* 2 (discs on a ring) or 3 (spheres in a shell) */
    size_t n;            /* balls */
    double r;            /* rest radius of every ball; rest mass 1 */
    double inner, outer; /* centres drawn between these distances from the box centre
                            (uniform in distance), COV_MIN_SEP_RADII apart */
    double v_in;         /* table speed towards the centre */
    double v_noise;      /* plus, per component, a uniform table speed in [-v_noise, v_noise] */
    double v_rms;        /* > 0: all velocities scaled so that the rms table speed is this */
    double c;            /* speed of light (INFINITY: classical, the boost Galilean) */
    double u;            /* velocity of the moving frame along x, |u| < c */
    double box;          /* box edge (never reached by t_check: the cluster stays open) */
    double t_end;        /* each run ends at time t_end of its own frame; the two runs'
                            ends are different hyperplanes, so t_end must come after every
                            contact of both (checked: cov_result.open) */
    unsigned seed;       /* rand_r state of the draw */
} cov_def;

/* Centres are drawn at least this many rest radii apart (2 diameters): room for the
 * contraction and for each frame's slice, so that the moving frame's start is accepted. */
#define COV_MIN_SEP_RADII 4.0
/* Attempts to place one ball before the shell counts as too full, and draws of the whole
 * cluster before no draw starts collision-free in both frames counts as failure. */
#define COV_PLACE_TRIES 100000
#define COV_MAX_DRAWS 200
/* The relative move of the round-off run's positions (a few ulps: the size of the
 * round-off any frame change makes). */
#define COV_JITTER 1e-15

enum { COV_OK = 0, COV_ENOMEM, COV_EPLACE, COV_EDRAWS, COV_ESPEED };

static inline const char *cov_strerror(int e)
{
    switch (e) {
    case COV_OK: return "ok";
    case COV_ENOMEM: return "out of memory";
    case COV_EPLACE: return "the shell is too full to place the balls apart";
    case COV_EDRAWS: return "no draw starts collision-free in both frames";
    case COV_ESPEED: return "a ball or the moving frame is not slower than c";
    default: return "unknown";
    }
}

/* A drawn cluster: the same worldlines given three ways. */
typedef struct cov_cluster {
    rc_sim_ball *b0;  /* table frame, at table time tmin */
    rc_sim_ball *bp;  /* moving frame, at its time t' = 0 */
    rc_sim_ball *bj;  /* b0 with the positions moved by COV_JITTER relative */
    double tmin, tmax; /* table times spanned by the moving frame's t' = 0 slice */
    int draws;        /* draws made (the first is 1) */
} cov_cluster;

/* One run's outcome. */
typedef struct cov_run_out {
    rc_vec3 *p, *x;      /* n final momenta and positions (caller's arrays) */
    double *m;           /* n final rest masses */
    uint64_t collisions; /* contacts resolved by t_end */
    uint64_t early;      /* contacts resolved before t_quiet */
    uint64_t overlaps;   /* contacts decided by the overlap policy */
    uint64_t tube_conflicts, order_conflicts, rollbacks; /* the per-ball frames' (rc_sim_diag) */
    uint64_t open;       /* pairs whose lines may still meet after t_end (cov_may_meet) */
    int walls;           /* a ball reached a wall (the cluster is no longer open) */
    int running;         /* on failure: 0 the engine refused the start, 1 it failed later */
    rc_validity val;     /* the run's validity report (relcol/validity.h) */
} cov_run_out;

/* A frame's comparison. */
typedef struct cov_result {
    int status;          /* rc_status of the first run that failed (RC_OK: all ran) */
    int which;           /* that run: 0 table, 1 moving, 2 round-off */
    int running;         /* 0: the engine refused its start; 1: it failed while running */
    uint64_t coll[3], early[3], overlaps[3]; /* per run: table, moving, round-off */
    uint64_t tube[3], order[3], undone[3]; /* per run: tube and order conflicts, and
                                              collisions undone (per-ball frames) */
    uint64_t open[3];    /* per run: pairs that may still meet after t_end (0: finished) */
    int walls;           /* a ball of some run reached a wall */
    double dp_frames, dp_roundoff; /* max_i |p_i - q_i| / rms |p| */
    double dx_frames, dx_roundoff; /* max_i |x_i - y_i| / r at table time t_end */
    rc_validity val[3];  /* per run: its validity report */
} cov_result;

static inline double cov_urand(unsigned *s) { return (double)rand_r(s) / ((double)RAND_MAX + 1.0); }

static inline rc_vec3 cov_centre(const cov_def *d)
{
    return rc_v3(0.5 * d->box, 0.5 * d->box, d->dim == 3 ? 0.5 * d->box : 0.0);
}

/* Whether balls a and b, on the straight lines through (t, xa) and (t, xb) with momenta
 * pa, pb (rest masses ma, mb), may still come within dmin of each other: in the run's
 * frame after t, or in the pair's ZMF after the earlier of the two events. A contact of
 * any frame is a touch of shapes that lie within the bounding spheres, found at equal
 * times of the run's frame (table, sphere) or of the pair's ZMF (zmf, covariant,
 * transport: its closest approach there), so a pair apart by more than dmin = 2 r in
 * both for ever can no longer collide. Classically the ZMF's times are the run's. */
static inline int cov_may_meet(double ic2, double dmin, rc_vec3 xa, rc_vec3 pa, double ma,
                               rc_vec3 xb, rc_vec3 pb, double mb, double t)
{
    const double Ma = sqrt(ma * ma + rc_v3_norm2(pa) * ic2);
    const double Mb = sqrt(mb * mb + rc_v3_norm2(pb) * ic2);
    for (int zmf = 0; zmf < 1 + (ic2 > 0.0); zmf++) {
        rc_four ea = {t, xa}, eb = {t, xb}, fa = {Ma, pa}, fb = {Mb, pb};
        if (zmf) {
            const rc_vec3 u = rc_v3_scale(1.0 / (Ma + Mb), rc_v3_add(pa, pb));
            if (rc_boost(u, ic2, &ea) != RC_OK || rc_boost(u, ic2, &eb) != RC_OK ||
                rc_boost(u, ic2, &fa) != RC_OK || rc_boost(u, ic2, &fb) != RC_OK)
                return 1;
        }
        const rc_vec3 va = rc_v3_scale(1.0 / fa.t, fa.x), vb = rc_v3_scale(1.0 / fb.t, fb.x);
        const double t0 = fmin(ea.t, eb.t);
        const rc_vec3 dx = rc_v3_sub(rc_v3_axpy(eb.x, t0 - eb.t, vb),
                                     rc_v3_axpy(ea.x, t0 - ea.t, va));
        const rc_vec3 dv = rc_v3_sub(vb, va);
        const double dv2 = rc_v3_norm2(dv);
        const double s = dv2 > 0.0 ? fmax(0.0, -rc_v3_dot(dx, dv) / dv2) : 0.0;
        if (!(rc_v3_norm(rc_v3_axpy(dx, s, dv)) > dmin))
            return 1;
    }
    return 0;
}

/* Run balls b (at time t0) of frame fr to t_end; collisions before t_quiet counted
 * apart; with o->p, the outcome and the pairs that may still meet. Returns an rc_status. */
static inline int cov_run(const cov_def *d, const rc_toi_frame *fr, const rc_sim_ball *b,
                          double t0, double t_quiet, double t_end, cov_run_out *o)
{
    rc_sim_def sd = rc_sim_def_default();
    sd.dim = d->dim;
    sd.box = rc_v3(d->box, d->box, d->dim == 3 ? d->box : 0.0);
    sd.c = d->c;
    sd.frame = fr;
    rc_sim *s = NULL;
    int st = rc_sim_create(&sd, &s);
    if (st == RC_OK)
        st = rc_sim_set_time(s, t0);
    if (st == RC_OK)
        st = rc_sim_set_balls(s, d->n, b, NULL);
    o->running = st == RC_OK;
    if (st == RC_OK)
        st = rc_sim_advance(s, t_quiet, 0);
    rc_sim_diag g;
    if (st == RC_OK) {
        rc_sim_diagnostics(s, &g);
        o->early = g.collisions;
        st = rc_sim_advance(s, t_end, 0);
    }
    if (st == RC_OK) {
        rc_sim_diagnostics(s, &g);
        o->collisions = g.collisions;
        o->overlaps = g.overlaps;
        o->tube_conflicts = g.tube_conflicts;
        o->order_conflicts = g.order_conflicts;
        o->rollbacks = g.rollbacks;
        for (size_t i = 0; i < d->n && o->p; i++) {
            rc_sim_ball q;
            rc_sim_get_ball(s, i, &q);
            o->p[i] = q.p;
            o->x[i] = q.x;
            o->m[i] = q.m;
        }
        o->open = 0;
        const double ic2 = rc_inv_c2_of(d->c);
        for (size_t i = 0; i < d->n && o->p; i++)
            for (size_t j = i + 1; j < d->n; j++)
                o->open += (uint64_t)cov_may_meet(ic2, 2.0 * d->r, o->x[i], o->p[i], o->m[i],
                                                  o->x[j], o->p[j], o->m[j], t_end);
        /* (a wall in a group of contacts shows only in the impulse, which otherwise holds
         * the round-off of the engine's bookkeeping) */
        o->walls = g.events[RC_SIM_EV_WALL] > 0 ||
                   rc_v3_norm(g.wall_impulse) > 1e-9 * g.momentum_scale;
    }
    if (s)
        rc_sim_validity(s, &o->val);
    rc_sim_free(&s);
    return st;
}

static inline void cov_cluster_free(cov_cluster *cl)
{
    free(cl->b0);
    free(cl->bp);
    free(cl->bj);
    memset(cl, 0, sizeof *cl);
}

/* Draw balls on the shell, moving inwards; d->seed is the first draw's state. */
static int cov_draw(const cov_def *d, unsigned *seed, rc_sim_ball *b)
{
    const rc_vec3 C = cov_centre(d);
    const double sep = COV_MIN_SEP_RADII * d->r;
    memset(b, 0, d->n * sizeof *b);
    for (size_t i = 0; i < d->n; i++) {
        for (int tries = 0;; tries++) {
            if (tries == COV_PLACE_TRIES)
                return COV_EPLACE;
            const double a = 2.0 * M_PI * cov_urand(seed);
            const double rr = d->inner + (d->outer - d->inner) * cov_urand(seed);
            rc_vec3 e = rc_v3(cos(a), sin(a), 0.0);
            if (d->dim == 3) { /* (uniform on the sphere: z uniform in [-1, 1]) */
                const double z = 2.0 * cov_urand(seed) - 1.0, s = sqrt(1.0 - z * z);
                e = rc_v3(s * cos(a), s * sin(a), z);
            }
            const rc_vec3 x = rc_v3_axpy(C, rr, e);
            int ok = 1;
            for (size_t j = 0; j < i && ok; j++)
                ok = rc_v3_norm(rc_v3_sub(x, b[j].x)) > sep;
            if (ok) {
                b[i].x = x;
                break;
            }
        }
        const rc_vec3 in = rc_v3_scale(-1.0 / rc_v3_norm(rc_v3_sub(b[i].x, C)), rc_v3_sub(b[i].x, C));
        rc_vec3 v = rc_v3_scale(d->v_in, in);
        const double n1 = 2 * cov_urand(seed) - 1, n0 = 2 * cov_urand(seed) - 1;
        const double n2 = d->dim == 3 ? 2 * cov_urand(seed) - 1 : 0.0;
        v = rc_v3_add(v, rc_v3(d->v_noise * n0, d->v_noise * n1, d->v_noise * n2));
        b[i].r = d->r;
        b[i].m = 1.0;
        b[i].p = v; /* (a velocity until the end) */
    }
    double s2 = 0.0;
    for (size_t i = 0; i < d->n; i++)
        s2 += rc_v3_norm2(b[i].p);
    const double k = d->v_rms > 0.0 ? d->v_rms / sqrt(s2 / (double)d->n) : 1.0;
    const double ic2 = rc_inv_c2_of(d->c);
    for (size_t i = 0; i < d->n; i++) {
        const rc_vec3 v = d->v_rms > 0.0 ? rc_v3_scale(k, b[i].p) : b[i].p;
        const double g2 = 1.0 - rc_v3_norm2(v) * ic2;
        if (!(g2 > 0.0))
            return COV_ESPEED;
        b[i].p = rc_v3_scale(1.0 / sqrt(g2), v);
    }
    return COV_OK;
}

/* Draw a cluster whose worldlines meet nowhere between the two frames' starts: the table
 * run with frame `check` has no collision before the latest t' = 0 event, and the moving
 * frame's start is accepted by the engine (its shapes apart); else the next draw (the
 * rand_r state goes on).
 * cl is the caller's, filled here (cov_cluster_free). */
static int cov_cluster_make(const cov_def *d, const rc_toi_frame *check, cov_cluster *cl)
{
    memset(cl, 0, sizeof *cl);
    const double ic2 = rc_inv_c2_of(d->c);
    if (!(fabs(d->u) * sqrt(ic2) < 1.0))
        return COV_ESPEED;
    const size_t n = d->n;
    cl->b0 = malloc(n * sizeof *cl->b0);
    cl->bp = malloc(n * sizeof *cl->bp);
    cl->bj = malloc(n * sizeof *cl->bj);
    rc_sim_ball *b = malloc(n * sizeof *b);
    if (!cl->b0 || !cl->bp || !cl->bj || !b) {
        free(b);
        cov_cluster_free(cl);
        return COV_ENOMEM;
    }
    const rc_vec3 C = cov_centre(d), Uv = rc_v3(d->u, 0.0, 0.0);
    unsigned seed = d->seed;
    int res = COV_EDRAWS;
    for (int draw = 0; draw < COV_MAX_DRAWS; draw++) {
        cl->draws = draw + 1;
        int e = cov_draw(d, &seed, b);
        if (e != COV_OK) {
            res = e;
            break;
        }
        /* the moving frame's initial data: ball i's event with t' = 0 on its free
         * worldline through (0, x_i) (origin of the boost at C), at table time t_i */
        double tmin = 0.0, tmax = 0.0;
        for (size_t i = 0; i < n; i++) {
            const double M = sqrt(1.0 + rc_v3_norm2(b[i].p) * ic2);
            const rc_vec3 v = rc_v3_scale(1.0 / M, b[i].p);
            const double ti = d->u * ic2 * (b[i].x.x - C.x) / (1.0 - d->u * ic2 * v.x);
            tmin = fmin(tmin, ti);
            tmax = fmax(tmax, ti);
            rc_four ev = {ti, rc_v3_sub(rc_v3_axpy(b[i].x, ti, v), C)};
            rc_four f = {M, b[i].p};
            if (rc_boost(Uv, ic2, &ev) != RC_OK || rc_boost(Uv, ic2, &f) != RC_OK) {
                free(b);
                cov_cluster_free(cl);
                return COV_ESPEED;
            }
            cl->bp[i] = b[i];
            cl->bp[i].p = f.x;
            /* (ev.t is round-off: fly the last bit to t' = 0) */
            cl->bp[i].x = rc_v3_add(C, rc_v3_axpy(ev.x, -ev.t, rc_v3_scale(1.0 / f.t, f.x)));
        }
        /* the table run starts at tmin (every ball flown back freely), so that both runs
         * start before any collision: the table run must have none before tmax */
        for (size_t i = 0; i < n; i++) {
            const double M = sqrt(1.0 + rc_v3_norm2(b[i].p) * ic2);
            cl->b0[i] = b[i];
            cl->b0[i].x = rc_v3_axpy(b[i].x, tmin, rc_v3_scale(1.0 / M, b[i].p));
        }
        cl->tmin = tmin;
        cl->tmax = tmax;
        cov_run_out o = {0};
        if (cov_run(d, check, cl->b0, tmin, tmax, tmax, &o) == RC_OK && o.early == 0 &&
            cov_run(d, check, cl->bp, 0.0, 0.0, 0.0, &o) == RC_OK) {
            res = COV_OK;
            break;
        }
    }
    free(b);
    if (res != COV_OK) {
        cov_cluster_free(cl);
        return res;
    }
    /* the same with the positions moved by COV_JITTER: -1, 0 or +1 times it, per ball
     * (not a translation, which the dynamics would not feel) */
    for (size_t i = 0; i < n; i++) {
        cl->bj[i] = cl->b0[i];
        cl->bj[i].x.x *= 1.0 + COV_JITTER * (double)((int)(i % 3) - 1);
    }
    return COV_OK;
}

/* max_i |p_i - q_i| / rms |p| */
static inline double cov_pdiff(size_t n, const rc_vec3 *p, const rc_vec3 *q)
{
    double mx = 0.0, s2 = 0.0;
    for (size_t i = 0; i < n; i++) {
        mx = fmax(mx, rc_v3_norm(rc_v3_sub(p[i], q[i])));
        s2 += rc_v3_norm2(p[i]);
    }
    return mx / sqrt(s2 / (double)n);
}

/* Run the cluster with frame fr from the table frame, from the moving frame and with the
 * jittered start, and compare. The moving run's final state, transformed back: momenta
 * by the inverse boost; each ball's final event by the inverse boost too, then along its
 * (free, outgoing) worldline to table time t_end, where it is compared with the table
 * run's position -- the outgoing worldlines carry where and when each ball last changed
 * velocity. Returns 0, or -1 with res->status and res->which set (the start refused,
 * e.g. uncontracted shapes that overlap on the moving frame's slice). */
static int cov_compare(const cov_def *d, const rc_toi_frame *fr, const cov_cluster *cl,
                       cov_result *res)
{
    memset(res, 0, sizeof *res);
    const size_t n = d->n;
    const double ic2 = rc_inv_c2_of(d->c);
    rc_vec3 *buf = malloc(6 * n * sizeof *buf);
    double *m = malloc(3 * n * sizeof *m);
    if (!buf || !m) {
        free(buf);
        free(m);
        res->status = RC_ENOMEM;
        return -1;
    }
    cov_run_out o[3];
    for (int k = 0; k < 3; k++)
        o[k] = (cov_run_out){.p = buf + (size_t)(2 * k) * n,
                             .x = buf + (size_t)(2 * k + 1) * n, .m = m + (size_t)k * n};
    const rc_sim_ball *start[3] = {cl->b0, cl->bp, cl->bj};
    const double t0[3] = {cl->tmin, 0.0, cl->tmin}, tq[3] = {cl->tmax, 0.0, cl->tmax};
    for (int k = 0; k < 3; k++) {
        int st = cov_run(d, fr, start[k], t0[k], tq[k], d->t_end, &o[k]);
        if (st != RC_OK) {
            res->status = st;
            res->which = k;
            res->running = o[k].running;
            free(buf);
            free(m);
            return -1;
        }
        res->coll[k] = o[k].collisions;
        res->early[k] = o[k].early;
        res->overlaps[k] = o[k].overlaps;
        res->tube[k] = o[k].tube_conflicts;
        res->order[k] = o[k].order_conflicts;
        res->undone[k] = o[k].rollbacks;
        res->open[k] = o[k].open;
        res->val[k] = o[k].val;
        res->walls |= o[k].walls;
    }
    /* the moving run back to the table frame */
    const rc_vec3 C = cov_centre(d), back = rc_v3(-d->u, 0.0, 0.0);
    for (size_t i = 0; i < n; i++) {
        rc_four q = {sqrt(o[1].m[i] * o[1].m[i] + rc_v3_norm2(o[1].p[i]) * ic2), o[1].p[i]};
        rc_four e = {d->t_end, rc_v3_sub(o[1].x[i], C)};
        if (rc_boost(back, ic2, &q) != RC_OK || rc_boost(back, ic2, &e) != RC_OK) {
            res->status = RC_ESPEED;
            res->which = 1;
            free(buf);
            free(m);
            return -1;
        }
        o[1].p[i] = q.x;
        /* (classically q.t is the rest mass and the velocity p/m: rc_velocity's rule) */
        const rc_vec3 v = rc_velocity(o[1].m[i], q.x, ic2);
        o[1].x[i] = rc_v3_add(C, rc_v3_axpy(e.x, d->t_end - e.t, v));
    }
    res->dp_frames = cov_pdiff(n, o[0].p, o[1].p);
    res->dp_roundoff = cov_pdiff(n, o[0].p, o[2].p);
    double xf = 0.0, xj = 0.0;
    for (size_t i = 0; i < n; i++) {
        xf = fmax(xf, rc_v3_norm(rc_v3_sub(o[0].x[i], o[1].x[i])));
        xj = fmax(xj, rc_v3_norm(rc_v3_sub(o[0].x[i], o[2].x[i])));
    }
    res->dx_frames = xf / d->r;
    res->dx_roundoff = xj / d->r;
    free(buf);
    free(m);
    return 0;
}

#endif
