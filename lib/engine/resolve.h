/* engine/resolve.h — the small steps every resolution shares: a ball advanced along its
 * line, compensated sums, kinetic energy. Not exported: eng_ prefix. */
#ifndef RELCOL_ENGINE_RESOLVE_H
#define RELCOL_ENGINE_RESOLVE_H

#include "private.h"

/* Move ball i's stored state to time T (position, proper time, clock). */
static inline void eng_advance_ball(rc_sim *s, int32_t i, double T)
{
    eng_ball *b = &s->b[i];
    const eng_aux *a = &s->a[i];
    double h = T - b->t;
    if (h == 0.0)
        return;
    b->x = rc_v3_axpy(b->x, h, b->v);
    if (s->inv_c2 == 0.0)
        s->clk[i].tau += h;
    else
        s->clk[i].tau += h * (a->m / eng_mass_rel(a->m, a->p, s->inv_c2));
    b->t = T;
}


static inline void eng_kahan(double *sum, double *comp, double x)
{
    double y = x - *comp;
    double t = *sum + y;
    *comp = (t - *sum) - y;
    *sum = t;
}

static inline double eng_kinetic(const rc_particle *b, double inv_c2)
{
    double M = eng_mass_rel(b->m, b->p, inv_c2);
    return rc_v3_norm2(b->p) / (M + b->m);
}


#endif
