/* boosted.h — the 2-D Jüttner law seen by an observer moving at V along x (c = 1, m = 1;
 * header only, shared by relcol-gas and tests/gas2d): counted on the observer's
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

#include <gsl/gsl_integration.h>

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

#endif
