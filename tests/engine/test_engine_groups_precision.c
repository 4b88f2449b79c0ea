/* test_engine_groups_precision.c — the group solver (rc_contacts_solve, `simultaneous` and
 * `sequential`) on three-ball groups moving together near c (issue 16, item 6): two
 * contacts, the group's ZMF at Lorentz factors 10 .. 1e8. The rules run in the group's
 * ZMF; the plain boost there cancels to order gamma^2 (papers/simultaneous-contacts.md,
 * "Accuracy near c"). Checked: no failure, elastic rest masses kept to 1e-14, total
 * energy and momentum kept to round-off of the total, and the outcome equal to the same
 * rule run on the same group taken to its ZMF in __float128 (where the group is slow and
 * the double solve is plain) and back, to 1e-12 of the sum of |p| or, where the data's
 * own rounding moves the exact outcome by more, to 16 times that move. */
#include <math.h>
#include <quadmath.h>

#include "rc_test.h"
#include "relcol/relcol.h"

__extension__ typedef __float128 q128;

typedef struct {
    q128 x, y, z;
} qv;

static qv qv_of(rc_vec3 v) { return (qv){v.x, v.y, v.z}; }
static rc_vec3 dv_of(qv v) { return rc_v3((double)v.x, (double)v.y, (double)v.z); }
static q128 qdot(qv a, qv b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static qv qaxpy(qv a, q128 s, qv b) { return (qv){a.x + s * b.x, a.y + s * b.y, a.z + s * b.z}; }
static qv qscale(q128 s, qv a) { return (qv){s * a.x, s * a.y, s * a.z}; }
static q128 qnorm(qv a) { return sqrtq(qdot(a, a)); }

/* Into the frame moving at u (Lorentz factor g): the textbook boost of (t, x). */
static void qboost(qv u, q128 g, q128 k, q128 *t, qv *x)
{
    const q128 xu = qdot(*x, u);
    const q128 f = g * g * k / (g + 1) * xu - g * *t;
    *t = g * (*t - xu * k);
    *x = qaxpy(*x, f, u);
}

static double uniform(rc_test_rng *r, double lo, double hi) { return rc_test_range(r, lo, hi); }
static double logu(rc_test_rng *r, double lo, double hi)
{
    return lo * exp(log(hi / lo) * rc_test_uniform(r));
}

static q128 qenergy(double m, qv p, q128 k) { return sqrtq((q128)m * m + qdot(p, p) * k); }

/* The group taken to its ZMF in __float128 (states, normals as four-vectors (u_ab.n/c^2,
 * n), events), solved there in double, taken back: the reference outcome. */
static int reference(int rule, double c, rc_particle *P, const rc_contact *C)
{
    const q128 k = rc_inv_c2_of(c);
    q128 Mt = 0;
    qv Pt = {0, 0, 0};
    for (int i = 0; i < 3; i++) {
        Mt += qenergy(P[i].m, qv_of(P[i].p), k);
        Pt = qaxpy(Pt, 1, qv_of(P[i].p));
    }
    const qv u = qscale(1 / Mt, Pt);
    const q128 g = 1 / sqrtq(1 - qdot(u, u) * k); /* 113 bits: ~1e-18 left at gamma 1e8 */
    rc_particle B[3];
    rc_contact Z[2];
    for (int i = 0; i < 3; i++) {
        q128 t = qenergy(P[i].m, qv_of(P[i].p), k);
        qv x = qv_of(P[i].p);
        qboost(u, g, k, &t, &x);
        B[i].m = P[i].m;
        B[i].p = dv_of(x);
    }
    for (int j = 0; j < 2; j++) {
        const rc_particle *a = &P[C[j].a], *b = &P[C[j].b];
        const qv pab = qaxpy(qv_of(a->p), 1, qv_of(b->p)), n = qv_of(C[j].n);
        q128 qt = qdot(pab, n) / (qenergy(a->m, qv_of(a->p), k) + qenergy(b->m, qv_of(b->p), k)) * k;
        qv qx = n;
        qboost(u, g, k, &qt, &qx);
        q128 et = C[j].t;
        qv ex = qv_of(C[j].x);
        qboost(u, g, k, &et, &ex);
        Z[j] = C[j];
        Z[j].n = dv_of(qscale(1 / qnorm(qx), qx));
        Z[j].t = (double)et;
        Z[j].x = dv_of(ex);
    }
    rc_collision_params prm = rc_collision_params_default();
    prm.c = c;
    prm.groups = rule;
    const int st = rc_contacts_solve(&prm, 3, B, 2, Z, NULL);
    if (st != RC_OK)
        return st;
    const qv mu = qscale(-1, u);
    for (int i = 0; i < 3; i++) {
        q128 t = qenergy(B[i].m, qv_of(B[i].p), k);
        qv x = qv_of(B[i].p);
        qboost(mu, g, k, &t, &x);
        P[i].m = B[i].m;
        P[i].p = dv_of(x);
    }
    return RC_OK;
}

/* How far the reference outcome moves when the data move by one rounding: each component
 * of every momentum and normal scaled by 1 +- 2^-53 (signs from a fixed generator), the
 * largest change over 8 draws, in units of sum |p|. A group moving together at gamma
 * turns a rounding of a direction across the motion into gamma times that angle in its
 * ZMF: by gamma ~ 1e7 the exact outcome itself moves by more than 1e-12. */
static double conditioning(int rule, double c, const rc_particle *P, const rc_contact *C,
                           const rc_particle *ref, double scale)
{
    rc_test_rng g = {4242};
    double kmax = 0.0;
    for (int t = 0; t < 8; t++) {
        rc_particle pp[3] = {P[0], P[1], P[2]};
        rc_contact cc[2] = {C[0], C[1]};
        for (int i = 0; i < 3; i++) {
            pp[i].p.x *= 1 + (rc_test_uniform(&g) < 0.5 ? -1 : 1) * 0x1p-53;
            pp[i].p.y *= 1 + (rc_test_uniform(&g) < 0.5 ? -1 : 1) * 0x1p-53;
            pp[i].p.z *= 1 + (rc_test_uniform(&g) < 0.5 ? -1 : 1) * 0x1p-53;
        }
        for (int j = 0; j < 2; j++) {
            cc[j].n.x *= 1 + (rc_test_uniform(&g) < 0.5 ? -1 : 1) * 0x1p-53;
            cc[j].n.y *= 1 + (rc_test_uniform(&g) < 0.5 ? -1 : 1) * 0x1p-53;
            cc[j].n.z *= 1 + (rc_test_uniform(&g) < 0.5 ? -1 : 1) * 0x1p-53;
        }
        if (reference(rule, c, pp, cc) != RC_OK)
            continue;
        for (int i = 0; i < 3; i++)
            kmax = fmax(kmax, rc_v3_norm(rc_v3_sub(pp[i].p, ref[i].p)) / scale);
    }
    return kmax;
}

/* Tolerances. Conservation: the outcome's total energy and momentum (summed in
 * __float128) against the input's, relative to the total energy times c: the rule
 * conserves them exactly in the ZMF, and the boosts there and back round each ball's
 * four-momentum to a few units of 2^-53 of its own size, which the total bounds. */
#define CONS_TOL 1e-14
/* Elastic rest masses: the rule sets them to their input values (its rest-mass step) or
 * computes them from slow ZMF states; a few roundings at most. */
#define MASS_TOL 1e-14
/* Against the reference: each ball's momentum to 1e-12 of the sum of |p| (as the pair
 * laws' precision test: the data are the double momenta, each uncertain by 2^-53 of its
 * length, and the outcome moves by that much when they do). */
#define REF_TOL 1e-12
/* Where the exact outcome moves by more than that under one rounding of the data
 * (conditioning()), no double algorithm can promise REF_TOL: the error must then stay
 * within COND_TOL times that move (as tests/law/test_law_precision.c). */
#define COND_TOL 16.0

static void test_comoving_groups(void)
{
    const int rules[2] = {RC_GROUPS_SIMULTANEOUS, RC_GROUPS_SEQUENTIAL};
    rc_test_rng r = {2026};
    double wc = 0.0, wm = 0.0, wr = 0.0, ratio = 0.0;
    int n = 0, nill = 0;
    for (int it = 0; it < 3000; it++) {
        const double c = rc_test_uniform(&r) < 0.5 ? 1.0 : logu(&r, 0.1, 10);
        const q128 k = rc_inv_c2_of(c);
        const int rule = rules[it % 2];
        const double eps = it % 3 == 0 ? uniform(&r, 0, 1) : 1.0;
        /* The group in a frame R where it is slow: ball 0 along +x (speed up to 0.9 c) into
         * balls 1 and 2 touching it at angles a1 above and -a2 below x, moving slowly. */
        const double a1 = uniform(&r, 0.2, 1.2), a2 = uniform(&r, 0.2, 1.2);
        const qv nR[2] = {{cos(a1), sin(a1), 0}, {cos(a2), -sin(a2), 0}};
        double m[3];
        qv pR[3];
        for (int i = 0; i < 3; i++)
            m[i] = logu(&r, 0.2, 5);
        pR[0] = (qv){m[0] * c * logu(&r, 1e-3, 2), 0, 0};
        for (int i = 1; i < 3; i++)
            pR[i] = (qv){m[i] * c * uniform(&r, -0.1, 0.1), m[i] * c * uniform(&r, -0.1, 0.1),
                         m[i] * c * uniform(&r, -0.1, 0.1)};
        /* R moves at speed V along d in the table: the Lorentz factor log-uniform 10 .. 1e8 */
        const qv d = qv_of(rc_v3(uniform(&r, -1, 1), uniform(&r, -1, 1), uniform(&r, -1, 1)));
        const qv dh = qscale(1 / qnorm(d), d);
        const q128 G = logu(&r, 10, 1e8), V = sqrtq((1 - 1 / (G * G)) / k);
        const qv back = qscale(-V, dh);
        rc_particle P[3];
        for (int i = 0; i < 3; i++) {
            q128 t = qenergy(m[i], pR[i], k);
            qv x = pR[i];
            qboost(back, G, k, &t, &x);
            P[i] = (rc_particle){m[i], dv_of(x)};
        }
        rc_contact C[2];
        int approaching = 1;
        for (int j = 0; j < 2; j++) {
            const int b = j + 1;
            const q128 Ma = qenergy(m[0], pR[0], k), Mb = qenergy(m[b], pR[b], k);
            const qv pab = qaxpy(pR[0], 1, pR[b]);
            approaching &= Mb * qdot(pR[0], nR[j]) - Ma * qdot(pR[b], nR[j]) > 0;
            q128 qt = qdot(pab, nR[j]) / (Ma + Mb) * k;
            qv qx = nR[j];
            qboost(back, G, k, &qt, &qx);
            const qv ev = qscale(0.5 + j, dh); /* events at table time 0 */
            C[j] = (rc_contact){0, b, dv_of(qscale(1 / qnorm(qx), qx)), eps, 0.0, dv_of(ev)};
        }
        if (!approaching)
            continue;
        n++;
        rc_particle out[3] = {P[0], P[1], P[2]}, ref[3] = {P[0], P[1], P[2]};
        rc_collision_params prm = rc_collision_params_default();
        prm.c = c;
        prm.groups = rule;
        const int st = rc_contacts_solve(&prm, 3, out, 2, C, NULL);
        ENSURE_MSG(st == RC_OK, "%s at gamma %.3g, c %g: %s", rc_group_rule_name(rule),
                   (double)G, c, rc_strerror(st));
        if (st != RC_OK)
            continue;
        q128 E0 = 0, E1 = 0;
        qv P0 = {0, 0, 0}, P1 = {0, 0, 0};
        for (int i = 0; i < 3; i++) {
            E0 += qenergy(P[i].m, qv_of(P[i].p), k);
            E1 += qenergy(out[i].m, qv_of(out[i].p), k);
            P0 = qaxpy(P0, 1, qv_of(P[i].p));
            P1 = qaxpy(P1, 1, qv_of(out[i].p));
        }
        const qv dP = qaxpy(P1, -1, P0);
        const double ec = (double)(fmaxq(fabsq(E1 - E0), qnorm(dP) * sqrtq(k)) / E0);
        wc = fmax(wc, ec);
        ENSURE_MSG(ec <= CONS_TOL, "%s at gamma %.3g: energy-momentum error %.3g of the total",
                   rc_group_rule_name(rule), (double)G, ec);
        if (eps == 1.0)
            for (int i = 0; i < 3; i++) {
                const double em = fabs(out[i].m - P[i].m) / P[i].m;
                wm = fmax(wm, em);
                ENSURE_MSG(em <= MASS_TOL, "%s at gamma %.3g: ball %d's rest mass %.17g -> %.17g",
                           rc_group_rule_name(rule), (double)G, i, P[i].m, out[i].m);
            }
        ENSURE(reference(rule, c, ref, C) == RC_OK);
        double scale = 0.0, er = 0.0;
        for (int i = 0; i < 3; i++)
            scale += rc_v3_norm(P[i].p);
        for (int i = 0; i < 3; i++)
            er = fmax(er, rc_v3_norm(rc_v3_sub(out[i].p, ref[i].p)) / scale);
        int ok = er <= REF_TOL;
        if (!ok) {
            const double kappa = conditioning(rule, c, P, C, ref, scale);
            ok = er <= COND_TOL * kappa;
            nill += ok;
            ratio = fmax(ratio, er / kappa);
        } else {
            wr = fmax(wr, er);
        }
        ENSURE_MSG(ok, "%s at gamma %.3g, c %g: momentum %.3g of sum |p| from the "
                   "__float128 reference", rc_group_rule_name(rule), (double)G, c, er);
    }
    printf("  %d approaching groups, gamma 10 .. 1e8: energy-momentum error <= %.1e of the "
           "total, elastic rest masses <= %.1e; momenta from the reference <= %.1e of sum |p|, "
           "or (%d groups) <= %.2f x the data's conditioning\n",
           n, wc, wm, wr, nill, ratio);
}

int main(void)
{
    RUN_TEST(test_comoving_groups);
    RC_TEST_MAIN_END();
}
