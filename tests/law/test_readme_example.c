/* test_readme_example.c — the library example of README.md, verbatim, with its claims
 * checked, so that the README stays true. */
#include <math.h>

#include "rc_test.h"
#include "relcol/relcol.h"

static void test_readme(void)
{
    rc_collision_params prm = rc_collision_params_default();   /* c = inf, eps = 1 */
    prm.c = 1.0;
    prm.eps = 0.0;
    double k;                                                   /* 1/c^2, for formulas */
    rc_inv_c2(prm.c, &k);
    rc_particle a = {1.0, {0, 0, 0}}, b = {1.0, {0, 0, 0}};    /* rest mass, momentum */
    rc_momentum_from_velocity(a.m, rc_v3(0.6, 0, 0), k, &a.p);
    rc_momentum_from_velocity(b.m, rc_v3(-0.6, 0, 0), k, &b.p);
    int st = rc_collide(rc_law_find("zmf"), &prm, &a, &b, rc_v3(1, 0, 0));
    /* st == RC_OK; both at rest; a.m == b.m == 1.25 (the kinetic energy became rest mass) */
    ENSURE(st == RC_OK);
    ENSURE(a.p.x == 0.0 && b.p.x == 0.0);
    /* 1.25 = gamma(0.6): a few ulps from the sqrt of m^2 + (p/c)^2 */
    ENSURE_REL(a.m, 1.25, 4e-16);
    ENSURE_REL(b.m, 1.25, 4e-16);
}

int main(void)
{
    RUN_TEST(test_readme);
    RC_TEST_MAIN_END();
}
