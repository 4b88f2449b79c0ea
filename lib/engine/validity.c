/* engine/validity.c — the validity report (relcol/validity.h): the overlap policy's share and
 * the clusters of collisions joined by kinks that cross inside a ball (papers/shape-change.md
 * section 8), counted online from three hooks, each event's net change read at the next event,
 * as tests/engine/kink_clusters.h counts it (test_validity); each ball keeps its last
 * VAL_DEPTH kinks and unreachable nodes are dropped, bounding memory by the balls, not the
 * run. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "private.h"
#include "relcol/status.h"
#include "relcol/validity.h"

#define VAL_DEPTH 4
#define VAL_NONE UINT32_MAX
#define VAL_MAGIC 0x31564c4156ULL /* "VALV1" */

typedef struct val_kink {
    double t;
    rc_vec3 v_in, v_out;
    uint32_t node, pol; /* pol: its node's policy flag, kept here (a cold node's byte is a miss; a checkpoint has 0) */
} val_kink;

/* per ball, at its storage slot (the hooks' b: the engine's renumbering keeps the balls of one
 * event close, eng_validity_reorder permutes them with it), one block of five cache lines:
 * its kink time and velocity when last read and its last VAL_DEPTH kinks (a hook prefetches
 * it for the next flush); a checkpoint holds them in the caller's order */
typedef struct val_ball {
    double last_t;
    rc_vec3 last_v;
    uint32_t hn, pad0;
    val_kink hk[VAL_DEPTH];
    unsigned char pad[320 - 40 - VAL_DEPTH * sizeof(val_kink)];
} val_ball;
_Static_assert(sizeof(val_ball) == 320, "a ball's block is five cache lines");

/* a node of the two union-finds, [UF_ALL] over all links and [UF_MODEL] over the model's
 * (neither end a policy decision): one record, so that a link's two finds share its lines */
enum { UF_ALL, UF_MODEL };
typedef struct val_node {
    uint32_t up[2], size[2];
} val_node;

/* the counters and the current event, as stored in a checkpoint (no padding) */
typedef struct val_books {
    uint64_t n, nodes, cap, nd;
    uint64_t events, pairs, pairs_model, crossing, crossing_model, popped;
    uint64_t big_all, big_model;
    double cur_t;
    uint64_t cur_count, have_cur, cur_policy;
} val_books;

struct eng_validity {
    val_books k;
    val_ball *ball;
    uint8_t *mark;  /* per slot: listed in dirty */
    uint32_t *dirty;
    uint8_t *pol;   /* per node: an overlap-policy decision */
    val_node *node; /* per node: its two union-find records */
    uint64_t big[2]; /* per union-find: its largest cluster ever */
    int failed; /* out of memory once: the clusters are short of some events */
};

const char *rc_sim_verdict_name(rc_sim_verdict v)
{
    switch (v) {
    case RC_VERDICT_DEFINED:
        return "defined";
    case RC_VERDICT_OUTSIDE:
        return "outside";
    case RC_VERDICT_NON_COVARIANT:
        return "non_covariant";
    }
    return "?";
}

static void state_free(eng_validity *V)
{
    if (V) {
        free(V->ball);
        free(V->mark);
        free(V->dirty);
        free(V->pol);
        free(V->node);
        free(V);
    }
}

void eng_validity_free(rc_sim *s)
{
    state_free(s->val);
    s->val = NULL;
    s->val_failed = 0; /* (new balls: a new count) */
}

static int nodes_alloc(eng_validity *V, size_t cap)
{
    val_node *p = realloc(V->node, cap * sizeof *p);
    if (!p)
        return RC_ENOMEM;
    V->node = p;
    uint8_t *q = realloc(V->pol, cap);
    if (!q)
        return RC_ENOMEM;
    V->pol = q;
    V->k.cap = cap;
    return RC_OK;
}

/* A zeroed state for s's balls; the per-ball "last" is filled by the caller. */
static eng_validity *state_new(size_t n, size_t cap)
{
    eng_validity *V = calloc(1, sizeof *V);
    if (!V)
        return NULL;
    const size_t m = n ? n : 1;
    V->k.n = n;
    V->ball = aligned_alloc(64, m * sizeof *V->ball);
    if (V->ball)
        memset(V->ball, 0, m * sizeof *V->ball);
    V->mark = calloc(m, 1);
    V->dirty = malloc(m * sizeof *V->dirty);
    if (!V->ball || !V->mark || !V->dirty ||
        nodes_alloc(V, cap) != RC_OK) {
        state_free(V);
        return NULL;
    }
    return V;
}

/* The kinks already placed are the starting point and join nothing (kc_init's). */
static int start(rc_sim *s)
{
    if (s->val || s->val_failed)
        return s->val ? RC_OK : RC_ENOMEM;
    eng_validity *V = state_new(s->n, 1024);
    if (!V) {
        s->val_failed = 1;
        return RC_ENOMEM;
    }
    for (size_t b = 0; b < s->n; b++) {
        V->ball[b].last_t = s->pb->cov[b].t_k;
        V->ball[b].last_v = s->b[b].v;
    }
    s->val = V;
    return RC_OK;
}

static uint32_t uf_find(val_node *nd, int m, uint32_t a)
{
    while (nd[a].up[m] != a) {
        nd[a].up[m] = nd[nd[a].up[m]].up[m];
        a = nd[a].up[m];
    }
    return a;
}

static void uf_union(eng_validity *V, int m, uint32_t a, uint32_t b)
{
    val_node *nd = V->node;
    a = uf_find(nd, m, a);
    b = uf_find(nd, m, b);
    if (a == b)
        return;
    if (nd[a].size[m] < nd[b].size[m]) {
        const uint32_t t = a;
        a = b;
        b = t;
    }
    nd[b].up[m] = a;
    nd[a].size[m] += nd[b].size[m];
    if (nd[a].size[m] > V->big[m])
        V->big[m] = nd[a].size[m];
}

/* a and b linked; pa, pb: their policy flags */
static void link_nodes(eng_validity *V, uint32_t a, int pa, uint32_t b, int pb)
{
    uf_union(V, UF_ALL, a, b);
    if (!pa && !pb)
        uf_union(V, UF_MODEL, a, b);
}

/* Keep only the nodes some ball's kinks name, renumbered in their old order; each cluster
 * keeps its size on its new root. RC_OK or RC_ENOMEM (nothing changed). */
static int compact(eng_validity *V)
{
    const size_t nodes = (size_t)V->k.nodes, n = (size_t)V->k.n;
    uint32_t *map = malloc(3 * (nodes ? nodes : 1) * sizeof *map);
    if (!map)
        return RC_ENOMEM;
    uint32_t *rep_a = map + nodes, *rep_m = rep_a + nodes;
    for (size_t x = 0; x < 3 * nodes; x++)
        map[x] = VAL_NONE;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < V->ball[i].hn; j++)
            map[V->ball[i].hk[j].node] = 0;
    uint32_t live = 0;
    for (size_t x = 0; x < nodes; x++)
        if (map[x] == 0)
            map[x] = live++;
        else
            map[x] = VAL_NONE;
    /* (the roots before anything is rewritten: finds read the old arrays) */
    for (size_t x = 0; x < nodes; x++)
        if (map[x] != VAL_NONE) {
            rep_a[x] = uf_find(V->node, UF_ALL, (uint32_t)x);
            rep_m[x] = uf_find(V->node, UF_MODEL, (uint32_t)x);
        }
    /* in place: new index y = map[x] <= x, so a slot is read before it is overwritten,
     * except the roots' sizes, read from their old slots first */
    uint32_t *sz = malloc(2 * (live ? live : 1) * sizeof *sz);
    if (!sz) {
        free(map);
        return RC_ENOMEM;
    }
    for (size_t x = 0; x < nodes; x++)
        if (map[x] != VAL_NONE) {
            sz[2 * map[x]] = V->node[rep_a[x]].size[UF_ALL];
            sz[2 * map[x] + 1] = V->node[rep_m[x]].size[UF_MODEL];
        }
    /* the first live node of each old root becomes the new root */
    uint32_t *first_a = malloc(2 * (nodes ? nodes : 1) * sizeof *first_a);
    if (!first_a) {
        free(sz);
        free(map);
        return RC_ENOMEM;
    }
    uint32_t *first_m = first_a + nodes;
    for (size_t x = 0; x < 2 * nodes; x++)
        first_a[x] = VAL_NONE;
    for (size_t x = 0; x < nodes; x++) {
        if (map[x] == VAL_NONE)
            continue;
        const uint32_t y = map[x];
        V->pol[y] = V->pol[x];
        if (first_a[rep_a[x]] == VAL_NONE)
            first_a[rep_a[x]] = y;
        if (first_m[rep_m[x]] == VAL_NONE)
            first_m[rep_m[x]] = y;
        V->node[y] = (val_node){{first_a[rep_a[x]], first_m[rep_m[x]]}, {sz[2 * y], sz[2 * y + 1]}};
    }
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < V->ball[i].hn; j++)
            V->ball[i].hk[j].node = map[V->ball[i].hk[j].node];
    V->k.nodes = live;
    free(first_a);
    free(sz);
    free(map);
    return RC_OK;
}

static uint32_t new_node(eng_validity *V, int policy)
{
    if (V->k.nodes == V->k.cap) {
        if (compact(V) != RC_OK)
            return VAL_NONE;
        if (2 * V->k.nodes > V->k.cap && nodes_alloc(V, 2 * (size_t)V->k.cap) != RC_OK)
            return VAL_NONE;
    }
    const uint32_t x = (uint32_t)V->k.nodes++;
    V->node[x] = (val_node){{x, x}, {1, 1}};
    V->big[UF_ALL] = V->big[UF_ALL] ? V->big[UF_ALL] : 1;
    V->big[UF_MODEL] = V->big[UF_MODEL] ? V->big[UF_MODEL] : 1;
    V->pol[x] = (uint8_t)(policy != 0);
    V->k.events++;
    return x;
}

/* The proper time below which successive kinks (v0, v1, v2) of a ball of radius r cross inside
 * it (papers/shape-change.md section 8). */
static double cross_tau(double inv_c2, double r, rc_vec3 v0, rc_vec3 v1, rc_vec3 v2)
{
    const double g0 = 1.0 / sqrt(1.0 - rc_v3_dot(v0, v0) * inv_c2);
    const double g1 = 1.0 / sqrt(1.0 - rc_v3_dot(v1, v1) * inv_c2);
    const double g2 = 1.0 / sqrt(1.0 - rc_v3_dot(v2, v2) * inv_c2);
    const double c01 = g0 * g1 * (1.0 - rc_v3_dot(v0, v1) * inv_c2);
    const double c21 = g2 * g1 * (1.0 - rc_v3_dot(v2, v1) * inv_c2);
    const double c02 = g0 * g2 * (1.0 - rc_v3_dot(v0, v2) * inv_c2);
    const double q = (c01 - 1.0) / (c01 + 1.0) + (c21 - 1.0) / (c21 + 1.0) -
                     2.0 * (c01 * c21 - c02) / ((1.0 + c01) * (1.0 + c21));
    return r * sqrt(inv_c2) * sqrt(q > 0.0 ? q : 0.0);
}

/* an undone ball comes back on its stored line, its velocity bit for bit; round-off
 * allowed in case a rebuild recomputes it */
static int same_v(rc_vec3 a, rc_vec3 b)
{
    if (a.x == b.x && a.y == b.y && a.z == b.z) /* (the usual case: d = 0 below) */
        return 1;
    const double d = rc_v3_norm(rc_v3_sub(a, b)), sc = rc_v3_norm(a) + rc_v3_norm(b);
    return d <= 1e-12 * (sc > 1e-300 ? sc : 1.0);
}

/* The marked balls' net change in the event just past. */
static void flush(const rc_sim *s, eng_validity *V)
{
    uint32_t node = VAL_NONE;
    for (size_t q = 0; q < V->k.nd; q++) {
        const uint32_t b = V->dirty[q];
        val_ball *B = &V->ball[b];
        const double t = s->pb->cov[b].t_k;
        const rc_vec3 v = s->b[b].v;
        if (t == B->last_t && v.x == B->last_v.x && v.y == B->last_v.y && v.z == B->last_v.z)
            continue;
        if (node == VAL_NONE) {
            node = new_node(V, (int)V->k.cur_policy);
            if (node == VAL_NONE) {
                V->failed = 1;
                break;
            }
        }
        val_kink *h = B->hk;
        const rc_vec3 vin = s->pb->glu[b].v_in;
        while (B->hn > 0 && !same_v(h[B->hn - 1].v_out, vin)) {
            link_nodes(V, node, V->pol[node], h[B->hn - 1].node, (int)h[B->hn - 1].pol);
            B->hn--;
            V->k.popped++;
        }
        if (B->hn > 0) {
            const val_kink *p = &h[B->hn - 1];
            const double g1 = 1.0 / sqrt(1.0 - rc_v3_dot(vin, vin) * s->inv_c2);
            const double dtau = (t - p->t) / g1;
            const int model = !V->pol[node] && !p->pol;
            const int cross = s->pb->glu[b].r == 0.0 ||
                              !(dtau >= cross_tau(s->inv_c2, s->b[b].r, p->v_in, vin, v));
            V->k.pairs++;
            V->k.pairs_model += (uint64_t)model;
            V->k.crossing += (uint64_t)cross;
            V->k.crossing_model += (uint64_t)(cross && model);
            if (cross)
                link_nodes(V, node, V->pol[node], p->node, (int)p->pol);
        }
        if (B->hn == VAL_DEPTH) { /* (the oldest can no longer be undone) */
            memmove(h, h + 1, (VAL_DEPTH - 1) * sizeof *h);
            B->hn--;
        }
        h[B->hn++] = (val_kink){t, vin, v, node, V->pol[node]};
        B->last_t = t;
        B->last_v = v;
    }
    for (size_t q = 0; q < V->k.nd; q++)
        V->mark[V->dirty[q]] = 0;
    V->k.nd = 0;
}

/* The event the hook is called from: the one before it, if any, is over. */
static eng_validity *enter(rc_sim *s)
{
    if (!(s->pb && s->inv_c2 > 0.0) || start(s) != RC_OK)
        return NULL;
    eng_validity *V = s->val;
    if (!V->k.have_cur || V->k.cur_t != s->bk.still_t || V->k.cur_count != s->bk.still_count) {
        flush(s, V);
        V->k.cur_t = s->bk.still_t;
        V->k.cur_count = s->bk.still_count;
        V->k.have_cur = 1;
        V->k.cur_policy = 0;
    }
    return V;
}

static void mark(rc_sim *s, int32_t b)
{
    eng_validity *V = enter(s);
    if (!V)
        return;
    const uint32_t i = (uint32_t)b;
    if (!V->mark[i]) {
        V->mark[i] = 1;
        for (size_t l = 0; l < sizeof(val_ball); l += 64)
            __builtin_prefetch((const char *)&V->ball[i] + l);
        V->dirty[V->k.nd++] = i;
    }
}

void eng_validity_kink(rc_sim *s, int32_t b) { mark(s, b); }

void eng_validity_undone(rc_sim *s, int32_t b) { mark(s, b); }

/* The engine renumbered its balls (engine/reorder.c): ball slot `from` is now inv's
 * preimage, i.e. new slot k holds old slot inv[k]; each cycle walked as reorder.c walks it,
 * the listed balls (an event not yet flushed) renamed in their order. done: n zeroed bytes. */
void eng_validity_reorder(rc_sim *s, const uint32_t *np, const uint32_t *inv, unsigned char *done)
{
    eng_validity *V = s->val;
    if (!V)
        return;
    const size_t n = (size_t)V->k.n;
    for (size_t q = 0; q < V->k.nd; q++) {
        V->mark[V->dirty[q]] = 0;
        V->dirty[q] = np[V->dirty[q]];
    }
    for (size_t q = 0; q < V->k.nd; q++)
        V->mark[V->dirty[q]] = 1;
    for (size_t i = 0; i < n; i++) {
        if (done[i])
            continue;
        const val_ball c = V->ball[i];
        size_t o = i;
        for (size_t from = inv[o]; from != i; o = from, from = inv[o]) {
            V->ball[o] = V->ball[from];
            done[o] = 1;
        }
        V->ball[o] = c;
        done[o] = 1;
    }
}

void eng_validity_policy(rc_sim *s)
{
    eng_validity *V = enter(s);
    if (V)
        V->k.cur_policy = 1;
}

int rc_sim_validity(const rc_sim *s, rc_validity *out)
{
    if (!s || !out)
        return RC_EINVAL;
    memset(out, 0, sizeof *out);
    const eng_books *bk = &s->bk;
    out->collisions = bk->collisions;
    out->policy = bk->overlaps;
    out->policy_share = bk->collisions ? (double)bk->overlaps / (double)bk->collisions : 0.0;
    out->tube_conflicts = bk->tube_conflicts;
    out->order_conflicts = bk->order_conflicts;
    out->undone = bk->rollbacks;
    out->threshold = RC_VALIDITY_P_MODEL_MAX;
    out->covariant = s->def.frame && s->def.frame->per_ball;
    if (s->val) {
        eng_validity *V = s->val;
        flush(s, V); /* (the event last resolved: its balls are final) */
        const val_books *k = &V->k;
        out->kink_events = k->events;
        out->kink_pairs = k->pairs;
        out->kink_pairs_model = k->pairs_model;
        out->crossing = k->crossing;
        out->crossing_model = k->crossing_model;
        out->kinks_popped = k->popped;
        out->p_all = k->pairs ? (double)k->crossing / (double)k->pairs : 0.0;
        out->p_model = k->pairs_model ? (double)k->crossing_model / (double)k->pairs_model : 0.0;
        out->largest_all = k->events ? (double)V->big[UF_ALL] / (double)k->events : 0.0;
        out->largest_model = k->events ? (double)V->big[UF_MODEL] / (double)k->events : 0.0;
    }
    double rsum = 0.0;
    for (size_t j = 0; j < s->n; j++)
        rsum += s->b[j].r;
    if (s->n && s->now > 0.0 && s->inv_c > 0.0)
        out->nu_r_c = (double)bk->collisions / ((double)s->n * s->now) * (rsum / (double)s->n) *
                      s->inv_c;
    if (s->inv_c2 == 0.0)
        out->verdict = RC_VERDICT_DEFINED;
    else if (!out->covariant)
        out->verdict = RC_VERDICT_NON_COVARIANT;
    else
        out->verdict = out->p_model > out->threshold ? RC_VERDICT_OUTSIDE : RC_VERDICT_DEFINED;
    out->verdict_name = rc_sim_verdict_name(out->verdict);
    return s->val_failed || (s->val && s->val->failed) ? RC_ENOMEM : RC_OK;
}

/* ---- checkpoint (engine/checkpoint.c) ------------------------------------------------ */

static size_t put(unsigned char *p, size_t at, const void *x, size_t bytes)
{
    if (p && bytes)
        memcpy(p + at, x, bytes);
    return at + bytes;
}

size_t eng_validity_bytes(const rc_sim *s, unsigned char *p)
{
    eng_validity *V = s->val;
    uint64_t head[2] = {VAL_MAGIC, V ? 1u : 0u};
    size_t at = put(p, 0, head, sizeof head);
    if (!V)
        return at;
    flush(s, V); /* (one form for one state: what a report would read) */
    const size_t n = (size_t)V->k.n, nodes = (size_t)V->k.nodes;
    at = put(p, at, &V->k, sizeof V->k);
    const uint64_t big[2] = {V->big[UF_ALL], V->big[UF_MODEL]};
    at = put(p, at, big, sizeof big);
    for (size_t i = 0; i < n; i++) { /* (caller's order: the same bytes whatever the slots) */
        val_ball B = V->ball[s->slot[i]];
        for (size_t j = 0; j < VAL_DEPTH; j++)
            B.hk[j].pol = 0; /* (rebuilt from pol on reading) */
        at = put(p, at, &B, sizeof B);
    }
    at = put(p, at, V->pol, nodes);
    /* (format 16's four arrays: all's parents, sizes, the model's parents, sizes) */
    for (int m = 0; m < 2; m++) {
        for (size_t x = 0; x < nodes; x++)
            at = put(p, at, &V->node[x].up[m], sizeof(uint32_t));
        for (size_t x = 0; x < nodes; x++)
            at = put(p, at, &V->node[x].size[m], sizeof(uint32_t));
    }
    return at;
}

static int take(const unsigned char *q, size_t size, size_t *at, void *x, size_t bytes)
{
    if (bytes > size - *at)
        return RC_ECORRUPT;
    if (bytes)
        memcpy(x, q + *at, bytes);
    *at += bytes;
    return RC_OK;
}

int eng_validity_read(rc_sim *s, const unsigned char *q, size_t size, size_t *used)
{
    eng_validity_free(s);
    s->val_failed = 0;
    size_t at = 0;
    uint64_t head[2];
    if (take(q, size, &at, head, sizeof head) || head[0] != VAL_MAGIC || head[1] > 1)
        return RC_ECORRUPT;
    if (head[1] == 0) {
        *used = at;
        return RC_OK;
    }
    val_books k;
    uint64_t big[2];
    if (take(q, size, &at, &k, sizeof k) || take(q, size, &at, big, sizeof big))
        return RC_ECORRUPT;
    /* the sizes must add up before anything is allocated for them */
    if (k.n != s->n || k.nd != 0 || k.nodes > k.cap || k.cap == 0 || k.cap > UINT32_MAX ||
        k.have_cur > 1 || k.cur_policy > 1 ||
        k.nodes > (size - at) / (1 + 4 * sizeof(uint32_t)))
        return RC_ECORRUPT;
    eng_validity *V = state_new((size_t)k.n, (size_t)k.cap);
    if (!V)
        return RC_ENOMEM;
    V->k = k;
    V->big[UF_ALL] = big[0];
    V->big[UF_MODEL] = big[1];
    const size_t n = (size_t)k.n, nodes = (size_t)k.nodes;
    /* caller's ball i's block to its slot k (id[k] = i): s->id is read, not yet checked */
    int st = n * sizeof *V->ball > size - at ? RC_ECORRUPT : RC_OK;
    for (size_t k = 0; k < n && st == RC_OK; k++) {
        const uint32_t i = s->id[k];
        if (i >= n || V->mark[i])
            st = RC_ECORRUPT;
        else {
            V->mark[i] = 1;
            memcpy(&V->ball[k], q + at + i * sizeof *V->ball, sizeof *V->ball);
        }
    }
    memset(V->mark, 0, n ? n : 1);
    at += st == RC_OK ? n * sizeof *V->ball : 0;
    st = st != RC_OK ||
             take(q, size, &at, V->pol, nodes) ||
             4 * nodes * sizeof(uint32_t) > size - at
                 ? RC_ECORRUPT
                 : RC_OK;
    for (int m = 0; m < 2 && st == RC_OK; m++) {
        for (size_t x = 0; x < nodes; x++)
            (void)take(q, size, &at, &V->node[x].up[m], sizeof(uint32_t));
        for (size_t x = 0; x < nodes; x++)
            (void)take(q, size, &at, &V->node[x].size[m], sizeof(uint32_t));
    }
    for (size_t i = 0; i < n && st == RC_OK; i++) {
        if (V->ball[i].hn > VAL_DEPTH)
            st = RC_ECORRUPT;
        for (size_t j = 0; j < V->ball[i].hn && st == RC_OK; j++)
            if (V->ball[i].hk[j].node >= nodes)
                st = RC_ECORRUPT;
    }
    for (size_t x = 0; x < nodes && st == RC_OK; x++)
        if (V->node[x].up[UF_ALL] >= nodes || V->node[x].up[UF_MODEL] >= nodes || V->pol[x] > 1)
            st = RC_ECORRUPT;
    for (size_t i = 0; i < n && st == RC_OK; i++)
        for (size_t j = 0; j < V->ball[i].hn; j++)
            V->ball[i].hk[j].pol = V->pol[V->ball[i].hk[j].node];
    if (st != RC_OK) {
        state_free(V);
        return st;
    }
    s->val = V;
    *used = at;
    return RC_OK;
}
