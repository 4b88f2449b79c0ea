/* engine/gas.c — a gas to start from: equal balls on random sites of a lattice sized for an
 * exact packing, isotropic momenta of a given rms speed and zero total; the few balls the
 * lattice has no room for placed at random. */
#include <math.h>
#include <stdlib.h>

#include "relcol/rng.h"
#include "relcol/sim.h"
#include "relcol/status.h"

/* Lattice spacing over the diameter (relative), so no two balls touch at the start (a
 * lattice-wide first group). */
#define GAS_MIN_CLEARANCE 1e-6
/* Bisection on the momentum scale stops at this relative width. */
#define GAS_SCALE_TOL 1e-15

/* Random sequential addition of n centres more than dmin apart, retried GAS_RSA_TRIES a ball
 * and GAS_RSA_STARTS in all: O(n^2), for the few balls a lattice wastes room on; 0 on success. */
#define GAS_RSA_TRIES 1000
#define GAS_RSA_STARTS 1000
#define GAS_RSA_MAX_N 64
/* ... and at most this many candidate centres in all, so that a packing no placement can
 * reach is refused in a fraction of a second, not after every start */
#define GAS_RSA_BUDGET 2000000

static int place_once(rc_rng *R, int dim, size_t n, double lo, double hi, double dmin,
                      rc_vec3 *x, long *budget)
{
    for (size_t i = 0; i < n; i++) {
        int placed = 0;
        for (long t = 0; t < GAS_RSA_TRIES && !placed && (*budget)-- > 0; t++) {
            const double w = hi - lo;
            const rc_vec3 c = rc_v3(lo + w * rc_rng_uniform(R), lo + w * rc_rng_uniform(R),
                                    dim == 3 ? lo + w * rc_rng_uniform(R) : 0.0);
            placed = 1;
            for (size_t j = 0; j < i && placed; j++)
                placed = rc_v3_norm2(rc_v3_sub(c, x[j])) > dmin * dmin;
            if (placed)
                x[i] = c;
        }
        if (!placed)
            return -1;
    }
    return 0;
}

static int place_rsa(rc_rng *R, int dim, size_t n, double lo, double hi, double dmin,
                     rc_vec3 *x)
{
    long budget = GAS_RSA_BUDGET;
    for (int k = 0; k < GAS_RSA_STARTS && budget > 0; k++)
        if (place_once(R, dim, n, lo, hi, dmin, x, &budget) == 0)
            return 0;
    return -1;
}

static double rms_speed(const rc_sim_ball *b, size_t n, double scale, double m, double k)
{
    double sum = 0.0;
    for (size_t i = 0; i < n; i++) {
        double p2 = rc_v3_norm2(b[i].p) * scale * scale;
        sum += p2 / (m * m + p2 * k);
    }
    return sqrt(sum / (double)n);
}

/* The lattice's side: the smallest whose side^dim sites hold n balls. */
static size_t lattice_side(int dim, size_t n)
{
    size_t side = (size_t)ceil(pow((double)n, 1.0 / dim) - 1e-9);
    while ((dim == 3 ? side * side * side : side * side) < n)
        side++;
    return side;
}

size_t rc_sim_gas_bytes(const rc_sim_gas_def *g)
{
    if (!g || (g->dim != 2 && g->dim != 3) || g->n == 0)
        return 0;
    const size_t side = lattice_side(g->dim, g->n);
    const size_t sites = g->dim == 3 ? side * side * side : side * side;
    /* the sites' permutation, and the random placement's positions where it may be taken */
    return sites * sizeof(size_t) + (g->n <= GAS_RSA_MAX_N ? g->n * sizeof(rc_vec3) : 0);
}

int rc_sim_gas_init(const rc_sim_gas_def *g, rc_vec3 *box, rc_sim_ball *balls)
{
    if (!g || !box || !balls)
        return RC_EINVAL;
    if (g->dim != 2 && g->dim != 3)
        return RC_EDIM;
    if (!isfinite(g->radius) || !isfinite(g->packing) || !isfinite(g->v_rms) ||
        !isfinite(g->density))
        return RC_ENONFINITE;
    if (!(g->radius > 0.0))
        return RC_ERADIUS;
    if (g->n == 0 || !(g->packing > 0.0) || !(g->v_rms >= 0.0) || !(g->density > 0.0))
        return RC_EINVAL;
    double k;
    int st = rc_inv_c2(g->c, &k);
    if (st != RC_OK)
        return st;
    if (!(g->v_rms * sqrt(k) < 1.0)) /* v_rms < c (no square: a huge classical v_rms
                                         is refused below, not as faster than light) */
        return RC_ESPEED;
    const int dim = g->dim;
    const double r = g->radius;
    const double vball = dim == 3 ? 4.0 / 3.0 * M_PI * r * r * r : M_PI * r * r;
    const double L = pow((double)g->n * vball / g->packing, 1.0 / dim);
    const size_t side = lattice_side(dim, g->n);
    const double a = L / (double)side;
    rc_rng R = {g->seed};
    rc_vec3 *xs = NULL; /* positions placed at random, where the lattice has no room */
    if (!(a > 2.0 * r * (1.0 + GAS_MIN_CLEARANCE))) {
        /* too dense for the lattice start: a few balls may still fit at random (a lattice
         * of side^dim >= n sites spends room on empty sites); many cannot */
        const double lo = r * (1.0 + GAS_MIN_CLEARANCE), hi = L - lo;
        if (g->n > GAS_RSA_MAX_N || !(hi > lo))
            return RC_EOVERLAP;
        if (!(xs = malloc(g->n * sizeof *xs)))
            return RC_ENOMEM;
        if (place_rsa(&R, dim, g->n, lo, hi, 2.0 * r * (1.0 + GAS_MIN_CLEARANCE), xs)) {
            free(xs);
            return RC_EOVERLAP;
        }
    }
    const size_t sites = dim == 3 ? side * side * side : side * side;
    size_t *perm = malloc(sites * sizeof *perm);
    if (!perm) {
        free(xs);
        return RC_ENOMEM;
    }
    for (size_t i = 0; i < sites; i++)
        perm[i] = i;
    for (size_t i = sites - 1; i > 0; i--) { /* Fisher-Yates */
        size_t j = (size_t)(rc_rng_uniform(&R) * (double)(i + 1));
        size_t t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    const double m = g->density * r * r * r;
    rc_vec3 ptot = rc_v3(0, 0, 0);
    for (size_t i = 0; i < g->n; i++) {
        size_t s = perm[i];
        size_t ix = s % side, iy = (s / side) % side, iz = s / (side * side);
        balls[i].x = xs ? xs[i]
                        : rc_v3((ix + 0.5) * a, (iy + 0.5) * a, dim == 3 ? (iz + 0.5) * a : 0.0);
        balls[i].p = rc_v3(rc_rng_gauss(&R), rc_rng_gauss(&R), dim == 3 ? rc_rng_gauss(&R) : 0.0);
        balls[i].r = r;
        balls[i].m = m;
        balls[i].tau = 0.0;
        balls[i].collided = 0; /* no collision yet: the TC model starts with no memory */
        balls[i].tau_last = 0.0;
        balls[i].image[0] = balls[i].image[1] = balls[i].image[2] = 0;
        ptot = rc_v3_add(ptot, balls[i].p);
    }
    free(perm);
    free(xs);
    for (size_t i = 0; i < g->n; i++)
        balls[i].p = rc_v3_axpy(balls[i].p, -1.0 / (double)g->n, ptot);
    /* rms speed grows monotonically with the scale; a lone ball has none to scale, and momenta
     * past ~1e150 (their squares overflow) are refused */
    double lo = 0.0, hi = 1.0;
    if (g->v_rms > 0.0) {
        if (!(rms_speed(balls, g->n, 1.0, m, k) > 0.0))
            return RC_EINVAL;
        while (rms_speed(balls, g->n, hi, m, k) < g->v_rms) {
            hi *= 2.0;
            if (!(hi < 1e150))
                return RC_ENONFINITE;
        }
        while (hi - lo > GAS_SCALE_TOL * hi) {
            double mid = 0.5 * (lo + hi);
            if (rms_speed(balls, g->n, mid, m, k) < g->v_rms)
                lo = mid;
            else
                hi = mid;
        }
    }
    for (size_t i = 0; i < g->n; i++)
        balls[i].p = rc_v3_scale(g->v_rms > 0.0 ? 0.5 * (lo + hi) : 0.0, balls[i].p);
    *box = rc_v3(L, L, dim == 3 ? L : 0.0);
    return RC_OK;
}
