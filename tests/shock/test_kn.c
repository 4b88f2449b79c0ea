/* test_kn.c — the dilute tube against the ideal fluid (papers/shock-tube.md, section 6):
 * the plateau's pressure and Eckart velocity at the last time, and the right shock's mean
 * speed since the membrane opened, (x_s - x0)/t with x_s the logistic front's mid-level
 * point (apps/shock/front.h), against the exact Riemann solution (Euler at c = inf, the
 * Synge gas at c = 2). 3-D, 7680 balls, 16 seeds: c = inf to t = 900, c = 2 to t = 1500,
 * Kn 0.020-0.022 at the last time: all three within 3 %. 2-D, 2250 balls, 8 seeds, c = inf
 * to t = 540, c = 2 to 900, Kn 0.020-0.024: within 6 %. Each with its seed errors below
 * half the tolerance. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "app.h"
#include "rc_test.h"
#include "shock_run.h"

static void kn_case(int dim, double c)
{
    sh_opts o;
    memset(&o, 0, sizeof o);
    sh_tube *t = &o.tube;
    t->dim = dim, t->c = c, t->r = 0.5;
    t->T[0] = 2.0, t->T[1] = 1.0;
    /* c = 2's shock is slower: it runs longer, to the same Kn */
    const double tend = (dim == 3 ? 900.0 : 540.0) * (isinf(c) ? 1.0 : 5.0 / 3.0);
    if (dim == 3) {
        t->box.x = 5000.0, t->box.y = t->box.z = 16.0;
        t->n[0] = 0.008, t->n[1] = 0.004;
        o.bins = 160, o.seeds = 16;
    } else {
        t->box.x = 3000.0, t->box.y = 50.0, t->box.z = 0.0;
        t->n[0] = 0.02, t->n[1] = 0.01;
        o.bins = 100, o.seeds = 8;
    }
    /* five times from a third of the last: the local speed beside the mean one */
    o.nt = 5;
    for (int j = 0; j < o.nt; j++)
        o.times[j] = tend * (1.0 + 0.5 * j) / 3.0;
    t->x0 = 0.5 * t->box.x;
    o.seed = 1;
    sh_result r;
    char err[APP_ERR_LEN];
    int rc = sh_run(&o, &r, 0, err);
    ENSURE_MSG(rc == 0, "%s", err);
    if (rc)
        return;
    const double tol = dim == 3 ? 0.03 : 0.06;
    const int j = r.nt - 1;
    const rs_solution *s = &r.sol;
    printf("  %d-D c %g: %zu balls, %d seeds, t %g, Kn %.3g; p %.5g +- %.2g (fluid %.5g), "
           "v %.5g +- %.2g (%.5g), shock %.5g +- %.2g (%.5g; local %.4g +- %.2g)\n",
           dim, c, r.nballs, r.seeds, tend, r.kn, r.plat_p[j], r.plat_p_err[j], s->p_star,
           r.plat_v[j], r.plat_v_err[j], s->v_star, r.vshock, r.vshock_err, s->headR,
           r.vshock_local, r.vshock_local_err);
    ENSURE(r.kn < (dim == 3 ? 0.025 : 0.04));
    ENSURE_REL(r.plat_p[j], s->p_star, tol);
    ENSURE_REL(r.plat_v[j], s->v_star, tol);
    ENSURE_REL(r.vshock, s->headR, tol);
    /* the errors are small enough for the tolerance to mean something */
    ENSURE(r.plat_p_err[j] < tol / 2.0 * s->p_star && r.plat_v_err[j] < tol / 2.0 * s->v_star &&
           r.vshock_err < tol / 2.0 * s->headR);
    /* and the collisions matter: free streaming is rejected (some raw moment's p < 1e-3) */
    ENSURE(fmin(r.pval[j][0], fmin(r.pval[j][1], r.pval[j][2])) < 1e-3);
    sh_result_free(&r);
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    setvbuf(stdout, NULL, _IOLBF, 0); /* each case's line as it ends */
    /* "2d": the 2-D tubes only (quick) */
    const int quick = argc > 1 && strcmp(argv[1], "2d") == 0;
    kn_case(2, INFINITY);
    kn_case(2, 2.0);
    if (!quick) {
        kn_case(3, INFINITY);
        kn_case(3, 2.0);
    }
    RC_TEST_MAIN_END();
}
