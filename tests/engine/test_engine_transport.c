/* test_engine_transport.c — the transport frame (points, closest approach in the pair's
 * CM frame with d_T < r0 + r1) in the engine: a pair collides at its closest approach,
 * not at touching, with the hard-sphere normal for its impact parameter; a gas conserves
 * energy and momentum to round-off at c = 2 and c = inf. */
#include <math.h>
#include <string.h>

#include "engine_util.h"

/* Two balls (r = 1, m = 1) on a 2-D table at c = 1, A at (10, 10) moving +0.6, B at
 * (20, 11) moving -0.6: d_T = 1, closest approach at t = 10/1.2 (spheres would touch at
 * 10/1.2 - sqrt(3)/1.2). Elastic, equal masses, the CM frame is the table: the zmf law
 * exchanges the normal momenta along n = (sqrt3/2, 1/2). Tolerance: a few dozen
 * roundings of numbers of size 1. */
static void test_pair(void)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.c = 1.0;
    d.box = rc_v3(40, 40, 0);
    d.frame = &rc_toi_frame_transport;
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    if (!s)
        return;
    rc_sim_ball b[2];
    memset(b, 0, sizeof b);
    b[0].x = rc_v3(10, 10, 0);
    b[1].x = rc_v3(20, 11, 0);
    b[0].r = b[1].r = b[0].m = b[1].m = 1.0;
    ENSURE(rc_momentum_from_velocity(1.0, rc_v3(0.6, 0, 0), 1.0, &b[0].p) == RC_OK);
    ENSURE(rc_momentum_from_velocity(1.0, rc_v3(-0.6, 0, 0), 1.0, &b[1].p) == RC_OK);
    ENSURE(rc_sim_set_balls(s, 2, b, NULL) == RC_OK);
    ENSURE(rc_sim_advance(s, 9.0, 1000) == RC_OK);
    rc_sim_diag dg;
    rc_sim_diagnostics(s, &dg);
    ENSURE(dg.collisions == 1);
    rc_sim_ball a0, a1;
    rc_sim_get_ball(s, 0, &a0);
    rc_sim_get_ball(s, 1, &a1);
    /* each ball is back at its pre-collision x after 9 - 25/3 of recoil, from x = 15 at
     * the collision: the outgoing momentum of A is p - 2 (p.n) n */
    const double p = b[0].p.x, nx = sqrt(3.0) / 2, ny = 0.5;
    const rc_vec3 pa = rc_v3(p - 2 * p * nx * nx, -2 * p * nx * ny, 0);
    ENSURE_CLOSE(a0.p.x, pa.x, 1e-14, p);
    ENSURE_CLOSE(a0.p.y, pa.y, 1e-14, p);
    ENSURE_CLOSE(a1.p.x, -pa.x, 1e-14, p);
    ENSURE_CLOSE(a1.p.y, -pa.y, 1e-14, p);
    const double M = sqrt(1 + p * p), tc = 10.0 / 1.2;
    ENSURE_CLOSE(a0.x.x, 15.0 + pa.x / M * (9.0 - tc), 1e-13, 15.0);
    ENSURE_CLOSE(a0.x.y, 10.0 + pa.y / M * (9.0 - tc), 1e-13, 15.0);
    rc_sim_free(&s);
}

static void run_gas(double c, double eps)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 3;
    d.c = c;
    d.eps_ball = eps;
    d.t_c = eps < 1.0 ? 1e-4 : 0.0;
    d.frame = &rc_toi_frame_transport;
    rc_sim *s = util_gas(d, 400, 0.3, isinf(c) ? 1.0 : 0.5 * c, 7);
    if (!s)
        return;
    rc_sim_diag d0, d1;
    rc_sim_diagnostics(s, &d0);
    util_run_collisions(s, 20000);
    rc_sim_diagnostics(s, &d1);
    /* the budget of the other frames' runs (test_engine_contracted): the frame changes
     * when and along which normal, never the four-momentum bookkeeping */
    ENSURE(d1.collisions >= d0.collisions + 20000);
    ENSURE_REL(d1.mass_rel, d0.mass_rel, 1e-10);
    ENSURE_REL(d1.energy, d0.energy, 1e-10);
    ENSURE_CLOSE(d1.momentum.x + d1.wall_impulse.x, d0.momentum.x, 1e-10, d0.momentum_scale);
    ENSURE_CLOSE(d1.momentum.y + d1.wall_impulse.y, d0.momentum.y, 1e-10, d0.momentum_scale);
    ENSURE_CLOSE(d1.momentum.z + d1.wall_impulse.z, d0.momentum.z, 1e-10, d0.momentum_scale);
    if (eps == 1.0 && d1.events[RC_SIM_EV_MULTI] == 0)
        ENSURE_REL(d1.rest_mass, d0.rest_mass, 1e-12);
    /* points never overlap: the overlap policy is never used */
    ENSURE(d1.overlaps == 0);
    printf("  c %g eps %g: %llu collisions, rel. energy change %.2g, %llu groups\n", c, eps,
           (unsigned long long)d1.collisions, fabs(d1.energy - d0.energy) / d0.energy,
           (unsigned long long)d1.events[RC_SIM_EV_MULTI]);
    rc_sim_free(&s);
}

static void test_gas(void)
{
    run_gas(2.0, 1.0);
    run_gas(2.0, 0.5);
    run_gas(INFINITY, 1.0);
}

int main(void)
{
    RUN_TEST(test_pair);
    RUN_TEST(test_gas);
    RC_TEST_MAIN_END();
}
