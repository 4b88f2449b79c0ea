/* test_wall_engine — thermal walls in the engine (relcol/wall.h, engine/walls.c; issue 39
 * item 5): bad definitions refused; a run is a function of its seed; a checkpoint carries
 * the walls' random stream, so a run stopped and continued has the bits of one that never
 * stopped (and a checkpoint of another wall temperature is not read); the walls' books
 * close the energy and momentum balance of an elastic gas exactly (to round-off); the hard
 * rule named explicitly is the default's bits. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../engine/engine_util.h"

static rc_sim_def thermal_def(int dim, double c, double k_hot, double k_cold)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    d.c = c;
    d.wall_rule[0] = &rc_wall_thermal;
    d.wall_kT[0] = k_hot;
    d.wall_rule[1] = &rc_wall_thermal;
    d.wall_kT[1] = k_cold;
    d.wall_seed = 12345;
    return d;
}

static void test_refusals(void)
{
    rc_sim *s = NULL;
    rc_sim_def d = thermal_def(3, 1.0, 2.0, 0.5);
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    rc_sim_free(&s);
    const double bad_kT[] = {-1.0, 0.0, NAN, INFINITY};
    for (size_t j = 0; j < 4; j++) {
        d = thermal_def(3, 1.0, bad_kT[j], 0.5);
        ENSURE_MSG(rc_sim_create(&d, &s) == RC_EINVAL && !s, "kT %g accepted", bad_kT[j]);
    }
    d = thermal_def(3, 1.0, 1.0, 1.0);
    d.boundary[0] = RC_SIM_PERIODIC; /* thermal on a periodic axis */
    ENSURE(rc_sim_create(&d, &s) == RC_EINVAL && !s);
    d = thermal_def(2, 1.0, 1.0, 1.0);
    d.wall_rule[4] = &rc_wall_thermal; /* a z wall of a 2-D table */
    d.wall_kT[4] = 1.0;
    ENSURE(rc_sim_create(&d, &s) == RC_EINVAL && !s);
    d = thermal_def(3, 1.0, 1.0, 1.0);
    d.frame = &rc_toi_frame_covariant; /* per_ball: a rollback would take back a draw */
    ENSURE(rc_sim_create(&d, &s) == RC_EINVAL && !s);
    /* the hard rule needs no temperature, also on a periodic axis */
    d = rc_sim_def_default();
    d.wall_rule[0] = &rc_wall_reflecting;
    d.boundary[0] = RC_SIM_PERIODIC;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    rc_sim_free(&s);
    ENSURE(rc_wall_rule_find("thermal") == &rc_wall_thermal);
    ENSURE(rc_wall_rule_find("reflecting") == &rc_wall_reflecting);
    ENSURE(rc_wall_rule_find("warm") == NULL && rc_wall_rule_find(NULL) == NULL);
}

static rc_sim *gas(rc_sim_def d, uint64_t seed) { return util_gas(d, 200, 0.1, 0.3, seed); }

/* The engine at t after a run from the same start: its hash and books. */
static void test_seed_and_default(void)
{
    rc_sim_def d = thermal_def(3, 1.0, 2.0, 0.5);
    rc_sim *a = gas(d, 3), *b = gas(d, 3);
    d.wall_seed = 12346;
    rc_sim *e = gas(d, 3);
    if (!a || !b || !e)
        return;
    ENSURE(rc_sim_advance(a, 40.0, 0) == RC_OK && rc_sim_advance(b, 40.0, 0) == RC_OK &&
           rc_sim_advance(e, 40.0, 0) == RC_OK);
    ENSURE(rc_sim_hash(a) == rc_sim_hash(b));
    ENSURE_MSG(rc_sim_hash(a) != rc_sim_hash(e), "the wall seed changes nothing");
    rc_sim_free(&a);
    rc_sim_free(&b);
    rc_sim_free(&e);
    /* rc_wall_reflecting on every wall: the default's bits, and no wall heat */
    rc_sim_def h = rc_sim_def_default();
    h.c = 1.0;
    rc_sim *p = gas(h, 5);
    for (int w = 0; w < 6; w++)
        h.wall_rule[w] = &rc_wall_reflecting;
    h.wall_seed = 99;
    rc_sim *q = gas(h, 5);
    if (!p || !q)
        return;
    ENSURE(rc_sim_advance(p, 30.0, 0) == RC_OK && rc_sim_advance(q, 30.0, 0) == RC_OK);
    ENSURE(rc_sim_hash(p) == rc_sim_hash(q));
    rc_sim_diag dq;
    rc_sim_diagnostics(q, &dq);
    ENSURE(dq.events[RC_SIM_EV_WALL] > 100);
    for (int w = 0; w < 6; w++)
        ENSURE_MSG(fabs(dq.wall_heat_by_wall[w]) <= 1e-12 * dq.kinetic, "wall %d heat %g", w,
                   dq.wall_heat_by_wall[w]);
    rc_sim_free(&p);
    rc_sim_free(&q);
}

/* Stopped at t1 and continued from the checkpoint: the bits of the run that never stopped. */
static void test_checkpoint(int dim, double c)
{
    rc_sim_def d = thermal_def(dim, c, 1.5, 0.2);
    rc_sim *a = gas(d, 7), *b = gas(d, 7);
    if (!a || !b)
        return;
    ENSURE(rc_sim_advance(a, 25.0, 0) == RC_OK);
    size_t bytes = 0;
    ENSURE(rc_sim_checkpoint_size(a, &bytes) == RC_OK);
    unsigned char *buf = malloc(bytes);
    ENSURE(rc_sim_checkpoint_write(a, buf, bytes) == RC_OK);
    rc_sim_free(&a);
    /* a fresh engine of the same definition (the box util_gas's gas chose) */
    rc_sim_def d2 = d;
    rc_sim_gas_def g = {dim, 200, 0.5, 0.1, 0.3, c, 1.0, 7};
    rc_sim_ball *tmp = malloc(200 * sizeof *tmp);
    ENSURE(rc_sim_gas_init(&g, &d2.box, tmp) == RC_OK);
    free(tmp);
    rc_sim *t = NULL;
    rc_sim_diag db;
    ENSURE(rc_sim_create(&d2, &t) == RC_OK);
    ENSURE(rc_sim_checkpoint_read(t, buf, bytes) == RC_OK);
    ENSURE(rc_sim_advance(t, 60.0, 0) == RC_OK && rc_sim_advance(b, 60.0, 0) == RC_OK);
    ENSURE_MSG(rc_sim_hash(t) == rc_sim_hash(b), "dim %d c %g: continued run differs", dim, c);
    rc_sim_diag dt;
    rc_sim_diagnostics(t, &dt);
    rc_sim_diagnostics(b, &db);
    ENSURE(memcmp(dt.wall_heat_by_wall, db.wall_heat_by_wall, sizeof dt.wall_heat_by_wall) == 0);
    ENSURE(dt.events[RC_SIM_EV_WALL] == db.events[RC_SIM_EV_WALL]);
    /* another wall temperature: not the run that wrote it */
    rc_sim_free(&t);
    rc_sim_def d3 = d2;
    d3.wall_kT[1] = 0.3;
    ENSURE(rc_sim_create(&d3, &t) == RC_OK && rc_sim_checkpoint_read(t, buf, bytes) == RC_EMISMATCH);
    rc_sim_free(&t);
    free(buf);
    rc_sim_free(&b);
}

/* Elastic balls: what the balls lost is what the walls took, energy and momentum. */
static void test_books(int dim, double c)
{
    rc_sim_def d = thermal_def(dim, c, 3.0, 0.1);
    d.wall_rule[2] = &rc_wall_thermal; /* a warm y wall too */
    d.wall_kT[2] = 1.0;
    rc_sim *s = gas(d, 11);
    if (!s)
        return;
    rc_sim_diag d0, d1;
    rc_sim_diagnostics(s, &d0);
    ENSURE(rc_sim_advance(s, 80.0, 0) == RC_OK);
    rc_sim_diagnostics(s, &d1);
    double q = 0.0;
    rc_vec3 pw = rc_v3(0, 0, 0);
    for (int w = 0; w < 6; w++) {
        q += d1.wall_heat_by_wall[w];
        pw = rc_v3_add(pw, d1.wall_momentum_by_wall[w]);
    }
    ENSURE(d1.events[RC_SIM_EV_WALL] > 500);
    ENSURE_MSG(fabs(d1.kinetic + q - d0.kinetic) <= 1e-11 * d0.kinetic, "dim %d: energy %.17g + %.17g vs %.17g",
               dim, d1.kinetic, q, d0.kinetic);
    ENSURE_CLOSE(d1.heat, q, 1e-11, d0.kinetic);
    for (int k = 0; k < dim; k++) {
        ENSURE_CLOSE(rc_v3_get(d1.momentum, k) + rc_v3_get(pw, k), rc_v3_get(d0.momentum, k), 1e-11,
                     d1.momentum_scale);
        ENSURE_CLOSE(rc_v3_get(pw, k), rc_v3_get(d1.wall_impulse, k), 1e-11, d1.momentum_scale);
    }
    /* the hot wall heats the gas, the cold one cools it */
    ENSURE(d1.wall_heat_by_wall[0] < 0.0 && d1.wall_heat_by_wall[1] > 0.0);
    /* the normal component of a wall's momentum is the one wall_impulse_by_wall keeps */
    for (int w = 0; w < 2 * dim; w++)
        ENSURE_CLOSE(rc_v3_get(d1.wall_momentum_by_wall[w], w / 2), d1.wall_impulse_by_wall[w], 1e-11,
                     d1.momentum_scale);
    rc_sim_free(&s);
}

int main(void)
{
    RUN_TEST(test_refusals);
    RUN_TEST(test_seed_and_default);
    test_checkpoint(3, 1.0);
    test_checkpoint(2, INFINITY);
    test_checkpoint(2, 1.0);
    test_books(3, 1.0);
    test_books(2, INFINITY);
    RC_TEST_MAIN_END();
}
