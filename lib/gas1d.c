/* gas1d.c — exact event-driven 1-D gas of point particles: neighbour-pair and wall times
 * in a tournament tree, per-particle local clocks, so an event costs O(log N). */
#include <math.h>
#include <stdlib.h>

#include "relcol/gas1d.h"
#include "relcol/status.h"

/* Event slots: slot 0 is particle 0 at the left wall, slot k (1..n-1) the pair (k-1, k),
 * slot n particle n-1 at the right wall. The slots that involve particle i are i and
 * i + 1, and slot order is left-to-right order, which is the documented tie order. */
struct rc_gas1d {
    size_t n, leaves;         /* particles; leaves of the tree (power of 2 >= n + 1) */
    double L, inv_c2, t;
    const rc_law *law;
    rc_collision_params prm;
    /* particle i: position x[i] at its local clock tl[i]; m, p and the derived M, v */
    double *x, *tl, *m, *p, *M, *v;
    double *et;               /* leaves entries: event time of each slot, inf if none */
    size_t *tree;             /* 2 leaves entries: tree[k] = earliest slot below node k */
    rc_gas1d_stats st;
    double wall_comp[2];      /* Neumaier compensation of st.wall_impulse */
};

rc_gas1d_def rc_gas1d_def_default(void)
{
    rc_gas1d_def d = {0, 1.0, INFINITY, 0.0, NULL, NULL, NULL, NULL};
    return d;
}

/* Same expression as the law kernels use, so "approaching" means the same to both. */
static void derive(rc_gas1d *g, size_t i)
{
    g->M[i] = sqrt(g->m[i] * g->m[i] + g->p[i] * g->p[i] * g->inv_c2);
    g->v[i] = g->p[i] / g->M[i];
}

static double slot_time(const rc_gas1d *g, size_t s)
{
    double t = INFINITY;
    if (s == 0) {
        if (g->v[0] < 0.0)
            t = g->tl[0] + g->x[0] / -g->v[0];
    } else if (s == g->n) {
        const size_t i = g->n - 1;
        if (g->v[i] > 0.0)
            t = g->tl[i] + (g->L - g->x[i]) / g->v[i];
    } else {
        const size_t i = s - 1, j = s;
        const double dv = g->v[i] - g->v[j];
        if (!(dv > 0.0))
            return INFINITY;
        /* both particles at the later of their clocks; the gap is >= 0 exactly, so a
         * negative value is round-off and means "touching now" */
        const double T = g->tl[i] > g->tl[j] ? g->tl[i] : g->tl[j];
        const double gap = (g->x[j] + g->v[j] * (T - g->tl[j])) -
                           (g->x[i] + g->v[i] * (T - g->tl[i]));
        t = T + (gap > 0.0 ? gap : 0.0) / dv;
    }
    /* exact times are never before now; keep the event sequence monotone */
    return t < g->t ? g->t : t;
}

static void tree_update(rc_gas1d *g, size_t s)
{
    size_t k = (g->leaves + s) >> 1;
    while (k >= 1) {
        const size_t a = g->tree[2 * k], b = g->tree[2 * k + 1], old = g->tree[k];
        /* a's slots are all left of b's: <= keeps the lower slot on ties */
        const size_t w = g->et[a] <= g->et[b] ? a : b;
        g->tree[k] = w;
        /* same winner, and not the slot whose time changed: nothing above changes */
        if (w == old && w != s)
            break;
        k >>= 1;
    }
}

static void slot_refresh(rc_gas1d *g, size_t s)
{
    if (s > g->n)
        return;
    g->et[s] = slot_time(g, s);
    tree_update(g, s);
}

static void neumaier_add(double *sum, double *comp, double x)
{
    const double t = *sum + x;
    if (fabs(*sum) >= fabs(x))
        *comp += (*sum - t) + x;
    else
        *comp += (x - t) + *sum;
    *sum = t;
}

static double clamp_box(const rc_gas1d *g, double x)
{
    return x < 0.0 ? 0.0 : (x > g->L ? g->L : x);
}

int rc_gas1d_create(const rc_gas1d_def *def, rc_gas1d **out, size_t *bad)
{
    if (!out)
        return RC_EINVAL;
    *out = NULL;
    if (!def || def->n == 0 || !def->x || !def->m || !def->p)
        return RC_EINVAL;
    if (!isfinite(def->length) || !isfinite(def->t0))
        return RC_ENONFINITE;
    if (!(def->length > 0.0))
        return RC_EINVAL;
    double k;
    if (rc_inv_c2(def->c, &k) != RC_OK)
        return RC_ESPEEDOFLIGHT;
    const size_t n = def->n;
    for (size_t i = 0; i < n; i++) {
        if (bad)
            *bad = i;
        if (!isfinite(def->x[i]) || !isfinite(def->m[i]) || !isfinite(def->p[i]))
            return RC_ENONFINITE;
        if (!(def->m[i] > 0.0))
            return RC_EMASS;
        if (!(def->x[i] >= 0.0 && def->x[i] <= def->length))
            return RC_EINVAL;
        if (i > 0 && !(def->x[i] > def->x[i - 1]))
            return RC_EINVAL;
    }
    size_t leaves = 2;
    while (leaves < n + 1)
        leaves *= 2;
    if (n > ((size_t)-1) / (16 * sizeof(double)))
        return RC_ENOMEM; /* the byte counts below would overflow */
    rc_gas1d *g = calloc(1, sizeof *g);
    double *buf = malloc((6 * n + leaves) * sizeof(double));
    size_t *tree = malloc(2 * leaves * sizeof(size_t));
    if (!g || !buf || !tree) {
        free(g);
        free(buf);
        free(tree);
        return RC_ENOMEM;
    }
    g->n = n;
    g->leaves = leaves;
    g->L = def->length;
    g->inv_c2 = k;
    g->t = def->t0;
    g->law = def->law ? def->law : &rc_law_zmf;
    g->prm = rc_collision_params_default();
    g->prm.c = def->c;
    g->prm.eps = 1.0;
    g->x = buf;
    g->tl = buf + n;
    g->m = buf + 2 * n;
    g->p = buf + 3 * n;
    g->M = buf + 4 * n;
    g->v = buf + 5 * n;
    g->et = buf + 6 * n;
    g->tree = tree;
    for (size_t i = 0; i < n; i++) {
        g->x[i] = def->x[i];
        g->tl[i] = def->t0;
        g->m[i] = def->m[i];
        g->p[i] = def->p[i];
        derive(g, i);
    }
    for (size_t s = 0; s < leaves; s++) {
        g->et[s] = s <= n ? slot_time(g, s) : INFINITY;
        g->tree[leaves + s] = s;
    }
    for (size_t k = leaves - 1; k >= 1; k--)
        g->tree[k] = g->et[g->tree[2 * k]] <= g->et[g->tree[2 * k + 1]] ? g->tree[2 * k]
                                                                         : g->tree[2 * k + 1];
    *out = g;
    if (bad)
        *bad = 0;
    return RC_OK;
}

void rc_gas1d_free(rc_gas1d **g)
{
    if (!g || !*g)
        return;
    free((*g)->x);
    free((*g)->tree);
    free(*g);
    *g = NULL;
}

/* Particle i to time t at position x (its local clock moves). */
static void move_to(rc_gas1d *g, size_t i, double t, double x)
{
    g->x[i] = x;
    g->tl[i] = t;
}

int rc_gas1d_step(rc_gas1d *g, double t_end, rc_gas1d_event *ev)
{
    if (!g || isnan(t_end))
        return RC_EINVAL;
    const rc_vec3 ex = rc_v3(1.0, 0.0, 0.0);
    for (;;) {
        const size_t s = g->tree[1];
        const double te = g->et[s];
        if (isinf(te) || !(te <= t_end)) {
            if (t_end > g->t && isfinite(t_end))
                g->t = t_end;
            return RC_MISS;
        }
        g->t = te;
        if (s == 0 || s == g->n) {
            const int left = s == 0;
            const size_t i = left ? 0 : g->n - 1;
            rc_particle a = {g->m[i], rc_v3(g->p[i], 0.0, 0.0)};
            const int st = rc_collide_wall(g->inv_c2, 1.0, &a, left ? rc_v3(-1.0, 0.0, 0.0)
                                                                      : ex);
            if (st != RC_OK) {
                g->st.declined++;
                g->et[s] = INFINITY;
                tree_update(g, s);
                continue;
            }
            neumaier_add(&g->st.wall_impulse[!left], &g->wall_comp[!left], a.p.x - g->p[i]);
            g->st.wall_events[!left]++;
            move_to(g, i, te, left ? 0.0 : g->L);
            g->p[i] = a.p.x;
            g->m[i] = a.m;
            derive(g, i);
            slot_refresh(g, i);
            slot_refresh(g, i + 1);
            if (ev) {
                ev->t = te;
                ev->x = g->x[i];
                ev->kind = left ? RC_GAS1D_WALL_LEFT : RC_GAS1D_WALL_RIGHT;
                ev->i = i;
            }
            return RC_OK;
        }
        const size_t i = s - 1, j = s;
        rc_particle a = {g->m[i], rc_v3(g->p[i], 0.0, 0.0)};
        rc_particle b = {g->m[j], rc_v3(g->p[j], 0.0, 0.0)};
        const int st = g->law->collide(&g->prm, &a, &b, ex);
        if (st != RC_OK) {
            g->st.declined++;
            g->et[s] = INFINITY;
            tree_update(g, s);
            continue;
        }
        /* the two computed positions agree to round-off: meet in the middle */
        const double xi = g->x[i] + g->v[i] * (te - g->tl[i]);
        const double xj = g->x[j] + g->v[j] * (te - g->tl[j]);
        const double xc = clamp_box(g, 0.5 * (xi + xj));
        move_to(g, i, te, xc);
        move_to(g, j, te, xc);
        g->p[i] = a.p.x;
        g->m[i] = a.m;
        g->p[j] = b.p.x;
        g->m[j] = b.m;
        derive(g, i);
        derive(g, j);
        slot_refresh(g, i);
        slot_refresh(g, i + 1);
        slot_refresh(g, i + 2);
        g->st.pair_events++;
        if (ev) {
            ev->t = te;
            ev->x = xc;
            ev->kind = RC_GAS1D_PAIR;
            ev->i = i;
        }
        return RC_OK;
    }
}

int rc_gas1d_advance(rc_gas1d *g, double t_end, uint64_t max_events)
{
    if (!g || isnan(t_end) || t_end < g->t)
        return RC_EINVAL;
    for (uint64_t k = 0; max_events == 0 || k < max_events; k++) {
        const int st = rc_gas1d_step(g, t_end, NULL);
        if (st == RC_MISS)
            return RC_OK;
        if (st != RC_OK)
            return st;
    }
    return RC_OK;
}

size_t rc_gas1d_count(const rc_gas1d *g) { return g ? g->n : 0; }

double rc_gas1d_time(const rc_gas1d *g) { return g ? g->t : NAN; }

int rc_gas1d_get(const rc_gas1d *g, double *x, double *m, double *p)
{
    if (!g)
        return RC_EINVAL;
    for (size_t i = 0; i < g->n; i++) {
        if (x)
            x[i] = clamp_box(g, g->x[i] + g->v[i] * (g->t - g->tl[i]));
        if (m)
            m[i] = g->m[i];
        if (p)
            p[i] = g->p[i];
    }
    return RC_OK;
}

int rc_gas1d_segment_get(const rc_gas1d *g, size_t i, rc_gas1d_segment *out)
{
    if (!g || !out || i >= g->n)
        return RC_EINVAL;
    /* the local clock moves only at the particle's own events (move_to), so (tl, x) is
     * its last event */
    out->t = g->tl[i];
    out->x = g->x[i];
    out->m = g->m[i];
    out->p = g->p[i];
    out->v = g->v[i];
    return RC_OK;
}

int rc_gas1d_stats_get(const rc_gas1d *g, rc_gas1d_stats *s)
{
    if (!g || !s)
        return RC_EINVAL;
    *s = g->st;
    s->wall_impulse[0] += g->wall_comp[0];
    s->wall_impulse[1] += g->wall_comp[1];
    return RC_OK;
}
