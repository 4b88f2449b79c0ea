/* engine/model.h — how the event loop reaches the model of where a ball's velocity
 * changes: an ops table called at named points of an event (after SUNDIALS'
 * SUNLinearSolver_Ops). One-instant frames, where every ball changes at its event's table
 * time, use engine/model.c's instant model, whose ops are all NULL (nothing to do); the
 * per-ball model (glued world tubes, papers/shape-change.md) has its own
 * (engine/perball/ops.c). The core calls an op where the table has one and never asks
 * which model it has. */
#ifndef RELCOL_ENGINE_MODEL_H
#define RELCOL_ENGINE_MODEL_H

#include "private.h"

/// Per-ball records of the model read for a narrow-phase candidate k, asked for ahead: row q at base[q] + k * stride[q].
typedef struct eng_rows {
    int n;               ///< rows in use (at most 3)
    const char *base[3]; ///< each row's address for ball 0
    size_t stride[3];    ///< and its bytes a ball
} eng_rows;

/// A ball event's contact event, as the model places it.
typedef struct eng_event_x {
    double tx[2];  ///< each ball's contact event: table time ...
    rc_vec3 dX[2]; ///< ... and offset from its centre then on its stored line
    int model;     ///< 1: a contact of the model (kinks through its event); 0: at the event's time, through the centres
    int wall_tube; ///< a wall met on the incoming side of the ball's hyperplane, left to the overlap policy
} eng_event_x;

/// A model of where balls change velocity: its properties and its ops (each may be NULL: nothing to do there).
typedef struct eng_model_ops {
    const char *name; ///< for messages and tests
    int per_ball;     ///< balls change velocity at their own events: the balls alone do not carry the run (rc_sim_sync re-plans nothing, rc_sim_set_c makes the kinks ahead now)
    /// The narrow phase of a pair whose bounding spheres can touch before best (dx: separation at tref; parting: they overlap and part): the contact's table time (>= now; its event in s->sc_tx, sc_dx; *n its normal) or INFINITY. NULL: the contact frame's own test.
    double (*pair_time)(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                        double tref, double best, int parting, rc_vec3 *n);
    /// The records pair_time reads of each candidate, into *rows (asked once a scan: no call per candidate).
    void (*candidate_rows)(const rc_sim *s, eng_rows *rows);
    /// Ball i's event with a ball is stored: the model keeps its contact event (s->bx_tx, bx_dx).
    void (*event_keep)(rc_sim *s, int32_t i);
    /// A crossing's scan starts from ball i's stored event: its contact event back into s->bx_tx, bx_dx.
    void (*event_recall)(rc_sim *s, int32_t i);
    /// A ball event (i, partner bp: a ball or a wall code) is about to be resolved.
    void (*event_begin)(rc_sim *s, int32_t i, int32_t bp);
    /// The event is resolved (RC_OK).
    void (*event_end)(rc_sim *s);
    /// A contact predicted comes up at T: its contact event into ev, and 0 to go on; 1 if the model resolved it (an undo); or the law's failure.
    int (*contact_event)(rc_sim *s, int32_t i, int32_t bp, double T, eng_event_x *ev);
    /// A contact of the model between two balls (members 0, 1 at T, contact 0 theirs): the group simultaneous with it in its own frame, solved (1), none (0, nothing changed), or the law's failure.
    int (*group_of_model)(rc_sim *s, int32_t i, int32_t bp, double T, const eng_event_x *ev);
    /// Before a resolve: the single contact takes P to Q (changed[j]: member j's state changes); the member whose last collision must be undone first (undo_order), or -1.
    int (*before_resolve)(rc_sim *s, size_t nm, const rc_particle *P, const rc_particle *Q,
                          const int *changed, const eng_event_x *ev, int undo_order);
    /// before_resolve asked for it: w's last collision undone and solved with w's contact with k (1), 0 it does not apply (nothing changed), or the law's failure.
    int (*undo_member)(rc_sim *s, int32_t w, int32_t k, double T, const eng_event_x *ev);
    /// Member j's new state Q is about to be written: its record at T kept, its kink placed.
    void (*resolve_member)(rc_sim *s, size_t j, const rc_particle *P, const rc_particle *Q,
                           int changed, const eng_event_x *ev);
    /// Member j's stored record at T before its kink (the simultaneity check reads it), or NULL: the stored one is at T.
    const eng_ball *(*member_before)(const rc_sim *s, size_t j);
    /// The single contact is taken back (a simultaneous one was found): member j's records as before resolve_member.
    void (*take_back)(rc_sim *s, size_t j);
    /// After a resolve of the single contact from P (vold: the velocities before; tc: the TC model made it elastic): records for a later undo.
    void (*after_resolve)(rc_sim *s, size_t nm, int32_t bp, const rc_particle *P,
                          const rc_vec3 *vold, const eng_event_x *ev, int tc);
    /// A group resolved at one table time: member b's change from in to out, through its centre at the group's time.
    void (*group_member)(rc_sim *s, int32_t b, const rc_particle *in, const rc_particle *out);
    /// Reading ball i at t >= now where it is not on its stored line: 1 (o, *img set), 2 the line was not recorded; 0 on its stored line.
    int (*ball_at)(const rc_sim *s, size_t i, double t, rc_sim_ball *o, const int32_t **img);
    /// Slices: the kink time that began ball k's stored segment (NULL: -INFINITY, no kinks).
    double (*segment_start)(const rc_sim *s, int32_t k);
    /// Slices reach back: the largest Lorentz factor of a segment a later event can start from (a slice is taken at its request and kept by the model's hooks). NULL: taken as the engine passes ts.
    double (*slice_gamma)(const rc_sim *s);
} eng_model_ops;

/// One-instant frames: every op NULL.
extern const eng_model_ops eng_model_instant;
/// The per-ball model: glued world tubes (engine/perball/ops.c).
extern const eng_model_ops eng_model_glued;

/// The model a frame's declared properties ask for at inverse c^2 ic2 (engine/model.c).
const eng_model_ops *eng_model_for(const rc_toi_frame *frame, int narrow, double ic2);

#endif
