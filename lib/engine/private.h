/* engine/private.h — the engine's internal state, shared by the files of lib/engine/.
 * Everything that defines a run lives in plain arrays so that a state can be written out
 * and continued bit-identically (checkpoint.c). Functions shared between these files carry
 * the engine's one internal prefix, eng_, and are not exported from the library. */
#ifndef RELCOL_ENGINE_PRIVATE_H
#define RELCOL_ENGINE_PRIVATE_H

#include <stdint.h>
#include "relcol/sim.h"
#include "../glue_kv.h"

/* Hot data read by every pair test: one 64-byte line per ball. The state is stored at
 * the ball's own time t (its local clock); v = p / M is derived from p and m. */
typedef struct eng_ball {
    rc_vec3 x;
    rc_vec3 v;
    double t;
    double r;
} eng_ball;

/* No event. */
#define ENG_NONE INT32_MIN
/* ev_partner for wall w = 2 d + side (side 1 is the far wall x_d = L_d) */
#define ENG_WALL(w) (-1 - (w))
#define ENG_WALL_INDEX(code) (-1 - (code))

/* The rest of the state a prediction or a collision reads, and the ball's single
 * scheduled event: one 64-byte line per ball (allocated aligned). */
typedef struct eng_aux {
    rc_vec3 p;
    double m;
    double ev_t;      /* earliest collision (ball or wall) */
    double cross_t;   /* next cell crossing */
    int32_t ev_partner;
    uint32_t ev_pcount; /* partner's counter (rc_sim.cnt) when ev was computed */
    int32_t cell;
    int32_t cross_code; /* 2 d + (direction > 0), -1 none */
} eng_aux;

/* (aligned_alloc wants sizes that are multiples of the alignment) */
_Static_assert(sizeof(eng_ball) == 64 && sizeof(eng_aux) == 64, "one cache line per record");

/* Proper time, read and written only when the ball collides (or is read out). */
typedef struct eng_clock {
    double tau;      /* proper time at t */
    double tau_last; /* proper time of the last collision (-inf: none yet) */
} eng_clock;

/* A per_ball frame's glued world tubes (papers/shape-change.md), cold, one 64-byte line
 * per ball: the hyperplane H that began the ball's current segment, t - t_k = kappa.(y -
 * x_k), through its last kink (t_k, x_k) -- x_k its centre at t_k on the stored line, so
 * nothing here moves when the ball wraps or is advanced; t_k = -inf, kappa = 0 before its
 * first collision. A contact of the model lies on the future side of both balls' H. */
typedef struct eng_cov {
    double t_k;
    rc_vec3 kappa;
    /* the contact event X of the ball's scheduled ball event, as its prediction found it
     * (a collision reads it rather than asking the frame again, whose reference time
     * depends on now): its table time and X - (the ball's centre then on its stored line) */
    double ev_tx;
    rc_vec3 ev_dx;
} eng_cov;
_Static_assert(sizeof(eng_cov) == 64, "one cache line per record");

/* per_ball frames: what undoing a ball's last collision needs (papers/shape-change.md,
 * sections 7 and 8): a third ball that meets the ball's incoming piece, before its kink
 * along its tube, undoes the collision -- a single contact of the model, or a group an
 * earlier undo solved -- and the contacts are solved together. Every member of the
 * collision holds a record; valid while no member has collided since (the counters). The
 * collision's contacts form a tree over its members: each member but the first holds its
 * contact with the member it joined (its parent), the first its contact with a wall if
 * there is one. Balls by their caller's index, which renumbering does not change. */
#define ENG_UNDO_NMAX 8 /* members of a collision that can be undone (bounds the work) */
#define ENG_ROOT (INT32_MIN + 1) /* partner: the first member, without a wall contact */
typedef struct eng_undo {
    rc_particle in;     /* the ball's state before */
    eng_cov cov;        /* its hyperplane before (and its scheduled event's X, unused) */
    rc_glue glu;        /* its glued tube before */
    double tau_last;    /* its clock's last collision before */
    rc_vec3 n;          /* the contact normal, from the ball to its partner */
    double dt;          /* the contact event X - the ball's kink E: time ... */
    rc_vec3 dx;         /* ... and position (E on both the incoming and the outgoing line) */
    int32_t partner;    /* its parent (caller's index), ENG_WALL(w), ENG_ROOT, or ENG_NONE:
                           no record */
    uint32_t nm;        /* the collision's members ... */
    int32_t mem[ENG_UNDO_NMAX];  /* ... by caller's index, in the order its books took them */
    uint32_t mcnt[ENG_UNDO_NMAX]; /* their counters after it */
    uint32_t kind;      /* its event kind (RC_SIM_EV_BALL, _WALL or _MULTI) ... */
    uint32_t ntc;       /* ... and the TC contacts it counted (rc_sim_diag) */
    uint32_t npol;      /* its contacts the overlap policy decided (counted once, when
                           decided: undone and solved again they stay counted) */
} eng_undo;
/* per_ball frames: where a ball's kinks lie after the engine's time. The engine stores a
 * ball at its latest kink on its outgoing line, which may lie ahead of now; the table-time
 * picture at now (rc_sim_get_ball) needs the line the ball is still on. Written after each
 * event for its own balls (engine/pending.c, eng_pend_note), read only by the read-out
 * (engine/diag.c), so nothing here changes a run. depth 0: none (the ball's kinks were at
 * or before the event that made them). depth >= 1: the ball moves on the line with
 * momentum l[0].p and rest mass l[0].m until its kink at table time l[0].t, at centre x
 * (in the wrap coordinates img, periodic boxes), where its proper time is tau; its TC
 * memory before it is tau_last (-inf: no collision); then on line k (l[k].p, l[k].m)
 * from kink l[k - 1].t until kink l[k].t, k < depth. Where the latest kink (eng_cov.t_k)
 * lies beyond the last recorded end l[depth - 1].t, the lines in between were not recorded (more than
 * ENG_PEND_LINES kinks ahead of now at once, or a chain the record lost): the read-out
 * says so (rc_sim_kink_ahead = 2). Dense hot gases put several kinks ahead of a ball
 * within a glue window: two lines made the delayed slice at packing 0.2 fail. */
#define ENG_PEND_LINES 6
typedef struct eng_pend_line {
    double t;  /* its kink's table time */
    double m;  /* the line's rest mass ... */
    rc_vec3 p; /* ... and momentum */
} eng_pend_line;
typedef struct eng_pend {
    /* (what every event's note reads first, then the lines: a record of one line, the
     * common case, lies in its first two cache lines, as the two-line record did) */
    int32_t depth;
    int32_t img[3];
    rc_vec3 x;
    double tau;
    double tau_last;
    eng_pend_line l[ENG_PEND_LINES];
    double pad[3];
} eng_pend;
_Static_assert(sizeof(eng_pend) % 64 == 0, "whole cache lines per record");

/* 1 - kappa.v for the hyperplane c that began a ball's segment and its velocity v on it:
 * for a ball fast before and after that kink the same way ~1/gamma^2, which the plain
 * difference loses to the rounding of its terms; then from the kink's tube's shapes
 * (glue_kv.h rc_glue_omkv_out), when g is that tube (r > 0: not an order conflict's) and
 * v its outgoing velocity, bit for bit. */
static inline double eng_seg_den(const eng_cov *c, const rc_glue *g, rc_vec3 v)
{
    const double kv = rc_v3_dot(c->kappa, v);
    if (!(kv > RC_GLUE_KV_FAST) || !(g->r > 0.0) || g->v_out.x != v.x || g->v_out.y != v.y ||
        g->v_out.z != v.z)
        return 1.0 - kv;
    return rc_glue_omkv_out(&g->in, &g->out);
}

/* Is the event X (table time tx, offset dxb from the ball's centre then on its stored
 * line, velocity v) on the future side of the hyperplane c that began its segment,
 * t - t_k = kappa.(y - x_k)? With x_k on the stored line, X - x_k = dxb + v (tx - t_k), so
 * the test reads (tx - t_k)(1 - kappa.v) >= kappa.dxb (1 - kappa.v > 0: |kappa| < 1/c).
 * No kink yet: t_k = -inf, always true. g: the ball's tube of that kink (s->glu). */
static inline int eng_glue_side(const eng_cov *c, const rc_glue *g, rc_vec3 v, double tx,
                                rc_vec3 dxb)
{
    return (tx - c->t_k) * eng_seg_den(c, g, v) >= rc_v3_dot(c->kappa, dxb);
}

/* The event queue (engine/queue.c): one entry per ball, popped in (time, ball) order.
 * (Functions shared between the engine files carry eng_: exported, not public.) */
typedef struct eng_qent {
    double key;   /* the ball's entry's time */
    int32_t next; /* links of the bucket list it is in, or its heap position (engine/queue.c) */
    int32_t prev;
} eng_qent;

/* A ball's key, links and heap place on one 16-byte entry: an update reads and writes one
 * line instead of four arrays' (at N = 1e5 they come from L3). */
_Static_assert(sizeof(eng_qent) == 16, "four entries a cache line");

typedef struct eng_queue {
    size_t n;
    eng_qent *e;          /* per ball */
    uint32_t *heap;       /* the bucket being drained: a binary heap (capacity n) */
    size_t hn;
    int32_t *head;        /* nb calendar lists, then overflow, then never */
    uint32_t nb;          /* buckets in the span, a power of two */
    double inv_w;         /* 1 / bucket width */
    int64_t cur;          /* number of the bucket being drained */
    int64_t redist;       /* end of the span: buckets from here on wait in the overflow
                             list, spread again when cur reaches it */
    size_t in_cal;        /* entries in the calendar lists */
    double over_min;      /* at most the least key in the overflow list (keys filed there
                             since it was last spread; INFINITY: none) */
    int32_t ahead;        /* the entry of the next bucket's list to fetch ahead (-1: none) */
} eng_queue;

/* Allocate for n balls; then eng_queue_build with every ball's key. */
int eng_queue_init(eng_queue *q, size_t n);
void eng_queue_free(eng_queue *q);
/* Refile every ball under keys[] (all >= now), choosing the bucket width afresh. */
void eng_queue_build(eng_queue *q, const double *keys, double now);
/* The same with the keys already in q->e[i].key. */
void eng_queue_rebuild(eng_queue *q, double now);
/* engine/reorder.c: the balls renumbered in cell order, every per-ball array with them
 * (the event loop calls it every ENG_REORDER_EVERY x N collisions and cell crossings) */
#define ENG_REORDER_EVERY 4
void eng_reorder(rc_sim *s);
/* Change ball's key (>= the time last popped). */
void eng_queue_update(eng_queue *q, uint32_t ball, double t);
/* The earliest entry (time, ball); 0 if the queue is empty. */
int eng_queue_top(eng_queue *q, double *t, uint32_t *ball);
size_t eng_queue_bytes(const eng_queue *q);
/* The ball likely to come after the top (the earlier child of the heap's root), -1 if
 * the heap holds no other: a hint for prefetching, not a promise of order. (Looking into
 * the next calendar lists as well names the next ball more often, but gained nothing
 * measurable: papers/relcol.md, section 7.) */
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
    double w[3];      /* cell edge per dimension */
    double inv_w[3];
    int32_t *slot;    /* ENG_CELL_CAP per cell */
    int32_t *next;    /* per ball: next of its overflow chain (-1: the end) */
    size_t ncells;
    int32_t block_rows[9]; /* a full 3^d block's rows, as slot offsets from its first */
    int wrap[3];      /* periodic axis: the cells wrap around (n >= 4) */
    /* a ball in cell c[d] moving up crosses a face if c[d] < up_lim[d] (n - 1 walled, n
     * periodic), moving down if c[d] > dn_lim[d] (0 walled, -1 periodic) */
    int up_lim[3], dn_lim[3];
} eng_cells;

/* periodic[d] != 0: axis d wraps, and gets at least four cells if min_edge allows (the
 * caller checks n[d] >= 4: eng_image). */
int eng_cells_init(eng_cells *g, int dim, rc_vec3 box, double min_edge, size_t nballs,
                      const int periodic[3]);
void eng_cells_free(eng_cells *g);
/* Every cell empty again. */
void eng_cells_clear(eng_cells *g);
/* rank[cell] (ncells entries): the cell's place in Z order, the order balls are
 * numbered in. */
void eng_cells_zorder(const eng_cells *g, int32_t *rank);
/* pos[i]: ball i's number in that order, from its cell cell[i] (stable). */
int eng_cells_number(const eng_cells *g, const int32_t *cell, size_t n, uint32_t *pos);
int32_t eng_cells_index_of(const eng_cells *g, int dim, rc_vec3 x);
void eng_cells_insert(eng_cells *g, eng_aux *a, int32_t i, int32_t cell);
void eng_cells_remove(eng_cells *g, const eng_aux *a, int32_t i);

/* The balls of one cell, in slot order, a chain where it stands:
 *   for (int32_t k = cell_first(g, cell, &it); k >= 0; k = cell_next(g, &it)) */
typedef struct eng_cell_it {
    const int32_t *sl;
    int j;     /* next slot */
    int32_t k; /* next ball of the chain being walked (-1: none) */
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

/* A broad-phase candidate of a contracted frame: bounding-sphere time, ball. */
typedef struct eng_cand {
    double t;
    int32_t k;
} eng_cand;

/* Lanes of the neighbour tests, the cells' walk and the cell crossings (engine/lanes.h):
 * chosen once per engine from the CPU, narrower if rc_sim_def.simd asks (to compare the
 * paths: same bits). */
enum { ENG_SIMD_NONE = 0, ENG_SIMD_AVX2 = 2, ENG_SIMD_AVX512 = 3 };

/* A run's bookkeeping: conservation sums (Kahan-compensated) and event counts. One struct,
 * so that everything that must survive a re-planning or a checkpoint is copied whole and
 * a counter added here cannot be forgotten there. All fields are 8-byte doubles and
 * counters: no padding, so its bytes are its value. */
typedef struct eng_books {
    double heat, heat_c;
    double wall[3], wall_c[3];
    /* per wall (index 2 d + side, side 1 the far wall x_d = L_d): the momentum along e_d
     * it has taken, attributed contact by contact (rc_sim_diag.wall_impulse_by_wall) */
    double wallw[6], wallw_c[6];
    uint64_t wall_shared;
    uint64_t pinned; /* wall contacts of a ball as wide as the box, made plastic */
    /* the momentum and energy that collisions carry across space (engine/moments.c):
     * sum over events of r_a dp_b (row a, column b) and r_a dE over the members, r the
     * member's centre relative to the event's first ball (nearest image); and the same
     * with r replaced by nearest image minus unwrapped separation (periodic axes only:
     * multiples of L), which turns the balls' unwrapped moments into Helfand moments.
     * Plain sums: their rounding is far below any statistical error they feed. */
    double vir[9], vir_e[3], wrap[9], wrap_e[3];
    uint64_t overlaps;
    uint64_t overlap_kind[3]; /* overlaps by the kind of contact: ball, wall, group */
    uint64_t collisions;
    uint64_t events[RC_SIM_EV_NKINDS];
    uint64_t max_group;
    uint64_t group_fallbacks;
    uint64_t group_sequential;
    /* per_ball frames: predicted contacts on the incoming side of a ball's last hyperplane
     * (the incoming piece of a glued tube: resolved by the overlap policy, counted in
     * overlaps too), and kinks that would have come before the ball's previous one along
     * its worldline (put at the previous one) */
    uint64_t tube_conflicts, order_conflicts;
    /* tube conflicts resolved by undoing a ball's last collision and solving the two
     * contacts together (eng_undo), not by the overlap policy (not in tube_conflicts) */
    uint64_t rollbacks;
    /* ... of which undid a chain: a member's later collision first (engine/undo.c;
     * read by the tests, not in rc_sim_diag) */
    uint64_t chain_rollbacks;
    /* ... and that undid an overlap-policy decision, or were a wall's tube conflict
     * (engine/undo.c; read by the tests) */
    uint64_t policy_rollbacks, wall_rollbacks;
    /* the chains (chain_rollbacks) that took back more than a chain of two: several
     * members' later collisions, a later member's later one, or the other ball's own
     * (engine/undo.c; read by the tests) */
    uint64_t wide_chains;
    /* the undos that took back the ball's own previous collision too: the contact from
     * the line before its last kink lay before its previous kink as well (engine/undo.c;
     * read by the tests) */
    uint64_t deep_rollbacks;
    /* the groups with a cycle of contacts undone (their root's record holds the contact
     * beyond a tree: engine/undo.c; read by the tests) */
    uint64_t cycle_rollbacks;
    /* the chains whose ball and partner were in contact in them already, solved again
     * with no new contact (engine/undo.c; read by the tests) */
    uint64_t rejoins;
    /* the undos of both balls' last collisions that took back a chain too: a member of
     * either had collided since (engine/undo.c; read by the tests) */
    uint64_t both_chains;
    /* progress: the time of the last event and how many events in a row came at it; when
     * that count passes eng_stall_limit the run stops (RC_ESTALL), naming the event's
     * balls (caller's index; a wall w as -1 - w; -2^62 none) */
    double still_t;
    uint64_t still_count;
    int64_t stall_ball, stall_partner;
} eng_books;
_Static_assert(sizeof(eng_books) == 8 * (2 + 6 + 12 + 1 + 1 + 24 + 1 + 3 + 1 + RC_SIM_EV_NKINDS + 3 + 2 + 2 + 11),
               "no padding in the bookkeeping");

/* per_ball frames: one answer of rc_glue_toi2 as windows_contact asked it: the two tubes
 * (in its orientation, the second moved into the first's coordinates) and the time, and
 * what came back. A pair with both balls in their windows is asked the same question by
 * each of its balls, one after the other (in a dense gas a sixth to a third of the
 * questions repeat one of the last few); an answer is a function of these bits alone, so
 * the kept one is the same bits. */
#define ENG_T2_MEMO 16
typedef struct eng_t2_memo {
    rc_glue g0, g1;
    double t1;
    int st, p0, p1;
    double t;
    rc_vec3 y, n;
} eng_t2_memo;

struct rc_sim {
    rc_sim_def def;
    int simd;
    double inv_c2;
    double inv_c; /* sqrt(inv_c2): contracted shapes' beta = p inv_c / M */
    double L[3];
    /* periodic boundaries: periodic != 0 if any axis is; inv_L[d] = 1 / L[d] on a periodic
     * axis, 0 on a walled one (eng_image: the same expression is then exactly dx);
     * walled: bit d set for a walled axis d < dim (wall events only there) */
    int periodic;
    double inv_L[3];
    unsigned walled;
    double now;
    size_t n;
    eng_ball *b;
    eng_aux *a;
    eng_clock *clk;
    uint32_t *id;   /* caller's index of internal ball k */
    uint32_t *slot; /* internal index of caller's ball i */
    /* collisions per ball so far: an event naming a ball whose counter moved is stale.
     * Its own compact array: read for every popped event, it stays in cache. */
    uint32_t *cnt;
    /* periodic boxes only (else NULL): per ball, three wrap counters (rc_sim_ball.image);
     * cold, read and written only when the ball wraps or is read out */
    int32_t *img;
    /* contracted frames only (else NULL): per ball, the frame's contact normal of its
     * scheduled ball event, from the same call that predicted the event's time (NAN: the
     * frame found the shapes overlapping), so that resolving the event need not ask the
     * frame again */
    rc_vec3 *ev_n;
    /* per_ball frames only (else NULL): per ball, its glued tube's last hyperplane */
    eng_cov *cov;
    /* per_ball frames only (else NULL): per ball, the glued tube of its last kink in
     * coordinates with the contact event at the origin (rc_glue_make), for a neighbour's
     * contact while the ball is in its window; r = 0: none (no kink yet, or one put at
     * the previous kink by the order rule) */
    rc_glue *glu;
    /* per_ball frames only (else NULL): per ball, how to undo its last collision ... */
    eng_undo *und;
    /* ... and the one before (the record und held before the last was written), so that a
     * collision whose member has collided once since can be undone after that later one
     * (a chain, engine/undo.c) */
    eng_undo *undp;
    /* scratch of one conflict's undo attempts (engine/undo.c): the ball whose contact from
     * its line before its last kink was found before its previous kink too, or -1 */
    int32_t undo_before;
    /* per_ball frames only (else NULL): per ball, the lines before its kinks ahead of now */
    eng_pend *pend;
    /* delayed table-time slices asked for (engine/slice.c; none: slc_n = 0, and no hook
     * does more than test slc_n) */
    struct eng_slice *slc;
    size_t slc_n, slc_cap;
    uint32_t slc_next_id;
    /* per_ball frames: caller's indices of the balls whose lines changed in the event
     * being resolved (slc_mark[i] != 0: listed), brought up to date after it */
    uint32_t *slc_dirty;
    unsigned char *slc_mark;
    size_t slc_nd;
    /* other frames: the least table time of a slice not yet taken (INFINITY: none) */
    double slc_due;
    /* per_ball frames: the largest Lorentz factor of any segment since the oldest slice
     * was asked for (the reach of later events: slice.c) */
    double slc_gmax;
    /* per_ball frames: scratch of the prediction -- the contact event of the pair last
     * put to the frame (pair_time_dx) and of the best event so far (scan_block_narrow),
     * as eng_cov.ev_tx / ev_dx */
    double sc_tx, bx_tx;
    rc_vec3 sc_dx, bx_dx;
    /* the per-ball kinks are in force: cov != NULL and c finite (with 1/c^2 = 0 every kink
     * is its contact event, kappa = 0, and the one-instant path is that model exactly) */
    int glue;
    eng_queue q;
    eng_cells g;
    rc_collision_params prm;
    /* contact geometry: narrow != 0 calls def.frame after the sphere test */
    int narrow;
    /* the frame's ball events are stored deferred (eng_defer): frame->deferrable */
    int defer;
    /* the frame's contact is the table-frame shapes' (frame->shapes declared): the engine
     * calls shapes directly and uses the table-frame shape bounds */
    int table;
    rc_toi_shapes_fn shapes;
    int wall_contracted;
    rc_toi_params toi;
    rc_toi_workspace *ws;
    eng_cand *cand;
    size_t cand_cap;
    /* what has happened so far, carried whole through a re-planning (rc_sim_sync) and a
     * checkpoint: the diagnostics continue */
    eng_books bk;
    uint64_t since_reorder; /* collisions and crossings since the balls were last renumbered */
    /* scratch for contact groups */
    int32_t *grp_ball;
    rc_particle *grp_part;
    rc_contact *grp_con;
    double *grp_j; /* the group solver's impulses, grp_con_cap entries */
    size_t grp_ball_cap, grp_con_cap;
    /* per_ball frames: the last answers of the two glued tubes' contact (engine/glue_pair.h
     * windows_contact), by their whole input */
    eng_t2_memo t2m[ENG_T2_MEMO];
    uint32_t t2m_n, t2m_next;
    /* per_ball frames: the validity report's kink clusters (engine/validity.c; NULL until
     * the first hook), and whether it once ran out of memory before it had a state */
    struct eng_validity *val;
    int val_failed;
};

/* A per-ball array of `bytes` (engine/mem.c): cache-line aligned, on transparent huge
 * pages where it spans some; NULL if out of memory. Released with free(). */
void *eng_alloc(size_t bytes);

/* Allocate the state of n balls (engine/setup.c), replacing any held: per-ball arrays,
 * cells sized for the largest rest radius rmax, queue; bookkeeping cleared. */
int eng_alloc_state(rc_sim *s, size_t n, double rmax);
/* Ball i (storage slot) at the engine's time (engine/diag.c): truth != 0 the table-time
 * picture (per_ball frames: on the line it is still on where its kink lies ahead, as
 * eng_pend records it), 0 its stored line taken to now (the state hash's view). */
/* Returns rc_sim_kink_ahead's value (0 without truth). */
int eng_ball_now(const rc_sim *s, size_t i, rc_sim_ball *o, int truth);
/* Release the balls' state (the engine then holds none). */
void eng_release_state(rc_sim *s);

/* Ball i (storage slot) at table time t >= its stored time's last event (engine/diag.c),
 * as eng_ball_now at the engine's time: the kink-ahead test and the lines before kinks
 * ahead (truth) are taken at t. eng_ball_now is eng_ball_at at s->now. */
int eng_ball_at(const rc_sim *s, size_t i, double t, rc_sim_ball *o, int truth);

/* engine/slice.c: the delayed slices' hooks, called only where s->slc_n != 0. A kink was
 * put on ball k (storage slot) in the event being resolved (its line is read after it). */
void eng_slice_mark(rc_sim *s, int32_t k);
/* Ball k's last kink, at its stored time, was undone: it is on its incoming line again. */
void eng_slice_undo(rc_sim *s, int32_t k);
/* After an event: the slices of the balls marked brought up to date. */
void eng_slice_flush(rc_sim *s);
/* Other frames: the engine's next event comes at t_next > slc_due: take the slices due. */
void eng_slice_take(rc_sim *s, double t_next);
/* Forget every slice (new balls, a new c, a checkpoint read, the engine freed). */
void eng_slice_clear(rc_sim *s);
/* Bytes the slices held take. */
size_t eng_slice_bytes(const rc_sim *s);

/* Velocity p / M and inverse Lorentz factor of a state. */
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

/* Cell c[d] + o on axis d: wrapped on a periodic axis, -1 off the grid on a walled one. */
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

/* Cell coordinates of a cell index. */
static inline void cell_coords(const eng_cells *g, int32_t cell, int c[3])
{
    c[0] = cell % g->n[0];
    c[1] = (cell / g->n[0]) % g->n[1];
    c[2] = cell / (g->n[0] * g->n[1]);
}

/* Heap key of a ball: its earliest event, collision or cell crossing. */
static inline double key_of(const eng_aux *a)
{
    return a->ev_t < a->cross_t ? a->ev_t : a->cross_t;
}

/* The table frame defers its root finds: a prediction stores, as its ball event,
 * the candidate with the least lower bound of contact (bounding spheres, centre line)
 * keyed by that bound, and a bound lb2 of every other event of the ball (ball or wall).
 * The frame is asked only when the bound comes up in the queue (eng_settle), and not
 * at all for the predictions that a collision elsewhere makes stale first, or that a
 * later prediction of the ball replaces (papers/relcol.md, section 7, has the count).
 * Such an event's ev_n entry is (lb2, 0, +inf): a contact normal is never infinite. */
typedef struct eng_defer {
    int on;     /* the best event so far is deferred: its time is a bound */
    double lb2; /* on: a lower bound of every other event */
} eng_defer;

static inline rc_vec3 ev_deferred_mark(double lb2) { return rc_v3(lb2, 0.0, INFINITY); }
static inline int ev_is_deferred(rc_vec3 n) { return n.z == INFINITY; }

/* Predict ball i's earliest events from scratch (and update its heap entry if asked). */
void eng_predict(rc_sim *s, int32_t i, int update_heap);
/* Ball i's deferred event has come up: ask the frame, store the event (queue updated). */
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
/* Ball i crosses into its next cell (events updated, queue too). */
void eng_cross(rc_sim *s, int32_t i);
/* per_ball frames: the frame's contact of a and b from their stored lines at t0, if one
 * of the model (engine/predict.c); ENG_BEFORE_A (not an RC_ code) when the frame's
 * contact lies on the incoming side of a's last hyperplane. */
#define ENG_BEFORE_A 100 /* (above every informational rc_status) */
int eng_pair_contact(rc_sim *s, int32_t a, int32_t b, double t0, double *tx, rc_vec3 *dx,
                     rc_vec3 *n);
/* The contracted contact test of a simultaneity check (engine/predict.c). */
int eng_narrow_conflict(rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                           double d2, const eng_check *chk, rc_vec3 *normal);
/* The event's transfer moments (eng_books.vir ...): members mem[0 .. nm) (internal
 * indices, all at the event's time) went from states before[] (NULL: their stored
 * states, s->a) to after[]. */
void eng_moments_add(rc_sim *s, size_t nm, const int32_t *mem, const rc_particle *before,
                     const rc_particle *after);
/* Support distance of ball i's shape along the wall normal e_d. */
double eng_wall_support(const rc_sim *s, int32_t i, int d);

/* The validity report's hooks (engine/validity.c): a kink about to be placed on ball b
 * (storage slot), a contact resolved by the overlap policy, ball b about to be put back
 * by an undo. Each is one line at its point; none changes the run. */
typedef struct eng_validity eng_validity;
void eng_validity_kink(rc_sim *s, int32_t b);
void eng_validity_policy(rc_sim *s);
void eng_validity_undone(rc_sim *s, int32_t b);
void eng_validity_free(rc_sim *s);
/* checkpoint: the state as bytes (p NULL: only counted), and back (*used: bytes read) */
size_t eng_validity_bytes(const rc_sim *s, unsigned char *p);
int eng_validity_read(rc_sim *s, const unsigned char *q, size_t size, size_t *used);

#endif
