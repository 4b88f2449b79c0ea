/* engine/resolve.h — what resolving an event shares between engine/core.c (the single
 * contact, groups, the books) and the per_ball frames' files: engine/undo.c (undoing a
 * ball's last collision, papers/shape-change.md section 7) and engine/pending.c (the
 * read-out's record of lines before kinks ahead). Not exported: eng_ prefix. */
#ifndef RELCOL_ENGINE_RESOLVE_H
#define RELCOL_ENGINE_RESOLVE_H

#include "private.h"

/* Move ball i's stored state to time T (position, proper time, clock). */
static inline void eng_advance_ball(rc_sim *s, int32_t i, double T)
{
    eng_ball *b = &s->b[i];
    const eng_aux *a = &s->a[i];
    double h = T - b->t;
    if (h == 0.0)
        return;
    b->x = rc_v3_axpy(b->x, h, b->v);
    if (s->inv_c2 == 0.0)
        s->clk[i].tau += h;
    else
        s->clk[i].tau += h * (a->m / eng_mass_rel(a->m, a->p, s->inv_c2));
    b->t = T;
}


/* 1 - kappa.v_in of the kink from `in` to `out` (H's normal kappa, v_in the stored
 * velocity p / M of `in`): the plain form, or for a ball fast before and after the same
 * way the one free of its cancellation (glue_kv.h) */
static inline double eng_kink_den(double ic2, const rc_particle *in, const rc_particle *out,
                                  rc_vec3 kappa, rc_vec3 v_in)
{
    const double kv = rc_v3_dot(kappa, v_in);
    if (!(kv > RC_GLUE_KV_FAST))
        return 1.0 - kv;
    const double M0 = eng_mass_rel(in->m, in->p, ic2), M1 = eng_mass_rel(out->m, out->p, ic2);
    return rc_glue_one_minus_kv(ic2, in, M0, out, M1, M0 / in->m + M1 / out->m, kv);
}

/* H's normal and the kink's time (glue_kink; the stored line is the incoming one) */
static inline double eng_kink_time(const rc_sim *s, int32_t b, const rc_particle *in,
                                   const rc_particle *out, double tx, rc_vec3 dx, rc_vec3 *kappa)
{
    const double ic2 = s->inv_c2;
    /* kappa = (g0 v0 + g1 v1) / (c^2 (g0 + g1)), g v = p / m, g = M / m (as rc_glue_make) */
    const double W0 = eng_mass_rel(in->m, in->p, ic2) / in->m + eng_mass_rel(out->m, out->p, ic2) / out->m;
    const rc_vec3 Wv = rc_v3_add(rc_v3_scale(1.0 / in->m, in->p), rc_v3_scale(1.0 / out->m, out->p));
    *kappa = rc_v3_scale(ic2 / W0, Wv);
    return tx - rc_v3_dot(*kappa, dx) / eng_kink_den(ic2, in, out, *kappa, s->b[b].v);
}

/* Would ball b's new kink (centre at table time te, H's normal kappa, from `in`, its
 * stored state, to `out`) have its hyperplane reach some point of the ball before its last
 * one did? On the segment between the two kinks (velocity v, the stored one) a point at
 * offset rho from the centre is reached by H_i at t_ci + a_i.rho, a_i = kappa_i / (1 -
 * kappa_i.v); the two sweep the contracted section in order iff t_c2 - t_c1 >= max over it
 * of (a1 - a2).rho, the support of the contracted disc, r sqrt(|g|^2 - (g.beta)^2). (The
 * order rule checks the centre only, rho = 0.) For a ball fast before and after each kink
 * the same way, both denominators are ~1/gamma^2 and the support's two terms gamma^2 times
 * its value: the last kink's denominator then comes from its tube's shapes (s->glu:
 * eng_seg_den), the new one's from the momenta (eng_kink_den), and the support as
 * r sqrt(|g|^2 / gamma^2 + |beta x g|^2), a sum of positive terms. */
static inline int eng_kinks_cross(const rc_sim *s, int32_t b, double te, rc_vec3 kappa,
                                  const rc_particle *in, const rc_particle *out)
{
    const eng_cov *c = &s->pb->cov[b];
    if (!(c->t_k > -INFINITY))
        return 0;
    const rc_vec3 v = s->b[b].v;
    const double d1 = eng_seg_den(c, &s->pb->glu[b], v);
    const double d2 = eng_kink_den(s->inv_c2, in, out, kappa, v);
    const rc_vec3 g = rc_v3_sub(rc_v3_scale(1.0 / d1, c->kappa), rc_v3_scale(1.0 / d2, kappa));
    const rc_vec3 beta = rc_v3_scale(s->inv_c, v);
    double h2;
    /* (1/gamma^2 above 2^-10: the plain form loses ten bits at most) */
    if (!(rc_v3_norm2(beta) > RC_GLUE_KV_FAST)) {
        const double gb = rc_v3_dot(g, beta);
        h2 = rc_v3_norm2(g) - gb * gb;
    } else {
        const double w = in->m / eng_mass_rel(in->m, in->p, s->inv_c2);
        h2 = w * w * rc_v3_norm2(g) + rc_v3_norm2(rc_v3_cross(beta, g));
    }
    return te - c->t_k < s->b[b].r * sqrt(h2 > 0.0 ? h2 : 0.0);
}


static inline void eng_kahan(double *sum, double *comp, double x)
{
    double y = x - *comp;
    double t = *sum + y;
    *comp = (t - *sum) - y;
    *sum = t;
}

static inline double eng_kinetic(const rc_particle *b, double inv_c2)
{
    double M = eng_mass_rel(b->m, b->p, inv_c2);
    return rc_v3_norm2(b->p) / (M + b->m);
}


/* engine/kink.c */
/* per_ball frames: ball b's velocity changes from `in` to `out` through the contact event
 * (tx, dx = X - its centre then on its stored line): its kink, moved to and kept
 * (at_event: a kink at the event's time through the centre, which overtakes a pending one) */
void eng_glue_kink(rc_sim *s, int32_t b, const rc_particle *in, const rc_particle *out,
                   double tx, rc_vec3 dx, int at_event);
/* ... with its time te and H's normal kappa already found (eng_kink_time) */
void eng_glue_kink_at(rc_sim *s, int32_t b, const rc_particle *in, const rc_particle *out,
                      double tx, rc_vec3 dx, double te, rc_vec3 kappa, int at_event);

/* engine/core.c */
/* Group member index of ball k, adding it (advanced to T) if new; -1 on ENOMEM. */
int eng_member_of(rc_sim *s, size_t *nm, int32_t k, double T);
/* Contact a-b (member indices; b < 0 a wall code) with normal n from a to b. */
int eng_add_contact(rc_sim *s, size_t *nc, int a, int b, rc_vec3 n);
/* Restitution of contact c (TC model, jammed walls). */
double eng_contact_eps(rc_sim *s, const rc_contact *c);
/* The law's or the wall law's outcome of contact c among P[]. */
int eng_resolve_contact(rc_sim *s, rc_particle *P, const rc_contact *c);
/* Write back, account heat and wall impulse, predict (single: states and predictions
 * done by the caller, the queue updated). */
void eng_finish(rc_sim *s, size_t nm, size_t nc, double k0, rc_vec3 p0, int kind, int single,
                const double *J);
/* The walls' shares of the momentum p0 - p1 taken in an event (contacts 0 .. nc). */
void eng_account_walls(rc_sim *s, size_t nc, rc_vec3 p0, rc_vec3 p1, const double *J);

/* engine/records.c: the records a single contact (eng_write_undo) and a group solved at
 * its members' events (eng_write_group) leave for a later undo */
void eng_write_undo(rc_sim *s, size_t nm, int32_t bp, int record, int policy,
                    const rc_particle *P,
                    const rc_vec3 *vold, const eng_clock *cat, const eng_cov *gat,
                    const rc_glue *uat, const double *tx, const rc_vec3 *dX,
                    const int *kinked, int tc);
void eng_write_group(rc_sim *s, size_t nm, size_t nc, const rc_particle *B, const eng_cov *gat,
                     const rc_glue *uat, const double *tau0, const int *kinked, uint32_t ntc,
                     uint32_t npol);

/* engine/undo.c */
int eng_undoable(const rc_sim *s, int32_t w, int32_t k);
int eng_rollback(rc_sim *s, int32_t w, int32_t k, double T, double tx);
/* ball i's shape met wall (code) at T on the incoming side of its hyperplane (tx: the
 * outgoing shape's contact time): its last collision undone and solved with the wall
 * contact from its incoming line. 1 done, 0 does not apply, or the law's failure. */
int eng_undo_wall(rc_sim *s, int32_t i, int32_t wall, double T, double tx);
/* per_ball frames: ball i's contact with wall w from its stored state (engine/kink.c):
 * *tx its time, *dx = X - (centre at *tx); 1 if X is on the future side of the ball's
 * last hyperplane (a contact of the model), else 0. */
int eng_wall_event_point(const rc_sim *s, int32_t i, int w, double *tx, rc_vec3 *dx);
int eng_undo_conflict(rc_sim *s, int32_t i, int32_t bp, double T, int tube);

/* engine/pending.c */
/* per_ball frames: what an event's ball was before it, for pend_note */
typedef struct eng_pend_snap {
    int32_t b;
    uint32_t cnt;
    double t_k;
    rc_particle in;
    double tau_last;
} eng_pend_snap;
eng_pend_snap eng_pend_take(const rc_sim *s, int32_t b);
void eng_pend_note(rc_sim *s, const eng_pend_snap *p);
void eng_pend_undo(eng_pend *r, double te);

/* engine/undo.c: a group whose contacts have events of their own (members at one table
 * time on their incoming lines, at most 2 ENG_UNDO_NMAX; contacts at most that + 1, each
 * with its event t, x), solved and each member kinked at its own event; ps: the
 * read-out's records to note after it; tied: the contacts are simultaneous by the group's
 * formation (an ordering rule sees them at one event); npol: of the contacts, the overlap
 * policy's (an undone decision's). 1, or the law's failure. */
#define ENG_EVGROUP_NMAX (2 * ENG_UNDO_NMAX)
int eng_solve_at_events(rc_sim *s, size_t nm, size_t nc, const eng_pend_snap *ps, size_t nps,
                        int tied, uint32_t npol);
/* engine/zmf_group.c: per_ball frames, at ball i's event with ball bp (members 0, 1 at T,
 * contact 0 theirs, X0 its event): the contacts simultaneous with it in the group's ZMF,
 * formed and solved (1, or the law's failure); 0: none, nothing changed. */
int eng_zmf_group(rc_sim *s, int32_t i, int32_t bp, double T, double tx0, rc_vec3 dX0);
/* The wall contacts of members 0 .. nm (at the group's time) by the table's criterion, the
 * wall's rest frame (core.c's grow_group's), each with its event where the ball's shape
 * meets the wall, while fewer than nc_max contacts are held; RC_ENOMEM. */
int eng_group_walls(rc_sim *s, size_t nm, size_t *nc, size_t nc_max);

#endif
