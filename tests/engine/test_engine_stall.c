/* test_engine_stall.c — a run whose time stands still stops with RC_ESTALL, in well under a
 * second, instead of resolving events at one instant for ever: a ball exactly as wide as
 * the box pushed against both walls (elastic, inelastic walls, the TC model, c = 1), and a
 * clock so large (1e20) that a ball's step between two walls rounds to nothing. The state
 * is whole afterwards (finite, readable, energy kept), advancing again stalls again, the
 * event is named; and a ball as wide as the box moving along the other axis runs. */
#include <math.h>
#include <string.h>

#include "engine_util.h"

/* the ball given by its velocity */
static rc_sim *one(rc_vec3 box, rc_vec3 x, rc_vec3 v, double c, double eps_wall, double t_c,
                   double t0)
{
    rc_vec3 p;
    ENSURE(rc_momentum_from_velocity(1.0, v, isinf(c) ? 0.0 : 1.0 / (c * c), &p) == RC_OK);
    return util_one_ball(box, x, p, c, eps_wall, t_c, t0);
}

static void expect_stall(rc_sim *s, double t_at, const char *what)
{
    if (!s)
        return;
    rc_sim_diag d0, d;
    rc_sim_diagnostics(s, &d0);
    int st = rc_sim_advance(s, t_at + 100.0, 0);
    ENSURE_MSG(st == RC_ESTALL, "%s: advance gave %s", what, rc_strerror(st));
    rc_sim_diagnostics(s, &d);
    ENSURE_MSG(d.time == t_at, "%s: stalled at t = %.17g, expected %.17g", what, d.time, t_at);
    ENSURE_MSG(d.stall_ball == 0 && (d.stall_partner == -1 || d.stall_partner == -2),
               "%s: named ball %lld and partner %lld (expected ball 0 and an x wall)", what,
               (long long)d.stall_ball, (long long)d.stall_partner);
    rc_sim_ball b;
    ENSURE(rc_sim_get_ball(s, 0, &b) == RC_OK && rc_v3_isfinite(b.x) && rc_v3_isfinite(b.p));
    ENSURE_MSG(fabs(d.energy - d0.energy) <= 1e-12 * d0.energy, "%s: energy %.17g -> %.17g",
               what, d0.energy, d.energy);
    ENSURE_MSG(rc_sim_advance(s, t_at + 100.0, 0) == RC_ESTALL, "%s: stalls again", what);
    rc_sim_free(&s);
}

static void test_pinned_ball(void)
{
    const rc_vec3 box = rc_v3(2, 10, 0), x = rc_v3(1, 5, 0), v = rc_v3(-0.5, 0, 0);
    expect_stall(one(box, x, v, INFINITY, 1.0, 0.0, 0.0), 0.0, "pinned, elastic");
    expect_stall(one(box, x, v, INFINITY, 0.5, 0.0, 0.0), 0.0, "pinned, eps_wall 0.5");
    expect_stall(one(box, x, v, INFINITY, 0.5, 0.1, 0.0), 0.0, "pinned, TC 0.1");
    expect_stall(one(box, x, v, 1.0, 1.0, 0.0, 0.0), 0.0, "pinned, c = 1");
    /* as wide as the box but moving along y: nothing pins it */
    rc_sim *s = one(box, x, rc_v3(0, 0.5, 0), INFINITY, 1.0, 0.0, 0.0);
    ENSURE(s && rc_sim_advance(s, 100.0, 0) == RC_OK);
    rc_sim_diag d;
    rc_sim_diagnostics(s, &d);
    ENSURE_MSG(d.events[RC_SIM_EV_WALL] >= 6, "along y: %llu wall hits",
               (unsigned long long)d.events[RC_SIM_EV_WALL]);
    rc_sim_free(&s);
}

/* At t = 1e20 one ulp is 16384: the ball's 8-unit flight from wall to wall rounds to
 * nothing, so it bounces at one instant for ever. */
static void test_huge_clock(void)
{
    const double t0 = 1e20;
    rc_sim *s = one(rc_v3(10, 10, 0), rc_v3(5, 5, 0), rc_v3(1, 0, 0), INFINITY, 1.0, 0.0, t0);
    expect_stall(s, t0, "t = 1e20");
}

int main(void)
{
    RUN_TEST(test_pinned_ball);
    RUN_TEST(test_huge_clock);
    RC_TEST_MAIN_END();
}
