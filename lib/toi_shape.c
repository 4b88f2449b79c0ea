/* toi_shape.c — the Lorentz-contracted shape of a moving ball (semi-axis r/gamma along v,
 * r across) and its support distance r sqrt(1 - (v.n)^2/c^2), without cancellation. */
#include <math.h>

#include "relcol/toi.h"
#include "toi_private.h"

rc_toi_shape rc_toi_shape_of(double r, double m, rc_vec3 p, double inv_c2)
{
    return rc_toi_shape_M_(r, m, p, inv_c2, sqrt(m * m + rc_v3_norm2(p) * inv_c2));
}

double rc_toi_support(const rc_toi_shape *s, rc_vec3 n)
{
    /* 1 - (beta.n)^2 = (1 - beta^2) + (beta^2 - (beta.n)^2) = g2 + |beta x n|^2 for unit
     * n: both terms are non-negative, so a fast ball's thin side keeps full precision. */
    return rc_toi_support_(s, n);
}
