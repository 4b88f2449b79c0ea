/* test_engine_cells.c — the engine's cells (lib/engine/cells.c, internal API) and the
 * neighbour walk over them (lib/engine/walk.h): against a plain record of which cell each
 * ball is in, after random inserts, removals and moves that fill cells far past their
 * slots (overflow chains of every length, a chain longer than a gather chunk):
 *  - each cell's iterator yields exactly its balls, each once;
 *  - a walk over any block yields exactly the balls of its cells but the scanning ball,
 *    each once, in the same order with the AVX2 and AVX-512 compresses as slot by slot,
 *    with the block clipped at walled faces and wrapped around periodic ones;
 *  - the Z order balls are numbered in is a permutation of the cells, the Morton code
 *    itself on a power-of-two grid, and plain order along a line of cells. */
#include <stdlib.h>
#include <string.h>

#include "../../lib/engine/walk.h"
#include "rc_test.h"
#include "relcol/relcol.h"

#define NX 5
#define NY 4
#define NZ 3

typedef struct world {
    rc_sim s; /* only s.g, s.b and s.simd are used by the walk */
    eng_aux *a;
    int32_t *where; /* cell of each ball, -1: not in the grid */
    size_t n;
    int per[3]; /* periodic axes */
} world;

static void world_init(world *w, size_t n, const int per[3])
{
    memset(w, 0, sizeof *w);
    w->n = n;
    for (int d = 0; d < 3; d++) {
        w->per[d] = per[d];
        w->s.periodic |= per[d];
    }
    ENSURE(eng_cells_init(&w->s.g, 3, rc_v3(NX, NY, NZ), 1.0, n, w->per) == RC_OK);
    ENSURE(w->s.g.n[0] == NX && w->s.g.n[1] == NY && w->s.g.n[2] == NZ);
    w->s.b = calloc(n, sizeof *w->s.b);
    w->a = calloc(n, sizeof *w->a);
    w->where = malloc(n * sizeof *w->where);
    for (size_t i = 0; i < n; i++)
        w->where[i] = -1;
}

static void world_free(world *w)
{
    eng_cells_free(&w->s.g);
    free(w->s.b);
    free(w->a);
    free(w->where);
}

/* Every cell's iterator against the record. */
static int cells_agree(const world *w)
{
    int ok = 1;
    unsigned char *seen = calloc(w->n, 1);
    for (int32_t c = 0; c < (int32_t)w->s.g.ncells; c++) {
        eng_cell_it it;
        for (int32_t k = cell_first(&w->s.g, c, &it); k >= 0; k = cell_next(&w->s.g, &it)) {
            ok &= k < (int32_t)w->n && w->where[k] == c && !seen[k];
            if (k < (int32_t)w->n)
                seen[k] = 1;
        }
    }
    for (size_t i = 0; i < w->n; i++)
        ok &= seen[i] == (w->where[i] >= 0);
    free(seen);
    return ok;
}

/* The walk over the block lo..hi around cell c, skipping ball skip, with the given path:
 * every index gathered, in order, into out (returns the count). */
static size_t walk_all(world *w, int simd, const int c[3], const int lo[3], const int hi[3],
                       int32_t skip, int32_t *out)
{
    w->s.simd = simd;
    eng_walk wk;
    walk_init(&wk, &w->s, skip, c, lo, hi);
    int32_t nb[NB_CAP];
    size_t total = 0;
    while (!wk.done) {
        const size_t m = walk_gather(&wk, nb);
        ENSURE(m <= GATHER_MAX);
        memcpy(out + total, nb, m * sizeof *nb);
        total += m;
    }
    return total;
}

/* Offset o of a cell from the block's centre along axis d (n cells): on a periodic axis
 * the nearest one around the ring. */
static int offset(const world *w, int d, int o, int n)
{
    if (!w->per[d])
        return o;
    o = ((o % n) + n) % n;
    return 2 * o > n ? o - n : o;
}

/* The walk against the record, both paths, over random blocks (full 3x3x3 blocks and
 * the slabs of a crossing, clipped at the grid's faces). */
static void check_walks(world *w, rc_test_rng *R, int blocks)
{
    int32_t *got = malloc(w->n * sizeof *got), *got2 = malloc(w->n * sizeof *got2);
    unsigned char *seen = malloc(w->n);
    for (int b = 0; b < blocks; b++) {
        const int c[3] = {(int)(rc_test_uniform(R) * NX), (int)(rc_test_uniform(R) * NY),
                          (int)(rc_test_uniform(R) * NZ)};
        int lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
        if (rc_test_uniform(R) < 0.5) { /* a slab */
            const int d = (int)(rc_test_uniform(R) * 3), dir = rc_test_uniform(R) < 0.5 ? -1 : 1;
            lo[d] = hi[d] = dir;
        }
        const int32_t skip = (int32_t)(rc_test_uniform(R) * (double)w->n);
        const size_t m = walk_all(w, ENG_SIMD_NONE, c, lo, hi, skip, got);
        memset(seen, 0, w->n);
        int ok = 1;
        for (size_t j = 0; j < m; j++) {
            const int32_t k = got[j];
            ok &= k >= 0 && k < (int32_t)w->n && k != skip && !seen[k];
            if (k >= 0 && k < (int32_t)w->n)
                seen[k] = 1;
        }
        size_t expect = 0;
        for (size_t i = 0; i < w->n; i++) {
            const int32_t cell = w->where[i];
            if (cell < 0 || (int32_t)i == skip)
                continue;
            const int x = cell % NX, y = (cell / NX) % NY, z = cell / (NX * NY);
            const int o[3] = {offset(w, 0, x - c[0], NX), offset(w, 1, y - c[1], NY),
                              offset(w, 2, z - c[2], NZ)};
            const int in = o[0] >= lo[0] && o[0] <= hi[0] && o[1] >= lo[1] && o[1] <= hi[1] &&
                           o[2] >= lo[2] && o[2] <= hi[2];
            expect += (size_t)in;
            ok &= seen[i] == in;
        }
        ENSURE_MSG(ok && m == expect, "block %d: %zu gathered, %zu expected", b, m, expect);
#ifdef ENG_WALK_AVX2
        if (__builtin_cpu_supports("avx2")) {
            const size_t m2 = walk_all(w, ENG_SIMD_AVX2, c, lo, hi, skip, got2);
            ENSURE_MSG(m2 == m && !memcmp(got, got2, m * sizeof *got),
                       "block %d: the AVX2 walk differs", b);
        }
        if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")) {
            const size_t m3 = walk_all(w, ENG_SIMD_AVX512, c, lo, hi, skip, got2);
            ENSURE_MSG(m3 == m && !memcmp(got, got2, m * sizeof *got),
                       "block %d: the AVX-512 walk differs", b);
        }
#endif
    }
    free(got);
    free(got2);
    free(seen);
}

/* Random inserts, removals and moves; cells drawn from a few favourites so that some
 * overflow deeply. */
static void test_random_churn(const int per[3])
{
    world w;
    world_init(&w, 400, per);
    rc_test_rng R = {42};
    const int32_t ncells = (int32_t)w.s.g.ncells;
    for (int step = 0; step < 20000; step++) {
        const int32_t i = (int32_t)(rc_test_uniform(&R) * (double)w.n);
        const int32_t cell = rc_test_uniform(&R) < 0.5 ? (int32_t)(rc_test_uniform(&R) * 4)
                                                       : (int32_t)(rc_test_uniform(&R) * ncells);
        if (w.where[i] >= 0) {
            eng_cells_remove(&w.s.g, w.a, i);
            w.where[i] = -1;
            if (rc_test_uniform(&R) < 0.7) { /* a move */
                eng_cells_insert(&w.s.g, w.a, i, cell);
                w.where[i] = cell;
            }
        } else {
            eng_cells_insert(&w.s.g, w.a, i, cell);
            w.where[i] = cell;
        }
        ENSURE(w.where[i] < 0 || w.a[i].cell == w.where[i]);
        if (step % 1000 == 999) {
            ENSURE_MSG(cells_agree(&w), "step %d", step);
            check_walks(&w, &R, 200);
        }
    }
    world_free(&w);
}

/* One cell holding 300 balls (a chain past a whole gather chunk), then emptied from the
 * middle, the head and the tail of its chain. */
static void test_long_chain(const int per[3])
{
    world w;
    world_init(&w, 300, per);
    rc_test_rng R = {7};
    const int32_t cell = (int32_t)(1 + NX * (1 + NY * 1));
    for (int32_t i = 0; i < 300; i++) {
        eng_cells_insert(&w.s.g, w.a, i, cell);
        w.where[i] = cell;
    }
    ENSURE(cells_agree(&w));
    check_walks(&w, &R, 100);
    const int32_t order[] = {150, 299, 0, 1, 298, 2, 100};
    for (size_t j = 0; j < sizeof order / sizeof *order; j++) {
        eng_cells_remove(&w.s.g, w.a, order[j]);
        w.where[order[j]] = -1;
        ENSURE_MSG(cells_agree(&w), "after removing %d", order[j]);
    }
    for (int32_t i = 0; i < 300; i++)
        if (w.where[i] >= 0) {
            eng_cells_remove(&w.s.g, w.a, i);
            w.where[i] = -1;
        }
    ENSURE(cells_agree(&w));
    for (size_t c = 0; c < w.s.g.ncells * ENG_CELL_CAP + ENG_SLOT_PAD; c++)
        ENSURE(w.s.g.slot[c] == -1);
    world_free(&w);
}

/* rank[] on a grid of nx x ny x nz cells (edge 1): a permutation; with morton = 1 (a
 * cube of side 2^k) the interleaved bits x0 y0 z0 x1 y1 z1 ... themselves; with 2 (a
 * line of cells) the plain order. */
static void zorder_case(int nx, int ny, int nz, int morton)
{
    eng_cells g;
    ENSURE(eng_cells_init(&g, nz > 1 ? 3 : 2, rc_v3(nx, ny, nz), 1.0, (size_t)(nx * ny * nz), (const int[3]){0, 0, 0}) ==
           RC_OK);
    ENSURE(g.n[0] == nx && g.n[1] == ny && g.n[2] == nz);
    int32_t *rank = malloc(g.ncells * sizeof *rank);
    unsigned char *hit = calloc(g.ncells, 1);
    for (size_t c = 0; c < g.ncells; c++)
        rank[c] = -1;
    eng_cells_zorder(&g, rank);
    int perm = 1, code_ok = 1;
    for (size_t c = 0; c < g.ncells; c++) {
        perm &= rank[c] >= 0 && (size_t)rank[c] < g.ncells && !hit[rank[c]];
        if (rank[c] >= 0 && (size_t)rank[c] < g.ncells)
            hit[rank[c]] = 1;
        const int x = (int)c % nx, y = ((int)c / nx) % ny, z = (int)c / (nx * ny);
        int32_t code = 0;
        for (int b = 0; b < 10; b++)
            code |= ((x >> b & 1) << (3 * b)) | ((y >> b & 1) << (3 * b + 1)) |
                    ((z >> b & 1) << (3 * b + 2));
        code_ok &= morton == 0 || rank[c] == (morton == 1 ? code : (int32_t)c);
    }
    ENSURE_MSG(perm, "%d x %d x %d: not a permutation", nx, ny, nz);
    ENSURE_MSG(code_ok, "%d x %d x %d: not the Morton order", nx, ny, nz);
    free(rank);
    free(hit);
    eng_cells_free(&g);
}

static void test_zorder(void)
{
    zorder_case(8, 8, 8, 1);
    zorder_case(5, 4, 3, 0);
    zorder_case(1000, 1, 1, 2); /* a line: y and z have no bits, the code is x itself */
    zorder_case(37, 23, 1, 0);
}

static void test_walled(void)
{
    static const int walls[3] = {0, 0, 0};
    test_random_churn(walls);
    test_long_chain(walls);
}

/* Periodic axes, alone and mixed with walls (NZ = 3: the fewest cells a periodic axis
 * may have, where the block's three planes are all the planes there are). */
static void test_periodic(void)
{
    static const int per[][3] = {{1, 1, 1}, {1, 0, 1}, {0, 1, 0}, {0, 0, 1}};
    for (size_t k = 0; k < sizeof per / sizeof *per; k++) {
        test_random_churn(per[k]);
        test_long_chain(per[k]);
    }
}

int main(void)
{
    RUN_TEST(test_zorder);
    RUN_TEST(test_walled);
    RUN_TEST(test_periodic);
    RC_TEST_MAIN_END();
}
