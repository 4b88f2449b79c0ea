/* test_engine_shapes.c — the supports of the table frame's contracted shapes that the
 * engine's separating-axis bounds and wall tests use (lib/engine/shapes.h: the shape from
 * a ball's stored state; toi_private.h's supports, also along an unnormalised axis):
 * against a long double reference, for speeds up to gamma = 1e12, and r/gamma exactly
 * along the motion.
 * The form r sqrt(1 - (u.v)^2/c^2) evaluated from v in double loses all its digits near c
 * (1 - v^2/c^2 ~ 1/gamma^2 is below the round-off of v^2 past gamma ~ 1e8), which moves
 * a separating-axis bound by more than its 1e-9 margin; the test shows that too.
 * And the Perram-Wertheim certificates that settle pairs without the frame, against the
 * frame. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../lib/engine/shapes.h"
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

/* An engine of n balls at c = 1, as far as engine/shapes.h reads one (its records). */
static rc_sim records_engine(eng_ball *b, eng_aux *a, size_t n)
{
    rc_sim s;
    memset(&s, 0, sizeof s);
    s.inv_c2 = 1.0;
    s.inv_c = 1.0;
    memset(b, 0, n * sizeof *b);
    memset(a, 0, n * sizeof *a);
    s.b = b;
    s.a = a;
    return s;
}

static void test_supports_near_c(void)
{
    eng_ball b[1];
    eng_aux a[1];
    rc_sim s = records_engine(b, a, 1);
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

/* pw_certify (engine/shapes.h), the Perram-Wertheim certificates the engine trusts in the
 * frame's place -- for parting pairs (parting_pw) and for approaching pairs asked at once
 * (overlap_now: an overlap answered without the frame) -- against the table frame itself
 * on random pairs whose bounding spheres overlap (gamma up to ~9, c = 1, 2-D and 3-D):
 * PW_OVERLAP only where the frame says RC_EOVERLAP; PW_APART with bound b only where the
 * frame finds no contact before b. Each answer must come up (a certificate that never
 * answers would pass vacuously). */
static void test_certificates(void)
{
    eng_ball b[2];
    eng_aux a[2];
    rc_sim s = records_engine(b, a, 2);
    rc_toi_params prm = rc_toi_params_default();
    prm.c = 1.0;
    rc_toi_workspace *ws = NULL;
    ENSURE(rc_toi_workspace_create(&ws) == RC_OK);
    rc_test_rng R = {11};
    size_t count[3] = {0, 0, 0}, bad = 0, near_touch = 0;
    for (int trial = 0; trial < 40000 && ws; trial++) {
        const int planar = trial % 2;
        for (int j = 0; j < 2; j++) {
            b[j].r = rc_test_range(&R, 0.3, 1.0);
            a[j].m = rc_test_range(&R, 0.5, 2.0);
            rc_vec3 p = rc_v3(rc_test_range(&R, -5, 5), rc_test_range(&R, -5, 5),
                              planar ? 0.0 : rc_test_range(&R, -5, 5));
            a[j].p = rc_v3_scale(a[j].m * rc_test_range(&R, 0.0, 1.0), p);
            b[j].v = rc_v3_scale(1.0 / eng_mass_rel(a[j].m, a[j].p, 1.0), a[j].p);
        }
        /* centres closer than the bounding spheres' radii sum, not closer than the
         * inscribed spheres' */
        rc_vec3 e = rc_v3(rc_test_range(&R, -1, 1), rc_test_range(&R, -1, 1),
                          planar ? 0.0 : rc_test_range(&R, -1, 1));
        if (!(rc_v3_norm(e) > 0.1))
            continue;
        e = rc_v3_scale(1.0 / rc_v3_norm(e), e);
        const double sig = b[0].r + b[1].r;
        const rc_vec3 dx = rc_v3_scale(sig * rc_test_range(&R, 0.55, 1.0), e);
        b[0].x = rc_v3(0, 0, 0);
        b[1].x = dx;
        /* the random separation, then (where the frame finds a contact) the separation at
         * contact scaled by 1 +- 1e-7 and 1 +- 1e-10: shapes apart or overlapping by a
         * hair, where a certificate without its margin (1e-9) would be wrong */
        rc_vec3 sep[5] = {dx, dx, dx, dx, dx};
        int nsep = 1;
        for (int q = 0; q < nsep; q++) {
            const rc_vec3 d = sep[q];
            const double d2 = rc_v3_norm2(d);
            if (!(d2 <= sig * sig))
                continue;
            const rc_toi_shape h0 = shape_of(&s, &b[0]), h1 = shape_of(&s, &b[1]);
            const double s0 = rc_toi_support_scaled_(&h0, d, d2);
            const double s1 = rc_toi_support_scaled_(&h1, d, d2);
            double bound = NAN;
            const int r = pw_certify(&s, &b[0], &b[1], d, d2, 0.0, s0 / (s0 + s1), &bound);
            count[r]++;
            near_touch += q > 0;
            const rc_toi_ball A = {rc_v3(0, 0, 0), b[0].r, a[0].m, a[0].p};
            const rc_toi_ball B = {d, b[1].r, a[1].m, a[1].p};
            rc_toi_contact out;
            const int st = rc_toi_frame_table.toi(&prm, &A, &B, ws, &out);
            int ok = 1;
            if (r == PW_OVERLAP)
                ok = st == RC_EOVERLAP;
            else if (r == PW_APART)
                ok = st == RC_MISS || (st == RC_OK && out.t >= bound);
            if (!ok && bad++ < 5)
                ENSURE_MSG(0, "trial %d.%d: certificate %d (bound %.17g), frame %d (t %.17g)",
                           trial, q, r, bound, st, st == RC_OK ? out.t : NAN);
            if (q == 0 && st == RC_OK && out.t > 0.0) {
                const rc_vec3 dc = rc_v3_axpy(d, out.t, rc_v3_sub(b[1].v, b[0].v));
                sep[1] = rc_v3_scale(1.0 + 1e-7, dc);
                sep[2] = rc_v3_scale(1.0 - 1e-7, dc);
                sep[3] = rc_v3_scale(1.0 + 1e-10, dc);
                sep[4] = rc_v3_scale(1.0 - 1e-10, dc);
                nsep = 5;
            }
        }
    }
    ENSURE_MSG(bad == 0, "%zu certificates the frame contradicts", bad);
    ENSURE_MSG(count[PW_OVERLAP] > 1000 && count[PW_APART] > 1000 && near_touch > 1000,
               "overlap %zu, apart %zu, near touching %zu: each should come up often",
               count[PW_OVERLAP], count[PW_APART], near_touch);
    printf("  %zu overlapping, %zu apart (bounded), %zu left to the frame (%zu pairs within "
           "1e-7 or 1e-10 of touching); %zu contradicted by the frame\n",
           count[PW_OVERLAP], count[PW_APART], count[PW_OPEN], near_touch, bad);
    rc_toi_workspace_free(&ws);
}

int main(void)
{
    RUN_TEST(test_supports_near_c);
    RUN_TEST(test_certificates);
    RC_TEST_MAIN_END();
}
