/* pressure_blocks.h — the pressure of a running gas, block by block, for relcol-gas's
 * read-out: with walls, each walled axis's two walls' momentum flux (rc_sim_diag's
 * wall_impulse_by_wall) over its area and the block's time; in a periodic box, the
 * momentum flux itself, the trace of the Helfand moment's change over d V t (exact,
 * papers/pressure.md). Mark at every block boundary, read the mean and its standard
 * error at the end. */
#ifndef RELCOL_PRESSURE_BLOCKS_H
#define RELCOL_PRESSURE_BLOCKS_H

#include <math.h>
#include "relcol/relcol.h"

#define PB_MAXBLOCKS 256

typedef struct pb_acc {
    rc_sim_moments m;
    rc_sim_diag d;
    int have, nb;
    double p[PB_MAXBLOCKS];
} pb_acc;

/* A block boundary at s's time (periodic != 0: every axis periodic). RC_OK or the
 * engine's code. */
static inline int pb_mark(const rc_sim *s, int periodic, const rc_vec3 box, pb_acc *a)
{
    rc_sim_moments m;
    rc_sim_diag d;
    int st = rc_sim_moments_get(s, &m);
    if (st == RC_OK)
        st = rc_sim_diagnostics(s, &d);
    if (st != RC_OK)
        return st;
    const double T = m.time - a->m.time;
    if (a->have && T > 0.0 && a->nb < PB_MAXBLOCKS) {
        const double L[3] = {box.x, box.y, box.z};
        double p = 0.0;
        for (int k = 0; k < m.dim; k++) {
            if (periodic)
                p += (m.helfand[4 * k] - a->m.helfand[4 * k]) / (m.dim * m.volume * T);
            else
                p += 0.5 * ((d.wall_impulse_by_wall[2 * k + 1] - a->d.wall_impulse_by_wall[2 * k + 1]) -
                            (d.wall_impulse_by_wall[2 * k] - a->d.wall_impulse_by_wall[2 * k])) /
                     (m.dim * (m.volume / L[k]) * T);
        }
        a->p[a->nb++] = p;
    }
    a->m = m;
    a->d = d;
    a->have = 1;
    return RC_OK;
}

/* Mean pressure of the blocks and its standard error (NAN with fewer than two). */
static inline double pb_result(const pb_acc *a, double *se)
{
    double mean = 0.0, v = 0.0;
    for (int k = 0; k < a->nb; k++)
        mean += a->p[k];
    mean = a->nb ? mean / a->nb : NAN;
    for (int k = 0; k < a->nb; k++)
        v += (a->p[k] - mean) * (a->p[k] - mean);
    *se = a->nb > 1 ? sqrt(v / (a->nb - 1) / a->nb) : NAN;
    return mean;
}

#endif
