/* toi_frames.c — the table of contact frames, the "table" and "sphere" frames, default
 * parameters and the validating entry point rc_toi(). A built-in frame: its entry with
 * its declared properties (relcol/toi.h) and one line in rc_toi_frames[] (the zmf frame
 * lives in toi_zmf.c). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "relcol/status.h"
#include "relcol/toi.h"
#include "toi_private.h"

rc_toi_params rc_toi_params_default(void)
{
    rc_toi_params p;
    p.c = INFINITY;
    p.touch_tol = 1e-12;
    p.graze_tol = 1e-9;
    p.lambda_tol = 1e-14;
    p.max_iter = 100;
    return p;
}

/* Contact found between the table-frame shapes, each contracted along its own v. */
static int table_toi(const rc_toi_params *prm, const rc_toi_ball *a, const rc_toi_ball *b,
                     rc_toi_workspace *ws, rc_toi_contact *out)
{
    const double k = rc_inv_c2_of(prm->c);
    const double M0 = rc_mass_rel(a->m, a->p, k), M1 = rc_mass_rel(b->m, b->p, k);
    /* v = p/M exactly as rc_velocity computes it (the frames compare with ==) */
    const rc_vec3 v0 = rc_v3_scale(1.0 / M0, a->p), v1 = rc_v3_scale(1.0 / M1, b->p);
    const rc_toi_shape s0 = rc_toi_shape_M_(a->r, a->m, a->p, k, M0);
    const rc_toi_shape s1 = rc_toi_shape_M_(b->r, b->m, b->p, k, M1);
    double t;
    rc_vec3 y0, n;
    int st = rc_toi_shapes_rel(&s0, &s1, rc_v3_sub(b->x, a->x), rc_v3_sub(v1, v0), prm,
                               ws, &t, &y0, &n);
    if (st != RC_OK)
        return st;
    out->t = t;
    out->x = rc_toi_point_(a->x, v0, t, y0);
    out->n = n;
    return RC_OK;
}

/* The naive model: uncontracted spheres of radius r moving at v. */
static int sphere_toi(const rc_toi_params *prm, const rc_toi_ball *a, const rc_toi_ball *b,
                      rc_toi_workspace *ws, rc_toi_contact *out)
{
    (void)ws;
    const double k = rc_inv_c2_of(prm->c);
    const rc_vec3 v0 = rc_velocity(a->m, a->p, k), v1 = rc_velocity(b->m, b->p, k);
    double t;
    rc_vec3 n;
    int st = rc_toi_sphere_rel(a->r + b->r, rc_v3_sub(b->x, a->x), rc_v3_sub(v1, v0), prm,
                               &t, &n);
    if (st != RC_OK)
        return st;
    out->t = t;
    out->x = rc_toi_point_(a->x, v0, t, rc_v3_scale(a->r, n));
    out->n = n;
    return RC_OK;
}

const rc_toi_frame rc_toi_frame_table = {
    .name = "table",
    .summary = "contact of the shapes contracted along their table-frame velocities",
    .toi = table_toi,
    .wall_contracted = 1,
    .contracted = 1,
    .covariant = 0,
    .deferrable = 1,
    .shapes = rc_toi_shapes_rel,
};
const rc_toi_frame rc_toi_frame_sphere = {
    .name = "sphere",
    .summary = "contraction ignored: uncontracted spheres (the naive model)",
    .toi = sphere_toi,
    .wall_contracted = 0,
    .contracted = 0,
    .covariant = 0,
    .deferrable = 0, /* (never asked: the engine's own sphere kernel decides) */
    .shapes = NULL,
};

const rc_toi_frame *const rc_toi_frames[] = {
    &rc_toi_frame_table,
    &rc_toi_frame_zmf,
    &rc_toi_frame_sphere,
    &rc_toi_frame_transport,
    &rc_toi_frame_covariant,
    NULL,
};

const rc_toi_frame *rc_toi_frame_find(const char *name)
{
    if (!name)
        return NULL;
    for (size_t i = 0; rc_toi_frames[i]; i++)
        if (strcmp(rc_toi_frames[i]->name, name) == 0)
            return rc_toi_frames[i];
    return NULL;
}

static int check_ball(const rc_toi_ball *a)
{
    if (!rc_v3_isfinite(a->x) || !isfinite(a->r))
        return RC_ENONFINITE;
    if (!(a->r > 0.0))
        return RC_ERADIUS;
    rc_particle b = {a->m, a->p};
    return rc_particle_check(&b);
}

/* Whether the doubles of the centres' positions, at time 0 and at t, are finer than a
 * thousandth of the smaller radius: beyond, the contact's geometry is rounding (a 1-D pair
 * 1e17 radii apart meets at a point where both centres are the same double). A choice:
 * it refuses boxes wider than ~4.5e12 radii, which no gas of the engine comes near. */
static int resolvable(const rc_toi_ball *a, const rc_toi_ball *b, double k, double t)
{
    double s = fmax(rc_v3_norm(a->x), rc_v3_norm(b->x));
    if (t != 0.0) {
        rc_vec3 xa = rc_v3_add(a->x, rc_v3_scale(t, rc_velocity(a->m, a->p, k)));
        rc_vec3 xb = rc_v3_add(b->x, rc_v3_scale(t, rc_velocity(b->m, b->p, k)));
        s = fmax(s, fmax(rc_v3_norm(xa), rc_v3_norm(xb)));
    }
    return DBL_EPSILON * s <= 1e-3 * fmin(a->r, b->r);
}

int rc_toi(const rc_toi_frame *frame, const rc_toi_params *prm, const rc_toi_ball *a,
           const rc_toi_ball *b, rc_toi_workspace *ws, rc_toi_contact *out)
{
    if (!frame || !prm || !a || !b || !out || !ws)
        return RC_EINVAL;
    double k;
    if (rc_inv_c2(prm->c, &k) != RC_OK)
        return RC_ESPEEDOFLIGHT;
    if (!(prm->touch_tol >= 0.0 && prm->touch_tol < 1.0) || !(prm->graze_tol >= 0.0) ||
        !(prm->lambda_tol > 0.0) || prm->max_iter < 1)
        return RC_EINVAL;
    int st;
    if ((st = check_ball(a)) != RC_OK || (st = check_ball(b)) != RC_OK)
        return st;
    if (!resolvable(a, b, k, 0.0))
        return RC_ESCALE;
    if ((st = frame->toi(prm, a, b, ws, out)) != RC_OK)
        return st;
    const double nn = rc_v3_dot(out->n, out->n);
    if (!isfinite(out->t) || !rc_v3_isfinite(out->x) || !(fabs(nn - 1.0) < 1e-6) ||
        !resolvable(a, b, k, out->t))
        return RC_ESCALE;
    return RC_OK;
}
