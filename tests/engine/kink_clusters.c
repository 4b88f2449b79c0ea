/* kink_clusters — the clusters of collisions joined by kinks that cross inside a ball
 * (kink_clusters.h), in the covariant frame's periodic gas: where the glued tube of
 * papers/glued-tube.md section 1 is not defined, and whether that region percolates.
 * A measurement, not a test (test_engine_kink_clusters checks two points of it).
 *
 *   kink_clusters [dim packing v_rms N collisions_per_ball seed eps]
 *
 * No argument: the table of papers/model-regime.md section 3 (issue 16's range, 2-D to
 * packing 0.7 and 3-D to 0.45, rms 0.5c and 0.9c, eps 1). One line per run: the share of
 * successive kink pairs that cross and the largest cluster's share of the collisions read,
 * over all kinks (p_all, big_all) and over kinks the overlap policy did not place (p_model,
 * big_mod: a cluster the policy's decisions do not make), the mean cluster a collision
 * sits in besides the largest (model) and the share in clusters of three or more, the
 * crossing share of kink pairs with a policy decision at either end, collisions undone,
 * the overlap policy's share. Exit status 0 unless a run fails. */
#include <stdio.h>
#include <stdlib.h>

#include "engine_util.h"
#include "kink_clusters.h"

/* One run: warm up `warm` collisions a ball, then read `per_ball` a ball. */
static int run(int dim, double packing, double v, size_t n, double per_ball, uint64_t seed,
               double eps)
{
    rc_sim_def d = util_covariant_periodic(dim);
    d.eps_ball = eps;
    d.t_c = eps < 1.0 ? 0.05 : 0.0; /* (overlap_share's TC) */
    rc_sim *s = util_gas(d, n, packing, v, seed);
    if (!s)
        return 1;
    /* two collisions a ball melt the initial placement (rc_sim_gas_init's) */
    util_run_collisions(s, (uint64_t)(2 * n));
    kc_state k;
    if (kc_init(&k, s) != 0) {
        rc_sim_free(&s);
        return 1;
    }
    rc_sim_diag g0, g, gp;
    rc_sim_diagnostics(s, &g0);
    gp = g0;
    const uint64_t target = (uint64_t)(per_ball * (double)n);
    int st = RC_OK;
    for (;;) {
        st = rc_sim_advance(s, INFINITY, 1);
        if (st != RC_OK)
            break;
        rc_sim_diagnostics(s, &g);
        if (kc_step(&k, s, g.overlaps != gp.overlaps) != 0) {
            st = RC_ENOMEM;
            break;
        }
        gp = g;
        if (g.collisions - g0.collisions >= target)
            break;
    }
    if (st != RC_OK) {
        fprintf(stderr, "kink_clusters: advance: %s\n", rc_strerror(st));
        kc_free(&k);
        rc_sim_free(&s);
        return 1;
    }
    const kc_result r = kc_measure(&k, 0), m = kc_measure(&k, 1);
    const uint64_t col = g.collisions - g0.collisions;
    /* the crossing share of kink pairs at least one of whose collisions was the policy's */
    const uint64_t pp = k.pairs - k.pairs_model, xp = k.crossing - k.crossing_model;
    const double p_pol = pp ? (double)xp / (double)pp : 0.0;
    printf("%3d %7.3f %5.2f %4.2f %6zu %8zu %8.4f %8.4f %8.4f %8.4f %7.2f %7.4f %8.4f %7llu %8.3f%%\n",
           dim, packing, v, eps, n, r.nodes, r.p, r.largest, m.p, m.largest, m.mean_other, m.in3,
           p_pol,
           (unsigned long long)r.undone,
           100.0 * (double)(g.overlaps - g0.overlaps) / (double)(col ? col : 1));
    fflush(stdout);
    kc_free(&k);
    rc_sim_free(&s);
    return 0;
}

int main(int argc, char **argv)
{
    printf("%3s %7s %5s %4s %6s %8s %8s %8s %8s %8s %7s %7s %8s %7s %9s\n", "dim", "packing",
           "v_rms", "eps", "N", "events", "p_all", "big_all", "p_model", "big_mod", "mean", "in3",
           "p_policy", "undone",
           "policy");
    if (argc == 8)
        return run(atoi(argv[1]), atof(argv[2]), atof(argv[3]), (size_t)atol(argv[4]),
                   atof(argv[5]), (uint64_t)atoll(argv[6]), atof(argv[7]));
    if (argc != 1) {
        fprintf(stderr, "usage: kink_clusters [dim packing v_rms N collisions_per_ball seed eps]\n");
        return 2;
    }
    const double packs[2][7] = {{0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7},
                                {0.01, 0.05, 0.1, 0.2, 0.3, 0.45, 0}};
    int bad = 0;
    for (int di = 0; di < 2; di++)
        for (int vi = 0; vi < 2; vi++)
            for (int pi = 0; pi < 7 && packs[di][pi] > 0; pi++)
                bad |= run(2 + di, packs[di][pi], vi ? 0.9 : 0.5, 1000, 10.0, 3, 1.0);
    return bad;
}
