/* relcol/gas1d.h — an exact event-driven 1-D gas of elastic point particles in a box.
 *
 * N point particles with individual rest masses move on [0, L] between two reflecting
 * walls, at any c (c = INFINITY classical). In 1-D point particles keep their order,
 * so only neighbours collide: the N-1 neighbour-pair times and the two wall times live in a
 * tournament tree (O(log N) per event), and each particle keeps a local clock (its state
 * is stored at its last event), so an event touches two particles and a handful of tree
 * leaves. Pair collisions use a two-ball law (default rc_law_zmf, which in 1-D is seed
 * 000's relativistic elastic collision) with eps = 1; walls use rc_collide_wall with
 * eps_w = 1. Reading the state never changes the trajectory: runs are bit-identical
 * however often they are sampled.
 *
 * Lifecycle: fill an rc_gas1d_def from rc_gas1d_def_default(), rc_gas1d_create,
 * rc_gas1d_advance / rc_gas1d_step, read with rc_gas1d_get / rc_gas1d_stats_get (and a
 * particle's worldline since its last event with rc_gas1d_segment_get), rc_gas1d_free.
 * Units: positions and L in one length unit, momenta p = m gamma v. */
#ifndef RELCOL_GAS1D_H
#define RELCOL_GAS1D_H

#include <stddef.h>
#include <stdint.h>
#include "relcol/law.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rc_gas1d rc_gas1d;

typedef struct rc_gas1d_def {
    size_t n;          /* number of particles, >= 1 */
    double length;     /* box [0, L], 0 < L < inf */
    double c;          /* speed of light, > 0; INFINITY (the default) is classical */
    double t0;         /* start time (finite) */
    const double *x;   /* n positions, 0 <= x[0] < x[1] < ... < x[n-1] <= L */
    const double *m;   /* n rest masses, 0 < m < inf */
    const double *p;   /* n momenta (finite; |v| < c holds by construction) */
    const rc_law *law; /* pair law, called with eps = 1; NULL means rc_law_zmf */
} rc_gas1d_def;

/* n = 0, L = 1, classical, t0 = 0, arrays NULL, law NULL. */
rc_gas1d_def rc_gas1d_def_default(void);

/* Copies the arrays. RC_EINVAL: n = 0, NULL arrays, L <= 0, positions outside [0, L] or
 * not strictly increasing (*bad, may be NULL, gets the particle index);
 * RC_ENONFINITE: a NaN/inf input; RC_EMASS: m <= 0; RC_ESPEEDOFLIGHT: bad c;
 * RC_ENOMEM. On failure *out is NULL. */
int rc_gas1d_create(const rc_gas1d_def *def, rc_gas1d **out, size_t *bad);
/* Frees and sets *g to NULL (g == NULL and *g == NULL are fine). */
void rc_gas1d_free(rc_gas1d **g);

enum rc_gas1d_event_kind {
    RC_GAS1D_PAIR = 0,       /* particles i and i + 1 collided */
    RC_GAS1D_WALL_LEFT = 1,  /* particle i = 0 hit the wall at x = 0 */
    RC_GAS1D_WALL_RIGHT = 2  /* particle i = n - 1 hit the wall at x = L */
};

typedef struct rc_gas1d_event {
    double t;   /* table time of the event */
    double x;   /* where it happened */
    int kind;   /* enum rc_gas1d_event_kind */
    size_t i;   /* the left particle of a pair, or the particle at the wall */
} rc_gas1d_event;

/* Process the next event if it happens at a time <= t_end: RC_OK and *ev (may be NULL)
 * describes it. Otherwise move the gas's time to t_end (never backwards; it stays put
 * if t_end = +inf) and return RC_MISS. Ties are broken by a fixed order (left wall, pairs left to right, right
 * wall). A pair the law declines (round-off grazing) is dropped without an event until
 * one of its particles changes (counted in rc_gas1d_stats.declined). */
int rc_gas1d_step(rc_gas1d *g, double t_end, rc_gas1d_event *ev);

/* Process events up to t_end; RC_OK. Stops early after max_events events (0 = no limit):
 * then rc_gas1d_time() < t_end (t_end = +inf with max_events runs a number of events). RC_EINVAL if t_end is NaN or before the gas's time. */
int rc_gas1d_advance(rc_gas1d *g, double t_end, uint64_t max_events);

size_t rc_gas1d_count(const rc_gas1d *g);
double rc_gas1d_time(const rc_gas1d *g);

/* State of every particle at the gas's time, in order left to right (x, m, p each of n
 * entries, any may be NULL). Positions are clamped into [0, L] against round-off. */
int rc_gas1d_get(const rc_gas1d *g, double *x, double *m, double *p);

/* Particle i's worldline since its last event: it left the event (t, x) -- its last pair
 * collision or wall hit, or (t0, its start) -- with rest mass m, momentum p and velocity v,
 * and moves on the line x + v (t' - t) until its next event. Read after each
 * rc_gas1d_step for the particles its event names, these segments rebuild every worldline
 * exactly (a moving observer's hyperplanes cut them anywhere, not at common table times:
 * apps/gas/gas_observer.c). v is the velocity the engine moves the particle with. */
typedef struct rc_gas1d_segment {
    double t, x, m, p, v;
} rc_gas1d_segment;

/* RC_EINVAL if g or out is NULL or i >= n. Never changes the trajectory. */
int rc_gas1d_segment_get(const rc_gas1d *g, size_t i, rc_gas1d_segment *out);

typedef struct rc_gas1d_stats {
    uint64_t pair_events;      /* pair collisions */
    uint64_t wall_events[2];   /* left, right wall hits */
    uint64_t declined;         /* pair times the law declined (see rc_gas1d_step) */
    /* momentum the walls gave the particles (left, right), compensated sums: the total
     * momentum is its initial value plus these two, to round-off */
    double wall_impulse[2];
} rc_gas1d_stats;

int rc_gas1d_stats_get(const rc_gas1d *g, rc_gas1d_stats *s);

#ifdef __cplusplus
}
#endif
#endif
