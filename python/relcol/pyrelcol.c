/* pyrelcol.c — the package-side loops of relcol._relcol (pyrelcol.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pyrelcol.h"

/* Balls read at a time: a block of states stays in the cache while its fields are
 * scattered to the balls' indices (whole rc_sim_balls scattered over 1e5 balls cost a
 * cache and TLB miss each). */
#define RCPY_BLOCK 256 /* (on the stack: 27 KB) */

int rcpy_sim_read(rc_sim *s, int which, uint32_t slice, size_t n, int dim, double inv_c2,
                  double *x, double *p, double *v, double *r, double *m, double *tau,
                  double *tau_last, int32_t *image, int8_t *ahead, size_t *bad)
{
    *bad = 0;
    if (!s || n != rc_sim_count(s) || dim < 1 || dim > 3 || which < RCPY_NOW ||
        which > RCPY_SLICE)
        return RC_EINVAL;
    rc_sim_ball all[RCPY_BLOCK];
    size_t id[RCPY_BLOCK];
    int8_t ah[RCPY_BLOCK];
    int st = RC_OK;
    for (size_t from = 0; from < n && st == RC_OK; from += RCPY_BLOCK) {
        const size_t count = n - from < RCPY_BLOCK ? n - from : RCPY_BLOCK;
        if (which == RCPY_SLICE) {
            for (size_t j = 0; j < count && st == RC_OK; j++) {
                id[j] = from + j;
                ah[j] = 0;
                if ((st = rc_sim_slice_get(s, slice, from + j, &all[j])) != RC_OK)
                    *bad = from + j;
            }
        } else {
            st = rc_sim_get_balls_stored(s, from, count, all, id, which == RCPY_LATEST,
                                         which == RCPY_NOW ? ah : NULL);
            if (which != RCPY_NOW)
                memset(ah, 0, sizeof ah);
        }
        for (size_t k = 0; k < count && st == RC_OK; k++) {
            const rc_sim_ball *b = &all[k];
            const size_t i = id[k], at = i * (size_t)dim;
            if (x)
                for (int d = 0; d < dim; d++)
                    x[at + (size_t)d] = rc_v3_get(b->x, d);
            if (p)
                for (int d = 0; d < dim; d++)
                    p[at + (size_t)d] = rc_v3_get(b->p, d);
            if (v) {
                const rc_vec3 u = rc_velocity(b->m, b->p, inv_c2);
                for (int d = 0; d < dim; d++)
                    v[at + (size_t)d] = rc_v3_get(u, d);
            }
            if (image)
                for (int d = 0; d < dim; d++)
                    image[at + (size_t)d] = b->image[d];
            if (r)
                r[i] = b->r;
            if (m)
                m[i] = b->m;
            if (tau)
                tau[i] = b->tau;
            if (tau_last)
                tau_last[i] = b->collided ? b->tau_last : NAN;
            if (ahead)
                ahead[i] = ah[k];
        }
    }
    return st;
}

int rcpy_sim_balls(const rc_sim *s, size_t n, rc_sim_ball *out, size_t *bad)
{
    *bad = 0;
    return rc_sim_get_balls(s, n, out, 0, NULL);
}

static inline rc_vec3 load3(const double *v, int dim)
{
    return rc_v3(v[0], dim > 1 ? v[1] : 0.0, dim > 2 ? v[2] : 0.0);
}

static inline void store3(double *out, rc_vec3 v, int dim)
{
    out[0] = v.x;
    if (dim > 1)
        out[1] = v.y;
    if (dim > 2)
        out[2] = v.z;
}

int rcpy_collide(const rc_law *law, const rc_collision_params *prm, size_t n, int dim,
                 const double *c, size_t c_stride, const double *eps, size_t eps_stride,
                 const double *m0, size_t m0_stride, const double *p0, size_t p0_stride,
                 const double *m1, size_t m1_stride, const double *p1, size_t p1_stride,
                 const double *nrm, size_t n_stride, double *m0o, double *p0o, double *m1o,
                 double *p1o, int *status, size_t *hits, size_t *bad)
{
    *hits = 0;
    *bad = 0;
    if (!law || !prm || dim < 1 || dim > 3 || (n && (!c || !eps || !m0 || !p0 || !m1 || !p1 ||
                                                      !nrm || !m0o || !p0o || !m1o || !p1o)))
        return RC_EINVAL;
    rc_collision_params q = *prm;
    q.c = n ? c[0] : q.c;
    q.eps = n ? eps[0] : q.eps;
    const int shared = !c_stride && !eps_stride;
    /* shared parameters: the library's checked batch over the caller's columns (its
     * checks a block at a time, branch-free, then the kernels) */
    if (shared)
        return rc_collide_columns(law, &q, n, dim, m0, m0_stride, p0, p0_stride, m1,
                                  m1_stride, p1, p1_stride, nrm, n_stride, m0o, p0o, m1o, p1o,
                                  status, hits, bad);
    size_t h = 0; /* per-pair c or eps: rc_collide a pair */
    for (size_t i = 0; i < n; i++) {
        if (c_stride)
            q.c = c[i * c_stride];
        if (eps_stride)
            q.eps = eps[i * eps_stride];
        rc_particle a = {m0[i * m0_stride], load3(p0 + i * p0_stride, dim)};
        rc_particle b = {m1[i * m1_stride], load3(p1 + i * p1_stride, dim)};
        const int r = rc_collide(law, &q, &a, &b, load3(nrm + i * n_stride, dim));
        if (r < 0) {
            *bad = i;
            *hits = h;
            return r;
        }
        m0o[i] = a.m;
        m1o[i] = b.m;
        store3(p0o + i * (size_t)dim, a.p, dim);
        store3(p1o + i * (size_t)dim, b.p, dim);
        if (status)
            status[i] = r;
        h += r == RC_OK;
    }
    *hits = h;
    return RC_OK;
}
