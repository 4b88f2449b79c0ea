/* engine/walk.h — gathering the balls of a block of cells (the 3^d cells around a ball,
 * or the slab a crossing brings into reach) for a neighbour scan: row by row of the block,
 * each row's slots read together (engine/private.h: ENG_CELL_CAP slots a cell, rows of
 * cells adjacent in memory), empty slots and the scanning ball dropped, by the engine's
 * lanes (engine/kernels.h: a compress of a row's eight slots, or slot by slot -- the same
 * indices in the same order either way). Overflow chains, rare, are walked after the
 * rows. Included by engine/predict.c and the lanes' kernels. */
#ifndef RELCOL_ENGINE_WALK_H
#define RELCOL_ENGINE_WALK_H

#include <stdint.h>

#include "lanes.h"
#include "private.h"

/* Neighbours gathered per chunk (a stack buffer; a block's rows always fit in one chunk,
 * only long overflow chains need more). Buffers hold NB_CAP: room for the compress to
 * store eight past the end, and for the padding of eight past it (the prefetch's and the
 * lanes'). */
#define GATHER_MAX 128
#define NB_CAP (GATHER_MAX + 8)

typedef struct eng_walk {
    const rc_sim *s;
    int32_t row[27];   /* first slot of each row of the block (a row wrapped around a
                          periodic x axis: one row a cell) */
    int nrows, nslots; /* rows; slots a row */
    int32_t chain[27]; /* first balls of the overflow chains met in the rows */
    int nchain, ci;    /* chains; the one being walked */
    int32_t k;         /* its next ball (-1: its first) */
    int32_t skip;      /* the scanning ball */
    /* its pairs need the nearest image: only a block that wraps (elsewhere neighbours in
     * their cells are less than L / 2 apart, where eng_image is exactly the identity) */
    int image;
    int rows_done, done;
} eng_walk;

/* The block of a walk that wraps around a periodic axis (walk_init): rows and planes
 * taken through cell_step; a row that wraps in x is cut into its cells, each a row of
 * its own (only blocks at a periodic face come here: the others are walk_init's). */
static inline void walk_init_wrapped(eng_walk *w, const rc_sim *s, int32_t skip,
                                     const int c[3], const int lo[3], const int hi[3])
{
    const eng_cells *g = &s->g;
    const int xwrap = g->wrap[0] && (c[0] + lo[0] < 0 || c[0] + hi[0] >= g->n[0]);
    const int x0 = c[0] + lo[0] > 0 ? c[0] + lo[0] : 0;
    const int x1 = c[0] + hi[0] < g->n[0] ? c[0] + hi[0] : g->n[0] - 1;
    w->s = s;
    w->skip = skip;
    w->image = 1;
    w->nrows = 0;
    w->nslots = xwrap ? ENG_CELL_CAP : (x1 - x0 + 1) * ENG_CELL_CAP;
    for (int oz = lo[2]; oz <= hi[2] && w->nslots > 0; oz++) {
        const int z = cell_step(g, 2, c[2], oz);
        for (int oy = lo[1]; oy <= hi[1] && z >= 0; oy++) {
            const int y = cell_step(g, 1, c[1], oy);
            if (y < 0)
                continue;
            const int32_t row = g->n[0] * (y + g->n[1] * z) * ENG_CELL_CAP;
            if (!xwrap) {
                w->row[w->nrows++] = row + x0 * ENG_CELL_CAP;
                continue;
            }
            for (int ox = lo[0]; ox <= hi[0]; ox++)
                w->row[w->nrows++] = row + cell_step(g, 0, c[0], ox) * ENG_CELL_CAP;
        }
    }
    w->nchain = w->ci = 0;
    w->k = -1;
    w->rows_done = w->done = 0;
}

/* Does the block at offsets lo..hi around c reach past a periodic face? */
static inline int walk_wraps(const eng_cells *g, const int c[3], const int lo[3],
                             const int hi[3])
{
    int out = 0;
    for (int d = 0; d < 3; d++)
        out |= g->wrap[d] & ((c[d] + lo[d] < 0) | (c[d] + hi[d] >= g->n[d]));
    return out;
}

/* The block of cells at offsets lo[d]..hi[d] around cell c, clipped to the grid on walled
 * axes, wrapped around periodic ones. */
static inline void walk_init(eng_walk *w, const rc_sim *s, int32_t skip, const int c[3],
                             const int lo[3], const int hi[3])
{
    const eng_cells *g = &s->g;
    if (s->periodic && walk_wraps(g, c, lo, hi)) {
        walk_init_wrapped(w, s, skip, c, lo, hi);
        return;
    }
    const int x0 = c[0] + lo[0] > 0 ? c[0] + lo[0] : 0;
    const int x1 = c[0] + hi[0] < g->n[0] ? c[0] + hi[0] : g->n[0] - 1;
    const int y0 = c[1] + lo[1] > 0 ? c[1] + lo[1] : 0;
    const int y1 = c[1] + hi[1] < g->n[1] ? c[1] + hi[1] : g->n[1] - 1;
    const int z0 = c[2] + lo[2] > 0 ? c[2] + lo[2] : 0;
    const int z1 = c[2] + hi[2] < g->n[2] ? c[2] + hi[2] : g->n[2] - 1;
    w->s = s;
    w->skip = skip;
    w->image = 0;
    w->nrows = 0;
    w->nslots = (x1 - x0 + 1) * ENG_CELL_CAP;
    /* (an empty block: a crossing into a boundary cell has no slab beyond it) */
    if (w->nslots > 0) {
        const int32_t sy = g->n[0] * ENG_CELL_CAP, sz = sy * g->n[1];
        int32_t plane = (x0 + g->n[0] * (y0 + g->n[1] * z0)) * ENG_CELL_CAP;
        if (y1 - y0 == 2 && (z1 - z0 == 2 || g->n[2] == 1)) {
            /* three rows a plane, one or three planes (a full block away from the
             * grid's edges, the common case): fixed counts, no loop branches to
             * mispredict (the general loops below are for blocks at the grid's edges) */
            for (int r = 0; r < 9; r++)
                w->row[r] = plane + g->block_rows[r];
            w->nrows = g->n[2] == 1 ? 3 : 9;
        } else {
            for (int z = z0; z <= z1; z++, plane += sz) {
                int32_t row = plane;
                for (int y = y0; y <= y1; y++, row += sy)
                    w->row[w->nrows++] = row;
            }
        }
    }
    w->nchain = w->ci = 0;
    w->k = -1;
    w->rows_done = w->done = 0;
}

#ifdef ENG_HAVE_AVX2
#define ENG_WALK_AVX2 1 /* (the lanes' walks exist: test_engine_cells compares them) */
#endif

/* More balls into nb (at most GATHER_MAX); w->done once the block is finished. The rows
 * first (all in this chunk: at most 9 rows of 6 slots, or 27 of 2 wrapped), then the chains. */
static inline size_t walk_gather(eng_walk *w, int32_t *nb)
{
    const rc_sim *s = w->s;
    size_t m = 0;
    if (!w->rows_done) {
        w->rows_done = 1;
        m = eng_lanes_of(s->simd)->gather_rows(w, nb);
        /* the records, fetched ahead of the tests (in a large gas each is a cache miss
         * otherwise): four at a time over the list padded with the scanning ball, fewer
         * loop branches */
        for (int l = 0; l < 8; l++)
            nb[m + (size_t)l] = w->skip;
        for (size_t j = 0; j < m; j += 4)
            for (int l = 0; l < 4; l++)
                __builtin_prefetch(&s->b[nb[j + (size_t)l]]);
    }
    for (; w->ci < w->nchain; w->ci++, w->k = -1) {
        int32_t k = w->k >= 0 ? w->k : w->chain[w->ci];
        for (; k >= 0; k = s->g.next[k]) {
            if (m == GATHER_MAX) {
                w->k = k;
                return m;
            }
            __builtin_prefetch(&s->b[k]);
            nb[m] = k;
            m += k != w->skip;
        }
    }
    w->done = 1;
    return m;
}

#endif
