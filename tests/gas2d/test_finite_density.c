/* test_finite_density.c — the engine's thermometer split at finite density against the
 * excluded-volume equilibrium (issue 17 item 3, papers/finite-density.md), 2-D, periodic,
 * c = 1, theta = 0.75 unless said:
 *  - uncontracted discs (sphere frame): no split, as the prediction (a constant excluded
 *    area) says;
 *  - the zmf frame: the split exceeds the prediction s eta (apps/gas/excluded.h) by
 *    many sigma, and stays within a factor 3 of it: what papers/finite-density.md
 *    measures (about 1.9 at this packing) and traces to the collision map, not to the
 *    overlap policy. When the contact-dynamics issue's overlap-free shapes land this is
 *    the check to revisit;
 *  - where they agree: zmf at theta = 0.25 against (1) with the zmf contact's own
 *    forbidden area.
 *  - the covariant frame (the same contacts and shapes, velocities changed per ball on
 *    their glued tubes) at theta = 0.75 against (1): it agrees, where zmf is twice it.
 * `test_finite_density --frame NAME` runs the contracted-frame check for another frame
 * (e.g. covariant, when it exists); `--paper` counts the pairs that overlap at one table
 * time and books the change of sum p.v to each event, overlap-policy collisions apart
 * (minutes, not a test); `--occupancy` only the first (at `--packing`, default 0.1). */
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "excluded.h"
#include "gas_stats.h"
#include "rc_test.h"
#include "relcol/relcol.h"

#define THETA 0.75
enum { NBLK = 10 };
/* the start's temperature (every speed that of Jüttner's <gamma> there) */
static double theta_start = THETA;

/* A periodic gas of n discs (dim 2) or balls (dim 3) of rest radius 1/2 at packing eta,
 * every speed that of Jüttner's <gamma> at THETA, in pairs of opposite momenta (zero total
 * momentum); *box gets the box. */
static int make_gas_d(int dim, const char *frame, size_t n, double eta, uint64_t seed,
                      rc_sim **out, rc_vec3 *box_out)
{
    rc_sim_ball *b = malloc(n * sizeof *b);
    if (!b)
        return RC_ENOMEM;
    rc_sim_gas_def g = {dim, n, 0.5, eta, 0.1, 1.0, 8.0, seed};
    rc_vec3 box;
    int st = rc_sim_gas_init(&g, &box, b);
    const double g0 = jt_mean_gamma(dim, theta_start), p0 = sqrt((g0 - 1.0) * (g0 + 1.0));
    rc_test_rng rng = {seed ^ 0xf1dULL};
    for (size_t i = 0; i + 1 < n; i += 2) {
        double u[3] = {0.0, 0.0, 0.0}, n2;
        do { /* a direction uniform on the circle / sphere, by rejection */
            n2 = 0.0;
            for (int k = 0; k < dim; k++) {
                u[k] = rc_test_range(&rng, -1.0, 1.0);
                n2 += u[k] * u[k];
            }
        } while (!(n2 > 1e-4 && n2 < 1.0));
        const double f = p0 / sqrt(n2);
        b[i].p = rc_v3(f * u[0], f * u[1], f * u[2]);
        b[i + 1].p = rc_v3_scale(-1.0, b[i].p);
        b[i].m = b[i + 1].m = 1.0;
    }
    if (box_out)
        *box_out = box;
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    d.box = box;
    d.c = 1.0;
    d.frame = rc_toi_frame_find(frame);
    for (int k = 0; k < 3; k++)
        d.boundary[k] = RC_SIM_PERIODIC;
    if (st == RC_OK)
        st = d.frame ? rc_sim_create(&d, out) : RC_EINVAL;
    if (st == RC_OK)
        st = rc_sim_set_balls(*out, n, b, NULL);
    free(b);
    return st;
}

static int make_gas(const char *frame, size_t n, double eta, uint64_t seed, rc_sim **out)
{
    return make_gas_d(2, frame, n, eta, seed, out, NULL);
}

/* theta_pv - theta_gamma: mean of NBLK block means over n_snap snapshots spread over
 * t_sample after t_eq, and its standard error. */
static int split_read(const char *frame, size_t n, double eta, double t_eq, double t_sample,
                      int n_snap, uint64_t seed, int latest, double *diff, double *se)
{
    rc_sim *s = NULL;
    int st = make_gas(frame, n, eta, seed, &s);
    if (st == RC_OK)
        st = rc_sim_advance(s, t_eq, 0);
    const int per = n_snap / NBLK;
    double bd[NBLK];
    for (int k = 0; k < NBLK && st == RC_OK; k++) {
        double sg = 0.0, spv = 0.0, cnt = 0.0;
        for (int j = 0; j < per && st == RC_OK; j++) {
            st = rc_sim_advance(s, t_eq + t_sample * (k * per + j + 1) / (double)n_snap, 0);
            for (size_t i = 0; i < n && st == RC_OK; i++) {
                rc_sim_ball q;
                st = latest ? rc_sim_get_ball_latest(s, i, &q) : rc_sim_get_ball(s, i, &q);
                const double u = rc_v3_norm2(q.p), gm = sqrt(1.0 + u);
                sg += gm;
                spv += u / gm;
                cnt += 1.0;
            }
        }
        bd[k] = 0.5 * spv / cnt - jt_theta_from_gamma(2, sg / cnt);
    }
    rc_sim_free(&s);
    if (st == RC_OK)
        *diff = gs_mean_se(bd, NBLK, se);
    return st;
}

/* The same from the complete delayed table-time slices (rc_sim_slice_*): snapshot j's
 * slice asked for while the engine is at snapshot j - 1, each read once final, in order
 * (as relcol-gas --readout slice). */
static int split_slice(const char *frame, size_t n, double eta, double t_eq, double t_sample,
                       int n_snap, uint64_t seed, double *diff, double *se)
{
    rc_sim *s = NULL;
    int st = make_gas(frame, n, eta, seed, &s);
    if (st == RC_OK)
        st = rc_sim_advance(s, t_eq, 0);
    const int per = n_snap / NBLK;
    uint32_t *id = malloc((size_t)n_snap * sizeof *id);
    double sg[NBLK] = {0}, spv[NBLK] = {0}, bd[NBLK];
    int next = 0;
    if (!id)
        st = RC_ENOMEM;
    for (int j = 0; j < n_snap && st == RC_OK; j++) {
        const double t = t_eq + t_sample * (j + 1) / (double)n_snap;
        st = rc_sim_slice_request(s, t, &id[j]);
        if (st == RC_OK)
            st = rc_sim_advance(s, t, 0);
        /* the final ones in order; after the last snapshot, on until all are */
        while (st == RC_OK && next <= j) {
            rc_sim_slice_info in;
            const int r = rc_sim_slice_ready(s, id[next], &in);
            if (r < 0) {
                st = r;
            } else if (r == 0) {
                if (j < n_snap - 1)
                    break;
                st = rc_sim_advance(s, in.t_final, 0);
            } else {
                for (size_t i = 0; i < n && st == RC_OK; i++) {
                    rc_sim_ball q;
                    st = rc_sim_slice_get(s, id[next], i, &q);
                    const double u = rc_v3_norm2(q.p), gm = sqrt(1.0 + u);
                    sg[next / per] += gm;
                    spv[next / per] += u / gm;
                }
                rc_sim_slice_release(s, id[next]);
                next++;
            }
        }
    }
    free(id);
    rc_sim_free(&s);
    for (int k = 0; k < NBLK; k++) {
        const double cnt = (double)per * (double)n;
        bd[k] = 0.5 * spv[k] / cnt - jt_theta_from_gamma(2, sg[k] / cnt);
    }
    if (st == RC_OK)
        *diff = gs_mean_se(bd, NBLK, se);
    return st;
}

/* (the table-time picture of every collision decided so far: rc_sim_get_ball) */
static int split(const char *frame, size_t n, double eta, double t_eq, double t_sample,
                 int n_snap, uint64_t seed, double *diff, double *se)
{
    return split_read(frame, n, eta, t_eq, t_sample, n_snap, seed, 0, diff, se);
}

/* The predicted slope s = d(theta_pv - theta_gamma)/d eta (2-D, THETA). */
static double predicted_slope(void)
{
    gsl_integration_glfixed_table *glt = gsl_integration_glfixed_table_alloc(8);
    const ex_quad q = {512, glt, 0};
    ex_coef c;
    const int st = ex_coefficients(2, THETA, 1, 12, 32, &q, &c);
    gsl_integration_glfixed_table_free(glt);
    return st == 0 ? c.slope : NAN;
}

static const char *contracted_frame = "zmf";
static double occ_packing = 0.1; /* --packing: of the occupancy count */

/* N = 500 at packing 0.25, ~150 collisions per ball sampled: block errors ~2e-4 against
 * a predicted split of 2.1e-3 (papers/finite-density.md measures 3.97e-3 +- 0.08e-3 at
 * N = 4000). Tolerances: 4 sigma (a fixed-seed check), and the block errors may be
 * understated by correlations between blocks (the app's sphere control reads 3.9 sigma
 * at eta = 0.05), so the sphere check also allows 2e-4 (that control's offset). */
static void test_split(void)
{
    const double eta = 0.25, s = predicted_slope();
    ENSURE(isfinite(s) && s > 0.0);
    double dz, sez, ds, ses;
    ENSURE(split("sphere", 500, eta, 50.0, 1200.0, 200, 5, &ds, &ses) == RC_OK);
    printf("  sphere: theta_pv - theta_gamma = %+.5f +- %.5f (predicted 0)\n", ds, ses);
    ENSURE_CLOSE(ds, 0.0, 1.0, 4.0 * ses + 2e-4);
    const int st = split(contracted_frame, 500, eta, 50.0, 1200.0, 200, 6, &dz, &sez);
    if (st == RC_EINVAL && !rc_toi_frame_find(contracted_frame)) {
        printf("  frame %s: not in this build, skipped\n", contracted_frame);
        return;
    }
    ENSURE(st == RC_OK);
    printf("  %s: theta_pv - theta_gamma = %+.5f +- %.5f, excluded-volume prediction "
           "%.5f (measured / predicted %.2f)\n", contracted_frame, dz, sez, s * eta,
           dz / (s * eta));
    ENSURE_MSG(dz - s * eta > 4.0 * sez, "split %g not above the prediction %g", dz, s * eta);
    ENSURE_MSG(dz < 3.0 * s * eta, "split %g above 3 x the prediction %g", dz, s * eta);
}

/* Where the engine meets a prediction: 2-D zmf at theta = 0.25, packing 0.25, against
 * (1) with the zmf contact's own forbidden area (ex_area_zmf_2d), s = 0.00173
 * (papers/finite-density.md measures 0.00045 +- 0.00003 at N = 4000, 1.04 +- 0.07 of
 * s eta). N = 2000, ~250 collisions per ball sampled: block errors ~5e-5 against the
 * predicted 4.3e-4. The prediction by a coarse rule (6 speeds, 12 angles, 96 normals:
 * within 3 % of the converged 0.00173, far below the statistical error). 4 sigma plus that
 * 3 %: a fixed-seed check. The table-frame sum's prediction (0.00036) is not excluded by
 * this size; the point is that the split is not twice the prediction, as at theta 0.75. */
static void test_zmf_agrees_cold(void)
{
    const double eta = 0.25;
    const ex_quad q = {96, NULL, 1};
    ex_coef c;
    ENSURE(ex_coefficients(2, 0.25, 1, 6, 12, &q, &c) == 0);
    ENSURE_REL(c.slope, 0.00173, 0.03);
    theta_start = 0.25;
    double dz, sez;
    const int st = split("zmf", 2000, eta, 60.0, 600.0, 100, 8, &dz, &sez);
    theta_start = THETA;
    ENSURE(st == RC_OK);
    printf("  zmf theta 0.25: theta_pv - theta_gamma = %+.5f +- %.5f, zmf-set prediction %.5f "
           "(measured / predicted %.2f)\n", dz, sez, c.slope * eta, dz / (c.slope * eta));
    ENSURE_CLOSE(dz, c.slope * eta, 1.0, 4.0 * sez + 0.03 * c.slope * eta);
}

/* The covariant frame (the zmf frame's contact event and shapes, each ball's velocity
 * changed at its own event of its glued world tube instead of both at one table time),
 * 2-D, theta = 0.75, packing 0.2, against (1) with the table-frame excluded area, s eta =
 * 0.00168. Read on each ball's latest segment the split is of the order of (1) and moves
 * with the engine's rules: papers/finite-density.md section 5.1 has 0.89 +- 0.05 of it at
 * N = 4000 before overlaps the frame reported from too late a reference became contacts
 * (papers/covariant-frame.md section 3), 1.04, 0.91 and 1.05 with earlier rules, 0.62 +-
 * 0.11 here now (chains undone too: 0.58 +- 0.03 at N = 4000); the zmf frame 1.95. So no agreement with (1) is claimed: asserted are a
 * positive split on the latest segments, 4 errors above zero and below 1.5 of (1), which
 * the zmf frame's is not (the test tells the two frames apart), and, read from complete
 * slices, one that is not (1)'s. N = 2000, ~150 collisions per ball sampled: block
 * errors 1e-4 to 2e-4; fixed seed. */
/* Read with rc_sim_get_ball_latest: each collision's change at its contact event's table
 * time, for both balls (the read-out the paper's numbers were made with, and the only one
 * of the engine's two that treats a ball whose kink comes before its contact event and
 * one whose kink comes after it alike). rc_sim_get_ball's table-time picture applies a
 * kink after its contact event at the kink but one before it still at the contact event
 * (not processed yet), so it selects balls by the sign of their kink's lead: its split is
 * printed beside, not asserted (papers/covariant-frame.md, section 1). */
static void test_covariant_agrees(void)
{
    const double eta = 0.2, s = predicted_slope();
    double dc, sec, dt, set;
    int st = split_read("covariant", 2000, eta, 50.0, 600.0, 100, 9, 1, &dc, &sec);
    ENSURE(st == RC_OK);
    st = split("covariant", 2000, eta, 50.0, 600.0, 100, 9, &dt, &set);
    ENSURE(st == RC_OK);
    printf("  covariant: theta_pv - theta_gamma = %+.5f +- %.5f, excluded-volume prediction "
           "%.5f (measured / predicted %.2f); read at the decided kinks %+.5f +- %.5f\n", dc,
           sec, s * eta, dc / (s * eta), dt, set);
    ENSURE(dc > 4.0 * sec && dc < 1.5 * s * eta);
    /* ... and read from the complete table-time slices the split is not (1)'s:
     * papers/finite-density.md section 5.1 measures -0.51 +- 0.03 of s eta at N = 4000
     * (-0.23 ... -0.51 at every packing), against 0.58 on the latest segments. Asserted: below half of (1), and below the latest segments' split by 4
     * of the two errors combined (a read-out that fell back to the latest segments, or
     * a slice that missed kinks, would fail) */
    double dsl = NAN, sesl = NAN;
    ENSURE(split_slice("covariant", 2000, eta, 50.0, 600.0, 100, 9, &dsl, &sesl) == RC_OK);
    printf("  covariant, complete slices: theta_pv - theta_gamma = %+.5f +- %.5f (%.2f of "
           "the prediction)\n", dsl, sesl, dsl / (s * eta));
    ENSURE(dsl < 0.5 * s * eta);
    ENSURE(dc - dsl > 4.0 * sqrt(sec * sec + sesl * sesl));
}

/* --paper: step the engine one event at a time and book the change of sum p.v (in
 * theta_pv units, per unit time) to contact collisions and to overlap-policy ones
 * (rc_sim_diag.overlaps grew), with the standard error of each sum. */
static void paper(int dim, double t_s)
{
    const size_t n = 500;
    const double eta = 0.1, t_eq = 100.0;
    rc_sim *s = NULL;
    int st = make_gas_d(dim, contracted_frame, n, eta, 1, &s, NULL);
    if (st == RC_OK)
        st = rc_sim_advance(s, t_eq, 0);
    rc_sim_diag dg;
    if (st == RC_OK)
        st = rc_sim_diagnostics(s, &dg);
    uint64_t cprev = dg.collisions, oprev = dg.overlaps;
    double prev = 0.0, sum[2] = {0.0, 0.0}, sum2[2] = {0.0, 0.0};
    long cnt[2] = {0, 0};
    for (int first = 1; st == RC_OK && rc_sim_time(s) < t_eq + t_s; first = 0) {
        if (!first && (st = rc_sim_advance(s, t_eq + t_s, 1)) != RC_OK)
            break;
        if ((st = rc_sim_diagnostics(s, &dg)) != RC_OK)
            break;
        if (!first && dg.collisions == cprev)
            continue;
        double spv = 0.0;
        for (size_t i = 0; i < n && st == RC_OK; i++) {
            rc_sim_ball q;
            st = rc_sim_get_ball(s, i, &q);
            const double u = rc_v3_norm2(q.p);
            spv += u / sqrt(1.0 + u);
        }
        if (!first) {
            const int k = dg.overlaps > oprev;
            sum[k] += spv - prev;
            sum2[k] += (spv - prev) * (spv - prev);
            cnt[k]++;
        }
        prev = spv;
        cprev = dg.collisions;
        oprev = dg.overlaps;
    }
    rc_sim_free(&s);
    if (st != RC_OK) {
        printf("engine error %d\n", st);
        return;
    }
    const double u = (double)dim * (double)n * t_s;
    printf("%d-D %s, theta %g, packing %g, N %zu, t %g: %ld contact events, %ld overlap-policy "
           "events\nd theta_pv/dt from contact events %+.4e +- %.2e, from overlap-policy "
           "events %+.4e +- %.2e\n", dim, contracted_frame, THETA, eta, n, t_s, cnt[0], cnt[1],
           sum[0] / u, sqrt(sum2[0]) / u, sum[1] / u, sqrt(sum2[1]) / u);
}

/* --paper, second part: how many pairs overlap at one table time, as a fraction of the
 * neighbours an uncorrelated gas would put in the excluded regions, n <V>/2 per ball
 * ((A) of papers/finite-density.md says none). Table-frame shapes, the Perram-Wertheim
 * test of excluded.h, nearest images; 20 snapshots after t_eq, t_step apart. */
static void occupancy(int dim, double eta)
{
    const size_t n = 500;
    const double t_eq = 40.0 / eta, t_step = 2.0 / eta;
    rc_sim *s = NULL;
    rc_vec3 box;
    int st = make_gas_d(dim, contracted_frame, n, eta, 3, &s, &box);
    if (st == RC_OK)
        st = rc_sim_advance(s, t_eq, 0);
    rc_sim_ball *b = malloc(n * sizeof *b);
    const double L[3] = {box.x, box.y, box.z};
    long over = 0, snaps = 0;
    for (int k = 0; st == RC_OK && b && k < 20; k++) {
        st = rc_sim_advance(s, t_eq + t_step * (k + 1), 0);
        for (size_t i = 0; i < n && st == RC_OK; i++)
            st = rc_sim_get_ball(s, i, &b[i]);
        for (size_t i = 0; i < n && st == RC_OK; i++) {
            const double xi[3] = {b[i].x.x, b[i].x.y, b[i].x.z};
            const double Ei = sqrt(1.0 + rc_v3_norm2(b[i].p));
            const double bi[3] = {b[i].p.x / Ei, b[i].p.y / Ei, b[i].p.z / Ei};
            double Pi[3][3];
            ex_shape(0.5, bi, Pi);
            for (size_t j = i + 1; j < n; j++) {
                const double xj[3] = {b[j].x.x, b[j].x.y, b[j].x.z};
                double x[3] = {0.0, 0.0, 0.0}, r2 = 0.0;
                for (int a = 0; a < dim; a++) {
                    x[a] = xj[a] - xi[a];
                    x[a] -= L[a] * round(x[a] / L[a]);
                    r2 += x[a] * x[a];
                }
                if (r2 >= 1.0) /* bounding spheres of radius 1/2 apart */
                    continue;
                const double Ej = sqrt(1.0 + rc_v3_norm2(b[j].p));
                const double bj[3] = {b[j].p.x / Ej, b[j].p.y / Ej, b[j].p.z / Ej};
                double Pj[3][3];
                ex_shape(0.5, bj, Pj);
                /* shallower than the engine's round-off scale is touching, not overlap:
                 * shrink both shapes by 1e-9 */
                for (int a = 0; a < 3; a++)
                    for (int c = 0; c < 3; c++)
                        Pi[a][c] *= 1.0 - 2e-9, Pj[a][c] *= 1.0 - 2e-9;
                over += ex_pw_overlap(dim, Pi, Pj, x);
                ex_shape(0.5, bi, Pi);
            }
        }
        snaps++;
    }
    rc_sim_free(&s);
    free(b);
    if (st != RC_OK || !snaps) {
        printf("engine error %d\n", st);
        return;
    }
    gsl_integration_glfixed_table *glt = gsl_integration_glfixed_table_alloc(48);
    const ex_quad q = {512, glt, 0};
    ex_coef c;
    ex_coefficients(dim, THETA, 1, 12, dim == 2 ? 32 : 12, &q, &c);
    gsl_integration_glfixed_table_free(glt);
    /* n <V>/2 per ball: eta <V>/v_d / 2 */
    const double expect = eta * c.mean_v / 2.0, per_ball = 2.0 * over / ((double)n * snaps);
    printf("%d-D %s, theta %g, packing %g, N %zu, %ld snapshots: %.5f overlapping neighbours "
           "per ball, %.4f of the n <V>/2 = %.4f an uncorrelated gas puts in the excluded "
           "regions\n", dim, contracted_frame, THETA, eta, n, snaps, per_ball,
           per_ball / expect, expect);
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    int do_paper = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--paper") == 0)
            do_paper = 1;
        else if (strcmp(argv[i], "--occupancy") == 0)
            do_paper = 2;
        else if (strcmp(argv[i], "--frame") == 0 && i + 1 < argc)
            contracted_frame = argv[++i];
        else if (strcmp(argv[i], "--packing") == 0 && i + 1 < argc)
            occ_packing = atof(argv[++i]);
    }
    if (do_paper) {
        occupancy(2, occ_packing);
        occupancy(3, occ_packing);
        if (do_paper == 1) {
            paper(2, 60000.0);
            paper(3, 30000.0);
        }
        return 0;
    }
    RUN_TEST(test_split);
    RUN_TEST(test_zmf_agrees_cold);
    RUN_TEST(test_covariant_agrees);
    RC_TEST_MAIN_END();
}
