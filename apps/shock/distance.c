/* distance.c — the normalised L2 distance of a profile from a reference
 * (papers/shock-tube.md, section 7). */
#include <math.h>

#include "distance.h"

static const int dist_q[SH_DIST_NQ] = {SH_N, SH_V, SH_P};

void sh_dist_span(const sh_result *r, double x0, double t, int *k0, int *k1)
{
    const double hl = r->sol.headL, hr = r->sol.headR, w = hr - hl;
    const double lo = x0 + (hl - 0.25 * w) * t, hi = x0 + (hr + 0.25 * w) * t;
    *k0 = r->nb, *k1 = 0;
    for (int k = 0; k < r->nb; k++)
        if (r->xc[k] >= lo && r->xc[k] <= hi) {
            if (k < *k0)
                *k0 = k;
            *k1 = k + 1;
        }
    if (*k1 <= *k0)
        *k0 = *k1 = 0;
}

int sh_distance(const sh_result *r, int j, int k0, int k1, int ref, sh_dist *out)
{
    const double *other = ref == SH_REF_FLUID ? r->fluid : r->freestr;
    double d2 = 0.0, var = 0.0;
    int nq = 0;
    out->bins = k1 - k0;
    for (int a = 0; a < SH_DIST_NQ; a++) {
        const int q = dist_q[a];
        double num = 0.0, nvar = 0.0, norm = 0.0;
        for (int k = k0; k < k1; k++) {
            const size_t i = sh_idx(r, j, k, q);
            const double m = r->mean[i], e = r->err[i], f = r->fluid[i], s = r->freestr[i];
            if (!isfinite(m) || !isfinite(f) || !isfinite(s))
                continue;
            const double dev = m - other[i], ee = isfinite(e) ? e * e : 0.0;
            /* E[(m - ref)^2] = (mean - ref)^2 + e^2: the noise is subtracted */
            num += dev * dev - ee;
            nvar += 4.0 * dev * dev * ee + 2.0 * ee * ee; /* var of (m - ref)^2 */
            norm += (f - s) * (f - s);
        }
        if (!(norm > 0.0)) {
            out->dq[a] = NAN;
            continue;
        }
        out->dq[a] = sqrt(fmax(num / norm, 0.0));
        d2 += num / norm, var += nvar / (norm * norm);
        nq++;
    }
    if (!nq) {
        out->d = out->err = NAN;
        return -1;
    }
    d2 /= nq, var /= (double)nq * nq;
    out->d = sqrt(fmax(d2, 0.0));
    /* dD = d(D^2) / (2D); near D = 0 the error of D^2 itself bounds it */
    out->err = out->d > 0.0 ? sqrt(var) / (2.0 * out->d) : sqrt(sqrt(var));
    return 0;
}
