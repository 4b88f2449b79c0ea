/* validity.c — the apps' side of the validity report (relcol/validity.h): every run an
 * app makes is noted before its engine is freed, and at the end the app prints one
 * warning line on stderr if any was outside the rigid-ball model's regime (p_model above
 * the threshold in the covariant frame), with the numbers that decided it. Noting is
 * safe from several threads (relcol-sweep's). */
#include <stdatomic.h>
#include <string.h>

#include "app.h"

static atomic_flag lock = ATOMIC_FLAG_INIT;
static size_t runs, outside;
static rc_validity worst; /* the outside run of largest p_model, or the last run noted */

void app_validity_note(const rc_sim *s)
{
    rc_validity v;
    if (s && rc_sim_validity(s, &v) == RC_OK)
        app_validity_note_report(&v);
}

void app_validity_note_report(const rc_validity *vp)
{
    const rc_validity v = *vp;
    while (atomic_flag_test_and_set_explicit(&lock, memory_order_acquire))
        ;
    runs++;
    const int out = v.verdict == RC_VERDICT_OUTSIDE;
    if (out)
        outside++;
    if ((out && !(worst.verdict == RC_VERDICT_OUTSIDE && worst.p_model >= v.p_model)) ||
        (!out && worst.verdict != RC_VERDICT_OUTSIDE))
        worst = v;
    atomic_flag_clear_explicit(&lock, memory_order_release);
}

size_t app_validity_outside(void) { return outside; }

int app_validity_warn(FILE *f, const char *prog)
{
    if (outside == 0)
        return 0;
    const rc_validity *v = &worst;
    fprintf(f, "%s: warning: ", prog);
    if (runs > 1)
        fprintf(f, "%zu of %zu runs ", outside, runs);
    fprintf(f, "outside the rigid-ball model's regime: p_model %.3g > %g (the share of "
               "successive kinks of the model's own that cross inside a ball%s; the largest "
               "kink cluster holds %.3g %% of the collisions, nu r/c %.3g, the overlap policy "
               "decided %.3g %% of %llu collisions): results here depend on the model's rules, "
               "not only on the physics (papers/validity.md)\n",
            v->p_model, v->threshold, runs > 1 ? ", in the run of largest" : "",
            100.0 * v->largest_model, v->nu_r_c, 100.0 * v->policy_share,
            (unsigned long long)v->collisions);
    return 1;
}
