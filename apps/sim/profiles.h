/* profiles.h — relcol-sim's profiles of a gas in a uniform field (scenario key "gravity"):
 * per slab in the field's coordinate, the count and the temperature measured two ways,
 * gathered at every output time of the run, written as profiles.csv and drawn as
 * profiles.png (papers/gravity.md section 5). */
#ifndef RELCOL_SIM_PROFILES_H
#define RELCOL_SIM_PROFILES_H

#include "scenario.h"

#define SIM_PROFILE_SLABS 20

typedef struct sim_profiles {
    int samples;                         /* states gathered */
    double n[SIM_PROFILE_SLABS];         /* balls, summed over samples */
    double n2[SIM_PROFILE_SLABS];        /* ... squared per sample */
    double along[SIM_PROFILE_SLABS], along2[SIM_PROFILE_SLABS];   /* p_z v_z per ball */
    double across[SIM_PROFILE_SLABS], across2[SIM_PROFILE_SLABS]; /* p_perp.v_perp/(d-1) */
    double lapse[SIM_PROFILE_SLABS], lapse2[SIM_PROFILE_SLABS];   /* (1 + g z/c^2) p.v/d */
} sim_profiles;

/* Gather the engine's state now. */
void profiles_sample(sim_profiles *p, const scn_scenario *s, const rc_sim *sim);
/* profiles.csv, profiles.gp and (with gnuplot, if s->out.plots) profiles.png in dir. 0, or
 * -1 with the reason in err. */
int profiles_write(const sim_profiles *p, const scn_scenario *s, const char *prog,
                   const char *dir, char *err);

#endif
