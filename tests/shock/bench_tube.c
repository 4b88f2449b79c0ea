/* bench_tube — issue 40's benchmark: a 10^5-ball 3-D shock tube (Sod's state in table
 * units, densities / 64: n 0.015625 | 0.001953125, T 1 | 0.8, r = 0.5, L = 5000, W = 48)
 * run until the fluid's shock reaches the far quarter (x = 3L/4), its CPU time per
 * collision as a ratio to a plain periodic gas of the same N in the same box (periodic
 * along x too, the mean density everywhere, the temperature that holds the same energy)
 * run for as many collisions, both in this process. Collisions are ball-ball contacts. The
 * balls' placement is not timed. Usage: bench_tube [W [c]] (W = 16: about 11 000 balls). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "app.h"
#include "riemann.h"
#include "tube.h"

static double now(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t ball_collisions(const rc_sim *s)
{
    rc_sim_diag dg;
    rc_sim_diagnostics(s, &dg);
    return dg.events[RC_SIM_EV_BALL] + dg.events[RC_SIM_EV_MULTI];
}

/* advance until t_end or `until` collisions (0: no bound); CPU and wall seconds. The
 * chunk grows with N and the collisions are read once a chunk: rc_sim_diagnostics scans
 * every ball (its overlap check), which at 20 000 events a chunk and two reads was 10 % of
 * a 25 000-ball run's profile */
static int run(rc_sim *s, double t_end, uint64_t until, double *cpu, double *wall)
{
    const double c0 = now(CLOCK_PROCESS_CPUTIME_ID), w0 = now(CLOCK_MONOTONIC);
    const size_t chunk = 20000 + 20 * rc_sim_count(s);
    int st = RC_OK;
    for (;;) {
        st = rc_sim_advance(s, t_end, chunk);
        rc_sim_diag dg;
        rc_sim_diagnostics(s, &dg);
        if (st != RC_OK || (until ? dg.events[RC_SIM_EV_BALL] + dg.events[RC_SIM_EV_MULTI] >= until
                                  : dg.time >= t_end))
            break;
    }
    *cpu = now(CLOCK_PROCESS_CPUTIME_ID) - c0, *wall = now(CLOCK_MONOTONIC) - w0;
    return st;
}

int main(int argc, char **argv)
{
    const double W = argc > 1 ? atof(argv[1]) : 48.0, c = argc > 2 ? atof(argv[2]) : INFINITY;
    sh_tube t = {.dim = 3, .c = c, .r = 0.5, .n = {0.015625, 0.001953125}, .T = {1.0, 0.8}};
    t.box = rc_v3(5000.0, W, W);
    t.x0 = 2500.0;
    char err[APP_ERR_LEN];
    rs_eos eos = isinf(c) ? rs_eos_ideal(5.0 / 3.0) : rs_eos_synge(3);
    rs_solution sol;
    rs_state L = {t.n[0], 0.0, t.n[0] * t.T[0]}, R = {t.n[1], 0.0, t.n[1] * t.T[1]};
    if (rs_solve(&eos, c, L, R, &sol)) {
        fprintf(stderr, "bench_tube: the Riemann solution failed\n");
        return 1;
    }
    const double t_end = 0.25 * t.box.x / sol.headR;
    rc_sim_ball *b = NULL, *bg = NULL;
    size_t n = 0, ng = 0;
    rc_sim *s = NULL, *g = NULL;
    /* the plain gas: both halves at the mean density and the energy's temperature, then
     * the x walls made periodic */
    sh_tube pg = t;
    const double nm = 0.5 * (t.n[0] + t.n[1]);
    pg.n[0] = pg.n[1] = nm;
    pg.T[0] = pg.T[1] = (t.n[0] * t.T[0] + t.n[1] * t.T[1]) / (2.0 * nm);
    if (sh_tube_balls(&t, 1, &b, &n, err) || sh_tube_sim(&t, n, b, &s, err) ||
        sh_tube_balls(&pg, 2, &bg, &ng, err)) {
        fprintf(stderr, "bench_tube: %s\n", err);
        return 1;
    }
    rc_sim_def d = rc_sim_def_default();
    d.dim = 3, d.box = t.box, d.c = c, d.eps_ball = d.eps_wall = 1.0;
    d.boundary[0] = d.boundary[1] = d.boundary[2] = RC_SIM_PERIODIC;
    d.cell_size = fmin(fmax(1.0, cbrt(t.box.x * W * W / (double)ng)), W / 4.0); /* (sh_tube_sim's) */
    size_t bad;
    if (rc_sim_create(&d, &g) || rc_sim_set_balls(g, ng, bg, &bad)) {
        fprintf(stderr, "bench_tube: the periodic gas: engine refused it\n");
        return 1;
    }
    double tc, tw, gc, gw;
    int st = run(s, t_end, 0, &tc, &tw);
    const uint64_t nc = ball_collisions(s);
    if (st == RC_OK)
        st = run(g, INFINITY, nc, &gc, &gw);
    if (st != RC_OK) {
        fprintf(stderr, "bench_tube: %s\n", rc_strerror(st));
        return 1;
    }
    const uint64_t gn = ball_collisions(g);
    printf("shock tube: %zu balls (periodic gas %zu), c = %g, to t = %.4g (the shock at 3L/4)\n",
           n, ng, c, t_end);
    printf("  tube %.3g s CPU (%.3g s wall), %llu collisions, %.3g us/collision\n", tc, tw,
           (unsigned long long)nc, 1e6 * tc / (double)nc);
    printf("  periodic gas %.3g s CPU, %llu collisions, %.3g us/collision\n", gc,
           (unsigned long long)gn, 1e6 * gc / (double)gn);
    printf("  ratio tube / periodic gas per collision: %.3f\n", (tc / (double)nc) / (gc / (double)gn));
    free(b), free(bg);
    rc_sim_free(&s), rc_sim_free(&g);
    return 0;
}
