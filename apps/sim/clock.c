/* clock.c — a run whose clock cannot resolve its collisions is refused, not run.
 *
 * Event times are doubles: near a time T they are ulp(T) ~ 2.2e-16 T apart. A ball at
 * speed v moves v ulp(T) within one such step; once that is not small against the radii,
 * the order and place of contacts are rounding (at time 1e17 every collision of unit balls
 * at unit speed was decided by the overlap policy). The bound on any ball's speed is
 * min(c, sqrt(2 K / m_min)), K the total kinetic energy at the start (no ball can hold
 * more; heat only takes from it, and for a given kinetic energy the relativistic speed is
 * below the classical one). The threshold, 1e-3 of the smallest radius, is a choice, the
 * same as relcol-toi's (lib/toi_frames.c): it refuses a unit-speed run of unit balls past
 * t ~ 4.5e12 while leaving every run of the data/ and the tests alone. */
#include <float.h>
#include <math.h>

#include "app.h"
#include "clock.h"

int sim_check_clock(const scn_scenario *s, char *err)
{
    const double k2 = isinf(s->c) ? 0.0 : 1.0 / (s->c * s->c);
    double kin = 0.0, m_min = INFINITY, r_min = INFINITY;
    for (size_t i = 0; i < s->n; i++) {
        const rc_sim_ball *b = &s->balls[i];
        const double p2 = rc_v3_dot(b->p, b->p), M = sqrt(b->m * b->m + p2 * k2);
        kin += p2 / (M + b->m); /* ((gamma - 1) m c^2 without cancellation) */
        m_min = fmin(m_min, b->m);
        r_min = fmin(r_min, b->r);
    }
    if (!(kin > 0.0) || !(m_min > 0.0) || !isfinite(r_min))
        return 0; /* (nothing moves, or the reader refuses the balls anyway) */
    const double v_max = fmin(s->c, sqrt(2.0 * kin / m_min));
    const double T = fmax(fabs(s->time), fabs(s->t_end));
    const double step = nextafter(T, INFINITY) - T;
    if (step * v_max <= 1e-3 * r_min)
        return 0;
    app_errf(err, "%s %.17g: doubles near it are %g apart, in which a ball can move up to "
             "%g (speed %g), more than a thousandth of the smallest radius %g: the run's "
             "collisions cannot be resolved there (the clock's origin is free: start near 0)",
             fabs(s->t_end) >= fabs(s->time) ? "t_end" : "time", T, step, step * v_max,
             v_max, r_min);
    return -1;
}
