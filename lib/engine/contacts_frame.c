/* engine/contacts_frame.c — a group's states and normals taken into its zero-momentum
 * frame when that frame moves near c (papers/simultaneous-contacts.md, "Accuracy near c"):
 * the plain boost p + [(g - 1) p.uhat - g M |u|] uhat subtracts numbers of order gamma^2
 * times the result when the balls move together near c (and 1 - u^2/c^2, the ZMF's
 * 1/gamma^2, is lost to rounding by gamma ~ 1e8). Here every part is formed as the pair
 * law forms its own ZMF (pair_axis.h, rc_pair_split_of), summed over the group. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "relcol/kinematics.h"
#include "relcol/status.h"
#include "../kinematics_private.h"
#include "../pair_axis.h"
#include "contacts.h"

int eng_group_zmf_fast(double k, size_t nm, const rc_particle *S, size_t nc,
                       const rc_contact *C0, rc_particle *B, rc_contact *Cz, double *f,
                       rc_vec3 *uout, double *gout)
{
    int st = RC_ENOMEM;
    double *M = malloc(nm * sizeof *M), *pl = malloc(nm * sizeof *pl);
    double *T2 = malloc(nm * sizeof *T2), *dl = malloc(nm * sizeof *dl);
    rc_vec3 *t = malloc(nm * sizeof *t);
    double *D = nm <= SIZE_MAX / sizeof(double) / nm ? malloc(nm * nm * sizeof *D) : NULL;
    if (!M || !pl || !T2 || !dl || !t || !D)
        goto done;
    const double sqrt_k = sqrt(k);
    rc_vec3 P = rc_v3(0, 0, 0);
    double Mt = 0.0;
    for (size_t i = 0; i < nm; i++) {
        M[i] = sqrt(S[i].m * S[i].m + rc_v3_norm2(S[i].p) * k);
        P = rc_v3_add(P, S[i].p);
        Mt += M[i];
    }
    const double Pl = rc_v3_norm(P);
    st = RC_ENOCONVERGE;
    if (!(Pl > 0.0))
        goto done;
    const rc_vec3 uh = rc_v3_scale(1.0 / Pl, P);
    /* Ball i's momentum across P: p_i x uhat = sum_j p_i x p_j / |P|, exact for the exact P
     * although P is rounded (as rc_pair_split_of), each product accurate to its own size;
     * T_i^2 = m_i^2 + |p_i x uhat|^2/c^2 its transverse mass along uhat. */
    for (size_t i = 0; i < nm; i++) {
        rc_vec3 w = rc_v3(0, 0, 0);
        for (size_t j = 0; j < nm; j++)
            if (j != i)
                w = rc_v3_add(w, rc_cross_exact(S[i].p, S[j].p));
        w = rc_v3_scale(1.0 / Pl, w);
        t[i] = rc_v3_cross(uh, w);
        T2[i] = S[i].m * S[i].m + rc_v3_norm2(w) * k;
        pl[i] = rc_v3_dot(S[i].p, uh);
    }
    /* Along P: p_i.uhat - M_i |P|/Mt = sum_j (M_j p_i.uhat - M_i p_j.uhat)/Mt, each term a
     * pair's approach along uhat (rc_axis_approach: a difference of rapidities). D[i][j]
     * = M_i M_j - p_i.p_j/c^2 (m_i^2 on the diagonal), a sum of positive terms
     * (rc_pair_dot); their sum is the invariant mass squared, Mt^2 - |P|^2/c^2. */
    double minv2 = 0.0;
    for (size_t i = 0; i < nm; i++) {
        dl[i] = 0.0;
        for (size_t j = 0; j < nm; j++) {
            if (j == i) {
                D[i * nm + i] = S[i].m * S[i].m;
            } else {
                const rc_axis ax = {M[i], M[j], pl[i], pl[j], T2[i], T2[j]};
                dl[i] += rc_axis_approach(&ax);
                if (j > i)
                    D[i * nm + j] = D[j * nm + i] =
                        rc_pair_dot(S[i].m, S[i].p, M[i], S[j].m, S[j].p, M[j], k, sqrt_k);
            }
            minv2 += D[i * nm + j];
        }
        dl[i] /= Mt;
    }
    const double g = Mt / sqrt(minv2);
    if (!isfinite(g))
        goto done;
    const rc_vec3 u = rc_v3_scale(1.0 / Mt, P);
    for (size_t i = 0; i < nm; i++) {
        B[i].m = S[i].m;
        B[i].p = rc_v3_axpy(t[i], g * dl[i], uh);
    }
    /* Normal j as its four-vector q = (u_ab.n/c^2, n): across uhat the boost leaves n_perp,
     * along it gives g (n.uhat - |u| u_ab.n/c^2) = g N / (M_ab Mt) with
     *   N = n.uhat (M_ab Mt - P_ab.P/c^2) - |P| P_ab,perp.n_perp / c^2,
     * the first bracket a sum of D (the pair's four-momentum times the group's), where the
     * plain form cancels to order gamma^2. n_perp from rc_cross_exact (n may lie along P). */
    for (size_t j = 0; j < nc; j++) {
        const rc_contact *c = &C0[j];
        const int a = c->a, b = c->b;
        double Dab = 0.0;
        for (size_t l = 0; l < nm; l++)
            Dab += D[(size_t)a * nm + l] + D[(size_t)b * nm + l];
        const rc_vec3 nperp = rc_v3_cross(uh, rc_cross_exact(c->n, uh));
        const double N = rc_v3_dot(c->n, uh) * Dab -
                         k * Pl * rc_v3_dot(rc_v3_add(t[a], t[b]), nperp);
        const rc_vec3 qx = rc_v3_axpy(nperp, g * N / ((M[a] + M[b]) * Mt), uh);
        f[j] = rc_v3_norm(qx);
        if (!(f[j] > 0.0) || !isfinite(f[j]))
            goto done;
        rc_four e = {c->t, c->x};
        rc_boost_g(u, g, k, &e);
        Cz[j] = *c;
        Cz[j].n = rc_v3_scale(1.0 / f[j], qx);
        Cz[j].t = e.t;
        Cz[j].x = e.x;
    }
    *uout = u;
    *gout = g;
    st = RC_OK;
done:
    free(M);
    free(pl);
    free(T2);
    free(dl);
    free(t);
    free(D);
    return st;
}
