/* relcol/sim.h — the event-driven N-ball engine: balls in a 2-D table or 3-D box, exact
 * event times, any c, ball and wall restitution, simultaneous contacts solved together.
 *
 * Lifecycle (Box2D style): fill an rc_sim_def made by rc_sim_def_default(), rc_sim_create,
 * rc_sim_set_balls, then rc_sim_advance as often as wanted, read the state with
 * rc_sim_get_ball / rc_sim_diagnostics, and rc_sim_free. The engine never prints.
 *
 * Overlap policy (contracted shapes change shape when their speed changes, so a collision
 * can leave a ball overlapping a neighbour): a pair found overlapping (RC_EOVERLAP from
 * the frame, or spheres deeper than round-off) whose bounding spheres approach collides
 * at once along the centre line, and is counted in rc_sim_diag.overlaps; an overlapping
 * pair that separates is left to separate.
 *
 * Event times are pure functions of the two balls' stored states (position at the ball's
 * own clock, momentum, rest mass), never of when they were asked for; so a run can be
 * written out and continued bit-identically (rc_sim_sync, then rc_sim_get_ball: see
 * rc_sim_sync).
 *
 * Cost per event does not grow with N: balls are grouped in cells at least one bounding
 * diameter wide, each ball keeps only its own earliest event in a calendar queue,
 * events made stale by a partner's later collision are detected by per-ball collision
 * counters, and every ball keeps its own clock (its state is stored at the time it was
 * last touched and advanced lazily), so an event touches only its balls. */
#ifndef RELCOL_SIM_H
#define RELCOL_SIM_H

#include <stddef.h>
#include <stdint.h>
#include "relcol/kinematics.h"
#include "relcol/law.h"
#include "relcol/toi.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rc_sim rc_sim;

/* Lanes of the neighbour test (rc_sim_def.simd). All give the same bits (the lanes do the
 * scalar operations in the same order); the choice exists to show that and to time them. */
typedef enum rc_sim_simd {
    RC_SIM_SIMD_AUTO = 0, /* the widest the CPU has: AVX-512 (eight pairs), AVX2 (four) */
    RC_SIM_SIMD_AVX512,   /* at most AVX-512 (the same as AUTO today) */
    RC_SIM_SIMD_AVX2,     /* at most AVX2 */
    RC_SIM_SIMD_SCALAR    /* the scalar loop */
} rc_sim_simd;

/* Deferred root finds (rc_sim_def.defer): a contact frame whose contact times the broad
 * phase bounds from below (the table frame) may store a candidate's bound as its event and
 * ask the frame only when it comes up in the queue. The same bits either way. */
typedef enum rc_sim_defer {
    RC_SIM_DEFER_AUTO = 0, /* defer where the frame allows it */
    RC_SIM_DEFER_ON,       /* defer; RC_EINVAL if the frame does not allow it */
    RC_SIM_DEFER_OFF       /* ask the frame at once */
} rc_sim_defer;

/* Boundary of one axis of the box (rc_sim_def.boundary). */
enum rc_sim_boundary {
    RC_SIM_WALLS = 0,   /* hard walls at 0 and L (restitution eps_wall) */
    RC_SIM_PERIODIC = 1 /* the faces 0 and L are one: a ball leaving through one comes back
                           through the other, and balls meet across it (nearest image).
                           Periodic in the box frame, which is the table frame: its
                           simultaneity decides the identification. The axis needs at least
                           four cells (rc_sim_def.cell_size, or automatic: at least one
                           largest bounding diameter each, so that the nearest image is the
                           copy two neighbours can meet), so the box edge must be >= 4 cell
                           edges: RC_EINVAL from rc_sim_create (cell_size given) or
                           rc_sim_set_balls (automatic cells) otherwise. Positions are kept
                           in [0, L); rc_sim_ball.image counts the wraps. */
};

/* Definition of a simulation. Make one with rc_sim_def_default() and change fields. */
typedef struct rc_sim_def {
    int dim;            /* 2 (table: z ignored, kept 0) or 3 */
    rc_vec3 box;        /* box edge lengths; the box is [0, box.x] x [0, box.y] (x [0, box.z]) */
    double c;           /* speed of light, > 0; INFINITY is the exact classical case */
    double eps_ball;    /* ball-ball restitution in [0, 1] */
    double eps_wall;    /* ball-wall restitution in [0, 1] */
    /* TC model against inelastic collapse: a contact in which a ball's proper time since
     * its previous collision is < t_c is elastic. Proper time, time units; 0 = off. */
    double t_c;
    /* two-ball law (rc_law_zmf by default, see relcol/law.h); a group of simultaneous
     * contacts goes to its group solver (law->group), or without one is resolved one
     * contact at a time (rc_sim_diag.group_sequential). A law's failure (a negative code
     * from collide) ends rc_sim_advance with that code. */
    const rc_law *law;
    /* Contact geometry (relcol/toi.h), chosen by the frame's declared properties: NULL or
     * a frame with contracted = 0 (sphere) = uncontracted spheres (the engine's own
     * inlined exact kernel, toi never called); a contracted frame (table, zmf, or a
     * user's) is called as the narrow phase after the exact bounding-sphere test says
     * the balls can touch first, and gives the contact normal -- through its direct
     * solver frame->shapes if it declares one, its root finds deferred if it declares
     * deferrable. Walls see the contracted support r sqrt(1 - (v.n)^2/c^2) when
     * frame->wall_contracted. toi holds the frame's tolerances; its c is NAN
     * (rc_sim_def_default: the engine's c) or must equal c (RC_EINVAL otherwise). */
    const rc_toi_frame *frame;
    rc_toi_params toi;
    /* Simultaneous contacts: at an event, every other contact whose surface gap is at
     * most sim_tol * (ri + rj) (walls: sim_tol * r) and which is approaching is resolved
     * together with it (relative, dimensionless; default 1e-9: far above the 1e-16
     * round-off of a computed contact, far below any physical gap). A per_ball frame
     * (covariant) at a ball-ball contact of the model instead groups the approaching
     * ball contacts whose contact events lie within sim_tol * (ri + rj) / c of the first
     * one's in the ZMF of the group's balls, and its members' walls by the gap rule at
     * the event's table time (papers/simultaneous-contacts.md). */
    double sim_tol;
    /* How such a group is resolved by a law with a group solver (rc_group_rule in
     * relcol/law.h: RC_GROUPS_SIMULTANEOUS, the default, RC_GROUPS_SEQUENTIAL or
     * RC_GROUPS_DROP; RC_EINVAL otherwise). The group itself is found at one table time
     * (the covariant frame's ball contacts: in the group's ZMF, sim_tol above); the
     * sequential rule orders it in the group's ZMF. */
    int groups;
    /* A touching pair whose normal approach speed is below approach_tol times its relative
     * speed scale counts as not approaching (dimensionless, default 1e-10): this stops the
     * zero-time re-collisions that round-off would otherwise create after an eps = 0 or a
     * grazing contact; the overlap it allows is <= approach_tol * (ri + rj) per free time. */
    double approach_tol;
    /* An overlap deeper than overlap_tol * (ri + rj) is counted in rc_sim_diag.overlaps
     * (dimensionless, default 1e-9; shallower ones are round-off of contact positions). */
    double overlap_tol;
    double cell_size;   /* cell edge, >= the largest ball diameter; 0 = automatic */
    double density;     /* rest mass of a ball given with m <= 0: density * r^3 (default 1) */
    /* restart != 0: the balls given to rc_sim_set_balls are a state an engine wrote
     * (rc_sim_get_ball after rc_sim_sync), to be continued. Such a state may hold shapes
     * that overlap by the frame's own geometry — shape change after a collision, and in
     * the zmf frame shapes judged at one table time — which the engine itself produced
     * and handles (see the overlap policy above), so with contracted shapes the overlap
     * check is skipped and a contracted shape may cross a wall as long as its centre is
     * inside the box; every other check stays, and uncontracted spheres (c = inf, the
     * sphere frame), which no shape change moves, are checked as always. Default 0:
     * overlapping input is rejected. */
    int restart;
    rc_sim_simd simd;   /* lanes of the neighbour test (default RC_SIM_SIMD_AUTO) */
    rc_sim_defer defer; /* deferred root finds (default RC_SIM_DEFER_AUTO) */
    /* per axis (x, y, z; z ignored in 2-D): RC_SIM_WALLS (the default) or RC_SIM_PERIODIC.
     * Walls and periodic axes mix freely; no wall event and no wall impulse on a periodic
     * axis (with every axis periodic total momentum is conserved to round-off). */
    int boundary[3];
} rc_sim_def;

rc_sim_def rc_sim_def_default(void);

/* A ball as given to and read from the engine (at the engine's current time). */
typedef struct rc_sim_ball {
    rc_vec3 x;   /* centre position */
    rc_vec3 p;   /* momentum */
    double r;    /* rest radius > 0 */
    double m;    /* rest mass; <= 0 on input: density * r^3 */
    double tau;  /* proper time */
    /* TC-model memory: collided != 0 means the ball's last collision happened at its
     * proper time tau_last (a zero-initialised ball has not collided yet). Read back by
     * rc_sim_get_ball so that a written state continues exactly. */
    int collided;
    double tau_last;
    /* Periodic axes: how many times the ball has wrapped across the far face (minus those
     * across the near one), so that x + image * L is its unwrapped position (diffusion,
     * mean square displacement). x itself is always in [0, L) on a periodic axis (input
     * outside: RC_EINVAL). Read only on periodic axes, read back as 0 on walled ones. */
    int32_t image[3];
} rc_sim_ball;

/* Event kinds, for rc_sim_diag.events[]. */
enum rc_sim_event_kind {
    RC_SIM_EV_BALL = 0,   /* two-ball collision resolved alone */
    RC_SIM_EV_WALL,       /* ball-wall collision resolved alone */
    RC_SIM_EV_MULTI,      /* a group of simultaneous contacts resolved together */
    RC_SIM_EV_CELL,       /* cell crossing (bookkeeping) */
    RC_SIM_EV_STALE,      /* queue entry invalidated by a partner's collision */
    RC_SIM_EV_TC,         /* contacts made elastic by the TC model */
    RC_SIM_EV_NKINDS
};

typedef struct rc_sim_diag {
    double time;            /* engine time */
    double mass_rel;        /* sum of M = E/c^2: conserved exactly when c is finite */
    double kinetic;         /* sum of kinetic energies */
    double heat;            /* kinetic energy turned into internal energy so far */
    double energy;          /* kinetic + heat: conserved for every c and restitution */
    double rest_mass;       /* sum of rest masses */
    rc_vec3 momentum;       /* sum of ball momenta */
    rc_vec3 wall_impulse;   /* momentum taken by the walls so far (all walls together) */
    /* ... and by each wall, w = 2 d + side (side 1 the far wall x_d = L_d): the component
     * along e_d of the momentum wall w took (negative on the near walls of a gas pushing
     * out). Exact per axis; see wall_shared for the one case where two walls share it. */
    double wall_impulse_by_wall[6];
    uint64_t wall_shared;   /* groups that touched both walls of one axis (a chain of balls
                               across the box): the axis's momentum was split between them
                               by the group solver's impulses, the rest-mass step's share
                               equally -- a choice, not a measurement */
    uint64_t pinned;        /* approaching wall contacts of a ball jammed along the wall's
                               axis (its shape exactly as wide as the box): resolved
                               perfectly plastic along that axis, whatever the walls'
                               restitution -- a model choice, the rigid-wall limit
                               (papers/relcol.md, "Limits") */
    /* What collisions carried across space so far (papers/pressure.md): virial[3 a + b] =
     * sum over collision events of sum_j r_j,a dp_j,b over the event's balls, r_j the
     * centre of ball j minus that of the event's first ball (nearest image) at the
     * event's table time -- for a two-ball contact r_01,a dp_1,b, the collisional
     * virial; a lone ball's wall contact adds nothing (a group with walls adds its
     * members' moments about its first ball). virial_energy[a]: the same with the
     * kinetic energy change dE_j. Its rate over the volume is the collisional part of the
     * pressure tensor (rc_sim_moments). helfand_wrap, helfand_wrap_energy: the same sums
     * with r_j replaced by (nearest image - unwrapped separation), whole box lengths
     * where a pair meets across a periodic face, 0 otherwise: the jump that makes the
     * unwrapped moment sum_i x_i p_i a Helfand moment (relcol/moments.h). */
    double virial[9], virial_energy[3];
    double helfand_wrap[9], helfand_wrap_energy[3];
    double momentum_scale;  /* sum of |p_i| (scale for relative momentum checks) */
    double max_overlap;     /* deepest sphere overlap now, relative to ri + rj (0 if none;
                               NAN with a contracted frame, whose bounding spheres may
                               overlap while the shapes do not) */
    uint64_t overlaps;      /* overlaps deeper than overlap_tol met by the engine: contacts
                               decided by the overlap policy, not found by the contact model */
    uint64_t overlaps_by_kind[3]; /* the same by the contact's kind: [0] the event's own
                               ball contact, [1] a ball-wall contact, [2] another ball
                               contact of a group of simultaneous contacts */
    uint64_t collisions;    /* contacts resolved (each contact of a group counts) */
    uint64_t events[RC_SIM_EV_NKINDS];
    size_t max_group;       /* most contacts resolved together */
    uint64_t group_fallbacks; /* groups whose joint solve failed (singular normals, or no
                                 rest-mass-keeping outcome): only the event's own contact
                                 was resolved, the rest follow as events of their own */
    /* Groups resolved one contact at a time because the law declares no group solver
     * (rc_law.group == NULL): the contacts in the group's order -- the event's own
     * first, then as the engine found them (each member in the order it joined: its
     * walls by axis, then its neighbours in the engine's cell order) -- each on the
     * states the previous ones left. What it costs: the outcome depends on that order
     * (a ball between two others ends differently if either contact goes first), which
     * is not physical; each group counted here is one where that happened. */
    uint64_t group_sequential;
    /* Frames whose balls change velocity at their own events (rc_toi_frame.per_ball: the
     * covariant frame; papers/shape-change.md). Each ball's worldline kinks where the
     * hyperplane H through the contact event X with normal u_in + u_out meets it, so its
     * world tube is the glued one and its stored state may be at a time after or before
     * the engine's; events are still popped in table-time order, keyed max(t_X, now).
     * rollbacks: contacts before a ball's last kink along its tube -- predicted on the
     * incoming side of its last H, an overlap the frame reports, or a new kink that would
     * come before the last -- where that kink's collision was a single contact of the
     * model or a group an earlier undo solved (up to eight balls), none of whose balls
     * has collided since, or once since (a chain: those later collisions undone first):
     * the collision is undone (its books too; both balls' where the contact lies before
     * both kinks, with either's chain, the ball's two last ones where it lies before
     * both of those) and its contacts and the new one are solved together by the group
     * rule -- without a new one where the two balls were in contact in the chain
     * already -- each ball's kink on its own worldline (papers/shape-change.md, sections
     * 7 and 8). Otherwise:
     * tube_conflicts: predicted contacts on the incoming side of a ball's last H (with
     * the incoming piece of its glued tube, which the table-time schedule cannot order),
     * resolved by the overlap policy, counted in overlaps too (a wall's as kind [1]);
     * one whose pieces part there (a ball met on its incoming piece moving with its
     * incoming velocity) is left to separate. Where the straight cylinder of a ball's
     * stored line overlaps or meets a neighbour inside the ball's window, its glued tube
     * is asked instead (rc_glue_toi: first table time of contact) -- for one ball in its
     * window; with both balls inside theirs, the two glued tubes (rc_glue_toi2), whose
     * contact is taken where it lies on neither incoming piece, or their miss; an
     * overlap of the two tubes, or an incoming piece met, is left to the straight
     * cylinders, and such a contact can pass uncounted (papers/shape-change.md sections
     * 8 and 10: 9 overlaps in 24 audited 2-D elastic runs of 3000-4000 events before the
     * two tubes were asked, 11 after, depth 4e-4 .. 0.018 r).
     * order_conflicts: kinks whose hyperplane crosses the ball's previous one inside it
     * (collisions less than a glue window apart, where the glued tube of the two is not
     * defined), not undone: counted; one that would come before the previous kink along
     * the worldline, a model rule, is put at the previous kink instead. At a ball-ball
     * contact of the model a group is formed by simultaneity in its own ZMF (sim_tol
     * below), solved by the group rule, each member's kink at its own event (the latest
     * along its worldline of its contacts' events); a group met at a wall contact or by
     * the overlap policy is formed and kinked at one table time as in the other frames.
     * rc_sim_get_ball gives the table-time picture of the collisions processed so far: a
     * ball whose kink lies after the engine's time on the line it is still on
     * (rc_sim_kink_ahead; rc_sim_get_ball_latest for the other read-out); the diagnostics'
     * sums (momentum, energy, rest mass) are over every ball's latest segment, which is
     * what collisions conserve. rc_sim_sync keeps the hyperplanes, tubes and kinks ahead
     * and changes nothing; rc_sim_set_c makes every kink still ahead at once and forgets
     * the hyperplanes (both below; a checkpoint keeps everything). */
    uint64_t tube_conflicts, order_conflicts, rollbacks;
    /* After rc_sim_advance returned RC_ESTALL: the ball whose event was next (caller's
     * index) and its partner (a ball's index, -1 - w for wall w = 2 d + side, or a large
     * negative number for a cell crossing). */
    int64_t stall_ball, stall_partner;
} rc_sim_diag;

/* A new engine. Its neighbour test runs in the widest lanes the CPU has up to def->simd;
 * the table frame's root finds are deferred as def->defer says. RC_EINVAL for a simd or
 * defer that is not one of its enum's values, or RC_SIM_DEFER_ON with a frame that cannot
 * defer. */
int rc_sim_create(const rc_sim_def *def, rc_sim **out);
/* Frees and sets *s to NULL (NULL and *s == NULL are fine). */
void rc_sim_free(rc_sim **s);

/* Set the engine's time (finite) before any balls are placed, e.g. to continue a run
 * that stopped at t: RC_EINVAL once balls are set. The default is 0. */
int rc_sim_set_time(rc_sim *s, double t);

/* Place n balls at the engine's time (replaces any previous set). Rejects non-finite
 * input, r <= 0, |v| >= c (impossible from a finite p), a ball whose shape is not inside
 * the box (RC_EINVAL) and balls overlapping by more than overlap_tol (RC_EOVERLAP;
 * touching is fine), both judged in the contact frame's own geometry (contracted shapes
 * for table and zmf at finite c). With contracted shapes an overlapping pair that is
 * separating is accepted: shape change after a collision produces exactly such states
 * (see the overlap policy above), and a restart must read them back. On a periodic axis
 * the centre must lie in [0, L) (the shape may reach across the face), overlaps are
 * judged between nearest images, image[] is taken as given, and a box edge below four
 * cell edges is RC_EINVAL. *bad (may be NULL) gets the index. */
int rc_sim_set_balls(rc_sim *s, size_t n, const rc_sim_ball *balls, size_t *bad);

/* Bring every ball to the engine's time and plan all events afresh from that state alone
 * (diagnostic counters are kept). Afterwards the run's future depends only on what
 * rc_sim_get_ball returns, so a state written now and loaded into a new engine with
 * rc_sim_set_time + rc_sim_set_balls continues bit for bit as this engine does. But the
 * re-planning itself rounds event times differently: the run after a sync differs in its
 * bits from the run without one. To stop and continue a run without changing it, use a
 * checkpoint (below); advancing in pieces, and reading balls or diagnostics between
 * them, gives the same bits as advancing in one go. */
/* A frame whose balls change velocity at their own events (rc_toi_frame.per_ball:
 * covariant) at finite c is the exception: a ball's state at now does not carry its
 * hyperplane, its glued tube or a kink still ahead of now, and the frame's predictions
 * depend on the time they are asked at, so re-planning would change the run. There
 * rc_sim_sync keeps the engine's whole state and plans nothing afresh: the run continues
 * with the same bits as without it (test_engine_covariant), and a state to continue from
 * is a checkpoint, not the balls. */
int rc_sim_sync(rc_sim *s);

/* Change the speed of light during a run, at the engine's time: every ball keeps its
 * position, momentum, rest mass, proper time and TC memory; its velocity p / M and its
 * contracted shape follow the new c (with a finite p every speed stays below any c > 0).
 * Events are planned afresh, as by rc_sim_sync (so the run's bits differ from one that
 * never changed c); the diagnostic counters continue. The kinetic energy is a function
 * of c, so rc_sim_diag.energy changes at the call: conservation holds from here on, with
 * the new value as its reference. A shape that grows (c raised) can overlap a neighbour
 * or a wall; such pairs are left to the overlap policy above and counted in
 * rc_sim_diag.overlaps. RC_EINVAL for a NULL engine, RC_ESPEEDOFLIGHT for c <= 0, NaN
 * or out of range as rc_inv_c2 says (c = INFINITY is the classical case), RC_ENOMEM; on
 * failure the engine keeps its old c and its balls. */
/* With a frame whose balls change velocity at their own events (covariant) the glued
 * tubes are functions of c (the hyperplane's tilt is (g0 v0 + g1 v1) / (c^2 (g0 + g1))),
 * so at the call every kink still ahead of the engine's time is made at once, at the
 * ball's true centre and proper time now (rc_sim_get_ball), with the momentum and rest
 * mass of its latest segment -- the one-instant rule, as the overlap policy's kinks;
 * total momentum and energy are those of the latest segments, so they are kept -- and
 * every hyperplane and glued tube is forgotten: the new c's collisions start new ones.
 * The engine then holds nothing the balls do not (set_c equals a new engine at the new
 * c given the balls read after it; test_engine_covariant). */
int rc_sim_set_c(rc_sim *s, double c);

/* ---- checkpoints: stopping and continuing without changing the run -------------- */

/* The engine's whole state as bytes: every ball at its own clock, every scheduled event,
 * the cells' order, the numbering, the bookkeeping (diagnostics continue too). Read into
 * an engine made from an equal definition (every field that changes the physics or the
 * event order: dim, box, c, restitutions, t_c, law and frame by name, tolerances, cell
 * size, density), it continues bit for bit as the engine that wrote it: a run stopped,
 * written, read and continued equals the run that never stopped, in every bit
 * (test_engine_checkpoint). The bytes are for machines of this one's byte order and
 * record layout, carry a checksum, and are checked ball by ball on reading, so damaged or
 * foreign bytes are refused (RC_ECORRUPT, RC_EMISMATCH), never run.
 *   size: the bytes a checkpoint of s takes now;
 *   write: exactly that many into buf;
 *   read: replaces s's balls and time; on failure s holds no balls. */
int rc_sim_checkpoint_size(const rc_sim *s, size_t *bytes);
int rc_sim_checkpoint_write(const rc_sim *s, void *buf, size_t bytes);
int rc_sim_checkpoint_read(rc_sim *s, const void *buf, size_t bytes);

/* Process events in time order until the next one would be later than t_end (then all
 * balls are at t_end) or max_events events were processed (0 = no limit). A collision law
 * that fails (a negative code other than from its group solver) stops the run with its
 * code; the event's balls keep their states from before it. A run whose time no longer
 * moves -- more than 10000 + 64 N events in a row at one instant: a chain of touching
 * balls exactly as wide as the box pushed against both walls, which the group solver
 * cannot resolve and the fallback resolves one wall after the other for ever (a single
 * ball as wide as the box is jammed, not stalled: rc_sim_diag.pinned), or a clock so
 * large that an event's step rounds to nothing -- stops with RC_ESTALL before the next
 * event, its state whole (it can be read and written), and rc_sim_diag.stall_ball and
 * stall_partner name that event; advancing again stalls again. */
int rc_sim_advance(rc_sim *s, double t_end, uint64_t max_events);

size_t rc_sim_count(const rc_sim *s);
double rc_sim_time(const rc_sim *s);
/* Ball i as it is at the engine's time. With a frame whose balls change velocity at their
 * own events (rc_toi_frame.per_ball: covariant, finite c) a ball's latest kink may lie
 * after the engine's time: the state given is then the one it really has at the engine's
 * time -- centre, momentum, rest mass, proper time and TC memory on the line it is still
 * on -- and rc_sim_kink_ahead says so. */
int rc_sim_get_ball(const rc_sim *s, size_t i, rc_sim_ball *out);
/* (the per-ball model's read-outs -- rc_sim_get_ball_latest, rc_sim_get_glue,
 * rc_sim_kink_ahead, delayed slices -- are in relcol/perball.h) */

/* Diagnostics at the engine's time (O(N); max_overlap is O(N) with the cells). */
int rc_sim_diagnostics(const rc_sim *s, rc_sim_diag *d);
/* FNV-1a hash of every ball's state bits at the engine's time (determinism tests). */
uint64_t rc_sim_hash(const rc_sim *s);
/* Bytes of memory held by the engine. */
size_t rc_sim_bytes(const rc_sim *s);

/* ---- simultaneous contacts ------------------------------------------------------ */

/* (rc_contact, a contact of a group, is defined in relcol/law.h beside the law's group
 * solver type rc_law_group_fn.) */

/* The zmf law's group solver (rc_law_zmf.group calls it).
 * Resolve k contacts among balls[] together (papers/simultaneous-contacts.md): contact
 * j gives ball b the four-impulse J_j q_j and ball a -J_j q_j, q_j = (u_j.n_j/c^2, n_j)
 * with u_j the pair's zero-momentum velocity before the group (q = (0, n) for a wall), and
 * the J_j solve, by Newton's method, the k restitution conditions of the zmf law: each
 * pair's post-group ZMF-normal approach a_j' = -eps_j a_j. Classically (inv_c2 = 0) this
 * is the k x k linear system, solved exactly in one step; k = 1 is the zmf law itself.
 * A contact whose impulse comes out pulling (J < 0) is dropped and the rest re-solved.
 * Then, relativistically with two or more contacts, the rest masses: the balls that took
 * an impulse have their momenta scaled by one factor in their common zero-momentum frame,
 * total energy kept, so that a ball whose contacts were all elastic keeps its rest mass
 * and no rest mass falls (no negative heat).
 * jout (may be NULL, k entries) receives the impulses of the first step. prm->eps is not
 * used. RC_ENOCONVERGE if Newton fails or no such scaling exists (the caller may then
 * resolve the contacts one at a time), RC_EMASS if a rest mass would become imaginary. */
int rc_contacts_resolve(double inv_c2, size_t nballs, rc_particle *balls, size_t k,
                        const rc_contact *contacts, double *jout);

/* The zmf law's group solver with the rule prm->groups (relcol/law.h, rc_group_rule;
 * prm->c the speed of light, prm->eps not used): RC_GROUPS_DROP is rc_contacts_resolve
 * above, in the frame of the given states. The other two rules run in the group's
 * zero-momentum frame (states, normals as their four-vectors q and events boosted there and
 * back; with a wall, or classically, in the given frame), so that their outcome does not
 * depend on the frame the states are given in. RC_GROUPS_SIMULTANEOUS replaces the
 * dropping by principal pivoting, so that on
 * return every impulse jout[j] >= 0, a contact with an impulse meets its restitution
 * condition and one without approaches no more than restitution allows (to round-off,
 * before the rest-mass step, which moves them by O((v/c)^2)); RC_GROUPS_SEQUENTIAL
 * resolves the contacts one after another in the order of their events' times
 * (rc_contact.t, .x) in the group's zero-momentum frame (jout: each contact's impulses
 * summed). RC_EINVAL for a rule that is not one. Other codes as rc_contacts_resolve. */
int rc_contacts_solve(const rc_collision_params *prm, size_t nballs, rc_particle *balls,
                      size_t k, const rc_contact *contacts, double *jout);

/* ---- initial states ------------------------------------------------------------- */

typedef struct rc_sim_gas_def {
    int dim;          /* 2 or 3 */
    size_t n;         /* number of balls */
    double radius;    /* rest radius of every ball */
    double packing;   /* packing fraction: < 0.52 in 3-D, < 0.78 in 2-D (lattice start) */
    double v_rms;     /* rms speed (< c) */
    double c;         /* speed of light (INFINITY classical) */
    double density;   /* rest mass = density * r^3 */
    uint64_t seed;
} rc_sim_gas_def;

/* n equal balls on a random subset of the sites of a square / cubic lattice filling a
 * cubic box whose edge makes the packing fraction exact, with isotropic random momenta
 * scaled so the rms speed is v_rms and total momentum is zero. Where that lattice (side^dim
 * >= n sites) has no room for n <= 64 balls, they are placed at random instead (random
 * sequential addition, from the seed; RC_EOVERLAP if no placement is found within a
 * bounded number of tries). Melt it with rc_sim_advance before measuring anything that
 * needs a fluid. balls: n entries.
 * RC_EINVAL also for n = 1 with v_rms > 0 (zero total momentum leaves one ball at rest),
 * RC_ENONFINITE for a v_rms whose momenta would overflow. */
int rc_sim_gas_init(const rc_sim_gas_def *g, rc_vec3 *box, rc_sim_ball *balls);

#ifdef __cplusplus
}
#endif
#endif
