/* engine/perball/undo.c — per_ball frames: undoing a ball's last collision when a third ball
 * meets it before that kink, and solving the contacts together (papers/shape-change.md
 * sections 7, 8); undoing a group into a larger one lets a fourth ball meet three inside a
 * window. */
#include <math.h>
#include <string.h>

#include "../group.h"
#include "model.h"
#include "relcol/status.h"

/* Does u hold a record (of a collision that can be undone, its members within the bound)? */
static int has_record(const eng_undo *u)
{
    return u->partner != ENG_NONE && u->nm > 0 && u->nm <= ENG_UNDO_NMAX;
}

/* The members of ball w's last collision (their slots in sl[], in its books' order) if it
 * can be undone: it left a record and none of them has collided since; else 0. */
static size_t undo_members(const rc_sim *s, int32_t w, int32_t *sl)
{
    const eng_undo *u = &s->pb->und[w];
    if (!has_record(u))
        return 0;
    for (size_t m = 0; m < u->nm; m++) {
        const int32_t b = (int32_t)s->slot[u->mem[m]];
        const eng_undo *v = &s->pb->und[b];
        /* (the same collision: member 0's counter after it names it) */
        if (s->cnt[b] != u->mcnt[m] || v->partner == ENG_NONE || v->nm != u->nm ||
            v->mem[0] != u->mem[0] || v->mcnt[0] != u->mcnt[0])
            return 0;
        sl[m] = b;
    }
    return u->nm;
}

static int in_list(const int32_t *sl, size_t n, int32_t b)
{
    for (size_t m = 0; m < n; m++)
        if (sl[m] == b)
            return 1;
    return 0;
}

/* The collisions a chain undo takes back: w's last, and each member's one later collision
 * since, at most one per ball beyond w's; ord undoes a collision only after every later one of
 * its members. */
#define UNDO_NG (ENG_UNDO_NMAX + 1)
typedef struct uchain {
    size_t ng;
    const eng_undo *key[UNDO_NG]; /* a record of it (member 0 and its counter name it) */
    size_t nm[UNDO_NG];
    int32_t sl[UNDO_NG][ENG_UNDO_NMAX];
    int later[UNDO_NG][ENG_UNDO_NMAX]; /* the member's later collision in the set; -1 */
    size_t nb;                         /* the balls, each once, in the order found */
    int32_t ball[ENG_UNDO_NMAX];
    size_t ord[UNDO_NG];
    int two; /* a chain of two the earlier rule took (one member's later collision, k
                and walls outside it, no other ball shared): counted apart */
    int again; /* w and k already in contact in one of the collisions */
} uchain;

static int same_coll(const eng_undo *a, const eng_undo *b)
{
    return a->partner != ENG_NONE && a->nm == b->nm && a->mem[0] == b->mem[0] &&
           a->mcnt[0] == b->mcnt[0];
}

/* A chain: w's last collision has members that collided once since, in kept collisions undone
 * first, latest first, so every ball returns to its line before the earliest; bounded by
 * ENG_UNDO_NMAX, one wall, no pair twice (C->again: w and k already in contact, solved without
 * a new contact). deep: from w's previous collision; both: k's last one in the set too. 1 and
 * the set, else 0. */
static int chain_set(const rc_sim *s, int32_t w, int32_t k, int deep, int both, uchain *C)
{
    const eng_undo *u = deep ? &s->pb->undp[w] : &s->pb->und[w];
    if (!has_record(u))
        return 0;
    C->again = 0;
    C->ng = 1;
    C->key[0] = u;
    if (both) { /* (k's last collision too, unless it is w's) */
        const eng_undo *uk = &s->pb->und[k];
        if (!has_record(uk))
            return 0;
        if (!same_coll(uk, u))
            C->key[C->ng++] = uk;
    }
    C->nb = 0;
    size_t walls = 0, np = 0, peeled = 0, walls_later = 0;
    int32_t pa[2 * ENG_UNDO_NMAX], pb[2 * ENG_UNDO_NMAX];
    for (size_t g = 0; g < C->ng; g++) {
        const eng_undo *cu = C->key[g];
        C->nm[g] = cu->nm;
        for (size_t m = 0; m < cu->nm; m++) {
            const int32_t b = (int32_t)s->slot[cu->mem[m]];
            const eng_undo *v = &s->pb->und[b], *r = v; /* r: b's record of collision g */
            int later = -1;
            if (s->cnt[b] != cu->mcnt[m]) {
                r = &s->pb->undp[b];
                if (s->cnt[b] != cu->mcnt[m] + 1u || !has_record(v))
                    return 0;
                size_t h = 0;
                while (h < C->ng && !same_coll(C->key[h], v))
                    h++;
                if (h == C->ng) {
                    if (h == UNDO_NG)
                        return 0;
                    C->key[C->ng++] = v;
                }
                later = (int)h;
                peeled++;
            }
            if (!same_coll(r, cu))
                return 0;
            C->sl[g][m] = b;
            C->later[g][m] = later;
            if (!in_list(C->ball, C->nb, b)) {
                if (C->nb == ENG_UNDO_NMAX)
                    return 0;
                C->ball[C->nb++] = b;
            }
            const int32_t q = r->partner;
            if (q < 0 && q != ENG_ROOT) {
                walls++;
                walls_later += g > 0;
            } else if (q >= 0) {
                const int32_t c = (int32_t)s->slot[q];
                if ((b == w && c == k) || (b == k && c == w))
                    C->again = 1;
                for (size_t e = 0; e < np; e++)
                    if ((pa[e] == b && pb[e] == c) || (pa[e] == c && pb[e] == b))
                        return 0;
                pa[np] = b;
                pb[np++] = c;
            }
        }
    }
    const int k_in = in_list(C->ball, C->nb, k);
    if (C->ng < 2 || walls > 1 || C->nb + !k_in > ENG_UNDO_NMAX)
        return 0;
    /* latest first: a collision once every later one of its members is undone (of those
     * ready, the last found) */
    int done[UNDO_NG] = {0};
    for (size_t i = 0; i < C->ng; i++) {
        size_t g = C->ng;
        for (size_t h = C->ng; h-- > 0 && g == C->ng;) {
            int ready = !done[h];
            for (size_t m = 0; m < C->nm[h] && ready; m++)
                ready = C->later[h][m] < 0 || done[C->later[h][m]];
            g = ready ? h : g;
        }
        if (g == C->ng)
            return 0;
        done[g] = 1;
        C->ord[i] = g;
    }
    C->two = C->ng == 2 && peeled == 1 && !k_in && walls_later == 0 &&
             C->nb == C->nm[0] + C->nm[1] - 1;
    return 1;
}

/* Can ball w's last collision be undone for a contact with ball k (not one of its
 * members), alone or after its members' later collisions (a chain). */
int eng_undoable(const rc_sim *s, int32_t w, int32_t k)
{
    int32_t sl[ENG_UNDO_NMAX];
    const size_t n = undo_members(s, w, sl);
    if (n > 0)
        return !in_list(sl, n, k);
    uchain C;
    return chain_set(s, w, k, 0, 0, &C);
}

/* One collision being undone: its members, their states as they were (to put back if the
 * frame finds no contact) and after it, and where each kinked. */
typedef struct ugroup {
    size_t nm;
    int32_t sl[ENG_UNDO_NMAX];
    eng_ball b[ENG_UNDO_NMAX];
    eng_aux a[ENG_UNDO_NMAX];
    eng_clock c[ENG_UNDO_NMAX];
    eng_cov g[ENG_UNDO_NMAX];
    rc_glue u[ENG_UNDO_NMAX];
    rc_particle out[ENG_UNDO_NMAX];
    rc_vec3 xe[ENG_UNDO_NMAX]; /* its kink E's position ... */
    double te[ENG_UNDO_NMAX];  /* ... and time */
} ugroup;

/* Every member back on its incoming line: at its kink E, with the momentum, hyperplane, tube
 * and clock it had before. */
static void lift(rc_sim *s, ugroup *G, int slices)
{
    for (size_t m = 0; m < G->nm; m++) {
        const int32_t b = G->sl[m];
        eng_validity_undone(s, b);
        const eng_undo *u = &s->pb->und[b];
        G->b[m] = s->b[b];
        G->a[m] = s->a[b];
        G->c[m] = s->clk[b];
        G->g[m] = s->pb->cov[b];
        G->u[m] = s->pb->glu[b];
        G->out[m] = (rc_particle){s->a[b].m, s->a[b].p};
        G->te[m] = s->pb->cov[b].t_k;
        eng_advance_ball(s, b, G->te[m]);
        G->xe[m] = s->b[b].x;
        s->a[b].m = u->in.m;
        s->a[b].p = u->in.p;
        s->b[b].v = rc_v3_scale(1.0 / eng_mass_rel(u->in.m, u->in.p, s->inv_c2), u->in.p);
        s->pb->cov[b] = u->cov;
        s->pb->glu[b] = u->glu;
        s->clk[b].tau_last = u->tau_last;
        if (slices && s->slc_n) /* (a delayed slice at or after the undone kink: the
                                   incoming line) */
            eng_slice_undo(s, b);
    }
}

static void put_back(rc_sim *s, const ugroup *G)
{
    for (size_t m = 0; m < G->nm; m++) {
        const int32_t b = G->sl[m];
        s->b[b] = G->b[m];
        s->a[b] = G->a[m];
        s->clk[b] = G->c[m];
        s->pb->cov[b] = G->g[m];
        s->pb->glu[b] = G->u[m];
    }
}

/* The collision's books taken back with the same operations negated, its moments at its kinks;
 * the per-wall share is the caller's. */
static void unbook(rc_sim *s, const ugroup *G, const eng_undo *const *rec)
{
    rc_particle in[ENG_UNDO_NMAX];
    for (size_t m = 0; m < G->nm; m++)
        in[m] = rec[m]->in;
    eng_moments_add(s, G->nm, G->sl, G->out, in);
    double k0 = 0.0, k1 = 0.0;
    rc_vec3 p0 = rc_v3(0, 0, 0), p1 = rc_v3(0, 0, 0);
    for (size_t m = 0; m < G->nm; m++) {
        k0 += eng_kinetic(&in[m], s->inv_c2);
        p0 = rc_v3_add(p0, in[m].p);
        k1 += eng_kinetic(&G->out[m], s->inv_c2);
        p1 = rc_v3_add(p1, G->out[m].p);
    }
    eng_kahan(&s->bk.heat, &s->bk.heat_c, -(k0 - k1));
    eng_kahan(&s->bk.wall[0], &s->bk.wall_c[0], -(p0.x - p1.x));
    eng_kahan(&s->bk.wall[1], &s->bk.wall_c[1], -(p0.y - p1.y));
    eng_kahan(&s->bk.wall[2], &s->bk.wall_c[2], -(p0.z - p1.z));
    const eng_undo *u = rec[0];
    /* its contacts: one a record, but the root's without a wall or a cycle's contact */
    size_t ncon = 0;
    for (size_t m = 0; m < G->nm; m++) {
        const int32_t q = rec[m]->partner;
        ncon += q != ENG_ROOT && q != ENG_NONE;
    }
    s->bk.events[u->kind]--;
    s->bk.collisions -= ncon;
    s->bk.events[RC_SIM_EV_TC] -= u->ntc;
}

/* The members' records once their collisions are undone: one undone collision gives back the
 * record before it, its counter raised by one since counters only grow (so the ball reads as
 * collided once since, as it has); two undone (a chain) clear it. */
static void keep_previous(rc_sim *s, const ugroup *G, size_t ng)
{
    int32_t once[2 * ENG_UNDO_NMAX];
    size_t no = 0;
    eng_undo *bump[4 * ENG_UNDO_NMAX * ENG_UNDO_NMAX];
    size_t bq[4 * ENG_UNDO_NMAX * ENG_UNDO_NMAX], nb = 0;
    for (size_t g = 0; g < ng; g++)
        for (size_t m = 0; m < G[g].nm; m++) {
            const int32_t b = G[g].sl[m];
            size_t times = 0;
            for (size_t h = 0; h < ng; h++)
                times += in_list(G[h].sl, G[h].nm, b);
            const eng_undo *x = &s->pb->undp[b];
            if (times != 1 || !has_record(x))
                continue;
            once[no++] = b;
            /* X's records in its members (one slot each), found before any is changed */
            for (size_t q = 0; q < x->nm; q++) {
                const int32_t xb = (int32_t)s->slot[x->mem[q]];
                eng_undo *r[2] = {&s->pb->und[xb], &s->pb->undp[xb]};
                for (int j = 0; j < 2; j++) {
                    if (!same_coll(r[j], x))
                        continue;
                    for (size_t e = 0; e < r[j]->nm; e++)
                        if (r[j]->mem[e] == (int32_t)s->id[b] && nb < sizeof bq / sizeof *bq) {
                            bump[nb] = r[j];
                            bq[nb++] = e;
                        }
                }
            }
        }
    for (size_t i = 0; i < nb; i++)
        bump[i]->mcnt[bq[i]]++;
    for (size_t g = 0; g < ng; g++)
        for (size_t m = 0; m < G[g].nm; m++) {
            const int32_t b = G[g].sl[m];
            if (in_list(once, no, b)) {
                s->pb->und[b] = s->pb->undp[b];
                s->pb->undp[b].partner = ENG_NONE;
                s->pb->undp[b].nm = 0;
            } else {
                s->pb->und[b].partner = ENG_NONE;
                s->pb->und[b].nm = 0;
            }
        }
}

/* One undo's plan: the collisions it takes back (undone in the order ord), each member's
 * record of its collision (rec; a chain's deeper ones from undp, the last kept in keep[]), and
 * its kind. */
typedef struct uplan {
    ugroup G[UNDO_NG];
    size_t ng;
    size_t ord[UNDO_NG];
    const eng_undo *rec[UNDO_NG][ENG_UNDO_NMAX];
    eng_undo keep[ENG_UNDO_NMAX];
    int32_t kb[ENG_UNDO_NMAX];
    size_t nk;
    uchain C;  /* chain: the chain's collisions (chain_set) */
    int wall;  /* k is a wall (its code) */
    int chain; /* the collisions are a chain */
    int k_in;  /* k is a member of an undone collision */
} uplan;

/* Step 1: which collisions an undo of w's last for its contact with k takes back (plain, both,
 * chain, deep), within the bound of members: 1 and the plan, or 0. */
static int plan_undo(const rc_sim *s, int32_t w, int32_t k, int both, int deep, uplan *U)
{
    ugroup *G = U->G;
    uchain *C = &U->C;
    U->ng = 1;
    U->wall = k < 0;
    U->chain = 0;
    U->nk = 0;
    C->nb = 0;
    const int wall = U->wall;
    if ((wall && both) || (deep && (wall || both)))
        return 0;
    int plain = !deep && (G[0].nm = undo_members(s, w, G[0].sl)) > 0;
    if (plain && both &&
        (!(G[1].nm = undo_members(s, k, G[1].sl)) || in_list(G[1].sl, G[1].nm, w)))
        plain = 0;
    if (!plain) {
        if (wall || !chain_set(s, w, k, deep, both, C))
            return 0;
        U->chain = 1;
        U->ng = C->ng;
        for (size_t g = 0; g < U->ng; g++) {
            G[g].nm = C->nm[g];
            for (size_t m = 0; m < G[g].nm; m++) {
                const int32_t b = C->sl[g][m];
                G[g].sl[m] = b;
                if (C->later[g][m] >= 0 && !in_list(U->kb, U->nk, b)) {
                    U->keep[U->nk] = s->pb->und[b];
                    U->kb[U->nk++] = b;
                }
            }
        }
    }
    /* k a member of w's group too (inner): the group's own kinks can leave two members
     * overlapping, so undone their contact is asked from both incoming lines, unless they were
     * already in contact in it */
    const int inner = !wall && !U->chain && in_list(G[0].sl, G[0].nm, k);
    if (inner && (both || s->pb->und[w].partner == (int32_t)s->id[k] ||
                  s->pb->und[k].partner == (int32_t)s->id[w]))
        return 0;
    if (both && !U->chain)
        U->ng = 2;
    if (!U->chain && G[0].nm + (both ? G[1].nm : !inner && !wall) > ENG_UNDO_NMAX)
        return 0;
    U->k_in = U->chain ? in_list(C->ball, C->nb, k) : both || inner;
    for (size_t i = 0; i < U->ng; i++) {
        U->ord[i] = U->chain ? C->ord[i] : i;
        for (size_t m = 0; m < G[i].nm; m++) {
            const int32_t b = G[i].sl[m];
            size_t j = 0;
            while (U->chain && j < U->nk && U->kb[j] != b)
                j++;
            U->rec[i][m] = U->chain && C->later[i][m] >= 0 ? &s->pb->undp[b]
                           : U->chain && j < U->nk          ? &U->keep[j]
                                                            : &s->pb->und[b];
        }
    }
    return 1;
}

/* Step 2: every undone member back on its incoming line, latest first; the slices follow only
 * once the contact is found, else a flush would leave a ball between its two kinks on its
 * first line. */
static void lift_all(rc_sim *s, uplan *U)
{
    if (U->chain) {
        for (size_t i = 0; i < U->ng; i++) {
            const size_t g = U->ord[i];
            for (size_t m = 0; m < U->G[g].nm; m++)
                if (U->C.later[g][m] >= 0)
                    s->pb->und[U->G[g].sl[m]] = s->pb->undp[U->G[g].sl[m]];
            lift(s, &U->G[g], 0);
        }
    } else {
        for (size_t g = 0; g < U->ng; g++)
            lift(s, &U->G[g], 1);
    }
}

/* Step 2, reversed where step 3 finds no contact: every member as it was. */
static void put_all_back(rc_sim *s, const uplan *U)
{
    for (size_t i = U->ng; i-- > 0;)
        put_back(s, &U->G[U->ord[i]]);
    for (size_t j = 0; j < U->nk; j++)
        s->pb->und[U->kb[j]] = U->keep[j];
    if (s->slc_nd) /* (slices lift moved: back on the members' lines) */
        eng_slice_flush(s);
}

/* Step 3: w's contact with k from the lifted lines (*t2, *dX2, *n2), asked a light-crossing
 * time before the conflict and the undone kinks, since from t_first the ZMF's tilt found them
 * overlapping; a wall's event of the model; none for a chain already in contact. 1 if found. */
static int new_contact(rc_sim *s, const uplan *U, int32_t w, int32_t k, double tx, double *t2,
                       rc_vec3 *dX2, rc_vec3 *n2)
{
    double t_first = tx;
    for (size_t g = 0; g < U->ng; g++)
        for (size_t m = 0; m < U->G[g].nm; m++)
            if ((U->G[g].sl[m] == w || (U->k_in && U->G[g].sl[m] == k)) &&
                U->G[g].te[m] < t_first)
                t_first = U->G[g].te[m];
    if (U->wall) {
        /* (the wall's normal, out of the box; the event where w's incoming shape meets it,
         * on the future side of w's hyperplane before the undone collision) */
        const int wi = ENG_WALL_INDEX(k), d = wi / 2;
        *n2 = rc_v3(0, 0, 0);
        rc_v3_set(n2, d, (wi & 1) ? 1.0 : -1.0);
        int found = rc_v3_get(s->b[w].v, d) * ((wi & 1) ? 1.0 : -1.0) > 0.0 &&
                    eng_wall_event_point(s, w, wi, t2, dX2) && *t2 > -INFINITY && *t2 < INFINITY;
        /* ... and not on the future side of the undone kink's hyperplane, where the incoming
         * piece is not the tube */
        for (size_t m = 0; m < U->G[0].nm && found; m++)
            if (U->G[0].sl[m] == w)
                found = !eng_glue_side(&U->G[0].g[m], &U->G[0].u[m], s->b[w].v, *t2, *dX2);
        return found;
    }
    if (U->chain && U->C.again) { /* (no new contact: the collisions' own, solved together) */
        *t2 = 0.0;
        *dX2 = *n2 = rc_v3(0, 0, 0);
        return 1;
    }
    const double t0 = t_first - (s->b[w].r + s->b[k].r) * s->inv_c;
    const int pst = eng_pair_contact(s, w, k, t0, t2, dX2, n2);
    if (pst == ENG_BEFORE_A)
        s->pb->undo_before = w;
    return pst == RC_OK;
}

/* Step 4, where collisions are undone: the undo's counts; returns how many undone contacts
 * were the policy's (they stay counted once). */
static uint32_t count_undone(rc_sim *s, const uplan *U, int both, int deep)
{
    const int chain = U->chain;
    s->bk.rollbacks++;
    s->pb->tally.chain_rollbacks += chain;
    s->pb->tally.wide_chains += chain && !U->C.two;
    s->pb->tally.deep_rollbacks += deep;
    s->pb->tally.rejoins += chain && U->C.again;
    s->pb->tally.both_chains += chain && both;
    /* (a group with a cycle: as many ball contacts as members) */
    for (size_t g = 0; g < U->ng; g++) {
        size_t nb = 0;
        for (size_t m = 0; m < U->G[g].nm; m++)
            nb += U->rec[g][m]->partner >= 0;
        s->pb->tally.cycle_rollbacks += U->G[g].nm >= 3 && nb == U->G[g].nm;
    }
    uint32_t npol = 0;
    for (size_t g = 0; g < U->ng; g++)
        npol += U->rec[g][0]->npol;
    s->pb->tally.policy_rollbacks += npol > 0;
    s->pb->tally.wall_rollbacks += U->wall;
    return npol;
}

/* The contacts of the undone collisions: member slot, partner slot or wall, normal,
 * event; and the one with a wall, if any (its share of the momentum is taken back). */
typedef struct ucon {
    int32_t a, b;
    rc_vec3 n;
    double t;
    rc_vec3 x;
} ucon;
typedef struct ucontacts {
    ucon con[2 * ENG_UNDO_NMAX];
    size_t n;
    size_t wall_g;     /* the collision with the wall contact ... */
    int32_t wall_root; /* ... its member (-1: none) ... */
    int32_t wall_code; /* ... the wall's code and the contact's normal */
    rc_vec3 wall_n;
} ucontacts;

/* Step 5: the undone contacts, read before their records are cleared, and their books taken
 * back, latest first. */
static void take_back(rc_sim *s, uplan *U, ucontacts *K)
{
    K->n = 0;
    K->wall_g = 0;
    K->wall_root = -1;
    K->wall_code = 0;
    K->wall_n = rc_v3(0, 0, 0);
    for (size_t i = 0; i < U->ng; i++) {
        const size_t g = U->ord[i];
        ugroup *G = &U->G[g];
        for (size_t m = 0; m < G->nm; m++) {
            const eng_undo *u = U->rec[g][m];
            if (u->partner == ENG_ROOT)
                continue;
            K->con[K->n] = (ucon){G->sl[m], u->partner >= 0 ? (int32_t)s->slot[u->partner] : u->partner,
                                  u->n, G->te[m] + u->dt, rc_v3_add(G->xe[m], u->dx)};
            if (u->partner < 0) {
                K->wall_root = G->sl[m];
                K->wall_code = u->partner;
                K->wall_n = u->n;
                K->wall_g = g;
            }
            K->n++;
        }
        if (U->chain) {
            /* (a ball undone twice is at its earlier kink: at this one for these books) */
            rc_vec3 x0[ENG_UNDO_NMAX];
            for (size_t m = 0; m < G->nm; m++) {
                x0[m] = s->b[G->sl[m]].x;
                s->b[G->sl[m]].x = G->xe[m];
            }
            unbook(s, G, U->rec[g]);
            for (size_t m = 0; m < G->nm; m++)
                s->b[G->sl[m]].x = x0[m];
        } else {
            unbook(s, G, U->rec[g]);
        }
    }
}

/* Step 6: the undone members' read-out records back to before the undone kinks, then taken to
 * be noted like any event's balls; returns how many, in ps[]. */
static size_t pend_back(rc_sim *s, const uplan *U, int32_t k, eng_pend_snap *ps)
{
    size_t nps = 0;
    if (!s->pb)
        return 0;
    for (size_t i = 0; i < U->ng; i++)
        for (size_t m = 0; m < U->G[U->ord[i]].nm; m++)
            eng_pend_undo(&s->pb->pend[U->G[U->ord[i]].sl[m]], U->G[U->ord[i]].te[m]);
    if (U->chain) {
        for (size_t j = 0; j < U->C.nb; j++)
            ps[nps++] = eng_pend_take(s, U->C.ball[j]);
    } else {
        for (size_t g = 0; g < U->ng; g++)
            for (size_t m = 0; m < U->G[g].nm; m++)
                ps[nps++] = eng_pend_take(s, U->G[g].sl[m]);
    }
    if (!U->k_in && !U->wall)
        ps[nps++] = eng_pend_take(s, k);
    return nps;
}

/* Step 7: the group at T, the wall's share taken back, then the undone contacts and w's with k
 * (step 3's), events in the first ball's coordinates. RC_OK or RC_ENOMEM. */
static int form_group(rc_sim *s, const uplan *U, const ucontacts *K, int32_t w, int32_t k,
                      double T, double t2, rc_vec3 dX2, rc_vec3 n2, size_t *nm_out,
                      size_t *nc_out)
{
    size_t nm = 0, nc = 0;
    for (size_t g = 0; g < U->ng; g++)
        for (size_t m = 0; m < U->G[g].nm; m++)
            if (eng_member_of(s, &nm, U->G[g].sl[m], T) < 0)
                return RC_ENOMEM;
    if (!U->k_in && !U->wall && eng_member_of(s, &nm, k, T) < 0)
        return RC_ENOMEM;
    if (K->wall_root >= 0) { /* (the wall's share taken back: p1 - p0, the original's negated) */
        const ugroup *Gw = &U->G[K->wall_g];
        rc_vec3 p0 = rc_v3(0, 0, 0), p1 = rc_v3(0, 0, 0);
        for (size_t m = 0; m < Gw->nm; m++) {
            p0 = rc_v3_add(p0, U->rec[K->wall_g][m]->in.p);
            p1 = rc_v3_add(p1, Gw->out[m].p);
        }
        const int mw = eng_member_of(s, &nm, K->wall_root, T);
        if (mw < 0 || eng_add_contact(s, &nc, mw, K->wall_code, K->wall_n) != RC_OK)
            return RC_ENOMEM;
        eng_account_walls(s, 1, p1, p0, NULL);
        nc = 0;
    }
    const int mw = eng_member_of(s, &nm, w, T), mk = U->wall ? k : eng_member_of(s, &nm, k, T);
    if (mw < 0 || (!U->wall && mk < 0))
        return RC_ENOMEM;
    for (size_t c = 0; c < K->n; c++) {
        const ucon *u = &K->con[c];
        const int a = eng_member_of(s, &nm, u->a, T);
        const int b = u->b >= 0 ? eng_member_of(s, &nm, u->b, T) : u->b;
        if (a < 0 || (u->b >= 0 && b < 0) || eng_add_contact(s, &nc, a, b, u->n) != RC_OK)
            return RC_ENOMEM;
        s->grp_con[nc - 1].t = u->t;
        s->grp_con[nc - 1].x = u->x;
    }
    if (!(U->chain && U->C.again)) {
        const eng_ball *bw = &s->b[w];
        if (eng_add_contact(s, &nc, mw, mk, n2) != RC_OK)
            return RC_ENOMEM;
        s->grp_con[nc - 1].t = t2;
        s->grp_con[nc - 1].x = rc_v3_add(rc_v3_axpy(bw->x, t2 - bw->t, bw->v), dX2);
    }
    *nm_out = nm;
    *nc_out = nc;
    return RC_OK;
}

/* Ball w met k before its last kink (a tube conflict at tx; tx = inf: an overlap the frame
 * reported): w's last collision (both: k's too; deep: w's two last; k < 0 a wall) undone and
 * solved with w's contact with k in the steps above, up to ENG_UNDO_NMAX members (a choice
 * bounding the work). 1 done, 0 does not apply, or the law's failure. */
static int rollback(rc_sim *s, int32_t w, int32_t k, double T, double tx, int both, int deep)
{
    uplan U;
    if (!plan_undo(s, w, k, both, deep, &U))
        return 0;
    lift_all(s, &U);
    double t2;
    rc_vec3 dX2, n2;
    if (!new_contact(s, &U, w, k, tx, &t2, &dX2, &n2)) {
        put_all_back(s, &U);
        return 0;
    }
    const uint32_t npol = count_undone(s, &U, both, deep);
    /* (each member stored at its earliest undone kink, on the line before it: a slice at
     * or after that kink is on that line) */
    for (size_t j = 0; U.chain && s->slc_n && j < U.C.nb; j++)
        eng_slice_undo(s, U.C.ball[j]);
    ucontacts K;
    take_back(s, &U, &K);
    eng_pend_snap ps[ENG_UNDO_NMAX + 1];
    const size_t nps = pend_back(s, &U, k, ps);
    size_t nm, nc;
    if (form_group(s, &U, &K, w, k, T, t2, dX2, n2, &nm, &nc) != RC_OK)
        return RC_ENOMEM;
    /* (only now: the wall's share above reads the undone records) */
    keep_previous(s, U.G, U.ng);
    return eng_solve_at_events(s, nm, nc, ps, nps, 0, npol);
}

int eng_rollback(rc_sim *s, int32_t w, int32_t k, double T, double tx)
{
    return rollback(s, w, k, T, tx, 0, 0);
}

int eng_undo_wall(rc_sim *s, int32_t i, int32_t wall, double T, double tx)
{
    return rollback(s, i, wall, T, tx, 0, 0);
}

/* Which collisions a conflict at i's event with bp can undo: X on one ball's incoming side
 * names that ball's, then both; on both sides, both; an overlap without X tries the later
 * kink's ball, the other, then both; last, deep. 1, 0, or the law's failure. */
int eng_undo_conflict(rc_sim *s, int32_t i, int32_t bp, double T, int tube)
{
    int st;
    s->pb->undo_before = -1;
    if (tube) {
        const double tx = s->pb->cov[i].ev_tx;
        const rc_vec3 dXi = s->pb->cov[i].ev_dx;
        const eng_ball *bi = &s->b[i], *bq = &s->b[bp];
        const rc_vec3 sep = eng_image(s, rc_v3_sub(rc_v3_axpy(bq->x, tx - bq->t, bq->v),
                                                   rc_v3_axpy(bi->x, tx - bi->t, bi->v)));
        const int in_i = !eng_glue_side(&s->pb->cov[i], &s->pb->glu[i], s->b[i].v, tx, dXi),
                  in_q = !eng_glue_side(&s->pb->cov[bp], &s->pb->glu[bp], s->b[bp].v, tx,
                                        rc_v3_sub(dXi, sep));
        if (!in_i && !in_q)
            return 0;
        if (in_i && in_q)
            return rollback(s, i, bp, T, tx, 1, 0);
        const int32_t w = in_i ? i : bp, k = in_i ? bp : i;
        if ((st = rollback(s, w, k, T, tx, 0, 0)) != 0 ||
            (st = rollback(s, w, k, T, tx, 1, 0)) != 0)
            return st;
        return s->pb->undo_before == w ? rollback(s, w, k, T, tx, 0, 1) : 0;
    }
    const int later = s->pb->cov[bp].t_k > s->pb->cov[i].t_k;
    const int32_t w0 = later ? bp : i, w1 = later ? i : bp;
    if ((st = rollback(s, w0, w1, T, INFINITY, 0, 0)) != 0 ||
        (st = rollback(s, w1, w0, T, INFINITY, 0, 0)) != 0 ||
        (st = rollback(s, w0, w1, T, INFINITY, 1, 0)) != 0)
        return st;
    const int32_t wd = s->pb->undo_before;
    return wd == w0 ? rollback(s, w0, w1, T, INFINITY, 0, 1)
         : wd == w1 ? rollback(s, w1, w0, T, INFINITY, 0, 1)
                    : 0;
}
