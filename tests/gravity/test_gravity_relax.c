/* test_gravity_relax — a colliding gas in the engine, started off equilibrium (uniform
 * density, one speed), relaxes to its coupling's equilibrium (papers/gravity.md section 5):
 * newtonian at c = inf to the barometric law n(z) ~ exp(-m g z/kT) with uniform kT;
 * equivalence at c = 1 to Tolman-Ehrenfest, theta(z)(1 + g z/c^2) = theta0, theta(z) falling
 * with height by >= 5 sigma, and n(z) ~ theta K2(1/theta). theta is measured two ways per
 * slab: <p_z v_z> along the field and <p_x v_x + p_y v_y>/2 across it (each kT in local
 * Juttner or Maxwell equilibrium). Profiles are averaged over snapshots far apart in time;
 * errors are the snapshots' scatter. The fitted constant (kT, theta0) is the pooled mean:
 * chi^2 has NBIN - 1 degrees of freedom. */
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sf_bessel.h>

#include "field_gas.h"
#include "slab_profile.h"

enum { NSNAP = 40 };

/* run the gas: relax for t_relax, then NSNAP snapshots dt apart */
static rc_sim *run(const rc_gravity_coupling *cp, double c, double g, uint64_t seed, prof *P,
                   double *chi_start)
{
    field_cell = 0.05;
    const size_t n = 3000;
    const double r = 0.005;
    rc_sim *s = field_gas(cp, c, g, n, r, 0.8, seed);
    ENSURE(s != NULL);
    if (!s)
        return NULL;
    /* the start is off equilibrium: its density is uniform (Poisson chi^2 against uniform
     * is small; against the barometric law, computed by the caller, large) */
    double cnt[NBIN] = {0};
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball b;
        rc_sim_get_ball(s, i, &b);
        cnt[(int)(b.x.z * NBIN)]++;
    }
    for (int k = 0; k < NBIN; k++)
        chi_start[k] = cnt[k];
    memset(P, 0, sizeof *P);
    int st = rc_sim_advance(s, 40.0, 0);
    ENSURE_MSG(st == RC_OK, "%s", rc_strerror(st));
    for (int q = 0; q < NSNAP && st == RC_OK; q++) {
        st = rc_sim_advance(s, 40.0 + 2.0 * (q + 1), 0);
        ENSURE_MSG(st == RC_OK, "%s", rc_strerror(st));
        snapshot(s, g, isinf(c) ? 0.0 : 1.0 / (c * c), P);
    }
    return s;
}

/* a bin's share of the centres' range [r, 1 - r] under the density f */
static void shares(double (*f)(double, const double *), const double *par, double *out)
{
    const double r = 0.005;
    double tot = 0;
    for (int k = 0; k < NBIN; k++) {
        const double lo = fmax(k / (double)NBIN, r), hi = fmin((k + 1) / (double)NBIN, 1 - r);
        const int m = 400; /* Simpson */
        double sum = f(lo, par) + f(hi, par);
        for (int j = 1; j < m; j++)
            sum += (j % 2 ? 4 : 2) * f(lo + (hi - lo) * j / m, par);
        out[k] = sum * (hi - lo) / (3 * m);
        tot += out[k];
    }
    for (int k = 0; k < NBIN; k++)
        out[k] /= tot;
}

static double baro(double z, const double *par) { return exp(-par[0] * z / par[1]); }

/* theta K2(1/theta), theta = theta0/(1 + g z) (c = 1, m = 1) */
static double tolman_n(double z, const double *par)
{
    const double th = par[1] / (1 + par[0] * z);
    return th * gsl_sf_bessel_Kn(2, 1 / th);
}

/* The second virial correction of a hard-sphere gas (diameter 2r): the local chemical
 * potential gains 2 B2 n kT, B2 = (2 pi/3)(2r)^3, so n(z) = A f(z) exp(-2 B2 n(z)); at the
 * test's packing fraction (1e-3) it moves the bottom slab by about 1% of its count, which
 * the snapshots resolve. Solved per slab by fixed-point iteration, A to keep the total. */
static void virial(const double *ideal, double ntot, double r, double *out)
{
    const double B2 = 2.0 * M_PI / 3.0 * pow(2 * r, 3), vol = 1.0 / NBIN; /* (a slab's volume, box 1 x 1) */
    double A = 1.0;
    for (int it = 0; it < 200; it++) {
        double tot = 0;
        for (int k = 0; k < NBIN; k++) {
            double n = ideal[k] * ntot / vol;
            for (int j = 0; j < 50; j++)
                n = A * ideal[k] * ntot / vol * exp(-2 * B2 * n);
            out[k] = n * vol;
            tot += out[k];
        }
        A *= ntot / tot;
    }
}

static void print_bins(const prof *P, int j, const double *want)
{
    for (int k = 0; k < NBIN; k++) {
        double m, v;
        mean_err(P, j, k, &m, &v);
        printf("    z %.2f  want %.5g  got %.5g +- %.2g  (%+.1f sigma)\n", (k + 0.5) / NBIN,
               want[k], m, sqrt(v), (m - want[k]) / sqrt(v));
    }
}

static void test_barometric(void)
{
    const double g = 1.0;
    prof P;
    double start[NBIN];
    rc_sim *s = run(&rc_gravity_newtonian, INFINITY, g, 0xa01, &P, start);
    if (!s)
        return;
    double kt_z, kt_p;
    const double chi_z = chi2_of(&P, 1, NULL, &kt_z), chi_p = chi2_of(&P, 2, NULL, &kt_p);
    const double kt = 0.5 * (kt_z + kt_p), par[2] = {g, kt};
    double sh[NBIN], want[NBIN];
    shares(baro, par, sh);
    double chi0 = 0;
    virial(sh, 3000, 0.005, want);
    for (int k = 0; k < NBIN; k++)
        chi0 += (start[k] - want[k]) * (start[k] - want[k]) / want[k];
    const double chi_n = chi2_of(&P, 0, want, NULL);
    print_bins(&P, 0, want);
    const double pn = gsl_cdf_chisq_Q(chi_n, NBIN - 1), pz = gsl_cdf_chisq_Q(chi_z, NBIN - 1),
                 pp = gsl_cdf_chisq_Q(chi_p, NBIN - 1), p0 = gsl_cdf_chisq_Q(chi0, NBIN - 1);
    printf("  newtonian c inf g %g: kT %.4f (z) %.4f (perp); n(z) barometric p %.3f "
           "(start p %.1e), theta_z uniform p %.3f, theta_perp uniform p %.3f\n",
           g, kt_z, kt_p, pn, p0, pz, pp);
    ENSURE_MSG(p0 < 1e-6, "the start is not off equilibrium (p %.3g)", p0);
    ENSURE_MSG(pn > 1e-3, "n(z) chi^2 %.1f", chi_n);
    ENSURE_MSG(pz > 1e-3, "theta_z chi^2 %.1f", chi_z);
    ENSURE_MSG(pp > 1e-3, "theta_perp chi^2 %.1f", chi_p);
    ENSURE(fabs(kt_z - kt_p) < 0.02 * kt);
    rc_sim_free(&s);
}

static void test_tolman(void)
{
    const double g = 0.5;
    prof P;
    double start[NBIN];
    rc_sim *s = run(&rc_gravity_equivalence, 1.0, g, 0xa02, &P, start);
    if (!s)
        return;
    double th0;
    const double chi_l = chi2_of(&P, 3, NULL, &th0);
    double wz[NBIN], sh[NBIN], wn[NBIN];
    for (int k = 0; k < NBIN; k++)
        wz[k] = th0 / (1 + g * P.zs[k] / P.zn[k]);
    const double chi_z = chi2_of(&P, 1, wz, NULL), chi_p = chi2_of(&P, 2, wz, NULL);
    const double par[2] = {g, th0};
    shares(tolman_n, par, sh);
    virial(sh, 3000, 0.005, wn);
    const double chi_n = chi2_of(&P, 0, wn, NULL);
    print_bins(&P, 0, wn);
    print_bins(&P, 3, (const double[NBIN]){th0, th0, th0, th0, th0, th0, th0, th0, th0, th0});
    /* the gradient of theta itself (both thermometers), weighted least squares */
    double sw = 0, swz = 0, swzz = 0, swy = 0, swzy = 0;
    for (int k = 0; k < NBIN; k++) {
        double mz, vz, mp, vp;
        mean_err(&P, 1, k, &mz, &vz);
        mean_err(&P, 2, k, &mp, &vp);
        const double y = (mz + 2 * mp) / 3, v = (vz + 4 * vp) / 9, z = P.zs[k] / P.zn[k];
        sw += 1 / v, swz += z / v, swzz += z * z / v, swy += y / v, swzy += z * y / v;
    }
    const double det = sw * swzz - swz * swz, slope = (sw * swzy - swz * swy) / det;
    const double serr = sqrt(sw / det);
    const double pl = gsl_cdf_chisq_Q(chi_l, NBIN - 1), pz = gsl_cdf_chisq_Q(chi_z, NBIN - 1),
                 pp = gsl_cdf_chisq_Q(chi_p, NBIN - 1), pn = gsl_cdf_chisq_Q(chi_n, NBIN - 1);
    printf("  equivalence c 1 g %g: theta0 %.4f; theta sqrt(g00) const p %.3f, theta_z Tolman "
           "p %.3f, theta_perp Tolman p %.3f, n(z) p %.3f; d theta/dz %.4f +- %.4f (%.1f sigma)\n",
           g, th0, pl, pz, pp, pn, slope, serr, -slope / serr);
    ENSURE_MSG(pl > 1e-3, "theta sqrt(g00) chi^2 %.1f", chi_l);
    ENSURE_MSG(pz > 1e-3, "theta_z chi^2 %.1f", chi_z);
    ENSURE_MSG(pp > 1e-3, "theta_perp chi^2 %.1f", chi_p);
    ENSURE_MSG(pn > 1e-3, "n(z) chi^2 %.1f", chi_n);
    ENSURE_MSG(slope < -5 * serr, "gradient %.4g +- %.4g", slope, serr);
    rc_sim_free(&s);
}

int main(void)
{
    gsl_set_error_handler_off();
    RUN_TEST(test_barometric);
    RUN_TEST(test_tolman);
    RC_TEST_MAIN_END();
}
