/*md
# 6. Soft spheres → hard spheres

A hard collision is an instant. relcol's `zmf` law says what comes out of it: a four-impulse
`J q`, `q = (u·n/c², n)`, that keeps each ball's energy in the pair's zero-momentum frame
(ZMF), scales the ZMF normal momentum by `−ε` and turns the lost kinetic energy into rest
mass. To check that law *from outside*, relcol has a soft-sphere reference
(`relcol/soft.h`, `papers/soft-sphere.md`): the balls overlap by `δ` and push with a linear
spring–dashpot `F = κδ + ηδ̇` through the four-force `∓F q`, integrated in time by an ODE
solver (SUNDIALS CVODE or GSL). The dashpot is matched to `ε`, the overlap's work goes
into internal energy `U = (m − m_rest)c²` (heat and elastic energy are rest mass), and as
the stiffness `κ → ∞` the contact shrinks to an instant.

What this notebook shows:

1. head-on, soft = hard at **every** stiffness (the `ε` matching is exact);
2. oblique, the soft outcome converges to the hard law as `κ^(−1/2)`, at `c = ∞` and
   `c = 1`, for `ε = 1` and `0.7`, with the fitted order checked;
3. during a contact, kinetic + internal energy is constant to the solver's tolerance, and
   the heat is split between the balls as the hard law splits it;
4. CVODE and GSL's Runge–Kutta steppers give the same outcome.

The two-ball scenario and the distance from the hard law come from `tests/soft/soft_cases.h`
(the tests' and the paper's own): rest masses 1 and 2, radii 0.3 and 0.4, velocities given
as fractions of `c` (of 1 when `c = ∞`), placed so that first touch is at table time ~1;
`soft_vs_hard` runs the soft collision and `rc_law_zmf` with the soft run's first-touch
normal, and returns the largest of `|p_soft − p_hard|/Σ|p_in|` and `|m_soft − m_hard|/m_hard`.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "nb.h"
#include "relcol/relcol.h"
#include "soft_cases.h"

/* Solver tolerance of every run: the solver's own error (~1e3 rtol for BDF over a contact,
 * papers/soft-sphere.md section 6) then sits far below the stiffness errors being fitted. */
#define RTOL 1e-11

static rc_soft_params params(double c, double eps, double kappa)
{
    rc_soft_params prm = rc_soft_params_default();
    prm.c = c;
    prm.eps = eps;
    prm.stiffness = kappa;
    prm.rtol = RTOL;
    return prm;
}

/* A velocity given as a fraction of c (of 1 when c = inf). */
static rc_vec3 beta(double c, double bx, double by, double bz)
{
    const double unit = isinf(c) ? 1.0 : c;
    return rc_v3(bx * unit, by * unit, bz * unit);
}

/*md
## Head-on: exact at any stiffness

Head-on (the centre worldlines intersect, so head-on in every frame), velocities
`(0.7, 0.3, −0.2)c` and `(−0.5, 0.1, 0.4)c`. In the pair's ZMF the soft contact is a damped
linear oscillator with constant inertia `μ* = E₀* E₁* / ((E₀* + E₁*) c²)`, whose restitution is
exactly `ε` for the matched damping, so the soft outcome should *be* the hard one, to the
solver's error, even at `κ = 10³`, a contact ten thousand times softer than the stiffest here.
@output headon
*/
static void headon(void)
{
    nb_section("headon");
    const double cs[2] = {INFINITY, 1.0}, epss[2] = {1.0, 0.7}, kappas[3] = {1e3, 1e5, 1e7};
    double worst = 0;
    int ok = 1;
    printf("  c     eps    kappa=1e3   kappa=1e5   kappa=1e7   (distance from the hard law)\n");
    for (int ic = 0; ic < 2; ic++)
        for (int ie = 0; ie < 2; ie++) {
            printf("%4g  %4g ", cs[ic], epss[ie]);
            for (int ik = 0; ik < 3; ik++) {
                rc_soft_params prm = params(cs[ic], epss[ie], kappas[ik]);
                rc_particle p[2];
                rc_vec3 x[2];
                double err = NAN;
                ok = ok && soft_case(rc_inv_c2_of(prm.c), beta(cs[ic], 0.7, 0.3, -0.2), beta(cs[ic], -0.5, 0.1, 0.4), 0.0,
                                     p, x) == 0;
                ok = ok && soft_vs_hard(&rc_soft_cvode_bdf, &prm, p, x, NULL, &err, NULL) == RC_OK;
                printf("  %10.3e", err);
                worst = fmax(worst, err);
            }
            printf("\n");
        }
    /* 3e-8 = 3000 RTOL: BDF's global error over a contact (measured <= 3.1e-9 in
     * test_soft_convergence); a wrong eps matching would be an O(1 - eps) error */
    NB_CHECK(ok && worst < 3e-8, "head-on: soft = hard at every stiffness (worst %.2g)", worst);
}

/*md
## Oblique: convergence as `κ^(−1/2)`

Velocities `(0.6, 0.1, 0)c` and `(−0.3, 0.05, 0.1)c`, impact parameter 0.3. During an
oblique contact the line of centres turns at the rate `w_t/(r₀ + r₁)` (`w_t` the tangential
relative speed), so the effective normal is off the first-touch normal by about half the
turn over the contact time `T = π/ω_d ∝ κ^(−1/2)`: the error should be first order in `T`,
order `−1/2` in `κ`. The fitted slope of `log error` against `log κ` over `κ = 10⁴…10⁸`
checks it, for both `c` and both `ε`.
@output oblique
*/
static void oblique(void)
{
    nb_section("oblique");
    enum { NK = 9 };
    const double cs[2] = {INFINITY, 1.0}, epss[2] = {1.0, 0.7};
    double kap[NK], err[4][NK], order[4];
    FILE *d = nb_figure_begin("soft-convergence");
    int ok = 1;
    for (int ik = 0; ik < NK; ik++)
        kap[ik] = pow(10.0, 4.0 + 0.5 * ik);
    printf("  c     eps   ");
    for (int ik = 0; ik < NK; ik += 2)
        printf("  kappa=%-6.0e", kap[ik]);
    printf("  fitted order\n");
    for (int s = 0; s < 4; s++) {
        double c = cs[s / 2], eps = epss[s % 2];
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (int ik = 0; ik < NK; ik++) {
            rc_soft_params prm = params(c, eps, kap[ik]);
            rc_particle p[2];
            rc_vec3 x[2];
            ok = ok && soft_case(rc_inv_c2_of(prm.c), beta(c, 0.6, 0.1, 0.0), beta(c, -0.3, 0.05, 0.1), 0.3, p, x) == 0;
            err[s][ik] = NAN;
            ok = ok && soft_vs_hard(&rc_soft_cvode_bdf, &prm, p, x, NULL, &err[s][ik], NULL) == RC_OK;
            double lx = log(kap[ik]), ly = log(err[s][ik]);
            sx += lx;
            sy += ly;
            sxx += lx * lx;
            sxy += lx * ly;
        }
        order[s] = (NK * sxy - sx * sy) / (NK * sxx - sx * sx);
        printf("%4g  %4g ", c, eps);
        for (int ik = 0; ik < NK; ik += 2)
            printf("  %12.4e", err[s][ik]);
        printf("  %8.4f\n", order[s]);
    }
    for (int ik = 0; ik < NK && d; ik++)
        fprintf(d, "%.6g %.6e %.6e %.6e %.6e\n", kap[ik], err[0][ik], err[1][ik], err[2][ik], err[3][ik]);
    int orders_ok = 1;
    for (int s = 0; s < 4; s++)
        orders_ok = orders_ok && fabs(order[s] + 0.5) < 0.03;
    /* 0.03: measured within 0.003 of -1/2 (papers/soft-sphere.md); a limit other than the
     * zmf law would level off (order -> 0), a cancelling turn would give order -1 */
    NB_CHECK(ok && orders_ok, "oblique: error ~ kappa^(-1/2) for c = inf and 1, eps = 1 and 0.7");
    NB_CHECK(err[0][NK - 1] < 1e-4 && err[3][NK - 1] < 1e-4, "at kappa = 1e8 within 1e-4 of the hard law");
    nb_figure_end(d, "soft-convergence",
                  "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset grid\n"
                  "set xlabel 'stiffness κ'\nset ylabel 'distance of the soft outcome from the hard zmf law'\n"
                  "set key top right\nset title 'oblique impact: soft spheres converge to the hard law'\n"
                  "plot datafile u 1:2 w lp pt 7 lw 2 t 'c = ∞, ε = 1', '' u 1:3 w lp pt 5 lw 2 t 'c = ∞, ε = 0.7', "
                  "'' u 1:4 w lp pt 6 lw 2 dt 2 t 'c = 1, ε = 1', '' u 1:5 w lp pt 4 lw 2 dt 2 t 'c = 1, ε = 0.7', "
                  "'' u 1:(1.2*$1**-0.5) w l dt 3 lw 1.5 lc rgb 'black' t '∝ κ^{-1/2}'\n");
}

/*md
The `c = 1` rows are within 15% of the `c = ∞` ones (same velocities as fractions of `c`,
`γ` up to 1.26 at `c = 1`): the mechanism, the turning line of centres, is the same, and
relativity only changes its constant. At `κ = 10⁸` every case is within `8·10⁻⁵` of the
hard law.

## Energy bookkeeping during one contact

There is no potential energy in this model: the overlap stands for the balls' deformation,
which is internal energy, so in relativity it is rest mass. The total four-momentum is
conserved at every instant, and in the form that stays finite as `c → ∞`, the sum of
kinetic energies `K = p²/(M + m)` and internal energies `U` is constant. We watch one soft
oblique contact (`c = 1`, `ε = 0.7`, `κ = 100`, soft enough to see the overlap), started
directly in the pair's ZMF (momenta `±(0.5, 0.15, 0)`, masses 1 and 2), by stopping the run
at a sequence of times (`t_max`) and reading the state. Time is in units of the matched
contact time `T = π/ω_d`, from first touch.

In the ZMF the four-force has no time component, so each ball's energy is constant and
whatever kinetic energy it loses becomes **its own** rest mass: both balls gain the same
`d(m²)`, which makes the light ball take more of the heat — the same split as the hard law,
`m'² = m² + (1 − ε²)(p̄·n̄)²/c²` for both.
@output energy
*/
static double kin(const rc_particle *b, double k) { return rc_kinetic_energy(b->m, b->p, k); }

static void energy(void)
{
    nb_section("energy");
    const double k = 1.0, eps = 0.7, kappa = 1e2;
    const double m[2] = {soft_m[0], soft_m[1]};
    rc_particle p0[2] = {{m[0], rc_v3(0.5, 0.15, 0)}, {m[1], rc_v3(-0.5, -0.15, 0)}};
    /* first touch at t1 = 1 with impact parameter 0.35 (r0 + r1 = 0.7) */
    rc_vec3 v0 = rc_velocity(m[0], p0[0].p, k), v1 = rc_velocity(m[1], p0[1].p, k);
    rc_vec3 w = rc_v3_sub(v1, v0), wh = rc_v3_scale(1.0 / rc_v3_norm(w), w);
    rc_vec3 side = rc_v3(-wh.y, wh.x, 0);
    const double R = soft_r[0] + soft_r[1], bimp = 0.35;
    rc_vec3 dtouch = rc_v3_add(rc_v3_scale(sqrt(R * R - bimp * bimp), rc_v3_scale(-1.0, wh)), rc_v3_scale(bimp, side));
    /* ball 0 at the origin and ball 1 at dtouch at t = 1 (approaching: dtouch.w < 0) */
    rc_vec3 x0[2] = {rc_v3_scale(-1.0, v0), rc_v3_sub(dtouch, v1)};
    /* contact time scale: mu* from the ZMF energies (here the table frame is the ZMF) */
    double E0 = rc_mass_rel(m[0], p0[0].p, k), E1 = rc_mass_rel(m[1], p0[1].p, k);
    double mus = E0 * E1 / (E0 + E1), zeta = rc_soft_damping_ratio(eps);
    double T = M_PI / (sqrt(kappa / mus) * sqrt(1 - zeta * zeta));
    double Kin = kin(&p0[0], k) + kin(&p0[1], k);

    FILE *d = nb_figure_begin("soft-energy");
    double worst = 0, dmax = 0;
    int ok = 1;
    rc_particle last[2];
    double ulast[2] = {0, 0};
    for (int j = 0; j <= 90; j++) {
        double tau = -0.15 + 1.5 * j / 90.0; /* (t - t1) / T */
        rc_soft_params prm = params(1.0, eps, kappa);
        prm.rtol = 1e-10;
        prm.t_max = 1.0 + tau * T;
        rc_particle b[2] = {p0[0], p0[1]};
        rc_vec3 x[2] = {x0[0], x0[1]};
        double u[2] = {0, 0};
        rc_soft_result res;
        ok = ok && rc_soft_collide(&rc_soft_cvode_bdf, &prm, 2, b, x, soft_r, u, &res) == RC_OK;
        double K = kin(&b[0], k) + kin(&b[1], k);
        double delta = fmax(0.0, R - rc_v3_norm(rc_v3_sub(x[1], x[0])));
        dmax = fmax(dmax, delta);
        worst = fmax(worst, fabs(K + u[0] + u[1] - Kin) / Kin);
        if (d)
            fprintf(d, "%.6f %.10g %.10g %.10g %.10g %.10g\n", tau, K / Kin, u[0] / Kin, u[1] / Kin,
                    (K + u[0] + u[1]) / Kin, delta / R);
        last[0] = b[0];
        last[1] = b[1];
        ulast[0] = u[0];
        ulast[1] = u[1];
    }
    double dm0 = last[0].m * last[0].m - m[0] * m[0], dm1 = last[1].m * last[1].m - m[1] * m[1];
    printf("contact time T = %.5f, deepest overlap %.4f of r0 + r1\n", T, dmax / R);
    printf("after the contact: K/K_in = %.6f, U0/K_in = %.6f, U1/K_in = %.6f (light ball takes %.1f%%)\n",
           (kin(&last[0], k) + kin(&last[1], k)) / Kin, ulast[0] / Kin, ulast[1] / Kin,
           100 * ulast[0] / (ulast[0] + ulast[1]));
    printf("m0'^2 - m0^2 = %.10f, m1'^2 - m1^2 = %.10f\n", dm0, dm1);
    printf("max over the contact of |K + U - K_in| / K_in = %.3g (rtol 1e-10)\n", worst);
    /* BDF's global error at rtol 1e-10 reaches ~700 rtol over a contact (papers/soft-sphere.md):
     * allow 2000 rtol; a potential energy left out of the books would be O(1) mid-contact */
    NB_CHECK(ok && worst < 2e-7, "kinetic + internal energy constant through the contact");
    NB_CHECK(fabs(dm0 - dm1) < 1e-7 * fabs(dm0), "both balls gain the same m^2: the hard law's heat split");
    NB_CHECK(ulast[0] > ulast[1] && dmax / R > 0.01, "the light ball takes more heat; the overlap is visible");
    nb_figure_end(d, "soft-energy",
                  "set xlabel '(t - t_{touch}) / T'\nset ylabel 'energy / initial kinetic energy'\n"
                  "set y2label 'overlap δ / (r_0 + r_1)'\nset y2tics\nset ytics nomirror\nset grid\n"
                  "set key at graph 0.97, graph 0.87 right top\nset yrange [0:1.1]\n"
                  "set title 'one soft contact in the ZMF: c = 1, ε = 0.7, κ = 100'\n"
                  "plot datafile u 1:2 w l lw 2 t 'kinetic K', '' u 1:3 w l lw 2 t 'internal U_0 (mass 1)', "
                  "'' u 1:4 w l lw 2 t 'internal U_1 (mass 2)', '' u 1:5 w l lw 3 lc rgb 'black' t 'K + U_0 + U_1', "
                  "'' u 1:6 axes x1y2 w l dt 2 lw 2 lc rgb 'gray50' t 'overlap (right axis)'\n");
}

/*md
The kinetic energy dips while the balls are compressed and comes back only in part: the
spring's share returns, the dashpot's stays as rest mass. The internal energy peaks at the
deepest overlap (it holds the elastic energy too) and settles to the heat. Just before the
balls separate, the dashpot pulls (`F = κδ + ηδ̇ < 0` once `δ` is small and shrinking fast):
that short tensile tail takes a little kinetic energy back into heat, and the matching of
`η` to `ε` counts it (`papers/soft-sphere.md`, section 4). The light ball ends up with about
twice the heat of the heavy one (`d(m²)` equal, so `dU ∝ 1/m` roughly).

## The heat against the hard law, and the steppers against each other

The oblique collision of the convergence section (`c = 1`, `ε = 0.7`, `κ = 10⁸`, table
frame), with the three steppers: CVODE's BDF (`cvode-bdf`) and GSL's explicit
Runge–Kutta pairs (`gsl-rk8pd`, `gsl-rkf45`) at `rtol = 10⁻¹⁰`. Each stepper's outcome, its
distance from the hard law, its energy error, and the heat `(m' − m)c²` against the hard
law's.
@output steppers
*/
static void steppers(void)
{
    nb_section("steppers");
    const rc_soft_stepper *st[3] = {&rc_soft_cvode_bdf, &rc_soft_gsl_rk8pd, &rc_soft_gsl_rkf45};
    rc_particle out[3][2];
    double err[3], eerr[3], U[3][2];
    long steps[3], rhs[3];
    int ok = 1;
    rc_particle hard[2];
    rc_soft_params prm = params(1.0, 0.7, 1e8);
    prm.rtol = 1e-10;
    rc_particle p[2];
    rc_vec3 x[2];
    ok = ok && soft_case(rc_inv_c2_of(prm.c), beta(1.0, 0.6, 0.1, 0.0), beta(1.0, -0.3, 0.05, 0.1), 0.3, p, x) == 0;
    for (int i = 0; i < 3; i++) {
        rc_soft_result res;
        memset(&res, 0, sizeof res);
        err[i] = NAN;
        out[i][0] = p[0];
        out[i][1] = p[1];
        int code = soft_vs_hard(st[i], &prm, p, x, out[i], &err[i], &res);
        ok = ok && code == RC_OK;
        eerr[i] = res.energy_error;
        steps[i] = res.n_steps;
        rhs[i] = res.n_rhs;
        if (i == 0) {
            hard[0] = p[0];
            hard[1] = p[1];
            rc_collision_params cp = rc_collision_params_default();
            cp.c = 1.0;
            cp.eps = 0.7;
            code = rc_collide(&rc_law_zmf, &cp, &hard[0], &hard[1], res.normal);
            ok = ok && code == RC_OK;
        }
        for (int b = 0; b < 2; b++)
            U[i][b] = out[i][b].m - p[b].m; /* (m' - m) c^2 at c = 1 */
    }
    double Uh[2] = {hard[0].m - p[0].m, hard[1].m - p[1].m};
    printf("stepper      steps    RHS   energy error  distance from hard   U0            U1\n");
    for (int i = 0; i < 3; i++)
        printf("%-10s %6ld %7ld   %10.3e   %10.3e        %.10f  %.10f\n", st[i]->name, steps[i], rhs[i], eerr[i],
               err[i], U[i][0], U[i][1]);
    printf("%-10s %6s %7s   %10s   %10s        %.10f  %.10f\n", "hard zmf", "", "", "", "", Uh[0], Uh[1]);
    double agree = fmax(soft_diff(out[1], out[0], 1.0), soft_diff(out[2], out[0], 1.0));
    double heat = fmax(fabs(U[0][0] - Uh[0]) / Uh[0], fabs(U[0][1] - Uh[1]) / Uh[1]);
    printf("steppers agree to %.3g; soft heat within %.3g (relative) of the hard law's at kappa = 1e8\n", agree,
           heat);
    /* the steppers' errors are each <= ~1e3 rtol (papers/soft-sphere.md: 5.1e-9 at rtol
     * 1e-10): 1e-7 */
    NB_CHECK(ok && agree < 1e-7, "CVODE and GSL steppers give the same outcome");
    NB_CHECK(eerr[0] < 2000 * prm.rtol && eerr[1] < 2000 * prm.rtol && eerr[2] < 2000 * prm.rtol,
             "every stepper keeps K + U to its tolerance");
    /* the outcome is within 6e-5 of the hard law at kappa = 1e8 (section above) and the heat
     * error is of the same relative order (measured 2.5e-5): 1e-3 leaves a factor 15 */
    NB_CHECK(heat < 1e-3 && Uh[0] > 0 && Uh[1] > 0, "the soft heat converges to the hard law's");
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    nb_init(argc, argv);
    headon();
    oblique();
    energy();
    steppers();
    return nb_finish();
}
