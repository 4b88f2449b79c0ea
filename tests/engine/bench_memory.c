/* bench_memory.c — what a cache miss costs on this machine, the bound on the engine's
 * time per collision past N = 1e4 (papers/relcol.md §7): random dependent loads through
 * arrays the size of the engine's per-ball state at N = 1e4, 1e5 and 1e6 (one 64-byte line
 * a load), one chain at a time (latency) and eight chains interleaved (how many misses the
 * core overlaps), on small pages and on transparent huge pages (the engine's, lib/
 * engine/mem.c). Usage: bench_memory [bytes ...] (default 2e6 2e7 2e8). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "relcol/rng.h"
#ifdef __linux__
#include <sys/mman.h>
#endif

#define LINE 64
#define HUGE_PAGE ((size_t)2 << 20)
#define LOADS 20000000

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* ns per load over `chains` interleaved chains of one random cycle through n lines */
static double chase(const uint64_t *a, size_t n, int chains)
{
    size_t p[8];
    for (int k = 0; k < chains; k++)
        p[k] = (size_t)k * (n / (size_t)chains) * (LINE / sizeof *a);
    const size_t steps = LOADS / (size_t)chains;
    const double t0 = now_s();
    for (size_t s = 0; s < steps; s++)
        for (int k = 0; k < chains; k++)
            p[k] = (size_t)a[p[k]];
    const double dt = now_s() - t0;
    size_t sink = 0;
    for (int k = 0; k < chains; k++)
        sink += p[k];
    if (sink == (size_t)-1) /* (keeps the loads) */
        puts("");
    return dt / (double)(steps * (size_t)chains) * 1e9;
}

static int measure(size_t bytes, int huge)
{
    const size_t n = bytes / LINE, words = LINE / sizeof(uint64_t);
    const size_t size = (n * LINE + HUGE_PAGE - 1) / HUGE_PAGE * HUGE_PAGE;
    uint64_t *a = NULL;
    size_t *perm = malloc(n * sizeof *perm);
    if (n < 16 || posix_memalign((void **)&a, HUGE_PAGE, size) != 0 || !perm) {
        fprintf(stderr, "bench_memory: %zu bytes: too small or out of memory\n", bytes);
        free(a);
        free(perm);
        return 1;
    }
#ifdef MADV_HUGEPAGE
    if (huge)
        (void)madvise(a, size, MADV_HUGEPAGE);
#endif
    /* one cycle through all lines in random order (Sattolo's shuffle) */
    rc_rng seed = {2024};
    for (size_t i = 0; i < n; i++)
        perm[i] = i;
    for (size_t i = n - 1; i > 0; i--) {
        const size_t j = (size_t)(rc_rng_next(&seed) % i);
        const size_t t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    for (size_t i = 0; i < n; i++)
        a[perm[i] * words] = perm[(i + 1) % n] * words;
    const double one = chase(a, n, 1), eight = chase(a, n, 8);
    printf("%9.3g bytes, %s pages: %6.1f ns a dependent load, %5.1f ns a load with 8 chains "
           "(%.1f overlapped)\n",
           (double)bytes, huge ? "huge " : "small", one, eight, one / eight);
    free(a);
    free(perm);
    return 0;
}

int main(int argc, char **argv)
{
    static const double def[] = {2e6, 2e7, 2e8};
    const int nsizes = argc > 1 ? argc - 1 : 3;
    int bad = 0;
    for (int k = 0; k < nsizes; k++) {
        char *end = NULL;
        const double b = argc > 1 ? strtod(argv[k + 1], &end) : def[k];
        if (argc > 1 && (end == argv[k + 1] || *end || !(b >= 1024.0 && b <= 1e11))) {
            fprintf(stderr, "bench_memory: size '%s': not a number of bytes in [1024, 1e11]\n",
                    argv[k + 1]);
            return 2;
        }
        bad |= measure((size_t)b, 0);
        bad |= measure((size_t)b, 1);
    }
    return bad;
}
