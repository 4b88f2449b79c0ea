/*md
# 9. A gas in a uniform gravitational field: hotter lower down

In special relativity gravity couples to energy, not to rest mass. A gas at rest in a static
field then has a temperature that falls with height. Tolman and Ehrenfest (1930) showed that
in equilibrium `T(z) √(−g₀₀(z)) = const`. For the field of a uniformly accelerated box,
`√(−g₀₀) = 1 + gz/c²` exactly. The gradient is of order `g/c²`: it vanishes as `c → ∞`, where
the gas is the classical barometric one, with `n(z) ∝ exp(−mgz/kT)` and a uniform `T`.

relcol offers two couplings of a ball to a uniform field (`relcol/gravity.h`; the
derivations are in `papers/gravity.md`). `newtonian` is the force `−mg` on rest mass in
the table frame, with the conserved `H = E + mgz`. Its equilibrium has a uniform
temperature and exactly the barometric density, at every `c`. `equivalence` is the box
frame of a floor accelerated at `g` (Rindler), with the conserved `H = (1 + gz/c²) E`. Its
equilibrium is local Jüttner at `θ(z) = θ₀/(1 + gz/c²)`, with the density
`n(z) ∝ θ K₂(1/θ)`.

This notebook draws 20 000 balls from each equilibrium (rest mass 1, a box of height 1,
`g = 0.5`, `kT₀ = 1` at the floor in the table's units, so `θ₀ = kT₀/(mc²) = 1/c²`). It lets them fly on the coupling's exact
paths between an elastic floor and ceiling for 7.3 box times, then reads the profiles.
There are no ball–ball collisions. A dilute gas keeps its equilibrium if and only if its
paths and walls are right. That is what this checks; relaxation to the equilibrium needs
collisions, which the engine will add. The shared code is
`tests/gravity/gravity_gas.h`, which `test_gravity_equilibrium` uses too.
*/
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>

#include "gravity_gas.h"
#include "nb.h"

static const double G = 0.5;
static const double CS[] = {1.0, 1.5, 2.0, 3.0, 5.0, INFINITY};
enum { NC = sizeof CS / sizeof CS[0] };

static model make(int equivalence, double c)
{
    model md = {equivalence ? &rc_gravity_equivalence : &rc_gravity_newtonian, {G, 2, 0.0},
                equivalence};
    rc_inv_c2(c, &md.f.inv_c2);
    return md;
}

/*md
## The temperature profile

For each `c`, each height bin gets the `p·v` thermometer (`⟨p·v⟩ = 3kT` for Jüttner, any
`c`), with its standard error. The prediction beside it is the bin's density-weighted mean of
`kT(z) = kT₀/(1 + gz/c²)`. The `newtonian` gas at `c = 1` is drawn too: at the same `g` and `c` it has no
gradient.

@output profile
*/
static grav_profile prof[NC], newton1;

static void profiles(void)
{
    nb_section("profile");
    FILE *d = nb_figure_begin("gravity-profile");
    printf("  c      g h/c^2   kT(bottom bin)      kT(top bin)       chi2/dof vs Tolman\n");
    for (int k = 0; k < NC; k++) {
        model md = make(1, CS[k]);
        grav_measure(&md, 0x900 + (uint64_t)k, NBALL, 7.3, &prof[k]);
        double chi = 0;
        for (int b = 0; b < NB; b++) {
            const double dt = prof[k].theta[b] - prof[k].expect_theta[b];
            chi += dt * dt / prof[k].theta_var[b];
        }
        printf("  %-5g  %-8.4g  %.4f +- %.4f   %.4f +- %.4f   %.2f\n", CS[k], G * md.f.inv_c2,
               prof[k].theta[0], sqrt(prof[k].theta_var[0]), prof[k].theta[NB - 1],
               sqrt(prof[k].theta_var[NB - 1]), chi / NB);
        NB_CHECK(gsl_cdf_chisq_Q(chi, NB) > 1e-3,
                 "c = %g: kT(z) fits Tolman-Ehrenfest (chi2 %.1f for %d bins)", CS[k], chi, NB);
        if (d && (k == 0 || k == 2 || k == NC - 1)) {
            fprintf(d, "# c = %g\n", CS[k]);
            for (int b = 0; b < NB; b++)
                fprintf(d, "%g %g %g %g\n", prof[k].z[b], prof[k].theta[b],
                        sqrt(prof[k].theta_var[b]), prof[k].expect_theta[b]);
            fprintf(d, "\n\n");
        }
    }
    model mn = make(0, 1.0);
    grav_measure(&mn, 0x9ff, NBALL, 7.3, &newton1);
    if (d) {
        for (int b = 0; b < NB; b++)
            fprintf(d, "%g %g %g %g\n", newton1.z[b], newton1.theta[b],
                    sqrt(newton1.theta_var[b]), newton1.expect_theta[b]);
        fprintf(d, "\n\n");
    }
    nb_figure_end(d, "gravity-profile",
                  "set xlabel 'height z above the floor (box height 1)'\n"
                  "set ylabel 'local temperature kT (p·v/3, units of m × box height²/box time²)'\n"
                  "set title 'Dilute gas at rest in a uniform field, g = 0.5, kT = 1 at the floor'\n"
                  "set grid\nset key bottom left\nset yrange [0.6:1.1]\n"
                  "plot datafile index 0 u 1:2:3 w yerrorbars pt 7 lc rgb '#08519c' t 'equivalence, c = 1', "
                  "'' index 0 u 1:4 w l lw 2 lc rgb '#08519c' t 'Tolman: kT_0/(1 + gz/c²), c = 1', "
                  "'' index 1 u 1:2:3 w yerrorbars pt 5 lc rgb '#6baed6' t 'equivalence, c = 2', "
                  "'' index 1 u 1:4 w l lw 2 lc rgb '#6baed6' t 'Tolman, c = 2', "
                  "'' index 2 u 1:2:3 w yerrorbars pt 9 lc rgb 'black' t 'equivalence, c = ∞', "
                  "'' index 3 u 1:2:3 w yerrorbars pt 13 lc rgb '#d62728' t 'newtonian (force on rest mass), c = 1', "
                  "'' index 3 u 1:4 w l lw 2 dt 2 lc rgb '#d62728' t 'uniform kT_0'\n");
    double slope, err;
    grav_slope(newton1.z, newton1.theta, newton1.theta_var, &slope, &err);
    NB_CHECK(fabs(slope) < 4 * err, "newtonian at c = 1 has no gradient: %.4f +- %.4f", slope, err);
}

/*md
## The gradient against c

The slope `dθ/dz` of each profile is a weighted least-squares line through the bins. The
prediction is the same line through the predicted bin means, with the same weights. The
exact form `kT₀/(1 + gz/c²)` gives a slope `−kT₀ g/c²` at the floor. Its order in `c` is −2,
so the gradient falls as `c⁻²`: at `c = 5` it is 4 % of the `c = 1` one, beside errors
of about 1.3 % of `kT₀` per unit height here.

@output gradient
*/
static void gradient(void)
{
    nb_section("gradient");
    FILE *d = nb_figure_begin("gravity-gradient");
    printf("  c      measured d(kT)/dz       predicted    pull\n");
    double chi = 0;
    for (int k = 0; k < NC; k++) {
        double s, e, sp, ep;
        grav_slope(prof[k].z, prof[k].theta, prof[k].theta_var, &s, &e);
        grav_slope(prof[k].z, prof[k].expect_theta, prof[k].theta_var, &sp, &ep);
        printf("  %-5g  %8.4f +- %.4f     %8.4f     %+.2f\n", CS[k], s, e, sp, (s - sp) / e);
        chi += (s - sp) * (s - sp) / (e * e);
        if (d && isfinite(CS[k]))
            fprintf(d, "%g %g %g %g\n", CS[k], -s, e, -sp);
    }
    NB_CHECK(gsl_cdf_chisq_Q(chi, NC) > 1e-3, "every measured gradient is the predicted one "
             "(chi2 %.1f for %d values of c)", chi, NC);
    double s0, e0;
    grav_slope(prof[0].z, prof[0].theta, prof[0].theta_var, &s0, &e0);
    NB_CHECK(s0 < -5 * e0, "at c = 1 the gradient is resolved: %.4f +- %.4f", s0, e0);
    /* the order of the predicted gradient, between c = 40 and 80: -2 (the closed form's) */
    const double a = G / 1600.0, b = G / 6400.0;
    const double order = log((a / (1 + a)) / (b / (1 + b))) / log(40.0 / 80.0);
    NB_CHECK(fabs(order + 2.0) < 1e-3, "the Tolman drop across the box falls as c^%.4f", order);
    nb_figure_end(d, "gravity-gradient",
                  "set logscale xy\nset xlabel 'speed of light c (box heights per box time)'\n"
                  "set ylabel '−d(kT)/dz (per box height)'\n"
                  "set title 'Tolman–Ehrenfest gradient of a gas at rest, g = 0.5'\nset grid\n"
                  "set key top right\nset xrange [0.8:6]\nset xtics (1, 1.5, 2, 3, 5)\n"
                  "plot datafile u 1:2:3 w yerrorbars pt 7 lc rgb '#08519c' t 'measured (20 000 balls)', "
                  "'' u 1:4 w lp pt 6 lc rgb '#d62728' t 'kT_0/(1 + gz/c²), fitted the same way', "
                  "0.5/x**2 w l dt 2 lc rgb 'gray40' t 'g/c² (order −2)'\n");
}

int main(int argc, char **argv)
{
    nb_init(argc, argv);
    (void)rc_test_checks, (void)rc_test_failures; /* the shared code's harness: NB_CHECK here */
    gsl_set_error_handler_off();
    profiles();
    gradient();
    return nb_finish();
}
