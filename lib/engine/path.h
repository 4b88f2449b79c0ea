/* engine/path.h — a ball's path between events, as the engine reaches it: an ops table
 * chosen once when the engine is made (rc_sim_def.gravity), never per event. The
 * field-free entry, eng_path_straight, is the straight line x + v t, and its event loop is
 * the engine's own (engine/core.c, whose lanes inline that line: run NULL). The entries of
 * a uniform field (papers/gravity.md) wrap a coupling of relcol/gravity.h and bring their
 * own event loop, engine/field.c, which reaches the path through these ops alone. */
#ifndef RELCOL_ENGINE_PATH_H
#define RELCOL_ENGINE_PATH_H

#include "private.h"

typedef struct eng_path_ops {
    const char *name; ///< "straight", "newtonian", "equivalence"
    /// The event loop for these paths (rc_sim_advance's work, its arguments checked); NULL: engine/core.c's.
    int (*run)(rc_sim *s, double t_end, uint64_t max_events);
    /// Ball i's events predicted from its stored state (the queue updated if asked).
    void (*predict)(rc_sim *s, int32_t i, int update_heap);
    /// A ball (rest mass m, *x, *p) moved along its path by dt >= 0 of the engine's clock, *dtau its proper time on the way (dtau NULL: not asked); changed only on RC_OK.
    int (*drift)(const rc_sim *s, double m, rc_vec3 *x, rc_vec3 *p, double dt, double *dtau);
    /// Earliest dt > 0 at which coordinate k of the ball equals X (RC_MISS: never).
    int (*plane_time)(const rc_sim *s, double m, rc_vec3 x, rc_vec3 p, int k, double X, double *dt);
    /// Earliest dt in [0, t_max] at which two balls on one instant of the clock touch (relcol/gravity.h).
    int (*pair_time)(const rc_sim *s, const rc_toi_ball *a, const rc_toi_ball *b, double t_max,
                     double *dt);
    /// The conserved energy of one ball minus its rest energy.
    int (*energy)(const rc_sim *s, double m, rc_vec3 x, rc_vec3 p, double *h);
    /// Ball i's stored state taken h > 0 along its path into o->x, o->p and o->tau (readouts); NULL: its stored straight line.
    void (*ball_at)(const rc_sim *s, size_t i, double h, rc_sim_ball *o);
    /// The mass the field pulls (rest mass, or E/c^2); a contact that changes it at height z changes the energy by g z times the change.
    double (*weight)(const rc_sim *s, double m, rc_vec3 p);
} eng_path_ops;

extern const eng_path_ops eng_path_straight;
extern const eng_path_ops eng_path_newtonian;
extern const eng_path_ops eng_path_equivalence;

/// The entry a definition asks for: straight without a field, else its coupling's; NULL for a coupling the engine has no entry for.
const eng_path_ops *eng_path_for(const rc_sim_def *def);

/// The field's event loop and prediction (engine/field.c).
int eng_field_run(rc_sim *s, double t_end, uint64_t max_events);
void eng_field_predict(rc_sim *s, int32_t i, int update_heap);

#endif
