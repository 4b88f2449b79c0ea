/*md
# 8. Why the contracted disc gas is not Jüttner: the gain–loss balance

Notebook 07 found that a 2-D gas of *contracted* discs (contact frame `table`: each disc is
an ellipse, its rest radius `r` across its velocity and `r/γ` along it) settles, conserves
energy, and yet is not Jüttner: the equipartition thermometer `⟨p·v⟩/2` reads about 1.5 %
below the temperature of its energy, with too many slow and too many fast discs, while
uncontracted discs (`sphere`) are Jüttner. Is that the engine or the model? Here there is
no engine: only the Boltzmann collision integral of the dilute gas.

**The kernel.** A pair with momenta `p0, p1` and contact normal `n` (from ball 0 to ball 1)
approaches when `(v0 − v1)·n > 0`. Seen from ball 0 the two rigid shapes translate, and
ball 1's centre crosses the boundary of the Minkowski sum of the shapes, whose length per
unit angle of its normal is `ρ0(n) + ρ1(n)` (`ρ`: a shape's radius of curvature where its
outward normal is `n`). So per unit table time and unit angle of `n`

    W(p0, p1, n) = (ρ0(n) + ρ1(n)) · max(0, (v0 − v1)·n).

For a disc `ρ = r`. For the table frame's ellipse, with support function
`h(n) = r √(1 − (v·n)²/c²)`, `ρ(n) = r² (r/γ)² / h(n)³`. The `zmf` frame finds the contact
between the shapes contracted in the pair's zero-momentum frame: its kernel is the same
formula there (starred), carried to the table by the invariance of the number of
collisions per unit volume and time (a beam's density is proportional to its energy):
`W = (E0* E1* / (E0 E1)) (ρ0*(n*) + ρ1*(n*)) max(0, (v0* − v1*)·n*)`. Each collision is
relcol's elastic four-impulse law along `n` (for `zmf`, along the normal whose four-vector
is the boost of `(0, n*)`), a map `T` of `(p0, p1)` that at fixed `n` is an involution.
The three kernels are in `apps/gas/kinetic.h`.

**Gain and loss.** The loss of momentum `p0` and its gain are

    L(p0) = f(p0) ∫d²p1 f(p1) ∫dn W(p0, p1, n)
    G(p0) = ∫d²p1 ∫dn W(T(p0, p1), n) f(T0) f(T1) |∂T/∂(p0, p1)|,

the gain written by substituting the pre-collision states `T(p0, p1)`, which the collision
sends to `(p0, p1)`. Jüttner, `f ∝ e^(−E/kT)`, is stationary if `G = L`. Since energy is
conserved, `f(T0) f(T1) = f(p0) f(p1)`; what remains is whether `W(T) |∂T/∂p|` is the rate
`W` of the reverse orientation. Classically `|∂T/∂p| = 1` and a collision reverses the
approach speed. At finite `c` neither holds.

## 1. A collision does not reverse the approach speed

Pairs drawn from the 2-D Jüttner law at θ = 0.75 (`c = 1`), each with a normal drawn with
the sphere kernel's weight (a collision that happens), collided; the ratio of the
separation speed after to the approach speed before:
@output approach
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_sort.h>

#include "kinetic.h"
#include "nb.h"
#include "relcol/relcol.h"

#define N 1000
#define R 0.5
#define THETA 0.75
#define NBIN 24 /* histogram of gamma - 1 in bins of BIN_W */
#define BIN_W 0.25

/* A momentum from the 2-D Jüttner law at THETA (m = c = 1): x = E - 1 has density
 * (1 + x) e^(-x/theta) / (theta (1 + theta)), a Gamma(1, theta) with weight 1/(1 + theta)
 * and a Gamma(2, theta) with weight theta/(1 + theta); the direction is uniform. */
static rc_vec3 juttner_p(gsl_rng *g)
{
    const double x = gsl_ran_gamma(g, gsl_rng_uniform(g) < 1.0 / (1.0 + THETA) ? 1.0 : 2.0,
                                   THETA);
    const double s = sqrt(x * (x + 2.0)), a = 2.0 * M_PI * gsl_rng_uniform(g);
    return rc_v3(s * cos(a), s * sin(a), 0.0);
}

static double approach(rc_vec3 p0, rc_vec3 p1, rc_vec3 n)
{
    return rc_v3_dot(p0, n) / kn_energy(p0) - rc_v3_dot(p1, n) / kn_energy(p1);
}

static void approach_speed(gsl_rng *g)
{
    nb_section("approach");
    enum { M = 100000 };
    static double ratio[M];
    double worst = 0.0;
    int m = 0;
    while (m < M) {
        const rc_vec3 p0 = juttner_p(g), p1 = juttner_p(g);
        const double phi = 2.0 * M_PI * gsl_rng_uniform(g);
        const rc_vec3 n = rc_v3(cos(phi), sin(phi), 0.0);
        const double a = approach(p0, p1, n);
        /* accept with the sphere kernel's weight a / 2 (a <= 2 at c = 1) */
        if (!(a > 0.0) || gsl_rng_uniform(g) * 2.0 >= a)
            continue;
        rc_vec3 q0 = p0, q1 = p1;
        if (kn_collide(KN_SPHERE, &q0, &q1, phi) != RC_OK)
            continue;
        const double b = -approach(q0, q1, n);
        ratio[m++] = b / a;
        const double E = kn_energy(p0) * kn_energy(p1), F = kn_energy(q0) * kn_energy(q1);
        worst = fmax(worst, fabs(b * F / (a * E) - 1.0));
    }
    gsl_sort(ratio, 1, M);
    printf("after/before approach speed over %d collisions: min %.3f, 1 %% %.3f, median "
           "%.4f, 99 %% %.3f, max %.3f\n", M, ratio[0], ratio[M / 100], ratio[M / 2],
           ratio[M - M / 100], ratio[M - 1]);
    printf("E0 E1 x approach speed, after / before: 1 to %.1e\n", worst);
    NB_CHECK(ratio[0] < 0.85 && ratio[M - 1] > 1.5,
             "the approach speed is not reversed: it shrinks and grows by tens of percent");
    NB_CHECK(worst < 1e-12, "E0 E1 (v0 - v1).n is reversed exactly (to round-off)");
}

/*md
What the law reverses is not the velocity difference but `E0 E1 (v0 − v1)·n =
E1 p0·n − E0 p1·n`. With the totals `Et = E0 + E1` and `Pn = (p0 + p1)·n` conserved it is
`A = Et p0·n − E0 Pn`; the law's impulse `J n` with `J = −2 A Et / (Et² − Pn²)` changes
`E0` by `J Pn / Et` (its four-impulse `J (u·n, n)` is orthogonal to the total
four-momentum), so `A' = A + J (Et² − Pn²)/Et = −A`: exactly reversed, as printed.

## 2. The Jacobian of the collision map is E0′E1′/(E0 E1)

The map keeps the Lorentz-invariant measure `d²p0/E0 · d²p1/E1`: written as the total
four-momentum times the relative direction in the zero-momentum frame, the collision
fixes the first and reflects the second. So `d²p0′ d²p1′ = (E0′E1′/(E0 E1)) d²p0 d²p1`.
Measured by central differences of the map (four momentum components, step `1e-5`):
@output jacobian
*/
static void jacobian(gsl_rng *g)
{
    nb_section("jacobian");
    const double h = 1e-5;
    double worst = 0.0, lo = INFINITY, hi = 0.0;
    for (int k = 0; k < 3; k++)
        for (int t = 0; t < 300; t++) {
            const rc_vec3 p0 = juttner_p(g), p1 = juttner_p(g);
            const double phi = 2.0 * M_PI * gsl_rng_uniform(g);
            double m[16], x[4] = {p0.x, p0.y, p1.x, p1.y};
            rc_vec3 q0 = p0, q1 = p1;
            kn_collide((kn_kernel)k, &q0, &q1, phi);
            for (int j = 0; j < 4; j++) {
                double y[2][4];
                for (int sg = 0; sg < 2; sg++) {
                    double z[4] = {x[0], x[1], x[2], x[3]};
                    z[j] += sg ? -h : h;
                    rc_vec3 a = rc_v3(z[0], z[1], 0.0), b = rc_v3(z[2], z[3], 0.0);
                    kn_collide((kn_kernel)k, &a, &b, phi);
                    y[sg][0] = a.x, y[sg][1] = a.y, y[sg][2] = b.x, y[sg][3] = b.y;
                }
                for (int i = 0; i < 4; i++)
                    m[i * 4 + j] = (y[0][i] - y[1][i]) / (2.0 * h);
            }
            gsl_matrix_view mv = gsl_matrix_view_array(m, 4, 4);
            gsl_permutation *perm = gsl_permutation_alloc(4);
            int sgn;
            gsl_linalg_LU_decomp(&mv.matrix, perm, &sgn);
            const double det = fabs(gsl_linalg_LU_det(&mv.matrix, sgn));
            gsl_permutation_free(perm);
            const double want = kn_energy(q0) * kn_energy(q1) / (kn_energy(p0) * kn_energy(p1));
            worst = fmax(worst, fabs(det / want - 1.0));
            lo = fmin(lo, det);
            hi = fmax(hi, det);
        }
    printf("|det dT/dp| over 900 collisions (3 kernels): from %.3f to %.3f; against "
           "E0'E1'/(E0 E1): 1 to %.1e\n", lo, hi, worst);
    NB_CHECK(worst < 1e-7, "the Jacobian is E0'E1'/(E0 E1) (to the differences' error)");
    NB_CHECK(lo < 0.9 && hi > 1.1, "and it is not 1");
}

/*md
## 3. The two effects cancel for discs, and for the zmf kernel; not for the ellipses

For discs `W = 2r · (approach speed)`, so `W E0 E1` is `2r |A|`, unchanged by the
collision: `W(T) E0′E1′ = W E0 E1`, i.e. `W(T) |∂T/∂p| = W` — the faster or slower
separation is exactly compensated by the phase-space volume the map stretches or
squeezes, and `G = L` at every momentum. The zmf kernel is `E0* E1* (ρ0* + ρ1*) ×
(ZMF approach speed) / (E0 E1)`: in the zero-momentum frame the collision keeps each
energy and reflects the momenta's `n*`-components, so `E0*`, `E1*`, the ZMF approach speed
and the curvatures `ρ*(n*)` (which depend on `(v*·n*)²`) are all unchanged — again
`W E0 E1` is invariant and `G = L`. For the table frame's ellipses `ρ0(n) + ρ1(n)` depends
on the velocities the collision changes: nothing compensates the Jacobian, and `G ≠ L`.

`(G − L)/L` on the exact 2-D Jüttner law at θ = 0.75, evaluated by one midpoint rule for
both integrals (`kn_gain_loss`; where the kernel balances, the two agree node by node):
@output balance
*/
static void balance(void)
{
    nb_section("balance");
    FILE *d = nb_figure_begin("gain-loss");
    double worst[3] = {0, 0, 0}, tlo = INFINITY, thi = -INFINITY;
    for (int i = 0; i <= 20; i++) {
        const double gam = 1.0 + 0.02 + 7.0 * i / 20.0;
        double dv[3];
        for (int k = 0; k < 3; k++) {
            double G, L;
            kn_gain_loss((kn_kernel)k, R, THETA, sqrt(gam * gam - 1.0), 32, 32, 48, &G, &L);
            dv[k] = (G - L) / L;
            worst[k] = fmax(worst[k], fabs(dv[k]));
        }
        tlo = fmin(tlo, dv[KN_TABLE]);
        thi = fmax(thi, dv[KN_TABLE]);
        if (d)
            fprintf(d, "%g %g %g %g\n", gam, dv[0], dv[1], dv[2]);
        if (i % 4 == 0)
            printf("gamma %.2f: (G - L)/L  sphere %+.1e  table %+.4f  zmf %+.1e\n", gam,
                   dv[KN_SPHERE], dv[KN_TABLE], dv[KN_ZMF]);
    }
    nb_figure_end(d, "gain-loss",
                  "set xlabel 'γ'\nset ylabel '(G − L)/L'\nset grid\nset key top left\n"
                  "set title 'Boltzmann gain − loss on the 2-D Jüttner law, θ = 0.75'\n"
                  "plot 0 w l lc rgb 'black' notitle, "
                  "datafile u 1:3 w lp pt 5 ps 0.6 lc rgb '#d62728' t 'table (contracted)', "
                  "'' u 1:2 w lp pt 7 ps 0.6 lc rgb '#1f77b4' t 'sphere (discs)', "
                  "'' u 1:4 w lp pt 9 ps 0.6 lc rgb '#2ca02c' t 'zmf'\n");
    printf("largest |G - L|/L: sphere %.1e, zmf %.1e; table from %+.3f to %+.3f\n",
           worst[KN_SPHERE], worst[KN_ZMF], tlo, thi);
    NB_CHECK(worst[KN_SPHERE] < 1e-12 && worst[KN_ZMF] < 1e-12,
             "sphere and zmf kernels: gain = loss on Jüttner, to round-off");
    NB_CHECK(tlo < -0.03 && thi > 0.1, "table kernel: out of balance by percents both ways");
}

/*md
The table kernel over-fills the slow and the fast momenta and under-fills those between:
the engine's histogram pattern (notebook 07). Where its stationary state lies is not
given by this balance; for that we sample the master equation.

## 4. What the imbalance does: Kac's model of the dilute gas

We sample the master equation directly (Kac's stochastic model, "DSMC"): pick a random
pair and a random normal parameter, accept with probability `W / W_max`, and collide.
Snapshots are taken at equal numbers of trials, which is equal table time for a constant
majorant, as the engine's snapshots are. `N = 1000` discs, `c = 1`, every disc starting
with the same speed (γ₀ = 2.0714, the energy of Jüttner's ⟨γ⟩ at θ = 0.75). The standard
errors treat snapshots as independent (they are not quite), so they are a rough guide.
@output kernels
*/
typedef struct result {
    double th_g, th_pv, se_pv; /* theta from <gamma> and from <p.v>/2 (standard error) */
    double hist[NBIN];         /* fraction of discs per bin over all snapshots */
} result;

/* 2-D Juttner: <gamma> = (1 + 2 t + 2 t^2)/(1 + t), inverted; P(gamma > x) =
 * (x + t) e^(-(x-1)/t) / (1 + t). */
static double theta_from_gamma(double g)
{
    return (-(2.0 - g) + sqrt((2.0 - g) * (2.0 - g) - 8.0 * (1.0 - g))) / 4.0;
}

static double juttner_sf(double t, double x) { return (x + t) * exp(-(x - 1.0) / t) / (1.0 + t); }

/* Kac's model: `per` accepted collisions per disc after 50 per disc to relax. */
static result kac(kn_kernel kern, double per, uint64_t seed)
{
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, (unsigned long)seed);
    rc_vec3 *b = malloc(N * sizeof *b);
    const double g0 = (1.0 + 2.0 * THETA + 2.0 * THETA * THETA) / (1.0 + THETA);
    const double p0 = sqrt(g0 * g0 - 1.0);
    for (size_t i = 0; i < N; i += 2) { /* pairs of opposite momenta: zero total */
        const double phi = 2.0 * M_PI * gsl_rng_uniform(g);
        b[i] = rc_v3(p0 * cos(phi), p0 * sin(phi), 0.0);
        b[i + 1] = rc_v3_scale(-1.0, b[i]);
    }
    /* Majorant of W: the approach speed (times the Moller factor for zmf) is <= 2 (c = 1),
     * rho_i + rho_j <= 2 r gamma^2 (an ellipse's tip). gamma is bounded only by the whole
     * gas's energy, so a cap that holds in practice (gamma^2 <= 1 + 27 theta) is used and
     * checked at every trial: a W above it marks the run invalid (th_pv = NAN fails every
     * check below). */
    const double w_cap = 2.0 * 2.0 * R * (kern == KN_SPHERE ? 1.0 : 1.0 + 27.0 * THETA);
    result res = {0};
    double s_pv = 0.0, s_pv2 = 0.0, s_g = 0.0, hist_n = 0.0;
    long snaps = 0;
    const uint64_t relax = 50 * N, total = relax + (uint64_t)(per * N);
    uint64_t done = 0, trials = 0;
    int over = 0;
    while (done < total) {
        const size_t i = (size_t)(gsl_rng_uniform(g) * N), j = (size_t)(gsl_rng_uniform(g) * N);
        const double phi = 2.0 * M_PI * gsl_rng_uniform(g);
        trials++;
        if (done > relax && trials % (100 * N) == 0) { /* a snapshot */
            double spv = 0.0, sg = 0.0;
            for (size_t k = 0; k < N; k++) {
                const double M = kn_energy(b[k]);
                spv += rc_v3_norm2(b[k]) / M;
                sg += M;
                const int bin = (int)((M - 1.0) / BIN_W);
                if (bin < NBIN)
                    res.hist[bin] += 1.0;
            }
            hist_n += N;
            s_pv += spv / N;
            s_pv2 += (spv / N) * (spv / N);
            s_g += sg / N;
            snaps++;
        }
        if (i == j)
            continue;
        const double W = kn_rate(kern, R, b[i], b[j], phi);
        if (!(W > 0.0))
            continue;
        over |= W > w_cap;
        if (gsl_rng_uniform(g) * w_cap >= W)
            continue;
        if (kn_collide(kern, &b[i], &b[j], phi) != RC_OK)
            continue;
        done++;
    }
    free(b);
    gsl_rng_free(g);
    const double mpv = s_pv / snaps;
    res.th_pv = mpv / 2.0;
    res.se_pv = sqrt(fmax(0.0, s_pv2 / snaps - mpv * mpv) / snaps) / 2.0;
    res.th_g = theta_from_gamma(s_g / snaps);
    for (int k = 0; k < NBIN; k++)
        res.hist[k] /= hist_n;
    if (over)
        res.th_pv = NAN; /* the majorant did not hold: the sampling is wrong */
    return res;
}

static void kernels(void)
{
    nb_section("kernels");
    result r[3];
    for (int k = 0; k < 3; k++) {
        r[k] = kac((kn_kernel)k, 100.0, 11);
        printf("%-6s kernel: theta from <gamma> %.5f, from <p.v>/2 %.5f +- %.5f (%+.2f %%)\n",
               kn_kernel_name[k], r[k].th_g, r[k].th_pv, r[k].se_pv,
               100.0 * (r[k].th_pv / r[k].th_g - 1.0));
    }
    printf("the engine's contracted gas (notebook 07, papers/relcol.md section 8): 0.7387\n");
    const result s = r[KN_SPHERE], t = r[KN_TABLE], z = r[KN_ZMF];
    FILE *d = nb_figure_begin("contracted-kinetics");
    for (int k = 0; d && k < NBIN; k++) {
        const double x0 = 1.0 + k * BIN_W, x1 = x0 + BIN_W;
        fprintf(d, "%g %g %g %g\n", x0 + 0.5 * BIN_W - 1.0,
                s.hist[k] / (juttner_sf(s.th_g, x0) - juttner_sf(s.th_g, x1)),
                t.hist[k] / (juttner_sf(t.th_g, x0) - juttner_sf(t.th_g, x1)),
                z.hist[k] / (juttner_sf(z.th_g, x0) - juttner_sf(z.th_g, x1)));
    }
    nb_figure_end(d, "contracted-kinetics",
                  "set xlabel 'γ − 1'\nset ylabel 'histogram / Jüttner(θ from ⟨γ⟩)'\n"
                  "set title 'Kac model of the 2-D disc gas, θ = 0.75'\nset grid\n"
                  "set key top left\nset yrange [0.5:*]\n"
                  "plot 1 w l lc rgb 'black' notitle, "
                  "datafile u 1:2 w lp pt 7 ps 0.6 lc rgb '#1f77b4' t 'sphere (discs)', "
                  "'' u 1:3 w lp pt 5 ps 0.6 lc rgb '#d62728' t 'table (contracted)', "
                  "'' u 1:4 w lp pt 9 ps 0.6 lc rgb '#2ca02c' t 'zmf'\n");
    NB_CHECK(fabs(s.th_pv - s.th_g) < 5.0 * s.se_pv + 1e-4,
             "sphere kernel: Jüttner (the two thermometers agree)");
    NB_CHECK(fabs(z.th_pv - z.th_g) < 5.0 * z.se_pv + 1e-4,
             "zmf kernel: Jüttner (the two thermometers agree)");
    NB_CHECK(t.th_pv < t.th_g - 10.0 * t.se_pv && t.th_pv / t.th_g - 1.0 > -0.03 &&
                 t.th_pv / t.th_g - 1.0 < -0.008,
             "table kernel: <p.v>/2 sits 0.8-3 %% below, > 10 standard errors: no engine "
             "needed for the deviation");
    NB_CHECK(fabs(t.th_pv - 0.7387) < 0.004,
             "and it is the engine's value (0.7387) to within the engine's dense-gas residual");
    const double slow = t.hist[0] / (juttner_sf(t.th_g, 1.0) - juttner_sf(t.th_g, 1.0 + BIN_W));
    NB_CHECK(slow > 1.15, "too many slow discs, as in the engine (first bin %.2f x Jüttner)",
             slow);
}

/*md
## Reading

A collision at finite `c` changes the approach speed, and the collision map changes the
momentum-space volume by `E0′E1′/(E0 E1)`. For uncontracted discs the two effects cancel
exactly, because the rate times `E0 E1` is unchanged by the collision; for the zmf
kernel they cancel too, because everything the rate depends on is unchanged in the pair's
zero-momentum frame. Both balance gain and loss on Jüttner, and their Kac gases are
Jüttner. For the table frame's ellipses the curvature at the contact, `ρ0(n) + ρ1(n)`,
depends on the velocities the collision changes, the cancellation fails, and the Kac gas
settles off Jüttner with the engine's temperature deficit and histogram, with no
positions, contact detection or overlaps. The deficit grows with θ (about −0.1 % at
θ = 0.1, −0.6 % at 0.3, −1.6 % at 0.75 and −1.9 % at 2, measured with this model at
`N = 2000`, 300 collisions per disc) and stays at the lowest packings of the engine's gas
(`tests/gas2d/test_gas2d_dilute.c`). So the −1.5 % is a property of the model — contracted
shapes decided in the table frame — not a fault of the engine, and `relcol-gas` defaults
to uncontracted discs, whose gas is Jüttner at every density. The zmf kernel's Kac gas
is Jüttner, but the engine's zmf gas is not at any packing measured (3-D, packing 0.01,
θ = 1, N = 1000, issue 36's run: θ_pv − θ_γ = +0.00044 ± 0.00006): the excluded area of two contracted shapes depends
on their velocities, and the one-instant velocity change adds to it
(papers/finite-density.md).
*/
int main(int argc, char **argv)
{
    nb_init(argc, argv);
    gsl_set_error_handler_off();
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, 8);
    approach_speed(g);
    jacobian(g);
    balance();
    kernels();
    gsl_rng_free(g);
    return nb_finish();
}
