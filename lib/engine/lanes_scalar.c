/* engine/lanes_scalar.c — the engine's lane kernels (engine/kernels.h) in one lane of
 * plain C: every machine has them, and they are the reference the wider lanes match. */
#define ENG_W 1
#include "kernels.h"

const eng_lanes eng_lanes_scalar = {test_list, sphere_times, gather_rows, cross_event};
