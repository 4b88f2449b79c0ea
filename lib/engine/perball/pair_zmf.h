/* engine/perball/pair_zmf.h — per_ball frames: two balls' straight cylinders (their
 * stored lines) seen from the pair's ZMF, to bound where the frame would put their
 * contact event X before it is asked (glue_pair.h glue_back, zmf_group.c try_join). Asked
 * from a reference where the cylinders are apart, the frame's X is the point of their
 * intersection S that comes first in the pair's ZMF. Stretched along the ZMF relative
 * velocity by ball i's Lorentz factor there, ball i is a sphere r_i and ball k lies
 * between the spheres r_k and r_k gi / gk; so X's ZMF time lies between the first
 * contacts of the outer and of the inner spheres (the inner spheres' contact point is a
 * point of S), and with equal factors (equal rest masses) X is that point. Bounds only:
 * the callers skip a question whose answer these prove useless, and keep its bits. */
#ifndef RELCOL_ENGINE_PAIR_ZMF_H
#define RELCOL_ENGINE_PAIR_ZMF_H

#include <math.h>

#include "../private.h"

/* Boosts within this Lorentz factor of the pair's ZMF (gamma_u^2 = 1 / (1 - the bound))
 * keep this arithmetic's rounding far below the margins its callers allow. */
#define ENG_ZPAIR_U2_MAX 0.9999

/* Origin: ball i's centre event at the reference (its time T, dx = k's centre - i's then,
 * nearest image). T(P) = t - u.y / c^2 is the ZMF time over gamma_u. */
typedef struct eng_zpair {
    double k2, gu, G; /* 1/c^2, gamma_u, gamma_u^2 / c^2 / (gamma_u + 1) */
    rc_vec3 u;        /* the pair's ZMF velocity */
    rc_vec3 vzi;      /* ball i's velocity in the ZMF */
    rc_vec3 e;        /* unit, along the ZMF relative velocity w = v_k' - v_i' */
    double wn;        /* |w| */
    double gi, gk;    /* Lorentz factors in the ZMF */
    rc_vec3 Ds, ws;   /* k - i at ZMF time tau, stretched by gi along e: Ds + tau ws */
} eng_zpair;

/* 0 where the bounds do not apply (a ZMF too fast for them, no relative motion). */
static inline int eng_zpair_make(const rc_sim *s, const eng_ball *bi, const eng_ball *bk,
                                 rc_vec3 dx, eng_zpair *z)
{
    const double k2 = s->inv_c2;
    const eng_aux *ai = &s->a[bi - s->b], *ak = &s->a[bk - s->b];
    const double Mi = eng_mass_rel(ai->m, ai->p, k2), Mk = eng_mass_rel(ak->m, ak->p, k2);
    const rc_vec3 u = rc_v3_scale(1.0 / (Mi + Mk), rc_v3_add(ai->p, ak->p));
    const double u2k = rc_v3_norm2(u) * k2;
    if (!(u2k < ENG_ZPAIR_U2_MAX))
        return 0;
    const double gu = 1.0 / sqrt(1.0 - u2k), G = gu * gu * k2 / (gu + 1.0);
    /* ZMF momenta (p + (G u.p - gu M) u), energies as masses, velocities */
    const double upi = rc_v3_dot(u, ai->p), upk = rc_v3_dot(u, ak->p);
    const double Mzi = gu * (Mi - k2 * upi), Mzk = gu * (Mk - k2 * upk);
    const rc_vec3 vzi = rc_v3_scale(1.0 / Mzi, rc_v3_axpy(ai->p, G * upi - gu * Mi, u));
    const rc_vec3 vzk = rc_v3_scale(1.0 / Mzk, rc_v3_axpy(ak->p, G * upk - gu * Mk, u));
    /* k's centre event (0, dx) in the ZMF: (-gu u.dx / c^2, dx + G (u.dx) u) */
    const double udx = rc_v3_dot(u, dx), tk0 = -gu * k2 * udx;
    const rc_vec3 w = rc_v3_sub(vzk, vzi);
    const rc_vec3 D0 = rc_v3_axpy(rc_v3_axpy(dx, G * udx, u), -tk0, vzk);
    z->wn = rc_v3_norm(w);
    z->gi = Mzi / ai->m;
    z->gk = Mzk / ak->m;
    if (!(z->wn > 0.0) || !(z->gi > 0.0) || !(z->gk > 0.0))
        return 0;
    z->k2 = k2;
    z->gu = gu;
    z->G = G;
    z->u = u;
    z->vzi = vzi;
    z->e = rc_v3_scale(1.0 / z->wn, w);
    z->Ds = rc_v3_axpy(D0, (z->gi - 1.0) * rc_v3_dot(z->e, D0), z->e);
    z->ws = rc_v3_scale(z->gi, w);
    return 1;
}

/* The first ZMF time at which the stretched centres are R apart (*tau); 0 if they never
 * are (or only touch). */
static inline int eng_zpair_entry(const eng_zpair *z, double R, double *tau)
{
    const double A = rc_v3_norm2(z->ws), B = rc_v3_dot(z->Ds, z->ws);
    const double disc = B * B - A * (rc_v3_norm2(z->Ds) - R * R);
    if (!(disc > 0.0))
        return 0;
    *tau = (-B - sqrt(disc)) / A;
    return 1;
}

/* The inner spheres' contact point at ZMF time tau (ri: ball i's radius, R their distance
 * then), as a table event relative to the origin: time *t, position *y. */
static inline void eng_zpair_point(const eng_zpair *z, double ri, double R, double tau,
                                   double *t, rc_vec3 *y)
{
    const rc_vec3 eh = rc_v3_scale(1.0 / R, rc_v3_axpy(z->Ds, tau, z->ws));
    const rc_vec3 off = rc_v3_axpy(eh, (1.0 / z->gi - 1.0) * rc_v3_dot(z->e, eh), z->e);
    const rc_vec3 yz = rc_v3_axpy(rc_v3_scale(tau, z->vzi), ri, off);
    const double uy = rc_v3_dot(z->u, yz);
    *t = z->gu * (tau + z->k2 * uy);
    *y = rc_v3_axpy(yz, z->G * uy + z->gu * tau, z->u);
}

#endif
