/* kinetic.h — the Boltzmann (dilute-gas) collision kernels of relcol's three contact
 * frames for a 2-D gas of equal discs (rest mass 1, rest radius r, c = 1), written as what
 * the Boltzmann collision integral needs: the rate of a pair's collisions per unit table
 * time, per unit angle of the normal parameter phi, and the collision map at fixed phi
 * (header only; shared by notebook 08 and tests/gas2d). Derivation: notebook 08.
 *
 * A pair (p0, p1) with contact normal n (from ball 0 to ball 1) approaches when
 * (v0 - v1).n > 0. Seen from ball 0 the two rigid shapes translate, so ball 1's centre
 * crosses the boundary of the Minkowski sum K0 + K1, whose length per unit angle of its
 * outward normal is rho0(n) + rho1(n) (rho: a shape's radius of curvature where its
 * outward normal is n). Hence, per unit phi:
 *   sphere  phi = table normal angle, W = 2 r (v0 - v1).n                (discs)
 *   table   phi = table normal angle, W = (rho0(n) + rho1(n)) (v0 - v1).n
 *           (ellipses contracted along their table velocities: semi-axes r across v and
 *           r/gamma along v, support h(n) = r sqrt(1 - (v.n)^2), rho = r^2 (r/gamma)^2/h^3)
 *   zmf     phi = normal angle in the pair's zero-momentum frame (starred),
 *           W = (E0* E1* / (E0 E1)) (rho0*(n*) + rho1*(n*)) (v0* - v1*).n*
 *           (the rate is found in the ZMF and carried to the table by the invariance of
 *           the number of collisions per unit volume and time: a beam's density is
 *           proportional to its energy, so n0* n1* = n0 n1 E0* E1* / (E0 E1)).
 * and W = 0 when the pair does not approach. The map is relcol's zmf law (rc_law_zmf,
 * eps = 1) along n; for the zmf kernel along the table normal whose four-vector is the
 * boost of (0, n*) -- the engine's zmf frame (lib/toi_zmf.c) -- which in the ZMF reverses
 * the momenta's n*-components. At fixed phi each map is an involution. */
#ifndef RELCOL_GAS_KINETIC_H
#define RELCOL_GAS_KINETIC_H

#include <math.h>

#include "relcol/relcol.h"

typedef enum { KN_SPHERE, KN_TABLE, KN_ZMF } kn_kernel;

static const char *const kn_kernel_name[] = {"sphere", "table", "zmf"};

static inline double kn_energy(rc_vec3 p) { return sqrt(1.0 + rc_v3_norm2(p)); }

/* Radius of curvature at outward normal n of a disc of rest radius r with momentum p
 * (mass 1, c = 1): r uncontracted, the contracted ellipse's a^2 b^2 / h(n)^3 otherwise. */
static inline double kn_rho(double r, rc_vec3 p, rc_vec3 n, int contracted)
{
    if (!contracted)
        return r;
    const double E = kn_energy(p), vn = rc_v3_dot(p, n) / E, b = r / E;
    const double h = r * sqrt((1.0 - vn) * (1.0 + vn));
    return r * r * b * b / (h * h * h);
}

/* The pair's zero-momentum-frame velocity u and both four-momenta seen there. */
static inline int kn_to_zmf(rc_vec3 p0, rc_vec3 p1, rc_vec3 *u, rc_four *q0, rc_four *q1)
{
    const double E0 = kn_energy(p0), E1 = kn_energy(p1);
    *u = rc_v3_scale(1.0 / (E0 + E1), rc_v3_add(p0, p1));
    *q0 = (rc_four){E0, p0};
    *q1 = (rc_four){E1, p1};
    int st = rc_boost(*u, 1.0, q0);
    return st != RC_OK ? st : rc_boost(*u, 1.0, q1);
}

/* Rate per unit table time, per unit phi, of the pair's collisions (0 if it does not
 * approach along the normal that phi names); NAN if a boost fails. */
static inline double kn_rate(kn_kernel k, double r, rc_vec3 p0, rc_vec3 p1, double phi)
{
    const rc_vec3 e = rc_v3(cos(phi), sin(phi), 0.0);
    if (k != KN_ZMF) {
        const double E0 = kn_energy(p0), E1 = kn_energy(p1);
        const double an = rc_v3_dot(p0, e) / E0 - rc_v3_dot(p1, e) / E1;
        if (!(an > 0.0))
            return 0.0;
        const int con = k == KN_TABLE;
        return (kn_rho(r, p0, e, con) + kn_rho(r, p1, e, con)) * an;
    }
    rc_vec3 u;
    rc_four q0, q1;
    if (kn_to_zmf(p0, p1, &u, &q0, &q1) != RC_OK)
        return NAN;
    const double an = rc_v3_dot(q0.x, e) / q0.t - rc_v3_dot(q1.x, e) / q1.t;
    if (!(an > 0.0))
        return 0.0;
    const double moller = q0.t * q1.t / (kn_energy(p0) * kn_energy(p1));
    return moller * (kn_rho(r, q0.x, e, 1) + kn_rho(r, q1.x, e, 1)) * an;
}

/* The table-frame normal the law is given for parameter phi. */
static inline int kn_normal(kn_kernel k, rc_vec3 p0, rc_vec3 p1, double phi, rc_vec3 *n)
{
    const rc_vec3 e = rc_v3(cos(phi), sin(phi), 0.0);
    if (k != KN_ZMF) {
        *n = e;
        return RC_OK;
    }
    rc_vec3 u;
    rc_four q0, q1, qn = {0.0, e};
    int st = kn_to_zmf(p0, p1, &u, &q0, &q1);
    if (st == RC_OK)
        st = rc_boost(rc_v3_scale(-1.0, u), 1.0, &qn);
    if (st == RC_OK)
        *n = rc_v3_scale(1.0 / rc_v3_norm(qn.x), qn.x);
    return st;
}

/* The collision map at fixed phi: the elastic zmf law along kn_normal(), for either
 * orientation of the pair (the law changes only pairs that approach along its normal,
 * and its impulse J n is even in n). */
static inline int kn_collide(kn_kernel k, rc_vec3 *p0, rc_vec3 *p1, double phi)
{
    rc_vec3 n;
    int st = kn_normal(k, *p0, *p1, phi, &n);
    if (st != RC_OK)
        return st;
    rc_collision_params prm = rc_collision_params_default();
    prm.c = 1.0;
    prm.eps = 1.0;
    rc_particle a = {1.0, *p0}, b = {1.0, *p1};
    st = rc_law_zmf.collide(&prm, &a, &b, n);
    if (st == RC_NO_COLLISION) /* receding along n: approaching along -n, the same map */
        st = rc_law_zmf.collide(&prm, &a, &b, rc_v3_scale(-1.0, n));
    if (st == RC_OK) {
        *p0 = a.p;
        *p1 = b.p;
    }
    return st;
}

/* Gain and loss of momentum p0 = (s0, 0) under the 2-D Jüttner law at theta,
 * f = e^(-(E-1)/theta) / (2 pi theta (1 + theta)):
 *   L(p0) = f(p0) Int d^2p1 f(p1) Int dphi W(p0, p1, phi)
 *   G(p0) = Int d^2p1 Int dphi W(T(p0, p1), phi) f(T0) f(T1) E_T0 E_T1 / (E0 E1)
 * (the pre-collision states T(p0, p1) that phi's collision sends to (p0, p1): the
 * involution substituted, with its Jacobian). One midpoint rule for both, ny x na x nphi
 * nodes: y = 1 - e^(-(E1-1)/theta) in (0, 1), the angle of p1, and phi (nphi even, so
 * phi + pi is a node: a pair that recedes along phi approaches along phi + pi, where L
 * counts it). NAN in both on a failed collision. */
static inline void kn_gain_loss(kn_kernel k, double r, double theta, double s0, int ny,
                                int na, int nphi, double *G, double *L)
{
    const rc_vec3 p0 = rc_v3(s0, 0.0, 0.0);
    const double E0 = kn_energy(p0), Z = 2.0 * M_PI * theta * (1.0 + theta);
    double g = 0.0, l = 0.0;
    for (int iy = 0; iy < ny; iy++) {
        const double y = (iy + 0.5) / ny, x = -theta * log1p(-y), E1 = 1.0 + x;
        const double s1 = sqrt(x * (x + 2.0));
        /* f(p1) d^2p1 = E1 dy dalpha / (2 pi (1 + theta)) */
        const double w1 = E1 / (2.0 * M_PI * (1.0 + theta)) / ny * (2.0 * M_PI / na) *
                          (2.0 * M_PI / nphi);
        const double f1 = exp(-x / theta) / Z;
        for (int ia = 0; ia < na; ia++) {
            const double a = 2.0 * M_PI * (ia + 0.5) / na;
            const rc_vec3 p1 = rc_v3(s1 * cos(a), s1 * sin(a), 0.0);
            for (int ip = 0; ip < nphi; ip++) {
                const double phi = 2.0 * M_PI * (ip + 0.5) / nphi;
                l += w1 * kn_rate(k, r, p0, p1, phi);
                rc_vec3 q0 = p0, q1 = p1;
                if (kn_collide(k, &q0, &q1, phi) != RC_OK) {
                    *G = *L = NAN;
                    return;
                }
                const double F0 = kn_energy(q0), F1 = kn_energy(q1);
                const double fT = exp(-(F0 - 1.0) / theta) / Z * exp(-(F1 - 1.0) / theta) / Z;
                g += w1 / f1 * kn_rate(k, r, q0, q1, phi) * fT * F0 * F1 / (E0 * E1);
            }
        }
    }
    *G = g;
    *L = l * exp(-(E0 - 1.0) / theta) / Z;
}

#endif
