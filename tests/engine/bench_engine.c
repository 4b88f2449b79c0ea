/* bench_engine.c — engine throughput (meson benchmark): classical hard spheres at packing
 * 0.45 (N = 1e4, 1e5), discs at 0.7 (N = 1e4), a relativistic gas (rms speed 0.5 c) as a
 * cost ratio to the classical run of the same N and density measured in this process,
 * and bytes per ball. Each run melts the lattice start first (not timed).
 * Usage: bench_engine [quick|full|N|2d:N|rel:N|per:N|per2d:N|ratio] [collisions per ball];
 * full adds N = 1e6; N, 2d:N, rel:N run one case, timing 20 (rel: 5) collisions a ball or
 * as many as asked; per:N and per2d:N are N and 2d:N in a periodic box (every axis: the
 * box EDMD and most event-driven codes use, so every collision is a pair collision); ratio
 * only the interleaved contracted/classical cost ratio, the zmf and covariant frames'
 * cost per collision against the table frame's, and the covariant frame's against the
 * zmf frame's at packing 0.1.
 * Figures are CPU time of this process (the wall clock on a shared machine is noisier).
 * RELCOL_SIMD (avx512, avx2, scalar) and RELCOL_DEFER=0 force a path (env_choices.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "env_choices.h"
#include "relcol/relcol.h"

static double cpu_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* every axis periodic (per:N, per2d:N) instead of walls */
static int periodic_box;

typedef struct result {
    double rate;  /* collisions per CPU second */
    double bytes; /* per ball */
    double ok;
} result;

/* A gas (radius 1/2, rms speed 1 classically, 0.5 c otherwise) in a fresh engine, not yet
 * melted; NULL (with a message) on failure. */
static rc_sim *setup(int dim, size_t n, double packing, double c, const char *frame)
{
    rc_sim_gas_def g = {dim, n, 0.5, packing, isinf(c) ? 1.0 : 0.5 * c, c, 1.0, 2024};
    rc_sim_ball *b = calloc(n, sizeof *b); /* zeroed: rc_sim_gas_init leaves collided, tau_last */
    rc_sim_def d = rc_sim_def_default();
    env_choices(&d);
    d.dim = dim;
    d.c = c;
    for (int k = 0; k < 3; k++)
        d.boundary[k] = periodic_box ? RC_SIM_PERIODIC : RC_SIM_WALLS;
    if (frame)
        d.frame = rc_toi_frame_find(frame);
    rc_sim *s = NULL;
    int st = b ? rc_sim_gas_init(&g, &d.box, b) : RC_ENOMEM;
    if (st == RC_OK)
        st = rc_sim_create(&d, &s);
    if (st == RC_OK)
        st = rc_sim_set_balls(s, n, b, NULL);
    free(b);
    if (st != RC_OK) {
        fprintf(stderr, "setup failed: %s\n", rc_strerror(st));
        rc_sim_free(&s);
    }
    return s;
}

static result run(int dim, size_t n, double packing, double c, const char *frame,
                  double melt_per_ball, double measure_per_ball)
{
    result res = {0, 0, 0};
    rc_sim *s = setup(dim, n, packing, c, frame);
    if (!s)
        return res;
    rc_sim_diag d0, d1;
    /* melt: collisions per ball (events include crossings and stale entries: ~1.5x) */
    uint64_t melt = (uint64_t)(melt_per_ball * (double)n * 1.5);
    rc_sim_advance(s, INFINITY, melt);
    rc_sim_diagnostics(s, &d0);
    double t0 = cpu_s();
    rc_sim_advance(s, INFINITY, (uint64_t)(measure_per_ball * (double)n * 1.5));
    double t1 = cpu_s();
    rc_sim_diagnostics(s, &d1);
    res.rate = (double)(d1.collisions - d0.collisions) / (t1 - t0);
    res.bytes = (double)rc_sim_bytes(s) / (double)n;
    res.ok = 1;
    printf("  %dD N=%-8zu phi=%.2f c=%-5g frame=%-6s%s %10.0f collisions/s  %.3g s  %.1f B/ball "
           "(events: ball %llu wall %llu multi %llu cell %llu stale %llu; overlaps %llu)\n",
           dim, n, packing, c, frame ? frame : "sphere", periodic_box ? " periodic" : "",
           res.rate, t1 - t0, res.bytes,
           (unsigned long long)(d1.events[RC_SIM_EV_BALL] - d0.events[RC_SIM_EV_BALL]),
           (unsigned long long)(d1.events[RC_SIM_EV_WALL] - d0.events[RC_SIM_EV_WALL]),
           (unsigned long long)(d1.events[RC_SIM_EV_MULTI] - d0.events[RC_SIM_EV_MULTI]),
           (unsigned long long)(d1.events[RC_SIM_EV_CELL] - d0.events[RC_SIM_EV_CELL]),
           (unsigned long long)(d1.events[RC_SIM_EV_STALE] - d0.events[RC_SIM_EV_STALE]),
           (unsigned long long)(d1.overlaps - d0.overlaps));
    fflush(stdout);
    rc_sim_free(&s);
    return res;
}

/* Cost ratio of run B to run A per collision, measured interleaved: both engines advance
 * in alternating chunks of events, so both see the same load on a shared machine. */
static rc_sim *make(int dim, size_t n, double packing, double c, const char *frame)
{
    rc_sim *s = setup(dim, n, packing, c, frame);
    if (s)
        rc_sim_advance(s, INFINITY, (uint64_t)(15 * n)); /* melt */
    return s;
}

static double interleaved_ratio(rc_sim *a, rc_sim *b, uint64_t chunk_a, uint64_t chunk_b,
                                int rounds)
{
    double ta = 0, tb = 0;
    uint64_t ca = 0, cb = 0;
    for (int r = 0; r < rounds; r++) {
        rc_sim_diag d0, d1;
        rc_sim_diagnostics(a, &d0);
        double t0 = cpu_s();
        rc_sim_advance(a, INFINITY, chunk_a);
        ta += cpu_s() - t0;
        rc_sim_diagnostics(a, &d1);
        ca += d1.collisions - d0.collisions;
        rc_sim_diagnostics(b, &d0);
        t0 = cpu_s();
        rc_sim_advance(b, INFINITY, chunk_b);
        tb += cpu_s() - t0;
        rc_sim_diagnostics(b, &d1);
        cb += d1.collisions - d0.collisions;
    }
    printf("  interleaved: A %.0f collisions/s, B %.0f collisions/s\n", (double)ca / ta,
           (double)cb / tb);
    return (tb / (double)cb) / (ta / (double)ca);
}

/* Time per collision at N = n against N = 1e4 (3-D, packing 0.45), interleaved; `label`
 * names n, `note` ends the line. */
static void scaling(size_t n, uint64_t chunk, int rounds, const char *label, const char *note)
{
    rc_sim *s4 = make(3, 10000, 0.45, INFINITY, NULL);
    rc_sim *sn = make(3, n, 0.45, INFINITY, NULL);
    if (s4 && sn)
        printf("time per collision N %s / N 1e4: %.2f (interleaved%s)\n", label,
               interleaved_ratio(s4, sn, chunk, chunk, rounds), note);
    rc_sim_free(&s4);
    rc_sim_free(&sn);
}

int main(int argc, char **argv)
{
    const char *mode = argc > 1 ? argv[1] : "quick";
    if (!strcmp(mode, "ratio")) { /* only the interleaved contracted/classical ratio */
        rc_sim *ca = make(3, 10000, 0.45, INFINITY, NULL);
        rc_sim *ct = make(3, 10000, 0.45, 2.0, "table");
        if (ca && ct)
            printf("relativistic 0.5c, contracted (table frame): %.2f x classical "
                   "(interleaved; target <= 3)\n", interleaved_ratio(ca, ct, 30000, 8000, 20));
        /* the covariant frame (and zmf, whose contact it shares) against the table frame,
         * per collision, same gas */
        rc_sim *cz = make(3, 10000, 0.45, 2.0, "zmf");
        rc_sim *cv = make(3, 10000, 0.45, 2.0, "covariant");
        if (ct && cz && cv) {
            printf("relativistic 0.5c, zmf frame: %.2f x table frame (interleaved)\n",
                   interleaved_ratio(ct, cz, 8000, 8000, 10));
            printf("relativistic 0.5c, covariant frame: %.2f x table frame (interleaved)\n",
                   interleaved_ratio(ct, cv, 8000, 8000, 10));
        }
        rc_sim_free(&cz);
        rc_sim_free(&cv);
        /* and where the glued tube is defined (packing 0.1, where the overlap policy
         * decides few collisions; at 0.45 it decides many), covariant against zmf */
        rc_sim *dz = make(3, 10000, 0.1, 2.0, "zmf");
        rc_sim *dv = make(3, 10000, 0.1, 2.0, "covariant");
        if (dz && dv)
            printf("relativistic 0.5c, packing 0.1, covariant frame: %.2f x zmf frame "
                   "(interleaved)\n", interleaved_ratio(dz, dv, 8000, 8000, 10));
        rc_sim_free(&dz);
        rc_sim_free(&dv);
        rc_sim_free(&ca);
        rc_sim_free(&ct);
        return 0;
    }
    if (strcmp(mode, "quick") && strcmp(mode, "full")) {
        /* one run: N (3-D, packing 0.45), 2d:N (2-D, 0.7) or rel:N (3-D, contracted
         * table frame at rms speed 0.5 c) */
        const double per = argc > 2 ? atof(argv[2]) : 0.0;
        if (argc > 2 && !(per > 0.0)) {
            fprintf(stderr, "bench_engine: collisions per ball '%s': not a positive number\n",
                    argv[2]);
            return 2;
        }
        if (!strncmp(mode, "per:", 4) || !strncmp(mode, "per2d:", 6)) {
            periodic_box = 1;
            mode += mode[3] == ':' ? 4 : 3; /* per:N -> N, per2d:N -> 2d:N */
        }
        if (!strncmp(mode, "2d:", 3))
            run(2, (size_t)atof(mode + 3), 0.70, INFINITY, NULL, 5, per > 0.0 ? per : 20);
        else if (!strncmp(mode, "rel:", 4))
            run(3, (size_t)atof(mode + 4), 0.45, 2.0, "table", 2, per > 0.0 ? per : 5);
        else
            run(3, (size_t)atof(mode), 0.45, INFINITY, NULL, 5, per > 0.0 ? per : 20);
        return 0;
    }
    printf("relcol engine benchmark (CPU time; targets from issue 4)\n");
    result a = run(3, 10000, 0.45, INFINITY, NULL, 10, 100);
    result b = run(3, 100000, 0.45, INFINITY, NULL, 5, 20);
    result c2 = run(2, 10000, 0.70, INFINITY, NULL, 10, 100);
    /* relativistic: rms speed 0.5 c, same N and density as run a */
    result r = run(3, 10000, 0.45, 2.0, NULL, 10, 50);
    result rt = run(3, 10000, 0.45, 2.0, "table", 2, 5);
    printf("3-D phi 0.45 N 1e4: %.3g M/s (target >= 1.35)\n", a.rate / 1e6);
    printf("3-D phi 0.45 N 1e5: %.3g M/s (target >= 0.87)\n", b.rate / 1e6);
    printf("2-D phi 0.70 N 1e4: %.3g M/s (target >= 1.05)\n", c2.rate / 1e6);
    printf("relativistic 0.5c, uncontracted spheres: cost per collision %.2f x classical "
           "(sequential runs)\n", a.rate / r.rate);
    printf("relativistic 0.5c, contracted (table frame): cost per collision %.2f x classical "
           "(sequential runs; target <= 3)\n", a.rate / rt.rate);
    {
        rc_sim *ca = make(3, 10000, 0.45, INFINITY, NULL);
        rc_sim *cr = make(3, 10000, 0.45, 2.0, NULL);
        rc_sim *ct = make(3, 10000, 0.45, 2.0, "table");
        if (ca && cr && ct) {
            printf("relativistic 0.5c, uncontracted: %.2f x classical (interleaved)\n",
                   interleaved_ratio(ca, cr, 30000, 30000, 20));
            printf("relativistic 0.5c, contracted (table frame): %.2f x classical "
                   "(interleaved; target <= 3)\n", interleaved_ratio(ca, ct, 30000, 8000, 20));
        }
        rc_sim_free(&ca);
        rc_sim_free(&cr);
        rc_sim_free(&ct);
    }
    printf("bytes per ball: %.1f (target <= 200); with a contracted frame %.1f (its contact "
           "normals)\n", a.bytes, rt.bytes);
    printf("time per collision N 1e5 / N 1e4: %.2f (sequential runs)\n", a.rate / b.rate);
    scaling(100000, 50000, 20, "1e5", "");
    if (!strcmp(mode, "full")) /* N = 1e6: ~200 MB and a few minutes */
        scaling(1000000, 100000, 10, "1e6", "; target <= 1.5");
    return 0;
}
