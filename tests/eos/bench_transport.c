/* bench_transport.c — the cost of eta and lambda at 2 % standard error (issue 39): one
 * relcol-eos --transport point of classical spheres, dilute (packing 0.02) and at packing
 * 0.3, timed (CPU of this process), against the engine's plain run of the same length (the
 * same start, one rc_sim_advance to the same time, no readings). The time to 2 % is the
 * run's time scaled by (worse relative error / 0.02)^2 (the estimators' variance falls as
 * 1 / run length; papers/transport.md, section 11). Arguments: [N] [t_run in mean free
 * times] [c] [frame]. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "eos_run.h"

/* CPU time of this process: the machine's other work does not count */
static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv)
{
    const double pack[2] = {0.02, 0.3};
    for (int ip = 0; ip < 2; ip++) {
        /* lag 16 mean free times: the Green–Kubo integrals' plateau begins by 8 (eta 4-6,
         * lambda 8-10, dilute and at 0.3), where the Einstein–Helfand window's flat part
         * ends */
        eos_in in = {3, 1000, pack[ip], 1.0, INFINITY, NULL, 1, 30.0, 40000.0, 30, 400, 1,
                     16.0, 0, 0.0, NULL, NULL, NULL};
        in.frame = rc_toi_frame_find(argc > 4 ? argv[4] : "sphere");
        if (argc > 1)
            in.n = (size_t)atol(argv[1]);
        if (argc > 2)
            in.t_run = atof(argv[2]);
        if (argc > 3)
            in.c = atof(argv[3]); /* "inf" parses as INFINITY */
        if (!in.frame || in.n < 4 || !(in.t_run > 0.0) || !(in.c > 0.0)) {
            fprintf(stderr, "bench_transport: bad arguments (N t_run c frame)\n");
            return 2;
        }
        in.per_block = (int)(in.t_run / in.blocks + 0.5); /* a reading each mean free time */
        char err[256];
        eos_out r;
        const double t0 = now();
        if (eos_measure(&in, &r, err) != 0) {
            fprintf(stderr, "bench_transport: %s\n", err);
            return 1;
        }
        const double t_meas = now() - t0;
        rc_sim *s = NULL;
        double box;
        const double t1 = now(); /* (the start counted in both) */
        if (eos_start(&in, &s, &box, err) != 0) {
            fprintf(stderr, "bench_transport: %s\n", err);
            return 1;
        }
        const int st = rc_sim_advance(s, (in.t_equil + in.t_run) * r.tau_free, 0);
        const double t_plain = now() - t1;
        rc_sim_free(&s);
        if (st != RC_OK)
            return 1;
        const double re = r.eta_se / r.eta, rl = r.lambda_se / r.lambda;
        const double worse = re > rl ? re : rl, f = (worse / 0.02) * (worse / 0.02);
        printf("bench_transport: N = %zu, packing %.2f, c = %g, frame %s, %.0f + %.0f mean free "
               "times, lag %.0f, %d blocks\n", in.n, in.packing, in.c, in.frame->name,
               in.t_equil, in.t_run, in.lag, in.blocks);
        printf("  eta = %.5f +- %.5f (%.2f %%), Green-Kubo %.5f +- %.5f; lambda = %.5f +- %.5f "
               "(%.2f %%), Green-Kubo %.5f +- %.5f; %llu collisions\n", r.eta, r.eta_se,
               100.0 * re, r.eta_f.gk, r.eta_f.gk_se, r.lambda, r.lambda_se, 100.0 * rl,
               r.lambda_f.gk, r.lambda_f.gk_se, (unsigned long long)r.collisions);
        printf("  measurement %.2f s CPU, plain engine run %.2f s: x %.3f; to 2 %% on both: "
               "%.0f mean free times, %.3g collisions, %.1f s CPU\n", t_meas, t_plain,
               t_meas / t_plain, in.t_run * f, (double)r.collisions * f, t_meas * f);
    }
    return 0;
}
