/* tube.c — the shock tube's start: each half's balls placed uniformly without overlap
 * (a cell grid for the rejection), their momenta drawn from the Juttner law exactly. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "tube.h"

/* Gamma(k, 1) for k in {1, 3/2, 2, 5/2, 3}: sums of exponentials and half a squared normal */
static double gamma_draw(double k, rc_rng *r)
{
    double s = 0.0;
    for (int i = 0; i < (int)k; i++)
        s -= log1p(-rc_rng_uniform(r));
    if (k != floor(k)) {
        const double z = rc_rng_gauss(r);
        s += 0.5 * z * z;
    }
    return s;
}

/* x = gamma - 1 of the rest-frame Juttner law at theta:
 * 2-D: density (1 + x) e^(-x/theta), a two-term Gamma mixture, exact;
 * 3-D: (1 + x) sqrt(x (x + 2)) e^(-x/theta) under the envelope (1 + x)(x + sqrt(2x)),
 * a four-term Gamma mixture, accepted with sqrt(x (x + 2))/(x + sqrt(2x)) >= 0.7 */
static double juttner_x(int dim, double th, rc_rng *r)
{
    if (dim == 2) {
        const double k = rc_rng_uniform(r) * (1.0 + th) < 1.0 ? 1.0 : 2.0;
        return th * gamma_draw(k, r);
    }
    const double sp = sqrt(M_PI), s2 = M_SQRT2;
    /* weights of x^(k-1) e^(-x/theta): coefficient * Gamma(k) theta^k */
    const double w[4] = {th * th, 2.0 * th * th * th, s2 * 0.5 * sp * pow(th, 1.5),
                         s2 * 0.75 * sp * pow(th, 2.5)};
    const double k[4] = {2.0, 3.0, 1.5, 2.5};
    const double tot = w[0] + w[1] + w[2] + w[3];
    for (;;) {
        double u = rc_rng_uniform(r) * tot;
        int j = 0;
        while (j < 3 && u >= w[j])
            u -= w[j++];
        const double x = th * gamma_draw(k[j], r);
        if (rc_rng_uniform(r) * (x + sqrt(2.0 * x)) <= sqrt(x * (x + 2.0)))
            return x;
    }
}

static rc_vec3 unit_dir(int dim, rc_rng *r)
{
    rc_vec3 u = {0, 0, 0};
    if (dim == 2) {
        const double a = 2.0 * M_PI * rc_rng_uniform(r);
        u.x = cos(a), u.y = sin(a);
    } else {
        const double z = 2.0 * rc_rng_uniform(r) - 1.0, a = 2.0 * M_PI * rc_rng_uniform(r);
        const double s = sqrt(fmax(0.0, 1.0 - z * z));
        u.x = s * cos(a), u.y = s * sin(a), u.z = z;
    }
    return u;
}

rc_vec3 sh_juttner_momentum(int dim, double c, double T, double v, rc_rng *r)
{
    rc_vec3 p = {0, 0, 0};
    if (isinf(c)) {
        const double s = sqrt(T);
        p.x = s * rc_rng_gauss(r) + v;
        p.y = s * rc_rng_gauss(r);
        if (dim == 3)
            p.z = s * rc_rng_gauss(r);
        return p;
    }
    const double th = T / (c * c), b = v / c, W = 1.0 / sqrt((1.0 - b) * (1.0 + b));
    for (;;) {
        const double x = juttner_x(dim, th, r);
        const rc_vec3 u = unit_dir(dim, r);
        const double pm = c * sqrt(x * (x + 2.0)); /* |p'| (m = 1) */
        const double vx = pm * u.x / (1.0 + x);    /* v'_x / c * c: p'_x c^2 / E' */
        /* counted at one table time the boosted law carries E/E' = W (1 + b v'_x/c) */
        if (rc_rng_uniform(r) * (1.0 + fabs(b)) > 1.0 + b * vx / c)
            continue;
        p.x = W * (pm * u.x + b * c * (1.0 + x));
        p.y = pm * u.y;
        p.z = pm * u.z;
        return p;
    }
}

size_t sh_tube_count(const sh_tube *t, int side)
{
    const double len = side ? t->box.x - t->x0 : t->x0;
    const double area = t->dim == 3 ? t->box.y * t->box.z : t->box.y;
    const double b = isinf(t->c) ? 0.0 : t->v[side] / t->c;
    const double W = 1.0 / sqrt((1.0 - b) * (1.0 + b));
    return (size_t)llround(t->n[side] * W * area * len);
}

typedef struct grid {
    int nc[3];
    double cs[3];
    long *head, *next;
} grid;

static long gcell(const grid *g, const rc_vec3 *x, int *ix)
{
    const double xs[3] = {x->x, x->y, x->z};
    for (int a = 0; a < 3; a++) {
        int i = (int)(xs[a] / g->cs[a]);
        ix[a] = i < 0 ? 0 : i >= g->nc[a] ? g->nc[a] - 1 : i;
    }
    return ((long)ix[2] * g->nc[1] + ix[1]) * g->nc[0] + ix[0];
}

/* does a ball at x of radius r overlap one already placed? (nearest image across) */
static int overlaps(const sh_tube *t, const grid *g, const rc_sim_ball *b, const rc_vec3 *x)
{
    int ix[3];
    gcell(g, x, ix);
    const double L[3] = {t->box.x, t->box.y, t->box.z};
    const int span[3] = {1, g->nc[1] >= 3 ? 1 : 0, t->dim == 3 && g->nc[2] >= 3 ? 1 : 0};
    for (int dz = -span[2]; dz <= span[2]; dz++)
        for (int dy = -span[1]; dy <= span[1]; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                const int cx = ix[0] + dx;
                if (cx < 0 || cx >= g->nc[0])
                    continue;
                const int cy = (ix[1] + dy + g->nc[1]) % g->nc[1];
                const int cz = (ix[2] + dz + g->nc[2]) % g->nc[2];
                for (long j = g->head[((long)cz * g->nc[1] + cy) * g->nc[0] + cx]; j >= 0; j = g->next[j]) {
                    double d[3] = {b[j].x.x - x->x, b[j].x.y - x->y, b[j].x.z - x->z};
                    for (int a = 1; a < t->dim; a++) /* 2-D: no z to wrap (L z = 0) */
                        d[a] -= L[a] * nearbyint(d[a] / L[a]);
                    if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < 4.0 * t->r * t->r)
                        return 1;
                }
            }
    return 0;
}

int sh_tube_balls(const sh_tube *t, uint64_t seed, rc_sim_ball **out, size_t *nout, char *err)
{
    const size_t nl = sh_tube_count(t, 0), nr = sh_tube_count(t, 1), n = nl + nr;
    /* random sequential placement jams near packing 0.38 (3-D) / 0.55 (2-D) and slows far
     * below it: the tube is for dilute gases, so the start refuses dense sides at once */
    for (int side = 0; side < 2; side++) {
        const double vb = t->dim == 3 ? 4.0 / 3.0 * M_PI * t->r * t->r * t->r : M_PI * t->r * t->r;
        const double b = isinf(t->c) ? 0.0 : t->v[side] / t->c;
        const double phi = t->n[side] / sqrt((1.0 - b) * (1.0 + b)) * vb;
        if (phi > SH_TUBE_MAX_PACKING) {
            app_errf(err, "the %s side's packing fraction %g is above %g: random placement is "
                          "for dilute gases (lower n or the radius)", side ? "right" : "left",
                     phi, SH_TUBE_MAX_PACKING);
            return -1;
        }
    }
    rc_sim_ball *b = calloc(n ? n : 1, sizeof *b);
    grid g;
    const double L[3] = {t->box.x, t->box.y, t->dim == 3 ? t->box.z : 1.0};
    for (int a = 0; a < 3; a++) {
        const double want = a < t->dim ? fmax(2.0 * t->r, 1e-9 * L[a]) : L[a];
        g.nc[a] = (int)fmin(fmax(1.0, floor(L[a] / want)), a == 0 ? 1e6 : 1e3);
        g.cs[a] = L[a] / g.nc[a];
    }
    /* no more cells than ~4 per ball: larger cells only check more neighbours */
    while ((double)g.nc[0] * g.nc[1] * g.nc[2] > 4.0 * (double)n + 64.0 && g.nc[0] > 1) {
        g.nc[0] = (g.nc[0] + 1) / 2;
        g.cs[0] = L[0] / g.nc[0];
    }
    const long ncell = (long)g.nc[0] * g.nc[1] * g.nc[2];
    g.head = malloc((size_t)ncell * sizeof *g.head);
    g.next = malloc((n ? n : 1) * sizeof *g.next);
    if (!b || !g.head || !g.next) {
        free(b), free(g.head), free(g.next);
        app_errf(err, "out of memory for %zu balls", n);
        return -1;
    }
    for (long i = 0; i < ncell; i++)
        g.head[i] = -1;
    /* splitmix64 steps its state by a fixed constant, so states seed and seed + 1 (or seed
     * times that constant) give one sequence shifted by a draw: seeds 1, 2, 3 would not be
     * independent. The state is the generator's output for the seed, a bijective mix. */
    rc_rng mix = {seed};
    rc_rng rng = {rc_rng_next(&mix)};
    for (size_t i = 0; i < n; i++) {
        const int side = i >= nl;
        const double lo = side ? t->x0 + t->r : t->r, hi = side ? t->box.x - t->r : t->x0 - t->r;
        if (!(hi > lo)) {
            free(b), free(g.head), free(g.next);
            app_errf(err, "the %s side is narrower than one ball", side ? "right" : "left");
            return -1;
        }
        rc_vec3 x;
        long tries = 0;
        do {
            x.x = lo + (hi - lo) * rc_rng_uniform(&rng);
            x.y = t->box.y * rc_rng_uniform(&rng);
            x.z = t->dim == 3 ? t->box.z * rc_rng_uniform(&rng) : 0.0;
            if (++tries > 100000) {
                free(b), free(g.head), free(g.next);
                app_errf(err, "cannot place ball %zu of the %s side without overlap (too dense "
                              "for random placement: lower n or the radius)", i - (side ? nl : 0),
                         side ? "right" : "left");
                return -1;
            }
        } while (overlaps(t, &g, b, &x));
        b[i].x = x;
        b[i].r = t->r;
        b[i].m = 1.0;
        b[i].p = sh_juttner_momentum(t->dim, t->c, t->T[side], t->v[side], &rng);
        int ix[3];
        const long cidx = gcell(&g, &x, ix);
        g.next[i] = g.head[cidx];
        g.head[cidx] = (long)i;
    }
    free(g.head), free(g.next);
    *out = b;
    *nout = n;
    return 0;
}

int sh_tube_sim(const sh_tube *t, size_t n, const rc_sim_ball *b, rc_sim **out, char *err)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = t->dim;
    d.box = t->box;
    if (t->dim == 2)
        d.box.z = 0.0;
    d.c = t->c;
    d.eps_ball = d.eps_wall = 1.0;
    d.boundary[0] = RC_SIM_WALLS;
    d.boundary[1] = d.boundary[2] = RC_SIM_PERIODIC;
    d.frame = t->frame;
    if (t->law)
        d.law = t->law;
    /* cells: one diameter at least, a few balls each at most, four across */
    const double vol = t->dim == 3 ? t->box.x * t->box.y * t->box.z : t->box.x * t->box.y;
    double cs = fmax(2.0 * t->r, pow(vol / (double)(n ? n : 1), 1.0 / t->dim));
    cs = fmin(cs, t->box.y / 4.0);
    if (t->dim == 3)
        cs = fmin(cs, t->box.z / 4.0);
    if (cs < 2.0 * t->r) {
        app_errf(err, "the tube is %s across: it needs at least four ball diameters (%g)",
                 "too narrow", 8.0 * t->r);
        return -1;
    }
    d.cell_size = cs;
    rc_sim *s = NULL;
    int rc = rc_sim_create(&d, &s);
    size_t bad = 0;
    if (!rc)
        rc = rc_sim_set_balls(s, n, b, &bad);
    if (rc) {
        app_errf(err, "engine: %s (ball %zu)", rc_strerror(rc), bad);
        rc_sim_free(&s);
        return -1;
    }
    *out = s;
    return 0;
}
