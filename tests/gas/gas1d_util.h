/* gas1d_util.h — shared set-up for the 1-D gas tests and benchmark: a binary mass mixture
 * at unit density with all speeds equal and random signs (a far-from-thermal start). */
#ifndef GAS1D_UTIL_H
#define GAS1D_UTIL_H

#include <math.h>
#include <stdlib.h>

#include "rc_test.h"
#include "relcol/relcol.h"

typedef struct gas_setup {
    size_t n;
    double L, inv_c2;
    double *x, *m, *p;
} gas_setup;

/* n particles on [0, n] (unit density), one per cell of width 1 at a random place in the
 * middle 80 % of the cell (so strictly increasing), species heavy (m_heavy) with
 * probability frac_heavy else light (m_light), every |v| = speed with a random sign. */
static inline int gas_setup_mixture(gas_setup *s, size_t n, double inv_c2, double m_light,
                                    double m_heavy, double frac_heavy, double speed,
                                    uint64_t seed)
{
    rc_test_rng r = {seed};
    s->n = n;
    s->L = (double)n;
    s->inv_c2 = inv_c2;
    s->x = malloc(n * sizeof(double));
    s->m = malloc(n * sizeof(double));
    s->p = malloc(n * sizeof(double));
    if (!s->x || !s->m || !s->p)
        return RC_ENOMEM;
    for (size_t i = 0; i < n; i++) {
        s->x[i] = (double)i + 0.1 + 0.8 * rc_test_uniform(&r);
        s->m[i] = rc_test_uniform(&r) < frac_heavy ? m_heavy : m_light;
        const double v = rc_test_uniform(&r) < 0.5 ? -speed : speed;
        rc_vec3 p;
        int st = rc_momentum_from_velocity(s->m[i], rc_v3(v, 0, 0), inv_c2, &p);
        if (st != RC_OK)
            return st;
        s->p[i] = p.x;
    }
    return RC_OK;
}

static inline void gas_setup_free(gas_setup *s)
{
    free(s->x);
    free(s->m);
    free(s->p);
    s->x = s->m = s->p = NULL;
}

static inline int gas_setup_create(const gas_setup *s, rc_gas1d **g)
{
    rc_gas1d_def d = rc_gas1d_def_default();
    d.n = s->n;
    d.length = s->L;
    d.c = rc_test_c_of(s->inv_c2);
    d.x = s->x;
    d.m = s->m;
    d.p = s->p;
    return rc_gas1d_create(&d, g, NULL);
}

#endif
