/* ce_rel.c — Chapman–Enskog eta, lambda, zeta of the invariant Boltzmann gas with an
 * isotropic cross-section, on Laguerre trial functions in the kinetic energy, the
 * collision brackets by Gauss quadrature over the pair's invariant mass, boost and CM
 * angle (papers/transport.md, section 6, has the derivation and the checks). */
#include "ce_rel.h"

#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_linalg.h>

enum { CE_SHEAR, CE_HEAT, CE_BULK, CE_NSET };

/* Laguerre parameter per set: classically the Sonine polynomials S_{5/2} (shear) and
 * S_{3/2} (heat), which keep the Gram matrix well conditioned at every z. */
static const double ce_alpha[CE_NSET] = {2.5, 1.5, 0.5};
/* First polynomial degree per set: 1 and K (scalars) and p (vectors) are collision
 * invariants; their brackets vanish. */
static const int ce_first[CE_NSET] = {0, 1, 2};
/* Components of one isotropic tensor that the contracted bracket counts: the traceless
 * symmetric tensor's 10 per xy component, the vector's 3, the scalar's 1. */
static const double ce_ncomp[CE_NSET] = {10.0, 3.0, 1.0};

#define CE_MAX_DEG (CE_REL_MAX_ORDER + 2)

ce_rel_quad ce_rel_quad_default(void)
{
    return (ce_rel_quad){.n_u = 64, .n_w = 64, .n_cos = 24};
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

typedef struct {
    double m, mean_k, var_k;
    int set, deg; /* which source and basis function; set < 0: moment K^deg */
} ce_moment;

/* d^3p e^-(E - m) g(K) / dK = 4 pi p E g(K), with the source contracted against one
 * basis function (or a power of K for the moments). */
static double moment_integrand(double K, void *vp)
{
    const ce_moment *c = vp;
    const double m = c->m, E = K + m, p2 = K * (K + 2.0 * m);
    const double jac = 4.0 * M_PI * sqrt(p2) * E * exp(-K);
    if (c->set < 0)
        return jac * pow(K, c->deg);
    double L[CE_MAX_DEG + 1];
    laguerre(K, ce_alpha[c->set], c->deg + 1, L);
    double src;
    if (c->set == CE_SHEAR)
        src = (2.0 / 3.0) * p2 * p2 / E; /* p^<ab> . p^<ab>/E */
    else if (c->set == CE_HEAT)
        src = (K - (c->mean_k + 1.0)) * p2 / E; /* p^a . (E - h) v^a */
    else
        src = p2 / (3.0 * E) - 1.0 - (K - c->mean_k) / c->var_k; /* Q */
    return jac * L[c->deg] * src;
}

static int integrate(ce_moment *c, double epsabs, double *out)
{
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(2000);
    if (!ws)
        return -1;
    gsl_function f = {moment_integrand, c};
    double err;
    const int st = gsl_integration_qagiu(&f, 0.0, epsabs, 1e-10, 2000, ws, out, &err);
    gsl_integration_workspace_free(ws);
    /* round-off may stop qagiu short of 1e-10; its estimate must still be small */
    return st == GSL_SUCCESS || (st == GSL_EROUND && err <= 1e-8 * fabs(*out) + epsabs) ? 0 : -1;
}

static int check_z(double z, const char **why)
{
    if (!(isfinite(z) && z >= 0.0)) {
        *why = "z = m c^2 / kT must be finite and >= 0";
        return -1;
    }
    return 0;
}

int ce_rel_juttner_moments(double z, ce_rel_juttner *out, const char **why)
{
    if (check_z(z, why))
        return -1;
    double mom[3];
    for (int k = 0; k < 3; k++) {
        ce_moment c = {.m = z, .set = -1, .deg = k};
        if (integrate(&c, 0.0, &mom[k])) {
            *why = "a Juttner moment's quadrature did not converge";
            return -1;
        }
    }
    out->z_scaled = mom[0];
    out->mean_k = mom[1] / mom[0];
    out->var_k = mom[2] / mom[0] - out->mean_k * out->mean_k;
    return 0;
}

/* The three Gauss rules of the pair integrals: u (weight e^-u), w (w^1/2 e^-w), cos. */
typedef struct {
    gsl_integration_fixed_workspace *u, *w, *c;
} ce_rules;

static void rules_free(ce_rules *r)
{
    gsl_integration_fixed_free(r->u);
    gsl_integration_fixed_free(r->w);
    gsl_integration_fixed_free(r->c);
}

static int rules_alloc(const ce_rel_quad *q, ce_rules *r, const char **why)
{
    r->u = gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, q->n_u, 0.0, 1.0, 0.0, 0.0);
    r->w = gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, q->n_w, 0.0, 1.0, 0.5, 0.0);
    r->c = gsl_integration_fixed_alloc(gsl_integration_fixed_legendre, q->n_cos, -1.0, 1.0, 0.0, 0.0);
    if (r->u && r->w && r->c)
        return 0;
    rules_free(r);
    *why = "out of memory";
    return -1;
}

/* The pair at one (u, w) node, P along z: CM momentum p*, and the boost's products
 * sinh chi E*, sinh chi p*, cosh chi p*, cosh chi E* - m, written without cancellation
 * (at m = 0 and small s as well). Ball 0 at CM angle cos t has K0 = kin + sh_p cos t,
 * p0 = (p* sin t, 0, sh_E + ch_p cos t); ball 1 the same with cos t -> -cos t, -px. */
typedef struct {
    double rs, ps2, ps, sh_E, sh_p, ch_p, kin;
} ce_node;

static ce_node node_at(double m, double u, double w)
{
    ce_node n;
    n.rs = u + 2.0 * m;
    n.ps2 = u * (0.25 * u + m);
    n.ps = sqrt(n.ps2);
    const double root = sqrt(w * (2.0 * n.rs + w)); /* sqrt(s) sinh chi */
    n.sh_E = 0.5 * root;
    n.sh_p = root * n.ps / n.rs;
    n.ch_p = n.ps + w * n.ps / n.rs;
    n.kin = 0.5 * (u + w);
    return n;
}

/* One (u, w) node's pair: Psi_i summed over both balls at each CM angle, contracted
 * over components; G accumulates int dcos Psi_i . Psi_j, M the mean's axial part
 * (the means are axial about the pair's momentum P, the zz component fixes them). */
typedef struct {
    double G[CE_NSET][CE_REL_MAX_ORDER][CE_REL_MAX_ORDER];
    double M[CE_NSET][CE_REL_MAX_ORDER];
} ce_angles;

static void pair_angles(double m, double u, double w, int N, const gsl_integration_fixed_workspace *gc,
                        ce_angles *a)
{
    const ce_node nd = node_at(m, u, w);
    const double ps = nd.ps, sh_E = nd.sh_E, sh_p = nd.sh_p, ch_p = nd.ch_p, kin = nd.kin;
    const double *xc = gsl_integration_fixed_nodes(gc), *wc = gsl_integration_fixed_weights(gc);
    const int nc = (int)gsl_integration_fixed_n(gc);
    for (int s = 0; s < CE_NSET; s++)
        for (int i = 0; i < N; i++) {
            a->M[s][i] = 0.0;
            for (int j = 0; j < N; j++)
                a->G[s][i][j] = 0.0;
        }
    for (int c = 0; c < nc; c++) {
        const double ct = xc[c], st = sqrt(fmax(0.0, 1.0 - ct * ct)), wt = wc[c];
        const double K0 = kin + sh_p * ct, K1 = kin - sh_p * ct;
        const double px = ps * st, p0z = sh_E + ch_p * ct, p1z = sh_E - ch_p * ct;
        const double q0 = px * px + p0z * p0z, q1 = px * px + p1z * p1z;
        double L0[CE_MAX_DEG + 1], L1[CE_MAX_DEG + 1];
        double T[CE_NSET][CE_REL_MAX_ORDER][4];
        for (int s = 0; s < CE_NSET; s++) {
            laguerre(K0, ce_alpha[s], ce_first[s] + N, L0);
            laguerre(K1, ce_alpha[s], ce_first[s] + N, L1);
            for (int i = 0; i < N; i++) {
                const double l0 = L0[ce_first[s] + i], l1 = L1[ce_first[s] + i];
                double *t = T[s][i];
                if (s == CE_SHEAR) { /* xx, yy, zz, xz of p^<a p^b> */
                    t[0] = l0 * (px * px - q0 / 3.0) + l1 * (px * px - q1 / 3.0);
                    t[1] = -(l0 * q0 + l1 * q1) / 3.0;
                    t[2] = l0 * (p0z * p0z - q0 / 3.0) + l1 * (p1z * p1z - q1 / 3.0);
                    t[3] = l0 * px * p0z - l1 * px * p1z;
                } else if (s == CE_HEAT) { /* x, z of p^a (ball 1 has -px) */
                    t[0] = (l0 - l1) * px;
                    t[2] = l0 * p0z + l1 * p1z;
                    t[1] = t[3] = 0.0;
                } else {
                    t[2] = l0 + l1;
                    t[0] = t[1] = t[3] = 0.0;
                }
            }
            for (int i = 0; i < N; i++) {
                const double *ti = T[s][i];
                a->M[s][i] += wt * ti[2];
                for (int j = 0; j <= i; j++) {
                    const double *tj = T[s][j];
                    a->G[s][i][j] += wt * (ti[0] * tj[0] + ti[1] * tj[1] + ti[2] * tj[2] +
                                           2.0 * ti[3] * tj[3]);
                }
            }
        }
    }
}

static int check_quad(const ce_rel_quad *q, const char **why)
{
    if (q->n_u < 4 || q->n_u > 400 || q->n_w < 4 || q->n_w > 400 || q->n_cos < 4 ||
        q->n_cos > 400) {
        *why = "quadrature sizes must lie in 4 .. 400";
        return -1;
    }
    return 0;
}

int ce_rel_pair_speeds(double z, const ce_rel_quad *q, double *v_moller, double *v_rel,
                       const char **why)
{
    const ce_rel_quad qd = q ? *q : ce_rel_quad_default();
    ce_rel_juttner J;
    if (check_z(z, why) || check_quad(&qd, why) || ce_rel_juttner_moments(z, &J, why))
        return -1;
    ce_rules R;
    if (rules_alloc(&qd, &R, why))
        return -1;
    const double m = z, Z2 = J.z_scaled * J.z_scaled;
    const double *xu = gsl_integration_fixed_nodes(R.u), *wu = gsl_integration_fixed_weights(R.u);
    const double *xw = gsl_integration_fixed_nodes(R.w), *ww = gsl_integration_fixed_weights(R.w);
    const double *xc = gsl_integration_fixed_nodes(R.c), *wc = gsl_integration_fixed_weights(R.c);
    double sm = 0.0, sr = 0.0;
    for (int iu = 0; iu < qd.n_u; iu++)
        for (int iw = 0; iw < qd.n_w; iw++) {
            const double u = xu[iu], w = xw[iw];
            const ce_node nd = node_at(m, u, w);
            const double rs = nd.rs, ps2 = nd.ps2, ps = nd.ps, sh_E = nd.sh_E, sh_p = nd.sh_p,
                         ch_p = nd.ch_p, kin = nd.kin;
            /* d^4P e^-(P0 - 2m), as in ce_rel_compute */
            const double d4p = wu[iu] * ww[iw] * 4.0 * M_PI * rs * sqrt(2.0 * rs + w) / Z2;
            /* d^3p d^3p1 v_M = p*^2 dOmega d^4P */
            sm += d4p * 4.0 * M_PI * ps2;
            /* d^3p d^3p1 = E0 E1 (p* / sqrt s) dOmega d^4P: <|v0 - v1|> = |E1 p0 - E0 p1| */
            double ang = 0.0;
            for (int c = 0; c < qd.n_cos; c++) {
                const double ct = xc[c], st = sqrt(fmax(0.0, 1.0 - ct * ct));
                const double E0 = m + kin + sh_p * ct, E1 = m + kin - sh_p * ct;
                const double px = ps * st, p0z = sh_E + ch_p * ct, p1z = sh_E - ch_p * ct;
                const double dx = E1 * px + E0 * px, dz = E1 * p0z - E0 * p1z;
                ang += wc[c] * sqrt(dx * dx + dz * dz);
            }
            sr += d4p * 2.0 * M_PI * (ps / rs) * ang;
        }
    rules_free(&R);
    *v_moller = sm;
    *v_rel = sr;
    return 0;
}

int ce_rel_compute(double z, int order, const ce_rel_quad *q, ce_rel_coeffs *out,
                   const char **why)
{
    if (check_z(z, why))
        return -1;
    if (order < 1 || order > CE_REL_MAX_ORDER) {
        *why = "order (trial functions per coefficient) must be 1 .. CE_REL_MAX_ORDER";
        return -1;
    }
    const ce_rel_quad qd = q ? *q : ce_rel_quad_default();
    if (check_quad(&qd, why))
        return -1;
    ce_rel_juttner J;
    if (ce_rel_juttner_moments(z, &J, why))
        return -1;
    const int N = order;
    const double m = z;
    double b[CE_NSET][CE_REL_MAX_ORDER];
    for (int s = 0; s < CE_NSET; s++)
        for (int i = 0; i < N; i++) {
            ce_moment c = {.m = m, .mean_k = J.mean_k, .var_k = J.var_k, .set = s,
                           .deg = ce_first[s] + i};
            /* absolute floor from the first function's moment: classically the higher
             * ones vanish (Sonine orthogonality), and the bulk source does at z = 0 */
            const double floor_abs = J.z_scaled * fmax(1e-13, i ? 1e-11 * fabs(b[s][0]) : 0.0);
            if (integrate(&c, floor_abs, &b[s][i])) {
                *why = "a source moment's quadrature did not converge";
                return -1;
            }
            b[s][i] /= J.z_scaled;
        }

    /* Pair measure d^3p d^3p1 v_Moller sigma* dOmega' = p*^2 dOmega dOmega' d^4P / (4 pi),
     * d^4P e^-(P0 - 2m) = 4 pi sqrt(s) sqrt(2 sqrt(s) + w) [e^-u du] [w^1/2 e^-w dw]. */
    ce_rules R;
    if (rules_alloc(&qd, &R, why))
        return -1;
    ce_angles *ang = malloc(sizeof *ang);
    if (!ang) {
        rules_free(&R);
        *why = "out of memory";
        return -1;
    }
    double A[CE_NSET][CE_REL_MAX_ORDER][CE_REL_MAX_ORDER] = {{{0}}};
    const double *xu = gsl_integration_fixed_nodes(R.u), *wu = gsl_integration_fixed_weights(R.u);
    const double *xw = gsl_integration_fixed_nodes(R.w), *ww = gsl_integration_fixed_weights(R.w);
    const double Z2 = J.z_scaled * J.z_scaled;
    /* Brackets: (1/4) int dOmega dOmega' (Delta psi_i)(Delta psi_j), in and out directions
     * independent and isotropic: 2 [4 pi int Psi_i Psi_j - int Psi_i . int Psi_j]; the
     * mean of a traceless axial tensor contracts to (3/2) zz zz'. */
    static const double mean_weight[CE_NSET] = {1.5, 1.0, 1.0};
    for (int iu = 0; iu < qd.n_u; iu++)
        for (int iw = 0; iw < qd.n_w; iw++) {
            const double u = xu[iu], w = xw[iw], rs = u + 2.0 * m, ps2 = u * (0.25 * u + m);
            const double meas = wu[iu] * ww[iw] * rs * sqrt(2.0 * rs + w) * ps2 / (2.0 * Z2);
            pair_angles(m, u, w, N, R.c, ang);
            for (int s = 0; s < CE_NSET; s++)
                for (int i = 0; i < N; i++)
                    for (int j = 0; j <= i; j++)
                        A[s][i][j] += meas * (8.0 * M_PI * M_PI * ang->G[s][i][j] -
                                              4.0 * M_PI * M_PI * mean_weight[s] *
                                                  ang->M[s][i] * ang->M[s][j]);
        }
    rules_free(&R);
    free(ang);

    double coef[CE_NSET];
    for (int s = 0; s < CE_NSET; s++) {
        double bb = 0.0;
        for (int i = 0; i < N; i++)
            bb += b[s][i] * b[s][i];
        if (bb == 0.0 || (s == CE_BULK && m == 0.0)) { /* conformal: Q = 0 identically */
            coef[s] = 0.0;
            continue;
        }
        /* Jacobi-scaled Cholesky: A is a Gram matrix, positive definite off invariants. */
        double am[CE_REL_MAX_ORDER * CE_REL_MAX_ORDER], bv[CE_REL_MAX_ORDER],
            xv[CE_REL_MAX_ORDER], d[CE_REL_MAX_ORDER];
        for (int i = 0; i < N; i++)
            d[i] = 1.0 / sqrt(A[s][i][i]);
        for (int i = 0; i < N; i++) {
            bv[i] = b[s][i] * d[i];
            for (int j = 0; j < N; j++) {
                const double aij = j <= i ? A[s][i][j] : A[s][j][i];
                am[i * N + j] = aij * d[i] * d[j];
            }
        }
        gsl_matrix_view mv = gsl_matrix_view_array(am, N, N);
        gsl_vector_view bw = gsl_vector_view_array(bv, N), xw2 = gsl_vector_view_array(xv, N);
        if (!(A[s][0][0] > 0.0) || gsl_linalg_cholesky_decomp1(&mv.matrix) ||
            gsl_linalg_cholesky_solve(&mv.matrix, &bw.vector, &xw2.vector)) {
            *why = "a collision-bracket matrix is not positive definite";
            return -1;
        }
        double r = 0.0;
        for (int i = 0; i < N; i++)
            r += bv[i] * xv[i];
        coef[s] = r / ce_ncomp[s];
    }
    out->eta = coef[CE_SHEAR];
    out->lambda = coef[CE_HEAT];
    out->zeta = coef[CE_BULK];
    return 0;
}
