/* engine/perball/pending.c — per_ball frames: the read-out's record of the lines a ball is
 * still on before kinks after the engine's time (eng_pend, read by engine/diag.c), kept after
 * each event and undo; changes nothing a run reads. */
#include <math.h>

#include "model.h"

eng_pend_snap eng_pend_take(const rc_sim *s, int32_t b)
{
    const eng_pend_snap p = {b, s->cnt[b], s->pb->cov[b].t_k, {s->a[b].m, s->a[b].p}, s->clk[b].tau_last};
    return p;
}

/* After an event: the record of the lines ball p.b is still on at now, from its state before
 * (only the event's own balls can get a kink after now). */
void eng_pend_note(rc_sim *s, const eng_pend_snap *p)
{
    const int32_t b = p->b;
    if (s->cnt[b] == p->cnt)
        return; /* (no change: no kink) */
    eng_pend *r = &s->pb->pend[b];
    const double te = s->pb->cov[b].t_k, now = s->now;
    while (r->depth >= 2 && r->l[0].t <= now) {
        /* the first recorded line has ended: the next is the one the ball is on, from
         * that kink (its centre and proper time there) */
        const double M = eng_mass_rel(r->l[1].m, r->l[1].p, s->inv_c2), h = r->l[1].t - r->l[0].t;
        r->x = rc_v3_axpy(r->x, h, rc_v3_scale(1.0 / M, r->l[1].p));
        r->tau_last = r->tau;
        r->tau += h * (r->l[1].m / M);
        for (int k = 1; k < r->depth; k++) {
            r->l[k - 1].t = r->l[k].t;
            r->l[k - 1].p = r->l[k].p;
            r->l[k - 1].m = r->l[k].m;
        }
        r->depth--;
    }
    if (!(te > now)) { /* on its outgoing line from now on */
        r->depth = 0;
        return;
    }
    if (!(p->t_k > now)) { /* it was on its stored line at now: that line, up to te */
        const eng_ball *e = &s->b[b];
        const double h = te - e->t;
        r->depth = 1;
        r->l[0].t = te;
        r->x = h == 0.0 ? e->x : rc_v3_axpy(e->x, h, e->v);
        r->l[0].p = p->in.p;
        r->l[0].m = p->in.m;
        r->tau = s->clk[b].tau;
        if (h != 0.0)
            r->tau += h * (s->a[b].m / eng_mass_rel(s->a[b].m, s->a[b].p, s->inv_c2));
        r->tau_last = p->tau_last;
        for (int d = 0; d < 3; d++)
            r->img[d] = s->img ? s->img[3 * (size_t)b + (size_t)d] : 0;
        return;
    }
    /* a kink was already ahead: the line from it to the new one is recorded if the record ends
     * there and has room (else the read-out says not recorded) */
    if (te > p->t_k && r->depth >= 1 && r->depth < ENG_PEND_LINES &&
        r->l[r->depth - 1].t == p->t_k) {
        r->l[r->depth].t = te;
        r->l[r->depth].p = p->in.p;
        r->l[r->depth].m = p->in.m;
        r->depth++;
    }
}

/* A ball's record when its kink at te is undone: the line ending there dropped (the one before
 * is its line again); a record not ending there is cleared. */
void eng_pend_undo(eng_pend *r, double te)
{
    if (r->depth >= 2 && r->l[r->depth - 1].t == te)
        r->depth--;
    else
        r->depth = 0;
}

/* Ball i at t >= now where its latest kink lies ahead, from eng_pend's lines: 1 (*x in the
 * wrap coordinates *img, p, m, tau, TC memory set), 2 if that line was not recorded, 0 if on
 * its stored line. */
int eng_pend_read(const rc_sim *s, size_t i, double now, rc_sim_ball *o, const int32_t **img)
{
    if (!s->pb || !(s->pb->cov[i].t_k > now))
        return 0;
    const eng_pend *r = &s->pb->pend[i];
    int k = 0;
    while (k < r->depth && !(now < r->l[k].t))
        k++;
    if (k == r->depth)
        return 2;
    /* line k: from the first recorded kink (k = 0: back from it), else along the lines
     * between to kink k - 1 */
    double t0 = r->l[0].t, tau0 = r->tau, tau_last = r->tau_last;
    rc_vec3 x0 = r->x;
    for (int q = 1; q < k; q++) {
        const double M = eng_mass_rel(r->l[q].m, r->l[q].p, s->inv_c2), h = r->l[q].t - t0;
        x0 = rc_v3_axpy(x0, h, rc_v3_scale(1.0 / M, r->l[q].p));
        tau0 += h * (r->l[q].m / M);
        t0 = r->l[q].t;
    }
    if (k >= 1)
        tau_last = tau0;
    const rc_vec3 p = r->l[k].p;
    const double m = r->l[k].m;
    const double h = now - t0, M = eng_mass_rel(m, p, s->inv_c2);
    o->x = rc_v3_axpy(x0, h, rc_v3_scale(1.0 / M, p));
    o->p = p;
    o->m = m;
    o->tau = tau0 + h * (m / M);
    o->collided = isfinite(tau_last);
    o->tau_last = o->collided ? tau_last : 0.0;
    *img = r->img;
    return 1;
}
