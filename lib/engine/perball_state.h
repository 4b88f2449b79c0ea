/* engine/perball_state.h — the state of the per-ball model (frames whose balls change
 * velocity at their own events: rc_toi_frame.per_ball), held by the engine behind one
 * pointer, rc_sim.pb (NULL in every other frame). The model: papers/shape-change.md. */
#ifndef RELCOL_ENGINE_PERBALL_STATE_H
#define RELCOL_ENGINE_PERBALL_STATE_H

#include <stdint.h>
#include "relcol/toi.h"
#include "../glue_kv.h"

/// A ball's last kink: the hyperplane H, t - t_k = kappa.(y - x_k), that began its segment (one cache line).
typedef struct eng_cov {
    double t_k;      ///< its kink's table time (-inf: no collision yet; x_k is the stored line's centre then)
    rc_vec3 kappa;   ///< H's normal over c^2 (0 before the first collision)
    double ev_tx;    ///< table time of the contact event X of the ball's scheduled ball event
    rc_vec3 ev_dx;   ///< X minus the ball's centre then on its stored line
} eng_cov;
_Static_assert(sizeof(eng_cov) == 64, "one cache line per record");

#define ENG_UNDO_NMAX 8 ///< members of a collision that can be undone (bounds the work)
#define ENG_ROOT (INT32_MIN + 1) ///< eng_undo.partner of the first member, without a wall contact

/// What undoing a ball's last collision needs; valid while no member has collided since (counters).
typedef struct eng_undo {
    rc_particle in;     ///< the ball's state before
    eng_cov cov;        ///< its hyperplane before
    rc_glue glu;        ///< its glued tube before
    double tau_last;    ///< its clock's last collision before
    rc_vec3 n;          ///< the contact normal, from the ball to its partner
    double dt;          ///< the contact event X minus the ball's kink E: time ...
    rc_vec3 dx;         ///< ... and position
    int32_t partner;    ///< its parent in the contacts' tree (caller's index), ENG_WALL(w), ENG_ROOT, or ENG_NONE: no record
    uint32_t nm;        ///< the collision's members ...
    int32_t mem[ENG_UNDO_NMAX];   ///< ... by caller's index, in the order its books took them
    uint32_t mcnt[ENG_UNDO_NMAX]; ///< their counters after it
    uint32_t kind;      ///< its event kind (RC_SIM_EV_BALL, _WALL or _MULTI)
    uint32_t ntc;       ///< the TC contacts it counted
    uint32_t npol;      ///< its contacts the overlap policy decided (counted once)
} eng_undo;

#define ENG_PEND_LINES 6 ///< lines before kinks ahead that a ball's read-out record holds

/// One line a ball is on before a kink ahead of the engine's time.
typedef struct eng_pend_line {
    double t;  ///< its kink's table time
    double m;  ///< the line's rest mass ...
    rc_vec3 p; ///< ... and momentum
} eng_pend_line;

/// The read-out's record of the lines before a ball's kinks ahead (engine/perball/pending.c); read only by the read-out.
typedef struct eng_pend {
    int32_t depth;   ///< lines recorded (0: none ahead)
    int32_t img[3];  ///< wrap counters of x
    rc_vec3 x;       ///< the centre at the first recorded kink l[0].t
    double tau;      ///< proper time there
    double tau_last; ///< TC memory before it (-inf: no collision)
    eng_pend_line l[ENG_PEND_LINES]; ///< line k runs until kink l[k].t
    double pad[3];   ///< (whole cache lines)
} eng_pend;
_Static_assert(sizeof(eng_pend) % 64 == 0, "whole cache lines per record");

#define ENG_T2_MEMO 16 ///< answers of the two tubes' contact kept
/// One answer of rc_glue_toi2 by its whole input (the same bits, so a repeat is recalled).
typedef struct eng_t2_memo {
    rc_glue g0, g1; ///< the two tubes, the second in the first's coordinates
    double t1;      ///< the time asked from
    int st, p0, p1; ///< the answer: status and the pieces met ...
    double t;       ///< ... its time ...
    rc_vec3 y, n;   ///< ... point and normal
} eng_t2_memo;

/// Undo counts the white-box tests read (not checkpointed, not in rc_sim_diag).
typedef struct eng_undo_tally {
    uint64_t chain_rollbacks;  ///< undos that took back a chain (a member's later collision first)
    uint64_t policy_rollbacks; ///< undos of an overlap-policy decision
    uint64_t wall_rollbacks;   ///< undos for a wall's tube conflict
    uint64_t wide_chains;      ///< chains longer than two collisions
    uint64_t deep_rollbacks;   ///< undos of the ball's own two last collisions
    uint64_t cycle_rollbacks;  ///< groups with a cycle of contacts undone
    uint64_t rejoins;          ///< chains solved again with no new contact
    uint64_t both_chains;      ///< undos of both balls' collisions with a chain
} eng_undo_tally;

/// What an event's ball was before it, for eng_pend_note.
typedef struct eng_pend_snap {
    int32_t b;       ///< the ball (storage slot)
    uint32_t cnt;    ///< its counter before
    double t_k;      ///< its last kink's time before
    rc_particle in;  ///< its state before
    double tau_last; ///< its TC memory before
} eng_pend_snap;
/// The single contact's records at its event's time T before its members' kinks (engine/perball/ops.c).
typedef struct eng_single_rec {
    eng_ball b[2];    ///< each member's stored record ...
    eng_clock c[2];   ///< ... clock ...
    eng_cov g[2];     ///< ... hyperplane ...
    rc_glue u[2];     ///< ... and glued tube
    int kinked[2];    ///< its kink placed cleanly (a record for a later undo)
    double te[2];     ///< its new kink's time ...
    rc_vec3 kap[2];   ///< ... and H's normal
    int cross[2];     ///< its new hyperplane reaches the ball before its last one did
} eng_single_rec;

/// The event being resolved: its balls as they were, for their read-out records after it.
typedef struct eng_event_rec {
    eng_pend_snap ps[2]; ///< the event's ball and partner
    int np;              ///< how many
    uint64_t rollbacks;  ///< undos before it (an undo notes its own balls)
} eng_event_rec;

/// The per-ball model's state: per ball arrays (caller's balls in storage order) and scratch.
typedef struct eng_perball {
    eng_cov *cov;       ///< each ball's last hyperplane
    rc_glue *glu;       ///< each ball's glued tube through its last kink, contact event at the origin (r = 0: none)
    eng_undo *und;      ///< how to undo each ball's last collision ...
    eng_undo *undp;     ///< ... and the one before (a chain's)
    eng_pend *pend;     ///< each ball's lines before its kinks ahead of now
    int32_t undo_before; ///< scratch of one conflict's undo attempts: the ball whose contact lay before its previous kink too, or -1
    eng_undo_tally tally; ///< counts for the tests
    eng_t2_memo t2m[ENG_T2_MEMO]; ///< the last answers of the two tubes' contact
    uint32_t t2m_n, t2m_next;     ///< answers kept, and the next to replace
    eng_single_rec single;        ///< scratch of the single-contact path
    eng_event_rec event;          ///< scratch of the event being resolved
} eng_perball;

/// 1 - kappa.v for the hyperplane c that began a segment and the velocity v on it: from the tube's shapes where v is its outgoing one and fast (glue_kv.h), bit for bit.
static inline double eng_seg_den(const eng_cov *c, const rc_glue *g, rc_vec3 v)
{
    const double kv = rc_v3_dot(c->kappa, v);
    if (!(kv > RC_GLUE_KV_FAST) || !(g->r > 0.0) || g->v_out.x != v.x || g->v_out.y != v.y ||
        g->v_out.z != v.z)
        return 1.0 - kv;
    return rc_glue_omkv_out(&g->in, &g->out);
}

/// Is the event X (table time tx, offset dxb from the centre then on the stored line, velocity v) on the future side of hyperplane c? (tx - t_k)(1 - kappa.v) >= kappa.dxb; always with no kink.
static inline int eng_glue_side(const eng_cov *c, const rc_glue *g, rc_vec3 v, double tx,
                                rc_vec3 dxb)
{
    return (tx - c->t_k) * eng_seg_den(c, g, v) >= rc_v3_dot(c->kappa, dxb);
}

#endif
