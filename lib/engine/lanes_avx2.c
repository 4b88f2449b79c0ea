/* engine/lanes_avx2.c — the engine's lane kernels (engine/kernels.h) in four lanes of
 * AVX2. Built with -mavx2 (lib/meson.build; no FMA, so the bits stay the plain C lane's),
 * and called only where the CPU has AVX2 (rc_sim_create asks it). */
#include "lanes.h"
#ifdef ENG_HAVE_AVX2
#define ENG_W 4
#include "kernels.h"

void eng_cross_event_avx2(rc_sim *s, int32_t i, const int c[3]) { cross_event(s, i, c); }

const eng_lanes eng_lanes_avx2 = {test_list, sphere_times, gather_rows,
                                     eng_cross_event_avx2};
#else
typedef int eng_lanes_avx2_absent; /* (ISO C wants a declaration in every file) */
#endif
