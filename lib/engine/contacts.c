/* engine/contacts.c — simultaneous contacts resolved together (papers/simultaneous-contacts.md):
 * one four-impulse J_j q_j per contact, the J_j found by Newton's method on the restitution
 * conditions of the zmf law of the contacts that push (a k x k linear system each step,
 * solved by LU; classically the conditions are linear and one step is exact), the set of
 * pushing contacts found by principal pivoting (the `simultaneous` rule) or by dropping the
 * most pulling one (the `drop` rule); rc_contacts_solve also dispatches the `sequential`
 * rule (contacts_seq.c). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "relcol/kinematics.h"
#include "relcol/sim.h"
#include "relcol/status.h"
#include "../kinematics_private.h"
#include "../pair_axis.h"
#include "contacts.h"
#include "ddouble.h"

/* Newton stops when every step is below this fraction of the largest impulse or ball
 * momentum (relative, a few ulps above the round-off floor of the residuals, which are
 * sums of products of the momenta) ... */
#define NEWTON_REL_TOL 1e-14
/* ... or fails after this many steps (quadratic convergence needs < 10 from J = 0). */
#define NEWTON_MAX_ITER 50
/* A pivot smaller than this fraction of the largest diagonal entry means the contact
 * normals are linearly dependent: the impulses are not unique (RC_ENOCONVERGE). */
#define PIVOT_REL_TOL 1e-13
/* Complementarity is violated by an impulse below -CP_REL_TOL times the largest impulse or
 * ball momentum, or by a contact without impulse whose post-group approach exceeds what
 * restitution allows by more than CP_REL_TOL times the largest ball momentum: far above
 * the round-off of Newton's converged impulses (NEWTON_REL_TOL), so that a contact whose
 * exact impulse is 0 does not flip for ever on round-off. */
#define CP_REL_TOL 1e-12
/* Principal pivots allowed (Murty's least-index rule ends in finitely many for the
 * positive definite classical matrix; a handful for the groups an engine meets). */
#define CP_MAX_PIVOTS(k) (16 + 8 * (k))

typedef struct cwork {
    size_t k;
    const rc_contact *c;
    const int *active;
    const rc_particle *b0; /* states before the group */
    const double *M0;
    double *qt;            /* time component of q_j: u_j.n_j / c^2 (0 for walls) */
    double *a0;            /* pre-group ZMF-normal approach of each contact, floored at 0
                              (a receding contact may at most stop receding) */
    double *Mp;            /* post states for the current J */
    rc_vec3 *pp;
    /* A group with a pair moving fast together (fast_pairs): the conditions' terms cancel
     * to order gamma^2, so the energies, q_t, post states, residuals and Jacobian are also
     * kept in double-double (NULL otherwise) */
    const eng_dd *M0d;
    const eng_dd *qtd;
    eng_dd *Mpd;
    eng_ddv *ppd;
} cwork;

/* Post states of every ball for impulses J (inactive contacts carry none). */
static void post_states(const cwork *w, size_t nb, const double *J)
{
    for (size_t i = 0; i < nb; i++) {
        w->pp[i] = w->b0[i].p;
        w->Mp[i] = w->M0[i];
    }
    for (size_t j = 0; j < w->k; j++) {
        if (!w->active[j])
            continue;
        const rc_contact *c = &w->c[j];
        w->pp[c->a] = rc_v3_axpy(w->pp[c->a], -J[j], c->n);
        w->Mp[c->a] -= J[j] * w->qt[j];
        if (c->b >= 0) {
            w->pp[c->b] = rc_v3_axpy(w->pp[c->b], J[j], c->n);
            w->Mp[c->b] += J[j] * w->qt[j];
        }
    }
    if (!w->Mpd)
        return;
    for (size_t i = 0; i < nb; i++) {
        w->ppd[i] = eng_ddv_of(w->b0[i].p);
        w->Mpd[i] = w->M0d[i];
    }
    for (size_t j = 0; j < w->k; j++) {
        if (!w->active[j])
            continue;
        const rc_contact *c = &w->c[j];
        const eng_dd dM = eng_dd_mul_d(w->qtd[j], J[j]);
        w->ppd[c->a] = eng_ddv_axpy(w->ppd[c->a], -J[j], c->n);
        w->Mpd[c->a] = eng_dd_sub(w->Mpd[c->a], dM);
        if (c->b >= 0) {
            w->ppd[c->b] = eng_ddv_axpy(w->ppd[c->b], J[j], c->n);
            w->Mpd[c->b] = eng_dd_add(w->Mpd[c->b], dM);
        }
    }
    for (size_t i = 0; i < nb; i++) {
        w->pp[i] = rc_v3(w->ppd[i].x.hi, w->ppd[i].y.hi, w->ppd[i].z.hi);
        w->Mp[i] = w->Mpd[i].hi;
    }
}

/* Residual of contact j: M_b' p_a'.n - M_a' p_b'.n + eps a0 (M_a' + M_b') for two balls
 * (the zmf-law condition a' = -eps a multiplied by M_a' + M_b' > 0), p_a'.n + eps a0 for
 * a wall. */
static double residual(const cwork *w, size_t j)
{
    const rc_contact *c = &w->c[j];
    if (w->Mpd && c->b >= 0) {
        const eng_dd pan = eng_ddv_dot_d(w->ppd[c->a], c->n);
        const eng_dd pbn = eng_ddv_dot_d(w->ppd[c->b], c->n);
        const eng_dd Ma = w->Mpd[c->a], Mb = w->Mpd[c->b];
        const eng_dd r = eng_dd_sub(eng_dd_mul(Mb, pan), eng_dd_mul(Ma, pbn));
        return eng_dd_add(r, eng_dd_mul_d(eng_dd_add(Ma, Mb), c->eps * w->a0[j])).hi;
    }
    double pan = rc_v3_dot(w->pp[c->a], c->n);
    if (c->b < 0)
        return pan + c->eps * w->a0[j];
    double pbn = rc_v3_dot(w->pp[c->b], c->n);
    double Ma = w->Mp[c->a], Mb = w->Mp[c->b];
    return Mb * pan - Ma * pbn + c->eps * w->a0[j] * (Ma + Mb);
}

/* d residual_j / d J_l at the current post states. */
static double jacobian(const cwork *w, size_t j, size_t l)
{
    const rc_contact *c = &w->c[j], *cl = &w->c[l];
    const double nn = rc_v3_dot(c->n, cl->n);
    /* sign with which J_l acts on ball x: -1 on its a, +1 on its b */
    double sa = (cl->a == c->a ? -1.0 : 0.0) + (cl->b == c->a ? 1.0 : 0.0);
    if (c->b < 0)
        return sa * nn;
    double sb = (cl->a == c->b ? -1.0 : 0.0) + (cl->b == c->b ? 1.0 : 0.0);
    if (w->Mpd) {
        /* (the diagonal is -M_t s: n.n and q_t to double-double too) */
        const eng_dd nnd = eng_dd_dot(c->n, cl->n);
        const eng_dd pan = eng_ddv_dot_d(w->ppd[c->a], c->n);
        const eng_dd pbn = eng_ddv_dot_d(w->ppd[c->b], c->n);
        const eng_dd Ma = w->Mpd[c->a], Mb = w->Mpd[c->b];
        /* dMb pan - dMa pbn + (Mb sa - Ma sb) nn + eps a0 (dMa + dMb), dM = s q_t */
        const eng_dd t1 = eng_dd_mul(w->qtd[l], eng_dd_sub(eng_dd_mul_d(pan, sb),
                                                           eng_dd_mul_d(pbn, sa)));
        const eng_dd t2 = eng_dd_mul(nnd, eng_dd_sub(eng_dd_mul_d(Mb, sa), eng_dd_mul_d(Ma, sb)));
        const eng_dd t3 = eng_dd_mul_d(w->qtd[l], c->eps * w->a0[j] * (sa + sb));
        return eng_dd_add(eng_dd_add(t1, t2), t3).hi;
    }
    double dpan = sa * nn, dpbn = sb * nn;
    double dMa = sa * w->qt[l], dMb = sb * w->qt[l];
    double pan = rc_v3_dot(w->pp[c->a], c->n), pbn = rc_v3_dot(w->pp[c->b], c->n);
    double Ma = w->Mp[c->a], Mb = w->Mp[c->b];
    return dMb * pan + Mb * dpan - dMa * pbn - Ma * dpbn + c->eps * w->a0[j] * (dMa + dMb);
}

/* LU factorisation with partial pivoting of the m x m row-major A, in place, and the
 * solve with it: the arithmetic of GSL 2.7's gsl_linalg_LU_decomp (its unblocked
 * algorithm, which GSL uses up to 24 unknowns) and gsl_linalg_LU_svx with GSL's CBLAS,
 * operation for operation, so that groups keep their bits. Written out because GSL's
 * versions allocate and call GSL's error handler (which aborts by default) when that
 * fails or the matrix is singular; here a zero pivot is a status. piv: m entries. */
static int lu_factor(double *A, size_t m, size_t *piv)
{
    for (size_t j = 0; j < m; j++) {
        size_t jp = j; /* the first largest |A(i, j)|, i >= j */
        double amax = 0.0;
        for (size_t i = j; i < m; i++)
            if (fabs(A[i * m + j]) > amax) {
                amax = fabs(A[i * m + j]);
                jp = i;
            }
        piv[j] = jp;
        if (!(A[jp * m + j] != 0.0))
            return RC_ENOCONVERGE; /* singular (or not finite) */
        if (jp != j)
            for (size_t k = 0; k < m; k++) {
                const double t = A[j * m + k];
                A[j * m + k] = A[jp * m + k];
                A[jp * m + k] = t;
            }
        const double ajj = A[j * m + j];
        if (fabs(ajj) >= DBL_MIN) {
            const double inv = 1.0 / ajj;
            for (size_t i = j + 1; i < m; i++)
                A[i * m + j] *= inv;
        } else {
            for (size_t i = j + 1; i < m; i++)
                A[i * m + j] /= ajj;
        }
        for (size_t i = j + 1; i < m; i++) {
            const double t = -1.0 * A[i * m + j];
            for (size_t k = j + 1; k < m; k++)
                A[i * m + k] += A[j * m + k] * t;
        }
    }
    return RC_OK;
}

static void lu_solve(const double *LU, size_t m, const size_t *piv, double *x)
{
    for (size_t i = 0; i < m; i++)
        if (piv[i] != i) {
            const double t = x[i];
            x[i] = x[piv[i]];
            x[piv[i]] = t;
        }
    for (size_t i = 1; i < m; i++) { /* L c = P b, L unit lower */
        double t = x[i];
        for (size_t j = 0; j < i; j++)
            t -= LU[i * m + j] * x[j];
        x[i] = t;
    }
    x[m - 1] = x[m - 1] / LU[(m - 1) * m + (m - 1)];
    for (size_t i = m - 1; i-- > 0;) { /* U x = c */
        double t = x[i];
        for (size_t j = i + 1; j < m; j++)
            t -= LU[i * m + j] * x[j];
        x[i] = t / LU[i * m + i];
    }
}

/* Newton on the active contacts; J of inactive ones stays 0. */
/* Newton from J = 0, or from start (k entries, those of the active contacts read). */
static int newton(cwork *w, size_t nb, double *J, double *A, double *rhs, size_t *idx,
                  size_t *piv, const double *start)
{
    double pscale = 0.0;
    for (size_t i = 0; i < nb; i++)
        pscale = fmax(pscale, rc_v3_norm(w->b0[i].p));
    size_t m = 0;
    for (size_t j = 0; j < w->k; j++) {
        J[j] = 0.0;
        if (w->active[j]) {
            idx[m++] = j;
            if (start)
                J[j] = start[j];
        }
    }
    if (m == 0)
        return RC_OK;
    for (int it = 0; it < NEWTON_MAX_ITER; it++) {
        post_states(w, nb, J);
        double dmax = 0.0;
        for (size_t r = 0; r < m; r++) {
            rhs[r] = -residual(w, idx[r]);
            for (size_t s = 0; s < m; s++)
                A[r * m + s] = jacobian(w, idx[r], idx[s]);
            if (fabs(A[r * m + r]) > dmax)
                dmax = fabs(A[r * m + r]);
        }
        if (lu_factor(A, m, piv) != RC_OK)
            return RC_ENOCONVERGE;
        for (size_t r = 0; r < m; r++)
            if (!(fabs(A[r * m + r]) > PIVOT_REL_TOL * dmax))
                return RC_ENOCONVERGE; /* singular */
        lu_solve(A, m, piv, rhs);
        double step = 0.0, jmax = 0.0;
        for (size_t r = 0; r < m; r++) {
            J[idx[r]] += rhs[r];
            step = fmax(step, fabs(rhs[r]));
            jmax = fmax(jmax, fabs(J[idx[r]]));
        }
        if (!isfinite(step))
            return RC_ENOCONVERGE;
        if (step <= NEWTON_REL_TOL * (jmax + pscale) || jmax == 0.0)
            return RC_OK;
    }
    return RC_ENOCONVERGE;
}

/* Rest masses after the group, restored (papers/simultaneous-contacts.md, "Rest masses"):
 * the normal four-impulses keep four-momentum and the restitution conditions but can move
 * rest mass between the balls of an elastic group, by O((v/c)^2) and far more in rare
 * grazing geometries. The balls that took an impulse are taken to their common
 * zero-momentum frame, where their momenta are scaled by one factor lam >= 0 so that each
 * gets its target rest mass m* -- its own m if all its contacts were elastic, else the
 * larger of m and the Newton value (heat is never negative) -- with their total energy
 * unchanged; then back. Total four-momentum is kept (to round-off), the order of the
 * contacts still does not matter, and lam - 1 = O((v/c)^2). RC_ENOCONVERGE when no lam
 * exists (the targets need more than the invariant mass): the caller resolves the
 * contacts one at a time instead. Relativistic groups of two or more contacts only. */
/* lam is done when the energy sum matches W to a few roundings of its terms */
#define LAM_ROUNDOFF (8.0 * DBL_EPSILON)
#define LAM_MAX_ITER 60

static int keep_rest_masses(double inv_c2, size_t nb, const rc_particle *b0, size_t k,
                            const rc_contact *c, const int *active, double *Mp, rc_vec3 *pp,
                            const eng_dd *Mpd, const eng_ddv *ppd, const double *m2d,
                            double *mstar)
{
    /* mstar[i]: 0 untouched, -1 touched elastically only, -2 touched inelastically */
    for (size_t i = 0; i < nb; i++)
        mstar[i] = 0.0;
    for (size_t j = 0; j < k; j++) {
        if (!active[j])
            continue;
        const double tag = c[j].eps == 1.0 ? -1.0 : -2.0;
        mstar[c[j].a] = fmin(mstar[c[j].a], tag);
        if (c[j].b >= 0)
            mstar[c[j].b] = fmin(mstar[c[j].b], tag);
    }
    double Mt = 0.0;
    rc_vec3 Pt = rc_v3(0, 0, 0);
    size_t touched = 0, one = 0;
    for (size_t i = 0; i < nb; i++) {
        if (mstar[i] == 0.0)
            continue;
        touched++;
        one = i;
        Mt += Mp[i];
        Pt = rc_v3_add(Pt, pp[i]);
        /* (m2d: the post rest masses squared without the cancellation, fast_pairs) */
        const double m2 = m2d ? m2d[i] : Mp[i] * Mp[i] - rc_v3_norm2(pp[i]) * inv_c2;
        const double mnew = m2 > 0.0 && Mp[i] > 0.0 ? sqrt(m2) : 0.0; /* not timelike: m */
        mstar[i] = mstar[i] == -1.0 ? b0[i].m : fmax(b0[i].m, mnew);
    }
    /* One ball against walls only (a corner): the walls' impulses (q = (0, n)) leave its
     * energy as it was, so nothing moves between balls and its rest mass is its target
     * with the impulses' momentum. Its zero-momentum frame is its own rest frame, where
     * its momentum is round-off: scaling that to absorb an energy mismatch of round-off
     * gave a corner hit at c = 1 a speed 1e-7 too high (found by fuzzing the engine) or
     * no solution at all (a fallback). */
    if (touched == 1) {
        Mp[one] = sqrt(mstar[one] * mstar[one] + rc_v3_norm2(pp[one]) * inv_c2);
        return RC_OK;
    }
    rc_vec3 u = rc_v3_scale(1.0 / Mt, Pt);
    /* ZMF states of the touched balls (kept in Mp, pp); W their total energy there */
    double W = 0.0, W0 = 0.0, g = 0.0, ul = 0.0;
    rc_vec3 uh = rc_v3(0, 0, 0);
    /* A group with a fast pair whose touched balls' ZMF moves near c: the boost there
     * subtracts terms gamma^2 times the result, so it is done on the double-double post
     * states (Mpd, ppd; an impulse-only state may be spacelike, so no rest mass is
     * assumed): with P, M_t their sums, uhat = P/|P|, |u| = |P|/M_t and g = M_t/minv,
     * minv^2 = M_t^2 - |P|^2/c^2, a ball's ZMF momentum is its part across uhat plus
     * g (p.uhat - M |u|) uhat and its energy g (M - |u| p.uhat/c^2). */
    const int fastz = Mpd && rc_v3_norm2(Pt) * inv_c2 > RC_PAIR_FAST * Mt * Mt;
    if (fastz) {
        eng_dd Md = eng_dd_of(0.0);
        eng_ddv Pd = eng_ddv_of(rc_v3(0, 0, 0));
        for (size_t i = 0; i < nb; i++) {
            if (mstar[i] == 0.0)
                continue;
            Md = eng_dd_add(Md, Mpd[i]);
            Pd = (eng_ddv){eng_dd_add(Pd.x, ppd[i].x), eng_dd_add(Pd.y, ppd[i].y),
                           eng_dd_add(Pd.z, ppd[i].z)};
        }
        const eng_dd P2 = eng_ddv_norm2(Pd), Pl = eng_dd_sqrt(P2);
        const eng_dd mi2 = eng_dd_sub(eng_dd_mul(Md, Md), eng_dd_mul_d(P2, inv_c2));
        if (!(mi2.hi > 0.0))
            return RC_ENOCONVERGE;
        g = eng_dd_div(Md, eng_dd_sqrt(mi2)).hi;
        const eng_dd uld = eng_dd_div(Pl, Md); /* |u| */
        ul = uld.hi;
        uh = rc_v3_scale(1.0 / Pl.hi, rc_v3(Pd.x.hi, Pd.y.hi, Pd.z.hi));
        u = rc_v3_scale(ul, uh);
        /* uhat to double-double (a double one is off unit length by 2^-53, which the
         * parts along it would carry into the ZMF times gamma) */
        const eng_ddv uhd = {eng_dd_div(Pd.x, Pl), eng_dd_div(Pd.y, Pl), eng_dd_div(Pd.z, Pl)};
        for (size_t i = 0; i < nb; i++) {
            if (mstar[i] == 0.0)
                continue;
            const eng_dd pl = eng_ddv_dot(ppd[i], uhd);
            const eng_ddv pt = {eng_dd_sub(ppd[i].x, eng_dd_mul(pl, uhd.x)),
                                eng_dd_sub(ppd[i].y, eng_dd_mul(pl, uhd.y)),
                                eng_dd_sub(ppd[i].z, eng_dd_mul(pl, uhd.z))};
            const eng_dd zl = eng_dd_mul_d(eng_dd_sub(pl, eng_dd_mul(Mpd[i], uld)), g);
            const eng_dd Mz = eng_dd_mul_d(
                eng_dd_sub(Mpd[i], eng_dd_mul_d(eng_dd_mul(uld, pl), inv_c2)), g);
            pp[i] = rc_v3_axpy(rc_v3(pt.x.hi, pt.y.hi, pt.z.hi), zl.hi, uh);
            Mp[i] = Mz.hi;
            W += Mp[i];
            W0 += mstar[i];
        }
    }
    for (size_t i = 0; i < nb && !fastz; i++) {
        if (mstar[i] == 0.0)
            continue;
        rc_four f = {Mp[i], pp[i]};
        if (rc_boost(u, inv_c2, &f) != RC_OK)
            return RC_ENOCONVERGE;
        Mp[i] = f.t;
        pp[i] = f.x;
        W += f.t;
        W0 += mstar[i];
    }
    if (!(W0 < W))
        return RC_ENOCONVERGE;
    /* sum_i sqrt(m*_i^2 + lam^2 |p_i|^2/c^2) = W: increasing and convex in lam, so Newton
     * from lam = 1 steps past the root at most once, then descends to it monotonically */
    double lam = 1.0;
    int it = 0;
    for (; it < LAM_MAX_ITER; it++) {
        double f = -W, df = 0.0, scale = W;
        for (size_t i = 0; i < nb; i++) {
            if (mstar[i] == 0.0)
                continue;
            const double s2 = rc_v3_norm2(pp[i]) * inv_c2;
            const double e = sqrt(mstar[i] * mstar[i] + lam * lam * s2);
            f += e;
            scale += e;
            df += lam * s2 / e;
        }
        /* energy matched to round-off of the sum */
        if (fabs(f) <= LAM_ROUNDOFF * scale)
            break;
        if (!(df > 0.0))
            return RC_ENOCONVERGE;
        double next = lam - f / df;
        if (next < 0.0)
            next = 0.5 * lam;
        lam = next;
    }
    if (it == LAM_MAX_ITER || !isfinite(lam))
        return RC_ENOCONVERGE;
    const rc_vec3 back = rc_v3_scale(-1.0, u);
    for (size_t i = 0; i < nb; i++) {
        if (mstar[i] == 0.0)
            continue;
        const rc_vec3 p = rc_v3_scale(lam, pp[i]);
        rc_four f = {sqrt(mstar[i] * mstar[i] + rc_v3_norm2(p) * inv_c2), p};
        if (fastz) {
            /* back without g^2 |u|^2/c^2 = g^2 - 1, which g and |u| rounded apart break */
            const double pl = rc_v3_dot(f.x, uh);
            const rc_vec3 pt = rc_v3_axpy(f.x, -pl, uh);
            const double E = g * (f.t + ul * pl * inv_c2);
            f.x = rc_v3_axpy(pt, g * (pl + f.t * ul), uh);
            f.t = E;
        } else if (rc_boost(back, inv_c2, &f) != RC_OK) {
            return RC_ENOCONVERGE;
        }
        Mp[i] = f.t;
        pp[i] = f.x;
    }
    return RC_OK;
}

/* Validation shared by the entry points. */
static int check_input(double inv_c2, size_t nballs, const rc_particle *balls, size_t k,
                       const rc_contact *contacts)
{
    if (!balls || (!contacts && k) || !(inv_c2 >= 0.0) || isinf(inv_c2))
        return RC_EINVAL;
    for (size_t i = 0; i < nballs; i++) {
        int st = rc_particle_check(&balls[i]);
        if (st != RC_OK)
            return st;
    }
    for (size_t j = 0; j < k; j++) {
        const rc_contact *c = &contacts[j];
        if (c->a < 0 || (size_t)c->a >= nballs || (c->b >= 0 && (size_t)c->b >= nballs) ||
            c->a == c->b)
            return RC_EINVAL;
        if (!rc_v3_isfinite(c->n) || !isfinite(c->eps))
            return RC_ENONFINITE;
        if (!(fabs(rc_v3_norm2(c->n) - 1.0) < 1e-12)) /* unit normals: caller normalises */
            return RC_EZERONORMAL;
        if (!(c->eps >= 0.0 && c->eps <= 1.0))
            return RC_ERESTITUTION;
    }
    return RC_OK;
}

/* Whether an active contact's impulse pulls (beyond round-off). */
static int pulls(const cwork *w, const double *J)
{
    double pscale = 0.0, jmax = 0.0;
    for (size_t j = 0; j < w->k; j++)
        jmax = fmax(jmax, fabs(J[j]));
    for (size_t i = 0; i < w->k; i++) {
        pscale = fmax(pscale, rc_v3_norm(w->b0[w->c[i].a].p));
        if (w->c[i].b >= 0)
            pscale = fmax(pscale, rc_v3_norm(w->b0[w->c[i].b].p));
    }
    for (size_t j = 0; j < w->k; j++)
        if (w->active[j] && J[j] < -CP_REL_TOL * (jmax + pscale))
            return 1;
    return 0;
}

/* The first contact that violates complementarity at J (post states current), k if none:
 * an active contact that pulls, or an inactive one approaching beyond its restitution. */
static size_t first_violation(const cwork *w, size_t nb, const double *J)
{
    double pscale = 0.0, jmax = 0.0;
    for (size_t i = 0; i < nb; i++)
        pscale = fmax(pscale, rc_v3_norm(w->b0[i].p));
    for (size_t j = 0; j < w->k; j++)
        jmax = fmax(jmax, fabs(J[j]));
    for (size_t j = 0; j < w->k; j++) {
        if (w->active[j]) {
            if (J[j] < -CP_REL_TOL * (jmax + pscale))
                return j;
            continue;
        }
        const rc_contact *c = &w->c[j];
        /* residual / (M_a' + M_b'): post approach plus eps times the pre-group one */
        const double g = c->b < 0 ? residual(w, j) : residual(w, j) / (w->Mp[c->a] + w->Mp[c->b]);
        if (g > CP_REL_TOL * pscale)
            return j;
    }
    return w->k;
}

/* 1 when a contact's two balls move fast the same way with a fast ZMF (pair_axis.h's
 * RC_GAMMA_FAST and RC_PAIR_FAST): there the restitution conditions M_b' p_a'.n - M_a'
 * p_b'.n subtract terms gamma^2 times their value, and so does the Jacobian's -M_t s; the
 * joint solve then keeps them in double-double. Other groups keep the plain forms and
 * their bits. */
static int fast_pairs(double inv_c2, const rc_particle *b, size_t k, const rc_contact *c,
                      const double *M)
{
    if (inv_c2 == 0.0)
        return 0;
    for (size_t j = 0; j < k; j++) {
        const int x = c[j].a, y = c[j].b;
        if (y < 0)
            continue;
        const double Mt = M[x] + M[y];
        if (M[x] > RC_GAMMA_FAST * b[x].m && M[y] > RC_GAMMA_FAST * b[y].m &&
            rc_v3_dot(b[x].p, b[y].p) > 0.0 &&
            rc_v3_norm2(rc_v3_add(b[x].p, b[y].p)) * inv_c2 > RC_PAIR_FAST * Mt * Mt)
            return 1;
    }
    return 0;
}

/* The joint solve: pivot = 1 the simultaneous rule (principal pivoting until the impulses
 * are complementary), 0 the drop rule. Input validated. */
static int joint(int pivot, double inv_c2, size_t nballs, rc_particle *balls, size_t k,
                 const rc_contact *contacts, double *jout)
{
    if (k == 0)
        return RC_OK;

    int st = RC_ENOMEM;
    double *M0 = malloc(nballs * sizeof *M0), *Mp = malloc(nballs * sizeof *Mp);
    rc_vec3 *pp = malloc(nballs * sizeof *pp);
    double *qt = malloc(k * sizeof *qt), *a0 = malloc(k * sizeof *a0);
    /* (k x k doubles must not wrap around) */
    double *J = malloc(k * sizeof *J);
    double *A = k <= SIZE_MAX / sizeof(double) / k ? malloc(k * k * sizeof *A) : NULL;
    double *rhs = malloc(k * sizeof *rhs);
    size_t *idx = malloc(k * sizeof *idx);
    int *active = malloc(k * sizeof *active);
    size_t *piv = malloc(k * sizeof *piv);
    /* the simultaneous rule's second start: zero energy parts, its root, the Newton run */
    double *qz = pivot ? calloc(k, sizeof *qz) : NULL;
    double *Jg = pivot ? malloc(k * sizeof *Jg) : NULL, *Jt = pivot ? malloc(k * sizeof *Jt) : NULL;
    /* double-double states for a group with a fast pair (fast_pairs) */
    eng_dd *M0d = NULL, *Mpd = NULL, *qtd = NULL;
    eng_ddv *ppd = NULL;
    double *m2d = NULL; /* their post rest masses squared */
    if (!M0 || !Mp || !pp || !qt || !a0 || !J || !A || !rhs || !idx || !active || !piv ||
        (pivot && (!qz || !Jg || !Jt)))
        goto done;

    for (size_t i = 0; i < nballs; i++)
        M0[i] = sqrt(balls[i].m * balls[i].m + rc_v3_norm2(balls[i].p) * inv_c2);
    for (size_t j = 0; j < k; j++) {
        const rc_contact *c = &contacts[j];
        double pan = rc_v3_dot(balls[c->a].p, c->n);
        if (c->b < 0) {
            qt[j] = 0.0;
            a0[j] = pan;
        } else {
            double pbn = rc_v3_dot(balls[c->b].p, c->n), Mt = M0[c->a] + M0[c->b];
            qt[j] = (pan + pbn) / Mt * inv_c2;
            /* the zmf law's approach, without its cancellation for a pair moving fast
             * together in this frame (pair_axis.h) */
            a0[j] = rc_pair_a0(&balls[c->a], &balls[c->b], c->n, inv_c2, M0[c->a], M0[c->b],
                               pan, pbn);
        }
        /* a contact that is not approaching takes no impulse to begin with */
        active[j] = a0[j] > 0.0;
        if (!active[j])
            a0[j] = 0.0;
    }
    cwork w = {k, contacts, active, balls, M0, qt, a0, Mp, pp, NULL, NULL, NULL, NULL};
    if (fast_pairs(inv_c2, balls, k, contacts, M0)) {
        M0d = malloc(nballs * sizeof *M0d);
        Mpd = malloc(nballs * sizeof *Mpd);
        ppd = malloc(nballs * sizeof *ppd);
        qtd = malloc(k * sizeof *qtd);
        st = RC_ENOMEM;
        if (!M0d || !Mpd || !ppd || !qtd)
            goto done;
        for (size_t i = 0; i < nballs; i++)
            M0d[i] = eng_dd_sqrt(eng_dd_add(eng_two_prod(balls[i].m, balls[i].m),
                                            eng_dd_mul_d(eng_dd_dot(balls[i].p, balls[i].p),
                                                         inv_c2)));
        for (size_t j = 0; j < k; j++) {
            const rc_contact *c = &contacts[j];
            if (c->b < 0) {
                qtd[j] = eng_dd_of(0.0);
                continue;
            }
            const eng_dd Pn = eng_dd_add(eng_dd_dot(balls[c->a].p, c->n),
                                         eng_dd_dot(balls[c->b].p, c->n));
            qtd[j] = eng_dd_div(eng_dd_mul_d(Pn, inv_c2), eng_dd_add(M0d[c->a], M0d[c->b]));
        }
        w.M0d = M0d;
        w.qtd = qtd;
        w.Mpd = Mpd;
        w.ppd = ppd;
    }
    if (pivot) {
        /* Murty's least-index principal pivoting: solve on the active set, then flip the
         * first contact that violates complementarity (a pulling one leaves, one that
         * would approach beyond its restitution joins), until none does. From the
         * approaching contacts: where none pulls, the first solve is the answer. */
        for (size_t np = 0;; np++) {
            st = newton(&w, nballs, J, A, rhs, idx, piv, NULL);
            if (st != RC_OK)
                goto done;
            if (inv_c2 != 0.0 && pulls(&w, J)) {
                /* At finite c the conditions are quadratic in J, and from J = 0 Newton can
                 * reach a root that pulls while one that pushes exists (fast symmetric
                 * groups: the middle ball of a head-on trio gains energy from both
                 * contacts). Try again from the root of the conditions with each ball's
                 * energy frozen (linear: one step), which is near the pushing one. */
                double *qsave = w.qt;
                w.qt = qz;
                int s2 = newton(&w, nballs, Jg, A, rhs, idx, piv, NULL);
                w.qt = qsave;
                if (s2 == RC_OK && !pulls(&w, Jg) &&
                    newton(&w, nballs, Jt, A, rhs, idx, piv, Jg) == RC_OK && !pulls(&w, Jt))
                    for (size_t j = 0; j < k; j++)
                        J[j] = Jt[j];
            }
            post_states(&w, nballs, J);
            const size_t flip = first_violation(&w, nballs, J);
            if (flip == k)
                break;
            if (np == CP_MAX_PIVOTS(k)) {
                st = RC_ENOCONVERGE;
                goto done;
            }
            active[flip] = !active[flip];
        }
    } else {
        /* Active set: solve, drop the most pulling contact, repeat (at most k times). */
        for (;;) {
            st = newton(&w, nballs, J, A, rhs, idx, piv, NULL);
            if (st != RC_OK)
                goto done;
            size_t worst = k;
            for (size_t j = 0; j < k; j++)
                if (active[j] && J[j] < 0.0 && (worst == k || J[j] < J[worst]))
                    worst = j;
            if (worst == k)
                break;
            active[worst] = 0;
        }
    }
    post_states(&w, nballs, J);
    /* a fast pair's post rest masses: M'^2 - |p'|^2/c^2 cancels to order gamma^2 */
    m2d = w.Mpd ? malloc(nballs * sizeof *m2d) : NULL;
    if (w.Mpd && !m2d) {
        st = RC_ENOMEM;
        goto done;
    }
    for (size_t i = 0; m2d && i < nballs; i++)
        m2d[i] = eng_dd_sub(eng_dd_mul(Mpd[i], Mpd[i]),
                            eng_dd_mul_d(eng_ddv_norm2(ppd[i]), inv_c2)).hi;
    size_t nactive = 0;
    for (size_t j = 0; j < k; j++)
        nactive += active[j] != 0;
    if (inv_c2 != 0.0 && nactive >= 2) {
        /* the rest masses come from the targets (an impulse-only outcome may even be
         * spacelike for a ball; the step below takes it back to its rest mass) */
        double *mstar = malloc(nballs * sizeof *mstar);
        if (!mstar) {
            st = RC_ENOMEM;
            goto done;
        }
        st = keep_rest_masses(inv_c2, nballs, balls, k, contacts, active, Mp, pp, w.Mpd, w.ppd,
                              m2d, mstar);
        for (size_t i = 0; i < nballs && st == RC_OK; i++)
            if (mstar[i] != 0.0) {
                balls[i].m = mstar[i];
                balls[i].p = pp[i];
            }
        free(mstar);
        if (st != RC_OK)
            goto done;
    } else {
        for (size_t i = 0; i < nballs; i++) {
            double m2 = m2d ? m2d[i] : Mp[i] * Mp[i] - rc_v3_norm2(pp[i]) * inv_c2;
            if (!(m2 > 0.0) || !(Mp[i] > 0.0)) {
                st = RC_EMASS;
                goto done;
            }
        }
        for (size_t i = 0; i < nballs; i++) {
            if (inv_c2 != 0.0)
                balls[i].m = sqrt(m2d ? m2d[i] : Mp[i] * Mp[i] - rc_v3_norm2(pp[i]) * inv_c2);
            balls[i].p = pp[i];
        }
    }
    if (jout)
        for (size_t j = 0; j < k; j++)
            jout[j] = J[j];
    st = RC_OK;
done:
    free(M0);
    free(Mp);
    free(pp);
    free(qt);
    free(a0);
    free(J);
    free(A);
    free(rhs);
    free(idx);
    free(active);
    free(piv);
    free(qz);
    free(Jg);
    free(Jt);
    free(M0d);
    free(Mpd);
    free(qtd);
    free(ppd);
    free(m2d);
    return st;
}

int rc_contacts_resolve(double inv_c2, size_t nballs, rc_particle *balls, size_t k,
                        const rc_contact *contacts, double *jout)
{
    const int st = check_input(inv_c2, nballs, balls, k, contacts);
    return st != RC_OK ? st : joint(0, inv_c2, nballs, balls, k, contacts, jout);
}

/* in_group_zmf for a group whose ZMF moves fast (pair_axis.h, RC_PAIR_FAST): its balls
 * (only those in its contacts: a bystander keeps its bits) taken to the ZMF by
 * eng_group_zmf_fast, the rule run there on them, the outcome boosted back. */
static int in_fast_zmf(const rc_collision_params *prm, int seq, double inv_c2, size_t nballs,
                       rc_particle *balls, size_t k, const rc_contact *contacts, double *jout)
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
    st = eng_group_zmf_fast(inv_c2, nm, S, k, C0, B, C, f, &u, &g);
    if (st != RC_OK)
        goto done;
    st = seq ? eng_contacts_sequential(prm, nm, B, k, C, J) : joint(1, inv_c2, nm, B, k, C, J);
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
static int in_group_zmf(const rc_collision_params *prm, double inv_c2, size_t nballs,
                        rc_particle *balls, size_t k, const rc_contact *contacts, double *jout)
{
    const int seq = prm->groups == RC_GROUPS_SEQUENTIAL;
    int wall = 0;
    for (size_t j = 0; j < k; j++)
        wall |= contacts[j].b < 0;
    if (inv_c2 == 0.0 || wall || k == 0)
        return seq ? eng_contacts_sequential(prm, nballs, balls, k, contacts, jout)
                   : joint(1, inv_c2, nballs, balls, k, contacts, jout);
    rc_vec3 P;
    double Mt;
    eng_group_momentum(inv_c2, nballs, balls, k, contacts, &P, &Mt);
    /* a ZMF moving near c: the plain boost below would cancel to order gamma^2 */
    if (rc_v3_norm2(P) * inv_c2 > RC_PAIR_FAST * Mt * Mt)
        return in_fast_zmf(prm, seq, inv_c2, nballs, balls, k, contacts, jout);
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
    st = seq ? eng_contacts_sequential(prm, nballs, B, k, C, J)
             : joint(1, inv_c2, nballs, B, k, C, J);
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

int rc_contacts_solve(const rc_collision_params *prm, size_t nballs, rc_particle *balls,
                      size_t k, const rc_contact *contacts, double *jout)
{
    double inv_c2;
    if (!prm || rc_inv_c2(prm->c, &inv_c2) != RC_OK || !rc_group_rule_name(prm->groups))
        return RC_EINVAL;
    const int st = check_input(inv_c2, nballs, balls, k, contacts);
    if (st != RC_OK)
        return st;
    if (prm->groups == RC_GROUPS_DROP)
        return joint(0, inv_c2, nballs, balls, k, contacts, jout);
    return in_group_zmf(prm, inv_c2, nballs, balls, k, contacts, jout);
}

void eng_group_momentum(double inv_c2, size_t nballs, const rc_particle *balls, size_t k,
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
