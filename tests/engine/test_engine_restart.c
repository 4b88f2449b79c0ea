/* test_engine_restart.c — restart identity: a run synchronised at T1 (rc_sim_sync), whose
 * state is read with rc_sim_get_ball, printed with %.17g, parsed back and loaded into a
 * fresh engine (rc_sim_set_time + rc_sim_set_balls), continues bit for bit as the
 * original does: classical, relativistic with contracted table-frame shapes, inelastic
 * with the TC model active (its per-ball memory travels in the state). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine_util.h"

#define N 300

/* the state as a restart file carries it: every double through "%.17g" and back */
static double roundtrip(double x)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%.17g", x);
    return strtod(buf, NULL);
}

static void check(double c, const char *frame, double eps, double t_c)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.c = c;
    d.eps_ball = eps;
    d.eps_wall = 1.0;
    d.t_c = t_c;
    d.frame = rc_toi_frame_find(frame);
    rc_sim_gas_def g = {2, N, 0.5, 0.4, isinf(c) ? 1.0 : 0.5 * c, c, 1.0, 5};
    static rc_sim_ball b[N];
    memset(b, 0, sizeof b); /* no state may leak from the previous case */
    ENSURE(rc_sim_gas_init(&g, &d.box, b) == RC_OK);
    rc_sim *s1 = NULL, *s2 = NULL;
    ENSURE(rc_sim_create(&d, &s1) == RC_OK && rc_sim_set_balls(s1, N, b, NULL) == RC_OK);
    const double T1 = 20.0, T2 = 45.0;
    ENSURE(rc_sim_advance(s1, T1, 0) == RC_OK);
    ENSURE(rc_sim_sync(s1) == RC_OK);
    for (size_t i = 0; i < N; i++) {
        rc_sim_ball *o = &b[i];
        ENSURE(rc_sim_get_ball(s1, i, o) == RC_OK);
        o->x = rc_v3(roundtrip(o->x.x), roundtrip(o->x.y), roundtrip(o->x.z));
        o->p = rc_v3(roundtrip(o->p.x), roundtrip(o->p.y), roundtrip(o->p.z));
        o->m = roundtrip(o->m);
        o->tau = roundtrip(o->tau);
        o->tau_last = roundtrip(o->tau_last);
    }
    size_t bad = 0;
    d.restart = 1; /* the engine's own state: overlaps it produced are part of it */
    ENSURE(rc_sim_create(&d, &s2) == RC_OK);
    ENSURE(rc_sim_set_time(s2, roundtrip(rc_sim_time(s1))) == RC_OK);
    int st = rc_sim_set_balls(s2, N, b, &bad);
    ENSURE_MSG(st == RC_OK, "c %g frame %s: reloading the state: %s (ball %zu)", c, frame,
               rc_strerror(st), bad);
    ENSURE(rc_sim_hash(s1) == rc_sim_hash(s2));
    ENSURE(rc_sim_advance(s1, T2, 0) == RC_OK);
    ENSURE(rc_sim_advance(s2, T2, 0) == RC_OK);
    rc_sim_diag d1, d2;
    rc_sim_diagnostics(s1, &d1);
    rc_sim_diagnostics(s2, &d2);
    ENSURE_MSG(rc_sim_hash(s1) == rc_sim_hash(s2), "c %g frame %s eps %g: restarted run differs",
               c, frame, eps);
    ENSURE_MSG(d1.collisions > 1000 && d1.events[RC_SIM_EV_TC] >= (t_c > 0 ? 1u : 0u),
               "too few collisions (%llu) or TC contacts (%llu) to mean anything",
               (unsigned long long)d1.collisions, (unsigned long long)d1.events[RC_SIM_EV_TC]);
    printf("  c %-5g %-6s eps %-4g t_c %-5g: %llu collisions in all (%llu TC), restart %s\n", c,
           frame, eps, t_c, (unsigned long long)d1.collisions,
           (unsigned long long)d1.events[RC_SIM_EV_TC],
           rc_sim_hash(s1) == rc_sim_hash(s2) ? "identical" : "DIFFERS");
    rc_sim_free(&s1);
    rc_sim_free(&s2);
}

static void test_restart_classical(void) { check(INFINITY, "sphere", 1.0, 0.0); }
static void test_restart_contracted(void) { check(2.0, "table", 1.0, 0.0); }
static void test_restart_tc(void) { check(2.0, "table", 0.3, 0.05); }
static void test_restart_zmf(void) { check(2.0, "zmf", 0.9, 0.0); }

int main(void)
{
    RUN_TEST(test_restart_classical);
    RUN_TEST(test_restart_contracted);
    RUN_TEST(test_restart_tc);
    RUN_TEST(test_restart_zmf);
    RC_TEST_MAIN_END();
}
