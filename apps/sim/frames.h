/* frames.h — relcol-sim's contact-frame option: "sphere", "table" or "zmf" mapped onto the
 * engine's time-of-impact kernel and wall geometry. */
#ifndef RELCOL_SIM_FRAMES_H
#define RELCOL_SIM_FRAMES_H

#include "relcol/relcol.h"

/* Set def->pair_toi, pair_toi_ctx and contracted_walls for the named frame; -1 with the
 * reason in err (APP_ERR_LEN) if unknown or unavailable. */
int sim_frame_apply(const char *frame, rc_sim_def *def, char *err);

#endif
