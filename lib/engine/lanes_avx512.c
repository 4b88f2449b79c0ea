/* engine/lanes_avx512.c — the engine's lane kernels (engine/kernels.h) in eight lanes of
 * AVX-512F, the walk's slots in AVX-512VL. Built with -mavx512f -mavx512vl
 * (lib/meson.build; the build contracts no multiply and add, -ffp-contract=off), and
 * called only where the CPU has both (rc_sim_create asks it). */
#include "lanes.h"
#ifdef ENG_HAVE_AVX512
#define ENG_W 8
#include "kernels.h"

/* A cell crossing has three dimensions: AVX2's four lanes hold them, and eight would only
 * make its division and its reduction over the lanes slower (every AVX-512 CPU has
 * AVX2). The neighbour tests fill eight lanes. */
const eng_lanes eng_lanes_avx512 = {test_list, sphere_times, gather_rows,
                                       eng_cross_event_avx2};
#else
typedef int eng_lanes_avx512_absent; /* (ISO C wants a declaration in every file) */
#endif
