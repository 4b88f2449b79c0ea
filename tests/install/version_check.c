/* version_check.c — a program outside the project, built by test_install.sh with
 * pkg-config against an installed relcol: it must compile with the installed headers, link
 * with the installed library, and run a collision through it. Prints the version and the
 * outcome of seed 000's inelastic example (two balls at +-0.6 c stick: rest masses 1.25). */
#include <stdio.h>
#include <string.h>

#include <relcol/relcol.h>

int main(void)
{
    rc_collision_params prm = rc_collision_params_default();
    prm.c = 1.0;
    prm.eps = 0.0;
    rc_particle a = {1.0, {0.75, 0, 0}}, b = {1.0, {-0.75, 0, 0}}; /* p = gamma m v, v = 0.6 */
    int st = rc_collide(rc_law_find("zmf"), &prm, &a, &b, rc_v3(1, 0, 0));
    printf("relcol %s (headers %s): %s, m = %.15g %.15g\n", rc_version(), RELCOL_VERSION,
           rc_strerror(st), a.m, b.m);
    return st == RC_OK && strcmp(rc_version(), RELCOL_VERSION) == 0 ? 0 : 1;
}
