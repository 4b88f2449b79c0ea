/* engine/path.c — the entries of engine/path.h: the straight line of the field-free gas,
 * and one per coupling of a uniform field, built on relcol/gravity.h's kernels (the
 * field's axis and g from the definition, c from the engine, read at each call so that
 * rc_sim_set_c holds). */
#include <math.h>

#include "path.h"
#include "../gravity_private.h"
#include "relcol/status.h"

/* ---- the straight line ------------------------------------------------------------- */

static int line_drift(const rc_sim *s, double m, rc_vec3 *x, rc_vec3 *p, double dt, double *dtau)
{
    const double M = eng_mass_rel(m, *p, s->inv_c2);
    *x = rc_v3_axpy(*x, dt, rc_v3_scale(1.0 / M, *p));
    if (dtau)
        *dtau = s->inv_c2 == 0.0 ? dt : dt * (m / M);
    return RC_OK;
}

static int line_plane_time(const rc_sim *s, double m, rc_vec3 x, rc_vec3 p, int k, double X,
                           double *dt)
{
    const double v = rc_v3_get(p, k) / eng_mass_rel(m, p, s->inv_c2);
    const double t = (X - rc_v3_get(x, k)) / v;
    if (!(t > 0.0) || !isfinite(t))
        return RC_MISS;
    *dt = t;
    return RC_OK;
}

/* |dx + dv t| = d, the first time, from the relative line (also the classical pair of a
 * uniform field: both balls fall alike) */
static int relative_line_time(rc_vec3 dx, rc_vec3 dv, double d, double t_max, double *dt)
{
    const double b = rc_v3_dot(dx, dv), d2 = rc_v3_norm2(dx) - d * d, a = rc_v3_norm2(dv);
    if (d2 < -1e-12 * d * d)
        return RC_EOVERLAP;
    if (!(b < 0.0))
        return RC_MISS;
    if (d2 <= 1e-12 * d * d) {
        *dt = 0.0;
        return RC_OK;
    }
    const double disc = b * b - a * d2;
    if (!(disc > 0.0))
        return RC_MISS;
    const double t = d2 / (sqrt(disc) - b);
    if (!(t <= t_max))
        return RC_MISS;
    *dt = t;
    return RC_OK;
}

static int line_pair_time(const rc_sim *s, const rc_toi_ball *a, const rc_toi_ball *b,
                          double t_max, double *dt)
{
    const rc_vec3 va = rc_v3_scale(1.0 / eng_mass_rel(a->m, a->p, s->inv_c2), a->p);
    const rc_vec3 vb = rc_v3_scale(1.0 / eng_mass_rel(b->m, b->p, s->inv_c2), b->p);
    return relative_line_time(rc_v3_sub(b->x, a->x), rc_v3_sub(vb, va), a->r + b->r, t_max, dt);
}

static int line_energy(const rc_sim *s, double m, rc_vec3 x, rc_vec3 p, double *h)
{
    (void)x;
    *h = rc_kinetic_energy(m, p, s->inv_c2);
    return RC_OK;
}

static double no_weight(const rc_sim *s, double m, rc_vec3 p)
{
    (void)s, (void)m, (void)p;
    return 0.0;
}

const eng_path_ops eng_path_straight = {
    .name = "straight",
    .run = NULL, /* engine/core.c's loop, the line inlined in its lanes */
    .predict = eng_predict,
    .drift = line_drift,
    .plane_time = line_plane_time,
    .pair_time = line_pair_time,
    .energy = line_energy,
    .ball_at = NULL,
    .weight = no_weight,
};

/* ---- a uniform field ---------------------------------------------------------------- */

static rc_gravity field_of(const rc_sim *s)
{
    return (rc_gravity){s->def.g, s->fld_axis, s->inv_c2};
}

static int newton_drift(const rc_sim *s, double m, rc_vec3 *x, rc_vec3 *p, double dt, double *dtau)
{
    const rc_gravity f = field_of(s);
    /* (before p moves; not asked when a neighbour is brought to an instant for a pair) */
    const double flight = dtau ? rc_gravity_newton_flight_(&f, m, *p, dt) : 0.0;
    const int st = rc_gravity_newtonian.drift(&f, m, x, p, dt);
    if (st == RC_OK && dtau)
        *dtau = m * flight;
    return st;
}

static int equiv_drift(const rc_sim *s, double m, rc_vec3 *x, rc_vec3 *p, double dt, double *dtau)
{
    const rc_gravity f = field_of(s);
    /* proper time on the line in the box's frame at the start: t' m / M there */
    const double flight = dtau ? rc_gravity_equiv_flight_(&f, m, *x, *p, dt) : 0.0;
    const double M = dtau ? rc_mass_rel(m, *p, s->inv_c2) : 1.0;
    const int st = rc_gravity_equivalence.drift(&f, m, x, p, dt);
    if (st == RC_OK && dtau)
        *dtau = flight * (m / M);
    return st;
}

static int newton_plane_time(const rc_sim *s, double m, rc_vec3 x, rc_vec3 p, int k, double X,
                             double *dt)
{
    const rc_gravity f = field_of(s);
    return rc_gravity_newtonian.plane_time(&f, m, x, p, k, X, dt);
}

static int equiv_plane_time(const rc_sim *s, double m, rc_vec3 x, rc_vec3 p, int k, double X,
                            double *dt)
{
    const rc_gravity f = field_of(s);
    return rc_gravity_equivalence.plane_time(&f, m, x, p, k, X, dt);
}

static int newton_pair_time(const rc_sim *s, const rc_toi_ball *a, const rc_toi_ball *b,
                            double t_max, double *dt)
{
    if (s->inv_c2 == 0.0) /* (both fall alike: the relative motion is straight) */
        return line_pair_time(s, a, b, t_max, dt);
    const rc_gravity f = field_of(s);
    return rc_gravity_newtonian.pair_time(&f, a, b, t_max, dt);
}

static int equiv_pair_time(const rc_sim *s, const rc_toi_ball *a, const rc_toi_ball *b,
                           double t_max, double *dt)
{
    if (s->inv_c2 == 0.0) /* (classically the quartic is the field-free quadratic: section 3) */
        return line_pair_time(s, a, b, t_max, dt);
    const rc_gravity f = field_of(s);
    return rc_gravity_equivalence.pair_time(&f, a, b, t_max, dt);
}

static int newton_energy(const rc_sim *s, double m, rc_vec3 x, rc_vec3 p, double *h)
{
    const rc_gravity f = field_of(s);
    return rc_gravity_newtonian.energy(&f, m, x, p, h);
}

static int equiv_energy(const rc_sim *s, double m, rc_vec3 x, rc_vec3 p, double *h)
{
    const rc_gravity f = field_of(s);
    return rc_gravity_equivalence.energy(&f, m, x, p, h);
}

static double rest_weight(const rc_sim *s, double m, rc_vec3 p)
{
    (void)s, (void)p;
    return m;
}

static double energy_weight(const rc_sim *s, double m, rc_vec3 p)
{
    return eng_mass_rel(m, p, s->inv_c2);
}

/* readouts: the stored state taken along the path (a failure, which the loop would have
 * met first, leaves the stored state) */
static void field_ball_at(const rc_sim *s, size_t i, double h, rc_sim_ball *o)
{
    rc_vec3 x = s->b[i].x, p = s->a[i].p;
    double dtau = 0.0;
    if (s->path->drift(s, s->a[i].m, &x, &p, h, &dtau) == RC_OK) {
        o->x = x;
        o->p = p;
        o->tau += dtau;
    }
}

const eng_path_ops eng_path_newtonian = {
    .name = "newtonian",
    .run = eng_field_run,
    .predict = eng_field_predict,
    .drift = newton_drift,
    .plane_time = newton_plane_time,
    .pair_time = newton_pair_time,
    .energy = newton_energy,
    .ball_at = field_ball_at,
    .weight = rest_weight,
};

const eng_path_ops eng_path_equivalence = {
    .name = "equivalence",
    .run = eng_field_run,
    .predict = eng_field_predict,
    .drift = equiv_drift,
    .plane_time = equiv_plane_time,
    .pair_time = equiv_pair_time,
    .energy = equiv_energy,
    .ball_at = field_ball_at,
    .weight = energy_weight,
};

const eng_path_ops *eng_path_for(const rc_sim_def *def)
{
    if (!def->gravity)
        return &eng_path_straight;
    if (def->gravity == &rc_gravity_newtonian)
        return &eng_path_newtonian;
    if (def->gravity == &rc_gravity_equivalence)
        return &eng_path_equivalence;
    return NULL;
}
