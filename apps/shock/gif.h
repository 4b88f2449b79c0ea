/* gif.h — relcol-shock --gif: an animated GIF of the profiles over the run's times
 * (issue 40 item 2), drawn by gnuplot's `gif animate` terminal from profiles.csv. */
#ifndef RELCOL_SHOCK_GIF_H
#define RELCOL_SHOCK_GIF_H

#include "shock_run.h"

/* Writes dir/profiles_gif.gp and, with gnuplot, dir/profiles.gif (through a temporary
 * name): one frame per time, n, v and p against x, the balls with their seed errors
 * beside the ideal fluid and free streaming, each frame titled with t, c and Kn at t.
 * *made: 1 when the GIF was made. 0, or -1 with err. */
int sh_gif(const char *prog, const char *dir, const sh_opts *o, const sh_result *r, int *made,
           char *err);

#endif
