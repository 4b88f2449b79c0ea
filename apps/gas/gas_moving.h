/* gas_moving.h — relcol-gas --observer-velocity: the gas's one-particle distribution seen
 * by an observer moving along x (sampled on its simultaneity hyperplanes,
 * gas_observer.h) against the boosted Jüttner law (boosted.h): chi-square, CSV and
 * figure. 2-D, balls of rest mass 1. */
#ifndef RELCOL_GAS_MOVING_H
#define RELCOL_GAS_MOVING_H

#include <stdint.h>

#include "relcol/sim.h"

typedef struct gas_moving_result {
    double v;                    /* observer velocity / c */
    uint64_t sampled, lost;
    double chi2, chi2_rest, phi, dof; /* against the boosted and the unboosted law, / phi */
    double step;                 /* grid step of the worldline rebuild */
    int made_png;
} gas_moving_result;

/* Sample the gas s (at table time t0, after equilibration) on nplanes hyperplanes dtau
 * apart (c units as the engine's), starting at t0, for an observer at velocity V along x;
 * compare with the boosted law at theta; write DIR/observer.csv, DIR/observer.gp and the
 * figure. -1 with err on failure. */
int gas_moving_run(const char *prog, rc_sim *s, size_t n, double c, double V, double theta,
                   double t0, double dtau, long nplanes, rc_vec3 box, const char *dir,
                   gas_moving_result *res, char *err);

#endif
