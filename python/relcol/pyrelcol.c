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
