/* test_engine_gas.c — rc_sim_gas_init: exact packing fraction, no overlaps, balls inside
 * the box, rms speed and zero total momentum, any c, many balls on the lattice and a few
 * at random; impossible requests rejected. */
#include <math.h>
#include <stdlib.h>

#include "rc_test.h"
#include "relcol/relcol.h"

static void check(int dim, size_t n, double packing, double v_rms, double c)
{
    rc_sim_gas_def g = {dim, n, 0.5, packing, v_rms, c, 1.0, 31};
    rc_sim_ball *b = malloc(n * sizeof *b);
    rc_vec3 box;
    ENSURE(rc_sim_gas_init(&g, &box, b) == RC_OK);
    double vol = dim == 3 ? box.x * box.y * box.z : box.x * box.y;
    double vb = dim == 3 ? 4.0 / 3.0 * M_PI * 0.125 : M_PI * 0.25;
    ENSURE_REL((double)n * vb / vol, packing, 1e-12); /* exact by construction */
    double k = isinf(c) ? 0.0 : 1.0 / (c * c), v2 = 0.0;
    rc_vec3 P = rc_v3(0, 0, 0);
    double pscale = 0.0;
    for (size_t i = 0; i < n; i++) {
        rc_vec3 v = rc_velocity(b[i].m, b[i].p, k);
        v2 += rc_v3_norm2(v);
        P = rc_v3_add(P, b[i].p);
        pscale += rc_v3_norm(b[i].p);
        if (dim == 2)
            ENSURE(b[i].x.z == 0.0 && b[i].p.z == 0.0);
    }
    ENSURE_REL(sqrt(v2 / (double)n), v_rms, 1e-12);   /* bisection to 1e-15 of the scale */
    ENSURE(rc_v3_norm(P) <= 1e-12 * pscale);
    /* the engine accepts it: inside the box, no overlap */
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    d.box = box;
    d.c = c;
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    ENSURE(rc_sim_set_balls(s, n, b, NULL) == RC_OK);
    rc_sim_free(&s);
    free(b);
}

static void test_packings(void)
{
    check(3, 1000, 0.45, 1.0, INFINITY);
    check(3, 999, 0.3, 0.5, 1.0); /* rms 0.5 c */
    check(2, 1000, 0.7, 1.0, INFINITY);
    check(2, 500, 0.2, 1.8, 2.0);
    /* a few balls, which the lattice of side^dim >= n sites has no room for at these
     * packings (two balls in a cube of 1.74 diameters): placed at random instead */
    check(3, 2, 0.2, 0.5, 1.0);
    check(3, 3, 0.2, 0.5, 1.0);
    check(3, 10, 0.2, 0.5, 1.0);
    check(3, 10, 0.25, 1.0, INFINITY);
    check(2, 2, 0.25, 0.5, 1.0);
    check(2, 3, 0.4, 1.0, INFINITY);
}

static void test_rejects(void)
{
    rc_sim_ball b[10];
    rc_vec3 box;
    rc_sim_gas_def g = {3, 10, 0.5, 0.6, 1.0, INFINITY, 1.0, 1}; /* above the lattice limit */
    ENSURE(rc_sim_gas_init(&g, &box, b) == RC_EOVERLAP);
    g.packing = 0.3;
    g.c = 1.0; /* rms speed 1 = c */
    ENSURE(rc_sim_gas_init(&g, &box, b) == RC_ESPEED);
    g.c = INFINITY;
    g.dim = 4;
    ENSURE(rc_sim_gas_init(&g, &box, b) == RC_EDIM);
    g.dim = 3;
    g.radius = NAN;
    ENSURE(rc_sim_gas_init(&g, &box, b) == RC_ENONFINITE);
    /* one ball: zero total momentum leaves it at rest, so no v_rms > 0 (it returned NaN
     * momenta, found by fuzzing the scenario reader); at rest it is a gas */
    g.radius = 0.5;
    g.n = 1;
    ENSURE(rc_sim_gas_init(&g, &box, b) == RC_EINVAL);
    g.v_rms = 0.0;
    ENSURE(rc_sim_gas_init(&g, &box, b) == RC_OK && b[0].p.x == 0.0 && b[0].p.y == 0.0);
    /* momenta whose squares would overflow: refused, not inf or NaN (8 balls: the
     * lattice start of 10 at packing 0.3 would need a denser lattice) */
    g.n = 8;
    g.v_rms = 1e200;
    g.density = 1e100; /* m = 1.25e99: p ~ 1e299 */
    ENSURE(rc_sim_gas_init(&g, &box, b) == RC_ENONFINITE);
    g.v_rms = 1e30; /* p ~ 1e129: fine */
    ENSURE(rc_sim_gas_init(&g, &box, b) == RC_OK);
    for (int i = 0; i < 8; i++)
        ENSURE(rc_v3_isfinite(b[i].p) && rc_v3_norm(b[i].p) > 1e120);
}

/* set_balls rejects bad input and names the ball */
static void test_set_balls_rejects(void)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.box = rc_v3(10, 10, 0);
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    rc_sim_ball b[3] = {{rc_v3(2, 2, 0), rc_v3(1, 0, 0), 1, 0, 0, 0, 0, {0, 0, 0}},
                        {rc_v3(5, 5, 0), rc_v3(0, 0, 0), 1, 0, 0, 0, 0, {0, 0, 0}},
                        {rc_v3(6.5, 5, 0), rc_v3(0, 0, 0), 1, 0, 0, 0, 0, {0, 0, 0}}};
    size_t bad = 99;
    ENSURE(rc_sim_set_balls(s, 3, b, &bad) == RC_EOVERLAP && bad == 2);
    b[2].x = rc_v3(9.5, 5, 0); /* sticks out of the box */
    ENSURE(rc_sim_set_balls(s, 3, b, &bad) == RC_EINVAL && bad == 2);
    b[2].x = rc_v3(8, 5, 0);
    b[1].p.x = NAN;
    ENSURE(rc_sim_set_balls(s, 3, b, &bad) == RC_ENONFINITE && bad == 1);
    b[1].p.x = 0;
    b[0].x.z = 1.0; /* 2-D table */
    ENSURE(rc_sim_set_balls(s, 3, b, &bad) == RC_EDIM && bad == 0);
    b[0].x.z = 0.0;
    ENSURE(rc_sim_set_balls(s, 3, b, &bad) == RC_OK);
    /* default mass density * r^3 */
    rc_sim_ball o;
    ENSURE(rc_sim_get_ball(s, 0, &o) == RC_OK && o.m == 1.0);
    ENSURE(rc_sim_advance(s, -1.0, 0) == RC_EINVAL);
    ENSURE(rc_sim_set_time(s, 5.0) == RC_EINVAL); /* balls are set */
    rc_sim_free(&s);
    /* a run continued from t = 5: balls placed at the engine's time, events after it */
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    ENSURE(rc_sim_set_time(s, INFINITY) == RC_ENONFINITE);
    ENSURE(rc_sim_set_time(s, 5.0) == RC_OK);
    ENSURE(rc_sim_set_balls(s, 3, b, NULL) == RC_OK);
    ENSURE(rc_sim_time(s) == 5.0);
    ENSURE(rc_sim_advance(s, 4.0, 0) == RC_EINVAL);
    ENSURE(rc_sim_advance(s, 6.0, 0) == RC_OK);
    rc_sim_get_ball(s, 0, &o);
    ENSURE(o.x.x == 3.0 && o.tau == 1.0); /* moved 1 at speed 1; proper time from 0 */
    ENSURE(rc_sim_advance(s, NAN, 0) == RC_EINVAL);
    rc_sim_free(&s);
    d.eps_ball = 1.5;
    ENSURE(rc_sim_create(&d, &s) == RC_ERESTITUTION && s == NULL);
    d.eps_ball = 1.0;
    d.c = -1.0;
    ENSURE(rc_sim_create(&d, &s) == RC_ESPEEDOFLIGHT);
    d.c = INFINITY;
    d.dim = 1;
    ENSURE(rc_sim_create(&d, &s) == RC_EDIM);
}

int main(void)
{
    RUN_TEST(test_packings);
    RUN_TEST(test_rejects);
    RUN_TEST(test_set_balls_rejects);
    RC_TEST_MAIN_END();
}
