/* kinematics.c — gamma, rapidity, velocity <-> momentum, boosts and ZMF, all through
 * inv_c2 = 1/c^2 so that inv_c2 = 0 is the exact classical limit. */
#include <math.h>

#include "relcol/kinematics.h"
#include "relcol/status.h"
#include "kinematics_private.h"
#include "pair_axis.h"

double rc_inv_c2_of(double c) { return isinf(c) ? 0.0 : 1.0 / (c * c); }

int rc_inv_c2(double c, double *inv_c2)
{
    if (!(c > 0.0))
        return RC_ESPEEDOFLIGHT;
    *inv_c2 = rc_inv_c2_of(c);
    if (*inv_c2 == 0.0 && !isinf(c))
        return RC_ESPEEDOFLIGHT; /* c so large that 1/c^2 underflows: use inf */
    if (isinf(*inv_c2))
        return RC_ESPEEDOFLIGHT; /* c so small that 1/c^2 overflows */
    return RC_OK;
}

double rc_mass_rel(double m, rc_vec3 p, double inv_c2)
{
    return sqrt(m * m + rc_v3_norm2(p) * inv_c2);
}

double rc_gamma_m1(double m, rc_vec3 p, double inv_c2)
{
    double x = rc_v3_norm2(p) * inv_c2;
    return x / (m * (sqrt(m * m + x) + m));
}

double rc_gamma(double m, rc_vec3 p, double inv_c2) { return rc_mass_rel(m, p, inv_c2) / m; }

double rc_kinetic_energy(double m, rc_vec3 p, double inv_c2)
{
    return rc_v3_norm2(p) / (rc_mass_rel(m, p, inv_c2) + m);
}

double rc_rapidity(double m, rc_vec3 p, double inv_c2)
{
    return asinh(rc_v3_norm(p) * sqrt(inv_c2) / m);
}

rc_vec3 rc_velocity(double m, rc_vec3 p, double inv_c2)
{
    return rc_v3_scale(1.0 / rc_mass_rel(m, p, inv_c2), p);
}

int rc_gamma_from_velocity(rc_vec3 v, double inv_c2, double *gamma)
{
    if (!rc_v3_isfinite(v))
        return RC_ENONFINITE;
    double b2 = rc_v3_norm2(v) * inv_c2;
    if (!(b2 < 1.0))
        return RC_ESPEED;
    *gamma = 1.0 / sqrt((1.0 - b2));
    return RC_OK;
}

int rc_momentum_from_velocity(double m, rc_vec3 v, double inv_c2, rc_vec3 *p)
{
    if (!isfinite(m))
        return RC_ENONFINITE;
    if (!(m > 0.0))
        return RC_EMASS;
    double g;
    int st = rc_gamma_from_velocity(v, inv_c2, &g);
    if (st != RC_OK)
        return st;
    *p = rc_v3_scale(m * g, v);
    return RC_OK;
}

void rc_boost_g(rc_vec3 w, double g, double inv_c2, rc_four *a) { rc_boost_g_(w, g, inv_c2, a); }

int rc_boost(rc_vec3 w, double inv_c2, rc_four *a)
{
    double g;
    int st = rc_gamma_from_velocity(w, inv_c2, &g);
    if (st != RC_OK)
        return st;
    rc_boost_g(w, g, inv_c2, a);
    return RC_OK;
}

int rc_velocity_boost(rc_vec3 v, rc_vec3 w, double inv_c2, rc_vec3 *out)
{
    double gv;
    int st = rc_gamma_from_velocity(v, inv_c2, &gv);
    if (st != RC_OK)
        return st;
    /* four-velocity of unit rest mass: (gamma, gamma v) */
    rc_four a = {gv, rc_v3_scale(gv, v)};
    st = rc_boost(w, inv_c2, &a);
    if (st != RC_OK)
        return st;
    *out = rc_v3_scale(1.0 / a.t, a.x);
    return RC_OK;
}

int rc_velocity_add(rc_vec3 w, rc_vec3 vprime, double inv_c2, rc_vec3 *out)
{
    return rc_velocity_boost(vprime, rc_v3_scale(-1.0, w), inv_c2, out);
}

rc_four rc_particle_four(const rc_particle *b, double inv_c2)
{
    rc_four f = {rc_mass_rel(b->m, b->p, inv_c2), b->p};
    return f;
}

/* M - |P|/c for n balls of total energy / c^2 M and momentum P, pc = |P|/c. When the
 * balls' ZMF moves near c (|P|/c > 0.95 M, as pair_axis.h's RC_PAIR_FAST) the difference
 * keeps only the rounding of M, gamma^2 times it; then it is the sum over the balls of
 * M_i - p_i.uhat/c (uhat = P/|P|, the identity holds for the exact P and its rounding
 * moves the terms by its square only), each positive: T_i^2/(M_i + p_i.uhat/c) for a ball
 * moving along uhat, with T_i^2 = m_i^2 + |p_i x uhat|^2/c^2 (rc_cross_exact), else M_i +
 * |p_i.uhat|/c. */
static double zmf_minus(const rc_particle *b, size_t n, double inv_c2, double M, rc_vec3 P,
                        double pc)
{
    if (!(pc * pc > RC_PAIR_FAST * M * M))
        return M - pc;
    const rc_vec3 uh = rc_v3_scale(1.0 / rc_v3_norm(P), P);
    const double sqrt_k = sqrt(inv_c2);
    double h = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double Mi = rc_mass_rel(b[i].m, b[i].p, inv_c2);
        const double pl = rc_v3_dot(b[i].p, uh) * sqrt_k;
        if (pl > 0.0) {
            const double T2 = b[i].m * b[i].m + rc_v3_norm2(rc_cross_exact(b[i].p, uh)) * inv_c2;
            h += T2 / (Mi + pl);
        } else {
            h += Mi - pl;
        }
    }
    return h;
}

int rc_zmf(const rc_particle *b, size_t n, double inv_c2, rc_vec3 *u, double *minv)
{
    if (n == 0)
        return RC_EINVAL;
    double M = 0.0;
    rc_vec3 P = rc_v3(0, 0, 0);
    for (size_t i = 0; i < n; i++) {
        int st = rc_particle_check(&b[i]);
        if (st != RC_OK)
            return st;
        M += rc_mass_rel(b[i].m, b[i].p, inv_c2);
        P = rc_v3_add(P, b[i].p);
    }
    if (u)
        *u = rc_v3_scale(1.0 / M, P);
    if (minv) {
        if (n == 2) {
            *minv = rc_pair_invariant_mass(&b[0], &b[1], inv_c2);
        } else {
            double pc = sqrt(rc_v3_norm2(P) * inv_c2);
            *minv = sqrt(zmf_minus(b, n, inv_c2, M, P, pc) * (M + pc));
        }
    }
    return RC_OK;
}

double rc_pair_invariant_mass(const rc_particle *a, const rc_particle *b, double inv_c2)
{
    /* minv^2 = (m0+m1)^2 + 2 (M0 M1 - m0 m1 - p0.p1/c^2), with M0 M1 - m0 m1 written
     * through the kinetic parts K = M - m = p^2/c^2 / (M + m): the large m0 m1 terms
     * never meet in a subtraction. */
    double M0 = rc_mass_rel(a->m, a->p, inv_c2), M1 = rc_mass_rel(b->m, b->p, inv_c2);
    /* Both balls fast the same way (pair_axis.h, RC_GAMMA_FAST): the kinetic parts are then
     * gamma^2 times x, whose last term cancels them. minv^2 = m0^2 + m1^2 + 2 (M0 M1 -
     * p0.p1/c^2) instead, the last term from rc_pair_dot as a sum of positive terms: every
     * term positive, minv to a few roundings. Otherwise x loses a few bits at most (one
     * ball's speed is below 0.95 c or the two move apart) and the form below is kept. */
    if (M0 > RC_GAMMA_FAST * a->m && M1 > RC_GAMMA_FAST * b->m &&
        rc_v3_dot(a->p, b->p) > 0.0) {
        const double d = rc_pair_dot(a->m, a->p, M0, b->m, b->p, M1, inv_c2, sqrt(inv_c2));
        return sqrt(a->m * a->m + b->m * b->m + 2.0 * d);
    }
    double K0 = rc_v3_norm2(a->p) * inv_c2 / (M0 + a->m);
    double K1 = rc_v3_norm2(b->p) * inv_c2 / (M1 + b->m);
    double x = a->m * K1 + b->m * K0 + K0 * K1 - rc_v3_dot(a->p, b->p) * inv_c2;
    double s = a->m + b->m;
    return sqrt(s * s + 2.0 * x);
}

int rc_particle_check(const rc_particle *b)
{
    if (!isfinite(b->m) || !rc_v3_isfinite(b->p))
        return RC_ENONFINITE;
    if (!(b->m > 0.0))
        return RC_EMASS;
    return RC_OK;
}
