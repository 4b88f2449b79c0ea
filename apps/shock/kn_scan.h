/* kn_scan.h — relcol-shock --kn-scan (issue 40 item 5): one state at one c read at one
 * time, the ball radius set for each Knudsen number of a list, the measured profile's
 * distance (distance.h) from the ideal fluid and from free streaming; CSV, JSON and two
 * figures (papers/shock-tube.md, section 7). */
#ifndef RELCOL_SHOCK_KN_SCAN_H
#define RELCOL_SHOCK_KN_SCAN_H

#include "shock_run.h"

#define SH_MAX_KN 16
#define SH_KN_MAX 1000.0       /* beyond, the tube is free streaming to its noise */
#define SH_KN_MAX_PACKING 0.01 /* the kinetic p misses the virial 4 phi (3-D): 4 % here */

/* The radius r that gives Kn = lambda*_R / (headR t) at read time t, lambda*_R =
 * 1 / (sqrt 2 n*_R sigma(r)) the mean free path in the right plateau of the fluid
 * solution (the definition sh_run's kn uses), and the densest start's packing fraction
 * (table frame) at that r. -1 with err for a state with no fluid solution, a right wave
 * that is not a shock, or a radius whose start is denser than SH_KN_MAX_PACKING. */
int sh_kn_radius(const sh_tube *t, double tread, double kn, double *r, double *packing,
                 char *err);

/* Runs o at each kn[0..n-1] (increasing; o->tube.r replaced), reads the last time;
 * writes dir/kn_scan.csv, kn_scan_profiles.csv, kn_scan.json, kn_scan.gp,
 * kn_scan_profiles.gp (and their PNGs with gnuplot). 0, or -1 with err. */
int sh_kn_scan(const char *prog, const sh_opts *o, const double *kn, int n, const char *dir,
               int verbose, char *err);

#endif
