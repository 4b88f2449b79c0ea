/* covariance_cluster — many-body frame dependence of the engine (issue 16, item 3, the
 * measurement): an open cluster of 64 discs (rest radius 0.5, m = 1, c = 1) converging at
 * rms 0.5c in a box far too large to reach, run from the table frame and from a frame
 * moving at 0.6c along x, whose initial data are the same worldlines cut at its t' = 0
 * (both runs start before any collision: checked). The final four-momenta of the moving
 * run, boosted back, are compared ball by ball with the table run's, for every frame of
 * rc_toi_frames; beside it, the table run against itself with the positions moved by
 * 1e-15 relative (how much the dynamics amplifies round-off), and the overlap-policy
 * contacts of both runs (and the covariant frame's conflicts). The harness is
 * relcol-covariance's (apps/covariance/cluster.h). A measurement printed per frame;
 * test_engine_covariant asserts the covariant frame's. */
#include <math.h>
#include <stdio.h>

#include "cluster.h"

/* The ring of radii 16..outer: inwards at 0.35 plus up to 0.15 per component (rms about
 * 0.5), in a box no ball reaches before t_end (the fastest, under c, from 400 off the
 * centre); t_end long after the last collision in both runs (their ends are different
 * hyperplanes: a collision between them would count in one run only; checked, the
 * column "open"). */
static cov_def ring(double outer, double c)
{
    return (cov_def){.dim = 2, .n = 64, .r = 0.5, .inner = 16.0, .outer = outer, .v_in = 0.35,
                     .v_noise = 0.15, .v_rms = 0.0, .c = c, .u = 0.6, .box = 20000.0,
                     .t_end = 6000.0, .seed = 16};
}

static int measure(const cov_def *d)
{
    cov_cluster cl;
    const int e = cov_cluster_make(d, rc_toi_frames[0], &cl);
    if (e != COV_OK) {
        fprintf(stderr, "covariance_cluster: %s\n", cov_strerror(e));
        return 1;
    }
    printf("open cluster: %zu discs on a ring of radii %g..%g, c = %g, moving frame %g; t' = 0 "
           "spans table times [%.2f, %.2f]\n", d->n, d->inner, d->outer, d->c, d->u, cl.tmin,
           cl.tmax);
    printf("%-9s %10s %10s %12s %12s %9s %6s %6s %6s %5s\n", "frame", "coll.table", "coll.moving",
           "dp(frames)", "dp(1e-15)", "overlaps", "tube", "order", "undone", "open");
    for (size_t f = 0; rc_toi_frames[f]; f++) {
        const rc_toi_frame *fr = rc_toi_frames[f];
        cov_result r;
        if (cov_compare(d, fr, &cl, &r) != 0) {
            if (r.status == RC_ENOMEM) {
                cov_cluster_free(&cl);
                return 1;
            }
            /* (the sphere frame's uncontracted discs may overlap on the moving frame's
             * slice: that frame is not covariant even in its shapes) */
            printf("%-9s the %s run: %s\n", fr->name,
                   r.which == 0 ? "table" : r.which == 1 ? "moving" : "round-off",
                   rc_strerror(r.status));
            continue;
        }
        if (r.early[0] != 0) {
            printf("%-9s a collision before the moving frame's t' = 0 (table run)\n", fr->name);
            continue;
        }
        printf("%-9s %10llu %10llu %12.3e %12.3e %4llu/%-4llu %6llu %6llu %6llu %5llu%s\n", fr->name,
               (unsigned long long)r.coll[0], (unsigned long long)r.coll[1], r.dp_frames,
               r.dp_roundoff, (unsigned long long)r.overlaps[0],
               (unsigned long long)r.overlaps[1], (unsigned long long)(r.tube[0] + r.tube[1]),
               (unsigned long long)(r.order[0] + r.order[1]),
               (unsigned long long)(r.undone[0] + r.undone[1]),
               (unsigned long long)(r.open[0] + r.open[1] + r.open[2]),
               r.walls ? " (a wall reached)" : "");
    }
    cov_cluster_free(&cl);
    return 0;
}

int main(void)
{
    /* a denser ring (a few collisions per disc) and sparser ones (fewer: less chaos) */
    const cov_def d30 = ring(30.0, 1.0), d120 = ring(120.0, 1.0), d400 = ring(400.0, 1.0);
    /* the harness itself: classically the change of frame is Galilean and the engine
     * Galilean invariant, so the frames differ by round-off amplified as dp(1e-15) is */
    const cov_def dcl = ring(30.0, INFINITY);
    return measure(&d30) || measure(&d120) || measure(&d400) || measure(&dcl);
}
