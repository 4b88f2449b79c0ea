/* ce_rel2d.c — Chapman–Enskog eta, lambda, zeta of the 2-D invariant Boltzmann gas, on
 * Laguerre trial functions in the kinetic energy; the collision brackets by Gauss quadrature
 * over the pair's invariant mass and boost and by harmonics on the CM circle, where the
 * angular law enters only through its cosine moments gamma_k;
 * papers/transport-2d.md has the derivation and the checks. */
#include "ce_rel2d.h"

#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_linalg.h>

enum { C2_SHEAR, C2_HEAT, C2_BULK, C2_NSET };

/* Laguerre parameter per set: d/2 + 1, d/2, d/2 - 1 (the 2-D Sonine polynomials). */
static const double c2_alpha[C2_NSET] = {2.0, 1.0, 0.0};
/* First degree per set: 1 and K (scalars) and p (vectors) are collision invariants. */
static const int c2_first[C2_NSET] = {0, 1, 2};
/* (d - 1)(d + 2) for the traceless tensor (Pi = -2 eta grad<u>), d for the vector. */
static const double c2_ncomp[C2_NSET] = {4.0, 2.0, 1.0};

#define C2_MAX_DEG (CE_REL2D_MAX_ORDER + 2)
#define C2_MAX_ANG 400
#define C2_MAX_HARM (C2_MAX_ANG / 2)

/* gamma_k = int g(chi) cos(k chi) dchi of the normalised CM law g. */
static double gamma_isotropic(int k)
{
    return k == 0 ? 1.0 : 0.0;
}

/* g = |sin(chi/2)|/4: uniform impact parameter b = sigma cos(chi/2) on a disc. */
static double gamma_hard_disc(int k)
{
    return 1.0 / (1.0 - 4.0 * k * k);
}

static const struct {
    const char *name;
    double (*gamma)(int k);
} c2_laws[CE_REL2D_NLAW] = {
    [CE_REL2D_ISOTROPIC] = {"isotropic", gamma_isotropic},
    [CE_REL2D_HARD_DISC] = {"hard-disc", gamma_hard_disc},
};

const char *ce_rel2d_law_name(ce_rel2d_law law)
{
    return (int)law >= 0 && law < CE_REL2D_NLAW ? c2_laws[law].name : NULL;
}

ce_rel2d_quad ce_rel2d_quad_default(void)
{
    return (ce_rel2d_quad){.n_u = 64, .n_w = 48, .n_ang = 0};
}

/* L_k^(a)(x) for k = 0 .. n - 1, by the three-term recurrence. */
static void laguerre(double x, double a, int n, double *L)
{
    L[0] = 1.0;
    if (n > 1)
        L[1] = 1.0 + a - x;
    for (int k = 1; k + 1 < n; k++)
        L[k + 1] = ((2.0 * k + 1.0 + a - x) * L[k] - (k + a) * L[k - 1]) / (k + 1.0);
}

static int check_z(double z, const char **why)
{
    if (!(isfinite(z) && z >= 0.0)) {
        *why = "z = m c^2 / kT must be finite and >= 0";
        return -1;
    }
    return 0;
}

int ce_rel2d_juttner_moments(double z, ce_rel_juttner *out, const char **why)
{
    if (check_z(z, why))
        return -1;
    /* d^2p = 2 pi E dE: int_m^inf E^n e^-(E - m) dE are polynomials in m */
    out->z_scaled = 2.0 * M_PI * (1.0 + z);
    out->mean_k = (z + 2.0) / (z + 1.0);
    out->var_k = (z * z + 4.0 * z + 2.0) / ((z + 1.0) * (z + 1.0));
    return 0;
}

/* Source of each set against one trial function's scalar factor, times the 2-D Jüttner
 * jacobian E (d^2p = 2 pi E dK): polynomials in K, so Gauss–Laguerre is exact. The bulk
 * source Q = p^2/(2E) - 1 - (K - <K>)/var K is written so that nothing cancels at large z:
 * Q = (K (2z + 1) - z)/(z^2 + 4z + 2) - K^2/(2E), classically -L_2(K)/z. */
static double source_times_e(int set, double K, double m, double mean_k)
{
    const double E = K + m, p2 = K * (K + 2.0 * m);
    if (set == C2_SHEAR)
        return 0.5 * p2 * p2; /* E . p^<ab> p_<ab>/E, p^<ab> p_<ab> = p^4/2 */
    if (set == C2_HEAT)
        return (K - (mean_k + 1.0)) * p2; /* E . p^a (E - h) v^a */
    return E * (K * (2.0 * m + 1.0) - m) / (m * m + 4.0 * m + 2.0) - 0.5 * K * K;
}

/* The pair at one (u, w) node, P along x: CM momentum p*, and the boost's products
 * sinh chi E*, sinh chi p*, cosh chi p* (as in ce_rel.c). Ball 0 at CM angle t has
 * K0 = kin + sh_p cos t, p0 = (sh_E + ch_p cos t, p* sin t); ball 1 has t + pi. */
typedef struct {
    double rs, ps, sh_E, sh_p, ch_p, kin;
} c2_node;

static c2_node node_at(double m, double u, double w)
{
    c2_node n;
    n.rs = u + 2.0 * m;
    n.ps = 0.5 * sqrt(u * (u + 4.0 * m));
    const double root = sqrt(w * (2.0 * n.rs + w)); /* sqrt(s) sinh chi */
    n.sh_E = 0.5 * root;
    n.sh_p = n.rs > 0.0 ? root * n.ps / n.rs : 0.0;
    n.ch_p = n.rs > 0.0 ? n.ps + w * n.ps / n.rs : 0.0;
    n.kin = 0.5 * (u + w);
    return n;
}

/* Harmonic amplitudes of Psi_i = psi_i(ball 0) + psi_i(ball 1) on the CM circle, per
 * set, function and component: Psi = a_0 + sum_k (C_k cos kt + S_k sin kt). With P along
 * x, t -> -t mirrors the pair (y -> -y): the xx, x and scalar components are even (C only),
 * xy and y odd (S only), so H holds C_k for component 0 and S_k for component 1. */
typedef struct {
    double H[C2_NSET][CE_REL2D_MAX_ORDER][2][C2_MAX_HARM];
} c2_harm;

/* Components per set and their weights in the full contraction: the traceless symmetric
 * tensor's xx and xy (T:T' = 2 T_xx T'_xx + 2 T_xy T'_xy), the vector's x and y, the
 * scalar. */
static const int c2_ncmp[C2_NSET] = {2, 2, 1};
static const double c2_cw[C2_NSET] = {2.0, 1.0, 1.0};

typedef struct {
    int n_ang, n_harm;
    double cs[C2_MAX_ANG][C2_MAX_HARM + 1], sn[C2_MAX_ANG][C2_MAX_HARM + 1];
} c2_circle;

static void node_harmonics(double m, double u, double w, int N, const c2_circle *cc, c2_harm *h)
{
    const c2_node nd = node_at(m, u, w);
    const int na = cc->n_ang, nh = cc->n_harm;
    for (int s = 0; s < C2_NSET; s++)
        for (int i = 0; i < N; i++)
            for (int c = 0; c < 2; c++)
                for (int k = 0; k < nh; k++)
                    h->H[s][i][c][k] = 0.0;
    for (int a = 0; a < na; a++) {
        const double ct = cc->cs[a][1], st = cc->sn[a][1];
        const double K0 = nd.kin + nd.sh_p * ct, K1 = nd.kin - nd.sh_p * ct;
        const double x0 = nd.sh_E + nd.ch_p * ct, x1 = nd.sh_E - nd.ch_p * ct;
        const double y0 = nd.ps * st, y1 = -y0;
        double L0[C2_MAX_DEG + 1], L1[C2_MAX_DEG + 1];
        for (int s = 0; s < C2_NSET; s++) {
            laguerre(K0, c2_alpha[s], c2_first[s] + N, L0);
            laguerre(K1, c2_alpha[s], c2_first[s] + N, L1);
            for (int i = 0; i < N; i++) {
                const double l0 = L0[c2_first[s] + i], l1 = L1[c2_first[s] + i];
                double v[2];
                if (s == C2_SHEAR) { /* xx, xy of p^<a p^b> */
                    v[0] = 0.5 * (l0 * (x0 * x0 - y0 * y0) + l1 * (x1 * x1 - y1 * y1));
                    v[1] = l0 * x0 * y0 + l1 * x1 * y1;
                } else if (s == C2_HEAT) {
                    v[0] = l0 * x0 + l1 * x1;
                    v[1] = l0 * y0 + l1 * y1;
                } else {
                    v[0] = l0 + l1;
                    v[1] = 0.0;
                }
                double *h0 = h->H[s][i][0], *h1 = h->H[s][i][1];
                const double *ck = cc->cs[a] + 1, *sk = cc->sn[a] + 1;
                for (int k = 0; k < nh; k++)
                    h0[k] += v[0] * ck[k];
                if (c2_ncmp[s] > 1)
                    for (int k = 0; k < nh; k++)
                        h1[k] += v[1] * sk[k];
            }
        }
    }
    for (int s = 0; s < C2_NSET; s++)
        for (int i = 0; i < N; i++)
            for (int c = 0; c < 2; c++)
                for (int k = 0; k < nh; k++)
                    h->H[s][i][c][k] *= 2.0 / na;
}

static int check_quad(const ce_rel2d_quad *q, int order, const char **why)
{
    if (q->n_u < 4 || q->n_u > 400 || q->n_w < 4 || q->n_w > 400) {
        *why = "quadrature sizes n_u, n_w must lie in 4 .. 400";
        return -1;
    }
    if (q->n_ang <= 2 * (order + 2) || q->n_ang > C2_MAX_ANG) {
        *why = "n_ang must exceed 2 (order + 2) (the trial functions' degree on the circle) "
               "and be at most 400";
        return -1;
    }
    return 0;
}

/* b_i = <psi_i, S> per set (contracted), Jüttner-normalised: Gauss–Laguerre in K with
 * 48 nodes integrates the degree <= order + 5 polynomials exactly. */
static int source_moments(double m, const ce_rel_juttner *J, int N,
                          double b[C2_NSET][CE_REL2D_MAX_ORDER], const char **why)
{
    gsl_integration_fixed_workspace *g =
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, 48, 0.0, 1.0, 0.0, 0.0);
    if (!g) {
        *why = "out of memory";
        return -1;
    }
    const double *x = gsl_integration_fixed_nodes(g), *wt = gsl_integration_fixed_weights(g);
    for (int s = 0; s < C2_NSET; s++)
        for (int i = 0; i < N; i++)
            b[s][i] = 0.0;
    for (int n = 0; n < 48; n++) {
        for (int s = 0; s < C2_NSET; s++) {
            double L[C2_MAX_DEG + 1];
            laguerre(x[n], c2_alpha[s], c2_first[s] + N, L);
            const double src = 2.0 * M_PI * source_times_e(s, x[n], m, J->mean_k);
            for (int i = 0; i < N; i++)
                b[s][i] += wt[n] * L[c2_first[s] + i] * src;
        }
    }
    gsl_integration_fixed_free(g);
    for (int s = 0; s < C2_NSET; s++)
        for (int i = 0; i < N; i++)
            b[s][i] /= J->z_scaled;
    return 0;
}

/* b^T A^-1 b by Jacobi-scaled Cholesky; A is a Gram matrix off the invariants. */
static int galerkin(int N, double A[CE_REL2D_MAX_ORDER][CE_REL2D_MAX_ORDER], const double *b,
                    double *out)
{
    double am[CE_REL2D_MAX_ORDER * CE_REL2D_MAX_ORDER], bv[CE_REL2D_MAX_ORDER],
        xv[CE_REL2D_MAX_ORDER], d[CE_REL2D_MAX_ORDER];
    for (int i = 0; i < N; i++) {
        if (!(A[i][i] > 0.0))
            return -1;
        d[i] = 1.0 / sqrt(A[i][i]);
    }
    for (int i = 0; i < N; i++) {
        bv[i] = b[i] * d[i];
        for (int j = 0; j < N; j++)
            am[i * N + j] = (j <= i ? A[i][j] : A[j][i]) * d[i] * d[j];
    }
    gsl_matrix_view mv = gsl_matrix_view_array(am, N, N);
    gsl_vector_view bw = gsl_vector_view_array(bv, N), xw = gsl_vector_view_array(xv, N);
    if (gsl_linalg_cholesky_decomp1(&mv.matrix) ||
        gsl_linalg_cholesky_solve(&mv.matrix, &bw.vector, &xw.vector))
        return -1;
    double r = 0.0;
    for (int i = 0; i < N; i++)
        r += bv[i] * xv[i];
    *out = r;
    return 0;
}

int ce_rel2d_compute(double z, int order, ce_rel2d_law law, const ce_rel2d_quad *q,
                     ce_rel_coeffs *out, const char **why)
{
    if (check_z(z, why))
        return -1;
    if (order < 1 || order > CE_REL2D_MAX_ORDER) {
        *why = "order (trial functions per coefficient) must be 1 .. CE_REL2D_MAX_ORDER";
        return -1;
    }
    if (!ce_rel2d_law_name(law)) {
        *why = "unknown angular law";
        return -1;
    }
    ce_rel2d_quad qd = q ? *q : ce_rel2d_quad_default();
    if (qd.n_ang == 0) /* the fewest angles that resolve the trial functions exactly */
        qd.n_ang = 2 * (order + 2) + 2;
    if (check_quad(&qd, order, why))
        return -1;
    const int N = order;
    const double m = z;
    ce_rel_juttner J;
    ce_rel2d_juttner_moments(z, &J, why);
    double b[C2_NSET][CE_REL2D_MAX_ORDER];
    if (source_moments(m, &J, N, b, why))
        return -1;

    c2_circle *cc = malloc(sizeof *cc);
    c2_harm *h = malloc(sizeof *h);
    /* u: weight u^1/2 e^-u with p* = u^1/2 sqrt(u + 4m)/2 left over; massless p* = u/2,
     * weight u e^-u (then the integrand is a polynomial in u). w: weight e^-w. */
    const double alpha_u = m > 0.0 ? 0.5 : 1.0;
    gsl_integration_fixed_workspace *gu =
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, qd.n_u, 0.0, 1.0, alpha_u, 0.0);
    gsl_integration_fixed_workspace *gw =
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, qd.n_w, 0.0, 1.0, 0.0, 0.0);
    if (!cc || !h || !gu || !gw) {
        free(cc);
        free(h);
        gsl_integration_fixed_free(gu);
        gsl_integration_fixed_free(gw);
        *why = "out of memory";
        return -1;
    }
    cc->n_ang = qd.n_ang;
    cc->n_harm = qd.n_ang / 2 - 1; /* harmonics resolved without aliasing */
    if (cc->n_harm > N + 2)
        cc->n_harm = N + 2; /* the trial functions' degree on the circle */
    for (int a = 0; a < qd.n_ang; a++) {
        const double t = 2.0 * M_PI * (a + 0.5) / qd.n_ang;
        for (int k = 0; k <= cc->n_harm; k++) {
            cc->cs[a][k] = cos(k * t);
            cc->sn[a][k] = sin(k * t);
        }
    }
    double one_minus_gamma[C2_MAX_HARM];
    for (int k = 1; k <= cc->n_harm; k++)
        one_minus_gamma[k - 1] = 1.0 - c2_laws[law].gamma(k);

    /* [psi_i, psi_j] = (1/4) int d^3P e^-(P0 - 2m) p* / Z^2 . 2 pi sum_k (1 - gamma_k)
     * (C_k C'_k + S_k S'_k), d^3P = 2 pi sqrt(s) du dw (papers/transport-2d.md) */
    double A[C2_NSET][CE_REL2D_MAX_ORDER][CE_REL2D_MAX_ORDER] = {{{0}}};
    const double *xu = gsl_integration_fixed_nodes(gu), *wu = gsl_integration_fixed_weights(gu);
    const double *xw = gsl_integration_fixed_nodes(gw), *ww = gsl_integration_fixed_weights(gw);
    const double Z2 = J.z_scaled * J.z_scaled;
    for (int iu = 0; iu < qd.n_u; iu++)
        for (int iw = 0; iw < qd.n_w; iw++) {
            const double u = xu[iu], w = xw[iw], rs = u + 2.0 * m;
            const double ps_left = m > 0.0 ? 0.5 * sqrt(u + 4.0 * m) : 0.5;
            const double meas = wu[iu] * ww[iw] * M_PI * M_PI * rs * ps_left / Z2;
            node_harmonics(m, u, w, N, cc, h);
            for (int s = 0; s < C2_NSET; s++)
                for (int i = 0; i < N; i++)
                    for (int j = 0; j <= i; j++) {
                        double acc = 0.0;
                        for (int c = 0; c < c2_ncmp[s]; c++) {
                            const double *Hi = h->H[s][i][c], *Hj = h->H[s][j][c];
                            double t = 0.0;
                            for (int k = 0; k < cc->n_harm; k++)
                                t += one_minus_gamma[k] * Hi[k] * Hj[k];
                            acc += c2_cw[s] * t;
                        }
                        A[s][i][j] += meas * acc;
                    }
        }
    free(cc);
    free(h);
    gsl_integration_fixed_free(gu);
    gsl_integration_fixed_free(gw);

    double coef[C2_NSET];
    for (int s = 0; s < C2_NSET; s++) {
        if (s == C2_BULK && m == 0.0) { /* conformal: Q = 0 identically */
            coef[s] = 0.0;
            continue;
        }
        double r;
        if (galerkin(N, A[s], b[s], &r)) {
            *why = "a collision-bracket matrix is not positive definite";
            return -1;
        }
        coef[s] = r / c2_ncomp[s];
    }
    out->eta = coef[C2_SHEAR];
    out->lambda = coef[C2_HEAT];
    out->zeta = coef[C2_BULK];
    return 0;
}
