/* gas_observer.h — the one-particle distribution seen by an inertial observer moving at V
 * along x relative to the box: every ball's momentum where its worldline crosses the
 * observer's simultaneity hyperplanes t - V x / c^2 = tau_j (papers/relcol.md section 8,
 * "moving frames"). The worldlines are rebuilt exactly from the engine's states at a grid
 * of table times: a ball that did not collide between two grid times moved on one straight
 * line; one that did has its last collision's table time from its proper time (tau_last);
 * a crossing that falls where more than one collision hid between two grid times is not
 * sampled, and counted. The 1-D gas is followed event by event instead: nothing is lost.
 * Momenta in units of m c (each ball's own m). */
#ifndef RELCOL_GAS_OBSERVER_H
#define RELCOL_GAS_OBSERVER_H

#include <stddef.h>
#include <stdint.h>

#include "relcol/gas1d.h"
#include "relcol/sim.h"

typedef struct gas_obs gas_obs;

/* n balls, c, observer velocity V along +x (|V| < c), hyperplanes tau_j = tau0 + j dtau
 * for j < nplanes. NULL on a bad argument or no memory. */
gas_obs *gas_obs_create(size_t n, double c, double V, double tau0, double dtau, size_t nplanes);
void gas_obs_free(gas_obs *o);

/* The table-time window that holds every crossing of the hyperplanes by balls with x in
 * [0, L]: [t_first, t_last]. */
void gas_obs_window(const gas_obs *o, double L, double *t_first, double *t_last);

/* The balls at table time t (increasing from call to call; the first call starts the
 * worldlines, so make it at or before t_first): box edges L[3] unwrap periodic images.
 * Returns -1 if a ball's state contradicts the worldline rebuilt (a bug), else 0. */
int gas_obs_record(gas_obs *o, double t, const rc_sim_ball *b, const double *L);

/* 1-D: follow the exact 1-D gas g (box [0, L]) event by event from its time, at or before
 * t_first, to past t_last: each ball's worldline is its straight segments between its
 * events (rc_gas1d_segment_get), so every crossing is sampled and none lost. Momenta are
 * p'/(m c) of each ball's own rest mass, the second component 0. Returns -1 on a bad
 * argument (g past t_first, another n) or if a segment does not reach its event (a
 * bug), else 0. */
int gas_obs_follow_gas1d(gas_obs *o, rc_gas1d *g, double L);

/* The samples: momenta (px', py') seen by the observer on hyperplane j, ball i at
 * [2 (j n + i)], NAN where not sampled; counts of samples taken and lost. */
const double *gas_obs_momenta(const gas_obs *o);
void gas_obs_counts(const gas_obs *o, uint64_t *taken, uint64_t *lost);

#endif
