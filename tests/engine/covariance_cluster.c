/* covariance_cluster — many-body frame dependence of the engine (issue 16, item 3, the
 * measurement; relcol-covariance sweeps the same over density and c): an open cluster of
 * 64 discs (rest radius 0.5, m = 1, c = 1) converging from a ring in a box far too large
 * to reach, run from the table frame and from a frame moving at 0.6c along x, whose
 * initial data are the same worldlines cut at its t' = 0 (both runs start before any
 * collision: checked). The final four-momenta of the moving run, boosted back, are
 * compared ball by ball with the table run's, for every frame of rc_toi_frames; beside
 * it, the table run against itself with the positions moved by 1e-15 relative (how much
 * the dynamics amplifies round-off). A measurement printed per frame, not a test (the
 * app's test, tests/covariance, checks the classical case). The harness itself is
 * apps/covariance/cluster.h. */
#include <stdio.h>

#include "cluster.h"

static int measure(double outer, double c)
{
    /* discs on a ring of radii 16..outer around the centre, 2 diameters apart, moving
     * inwards at 0.35 plus noise: they meet near the centre after ~50 r/c */
    cov_def d = {.dim = 2, .n = 64, .r = 0.5, .inner = 16.0, .outer = outer, .v_in = 0.35,
                 .v_noise = 0.15, .v_rms = 0.0, .c = c, .u = 0.6, .box = 4000.0,
                 .t_end = 800.0 /* long after the last collision, long before a wall */,
                 .seed = 16};
    cov_cluster cl;
    int e = cov_cluster_make(&d, rc_toi_frames[0], &cl);
    if (e != COV_OK) {
        printf("covariance_cluster: %s\n", cov_strerror(e));
        return 1;
    }
    printf("open cluster: %zu discs on a ring of radii %g..%g, c = %g, moving frame %g; t' = 0 "
           "spans table times [%.2f, %.2f]\n", d.n, d.inner, outer, c, d.u, cl.tmin, cl.tmax);
    printf("%-9s %10s %11s %12s %12s %12s %12s\n", "frame", "coll.table", "coll.moving",
           "dp(frames)", "dp(1e-15)", "dx(frames)", "dx(1e-15)");
    for (size_t f = 0; rc_toi_frames[f]; f++) {
        const rc_toi_frame *fr = rc_toi_frames[f];
        cov_result r;
        if (cov_compare(&d, fr, &cl, &r) != 0) {
            /* (the sphere frame's uncontracted discs may overlap on the moving frame's
             * slice: that frame is not covariant even in its shapes) */
            printf("%-9s refused the start of the %s run: %s\n", fr->name,
                   r.which == 1 ? "moving" : "table", rc_strerror(r.status));
            continue;
        }
        if (r.early[0] != 0) {
            printf("%-9s a collision before the moving frame's t' = 0 (table run)\n", fr->name);
            continue;
        }
        printf("%-9s %10llu %11llu %12.3e %12.3e %12.3e %12.3e\n", fr->name,
               (unsigned long long)r.coll[0], (unsigned long long)r.coll[1], r.dp_frames,
               r.dp_roundoff, r.dx_frames, r.dx_roundoff);
    }
    cov_cluster_free(&cl);
    return 0;
}

int main(void)
{
    /* a denser ring (a few collisions per disc) and a sparser one (fewer: less chaos);
     * then the harness itself: classically the change of frame is Galilean and the engine
     * Galilean invariant, so the frames differ by round-off amplified as dp(1e-15) is */
    return measure(30.0, 1.0) || measure(120.0, 1.0) || measure(30.0, INFINITY);
}
