/*md
# 1. Relativistic restitution in one dimension

Seed 000 ("Relativistic collision in one dimension") collides two balls head-on with
rest masses that may change. It conserves energy and momentum, keeps each ball's energy in
the zero-momentum frame (ZMF), scales each ZMF momentum by −ε, and arrives at closed forms:

- (U) the ZMF velocity `u = (m₀γ₀v₀ + m₁γ₁v₁)/(m₀γ₀ + m₁γ₁)`,
- (V) `v' = [u(1 − uv/c²) + ε(u − v)] / [1 − uv/c² + ε u(u − v)/c²]`,
- (M) `m' = m √{[1 − 2(1−ε²)vu/c² − ε²(v² + u²)/c² + v²u²/c⁴] / [1 − (v² + u²)/c² + v²u²/c⁴]}`.

Here we do not trust the algebra: we solve the **raw** equations — energy and momentum
conservation in the table frame, plus the two ZMF conditions — numerically with GSL's
`multiroot` solver, and compare with (U), (V), (M) and with relcol's `zmf` law.
Units: `c = 1` unless a sweep says otherwise.
*/
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_vector.h>

#include "nb.h"
#include "relcol/relcol.h"

/*md
## The raw equations

Unknowns: the final momenta `p₀', p₁'` and rest masses `m₀', m₁'` (four numbers). With
`E = √(m²c⁴ + p²c²)` and the ZMF velocity `u` of the initial state (it is the same after:
total energy and momentum are conserved), the four equations are

1. `E₀' + E₁' = E₀ + E₁` (energy),
2. `p₀' + p₁' = p₀ + p₁` (momentum),
3. `γ_u (E₀' − u p₀') = γ_u (E₀ − u p₀)` (ball 0's ZMF energy kept),
4. `γ_u (p₀' − u E₀'/c²) = −ε γ_u (p₀ − u E₀/c²)` (ball 0's ZMF momentum scaled by −ε).

Ball 1's ZMF conditions then follow from 1–4.
*/
typedef struct {
    double c, eps, m0, m1, p0, p1;
} raw_problem;

static double energy(double m, double p, double c) { return sqrt(m * m * c * c * c * c + p * p * c * c); }

static int raw_f(const gsl_vector *x, void *params, gsl_vector *f)
{
    const raw_problem *q = params;
    const double c = q->c;
    double p0 = gsl_vector_get(x, 0), p1 = gsl_vector_get(x, 1);
    double m0 = gsl_vector_get(x, 2), m1 = gsl_vector_get(x, 3);
    double E0 = energy(q->m0, q->p0, c), E1 = energy(q->m1, q->p1, c);
    double E0n = energy(m0, p0, c), E1n = energy(m1, p1, c);
    double u = (q->p0 + q->p1) * c * c / (E0 + E1);
    double Escale = E0 + E1, pscale = (E0 + E1) / c;
    gsl_vector_set(f, 0, (E0n + E1n - E0 - E1) / Escale);
    gsl_vector_set(f, 1, (p0 + p1 - q->p0 - q->p1) / pscale);
    gsl_vector_set(f, 2, ((E0n - u * p0) - (E0 - u * q->p0)) / Escale);
    gsl_vector_set(f, 3, ((p0 - u * E0n / (c * c)) + q->eps * (q->p0 - u * E0 / (c * c))) / pscale);
    return GSL_SUCCESS;
}

/* Solve the raw system from the classical guess; returns GSL status. */
static int raw_solve(const raw_problem *q, double out[4])
{
    const gsl_multiroot_fsolver_type *T = gsl_multiroot_fsolver_hybrids;
    gsl_multiroot_fsolver *s = gsl_multiroot_fsolver_alloc(T, 4);
    gsl_multiroot_function F = {raw_f, 4, (void *)q};
    gsl_vector *x = gsl_vector_alloc(4);
    gsl_vector_set(x, 0, q->p1 * q->m0 / q->m1);
    gsl_vector_set(x, 1, q->p0 * q->m1 / q->m0);
    gsl_vector_set(x, 2, q->m0);
    gsl_vector_set(x, 3, q->m1);
    gsl_multiroot_fsolver_set(s, &F, x);
    int st = GSL_CONTINUE;
    for (int it = 0; it < 200 && st == GSL_CONTINUE; it++) {
        st = gsl_multiroot_fsolver_iterate(s);
        if (st)
            break;
        st = gsl_multiroot_test_residual(s->f, 1e-15);
    }
    for (int i = 0; i < 4; i++)
        out[i] = gsl_vector_get(s->x, i);
    /* the equations contain the rest masses only squared: report the positive root */
    out[2] = fabs(out[2]);
    out[3] = fabs(out[3]);
    gsl_vector_free(x);
    gsl_multiroot_fsolver_free(s);
    return st;
}

/*md
## Seed 000's closed forms
*/
static double seed_V(double v, double u, double eps, double c)
{
    double k = 1.0 / (c * c);
    return (u * (1 - u * v * k) + eps * (u - v)) / (1 - u * v * k + eps * u * k * (u - v));
}

static double seed_M(double m, double v, double u, double eps, double c)
{
    double k = 1.0 / (c * c);
    double num = 1 - 2 * (1 - eps * eps) * v * u * k - eps * eps * (v * v + u * u) * k + v * v * u * u * k * k;
    double den = 1 - (v * v + u * u) * k + v * v * u * u * k * k;
    return m * sqrt(num / den);
}

/*md
## A worked case

Ball 0 (`m = 1`) at `0.8c` hits ball 1 (`m = 2`) moving at `−0.3c`, `ε = 0.6`.
@output worked
*/
static void worked(void)
{
    nb_section("worked");
    raw_problem q = {1.0, 0.6, 1.0, 2.0, 0, 0};
    double v0 = 0.8, v1 = -0.3;
    q.p0 = q.m0 * v0 / sqrt(1 - v0 * v0);
    q.p1 = q.m1 * v1 / sqrt(1 - v1 * v1);
    double x[4];
    int st = raw_solve(&q, x);
    double u = (q.p0 + q.p1) / (sqrt(q.m0 * q.m0 + q.p0 * q.p0) + sqrt(q.m1 * q.m1 + q.p1 * q.p1));
    double vr0 = x[0] / sqrt(x[2] * x[2] + x[0] * x[0]), vr1 = x[1] / sqrt(x[3] * x[3] + x[1] * x[1]);

    rc_collision_params prm = rc_collision_params_default();
    prm.c = 1.0;
    prm.eps = q.eps;
    rc_particle a = {q.m0, rc_v3(q.p0, 0, 0)}, b = {q.m1, rc_v3(q.p1, 0, 0)};
    rc_collide(&rc_law_zmf, &prm, &a, &b, rc_v3(1, 0, 0));
    double vl0 = rc_velocity(a.m, a.p, 1).x, vl1 = rc_velocity(b.m, b.p, 1).x;

    printf("ZMF velocity u (U)          = %.15f\n", u);
    printf("                 multiroot    (U)/(V)/(M)     relcol zmf\n");
    printf("v0'   %20.15f %17.15f %17.15f\n", vr0, seed_V(v0, u, q.eps, 1), vl0);
    printf("v1'   %20.15f %17.15f %17.15f\n", vr1, seed_V(v1, u, q.eps, 1), vl1);
    printf("m0'   %20.15f %17.15f %17.15f\n", x[2], seed_M(q.m0, v0, u, q.eps, 1), a.m);
    printf("m1'   %20.15f %17.15f %17.15f\n", x[3], seed_M(q.m1, v1, u, q.eps, 1), b.m);
    NB_CHECK(st == GSL_SUCCESS, "multiroot converged (%s)", gsl_strerror(st));
    /* 1e-12: the residual test is 1e-15 on O(1) scaled equations; the answers are O(1) */
    NB_CHECK(fabs(vr0 - seed_V(v0, u, q.eps, 1)) < 1e-12 && fabs(vr1 - seed_V(v1, u, q.eps, 1)) < 1e-12,
             "raw solution = (V) for both balls");
    NB_CHECK(fabs(x[2] - seed_M(q.m0, v0, u, q.eps, 1)) < 1e-12 && fabs(x[3] - seed_M(q.m1, v1, u, q.eps, 1)) < 1e-12,
             "raw solution = (M) for both balls");
    NB_CHECK(fabs(vl0 - vr0) < 1e-12 && fabs(vl1 - vr1) < 1e-12 && fabs(a.m - x[2]) < 1e-12 && fabs(b.m - x[3]) < 1e-12,
             "relcol's zmf law = raw solution");
}

/*md
## Many random cases

500 random collisions: speeds up to 0.95c, masses in [0.5, 3], ε in [0, 1]. We record the
largest difference between the multiroot solution, the seed's formulas and the library.
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

static void random_cases(void)
{
    nb_section("random");
    unsigned long long seed = 12345;
    double worst_raw = 0, worst_lib = 0;
    int fails = 0;
    for (int i = 0; i < 500; i++) {
        raw_problem q = {1.0, urand(&seed), 0.5 + 2.5 * urand(&seed), 0.5 + 2.5 * urand(&seed), 0, 0};
        double v0 = 0.95 * urand(&seed), v1 = -0.95 * urand(&seed);
        q.p0 = q.m0 * v0 / sqrt(1 - v0 * v0);
        q.p1 = q.m1 * v1 / sqrt(1 - v1 * v1);
        double x[4];
        if (raw_solve(&q, x) != GSL_SUCCESS) {
            fails++;
            continue;
        }
        double u = (q.p0 + q.p1) / (sqrt(q.m0 * q.m0 + q.p0 * q.p0) + sqrt(q.m1 * q.m1 + q.p1 * q.p1));
        double vr0 = x[0] / sqrt(x[2] * x[2] + x[0] * x[0]);
        double d = fmax(fabs(vr0 - seed_V(v0, u, q.eps, 1)), fabs(x[2] - seed_M(q.m0, v0, u, q.eps, 1)));
        worst_raw = fmax(worst_raw, d);
        rc_collision_params prm = rc_collision_params_default();
        prm.c = 1.0;
        prm.eps = q.eps;
        rc_particle a = {q.m0, rc_v3(q.p0, 0, 0)}, b = {q.m1, rc_v3(q.p1, 0, 0)};
        rc_collide(&rc_law_zmf, &prm, &a, &b, rc_v3(1, 0, 0));
        worst_lib = fmax(worst_lib, fmax(fabs(rc_velocity(a.m, a.p, 1).x - vr0), fabs(a.m - x[2])));
    }
    printf("solver failures: %d of 500\n", fails);
    printf("max |raw - seed (V),(M)| = %.3g\n", worst_raw);
    printf("max |raw - relcol zmf|   = %.3g\n", worst_lib);
    NB_CHECK(fails == 0, "multiroot converged on all 500 cases");
    /* speeds up to 0.95c: gamma up to 3.2, so 1e-10 leaves room for conditioning */
    NB_CHECK(worst_raw < 1e-10 && worst_lib < 1e-10, "seed formulas and library agree with the raw equations");
}

/*md
## Classical limit and sticking

As `c → ∞`, (V) tends to `v' = (1 + ε)u − εv` with the Newtonian `u`. The deviation of
relcol's result from the classical one falls as `(v/c)²`: the figure shows it over six
decades of `c`. With `ε = 0`, (V) is `v' = u`: the balls stick.
@output limit
*/
static void classical_limit(void)
{
    nb_section("limit");
    const double m0 = 1, m1 = 2, v0 = 1.0, v1 = -0.5, eps = 0.7;
    double ucl = (m0 * v0 + m1 * v1) / (m0 + m1);
    double vcl = (1 + eps) * ucl - eps * v0;
    FILE *d = nb_figure_begin("restitution-1d-limit");
    double first = 0, last = 0, lc0 = 0, lc1 = 0;
    for (int k = 0; k <= 24; k++) {
        double c = pow(10.0, 0.5 + 0.25 * k);
        rc_collision_params prm = rc_collision_params_default();
        prm.c = c;
        prm.eps = eps;
        rc_particle a = {m0, rc_v3(0, 0, 0)}, b = {m1, rc_v3(0, 0, 0)};
        rc_momentum_from_velocity(m0, rc_v3(v0, 0, 0), rc_inv_c2_of(prm.c), &a.p);
        rc_momentum_from_velocity(m1, rc_v3(v1, 0, 0), rc_inv_c2_of(prm.c), &b.p);
        rc_collide(&rc_law_zmf, &prm, &a, &b, rc_v3(1, 0, 0));
        double dev = fabs(rc_velocity(a.m, a.p, rc_inv_c2_of(prm.c)).x - vcl) / fabs(vcl);
        if (d)
            fprintf(d, "%.6g %.6g %.6g\n", c, dev, (v0 / c) * (v0 / c));
        if (k == 4) {
            first = dev;
            lc0 = log10(c);
        }
        if (k == 16) {
            last = dev;
            lc1 = log10(c);
        }
    }
    double slope = (log10(last) - log10(first)) / (lc1 - lc0);
    printf("log-log slope of |v0'(c) - v0'(inf)| between c = %.0f and %.0f: %.4f\n",
           pow(10, lc0), pow(10, lc1), slope);
    nb_figure_end(d, "restitution-1d-limit",
                  "set logscale xy\nset format y '10^{%L}'\nset format x '10^{%L}'\n"
                  "set xlabel 'c / v_0'\nset ylabel \"relative deviation of v_0' from c = ∞\"\n"
                  "set key top right\nset grid\n"
                  "plot datafile u 1:2 w lp pt 7 t 'relcol zmf, ε = 0.7', "
                  "'' u 1:3 w l dt 2 t '(v_0/c)^2'\n");
    NB_CHECK(fabs(slope + 2) < 0.02, "deviation falls as (v/c)^2 (slope %.4f)", slope);

    rc_collision_params prm = rc_collision_params_default();
    prm.c = 1.0;
    prm.eps = 0.0;
    rc_particle a = {1, rc_v3(0, 0, 0)}, b = {3, rc_v3(0, 0, 0)};
    rc_momentum_from_velocity(1, rc_v3(0.9, 0, 0), 1, &a.p);
    rc_momentum_from_velocity(3, rc_v3(-0.2, 0, 0), 1, &b.p);
    rc_collide(&rc_law_zmf, &prm, &a, &b, rc_v3(1, 0, 0));
    double va = rc_velocity(a.m, a.p, 1).x, vb = rc_velocity(b.m, b.p, 1).x;
    printf("eps = 0 at c = 1: v0' = %.15f, v1' = %.15f\n", va, vb);
    NB_CHECK(fabs(va - vb) < 1e-15, "eps = 0: the balls move together");
}

int main(int argc, char **argv)
{
    nb_init(argc, argv);
    gsl_set_error_handler_off();
    worked();
    random_cases();
    classical_limit();
    return nb_finish();
}
