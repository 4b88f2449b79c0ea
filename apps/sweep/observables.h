/* observables.h — what relcol-sweep measures: a table of scenarios, each computing a few
 * named observables at a given 1/c^2 (0 = classical). A scenario is deterministic and
 * thread-safe (its own workspaces), so grid points can run in any order on any thread or
 * MPI rank and give the same bits. Add a scenario: one function and one table entry. */
#ifndef RELCOL_SWEEP_OBSERVABLES_H
#define RELCOL_SWEEP_OBSERVABLES_H

#include "relcol/relcol.h"

#define OBS_MAX 12

/* The two-ball set-up shared by the scenarios (table units). */
typedef struct sweep_setup {
    double m[2], r[2];
    rc_vec3 x[2], v[2];  /* positions at t = 0, table velocities (|v| < c for the grid) */
    double eps;          /* restitution */
    double stiffness;    /* soft reference */
} sweep_setup;

typedef struct sweep_scenario {
    const char *name;
    const char *summary;
    int n_obs;
    const char *obs[OBS_MAX];   /* observable names, for the CSV */
    /* Observable values at inv_c2; returns 0 or -1 with a reason in err (APP_ERR_LEN). */
    int (*eval)(const sweep_setup *s, double c, double *out, char *err);
    /* groups of observables whose deviation is reported together: a vector observable
     * counts as one deviation |a - a_inf| / |a_inf| over its components */
    int n_groups;
    const char *group[OBS_MAX];
    int group_of[OBS_MAX];
    /* Deviations at or below this are numerical noise, not convergence: excluded from the
     * fitted order (dimensionless, relative). */
    double floor;
} sweep_scenario;

extern const sweep_scenario *const sweep_scenarios[]; /* NULL-terminated */
const sweep_scenario *sweep_scenario_find(const char *name);
sweep_setup sweep_setup_default(void);

#endif
