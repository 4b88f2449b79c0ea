/* engine/checkpoint.c — the whole state as bytes and back, so a stopped and continued run is
 * bit-identical to one that never stopped: a fresh engine given the same balls would predict
 * from other clocks and round differently. The queue is not carried (its order is the keys');
 * layout: header, scalars, per-ball arrays, cells, FNV-1a checksum, native order and sizes
 * checked. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "private.h"
#include "relcol/status.h"

#define CK_MAGIC "relcolck"
#define CK_VERSION 18u /* the format's number: raised by every change of layout; another is RC_EMISMATCH */
#define CK_ORDER 0x01020304u

typedef struct ck_header {
    char magic[8];
    uint32_t version, order;
    uint32_t size_ball, size_aux, size_clock, dim;
    uint64_t def_print; /* fingerprint of the definition (def_print) */
    uint64_t n, ncells;
    uint32_t has_normals, size_books;
} ck_header;

/* A cursor over the bytes; with p == NULL it only counts. */
typedef struct ck_cursor {
    unsigned char *p;
    const unsigned char *q;
    size_t at, size;
} ck_cursor;

static void put(ck_cursor *c, const void *x, size_t bytes)
{
    if (c->p && x && bytes) /* (x is NULL only when counting) */
        memcpy(c->p + c->at, x, bytes);
    c->at += bytes;
}

static int get(ck_cursor *c, void *x, size_t bytes)
{
    if (bytes > c->size - c->at)
        return RC_ECORRUPT;
    if (bytes)
        memcpy(x, c->q + c->at, bytes);
    c->at += bytes;
    return RC_OK;
}

static uint64_t fnv_bytes(uint64_t h, const void *x, size_t bytes)
{
    const unsigned char *c = x;
    for (size_t k = 0; k < bytes; k++) {
        h ^= c[k];
        h *= 0x100000001b3ULL;
    }
    return h;
}

static uint64_t fnv_double(uint64_t h, double x) { return fnv_bytes(h, &x, sizeof x); }

static uint64_t fnv_string(uint64_t h, const char *str)
{
    return fnv_bytes(h, str ? str : "", strlen(str ? str : "") + 1);
}

/* What a continued run must share with the writer: every definition field that changes the
 * physics or the event order (restart only relaxes input checks). */
static uint64_t def_print(const rc_sim *s)
{
    const rc_sim_def *d = &s->def;
    uint64_t h = 0xcbf29ce484222325ULL;
    const uint32_t dim = (uint32_t)d->dim;
    h = fnv_bytes(h, &dim, sizeof dim);
    h = fnv_double(h, d->box.x);
    h = fnv_double(h, d->box.y);
    h = fnv_double(h, d->box.z);
    h = fnv_double(h, d->c);
    h = fnv_double(h, d->eps_ball);
    h = fnv_double(h, d->eps_wall);
    h = fnv_double(h, d->t_c);
    h = fnv_string(h, d->law->name);
    h = fnv_string(h, d->frame ? d->frame->name : NULL);
    h = fnv_double(h, d->toi.touch_tol);
    h = fnv_double(h, d->toi.graze_tol);
    h = fnv_double(h, d->toi.lambda_tol);
    const int32_t it = (int32_t)d->toi.max_iter;
    h = fnv_bytes(h, &it, sizeof it);
    h = fnv_double(h, d->sim_tol);
    h = fnv_double(h, d->approach_tol);
    if (d->groups != RC_GROUPS_SIMULTANEOUS) { /* (the default leaves the print as it was) */
        const int32_t g = (int32_t)d->groups;
        h = fnv_bytes(h, &g, sizeof g);
    }
    h = fnv_double(h, d->overlap_tol);
    h = fnv_double(h, d->cell_size);
    h = fnv_double(h, d->density);
    for (int w = 0; w < 6; w++) /* (hard walls, the default, leave the print as it was) */
        if (s->wrule[w] != &rc_wall_reflecting) {
            const int32_t ww = (int32_t)w;
            h = fnv_bytes(h, &ww, sizeof ww);
            h = fnv_string(h, s->wrule[w]->name);
            h = fnv_double(h, s->wrule[w]->temperature ? d->wall_kT[w] : 0.0);
        }
    if (s->periodic) /* (walls, the default, leave the print as it was before boundaries) */
        for (int k = 0; k < d->dim; k++) {
            const int32_t bk = (int32_t)d->boundary[k];
            h = fnv_bytes(h, &bk, sizeof bk);
        }
    if (d->gravity) { /* (no field, the default, leaves the print as it was before fields) */
        h = fnv_string(h, d->gravity->name);
        h = fnv_double(h, d->g);
        const int32_t ax = (int32_t)s->fld_axis;
        h = fnv_bytes(h, &ax, sizeof ax);
    }
    return h;
}

/* The cells' chain links with every entry outside a chain set to -1 (the engine leaves
 * a removed ball's link as it was): the bytes are a function of the state alone. */
static int32_t *chain_links(const rc_sim *s)
{
    const eng_cells *g = &s->g;
    int32_t *next = malloc((s->n ? s->n : 1) * sizeof *next);
    if (!next)
        return NULL;
    for (size_t k = 0; k < s->n; k++)
        next[k] = -1;
    for (size_t j = 0; j < g->ncells * ENG_CELL_CAP; j++)
        if (g->slot[j] < -1)
            for (int32_t k = ENG_CHAIN_HEAD(g->slot[j]); k >= 0; k = g->next[k])
                next[k] = g->next[k];
    return next;
}

/* Everything but the checksum, to c (counting only if c->p is NULL; next: the chain
 * links, as chain_links gives them). */
static void write_all(const rc_sim *s, ck_cursor *c, const int32_t *next)
{
    ck_header hd;
    memset(&hd, 0, sizeof hd);
    memcpy(hd.magic, CK_MAGIC, sizeof hd.magic);
    hd.version = CK_VERSION;
    hd.order = CK_ORDER;
    hd.size_ball = sizeof(eng_ball);
    hd.size_aux = sizeof(eng_aux);
    hd.size_clock = sizeof(eng_clock);
    hd.dim = (uint32_t)s->def.dim;
    hd.def_print = def_print(s);
    hd.n = s->n;
    hd.ncells = s->n ? s->g.ncells : 0;
    hd.has_normals = s->ev_n != NULL;
    hd.size_books = sizeof(eng_books);
    put(c, &hd, sizeof hd);
    const size_t n = s->n;
    put(c, &s->now, sizeof s->now);
    const uint64_t since_reorder = s->since_reorder;
    put(c, &since_reorder, sizeof since_reorder);
    put(c, &s->bk, sizeof s->bk);
    put(c, s->b, n * sizeof *s->b);
    put(c, s->a, n * sizeof *s->a);
    put(c, s->clk, n * sizeof *s->clk);
    put(c, s->id, n * sizeof *s->id);
    put(c, s->cnt, n * sizeof *s->cnt);
    if (s->ev_n)
        put(c, s->ev_n, n * sizeof *s->ev_n);
    if (s->img) /* (periodic boxes: the wrap counters) */
        put(c, s->img, 3 * n * sizeof *s->img);
    if (s->pb) { /* (per_ball frames: the glued tubes' hyperplanes and tubes) */
        put(c, s->pb->cov, n * sizeof *s->pb->cov);
        put(c, s->pb->glu, n * sizeof *s->pb->glu);
        put(c, s->pb->und, n * sizeof *s->pb->und);
        put(c, s->pb->undp, n * sizeof *s->pb->undp);
        put(c, s->pb->pend, n * sizeof *s->pb->pend);
        c->at += eng_validity_bytes(s, c->p ? c->p + c->at : NULL);
    }
    if (s->def.gravity) /* (a field: the energy its contacts booked) */
        put(c, s->fld_work, sizeof s->fld_work);
    if (n) {
        put(c, s->g.slot, s->g.ncells * ENG_CELL_CAP * sizeof *s->g.slot);
        put(c, next, n * sizeof *next);
    }
}

int rc_sim_checkpoint_size(const rc_sim *s, size_t *bytes)
{
    if (!s || !bytes)
        return RC_EINVAL;
    ck_cursor c = {NULL, NULL, 0, 0};
    write_all(s, &c, NULL);
    *bytes = c.at + sizeof(uint64_t);
    return RC_OK;
}

int rc_sim_checkpoint_write(const rc_sim *s, void *buf, size_t bytes)
{
    size_t need;
    if (!s || !buf || rc_sim_checkpoint_size(s, &need) != RC_OK || bytes != need)
        return RC_EINVAL;
    int32_t *next = chain_links(s);
    if (!next)
        return RC_ENOMEM;
    ck_cursor c = {buf, NULL, 0, bytes};
    write_all(s, &c, next);
    free(next);
    const uint64_t sum = fnv_bytes(0xcbf29ce484222325ULL, buf, c.at);
    put(&c, &sum, sizeof sum);
    return RC_OK;
}

/* An undo record names another ball or a wall of the box, from a state the law could have left
 * (the rollback trusts it). */
static int undo_ok(const rc_sim *s, size_t k, const eng_undo *u)
{
    const eng_ball *b = &s->b[k];
    const int dim = s->def.dim;
    const int32_t q = u->partner;
    if (!(q == ENG_NONE || q == ENG_ROOT ||
          (q >= 0 && (size_t)q < s->n && (uint32_t)q != s->id[k]) ||
          (q < 0 && ENG_WALL_INDEX(q) < 2 * dim && (s->walled >> ENG_WALL_INDEX(q) / 2 & 1u))))
        return 0;
    /* its collision's members: balls of this engine, this one among them; a kind of
     * event a collision is */
    if (q != ENG_NONE) {
        int self = 0;
        if (!(u->nm >= 1 && u->nm <= ENG_UNDO_NMAX) ||
            !(u->kind == RC_SIM_EV_BALL || u->kind == RC_SIM_EV_WALL ||
              u->kind == RC_SIM_EV_MULTI) ||
            u->npol > 2 * ENG_UNDO_NMAX) /* (a tree of nm and a wall, or a cycle) */
            return 0;
        for (uint32_t m = 0; m < u->nm; m++) {
            if (!(u->mem[m] >= 0 && (size_t)u->mem[m] < s->n))
                return 0;
            self |= (uint32_t)u->mem[m] == s->id[k];
        }
        if (!self)
            return 0;
    }
    if (q != ENG_NONE &&
        (!(u->in.m > 0.0) || !isfinite(u->in.m) || !rc_v3_isfinite(u->in.p) ||
         !rc_v3_isfinite(u->n) || !isfinite(u->dt) || !rc_v3_isfinite(u->dx) ||
         isnan(u->tau_last) || u->tau_last == INFINITY || isnan(u->cov.t_k) ||
         u->cov.t_k == INFINITY || !rc_v3_isfinite(u->cov.kappa) ||
         !(rc_v3_norm2(u->cov.kappa) * s->def.c * s->def.c < 1.0 || isinf(s->def.c)) ||
         (u->glu.r != 0.0 &&
          (u->glu.r != b->r || !isfinite(u->glu.t_c) || !isfinite(u->glu.t_first) ||
           !isfinite(u->glu.t_last) || !rc_v3_isfinite(u->glu.x_c) ||
           !rc_v3_isfinite(u->glu.kappa) || !(u->glu.inv_c2 == s->inv_c2))) ||
         (dim == 2 && u->in.p.z != 0.0)))
        return 0;
    return 1;
}

/* Every scheduled event and clock as the engine itself could have left it. */
static int check_ball(const rc_sim *s, size_t k)
{
    const eng_ball *b = &s->b[k];
    const eng_aux *a = &s->a[k];
    const eng_clock *t = &s->clk[k];
    const int dim = s->def.dim;
    /* (a per_ball ball's clock may be at its last kink, after now) */
    if (!rc_v3_isfinite(b->x) || !rc_v3_isfinite(b->v) || !isfinite(b->t) ||
        !(b->t <= s->now || s->pb) ||
        !isfinite(b->r) || !(b->r > 0.0) || !rc_v3_isfinite(a->p) || !isfinite(a->m) ||
        !(a->m > 0.0) || !isfinite(t->tau) || isnan(t->tau_last) || t->tau_last == INFINITY)
        return RC_ECORRUPT;
    if (dim == 2 && (b->x.z != 0.0 || a->p.z != 0.0))
        return RC_ECORRUPT;
    if (s->pb && (isnan(s->pb->cov[k].t_k) || s->pb->cov[k].t_k == INFINITY ||
                   !isfinite(s->pb->cov[k].ev_tx) || !rc_v3_isfinite(s->pb->cov[k].ev_dx) ||
                   !rc_v3_isfinite(s->pb->cov[k].kappa) ||
                   !(rc_v3_norm2(s->pb->cov[k].kappa) * s->def.c * s->def.c < 1.0 || isinf(s->def.c))))
        return RC_ECORRUPT;
    if (s->pb && s->pb->glu[k].r != 0.0 &&
        (s->pb->glu[k].r != b->r || !isfinite(s->pb->glu[k].t_c) || !isfinite(s->pb->glu[k].t_first) ||
         !isfinite(s->pb->glu[k].t_last) || !rc_v3_isfinite(s->pb->glu[k].x_c) ||
         !rc_v3_isfinite(s->pb->glu[k].kappa) || !(s->pb->glu[k].inv_c2 == s->inv_c2)))
        return RC_ECORRUPT;
    if (s->pb && (!undo_ok(s, k, &s->pb->und[k]) || !undo_ok(s, k, &s->pb->undp[k])))
        return RC_ECORRUPT;
    if (s->pb) { /* (read only by the read-out, but it must be a state it can read) */
        const eng_pend *r = &s->pb->pend[k];
        if (r->depth < 0 || r->depth > ENG_PEND_LINES ||
            (r->depth >= 1 && (!rc_v3_isfinite(r->x) || !isfinite(r->tau) ||
                               isnan(r->tau_last) || r->tau_last == INFINITY)))
            return RC_ECORRUPT;
        for (int q = 0; q < r->depth; q++)
            if (!isfinite(r->l[q].t) || !rc_v3_isfinite(r->l[q].p) || !(r->l[q].m > 0.0) ||
                !isfinite(r->l[q].m))
                return RC_ECORRUPT;
    }
    /* v is derived from p and m, the same way every time the engine sets it */
    const rc_vec3 v = rc_v3_scale(1.0 / eng_mass_rel(a->m, a->p, s->inv_c2), a->p);
    if (memcmp(&v, &b->v, sizeof v) != 0)
        return RC_ECORRUPT;
    /* events are never in the past: the queue pops them in time order from now on */
    if (isnan(a->ev_t) || isnan(a->cross_t) || a->ev_t < s->now || a->cross_t < s->now)
        return RC_ECORRUPT;
    const int32_t p = a->ev_partner;
    if (!(p == ENG_NONE || (p >= 0 && (size_t)p < s->n && (size_t)p != k) ||
          (p < 0 && ENG_WALL_INDEX(p) < 2 * dim && (s->walled >> ENG_WALL_INDEX(p) / 2 & 1u))))
        return RC_ECORRUPT;
    if (!(a->cross_code >= -1 && a->cross_code < 2 * dim) || a->cell < 0 ||
        (size_t)a->cell >= s->g.ncells)
        return RC_ECORRUPT;
    return RC_OK;
}

/* The cells hold every ball once, in the cell its record names, every other link -1: walked
 * with bounds checks, since cell_next trusts its links. */
static int check_cells(const rc_sim *s)
{
    const eng_cells *g = &s->g;
    const size_t n = s->n;
    unsigned char *seen = calloc(n ? n : 1, 1);
    if (!seen)
        return RC_ENOMEM;
    size_t count = 0, in_chains = 0;
    int st = RC_OK;
    for (size_t j = 0; j < g->ncells * ENG_CELL_CAP && st == RC_OK; j++) {
        const int32_t v = g->slot[j];
        const int32_t cell = (int32_t)(j / ENG_CELL_CAP);
        if (v == -1)
            continue;
        int32_t k = v >= 0 ? v : ENG_CHAIN_HEAD(v);
        const int chain = v < -1;
        size_t len = 0;
        while (st == RC_OK) {
            if (k < 0 || (size_t)k >= n || seen[k] || s->a[k].cell != cell) {
                st = RC_ECORRUPT;
                break;
            }
            seen[k] = 1;
            count++;
            len++;
            if (!chain)
                break;
            in_chains++;
            if (g->next[k] == -1)
                break;
            k = g->next[k];
        }
        if (st == RC_OK && chain && len < 2)
            st = RC_ECORRUPT; /* a chain keeps at least two balls */
    }
    size_t linked = 0;
    for (size_t k = 0; k < n; k++)
        linked += g->next[k] != -1;
    free(seen);
    if (st != RC_OK)
        return st;
    /* each chain has one -1 at its end: the links that are not -1 are the chains' others */
    return count == n && linked <= in_chains ? RC_OK : RC_ECORRUPT;
}

static int read_all(rc_sim *s, ck_cursor *c)
{
    ck_header hd;
    if (get(c, &hd, sizeof hd) != RC_OK || memcmp(hd.magic, CK_MAGIC, sizeof hd.magic) != 0)
        return RC_ECORRUPT;
    if (hd.version != CK_VERSION || hd.order != CK_ORDER || hd.size_ball != sizeof(eng_ball) ||
        hd.size_aux != sizeof(eng_aux) || hd.size_clock != sizeof(eng_clock) ||
        hd.size_books != sizeof(eng_books))
        return RC_EMISMATCH; /* another format, byte order or build */
    if (hd.dim != (uint32_t)s->def.dim || hd.def_print != def_print(s) ||
        hd.has_normals != (s->narrow != 0))
        return RC_EMISMATCH;
    if (hd.n > (uint64_t)INT32_MAX)
        return RC_ECORRUPT;
    const size_t n = (size_t)hd.n;
    /* the sizes must add up before anything is allocated for them */
    const size_t per_ball = sizeof(eng_ball) + sizeof(eng_aux) + sizeof(eng_clock) +
                            2 * sizeof(uint32_t) + (hd.has_normals ? sizeof(rc_vec3) : 0) +
                            sizeof(int32_t);
    if (n > (c->size - c->at) / per_ball)
        return RC_ECORRUPT;
    double now;
    uint64_t since_reorder;
    eng_books bk;
    if (get(c, &now, sizeof now) || get(c, &since_reorder, sizeof since_reorder) ||
        get(c, &bk, sizeof bk) || !isfinite(now))
        return RC_ECORRUPT;
    /* the sums are finite (the counters may hold any count) */
    const double sums[] = {bk.heat, bk.heat_c, bk.wall[0], bk.wall[1], bk.wall[2], bk.wall_c[0],
                           bk.wall_c[1], bk.wall_c[2], bk.wallw[0], bk.wallw[1], bk.wallw[2],
                           bk.wallw[3], bk.wallw[4], bk.wallw[5], bk.wallw_c[0], bk.wallw_c[1],
                           bk.wallw_c[2], bk.wallw_c[3], bk.wallw_c[4], bk.wallw_c[5]};
    for (size_t j = 0; j < sizeof sums / sizeof *sums; j++)
        if (!isfinite(sums[j]))
            return RC_ECORRUPT;
    for (size_t j = 0; j < 18; j++)
        if (!isfinite(bk.wall_pm[j]) || !isfinite(bk.wall_pm_c[j]) ||
            (j < 6 && (!isfinite(bk.wall_q[j]) || !isfinite(bk.wall_q_c[j]))))
            return RC_ECORRUPT;
    for (size_t j = 0; j < 9; j++)
        if (!isfinite(bk.vir[j]) || !isfinite(bk.wrap[j]) ||
            (j < 3 && (!isfinite(bk.vir_e[j]) || !isfinite(bk.wrap_e[j]))))
            return RC_ECORRUPT;
    /* the largest radius sizes the cells: read it off the records before allocating */
    double rmax = 0.0;
    for (size_t k = 0; k < n; k++) {
        eng_ball b;
        memcpy(&b, c->q + c->at + k * sizeof b, sizeof b);
        if (!(b.r > 0.0 && b.r < INFINITY))
            return RC_ECORRUPT;
        rmax = b.r > rmax ? b.r : rmax;
    }
    int st = eng_alloc_state(s, n, rmax);
    if (st != RC_OK) /* (radii too large for a periodic box's four cells: not a state the
                        engine could have written) */
        return st == RC_EINVAL ? RC_ECORRUPT : st;
    if ((n ? s->g.ncells : 0) != hd.ncells)
        return RC_ECORRUPT;
    s->now = now;
    if (get(c, s->b, n * sizeof *s->b) || get(c, s->a, n * sizeof *s->a) ||
        get(c, s->clk, n * sizeof *s->clk) || get(c, s->id, n * sizeof *s->id) ||
        get(c, s->cnt, n * sizeof *s->cnt) ||
        (s->ev_n && get(c, s->ev_n, n * sizeof *s->ev_n)) ||
        (s->img && get(c, s->img, 3 * n * sizeof *s->img)) ||
        (s->pb && (get(c, s->pb->cov, n * sizeof *s->pb->cov) || get(c, s->pb->glu, n * sizeof *s->pb->glu) ||
                     get(c, s->pb->und, n * sizeof *s->pb->und) ||
                     get(c, s->pb->undp, n * sizeof *s->pb->undp) ||
                     get(c, s->pb->pend, n * sizeof *s->pb->pend))))
        return RC_ECORRUPT;
    size_t vb = 0;
    if (s->pb && (st = eng_validity_read(s, c->q + c->at, c->size - c->at, &vb)) != RC_OK)
        return st;
    c->at += vb;
    double work[2] = {0.0, 0.0};
    if (s->def.gravity &&
        (get(c, work, sizeof work) || !isfinite(work[0]) || !isfinite(work[1])))
        return RC_ECORRUPT;
    if (n && (get(c, s->g.slot, s->g.ncells * ENG_CELL_CAP * sizeof *s->g.slot) ||
              get(c, s->g.next, n * sizeof *s->g.next)))
        return RC_ECORRUPT;
    if (c->at != c->size)
        return RC_ECORRUPT;
    /* id is a permutation; slot its inverse */
    for (size_t k = 0; k < n; k++)
        s->slot[k] = UINT32_MAX;
    for (size_t k = 0; k < n; k++) {
        if (s->id[k] >= n || s->slot[s->id[k]] != UINT32_MAX)
            return RC_ECORRUPT;
        s->slot[s->id[k]] = (uint32_t)k;
    }
    for (size_t k = 0; k < n; k++)
        if ((st = check_ball(s, k)) != RC_OK)
            return st;
    if (n && (st = check_cells(s)) != RC_OK)
        return st;
    s->bk = bk;
    s->fld_work[0] = work[0];
    s->fld_work[1] = work[1];
    s->since_reorder = since_reorder;
    for (size_t k = 0; k < n; k++)
        s->q.e[k].key = key_of(&s->a[k]);
    eng_queue_rebuild(&s->q, s->now);
    return RC_OK;
}

int rc_sim_checkpoint_read(rc_sim *s, const void *buf, size_t bytes)
{
    if (!s || !buf)
        return RC_EINVAL;
    eng_slice_clear(s); /* (slices are not in a checkpoint: sim.h) */
    if (bytes < sizeof(ck_header) + sizeof(uint64_t))
        return RC_ECORRUPT;
    uint64_t sum;
    memcpy(&sum, (const unsigned char *)buf + bytes - sizeof sum, sizeof sum);
    if (sum != fnv_bytes(0xcbf29ce484222325ULL, buf, bytes - sizeof sum))
        return RC_ECORRUPT;
    ck_cursor c = {NULL, buf, 0, bytes - sizeof sum};
    const double was = s->now;
    const int st = read_all(s, &c);
    if (st != RC_OK) {
        eng_release_state(s); /* no half-loaded state is ever left behind */
        s->now = was;
    }
    return st;
}
