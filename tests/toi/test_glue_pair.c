/* test_glue_pair — the first contact of two glued world tubes (rc_glue_toi2,
 * papers/glued-tube.md section 4), both balls inside their glue windows:
 *   - against a scan in time of the two sections sampled on their boundaries and tested
 *     with rc_glue_inside (independent of the solver's convex programs), 2-D and 3-D;
 *   - a tube without a kink (in = out) is a rigid ball: rc_glue_toi's answer;
 *   - the pair asked the other way round: the same time and point, the normal reversed;
 *   - the classical limit (H the slices t = t_x): two spheres that change velocity at
 *     t_x1 and t_x2, solved interval by interval with the quadratic;
 *   - bad inputs refused. */
#define _USE_MATH_DEFINES
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "glue_sample.h"
#include "rc_test.h"
#include "sphere_in.h"
#include "relcol/relcol.h"

static double urand(unsigned *s) { return (double)rand_r(s) / ((double)RAND_MAX + 1.0); }

static rc_vec3 rvec(unsigned *s, double a, int dim)
{
    return rc_v3(a * (2 * urand(s) - 1), a * (2 * urand(s) - 1),
                 dim == 3 ? a * (2 * urand(s) - 1) : 0.0);
}

static rc_vec3 unit(unsigned *s, int dim)
{
    rc_vec3 d;
    do
        d = rvec(s, 1.0, dim);
    while (!(rc_v3_norm2(d) > 0.01 && rc_v3_norm2(d) <= 1.0));
    return rc_v3_scale(1.0 / rc_v3_norm(d), d);
}

/* A momentum of speed below vmax (c = 1, m = 1: |p| = gamma v). */
static rc_vec3 rmom(unsigned *s, int dim, double vmax)
{
    rc_vec3 v;
    do
        v = rvec(s, vmax, dim);
    while (rc_v3_norm2(v) >= vmax * vmax);
    return rc_v3_scale(1.0 / sqrt(1.0 - rc_v3_norm2(v)), v);
}

static rc_vec3 vel(rc_vec3 p) { return rc_v3_scale(1.0 / sqrt(1.0 + rc_v3_norm2(p)), p); }

/* A glued tube of rest radius 1 (c = 1) whose centre is at c0 at time t0 on its incoming
 * line and whose collision is at t_x, its X on the incoming section's boundary along u. */
static rc_glue tube(double ic2, const rc_particle *in, const rc_particle *out, rc_vec3 c0,
                    double t0, double tx, rc_vec3 u)
{
    const rc_vec3 vi = ic2 > 0.0 ? vel(in->p) : in->p;
    const rc_vec3 xc = rc_v3_axpy(c0, tx - t0, vi);
    const rc_toi_shape sh = rc_toi_shape_of(1.0, in->m, in->p, ic2);
    const double bu = rc_v3_dot(sh.beta, u);
    const rc_vec3 X = rc_v3_add(xc, rc_v3_scale(1.0 / sqrt(1.0 + bu * bu / sh.g2), u));
    rc_glue g;
    ENSURE(rc_glue_make(ic2, 1.0, in, out, tx, xc, X, &g) == RC_OK);
    return g;
}

/* ---- the scan: sections sampled on their boundaries ---------------------------------- */

#define NB 360
static int g_dim = 2;

/* Does a boundary point of tube a's section at t (of its incoming or its outgoing shape,
 * where that point belongs to the section) lie in tube b's section? */
static int boundary_in(const rc_glue *a, const rc_glue *b, double t, int nb)
{
    const int m = glue_sample_count(g_dim, nb);
    for (int pc = 0; pc < 2; pc++) {
        const rc_toi_shape *sh = pc ? &a->out : &a->in;
        const rc_vec3 c = rc_v3_axpy(a->x_c, t - a->t_c, pc ? a->v_out : a->v_in);
        if (rc_glue_inside(b, t, c) && rc_glue_inside(a, t, c))
            return 1;
        for (int j = 0; j < m; j++) {
            const rc_vec3 u = glue_sample_dir(g_dim, j, m);
            const double s = glue_sample_reach(sh, u);
            /* (a hair inside, so that the point is the section's where its shape's is) */
            if (rc_glue_inside(a, t, rc_v3_axpy(c, s * (1.0 - 1e-9), u)) &&
                rc_glue_inside(b, t, rc_v3_axpy(c, s, u)))
                return 1;
        }
    }
    return 0;
}

/* Two sections that meet: a boundary point of one lies in the other. */
static int meets(const rc_glue *g1, const rc_glue *g2, double t, int nb)
{
    return boundary_in(g1, g2, t, nb) || boundary_in(g2, g1, t, nb);
}

/* par: 0 four independent momenta; 1 pieces of the two tubes parallel, by turns ball 2's
 * incoming or outgoing piece with ball 1's incoming or outgoing one (the straight
 * cylinders then meet at all times or never, and have no first contact to start from) */
/* meets() of the two tubes in ctx (rc_glue[2]), NB samples: glue_first_meet's question */
static int pair_meets(double t, void *ctx)
{
    const rc_glue *g = ctx;
    return meets(&g[0], &g[1], t, NB);
}

static void scan(int dim, int trials, double tol, int par)
{
    g_dim = dim;
    unsigned seed = 29;
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    int found = 0, overl = 0, misses = 0, where[3][3] = {{0}};
    for (int trial = 0; trial < trials; trial++) {
        rc_particle i1 = {1.0, rmom(&seed, dim, 0.9)}, o1 = {1.0, rmom(&seed, dim, 0.9)};
        rc_particle i2 = {1.0, rmom(&seed, dim, 0.9)}, o2 = {1.0, rmom(&seed, dim, 0.9)};
        if (par) {
            const rc_particle *p1 = trial % 2 ? &o1 : &i1;
            if ((trial / 2) % 2)
                o2 = *p1;
            else
                i2 = *p1;
        }
        /* ball 1 at the origin at t = 0, its collision at 0; ball 2 near it, its collision
         * at a time within a window's length, so that both windows are open together */
        const rc_glue g1 = tube(1.0, &i1, &o1, rc_v3(0, 0, 0), 0.0, 0.0, unit(&seed, dim));
        const rc_vec3 dk = unit(&seed, dim);
        const double dist = trial % 4 ? 2.0 + 0.3 * urand(&seed) : 1.3 + 0.7 * urand(&seed);
        const double t_from = g1.t_first - 0.1 * urand(&seed);
        const rc_vec3 c2 = rc_v3_axpy(rc_glue_centre(&g1, t_from), dist, dk);
        const double tx2 = t_from + 1.5 * urand(&seed);
        const rc_glue g2 = tube(1.0, &i2, &o2, c2, t_from, tx2, unit(&seed, dim));
        double t;
        rc_vec3 y, n;
        int p1, p2;
        const int st = rc_glue_toi2(&g1, &g2, &prm, ws, t_from, &t, &y, &n, &p1, &p2);
        if (meets(&g1, &g2, t_from, NB)) {
            overl++;
            ENSURE_MSG(st == RC_EOVERLAP, "trial %d: st %d", trial, st);
            continue;
        }
        const double T = t_from + 6.0;
        const rc_glue pair[2] = {g1, g2};
        double tb = glue_first_meet(t_from, T, 1e-2, pair_meets, (void *)pair);
        if (st == RC_OK && t > T)
            continue; /* beyond the scan */
        if (st == RC_MISS) {
            misses++;
            ENSURE_MSG(tb == INFINITY, "trial %d: missed a contact at %g", trial, tb);
            continue;
        }
        ENSURE_MSG(st == RC_OK, "trial %d: st %d", trial, st);
        if (st != RC_OK)
            continue;
        found++;
        where[p1][p2]++;
        if (!(tb <= t + tol)) {
            /* a shallow touch can slip between the samples: look again near t, denser */
            for (double s = t - tol; s < t + 10.0 * tol; s += 0.05 * tol)
                if (meets(&g1, &g2, s, 10 * NB)) {
                    tb = s;
                    break;
                }
        }
        ENSURE_MSG(fabs(tb - t) <= tol, "trial %d pieces %d %d: t %.9g scan %.9g", trial, p1,
                   p2, t, tb);
        /* the point lies on both tubes' boundaries: in each, a hair outside is not */
        ENSURE_CLOSE(rc_v3_norm(n), 1.0, 1e-12, 1.0);
        const rc_vec3 in1 = rc_v3_axpy(y, -1e-6, n), in2 = rc_v3_axpy(y, 1e-6, n);
        ENSURE_MSG(rc_glue_inside(&g1, t, in1) && rc_glue_inside(&g2, t, in2),
                   "trial %d pieces %d %d: the point is not on both", trial, p1, p2);
    }
    printf("  %d-D: contacts %d, misses %d, overlapping starts %d; where (tube 1 x tube 2; "
           "incoming, outgoing, on H):\n", dim, found, misses, overl);
    for (int a = 0; a < 3; a++)
        printf("    %5d %5d %5d\n", where[a][0], where[a][1], where[a][2]);
    if (par) { /* (both verdicts, on parallel pieces) */
        ENSURE(found > trials / 8 && overl > 0);
        rc_toi_workspace_free(&ws);
        return;
    }
    ENSURE(found > trials / 4 && overl > 0 && misses > 0);
    /* the kinds of contact the scan checked: pieces of both kinds on both tubes, a crease */
    ENSURE(where[0][0] > 0 && where[1][1] > 0 && where[0][1] + where[1][0] > 0);
    ENSURE(dim == 3 || where[2][0] + where[2][1] + where[0][2] + where[1][2] > 0);
    rc_toi_workspace_free(&ws);
}

/* (2-D: the sampled circle's chord depth, (pi / NB)^2 / 2 radii, over approach speeds
 * of 0.01c and more; 3-D: points about 0.05 radii apart, a chord depth of 4e-4 radii) */
static void test_scan_2d(void) { scan(2, 300, 4e-3, 0); }
static void test_scan_3d(void) { scan(3, 60, 2e-2, 0); }
/* (with no first contact of the straight cylinders to start from, every piece's answer is
 * asked: the first version had the unbounded pieces' direction the wrong way round, and
 * called two incoming pieces that always overlapped a later contact) */
static void test_scan_parallel(void) { scan(2, 120, 4e-3, 1); }

/* ---- a tube without a kink is a rigid ball ------------------------------------------- */

static void test_rigid_limit(void)
{
    unsigned seed = 5;
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    int same = 0, contacts = 0;
    for (int trial = 0; trial < 2000; trial++) {
        const int dim = 2 + trial % 2;
        rc_particle i1 = {1.0, rmom(&seed, dim, 0.95)}, o1 = {1.0, rmom(&seed, dim, 0.95)};
        rc_particle k = {1.0, rmom(&seed, dim, 0.95)};
        const rc_glue g1 = tube(1.0, &i1, &o1, rc_v3(0, 0, 0), 0.0, 0.0, unit(&seed, dim));
        const double t_from = g1.t_first - 0.1 * urand(&seed);
        const rc_vec3 ck = rc_v3_axpy(rc_glue_centre(&g1, t_from), 1.2 + urand(&seed),
                                      unit(&seed, dim));
        /* the rigid ball as a tube: its state the same before and after, X anywhere */
        const rc_glue g2 = tube(1.0, &k, &k, ck, t_from, t_from + urand(&seed), unit(&seed, dim));
        const rc_toi_ball kb = {ck, 1.0, k.m, k.p};
        double t1, t2;
        rc_vec3 y1, y2, n1, n2;
        int pc, p1, p2;
        const int s1 = rc_glue_toi(&g1, &prm, ws, t_from, &kb, &t1, &y1, &n1, &pc);
        const int s2 = rc_glue_toi2(&g1, &g2, &prm, ws, t_from, &t2, &y2, &n2, &p1, &p2);
        ENSURE_MSG(s1 == s2, "trial %d: rc_glue_toi %d, rc_glue_toi2 %d", trial, s1, s2);
        if (s1 != RC_OK || s2 != RC_OK)
            continue;
        contacts++;
        /* (two routes through Brent and the dual search, each to ~1e-13 of times ~1) */
        ENSURE_CLOSE(t2, t1, 1e-9, 1.0);
        ENSURE(rc_v3_norm(rc_v3_sub(y2, y1)) < 1e-6);
        /* on ball 1 the same piece, unless the contact lies on its crease within round-off */
        same += p1 == pc;
    }
    printf("  %d contacts, the same piece of ball 1 in %d\n", contacts, same);
    ENSURE(contacts > 300 && same >= contacts - contacts / 100);
    rc_toi_workspace_free(&ws);
}

/* ---- the pair asked the other way round ---------------------------------------------- */

static void test_swap(void)
{
    unsigned seed = 17;
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    int contacts = 0;
    for (int trial = 0; trial < 1000; trial++) {
        const int dim = 2 + trial % 2;
        rc_particle i1 = {1.0, rmom(&seed, dim, 0.9)}, o1 = {1.0, rmom(&seed, dim, 0.9)};
        rc_particle i2 = {1.0, rmom(&seed, dim, 0.9)}, o2 = {1.0, rmom(&seed, dim, 0.9)};
        const rc_glue g1 = tube(1.0, &i1, &o1, rc_v3(0, 0, 0), 0.0, 0.0, unit(&seed, dim));
        const double t_from = g1.t_first - 0.1 * urand(&seed);
        const rc_vec3 c2 = rc_v3_axpy(rc_glue_centre(&g1, t_from), 2.0 + 0.3 * urand(&seed),
                                      unit(&seed, dim));
        const rc_glue g2 = tube(1.0, &i2, &o2, c2, t_from, t_from + 1.5 * urand(&seed),
                                unit(&seed, dim));
        double ta, tb;
        rc_vec3 ya, yb, na, nb;
        int a1, a2, b1, b2;
        const int sa = rc_glue_toi2(&g1, &g2, &prm, ws, t_from, &ta, &ya, &na, &a1, &a2);
        const int sb = rc_glue_toi2(&g2, &g1, &prm, ws, t_from, &tb, &yb, &nb, &b1, &b2);
        ENSURE_MSG(sa == sb, "trial %d: %d and %d", trial, sa, sb);
        if (sa != RC_OK || sb != RC_OK)
            continue;
        contacts++;
        ENSURE_CLOSE(tb, ta, 1e-9, 1.0);
        ENSURE(rc_v3_norm(rc_v3_sub(ya, yb)) < 1e-6);
        ENSURE(rc_v3_dot(na, nb) < -0.99);
    }
    printf("  %d contacts\n", contacts);
    ENSURE(contacts > 200);
    rc_toi_workspace_free(&ws);
}

/* ---- the classical limit: spheres that change velocity at t_x1 and t_x2 -------------- */

static void test_classical(void)
{
    unsigned seed = 3;
    rc_toi_params prm = rc_toi_params_default();
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    int contacts = 0, later = 0;
    for (int trial = 0; trial < 1000; trial++) {
        const int dim = 2 + trial % 2;
        rc_particle i1 = {1.0, rvec(&seed, 1.0, dim)}, o1 = {1.0, rvec(&seed, 1.0, dim)};
        rc_particle i2 = {1.0, rvec(&seed, 1.0, dim)}, o2 = {1.0, rvec(&seed, 1.0, dim)};
        const rc_glue g1 = tube(0.0, &i1, &o1, rc_v3(0, 0, 0), 0.0, 0.5 * urand(&seed),
                                unit(&seed, dim));
        const rc_vec3 c2 = rc_v3_scale(2.05 + urand(&seed), unit(&seed, dim));
        const rc_glue g2 = tube(0.0, &i2, &o2, c2, 0.0, 1.5 * urand(&seed), unit(&seed, dim));
        ENSURE(g1.t_first == g1.t_x && g2.t_last == g2.t_x);
        double t;
        rc_vec3 y, n;
        int p1, p2;
        const int st = rc_glue_toi2(&g1, &g2, &prm, ws, 0.0, &t, &y, &n, &p1, &p2);
        /* the reference: the intervals between the kinks, each with constant velocities */
        const double k1 = g1.t_x < g2.t_x ? g1.t_x : g2.t_x, k2 = g1.t_x < g2.t_x ? g2.t_x : g1.t_x;
        const double cut[4] = {0.0, k1, k2, INFINITY};
        double tr = INFINITY;
        for (int q = 0; q < 3 && tr == INFINITY; q++) {
            const double a = cut[q];
            const rc_vec3 d = rc_v3_sub(rc_glue_centre(&g2, a),
                                        rc_glue_centre(&g1, a));
            const rc_vec3 v1 = a < g1.t_x ? i1.p : o1.p, v2 = a < g2.t_x ? i2.p : o2.p;
            tr = sphere_in(a, cut[q + 1], d, rc_v3_sub(v2, v1));
        }
        if (tr == INFINITY) {
            ENSURE_MSG(st == RC_MISS, "trial %d: st %d", trial, st);
            continue;
        }
        ENSURE_MSG(st == RC_OK, "trial %d: st %d, the reference %g", trial, st, tr);
        if (st != RC_OK)
            continue;
        contacts++;
        later += tr > k1;
        ENSURE_CLOSE(t, tr, 1e-10, 1.0);
        ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(rc_glue_centre(&g2, t), rc_glue_centre(&g1, t))), 2.0,
                     1e-9, 1.0);
    }
    printf("  %d contacts, %d after a kink\n", contacts, later);
    ENSURE(contacts > 200 && later > 50);
    rc_toi_workspace_free(&ws);
}

static void test_bad_input(void)
{
    rc_toi_params prm = rc_toi_params_default();
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    rc_particle a = {1.0, rc_v3(0.1, 0, 0)}, b = {1.0, rc_v3(-0.1, 0, 0)};
    const rc_glue g1 = tube(1.0, &a, &b, rc_v3(0, 0, 0), 0.0, 0.0, rc_v3(1, 0, 0));
    const rc_glue g2 = tube(1.0, &b, &a, rc_v3(3, 0, 0), 0.0, 0.0, rc_v3(-1, 0, 0));
    const rc_glue g0 = tube(0.0, &b, &a, rc_v3(3, 0, 0), 0.0, 0.0, rc_v3(-1, 0, 0));
    double t;
    rc_vec3 y, n;
    int p1, p2;
    ENSURE(rc_glue_toi2(NULL, &g2, &prm, ws, 0.0, &t, &y, &n, &p1, &p2) == RC_EINVAL);
    ENSURE(rc_glue_toi2(&g1, &g2, &prm, ws, NAN, &t, &y, &n, &p1, &p2) == RC_EINVAL);
    ENSURE(rc_glue_toi2(&g1, &g2, &prm, ws, 0.0, &t, &y, &n, &p1, NULL) == RC_EINVAL);
    ENSURE(rc_glue_toi2(&g1, &g0, &prm, ws, 0.0, &t, &y, &n, &p1, &p2) == RC_EINVAL);
    rc_glue bad = g2;
    bad.r = 0.0;
    ENSURE(rc_glue_toi2(&g1, &bad, &prm, ws, 0.0, &t, &y, &n, &p1, &p2) == RC_ERADIUS);
    rc_toi_workspace_free(&ws);
}

int main(void)
{
    RUN_TEST(test_classical);
    RUN_TEST(test_rigid_limit);
    RUN_TEST(test_swap);
    RUN_TEST(test_scan_2d);
    RUN_TEST(test_scan_3d);
    RUN_TEST(test_scan_parallel);
    RUN_TEST(test_bad_input);
    RC_TEST_MAIN_END();
}
