/* engine/perball/records.c — per_ball frames: the records a collision leaves so a later
 * conflict can undo it (eng_undo), written by the single-contact path and the undo's groups
 * (papers/shape-change.md sections 7, 8). */
#include <string.h>

#include "model.h"

/* A ball's record about to be written: the one it holds becomes its previous one (a chain
 * undo's, chain_set). */
static inline void undo_shift(rc_sim *s, int32_t b)
{
    if (s->pb->und[b].partner != ENG_NONE) {
        s->pb->undp[b] = s->pb->und[b];
    } else {
        s->pb->undp[b].partner = ENG_NONE;
        s->pb->undp[b].nm = 0;
    }
}

/* Ball b's record for the collision being written (its previous one shifted back): its state,
 * hyperplane, tube and clock before, the members and their counters after; NULL, cleared, if
 * ok == 0. */
static eng_undo *undo_open(rc_sim *s, int32_t b, int ok, size_t nm, const rc_particle *in,
                           const eng_cov *cov, const rc_glue *glu, double tau_last)
{
    eng_undo *u = &s->pb->und[b];
    undo_shift(s, b);
    if (!ok) {
        u->partner = ENG_NONE;
        u->nm = 0;
        return NULL;
    }
    u->in = *in;
    u->cov = *cov;
    u->glu = *glu;
    u->tau_last = tau_last;
    u->nm = (uint32_t)nm;
    for (size_t q = 0; q < nm; q++) {
        u->mem[q] = (int32_t)s->id[s->grp_ball[q]];
        u->mcnt[q] = s->cnt[s->grp_ball[q]];
    }
    return u;
}

/* After a single contact (the model's, or the policy's between two balls: dX its centre-line
 * event), each cleanly kinked member gets the record that undoes it; any other collision
 * leaves them stale or cleared. */
void eng_write_undo(rc_sim *s, size_t nm, int32_t bp, int record, int policy,
                    const rc_particle *P,
                    const rc_vec3 *vold, const eng_clock *cat, const eng_cov *gat,
                    const rc_glue *uat, const double *tx, const rc_vec3 *dX,
                    const int *kinked, int tc)
{
    const rc_vec3 n0 = s->grp_con[0].n;
    int ok = record;
    for (size_t j = 0; j < nm; j++)
        ok = ok && kinked[j];
    for (size_t j = 0; j < nm; j++) {
        const int32_t b = s->grp_ball[j];
        eng_undo *u = undo_open(s, b, ok, nm, &P[j], &gat[j], &uat[j], cat[j].tau_last);
        if (!u)
            continue;
        const double te = s->pb->cov[b].t_k; /* (its kink E: X - E, the same on both lines) */
        u->n = j == 0 ? n0 : rc_v3_scale(-1.0, n0);
        u->dt = tx[j] - te;
        u->dx = rc_v3_axpy(dX[j], tx[j] - te, vold[j]);
        u->partner = j == 0 ? (nm > 1 ? ENG_ROOT : bp) : (int32_t)s->id[s->grp_ball[0]];
        u->kind = nm > 1 ? RC_SIM_EV_BALL : RC_SIM_EV_WALL;
        u->ntc = tc ? 1u : 0u;
        u->npol = policy ? 1u : 0u;
    }
}

/* A group's records when its contacts form a tree over its members (at most one wall contact,
 * at the root) or, without a wall, one cycle, every member kinked cleanly; else all cleared. */
void eng_write_group(rc_sim *s, size_t nm, size_t nc, const rc_particle *B, const eng_cov *gat,
                     const rc_glue *uat, const double *tau0, const int *kinked, uint32_t ntc,
                     uint32_t npol)
{
    int ok = nm <= ENG_UNDO_NMAX;
    size_t walls = 0, root = 0;
    for (size_t c = 0; c < nc && ok; c++)
        if (s->grp_con[c].b < 0) {
            walls++;
            root = (size_t)s->grp_con[c].a;
        }
    /* a tree of contacts, or -- no wall -- one cycle: a tree and one contact more, which
     * the root's record holds (its partner that contact's other ball) */
    const int cycle = walls == 0 && nc == nm && nm >= 3;
    ok = ok && walls <= 1 && (nc - walls == nm - 1 || cycle);
    for (size_t m = 0; m < nm && ok; m++)
        ok = kinked[m];
    /* each member's parent from the root out, leaving out the cycle's extra contact; a member
     * no contact reaches: no tree */
    int32_t parent[ENG_UNDO_NMAX];
    size_t pc[ENG_UNDO_NMAX], extra = nc, tail = 0;
    for (size_t x = 0; ok && x < (cycle ? nc : 1); x++) {
        size_t order[ENG_UNDO_NMAX], head = 0;
        if (cycle) {
            extra = x;
            root = (size_t)s->grp_con[x].a;
        }
        tail = 0;
        for (size_t m = 0; m < nm; m++)
            parent[m] = -1;
        parent[root] = (int32_t)root;
        order[tail++] = root;
        while (head < tail) {
            const int a = (int)order[head++];
            for (size_t c = 0; c < nc; c++) {
                const rc_contact *ct = &s->grp_con[c];
                if (c == extra || ct->b < 0 || (ct->a != a && ct->b != a))
                    continue;
                const int o = ct->a == a ? ct->b : ct->a;
                if (parent[o] < 0) {
                    parent[o] = a;
                    pc[o] = c;
                    order[tail++] = (size_t)o;
                }
            }
        }
        if (tail == nm)
            break;
    }
    ok = ok && tail == nm;
    for (size_t m = 0; m < nm; m++) {
        const int32_t b = s->grp_ball[m];
        eng_undo *u = undo_open(s, b, ok, nm, &B[m], &gat[m], &uat[m], tau0[m]);
        if (!u)
            continue;
        const rc_contact *ct = NULL;
        if (m != root) {
            ct = &s->grp_con[pc[m]];
            u->partner = (int32_t)s->id[s->grp_ball[parent[m]]];
        } else if (extra < nc) {
            ct = &s->grp_con[extra];
            u->partner = (int32_t)s->id[s->grp_ball[ct->a == (int)m ? ct->b : ct->a]];
        } else {
            u->partner = ENG_ROOT;
            for (size_t c = 0; c < nc; c++)
                if (s->grp_con[c].b < 0) {
                    ct = &s->grp_con[c];
                    u->partner = ct->b;
                }
        }
        if (ct) {
            /* (the normal from this member to its parent or wall) */
            u->n = ct->a == (int)m ? ct->n : rc_v3_scale(-1.0, ct->n);
            u->dt = ct->t - s->pb->cov[b].t_k;
            u->dx = eng_image(s, rc_v3_sub(ct->x, s->b[b].x));
        } else {
            u->n = rc_v3(0, 0, 0);
            u->dt = 0.0;
            u->dx = rc_v3(0, 0, 0);
        }
        u->kind = RC_SIM_EV_MULTI;
        u->ntc = ntc;
        u->npol = npol;
    }
}
