/* test_engine_determinism.c — same input twice gives a bit-identical state hash; running
 * in pieces gives the same bits as one go; shuffling the ball order gives the same
 * physics (ball by ball); relativistic runs too, with uncontracted and with contracted
 * (table- and zmf-frame) shapes; the neighbour test's AVX2 lanes give the same bits as
 * the scalar loop. */
#include <math.h>
#include <string.h>

#include "engine_util.h"

#define N 600

static rc_sim_def def2d(double c)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.c = c;
    d.eps_ball = 0.9;
    d.eps_wall = 0.95;
    d.t_c = 1e-4;
    return d;
}

static rc_sim *make(rc_sim_def d, const rc_sim_ball *b, size_t n)
{
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    if (s)
        ENSURE(rc_sim_set_balls(s, n, b, NULL) == RC_OK);
    return s;
}

/* T: run time (40: ~30 collisions per ball); frame: NULL for the default (spheres). */
static void check(double c, const char *frame, double T)
{
    rc_sim_def d = def2d(c);
    if (frame)
        d.frame = rc_toi_frame_find(frame);
    rc_sim_gas_def g = {2, N, 0.5, 0.5, isinf(c) ? 1.0 : 0.5 * c, c, 1.0, 9};
    static rc_sim_ball b[N], shuffled[N];
    size_t perm[N];
    ENSURE(rc_sim_gas_init(&g, &d.box, b) == RC_OK);

    rc_sim *s1 = make(d, b, N), *s2 = make(d, b, N), *s3 = make(d, b, N);
    ENSURE(rc_sim_advance(s1, T, 0) == RC_OK);
    ENSURE(rc_sim_advance(s2, T, 0) == RC_OK);
    for (int k = 1; k <= 8; k++) /* the same run cut into pieces */
        ENSURE(rc_sim_advance(s3, T * k / 8.0, 0) == RC_OK);
    rc_sim_diag dg;
    rc_sim_diagnostics(s1, &dg);
    ENSURE(dg.collisions > 5000);
    ENSURE(rc_sim_hash(s1) == rc_sim_hash(s2));
    ENSURE(rc_sim_hash(s1) == rc_sim_hash(s3));

    /* shuffled order: same balls under other indices */
    rc_test_rng R = {3};
    for (size_t i = 0; i < N; i++)
        perm[i] = i;
    for (size_t i = N - 1; i > 0; i--) {
        size_t j = (size_t)(rc_test_uniform(&R) * (double)(i + 1)), t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    for (size_t i = 0; i < N; i++)
        shuffled[i] = b[perm[i]];
    rc_sim *s4 = make(d, shuffled, N);
    ENSURE(rc_sim_advance(s4, T, 0) == RC_OK);
    /* Hard-sphere dynamics is chaotic: any difference in the arithmetic would grow to
     * O(1) over ~1e4 collisions. Agreement to 1e-9 of the box therefore means the same
     * events in the same order with the same arithmetic; the pair kernels are written to
     * give the same bits whichever ball of a pair is first. */
    double worst = 0.0;
    for (size_t i = 0; i < N; i++) {
        rc_sim_ball x, y;
        rc_sim_get_ball(s1, perm[i], &x);
        rc_sim_get_ball(s4, i, &y);
        worst = fmax(worst, rc_v3_norm(rc_v3_sub(x.x, y.x)));
        worst = fmax(worst, rc_v3_norm(rc_v3_sub(x.p, y.p)));
    }
    ENSURE_MSG(worst <= 1e-9 * d.box.x, "shuffled order differs by %g", worst);
    printf("  c = %g %s: %llu collisions, shuffled-order max difference %.3g\n", c,
           frame ? frame : "sphere", (unsigned long long)dg.collisions, worst);
    rc_sim_free(&s1);
    rc_sim_free(&s2);
    rc_sim_free(&s3);
    rc_sim_free(&s4);
}

/* The neighbour test runs in AVX-512 lanes, AVX2 lanes (rc_sim_def.simd = RC_SIM_SIMD_AVX2)
 * or one by one (RC_SIM_SIMD_SCALAR): the same operations
 * in the same order, so the same bits. Uncontracted frames take it for every prediction,
 * contracted ones for their broad phase; 2-D and 3-D, classical and c = 2, with walls,
 * restitution, the TC model and the simultaneity check (sim_tol > 0) in play, and a
 * contracted (table-frame) gas. On a CPU without the wider lanes the runs fall back to
 * the narrower ones and that part of the check is trivially met. */
static void lanes(int dim, double c, const char *frame)
{
    rc_sim_def d = def2d(c);
    d.dim = dim;
    if (frame)
        d.frame = rc_toi_frame_find(frame);
    const size_t n = dim == 3 ? 2000 : N;
    const rc_sim_simd mode[3] = {RC_SIM_SIMD_SCALAR, RC_SIM_SIMD_AVX2, RC_SIM_SIMD_AUTO};
    uint64_t h[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++) {
        d.simd = mode[k];
        rc_sim *s = util_gas(d, n, dim == 3 ? 0.4 : 0.6, isinf(c) ? 1.0 : 0.5 * c, 17);
        if (!s)
            continue;
        util_run_collisions(s, (frame ? 5 : 40) * n);
        h[k] = rc_sim_hash(s);
        rc_sim_free(&s);
    }
    ENSURE_MSG(h[0] == h[1] && h[1] == h[2], "%dD c=%g %s: scalar %llx avx2 %llx best %llx",
               dim, c, frame ? frame : "sphere", (unsigned long long)h[0],
               (unsigned long long)h[1], (unsigned long long)h[2]);
}

static void test_lanes(void)
{
    lanes(2, INFINITY, NULL);
    lanes(3, INFINITY, NULL);
    lanes(2, 2.0, NULL);
    lanes(3, 2.0, NULL);
    lanes(3, 2.0, "table");
}

static void test_classical(void) { check(INFINITY, NULL, 40.0); }
static void test_relativistic(void) { check(2.0, NULL, 40.0); }
/* contracted shapes: the same physics whatever order the balls are given in (the engine
 * numbers them by cell, and within a cell by the input order) */
static void test_contracted(void)
{
    check(2.0, "table", 20.0);
    check(2.0, "zmf", 20.0);
}

int main(void)
{
    RUN_TEST(test_classical);
    RUN_TEST(test_relativistic);
    RUN_TEST(test_contracted);
    RUN_TEST(test_lanes);
    RC_TEST_MAIN_END();
}
