/* toi_transport.c — the "transport" contact frame: the geometric criterion of transport
 * codes (SMASH's covariant criterion, UrQMD's geometric one) for two balls taken as
 * points with cross-section pi (r0 + r1)^2. In the pair's centre-of-momentum frame the
 * two centres reach their closest approach at one CM time; they collide when that lies
 * ahead and the distance there (the transverse distance d_T, the impact parameter) is
 * below r0 + r1. The event is the midpoint of the two centres' closest-approach events
 * (SMASH's collision time, the mean of their computational-frame times). The normal
 * handed to the law is the one two hard spheres of radius sum r0 + r1 with impact
 * parameter d_T have when they touch, so the law sees an approaching pair and with c = inf
 * the outcome is the hard-sphere one. Walls see spheres of radius r.
 * papers/time-of-impact.md, "The transport frame". */
#include <math.h>

#include "relcol/status.h"
#include "relcol/toi.h"
#include "kinematics_private.h"
#include "toi_private.h"

/* The pair in its CM frame: velocity u of that frame (gamma gu), the centres at CM time
 * tau0 (the later of the two given events, so both lie in the future of the given
 * states), their CM velocities. */
typedef struct cm_pair {
    double k, gu, tau0;
    rc_vec3 u, x0, x1, v0, v1;
    int fast;      /* a CM moving near c (rc_toi_zmf_is_fast_): ... */
    double t0, t1; /* ... the given states' CM times, and the ratios of their balls' table */
    double r0, r1; /* and CM energies M/Mz: table time elapsed per CM time on a worldline */
} cm_pair;

static int cm_of(const rc_toi_params *prm, const rc_toi_ball *a, const rc_toi_ball *b,
                 cm_pair *c)
{
    const double k = rc_inv_c2_of(prm->c);
    const double M0 = rc_mass_rel(a->m, a->p, k), M1 = rc_mass_rel(b->m, b->p, k);
    c->k = k;
    c->u = rc_v3_scale(1.0 / (M0 + M1), rc_v3_add(a->p, b->p));
    c->fast = rc_toi_zmf_is_fast_(a, b, k, M0, M1);
    if (c->fast) {
        /* the plain boost cancels to order gamma^2 (toi_private.h, rc_toi_zmf_fast_) */
        double M0z, M1z;
        rc_vec3 p0z;
        rc_toi_zmf_fast_(a, b, k, M0, M1, &c->gu, &p0z, &M0z, &M1z);
        c->v0 = rc_v3_scale(1.0 / M0z, p0z);
        c->v1 = rc_v3_scale(-1.0 / M1z, p0z);
        c->r0 = M0 / M0z;
        c->r1 = M1 / M1z;
        rc_four e0 = {0.0, a->x}, e1 = {0.0, b->x};
        rc_boost_g(c->u, c->gu, k, &e0);
        rc_boost_g(c->u, c->gu, k, &e1);
        c->t0 = e0.t;
        c->t1 = e1.t;
        c->tau0 = e0.t > e1.t ? e0.t : e1.t;
        c->x0 = rc_v3_axpy(e0.x, c->tau0 - e0.t, c->v0);
        c->x1 = rc_v3_axpy(e1.x, c->tau0 - e1.t, c->v1);
        return RC_OK;
    }
    int st = rc_gamma_from_velocity(c->u, k, &c->gu);
    if (st != RC_OK)
        return st;
    rc_four q0 = {M0, a->p}, q1 = {M1, b->p}, e0 = {0.0, a->x}, e1 = {0.0, b->x};
    if ((st = rc_boost(c->u, k, &q0)) != RC_OK || (st = rc_boost(c->u, k, &q1)) != RC_OK ||
        (st = rc_boost(c->u, k, &e0)) != RC_OK || (st = rc_boost(c->u, k, &e1)) != RC_OK)
        return st;
    c->v0 = rc_v3_scale(1.0 / q0.t, q0.x);
    c->v1 = rc_v3_scale(1.0 / q1.t, q1.x);
    c->tau0 = e0.t > e1.t ? e0.t : e1.t;
    c->x0 = rc_v3_axpy(e0.x, c->tau0 - e0.t, c->v0);
    c->x1 = rc_v3_axpy(e1.x, c->tau0 - e1.t, c->v1);
    return RC_OK;
}

/* Squared distance of closest approach |d x w|^2 / |w|^2 (no cancellation against d.d);
 * |d|^2 when the centres do not move apart in the CM frame. */
static double impact2(rc_vec3 d, rc_vec3 w)
{
    const double w2 = rc_v3_norm2(w);
    return w2 > 0.0 ? rc_v3_norm2(rc_v3_cross(d, w)) / w2 : rc_v3_norm2(d);
}

int rc_toi_transport_impact(const rc_toi_params *prm, const rc_toi_ball *a,
                            const rc_toi_ball *b, double *dT2, double *tcm)
{
    if (!prm || !a || !b || !dT2)
        return RC_EINVAL;
    rc_toi_workspace *ws = NULL;
    rc_toi_contact out;
    /* the validation of rc_toi (the kernel itself needs no workspace) */
    int st = rc_toi_workspace_create(&ws);
    if (st != RC_OK)
        return st;
    st = rc_toi(&rc_toi_frame_transport, prm, a, b, ws, &out);
    rc_toi_workspace_free(&ws);
    if (st < 0)
        return st;
    cm_pair c;
    if ((st = cm_of(prm, a, b, &c)) != RC_OK)
        return st;
    const rc_vec3 d = rc_v3_sub(c.x1, c.x0), w = rc_v3_sub(c.v1, c.v0);
    *dT2 = impact2(d, w);
    if (tcm) {
        const double w2 = rc_v3_norm2(w);
        *tcm = w2 > 0.0 ? c.tau0 - rc_v3_dot(d, w) / w2 : c.tau0;
    }
    return RC_OK;
}

static int transport_toi(const rc_toi_params *prm, const rc_toi_ball *a, const rc_toi_ball *b,
                         rc_toi_workspace *ws, rc_toi_contact *out)
{
    (void)ws;
    cm_pair c;
    int st = cm_of(prm, a, b, &c);
    if (st != RC_OK)
        return st;
    const rc_vec3 d = rc_v3_sub(c.x1, c.x0), w = rc_v3_sub(c.v1, c.v0);
    const double w2 = rc_v3_norm2(w), dw = rc_v3_dot(d, w);
    /* closest approach strictly ahead: a pair at or past it (the pair just resolved
     * here, head on, sits exactly at it) is not hit again */
    if (!(w2 > 0.0) || !(dw < 0.0))
        return RC_MISS;
    const double R = a->r + b->r, bT = sqrt(impact2(d, w));
    if (!(bT < R))
        return RC_MISS;
    /* sqrt(R^2 - b^2) without cancellation; the spheres' normal approach speed is
     * |w| s / R: a grazing pair (graze_tol, as for every frame) transfers nothing */
    const double s = sqrt((R - bT) * (R + bT));
    if (!(s > prm->graze_tol * R))
        return RC_MISS;
    const double ts = -dw / w2;
    const rc_vec3 ds = rc_v3_axpy(d, ts, w); /* separation at closest approach, _|_ w */
    rc_vec3 nz = rc_v3_axpy(ds, -s / sqrt(w2), w);
    nz = rc_v3_scale(1.0 / sqrt(rc_v3_norm2(nz)), nz);

    const double T = c.tau0 + ts;
    const double un = rc_v3_dot(c.u, nz);
    const double nf = 1.0 / sqrt(1.0 + c.gu * c.gu * c.k * un * un);
    if (c.fast) {
        /* each centre's closest-approach event on its table worldline at the table time
         * its proper time gives ((CM time elapsed) M/Mz): boosting the midpoint back would
         * subtract terms gamma^2 times the result */
        const double s0 = ((c.tau0 - c.t0) + ts) * c.r0, s1 = ((c.tau0 - c.t1) + ts) * c.r1;
        const rc_vec3 v0 = rc_v3_scale(1.0 / rc_mass_rel(a->m, a->p, c.k), a->p);
        const rc_vec3 v1 = rc_v3_scale(1.0 / rc_mass_rel(b->m, b->p, c.k), b->p);
        rc_four qn = {0.0, nz};
        rc_boost_g(rc_v3_scale(-1.0, c.u), c.gu, c.k, &qn);
        out->t = 0.5 * (s0 + s1);
        out->x = rc_v3_scale(0.5, rc_v3_add(rc_v3_axpy(a->x, s0, v0), rc_v3_axpy(b->x, s1, v1)));
        out->n = rc_v3_scale(nf, qn.x);
        return RC_OK;
    }
    /* the event: midpoint of the two closest-approach events, boosted back */
    const rc_vec3 X0 = rc_v3_axpy(c.x0, ts, c.v0), X1 = rc_v3_axpy(c.x1, ts, c.v1);
    rc_four em = {T, rc_v3_scale(0.5, rc_v3_add(X0, X1))};
    rc_four qn = {0.0, nz};
    const rc_vec3 mu = rc_v3_scale(-1.0, c.u);
    if ((st = rc_boost(mu, c.k, &em)) != RC_OK || (st = rc_boost(mu, c.k, &qn)) != RC_OK)
        return st;
    /* both events lie on the worldlines after the given states, so their table times are
     * >= 0; the clamp only removes round-off */
    out->t = em.t > 0.0 ? em.t : 0.0;
    out->x = em.x;
    /* (0, nz) boosted has spatial norm^2 1 + gamma_u^2 (u.nz)^2 / c^2: normalised, the
     * four-vector is (u.n/c^2, n), the zmf law's q (as the zmf frame hands it over) */
    out->n = rc_v3_scale(nf, qn.x);
    return RC_OK;
}

const rc_toi_frame rc_toi_frame_transport = {
    .name = "transport",
    .summary = "transport codes' criterion: points, CM-frame closest approach with d_T < r0 + r1",
    .toi = transport_toi,
    .wall_contracted = 0,
    .contracted = 0,
    /* the decision, d_T and the event are computed in the pair's CM frame from invariant
     * worldlines: the same from every inertial frame */
    .covariant = 1,
    /* the closest approach comes after the bounding spheres touch only in the CM frame */
    .deferrable = 0,
    .shapes = NULL,
    .pointlike = 1,
};
