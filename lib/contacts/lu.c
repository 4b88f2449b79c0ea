/* contacts/lu.c — the dense LU factorisation and solve of the joint solve's Newton steps. */
#include <float.h>
#include <math.h>
#include <stddef.h>

#include "relcol/status.h"
#include "private.h"

/* LU factorisation with partial pivoting of the m x m row-major A, in place, and the
 * solve with it: the arithmetic of GSL 2.7's gsl_linalg_LU_decomp (its unblocked
 * algorithm, which GSL uses up to 24 unknowns) and gsl_linalg_LU_svx with GSL's CBLAS,
 * operation for operation, so that groups keep their bits. Written out because GSL's
 * versions allocate and call GSL's error handler (which aborts by default) when that
 * fails or the matrix is singular; here a zero pivot is a status. piv: m entries. */
int ctc_lu_factor(double *A, size_t m, size_t *piv)
{
    for (size_t j = 0; j < m; j++) {
        size_t jp = j; /* the first largest |A(i, j)|, i >= j */
        double amax = 0.0;
        for (size_t i = j; i < m; i++)
            if (fabs(A[i * m + j]) > amax) {
                amax = fabs(A[i * m + j]);
                jp = i;
            }
        piv[j] = jp;
        if (!(A[jp * m + j] != 0.0))
            return RC_ENOCONVERGE; /* singular (or not finite) */
        if (jp != j)
            for (size_t k = 0; k < m; k++) {
                const double t = A[j * m + k];
                A[j * m + k] = A[jp * m + k];
                A[jp * m + k] = t;
            }
        const double ajj = A[j * m + j];
        if (fabs(ajj) >= DBL_MIN) {
            const double inv = 1.0 / ajj;
            for (size_t i = j + 1; i < m; i++)
                A[i * m + j] *= inv;
        } else {
            for (size_t i = j + 1; i < m; i++)
                A[i * m + j] /= ajj;
        }
        for (size_t i = j + 1; i < m; i++) {
            const double t = -1.0 * A[i * m + j];
            for (size_t k = j + 1; k < m; k++)
                A[i * m + k] += A[j * m + k] * t;
        }
    }
    return RC_OK;
}

void ctc_lu_solve(const double *LU, size_t m, const size_t *piv, double *x)
{
    for (size_t i = 0; i < m; i++)
        if (piv[i] != i) {
            const double t = x[i];
            x[i] = x[piv[i]];
            x[piv[i]] = t;
        }
    for (size_t i = 1; i < m; i++) { /* L c = P b, L unit lower */
        double t = x[i];
        for (size_t j = 0; j < i; j++)
            t -= LU[i * m + j] * x[j];
        x[i] = t;
    }
    x[m - 1] = x[m - 1] / LU[(m - 1) * m + (m - 1)];
    for (size_t i = m - 1; i-- > 0;) { /* U x = c */
        double t = x[i];
        for (size_t j = i + 1; j < m; j++)
            t -= LU[i * m + j] * x[j];
        x[i] = t / LU[i * m + i];
    }
}
