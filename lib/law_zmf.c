/* law_zmf.c — the four-impulse restitution law of shared/DESIGN.md (papers/zmf-law.md).
 *
 * The impulse on ball 0 is the four-vector J q with q = (u.n/c^2, n): q is orthogonal to
 * the total four-momentum, so energy and momentum are conserved exactly and each ball's
 * ZMF energy is unchanged. Writing a0 = p0.n - M0 u.n = (M1 p0.n - M0 p1.n)/(M0 + M1)
 * (the ZMF normal momentum of ball 0 times sqrt(s), s = 1 - (u.n)^2/c^2), restitution
 * on the ZMF normal momentum gives J = -(1 + eps) a0 / s and the rest-mass rise
 * m'^2 = m^2 + (1 - eps^2) a0^2 / (s c^2), the same for both balls. */
#include <math.h>

#include "relcol/law.h"
#include "relcol/sim.h"
#include "relcol/status.h"

static int zmf_collide(const rc_collision_params *prm, rc_particle *a, rc_particle *b,
                       rc_vec3 n)
{
    const double k = rc_inv_c2_of(prm->c), eps = prm->eps;
    const double M0 = sqrt(a->m * a->m + rc_v3_norm2(a->p) * k);
    const double M1 = sqrt(b->m * b->m + rc_v3_norm2(b->p) * k);
    const double Mt = M0 + M1;
    const double pn0 = rc_v3_dot(a->p, n), pn1 = rc_v3_dot(b->p, n);
    const double un = (pn0 + pn1) / Mt;
    /* a0 = mu (v0 - v1).n with mu = M0 M1 / (M0 + M1): > 0 when approaching */
    const double a0 = (M1 * pn0 - M0 * pn1) / Mt;
    if (!(a0 > 0.0))
        return RC_NO_COLLISION;
    const double s = 1.0 - un * un * k;
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
 * prm->groups (lib/engine/contacts.c). */
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
