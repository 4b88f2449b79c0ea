/* front.c — the shock front's mid-level point by a least-squares logistic step (front.h),
 * with GSL's trust-region solver; the width is fitted as ln w so that it stays > 0. */
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_vector.h>

#include "front.h"

typedef struct {
    const sh_front *f;
    const double *x, *n, *sw; /* the window's bins; sw = sqrt(weight) */
    int m;
} fit_data;

static int resid(const gsl_vector *p, void *v, gsl_vector *out)
{
    const fit_data *d = v;
    const double xs = gsl_vector_get(p, 0), w = exp(gsl_vector_get(p, 1));
    for (int i = 0; i < d->m; i++) {
        const double e = 1.0 / (1.0 + exp((d->x[i] - xs) / w));
        gsl_vector_set(out, i, d->sw[i] * (d->f->nb + (d->f->na - d->f->nb) * e - d->n[i]));
    }
    return GSL_SUCCESS;
}

static int jac(const gsl_vector *p, void *v, gsl_matrix *J)
{
    const fit_data *d = v;
    const double xs = gsl_vector_get(p, 0), w = exp(gsl_vector_get(p, 1));
    for (int i = 0; i < d->m; i++) {
        const double z = (d->x[i] - xs) / w, e = 1.0 / (1.0 + exp(z));
        const double de = (d->f->na - d->f->nb) * e * (1.0 - e); /* -(dn/dz) */
        gsl_matrix_set(J, i, 0, d->sw[i] * de / w);
        gsl_matrix_set(J, i, 1, d->sw[i] * de * z);
    }
    return GSL_SUCCESS;
}

int sh_front_fit(const sh_front *f, const double *xc, const double *n, const double *wt,
                 int nb, double *xs, double *w)
{
    *xs = NAN;
    if (w)
        *w = NAN;
    double *buf = malloc(3 * (size_t)(nb > 0 ? nb : 1) * sizeof *buf);
    if (!buf)
        return -1;
    fit_data d = {f, buf, buf + nb, buf + 2 * nb, 0};
    for (int k = 0; k < nb; k++)
        if (xc[k] > f->xlo && xc[k] < f->xhi && wt[k] > 0.0 && isfinite(n[k])) {
            buf[d.m] = xc[k], buf[nb + d.m] = n[k], buf[2 * nb + d.m] = sqrt(wt[k]);
            d.m++;
        }
    int rc = -1;
    if (d.m >= 4) {
        gsl_multifit_nlinear_parameters fp = gsl_multifit_nlinear_default_parameters();
        gsl_multifit_nlinear_workspace *ws =
            gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &fp, (size_t)d.m, 2);
        if (ws) {
            gsl_multifit_nlinear_fdf fdf = {resid, jac, NULL, (size_t)d.m, 2, &d, 0, 0, 0};
            double p0[2] = {f->x_guess, log(f->w_guess)};
            gsl_vector_view pv = gsl_vector_view_array(p0, 2);
            int info = 0;
            if (!gsl_multifit_nlinear_init(&pv.vector, &fdf, ws) &&
                !gsl_multifit_nlinear_driver(200, 1e-10, 1e-12, 1e-12, NULL, NULL, &info, ws)) {
                const gsl_vector *p = gsl_multifit_nlinear_position(ws);
                const double x = gsl_vector_get(p, 0);
                /* a front outside its window is not a reading of it */
                if (isfinite(x) && x > f->xlo && x < f->xhi) {
                    *xs = x;
                    if (w)
                        *w = exp(gsl_vector_get(p, 1));
                    rc = 0;
                }
            }
            gsl_multifit_nlinear_free(ws);
        }
    }
    free(buf);
    return rc;
}
