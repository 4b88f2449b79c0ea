/* distance.h — how far a measured profile is from a reference (papers/shock-tube.md,
 * section 7): the L2 distance of n, v and p over the span the waves have reached,
 * each normalised by the distance between the ideal fluid and free streaming there, the
 * statistical noise of the seed means subtracted, so that 0 is the reference itself and
 * 1 the other reference. */
#ifndef RELCOL_SHOCK_DISTANCE_H
#define RELCOL_SHOCK_DISTANCE_H

#include "shock_run.h"

enum { SH_REF_FLUID = 0, SH_REF_FREE = 1, SH_DIST_NQ = 3 };

typedef struct sh_dist {
    double d, err;              /* D = sqrt(mean over n, v, p of D_q^2), its error */
    double dq[SH_DIST_NQ];      /* per quantity (n, v, p): sqrt(D_q^2), NAN if none */
    int bins;                   /* bins in the span */
} sh_dist;

/* The span of time j: bins whose centre lies at xi = (x - x0)/t in [headL - w/4,
 * headR + w/4], w = headR - headL (the fluid's outer waves; free streaming's spread
 * reaches a little beyond). *k0, *k1: the first and one past the last. */
void sh_dist_span(const sh_result *r, double x0, double t, int *k0, int *k1);

/* D of r's measured profile at time j from reference `ref` (SH_REF_FLUID or
 * SH_REF_FREE) over bins [k0, k1). 0, or -1 when the references coincide there (no
 * normalisation: a state with no waves). */
int sh_distance(const sh_result *r, int j, int k0, int k1, int ref, sh_dist *out);

#endif
