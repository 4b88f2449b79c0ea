/* contacts/sequential.c — the sequential group rule (papers/simultaneous-contacts.md): the
 * contacts of a group one after another, each by the law's pair kernel (the wall law for a
 * wall), in the order of their events' times in the group's zero-momentum frame, the frame
 * in which the soft model's stiff limit resolves them. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "relcol/kinematics.h"
#include "relcol/status.h"
#include "../pair_axis.h"
#include "private.h"

/* Two events tie when their ZMF times differ by no more than this many roundings of the
 * terms that make them: exact simultaneity, up to the round-off of computing it. (Classically
 * every event of one table time ties: simultaneity is absolute there.) */
#define SEQ_TIE_ULPS 16.0
/* A contact approaching by less than this fraction of the group's largest initial approach
 * counts as at rest: as the engine's approach_tol, it ends the ever smaller re-collisions of
 * inelastic chains, whose number would otherwise grow without bound. */
#define SEQ_APPROACH_REL 1e-10
/* Pair collisions allowed per contact before the rule gives up (RC_ENOCONVERGE: a ball
 * wedged between walls it alternately strikes never stops approaching one of them). */
#define SEQ_MAX_PER_CONTACT 64

/* ZMF-normal approach of contact c (wall: p_a.n): > 0 approaching. */
static double approach(double inv_c2, const rc_particle *b, const rc_contact *c)
{
    const double pan = rc_v3_dot(b[c->a].p, c->n);
    if (c->b < 0)
        return pan;
    const double Ma = sqrt(b[c->a].m * b[c->a].m + rc_v3_norm2(b[c->a].p) * inv_c2);
    const double Mb = sqrt(b[c->b].m * b[c->b].m + rc_v3_norm2(b[c->b].p) * inv_c2);
    /* as the zmf law, which resolves the contact: no false "at rest" for a pair moving
     * fast together (pair_axis.h) */
    return rc_pair_a0(&b[c->a], &b[c->b], c->n, inv_c2, Ma, Mb, pan, rc_v3_dot(b[c->b].p, c->n));
}

/* Contacts whose events tie, resolved together by the simultaneous rule in their own
 * group's zero-momentum frame. */
static int tied(const ctc_rule *r, size_t nballs, rc_particle *b, size_t ns,
                const rc_contact *sub, double *jsub)
{
    const int st = ctc_check_input(r->inv_c2, nballs, b, ns, sub);
    if (st != RC_OK)
        return st;
    const ctc_rule sim = {ctc_simultaneous, r->law, r->prm, r->inv_c2};
    return ctc_in_group_zmf(&sim, nballs, b, ns, sub, jsub);
}

int ctc_sequential(const ctc_rule *r, size_t nballs, rc_particle *balls, size_t k,
                   const rc_contact *contacts, double *jout)
{
    if (k == 0)
        return RC_OK;
    const double inv_c2 = r->inv_c2;
    /* The group's zero-momentum velocity: of the balls in its contacts; with a wall, whose
     * mass is infinite, the wall's rest frame. */
    rc_vec3 P;
    double Mt;
    int wall = 0;
    ctc_group_momentum(inv_c2, nballs, balls, k, contacts, &P, &Mt);
    for (size_t j = 0; j < k; j++)
        wall |= contacts[j].b < 0;
    const rc_vec3 u = wall ? rc_v3(0, 0, 0) : rc_v3_scale(1.0 / Mt, P);

    int st = RC_ENOMEM;
    double *key = malloc(k * sizeof *key), *J = malloc(k * sizeof *J);
    double *jsub = malloc(k * sizeof *jsub);
    rc_contact *sub = malloc(k * sizeof *sub);
    size_t *who = malloc(k * sizeof *who);
    /* worked on a copy: a rule that fails leaves the caller's states as they were */
    rc_particle *b = malloc(nballs * sizeof *b);
    if (!key || !J || !jsub || !sub || !who || !b)
        goto done;
    for (size_t i = 0; i < nballs; i++)
        b[i] = balls[i];
    /* ZMF time over gamma, t - u.x/c^2: the same order as the ZMF time itself */
    double tscale = 0.0, amax = 0.0;
    for (size_t j = 0; j < k; j++) {
        const rc_contact *c = &contacts[j];
        const double ux = rc_v3_dot(u, c->x) * inv_c2;
        key[j] = c->t - ux;
        tscale = fmax(tscale, fabs(c->t) + fabs(ux));
        J[j] = 0.0;
        amax = fmax(amax, approach(inv_c2, b, c));
    }
    const double tie = SEQ_TIE_ULPS * DBL_EPSILON * tscale;
    const double at_rest = SEQ_APPROACH_REL * amax;
    rc_collision_params pair = *r->prm;
    st = RC_ENOCONVERGE;
    for (size_t step = 0; step < SEQ_MAX_PER_CONTACT * k; step++) {
        /* the earliest approaching contact, and every approaching one tied with it */
        size_t first = k;
        for (size_t j = 0; j < k; j++)
            if (approach(inv_c2, b, &contacts[j]) > at_rest && (first == k || key[j] < key[first]))
                first = j;
        if (first == k) {
            st = RC_OK;
            break;
        }
        size_t ns = 0;
        for (size_t j = 0; j < k; j++)
            if (fabs(key[j] - key[first]) <= tie && approach(inv_c2, b, &contacts[j]) > at_rest) {
                who[ns] = j;
                sub[ns++] = contacts[j];
            }
        if (ns > 1) {
            const int s2 = tied(r, nballs, b, ns, sub, jsub);
            if (s2 != RC_OK) {
                st = s2;
                goto done;
            }
            for (size_t r = 0; r < ns; r++)
                J[who[r]] += jsub[r];
            continue;
        }
        const rc_contact *c = &contacts[first];
        int s1;
        if (c->b < 0) {
            const double before = rc_v3_dot(b[c->a].p, c->n);
            s1 = rc_collide_wall(inv_c2, c->eps, &b[c->a], c->n);
            J[first] += before - rc_v3_dot(b[c->a].p, c->n);
        } else {
            const double before = rc_v3_dot(b[c->b].p, c->n);
            pair.eps = c->eps;
            s1 = r->law->collide(&pair, &b[c->a], &b[c->b], c->n);
            J[first] += rc_v3_dot(b[c->b].p, c->n) - before;
        }
        if (s1 != RC_OK) { /* (RC_NO_COLLISION: a law that finds not approaching what the
                             * zmf law's approach does; the rule cannot go on) */
            st = s1 == RC_NO_COLLISION ? RC_ENOCONVERGE : s1;
            goto done;
        }
    }
    if (st == RC_OK) {
        for (size_t i = 0; i < nballs; i++)
            balls[i] = b[i];
        if (jout)
            for (size_t j = 0; j < k; j++)
                jout[j] = J[j];
    }
done:
    free(key);
    free(J);
    free(jsub);
    free(sub);
    free(who);
    free(b);
    return st;
}
