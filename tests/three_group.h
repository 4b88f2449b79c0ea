/* three_group.h — papers/simultaneous-contacts.md's three-ball group, shared by the group
 * and soft-model tests: ball 0 (m = 1, v = 0.9 along x) onto m = 1 at +30 deg and m = 2 at
 * -45 deg, all radii 0.5, touching at table time 0 (ball 0 moved `back` along -x: moving
 * along x it reaches both at once from any distance back); elastic contacts. */
#ifndef RC_TEST_THREE_GROUP_H
#define RC_TEST_THREE_GROUP_H

#include <math.h>

#include "relcol/relcol.h"

static inline int rc_three_group(double c, double back, rc_particle P[3], rc_vec3 x[3],
                                 rc_contact C[2])
{
    const double k = rc_inv_c2_of(c), m[3] = {1, 1, 2};
    const rc_vec3 n1 = rc_v3(cos(M_PI / 6), sin(M_PI / 6), 0);
    const rc_vec3 n2 = rc_v3(cos(M_PI / 4), -sin(M_PI / 4), 0);
    for (int i = 0; i < 3; i++)
        P[i] = (rc_particle){m[i], rc_v3(0, 0, 0)};
    x[0] = rc_v3(-back, 0, 0);
    x[1] = n1;
    x[2] = n2;
    C[0] = (rc_contact){0, 1, n1, 1.0, 0.0, rc_v3_scale(0.5, n1)};
    C[1] = (rc_contact){0, 2, n2, 1.0, 0.0, rc_v3_scale(0.5, n2)};
    return rc_momentum_from_velocity(1.0, rc_v3(0.9, 0, 0), k, &P[0].p);
}

#endif
