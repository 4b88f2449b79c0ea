/* The validity report's online kink clusters (lib/engine/validity.c) against the offline
 * reading of tests/engine/kink_clusters.h on the same run, count for count: one covariant
 * gas stepped one event at a time and read by kc_step after each, its twin advanced in
 * chunks of events, checkpointed half-way and continued in a new engine; the report of
 * both is the offline tool's exactly (pairs, crossings, undone kinks, both clusters'
 * largest share), from a dilute gas through the giant cluster of the 3-D 0.45 row, and the
 * twin's balls are the stepped run's bit for bit (the hooks change nothing). The verdict:
 * `defined` in the dilute gas, `outside` at 3-D packing 0.45 (0.5c), `non_covariant` for
 * the table frame at finite c, `defined` at c = inf. */
#include <stdio.h>

#include "engine_util.h"
#include "kink_clusters.h"

/* the twin continued from a checkpoint in a new engine of the same definition */
static rc_sim *restart(rc_sim *s, rc_sim_def d)
{
    size_t bytes = 0;
    ENSURE(rc_sim_checkpoint_size(s, &bytes) == RC_OK);
    void *buf = malloc(bytes);
    rc_sim *t = NULL;
    ENSURE(buf && rc_sim_checkpoint_write(s, buf, bytes) == RC_OK);
    ENSURE(rc_sim_create(&d, &t) == RC_OK);
    const int st = t ? rc_sim_checkpoint_read(t, buf, bytes) : RC_EINVAL;
    ENSURE_MSG(st == RC_OK, "checkpoint read: %s", rc_strerror(st));
    /* a checkpoint of the restarted engine is the same bytes */
    size_t b2 = 0;
    ENSURE(rc_sim_checkpoint_size(t, &b2) == RC_OK && b2 == bytes);
    void *buf2 = malloc(b2);
    ENSURE(buf2 && rc_sim_checkpoint_write(t, buf2, b2) == RC_OK);
    ENSURE_MSG(buf2 && buf && memcmp(buf, buf2, bytes) == 0, "checkpoint bytes after restart");
    free(buf2);
    free(buf);
    rc_sim_free(&s);
    return t;
}

static void one(int dim, double packing, double v, size_t n, double per_ball, uint64_t seed,
                const char *want)
{
    rc_sim_def d = util_covariant_periodic(dim);
    rc_sim *s = util_gas(d, n, packing, v, seed);
    rc_sim *w = util_gas(d, n, packing, v, seed);
    /* (the box the gas was made in, for the restart's definition) */
    rc_sim_gas_def gd = {dim, n, 0.5, packing, v, d.c, 1.0, seed};
    rc_sim_ball *tmp_b = malloc(n * sizeof *tmp_b);
    ENSURE(tmp_b && rc_sim_gas_init(&gd, &d.box, tmp_b) == RC_OK);
    free(tmp_b);
    d.restart = 1;
    if (!s || !w)
        return;
    kc_state k;
    ENSURE(kc_init(&k, s) == 0);
    rc_sim_diag g0, g, gp;
    rc_sim_diagnostics(s, &g0);
    gp = g0;
    const uint64_t target = (uint64_t)(per_ball * (double)n);
    uint64_t events = 0;
    int st = RC_OK;
    for (;;) {
        st = rc_sim_advance(s, INFINITY, 1);
        if (st != RC_OK)
            break;
        events++;
        rc_sim_diagnostics(s, &g);
        if (kc_step(&k, s, g.overlaps != gp.overlaps) != 0) {
            st = RC_ENOMEM;
            break;
        }
        gp = g;
        if (g.collisions - g0.collisions >= target)
            break;
    }
    ENSURE_MSG(st == RC_OK, "stepped run: %s", rc_strerror(st));
    /* the twin: the same events in chunks, a report read at every chunk (reading changes
     * nothing), a restart half-way */
    uint64_t done = 0;
    while (done < events) {
        const uint64_t m = events - done < 997 ? events - done : 997;
        ENSURE(rc_sim_advance(w, INFINITY, m) == RC_OK);
        done += m;
        rc_validity tmp;
        ENSURE(rc_sim_validity(w, &tmp) == RC_OK);
        if (done >= events / 2 && done - m < events / 2)
            w = restart(w, d);
    }
    int same = 1;
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball a, b;
        rc_sim_get_ball(s, i, &a);
        rc_sim_get_ball(w, i, &b);
        same &= memcmp(&a.x, &b.x, sizeof a.x) == 0 && memcmp(&a.p, &b.p, sizeof a.p) == 0;
    }
    ENSURE_MSG(same, "%dD %.2f: the twin's balls are the stepped run's", dim, packing);
    const kc_result ra = kc_measure(&k, 0), rm = kc_measure(&k, 1);
    rc_validity o;
    ENSURE(rc_sim_validity(w, &o) == RC_OK);
    printf("%dD packing %.2f v %.2f N %zu: %llu kink events, p_all %.6f p_model %.6f "
           "largest %.4f / %.4f (model), %llu popped, nu r/c %.4f, policy %.4f%%: %s\n",
           dim, packing, v, n, (unsigned long long)o.kink_events, o.p_all, o.p_model,
           o.largest_all, o.largest_model, (unsigned long long)o.kinks_popped, o.nu_r_c,
           100.0 * o.policy_share, o.verdict_name);
    ENSURE_MSG(o.kink_events == ra.nodes, "nodes %llu offline %zu",
               (unsigned long long)o.kink_events, ra.nodes);
    ENSURE_MSG(o.kink_pairs == k.pairs && o.kink_pairs_model == k.pairs_model &&
                   o.crossing == k.crossing && o.crossing_model == k.crossing_model,
               "pairs %llu/%llu crossing %llu/%llu offline %llu/%llu %llu/%llu",
               (unsigned long long)o.kink_pairs, (unsigned long long)o.kink_pairs_model,
               (unsigned long long)o.crossing, (unsigned long long)o.crossing_model,
               (unsigned long long)k.pairs, (unsigned long long)k.pairs_model,
               (unsigned long long)k.crossing, (unsigned long long)k.crossing_model);
    ENSURE_MSG(o.kinks_popped == ra.undone, "popped %llu offline %llu",
               (unsigned long long)o.kinks_popped, (unsigned long long)ra.undone);
    ENSURE_MSG(o.p_all == ra.p && o.p_model == rm.p, "p %.17g %.17g offline %.17g %.17g",
               o.p_all, o.p_model, ra.p, rm.p);
    ENSURE_MSG(o.largest_all == ra.largest && o.largest_model == rm.largest,
               "largest %.17g %.17g offline %.17g %.17g", o.largest_all, o.largest_model,
               ra.largest, rm.largest);
    ENSURE_MSG(strcmp(o.verdict_name, want) == 0, "verdict %s, want %s", o.verdict_name, want);
    ENSURE(o.verdict == (o.p_model > RC_VALIDITY_P_MODEL_MAX ? RC_VERDICT_OUTSIDE
                                                             : RC_VERDICT_DEFINED));
    kc_free(&k);
    rc_sim_free(&s);
    rc_sim_free(&w);
}

/* the other verdicts: a non-covariant model at finite c, every frame at c = inf */
static void others(void)
{
    rc_sim_def d = util_covariant_periodic(3);
    d.frame = &rc_toi_frame_table;
    rc_sim *s = util_gas(d, 125, 0.1, 0.5, 4);
    if (!s)
        return;
    util_run_collisions(s, 500);
    rc_validity o;
    ENSURE(rc_sim_validity(s, &o) == RC_OK);
    ENSURE_MSG(o.verdict == RC_VERDICT_NON_COVARIANT && !o.covariant && o.kink_events == 0,
               "table frame: %s", o.verdict_name);
    rc_sim_free(&s);
    d = util_covariant_periodic(3);
    d.c = INFINITY;
    s = util_gas(d, 125, 0.1, 0.5, 4);
    if (!s)
        return;
    util_run_collisions(s, 500);
    ENSURE(rc_sim_validity(s, &o) == RC_OK);
    ENSURE_MSG(o.verdict == RC_VERDICT_DEFINED && o.nu_r_c == 0.0 && o.kink_events == 0,
               "c = inf: %s", o.verdict_name);
    rc_sim_free(&s);
    ENSURE(rc_sim_validity(NULL, &o) == RC_EINVAL);
    ENSURE(strcmp(rc_sim_verdict_name((rc_sim_verdict)7), "?") == 0);
}

static void test_dilute(void) { one(3, 0.01, 0.5, 216, 20.0, 3, "defined"); }

static void test_dense(void)
{
    one(2, 0.5, 0.9, 400, 8.0, 4, "outside");
    one(3, 0.45, 0.5, 216, 8.0, 3, "outside");
    one(3, 0.3, 0.9, 216, 8.0, 5, "outside");
}

int main(void)
{
    RUN_TEST(test_dilute);
    RUN_TEST(test_dense);
    RUN_TEST(others);
    RC_TEST_MAIN_END();
}
