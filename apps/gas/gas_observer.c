/* gas_observer.c — sampling a gas on a moving observer's simultaneity hyperplanes from the
 * balls' worldlines (gas_observer.h): rebuilt from grid states and proper times (2-D/3-D
 * engine) or followed event by event (1-D gas). c = 1 units inside: velocities v/c,
 * times c t. */
#include <math.h>
#include <stdlib.h>

#include "gas_observer.h"
#include "relcol/status.h"

/* Round-off allowance, relative to the grid step, for deciding whether a ball's last
 * collision lies inside the last grid interval and whether the straight lines before and
 * after it meet: proper times and positions are accumulated over many events, each
 * rounding at ~1e-16, so 1e-9 separates round-off from a real second collision (which
 * moves the meeting point by a fraction of a diameter). */
#define OBS_TOL 1e-9

typedef struct ball_state {
    double t, x, y, px, py, E, tau; /* at the last grid time; x, y unwrapped; E = gamma m */
    double vx;                      /* 1-D: the engine's velocity on the current segment */
    size_t next;                    /* the next hyperplane it crosses */
    int started;
} ball_state;

struct gas_obs {
    size_t n, nplanes;
    double c, V, gV, tau0, dtau;
    ball_state *s;
    double *mom; /* 2 * nplanes * n */
    uint64_t taken, lost;
};

gas_obs *gas_obs_create(size_t n, double c, double V, double tau0, double dtau, size_t nplanes)
{
    if (!(n > 0) || !(c > 0.0) || !isfinite(c) || !(fabs(V) < c) || !(dtau > 0.0) ||
        !(nplanes > 0) || !isfinite(tau0))
        return NULL;
    gas_obs *o = calloc(1, sizeof *o);
    if (!o)
        return NULL;
    o->n = n;
    o->nplanes = nplanes;
    o->c = c;
    o->V = V / c;
    o->gV = 1.0 / sqrt((1.0 - o->V) * (1.0 + o->V));
    o->tau0 = tau0 * c;
    o->dtau = dtau * c;
    o->s = calloc(n, sizeof *o->s);
    o->mom = malloc(2 * nplanes * n * sizeof *o->mom);
    if (!o->s || !o->mom) {
        gas_obs_free(o);
        return NULL;
    }
    for (size_t k = 0; k < 2 * nplanes * n; k++)
        o->mom[k] = NAN;
    return o;
}

void gas_obs_free(gas_obs *o)
{
    if (!o)
        return;
    free(o->s);
    free(o->mom);
    free(o);
}

void gas_obs_window(const gas_obs *o, double L, double *t_first, double *t_last)
{
    const double a = o->V * L; /* t = tau + V x: the hyperplane's table times over [0, L] */
    const double tl = o->tau0 + o->dtau * (double)(o->nplanes - 1);
    *t_first = (o->tau0 + fmin(0.0, a)) / o->c;
    *t_last = (tl + fmax(0.0, a)) / o->c;
}

/* s = t - V x along a straight segment through (t0, x0) with velocity vx: every
 * hyperplane tau_j with s(ta) <= tau_j < s(tb) crossed on [ta, tb] is sampled there. */
static void cross(gas_obs *o, size_t i, ball_state *q, double t0, double x0, double vx,
                  double px, double py, double E, double ta, double tb)
{
    const double sa = ta - o->V * (x0 + vx * (ta - t0)), sb = tb - o->V * (x0 + vx * (tb - t0));
    while (q->next < o->nplanes) {
        const double tau = o->tau0 + o->dtau * (double)q->next;
        if (tau < sa) { /* crossed before this segment where it could not be seen */
            q->next++;
            o->lost++;
            continue;
        }
        if (!(tau < sb))
            break;
        /* the observer's momentum: boost along x by V */
        double *m = o->mom + 2 * (q->next * o->n + i);
        m[0] = o->gV * (px - o->V * E);
        m[1] = py;
        o->taken++;
        q->next++;
    }
}

int gas_obs_record(gas_obs *o, double t, const rc_sim_ball *b, const double *L)
{
    const double c = o->c;
    t *= c;
    int bad = 0;
    for (size_t i = 0; i < o->n; i++) {
        ball_state *q = &o->s[i];
        const double x = (b[i].x.x + b[i].image[0] * L[0]), y = (b[i].x.y + b[i].image[1] * L[1]);
        const double px = b[i].p.x / (b[i].m * c), py = b[i].p.y / (b[i].m * c);
        const double E = sqrt(1.0 + px * px + py * py);
        const double tau = b[i].tau * c;
        if (q->started) {
            const double dt = t - q->t;
            /* the last collision's table time from the proper time since it */
            const double tc = b[i].collided ? t - (tau - b[i].tau_last * c) * E : -INFINITY;
            const double tol = OBS_TOL * fmax(dt, 1.0);
            if (!(tc > q->t + tol)) { /* no collision since the last grid time */
                cross(o, i, q, q->t, q->x, q->px / q->E, q->px, q->py, q->E, q->t, t);
            } else {
                /* the line after the last collision, back to tc; does the line before
                 * reach the same event at the same proper time (exactly one collision)? */
                const double xc = x - px / E * (t - tc), yc = y - py / E * (t - tc);
                const double xa = q->x + q->px / q->E * (tc - q->t);
                const double ya = q->y + q->py / q->E * (tc - q->t);
                const double ta = q->tau + (tc - q->t) / q->E;
                const int one = fabs(xa - xc) <= tol && fabs(ya - yc) <= tol &&
                                fabs(ta - b[i].tau_last * c) <= tol;
                if (one)
                    cross(o, i, q, q->t, q->x, q->px / q->E, q->px, q->py, q->E, q->t, tc);
                /* (otherwise crossings before tc are lost: cross() counts them) */
                cross(o, i, q, t, x, px / E, px, py, E, tc, t);
                if (tc > t + tol)
                    bad = 1;
            }
        } else {
            q->started = 1;
        }
        q->t = t, q->x = x, q->y = y, q->px = px, q->py = py, q->E = E, q->tau = tau;
    }
    return bad ? -1 : 0;
}

/* 1-D: ball i's worldline from its last event on, in c = 1 units. */
static void load_segment(const gas_obs *o, ball_state *q, const rc_gas1d_segment *sg)
{
    const double c = o->c;
    q->t = sg->t * c;
    q->x = sg->x;
    q->vx = sg->v / c;
    q->px = sg->p / (sg->m * c);
    q->E = sqrt(1.0 + q->px * q->px);
}

int gas_obs_follow_gas1d(gas_obs *o, rc_gas1d *g, double L)
{
    if (!o || !g || rc_gas1d_count(g) != o->n || !(L > 0.0))
        return -1;
    double ta, tb;
    gas_obs_window(o, L, &ta, &tb);
    if (!(rc_gas1d_time(g) <= ta))
        return -1;
    /* one spacing past the window, so that a ball at x = L crosses the last hyperplane
     * inside the run rather than at its end */
    const double t_stop = tb + o->dtau / o->c;
    rc_gas1d_segment sg;
    for (size_t i = 0; i < o->n; i++) {
        rc_gas1d_segment_get(g, i, &sg);
        load_segment(o, &o->s[i], &sg);
    }
    const double tol = OBS_TOL * fmax(L, 1.0);
    int bad = 0;
    rc_gas1d_event ev;
    while (rc_gas1d_step(g, t_stop, &ev) == RC_OK) {
        const double te = ev.t * o->c;
        const size_t i1 = ev.kind == RC_GAS1D_PAIR ? ev.i + 1 : ev.i;
        for (size_t i = ev.i; i <= i1; i++) {
            ball_state *q = &o->s[i];
            /* the segment that ends here must reach the event (a bug otherwise) */
            bad |= !(fabs(q->x + q->vx * (te - q->t) - ev.x) <= tol);
            cross(o, i, q, q->t, q->x, q->vx, q->px, 0.0, q->E, q->t, te);
            rc_gas1d_segment_get(g, i, &sg);
            load_segment(o, q, &sg);
        }
    }
    for (size_t i = 0; i < o->n; i++) {
        ball_state *q = &o->s[i];
        cross(o, i, q, q->t, q->x, q->vx, q->px, 0.0, q->E, q->t, t_stop * o->c);
    }
    return bad ? -1 : 0;
}

const double *gas_obs_momenta(const gas_obs *o) { return o->mom; }

void gas_obs_counts(const gas_obs *o, uint64_t *taken, uint64_t *lost)
{
    *taken = o->taken;
    *lost = o->lost;
}
