/* The covariant frame's two promises (relcol/validity.h, issue 36), as tests.
 *
 * (a) Final four-momenta from two inertial frames agree within a small multiple of the
 * run's own round-off growth, whenever no rule decision differs: relcol-covariance's open
 * cluster (apps/covariance/cluster.h: 64 discs, rms ~0.5c, run from the table and from a
 * frame moving at 0.6c, and again from the table with positions moved by 1e-15) over
 * several seeds. Where both frames' runs made the same contacts and the same rule
 * decisions (overlap policy, tube and order conflicts, undos), the frames' difference
 * dp_frames must be within 10 of the round-off run's dp_roundoff (or 1e-12 of the rms
 * momentum, a few hundred ulps, where the round-off did not grow); at least three seeds
 * must qualify. A seed whose decisions differ is reported, not bounded: that is where the
 * promise says nothing.
 *
 * (b) The overlap policy's share stays <= 0.1 % wherever p_model <= 1e-3: the small rows
 * of the share map (covariant periodic gases, 2-D and 3-D, 0.5c and 0.9c), each run for
 * 12 collisions a ball; every row whose report has p_model <= 1e-3 must have a policy
 * share <= 1e-3, and at least two rows must qualify. `test_engine_promise map` runs the
 * longer map (N 1000, 20 collisions a ball, packings to 0.7 / 0.45) as a benchmark. */
#include <stdio.h>
#include <string.h>

#include "engine_util.h"
#include "cluster.h"

static void test_frames(void)
{
    int qualified = 0;
    for (unsigned seed = 16; seed < 24; seed++) {
        const cov_def d = {.dim = 2, .n = 64, .r = 0.5, .inner = 16.0, .outer = 120.0,
                           .v_in = 0.35, .v_noise = 0.15, .c = 1.0, .u = 0.6, .box = 20000.0,
                           .t_end = 6000.0, .seed = seed}; /* (covariance_cluster's) */
        cov_cluster cl;
        if (cov_cluster_make(&d, rc_toi_frames[0], &cl) != COV_OK) {
            printf("seed %u: no draw\n", seed);
            continue;
        }
        cov_result r;
        const int st = cov_compare(&d, &rc_toi_frame_covariant, &cl, &r);
        cov_cluster_free(&cl);
        if (st != 0) {
            printf("seed %u: run %d failed: %s\n", seed, r.which, rc_strerror(r.status));
            continue;
        }
        const int same = r.coll[0] == r.coll[1] && r.coll[0] == r.coll[2] &&
                         r.overlaps[0] == r.overlaps[1] && r.overlaps[0] == r.overlaps[2] &&
                         r.tube[0] == r.tube[1] && r.tube[0] == r.tube[2] &&
                         r.order[0] == r.order[1] && r.order[0] == r.order[2] &&
                         r.undone[0] == r.undone[1] && r.undone[0] == r.undone[2];
        const int clean = r.early[0] == 0 && !r.walls && r.open[0] + r.open[1] + r.open[2] == 0;
        const double lim = 10.0 * fmax(r.dp_roundoff, 1e-12);
        printf("seed %u: %llu contacts, decisions %s (policy %llu/%llu, tube %llu/%llu, order "
               "%llu/%llu, undone %llu/%llu), dp frames %.3g, round-off %.3g, p_model %.3g "
               "(%s)\n", seed, (unsigned long long)r.coll[0], same ? "the same" : "differ",
               (unsigned long long)r.overlaps[0], (unsigned long long)r.overlaps[1],
               (unsigned long long)r.tube[0], (unsigned long long)r.tube[1],
               (unsigned long long)r.order[0], (unsigned long long)r.order[1],
               (unsigned long long)r.undone[0], (unsigned long long)r.undone[1], r.dp_frames,
               r.dp_roundoff, r.val[0].p_model, r.val[0].verdict_name);
        if (!same || !clean)
            continue;
        qualified++;
        ENSURE_MSG(r.dp_frames <= lim, "seed %u: frames differ by %.3g, round-off %.3g", seed,
                   r.dp_frames, r.dp_roundoff);
    }
    ENSURE_MSG(qualified >= 3, "only %d seeds made the same decisions in both frames", qualified);
}

/* one row: the report after per_ball collisions a ball; 1 if it qualified */
static int row(int dim, double packing, double v, size_t n, double per_ball, int check)
{
    rc_sim *s = util_gas(util_covariant_periodic(dim), n, packing, v, 5);
    if (!s)
        return 0;
    util_run_collisions(s, (uint64_t)(per_ball * (double)n));
    rc_validity o;
    ENSURE(rc_sim_validity(s, &o) == RC_OK);
    rc_sim_free(&s);
    const int q = o.p_model <= RC_VALIDITY_P_MODEL_MAX;
    printf("%dD packing %5.3f v %.1f N %5zu: %7llu collisions, p_model %.5f, policy %.4f %%, "
           "largest cluster %.4f, nu r/c %.4f: %s\n", dim, packing, v, n,
           (unsigned long long)o.collisions, o.p_model, 100.0 * o.policy_share,
           o.largest_model, o.nu_r_c, o.verdict_name);
    if (q && check)
        ENSURE_MSG(o.policy_share <= 1e-3, "%dD packing %g v %g: p_model %.3g, policy %.3g %%",
                   dim, packing, v, o.p_model, 100.0 * o.policy_share);
    return q;
}

static void test_share(void)
{
    int q = 0;
    q += row(2, 0.01, 0.5, 400, 12.0, 1);
    q += row(2, 0.05, 0.5, 400, 12.0, 1);
    q += row(3, 0.01, 0.5, 216, 12.0, 1);
    q += row(3, 0.01, 0.9, 216, 12.0, 1);
    ENSURE_MSG(q >= 2, "only %d rows with p_model <= 1e-3", q);
}

static int map(void)
{
    const double packs[2][7] = {{0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7},
                                {0.01, 0.05, 0.1, 0.2, 0.3, 0.45, 0}};
    int q = 0;
    for (int di = 0; di < 2; di++)
        for (int vi = 0; vi < 2; vi++)
            for (int pi = 0; pi < 7 && packs[di][pi] > 0; pi++)
                q += row(2 + di, packs[di][pi], vi ? 0.9 : 0.5, 1000, 20.0, 1);
    printf("%d rows with p_model <= 1e-3; %ld checks, %ld failed\n", q, rc_test_checks,
           rc_test_failures);
    return rc_test_failures == 0 ? 0 : 1;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "map") == 0)
        return map();
    RUN_TEST(test_frames);
    RUN_TEST(test_share);
    RC_TEST_MAIN_END();
}
