/* engine/undo.c — per_ball frames: undoing a ball's last collision when a third ball meets
 * it before that kink along its tube, and solving the contacts together
 * (papers/shape-change.md, sections 7 and 8). A collision that can be undone is a single
 * contact of the model, or a group an earlier undo solved: undoing a group into a larger
 * one is what lets a fourth ball meet a group of three inside a window. The records are
 * written by engine/records.c (eng_write_undo, eng_write_group). */
#include <math.h>
#include <string.h>

#include "resolve.h"
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
    const eng_undo *u = &s->und[w];
    if (!has_record(u))
        return 0;
    for (size_t m = 0; m < u->nm; m++) {
        const int32_t b = (int32_t)s->slot[u->mem[m]];
        const eng_undo *v = &s->und[b];
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

/* The collisions a chain undo takes back: ball w's last one, and for each member that has
 * collided once since, that member's later collision (found the same way), at most one
 * per ball beyond w's (each ball keeps two records), in the order found; ord: the order
 * of undoing them, a collision only after every later one of its members. */
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

/* A chain: ball w's last collision G0 cannot be undone because members have collided
 * since. Each such member b has collided exactly once since, in a collision of which its
 * record is kept (its previous record is then G0's, or the collision's that led to it);
 * those are undone first, and their members' later collisions before them, the same way.
 * Undone latest first, every ball goes back to its line before the earliest (a ball's
 * two records bound the depth: a member that has collided twice since, or whose later
 * collision left no record, stops it). The set takes at most one wall contact (its share
 * is taken back for one wall), no pair of balls in contact twice (a second contact of one
 * pair is not a contact the model has), and with k no more than ENG_UNDO_NMAX balls. If
 * w and k are already in contact in it (C->again), their meeting again is no new contact:
 * the set's own contacts are solved together, the later collision's impulses with the
 * earlier one's, instead of adding w-k; k may be in it (then undone too, and w's contact with
 * it solved with the rest). deep: the chain starts at w's previous collision instead (its
 * record undp), so that w's last one is the later collision of one of its members, w
 * itself, and is undone first -- for a contact that lies before both of w's kinks. both:
 * k's last collision is in the set from the start too, for a contact on the incoming side
 * of both balls' hyperplanes where either collision has members that collided since (the
 * plain both-undo takes only collisions none of whose balls has). 1 and the set if it
 * applies, else 0. */
static int chain_set(const rc_sim *s, int32_t w, int32_t k, int deep, int both, uchain *C)
{
    const eng_undo *u = deep ? &s->undp[w] : &s->und[w];
    if (!has_record(u))
        return 0;
    C->again = 0;
    C->ng = 1;
    C->key[0] = u;
    if (both) { /* (k's last collision too, unless it is w's) */
        const eng_undo *uk = &s->und[k];
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
            const eng_undo *v = &s->und[b], *r = v; /* r: b's record of collision g */
            int later = -1;
            if (s->cnt[b] != cu->mcnt[m]) {
                r = &s->undp[b];
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

/* Every member back on its incoming line: stored at its kink E (where the collision's
 * moments were taken), with the momentum, hyperplane, glued tube and clock it had
 * before. */
static void lift(rc_sim *s, ugroup *G, int slices)
{
    for (size_t m = 0; m < G->nm; m++) {
        const int32_t b = G->sl[m];
        eng_validity_undone(s, b);
        const eng_undo *u = &s->und[b];
        G->b[m] = s->b[b];
        G->a[m] = s->a[b];
        G->c[m] = s->clk[b];
        G->g[m] = s->cov[b];
        G->u[m] = s->glu[b];
        G->out[m] = (rc_particle){s->a[b].m, s->a[b].p};
        G->te[m] = s->cov[b].t_k;
        eng_advance_ball(s, b, G->te[m]);
        G->xe[m] = s->b[b].x;
        s->a[b].m = u->in.m;
        s->a[b].p = u->in.p;
        s->b[b].v = rc_v3_scale(1.0 / eng_mass_rel(u->in.m, u->in.p, s->inv_c2), u->in.p);
        s->cov[b] = u->cov;
        s->glu[b] = u->glu;
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
        s->cov[b] = G->g[m];
        s->glu[b] = G->u[m];
    }
}

/* The collision's books, taken back: its moments at the kinks it was taken at, in its
 * members' order; heat and momentum with the same operations, negated; its counts. (The
 * members are at their kinks, lift; rec: their records of it.) The per-wall share is the
 * caller's (it needs the group's contact list). */
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

/* Solve the group the caller formed (members grp_ball[0 .. nm), on their incoming lines at
 * one table time; contacts grp_con[0 .. nc), each with its own event t, x) by the group
 * rule -- or, if there is none or it fails, one contact after the other in the order of
 * their events' table times (a choice; counted) -- and change each member's velocity at
 * its own kink: through its contact's event, or the latest along its worldline of its
 * contacts' events (so that all lie on its incoming piece, whose state the impulses act
 * on). Records for a later undo when the contacts form a tree; books, predictions; the
 * read-out's records ps[0 .. nps) noted; npol of the contacts were the overlap policy's
 * (an undone decision's, solved again). 1 (done), or the law's failure. */
int eng_solve_at_events(rc_sim *s, size_t nm, size_t nc, const eng_pend_snap *ps, size_t nps,
                        int tied, uint32_t npol)
{
    rc_particle *P = s->grp_part;
    rc_particle B[2 * ENG_UNDO_NMAX];
    double k0 = 0.0;
    rc_vec3 p0 = rc_v3(0, 0, 0);
    for (size_t m = 0; m < nm; m++) {
        P[m] = (rc_particle){s->a[s->grp_ball[m]].m, s->a[s->grp_ball[m]].p};
        B[m] = P[m];
        k0 += eng_kinetic(&P[m], s->inv_c2);
        p0 = rc_v3_add(p0, P[m].p);
    }
    const uint64_t tc_before = s->bk.events[RC_SIM_EV_TC];
    for (size_t c = 0; c < nc; c++)
        s->grp_con[c].eps = eng_contact_eps(s, &s->grp_con[c]);
    const double *J = NULL;
    /* tied: the group's contacts are simultaneous by how it was formed, so a rule that
     * orders them by their events (sequential) sees them all at the first one's -- their
     * own differ by the events' rounding, which would decide the order -- while the kinks
     * and the records below keep each contact's own */
    double ev_t[2 * ENG_UNDO_NMAX + 1];
    rc_vec3 ev_x[2 * ENG_UNDO_NMAX + 1];
    for (size_t c = 0; c < nc && tied; c++) {
        ev_t[c] = s->grp_con[c].t;
        ev_x[c] = s->grp_con[c].x;
        s->grp_con[c].t = s->grp_con[0].t;
        s->grp_con[c].x = s->grp_con[0].x;
    }
    int st = s->def.law->group ? s->def.law->group(&s->prm, nm, P, nc, s->grp_con, s->grp_j)
                               : RC_EINVAL;
    for (size_t c = 0; c < nc && tied; c++) {
        s->grp_con[c].t = ev_t[c];
        s->grp_con[c].x = ev_x[c];
    }
    if (st == RC_OK) {
        J = s->grp_j;
    } else {
        /* no group solver, or none found: the contacts one after the other, in the order
         * of their events' table times (a choice; counted) */
        if (s->def.law->group)
            s->bk.group_fallbacks++;
        else
            s->bk.group_sequential++;
        for (size_t m = 0; m < nm; m++)
            P[m] = B[m];
        size_t ord[2 * ENG_UNDO_NMAX + 1];
        for (size_t c = 0; c < nc; c++) {
            size_t q = c;
            for (; q > 0 && s->grp_con[ord[q - 1]].t > s->grp_con[c].t; q--)
                ord[q] = ord[q - 1];
            ord[q] = c;
        }
        for (size_t c = 0; c < nc; c++)
            if ((st = eng_resolve_contact(s, P, &s->grp_con[ord[c]])) != RC_OK)
                return st;
    }
    /* each member's kink through its contact's event, or the latest along its worldline
     * of its contacts' events */
    eng_cov gat[2 * ENG_UNDO_NMAX];
    rc_glue uat[2 * ENG_UNDO_NMAX];
    double tau0[2 * ENG_UNDO_NMAX];
    int kinked[2 * ENG_UNDO_NMAX];
    for (size_t m = 0; m < nm; m++) {
        const int32_t b = s->grp_ball[m];
        gat[m] = s->cov[b];
        uat[m] = s->glu[b];
        tau0[m] = s->clk[b].tau_last;
        kinked[m] = 0;
        if (P[m].m == B[m].m && memcmp(&P[m].p, &B[m].p, sizeof P[m].p) == 0)
            continue;
        const eng_ball *bb = &s->b[b];
        double best = -INFINITY, tb = 0.0;
        rc_vec3 db = rc_v3(0, 0, 0), kap;
        for (size_t c = 0; c < nc; c++) {
            const rc_contact *ct = &s->grp_con[c];
            if (ct->a != (int)m && ct->b != (int)m)
                continue;
            const rc_vec3 d = eng_image(s, rc_v3_sub(ct->x, rc_v3_axpy(bb->x, ct->t - bb->t, bb->v)));
            const double te = eng_kink_time(s, b, &B[m], &P[m], ct->t, d, &kap);
            if (te > best) {
                best = te;
                tb = ct->t;
                db = d;
            }
        }
        const uint64_t oc = s->bk.order_conflicts;
        eng_glue_kink(s, b, &B[m], &P[m], tb, db, 0);
        kinked[m] = s->bk.order_conflicts == oc && s->glu[b].r > 0.0;
    }
    for (size_t m = 0; m < nm; m++) {
        const int32_t b = s->grp_ball[m];
        s->a[b].m = P[m].m;
        s->a[b].p = P[m].p;
        s->b[b].v = rc_v3_scale(1.0 / eng_mass_rel(P[m].m, P[m].p, s->inv_c2), P[m].p);
        s->cnt[b]++;
    }
    eng_moments_add(s, nm, s->grp_ball, B, P);
    eng_write_group(s, nm, nc, B, gat, uat, tau0, kinked,
                (uint32_t)(s->bk.events[RC_SIM_EV_TC] - tc_before), npol);
    for (size_t m = 0; m < nm; m++)
        eng_predict(s, s->grp_ball[m], 0);
    eng_finish(s, nm, nc, k0, p0, RC_SIM_EV_MULTI, 1, J);
    for (size_t q = 0; q < nps; q++)
        eng_pend_note(s, &ps[q]);
    return 1;
}

/* The members' records once their collisions are undone. A ball with one collision
 * undone gets back the record of the one before it (X, its previous record), which the
 * group solved next shifts back again: without this, X's record was cleared with the
 * undone one's and lost. X's records, in each member of X, count the ball's collisions
 * after X by its counter, which the undone collision advanced and the group solved next
 * advances again (counters only grow: events predicted with a counter must not become
 * valid again); so X's counter for the ball goes up by one, and after the group the ball
 * reads as having collided once since X, as it has. A ball with two collisions undone (a
 * chain's) has no record of the one before them; its records are cleared. */
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
            const eng_undo *x = &s->undp[b];
            if (times != 1 || !has_record(x))
                continue;
            once[no++] = b;
            /* X's records in its members (one slot each), found before any is changed */
            for (size_t q = 0; q < x->nm; q++) {
                const int32_t xb = (int32_t)s->slot[x->mem[q]];
                eng_undo *r[2] = {&s->und[xb], &s->undp[xb]};
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
                s->und[b] = s->undp[b];
                s->undp[b].partner = ENG_NONE;
                s->undp[b].nm = 0;
            } else {
                s->und[b].partner = ENG_NONE;
                s->und[b].nm = 0;
            }
        }
}

/* Ball w met ball k before its last kink along its tube (a tube conflict at the
 * prediction's X, table time tx; an overlap the frame reported: tx = inf). If w's last
 * collision can be undone (eng_undoable) -- and with both, k's too -- it is undone (its
 * books too) and the contacts of the undone collisions, as they were, and w's with k, as
 * the frame finds it from the incoming lines, are solved together by the group rule (the
 * scenario's, relcol/sim.h), each ball's velocity changed at its own kink: through its
 * contact's event, or the latest of its contacts' events along its worldline (so that
 * all lie on its incoming piece, whose state the impulses act on). The group's members
 * get records of their own when its contacts form a tree, so a later conflict can undo
 * it into a larger group, up to ENG_UNDO_NMAX members (a choice: it bounds the work; a
 * conflict beyond goes to the overlap policy). k < 0: a wall (its code, ENG_WALL), which
 * w's shape met on the incoming side of its hyperplane: w's last collision is undone
 * (not a chain) and solved with w's contact with that wall from its incoming line, the
 * wall's event of the model there (eng_wall_event_point). deep (not with both or a wall):
 * w's previous collision and its last one undone together (chain_set from the previous),
 * and w's contact with k asked from its line before both (papers/shape-change.md section
 * 8). 1 when done; 0 when it does not apply (nothing changed); the law's failure
 * (negative). */
static int rollback(rc_sim *s, int32_t w, int32_t k, double T, double tx, int both, int deep)
{
    ugroup G[UNDO_NG];
    size_t ng = 1;
    const int wall = k < 0;
    if ((wall && both) || (deep && (wall || both)))
        return 0;
    /* a chain (chain_set): the collisions C.ord undone in that order, each member's record
     * of its collision rec[g][m] -- a ball whose later collision is undone first has its
     * previous record (undp) put in place then, its last one kept in keep[] */
    uchain C;
    int chain = 0;
    const eng_undo *rec[UNDO_NG][ENG_UNDO_NMAX];
    eng_undo keep[ENG_UNDO_NMAX];
    int32_t kb[ENG_UNDO_NMAX];
    size_t nk = 0;
    int plain = !deep && (G[0].nm = undo_members(s, w, G[0].sl)) > 0;
    if (plain && both &&
        (!(G[1].nm = undo_members(s, k, G[1].sl)) || in_list(G[1].sl, G[1].nm, w)))
        plain = 0;
    if (!plain) {
        if (wall || !chain_set(s, w, k, deep, both, &C))
            return 0;
        chain = 1;
        ng = C.ng;
        for (size_t g = 0; g < ng; g++) {
            G[g].nm = C.nm[g];
            for (size_t m = 0; m < G[g].nm; m++) {
                const int32_t b = C.sl[g][m];
                G[g].sl[m] = b;
                if (C.later[g][m] >= 0 && !in_list(kb, nk, b)) {
                    keep[nk] = s->und[b];
                    kb[nk++] = b;
                }
            }
        }
    }
    /* k a member of w's group too (inner): the group's kinks, each through its own event,
     * can leave two members that were not in contact overlapping nearby; undone, the
     * frame is asked for their contact from both incoming lines and the group solved with
     * it -- unless the two were already in contact in it (a second contact of one pair is
     * not a contact the model has) */
    const int inner = !wall && !chain && in_list(G[0].sl, G[0].nm, k);
    if (inner && (both || s->und[w].partner == (int32_t)s->id[k] ||
                  s->und[k].partner == (int32_t)s->id[w]))
        return 0;
    if (both && !chain)
        ng = 2;
    if (!chain && G[0].nm + (both ? G[1].nm : !inner && !wall) > ENG_UNDO_NMAX)
        return 0;
    const int k_in = chain ? in_list(C.ball, C.nb, k) : both || inner;
    size_t ord[UNDO_NG];
    for (size_t i = 0; i < ng; i++) {
        ord[i] = chain ? C.ord[i] : i;
        for (size_t m = 0; m < G[i].nm; m++) {
            const int32_t b = G[i].sl[m];
            size_t j = 0;
            while (chain && j < nk && kb[j] != b)
                j++;
            rec[i][m] = chain && C.later[i][m] >= 0 ? &s->undp[b]
                        : chain && j < nk           ? &keep[j]
                                                    : &s->und[b];
        }
    }
    if (chain) {
        /* latest first: each ball's previous record in place once its later collision is
         * undone. (The delayed slices only once the frame has found the contact: the
         * flush that restores them where it does not would leave a ball's between its
         * two kinks on its first line) */
        for (size_t i = 0; i < ng; i++) {
            const size_t g = ord[i];
            for (size_t m = 0; m < G[g].nm; m++)
                if (C.later[g][m] >= 0)
                    s->und[G[g].sl[m]] = s->undp[G[g].sl[m]];
            lift(s, &G[g], 0);
        }
    } else {
        for (size_t g = 0; g < ng; g++)
            lift(s, &G[g], 1);
    }
    /* the frame is asked from a pair's light-crossing time before the conflict's X and the
     * undone kinks of w and (undone too) k: from t_first itself the pair's ZMF, whose
     * simultaneity tilts by up to that much across the pair, often found the two already
     * overlapping (papers/shape-change.md, section 7) */
    double t_first = tx;
    for (size_t g = 0; g < ng; g++)
        for (size_t m = 0; m < G[g].nm; m++)
            if ((G[g].sl[m] == w || (k_in && G[g].sl[m] == k)) && G[g].te[m] < t_first)
                t_first = G[g].te[m];
    double t2;
    rc_vec3 dX2, n2;
    int found;
    if (wall) {
        /* (the wall's normal, out of the box; the event where w's incoming shape meets it,
         * on the future side of w's hyperplane before the undone collision) */
        const int wi = ENG_WALL_INDEX(k), d = wi / 2;
        n2 = rc_v3(0, 0, 0);
        rc_v3_set(&n2, d, (wi & 1) ? 1.0 : -1.0);
        found = rc_v3_get(s->b[w].v, d) * ((wi & 1) ? 1.0 : -1.0) > 0.0 &&
                eng_wall_event_point(s, w, wi, &t2, &dX2) && t2 > -INFINITY && t2 < INFINITY;
        /* ... and not on the future side of the undone kink's hyperplane, where the
         * incoming piece is not the tube (its first contact would lie on that section,
         * not built for walls) */
        for (size_t m = 0; m < G[0].nm && found; m++)
            if (G[0].sl[m] == w)
                found = !eng_glue_side(&G[0].g[m], &G[0].u[m], s->b[w].v, t2, dX2);
    } else if (chain && C.again) {
        found = 1; /* (no new contact: the collisions' own, solved together) */
        t2 = 0.0;
        dX2 = n2 = rc_v3(0, 0, 0);
    } else {
        const double t0 = t_first - (s->b[w].r + s->b[k].r) * s->inv_c;
        const int pst = eng_pair_contact(s, w, k, t0, &t2, &dX2, &n2);
        found = pst == RC_OK;
        if (pst == ENG_BEFORE_A)
            s->undo_before = w;
    }
    if (!found) {
        for (size_t i = ng; i-- > 0;)
            put_back(s, &G[ord[i]]);
        for (size_t j = 0; j < nk; j++)
            s->und[kb[j]] = keep[j];
        if (s->slc_nd) /* (slices lift moved: back on the members' lines) */
            eng_slice_flush(s);
        return 0;
    }
    s->bk.rollbacks++;
    s->bk.chain_rollbacks += chain;
    s->bk.wide_chains += chain && !C.two;
    s->bk.deep_rollbacks += deep;
    s->bk.rejoins += chain && C.again;
    s->bk.both_chains += chain && both;
    /* (a group with a cycle: as many ball contacts as members) */
    for (size_t g = 0; g < ng; g++) {
        size_t nb = 0;
        for (size_t m = 0; m < G[g].nm; m++)
            nb += rec[g][m]->partner >= 0;
        s->bk.cycle_rollbacks += G[g].nm >= 3 && nb == G[g].nm;
    }
    /* the undone collisions' policy decisions: solved again with the rest, still counted
     * once (rc_sim_diag.overlaps keeps them) */
    uint32_t npol = 0;
    for (size_t g = 0; g < ng; g++)
        npol += rec[g][0]->npol;
    s->bk.policy_rollbacks += npol > 0;
    s->bk.wall_rollbacks += wall;
    /* (each member stored at its earliest undone kink, on the line before it: a slice at
     * or after that kink is on that line) */
    for (size_t j = 0; chain && s->slc_n && j < C.nb; j++)
        eng_slice_undo(s, C.ball[j]);
    /* the contacts of the undone collisions (member slot, partner slot or wall, normal,
     * event), read from their records before these are cleared; their books, latest
     * first (each collision's moments at its own kinks) */
    typedef struct { int32_t a, b; rc_vec3 n; double t; rc_vec3 x; } ucon;
    ucon con[2 * ENG_UNDO_NMAX];
    size_t ncon = 0, wall_g = 0;
    int32_t wall_root = -1, wall_code = 0;
    rc_vec3 wall_n = rc_v3(0, 0, 0);
    for (size_t i = 0; i < ng; i++) {
        const size_t g = ord[i];
        for (size_t m = 0; m < G[g].nm; m++) {
            const eng_undo *u = rec[g][m];
            if (u->partner == ENG_ROOT)
                continue;
            con[ncon] = (ucon){G[g].sl[m], u->partner >= 0 ? (int32_t)s->slot[u->partner] : u->partner,
                               u->n, G[g].te[m] + u->dt, rc_v3_add(G[g].xe[m], u->dx)};
            if (u->partner < 0) {
                wall_root = G[g].sl[m];
                wall_code = u->partner;
                wall_n = u->n;
                wall_g = g;
            }
            ncon++;
        }
        if (chain) {
            /* (a ball undone twice is at its earlier kink: at this one for these books) */
            rc_vec3 x0[ENG_UNDO_NMAX];
            for (size_t m = 0; m < G[g].nm; m++) {
                x0[m] = s->b[G[g].sl[m]].x;
                s->b[G[g].sl[m]].x = G[g].xe[m];
            }
            unbook(s, &G[g], rec[g]);
            for (size_t m = 0; m < G[g].nm; m++)
                s->b[G[g].sl[m]].x = x0[m];
        } else {
            unbook(s, &G[g], rec[g]);
        }
    }
    /* the read-out's records of the undone members (eng_pend) back to before the undone
     * kinks, latest first, then noted for the group's kinks like any event's balls */
    eng_pend_snap ps[ENG_UNDO_NMAX + 1];
    size_t nps = 0;
    if (s->pend) {
        for (size_t i = 0; i < ng; i++)
            for (size_t m = 0; m < G[ord[i]].nm; m++)
                eng_pend_undo(&s->pend[G[ord[i]].sl[m]], G[ord[i]].te[m]);
        if (chain) {
            for (size_t j = 0; j < C.nb; j++)
                ps[nps++] = eng_pend_take(s, C.ball[j]);
        } else {
            for (size_t g = 0; g < ng; g++)
                for (size_t m = 0; m < G[g].nm; m++)
                    ps[nps++] = eng_pend_take(s, G[g].sl[m]);
        }
        if (!k_in && !wall)
            ps[nps++] = eng_pend_take(s, k);
    }
    /* the group at T (the undone members on their incoming lines) */
    size_t nm = 0, nc = 0;
    for (size_t g = 0; g < ng; g++)
        for (size_t m = 0; m < G[g].nm; m++)
            if (eng_member_of(s, &nm, G[g].sl[m], T) < 0)
                return RC_ENOMEM;
    if (!k_in && !wall && eng_member_of(s, &nm, k, T) < 0)
        return RC_ENOMEM;
    if (wall_root >= 0) { /* (the wall's share taken back: p1 - p0, the original's negated) */
        const ugroup *Gw = &G[wall_g];
        rc_vec3 p0 = rc_v3(0, 0, 0), p1 = rc_v3(0, 0, 0);
        for (size_t m = 0; m < Gw->nm; m++) {
            p0 = rc_v3_add(p0, rec[wall_g][m]->in.p);
            p1 = rc_v3_add(p1, Gw->out[m].p);
        }
        const int mw = eng_member_of(s, &nm, wall_root, T);
        if (mw < 0 || eng_add_contact(s, &nc, mw, wall_code, wall_n) != RC_OK)
            return RC_ENOMEM;
        eng_account_walls(s, 1, p1, p0, NULL);
        nc = 0;
    }
    /* the contacts: the undone ones, then w's with k (events in the first ball's
     * coordinates) */
    const int mw = eng_member_of(s, &nm, w, T), mk = wall ? k : eng_member_of(s, &nm, k, T);
    if (mw < 0 || (!wall && mk < 0))
        return RC_ENOMEM;
    for (size_t c = 0; c < ncon; c++) {
        const int a = eng_member_of(s, &nm, con[c].a, T);
        const int b = con[c].b >= 0 ? eng_member_of(s, &nm, con[c].b, T) : con[c].b;
        if (a < 0 || (con[c].b >= 0 && b < 0) || eng_add_contact(s, &nc, a, b, con[c].n) != RC_OK)
            return RC_ENOMEM;
        s->grp_con[nc - 1].t = con[c].t;
        s->grp_con[nc - 1].x = con[c].x;
    }
    if (!(chain && C.again)) {
        const eng_ball *bw = &s->b[w];
        if (eng_add_contact(s, &nc, mw, mk, n2) != RC_OK)
            return RC_ENOMEM;
        s->grp_con[nc - 1].t = t2;
        s->grp_con[nc - 1].x = rc_v3_add(rc_v3_axpy(bw->x, t2 - bw->t, bw->v), dX2);
    }
    /* (only now: the wall's share above reads the undone records) */
    keep_previous(s, G, ng);
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

/* Which collisions a conflict at ball i's event with partner bp can undo: a tube
 * conflict's X (the prediction's) on the incoming side of one ball's hyperplane names
 * that ball's last collision, then both balls' if the frame finds no contact from that
 * ball's incoming line alone; on the incoming side of both, both. An overlap the frame
 * reported (no X) tries the ball with the later kink, then the other, then both. Last,
 * where an attempt found the contact from a ball's incoming line before its previous kink
 * too, that ball's two last collisions (deep; in the 3-D gas at packing 0.1, rms 0.5c, a
 * quarter of the conflicts left to the policy were such). 1 done, 0 none applies, or the
 * law's failure. */
int eng_undo_conflict(rc_sim *s, int32_t i, int32_t bp, double T, int tube)
{
    int st;
    s->undo_before = -1;
    if (tube) {
        const double tx = s->cov[i].ev_tx;
        const rc_vec3 dXi = s->cov[i].ev_dx;
        const eng_ball *bi = &s->b[i], *bq = &s->b[bp];
        const rc_vec3 sep = eng_image(s, rc_v3_sub(rc_v3_axpy(bq->x, tx - bq->t, bq->v),
                                                   rc_v3_axpy(bi->x, tx - bi->t, bi->v)));
        const int in_i = !eng_glue_side(&s->cov[i], &s->glu[i], s->b[i].v, tx, dXi),
                  in_q = !eng_glue_side(&s->cov[bp], &s->glu[bp], s->b[bp].v, tx,
                                        rc_v3_sub(dXi, sep));
        if (!in_i && !in_q)
            return 0;
        if (in_i && in_q)
            return rollback(s, i, bp, T, tx, 1, 0);
        const int32_t w = in_i ? i : bp, k = in_i ? bp : i;
        if ((st = rollback(s, w, k, T, tx, 0, 0)) != 0 ||
            (st = rollback(s, w, k, T, tx, 1, 0)) != 0)
            return st;
        return s->undo_before == w ? rollback(s, w, k, T, tx, 0, 1) : 0;
    }
    const int later = s->cov[bp].t_k > s->cov[i].t_k;
    const int32_t w0 = later ? bp : i, w1 = later ? i : bp;
    if ((st = rollback(s, w0, w1, T, INFINITY, 0, 0)) != 0 ||
        (st = rollback(s, w1, w0, T, INFINITY, 0, 0)) != 0 ||
        (st = rollback(s, w0, w1, T, INFINITY, 1, 0)) != 0)
        return st;
    const int32_t wd = s->undo_before;
    return wd == w0 ? rollback(s, w0, w1, T, INFINITY, 0, 1)
         : wd == w1 ? rollback(s, w1, w0, T, INFINITY, 0, 1)
                    : 0;
}
