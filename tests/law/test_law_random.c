/* test_law_random.c — 1e5 random collisions per law (zmf, cm-isotropic, wall) in 1-3 D,
 * c from 1.01 x the fastest speed to inf, eps in [0, 1]: conservation, the ZMF picture of
 * each law, rest masses, the heat, subspaces, and that the zmf law commutes with boosts. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "law_util.h"

#define N_PER_LAW 100000
#define N_BOOST 20000

/* Conservation: issue 2 asks for 1e-12 relative to the largest term. Each output is a few
 * roundings of terms no larger than that (~1e-15), so 1e-12 leaves a factor ~1000 for the
 * growth with gamma (<= 7 here, c >= 1.01 x the fastest speed). */
#define TOL_CONS 1e-12
/* ZMF quantities are computed by the test's own long-double boost of the library's
 * outputs; the library's ~few-ulp errors are amplified by the boost by <= 2 gamma_u, and
 * compared relative to the largest term of that boost (gamma_u (|p| + M |u|)). */
#define TOL_ZMF 1e-12
/* New rest mass against sqrt(m^2 + dm2), dm2 from the test's own ZMF momentum: m' is a
 * few roundings of its own (~1e-15); a relative error d in pbar moves m' by at most d
 * (dm2 c^2 <= pbar^2 <= m'^2 c^2), and pbar is ~ few ulp x gamma (<= 7) from cancellation-
 * free formulas in both the law and the test: 1e-13 (~450 ulp) covers it. */
#define TOL_MASS 1e-13

typedef struct {
    int dim;
    double c, k, eps;
    rc_particle b[2];
    rc_vec3 v[2], n;
} config;

/* Velocities up to 1 in `dim` dimensions, masses in [0.1, 10], n from ball 0 to ball 1
 * flipped so that the balls approach; c = inf (1 in 4), exactly 1.01 x the fastest speed
 * (1 in 10), else 1.01 x that times a log-uniform factor in [1, 1e6]; eps exactly 0 or 1
 * (1 in 10 each), else uniform in [0, 1]. */
static void random_config(rc_test_rng *r, config *cf, int dim)
{
    cf->dim = dim;
    for (;;) {
        double vmax = 0.0;
        for (int j = 0; j < 2; j++) {
            cf->b[j].m = lu_logu(r, 0.1, 10.0);
            cf->v[j] = lu_vec(r, dim, 1.0);
            vmax = lu_max(vmax, rc_v3_norm(cf->v[j]));
        }
        cf->n = lu_unit(r, dim);
        double dvn = rc_v3_dot(rc_v3_sub(cf->v[0], cf->v[1]), cf->n);
        if (vmax == 0.0 || fabs(dvn) < 1e-6)
            continue;
        if (dvn < 0.0)
            cf->n = rc_v3_scale(-1.0, cf->n);
        double x = rc_test_uniform(r);
        cf->c = x < 0.25 ? INFINITY : 1.01 * vmax * (x < 0.35 ? 1.0 : lu_logu(r, 1.0, 1e6));
        break;
    }
    ENSURE(rc_inv_c2(cf->c, &cf->k) == RC_OK);
    double e = rc_test_uniform(r);
    cf->eps = e < 0.1 ? 0.0 : (e < 0.2 ? 1.0 : rc_test_uniform(r));
    for (int j = 0; j < 2; j++)
        ENSURE(rc_momentum_from_velocity(cf->b[j].m, cf->v[j], cf->k, &cf->b[j].p) == RC_OK);
}

static double worst_energy, worst_momentum; /* measured, printed per law */

/* Totals before/after: energy sum M and momentum sum p, relative to the largest term. */
static void check_conservation(const config *cf, const rc_particle *out)
{
    double M[4], pmax = 0.0;
    for (int j = 0; j < 2; j++) {
        M[j] = rc_mass_rel(cf->b[j].m, cf->b[j].p, cf->k);
        M[2 + j] = rc_mass_rel(out[j].m, out[j].p, cf->k);
        pmax = lu_max(pmax, lu_max(rc_v3_norm(cf->b[j].p), rc_v3_norm(out[j].p)));
    }
    double Mmax = lu_max(lu_max(M[0], M[1]), lu_max(M[2], M[3]));
    ENSURE_CLOSE(M[2] + M[3], M[0] + M[1], TOL_CONS, Mmax);
    rc_vec3 P0 = rc_v3_add(cf->b[0].p, cf->b[1].p), P1 = rc_v3_add(out[0].p, out[1].p);
    ENSURE_CLOSE(P1.x, P0.x, TOL_CONS, pmax);
    ENSURE_CLOSE(P1.y, P0.y, TOL_CONS, pmax);
    ENSURE_CLOSE(P1.z, P0.z, TOL_CONS, pmax);
    worst_energy = lu_max(worst_energy, fabs(M[2] + M[3] - M[0] - M[1]) / Mmax);
    worst_momentum = lu_max(worst_momentum, rc_v3_norm(rc_v3_sub(P1, P0)) / pmax);
}

/* 1-D and 2-D problems stay in their subspace exactly. */
static void check_subspace(const config *cf, const rc_particle *out)
{
    for (int j = 0; j < 2; j++) {
        if (cf->dim < 3)
            ENSURE_MSG(out[j].p.z == 0.0, "dim %d: pz = %g", cf->dim, out[j].p.z);
        if (cf->dim < 2)
            ENSURE_MSG(out[j].p.y == 0.0, "dim 1: py = %g", out[j].p.y);
    }
}

/* Rest masses: unchanged (bit for bit) at eps = 1, never lower. */
static void check_masses(const config *cf, const rc_particle *out)
{
    for (int j = 0; j < 2; j++) {
        ENSURE_MSG(out[j].m >= cf->b[j].m, "rest mass fell: %.17g -> %.17g", cf->b[j].m,
                   out[j].m);
        if (cf->eps == 1.0)
            ENSURE_MSG(out[j].m == cf->b[j].m, "eps = 1 changed m: %.17g -> %.17g", cf->b[j].m,
                       out[j].m);
    }
}

/* A ball in the pair's ZMF (velocity u, Lorentz factor from the test's own formula). */
typedef struct {
    double E;    /* Mbar */
    rc_vec3 p;   /* pbar */
    double scale; /* largest term of the boost: gamma_u (|p| + M |u|) */
} zmf_state;

static zmf_state to_zmf(const rc_particle *b, rc_vec3 u, double k)
{
    zmf_state z;
    double M = rc_mass_rel(b->m, b->p, k);
    lu_boost_ref(u, k, M, b->p, &z.E, &z.p);
    double g = 1.0 / sqrt(1.0 - rc_v3_norm2(u) * k);
    z.scale = g * (rc_v3_norm(b->p) + M * rc_v3_norm(u));
    return z;
}

/* The ZMF unit normal: the normal four-vector (u.n/c^2, n) boosted to (0, nbar). */
static rc_vec3 zmf_normal(rc_vec3 u, rc_vec3 n, double k)
{
    double t;
    rc_vec3 nb;
    lu_boost_ref(u, k, rc_v3_dot(u, n) * k, n, &t, &nb);
    return rc_v3_scale(1.0 / rc_v3_norm(nb), nb);
}

/* Kinetic energy sum (M - m) c^2 = p^2/(M + m), each term cancellation-free. */
static double kinetic(const rc_particle *b, double k)
{
    return rc_kinetic_energy(b[0].m, b[0].p, k) + rc_kinetic_energy(b[1].m, b[1].p, k);
}

static void test_law(const rc_law *law, uint64_t seed)
{
    const int is_zmf = (law == &rc_law_zmf);
    rc_test_rng r = {seed};
    worst_energy = worst_momentum = 0.0;
    long collided = 0, n_eps0 = 0, n_eps1 = 0, n_inf = 0, n_alpha = 0;
    for (int i = 0; i < N_PER_LAW; i++) {
        config cf;
        random_config(&r, &cf, 1 + i % 3);
        rc_collision_params prm = rc_collision_params_default();
        prm.c = rc_test_c_of(cf.k);
        prm.eps = cf.eps;
        if (!is_zmf && rc_test_uniform(&r) < 0.5) {
            double u1 = rc_test_uniform(&r), u2 = rc_test_uniform(&r);
            rc_impact_angle_draw(cf.dim, u1, u2, &prm.alpha, &prm.azimuth);
            /* keep clear of grazing (|alpha| = pi/2 is refused) */
            if (fabs(prm.alpha) > 1.5)
                prm.alpha = copysign(1.5, prm.alpha);
        }
        rc_particle out[2] = {cf.b[0], cf.b[1]};
        int st = rc_collide(law, &prm, &out[0], &out[1], cf.n);
        ENSURE_MSG(st == RC_OK, "%s: status %d (%s)", law->name, st, rc_strerror(st));
        if (st != RC_OK)
            continue;
        collided++;
        n_eps0 += cf.eps == 0.0;
        n_eps1 += cf.eps == 1.0;
        n_inf += cf.k == 0.0;
        n_alpha += !isnan(prm.alpha);

        check_conservation(&cf, out);
        check_masses(&cf, out);
        check_subspace(&cf, out);

        /* the pair's ZMF (same before and after: the totals are conserved) */
        rc_vec3 u = rc_v3_scale(1.0 / (rc_mass_rel(cf.b[0].m, cf.b[0].p, cf.k) +
                                       rc_mass_rel(cf.b[1].m, cf.b[1].p, cf.k)),
                                rc_v3_add(cf.b[0].p, cf.b[1].p));
        zmf_state z[2], zo[2];
        for (int j = 0; j < 2; j++) {
            z[j] = to_zmf(&cf.b[j], u, cf.k);
            zo[j] = to_zmf(&out[j], u, cf.k);
            /* each ball's ZMF energy is kept */
            ENSURE_CLOSE(zo[j].E, z[j].E, TOL_ZMF, lu_max(z[j].scale, z[j].E));
        }
        double sc = lu_max(lu_max(z[0].scale, z[1].scale), lu_max(zo[0].scale, zo[1].scale));
        /* the ZMF momenta are opposite, before and after */
        ENSURE_CLOSE(rc_v3_norm(rc_v3_add(zo[0].p, zo[1].p)), 0.0, TOL_ZMF, sc);

        double heat_pred = 0.0; /* sum (m' - m) c^2 = sum dm2 c^2 / (m' + m) */
        if (is_zmf) {
            rc_vec3 nh = zmf_normal(u, cf.n, cf.k);
            for (int j = 0; j < 2; j++) {
                double pn = rc_v3_dot(z[j].p, nh), pn1 = rc_v3_dot(zo[j].p, nh);
                rc_vec3 pt = rc_v3_axpy(z[j].p, -pn, nh), pt1 = rc_v3_axpy(zo[j].p, -pn1, nh);
                /* normal ZMF momentum scaled by -eps (eps = 0: ~0), tangential kept */
                ENSURE_CLOSE(pn1, -cf.eps * pn, TOL_ZMF, sc);
                ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(pt1, pt)), 0.0, TOL_ZMF, sc);
                /* m'^2 = m^2 + (1 - eps^2) pbar_n^2 / c^2 */
                double dm2c2 = (1.0 - cf.eps * cf.eps) * pn * pn; /* dm2 c^2 */
                ENSURE_REL(out[j].m, sqrt(cf.b[j].m * cf.b[j].m + dm2c2 * cf.k), TOL_MASS);
                heat_pred += dm2c2 / (out[j].m + cf.b[j].m);
            }
            /* eps = 0: both balls move with the ZMF along n (v.n = u.n in the table) */
            if (cf.eps == 0.0) {
                double vn0 = rc_v3_dot(rc_velocity(out[0].m, out[0].p, cf.k), cf.n);
                double vn1 = rc_v3_dot(rc_velocity(out[1].m, out[1].p, cf.k), cf.n);
                ENSURE_CLOSE(vn0, rc_v3_dot(u, cf.n), TOL_CONS, 1.0);
                ENSURE_CLOSE(vn1, rc_v3_dot(u, cf.n), TOL_CONS, 1.0);
            }
        } else {
            for (int j = 0; j < 2; j++) {
                double p2 = rc_v3_norm2(z[j].p);
                /* |pbar'| = R |pbar| */
                ENSURE_CLOSE(rc_v3_norm(zo[j].p), cf.eps * sqrt(p2), TOL_ZMF, sc);
                double dm2c2 = (1.0 - cf.eps * cf.eps) * p2;
                ENSURE_REL(out[j].m, sqrt(cf.b[j].m * cf.b[j].m + dm2c2 * cf.k), TOL_MASS);
                heat_pred += dm2c2 / (out[j].m + cf.b[j].m);
            }
            /* the reflection: pbar0' = R (pbar0 - 2 (pbar0.nh) nh), nh the ZMF normal
             * (from n, or at angle alpha from pbar0, so pbar0'.pbar0 = -R |pbar0|^2 cos 2a) */
            if (isnan(prm.alpha)) {
                rc_vec3 nh = zmf_normal(u, cf.n, cf.k);
                rc_vec3 refl = rc_v3_axpy(z[0].p, -2.0 * rc_v3_dot(z[0].p, nh), nh);
                rc_vec3 ref = rc_v3_scale(cf.eps, refl);
                ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(zo[0].p, ref)), 0.0, TOL_ZMF, sc);
            } else {
                double p2 = rc_v3_norm2(z[0].p);
                ENSURE_CLOSE(rc_v3_dot(zo[0].p, z[0].p), -cf.eps * p2 * cos(2.0 * prm.alpha),
                             TOL_ZMF, sc * sc);
            }
        }
        /* the kinetic energy lost is the heat sum (m' - m) c^2 (energy conservation with
         * rest mass as internal energy), relative to the largest kinetic term */
        double K0 = kinetic(cf.b, cf.k), K1 = kinetic(out, cf.k);
        ENSURE_CLOSE(K0 - K1, heat_pred, TOL_CONS, K0);
        if (cf.k == 0.0 && is_zmf) {
            /* classical heat (1 - eps^2) mu vn^2 / 2 from the input velocities */
            double m0 = cf.b[0].m, m1 = cf.b[1].m, mu = m0 * m1 / (m0 + m1);
            double vn = rc_v3_dot(rc_v3_sub(cf.v[0], cf.v[1]), cf.n);
            ENSURE_CLOSE(K0 - K1, (1.0 - cf.eps * cf.eps) * mu * vn * vn / 2.0, TOL_CONS, K0);
        }
    }
    printf("  %s: %ld collisions (%ld eps=0, %ld eps=1, %ld c=inf, %ld alpha given)\n",
           law->name, collided, n_eps0, n_eps1, n_inf, n_alpha);
    printf("  %s: worst relative energy error %.3g, momentum error %.3g\n", law->name,
           worst_energy, worst_momentum);
    ENSURE(collided == N_PER_LAW);
    ENSURE(n_eps0 > N_PER_LAW / 20 && n_eps1 > N_PER_LAW / 20 && n_inf > N_PER_LAW / 10);
}

static void test_zmf_random(void) { test_law(&rc_law_zmf, 101); }
static void test_cm_isotropic_random(void) { test_law(&rc_law_cm_isotropic, 102); }

/* Every law in the table passes the law-independent checks (conservation, masses). */
static void test_every_law_conserves(void)
{
    for (size_t l = 0; rc_laws[l]; l++) {
        rc_test_rng r = {103 + l};
        for (int i = 0; i < 2000; i++) {
            config cf;
            random_config(&r, &cf, 1 + i % 3);
            rc_collision_params prm = rc_collision_params_default();
            prm.c = rc_test_c_of(cf.k);
            prm.eps = cf.eps;
            rc_particle out[2] = {cf.b[0], cf.b[1]};
            int st = rc_collide(rc_laws[l], &prm, &out[0], &out[1], cf.n);
            ENSURE_MSG(st == RC_OK, "%s: %s", rc_laws[l]->name, rc_strerror(st));
            if (st == RC_OK) {
                check_conservation(&cf, out);
                check_masses(&cf, out);
                check_subspace(&cf, out);
            }
        }
    }
}

/* Wall: p_n' = -eps_w p_n, tangential kept, energy M kept, rest mass rises by
 * m'^2 - m^2 = (1 - eps_w^2) p_n^2 / c^2, heat = kinetic energy lost. */
static void test_wall_random(void)
{
    rc_test_rng r = {104};
    long n_inf = 0;
    for (int i = 0; i < N_PER_LAW; i++) {
        int dim = 1 + i % 3;
        double m = lu_logu(&r, 0.1, 10.0);
        rc_vec3 v = lu_vec(&r, dim, 1.0), n = lu_unit(&r, dim);
        if (rc_v3_dot(v, n) < 0.0)
            n = rc_v3_scale(-1.0, n);
        if (rc_v3_dot(v, n) < 1e-6) {
            i--;
            continue;
        }
        double x = rc_test_uniform(&r), e = rc_test_uniform(&r);
        double c = x < 0.25 ? INFINITY
                            : 1.01 * rc_v3_norm(v) * (x < 0.35 ? 1.0 : lu_logu(&r, 1.0, 1e6));
        double epsw = e < 0.1 ? 0.0 : (e < 0.2 ? 1.0 : rc_test_uniform(&r)), k;
        ENSURE(rc_inv_c2(c, &k) == RC_OK);
        n_inf += k == 0.0;
        rc_particle b;
        b.m = m;
        ENSURE(rc_momentum_from_velocity(m, v, k, &b.p) == RC_OK);
        rc_particle a = b;
        ENSURE(rc_collide_wall(k, epsw, &a, n) == RC_OK);
        double pn = rc_v3_dot(b.p, n), pn1 = rc_v3_dot(a.p, n), sc = rc_v3_norm(b.p);
        ENSURE_CLOSE(pn1, -epsw * pn, TOL_CONS, sc);
        ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(rc_v3_axpy(a.p, -pn1, n), rc_v3_axpy(b.p, -pn, n))), 0.0,
                     TOL_CONS, sc);
        double M0 = rc_mass_rel(b.m, b.p, k), M1 = rc_mass_rel(a.m, a.p, k);
        ENSURE_CLOSE(M1, M0, TOL_CONS, M0);
        ENSURE(a.m >= b.m);
        if (epsw == 1.0)
            ENSURE(a.m == b.m);
        ENSURE_REL(a.m, sqrt(m * m + (1.0 - epsw * epsw) * pn * pn * k), TOL_MASS);
        double heat = (1.0 - epsw * epsw) * pn * pn / (a.m + b.m); /* (m' - m) c^2 */
        double K0 = rc_kinetic_energy(b.m, b.p, k), K1 = rc_kinetic_energy(a.m, a.p, k);
        ENSURE_CLOSE(K0 - K1, heat, TOL_CONS, K0);
        if (dim < 3)
            ENSURE(a.p.z == 0.0);
        if (dim < 2)
            ENSURE(a.p.y == 0.0);
        /* leaving the wall: no collision, ball untouched (eps_w = 0 leaves p_n' ~ 0 of
         * either sign, so only eps_w > 0) */
        if (epsw > 0.0) {
            rc_particle c2 = a;
            ENSURE(rc_collide_wall(k, epsw, &c2, n) == RC_NO_COLLISION);
            ENSURE(memcmp(&c2, &a, sizeof a) == 0);
        }
    }
    printf("  wall: %d collisions (%ld c=inf)\n", N_PER_LAW, n_inf);
    rc_particle b = {1.0, {1.0, 0, 0}};
    ENSURE(rc_collide_wall(0.0, 1.5, &b, rc_v3(1, 0, 0)) == RC_ERESTITUTION);
    ENSURE(rc_collide_wall(0.0, -0.1, &b, rc_v3(1, 0, 0)) == RC_ERESTITUTION);
    ENSURE(rc_collide_wall(0.0, NAN, &b, rc_v3(1, 0, 0)) == RC_ERESTITUTION);
    ENSURE(b.m == 1.0 && b.p.x == 1.0);
}

/* Boost a ball's four-momentum with the library; the rest mass is invariant. */
static rc_particle boosted(const rc_particle *b, rc_vec3 w, double k)
{
    rc_four f = rc_particle_four(b, k);
    ENSURE(rc_boost(w, k, &f) == RC_OK);
    rc_particle o = {b->m, f.x};
    return o;
}

/* zmf commutes with boosts: collide then boost = boost then collide, the normal in the new
 * frame being the spatial part of the boosted normal four-vector (u.n/c^2, n), normalised.
 * Scale: the largest term of the boosts, gamma_w (|p| + M |w|) over both balls; the
 * library's boost and law each carry ~10 ulp, amplified by <= 2 gamma_w (<= 4.6). */
static void test_zmf_commutes_with_boosts(void)
{
    rc_test_rng r = {105};
    double worst = 0.0;
    for (int i = 0; i < N_BOOST; i++) {
        config cf;
        random_config(&r, &cf, 1 + i % 3);
        rc_vec3 w = lu_vec(&r, 3, isinf(cf.c) ? 2.0 : 0.9 * cf.c);
        rc_collision_params prm = rc_collision_params_default();
        prm.c = rc_test_c_of(cf.k);
        prm.eps = cf.eps;

        rc_particle a = cf.b[0], b = cf.b[1];
        ENSURE(rc_collide(&rc_law_zmf, &prm, &a, &b, cf.n) == RC_OK);
        rc_particle a1 = boosted(&a, w, cf.k), b1 = boosted(&b, w, cf.k);

        double Mt = rc_mass_rel(cf.b[0].m, cf.b[0].p, cf.k) +
                    rc_mass_rel(cf.b[1].m, cf.b[1].p, cf.k);
        rc_vec3 u = rc_v3_scale(1.0 / Mt, rc_v3_add(cf.b[0].p, cf.b[1].p));
        rc_four q = {rc_v3_dot(u, cf.n) * cf.k, cf.n};
        ENSURE(rc_boost(w, cf.k, &q) == RC_OK);
        rc_particle a2 = boosted(&cf.b[0], w, cf.k), b2 = boosted(&cf.b[1], w, cf.k);
        int st = rc_collide(&rc_law_zmf, &prm, &a2, &b2, q.x);
        ENSURE_MSG(st == RC_OK, "boosted frame: %s", rc_strerror(st));
        if (st != RC_OK)
            continue;

        double g = 1.0 / sqrt(1.0 - rc_v3_norm2(w) * cf.k), sc = 0.0;
        for (int j = 0; j < 2; j++)
            sc = lu_max(sc, g * (rc_v3_norm(cf.b[j].p) +
                                 rc_mass_rel(cf.b[j].m, cf.b[j].p, cf.k) * rc_v3_norm(w)));
        ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(a2.p, a1.p)), 0.0, TOL_CONS, sc);
        ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(b2.p, b1.p)), 0.0, TOL_CONS, sc);
        /* the rest masses are invariants: the same in both frames. The boosted inputs
         * carry ~TOL_CONS sc errors, so the ZMF normal momentum pn behind dm2 is known
         * to that, and m' to TOL_CONS sc |pn| / (m' c^2). */
        double pn = fabs(rc_v3_dot(to_zmf(&cf.b[0], u, cf.k).p, zmf_normal(u, cf.n, cf.k)));
        ENSURE_CLOSE(a2.m, a.m, 1.0, TOL_MASS * a.m + TOL_CONS * sc * pn * cf.k / a.m);
        ENSURE_CLOSE(b2.m, b.m, 1.0, TOL_MASS * b.m + TOL_CONS * sc * pn * cf.k / b.m);
        worst = lu_max(worst, rc_v3_norm(rc_v3_sub(a2.p, a1.p)) / sc);
    }
    printf("  zmf boost commutation: worst |dp| / scale = %.3g\n", worst);
}

int main(void)
{
    RUN_TEST(test_zmf_random);
    RUN_TEST(test_cm_isotropic_random);
    RUN_TEST(test_every_law_conserves);
    RUN_TEST(test_wall_random);
    RUN_TEST(test_zmf_commutes_with_boosts);
    RC_TEST_MAIN_END();
}
