/* test_tube.c — relcol-shock's tube against the Kn -> inf reference (papers/shock-tube.md,
 * sections 4-6): the free-streaming moments' own checks (balls conserved with walls, the
 * t -> 0 limit, c = 100 against Maxwell), the Juttner sampler's moments against the
 * Juttner law (<gamma> and equipartition <p.v> = d T within 4 standard errors), and
 * tubes of nearly point-like balls (r = 1e-4: no collisions in the run) against free
 * streaming in 2-D and 3-D, c = inf and c = 1, halves at rest and moving (colliding streams): each raw moment's chi^2 over the bins with
 * its p-value above 1e-3, and the tube's seeds independent. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "app.h"
#include "juttner.h"
#include "rc_test.h"
#include "shock_run.h"

static void test_reference(void)
{
    for (int d = 2; d <= 3; d++) {
        fs_def a = {d, INFINITY, 400.0, 150.0, {0.5, 0.125}, {2.0, 0.8}, {0.0, 0.0}}, b = a;
        b.c = 100.0;
        const double total = a.n[0] * a.x0 + a.n[1] * (a.L - a.x0);
        for (double t = 20.0; t < 1000.0; t *= 2.5) {
            /* balls and energy conserved between the walls (trapezoid over 2000 points) */
            double sum = 0.0, sk = 0.0, sk0 = 0.0;
            for (int i = 0; i <= 2000; i++) {
                const double x = a.L * i / 2000.0, w = (i == 0 || i == 2000) ? 0.5 : 1.0;
                sh_mom m, m0;
                ENSURE(fs_moments(&a, x, t, &m) == 0);
                ENSURE(fs_moments(&a, x, 0.0, &m0) == 0);
                sum += w * m.N0 * a.L / 2000.0;
                sk += w * m.K * a.L / 2000.0;
                sk0 += w * m0.K * a.L / 2000.0;
            }
            ENSURE_REL(sum, total, 2e-3); /* the step at x0 costs the trapezoid O(dx) at t -> 0 */
            ENSURE_REL(sk, sk0, 2e-3);
            for (double x = 10.0; x < a.L; x += 37.0) {
                sh_mom m1, m2;
                ENSURE(fs_moments(&a, x, t, &m1) == 0);
                ENSURE(fs_moments(&b, x, t, &m2) == 0);
                /* relativistic corrections at theta = T/c^2 = 2e-4: relative 1e-3 allowed */
                ENSURE_CLOSE(m2.N0, m1.N0, 1e-3, a.n[0]);
                ENSURE_CLOSE(m2.g, m1.g, 1e-3, a.n[0] * sqrt(a.T[0]));
                ENSURE_CLOSE(m2.Pxx, m1.Pxx, 1e-3, a.n[0] * a.T[0]);
                ENSURE_CLOSE(m2.K, m1.K, 1e-3, a.n[0] * a.T[0]);
                ENSURE_CLOSE(m2.Pyy, m1.Pyy, 1e-3, a.n[0] * a.T[0]);
            }
        }
        /* t -> 0+: the halves themselves; far from the membrane at small t too */
        sh_mom m;
        ENSURE(fs_moments(&b, 50.0, 1e-6, &m) == 0);
        ENSURE_REL(m.N0, a.n[0], 1e-9);
        ENSURE_REL(m.Pyy, a.n[0] * a.T[0], 1e-9);
        ENSURE(fs_moments(&b, 300.0, 1e-6, &m) == 0);
        ENSURE_REL(m.N0, a.n[1], 1e-9);
        ENSURE_REL(m.Pxx, a.n[1] * a.T[1], 1e-9);
        double q[SH_NDERIVED];
        sh_derive(d, b.c, &m, q);
        ENSURE_REL(q[SH_TE], a.T[1], 1e-6);
        ENSURE_REL(q[SH_TP], a.T[1], 1e-9);
    }
}

/* moving halves (v_L = 0.6 c_s-ish right, v_R left; c = inf, 100 and 1): balls (lab density
 * n W) and energy conserved between the walls, the t -> 0 limit the boosted halves, c = 100
 * against the drifting Maxwell */
static void test_reference_moving(void)
{
    for (int d = 2; d <= 3; d++)
        for (int k = 0; k < 3; k++) {
            const double c = k == 0 ? INFINITY : k == 1 ? 100.0 : 1.0;
            const double T0 = k == 2 ? 0.5 : 2.0, T1 = 0.4 * T0;
            const double v0 = k == 2 ? 0.4 : 0.8, v1 = k == 2 ? -0.3 : -0.6;
            fs_def a = {d, c, 400.0, 150.0, {0.5, 0.125}, {T0, T1}, {v0, v1}};
            const double W0 = isinf(c) ? 1.0 : 1.0 / sqrt(1.0 - v0 * v0 / (c * c));
            const double W1 = isinf(c) ? 1.0 : 1.0 / sqrt(1.0 - v1 * v1 / (c * c));
            const double total = a.n[0] * W0 * a.x0 + a.n[1] * W1 * (a.L - a.x0);
            /* two times (before and after the fronts reach the walls), 1000 points: the
             * quadratures at finite c are what this test's time goes to */
            /* the start's energy: each half's uniform K over its length (no step to sample) */
            sh_mom kl, kr;
            ENSURE(fs_moments(&a, 0.5 * a.x0, 0.0, &kl) == 0);
            ENSURE(fs_moments(&a, 0.5 * (a.x0 + a.L), 0.0, &kr) == 0);
            const double sk0 = kl.K * a.x0 + kr.K * (a.L - a.x0);
            for (double t = 20.0; t < 600.0; t *= 15.0) {
                double sum = 0.0, sk = 0.0;
                for (int i = 0; i <= 1000; i++) {
                    const double x = a.L * i / 1000.0, w = (i == 0 || i == 1000) ? 0.5 : 1.0;
                    sh_mom m;
                    ENSURE(fs_moments(&a, x, t, &m) == 0);
                    sum += w * m.N0 * a.L / 1000.0;
                    sk += w * m.K * a.L / 1000.0;
                }
                ENSURE_MSG(fabs(sum / total - 1.0) < 2e-3, "d %d c %g t %g: balls %g of %g", d, c, t, sum, total);
                ENSURE_MSG(fabs(sk / sk0 - 1.0) < 2e-3, "d %d c %g t %g: K %g of %g", d, c, t, sk, sk0);
            }
            /* t -> 0+: each half's lab moments, N0 = n W and Nx = v N0 */
            sh_mom m;
            ENSURE(fs_moments(&a, 50.0, 1e-6, &m) == 0);
            ENSURE_REL(m.N0, a.n[0] * W0, 1e-9);
            ENSURE_REL(m.Nx, v0 * a.n[0] * W0, 1e-8);
            ENSURE(fs_moments(&a, 300.0, 1e-6, &m) == 0);
            ENSURE_REL(m.N0, a.n[1] * W1, 1e-9);
            ENSURE_REL(m.Nx, v1 * a.n[1] * W1, 1e-8);
            double q[SH_NDERIVED];
            sh_derive(d, c, &m, q);
            ENSURE_REL(q[SH_V], v1, 1e-8);
            ENSURE_REL(q[SH_N], a.n[1], 1e-8);
            ENSURE_REL(q[SH_TP], a.T[1], 1e-7);
            if (k == 1) { /* c = 100 against the drifting Maxwell */
                fs_def b = a;
                b.c = INFINITY;
                for (double x = 10.0; x < a.L; x += 37.0) {
                    sh_mom m1, m2;
                    ENSURE(fs_moments(&b, x, 80.0, &m1) == 0);
                    ENSURE(fs_moments(&a, x, 80.0, &m2) == 0);
                    ENSURE_CLOSE(m2.N0, m1.N0, 1e-3, a.n[0]);
                    ENSURE_CLOSE(m2.g, m1.g, 1e-3, a.n[0] * sqrt(T0));
                    ENSURE_CLOSE(m2.Pxx, m1.Pxx, 1e-3, a.n[0] * T0);
                    ENSURE_CLOSE(m2.K, m1.K, 1e-3, a.n[0] * T0);
                }
            }
        }
}

static void test_sampler(void)
{
    for (int d = 2; d <= 3; d++)
        for (int k = 0; k < 3; k++) {
            const double c = k == 0 ? INFINITY : k == 1 ? 1.0 : 4.0, T = k == 1 ? 0.7 : 1.5;
            rc_rng r = {12345 + 7 * d + k};
            const int N = 200000;
            double sg = 0.0, sg2 = 0.0, spv = 0.0, spv2 = 0.0;
            for (int i = 0; i < N; i++) {
                const rc_vec3 p = sh_juttner_momentum(d, c, T, 0.0, &r);
                const double p2 = p.x * p.x + p.y * p.y + p.z * p.z;
                const double M = isinf(c) ? 1.0 : sqrt(1.0 + p2 / (c * c));
                const double e = p2 / (M + 1.0); /* E - m c^2 */
                sg += e, sg2 += e * e, spv += p2 / M, spv2 += p2 * p2 / (M * M);
            }
            const double me = sg / N, se = sqrt((sg2 / N - me * me) / N);
            const double mpv = spv / N, spe = sqrt((spv2 / N - mpv * mpv) / N);
            const double want = isinf(c) ? 0.5 * d * T : (jt_mean_gamma(d, T / (c * c)) - 1.0) * c * c;
            ENSURE_MSG(fabs(me - want) < 4.0 * se, "d %d c %g: <E - m> %g want %g +- %g", d, c, me, want, se);
            ENSURE_MSG(fabs(mpv - d * T) < 4.0 * spe, "d %d c %g: <p.v> %g want %g +- %g", d, c, mpv, d * T, spe);
        }
}

static void tube_case(int dim, double c, int moving)
{
    sh_opts o;
    memset(&o, 0, sizeof o);
    sh_tube *t = &o.tube;
    t->dim = dim, t->c = c, t->r = 1e-4;
    /* wide and dilute: the engine's cells, and so its cell crossings, scale with the width */
    t->box.x = 600.0, t->box.y = dim == 3 ? 40.0 : 100.0, t->box.z = dim == 3 ? 40.0 : 0.0;
    t->x0 = 300.0;
    t->n[0] = dim == 3 ? 0.01 : 0.05, t->n[1] = 0.5 * t->n[0];
    t->T[0] = isinf(c) ? 2.0 : 0.5, t->T[1] = 0.5 * t->T[0];
    if (moving) /* colliding streams, the left one the faster */
        t->v[0] = isinf(c) ? 0.8 : 0.4, t->v[1] = isinf(c) ? -0.6 : -0.3;
    o.nt = 2, o.times[0] = 60.0, o.times[1] = 200.0;
    o.bins = 40, o.seeds = 8, o.seed = 3;
    sh_result r;
    char err[APP_ERR_LEN];
    int rc = sh_run(&o, &r, 0, err);
    ENSURE_MSG(rc == 0, "%s", err);
    if (rc)
        return;
    /* point-like: a ball meets another with probability ~ (run length) / (mean free path) */
    ENSURE_MSG(r.collisions < r.nballs * o.seeds / 100, "%llu collisions", (unsigned long long)r.collisions);
    static const char *const nm[3] = {"N0", "g", "Pxx"};
    for (int j = 0; j < r.nt; j++)
        for (int q = 0; q < 3; q++) {
            ENSURE(r.dof[j][q] == o.bins);
            ENSURE_MSG(r.pval[j][q] > 1e-3, "%d-D c %g v %g %g t %g %s: chi2 %g / %d, p %g", dim,
                       c, t->v[0], t->v[1], o.times[j], nm[q], r.chi2[j][q], r.dof[j][q],
                       r.pval[j][q]);
        }
    sh_result_free(&r);
}

static void test_free_streaming(void)
{
    for (int moving = 0; moving < 2; moving++) {
        tube_case(3, INFINITY, moving);
        tube_case(2, INFINITY, moving);
        tube_case(3, 1.0, moving);
        tube_case(2, 1.0, moving);
    }
}

/* two seeds give different starts, one seed the same start */
static void test_seeds(void)
{
    sh_tube t = {3, INFINITY, {100.0, 10.0, 10.0}, 50.0, 0.5, {0.05, 0.02}, {1.0, 1.0}, {0.0, 0.0}, NULL, NULL};
    rc_sim_ball *a = NULL, *b = NULL, *a2 = NULL;
    size_t na, nb, na2;
    char err[APP_ERR_LEN];
    ENSURE(sh_tube_balls(&t, 1, &a, &na, err) == 0);
    ENSURE(sh_tube_balls(&t, 2, &b, &nb, err) == 0);
    ENSURE(sh_tube_balls(&t, 1, &a2, &na2, err) == 0);
    ENSURE(na == nb && na == na2 && na == sh_tube_count(&t, 0) + sh_tube_count(&t, 1));
    int same = 0, ok_side = 1;
    for (size_t i = 0; i < na; i++) {
        for (size_t j = 0; j < nb; j++)
            same += a[i].x.x == b[j].x.x;
        ENSURE(memcmp(&a[i], &a2[i], sizeof a[i]) == 0);
        const int left = i < sh_tube_count(&t, 0);
        ok_side &= left ? a[i].x.x + a[i].r <= t.x0 : a[i].x.x - a[i].r >= t.x0;
    }
    ENSURE(same == 0);
    ENSURE(ok_side);
    free(a), free(b), free(a2);
}

int main(void)
{
    gsl_set_error_handler_off();
    RUN_TEST(test_reference);
    RUN_TEST(test_reference_moving);
    RUN_TEST(test_sampler);
    RUN_TEST(test_seeds);
    RUN_TEST(test_free_streaming);
    RC_TEST_MAIN_END();
}
