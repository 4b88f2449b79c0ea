/* engine_private.h — the engine's internal state, shared by engine_*.c, queue_heap.c and
 * cells_grid.c. Everything that defines a run lives in plain arrays so that a state can
 * later be written out and continued bit-identically. */
#ifndef RELCOL_ENGINE_PRIVATE_H
#define RELCOL_ENGINE_PRIVATE_H

#include <stdint.h>
#include "relcol/sim.h"

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

/* Cold data: the dynamical state beyond x, v and the ball's single scheduled event. */
typedef struct eng_aux {
    rc_vec3 p;
    double m;
    double tau;       /* proper time at t */
    double tau_last;  /* proper time of the last collision (-inf: none yet) */
    double ev_t;      /* earliest collision (ball or wall) */
    double cross_t;   /* next cell crossing */
    int32_t ev_partner;
    uint32_t ev_pcount; /* partner's counter (rc_sim.cnt) when ev was computed */
    int32_t cell, prev;
    int32_t cross_code; /* 2 d + (direction > 0), -1 none */
    int32_t pad_;
} eng_aux;

/* Indexed 4-ary heap of (time, ball), one entry per ball; ties by ball index.
 * (Functions shared between the engine files carry rc_eng_: exported, not public.) */
typedef struct eng_heap_entry {
    double t;
    uint32_t ball;
    uint32_t pad_;
} eng_heap_entry;

typedef struct eng_heap {
    eng_heap_entry *h;
    uint32_t *pos;
    size_t n;
    eng_heap_entry *mem; /* the allocation h points into (h is offset so siblings share a line) */
} eng_heap;

/* Allocate for n balls; then rc_eng_heap_build with every ball's key. */
int rc_eng_heap_init(eng_heap *q, size_t n);
void rc_eng_heap_free(eng_heap *q);
void rc_eng_heap_build(eng_heap *q, const double *keys);
/* Change ball's key and restore heap order (up or down). */
void rc_eng_heap_update(eng_heap *q, uint32_t ball, double t);

/* Uniform cell grid over the box, doubly linked lists per cell. */
typedef struct eng_cells {
    int n[3];
    double w[3];      /* cell edge per dimension */
    double inv_w[3];
    int32_t *head;
    int32_t *next;    /* per ball: next ball of its cell (compact: read by every scan) */
    size_t ncells;
} eng_cells;

int rc_eng_cells_init(eng_cells *g, int dim, rc_vec3 box, double min_edge, size_t nballs);
void rc_eng_cells_free(eng_cells *g);
int32_t rc_eng_cells_index_of(const eng_cells *g, int dim, rc_vec3 x);
void rc_eng_cells_insert(eng_cells *g, eng_aux *a, int32_t i, int32_t cell);
void rc_eng_cells_remove(eng_cells *g, eng_aux *a, int32_t i);

/* A broad-phase candidate of a contracted frame: bounding-sphere time, ball. */
typedef struct eng_cand {
    double t;
    int32_t k;
} eng_cand;

/* Lanes of the neighbour test (engine_pairs.h): chosen once per engine from the CPU, or
 * from RELCOL_SIMD=scalar|sse2|avx2 in the environment (to compare the paths: same bits). */
enum { ENG_SIMD_NONE = 0, ENG_SIMD_SSE2 = 1, ENG_SIMD_AVX2 = 2 };

struct rc_sim {
    rc_sim_def def;
    int simd;
    double inv_c2;
    double L[3];
    double now;
    size_t n;
    eng_ball *b;
    eng_aux *a;
    uint32_t *id;   /* caller's index of internal ball k */
    uint32_t *slot; /* internal index of caller's ball i */
    /* collisions per ball so far: an event naming a ball whose counter moved is stale.
     * Its own compact array: read for every popped event, it stays in cache. */
    uint32_t *cnt;
    eng_heap q;
    eng_cells g;
    rc_collision_params prm;
    /* contact geometry: narrow != 0 calls def.frame after the sphere test */
    int narrow;
    int wall_contracted;
    rc_toi_params toi;
    rc_toi_workspace *ws;
    eng_cand *cand;
    size_t cand_cap;
    /* conservation bookkeeping (Kahan-compensated sums) */
    double heat, heat_c;
    double wall[3], wall_c[3];
    uint64_t overlaps;
    uint64_t collisions;
    uint64_t events[RC_SIM_EV_NKINDS];
    size_t max_group;
    uint64_t group_fallbacks;
    uint64_t since_reorder; /* events since the balls were last renumbered */
    /* scratch for contact groups */
    int32_t *grp_ball;
    rc_particle *grp_part;
    rc_contact *grp_con;
    size_t grp_ball_cap, grp_con_cap;
};

/* Velocity p / M and inverse Lorentz factor of a state. */
static inline double eng_mass_rel(double m, rc_vec3 p, double inv_c2)
{
    return inv_c2 == 0.0 ? m : sqrt(m * m + rc_v3_norm2(p) * inv_c2);
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

/* Predict ball i's earliest events from scratch (and update its heap entry if asked). */
void rc_eng_predict(rc_sim *s, int32_t i, int update_heap);

#endif
