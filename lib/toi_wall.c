/* toi_wall.c — closed-form time of impact of a contracted ball with a wall and with the
 * sides of a box: the centre meets the plane shifted by the support distance
 * h(n) = r sqrt(1 - (v.n)^2/c^2), which is constant while the velocity is. */
#include <math.h>

#include "relcol/status.h"
#include "relcol/toi.h"
#include "toi_private.h"

/* Trusted core: unit n, validated ball and params. */
static int wall_core(const rc_toi_params *prm, int contracted, const rc_toi_ball *a,
                     rc_vec3 n, double offset, double *t, rc_vec3 *x)
{
    const double k = rc_inv_c2_of(prm->c);
    const rc_vec3 v = rc_velocity(a->m, a->p, k);
    /* A wall's rest frame is the table (and the ball-wall ZMF: the wall is infinitely
     * massive), so the shape is the table-frame one, or the sphere if not contracted. */
    const rc_toi_shape s = rc_toi_shape_of(a->r, a->m, a->p, contracted ? k : 0.0);
    const double h = rc_toi_support(&s, n);
    const double gap = offset - rc_v3_dot(n, a->x); /* centre-to-plane distance */
    const double vn = rc_v3_dot(v, n);
    const double sv = rc_v3_norm(v);
    const double mu = gap / h; /* scale factor that makes the shape touch the plane */
    double tt;
    if (mu <= 1.0 + prm->touch_tol) {
        if (mu < 1.0 - prm->touch_tol)
            return RC_EOVERLAP;
        if (!(vn > prm->graze_tol * sv))
            return RC_MISS; /* touching but separating (or sliding along the wall) */
        tt = 0.0;
    } else {
        if (!(vn > prm->graze_tol * sv))
            return RC_MISS;
        tt = (gap - h) / vn;
    }
    *t = tt;
    if (x)
        *x = rc_toi_point_(a->x, v, tt, rc_toi_support_point_(&s, n, h));
    return RC_OK;
}

static int check_ball(const rc_toi_params *prm, const rc_toi_ball *a)
{
    if (!prm || !a)
        return RC_EINVAL;
    double k;
    if (rc_inv_c2(prm->c, &k) != RC_OK)
        return RC_ESPEEDOFLIGHT;
    if (!(prm->touch_tol >= 0.0 && prm->touch_tol < 1.0) || !(prm->graze_tol >= 0.0))
        return RC_EINVAL;
    if (!rc_v3_isfinite(a->x) || !isfinite(a->r))
        return RC_ENONFINITE;
    if (!(a->r > 0.0))
        return RC_ERADIUS;
    rc_particle b = {a->m, a->p};
    return rc_particle_check(&b);
}

int rc_toi_wall(const rc_toi_params *prm, int contracted, const rc_toi_ball *a,
                rc_vec3 n, double offset, double *t, rc_vec3 *x)
{
    int st = check_ball(prm, a);
    if (st != RC_OK)
        return st;
    if (!t)
        return RC_EINVAL;
    if (!rc_v3_isfinite(n) || !isfinite(offset))
        return RC_ENONFINITE;
    const double len = rc_v3_norm(n);
    if (!(len > 0.0))
        return RC_EZERONORMAL;
    return wall_core(prm, contracted, a, rc_v3_scale(1.0 / len, n), offset / len, t, x);
}

int rc_toi_box(const rc_toi_params *prm, int contracted, const rc_toi_ball *a, int dim,
               const double lo[], const double hi[], double *t, int *side, rc_vec3 *n,
               rc_vec3 *x)
{
    int st = check_ball(prm, a);
    if (st != RC_OK)
        return st;
    if (dim < 1 || dim > 3)
        return RC_EDIM;
    if (!lo || !hi || !t)
        return RC_EINVAL;
    for (int i = 0; i < dim; i++) {
        if (!isfinite(lo[i]) || !isfinite(hi[i]))
            return RC_ENONFINITE;
        if (!(lo[i] < hi[i]))
            return RC_EINVAL;
    }
    int best = -1;
    double tb = INFINITY;
    rc_vec3 nb = rc_v3(0, 0, 0), xb = rc_v3(0, 0, 0);
    for (int s = 0; s < 2 * dim; s++) {
        rc_vec3 nn = rc_v3(0, 0, 0);
        const int axis = s / 2;
        const double sign = (s % 2) ? 1.0 : -1.0;
        rc_v3_set(&nn, axis, sign);
        const double off = (s % 2) ? hi[axis] : -lo[axis];
        double ts;
        rc_vec3 xs;
        st = wall_core(prm, contracted, a, nn, off, &ts, &xs);
        if (st == RC_EOVERLAP)
            return st;
        if (st == RC_OK && ts < tb) { /* strict: ties keep the lowest side number */
            tb = ts;
            best = s;
            nb = nn;
            xb = xs;
        }
    }
    if (best < 0)
        return RC_MISS;
    *t = tb;
    if (side)
        *side = best;
    if (n)
        *n = nb;
    if (x)
        *x = xb;
    return RC_OK;
}
