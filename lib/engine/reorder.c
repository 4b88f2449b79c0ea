/* engine/reorder.c — renumbering the balls in cell order every ENG_REORDER_EVERY x N
 * collisions and crossings: per-ball arrays permuted in place, cells and queue rebuilt;
 * invisible to the caller (id / slot) and to the bits. */
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
    if (s->pb) {
        c->g = s->pb->cov[i];
        c->u = s->pb->glu[i];
        c->z = s->pb->und[i]; /* (partners by caller's index: unchanged) */
        c->zp = s->pb->undp[i];
        c->p = s->pb->pend[i];
    }
}

/* c's elements put at slot `to` */
static void put(rc_sim *s, size_t to, const carry_set *c)
{
    s->b[to] = c->b;
    s->a[to] = c->a;
    s->clk[to] = c->c;
    s->id[to] = c->id;
    s->cnt[to] = c->cnt;
    if (s->ev_n)
        s->ev_n[to] = c->n;
    if (s->img)
        memcpy(s->img + 3 * to, c->img, sizeof c->img);
    if (s->pb) {
        s->pb->cov[to] = c->g;
        s->pb->glu[to] = c->u;
        s->pb->und[to] = c->z;
        s->pb->undp[to] = c->zp;
        s->pb->pend[to] = c->p;
    }
}

/* slot `from`'s elements copied to slot `to` */
static void move(rc_sim *s, size_t to, size_t from)
{
    s->b[to] = s->b[from];
    s->a[to] = s->a[from];
    s->clk[to] = s->clk[from];
    s->id[to] = s->id[from];
    s->cnt[to] = s->cnt[from];
    if (s->ev_n)
        s->ev_n[to] = s->ev_n[from];
    if (s->img)
        memcpy(s->img + 3 * to, s->img + 3 * from, 3 * sizeof *s->img);
    if (s->pb) {
        s->pb->cov[to] = s->pb->cov[from];
        s->pb->glu[to] = s->pb->glu[from];
        s->pb->und[to] = s->pb->und[from];
        s->pb->undp[to] = s->pb->undp[from];
        s->pb->pend[to] = s->pb->pend[from];
    }
}

/* Renumber in cell order again (balls diffuse away from it, and shared cache lines keep pair
 * tests cheap); the clock counts collisions and crossings, not queue entries, so that how
 * events are predicted cannot change a run's tie-breaking and its bits. */
void eng_reorder(rc_sim *s)
{
    const size_t n = s->n;
    uint32_t *np = malloc(n * sizeof *np);
    int32_t *cell = malloc(n * sizeof *cell);
    uint32_t *inv = malloc(n * sizeof *inv);
    unsigned char *done = calloc(n, 1);
    if (cell)
        for (size_t i = 0; i < n; i++)
            cell[i] = s->a[i].cell;
    if (!np || !cell || !inv || !done || eng_cells_number(&s->g, cell, n, np) != RC_OK) {
        free(np); /* no memory: simply keep the old order */
        free(inv);
        free(cell);
        free(done);
        return;
    }
    free(cell);
    /* references first, then each cycle of the permutation walked backwards: one copy of each
     * element (per_ball records are kilobytes a ball); the permutation is the same */
    for (size_t i = 0; i < n; i++) {
        if (s->a[i].ev_partner >= 0)
            s->a[i].ev_partner = (int32_t)np[s->a[i].ev_partner];
        s->slot[i] = np[s->slot[i]];
    }
    for (size_t i = 0; i < n; i++)
        inv[np[i]] = (uint32_t)i;
    for (size_t i = 0; i < n; i++) {
        if (done[i])
            continue;
        carry_set c;
        take(s, i, &c);
        size_t o = i;
        for (size_t from = inv[o]; from != i; o = from, from = inv[o]) {
            move(s, o, from);
            done[o] = 1;
        }
        put(s, o, &c);
        done[o] = 1;
    }
    memset(done, 0, n);
    eng_validity_reorder(s, np, inv, done); /* (its blocks by slot too) */
    free(inv);
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
