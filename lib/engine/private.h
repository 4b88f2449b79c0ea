/* engine/private.h — the engine's internal state, shared by the files of lib/engine/.
 * Everything that defines a run lives in plain arrays so that a state can be written out
 * and continued bit-identically (checkpoint.c). Functions shared between these files carry
 * the engine's one internal prefix, eng_, and are not exported from the library. */
#ifndef RELCOL_ENGINE_PRIVATE_H
#define RELCOL_ENGINE_PRIVATE_H

#include <stdint.h>
#include "relcol/sim.h"
#include "relcol/perball.h"

/* Hot data read by every pair test: one 64-byte line per ball. The state is stored at
 * the ball's own time t (its local clock); v = p / M is derived from p and m. */
typedef struct eng_ball {
    rc_vec3 x;
    rc_vec3 v;
    double t;
    double r;
} eng_ball;

/// No event.
#define ENG_NONE INT32_MIN
/// ev_partner for wall w = 2 d + side (side 1 is the far wall x_d = L_d)
#define ENG_WALL(w) (-1 - (w))
#define ENG_WALL_INDEX(code) (-1 - (code))

/* The rest of the state a prediction or a collision reads, and the ball's single
 * scheduled event: one 64-byte line per ball (allocated aligned). */
typedef struct eng_aux {
    rc_vec3 p;
    double m;
    double ev_t;      ///< earliest collision (ball or wall)
    double cross_t;   ///< next cell crossing
    int32_t ev_partner;
    uint32_t ev_pcount; ///< partner's counter (rc_sim.cnt) when ev was computed
    int32_t cell;
    int32_t cross_code; ///< 2 d + (direction > 0), -1 none
} eng_aux;

/// (aligned_alloc wants sizes that are multiples of the alignment)
_Static_assert(sizeof(eng_ball) == 64 && sizeof(eng_aux) == 64, "one cache line per record");

/// Proper time, read and written only when the ball collides (or is read out).
typedef struct eng_clock {
    double tau;      ///< proper time at t
    double tau_last; ///< proper time of the last collision (-inf: none yet)
} eng_clock;

#include "perball_state.h" /* (the per-ball model's records, which hold these) */

/* The event queue (engine/queue.c): one entry per ball, popped in (time, ball) order.
 * (Functions shared between the engine files carry eng_: exported, not public.) */
typedef struct eng_qent {
    double key;   ///< the ball's entry's time
    int32_t next; ///< links of the bucket list it is in, or its heap position (engine/queue.c)
    int32_t prev;
} eng_qent;

/* A ball's key, links and heap place on one 16-byte entry: an update reads and writes one
 * line instead of four arrays'. */
_Static_assert(sizeof(eng_qent) == 16, "four entries a cache line");

typedef struct eng_queue {
    size_t n;
    eng_qent *e;          ///< per ball
    uint32_t *heap;       ///< the bucket being drained: a binary heap (capacity n)
    size_t hn;
    int32_t *head;        ///< nb calendar lists, then overflow, then never
    uint32_t nb;          ///< buckets in the span, a power of two
    double inv_w;         ///< 1 / bucket width
    int64_t cur;          ///< number of the bucket being drained
    int64_t redist;       /* end of the span: buckets from here on wait in the overflow
                             list, spread again when cur reaches it */
    size_t in_cal;        ///< entries in the calendar lists
    double over_min;      /* at most the least key in the overflow list (keys filed there
                             since it was last spread; INFINITY: none) */
    int32_t ahead;        ///< the entry of the next bucket's list to fetch ahead (-1: none)
} eng_queue;

/// Allocate for n balls; then eng_queue_build with every ball's key.
int eng_queue_init(eng_queue *q, size_t n);
void eng_queue_free(eng_queue *q);
/// Refile every ball under keys[] (all >= now), choosing the bucket width afresh.
void eng_queue_build(eng_queue *q, const double *keys, double now);
/// The same with the keys already in q->e[i].key.
void eng_queue_rebuild(eng_queue *q, double now);
/* engine/reorder.c: the balls renumbered in cell order, every per-ball array with them
 * (the event loop calls it every ENG_REORDER_EVERY x N collisions and cell crossings) */
#define ENG_REORDER_EVERY 4
void eng_reorder(rc_sim *s);
/// Change ball's key (>= the time last popped).
void eng_queue_update(eng_queue *q, uint32_t ball, double t);
/// The earliest entry (time, ball); 0 if the queue is empty.
int eng_queue_top(eng_queue *q, double *t, uint32_t *ball);
size_t eng_queue_bytes(const eng_queue *q);
/* The ball likely to come after the top (the earlier child of the heap's root), -1 if
 * the heap holds no other: a hint for prefetching, not a promise of order. */
static inline int32_t eng_queue_next(const eng_queue *q)
{
    if (q->hn < 2)
        return -1;
    uint32_t k = q->heap[1];
    if (q->hn > 2 && q->e[q->heap[2]].key < q->e[k].key)
        k = q->heap[2];
    return (int32_t)k;
}

/* Uniform cell grid over the box. A cell keeps its balls in ENG_CELL_CAP slots of its
 * own (cells hold about one ball): a ball index, -1 (empty) or, in the last slot only,
 * ENG_CHAIN(k) -- the cell has more balls than slots, and the last slot's share of them
 * is the chain k, next[k], ... (at least two). The slots of a row of cells lie together,
 * so a neighbour scan reads each row of its block in one or two loads, with no list to
 * walk unless a cell overflows (engine/cells.c). */
#define ENG_CELL_CAP 2
#define ENG_SLOT_PAD 8 /* (slots past the last cell, always empty: rows are read 8 at a time) */
#define ENG_CHAIN(k) (-2 - (k))
#define ENG_CHAIN_HEAD(v) (-2 - (v))

typedef struct eng_cells {
    int n[3];
    double w[3];      ///< cell edge per dimension
    double inv_w[3];
    int32_t *slot;    ///< ENG_CELL_CAP per cell
    int32_t *next;    ///< per ball: next of its overflow chain (-1: the end)
    size_t ncells;
    int32_t block_rows[9]; ///< a full 3^d block's rows, as slot offsets from its first
    int wrap[3];      ///< periodic axis: the cells wrap around (n >= 4)
    /* a ball in cell c[d] moving up crosses a face if c[d] < up_lim[d] (n - 1 walled, n
     * periodic), moving down if c[d] > dn_lim[d] (0 walled, -1 periodic) */
    int up_lim[3], dn_lim[3];
} eng_cells;

/* periodic[d] != 0: axis d wraps, and gets at least four cells if min_edge allows (the
 * caller checks n[d] >= 4: eng_image). */
int eng_cells_init(eng_cells *g, int dim, rc_vec3 box, double min_edge, size_t nballs,
                      const int periodic[3]);
void eng_cells_free(eng_cells *g);
/// Every cell empty again.
void eng_cells_clear(eng_cells *g);
/* rank[cell] (ncells entries): the cell's place in Z order, the order balls are
 * numbered in. */
void eng_cells_zorder(const eng_cells *g, int32_t *rank);
/// pos[i]: ball i's number in that order, from its cell cell[i] (stable).
int eng_cells_number(const eng_cells *g, const int32_t *cell, size_t n, uint32_t *pos);
int32_t eng_cells_index_of(const eng_cells *g, int dim, rc_vec3 x);
void eng_cells_insert(eng_cells *g, eng_aux *a, int32_t i, int32_t cell);
void eng_cells_remove(eng_cells *g, const eng_aux *a, int32_t i);

/* The balls of one cell, in slot order, a chain where it stands:
 *   for (int32_t k = cell_first(g, cell, &it); k >= 0; k = cell_next(g, &it)) */
typedef struct eng_cell_it {
    const int32_t *sl;
    int j;     ///< next slot
    int32_t k; ///< next ball of the chain being walked (-1: none)
} eng_cell_it;

static inline int32_t cell_next(const eng_cells *g, eng_cell_it *it)
{
    if (it->k >= 0) {
        const int32_t k = it->k;
        it->k = g->next[k];
        return k;
    }
    while (it->j < ENG_CELL_CAP) {
        const int32_t v = it->sl[it->j++];
        if (v >= 0)
            return v;
        if (v < -1) {
            it->k = g->next[ENG_CHAIN_HEAD(v)];
            return ENG_CHAIN_HEAD(v);
        }
    }
    return -1;
}

static inline int32_t cell_first(const eng_cells *g, int32_t cell, eng_cell_it *it)
{
    it->sl = g->slot + (size_t)cell * ENG_CELL_CAP;
    it->j = 0;
    it->k = -1;
    return cell_next(g, it);
}

/// A broad-phase candidate of a contracted frame: bounding-sphere time, ball.
typedef struct eng_cand {
    double t;
    int32_t k;
} eng_cand;

/* Lanes of the neighbour tests, the cells' walk and the cell crossings (engine/lanes.h):
 * chosen once per engine from the CPU, narrower if rc_sim_def.simd asks (to compare the
 * paths: same bits). */
enum { ENG_SIMD_NONE = 0, ENG_SIMD_AVX2 = 2, ENG_SIMD_AVX512 = 3 };

/// A run's bookkeeping: what survives a re-planning and a checkpoint, copied whole; 8-byte fields only, so its bytes are its value.
typedef struct eng_books {
    double heat, heat_c;         ///< kinetic energy turned into heat (Kahan sum and compensation)
    double wall[3], wall_c[3];   ///< momentum the walls took, per axis
    double wallw[6], wallw_c[6]; ///< ... per wall w = 2 d + side, along e_d, contact by contact
    uint64_t wall_shared;        ///< groups touching both walls of an axis (rc_sim_diag.wall_shared)
    uint64_t pinned;             ///< wall contacts of a ball as wide as the box, made plastic
    double vir[9], vir_e[3];     ///< sum of r_a dp_b and r_a dE over events' members (engine/moments.c)
    double wrap[9], wrap_e[3];   ///< the same with r replaced by nearest image minus unwrapped separation
    uint64_t overlaps;           ///< contacts the overlap policy decided (eng_note_overlap)
    uint64_t overlap_kind[3];    ///< ... by kind: the event's own ball contact, a wall's, a group's other
    uint64_t collisions;         ///< contacts resolved
    uint64_t events[RC_SIM_EV_NKINDS]; ///< events by kind
    uint64_t max_group;          ///< most contacts resolved together
    uint64_t group_fallbacks;    ///< groups whose joint solve failed
    uint64_t group_sequential;   ///< groups resolved one contact at a time (no group solver)
    uint64_t tube_conflicts;     ///< per-ball frames: contacts on a tube's incoming piece left to the policy
    uint64_t order_conflicts;    ///< per-ball frames: kinks put at the previous one by the order rule
    uint64_t rollbacks;          ///< per-ball frames: collisions undone and solved again
    double still_t;              ///< the time of the last event ...
    uint64_t still_count;        ///< ... and how many came at it in a row (RC_ESTALL past the limit)
    int64_t stall_ball, stall_partner; ///< the stalled event's balls (caller's index; wall w as -1 - w; -2^62 none)
    double wall_q[6], wall_q_c[6];     ///< kinetic energy the balls gave wall w, contact by contact (engine/walls.c)
    double wall_pm[18], wall_pm_c[18]; ///< ... momentum, every component (3 w + axis)
    rc_rng rng;                        ///< the walls' random stream (rules that draw), seeded by def.wall_seed
} eng_books;
_Static_assert(sizeof(eng_books) == 8 * (2 + 6 + 12 + 1 + 1 + 24 + 1 + 3 + 1 + RC_SIM_EV_NKINDS + 3 + 2 + 1 + 4 + 12 + 36 + 1),
               "no padding in the bookkeeping");

/// The engine (relcol/sim.h's opaque rc_sim): plain arrays per ball, so a state can be written out and continued bit-identically.
struct rc_sim {
    rc_sim_def def;      ///< the definition it was made from
    int simd;            ///< lanes in use (ENG_SIMD_*)
    double inv_c2;       ///< 1 / c^2 (0 classically)
    double inv_c;        ///< sqrt(inv_c2): contracted shapes' beta = p inv_c / M
    double L[3];         ///< box edges
    int periodic;        ///< some axis is periodic
    double inv_L[3];     ///< 1 / L on a periodic axis, 0 on a walled one (eng_image needs no branch)
    unsigned walled;     ///< bit d: axis d < dim has walls (wall events only there)
    double now;          ///< the engine's time
    size_t n;            ///< balls
    eng_ball *b;         ///< per ball: hot line (position, velocity, own clock, radius)
    eng_aux *a;          ///< per ball: momentum, mass, scheduled event, cell
    eng_clock *clk;      ///< per ball: proper time
    uint32_t *id;        ///< caller's index of internal ball k
    uint32_t *slot;      ///< internal index of caller's ball i
    uint32_t *cnt;       ///< collisions per ball: an event naming a ball whose counter moved is stale (own array: read for every event)
    int32_t *img;        ///< periodic boxes (else NULL): three wrap counters per ball
    rc_vec3 *ev_n;       ///< contracted frames (else NULL): the frame's normal of each ball's scheduled event (NAN: overlap; eng_defer's mark: deferred)
    eng_perball *pb;     ///< the per-ball model's state (engine/perball_state.h); NULL in other frames
    struct eng_validity *val; ///< the validity report's kink clusters (engine/validity.c); NULL until its first hook
    int val_failed;      ///< the report once ran out of memory before it had a state
    struct eng_slice *slc; ///< delayed table-time slices asked for (engine/slice.c) ...
    size_t slc_n, slc_cap; ///< ... how many (0: no hook does more than test slc_n), room
    uint32_t slc_next_id;  ///< the next slice's id
    uint32_t *slc_dirty;   ///< per-ball frames: caller's indices of the balls whose lines changed in the event ...
    unsigned char *slc_mark; ///< ... listed (nonzero), brought up to date after it
    size_t slc_nd;         ///< ... how many
    double slc_due;        ///< other frames: the least table time of a slice not yet taken (INFINITY: none)
    double slc_gmax;       ///< per-ball frames: the largest Lorentz factor of a segment since the oldest slice was asked for
    double sc_tx, bx_tx;   ///< prediction scratch: the contact event's time of the pair last put to the frame, and of the best event so far ...
    rc_vec3 sc_dx, bx_dx;  ///< ... and its offset from the ball's centre then
    const struct eng_model_ops *model; ///< where balls change velocity: its properties and ops (engine/model.h)
    const struct eng_path_ops *path; ///< a ball's path between events: its ops (engine/path.h), chosen at creation
    int fld_axis;          ///< with a field: its axis
    int fld_err;           ///< with a field: a path op's failure met by a prediction, which the loop returns
    double fld_work[2];    ///< with a field: the energy change booked at contacts (Kahan sum, compensation)
    eng_queue q;           ///< the event queue
    eng_cells g;           ///< the cells
    rc_collision_params prm; ///< the law's parameters
    int narrow;            ///< the frame is called after the sphere test (contracted)
    int defer;             ///< ball events stored deferred (eng_defer)
    int table;             ///< the frame declares the table-frame shapes' direct solver (shapes): called directly, shape bounds used
    rc_toi_shapes_fn shapes; ///< that solver
    int wall_contracted;   ///< walls see the contracted support
    rc_toi_params toi;     ///< the frame's tolerances
    rc_toi_workspace *ws;  ///< the frame's workspace
    eng_cand *cand;        ///< broad-phase candidates (scratch) ...
    size_t cand_cap;       ///< ... room
    eng_books bk;          ///< what has happened so far
    uint64_t since_reorder; ///< collisions and crossings since the balls were last renumbered
    int32_t *grp_ball;     ///< group scratch: members (internal index) ...
    rc_particle *grp_part; ///< ... their states ...
    rc_contact *grp_con;   ///< ... contacts ...
    double *grp_j;         ///< ... the solver's impulses (grp_con_cap entries)
    size_t grp_ball_cap, grp_con_cap; ///< room
    const rc_wall_rule *wrule[6]; ///< each wall's rule (def's NULL: rc_wall_reflecting)
    int walls_rigid;       ///< every wall's rule is rigid (a group never needs the scan)
    double wev_q[6];       ///< the event's wall exchanges so far, booked by eng_finish ...
    rc_vec3 wev_p[6];
    unsigned wev_mask;     ///< ... the walls they touch (bit w)
};

/* A per-ball array of `bytes` (engine/mem.c): cache-line aligned, on transparent huge
 * pages where it spans some; NULL if out of memory. Released with free(). */
void *eng_alloc(size_t bytes);
/* The per-ball model's state for n balls (engine/perball/state.c): no kink, nothing to
 * undo; NULL if out of memory. Freed by eng_perball_free, which NULLs the pointer. */
eng_perball *eng_perball_alloc(size_t n);
void eng_perball_free(eng_perball **pb);

/* Allocate the state of n balls (engine/setup.c), replacing any held: per-ball arrays,
 * cells sized for the largest rest radius rmax, queue; bookkeeping cleared. */
int eng_alloc_state(rc_sim *s, size_t n, double rmax);
/* Ball i (storage slot) at the engine's time (engine/diag.c): truth != 0 the table-time
 * picture (per_ball frames: on the line it is still on where its kink lies ahead, as
 * eng_pend records it), 0 its stored line taken to now (the state hash's view). */
/// Returns rc_sim_kink_ahead's value (0 without truth).
int eng_ball_now(const rc_sim *s, size_t i, rc_sim_ball *o, int truth);
/// Release the balls' state (the engine then holds none).
void eng_release_state(rc_sim *s);

/* Ball i (storage slot) at table time t >= its stored time's last event (engine/diag.c),
 * as eng_ball_now at the engine's time: the kink-ahead test and the lines before kinks
 * ahead (truth) are taken at t. eng_ball_now is eng_ball_at at s->now. */
int eng_ball_at(const rc_sim *s, size_t i, double t, rc_sim_ball *o, int truth);

/* engine/slice.c: the delayed slices' hooks, called only where s->slc_n != 0. A kink was
 * put on ball k (storage slot) in the event being resolved (its line is read after it). */
void eng_slice_mark(rc_sim *s, int32_t k);
/// Ball k's last kink, at its stored time, was undone: it is on its incoming line again.
void eng_slice_undo(rc_sim *s, int32_t k);
/// After an event: the slices of the balls marked brought up to date.
void eng_slice_flush(rc_sim *s);
/// Other frames: the engine's next event comes at t_next > slc_due: take the slices due.
void eng_slice_take(rc_sim *s, double t_next);
/// Forget every slice (new balls, a new c, a checkpoint read, the engine freed).
void eng_slice_clear(rc_sim *s);
/// Bytes the slices held take.
size_t eng_slice_bytes(const rc_sim *s);

/// Velocity p / M and inverse Lorentz factor of a state.
static inline double eng_mass_rel(double m, rc_vec3 p, double inv_c2)
{
    return inv_c2 == 0.0 ? m : sqrt(m * m + rc_v3_norm2(p) * inv_c2);
}

/* Round to the nearest integer, ties to even (the default rounding mode), for
 * |y| < 2^51: the same two operations in the scalar code and in the lanes, so the same
 * bits (no libm call, no dependence on SSE4.1). */
static inline double eng_rint(double y)
{
    const double big = 0x1.8p52;
    return (y + big) - big;
}

/* The nearest image of a separation dx of two balls: dx - L round(dx / L) on the
 * periodic axes; on a walled one inv_L = 0 makes it dx - L * 0 = dx exactly (signed zeros
 * included), so no axis needs a branch. The copy two neighbours can meet: in their
 * current cells (eng_cross keeps stored positions there) they are less than two cells
 * apart along an axis, which is at most L / 2 with four cells or more; with three, two
 * balls 1.6 cells apart in adjacent cells would be nearer to the other copy (1.4 cells)
 * and could still meet before leaving their cells. */
static inline double eng_image1(double dx, double L, double inv_L)
{
    return dx - L * eng_rint(dx * inv_L);
}
static inline rc_vec3 eng_image(const rc_sim *s, rc_vec3 dx)
{
    if (!s->periodic)
        return dx;
    dx.x = eng_image1(dx.x, s->L[0], s->inv_L[0]);
    dx.y = eng_image1(dx.y, s->L[1], s->inv_L[1]);
    dx.z = eng_image1(dx.z, s->L[2], s->inv_L[2]);
    return dx;
}

/// Cell c[d] + o on axis d: wrapped on a periodic axis, -1 off the grid on a walled one.
static inline int cell_step(const eng_cells *g, int d, int c, int o)
{
    int k = c + o;
    if (k >= 0 && k < g->n[d])
        return k;
    if (!g->wrap[d])
        return -1;
    return k < 0 ? k + g->n[d] : k - g->n[d];
}

/* The cell at offset (ox, oy, oz) from cell coordinates c: wrapped on periodic axes, -1
 * off the grid (distinct cells for distinct offsets in -1..1: n >= 4 on a periodic axis). */
static inline int32_t cell_at(const eng_cells *g, const int c[3], int ox, int oy, int oz)
{
    const int x = cell_step(g, 0, c[0], ox), y = cell_step(g, 1, c[1], oy),
              z = cell_step(g, 2, c[2], oz);
    if (x < 0 || y < 0 || z < 0)
        return -1;
    return (int32_t)(x + g->n[0] * (y + g->n[1] * z));
}

/// Cell coordinates of a cell index.
static inline void cell_coords(const eng_cells *g, int32_t cell, int c[3])
{
    c[0] = cell % g->n[0];
    c[1] = (cell / g->n[0]) % g->n[1];
    c[2] = cell / (g->n[0] * g->n[1]);
}

/// Heap key of a ball: its earliest event, collision or cell crossing.
static inline double key_of(const eng_aux *a)
{
    return a->ev_t < a->cross_t ? a->ev_t : a->cross_t;
}

/* The table frame defers its root finds: a prediction stores, as its ball event,
 * the candidate with the least lower bound of contact (bounding spheres, centre line)
 * keyed by that bound, and a bound lb2 of every other event of the ball (ball or wall).
 * The frame is asked only when the bound comes up in the queue (eng_settle), and not
 * at all for the predictions that a collision elsewhere makes stale first, or that a
 * later prediction of the ball replaces.
 * Such an event's ev_n entry is (lb2, 0, +inf): a contact normal is never infinite. */
typedef struct eng_defer {
    int on;     ///< the best event so far is deferred: its time is a bound
    double lb2; ///< on: a lower bound of every other event
} eng_defer;

static inline rc_vec3 ev_deferred_mark(double lb2) { return rc_v3(lb2, 0.0, INFINITY); }
static inline int ev_is_deferred(rc_vec3 n) { return n.z == INFINITY; }

/// Predict ball i's earliest events from scratch (and update its heap entry if asked).
void eng_predict(rc_sim *s, int32_t i, int update_heap);
/// Ball i's deferred event has come up: ask the frame, store the event (queue updated).
void eng_settle(rc_sim *s, int32_t i);

/* What a contracted-frame prediction for a ball that has just collided (at T, its clock)
 * also looks for: another contact simultaneous with the one resolved -- as grow_group
 * judges it, on the states before the collision (old momentum, old velocity), the event's
 * own partner excepted. */
typedef struct eng_check {
    rc_particle old;
    rc_vec3 vold;
    int32_t partner;
    /* the ball's record at T before the collision when its stored one has moved to its
     * own kink (per_ball frames), else NULL: the stored one is at T */
    const eng_ball *at;
    /* per_ball frames at a contact of the model: the ball contacts simultaneous with it
     * are those of the group's ZMF, already looked for (eng_zmf_group), so only a wall
     * contact (the wall's frame is the table) is checked here */
    int zmf;
} eng_check;

/* Prediction for ball i just resolved at T (uncontracted frames / contracted ones), that
 * also looks for another contact simultaneous with the resolved one: 1 on one (nothing
 * stored), else the events are stored (the queue is not updated) and 0. */
int eng_predict_checked(rc_sim *s, int32_t i, const eng_check *chk, double T);
int eng_predict_checked_narrow(rc_sim *s, int32_t i, const eng_check *chk);
/// Ball i crosses into its next cell (events updated, queue too).
void eng_cross(rc_sim *s, int32_t i);
/// The contracted contact test of a simultaneity check (engine/predict.c).
int eng_narrow_conflict(rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                           double d2, const eng_check *chk, rc_vec3 *normal);
/* The event's transfer moments (eng_books.vir ...): members mem[0 .. nm) (internal
 * indices, all at the event's time) went from states before[] (NULL: their stored
 * states, s->a) to after[]. */
void eng_moments_add(rc_sim *s, size_t nm, const int32_t *mem, const rc_particle *before,
                     const rc_particle *after);
/* engine/walls.c: each wall's rule. Chosen from the definition (at create). */
void eng_walls_init(rc_sim *s);
/// Ball state *a meets wall w along outward normal n with restitution eps: its rule's op, the exchange noted for the event; RC_OK, RC_NO_COLLISION or the rule's failure.
int eng_wall_collide(rc_sim *s, int w, rc_particle *a, rc_vec3 n, double eps);
/// The event's noted wall exchanges into the books (eng_finish) ...
void eng_walls_book(rc_sim *s);
/// ... or forgotten (an event taken back or resolved again).
static inline void eng_walls_forget(rc_sim *s) { s->wev_mask = 0; }
/// Is one of contacts 0 .. nc with a wall whose rule is not rigid?
int eng_walls_soft_in(const rc_sim *s, size_t nc);

/// Support distance of ball i's shape along the wall normal e_d.
double eng_wall_support(const rc_sim *s, int32_t i, int d);

/* The validity report's hooks (engine/validity.c): a kink about to be placed on ball b
 * (storage slot), a contact resolved by the overlap policy, ball b about to be put back
 * by an undo. Each is one line at its point; none changes the run. */
typedef struct eng_validity eng_validity;
void eng_validity_kink(rc_sim *s, int32_t b);
void eng_validity_policy(rc_sim *s);
void eng_validity_undone(rc_sim *s, int32_t b);
void eng_validity_free(rc_sim *s);
/* the balls renumbered (engine/reorder.c): np old slot -> new, inv its inverse, done n zeroed bytes */
void eng_validity_reorder(rc_sim *s, const uint32_t *np, const uint32_t *inv, unsigned char *done);
/* checkpoint: the state as bytes (p NULL: only counted), and back (*used: bytes read) */
size_t eng_validity_bytes(const rc_sim *s, unsigned char *p);
int eng_validity_read(rc_sim *s, const unsigned char *q, size_t size, size_t *used);

#endif
