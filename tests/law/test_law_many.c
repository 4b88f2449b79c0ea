/* test_law_many.c — rc_collide_many, the validating batch: every pair gives rc_collide's
 * bits and code, whatever the length of its normal; the first bad pair stops the batch
 * with rc_collide's code and its index, the pairs before it done and the rest untouched;
 * and rc_version() is the version of the headers (RELCOL_VERSION). */
#include <string.h>

#include "law_util.h"

#define N 2000

static int same_particle(const rc_particle *x, const rc_particle *y)
{
    return memcmp(x, y, sizeof *x) == 0;
}

/* rc_collide_many on pairs held as records: split into its columns, run, joined back */
static int many(const rc_law *law, const rc_collision_params *prm, size_t np, rc_particle *a,
                rc_particle *b, const rc_vec3 *n, int *st, size_t *hits, size_t *bad)
{
    static double m0[N], m1[N];
    static rc_vec3 p0[N], p1[N];
    for (size_t i = 0; i < np; i++) {
        m0[i] = a[i].m, p0[i] = a[i].p;
        m1[i] = b[i].m, p1[i] = b[i].p;
    }
    int rc = rc_collide_many(law, prm, np, np ? m0 : NULL, np ? p0 : NULL, np ? m1 : NULL,
                             np ? p1 : NULL, n, st, hits, bad);
    for (size_t i = 0; i < np; i++) {
        a[i] = (rc_particle){m0[i], p0[i]};
        b[i] = (rc_particle){m1[i], p1[i]};
    }
    return rc;
}

static void test_many_equals_single(void)
{
    static rc_particle a[N], b[N], a1[N], b1[N];
    static rc_vec3 n[N];
    static int st[N];
    rc_test_rng r = {77};
    for (int li = 0; rc_laws[li]; li++) {
        for (int ci = 0; ci < 3; ci++) {
            const double inv_c2 = ci == 0 ? 0.0 : ci == 1 ? 1.0 : 4.0;
            rc_collision_params prm = rc_collision_params_default();
            prm.c = rc_test_c_of(inv_c2);
            prm.eps = 0.7;
            for (int i = 0; i < N; i++) {
                const double vmax = inv_c2 > 0 ? 0.95 / sqrt(inv_c2) : 3.0;
                a[i].m = lu_logu(&r, 0.1, 10.0);
                b[i].m = lu_logu(&r, 0.1, 10.0);
                rc_momentum_from_velocity(a[i].m, lu_vec(&r, 3, vmax), inv_c2, &a[i].p);
                rc_momentum_from_velocity(b[i].m, lu_vec(&r, 3, vmax), inv_c2, &b[i].p);
                /* normals of any length and either sense: both outcomes occur */
                n[i] = rc_v3_scale(lu_logu(&r, 1e-3, 1e3), lu_unit(&r, 3));
                if (i % 5 == 0) /* length exactly 1: taken as it is */
                    n[i] = rc_v3(0, i % 2 ? 1.0 : -1.0, 0);
                a1[i] = a[i];
                b1[i] = b[i];
            }
            size_t hits = 0, bad = 99, want = 0;
            int rc = many(rc_laws[li], &prm, N, a, b, n, st, &hits, &bad);
            ENSURE(rc == RC_OK);
            ENSURE(bad == 0);
            int same = 1;
            for (int i = 0; i < N; i++) {
                int s1 = rc_collide(rc_laws[li], &prm, &a1[i], &b1[i], n[i]);
                want += s1 == RC_OK;
                same &= s1 == st[i] && same_particle(&a[i], &a1[i]) && same_particle(&b[i], &b1[i]);
            }
            ENSURE_MSG(same, "law %s, 1/c^2 = %g", rc_laws[li]->name, inv_c2);
            ENSURE(hits == want);
            ENSURE(want > N / 4 && want < 3 * N / 4);
        }
    }
}

static void test_many_stops_at_bad_pair(void)
{
    rc_collision_params prm = rc_collision_params_default();
    prm.c = 1.0;
    rc_particle a[4], b[4], a0[4], b0[4];
    rc_vec3 n[4];
    for (int i = 0; i < 4; i++) {
        /* (normals of length 2 and of length exactly 1, which is used as it is) */
        a[i] = (rc_particle){1.0, {0.5, 0, 0}};
        b[i] = (rc_particle){2.0, {-0.5, 0, 0}};
        n[i] = rc_v3(i == 1 ? 1.0 : 2.0, 0, 0);
    }
    b[2].m = -1.0;
    memcpy(a0, a, sizeof a);
    memcpy(b0, b, sizeof b);
    size_t hits = 9, bad = 9;
    int st[4] = {0};
    ENSURE(many(&rc_law_zmf, &prm, 4, a, b, n, st, &hits, &bad) == RC_EMASS);
    ENSURE(bad == 2 && hits == 2);
    ENSURE(!same_particle(&a[1], &a0[1]) && same_particle(&a[2], &a0[2]) &&
           same_particle(&a[3], &a0[3]) && same_particle(&b[3], &b0[3]));
    b[2].m = 2.0;
    n[3] = rc_v3(0, 0, 0);
    ENSURE(many(&rc_law_zmf, &prm, 4, a, b, n, NULL, NULL, &bad) == RC_EZERONORMAL);
    ENSURE(bad == 3);
    prm.eps = 1.5;
    ENSURE(many(&rc_law_zmf, &prm, 4, a, b, n, NULL, &hits, &bad) == RC_ERESTITUTION);
    ENSURE(hits == 0);
    prm.eps = 1.0;
    ENSURE(many(NULL, &prm, 4, a, b, n, NULL, NULL, NULL) == RC_EINVAL);
    ENSURE(many(&rc_law_zmf, &prm, 0, NULL, NULL, NULL, NULL, &hits, NULL) == RC_OK);
    ENSURE(hits == 0);
}

static void test_version(void)
{
    ENSURE(strcmp(rc_version(), RELCOL_VERSION) == 0);
    char want[64];
    snprintf(want, sizeof want, "%d.%d.%d", RELCOL_VERSION_MAJOR, RELCOL_VERSION_MINOR,
             RELCOL_VERSION_PATCH);
    ENSURE(strcmp(want, RELCOL_VERSION) == 0);
}

int main(void)
{
    RUN_TEST(test_many_equals_single);
    RUN_TEST(test_many_stops_at_bad_pair);
    RUN_TEST(test_version);
    RC_TEST_MAIN_END();
}
