/* toi_covariant.c — the "covariant" contact frame: the pair's contact event is the zmf
 * frame's (decided in the pair's zero-momentum frame, a covariant event of the two
 * straight world cylinders), and the engine changes each ball's velocity at its own event
 * on its glued world tube, not both at one table time (per_ball; papers/shape-change.md). */
#include "relcol/toi.h"
#include "toi_private.h"

const rc_toi_frame rc_toi_frame_covariant = {
    .name = "covariant",
    .summary = "zmf's contact event, each ball's velocity changed at its own event (glued tube)",
    .toi = rc_toi_zmf_,
    .wall_contracted = 1, /* (the wall's rest frame is the table) */
    .contracted = 1,
    .covariant = 1,
    /* not deferrable for zmf's reason: its contact is not simultaneous in the table */
    .deferrable = 0,
    .shapes = NULL,
    .per_ball = 1,
};
