/* engine/perball/ops.c — the per-ball model's ops (engine/model.h): contact events, the undo
 * or group its frame forms, each member's kink around a resolve, the narrow phase's records
 * and the read-out of kinks ahead (papers/shape-change.md). */
#include <math.h>
#include <string.h>

#include "../model.h"
#include "model.h"
#include "relcol/status.h"

/* A collision reads ball b's cold records (hyperplane, tube, undo records, read-out record)
 * one after another: asked for at once their lines come in parallel. (Always inline: out of
 * line GCC drops the calls as free of side effects.) */
__attribute__((always_inline)) static inline void glue_prefetch(const rc_sim *s, int32_t b)
{
    const char *g = (const char *)&s->pb->glu[b];
    __builtin_prefetch(&s->pb->cov[b]);
    /* (five lines: the array is line-aligned, so a record starts at most 56 bytes into
     * its first line) */
    for (size_t o = 0; o < sizeof(rc_glue); o += 64)
        __builtin_prefetch(g + o);
    __builtin_prefetch(&s->pb->und[b].partner);
    /* (the record a new one shifts into the previous one: whole, written at once) */
    const char *u = (const char *)&s->pb->und[b], *up = (const char *)&s->pb->undp[b];
    for (size_t o = 0; o < sizeof(eng_undo); o += 64) {
        __builtin_prefetch(u + o);
        __builtin_prefetch(up + o, 1);
    }
    __builtin_prefetch(&s->pb->pend[b].depth);
}

static void event_begin(rc_sim *s, int32_t i, int32_t bp)
{
    glue_prefetch(s, i);
    if (bp >= 0)
        glue_prefetch(s, bp);
    eng_event_rec *e = &s->pb->event;
    e->np = bp >= 0 ? 2 : 1;
    e->ps[0] = eng_pend_take(s, i);
    if (e->np == 2)
        e->ps[1] = eng_pend_take(s, bp);
    e->rollbacks = s->bk.rollbacks;
}

/* The read-out's records of the event's balls (an undo noted its own). */
static void event_end(rc_sim *s)
{
    const eng_event_rec *e = &s->pb->event;
    for (int j = 0; j < e->np && s->bk.rollbacks == e->rollbacks; j++)
        eng_pend_note(s, &e->ps[j]);
}

/* The contact event as predicted (a ball's) or from the stored state (a wall's); one on a
 * hyperplane's incoming side, or an overlap the frame reported, goes to an undo first, else to
 * the overlap policy at T (counted). */
static int contact_event(rc_sim *s, int32_t i, int32_t bp, double T, eng_event_x *ev)
{
    if (bp >= 0) {
        const rc_vec3 n = s->ev_n[i];
        if (!isnan(n.x)) {
            ev->tx[0] = s->pb->cov[i].ev_tx;
            ev->dX[0] = s->pb->cov[i].ev_dx;
            ev->model = 1;
        } else {
            const int st = eng_undo_conflict(s, i, bp, T, n.y == 1.0);
            if (st != 0)
                return st;
            if (n.y == 1.0)
                s->bk.tube_conflicts++;
        }
        return 0;
    }
    ev->model = eng_wall_event_point(s, i, ENG_WALL_INDEX(bp), &ev->tx[0], &ev->dX[0]);
    ev->wall_tube = !ev->model;
    if (ev->wall_tube) {
        /* the shape met the wall on the incoming side of its hyperplane: the last collision
         * undone with the wall's contact, else the overlap policy */
        const int st = eng_undo_wall(s, i, bp, T, ev->tx[0]);
        if (st != 0)
            return st;
        s->bk.tube_conflicts++;
        ev->tx[0] = T;
        ev->dX[0] = rc_v3(0, 0, 0);
    }
    return 0;
}

static int group_of_model(rc_sim *s, int32_t i, int32_t bp, double T, const eng_event_x *ev)
{
    return eng_zmf_group(s, i, bp, T, ev->tx[0], ev->dX[0]);
}

/* Each changed member's kink, once, and whether its hyperplane would reach the ball before the
 * last one did: then it met its partner within its last kink's window, and that collision is
 * undone if it can be (else the order rule). */
static int before_resolve(rc_sim *s, size_t nm, const rc_particle *P, const rc_particle *Q,
                          const int *changed, const eng_event_x *ev, int undo_order)
{
    eng_single_rec *r = &s->pb->single;
    for (size_t j = 0; j < nm; j++) {
        r->cross[j] = 0;
        r->te[j] = 0.0;
        r->kap[j] = rc_v3(0, 0, 0);
        if (changed[j]) {
            const int32_t b = s->grp_ball[j];
            r->te[j] = eng_kink_time(s, b, &P[j], &Q[j], ev->tx[j], ev->dX[j], &r->kap[j]);
            r->cross[j] = eng_kinks_cross(s, b, r->te[j], r->kap[j], &P[j], &Q[j]);
        }
    }
    for (size_t j = 0; j < nm && ev->model && undo_order && nm > 1; j++)
        if (changed[j] && r->cross[j] && eng_undoable(s, s->grp_ball[j], s->grp_ball[1 - j]))
            return (int)j;
    return -1;
}

static int undo_member(rc_sim *s, int32_t w, int32_t k, double T, const eng_event_x *ev)
{
    return eng_rollback(s, w, k, T, ev->tx[0]);
}

static void resolve_member(rc_sim *s, size_t j, const rc_particle *P, const rc_particle *Q,
                           int changed, const eng_event_x *ev)
{
    eng_single_rec *r = &s->pb->single;
    const int32_t b = s->grp_ball[j];
    r->b[j] = s->b[b];
    r->c[j] = s->clk[b];
    r->g[j] = s->pb->cov[b];
    r->u[j] = s->pb->glu[b];
    /* (no change, no kink: a contact the law found nothing to resolve keeps the ball's
     * line and its hyperplane) */
    r->kinked[j] = 0;
    if (!changed)
        return;
    /* hyperplanes crossing inside the ball though the centres' kinks come in order: the tube
     * is not defined there (counted with the order conflicts; still undoable) */
    if (r->te[j] >= s->pb->cov[b].t_k && r->cross[j])
        s->bk.order_conflicts++;
    const uint64_t oc = s->bk.order_conflicts;
    eng_glue_kink_at(s, b, &P[j], &Q[j], ev->tx[j], ev->dX[j], r->te[j], r->kap[j], !ev->model);
    r->kinked[j] = s->bk.order_conflicts == oc && s->pb->glu[b].r > 0.0;
}

static const eng_ball *member_before(const rc_sim *s, size_t j) { return &s->pb->single.b[j]; }

static void take_back(rc_sim *s, size_t j)
{
    const eng_single_rec *r = &s->pb->single;
    const int32_t b = s->grp_ball[j];
    s->b[b] = r->b[j];
    s->clk[b] = r->c[j];
    s->pb->cov[b] = r->g[j];
    s->pb->glu[b] = r->u[j];
}

/* An overlap-policy decision between two balls leaves a record too, so a later tube conflict
 * undoes it with the new contact instead of a second policy decision; its event for both: on
 * the centre line at T where the rest spheres touch. */
static void after_resolve(rc_sim *s, size_t nm, int32_t bp, const rc_particle *P,
                          const rc_vec3 *vold, const eng_event_x *ev, int tc)
{
    const eng_single_rec *r = &s->pb->single;
    const int policy_pair = !ev->model && nm == 2;
    rc_vec3 dXp[2];
    if (policy_pair) {
        const int32_t b0 = s->grp_ball[0], b1 = s->grp_ball[1];
        const rc_vec3 d = eng_image(s, rc_v3_sub(r->b[1].x, r->b[0].x));
        dXp[0] = rc_v3_scale(s->b[b0].r / (s->b[b0].r + s->b[b1].r), d);
        dXp[1] = rc_v3_sub(dXp[0], d);
    }
    eng_write_undo(s, nm, bp, ev->model || policy_pair, policy_pair, P, vold, r->c, r->g, r->u,
                   ev->tx, policy_pair ? dXp : ev->dX, r->kinked, tc);
}

/* A group at one table time: every kink at the group's time (members are there),
 * through the centre. */
static void group_member(rc_sim *s, int32_t b, const rc_particle *in, const rc_particle *out)
{
    eng_glue_kink(s, b, in, out, s->b[b].t, rc_v3(0, 0, 0), 1);
}

/* (glue_valid reads a candidate's hyperplane, window_contact its window) */
static void candidate_rows(const rc_sim *s, eng_rows *rows)
{
    *rows = (eng_rows){3,
                       {(const char *)&s->pb->cov[0], (const char *)&s->pb->glu[0].r,
                        (const char *)&s->pb->glu[0].t_last},
                       {sizeof(eng_cov), sizeof(rc_glue), sizeof(rc_glue)}};
}

static void event_keep(rc_sim *s, int32_t i)
{
    s->pb->cov[i].ev_tx = s->bx_tx;
    s->pb->cov[i].ev_dx = s->bx_dx;
}

static void event_recall(rc_sim *s, int32_t i)
{
    s->bx_tx = s->pb->cov[i].ev_tx;
    s->bx_dx = s->pb->cov[i].ev_dx;
}

static double segment_start(const rc_sim *s, int32_t k) { return s->pb->cov[k].t_k; }

static double gamma_of(const rc_sim *s, double m, rc_vec3 p)
{
    return eng_mass_rel(m, p, s->inv_c2) / m;
}

/* Every ball's stored segment, the lines before its kinks ahead and the incoming lines an
 * undo (or a chain undo's) restores. */
static double slice_gamma(const rc_sim *s)
{
    double g = 1.0;
    for (size_t k = 0; k < s->n; k++) {
        g = fmax(g, gamma_of(s, s->a[k].m, s->a[k].p));
        const eng_pend *r = &s->pb->pend[k];
        for (int q = 0; q < r->depth; q++)
            g = fmax(g, gamma_of(s, r->l[q].m, r->l[q].p));
        if (s->pb->und[k].partner != ENG_NONE)
            g = fmax(g, gamma_of(s, s->pb->und[k].in.m, s->pb->und[k].in.p));
        if (s->pb->undp[k].partner != ENG_NONE)
            g = fmax(g, gamma_of(s, s->pb->undp[k].in.m, s->pb->undp[k].in.p));
    }
    return g;
}

const eng_model_ops eng_model_glued = {
    .name = "glued tubes",
    .per_ball = 1,
    .pair_time = eng_glued_pair_time,
    .candidate_rows = candidate_rows,
    .event_keep = event_keep,
    .event_recall = event_recall,
    .event_begin = event_begin,
    .event_end = event_end,
    .contact_event = contact_event,
    .group_of_model = group_of_model,
    .before_resolve = before_resolve,
    .undo_member = undo_member,
    .resolve_member = resolve_member,
    .member_before = member_before,
    .take_back = take_back,
    .after_resolve = after_resolve,
    .group_member = group_member,
    .ball_at = eng_pend_read,
    .segment_start = segment_start,
    .slice_gamma = slice_gamma,
};
