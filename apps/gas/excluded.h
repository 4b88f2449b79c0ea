/* excluded.h — the second-virial (first order in density) correction to the momentum
 * distribution of a gas of Lorentz-contracted hard balls, and the thermometers' split it
 * predicts (header only; derivation: papers/finite-density.md; tests/gas2d/
 * test_excluded.c). Units: c = 1, rest mass 1; shapes depend on the velocities beta only.
 *
 * A ball of rest radius r with velocity beta is the ellipse / spheroid contracted along
 * beta (relcol/toi.h): support function h(n) = r sqrt(1 - (beta.n)^2). Two such shapes
 * exclude, for the relative position of their centres, the Minkowski sum K1 + (-K2) =
 * K1 + K2 (both centrally symmetric), whose support function is h1 + h2:
 *   2-D  A = 1/2 Int_0^2pi h rho dphi,  rho = rho1 + rho2 the radius of curvature, an
 *        ellipse's rho = det(P)/h^3 (P = r^2 (I - beta beta^T), det P = r^4/gamma^2);
 *   3-D  V = 1/3 Int_S2 h det_T(R) dOmega, R = R1 + R2 the curvature-radius tensors
 *        (the Hessian of the degree-1 extension of h, (P h^2 - P n n^T P)/h^3, which
 *        annihilates n), det_T its determinant on the tangent plane, 1/2 ((tr R)^2 -
 *        tr R^2); the radii of curvature of a Minkowski sum add as tensors.
 * If the stationary measure is uniform on the non-overlapping configurations times the
 * Jüttner weight J(p), the one-ball law to first order in the number density n is
 *   f(p) = J(p) [1 - n (Vex(p) - <Vex>)],  Vex(p) = <V(p, p2)>_{p2 ~ J},
 * so a mean moves by <A>_f - <A>_J = -n Cov_J(A(p1), V(p1, p2)) (the pair average over
 * J x J). With the packing eta = n v_d (v_d = pi r^2 or 4/3 pi r^3) the thermometers
 * move by
 *   theta_gamma: -eta C_gamma / (d<gamma>/dtheta),   theta_pv: -eta C_pv / d,
 * C_A = Cov_J(A, V) / v_d dimensionless (independent of r). */
#ifndef RELCOL_GAS_EXCLUDED_H
#define RELCOL_GAS_EXCLUDED_H

#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_integration.h>

#include "juttner.h"

/* 2-D: area of the Minkowski sum of two ellipses of rest radii r1, r2 contracted along
 * the velocities b1, b2 (|b| < 1; z ignored): the trapezoid rule over nphi equally spaced
 * normal angles, which converges geometrically for this smooth periodic integrand once
 * the spacing resolves the flattest shape's curvature peak (angular width ~1/gamma). */
static inline double ex_area_2d(double r1, const double b1[2], double r2, const double b2[2],
                                int nphi)
{
    const double d1 = r1 * r1 * r1 * r1 * (1.0 - b1[0] * b1[0] - b1[1] * b1[1]);
    const double d2 = r2 * r2 * r2 * r2 * (1.0 - b2[0] * b2[0] - b2[1] * b2[1]);
    double s = 0.0;
    for (int k = 0; k < nphi; k++) {
        const double phi = 2.0 * M_PI * k / nphi, c = cos(phi), si = sin(phi);
        const double u1 = b1[0] * c + b1[1] * si, u2 = b2[0] * c + b2[1] * si;
        const double h1 = r1 * sqrt((1.0 - u1) * (1.0 + u1));
        const double h2 = r2 * sqrt((1.0 - u2) * (1.0 + u2));
        s += (h1 + h2) * (d1 / (h1 * h1 * h1) + d2 / (h2 * h2 * h2));
    }
    return 0.5 * s * (2.0 * M_PI / nphi);
}

/* The curvature-radius tensor of the spheroid (r, b) at normal n, added into R. */
static inline void ex_curv_add(double r, const double b[3], const double n[3], double R[3][3],
                               double *h)
{
    double P[3][3], Pn[3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            P[i][j] = r * r * ((i == j) - b[i] * b[j]);
    for (int i = 0; i < 3; i++)
        Pn[i] = P[i][0] * n[0] + P[i][1] * n[1] + P[i][2] * n[2];
    const double h2 = Pn[0] * n[0] + Pn[1] * n[1] + Pn[2] * n[2], hh = sqrt(h2);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] += (P[i][j] * h2 - Pn[i] * Pn[j]) / (h2 * hh);
    *h += hh;
}

/* 3-D: volume of the Minkowski sum of two spheroids, by a product rule over the normal:
 * Gauss-Legendre in cos(polar angle) (nmu nodes, table glt) about b1's direction, and the
 * trapezoid rule in the azimuth (2 nmu nodes). */
static inline double ex_volume_3d(double r1, const double b1[3], double r2, const double b2[3],
                                  const gsl_integration_glfixed_table *glt)
{
    /* an orthonormal frame (e0, e1, e2) with e2 along b1 (any, if b1 = 0) */
    double e2[3] = {0.0, 0.0, 1.0};
    const double bb = sqrt(b1[0] * b1[0] + b1[1] * b1[1] + b1[2] * b1[2]);
    if (bb > 0.0)
        for (int i = 0; i < 3; i++)
            e2[i] = b1[i] / bb;
    double e0[3];
    if (fabs(e2[0]) < 0.9) { /* e0 = x - (x.e2) e2, normalised */
        e0[0] = 1.0 - e2[0] * e2[0], e0[1] = -e2[0] * e2[1], e0[2] = -e2[0] * e2[2];
    } else {
        e0[0] = -e2[1] * e2[0], e0[1] = 1.0 - e2[1] * e2[1], e0[2] = -e2[1] * e2[2];
    }
    const double l0 = sqrt(e0[0] * e0[0] + e0[1] * e0[1] + e0[2] * e0[2]);
    for (int i = 0; i < 3; i++)
        e0[i] /= l0;
    const double e1[3] = {e2[1] * e0[2] - e2[2] * e0[1], e2[2] * e0[0] - e2[0] * e0[2],
                          e2[0] * e0[1] - e2[1] * e0[0]};
    const int nmu = (int)glt->n, naz = 2 * nmu;
    double s = 0.0;
    for (int i = 0; i < nmu; i++) {
        double mu, wmu;
        gsl_integration_glfixed_point(-1.0, 1.0, (size_t)i, &mu, &wmu, glt);
        const double st = sqrt((1.0 - mu) * (1.0 + mu));
        for (int k = 0; k < naz; k++) {
            const double a = 2.0 * M_PI * k / naz, ca = st * cos(a), sa = st * sin(a);
            const double n[3] = {ca * e0[0] + sa * e1[0] + mu * e2[0],
                                 ca * e0[1] + sa * e1[1] + mu * e2[1],
                                 ca * e0[2] + sa * e1[2] + mu * e2[2]};
            double R[3][3] = {{0.0}}, h = 0.0;
            ex_curv_add(r1, b1, n, R, &h);
            ex_curv_add(r2, b2, n, R, &h);
            const double tr = R[0][0] + R[1][1] + R[2][2];
            double tr2 = 0.0;
            for (int p = 0; p < 3; p++)
                for (int q = 0; q < 3; q++)
                    tr2 += R[p][q] * R[q][p];
            s += wmu * h * 0.5 * (tr * tr - tr2);
        }
    }
    return s * (2.0 * M_PI / naz) / 3.0;
}

/* 2-D: the area of relative table-time positions r (ball 2 minus ball 1, both at one
 * table time) that a contact decided in the pair's ZMF forbids, for equal rest radii r0
 * and velocities b1, b2 (|b| < 1). Seen from the ZMF (velocity u, Lorentz factor g), the
 * two table-time events are not simultaneous: ball 2's is at ZMF time t2 = -g u.r. The
 * pair has collided, or is colliding, if at some ZMF time between the two events its
 * ZMF sections overlap, i.e. if the relative position at ZMF time s t2, A_s r with
 * A_s = B + g ((1 - s) v2 + s v1) u^T (B = I + (g - 1) uh uh^T, v1, v2 the ZMF
 * velocities), lies in K* (the Minkowski sum of the shapes contracted along v1, v2) for
 * some s in [0, 1]. That set is star-shaped about 0: its area is 1/2 Int rho^2 dphi with
 * rho(e) = 1 / min_s |A_s e|_K* (the gauge |x|_K = max_n n.x / h_K(n), scanned over
 * nphi normals; the minimum over s of a convex function of s by golden section). With
 * tab != NULL also *tab = the area of its intersection with the table-frame Minkowski
 * sum (both star-shaped about 0: 1/2 Int min(rho, rho_table)^2 dphi). */
static inline double ex_area_zmf_2d(double r0, const double b1[2], const double b2[2], int nphi,
                                    double *tab)
{
    const double g1 = 1.0 / sqrt((1.0 - b1[0] * b1[0] - b1[1] * b1[1])),
                 g2 = 1.0 / sqrt((1.0 - b2[0] * b2[0] - b2[1] * b2[1]));
    const double p1[2] = {g1 * b1[0], g1 * b1[1]}, p2[2] = {g2 * b2[0], g2 * b2[1]};
    const double u[2] = {(p1[0] + p2[0]) / (g1 + g2), (p1[1] + p2[1]) / (g1 + g2)};
    const double uu = sqrt(u[0] * u[0] + u[1] * u[1]), gu = 1.0 / sqrt(1.0 - uu * uu);
    const double uh[2] = {uu > 0.0 ? u[0] / uu : 1.0, uu > 0.0 ? u[1] / uu : 0.0};
    double v[2][2]; /* ZMF velocities */
    const double *pp[2] = {p1, p2}, ee[2] = {g1, g2};
    for (int i = 0; i < 2; i++) {
        const double up = uh[0] * pp[i][0] + uh[1] * pp[i][1];
        const double E = gu * (ee[i] - (u[0] * pp[i][0] + u[1] * pp[i][1]));
        const double f = (gu - 1.0) * up - gu * ee[i] * uu;
        v[i][0] = (pp[i][0] + f * uh[0]) / E;
        v[i][1] = (pp[i][1] + f * uh[1]) / E;
    }
    double *hz = malloc(2 * (size_t)nphi * sizeof *hz), *ht = hz ? hz + nphi : NULL;
    if (!hz)
        return NAN;
    for (int k = 0; k < nphi; k++) {
        const double c = cos(2.0 * M_PI * k / nphi), si = sin(2.0 * M_PI * k / nphi);
        double hs = 0.0, hh = 0.0;
        for (int i = 0; i < 2; i++) {
            const double a = v[i][0] * c + v[i][1] * si;
            hs += r0 * sqrt((1.0 - a) * (1.0 + a));
        }
        const double a1 = b1[0] * c + b1[1] * si, a2 = b2[0] * c + b2[1] * si;
        hh = r0 * (sqrt((1.0 - a1) * (1.0 + a1)) + sqrt((1.0 - a2) * (1.0 + a2)));
        hz[k] = hs;
        ht[k] = hh;
    }
    double area = 0.0, inter = 0.0;
    for (int j = 0; j < nphi; j++) {
        const double e[2] = {cos(2.0 * M_PI * j / nphi), sin(2.0 * M_PI * j / nphi)};
        /* A_s e = B e + g (v2 + s (v1 - v2)) (u.e) */
        const double ue = u[0] * e[0] + u[1] * e[1], be = (gu - 1.0) * (uh[0] * e[0] + uh[1] * e[1]);
        const double a0[2] = {e[0] + be * uh[0] + gu * v[1][0] * ue, e[1] + be * uh[1] + gu * v[1][1] * ue};
        const double a1[2] = {gu * (v[0][0] - v[1][0]) * ue, gu * (v[0][1] - v[1][1]) * ue};
        double lo = 0.0, hi = 1.0, best = INFINITY;
        const double gr = 0.5 * (sqrt(5.0) - 1.0);
        for (int it = 0; it < 40; it++) {
            const double sa = hi - gr * (hi - lo), sb = lo + gr * (hi - lo);
            double ga = 0.0, gb = 0.0;
            for (int k = 0; k < nphi; k++) {
                const double c = cos(2.0 * M_PI * k / nphi), si = sin(2.0 * M_PI * k / nphi);
                const double xa = (a0[0] + sa * a1[0]) * c + (a0[1] + sa * a1[1]) * si;
                const double xb = (a0[0] + sb * a1[0]) * c + (a0[1] + sb * a1[1]) * si;
                ga = fmax(ga, xa / hz[k]);
                gb = fmax(gb, xb / hz[k]);
            }
            best = fmin(best, fmin(ga, gb));
            if (ga < gb)
                hi = sb;
            else
                lo = sa;
        }
        double gt = 0.0; /* the table-frame sum's gauge of e */
        for (int k = 0; k < nphi; k++)
            gt = fmax(gt, (e[0] * cos(2.0 * M_PI * k / nphi) + e[1] * sin(2.0 * M_PI * k / nphi)) / ht[k]);
        const double rz = 1.0 / best, rt = 1.0 / gt;
        area += rz * rz;
        inter += fmin(rz, rt) * fmin(rz, rt);
    }
    free(hz);
    if (tab)
        *tab = 0.5 * inter * (2.0 * M_PI / nphi);
    return 0.5 * area * (2.0 * M_PI / nphi);
}

/* Excluded area (d = 2) or volume (d = 3) of two balls of rest radius r with velocities
 * b1, b2 (components beyond d ignored); nq: nphi in 2-D, glt in 3-D; zmf != 0 (2-D only):
 * the area ex_area_zmf_2d forbids instead of the table-frame Minkowski sum. */
typedef struct ex_quad {
    int nphi;                                  /* 2-D trapezoid nodes */
    const gsl_integration_glfixed_table *glt;  /* 3-D Gauss-Legendre table */
    int zmf;                                   /* 2-D: the zmf contact's forbidden area */
} ex_quad;

static inline double ex_excluded(int d, double r, const double b1[3], const double b2[3],
                                 const ex_quad *q)
{
    if (d == 2 && q->zmf)
        return ex_area_zmf_2d(r, b1, b2, q->nphi, NULL);
    return d == 2 ? ex_area_2d(r, b1, r, b2, q->nphi) : ex_volume_3d(r, b1, r, b2, q->glt);
}

/* Result of ex_coefficients: Jüttner means by the quadrature (checks), the excluded
 * volume's mean and covariances in units of v_d, and the thermometers' slopes in the
 * packing, d theta / d eta at eta -> 0. */
typedef struct ex_coef {
    double mean_gamma, mean_pv;  /* <gamma>, <p.v> of the quadrature's Jüttner law */
    double mean_v;               /* <V>_JxJ / v_d (4 for discs, 8 for spheres) */
    double c_gamma, c_pv;        /* Cov(gamma, V) / v_d, Cov(p.v, V) / v_d */
    double dtheta_gamma, dtheta_pv; /* slopes of each thermometer */
    double slope;                /* d(theta_pv - theta_gamma)/d eta */
} ex_coef;

/* The first-order coefficients at temperature theta in d = 2 or 3 dimensions: a product
 * rule over Jüttner pairs. Each ball's speed: ns-node generalised Gauss-Laguerre in
 * x = gamma - 1 for the weight x^((d-2)/2) e^(-x/theta) (the Jüttner density in x is
 * gamma (x (x + 2))^((d-2)/2) e^(-x/theta), so what is left, gamma (x + 2)^((d-2)/2) times
 * a smooth function of beta^2, is smooth: the rule converges geometrically). The angle
 * between the velocities: na nodes (2-D: trapezoid over [0, 2 pi); 3-D: Gauss-Legendre in
 * its cosine). The excluded volume by q. The weights are normalised by their sum, so the
 * rule's own error in the normalisation cancels. contracted = 0: uncontracted spheres (the
 * sphere frame, and every frame at c = inf), whose V is a constant: no correction. Status: 0, or -1 on bad arguments or a
 * failed allocation. */
static inline int ex_coefficients(int d, double theta, int contracted, int ns, int na,
                                  const ex_quad *q, ex_coef *out)
{
    *out = (ex_coef){NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN};
    if ((d != 2 && d != 3) || !(theta > 0.0) || !isfinite(theta) || ns < 2 || na < 2)
        return -1;
    gsl_integration_fixed_workspace *gs =
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, (size_t)ns, 0.0,
                                    1.0 / theta, 0.5 * (d - 2), 0.0);
    gsl_integration_glfixed_table *ga = gsl_integration_glfixed_table_alloc((size_t)na);
    double *w = malloc((size_t)ns * sizeof *w), *beta = malloc((size_t)ns * sizeof *beta);
    double *gam = malloc((size_t)ns * sizeof *gam), *pv = malloc((size_t)ns * sizeof *pv);
    double *wa = malloc((size_t)na * sizeof *wa), *ca = malloc((size_t)na * sizeof *ca);
    int st = gs && ga && w && beta && gam && pv && wa && ca ? 0 : -1;
    if (st == 0) {
        const double *xn = gsl_integration_fixed_nodes(gs), *xw = gsl_integration_fixed_weights(gs);
        double sw = 0.0;
        for (int i = 0; i < ns; i++) {
            const double x = xn[i], g = 1.0 + x, pp = sqrt(x * (x + 2.0));
            w[i] = xw[i] * g * pow(x + 2.0, 0.5 * (d - 2));
            gam[i] = g;
            beta[i] = contracted ? pp / g : 0.0;
            pv[i] = pp * pp / g;
            sw += w[i];
        }
        for (int i = 0; i < ns; i++)
            w[i] /= sw;
        double swa = 0.0;
        for (int k = 0; k < na; k++) {
            if (d == 2) {
                wa[k] = 1.0;
                ca[k] = cos(2.0 * M_PI * k / na);
            } else {
                double mu, wmu;
                gsl_integration_glfixed_point(-1.0, 1.0, (size_t)k, &mu, &wmu, ga);
                wa[k] = wmu;
                ca[k] = mu;
            }
            swa += wa[k];
        }
        for (int k = 0; k < na; k++)
            wa[k] /= swa;
        const double vd = d == 2 ? M_PI : 4.0 * M_PI / 3.0; /* r = 1 */
        double mg = 0.0, mp = 0.0, mv = 0.0, sgv = 0.0, spv = 0.0;
        for (int i = 0; i < ns; i++) {
            mg += w[i] * gam[i];
            mp += w[i] * pv[i];
        }
        for (int i = 0; i < ns; i++) {
            double vi = 0.0; /* Vex(p1) = <V(p1, p2)> over p2 */
            for (int j = 0; j < ns; j++)
                for (int k = 0; k < na; k++) {
                    const double sk = sqrt((1.0 - ca[k]) * (1.0 + ca[k]));
                    /* ball 1 along x; ball 2 at angle k from it (in the (x, y) plane) */
                    const double sa = d == 2 ? sin(2.0 * M_PI * k / na) : sk;
                    const double b1[3] = {beta[i], 0.0, 0.0};
                    const double b2[3] = {beta[j] * ca[k], beta[j] * sa, 0.0};
                    vi += w[j] * wa[k] * ex_excluded(d, 1.0, b1, b2, q);
                }
            vi /= vd;
            mv += w[i] * vi;
            sgv += w[i] * gam[i] * vi;
            spv += w[i] * pv[i] * vi;
        }
        out->mean_gamma = mg;
        out->mean_pv = mp;
        out->mean_v = mv;
        out->c_gamma = sgv - mg * mv;
        out->c_pv = spv - mp * mv;
        /* d<gamma>/dtheta of the exact law, by a central difference (relative step 1e-4:
         * truncation ~1e-8, round-off ~1e-12, far below the quadrature's error) */
        const double dt = 1e-4 * theta;
        const double dg = (jt_mean_gamma(d, theta + dt) - jt_mean_gamma(d, theta - dt)) / (2.0 * dt);
        out->dtheta_gamma = -out->c_gamma / dg;
        out->dtheta_pv = -out->c_pv / d;
        out->slope = out->dtheta_pv - out->dtheta_gamma;
    }
    if (gs)
        gsl_integration_fixed_free(gs);
    if (ga)
        gsl_integration_glfixed_table_free(ga);
    free(w), free(beta), free(gam), free(pv), free(wa), free(ca);
    return st;
}

/* Vex(p)/v_d = <V(p, p2)>_{p2 ~ J} / v_d for a ball of Lorentz factor gamma, the same
 * pair rule as ex_coefficients (ns speed nodes, na angles, q): the one-ball law to first
 * order is f(p) = J(p) [1 - eta (ex_vex(p) - <V>/v_d)] (eta the packing). NAN on bad
 * arguments or a failed allocation. */
static inline double ex_vex(int d, double theta, double gamma, int ns, int na, const ex_quad *q)
{
    if ((d != 2 && d != 3) || !(theta > 0.0) || !isfinite(theta) || !(gamma >= 1.0) ||
        !isfinite(gamma) || ns < 2 || na < 2)
        return NAN;
    gsl_integration_fixed_workspace *gs =
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, (size_t)ns, 0.0,
                                    1.0 / theta, 0.5 * (d - 2), 0.0);
    gsl_integration_glfixed_table *ga = gsl_integration_glfixed_table_alloc((size_t)na);
    double v = NAN;
    if (gs && ga) {
        const double *xn = gsl_integration_fixed_nodes(gs), *xw = gsl_integration_fixed_weights(gs);
        const double b1[3] = {sqrt((gamma - 1.0) * (gamma + 1.0)) / gamma, 0.0, 0.0};
        double s = 0.0, sw = 0.0;
        for (int j = 0; j < ns; j++) {
            const double x = xn[j], g = 1.0 + x, bj = sqrt(x * (x + 2.0)) / g;
            const double wj = xw[j] * g * pow(x + 2.0, 0.5 * (d - 2));
            for (int k = 0; k < na; k++) {
                double ck, sk, wk = 1.0;
                if (d == 2) {
                    ck = cos(2.0 * M_PI * k / na), sk = sin(2.0 * M_PI * k / na);
                } else {
                    gsl_integration_glfixed_point(-1.0, 1.0, (size_t)k, &ck, &wk, ga);
                    sk = sqrt((1.0 - ck) * (1.0 + ck));
                }
                const double b2[3] = {bj * ck, bj * sk, 0.0};
                s += wj * wk * ex_excluded(d, 1.0, b1, b2, q);
                sw += wj * wk;
            }
        }
        v = s / sw / (d == 2 ? M_PI : 4.0 * M_PI / 3.0);
    }
    if (gs)
        gsl_integration_fixed_free(gs);
    if (ga)
        gsl_integration_glfixed_table_free(ga);
    return v;
}

/* The shape matrix P = r^2 (I - b b^T) of relcol/toi.h: the ball is x^T P^-1 x <= 1. */
static inline void ex_shape(double r, const double b[3], double P[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            P[i][j] = r * r * ((i == j) - b[i] * b[j]);
}

/* x^T M^-1 x for a symmetric positive-definite d x d M (Gaussian elimination). */
static inline double ex_quad_inv(int d, double M[3][3], const double x[3])
{
    double a[3][4];
    for (int i = 0; i < d; i++) {
        for (int j = 0; j < d; j++)
            a[i][j] = M[i][j];
        a[i][3] = x[i];
    }
    for (int k = 0; k < d; k++)
        for (int i = k + 1; i < d; i++) {
            const double f = a[i][k] / a[k][k];
            for (int j = k; j < 4; j++)
                a[i][j] -= f * a[k][j];
        }
    double y[3], s = 0.0;
    for (int i = d - 1; i >= 0; i--) {
        double t = a[i][3];
        for (int j = i + 1; j < d; j++)
            t -= a[i][j] * y[j];
        y[i] = t / a[i][i];
    }
    for (int i = 0; i < d; i++)
        s += x[i] * y[i];
    return s;
}

/* An independent overlap test (Monte Carlo checks, the engine's configurations).
 * Perram & Wertheim (1985): the shapes P1 (at 0) and P2 (at x) overlap iff
 * max over lambda in [0, 1] of F = lambda (1 - lambda) x^T [(1 - lambda) P1 + lambda P2]^-1 x
 * is below 1; F is concave in lambda, so golden section finds the maximum. */
static inline int ex_pw_overlap(int d, double P1[3][3], double P2[3][3], const double x[3])
{
    double lo = 0.0, hi = 1.0;
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double best = 0.0;
    for (int it = 0; it < 60; it++) {
        const double l1 = hi - g * (hi - lo), l2 = lo + g * (hi - lo);
        double F[2];
        const double l[2] = {l1, l2};
        for (int k = 0; k < 2; k++) {
            double M[3][3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    M[i][j] = (1.0 - l[k]) * P1[i][j] + l[k] * P2[i][j];
            F[k] = l[k] * (1.0 - l[k]) * ex_quad_inv(d, M, x);
        }
        best = fmax(best, fmax(F[0], F[1]));
        if (best >= 1.0)
            return 0;
        if (F[0] < F[1])
            lo = l1;
        else
            hi = l2;
    }
    return 1;
}

#endif
