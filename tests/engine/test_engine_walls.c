/* test_engine_walls.c — the momentum each wall takes (rc_sim_diag.wall_impulse_by_wall),
 * which a pressure is read from, and the overlap policy's count by kind of contact.
 * Exact cases: a ball bouncing between two walls (each bounce gives the wall (1 + eps) p_n,
 * classically and at c = 1), a ball running into a corner (both walls of the corner in
 * one group: each takes its own component); then a gas, where the walls of one axis must
 * add up to the engine's net wall impulse along it, and the counts by kind to the total. */
#include <math.h>
#include <string.h>

#include "engine_util.h"

static rc_sim *one_ball(double c, double eps_wall, rc_vec3 x, rc_vec3 p, rc_vec3 box)
{
    return util_one_ball(box, x, p, c, eps_wall, 0.0, 0.0);
}

/* Bounces between x = 0 and x = 10 with |p| = 1: every bounce at the far wall gives it
 * +2 along e_x, at the near wall -2 (elastic: exact in binary). With eps_wall < 1 each
 * bounce gives (1 + eps) p_n with p_n the momentum it arrives with. */
static void test_bounces(void)
{
    const double cs[2] = {INFINITY, 1.0};
    for (int k = 0; k < 2; k++) {
        rc_sim *s = one_ball(cs[k], 1.0, rc_v3(5, 5, 0), rc_v3(1, 0, 0), rc_v3(10, 10, 0));
        /* far wall at t = 4, 20, 36, 52, near at 12, 28, 44 (speed 1; 1/sqrt 2 at c = 1) */
        ENSURE(rc_sim_advance(s, isinf(cs[k]) ? 53.0 : 53.0 * sqrt(2.0), 0) == RC_OK);
        rc_sim_diag d;
        rc_sim_diagnostics(s, &d);
        ENSURE(d.events[RC_SIM_EV_WALL] == 7);
        ENSURE_MSG(d.wall_impulse_by_wall[1] == 8.0 && d.wall_impulse_by_wall[0] == -6.0,
                   "c %g: near %.17g far %.17g", cs[k], d.wall_impulse_by_wall[0],
                   d.wall_impulse_by_wall[1]);
        for (int w = 2; w < 6; w++)
            ENSURE(d.wall_impulse_by_wall[w] == 0.0);
        ENSURE(d.wall_impulse.x == 2.0 && d.wall_shared == 0);
        rc_sim_free(&s);
    }
    /* eps_wall = 0.5, classical: p 1 -> -0.5 -> 0.25 ...: far wall 1.5, near 0.75, far 0.375 */
    rc_sim *s = one_ball(INFINITY, 0.5, rc_v3(5, 5, 0), rc_v3(1, 0, 0), rc_v3(10, 10, 0));
    ENSURE(rc_sim_advance(s, 53.0, 0) == RC_OK); /* far t = 4, near 20, far 52 */
    rc_sim_diag d;
    rc_sim_diagnostics(s, &d);
    ENSURE_MSG(d.wall_impulse_by_wall[1] == 1.5 + 0.375 && d.wall_impulse_by_wall[0] == -0.75,
               "far %.17g near %.17g", d.wall_impulse_by_wall[1], d.wall_impulse_by_wall[0]);
    rc_sim_free(&s);
}

/* A ball running diagonally into the corner of a 10 x 7 table reaches both walls at once
 * (x = 9 and y = 6 at t = 4): one group, each wall takes twice its own component. */
static void test_corner(void)
{
    rc_sim *s = one_ball(INFINITY, 1.0, rc_v3(5, 4, 0), rc_v3(1, 0.5, 0), rc_v3(10, 7, 0));
    ENSURE(rc_sim_advance(s, 5.0, 0) == RC_OK);
    rc_sim_diag d;
    rc_sim_diagnostics(s, &d);
    ENSURE_MSG(d.events[RC_SIM_EV_MULTI] == 1, "corner: %llu groups",
               (unsigned long long)d.events[RC_SIM_EV_MULTI]);
    ENSURE_MSG(d.wall_impulse_by_wall[1] == 2.0 && d.wall_impulse_by_wall[3] == 1.0,
               "corner: x wall %.17g, y wall %.17g", d.wall_impulse_by_wall[1],
               d.wall_impulse_by_wall[3]);
    ENSURE(d.wall_impulse_by_wall[0] == 0.0 && d.wall_impulse_by_wall[2] == 0.0);
    rc_sim_free(&s);
}

/* A gas at c = 1 (sphere, table frames; eps < 1 with TC): per axis the walls add up to
 * the net wall impulse (to the round-off of the many ball-ball events that put their
 * momentum round-off only in the net: relative to the sum of |p| times the events);
 * near walls take momentum against e_d, far walls along it; the counts by kind add up. */
static void test_gas(void)
{
    const char *frames[2] = {"sphere", "table"};
    for (int dim = 2; dim <= 3; dim++)
        for (int f = 0; f < 2; f++) {
            rc_sim_def d = rc_sim_def_default();
            d.dim = dim;
            d.c = 1.0;
            d.eps_ball = 0.9;
            d.t_c = 0.05;
            d.frame = rc_toi_frame_find(frames[f]);
            rc_sim *s = util_gas(d, 400, 0.3, 0.6, 11);
            if (!s)
                continue;
            util_run_collisions(s, 40000);
            rc_sim_diag g;
            rc_sim_diagnostics(s, &g);
            const double scale = g.momentum_scale * (double)(g.collisions + 1) * 1e-15;
            for (int a = 0; a < dim; a++) {
                const double near = g.wall_impulse_by_wall[2 * a];
                const double far = g.wall_impulse_by_wall[2 * a + 1];
                ENSURE_CLOSE(near + far, rc_v3_get(g.wall_impulse, a), 1.0, scale);
                ENSURE_MSG(near < 0.0 && far > 0.0, "dim %d %s axis %d: near %g far %g", dim,
                           frames[f], a, near, far);
            }
            ENSURE(g.overlaps_by_kind[0] + g.overlaps_by_kind[1] + g.overlaps_by_kind[2] ==
                   g.overlaps);
            if (f == 0)
                ENSURE_MSG(g.overlaps == 0, "sphere frame: %llu overlaps",
                           (unsigned long long)g.overlaps);
            else
                ENSURE_MSG(g.overlaps_by_kind[0] > 0, "table frame: no shape-change overlap "
                                                      "counted (the policy is known to act)");
            rc_sim_free(&s);
        }
}

int main(void)
{
    RUN_TEST(test_bounces);
    RUN_TEST(test_corner);
    RUN_TEST(test_gas);
    RC_TEST_MAIN_END();
}
