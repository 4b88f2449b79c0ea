/* relcol/rng.h — relcol's one seeded random generator: splitmix64 (Steele, Lea & Flood,
 * "Fast splittable pseudorandom number generators", OOPSLA 2014), used by the library's
 * gas start (rc_sim_gas_init), the apps, the tests and the notebooks, so that a seed means
 * the same numbers everywhere. 64 bits of state, any seed (0 included) is good, period
 * 2^64; not for cryptography. */
#ifndef RELCOL_RNG_H
#define RELCOL_RNG_H

#include <stdint.h>

/// The generator's state.
typedef struct rc_rng {
    uint64_t state; ///< the seed, then advanced by each draw (set it directly, or {seed})
} rc_rng;

/// The next 64 random bits.
uint64_t rc_rng_next(rc_rng *r);
/// Uniform in [0, 1): the top 53 bits of rc_rng_next, a multiple of 2^-53.
double rc_rng_uniform(rc_rng *r);
/// Standard normal (Box-Muller from two uniforms; one value a call).
double rc_rng_gauss(rc_rng *r);

#endif
