/* kink_clusters.h — where the glued tube is not defined, as clusters (white box, tests
 * only): the covariant engine is stepped one event at a time, every ball's kinks are read
 * as they are placed (its kink time, velocity before and after), and two collisions are
 * joined when a ball's kink at the later one crosses its kink at the earlier one inside the
 * ball (papers/model-regime.md section 2: the proper time between them below
 * (r/c)|tanh(phi_0/2) w_0 - tanh(phi_2/2) w_2|) or the order rule put it there. Inside such
 * a cluster the glued tube of section 1 is not defined; the one rule that keeps it (every
 * cluster solved as one group, one kink a ball) makes a cluster one collision. Measured:
 * the share of crossing kinks and the largest cluster's share of the collisions. */
#ifndef KINK_CLUSTERS_H
#define KINK_CLUSTERS_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../../lib/engine/private.h"
#include "relcol/relcol.h"

/* Minkowski product u_a . u_b of two unit four-velocities, from three-velocities (c = 1/
 * sqrt(inv_c2)): gamma_a gamma_b (1 - v_a . v_b / c^2). */
static inline double kc_dot(double inv_c2, rc_vec3 a, rc_vec3 b)
{
    const double ga = 1.0 / sqrt(1.0 - rc_v3_dot(a, a) * inv_c2);
    const double gb = 1.0 / sqrt(1.0 - rc_v3_dot(b, b) * inv_c2);
    return ga * gb * (1.0 - rc_v3_dot(a, b) * inv_c2);
}

/* The proper time below which two successive kinks of a ball of radius r, velocities v0
 * before the first, v1 between, v2 after the second, cross inside it: (r/c) times the
 * square root of (C01-1)/(C01+1) + (C21-1)/(C21+1) - 2 (C01 C21 - C02)/((1+C01)(1+C21))
 * (papers/model-regime.md section 2, checked there against eng_kinks_cross). */
static inline double kc_cross_tau(double inv_c2, double r, rc_vec3 v0, rc_vec3 v1, rc_vec3 v2)
{
    const double c01 = kc_dot(inv_c2, v0, v1), c21 = kc_dot(inv_c2, v2, v1);
    const double c02 = kc_dot(inv_c2, v0, v2);
    const double q = (c01 - 1.0) / (c01 + 1.0) + (c21 - 1.0) / (c21 + 1.0) -
                     2.0 * (c01 * c21 - c02) / ((1.0 + c01) * (1.0 + c21));
    return r * sqrt(inv_c2) * sqrt(q > 0.0 ? q : 0.0);
}

typedef struct kc_kink {
    double t;          /* the kink's table time on the ball's worldline */
    rc_vec3 v_in, v_out;
    uint32_t node;     /* the collision (event) that placed it */
} kc_kink;

typedef struct kc_state {
    size_t n;          /* balls */
    double inv_c2, r;
    kc_kink *last;     /* each ball's latest kink read (node UINT32_MAX: none) */
    kc_kink **hk;
    size_t *hn, *hcap;
    uint8_t *policy;   /* per node: the overlap policy decided it */
    uint32_t *parent, *size; /* union-find over nodes */
    size_t nodes, cap;
    uint32_t (*link)[2];     /* joined nodes: crossing kinks, or an undo's */
    size_t links, lcap;
    uint64_t pairs, crossing, undone;
    uint64_t pairs_model, crossing_model; /* both kinks the model's (no policy decision) */
} kc_state;

static inline uint32_t kc_find(kc_state *k, uint32_t a)
{
    while (k->parent[a] != a) {
        k->parent[a] = k->parent[k->parent[a]];
        a = k->parent[a];
    }
    return a;
}

static inline void kc_union(kc_state *k, uint32_t a, uint32_t b)
{
    a = kc_find(k, a);
    b = kc_find(k, b);
    if (a == b)
        return;
    if (k->size[a] < k->size[b]) {
        uint32_t t = a;
        a = b;
        b = t;
    }
    k->parent[b] = a;
    k->size[a] += k->size[b];
}

static inline int kc_same_v(rc_vec3 a, rc_vec3 b)
{
    /* an undone ball is put back on its stored line: its velocity comes back bit for bit,
     * but allow round-off in case a rebuild recomputes it */
    const double d = rc_v3_norm(rc_v3_sub(a, b)), s = rc_v3_norm(a) + rc_v3_norm(b);
    return d <= 1e-12 * (s > 1e-300 ? s : 1.0);
}

static inline int kc_link(kc_state *k, uint32_t a, uint32_t b)
{
    if (k->links == k->lcap) {
        const size_t nc = k->lcap ? 2 * k->lcap : 1024;
        uint32_t(*l)[2] = realloc(k->link, nc * sizeof *l);
        if (!l)
            return -1;
        k->link = l;
        k->lcap = nc;
    }
    k->link[k->links][0] = a;
    k->link[k->links++][1] = b;
    return 0;
}

/* Free; safe on a zeroed state. */
static inline void kc_free(kc_state *k)
{
    if (k->hk)
        for (size_t i = 0; i < k->n; i++)
            free(k->hk[i]);
    free(k->hk);
    free(k->hn);
    free(k->hcap);
    free(k->last);
    free(k->parent);
    free(k->size);
    free(k->policy);
    free(k->link);
    memset(k, 0, sizeof *k);
}

/* Start reading the kinks of s (a per_ball frame, finite c) from now: the kinks already
 * placed are the starting point and join nothing. 0 or -1 (no memory). */
static inline int kc_init(kc_state *k, const rc_sim *s)
{
    memset(k, 0, sizeof *k);
    k->n = s->n;
    k->inv_c2 = s->inv_c2;
    k->hk = calloc(k->n, sizeof *k->hk);
    k->hn = calloc(k->n, sizeof *k->hn);
    k->hcap = calloc(k->n, sizeof *k->hcap);
    k->last = calloc(k->n, sizeof *k->last);
    if (!k->hk || !k->hn || !k->hcap || !k->last) {
        kc_free(k);
        return -1;
    }
    for (size_t i = 0; i < k->n; i++) {
        const uint32_t b = s->slot[i];
        k->last[i] = (kc_kink){s->pb->cov[b].t_k, s->pb->glu[b].v_in, s->b[b].v, UINT32_MAX};
    }
    return 0;
}

/* After one event of s: every ball whose kink changed joins this event's node; its new kink
 * is set against the one it follows on the ball's line (a kink undone since is popped and
 * its node joins this one: the undo solved both together). policy: the overlap policy
 * decided the event. 0 or -1 (no memory). */
static inline int kc_step(kc_state *k, const rc_sim *s, int policy)
{
    uint32_t node = UINT32_MAX;
    for (size_t i = 0; i < k->n; i++) {
        const uint32_t b = s->slot[i];
        const double t = s->pb->cov[b].t_k;
        const rc_vec3 v = s->b[b].v;
        if (t == k->last[i].t && v.x == k->last[i].v_out.x && v.y == k->last[i].v_out.y &&
            v.z == k->last[i].v_out.z)
            continue;
        if (node == UINT32_MAX) {
            if (k->nodes == k->cap) {
                const size_t nc = k->cap ? 2 * k->cap : 1024;
                uint32_t *p = realloc(k->parent, nc * sizeof *p);
                if (!p)
                    return -1;
                k->parent = p;
                uint32_t *z = realloc(k->size, nc * sizeof *z);
                if (!z)
                    return -1;
                k->size = z;
                uint8_t *q = realloc(k->policy, nc);
                if (!q)
                    return -1;
                k->policy = q;
                k->cap = nc;
            }
            node = (uint32_t)k->nodes++;
            k->policy[node] = (uint8_t)(policy != 0);
        }
        const rc_vec3 vin = s->pb->glu[b].v_in;
        /* the kink this one follows: pop those an undo took back (their out-velocity is not
         * this kink's in-velocity) */
        while (k->hn[i] > 0 && !kc_same_v(k->hk[i][k->hn[i] - 1].v_out, vin)) {
            if (kc_link(k, node, k->hk[i][k->hn[i] - 1].node) != 0)
                return -1;
            k->hn[i]--;
            k->undone++;
        }
        if (k->hn[i] > 0) {
            const kc_kink *p = &k->hk[i][k->hn[i] - 1];
            const double g1 = 1.0 / sqrt(1.0 - rc_v3_dot(vin, vin) * k->inv_c2);
            const double dtau = (t - p->t) / g1;
            const double r = s->b[b].r;
            const int model = !k->policy[node] && !k->policy[p->node];
            const int cross =
                s->pb->glu[b].r == 0.0 || !(dtau >= kc_cross_tau(k->inv_c2, r, p->v_in, vin, v));
            k->pairs++;
            k->pairs_model += (uint64_t)model;
            k->crossing += (uint64_t)cross;
            k->crossing_model += (uint64_t)(cross && model);
            if (cross && kc_link(k, node, p->node) != 0)
                return -1;
        }
        if (k->hn[i] == k->hcap[i]) {
            const size_t nc = k->hcap[i] ? 2 * k->hcap[i] : 16;
            kc_kink *h = realloc(k->hk[i], nc * sizeof *h);
            if (!h)
                return -1;
            k->hk[i] = h;
            k->hcap[i] = nc;
        }
        k->hk[i][k->hn[i]++] = (kc_kink){t, vin, v, node};
        k->last[i] = (kc_kink){t, vin, v, node};
    }
    return 0;
}

typedef struct kc_result {
    size_t nodes;        /* collisions (events that placed kinks) */
    double p;            /* share of successive kink pairs that cross (model_only: of those
                          * neither of whose collisions the overlap policy decided) */
    double largest;      /* the largest cluster's share of the nodes */
    double mean_other;   /* mean cluster size a node sits in, largest cluster left out */
    double in3;          /* share of the nodes in clusters of three collisions or more */
    uint64_t undone;
} kc_result;

/* The clusters; model_only: joined only where neither collision was an overlap-policy
 * decision (through crossing kinks or an undo), so that the policy's own kinks do not
 * make them. */
static inline kc_result kc_measure(kc_state *k, int model_only)
{
    const uint64_t np = model_only ? k->pairs_model : k->pairs;
    const uint64_t nx = model_only ? k->crossing_model : k->crossing;
    kc_result r = {k->nodes, np ? (double)nx / (double)np : 0.0, 0.0, 0.0, 0.0, k->undone};
    for (size_t a = 0; a < k->nodes; a++) {
        k->parent[a] = (uint32_t)a;
        k->size[a] = 1;
    }
    for (size_t l = 0; l < k->links; l++) {
        const uint32_t a = k->link[l][0], b = k->link[l][1];
        if (model_only && (k->policy[a] || k->policy[b]))
            continue;
        kc_union(k, a, b);
    }
    size_t big = 0;
    uint32_t root_big = 0;
    for (size_t a = 0; a < k->nodes; a++)
        if (k->parent[a] == a && k->size[a] > big) {
            big = k->size[a];
            root_big = (uint32_t)a;
        }
    double s2 = 0.0, s1 = 0.0, s3 = 0.0;
    for (size_t a = 0; a < k->nodes; a++)
        if (k->parent[a] == a && k->size[a] >= 3)
            s3 += (double)k->size[a];
    for (size_t a = 0; a < k->nodes; a++)
        if (k->parent[a] == a && a != root_big) {
            s2 += (double)k->size[a] * k->size[a];
            s1 += (double)k->size[a];
        }
    r.largest = k->nodes ? (double)big / (double)k->nodes : 0.0;
    r.mean_other = s1 > 0.0 ? s2 / s1 : 0.0;
    r.in3 = k->nodes ? s3 / (double)k->nodes : 0.0;
    return r;
}

#endif
