/* cells_grid.c — the neighbour search: a uniform grid of cells at least one largest
 * bounding diameter wide, so balls that can touch are always in adjacent cells, with an
 * intrusive doubly linked list per cell so moving a ball is O(1). */
#include <math.h>
#include <stdlib.h>

#include "engine_private.h"
#include "relcol/status.h"

/* At most this many cells per ball (then cells grow): bounds memory for sparse gases. */
#define CELLS_PER_BALL_MAX 8.0

int rc_eng_cells_init(eng_cells *g, int dim, rc_vec3 box, double min_edge, size_t nballs)
{
    double L[3] = {box.x, box.y, dim == 3 ? box.z : 1.0};
    double edge = min_edge;
    double cap = CELLS_PER_BALL_MAX * (double)nballs + 64.0;
    for (;;) {
        double total = 1.0;
        for (int d = 0; d < 3; d++) {
            double nd = d < dim ? floor(L[d] / edge) : 1.0;
            if (nd < 1.0)
                nd = 1.0;
            total *= nd;
        }
        if (total <= cap)
            break;
        edge *= 1.25;
    }
    g->ncells = 1;
    for (int d = 0; d < 3; d++) {
        double nd = d < dim ? floor(L[d] / edge) : 1.0;
        g->n[d] = nd < 1.0 ? 1 : (int)nd;
        g->w[d] = d < dim ? L[d] / g->n[d] : 1.0;
        g->inv_w[d] = 1.0 / g->w[d];
        g->ncells *= (size_t)g->n[d];
    }
    g->head = malloc(g->ncells * sizeof *g->head);
    g->next = malloc((nballs ? nballs : 1) * sizeof *g->next);
    g->prev = malloc((nballs ? nballs : 1) * sizeof *g->prev);
    if (!g->head || !g->next || !g->prev) {
        rc_eng_cells_free(g);
        return RC_ENOMEM;
    }
    for (size_t c = 0; c < g->ncells; c++)
        g->head[c] = -1;
    return RC_OK;
}

void rc_eng_cells_free(eng_cells *g)
{
    free(g->head);
    free(g->next);
    free(g->prev);
    g->head = NULL;
    g->next = NULL;
    g->prev = NULL;
}

int32_t rc_eng_cells_index_of(const eng_cells *g, int dim, rc_vec3 x)
{
    int c[3] = {0, 0, 0};
    for (int d = 0; d < dim; d++) {
        double f = floor(rc_v3_get(x, d) * g->inv_w[d]);
        int k = f < 0.0 ? 0 : (f >= g->n[d] ? g->n[d] - 1 : (int)f);
        c[d] = k;
    }
    return (int32_t)(c[0] + g->n[0] * (c[1] + g->n[1] * c[2]));
}

void rc_eng_cells_insert(eng_cells *g, eng_aux *a, int32_t i, int32_t cell)
{
    int32_t h = g->head[cell];
    a[i].cell = cell;
    g->prev[i] = -1;
    g->next[i] = h;
    if (h >= 0)
        g->prev[h] = i;
    g->head[cell] = i;
}

void rc_eng_cells_remove(eng_cells *g, const eng_aux *a, int32_t i)
{
    int32_t p = g->prev[i], nx = g->next[i];
    if (p >= 0)
        g->next[p] = nx;
    else
        g->head[a[i].cell] = nx;
    if (nx >= 0)
        g->prev[nx] = p;
}
