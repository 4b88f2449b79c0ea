/* test_gravity_events — each coupling's plane crossing times (papers/gravity.md section 3:
 * floor, ceiling, planes across the field) against brute force: the path sampled densely
 * (by the drift that test_gravity_drift holds against rk8pd) and the first sign change
 * bisected. A crossing the brute force finds must be the one returned; where it finds
 * none, none may be returned before the end of the scan. */
#include "gravity_util.h"

enum { SAMPLES = 3000 };

/* coordinate k of the ball after t, by the drift, minus X */
typedef struct plane_q {
    const rc_gravity_coupling *cp;
    const rc_gravity *f;
    double m;
    rc_vec3 x, p;
    int k;
    double X;
} plane_q;

static double coord_minus(double t, void *ctx)
{
    const plane_q *q = ctx;
    rc_vec3 x = q->x, p = q->p;
    q->cp->drift(q->f, q->m, &x, &p, t);
    return rc_v3_get(x, q->k) - q->X;
}

static double coord_at(const rc_gravity_coupling *cp, const rc_gravity *f, double m,
                       rc_vec3 x, rc_vec3 p, int k, double t)
{
    plane_q q = {cp, f, m, x, p, k, 0.0};
    return coord_minus(t, &q);
}

static double brute(const rc_gravity_coupling *cp, const rc_gravity *f, double m, rc_vec3 x,
                    rc_vec3 p, int k, double X, double tmax)
{
    plane_q q = {cp, f, m, x, p, k, X};
    return grav_first_change(coord_minus, &q, tmax, SAMPLES);
}

static void check_planes(const rc_gravity_coupling *cp, double c, uint64_t seed)
{
    rc_test_rng r = {seed};
    const double tmax = 6.0;
    long found = 0, missed = 0;
    for (int i = 0; i < 600; i++) {
        rc_gravity f = {rc_test_range(&r, 0.3, 2.0), i % 3, 0.0};
        rc_inv_c2(c, &f.inv_c2);
        double m;
        rc_vec3 x, p;
        grav_random_ball(&r, f.axis, 2.0, 1.5, &m, &x, &p);
        int k;
        double X;
        switch (i % 4) {
        case 0: k = f.axis; X = 0.0; break;                                     /* floor */
        case 1: k = f.axis; X = rc_v3_get(x, k) + rc_test_range(&r, 0.01, 1.0); break; /* ceiling */
        case 2: k = (f.axis + 1) % 3; X = rc_v3_get(x, k) + rc_test_range(&r, -2, 2); break;
        default: k = (f.axis + 2) % 3; X = rc_v3_get(x, k) + rc_test_range(&r, -2, 2); break;
        }
        double t = -1.0;
        const int st = cp->plane_time(&f, m, x, p, k, X, &t);
        ENSURE(st == RC_OK || st == RC_MISS);
        const double tb = brute(cp, &f, m, x, p, k, X, tmax);
        if (tb > 0.0) {
            found++;
            ENSURE_MSG(st == RC_OK, "%s c %g case %d: brute force crosses at %.17g, got %d",
                       cp->name, c, i % 4, tb, st);
            if (st == RC_OK)
                ENSURE_CLOSE(t, tb, 1e-9, 1.0 + tb);
            /* and the ball is on the plane then */
            if (st == RC_OK)
                ENSURE_CLOSE(coord_at(cp, &f, m, x, p, k, t), X, 1e-10, 1.0 + fabs(X));
        } else {
            missed++;
            ENSURE_MSG(st == RC_MISS || t > tmax * (1 - 1e-9),
                       "%s c %g case %d: no crossing before %g, got t = %.17g", cp->name, c,
                       i % 4, tmax, t);
        }
    }
    /* both kinds of answer occur, or the test proves little */
    ENSURE_MSG(found > 100 && missed > 20, "%s c %g: %ld crossings, %ld misses", cp->name, c,
               found, missed);
}

static void test_newtonian(void)
{
    check_planes(&rc_gravity_newtonian, 1.0, 11);
    check_planes(&rc_gravity_newtonian, 3.0, 12);
    check_planes(&rc_gravity_newtonian, INFINITY, 13);
}

static void test_equivalence(void)
{
    check_planes(&rc_gravity_equivalence, 1.0, 21);
    check_planes(&rc_gravity_equivalence, 3.0, 22);
    check_planes(&rc_gravity_equivalence, INFINITY, 23);
}

/* A ball dropped from rest at height h: the floor time is sqrt(2h/g) classically; the
 * newtonian one follows from energy, c^2 (M - m) = m g h, p = m g t (hyperbolic motion:
 * t = sqrt((1 + g h/c^2)^2 - 1) c/g); the equivalence one from the straight line that
 * meets the floor's hyperbola, (h + L)^2 = L^2 + c^2 t'^2 ... whose box time is
 * (c/g) atanh(c t'/(h + L)). Independent closed forms, written out here. */
static void test_drop_from_rest(void)
{
    const double g = 1.3, h = 0.7;
    for (int ic = 0; ic < 3; ic++) {
        const double c = ic == 0 ? 1.0 : ic == 1 ? 2.5 : INFINITY;
        rc_gravity f = {g, 2, 0.0};
        rc_inv_c2(c, &f.inv_c2);
        const rc_vec3 x = rc_v3(0, 0, h), p = rc_v3(0, 0, 0);
        double tn, te;
        ENSURE(rc_gravity_newtonian.plane_time(&f, 1.0, x, p, 2, 0.0, &tn) == RC_OK);
        ENSURE(rc_gravity_equivalence.plane_time(&f, 1.0, x, p, 2, 0.0, &te) == RC_OK);
        if (isinf(c)) {
            ENSURE_REL(tn, sqrt(2 * h / g), 1e-15);
            ENSURE_REL(te, sqrt(2 * h / g), 1e-15);
        } else {
            const double L = c * c / g, a = 1 + g * h / (c * c);
            ENSURE_REL(tn, sqrt(a * a - 1) * c / g, 1e-14);
            /* the ball rests at z = h in the frame comoving at tau = 0: z(t) = h; the
             * floor z + L = sqrt(L^2 + c^2 t^2) reaches it at c t = sqrt((h+L)^2 - L^2) */
            const double ct = sqrt((h + L) * (h + L) - L * L);
            ENSURE_REL(te, (c / g) * atanh(ct / (h + L)), 1e-14);
        }
    }
}

int main(void)
{
    gsl_set_error_handler_off();
    RUN_TEST(test_drop_from_rest);
    RUN_TEST(test_newtonian);
    RUN_TEST(test_equivalence);
    RC_TEST_MAIN_END();
}
