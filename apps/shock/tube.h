/* tube.h — relcol-shock's tube (papers/shock-tube.md, section 1): a box walled along x,
 * periodic across, two Juttner (Maxwell at c = inf) halves at their own rest-frame
 * density n, temperature T and table-frame velocity v, no ball reaching across the
 * membrane at x0; the engine made for it (relcol/sim.h, public API only). m = 1. */
#ifndef RELCOL_SHOCK_TUBE_H
#define RELCOL_SHOCK_TUBE_H

#include <stddef.h>
#include <stdint.h>

#include "relcol/rng.h"
#include "relcol/sim.h"

typedef struct sh_tube {
    int dim;
    double c;
    rc_vec3 box;                 /* box.x the tube's length, box.y (box.z) across */
    double x0;                   /* the membrane */
    double r;                    /* ball radius */
    double n[2], T[2], v[2];     /* left, right */
    const rc_toi_frame *frame;   /* NULL: uncontracted spheres */
    const rc_law *law;           /* NULL: the engine's default */
} sh_tube;

/* balls on each side: round(n W A x_side) (lab density n W over the side's whole volume) */
size_t sh_tube_count(const sh_tube *t, int side);

/* the densest side the start places (packing fraction in the table frame) */
#define SH_TUBE_MAX_PACKING 0.2

/* The start of seed `seed`: *out (malloc'ed, *nout entries; left side first). -1 with err
 * for a side too dense to place (above SH_TUBE_MAX_PACKING, or a ball with no room after
 * 1e5 tries), or no memory. */
int sh_tube_balls(const sh_tube *t, uint64_t seed, rc_sim_ball **out, size_t *nout, char *err);

/* An engine for the tube holding balls b. -1 with err (the engine's reason). */
int sh_tube_sim(const sh_tube *t, size_t n, const rc_sim_ball *b, rc_sim **out, char *err);

/* Draw a rest-frame Juttner (Maxwell at c = inf) momentum at temperature T, boosted to
 * the table-frame velocity v along x as counted at one table time (exact, by rejection). */
rc_vec3 sh_juttner_momentum(int dim, double c, double T, double v, rc_rng *rng);

#endif
