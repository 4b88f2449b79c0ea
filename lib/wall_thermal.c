/* wall_thermal.c — sampling the wall-flux Jüttner law a thermal wall re-emits from
 * (relcol/wall_thermal.h): Lambert's cosine law for the direction, a two-term Gamma
 * mixture for the kinetic energy, both exact. */
#include <math.h>

#include "relcol/kinematics.h"
#include "relcol/status.h"
#include "relcol/wall_thermal.h"

/* -log of a uniform in (0, 1]: an exponential variate, never infinite. */
static double expo(rc_rng *r) { return -log(1.0 - rc_rng_uniform(r)); }

/* 2-D kinetic energy, density ~ sqrt(K (2 m + k K)) e^-K (kT = 1; k = 1/c^2 in the
 * scaled units): proposal (sqrt(k) K + sqrt(2 m K)) e^-K >= it, a mixture of Gamma(2)
 * (weight sqrt k) and Gamma(3/2) (weight sqrt(2 m) Gamma(3/2) = sqrt(2 m pi)/2). */
static double kinetic_2d(rc_rng *r, double m, double k)
{
    const double w2 = sqrt(k), w32 = 0.5 * sqrt(2.0 * m * M_PI);
    for (;;) {
        double K;
        if (rc_rng_uniform(r) * (w2 + w32) < w2) {
            K = expo(r) + expo(r);
        } else {
            const double g = rc_rng_gauss(r);
            K = expo(r) + 0.5 * g * g;
        }
        if (rc_rng_uniform(r) * (sqrt(k) * K + sqrt(2.0 * m * K)) <= sqrt(K * (2.0 * m + k * K)))
            return K;
    }
}

int rc_wall_thermal_emit(rc_rng *r, int dim, double m, double c, double kT, rc_vec3 normal,
                         rc_vec3 *p_out)
{
    if (dim != 2 && dim != 3)
        return RC_EINVAL;
    if (!(m > 0.0) || !isfinite(m))
        return RC_EMASS;
    if (!(c > 0.0))
        return RC_ESPEEDOFLIGHT;
    if (!isfinite(kT) || !isfinite(normal.x) || !isfinite(normal.y) || !isfinite(normal.z))
        return RC_ENONFINITE;
    if (!(kT > 0.0))
        return RC_EINVAL;
    if (dim == 2 && normal.z != 0.0)
        return RC_EINVAL;
    const double nn = rc_v3_norm(normal);
    if (!(nn > 0.0))
        return RC_EZERONORMAL;
    const double k = rc_inv_c2_of(c);
    const rc_vec3 e = rc_v3_scale(1.0 / nn, normal);
    if (dim == 2) {
        /* K = kT x, x of density ~ sqrt(x (2 m + k kT x)) e^-x; p^2 = K (2 m + k K) */
        const double x = kinetic_2d(r, m, k * kT);
        const double q = sqrt(x * (2.0 * m + k * kT * x) * kT);
        const double sa = 2.0 * rc_rng_uniform(r) - 1.0, ca = sqrt(1.0 - sa * sa);
        const rc_vec3 t = rc_v3(-e.y, e.x, 0.0);
        *p_out = rc_v3_add(rc_v3_scale(q * ca, e), rc_v3_scale(q * sa, t));
        return RC_OK;
    }
    /* K: Gamma(3, kT) with weight kT/(kT + m c^2) = kT k/(kT k + m), else Gamma(2, kT) */
    double K = expo(r) + expo(r);
    if (rc_rng_uniform(r) * (kT * k + m) < kT * k)
        K += expo(r);
    K *= kT;
    /* p^2 = K (K + 2 m c^2)/c^2 = K (2 m + K/c^2), classical at k = 0 */
    const double q = sqrt(K * (2.0 * m + k * K));
    /* direction: cos a = sqrt(U) about the normal (density 2 cos a), azimuth uniform */
    const rc_vec3 t0 = fabs(e.x) < 0.9 ? rc_v3(1, 0, 0) : rc_v3(0, 1, 0);
    rc_vec3 e1 = rc_v3_cross(e, t0);
    e1 = rc_v3_scale(1.0 / rc_v3_norm(e1), e1);
    const rc_vec3 e2 = rc_v3_cross(e, e1);
    const double ca = sqrt(rc_rng_uniform(r)), sa = sqrt(1.0 - ca * ca);
    const double ph = 2.0 * M_PI * rc_rng_uniform(r);
    *p_out = rc_v3_add(rc_v3_scale(q * ca, e),
                       rc_v3_add(rc_v3_scale(q * sa * cos(ph), e1), rc_v3_scale(q * sa * sin(ph), e2)));
    return RC_OK;
}
