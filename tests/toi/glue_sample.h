/* glue_sample.h — the boundary samples of a contracted shape that the glued-tube tests
 * scan with rc_glue_inside (test_glue.c, test_glue_pair.c): nb directions on a circle
 * (2-D) or 6 nb on a Fibonacci lattice on the sphere (3-D), and the boundary point along
 * each. */
#ifndef RELCOL_TEST_GLUE_SAMPLE_H
#define RELCOL_TEST_GLUE_SAMPLE_H

#include <math.h>

#include "relcol/relcol.h"

/* the number of samples for nb in dimension dim */
static inline int glue_sample_count(int dim, int nb) { return dim == 3 ? 6 * nb : nb; }

/* the j-th of m unit directions */
static inline rc_vec3 glue_sample_dir(int dim, int j, int m)
{
    if (dim == 3) {
        const double z = 1.0 - (2.0 * j + 1.0) / m, a = j * M_PI * (3.0 - sqrt(5.0));
        const double q = sqrt(1.0 - z * z);
        return rc_v3(q * cos(a), q * sin(a), z);
    }
    const double a = 2.0 * M_PI * j / m;
    return rc_v3(cos(a), sin(a), 0.0);
}

/* the distance along unit u from the centre of shape sh to its boundary: the rest-frame
 * length of s u equals r */
static inline double glue_sample_reach(const rc_toi_shape *sh, rc_vec3 u)
{
    const double bu = rc_v3_dot(sh->beta, u);
    return sh->r / sqrt(1.0 + bu * bu / sh->g2);
}

#endif
