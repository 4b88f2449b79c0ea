/* soft_sys.c — a soft-sphere run as its stepper sees it (relcol/soft.h): the settings, the
 * state, the step budget and the contact switches, read through functions so that the
 * run's struct stays private and a stepper can live outside the library. */
#include <math.h>

#include "relcol/soft.h"
#include "soft_private.h"

void rc_soft_sys_get_info(const rc_soft_sys *s, rc_soft_sys_info *info)
{
    info->ny = s->ny;
    info->npair = s->npair;
    info->rtol = s->rtol;
    info->abs_scale = s->abs_scale;
    info->t_max = s->t_max;
    info->ghosts = s->shape != RC_SOFT_SPHERE;
    /* a hundredth of the time the fastest ball takes to cross the smallest radius */
    double vmax = 0.0, rmin = INFINITY;
    for (size_t i = 0; i < s->n; i++) {
        rmin = fmin(rmin, s->r[i]);
        const double *yi = s->y + RC_SOFT_NY * i;
        const double m = s->m0[i] + yi[6] * s->inv_c2;
        const double p2 = yi[3] * yi[3] + yi[4] * yi[4] + yi[5] * yi[5];
        vmax = fmax(vmax, sqrt(p2) / sqrt(m * m + p2 * s->inv_c2));
    }
    info->h0 = vmax > 0.0 ? 0.01 * rmin / vmax : 1.0;
}

double *rc_soft_sys_state(rc_soft_sys *s) { return s->y; }

int rc_soft_sys_budget_left(const rc_soft_sys *s) { return s->n_steps < s->max_steps; }

void rc_soft_sys_count_step(rc_soft_sys *s) { s->n_steps++; }

int rc_soft_sys_contact(const rc_soft_sys *s, size_t q) { return s->on[q]; }

void rc_soft_sys_finish(rc_soft_sys *s, double t) { s->t = t; }
