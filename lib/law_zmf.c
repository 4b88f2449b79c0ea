/* law_zmf.c — the four-impulse restitution law of shared/DESIGN.md (papers/zmf-law.md).
 *
 * The impulse on ball 0 is the four-vector J q with q = (u.n/c^2, n): q is orthogonal to
 * the total four-momentum, so energy and momentum are conserved exactly and each ball's
 * ZMF energy is unchanged. Writing a0 = p0.n - M0 u.n = (M1 p0.n - M0 p1.n)/(M0 + M1)
 * (the ZMF normal momentum of ball 0 times sqrt(s), s = 1 - (u.n)^2/c^2), restitution
 * on the ZMF normal momentum gives J = -(1 + eps) a0 / s and the rest-mass rise
 * m'^2 = m^2 + (1 - eps^2) a0^2 / (s c^2), the same for both balls.
 *
 * When the pair moves fast along n or both balls are fast (pair_axis.h: RC_PAIR_FAST,
 * RC_GAMMA_FAST), a0 and s can be differences of numbers gamma^2 times their size (balls
 * moving together near c) and are computed without the cancellation instead: a0 from the
 * rapidity difference along n or as d.n from the split of d = mu (v0 - v1) along and
 * across the total momentum, s as a sum of positive terms. The plain forms would lose
 * every digit by gamma ~ 1e8 and call an approaching pair separating. Otherwise they
 * lose a few bits at most and are kept (the classical path is one of them). */
#include <math.h>

#include "relcol/contacts.h"
#include "relcol/law.h"
#include "relcol/status.h"
#include "pair_axis.h"

/* a0 and s for a fast pair, kept out of line (and returned in registers) so that the
 * common path stays small. */
typedef struct {
    double a0, s;
} zmf_as;

__attribute__((noinline)) static zmf_as zmf_fast(const rc_particle *a, const rc_particle *b,
                                                 rc_vec3 n, double k, double M0, double M1,
                                                 double pn0, double pn1)
{
    const double sqrt_k = sqrt(k);
    const rc_axis ax = rc_axis_along(a, b, n, k, M0, M1, pn0, pn1);
    return (zmf_as){rc_pair_a0_fast(a, b, n, k, sqrt_k, &ax), rc_axis_s(&ax, sqrt_k)};
}

static int zmf_collide(const rc_collision_params *prm, rc_particle *a, rc_particle *b,
                       rc_vec3 n)
{
    const double k = rc_inv_c2_of(prm->c), eps = prm->eps;
    const double M0 = sqrt(a->m * a->m + rc_v3_norm2(a->p) * k);
    const double M1 = sqrt(b->m * b->m + rc_v3_norm2(b->p) * k);
    const double Mt = M0 + M1;
    const double pn0 = rc_v3_dot(a->p, n), pn1 = rc_v3_dot(b->p, n);
    const double un = (pn0 + pn1) / Mt;
    double a0, s;
    const double w = un * un * k;
    /* s cancels only when the pair moves fast along n, a0 only when both balls are fast,
     * move the same way along n and so make the ZMF fast (pair_axis.h): the cheap tests
     * first keep the common path plain */
    if (!(w > RC_PAIR_FAST) &&
        !(M0 > RC_GAMMA_FAST * a->m && M1 > RC_GAMMA_FAST * b->m && pn0 * pn1 > 0.0 &&
          rc_v3_norm2(rc_v3_add(a->p, b->p)) * k > RC_PAIR_FAST * Mt * Mt)) {
        /* a0 = mu (v0 - v1).n with mu = M0 M1 / (M0 + M1): > 0 when approaching */
        a0 = (M1 * pn0 - M0 * pn1) / Mt;
        s = 1.0 - w;
    } else {
        const zmf_as f = zmf_fast(a, b, n, k, M0, M1, pn0, pn1);
        a0 = f.a0;
        s = f.s;
    }
    if (!(a0 > 0.0))
        return RC_NO_COLLISION;
    const double J = -(1.0 + eps) * a0 / s;
    a->p = rc_v3_axpy(a->p, J, n);
    b->p = rc_v3_axpy(b->p, -J, n);
    if (eps != 1.0) {
        const double dm2 = (1.0 - eps * eps) * a0 * (a0 / s) * k;
        a->m = sqrt(a->m * a->m + dm2);
        b->m = sqrt(b->m * b->m + dm2);
    }
    return RC_OK;
}

/* The group solver: the same restitution condition on every contact, by the rule
 * prm->groups (lib/contacts/), the sequential rule's single contacts by this law. */
int rc_contacts_solve(const rc_collision_params *prm, size_t nballs, rc_particle *balls,
                      size_t k, const rc_contact *contacts, double *jout)
{
    return rc_contacts_solve_law(&rc_law_zmf, prm, nballs, balls, k, contacts, jout);
}

static int zmf_group(const rc_collision_params *prm, size_t nballs, rc_particle *balls,
                     size_t k, const rc_contact *contacts, double *jout)
{
    return rc_contacts_solve(prm, nballs, balls, k, contacts, jout);
}

const rc_law rc_law_zmf = {
    .name = "zmf",
    .summary = "four-impulse along n; ZMF energies kept, ZMF normal momentum scaled by -eps",
    .collide = zmf_collide,
    .group = zmf_group,
    .uses_angle = 0,
    .keeps_zmf_energy = 1,
};
