/* test_engine_gsl_handler.c — the library never reaches GSL's error handler: with a handler
 * installed that aborts the test, bad and extreme inputs go through the engine (groups of
 * simultaneous contacts, the only engine path that calls GSL), the contact solver itself,
 * the laws, time of impact and the soft reference (both GSL steppers), and every call must
 * come back with a status code. The handler is first shown to catch a GSL error, so the
 * test can fail; and (builds without sanitizers) malloc is made to fail at each call in
 * turn of a group's solve, where GSL's own allocator used to call the handler. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_permutation.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "rc_test.h"
#include "relcol/relcol.h"

static int handler_calls;

#ifdef RC_TEST_MALLOC_FAULTS
/* malloc, calloc and realloc fail at call number fail_at (counted from arming; -1: never),
 * for every library in the process: GSL's allocators included. */
extern void *__libc_malloc(size_t);
extern void *__libc_calloc(size_t, size_t);
extern void *__libc_realloc(void *, size_t);
static long fail_at = -1, n_calls;

static int fail_now(void) { return fail_at >= 0 && n_calls++ == fail_at; }
void *malloc(size_t n) { return fail_now() ? NULL : __libc_malloc(n); }
void *calloc(size_t n, size_t m) { return fail_now() ? NULL : __libc_calloc(n, m); }
void *realloc(void *p, size_t n) { return fail_now() ? NULL : __libc_realloc(p, n); }

/* A group of two contacts on one ball (relativistic: Newton, then the rest masses)
 * solved with the allocation number k failing, for every k until a run allocates no more
 * than k times: RC_ENOMEM or RC_OK, never the handler. */
static void test_contacts_out_of_memory(void)
{
    const rc_contact c[2] = {{0, 1, {1, 0, 0}, 0.5, 0.0, {0, 0, 0}},
                             {1, 2, {0, 1, 0}, 0.5, 0.0, {0, 0, 0}}};
    int nomem = 0;
    for (long k = 0;; k++) {
        rc_particle b[3] = {{1.0, rc_v3(1, 0, 0)}, {1.0, rc_v3(0, 0, 0)},
                            {1.0, rc_v3(0, -1, 0)}};
        n_calls = 0;
        fail_at = k;
        const int st = rc_contacts_resolve(0.25, 3, b, 2, c, NULL);
        const long used = n_calls;
        fail_at = -1;
        ENSURE_MSG(st == RC_OK || st == RC_ENOMEM, "allocation %ld failing: %d", k, st);
        nomem += st == RC_ENOMEM;
        if (used <= k)
            break;
    }
    ENSURE_MSG(nomem >= 10, "only %d allocations failed", nomem);
}

/* The engine through a billiard break (groups of contacts) with the allocation number k
 * failing, for k up to the number of allocations of a whole run. */
static void test_engine_out_of_memory(void)
{
    int nomem = 0;
    for (long k = 0;; k++) {
        rc_sim_def d = rc_sim_def_default();
        d.dim = 2;
        d.box = rc_v3(40, 20, 0);
        d.c = 8.0;
        d.eps_ball = 0.9;
        rc_sim_ball b[16];
        int n = 0;
        b[n++] = (rc_sim_ball){rc_v3(5, 10, 0), rc_v3(5, 0, 0), 0.5, 1.0, 0, 0, 0, {0, 0, 0}};
        for (int row = 0; row < 5; row++)
            for (int j = 0; j <= row; j++)
                b[n++] = (rc_sim_ball){rc_v3(20 + row * sqrt(3.0) * 0.5, 10 + (j - row / 2.0), 0),
                                       rc_v3(0, 0, 0), 0.5, 1.0, 0, 0, 0, {0, 0, 0}};
        n_calls = 0;
        fail_at = k;
        rc_sim *s = NULL;
        int st = rc_sim_create(&d, &s);
        if (st == RC_OK)
            st = rc_sim_set_balls(s, (size_t)n, b, NULL);
        if (st == RC_OK)
            st = rc_sim_advance(s, 4.0, 100000);
        const long used = n_calls;
        fail_at = -1;
        rc_sim_free(&s);
        ENSURE_MSG(st == RC_OK || st == RC_ENOMEM, "allocation %ld failing: %d", k, st);
        nomem += st == RC_ENOMEM;
        if (used <= k)
            break;
    }
    ENSURE_MSG(nomem >= 3, "only %d allocations failed", nomem);
}
#endif

static void recording_handler(const char *reason, const char *file, int line, int gsl_errno)
{
    (void)reason, (void)file, (void)line, (void)gsl_errno;
    handler_calls++;
}

/* the library reached GSL's handler: the test fails here, naming the call */
static void aborting_handler(const char *reason, const char *file, int line, int gsl_errno)
{
    fprintf(stderr, "GSL error handler reached: %s (%s:%d, code %d)\n", reason, file, line,
            gsl_errno);
    abort();
}

/* The handler sees GSL's errors: a zero-length permutation is one. */
static void test_handler_catches(void)
{
    handler_calls = 0;
    gsl_set_error_handler(recording_handler);
    gsl_permutation *p = gsl_permutation_alloc(0);
    ENSURE(p == NULL);
    ENSURE(handler_calls == 1);
    gsl_set_error_handler(aborting_handler);
}

/* The contact solver on dependent normals (a singular system) and extreme c. */
static void test_contacts_bad(void)
{
    rc_particle b[3] = {{1.0, rc_v3(1, 0, 0)}, {1.0, rc_v3(0, 0, 0)}, {1.0, rc_v3(-1, 0, 0)}};
    const rc_contact twice[2] = {{0, 1, {1, 0, 0}, 1.0, 0.0, {0, 0, 0}},
                                 {0, 1, {1, 0, 0}, 1.0, 0.0, {0, 0, 0}}};
    const double inv_c2s[] = {0.0, 1.0, 1e300, 1e-300};
    for (int i = 0; i < 4; i++) {
        rc_particle q[3] = {b[0], b[1], b[2]};
        const int st = rc_contacts_resolve(inv_c2s[i], 3, q, 2, twice, NULL);
        ENSURE_MSG(st != RC_OK || isfinite(q[0].p.x), "singular group: %d", st);
    }
    /* a wall and a ball contact along one normal: dependent too */
    const rc_contact wall_ball[2] = {{1, -1, {1, 0, 0}, 0.0, 0.0, {0, 0, 0}},
                                     {0, 1, {1, 0, 0}, 0.0, 0.0, {0, 0, 0}}};
    rc_particle q[3] = {b[0], b[1], b[2]};
    (void)rc_contacts_resolve(1.0, 3, q, 2, wall_ball, NULL);
    /* a chain at nearly c: momenta of 1e150 (gamma ~ 1e150) */
    rc_particle fast[3] = {{1.0, rc_v3(1e150, 0, 0)}, {1.0, rc_v3(0, 0, 0)},
                           {1.0, rc_v3(-1e150, 0, 0)}};
    const rc_contact chain[2] = {{0, 1, {1, 0, 0}, 0.5, 0.0, {0, 0, 0}},
                                 {1, 2, {1, 0, 0}, 0.5, 0.0, {0, 0, 0}}};
    (void)rc_contacts_resolve(1.0, 3, fast, 2, chain, NULL);
    /* four copies of one contact: a 4 x 4 singular system */
    const rc_contact four[4] = {twice[0], twice[0], twice[0], twice[0]};
    rc_particle r[3] = {b[0], b[1], b[2]};
    ENSURE(rc_contacts_resolve(0.0, 3, r, 4, four, NULL) != RC_OK);
}

/* A Newton's cradle and a billiard rack: groups of simultaneous contacts, resolved with
 * GSL's LU, at every frame, at c = inf and c close to the speeds, eps 0 and 1. */
static void test_engine_groups(void)
{
    const double cs[] = {INFINITY, 3.0, 1.02};
    const double epss[] = {1.0, 0.0};
    uint64_t groups = 0;
    for (int ic = 0; ic < 3; ic++)
        for (int ie = 0; ie < 2; ie++)
            for (int f = 0; rc_toi_frames[f]; f++) {
                rc_sim_def d = rc_sim_def_default();
                d.dim = 2;
                d.box = rc_v3(40, 20, 0);
                d.c = cs[ic];
                d.eps_ball = epss[ie];
                d.eps_wall = epss[ie];
                d.t_c = ie ? 1e-6 : 0.0;
                d.frame = rc_toi_frames[f];
                rc_sim *s = NULL;
                ENSURE(rc_sim_create(&d, &s) == RC_OK);
                if (!s)
                    continue;
                rc_sim_ball b[16];
                int n = 0;
                const double v = isinf(d.c) ? 5.0 : 0.99 * d.c;
                b[n++] = (rc_sim_ball){rc_v3(5, 10, 0), rc_v3(v, 0, 0), 0.5, 1.0, 0, 0, 0, {0, 0, 0}};
                for (int row = 0; row < 5; row++)
                    for (int k = 0; k <= row; k++)
                        b[n++] = (rc_sim_ball){
                            rc_v3(20 + row * sqrt(3.0) * 0.5, 10 + (k - row / 2.0), 0),
                            rc_v3(0, 0, 0), 0.5, 1.0, 0, 0, 0, {0, 0, 0}};
                /* momentum for the speed v: p = m v gamma */
                if (!isinf(d.c))
                    b[0].p.x = v / sqrt(1.0 - v * v / (d.c * d.c));
                const int st = rc_sim_set_balls(s, (size_t)n, b, NULL);
                if (st == RC_OK) {
                    (void)rc_sim_advance(s, 20.0, 20000);
                    rc_sim_diag dg;
                    rc_sim_diagnostics(s, &dg);
                    groups += dg.events[RC_SIM_EV_MULTI];
                }
                rc_sim_free(&s);
            }
    ENSURE_MSG(groups > 0, "no group was resolved: GSL's solver was not exercised");
    printf("  %llu groups resolved\n", (unsigned long long)groups);
}

/* Definitions and balls the engine must reject with a code. */
static void test_engine_bad_input(void)
{
    rc_sim_def d = rc_sim_def_default();
    d.c = NAN;
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) != RC_OK);
    /* one speed of light: the contact solver's copy is the engine's (NAN) or equal */
    d = rc_sim_def_default();
    d.c = 2.0;
    d.frame = &rc_toi_frame_table;
    ENSURE(isnan(d.toi.c));
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    rc_sim_free(&s);
    d.toi.c = 2.0;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    rc_sim_free(&s);
    d.toi.c = 3.0;
    ENSURE(rc_sim_create(&d, &s) == RC_EINVAL);
    d.toi.c = INFINITY;
    ENSURE(rc_sim_create(&d, &s) == RC_EINVAL);
    ENSURE(s == NULL);
    d = rc_sim_def_default();
    d.dim = 7;
    ENSURE(rc_sim_create(&d, &s) != RC_OK);
    d = rc_sim_def_default();
    d.eps_ball = -1.0;
    ENSURE(rc_sim_create(&d, &s) != RC_OK);
    d = rc_sim_def_default();
    d.box = rc_v3(1e308, 1e308, 1e308);
    d.cell_size = 1e-300;
    if (rc_sim_create(&d, &s) == RC_OK) {
        rc_sim_ball b[2] = {{rc_v3(1, 1, 1), rc_v3(NAN, 0, 0), 0.5, 1.0, 0, 0, 0, {0, 0, 0}},
                            {rc_v3(3, 1, 1), rc_v3(0, 0, 0), -0.5, 1.0, 0, 0, 0, {0, 0, 0}}};
        size_t bad = 0;
        ENSURE(rc_sim_set_balls(s, 2, b, &bad) != RC_OK);
        rc_sim_free(&s);
    }
    rc_sim_gas_def g = {3, 1000, 0.5, 0.9, 2.0, 1.0, 1.0, 1};
    rc_vec3 box;
    rc_sim_ball *balls = malloc(1000 * sizeof *balls);
    if (balls) {
        ENSURE(rc_sim_gas_init(&g, &box, balls) != RC_OK); /* v_rms > c */
        free(balls);
    }
}

/* Every law and the wall law on bad and extreme particles. */
static void test_laws_bad(void)
{
    const double cs[] = {INFINITY, 1.0, 1e-150, -1.0, NAN, 0.0};
    const double ks[] = {0.0, 1.0, 1e300, -1.0, NAN, INFINITY}; /* the wall law's 1/c^2 */
    const rc_particle as[] = {{1.0, rc_v3(1, 0, 0)},   {NAN, rc_v3(1, 0, 0)},
                              {-1.0, rc_v3(1, 0, 0)},  {1.0, rc_v3(1e300, 0, 0)},
                              {1e-300, rc_v3(1, 1, 1)}, {1.0, rc_v3(INFINITY, 0, 0)}};
    const rc_vec3 ns[] = {rc_v3(1, 0, 0), rc_v3(0, 0, 0), rc_v3(NAN, 0, 0), rc_v3(1e-300, 0, 0)};
    int ok = 0, rejected = 0; /* the inputs do reach the laws, good and bad */
    for (int l = 0; rc_laws[l]; l++)
        for (int ic = 0; ic < 6; ic++)
            for (int ia = 0; ia < 6; ia++)
                for (int in = 0; in < 4; in++) {
                    rc_collision_params prm = rc_collision_params_default();
                    prm.c = cs[ic];
                    prm.eps = in == 3 ? 2.0 : 0.5;
                    rc_particle a = as[ia], b = {1.0, rc_v3(-1, 0, 0)};
                    const int st = rc_collide(rc_laws[l], &prm, &a, &b, ns[in]);
                    ok += st == RC_OK;
                    rejected += st < 0;
                    rc_particle w = as[ia];
                    (void)rc_collide_wall(ks[ic], prm.eps, &w, ns[in]);
                }
    ENSURE_MSG(ok > 0 && rejected > 0, "%d collided, %d rejected", ok, rejected);
}

/* Every frame and the walls on bad and extreme balls. */
static void test_toi_bad(void)
{
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    const double cs[] = {INFINITY, 1.0, 1e-150, -1.0, NAN};
    int ok = 0, rejected = 0;
    const rc_toi_ball as[] = {{rc_v3(0, 0, 0), 1.0, 1.0, rc_v3(1, 0, 0)},
                              {rc_v3(0, 0, 0), 1.0, 1.0, rc_v3(1e150, 1e150, 0)},
                              {rc_v3(0, 0, 0), 0.0, 1.0, rc_v3(1, 0, 0)},
                              {rc_v3(NAN, 0, 0), 1.0, 1.0, rc_v3(1, 0, 0)},
                              {rc_v3(3, 0, 0), 1.0, 1e-300, rc_v3(1, 1e-300, 0)}};
    const rc_toi_ball bs[] = {{rc_v3(3, 0, 0), 1.0, 1.0, rc_v3(-1, 0, 0)},
                              {rc_v3(0, 0, 0), 1.0, 1.0, rc_v3(0, 0, 0)},
                              {rc_v3(1e300, 0, 0), 1.0, 1.0, rc_v3(-1e300, 0, 0)}};
    for (int f = 0; rc_toi_frames[f]; f++)
        for (int ic = 0; ic < 5; ic++)
            for (int ia = 0; ia < 5; ia++)
                for (int ib = 0; ib < 3; ib++) {
                    rc_toi_params prm = rc_toi_params_default();
                    prm.c = cs[ic];
                    rc_toi_contact out;
                    const int st = rc_toi(rc_toi_frames[f], &prm, &as[ia], &bs[ib], ws, &out);
                    ok += st == RC_OK;
                    rejected += st < 0;
                    double t;
                    rc_vec3 x;
                    (void)rc_toi_wall(&prm, 1, &as[ia], rc_v3(1, 0, 0), 10.0, &t, &x);
                }
    rc_toi_workspace_free(&ws);
    ENSURE(ws == NULL);
    ENSURE_MSG(ok > 0 && rejected > 0, "%d contacts, %d rejected", ok, rejected);
}

/* Both GSL steppers (and CVODE) with bad parameters, and with extreme ones that must end
 * in a status: stiffness at the top of the range with a tiny step budget, c close to the
 * speeds. */
static void test_soft_bad(void)
{
    const double r[2] = {0.5, 0.5};
    for (int k = 0; rc_soft_steppers[k]; k++)
        for (int ip = 0; ip < 8; ip++) {
            rc_soft_params prm = rc_soft_params_default();
            switch (ip) {
            case 0: prm.rtol = 0.0; break;
            case 1: prm.rtol = -1.0; break;
            case 2: prm.stiffness = NAN; break;
            case 3: prm.max_steps = 5; prm.stiffness = 1e12; break;
            case 4: prm.c = 1.001; prm.shape = RC_SOFT_CONTRACTED; break;
            case 5: prm.t_max = -1.0; break;
            case 6: prm.eps = 0.0; break;
            default: prm.c = 2.0; break; /* valid: the steppers run */
            }
            rc_particle b[2] = {{1.0, rc_v3(1, 0.1, 0)}, {1.0, rc_v3(-1, 0, 0)}};
            if (ip == 4) {
                b[0].p = rc_v3(20.0, 1.0, 0); /* gamma ~ 20 */
                b[1].p = rc_v3(-20.0, 0, 0);
            }
            rc_vec3 x[2] = {rc_v3(0, 0, 0), rc_v3(1.5, 0, 0)};
            rc_soft_result res;
            const int st = rc_soft_collide(rc_soft_steppers[k], &prm, 2, b, x, r, NULL, &res);
            if (ip == 7)
                ENSURE_MSG(st == RC_OK, "%s: %d", rc_soft_steppers[k]->name, st);
            else if (ip != 3 && ip != 4) /* invalid parameters */
                ENSURE_MSG(st == RC_EINVAL || st == RC_ENONFINITE || st == RC_ERESTITUTION,
                           "%s, case %d: %d", rc_soft_steppers[k]->name, ip, st);
        }
}

int main(void)
{
    RUN_TEST(test_handler_catches);
    RUN_TEST(test_contacts_bad);
    RUN_TEST(test_engine_groups);
    RUN_TEST(test_engine_bad_input);
    RUN_TEST(test_laws_bad);
    RUN_TEST(test_toi_bad);
    RUN_TEST(test_soft_bad);
#ifdef RC_TEST_MALLOC_FAULTS
    RUN_TEST(test_contacts_out_of_memory);
    RUN_TEST(test_engine_out_of_memory);
#endif
    RC_TEST_MAIN_END();
}
