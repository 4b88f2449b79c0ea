/* engine/setup.c — making an engine: the definition's defaults and checks, create/free,
 * and placing balls (validated, stored in cell order, first events predicted). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lanes.h"
#include "private.h"
#include "model.h"
#include "path.h"
#include "relcol/status.h"

/* Cell edge margin over the largest bounding diameter (relative): balls that can touch stay in
 * adjacent cells despite round-off of the boundaries. */
#define CELL_MARGIN 1e-8

rc_sim_def rc_sim_def_default(void)
{
    rc_sim_def d;
    memset(&d, 0, sizeof d);
    d.dim = 3;
    d.box = rc_v3(1.0, 1.0, 1.0);
    d.c = INFINITY;
    d.eps_ball = 1.0;
    d.eps_wall = 1.0;
    d.t_c = 0.0;
    d.law = &rc_law_zmf;
    d.frame = NULL;
    d.toi = rc_toi_params_default();
    d.toi.c = NAN; /* the engine's c */
    d.sim_tol = 1e-9;
    d.groups = RC_GROUPS_SIMULTANEOUS;
    d.approach_tol = 1e-10;
    d.overlap_tol = 1e-9;
    d.cell_size = 0.0;
    d.density = 1.0;
    d.simd = RC_SIM_SIMD_AUTO;
    d.defer = RC_SIM_DEFER_AUTO;
    return d;
}

/* A uniform field (papers/gravity.md): a coupling the engine has a path for, g > 0, an
 * axis of the box with walls (its floor and ceiling); the frame one-instant and
 * uncontracted, for the field's contact is decided at one instant of the coupling's clock
 * (a per-ball or contracted frame in a field is not defined: RC_EUNDEFINED); its walls
 * are hard walls (a thermal wall in a field is not built: RC_EUNDEFINED). */
static int check_field(const rc_sim_def *d)
{
    if (!d->gravity)
        return RC_OK;
    if (!eng_path_for(d))
        return RC_EUNKNOWN;
    if (!isfinite(d->g))
        return RC_ENONFINITE;
    const int ax = d->g_axis < 0 ? d->dim - 1 : d->g_axis;
    if (!(d->g > 0.0) || d->g_axis < -1 || ax >= d->dim || d->boundary[ax] != RC_SIM_WALLS)
        return RC_EINVAL;
    if (d->frame && (d->frame->contracted || d->frame->pointlike || d->frame->per_ball ||
                     d->frame->wall_contracted))
        return RC_EUNDEFINED;
    for (int w = 0; w < 6; w++) /* the field's own loop resolves walls as hard walls only */
        if (d->wall_rule[w] && d->wall_rule[w] != &rc_wall_reflecting)
            return RC_EUNDEFINED;
    return RC_OK;
}

static int check_def(const rc_sim_def *d)
{
    if (d->dim != 2 && d->dim != 3)
        return RC_EDIM;
    if (!rc_v3_isfinite(d->box) || !isfinite(d->eps_ball) || !isfinite(d->eps_wall) ||
        !isfinite(d->t_c) || !isfinite(d->sim_tol) || !isfinite(d->approach_tol) ||
        !isfinite(d->overlap_tol) || !isfinite(d->cell_size) || !isfinite(d->density))
        return RC_ENONFINITE;
    if (!(d->box.x > 0.0 && d->box.y > 0.0 && (d->dim == 2 || d->box.z > 0.0)))
        return RC_EINVAL;
    if (!(d->eps_ball >= 0.0 && d->eps_ball <= 1.0 && d->eps_wall >= 0.0 &&
          d->eps_wall <= 1.0))
        return RC_ERESTITUTION;
    if (!(d->t_c >= 0.0 && d->sim_tol >= 0.0 && d->sim_tol < 1e-3 && d->approach_tol >= 0.0 &&
          d->approach_tol < 1e-3 && d->overlap_tol >= 0.0 && d->cell_size >= 0.0 &&
          d->density > 0.0))
        return RC_EINVAL;
    if (!rc_group_rule_name(d->groups))
        return RC_EINVAL;
    for (int w = 0; w < 6; w++) { /* (NULL: the hard wall) */
        const rc_wall_rule *r = d->wall_rule[w];
        if (!r || r == &rc_wall_reflecting)
            continue;
        const int axis = w / 2;
        if (!r->collide || axis >= d->dim || (!r->rigid && d->boundary[axis] == RC_SIM_PERIODIC) ||
            (!r->rigid && d->frame && d->frame->per_ball) ||
            (r->temperature && !(isfinite(d->wall_kT[w]) && d->wall_kT[w] > 0.0)))
            return RC_EINVAL;
    }
    if (!d->law || !d->law->collide)
        return RC_EINVAL;
    if (!(d->simd >= RC_SIM_SIMD_AUTO && d->simd <= RC_SIM_SIMD_SCALAR) ||
        !(d->defer >= RC_SIM_DEFER_AUTO && d->defer <= RC_SIM_DEFER_OFF))
        return RC_EINVAL;
    const double L[3] = {d->box.x, d->box.y, d->box.z};
    for (int k = 0; k < d->dim; k++) {
        if (d->boundary[k] != RC_SIM_WALLS && d->boundary[k] != RC_SIM_PERIODIC)
            return RC_EINVAL;
        /* a periodic axis needs four cells (the automatic cells are checked when the
         * balls, and so the largest diameter, are known) */
        if (d->boundary[k] == RC_SIM_PERIODIC && d->cell_size > 0.0 &&
            !(floor(L[k] / d->cell_size) >= 4.0))
            return RC_EINVAL;
    }
    if (d->frame) { /* the engine calls frame->toi directly: validate its settings once */
        const rc_toi_params *t = &d->toi;
        if (!d->frame->toi || !isfinite(t->touch_tol) || !isfinite(t->graze_tol) ||
            !isfinite(t->lambda_tol) || !(t->touch_tol >= 0.0 && t->graze_tol >= 0.0 &&
                                          t->lambda_tol > 0.0 && t->max_iter > 0))
            return RC_EINVAL;
    }
    /* one speed of light: the contact solver's copy is the def's (NAN) or equal to it */
    if (!isnan(d->toi.c) && d->toi.c != d->c)
        return RC_EINVAL;
    double k;
    const int st = rc_inv_c2(d->c, &k);
    return st != RC_OK ? st : check_field(d);
}

/* The widest lanes this CPU has for the neighbour test (AVX-512F with VL for the walk's
 * compress, else AVX2), up to those the def asks for (the paths give the same bits). */
static int choose_simd(rc_sim_simd want)
{
    int best = ENG_SIMD_NONE;
#ifdef ENG_HAVE_AVX2
    if (__builtin_cpu_supports("avx2"))
        best = ENG_SIMD_AVX2;
#endif
#ifdef ENG_HAVE_AVX512
    if (best == ENG_SIMD_AVX2 && __builtin_cpu_supports("avx512f") &&
        __builtin_cpu_supports("avx512vl"))
        best = ENG_SIMD_AVX512;
#endif
    if (want == RC_SIM_SIMD_SCALAR)
        return ENG_SIMD_NONE;
    if (want == RC_SIM_SIMD_AVX2 && best > ENG_SIMD_AVX2)
        return ENG_SIMD_AVX2;
    return best;
}

/* Defer root finds only where the broad phase bounds contact from below (deferrable: contact
 * simultaneous in the table frame; zmf's is not); the bits are the same either way
 * (test_engine_defer). */
static int defer_wanted(rc_sim_defer want) { return want != RC_SIM_DEFER_OFF; }

int rc_sim_create(const rc_sim_def *def, rc_sim **out)
{
    if (!def || !out)
        return RC_EINVAL;
    *out = NULL;
    int st = check_def(def);
    if (st != RC_OK)
        return st;
    rc_sim *s = calloc(1, sizeof *s);
    if (!s)
        return RC_ENOMEM;
    s->slc_due = INFINITY; /* (no delayed slice) */
    s->def = *def;
    if (def->dim == 2)
        s->def.box.z = 0.0;
    rc_inv_c2(def->c, &s->inv_c2);
    s->inv_c = sqrt(s->inv_c2);
    s->L[0] = def->box.x;
    s->L[1] = def->box.y;
    s->L[2] = def->box.z;
    for (int d = 0; d < 3; d++) {
        const int per = d < def->dim && def->boundary[d] == RC_SIM_PERIODIC;
        s->periodic |= per;
        s->inv_L[d] = per ? 1.0 / s->L[d] : 0.0;
        s->walled |= (unsigned)(d < def->dim && !per) << d;
    }
    s->prm = rc_collision_params_default();
    s->prm.c = def->c;
    s->prm.groups = def->groups;
    s->toi = def->toi;
    s->toi.c = def->c;
    s->simd = choose_simd(def->simd);
    /* the frame's declared properties choose the paths (relcol/toi.h) */
    s->narrow = def->frame && (def->frame->contracted || def->frame->pointlike);
    s->table = s->narrow && def->frame->shapes;
    s->shapes = s->table ? def->frame->shapes : NULL;
    s->defer = s->narrow && def->frame->deferrable && defer_wanted(def->defer);
    if (def->defer == RC_SIM_DEFER_ON && !s->defer) {
        free(s);
        return RC_EINVAL;
    }
    s->wall_contracted = def->frame && def->frame->wall_contracted && s->inv_c2 > 0.0;
    s->model = eng_model_for(def->frame, s->narrow, s->inv_c2);
    eng_walls_init(s);
    s->path = eng_path_for(def); /* (once: the loop and the paths it takes) */
    s->fld_axis = def->g_axis < 0 ? def->dim - 1 : def->g_axis;
    if (s->narrow) {
        if (!def->frame->toi || rc_toi_workspace_create(&s->ws) != RC_OK) {
            free(s);
            return def->frame->toi ? RC_ENOMEM : RC_EINVAL;
        }
    }
    *out = s;
    return RC_OK;
}

static void release_balls(rc_sim *s)
{
    free(s->b);
    free(s->a);
    free(s->clk);
    s->clk = NULL;
    free(s->id);
    free(s->slot);
    free(s->cnt);
    s->cnt = NULL;
    free(s->ev_n);
    s->ev_n = NULL;
    eng_perball_free(&s->pb);
    free(s->img);
    s->img = NULL;
    eng_validity_free(s);
    s->b = NULL;
    s->a = NULL;
    s->id = NULL;
    s->slot = NULL;
    eng_queue_free(&s->q);
    eng_cells_free(&s->g);
    s->n = 0;
}

void eng_release_state(rc_sim *s) { release_balls(s); }

void rc_sim_free(rc_sim **sp)
{
    if (!sp || !*sp)
        return;
    rc_sim *s = *sp;
    eng_slice_clear(s);
    release_balls(s);
    free(s->grp_ball);
    free(s->grp_part);
    free(s->grp_con);
    free(s->grp_j);
    rc_toi_workspace_free(&s->ws);
    free(s->cand);
    free(s);
    *sp = NULL;
}

/* ---- setting up ------------------------------------------------------------------ */

int rc_sim_set_time(rc_sim *s, double t)
{
    if (!s || s->n > 0)
        return RC_EINVAL;
    if (!isfinite(t))
        return RC_ENONFINITE;
    s->now = t;
    return RC_OK;
}

/* Does the contact frame see contracted shapes (walls and pairs)? */
static int contracted(const rc_sim *s)
{
    return s->inv_c2 > 0.0 && s->narrow && s->def.frame->contracted;
}

/* Do balls i and k overlap by more than overlap_tol in the frame's geometry? Contraction only
 * brings surfaces closer to the centres, so the sphere test decides otherwise. */
static int overlapping(rc_sim *s, size_t i, size_t k)
{
    const eng_ball *bi = &s->b[i], *bk = &s->b[k];
    double sig = (bi->r + bk->r) * (1.0 - s->def.overlap_tol);
    const rc_vec3 dx = eng_image(s, rc_v3_sub(bk->x, bi->x)); /* (nearest image) */
    if (!(rc_v3_norm2(dx) < sig * sig))
        return 0;
    if (!contracted(s))
        return 1;
    rc_toi_params prm = s->toi;
    if (prm.touch_tol < s->def.overlap_tol)
        prm.touch_tol = s->def.overlap_tol;
    rc_toi_ball A = {bi->x, bi->r, s->a[i].m, s->a[i].p};
    rc_toi_ball B = {s->periodic ? rc_v3_add(bi->x, dx) : bk->x, bk->r, s->a[k].m, s->a[k].p};
    rc_toi_contact out;
    if (s->def.frame->toi(&prm, &A, &B, s->ws, &out) != RC_EOVERLAP)
        return 0;
    /* a separating pair a shape change left overlapping is a state the engine itself makes:
     * accepted; an approaching overlap is not */
    const rc_vec3 dv = rc_v3_sub(bk->v, bi->v);
    return !(rc_v3_dot(dx, dv) > 0.0);
}

static int load_balls(rc_sim *s, size_t n, const rc_sim_ball *in, size_t *bad, int validate);

int rc_sim_set_balls(rc_sim *s, size_t n, const rc_sim_ball *in, size_t *bad)
{
    if (s) {
        eng_slice_clear(s); /* (slices are of the balls replaced: sim.h) */
        s->fld_work[0] = s->fld_work[1] = 0.0; /* (a field's books start afresh) */
    }
    return load_balls(s, n, in, bad, 1);
}

int rc_sim_sync(rc_sim *s)
{
    if (!s)
        return RC_EINVAL;
    /* per_ball frames at finite c: the balls do not carry the hyperplanes, tubes and kinks
     * ahead, and a prediction asked later rounds differently (relcol/sim.h): keep all */
    if (s->model->per_ball)
        return RC_OK;
    size_t n = s->n;
    rc_sim_ball *b = malloc((n ? n : 1) * sizeof *b);
    if (!b)
        return RC_ENOMEM;
    for (size_t i = 0; i < n; i++)
        rc_sim_get_ball(s, i, &b[i]);
    /* the run's accumulated diagnostics survive the re-planning */
    const eng_books kept = s->bk;
    int st = load_balls(s, n, b, NULL, 0);
    free(b);
    if (st != RC_OK)
        return st;
    s->bk = kept;
    return RC_OK;
}

int rc_sim_set_c(rc_sim *s, double c)
{
    if (!s)
        return RC_EINVAL;
    double k;
    int st = rc_inv_c2(c, &k);
    if (st != RC_OK)
        return st;
    eng_slice_clear(s); /* (the kinks ahead are made now: the worldlines change, sim.h) */
    size_t n = s->n;
    rc_sim_ball *b = malloc((n ? n : 1) * sizeof *b);
    if (!b)
        return RC_ENOMEM;
    /* every ball at the engine's time, with the momentum and rest mass it has now: these
     * are what c leaves alone (sim.h) */
    for (size_t i = 0; i < n; i++)
        rc_sim_get_ball(s, i, &b[i]);
    /* per_ball frames: a kink still ahead is made now, with its latest segment's momentum and
     * rest mass (its glued tube is a function of the old c) */
    for (size_t i = 0; s->model->per_ball && i < n; i++)
        if (rc_sim_kink_ahead(s, i) > 0) {
            const eng_aux *a = &s->a[s->slot[i]];
            b[i].p = a->p;
            b[i].m = a->m;
            b[i].collided = 1;
            b[i].tau_last = b[i].tau;
        }
    const eng_books kept = s->bk;
    const rc_sim_def def0 = s->def;
    const double k0 = s->inv_c2, ic0 = s->inv_c;
    const int wc0 = s->wall_contracted;
    s->def.c = c;
    if (!isnan(s->def.toi.c))
        s->def.toi.c = c;
    s->inv_c2 = k;
    s->inv_c = sqrt(k);
    s->prm.c = c;
    s->toi.c = c;
    s->wall_contracted = s->def.frame && s->def.frame->wall_contracted && k > 0.0;
    s->model = eng_model_for(s->def.frame, s->narrow, k);
    /* planned afresh, unchecked: the shapes the new c gives may overlap a neighbour or a
     * wall, which the overlap policy resolves (and counts) as for any shape change */
    st = load_balls(s, n, b, NULL, 0);
    if (st != RC_OK) { /* (out of memory) the old c and its balls, planned afresh */
        s->def = def0;
        s->inv_c2 = k0;
        s->inv_c = ic0;
        s->prm.c = def0.c;
        s->toi.c = def0.c;
        s->wall_contracted = wc0;
        s->model = eng_model_for(s->def.frame, s->narrow, k0);
        if (load_balls(s, n, b, NULL, 0) == RC_OK)
            s->bk = kept;
        free(b);
        return st;
    }
    free(b);
    s->bk = kept;
    return RC_OK;
}

/* Allocate the state of n balls (rmax sizes the cells), replacing any held, the books afresh
 * (rc_sim_set_balls, rc_sim_checkpoint_read); on failure nothing is held. */
int eng_alloc_state(rc_sim *s, size_t n, double rmax)
{
    const int dim = s->def.dim;
    release_balls(s);
    /* a new set of balls starts its bookkeeping afresh */
    memset(&s->bk, 0, sizeof s->bk);
    s->bk.rng.state = s->def.wall_seed;
    s->since_reorder = 0;
    int st = RC_ENOMEM;
    /* each 64-byte record on one cache line, not straddling two (eng_alloc aligns to 64):
     * every neighbour test loads one whole record */
    s->b = eng_alloc(n * sizeof *s->b);
    s->a = eng_alloc(n * sizeof *s->a);
    s->clk = eng_alloc(n * sizeof *s->clk);
    if (!s->b || !s->a || !s->clk)
        goto fail;
    double edge = 2.0 * rmax * (1.0 + CELL_MARGIN + 2.0 * s->def.sim_tol);
    if (s->def.cell_size > edge)
        edge = s->def.cell_size;
    if (!(edge > 0.0))
        edge = 1.0;
    int periodic[3];
    for (int d = 0; d < 3; d++)
        periodic[d] = !(s->walled >> d & 1u) && d < dim;
    if ((st = eng_cells_init(&s->g, dim, s->def.box, edge, n, periodic)) != RC_OK)
        goto fail;
    for (int d = 0; d < dim; d++)
        if (periodic[d] && s->g.n[d] < 4) { /* (sim.h: RC_SIM_PERIODIC) */
            st = RC_EINVAL;
            goto fail;
        }
    if ((st = eng_queue_init(&s->q, n)) != RC_OK)
        goto fail;
    s->n = n;
    /* Balls stored in cell order, so neighbours share cache lines once N outgrows the caches;
     * id[] / slot[] translate to and from the caller's indices. */
    s->cnt = eng_alloc(n * sizeof *s->cnt);
    if (s->cnt)
        memset(s->cnt, 0, n * sizeof *s->cnt);
    s->id = eng_alloc(n * sizeof *s->id);
    s->slot = eng_alloc(n * sizeof *s->slot);
    if (s->narrow && !(s->ev_n = eng_alloc(n * sizeof *s->ev_n))) {
        st = RC_ENOMEM;
        goto fail;
    }
    if (s->narrow && s->def.frame->per_ball && !(s->pb = eng_perball_alloc(n))) {
        st = RC_ENOMEM;
        goto fail;
    }
    if (s->periodic && !(s->img = eng_alloc(3 * n * sizeof *s->img))) {
        st = RC_ENOMEM;
        goto fail;
    }
    if (!s->id || !s->slot || !s->cnt) {
        st = RC_ENOMEM;
        goto fail;
    }
    return RC_OK;
fail:
    release_balls(s);
    return st;
}

static int load_balls(rc_sim *s, size_t n, const rc_sim_ball *in, size_t *bad, int validate)
{
    if (!s || (!in && n))
        return RC_EINVAL;
    if (n > (size_t)INT32_MAX)
        return RC_EINVAL;
    const int dim = s->def.dim;
    double rmax = 0.0;
    for (size_t i = 0; i < n; i++) {
        const rc_sim_ball *b = &in[i];
        if (bad)
            *bad = i;
        if (!rc_v3_isfinite(b->x) || !rc_v3_isfinite(b->p) || !isfinite(b->r) ||
            !isfinite(b->m) || !isfinite(b->tau) || (b->collided && !isfinite(b->tau_last)))
            return RC_ENONFINITE;
        if (!(b->r > 0.0))
            return RC_ERADIUS;
        if (dim == 2 && (b->x.z != 0.0 || b->p.z != 0.0))
            return RC_EDIM;
        /* the shape inside the box along each axis (r, or contracted when walls see it), to
         * within overlap_tol r of round-off */
        double m = b->m > 0.0 ? b->m : s->def.density * b->r * b->r * b->r;
        rc_toi_shape sh = rc_toi_shape_of(b->r, m, b->p, s->inv_c2);
        int wc = contracted(s) && s->def.frame->wall_contracted;
        for (int d = 0; validate && d < dim; d++) {
            if (!(s->walled >> d & 1u)) { /* periodic: the centre in [0, L) */
                const double x = rc_v3_get(b->x, d);
                if (!(x >= 0.0 && x < s->L[d]))
                    return RC_EINVAL;
                continue;
            }
            rc_vec3 e = rc_v3(d == 0, d == 1, d == 2);
            double h = wc ? rc_toi_support(&sh, e) : b->r, tol = s->def.overlap_tol * b->r;
            /* a restart may hold a shape a collision pushed across a wall (the engine resolves
             * it, as for pairs): only the centre must be inside */
            if (s->def.restart && wc)
                h = tol = 0.0;
            double x = rc_v3_get(b->x, d);
            if (!(x >= h - tol && x <= s->L[d] - h + tol))
                return RC_EINVAL; /* the shape crosses a wall */
        }
        if (b->r > rmax)
            rmax = b->r;
    }
    int st = eng_alloc_state(s, n, rmax);
    if (st != RC_OK)
        return st;
    int32_t *cellof = malloc((n ? n : 1) * sizeof *cellof);
    if (!cellof) {
        st = RC_ENOMEM;
        goto fail;
    }
    for (size_t i = 0; i < n; i++)
        cellof[i] = eng_cells_index_of(&s->g, dim, in[i].x);
    /* (cells in Z order: see engine/cells.c) */
    if ((st = eng_cells_number(&s->g, cellof, n, s->slot)) != RC_OK) {
        free(cellof);
        goto fail;
    }
    for (size_t i = 0; i < n; i++)
        s->id[s->slot[i]] = (uint32_t)i;
    for (size_t k = 0; k < n; k++) { /* (cells fill their slots in ball order) */
        const rc_sim_ball *b = &in[s->id[k]];
        eng_ball *e = &s->b[k];
        eng_aux *a = &s->a[k];
        memset(a, 0, sizeof *a);
        a->m = b->m > 0.0 ? b->m : s->def.density * b->r * b->r * b->r;
        a->p = b->p;
        s->clk[k].tau = b->tau;
        s->clk[k].tau_last = b->collided ? b->tau_last : -INFINITY;
        double M = eng_mass_rel(a->m, a->p, s->inv_c2);
        e->x = b->x;
        e->v = rc_v3_scale(1.0 / M, a->p);
        e->t = s->now;
        e->r = b->r;
        for (int d = 0; s->img && d < 3; d++) /* (read on periodic axes only) */
            s->img[3 * k + (size_t)d] = s->walled >> d & 1u || d >= dim ? 0 : b->image[d];
        eng_cells_insert(&s->g, s->a, (int32_t)k, cellof[s->id[k]]);
    }
    free(cellof);
    /* overlap check through the cells: each pair once */
    /* (a restart of contracted shapes may hold the overlaps shape change made; spheres
     * never overlap by more than round-off, restart or not) */
    for (size_t i = 0; validate && !(s->def.restart && contracted(s)) && i < n; i++) {
        int c[3];
        cell_coords(&s->g, s->a[i].cell, c);
        for (int dz = (dim == 3 ? -1 : 0); dz <= (dim == 3 ? 1 : 0); dz++)
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    const int32_t cell = cell_at(&s->g, c, dx, dy, dz); /* (wraps) */
                    if (cell < 0)
                        continue;
                    eng_cell_it it;
                    for (int32_t k = cell_first(&s->g, cell, &it); k >= 0;
                         k = cell_next(&s->g, &it)) {
                        if ((size_t)k <= i)
                            continue;
                        /* touching is allowed (a rack): only overlaps deeper than the
                         * round-off of placed positions, overlap_tol, are rejected */
                        if (overlapping(s, i, (size_t)k)) {
                            if (bad)
                                *bad = s->id[k] > s->id[i] ? s->id[k] : s->id[i];
                            st = RC_EOVERLAP;
                            goto fail;
                        }
                    }
                }
    }
    double *keys = malloc((n ? n : 1) * sizeof *keys);
    if (!keys) {
        st = RC_ENOMEM;
        goto fail;
    }
    for (size_t i = 0; i < n; i++)
        s->path->predict(s, (int32_t)i, 0);
    for (size_t i = 0; i < n; i++)
        keys[i] = key_of(&s->a[i]);
    eng_queue_build(&s->q, keys, s->now);
    free(keys);
    return RC_OK;
fail:
    release_balls(s);
    return st;
}

