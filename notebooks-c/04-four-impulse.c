/*md
# 4. The four-impulse law in 2-D and 3-D

relcol's `zmf` law (`papers/zmf-law.md`) applies to ball 0 the four-impulse `J q`,
`q = ((u·n)/c², n)`, with `J = −(1 + ε)(p₀·n − M₀ u·n)/(1 − (u·n)²/c²)`. This notebook
checks its claims numerically on oblique collisions in 2-D and 3-D:

1. total energy and momentum are conserved;
2. in the pair's zero-momentum frame (ZMF) each ball keeps its energy, its momentum along the
   ZMF normal `n̂` is scaled by `−ε`, and its tangential momentum is unchanged;
3. the rest masses rise as `m'² = m² + (1 − ε²)(p̄·n̂)²/c²`, with `p̄` the ZMF momentum.

The ZMF normal is the spatial part of `q` boosted into the ZMF, normalised.
*/
#include <math.h>
#include <stdio.h>

#include "nb.h"
#include "relcol/relcol.h"

/*md
## One oblique 3-D collision at `c = 1`, `ε = 0.5`
@output one
*/
typedef struct {
    rc_particle a, b; /* before */
    rc_particle a1, b1; /* after */
    rc_vec3 n;
    double k, eps;
} collision;

static collision make(rc_vec3 v0, rc_vec3 v1, double m0, double m1, rc_vec3 n, double k, double eps)
{
    collision C = {{m0, {0, 0, 0}}, {m1, {0, 0, 0}}, {0, {0, 0, 0}}, {0, {0, 0, 0}}, n, k, eps};
    rc_momentum_from_velocity(m0, v0, k, &C.a.p);
    rc_momentum_from_velocity(m1, v1, k, &C.b.p);
    C.a1 = C.a;
    C.b1 = C.b;
    rc_collision_params prm = rc_collision_params_default();
    prm.c = (k > 0.0 ? 1.0 / sqrt(k) : INFINITY) /* the c of 1/c^2 = k */;
    prm.eps = eps;
    rc_collide(&rc_law_zmf, &prm, &C.a1, &C.b1, n);
    return C;
}

/* ZMF quantities of a particle: energy (as mass) and momentum components along/across nhat */
typedef struct {
    double Mbar, pn;
    rc_vec3 pt;
} zmf_view;

static zmf_view view(const rc_particle *x, rc_vec3 u, rc_vec3 nhat, double k)
{
    rc_four P = rc_particle_four(x, k);
    rc_boost(u, k, &P);
    zmf_view z = {P.t, rc_v3_dot(P.x, nhat), rc_v3_axpy(P.x, -rc_v3_dot(P.x, nhat), nhat)};
    return z;
}

static rc_vec3 zmf_normal(rc_vec3 u, rc_vec3 n, double k)
{
    rc_four q = {rc_v3_dot(u, n) * k, n};
    rc_boost(u, k, &q);
    return rc_v3_scale(1.0 / rc_v3_norm(q.x), q.x);
}

static void one(void)
{
    nb_section("one");
    rc_vec3 n = rc_v3(0.8, 0.36, 0.48);
    collision C = make(rc_v3(0.7, 0.2, -0.1), rc_v3(-0.3, -0.4, 0.2), 1.0, 1.7, n, 1.0, 0.5);
    const rc_particle *before[2] = {&C.a, &C.b}, *after[2] = {&C.a1, &C.b1};
    printf("ball       m            px           py           pz           E/c^2\n");
    for (int i = 0; i < 2; i++) {
        printf("%d before %10.7f %12.8f %12.8f %12.8f %12.8f\n", i, before[i]->m, before[i]->p.x,
               before[i]->p.y, before[i]->p.z, rc_mass_rel(before[i]->m, before[i]->p, 1));
        printf("%d after  %10.7f %12.8f %12.8f %12.8f %12.8f\n", i, after[i]->m, after[i]->p.x,
               after[i]->p.y, after[i]->p.z, rc_mass_rel(after[i]->m, after[i]->p, 1));
    }
    double E0 = rc_mass_rel(C.a.m, C.a.p, 1) + rc_mass_rel(C.b.m, C.b.p, 1);
    double E1 = rc_mass_rel(C.a1.m, C.a1.p, 1) + rc_mass_rel(C.b1.m, C.b1.p, 1);
    rc_vec3 dP = rc_v3_sub(rc_v3_add(C.a1.p, C.b1.p), rc_v3_add(C.a.p, C.b.p));
    printf("energy change %.3g, momentum change %.3g\n", E1 - E0, rc_v3_norm(dP));
    NB_CHECK(fabs(E1 - E0) < 1e-15 * E0 * 4 && rc_v3_norm(dP) < 1e-15 * 4 * E0,
             "energy and momentum conserved to round-off");

    rc_particle pair[2] = {C.a, C.b};
    rc_vec3 u;
    rc_zmf(pair, 2, 1.0, &u, NULL);
    rc_vec3 nh = zmf_normal(u, n, 1.0);
    zmf_view z0 = view(&C.a, u, nh, 1), z0p = view(&C.a1, u, nh, 1);
    zmf_view z1 = view(&C.b, u, nh, 1), z1p = view(&C.b1, u, nh, 1);
    printf("ZMF velocity u = (%.6f, %.6f, %.6f); ZMF normal = (%.6f, %.6f, %.6f)\n", u.x, u.y, u.z,
           nh.x, nh.y, nh.z);
    printf("ball 0 in ZMF: E/c^2 %.12f -> %.12f, p.n %.12f -> %.12f, |p_t| %.12f -> %.12f\n",
           z0.Mbar, z0p.Mbar, z0.pn, z0p.pn, rc_v3_norm(z0.pt), rc_v3_norm(z0p.pt));
    printf("ball 1 in ZMF: E/c^2 %.12f -> %.12f, p.n %.12f -> %.12f, |p_t| %.12f -> %.12f\n",
           z1.Mbar, z1p.Mbar, z1.pn, z1p.pn, rc_v3_norm(z1.pt), rc_v3_norm(z1p.pt));
    NB_CHECK(fabs(z0p.Mbar - z0.Mbar) < 1e-14 && fabs(z1p.Mbar - z1.Mbar) < 1e-14, "ZMF energies kept");
    NB_CHECK(fabs(z0p.pn + 0.5 * z0.pn) < 1e-14 && fabs(z1p.pn + 0.5 * z1.pn) < 1e-14,
             "ZMF normal momenta scaled by -eps");
    NB_CHECK(rc_v3_norm(rc_v3_sub(z0p.pt, z0.pt)) < 1e-14 && rc_v3_norm(rc_v3_sub(z1p.pt, z1.pt)) < 1e-14,
             "ZMF tangential momenta kept");
    double m0pred = sqrt(C.a.m * C.a.m + (1 - 0.25) * z0.pn * z0.pn);
    printf("rest mass of ball 0: %.15f, predicted sqrt(m^2 + (1-eps^2) pbar_n^2/c^2) = %.15f\n", C.a1.m, m0pred);
    NB_CHECK(fabs(C.a1.m - m0pred) < 1e-14, "rest-mass rise formula");
}

/*md
## The rest-mass rise over random collisions

2000 random collisions in 2-D and 3-D, `c` between 1.05 and 20 times the faster ball's
speed, `ε` uniform in [0, 1]. The largest relative error of the rest-mass formula and of the
ZMF claims:
@output random
*/
/* relcol's generator (relcol/rng.h), on the notebook's seed variable */
static double urand(unsigned long long *s)
{
    rc_rng r = {*s};
    const double u = rc_rng_uniform(&r);
    *s = r.state;
    return u;
}

static rc_vec3 rvec(unsigned long long *s, int dim)
{
    rc_vec3 v;
    do {
        v = rc_v3(2 * urand(s) - 1, 2 * urand(s) - 1, dim == 3 ? 2 * urand(s) - 1 : 0);
    } while (rc_v3_norm2(v) > 1 || rc_v3_norm2(v) < 1e-6);
    return v;
}

static void random_cases(void)
{
    nb_section("random");
    unsigned long long s = 7;
    double worst_m = 0, worst_E = 0, worst_n = 0;
    int n_coll = 0;
    for (int i = 0; i < 2000; i++) {
        int dim = 2 + (i & 1);
        rc_vec3 v0 = rvec(&s, dim), v1 = rvec(&s, dim), n = rvec(&s, dim);
        n = rc_v3_scale(1 / rc_v3_norm(n), n);
        double vmax = fmax(rc_v3_norm(v0), rc_v3_norm(v1));
        double c = vmax * (1.05 + 19 * urand(&s)), k = 1 / (c * c), eps = urand(&s);
        collision C = make(v0, v1, 0.5 + urand(&s), 0.5 + urand(&s), n, k, eps);
        if (C.a1.p.x == C.a.p.x && C.a1.p.y == C.a.p.y && C.a1.p.z == C.a.p.z)
            continue; /* separating along n: no collision */
        n_coll++;
        rc_particle pair[2] = {C.a, C.b};
        rc_vec3 u;
        rc_zmf(pair, 2, k, &u, NULL);
        rc_vec3 nh = zmf_normal(u, n, k);
        zmf_view z0 = view(&C.a, u, nh, k), z0p = view(&C.a1, u, nh, k);
        double pred = sqrt(C.a.m * C.a.m + (1 - eps * eps) * z0.pn * z0.pn * k);
        worst_m = fmax(worst_m, fabs(C.a1.m - pred) / C.a.m);
        worst_E = fmax(worst_E, fabs(z0p.Mbar - z0.Mbar) / z0.Mbar);
        worst_n = fmax(worst_n, fabs(z0p.pn + eps * z0.pn) / (fabs(z0.pn) * (1 + eps)));
    }
    printf("%d collisions (the rest were separating along n)\n", n_coll);
    printf("max relative error: rest mass %.2g, ZMF energy %.2g, ZMF normal momentum %.2g\n",
           worst_m, worst_E, worst_n);
    /* speeds up to c/1.05: gamma up to ~3.3; boosts and sqrt cost a few ulps each */
    NB_CHECK(worst_m < 1e-13 && worst_E < 1e-13 && worst_n < 1e-12, "claims hold on every random case");
}

/*md
## How the heat depends on the impact parameter and on `c`

Two equal balls (radius 1), one at rest, the other arriving at speed `0.6` with impact
parameter `b`; `ε = 0.5`. The energy that becomes rest mass, `Q = Σ(m' − m)c²`, in units of
the classical head-on loss, for several `c`. Classically `Q ∝ cos²α = 1 − (b/2)²`; at finite
`c` the ZMF normal momentum is larger (γ factors) and the curve rises.
@output heat
*/
static void heat(void)
{
    nb_section("heat");
    const double cs[] = {0.65, 0.8, 1.2, 3.0, INFINITY};
    const double v = 0.6, eps = 0.5;
    double Qcl0 = (1 - eps * eps) * 0.5 * v * v / 2; /* mu = 1/2, head-on */
    FILE *d = nb_figure_begin("four-impulse-heat");
    double Qinf_mid = 0;
    for (int j = 0; j <= 40; j++) {
        double b = 2.0 * j / 40.0 * 0.999;
        rc_vec3 n = rc_v3(sqrt(1 - b * b / 4), b / 2, 0);
        if (d)
            fprintf(d, "%.6g", b / 2);
        for (int i = 0; i < 5; i++) {
            double k = isinf(cs[i]) ? 0 : 1 / (cs[i] * cs[i]);
            collision C = make(rc_v3(v, 0, 0), rc_v3(0, 0, 0), 1, 1, n, k, eps);
            double Q = 0;
            if (k > 0) {
                Q = ((C.a1.m * C.a1.m - 1) / (C.a1.m + 1) + (C.b1.m * C.b1.m - 1) / (C.b1.m + 1)) / k;
            } else {
                double K0 = rc_kinetic_energy(C.a.m, C.a.p, 0) + rc_kinetic_energy(C.b.m, C.b.p, 0);
                double K1 = rc_kinetic_energy(C.a1.m, C.a1.p, 0) + rc_kinetic_energy(C.b1.m, C.b1.p, 0);
                Q = K0 - K1;
                if (j == 20)
                    Qinf_mid = Q / Qcl0;
            }
            if (d)
                fprintf(d, " %.8g", Q / Qcl0);
        }
        if (d)
            fprintf(d, "\n");
    }
    double b = 2.0 * 20 / 40.0 * 0.999;
    printf("classical Q/Q_head-on at b = %.4f: %.12f (cos^2 alpha = %.12f)\n", b, Qinf_mid, 1 - b * b / 4);
    NB_CHECK(fabs(Qinf_mid - (1 - b * b / 4)) < 1e-12, "classical heat is (1-eps^2) mu (v.n)^2 / 2");
    nb_figure_end(d, "four-impulse-heat",
                  "set xlabel 'impact parameter b / (r_0 + r_1)'\n"
                  "set ylabel 'Q / Q_{classical, head-on}'\nset key top right\nset grid\n"
                  "plot for [i=2:6] datafile u 1:i w l lw 2 t word('c=0.65 c=0.8 c=1.2 c=3 c=∞', i-1)\n");
}

int main(int argc, char **argv)
{
    nb_init(argc, argv);
    one();
    random_cases();
    heat();
    return nb_finish();
}
