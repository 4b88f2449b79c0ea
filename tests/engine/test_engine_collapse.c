/* test_engine_collapse.c — inelastic collapse: 500 discs with eps = 0.5 cool into
 * clusters where a naive engine makes infinitely many collisions in finite time; the
 * TC model (elastic within t_c of proper time after a collision) lets the run finish. */
#include <math.h>

#include "engine_util.h"

/* 500 discs, packing 0.5, eps 0.5 (balls and walls), to t = 2000 (~3e4 initial free
 * times) with at most 1.5e6 events. */
static void run(double t_c, rc_sim_diag *d0, rc_sim_diag *d1)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.eps_ball = 0.5;
    d.eps_wall = 0.5;
    d.t_c = t_c;
    rc_sim *s = util_gas(d, 500, 0.5, 1.0, 17);
    if (!s)
        return;
    rc_sim_diagnostics(s, d0);
    ENSURE(rc_sim_advance(s, 2000.0, 1500000) == RC_OK);
    rc_sim_diagnostics(s, d1);
    rc_sim_free(&s);
}

/* Without protection the same run stalls: the cap is reached long before t = 2000 (the
 * collision rate diverges in the collapsing clusters). Shows the test can fail. */
static void test_naive_stalls(void)
{
    rc_sim_diag d0, d1;
    run(0.0, &d0, &d1);
    ENSURE_MSG(d1.time < 2000.0, "naive run finished: t = %g", d1.time);
    printf("  naive: stopped at t = %.4g after %llu collisions\n", d1.time,
           (unsigned long long)d1.collisions);
}

static void test_tc_finishes(void)
{
    rc_sim_diag d0, d1;
    run(1e-3, &d0, &d1); /* t_c ~ 1% of the initial free time */
    const double T = 2000.0;
    ENSURE_MSG(d1.time == T, "stopped at t = %g after the event cap", d1.time);
    ENSURE(d1.events[RC_SIM_EV_TC] > 0);              /* the protection was needed */
    ENSURE(d1.kinetic < 0.2 * d0.kinetic);            /* and the gas did cool */
    ENSURE_REL(d1.energy, d0.energy, 1e-10);          /* with the energy accounted */
    ENSURE(d1.max_overlap <= 1e-9);
    printf("  %llu collisions, %llu made elastic by TC, kinetic %.3g of the initial\n",
           (unsigned long long)d1.collisions, (unsigned long long)d1.events[RC_SIM_EV_TC],
           d1.kinetic / d0.kinetic);
}

int main(void)
{
    RUN_TEST(test_naive_stalls);
    RUN_TEST(test_tc_finishes);
    RC_TEST_MAIN_END();
}
