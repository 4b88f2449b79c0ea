/* sweep.h — relcol-shock --sweep-c: one tube (its state in table units) run at each c of a
 * list, its plateau and shock read at the last time against both the exact relativistic
 * solution at that c and Sod's (the Euler solution, c = inf); CSV and a one-page figure. */
#ifndef RELCOL_SHOCK_SWEEP_H
#define RELCOL_SHOCK_SWEEP_H

#include "shock_run.h"

/* Runs o at each of cs[0..n-1] (o->tube.c ignored), writes dir/sweep.csv, summary.json
 * (the fitted order of approach, with inf in cs),
 * sweep_profiles.csv, sweep.gp (and sweep.png with gnuplot). 0, or -1 with err. */
int sh_sweep(const char *prog, const sh_opts *o, const double *cs, int n, const char *dir,
             int verbose, char *err);

#endif
