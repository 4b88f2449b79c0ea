/* test_transport_errors.c — are relcol-eos's quoted errors of eta and lambda right? The
 * spread of K independent seeds of a small dilute gas against the mean block error each
 * run quotes, for both estimators (Einstein–Helfand and Green–Kubo, apps/eos/eos_flux.h;
 * papers/transport.md, section 11).
 *
 * The band: for Gaussian estimates with the right errors, the seeds' sample sd s over the
 * true sd sigma is sqrt(chi2_{K-1} / (K-1)); the mean of K quoted errors is far steadier
 * (each from 20 blocks, 16 % apiece, 2.3 % for the mean of 48). With K = 48 and the band
 * R = s / <quoted> in [1/1.5, 1.5] a correct estimator passes with probability 0.9997 per
 * quantity, one whose errors are half the truth with 0.0067, twice the truth with 0.0008
 * (chi-square cdf; the section gives the table for K = 8 ... 64: at K = 8 a correct
 * estimator would fail 15 % of the time and one off by 2 pass 21 %). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "eos_run.h"
#include "rc_test.h"

enum { K = 48 };

static double sd(const double *x, int k)
{
    double m = 0.0, v = 0.0;
    for (int i = 0; i < k; i++)
        m += x[i] / k;
    for (int i = 0; i < k; i++)
        v += (x[i] - m) * (x[i] - m);
    return sqrt(v / (k - 1));
}

static double mean(const double *x, int k)
{
    double m = 0.0;
    for (int i = 0; i < k; i++)
        m += x[i] / k;
    return m;
}

/* classical spheres, packing 0.02, N = 100 (eta and lambda are collective: their relative
 * error does not fall with N, so a small box tests the errors as well as a large one),
 * 400 mean free times in 20 blocks of 20 readings, lag 6 */
static void test_seed_spread(void)
{
    static double x[4][K], e[4][K], rho[2][K];
    const char *name[4] = {"eta (Einstein-Helfand)", "lambda (Einstein-Helfand)",
                           "eta (Green-Kubo)", "lambda (Green-Kubo)"};
    for (int s = 0; s < K; s++) {
        eos_in in = {3, 100, 0.02, 1.0, INFINITY, NULL, (uint64_t)(1000 + s), 10.0, 400.0, 20,
                     20, 1, 6.0, 0, 0.0, NULL, NULL, NULL};
        in.frame = rc_toi_frame_find("sphere");
        eos_out r;
        char err[256];
        ENSURE_MSG(eos_measure(&in, &r, err) == 0, "seed %d: %s", s, err);
        const eos_flux_est *q[4] = {&r.eta_f, &r.lambda_f, &r.eta_f, &r.lambda_f};
        for (int k = 0; k < 4; k++) {
            x[k][s] = k < 2 ? q[k]->eh : q[k]->gk;
            e[k][s] = k < 2 ? q[k]->eh_se : q[k]->gk_se;
            ENSURE(isfinite(x[k][s]) && e[k][s] > 0.0);
        }
        rho[0][s] = r.eta_f.rho1;
        rho[1][s] = r.lambda_f.rho1;
    }
    for (int k = 0; k < 4; k++) {
        const double spread = sd(x[k], K), quoted = mean(e[k], K), R = spread / quoted;
        printf("  %-26s mean %.5f, seed spread %.5f, mean quoted error %.5f: ratio %.3f\n",
               name[k], mean(x[k], K), spread, quoted, R);
        ENSURE_MSG(R <= 1.5 && R >= 1.0 / 1.5, "%s: spread / quoted error %.3f", name[k], R);
    }
    /* adjacent blocks share the windows that run on across their border: their estimates'
     * correlation, pooled over the seeds, is small (white-noise estimate L / (8 B) = 0.04) */
    printf("  lag-1 correlation of the block estimates, mean over seeds: eta %.3f, lambda "
           "%.3f (+- %.3f)\n", mean(rho[0], K), mean(rho[1], K), sd(rho[0], K) / sqrt(K));
}

int main(void)
{
    RUN_TEST(test_seed_spread);
    RC_TEST_MAIN_END();
}
