/* test_soft_conservation.c — the soft integration keeps the total four-momentum (kinetic +
 * internal energy, momentum) to the solver tolerance, splits the internal energy as the
 * four-force dictates, and its CVODE and GSL steppers agree to that tolerance. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "rc_test.h"
#include "soft_cases.h"

#define RTOL 1e-10

static rc_soft_params params(double c, double eps, double kappa, double rtol)
{
    rc_soft_params prm = rc_soft_params_default();
    prm.c = c;
    prm.eps = eps;
    prm.stiffness = kappa;
    prm.rtol = rtol;
    return prm;
}

static rc_vec3 beta(double c, double bx, double by, double bz)
{
    const double unit = isinf(c) ? 1.0 : c;
    return rc_v3(bx * unit, by * unit, bz * unit);
}

/* sum of kinetic energies p^2/(M + m) (finite classically) */
static double kinetic(const rc_particle *b, size_t n, double k)
{
    double e = 0.0;
    for (size_t i = 0; i < n; i++)
        e += rc_kinetic_energy(b[i].m, b[i].p, k);
    return e;
}

static rc_vec3 total_p(const rc_particle *b, size_t n)
{
    rc_vec3 P = rc_v3(0, 0, 0);
    for (size_t i = 0; i < n; i++)
        P = rc_v3_add(P, b[i].p);
    return P;
}

static double sum_abs_p(const rc_particle *b, size_t n)
{
    double s = 0.0;
    for (size_t i = 0; i < n; i++)
        s += rc_v3_norm(b[i].p);
    return s;
}

/* Energy error of the whole run (sampled after every step, in the integration frame) and
 * in the table frame between start and end, over c, eps and impact parameter. Measured
 * (cvode-bdf, rtol 1e-10): energy_error / rtol at most ~700 (BDF's global error over the
 * ~250 steps of a contact, with an oscillation it damps slightly), table-frame energy the
 * same, ZMF momentum at round-off (a linear invariant: BDF's Newton corrections and RK
 * stages keep it exactly up to rounding). Bounds: 3000 rtol for energy (4x margin), 1e-13
 * for the ZMF momentum (about 1000 steps of 1e-16 rounding). */
static void test_two_balls_conserve(void)
{
    const double cs[] = {INFINITY, 2.0, 1.0};
    const double epss[] = {1.0, 0.5, 0.1};
    const double bs[] = {0.0, 0.3, 0.6};
    double worst = 0.0;
    for (int ic = 0; ic < 3; ic++)
        for (int ie = 0; ie < 3; ie++)
            for (int ib = 0; ib < 3; ib++) {
                rc_soft_params prm = params(cs[ic], epss[ie], 1e6, RTOL);
                const double k = rc_inv_c2_of(prm.c);
                rc_particle p[2], q[2];
                rc_vec3 x[2];
                soft_case(k, beta(cs[ic], 0.6, 0.1, 0.0), beta(cs[ic], -0.3, 0.05, 0.1), bs[ib],
                          p, x);
                memcpy(q, p, sizeof q);
                double U[2] = {NAN, NAN};
                rc_soft_result res;
                ENSURE(rc_soft_collide(&rc_soft_cvode_bdf, &prm, 2, q, x, soft_r, U, &res) ==
                       RC_OK);
                ENSURE(res.n_contacts == 1 && res.finished == 1);
                worst = fmax(worst, res.energy_error / RTOL);
                ENSURE_MSG(res.energy_error <= 3000 * RTOL, "energy %.3g", res.energy_error);
                ENSURE_MSG(res.momentum_error <= 1e-13, "momentum %.3g", res.momentum_error);
                /* table frame, start to end: K + U and p */
                const double K0 = kinetic(p, 2, k);
                ENSURE_CLOSE(kinetic(q, 2, k) + U[0] + U[1], K0, 3000 * RTOL, K0);
                /* table momentum gamma_u (p_zmf + u E_zmf / c^2) mixes in the ZMF energy:
                 * at finite c it is kept to the energy's tolerance, at c = inf to rounding */
                ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(total_p(q, 2), total_p(p, 2))), 0.0,
                             k > 0.0 ? 3000 * RTOL : 1e-13, sum_abs_p(p, 2));
                /* rest masses: m'^2 - m^2 is the same for both balls (both receive
                 * m dm/dt = F a / c^2), i.e. m U + U^2/(2 c^2) equal; classically m U */
                const double S0 = soft_m[0] * U[0] + 0.5 * U[0] * U[0] * k;
                const double S1 = soft_m[1] * U[1] + 0.5 * U[1] * U[1] * k;
                if (epss[ie] < 1.0) {
                    ENSURE(U[0] > 0.0 && U[1] > 0.0);
                    ENSURE_CLOSE(S1, S0, 3000 * RTOL, K0 * soft_m[0]);
                    /* the rest masses carry exactly the internal energy */
                    ENSURE_REL(q[0].m, soft_m[0] + U[0] * k, 1e-15);
                } else {
                    /* elastic: the deformation energy stored as rest mass comes back */
                    ENSURE_CLOSE(U[0], 0.0, 3000 * RTOL, K0);
                    ENSURE_CLOSE(U[1], 0.0, 3000 * RTOL, K0);
                }
            }
    printf("  worst energy_error / rtol (cvode-bdf) = %.0f\n", worst);
}

/* The energy error is the solver's: it falls with the tolerance (measured ratios 429 at
 * c = inf and 149 at c = 1 for a factor 1000 in rtol; bound 30). A modelling error in the
 * bookkeeping (a wrong dU/dt) would not fall: ratio ~1. */
static void test_energy_error_follows_tolerance(void)
{
    for (int ic = 0; ic < 2; ic++) {
        const double c = ic ? 1.0 : INFINITY;
        double e[2];
        for (int it = 0; it < 2; it++) {
            rc_soft_params prm = params(c, 0.5, 1e6, it ? 1e-10 : 1e-7);
            rc_particle p[2];
            rc_vec3 x[2];
            soft_case(rc_inv_c2_of(prm.c), beta(c, 0.6, 0.1, 0.0), beta(c, -0.3, 0.05, 0.1), 0.3, p, x);
            rc_soft_result res;
            ENSURE(rc_soft_collide(&rc_soft_cvode_bdf, &prm, 2, p, x, soft_r, NULL, &res) ==
                   RC_OK);
            e[it] = res.energy_error;
        }
        ENSURE_MSG(e[0] / e[1] > 30.0, "c=%g: %.3g -> %.3g", c, e[0], e[1]);
    }
}

/* Three balls: a chain hit from both ends at once (contacts overlap in time) and a
 * sequence of contacts. Four-momentum conserved as for two. */
static void test_three_balls_conserve(void)
{
    const double r3[3] = {0.3, 0.4, 0.35};
    for (int ic = 0; ic < 2; ic++) {
        const double c = ic ? 1.0 : INFINITY;
        for (int eps_i = 0; eps_i < 2; eps_i++) {
            rc_soft_params prm = params(c, eps_i ? 0.6 : 1.0, 1e6, RTOL);
            const double k = rc_inv_c2_of(prm.c);
            rc_particle p[3] = {{1.0, {0, 0, 0}}, {2.0, {0, 0, 0}}, {1.5, {0, 0, 0}}};
            ENSURE(rc_momentum_from_velocity(1.0, beta(c, 0.5, 0.02, 0), k, &p[0].p) == RC_OK);
            ENSURE(rc_momentum_from_velocity(2.0, beta(c, 0.0, 0.0, 0.01), k, &p[1].p) == RC_OK);
            ENSURE(rc_momentum_from_velocity(1.5, beta(c, -0.5, 0, 0), k, &p[2].p) == RC_OK);
            /* symmetric gaps: 0 and 2 reach 1 at (nearly) the same time */
            rc_vec3 x[3] = {rc_v3(-1.2, 0.05, 0), rc_v3(0, 0, 0), rc_v3(1.25, 0, 0.02)};
            rc_particle q[3];
            memcpy(q, p, sizeof q);
            double U[3];
            rc_soft_result res;
            ENSURE(rc_soft_collide(&rc_soft_cvode_bdf, &prm, 3, q, x, r3, U, &res) == RC_OK);
            ENSURE_MSG(res.n_contacts >= 2, "contacts %d", res.n_contacts);
            ENSURE(res.finished == 1);
            ENSURE_MSG(res.energy_error <= 3000 * RTOL, "energy %.3g", res.energy_error);
            ENSURE_MSG(res.momentum_error <= 1e-13, "momentum %.3g", res.momentum_error);
            const double K0 = kinetic(p, 3, k);
            ENSURE_CLOSE(kinetic(q, 3, k) + U[0] + U[1] + U[2], K0, 3000 * RTOL, K0);
            ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(total_p(q, 3), total_p(p, 3))), 0.0,
                         k > 0.0 ? 3000 * RTOL : 1e-13, sum_abs_p(p, 3));
        }
    }
}

/* A small gas: 16 balls on a 4 x 4 grid with random velocities, run for a fixed time with
 * contacts (120 pairs: exercises the general-N paths). Measured: 6 contacts, energy error
 * 469 rtol (cvode-bdf, c = inf) and 795 rtol (c = 1), rk8pd < 0.1 rtol, momentum at
 * round-off. Same bounds as for two balls. */
static void test_sixteen_balls_conserve(void)
{
    enum { N = 16 };
    const rc_soft_stepper *st[2] = {&rc_soft_cvode_bdf, &rc_soft_gsl_rk8pd};
    for (int ic = 0; ic < 2; ic++) {
        const double c = ic ? 1.0 : INFINITY;
        rc_soft_params prm = params(c, 0.7, 1e4, RTOL);
        prm.t_max = 1.0;
        const double k = rc_inv_c2_of(prm.c);
        rc_test_rng g = {2024};
        rc_particle p[N];
        rc_vec3 x[N];
        double r[N];
        for (int i = 0; i < N; i++) {
            r[i] = rc_test_range(&g, 0.25, 0.35);
            p[i].m = r[i] * r[i] * r[i] / 0.027; /* equal density */
            rc_vec3 v = beta(c, rc_test_range(&g, -0.5, 0.5), rc_test_range(&g, -0.5, 0.5),
                             rc_test_range(&g, -0.1, 0.1));
            ENSURE(rc_momentum_from_velocity(p[i].m, v, k, &p[i].p) == RC_OK);
            x[i] = rc_v3((i % 4) * 0.8, (i / 4) * 0.8, 0.0);
        }
        for (int s = 0; s < 2; s++) {
            rc_particle q[N];
            rc_vec3 xx[N];
            double U[N];
            memcpy(q, p, sizeof q);
            memcpy(xx, x, sizeof xx);
            rc_soft_result res;
            ENSURE(rc_soft_collide(st[s], &prm, N, q, xx, r, U, &res) == RC_OK);
            ENSURE_MSG(res.n_contacts == 6, "%s: contacts %d", st[s]->name, res.n_contacts);
            ENSURE_MSG(res.energy_error <= 3000 * RTOL, "%s energy %.3g", st[s]->name,
                       res.energy_error);
            ENSURE_MSG(res.momentum_error <= 1e-13, "%s momentum %.3g", st[s]->name,
                       res.momentum_error);
        }
    }
}

/* CVODE BDF and the two GSL Runge-Kutta steppers reach the same outcome. Measured
 * (rtol 1e-10): largest relative difference 5.1e-9 against cvode-bdf. Bound 1000 rtol:
 * the BDF global error alone is up to ~700 rtol (energy, above). A stepper that
 * mislocated a contact by one of its steps would differ by ~1e-3. */
static void test_steppers_agree(void)
{
    const double cs[] = {INFINITY, 1.5};
    const double epss[] = {1.0, 0.4};
    const double bs[] = {0.0, 0.45};
    double worst = 0.0;
    for (int ic = 0; ic < 2; ic++)
        for (int ie = 0; ie < 2; ie++)
            for (int ib = 0; ib < 2; ib++) {
                rc_soft_params prm = params(cs[ic], epss[ie], 1e5, RTOL);
                rc_particle p[2], out[3][2];
                rc_vec3 x[2];
                soft_case(rc_inv_c2_of(prm.c), beta(cs[ic], 0.5, -0.2, 0.1), beta(cs[ic], -0.4, 0.1, 0.0),
                          bs[ib], p, x);
                const rc_soft_stepper *st[3] = {&rc_soft_cvode_bdf, &rc_soft_gsl_rk8pd,
                                                &rc_soft_gsl_rkf45};
                rc_soft_result res[3];
                for (int s = 0; s < 3; s++) {
                    rc_vec3 xx[2] = {x[0], x[1]};
                    memcpy(out[s], p, sizeof p);
                    ENSURE(rc_soft_collide(st[s], &prm, 2, out[s], xx, soft_r, NULL, &res[s]) ==
                           RC_OK);
                    ENSURE(res[s].n_contacts == 1);
                }
                const double ps = sum_abs_p(p, 2);
                for (int s = 1; s < 3; s++) {
                    const double d = soft_diff(out[s], out[0], ps);
                    worst = fmax(worst, d);
                    ENSURE_MSG(d <= 1000 * RTOL, "%s vs cvode: %.3g", st[s]->name, d);
                    /* the GSL runs conserve as well */
                    ENSURE(res[s].energy_error <= 3000 * RTOL);
                    ENSURE(res[s].momentum_error <= 1e-13);
                }
            }
    printf("  worst stepper difference = %.3g\n", worst);
}

/* eps <-> zeta matching: the classical spring-dashpot restitution formula inverted. */
static void test_damping_ratio(void)
{
    ENSURE(rc_soft_damping_ratio(1.0) == 0.0);
    for (double eps = 0.05; eps < 1.0; eps += 0.05) {
        const double z = rc_soft_damping_ratio(eps);
        ENSURE(z > 0.0 && z < 1.0);
        ENSURE_REL(exp(-M_PI * z / sqrt(1.0 - z * z)), eps, 1e-14);
    }
    ENSURE(isnan(rc_soft_damping_ratio(0.0)));
    ENSURE(isnan(rc_soft_damping_ratio(1.5)));
}

/* Bad input is refused with the right code and leaves the balls untouched. */
static void test_rejects_bad_input(void)
{
    rc_soft_params prm = params(INFINITY, 1.0, 1e6, RTOL);
    rc_particle p[2];
    rc_vec3 x[2];
    soft_case(0.0, rc_v3(0.5, 0, 0), rc_v3(-0.5, 0, 0), 0.0, p, x);
    rc_particle q[2];
    memcpy(q, p, sizeof q);
    const rc_soft_stepper *st = &rc_soft_cvode_bdf;
    ENSURE(rc_soft_collide(NULL, &prm, 2, q, x, soft_r, NULL, NULL) == RC_EINVAL);
    ENSURE(rc_soft_collide(st, &prm, 1, q, x, soft_r, NULL, NULL) == RC_EINVAL);
    rc_soft_params bad = prm;
    bad.eps = 0.0;
    ENSURE(rc_soft_collide(st, &bad, 2, q, x, soft_r, NULL, NULL) == RC_ERESTITUTION);
    bad = prm;
    bad.stiffness = -1.0;
    ENSURE(rc_soft_collide(st, &bad, 2, q, x, soft_r, NULL, NULL) == RC_EINVAL);
    bad = prm;
    bad.rtol = NAN;
    ENSURE(rc_soft_collide(st, &bad, 2, q, x, soft_r, NULL, NULL) == RC_ENONFINITE);
    bad = prm;
    bad.c = -1.0;
    ENSURE(rc_soft_collide(st, &bad, 2, q, x, soft_r, NULL, NULL) == RC_ESPEEDOFLIGHT);
    const double r0[2] = {0.3, 0.0};
    ENSURE(rc_soft_collide(st, &prm, 2, q, x, r0, NULL, NULL) == RC_ERADIUS);
    rc_vec3 xo[2] = {rc_v3(0, 0, 0), rc_v3(0.5, 0, 0)}; /* 0.5 < 0.3 + 0.4 */
    ENSURE(rc_soft_collide(st, &prm, 2, q, xo, soft_r, NULL, NULL) == RC_EOVERLAP);
    rc_vec3 xn[2] = {rc_v3(NAN, 0, 0), x[1]};
    ENSURE(rc_soft_collide(st, &prm, 2, q, xn, soft_r, NULL, NULL) == RC_ENONFINITE);
    q[1].m = 0.0;
    ENSURE(rc_soft_collide(st, &prm, 2, q, x, soft_r, NULL, NULL) == RC_EMASS);
    q[1].m = p[1].m;
    ENSURE(memcmp(q, p, sizeof q) == 0);
    /* the step budget is a failure, not a silent truncation */
    bad = prm;
    bad.max_steps = 3;
    ENSURE(rc_soft_collide(st, &bad, 2, q, x, soft_r, NULL, NULL) == RC_ENOCONVERGE);
    ENSURE(rc_soft_collide(&rc_soft_gsl_rk8pd, &bad, 2, q, x, soft_r, NULL, NULL) ==
           RC_ENOCONVERGE);
    ENSURE(memcmp(q, p, sizeof q) == 0);
}

/* t_max stops a run early and says so; the stepper table finds its entries by name. */
static void test_t_max_and_table(void)
{
    rc_soft_params prm = params(INFINITY, 1.0, 1e6, RTOL);
    prm.t_max = 0.5; /* first touch comes at t ~ 1 */
    rc_particle p[2];
    rc_vec3 x[2];
    soft_case(0.0, rc_v3(0.5, 0, 0), rc_v3(-0.5, 0, 0), 0.0, p, x);
    rc_soft_result res;
    for (int s = 0; rc_soft_steppers[s]; s++) {
        rc_particle q[2] = {p[0], p[1]};
        rc_vec3 xx[2] = {x[0], x[1]};
        ENSURE(rc_soft_collide(rc_soft_steppers[s], &prm, 2, q, xx, soft_r, NULL, &res) ==
               RC_OK);
        ENSURE(res.finished == 0 && res.n_contacts == 0);
        /* free flight: momenta kept, positions moved by v t (exact for straight lines) */
        ENSURE(rc_v3_norm(rc_v3_sub(q[0].p, p[0].p)) <= 1e-15);
        ENSURE_CLOSE(xx[0].x, x[0].x + 0.5 * 0.5, 1e-12, 1.0);
        ENSURE(rc_soft_stepper_find(rc_soft_steppers[s]->name) == rc_soft_steppers[s]);
    }
    ENSURE(rc_soft_stepper_find("cvode-bdf") == &rc_soft_cvode_bdf);
    ENSURE(rc_soft_stepper_find("nope") == NULL);
    ENSURE(rc_soft_stepper_find(NULL) == NULL);
}

int main(void)
{
    gsl_set_error_handler_off();
    RUN_TEST(test_two_balls_conserve);
    RUN_TEST(test_energy_error_follows_tolerance);
    RUN_TEST(test_three_balls_conserve);
    RUN_TEST(test_sixteen_balls_conserve);
    RUN_TEST(test_steppers_agree);
    RUN_TEST(test_damping_ratio);
    RUN_TEST(test_rejects_bad_input);
    RUN_TEST(test_t_max_and_table);
    RC_TEST_MAIN_END();
}
