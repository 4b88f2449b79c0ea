/* test_soft_stepper.c — a soft-sphere stepper written outside the library, against only
 * relcol/soft.h's public rc_soft_sys functions: classical RK4 with the contact switches
 * flipped at step ends. rc_soft_collide must accept it and run it to the end, and its
 * outcome must agree with the library's CVODE stepper to its own (first-order switching)
 * accuracy. */
#include <math.h>
#include <stdlib.h>

#include "rc_test.h"
#include "relcol/relcol.h"

/* Steps per rc_soft_max_step: within a contact that cap is 1/(2 omega), so a step is
 * 1/(2 omega STEP_DIV) and a switch flipped at a step's end is late by at most that:
 * an outcome error of order 1/(2 STEP_DIV) = 1e-3 of the momentum. */
#define STEP_DIV 500.0

static long calls;

static void axpy(size_t n, double *out, const double *y, double h, const double *k)
{
    for (size_t i = 0; i < n; i++)
        out[i] = y[i] + h * k[i];
}

static int rk4_integrate(rc_soft_sys *s)
{
    calls++;
    rc_soft_sys_info in;
    rc_soft_sys_get_info(s, &in);
    double *y = rc_soft_sys_state(s);
    const size_t ny = in.ny, np = in.npair;
    double *w = malloc((5 * ny + np) * sizeof *w);
    if (!w)
        return RC_ENOMEM;
    double *k1 = w, *k2 = w + ny, *k3 = w + 2 * ny, *k4 = w + 3 * ny, *yt = w + 4 * ny;
    double *g = w + 5 * ny;
    double t = 0.0;
    int st = RC_OK;
    rc_soft_observe(s, y);
    while (!rc_soft_done(s, y) && t < in.t_max) {
        if (!rc_soft_sys_budget_left(s)) {
            st = RC_ENOCONVERGE;
            break;
        }
        rc_soft_sys_count_step(s);
        double h = rc_soft_max_step(s, y) / STEP_DIV;
        if (!(h < in.t_max - t))
            h = in.t_max - t;
        rc_soft_rhs(s, y, k1);
        axpy(ny, yt, y, 0.5 * h, k1);
        rc_soft_rhs(s, yt, k2);
        axpy(ny, yt, y, 0.5 * h, k2);
        rc_soft_rhs(s, yt, k3);
        axpy(ny, yt, y, h, k3);
        rc_soft_rhs(s, yt, k4);
        for (size_t i = 0; i < ny; i++)
            y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        t += h;
        rc_soft_overlap(s, y, g);
        for (size_t q = 0; q < np; q++) {
            const int on = rc_soft_sys_contact(s, q);
            if (!on && g[q] > 0.0 && rc_soft_approaching(s, q, y))
                rc_soft_switch(s, q, 1, y);
            else if (on && g[q] < 0.0)
                rc_soft_switch(s, q, 0, y);
        }
        rc_soft_shape_overlaps(s, y);
        rc_soft_observe(s, y);
    }
    rc_soft_sys_finish(s, t);
    free(w);
    return st;
}

static const rc_soft_stepper rk4 = {"test-rk4", "RK4, switches at step ends", rk4_integrate};

/* An oblique two-ball collision at c (INFINITY classical), eps 0.8, kappa 1e4: the outside
 * stepper against cvode-bdf. */
static void test_outside_stepper(void)
{
    const double cs[2] = {INFINITY, 3.0};
    for (int ci = 0; ci < 2; ci++) {
        rc_soft_params prm = rc_soft_params_default();
        prm.c = cs[ci];
        prm.eps = 0.8;
        prm.stiffness = 1e4;
        rc_particle b[2][2];
        rc_vec3 x[2][2];
        const double r[2] = {1.0, 1.0};
        rc_soft_result res[2];
        int st[2];
        for (int k = 0; k < 2; k++) {
            b[k][0] = (rc_particle){1.0, rc_v3(1.0, 0.0, 0.0)};
            b[k][1] = (rc_particle){2.0, rc_v3(-0.5, 0.0, 0.0)};
            x[k][0] = rc_v3(-2.0, 0.6, 0.0);
            x[k][1] = rc_v3(1.0, 0.0, 0.0);
        }
        calls = 0;
        st[0] = rc_soft_collide(&rk4, &prm, 2, b[0], x[0], r, NULL, &res[0]);
        st[1] = rc_soft_collide(&rc_soft_cvode_bdf, &prm, 2, b[1], x[1], r, NULL, &res[1]);
        ENSURE_MSG(st[0] == RC_OK && st[1] == RC_OK, "rk4 %s, cvode %s", rc_strerror(st[0]),
                   rc_strerror(st[1]));
        ENSURE(calls == 1);
        ENSURE(res[0].finished && res[0].n_contacts == 1 && res[0].n_steps > 1000);
        /* momentum is a linear invariant of every RK stage: round-off only */
        ENSURE(res[0].momentum_error < 1e-12);
        /* STEP_DIV's switching error (1e-3 of |p|; 3x margin) */
        for (int i = 0; i < 2; i++) {
            ENSURE_CLOSE(rc_v3_norm(rc_v3_sub(b[0][i].p, b[1][i].p)), 0.0, 3e-3, 1.0);
            ENSURE_CLOSE(b[0][i].m, b[1][i].m, 3e-3, b[1][i].m);
        }
        printf("  c = %g: rk4 %ld steps, p0 (%.6f, %.6f), cvode (%.6f, %.6f)\n", cs[ci],
               res[0].n_steps, b[0][0].p.x, b[0][0].p.y, b[1][0].p.x, b[1][0].p.y);
    }
}

int main(void)
{
    RUN_TEST(test_outside_stepper);
    RC_TEST_MAIN_END();
}
