/* gas_stats.h — the statistics of a sampled gas shared by relcol-gas and the Jüttner
 * reproduction tests (header only): block means with standard errors, the cell of a sample
 * among sorted edges, the Pearson chi-square of block counts with its variance inflation,
 * chi-square p-values and bounds from GSL's distribution functions, and the integrated
 * autocorrelation time that says whether blocks are long enough. */
#ifndef RELCOL_GAS_STATS_H
#define RELCOL_GAS_STATS_H

#include <math.h>
#include <stddef.h>

#include <gsl/gsl_cdf.h>

/* Mean of nb block values and its standard error sqrt(var / nb) (nb >= 2). */
static inline double gs_mean_se(const double *b, int nb, double *se)
{
    double s = 0.0, s2 = 0.0;
    for (int k = 0; k < nb; k++)
        s += b[k];
    const double mean = s / nb;
    for (int k = 0; k < nb; k++)
        s2 += (b[k] - mean) * (b[k] - mean);
    *se = sqrt(s2 / (nb - 1) / nb);
    return mean;
}

/* Cell lo with edge[lo] <= x < edge[lo + 1] among ncell cells (edge[0] <= x assumed:
 * 0 otherwise), by bisection. */
static inline int gs_find_cell(const double *edge, int ncell, double x)
{
    int lo = 0, hi = ncell; /* edge[lo] <= x < edge[hi] */
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        if (x >= edge[mid])
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* One cell's count pooled over nblock blocks (replicas or time blocks), cnt[b * stride]
 * for b < nblock (a row-major [nblock][...] count array seen flat, offset to the cell), and
 * the block-to-block variance of the count (*var). The Pearson
 * chi-square is divided by the variance inflation phi, the mean over cells of *var over
 * the multinomial variance gs_phi_term(): 1 for independent samples, > 1 for correlated
 * snapshots of one replica. */
static inline double gs_pooled_count(const double *cnt, int nblock, size_t stride, double *var)
{
    double tot = 0.0, v = 0.0;
    for (int b = 0; b < nblock; b++)
        tot += cnt[b * stride];
    for (int b = 0; b < nblock; b++)
        v += (cnt[b * stride] - tot / nblock) * (cnt[b * stride] - tot / nblock);
    *var = v / (nblock - 1);
    return tot;
}

/* A cell's block variance over the multinomial one of nb samples per block at cell
 * probability p. */
static inline double gs_phi_term(double var, double nb, double p)
{
    return var / (nb * p * (1.0 - p));
}

/* A cell's Pearson term (observed - expected)^2 / expected. */
static inline double gs_pearson_term(double observed, double expected)
{
    return (observed - expected) * (observed - expected) / expected;
}

/* Pearson chi-squares of cell counts pooled over nblock blocks (cnt row-major
 * [nblock][ncell], ntot samples in all) against two models' cell probabilities pa and pb
 * (*chi2_a, *chi2_b); returns the variance inflation phi measured under model a. */
static inline double gs_chi2_two_models(const double *cnt, int nblock, int ncell, double ntot,
                                        const double *pa, const double *pb, double *chi2_a,
                                        double *chi2_b)
{
    const double nb = ntot / nblock;
    double phi = 0.0;
    *chi2_a = *chi2_b = 0.0;
    for (int c = 0; c < ncell; c++) {
        double var;
        const double tot = gs_pooled_count(cnt + c, nblock, (size_t)ncell, &var);
        phi += gs_phi_term(var, nb, pa[c]);
        *chi2_a += gs_pearson_term(tot, ntot * pa[c]);
        *chi2_b += gs_pearson_term(tot, ntot * pb[c]);
    }
    return phi / ncell;
}

/* Pass bound of a chi-square with dof degrees of freedom: mean + 4.5 standard deviations
 * (p ~ 1e-4 at dof ~ 20-40, so a fixed-seed pass is not luck, while a real misfit of the
 * shape, which grows like the sample size, cannot hide). */
static inline double gs_chi2_bound(double dof) { return dof + 4.5 * sqrt(2.0 * dof); }

/* p-value of a chi-square with dof degrees of freedom: P(X >= chi2). */
static inline double gs_chi2_p(double chi2, double dof) { return gsl_cdf_chisq_Q(chi2, dof); }

/* The chi-square that a fit exceeds with the probability of a one-sided nsigma normal
 * deviation (nsigma = 5: p = 2.9e-7), from the chi-square quantile itself: the normal
 * approximation dof + nsigma sqrt(2 dof) sits far inside the right-skewed tail (3.6
 * sigma at dof 18 for nsigma 5). */
static inline double gs_chi2_sigma_bound(double dof, double nsigma)
{
    return gsl_cdf_chisq_Qinv(gsl_cdf_ugaussian_Q(nsigma), dof);
}

/* Integrated autocorrelation time (in sampling intervals) of a series: 1/2 + sum of the
 * autocorrelations up to the first that is not positive (or lag K/4). */
static inline double gs_tau_int(const double *x, size_t k)
{
    double mean = 0.0, var = 0.0;
    for (size_t i = 0; i < k; i++)
        mean += x[i];
    mean /= (double)k;
    for (size_t i = 0; i < k; i++)
        var += (x[i] - mean) * (x[i] - mean);
    if (!(var > 0.0))
        return 0.5;
    double tau = 0.5;
    for (size_t lag = 1; lag < k / 4; lag++) {
        double c = 0.0;
        for (size_t i = 0; i + lag < k; i++)
            c += (x[i] - mean) * (x[i + lag] - mean);
        const double rho = c / var;
        if (!(rho > 0.0))
            break;
        tau += rho;
    }
    return tau;
}

#endif
