/* test_glue_dual — the least k.z over two ellipsoids (z - m_i)^T A_i (z - m_i) <= 1, the
 * question rc_glue_toi and rc_glue_toi2 ask on a hyperplane, found two ways from the same
 * dual (the blend of the two forms, lam in [0, 1]): rc_glue_lin_min2_ by the golden section
 * on the dual's values, rc_glue_lin_min2_slope_ by the sign of its slope. Each answer is
 * checked on its own terms too: its point lies in both ellipsoids (to the forms' rounding)
 * and k.z there equals the returned value, a dual value and so a lower bound of the
 * minimum: a feasible point whose k.z meets a lower bound is the minimiser, so this proves
 * the minimum independently of how lam was searched. Ellipsoids of the sections' kinds:
 * round ones, flat ones (semi-axes 1e-3 to 1e3, H's sections of balls near c), and the
 * 2-D cylinders plane_min2 builds (third axis free, k in the plane). */
#define _USE_MATH_DEFINES
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "glue_section.h"
#include "rc_test.h"
#include "relcol/relcol.h"

static double form(const rc_sym3 *A, rc_vec3 m, rc_vec3 z)
{
    const rc_vec3 d = rc_v3_sub(z, m);
    return rc_v3_dot(d, rc_sym3_mul_(A, d, 0));
}

/* a random rotation's columns (Gram-Schmidt of three normal vectors) */
static void rotation(rc_rng *g, rc_vec3 e[3])
{
    for (int i = 0; i < 3; i++) {
        rc_vec3 v = rc_v3(rc_rng_gauss(g), rc_rng_gauss(g), rc_rng_gauss(g));
        for (int j = 0; j < i; j++)
            v = rc_v3_axpy(v, -rc_v3_dot(v, e[j]), e[j]);
        e[i] = rc_v3_scale(1.0 / rc_v3_norm(v), v);
    }
}

/* A = sum e_i e_i^T / a_i^2; flat: one semi-axis up to 1e3 times the others. *amax the
 * longest semi-axis, *kap A's condition number (amax / amin)^2. */
static rc_sym3 ellipsoid(rc_rng *g, int kind, double *amax, double *kap)
{
    rc_vec3 e[3];
    rotation(g, e);
    double a[3];
    for (int i = 0; i < 3; i++)
        a[i] = exp(rc_rng_uniform(g) * 2.0 - 1.0); /* 0.37 .. 2.7 */
    if (kind == 1)
        a[0] *= exp(rc_rng_uniform(g) * log(1e3));
    *amax = fmax(a[0], fmax(a[1], a[2]));
    const double amin = fmin(a[0], fmin(a[1], a[2]));
    *kap = (*amax / amin) * (*amax / amin);
    rc_sym3 A = {0, 0, 0, 0, 0, 0};
    for (int i = 0; i < 3; i++) {
        const double w = 1.0 / (a[i] * a[i]);
        A.xx += w * e[i].x * e[i].x;
        A.yy += w * e[i].y * e[i].y;
        A.zz += w * e[i].z * e[i].z;
        A.xy += w * e[i].x * e[i].y;
        A.xz += w * e[i].x * e[i].z;
        A.yz += w * e[i].y * e[i].z;
    }
    return A;
}

/* plane_min2's kind: an ellipse in (x, y), the third axis free */
static rc_sym3 cylinder(rc_rng *g, double *amax, double *kap)
{
    const double ph = 2.0 * M_PI * rc_rng_uniform(g);
    const double a = exp(rc_rng_uniform(g) * 2.0 - 1.0), b = a * exp(rc_rng_uniform(g) * 4.0);
    const double c = cos(ph), s = sin(ph);
    *amax = b;
    *kap = (b / a) * (b / a);
    const rc_sym3 A = {c * c / (a * a) + s * s / (b * b), s * s / (a * a) + c * c / (b * b), 1.0,
                       c * s * (1.0 / (a * a) - 1.0 / (b * b)), 0.0, 0.0};
    return A;
}

typedef struct tally {
    long both, empty, disagree;
    double worst; /* |slope - golden| in round-offs times kap */
} tally;

static void one_case(rc_rng *g, int kind, tally *t)
{
    double a1, a2, kap1, kap2;
    rc_sym3 A1, A2;
    if (kind == 2) {
        A1 = cylinder(g, &a1, &kap1);
        A2 = cylinder(g, &a2, &kap2);
    } else {
        A1 = ellipsoid(g, kind, &a1, &kap1);
        A2 = ellipsoid(g, kind, &a2, &kap2);
    }
    /* centres apart by up to 1.2 of the longest semi-axes (0.4 for the flat ones, which
     * reach that far along one axis only): about half the pairs meet */
    const rc_vec3 m1 = rc_v3(3.0 * rc_rng_gauss(g), 3.0 * rc_rng_gauss(g),
                             kind == 2 ? 0.0 : 3.0 * rc_rng_gauss(g));
    rc_vec3 u = rc_v3(rc_rng_gauss(g), rc_rng_gauss(g), kind == 2 ? 0.0 : rc_rng_gauss(g));
    u = rc_v3_scale(1.0 / rc_v3_norm(u), u);
    const rc_vec3 m2 = rc_v3_axpy(m1, (kind == 1 ? 0.4 : 1.2) * (a1 + a2) * rc_rng_uniform(g), u);
    rc_vec3 k = rc_v3(rc_rng_gauss(g), rc_rng_gauss(g), kind == 2 ? 0.0 : rc_rng_gauss(g));
    k = rc_v3_scale(exp(rc_rng_uniform(g) * 4.0 - 2.0), k);
    rc_vec3 zg, zs;
    const double fg = rc_glue_lin_min2_(&A1, m1, &A2, m2, k, &zg);
    const double fs = rc_glue_lin_min2_slope_(&A1, m1, &A2, m2, k, &zs);
    ENSURE_MSG(!isnan(fg) && !isnan(fs), "a regular pair gave NAN: %g %g", fg, fs);
    if ((fg == INFINITY) != (fs == INFINITY)) {
        t->disagree++;
        ENSURE_MSG(0, "empty for one search only: golden %.17g, slope %.17g", fg, fs);
        return;
    }
    if (fs == INFINITY) {
        t->empty++;
        return;
    }
    t->both++;
    /* The terms' size: k.z at points as far out as the ellipsoids reach. Both searches
     * evaluate the same dual, whose blend is solved with the blend's condition number
     * (at most the larger kap) times the round-off: so they agree to that many round-offs
     * (measured: at most 68 in these draws; 1000 allowed). A form at the point carries the
     * rounding of z - m, z and m as far as |m| from the origin, over the shortest
     * semi-axis: so much more for feasibility. An answer off by a search's fault (a wrong
     * end, a bracket left early) is off by far more: the golden section's first brackets
     * are 0.38 of lam wide. */
    const double scale = rc_v3_norm(k) * (rc_v3_norm(m1) + rc_v3_norm(m2) + a1 + a2);
    const double kap = fmax(kap1, kap2), tol = 1000.0 * DBL_EPSILON * kap;
    const double amin = fmin(a1 / sqrt(kap1), a2 / sqrt(kap2));
    const double ftol = tol * (1.0 + (rc_v3_norm(m1) + rc_v3_norm(m2)) / amin);
    ENSURE_CLOSE(fs, fg, tol, scale);
    ENSURE_MSG(form(&A1, m1, zs) <= 1.0 + ftol && form(&A2, m2, zs) <= 1.0 + ftol,
               "slope's point outside: forms %.17g %.17g", form(&A1, m1, zs), form(&A2, m2, zs));
    ENSURE_CLOSE(rc_v3_dot(k, zs), fs, tol, scale);
    t->worst = fmax(t->worst, fabs(fs - fg) / (scale * DBL_EPSILON * fmax(kap1, kap2)));
}

static void test_agree(int kind, long n, const char *what)
{
    rc_rng g = {1234 + (uint64_t)kind};
    tally t = {0, 0, 0, 0.0};
    for (long i = 0; i < n; i++)
        one_case(&g, kind, &t);
    printf("  %s: %ld met (minimum compared, worst %.3g round-offs x kap), %ld empty for both, "
           "%ld disagreeing\n", what, t.both, t.worst, t.empty, t.disagree);
    /* both verdicts must occur, or the draw does not test what it claims */
    ENSURE(t.both > n / 10 && t.empty > n / 10);
}

static void test_round(void) { test_agree(0, 20000, "round ellipsoids"); }
static void test_flat(void) { test_agree(1, 20000, "flat ellipsoids (1e3)"); }
static void test_plane(void) { test_agree(2, 20000, "plane_min2's cylinders"); }

/* hand-solved: two unit balls centred at 0 and (1, 0, 0), k = (0, 0, 1): the lens's
 * lowest point is on the circle x = 1/2, at z = -sqrt(3)/2; and k = (1, 0, 0): x = 0
 * (ball 2's own minimiser, inside ball 1: the end lam = 1) */
static void test_lens(void)
{
    const rc_sym3 I = {1, 1, 1, 0, 0, 0};
    rc_vec3 z;
    double f = rc_glue_lin_min2_slope_(&I, rc_v3(0, 0, 0), &I, rc_v3(1, 0, 0), rc_v3(0, 0, 1), &z);
    ENSURE_CLOSE(f, -sqrt(3.0) / 2.0, 1e-15, 1.0);
    ENSURE_CLOSE(z.x, 0.5, 1e-8, 1.0);
    f = rc_glue_lin_min2_slope_(&I, rc_v3(0, 0, 0), &I, rc_v3(1, 0, 0), rc_v3(1, 0, 0), &z);
    ENSURE_CLOSE(f, 0.0, 1e-15, 1.0);
    /* apart: empty */
    f = rc_glue_lin_min2_slope_(&I, rc_v3(0, 0, 0), &I, rc_v3(2.001, 0, 0), rc_v3(0, 0, 1), &z);
    ENSURE(f == INFINITY);
}

int main(void)
{
    RUN_TEST(test_lens);
    RUN_TEST(test_round);
    RUN_TEST(test_flat);
    RUN_TEST(test_plane);
    RC_TEST_MAIN_END();
}
