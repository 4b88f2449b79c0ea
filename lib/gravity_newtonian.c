/* gravity_newtonian.c — the field acting on rest mass in the table frame, dp/dt = -m g e_z:
 * the textbook constant force (hyperbolic motion), with H = E + m g z conserved. Closed
 * forms of papers/gravity.md sections 2 and 3, written so that inv_c2 = 0 is the parabola. */
#include <float.h>

#include "gravity_private.h"

/* The ball's invariants along its path: a2 = m^2 + p_perp^2/c^2 and the relativistic mass
 * M(pz) = sqrt(a2 + pz^2/c^2). */
static double mass_at(double a2, double pz, double inv_c2) { return sqrt(a2 + pz * pz * inv_c2); }

static int newton_drift(const rc_gravity *f, double m, rc_vec3 *x, rc_vec3 *p, double dt)
{
    int st = rc_gravity_check_(f, m, *x, *p);
    if (st == RC_OK)
        st = rc_gravity_arg_dt_(dt);
    if (st != RC_OK)
        return st;
    const int ax = f->axis;
    const double i2 = f->inv_c2, mg = m * f->g;
    const double pz0 = rc_v3_get(*p, ax), pz = pz0 - mg * dt;
    rc_vec3 pp = *p;
    rc_v3_set(&pp, ax, 0.0);
    const double a2 = m * m + rc_v3_norm2(pp) * i2;
    const double m0 = mass_at(a2, pz0, i2), mt = mass_at(a2, pz, i2);
    /* M0 Mt - pz0 pz / c^2 (> 0), as a quotient where the two products nearly cancel */
    const double w = pz0 * pz > 0.0
                         ? (a2 * a2 + a2 * i2 * (pz0 * pz0 + pz * pz)) / (m0 * mt + pz0 * pz * i2)
                         : m0 * mt - pz0 * pz * i2;
    const double q = dt * (a2 + w) / ((m0 + mt) * a2); /* the integral of dt/M, to first order */
    const double phi = q * grav_asinhc(mg * q * sqrt(i2));
    rc_vec3 xn = rc_v3_axpy(*x, phi, pp);
    rc_v3_set(&xn, ax, rc_v3_get(*x, ax) + (pz0 + pz) * dt / (m0 + mt));
    rc_vec3 pn = *p;
    rc_v3_set(&pn, ax, pz);
    return rc_gravity_put_(x, p, xn, pn);
}

double rc_gravity_newton_flight_(const rc_gravity *f, double m, rc_vec3 p, double dt)
{
    const int ax = f->axis;
    const double i2 = f->inv_c2, mg = m * f->g;
    const double pz0 = rc_v3_get(p, ax), pz = pz0 - mg * dt;
    rc_vec3 pp = p;
    rc_v3_set(&pp, ax, 0.0);
    const double a2 = m * m + rc_v3_norm2(pp) * i2;
    const double m0 = mass_at(a2, pz0, i2), mt = mass_at(a2, pz, i2);
    const double w = pz0 * pz > 0.0
                         ? (a2 * a2 + a2 * i2 * (pz0 * pz0 + pz * pz)) / (m0 * mt + pz0 * pz * i2)
                         : m0 * mt - pz0 * pz * i2;
    const double q = dt * (a2 + w) / ((m0 + mt) * a2);
    return q * grav_asinhc(mg * q * sqrt(i2));
}

static int newton_plane_time(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p, int k,
                             double X, double *dt)
{
    int st = rc_gravity_check_(f, m, x, p);
    if (st == RC_OK)
        st = rc_gravity_arg_plane_(k, X, dt);
    if (st != RC_OK)
        return st;
    const int ax = f->axis;
    const double i2 = f->inv_c2, mg = m * f->g;
    const double pz0 = rc_v3_get(p, ax);
    rc_vec3 pp = p;
    rc_v3_set(&pp, ax, 0.0);
    const double a2 = m * m + rc_v3_norm2(pp) * i2;
    const double m0 = mass_at(a2, pz0, i2);
    double t;
    if (k == ax) {
        /* energy: c^2 (M_X - M0) = m g Z, Z the height above the plane; then pz at the plane */
        const double Z = rc_v3_get(x, ax) - X;
        const double mx = m0 + mg * Z * i2;
        const double P2 = pz0 * pz0 + mg * Z * (mx + m0);
        if (!(P2 >= 0.0))
            return RC_MISS; /* the plane is above the top of the path */
        const double P = sqrt(P2);
        if (Z > 0.0) /* falling onto it: pz = -P */
            t = pz0 >= 0.0 ? (pz0 + P) / mg : Z * (mx + m0) / (P - pz0);
        else if (Z < 0.0) { /* rising to it: pz = +P */
            if (!(pz0 > 0.0))
                return RC_MISS;
            t = -Z * (mx + m0) / (pz0 + P);
        } else {
            if (!(pz0 > 0.0))
                return RC_MISS;
            t = 2.0 * pz0 / mg; /* back on the plane it starts on */
        }
    } else {
        /* x_k(t) = x_k + p_k * (integral of dt/M), inverted in closed form */
        const double pk = rc_v3_get(p, k);
        if (pk == 0.0)
            return RC_MISS;
        const double want = (X - rc_v3_get(x, k)) / pk;
        if (!(want > 0.0))
            return RC_MISS;
        const double a = sqrt(a2), sig = mg * want * sqrt(i2);
        const double alpha = asinh(pz0 * sqrt(i2) / a);
        t = a * want * grav_sinhc(0.5 * sig) * cosh(alpha - 0.5 * sig);
    }
    if (!isfinite(t) || !(t > 0.0))
        return RC_MISS;
    *dt = t;
    return RC_OK;
}

static int newton_energy(const rc_gravity *f, double m, rc_vec3 x, rc_vec3 p, double *h)
{
    int st = rc_gravity_check_(f, m, x, p);
    if (st != RC_OK)
        return st;
    if (!h)
        return RC_EINVAL;
    *h = rc_kinetic_energy(m, p, f->inv_c2) + m * f->g * rc_v3_get(x, f->axis);
    return RC_OK;
}


/* Two balls at one table instant. Their accelerations differ with their momenta, so the
 * contact has no closed form: conservative advancement, each step one the gap cannot close
 * in, until the gap is a few roundings of the contact distance. The pair's relative
 * acceleration is at most rel_accel_bound's (papers/gravity.md section 3): 2 g, and
 * 2 g |u_a - u_b| / c with u = p/m constant in difference, so that nearly comoving balls
 * take long steps instead of the 2 g ones' sqrt(gap / g). */
static double rel_accel_bound(const rc_gravity *f, const rc_toi_ball *a, const rc_toi_ball *b)
{
    const double du = rc_v3_norm(rc_v3_sub(rc_v3_scale(1.0 / a->m, a->p), rc_v3_scale(1.0 / b->m, b->p)));
    return f->g * fmin(2.0, 2.0 * du * sqrt(f->inv_c2));
}

static int newton_pair_time(const rc_gravity *f, const rc_toi_ball *a, const rc_toi_ball *b,
                            double t_max, double *dt)
{
    int st = rc_gravity_pair_check_(f, a, b, t_max, dt);
    if (st != RC_OK)
        return st;
    if (!isfinite(t_max))
        return RC_EINVAL; /* the advancement needs a horizon */
    const double i2 = f->inv_c2, d = a->r + b->r, tol = RC_GRAVITY_TOUCH * d;
    const double acc = rel_accel_bound(f, a, b); /* (the same all along: du is constant) */
    rc_vec3 xa = a->x, pa = a->p, xb = b->x, pb = b->p;
    {
        /* No contact by t_max when the straight relative line stays a margin farther than
         * d + acc t_max^2/2 all along: the relative path leaves that line by at most
         * acc t^2/2. The margin, 2 tol, is far above the drifts' rounding. Most
         * neighbours are rejected here, without a step. */
        const rc_vec3 dx = rc_v3_sub(xb, xa);
        const rc_vec3 dv = rc_v3_sub(rc_velocity(b->m, pb, i2), rc_velocity(a->m, pa, i2));
        const double w2 = rc_v3_norm2(dv), b0 = rc_v3_dot(dx, dv);
        const double tc = b0 < 0.0 && w2 > 0.0 ? fmin(-b0 / w2, t_max) : 0.0;
        const double dmin = rc_v3_norm(rc_v3_axpy(dx, tc, dv));
        if (dmin - 0.5 * acc * t_max * t_max > d + 2.0 * tol)
            return RC_MISS;
    }
    double t = 0.0;
    for (long it = 0; it < 1000000; it++) {
        const rc_vec3 dx = rc_v3_sub(xb, xa);
        const rc_vec3 dv = rc_v3_sub(rc_velocity(b->m, pb, i2), rc_velocity(a->m, pa, i2));
        const double dist = rc_v3_norm(dx), gap = dist - d, w = rc_v3_norm(dv);
        if (it == 0 && gap < -tol)
            return RC_EOVERLAP;
        const int approaching = rc_v3_dot(dx, dv) < 0.0;
        if (gap <= tol && approaching) {
            *dt = t;
            return RC_OK;
        }
        /* the longest step the gap survives: the straight distance is convex, so it falls
         * no faster than the approach speed along the centres, wn, and the relative
         * acceleration (at most acc) moves the pair apart from its line by at most
         * acc t^2 / 2; the gap is then at least gap - wn t - acc t^2 / 2 (a grazing pair
         * takes long steps). Or, touching and parting, a step that lets the pair part by a
         * rounding's worth. */
        const double wn = fmax(-rc_v3_dot(dx, dv) / fmax(dist, DBL_MIN), 0.0), gp = fmax(gap, 0.0);
        double step = 2.0 * gp / (wn + sqrt(wn * wn + 2.0 * acc * gp));
        if (!(step > 4.0 * DBL_EPSILON * (t + 1.0)))
            step = fmax(tol / fmax(w, DBL_MIN), 4.0 * DBL_EPSILON * (t + 1.0));
        if (t + step > t_max)
            return RC_MISS;
        if (newton_drift(f, a->m, &xa, &pa, step) != RC_OK ||
            newton_drift(f, b->m, &xb, &pb, step) != RC_OK)
            return RC_ENONFINITE;
        t += step;
    }
    return RC_ENOCONVERGE;
}

const rc_gravity_coupling rc_gravity_newtonian = {
    .name = "newtonian",
    .summary = "force -m g on rest mass in the table frame; H = E + m g z",
    .drift = newton_drift,
    .plane_time = newton_plane_time,
    .energy = newton_energy,
    .pair_time = newton_pair_time,
};
