/* frames.c — contact frame name -> the engine's time-of-impact frame (relcol/toi.h):
 * "table" (contracted shapes in the table frame), "zmf" (contact found in each pair's
 * zero-momentum frame), "sphere" (contraction ignored). At c = inf they coincide. */
#include "app.h"
#include "frames.h"

int sim_frame_apply(const char *frame, rc_sim_def *def, char *err)
{
    const rc_toi_frame *f = rc_toi_frame_find(frame);
    if (!f) {
        app_errf(err, "unknown frame '%s' (expected table, zmf or sphere)", frame);
        return -1;
    }
    def->frame = f;
    return 0;
}
