/* test_engine_queue.c — the engine's event queue (lib/engine/queue.c, internal API) pops in
 * exact (time, ball) order: against a brute-force minimum over all keys, under the engine's
 * usage (the popped ball and a few others get new keys >= the time popped), with ties,
 * balls without events (inf), keys far beyond the calendar's span, negative times and a
 * bucket width that no longer fits the gas. And the engine stops when no event is left. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../lib/engine/private.h"
#include "rc_test.h"
#include "relcol/relcol.h"

/* The minimum by (key, ball): what the queue must pop. */
static void brute_min(const double *key, size_t n, double *t, uint32_t *ball)
{
    *t = INFINITY;
    *ball = UINT32_MAX;
    for (size_t i = 0; i < n; i++)
        if (key[i] < *t || (key[i] == *t && (uint32_t)i < *ball)) {
            *t = key[i];
            *ball = (uint32_t)i;
        }
}

/* The queue's bookkeeping, walked: every ball in the heap (its entry naming its position)
 * or in exactly one list (links consistent both ways, the head's entry naming its list),
 * in_cal the number in the calendar lists (an overcount only slows the queue, an
 * undercount skips entries: both must be caught here), and over_min at most every key of
 * the overflow list (the span then starts at or before its earliest entry; a bound above
 * one would not break the order, the heap takes what lies before the span, but it could
 * fill the heap). Returns the faults found. */
static long structure_faults(const eng_queue *q)
{
    long bad = 0;
    size_t seen = 0, in_cal = 0;
    for (size_t k = 0; k < q->hn; k++) {
        const eng_qent *e = &q->e[q->heap[k]];
        bad += !(e->next == INT32_MIN && e->prev == (int32_t)k);
        seen++;
    }
    for (uint32_t L = 0; L < q->nb + 2; L++) {
        int32_t prev = -1 - (int32_t)L;
        for (int32_t k = q->head[L]; k >= 0; k = q->e[k].next) {
            bad += q->e[k].prev != prev;
            bad += L == q->nb && !(q->e[k].key >= q->over_min);
            prev = k;
            seen++;
            in_cal += L < q->nb;
            if (seen > q->n)
                return bad + 1; /* a cycle */
        }
    }
    bad += seen != q->n;
    bad += in_cal != q->in_cal;
    return bad;
}

/* A new key after time now, drawn from a mixture that exercises every path: soon (the
 * bucket being drained), within a few mean times, far beyond the span, exactly now (ties),
 * a value shared with other balls (ties by ball index), never. */
static double draw(rc_test_rng *R, double now, double scale)
{
    const double u = rc_test_uniform(R);
    if (u < 0.05)
        return now;
    if (u < 0.10)
        return now + scale * floor(rc_test_range(R, 0.0, 4.0)); /* shared grid values */
    if (u < 0.15)
        return INFINITY;
    if (u < 0.20)
        return now + scale * rc_test_range(R, 1e3, 1e6); /* overflow */
    return now - scale * log(rc_test_uniform(R) + 1e-300);
}

static void order_case(size_t n, double t0, double scale, uint64_t seed, int pops)
{
    rc_test_rng R = {seed};
    eng_queue q;
    ENSURE(eng_queue_init(&q, n) == RC_OK);
    double *key = malloc(n * sizeof *key);
    for (size_t i = 0; i < n; i++)
        key[i] = draw(&R, t0, scale);
    eng_queue_build(&q, key, t0);
    long bad = 0, faults = structure_faults(&q);
    for (int p = 0; p < pops; p++) {
        double t, tb;
        uint32_t b, bb;
        const int got = eng_queue_top(&q, &t, &b);
        brute_min(key, n, &tb, &bb);
        if (!got) {
            bad++;
            break;
        }
        if (tb == INFINITY) { /* only balls without events: any of them, at inf */
            bad += !(t == INFINITY && key[b] == INFINITY);
            break;
        }
        bad += !(t == tb && b == bb);
        /* the engine's pattern: the popped ball always gets a new key, sometimes others */
        key[b] = draw(&R, t, scale);
        eng_queue_update(&q, b, key[b]);
        const int others = (int)(rc_test_uniform(&R) * 3.0);
        for (int o = 0; o < others; o++) {
            const uint32_t k = (uint32_t)(rc_test_uniform(&R) * (double)n);
            key[k] = draw(&R, t, scale);
            eng_queue_update(&q, k, key[k]);
        }
        if (p % 5000 == 4999) /* the engine refiles everything when it renumbers */
            eng_queue_build(&q, key, t);
        if (p % 997 == 0)
            faults += structure_faults(&q);
    }
    ENSURE_MSG(bad == 0, "n=%zu t0=%g scale=%g: %ld pops out of order", n, t0, scale, bad);
    ENSURE_MSG(faults == 0, "n=%zu t0=%g scale=%g: %ld faults in the queue's structure", n,
               t0, scale, faults);
    eng_queue_free(&q);
    free(key);
}

static void test_order(void)
{
    order_case(1, 0.0, 1.0, 1, 2000);
    order_case(7, 0.0, 1.0, 2, 20000);
    order_case(1000, 0.0, 1.0, 3, 60000);
    order_case(1000, -50.0, 1e-3, 4, 60000); /* negative times */
    order_case(1000, 1e9, 1e-4, 5, 60000);   /* late times, fine scale */
    order_case(20000, 0.0, 1.0, 6, 60000);
}

/* The width is fitted when the queue is built; a gas that then slows down 1e4 times (or
 * speeds up) leaves it far off. Order must not care. */
static void test_width_drift(void)
{
    const size_t n = 500;
    rc_test_rng R = {9};
    eng_queue q;
    ENSURE(eng_queue_init(&q, n) == RC_OK);
    double key[500];
    for (size_t i = 0; i < n; i++)
        key[i] = rc_test_range(&R, 0.0, 1.0);
    eng_queue_build(&q, key, 0.0);
    long bad = 0;
    for (int p = 0; p < 40000; p++) {
        double t, tb;
        uint32_t b, bb;
        eng_queue_top(&q, &t, &b);
        brute_min(key, n, &tb, &bb);
        bad += !(t == tb && b == bb);
        const double scale = p < 20000 ? 1e4 : 1e-4; /* slower, then much faster */
        key[b] = t + scale * rc_test_uniform(&R);
        eng_queue_update(&q, b, key[b]);
    }
    ENSURE_MSG(bad == 0, "%ld pops out of order", bad);
    eng_queue_free(&q);
}

/* Balls at rest away from each other and the walls: no event will ever come; advancing
 * by event count must return (it used to take the infinite entry for an event). */
static void test_nothing_happens(void)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.box = rc_v3(10.0, 10.0, 0.0);
    rc_sim_ball b[2];
    memset(b, 0, sizeof b);
    b[0].r = b[1].r = 0.5;
    b[0].m = b[1].m = 1.0;
    b[0].x = rc_v3(2.0, 2.0, 0.0);
    b[1].x = rc_v3(6.0, 6.0, 0.0);
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    ENSURE(s && rc_sim_set_balls(s, 2, b, NULL) == RC_OK);
    ENSURE(rc_sim_advance(s, INFINITY, 1000) == RC_OK);
    ENSURE(rc_sim_advance(s, 5.0, 0) == RC_OK);
    ENSURE(rc_sim_time(s) == 5.0);
    rc_sim_diag dg;
    rc_sim_diagnostics(s, &dg);
    ENSURE(dg.collisions == 0);
    rc_sim_free(&s);
}

int main(void)
{
    RUN_TEST(test_order);
    RUN_TEST(test_width_drift);
    RUN_TEST(test_nothing_happens);
    RC_TEST_MAIN_END();
}
