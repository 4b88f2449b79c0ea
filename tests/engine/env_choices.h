/* env_choices.h — the benchmarks' environment variables RELCOL_SIMD (avx512, avx2, scalar)
 * and RELCOL_DEFER (0, 1), read by the programs themselves (the library reads no
 * environment) into rc_sim_def.simd and .defer, so that a timing can force a path:
 * RELCOL_SIMD=avx2 scripts/ab-revs.sh ... */
#ifndef RELCOL_ENV_CHOICES_H
#define RELCOL_ENV_CHOICES_H

#include <stdlib.h>
#include <string.h>

#include "relcol/sim.h"

static inline void env_choices(rc_sim_def *d)
{
    const char *simd = getenv("RELCOL_SIMD"), *defer = getenv("RELCOL_DEFER");
    if (simd)
        d->simd = !strcmp(simd, "scalar") ? RC_SIM_SIMD_SCALAR
                  : !strcmp(simd, "avx2") ? RC_SIM_SIMD_AVX2
                  : !strcmp(simd, "avx512") ? RC_SIM_SIMD_AVX512
                                            : RC_SIM_SIMD_AUTO;
    if (defer)
        d->defer = !strcmp(defer, "0") ? RC_SIM_DEFER_OFF : RC_SIM_DEFER_AUTO;
}

#endif
