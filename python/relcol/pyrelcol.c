/* pyrelcol.c — the package-side loops of relcol._relcol (pyrelcol.h). */
#include <math.h>

#include "pyrelcol.h"

int rcpy_sim_read(rc_sim *s, int which, uint32_t slice, size_t n, int dim, double *x,
                  double *p, double *r, double *m, double *tau, double *tau_last,
                  int32_t *image, int8_t *ahead, size_t *bad)
{
    *bad = 0;
    if (!s || n != rc_sim_count(s) || dim < 1 || dim > 3 || which < RCPY_NOW ||
        which > RCPY_SLICE)
        return RC_EINVAL;
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball b;
        int st = which == RCPY_NOW      ? rc_sim_get_ball(s, i, &b)
                 : which == RCPY_LATEST ? rc_sim_get_ball_latest(s, i, &b)
                                        : rc_sim_slice_get(s, slice, i, &b);
        if (st != RC_OK) {
            *bad = i;
            return st;
        }
        const double bx[3] = {b.x.x, b.x.y, b.x.z}, bp[3] = {b.p.x, b.p.y, b.p.z};
        for (int d = 0; d < dim; d++) {
            if (x)
                x[i * (size_t)dim + (size_t)d] = bx[d];
            if (p)
                p[i * (size_t)dim + (size_t)d] = bp[d];
            if (image)
                image[i * (size_t)dim + (size_t)d] = b.image[d];
        }
        if (r)
            r[i] = b.r;
        if (m)
            m[i] = b.m;
        if (tau)
            tau[i] = b.tau;
        if (tau_last)
            tau_last[i] = b.collided ? b.tau_last : NAN;
        if (ahead)
            ahead[i] = (int8_t)(which == RCPY_NOW ? rc_sim_kink_ahead(s, i) : 0);
    }
    return RC_OK;
}

int rcpy_sim_balls(const rc_sim *s, size_t n, rc_sim_ball *out, size_t *bad)
{
    *bad = 0;
    if (!s || n != rc_sim_count(s))
        return RC_EINVAL;
    for (size_t i = 0; i < n; i++) {
        int st = rc_sim_get_ball(s, i, &out[i]);
        if (st != RC_OK) {
            *bad = i;
            return st;
        }
    }
    return RC_OK;
}
