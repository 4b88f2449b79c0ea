/* test_engine_shapes.c — the supports of the table frame's contracted shapes that the
 * engine's separating-axis bounds and wall tests use (lib/engine_shapes.h: the shape from
 * a ball's stored state; toi_private.h's supports, also along an unnormalised axis):
 * against a long double reference, for speeds up to gamma = 1e12, and r/gamma exactly
 * along the motion.
 * The form r sqrt(1 - (u.v)^2/c^2) evaluated from v in double loses all its digits near c
 * (1 - v^2/c^2 ~ 1/gamma^2 is below the round-off of v^2 past gamma ~ 1e8), which moves
 * a separating-axis bound by more than its 1e-9 margin; the test shows that too. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../lib/engine_shapes.h"
#include "rc_test.h"
#include "relcol/relcol.h"

/* Error allowed, relative to the radius (the scale of the callers' margins, 1e-9 of the
 * radii): a few ulps (~1e-15). The naive form's error reaches ~1e-8 of the radius once
 * 1/gamma^2 is below round-off, more than the margins. */
#define TOL 1e-13
#define MARGIN 1e-9

/* r sqrt(|u|^2 - (u.v)^2/c^2) with v = p / M (c = 1) in long double, from (m, p): with
 * M^2 = m^2 + |p|^2, |u|^2 - (u.p)^2/M^2 = (m^2 |u|^2 + |p x u|^2) / M^2 (Lagrange's
 * identity), which cancels nothing: the reference. */
static long double support_ref(double r, double m, rc_vec3 p, rc_vec3 u)
{
    const long double px = p.x, py = p.y, pz = p.z, ux = u.x, uy = u.y, uz = u.z;
    const long double cx = py * uz - pz * uy, cy = pz * ux - px * uz, cz = px * uy - py * ux;
    const long double m2 = (long double)m * m, M2 = m2 + px * px + py * py + pz * pz;
    return (long double)r *
           sqrtl((m2 * (ux * ux + uy * uy + uz * uz) + cx * cx + cy * cy + cz * cz) / M2);
}

static void test_supports_near_c(void)
{
    rc_sim s;
    memset(&s, 0, sizeof s);
    s.inv_c2 = 1.0;
    s.inv_c = 1.0;
    eng_ball b[1];
    eng_aux a[1];
    memset(b, 0, sizeof b);
    memset(a, 0, sizeof a);
    s.b = b;
    s.a = a;
    rc_test_rng R = {5};
    double worst = 0.0, worst_naive = 0.0;
    for (int k = 0; k <= 12; k++) {
        const double gamma = pow(10.0, k);
        for (int trial = 0; trial < 200; trial++) {
            /* a random direction of motion and a random axis */
            rc_vec3 e = rc_v3(rc_test_range(&R, -1, 1), rc_test_range(&R, -1, 1),
                              rc_test_range(&R, -1, 1));
            e = rc_v3_scale(1.0 / rc_v3_norm(e), e);
            rc_vec3 u = trial % 4 == 0 ? e
                                       : rc_v3(rc_test_range(&R, -1, 1), rc_test_range(&R, -1, 1),
                                               rc_test_range(&R, -1, 1));
            u = rc_v3_scale(1.0 / rc_v3_norm(u), u);
            b[0].r = 0.5;
            a[0].m = 1.0;
            a[0].p = rc_v3_scale(sqrt(gamma * gamma - 1.0), e); /* |p| = m sqrt(g^2 - 1) */
            const double M = eng_mass_rel(a[0].m, a[0].p, s.inv_c2);
            b[0].v = rc_v3_scale(1.0 / M, a[0].p);
            const rc_toi_shape h = shape_of(&s, &b[0]);
            const long double ref = support_ref(b[0].r, a[0].m, a[0].p, u);
            const double got = rc_toi_support_(&h, u);
            const double got_scaled = rc_toi_support_scaled_(&h, rc_v3_scale(3.0, u), 9.0) / 3.0;
            const double uv = rc_v3_dot(u, b[0].v);
            const double naive = b[0].r * sqrt(fmax(0.0, 1.0 - uv * uv));
            worst = fmax(worst, (double)fabsl((got - ref) / b[0].r));
            worst = fmax(worst, (double)fabsl((got_scaled - ref) / b[0].r));
            worst_naive = fmax(worst_naive, (double)fabsl((naive - ref) / b[0].r));
            if (trial % 4 == 0) /* along the motion: r / gamma exactly */
                ENSURE_MSG(fabs(h.r * h.g - b[0].r / gamma) <= TOL * b[0].r / gamma,
                           "gamma %g: r/gamma %.17g, r g %.17g", gamma, b[0].r / gamma, h.r * h.g);
        }
    }
    ENSURE_MSG(worst <= TOL, "support off by %.3g of the radius", worst);
    /* the check can tell: the cancelling form is wrong by more than the margins near c */
    ENSURE_MSG(worst_naive > MARGIN, "the naive form's error %.3g", worst_naive);
    printf("  gamma 1 .. 1e12: worst error %.2g of the radius (the naive form: %.2g)\n", worst,
           worst_naive);
}

int main(void)
{
    RUN_TEST(test_supports_near_c);
    RC_TEST_MAIN_END();
}
