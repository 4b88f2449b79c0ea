/* test_law_published.c — textbook values at c = 1 (sticking balls, a ball hitting one at
 * rest, the elastic 1-on-2 collision) and the contract of the law API: rc_collide's
 * validation, rc_collide_batch, rc_law_find, rc_strerror, the defaults. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "law_util.h"

/* The published values are closed forms of a few operations: the library's ~10 roundings
 * give <= 16 ulp; speeds that are exactly 0 are checked against the input scale 1. */
#define TOL_PUB (16 * DBL_EPSILON)

static void collide_1d(const rc_law *law, double eps, double m0, double v0, double m1,
                       double v1, double *w0, double *w1, double *mo0, double *mo1)
{
    rc_particle a = {m0, {0, 0, 0}}, b = {m1, {0, 0, 0}};
    ENSURE(rc_momentum_from_velocity(m0, rc_v3(v0, 0, 0), 1.0, &a.p) == RC_OK);
    ENSURE(rc_momentum_from_velocity(m1, rc_v3(v1, 0, 0), 1.0, &b.p) == RC_OK);
    rc_collision_params prm = rc_collision_params_default();
    prm.c = 1.0; /* c = 1 */
    prm.eps = eps;
    ENSURE(rc_collide(law, &prm, &a, &b, rc_v3(1, 0, 0)) == RC_OK);
    *w0 = rc_velocity(a.m, a.p, 1.0).x;
    *w1 = rc_velocity(b.m, b.p, 1.0).x;
    *mo0 = a.m;
    *mo1 = b.m;
}

/* Each published case through both laws (in 1-D they coincide). */
static void test_published(void)
{
    for (size_t l = 0; rc_laws[l]; l++) {
        const rc_law *law = rc_laws[l];
        double w0, w1, m0, m1;
        /* balls at +-0.6, eps = 0: they stick at rest; each takes half of the energy
         * 2 gamma(0.6) = 2.5 as rest mass: 1.25 */
        collide_1d(law, 0.0, 1.0, 0.6, 1.0, -0.6, &w0, &w1, &m0, &m1);
        ENSURE_CLOSE(w0, 0.0, TOL_PUB, 1.0);
        ENSURE_CLOSE(w1, 0.0, TOL_PUB, 1.0);
        ENSURE_REL(m0, 1.25, TOL_PUB);
        ENSURE_REL(m1, 1.25, TOL_PUB);
        /* 0.8 on a ball at rest, eps = 0: E = 5/3 + 1 = 8/3, p = 4/3, both at p/E = 0.5;
         * invariant mass sqrt(E^2 - p^2) = 4/sqrt(3), each 2/sqrt(3) */
        collide_1d(law, 0.0, 1.0, 0.8, 1.0, 0.0, &w0, &w1, &m0, &m1);
        ENSURE_REL(w0, 0.5, TOL_PUB);
        ENSURE_REL(w1, 0.5, TOL_PUB);
        ENSURE_REL(m0, 2.0 / sqrt(3.0), TOL_PUB);
        ENSURE_REL(m1, 2.0 / sqrt(3.0), TOL_PUB);
        /* elastic, m = 1 at 0.6 on m = 2 at rest: -9/41 and 39/89, rest masses kept */
        collide_1d(law, 1.0, 1.0, 0.6, 2.0, 0.0, &w0, &w1, &m0, &m1);
        ENSURE_REL(w0, -9.0 / 41.0, TOL_PUB);
        ENSURE_REL(w1, 39.0 / 89.0, TOL_PUB);
        ENSURE(m0 == 1.0 && m1 == 2.0);
        /* the same collision classically (c = inf): (m0 - m1)/(m0 + m1) v = -0.2 and
         * 2 m0/(m0 + m1) v = 0.4 */
        rc_particle a = {1.0, {0.6, 0, 0}}, b = {2.0, {0, 0, 0}};
        rc_collision_params prm = rc_collision_params_default();
        ENSURE(rc_collide(law, &prm, &a, &b, rc_v3(1, 0, 0)) == RC_OK);
        ENSURE_REL(a.p.x / a.m, -0.2, TOL_PUB);
        ENSURE_REL(b.p.x / b.m, 0.4, TOL_PUB);
    }
}

/* Wall at c = 1: a ball at 0.6 with eps_w = 0 stops and its rest mass takes the kinetic
 * energy: m' = gamma m = 1.25; with eps_w = 1 it returns at -0.6, mass kept. */
static void test_published_wall(void)
{
    rc_particle a = {1.0, {0.75, 0, 0}}; /* p = gamma m v = 1.25 * 0.6 */
    ENSURE(rc_collide_wall(1.0, 0.0, &a, rc_v3(1, 0, 0)) == RC_OK);
    ENSURE_CLOSE(a.p.x, 0.0, TOL_PUB, 1.0);
    ENSURE_REL(a.m, 1.25, TOL_PUB);
    rc_particle b = {1.0, {0.75, 0, 0}};
    ENSURE(rc_collide_wall(1.0, 1.0, &b, rc_v3(1, 0, 0)) == RC_OK);
    ENSURE_REL(rc_velocity(b.m, b.p, 1.0).x, -0.6, TOL_PUB);
    ENSURE(b.m == 1.0);
}

/* rc_collide: every invalid input is refused with its code, leaving the balls untouched;
 * separating or tangent balls are RC_NO_COLLISION, untouched. */
static void test_validation(void)
{
    const rc_particle a0 = {1.0, {0.5, 0.1, 0}}, b0 = {2.0, {-0.3, 0, 0.2}};
    const rc_vec3 n0 = rc_v3(1, 0, 0);
    for (size_t l = 0; rc_laws[l]; l++) {
        const rc_law *law = rc_laws[l];
        rc_collision_params p0 = rc_collision_params_default();
        p0.c = 2.0;
        p0.eps = 0.5;
        struct {
            const char *what;
            rc_particle a, b;
            rc_collision_params p;
            rc_vec3 n;
            int expect;
        } cases[32];
        int nc = 0;
#define CASE(WHAT, EXPECT, ...)                                                            \
    do {                                                                                  \
        cases[nc].what = WHAT;                                                            \
        cases[nc].a = a0;                                                                 \
        cases[nc].b = b0;                                                                 \
        cases[nc].p = p0;                                                                 \
        cases[nc].n = n0;                                                                 \
        {                                                                                 \
            rc_particle *A = &cases[nc].a, *B = &cases[nc].b;                             \
            rc_collision_params *P = &cases[nc].p;                                        \
            rc_vec3 *N = &cases[nc].n;                                                    \
            (void)A, (void)B, (void)P, (void)N;                                           \
            __VA_ARGS__;                                                                  \
        }                                                                                 \
        cases[nc++].expect = EXPECT;                                                      \
    } while (0)
        CASE("m NaN", RC_ENONFINITE, A->m = NAN);
        CASE("m inf", RC_ENONFINITE, B->m = INFINITY);
        CASE("p NaN", RC_ENONFINITE, A->p.y = NAN);
        CASE("p inf", RC_ENONFINITE, B->p.z = -INFINITY);
        CASE("m = 0", RC_EMASS, A->m = 0.0);
        CASE("m < 0", RC_EMASS, B->m = -1.0);
        CASE("c NaN", RC_ESPEEDOFLIGHT, P->c = NAN);
        CASE("c < 0", RC_ESPEEDOFLIGHT, P->c = -1.0);
        CASE("c = 0", RC_ESPEEDOFLIGHT, P->c = 0.0);
        CASE("eps < 0", RC_ERESTITUTION, P->eps = -1e-300);
        CASE("eps > 1", RC_ERESTITUTION, P->eps = 1.0 + DBL_EPSILON);
        CASE("eps NaN", RC_ERESTITUTION, P->eps = NAN);
        CASE("alpha = pi/2", RC_EINVAL, P->alpha = M_PI / 2);
        CASE("alpha inf", RC_EINVAL, P->alpha = -INFINITY);
        CASE("azimuth NaN", RC_EINVAL, P->alpha = 0.3; P->azimuth = NAN);
        CASE("n NaN", RC_ENONFINITE, N->x = NAN);
        CASE("n inf", RC_ENONFINITE, N->y = INFINITY);
        CASE("n zero", RC_EZERONORMAL, *N = rc_v3(0, 0, 0));
        CASE("separating", RC_NO_COLLISION, *N = rc_v3(-1, 0, 0));
        CASE("separating 3-D", RC_NO_COLLISION, *N = rc_v3(-1, 0.5, -0.2));
        if (law == &rc_law_zmf) /* equal M, equal p.n: a0 = 0 exactly, tangent */
            CASE("tangent", RC_NO_COLLISION, A->m = B->m = 1.5; A->p = rc_v3(0.3, 0.4, 0);
                 B->p = rc_v3(0.3, -0.4, 0));
#undef CASE
        for (int i = 0; i < nc; i++) {
            rc_particle a = cases[i].a, b = cases[i].b;
            int st = rc_collide(law, &cases[i].p, &a, &b, cases[i].n);
            ENSURE_MSG(st == cases[i].expect, "%s, %s: got %d (%s), expected %d", law->name,
                       cases[i].what, st, rc_strerror(st), cases[i].expect);
            ENSURE_MSG(memcmp(&a, &cases[i].a, sizeof a) == 0 &&
                           memcmp(&b, &cases[i].b, sizeof b) == 0,
                       "%s, %s: balls changed", law->name, cases[i].what);
        }
        rc_particle a = a0, b = b0;
        ENSURE(rc_collide(NULL, &p0, &a, &b, n0) == RC_EINVAL);
        ENSURE(rc_collide(law, NULL, &a, &b, n0) == RC_EINVAL);
        ENSURE(rc_collide(law, &p0, NULL, &b, n0) == RC_EINVAL);
        ENSURE(rc_collide(law, &p0, &a, NULL, n0) == RC_EINVAL);
        /* eps exactly 0 and 1 and alpha just inside (-pi/2, pi/2) are valid */
        rc_collision_params p1 = p0;
        p1.eps = 0.0;
        ENSURE(rc_collide(law, &p1, &a, &b, n0) == RC_OK);
        a = a0, b = b0;
        p1.eps = 1.0;
        p1.alpha = nextafter(M_PI / 2, 0.0);
        ENSURE(rc_collide(law, &p1, &a, &b, n0) == RC_OK);
    }
}

/* The normal need not be unit: rc_collide normalises it (same outcome to an ulp or so). */
/* The wall law checks its input like rc_collide: every bad value gets its own code, the
 * ball is left untouched, and a non-unit normal is normalised. */
static void test_wall_validation(void)
{
    const rc_particle good = {1.0, {0.5, 0.1, 0}};
    rc_particle a = good;
    a.p.x = NAN;
    ENSURE(rc_collide_wall(1.0, 1.0, &a, rc_v3(1, 0, 0)) == RC_ENONFINITE);
    a = good;
    a.m = 0.0;
    ENSURE(rc_collide_wall(1.0, 1.0, &a, rc_v3(1, 0, 0)) == RC_EMASS);
    a = good;
    ENSURE(rc_collide_wall(-1.0, 1.0, &a, rc_v3(1, 0, 0)) == RC_ESPEEDOFLIGHT);
    ENSURE(rc_collide_wall(NAN, 1.0, &a, rc_v3(1, 0, 0)) == RC_ESPEEDOFLIGHT);
    ENSURE(rc_collide_wall(1.0, 1.5, &a, rc_v3(1, 0, 0)) == RC_ERESTITUTION);
    ENSURE(rc_collide_wall(1.0, 1.0, &a, rc_v3(0, 0, 0)) == RC_EZERONORMAL);
    ENSURE(rc_collide_wall(1.0, 1.0, &a, rc_v3(INFINITY, 0, 0)) == RC_ENONFINITE);
    ENSURE(rc_collide_wall(1.0, 1.0, NULL, rc_v3(1, 0, 0)) == RC_EINVAL);
    ENSURE(a.m == good.m && a.p.x == good.p.x && a.p.y == good.p.y);
    /* normal of length 2 along x: same as the unit normal */
    rc_particle b = good, c = good;
    ENSURE(rc_collide_wall(1.0, 0.5, &b, rc_v3(2, 0, 0)) == RC_OK);
    ENSURE(rc_collide_wall(1.0, 0.5, &c, rc_v3(1, 0, 0)) == RC_OK);
    ENSURE(b.p.x == c.p.x && b.m == c.m);
    ENSURE_REL(b.p.x, -0.25, 1e-15);
}

static void test_normal_normalised(void)
{
    rc_test_rng r = {301};
    for (int i = 0; i < 1000; i++) {
        rc_particle a = {lu_logu(&r, 0.1, 10), lu_vec(&r, 3, 1.0)};
        rc_particle b = {lu_logu(&r, 0.1, 10), lu_vec(&r, 3, 1.0)};
        rc_vec3 n = lu_unit(&r, 3);
        rc_collision_params prm = rc_collision_params_default();
        prm.c = rc_test_c_of(0.1);
        prm.eps = rc_test_uniform(&r);
        rc_particle a1 = a, b1 = b, a2 = a, b2 = b;
        int s1 = rc_collide(&rc_law_zmf, &prm, &a1, &b1, n);
        rc_vec3 n2 = rc_v3_scale(lu_logu(&r, 1e-100, 1e100), n);
        int s2 = rc_collide(&rc_law_zmf, &prm, &a2, &b2, n2);
        ENSURE(s1 == s2);
        double sc = rc_v3_norm(a.p) + rc_v3_norm(b.p);
        ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(a1.p, a2.p)), 0.0, 8 * DBL_EPSILON, sc);
        ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(b1.p, b2.p)), 0.0, 8 * DBL_EPSILON, sc);
        ENSURE_REL(a1.m, a2.m, 4 * DBL_EPSILON);
    }
}

/* rc_collide_batch = rc_collide pair by pair (bit for bit for unit normals), the status
 * array filled, the count of collisions returned; status may be NULL. */
static void test_batch(void)
{
    enum { N = 1000 };
    static rc_particle a[N], b[N], a1[N], b1[N], a2[N], b2[N];
    static rc_vec3 n[N];
    static int st[N];
    rc_test_rng r = {302};
    for (size_t l = 0; rc_laws[l]; l++) {
        rc_collision_params prm = rc_collision_params_default();
        prm.c = rc_test_c_of(0.3);
        prm.eps = 0.7;
        for (int i = 0; i < N; i++) {
            a[i] = (rc_particle){lu_logu(&r, 0.1, 10), lu_vec(&r, 3, 1.0)};
            b[i] = (rc_particle){lu_logu(&r, 0.1, 10), lu_vec(&r, 3, 1.0)};
            n[i] = lu_unit(&r, 3);
        }
        memcpy(a1, a, sizeof a);
        memcpy(b1, b, sizeof b);
        memcpy(a2, a, sizeof a);
        memcpy(b2, b, sizeof b);
        size_t hits = rc_collide_batch(rc_laws[l], &prm, N, a1, b1, n, st), count = 0;
        ENSURE(rc_collide_batch(rc_laws[l], &prm, N, a2, b2, n, NULL) == hits);
        for (int i = 0; i < N; i++) {
            rc_particle x = a[i], y = b[i];
            int s = rc_laws[l]->collide(&prm, &x, &y, n[i]);
            ENSURE(s == st[i]);
            count += (s == RC_OK);
            ENSURE(memcmp(&x, &a1[i], sizeof x) == 0 && memcmp(&y, &b1[i], sizeof y) == 0);
            ENSURE(memcmp(&a1[i], &a2[i], sizeof x) == 0 && memcmp(&b1[i], &b2[i], sizeof y) == 0);
            if (s != RC_OK)
                ENSURE(memcmp(&a[i], &a1[i], sizeof x) == 0 &&
                       memcmp(&b[i], &b1[i], sizeof y) == 0);
        }
        ENSURE(count == hits);
        ENSURE(hits > N / 4 && hits < N); /* random pairs: some approach, some separate */
        ENSURE(rc_collide_batch(rc_laws[l], &prm, 0, a1, b1, n, st) == 0);
    }
}

static void test_law_table(void)
{
    ENSURE(rc_law_find("zmf") == &rc_law_zmf);
    ENSURE(rc_law_find("cm-isotropic") == &rc_law_cm_isotropic);
    ENSURE(rc_law_find("ZMF") == NULL);
    ENSURE(rc_law_find("zmf ") == NULL);
    ENSURE(rc_law_find("") == NULL);
    ENSURE(rc_law_find("wall") == NULL);
    ENSURE(rc_law_find(NULL) == NULL);
    size_t nl = 0;
    for (size_t l = 0; rc_laws[l]; l++, nl++) {
        ENSURE(rc_laws[l]->name && rc_laws[l]->name[0] != '\0');
        ENSURE(rc_laws[l]->summary && rc_laws[l]->summary[0] != '\0');
        ENSURE(rc_laws[l]->collide != NULL);
        ENSURE(rc_law_find(rc_laws[l]->name) == rc_laws[l]); /* names are unique */
    }
    ENSURE(nl >= 2);
    rc_collision_params p = rc_collision_params_default();
    ENSURE(isinf(p.c) && p.eps == 1.0 && isnan(p.alpha));
}

static void test_strerror(void)
{
    const int codes[] = {RC_OK, RC_NO_COLLISION, RC_MISS, RC_EINVAL, RC_ENONFINITE, RC_EMASS,
                         RC_ESPEED, RC_ERESTITUTION, RC_ESPEEDOFLIGHT, RC_EZERONORMAL,
                         RC_EOVERLAP, RC_ENOMEM, RC_ENOCONVERGE, RC_EUNKNOWN, RC_ERADIUS,
                         RC_EDIM};
    const size_t nc = sizeof codes / sizeof codes[0];
    const char *unknown = rc_strerror(12345);
    ENSURE(unknown && unknown[0] != '\0');
    ENSURE(rc_strerror(-12345) == unknown || strcmp(rc_strerror(-12345), unknown) == 0);
    for (size_t i = 0; i < nc; i++) {
        const char *s = rc_strerror(codes[i]);
        ENSURE_MSG(s && s[0] != '\0' && strcmp(s, unknown) != 0, "code %d", codes[i]);
        for (size_t j = 0; j < i; j++)
            ENSURE_MSG(strcmp(s, rc_strerror(codes[j])) != 0, "codes %d and %d share text",
                       codes[i], codes[j]);
    }
}

/* Impact-angle draw: 2-D sin(alpha) = 2 u1 - 1, 3-D sin^2(alpha) = u1, azimuth 2 pi u2. */
static void test_impact_angle_draw(void)
{
    double al, az;
    rc_impact_angle_draw(1, 0.3, 0.7, &al, &az);
    ENSURE(al == 0.0 && az == 0.0);
    rc_impact_angle_draw(2, 0.5, 0.7, &al, &az);
    ENSURE(al == 0.0 && az == 0.0);
    rc_impact_angle_draw(2, 0.75, 0.1, &al, &az);
    ENSURE_REL(sin(al), 0.5, 4 * DBL_EPSILON);
    rc_impact_angle_draw(3, 0.25, 0.25, &al, &az);
    ENSURE_REL(sin(al), 0.5, 4 * DBL_EPSILON);
    ENSURE_REL(az, M_PI / 2, 4 * DBL_EPSILON);
    rc_test_rng r = {303};
    for (int i = 0; i < 10000; i++) {
        rc_impact_angle_draw(2 + i % 2, rc_test_uniform(&r), rc_test_uniform(&r), &al, &az);
        ENSURE(fabs(al) <= M_PI / 2 && az >= 0.0 && az < 2 * M_PI);
    }
}

int main(void)
{
    RUN_TEST(test_published);
    RUN_TEST(test_published_wall);
    RUN_TEST(test_validation);
    RUN_TEST(test_wall_validation);
    RUN_TEST(test_normal_normalised);
    RUN_TEST(test_batch);
    RUN_TEST(test_law_table);
    RUN_TEST(test_strerror);
    RUN_TEST(test_impact_angle_draw);
    RC_TEST_MAIN_END();
}
