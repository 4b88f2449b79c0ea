/* test_engine_conservation.c — >= 1e6 collisions over four runs (classical and
 * relativistic, elastic and inelastic, 2-D and 3-D): energy (kinetic + heat; and sum M
 * when c is finite) and momentum (with the walls' impulse) to 1e-10 relative, no overlap
 * beyond the documented tolerance, proper time consistent with the clocks. */
#include <math.h>

#include "engine_util.h"

static uint64_t total_collisions;

static void run(int dim, double c, double eps, double eps_w, double packing, size_t n,
                uint64_t target, uint64_t seed)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    d.c = c;
    d.eps_ball = eps;
    d.eps_wall = eps_w;
    /* TC window: a small fraction of the initial free time ~ 0.1 (radius 0.5, speed 1) */
    d.t_c = eps < 1.0 ? 1e-4 : 0.0;
    rc_sim *s = util_gas(d, n, packing, isinf(c) ? 1.0 : 0.5 * c, seed);
    if (!s)
        return;
    rc_sim_diag d0, d1;
    rc_sim_diagnostics(s, &d0);
    util_run_collisions(s, target);
    rc_sim_diagnostics(s, &d1);
    total_collisions += d1.collisions;
    /* 1e-10 relative: round-off of ~1e6 pair updates each exact to a few ulps, summed
     * with compensation; a lost impulse or a wrong law would be O(1e-3) */
    ENSURE_REL(d1.energy, d0.energy, 1e-10);
    if (isfinite(c))
        ENSURE_REL(d1.mass_rel, d0.mass_rel, 1e-10);
    ENSURE_CLOSE(d1.momentum.x + d1.wall_impulse.x, d0.momentum.x, 1e-10, d0.momentum_scale);
    ENSURE_CLOSE(d1.momentum.y + d1.wall_impulse.y, d0.momentum.y, 1e-10, d0.momentum_scale);
    ENSURE_CLOSE(d1.momentum.z + d1.wall_impulse.z, d0.momentum.z, 1e-10, d0.momentum_scale);
    /* the walls really took momentum (the test can see a missing wall impulse) */
    ENSURE(rc_v3_norm(d1.wall_impulse) > 1e-6 * d0.momentum_scale);
    /* inelastic runs dissipate; elastic ones do not; rest mass rises only with c finite */
    if (eps < 1.0)
        ENSURE(d1.heat > 1e-3 * d0.kinetic);
    else
        ENSURE(fabs(d1.heat) <= 1e-10 * d0.kinetic);
    if (isfinite(c) && eps < 1.0)
        ENSURE(d1.rest_mass > d0.rest_mass);
    else if (eps == 1.0 && eps_w == 1.0)
        ENSURE_REL(d1.rest_mass, d0.rest_mass, 1e-12);
    /* no overlap beyond overlap_tol (1e-9 of ri + rj) anywhere, none met on the way */
    ENSURE_MSG(d1.max_overlap <= 1e-9, "max overlap %g", d1.max_overlap);
    ENSURE(d1.overlaps == 0);
    /* proper time: classical = coordinate time; relativistic strictly less for movers */
    size_t slow = 0;
    for (size_t i = 0; i < rc_sim_count(s); i++) {
        rc_sim_ball b;
        rc_sim_get_ball(s, i, &b);
        if (isinf(c))
            ENSURE_CLOSE(b.tau, d1.time, 1e-12, d1.time);
        else
            slow += b.tau < d1.time;
    }
    if (isfinite(c))
        ENSURE(slow == rc_sim_count(s));
    printf("  dim %d c %g eps %g/%g: %llu collisions, %llu groups (max %zu, %llu resolved "
           "one contact at a time), TC %llu, dE/E %.2g\n", dim, c, eps, eps_w,
           (unsigned long long)d1.collisions, (unsigned long long)d1.events[RC_SIM_EV_MULTI],
           d1.max_group, (unsigned long long)d1.group_fallbacks,
           (unsigned long long)d1.events[RC_SIM_EV_TC], (d1.energy - d0.energy) / d0.energy);
    rc_sim_free(&s);
}

static void test_classical_elastic_3d(void) { run(3, INFINITY, 1.0, 1.0, 0.3, 1000, 300000, 1); }
static void test_classical_inelastic_2d(void) { run(2, INFINITY, 0.8, 0.9, 0.5, 1000, 250000, 2); }
static void test_relativistic_elastic_3d(void) { run(3, 2.0, 1.0, 1.0, 0.3, 1000, 250000, 3); }
static void test_relativistic_inelastic_2d(void) { run(2, 2.0, 0.7, 0.8, 0.5, 1000, 250000, 4); }

int main(void)
{
    RUN_TEST(test_classical_elastic_3d);
    RUN_TEST(test_classical_inelastic_2d);
    RUN_TEST(test_relativistic_elastic_3d);
    RUN_TEST(test_relativistic_inelastic_2d);
    ENSURE(total_collisions >= 1000000);
    printf("total collisions %llu\n", (unsigned long long)total_collisions);
    RC_TEST_MAIN_END();
}
