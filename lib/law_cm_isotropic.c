/* law_cm_isotropic.c — seed 002's impact-angle law with restitution R on the whole
 * centre-of-momentum velocity, made relativistic (papers/cm-isotropic.md): in the pair's
 * ZMF the momenta are reflected about the ZMF contact normal (an elastic collision at
 * impact angle alpha) and then the whole ZMF momentum is scaled by R, each ball's ZMF
 * energy kept, so m'^2 = m^2 + (1 - R^2) |pbar|^2 / c^2. Classically this is exactly
 * eqs (8)-(13) followed by (22)-(27). */
#include <math.h>

#include "relcol/law.h"
#include "relcol/status.h"
#include "kinematics_private.h"
#include "pair_axis.h"

/* Unit vectors e1, e2 completing phat to a right-handed frame, with e1 the in-plane
 * (xy) perpendicular rotated +90 degrees, so that azimuth 0 keeps a 2-D problem 2-D. */
static void perp_frame(rc_vec3 phat, rc_vec3 *e1, rc_vec3 *e2)
{
    double h = hypot(phat.x, phat.y);
    if (h > 0.0)
        *e1 = rc_v3(-phat.y / h, phat.x / h, 0.0);
    else
        *e1 = rc_v3(1.0, 0.0, 0.0);
    *e2 = rc_v3_cross(phat, *e1);
}

static int cm_isotropic_collide(const rc_collision_params *prm, rc_particle *a,
                                rc_particle *b, rc_vec3 n)
{
    const double k = rc_inv_c2_of(prm->c), R = prm->eps;
    const double M0 = rc_mass_rel(a->m, a->p, k), M1 = rc_mass_rel(b->m, b->p, k);
    const double Mt = M0 + M1;
    const rc_vec3 P = rc_v3_add(a->p, b->p);
    const rc_vec3 u = rc_v3_scale(1.0 / Mt, P);
    const int fast = rc_v3_norm2(P) * k > RC_PAIR_FAST * Mt * Mt;
    rc_pair_split z = {0};
    double g;
    rc_four A;
    if (!fast) {
        g = Mt / rc_pair_invariant_mass(a, b, k); /* gamma of the ZMF */
        /* Ball 0 in the ZMF: (Mbar0, pbar). Boosting p0 directly computes p0 - gamma M0 u
         * + ..., which cancels when ball 0 moves nearly with the ZMF (a heavy ball 0), and
         * then costs the light ball its accuracy. With d = p0 - M0 u = (M1 p0 - M0 p1)/(M0 +
         * M1) the boost is pbar = d + (gamma - 1)(d.uhat) uhat: no cancellation beyond that
         * of v0 - v1, which a slow ZMF keeps to a few bits (RC_PAIR_FAST). */
        const rc_vec3 d =
            rc_v3_scale(1.0 / Mt, rc_v3_sub(rc_v3_scale(M1, a->p), rc_v3_scale(M0, b->p)));
        A.x = rc_v3_axpy(d, g * g * k / (g + 1.0) * rc_v3_dot(d, u), u);
    } else {
        /* A fast ZMF: v0 - v1 and 1/gamma^2 would cancel to order gamma^2 (balls moving
         * together near c); pair_axis.h forms d without it, and pbar = t0 + gamma dl uhat */
        rc_pair_split_of(a, b, M0, M1, k, sqrt(k), &z);
        g = z.g;
        A.x = rc_v3_axpy(z.t0, g * z.dl, z.uhat);
    }
    const double pb2 = rc_v3_norm2(A.x);
    A.t = sqrt(a->m * a->m + pb2 * k);
    if (!(pb2 > 0.0))
        return RC_NO_COLLISION;

    rc_vec3 nh;
    if (isnan(prm->alpha) && !fast) {
        rc_four q = {rc_v3_dot(u, n) * k, n}; /* normal four-vector -> (0, nbar) */
        rc_boost_g(u, g, k, &q);
        nh = rc_v3_scale(1.0 / rc_v3_norm(q.x), q.x);
    } else if (isnan(prm->alpha)) {
        /* the boosted normal four-vector is n across uhat plus (n.uhat)/gamma along it:
         * the boost's own form subtracts numbers of order gamma to get the 1/gamma */
        const double nl = rc_v3_dot(n, z.uhat);
        const rc_vec3 nb = rc_v3_axpy(rc_v3_axpy(n, -nl, z.uhat), nl / g, z.uhat);
        nh = rc_v3_scale(1.0 / rc_v3_norm(nb), nb);
    } else {
        rc_vec3 ph = rc_v3_scale(1.0 / sqrt(pb2), A.x), e1, e2;
        perp_frame(ph, &e1, &e2);
        const double sa = sin(prm->alpha), ca = cos(prm->alpha);
        nh = rc_v3_scale(ca, ph);
        nh = rc_v3_axpy(nh, sa * cos(prm->azimuth), e1);
        nh = rc_v3_axpy(nh, sa * sin(prm->azimuth), e2);
    }
    const double pn = rc_v3_dot(A.x, nh);
    if (!(pn > 0.0))
        return RC_NO_COLLISION;

    A.x = rc_v3_scale(R, rc_v3_axpy(A.x, -2.0 * pn, nh));
    /* Ball 1 has the opposite ZMF momentum and its own ZMF energy (kept); each ball is
     * boosted back on its own rather than as P - p0', which would lose the light ball's
     * digits to the heavy one's. */
    rc_four B = {sqrt(b->m * b->m + pb2 * k), rc_v3_scale(-1.0, A.x)};
    rc_boost_g(rc_v3_scale(-1.0, u), g, k, &A); /* back to the table frame */
    rc_boost_g(rc_v3_scale(-1.0, u), g, k, &B);
    if (R != 1.0) {
        const double dm2 = (1.0 - R * R) * pb2 * k;
        a->m = sqrt(a->m * a->m + dm2);
        b->m = sqrt(b->m * b->m + dm2);
    }
    a->p = A.x;
    b->p = B.x;
    return RC_OK;
}

const rc_law rc_law_cm_isotropic = {
    .name = "cm-isotropic",
    .summary =
        "seed 002: elastic at impact angle alpha in the ZMF, then ZMF momentum scaled by R",
    .collide = cm_isotropic_collide,
    /* no group solver: seed 002's rule is defined for one pair (the engine resolves a
     * group's contacts one at a time, rc_sim_diag.group_sequential) */
    .group = NULL,
    .uses_angle = 1,
    .keeps_zmf_energy = 1,
};
