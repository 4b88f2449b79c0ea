/* engine/reorder.c — renumbering the balls in cell order (the event loop, engine/core.c,
 * calls it every ENG_REORDER_EVERY x N collisions and cell crossings): every per-ball array
 * permuted in place by cycles, the cells and the queue rebuilt. Invisible to the caller
 * (id / slot) and to the run's bits. */
#include <stdlib.h>
#include <string.h>

#include "private.h"
#include "relcol/status.h"

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
        const rc_vec3 zero = rc_v3(0, 0, 0);
        rc_vec3 cn = s->ev_n ? s->ev_n[i] : zero;
        eng_cov cg;
        rc_glue cu;
        eng_undo cz, czp;
        eng_pend cp;
        if (s->cov) {
            cg = s->cov[i];
            cu = s->glu[i];
            cz = s->und[i];
            czp = s->undp[i];
            cp = s->pend[i];
        }
        eng_ball cb = s->b[i];
        eng_aux ca = s->a[i];
        eng_clock cc = s->clk[i];
        uint32_t cid = s->id[i], ccnt = s->cnt[i];
        int32_t cim[3] = {0, 0, 0};
        if (s->img)
            memcpy(cim, s->img + 3 * i, sizeof cim);
        size_t o = i;
        do {
            size_t to = np[o];
            if (s->img) { /* (periodic boxes: the wrap counters travel with the ball) */
                int32_t tim[3];
                memcpy(tim, s->img + 3 * to, sizeof tim);
                memcpy(s->img + 3 * to, cim, sizeof cim);
                memcpy(cim, tim, sizeof cim);
            }
            eng_ball tb = s->b[to];
            eng_aux ta = s->a[to];
            eng_clock tcl = s->clk[to];
            uint32_t tid = s->id[to], tcnt = s->cnt[to];
            const rc_vec3 tn = s->ev_n ? s->ev_n[to] : zero;
            if (s->ev_n)
                s->ev_n[to] = cn;
            cn = tn;
            if (s->cov) {
                const eng_cov tg = s->cov[to];
                s->cov[to] = cg;
                cg = tg;
                const rc_glue tu = s->glu[to];
                s->glu[to] = cu;
                cu = tu;
                const eng_undo tz = s->und[to]; /* (partners by caller's index: unchanged) */
                s->und[to] = cz;
                cz = tz;
                const eng_undo tzp = s->undp[to];
                s->undp[to] = czp;
                czp = tzp;
                const eng_pend tp = s->pend[to];
                s->pend[to] = cp;
                cp = tp;
            }
            s->b[to] = cb;
            s->a[to] = ca;
            s->clk[to] = cc;
            s->id[to] = cid;
            s->cnt[to] = ccnt;
            cb = tb;
            ca = ta;
            cc = tcl;
            cid = tid;
            ccnt = tcnt;
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
