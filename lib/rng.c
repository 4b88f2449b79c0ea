/* rng.c — splitmix64 (relcol/rng.h). */
#include <math.h>

#include "relcol/rng.h"

uint64_t rc_rng_next(rc_rng *r)
{
    uint64_t z = (r->state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double rc_rng_uniform(rc_rng *r) { return (double)(rc_rng_next(r) >> 11) * 0x1.0p-53; }

double rc_rng_gauss(rc_rng *r)
{
    /* log1p(-u): u in [0, 1), so 1 - u in (0, 1] and the logarithm is finite */
    const double u = rc_rng_uniform(r), v = rc_rng_uniform(r);
    return sqrt(-2.0 * log1p(-u)) * cos(2.0 * M_PI * v);
}
