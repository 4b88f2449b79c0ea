/* gravity.c — the table of field couplings, and the checks every coupling's entry points
 * share (relcol/gravity.h). */
#include <string.h>

#include "gravity_private.h"

const rc_gravity_coupling *const rc_gravity_couplings[] = {&rc_gravity_newtonian,
                                                           &rc_gravity_equivalence, NULL};

const rc_gravity_coupling *rc_gravity_find(const char *name)
{
    if (!name)
        return NULL;
    for (size_t i = 0; rc_gravity_couplings[i]; i++)
        if (strcmp(rc_gravity_couplings[i]->name, name) == 0)
            return rc_gravity_couplings[i];
    return NULL;
}

int rc_gravity_check_(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p)
{
    if (!f)
        return RC_EINVAL;
    if (!isfinite(f->g) || !isfinite(f->inv_c2) || !isfinite(m) || !rc_v3_isfinite(x) ||
        !rc_v3_isfinite(p))
        return RC_ENONFINITE;
    if (!(f->g > 0.0) || f->axis < 0 || f->axis > 2 || !(f->inv_c2 >= 0.0))
        return RC_EINVAL;
    if (!(m > 0.0))
        return RC_EMASS;
    return RC_OK;
}

int rc_gravity_first_root_(double a, double b, double c0, double *t)
{
    const double d = b * b - 4.0 * a * c0;
    if (!(d >= 0.0))
        return RC_MISS;
    const double q = -0.5 * (b + copysign(sqrt(d), b));
    const double r1 = q / a, r2 = q != 0.0 ? c0 / q : r1;
    double best = INFINITY;
    if (r1 > 0.0)
        best = r1;
    if (r2 > 0.0 && r2 < best)
        best = r2;
    if (!isfinite(best))
        return RC_MISS;
    *t = best;
    return RC_OK;
}
