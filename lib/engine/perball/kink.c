/* engine/perball/kink.c — per_ball frames: where a ball's velocity changes on its worldline (its
 * kink, through the glued tube's hyperplane, and the order rule where kinks cross), and a
 * wall's contact event of the model (papers/shape-change.md, sections 2, 6 and 8). Used
 * by the event loop (engine/core.c) and the undo (engine/perball/undo.c). */
#include "model.h"
#include "relcol/status.h"

/* per_ball frames: ball b's velocity changes from `in` to `out` through the contact event
 * X at table time tx, dx = X - (its centre at tx on its stored line), which is still the
 * incoming one (papers/shape-change.md, section 2): its kink is where the hyperplane H
 * through X with normal u_in + u_out, t - tx = kappa.(y - X), meets that line, at
 * t_E = tx - kappa.dx / (1 - kappa.v_in). The stored state is moved there (backwards or
 * forwards along the incoming line; the caller then writes the outgoing momentum) and H
 * is kept as the start of the new segment. A kink before the ball's previous one along
 * its worldline (successive hyperplanes crossing inside the tube: collisions less than a
 * glue window apart, where the glued tube of the two is not defined) is a model rule:
 * the change is put at the previous kink, and counted.
 * at_event: a kink the engine puts at the event's time through the centre (the overlap
 * policy's, a group's). Such a kink before a kink still pending (ahead of now) overtakes
 * it: put where the order rule would, at the pending kink, it would leave the ball's line
 * up to there, and so the geometry that called the policy, as it was, and the same
 * contact would come up again at the same instant for ever (RC_ESTALL). It is kept at the event's time instead (counted with the order
 * conflicts; the ball's centre there is its stored line's). te, kappa: eng_kink_time's. */
void eng_glue_kink_at(rc_sim *s, int32_t b, const rc_particle *in, const rc_particle *out,
                      double tx, rc_vec3 dx, double te, rc_vec3 kappa, int at_event)
{
    eng_validity_kink(s, b);
    eng_cov *cv = &s->pb->cov[b];
    /* the tube, for a neighbour met while the ball is in its window (X at the origin) */
    if (rc_glue_make(s->inv_c2, s->b[b].r, in, out, tx, rc_v3_scale(-1.0, dx),
                     rc_v3(0.0, 0.0, 0.0), &s->pb->glu[b]) != RC_OK)
        s->pb->glu[b].r = 0.0;
    if (!(te >= cv->t_k)) {
        if (!(at_event && cv->t_k > s->now))
            te = cv->t_k;
        s->bk.order_conflicts++;
        s->pb->glu[b].r = 0.0; /* (the stored line is no longer the tube's outgoing one) */
    }
    eng_advance_ball(s, b, te);
    cv->t_k = te;
    cv->kappa = kappa;
    if (s->slc_n) /* (a delayed slice at or after te follows the ball after the event) */
        eng_slice_mark(s, b);
}

void eng_glue_kink(rc_sim *s, int32_t b, const rc_particle *in, const rc_particle *out,
                   double tx, rc_vec3 dx, int at_event)
{
    rc_vec3 kappa;
    const double te = eng_kink_time(s, b, in, out, tx, dx, &kappa);
    eng_glue_kink_at(s, b, in, out, tx, dx, te, kappa, at_event);
}

/* per_ball frames: ball i's wall contact w from its stored state, *tx its time (not
 * clamped to now), *dx = X - (centre at *tx): the support point of its shape along the
 * wall normal n, P n / h(n) with P = r^2 (I - beta beta^T). 1 if X is on the future side
 * of the ball's last hyperplane (a contact of the model), else 0. */
int eng_wall_event_point(const rc_sim *s, int32_t i, int w, double *tx, rc_vec3 *dx)
{
    const eng_ball *b = &s->b[i];
    const int d = w / 2, up = w & 1;
    const double h = eng_wall_support(s, i, d), x = rc_v3_get(b->x, d), v = rc_v3_get(b->v, d);
    *tx = b->t + (up ? s->L[d] - h - x : x - h) / (up ? v : -v);
    const rc_vec3 beta = rc_v3_scale(s->inv_c, b->v);
    rc_vec3 e = rc_v3(0, 0, 0);
    rc_v3_set(&e, d, up ? 1.0 : -1.0);
    const double bn = rc_v3_get(beta, d) * (up ? 1.0 : -1.0);
    *dx = rc_v3_scale(b->r * b->r / h, rc_v3_axpy(e, -bn, beta));
    return eng_glue_side(&s->pb->cov[i], &s->pb->glu[i], b->v, *tx, *dx);
}
