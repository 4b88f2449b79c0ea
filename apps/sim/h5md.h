/* h5md.h — relcol-sim's trajectory in H5MD 1.1 (HDF5 for molecular data), the format
 * that h5py, MDAnalysis, OVITO and GROMACS read. Written into a temporary file and renamed
 * into place at the end, like every other output of a run. */
#ifndef RELCOL_SIM_H5MD_H
#define RELCOL_SIM_H5MD_H

#include "app.h"
#include "scenario.h"

typedef struct sim_h5md sim_h5md;

/* Create path's temporary, with the H5MD metadata, the box, the time-independent
 * elements (species, radius) and the scenario; n balls. 0, or -1 with the reason. */
int h5md_open(sim_h5md **h, const char *path, const scn_scenario *s, size_t n,
              const char *prog, char *err);
/* Append the engine's current state as frame `step` (its index on the frame grid). */
int h5md_frame(sim_h5md *h, const rc_sim *sim, long long step, char *err);
/* Close the file; with commit, rename it into place (else remove it). Frees *h. */
int h5md_close(sim_h5md **h, int commit, char *err);

#endif
