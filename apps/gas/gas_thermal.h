/* gas_thermal.h — which contact frames give relcol-gas a Jüttner (thermal) stationary
 * state, from the frames' declared properties (notebook 08, papers/relcol.md section 8). */
#ifndef RELCOL_GAS_THERMAL_H
#define RELCOL_GAS_THERMAL_H

#include <stdio.h>

#include "relcol/toi.h"

/* The frame relcol-gas uses by default: the first of rc_toi_frames[] that is thermal at
 * every density (NULL if none is). */
const rc_toi_frame *gas_default_frame(void);

/* Is a frame's stationary state Jüttner in a gas of dimension dim? 2: at every density;
 * 1: in the dilute limit only; 0: not even there; 3: not shown (a covariant one-instant
 * frame in 3-D, off Jüttner at the lowest packing measured). */
int gas_frame_thermal(const rc_toi_frame *f, int dim);

/* One warning line on f (stderr, "prog: warning: ...") when frame f's stationary state
 * is not Jüttner at this packing; nothing for a thermal one. */
void gas_frame_warn(FILE *f, const char *prog, const rc_toi_frame *frame, int dim,
                    double packing);

#endif
