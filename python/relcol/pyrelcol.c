/* pyrelcol.c — the package-side loops of relcol._relcol (pyrelcol.h). */
#include <math.h>
#include <stdlib.h>

#include "pyrelcol.h"

int rcpy_sim_read(rc_sim *s, int which, uint32_t slice, size_t n, int dim, double inv_c2,
                  double *x, double *p, double *v, double *r, double *m, double *tau,
                  double *tau_last, int32_t *image, int8_t *ahead, size_t *bad)
{
    *bad = 0;
    if (!s || n != rc_sim_count(s) || dim < 1 || dim > 3 || which < RCPY_NOW ||
        which > RCPY_SLICE)
        return RC_EINVAL;
    rc_sim_ball *all = malloc((n ? n : 1) * sizeof *all);
    if (!all)
        return RC_ENOMEM;
    int st = RC_OK;
    if (which == RCPY_SLICE) {
        for (size_t i = 0; i < n && st == RC_OK; i++)
            if ((st = rc_sim_slice_get(s, slice, i, &all[i])) != RC_OK)
                *bad = i;
    } else {
        st = rc_sim_get_balls(s, n, all, which == RCPY_LATEST,
                              which == RCPY_NOW ? ahead : NULL);
    }
    for (size_t i = 0; i < n && st == RC_OK; i++) {
        const rc_sim_ball *b = &all[i];
        const double bx[3] = {b->x.x, b->x.y, b->x.z}, bp[3] = {b->p.x, b->p.y, b->p.z};
        const rc_vec3 u = v ? rc_velocity(b->m, b->p, inv_c2) : b->p;
        const double bv[3] = {u.x, u.y, u.z};
        for (int d = 0; d < dim; d++) {
            if (x)
                x[i * (size_t)dim + (size_t)d] = bx[d];
            if (p)
                p[i * (size_t)dim + (size_t)d] = bp[d];
            if (v)
                v[i * (size_t)dim + (size_t)d] = bv[d];
            if (image)
                image[i * (size_t)dim + (size_t)d] = b->image[d];
        }
        if (r)
            r[i] = b->r;
        if (m)
            m[i] = b->m;
        if (tau)
            tau[i] = b->tau;
        if (tau_last)
            tau_last[i] = b->collided ? b->tau_last : NAN;
        if (ahead && which != RCPY_NOW)
            ahead[i] = 0;
    }
    free(all);
    return st;
}

int rcpy_sim_balls(const rc_sim *s, size_t n, rc_sim_ball *out, size_t *bad)
{
    *bad = 0;
    return rc_sim_get_balls(s, n, out, 0, NULL);
}

int rcpy_collide_many(const rc_law *law, const rc_collision_params *prm, size_t n_pairs,
                      const double *c, size_t c_stride, const double *eps, size_t eps_stride,
                      double *m0, rc_vec3 *p0, double *m1, rc_vec3 *p1, const rc_vec3 *n,
                      int *status, size_t *hits, size_t *bad)
{
    if (!prm || !c || !eps)
        return RC_EINVAL;
    rc_collision_params q = *prm;
    if (c_stride == 0 && eps_stride == 0) {
        q.c = c[0];
        q.eps = eps[0];
        return rc_collide_many(law, &q, n_pairs, m0, p0, m1, p1, n, status, hits, bad);
    }
    /* per-pair parameters: the library's checked batch, one pair at a time */
    size_t h = 0;
    *bad = 0;
    for (size_t i = 0; i < n_pairs; i++) {
        size_t hi = 0;
        q.c = c[i * c_stride];
        q.eps = eps[i * eps_stride];
        int st = rc_collide_many(law, &q, 1, m0 + i, p0 + i, m1 + i, p1 + i, n + i,
                                 status ? status + i : NULL, &hi, NULL);
        if (st < 0) {
            *bad = i;
            *hits = h;
            return st;
        }
        h += hi;
    }
    *hits = h;
    return RC_OK;
}
