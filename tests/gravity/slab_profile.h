/* slab_profile.h — a gas in a field read in NBIN slabs along z over snapshots: per slab the
 * count, theta along the field <p_z v_z>, across it <p_x v_x + p_y v_y>/2 and the lapse-weighted
 * (1 + g z/c^2) <p.v>/3, each mean with the snapshots' scatter as its error, and chi^2 against
 * a profile or the pooled mean. Shared by test_gravity_relax and notebook 10. */
#ifndef RELCOL_TESTS_SLAB_PROFILE_H
#define RELCOL_TESTS_SLAB_PROFILE_H

#include <stddef.h>
#include <stdint.h>

#include <relcol/relcol.h>

enum { NBIN = 10 };

typedef struct prof {
    double s[4][NBIN], s2[4][NBIN]; /* per snapshot: count, theta_z, theta_perp, lapse theta */
    double zs[NBIN];
    long zn[NBIN];
    int snaps;
    double start[NBIN]; /* the start's counts */
    double eerr;        /* |change of H - booked| / |H| over the run (papers/gravity.md s. 4) */
    uint64_t coll;      /* collisions (ball and wall contacts) */
} prof;

static inline void snapshot(rc_sim *s, double g, double ic2, prof *P)
{
    double cnt[NBIN] = {0}, tz[NBIN] = {0}, tp[NBIN] = {0}, lt[NBIN] = {0};
    for (size_t i = 0; i < rc_sim_count(s); i++) {
        rc_sim_ball b;
        rc_sim_get_ball(s, i, &b);
        const int k = (int)(b.x.z * NBIN);
        if (k < 0 || k >= NBIN)
            continue;
        const rc_vec3 v = rc_velocity(b.m, b.p, ic2);
        cnt[k]++;
        tz[k] += b.p.z * v.z;
        tp[k] += 0.5 * (b.p.x * v.x + b.p.y * v.y);
        lt[k] += (1.0 + g * b.x.z * ic2) * rc_v3_dot(b.p, v) / 3.0;
        P->zs[k] += b.x.z;
        P->zn[k]++;
    }
    for (int k = 0; k < NBIN; k++) {
        const double q[4] = {cnt[k], tz[k] / cnt[k], tp[k] / cnt[k], lt[k] / cnt[k]};
        for (int j = 0; j < 4; j++) {
            P->s[j][k] += q[j];
            P->s2[j][k] += q[j] * q[j];
        }
    }
    P->snaps++;
}

static inline void mean_err(const prof *P, int j, int k, double *m, double *var)
{
    const double S = P->snaps;
    *m = P->s[j][k] / S;
    *var = (P->s2[j][k] / S - *m * *m) / (S - 1.0);
}

static inline double zmean(const prof *P, int k) { return P->zs[k] / P->zn[k]; }

/* chi^2 of quantity j against want[k] (want NULL: its weighted mean, returned in *fit) */
static inline double chi2_of(const prof *P, int j, const double *want, double *fit)
{
    double sw = 0, swy = 0, chi = 0;
    for (int k = 0; k < NBIN; k++) {
        double m, v;
        mean_err(P, j, k, &m, &v);
        sw += 1 / v, swy += m / v;
    }
    const double c = swy / sw;
    for (int k = 0; k < NBIN; k++) {
        double m, v;
        mean_err(P, j, k, &m, &v);
        const double d = m - (want ? want[k] : c);
        chi += d * d / v;
    }
    if (fit)
        *fit = c;
    return chi;
}

#endif
