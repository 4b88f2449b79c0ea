/* engine/perball/model.h — the per-ball model's functions, shared by its files
 * (engine/perball/) and called by the engine at its named points: where a ball's kink
 * lies, the records that undo a collision, the undo itself, groups at their members' own
 * events, and the read-out's record of lines before kinks ahead. */
#ifndef RELCOL_ENGINE_PERBALL_MODEL_H
#define RELCOL_ENGINE_PERBALL_MODEL_H

#include "../resolve.h"

/// 1 - kappa.v_in of the kink from `in` to `out` (kappa H's normal, v_in the stored velocity), free of cancellation for a ball fast before and after the same way (glue_kv.h).
static inline double eng_kink_den(double ic2, const rc_particle *in, const rc_particle *out,
                                  rc_vec3 kappa, rc_vec3 v_in)
{
    const double kv = rc_v3_dot(kappa, v_in);
    if (!(kv > RC_GLUE_KV_FAST))
        return 1.0 - kv;
    const double M0 = eng_mass_rel(in->m, in->p, ic2), M1 = eng_mass_rel(out->m, out->p, ic2);
    return rc_glue_one_minus_kv(ic2, in, M0, out, M1, M0 / in->m + M1 / out->m, kv);
}

/// The kink's table time through the contact event (tx, dx), and H's normal *kappa (the stored line is the incoming one).
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

/// Would ball b's new kink (te, kappa, from `in` to `out`) have its hyperplane reach some point of the ball before its last one did: the contracted section's support test (papers/shape-change.md).
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


/* ---- kink.c: where a ball's velocity changes on its worldline ---------------------- */

/// Ball b's velocity changes from `in` to `out` through the contact event (tx, dx = X - its centre then on its stored line): its kink placed (at_event: at the event's time through the centre).
void eng_glue_kink(rc_sim *s, int32_t b, const rc_particle *in, const rc_particle *out,
                   double tx, rc_vec3 dx, int at_event);
/// The same with its time te and H's normal kappa already found (eng_kink_time): the one place a kink is placed.
void eng_glue_kink_at(rc_sim *s, int32_t b, const rc_particle *in, const rc_particle *out,
                      double tx, rc_vec3 dx, double te, rc_vec3 kappa, int at_event);
/// Ball i's contact with wall w from its stored state: *tx its time, *dx = X - centre then; 1 if X is a contact of the model (future side of its hyperplane).
int eng_wall_event_point(const rc_sim *s, int32_t i, int w, double *tx, rc_vec3 *dx);

/* ---- records.c: what a collision leaves so that a later conflict can undo it -------- */

/// After a single contact (record: the model's, or policy: the overlap policy's between two balls): each member's undo record, or cleared.
void eng_write_undo(rc_sim *s, size_t nm, int32_t bp, int record, int policy,
                    const rc_particle *P,
                    const rc_vec3 *vold, const eng_clock *cat, const eng_cov *gat,
                    const rc_glue *uat, const double *tx, const rc_vec3 *dX,
                    const int *kinked, int tc);
/// After a group solved at its members' events: records when its contacts form a tree (or one cycle), else cleared.
void eng_write_group(rc_sim *s, size_t nm, size_t nc, const rc_particle *B, const eng_cov *gat,
                     const rc_glue *uat, const double *tau0, const int *kinked, uint32_t ntc,
                     uint32_t npol);

/* ---- undo.c: undoing a ball's last collision for a contact before its kink ---------- */

/// Can ball w's last collision be undone for a contact with ball k, alone or as a chain?
int eng_undoable(const rc_sim *s, int32_t w, int32_t k);
/// Undo w's last collision and solve it with w's contact with k (an order conflict): 1 done, 0 does not apply, or the law's failure.
int eng_rollback(rc_sim *s, int32_t w, int32_t k, double T, double tx);
/// Ball i met wall (code) on the incoming side of its hyperplane: its last collision undone and solved with the wall contact; 1, 0, or the law's failure.
int eng_undo_wall(rc_sim *s, int32_t i, int32_t wall, double T, double tx);
/// A conflict at i's event with bp (tube: the prediction's X before a hyperplane; else an overlap the frame reported): the undos that apply, tried in turn; 1, 0, or the law's failure.
int eng_undo_conflict(rc_sim *s, int32_t i, int32_t bp, double T, int tube);

/* ---- pending.c: the read-out's record of lines before kinks ahead ------------------ */

/// Ball b's snapshot before an event.
eng_pend_snap eng_pend_take(const rc_sim *s, int32_t b);
/// After an event: ball p->b's record of the lines it is still on at now.
void eng_pend_note(rc_sim *s, const eng_pend_snap *p);
/// A ball's record when its kink at te is undone.
void eng_pend_undo(eng_pend *r, double te);
/// Ball i's state at t >= now where its latest kink lies after t: 1 (o and *img set), 2 the line was not recorded, 0 on its stored line.
int eng_pend_read(const rc_sim *s, size_t i, double t, rc_sim_ball *o, const int32_t **img);

/* ---- narrow.c: a pair's contact on the glued tubes -------------------------------- */

/// The model's narrow phase (engine/model.h pair_time): bi and bk's contact from their separation dx at tref, checked against both hyperplanes; its table time (its event in s->sc_tx, sc_dx) or INFINITY.
double eng_glued_pair_time(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                           double tref, double best, int parting, rc_vec3 *n);
#define ENG_BEFORE_A 100 ///< eng_pair_contact: X on the incoming side of a's last hyperplane (above every informational rc_status)
/// The frame's contact of a and b from their stored lines at t0 (not clamped to now): RC_OK with X (*tx, *dx from a's centre) and the normal *n; ENG_BEFORE_A; RC_MISS if not one of the model; or the frame's code.
int eng_pair_contact(rc_sim *s, int32_t a, int32_t b, double t0, double *tx, rc_vec3 *dx,
                     rc_vec3 *n);

/* ---- solve.c, zmf_group.c: groups whose contacts have events of their own ----------- */

#define ENG_EVGROUP_NMAX (2 * ENG_UNDO_NMAX) ///< members of such a group
/// Solve the group formed in grp_ball / grp_con (members on their incoming lines at one table time, each contact with its event), each member kinked at its own event; ps: read-out records to note; tied: simultaneous by formation; npol: the policy's contacts. 1, or the law's failure.
int eng_solve_at_events(rc_sim *s, size_t nm, size_t nc, const eng_pend_snap *ps, size_t nps,
                        int tied, uint32_t npol);
/// At i's event with bp (members 0, 1 at T, contact 0 theirs, X0 its event): the contacts simultaneous with it in the group's ZMF, formed and solved (1, or the law's failure); 0: none, nothing changed.
int eng_zmf_group(rc_sim *s, int32_t i, int32_t bp, double T, double tx0, rc_vec3 dX0);

#endif
