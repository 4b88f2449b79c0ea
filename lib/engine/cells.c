/* engine/cells.c — the neighbour search: a uniform grid of cells at least one largest
 * bounding diameter wide, so balls that can touch are always in adjacent cells. Each
 * cell keeps its balls in ENG_CELL_CAP slots of its own, the last of which becomes an
 * overflow chain when more arrive (engine/private.h); moving a ball is O(1) unless its
 * cell overflows. */
#include <math.h>
#include <stdlib.h>

#include "private.h"
#include "relcol/status.h"

/* At most this many cells per ball (then cells grow): bounds memory for sparse gases
 * (12 bytes a cell). */
#define CELLS_PER_BALL_MAX 3.0

int eng_cells_init(eng_cells *g, int dim, rc_vec3 box, double min_edge, size_t nballs,
                      const int periodic[3])
{
    double L[3] = {box.x, box.y, dim == 3 ? box.z : 1.0};
    double edge = min_edge;
    double cap = CELLS_PER_BALL_MAX * (double)nballs + 64.0;
    /* a periodic axis keeps four cells when min_edge allows them, however sparse the gas
     * (the nearest image needs them: eng_image) */
    double least[3];
    for (int d = 0; d < 3; d++) {
        const double most = floor(L[d] / min_edge);
        least[d] = d < dim && periodic[d] ? (most < 4.0 ? most : 4.0) : 1.0;
        if (least[d] < 1.0)
            least[d] = 1.0;
    }
    for (;;) {
        double total = 1.0;
        for (int d = 0; d < 3; d++) {
            double nd = d < dim ? floor(L[d] / edge) : 1.0;
            if (nd < least[d])
                nd = least[d];
            total *= nd;
        }
        if (total <= cap)
            break;
        edge *= 1.25;
    }
    g->ncells = 1;
    for (int d = 0; d < 3; d++) {
        double nd = d < dim ? floor(L[d] / edge) : 1.0;
        if (nd < least[d])
            nd = least[d];
        g->n[d] = nd < 1.0 ? 1 : (int)nd;
        g->w[d] = d < dim ? L[d] / g->n[d] : 1.0;
        g->inv_w[d] = 1.0 / g->w[d];
        g->ncells *= (size_t)g->n[d];
        g->wrap[d] = d < dim && periodic[d];
        g->up_lim[d] = g->wrap[d] ? g->n[d] : g->n[d] - 1;
        g->dn_lim[d] = g->wrap[d] ? -1 : 0;
    }
    /* slot indices are int32 (rows are computed in int32 by the walk) */
    if (g->ncells > ((size_t)INT32_MAX - ENG_SLOT_PAD) / ENG_CELL_CAP) {
        g->slot = NULL;
        g->next = NULL;
        return RC_ENOMEM;
    }
    /* a full block's rows from its first: 3 rows a plane, 3 planes (one in 2-D: the
     * others repeat it, unused) */
    const int32_t sy = g->n[0] * ENG_CELL_CAP, sz = g->n[2] == 1 ? 0 : sy * g->n[1];
    for (int r = 0; r < 9; r++)
        g->block_rows[r] = (r / 3) * sz + (r % 3) * sy;
    g->slot = eng_alloc((g->ncells * ENG_CELL_CAP + ENG_SLOT_PAD) * sizeof *g->slot);
    g->next = eng_alloc(nballs * sizeof *g->next);
    if (!g->slot || !g->next) {
        eng_cells_free(g);
        return RC_ENOMEM;
    }
    eng_cells_clear(g);
    return RC_OK;
}

void eng_cells_clear(eng_cells *g)
{
    for (size_t c = 0; c < g->ncells * ENG_CELL_CAP + ENG_SLOT_PAD; c++)
        g->slot[c] = -1;
}

void eng_cells_free(eng_cells *g)
{
    free(g->slot);
    free(g->next);
    g->slot = NULL;
    g->next = NULL;
}

int32_t eng_cells_index_of(const eng_cells *g, int dim, rc_vec3 x)
{
    int c[3] = {0, 0, 0};
    for (int d = 0; d < dim; d++) {
        double f = floor(rc_v3_get(x, d) * g->inv_w[d]);
        int k = f < 0.0 ? 0 : (f >= g->n[d] ? g->n[d] - 1 : (int)f);
        c[d] = k;
    }
    return (int32_t)(c[0] + g->n[0] * (c[1] + g->n[1] * c[2]));
}

/* Into the first empty slot; with none, the last slot's ball and i form a chain, or i
 * joins the chain there at its head. */
void eng_cells_insert(eng_cells *g, eng_aux *a, int32_t i, int32_t cell)
{
    int32_t *sl = g->slot + (size_t)cell * ENG_CELL_CAP;
    a[i].cell = cell;
    for (int j = 0; j < ENG_CELL_CAP; j++)
        if (sl[j] == -1) {
            sl[j] = i;
            return;
        }
    const int32_t last = sl[ENG_CELL_CAP - 1];
    if (last >= 0) {
        g->next[last] = -1;
        g->next[i] = last;
    } else {
        g->next[i] = ENG_CHAIN_HEAD(last);
    }
    sl[ENG_CELL_CAP - 1] = ENG_CHAIN(i);
}

/* A slot simply empties (a chain keeps at least two balls); a chain left with one ball
 * is a plain slot again. */
void eng_cells_remove(eng_cells *g, const eng_aux *a, int32_t i)
{
    int32_t *sl = g->slot + (size_t)a[i].cell * ENG_CELL_CAP;
    for (int j = 0; j < ENG_CELL_CAP; j++)
        if (sl[j] == i) {
            sl[j] = -1;
            return;
        }
    if (sl[ENG_CELL_CAP - 1] >= -1)
        return; /* not in its cell: nothing to undo (does not happen) */
    int32_t h = ENG_CHAIN_HEAD(sl[ENG_CELL_CAP - 1]);
    if (h == i) {
        h = g->next[i];
    } else {
        int32_t p = h;
        while (p >= 0 && g->next[p] != i)
            p = g->next[p];
        if (p < 0)
            return;
        g->next[p] = g->next[i];
    }
    sl[ENG_CELL_CAP - 1] = g->next[h] < 0 ? h : ENG_CHAIN(h);
}

/* Z order of the cells: the bits of the cell coordinates interleaved (x lowest), a
 * dimension with fewer bits simply dropping out of the higher levels. Visited as the
 * binary tree those bits span, subtrees off the grid pruned: O(cells x levels). */
typedef struct zwalk {
    const eng_cells *g;
    int32_t *rank;
    int32_t r;
    int dim_of[96]; /* the dimension each level splits, lowest bit first */
} zwalk;

static void zvisit(zwalk *z, int lev, int c[3], int span[3])
{
    const eng_cells *g = z->g;
    if (c[0] >= g->n[0] || c[1] >= g->n[1] || c[2] >= g->n[2])
        return;
    if (lev < 0) {
        z->rank[c[0] + g->n[0] * (c[1] + g->n[1] * c[2])] = z->r++;
        return;
    }
    const int d = z->dim_of[lev];
    span[d] /= 2;
    zvisit(z, lev - 1, c, span);
    c[d] += span[d];
    zvisit(z, lev - 1, c, span);
    c[d] -= span[d];
    span[d] *= 2;
}

/* rank[c]: the place of cell c in Z (Morton) order, so that balls numbered in this order
 * of their cells lie near their neighbours in y and z too, not only in x (row-major order
 * puts a cell's y and z neighbours a row or a plane of cells away), which matters once
 * the state no longer fits in the caches. */
void eng_cells_zorder(const eng_cells *g, int32_t *rank)
{
    zwalk z = {g, rank, 0, {0}};
    int bits[3] = {0, 0, 0}, span[3], levels = 0;
    for (int d = 0; d < 3; d++) {
        while ((1L << bits[d]) < g->n[d])
            bits[d]++;
        span[d] = 1 << bits[d];
    }
    for (int b = 0; b < 32; b++)
        for (int d = 0; d < 3; d++)
            if (b < bits[d])
                z.dim_of[levels++] = d;
    int c[3] = {0, 0, 0};
    zvisit(&z, levels - 1, c, span);
}

/* pos[i]: ball i's place when the n balls are numbered in the Z order of their cells
 * (cell[i]), ties in index order (a stable counting sort). RC_ENOMEM leaves pos unset. */
int eng_cells_number(const eng_cells *g, const int32_t *cell, size_t n, uint32_t *pos)
{
    size_t *start = calloc(g->ncells + 1, sizeof *start);
    int32_t *rank = malloc(g->ncells * sizeof *rank);
    if (!start || !rank) {
        free(start);
        free(rank);
        return RC_ENOMEM;
    }
    eng_cells_zorder(g, rank);
    for (size_t i = 0; i < n; i++)
        start[rank[cell[i]] + 1]++;
    for (size_t c = 0; c < g->ncells; c++)
        start[c + 1] += start[c];
    for (size_t i = 0; i < n; i++)
        pos[i] = (uint32_t)start[rank[cell[i]]]++;
    free(start);
    free(rank);
    return RC_OK;
}
