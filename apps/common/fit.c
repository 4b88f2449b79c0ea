/* fit.c — the least-squares slope of a log-log plot (GSL), used by every convergence
 * sweep to turn "the error falls like c^-2" into one printed number. */
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_fit.h>

#include "app.h"

int app_loglog_slope(const double *x, const double *y, size_t n, double *slope,
                     double *intercept, double *slope_sd, size_t *used)
{
    double *lx = malloc((n ? n : 1) * sizeof *lx), *ly = malloc((n ? n : 1) * sizeof *ly);
    size_t k = 0;
    int rc = -1;
    if (!lx || !ly)
        goto out;
    for (size_t i = 0; i < n; i++)
        if (isfinite(x[i]) && isfinite(y[i]) && x[i] > 0.0 && y[i] > 0.0) {
            lx[k] = log10(x[i]);
            ly[k] = log10(y[i]);
            k++;
        }
    if (used)
        *used = k;
    if (k < 3)
        goto out;
    double c0, c1, cov00, cov01, cov11, sumsq;
    if (gsl_fit_linear(lx, 1, ly, 1, k, &c0, &c1, &cov00, &cov01, &cov11, &sumsq) != 0)
        goto out;
    *slope = c1;
    if (intercept)
        *intercept = c0;
    if (slope_sd)
        *slope_sd = sqrt(cov11);
    rc = 0;
out:
    free(lx);
    free(ly);
    return rc;
}
