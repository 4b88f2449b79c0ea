/* engine/slice.c — delayed table-time slices (relcol/sim.h): every ball's state at one
 * table time ts, kept up to date while kinks at or before ts are placed and undone, and
 * read once no later event can reach back to ts. Reads the engine; changes nothing a run
 * reads (its hooks only copy states out). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "private.h"
#include "model.h"
#include "relcol/status.h"

/* A ball's state at ts, and the segment it was taken on: the kink time that began it and
 * its momentum and rest mass (the stored line's); tk = NAN: taken from the record of the
 * lines before kinks ahead (eng_pend), not from a stored line. */
typedef struct slice_ball {
    rc_sim_ball b;
    double tk;
} slice_ball;

struct eng_slice {
    double ts;
    double rmax;   /* the largest rest radius (W) */
    uint32_t id;
    int taken;     /* the states are in: per_ball frames from the request on, other frames
                      once the engine's next event lies after ts */
    int read;      /* read final at least once */
    uint64_t late; /* changes after that */
    double reach;  /* the latest change: now - ts */
    slice_ball *e; /* per caller's index */
};

/* Lorentz factor of ball k's stored segment. */
static double seg_gamma(const rc_sim *s, int32_t k)
{
    const eng_aux *a = &s->a[k];
    return eng_mass_rel(a->m, a->p, s->inv_c2) / a->m;
}

/* On a periodic axis a slice may lie further from the stored time than one wrap: x in
 * [0, L) with the wraps counted (eng_ball_at wraps once, as a read at now needs). */
static void wrap_all(const rc_sim *s, rc_sim_ball *o)
{
    if (!s->img)
        return;
    for (int d = 0; d < s->def.dim; d++) {
        if (s->walled >> d & 1u)
            continue;
        const double L = s->L[d];
        double x = rc_v3_get(o->x, d);
        if (x >= 0.0 && x < L)
            continue;
        const double f = floor(x * s->inv_L[d]);
        x -= f * L;
        int32_t im = o->image[d] + (int32_t)f;
        if (x >= L) {
            x -= L;
            im++;
        } else if (x < 0.0) {
            x += L;
            im--;
            if (!(x < L))
                x = 0.0;
        }
        rc_v3_set(&o->x, d, x);
        o->image[d] = im;
    }
}

/* A change to slice sl at the engine's time: counted late if it was read. */
static void changed(const rc_sim *s, struct eng_slice *sl)
{
    sl->late += (uint64_t)sl->read;
    sl->reach = fmax(sl->reach, s->now - sl->ts);
}

/* Ball k's stored line at the slice's time (truth: the lines before kinks ahead where its
 * latest kink lies after ts; returns eng_ball_at's value). */
static int take(const rc_sim *s, const struct eng_slice *sl, int32_t k, int truth)
{
    slice_ball *e = &sl->e[s->id[k]];
    const int ahead = eng_ball_at(s, (size_t)k, sl->ts, &e->b, truth);
    wrap_all(s, &e->b);
    e->tk = ahead ? NAN : s->model->segment_start ? s->model->segment_start(s, k) : -INFINITY;
    return ahead;
}

static struct eng_slice *find(const rc_sim *s, uint32_t id)
{
    for (size_t q = 0; q < s->slc_n; q++)
        if (s->slc[q].id == id)
            return &s->slc[q];
    return NULL;
}

static void drop(rc_sim *s, size_t q)
{
    free(s->slc[q].e);
    s->slc[q] = s->slc[--s->slc_n];
}

/* other frames: the least time of a slice not taken yet */
static void set_due(rc_sim *s)
{
    s->slc_due = INFINITY;
    for (size_t q = 0; q < s->slc_n; q++)
        if (!s->slc[q].taken && s->slc[q].ts < s->slc_due)
            s->slc_due = s->slc[q].ts;
}

int rc_sim_slice_request(rc_sim *s, double ts, uint32_t *id)
{
    if (!s || !id || s->n == 0 || !isfinite(ts) || ts < s->now)
        return RC_EINVAL;
    if (s->def.gravity)
        return RC_EUNDEFINED; /* the field's loop (engine/field.c) takes no slices: never ready */
    if (s->slc_n == s->slc_cap) {
        const size_t cap = s->slc_cap ? 2 * s->slc_cap : 4;
        struct eng_slice *p = realloc(s->slc, cap * sizeof *p);
        if (!p)
            return RC_ENOMEM;
        s->slc = p;
        s->slc_cap = cap;
    }
    if (s->model->slice_gamma && !s->slc_mark) {
        s->slc_dirty = malloc(s->n * sizeof *s->slc_dirty);
        s->slc_mark = calloc(s->n, 1);
        s->slc_nd = 0;
        if (!s->slc_dirty || !s->slc_mark) {
            free(s->slc_dirty);
            free(s->slc_mark);
            s->slc_dirty = NULL;
            s->slc_mark = NULL;
            return RC_ENOMEM;
        }
    }
    struct eng_slice sl = {ts, 0.0, s->slc_next_id, 0, 0, 0, -INFINITY,
                           malloc(s->n * sizeof(slice_ball))};
    if (!sl.e)
        return RC_ENOMEM;
    for (size_t k = 0; k < s->n; k++)
        sl.rmax = fmax(sl.rmax, s->b[k].r);
    if (s->model->slice_gamma) {
        /* every ball's line at ts now; the hooks keep it (a ball with three kinks ahead of
         * ts has no recorded line there) */
        for (size_t k = 0; k < s->n; k++)
            if (take(s, &sl, (int32_t)k, 1) == 2) {
                free(sl.e);
                return RC_EINVAL;
            }
        sl.taken = 1;
        const double g = s->model->slice_gamma(s);
        s->slc_gmax = s->slc_n == 0 ? g : fmax(s->slc_gmax, g);
    }
    s->slc[s->slc_n++] = sl;
    s->slc_next_id++;
    *id = sl.id;
    if (!s->model->slice_gamma)
        set_due(s);
    return RC_OK;
}

int rc_sim_slice_ready(const rc_sim *s, uint32_t id, rc_sim_slice_info *info)
{
    if (!s)
        return RC_EINVAL;
    const struct eng_slice *sl = find(s, id);
    if (!sl)
        return RC_ENOSLICE;
    double t_final = sl->ts;
    if (s->model->slice_gamma) {
        const double g = s->slc_gmax;
        t_final = sl->ts + 2.0 * sl->rmax * s->inv_c * (1.0 + 3.0 * sqrt((g - 1.0) * (g + 1.0)));
    }
    const int fin = sl->taken && s->now >= t_final;
    if (info) {
        info->ts = sl->ts;
        info->t_final = t_final;
        info->final = fin;
        info->late = sl->late;
        info->reach = sl->reach;
    }
    return fin;
}

int rc_sim_slice_get(rc_sim *s, uint32_t id, size_t i, rc_sim_ball *out)
{
    if (!s || !out)
        return RC_EINVAL;
    struct eng_slice *sl = find(s, id);
    if (!sl)
        return RC_ENOSLICE;
    if (i >= s->n)
        return RC_EINVAL;
    if (rc_sim_slice_ready(s, id, NULL) != 1)
        return RC_ENOTREADY;
    sl->read = 1;
    *out = sl->e[i].b;
    return RC_OK;
}

int rc_sim_slice_release(rc_sim *s, uint32_t id)
{
    if (!s)
        return RC_EINVAL;
    for (size_t q = 0; q < s->slc_n; q++)
        if (s->slc[q].id == id) {
            drop(s, q);
            set_due(s);
            return RC_OK;
        }
    return RC_ENOSLICE;
}

void eng_slice_clear(rc_sim *s)
{
    while (s->slc_n)
        drop(s, s->slc_n - 1);
    free(s->slc);
    s->slc = NULL;
    s->slc_cap = 0;
    free(s->slc_dirty);
    free(s->slc_mark);
    s->slc_dirty = NULL;
    s->slc_mark = NULL;
    s->slc_nd = 0;
    s->slc_due = INFINITY;
}

size_t eng_slice_bytes(const rc_sim *s)
{
    size_t b = s->slc_cap * sizeof *s->slc + s->slc_n * s->n * sizeof(slice_ball);
    if (s->slc_mark)
        b += s->n * (sizeof *s->slc_dirty + 1);
    return b;
}

/* ---- the hooks (per_ball frames) --------------------------------------------------- */

void eng_slice_mark(rc_sim *s, int32_t k)
{
    if (!s->slc_mark)
        return;
    const uint32_t i = s->id[k];
    if (!s->slc_mark[i]) {
        s->slc_mark[i] = 1;
        s->slc_dirty[s->slc_nd++] = i;
    }
}

/* The undone kink lay at the ball's stored time: a slice at or after it is on the incoming
 * line again (which began at or before that kink), at once -- the same event may kink the
 * ball again after ts, and the end of the event would then leave the slice as it was. */
void eng_slice_undo(rc_sim *s, int32_t k)
{
    const double te = s->b[k].t;
    for (size_t q = 0; q < s->slc_n; q++) {
        struct eng_slice *sl = &s->slc[q];
        if (te <= sl->ts) {
            changed(s, sl);
            take(s, sl, k, 0);
        }
    }
    eng_slice_mark(s, k);
}

/* A ball whose latest kink lies at or before ts is on its stored line there; one whose
 * latest kink lies after ts is on a line before it, which no kink of this event changed
 * (a kink at or before ts followed by one after it in one event comes only through an
 * undo, which took the slice above), so it keeps its state. Only a new segment is taken
 * again: the same segment taken from another point of its line would round differently. */
void eng_slice_flush(rc_sim *s)
{
    for (size_t d = 0; d < s->slc_nd; d++) {
        const uint32_t i = s->slc_dirty[d];
        const int32_t k = (int32_t)s->slot[i];
        s->slc_mark[i] = 0;
        s->slc_gmax = fmax(s->slc_gmax, seg_gamma(s, k));
        const double tk = s->model->segment_start(s, k);
        const eng_aux *a = &s->a[k];
        for (size_t q = 0; q < s->slc_n; q++) {
            struct eng_slice *sl = &s->slc[q];
            if (!(tk <= sl->ts))
                continue;
            const slice_ball *e = &sl->e[i];
            if (e->tk == tk && e->b.m == a->m && memcmp(&e->b.p, &a->p, sizeof a->p) == 0)
                continue;
            changed(s, sl);
            take(s, sl, k, 0);
        }
    }
    s->slc_nd = 0;
}

/* ---- other frames: taken as the engine passes ts ------------------------------------ */

void eng_slice_take(rc_sim *s, double t_next)
{
    for (size_t q = 0; q < s->slc_n; q++) {
        struct eng_slice *sl = &s->slc[q];
        if (sl->taken || !(sl->ts < t_next))
            continue;
        for (size_t k = 0; k < s->n; k++)
            take(s, sl, (int32_t)k, 1);
        sl->taken = 1;
    }
    set_due(s);
}
