/* sweep_plot.h — relcol-sweep's gnuplot script: one panel per scenario, so that curves of
 * one order and similar size (the soft reference's under the collision law's) stay apart. */
#ifndef RELCOL_SWEEP_PLOT_H
#define RELCOL_SWEEP_PLOT_H

#include <stddef.h>

#include "observables.h"

/* sweep.gp for the ns scenarios of list, whose deviations are sweep.csv's columns 4, 5,
 * ... in list order (scenario by scenario, group by group); order[k] the fitted order of
 * the k-th deviation (NaN when none, k < norder). 0, or -1 with the reason in err. */
int sweep_plot_write(const char *path, const sweep_scenario *const *list, size_t ns,
                     const double *order, size_t norder, double eps, double stiffness,
                     char *err);

#endif
