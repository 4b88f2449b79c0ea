/* engine/perball/solve.c — a group whose contacts have events of their own, solved by the
 * group rule with each member kinked at its own event: where an undo and a ZMF-formed group
 * both end (papers/shape-change.md). */
#include <math.h>
#include <string.h>

#include "../group.h"
#include "model.h"
#include "relcol/status.h"

/* Solve the formed group (members on their incoming lines at one table time, each contact with
 * its event) by the group rule, or one contact after another by event time if it has none or
 * fails (counted), each member kinked at the latest of its contacts' events so all lie on its
 * incoming piece; records, books, predictions. 1, or the law's failure. */
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
    /* tied: simultaneous by formation, so the sequential rule sees every contact at the first
     * one's event (their own differ by rounding, which would decide the order); kinks and
     * records keep each contact's own */
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
        gat[m] = s->pb->cov[b];
        uat[m] = s->pb->glu[b];
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
        kinked[m] = s->bk.order_conflicts == oc && s->pb->glu[b].r > 0.0;
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
