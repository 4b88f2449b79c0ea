/* contacts/frame.c — a group's rule run in the group's zero-momentum frame
 * (papers/simultaneous-contacts.md), so that its outcome does not depend on the frame the
 * states are given in; near c without the gamma^2 cancellation of the plain boost
 * ("Accuracy near c"). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "relcol/kinematics.h"
#include "relcol/status.h"
#include "../kinematics_private.h"
#include "../pair_axis.h"
#include "private.h"

/* A group whose zero-momentum frame moves fast (|P|^2/c^2 > RC_PAIR_FAST Mt^2, pair_axis.h),
 * of nm balls S (all in its contacts, no wall) and nc contacts C0 indexing S: B gets the
 * states in the group's ZMF, Cz the contacts there (normal the unit spatial part of the
 * boosted four-vector q = (u_ab.n/c^2, n), f its length, event boosted), *u and *g the
 * frame's velocity P/Mt and Lorentz factor Mt/minv for the boost back (rc_boost_g), all
 * without the gamma^2 cancellation of the plain boost: the plain boost
 * p + [(g - 1) p.uhat - g M |u|] uhat subtracts numbers of order gamma^2 times the result
 * when the balls move together near c (and 1 - u^2/c^2, the ZMF's 1/gamma^2, is lost to
 * rounding by gamma ~ 1e8). Here every part is formed as the pair law forms its own ZMF
 * (pair_axis.h, rc_pair_split_of), summed over the group. */
static int group_zmf_fast(double k, size_t nm, const rc_particle *S, size_t nc,
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

/* ctc_in_group_zmf for a group whose ZMF moves fast (pair_axis.h, RC_PAIR_FAST): its balls
 * (only those in its contacts: a bystander keeps its bits) taken to the ZMF by
 * group_zmf_fast, the rule run there on them, the outcome boosted back. */
static int in_fast_zmf(const ctc_rule *r, size_t nballs, rc_particle *balls, size_t k,
                       const rc_contact *contacts, double *jout)
{
    int st = RC_ENOMEM;
    int *at = malloc(nballs * sizeof *at);     /* ball -> its place among the members */
    size_t *who = malloc(nballs * sizeof *who); /* member -> ball */
    rc_particle *S = malloc(nballs * sizeof *S), *B = malloc(nballs * sizeof *B);
    rc_contact *C0 = malloc(k * sizeof *C0), *C = malloc(k * sizeof *C);
    double *f = malloc(k * sizeof *f), *J = malloc(k * sizeof *J);
    if (!at || !who || !S || !B || !C0 || !C || !f || !J)
        goto done;
    for (size_t i = 0; i < nballs; i++)
        at[i] = -1;
    for (size_t j = 0; j < k; j++)
        at[contacts[j].a] = at[contacts[j].b] = 0;
    size_t nm = 0;
    for (size_t i = 0; i < nballs; i++)
        if (at[i] == 0) {
            at[i] = (int)nm;
            who[nm] = i;
            S[nm++] = balls[i];
        }
    for (size_t j = 0; j < k; j++) {
        C0[j] = contacts[j];
        C0[j].a = at[contacts[j].a];
        C0[j].b = at[contacts[j].b];
    }
    rc_vec3 u;
    double g;
    const double inv_c2 = r->inv_c2;
    st = group_zmf_fast(inv_c2, nm, S, k, C0, B, C, f, &u, &g);
    if (st != RC_OK)
        goto done;
    st = r->run(r, nm, B, k, C, J);
    if (st != RC_OK)
        goto done;
    const rc_vec3 back = rc_v3_scale(-1.0, u);
    for (size_t i = 0; i < nm; i++) {
        rc_four q = {sqrt(B[i].m * B[i].m + rc_v3_norm2(B[i].p) * inv_c2), B[i].p};
        rc_boost_g(back, g, inv_c2, &q);
        balls[who[i]].m = B[i].m;
        balls[who[i]].p = q.x;
    }
    if (jout)
        for (size_t j = 0; j < k; j++)
            jout[j] = J[j] / f[j];
done:
    free(at);
    free(who);
    free(S);
    free(B);
    free(C0);
    free(C);
    free(f);
    free(J);
    return st;
}

/* A rule run in the group's zero-momentum frame (of the balls in its contacts), so that
 * its outcome does not depend on the frame the states are given in: states boosted there,
 * each normal as its four-vector q = (u.n/c^2, n) (orthogonal to its pair's momentum, so
 * that the zmf law's own covariance carries over), each event as an event; the outcome
 * boosted back, the impulses rescaled to the given normals. A group with a wall stays in
 * the wall's rest frame, the given one (an infinite mass at rest is its ZMF); so does a
 * classical group, whose rules are Galilean invariant. */
int ctc_in_group_zmf(const ctc_rule *r, size_t nballs, rc_particle *balls, size_t k,
                     const rc_contact *contacts, double *jout)
{
    const double inv_c2 = r->inv_c2;
    int wall = 0;
    for (size_t j = 0; j < k; j++)
        wall |= contacts[j].b < 0;
    if (inv_c2 == 0.0 || wall || k == 0)
        return r->run(r, nballs, balls, k, contacts, jout);
    rc_vec3 P;
    double Mt;
    ctc_group_momentum(inv_c2, nballs, balls, k, contacts, &P, &Mt);
    /* a ZMF moving near c: the plain boost below would cancel to order gamma^2 */
    if (rc_v3_norm2(P) * inv_c2 > RC_PAIR_FAST * Mt * Mt)
        return in_fast_zmf(r, nballs, balls, k, contacts, jout);
    int st = RC_ENOMEM;
    rc_particle *B = malloc(nballs * sizeof *B);
    rc_contact *C = malloc(k * sizeof *C);
    double *f = malloc(k * sizeof *f), *J = malloc(k * sizeof *J);
    if (!B || !C || !f || !J)
        goto done;
    const rc_vec3 u = rc_v3_scale(1.0 / Mt, P);
    st = RC_ENOCONVERGE; /* (a boost of finite, timelike data does not fail) */
    for (size_t i = 0; i < nballs; i++) {
        rc_four q = {sqrt(balls[i].m * balls[i].m + rc_v3_norm2(balls[i].p) * inv_c2), balls[i].p};
        if (rc_boost(u, inv_c2, &q) != RC_OK)
            goto done;
        B[i].m = balls[i].m;
        B[i].p = q.x;
    }
    for (size_t j = 0; j < k; j++) {
        const rc_contact *c = &contacts[j];
        const rc_particle *a = &balls[c->a], *b = &balls[c->b];
        const double Ma = sqrt(a->m * a->m + rc_v3_norm2(a->p) * inv_c2);
        const double Mb = sqrt(b->m * b->m + rc_v3_norm2(b->p) * inv_c2);
        rc_four q = {rc_v3_dot(rc_v3_add(a->p, b->p), c->n) / (Ma + Mb) * inv_c2, c->n};
        rc_four e = {c->t, c->x};
        if (rc_boost(u, inv_c2, &q) != RC_OK || rc_boost(u, inv_c2, &e) != RC_OK)
            goto done;
        f[j] = rc_v3_norm(q.x);
        if (!(f[j] > 0.0))
            goto done;
        C[j] = *c;
        C[j].n = rc_v3_scale(1.0 / f[j], q.x);
        C[j].t = e.t;
        C[j].x = e.x;
    }
    st = r->run(r, nballs, B, k, C, J);
    if (st != RC_OK)
        goto done;
    const rc_vec3 back = rc_v3_scale(-1.0, u);
    for (size_t i = 0; i < nballs; i++) {
        rc_four q = {sqrt(B[i].m * B[i].m + rc_v3_norm2(B[i].p) * inv_c2), B[i].p};
        if (rc_boost(back, inv_c2, &q) != RC_OK) {
            st = RC_ENOCONVERGE;
            goto done;
        }
        balls[i].m = B[i].m;
        balls[i].p = q.x;
    }
    /* the four-impulse J q_z in the ZMF is (J / f) q in the given frame */
    if (jout)
        for (size_t j = 0; j < k; j++)
            jout[j] = J[j] / f[j];
done:
    free(B);
    free(C);
    free(f);
    free(J);
    return st;
}

void ctc_group_momentum(double inv_c2, size_t nballs, const rc_particle *balls, size_t k,
                        const rc_contact *contacts, rc_vec3 *Pout, double *Mtout)
{
    rc_vec3 P = rc_v3(0, 0, 0);
    double Mt = 0.0;
    for (size_t i = 0; i < nballs; i++) {
        int in = 0;
        for (size_t j = 0; j < k && !in; j++)
            in = contacts[j].a == (int)i || contacts[j].b == (int)i;
        if (!in)
            continue;
        P = rc_v3_add(P, balls[i].p);
        Mt += sqrt(balls[i].m * balls[i].m + rc_v3_norm2(balls[i].p) * inv_c2);
    }
    *Pout = P;
    *Mtout = Mt;
}
