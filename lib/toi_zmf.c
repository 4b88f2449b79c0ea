/* toi_zmf.c — the "zmf" contact frame: both worldlines are boosted into the pair's
 * zero-momentum frame (both shapes contracted along the relative axis there), contact is
 * found there, and the event and the normal four-vector (0, nbar) are boosted back.
 *
 * Every change of frame is written as identity + a term carrying a factor 1/c^2, so
 * with inv_c2 = 0 (a Galilean boost) the ZMF problem has bit for bit the table's d and
 * w, both ZMF shapes are exact spheres, and the result equals the sphere frame's. */
#include <math.h>

#include "relcol/status.h"
#include "relcol/toi.h"
#include "kinematics_private.h"
#include "toi_private.h"

/* v' - (v - u), with v' the velocity seen from the frame moving at u; every term has a
 * factor inv_c2 (G = gamma_u inv_c2/(gamma_u + 1), since 1/gamma_u - 1 = -G u^2):
 *   v' = [v/gamma_u - u + G (u.v) u] / (1 - u.v/c^2). */
static rc_vec3 boost_velocity_correction(rc_vec3 v, rc_vec3 u, double gu, double k)
{
    const double G = gu * k / (gu + 1.0);
    const double uv = rc_v3_dot(u, v), u2 = rc_v3_norm2(u);
    const rc_vec3 a = rc_v3_axpy(rc_v3_scale(-u2, v), uv, u); /* (u.v)u - u^2 v */
    const rc_vec3 num = rc_v3_axpy(rc_v3_scale(G, a), k * uv, rc_v3_sub(v, u));
    return rc_v3_scale(1.0 / (1.0 - uv * k), num);
}

/* The zmf kernel for a pair whose ZMF moves near c (rc_toi_zmf_is_fast_): the ZMF momenta
 * from rc_toi_zmf_fast_, the relative ZMF velocity as the difference of two opposite
 * velocities, and ball 0's table time at contact from its proper time, (ZMF time elapsed)
 * M0/M0z, where boosting its centre event back would subtract terms gamma^2 times the
 * result. The events of the given states and the offsets boost without cancellation. */
static int zmf_fast(const rc_toi_params *prm, const rc_toi_ball *a, const rc_toi_ball *b,
                    rc_toi_workspace *ws, rc_toi_contact *out, double k, double M0, double M1)
{
    const rc_vec3 v0 = rc_v3_scale(1.0 / M0, a->p);
    const rc_vec3 u = rc_v3_scale(1.0 / (M0 + M1), rc_v3_add(a->p, b->p));
    double gu, M0z, M1z;
    rc_vec3 p0z;
    rc_toi_zmf_fast_(a, b, k, M0, M1, &gu, &p0z, &M0z, &M1z);
    const rc_vec3 p1z = rc_v3_scale(-1.0, p0z);
    const rc_toi_shape s0 = rc_toi_shape_of(a->r, a->m, p0z, k);
    const rc_toi_shape s1 = rc_toi_shape_of(b->r, b->m, p1z, k);
    const rc_vec3 v0z = rc_v3_scale(1.0 / M0z, p0z), v1z = rc_v3_scale(1.0 / M1z, p1z);
    rc_four e0 = {0.0, a->x}, e1 = {0.0, b->x};
    rc_boost_g_(u, gu, k, &e0);
    rc_boost_g_(u, gu, k, &e1);
    const double tau0 = e0.t > e1.t ? e0.t : e1.t;
    const rc_vec3 x0z = rc_v3_axpy(e0.x, tau0 - e0.t, v0z);
    const rc_vec3 x1z = rc_v3_axpy(e1.x, tau0 - e1.t, v1z);
    double tz;
    rc_vec3 y0z, nz;
    int st = rc_toi_shapes_rel(&s0, &s1, rc_v3_sub(x1z, x0z), rc_v3_sub(v1z, v0z), prm, ws,
                               &tz, &y0z, &nz);
    if (st != RC_OK)
        return st;
    const rc_vec3 mu = rc_v3_scale(-1.0, u);
    const double tc0 = ((tau0 - e0.t) + tz) * (M0 / M0z);
    rc_four dy = {0.0, y0z}, qn = {0.0, nz};
    rc_boost_g_(mu, gu, k, &dy);
    rc_boost_g_(mu, gu, k, &qn);
    out->t = tc0 + dy.t;
    out->x = rc_toi_point_(a->x, v0, tc0, dy.x);
    const double un = rc_v3_dot(u, nz);
    out->n = rc_v3_scale(1.0 / sqrt(1.0 + gu * gu * k * un * un), qn.x);
    return RC_OK;
}

int rc_toi_zmf_(const rc_toi_params *prm, const rc_toi_ball *a, const rc_toi_ball *b,
                rc_toi_workspace *ws, rc_toi_contact *out)
{
    const double k = rc_inv_c2_of(prm->c);
    const double M0 = rc_mass_rel(a->m, a->p, k), M1 = rc_mass_rel(b->m, b->p, k);
    if (rc_toi_zmf_is_fast_(a, b, k, M0, M1))
        return zmf_fast(prm, a, b, ws, out, k, M0, M1);
    /* (rc_velocity: p / rc_mass_rel, the masses above) */
    const rc_vec3 v0 = rc_v3_scale(1.0 / M0, a->p), v1 = rc_v3_scale(1.0 / M1, b->p);
    const rc_vec3 u = rc_v3_scale(1.0 / (M0 + M1), rc_v3_add(a->p, b->p));
    double gu;
    int st = rc_gamma_from_velocity(u, k, &gu);
    if (st != RC_OK)
        return st;
    const rc_vec3 mu = rc_v3_scale(-1.0, u);

    /* ZMF momenta give the ZMF shapes (antiparallel velocities: the relative axis). Every
     * boost is by u or -u, whose Lorentz factor (the same bits: |-u|^2 = |u|^2) is gu, so
     * each is rc_boost's without the factor computed and checked again. */
    rc_four q0 = {M0, a->p}, q1 = {M1, b->p};
    rc_boost_g_(u, gu, k, &q0);
    rc_boost_g_(u, gu, k, &q1);
    const rc_vec3 v0z = rc_v3_scale(1.0 / q0.t, q0.x), v1z = rc_v3_scale(1.0 / q1.t, q1.x);

    /* The given states are the events (0, x_i); in the ZMF they are not simultaneous.
     * Contact is searched from ZMF time tau0 = the later of the two, so that the centre
     * events at contact lie in the future of both given states on their worldlines. */
    rc_four e0 = {0.0, a->x}, e1 = {0.0, b->x};
    rc_boost_g_(u, gu, k, &e0);
    rc_boost_g_(u, gu, k, &e1);
    const double tau0 = e0.t > e1.t ? e0.t : e1.t;
    const rc_vec3 x0z = rc_v3_axpy(e0.x, tau0 - e0.t, v0z); /* centres at ZMF time tau0 */
    const rc_vec3 x1z = rc_v3_axpy(e1.x, tau0 - e1.t, v1z);
    /* relative ZMF velocity as w + corrections (exactly w when inv_c2 = 0) */
    const rc_vec3 wz = rc_v3_add(
        rc_v3_sub(v1, v0), rc_v3_sub(boost_velocity_correction(v1, u, gu, k),
                                     boost_velocity_correction(v0, u, gu, k)));
    const rc_vec3 dz = rc_v3_sub(x1z, x0z);
    /* bounding spheres apart and not approaching in the ZMF: rc_toi_shapes_rel's answer
     * is RC_MISS whatever the shapes (its broad phase, or the sphere problem of exact
     * spheres, decides it by these very tests), so they are not made */
    if (!(rc_v3_dot(dz, wz) < 0.0) &&
        !(rc_v3_norm(dz) <= (a->r + b->r) * (1.0 + prm->touch_tol)))
        return RC_MISS;
    /* (rc_toi_shape_of's shapes, inline, 1/c taken once) */
    const double ic = sqrt(k);
    const rc_toi_shape s0 = rc_toi_shape_Mc_(a->r, a->m, q0.x, ic,
                                             sqrt(a->m * a->m + rc_v3_norm2(q0.x) * k));
    const rc_toi_shape s1 = rc_toi_shape_Mc_(b->r, b->m, q1.x, ic,
                                             sqrt(b->m * b->m + rc_v3_norm2(q1.x) * k));
    double tz;
    rc_vec3 y0z, nz;
    st = rc_toi_shapes_rel(&s0, &s1, dz, wz, prm, ws, &tz, &y0z, &nz);
    if (st != RC_OK)
        return st;

    /* Back to the table: ball 0's centre event at contact lies on its table worldline
     * at table time tc0; the contact offset (0, y0z) is boosted separately (linear). */
    const double tzabs = tau0 + tz;
    rc_four c0 = {tzabs, rc_v3_axpy(e0.x, tzabs - e0.t, v0z)};
    rc_four dy = {0.0, y0z};
    rc_four qn = {0.0, nz};
    rc_boost_g_(mu, gu, k, &c0);
    rc_boost_g_(mu, gu, k, &dy);
    rc_boost_g_(mu, gu, k, &qn);
    out->t = c0.t + dy.t;
    out->x = rc_toi_point_(a->x, v0, c0.t, dy.x);
    /* |spatial part of boost(0, nbar)|^2 = 1 + gamma_u^2 (u.nbar)^2 / c^2; normalising
     * with this closed form keeps n = nbar bit for bit when inv_c2 = 0. The normalised
     * four-vector is then (u.n/c^2, n): the zmf law's q. */
    const double un = rc_v3_dot(u, nz);
    out->n = rc_v3_scale(1.0 / sqrt(1.0 + gu * gu * k * un * un), qn.x);
    return RC_OK;
}

const rc_toi_frame rc_toi_frame_zmf = {
    .name = "zmf",
    .summary = "contact found in the pair's zero-momentum frame, event and normal boosted back",
    .toi = rc_toi_zmf_,
    .wall_contracted = 1,
    .contracted = 1,
    .covariant = 1,
    /* not deferrable: a pair can overlap in its ZMF while its bounding spheres are apart
     * in the table frame, so the spheres' contact time is no lower bound */
    .deferrable = 0,
    .shapes = NULL,
};
