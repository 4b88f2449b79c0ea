/* contacts/rest_masses.c — rest masses after a relativistic joint solve, restored
 * (papers/simultaneous-contacts.md, "Rest masses"): the normal four-impulses keep
 * four-momentum and the restitution conditions but can move rest mass between the balls of
 * an elastic group, by O((v/c)^2) and far more in rare grazing geometries. The balls that
 * took an impulse are taken to their common zero-momentum frame, where their momenta are
 * scaled by one factor lam >= 0 so that each gets its target rest mass m* -- its own m if
 * all its contacts were elastic, else the larger of m and the Newton value (heat is never
 * negative) -- with their total energy unchanged; then back. Total four-momentum is kept
 * (to round-off), the order of the contacts still does not matter, and lam - 1 =
 * O((v/c)^2). RC_ENOCONVERGE when no lam exists (the targets need more than the invariant
 * mass): the caller resolves the contacts one at a time instead. Relativistic groups of two
 * or more contacts only. */
#include <float.h>
#include <math.h>

#include "relcol/kinematics.h"
#include "relcol/status.h"
#include "../pair_axis.h"
#include "private.h"

/* lam is done when the energy sum matches W to a few roundings of its terms */
#define LAM_ROUNDOFF (8.0 * DBL_EPSILON)
#define LAM_MAX_ITER 60

/* The touched balls' zero-momentum frame: velocity u; for a fast one (fast = 1) also its
 * direction uh, speed ul and Lorentz factor g, boosted by hand (to_zmf_fast). */
typedef struct zframe {
    rc_vec3 u, uh;
    double g, ul;
    int fast;
} zframe;

/* mstar[i] the target rest mass of ball i (0: untouched); *Mt, *Pt the touched balls'
 * energy / c^2 and momentum; returns how many balls are touched, *one the last of them. */
static size_t rest_targets(double inv_c2, size_t nb, const rc_particle *b0, size_t k,
                           const rc_contact *c, const int *active, const double *Mp,
                           const rc_vec3 *pp, const double *m2d, double *mstar, double *Mt,
                           rc_vec3 *Pt, size_t *one)
{
    /* mstar[i]: 0 untouched, -1 touched elastically only, -2 touched inelastically */
    for (size_t i = 0; i < nb; i++)
        mstar[i] = 0.0;
    for (size_t j = 0; j < k; j++) {
        if (!active[j])
            continue;
        const double tag = c[j].eps == 1.0 ? -1.0 : -2.0;
        mstar[c[j].a] = fmin(mstar[c[j].a], tag);
        if (c[j].b >= 0)
            mstar[c[j].b] = fmin(mstar[c[j].b], tag);
    }
    *Mt = 0.0;
    *Pt = rc_v3(0, 0, 0);
    size_t touched = 0;
    for (size_t i = 0; i < nb; i++) {
        if (mstar[i] == 0.0)
            continue;
        touched++;
        *one = i;
        *Mt += Mp[i];
        *Pt = rc_v3_add(*Pt, pp[i]);
        /* (m2d: the post rest masses squared without the cancellation, fast_pairs) */
        const double m2 = m2d ? m2d[i] : Mp[i] * Mp[i] - rc_v3_norm2(pp[i]) * inv_c2;
        const double mnew = m2 > 0.0 && Mp[i] > 0.0 ? sqrt(m2) : 0.0; /* not timelike: m */
        mstar[i] = mstar[i] == -1.0 ? b0[i].m : fmax(b0[i].m, mnew);
    }
    return touched;
}

/* A group with a fast pair whose touched balls' ZMF moves near c: the boost there subtracts
 * terms gamma^2 times the result, so it is done on the double-double post states (Mpd,
 * ppd; an impulse-only state may be spacelike, so no rest mass is assumed): with P, M_t
 * their sums, uhat = P/|P|, |u| = |P|/M_t and g = M_t/minv, minv^2 = M_t^2 - |P|^2/c^2, a
 * ball's ZMF momentum is its part across uhat plus g (p.uhat - M |u|) uhat and its energy
 * g (M - |u| p.uhat/c^2). Mp, pp get the ZMF states, *W, *W0 their energies' and targets'
 * sums. */
static int to_zmf_fast(double inv_c2, size_t nb, const ctc_dd *Mpd, const ctc_ddv *ppd,
                       const double *mstar, double *Mp, rc_vec3 *pp, zframe *z, double *W,
                       double *W0)
{
    ctc_dd Md = ctc_dd_of(0.0);
    ctc_ddv Pd = ctc_ddv_of(rc_v3(0, 0, 0));
    for (size_t i = 0; i < nb; i++) {
        if (mstar[i] == 0.0)
            continue;
        Md = ctc_dd_add(Md, Mpd[i]);
        Pd = (ctc_ddv){ctc_dd_add(Pd.x, ppd[i].x), ctc_dd_add(Pd.y, ppd[i].y),
                       ctc_dd_add(Pd.z, ppd[i].z)};
    }
    const ctc_dd P2 = ctc_ddv_norm2(Pd), Pl = ctc_dd_sqrt(P2);
    const ctc_dd mi2 = ctc_dd_sub(ctc_dd_mul(Md, Md), ctc_dd_mul_d(P2, inv_c2));
    if (!(mi2.hi > 0.0))
        return RC_ENOCONVERGE;
    const double g = ctc_dd_div(Md, ctc_dd_sqrt(mi2)).hi;
    const ctc_dd uld = ctc_dd_div(Pl, Md); /* |u| */
    z->g = g;
    z->ul = uld.hi;
    z->uh = rc_v3_scale(1.0 / Pl.hi, rc_v3(Pd.x.hi, Pd.y.hi, Pd.z.hi));
    z->u = rc_v3_scale(z->ul, z->uh);
    /* uhat to double-double (a double one is off unit length by 2^-53, which the parts
     * along it would carry into the ZMF times gamma) */
    const ctc_ddv uhd = {ctc_dd_div(Pd.x, Pl), ctc_dd_div(Pd.y, Pl), ctc_dd_div(Pd.z, Pl)};
    for (size_t i = 0; i < nb; i++) {
        if (mstar[i] == 0.0)
            continue;
        const ctc_dd pl = ctc_ddv_dot(ppd[i], uhd);
        const ctc_ddv pt = {ctc_dd_sub(ppd[i].x, ctc_dd_mul(pl, uhd.x)),
                            ctc_dd_sub(ppd[i].y, ctc_dd_mul(pl, uhd.y)),
                            ctc_dd_sub(ppd[i].z, ctc_dd_mul(pl, uhd.z))};
        const ctc_dd zl = ctc_dd_mul_d(ctc_dd_sub(pl, ctc_dd_mul(Mpd[i], uld)), g);
        const ctc_dd Mz =
            ctc_dd_mul_d(ctc_dd_sub(Mpd[i], ctc_dd_mul_d(ctc_dd_mul(uld, pl), inv_c2)), g);
        pp[i] = rc_v3_axpy(rc_v3(pt.x.hi, pt.y.hi, pt.z.hi), zl.hi, z->uh);
        Mp[i] = Mz.hi;
        *W += Mp[i];
        *W0 += mstar[i];
    }
    return RC_OK;
}

/* The same by the plain boost by z->u. */
static int to_zmf(double inv_c2, size_t nb, const double *mstar, double *Mp, rc_vec3 *pp,
                  const zframe *z, double *W, double *W0)
{
    for (size_t i = 0; i < nb; i++) {
        if (mstar[i] == 0.0)
            continue;
        rc_four f = {Mp[i], pp[i]};
        if (rc_boost(z->u, inv_c2, &f) != RC_OK)
            return RC_ENOCONVERGE;
        Mp[i] = f.t;
        pp[i] = f.x;
        *W += f.t;
        *W0 += mstar[i];
    }
    return RC_OK;
}

/* The scale lam of the ZMF momenta pp that gives the targets mstar the energy W:
 * sum_i sqrt(m*_i^2 + lam^2 |p_i|^2/c^2) = W, increasing and convex in lam, so Newton from
 * lam = 1 steps past the root at most once, then descends to it monotonically. */
static int solve_lam(double inv_c2, size_t nb, const double *mstar, const rc_vec3 *pp,
                     double W, double *lamout)
{
    double lam = 1.0;
    int it = 0;
    for (; it < LAM_MAX_ITER; it++) {
        double f = -W, df = 0.0, scale = W;
        for (size_t i = 0; i < nb; i++) {
            if (mstar[i] == 0.0)
                continue;
            const double s2 = rc_v3_norm2(pp[i]) * inv_c2;
            const double e = sqrt(mstar[i] * mstar[i] + lam * lam * s2);
            f += e;
            scale += e;
            df += lam * s2 / e;
        }
        /* energy matched to round-off of the sum */
        if (fabs(f) <= LAM_ROUNDOFF * scale)
            break;
        if (!(df > 0.0))
            return RC_ENOCONVERGE;
        double next = lam - f / df;
        if (next < 0.0)
            next = 0.5 * lam;
        lam = next;
    }
    if (it == LAM_MAX_ITER || !isfinite(lam))
        return RC_ENOCONVERGE;
    *lamout = lam;
    return RC_OK;
}

/* Each touched ball at its target rest mass with its ZMF momentum scaled by lam, boosted
 * back to the given frame (into Mp, pp). */
static int scale_back(double inv_c2, size_t nb, const double *mstar, double lam,
                      const zframe *z, double *Mp, rc_vec3 *pp)
{
    const rc_vec3 back = rc_v3_scale(-1.0, z->u);
    for (size_t i = 0; i < nb; i++) {
        if (mstar[i] == 0.0)
            continue;
        const rc_vec3 p = rc_v3_scale(lam, pp[i]);
        rc_four f = {sqrt(mstar[i] * mstar[i] + rc_v3_norm2(p) * inv_c2), p};
        if (z->fast) {
            /* back without g^2 |u|^2/c^2 = g^2 - 1, which g and |u| rounded apart break */
            const double pl = rc_v3_dot(f.x, z->uh);
            const rc_vec3 pt = rc_v3_axpy(f.x, -pl, z->uh);
            const double E = z->g * (f.t + z->ul * pl * inv_c2);
            f.x = rc_v3_axpy(pt, z->g * (pl + f.t * z->ul), z->uh);
            f.t = E;
        } else if (rc_boost(back, inv_c2, &f) != RC_OK) {
            return RC_ENOCONVERGE;
        }
        Mp[i] = f.t;
        pp[i] = f.x;
    }
    return RC_OK;
}

int ctc_keep_rest_masses(double inv_c2, size_t nb, const rc_particle *b0, size_t k,
                         const rc_contact *c, const int *active, double *Mp, rc_vec3 *pp,
                         const ctc_dd *Mpd, const ctc_ddv *ppd, const double *m2d,
                         double *mstar)
{
    double Mt;
    rc_vec3 Pt;
    size_t one = 0;
    const size_t touched =
        rest_targets(inv_c2, nb, b0, k, c, active, Mp, pp, m2d, mstar, &Mt, &Pt, &one);
    /* One ball against walls only (a corner): the walls' impulses (q = (0, n)) leave its
     * energy as it was, so nothing moves between balls and its rest mass is its target
     * with the impulses' momentum. Its zero-momentum frame is its own rest frame, where
     * its momentum is round-off: scaling that to absorb an energy mismatch of round-off
     * gave a corner hit at c = 1 a speed 1e-7 too high (found by fuzzing the engine) or
     * no solution at all (a fallback). */
    if (touched == 1) {
        Mp[one] = sqrt(mstar[one] * mstar[one] + rc_v3_norm2(pp[one]) * inv_c2);
        return RC_OK;
    }
    zframe z = {rc_v3_scale(1.0 / Mt, Pt), rc_v3(0, 0, 0), 0.0, 0.0, 0};
    z.fast = Mpd && rc_v3_norm2(Pt) * inv_c2 > RC_PAIR_FAST * Mt * Mt;
    double W = 0.0, W0 = 0.0, lam;
    const int st = z.fast ? to_zmf_fast(inv_c2, nb, Mpd, ppd, mstar, Mp, pp, &z, &W, &W0)
                          : to_zmf(inv_c2, nb, mstar, Mp, pp, &z, &W, &W0);
    if (st != RC_OK)
        return st;
    if (!(W0 < W))
        return RC_ENOCONVERGE;
    if (solve_lam(inv_c2, nb, mstar, pp, W, &lam) != RC_OK)
        return RC_ENOCONVERGE;
    return scale_back(inv_c2, nb, mstar, lam, &z, Mp, pp);
}
