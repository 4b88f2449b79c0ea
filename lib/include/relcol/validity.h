/* relcol/validity.h — where a run stands against the rigid-ball model's regime (issue 36,
 * papers/validity.md): a rigid ball struck again within its light-crossing time has no
 * defined shape, and there every rule the engine applies is a model choice.
 *
 * The covariant (per_ball) frame promises (a) final four-momenta from two inertial frames
 * that agree within a small multiple of the run's own round-off growth wherever no rule
 * decision differs, and (b) an overlap-policy share <= 0.1 % wherever the share of the
 * model's own crossing kinks, p_model, is <= RC_VALIDITY_P_MODEL_MAX. The verdict names
 * which side of that threshold the run is on. The table, zmf, sphere and transport frames
 * at finite c are non-covariant models: their numbers are counted, never bounded. At
 * c = inf every frame is the exact classical model. */
#ifndef RELCOL_VALIDITY_H
#define RELCOL_VALIDITY_H

#include <stdint.h>

#include "relcol/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The p_model above which a covariant run is `outside` (issue 36, promise (b)). */
#define RC_VALIDITY_P_MODEL_MAX 1e-3

typedef enum rc_sim_verdict {
    RC_VERDICT_DEFINED = 0,        /* covariant frame, p_model <= threshold; or c = inf */
    RC_VERDICT_OUTSIDE = 1,        /* covariant frame, p_model > threshold */
    RC_VERDICT_NON_COVARIANT = 2   /* a non-covariant model at finite c: counted, no bound */
} rc_sim_verdict;

typedef struct rc_validity {
    uint64_t collisions;      /* contacts resolved (rc_sim_diag.collisions) */
    uint64_t policy;          /* contacts resolved by the overlap policy (diag.overlaps) */
    double policy_share;      /* policy / collisions (0 with no collision) */
    uint64_t tube_conflicts, order_conflicts; /* per_ball frames (diag's) */
    uint64_t undone;          /* collisions undone and solved again (diag.rollbacks) */
    /* the kink clusters (per_ball frames at finite c, counted online from the run's start
     * or its first event after rc_sim_set_balls): */
    uint64_t kink_events;     /* events that placed kinks: the clusters' nodes */
    uint64_t kink_pairs;      /* successive kinks of one ball */
    uint64_t kink_pairs_model;/* ... neither placed by an overlap-policy decision */
    uint64_t crossing, crossing_model; /* ... that cross inside the ball */
    uint64_t kinks_popped;    /* kinks an undo took back */
    double p_all;             /* crossing / kink_pairs */
    double p_model;           /* crossing_model / kink_pairs_model: the verdict's number */
    double largest_all;       /* the largest cluster's share of kink_events */
    double largest_model;     /* ... joined only through the model's own kinks */
    /* nu r / c: collisions per ball per light-crossing time of the mean radius, from the
     * run's table time (0 at c = inf or before any time has passed) */
    double nu_r_c;
    double threshold;         /* RC_VALIDITY_P_MODEL_MAX */
    int covariant;            /* the frame is per_ball (its promises apply) */
    rc_sim_verdict verdict;
    const char *verdict_name; /* rc_sim_verdict_name(verdict) */
} rc_validity;

/* "defined", "outside" or "non_covariant" ("?" for a value outside the enum). */
const char *rc_sim_verdict_name(rc_sim_verdict v);

/* The report of s so far. RC_OK; RC_EINVAL for a NULL argument; RC_ENOMEM if the online
 * cluster count ran out of memory at some point (the other fields still filled). Reading
 * never changes the run. */
int rc_sim_validity(const rc_sim *s, rc_validity *out);

#ifdef __cplusplus
}
#endif

#endif
