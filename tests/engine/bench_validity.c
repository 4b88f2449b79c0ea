/* bench_validity — what the validity report's online kink clusters cost a covariant run
 * (issue 36: at most 5 %): the same 3-D covariant periodic gas run with the count (as every
 * run has it) and with it switched off (white box: val_failed set before the first event,
 * so each hook returns at once), paired and alternated, both orders, at packing 0.1 and
 * 0.45 (0.5c). Prints each pair's ratio and the median per packing. (meson test
 * --benchmark --suite relcol validity.) */
#include <stdio.h>
#include <time.h>

#include "engine_util.h"
#include "../../lib/engine/private.h"

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t); /* (CPU time: the machine is shared) */
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double one(double packing, size_t n, double per_ball, int count)
{
    rc_sim *s = util_gas(util_covariant_periodic(3), n, packing, 0.5, 3);
    if (!s)
        return NAN;
    if (!count)
        s->val_failed = 1; /* (no state: start() refuses, every hook returns) */
    const double t0 = seconds();
    util_run_collisions(s, (uint64_t)(per_ball * (double)n));
    const double t = seconds() - t0;
    rc_validity v;
    const int st = rc_sim_validity(s, &v);
    ENSURE(count ? st == RC_OK && v.kink_events > 0 : v.kink_events == 0);
    rc_sim_free(&s);
    return t;
}

static int cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(void)
{
    const double packs[2] = {0.1, 0.45};
    enum { PAIRS = 6 };
    printf("%7s %6s %10s %10s %8s\n", "packing", "pair", "with (s)", "without", "ratio");
    for (int p = 0; p < 2; p++) {
        double r[PAIRS];
        for (int k = 0; k < PAIRS; k++) {
            double with, without;
            if (k % 2) {
                without = one(packs[p], 1000, 20.0, 0);
                with = one(packs[p], 1000, 20.0, 1);
            } else {
                with = one(packs[p], 1000, 20.0, 1);
                without = one(packs[p], 1000, 20.0, 0);
            }
            r[k] = with / without;
            printf("%7.2f %6d %10.4f %10.4f %8.4f\n", packs[p], k, with, without, r[k]);
        }
        qsort(r, PAIRS, sizeof *r, cmp);
        printf("packing %.2f: median ratio with/without the validity count %.4f (target <= 1.05)\n",
               packs[p], 0.5 * (r[PAIRS / 2 - 1] + r[PAIRS / 2]));
    }
    return rc_test_failures == 0 ? 0 : 1;
}
