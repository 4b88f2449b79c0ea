/* contacts/solve.c — the group solver's entry points: input checked, then the rule
 * prm->groups run (the drop rule in the given frame, the others in the group's
 * zero-momentum frame, the sequential one with the law's pair kernel). */
#include "relcol/contacts.h"
#include "relcol/status.h"
#include "private.h"

int rc_contacts_resolve(double inv_c2, size_t nballs, rc_particle *balls, size_t k,
                        const rc_contact *contacts, double *jout)
{
    const int st = ctc_check_input(inv_c2, nballs, balls, k, contacts);
    return st != RC_OK ? st : ctc_joint(0, inv_c2, nballs, balls, k, contacts, jout);
}

int rc_contacts_solve_law(const rc_law *law, const rc_collision_params *prm, size_t nballs,
                          rc_particle *balls, size_t k, const rc_contact *contacts,
                          double *jout)
{
    double inv_c2;
    if (!law || !law->collide || !prm || rc_inv_c2(prm->c, &inv_c2) != RC_OK ||
        !rc_group_rule_name(prm->groups))
        return RC_EINVAL;
    const int st = ctc_check_input(inv_c2, nballs, balls, k, contacts);
    if (st != RC_OK)
        return st;
    if (prm->groups == RC_GROUPS_DROP)
        return ctc_joint(0, inv_c2, nballs, balls, k, contacts, jout);
    const ctc_rule r = {prm->groups == RC_GROUPS_SEQUENTIAL ? ctc_sequential : ctc_simultaneous,
                        law, prm, inv_c2};
    return ctc_in_group_zmf(&r, nballs, balls, k, contacts, jout);
}
