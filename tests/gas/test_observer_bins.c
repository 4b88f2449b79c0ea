/* test_observer_bins.c — observer.csv's boosted_juttner and juttner_at_rest columns are
 * the laws' means over each histogram bin (bj_bin_mean, apps/gas/boosted.h), as the
 * histogram beside them is, not the densities at the bins' midpoints: against adaptive
 * quadrature (GSL qags) of the 1-D density over the bins relcol-gas uses, and of the 2-D
 * law's p'_x marginal (qags over p'_y too) over a bin; the midpoint value is a few
 * per cent off where the law curves, so this test tells the two apart. */
#include <math.h>

#include <gsl/gsl_errno.h>

#include "boosted.h"
#include "rc_test.h"

static double qags_mean(gsl_function *F, double lo, double hi)
{
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
    double v = NAN, e;
    if (ws && gsl_integration_qags(F, lo, hi, 0.0, 1e-12, 200, ws, &v, &e) != GSL_SUCCESS)
        v = NAN;
    gsl_integration_workspace_free(ws);
    return v / (hi - lo);
}

/* the 1-D observer's bins (gas_moving.c: MH1 = 80 over sinh(min(-eta, 0) - Y) ..
 * sinh(max(-eta, 0) + Y), Y = acosh(1 + 8 theta)) */
static void test_bins_1d(void)
{
    gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc(20);
    ENSURE(gl != NULL);
    if (!gl)
        return;
    const double thetas[] = {0.5, 1.0}, V = 0.5;
    double worst_mid = 0.0;
    for (int k = 0; k < 2; k++) {
        const double th = thetas[k], Y = acosh(1.0 + 8.0 * th), eta = atanh(V);
        const double lo = sinh(fmin(-eta, 0.0) - Y), hi = sinh(fmax(-eta, 0.0) + Y);
        const double bw = (hi - lo) / 80.0;
        double par[2] = {th, V};
        gsl_function F = {bj1_density_fn, par};
        for (int b = 0; b < 80; b++) {
            const double x0 = lo + bw * b, ref = qags_mean(&F, x0, x0 + bw);
            ENSURE_CLOSE(bj_bin_mean(&F, x0, x0 + bw, gl), ref, 1e-10, ref);
            if (ref > 1e-3)
                worst_mid = fmax(worst_mid, fabs(bj1_density(th, V, x0 + 0.5 * bw) / ref - 1.0));
        }
    }
    printf("  1-D: the midpoint density is up to %.2f %% off the bin mean (density > 1e-3)\n",
           100.0 * worst_mid);
    ENSURE(worst_mid > 1e-3);
    gsl_integration_glfixed_table_free(gl);
}

/* the 2-D law's p'_x marginal: qags over p'_y, then over the bin */
typedef struct {
    double theta, V, px;
} marg;
static double dens_y(double py, void *p)
{
    const marg *m = p;
    return bj_density(m->theta, m->V, m->px, py);
}
static double marginal(double px, void *p)
{
    marg m = *(const marg *)p;
    m.px = px;
    gsl_function F = {dens_y, &m};
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
    double v = NAN, e;
    if (ws && gsl_integration_qagi(&F, 0.0, 1e-12, 200, ws, &v, &e) != GSL_SUCCESS)
        v = NAN;
    gsl_integration_workspace_free(ws);
    return v;
}

static void test_bin_2d(void)
{
    gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc(20);
    ENSURE(gl != NULL);
    if (!gl)
        return;
    marg m = {1.0, 0.5, 0.0};
    gsl_function F = {marginal, &m};
    /* bins of the width relcol-gas uses at theta 1, V 0.5 (2 w / 50) */
    const double gV = 1.0 / sqrt(0.75), w = 8.0 * gV * sqrt(2.0) + 2.0, bw = 2.0 * w / 50.0;
    double worst_mid = 0.0;
    for (double x0 = -3.0; x0 < 3.0; x0 += 0.75) {
        const double ref = qags_mean(&F, x0, x0 + bw);
        ENSURE_CLOSE(bj_bin_mean(&F, x0, x0 + bw, gl), ref, 1e-9, ref);
        worst_mid = fmax(worst_mid, fabs(marginal(x0 + 0.5 * bw, &m) / ref - 1.0));
    }
    printf("  2-D: the midpoint marginal is up to %.2f %% off the bin mean on -3..3\n",
           100.0 * worst_mid);
    gsl_integration_glfixed_table_free(gl);
}

int main(void)
{
    gsl_set_error_handler_off();
    RUN_TEST(test_bins_1d);
    RUN_TEST(test_bin_2d);
    RC_TEST_MAIN_END();
}
