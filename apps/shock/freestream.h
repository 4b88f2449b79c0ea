/* freestream.h — the Kn -> inf reference: the moments (moments.h) of two Juttner
 * (Maxwell at c = inf) halves, each at rest or moving along x, streaming freely in a tube [0, L] walled at both
 * ends, the membrane at x0 removed at t = 0 (papers/shock-tube.md, section 4): the walls
 * unfolded into a circle of length 2L, each moment a sum over the halves' images of a
 * momentum integral over the v_x that reach x at t, in the longitudinal rapidity with
 * the transverse integral closed form. Point balls of rest mass 1. */
#ifndef RELCOL_SHOCK_FREESTREAM_H
#define RELCOL_SHOCK_FREESTREAM_H

#include "moments.h"

typedef struct fs_def {
    int dim;          /* 2 or 3 */
    double c;         /* INFINITY: Maxwell */
    double L, x0;     /* tube length and membrane position */
    double n[2], T[2];/* rest-frame densities and temperatures of the left, right halves */
    double v[2];      /* their table-frame velocities along x, |v| < c */
} fs_def;

/* the moments at (x, t), t > 0 (t = 0: the initial state). 0, or RS_ENOCONV. */
int fs_moments(const fs_def *d, double x, double t, sh_mom *out);
/* their average over [xa, xb] (Gauss-Legendre, 8 points) */
int fs_moments_bin(const fs_def *d, double xa, double xb, double t, sh_mom *out);

#endif
