/* test_eos_start.c — relcol-eos's start reaches every packing the fluid has, for any N:
 * over several N (cubes and not) and packings to the freezing packing (3-D 0.494, 2-D
 * 0.70), eos_start makes the gas (rc_sim_create refuses overlapping balls), with the exact
 * packing and every periodic pair farther apart than a diameter; and 2-D's theory column,
 * Luding's disc equation of state, agrees with Liu's independent fit (2020) where the
 * virial series does not. */
#include <math.h>
#include <stdlib.h>

#include "eos_run.h"
#include "eos_theory.h"
#include "rc_test.h"

/* nearest periodic pair distance, O(n^2) */
static double nearest(const rc_sim *s, size_t n, int dim, double L)
{
    rc_vec3 *x = malloc(n * sizeof *x);
    double d2 = INFINITY;
    if (!x)
        return 0.0;
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball b;
        rc_sim_get_ball(s, i, &b);
        x[i] = b.x;
    }
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            double q[3] = {x[i].x - x[j].x, x[i].y - x[j].y, x[i].z - x[j].z}, r2 = 0.0;
            for (int a = 0; a < dim; a++) {
                q[a] -= L * round(q[a] / L);
                r2 += q[a] * q[a];
            }
            d2 = fmin(d2, r2);
        }
    free(x);
    return sqrt(d2);
}

static void test_every_packing(void)
{
    static const size_t ns[] = {100, 250, 257, 500, 999, 1331, 2001};
    static const double p3[] = {0.3, 0.45, 0.494}, p2[] = {0.5, 0.65, 0.70};
    for (int dim = 2; dim <= 3; dim++)
        for (size_t a = 0; a < sizeof ns / sizeof *ns; a++)
            for (int k = 0; k < 3; k++) {
                eos_in in = {dim, ns[a], dim == 3 ? p3[k] : p2[k], 1.0, INFINITY, NULL, 7,
                             1.0, 1.0, 2, 1, 0, 1.0, 0, 0.0, NULL, NULL, NULL};
                in.frame = rc_toi_frame_find("sphere");
                rc_sim *s = NULL;
                double L = 0.0;
                char err[256] = "";
                const int st = eos_start(&in, &s, &L, err);
                ENSURE_MSG(st == 0, "dim %d n %zu packing %g: %s", dim, in.n, in.packing, err);
                if (st != 0)
                    continue;
                const double vball = dim == 3 ? M_PI / 6.0 : M_PI / 4.0;
                ENSURE_REL((double)in.n * vball / pow(L, dim), in.packing, 1e-12);
                const double dmin = nearest(s, in.n, dim, L);
                ENSURE_MSG(dmin > 1.0, "dim %d n %zu packing %g: nearest %.6f", dim, in.n,
                           in.packing, dmin);
                rc_sim_free(&s);
            }
}

/* Liu, "Global equation of state and phase transitions of the hard disc systems",
 * arXiv:2010.10624 (2020), Eq. 1 for the stable fluid */
static double z_liu(double e)
{
    return (1.0 + e * e / 8.0 + e * e * e / 18.0 - 4.0 * e * e * e * e / 21.0) /
           ((1.0 - e) * (1.0 - e));
}

static void test_disc_theory(void)
{
    /* the two fits to simulations agree to 0.05 % to 0.5 and 0.31 % at 0.65 */
    for (double e = 0.05; e <= 0.6501; e += 0.05)
        ENSURE_CLOSE(eos_z_disc(e), z_liu(e), e <= 0.5 ? 6e-4 : 3.5e-3, z_liu(e));
    /* the virial series agrees in the dilute gas and falls away near freezing */
    ENSURE_REL(eos_z_disc_virial(0.2), eos_z_disc(0.2), 2e-4);
    ENSURE(eos_z_disc_virial(0.65) < 0.95 * eos_z_disc(0.65));
    /* the contact value that follows from it (Z = 1 + 2 eta chi) */
    ENSURE_REL(1.0 + 2.0 * 0.6 * eos_chi(2, 0.6), eos_z_disc(0.6), 1e-14);
}

int main(void)
{
    RUN_TEST(test_every_packing);
    RUN_TEST(test_disc_theory);
    RC_TEST_MAIN_END();
}
