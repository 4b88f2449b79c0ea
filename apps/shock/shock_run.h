/* shock_run.h — relcol-shock's run: independent seeds of the tube (tube.h), profiles in
 * bins of x at chosen times (moments.h), the ideal-fluid (riemann.h) and free-streaming
 * (freestream.h) references beside them, and what is read from them: chi-squares
 * against free streaming, the plateau and the shock speed against the ideal fluid. */
#ifndef RELCOL_SHOCK_RUN_H
#define RELCOL_SHOCK_RUN_H

#include <stdint.h>

#include "relcol/validity.h"

#include "freestream.h"
#include "moments.h"
#include "riemann.h"
#include "tube.h"

#define SH_MAX_TIMES 32
/* the profile's quantities: the derived ones (moments.h, SH_N ... SH_TE), then the raw
 * densities N0, Nx, g, K, Pxx, Pyy */
enum { SH_RAW = SH_NDERIVED, SH_NQ = SH_NDERIVED + 6 };
extern const char *const sh_q_names[SH_NQ];

typedef struct sh_opts {
    sh_tube tube;
    int nt;
    double times[SH_MAX_TIMES]; /* increasing, > 0 */
    int bins;
    int seeds;
    uint64_t seed;
} sh_opts;

typedef struct sh_result {
    int nt, nb, seeds;
    size_t nballs;
    uint64_t collisions;         /* ball-ball events over all seeds */
    double *xc;                  /* nb bin centres */
    double *mean, *err;          /* [t][bin][q]: mean over seeds, its standard error */
    double *fluid, *freestr;     /* [t][bin][q]: the references */
    rs_solution sol;             /* the ideal fluid's Riemann solution (table units) */
    rs_eos eos;
    /* against free streaming, per time: chi^2 of N0, g, Pxx over the bins (Student t's of
     * the seed means mapped to normal quantiles), bins used, p-values */
    double chi2[SH_MAX_TIMES][3], pval[SH_MAX_TIMES][3];
    int dof[SH_MAX_TIMES][3];
    /* against the fluid, per time: the plateau's p and v (bins inside the central 60 % of
     * [tail of the left wave, right shock]), the right shock's mid-level point (front.h)
     * and its fitted logistic width */
    double plat_p[SH_MAX_TIMES], plat_p_err[SH_MAX_TIMES];
    double plat_v[SH_MAX_TIMES], plat_v_err[SH_MAX_TIMES];
    double xshock[SH_MAX_TIMES], xshock_err[SH_MAX_TIMES], wshock[SH_MAX_TIMES];
    int plat_bins[SH_MAX_TIMES];
    double vshock, vshock_err;   /* the mean speed since t = 0: (xshock - x0)/t, last time */
    double vshock_local, vshock_local_err; /* the slope of xshock over the times (>= 3) */
    double lambda_star, kn;      /* mean free path in the right plateau; / shock travel at the last time */
    double lambda[2];            /* mean free paths of the two starting halves */
    /* where the seeds stand against the rigid-ball model's regime (relcol/validity.h):
     * the report of the seed of largest p_model (each seed noted for app_validity_warn) */
    rc_validity model;
    int model_ok;                /* model was read (rc_sim_validity succeeded for a seed) */
    int seeds_outside;           /* seeds whose verdict was `outside` */
} sh_result;

/* -1 with err on failure (engine, placement, references). progress: 1 to draw a bar. */
int sh_run(const sh_opts *o, sh_result *r, int progress, char *err);
void sh_result_free(sh_result *r);

static inline size_t sh_idx(const sh_result *r, int t, int b, int q)
{
    return ((size_t)t * r->nb + b) * SH_NQ + q;
}

#endif
