/* Where the glued tube is not defined (kink_clusters.h; papers/model-regime.md sections 2-3):
 * the crossing bound of two kinks against its closed forms and under a boost, and the
 * clusters of collisions joined by crossing kinks at the two ends of issue 16's range — a
 * dilute covariant gas where they stay single collisions, the densest 3-D row where
 * successive kinks cross more often than the threshold 1/3 of a graph whose collisions
 * have four neighbours each and one cluster holds most of the run. */
#include <stdio.h>

#include "engine_util.h"
#include "kink_clusters.h"

/* tanh of half the rapidity of speed b (c = 1): gamma b / (1 + gamma) */
static double th_half(double b)
{
    const double g = 1.0 / sqrt(1.0 - b * b);
    return g * b / (1.0 + g);
}

/* boost of velocity v by U (c = 1): the velocity seen from a frame moving at U */
static rc_vec3 boost(rc_vec3 U, rc_vec3 v)
{
    const double u2 = rc_v3_dot(U, U), g = 1.0 / sqrt(1.0 - u2), uv = rc_v3_dot(U, v);
    const double den = 1.0 - uv;
    const rc_vec3 par = rc_v3_scale(uv / u2, U), perp = rc_v3_sub(v, par);
    return rc_v3_scale(1.0 / den, rc_v3_add(rc_v3_sub(par, U), rc_v3_scale(1.0 / g, perp)));
}

/* The ball at rest between its kinks: a_1 = tanh(phi_0/2) w_0, a_2 = tanh(phi_2/2) w_2 with
 * w the directions of its velocities before and after, so the bound is r |a_1 - a_2|: head
 * on (v_0 = -b0 x, v_2 = +b2 x) r (t0 + t2), at right angles r sqrt(t0^2 + t2^2). A
 * proper time is invariant: the same bound with all three velocities boosted. The double
 * form cancels in C - 1 only, ~ b^2/2 of C: relative 1e-12 holds to b = 1e-2 and near c
 * (b = 0.999999: C ~ 1e3, nothing cancels). */
static void test_cross_tau(void)
{
    const double bs[4] = {0.01, 0.3, 0.9, 0.999999};
    const rc_vec3 U = rc_v3(0.6 / sqrt(2.0), 0.6 / sqrt(2.0), 0.0);
    double worst = 0.0, worst_boost = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            const double b0 = bs[i], b2 = bs[j], r = 0.7;
            const rc_vec3 z = rc_v3(0, 0, 0);
            const rc_vec3 head[3] = {rc_v3(-b0, 0, 0), z, rc_v3(b2, 0, 0)};
            const rc_vec3 right[3] = {rc_v3(-b0, 0, 0), z, rc_v3(0, b2, 0)};
            const double want_h = r * (th_half(b0) + th_half(b2));
            const double want_r = r * hypot(th_half(b0), th_half(b2));
            const double got_h = kc_cross_tau(1.0, r, head[0], head[1], head[2]);
            const double got_r = kc_cross_tau(1.0, r, right[0], right[1], right[2]);
            worst = fmax(worst, fmax(fabs(got_h - want_h) / want_h, fabs(got_r - want_r) / want_r));
            const double bst = kc_cross_tau(1.0, r, boost(U, right[0]), boost(U, right[1]),
                                            boost(U, right[2]));
            worst_boost = fmax(worst_boost, fabs(bst - want_r) / want_r);
        }
    ENSURE_MSG(worst < 1e-12, "crossing bound against closed forms: %.3g", worst);
    /* the boosted velocities carry one rounding each, amplified by 1/(C - 1) ~ 2/b^2 at
     * b = 0.01: 1e-16 * 2e4 */
    ENSURE_MSG(worst_boost < 1e-10, "crossing bound after a boost: %.3g", worst_boost);
    /* no change of velocity, no crossing interval: q is a rounding of C = 1, ~1e-16, and
     * the bound r sqrt(q) ~1e-8 r */
    ENSURE(kc_cross_tau(1.0, 1.0, rc_v3(0.5, 0, 0), rc_v3(0.5, 0, 0), rc_v3(0.5, 0, 0)) < 1e-7);
}

/* One covariant periodic gas read for per_ball collisions a ball after two a ball. */
static int clusters(int dim, double packing, double v, size_t n, double per_ball,
                    kc_result *all, kc_result *model)
{
    rc_sim *s = util_gas(util_covariant_periodic(dim), n, packing, v, 3);
    if (!s)
        return -1;
    util_run_collisions(s, (uint64_t)(2 * n));
    kc_state k;
    int st = kc_init(&k, s) == 0 ? RC_OK : RC_ENOMEM;
    rc_sim_diag g0, g, gp;
    rc_sim_diagnostics(s, &g0);
    gp = g0;
    while (st == RC_OK) {
        st = rc_sim_advance(s, INFINITY, 1);
        if (st != RC_OK)
            break;
        rc_sim_diagnostics(s, &g);
        if (kc_step(&k, s, g.overlaps != gp.overlaps) != 0)
            st = RC_ENOMEM;
        gp = g;
        if ((double)(g.collisions - g0.collisions) >= per_ball * (double)n)
            break;
    }
    ENSURE_MSG(st == RC_OK, "%dD packing %g: %s", dim, packing, rc_strerror(st));
    *all = kc_measure(&k, 0);
    *model = kc_measure(&k, 1);
    kc_free(&k);
    rc_sim_free(&s);
    return st == RC_OK ? 0 : -1;
}

/* dilute: a collision every ~50 r/c of proper time, so a kink crosses the one before about
 * once in 1e3-1e4 (measured 1.5e-4 over 1e4 collisions) */
static void test_dilute(void)
{
    kc_result a, m;
    if (clusters(2, 0.01, 0.5, 1000, 5.0, &a, &m) != 0)
        return;
    printf("2-D packing 0.01, 0.5c: %zu collisions, p %.4f, largest %.4f\n", a.nodes, a.p,
           a.largest);
    ENSURE_MSG(a.nodes >= 4000, "dilute: %zu collisions read", a.nodes);
    ENSURE_MSG(a.p < 5e-3, "dilute: crossing share %.4f", a.p);
    ENSURE_MSG(a.largest < 0.01, "dilute: largest cluster %.4f", a.largest);
}

/* issue 16's densest 3-D row (measured: p 0.75, largest 0.994 at N 1000): p well above 1/3
 * and one cluster holding most collisions. Joined only where neither collision was an
 * overlap-policy decision -- the model's own kinks -- p is above 1/3 too and the largest
 * cluster holds a fixed share of the run: there the glued tube is not defined over a
 * finite part of the dynamics whatever the policy does, which is what blocks issue 16's
 * bound in this row (papers/model-regime.md section 3; measured at N 343, seeds 3-7: p
 * 0.44-0.46, largest 0.09-0.25; at N 1000: 0.43, 0.22). */
static void test_dense(void)
{
    kc_result a, m;
    if (clusters(3, 0.45, 0.9, 343, 5.0, &a, &m) != 0)
        return;
    printf("3-D packing 0.45, 0.9c: %zu collisions, p %.4f, largest %.4f; model's kinks p "
           "%.4f, largest %.4f\n", a.nodes, a.p, a.largest, m.p, m.largest);
    ENSURE_MSG(a.nodes >= 1500, "dense: %zu collisions read", a.nodes);
    ENSURE_MSG(a.p > 0.5, "dense: crossing share %.4f", a.p);
    ENSURE_MSG(a.largest > 0.5, "dense: largest cluster %.4f", a.largest);
    ENSURE_MSG(m.p > 1.0 / 3.0, "dense: the model's kinks' crossing share %.4f", m.p);
    ENSURE_MSG(m.largest > 0.05, "dense: the model's largest cluster %.4f", m.largest);
}

int main(void)
{
    RUN_TEST(test_cross_tau);
    RUN_TEST(test_dilute);
    RUN_TEST(test_dense);
    RC_TEST_MAIN_END();
}
