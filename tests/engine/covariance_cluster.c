/* covariance_cluster — many-body frame dependence of the engine (issue 16, item 3, the
 * measurement): an open cluster of 64 discs (rest radius 0.5, m = 1, c = 1) converging at
 * rms 0.5c in a box far too large to reach, run from the table frame and from a frame
 * moving at 0.6c along x, whose initial data are the same worldlines cut at its t' = 0
 * (both runs start before any collision: checked; tests/engine/cluster_util.h). The final
 * four-momenta of the moving run, boosted back, are compared ball by ball with the table
 * run's, for every frame of rc_toi_frames; beside it, the table run against itself with
 * the positions moved by 1e-15 relative (how much the dynamics amplifies round-off), and
 * the overlap-policy contacts of both runs (and the covariant frame's conflicts). A
 * measurement printed per frame; test_engine_covariant asserts the covariant frame's. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cluster_util.h"

#define N 64

/* a box no ball reaches before t_end (the fastest, under c, from 400 off the centre) */
static cl_def K = {N, 20000.0, 0.6, 1.0, 1.0};

static int measure(double outer)
{
    rc_sim_ball bp[N], b0[N];
    double tmin = 0.0, tmax = 0.0;
    if (cl_draw(&K, outer, 16, b0, bp, &tmin, &tmax))
        return 1;
    rc_sim_ball bj[N]; /* the same with the positions moved by 1e-15 relative */
    for (int i = 0; i < N; i++)
        bj[i] = b0[i];
    for (int i = 0; i < N; i++) /* (-1, 0 or +1 times 1e-15 of x: not a translation) */
        bj[i].x.x *= 1.0 + 1e-15 * (double)(i % 3 - 1);
    /* long after the last collision in both runs (their ends are different hyperplanes:
     * a collision between them would count in one run only), long before a wall */
    const double t_end = 6000.0;
    printf("open cluster: %d discs on a ring of radii 16..%g, c = %g, moving frame 0.6; t' = 0 "
           "spans table times [%.2f, %.2f]\n", N, outer, K.c, tmin, tmax);
    printf("%-9s %10s %10s %12s %12s %9s %6s %6s\n", "frame", "coll.table", "coll.moving",
           "dp(frames)", "dp(1e-15)", "overlaps", "tube", "order");
    for (size_t f = 0; rc_toi_frames[f]; f++) {
        const rc_toi_frame *fr = rc_toi_frames[f];
        rc_vec3 pa[N], pb[N], pj[N];
        double ma[N], mb[N], mj[N];
        uint64_t na, nb, nj, ea, eb, ej;
        rc_sim_diag ga, gb;
        if (cl_run(&K, fr, b0, tmin, tmax, t_end, pa, ma, &na, &ea, &ga, 0) != RC_OK ||
            cl_run(&K, fr, bp, 0.0, 0.0, t_end, pb, mb, &nb, &eb, &gb, 0) != RC_OK ||
            cl_run(&K, fr, bj, tmin, tmax, t_end, pj, mj, &nj, &ej, NULL, 0) != RC_OK) {
            /* (the sphere frame's uncontracted discs may overlap on the moving frame's
             * slice: that frame is not covariant even in its shapes) */
            printf("%-9s refused the start (above)\n", fr->name);
            continue;
        }
        if (ea != 0) {
            printf("%-9s a collision before the moving frame's t' = 0 (table run)\n", fr->name);
            continue;
        }
        if (cl_back(&K, pb, mb))
            return 1;
        printf("%-9s %10llu %10llu %12.3e %12.3e %4llu/%-4llu %6llu %6llu\n", fr->name,
               (unsigned long long)na, (unsigned long long)nb, cl_pdiff(N, pa, pb),
               cl_pdiff(N, pa, pj), (unsigned long long)ga.overlaps,
               (unsigned long long)gb.overlaps,
               (unsigned long long)(ga.tube_conflicts + gb.tube_conflicts),
               (unsigned long long)(ga.order_conflicts + gb.order_conflicts));
    }
    return 0;
}

int main(void)
{
    /* a denser ring (a few collisions per disc) and a sparser one (fewer: less chaos) */
    int st = measure(30.0) || measure(120.0) || measure(400.0);
    /* the harness itself: classically the change of frame is Galilean and the engine
     * Galilean invariant, so the frames differ by round-off amplified as dp(1e-15) is */
    K.c = INFINITY;
    K.ic2 = 0.0;
    return st || measure(30.0);
}
