/* test_engine_defer.c — the table frame's deferred root finds (eng_defer in
 * lib/engine/private.h): a prediction stores the candidate with the least lower bound of
 * contact, keyed by that bound, with a bound lb2 of every other event; when the bound
 * comes up the frame is asked (eng_settle), and its answer is kept only if it comes
 * before lb2, else the ball is predicted again asking the frame at once.
 *  - Settling, ball by ball, gives the very event (time bits, partner) that asking the
 *    frame at once gives, on states of dense gases at rms speed 0.9c (white box, on the
 *    internal API). Among them are balls whose least bound is not their event (the
 *    fallback is needed: counted, and required to occur), so a prediction that left out
 *    the others' bound lb2 fails here (~230 of the 9000 balls differ). (The settle's own
 *    comparison with lb2 is also made by pair_time's cut-off, which it is given.)
 *  - Whole runs with and without deferring (RC_SIM_DEFER_OFF) agree bit for bit at a given
 *    time: the state hash, collisions, groups, crossings, overlaps, TC events. Only the
 *    stale entries differ (a deferred bound is popped and found stale where an exact
 *    time would have been found stale at a crossing): checked to differ, so that the
 *    comparison is not of one mode with itself. 2-D and 3-D, dense and dilute, elastic
 *    and inelastic, c near 1. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "../../lib/engine/private.h"
#include "engine_util.h"

static rc_sim_def table_def(int dim, double c, double eps)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    d.c = c;
    d.eps_ball = eps;
    d.eps_wall = 0.95;
    d.t_c = 1e-4;
    d.frame = rc_toi_frame_find("table");
    return d;
}

static rc_sim *engine_of(rc_sim_def d, double t, const rc_sim_ball *b, size_t n, int defer)
{
    d.restart = 1; /* (a melted state holds shape-change overlaps that are separating) */
    d.defer = defer ? RC_SIM_DEFER_ON : RC_SIM_DEFER_OFF;
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    size_t bad = 0;
    int st = s ? rc_sim_set_time(s, t) : RC_OK;
    if (s && (st != RC_OK || (st = rc_sim_set_balls(s, n, b, &bad)) != RC_OK)) {
        ENSURE_MSG(0, "set_time/set_balls: %s (ball %zu)", rc_strerror(st), bad);
        rc_sim_free(&s);
    }
    return s;
}

/* A melted gas's state (run `melt` collisions a ball from a lattice), as balls at one
 * time. */
static rc_sim_ball *melted(rc_sim_def *d, size_t n, double packing, double beta, double melt,
                           double *t)
{
    rc_sim_gas_def g = {d->dim, n, 0.5, packing, beta * d->c, d->c, 1.0, 31};
    rc_sim_ball *lattice = calloc(n, sizeof *lattice);
    rc_sim *s = NULL;
    ENSURE(lattice && rc_sim_gas_init(&g, &d->box, lattice) == RC_OK); /* (sets the box) */
    ENSURE(rc_sim_create(d, &s) == RC_OK);
    if (s && rc_sim_set_balls(s, n, lattice, NULL) != RC_OK)
        rc_sim_free(&s);
    free(lattice);
    if (!s)
        return NULL;
    util_run_collisions(s, (uint64_t)(melt * (double)n));
    *t = rc_sim_time(s);
    rc_sim_ball *b = malloc(n * sizeof *b);
    for (size_t i = 0; b && i < n; i++)
        ENSURE(rc_sim_get_ball(s, i, &b[i]) == RC_OK);
    rc_sim_free(&s);
    return b;
}

/* Each ball's event by settling (engine A) against asking at once (engine B), both made
 * from the same balls. Returns the balls whose least bound was not their event. */
static size_t settle_vs_at_once(int dim, size_t n, double packing, double c, double beta)
{
    rc_sim_def d = table_def(dim, c, 1.0);
    double t = 0.0;
    rc_sim_ball *b = melted(&d, n, packing, beta, 3.0, &t);
    rc_sim *A = b ? engine_of(d, t, b, n, 1) : NULL, *B = b ? engine_of(d, t, b, n, 0) : NULL;
    size_t moved = 0, deferred = 0, bad = 0;
    if (A && B) {
        ENSURE(A->defer && !B->defer);
        for (size_t k = 0; k < n; k++) {
            const int32_t i = (int32_t)A->slot[k];
            ENSURE(B->slot[k] == (uint32_t)i); /* (the same numbering: same input) */
            eng_predict(A, i, 1);
            eng_predict(B, i, 1);
            const int32_t first = A->a[i].ev_partner;
            int was_deferred = 0;
            /* settle as the event loop does: at the bound, while the entry is deferred */
            for (int round = 0; round < 4 && A->a[i].ev_partner >= 0 &&
                                ev_is_deferred(A->ev_n[i]);
                 round++) {
                was_deferred = 1;
                const double now = A->now;
                A->now = A->a[i].ev_t;
                eng_settle(A, i);
                A->now = now;
            }
            deferred += (size_t)was_deferred;
            moved += (size_t)(was_deferred && A->a[i].ev_partner != first);
            const eng_aux *x = &A->a[i], *y = &B->a[i];
            const int same = x->ev_t == y->ev_t && x->ev_partner == y->ev_partner &&
                             !ev_is_deferred(A->ev_n[i]) &&
                             (x->ev_partner < 0 || (A->ev_n[i].x == B->ev_n[i].x &&
                                                    A->ev_n[i].y == B->ev_n[i].y &&
                                                    A->ev_n[i].z == B->ev_n[i].z) ||
                              (isnan(A->ev_n[i].x) && isnan(B->ev_n[i].x)));
            if (!same && bad++ < 5)
                ENSURE_MSG(0, "%dD ball %zu: settled t=%a partner %d, at once t=%a partner %d",
                           dim, k, x->ev_t, (int)x->ev_partner, y->ev_t, (int)y->ev_partner);
        }
        ENSURE_MSG(bad == 0, "%dD: %zu of %zu balls differ", dim, bad, n);
        ENSURE_MSG(deferred > n / 4, "%dD: only %zu of %zu events were deferred", dim,
                   deferred, n);
        printf("  %dD phi=%g c=%g rms %gc: %zu balls, %zu deferred, %zu settled on another "
               "partner\n", dim, packing, c, beta, n, deferred, moved);
    }
    rc_sim_free(&A);
    rc_sim_free(&B);
    free(b);
    return moved;
}

static void test_settle(void)
{
    size_t moved = settle_vs_at_once(3, 3000, 0.40, 1.0, 0.9);
    moved += settle_vs_at_once(2, 3000, 0.60, 1.0, 0.9);
    moved += settle_vs_at_once(3, 3000, 0.45, 2.0, 0.5);
    ENSURE_MSG(moved > 0, "%s", "no ball's least bound was another partner's: the fallback "
                                "was never exercised");
}

/* Whole runs to time T with and without deferring. */
static void runs(int dim, size_t n, double packing, double c, double beta, double eps, double T)
{
    rc_sim_def d = table_def(dim, c, eps);
    rc_sim_diag g[2];
    uint64_t h[2] = {0, 0};
    for (int k = 0; k < 2; k++) {
        d.defer = k == 0 ? RC_SIM_DEFER_OFF : RC_SIM_DEFER_AUTO;
        rc_sim *s = util_gas(d, n, packing, beta * c, 23);
        if (!s)
            return;
        ENSURE(s->defer == k);
        ENSURE(rc_sim_advance(s, T, 0) == RC_OK);
        rc_sim_diagnostics(s, &g[k]);
        h[k] = rc_sim_hash(s);
        rc_sim_free(&s);
    }
    const char *what = dim == 3 ? "3-D" : "2-D";
    printf("  %s phi=%g c=%g rms %gc eps=%g: %llu collisions, %llu overlaps, stale entries "
           "%llu at once, %llu deferred\n", what, packing, c, beta, eps,
           (unsigned long long)g[0].collisions, (unsigned long long)g[0].overlaps,
           (unsigned long long)g[0].events[RC_SIM_EV_STALE],
           (unsigned long long)g[1].events[RC_SIM_EV_STALE]);
    ENSURE_MSG(g[0].collisions > 10 * n, "%s: only %llu collisions", what,
               (unsigned long long)g[0].collisions);
    ENSURE_MSG(h[0] == h[1], "%s phi=%g c=%g eps=%g: at once %llx, deferred %llx", what,
               packing, c, eps, (unsigned long long)h[0], (unsigned long long)h[1]);
    ENSURE(g[0].collisions == g[1].collisions && g[0].overlaps == g[1].overlaps);
    const int same[] = {RC_SIM_EV_BALL, RC_SIM_EV_WALL, RC_SIM_EV_MULTI, RC_SIM_EV_CELL,
                        RC_SIM_EV_TC};
    for (size_t j = 0; j < sizeof same / sizeof *same; j++)
        ENSURE_MSG(g[0].events[same[j]] == g[1].events[same[j]],
                   "%s: events of kind %d: %llu at once, %llu deferred", what, same[j],
                   (unsigned long long)g[0].events[same[j]],
                   (unsigned long long)g[1].events[same[j]]);
    ENSURE_MSG(g[0].events[RC_SIM_EV_STALE] != g[1].events[RC_SIM_EV_STALE],
               "%s: as many stale entries deferred as not (%llu): was anything deferred?",
               what, (unsigned long long)g[0].events[RC_SIM_EV_STALE]);
}

static void test_runs(void)
{
    runs(3, 3000, 0.45, 2.0, 0.5, 1.0, 2.0);
    runs(2, 2000, 0.70, 2.0, 0.5, 1.0, 3.0);
    runs(3, 2000, 0.30, 1.1, 0.5, 0.7, 14.0);
    runs(2, 2000, 0.50, 1.2, 0.5, 0.5, 24.0);
    runs(3, 2000, 0.30, 1.0, 0.9, 1.0, 7.0);
    runs(2, 2000, 0.50, 1.0, 0.9, 1.0, 12.0);
}

/* The def's choice: on for the table frame, RC_EINVAL where deferring is not allowed (the
 * zmf frame, uncontracted spheres), off anywhere; values outside the enum are RC_EINVAL. */
static void test_def_field(void)
{
    const char *frames[3] = {"table", "zmf", "sphere"};
    for (int f = 0; f < 3; f++)
        for (int k = 0; k < 3; k++) {
            rc_sim_def d = table_def(3, 2.0, 1.0);
            d.frame = rc_toi_frame_find(frames[f]);
            d.defer = k == 0 ? RC_SIM_DEFER_AUTO : k == 1 ? RC_SIM_DEFER_ON : RC_SIM_DEFER_OFF;
            rc_sim *s = NULL;
            const int st = rc_sim_create(&d, &s);
            const int allowed = f == 0 || d.defer != RC_SIM_DEFER_ON;
            ENSURE_MSG(st == (allowed ? RC_OK : RC_EINVAL), "%s defer %d: %d", frames[f], k, st);
            if (s)
                ENSURE(s->defer == (f == 0 && d.defer != RC_SIM_DEFER_OFF));
            rc_sim_free(&s);
        }
    rc_sim_def d = table_def(3, 2.0, 1.0);
    d.defer = (rc_sim_defer)7;
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_EINVAL);
    d = table_def(3, 2.0, 1.0);
    d.simd = (rc_sim_simd)-1;
    ENSURE(rc_sim_create(&d, &s) == RC_EINVAL);
}

int main(void)
{
    RUN_TEST(test_def_field);
    RUN_TEST(test_settle);
    RUN_TEST(test_runs);
    RC_TEST_MAIN_END();
}
