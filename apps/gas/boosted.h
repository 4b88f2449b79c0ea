/* boosted.h — the 2-D and 1-D Jüttner laws seen by an observer moving at V along x (c = 1,
 * m = 1; header only, shared by relcol-gas and the tests): counted on the observer's
 * simultaneity hyperplanes, the momenta p' have the density
 *   f'(p') ∝ exp(-(E - 1)/theta),  E = gamma_V (E' + V p'_x),
 * the rest-frame law at the box-frame energy (f is a Lorentz scalar: the count in d^2x'
 * d^2p' is the same as in d^2x d^2p, and the box is uniform). A table-time snapshot of
 * the box, boosted ball by ball, has instead the density f' E/E' in p' (d^2p/E is
 * invariant, so d^2p = (E/E') d^2p'): the test's control. Chi-square cells: nr
 * radial cells in |p'|, equiprobable under f', times na cells of the angle of p' from +x
 * folded to [0, pi]; their probabilities by Gauss-Legendre quadrature (GSL). */
#ifndef RELCOL_GAS_BOOSTED_H
#define RELCOL_GAS_BOOSTED_H

#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>

static inline double bj_density(double theta, double V, double px, double py)
{
    const double gV = 1.0 / sqrt((1.0 - V) * (1.0 + V));
    const double Ep = sqrt(1.0 + px * px + py * py);
    return exp(-(gV * (Ep + V * px) - 1.0) / theta);
}

/* density of |p'| = u, the angle folded (both halves): u Int_0^pi 2 f dphi */
static inline double bj_radial(double theta, double V, double u, gsl_integration_glfixed_table *ta)
{
    double s = 0.0;
    for (size_t k = 0; k < ta->n; k++) {
        double phi, w;
        gsl_integration_glfixed_point(0.0, M_PI, k, &phi, &w, ta);
        s += w * bj_density(theta, V, u * cos(phi), u * sin(phi));
    }
    return 2.0 * u * s;
}

/* The largest |p'| with any weight: E >= gamma_V E' (1 - |V|) and e^(-40) ~ 4e-18. */
static inline double bj_umax(double theta, double V)
{
    const double gV = 1.0 / sqrt((1.0 - V) * (1.0 + V));
    const double Ep = (1.0 + 40.0 * theta) / (gV * (1.0 - fabs(V)));
    return sqrt(Ep * Ep - 1.0);
}

/* Radial edges edge[0..nr] (edge[0] = 0, edge[nr] = bj_umax) equiprobable under f' and
 * the cell probabilities prob[r * na + a] (summing to 1). 0, or -1 without memory. */
static inline int bj_cells(double theta, double V, int nr, int na, double *edge, double *prob)
{
    enum { NFINE = 20000 };
    gsl_integration_glfixed_table *ta = gsl_integration_glfixed_table_alloc(64);
    gsl_integration_glfixed_table *tr = gsl_integration_glfixed_table_alloc(24);
    double *cum = malloc((NFINE + 1) * sizeof *cum);
    if (!ta || !tr || !cum) {
        gsl_integration_glfixed_table_free(ta);
        gsl_integration_glfixed_table_free(tr);
        free(cum);
        return -1;
    }
    const double umax = bj_umax(theta, V), h = umax / NFINE;
    cum[0] = 0.0;
    double prev = 0.0;
    for (int k = 1; k <= NFINE; k++) {
        const double cur = bj_radial(theta, V, k * h, ta);
        cum[k] = cum[k - 1] + 0.5 * h * (prev + cur);
        prev = cur;
    }
    edge[0] = 0.0;
    edge[nr] = umax;
    for (int r = 1, k = 0; r < nr; r++) {
        const double want = cum[NFINE] * r / nr;
        while (cum[k + 1] < want)
            k++;
        edge[r] = h * (k + (want - cum[k]) / (cum[k + 1] - cum[k]));
    }
    double tot = 0.0;
    for (int r = 0; r < nr; r++)
        for (int a = 0; a < na; a++) {
            const double p0 = M_PI * a / na, p1 = M_PI * (a + 1) / na;
            double s = 0.0;
            for (size_t i = 0; i < tr->n; i++) {
                double u, wu;
                gsl_integration_glfixed_point(edge[r], edge[r + 1], i, &u, &wu, tr);
                for (size_t j = 0; j < tr->n; j++) {
                    double phi, wp;
                    gsl_integration_glfixed_point(p0, p1, j, &phi, &wp, tr);
                    s += wu * wp * 2.0 * u * bj_density(theta, V, u * cos(phi), u * sin(phi));
                }
            }
            prob[r * na + a] = s;
            tot += s;
        }
    for (int k = 0; k < nr * na; k++)
        prob[k] /= tot;
    gsl_integration_glfixed_table_free(ta);
    gsl_integration_glfixed_table_free(tr);
    free(cum);
    return 0;
}

/* The cell of momentum (px, py): radial by bisection among the edges, angle folded. */
static inline int bj_cell_of(const double *edge, int nr, int na, double px, double py)
{
    const double u = sqrt(px * px + py * py);
    int lo = 0, hi = nr;
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        if (u >= edge[mid])
            lo = mid;
        else
            hi = mid;
    }
    int a = (int)(atan2(fabs(py), px) / M_PI * na);
    if (a >= na)
        a = na - 1;
    return lo * na + a;
}

/* ---- 1-D (Cubero et al. 2007) -----------------------------------------------------
 * The same law on a line, for a species of rest mass m at theta = kT/(m c^2), momenta
 * u' = p'/(m c): counted on the hyperplanes (the crossings of a hyperplane's segment of
 * length dx' by worldlines with u' in du' are f dx' du', the 1-D form of the argument
 * above: the flux through t' = const is n gamma_V (1 - V v) du = n du' as du/E is
 * invariant and E' = gamma_V E (1 - V v)), the density is
 *   f'(u') = exp(-(gamma_V (E' + V u') - 1)/theta) / (2 gamma_V K1(1/theta) e^(1/theta)),
 * the normalisation because du' = (E'/E) du = gamma_V (1 - V v) du and the odd part
 * integrates to 0. In the observer's rapidity y' (u' = sinh y') the box's is y' + eta
 * with V = tanh eta, so the weight per dy' is exp(-(cosh(y' + eta) - 1)/theta) cosh y'.
 * A table-time snapshot boosted ball by ball carries the extra E/E' again. */

static inline double bj1_density(double theta, double V, double u)
{
    const double gV = 1.0 / sqrt((1.0 - V) * (1.0 + V));
    const double Ep = sqrt(1.0 + u * u);
    return exp(-(gV * (Ep + V * u) - 1.0) / theta) /
           (2.0 * gV * gsl_sf_bessel_K1_scaled(1.0 / theta));
}

/* bj1_density as a gsl_function; par: theta, V */
static inline double bj1_density_fn(double u, void *par)
{
    const double *tv = par;
    return bj1_density(tv[0], tv[1], u);
}

/* The mean of F over [lo, hi] (20-point Gauss-Legendre, table t): what a histogram bin of
 * that width should hold per unit p', not the density at its midpoint (up to 4-5 % apart
 * where the law curves within a bin). */
static inline double bj_bin_mean(const gsl_function *F, double lo, double hi,
                                 const gsl_integration_glfixed_table *t)
{
    return gsl_integration_glfixed(F, lo, hi, t) / (hi - lo);
}

/* weight per unit observer rapidity, unnormalised; par: theta, eta and 1 for Jüttner or
 * 0 for the "modified Jüttner" law exp(-E/kT)/E per du (exp(-cosh y/theta) per box
 * rapidity: the alternative Cubero et al. tested against), whose weight on the
 * hyperplanes is Jüttner's divided by E = cosh(y' + eta) (the counting argument above
 * holds for any stationary f(p)) */
static inline double bj1_weight_y(double y, void *par)
{
    const double *tv = par; /* theta, eta, juttner */
    const double a = (cosh(y + tv[1]) - 1.0) / tv[0];
    if (!(a < 745.0)) /* the tails of an infinite cell: exp underflows while cosh overflows */
        return 0.0;
    return tv[2] != 0.0 ? exp(-a) * cosh(y) : exp(-a) * cosh(y) / cosh(y + tv[1]);
}

/* Edges edge[0..ncell] in the observer's rapidity, edge[0] = -inf and edge[ncell] = inf,
 * inner ones equiprobable under f' (to a fine grid's accuracy: the probabilities do not
 * rely on it), and the cell probabilities prob[k] by adaptive quadrature (GSL), summing
 * to 1, for the law juttner = 1 (bj1_density) or the modified one (juttner = 0). 0, or -1
 * without memory or if a quadrature fails. */
static inline int bj1_cells_law(double theta, double V, int juttner, int ncell, double *edge,
                                double *prob)
{
    enum { NFINE = 20000 };
    double tv[3] = {theta, atanh(V), juttner ? 1.0 : 0.0};
    const double Y = acosh(1.0 + 40.0 * theta); /* e^-40 beyond */
    const double lo = -tv[1] - Y, h = 2.0 * Y / NFINE;
    double *cum = malloc((NFINE + 1) * sizeof *cum);
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(200);
    int rc = -1;
    if (!cum || !w)
        goto out;
    cum[0] = 0.0;
    for (int k = 1; k <= NFINE; k++)
        cum[k] = cum[k - 1] + 0.5 * h * (bj1_weight_y(lo + (k - 1) * h, tv) +
                                         bj1_weight_y(lo + k * h, tv));
    edge[0] = -INFINITY;
    edge[ncell] = INFINITY;
    for (int r = 1, k = 0; r < ncell; r++) {
        const double want = cum[NFINE] * r / ncell;
        while (cum[k + 1] < want)
            k++;
        edge[r] = lo + h * (k + (want - cum[k]) / (cum[k + 1] - cum[k]));
    }
    gsl_function F = {bj1_weight_y, tv};
    double tot = 0.0;
    for (int r = 0; r < ncell; r++) {
        double v, err;
        int st;
        if (r == 0)
            st = gsl_integration_qagil(&F, edge[1], 0.0, 1e-12, 200, w, &v, &err);
        else if (r == ncell - 1)
            st = gsl_integration_qagiu(&F, edge[r], 0.0, 1e-12, 200, w, &v, &err);
        else
            st = gsl_integration_qags(&F, edge[r], edge[r + 1], 0.0, 1e-12, 200, w, &v, &err);
        if (st != GSL_SUCCESS)
            goto out;
        prob[r] = v;
        tot += v;
    }
    for (int r = 0; r < ncell; r++)
        prob[r] /= tot;
    rc = 0;
out:
    gsl_integration_workspace_free(w);
    free(cum);
    return rc;
}

static inline int bj1_cells(double theta, double V, int ncell, double *edge, double *prob)
{
    return bj1_cells_law(theta, V, 1, ncell, edge, prob);
}

/* The cell of momentum u' = p'/(m c) among bj1_cells' edges. */
static inline int bj1_cell_of(const double *edge, int ncell, double u)
{
    const double y = asinh(u);
    int lo = 0, hi = ncell;
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        if (y >= edge[mid])
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

#endif
