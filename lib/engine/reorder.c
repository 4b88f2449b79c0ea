/* engine/reorder.c — renumbering the balls in cell order (the event loop, engine/core.c,
 * calls it every ENG_REORDER_EVERY x N collisions and cell crossings): every per-ball array
 * permuted in place by cycles, the cells and the queue rebuilt. Invisible to the caller
 * (id / slot) and to the run's bits. */
#include <stdlib.h>
#include <string.h>

#include "private.h"
#include "relcol/status.h"

/* One ball's elements of every per-ball array, as a cycle of the permutation carries
 * them (the per_ball frames' records only where the frame keeps them). */
typedef struct carry_set {
    eng_ball b;
    eng_aux a;
    eng_clock c;
    uint32_t id, cnt;
    rc_vec3 n;
    int32_t img[3];
    eng_cov g;
    rc_glue u;
    eng_undo z, zp;
    eng_pend p;
} carry_set;

/* *slot and *cur exchanged (size bytes, at most a carry_set's member) */
static void swap_bytes(void *slot, void *cur, size_t size)
{
    unsigned char t[sizeof(carry_set)];
    memcpy(t, slot, size);
    memcpy(slot, cur, size);
    memcpy(cur, t, size);
}

/* ball i's elements into c */
static void take(const rc_sim *s, size_t i, carry_set *c)
{
    c->b = s->b[i];
    c->a = s->a[i];
    c->c = s->clk[i];
    c->id = s->id[i];
    c->cnt = s->cnt[i];
    c->n = s->ev_n ? s->ev_n[i] : rc_v3(0, 0, 0);
    memset(c->img, 0, sizeof c->img);
    if (s->img) /* (periodic boxes: the wrap counters travel with the ball) */
        memcpy(c->img, s->img + 3 * i, sizeof c->img);
    if (s->cov) {
        c->g = s->cov[i];
        c->u = s->glu[i];
        c->z = s->und[i]; /* (partners by caller's index: unchanged) */
        c->zp = s->undp[i];
        c->p = s->pend[i];
    }
}

/* c put at slot `to`, and what was there into c */
static void swap_in(rc_sim *s, size_t to, carry_set *c)
{
    swap_bytes(&s->b[to], &c->b, sizeof c->b);
    swap_bytes(&s->a[to], &c->a, sizeof c->a);
    swap_bytes(&s->clk[to], &c->c, sizeof c->c);
    swap_bytes(&s->id[to], &c->id, sizeof c->id);
    swap_bytes(&s->cnt[to], &c->cnt, sizeof c->cnt);
    if (s->ev_n)
        swap_bytes(&s->ev_n[to], &c->n, sizeof c->n);
    if (s->img)
        swap_bytes(s->img + 3 * to, c->img, sizeof c->img);
    if (s->cov) {
        swap_bytes(&s->cov[to], &c->g, sizeof c->g);
        swap_bytes(&s->glu[to], &c->u, sizeof c->u);
        swap_bytes(&s->und[to], &c->z, sizeof c->z);
        swap_bytes(&s->undp[to], &c->zp, sizeof c->zp);
        swap_bytes(&s->pend[to], &c->p, sizeof c->p);
    }
}

/* Every ENG_REORDER_EVERY x N collisions and cell crossings the balls are renumbered in cell
 * order again: they diffuse away from the order set_balls gave them, and neighbours that
 * share cache lines are what keeps a pair test from being a cache miss. O(N), in place,
 * deterministic, invisible to the caller (id / slot). The clock counts what happens to
 * the balls, not the queue's stale entries or settled bounds: how many of those there
 * are depends on how events are predicted, not on the physics, and the numbering breaks
 * ties of equal event times (which ball of a pair resolves it), so a count of entries
 * would let a change in prediction alone change the bits of a run (it made a run with
 * deferred root finds differ from one without). */
void eng_reorder(rc_sim *s)
{
    const size_t n = s->n;
    uint32_t *np = malloc(n * sizeof *np);
    int32_t *cell = malloc(n * sizeof *cell);
    unsigned char *done = calloc(n, 1);
    if (cell)
        for (size_t i = 0; i < n; i++)
            cell[i] = s->a[i].cell;
    if (!np || !cell || !done || eng_cells_number(&s->g, cell, n, np) != RC_OK) {
        free(np); /* no memory: simply keep the old order */
        free(cell);
        free(done);
        return;
    }
    free(cell);
    /* references first, then move the elements along the cycles of the permutation */
    for (size_t i = 0; i < n; i++) {
        if (s->a[i].ev_partner >= 0)
            s->a[i].ev_partner = (int32_t)np[s->a[i].ev_partner];
        s->slot[i] = np[s->slot[i]];
    }
    for (size_t i = 0; i < n; i++) {
        if (done[i])
            continue;
        /* the element carried along the cycle, one per per-ball array */
        carry_set c;
        take(s, i, &c);
        size_t o = i;
        do {
            const size_t to = np[o];
            swap_in(s, to, &c);
            done[o] = 1;
            o = to;
        } while (o != i);
    }
    free(done);
    free(np);
    eng_cells_clear(&s->g);
    for (size_t k = 0; k < n; k++)
        eng_cells_insert(&s->g, s->a, (int32_t)k, s->a[k].cell);
    /* the queue under the new numbers (and a bucket width fitted to the gas as it is now) */
    for (size_t k = 0; k < n; k++)
        s->q.e[k].key = key_of(&s->a[k]);
    eng_queue_rebuild(&s->q, s->now);
}
