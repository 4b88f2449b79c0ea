/* contacts/check.c — the group solver's input check: valid states, contacts naming two
 * balls (or a ball and a wall), unit finite normals, restitution in [0, 1]. */
#include <math.h>

#include "relcol/status.h"
#include "private.h"

int ctc_check_input(double inv_c2, size_t nballs, const rc_particle *balls, size_t k,
                       const rc_contact *contacts)
{
    if (!balls || (!contacts && k) || !(inv_c2 >= 0.0) || isinf(inv_c2))
        return RC_EINVAL;
    for (size_t i = 0; i < nballs; i++) {
        int st = rc_particle_check(&balls[i]);
        if (st != RC_OK)
            return st;
    }
    for (size_t j = 0; j < k; j++) {
        const rc_contact *c = &contacts[j];
        if (c->a < 0 || (size_t)c->a >= nballs || (c->b >= 0 && (size_t)c->b >= nballs) ||
            c->a == c->b)
            return RC_EINVAL;
        if (!rc_v3_isfinite(c->n) || !isfinite(c->eps))
            return RC_ENONFINITE;
        if (!(fabs(rc_v3_norm2(c->n) - 1.0) < 1e-12)) /* unit normals: caller normalises */
            return RC_EZERONORMAL;
        if (!(c->eps >= 0.0 && c->eps <= 1.0))
            return RC_ERESTITUTION;
    }
    return RC_OK;
}
