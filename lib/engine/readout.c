/* engine/readout.c — a ball at a time: its stored line taken there, or (per-ball frames) the
 * line it is still on before a kink ahead, and the public read-outs built on it. */
#include <math.h>

#include "private.h"
#include "model.h"
#include "path.h"
#include "relcol/status.h"

/* Periodic axes: x put in [0, L) (a ball exactly at its wrap, not yet processed, may lie
 * a rounding error outside), with the wrap counted in image from the stored img. */
static inline void wrap(const rc_sim *s, const int32_t *img, rc_vec3 *xo, int32_t image[3])
{
    for (int d = 0; d < 3; d++) {
        image[d] = 0;
        if (!s->img || s->walled >> d & 1u || d >= s->def.dim)
            continue;
        int32_t im = img[d];
        double x = rc_v3_get(*xo, d);
        const double L = s->L[d];
        if (x >= L) {
            x -= L;
            im++;
        } else if (x < 0.0) {
            const double y = x + L;
            if (y < L) {
                x = y;
                im--;
            } else {
                x = 0.0; /* (within half an ulp of L below 0) */
            }
        }
        rc_v3_set(xo, d, x);
        image[d] = im;
    }
}

int eng_ball_now(const rc_sim *s, size_t i, rc_sim_ball *o, int truth)
{
    return eng_ball_at(s, i, s->now, o, truth);
}

int eng_ball_at(const rc_sim *s, size_t i, double t, rc_sim_ball *o, int truth)
{
    const eng_ball *b = &s->b[i];
    const eng_aux *a = &s->a[i];
    double h = t - b->t;
    o->x = h == 0.0 ? b->x : rc_v3_axpy(b->x, h, b->v);
    o->p = a->p;
    o->r = b->r;
    o->m = a->m;
    const eng_clock *k = &s->clk[i];
    o->tau = k->tau;
    o->collided = isfinite(k->tau_last);
    o->tau_last = o->collided ? k->tau_last : 0.0;
    if (h != 0.0)
        o->tau += s->inv_c2 == 0.0 ? h : h * (a->m / eng_mass_rel(a->m, a->p, s->inv_c2));
    if (h != 0.0 && s->path->ball_at) { /* (a curved path: engine/path.h) */
        o->tau = k->tau;
        s->path->ball_at(s, i, h, o);
    }
    const int32_t *img = s->img ? s->img + 3 * i : NULL;
    const int ahead = truth && s->model->ball_at ? s->model->ball_at(s, i, t, o, &img) : 0;
    wrap(s, img, &o->x, o->image);
    return ahead;
}

int rc_sim_get_ball(const rc_sim *s, size_t i, rc_sim_ball *out)
{
    if (!s || !out || i >= s->n)
        return RC_EINVAL;
    eng_ball_now(s, s->slot[i], out, 1);
    return RC_OK;
}

int rc_sim_get_ball_latest(const rc_sim *s, size_t i, rc_sim_ball *out)
{
    if (!s || !out || i >= s->n)
        return RC_EINVAL;
    eng_ball_now(s, s->slot[i], out, 0);
    return RC_OK;
}

int rc_sim_get_balls(const rc_sim *s, size_t n, rc_sim_ball *out, int latest, int8_t *ahead)
{
    if (!s || (n && !out) || n != s->n)
        return RC_EINVAL;
    /* in storage order, each ball written to its caller's index: the engine's arrays are
     * walked once, in order, however the balls were renumbered */
    for (size_t k = 0; k < n; k++) {
        const int a = eng_ball_now(s, k, &out[s->id[k]], !latest);
        if (ahead)
            ahead[s->id[k]] = (int8_t)a;
    }
    return RC_OK;
}

int rc_sim_get_balls_stored(const rc_sim *s, size_t from, size_t count, rc_sim_ball *out,
                            size_t *id, int latest, int8_t *ahead)
{
    if (!s || (count && (!out || !id)) || from > s->n || count > s->n - from)
        return RC_EINVAL;
    for (size_t j = 0; j < count; j++) {
        const int a = eng_ball_now(s, from + j, &out[j], !latest);
        id[j] = s->id[from + j];
        if (ahead)
            ahead[j] = (int8_t)a;
    }
    return RC_OK;
}

int rc_sim_get_positions(const rc_sim *s, size_t n, int dim, double *x, int latest)
{
    if (!s || (n && !x) || n != s->n || dim != s->def.dim)
        return RC_EINVAL;
    /* the full read's centres without its proper time (a square root and a division a
     * ball): a curved path or a per-ball frame's kinks ahead take the full read */
    const int full = s->path->ball_at || (!latest && s->model->ball_at);
    for (size_t k = 0; k < n; k++) {
        rc_vec3 c;
        int32_t image[3];
        if (full) {
            rc_sim_ball o;
            eng_ball_now(s, k, &o, !latest);
            c = o.x;
        } else {
            const eng_ball *b = &s->b[k];
            const double h = s->now - b->t;
            c = h == 0.0 ? b->x : rc_v3_axpy(b->x, h, b->v);
            wrap(s, s->img ? s->img + 3 * k : NULL, &c, image);
        }
        double *to = x + s->id[k] * (size_t)dim;
        for (int d = 0; d < dim; d++)
            to[d] = rc_v3_get(c, d);
    }
    return RC_OK;
}

int rc_sim_get_glue(const rc_sim *s, size_t i, rc_glue *out)
{
    if (!s || !out || i >= s->n || !s->pb)
        return RC_EINVAL;
    const size_t k = s->slot[i];
    *out = s->pb->glu[k];
    if (out->r > 0.0) {
        /* kept with the contact event at the origin: shifted so that its centre at t_c is
         * the stored line's there (its kink) */
        const eng_ball *b = &s->b[k];
        const rc_vec3 shift = rc_v3_sub(rc_v3_axpy(b->x, out->t_c - b->t, b->v), out->x_c);
        out->x = rc_v3_add(out->x, shift);
        out->x_c = rc_v3_add(out->x_c, shift);
    }
    return RC_OK;
}

int rc_sim_kink_ahead(const rc_sim *s, size_t i)
{
    if (!s || i >= s->n)
        return RC_EINVAL;
    rc_sim_ball b;
    return eng_ball_now(s, s->slot[i], &b, 1);
}
