/*md
# 10. A colliding gas in a uniform field relaxes to its coupling's equilibrium

Notebook 9 moved balls drawn from each equilibrium along the exact paths, without
collisions: a check of the paths and the walls. Here the balls collide. A gas started off
equilibrium (uniform in height, every ball at one speed 0.8 in a random direction) relaxes,
through its collisions, to the equilibrium of its coupling. The set-up is the one of
`tests/gravity/test_gravity_relax` (`tests/gravity/field_gas.h`): a 3-D box of edge 1,
periodic across, floor `z = 0` and ceiling `z = 1`, balls of rest mass 1, cells of 0.05.
The test has 3000 balls of radius 0.005; here 800 balls of radius 0.01 collide as often
(the rate a ball goes as `N r²`), so that the page renders in about a minute.

## The two equilibria

Both couplings conserve a Hamiltonian `H(x, p)` on the canonical phase space `d³x d³p`
(`papers/gravity.md`, sections 1 and 5). Collisions exchange energy and momentum and
conserve `H` (the engine books what a one-instant contact changes, section 4). The dilute
gas's equilibrium is then the canonical one, `f ∝ exp(−H/kT₀)`.

**`newtonian`** (the force `−mg` on rest mass, table time): `H = E(p) + mgz`, so

    f ∝ exp(−(E(p) + mgz)/kT₀) = exp(−E(p)/kT₀) · exp(−mgz/kT₀).

The two factors separate. The momenta are Jüttner at one `θ = kT₀/(mc²)` at every height:
the temperature is **uniform**. The momentum integral does not depend on `z`, so the
density is **exactly barometric**, `n(z) ∝ exp(−mgz/kT₀)`, at every `c`.

**`equivalence`** (the box of a floor with proper acceleration `g`, its clock the floor's
proper time): `H = (1 + gz/c²) E_loc`, `E_loc` the energy a box observer at height `z`
measures, and `√(−g₀₀) = 1 + gz/c²`. Then

    f ∝ exp(−(1 + gz/c²) E_loc/kT₀) = exp(−E_loc/kT(z)),   kT(z) = kT₀/(1 + gz/c²):

**local Jüttner** in each slab, at a temperature with `θ(z) √g₀₀(z) = θ₀`
(Tolman–Ehrenfest). The density is the Jüttner normalisation at the local temperature,
`n(z) ∝ T K₂(mc²/kT)`. The gradient is of order `g/c²`: classically both couplings are
the barometric gas.

In each slab `θ` is measured two ways, `⟨p_z v_z⟩` along the field and
`⟨p_x v_x + p_y v_y⟩/2` across it: each is `kT` for local Jüttner (or Maxwell) momenta.
The profile is averaged over 25 snapshots 2 time units apart, after 30 time units of
relaxation; its errors are the snapshots' scatter. The density
is compared with the dilute law corrected by the second virial coefficient
(`n = A f(z) e^{−2 B₂ n}`, `B₂ = (2π/3)(2r)³`), as the test does.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_bessel.h>

#include "field_gas.h"
#include "slab_profile.h"
#include "nb.h"

enum { NSNAP = 25 };
static const size_t NBALL = 800;
static const double RAD = 0.01, T_RELAX = 30.0, DT_SNAP = 2.0;

/* the gas of field_gas.h relaxed, then NSNAP snapshots */
static int run(const rc_gravity_coupling *cp, double c, double g, uint64_t seed, prof *P)
{
    field_cell = 0.05;
    memset(P, 0, sizeof *P);
    rc_sim *s = field_gas(cp, c, g, NBALL, RAD, 0.8, seed);
    if (!s)
        return -1;
    for (size_t i = 0; i < NBALL; i++) {
        rc_sim_ball b;
        rc_sim_get_ball(s, i, &b);
        P->start[(int)(b.x.z * NBIN)]++;
    }
    double h0, b0, h, booked;
    rc_sim_field_energy(s, &h0, &b0);
    int st = rc_sim_advance(s, T_RELAX, 0);
    for (int q = 0; q < NSNAP && st == RC_OK; q++) {
        st = rc_sim_advance(s, T_RELAX + DT_SNAP * (q + 1), 0);
        snapshot(s, g, isinf(c) ? 0.0 : 1.0 / (c * c), P);
    }
    rc_sim_field_energy(s, &h, &booked);
    P->eerr = fabs((h - booked) - (h0 - b0)) / fabs(h0);
    P->coll = field_collisions(s);
    rc_sim_free(&s);
    return st == RC_OK ? 0 : -1;
}

/* a slab's share of the centres' range [r, 1 - r] under the density f (Simpson) */
static void shares(double (*f)(double, const double *), const double *par, double *out)
{
    double tot = 0;
    for (int k = 0; k < NBIN; k++) {
        const double lo = fmax(k / (double)NBIN, RAD), hi = fmin((k + 1) / (double)NBIN, 1 - RAD);
        const int m = 400;
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

/* theta K2(1/theta) at theta = theta0/(1 + g z/c^2) (m = 1; par: g, theta0, 1/c^2) */
static double tolman_n(double z, const double *par)
{
    const double th = par[1] / (1 + par[0] * z * par[2]);
    return th * gsl_sf_bessel_Kn_scaled(2, 1 / th) * exp(-1 / th + 1 / par[1]);
}

/* the second virial correction (test_gravity_relax): counts per slab */
static void virial(const double *ideal, double *out)
{
    const double B2 = 2.0 * M_PI / 3.0 * pow(2 * RAD, 3), vol = 1.0 / NBIN, N = (double)NBALL;
    double A = 1.0;
    for (int it = 0; it < 200; it++) {
        double tot = 0;
        for (int k = 0; k < NBIN; k++) {
            double n = ideal[k] * N / vol;
            for (int j = 0; j < 50; j++)
                n = A * ideal[k] * N / vol * exp(-2 * B2 * n);
            out[k] = n * vol;
            tot += out[k];
        }
        A *= N / tot;
    }
}

/* weighted least-squares slope of theta (both thermometers, (z + 2 perp)/3) against z */
static void theta_slope(const prof *P, double *slope, double *err)
{
    double sw = 0, swz = 0, swzz = 0, swy = 0, swzy = 0;
    for (int k = 0; k < NBIN; k++) {
        double mz, vz, mp, vp;
        mean_err(P, 1, k, &mz, &vz);
        mean_err(P, 2, k, &mp, &vp);
        const double y = (mz + 2 * mp) / 3, v = (vz + 4 * vp) / 9, z = zmean(P, k);
        sw += 1 / v, swz += z / v, swzz += z * z / v, swy += y / v, swzy += z * y / v;
    }
    const double det = sw * swzz - swz * swz;
    *slope = (sw * swzy - swz * swy) / det;
    *err = sqrt(sw / det);
}

static void dump_profile(FILE *d, const prof *P, const double *want_n, const double *want_t)
{
    for (int k = 0; k < NBIN; k++) {
        double n, nv, tz, tzv, tp, tpv;
        mean_err(P, 0, k, &n, &nv);
        mean_err(P, 1, k, &tz, &tzv);
        mean_err(P, 2, k, &tp, &tpv);
        fprintf(d, "%g %g %g %g %g %g %g %g %g\n", zmean(P, k), n, sqrt(nv), want_n[k], tz,
                sqrt(tzv), tp, sqrt(tpv), want_t[k]);
    }
    fprintf(d, "\n\n");
}

/*md
## newtonian at c = ∞: the barometric law with a uniform temperature

`g = 0.5`, as for the `equivalence` runs below: classically both couplings are the same
parabola, so this run is also the `c = ∞` point of the gradient. The fitted `kT` is the pooled mean of the two thermometers; `χ²` of the density
has 9 degrees of freedom (10 slabs, the total fixed), each thermometer's against a
uniform `kT` likewise (the constant fitted). The start's counts against the same law show
that the gas did start off equilibrium.

@output barometric
*/
static prof Pn;
static const double GE = 0.5;

static void barometric(void)
{
    nb_section("barometric");
    const double g = GE;
    NB_CHECK(run(&rc_gravity_newtonian, INFINITY, g, 0xa01, &Pn) == 0, "the run");
    double kt_z, kt_p;
    const double chi_z = chi2_of(&Pn, 1, NULL, &kt_z), chi_p = chi2_of(&Pn, 2, NULL, &kt_p);
    const double kt = 0.5 * (kt_z + kt_p), par[2] = {g, kt};
    double sh[NBIN], want[NBIN], wt[NBIN], chi0 = 0;
    shares(baro, par, sh);
    virial(sh, want);
    for (int k = 0; k < NBIN; k++) {
        chi0 += (Pn.start[k] - want[k]) * (Pn.start[k] - want[k]) / want[k];
        wt[k] = kt;
    }
    const double chi_n = chi2_of(&Pn, 0, want, NULL);
    const double pn = gsl_cdf_chisq_Q(chi_n, NBIN - 1), pz = gsl_cdf_chisq_Q(chi_z, NBIN - 1),
                 pp = gsl_cdf_chisq_Q(chi_p, NBIN - 1), p0 = gsl_cdf_chisq_Q(chi0, NBIN - 1);
    printf("  %llu collisions; H - booked conserved to %.1e\n", (unsigned long long)Pn.coll, Pn.eerr);
    NB_CHECK(Pn.eerr < 1e-10, "H conserved (%.1e)", Pn.eerr);
    printf("  kT %.4f (along) %.4f (across)\n", kt_z, kt_p);
    printf("  n(z) barometric:  chi2 %.1f for %d, p %.3f   (the start: chi2 %.0f, p %.1e)\n",
           chi_n, NBIN - 1, pn, chi0, p0);
    printf("  kT along uniform: chi2 %.1f, p %.3f;  kT across uniform: chi2 %.1f, p %.3f\n",
           chi_z, pz, chi_p, pp);
    NB_CHECK(p0 < 1e-6, "the start is off equilibrium (p %.1e)", p0);
    NB_CHECK(pn > 1e-3, "the density is barometric (p %.3f)", pn);
    NB_CHECK(pz > 1e-3 && pp > 1e-3, "kT is uniform, both ways (p %.3f, %.3f)", pz, pp);
    FILE *d = nb_figure_begin("atmosphere-barometric");
    if (d)
        dump_profile(d, &Pn, want, wt);
    nb_figure_end(d, "atmosphere-barometric",
                  "set multiplot layout 1,2 title 'Colliding gas, newtonian coupling, c = ∞, g = 0.5: "
                  "800 balls of radius 0.01, 25 snapshots after t = 30'\n"
                  "set xlabel 'height z above the floor (box height 1)'\nset grid\n"
                  "set ylabel 'balls per slab (slab 0.1 high)'\nset key top right font ',9'\n"
                  "plot datafile u 1:2:3 w yerrorbars pt 7 lc rgb '#08519c' t 'gas (± s.e. of the mean over snapshots)', "
                  "'' u 1:4 w lp pt 6 lc rgb '#d62728' t 'barometric e^{−mgz/kT} (2nd virial)'\n"
                  "set ylabel 'kT (units of m × box height²/time²)'\nset key bottom left\n"
                  "plot datafile u 1:5:6 w yerrorbars pt 7 lc rgb '#08519c' t '<p_z v_z>', "
                  "'' u 1:7:8 w yerrorbars pt 5 lc rgb '#31a354' t '<p_⊥·v_⊥>/2', "
                  "'' u 1:9 w l lw 2 lc rgb '#d62728' t 'uniform kT (fitted)'\n"
                  "unset multiplot\n");
}

/*md
## equivalence at c = 1: Tolman–Ehrenfest

`g = 0.5`, so `gh/c² = 0.5` across the box. `θ₀` is the pooled mean of
`θ(z)(1 + gz/c²)` (the `p·v/3` thermometer), whose constancy is the first check; each
thermometer's `θ(z)` is then compared with `θ₀/(1 + gz/c²)` at the slab's mean height, and
the density with the local Jüttner normalisation `θ K₂(1/θ)`.

@output tolman
*/
static prof Pe[3]; /* c = 1, 2 (equivalence) and inf (the newtonian run: the same paths) */
static const double CS[3] = {1.0, 2.0, INFINITY};

static void tolman(void)
{
    nb_section("tolman");
    NB_CHECK(run(&rc_gravity_equivalence, 1.0, GE, 0xa02, &Pe[0]) == 0, "the run");
    const prof *P = &Pe[0];
    double th0;
    const double chi_l = chi2_of(P, 3, NULL, &th0);
    double wz[NBIN], sh[NBIN], wn[NBIN];
    for (int k = 0; k < NBIN; k++)
        wz[k] = th0 / (1 + GE * zmean(P, k));
    const double chi_z = chi2_of(P, 1, wz, NULL), chi_p = chi2_of(P, 2, wz, NULL);
    const double par[3] = {GE, th0, 1.0};
    shares(tolman_n, par, sh);
    virial(sh, wn);
    const double chi_n = chi2_of(P, 0, wn, NULL);
    double slope, serr;
    theta_slope(P, &slope, &serr);
    const double pl = gsl_cdf_chisq_Q(chi_l, NBIN - 1), pz = gsl_cdf_chisq_Q(chi_z, NBIN - 1),
                 pp = gsl_cdf_chisq_Q(chi_p, NBIN - 1), pn = gsl_cdf_chisq_Q(chi_n, NBIN - 1);
    printf("  %llu collisions; H - booked conserved to %.1e\n", (unsigned long long)P->coll, P->eerr);
    NB_CHECK(P->eerr < 1e-10, "H conserved (%.1e)", P->eerr);
    printf("  theta0 %.4f\n", th0);
    printf("  theta (1 + gz/c^2) constant: chi2 %.1f for %d, p %.3f\n", chi_l, NBIN - 1, pl);
    printf("  theta along vs Tolman:  chi2 %.1f, p %.3f;  across: chi2 %.1f, p %.3f\n", chi_z,
           pz, chi_p, pp);
    printf("  n(z) vs theta K2(1/theta): chi2 %.1f, p %.3f\n", chi_n, pn);
    printf("  d theta/dz %.4f +- %.4f (%.1f sigma from 0)\n", slope, serr, -slope / serr);
    NB_CHECK(pl > 1e-3, "theta sqrt(g00) is constant (p %.3f)", pl);
    NB_CHECK(pz > 1e-3 && pp > 1e-3, "theta(z) is Tolman's, both ways (p %.3f, %.3f)", pz, pp);
    NB_CHECK(pn > 1e-3, "the density is local Juttner's (p %.3f)", pn);
    NB_CHECK(slope < -5 * serr, "theta itself falls with height at >= 5 sigma (%.1f)", -slope / serr);
    FILE *d = nb_figure_begin("atmosphere-tolman");
    if (d)
        dump_profile(d, P, wn, wz);
    nb_figure_end(d, "atmosphere-tolman",
                  "set multiplot layout 1,2 title 'Colliding gas, equivalence coupling, c = 1, g = 0.5: "
                  "800 balls of radius 0.01, 25 snapshots after t = 30'\n"
                  "set xlabel 'height z above the floor (box height 1)'\nset grid\n"
                  "set ylabel 'balls per slab (slab 0.1 high)'\nset key top right font ',9'\n"
                  "plot datafile u 1:2:3 w yerrorbars pt 7 lc rgb '#08519c' t 'gas (± s.e. of the mean over snapshots)', "
                  "'' u 1:4 w lp pt 6 lc rgb '#d62728' t 'local Jüttner θ K_2(1/θ) (2nd virial)'\n"
                  "set ylabel 'θ = kT/mc²'\nset key top right\n"
                  "plot datafile u 1:5:6 w yerrorbars pt 7 lc rgb '#08519c' t '<p_z v_z>/mc²', "
                  "'' u 1:7:8 w yerrorbars pt 5 lc rgb '#31a354' t '<p_⊥·v_⊥>/2mc²', "
                  "'' u 1:9 w l lw 2 lc rgb '#d62728' t 'Tolman θ_0/(1 + gz/c²)'\n"
                  "unset multiplot\n");
}

/*md
## The gradient vanishes as c grows

The same `equivalence` gas at `c = 2`, beside `c = 1` from above and `c = ∞` (the
`newtonian` run of the first section: classically the two couplings have the same paths). Each slope of
`θ(z)` is set beside the slope of `θ₀/(1 + gz/c²)` fitted the same way on the same slabs
(`θ₀` each run's own). At `c = ∞` both couplings are the barometric gas and the slope is
0. The closed form's drop across the box is `θ₀ (gh/c²)/(1 + gh/c²)`, of order `g/c²`.

@output gradient
*/
static void gradient(void)
{
    nb_section("gradient");
    NB_CHECK(run(&rc_gravity_equivalence, CS[1], GE, 0xa03, &Pe[1]) == 0, "the run at c = 2");
    Pe[2] = Pn;
    FILE *d = nb_figure_begin("atmosphere-gradient");
    printf("  c      theta0    d theta/dz          closed form   pull\n");
    double chi = 0, s[3], e[3];
    for (int i = 0; i < 3; i++) {
        const prof *P = &Pe[i];
        double th0, want[NBIN];
        chi2_of(P, 3, NULL, &th0);
        const double ic2 = isinf(CS[i]) ? 0.0 : 1.0 / (CS[i] * CS[i]);
        theta_slope(P, &s[i], &e[i]);
        /* the closed form's slope on the same slabs and weights */
        prof Q = *P;
        for (int k = 0; k < NBIN; k++) {
            want[k] = th0 / (1 + GE * zmean(P, k) * ic2);
            double mz, vz, mp, vp;
            mean_err(P, 1, k, &mz, &vz);
            mean_err(P, 2, k, &mp, &vp);
            /* (the snapshots' sums replaced by the closed form's value, variances kept) */
            for (int j = 1; j <= 2; j++) {
                const double v = j == 1 ? vz : vp, S = Q.snaps;
                Q.s[j][k] = want[k] * S;
                Q.s2[j][k] = S * (v * (S - 1.0) + want[k] * want[k]);
            }
        }
        double sp, ep;
        theta_slope(&Q, &sp, &ep);
        chi += (s[i] - sp) * (s[i] - sp) / (e[i] * e[i]);
        printf("  %-5g  %.4f    %8.4f +- %.4f   %8.4f     %+.2f\n", CS[i], th0, s[i], e[i], sp,
               (s[i] - sp) / e[i]);
        if (d)
            fprintf(d, "%g %g %g %g\n", isinf(CS[i]) ? 0.0 : ic2, -s[i], e[i], -sp);
    }
    const double p = gsl_cdf_chisq_Q(chi, 3);
    printf("  slopes against the closed form: chi2 %.2f for 3 values, p %.3f\n", chi, p);
    NB_CHECK(p > 1e-3, "every slope is the closed form's (p %.3f)", p);
    NB_CHECK(fabs(s[2]) < 4 * e[2], "no gradient at c = inf (%.4f +- %.4f)", s[2], e[2]);
    NB_CHECK(-s[0] > -s[1] && s[0] < -5 * e[0], "the gradient falls from c = 1 to c = 2");
    nb_figure_end(d, "atmosphere-gradient",
                  "set xlabel '1/c² (c in box heights per unit time; 0 is c = ∞)'\n"
                  "set ylabel '−dθ/dz (per box height)'\n"
                  "set title 'Tolman gradient of the colliding gas, equivalence, g = 0.5: c = 1, 2, ∞'\n"
                  "set grid\nset key top left\nset xrange [-0.05:1.1]\n"
                  "plot datafile u 1:2:3 w yerrorbars pt 7 lc rgb '#08519c' t 'colliding gas (± s.e.)', "
                  "'' u 1:4 w lp pt 6 lc rgb '#d62728' t 'θ_0/(1 + gz/c²) fitted the same way'\n");
}

int main(int argc, char **argv)
{
    nb_init(argc, argv);
    (void)rc_test_checks, (void)rc_test_failures; /* the shared code's harness: NB_CHECK here */
    gsl_set_error_handler_off();
    barometric();
    tolman();
    gradient();
    return nb_finish();
}
