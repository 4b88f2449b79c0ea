/* toi_sphere.c — time of impact of two uncontracted spheres (relative coordinates), the
 * exact quadratic root in its cancellation-free form; seed 002's eq. (17) is this root. */
#include <math.h>

#include "relcol/status.h"
#include "relcol/toi.h"

int rc_toi_sphere_rel(double R, rc_vec3 d, rc_vec3 w, const rc_toi_params *prm,
                      double *t, rc_vec3 *n)
{
    const double dn = rc_v3_norm(d);
    const double sw = rc_v3_norm(w);
    const double dw = rc_v3_dot(d, w);
    /* Touching / overlapping now: mu = |d|/R is the factor that makes the spheres touch. */
    if (dn <= R * (1.0 + prm->touch_tol)) {
        if (dn < R * (1.0 - prm->touch_tol))
            return RC_EOVERLAP;
        const rc_vec3 nn = rc_v3_scale(1.0 / dn, d);
        if (-rc_v3_dot(w, nn) > prm->graze_tol * sw) {
            *t = 0.0;
            *n = nn;
            return RC_OK;
        }
        return RC_MISS; /* touching but separating (or sliding): no collision */
    }
    if (!(dw < 0.0))
        return RC_MISS; /* not approaching (includes w = 0) */
    /* Discriminant w.w R^2 - (d.w)^2 + ... written through Lagrange's identity:
     * (d.w)^2 - w.w (d.d - R^2) = w.w R^2 - |d x w|^2, a product of two factors. */
    const double xw = rc_v3_norm(rc_v3_cross(d, w));
    const double disc = (sw * R - xw) * (sw * R + xw);
    if (!(disc >= 0.0))
        return RC_MISS;
    const double sq = sqrt(disc);
    /* At contact (d + w t).w = -sq and |d + w t| = R: the normal approach speed is sq/R. */
    if (!(sq > prm->graze_tol * sw * R))
        return RC_MISS; /* grazing */
    /* t = (-dw - sq)/ww = (d.d - R^2)/(-dw + sq): no cancellation since dw < 0. */
    const double tt = ((dn - R) * (dn + R)) / (sq - dw);
    const rc_vec3 rc = rc_v3_axpy(d, tt, w);
    *t = tt;
    *n = rc_v3_scale(1.0 / rc_v3_norm(rc), rc);
    return RC_OK;
}
