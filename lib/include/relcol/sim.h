/* relcol/sim.h — the event-driven N-ball engine: balls in a 2-D table or 3-D box, exact
 * event times, any c, restitution, simultaneous contacts solved together. Lifecycle (Box2D
 * style): rc_sim_def_default, rc_sim_create, rc_sim_set_balls, rc_sim_advance, read-outs,
 * rc_sim_free. Event times depend only on two balls' stored states, so a checkpointed
 * run continues bit for bit. The model: papers/relcol.md; per-ball read-outs: relcol/perball.h. */
#ifndef RELCOL_SIM_H
#define RELCOL_SIM_H

#include <stddef.h>
#include <stdint.h>
#include "relcol/kinematics.h"
#include "relcol/law.h"
#include "relcol/contacts.h"
#include "relcol/toi.h"
#include "relcol/wall.h"
#include "relcol/gravity.h"

#ifdef __cplusplus
extern "C" {
#endif

/// An engine (opaque).
typedef struct rc_sim rc_sim;

/// Lanes of the neighbour test (rc_sim_def.simd); all give the same bits.
typedef enum rc_sim_simd {
    RC_SIM_SIMD_AUTO = 0, ///< the widest the CPU has
    RC_SIM_SIMD_AVX512,   ///< at most AVX-512
    RC_SIM_SIMD_AVX2,     ///< at most AVX2
    RC_SIM_SIMD_SCALAR    ///< the scalar loop
} rc_sim_simd;

/// Deferred root finds (rc_sim_def.defer): a frame whose contact the broad phase bounds is asked only when the bound comes up; the same bits either way.
typedef enum rc_sim_defer {
    RC_SIM_DEFER_AUTO = 0, ///< defer where the frame allows it
    RC_SIM_DEFER_ON,       ///< defer; RC_EINVAL if the frame does not allow it
    RC_SIM_DEFER_OFF       ///< ask the frame at once
} rc_sim_defer;

/// Boundary of one axis of the box (rc_sim_def.boundary).
enum rc_sim_boundary {
    RC_SIM_WALLS = 0,   ///< hard walls at 0 and L (restitution eps_wall)
    RC_SIM_PERIODIC = 1 ///< faces 0 and L identified in the table frame (nearest image); needs at least four cell edges per box edge (RC_EINVAL otherwise); x kept in [0, L), image counts wraps
};

/// Definition of a simulation: make one with rc_sim_def_default() and change fields.
typedef struct rc_sim_def {
    int dim;            ///< 2 (table: z ignored, kept 0) or 3
    rc_vec3 box;        ///< box edge lengths: [0, box.x] x [0, box.y] (x [0, box.z])
    double c;           ///< speed of light, > 0; INFINITY is the exact classical case
    double eps_ball;    ///< ball-ball restitution in [0, 1]
    double eps_wall;    ///< ball-wall restitution in [0, 1]
    double t_c;         ///< TC model: a contact within proper time t_c of a ball's previous collision is elastic (0 = off)
    const rc_law *law;  ///< two-ball law (rc_law_zmf by default); groups go to law->group, or one contact at a time without one; a law's failure ends rc_sim_advance with its code
    const rc_toi_frame *frame; ///< contact geometry (relcol/toi.h), chosen by its declared properties: NULL or uncontracted = the engine's exact sphere kernel; a contracted frame is the narrow phase after the bounding-sphere test
    rc_toi_params toi;  ///< the frame's tolerances; toi.c NAN (the default: the engine's c) or equal to c
    double sim_tol;     ///< contacts within sim_tol (ri + rj) of touching and approaching are resolved together (default 1e-9); the per-ball frame groups ball contacts by sim_tol (ri + rj) / c in the group's ZMF
    int groups;         ///< how a law with a group solver resolves a group (rc_group_rule: RC_GROUPS_SIMULTANEOUS, the default, _SEQUENTIAL or _DROP)
    double approach_tol; ///< a touching pair approaching slower than approach_tol times its speed scale counts as not approaching (default 1e-10)
    double overlap_tol; ///< overlaps deeper than overlap_tol (ri + rj) are counted in rc_sim_diag.overlaps (default 1e-9)
    double cell_size;   ///< cell edge, >= the largest ball diameter; 0 = automatic
    double density;     ///< rest mass of a ball given with m <= 0: density r^3 (default 1)
    int restart;        ///< the balls are a state an engine wrote: contracted shapes may overlap as the engine left them (not checked); default 0, overlapping input rejected
    rc_sim_simd simd;   ///< lanes of the neighbour test (default RC_SIM_SIMD_AUTO)
    rc_sim_defer defer; ///< deferred root finds (default RC_SIM_DEFER_AUTO)
    int boundary[3];    ///< per axis RC_SIM_WALLS (default) or RC_SIM_PERIODIC; mixed freely (z ignored in 2-D)
    const rc_wall_rule *wall_rule[6]; ///< wall w = 2 d + side's rule (relcol/wall.h; side 1 the far wall): NULL is rc_wall_reflecting; RC_EINVAL for one not rigid on a periodic axis, on a wall beyond dim, or with a per_ball frame
    double wall_kT[6];  ///< wall w's temperature kT, where its rule declares temperature: finite and > 0 (RC_EINVAL)
    uint64_t wall_seed; ///< seed of the run's wall stream (rules that declare random), started when balls are placed; its state is in the checkpoint
    /// A uniform field (papers/gravity.md): NULL (the default) none; else its coupling
    /// (rc_gravity_newtonian, rc_gravity_equivalence), pointing along -e_g_axis with
    /// acceleration g at the floor (coordinate 0). The field's axis must have walls; the
    /// frame must be uncontracted and one-instant (a per-ball or contracted frame in a
    /// field is not defined: RC_EUNDEFINED), t_c 0. The engine's clock is the coupling's.
    const rc_gravity_coupling *gravity;
    double g;           ///< the field's acceleration at the floor, > 0 (with gravity)
    int g_axis;         ///< the field's axis, 1 (2-D) or 2 (3-D) by default: -1 = the last axis
} rc_sim_def;

/// The default definition.
rc_sim_def rc_sim_def_default(void);

/// A ball as given to and read from the engine, at the engine's time.
typedef struct rc_sim_ball {
    rc_vec3 x;          ///< centre position
    rc_vec3 p;          ///< momentum
    double r;           ///< rest radius > 0
    double m;           ///< rest mass; <= 0 on input: density r^3
    double tau;         ///< proper time
    int collided;       ///< the TC memory: nonzero if the ball has collided, at proper time tau_last
    double tau_last;    ///< proper time of its last collision (read back so a written state continues exactly)
    int32_t image[3];   ///< periodic axes: wraps across the far face minus the near one (x + image L unwrapped); 0 on walled axes
} rc_sim_ball;

/// Event kinds, for rc_sim_diag.events[].
enum rc_sim_event_kind {
    RC_SIM_EV_BALL = 0, ///< two-ball collision resolved alone
    RC_SIM_EV_WALL,     ///< ball-wall collision resolved alone
    RC_SIM_EV_MULTI,    ///< a group of simultaneous contacts resolved together
    RC_SIM_EV_CELL,     ///< cell crossing (bookkeeping)
    RC_SIM_EV_STALE,    ///< queue entry invalidated by a partner's collision
    RC_SIM_EV_TC,       ///< contacts made elastic by the TC model
    RC_SIM_EV_NKINDS    ///< (the number of kinds)
};

/// Diagnostics at the engine's time (rc_sim_diagnostics).
typedef struct rc_sim_diag {
    double time;            ///< engine time
    double mass_rel;        ///< sum of M = E/c^2: conserved exactly when c is finite
    double kinetic;         ///< sum of kinetic energies
    double heat;            ///< kinetic energy turned into internal energy so far (a thermal wall's exchange included: wall_heat_by_wall)
    double energy;          ///< kinetic + heat: conserved for every c and restitution
    double rest_mass;       ///< sum of rest masses
    rc_vec3 momentum;       ///< sum of ball momenta
    rc_vec3 wall_impulse;   ///< momentum taken by the walls so far
    double wall_impulse_by_wall[6]; ///< ... by wall w = 2 d + side (side 1 the far wall): its component along e_d
    uint64_t wall_shared;   ///< groups touching both walls of one axis, whose share between them is the solver's split (a choice)
    uint64_t pinned;        ///< wall contacts of a ball as wide as the box, made plastic along the axis (a model choice: papers/relcol.md, "Limits")
    double virial[9], virial_energy[3]; ///< sum over events of r_j,a dp_j,b (r from the event's first ball, nearest image) and r_j,a dE_j: the collisional transfer (papers/pressure.md); NaN in a uniform field, which books none
    double helfand_wrap[9], helfand_wrap_energy[3]; ///< the same with r replaced by nearest image minus unwrapped separation (relcol/moments.h)
    double momentum_scale;  ///< sum of |p_i| (scale for relative momentum checks)
    double max_overlap;     ///< deepest sphere overlap now, relative to ri + rj (NAN with a contracted frame)
    uint64_t overlaps;      ///< contacts decided by the overlap policy (overlaps deeper than overlap_tol met)
    uint64_t overlaps_by_kind[3]; ///< the same by kind: [0] the event's own ball contact, [1] a wall's, [2] a group's other ball contact
    uint64_t collisions;    ///< contacts resolved (each contact of a group counts)
    uint64_t events[RC_SIM_EV_NKINDS]; ///< events by kind
    size_t max_group;       ///< most contacts resolved together
    uint64_t group_fallbacks; ///< groups whose joint solve failed: the event's own contact resolved, the rest events of their own
    uint64_t group_sequential; ///< groups resolved one contact at a time by a law without a group solver (the outcome depends on the order: a choice)
    uint64_t tube_conflicts, order_conflicts, rollbacks; ///< per-ball frames: contacts on a glued tube's incoming piece left to the overlap policy; kinks put at the previous one by the order rule; collisions undone and solved again (papers/shape-change.md)
    int64_t stall_ball, stall_partner; ///< after RC_ESTALL: the next event's ball (caller's index) and partner (a ball, -1 - w for wall w, or a large negative number for a cell crossing)
    double wall_heat_by_wall[6]; ///< energy (kinetic) the balls gave wall w so far, contact by contact: a thermal wall's heat, negative when it heated the gas (a joint group solve's rigid-wall contacts are in heat and wall_impulse_by_wall only)
    rc_vec3 wall_momentum_by_wall[6]; ///< momentum the balls gave wall w so far, every component, contact by contact (the same contacts)
} rc_sim_diag;

/// A new engine; RC_EINVAL for a bad definition (simd, defer, a frame that cannot defer with RC_SIM_DEFER_ON).
int rc_sim_create(const rc_sim_def *def, rc_sim **out);
/// Frees the engine and sets *s to NULL (NULL and *s == NULL are fine).
void rc_sim_free(rc_sim **s);
/// Set the engine's time (finite) before any balls are placed; RC_EINVAL once balls are set.
int rc_sim_set_time(rc_sim *s, double t);
/// Place n balls at the engine's time, judged in the frame's own geometry: RC_EINVAL (non-finite, r <= 0, |v| >= c, outside the box, a periodic box under four cells), RC_EOVERLAP (deeper than overlap_tol, unless separating contracted shapes); *bad (may be NULL) the index.
int rc_sim_set_balls(rc_sim *s, size_t n, const rc_sim_ball *balls, size_t *bad);
/// Bring every ball to the engine's time and plan all events afresh (counters kept): the run then depends only on rc_sim_get_ball's states (its bits differ from a run without the sync); per-ball frames keep everything and plan nothing (use a checkpoint to continue).
int rc_sim_sync(rc_sim *s);
/// Change c at the engine's time: positions, momenta, rest masses, clocks kept, events planned afresh; per-ball frames make every kink ahead now and forget the hyperplanes; RC_EINVAL, RC_ESPEEDOFLIGHT, RC_ENOMEM (the old c kept).
int rc_sim_set_c(rc_sim *s, double c);

/* ---- checkpoints: the whole state as bytes (this machine's layout, checksummed), read
 * back into an engine of an equal definition it continues bit for bit; no slices ---- */

/// The bytes a checkpoint of s takes now.
int rc_sim_checkpoint_size(const rc_sim *s, size_t *bytes);
/// Write exactly that many into buf.
int rc_sim_checkpoint_write(const rc_sim *s, void *buf, size_t bytes);
/// Replace s's balls and time by a checkpoint's; on failure s holds no balls.
int rc_sim_checkpoint_read(rc_sim *s, const void *buf, size_t bytes);

/// Process events in time order until the next is later than t_end (then every ball is at t_end) or max_events were processed (0 = no limit); a law's failure returns its code (the event's balls as before it); RC_ESTALL when more than 10000 + 64 N events come at one instant (state whole, stall_ball names it).
int rc_sim_advance(rc_sim *s, double t_end, uint64_t max_events);

/// Number of balls.
size_t rc_sim_count(const rc_sim *s);
/// The engine's time.
double rc_sim_time(const rc_sim *s);
/// Ball i as it is at the engine's time (per-ball frames: on the line it is still on where its kink lies ahead, rc_sim_kink_ahead).
int rc_sim_get_ball(const rc_sim *s, size_t i, rc_sim_ball *out);
/// Every ball at once, out[i] for i < n = rc_sim_count(s) (RC_EINVAL otherwise): rc_sim_get_ball's (latest = 0) or rc_sim_get_ball_latest's (latest != 0) states bit for bit, read in the engine's storage order; ahead (may be NULL, n entries, latest = 0) gets rc_sim_kink_ahead of each ball.
int rc_sim_get_balls(const rc_sim *s, size_t n, rc_sim_ball *out, int latest, int8_t *ahead);
/// rc_sim_get_balls by storage slots, unscattered: out[j] is the state (bit for bit) of caller ball id[j], held in slot from + j, for j < count (from + count <= rc_sim_count(s), RC_EINVAL otherwise); ahead (may be NULL) likewise; for readers that keep a few numbers a ball, a cached block at a time (at 1e5 balls rc_sim_get_balls' scattered writes cost a cache and TLB miss a ball).
int rc_sim_get_balls_stored(const rc_sim *s, size_t from, size_t count, rc_sim_ball *out,
                            size_t *id, int latest, int8_t *ahead);

/// Centres only, rc_sim_get_balls' x bit for bit (latest likewise) without the rest of each ball's state: x[i * dim + d] for caller ball i < n = rc_sim_count(s), dim the definition's (RC_EINVAL otherwise).
int rc_sim_get_positions(const rc_sim *s, size_t n, int dim, double *x, int latest);

/// Diagnostics at the engine's time (O(N)).
int rc_sim_diagnostics(const rc_sim *s, rc_sim_diag *d);
/// FNV-1a hash of every ball's state bits at the engine's time (determinism tests).
uint64_t rc_sim_hash(const rc_sim *s);
/* With a field: *h the sum of the coupling's conserved energies (relcol/gravity.h's
 * energy op, rest energy subtracted) plus the heat, and *booked the change the contacts
 * made to it (g sum z dw over each contact's members, w the mass the field pulls: rest
 * mass for newtonian, E/c^2 for equivalence -- papers/gravity.md section 4); h - booked
 * is constant. RC_EINVAL without a field. */
int rc_sim_field_energy(const rc_sim *s, double *h, double *booked);
/// Bytes of memory held by the engine.
size_t rc_sim_bytes(const rc_sim *s);

/* ---- simultaneous contacts: relcol/contacts.h (the zmf law's group solver) ---- */

/* ---- initial states ------------------------------------------------------------- */

/// A gas to start from (rc_sim_gas_init).
typedef struct rc_sim_gas_def {
    int dim;          ///< 2 or 3
    size_t n;         ///< number of balls
    double radius;    ///< rest radius of every ball
    double packing;   ///< packing fraction: < 0.52 in 3-D, < 0.78 in 2-D (lattice start)
    double v_rms;     ///< rms speed (< c)
    double c;         ///< speed of light (INFINITY classical)
    double density;   ///< rest mass = density r^3
    uint64_t seed;    ///< the random stream's seed
} rc_sim_gas_def;

/// n equal balls on random sites of a lattice filling a cubic box of the exact packing (n <= 64 without room: random placement, RC_EOVERLAP if none), isotropic momenta of rms speed v_rms and zero total; RC_EINVAL (n = 1 with v_rms > 0), RC_ENONFINITE. Melt it before measuring a fluid.
int rc_sim_gas_init(const rc_sim_gas_def *g, rc_vec3 *box, rc_sim_ball *balls);
/// The bytes rc_sim_gas_init takes for g beside the balls (its working memory; 0 for a g it refuses for its dim or n): what an out-of-memory refusal names.
size_t rc_sim_gas_bytes(const rc_sim_gas_def *g);

#ifdef __cplusplus
}
#endif
#endif
