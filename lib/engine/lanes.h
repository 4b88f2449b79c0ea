/* engine/lanes.h — the engine's lane kernels as a table of functions, one table per back
 * end (AVX-512, AVX2, plain C), picked per engine by s->simd. Each table is the same
 * kernels (engine/kernels.h) compiled over that back end's lanes (engine/wide.h) in its
 * own file, lanes_<back end>.c, built for its instruction set; the back ends give
 * the same bits (test_engine_determinism, test_engine_cells). */
#ifndef RELCOL_ENGINE_LANES_H
#define RELCOL_ENGINE_LANES_H

#include <stddef.h>
#include <stdint.h>

#include "private.h"

/* x86-64 builds have the AVX2 and AVX-512 back ends, used where the CPU has those
 * instruction sets (rc_sim_create asks it once); other machines, and builds with
 * RELCOL_NO_SIMD, the plain C one alone. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(RELCOL_NO_SIMD)
#define ENG_HAVE_AVX2 1
#define ENG_HAVE_AVX512 1
#endif

struct eng_walk;

typedef struct eng_lanes {
    /* Sphere contact of ball i with the m gathered neighbours nb (uncontracted frames),
     * the earliest below *best into (*best, *bp) (ties: the first in nb order). With chk
     * (ball i just collided at T = t_i, every other clock <= T) it also looks for another
     * contact simultaneous with the resolved one -- gap <= sim_tol, approaching ball i's
     * old state (engine/approach.h), not chk->partner -- and returns 1 at the first, else
     * 0. latest: every neighbour's clock is at most ball i's; per: the pairs need the
     * nearest image (the walk's block wraps, eng_walk.image). nb holds NB_CAP (padded in
     * place). */
    int (*test_list)(const rc_sim *s, int32_t i, int32_t *nb, size_t m, double *best,
                     int32_t *bp, const eng_check *chk, double T, int latest, int per);
    /* Bounding-sphere times t[j] of ball i with the m <= GATHER_MAX neighbours nb
     * (INFINITY unless below `best`; nb and t hold NB_CAP), the broad phase of a contracted
     * frame; as bits (j of the 128): hit, t[j] finite; near, the centres within
     * (r_i + r_k)(1 + sim_tol). */
    void (*sphere_times)(const rc_sim *s, int32_t i, int32_t *nb, size_t m, double best,
                         double *t, uint64_t hit[2], uint64_t near[2]);
    /* The walk's rows of slots onto nb (engine/walk.h): the balls other than the scanning
     * one, in slot order, overflow chains noted; their count. */
    size_t (*gather_rows)(struct eng_walk *w, int32_t *nb);
    /* Ball i's next cell crossing (in cell c) into its cross_t and cross_code. */
    void (*cross_event)(rc_sim *s, int32_t i, const int c[3]);
} eng_lanes;

extern const eng_lanes eng_lanes_scalar;
#ifdef ENG_HAVE_AVX2
extern const eng_lanes eng_lanes_avx2;
extern const eng_lanes eng_lanes_avx512;
/* the AVX2 crossing, the AVX-512 table's too (engine/lanes_avx512.c) */
void eng_cross_event_avx2(rc_sim *s, int32_t i, const int c[3]);
#endif

/* The table of the lanes an engine uses (s->simd: ENG_SIMD_*). */
static inline const eng_lanes *eng_lanes_of(int simd)
{
#ifdef ENG_HAVE_AVX2
    if (simd == ENG_SIMD_AVX512)
        return &eng_lanes_avx512;
    if (simd == ENG_SIMD_AVX2)
        return &eng_lanes_avx2;
#else
    (void)simd;
#endif
    return &eng_lanes_scalar;
}

#endif
