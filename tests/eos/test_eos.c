/* test_eos.c — the gas's pressure and transport measured against theory, each at a size
 * that runs in seconds: the flux-moment pressure against the walls' momentum flux, the
 * dilute relativistic limit P = n kT (and the classical equation of state it keeps for
 * uncontracted spheres), Kolafa's hard-sphere equation of state, and the self-diffusion of
 * a dilute gas against Chapman–Enskog (classical, and relativistic for the sphere kernel)
 * and of the dense gas (packing 0.2) against Speedy's fit, and the shear viscosity and heat
 * conductivity of the relativistic gas against the sphere kernel's Chapman–Enskog values. Tolerances: a few standard errors of the blocks
 * (measured in the run itself) plus the stated accuracy of the theory. */
#include <math.h>
#include <stdlib.h>

#include "eos_run.h"
#include "eos_theory.h"
#include "tr_first_order.h"
#include "tr_shear_heat.h"
#include "rc_test.h"

static eos_in base(void)
{
    eos_in in = {3, 500, 0.1, 1.0, INFINITY, NULL, 7, 20.0, 400.0, 20, 50, 0, 10.0, 0, 0.0, NULL, NULL, NULL};
    in.frame = rc_toi_frame_find("sphere");
    return in;
}

/* Classical hard spheres at packing 0.3 against Kolafa's equation of state (accurate to
 * 1e-4 there): within 4 standard errors (N = 500 adds an O(1/N) shift far below that). */
static void test_kolafa(void)
{
    eos_in in = base();
    in.packing = 0.3;
    in.t_equil = 50.0;
    eos_out r;
    char err[256];
    ENSURE_MSG(eos_measure(&in, &r, err) == 0, "%s", err);
    const double zk = eos_z_kolafa(0.3);
    printf("  Z(0.3) = %.5f +- %.5f, Kolafa %.5f, Carnahan-Starling %.5f\n", r.z, r.z_se, zk,
           eos_z_cs(0.3));
    ENSURE(r.z_se > 0.0 && r.z_se < 0.01 * zk);
    ENSURE_CLOSE(r.z, zk, 4.0, r.z_se + 1e-4 * zk);
}

/* Relativistic gas (c = 1, theta = 1) of uncontracted spheres: its equilibrium is Jüttner
 * times the classical configurations, so P = n kT (1 + 4 eta chi) with Kolafa's chi at
 * every c -- at packing 0.01 the dilute limit P = n kT to 4 %, tested to 4 standard
 * errors; and kT = <p.v> / 3 is the Jüttner temperature theta the start energy set. */
static void test_dilute_relativistic(void)
{
    eos_in in = base();
    in.packing = 0.01;
    in.c = 1.0;
    in.theta = 1.0;
    eos_out r;
    char err[256];
    ENSURE_MSG(eos_measure(&in, &r, err) == 0, "%s", err);
    const double zk = eos_z_kolafa(0.01);
    printf("  relativistic theta 1, packing 0.01: Z = %.5f +- %.5f (Kolafa %.5f), kT = "
           "%.5f +- %.5f\n", r.z, r.z_se, zk, r.kT, r.kT_se);
    ENSURE_CLOSE(r.z, zk, 4.0, r.z_se);
    /* (the mean of the blocks' ratios against the ratio of their means) */
    ENSURE_CLOSE(r.p * r.volume / ((double)in.n * r.kT), r.z, 4.0, r.z_se);
    /* the start is every ball at the Jüttner mean energy: <p.v>/3 relaxes to theta (the
     * 1/N of zero total momentum and the dilute packing aside: 1 %) */
    ENSURE_CLOSE(r.kT, 1.0, 0.01, 1.0);
}

/* Self-diffusion of a dilute hard-sphere gas (packing 0.02): Enskog's D0 / chi times the
 * second Chapman–Enskog approximation's 1.019 (Chapman & Cowling, rigid spheres); within 4
 * standard errors plus 1.5 % for the dense-fluid correction (Alder, Gass & Wainwright
 * 1970: a few per cent only at packings above 0.05) and the finite box. */
static void test_diffusion(void)
{
    eos_in in = base();
    in.packing = 0.02;
    in.transport = 1;
    in.t_run = 1000.0;
    eos_out r;
    char err[256];
    ENSURE_MSG(eos_measure(&in, &r, err) == 0, "%s", err);
    const double de = 1.019 * tr_d_enskog(0.02, r.kT);
    printf("  D(0.02) = %.4f +- %.4f, Chapman-Enskog x Enskog %.4f\n", r.d, r.d_se, de);
    ENSURE(r.d_se > 0.0 && r.d_se < 0.05 * de);
    ENSURE_CLOSE(r.d, de, 1.0, 4.0 * r.d_se + 0.015 * de);
}

/* Self-diffusion at packing 0.2 (N = 500) against Speedy's (1987) fit, which represents
 * systems of about 500 spheres (Sigurgeirsson & Heyes 2003), carried to this box by the
 * Yeh-Hummer law (a no-op at N = 500). The lag is 100 mean free times: the hydrodynamic
 * long-time tail of the velocity correlation is still adding to D at the default 20
 * (papers/transport.md, section 5). Within 4 standard errors plus 2 %: neither source
 * states the fit's error, and "about 500" alone spans 1 % (N from 400 to 700 moves D by
 * 0.8-1.1 % by Yeh-Hummer). Subtracting the whole infinite-box correction instead, as the
 * theory here once did, misses by 10 % and fails. */
static void test_diffusion_dense(void)
{
    eos_in in = base();
    in.packing = 0.2;
    in.transport = 1;
    in.t_run = 4000.0;
    in.lag = 100.0;
    eos_out r;
    char err[256];
    ENSURE_MSG(eos_measure(&in, &r, err) == 0, "%s", err);
    const double ds = tr_d_speedy_box(0.2, r.kT, tr_eta_enskog(0.2, r.kT), r.box);
    printf("  D(0.2) = %.4f +- %.4f, Speedy (N = 500) in this box %.4f, Enskog %.4f\n", r.d,
           r.d_se, ds, tr_d_enskog(0.2, r.kT));
    ENSURE(r.d_se > 0.0 && r.d_se < 0.02 * ds);
    ENSURE_CLOSE(r.d, ds, 1.0, 4.0 * r.d_se + 0.02 * ds);
}

/* The first Chapman–Enskog approximation of self-diffusion for the sphere kernel
 * (tr_first_order.h), by Monte Carlo: classically it must be Chapman & Cowling's
 * 3/(8 n sigma^2) sqrt(kT/(pi m)) (within 4 of its standard errors). Relativistic
 * (c = 1, theta = 1, packing 0.02, N = 500, sphere frame): the measured D against the
 * Galerkin solution on {p_x, v_x} divided by Enskog's chi, within 4 standard errors of
 * each plus 2 % -- the classical first approximation's own error (1.9 %, Chapman &
 * Cowling); the relativistic one is not known, and p_x alone falls 7 % short here, so
 * the test also asks the measurement to lie above the one-function value. */
static void test_diffusion_relativistic(void)
{
    double nd, nd_se;
    ENSURE(tr_nd_sphere(INFINITY, 1.0, 1, 400000, 5, &nd, &nd_se) == 0);
    printf("  classical n D_1 = %.5f +- %.5f (Chapman-Cowling %.5f)\n", nd, nd_se,
           3.0 / 8.0 * sqrt(1.0 / M_PI));
    ENSURE_CLOSE(nd, 3.0 / 8.0 * sqrt(1.0 / M_PI), 4.0, nd_se);

    eos_in in = base();
    in.packing = 0.02;
    in.c = 1.0;
    in.theta = 1.0;
    in.transport = 1;
    in.t_run = 1000.0;
    in.lag = 20.0;
    eos_out r;
    char err[256];
    ENSURE_MSG(eos_measure(&in, &r, err) == 0, "%s", err);
    const double n = 6.0 * 0.02 / M_PI, chi = eos_chi(3, 0.02);
    double n1, n1_se, n2, n2_se;
    ENSURE(tr_nd_sphere(1.0, 1.0, 1, 400000, 6, &n1, &n1_se) == 0);
    ENSURE(tr_nd_sphere(1.0, 1.0, 2, 400000, 7, &n2, &n2_se) == 0);
    const double d1 = n1 / (n * chi), d2 = n2 / (n * chi), d2_se = n2_se / (n * chi);
    printf("  c = 1, theta = 1, packing 0.02: D = %.4f +- %.4f; first approximation {p_x, "
           "v_x} %.4f +- %.4f, p_x alone %.4f\n", r.d, r.d_se, d2, d2_se, d1);
    ENSURE(r.d_se > 0.0 && r.d_se < 0.02 * d2);
    ENSURE_CLOSE(r.d, d2, 1.0, 4.0 * (r.d_se + d2_se) + 0.02 * d2);
    ENSURE(r.d > d1 + 4.0 * r.d_se);
}

/* The first Chapman–Enskog eta and lambda of the sphere kernel (tr_shear_heat.h), by Monte
 * Carlo. Classically (first functions alone) they must be Chapman & Cowling's first
 * approximations for spheres, 5/16 sqrt(kT/pi) and 75/64 sqrt(kT/pi), and for discs
 * 1/2 sqrt(kT/pi) and 2 sqrt(kT/pi), and the spheres' collisional-transfer terms Enskog's
 * 2/5 and 3/5 (the 0.8 b n and 1.2 b n of eos_theory.h) -- each within 4 of the Monte
 * Carlo's standard errors; and the collision leaves the pair measure alone (heat_inv = 0
 * within 4 standard errors, at c = 1 too). Relativistic (c = 1, theta = 1, packing 0.02,
 * N = 500, sphere frame): the Einstein–Helfand eta and lambda against the two-function
 * values carried to the packing (tr_shear_heat_enskog), within 4 combined standard errors
 * (run and Monte Carlo) plus 2 %: the two-function values move by under 0.5 % with a third
 * function, and the (b n)^2 terms taken from the classical gas are 0.5 % of the values.
 * At theta = 1 both coefficients lie far from the classical ones at the same kT (eta twice
 * Enskog's, lambda 15 % below), so the test tells the relativistic theory from the
 * classical one. */
static void test_shear_heat_relativistic(void)
{
    const double s = sqrt(1.0 / M_PI);
    const double ref[2][2] = {{0.5 * s, 2.0 * s}, {5.0 / 16.0 * s, 75.0 / 64.0 * s}};
    tr_shear_heat o;
    for (int dim = 2; dim <= 3; dim++) {
        ENSURE(tr_shear_heat_sphere(dim, INFINITY, 1.0, 1, 400000, 11 + dim, &o) == 0);
        printf("  classical %d-D: eta_1 = %.5f +- %.5f (%.5f), lambda_1 = %.5f +- %.5f (%.5f), "
               "momentum part %.4f +- %.4f, alpha %.4f +- %.4f and %.4f +- %.4f\n", dim, o.eta,
               o.eta_se, ref[dim - 2][0], o.lambda, o.lambda_se, ref[dim - 2][1], o.heat_inv,
               o.heat_inv_se, o.alpha_eta, o.alpha_eta_se, o.alpha_lambda, o.alpha_lambda_se);
        ENSURE(o.eta_se > 0.0 && o.eta_se < 0.01 * o.eta);
        ENSURE(o.lambda_se > 0.0 && o.lambda_se < 0.02 * o.lambda);
        ENSURE_CLOSE(o.eta, ref[dim - 2][0], 4.0, o.eta_se);
        ENSURE_CLOSE(o.lambda, ref[dim - 2][1], 4.0, o.lambda_se);
        ENSURE_CLOSE(o.heat_inv, 0.0, 4.0, o.heat_inv_se);
    }
    ENSURE_CLOSE(o.alpha_eta, 0.4, 4.0, o.alpha_eta_se);
    ENSURE_CLOSE(o.alpha_lambda, 0.6, 4.0, o.alpha_lambda_se);
    /* the bad inputs are refused */
    ENSURE(tr_shear_heat_sphere(4, 1.0, 1.0, 1, 400000, 1, &o) == -1);
    ENSURE(tr_shear_heat_sphere(3, 1.0, 0.0, 1, 400000, 1, &o) == -1);
    ENSURE(tr_shear_heat_sphere(3, 1.0, 1.0, 4, 400000, 1, &o) == -1);

    eos_in in = base();
    in.packing = 0.02;
    in.c = 1.0;
    in.theta = 1.0;
    in.transport = 1;
    in.t_run = 6000.0;
    in.blocks = 30;
    in.per_block = 200;
    in.lag = 20.0;
    eos_out r;
    char err[256];
    ENSURE_MSG(eos_measure(&in, &r, err) == 0, "%s", err);
    ENSURE(tr_shear_heat_sphere(3, 1.0, r.kT, 2, 400000, 17, &o) == 0);
    ENSURE_CLOSE(o.heat_inv, 0.0, 4.0, o.heat_inv_se);
    double et, lt;
    tr_shear_heat_enskog(&o, 1.0, r.kT, 0.02, &et, &lt);
    const double et_se = o.eta_se * et / o.eta, lt_se = o.lambda_se * lt / o.lambda;
    printf("  c = 1, theta = 1, packing 0.02: eta = %.4f +- %.4f (Chapman-Enskog %.4f +- %.4f, "
           "Enskog %.4f); lambda = %.4f +- %.4f (Chapman-Enskog %.4f +- %.4f, Enskog %.4f)\n",
           r.eta, r.eta_se, et, et_se, tr_eta_enskog(0.02, r.kT), r.lambda, r.lambda_se, lt,
           lt_se, tr_lambda_enskog(0.02, r.kT));
    ENSURE(r.eta_se > 0.0 && r.eta_se < 0.1 * et);
    ENSURE(r.lambda_se > 0.0 && r.lambda_se < 0.1 * lt);
    ENSURE_CLOSE(r.eta, et, 1.0, 4.0 * hypot(r.eta_se, et_se) + 0.02 * et);
    ENSURE_CLOSE(r.lambda, lt, 1.0, 4.0 * hypot(r.lambda_se, lt_se) + 0.02 * lt);
}

/* A walled box: what the walls take per unit area and time equals the virial pressure of
 * the gas, (<sum p_d v_d> + collisional transfer rate) / ((L - 2 r) A): the virial
 * theorem with the walls' own moment, the centres reaching only L - 2 r. 3-D, packing
 * 0.02, within 4 standard errors of the blocks. */
static void test_walls(void)
{
    const size_t n = 400;
    rc_sim_ball *b = malloc(n * sizeof *b);
    rc_sim_gas_def g = {3, n, 0.5, 0.02, sqrt(3.0), INFINITY, 8.0, 11};
    rc_vec3 box;
    ENSURE(rc_sim_gas_init(&g, &box, b) == RC_OK);
    rc_sim_def d = rc_sim_def_default();
    d.dim = 3;
    d.box = box;
    d.c = INFINITY;
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK && rc_sim_set_balls(s, n, b, NULL) == RC_OK);
    free(b);
    if (!s)
        return;
    const double L = box.x, A = L * L, r = 0.5;
    const double tfree = 1.0 / (6.0 * 0.02 / M_PI * M_PI * sqrt(2.0) * sqrt(8.0 / M_PI));
    enum { NB = 20, PB = 200 };
    ENSURE(rc_sim_advance(s, 20.0 * tfree, 0) == RC_OK);
    double pw[NB], pv[NB];
    rc_sim_diag d0;
    rc_sim_diagnostics(s, &d0);
    const double dt = 20.0 * tfree / PB;
    for (int blk = 0; blk < NB; blk++) {
        double kin = 0.0;
        const double t0 = rc_sim_time(s);
        for (int k = 0; k < PB; k++) {
            ENSURE(rc_sim_advance(s, t0 + dt * (k + 1), 0) == RC_OK);
            rc_sim_moments m;
            rc_sim_moments_get(s, &m);
            kin += m.kinetic[0] + m.kinetic[4] + m.kinetic[8];
        }
        rc_sim_diag d1;
        rc_sim_diagnostics(s, &d1);
        const double T = rc_sim_time(s) - t0;
        double wall = 0.0, vir = 0.0;
        for (int a = 0; a < 3; a++) {
            wall += (d1.wall_impulse_by_wall[2 * a + 1] - d0.wall_impulse_by_wall[2 * a + 1]) -
                    (d1.wall_impulse_by_wall[2 * a] - d0.wall_impulse_by_wall[2 * a]);
            vir += d1.virial[4 * a] - d0.virial[4 * a];
        }
        pw[blk] = wall / 2.0 / (3.0 * A * T);
        pv[blk] = (kin / PB + vir / T) / (3.0 * A * (L - 2.0 * r));
        d0 = d1;
    }
    double diff[NB], se_d;
    for (int k = 0; k < NB; k++)
        diff[k] = pw[k] - pv[k];
    double se_w, se_v;
    const double mw = eos_mean_se(pw, NB, &se_w), mv = eos_mean_se(pv, NB, &se_v);
    const double md = eos_mean_se(diff, NB, &se_d);
    printf("  walled box: P_wall = %.5f +- %.5f, P_virial = %.5f +- %.5f (difference %.5f +- "
           "%.5f)\n", mw, se_w, mv, se_v, md, se_d);
    ENSURE_CLOSE(md, 0.0, 4.0, se_d);
    ENSURE(se_d < 0.02 * mw);
    rc_sim_free(&s);
}

/* Two balls meeting head-on across a periodic face: the Helfand moment stays continuous
 * (its change is the kinetic flux times the time plus r dp of the collision, r the nearest
 * image), while the unwrapped sum x p alone jumps by L dp. Exact arithmetic up to round-off:
 * x_A = 0.8, v = -1; x_B = 9.7, v = +1 in a box of 10; contact at t = 0.05 across x = 0
 * with r = x_B - x_A = -1 (nearest image), dp_B = -2; between t = 0.04 and 0.06,
 * dG_xx = 2 x 0.02 + (-1)(-2) = 2.04, virial 2, wrap term (-1 - 9)(-2) = 20. */
static void test_helfand_across_face(void)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 3;
    d.box = rc_v3(10.0, 10.0, 10.0);
    d.c = INFINITY;
    for (int k = 0; k < 3; k++)
        d.boundary[k] = RC_SIM_PERIODIC;
    rc_sim_ball b[2] = {{rc_v3(0.8, 5.0, 5.0), rc_v3(-1.0, 0.0, 0.0), 0.5, 1.0, 0, 0, 0, {0, 0, 0}},
                        {rc_v3(9.7, 5.0, 5.0), rc_v3(1.0, 0.0, 0.0), 0.5, 1.0, 0, 0, 0, {0, 0, 0}}};
    rc_sim *s = NULL;
    ENSURE(rc_sim_create(&d, &s) == RC_OK && rc_sim_set_balls(s, 2, b, NULL) == RC_OK);
    if (!s)
        return;
    rc_sim_moments m0, m1;
    ENSURE(rc_sim_advance(s, 0.04, 0) == RC_OK && rc_sim_moments_get(s, &m0) == RC_OK);
    ENSURE(rc_sim_advance(s, 0.06, 0) == RC_OK && rc_sim_moments_get(s, &m1) == RC_OK);
    ENSURE_CLOSE(m1.helfand[0] - m0.helfand[0], 2.04, 1e-12, 20.0);
    ENSURE_CLOSE(m1.virial[0] - m0.virial[0], 2.0, 1e-12, 2.0);
    ENSURE_CLOSE(m1.kinetic[0], 2.0, 1e-15, 2.0);
    rc_sim_diag dg;
    rc_sim_diagnostics(s, &dg);
    ENSURE_CLOSE(dg.helfand_wrap[0], 20.0, 1e-12, 20.0);
    ENSURE(dg.collisions == 1);
    rc_sim_free(&s);
}

int main(void)
{
    RUN_TEST(test_helfand_across_face);
    RUN_TEST(test_walls);
    RUN_TEST(test_kolafa);
    RUN_TEST(test_dilute_relativistic);
    RUN_TEST(test_diffusion);
    RUN_TEST(test_diffusion_dense);
    RUN_TEST(test_diffusion_relativistic);
    RUN_TEST(test_shear_heat_relativistic);
    RC_TEST_MAIN_END();
}
