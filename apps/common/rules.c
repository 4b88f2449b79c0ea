/* rules.c — the warning that a run's collisions were decided by the engine's rules rather
 * than by its contact model. Contracted frames resolve a contact the model cannot place
 * (an overlap, a contact with the incoming piece of a glued tube) along the centre line:
 * the overlap policy; and the covariant frame puts a kink that would come before, or cross
 * inside the ball, the ball's previous one by the order rule (collisions less than a glue
 * window apart, where the glued tube is not defined). Both are choices. How much a result
 * leans on them is measured, not guessed: at packing 0.05 the covariant gas's
 * finite-density split moved by up to a factor two between three such rules with 1.5 %
 * of its collisions policy decisions (papers/finite-density.md, section 5.1). So a run
 * says so on stderr when either share passes 0.1 %, the share the covariant frame keeps
 * where its own crossing kinks are rare (papers/model-regime.md, section 4; a choice for a
 * warning, not a bound). */
#include "app.h"

int app_rules_warn(FILE *f, const char *prog, const rc_sim_diag *d, const rc_sim_diag *d0)
{
    const uint64_t coll = d->collisions - (d0 ? d0->collisions : 0);
    const uint64_t pol = d->overlaps - (d0 ? d0->overlaps : 0);
    const uint64_t ord = d->order_conflicts - (d0 ? d0->order_conflicts : 0);
    if (coll == 0)
        return 0;
    const double sp = (double)pol / (double)coll, so = (double)ord / (double)coll;
    if (!(sp > APP_RULES_SHARE) && !(so > APP_RULES_SHARE))
        return 0;
    fprintf(f, "%s: warning: of %llu collisions, %.3g %% were decided by the overlap policy "
               "(along the centre line, not by the contact model)", prog,
            (unsigned long long)coll, 100.0 * sp);
    if (ord > 0)
        fprintf(f, " and %.3g kinks per 100 collisions by the order rule (a kink before or "
                   "crossing the ball's previous one: collisions less than a glue window "
                   "apart, where the glued tube is not defined)", 100.0 * so);
    fprintf(f, ": above %g %%, results that depend on the collisions depend on these rules "
               "(papers/model-regime.md, section 4)\n", 100.0 * APP_RULES_SHARE);
    return 1;
}
