/* gravity_equivalence.c — the box frame of a floor with proper acceleration g (Rindler):
 * the clock is the floor's proper time tau, a free ball's path is the image of a straight
 * line of the box's momentary rest frame, and H = (1 + g z/c^2) E is conserved (Tolman's
 * redshifted energy). Closed forms of papers/gravity.md sections 2 and 3. */
#include <float.h>

#include "gravity_private.h"

/* 1 + g z/c^2 at height z: the lapse sqrt(-g_00); > 0 above the horizon */
static double lapse(const rc_gravity *f, double z) { return 1.0 + f->g * z * f->inv_c2; }

/* The box time from an event of the ball's line at t' (comoving-frame time since tau0) and
 * height zp there: tanh(g dtau/c) = c t'/(zp + L). RC_MISS beyond the horizon. */
static int box_time(const rc_gravity *f, double tp, double zp, double *dtau)
{
    const double l = lapse(f, zp);
    if (!(l > 0.0))
        return RC_MISS;
    const double xarg = f->g * tp * sqrt(f->inv_c2) / l;
    if (!(xarg < 1.0))
        return RC_MISS;
    *dtau = tp * grav_atanhc(xarg) / l;
    return isfinite(*dtau) && *dtau > 0.0 ? RC_OK : RC_MISS;
}

static int equiv_check(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p)
{
    int st = rc_gravity_check_(f, m, x, p);
    if (st != RC_OK)
        return st;
    return lapse(f, rc_v3_get(x, f->axis)) > 0.0 ? RC_OK : RC_EINVAL; /* below the horizon */
}

static int equiv_drift(const rc_gravity *f, double m, rc_vec3 *x, rc_vec3 *p, double dt)
{
    int st = equiv_check(f, m, *x, *p);
    if (st == RC_OK)
        st = rc_gravity_arg_dt_(dt);
    if (st != RC_OK)
        return st;
    const int ax = f->axis;
    const double i2 = f->inv_c2, g = f->g;
    const double m0 = rc_mass_rel(m, *p, i2);
    const rc_vec3 v = rc_v3_scale(1.0 / m0, *p);
    const double z0 = rc_v3_get(*x, ax), vz = rc_v3_get(v, ax), pz0 = rc_v3_get(*p, ax);
    const double phi = g * dt * sqrt(i2), ch = cosh(phi);
    const double T = grav_tanhc(phi), sh = grav_sinhc(phi), hc = grav_sinhc(0.5 * phi);
    /* where the line meets the slice: comoving time t', height z' there */
    const double tp = lapse(f, z0) * dt * T / (1.0 - g * vz * dt * i2 * T);
    const double zp = z0 + vz * tp;
    rc_vec3 xn = rc_v3_axpy(*x, tp, v);
    rc_v3_set(&xn, ax, (zp - 0.5 * g * dt * dt * hc * hc) / ch);
    rc_vec3 pn = *p; /* the boost by phi along the field */
    rc_v3_set(&pn, ax, ch * pz0 - g * dt * sh * m0);
    return rc_gravity_put_(x, p, xn, pn);
}

double rc_gravity_equiv_flight_(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p, double dt)
{
    const double i2 = f->inv_c2, g = f->g;
    const double vz = rc_v3_get(p, f->axis) / rc_mass_rel(m, p, i2);
    const double phi = g * dt * sqrt(i2), T = grav_tanhc(phi);
    return lapse(f, rc_v3_get(x, f->axis)) * dt * T / (1.0 - g * vz * dt * i2 * T);
}

static int equiv_plane_time(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p, int k,
                            double X, double *dt)
{
    int st = equiv_check(f, m, x, p);
    if (st == RC_OK)
        st = rc_gravity_arg_plane_(k, X, dt);
    if (st != RC_OK)
        return st;
    const int ax = f->axis;
    const double i2 = f->inv_c2;
    const double m0 = rc_mass_rel(m, p, i2);
    const double z0 = rc_v3_get(x, ax), vz = rc_v3_get(p, ax) / m0;
    double tp;
    if (k == ax) {
        if (!(lapse(f, X) > 0.0))
            return RC_EINVAL; /* a plane at or below the horizon */
        /* the line against the hyperbola of the box points at height X (proper
         * acceleration gx), divided through by 2 (L + X) */
        const double gx = f->g / lapse(f, X), Z = z0 - X;
        rc_vec3 pp = p;
        rc_v3_set(&pp, ax, 0.0);
        const double slow = (m * m + rc_v3_norm2(pp) * i2) / (m0 * m0); /* 1 - vz^2/c^2 */
        st = rc_gravity_first_root_(-0.5 * gx * slow, (1.0 + gx * Z * i2) * vz,
                                    Z * (1.0 + 0.5 * gx * Z * i2), &tp);
        if (st != RC_OK)
            return st;
    } else {
        const double vk = rc_v3_get(p, k) / m0;
        if (vk == 0.0)
            return RC_MISS;
        tp = (X - rc_v3_get(x, k)) / vk;
        if (!(tp > 0.0))
            return RC_MISS;
    }
    return box_time(f, tp, z0 + vz * tp, dt);
}

static int equiv_energy(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p, double *h)
{
    int st = equiv_check(f, m, x, p);
    if (st != RC_OK)
        return st;
    if (!h)
        return RC_EINVAL;
    const double z = rc_v3_get(x, f->axis), k = rc_kinetic_energy(m, p, f->inv_c2);
    *h = k + m * f->g * z + f->g * z * k * f->inv_c2;
    return RC_OK;
}


/* Two balls on one slice of the box's time: each meets the slice tanh(g dtau/c) = g s/c at
 * t' = a s/(1 - b s) on its line, a = 1 + g z/c^2, b = g v_z/c^2. Their distance there is
 * the Minkowski interval of the two events, and times Q = (1 - b_0 s)(1 - b_1 s) squared it
 * is a quartic in s (papers/gravity.md section 3): |A(s)|^2 - (c C(s))^2 - d^2 Q(s)^2 with
 * A = (the events' separation) Q and C = (their time difference) Q. */
static int equiv_pair_time(const rc_gravity *f, const rc_toi_ball *a, const rc_toi_ball *b,
                           double t_max, double *dt)
{
    int st = rc_gravity_pair_check_(f, a, b, t_max, dt);
    if (st == RC_OK)
        st = equiv_check(f, a->m, a->x, a->p);
    if (st == RC_OK)
        st = equiv_check(f, b->m, b->x, b->p);
    if (st != RC_OK)
        return st;
    const int ax = f->axis;
    const double i2 = f->inv_c2, g = f->g, rc = sqrt(i2), d = a->r + b->r;
    const rc_vec3 va = rc_v3_scale(1.0 / rc_mass_rel(a->m, a->p, i2), a->p);
    const rc_vec3 vb = rc_v3_scale(1.0 / rc_mass_rel(b->m, b->p, i2), b->p);
    const double aa = lapse(f, rc_v3_get(a->x, ax)), ab = lapse(f, rc_v3_get(b->x, ax));
    const double ba = g * rc_v3_get(va, ax) * i2, bb = g * rc_v3_get(vb, ax) * i2;
    const double q[3] = {1.0, -(ba + bb), ba * bb};
    const rc_vec3 dx = rc_v3_sub(a->x, b->x);
    double p[5] = {0};
    for (int k = 0; k < 3; k++) {
        const double x0 = rc_v3_get(dx, k), wa = rc_v3_get(va, k) * aa, wb = rc_v3_get(vb, k) * ab;
        const double A[3] = {x0, x0 * q[1] + wa - wb, x0 * q[2] - wa * bb + wb * ba};
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                p[i + j] += A[i] * A[j];
    }
    const double dz = rc_v3_get(dx, ax);
    const double C[3] = {0.0, g * rc * dz,
                         g * rc * (ab * rc_v3_get(va, ax) - aa * rc_v3_get(vb, ax))};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            p[i + j] -= C[i] * C[j] + d * d * q[i] * q[j];
    if (p[0] < -RC_GRAVITY_TOUCH * d * d)
        return RC_EOVERLAP;
    if (p[0] <= RC_GRAVITY_TOUCH * d * d && p[1] < 0.0) {
        *dt = 0.0; /* touching and approaching */
        return RC_OK;
    }
    /* the slice parameter s = (c/g) tanh(g dtau/c) < c/g, and s at t_max */
    const double s_max = rc > 0.0 ? 1.0 / (g * rc) : INFINITY;
    const double s_hi = isfinite(t_max) ? t_max * grav_tanhc(g * t_max * rc) : s_max;
    double s;
    const double lo = p[0] > RC_GRAVITY_TOUCH * d * d ? 0.0 : DBL_MIN;
    st = rc_gravity_poly_first_fall_(p, 4, lo, fmin(s_hi, s_max), &s);
    if (st != RC_OK)
        return st;
    const double x = g * s * rc;
    if (!(x < 1.0))
        return RC_MISS;
    *dt = s * grav_atanhc(x);
    return *dt <= t_max ? RC_OK : RC_MISS;
}

const rc_gravity_coupling rc_gravity_equivalence = {
    .name = "equivalence",
    .summary = "box of a floor accelerated at g (Rindler); H = (1 + g z/c^2) E",
    .drift = equiv_drift,
    .plane_time = equiv_plane_time,
    .energy = equiv_energy,
    .pair_time = equiv_pair_time,
};
