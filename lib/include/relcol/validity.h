/* relcol/validity.h — where a run stands against the rigid-ball model's regime
 * (papers/validity.md): a ball struck again within its light-crossing time has no defined
 * shape, and there every rule is a model choice. The covariant frame promises agreement
 * between inertial frames and a small overlap-policy share while p_model stays below
 * RC_VALIDITY_P_MODEL_MAX; the other frames at finite c are counted, never bounded. */
#ifndef RELCOL_VALIDITY_H
#define RELCOL_VALIDITY_H

#include <stdint.h>

#include "relcol/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/// The p_model above which a covariant run is `outside` (papers/validity.md, promise (b))
#define RC_VALIDITY_P_MODEL_MAX 1e-3

/// Which side of the model's regime a run is on.
typedef enum rc_sim_verdict {
    RC_VERDICT_DEFINED = 0,      ///< covariant frame, p_model <= threshold; or c = inf
    RC_VERDICT_OUTSIDE = 1,      ///< covariant frame, p_model > threshold
    RC_VERDICT_NON_COVARIANT = 2 ///< a non-covariant model at finite c: counted, no bound
} rc_sim_verdict;

/// A run's validity report (rc_sim_validity); the kink clusters are per_ball frames' at finite c, counted online from the run's start or its first event after rc_sim_set_balls.
typedef struct rc_validity {
    uint64_t collisions;       ///< contacts resolved (rc_sim_diag.collisions)
    uint64_t policy;           ///< contacts resolved by the overlap policy (diag.overlaps)
    double policy_share;       ///< policy / collisions (0 with no collision)
    uint64_t tube_conflicts, order_conflicts; ///< per_ball frames (diag's)
    uint64_t undone;           ///< collisions undone and solved again (diag.rollbacks)
    uint64_t kink_events;      ///< events that placed kinks: the clusters' nodes
    uint64_t kink_pairs;       ///< successive kinks of one ball
    uint64_t kink_pairs_model; ///< ... neither placed by an overlap-policy decision
    uint64_t crossing, crossing_model; ///< ... that cross inside the ball
    uint64_t kinks_popped;     ///< kinks an undo took back
    double p_all;              ///< crossing / kink_pairs
    double p_model;            ///< crossing_model / kink_pairs_model: the verdict's number
    double largest_all;        ///< the largest cluster's share of kink_events
    double largest_model;      ///< ... joined only through the model's own kinks
    double nu_r_c;             ///< collisions per ball per light-crossing time of the mean radius so far (0 at c = inf or at t = 0)
    double threshold;          ///< RC_VALIDITY_P_MODEL_MAX
    int covariant;             ///< the frame is per_ball (its promises apply)
    rc_sim_verdict verdict;    ///< the verdict
    const char *verdict_name;  ///< rc_sim_verdict_name(verdict)
} rc_validity;

/// "defined", "outside" or "non_covariant" ("?" for a value outside the enum).
const char *rc_sim_verdict_name(rc_sim_verdict v);

/// The report of s so far (reading never changes the run): RC_OK; RC_EINVAL for NULL; RC_ENOMEM if the online cluster count ran out of memory (the other fields still filled).
int rc_sim_validity(const rc_sim *s, rc_validity *out);

#ifdef __cplusplus
}
#endif

#endif
