/* bench_eos.c — the cost of a measurement (issue 17, benchmark): one equation-of-state
 * point of N = 10^4 classical hard spheres at packing 0.3 to 0.3 % standard error in Z
 * (eos_measure, as relcol-eos runs it), timed, and against the engine's plain run of the
 * same length (the same start, one rc_sim_advance to the same time, no readings): the
 * ratio is what measuring costs. Arguments: [N] [t_run in mean free times]. */
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
    eos_in in = {3, 10000, 0.3, 1.0, INFINITY, NULL, 3, 20.0, 40.0, 20, 50, 0, 1.0, 0, 0.0, NULL, NULL, NULL};
    in.frame = rc_toi_frame_find("sphere");
    if (argc > 1)
        in.n = (size_t)atol(argv[1]);
    if (argc > 2)
        in.t_run = atof(argv[2]);
    char err[256];
    eos_out r;
    const double t0 = now();
    if (eos_measure(&in, &r, err) != 0) {
        fprintf(stderr, "bench_eos: %s\n", err);
        return 1;
    }
    const double t_meas = now() - t0;
    rc_sim *s = NULL;
    double box;
    const double t1 = now(); /* (the start counted in both) */
    if (eos_start(&in, &s, &box, err) != 0) {
        fprintf(stderr, "bench_eos: %s\n", err);
        return 1;
    }
    const int st = rc_sim_advance(s, (in.t_equil + in.t_run) * r.tau_free, 0);
    const double t_plain = now() - t1;
    rc_sim_diag d;
    rc_sim_diagnostics(s, &d);
    rc_sim_free(&s);
    if (st != RC_OK)
        return 1;
    printf("bench_eos: N = %zu, packing %.2f, %.0f + %.0f mean free times, %d blocks (a "
           "reading of the moments at each end)\n", in.n, in.packing, in.t_equil, in.t_run,
           in.blocks);
    printf("Z = %.5f +- %.5f (%.3f %%; Kolafa %.5f), %llu collisions\n", r.z, r.z_se,
           100.0 * r.z_se / r.z, eos_z_kolafa(in.packing), (unsigned long long)r.collisions);
    printf("measurement %.2f s CPU, plain engine run %.2f s (%llu collisions): x %.3f\n", t_meas,
           t_plain, (unsigned long long)d.collisions, t_meas / t_plain);
    return r.z_se / r.z <= 0.003 ? 0 : 1;
}
