/* test_glue_reference — rc_glue_toi against its former self: the first contact with a
 * glued tube as it was computed before its comparisons were certified (lib/toi_glue.c
 * decides "is the minimum over two ellipsoids below theta" from a dual lower bound or a
 * common point, and converges the minimum with the golden-section search only when the
 * value is used or the verdict is within a margin of round-off of theta). That search is
 * kept unchanged for every value returned, so the answers must be the same bits: the
 * same status, piece, time, point and normal, on many random configurations of the
 * engine's kind (a neighbour near a ball inside its glue window, overlapping or not,
 * 2-D and 3-D, speeds to 0.95 c). A verdict could differ only if the search's answer were
 * off the true minimum by more than the margin (1e-10 of the terms' size), thousands of
 * times its round-off. The old code below is the previous lib/toi_glue.c's, verbatim but
 * for its names and the counters of its verdicts. */
#define _USE_MATH_DEFINES
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rc_test.h"
#include "relcol/relcol.h"
#include "toi_private.h"

/* the old code's verdicts: overlap path (common part reaches the piece's side of H, or
 * not), contact on H with a contact on a piece already found (taken, or later) */
static long n_ovl_below, n_ovl_not, n_h_taken, n_h_later;

/* Rest-frame metric of a shape: d is inside iff d^T G d <= 1, G = (I + u u^T) / r^2 with
 * u = gamma beta (the shape's rest-frame length of d over r, squared). */
static rc_sym3 shape_metric(const rc_toi_shape *s)
{
    const rc_vec3 u = rc_v3_scale(1.0 / s->g, s->beta);
    const double f = 1.0 / (s->r * s->r);
    const rc_sym3 G = {f * (1.0 + u.x * u.x), f * (1.0 + u.y * u.y), f * (1.0 + u.z * u.z),
                       f * u.x * u.y,         f * u.x * u.z,         f * u.y * u.z};
    return G;
}

/* L^T G L for L = I - v k^T: G - k (G v)^T - (G v) k^T + (v^T G v) k k^T. */
static rc_sym3 pull_back(const rc_sym3 *G, rc_vec3 v, rc_vec3 k)
{
    const rc_vec3 w = rc_sym3_mul_(G, v, 0);
    const double q = rc_v3_dot(v, w);
    rc_sym3 A;
    A.xx = G->xx - 2.0 * k.x * w.x + q * k.x * k.x;
    A.yy = G->yy - 2.0 * k.y * w.y + q * k.y * k.y;
    A.zz = G->zz - 2.0 * k.z * w.z + q * k.z * k.z;
    A.xy = G->xy - k.x * w.y - w.x * k.y + q * k.x * k.y;
    A.xz = G->xz - k.x * w.z - w.x * k.z + q * k.x * k.z;
    A.yz = G->yz - k.y * w.z - w.y * k.z + q * k.y * k.z;
    return A;
}

/* The dual value at lam of min k.z over {(z - m1)^T A1 (z - m1) <= 1} and the same for
 * 2: the minimum of k.z over the blended ellipsoid (1 - lam) q1 + lam q2 <= 1, a lower
 * bound of the minimum over the intersection, INFINITY if the blend is empty (then so is
 * the intersection). *z its minimiser. */
static double dual_at(const rc_sym3 *A1, rc_vec3 b1, double c1, const rc_sym3 *A2, rc_vec3 b2,
                      double c2, rc_vec3 k, double lam, rc_vec3 *z)
{
    const rc_sym3 A = rc_sym3_blend_(A1, A2, lam, 0);
    rc_sym3 adj;
    const double det = rc_sym3_adj_(&A, &adj, 0);
    if (!(det > 0.0))
        return NAN;
    const rc_vec3 b = rc_v3_add(rc_v3_scale(1.0 - lam, b1), rc_v3_scale(lam, b2));
    const rc_vec3 m = rc_v3_scale(1.0 / det, rc_sym3_mul_(&adj, b, 0));
    const double e = (1.0 - lam) * c1 + lam * c2 - rc_v3_dot(b, m);
    if (e > 1.0)
        return INFINITY;
    const rc_vec3 aik = rc_v3_scale(1.0 / det, rc_sym3_mul_(&adj, k, 0)); /* A^-1 k */
    const double s = rc_v3_dot(k, aik);
    const double f = s > 0.0 ? sqrt((1.0 - e) / s) : 0.0;
    *z = rc_v3_axpy(m, -f, aik);
    return rc_v3_dot(k, m) - f * s;
}

/* Golden-section steps on lam in [0, 1]: the dual value is quasi-concave in lam (the
 * best scale of a concave dual along each direction), so it is unimodal; 90 steps narrow
 * the bracket below the round-off of lam. */
#define DUAL_STEPS 90

/* min k.z over the intersection of two ellipsoids {(z - m_i)^T A_i (z - m_i) <= 1}:
 * strong duality of the convex problem makes it the largest dual value. INFINITY if
 * the intersection is empty; *z the minimiser. */
static double ref_lin_min2(const rc_sym3 *A1, rc_vec3 m1, const rc_sym3 *A2, rc_vec3 m2, rc_vec3 k,
                       rc_vec3 *z)
{
    const rc_vec3 b1 = rc_sym3_mul_(A1, m1, 0), b2 = rc_sym3_mul_(A2, m2, 0);
    const double c1 = rc_v3_dot(m1, b1), c2 = rc_v3_dot(m2, b2);
    const double gr = 0.5 * (sqrt(5.0) - 1.0);
    double lo = 0.0, hi = 1.0;
    double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo);
    rc_vec3 z1, z2, zb = m1;
    double f1 = dual_at(A1, b1, c1, A2, b2, c2, k, x1, &z1);
    double f2 = dual_at(A1, b1, c1, A2, b2, c2, k, x2, &z2);
    for (int it = 0; it < DUAL_STEPS; it++) {
        if (f1 == INFINITY || f2 == INFINITY)
            return INFINITY;
        if (isnan(f1) || isnan(f2))
            return NAN;
        if (f1 < f2) {
            lo = x1;
            x1 = x2;
            f1 = f2;
            z1 = z2;
            x2 = lo + gr * (hi - lo);
            f2 = dual_at(A1, b1, c1, A2, b2, c2, k, x2, &z2);
        } else {
            hi = x2;
            x2 = x1;
            f2 = f1;
            z2 = z1;
            x1 = hi - gr * (hi - lo);
            f1 = dual_at(A1, b1, c1, A2, b2, c2, k, x1, &z1);
        }
    }
    /* the ends: one ellipsoid's own minimiser may lie inside the other */
    double best = f1 > f2 ? f1 : f2;
    zb = f1 > f2 ? z1 : z2;
    rc_vec3 ze;
    for (int e = 0; e < 2; e++) {
        const double fe = dual_at(A1, b1, c1, A2, b2, c2, k, (double)e, &ze);
        if (fe == INFINITY)
            return INFINITY;
        if (fe > best) {
            best = fe;
            zb = ze;
        }
    }
    *z = zb;
    return best;
}

/* The section of ball a's world cylinder (shape s, velocity v, centre ca at time ta) by
 * H, in z = y - X: the ellipsoid (z - m)^T A (z - m) <= 1. On H, y's table time is
 * t_x + kappa.z, so the offset from the centre is L z + e with L = I - v kappa^T and
 * e = X - c(t_x); m = -L^-1 e = -(e + v (kappa.e) / (1 - kappa.v)) (Sherman-Morrison). */
static void section_on_h(const rc_glue *g, const rc_toi_shape *s, rc_vec3 v, rc_vec3 ca, double ta,
                         rc_sym3 *A, rc_vec3 *m)
{
    const rc_sym3 G = shape_metric(s);
    *A = pull_back(&G, v, g->kappa);
    const rc_vec3 e = rc_v3_sub(g->x, rc_v3_axpy(ca, g->t_x - ta, v));
    const double ke = rc_v3_dot(g->kappa, e) / (1.0 - rc_v3_dot(g->kappa, v));
    *m = rc_v3_scale(-1.0, rc_v3_axpy(e, ke, v));
}

static int ref_glue_toi(const rc_glue *g, const rc_toi_params *prm, rc_toi_workspace *ws,
                double t_from, const rc_toi_ball *k, double *t, rc_vec3 *y, rc_vec3 *n,
                int *piece)
{
    if (!g || !prm || !ws || !k || !t || !y || !n || !piece || !isfinite(t_from))
        return RC_EINVAL;
    if (!rc_v3_isfinite(k->x) || !isfinite(k->r))
        return RC_ENONFINITE;
    if (!(k->r > 0.0))
        return RC_ERADIUS;
    const rc_particle kp = {k->m, k->p};
    int st = rc_particle_check(&kp);
    if (st != RC_OK)
        return st;
    const double ic2 = g->inv_c2;
    const double Mk = rc_mass_rel(k->m, k->p, ic2);
    const rc_toi_shape sk = rc_toi_shape_M_(k->r, k->m, k->p, ic2, Mk);
    const rc_vec3 vk = rc_v3_scale(1.0 / Mk, k->p);
    const rc_sym3 Gk = shape_metric(&sk);
    /* which side of H a point is on: ell > 0 not yet reached (incoming), < 0 reached */
#define ELL(Y, T) (rc_v3_dot(g->kappa, rc_v3_sub((Y), g->x)) - ((T) - g->t_x))
    double bt = INFINITY;
    rc_vec3 by = rc_v3(0, 0, 0), bn = by;
    int bp = -1, need_h = 0;
    for (int pc = 0; pc < 2; pc++) {
        const rc_toi_shape *sa = pc ? &g->out : &g->in;
        const rc_vec3 va = pc ? g->v_out : g->v_in;
        const rc_vec3 ca = rc_v3_axpy(g->x_c, t_from - g->t_c, va);
        double ta;
        rc_vec3 ya, na;
        st = rc_toi_shapes_rel(sa, &sk, rc_v3_sub(k->x, ca), rc_v3_sub(vk, va), prm, ws, &ta,
                               &ya, &na);
        if (st == RC_MISS)
            continue; /* the whole cylinders never meet: neither does the piece */
        if (st == RC_EOVERLAP) {
            /* overlapping whole shapes now: the piece overlaps k if the common part reaches
             * its side of H; else its first contact is on H */
            const rc_sym3 Ga = shape_metric(sa);
            rc_vec3 z;
            const rc_vec3 dir = rc_v3_scale(pc ? 1.0 : -1.0, g->kappa);
            const double lo = ref_lin_min2(&Ga, rc_v3_sub(ca, g->x), &Gk, rc_v3_sub(k->x, g->x), dir, &z);
            const double side = pc ? lo - (t_from - g->t_x) : -lo - (t_from - g->t_x);
            /* (pc 0: the largest ell over the common part, > 0 reaches the incoming side;
             * pc 1: the least, < 0 reaches the outgoing side; a tolerance of touch_tol
             * radii of H's travel, as rc_toi's own overlap verdict) */
            const double tol = prm->touch_tol * g->r * rc_v3_norm(g->kappa);
            if (lo != INFINITY && (pc ? side < -tol : side > tol)) {
                n_ovl_below++;
                return RC_EOVERLAP;
            }
            n_ovl_not++;
            need_h = 1;
            continue;
        }
        if (st != RC_OK)
            return st;
        const double tc = t_from + ta;
        const rc_vec3 Y = rc_v3_add(rc_v3_axpy(ca, ta, va), ya);
        const double ell = ELL(Y, tc);
        if (pc ? ell <= 0.0 : ell >= 0.0) {
            if (tc < bt) {
                bt = tc;
                by = Y;
                bn = na;
                bp = pc;
            }
        } else {
            need_h = 1;
        }
    }
    if (need_h) {
        /* on H: min of t_x + kappa.z over both cylinders' sections (the incoming and the
         * outgoing cylinder have the same one) */
        rc_sym3 Aa, Ak;
        rc_vec3 ma, mk, z;
        section_on_h(g, &g->in, g->v_in, g->x_c, g->t_c, &Aa, &ma);
        section_on_h(g, &sk, vk, k->x, t_from, &Ak, &mk);
        const double lo = ref_lin_min2(&Aa, ma, &Ak, mk, g->kappa, &z);
        if (isnan(lo))
            return RC_EINVAL;
        const double th = g->t_x + lo;
        if (bt < INFINITY)
            ++*(lo != INFINITY && th >= t_from && th < bt ? &n_h_taken : &n_h_later);
        if (lo != INFINITY && th >= t_from && th < bt) {
            bt = th;
            by = rc_v3_add(g->x, z);
            /* k's outward normal at the point, reversed: from the glued ball to k */
            const rc_vec3 ck = rc_v3_axpy(k->x, th - t_from, vk);
            const rc_vec3 gr = rc_sym3_mul_(&Gk, rc_v3_sub(ck, by), 0);
            bn = rc_v3_scale(1.0 / rc_v3_norm(gr), gr);
            bp = 2;
        }
    }
#undef ELL
    if (bp < 0)
        return RC_MISS;
    *t = bt;
    *y = by;
    *n = bn;
    *piece = bp;
    return RC_OK;
}

static double urand(unsigned *s) { return (double)rand_r(s) / ((double)RAND_MAX + 1.0); }

static rc_vec3 rvec(unsigned *s, double a, int dim)
{
    const double x = a * (2 * urand(s) - 1), y = a * (2 * urand(s) - 1);
    return rc_v3(x, y, dim == 3 ? a * (2 * urand(s) - 1) : 0.0);
}

/* A random momentum (m = 1, c = 1) of speed below vmax. */
static rc_vec3 rmom(unsigned *s, int dim, double vmax)
{
    rc_vec3 v;
    do
        v = rvec(s, vmax, dim);
    while (rc_v3_norm2(v) >= vmax * vmax);
    return rc_v3_scale(1.0 / sqrt(1.0 - rc_v3_norm2(v)), v);
}

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }
static int same_vec(rc_vec3 a, rc_vec3 b)
{
    return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

/* A ball's glue window from a random collision state change at a contact point X on its
 * incoming section, and a neighbour k at t_from inside the window (or just before it),
 * between overlapping the ball and two radii away, moving towards it or not. */
/* A neighbour that first touches the incoming cylinder at a point of H (the crease):
 * Y on the section's boundary where H passes at time th, k (speed below 0.97c) tangent
 * there at th and approaching along the section's normal, t_from before th. Both pieces'
 * straight cylinders and the section on H are met at th at Y, so every comparison of
 * rc_glue_toi is a tie within round-off: the cases its margin must send to the search.
 * 0 if the drawn velocity is too fast. */
static int crease_neighbour(const rc_glue *g, int dim, unsigned *seed, rc_toi_ball *k,
                            double *t_from)
{
    rc_vec3 u;
    do
        u = rvec(seed, 1.0, dim);
    while (!(rc_v3_norm2(u) > 0.01 && rc_v3_norm2(u) <= 1.0));
    u = rc_v3_scale(1.0 / rc_v3_norm(u), u);
    const rc_toi_shape *si = &g->in;
    const double bu = rc_v3_dot(si->beta, u);
    const double s = si->r / sqrt(1.0 + bu * bu / si->g2);
    /* the centre on H at t_c; Y = c(th) + s u on H: th - t_c = s kappa.u / (1 - kappa.v) */
    const double th = g->t_c + s * rc_v3_dot(g->kappa, u) / (1.0 - rc_v3_dot(g->kappa, g->v_in));
    const rc_vec3 c = rc_v3_axpy(g->x_c, th - g->t_c, g->v_in), d = rc_v3_scale(s, u);
    const rc_vec3 Y = rc_v3_add(c, d);
    /* the section's outward normal at Y: (I + gamma^2 beta beta^T) d */
    rc_vec3 nn = rc_v3_axpy(d, rc_v3_dot(si->beta, d) / si->g2, si->beta);
    nn = rc_v3_scale(1.0 / rc_v3_norm(nn), nn);
    const rc_vec3 vk = rc_v3_axpy(g->v_in, -(0.1 + 0.5 * urand(seed)), nn);
    if (!(rc_v3_norm2(vk) < 0.97 * 0.97))
        return 0;
    k->r = 0.5 + urand(seed);
    k->m = 0.5 + urand(seed);
    k->p = rc_v3_scale(k->m / sqrt(1.0 - rc_v3_norm2(vk)), vk);
    /* k's boundary point with outward normal -nn: G_k^-1 (-nn) / sqrt(nn^T G_k^-1 nn),
     * G_k^-1 = r^2 (I - beta beta^T) */
    const rc_vec3 bk = vk; /* (c = 1) */
    const rc_vec3 gi = rc_v3_scale(-k->r * k->r, rc_v3_axpy(nn, -rc_v3_dot(bk, nn), bk));
    const rc_vec3 dk = rc_v3_scale(1.0 / sqrt(-rc_v3_dot(nn, gi)), gi);
    *t_from = th - (1e-3 + 0.3 * urand(seed));
    k->x = rc_v3_axpy(rc_v3_sub(Y, dk), *t_from - th, vk);
    return 1;
}

static void compare(int dim, int trials, double vmax, int crease)
{
    unsigned seed = 1600 + (unsigned)dim;
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    long outcome[4] = {0, 0, 0, 0}, pieces[3] = {0, 0, 0}, diff = 0;
    const long ob0 = n_ovl_below, on0 = n_ovl_not, ht0 = n_h_taken, hl0 = n_h_later;
    for (int trial = 0; trial < trials; trial++) {
        const double r = 0.5 + urand(&seed);
        const rc_particle in = {1.0, rmom(&seed, dim, vmax)};
        const rc_particle out = {1.0 + 0.2 * urand(&seed), rmom(&seed, dim, vmax)};
        const rc_vec3 xc = rvec(&seed, 2.0, dim);
        rc_glue g0;
        ENSURE(rc_glue_make(1.0, r, &in, &out, 0.0, xc, xc, &g0) == RC_OK);
        rc_vec3 u;
        do
            u = rvec(&seed, 1.0, dim);
        while (!(rc_v3_norm2(u) > 0.01 && rc_v3_norm2(u) <= 1.0));
        u = rc_v3_scale(1.0 / rc_v3_norm(u), u);
        const double bu = rc_v3_dot(g0.in.beta, u);
        const rc_vec3 X = rc_v3_axpy(xc, r / sqrt(1.0 + bu * bu / g0.in.g2), u);
        const double tx = 3.0 * urand(&seed);
        rc_glue g;
        const rc_vec3 vin = rc_v3_scale(1.0 / sqrt(1.0 + rc_v3_norm2(in.p)), in.p);
        ENSURE(rc_glue_make(1.0, r, &in, &out, tx, rc_v3_axpy(xc, tx, vin), X, &g) == RC_OK);
        const double t_from = g.t_first + (g.t_last - g.t_first) * (1.2 * urand(&seed) - 0.2);
        rc_vec3 dk;
        do
            dk = rvec(&seed, 1.0, dim);
        while (!(rc_v3_norm2(dk) > 0.01 && rc_v3_norm2(dk) <= 1.0));
        dk = rc_v3_scale(1.0 / rc_v3_norm(dk), dk);
        const double rk = 0.5 + urand(&seed);
        const rc_vec3 vk0 =
            rc_v3_add(rc_v3_scale(-0.7 * vmax * urand(&seed), dk), rvec(&seed, 0.3 * vmax, dim));
        const double vk2 = rc_v3_norm2(vk0) < 0.97 * 0.97 ? rc_v3_norm2(vk0) : 0.0;
        const rc_vec3 vk = vk2 > 0.0 ? vk0 : rc_v3(0, 0, 0);
        const double dist = (r + rk) * (0.3 + 1.0 * urand(&seed));
        const rc_toi_ball k = {rc_v3_axpy(rc_glue_centre(&g, t_from), dist, dk), rk,
                               0.5 + urand(&seed), rc_v3(0, 0, 0)};
        rc_toi_ball kk = k;
        kk.p = rc_v3_scale(kk.m / sqrt(1.0 - vk2), vk);
        double tf = t_from;
        if (crease && !crease_neighbour(&g, dim, &seed, &kk, &tf))
            continue;
        double t0 = 0, t1 = 0;
        rc_vec3 y0 = rc_v3(0, 0, 0), y1 = y0, n0 = y0, n1 = y0;
        int p0 = -1, p1 = -1;
        const int s0 = ref_glue_toi(&g, &prm, ws, tf, &kk, &t0, &y0, &n0, &p0);
        const int s1 = rc_glue_toi(&g, &prm, ws, tf, &kk, &t1, &y1, &n1, &p1);
        ENSURE_MSG(s0 == s1, "%d-D trial %d: status %d, was %d", dim, trial, s1, s0);
        outcome[s0 == RC_OK ? 0 : s0 == RC_MISS ? 1 : s0 == RC_EOVERLAP ? 2 : 3]++;
        if (s0 != RC_OK || s1 != RC_OK)
            continue;
        pieces[p0]++;
        ENSURE_MSG(p0 == p1, "%d-D trial %d: piece %d, was %d", dim, trial, p1, p0);
        const int same = same_bits(t0, t1) && same_vec(y0, y1) && same_vec(n0, n1);
        diff += !same;
        ENSURE_MSG(same, "%d-D trial %d: t %.17g, was %.17g", dim, trial, t1, t0);
    }
    printf("  %d-D, speeds < %.2fc%s: contacts %ld (incoming %ld, outgoing %ld, on H %ld), "
           "misses %ld, overlaps %ld; old verdicts: overlap reaching %ld / not %ld, on H "
           "taken %ld / later %ld; differing %ld\n",
           dim, vmax, crease ? ", at the crease" : "", outcome[0], pieces[0], pieces[1],
           pieces[2], outcome[1], outcome[2], n_ovl_below - ob0, n_ovl_not - on0,
           n_h_taken - ht0, n_h_later - hl0, diff);
    ENSURE(outcome[3] == 0);
    /* every verdict the new code certifies came up many times; at the crease, contacts on
     * H taken against a contact on a piece (ties) */
    if (crease) {
        ENSURE(n_h_taken - ht0 > trials / 500 && n_h_later - hl0 > trials / 100);
    } else {
        ENSURE(n_ovl_below - ob0 > trials / 50 && n_ovl_not - on0 > trials / 50);
        ENSURE(n_h_later - hl0 > trials / 50);
        ENSURE(pieces[0] > 0 && pieces[1] > 0 && pieces[2] > 0);
    }
    rc_toi_workspace_free(&ws);
}

static void test_same_answers_2d(void) { compare(2, 40000, 0.95, 0); }
static void test_same_answers_3d(void) { compare(3, 40000, 0.95, 0); }
static void test_same_answers_slow(void) { compare(3, 10000, 0.6, 0); }
static void test_same_answers_crease(void)
{
    compare(2, 20000, 0.95, 1);
    compare(3, 20000, 0.95, 1);
}

int main(void)
{
    RUN_TEST(test_same_answers_2d);
    RUN_TEST(test_same_answers_3d);
    RUN_TEST(test_same_answers_slow);
    RUN_TEST(test_same_answers_crease);
    RC_TEST_MAIN_END();
}
