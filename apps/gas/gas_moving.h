/* gas_moving.h — relcol-gas --observer-velocity: the gas's one-particle distribution seen
 * by an observer moving along x (sampled on its simultaneity hyperplanes,
 * gas_observer.h) against the boosted Jüttner law (boosted.h): chi-square, CSV and
 * figure. 2-D, balls of rest mass 1; 1-D, the two-species mixture. */
#ifndef RELCOL_GAS_MOVING_H
#define RELCOL_GAS_MOVING_H

#include <stdint.h>

#include "relcol/gas1d.h"
#include "relcol/sim.h"

typedef struct gas_moving_result {
    double v;                    /* observer velocity / c */
    uint64_t sampled, lost;
    double chi2, chi2_rest, phi, dof; /* against the boosted and the unboosted law, / phi */
    double step;                 /* grid step of the worldline rebuild (1-D: none, NAN) */
    int made_png;
    /* 1-D, per species (nspec 2): the top level then sums chi2/phi over them (phi NAN) */
    int nspec;
    double sp_mass[2], sp_theta[2], sp_chi2[2], sp_chi2_rest[2], sp_phi[2], sp_dof[2];
    /* 1-D: integrated autocorrelation time of the energy on a hyperplane, in hyperplanes
     * (unlike a table-time snapshot's, it is not fixed by conservation: it carries the
     * gas's slow collective modes, and blocks much shorter than it understate phi) */
    double tau;
} gas_moving_result;

/* Sample the gas s (at table time t0, after equilibration) on nplanes hyperplanes dtau
 * apart (c units as the engine's), starting at t0, for an observer at velocity V along x;
 * compare with the boosted law at theta; write DIR/observer.csv, DIR/observer.gp and the
 * figure. -1 with err on failure. */
int gas_moving_run(const char *prog, rc_sim *s, size_t n, double c, double V, double theta,
                   double t0, double dtau, long nplanes, rc_vec3 box, const char *dir,
                   gas_moving_result *res, char *err);

/* 1-D: the exact 1-D gas g on [0, L] (at table time t0, after equilibration; particle i
 * of species spec[i], rest mass mass[spec[i]]) followed event by event through nplanes
 * hyperplanes dtau apart, the first of them reaching into the box at t0, against each
 * species' boosted law at its theta[s] (as the resting gas measured it): chi-square per
 * species, CSV and figure as gas_moving_run. */
int gas_moving_run_1d(const char *prog, rc_gas1d *g, size_t n, const unsigned char *spec,
                      const double *mass, const double *theta, double c, double V,
                      double t0, double dtau, long nplanes, double L, const char *dir,
                      gas_moving_result *res, char *err);

#endif
