/* field_gas.h — a colliding gas in the engine with a uniform field, shared by
 * test_gravity_gas and bench_gravity_gas: a 3-D box [0,1)^2 periodic across, floor z = 0
 * and ceiling z = 1, N balls of radius r placed uniformly (no overlaps) with one speed in
 * random directions: off equilibrium in both the density and the momenta. */
#ifndef FIELD_GAS_H
#define FIELD_GAS_H

#include <stdlib.h>

#include "gravity_util.h"

/* gravity NULL: the same gas without a field */
static double field_cell = 0.0; /* the cell edge asked for (0: the engine's) */

static inline rc_sim *field_gas(const rc_gravity_coupling *cp, double c, double g, size_t n, double r,
                         double speed, uint64_t seed)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 3;
    d.box = rc_v3(1, 1, 1);
    d.c = c;
    d.boundary[0] = d.boundary[1] = RC_SIM_PERIODIC;
    d.gravity = cp;
    d.g = g;
    d.g_axis = -1;
    d.density = 1.0 / (r * r * r); /* (m = 1) */
    d.cell_size = field_cell;
    rc_sim *s = NULL;
    if (rc_sim_create(&d, &s) != RC_OK)
        return NULL;
    rc_test_rng R = {seed};
    rc_sim_ball *b = calloc(n, sizeof *b);
    const double pm = isinf(c) ? speed : speed / sqrt(1.0 - speed * speed / (c * c));
    for (size_t i = 0; i < n; i++) {
        b[i].r = r;
        b[i].m = 1.0;
        b[i].x = rc_v3(rc_test_range(&R, 0, 1), rc_test_range(&R, 0, 1),
                       rc_test_range(&R, r, 1 - r));
        const double cz = rc_test_range(&R, -1, 1), ph = rc_test_range(&R, 0, 2 * M_PI);
        const double sn = sqrt(1 - cz * cz);
        b[i].p = rc_v3(pm * sn * cos(ph), pm * sn * sin(ph), pm * cz);
    }
    size_t bad;
    int st;
    while ((st = rc_sim_set_balls(s, n, b, &bad)) == RC_EOVERLAP) /* (draw it again) */
        b[bad].x = rc_v3(rc_test_range(&R, 0, 1), rc_test_range(&R, 0, 1),
                         rc_test_range(&R, r, 1 - r));
    free(b);
    if (st != RC_OK)
        rc_sim_free(&s);
    return s;
}

/* collisions (ball and wall contacts) so far */
static inline uint64_t field_collisions(const rc_sim *s)
{
    rc_sim_diag dg;
    rc_sim_diagnostics(s, &dg);
    return dg.collisions;
}

#endif
