/* engine_lanes_avx512.c — the engine's lane kernels (engine_kernels.h) in eight lanes of
 * AVX-512F, the walk's slots in AVX-512VL. Built with -mavx512f -mavx512vl
 * (lib/meson.build; the build contracts no multiply and add, -ffp-contract=off), and
 * called only where the CPU has both (rc_sim_create asks it). */
#include "engine_lanes.h"
#ifdef ENG_HAVE_AVX512
#define ENG_W 8
#define ENG_LANES_TABLE rc_eng_lanes_avx512
#include "engine_kernels.h"
#else
typedef int eng_lanes_avx512_absent; /* (ISO C wants a declaration in every file) */
#endif
