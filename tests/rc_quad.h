/* rc_quad.h — __float128 references for the precision tests (libquadmath): three-vectors,
 * energies and the textbook boost in quad precision, log-uniform draws, states slow in a
 * frame moving near c, and the one rounding of the data that measures conditioning. One
 * copy for every test that checks a double-precision path against the exact answer on its
 * data. */
#ifndef RC_QUAD_H
#define RC_QUAD_H

#include <math.h>
#include <quadmath.h>

#include "rc_test.h"
#include "relcol/kinematics.h"
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

/* a point of the cube [-1, 1)^3 (not normalised): random directions */
static inline qv qcube(rc_test_rng *r)
{
    return qv_of(rc_v3(rc_test_range(r, -1, 1), rc_test_range(r, -1, 1),
                       rc_test_range(r, -1, 1)));
}

/* The direction of a frame R's motion in the table, not normalised: along a coordinate
 * axis (drawn) when `axis` (the momenta across it are then small numbers, exact to their
 * own size), else random. */
static inline qv qframe_dir(rc_test_rng *r, int axis)
{
    const int ax = (int)(3 * rc_test_uniform(r));
    qv d = qcube(r);
    if (axis)
        d = (qv){ax == 0, ax == 1, ax == 2};
    return d;
}

/* a velocity in R of random direction and speed up to `frac` c */
static inline qv qslow_vel(rc_test_rng *r, double c, double frac)
{
    const qv w = qcube(r);
    return qscale(c * rc_test_range(r, 0.0, frac) / qnorm(w), w);
}

/* A ball of rest mass m moving at vR in R, in the table: boosted into the frame moving at
 * u (Lorentz factor G) relative to R, so R moves at -u there. */
static inline rc_particle qboosted(double m, qv vR, qv u, q128 G, q128 k)
{
    const q128 g = 1 / sqrtq(1 - qdot(vR, vR) * k);
    q128 E = m * g;
    qv p = qscale(m * g, vR);
    qboost(u, G, k, &E, &p);
    return (rc_particle){m, dv_of(p)};
}

/* One rounding of the data: each component times 1 +- 2^-53, the signs from g (a fixed
 * generator, so that every test's conditioning draws are the same each run). */
static inline void round_datum(rc_test_rng *g, double *x)
{
    *x *= 1 + (rc_test_uniform(g) < 0.5 ? -1 : 1) * 0x1p-53;
}

static inline void round_vec(rc_test_rng *g, rc_vec3 *v)
{
    round_datum(g, &v->x);
    round_datum(g, &v->y);
    round_datum(g, &v->z);
}

#endif
