/* rc_quad.h — __float128 references for the precision tests (libquadmath): three-vectors,
 * energies and the textbook boost in quad precision, and log-uniform draws. One copy for
 * every test that checks a double-precision path against the exact answer on its data. */
#ifndef RC_QUAD_H
#define RC_QUAD_H

#include <math.h>
#include <quadmath.h>

#include "rc_test.h"
#include "relcol/vec.h"

__extension__ typedef __float128 q128;

typedef struct {
    q128 x, y, z;
} qv;

static inline qv qv_of(rc_vec3 v) { return (qv){v.x, v.y, v.z}; }
static inline rc_vec3 dv_of(qv v) { return rc_v3((double)v.x, (double)v.y, (double)v.z); }
static inline q128 qdot(qv a, qv b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline qv qaxpy(qv a, q128 s, qv b) { return (qv){a.x + s * b.x, a.y + s * b.y, a.z + s * b.z}; }
static inline qv qscale(q128 s, qv a) { return (qv){s * a.x, s * a.y, s * a.z}; }
static inline q128 qnorm(qv a) { return sqrtq(qdot(a, a)); }
/* M c^2 / c^2 = sqrt(m^2 + p^2 k), k = 1/c^2 */
static inline q128 qenergy(double m, qv p, q128 k) { return sqrtq((q128)m * m + qdot(p, p) * k); }

/* Into the frame moving at u (Lorentz factor g): the textbook boost of (t, x). */
static inline void qboost(qv u, q128 g, q128 k, q128 *t, qv *x)
{
    const q128 xu = qdot(*x, u);
    const q128 f = g * g * k / (g + 1) * xu - g * *t;
    *t = g * (*t - xu * k);
    *x = qaxpy(*x, f, u);
}

/* log-uniform in [lo, hi): gammas and scales over decades */
static inline double logu(rc_test_rng *r, double lo, double hi)
{
    return lo * exp(log(hi / lo) * rc_test_uniform(r));
}

#endif
