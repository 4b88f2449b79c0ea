/* engine/perball/narrow.c — the per-ball model's narrow phase (engine/model.h pair_time): a
 * predicted contact of two glued tubes checked against both hyperplanes, and the same contact
 * asked from earlier stored lines (an undo's, a group's). */
#include <math.h>

#include "glue_pair.h"
#include "../model.h"
#include "model.h"
#include "relcol/status.h"

/* Do the pieces a tube contact met approach at ta though the stored lines part? An incoming
 * piece moves on its incoming line, and judged by the stored lines alone the pair would go on
 * overlapping uncounted (papers/shape-change.md section 8). dx, dv at pref; tref, t, y:
 * glue_contact's. */
static int pieces_approach(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                           double pref, rc_vec3 dv, double tref, double t, rc_vec3 y, double ta)
{
    const size_t i = (size_t)(bi - s->b), k = (size_t)(bk - s->b);
    const rc_glue *gi = &s->pb->glu[i], *gk = &s->pb->glu[k];
    const int sides = glue_sides(s, bi, bk, rc_v3_axpy(dx, tref - pref, dv), tref, t, y);
    const int in_i = gi->r > 0.0 && !(sides & 1), in_k = gk->r > 0.0 && !(sides & 2);
    if (!in_i && !in_k)
        return 0;
    rc_vec3 sep = rc_v3_axpy(dx, ta - pref, dv), vi = bi->v, vk = bk->v;
    if (in_i) { /* (the incoming centre minus the outgoing one at ta) */
        vi = gi->v_in;
        sep = rc_v3_axpy(sep, -(ta - gi->t_c), rc_v3_sub(vi, bi->v));
    }
    if (in_k) {
        vk = gk->v_in;
        sep = rc_v3_axpy(sep, ta - gk->t_c, rc_v3_sub(vk, bk->v));
    }
    return rc_v3_dot(sep, rc_v3_sub(vk, vi)) < 0.0;
}


/* The contact of bi and bk whose bounding spheres can touch before best (dx: their
 * separation at tref; parting: the spheres overlap and part): its table time, or INFINITY. */
double eng_glued_pair_time(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                           double tref, double best, int parting, rc_vec3 *n)
{
    double ta;
    /* per_ball frames: the contact event, checked against both balls' hyperplanes */
    rc_toi_contact out;
    int valid = 0;
    const double pref = tref; /* (dx is at pref; glue_contact may move tref) */
    const int st = glue_contact(s, bi, bk, dx, &tref, &out, &valid);
    if (st == RC_OK && !valid) {
        /* a contact with a tube's incoming piece, which the schedule cannot order: an event
         * (an undo, else the policy, counted) if the centres or the pieces met approach at
         * max(t_X, now), when it is resolved; judged earlier, a pair parting by then would
         * come up again at once (RC_ESTALL) */
        const rc_vec3 dv = rc_v3_sub(bk->v, bi->v);
        ta = tref + out.t;
        ta = ta < s->now ? s->now : ta;
        if (!(rc_v3_dot(rc_v3_axpy(dx, ta - pref, dv), dv) < 0.0) &&
            !(tref + out.t > s->now &&
              pieces_approach(s, bi, bk, dx, pref, dv, tref, out.t, out.x, ta)))
            return INFINITY;
        if (!(ta < best))
            return INFINITY;
        *n = rc_v3(NAN, 1.0, 0.0);
        rc_sim *w = (rc_sim *)s; /* (its X: the collision decides whose tube it is) */
        w->sc_tx = tref + out.t;
        w->sc_dx = rc_v3_axpy(out.x, -out.t, bi->v);
        return ta;
    }
    if (st == RC_EOVERLAP && glue_back(s, bi, bk, dx, pref, &out) == RC_OK) {
        tref = pref; /* (out is relative to dx's time) */
    } else if (st == RC_EOVERLAP) {
        if (parting)
            return INFINITY;
        *n = rc_v3(NAN, NAN, NAN);
        return s->now;
    } else if (st != RC_OK)
        return INFINITY;
    /* approach as the law sees it (velocities along n), not the frame's ZMF verdict from a
     * line taken back before its kink: where they disagree the law resolves nothing and the
     * contact recurs at once (RC_ESTALL) */
    if (!(rc_v3_dot(rc_v3_sub(bi->v, bk->v), out.n) > 0.0))
        return INFINITY;
    *n = out.n;
    ta = tref + out.t;
    if (ta < s->now)
        ta = s->now;
    if (!(ta < best))
        return INFINITY;
    rc_sim *w = (rc_sim *)s; /* (scratch: the event's X, kept if it becomes the best) */
    w->sc_tx = tref + out.t;
    w->sc_dx = rc_v3_axpy(out.x, -out.t, bi->v);
    return ta;
}

/* The frame's contact of a and b from their stored lines at t0 (not clamped, so one behind the
 * schedule is found): RC_OK with X (*tx, *dx from a's centre) and *n when X is on both future
 * sides and the law sees approach; ENG_BEFORE_A on a's incoming side; RC_MISS; else the
 * frame's code. */
int eng_pair_contact(rc_sim *s, int32_t a, int32_t b, double t0, double *tx, rc_vec3 *dx,
                     rc_vec3 *n)
{
    const eng_ball *ba = &s->b[a], *bb = &s->b[b];
    const rc_vec3 d = eng_image(s, rc_v3_sub(rc_v3_axpy(bb->x, t0 - bb->t, bb->v),
                                             rc_v3_axpy(ba->x, t0 - ba->t, ba->v)));
    rc_toi_contact out;
    int st = frame_call(s, ba, bb, d, &out);
    if (st == RC_EOVERLAP) /* (the straight cylinders met ZMF-before t0: glue_back) */
        st = glue_back(s, ba, bb, d, t0, &out) == RC_OK ? RC_OK : RC_MISS;
    if (st != RC_OK)
        return st;
    if (!glue_valid(s, ba, bb, d, t0, out.t, out.x)) {
        /* (X on the incoming side of a's hyperplane: before a's last kink too) */
        const int before_a = !eng_glue_side(&s->pb->cov[a], &s->pb->glu[a], ba->v, t0 + out.t,
                                            rc_v3_axpy(out.x, -out.t, ba->v));
        return before_a ? ENG_BEFORE_A : RC_MISS;
    }
    if (!(rc_v3_dot(rc_v3_sub(ba->v, bb->v), out.n) > 0.0))
        return RC_MISS;
    *tx = t0 + out.t;
    *dx = rc_v3_axpy(out.x, -out.t, ba->v);
    *n = out.n;
    return RC_OK;
}
