/* pair_axis.h — two balls' motion along one unit direction e, free of the cancellation of
 * order gamma^2 that the plain formulas suffer when both move near c the same way
 * (papers/zmf-law.md, "Accuracy near c"). Private to the library (the laws use it).
 *
 * Along e each ball has its momentum pe = p.e and its transverse mass T, T^2 = m^2 +
 * |p x e|^2/c^2 = M^2 - pe^2/c^2: (T, pe/c) is a hyperbola point of rapidity y with
 * M = T cosh y, pe/c = T sinh y. Two quantities of the pair are differences of nearly
 * equal numbers when both balls are fast along e:
 *   M1 pe0 - M0 pe1 = T0 T1 c sinh(y0 - y1)     (approach: M0 M1 (v0 - v1).e)
 *   Mt^2 - Pe^2/c^2 = Mt^2 (1 - ue^2/c^2)       (s of the zmf law; 1/gamma^2 of the ZMF)
 * Both are rewritten through T, whose square is a sum of positive terms. */
#ifndef RELCOL_PAIR_AXIS_H
#define RELCOL_PAIR_AXIS_H

#include <math.h>

#include "relcol/kinematics.h"

/* a b - c d to within a few units in the last place of the result, where the plain form
 * loses all its digits when the two products nearly cancel: fma returns each product's
 * rounding error exactly, and the difference of the rounded products is exact when they
 * are that close. Written symmetrically, so that swapping (a, b) with (c, d) negates the
 * result bit for bit (a pair's law gives mirrored bits when its balls are swapped). */
static inline double rc_diff_prod(double a, double b, double c, double d)
{
    const double ab = a * b, cd = c * d;
    return (ab - cd) + (fma(a, b, -ab) - fma(c, d, -cd));
}

/* p x e with every component accurate to its own size: the transverse momentum of a ball
 * moving nearly along e, which the rounding of p.e would swamp in p - (p.e) e. */
static inline rc_vec3 rc_cross_exact(rc_vec3 p, rc_vec3 e)
{
    return rc_v3(rc_diff_prod(p.y, e.z, p.z, e.y), rc_diff_prod(p.z, e.x, p.x, e.z),
                 rc_diff_prod(p.x, e.y, p.y, e.x));
}

/* M0 M1 - p0.p1/c^2 for two balls of rest masses m, momenta p and energies / c^2 M (k =
 * 1/c^2, sqrt_k = 1/c): their four-momenta's product over c^2, = m0 m1 cosh of their
 * relative rapidity >= m0 m1. When p0.p1/c^2 is near M0 M1 (both balls fast the same
 * way) the plain difference keeps only the rounding of its terms, which are gamma^2
 * times the result. Then it is written as (X^2 - Y^2)/(X + Y), X = M0 M1, Y = p0.p1/c^2,
 * with Lagrange's identity (p0.p1)^2 + |p0 x p1|^2 = |p0|^2 |p1|^2 making the numerator
 *   X^2 - Y^2 = m0^2 m1^2 + (m0^2 |p1|^2 + m1^2 |p0|^2)/c^2 + |p0 x p1|^2/c^4,
 * a sum of positive terms; both sides are divided by X (each term a product of ratios
 * m/M and |p|/(c M) <= 1, so that no fourth power overflows) and |p0 x p1| is formed
 * from p0 and p1 scaled by powers of two (exact) with rc_cross_exact, accurate to its own
 * size when the two are nearly parallel. Every rounding is then of a term of the result's
 * own size. Below Y = X/2 the plain form loses a bit at most and is kept. */
static inline double rc_pair_dot(double m0, rc_vec3 p0, double M0, double m1, rc_vec3 p1,
                                 double M1, double k, double sqrt_k)
{
    const double X = M0 * M1, Y = rc_v3_dot(p0, p1) * k;
    if (!(Y > 0.5 * X))
        return X - Y;
    /* Y > 0: both momenta nonzero, and sqrt_k |p| / M in (1/2, 1] for each ball */
    const int e0 = ilogb(rc_v3_norm(p0)), e1 = ilogb(rc_v3_norm(p1));
    const rc_vec3 q0 = rc_v3_scale(ldexp(1.0, -e0), p0), q1 = rc_v3_scale(ldexp(1.0, -e1), p1);
    /* f = sqrt_k 2^e / M: q f = p / (c M), the ball's velocity over c */
    const double f0 = ldexp(sqrt_k, e0) / M0, f1 = ldexp(sqrt_k, e1) / M1;
    const double w0 = m0 / M0, w1 = m1 / M1;
    const double b0 = rc_v3_norm(q0) * f0, b1 = rc_v3_norm(q1) * f1;
    const double x = rc_v3_norm(rc_cross_exact(q0, q1)) * f0 * f1;
    const double r = (w0 * w0 * (w1 * w1 + b1 * b1) + w1 * w1 * b0 * b0 + x * x) / (1.0 + Y / X);
    return X * r;
}

/* The pair along e: energies (relativistic masses) M, momenta along e pe, and T^2. */
typedef struct rc_axis {
    double M0, M1, pe0, pe1, T02, T12;
} rc_axis;

/* M1 pe0 - M0 pe1. With pe0, pe1 of one sign it is (T1 pe0 - T0 pe1) times
 * (T1 pe0 + T0 pe1) / (M1 pe0 + M0 pe1): the difference left is one of rapidities (as
 * well conditioned as the data), the ratio a quotient of sums. Otherwise the plain form
 * adds two terms of one sign. */
static inline double rc_axis_approach(const rc_axis *a)
{
    if (!(a->pe0 * a->pe1 > 0.0))
        return a->M1 * a->pe0 - a->M0 * a->pe1;
    const double T0 = sqrt(a->T02), T1 = sqrt(a->T12);
    const double r = (T1 * a->pe0 + T0 * a->pe1) / (a->M1 * a->pe0 + a->M0 * a->pe1);
    return (T1 * a->pe0 - T0 * a->pe1) * r;
}

/* 1 - (Pe/Mt)^2/c^2 for Pe = pe0 + pe1, Mt = M0 + M1, sqrt_k = 1/c > 0, as
 * (1 - x)(1 + x) with x = |Pe|/(c Mt) and Mt (1 - x) = sum over the balls of M - sigma pe/c
 * (sigma the sign of Pe): M + |pe|/c when the ball moves against Pe, T^2/(M + |pe|/c)
 * when with it. Every term is positive. */
static inline double rc_axis_s(const rc_axis *a, double sqrt_k)
{
    const double Mt = a->M0 + a->M1, Pe = a->pe0 + a->pe1;
    if (Pe == 0.0)
        return 1.0; /* sigma undefined; x = 0 exactly */
    const double q0 = fabs(a->pe0) * sqrt_k, q1 = fabs(a->pe1) * sqrt_k;
    const double h0 = a->pe0 * Pe > 0.0 ? a->T02 / (a->M0 + q0) : a->M0 + q0;
    const double h1 = a->pe1 * Pe > 0.0 ? a->T12 / (a->M1 + q1) : a->M1 + q1;
    return (h0 + h1) / Mt * (1.0 + fabs(Pe) * sqrt_k / Mt);
}

/* When the plain forms are kept. s = 1 - (u.n)^2/c^2 loses log2(1/s) bits, at most ~3.3
 * while (u.n)^2/c^2 <= RC_PAIR_FAST. a0's terms cancel at order gamma^2 only when both
 * balls move fast the same way, which makes the ZMF fast: while one ball's Lorentz factor
 * is at most RC_GAMMA_FAST, or the ZMF's |u|^2/c^2 at most RC_PAIR_FAST, they cancel by a
 * factor ~10 at most. The same bound on the ZMF serves cm-isotropic's boost. Below them
 * the classical path and every slower pair keep their bits; the forms below cost a few
 * times the plain ones. */
#define RC_PAIR_FAST 0.9
#define RC_GAMMA_FAST 3.0

/* The pair's ZMF seen along its total momentum P: what a boost into the ZMF needs, for a
 * pair whose ZMF moves fast (the callers use the plain formulas below RC_PAIR_FAST).
 * d = p0 - M0 u = (M1 p0 - M0 p1)/(M0 + M1) = mu (v0 - v1) is split into its part across
 * P, p0's own transverse momentum t0 (= -t1), formed from p0 x p1 which is accurate to
 * its own size (rc_cross_exact), and its part along P, an approach along uhat
 * (rc_axis_approach). The ZMF's 1/gamma^2 is rc_axis_s along uhat. Ball 0's ZMF momentum
 * is then t0 + g dl uhat. */
typedef struct rc_pair_split {
    rc_vec3 uhat; /* P / |P| */
    rc_vec3 d;    /* t0 + dl uhat */
    rc_vec3 t0;   /* ball 0's momentum across P */
    double dl;    /* d.uhat */
    double g;     /* Lorentz factor of the ZMF */
} rc_pair_split;

/* Trusted input: |P| > 0, sqrt_k = 1/c > 0, M0 and M1 the balls' energies over c^2. */
static inline void rc_pair_split_of(const rc_particle *a, const rc_particle *b, double M0,
                                    double M1, double k, double sqrt_k, rc_pair_split *z)
{
    const rc_vec3 P = rc_v3_add(a->p, b->p);
    const double Pl = rc_v3_norm(P);
    z->uhat = rc_v3_scale(1.0 / Pl, P);
    /* p0 x uhat = (p0 x p1)/|P|: exact for the exact P although P itself is rounded */
    const rc_vec3 w = rc_v3_scale(1.0 / Pl, rc_cross_exact(a->p, b->p));
    const double t2k = rc_v3_norm2(w) * k;
    const rc_axis ax = {M0, M1, rc_v3_dot(a->p, z->uhat), rc_v3_dot(b->p, z->uhat),
                        a->m * a->m + t2k, b->m * b->m + t2k};
    z->dl = rc_axis_approach(&ax) / (M0 + M1);
    z->t0 = rc_v3_cross(z->uhat, w);
    z->d = rc_v3_axpy(z->t0, z->dl, z->uhat);
    z->g = 1.0 / sqrt(rc_axis_s(&ax, sqrt_k));
}

/* |p x n|^2: as |p|^2 - (p.n)^2 when p is at least 45 degrees off n (a bit lost at most),
 * else from the cross product formed to its own accuracy. */
static inline double rc_across2(rc_vec3 p, double pn, rc_vec3 n)
{
    const double p2 = rc_v3_norm2(p);
    return pn * pn <= 0.5 * p2 ? p2 - pn * pn : rc_v3_norm2(rc_cross_exact(p, n));
}

/* The pair along unit n, pn = p.n, M the balls' energies over c^2. */
static inline rc_axis rc_axis_along(const rc_particle *a, const rc_particle *b, rc_vec3 n,
                                    double k, double M0, double M1, double pn0, double pn1)
{
    return (rc_axis){M0, M1, pn0, pn1, a->m * a->m + rc_across2(a->p, pn0, n) * k,
                     b->m * b->m + rc_across2(b->p, pn1, n) * k};
}

/* a0 = (M1 p0.n - M0 p1.n)/(M0 + M1), the zmf law's approach along n (> 0 approaching),
 * for a fast pair (ax = rc_axis_along(...)): without the cancellation of the plain form.
 * Two cancellation-free forms with different weak spots: along n (the rapidity
 * difference along n), poor when the balls move fast across n, whose large transverse
 * masses T then nearly cancel; and d.n with d split along the total momentum, whose
 * rounding (of order |t0| + |dl|) 1/s amplifies when n lies nearly along the motion. Each
 * form's rounding is bounded, in units of 2^-53, by the sizes of the terms it adds: along
 * n, for pn0 pn1 > 0, (T1 |pn0| + T0 |pn1|) r / Mt (rc_axis_approach), otherwise 0 (terms
 * of one sign); the smaller bound wins, and d is formed only when the first is not
 * already within a few units of a0 itself. */
static inline double rc_pair_a0_fast(const rc_particle *a, const rc_particle *b, rc_vec3 n,
                                     double k, double sqrt_k, const rc_axis *ax)
{
    const double M0 = ax->M0, M1 = ax->M1, pn0 = ax->pe0, pn1 = ax->pe1;
    const double Mt = M0 + M1;
    double a0 = rc_axis_approach(ax) / Mt;
    const double tn = sqrt(ax->T12) * fabs(pn0) + sqrt(ax->T02) * fabs(pn1);
    const double err_n = pn0 * pn1 > 0.0 ? tn * tn / (fabs(M1 * pn0 + M0 * pn1) * Mt) : 0.0;
    if (err_n > 8.0 * fabs(a0) && rc_v3_norm2(rc_v3_add(a->p, b->p)) > 0.0) {
        rc_pair_split z;
        rc_pair_split_of(a, b, M0, M1, k, sqrt_k, &z);
        if (rc_v3_norm(z.t0) + fabs(z.dl) < err_n)
            a0 = rc_v3_dot(z.d, n);
    }
    return a0;
}

/* a0 for any pair: the plain form unless both balls are fast and move the same way along
 * n with a fast ZMF (the zmf law's test), where its terms cancel to order gamma^2. */
static inline double rc_pair_a0(const rc_particle *a, const rc_particle *b, rc_vec3 n,
                                double k, double M0, double M1, double pn0, double pn1)
{
    const double Mt = M0 + M1;
    if (!(M0 > RC_GAMMA_FAST * a->m && M1 > RC_GAMMA_FAST * b->m && pn0 * pn1 > 0.0 &&
          rc_v3_norm2(rc_v3_add(a->p, b->p)) * k > RC_PAIR_FAST * Mt * Mt))
        return (M1 * pn0 - M0 * pn1) / Mt;
    const rc_axis ax = rc_axis_along(a, b, n, k, M0, M1, pn0, pn1);
    return rc_pair_a0_fast(a, b, n, k, sqrt(k), &ax);
}

#endif
