/* test_glue — a ball's world tube glued on H through a collision (rc_glue,
 * papers/glued-tube.md): the incoming and outgoing cylinders have the same section on
 * H, so the window H takes to sweep the ball is the same computed from either side, and
 * a point on H is in one cylinder exactly when it is in the other; the shape before the
 * window is the incoming one and after it the outgoing one; the classical limit has no
 * window; bad inputs are refused. */
#define _USE_MATH_DEFINES
#include <math.h>
#include <stdlib.h>

#include "glue_sample.h"
#include "rc_test.h"
#include "sphere_in.h"
#include "relcol/relcol.h"

static double urand(unsigned *s) { return (double)rand_r(s) / ((double)RAND_MAX + 1.0); }

static rc_vec3 rvec(unsigned *s, double a, int dim)
{
    return rc_v3(a * (2 * urand(s) - 1), a * (2 * urand(s) - 1), dim == 3 ? a * (2 * urand(s) - 1) : 0.0);
}

/* A random momentum of speed below 0.95 c (c = 1, m = 1 gives |p| = gamma v). */
static rc_vec3 rmom(unsigned *s, int dim)
{
    rc_vec3 v;
    do
        v = rvec(s, 0.95, dim);
    while (rc_v3_norm2(v) >= 0.95 * 0.95);
    return rc_v3_scale(1.0 / sqrt(1.0 - rc_v3_norm2(v)), v);
}

/* Rest-frame squared length of d in a ball of state (m, p), c = 1, over r^2. */
static double form(const rc_particle *b, double r, rc_vec3 d)
{
    const double pd = rc_v3_dot(b->p, d) / b->m; /* gamma beta . d */
    return (rc_v3_norm2(d) + pd * pd) / (r * r);
}

static void test_sections_match(void)
{
    unsigned seed = 16;
    int boundary_skips = 0;
    for (int trial = 0; trial < 400; trial++) {
        const int dim = 2 + trial % 2;
        const double r = 0.5 + urand(&seed);
        rc_particle in = {1.0, rmom(&seed, dim)}, out = {1.0 + 0.3 * urand(&seed), rmom(&seed, dim)};
        const rc_vec3 xc = rvec(&seed, 3.0, dim), X = rc_v3_add(xc, rvec(&seed, r, dim));
        const double tx = 5.0 * urand(&seed);
        rc_glue g;
        ENSURE(rc_glue_make(1.0, r, &in, &out, tx, xc, X, &g) == RC_OK);
        /* the window from the outgoing side: D = h_out(kappa) / (1 - kappa.v_out) */
        const double k = rc_v3_norm(g.kappa);
        const rc_vec3 kh = rc_v3_scale(1.0 / k, g.kappa);
        const double Din = rc_toi_support(&g.in, kh) * k / (1.0 - rc_v3_dot(g.kappa, g.v_in));
        const double Dout = rc_toi_support(&g.out, kh) * k / (1.0 - rc_v3_dot(g.kappa, g.v_out));
        /* (a few roundings of terms of size r: relative 1e-13) */
        ENSURE_REL(Dout, Din, 1e-13);
        ENSURE_REL(g.t_last - g.t_c, Din, 1e-13);
        ENSURE(k < 1.0); /* H is spacelike: it sweeps faster than light */
        /* the centre event lies on H */
        ENSURE_CLOSE(g.t_c - g.t_x, rc_v3_dot(g.kappa, rc_v3_sub(g.x_c, X)), 1e-14, 10.0);
        /* points of H: in the incoming cylinder exactly when in the outgoing one */
        for (int j = 0; j < 50; j++) {
            const rc_vec3 y = rc_v3_add(g.x_c, rvec(&seed, 1.2 * r, dim));
            const double t = tx + rc_v3_dot(g.kappa, rc_v3_sub(y, X));
            const double fi = form(&in, r, rc_v3_sub(y, rc_v3_axpy(g.x_c, t - g.t_c, g.v_in)));
            const double fo = form(&out, r, rc_v3_sub(y, rc_v3_axpy(g.x_c, t - g.t_c, g.v_out)));
            /* the two rest-frame distances are equal (y.u_in = -y.u_out on H) */
            ENSURE_CLOSE(fo, fi, 1e-12, 1.0 + fi);
            if (fabs(fi - 1.0) < 1e-9) {
                boundary_skips++;
                continue;
            }
            ENSURE((fi <= 1.0) == (fo <= 1.0));
        }
        /* before the window the section is the incoming shape, after it the outgoing */
        for (int j = 0; j < 50; j++) {
            const rc_vec3 d = rvec(&seed, 1.1 * r, dim);
            const double tb = g.t_first - 1e-9 - urand(&seed), ta = g.t_last + 1e-9 + urand(&seed);
            const rc_vec3 yb = rc_v3_add(rc_v3_axpy(g.x_c, tb - g.t_c, g.v_in), d);
            const rc_vec3 ya = rc_v3_add(rc_v3_axpy(g.x_c, ta - g.t_c, g.v_out), d);
            ENSURE(rc_glue_inside(&g, tb, yb) == (form(&in, r, d) <= 1.0));
            ENSURE(rc_glue_inside(&g, ta, ya) == (form(&out, r, d) <= 1.0));
        }
    }
    ENSURE(boundary_skips < 10);
}

/* Inside the window both parts show: a point the incoming shape holds and one only the
 * outgoing holds, at the middle of the window (a ball moving fast, turned round). */
static void test_window_mixes(void)
{
    rc_particle in = {1.0, rc_v3(1.5, 0.3, 0)}, out = {1.0, rc_v3(-0.2, 1.4, 0)};
    rc_glue g;
    ENSURE(rc_glue_make(1.0, 1.0, &in, &out, 0.0, rc_v3(0, 0, 0), rc_v3(1, 0, 0), &g) == RC_OK);
    ENSURE(g.t_first < g.t_c && g.t_c < g.t_last);
    /* at t_c, H passes through the centre: points ahead of it along kappa are incoming */
    const rc_vec3 kh = rc_v3_scale(1.0 / rc_v3_norm(g.kappa), g.kappa);
    const double t = g.t_c;
    const rc_vec3 c = g.x_c;
    int seen_in = 0, seen_out = 0;
    for (int j = -40; j <= 40; j++)
        for (int k = -40; k <= 40; k++) {
            const rc_vec3 y = rc_v3_add(c, rc_v3(j / 40.0, k / 40.0, 0));
            const int ahead = rc_v3_dot(kh, rc_v3_sub(y, c)) > 1e-9;
            const int behind = rc_v3_dot(kh, rc_v3_sub(y, c)) < -1e-9;
            const int fi = form(&in, 1.0, rc_v3_sub(y, c)) <= 1.0;
            const int fo = form(&out, 1.0, rc_v3_sub(y, c)) <= 1.0;
            const int s = rc_glue_inside(&g, t, y);
            if (ahead) {
                ENSURE(s == fi);
                seen_in += fi && !fo;
            }
            if (behind) {
                ENSURE(s == fo);
                seen_out += fo && !fi;
            }
        }
    ENSURE(seen_in > 0 && seen_out > 0);
}

static void test_classical(void)
{
    rc_particle in = {2.0, rc_v3(3, 1, 0)}, out = {2.0, rc_v3(-1, 2, 0)};
    rc_glue g;
    ENSURE(rc_glue_make(0.0, 1.0, &in, &out, 7.0, rc_v3(1, 1, 0), rc_v3(2, 1, 0), &g) == RC_OK);
    ENSURE(g.t_first == 7.0 && g.t_last == 7.0 && g.t_c == 7.0);
    ENSURE(g.x_c.x == 1.0 && g.x_c.y == 1.0);
}

/* The classical limit of rc_glue_toi: a sphere that changes velocity at t_x, met by a
 * rigid sphere, against the two intervals' quadratics. With kappa = 0, H is the slice
 * t = t_x and the search on it has nothing to minimise: it must still tell two sections
 * that touch there from two that are apart (the first version called sections apart but
 * within a few per cent of touching a contact at t_x). */
static void test_toi_classical(void)
{
    unsigned seed = 41;
    rc_toi_params prm = rc_toi_params_default();
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    int contacts = 0, misses = 0;
    for (int trial = 0; trial < 2000; trial++) {
        const int dim = 2 + trial % 2;
        rc_particle in = {1.0, rvec(&seed, 1.0, dim)}, out = {1.0, rvec(&seed, 1.0, dim)};
        rc_particle kp = {1.0, rvec(&seed, 1.0, dim)};
        const double tx = 0.5 * urand(&seed);
        const rc_vec3 xc = rc_v3_scale(tx, in.p);
        rc_vec3 u = rvec(&seed, 1.0, dim);
        u = rc_v3_scale(1.0 / rc_v3_norm(u), u);
        rc_glue g;
        ENSURE(rc_glue_make(0.0, 1.0, &in, &out, tx, xc, rc_v3_add(xc, u), &g) == RC_OK);
        /* k apart at 0; every few trials k's centre placed so that the two just miss or
         * just touch at t_x */
        rc_vec3 ck;
        if (trial % 3) {
            rc_vec3 e = rvec(&seed, 1.0, dim);
            ck = rc_v3_scale((2.05 + urand(&seed)) / rc_v3_norm(e), e);
        } else {
            rc_vec3 e = rvec(&seed, 1.0, dim);
            e = rc_v3_scale(1.0 / rc_v3_norm(e), e);
            /* at t_x k's centre is 2 (1 + s) from the ball's, s in [-0.02, 0.02] */
            const double sgap = 0.04 * urand(&seed) - 0.02;
            ck = rc_v3_axpy(rc_v3_axpy(xc, 2.0 * (1.0 + sgap), e), -tx, kp.p);
            if (!(rc_v3_norm(ck) > 2.0 * (1.0 + 1e-9)))
                continue; /* (not apart at the start) */
        }
        const rc_toi_ball k = {ck, 1.0, kp.m, kp.p};
        double t;
        rc_vec3 y, n;
        int piece;
        const int st = rc_glue_toi(&g, &prm, ws, 0.0, &k, &t, &y, &n, &piece);
        double tr = sphere_in(0.0, tx, ck, rc_v3_sub(kp.p, in.p));
        if (tr == INFINITY)
            tr = sphere_in(tx, INFINITY, rc_v3_sub(rc_v3_axpy(ck, tx, kp.p), xc),
                           rc_v3_sub(kp.p, out.p));
        const rc_vec3 dxk = rc_v3_sub(rc_v3_axpy(ck, tx, kp.p), xc);
        if (tr == INFINITY) {
            misses++;
            ENSURE_MSG(st == RC_MISS, "trial %d: st %d (t %.9g, piece %d), gap at t_x %.3g",
                       trial, st, t, piece, rc_v3_norm(dxk) - 2.0);
            continue;
        }
        ENSURE_MSG(st == RC_OK, "trial %d: st %d, reference %.9g", trial, st, tr);
        if (st != RC_OK)
            continue;
        contacts++;
        /* (Brent's root of the cylinders' contact, to ~1e-13 of times ~1) */
        ENSURE_CLOSE(t, tr, 1e-10, 1.0);
    }
    printf("  %d contacts, %d misses\n", contacts, misses);
    ENSURE(contacts > 300 && misses > 300);
    rc_toi_workspace_free(&ws);
}

static void test_bad_input(void)
{
    rc_particle in = {1.0, rc_v3(0.1, 0, 0)}, out = {1.0, rc_v3(-0.1, 0, 0)}, bad = {-1.0, rc_v3(0, 0, 0)};
    rc_glue g;
    const rc_vec3 o = rc_v3(0, 0, 0);
    ENSURE(rc_glue_make(1.0, 1.0, NULL, &out, 0.0, o, o, &g) == RC_EINVAL);
    ENSURE(rc_glue_make(1.0, 1.0, &in, &out, 0.0, o, o, NULL) == RC_EINVAL);
    ENSURE(rc_glue_make(-1.0, 1.0, &in, &out, 0.0, o, o, &g) == RC_EINVAL);
    ENSURE(rc_glue_make(1.0, 1.0, &in, &out, NAN, o, o, &g) == RC_EINVAL);
    ENSURE(rc_glue_make(1.0, 1.0, &in, &out, 0.0, rc_v3(INFINITY, 0, 0), o, &g) == RC_EINVAL);
    ENSURE(rc_glue_make(1.0, 0.0, &in, &out, 0.0, o, o, &g) == RC_ERADIUS);
    ENSURE(rc_glue_make(1.0, 1.0, &in, &bad, 0.0, o, o, &g) != RC_OK);
}

/* 1 if k's shape at time t (centre ck, state kb) meets the glued section: its boundary
 * sampled at nb points, each tested with rc_glue_inside (independent of rc_glue_toi). */
#define NB 720
static int g_dim = 2; /* the dimension brute_meets samples (a circle or a sphere) */
static int brute_meets(const rc_glue *g, double t, rc_vec3 ck, const rc_toi_shape *hk, int nb)
{
    const int m = glue_sample_count(g_dim, nb);
    for (int j = 0; j < m; j++) {
        const rc_vec3 u = glue_sample_dir(g_dim, j, m);
        const double s = glue_sample_reach(hk, u); /* boundary point of k along u */
        if (rc_glue_inside(g, t, rc_v3_axpy(ck, s, u)))
            return 1;
    }
    return rc_glue_inside(g, t, ck);
}

/* glue_first_meet's question: does k (centre ck0 at t0, velocity vk) meet the tube at t? */
typedef struct brute_ctx {
    const rc_glue *g;
    const rc_toi_shape *hk;
    rc_vec3 ck0, vk;
    double t0;
} brute_ctx;

static int brute_meets_at(double t, void *ctx)
{
    const brute_ctx *c = ctx;
    return brute_meets(c->g, t, rc_v3_axpy(c->ck0, t - c->t0, c->vk), c->hk, NB);
}

/* rc_glue_toi against a scan in time of the sampled sections (2-D): the first time the
 * scan sees k meet the glued ball lies within one step after the solver's time, the
 * scan sees no meeting before it, and the contact point lies on k's boundary. */
static void toi_brute(int dim, int trials, double tol)
{
    g_dim = dim;
    unsigned seed = 7;
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    int found = 0, on_h = 0, pieces[3] = {0, 0, 0}, overl = 0;
    for (int trial = 0; trial < trials; trial++) {
        const double r = 1.0;
        rc_particle in = {1.0, rmom(&seed, dim)}, out = {1.0, rmom(&seed, dim)};
        const double a0 = 2.0 * M_PI * urand(&seed);
        const rc_vec3 xc = rc_v3(0, 0, 0);
        rc_glue g0;
        ENSURE(rc_glue_make(1.0, r, &in, &out, 0.0, xc, rc_v3(0, 0, 0), &g0) == RC_OK);
        /* X on the incoming section's boundary at t_x = 0 */
        rc_vec3 u = rc_v3(cos(a0), sin(a0), 0.0);
        if (dim == 3) {
            const double z = 2.0 * urand(&seed) - 1.0;
            u = rc_v3(sqrt(1.0 - z * z) * u.x, sqrt(1.0 - z * z) * u.y, z);
        }
        const double bu = rc_v3_dot(g0.in.beta, u);
        const rc_vec3 X = rc_v3_scale(r / sqrt(1.0 + bu * bu / g0.in.g2), u);
        rc_glue g;
        ENSURE(rc_glue_make(1.0, r, &in, &out, 0.0, xc, X, &g) == RC_OK);
        /* k near the ball at t_from, a little before the window */
        const double t_from = g.t_first - 0.05 * urand(&seed);
        /* k just outside the bounding circles, moving towards the ball */
        rc_vec3 dk;
        do
            dk = rvec(&seed, 1.0, dim);
        while (!(rc_v3_norm2(dk) > 0.01 && rc_v3_norm2(dk) <= 1.0));
        dk = rc_v3_scale(1.0 / rc_v3_norm(dk), dk);
        rc_vec3 vk0 = rc_v3_add(rc_v3_scale(-0.6 * urand(&seed), dk), rvec(&seed, 0.25, dim));
        /* (every fourth nearer: its shape may overlap the glued section already) */
        const double dist = trial % 4 ? 2.0 + 0.2 * urand(&seed) : 1.2 + 0.8 * urand(&seed);
        rc_toi_ball k = {rc_v3_axpy(rc_glue_centre(&g, t_from), dist, dk),
                         1.0, 1.0, rc_v3_scale(1.0 / sqrt(1.0 - rc_v3_norm2(vk0)), vk0)};
        const double Mk = sqrt(1.0 + rc_v3_norm2(k.p));
        const rc_vec3 vk = rc_v3_scale(1.0 / Mk, k.p);
        const rc_toi_shape hk = rc_toi_shape_of(k.r, k.m, k.p, 1.0);
        double t;
        rc_vec3 y, n;
        int piece;
        const int st = rc_glue_toi(&g, &prm, ws, t_from, &k, &t, &y, &n, &piece);
        if (brute_meets(&g, t_from, k.x, &hk, NB)) {
            overl++;
            ENSURE_MSG(st == RC_EOVERLAP, "trial %d: st %d", trial, st);
            continue;
        }
        /* a coarse scan, then bisection inside the first step that meets */
        const double T = g.t_last + 1.0;
        const brute_ctx bc = {&g, &hk, k.x, vk, t_from};
        double tb = glue_first_meet(t_from, T, 1e-2, brute_meets_at, (void *)&bc);
        if (st == RC_OK && t > T)
            continue; /* beyond the scan */
        if (st == RC_MISS) {
            ENSURE_MSG(tb == INFINITY, "trial %d: missed a contact at %g", trial, tb);
            continue;
        }
        ENSURE_MSG(st == RC_OK, "trial %d: st %d", trial, st);
        if (st != RC_OK)
            continue;
        found++;
        pieces[piece]++;
        on_h += piece == 2;
        /* (the sampled boundary's chord depth, (pi / NB)^2 / 2 radii, over approach
         * speeds of 0.01 c and more) */
        if (!(tb <= t + tol)) {
            /* a shallow touch (a ridge of the crease grazed) can slip between the scan's
             * samples: look again near t, ten times denser in time and in directions */
            for (double s = t - tol; s < t + 10.0 * tol; s += 0.05 * tol)
                if (brute_meets(&g, s, rc_v3_axpy(k.x, s - t_from, vk), &hk, 10 * NB)) {
                    tb = s;
                    break;
                }
        }
        ENSURE_MSG(fabs(tb - t) <= tol, "trial %d piece %d: t %.9g scan %.9g",
                   trial, piece, t, tb);
        const rc_vec3 ck = rc_v3_axpy(k.x, t - t_from, vk);
        const rc_vec3 d = rc_v3_sub(y, ck);
        const double bd = rc_v3_dot(hk.beta, d) / hk.g;
        ENSURE_CLOSE(rc_v3_norm2(d) + bd * bd, 1.0, 1e-7, 1.0);
        ENSURE_CLOSE(rc_v3_norm(n), 1.0, 1e-12, 1.0);
    }
    printf("  %d-D: contacts %d (incoming %d, outgoing %d, on H %d), overlapping starts %d\n", dim, found,
           pieces[0], pieces[1], pieces[2], overl);
    ENSURE(found > trials / 4 && pieces[0] > 0 && pieces[1] > 0 && overl > 0);
    ENSURE(dim == 3 || on_h > 0);
    rc_toi_workspace_free(&ws);
}

/* (2-D: the sampled circle's chord depth, (pi / NB)^2 / 2 radii, over approach speeds of
 * 0.01c and more; 3-D: the 6 NB points of the Fibonacci sphere are about 0.05 radii apart,
 * a chord depth of 4e-4 radii) */
static void test_toi_brute(void) { toi_brute(2, 400, 2e-3); }
static void test_toi_brute_3d(void) { toi_brute(3, 80, 2e-2); }

/* Windows of random elastic pair collisions (zmf law, c = 1, r = 1): the contact event
 * lies on the ball's section, so H reaches it inside the window, t_first <= t_x <= t_last.
 * Prints the mean window and the mean lead of its start over the contact (the figures of
 * papers/model-regime.md, section 5). */
static void test_window_lengths(void)
{
    for (int vi = 0; vi < 2; vi++) {
        const double vr = vi ? 0.9 : 0.5;
        unsigned seed = 11;
        double wsum = 0.0, lsum = 0.0;
        int n = 0;
        for (int trial = 0; trial < 10000; trial++) {
            rc_particle P[2];
            for (int i = 0; i < 2; i++) {
                rc_vec3 v; /* uniform components of rms vr / sqrt(2): rms speed vr in 2-D */
                do
                    v = rvec(&seed, vr * sqrt(1.5), 2);
                while (rc_v3_norm2(v) >= 0.99);
                P[i].m = 1.0;
                P[i].p = rc_v3_scale(1.0 / sqrt(1.0 - rc_v3_norm2(v)), v);
            }
            const double a = 2.0 * M_PI * urand(&seed);
            const rc_vec3 nn = rc_v3(cos(a), sin(a), 0.0);
            rc_particle Q[2] = {P[0], P[1]};
            rc_collision_params cp = rc_collision_params_default();
            cp.c = 1.0;
            if (rc_law_zmf.collide(&cp, &Q[0], &Q[1], nn) != RC_OK)
                continue; /* not approaching along nn */
            /* the contact point: ball 0's support point along nn */
            const double M0 = sqrt(1.0 + rc_v3_norm2(P[0].p));
            const rc_vec3 b = rc_v3_scale(1.0 / M0, P[0].p);
            const double bn = rc_v3_dot(b, nn);
            const rc_vec3 X = rc_v3_scale(1.0 / sqrt(1.0 - bn * bn), rc_v3_axpy(nn, -bn, b));
            rc_glue g;
            ENSURE(rc_glue_make(1.0, 1.0, &P[0], &Q[0], 0.0, rc_v3(0, 0, 0), X, &g) == RC_OK);
            /* (round-off of terms of size r) */
            ENSURE_MSG(g.t_first <= 1e-12 && g.t_last >= -1e-12, "window [%g, %g]", g.t_first,
                       g.t_last);
            wsum += g.t_last - g.t_first;
            lsum -= g.t_first;
            n++;
        }
        printf("  rms %.1fc: %d collisions, mean window %.3f r/c, mean start %.3f r/c before "
               "the contact\n", vr, n, wsum / n, lsum / n);
    }
}

int main(void)
{
    RUN_TEST(test_window_lengths);
    RUN_TEST(test_toi_brute);
    RUN_TEST(test_toi_brute_3d);
    RUN_TEST(test_sections_match);
    RUN_TEST(test_window_mixes);
    RUN_TEST(test_classical);
    RUN_TEST(test_toi_classical);
    RUN_TEST(test_bad_input);
    RC_TEST_MAIN_END();
}
