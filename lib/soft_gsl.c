/* soft_gsl.c — the soft-sphere steppers on GSL odeiv2 (explicit Runge-Kutta pairs). odeiv2
 * has no event detection: after each step, a contact switch inside it is bracketed and
 * located by Illinois regula falsi on the overlap, re-integrating from the bracket's left
 * end, and the stepper restarts at the event because the force switches there.
 * GSL's error handler: every argument these calls check is valid by construction (rtol
 * and the scales positive, ny > 0, steps forward), so only an allocation failing inside
 * GSL's odeiv2 allocators can reach it (relcol/soft.h: applications turn it off). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "relcol/soft.h"
#include "relcol/status.h"

/* Event times are located to this many ulps of the bracket's end time: far below the
 * contact duration for any stiffness the tolerance can resolve. */
#define RC_SOFT_EVENT_ULPS 16.0
/* Iteration cap of the event search (Illinois converges superlinearly; 200 is a guard). */
#define RC_SOFT_EVENT_MAXIT 200

typedef struct gsl_run {
    rc_soft_sys *s;
    size_t ny;
    gsl_odeiv2_system sys;
    gsl_odeiv2_step *step;
    gsl_odeiv2_control *ctrl;
    gsl_odeiv2_evolve *ev;
} gsl_run;

static int gsl_rhs(double t, const double y[], double dydt[], void *user)
{
    (void)t;
    rc_soft_rhs(user, y, dydt);
    return GSL_SUCCESS;
}

/* y_out = state at t_to, integrated from (t_from, y_from) with fresh stepper history. */
static int advance(gsl_run *g, double t_from, const double *y_from, double t_to,
                   double *y_out)
{
    memcpy(y_out, y_from, g->ny * sizeof *y_out);
    gsl_odeiv2_evolve_reset(g->ev);
    gsl_odeiv2_step_reset(g->step);
    double t = t_from, h = t_to - t_from;
    while (t < t_to) {
        const int spent = !rc_soft_sys_budget_left(g->s);
        rc_soft_sys_count_step(g->s);
        if (spent)
            return RC_ENOCONVERGE;
        if (gsl_odeiv2_evolve_apply(g->ev, g->ctrl, g->step, &g->sys, &t, t_to, &h, y_out) !=
            GSL_SUCCESS)
            return RC_ENOCONVERGE;
    }
    return RC_OK;
}

/* Pair q's overlap has crossed to the side `start` wants (> 0 to start, < 0 to end)
 * between (ta, ya) and (tb, yb). Locate the crossing; return its time and the state on
 * the new side in *tr, yr. ybuf needs 2 ny doubles, gbuf npair. */
static int locate(gsl_run *g, size_t q, int start, double ta, const double *ya, double tb,
                  const double *yb, double *tr, double *yr, double *ybuf, double *gbuf)
{
    rc_soft_sys *s = g->s;
    const size_t ny = g->ny;
    double *yl = ybuf, *ym = ybuf + ny;
    memcpy(yl, ya, ny * sizeof *yl);
    memcpy(yr, yb, ny * sizeof *yr);
    rc_soft_overlap(s, ya, gbuf);
    double ga = gbuf[q];
    rc_soft_overlap(s, yb, gbuf);
    double gb = gbuf[q];
    int side = 0;
    for (int it = 0; it < RC_SOFT_EVENT_MAXIT; it++) {
        if (tb - ta <= RC_SOFT_EVENT_ULPS * DBL_EPSILON * fmax(fabs(tb), DBL_MIN))
            break;
        double tm = ta - ga * (tb - ta) / (gb - ga);
        if (!(tm > ta && tm < tb))
            tm = 0.5 * (ta + tb);
        int st = advance(g, ta, yl, tm, ym);
        if (st != RC_OK)
            return st;
        rc_soft_overlap(s, ym, gbuf);
        const double gm = gbuf[q];
        const int newside = start ? gm > 0.0 : gm < 0.0;
        if (newside) {
            tb = tm;
            gb = gm;
            memcpy(yr, ym, ny * sizeof *yr);
            if (side == 1)
                ga *= 0.5; /* Illinois: halve the stale end's weight */
            side = 1;
        } else {
            ta = tm;
            ga = gm;
            memcpy(yl, ym, ny * sizeof *yl);
            if (side == -1)
                gb *= 0.5;
            side = -1;
        }
    }
    *tr = tb;
    return RC_OK;
}

static int gsl_integrate(rc_soft_sys *s, const gsl_odeiv2_step_type *type)
{
    rc_soft_sys_info in;
    rc_soft_sys_get_info(s, &in);
    const size_t ny = in.ny, np = in.npair;
    gsl_run g = {s, ny, {gsl_rhs, NULL, ny, s}, NULL, NULL, NULL};
    double *buf = malloc((6 * ny + 3 * np) * sizeof *buf);
    g.step = gsl_odeiv2_step_alloc(type, ny);
    g.ctrl = gsl_odeiv2_control_scaled_new(in.rtol, in.rtol, 1.0, 0.0, in.abs_scale, ny);
    g.ev = gsl_odeiv2_evolve_alloc(ny);
    int st = RC_ENOMEM;
    if (!buf || !g.step || !g.ctrl || !g.ev)
        goto out;
    double *ya = buf, *yr = buf + ny, *ybest = buf + 2 * ny, *ybuf = buf + 3 * ny;
    double *gb = buf + 5 * ny, *gtmp = gb + np, *g0 = gtmp + np;
    double *y = rc_soft_sys_state(s);
    const double t1 = isfinite(in.t_max) ? in.t_max : DBL_MAX;
    double h = in.h0; /* (the controller adapts it at once) */
    double t = 0.0;
    rc_soft_observe(s, y);
    st = RC_ENOCONVERGE;
    while (!rc_soft_done(s, y) && t < in.t_max) {
        const int spent = !rc_soft_sys_budget_left(s);
        rc_soft_sys_count_step(s);
        if (spent)
            goto out;
        const double ta = t;
        memcpy(ya, y, ny * sizeof *ya);
        if (in.ghosts)
            rc_soft_overlap(s, y, g0);
        /* cap the step as soft_cvode.c does, so no contact is stepped over unseen */
        const double tcap = fmin(t1, t + rc_soft_max_step(s, y));
        if (gsl_odeiv2_evolve_apply(g.ev, g.ctrl, g.step, &g.sys, &t, tcap, &h, y) !=
            GSL_SUCCESS)
            goto out;
        rc_soft_overlap(s, y, gb);
        size_t qbest = np;
        double tbest = t;
        for (size_t q = 0; q < np; q++) {
            /* contracted shapes: a pair out of contact that already overlapped at the
             * step's start (a shape change made it: rc_soft_shape_overlaps) has no entry
             * to locate (spheres keep their original test exactly) */
            const int ghost = in.ghosts && g0[q] > 0.0;
            const int crossed = rc_soft_sys_contact(s, q) ? gb[q] < 0.0 : gb[q] > 0.0 && !ghost;
            if (!crossed)
                continue;
            double tr;
            int rs = locate(&g, q, !rc_soft_sys_contact(s, q), ta, ya, t, y, &tr, yr, ybuf, gtmp);
            if (rs != RC_OK) {
                st = rs;
                goto out;
            }
            if (qbest == np || tr < tbest) {
                qbest = q;
                tbest = tr;
                memcpy(ybest, yr, ny * sizeof *ybest);
            }
        }
        if (qbest < np) {
            /* continue from the earliest event; later crossings are found again */
            t = tbest;
            memcpy(y, ybest, ny * sizeof *y);
            rc_soft_switch(s, qbest, !rc_soft_sys_contact(s, qbest), y);
            gsl_odeiv2_evolve_reset(g.ev);
            gsl_odeiv2_step_reset(g.step);
        }
        rc_soft_shape_overlaps(s, y);
        rc_soft_observe(s, y);
    }
    rc_soft_sys_finish(s, t);
    st = RC_OK;
out:
    if (g.ev)
        gsl_odeiv2_evolve_free(g.ev);
    if (g.ctrl)
        gsl_odeiv2_control_free(g.ctrl);
    if (g.step)
        gsl_odeiv2_step_free(g.step);
    free(buf);
    return st;
}

static int rk8pd_integrate(rc_soft_sys *s) { return gsl_integrate(s, gsl_odeiv2_step_rk8pd); }
static int rkf45_integrate(rc_soft_sys *s) { return gsl_integrate(s, gsl_odeiv2_step_rkf45); }

const rc_soft_stepper rc_soft_gsl_rk8pd = {
    "gsl-rk8pd",
    "GSL odeiv2 Runge-Kutta Prince-Dormand 8(9), events by Illinois regula falsi",
    rk8pd_integrate,
};

const rc_soft_stepper rc_soft_gsl_rkf45 = {
    "gsl-rkf45",
    "GSL odeiv2 Runge-Kutta-Fehlberg 4(5), events by Illinois regula falsi",
    rkf45_integrate,
};
