/* test_wall_knudsen — the free-molecular (Knudsen) steady state between two thermal walls
 * (issue 39 item 5): balls too small to meet each other (r = 1e-6 in a box of edge 10:
 * mean free path ~ 1e11) between the wall x = 0 at kT_h and x = L at kT_c, the y and z walls
 * hard. Each ball flies from wall to wall, so the gas is two half-range Jüttner
 * populations: those moving +x as the hot wall emits them, f_+ = a_h e^(-E/kT_h) on p_x > 0,
 * those moving -x as the cold wall does, f_- = a_c e^(-E/kT_c) on p_x < 0, uniform in x, with
 * no net flux of balls, a_h Phi(kT_h) = a_c Phi(kT_c), and n = a_h H(kT_h) + a_c H(kT_c):
 *   H(T) = 2 pi int p^2 e^(-K/T) dp                  (half-range density per unit a)
 *   Phi(T) = pi int p^3 / M e^(-K/T) dp             (half-range flux of balls, v_x = p_x / M)
 *   G(T) = pi int p^3 / M K e^(-K/T) dp            (half-range flux of kinetic energy)
 * (M = sqrt(m^2 + p^2/c^2), K = p^2 / (M + m): the rest energy's flux is m c^2 times the net
 * flux of balls, 0), computed here by GSL quadrature, independently of the engine. The
 * energy flux T^0x = a_h G(kT_h) - a_c G(kT_c) is the heat per unit time and area that the
 * hot wall gives and the cold wall takes. Measured: n_+ and n_- (the balls moving +x and
 * -x), T^0x from snapshots (sum of K v_x / V), and each wall's heat rate from its counter
 * (rc_sim_diag.wall_heat_by_wall), each with a batch-means error (16 blocks), against the
 * solution within 4 errors; classically and at c = 1 (theta_h = 2, theta_c = 0.2). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_integration.h>

#include "rc_test.h"
#include "relcol/relcol.h"

enum { NBALL = 400, NBLOCK = 16, PER_BLOCK = 25 };

typedef struct { double T, c; int what; } kpar; /* what: 0 H, 1 Phi, 2 G */

static double integrand(double p, void *vp)
{
    const kpar *q = vp;
    const double M = isinf(q->c) ? 1.0 : sqrt(1.0 + p * p / (q->c * q->c)); /* m = 1 */
    const double K = p * p / (M + 1.0), e = exp(-K / q->T);
    return q->what == 0 ? 2.0 * M_PI * p * p * e
         : q->what == 1 ? M_PI * p * p * p / M * e
                        : M_PI * p * p * p / M * K * e;
}

static double half(double T, double c, int what)
{
    kpar q = {T, c, what};
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    gsl_function f = {integrand, &q};
    double r, e;
    gsl_integration_qagiu(&f, 0.0, 0.0, 1e-12, 1000, ws, &r, &e);
    gsl_integration_workspace_free(ws);
    return r;
}

typedef struct { double mean, err; } stat;

static stat batch(const double *x, int nb)
{
    double s = 0.0, s2 = 0.0;
    for (int b = 0; b < nb; b++) {
        s += x[b];
        s2 += x[b] * x[b];
    }
    const double m = s / nb;
    return (stat){m, sqrt(fmax(s2 / nb - m * m, 0.0) / (nb - 1))};
}

static void check(const char *what, stat m, double want)
{
    printf("  %-8s %.6g +- %.2g (%.2f %%) vs %.6g: %+.1f errors\n", what, m.mean, m.err,
           100.0 * m.err / fabs(want), want, (m.mean - want) / m.err);
    ENSURE_MSG(m.err < 0.05 * fabs(want), "%s: error %g too large to tell", what, m.err);
    ENSURE_MSG(fabs(m.mean - want) < 4.0 * m.err, "%s: %g +- %g vs %g", what, m.mean, m.err, want);
}

static void knudsen(double c, double Th, double Tc, uint64_t seed)
{
    const double L = 10.0, V = L * L * L, A = L * L;
    /* the solution */
    const double Hh = half(Th, c, 0), Hc = half(Tc, c, 0), Ph = half(Th, c, 1), Pc = half(Tc, c, 1);
    const double Gh = half(Th, c, 2), Gc = half(Tc, c, 2), n = NBALL / V;
    const double ah = n / (Hh + Hc * Ph / Pc), ac = ah * Ph / Pc;
    const double n_plus = ah * Hh, n_minus = ac * Hc, q = ah * Gh - ac * Gc;
    printf("c %g, kT_h %g, kT_c %g: n_+ %.6g, n_- %.6g, T^0x %.6g\n", c, Th, Tc, n_plus, n_minus, q);
    rc_sim_def d = rc_sim_def_default();
    d.c = c;
    d.box = rc_v3(L, L, L);
    d.cell_size = 2.0;
    d.wall_rule[0] = d.wall_rule[1] = &rc_wall_thermal;
    d.wall_kT[0] = Th;
    d.wall_kT[1] = Tc;
    d.wall_seed = seed;
    /* the start: uniform in the box, isotropic at speed 0.5 (no memory of the walls) */
    rc_rng r = {seed + 100};
    rc_sim_ball *b = calloc(NBALL, sizeof *b);
    for (size_t i = 0; i < NBALL; i++) {
        b[i].r = 1e-6;
        b[i].m = 1.0;
        b[i].x = rc_v3(L * (0.01 + 0.98 * rc_rng_uniform(&r)), L * (0.01 + 0.98 * rc_rng_uniform(&r)),
                       L * (0.01 + 0.98 * rc_rng_uniform(&r)));
        const double mu = 2.0 * rc_rng_uniform(&r) - 1.0, ph = 2.0 * M_PI * rc_rng_uniform(&r);
        const double s = sqrt(1.0 - mu * mu), v = 0.5, pm = v / sqrt(1.0 - (isinf(c) ? 0.0 : v * v / (c * c)));
        b[i].p = rc_v3(pm * mu, pm * s * cos(ph), pm * s * sin(ph));
    }
    rc_sim *sim = NULL;
    ENSURE(rc_sim_create(&d, &sim) == RC_OK && rc_sim_set_balls(sim, NBALL, b, NULL) == RC_OK);
    if (!sim) {
        free(b);
        return;
    }
    /* a slow hot-wall ball crosses in L / v ~ 10 / 0.7: warm-up 300 crossings, snapshots 2 apart */
    const double dt = 15.0;
    double t = 4500.0;
    ENSURE(rc_sim_advance(sim, t, 0) == RC_OK);
    rc_sim_diag d0, d1;
    rc_sim_diagnostics(sim, &d0);
    double np[NBLOCK], nm[NBLOCK], qs[NBLOCK], hh[NBLOCK], hc[NBLOCK];
    for (int k = 0; k < NBLOCK; k++) {
        np[k] = nm[k] = qs[k] = 0.0;
        for (int j = 0; j < PER_BLOCK; j++) {
            t += dt;
            ENSURE(rc_sim_advance(sim, t, 0) == RC_OK);
            ENSURE(rc_sim_get_balls(sim, NBALL, b, 0, NULL) == RC_OK);
            for (size_t i = 0; i < NBALL; i++) {
                const double p2 = rc_v3_norm2(b[i].p);
                const double M = isinf(c) ? 1.0 : sqrt(1.0 + p2 / (c * c));
                const double K = p2 / (M + 1.0);
                (b[i].p.x > 0.0 ? np : nm)[k] += 1.0 / (V * PER_BLOCK);
                qs[k] += K * b[i].p.x / M / (V * PER_BLOCK);
            }
        }
        rc_sim_diagnostics(sim, &d1);
        const double span = dt * PER_BLOCK * A;
        hh[k] = -(d1.wall_heat_by_wall[0] - d0.wall_heat_by_wall[0]) / span; /* given to the gas */
        hc[k] = (d1.wall_heat_by_wall[1] - d0.wall_heat_by_wall[1]) / span;  /* taken from it */
        d0 = d1;
    }
    ENSURE_MSG(d1.events[RC_SIM_EV_BALL] == 0 && d1.events[RC_SIM_EV_MULTI] == 0,
               "balls met: %llu", (unsigned long long)d1.events[RC_SIM_EV_BALL]);
    check("n_+", batch(np, NBLOCK), n_plus);
    check("n_-", batch(nm, NBLOCK), n_minus);
    check("T^0x", batch(qs, NBLOCK), q);
    check("q_hot", batch(hh, NBLOCK), q);
    check("q_cold", batch(hc, NBLOCK), q);
    rc_sim_free(&sim);
    free(b);
}

int main(void)
{
    knudsen(INFINITY, 2.0, 0.5, 1);
    knudsen(1.0, 2.0, 0.2, 2);
    RC_TEST_MAIN_END();
}
