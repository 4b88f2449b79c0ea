/* test_transport.c — the "transport" contact frame (transport codes' geometric
 * criterion): head-on and oblique pairs solved by hand, misses, the classical hard-sphere
 * normal and outcome at c = inf, the decision, d_T and the event unchanged when the pair
 * is given in a frame moving at 0.6 c, d_T against SMASH's covariant formula. */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "rc_test.h"
#include "relcol/relcol.h"

static rc_toi_workspace *ws;

static rc_toi_ball ball_v(double x, double y, double z, double r, double m, double vx,
                          double vy, double vz, double inv_c2)
{
    rc_toi_ball b = {rc_v3(x, y, z), r, m, rc_v3(0, 0, 0)};
    ENSURE(rc_momentum_from_velocity(m, rc_v3(vx, vy, vz), inv_c2, &b.p) == RC_OK);
    return b;
}

/* Head-on, c = 1, r = 1, m = 1: A at 0 moving +0.6, B at 10 moving -0.6 (the table is the
 * CM frame). Points: closest approach when they meet, t = 10/1.2, at x = 5, d_T = 0,
 * n = +x. (Touching spheres would collide at 20/3: the time differs by R/|w|.)
 * Oblique: the same with B at y = 1, R = 2: d_T = 1, t = 10/1.2, event (5, 0.5); the
 * spheres' normal at touching with b = 1 is (sqrt(R^2 - b^2), b)/R = (sqrt3/2, 1/2).
 * Tolerances: a few ulp of each quantity (a handful of roundings). */
static void test_by_hand_cm(void)
{
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_contact c;
    rc_toi_ball a = ball_v(0, 0, 0, 1, 1, 0.6, 0, 0, 1.0);
    rc_toi_ball b = ball_v(10, 0, 0, 1, 1, -0.6, 0, 0, 1.0);
    ENSURE(rc_toi(&rc_toi_frame_transport, &prm, &a, &b, ws, &c) == RC_OK);
    ENSURE_REL(c.t, 10.0 / 1.2, 8 * DBL_EPSILON);
    ENSURE_REL(c.x.x, 5.0, 8 * DBL_EPSILON);
    ENSURE_REL(c.n.x, 1.0, 8 * DBL_EPSILON);
    ENSURE_CLOSE(c.n.y, 0.0, 8 * DBL_EPSILON, 1.0);
    double dT2, tcm;
    ENSURE(rc_toi_transport_impact(&prm, &a, &b, &dT2, &tcm) == RC_OK);
    ENSURE_CLOSE(dT2, 0.0, 8 * DBL_EPSILON, 1.0);
    ENSURE_REL(tcm, 10.0 / 1.2, 8 * DBL_EPSILON);

    b = ball_v(10, 1, 0, 1, 1, -0.6, 0, 0, 1.0);
    ENSURE(rc_toi(&rc_toi_frame_transport, &prm, &a, &b, ws, &c) == RC_OK);
    ENSURE_REL(c.t, 10.0 / 1.2, 8 * DBL_EPSILON);
    ENSURE_REL(c.x.x, 5.0, 8 * DBL_EPSILON);
    ENSURE_REL(c.x.y, 0.5, 8 * DBL_EPSILON);
    ENSURE_REL(c.n.x, sqrt(3.0) / 2, 8 * DBL_EPSILON);
    ENSURE_REL(c.n.y, 0.5, 8 * DBL_EPSILON);
    ENSURE(rc_toi_transport_impact(&prm, &a, &b, &dT2, NULL) == RC_OK);
    ENSURE_REL(dT2, 1.0, 8 * DBL_EPSILON);
}

/* Oblique with the CM frame moving: A (m = 1) at 0 moving +0.6 c onto B (m = 1) at rest
 * at (10, 1), c = 1, r = 1. p = 0.75, M0 = 1.25: u = 0.75/2.25 = 1/3, gamma_u^2 = 9/8.
 * The motion is along x in every frame along x, so d_T = 1 (y is invariant); at the
 * closest approach the two CM events have equal CM t and x, hence equal table t and x:
 * A at x = 10, t = 10/0.6, the event (10, 0.5). The CM normal (sqrt3/2, 1/2) is the
 * four-vector (0, nz) in the CM frame: in the table (gamma u nz_x, gamma nz_x, 1/2), whose
 * spatial part normalised is (3 sqrt3, 2 sqrt2)/sqrt35. */
static void test_by_hand_moving_cm(void)
{
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_contact c;
    rc_toi_ball a = ball_v(0, 0, 0, 1, 1, 0.6, 0, 0, 1.0);
    rc_toi_ball b = ball_v(10, 1, 0, 1, 1, 0, 0, 0, 1.0);
    ENSURE(rc_toi(&rc_toi_frame_transport, &prm, &a, &b, ws, &c) == RC_OK);
    /* boosts there and back: a few dozen roundings */
    ENSURE_REL(c.t, 10.0 / 0.6, 64 * DBL_EPSILON);
    ENSURE_REL(c.x.x, 10.0, 64 * DBL_EPSILON);
    ENSURE_REL(c.x.y, 0.5, 64 * DBL_EPSILON);
    ENSURE_REL(c.n.x, 3 * sqrt(3.0) / sqrt(35.0), 64 * DBL_EPSILON);
    ENSURE_REL(c.n.y, 2 * sqrt(2.0) / sqrt(35.0), 64 * DBL_EPSILON);
    double dT2;
    ENSURE(rc_toi_transport_impact(&prm, &a, &b, &dT2, NULL) == RC_OK);
    ENSURE_REL(dT2, 1.0, 64 * DBL_EPSILON);
}

/* Misses: d_T = 2.5 > R = 2; a receding pair; no relative motion; d_T = R exactly (the
 * criterion is strict, and the spheres' normal speed would be 0). A pair whose
 * centres overlap in the table frame is no error for points (not RC_EOVERLAP). */
static void test_miss(void)
{
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_contact c;
    rc_toi_ball a = ball_v(0, 0, 0, 1, 1, 0.6, 0, 0, 1.0);
    rc_toi_ball b = ball_v(10, 2.5, 0, 1, 1, -0.6, 0, 0, 1.0);
    ENSURE(rc_toi(&rc_toi_frame_transport, &prm, &a, &b, ws, &c) == RC_MISS);
    double dT2;
    ENSURE(rc_toi_transport_impact(&prm, &a, &b, &dT2, NULL) == RC_OK);
    ENSURE_REL(dT2, 6.25, 8 * DBL_EPSILON);
    b = ball_v(-10, 0, 0, 1, 1, -0.6, 0, 0, 1.0); /* behind A, moving away */
    ENSURE(rc_toi(&rc_toi_frame_transport, &prm, &a, &b, ws, &c) == RC_MISS);
    b = ball_v(10, 0, 0, 1, 1, 0.6, 0, 0, 1.0); /* co-moving */
    ENSURE(rc_toi(&rc_toi_frame_transport, &prm, &a, &b, ws, &c) == RC_MISS);
    b = ball_v(10, 2.0, 0, 1, 1, -0.6, 0, 0, 1.0);
    ENSURE(rc_toi(&rc_toi_frame_transport, &prm, &a, &b, ws, &c) == RC_MISS);
    b = ball_v(1.0, 0.5, 0, 1, 1, -0.6, 0, 0, 1.0); /* centres 1.1 apart, approaching */
    ENSURE(rc_toi(&rc_toi_frame_transport, &prm, &a, &b, ws, &c) == RC_OK);
    ENSURE_REL(c.t, 1.0 / 1.2, 8 * DBL_EPSILON);
}

static double rnd(rc_test_rng *r, double lo, double hi) { return rc_test_range(r, lo, hi); }

/* c = inf, random pairs of spheres that do not overlap now: the decision is the sphere
 * frame's (same graze rule: -w.n/|w| = sqrt(R^2 - b^2)/R), the normal is the spheres' at
 * touching (to 1e-12: two different formulas for the same vector, each a few dozen
 * roundings, the closest-approach one well conditioned away from grazing, which the
 * margin below excludes), and the zmf law with it gives the classical hard-sphere
 * outcome J = (1 + eps) mu (w.n), computed here by hand. Only the time differs: the
 * closest approach comes sqrt(R^2 - b^2)/|w| after the touching. */
static void test_classical(void)
{
    rc_toi_params prm = rc_toi_params_default();
    rc_test_rng rng = {1616};
    int hits = 0;
    for (int i = 0; i < 4000; i++) {
        const int dim = 2 + (i & 1);
        rc_toi_ball a, b;
        a.r = rnd(&rng, 0.1, 2);
        b.r = rnd(&rng, 0.1, 2);
        a.m = rnd(&rng, 0.1, 5);
        b.m = rnd(&rng, 0.1, 5);
        a.x = rc_v3(rnd(&rng, -8, 8), rnd(&rng, -8, 8), dim == 3 ? rnd(&rng, -8, 8) : 0);
        b.x = rc_v3(rnd(&rng, -8, 8), rnd(&rng, -8, 8), dim == 3 ? rnd(&rng, -8, 8) : 0);
        a.p = rc_v3(rnd(&rng, -3, 3), rnd(&rng, -3, 3), dim == 3 ? rnd(&rng, -3, 3) : 0);
        b.p = rc_v3(rnd(&rng, -3, 3), rnd(&rng, -3, 3), dim == 3 ? rnd(&rng, -3, 3) : 0);
        const double R = a.r + b.r;
        if (rc_v3_norm(rc_v3_sub(b.x, a.x)) <= R)
            continue;
        double dT2;
        ENSURE(rc_toi_transport_impact(&prm, &a, &b, &dT2, NULL) == RC_OK);
        if (fabs(sqrt(dT2) - R) < 1e-6 * R)
            continue;
        rc_toi_contact cs, c;
        const int ss = rc_toi(&rc_toi_frame_sphere, &prm, &a, &b, ws, &cs);
        const int st = rc_toi(&rc_toi_frame_transport, &prm, &a, &b, ws, &c);
        ENSURE_MSG(st == ss, "pair %d: %d vs %d", i, st, ss);
        if (st != RC_OK || ss != RC_OK)
            continue;
        hits++;
        ENSURE_CLOSE(c.n.x, cs.n.x, 1e-12, 1.0);
        ENSURE_CLOSE(c.n.y, cs.n.y, 1e-12, 1.0);
        ENSURE_CLOSE(c.n.z, cs.n.z, 1e-12, 1.0);
        const rc_vec3 w = rc_v3_sub(rc_v3_scale(1 / b.m, b.p), rc_v3_scale(1 / a.m, a.p));
        const double wn = rc_v3_dot(w, cs.n), s = -wn / rc_v3_norm(w) * R;
        ENSURE_REL(c.t, cs.t + s / rc_v3_norm(w), 1e-12);
        const double eps = 0.7, mu = a.m * b.m / (a.m + b.m), J = (1 + eps) * mu * wn;
        rc_collision_params cp = rc_collision_params_default();
        cp.eps = eps;
        rc_particle pa = {a.m, a.p}, pb = {b.m, b.p};
        ENSURE(rc_collide(&rc_law_zmf, &cp, &pa, &pb, c.n) == RC_OK);
        const double ps = rc_v3_norm(a.p) + rc_v3_norm(b.p);
        const rc_vec3 pa_want = rc_v3_axpy(a.p, J, cs.n), pb_want = rc_v3_axpy(b.p, -J, cs.n);
        ENSURE_CLOSE(pa.p.x, pa_want.x, 1e-12, ps);
        ENSURE_CLOSE(pa.p.y, pa_want.y, 1e-12, ps);
        ENSURE_CLOSE(pa.p.z, pa_want.z, 1e-12, ps);
        ENSURE_CLOSE(pb.p.x, pb_want.x, 1e-12, ps);
        ENSURE_CLOSE(pb.p.y, pb_want.y, 1e-12, ps);
        ENSURE_CLOSE(pb.p.z, pb_want.z, 1e-12, ps);
    }
    printf("  c = inf: %d hits compared with the hard-sphere normal and outcome\n", hits);
    ENSURE(hits > 100);
}

/* The pair given in the frame moving at V: four-momenta boosted, each centre's event
 * (0, x) boosted to (t', x') and moved along its new worldline to t' = 0. */
static void to_frame(rc_vec3 V, double k, const rc_toi_ball *in, rc_toi_ball *out)
{
    const double M = sqrt(in->m * in->m + rc_v3_norm2(in->p) * k);
    rc_four q = {M, in->p}, e = {0.0, in->x};
    ENSURE(rc_boost(V, k, &q) == RC_OK && rc_boost(V, k, &e) == RC_OK);
    *out = *in;
    out->p = q.x;
    out->x = rc_v3_axpy(e.x, -e.t / q.t, q.x);
}

/* SMASH's covariant transverse distance squared (scatteraction.cc), c = 1, metric
 * (+,-,-,-), dx = x_a - x_b at equal times: an independent formula for d_T^2. */
static double smash_dT2(const rc_toi_ball *a, const rc_toi_ball *b)
{
    const double Ea = sqrt(a->m * a->m + rc_v3_norm2(a->p));
    const double Eb = sqrt(b->m * b->m + rc_v3_norm2(b->p));
    const rc_vec3 dx = rc_v3_sub(a->x, b->x);
    const double x2 = -rc_v3_norm2(dx), pa2 = a->m * a->m, pb2 = b->m * b->m;
    const double pax = -rc_v3_dot(a->p, dx), pbx = -rc_v3_dot(b->p, dx);
    const double papb = Ea * Eb - rc_v3_dot(a->p, b->p);
    return -x2 - (pa2 * pbx * pbx + pb2 * pax * pax - 2 * papb * pax * pbx) /
                     (papb * papb - pa2 * pb2);
}

/* Covariance: random pairs at c = 1 set up to reach their closest approach well ahead
 * (each centre at its approach position minus 30 of its velocity, so the approach is
 * ahead in every frame below), given in the table and in frames moving at 0.6 c in random
 * directions: the decision, d_T^2 (relative to max(d_T^2, R^2)) and the event agree to
 * 1e-12 relative (a few boosts of
 * numbers of size ~30, each a handful of roundings: ~1e-14; d_T^2 is well conditioned as
 * |d x w|^2/|w|^2). Decisions within 1e-9 R of the boundary are skipped (round-off
 * decides them). Also d_T^2 equals SMASH's formula to 1e-10 relative to |dx|^2 (it
 * subtracts terms of size |dx|^2). */
static void test_covariance(void)
{
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_test_rng rng = {616};
    int hits = 0, misses = 0;
    for (int i = 0; i < 2000; i++) {
        const int dim = 2 + (i & 1);
        rc_toi_ball a, b;
        a.r = rnd(&rng, 0.2, 1);
        b.r = rnd(&rng, 0.2, 1);
        a.m = rnd(&rng, 0.5, 2);
        b.m = rnd(&rng, 0.5, 2);
        rc_vec3 va = rc_v3(rnd(&rng, -0.6, 0.6), rnd(&rng, -0.6, 0.6), dim == 3 ? rnd(&rng, -0.6, 0.6) : 0);
        rc_vec3 vb = rc_v3(rnd(&rng, -0.6, 0.6), rnd(&rng, -0.6, 0.6), dim == 3 ? rnd(&rng, -0.6, 0.6) : 0);
        if (rc_v3_norm(rc_v3_sub(va, vb)) < 0.3)
            continue;
        const rc_vec3 Xa = rc_v3(rnd(&rng, -1.5, 1.5), rnd(&rng, -1.5, 1.5), dim == 3 ? rnd(&rng, -1.5, 1.5) : 0);
        const rc_vec3 Xb = rc_v3(rnd(&rng, -1.5, 1.5), rnd(&rng, -1.5, 1.5), dim == 3 ? rnd(&rng, -1.5, 1.5) : 0);
        ENSURE(rc_momentum_from_velocity(a.m, va, 1.0, &a.p) == RC_OK);
        ENSURE(rc_momentum_from_velocity(b.m, vb, 1.0, &b.p) == RC_OK);
        a.x = rc_v3_axpy(Xa, -30.0, va);
        b.x = rc_v3_axpy(Xb, -30.0, vb);
        double d2, d2p;
        ENSURE(rc_toi_transport_impact(&prm, &a, &b, &d2, NULL) == RC_OK);
        const double R = a.r + b.r;
        ENSURE_CLOSE(smash_dT2(&a, &b), d2, 1e-10, rc_v3_norm2(rc_v3_sub(a.x, b.x)));
        rc_toi_contact c, cp;
        const int st = rc_toi(&rc_toi_frame_transport, &prm, &a, &b, ws, &c);
        const double th = rnd(&rng, 0, 2 * M_PI), ph = dim == 3 ? rnd(&rng, -1, 1) : 0;
        const double sp = sqrt(1 - ph * ph);
        const rc_vec3 V = rc_v3_scale(0.6, rc_v3(sp * cos(th), sp * sin(th), ph));
        rc_toi_ball ap, bp;
        to_frame(V, 1.0, &a, &ap);
        to_frame(V, 1.0, &b, &bp);
        ENSURE(rc_toi_transport_impact(&prm, &ap, &bp, &d2p, NULL) == RC_OK);
        /* relative to max(d_T^2, R^2), the scale it is compared with: a nearly head-on
         * d_T^2 carries an absolute error of a few ulp of R^2 (the distances of ~30
         * travelled before the approach cancel in d) */
        ENSURE_CLOSE(d2p, d2, 1e-12, fmax(d2, R * R));
        if (fabs(sqrt(d2) - R) < 1e-9 * R)
            continue;
        const int stp = rc_toi(&rc_toi_frame_transport, &prm, &ap, &bp, ws, &cp);
        ENSURE_MSG(st == stp, "pair %d: %d in the table, %d at 0.6 c", i, st, stp);
        if (st != RC_OK || stp != RC_OK) {
            misses += st == RC_MISS;
            continue;
        }
        hits++;
        rc_four e = {cp.t, cp.x};
        ENSURE(rc_boost(rc_v3_scale(-1.0, V), 1.0, &e) == RC_OK);
        const double sc = 30.0;
        ENSURE_CLOSE(e.t, c.t, 1e-12, sc);
        ENSURE_CLOSE(e.x.x, c.x.x, 1e-12, sc);
        ENSURE_CLOSE(e.x.y, c.x.y, 1e-12, sc);
        ENSURE_CLOSE(e.x.z, c.x.z, 1e-12, sc);
    }
    printf("  0.6 c: %d hits and %d misses decided alike\n", hits, misses);
    ENSURE(hits > 100 && misses > 100);
}

/* The frame's declared properties and its place in the table. */
static void test_properties(void)
{
    ENSURE(rc_toi_frame_find("transport") == &rc_toi_frame_transport);
    ENSURE(rc_toi_frame_transport.pointlike && !rc_toi_frame_transport.contracted &&
           !rc_toi_frame_transport.wall_contracted && rc_toi_frame_transport.covariant &&
           !rc_toi_frame_transport.deferrable && !rc_toi_frame_transport.shapes);
    rc_toi_params prm = rc_toi_params_default();
    rc_toi_ball a = ball_v(0, 0, 0, 1, 1, 0.6, 0, 0, 0.0), b = a;
    double d2;
    ENSURE(rc_toi_transport_impact(NULL, &a, &b, &d2, NULL) == RC_EINVAL);
    ENSURE(rc_toi_transport_impact(&prm, &a, &b, NULL, NULL) == RC_EINVAL);
    b.r = -1;
    ENSURE(rc_toi_transport_impact(&prm, &a, &b, &d2, NULL) == RC_ERADIUS);
}

int main(void)
{
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    RUN_TEST(test_by_hand_cm);
    RUN_TEST(test_by_hand_moving_cm);
    RUN_TEST(test_miss);
    RUN_TEST(test_classical);
    RUN_TEST(test_covariance);
    RUN_TEST(test_properties);
    rc_toi_workspace_free(&ws);
    ENSURE(ws == NULL);
    RC_TEST_MAIN_END();
}
