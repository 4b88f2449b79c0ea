/* test_soft_group_frame.c — papers/simultaneous-contacts.md's three-ball group (ball 0,
 * m = 1 at 0.9, onto m = 1 at +30 deg and m = 2 at -45 deg, radii 0.5, both contacts at
 * table time 0) at c = 3 under the soft model with its potential acting in two frames:
 * the group's zero-momentum frame (rc_soft_collide's own integration frame) and the table
 * frame (the same run with a far, heavy bystander carrying minus the group's momentum, so
 * that the ZMF of all the balls is the table frame; it touches nothing). The stiff limit
 * supports the `sequential` rule only for the first: in the table frame, where the two
 * contacts start at one instant, it lands near `simultaneous`. */
#include <math.h>

#include "rc_test.h"
#include "three_group.h"
#include "relcol/relcol.h"

#define C_LIGHT 3.0

static void three(rc_particle P[3], rc_vec3 x[3], rc_contact C[2], double back)
{
    ENSURE(rc_three_group(C_LIGHT, back, P, x, C) == RC_OK);
}

static rc_vec3 rule(int groups)
{
    rc_particle P[3];
    rc_vec3 x[3];
    rc_contact C[2];
    three(P, x, C, 0.0);
    rc_collision_params prm = rc_collision_params_default();
    prm.c = C_LIGHT;
    prm.groups = groups;
    ENSURE(rc_contacts_solve(&prm, 3, P, 2, C, NULL) == RC_OK);
    return rc_velocity(P[0].m, P[0].p, rc_inv_c2_of(C_LIGHT));
}

/* ball 0's final velocity; table = 1: the potential at table-frame simultaneity */
static rc_vec3 soft(double kappa, int table)
{
    rc_particle P[4];
    rc_vec3 x[4];
    rc_contact C[2];
    three(P, x, C, 0.05);
    /* the bystander: rest mass 1e4 (speed ~1e-4 c), 1e3 radii away */
    P[3] = (rc_particle){1e4, rc_v3_scale(-1.0, P[0].p)};
    x[3] = rc_v3(0.0, 1e3, 0.0);
    const double r[4] = {0.5, 0.5, 0.5, 0.5};
    rc_soft_params sp = rc_soft_params_default();
    sp.c = C_LIGHT;
    sp.stiffness = kappa;
    rc_soft_result res;
    const int st = rc_soft_collide(&rc_soft_cvode_bdf, &sp, table ? 4 : 3, P, x, r, NULL, &res);
    ENSURE_MSG(st == RC_OK && res.finished == 1 && res.n_contacts == 2,
               "kappa %g table %d: status %d, finished %d, contacts %d", kappa, table, st,
               res.finished, res.n_contacts);
    return rc_velocity(P[0].m, P[0].p, rc_inv_c2_of(C_LIGHT));
}

static double dist(rc_vec3 a, rc_vec3 b) { return rc_v3_norm(rc_v3_sub(a, b)); }

static void test_frame_of_the_potential(void)
{
    const rc_vec3 sim = rule(RC_GROUPS_SIMULTANEOUS), seq = rule(RC_GROUPS_SEQUENTIAL);
    const double kap[2] = {1e9, 1e11};
    rc_vec3 z[2], t[2];
    for (int i = 0; i < 2; i++) {
        z[i] = soft(kap[i], 0);
        t[i] = soft(kap[i], 1);
        printf("  kappa %.0e: group ZMF (%.4f, %.4f): %.3g from sequential, %.3g from "
               "simultaneous; table frame (%.4f, %.4f): %.3g from sequential, %.3g from "
               "simultaneous\n", kap[i], z[i].x, z[i].y, dist(z[i], seq), dist(z[i], sim),
               t[i].x, t[i].y, dist(t[i], seq), dist(t[i], sim));
    }
    printf("  sequential (%.4f, %.4f), simultaneous (%.4f, %.4f), %.3g apart\n", seq.x, seq.y,
           sim.x, sim.y, dist(seq, sim));
    /* converged in kappa: a hundredfold stiffer moves each limit by well under the gap
     * between the rules */
    ENSURE_MSG(dist(t[0], t[1]) < 0.05 * dist(seq, sim), "table: %.3g", dist(t[0], t[1]));
    ENSURE_MSG(dist(z[0], z[1]) < 0.05 * dist(seq, sim), "zmf: %.3g", dist(z[0], z[1]));
    /* the group's ZMF: nearer sequential; the table frame: nearer simultaneous, and far
     * from sequential */
    ENSURE(dist(z[1], seq) < dist(z[1], sim));
    ENSURE(dist(t[1], sim) < 0.25 * dist(t[1], seq));
}

int main(void)
{
    RUN_TEST(test_frame_of_the_potential);
    RC_TEST_MAIN_END();
}
