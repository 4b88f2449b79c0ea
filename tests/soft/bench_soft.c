/* bench_soft.c — two-ball soft collisions per second with CVODE, at the smallest stiffness
 * (decades of 10) where every sampled collision is within 1e-6 of the hard zmf law; the
 * GSL rk8pd stepper and the hard law itself are timed on the same collisions in the same
 * process as baselines. Spheres at c = inf and c = 1, then contracted shapes frozen per
 * contact at c = 1 (hard reference: the zmf law with the soft run's first-touch normal,
 * which is rc_toi's zmf-frame normal, test_soft_contracted), and the live contracted
 * shapes at eps = 1, kappa = 1e8 for their cost. Prints figures; asserts nothing about
 * time. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "rc_test.h"
#include "soft_cases.h"

enum { NSAMPLE = 40, NTIME = 1000 };
#define TARGET 1e-6 /* outcome distance from the hard law the stiffness must reach */
#define RTOL 1e-11  /* the solver's own error (~1e-8 here) stays well under TARGET */

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Random oblique collision: velocities up to 0.6 (of c, or of 1 classically) in 3-D,
 * impact parameter uniform in [0, 0.8) of the sum of the radii. */
static void draw(rc_test_rng *g, double c, rc_particle p[2], rc_vec3 x[2])
{
    const double unit = isinf(c) ? 1.0 : c, k = isinf(c) ? 0.0 : 1.0 / (c * c);
    for (;;) {
        rc_vec3 v[2];
        for (int i = 0; i < 2; i++)
            do
                v[i] = rc_v3(rc_test_range(g, -0.6, 0.6), rc_test_range(g, -0.6, 0.6),
                             rc_test_range(g, -0.6, 0.6));
            while (rc_v3_norm(v[i]) >= 0.6);
        if (rc_v3_norm(rc_v3_sub(v[1], v[0])) < 0.2)
            continue; /* keep the flight to first touch short */
        const double b = rc_test_range(g, 0.0, 0.8) * (soft_r[0] + soft_r[1]);
        if (soft_case(k, rc_v3_scale(unit, v[0]), rc_v3_scale(unit, v[1]), b, p, x) == 0)
            return;
    }
}

static const char *shape_name(rc_soft_shape sh)
{
    return sh == RC_SOFT_SPHERE ? "sphere" : sh == RC_SOFT_CONTRACTED ? "live" : "frozen";
}

/* Collisions per second of each stepper on NTIME random collisions at prm. */
static void time_steppers(double c, const rc_soft_params *prm, double rate[2])
{
    const rc_soft_stepper *st[2] = {&rc_soft_cvode_bdf, &rc_soft_gsl_rk8pd};
    for (int s = 0; s < 2; s++) {
        rc_test_rng g = {7};
        long steps = 0, rhs = 0, pw = 0;
        int fails = 0;
        double t0 = now();
        for (int i = 0; i < NTIME; i++) {
            rc_particle p[2];
            rc_vec3 x[2];
            draw(&g, c, p, x);
            rc_soft_result res;
            fails += rc_soft_collide(st[s], prm, 2, p, x, soft_r, NULL, &res) != RC_OK;
            steps += res.n_steps;
            rhs += res.n_rhs;
            pw += res.n_pw;
        }
        const double dt = now() - t0;
        rate[s] = NTIME / dt;
        printf("  c=%-4g %-6s eps=%.1f kappa=%.0e %-10s %9.0f collisions/s  (%.1f us each, "
               "%.0f steps, %.0f rhs, %.0f PW evaluations per collision, %d failed)\n",
               c, shape_name(prm->shape), prm->eps, prm->stiffness, st[s]->name, rate[s],
               1e6 * dt / NTIME, (double)steps / NTIME, (double)rhs / NTIME,
               (double)pw / NTIME, fails);
    }
}

static void bench(double c, rc_soft_shape shape)
{
    rc_soft_params prm = rc_soft_params_default();
    prm.c = c;
    prm.rtol = RTOL;
    prm.eps = 0.8;
    prm.shape = shape;
    /* stiffness: first decade whose worst sampled error is within TARGET */
    double kappa = 0.0, worst = 0.0, best = INFINITY, best_kappa = 0.0;
    /* contracted shapes: CVODE at RTOL stops improving beyond 1e12 (solver error ~1e-5
     * and failures at 1e13, papers/soft-sphere.md 7.6): search no further */
    const double kmax = shape == RC_SOFT_SPHERE ? 1e16 : 1e12;
    for (double kp = 1e8; kp <= kmax && kappa == 0.0; kp *= 10.0) {
        prm.stiffness = kp;
        rc_test_rng g = {42};
        worst = 0.0;
        for (int i = 0; i < NSAMPLE; i++) {
            rc_particle p[2];
            rc_vec3 x[2];
            draw(&g, c, p, x);
            double err = INFINITY;
            int st = soft_vs_hard(&rc_soft_cvode_bdf, &prm, p, x, NULL, &err, NULL);
            if (st != RC_OK) {
                printf("c=%g kappa=%g: %s\n", c, kp, rc_strerror(st));
                err = INFINITY;
            }
            worst = fmax(worst, err);
        }
        printf("  c=%-4g %-6s eps=%.1f kappa=%.0e  worst |soft - hard| over %d collisions = "
               "%.2e\n",
               c, shape_name(shape), prm.eps, kp, NSAMPLE, worst);
        if (worst <= TARGET)
            kappa = kp;
        if (worst < best) {
            best = worst;
            best_kappa = kp;
        }
    }
    if (kappa == 0.0) {
        printf("  c=%g %s: no stiffness up to %.0e reached %.0e; timing at the best one, "
               "kappa = %.0e (worst %.2e)\n",
               c, shape_name(shape), kmax, TARGET, best_kappa, best);
        if (!(best_kappa > 0.0))
            return;
        kappa = best_kappa;
    }
    prm.stiffness = kappa;
    double rate[2];
    time_steppers(c, &prm, rate);
    /* the hard law on the same collisions, with each pair's own touch normal */
    rc_test_rng g = {7};
    rc_particle pp[NTIME][2];
    rc_vec3 nn[NTIME];
    for (int i = 0; i < NTIME; i++) {
        rc_vec3 x[2];
        draw(&g, c, pp[i], x);
        nn[i] = rc_v3_sub(x[1], x[0]); /* not the touch normal: timing only */
    }
    rc_collision_params cp = rc_collision_params_default();
    cp.c = prm.c;
    cp.eps = prm.eps;
    const int reps = 200;
    double t0 = now();
    volatile double sink = 0.0;
    for (int r = 0; r < reps; r++)
        for (int i = 0; i < NTIME; i++) {
            rc_particle a = pp[i][0], b = pp[i][1];
            rc_collide(&rc_law_zmf, &cp, &a, &b, nn[i]);
            sink += a.p.x;
        }
    const double hard = reps * NTIME / (now() - t0);
    printf("  c=%-4g hard zmf law %.3g collisions/s: soft cvode-bdf is %.0fx slower, "
           "gsl-rk8pd/cvode-bdf speed ratio %.2f\n",
           c, hard, hard / rate[0], rate[1] / rate[0]);
}

int main(void)
{
    (void)rc_test_checks; /* only the generator of rc_test.h is used here */
    (void)rc_test_failures;
    gsl_set_error_handler_off();
    printf("bench_soft: rtol %.0e, target %.0e, %d collisions timed per stepper\n", RTOL,
           TARGET, NTIME);
    bench(INFINITY, RC_SOFT_SPHERE);
    bench(1.0, RC_SOFT_SPHERE);
    bench(1.0, RC_SOFT_CONTRACTED_FROZEN);
    /* live contracted shapes converge to their own limit, not the hard law (section 7.4):
     * timed at eps = 1 (eps < 1 sticks and costs ~kappa steps) and kappa = 1e8 */
    rc_soft_params live = rc_soft_params_default();
    live.c = 1.0;
    live.rtol = RTOL;
    live.eps = 1.0;
    live.stiffness = 1e8;
    live.shape = RC_SOFT_CONTRACTED;
    double rate[2];
    time_steppers(1.0, &live, rate);
    return 0;
}
