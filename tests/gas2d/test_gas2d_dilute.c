/* test_gas2d_dilute.c — the 2-D disc gas in the dilute limit (issue 17, items 1 and 6),
 * periodic boxes, c = 1, theta = 0.75:
 *  - the thermometers against packing: the zmf frame's gas tends to Jüttner as the packing
 *    falls (its kernel balances gain and loss: test_gain_loss.c), while the table frame's
 *    stays off it at the lowest packing (its kernel does not);
 *  - the invariant collision rate: per unit area and time, 1/2 n^2 sigma <v_Moller> g for
 *    the covariant zmf frame, 1/2 n^2 sigma <|v0 - v1|> g for uncontracted discs, with
 *    sigma = 2 (r0 + r1) the 2-D cross-section of discs and g the contact value of the
 *    pair correlation (Enskog factor; 2-D Henderson (1 - 7 eta/16)/(1 - eta)^2). */
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "gas_stats.h"
#include "juttner.h"
#include "rc_test.h"
#include "relcol/relcol.h"

#define THETA 0.75
enum { NBLK = 10 };

/* `test_gas2d_dilute --paper`: the same runs with 8 times the balls and 4 times the
 * sampled time, for the figures quoted in papers/relcol.md (minutes, not a test). */
static size_t big_n = 1;
static double big_t = 1.0;

typedef struct dilute_run {
    const char *frame;
    size_t n;
    double packing;
    double t_eq, t_sample;
    int n_snap;                    /* a multiple of NBLK */
    uint64_t seed;
    /* results */
    double th_g, th_pv, se_diff;   /* thermometers, se of their difference */
    double rate, se_rate;          /* collisions per unit area and time */
    double v_moller, v_rel;        /* pair means over the sampled momenta */
    double area;
} dilute_run;

/* Moller relative speed of two unit-mass momenta (c = 1): sqrt((p0.p1)^2 - 1)/(E0 E1),
 * (p0.p1) the four-product E0 E1 - p0.p1, its square minus one written without the
 * cancellation: ((E0E1 - p0.p1)^2 - 1). */
static double v_moller(rc_vec3 p0, rc_vec3 p1)
{
    const double E0 = sqrt(1.0 + rc_v3_norm2(p0)), E1 = sqrt(1.0 + rc_v3_norm2(p1));
    const double g = E0 * E1 - rc_v3_dot(p0, p1);
    return sqrt((g - 1.0) * (g + 1.0)) / (E0 * E1);
}

static int run(dilute_run *r)
{
    r->n *= big_n;
    r->t_sample *= big_t;
    const size_t n = r->n;
    rc_sim_ball *b = malloc(n * sizeof *b);
    rc_vec3 *p = malloc(n * sizeof *p);
    if (!b || !p) {
        free(b), free(p);
        return RC_ENOMEM;
    }
    rc_sim_gas_def g = {2, n, 0.5, r->packing, 0.1, 1.0, 8.0, r->seed};
    rc_vec3 box;
    int st = rc_sim_gas_init(&g, &box, b);
    /* every speed that of Jüttner's <gamma> at THETA, pairs of opposite momenta (zero
     * total: a periodic box keeps it) */
    const double g0 = jt_mean_gamma(2, THETA), p0 = sqrt((g0 - 1.0) * (g0 + 1.0));
    rc_test_rng rng = {r->seed ^ 0xd11ULL};
    for (size_t i = 0; i + 1 < n; i += 2) {
        const double a = 2.0 * M_PI * rc_test_uniform(&rng);
        b[i].p = rc_v3(p0 * cos(a), p0 * sin(a), 0.0);
        b[i + 1].p = rc_v3_scale(-1.0, b[i].p);
        b[i].m = b[i + 1].m = 1.0;
    }
    r->area = box.x * box.y;
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.box = box;
    d.c = 1.0;
    d.frame = rc_toi_frame_find(r->frame);
    for (int k = 0; k < 3; k++)
        d.boundary[k] = RC_SIM_PERIODIC;
    rc_sim *s = NULL;
    if (st == RC_OK)
        st = d.frame ? rc_sim_create(&d, &s) : RC_EINVAL;
    if (st == RC_OK)
        st = rc_sim_set_balls(s, n, b, NULL);
    if (st == RC_OK)
        st = rc_sim_advance(s, r->t_eq, 0);
    rc_sim_diag dg;
    uint64_t c_prev = 0;
    if (st == RC_OK && (st = rc_sim_diagnostics(s, &dg)) == RC_OK)
        c_prev = dg.collisions;
    const int per = r->n_snap / NBLK;
    const double dt = r->t_sample / r->n_snap;
    double bg[NBLK], bpv[NBLK], bd[NBLK], brate[NBLK];
    double svm = 0.0, svr = 0.0, npair = 0.0;
    for (int k = 0; k < NBLK && st == RC_OK; k++) {
        double sg = 0.0, spv = 0.0, cnt = 0.0;
        for (int j = 0; j < per && st == RC_OK; j++) {
            st = rc_sim_advance(s, r->t_eq + dt * (k * per + j + 1), 0);
            for (size_t i = 0; i < n && st == RC_OK; i++) {
                rc_sim_ball q;
                st = rc_sim_get_ball(s, i, &q);
                p[i] = q.p;
                const double u = rc_v3_norm2(q.p), gm = sqrt(1.0 + u);
                sg += gm;
                spv += u / gm;
                cnt += 1.0;
            }
            /* pair means over all pairs of every block's first snapshot (the speeds'
             * distribution itself, not a sample of pairs from it) */
            if (j > 0)
                continue;
            for (size_t i = 0; i < n; i++)
                for (size_t l = i + 1; l < n; l++) {
                    const double E0 = sqrt(1.0 + rc_v3_norm2(p[i])), E1 = sqrt(1.0 + rc_v3_norm2(p[l]));
                    svm += v_moller(p[i], p[l]);
                    svr += rc_v3_norm(rc_v3_sub(rc_v3_scale(1.0 / E0, p[i]), rc_v3_scale(1.0 / E1, p[l])));
                    npair += 1.0;
                }
        }
        if (st == RC_OK && (st = rc_sim_diagnostics(s, &dg)) == RC_OK) {
            brate[k] = (double)(dg.collisions - c_prev) / (r->area * dt * per);
            c_prev = dg.collisions;
        }
        bg[k] = jt_theta_from_gamma(2, sg / cnt);
        bpv[k] = 0.5 * spv / cnt;
        bd[k] = bpv[k] - bg[k];
    }
    rc_sim_free(&s);
    free(b), free(p);
    if (st != RC_OK)
        return st;
    double se;
    r->th_g = gs_mean_se(bg, NBLK, &se);
    r->th_pv = gs_mean_se(bpv, NBLK, &se);
    gs_mean_se(bd, NBLK, &r->se_diff);
    r->rate = gs_mean_se(brate, NBLK, &r->se_rate);
    r->v_moller = svm / npair;
    r->v_rel = svr / npair;
    return RC_OK;
}

static void print(const dilute_run *r)
{
    printf("  %-6s packing %-5g N %zu: theta <p.v>/2 - <gamma> = %+.5f +- %.5f (%.1f sigma)\n",
           r->frame, r->packing, r->n, r->th_pv - r->th_g, r->se_diff,
           (r->th_pv - r->th_g) / r->se_diff);
}

/* zmf: the deviation falls with the packing and is gone (within 4 sigma: a fixed-seed
 * check that fails ~1e-4 of seeds) at the lowest; table: at the lowest packing it is
 * still >= 1 % low, > 10 sigma (notebook 08's Boltzmann kernel gives -1.6 %). */
static void test_thermometers_dilute(void)
{
    dilute_run z[3] = {
        {.frame = "zmf", .n = 500, .packing = 0.01, .t_eq = 1500, .t_sample = 6000, .n_snap = 60, .seed = 1},
        {.frame = "zmf", .n = 500, .packing = 0.05, .t_eq = 300, .t_sample = 1200, .n_snap = 60, .seed = 2},
        {.frame = "zmf", .n = 500, .packing = 0.25, .t_eq = 60, .t_sample = 240, .n_snap = 60, .seed = 3},
    };
    for (int i = 0; i < 3; i++) {
        ENSURE(run(&z[i]) == RC_OK);
        print(&z[i]);
    }
    ENSURE_CLOSE(z[0].th_pv, z[0].th_g, 4.0, z[0].se_diff);
    const double d0 = z[0].th_pv - z[0].th_g, d2 = z[2].th_pv - z[2].th_g;
    /* (3 combined sigma: the expected separation, ~0.0037, is 4-6 of the block errors
     * these sample sizes give, and the errors themselves scatter by tens of percent from
     * seed to seed and build to build; a deviation that did not grow passes 3 sigma by
     * chance ~1e-3 of the time) */
    ENSURE_MSG(d2 - d0 > 3.0 * hypot(z[0].se_diff, z[2].se_diff),
               "zmf deviation at packing 0.25 (%g) not above the dilute one (%g)", d2, d0);
    dilute_run t = {.frame = "table", .n = 500, .packing = 0.01, .t_eq = 1500,
                    .t_sample = 6000, .n_snap = 60, .seed = 4};
    ENSURE(run(&t) == RC_OK);
    print(&t);
    ENSURE(t.th_pv / t.th_g - 1.0 < -0.01 && t.th_g - t.th_pv > 10.0 * t.se_diff);
}

/* 2-D Enskog factor: the contact value of the hard-disc pair correlation (Henderson). */
static double enskog_2d(double eta) { return (1.0 - 7.0 * eta / 16.0) / ((1.0 - eta) * (1.0 - eta)); }

static void test_invariant_rate(void)
{
    dilute_run r[2] = {
        {.frame = "zmf", .n = 500, .packing = 0.01, .t_eq = 1500, .t_sample = 6000, .n_snap = 60, .seed = 11},
        {.frame = "sphere", .n = 500, .packing = 0.01, .t_eq = 1500, .t_sample = 6000, .n_snap = 60, .seed = 12},
    };
    for (int i = 0; i < 2; i++) {
        ENSURE(run(&r[i]) == RC_OK);
        const double nd = (double)r[i].n / r[i].area, g = enskog_2d(r[i].packing);
        const double sigma = 2.0; /* 2 (r0 + r1), r = 1/2 */
        const double pm = 0.5 * nd * nd * sigma * r[i].v_moller * g;
        const double pr = 0.5 * nd * nd * sigma * r[i].v_rel * g;
        printf("  %-6s packing %g: rate / (1/2 n^2 sigma g <v_Moller>) = %.4f +- %.4f, "
               "/ (... <|v0 - v1|>) = %.4f +- %.4f (g = %.4f, <|w|>/<v_M> = %.4f)\n",
               r[i].frame, r[i].packing, r[i].rate / pm, r[i].se_rate / pm, r[i].rate / pr,
               r[i].se_rate / pr, g, r[i].v_rel / r[i].v_moller);
        /* 4 sigma of the block errors; the pair means come from 10 snapshots of all
         * pairs, whose own scatter (the speeds' distribution fluctuates by ~1/sqrt(N) per
         * snapshot) is allowed as 2e-3 */
        const double tol = 4.0 * r[i].se_rate + 2e-3 * pm;
        if (i == 1) {
            /* uncontracted discs: the non-invariant <|v0 - v1|> rate with the discs'
             * Enskog factor */
            ENSURE_CLOSE(r[i].rate, pr, 1.0, tol);
            ENSURE(r[i].rate - pm > 8.0 * r[i].se_rate); /* and not the Moller one */
        } else {
            /* zmf: the invariant Moller rate, times a density correction between 1 and
             * the discs' Enskog factor (the contracted shapes exclude less area than
             * discs; the dilute limit is the claim, the correction item 3's) */
            ENSURE_MSG(r[i].rate > pm / g - tol && r[i].rate < pm + tol,
                       "zmf rate / (1/2 n^2 sigma <v_M>) = %g outside [1, %g]", r[i].rate * g / pm, g);
            ENSURE(pr - r[i].rate > 8.0 * r[i].se_rate); /* and not the <|w|> one */
        }
    }
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "--paper") == 0)
        big_n = 8, big_t = 4.0;
    gsl_set_error_handler_off();
    RUN_TEST(test_thermometers_dilute);
    RUN_TEST(test_invariant_rate);
    RC_TEST_MAIN_END();
}
