/* observables.c — relcol-sweep's scenarios: the collision law, the contracted time of
 * impact, the soft-sphere reference and a small engine run, each reduced to a few numbers
 * whose deviation from c = inf the sweep measures. */
#include <math.h>
#include <string.h>

#include "app.h"
#include "observables.h"

sweep_setup sweep_setup_default(void)
{
    /* An oblique 2-D collision with unequal masses, speeds ~1: ball 0 hits ball 1 at an
     * impact parameter of ~0.45 diameters (sphere geometry) after ~2.4 time units. */
    sweep_setup s = {{1.0, 2.0}, {1.0, 1.0},
                     {{0, 0, 0}, {4.0, 0.9, 0}},
                     {{0.9, 0.1, 0}, {-0.3, 0.0, 0}},
                     0.8, 1e8};
    return s;
}

static int particles(const sweep_setup *s, double k, rc_particle b[2], char *err)
{
    for (int i = 0; i < 2; i++) {
        b[i].m = s->m[i];
        if (rc_momentum_from_velocity(s->m[i], s->v[i], k, &b[i].p) != RC_OK) {
            app_errf(err, "ball %d: |v| = %g >= c = %g", i, rc_v3_norm(s->v[i]), 1 / sqrt(k));
            return -1;
        }
    }
    return 0;
}

/* Classical (sphere) contact normal: the collision-law scenario isolates the law. */
static int sphere_normal(const sweep_setup *s, rc_vec3 *n, char *err)
{
    rc_toi_params tp = rc_toi_params_default();
    double t;
    int st = rc_toi_sphere_rel(s->r[0] + s->r[1], rc_v3_sub(s->x[1], s->x[0]),
                               rc_v3_sub(s->v[1], s->v[0]), &tp, &t, n);
    if (st != RC_OK) {
        app_errf(err, "the balls do not meet: %s", rc_strerror(st));
        return -1;
    }
    return 0;
}

static int eval_collide(const sweep_setup *s, double c, double *out, char *err)
{
    const double k = rc_inv_c2_of(c);
    rc_particle b[2], a[2];
    rc_vec3 n;
    if (particles(s, k, b, err) || sphere_normal(s, &n, err))
        return -1;
    a[0] = b[0];
    a[1] = b[1];
    rc_collision_params prm = rc_collision_params_default();
    prm.c = c;
    prm.eps = s->eps;
    int st = rc_collide(&rc_law_zmf, &prm, &a[0], &a[1], n);
    if (st != RC_OK) {
        app_errf(err, "collision: %s", rc_strerror(st));
        return -1;
    }
    for (int i = 0; i < 2; i++) {
        rc_vec3 v = rc_velocity(a[i].m, a[i].p, k);
        out[2 * i] = v.x;
        out[2 * i + 1] = v.y;
    }
    out[4] = rc_pair_heat(b, a, k, NULL); /* zmf keeps ZMF energies */
    return 0;
}

static int eval_toi(const sweep_setup *s, double c, double *out, char *err)
{
    const double k = rc_inv_c2_of(c);
    rc_particle b[2];
    if (particles(s, k, b, err))
        return -1;
    rc_toi_ball tb[2];
    for (int i = 0; i < 2; i++) {
        tb[i].x = s->x[i];
        tb[i].r = s->r[i];
        tb[i].m = b[i].m;
        tb[i].p = b[i].p;
    }
    rc_toi_params prm = rc_toi_params_default();
    prm.c = c;
    rc_toi_workspace *ws = NULL;
    if (rc_toi_workspace_create(&ws) != RC_OK) {
        app_errf(err, "out of memory");
        return -1;
    }
    rc_toi_contact con;
    int st = rc_toi(&rc_toi_frame_table, &prm, &tb[0], &tb[1], ws, &con);
    rc_toi_workspace_free(&ws);
    if (st != RC_OK) {
        app_errf(err, "time of impact: %s", rc_strerror(st));
        return -1;
    }
    out[0] = con.t;
    out[1] = con.n.x;
    out[2] = con.n.y;
    return 0;
}

static int eval_soft(const sweep_setup *s, double c, double *out, char *err)
{
    const double k = rc_inv_c2_of(c);
    rc_particle b[2], a[2];
    if (particles(s, k, b, err))
        return -1;
    a[0] = b[0];
    a[1] = b[1];
    rc_vec3 x[2] = {s->x[0], s->x[1]};
    rc_soft_params prm = rc_soft_params_default();
    prm.c = c;
    prm.stiffness = s->stiffness;
    prm.eps = s->eps;
    prm.rtol = 1e-11;
    double u[2];
    rc_soft_result res;
    int st = rc_soft_collide(&rc_soft_cvode_bdf, &prm, 2, a, x, s->r, u, &res);
    if (st != RC_OK) {
        app_errf(err, "soft collision: %s", rc_strerror(st));
        return -1;
    }
    for (int i = 0; i < 2; i++) {
        rc_vec3 v = rc_velocity(a[i].m, a[i].p, k);
        out[2 * i] = v.x;
        out[2 * i + 1] = v.y;
    }
    out[4] = u[0] + u[1];
    return 0;
}

/* A small engine run: four balls in a 2-D box (walls elastic, balls with the set-up's
 * restitution), contact frame "table" (Lorentz-contracted shapes), run to t = 14: a few
 * ball-ball and wall collisions, well separated in time so that no event changes order
 * over the grid (the deviation is then smooth in 1/c^2). Observables: the positions at
 * the end and the heat made. */
static int eval_engine(const sweep_setup *s, double c, double *out, char *err)
{
    const double k = rc_inv_c2_of(c);
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.box = rc_v3(16, 10, 0);
    d.c = c;
    d.eps_ball = s->eps;
    d.eps_wall = 1.0;
    d.frame = &rc_toi_frame_table;
    const double vx[4] = {0.9, -0.5, 0.2, -0.3}, vy[4] = {0.15, 0.1, -0.6, 0.35};
    const double x0[4] = {2.0, 9.0, 6.0, 13.0}, y0[4] = {3.0, 3.6, 8.0, 6.5};
    rc_sim_ball b[4];
    memset(b, 0, sizeof b);
    for (int i = 0; i < 4; i++) {
        b[i].x = rc_v3(x0[i], y0[i], 0);
        b[i].r = 1.0;
        b[i].m = 1.0 + 0.5 * i;
        if (rc_momentum_from_velocity(b[i].m, rc_v3(vx[i], vy[i], 0), k, &b[i].p) != RC_OK) {
            app_errf(err, "engine ball %d: |v| >= c", i);
            return -1;
        }
    }
    rc_sim *sim = NULL;
    int st = rc_sim_create(&d, &sim);
    if (st == RC_OK)
        st = rc_sim_set_balls(sim, 4, b, NULL);
    if (st == RC_OK)
        st = rc_sim_advance(sim, 14.0, 0);
    rc_sim_diag dg;
    if (st == RC_OK)
        st = rc_sim_diagnostics(sim, &dg);
    for (int i = 0; st == RC_OK && i < 4; i++) {
        rc_sim_ball o;
        st = rc_sim_get_ball(sim, (size_t)i, &o);
        out[2 * i] = o.x.x;
        out[2 * i + 1] = o.x.y;
    }
    if (st == RC_OK)
        out[8] = dg.heat;
    app_validity_note(sim);
    rc_sim_free(&sim);
    if (st != RC_OK) {
        app_errf(err, "engine run: %s", rc_strerror(st));
        return -1;
    }
    return 0;
}

static const sweep_scenario sc_collide = {
    "collide", "zmf law at the classical contact normal: final velocities and heat",
    5, {"v0x", "v0y", "v1x", "v1y", "heat"}, eval_collide,
    2, {"velocities", "heat"}, {0, 0, 0, 0, 1},
    1e-13, /* closed form: a few hundred ulps */
};
static const sweep_scenario sc_toi = {
    "toi", "contracted time of impact (table frame): time and contact normal",
    3, {"t", "nx", "ny"}, eval_toi,
    2, {"time", "normal"}, {0, 1, 1},
    1e-13, /* root found to lambda_tol = 1e-14 in a stationary variable */
};
static const sweep_scenario sc_soft = {
    "soft", "soft-sphere reference (CVODE) at stiffness K: final velocities and heat",
    5, {"v0x", "v0y", "v1x", "v1y", "heat"}, eval_soft,
    2, {"velocities", "heat"}, {0, 0, 0, 0, 1},
    /* CVODE at rtol 1e-11 leaves ~1e-10 to 3e-9 of noise in the outcome (measured at
     * c > 3e4 |v|, where the physics deviation is smaller): fit only well above it */
    1e-7,
};

static const sweep_scenario sc_engine = {
    "engine", "4-ball engine run, contracted table-frame shapes: final positions and heat",
    9, {"x0", "y0", "x1", "y1", "x2", "y2", "x3", "y3", "heat"}, eval_engine,
    2, {"positions", "heat"}, {0, 0, 0, 0, 0, 0, 0, 0, 1},
    1e-12, /* exact event times; positions O(10) carry round-off of a few ulps per event */
};

const sweep_scenario *const sweep_scenarios[] = {&sc_collide, &sc_toi, &sc_soft, &sc_engine, NULL};

const sweep_scenario *sweep_scenario_find(const char *name)
{
    for (size_t i = 0; sweep_scenarios[i]; i++)
        if (strcmp(sweep_scenarios[i]->name, name) == 0)
            return sweep_scenarios[i];
    return NULL;
}
