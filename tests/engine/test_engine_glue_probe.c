/* test_engine_glue_probe — two shortcuts the engine takes before the first contact of two
 * glued tubes (engine/perball/glue_pair.h, papers/covariant-cost.md section 3), white-box:
 *  - tubes_overlap_probe: a point inside both tubes shrunk by 1e-6 of their radii is an
 *    overlap, so where the probe says so rc_glue_toi2 must answer RC_EOVERLAP; and on
 *    these configurations it must find a fair share of those overlaps, or it saves nothing;
 *  - toi2_memo: an answer kept by its whole input is rc_glue_toi2's, to the bit, whether
 *    computed or recalled, and a different question is not answered from the memo.
 * Tubes of the engine's kind: two balls of rest radius 1 (c = 1), speeds to 0.9c, each
 * inside its glue window at the time asked, overlapping or not. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* (the header's other helpers serve engine/predict.c, not this test) */
#pragma GCC diagnostic ignored "-Wunused-function"
#include "../../lib/engine/perball/glue_pair.h"
#include "rc_test.h"
#include "relcol/relcol.h"

/* a momentum of speed below 0.9c, m = 1 */
static rc_vec3 draw_p(rc_rng *g, int dim)
{
    rc_vec3 v;
    do
        v = rc_v3(1.8 * rc_rng_uniform(g) - 0.9, 1.8 * rc_rng_uniform(g) - 0.9,
                  dim == 3 ? 1.8 * rc_rng_uniform(g) - 0.9 : 0.0);
    while (!(rc_v3_norm2(v) < 0.81));
    return rc_v3_scale(1.0 / sqrt(1.0 - rc_v3_norm2(v)), v);
}

static rc_vec3 draw_dir(rc_rng *g, int dim)
{
    const rc_vec3 u = rc_v3(rc_rng_gauss(g), rc_rng_gauss(g), dim == 3 ? rc_rng_gauss(g) : 0.0);
    return rc_v3_scale(1.0 / rc_v3_norm(u), u);
}

/* a tube whose collision is at table time tx, its centre at tx at xc, X on its incoming
 * shape's boundary along a random direction */
static int draw_tube(rc_rng *g, int dim, double tx, rc_vec3 xc, rc_glue *out)
{
    const rc_particle in = {1.0, draw_p(g, dim)}, o = {1.0, draw_p(g, dim)};
    const rc_toi_shape sh = rc_toi_shape_of(1.0, in.m, in.p, 1.0);
    const rc_vec3 u = draw_dir(g, dim);
    const double bu = rc_v3_dot(sh.beta, u);
    const rc_vec3 X = rc_v3_axpy(xc, 1.0 / sqrt(1.0 + bu * bu / sh.g2), u);
    return rc_glue_make(1.0, 1.0, &in, &o, tx, xc, X, out);
}

/* a pair asked at a time inside both windows; centres 1.3 to 2.6 apart then */
static int draw_pair(rc_rng *g, int dim, rc_glue *g0, rc_glue *g1, double *t)
{
    if (draw_tube(g, dim, 0.0, rc_v3(0, 0, 0), g0) != RC_OK)
        return 0;
    *t = g0->t_first + (g0->t_last - g0->t_first) * rc_rng_uniform(g);
    const rc_vec3 c1 = rc_v3_axpy(rc_glue_centre(g0, *t), 1.3 + 1.3 * rc_rng_uniform(g),
                                  draw_dir(g, dim));
    /* ball 1's collision within a window's length of t, its centre at t at c1 */
    const double tx1 = *t + (rc_rng_uniform(g) - 0.5) * 0.8;
    rc_glue probe;
    if (draw_tube(g, dim, tx1, rc_v3(0, 0, 0), &probe) != RC_OK)
        return 0;
    /* moved so that its centre at t is c1 */
    const rc_vec3 shift = rc_v3_sub(c1, rc_glue_centre(&probe, *t));
    probe.x = rc_v3_add(probe.x, shift);
    probe.x_c = rc_v3_add(probe.x_c, shift);
    *g1 = probe;
    return *t > g1->t_first && *t < g1->t_last;
}

static void test_probe(void)
{
    rc_rng g = {77};
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    long asked = 0, overlaps = 0, probed = 0;
    for (int trial = 0; trial < 6000; trial++) {
        const int dim = 2 + trial % 2;
        rc_glue g0, g1;
        double t1;
        if (!draw_pair(&g, dim, &g0, &g1, &t1))
            continue;
        asked++;
        double t;
        rc_vec3 y, n;
        int p0, p1;
        const int st = rc_glue_toi2(&g0, &g1, &prm, ws, t1, &t, &y, &n, &p0, &p1);
        const int pr = tubes_overlap_probe(&g0, &g1, t1);
        overlaps += st == RC_EOVERLAP;
        probed += pr;
        ENSURE_MSG(!pr || st == RC_EOVERLAP, "trial %d: the probe found an overlap, rc_glue_toi2 %d",
                   trial, st);
    }
    printf("  %ld pairs asked: %ld overlaps, %ld found by the probe\n", asked, overlaps, probed);
    ENSURE(asked > 2000 && overlaps > asked / 10 && probed > overlaps / 3);
    rc_toi_workspace_free(&ws);
}

static int same_bits(const void *a, const void *b, size_t n) { return memcmp(a, b, n) == 0; }

static void test_memo(void)
{
    rc_rng g = {78};
    rc_sim *s = calloc(1, sizeof *s);
    eng_perball *pb = calloc(1, sizeof *pb);
    ENSURE(s != NULL && pb != NULL);
    if (!s || !pb) {
        free(s);
        free(pb);
        return;
    }
    s->pb = pb; /* (the memo is the per-ball model's scratch) */
    s->toi = rc_toi_params_default();
    s->toi.c = 1.0;
    ENSURE(rc_toi_workspace_create(&s->ws) == RC_OK);
    /* a stream of questions, each asked again after a few others (as a pair's two balls
     * and their neighbours ask), some of them more than ENG_T2_MEMO questions later */
    enum { NQ = 64 };
    rc_glue q0[NQ], q1[NQ];
    double qt[NQ];
    int nq = 0;
    while (nq < NQ)
        if (draw_pair(&g, 2 + nq % 2, &q0[nq], &q1[nq], &qt[nq]))
            nq++;
    long recalled = 0, contacts = 0;
    for (int step = 0; step < 4 * NQ; step++) {
        const int i = (int)(rc_rng_uniform(&g) * (step < NQ ? step + 1 : NQ));
        double ta, tb;
        rc_vec3 ya, yb, na, nb;
        int a0, a1, b0, b1;
        const uint32_t next_before = s->pb->t2m_next;
        const int sa = toi2_memo(s, &q0[i], &q1[i], qt[i], &ta, &ya, &na, &a0, &a1);
        recalled += s->pb->t2m_next == next_before; /* (nothing stored: recalled) */
        const int sb = rc_glue_toi2(&q0[i], &q1[i], &s->toi, s->ws, qt[i], &tb, &yb, &nb, &b0, &b1);
        ENSURE_MSG(sa == sb, "step %d: memo %d, solver %d", step, sa, sb);
        if (sa != RC_OK || sb != RC_OK)
            continue;
        contacts++;
        ENSURE(same_bits(&ta, &tb, sizeof ta) && same_bits(&ya, &yb, sizeof ya) &&
               same_bits(&na, &nb, sizeof na) && a0 == b0 && a1 == b1);
    }
    /* asked twice in a row: the second answer is recalled (the memo does not grow) */
    double t;
    rc_vec3 y, n;
    int p0, p1;
    toi2_memo(s, &q0[0], &q1[0], qt[0], &t, &y, &n, &p0, &p1);
    const uint32_t next = s->pb->t2m_next;
    toi2_memo(s, &q0[0], &q1[0], qt[0], &t, &y, &n, &p0, &p1);
    ENSURE(s->pb->t2m_next == next);
    /* the same tubes at another time are another question */
    toi2_memo(s, &q0[0], &q1[0], qt[0] + 1e-9, &t, &y, &n, &p0, &p1);
    ENSURE(s->pb->t2m_next == (next + 1) % ENG_T2_MEMO);
    printf("  %d questions asked %d times (%ld answers recalled), %ld contacts compared to "
           "the bit\n", NQ, 4 * NQ, recalled, contacts);
    /* both paths taken: answers recalled, and more computed than the memo holds */
    ENSURE(contacts > 20 && recalled > 0 && 4 * NQ - recalled > ENG_T2_MEMO);
    rc_toi_workspace_free(&s->ws);
    free(pb);
    free(s);
}

int main(void)
{
    RUN_TEST(test_probe);
    RUN_TEST(test_memo);
    RC_TEST_MAIN_END();
}
