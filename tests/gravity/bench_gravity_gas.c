/* bench_gravity_gas — CPU time per collision (ball and wall contacts) of the gas in a
 * uniform field, as a ratio to the same gas without one, measured in this process:
 * field_gas.h's box, N balls of radius 0.005 (packing 1e-3 at N = 2000), one speed 0.8
 * (classically; at c = 2 that is 0.4 c), g = 1, the engine's own cells. Each gas first
 * runs `warm` collisions (not timed), then `timed` collisions are timed.
 * Usage: bench_gravity_gas [N [timed [coupling c]]]; a coupling ("none", "newtonian",
 * "equivalence") and c time that one case alone (for a profiler). */
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "field_gas.h"

static double cpu_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double per_collision(const rc_gravity_coupling *cp, double c, size_t n, uint64_t timed)
{
    rc_sim *s = field_gas(cp, c, 1.0, n, 0.005, 0.8, 0xb01);
    if (!s)
        return NAN;
    int st = RC_OK;
    while (st == RC_OK && field_collisions(s) < timed / 10)
        st = rc_sim_advance(s, INFINITY, 20000);
    const uint64_t c0 = field_collisions(s);
    const double t0 = cpu_s();
    while (st == RC_OK && field_collisions(s) < c0 + timed)
        st = rc_sim_advance(s, INFINITY, 20000);
    if (st != RC_OK) {
        fprintf(stderr, "%s c %g: %s\n", cp ? cp->name : "no field", c, rc_strerror(st));
        rc_sim_free(&s);
        return NAN;
    }
    const double dt = cpu_s() - t0;
    const double per = dt / (double)(field_collisions(s) - c0);
    rc_sim_free(&s);
    return per;
}

int main(int argc, char **argv)
{
    const size_t n = argc > 1 ? (size_t)atol(argv[1]) : 4000;
    const uint64_t timed = argc > 2 ? (uint64_t)atol(argv[2]) : 200000;
    const double cs[2] = {INFINITY, 2.0};
    if (argc > 4) { /* one case */
        const rc_gravity_coupling *cp = strcmp(argv[3], "none") ? rc_gravity_find(argv[3]) : NULL;
        if (strcmp(argv[3], "none") && !cp) {
            fprintf(stderr, "bench_gravity_gas: coupling %s: not one of none, newtonian, "
                            "equivalence\n", argv[3]);
            return 2;
        }
        const double c = atof(argv[4]);
        const double t = per_collision(cp, c > 0.0 ? c : INFINITY, n, timed);
        printf("  %s c %g: %.3g us/collision\n", argv[3], c, 1e6 * t);
        return isfinite(t) ? 0 : 1;
    }
    printf("gravity gas: N %zu, %llu collisions timed a case (CPU time)\n", n,
           (unsigned long long)timed);
    for (int j = 0; j < 2; j++) {
        const double c = cs[j];
        const double none = per_collision(NULL, c, n, timed);
        const double nw = per_collision(&rc_gravity_newtonian, c, n, timed);
        const double eq = per_collision(&rc_gravity_equivalence, c, n, timed);
        printf("  c %-4g no field %.3g us/collision; newtonian %.3g us (ratio %.2f); "
               "equivalence %.3g us (ratio %.2f)\n",
               c, 1e6 * none, 1e6 * nw, nw / none, 1e6 * eq, eq / none);
    }
    (void)rc_test_checks, (void)rc_test_failures; /* (rc_test.h's, unused here) */
    return 0;
}
