/* relcol/perball.h — reading a run whose balls change velocity at their own events
 * (rc_toi_frame.per_ball: the covariant frame), where a ball's kink can lie before or after
 * the engine's time: its glued tube, the kink ahead, and delayed table-time slices. Every
 * call also answers in the one-instant frames, where it reduces to the plain read-out.
 * The model, its windows and the slice's bound W: papers/shape-change.md. */
#ifndef RELCOL_PERBALL_H
#define RELCOL_PERBALL_H

#include <stddef.h>
#include <stdint.h>
#include "relcol/sim.h"
#include "relcol/toi.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Ball i's latest segment taken to the engine's time, every processed change applied at its contact event's table time (rc_sim_get_ball in one-instant frames).
int rc_sim_get_ball_latest(const rc_sim *s, size_t i, rc_sim_ball *out);
/// Ball i's glued tube through its latest kink, in table coordinates; out->r = 0: none (no kink, c infinite, or an order-rule kink); RC_EINVAL for a bad index or another frame.
int rc_sim_get_glue(const rc_sim *s, size_t i, rc_glue *out);
/// Whether ball i's latest kink lies after the engine's time: 0 no, 1 yes (rc_sim_get_ball gives the line it is on), 2 yes but that line was not recorded (more than six kinks ahead); RC_EINVAL.
int rc_sim_kink_ahead(const rc_sim *s, size_t i);

/* ---- delayed table-time slices: every ball's state at one table time ts, final from ts + W
 * on (W = 0 in one-instant frames and at infinite c); dropped by a checkpoint read,
 * rc_sim_set_balls and rc_sim_set_c ---- */

/// What rc_sim_slice_ready reports about a slice.
typedef struct rc_sim_slice_info {
    double ts;      ///< the slice's table time
    double t_final; ///< engine time from which it is final, as W is bounded now
    int final;      ///< 1: final, it can be read
    uint64_t late;  ///< changes to the slice after it was first read final (an event reached back beyond W)
    double reach;   ///< largest engine time minus ts at which an event changed the slice (-inf: none)
} rc_sim_slice_info;

/// Ask for the slice at table time ts >= the engine's time (*id names it); RC_EINVAL (bad argument, no balls, or a ball whose line at ts was not recorded), RC_ENOMEM, RC_EUNDEFINED in a uniform field (its loop takes no slices).
int rc_sim_slice_request(rc_sim *s, double ts, uint32_t *id);
/// 1 if slice id is final, 0 if not yet; *info (may be NULL) filled; RC_EINVAL, RC_ENOSLICE.
int rc_sim_slice_ready(const rc_sim *s, uint32_t id, rc_sim_slice_info *info);
/// Ball i of slice id at ts on the segment of its worldline that holds ts; RC_ENOTREADY before it is final, RC_ENOSLICE, RC_EINVAL.
int rc_sim_slice_get(rc_sim *s, uint32_t id, size_t i, rc_sim_ball *out);
/// Drop slice id; RC_ENOSLICE if not held.
int rc_sim_slice_release(rc_sim *s, uint32_t id);

#ifdef __cplusplus
}
#endif
#endif
