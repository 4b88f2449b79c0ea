/* eos_flux.h — η and λ from the series of a run's Helfand moments, two ways over the same
 * readings (papers/transport.md, section 11): Einstein–Helfand over every time origin
 * of the run (windows may run on into the next block), and Green–Kubo on the bin-averaged
 * flux (the moment's increments, exact for impulsive collisions), its autocorrelation
 * integrated to a cutoff chosen by a rule. Errors from blocks of time origins. */
#ifndef RELCOL_EOS_FLUX_H
#define RELCOL_EOS_FLUX_H

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "relcol/moments.h"

/* one coefficient measured both ways, each with its block error */
typedef struct eos_flux_est {
    double eh, eh_se;  /* Einstein–Helfand: (<dX(L)^2> - <dX(L/2)^2>) / (L/2) */
    double gk, gk_se;  /* Green–Kubo: the binned autocorrelation integrated to gk_cut */
    double gk_cut;     /* the rule's cutoff, in the time unit of dt */
    int gk_found;      /* 1: the rule found a plateau within the lag; 0: cut at the lag */
    double diff_se;    /* block error of gk - eh (the two share the data) */
    double rho1;       /* lag-1 correlation of the Einstein–Helfand block estimates */
} eos_flux_est;

/* Independent components of the traceless symmetric pressure tensor, as Helfand moments:
 * under isotropy each has the autocorrelation of P_xy (3-D: five; 2-D: two). */
static inline int eos_flux_shear_count(int dim) { return dim == 3 ? 5 : 2; }

/* x[c * m + k]: shear component c at reading k; the symmetrised off-diagonal moments and
 * the normal-stress differences (G_xx - G_yy)/2, (G_xx + G_yy - 2 G_zz)/(2 sqrt 3) */
static inline void eos_flux_shear_series(const rc_sim_moments *M, size_t m, int dim, double *x)
{
    for (size_t k = 0; k < m; k++) {
        const double *g = M[k].helfand;
        x[k] = 0.5 * (g[1] + g[3]);
        x[m + k] = 0.5 * (g[0] - g[4]);
        if (dim == 3) {
            x[2 * m + k] = 0.5 * (g[2] + g[6]);
            x[3 * m + k] = 0.5 * (g[5] + g[7]);
            x[4 * m + k] = (g[0] + g[4] - 2.0 * g[8]) / (2.0 * sqrt(3.0));
        }
    }
}

/* x[a * m + k]: the heat moment (Eckart) along axis a, h the enthalpy per ball */
static inline void eos_flux_heat_series(const rc_sim_moments *M, size_t m, int dim, double h,
                                        double *x)
{
    for (int a = 0; a < dim; a++)
        for (size_t k = 0; k < m; k++)
            x[(size_t)a * m + k] = M[k].helfand_energy[a] - h * M[k].position[a];
}

static inline double eos_flux_mean_se(const double *x, size_t k, double *se)
{
    double mu = 0.0, v = 0.0;
    for (size_t i = 0; i < k; i++)
        mu += x[i];
    mu /= (double)k;
    for (size_t i = 0; i < k; i++)
        v += (x[i] - mu) * (x[i] - mu);
    *se = k > 1 ? sqrt(v / (double)(k - 1) / (double)k) : NAN;
    return mu;
}

/* Both estimators of scale * (growth rate of <dX^2>) over nc series x[c * m + k] of m
 * readings dt apart, m >= nb * pb + 1; block b holds the time origins b pb .. (b+1) pb - 1
 * (the last block those whose windows end within the run). L: the lag in readings (even,
 * 2 <= L <= pb). scale: 1 / (2 V kT) for eta, 1 / (2 V kT^2) for lambda. 0, or -1 for bad
 * arguments or memory. curve (NULL, or 2 (L + 1) values): the running Green–Kubo integral
 * to mu readings, mu = 0 .. L, and its block error. */
static inline int eos_flux_estimate(const double *x, int nc, size_t m, size_t nb, size_t pb,
                                    size_t L, double dt, double scale, eos_flux_est *o,
                                    double *curve)
{
    if (nc < 1 || nb < 2 || pb < 2 || L < 2 || L % 2 || L > pb || m < nb * pb + 1 || !(dt > 0.0))
        return -1;
    const size_t H = L / 2;
    double *eh = malloc(nb * sizeof *eh), *I = malloc(nb * (L + 1) * sizeof *I),
           *acf = malloc((L + 1) * sizeof *acf), *tmp = malloc(nb * sizeof *tmp);
    if (!eh || !I || !acf || !tmp) {
        free(eh);
        free(I);
        free(acf);
        free(tmp);
        return -1;
    }
    for (size_t b = 0; b < nb; b++) {
        /* origins k: every one of the block whose longest window (L readings for the
         * moments, L + 1 for the increments' products) ends within the run */
        const size_t k0 = b * pb;
        size_t k1 = k0 + pb;
        if (k1 + L + 1 > m)
            k1 = m - L - 1;
        const double cnt = (double)(k1 - k0);
        double s2 = 0.0, s1 = 0.0;
        for (size_t mu = 0; mu <= L; mu++)
            acf[mu] = 0.0;
        for (int c = 0; c < nc; c++) {
            const double *xc = x + (size_t)c * m;
            for (size_t k = k0; k < k1; k++) {
                const double a = xc[k + L] - xc[k], d = xc[k + H] - xc[k];
                s2 += a * a;
                s1 += d * d;
                /* the bin-averaged flux times dt: the increment, exact */
                const double j0 = xc[k + 1] - xc[k];
                for (size_t mu = 0; mu <= L; mu++)
                    acf[mu] += j0 * (xc[k + mu + 1] - xc[k + mu]);
            }
        }
        eh[b] = scale * (s2 - s1) / (cnt * nc) / ((double)H * dt);
        /* running Green–Kubo integral: (c_0 + 2 sum_1^M c_mu) / dt, two-sided */
        double run = acf[0];
        I[b * (L + 1)] = scale * run / (cnt * nc) / dt;
        for (size_t mu = 1; mu <= L; mu++) {
            run += 2.0 * acf[mu];
            I[b * (L + 1) + mu] = scale * run / (cnt * nc) / dt;
        }
    }
    o->eh = eos_flux_mean_se(eh, nb, &o->eh_se);
    for (size_t mu = 0; curve && mu <= L; mu++) {
        for (size_t b = 0; b < nb; b++)
            tmp[b] = I[b * (L + 1) + mu];
        curve[mu] = eos_flux_mean_se(tmp, nb, &curve[L + 1 + mu]);
    }
    /* the rule: the first M whose next stretch [M, 2M] adds to the integral less than its
     * own block error -- the plateau as far as the data resolve it; report I(2M) */
    size_t cut = L;
    o->gk_found = 0;
    for (size_t M = 1; 2 * M <= L; M++) {
        double se;
        for (size_t b = 0; b < nb; b++)
            tmp[b] = I[b * (L + 1) + 2 * M] - I[b * (L + 1) + M];
        const double d = eos_flux_mean_se(tmp, nb, &se);
        if (fabs(d) <= se) {
            cut = 2 * M;
            o->gk_found = 1;
            break;
        }
    }
    for (size_t b = 0; b < nb; b++)
        tmp[b] = I[b * (L + 1) + cut];
    o->gk = eos_flux_mean_se(tmp, nb, &o->gk_se);
    o->gk_cut = (double)cut * dt;
    for (size_t b = 0; b < nb; b++)
        tmp[b] -= eh[b];
    (void)eos_flux_mean_se(tmp, nb, &o->diff_se);
    double c01 = 0.0, c00 = 0.0;
    for (size_t b = 0; b < nb; b++) {
        c00 += (eh[b] - o->eh) * (eh[b] - o->eh);
        if (b + 1 < nb)
            c01 += (eh[b] - o->eh) * (eh[b + 1] - o->eh);
    }
    o->rho1 = c00 > 0.0 ? c01 / c00 : 0.0;
    free(eh);
    free(I);
    free(acf);
    free(tmp);
    return 0;
}

#endif
