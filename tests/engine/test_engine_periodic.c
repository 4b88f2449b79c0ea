/* test_engine_periodic.c — periodic boundaries (rc_sim_def.boundary):
 *  - a lone ball crossing every periodic face both ways, 2-D and 3-D, all periodic and
 *    mixed with walls: its position stays in [0, L), position + image L is the free
 *    flight exactly (to round-off), every cell crossing and every wall hit happens (counts
 *    against the count of grid lines and walls the straight line meets), none on a
 *    periodic axis;
 *  - two balls meeting across each face (nearest image): one collision, at the right time,
 *    with the right outcome; also after a long flight through several cells, where the
 *    nearest image at the flying ball's last collision is the other copy;
 *  - a state read back (image counters included) continues bit for bit in a new engine
 *    after rc_sim_sync; a checkpoint continues as the run that never stopped, and a
 *    walled engine refuses a periodic one's;
 *  - the scalar loop, the AVX2 and the AVX-512 lanes (rc_sim_def.simd) give the same bits in
 *    periodic boxes (the image is skipped in blocks that do not wrap);
 *  - bad periodic input refused: fewer than four cells, a centre outside [0, L), an
 *    unknown boundary;
 *  - conservation over >= 1e6 collisions in all-periodic boxes (3-D and 2-D, classical; a
 *    contracted table-frame gas at c = 1 with eps < 1 and the TC model): energy (kinetic
 *    + heat) and momentum to 1e-12 relative with no wall impulse at all, no overlap. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine_util.h"

static rc_sim_def periodic_def(int dim, int bx, int by, int bz)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    d.boundary[0] = bx;
    d.boundary[1] = by;
    d.boundary[2] = bz;
    return d;
}

/* Grid lines k w (k integer) strictly between a and b. */
static long lines_between(double a, double b, double w)
{
    return labs((long)floor(b / w) - (long)floor(a / w));
}

/* Wall hits of a coordinate bouncing between lo and hi from y0 at speed v over time t:
 * the unfolded line y0 + v t crosses lo + k (hi - lo). */
static long bounces(double y0, double v, double t, double lo, double hi)
{
    return lines_between(y0 - lo, y0 - lo + v * t, hi - lo);
}

/* Where the unfolded coordinate u lies inside [lo, hi] after its reflections. */
static double folded(double u, double lo, double hi)
{
    const double w = hi - lo, q = fmod(fabs(u - lo), 2.0 * w);
    return lo + (q <= w ? q : 2.0 * w - q);
}

/* A lone ball (r = 0.5, cells of edge W = 1.1) flying through a box of 4 x 4 x 4 cells
 * (2-D: 7 x 6; few enough that the grid keeps them for one ball; four: the fewest a
 * periodic axis may have) with the given boundaries, read at irregular times up to
 * t ~ 70. */
#define W 1.1
static void lone_ball(int dim, const int bnd[3], rc_vec3 v)
{
    rc_sim_def d = periodic_def(dim, bnd[0], bnd[1], bnd[2]);
    const double L[3] = {(dim == 3 ? 4 : 7) * W, (dim == 3 ? 4 : 6) * W, 4 * W};
    d.box = rc_v3(L[0], L[1], dim == 3 ? L[2] : 0.0);
    d.cell_size = W;
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    if (!s)
        return;
    const rc_vec3 x0 = rc_v3(3.3, 2.7, dim == 3 ? 1.2 : 0.0);
    if (dim == 2)
        v.z = 0.0;
    rc_sim_ball b;
    memset(&b, 0, sizeof b);
    b.x = x0;
    b.p = v; /* (m = 1: density * r^3 with density 8) */
    b.r = 0.5;
    b.m = 1.0;
    ENSURE(rc_sim_set_balls(s, 1, &b, NULL) == RC_OK);
    double t = 0.0;
    for (int step = 1; step <= 40; step++) {
        t += 0.5 + 2.5 * fmod(0.618 * step, 1.0); /* irregular reading times */
        ENSURE(rc_sim_advance(s, t, 0) == RC_OK);
        rc_sim_ball o;
        ENSURE(rc_sim_get_ball(s, 0, &o) == RC_OK);
        long cells = 0, walls = 0;
        for (int k = 0; k < dim; k++) {
            const double x = rc_v3_get(o.x, k), u = rc_v3_get(x0, k) + rc_v3_get(v, k) * t;
            if (bnd[k] == RC_SIM_PERIODIC) {
                ENSURE_MSG(x >= 0.0 && x < L[k], "axis %d: x = %.17g outside [0, %g)", k, x,
                           L[k]);
                /* unwrapped = free flight (a wrap moves x by L: round-off of L) */
                ENSURE_CLOSE(x + o.image[k] * L[k], u, 1e-13, L[k] + fabs(u));
                ENSURE_MSG(o.image[k] == (int32_t)floor(u / L[k]), "axis %d: image %d at t %g",
                           k, o.image[k], t);
                cells += lines_between(rc_v3_get(x0, k), u, W);
            } else {
                ENSURE(o.image[k] == 0);
                const double y = folded(u, 0.5, L[k] - 0.5);
                ENSURE_CLOSE(x, y, 1e-12, L[k]);
                const long hits = bounces(rc_v3_get(x0, k), rc_v3_get(v, k), t, 0.5, L[k] - 0.5);
                walls += hits;
            }
        }
        rc_sim_diag g;
        rc_sim_diagnostics(s, &g);
        ENSURE_MSG(g.events[RC_SIM_EV_WALL] == (uint64_t)walls, "t %g: %llu wall hits, %ld expected",
                   t, (unsigned long long)g.events[RC_SIM_EV_WALL], walls);
        int all_periodic = 1;
        for (int k = 0; k < dim; k++)
            all_periodic &= bnd[k] == RC_SIM_PERIODIC;
        if (all_periodic) /* every grid line met is one crossing, periodic faces included */
            ENSURE_MSG(g.events[RC_SIM_EV_CELL] == (uint64_t)cells,
                       "%d-D v (%g %g %g) t %g: %llu cell crossings, %ld expected", dim, v.x,
                       v.y, v.z, t, (unsigned long long)g.events[RC_SIM_EV_CELL], cells);
        ENSURE(g.collisions == g.events[RC_SIM_EV_WALL]);
        /* momentum only changes at walls; energy never */
        for (int k = 0; k < dim; k++)
            if (bnd[k] == RC_SIM_PERIODIC)
                ENSURE(rc_v3_get(o.p, k) == rc_v3_get(v, k));
        ENSURE(rc_v3_norm2(o.p) == rc_v3_norm2(v));
    }
    rc_sim_free(&s);
}

static void test_faces(void)
{
    static const int all[3] = {RC_SIM_PERIODIC, RC_SIM_PERIODIC, RC_SIM_PERIODIC};
    static const int mixed[3] = {RC_SIM_PERIODIC, RC_SIM_WALLS, RC_SIM_PERIODIC};
    static const int mixed2[3] = {RC_SIM_WALLS, RC_SIM_PERIODIC, RC_SIM_WALLS};
    /* every sign pattern: each periodic face crossed both ways */
    for (int sx = -1; sx <= 1; sx += 2)
        for (int sy = -1; sy <= 1; sy += 2)
            for (int sz = -1; sz <= 1; sz += 2) {
                const rc_vec3 v = rc_v3(sx * 1.3, sy * 0.7, sz * 0.45);
                lone_ball(3, all, v);
                lone_ball(3, mixed, v);
                lone_ball(3, mixed2, v);
                if (sz > 0) {
                    lone_ball(2, all, v);
                    lone_ball(2, mixed, v);
                    lone_ball(2, mixed2, v);
                }
            }
    /* straight along an axis (the other components exactly 0) */
    lone_ball(3, all, rc_v3(0.0, -1.73, 0.0));
    lone_ball(2, mixed, rc_v3(2.1, 0.0, 0.0));
}

/* Two equal balls at x = 0.6 and L - 0.6 on axis k, approaching through the face between
 * them at speed 1 each: contact at t = 0.1 (gap 0.2 across the face), then they swap
 * velocities; at t = 0.2 they are back where they started, moving apart. */
static void across(int dim, int k, int walls_elsewhere)
{
    rc_sim_def d = periodic_def(dim, RC_SIM_PERIODIC, RC_SIM_PERIODIC, RC_SIM_PERIODIC);
    for (int j = 0; j < 3 && walls_elsewhere; j++)
        if (j != k)
            d.boundary[j] = RC_SIM_WALLS;
    d.box = rc_v3(6.0, 5.0, dim == 3 ? 4.5 : 0.0);
    const double L = rc_v3_get(d.box, k);
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    if (!s)
        return;
    rc_sim_ball b[2];
    memset(b, 0, sizeof b);
    for (int i = 0; i < 2; i++) {
        b[i].x = rc_v3(2.0, 2.0, dim == 3 ? 2.0 : 0.0);
        b[i].r = 0.5;
        b[i].m = 1.0;
    }
    rc_v3_set(&b[0].x, k, 0.6);
    rc_v3_set(&b[1].x, k, L - 0.6);
    rc_v3_set(&b[0].p, k, -1.0);
    rc_v3_set(&b[1].p, k, 1.0);
    ENSURE(rc_sim_set_balls(s, 2, b, NULL) == RC_OK);
    ENSURE(rc_sim_advance(s, 0.05, 0) == RC_OK);
    rc_sim_diag g;
    rc_sim_diagnostics(s, &g);
    ENSURE(g.collisions == 0);
    ENSURE(rc_sim_advance(s, 0.2, 0) == RC_OK);
    rc_sim_diagnostics(s, &g);
    ENSURE_MSG(g.collisions == 1 && g.events[RC_SIM_EV_BALL] == 1, "dim %d axis %d: %llu",
               dim, k, (unsigned long long)g.collisions);
    ENSURE(g.events[RC_SIM_EV_WALL] == 0);
    rc_sim_ball o[2];
    rc_sim_get_ball(s, 0, &o[0]);
    rc_sim_get_ball(s, 1, &o[1]);
    ENSURE_CLOSE(rc_v3_get(o[0].p, k), 1.0, 1e-15, 1.0);
    ENSURE_CLOSE(rc_v3_get(o[1].p, k), -1.0, 1e-15, 1.0);
    ENSURE_CLOSE(rc_v3_get(o[0].x, k), 0.6, 1e-14, L);
    ENSURE_CLOSE(rc_v3_get(o[1].x, k), L - 0.6, 1e-14, L);
    ENSURE(o[0].image[k] == 0 && o[1].image[k] == 0);
    rc_sim_free(&s);
}

/* A long flight: ball 0 at 6 moving down axis k at speed 1 through four cells (no
 * collision, no wrap, its clock stays at 0), ball 1 at rest at L - 0.2 = 9.8: they meet
 * across the face at t = 5.3 (x0 = 0.7 touches the image at -0.2). At t = 0 the nearest
 * image of the pair is the other copy (3.8 apart, parting): only the image as the balls
 * are when they become neighbours finds the contact. */
static void long_flight(int dim, int k)
{
    rc_sim_def d = periodic_def(dim, RC_SIM_PERIODIC, RC_SIM_PERIODIC, RC_SIM_PERIODIC);
    d.box = rc_v3(10.0, 10.0, dim == 3 ? 10.0 : 0.0);
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    if (!s)
        return;
    rc_sim_ball b[2];
    memset(b, 0, sizeof b);
    for (int i = 0; i < 2; i++) {
        b[i].x = rc_v3(5.0, 5.0, dim == 3 ? 5.0 : 0.0);
        b[i].r = 0.45;
        b[i].m = 1.0;
    }
    rc_v3_set(&b[0].x, k, 6.0);
    rc_v3_set(&b[1].x, k, 9.8);
    rc_v3_set(&b[0].p, k, -1.0);
    ENSURE(rc_sim_set_balls(s, 2, b, NULL) == RC_OK);
    ENSURE(rc_sim_advance(s, 5.2, 0) == RC_OK);
    rc_sim_diag g;
    rc_sim_diagnostics(s, &g);
    ENSURE(g.collisions == 0);
    ENSURE(rc_sim_advance(s, 6.0, 0) == RC_OK);
    rc_sim_diagnostics(s, &g);
    ENSURE_MSG(g.collisions == 1, "dim %d axis %d: %llu collisions, 1 expected", dim, k,
               (unsigned long long)g.collisions);
    rc_sim_ball o[2];
    rc_sim_get_ball(s, 0, &o[0]);
    rc_sim_get_ball(s, 1, &o[1]);
    ENSURE_CLOSE(rc_v3_get(o[0].p, k), 0.0, 1e-15, 1.0);
    ENSURE_CLOSE(rc_v3_get(o[1].p, k), -1.0, 1e-15, 1.0);
    ENSURE_CLOSE(rc_v3_get(o[0].x, k), 0.7, 1e-13, 10.0); /* at rest since t = 5.3 */
    ENSURE_CLOSE(rc_v3_get(o[1].x, k), 9.8 - 0.7, 1e-13, 10.0);
    rc_sim_free(&s);
}

static void test_across_faces(void)
{
    for (int k = 0; k < 3; k++) {
        long_flight(3, k);
        if (k < 2)
            long_flight(2, k);
    }
    for (int k = 0; k < 3; k++) {
        across(3, k, 0);
        across(3, k, 1);
        if (k < 2) {
            across(2, k, 0);
            across(2, k, 1);
        }
    }
}

/* A periodic gas stopped, read out (image counters included) and loaded into a new
 * engine continues exactly as the synced original. */
static void test_restart(void)
{
    for (int dim = 2; dim <= 3; dim++) {
        rc_sim_def d = periodic_def(dim, RC_SIM_PERIODIC, RC_SIM_WALLS, RC_SIM_PERIODIC);
        const size_t n = 500;
        rc_sim_gas_def g = {dim, n, 0.5, 0.3, 1.0, INFINITY, 1.0, 11 + (uint64_t)dim};
        rc_sim_ball *b = malloc(n * sizeof *b);
        rc_sim *s = NULL, *t = NULL;
        ENSURE(rc_sim_gas_init(&g, &d.box, b) == RC_OK);
        ENSURE(rc_sim_create(&d, &s) == RC_OK && rc_sim_create(&d, &t) == RC_OK);
        ENSURE(rc_sim_set_balls(s, n, b, NULL) == RC_OK);
        ENSURE(rc_sim_advance(s, 3.0, 0) == RC_OK);
        ENSURE(rc_sim_sync(s) == RC_OK);
        long wrapped = 0;
        for (size_t i = 0; i < n; i++) {
            rc_sim_get_ball(s, i, &b[i]);
            wrapped += labs(b[i].image[0]) + labs(b[i].image[2]);
        }
        ENSURE(wrapped > 0); /* (the test sees the counters) */
        ENSURE(rc_sim_set_time(t, rc_sim_time(s)) == RC_OK);
        ENSURE(rc_sim_set_balls(t, n, b, NULL) == RC_OK);
        ENSURE(rc_sim_hash(t) == rc_sim_hash(s));
        ENSURE(rc_sim_advance(s, 6.0, 0) == RC_OK);
        ENSURE(rc_sim_advance(t, 6.0, 0) == RC_OK);
        ENSURE_MSG(rc_sim_hash(t) == rc_sim_hash(s), "dim %d: the continued run differs", dim);
        for (size_t i = 0; i < n; i++) {
            rc_sim_ball u, w;
            rc_sim_get_ball(s, i, &u);
            rc_sim_get_ball(t, i, &w);
            ENSURE(!memcmp(u.image, w.image, sizeof u.image));
        }
        free(b);
        rc_sim_free(&s);
        rc_sim_free(&t);
    }
}

/* Checkpoints of periodic runs (classical, and the table frame at c = 1 with eps < 1 and
 * TC): stopped at t = 2, written, read into a new engine and continued to t = 5, the
 * same hash and images as the run that never stopped. */
static void test_checkpoint(void)
{
    for (int k = 0; k < 4; k++) {
        const int dim = 2 + k % 2, rel = k >= 2;
        rc_sim_def d = periodic_def(dim, RC_SIM_PERIODIC, k == 1 ? RC_SIM_WALLS : RC_SIM_PERIODIC,
                                    RC_SIM_PERIODIC);
        if (rel) {
            d.c = 1.0;
            d.frame = &rc_toi_frame_table;
            d.eps_ball = 0.8;
            d.t_c = 1e-4;
        }
        const size_t n = 400;
        rc_sim_gas_def g = {dim, n, 0.5, 0.3, rel ? 0.5 : 1.0, d.c, 1.0, 21 + (uint64_t)k};
        rc_sim_ball *b = malloc(n * sizeof *b);
        rc_sim *s = NULL, *u = NULL, *t = NULL;
        ENSURE(rc_sim_gas_init(&g, &d.box, b) == RC_OK);
        ENSURE(rc_sim_create(&d, &s) == RC_OK && rc_sim_create(&d, &u) == RC_OK &&
               rc_sim_create(&d, &t) == RC_OK);
        ENSURE(rc_sim_set_balls(s, n, b, NULL) == RC_OK);
        ENSURE(rc_sim_set_balls(u, n, b, NULL) == RC_OK);
        ENSURE(rc_sim_advance(s, 2.0, 0) == RC_OK);
        size_t bytes = 0;
        ENSURE(rc_sim_checkpoint_size(s, &bytes) == RC_OK);
        void *buf = malloc(bytes);
        ENSURE(buf && rc_sim_checkpoint_write(s, buf, bytes) == RC_OK);
        ENSURE(rc_sim_checkpoint_read(t, buf, bytes) == RC_OK);
        ENSURE(rc_sim_advance(t, 5.0, 0) == RC_OK && rc_sim_advance(u, 5.0, 0) == RC_OK);
        ENSURE_MSG(rc_sim_hash(t) == rc_sim_hash(u), "case %d: the continued run differs", k);
        long wrapped = 0;
        for (size_t i = 0; i < n; i++) {
            rc_sim_ball p, q;
            rc_sim_get_ball(t, i, &p);
            rc_sim_get_ball(u, i, &q);
            ENSURE(!memcmp(p.image, q.image, sizeof p.image));
            wrapped += labs(p.image[0]) + labs(p.image[1]) + labs(p.image[2]);
        }
        ENSURE(wrapped > 0);
        /* the same box with walls is another definition */
        rc_sim_def w = d;
        w.boundary[0] = w.boundary[1] = w.boundary[2] = RC_SIM_WALLS;
        rc_sim *x = NULL;
        ENSURE(rc_sim_create(&w, &x) == RC_OK);
        ENSURE(rc_sim_checkpoint_read(x, buf, bytes) == RC_EMISMATCH);
        rc_sim_free(&x);
        free(buf);
        free(b);
        rc_sim_free(&s);
        rc_sim_free(&t);
        rc_sim_free(&u);
    }
}

/* The same periodic gas through each lane width (rc_sim_def.simd): the same hash after
 * 40 collisions a ball (5 with a contracted frame). */
static void lanes(int dim, size_t n, double packing, const rc_toi_frame *frame, const int bnd[3])
{
    rc_sim_def d = periodic_def(dim, bnd[0], bnd[1], bnd[2]);
    d.frame = frame;
    d.c = frame ? 2.0 : INFINITY;
    const rc_sim_simd mode[3] = {RC_SIM_SIMD_SCALAR, RC_SIM_SIMD_AVX2, RC_SIM_SIMD_AUTO};
    uint64_t h[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++) {
        d.simd = mode[k];
        rc_sim *s = util_gas(d, n, packing, 1.0, 31); /* (0.5 c with a frame) */
        if (!s)
            continue;
        util_run_collisions(s, (frame ? 5 : 40) * n);
        h[k] = rc_sim_hash(s);
        rc_sim_free(&s);
    }
    ENSURE_MSG(h[0] == h[1] && h[1] == h[2], "%dD N %zu: scalar %llx avx2 %llx best %llx", dim, n,
               (unsigned long long)h[0], (unsigned long long)h[1], (unsigned long long)h[2]);
}

static void test_lanes(void)
{
    static const int all[3] = {RC_SIM_PERIODIC, RC_SIM_PERIODIC, RC_SIM_PERIODIC};
    static const int mixed[3] = {RC_SIM_PERIODIC, RC_SIM_WALLS, RC_SIM_PERIODIC};
    lanes(3, 2000, 0.4, NULL, all);
    lanes(3, 2000, 0.4, NULL, mixed);
    lanes(2, 2000, 0.6, NULL, all);
    lanes(2, 2000, 0.6, NULL, mixed);
    lanes(3, 60, 0.3, NULL, all);  /* (a box four cells wide: every block wraps) */
    lanes(2, 12, 0.5, NULL, mixed);
    lanes(3, 1000, 0.3, &rc_toi_frame_table, all);
}

static void test_refusals(void)
{
    rc_sim_def d = periodic_def(3, RC_SIM_PERIODIC, RC_SIM_PERIODIC, RC_SIM_PERIODIC);
    rc_sim *s = NULL;
    d.boundary[1] = 2;
    ENSURE(rc_sim_create(&d, &s) == RC_EINVAL);
    d.boundary[1] = -1;
    ENSURE(rc_sim_create(&d, &s) == RC_EINVAL);
    d.boundary[1] = RC_SIM_PERIODIC;
    /* cells given: fewer than four across a periodic axis */
    d.box = rc_v3(10.0, 3.9, 10.0);
    d.cell_size = 1.0;
    ENSURE(rc_sim_create(&d, &s) == RC_EINVAL);
    d.boundary[1] = RC_SIM_WALLS; /* (a walled axis may have any number) */
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    rc_sim_free(&s);
    /* automatic cells: box edge < 4 largest diameters */
    d.boundary[1] = RC_SIM_PERIODIC;
    d.cell_size = 0.0;
    d.box = rc_v3(10.0, 3.9, 10.0);
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    rc_sim_ball b;
    memset(&b, 0, sizeof b);
    b.x = rc_v3(5.0, 1.0, 5.0);
    b.r = 0.5;
    ENSURE(rc_sim_set_balls(s, 1, &b, NULL) == RC_EINVAL);
    b.r = 0.45;
    ENSURE(rc_sim_set_balls(s, 1, &b, NULL) == RC_OK);
    /* a centre outside [0, L) on a periodic axis (on a walled one the wall rule) */
    b.x = rc_v3(10.0, 1.0, 5.0);
    ENSURE(rc_sim_set_balls(s, 1, &b, NULL) == RC_EINVAL);
    b.x = rc_v3(-1e-300, 1.0, 5.0);
    ENSURE(rc_sim_set_balls(s, 1, &b, NULL) == RC_EINVAL);
    b.x = rc_v3(0.0, 1.0, 5.0); /* on the face: fine, the shape reaches across */
    ENSURE(rc_sim_set_balls(s, 1, &b, NULL) == RC_OK);
    /* overlap across a face is an overlap */
    rc_sim_ball two[2];
    memset(two, 0, sizeof two);
    two[0].x = rc_v3(0.2, 1.0, 5.0);
    two[1].x = rc_v3(9.5, 1.0, 5.0);
    two[0].r = two[1].r = 0.45;
    ENSURE(rc_sim_set_balls(s, 2, two, NULL) == RC_EOVERLAP);
    two[1].x.x = 9.0;
    ENSURE(rc_sim_set_balls(s, 2, two, NULL) == RC_OK);
    rc_sim_free(&s);
}

static uint64_t total_collisions;

/* A gas in an all-periodic box run for >= target collisions: energy (kinetic + heat) and
 * momentum to 1e-12 relative, the walls took nothing. */
static void conserve(int dim, double c, const rc_toi_frame *frame, double eps, size_t n,
                     double packing, uint64_t target, uint64_t seed)
{
    rc_sim_def d = periodic_def(dim, RC_SIM_PERIODIC, RC_SIM_PERIODIC, RC_SIM_PERIODIC);
    d.c = c;
    d.frame = frame;
    d.eps_ball = eps;
    d.t_c = eps < 1.0 ? 1e-4 : 0.0; /* (as test_engine_conservation) */
    rc_sim *s = util_gas(d, n, packing, isinf(c) ? 1.0 : 0.5 * c, seed);
    if (!s)
        return;
    rc_sim_diag d0, d1;
    rc_sim_diagnostics(s, &d0);
    util_run_collisions(s, target);
    rc_sim_diagnostics(s, &d1);
    total_collisions += d1.collisions;
    /* 1e-12: each collision conserves energy and momentum to a few ulps of the pair's,
     * which is ~1/N of the totals; 1e6 such errors add (as a random walk) to ~1e-13 of
     * the totals at most. The momentum is zero to start with: relative to sum |p_i|. */
    ENSURE_REL(d1.energy, d0.energy, 1e-12);
    if (isfinite(c))
        ENSURE_REL(d1.mass_rel, d0.mass_rel, 1e-12);
    ENSURE_CLOSE(d1.momentum.x, d0.momentum.x, 1e-12, d0.momentum_scale);
    ENSURE_CLOSE(d1.momentum.y, d0.momentum.y, 1e-12, d0.momentum_scale);
    ENSURE_CLOSE(d1.momentum.z, d0.momentum.z, 1e-12, d0.momentum_scale);
    /* no walls: no wall event, the wall impulse only the round-off of pair collisions */
    ENSURE(d1.events[RC_SIM_EV_WALL] == 0);
    ENSURE(rc_v3_norm(d1.wall_impulse) <= 1e-12 * d0.momentum_scale);
    for (int w = 0; w < 6; w++) /* (no wall took anything: exactly) */
        ENSURE(d1.wall_impulse_by_wall[w] == 0.0);
    if (eps < 1.0)
        ENSURE(d1.heat > 1e-3 * d0.kinetic);
    if (isnan(d1.max_overlap))
        ENSURE(frame && frame != &rc_toi_frame_sphere);
    else
        ENSURE_MSG(d1.max_overlap <= 1e-9, "max overlap %g", d1.max_overlap);
    if (!frame)
        ENSURE(d1.overlaps == 0);
    /* the balls did cross the faces */
    long wrapped = 0;
    for (size_t i = 0; i < rc_sim_count(s); i++) {
        rc_sim_ball b;
        rc_sim_get_ball(s, i, &b);
        wrapped += labs(b.image[0]) + labs(b.image[1]) + labs(b.image[2]);
    }
    ENSURE(wrapped > (long)n / 10);
    rc_sim_free(&s);
}

static void test_conservation(void)
{
    conserve(3, INFINITY, NULL, 1.0, 2000, 0.3, 1000000, 5);
    conserve(2, INFINITY, NULL, 1.0, 2000, 0.5, 1000000, 6);
    /* contracted shapes (overlap policy at work), inelastic with TC: the heat books */
    conserve(3, 1.0, &rc_toi_frame_table, 0.8, 500, 0.3, 100000, 7);
    conserve(2, 1.0, &rc_toi_frame_zmf, 0.8, 500, 0.4, 100000, 8);
    ENSURE_MSG(total_collisions >= 2200000, "%llu", (unsigned long long)total_collisions);
}

int main(void)
{
    RUN_TEST(test_refusals);
    RUN_TEST(test_faces);
    RUN_TEST(test_across_faces);
    RUN_TEST(test_restart);
    RUN_TEST(test_checkpoint);
    RUN_TEST(test_lanes);
    RUN_TEST(test_conservation);
    RC_TEST_MAIN_END();
}
