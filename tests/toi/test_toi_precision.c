/* test_toi_precision.c — the frames that find contact in the pair's zero-momentum frame
 * (`zmf`, and `covariant` which is its kernel, and `transport`) on nearly co-moving pairs,
 * the ZMF moving at Lorentz factors 10 .. 1e8 (issue 16, item 6). The plain boost into the
 * ZMF cancels to order gamma^2 there (papers/time-of-impact.md, "Accuracy near c").
 * Checked against the same frame run on the pair taken to its ZMF in __float128 (where the
 * pair is slow and the double kernel is plain) and the event and normal taken back in
 * __float128: the contact event to 1e-12 of its size and the normal to 1e-12, or, where
 * the data's own rounding moves the exact answer by more, to 16 times that move. */
#include <math.h>
#include <quadmath.h>

#include "rc_quad.h"
#include "rc_test.h"
#include "relcol/relcol.h"


/* The pair taken to its ZMF in __float128 (both states to the later of their ZMF times,
 * ball 0's centre there the origin), the frame's kernel run there in double, its event
 * and normal (as the four-vector (0, n)) taken back. */
static int reference(const rc_toi_frame *fr, const rc_toi_params *prm, const rc_toi_ball *a,
                     const rc_toi_ball *b, rc_toi_workspace *ws, rc_toi_contact *out)
{
    const q128 k = rc_inv_c2_of(prm->c);
    const q128 M0 = qenergy(a->m, qv_of(a->p), k), M1 = qenergy(b->m, qv_of(b->p), k);
    const qv u = qscale(1 / (M0 + M1), qaxpy(qv_of(a->p), 1, qv_of(b->p)));
    const q128 g = 1 / sqrtq(1 - qdot(u, u) * k); /* 113 bits: ~1e-18 left at gamma 1e8 */
    q128 E0 = M0, E1 = M1, t0 = 0, t1 = 0;
    qv p0 = qv_of(a->p), p1 = qv_of(b->p), x0 = qv_of(a->x), x1 = qv_of(b->x);
    qboost(u, g, k, &E0, &p0);
    qboost(u, g, k, &E1, &p1);
    qboost(u, g, k, &t0, &x0);
    qboost(u, g, k, &t1, &x1);
    const q128 tau = t0 > t1 ? t0 : t1;
    x0 = qaxpy(x0, (tau - t0) / E0, p0);
    x1 = qaxpy(x1, (tau - t1) / E1, p1);
    const rc_toi_ball A = {rc_v3(0, 0, 0), a->r, a->m, dv_of(p0)};
    const rc_toi_ball B = {dv_of(qaxpy(x1, -1, x0)), b->r, b->m, dv_of(p1)};
    rc_toi_contact z;
    const int st = rc_toi(fr, prm, &A, &B, ws, &z);
    if (st != RC_OK)
        return st;
    const qv mu = qscale(-1, u);
    q128 et = tau + (q128)z.t;
    qv ex = qaxpy(x0, 1, qv_of(z.x));
    qboost(mu, g, k, &et, &ex);
    q128 nt = 0;
    qv nx = qv_of(z.n);
    qboost(mu, g, k, &nt, &nx);
    out->t = (double)et;
    out->x = dv_of(ex);
    out->n = dv_of(qscale(1 / qnorm(nx), nx));
    return RC_OK;
}

/* The event's error relative to its size (c |t| + |x|, at least the pair's size r0 + r1)
 * and the normal's. */
static void errors(const rc_toi_contact *o, const rc_toi_contact *ref, double c, double R,
                   double *ee, double *en)
{
    const double cc = isinf(c) ? 0.0 : c;
    const double size = fmax(cc * fabs(ref->t) + rc_v3_norm(ref->x), R);
    *ee = (cc * fabs(o->t - ref->t) + rc_v3_norm(rc_v3_sub(o->x, ref->x))) / size;
    *en = rc_v3_norm(rc_v3_sub(o->n, ref->n));
}

/* How far the reference moves when the data move by one rounding: each component of both
 * momenta and of ball 1's position scaled by 1 +- 2^-53 (signs from a fixed generator),
 * the largest change of the event (relative, as errors()) and of the normal over 8 draws.
 * A pair moving together at gamma turns a rounding of a direction across the motion into
 * gamma times that angle in its ZMF. -1 when a perturbed pair does not hit. */
static void conditioning(const rc_toi_frame *fr, const rc_toi_params *prm, const rc_toi_ball *a,
                         const rc_toi_ball *b, rc_toi_workspace *ws, const rc_toi_contact *ref,
                         double *ke, double *kn)
{
    rc_test_rng g = {4242};
    *ke = *kn = 0.0;
    for (int t = 0; t < 8; t++) {
        rc_toi_ball A = *a, B = *b;
        double *d[9] = {&A.p.x, &A.p.y, &A.p.z, &B.p.x, &B.p.y, &B.p.z, &B.x.x, &B.x.y, &B.x.z};
        for (int i = 0; i < 9; i++)
            *d[i] *= 1 + (rc_test_uniform(&g) < 0.5 ? -1 : 1) * 0x1p-53;
        rc_toi_contact o;
        if (reference(fr, prm, &A, &B, ws, &o) != RC_OK) {
            *ke = *kn = -1.0;
            return;
        }
        double ee, en;
        errors(&o, ref, prm->c, a->r + b->r, &ee, &en);
        *ke = fmax(*ke, ee);
        *kn = fmax(*kn, en);
    }
}

/* Against the reference: the event to 1e-12 of its size and the normal to 1e-12 (the data
 * are the double positions and momenta, each uncertain by 2^-53 of its size; a
 * well-conditioned pair moves its contact by a few times that). */
#define REF_TOL 1e-12
/* Where the exact answer moves by more than that under one rounding of the data
 * (conditioning()), no double algorithm can promise REF_TOL: the error must then stay
 * within COND_TOL times that move (as tests/law/test_law_precision.c). */
#define COND_TOL 16.0

static void run_frame(const rc_toi_frame *fr)
{
    rc_test_rng r = {2027};
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    double we = 0.0, wn = 0.0, ratio = 0.0, ae = 0.0, an = 0.0;
    int n = 0, nill = 0, nmiss = 0, nfail = 0;
    for (int it = 0; it < 1500; it++) {
        rc_toi_params prm = rc_toi_params_default();
        prm.c = rc_test_uniform(&r) < 0.5 ? 1.0 : logu(&r, 0.1, 10);
        const double c = prm.c;
        const q128 k = rc_inv_c2_of(c);
        /* The pair in a frame R where it is slow: ball 0 near rest at the origin, ball 1
         * a few radii away, aimed at it (impact parameter below half the radius sum). */
        double m[2], rad[2];
        for (int i = 0; i < 2; i++) {
            m[i] = logu(&r, 0.2, 5);
            rad[i] = rc_test_range(&r, 0.2, 1.0);
        }
        const double R = rad[0] + rad[1];
        const rc_vec3 e = rc_v3(rc_test_range(&r, -1, 1), rc_test_range(&r, -1, 1),
                                rc_test_range(&r, -1, 1));
        const qv eh = qscale(1 / qnorm(qv_of(e)), qv_of(e));
        const qv off = qv_of(rc_v3(rc_test_range(&r, -1, 1), rc_test_range(&r, -1, 1),
                                   rc_test_range(&r, -1, 1)));
        const qv perp = qaxpy(off, -qdot(off, eh), eh);
        const qv xR1 = qaxpy(qscale(R * rc_test_range(&r, 1.05, 3.0), eh),
                             0.5 * R * rc_test_uniform(&r) / qnorm(perp), perp);
        const qv vR0 = qscale(c * rc_test_range(&r, -0.3, 0.3) / qnorm(qv_of(e)), qv_of(e));
        const qv vR1 = qscale(-c * rc_test_range(&r, 0.05, 0.6) / qnorm(xR1), xR1);
        const qv xR[2] = {{0, 0, 0}, xR1}, vR[2] = {vR0, vR1};
        /* R moves at speed V along d in the table: the Lorentz factor log-uniform 10 .. 1e8;
         * each ball's state is its worldline's event at table time 0 */
        const qv d = qv_of(rc_v3(rc_test_range(&r, -1, 1), rc_test_range(&r, -1, 1),
                                 rc_test_range(&r, -1, 1)));
        const qv dh = qscale(1 / qnorm(d), d);
        const q128 G = logu(&r, 10, 1e8), V = sqrtq((1 - 1 / (G * G)) / k);
        const qv back = qscale(-V, dh);
        rc_toi_ball ball[2];
        for (int i = 0; i < 2; i++) {
            const q128 g = 1 / sqrtq(1 - qdot(vR[i], vR[i]) * k);
            q128 E = m[i] * g;
            qv p = qscale(m[i] * g, vR[i]);
            qboost(back, G, k, &E, &p);
            /* t = G (tR - (xR + vR tR).back k) = 0 */
            const q128 tR = qdot(xR[i], back) * k / (1 - qdot(vR[i], back) * k);
            q128 t = tR;
            qv x = qaxpy(xR[i], tR, vR[i]);
            qboost(back, G, k, &t, &x);
            ball[i] = (rc_toi_ball){dv_of(x), rad[i], m[i], dv_of(p)};
        }
        rc_toi_contact ref, o;
        const int sr = reference(fr, &prm, &ball[0], &ball[1], ws, &ref);
        if (sr != RC_OK) {
            nmiss++;
            continue;
        }
        n++;
        const int st = rc_toi(fr, &prm, &ball[0], &ball[1], ws, &o);
        double ee = INFINITY, en = INFINITY;
        if (st == RC_OK) {
            errors(&o, &ref, c, R, &ee, &en);
            ae = fmax(ae, ee);
            an = fmax(an, en);
        } else {
            nfail++;
        }
        int ok = ee <= REF_TOL && en <= REF_TOL;
        if (ok) {
            we = fmax(we, ee);
            wn = fmax(wn, en);
        } else {
            double ke, kn;
            conditioning(fr, &prm, &ball[0], &ball[1], ws, &ref, &ke, &kn);
            const double q = fmax(ee / fmax(ke, REF_TOL), en / fmax(kn, REF_TOL));
            ok = ke >= 0.0 && q <= COND_TOL;
            nill += ok;
            if (ke >= 0.0)
                ratio = fmax(ratio, q);
        }
        ENSURE_MSG(ok, "%s at gamma %.3g, c %g: %s, event %.3g of its size, normal %.3g from "
                   "the __float128 reference", fr->name, (double)G, c, rc_strerror(st), ee, en);
    }
    printf("  %s: %d hitting pairs (%d missing), gamma 10 .. 1e8: event <= %.1e of its size, "
           "normal <= %.1e from the reference, or (%d pairs) <= %.2f x the data's "
           "conditioning; largest errors %.2g (event), %.2g (normal), %d hits not found\n",
           fr->name, n, nmiss, we, wn, nill, ratio, ae, an, nfail);
    rc_toi_workspace_free(&ws);
}

static void test_zmf(void) { run_frame(&rc_toi_frame_zmf); }
static void test_transport(void) { run_frame(&rc_toi_frame_transport); }

int main(void)
{
    RUN_TEST(test_zmf);
    RUN_TEST(test_transport);
    RC_TEST_MAIN_END();
}
