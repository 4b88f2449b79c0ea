/* test_law_precision.c — the zmf and cm-isotropic kernels against the same laws written
 * from their textbook definitions in __float128 (issue 16, item 6): random pairs with
 * Lorentz factors up to 1e8, nearly co-moving pairs, head-on, grazing and exact-swap
 * cases; momenta and rest masses within 1e-12 (or, for data whose exact outcome moves by
 * more than that under one rounding, within 16 times that move: see TOL) and no false
 * "no collision". Fails on the old kernels (papers/zmf-law.md section 10).
 *
 * The reference is deliberately the naive formula (papers/zmf-law.md section 4,
 * papers/cm-isotropic.md): it cancels terms of order gamma^2 just as the old double code
 * did, but 113 bits leave it ~1e-18 of the scale at gamma = 1e8 (2^-113 * 1e16), far below
 * the tolerance. Both sides see the same double inputs (m, p, n, 1/c^2 = rc_inv_c2_of(c)),
 * so any difference is the double kernel's own error. */
#include <quadmath.h>
#include <string.h>

#include "law_util.h"

__extension__ typedef __float128 q128;

typedef struct {
    q128 x, y, z;
} qv;

static qv qv_of(rc_vec3 v) { return (qv){v.x, v.y, v.z}; }
/* The exact direction of a double normal: the kernels take |n| = 1, which a double meets
 * only to 1e-16, and at gamma 1e8 the law itself moves by O(1) with |n| (the transverse
 * mass m^2 + (|p|^2 - (p.n)^2)/c^2 carries (1 - |n|^2) |p|^2/c^2). */
static qv qunit(rc_vec3 v)
{
    const qv a = qv_of(v);
    const q128 l = sqrtq(a.x * a.x + a.y * a.y + a.z * a.z);
    return (qv){a.x / l, a.y / l, a.z / l};
}
static q128 qdot(qv a, qv b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static qv qaxpy(qv a, q128 s, qv b) { return (qv){a.x + s * b.x, a.y + s * b.y, a.z + s * b.z}; }
static qv qscale(q128 s, qv a) { return (qv){s * a.x, s * a.y, s * a.z}; }
static qv qcross(qv a, qv b)
{
    return (qv){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/* A reference outcome: collided or not, and the two balls after. */
typedef struct {
    int hit;
    qv p[2];
    q128 m[2];
    q128 approach; /* the invariant a0 = (M1 p0.n - M0 p1.n)/(M0 + M1): > 0 approaching */
} ref_out;

/* zmf, DESIGN.md's formulas verbatim: J = -(1+eps) a0 / s, s = 1 - (u.n)^2/c^2. */
static ref_out ref_zmf(double k_, double eps_, const rc_particle *a, const rc_particle *b,
                       rc_vec3 n_)
{
    ref_out o = {0};
    const q128 k = k_, eps = eps_, m0 = a->m, m1 = b->m;
    const qv p0 = qv_of(a->p), p1 = qv_of(b->p), n = qunit(n_);
    const q128 M0 = sqrtq(m0 * m0 + qdot(p0, p0) * k), M1 = sqrtq(m1 * m1 + qdot(p1, p1) * k);
    const q128 Mt = M0 + M1, pn0 = qdot(p0, n), pn1 = qdot(p1, n), un = (pn0 + pn1) / Mt;
    const q128 a0 = (M1 * pn0 - M0 * pn1) / Mt, s = 1 - un * un * k;
    o.approach = a0;
    o.hit = a0 > 0;
    const q128 J = -(1 + eps) * a0 / s, dm2 = (1 - eps * eps) * a0 * a0 / s * k;
    o.p[0] = qaxpy(p0, J, n);
    o.p[1] = qaxpy(p1, -J, n);
    o.m[0] = sqrtq(m0 * m0 + dm2);
    o.m[1] = sqrtq(m1 * m1 + dm2);
    return o;
}

/* Boost of (M, p) into the frame moving at u (textbook: pbar = p + [(g-1)(p.u)/u^2 - g M] u,
 * Mbar = g (M - p.u/c^2), with (g-1)/u^2 written g^2 k/(g+1)). */
static void qboost(qv u, q128 g, q128 k, q128 *M, qv *p)
{
    const q128 pu = qdot(*p, u);
    const q128 f = g * g * k / (g + 1) * pu - g * *M;
    *M = g * (*M - pu * k);
    *p = qaxpy(*p, f, u);
}

/* cm-isotropic (papers/cm-isotropic.md steps 1-5): boost to the ZMF, normal from alpha or
 * from the boosted normal four-vector (u.n/c^2, n), reflect, scale by R, boost back. */
static ref_out ref_cm(double k_, double R_, double alpha, double azimuth, const rc_particle *a,
                      const rc_particle *b, rc_vec3 n_)
{
    ref_out o = {0};
    const q128 k = k_, R = R_, m0 = a->m, m1 = b->m;
    const qv p0 = qv_of(a->p), p1 = qv_of(b->p), n = qunit(n_);
    const q128 M0 = sqrtq(m0 * m0 + qdot(p0, p0) * k), M1 = sqrtq(m1 * m1 + qdot(p1, p1) * k);
    const q128 Mt = M0 + M1;
    const qv u = qscale(1 / Mt, qaxpy(p0, 1, p1));
    const q128 g = 1 / sqrtq(1 - qdot(u, u) * k);
    o.approach = (M1 * qdot(p0, n) - M0 * qdot(p1, n)) / Mt;
    q128 Mb = M0;
    qv pb = p0;
    qboost(u, g, k, &Mb, &pb);
    const q128 pb2 = qdot(pb, pb);
    if (!(pb2 > 0))
        return o;
    qv nh;
    if (isnan(alpha)) {
        q128 qt = qdot(u, n) * k;
        qv qx = n;
        qboost(u, g, k, &qt, &qx);
        nh = qscale(1 / sqrtq(qdot(qx, qx)), qx);
    } else {
        const qv ph = qscale(1 / sqrtq(pb2), pb);
        const q128 h = sqrtq(ph.x * ph.x + ph.y * ph.y);
        const qv e1 = h > 0 ? (qv){-ph.y / h, ph.x / h, 0} : (qv){1, 0, 0};
        const qv e2 = qcross(ph, e1);
        const q128 sa = sinq(alpha), ca = cosq(alpha);
        nh = qscale(ca, ph);
        nh = qaxpy(nh, sa * cosq(azimuth), e1);
        nh = qaxpy(nh, sa * sinq(azimuth), e2);
    }
    const q128 pn = qdot(pb, nh);
    o.hit = pn > 0;
    const qv pbo = qscale(R, qaxpy(pb, -2 * pn, nh));
    q128 E0 = sqrtq(m0 * m0 + pb2 * k), E1 = sqrtq(m1 * m1 + pb2 * k);
    qv q0 = pbo, q1 = qscale(-1, pbo);
    const qv mu = qscale(-1, u);
    qboost(mu, g, k, &E0, &q0);
    qboost(mu, g, k, &E1, &q1);
    o.p[0] = q0;
    o.p[1] = q1;
    const q128 dm2 = (1 - R * R) * pb2 * k;
    o.m[0] = sqrtq(m0 * m0 + dm2);
    o.m[1] = sqrtq(m1 * m1 + dm2);
    return o;
}

/* How far the exact outcome moves when the data move by one rounding: each component
 * of p0, p1 and n and each rest mass scaled by 1 +- 2^-53 (signs from a fixed generator),
 * the largest change over 16 draws, in the units of the checks below. */
static void conditioning(const rc_law *law, double k, double eps, double alpha, double azim,
                         const rc_particle *a, const rc_particle *b, rc_vec3 n, const ref_out *r0,
                         double *kp, double *km)
{
    rc_test_rng g = {12345};
    const double u = 0x1p-53, scale = rc_v3_norm(a->p) + rc_v3_norm(b->p);
    *kp = *km = 0.0;
    for (int t = 0; t < 16; t++) {
        double f[11];
        for (int i = 0; i < 11; i++)
            f[i] = 1.0 + (rc_test_uniform(&g) < 0.5 ? -u : u);
        rc_particle x = {a->m * f[0], rc_v3(a->p.x * f[1], a->p.y * f[2], a->p.z * f[3])};
        rc_particle y = {b->m * f[4], rc_v3(b->p.x * f[5], b->p.y * f[6], b->p.z * f[7])};
        const rc_vec3 m = rc_v3(n.x * f[8], n.y * f[9], n.z * f[10]);
        const ref_out r = law == &rc_law_zmf ? ref_zmf(k, eps, &x, &y, m)
                                             : ref_cm(k, eps, alpha, azim, &x, &y, m);
        if (!r.hit)
            continue;
        for (int j = 0; j < 2; j++) {
            const qv d = {r.p[j].x - r0->p[j].x, r.p[j].y - r0->p[j].y, r.p[j].z - r0->p[j].z};
            *kp = fmax(*kp, (double)sqrtq(qdot(d, d)) / scale);
            *km = fmax(*km, fabs((double)((r.m[j] - r0->m[j]) / r0->m[j])));
        }
    }
}

/* Tolerance. Momenta: 1e-12 of |p0| + |p1|. The data are the two momenta in double, each
 * uncertain by 2^-53 of its own length, and the law's outcome moves by that much when they
 * do (momentum conservation alone hands the total's rounding to whichever ball ends
 * slow), so |p0| + |p1| is the scale the problem is conditioned on; 1e-12 leaves ~4000
 * roundings of it. A ball's own |p'| is not a usable scale: a 1e8 momentum stopped dead
 * leaves a final momentum of order m c carrying 1e-16 of 1e8. Rest masses: 1e-12
 * relative to each ball's own (m' >= m > 0 and it is computed from the invariant ZMF
 * normal momentum, never from M'^2 - p'^2/c^2).
 * Where the exact outcome itself moves by more than that when the data move by one
 * rounding (conditioning(): a grazing hit's rest-mass rise goes as a0^2 and a0 = d.n moves
 * by 2^-53 |d| with n; a fast ZMF turns a rounding of P's direction into gamma times that
 * angle, papers/zmf-law.md "Accuracy near c"), no double algorithm can promise 1e-12: the
 * error must then stay within COND_TOL times that move. The report counts such pairs. */
#define COND_TOL 16.0
#define TOL 1e-12

typedef struct {
    const char *what;
    long n, hits;
    double ep, em; /* largest errors seen */
    long illcond;  /* pairs beyond TOL but within COND_TOL times the data's conditioning */
    double ratio;  /* largest error / conditioning among those */
} tally;

static double qerr_p(const rc_particle *x, qv ref)
{
    const qv d = {(q128)x->p.x - ref.x, (q128)x->p.y - ref.y, (q128)x->p.z - ref.z};
    return (double)sqrtq(qdot(d, d));
}

/* Run one law on one pair along n and along -n: exactly the side the reference calls
 * approaching must collide (no false "no collision", no false collision), and the outcome
 * must match. */
static void check_pair(const rc_law *law, double c, double eps, double alpha,
                       const rc_particle *a, const rc_particle *b, rc_vec3 n, tally *t)
{
    const double k = rc_inv_c2_of(c);
    rc_collision_params prm = rc_collision_params_default();
    prm.c = c;
    prm.eps = eps;
    prm.alpha = alpha;
    prm.azimuth = 0.7;
    for (int side = 0; side < 2; side++) {
        const rc_vec3 ns = side ? rc_v3_scale(-1.0, n) : n;
        const ref_out r = law == &rc_law_zmf
                              ? ref_zmf(k, eps, a, b, ns)
                              : ref_cm(k, eps, alpha, prm.azimuth, a, b, ns);
        if (!isnan(alpha) && side)
            break; /* with an impact angle the normal is not read */
        rc_particle x = *a, y = *b;
        const int st = law->collide(&prm, &x, &y, ns);
        t->n++;
        ENSURE_MSG((st == RC_OK) == (r.hit != 0),
                   "%s %s: kernel says %s, reference %s (approach %.3g, c %g, m %.17g %.17g, "
                   "p0 (%.17g %.17g %.17g) p1 (%.17g %.17g %.17g) n (%.17g %.17g %.17g))",
                   law->name, t->what, st == RC_OK ? "collision" : "no collision",
                   r.hit ? "collision" : "no collision", (double)r.approach, c, a->m, b->m,
                   a->p.x, a->p.y, a->p.z, b->p.x, b->p.y, b->p.z, ns.x, ns.y, ns.z);
        if (st != RC_OK || !r.hit)
            continue;
        t->hits++;
        const double scale = rc_v3_norm(a->p) + rc_v3_norm(b->p);
        const double ep = fmax(qerr_p(&x, r.p[0]), qerr_p(&y, r.p[1])) / scale;
        const double em = fmax(fabs((double)(((q128)x.m - r.m[0]) / r.m[0])),
                               fabs((double)(((q128)y.m - r.m[1]) / r.m[1])));
        t->ep = fmax(t->ep, ep);
        t->em = fmax(t->em, em);
        double kp = 0, km = 0;
        int ok = ep <= TOL && em <= TOL;
        if (!ok) {
            conditioning(law, k, eps, alpha, prm.azimuth, a, b, ns, &r, &kp, &km);
            ok = (ep <= TOL || ep <= COND_TOL * kp) && (em <= TOL || em <= COND_TOL * km);
            t->illcond += ok;
            t->ratio = fmax(t->ratio, fmax(ep > TOL ? ep / kp : 0, em > TOL ? em / km : 0));
        }
        ENSURE_MSG(ok,
                   "%s %s: momentum error %.3g of |p0|+|p1| (the data's conditioning %.3g), "
                   "rest-mass error %.3g (%.3g) (c %g, eps %g, m %.17g %.17g, p0 (%.17g %.17g "
                   "%.17g) p1 (%.17g %.17g %.17g) n (%.17g %.17g %.17g))",
                   law->name, t->what, ep, kp, em, km, c, eps, a->m, b->m, a->p.x, a->p.y,
                   a->p.z, b->p.x, b->p.y, b->p.z, ns.x, ns.y, ns.z);
    }
}

static void report(const rc_law *law, const tally *t)
{
    printf("  %-13s %-10s %5ld pairs, %5ld collided: max error momenta %.1e, rest masses "
           "%.1e; %ld beyond 1e-12, ill-conditioned (error <= %.1f x the data's)\n",
           law->name, t->what, t->n, t->hits, t->ep, t->em, t->illcond, t->ratio);
}

/* A ball of rest mass m with p = m c eta along unit d, eta log-uniform in [1e-3, 1e8]
 * (Lorentz factors from 1 to 1e8). */
static rc_vec3 fast_p(rc_test_rng *r, double m, double c, rc_vec3 d)
{
    return rc_v3_scale(m * c * lu_logu(r, 1e-3, 1e8), d);
}

static rc_vec3 unit(rc_vec3 a) { return rc_v3_scale(1.0 / rc_v3_norm(a), a); }

static double draw_c(rc_test_rng *r) { return rc_test_uniform(r) < 0.5 ? 1.0 : lu_logu(r, 0.1, 10); }

static double draw_eps(rc_test_rng *r)
{
    double u = rc_test_uniform(r);
    return u < 0.3 ? 1.0 : u < 0.4 ? 0.0 : rc_test_uniform(r);
}

/* A unit vector perpendicular to unit d. */
static rc_vec3 perp(rc_test_rng *r, rc_vec3 d)
{
    for (;;) {
        rc_vec3 e = lu_unit(r, 3);
        e = rc_v3_axpy(e, -rc_v3_dot(e, d), d);
        double l = rc_v3_norm(e);
        if (l > 0.1)
            return rc_v3_scale(1.0 / l, e);
    }
}

/* A law's alpha for a draw: NAN (normal from n) for zmf and half of cm-isotropic's. */
static double draw_alpha(rc_test_rng *r, const rc_law *law)
{
    if (!law->uses_angle || rc_test_uniform(r) < 0.5)
        return NAN;
    return rc_test_range(r, -1.5, 1.5);
}

/* Independent balls: random masses, directions, Lorentz factors up to 1e8, normal. */
static void test_random(const rc_law *law, uint64_t seed)
{
    rc_test_rng r = {seed};
    tally t = {"random", 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < 4000; i++) {
        const double c = draw_c(&r);
        rc_particle a = {lu_logu(&r, 0.2, 5), {0, 0, 0}}, b = {lu_logu(&r, 0.2, 5), {0, 0, 0}};
        a.p = fast_p(&r, a.m, c, lu_unit(&r, 3));
        b.p = fast_p(&r, b.m, c, lu_unit(&r, 3));
        check_pair(law, c, draw_eps(&r), draw_alpha(&r, law), &a, &b, lu_unit(&r, 3), &t);
    }
    report(law, &t);
}

/* Nearly co-moving: ball 1's momentum per unit mass differs from ball 0's by a relative
 * 1e-12 .. 1e-1 along and across the motion; the normal along the motion (one catches up
 * with the other), slightly off it, or anywhere. Equal masses in half the pairs. */
static void test_comoving(const rc_law *law, uint64_t seed)
{
    rc_test_rng r = {seed};
    tally t = {"co-moving", 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < 4000; i++) {
        const double c = draw_c(&r);
        const rc_vec3 d = lu_unit(&r, 3);
        rc_particle a = {lu_logu(&r, 0.2, 5), {0, 0, 0}}, b = {0, {0, 0, 0}};
        b.m = rc_test_uniform(&r) < 0.5 ? a.m : lu_logu(&r, 0.2, 5);
        a.p = fast_p(&r, a.m, c, d);
        const double along = (rc_test_uniform(&r) < 0.5 ? -1 : 1) * lu_logu(&r, 1e-12, 0.1);
        const double across = rc_test_uniform(&r) < 0.3 ? 0.0 : lu_logu(&r, 1e-12, 0.1);
        const rc_vec3 e = perp(&r, d);
        b.p = rc_v3_scale(b.m / a.m,
                          rc_v3_axpy(rc_v3_scale(1.0 + along, a.p), across * rc_v3_norm(a.p), e));
        rc_vec3 n;
        const double u = rc_test_uniform(&r);
        if (u < 0.4)
            n = d;
        else if (u < 0.7)
            n = unit(rc_v3_axpy(d, lu_logu(&r, 1e-9, 0.1), e));
        else
            n = lu_unit(&r, 3);
        check_pair(law, c, draw_eps(&r), draw_alpha(&r, law), &a, &b, n, &t);
    }
    report(law, &t);
}

/* Head-on: opposite momenta along the normal (or a hair off it). */
static void test_head_on(const rc_law *law, uint64_t seed)
{
    rc_test_rng r = {seed};
    tally t = {"head-on", 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < 2000; i++) {
        const double c = draw_c(&r);
        const rc_vec3 d = lu_unit(&r, 3);
        rc_particle a = {lu_logu(&r, 0.2, 5), {0, 0, 0}}, b = {lu_logu(&r, 0.2, 5), {0, 0, 0}};
        a.p = fast_p(&r, a.m, c, d);
        b.p = rc_test_uniform(&r) < 0.2 ? rc_v3(0, 0, 0) : fast_p(&r, b.m, c, rc_v3_scale(-1, d));
        rc_vec3 n = d;
        if (rc_test_uniform(&r) < 0.5)
            n = unit(rc_v3_axpy(d, lu_logu(&r, 1e-12, 1e-3), perp(&r, d)));
        check_pair(law, c, draw_eps(&r), draw_alpha(&r, law), &a, &b, n, &t);
    }
    report(law, &t);
}

/* Grazing: the normal nearly perpendicular to the relative velocity (v0 - v1, formed in
 * long double from the momenta), tilted by 1e-9 .. 1e-2 either way. */
static void test_grazing(const rc_law *law, uint64_t seed)
{
    rc_test_rng r = {seed};
    tally t = {"grazing", 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < 2000; i++) {
        const double c = draw_c(&r), k = rc_inv_c2_of(c);
        rc_particle a = {lu_logu(&r, 0.2, 5), {0, 0, 0}}, b = {lu_logu(&r, 0.2, 5), {0, 0, 0}};
        a.p = fast_p(&r, a.m, c, lu_unit(&r, 3));
        b.p = rc_test_uniform(&r) < 0.5 ? fast_p(&r, b.m, c, lu_unit(&r, 3))
                                        : rc_v3_scale(b.m / a.m * (1 + lu_logu(&r, 1e-6, 0.1)),
                                                      rc_v3_axpy(a.p, lu_logu(&r, 1e-6, 0.1) *
                                                                          rc_v3_norm(a.p),
                                                                 perp(&r, unit(a.p))));
        const qv p0 = qv_of(a.p), p1 = qv_of(b.p);
        const q128 M0 = sqrtq((q128)a.m * a.m + qdot(p0, p0) * k);
        const q128 M1 = sqrtq((q128)b.m * b.m + qdot(p1, p1) * k);
        const qv dv = qaxpy(qscale(1 / M0, p0), -1 / M1, p1);
        const q128 l = sqrtq(qdot(dv, dv));
        if (!(l > 0))
            continue;
        const rc_vec3 w = rc_v3((double)(dv.x / l), (double)(dv.y / l), (double)(dv.z / l));
        const rc_vec3 n = unit(rc_v3_axpy(perp(&r, w), lu_logu(&r, 1e-9, 1e-2), w));
        check_pair(law, c, draw_eps(&r), draw_alpha(&r, law), &a, &b, n, &t);
    }
    report(law, &t);
}

/* Equal masses, elastic, co-moving along the normal: the outcome is the exact swap of the
 * momenta (the example: 4e-5 off at gamma 1e6 before). */
static void test_swap(void)
{
    rc_test_rng r = {77};
    double worst = 0.0;
    for (int i = 0; i < 200; i++) {
        const rc_vec3 n = i % 2 ? rc_v3(1, 0, 0) : rc_v3(0, 0, -1);
        const double m = lu_logu(&r, 0.2, 5), P = m * lu_logu(&r, 1, 1e8);
        const double f = 1.0 + (rc_test_uniform(&r) < 0.5 ? -1 : 1) * lu_logu(&r, 1e-10, 0.1);
        rc_particle a = {m, rc_v3_scale(P * f, n)}, b = {m, rc_v3_scale(P, n)};
        if (f < 1.0) { /* ball 0 must be the faster one to approach along +n */
            rc_particle tmp = a;
            a = b;
            b = tmp;
        }
        rc_collision_params prm = rc_collision_params_default();
        prm.c = 1.0;
        rc_particle x = a, y = b;
        ENSURE(rc_law_zmf.collide(&prm, &x, &y, n) == RC_OK);
        const double sc = rc_v3_norm(a.p) + rc_v3_norm(b.p);
        const double e = fmax(rc_v3_norm(rc_v3_sub(x.p, b.p)), rc_v3_norm(rc_v3_sub(y.p, a.p))) / sc;
        worst = fmax(worst, e);
        ENSURE_MSG(e <= TOL && x.m == m && y.m == m, "swap at P %.17g, f %.17g: error %.3g", P, f, e);
    }
    printf("  zmf           exact swap: max momentum error %.2e\n", worst);
}

static void test_zmf(void)
{
    test_random(&rc_law_zmf, 11);
    test_comoving(&rc_law_zmf, 12);
    test_head_on(&rc_law_zmf, 13);
    test_grazing(&rc_law_zmf, 14);
    test_swap();
}

static void test_cm_isotropic(void)
{
    test_random(&rc_law_cm_isotropic, 21);
    test_comoving(&rc_law_cm_isotropic, 22);
    test_head_on(&rc_law_cm_isotropic, 23);
    test_grazing(&rc_law_cm_isotropic, 24);
}

/* The example through the validating entry point: an approaching pair at gamma
 * 1e8 (and 1e6) along +x was called "no collision". */
static void test_no_false_no_collision(void)
{
    for (int l = 0; rc_laws[l]; l++)
        for (double P = 1e6; P <= 1e8; P *= 100) {
            rc_collision_params prm = rc_collision_params_default();
            prm.c = 1.0;
            rc_particle a = {1, rc_v3(P, 0, 0)}, b = {1, rc_v3(0.99999 * P, 0, 0)};
            const int st = rc_collide(rc_laws[l], &prm, &a, &b, rc_v3(1, 0, 0));
            ENSURE_MSG(st == RC_OK, "%s at p = %g: %s", rc_laws[l]->name, P, rc_strerror(st));
        }
}

/* Invariant mass against (M0 + M1)^2 - |p0 + p1|^2/c^2 in __float128 (113 bits leave
 * ~1e-18 of m^2 at gamma 1e8 after the gamma^2 cancellation): random pairs with Lorentz
 * factors up to 1e8, nearly co-moving pairs (as test_comoving, relative differences 1e-12
 * .. 1e-1 along and across), and three co-moving balls through rc_zmf. The exact value of
 * the given doubles is the reference, so 1e-12 relative leaves ~4000 roundings: the new
 * forms are sums of positive terms, accurate to a few. The old forms fail it. */
static q128 ref_minv(const rc_particle *b, int n, q128 k)
{
    q128 E = 0;
    qv P = {0, 0, 0};
    for (int i = 0; i < n; i++) {
        const qv p = qv_of(b[i].p);
        E += sqrtq((q128)b[i].m * b[i].m + qdot(p, p) * k);
        P = qaxpy(P, 1, p);
    }
    return sqrtq(E * E - qdot(P, P) * k);
}

static void test_invariant_mass(void)
{
    rc_test_rng r = {31};
    double worst2 = 0.0, worst3 = 0.0;
    for (int i = 0; i < 20000; i++) {
        const double c = draw_c(&r), k = rc_inv_c2_of(c);
        const rc_vec3 d = lu_unit(&r, 3);
        rc_particle b[3];
        for (int j = 0; j < 3; j++) {
            b[j].m = lu_logu(&r, 0.2, 5);
            if (i % 4 == 0) { /* independent */
                b[j].p = fast_p(&r, b[j].m, c, lu_unit(&r, 3));
            } else if (j == 0) {
                b[0].p = fast_p(&r, b[0].m, c, d);
            } else { /* co-moving with ball 0 */
                const double along = (rc_test_uniform(&r) < 0.5 ? -1 : 1) * lu_logu(&r, 1e-12, 0.1);
                const double across = rc_test_uniform(&r) < 0.3 ? 0.0 : lu_logu(&r, 1e-12, 0.1);
                b[j].p = rc_v3_scale(b[j].m / b[0].m,
                                     rc_v3_axpy(rc_v3_scale(1.0 + along, b[0].p),
                                                across * rc_v3_norm(b[0].p), perp(&r, d)));
            }
        }
        const q128 r2 = ref_minv(b, 2, k), r3 = ref_minv(b, 3, k);
        const double m2 = rc_pair_invariant_mass(&b[0], &b[1], k);
        double m3 = 0.0;
        ENSURE(rc_zmf(b, 3, k, NULL, &m3) == RC_OK);
        const double e2 = fabs((double)((m2 - r2) / r2)), e3 = fabs((double)((m3 - r3) / r3));
        worst2 = fmax(worst2, e2);
        worst3 = fmax(worst3, e3);
        ENSURE_MSG(e2 <= TOL && e3 <= TOL,
                   "invariant mass: error %.3g (pair), %.3g (three) at c %g, m %.17g %.17g "
                   "%.17g, p0 (%.17g %.17g %.17g) p1 (%.17g %.17g %.17g) p2 (%.17g %.17g %.17g)",
                   e2, e3, c, b[0].m, b[1].m, b[2].m, b[0].p.x, b[0].p.y, b[0].p.z, b[1].p.x,
                   b[1].p.y, b[1].p.z, b[2].p.x, b[2].p.y, b[2].p.z);
    }
    printf("  invariant mass, 20000 draws: max relative error %.1e (rc_pair_invariant_mass), "
           "%.1e (rc_zmf, three balls)\n", worst2, worst3);
}

/* rc_pair_heat on co-moving pairs (as test_comoving) collided by the zmf law, against its
 * definition in __float128: each ball's (|pbar|^2 - |pbar'|^2)/(m' + m), the ZMF momentum
 * length from the pair's invariants, |pbar|^2/c^2 = (D^2 - m0^2 m1^2)/minv^2 with D = M0 M1
 * - p0.p1/c^2 (the same for both balls, and for the after states in their own ZMF: the
 * before states' ZMF seen from the rounded after states is uncertain by a rapidity of
 * order gamma^2 2^-53). Within 1e-12 of the ZMF kinetic scale sum |pbar|^2/(m' + m) plus
 * COND_TOL times the data's own uncertainty (below: a pair with little relative motion
 * has a heat far below what one rounding of its momenta moves). The old boost gave NAN
 * (rc_boost refusing the rounded |u| >= c) or lost every digit. */
static q128 ref_pbar2(const rc_particle *b, q128 k)
{
    const qv p0 = qv_of(b[0].p), p1 = qv_of(b[1].p);
    const q128 m0 = b[0].m, m1 = b[1].m;
    const q128 M0 = sqrtq(m0 * m0 + qdot(p0, p0) * k), M1 = sqrtq(m1 * m1 + qdot(p1, p1) * k);
    const q128 D = M0 * M1 - qdot(p0, p1) * k;
    return (D * D - m0 * m0 * m1 * m1) / ((m0 * m0 + m1 * m1 + 2 * D) * k);
}

static void test_heat(void)
{
    rc_test_rng r = {41};
    double worst = 0.0;
    int n = 0;
    for (int i = 0; i < 4000; i++) {
        const double c = draw_c(&r), k = rc_inv_c2_of(c);
        const rc_vec3 d = lu_unit(&r, 3);
        rc_particle in[2] = {{lu_logu(&r, 0.2, 5), {0, 0, 0}}, {lu_logu(&r, 0.2, 5), {0, 0, 0}}};
        in[0].p = fast_p(&r, in[0].m, c, d);
        const double along = (rc_test_uniform(&r) < 0.5 ? -1 : 1) * lu_logu(&r, 1e-9, 0.1);
        const double across = rc_test_uniform(&r) < 0.3 ? 0.0 : lu_logu(&r, 1e-9, 0.1);
        in[1].p = rc_v3_scale(in[1].m / in[0].m,
                              rc_v3_axpy(rc_v3_scale(1.0 + along, in[0].p),
                                         across * rc_v3_norm(in[0].p), perp(&r, d)));
        const rc_vec3 n0 = rc_test_uniform(&r) < 0.5 ? d : lu_unit(&r, 3);
        rc_collision_params prm = rc_collision_params_default();
        prm.c = c;
        prm.eps = draw_eps(&r);
        rc_particle out[2] = {in[0], in[1]};
        if (rc_law_zmf.collide(&prm, &out[0], &out[1], n0) != RC_OK &&
            rc_law_zmf.collide(&prm, &out[0], &out[1], rc_v3_scale(-1, n0)) != RC_OK)
            continue;
        n++;
        const q128 b2 = ref_pbar2(in, k), a2 = ref_pbar2(out, k);
        q128 ref = 0, scale = 0;
        for (int j = 0; j < 2; j++) {
            ref += (b2 - a2) / ((q128)out[j].m + in[j].m);
            scale += b2 / ((q128)out[j].m + in[j].m);
        }
        /* the data's own part: a rounding of a table momentum across the motion is the
         * same momentum in the ZMF, so |pbar|^2 is uncertain by 2 |pbar| 2^-53 sum |p| */
        const double S = rc_v3_norm(in[0].p) + rc_v3_norm(in[1].p);
        q128 cond = 0;
        for (int j = 0; j < 2; j++)
            cond += 2 * 0x1p-53 * S * (sqrtq(b2) + sqrtq(fabsq(a2))) / ((q128)out[j].m + in[j].m);
        const double q = rc_pair_heat(in, out, k, NULL);
        const double e = fabs((double)((q - ref) / (TOL * scale + COND_TOL * cond)));
        worst = fmax(worst, isnan(e) ? INFINITY : e);
        ENSURE_MSG(e <= 1.0, "heat %.17g, reference %.17g (scale %.3g, the data's %.3g) at c %g, gamma %.3g", q,
                   (double)ref, (double)scale, (double)cond, c, rc_v3_norm(in[0].p) / (in[0].m * c));
    }
    printf("  rc_pair_heat, %d co-moving zmf collisions: max error %.2f of the tolerance\n", n,
           worst);
}

int main(void)
{
    RUN_TEST(test_heat);
    RUN_TEST(test_invariant_mass);
    RUN_TEST(test_zmf);
    RUN_TEST(test_cm_isotropic);
    RUN_TEST(test_no_false_no_collision);
    RC_TEST_MAIN_END();
}
