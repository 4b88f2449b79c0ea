/* test_engine_set_c.c — rc_sim_set_c lowers or raises c during a run keeping every ball's
 * position, momentum, rest mass and proper time; velocities follow p / M at the new c;
 * the run goes on conserving energy (the new value its reference) and equals, bit for bit,
 * a new engine at the new c continued from the synced state; bad c is refused with the
 * engine unchanged. */
#include <math.h>
#include <string.h>

#include "engine_util.h"

static rc_sim_def gas_def(double c, const rc_toi_frame *frame)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.c = c;
    d.frame = frame;
    return d;
}

/* the same position, momentum, rest mass, proper time and TC memory, every bit */
static void same_balls(const rc_sim *a, const rc_sim_ball *b, size_t n, const char *what)
{
    int diff = 0;
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball x;
        ENSURE(rc_sim_get_ball(a, i, &x) == RC_OK);
        diff += memcmp(&x.x, &b[i].x, sizeof x.x) || memcmp(&x.p, &b[i].p, sizeof x.p) ||
                x.m != b[i].m || x.tau != b[i].tau || x.collided != b[i].collided ||
                x.r != b[i].r;
    }
    ENSURE_MSG(diff == 0, "%s: %d balls changed", what, diff);
}

static void test_keeps_momenta(const rc_toi_frame *frame, double c0, double c1)
{
    rc_sim *s = util_gas(gas_def(c0, frame), 100, 0.2, 0.4, 7);
    if (!s)
        return;
    util_run_collisions(s, 300);
    ENSURE(rc_sim_sync(s) == RC_OK);
    const size_t n = rc_sim_count(s);
    rc_sim_ball *b = malloc(n * sizeof *b);
    for (size_t i = 0; i < n; i++)
        rc_sim_get_ball(s, i, &b[i]);
    rc_sim_diag d0;
    rc_sim_diagnostics(s, &d0);
    ENSURE(rc_sim_set_c(s, c1) == RC_OK);
    same_balls(s, b, n, "set_c");
    rc_sim_diag d1;
    rc_sim_diagnostics(s, &d1);
    ENSURE_MSG(d1.collisions == d0.collisions && d1.time == d0.time,
               "counters and time continue: %llu -> %llu", (unsigned long long)d0.collisions,
               (unsigned long long)d1.collisions);
    /* kinetic energy at the new c, from the kept momenta: sum (M - m) c^2, exactly the
     * engine's own sum up to the order of additions (relative 1e-13 for 100 terms) */
    const double k1 = isinf(c1) ? 0.0 : 1.0 / (c1 * c1);
    double kin = 0.0;
    for (size_t i = 0; i < n; i++)
        kin += rc_kinetic_energy(b[i].m, b[i].p, k1);
    ENSURE_REL(d1.kinetic, kin, 1e-13);
    /* conservation from here on: 2000 collisions of round-off, relative 1e-12 */
    util_run_collisions(s, 2000);
    rc_sim_diag d2;
    rc_sim_diagnostics(s, &d2);
    ENSURE_REL(d2.energy, d1.energy, 1e-12);
    ENSURE_CLOSE(d2.momentum.x + d2.wall_impulse.x, d1.momentum.x + d1.wall_impulse.x, 1e-12,
                 d1.momentum_scale);
    /* every ball below the new c */
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball x;
        rc_sim_get_ball(s, i, &x);
        const double M = rc_mass_rel(x.m, x.p, k1);
        ENSURE(rc_v3_norm(x.p) / M < c1);
    }
    free(b);
    rc_sim_free(&s);
}

/* set_c continues exactly as a new engine at the new c, restarted from the synced state */
static void test_equals_restart(const rc_toi_frame *frame, double c0, double c1)
{
    const size_t n = 64;
    rc_sim_def d0 = gas_def(c0, frame), d1 = gas_def(c1, frame);
    rc_sim_gas_def g = {2, n, 0.5, 0.2, 0.4, c0, 1.0, 3};
    rc_sim_ball *b = malloc(n * sizeof *b);
    ENSURE(rc_sim_gas_init(&g, &d0.box, b) == RC_OK);
    d1.box = d0.box;
    d1.restart = 1;
    rc_sim *s = NULL, *r = NULL;
    ENSURE(rc_sim_create(&d0, &s) == RC_OK && rc_sim_set_balls(s, n, b, NULL) == RC_OK);
    util_run_collisions(s, 200);
    ENSURE(rc_sim_sync(s) == RC_OK);
    for (size_t i = 0; i < n; i++)
        rc_sim_get_ball(s, i, &b[i]);
    const double t = rc_sim_time(s);
    ENSURE(rc_sim_create(&d1, &r) == RC_OK && rc_sim_set_time(r, t) == RC_OK);
    int st = rc_sim_set_balls(r, n, b, NULL);
    ENSURE_MSG(st == RC_OK, "restart at c = %g: %s", c1, rc_strerror(st));
    ENSURE(rc_sim_set_c(s, c1) == RC_OK);
    ENSURE(rc_sim_advance(s, t + 20.0, 0) == RC_OK);
    ENSURE(rc_sim_advance(r, t + 20.0, 0) == RC_OK);
    ENSURE_MSG(rc_sim_hash(s) == rc_sim_hash(r), "c %g -> %g: set_c and restart differ", c0,
               c1);
    free(b);
    rc_sim_free(&r);
    rc_sim_free(&s);
}

static void test_refused(void)
{
    rc_sim *s = util_gas(gas_def(1.0, &rc_toi_frame_table), 50, 0.2, 0.4, 1);
    if (!s)
        return;
    rc_sim_advance(s, 3.0, 0);
    const uint64_t h = rc_sim_hash(s);
    ENSURE(rc_sim_set_c(NULL, 1.0) == RC_EINVAL);
    ENSURE(rc_sim_set_c(s, 0.0) == RC_ESPEEDOFLIGHT);
    ENSURE(rc_sim_set_c(s, -1.0) == RC_ESPEEDOFLIGHT);
    ENSURE(rc_sim_set_c(s, NAN) == RC_ESPEEDOFLIGHT);
    ENSURE(rc_sim_set_c(s, 1e300) == RC_ESPEEDOFLIGHT); /* 1/c^2 underflows: use inf */
    ENSURE_MSG(rc_sim_hash(s) == h, "refused c changed the state");
    ENSURE(rc_sim_advance(s, 6.0, 0) == RC_OK); /* and the engine still runs at c = 1 */
    rc_sim_free(&s);
}

static void run_all(void)
{
    test_keeps_momenta(&rc_toi_frame_table, 1.0, 0.6);   /* lower c: shapes shrink */
    test_keeps_momenta(&rc_toi_frame_table, 0.6, 3.0);   /* raise c: shapes grow */
    test_keeps_momenta(&rc_toi_frame_table, 1.0, INFINITY);
    test_keeps_momenta(&rc_toi_frame_zmf, 1.0, 0.5);
    test_keeps_momenta(NULL, INFINITY, 0.5);             /* spheres */
    test_equals_restart(&rc_toi_frame_table, 1.0, 0.6);
    test_equals_restart(NULL, 1.0, 2.0);
}

int main(void)
{
    RUN_TEST(run_all);
    RUN_TEST(test_refused);
    RC_TEST_MAIN_END();
}
