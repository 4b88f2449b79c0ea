/* test_gravity_pairs — two balls' contact time at one instant of each coupling's clock
 * (papers/gravity.md section 3: equivalence's quartic on the box's slices, newtonian's
 * conservative advancement) against brute force: the distance along both paths (the drift
 * that test_gravity_drift holds against rk8pd) sampled densely and the first fall below
 * r_a + r_b bisected; classically against the field-free quadratic, since both balls fall
 * alike; bad inputs refused. */
#include <float.h>

#include "gravity_util.h"

enum { SAMPLES = 4000 };

typedef struct pair_q {
    const rc_gravity_coupling *cp;
    const rc_gravity *f;
    const rc_toi_ball *a, *b;
} pair_q;

/* the gap between the two spheres after t, both moved by the drift */
static double gap_fn(double t, void *ctx)
{
    const pair_q *q = ctx;
    rc_vec3 xa = q->a->x, pa = q->a->p, xb = q->b->x, pb = q->b->p;
    q->cp->drift(q->f, q->a->m, &xa, &pa, t);
    q->cp->drift(q->f, q->b->m, &xb, &pb, t);
    return rc_v3_norm(rc_v3_sub(xa, xb)) - (q->a->r + q->b->r);
}

static double gap_at(const rc_gravity_coupling *cp, const rc_gravity *f, const rc_toi_ball *a,
                     const rc_toi_ball *b, double t)
{
    pair_q q = {cp, f, a, b};
    return gap_fn(t, &q);
}

static double brute(const rc_gravity_coupling *cp, const rc_gravity *f, const rc_toi_ball *a,
                    const rc_toi_ball *b, double tmax)
{
    pair_q q = {cp, f, a, b};
    return grav_first_change(gap_fn, &q, tmax, SAMPLES);
}

static void random_pair(rc_test_rng *r, int axis, double c, rc_toi_ball *a, rc_toi_ball *b)
{
    const double pm = isinf(c) ? 1.5 : 0.9 * c;
    rc_vec3 x, p;
    grav_random_ball(r, axis, 2.0, pm, &a->m, &x, &p);
    a->x = x, a->p = p, a->r = rc_test_range(r, 0.05, 0.3);
    grav_random_ball(r, axis, 2.0, pm, &b->m, &x, &p);
    b->r = rc_test_range(r, 0.05, 0.3);
    /* a partner within a few radii, above the floor */
    rc_vec3 off = grav_cube(r, 1.0);
    off = rc_v3_scale((a->r + b->r) * rc_test_range(r, 1.05, 5.0) / rc_v3_norm(off), off);
    b->x = rc_v3_add(a->x, off);
    if (rc_v3_get(b->x, axis) < 0.01)
        rc_v3_set(&b->x, axis, rc_v3_get(b->x, axis) + 2.0 * (a->r + b->r));
    b->p = p;
    /* half the pairs aimed at each other, give or take, so that contacts are common */
    if (rc_test_uniform(r) < 0.5) {
        const rc_vec3 aim = rc_v3_scale(-rc_test_range(r, 0.2, 0.8) * pm * b->m / rc_v3_norm(off), off);
        b->p = rc_v3_add(rc_v3_scale(0.1, b->p), aim);
        a->p = rc_v3_scale(0.1, a->p);
    }
}

static void check(const rc_gravity_coupling *cp, double c, uint64_t seed, double tol)
{
    rc_test_rng r = {seed};
    const double tmax = 3.0;
    long hits = 0, misses = 0;
    for (int i = 0; i < 400; i++) {
        rc_gravity f = {rc_test_range(&r, 0.3, 2.0), i % 3, 0.0};
        rc_inv_c2(c, &f.inv_c2);
        rc_toi_ball a, b;
        random_pair(&r, f.axis, c, &a, &b);
        if (gap_at(cp, &f, &a, &b, 0.0) <= 0.0)
            continue;
        double t = -1.0;
        const int st = cp->pair_time(&f, &a, &b, tmax, &t);
        ENSURE_MSG(st == RC_OK || st == RC_MISS, "%s c %g: status %d", cp->name, c, st);
        const double tb = brute(cp, &f, &a, &b, tmax);
        if (tb > 0.0) {
            hits++;
            ENSURE_MSG(st == RC_OK, "%s c %g: brute force touches at %.17g, got %d", cp->name,
                       c, tb, st);
            if (st == RC_OK) {
                ENSURE_CLOSE(t, tb, tol, 1.0 + tb);
                ENSURE_CLOSE(gap_at(cp, &f, &a, &b, t), 0.0, 1e-9, a.r + b.r);
            }
        } else {
            misses++;
            ENSURE_MSG(st == RC_MISS, "%s c %g: no contact by %g, got t = %.17g", cp->name, c,
                       tmax, t);
        }
    }
    printf("  %s c %g: %ld contacts, %ld misses\n", cp->name, c, hits, misses);
    ENSURE(hits > 50 && misses > 50);
}

static void test_equivalence(void)
{
    check(&rc_gravity_equivalence, 1.0, 31, 1e-9);
    check(&rc_gravity_equivalence, 3.0, 32, 1e-9);
    check(&rc_gravity_equivalence, INFINITY, 33, 1e-9);
}

static void test_newtonian(void)
{
    check(&rc_gravity_newtonian, 1.0, 41, 1e-7);
    check(&rc_gravity_newtonian, 3.0, 42, 1e-7);
    check(&rc_gravity_newtonian, INFINITY, 43, 1e-7);
}

/* Nearly comoving pairs (issue 41, defect 1): b's u = p/m within 1e-12..1e-3 of a's and a
 * gap of 1e-12..1e-4 of the contact distance, the pairs a gas leaves after its collisions.
 * Each query must end (RC_OK or RC_MISS, never RC_ENOCONVERGE) and agree with brute force:
 * the contact's time within 1e-7 plus the gap's 1e-9 over the closing speed there (a slow
 * approach leaves the time that ill-conditioned), its gap within 1e-9. */
static void check_near(const rc_gravity_coupling *cp, double c, uint64_t seed)
{
    rc_test_rng r = {seed};
    const double tmax = 3.0, pm = isinf(c) ? 1.5 : 0.9 * c, vs = isinf(c) ? 1.0 : c;
    long hits = 0, misses = 0;
    for (int i = 0; i < 300; i++) {
        rc_gravity f = {rc_test_range(&r, 0.3, 2.0), i % 3, 0.0};
        rc_inv_c2(c, &f.inv_c2);
        rc_toi_ball a, b;
        rc_vec3 x, p;
        grav_random_ball(&r, f.axis, 2.0, pm, &a.m, &x, &p);
        a.x = x, a.p = p, a.r = rc_test_range(&r, 0.05, 0.3);
        grav_random_ball(&r, f.axis, 2.0, pm, &b.m, &x, &p);
        b.r = rc_test_range(&r, 0.05, 0.3);
        const double d = a.r + b.r;
        const rc_vec3 n = grav_cube(&r, 1.0);
        const double gap = d * pow(10.0, rc_test_range(&r, -12.0, -4.0));
        b.x = rc_v3_add(a.x, rc_v3_scale((d + gap) / rc_v3_norm(n), n));
        if (rc_v3_get(b.x, f.axis) < 0.01)
            rc_v3_set(&b.x, f.axis, rc_v3_get(b.x, f.axis) + 2.0 * d + 0.01);
        const rc_vec3 du = rc_v3_scale(vs * pow(10.0, rc_test_range(&r, -12.0, -3.0)),
                                       grav_cube(&r, 1.0));
        b.p = rc_v3_scale(b.m, rc_v3_add(rc_v3_scale(1.0 / a.m, a.p), du));
        if (gap_at(cp, &f, &a, &b, 0.0) <= 0.0)
            continue;
        double t = -1.0;
        const int st = cp->pair_time(&f, &a, &b, tmax, &t);
        ENSURE_MSG(st == RC_OK || st == RC_MISS, "%s c %g near pair %d: status %d (%s)",
                   cp->name, c, i, st, rc_strerror(st));
        const double tb = brute(cp, &f, &a, &b, tmax);
        if (tb > 0.0) {
            hits++;
            ENSURE_MSG(st == RC_OK, "%s c %g near pair %d: brute force touches at %.17g, got %d",
                       cp->name, c, i, tb, st);
            if (st == RC_OK) {
                const double h = 1e-6 * (1.0 + tb);
                const double close = fmax((gap_at(cp, &f, &a, &b, fmax(tb - h, 0.0)) -
                                           gap_at(cp, &f, &a, &b, tb)) / h, DBL_MIN);
                ENSURE_CLOSE(t, tb, 1e-7 + 1e-9 * d / (close * (1.0 + tb)), 1.0 + tb);
                ENSURE_CLOSE(gap_at(cp, &f, &a, &b, t), 0.0, 1e-9, d);
            }
        } else {
            misses++;
            ENSURE_MSG(st == RC_MISS, "%s c %g near pair %d: no contact by %g, got t = %.17g",
                       cp->name, c, i, tmax, t);
        }
    }
    printf("  %s c %g near-comoving: %ld contacts, %ld misses\n", cp->name, c, hits, misses);
    ENSURE(hits > 20 && misses > 20);
}

static void test_near_comoving(void)
{
    const double cs[4] = {1.0, 2.0, 3.0, INFINITY};
    for (int j = 0; j < 4; j++) {
        check_near(&rc_gravity_newtonian, cs[j], 61 + (uint64_t)j);
        check_near(&rc_gravity_equivalence, cs[j], 71 + (uint64_t)j);
    }
}

/* classically both balls fall alike: |dx + dv t| = d, solved here */
static void test_classical_quadratic(void)
{
    rc_test_rng r = {51};
    long n = 0;
    for (int i = 0; i < 2000; i++) {
        rc_gravity f = {rc_test_range(&r, 0.3, 2.0), i % 3, 0.0};
        rc_toi_ball a, b;
        random_pair(&r, f.axis, INFINITY, &a, &b);
        if (rc_v3_norm(rc_v3_sub(a.x, b.x)) <= a.r + b.r)
            continue;
        const rc_vec3 dx = rc_v3_sub(b.x, a.x);
        const rc_vec3 dv = rc_v3_sub(rc_v3_scale(1 / b.m, b.p), rc_v3_scale(1 / a.m, a.p));
        const double d = a.r + b.r, A = rc_v3_norm2(dv), B = rc_v3_dot(dx, dv);
        const double C = rc_v3_norm2(dx) - d * d, disc = B * B - A * C;
        const double t = B < 0 && disc > 0 ? C / (-B + sqrt(disc)) : -1.0;
        for (int e = 0; e < 2; e++) {
            const rc_gravity_coupling *cp = e ? &rc_gravity_equivalence : &rc_gravity_newtonian;
            double tc;
            const int st = cp->pair_time(&f, &a, &b, 50.0, &tc);
            if (t > 0 && t < 50) {
                n++;
                ENSURE(st == RC_OK);
                ENSURE_CLOSE(tc, t, e ? 1e-12 : 1e-8, 1 + t);
            } else
                ENSURE(st == RC_MISS);
        }
    }
    ENSURE(n > 300);
}

static void test_bad_inputs(void)
{
    const rc_gravity f = {1.0, 2, 1.0};
    rc_toi_ball a = {rc_v3(0, 0, 1), 0.1, 1.0, rc_v3(0.1, 0, 0)}, b = a;
    b.x = rc_v3(0.5, 0, 1);
    double t;
    for (int e = 0; e < 2; e++) {
        const rc_gravity_coupling *cp = e ? &rc_gravity_equivalence : &rc_gravity_newtonian;
        rc_toi_ball z = b;
        z.r = 0;
        ENSURE(cp->pair_time(&f, &a, &z, 1, &t) == RC_ERADIUS);
        z = b, z.m = -1;
        ENSURE(cp->pair_time(&f, &a, &z, 1, &t) == RC_EMASS);
        z = b, z.p.x = NAN;
        ENSURE(cp->pair_time(&f, &a, &z, 1, &t) == RC_ENONFINITE);
        ENSURE(cp->pair_time(&f, &a, &b, -1, &t) == RC_EINVAL);
        ENSURE(cp->pair_time(&f, &a, &b, 1, NULL) == RC_EINVAL);
        z = b, z.x = rc_v3(0.1, 0, 1); /* overlapping */
        ENSURE(cp->pair_time(&f, &a, &z, 1, &t) == RC_EOVERLAP);
        z = b, z.x = rc_v3(0.2, 0, 1), z.p = rc_v3(-0.3, 0, 0); /* touching, approaching */
        ENSURE(cp->pair_time(&f, &a, &z, 1, &t) == RC_OK && t == 0.0);
    }
    ENSURE(rc_gravity_newtonian.pair_time(&f, &a, &b, INFINITY, &t) == RC_EINVAL);
}

int main(void)
{
    gsl_set_error_handler_off();
    RUN_TEST(test_equivalence);
    RUN_TEST(test_newtonian);
    RUN_TEST(test_near_comoving);
    RUN_TEST(test_classical_quadratic);
    RUN_TEST(test_bad_inputs);
    RC_TEST_MAIN_END();
}
