/* relcol/gas1d.h — an exact event-driven 1-D gas of elastic point particles between two
 * walls, at any c: only neighbours collide, so the N-1 pair times and two wall times live
 * in a tournament tree (O(log N) an event) and each particle keeps its own clock. Pairs
 * use a two-ball law with eps = 1, walls rc_collide_wall with eps_w = 1; reading never
 * changes the run. Lifecycle: rc_gas1d_def_default, rc_gas1d_create, rc_gas1d_advance /
 * rc_gas1d_step, rc_gas1d_get / _stats_get / _segment_get, rc_gas1d_free. */
#ifndef RELCOL_GAS1D_H
#define RELCOL_GAS1D_H

#include <stddef.h>
#include <stdint.h>
#include "relcol/law.h"

#ifdef __cplusplus
extern "C" {
#endif

/// A 1-D gas (opaque).
typedef struct rc_gas1d rc_gas1d;

/// Definition of a gas: make one with rc_gas1d_def_default() and change fields.
typedef struct rc_gas1d_def {
    size_t n;          ///< number of particles, >= 1
    double length;     ///< box [0, L], 0 < L < inf
    double c;          ///< speed of light, > 0; INFINITY (the default) is classical
    double t0;         ///< start time (finite)
    const double *x;   ///< n positions, 0 <= x[0] < x[1] < ... < x[n-1] <= L
    const double *m;   ///< n rest masses, 0 < m < inf
    const double *p;   ///< n momenta (finite; |v| < c holds by construction)
    const rc_law *law; ///< pair law, called with eps = 1; NULL means rc_law_zmf
} rc_gas1d_def;

/// n = 0, L = 1, classical, t0 = 0, arrays NULL, law NULL.
rc_gas1d_def rc_gas1d_def_default(void);

/// A new gas (the arrays copied): RC_EINVAL (n = 0, NULL arrays, L <= 0, positions outside [0, L] or not increasing: *bad, may be NULL, the index), RC_ENONFINITE, RC_EMASS, RC_ESPEEDOFLIGHT, RC_ENOMEM; *out NULL on failure.
int rc_gas1d_create(const rc_gas1d_def *def, rc_gas1d **out, size_t *bad);
/// Frees and sets *g to NULL (g == NULL and *g == NULL are fine).
void rc_gas1d_free(rc_gas1d **g);

/// Kinds of events.
enum rc_gas1d_event_kind {
    RC_GAS1D_PAIR = 0,       ///< particles i and i + 1 collided
    RC_GAS1D_WALL_LEFT = 1,  ///< particle i = 0 hit the wall at x = 0
    RC_GAS1D_WALL_RIGHT = 2  ///< particle i = n - 1 hit the wall at x = L
};

/// One event.
typedef struct rc_gas1d_event {
    double t;   ///< table time of the event
    double x;   ///< where it happened
    int kind;   ///< enum rc_gas1d_event_kind
    size_t i;   ///< the left particle of a pair, or the particle at the wall
} rc_gas1d_event;

/// The next event if at t <= t_end: RC_OK, *ev (may be NULL); else the time moves to t_end (never back, kept at +inf) and RC_MISS; ties in a fixed order (left wall, pairs left to right, right wall); a pair the law declines waits for one of its particles to change (stats.declined).
int rc_gas1d_step(rc_gas1d *g, double t_end, rc_gas1d_event *ev);

/// Events up to t_end, or max_events of them (0 = no limit; then rc_gas1d_time() < t_end); RC_EINVAL if t_end is NaN or before the gas's time.
int rc_gas1d_advance(rc_gas1d *g, double t_end, uint64_t max_events);

/// Number of particles.
size_t rc_gas1d_count(const rc_gas1d *g);
/// The gas's time.
double rc_gas1d_time(const rc_gas1d *g);

/// Every particle at the gas's time, left to right (x, m, p: n entries each, any may be NULL); positions clamped into [0, L] against round-off.
int rc_gas1d_get(const rc_gas1d *g, double *x, double *m, double *p);

/// Particle i's worldline since its last event (t, x), on x + v (t' - t) until its next: read after each step for the particles it names, these rebuild every worldline exactly (apps/gas/gas_observer.c).
typedef struct rc_gas1d_segment {
    double t, x, m, p, v; ///< the event, rest mass, momentum, and the velocity the engine moves it with
} rc_gas1d_segment;

/// Particle i's segment; RC_EINVAL if g or out is NULL or i >= n.
int rc_gas1d_segment_get(const rc_gas1d *g, size_t i, rc_gas1d_segment *out);

/// Counts and wall impulses so far.
typedef struct rc_gas1d_stats {
    uint64_t pair_events;      ///< pair collisions
    uint64_t wall_events[2];   ///< left, right wall hits
    uint64_t declined;         ///< pair times the law declined (see rc_gas1d_step)
    double wall_impulse[2];    ///< momentum the walls gave (left, right), compensated: total momentum is its start plus these, to round-off
} rc_gas1d_stats;

/// The counts of g into *s.
int rc_gas1d_stats_get(const rc_gas1d *g, rc_gas1d_stats *s);

#ifdef __cplusplus
}
#endif
#endif
