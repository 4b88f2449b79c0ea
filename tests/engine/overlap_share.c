/* overlap_share — the share of contacts decided by the overlap policy (rc_sim_diag.overlaps
 * over collisions) in every contracted frame of the library's table, over the range issue
 * 16 names: 2-D to packing 0.7 and 3-D to 0.45, rms 0.5c and 0.9c, eps 1 and eps 0.5 with
 * the TC model, with the covariant frame's tube and order conflicts and collisions undone.
 * A measurement, not a
 * test: the table and zmf frames change a ball's shape at one table instant, and the
 * covariant frame's glued tubes leave the contacts within a glue window to its rules
 * (papers/model-regime.md, section 4). Prints one line per run and the largest share;
 * argv[1] names one frame. Exit status 0 unless a run fails. (A benchmark target: meson
 * test --benchmark --suite relcol overlap-share.) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine_util.h"

/* contacts per run: enough that a share of 0.1 % is a count of a few */
#define CONTACTS 4000

int main(int argc, char **argv)
{
    /* argv[1] (optional): only the frame of that name */
    const char *only = argc > 1 ? argv[1] : NULL;
    const int dims[2] = {2, 3};
    const double packs[2][2] = {{0.3, 0.7}, {0.2, 0.45}};
    const size_t ns[2] = {400, 216};
    const double vs[2] = {0.5, 0.9};
    double worst = 0.0;
    printf("%-9s %3s %7s %5s %5s %9s %9s %8s %6s %6s %6s\n", "frame", "dim", "packing", "v_rms",
           "eps", "contacts", "overlaps", "share", "tube", "order", "undone");
    for (size_t f = 0; rc_toi_frames[f]; f++) {
        const rc_toi_frame *fr = rc_toi_frames[f];
        if (!fr->contracted || (only && strcmp(only, fr->name) != 0))
            continue;
        for (int di = 0; di < 2; di++)
            for (int pi = 0; pi < 2; pi++)
                for (int vi = 0; vi < 2; vi++)
                    for (int ei = 0; ei < 2; ei++) {
                        rc_sim_def d = rc_sim_def_default();
                        d.dim = dims[di];
                        d.c = 1.0;
                        d.frame = fr;
                        d.eps_ball = ei ? 0.5 : 1.0;
                        /* TC: elastic within a tenth of a radius' light time of the last
                         * collision (keeps the inelastic gas from collapsing) */
                        d.t_c = ei ? 0.05 : 0.0;
                        rc_sim *s = util_gas(d, ns[di], packs[di][pi], vs[vi], 16);
                        if (!s)
                            return 1;
                        util_run_collisions(s, CONTACTS);
                        rc_sim_diag g;
                        rc_sim_diagnostics(s, &g);
                        const double share = (double)g.overlaps / (double)g.collisions;
                        worst = share > worst ? share : worst;
                        printf("%-9s %3d %7.2f %5.2f %5.2f %9llu %9llu %7.3f%% %6llu %6llu %6llu\n",
                               fr->name, d.dim, packs[di][pi], vs[vi], d.eps_ball,
                               (unsigned long long)g.collisions,
                               (unsigned long long)g.overlaps, 100.0 * share,
                               (unsigned long long)g.tube_conflicts,
                               (unsigned long long)g.order_conflicts,
                               (unsigned long long)g.rollbacks);
                        fflush(stdout);
                        rc_sim_free(&s);
                    }
    }
    printf("largest share %.3f%% (target 0.1%%)\n", 100.0 * worst);
    return rc_test_failures == 0 ? 0 : 1;
}
