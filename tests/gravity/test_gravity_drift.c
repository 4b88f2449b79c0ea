/* test_gravity_drift — each coupling's closed-form free path (papers/gravity.md section 2)
 * against Hamilton's equations integrated by rk8pd; its energy constant along the path;
 * two drifts equal to one; inv_c2 = 0 the parabola; bad inputs refused. */
#include "gravity_util.h"

static const double cs[] = {1.0, 3.0, 30.0, INFINITY};

static void test_against_ode(void)
{
    rc_test_rng r = {0x9a11};
    for (int e = 0; e < 2; e++) {
        const rc_gravity_coupling *cp = e ? &rc_gravity_equivalence : &rc_gravity_newtonian;
        for (size_t ic = 0; ic < sizeof cs / sizeof cs[0]; ic++) {
            for (int i = 0; i < 200; i++) {
                rc_gravity f = {rc_test_range(&r, 0.2, 2.0), i % 3, 0.0};
                rc_inv_c2(cs[ic], &f.inv_c2);
                double m;
                rc_vec3 x, p;
                grav_random_ball(&r, f.axis, 3.0, 2.0, &m, &x, &p);
                const double dt = rc_test_range(&r, 0.0, 3.0);
                rc_vec3 xa = x, pa = p, xb = x, pb = p;
                ENSURE(cp->drift(&f, m, &xa, &pa, dt) == RC_OK);
                ENSURE(grav_integrate(&f, e, m, &xb, &pb, dt) == GSL_SUCCESS);
                /* rk8pd's own error, accumulated over at most a few hundred steps */
                const double sx = 1.0 + rc_v3_norm(xb), sp = m * (1.0 + rc_v3_norm(pb) / m);
                ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(xa, xb)), 0.0, 1e-10, sx);
                ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(pa, pb)), 0.0, 1e-10, sp);
                /* the conserved energy: round-off of its terms */
                double h0, h1;
                ENSURE(cp->energy(&f, m, x, p, &h0) == RC_OK);
                ENSURE(cp->energy(&f, m, xa, pa, &h1) == RC_OK);
                const double kin = rc_kinetic_energy(m, p, f.inv_c2) +
                                   rc_kinetic_energy(m, pa, f.inv_c2);
                const double pot = m * f.g * (fabs(rc_v3_get(x, f.axis)) +
                                              fabs(rc_v3_get(xa, f.axis)));
                ENSURE_CLOSE(h1, h0, 1e-13, kin + pot + m * f.g * f.g * dt * dt);
            }
        }
    }
}

static void test_composition(void)
{
    rc_test_rng r = {0x9a12};
    for (int e = 0; e < 2; e++) {
        const rc_gravity_coupling *cp = e ? &rc_gravity_equivalence : &rc_gravity_newtonian;
        for (size_t ic = 0; ic < sizeof cs / sizeof cs[0]; ic++) {
            for (int i = 0; i < 500; i++) {
                rc_gravity f = {1.0, 2, 0.0};
                rc_inv_c2(cs[ic], &f.inv_c2);
                double m;
                rc_vec3 x, p;
                grav_random_ball(&r, 2, 3.0, 2.0, &m, &x, &p);
                const double a = rc_test_range(&r, 0, 2), b = rc_test_range(&r, 0, 2);
                rc_vec3 x1 = x, p1 = p, x2 = x, p2 = p;
                ENSURE(cp->drift(&f, m, &x1, &p1, a) == RC_OK);
                ENSURE(cp->drift(&f, m, &x1, &p1, b) == RC_OK);
                ENSURE(cp->drift(&f, m, &x2, &p2, a + b) == RC_OK);
                const double sx = 1.0 + rc_v3_norm(x2) + rc_v3_norm(p2) / m * (a + b);
                ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(x1, x2)), 0.0, 1e-13, sx);
                ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(p1, p2)), 0.0, 1e-13,
                             rc_v3_norm(p2) + m * (a + b));
            }
        }
    }
}

static void test_classical_parabola(void)
{
    rc_test_rng r = {0x9a13};
    for (int e = 0; e < 2; e++) {
        const rc_gravity_coupling *cp = e ? &rc_gravity_equivalence : &rc_gravity_newtonian;
        for (int i = 0; i < 1000; i++) {
            rc_gravity f = {rc_test_range(&r, 0.2, 2.0), i % 3, 0.0};
            double m;
            rc_vec3 x, p;
            grav_random_ball(&r, f.axis, 3.0, 2.0, &m, &x, &p);
            const double t = rc_test_range(&r, 0, 3);
            rc_vec3 xa = x, pa = p;
            ENSURE(cp->drift(&f, m, &xa, &pa, t) == RC_OK);
            rc_vec3 xe = rc_v3_axpy(x, t / m, p), pe = p;
            rc_v3_set(&xe, f.axis, rc_v3_get(xe, f.axis) - 0.5 * f.g * t * t);
            rc_v3_set(&pe, f.axis, rc_v3_get(p, f.axis) - m * f.g * t);
            ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(xa, xe)), 0.0, 4e-16,
                         rc_v3_norm(x) + rc_v3_norm(p) / m * t + f.g * t * t);
            ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(pa, pe)), 0.0, 4e-16, rc_v3_norm(p) + m * f.g * t);
        }
    }
}

static void test_bad_inputs(void)
{
    const rc_gravity ok = {1.0, 2, 1.0};
    for (int e = 0; e < 2; e++) {
        const rc_gravity_coupling *cp = e ? &rc_gravity_equivalence : &rc_gravity_newtonian;
        rc_vec3 x = rc_v3(0, 0, 1), p = rc_v3(0.1, 0, 0.2), x0 = x, p0 = p;
        double t, h;
        rc_gravity bad = ok;
        bad.g = 0.0;
        ENSURE(cp->drift(&bad, 1, &x, &p, 1) == RC_EINVAL);
        bad = ok;
        bad.axis = 3;
        ENSURE(cp->plane_time(&bad, 1, x, p, 2, 0, &t) == RC_EINVAL);
        bad = ok;
        bad.inv_c2 = -1;
        ENSURE(cp->energy(&bad, 1, x, p, &h) == RC_EINVAL);
        bad = ok;
        bad.g = NAN;
        ENSURE(cp->drift(&bad, 1, &x, &p, 1) == RC_ENONFINITE);
        ENSURE(cp->drift(&ok, 0, &x, &p, 1) == RC_EMASS);
        ENSURE(cp->drift(&ok, 1, &x, &p, -1) == RC_EINVAL);
        ENSURE(cp->drift(&ok, 1, &x, &p, NAN) == RC_ENONFINITE);
        ENSURE(cp->plane_time(&ok, 1, x, p, 3, 0, &t) == RC_EINVAL);
        ENSURE(cp->plane_time(&ok, 1, x, p, 2, INFINITY, &t) == RC_ENONFINITE);
        ENSURE(cp->plane_time(&ok, 1, x, rc_v3(NAN, 0, 0), 2, 0, &t) == RC_ENONFINITE);
        ENSURE(memcmp(&x, &x0, sizeof x) == 0 && memcmp(&p, &p0, sizeof p) == 0);
    }
    /* equivalence: a ball or a plane at or below the horizon z = -c^2/g */
    rc_vec3 x = rc_v3(0, 0, -1.5), p = rc_v3(0, 0, 0);
    double t;
    ENSURE(rc_gravity_equivalence.drift(&ok, 1, &x, &p, 1) == RC_EINVAL);
    ENSURE(rc_gravity_equivalence.plane_time(&ok, 1, rc_v3(0, 0, 1), p, 2, -1.0, &t) ==
           RC_EINVAL);
    ENSURE(rc_gravity_find("newtonian") == &rc_gravity_newtonian);
    ENSURE(rc_gravity_find("equivalence") == &rc_gravity_equivalence);
    ENSURE(rc_gravity_find("rindler") == NULL && rc_gravity_find(NULL) == NULL);
}

int main(void)
{
    gsl_set_error_handler_off();
    RUN_TEST(test_against_ode);
    RUN_TEST(test_composition);
    RUN_TEST(test_classical_parabola);
    RUN_TEST(test_bad_inputs);
    RC_TEST_MAIN_END();
}
