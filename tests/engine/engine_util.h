/* engine_util.h — helpers shared by the engine tests: build a gas run, step it. */
#ifndef ENGINE_UTIL_H
#define ENGINE_UTIL_H

#include <math.h>
#include <stdlib.h>

#include "rc_test.h"
#include "relcol/relcol.h"

/* A gas of n balls (radius 0.5) from rc_sim_gas_init in an engine made from d (box,
 * dim and c are set from the gas). Returns NULL on failure (recorded as a check). */
static inline rc_sim *util_gas(rc_sim_def d, size_t n, double packing, double v_rms, uint64_t seed)
{
    rc_sim_gas_def g = {d.dim, n, 0.5, packing, v_rms, d.c, 1.0, seed};
    rc_sim_ball *b = malloc(n * sizeof *b);
    rc_sim *s = NULL;
    int st = b ? rc_sim_gas_init(&g, &d.box, b) : RC_ENOMEM;
    ENSURE_MSG(st == RC_OK, "gas: %s", rc_strerror(st));
    if (st == RC_OK) {
        st = rc_sim_create(&d, &s);
        ENSURE_MSG(st == RC_OK, "create: %s", rc_strerror(st));
    }
    if (st == RC_OK) {
        st = rc_sim_set_balls(s, n, b, NULL);
        ENSURE_MSG(st == RC_OK, "set: %s", rc_strerror(st));
        if (st != RC_OK)
            rc_sim_free(&s);
    }
    free(b);
    return s;
}

/* The covariant frame in a periodic box of dim dimensions at c = 1: the engine of the
 * tests that measure the overlap policy's share and the kinks (other fields default). */
static inline rc_sim_def util_covariant_periodic(int dim)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    d.c = 1.0;
    d.frame = &rc_toi_frame_covariant;
    for (int k = 0; k < 3; k++)
        d.boundary[k] = RC_SIM_PERIODIC;
    return d;
}

/* Balls in[0 .. n-1] (centres at table time 0) seen from a frame moving at U, cut at its
 * t' = 0 by free flight (the caller's scene has no contact before that cut in either
 * frame), positions relative to o kept relative to o; c the speed of light. */
static inline void util_to_frame(double c, rc_vec3 o, rc_vec3 U, size_t n, const rc_sim_ball *in,
                                 rc_sim_ball *out)
{
    for (size_t i = 0; i < n; i++) {
        const double M = sqrt(in[i].m * in[i].m + rc_v3_norm2(in[i].p) / (c * c));
        const rc_vec3 v = rc_v3_scale(1.0 / M, in[i].p), x = rc_v3_sub(in[i].x, o);
        const double ti = rc_v3_dot(U, x) / (c * c - rc_v3_dot(U, v));
        rc_four e = {ti, rc_v3_axpy(x, ti, v)};
        rc_four f = {M, in[i].p};
        ENSURE(rc_boost(U, 1.0 / (c * c), &e) == RC_OK && rc_boost(U, 1.0 / (c * c), &f) == RC_OK);
        out[i] = in[i];
        out[i].p = f.x;
        out[i].x = rc_v3_add(o, rc_v3_axpy(e.x, -e.t, rc_v3_scale(1.0 / f.t, f.x)));
    }
}

/* One ball of rest radius and mass 1 at x with momentum p, alone on a 2-D table box,
 * from time t0 (NULL on failure, recorded as a check). */
static inline rc_sim *util_one_ball(rc_vec3 box, rc_vec3 x, rc_vec3 p, double c,
                                    double eps_wall, double t_c, double t0)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.box = box;
    d.c = c;
    d.eps_wall = eps_wall;
    d.t_c = t_c;
    rc_sim *s = NULL;
    rc_sim_ball b = {0};
    b.x = x;
    b.p = p;
    b.r = 1.0;
    b.m = 1.0;
    int st = rc_sim_create(&d, &s);
    if (st == RC_OK && (st = rc_sim_set_time(s, t0)) == RC_OK)
        st = rc_sim_set_balls(s, 1, &b, NULL);
    ENSURE_MSG(st == RC_OK, "one ball: %s", rc_strerror(st));
    if (st != RC_OK)
        rc_sim_free(&s);
    return s;
}

/* Run until at least `target` contacts were resolved (events in chunks, no time limit). */
static inline void util_run_collisions(rc_sim *s, uint64_t target)
{
    rc_sim_diag d;
    rc_sim_diagnostics(s, &d);
    uint64_t start = d.collisions;
    for (int guard = 0; guard < 100000; guard++) {
        int st = rc_sim_advance(s, INFINITY, 20000);
        ENSURE_MSG(st == RC_OK, "advance: %s", rc_strerror(st));
        rc_sim_diagnostics(s, &d);
        if (st != RC_OK || d.collisions - start >= target)
            return;
    }
}

#endif
