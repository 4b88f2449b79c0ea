/*md
# 8. Why the contracted disc gas is not Jüttner: the collision kernel alone

Notebook 07 found that a 2-D gas of *contracted* discs (contact frame `table`: each disc is
an ellipse, its rest radius `r` across its velocity and `r/γ` along it) settles, conserves
energy, and yet is not Jüttner: the equipartition thermometer `⟨p·v⟩/2` reads about 1.5 %
below the temperature of its energy, with too many slow and too many fast discs. Is that
the engine (a contact found late, missed or invented) or the model?

Here there is no engine at all. In the Boltzmann limit (a dilute gas) a pair `i, j`
collides with contact normal `n` at a rate per unit angle of `n`

    W(i, j, n) = max(0, −(v_j − v_i)·n) · (ρ_i(n) + ρ_j(n)),

where `ρ(n)` is the radius of curvature of a shape's boundary where its outward normal is
`n` (the Minkowski sum of two convex shapes has curvature radius `ρ_i + ρ_j` there, so
`ρ_i + ρ_j` is the length of contact circle per unit angle). For a disc `ρ = r`. For the
ellipse with semi-axes `a = r` (across v) and `b = r/γ` (along v), with support function
`h(n) = r √(1 − (v·n)²/c²)`, it is `ρ(n) = a² b² / h(n)³`.

We sample this master equation directly (Kac's stochastic model, "DSMC"): pick a random
pair and a random normal, accept with probability `W / W_max`, and collide with relcol's
own four-impulse law (`rc_law_zmf`). Snapshots are taken at equal numbers of trials, which
is equal table time for a constant majorant, as the engine's snapshots are. `N = 1000`
discs, `c = 1`, every disc starting with the same speed (γ₀ = 2.0714, the energy of
Jüttner's ⟨γ⟩ at θ = 0.75).

**What breaks.** With plain discs `ρ` is a constant and `W` depends on the velocities only
through the approach speed, which a collision reverses: the rate of a collision and of
its reverse are equal (micro-reversibility), and Jüttner is stationary. With contracted
shapes `ρ_i(n) + ρ_j(n)` depends on the velocities, and the collision changes them: the
reverse collision has a different rate, detailed balance fails, and nothing forces
Jüttner. This is the kinetic form of "a shape that changes the instant its speed
changes"; the simulation below shows it is enough to produce the whole deviation.
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_rng.h>

#include "nb.h"
#include "relcol/relcol.h"

#define N 1000
#define R 0.5
#define THETA 0.75
#define NBIN 24  /* histogram of gamma - 1 in bins of BIN_W */
#define BIN_W 0.25

/* uniform on [0, 1): GSL's Mersenne twister */
static double uniform(gsl_rng *g) { return gsl_rng_uniform(g); }

/* Radius of curvature of a disc's table-frame shape (c = 1) at outward normal n. */
static double rho(const rc_particle *a, rc_vec3 n, int contracted)
{
    if (!contracted)
        return R;
    const double M = sqrt(a->m * a->m + rc_v3_norm2(a->p));
    const double vn = rc_v3_dot(a->p, n) / M, b = R * a->m / M; /* b = r / gamma */
    const double h = R * sqrt(1.0 - vn * vn);
    return R * R * b * b / (h * h * h);
}

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
static result kac(int contracted, double per, uint64_t seed)
{
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, (unsigned long)seed);
    rc_particle *b = malloc(N * sizeof *b);
    const double g0 = (1.0 + 2.0 * THETA + 2.0 * THETA * THETA) / (1.0 + THETA);
    const double p0 = sqrt(g0 * g0 - 1.0);
    for (size_t i = 0; i < N; i += 2) { /* pairs of opposite momenta: zero total */
        const double phi = 2.0 * M_PI * uniform(g);
        b[i] = (rc_particle){1.0, rc_v3(p0 * cos(phi), p0 * sin(phi), 0.0)};
        b[i + 1] = (rc_particle){1.0, rc_v3(-p0 * cos(phi), -p0 * sin(phi), 0.0)};
    }
    rc_collision_params prm = rc_collision_params_default();
    prm.c = 1.0;
    prm.eps = 1.0;
    /* Majorant of W: |w| <= 2 (c = 1) times rho_i + rho_j <= 2 r gamma^2 (an ellipse's
     * tip). gamma is bounded only by the whole gas's energy, so a cap that holds in
     * practice (gamma^2 <= 1 + 27 theta) is used and checked at every trial: a W above
     * it marks the run invalid (th_pv = NAN fails every check below). */
    const double w_cap = 2.0 * 2.0 * R * (contracted ? 1.0 + 27.0 * THETA : 1.0);
    result res = {0};
    double s_pv = 0.0, s_pv2 = 0.0, s_g = 0.0, hist_n = 0.0;
    long snaps = 0;
    const uint64_t relax = 50 * N, total = relax + (uint64_t)(per * N);
    uint64_t done = 0, trials = 0;
    int over = 0;
    while (done < total) {
        const size_t i = (size_t)(uniform(g) * N), j = (size_t)(uniform(g) * N);
        const double phi = 2.0 * M_PI * uniform(g);
        trials++;
        if (done > relax && trials % (100 * N) == 0) { /* a snapshot */
            double spv = 0.0, sg = 0.0;
            for (size_t k = 0; k < N; k++) {
                const double M = sqrt(1.0 + rc_v3_norm2(b[k].p));
                spv += rc_v3_norm2(b[k].p) / M;
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
        const rc_vec3 n = rc_v3(cos(phi), sin(phi), 0.0);
        const double Mi = sqrt(1.0 + rc_v3_norm2(b[i].p)), Mj = sqrt(1.0 + rc_v3_norm2(b[j].p));
        const rc_vec3 w = rc_v3_sub(rc_v3_scale(1.0 / Mj, b[j].p), rc_v3_scale(1.0 / Mi, b[i].p));
        const double wn = -rc_v3_dot(w, n);
        if (wn <= 0.0)
            continue;
        const double W = wn * (rho(&b[i], n, contracted) + rho(&b[j], n, contracted));
        over |= W > w_cap;
        if (uniform(g) * w_cap >= W)
            continue;
        rc_particle a = b[i], c = b[j];
        if (rc_law_zmf.collide(&prm, &a, &c, n) != RC_OK)
            continue;
        b[i] = a;
        b[j] = c;
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

/*md
## The two kernels side by side

The same start, the same law, the same sampling; only `ρ` differs. The standard errors
treat snapshots as independent (they are not quite), so they are a rough guide.
@output kernels
*/
static void kernels(void)
{
    nb_section("kernels");
    const result s = kac(0, 100.0, 11), t = kac(1, 100.0, 11);
    printf("plain discs:      theta from <gamma> %.5f, from <p.v>/2 %.5f +- %.5f\n", s.th_g,
           s.th_pv, s.se_pv);
    printf("contracted discs: theta from <gamma> %.5f, from <p.v>/2 %.5f +- %.5f (%+.2f %%)\n",
           t.th_g, t.th_pv, t.se_pv, 100.0 * (t.th_pv / t.th_g - 1.0));
    printf("the engine's contracted gas (notebook 07, papers/relcol.md section 8): 0.7387\n");
    FILE *d = nb_figure_begin("contracted-kinetics");
    for (int k = 0; d && k < NBIN; k++) {
        const double x0 = 1.0 + k * BIN_W, x1 = x0 + BIN_W;
        fprintf(d, "%g %g %g\n", x0 + 0.5 * BIN_W - 1.0,
                s.hist[k] / (juttner_sf(s.th_g, x0) - juttner_sf(s.th_g, x1)),
                t.hist[k] / (juttner_sf(t.th_g, x0) - juttner_sf(t.th_g, x1)));
    }
    nb_figure_end(d, "contracted-kinetics",
                  "set xlabel 'γ − 1'\nset ylabel 'histogram / Jüttner(θ from ⟨γ⟩)'\n"
                  "set title 'Kac model of the 2-D disc gas, θ = 0.75'\nset grid\n"
                  "set key top left\nset yrange [0.5:*]\n"
                  "plot 1 w l lc rgb 'black' notitle, "
                  "datafile u 1:2 w lp pt 7 ps 0.6 lc rgb '#1f77b4' t 'plain discs', "
                  "'' u 1:3 w lp pt 5 ps 0.6 lc rgb '#d62728' t 'contracted discs'\n");
    NB_CHECK(fabs(s.th_pv - s.th_g) < 5.0 * s.se_pv + 1e-4,
             "plain discs: the kinetic model is Jüttner (the two thermometers agree)");
    NB_CHECK(t.th_pv < t.th_g - 10.0 * t.se_pv && t.th_pv / t.th_g - 1.0 > -0.03 &&
                 t.th_pv / t.th_g - 1.0 < -0.008,
             "contracted discs: <p.v>/2 sits 0.8-3 %% below, > 10 standard errors: no engine "
             "needed for the deviation");
    NB_CHECK(fabs(t.th_pv - 0.7387) < 0.004,
             "and it is the engine's value (0.7387) to within the engine's dense-gas residual");
    const double slow = t.hist[0] / (juttner_sf(t.th_g, 1.0) - juttner_sf(t.th_g, 1.0 + BIN_W));
    NB_CHECK(slow > 1.15, "too many slow discs, as in the engine (first bin %.2f x Jüttner)",
             slow);
}

/*md
## Reading

The plain-disc kernel gives Jüttner; the contracted kernel alone, with no positions, no
contact detection and no overlaps, gives the engine's temperature deficit and the shape of
its histogram (too many slow and fast discs). The deviation grows with θ (about −0.1 % at
θ = 0.1, −0.6 % at 0.3, −1.6 % at 0.75 and −1.9 % at 2, measured with this model at
`N = 2000`, 300 collisions per disc); the engine's dense gas adds a residual of 10–20 %
of it. So the −1.5 % is a property of the model — contracted shapes in the table frame
collide at velocity-dependent rates that break detailed balance — not a fault of the
engine. (An all-pairs audit of the engine's contacts in the same gas, run alongside this
work, found one real fault — pairs whose bounding circles overlap while their centres
part could meet unseen, about one contact in 3000 — fixed, and it did not move θ.)
*/
int main(int argc, char **argv)
{
    nb_init(argc, argv);
    kernels();
    return nb_finish();
}
