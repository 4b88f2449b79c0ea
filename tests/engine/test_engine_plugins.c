/* test_engine_plugins.c — a contact frame and a collision law defined here, outside the
 * library, run through the engine (rc_sim_def.frame / .law) and through relcol-sim's
 * scenario reader (scn_parse_ext with this file's own tables), without touching the
 * library: the engine must really call them (counted), choose its paths from their
 * declared properties (group solver or none, direct solver, deferral), report their
 * failures, and keep the physics (conservation; the same bits as the built-in entries
 * whose rules they restate). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "engine_util.h"
#include "scenario.h"

/* ---- a law: the four-impulse rule of shared/DESIGN.md, written out here ------------- */

static long law_calls, group_calls, fail_after = -1;

static int four_impulse(const rc_collision_params *prm, rc_particle *a, rc_particle *b,
                        rc_vec3 n)
{
    law_calls++;
    if (fail_after >= 0 && law_calls > fail_after)
        return RC_EMASS; /* a law that gives up: the engine must say so */
    const double k = rc_inv_c2_of(prm->c), eps = prm->eps;
    const double M0 = sqrt(a->m * a->m + rc_v3_norm2(a->p) * k);
    const double M1 = sqrt(b->m * b->m + rc_v3_norm2(b->p) * k);
    const double Mt = M0 + M1;
    const double pn0 = rc_v3_dot(a->p, n), pn1 = rc_v3_dot(b->p, n);
    const double un = (pn0 + pn1) / Mt;
    const double a0 = (M1 * pn0 - M0 * pn1) / Mt; /* ZMF normal approach, > 0 approaching */
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

static int joint(const rc_collision_params *prm, size_t nballs, rc_particle *balls, size_t k,
                 const rc_contact *contacts, double *jout)
{
    group_calls++;
    return rc_contacts_resolve(rc_inv_c2_of(prm->c), nballs, balls, k, contacts, jout);
}

/* with a group solver (the library's joint solve) ... */
static const rc_law law_grouped = {
    .name = "test-four-impulse",
    .summary = "the zmf law restated in a test, with the joint group solve",
    .collide = four_impulse,
    .group = joint,
    .keeps_zmf_energy = 1,
};
/* ... and without one: groups resolved one contact at a time */
static const rc_law law_single = {
    .name = "test-four-impulse-single",
    .summary = "the zmf law restated in a test, no group solver",
    .collide = four_impulse,
    .keeps_zmf_energy = 1,
};

/* ---- a frame: contact of the table-frame shapes, from the public toi routines ------- */

static long frame_calls, shapes_calls;

static int table_shapes(const rc_toi_params *prm, const rc_toi_ball *a, const rc_toi_ball *b,
                        rc_toi_workspace *ws, rc_toi_contact *out)
{
    frame_calls++;
    const double k = rc_inv_c2_of(prm->c);
    const rc_vec3 v0 = rc_velocity(a->m, a->p, k), v1 = rc_velocity(b->m, b->p, k);
    const rc_toi_shape s0 = rc_toi_shape_of(a->r, a->m, a->p, k);
    const rc_toi_shape s1 = rc_toi_shape_of(b->r, b->m, b->p, k);
    double t;
    rc_vec3 y0, n;
    const int st = rc_toi_shapes_rel(&s0, &s1, rc_v3_sub(b->x, a->x), rc_v3_sub(v1, v0), prm,
                                     ws, &t, &y0, &n);
    if (st != RC_OK)
        return st;
    out->t = t;
    out->x = rc_v3_add(rc_v3_axpy(a->x, t, v0), y0);
    out->n = n;
    return RC_OK;
}

static int counted_shapes(const rc_toi_shape *s0, const rc_toi_shape *s1, rc_vec3 d, rc_vec3 w,
                          const rc_toi_params *prm, rc_toi_workspace *ws, double *t,
                          rc_vec3 *y0, rc_vec3 *n)
{
    shapes_calls++;
    return rc_toi_shapes_rel(s0, s1, d, w, prm, ws, t, y0, n);
}

/* Declares only what its kernel is: contracted, walls too; no deferral, no direct solver.
 * The engine must then ask it through toi for every narrow-phase pair. */
static const rc_toi_frame frame_plain = {
    .name = "test-table",
    .summary = "table-frame shapes, from the public routines, nothing else declared",
    .toi = table_shapes,
    .wall_contracted = 1,
    .contracted = 1,
};
/* The same contact declaring all it may: deferrable, and a direct solver (counted). */
static const rc_toi_frame frame_direct = {
    .name = "test-table-direct",
    .summary = "table-frame shapes with a declared direct solver and deferral",
    .toi = table_shapes,
    .wall_contracted = 1,
    .contracted = 1,
    .deferrable = 1,
    .shapes = counted_shapes,
};

/* ---- helpers ---------------------------------------------------------------------- */

/* A gas at finite c (rms 0.5 c) run to time t_end (not to a count of events: how many
 * queue entries a run pops depends on how events are predicted, e.g. deferred, while
 * the trajectory does not): final hash and diagnostics. */
static uint64_t run_gas(const rc_law *law, const rc_toi_frame *frame, int dim, double eps,
                        double t_end, rc_sim_diag *out, rc_sim_diag *start)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    d.c = 1.0;
    d.eps_ball = eps;
    d.law = law;
    d.frame = frame;
    rc_sim *s = util_gas(d, dim == 2 ? 300 : 400, 0.3, 0.5, 11);
    if (!s)
        return 0;
    rc_sim_diagnostics(s, start);
    const int st = rc_sim_advance(s, t_end, 0);
    ENSURE_MSG(st == RC_OK, "advance: %s", rc_strerror(st));
    rc_sim_diagnostics(s, out);
    const uint64_t h = rc_sim_hash(s);
    rc_sim_free(&s);
    return h;
}

/* about 1e4 collisions in run_gas's gases */
#define T_RUN(dim) ((dim) == 2 ? 80.0 : 16.0)

/* Energy (kinetic + heat, and sum of M at finite c) and momentum (with the walls')
 * conserved: round-off of the Kahan-compensated sums over a few thousand collisions is
 * ~1e-14 relative; a lost or doubled impulse would be O(1e-3). */
static void ensure_conserved(const rc_sim_diag *a, const rc_sim_diag *b)
{
    ENSURE_REL(b->energy, a->energy, 1e-12);
    if (isfinite(a->mass_rel))
        ENSURE_REL(b->mass_rel, a->mass_rel, 1e-12);
    const rc_vec3 pa = rc_v3_add(a->momentum, a->wall_impulse);
    const rc_vec3 pb = rc_v3_add(b->momentum, b->wall_impulse);
    ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(pa, pb)), 0.0, 1e-12, b->momentum_scale);
}

/* ---- the tests -------------------------------------------------------------------- */

/* The outside law with a group solver: called for every two-ball contact and for every
 * group, and the run is the built-in zmf law's bit for bit (the same rule, the same
 * expression order), contracted frames and inelastic contacts included. */
static void test_law_through_engine(void)
{
    for (int dim = 2; dim <= 3; dim++) {
        rc_sim_diag a0, a, b0, b;
        const uint64_t want = run_gas(&rc_law_zmf, &rc_toi_frame_table, dim, 0.8, T_RUN(dim), &a, &a0);
        law_calls = group_calls = 0;
        const uint64_t got = run_gas(&law_grouped, &rc_toi_frame_table, dim, 0.8, T_RUN(dim), &b, &b0);
        ENSURE_MSG(got == want, "dim %d: hash %016llx, zmf law %016llx", dim,
                   (unsigned long long)got, (unsigned long long)want);
        const uint64_t pairs = b.events[RC_SIM_EV_BALL];
        ENSURE_MSG(law_calls >= (long)pairs && pairs > 1000, "dim %d: %ld law calls, %llu pair "
                   "events", dim, law_calls, (unsigned long long)pairs);
        ENSURE(b.group_sequential == 0);
        /* every group went to the law's own solver (a failed joint solve is counted as a
         * fallback and resolved as a pair event) */
        ENSURE_MSG(group_calls == (long)(b.events[RC_SIM_EV_MULTI] + b.group_fallbacks),
                   "dim %d: %ld group calls, %llu groups", dim, group_calls,
                   (unsigned long long)b.events[RC_SIM_EV_MULTI]);
        ensure_conserved(&b0, &b);
        printf("  dim %d: %llu pair events, %llu groups; %ld law calls, %ld group calls\n", dim,
               (unsigned long long)pairs, (unsigned long long)b.events[RC_SIM_EV_MULTI],
               law_calls, group_calls);
    }
}

/* A billiard break (test_engine_contacts' rack): contacts propagate through the rack in
 * groups, each of which must go to the law's own group solver; the same bits as the zmf
 * law's run. */
static void test_law_groups_rack(void)
{
    rc_sim_ball b[16];
    int n = 0;
    b[n++] = (rc_sim_ball){rc_v3(5, 10, 0), rc_v3(5, 0, 0), 0.5, 0, 0, 0, 0, {0, 0, 0}};
    for (int row = 0; row < 5; row++)
        for (int k = 0; k <= row; k++)
            b[n++] = (rc_sim_ball){rc_v3(20 + row * sqrt(3.0) * 0.5, 10 + (k - row / 2.0), 0),
                                   rc_v3(0, 0, 0), 0.5, 0, 0, 0, 0, {0, 0, 0}};
    uint64_t h[2];
    for (int w = 0; w < 2; w++) {
        rc_sim_def d = rc_sim_def_default();
        d.dim = 2;
        d.box = rc_v3(40, 20, 0);
        d.eps_ball = 0.95;
        d.eps_wall = 0.8;
        d.law = w ? &law_grouped : &rc_law_zmf;
        rc_sim *s = NULL;
        ENSURE(rc_sim_create(&d, &s) == RC_OK);
        ENSURE(s && rc_sim_set_balls(s, (size_t)n, b, NULL) == RC_OK);
        group_calls = 0;
        ENSURE(s && rc_sim_advance(s, 3.5, 0) == RC_OK);
        rc_sim_diag dg;
        rc_sim_diagnostics(s, &dg);
        h[w] = rc_sim_hash(s);
        if (w) {
            ENSURE(dg.events[RC_SIM_EV_MULTI] > 0);
            ENSURE_MSG(group_calls == (long)(dg.events[RC_SIM_EV_MULTI] + dg.group_fallbacks),
                       "%ld group calls, %llu groups", group_calls,
                       (unsigned long long)dg.events[RC_SIM_EV_MULTI]);
        }
        rc_sim_free(&s);
    }
    ENSURE(h[0] == h[1]);
}

/* Three balls: 0 strikes 1 and 2 at +-30 degrees at once (test_engine_contacts' double
 * collision). With a group solver the law's own solver is called and the outcome is
 * symmetric; without one the engine resolves the two contacts one at a time, counts it,
 * conserves, and the outcome is no longer symmetric: the cost the counter reports. */
static void test_group_fallback(void)
{
    rc_sim_ball b[3] = {
        {rc_v3(4, 10, 0), rc_v3(1, 0, 0), 1, 0, 0, 0, 0, {0, 0, 0}},
        {rc_v3(5 + 2 * cos(M_PI / 6), 10 + 2 * sin(M_PI / 6), 0), rc_v3(0, 0, 0), 1, 0, 0, 0, 0, {0, 0, 0}},
        {rc_v3(5 + 2 * cos(M_PI / 6), 10 - 2 * sin(M_PI / 6), 0), rc_v3(0, 0, 0), 1, 0, 0, 0, 0, {0, 0, 0}},
    };
    for (int with = 0; with < 2; with++) {
        for (int rel = 0; rel < 2; rel++) {
            rc_sim_def d = rc_sim_def_default();
            d.dim = 2;
            d.box = rc_v3(20, 20, 0);
            d.eps_ball = 0.8;
            d.c = rel ? 3.0 : INFINITY;
            d.law = with ? &law_grouped : &law_single;
            rc_sim *s = NULL;
            ENSURE(rc_sim_create(&d, &s) == RC_OK);
            ENSURE(rc_sim_set_balls(s, 3, b, NULL) == RC_OK);
            rc_sim_diag d0, d1;
            rc_sim_diagnostics(s, &d0);
            law_calls = group_calls = 0;
            ENSURE(rc_sim_advance(s, 1.5, 0) == RC_OK);
            rc_sim_diagnostics(s, &d1);
            ENSURE(d1.events[RC_SIM_EV_MULTI] == 1);
            ENSURE(d1.collisions == 2);
            ensure_conserved(&d0, &d1);
            rc_sim_ball o;
            rc_sim_get_ball(s, 0, &o);
            if (with) {
                ENSURE(group_calls == 1);
                ENSURE(d1.group_sequential == 0);
                /* symmetric: only round-off of the +-30 degree positions (1e-15) */
                ENSURE_MSG(fabs(o.p.y) < 1e-12, "p_y %g", o.p.y);
            } else {
                ENSURE(group_calls == 0);
                ENSURE(d1.group_sequential == 1);
                ENSURE_MSG(law_calls >= 2, "%ld law calls", law_calls);
                /* one contact first: ball 0 leaves off the axis (O(0.1) at eps = 0.8) */
                ENSURE_MSG(fabs(o.p.y) > 1e-3, "p_y %g", o.p.y);
            }
            rc_sim_free(&s);
        }
    }
}

/* A law that fails: rc_sim_advance returns its code (it is not ignored), and the balls of
 * the failed event keep their states (energy and momentum as before it). */
static void test_law_failure(void)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.c = 2.0;
    d.law = &law_single;
    d.frame = &rc_toi_frame_zmf;
    rc_sim *s = util_gas(d, 200, 0.3, 0.5, 5);
    if (!s)
        return;
    rc_sim_diag d0, d1;
    rc_sim_diagnostics(s, &d0);
    law_calls = 0;
    fail_after = 50;
    int st = RC_OK;
    for (int k = 0; k < 100000 && st == RC_OK; k++)
        st = rc_sim_advance(s, INFINITY, 100);
    fail_after = -1;
    ENSURE_MSG(st == RC_EMASS, "advance: %s", rc_strerror(st));
    ENSURE(law_calls == 51);
    rc_sim_diagnostics(s, &d1);
    ENSURE(d1.collisions > 0);
    ensure_conserved(&d0, &d1);
    rc_sim_free(&s);
}

/* The outside frame: declaring nothing but its kernel, the engine asks it (counted) and
 * the run is the built-in table frame's bit for bit (deferral and the direct solver give
 * the same bits, test_engine_defer); declaring the direct solver, the engine calls that
 * instead, not toi. Walls see its contracted shapes (wall_contracted). */
static void test_frame_through_engine(void)
{
    for (int dim = 2; dim <= 3; dim++) {
        rc_sim_diag a0, a, b0, b, c0, c;
        const uint64_t want = run_gas(&rc_law_zmf, &rc_toi_frame_table, dim, 1.0, T_RUN(dim), &a, &a0);
        frame_calls = shapes_calls = 0;
        const uint64_t plain = run_gas(&rc_law_zmf, &frame_plain, dim, 1.0, T_RUN(dim), &b, &b0);
        ENSURE_MSG(plain == want, "dim %d: hash %016llx, table frame %016llx", dim,
                   (unsigned long long)plain, (unsigned long long)want);
        ENSURE_MSG(frame_calls > 1000 && shapes_calls == 0, "dim %d: %ld toi, %ld direct", dim,
                   frame_calls, shapes_calls);
        ensure_conserved(&b0, &b);
        frame_calls = shapes_calls = 0;
        const uint64_t direct = run_gas(&rc_law_zmf, &frame_direct, dim, 1.0, T_RUN(dim), &c, &c0);
        ENSURE(direct == want);
        ENSURE_MSG(shapes_calls > 1000, "dim %d: %ld direct calls", dim, shapes_calls);
        ensure_conserved(&c0, &c);
    }
    /* a frame declaring itself uncontracted is never asked: the engine's sphere kernel */
    rc_toi_frame sphere_like = frame_plain;
    sphere_like.contracted = 0;
    sphere_like.wall_contracted = 0;
    rc_sim_diag a0, a, b0, b;
    const uint64_t want = run_gas(&rc_law_zmf, &rc_toi_frame_sphere, 2, 1.0, 40.0, &a, &a0);
    frame_calls = 0;
    ENSURE(run_gas(&rc_law_zmf, &sphere_like, 2, 1.0, 40.0, &b, &b0) == want);
    ENSURE(frame_calls == 0);
}

/* relcol-sim's scenario reader takes the test's tables: the names resolve to these
 * entries (and only with the tables), a run made from the scenario as relcol-sim makes
 * it calls them, and the scenario writes back and reads again. */
static void test_scenario_reader(void)
{
    static const rc_law *const laws[] = {&law_single, &law_grouped, NULL};
    static const rc_toi_frame *const frames[] = {&frame_plain, &frame_direct, NULL};
    const scn_tables extra = {laws, frames};
    const char *text =
        "{\"relcol\": 1, \"dim\": 2, \"c\": 2, \"law\": \"test-four-impulse-single\",\n"
        " \"contact_frame\": \"test-table\", \"restitution\": {\"ball\": 0.9, \"wall\": 1},\n"
        " \"t_end\": 10, \"generate\": {\"kind\": \"gas\", \"n\": 200, \"radius\": 1,\n"
        " \"packing\": 0.3, \"v_rms\": 0.5}}\n";
    scn_scenario sc;
    char err[APP_ERR_LEN];
    /* without the tables the names are unknown, and the message lists the known ones */
    ENSURE(scn_parse(text, "plugins", &sc, err) != 0);
    ENSURE_MSG(strstr(err, "unknown collision law") && strstr(err, "zmf"), "%s", err);
    if (scn_parse_ext(text, "plugins", &extra, &sc, err) != 0) {
        ENSURE_MSG(0, "%s", err);
        return;
    }
    ENSURE(sc.law == &law_single);
    ENSURE(sc.frame == &frame_plain);
    /* built-in names still resolve to the library's entries with the tables given */
    scn_scenario sb;
    char *t2 = strdup(text);
    char *p = strstr(t2, "test-four-impulse-single");
    memcpy(p, "zmf\"", 4);
    memmove(p + 4, p + strlen("test-four-impulse-single\""),
            strlen(p + strlen("test-four-impulse-single\"")) + 1);
    ENSURE(scn_parse_ext(t2, "plugins", &extra, &sb, err) == 0);
    ENSURE(sb.law == &rc_law_zmf);
    scn_free(&sb);
    free(t2);

    /* the run, as relcol-sim sets it up */
    rc_sim_def d = scn_sim_def(&sc);
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    ENSURE(s && rc_sim_set_time(s, sc.time) == RC_OK);
    ENSURE(s && rc_sim_set_balls(s, sc.n, sc.balls, NULL) == RC_OK);
    law_calls = frame_calls = 0;
    rc_sim_diag d0, d1;
    if (s) {
        rc_sim_diagnostics(s, &d0);
        ENSURE(rc_sim_advance(s, sc.t_end, 0) == RC_OK);
        rc_sim_diagnostics(s, &d1);
        ENSURE_MSG(law_calls > 100 && frame_calls > 100, "%ld law, %ld frame calls", law_calls,
                   frame_calls);
        ENSURE(d1.collisions > 100);
        ensure_conserved(&d0, &d1);
    }
    /* written back (a final state) and read again with the same tables */
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    ENSURE(f && scn_write(f, &sc, sc.time, sc.t_end, sc.n, sc.balls) == 0);
    if (f)
        fclose(f);
    scn_scenario back;
    ENSURE(buf && scn_parse_ext(buf, "written", &extra, &back, err) == 0);
    if (buf) {
        ENSURE(back.law == &law_single && back.frame == &frame_plain);
        scn_free(&back);
    }
    free(buf);
    rc_sim_free(&s);
    scn_free(&sc);
}

int main(void)
{
    RUN_TEST(test_law_through_engine);
    RUN_TEST(test_law_groups_rack);
    RUN_TEST(test_group_fallback);
    RUN_TEST(test_law_failure);
    RUN_TEST(test_frame_through_engine);
    RUN_TEST(test_scenario_reader);
    RC_TEST_MAIN_END();
}
