/* test_toi.c — time of impact: the worked cases (head-on t = 7, wall at 0.8 r),
 * seed 002's eq. (17), c = inf equal (==) to the sphere result in every frame of shapes, the
 * documented outcomes (touching-but-separating, overlap, grazing, miss), the zmf frame
 * against an independent boost of the worldlines, the contracted solver without the
 * contact point giving the same bits, and input validation. */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "rc_test.h"
#include "relcol/relcol.h"

static rc_toi_workspace *ws;

static rc_toi_ball ball_v(double x, double y, double z, double r, double vx, double vy,
                          double vz, double inv_c2)
{
    rc_toi_ball b = {rc_v3(x, y, z), r, 1.0, rc_v3(0, 0, 0)};
    int st = rc_momentum_from_velocity(1.0, rc_v3(vx, vy, vz), inv_c2, &b.p);
    ENSURE(st == RC_OK);
    return b;
}

/* Head-on, c = 1, r = 1: A at 0 moving +0.6, B at 10 moving -0.6. Each is contracted
 * to 0.8 along x, so they touch when the gap is 1.6: 10 - 1.2 t = 1.6, t = 7; the
 * uncontracted spheres touch at 10 - 1.2 t = 2, t = 20/3. Tolerance: a handful of ulp
 * of 7 (the root is a quadratic root at a Brent-converged lambda, and the time is
 * stationary in lambda). */
static void test_head_on(void)
{
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_ball a = ball_v(0, 0, 0, 1, 0.6, 0, 0, 1.0), b = ball_v(10, 0, 0, 1, -0.6, 0, 0, 1.0);
    rc_toi_contact c;
    for (int i = 0; rc_toi_frames[i]; i++) {
        if (rc_toi_frames[i]->pointlike)
            continue; /* points meet at closest approach: test_transport.c */
        int st = rc_toi(rc_toi_frames[i], &prm, &a, &b, ws, &c);
        ENSURE(st == RC_OK);
        const double want = rc_toi_frames[i] == &rc_toi_frame_sphere ? 20.0 / 3.0 : 7.0;
        ENSURE_REL(c.t, want, 8 * DBL_EPSILON);
        ENSURE_CLOSE(c.n.x, 1.0, 8 * DBL_EPSILON, 1.0);
        ENSURE_CLOSE(c.n.y, 0.0, 8 * DBL_EPSILON, 1.0);
        /* contact point: midway, x = 5 */
        ENSURE_CLOSE(c.x.x, 5.0, 16 * DBL_EPSILON, 5.0);
    }
    /* 3-D, along z and along a diagonal: same numbers (rotation invariance) */
    a = ball_v(0, 0, 0, 1, 0, 0, 0.6, 1.0);
    b = ball_v(0, 0, 10, 1, 0, 0, -0.6, 1.0);
    ENSURE(rc_toi(&rc_toi_frame_table, &prm, &a, &b, ws, &c) == RC_OK);
    ENSURE_REL(c.t, 7.0, 8 * DBL_EPSILON);
    const double s = 1.0 / sqrt(3.0);
    a = ball_v(0, 0, 0, 1, 0.6 * s, 0.6 * s, 0.6 * s, 1.0);
    b = ball_v(10 * s, 10 * s, 10 * s, 1, -0.6 * s, -0.6 * s, -0.6 * s, 1.0);
    ENSURE(rc_toi(&rc_toi_frame_table, &prm, &a, &b, ws, &c) == RC_OK);
    ENSURE_REL(c.t, 7.0, 64 * DBL_EPSILON); /* diagonal data carry rounding of s */
    /* one ball at rest: the root sits on the edge of the lambda bracket */
    a = ball_v(0, 0, 0, 1, 0.6, 0, 0, 1.0);
    b = ball_v(10, 0, 0, 1, 0, 0, 0, 1.0);
    ENSURE(rc_toi(&rc_toi_frame_table, &prm, &a, &b, ws, &c) == RC_OK);
    ENSURE_REL(c.t, (10.0 - 1.8) / 0.6, 8 * DBL_EPSILON);
}

/* A ball moving at 0.6 c towards a wall touches it when its centre is 0.8 r away; for
 * every side of a box, and obliquely r sqrt(1 - v_n^2/c^2). */
static void test_wall(void)
{
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    const double lo[3] = {-10, -20, -30}, hi[3] = {10, 20, 30};
    const double r = 1.5;
    for (int side = 0; side < 6; side++) {
        const int axis = side / 2;
        const double sign = side % 2 ? 1.0 : -1.0;
        double v[3] = {0, 0, 0};
        v[axis] = 0.6 * sign;
        rc_toi_ball a = ball_v(0, 0, 0, r, v[0], v[1], v[2], 1.0);
        double t;
        int sd;
        rc_vec3 n, x;
        ENSURE(rc_toi_box(&prm, 1, &a, 3, lo, hi, &t, &sd, &n, &x) == RC_OK);
        ENSURE(sd == side);
        const double wall = sign > 0 ? hi[axis] : -lo[axis];
        ENSURE_REL(t, (wall - 0.8 * r) / 0.6, 4 * DBL_EPSILON);
        ENSURE_CLOSE(rc_v3_get(x, axis), sign * wall, 4 * DBL_EPSILON, wall);
        /* the naive model: centre r away */
        ENSURE(rc_toi_box(&prm, 0, &a, 3, lo, hi, &t, &sd, &n, &x) == RC_OK);
        ENSURE_REL(t, (wall - r) / 0.6, 4 * DBL_EPSILON);
    }
    /* oblique: v = (0.5, 0.7), c = 1; support along x is r sqrt(1 - 0.25) */
    rc_toi_ball a = ball_v(1, 2, 0, r, 0.5, 0.7, 0, 1.0);
    double t;
    rc_vec3 x;
    ENSURE(rc_toi_wall(&prm, 1, &a, rc_v3(1, 0, 0), 10, &t, &x) == RC_OK);
    ENSURE_REL(t, (9 - r * sqrt(0.75)) / 0.5, 8 * DBL_EPSILON);
    /* the support point lies on the wall */
    ENSURE_CLOSE(x.x, 10.0, 8 * DBL_EPSILON, 10.0);
    /* walls: touching and separating, overlapping, moving away */
    a = ball_v(9.2, 0, 0, 1, -0.6, 0, 0, 1.0);
    ENSURE(rc_toi_wall(&prm, 1, &a, rc_v3(1, 0, 0), 10, &t, NULL) == RC_MISS);
    a = ball_v(9.2, 0, 0, 1, 0.6, 0, 0, 1.0);
    ENSURE(rc_toi_wall(&prm, 1, &a, rc_v3(1, 0, 0), 10, &t, NULL) == RC_OK && t == 0.0);
    a = ball_v(9.3, 0, 0, 1, 0.6, 0, 0, 1.0);
    ENSURE(rc_toi_wall(&prm, 1, &a, rc_v3(1, 0, 0), 10, &t, NULL) == RC_EOVERLAP);
    ENSURE(rc_toi_wall(&prm, 0, &a, rc_v3(1, 0, 0), 10, &t, NULL) == RC_EOVERLAP);
    a = ball_v(0, 0, 0, 1, 0, 0.6, 0, 1.0);
    ENSURE(rc_toi_wall(&prm, 1, &a, rc_v3(1, 0, 0), 10, &t, NULL) == RC_MISS);
    /* c = inf: the contracted wall time is the sphere time exactly */
    prm.c = INFINITY;
    a = ball_v(0.3, 0.1, 0, 0.7, 0.61, -0.2, 0, 0.0);
    double t1, t2;
    rc_vec3 x1, x2;
    ENSURE(rc_toi_wall(&prm, 1, &a, rc_v3(1, 0, 0), 10, &t1, &x1) == RC_OK);
    ENSURE(rc_toi_wall(&prm, 0, &a, rc_v3(1, 0, 0), 10, &t2, &x2) == RC_OK);
    ENSURE(t1 == t2 && x1.x == x2.x && x1.y == x2.y);
}

/* Seed 002 eq. (17): t = {d cos(g_xy - g_v) - sqrt[(r1+r2)^2 - (d sin(g_xy - g_v))^2]}
 * / |v1 - v2|, g_xy the direction from ball 1 to ball 2, g_v that of v1 - v2 (taken
 * with atan2: the seed's arctan loses the quadrant). The trig form carries a few ulp of
 * angle rounding times d/|v|: 1e-13 relative is ~500 ulp of headroom. */
static void test_seed002_eq17(void)
{
    rc_toi_params prm = rc_toi_params_default();
    rc_test_rng rng = {2002};
    int compared = 0;
    for (int i = 0; i < 6000; i++) {
        const double r1 = rc_test_range(&rng, 0.2, 2), r2 = rc_test_range(&rng, 0.2, 2);
        rc_vec3 x1 = rc_v3(rc_test_range(&rng, -10, 10), rc_test_range(&rng, -10, 10), 0);
        rc_vec3 x2 = rc_v3(rc_test_range(&rng, -10, 10), rc_test_range(&rng, -10, 10), 0);
        rc_vec3 v1 = rc_v3(rc_test_range(&rng, -3, 3), rc_test_range(&rng, -3, 3), 0);
        rc_vec3 v2 = rc_v3(rc_test_range(&rng, -3, 3), rc_test_range(&rng, -3, 3), 0);
        const double R = r1 + r2;
        const double d = hypot(x2.x - x1.x, x2.y - x1.y);
        if (d < 1.1 * R)
            continue;
        const double gxy = atan2(x2.y - x1.y, x2.x - x1.x);
        const double gv = atan2(v1.y - v2.y, v1.x - v2.x);
        const double s = d * sin(gxy - gv), cs = d * cos(gxy - gv);
        double t;
        rc_vec3 n;
        /* our ball 0 = seed's ball 1: d = x2 - x1, w = v2 - v1 */
        int st = rc_toi_sphere_rel(R, rc_v3_sub(x2, x1), rc_v3_sub(v2, v1), &prm, &t, &n);
        if (fabs(s) > R || cs <= 0) {
            ENSURE(st == RC_MISS);
            continue;
        }
        ENSURE(st == RC_OK);
        const double ts = (cs - sqrt(R * R - s * s)) / hypot(v1.x - v2.x, v1.y - v2.y);
        if (R * R - s * s < 1e-6 * R * R)
            continue; /* the seed form loses digits at grazing; ours does not */
        ENSURE_REL(t, ts, 1e-13);
        compared++;
    }
    ENSURE_MSG(compared > 300, "%d", compared);
}

/* c = inf: every frame of shapes returns exactly (==) the uncontracted-sphere result. */
static void test_classical_exact(void)
{
    rc_toi_params prm = rc_toi_params_default();
    rc_test_rng rng = {77};
    int hits = 0;
    for (int i = 0; i < 4000; i++) {
        const int dim = 2 + (i & 1);
        rc_toi_ball a, b;
        a.r = rc_test_range(&rng, 0.1, 2);
        b.r = rc_test_range(&rng, 0.1, 2);
        a.m = rc_test_range(&rng, 0.1, 5);
        b.m = rc_test_range(&rng, 0.1, 5);
        a.x = rc_v3(rc_test_range(&rng, -8, 8), rc_test_range(&rng, -8, 8),
                    dim == 3 ? rc_test_range(&rng, -8, 8) : 0);
        b.x = rc_v3(rc_test_range(&rng, -8, 8), rc_test_range(&rng, -8, 8),
                    dim == 3 ? rc_test_range(&rng, -8, 8) : 0);
        a.p = rc_v3(rc_test_range(&rng, -3, 3), rc_test_range(&rng, -3, 3),
                    dim == 3 ? rc_test_range(&rng, -3, 3) : 0);
        b.p = rc_v3(rc_test_range(&rng, -3, 3), rc_test_range(&rng, -3, 3),
                    dim == 3 ? rc_test_range(&rng, -3, 3) : 0);
        rc_toi_contact cs, c;
        const int ss = rc_toi(&rc_toi_frame_sphere, &prm, &a, &b, ws, &cs);
        for (int f = 0; rc_toi_frames[f]; f++) {
            if (rc_toi_frames[f]->pointlike)
                continue; /* another event by design: test_transport.c's c = inf test */
            const int st = rc_toi(rc_toi_frames[f], &prm, &a, &b, ws, &c);
            ENSURE_MSG(st == ss, "frame %s: %d vs %d", rc_toi_frames[f]->name, st, ss);
            if (st == RC_OK && ss == RC_OK) {
                ENSURE_MSG(c.t == cs.t && c.x.x == cs.x.x && c.x.y == cs.x.y &&
                               c.x.z == cs.x.z && c.n.x == cs.n.x && c.n.y == cs.n.y &&
                               c.n.z == cs.n.z,
                           "frame %s: t %.17g vs %.17g", rc_toi_frames[f]->name, c.t, cs.t);
            }
        }
        hits += ss == RC_OK;
        /* the sphere result itself: |d + w t| = R at contact */
        if (ss == RC_OK) {
            rc_vec3 w = rc_v3_sub(rc_v3_scale(1 / b.m, b.p), rc_v3_scale(1 / a.m, a.p));
            rc_vec3 d = rc_v3_axpy(rc_v3_sub(b.x, a.x), cs.t, w);
            ENSURE_REL(rc_v3_norm(d), a.r + b.r, 1e-13);
        }
    }
    ENSURE(hits > 100);
}

/* The documented outcomes: touching and approaching -> t = 0; touching and separating
 * -> RC_MISS; overlapping -> RC_EOVERLAP; grazing -> RC_MISS; parallel -> RC_MISS. */
static void test_outcomes(void)
{
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_contact c;
    /* contracted head-on pair placed at contact (gap 1.6) */
    rc_toi_ball a = ball_v(0, 0, 0, 1, 0.6, 0, 0, 1.0), b = ball_v(1.6, 0, 0, 1, -0.6, 0, 0, 1.0);
    for (int f = 0; f < 2; f++) {
        const rc_toi_frame *fr = f ? &rc_toi_frame_zmf : &rc_toi_frame_table;
        ENSURE(rc_toi(fr, &prm, &a, &b, ws, &c) == RC_OK && c.t == 0.0);
        rc_toi_ball a2 = a, b2 = b;
        a2.p = rc_v3_scale(-1, a.p);
        b2.p = rc_v3_scale(-1, b.p);
        ENSURE(rc_toi(fr, &prm, &a2, &b2, ws, &c) == RC_MISS);
        b2 = b;
        b2.x.x = 1.5; /* overlapping the contracted shapes, inside the bounding spheres */
        ENSURE(rc_toi(fr, &prm, &a, &b2, ws, &c) == RC_EOVERLAP);
    }
    /* bounding spheres overlap (gap 1.7 < 2) but the contracted shapes (gap 1.6) do
     * not: approaching hits at t = 0.1/1.2, separating is a miss */
    b.x.x = 1.7;
    for (int f = 0; f < 2; f++) {
        const rc_toi_frame *fr = f ? &rc_toi_frame_zmf : &rc_toi_frame_table;
        ENSURE(rc_toi(fr, &prm, &a, &b, ws, &c) == RC_OK);
        ENSURE_REL(c.t, 0.1 / 1.2, 1e-13); /* 1.7 - 1.6 carries ulp of 1.7: ~1e-15/0.1 */
        rc_toi_ball a2 = a, b2 = b;
        a2.p = rc_v3_scale(-1, a.p);
        b2.p = rc_v3_scale(-1, b.p);
        ENSURE(rc_toi(fr, &prm, &a2, &b2, ws, &c) == RC_MISS);
    }
    b.x.x = 1.6;
    /* in the naive model that pair overlaps (bounding spheres) */
    ENSURE(rc_toi(&rc_toi_frame_sphere, &prm, &a, &b, ws, &c) == RC_EOVERLAP);

    /* 2-D oblique: advance to the contact found, then ask again */
    rc_test_rng rng = {5};
    int n_touch = 0;
    for (int i = 0; i < 600; i++) {
        a = ball_v(0, 0, 0, rc_test_range(&rng, 0.5, 1.5), rc_test_range(&rng, 0, 0.6),
                   rc_test_range(&rng, -0.6, 0.6), 0, 1.0);
        b = ball_v(8, rc_test_range(&rng, -1, 1), 0, rc_test_range(&rng, 0.5, 1.5),
                   rc_test_range(&rng, -0.6, 0), rc_test_range(&rng, -0.6, 0.6), 0, 1.0);
        if (rc_toi(&rc_toi_frame_table, &prm, &a, &b, ws, &c) != RC_OK)
            continue;
        rc_toi_ball a2 = a, b2 = b;
        a2.x = rc_v3_axpy(a.x, c.t, rc_velocity(a.m, a.p, 1.0));
        b2.x = rc_v3_axpy(b.x, c.t, rc_velocity(b.m, b.p, 1.0));
        rc_toi_contact c2;
        int st = rc_toi(&rc_toi_frame_table, &prm, &a2, &b2, ws, &c2);
        /* touching within touch_tol (1e-12) and approaching: contact now */
        ENSURE_MSG(st == RC_OK && c2.t <= 1e-11, "st %d t %g", st, c2.t);
        if (st == RC_OK && c2.t == 0.0)
            n_touch++;
        a2.p = rc_v3_scale(-1, a.p);
        b2.p = rc_v3_scale(-1, b.p);
        ENSURE(rc_toi(&rc_toi_frame_table, &prm, &a2, &b2, ws, &c2) == RC_MISS);
    }
    ENSURE_MSG(n_touch > 50, "%d", n_touch);
    /* parallel motion, separated: miss; no relative motion: miss */
    a = ball_v(0, 0, 0, 1, 0.5, 0, 0, 1.0);
    b = ball_v(0, 3, 0, 1, 0.5, 0, 0, 1.0);
    ENSURE(rc_toi(&rc_toi_frame_table, &prm, &a, &b, ws, &c) == RC_MISS);
    /* exactly grazing spheres (impact parameter = R): a miss, never a time */
    prm.c = INFINITY;
    a = ball_v(0, 0, 0, 1, 1, 0, 0, 0.0);
    b = ball_v(10, 2, 0, 1, 0, 0, 0, 0.0);
    ENSURE(rc_toi(&rc_toi_frame_table, &prm, &a, &b, ws, &c) == RC_MISS);
}

/* A pair whose bounding spheres hit but whose contracted shapes miss is RC_MISS, and
 * just inside the contracted width it hits. A (r = 1) moves along +y at beta = 0.99 c,
 * B (r = 1) along +x at beta: w = beta (1, -1). Across w, along e = (1, 1)/sqrt 2, each
 * shape's support is sqrt(1 - (beta.e)^2) = sqrt(1 - beta^2/2), so the Minkowski sum's
 * half-width is hw = 2 sqrt(1 - beta^2/2) = 1.428 < 2 = the bounding spheres'. */
static void test_contraction_miss(void)
{
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    const double s = sqrt(0.5), beta = 0.99;
    const double hw = 2 * sqrt(1 - beta * beta / 2);
    /* 1e-6 either side of the contracted half-width: far above the solver's round-off
     * (~1e-15) and the grazing tolerance (a contact at 1e-6 relative inside hw meets the
     * surface at an angle ~sqrt(2e-6) ~ 1e-3 >> graze_tol = 1e-9) */
    for (int k = 0; k < 2; k++) {
        const double q = k ? hw * (1 + 1e-6) : hw * (1 - 1e-6);
        /* B starts at -10 w_hat + q e relative to A */
        const rc_vec3 wh = rc_v3(s, s, 0), np = rc_v3(s, -s, 0);
        rc_toi_ball a = ball_v(0, 0, 0, 1, 0, beta, 0, 1.0);
        rc_toi_ball b = ball_v(-10 * np.x + q * wh.x, -10 * np.y + q * wh.y, 0, 1, beta, 0, 0, 1.0);
        rc_toi_contact c;
        int st = rc_toi(&rc_toi_frame_table, &prm, &a, &b, ws, &c);
        ENSURE_MSG(st == (k ? RC_MISS : RC_OK), "k %d st %d", k, st);
        /* and the bounding spheres (half-width 2 > hw) do hit */
        double ts;
        rc_vec3 ns;
        ENSURE(rc_toi_sphere_rel(2.0, rc_v3_sub(b.x, a.x),
                                 rc_v3_sub(rc_velocity(1, b.p, 1), rc_velocity(1, a.p, 1)),
                                 &prm, &ts, &ns) == RC_OK);
    }
}

/* The zmf frame against an independent construction: boost every worldline into the
 * pair's ZMF with rc_boost / rc_velocity_boost, solve in the table frame there, boost
 * the event back, and compare; and check the normal is the zmf law's q = (u.n/c^2, n)
 * (its boost into the ZMF is purely spatial). Tolerance 1e-11: two routes through a
 * handful of boosts and a converged root find. */
static void test_zmf_frame(void)
{
    rc_toi_params prm = rc_toi_params_default();
    const double k = 1.0;
    prm.c = rc_test_c_of(k);
    rc_test_rng rng = {99};
    int compared = 0;
    for (int i = 0; i < 1000; i++) {
        const int dim = 2 + (i & 1);
        rc_toi_ball a = ball_v(0, 0, 0, rc_test_range(&rng, 0.5, 1.5), rc_test_range(&rng, 0, 0.8),
                               rc_test_range(&rng, -0.4, 0.4),
                               dim == 3 ? rc_test_range(&rng, -0.4, 0.4) : 0, k);
        rc_toi_ball b = ball_v(8, rc_test_range(&rng, -1, 1), dim == 3 ? rc_test_range(&rng, -1, 1) : 0,
                               rc_test_range(&rng, 0.5, 1.5), rc_test_range(&rng, -0.8, 0),
                               rc_test_range(&rng, -0.4, 0.4),
                               dim == 3 ? rc_test_range(&rng, -0.4, 0.4) : 0, k);
        b.m = rc_test_range(&rng, 0.5, 2);
        rc_toi_contact c;
        if (rc_toi(&rc_toi_frame_zmf, &prm, &a, &b, ws, &c) != RC_OK)
            continue;
        rc_particle pa = {a.m, a.p}, pb = {b.m, b.p};
        rc_particle pp[2] = {pa, pb};
        rc_vec3 u;
        ENSURE(rc_zmf(pp, 2, k, &u, NULL) == RC_OK);
        rc_toi_ball az = a, bz = b;
        rc_four e0 = {0, a.x}, e1 = {0, b.x}, q0 = rc_particle_four(&pa, k),
                q1 = rc_particle_four(&pb, k);
        rc_boost(u, k, &e0);
        rc_boost(u, k, &e1);
        rc_boost(u, k, &q0);
        rc_boost(u, k, &q1);
        rc_vec3 v0z, v1z;
        rc_velocity_boost(rc_velocity(a.m, a.p, k), u, k, &v0z);
        rc_velocity_boost(rc_velocity(b.m, b.p, k), u, k, &v1z);
        const double tau0 = fmax(e0.t, e1.t);
        az.x = rc_v3_axpy(e0.x, tau0 - e0.t, v0z);
        bz.x = rc_v3_axpy(e1.x, tau0 - e1.t, v1z);
        az.p = q0.x;
        bz.p = q1.x;
        rc_toi_contact cz;
        int st = rc_toi(&rc_toi_frame_table, &prm, &az, &bz, ws, &cz);
        ENSURE(st == RC_OK);
        if (st != RC_OK)
            continue;
        rc_four ev = {tau0 + cz.t, cz.x};
        rc_boost(rc_v3_scale(-1, u), k, &ev);
        ENSURE_CLOSE(c.t, ev.t, 1e-11, fmax(1.0, fabs(ev.t)));
        ENSURE_CLOSE(c.x.x, ev.x.x, 1e-11, 10.0);
        ENSURE_CLOSE(c.x.y, ev.x.y, 1e-11, 10.0);
        ENSURE_CLOSE(c.x.z, ev.x.z, 1e-11, 10.0);
        rc_four qn = {0, cz.n};
        rc_boost(rc_v3_scale(-1, u), k, &qn);
        const double len = rc_v3_norm(qn.x);
        ENSURE_CLOSE(c.n.x, qn.x.x / len, 1e-11, 1.0);
        ENSURE_CLOSE(c.n.y, qn.x.y / len, 1e-11, 1.0);
        ENSURE_CLOSE(c.n.z, qn.x.z / len, 1e-11, 1.0);
        ENSURE_CLOSE(rc_v3_norm(c.n), 1.0, 4 * DBL_EPSILON, 1.0);
        /* q = (u.n/c^2, n) boosted into the ZMF has no time component */
        rc_four q = {rc_v3_dot(u, c.n) * k, c.n};
        rc_boost(u, k, &q);
        ENSURE_CLOSE(q.t, 0.0, 1e-14, 1.0);
        compared++;
    }
    ENSURE_MSG(compared > 200, "%d", compared);
}

/* Units: scaling every length by L and every speed (and c) by V scales the time by
 * L/V and the point by L, to round-off (the solver works in power-of-two units, so the
 * huge and tiny scales neither overflow nor lose digits). */
static void test_scale_invariance(void)
{
    rc_test_rng rng = {123};
    const double Ls[3] = {1e-30, 1.0, 1e30}, Vs[3] = {1e-20, 1.0, 3e8};
    int compared = 0;
    for (int i = 0; i < 200; i++) {
        const int dim = 2 + (i & 1);
        rc_toi_ball a = ball_v(0, 0, 0, rc_test_range(&rng, 0.5, 1.5), rc_test_range(&rng, 0, 0.8),
                               rc_test_range(&rng, -0.4, 0.4),
                               dim == 3 ? rc_test_range(&rng, -0.4, 0.4) : 0, 1.0);
        rc_toi_ball b = ball_v(8, rc_test_range(&rng, -1, 1), dim == 3 ? rc_test_range(&rng, -1, 1) : 0,
                               rc_test_range(&rng, 0.5, 1.5), rc_test_range(&rng, -0.8, 0),
                               rc_test_range(&rng, -0.4, 0.4),
                               dim == 3 ? rc_test_range(&rng, -0.4, 0.4) : 0, 1.0);
        rc_toi_params prm = rc_toi_params_default();
        prm.c = 1.0;
        rc_toi_contact c0;
        if (rc_toi(&rc_toi_frame_table, &prm, &a, &b, ws, &c0) != RC_OK)
            continue;
        for (int j = 0; j < 3; j++) {
            const double L = Ls[j], V = Vs[j];
            rc_toi_ball as = a, bs = b;
            as.x = rc_v3_scale(L, a.x);
            bs.x = rc_v3_scale(L, b.x);
            as.r *= L;
            bs.r *= L;
            as.p = rc_v3_scale(V, a.p); /* m = 1: p scales with v */
            bs.p = rc_v3_scale(V, b.p);
            prm.c = V;
            rc_toi_contact c;
            ENSURE(rc_toi(&rc_toi_frame_table, &prm, &as, &bs, ws, &c) == RC_OK);
            /* 1e-12: the scaled inputs carry their own rounding (inv_c2, p, x) */
            ENSURE_REL(c.t, c0.t * (L / V), 1e-12);
            ENSURE_CLOSE(c.x.x, c0.x.x * L, 1e-12, 10 * L);
            ENSURE_CLOSE(c.n.y, c0.n.y, 1e-12, 1.0);
        }
        compared++;
    }
    ENSURE(compared > 50);
}

/* rc_toi_shapes_rel without the contact point (y0 = NULL, what the engine asks for):
 * the same time and normal, bit for bit, and the same outcome, on random pairs -- near
 * (bounding spheres overlapping: overlap, touching and moving outcomes) and far. */
static void test_no_contact_point(void)
{
    rc_test_rng rng = {321};
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    int hits = 0, others = 0;
    for (int i = 0; i < 2000; i++) {
        const int dim = 2 + (i & 1);
        rc_toi_shape sh[2];
        for (int j = 0; j < 2; j++) {
            const rc_vec3 p = rc_v3(rc_test_range(&rng, -3, 3), rc_test_range(&rng, -3, 3),
                                    dim == 3 ? rc_test_range(&rng, -3, 3) : 0);
            sh[j] = rc_toi_shape_of(rc_test_range(&rng, 0.5, 1.5), 1.0, p, 1.0);
        }
        const double R = sh[0].r + sh[1].r, far = i % 4 ? 1.0 : 4.0;
        const rc_vec3 d = rc_v3(R * rc_test_range(&rng, 0.6, far), rc_test_range(&rng, -1, 1),
                                dim == 3 ? rc_test_range(&rng, -1, 1) : 0);
        const rc_vec3 w = rc_v3(rc_test_range(&rng, -1.5, 0.2), rc_test_range(&rng, -0.5, 0.5),
                                dim == 3 ? rc_test_range(&rng, -0.5, 0.5) : 0);
        double t1 = NAN, t2 = NAN;
        rc_vec3 y0, n1 = rc_v3(0, 0, 0), n2 = rc_v3(0, 0, 0);
        const int s1 = rc_toi_shapes_rel(&sh[0], &sh[1], d, w, &prm, ws, &t1, &y0, &n1);
        const int s2 = rc_toi_shapes_rel(&sh[0], &sh[1], d, w, &prm, ws, &t2, NULL, &n2);
        ENSURE(s1 == s2);
        if (s1 == RC_OK) {
            ENSURE(t1 == t2 && n1.x == n2.x && n1.y == n2.y && n1.z == n2.z);
            hits++;
        } else {
            others++;
        }
    }
    ENSURE(hits > 100 && others > 100);
}

static void test_validation(void)
{
    rc_toi_params prm = rc_toi_params_default();
    rc_toi_ball a = ball_v(0, 0, 0, 1, 0.5, 0, 0, 0), b = ball_v(5, 0, 0, 1, 0, 0, 0, 0);
    rc_toi_contact c;
    ENSURE(rc_toi(NULL, &prm, &a, &b, ws, &c) == RC_EINVAL);
    ENSURE(rc_toi(&rc_toi_frame_table, &prm, &a, &b, NULL, &c) == RC_EINVAL);
    rc_toi_ball bad = a;
    bad.r = 0;
    ENSURE(rc_toi(&rc_toi_frame_table, &prm, &bad, &b, ws, &c) == RC_ERADIUS);
    bad = a;
    bad.x.y = NAN;
    ENSURE(rc_toi(&rc_toi_frame_table, &prm, &bad, &b, ws, &c) == RC_ENONFINITE);
    bad = a;
    bad.m = -1;
    ENSURE(rc_toi(&rc_toi_frame_table, &prm, &bad, &b, ws, &c) == RC_EMASS);
    bad = a;
    bad.p.x = INFINITY;
    ENSURE(rc_toi(&rc_toi_frame_table, &prm, &bad, &b, ws, &c) == RC_ENONFINITE);
    rc_toi_params p2 = prm;
    p2.c = -1.0;
    ENSURE(rc_toi(&rc_toi_frame_table, &p2, &a, &b, ws, &c) == RC_ESPEEDOFLIGHT);
    p2 = prm;
    p2.graze_tol = NAN;
    ENSURE(rc_toi(&rc_toi_frame_table, &p2, &a, &b, ws, &c) == RC_EINVAL);
    ENSURE(rc_toi_frame_find("zmf") == &rc_toi_frame_zmf);
    ENSURE(rc_toi_frame_find("table") == &rc_toi_frame_table);
    ENSURE(rc_toi_frame_find("sphere") == &rc_toi_frame_sphere);
    ENSURE(rc_toi_frame_find("nope") == NULL);
    double lo[2] = {0, 0}, hi[2] = {0, 1}, t;
    ENSURE(rc_toi_box(&prm, 1, &a, 2, lo, hi, &t, NULL, NULL, NULL) == RC_EINVAL);
    ENSURE(rc_toi_box(&prm, 1, &a, 4, lo, hi, &t, NULL, NULL, NULL) == RC_EDIM);
    ENSURE(rc_toi_wall(&prm, 1, &a, rc_v3(0, 0, 0), 1, &t, NULL) == RC_EZERONORMAL);
    /* a ball sticking out of the box */
    double lo2[2] = {0.5, -5}, hi2[2] = {5, 5};
    ENSURE(rc_toi_box(&prm, 1, &a, 2, lo2, hi2, &t, NULL, NULL, NULL) == RC_EOVERLAP);
}

int main(void)
{
    if (rc_toi_workspace_create(&ws) != RC_OK)
        return 1;
    RUN_TEST(test_head_on);
    RUN_TEST(test_wall);
    RUN_TEST(test_seed002_eq17);
    RUN_TEST(test_classical_exact);
    RUN_TEST(test_outcomes);
    RUN_TEST(test_contraction_miss);
    RUN_TEST(test_zmf_frame);
    RUN_TEST(test_scale_invariance);
    RUN_TEST(test_no_contact_point);
    RUN_TEST(test_validation);
    rc_toi_workspace_free(&ws);
    ENSURE(ws == NULL);
    RC_TEST_MAIN_END();
}
