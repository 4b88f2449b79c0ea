/* test_engine_approach.c — the engine's approach test (lib/engine/approach.h: group
 * forming in core.c's grow_group, the contracted simultaneity check narrow_conflict) on
 * pairs of balls moving together near c, Lorentz factors 10 .. 1e8 (issue 16, item 6).
 * The plain form dx.(vk - vi) takes the difference of two table velocities, whose part
 * along the motion is 1/gamma^2 of either: its sign is lost to rounding. Checked against
 * the same test in __float128 on the same double data: the verdict the same, except where
 * one rounding of the data flips the exact verdict; |vk - vi|^2 to 1e-12 of itself, or to
 * 16 times its move under one rounding of the data. */
#include <math.h>
#include <quadmath.h>

#include "rc_quad.h"
#include "rc_test.h"
#include "relcol/relcol.h"
#include "../../lib/engine/approach.h"
#include "../../lib/engine/private.h"


/* The exact verdict on the double data (velocities p/M in __float128), and |vk - vi|^2. */
static int exact(q128 k, const rc_particle *a, const rc_particle *b, rc_vec3 dx, double sig,
                 double atol, q128 *w2)
{
    const qv va = qscale(1 / qenergy(a->m, qv_of(a->p), k), qv_of(a->p));
    const qv vb = qscale(1 / qenergy(b->m, qv_of(b->p), k), qv_of(b->p));
    const qv dv = qaxpy(vb, -1, va);
    const q128 bb = qdot(qv_of(dx), dv);
    *w2 = qdot(dv, dv);
    return bb < 0 && bb * bb > (q128)atol * atol * sig * sig * *w2;
}

/* One rounding of the data (each momentum and separation component times 1 +- 2^-53,
 * signs from a fixed generator, 8 draws): whether the exact verdict flips, and the largest
 * relative move of |vk - vi|^2. */
static void conditioning(q128 k, const rc_particle *a, const rc_particle *b, rc_vec3 dx,
                         double sig, double atol, int verdict, q128 w2, int *flips, double *kw)
{
    rc_test_rng g = {4242};
    *flips = 0;
    *kw = 0.0;
    for (int t = 0; t < 8; t++) {
        rc_particle A = *a, B = *b;
        rc_vec3 d = dx;
        round_vec(&g, &A.p);
        round_vec(&g, &B.p);
        round_vec(&g, &d);
        q128 w;
        *flips |= exact(k, &A, &B, d, sig, atol, &w) != verdict;
        *kw = fmax(*kw, (double)(fabsq(w - w2) / w2));
    }
}

/* |vk - vi|^2 to 1e-12 of itself: the verdict's threshold is relative (approach_tol), the
 * contracted check's distance per unit time too; the data's rounding moves it by a few
 * 2^-53 when well conditioned ... */
#define REF_TOL 1e-12
/* ... else within this many times the move of the exact value under one rounding. */
#define COND_TOL 16.0

/* c (1 in half the draws, else log-uniform 0.1 .. 10; k = 1/c^2) and a pair's rest masses
 * and radii; returns the radius sum. */
static double pair_draw(rc_test_rng *r, double *c, q128 *k, double *m, double *rad)
{
    *c = rc_test_uniform(r) < 0.5 ? 1.0 : logu(r, 0.1, 10);
    *k = rc_inv_c2_of(*c);
    for (int i = 0; i < 2; i++) {
        m[i] = logu(r, 0.2, 5);
        rad[i] = rc_test_range(r, 0.2, 1.0);
    }
    return rad[0] + rad[1];
}

static void test_comoving_pairs(void)
{
    rc_test_rng r = {2028};
    const double atol = 1e-10; /* the engine's default approach_tol */
    int n = 0, napp = 0, wrong = 0, nill = 0, nflip = 0;
    double ww = 0.0, ratio = 0.0, aw = 0.0;
    for (int it = 0; it < 20000; it++) {
        double c, m[2], rad[2];
        q128 k;
        const double sig = pair_draw(&r, &c, &k, m, rad);
        /* In a frame R where the pair is slow: ball 0 at the origin, ball 1 touching it
         * along a random n, relative speed up to 0.9 c in a random direction; R moves at
         * Lorentz factor 10 .. 1e8 in the table, each state its worldline's event at table
         * time 0. */
        qv vR[2], xR[2] = {{0, 0, 0}, {0, 0, 0}};
        /* R's motion in the table: along a coordinate axis in two draws of three (the
         * momenta across it are then small numbers, exact to their own size, and the
         * rounding of the data no longer hides the approach along the motion), else
         * random; the contact normal near that axis in half of the draws (the approach
         * then lies along the motion, where the table velocities differ by 1/gamma^2) */
        const int axis = it % 3 != 0;
        const qv d = qframe_dir(&r, axis);
        qv e = qcube(&r);
        if (it % 2)
            e = qaxpy(qscale(rc_test_uniform(&r) < 0.5 ? -1 : 1, qscale(1 / qnorm(d), d)),
                      rc_test_range(&r, 0.0, 0.3) / qnorm(e), e);
        xR[1] = qscale(sig / qnorm(e), e);
        /* in a quarter of the draws along the axis, or off it by a log-uniform angle
         * 1e-20 .. 1e-2 (a row of balls, a cradle) */
        const int line = axis && it % 4 == 1;
        const double tilt = rc_test_uniform(&r) < 0.5 ? 0.0 : logu(&r, 1e-20, 1e-2);
        if (line)
            xR[1] = qscale(sig * (rc_test_uniform(&r) < 0.5 ? -1 : 1), d);
        for (int i = 0; i < 2; i++) {
            qv w = qcube(&r);
            if (line)
                w = qaxpy(qscale(rc_test_range(&r, -1, 1), d), tilt / qnorm(w), w);
            vR[i] = qscale(c * rc_test_range(&r, 0.0, 0.45) / qnorm(w), w);
        }
        const q128 G = logu(&r, 10, 1e8), V = sqrtq((1 - 1 / (G * G)) / k);
        const qv back = qscale(-V / qnorm(d), d);
        rc_particle P[2];
        qv X[2];
        for (int i = 0; i < 2; i++) {
            P[i] = qboosted(m[i], vR[i], back, G, k);
            const q128 tR = qdot(xR[i], back) * k / (1 - qdot(vR[i], back) * k);
            q128 t = tR;
            X[i] = qaxpy(xR[i], tR, vR[i]);
            qboost(back, G, k, &t, &X[i]);
        }
        const rc_vec3 dx = dv_of(qaxpy(X[1], -1, X[0]));
        const rc_vec3 v0 = rc_v3_scale(1.0 / rc_mass_rel(P[0].m, P[0].p, (double)k), P[0].p);
        const rc_vec3 v1 = rc_v3_scale(1.0 / rc_mass_rel(P[1].m, P[1].p, (double)k), P[1].p);
        q128 w2;
        const int want = exact(k, &P[0], &P[1], dx, sig, atol, &w2);
        double dv2;
        const int got = eng_approaching((double)k, &P[0], v0, &P[1], v1, dx, sig, atol, &dv2);
        n++;
        napp += want;
        const double ew = (double)(fabsq(dv2 - w2) / w2);
        aw = fmax(aw, ew);
        int ok = got == want && ew <= REF_TOL;
        if (ok) {
            ww = fmax(ww, ew);
        } else {
            int flips;
            double kw;
            conditioning(k, &P[0], &P[1], dx, sig, atol, want, w2, &flips, &kw);
            ok = (got == want || flips) && ew <= COND_TOL * fmax(kw, REF_TOL);
            nflip += ok && got != want;
            nill += ok;
            if (ok)
                ratio = fmax(ratio, ew / fmax(kw, REF_TOL));
        }
        wrong += got != want;
        ENSURE_MSG(ok, "gamma %.3g, c %g: verdict %d (exact %d), |dv|^2 %.3g off", (double)G, c,
                   got, want, ew);
    }
    printf("  %d pairs (%d approaching), gamma 10 .. 1e8: %d verdicts differ from the exact "
           "one (%d where one rounding of the data flips it); |dv|^2 within %.1e, or (%d "
           "pairs) %.2f x its conditioning; largest |dv|^2 error %.2g\n",
           n, napp, wrong, nflip, ww, nill, ratio, aw);
}

/* An engine (lane width simd) holding the two balls P at x0 and x1, or NULL where it
 * refuses them. */
static rc_sim *pair_sim(rc_sim_simd simd, double c, const rc_particle *P, const double *rad,
                        rc_vec3 x0, rc_vec3 x1)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 3;
    d.box = rc_v3(8, 8, 8);
    d.c = c;
    d.simd = simd;
    rc_sim *s = NULL;
    if (rc_sim_create(&d, &s) != RC_OK)
        return NULL;
    const rc_sim_ball b[2] = {{.x = x0, .p = P[0].p, .r = rad[0], .m = P[0].m},
                              {.x = x1, .p = P[1].p, .r = rad[1], .m = P[1].m}};
    if (rc_sim_set_balls(s, 2, b, NULL) != RC_OK)
        rc_sim_free(&s);
    return s;
}

/* The same question as the engine's lanes ask it: eng_predict_checked, after a resolved
 * contact, looks among the neighbours of a ball just collided for one in contact with it
 * (the spheres within sim_tol) and approaching its velocity before -- a simultaneous
 * contact, which sends the whole group to the group solver. Two uncontracted spheres
 * touching in the table, moving together near c (Lorentz factors 10 .. 1e8) with the
 * data's momenta, in an engine of each lane width (plain C, AVX2, AVX-512: the widths the
 * CPU lacks fall back to narrower ones, and that part is trivially met). The verdict must
 * be the exact one on the double data (__float128), except where one rounding of the data
 * flips it, and the same in every width.
 * engine 1: the engine's first event, run to 1e-9 after the start: 1 if it was a collision
 * (a touching pair is predicted at once by the lanes' sphere test, pair_lanes in
 * lib/engine/kernels.h, when it approaches; the law then resolves it).
 * -1 where the engine refuses the pair. */
static int pair_verdict(int engine, rc_sim_simd simd, double c, const rc_particle *P,
                        const double *rad, rc_vec3 x0, rc_vec3 x1)
{
    rc_sim *s = pair_sim(simd, c, P, rad, x0, x1);
    if (!s)
        return -1;
    int v = -1;
    if (engine) {
        rc_sim_diag dg;
        if (rc_sim_advance(s, 1e-9, 16) >= 0 && rc_sim_diagnostics(s, &dg) == RC_OK)
            v = dg.collisions > 0;
    } else {
        /* (the engine's own index of ball 0: its cells may order them otherwise) */
        const int32_t i = s->b[0].x.x == x0.x && s->b[0].x.y == x0.y && s->b[0].x.z == x0.z ? 0 : 1;
        const eng_check chk = {{s->a[i].m, s->a[i].p}, s->b[i].v, ENG_NONE, NULL, 0};
        v = eng_predict_checked(s, i, &chk, s->now);
    }
    rc_sim_free(&s);
    return v;
}

/* engine: 0 asks eng_predict_checked's simultaneity check (the pair within sim_tol of
 * touching), 1 the engine's own prediction of a touching pair (overlapping by 1e-12 of the
 * radius sum, far below overlap_tol: the state after a collision) */
static void touching_pairs(int engine)
{
    rc_test_rng r = {2031};
    const double atol = 1e-10; /* the engine's default approach_tol */
    const rc_sim_simd widths[3] = {RC_SIM_SIMD_SCALAR, RC_SIM_SIMD_AVX2, RC_SIM_SIMD_AUTO};
    int n = 0, napp = 0, wrong = 0, nflip = 0, differ = 0;
    for (int it = 0; it < 4000; it++) {
        double c, m[2], rad[2];
        q128 k;
        const double sig = pair_draw(&r, &c, &k, m, rad);
        /* the pair slow in a frame R (relative speed up to 0.9 c), R moving at Lorentz
         * factor 10 .. 1e8 along a coordinate axis in two draws of three, else along a
         * random direction d */
        qv d = qframe_dir(&r, it % 3 != 0);
        d = qscale(1 / qnorm(d), d);
        qv vR[2];
        for (int i = 0; i < 2; i++)
            vR[i] = qslow_vel(&r, c, 0.45);
        const q128 G = logu(&r, 10, 1e8), V = sqrtq((1 - 1 / (G * G)) / k);
        rc_particle P[2];
        for (int i = 0; i < 2; i++)
            P[i] = qboosted(m[i], vR[i], qscale(-V, d), G, k);
        /* touching in the table along the motion (a row of balls), off it by a
         * log-uniform angle 1e-20 .. 1, or in a random direction */
        const qv e = qcube(&r);
        const int how = it % 4;
        qv dir = e;
        if (how != 3)
            dir = qaxpy(qscale(rc_test_uniform(&r) < 0.5 ? -1 : 1, d),
                        how == 0 ? 0 : logu(&r, 1e-20, 1) / qnorm(e), e);
        const rc_vec3 x0 = rc_v3(4, 4, 4);
        const q128 f = engine ? 1 - (q128)1e-12 : 1;
        const rc_vec3 x1 = rc_v3_add(x0, dv_of(qscale(f * sig / qnorm(dir), dir)));
        const rc_vec3 dx = rc_v3_sub(x1, x0); /* (exact: Sterbenz) */
        q128 w2;
        const int want = exact(k, &P[0], &P[1], dx, sig, atol, &w2);
        int got[3];
        for (int l = 0; l < 3; l++)
            got[l] = pair_verdict(engine, widths[l], c, P, rad, x0, x1);
        ENSURE_MSG(got[0] >= 0, "gamma %.3g: the engine refused the pair", (double)G);
        if (got[0] < 0)
            continue;
        n++;
        napp += want;
        differ += got[1] != got[0] || got[2] != got[0];
        ENSURE_MSG(got[1] == got[0] && got[2] == got[0], "gamma %.3g: lanes differ: %d %d %d",
                   (double)G, got[0], got[1], got[2]);
        int ok = got[0] == want;
        if (!ok) {
            int flips;
            double kw;
            conditioning(k, &P[0], &P[1], dx, sig, atol, want, w2, &flips, &kw);
            ok = flips;
            nflip += ok;
        }
        wrong += got[0] != want;
        ENSURE_MSG(ok, "%s: gamma %.3g, c %g, contact %s: %d (exact %d)",
                   engine ? "collision" : "conflict", (double)G, c,
                   how == 0 ? "along the motion" : how == 3 ? "random" : "tilted", got[0],
                   want);
    }
    printf("  %s, %d touching pairs (%d approaching), gamma 10 .. 1e8, three "
           "lane widths (%d differ): %d verdicts differ from the exact one (%d where one "
           "rounding of the data flips it)\n",
           engine ? "the engine's first collision" : "eng_predict_checked", n, napp, differ,
           wrong, nflip);
}

static void test_predict_checked(void) { touching_pairs(0); }
static void test_touching_predicted(void) { touching_pairs(1); }

int main(void)
{
    RUN_TEST(test_comoving_pairs);
    RUN_TEST(test_predict_checked);
    RUN_TEST(test_touching_predicted);
    RC_TEST_MAIN_END();
}
