/* engine/perball/kink.c — per_ball frames: where a ball's velocity changes on its worldline
 * (its kink, on the glued tube's hyperplane, and the order rule where kinks cross) and a
 * wall's contact event of the model (papers/shape-change.md sections 2, 6, 8). */
#include "model.h"
#include "relcol/status.h"

/* Ball b goes from `in` to `out` through the contact event X (tx, dx from its centre on its
 * incoming line): its kink where H (normal u_in + u_out) meets that line; a kink before the
 * previous one is put there by the order rule (counted), and an at_event kink that would
 * overtake one still pending stays at the event's time, since moving it would replay the same
 * contact for ever (RC_ESTALL). te, kappa: eng_kink_time's. */
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

/* Ball i's wall contact w from its stored state (*tx not clamped to now; *dx the shape's
 * support point P n / h(n)): 1 if X is on the future side of its last hyperplane (a contact of
 * the model). */
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
