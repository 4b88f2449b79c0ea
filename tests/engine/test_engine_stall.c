/* test_engine_stall.c — time that cannot advance, and the jam that used to look like it.
 * A ball exactly as wide as the box pushed against both walls is jammed along that axis:
 * its wall contacts are perfectly plastic there (the rigid-wall limit, a model choice:
 * papers/relcol.md, "Limits"), so the motion along the axis stops, its kinetic energy
 * becomes heat (rest mass at finite c) and the run goes on -- whatever the walls'
 * restitution or the TC model. A chain of touching balls across the box, and a clock so
 * large (1e20) that a ball's step between two walls rounds to nothing, still stop with
 * RC_ESTALL, in well under a second, instead of resolving events at one instant for ever:
 * the state is whole afterwards (finite, readable, energy kept), advancing again stalls
 * again, the event is named. */
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

/* Run a jammed configuration to t = 100: it must advance, keep the energy (kinetic +
 * heat, relative to round-off of the sums), stop every ball's motion along x (exactly: a
 * plastic wall impulse removes p.n from p), keep the motion along y, and count `pinned`
 * approaching wall contacts. m_after: the rest mass ball 0 must have (its energy kept,
 * its x momentum gone: m' = sqrt(m^2 + p_x^2 / c^2); 1 classically). */
static void expect_jam(rc_sim *s, const char *what, uint64_t pinned, double m_after)
{
    if (!s)
        return;
    rc_sim_diag d0, d;
    rc_sim_diagnostics(s, &d0);
    rc_sim_ball b0;
    ENSURE(rc_sim_get_ball(s, 0, &b0) == RC_OK);
    const int st = rc_sim_advance(s, 100.0, 0);
    ENSURE_MSG(st == RC_OK, "%s: advance gave %s", what, rc_strerror(st));
    rc_sim_diagnostics(s, &d);
    ENSURE_MSG(d.time == 100.0, "%s: stopped at t = %.17g", what, d.time);
    ENSURE_MSG(fabs(d.energy - d0.energy) <= 1e-14 * d0.energy, "%s: energy %.17g -> %.17g",
               what, d0.energy, d.energy);
    ENSURE_MSG(d.pinned == pinned, "%s: %llu pinned contacts, want %llu", what,
               (unsigned long long)d.pinned, (unsigned long long)pinned);
    for (size_t i = 0; i < rc_sim_count(s); i++) {
        rc_sim_ball b;
        ENSURE(rc_sim_get_ball(s, i, &b) == RC_OK);
        ENSURE_MSG(b.p.x == 0.0, "%s: ball %zu keeps p_x = %.3g", what, i, b.p.x);
    }
    rc_sim_ball b;
    ENSURE(rc_sim_get_ball(s, 0, &b) == RC_OK);
    ENSURE_MSG(fabs(b.p.y) == fabs(b0.p.y), "%s: |p_y| %.17g -> %.17g", what, b0.p.y, b.p.y);
    ENSURE_MSG(fabs(b.m - m_after) <= 4e-16 * m_after, "%s: rest mass %.17g, want %.17g", what,
               b.m, m_after);
    /* the heat is the kinetic energy of the x motion (classically 1/2 m v_x^2) */
    ENSURE_MSG(d.heat > d0.heat, "%s: no heat", what);
    rc_sim_free(&s);
}

static void test_pinned_ball(void)
{
    const rc_vec3 box = rc_v3(2, 10, 0), x = rc_v3(1, 5, 0), v = rc_v3(-0.5, 0, 0);
    expect_jam(one(box, x, v, INFINITY, 1.0, 0.0, 0.0), "pinned, elastic", 1, 1.0);
    expect_jam(one(box, x, v, INFINITY, 0.5, 0.0, 0.0), "pinned, eps_wall 0.5", 1, 1.0);
    expect_jam(one(box, x, v, INFINITY, 0.5, 0.1, 0.0), "pinned, TC 0.1", 1, 1.0);
    /* c = 1: p_x = gamma v = 0.5 / sqrt(0.75), so m' = sqrt(1 + 1/3) */
    expect_jam(one(box, x, v, 1.0, 1.0, 0.0, 0.0), "pinned, c = 1", 1, sqrt(4.0 / 3.0));
    /* moving along y as well: the y motion goes on, bouncing between the y walls */
    rc_sim *s = one(box, x, rc_v3(-0.5, 0.3, 0), INFINITY, 1.0, 0.0, 0.0);
    expect_jam(s, "pinned, diagonal", 1, 1.0);
    /* classically the heat is exactly 1/2 m v_x^2 */
    s = one(box, x, v, INFINITY, 1.0, 0.0, 0.0);
    rc_sim_diag d;
    ENSURE(s && rc_sim_advance(s, 1.0, 0) == RC_OK);
    rc_sim_diagnostics(s, &d);
    ENSURE_MSG(d.heat == 0.125 && d.wall_impulse_by_wall[0] == -0.5,
               "heat %.17g (want 0.125), x- wall took %.17g (want -0.5)", d.heat,
               d.wall_impulse_by_wall[0]);
    rc_sim_free(&s);
    /* as wide as the box but moving along y only: nothing pins it, it bounces freely */
    s = one(box, x, rc_v3(0, 0.5, 0), INFINITY, 1.0, 0.0, 0.0);
    ENSURE(s && rc_sim_advance(s, 100.0, 0) == RC_OK);
    rc_sim_diagnostics(s, &d);
    ENSURE_MSG(d.events[RC_SIM_EV_WALL] >= 6 && d.pinned == 0 && d.heat == 0.0,
               "along y: %llu wall hits, %llu pinned",
               (unsigned long long)d.events[RC_SIM_EV_WALL], (unsigned long long)d.pinned);
    rc_sim_free(&s);
    /* a ball narrower than the box by more than sim_tol bounces elastically as ever */
    s = one(rc_v3(2.001, 10, 0), x, v, INFINITY, 1.0, 0.0, 0.0);
    ENSURE(s && rc_sim_advance(s, 1.0, 0) == RC_OK);
    rc_sim_diagnostics(s, &d);
    ENSURE_MSG(d.pinned == 0 && d.heat == 0.0 && d.events[RC_SIM_EV_WALL] >= 100,
               "narrower ball: %llu pinned, heat %.3g, %llu wall hits",
               (unsigned long long)d.pinned, d.heat,
               (unsigned long long)d.events[RC_SIM_EV_WALL]);
    rc_sim_free(&s);
}

/* Two touching balls across a box four radii wide, pushed apart into both walls: whether
 * such a chain is rigid along the axis depends on its geometry, and the engine does not
 * decide it; the stall detector stops the run, naming a ball of the chain. */
static void test_chain(void)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.box = rc_v3(4, 10, 0);
    rc_sim *s = NULL;
    rc_sim_ball b[2];
    memset(b, 0, sizeof b);
    b[0].x = rc_v3(1, 5, 0);
    b[1].x = rc_v3(3, 5, 0);
    b[0].p = rc_v3(-0.5, 0, 0);
    b[1].p = rc_v3(0.3, 0, 0);
    b[0].r = b[0].m = b[1].r = b[1].m = 1.0;
    ENSURE(rc_sim_create(&d, &s) == RC_OK && rc_sim_set_balls(s, 2, b, NULL) == RC_OK);
    if (!s)
        return;
    rc_sim_diag d0, dd;
    rc_sim_diagnostics(s, &d0);
    ENSURE(rc_sim_advance(s, 100.0, 0) == RC_ESTALL);
    rc_sim_diagnostics(s, &dd);
    ENSURE_MSG(dd.time == 0.0 && (dd.stall_ball == 0 || dd.stall_ball == 1) && dd.pinned == 0,
               "chain: t = %.17g, ball %lld, %llu pinned", dd.time, (long long)dd.stall_ball,
               (unsigned long long)dd.pinned);
    ENSURE(fabs(dd.energy - d0.energy) <= 1e-14 * d0.energy);
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
    RUN_TEST(test_chain);
    RUN_TEST(test_huge_clock);
    RC_TEST_MAIN_END();
}
