/* contacts/joint.c — simultaneous contacts resolved together (papers/simultaneous-contacts.md):
 * one four-impulse J_j q_j per contact, the J_j found by Newton's method on the restitution
 * conditions of the zmf law of the contacts that push (a k x k linear system each step,
 * solved by LU; classically the conditions are linear and one step is exact), the set of
 * pushing contacts found by principal pivoting (the `simultaneous` rule) or by dropping the
 * most pulling one (the `drop` rule). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "relcol/kinematics.h"
#include "relcol/status.h"
#include "../pair_axis.h"
#include "private.h"

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
    const ctc_dd *M0d;
    const ctc_dd *qtd;
    ctc_dd *Mpd;
    ctc_ddv *ppd;
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
        w->ppd[i] = ctc_ddv_of(w->b0[i].p);
        w->Mpd[i] = w->M0d[i];
    }
    for (size_t j = 0; j < w->k; j++) {
        if (!w->active[j])
            continue;
        const rc_contact *c = &w->c[j];
        const ctc_dd dM = ctc_dd_mul_d(w->qtd[j], J[j]);
        w->ppd[c->a] = ctc_ddv_axpy(w->ppd[c->a], -J[j], c->n);
        w->Mpd[c->a] = ctc_dd_sub(w->Mpd[c->a], dM);
        if (c->b >= 0) {
            w->ppd[c->b] = ctc_ddv_axpy(w->ppd[c->b], J[j], c->n);
            w->Mpd[c->b] = ctc_dd_add(w->Mpd[c->b], dM);
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
        const ctc_dd pan = ctc_ddv_dot_d(w->ppd[c->a], c->n);
        const ctc_dd pbn = ctc_ddv_dot_d(w->ppd[c->b], c->n);
        const ctc_dd Ma = w->Mpd[c->a], Mb = w->Mpd[c->b];
        const ctc_dd r = ctc_dd_sub(ctc_dd_mul(Mb, pan), ctc_dd_mul(Ma, pbn));
        return ctc_dd_add(r, ctc_dd_mul_d(ctc_dd_add(Ma, Mb), c->eps * w->a0[j])).hi;
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
        const ctc_dd nnd = ctc_dd_dot(c->n, cl->n);
        const ctc_dd pan = ctc_ddv_dot_d(w->ppd[c->a], c->n);
        const ctc_dd pbn = ctc_ddv_dot_d(w->ppd[c->b], c->n);
        const ctc_dd Ma = w->Mpd[c->a], Mb = w->Mpd[c->b];
        /* dMb pan - dMa pbn + (Mb sa - Ma sb) nn + eps a0 (dMa + dMb), dM = s q_t */
        const ctc_dd t1 = ctc_dd_mul(w->qtd[l], ctc_dd_sub(ctc_dd_mul_d(pan, sb),
                                                           ctc_dd_mul_d(pbn, sa)));
        const ctc_dd t2 = ctc_dd_mul(nnd, ctc_dd_sub(ctc_dd_mul_d(Mb, sa), ctc_dd_mul_d(Ma, sb)));
        const ctc_dd t3 = ctc_dd_mul_d(w->qtd[l], c->eps * w->a0[j] * (sa + sb));
        return ctc_dd_add(ctc_dd_add(t1, t2), t3).hi;
    }
    double dpan = sa * nn, dpbn = sb * nn;
    double dMa = sa * w->qt[l], dMb = sb * w->qt[l];
    double pan = rc_v3_dot(w->pp[c->a], c->n), pbn = rc_v3_dot(w->pp[c->b], c->n);
    double Ma = w->Mp[c->a], Mb = w->Mp[c->b];
    return dMb * pan + Mb * dpan - dMa * pbn - Ma * dpbn + c->eps * w->a0[j] * (dMa + dMb);
}


/* Newton on the active contacts (J of inactive ones stays 0), from J = 0, or from start (k entries, those of the active contacts read). */
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
        if (ctc_lu_factor(A, m, piv) != RC_OK)
            return RC_ENOCONVERGE;
        for (size_t r = 0; r < m; r++)
            if (!(fabs(A[r * m + r]) > PIVOT_REL_TOL * dmax))
                return RC_ENOCONVERGE; /* singular */
        ctc_lu_solve(A, m, piv, rhs);
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


/* The joint solve's arrays. */
typedef struct jbuf {
    double *M0, *Mp, *qt, *a0, *J, *A, *rhs;
    rc_vec3 *pp;
    size_t *idx, *piv;
    int *active;
    /* the simultaneous rule's second start: zero energy parts, its root, the Newton run */
    double *qz, *Jg, *Jt;
    /* double-double states for a group with a fast pair (fast_pairs) */
    ctc_dd *M0d, *Mpd, *qtd;
    ctc_ddv *ppd;
    double *m2d; /* their post rest masses squared */
} jbuf;

static void jbuf_free(jbuf *b)
{
    free(b->M0);
    free(b->Mp);
    free(b->pp);
    free(b->qt);
    free(b->a0);
    free(b->J);
    free(b->A);
    free(b->rhs);
    free(b->idx);
    free(b->active);
    free(b->piv);
    free(b->qz);
    free(b->Jg);
    free(b->Jt);
    free(b->M0d);
    free(b->Mpd);
    free(b->qtd);
    free(b->ppd);
    free(b->m2d);
}

static int jbuf_alloc(jbuf *b, int pivot, size_t nballs, size_t k)
{
    *b = (jbuf){0};
    b->M0 = malloc(nballs * sizeof *b->M0);
    b->Mp = malloc(nballs * sizeof *b->Mp);
    b->pp = malloc(nballs * sizeof *b->pp);
    b->qt = malloc(k * sizeof *b->qt);
    b->a0 = malloc(k * sizeof *b->a0);
    b->J = malloc(k * sizeof *b->J);
    /* (k x k doubles must not wrap around) */
    b->A = k <= SIZE_MAX / sizeof(double) / k ? malloc(k * k * sizeof *b->A) : NULL;
    b->rhs = malloc(k * sizeof *b->rhs);
    b->idx = malloc(k * sizeof *b->idx);
    b->active = malloc(k * sizeof *b->active);
    b->piv = malloc(k * sizeof *b->piv);
    if (pivot) {
        b->qz = calloc(k, sizeof *b->qz);
        b->Jg = malloc(k * sizeof *b->Jg);
        b->Jt = malloc(k * sizeof *b->Jt);
    }
    if (!b->M0 || !b->Mp || !b->pp || !b->qt || !b->a0 || !b->J || !b->A || !b->rhs ||
        !b->idx || !b->active || !b->piv || (pivot && (!b->qz || !b->Jg || !b->Jt)))
        return RC_ENOMEM;
    return RC_OK;
}

/* Each ball's energy / c^2, each contact's q_t and approach; the approaching contacts are
 * the first active set. */
static void conditions(jbuf *b, double inv_c2, size_t nballs, const rc_particle *balls,
                       size_t k, const rc_contact *contacts)
{
    for (size_t i = 0; i < nballs; i++)
        b->M0[i] = sqrt(balls[i].m * balls[i].m + rc_v3_norm2(balls[i].p) * inv_c2);
    for (size_t j = 0; j < k; j++) {
        const rc_contact *c = &contacts[j];
        double pan = rc_v3_dot(balls[c->a].p, c->n);
        if (c->b < 0) {
            b->qt[j] = 0.0;
            b->a0[j] = pan;
        } else {
            double pbn = rc_v3_dot(balls[c->b].p, c->n), Mt = b->M0[c->a] + b->M0[c->b];
            b->qt[j] = (pan + pbn) / Mt * inv_c2;
            /* the zmf law's approach, without its cancellation for a pair moving fast
             * together in this frame (pair_axis.h) */
            b->a0[j] = rc_pair_a0(&balls[c->a], &balls[c->b], c->n, inv_c2, b->M0[c->a],
                                  b->M0[c->b], pan, pbn);
        }
        /* a contact that is not approaching takes no impulse to begin with */
        b->active[j] = b->a0[j] > 0.0;
        if (!b->active[j])
            b->a0[j] = 0.0;
    }
}

/* The energies and q_t in double-double, for a group with a fast pair (w then keeps its
 * post states so too). */
static int conditions_dd(jbuf *b, cwork *w, double inv_c2, size_t nballs,
                         const rc_particle *balls, size_t k, const rc_contact *contacts)
{
    b->M0d = malloc(nballs * sizeof *b->M0d);
    b->Mpd = malloc(nballs * sizeof *b->Mpd);
    b->ppd = malloc(nballs * sizeof *b->ppd);
    b->qtd = malloc(k * sizeof *b->qtd);
    if (!b->M0d || !b->Mpd || !b->ppd || !b->qtd)
        return RC_ENOMEM;
    for (size_t i = 0; i < nballs; i++)
        b->M0d[i] = ctc_dd_sqrt(ctc_dd_add(ctc_two_prod(balls[i].m, balls[i].m),
                                           ctc_dd_mul_d(ctc_dd_dot(balls[i].p, balls[i].p),
                                                        inv_c2)));
    for (size_t j = 0; j < k; j++) {
        const rc_contact *c = &contacts[j];
        if (c->b < 0) {
            b->qtd[j] = ctc_dd_of(0.0);
            continue;
        }
        const ctc_dd Pn = ctc_dd_add(ctc_dd_dot(balls[c->a].p, c->n),
                                     ctc_dd_dot(balls[c->b].p, c->n));
        b->qtd[j] = ctc_dd_div(ctc_dd_mul_d(Pn, inv_c2), ctc_dd_add(b->M0d[c->a], b->M0d[c->b]));
    }
    w->M0d = b->M0d;
    w->qtd = b->qtd;
    w->Mpd = b->Mpd;
    w->ppd = b->ppd;
    return RC_OK;
}

/* Murty's least-index principal pivoting: solve on the active set, then flip the first
 * contact that violates complementarity (a pulling one leaves, one that would approach
 * beyond its restitution joins), until none does. From the approaching contacts: where
 * none pulls, the first solve is the answer. */
static int solve_pivoting(cwork *w, jbuf *b, double inv_c2, size_t nballs, size_t k)
{
    for (size_t np = 0;; np++) {
        const int st = newton(w, nballs, b->J, b->A, b->rhs, b->idx, b->piv, NULL);
        if (st != RC_OK)
            return st;
        if (inv_c2 != 0.0 && pulls(w, b->J)) {
            /* At finite c the conditions are quadratic in J, and from J = 0 Newton can
             * reach a root that pulls while one that pushes exists (fast symmetric groups:
             * the middle ball of a head-on trio gains energy from both contacts). Try again
             * from the root of the conditions with each ball's energy frozen (linear: one
             * step), which is near the pushing one. */
            double *qsave = w->qt;
            w->qt = b->qz;
            int s2 = newton(w, nballs, b->Jg, b->A, b->rhs, b->idx, b->piv, NULL);
            w->qt = qsave;
            if (s2 == RC_OK && !pulls(w, b->Jg) &&
                newton(w, nballs, b->Jt, b->A, b->rhs, b->idx, b->piv, b->Jg) == RC_OK &&
                !pulls(w, b->Jt))
                for (size_t j = 0; j < k; j++)
                    b->J[j] = b->Jt[j];
        }
        post_states(w, nballs, b->J);
        const size_t flip = first_violation(w, nballs, b->J);
        if (flip == k)
            return RC_OK;
        if (np == CP_MAX_PIVOTS(k))
            return RC_ENOCONVERGE;
        b->active[flip] = !b->active[flip];
    }
}

/* Active set: solve, drop the most pulling contact, repeat (at most k times). */
static int solve_dropping(cwork *w, jbuf *b, size_t nballs, size_t k)
{
    for (;;) {
        const int st = newton(w, nballs, b->J, b->A, b->rhs, b->idx, b->piv, NULL);
        if (st != RC_OK)
            return st;
        size_t worst = k;
        for (size_t j = 0; j < k; j++)
            if (b->active[j] && b->J[j] < 0.0 && (worst == k || b->J[j] < b->J[worst]))
                worst = j;
        if (worst == k)
            return RC_OK;
        b->active[worst] = 0;
    }
}

/* The outcome into balls[]: relativistically with two or more pushing contacts through
 * the rest-mass step, otherwise the impulses' post states (each must stay timelike). */
static int outcome(jbuf *b, const cwork *w, double inv_c2, size_t nballs, rc_particle *balls,
                   size_t k, const rc_contact *contacts)
{
    /* a fast pair's post rest masses: M'^2 - |p'|^2/c^2 cancels to order gamma^2 */
    if (w->Mpd && !(b->m2d = malloc(nballs * sizeof *b->m2d)))
        return RC_ENOMEM;
    for (size_t i = 0; b->m2d && i < nballs; i++)
        b->m2d[i] = ctc_dd_sub(ctc_dd_mul(b->Mpd[i], b->Mpd[i]),
                               ctc_dd_mul_d(ctc_ddv_norm2(b->ppd[i]), inv_c2)).hi;
    const double *m2d = b->m2d;
    size_t nactive = 0;
    for (size_t j = 0; j < k; j++)
        nactive += b->active[j] != 0;
    if (inv_c2 != 0.0 && nactive >= 2) {
        /* the rest masses come from the targets (an impulse-only outcome may even be
         * spacelike for a ball; the step below takes it back to its rest mass) */
        double *mstar = malloc(nballs * sizeof *mstar);
        if (!mstar)
            return RC_ENOMEM;
        const int st = ctc_keep_rest_masses(inv_c2, nballs, balls, k, contacts, b->active,
                                            b->Mp, b->pp, w->Mpd, w->ppd, m2d, mstar);
        for (size_t i = 0; i < nballs && st == RC_OK; i++)
            if (mstar[i] != 0.0) {
                balls[i].m = mstar[i];
                balls[i].p = b->pp[i];
            }
        free(mstar);
        return st;
    }
    for (size_t i = 0; i < nballs; i++) {
        double m2 = m2d ? m2d[i] : b->Mp[i] * b->Mp[i] - rc_v3_norm2(b->pp[i]) * inv_c2;
        if (!(m2 > 0.0) || !(b->Mp[i] > 0.0))
            return RC_EMASS;
    }
    for (size_t i = 0; i < nballs; i++) {
        if (inv_c2 != 0.0)
            balls[i].m = sqrt(m2d ? m2d[i] : b->Mp[i] * b->Mp[i] - rc_v3_norm2(b->pp[i]) * inv_c2);
        balls[i].p = b->pp[i];
    }
    return RC_OK;
}

int ctc_joint(int pivot, double inv_c2, size_t nballs, rc_particle *balls, size_t k,
              const rc_contact *contacts, double *jout)
{
    if (k == 0)
        return RC_OK;
    jbuf b;
    int st = jbuf_alloc(&b, pivot, nballs, k);
    if (st != RC_OK)
        goto done;
    conditions(&b, inv_c2, nballs, balls, k, contacts);
    cwork w = {k, contacts, b.active, balls, b.M0, b.qt, b.a0, b.Mp, b.pp, NULL, NULL, NULL, NULL};
    if (fast_pairs(inv_c2, balls, k, contacts, b.M0) &&
        (st = conditions_dd(&b, &w, inv_c2, nballs, balls, k, contacts)) != RC_OK)
        goto done;
    st = pivot ? solve_pivoting(&w, &b, inv_c2, nballs, k) : solve_dropping(&w, &b, nballs, k);
    if (st != RC_OK)
        goto done;
    post_states(&w, nballs, b.J);
    if ((st = outcome(&b, &w, inv_c2, nballs, balls, k, contacts)) != RC_OK)
        goto done;
    if (jout)
        for (size_t j = 0; j < k; j++)
            jout[j] = b.J[j];
done:
    jbuf_free(&b);
    return st;
}

int ctc_simultaneous(const ctc_rule *r, size_t nballs, rc_particle *balls, size_t k,
                     const rc_contact *contacts, double *jout)
{
    return ctc_joint(1, r->inv_c2, nballs, balls, k, contacts, jout);
}
