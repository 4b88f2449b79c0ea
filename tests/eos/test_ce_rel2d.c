/* test_ce_rel2d — the 2-D invariant-Boltzmann Chapman–Enskog references
 * (apps/eos/ce_rel2d.c) against closed forms derived by hand, an independent classical
 * quadrature of the Sonine brackets and an independent Monte Carlo of the relativistic
 * first approximation (papers/transport-2d.md). Units kT = c = sigma_T = 1,
 * z = m c^2 / kT; discs of diameter sigma have sigma_T = 2 sigma. */
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "ce_rel2d.h"
#include "rc_test.h"

static ce_rel_coeffs at(double z, int order, ce_rel2d_law law)
{
    ce_rel_coeffs c = {NAN, NAN, NAN};
    const char *why = "";
    const int st = ce_rel2d_compute(z, order, law, NULL, &c, &why);
    ENSURE_MSG(st == 0, "z %g order %d law %d: %s", z, order, (int)law, why);
    return c;
}

/* --- independent adaptive quadratures of 2-D Jüttner moments: d^2p = 2 pi E dK --- */
typedef struct {
    double m, hk;
    int what; /* 0..2: K^what; 3: shear source; 4: heat source */
} jm;

static double jm_f(double K, void *vp)
{
    const jm *c = vp;
    const double E = K + c->m, p2 = K * (K + 2.0 * c->m), jac = 2.0 * M_PI * E * exp(-K);
    if (c->what < 3)
        return jac * pow(K, c->what);
    if (c->what == 3)
        return jac * p2 * p2 / (2.0 * E); /* p^<ab> . p_<ab>/E */
    return jac * K * (K - c->hk) * p2 / E; /* K p^a . (E - h) v^a */
}

static double jm_int(double m, double hk, int what)
{
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    jm c = {m, hk, what};
    gsl_function f = {jm_f, &c};
    double r = NAN, err;
    gsl_integration_qagiu(&f, 0.0, 0.0, 1e-12, 1000, ws, &r, &err);
    gsl_integration_workspace_free(ws);
    return r;
}

/* The closed forms of the moments (Z e^z = 2 pi (1 + z), <K>, var K) against quadrature. */
static void test_juttner_moments(void)
{
    static const double zs[] = {0.0, 0.1, 1.0, 10.0, 1000.0};
    for (int i = 0; i < 5; i++) {
        ce_rel_juttner J;
        const char *why;
        ENSURE(ce_rel2d_juttner_moments(zs[i], &J, &why) == 0);
        const double m0 = jm_int(zs[i], 0, 0), m1 = jm_int(zs[i], 0, 1), m2 = jm_int(zs[i], 0, 2);
        ENSURE_REL(J.z_scaled, m0, 1e-10);
        ENSURE_REL(J.mean_k, m1 / m0, 1e-10);
        ENSURE_REL(J.var_k, m2 / m0 - (m1 / m0) * (m1 / m0), 1e-9);
    }
}

/* Massless first approximation, derived by hand in papers/transport-2d.md (only the k = 2 harmonic
 * on the CM circle): eta_1 = 12/(11 (1 - gamma_2)), lambda_1 = 12/(5 (1 - gamma_2)),
 * gamma_2 = 0 isotropic, -1/15 hard-disc law. Then convergence with the order; zeta = 0. */
static void test_massless(void)
{
    const ce_rel_coeffs i1 = at(0.0, 1, CE_REL2D_ISOTROPIC), d1 = at(0.0, 1, CE_REL2D_HARD_DISC);
    ENSURE_REL(i1.eta, 12.0 / 11.0, 1e-10);
    ENSURE_REL(i1.lambda, 12.0 / 5.0, 1e-10);
    ENSURE_REL(d1.eta, 45.0 / 44.0, 1e-10);
    ENSURE_REL(d1.lambda, 9.0 / 4.0, 1e-10);
    ENSURE(i1.zeta == 0.0 && d1.zeta == 0.0);
    /* increments fall with the order: eta converged to 1e-5 at 16, lambda rising slowly */
    const ce_rel_coeffs i8 = at(0.0, 8, CE_REL2D_ISOTROPIC), i12 = at(0.0, 12, CE_REL2D_ISOTROPIC),
                        i16 = at(0.0, 16, CE_REL2D_ISOTROPIC);
    ENSURE(i16.eta > i12.eta && i16.eta - i12.eta < 1e-5 && i12.eta - i8.eta < 1e-4);
    ENSURE(i16.lambda > i12.lambda && i16.lambda - i12.lambda < 0.5 * (i12.lambda - i8.lambda));
    ENSURE(i16.eta > 1.138 && i16.eta < 1.1381); /* papers/transport-2d.md's table: 1.13808 */
    /* the massless limit is continuous: z = 1e-4 within 1e-5 of z = 0 */
    ENSURE_REL(at(1e-4, 3, CE_REL2D_ISOTROPIC).eta, at(0.0, 3, CE_REL2D_ISOTROPIC).eta, 1e-5);
}

/* --- an independent classical computation of the Sonine brackets: Galilean CM variables
 * p = P/2 + q, p1 = P/2 - q (m = kT = 1), q along x, P at angle phi, q' at angle chi;
 * Gauss–Laguerre in P^2/4 and q^2, trapezoid in phi, Gauss–Legendre in chi (the hard-disc
 * law's |sin(chi/2)|/4 is smooth inside (0, 2 pi)). No variable in common with ce_rel2d. */
static double laguerre_poly(int n, double a, double x)
{
    double l0 = 1.0, l1 = 1.0 + a - x;
    if (n == 0)
        return l0;
    for (int k = 1; k < n; k++) {
        const double l2 = ((2.0 * k + 1.0 + a - x) * l1 - (k + a) * l0) / (k + 1.0);
        l0 = l1, l1 = l2;
    }
    return l1;
}

/* psi of set s (0 shear: L_i^(2)(x) p^<ab> as xx, xy; 1 heat: L_{i+1}^(1)(x) p^a), x = p^2/2 */
static void cl_psi(int s, int i, double px, double py, double out[2])
{
    const double x = 0.5 * (px * px + py * py);
    if (s == 0) {
        const double l = laguerre_poly(i, 2.0, x);
        out[0] = l * 0.5 * (px * px - py * py), out[1] = l * px * py;
    } else {
        const double l = laguerre_poly(i + 1, 1.0, x);
        out[0] = l * px, out[1] = l * py;
    }
}

/* Classical eta_N (s = 0) or lambda_N (s = 1) for the law g, N <= 4. */
static double classical(int s, int N, int disc)
{
    enum { NT = 16, NS = 16, NP = 24, NC = 64 };
    gsl_integration_fixed_workspace *gt =
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, NT, 0.0, 1.0, 0.0, 0.0);
    gsl_integration_fixed_workspace *gs =
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, NS, 0.0, 1.0, 0.5, 0.0);
    gsl_integration_fixed_workspace *gc =
        gsl_integration_fixed_alloc(gsl_integration_fixed_legendre, NC, 0.0, 2.0 * M_PI, 0.0, 0.0);
    const double *xt = gsl_integration_fixed_nodes(gt), *wt = gsl_integration_fixed_weights(gt);
    const double *xs = gsl_integration_fixed_nodes(gs), *ws = gsl_integration_fixed_weights(gs);
    const double *xc = gsl_integration_fixed_nodes(gc), *wc = gsl_integration_fixed_weights(gc);
    double A[4][4] = {{0}}, b[4] = {0};
    const double cw = s == 0 ? 2.0 : 1.0; /* T:T' = 2 xx xx' + 2 xy xy' */
    for (int it = 0; it < NT; it++)
        for (int is = 0; is < NS; is++)
            for (int ip = 0; ip < NP; ip++)
                for (int ic = 0; ic < NC; ic++) {
                    const double R = 2.0 * sqrt(xt[it]), r = sqrt(xs[is]);
                    const double ph = 2.0 * M_PI * ip / NP, ch = xc[ic];
                    const double g = disc ? 0.25 * fabs(sin(0.5 * ch)) : 1.0 / (2.0 * M_PI);
                    const double Px = R * cos(ph), Py = R * sin(ph);
                    const double qx = r, qy = 0.0, rx = r * cos(ch), ry = r * sin(ch);
                    /* (1/4) (2 pi)^-2 . 2 pi (q direction) . 2 dt (R dR) . ds/2 (r dr) . 2r |v - v1| */
                    const double meas = 0.25 / (4.0 * M_PI * M_PI) * 2.0 * M_PI * 2.0 * 0.5 * 2.0 *
                                        wt[it] * ws[is] * (2.0 * M_PI / NP) * wc[ic] * g;
                    double d[4][2];
                    for (int i = 0; i < N; i++) {
                        double a0[2], a1[2], a2[2], a3[2];
                        cl_psi(s, i, 0.5 * Px + qx, 0.5 * Py + qy, a0);
                        cl_psi(s, i, 0.5 * Px - qx, 0.5 * Py - qy, a1);
                        cl_psi(s, i, 0.5 * Px + rx, 0.5 * Py + ry, a2);
                        cl_psi(s, i, 0.5 * Px - rx, 0.5 * Py - ry, a3);
                        for (int c = 0; c < 2; c++)
                            d[i][c] = a0[c] + a1[c] - a2[c] - a3[c];
                    }
                    for (int i = 0; i < N; i++)
                        for (int j = 0; j < N; j++)
                            A[i][j] += meas * cw * (d[i][0] * d[j][0] + d[i][1] * d[j][1]);
                }
    /* sources, x ~ Exp(1): shear <L_i^(2) . p^4/2> = <L_i^(2) 2x^2>; heat
     * <L_{i+1}^(1) p^a . (x - 2) p^a> = <L_{i+1}^(1) 2x (x - 2)> */
    for (int n = 0; n < NT; n++)
        for (int i = 0; i < N; i++) {
            const double x = xt[n];
            b[i] += wt[n] * (s == 0 ? laguerre_poly(i, 2.0, x) * 2.0 * x * x
                                    : laguerre_poly(i + 1, 1.0, x) * 2.0 * x * (x - 2.0));
        }
    gsl_integration_fixed_free(gt);
    gsl_integration_fixed_free(gs);
    gsl_integration_fixed_free(gc);
    /* b^T A^-1 b by Gauss elimination (A is small and positive definite) */
    double M[4][5];
    for (int i = 0; i < N; i++) {
        for (int j = 0; j < N; j++)
            M[i][j] = A[i][j];
        M[i][N] = b[i];
    }
    for (int k = 0; k < N; k++)
        for (int i = k + 1; i < N; i++) {
            const double f = M[i][k] / M[k][k];
            for (int j = k; j <= N; j++)
                M[i][j] -= f * M[k][j];
        }
    double x[4];
    for (int i = N - 1; i >= 0; i--) {
        double t = M[i][N];
        for (int j = i + 1; j < N; j++)
            t -= M[i][j] * x[j];
        x[i] = t / M[i][i];
    }
    double r = 0.0;
    for (int i = 0; i < N; i++)
        r += b[i] * x[i];
    return r / (s == 0 ? 4.0 : 2.0);
}

/* Classical (z = 1e6; the relativistic corrections are +1.06/z for eta, +0.31/z for
 * lambda, -9.9/z for zeta, papers/transport-2d.md): the hard-disc law gives the hard-disc values
 * eta_1 = (1/(2 sigma)) sqrt(m kT/pi) and lambda_1 = (2k/sigma) sqrt(kT/(pi m)) with
 * sigma = sigma_T/2, and zeta_1 = (2/sqrt pi) z^-3/2 (derived in papers/transport-2d.md); the
 * isotropic law 16/15 of them. Orders 2-4 against the independent classical quadrature. */
static void test_classical(void)
{
    const double z = 1e6, rz = sqrt(z);
    const ce_rel_coeffs d1 = at(z, 1, CE_REL2D_HARD_DISC), i1 = at(z, 1, CE_REL2D_ISOTROPIC);
    ENSURE_REL(d1.eta, sqrt(z / M_PI), 3e-6);
    ENSURE_REL(d1.lambda, 4.0 / sqrt(M_PI * z), 3e-6);
    ENSURE_REL(d1.zeta * z * rz, 2.0 / sqrt(M_PI), 2e-5);
    ENSURE_REL(i1.eta, (16.0 / 15.0) * sqrt(z / M_PI), 3e-6);
    ENSURE_REL(i1.lambda, (16.0 / 15.0) * 4.0 / sqrt(M_PI * z), 3e-6);
    ENSURE_REL(i1.zeta * z * rz, (16.0 / 15.0) * 2.0 / sqrt(M_PI), 2e-5);
    for (int disc = 0; disc < 2; disc++)
        for (int N = 1; N <= 4; N++) {
            const ce_rel_coeffs c = at(z, N, disc ? CE_REL2D_HARD_DISC : CE_REL2D_ISOTROPIC);
            const double ce = classical(0, N, disc), cl = classical(1, N, disc);
            ENSURE_REL(c.eta / rz, ce, 3e-6);
            ENSURE_REL(c.lambda * rz, cl, 3e-6);
            if (N == 1) /* the independent quadrature's own first approximation */
                ENSURE_REL(ce, disc ? 1.0 / sqrt(M_PI) : (16.0 / 15.0) / sqrt(M_PI), 1e-10);
        }
    /* hard discs converged (16 functions): eta and lambda 1.0220 and 1.0297 times the
     * first approximation, the increments 12 -> 16 below 1e-6 */
    const ce_rel_coeffs d12 = at(z, 12, CE_REL2D_HARD_DISC), d16 = at(z, 16, CE_REL2D_HARD_DISC);
    ENSURE_CLOSE(d16.eta / d1.eta, 1.02197, 1e-5, 1.0);
    ENSURE_CLOSE(d16.lambda / d1.lambda, 1.02972, 1e-5, 1.0);
    ENSURE_REL(d16.eta, d12.eta, 1e-6);
    ENSURE_REL(d16.lambda, d12.lambda, 1e-6);
}

/* Quadrature converged: doubling the u and w node counts moves the 8-function values by
 * < 1e-7 (z <= 0.1 is the worst: p* = sqrt(u (u + 4m))/2 varies on the scale 4m near
 * u = 0); the angles are exact by construction, twice as many change nothing. */
static void test_quadrature_converged(void)
{
    static const double zs[] = {0.0, 0.01, 0.3, 3.0, 100.0};
    const ce_rel2d_quad fine = {128, 96, 0};
    for (int i = 0; i < 5; i++) {
        const ce_rel2d_law law = i % 2 ? CE_REL2D_HARD_DISC : CE_REL2D_ISOTROPIC;
        {
            const ce_rel_coeffs a = at(zs[i], 8, law);
            ce_rel_coeffs b, b2;
            const char *why;
            const ce_rel2d_quad angles = {64, 48, 4 * (8 + 2) + 2};
            ENSURE(ce_rel2d_compute(zs[i], 8, law, &angles, &b2, &why) == 0);
            ENSURE_REL(a.eta, b2.eta, 1e-12);
            ENSURE_REL(a.lambda, b2.lambda, 1e-12);
            ENSURE(ce_rel2d_compute(zs[i], 8, law, &fine, &b, &why) == 0);
            ENSURE_REL(a.eta, b.eta, 1e-7);
            ENSURE_REL(a.lambda, b.lambda, 1e-7);
            if (zs[i] > 0.0)
                ENSURE_REL(a.zeta, b.zeta, zs[i] < 0.1 ? 1e-5 : 1e-7);
        }
    }
}

/* --- an independent Monte Carlo of the relativistic first approximation at z = 1 --- */
typedef struct {
    double E, x, y;
} mom2;

/* 2-D Jüttner, m = 1: K has density (K + 1) e^-K / 2, half Exp(1), half Gamma(2). */
static mom2 draw_juttner(rc_rng *r)
{
    double K = -log(1.0 - rc_rng_uniform(r));
    if (rc_rng_uniform(r) < 0.5)
        K -= log(1.0 - rc_rng_uniform(r));
    const double p = sqrt(K * (K + 2.0)), ph = 2.0 * M_PI * rc_rng_uniform(r);
    return (mom2){K + 1.0, p * cos(ph), p * sin(ph)};
}

/* boost of (E, x, y) into the frame moving with velocity (bx, by) */
static mom2 boost2(mom2 p, double bx, double by)
{
    const double b2 = bx * bx + by * by, g = 1.0 / sqrt(1.0 - b2), bp = bx * p.x + by * p.y;
    const double k = b2 > 0.0 ? (g - 1.0) * bp / b2 : 0.0;
    return (mom2){g * (p.E - bp), p.x + (k - g * p.E) * bx, p.y + (k - g * p.E) * by};
}

static void mc_first(int disc, double *eta, double *ee, double *lam, double *el)
{
    rc_rng r = {disc ? 20261203 : 20261202};
    const int n = 1000000;
    double as = 0.0, as2 = 0.0, ah = 0.0, ah2 = 0.0;
    for (int i = 0; i < n; i++) {
        const mom2 p0 = draw_juttner(&r), p1 = draw_juttner(&r);
        const double pp = p0.E * p1.E - p0.x * p1.x - p0.y * p1.y;
        const double vm = sqrt(pp * pp - 1.0) / (p0.E * p1.E);
        const double Et = p0.E + p1.E, bx = (p0.x + p1.x) / Et, by = (p0.y + p1.y) / Et;
        const mom2 s0 = boost2(p0, bx, by);
        const double q = sqrt(s0.x * s0.x + s0.y * s0.y), th = atan2(s0.y, s0.x);
        /* out direction: isotropic, or the hard-disc reflection at impact parameter b */
        const double bimp = 2.0 * rc_rng_uniform(&r) - 1.0;
        const double to = disc ? th + M_PI - 2.0 * asin(bimp) : 2.0 * M_PI * rc_rng_uniform(&r);
        const mom2 f0 = boost2((mom2){s0.E, q * cos(to), q * sin(to)}, -bx, -by);
        const mom2 f1 = boost2((mom2){s0.E, -q * cos(to), -q * sin(to)}, -bx, -by);
        const mom2 pv[4] = {p0, p1, f0, f1};
        static const double sg[4] = {1, 1, -1, -1};
        double txx = 0.0, txy = 0.0, vx = 0.0, vy = 0.0;
        for (int k = 0; k < 4; k++) {
            txx += sg[k] * 0.5 * (pv[k].x * pv[k].x - pv[k].y * pv[k].y);
            txy += sg[k] * pv[k].x * pv[k].y;
            vx += sg[k] * (pv[k].E - 1.0) * pv[k].x; /* K p^a: (2 - K) p^a less the invariant */
            vy += sg[k] * (pv[k].E - 1.0) * pv[k].y;
        }
        const double ts = vm * (2.0 * txx * txx + 2.0 * txy * txy) / 4.0,
                     th2 = vm * (vx * vx + vy * vy) / 4.0;
        as += ts, as2 += ts * ts, ah += th2, ah2 += th2 * th2;
    }
    as /= n, ah /= n;
    const double eas = sqrt((as2 / n - as * as) / n) / as, eah = sqrt((ah2 / n - ah * ah) / n) / ah;
    /* sources by adaptive quadrature (exact to 1e-12): h_K = <K> + kT */
    const double Z = jm_int(1.0, 0, 0), hk = jm_int(1.0, 0, 1) / Z + 1.0;
    const double bs = jm_int(1.0, 0, 3) / Z, bh = jm_int(1.0, hk, 4) / Z;
    *eta = bs * bs / (4.0 * as), *ee = eas;
    *lam = bh * bh / (2.0 * ah), *el = eah;
}

static void test_monte_carlo_z1(void)
{
    for (int disc = 0; disc < 2; disc++) {
        double eta, ee, lam, el;
        mc_first(disc, &eta, &ee, &lam, &el);
        const ce_rel_coeffs c = at(1.0, 1, disc ? CE_REL2D_HARD_DISC : CE_REL2D_ISOTROPIC);
        /* 4 standard errors of the bracket (the sources are exact) */
        ENSURE_CLOSE(eta, c.eta, 4.0 * ee, c.eta);
        ENSURE_CLOSE(lam, c.lambda, 4.0 * el, c.lambda);
        printf("  z = 1, %s law, first approximation: Monte Carlo eta %.5f +- %.2g %%, lambda "
               "%.5f +- %.2g %%; quadrature %.6f %.6f\n",
               disc ? "hard-disc" : "isotropic", eta, 100.0 * ee, lam, 100.0 * el, c.eta,
               c.lambda);
    }
}

static void test_bad_input(void)
{
    ce_rel_coeffs c;
    const char *why = NULL;
    ENSURE(ce_rel2d_compute(-1.0, 1, CE_REL2D_ISOTROPIC, NULL, &c, &why) == -1 && why);
    ENSURE(ce_rel2d_compute(NAN, 1, CE_REL2D_ISOTROPIC, NULL, &c, &why) == -1);
    ENSURE(ce_rel2d_compute(INFINITY, 1, CE_REL2D_ISOTROPIC, NULL, &c, &why) == -1);
    ENSURE(ce_rel2d_compute(1.0, 0, CE_REL2D_ISOTROPIC, NULL, &c, &why) == -1);
    ENSURE(ce_rel2d_compute(1.0, CE_REL2D_MAX_ORDER + 1, CE_REL2D_ISOTROPIC, NULL, &c, &why) == -1);
    ENSURE(ce_rel2d_compute(1.0, 1, CE_REL2D_NLAW, NULL, &c, &why) == -1);
    ENSURE(ce_rel2d_compute(1.0, 1, (ce_rel2d_law)-1, NULL, &c, &why) == -1);
    const ce_rel2d_quad few = {64, 48, 2 * (8 + 2)}; /* too few angles for 8 functions */
    ENSURE(ce_rel2d_compute(1.0, 8, CE_REL2D_ISOTROPIC, &few, &c, &why) == -1);
    const ce_rel2d_quad bad = {2, 48, 48};
    ENSURE(ce_rel2d_compute(1.0, 1, CE_REL2D_ISOTROPIC, &bad, &c, &why) == -1);
    ENSURE(ce_rel2d_juttner_moments(-0.5, &(ce_rel_juttner){0}, &why) == -1);
    ENSURE(ce_rel2d_law_name(CE_REL2D_HARD_DISC) && !ce_rel2d_law_name(CE_REL2D_NLAW));
}

int main(void)
{
    gsl_set_error_handler_off();
    RUN_TEST(test_juttner_moments);
    RUN_TEST(test_massless);
    RUN_TEST(test_classical);
    RUN_TEST(test_quadrature_converged);
    RUN_TEST(test_monte_carlo_z1);
    RUN_TEST(test_bad_input);
    RC_TEST_MAIN_END();
}
