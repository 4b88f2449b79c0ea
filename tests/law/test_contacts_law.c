/* test_contacts_law.c — the group solver's sequential rule runs the law it is given
 * (relcol/contacts.h, rc_contacts_solve_law): a one-contact group gives that law's pair
 * outcome (cm-isotropic, which differs from zmf at eps < 1, and a test-only law), a chain
 * calls the law once per pair collision, and rc_contacts_solve is the zmf law's. */
#include <math.h>
#include <string.h>

#include "rc_test.h"
#include "relcol/relcol.h"

static rc_collision_params params(double c, int rule)
{
    rc_collision_params prm = rc_collision_params_default();
    prm.c = c;
    prm.groups = rule;
    return prm;
}

/* A test-only law: the zmf kernel with each ball's momentum component across n then
 * halved in the pair's table frame (not a physical law: an outcome no other law gives),
 * counting its calls. */
static long odd_calls;
static int odd_collide(const rc_collision_params *prm, rc_particle *a, rc_particle *b, rc_vec3 n)
{
    odd_calls++;
    const int st = rc_law_zmf.collide(prm, a, b, n);
    if (st != RC_OK)
        return st;
    a->p = rc_v3_axpy(rc_v3_scale(0.5, a->p), 0.5 * rc_v3_dot(a->p, n), n);
    b->p = rc_v3_axpy(rc_v3_scale(0.5, b->p), 0.5 * rc_v3_dot(b->p, n), n);
    return RC_OK;
}
static const rc_law law_odd = {.name = "test-odd", .summary = "zmf, then transverse halved",
                               .collide = odd_collide};

static int same_bits(const rc_particle *x, const rc_particle *y, size_t n)
{
    return memcmp(x, y, n * sizeof *x) == 0;
}

static double dist(const rc_particle *x, const rc_particle *y, size_t n)
{
    double d = 0.0;
    for (size_t i = 0; i < n; i++)
        d = fmax(d, rc_v3_norm(rc_v3_sub(x[i].p, y[i].p)) + fabs(x[i].m - y[i].m));
    return d;
}

/* One contact, oblique, inelastic: the sequential rule's outcome is law->collide's. */
static void test_two_balls(const rc_law *law, double c)
{
    const rc_particle in[2] = {{1.0, {0.6, 0.2, -0.1}}, {1.5, {-0.4, 0.1, 0.3}}};
    const rc_vec3 n = rc_v3_scale(1.0 / sqrt(1.0 + 0.09 + 0.01), rc_v3(1.0, 0.3, -0.1));
    const double eps = 0.5;
    const rc_contact con = {0, 1, n, eps, 0.0, {0, 0, 0}};

    rc_collision_params prm = params(c, RC_GROUPS_SEQUENTIAL);
    rc_particle grp[2] = {in[0], in[1]}, pair[2] = {in[0], in[1]}, zmf[2] = {in[0], in[1]};
    double J = NAN;
    ENSURE(rc_contacts_solve_law(law, &prm, 2, grp, 1, &con, &J) == RC_OK);
    rc_collision_params pp = params(c, RC_GROUPS_SIMULTANEOUS);
    pp.eps = eps;
    ENSURE(law->collide(&pp, &pair[0], &pair[1], n) == RC_OK);
    ENSURE(rc_contacts_solve(&prm, 2, zmf, 1, &con, NULL) == RC_OK);
    /* the impulse reported is the momentum ball 1 gained along n (classically; at finite c
     * the rule reports it along the normal's four-vector in the pair's ZMF) */
    if (isinf(c))
        ENSURE(J == rc_v3_dot(grp[1].p, n) - rc_v3_dot(in[1].p, n));
    if (isinf(c)) /* classically the rule runs in the given frame: the kernel's bits */
        ENSURE_MSG(same_bits(grp, pair, 2), "%s: group %.17g %.17g, pair %.17g %.17g",
                   law->name, grp[0].p.x, grp[0].p.y, pair[0].p.x, pair[0].p.y);
    else /* in the pair's ZMF and back: a covariant law's outcome to round-off */
        ENSURE_MSG(dist(grp, pair, 2) < 1e-14, "%s c=%g: %.3g", law->name, c, dist(grp, pair, 2));
    /* and not the zmf law's: a rule that ignored the law would fail here */
    ENSURE_MSG(dist(grp, zmf, 2) > 1e-3, "%s c=%g: %.3g from zmf", law->name, c,
               dist(grp, zmf, 2));
}

/* A head-on chain 0 -> 1 -> 2 with the second contact later in every frame: the
 * sequential rule strikes 0-1, then 1-2, by the law each time. */
static void test_chain_calls(void)
{
    const rc_particle in[3] = {{1.0, {0.5, 0.0, 0.0}}, {1.0, {0.0, 0.0, 0.0}},
                               {1.0, {0.0, 0.0, 0.0}}};
    const rc_contact con[2] = {{0, 1, {1, 0, 0}, 1.0, 0.0, {1, 0, 0}},
                               {1, 2, {1, 0, 0}, 1.0, 1.0, {3, 0, 0}}};
    rc_particle b[3] = {in[0], in[1], in[2]}, z[3] = {in[0], in[1], in[2]};
    const rc_collision_params prm = params(INFINITY, RC_GROUPS_SEQUENTIAL);
    odd_calls = 0;
    ENSURE(rc_contacts_solve_law(&law_odd, &prm, 3, b, 2, con, NULL) == RC_OK);
    ENSURE_MSG(odd_calls == 2, "%ld calls", odd_calls);
    /* head-on, nothing across n: the odd law is zmf here, Newton's cradle (all to ball 2) */
    ENSURE(rc_contacts_solve(&prm, 3, z, 2, con, NULL) == RC_OK);
    ENSURE(same_bits(b, z, 3));
    ENSURE(z[2].p.x == 0.5 && z[0].p.x == 0.0 && z[1].p.x == 0.0);
}

/* rc_contacts_solve is rc_contacts_solve_law with the zmf law, every rule; bad laws */
static void test_zmf_and_errors(void)
{
    const rc_particle in[3] = {{1.0, {0.4, 0.1, 0.0}}, {1.2, {-0.1, 0.0, 0.05}},
                               {0.8, {-0.3, -0.1, 0.0}}};
    const rc_vec3 n0 = rc_v3_scale(1.0 / sqrt(1.01), rc_v3(1.0, 0.1, 0.0));
    const rc_vec3 n1 = rc_v3_scale(1.0 / sqrt(1.04), rc_v3(1.0, -0.2, 0.0));
    const rc_contact con[2] = {{0, 1, n0, 1.0, 0.0, {1, 0, 0}}, {1, 2, n1, 1.0, 0.1, {3, 0, 0}}};
    for (int rule = 0; rule < 3; rule++)
        for (int ic = 0; ic < 2; ic++) {
            const rc_collision_params prm = params(ic ? 3.0 : INFINITY, rule);
            rc_particle a[3] = {in[0], in[1], in[2]}, b[3] = {in[0], in[1], in[2]};
            const int sa = rc_contacts_solve(&prm, 3, a, 2, con, NULL);
            const int sb = rc_contacts_solve_law(&rc_law_zmf, &prm, 3, b, 2, con, NULL);
            ENSURE_MSG(sa == RC_OK && sb == RC_OK, "rule %d c %s: %d %d", rule, ic ? "3" : "inf",
                       sa, sb);
            ENSURE_MSG(same_bits(a, b, 3), "rule %d c %s", rule, ic ? "3" : "inf");
        }
    const rc_collision_params prm = params(INFINITY, RC_GROUPS_SEQUENTIAL);
    rc_particle b[3] = {in[0], in[1], in[2]};
    const rc_law nokernel = {.name = "none", .summary = "no kernel"};
    ENSURE(rc_contacts_solve_law(NULL, &prm, 3, b, 2, con, NULL) == RC_EINVAL);
    ENSURE(rc_contacts_solve_law(&nokernel, &prm, 3, b, 2, con, NULL) == RC_EINVAL);
    ENSURE(same_bits(b, in, 3));
}

static void test_cm_isotropic_classical(void) { test_two_balls(&rc_law_cm_isotropic, INFINITY); }
static void test_cm_isotropic_c3(void) { test_two_balls(&rc_law_cm_isotropic, 3.0); }
static void test_odd_law(void) { test_two_balls(&law_odd, INFINITY); }

int main(void)
{
    RUN_TEST(test_cm_isotropic_classical);
    RUN_TEST(test_cm_isotropic_c3);
    RUN_TEST(test_odd_law);
    RUN_TEST(test_chain_calls);
    RUN_TEST(test_zmf_and_errors);
    RC_TEST_MAIN_END();
}
