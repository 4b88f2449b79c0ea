/* test_engine_lanes.c — the engine's lanes (lib/engine/lanes.h: AVX-512, AVX2, plain C,
 * one kernel each) give the same bits in periodic and mixed boxes, where the neighbour
 * test takes the nearest image in lanes and the walk wraps its rows (test_engine_determinism
 * checks walled boxes): a gas run in each of the three, its final hash compared. 2-D and
 * 3-D, classical and c = 2, and a contracted (table-frame) gas whose broad phase runs in
 * the lanes. On a CPU without the wider lanes the runs fall back to the narrower ones and
 * that part of the check is trivially met. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "engine_util.h"

/* Run with the lanes named (rc_sim_def.simd: an upper limit on the lanes, AUTO the CPU's
 * widest) and return the final hash (0 if the gas could not be made). */
static uint64_t run(rc_sim_def d, size_t n, double packing, uint64_t collisions,
                    rc_sim_simd mode)
{
    d.simd = mode;
    rc_sim *s = util_gas(d, n, packing, isinf(d.c) ? 1.0 : 0.5 * d.c, 23);
    if (!s)
        return 0;
    util_run_collisions(s, collisions);
    const uint64_t h = rc_sim_hash(s);
    rc_sim_free(&s);
    return h;
}

static void lanes(int dim, const int bnd[3], double c, const char *frame)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    for (int k = 0; k < 3; k++)
        d.boundary[k] = bnd[k];
    d.c = c;
    d.eps_ball = 0.9; /* (restitution and the TC model in play too) */
    d.t_c = 1e-4;
    if (frame)
        d.frame = rc_toi_frame_find(frame);
    const size_t n = dim == 3 ? 2000 : 1500;
    const uint64_t target = (frame ? 5 : 40) * n;
    const double packing = dim == 3 ? 0.4 : 0.6;
    const uint64_t hs = run(d, n, packing, target, RC_SIM_SIMD_SCALAR);
    const uint64_t h2 = run(d, n, packing, target, RC_SIM_SIMD_AVX2);
    const uint64_t hb = run(d, n, packing, target, RC_SIM_SIMD_AUTO);
    ENSURE_MSG(hs != 0 && hs == h2 && h2 == hb,
               "%dD boundary %d%d%d c=%g %s: scalar %llx avx2 %llx best %llx", dim, bnd[0],
               bnd[1], bnd[2], c, frame ? frame : "sphere", (unsigned long long)hs,
               (unsigned long long)h2, (unsigned long long)hb);
    printf("  %dD boundary %d%d%d c=%g %s: %016llx\n", dim, bnd[0], bnd[1], bnd[2], c,
           frame ? frame : "sphere", (unsigned long long)hs);
}

static void test_periodic_lanes(void)
{
    const int P = RC_SIM_PERIODIC, W = RC_SIM_WALLS;
    const int all[3] = {P, P, P}, mixed[3] = {P, W, P}, xwall[3] = {W, P, P};
    lanes(2, all, INFINITY, NULL);
    lanes(3, all, INFINITY, NULL);
    lanes(2, mixed, 2.0, NULL);
    lanes(3, mixed, INFINITY, NULL);
    lanes(3, xwall, 2.0, NULL);
    lanes(3, all, 2.0, NULL);
    lanes(3, all, 2.0, "table");
    lanes(2, xwall, 2.0, "table");
}

int main(void)
{
    RUN_TEST(test_periodic_lanes);
    RC_TEST_MAIN_END();
}
