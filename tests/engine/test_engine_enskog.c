/* test_engine_enskog.c — the classical equilibrium collision rate per ball of hard spheres
 * and discs in a periodic box, against Enskog's exact-in-equilibrium formula with an
 * accurate contact value of the pair distribution, with no box-size extrapolation:
 *
 *   3-D  Gamma = 4 n sigma^2 g(sigma) sqrt(pi kT / m)
 *   2-D  Gamma = 2 n sigma   g(sigma) sqrt(pi kT / m)
 *
 * (Gamma = n g(sigma) x the collision cross-section, pi sigma^2 or 2 sigma, x the mean
 * relative speed, sqrt(16 kT / (pi m)) in 3-D and sqrt(pi kT / m) in 2-D; in equilibrium
 * the velocities of a pair at contact are uncorrelated with its position, so this is
 * exact given the true g(sigma) -- the same g(sigma) the virial route turns into the
 * pressure, Z = 1 + 4 eta g(sigma) in 3-D, 1 + 2 eta g(sigma) in 2-D; papers/periodic.md).
 * g(sigma) = (Z - 1) / (4 eta) from Kolafa's equation of state (3-D), and Luding's
 * contact value for discs (2-D). Packings 0.30 and 0.45 (3-D), 0.5 (2-D). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "engine_util.h"

/* Kolafa: Z = (1 + eta + eta^2 - 2/3 eta^3 (1 + eta)) / (1 - eta)^3 (Boublik & Nezbeda,
 * Collect. Czech. Chem. Commun. 51, 2301 (1986)); within ~1e-4 of the simulated hard-sphere
 * pressure over the stable fluid, where Carnahan-Starling is 0.2 % low at 0.45. */
static double g_kolafa(double eta)
{
    const double z = (1 + eta + eta * eta - 2.0 / 3.0 * eta * eta * eta * (1 + eta)) /
                     pow(1 - eta, 3);
    return (z - 1) / (4 * eta);
}

/* Luding, Phys. Rev. E 63, 042201 (2001): Henderson's (1 - 7 eta/16)/(1 - eta)^2 with the
 * correction - eta^3 / (128 (1 - eta)^4) (0.5 % at 0.5), which brings it to the simulated
 * disc pressure within ~0.1 % in the fluid. */
static double g_luding(double eta)
{
    const double u = 1 - eta;
    return (1 - 7 * eta / 16) / (u * u) - eta * eta * eta / (128 * u * u * u * u);
}

/* Relative difference of the measured rate from Enskog's, and its standard error from
 * NB block means (blocks of ~6e4 collisions, 60 a ball: far longer than the time over which
 * the collision rate is correlated, so the block means are independent). */
#define NB 16

static void rate(int dim, size_t n, double eta, double melt_per_ball, double per_ball,
                 uint64_t seed, double tol)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    for (int k = 0; k < 3; k++)
        d.boundary[k] = RC_SIM_PERIODIC;
    const double r = 0.5, sigma = 2 * r;
    rc_sim_gas_def g = {dim, n, r, eta, 1.0, INFINITY, 1.0, seed};
    rc_sim_ball *b = malloc(n * sizeof *b);
    rc_sim *s = NULL;
    ENSURE(rc_sim_gas_init(&g, &d.box, b) == RC_OK);
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    ENSURE(rc_sim_set_balls(s, n, b, NULL) == RC_OK);
    const double m = b[0].m;
    free(b);
    if (!s)
        return;
    const double V = dim == 3 ? d.box.x * d.box.y * d.box.z : d.box.x * d.box.y;
    const double nd = (double)n / V;
    /* melt the lattice start */
    util_run_collisions(s, (uint64_t)(melt_per_ball * (double)n));
    rc_sim_diag d0, d1;
    rc_sim_diagnostics(s, &d0);
    /* the temperature: the kinetic energy is conserved exactly, with d (N - 1) degrees of
     * freedom (total momentum is zero) */
    const double kT = 2 * d0.kinetic / (dim * ((double)n - 1));
    const double gs = dim == 3 ? g_kolafa(eta) : g_luding(eta);
    const double enskog = (dim == 3 ? 4 * nd * sigma * sigma : 2 * nd * sigma) * gs *
                          sqrt(M_PI * kT / m);
    /* blocks of equal time, each expected to hold per_ball / NB collisions a ball */
    const double tb = per_ball / NB / enskog;
    double sum = 0, sum2 = 0;
    for (int k = 0; k < NB; k++) {
        rc_sim_diagnostics(s, &d0);
        ENSURE(rc_sim_advance(s, d0.time + tb, 0) == RC_OK);
        rc_sim_diagnostics(s, &d1);
        const double x = 2.0 * (double)(d1.collisions - d0.collisions) / ((double)n * tb);
        sum += x;
        sum2 += x * x;
    }
    ENSURE(d1.events[RC_SIM_EV_WALL] == 0);
    const double mean = sum / NB, sd = sqrt((sum2 - sum * sum / NB) / (NB - 1));
    const double se = sd / sqrt(NB) / mean, dev = mean / enskog - 1;
    printf("  %d-D eta %.2f N %zu: rate %.5f per ball, Enskog (g %.5f) %.5f: %+.4f +- %.4f "
           "(relative; tolerance %.4f)\n", dim, eta, n, mean, gs, enskog, dev, se, tol);
    ENSURE_MSG(fabs(dev) <= tol, "%d-D eta %.2f: rate off Enskog's by %+.4f (+- %.4f)", dim,
               eta, dev, se);
    /* the statistical error must be well inside the tolerance for the test to mean it */
    ENSURE_MSG(3 * se <= tol, "%d-D eta %.2f: standard error %.4f too large for %.4f", dim, eta,
               se, tol);
    rc_sim_free(&s);
}

/* Tolerances: 3 standard errors of the block mean (~0.1 % each at ~1e6 collisions), plus
 * the equation of state's own error (~0.01 % Kolafa, ~0.1 % Luding), plus the finite
 * size of a periodic system of N balls, O(1/N) in g(sigma) (~0.1 % at N = 2000 by the
 * runs at N = 500 and 8000 in papers/periodic.md): 0.5 % in 3-D, 0.6 % in 2-D. Walls
 * would raise the rate by several per cent (the contact value at a wall is higher), a
 * wrong nearest image or a lost event by more. */
static void test_enskog(void)
{
    rate(3, 2000, 0.30, 30, 1000, 3, 5e-3);
    rate(3, 2000, 0.45, 30, 1000, 4, 5e-3);
    rate(2, 2000, 0.50, 30, 1000, 5, 6e-3);
}

int main(void)
{
    RUN_TEST(test_enskog);
    RC_TEST_MAIN_END();
}
