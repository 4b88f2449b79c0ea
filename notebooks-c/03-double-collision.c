/*md
# 3. The double collision

Seed 000 part 8 ("Billiard simulation–part 8: double collision") lets ball 0 hit balls 1
and 2 at the same instant. Forces act only along the two centre lines, so each struck ball
keeps its velocity across its line; each line obeys the restitution formula; momentum is
conserved. With `u = (v₀'−v₀, w₀'−w₀, v₁'−v₁, w₁'−w₁, v₂'−v₂, w₂'−w₂)` the seed writes six
linear equations

    x01 u3 − y01 u2 = 0                       x02 u5 − y02 u4 = 0
    x01 (u0 − u2) + y01 (u1 − u3) = B01       x02 (u0 − u4) + y02 (u1 − u5) = B02
    m0 u0 + m1 u2 + m2 u4 = 0                 m0 u1 + m1 u3 + m2 u5 = 0

with `B0k = (1 + ε)[x0k (vk − v0) + y0k (wk − w0)]`, and solves them by hand into the closed
form `collide2` (transcribed literally in `tests/law/seed_formulas.h`). Here we solve the
six equations numerically with GSL's LU decomposition and compare with `collide2` and with
relcol's K-contact solver `rc_contacts_resolve` (`papers/simultaneous-contacts.md`), which
writes the same conditions as a 2×2 system for the two normal impulses. Then: the
straight-back shot, order independence, and the relativistic rule at finite `c`.

(The seed's expanded fourth equation has a typo, `v'₁` where `v'₂` is meant, and its
`p'₂ = o₂` is `p'₂ = p₂`; the `u` form above, which we solve, is the correct one.)
*/
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_permutation.h>
#include <gsl/gsl_vector.h>

#include "nb.h"
#include "relcol/relcol.h"
#include "seed_formulas.h"

/*md
## The six equations, one example

Ball 0 (radius 1) moving at `(1, 0.2)` touches ball 1 (radius 0.8) at 35° and ball 2
(radius 1.2) at −50°, both moving slowly; `ε = 0.9`, masses `radius³` as in the seed.
@output one
*/
/* relcol's generator (relcol/rng.h), on the notebook's seed variable */
static double urand(unsigned long long *s)
{
    rc_rng r = {*s};
    const double u = rc_rng_uniform(&r);
    *s = r.state;
    return u;
}

/* Solve the seed's six equations for the velocity changes u[6] with GSL LU. */
static int solve6(const Ball b[3], double eps, double u[6])
{
    double m0 = pow(b[0].radius, 3), m1 = pow(b[1].radius, 3), m2 = pow(b[2].radius, 3);
    double x01 = b[1].x - b[0].x, y01 = b[1].y - b[0].y;
    double x02 = b[2].x - b[0].x, y02 = b[2].y - b[0].y;
    double B01 = (1 + eps) * (x01 * (b[1].v - b[0].v) + y01 * (b[1].w - b[0].w));
    double B02 = (1 + eps) * (x02 * (b[2].v - b[0].v) + y02 * (b[2].w - b[0].w));
    double A[36] = {
        0,   0,   -y01, x01,  0,    0,    /* ball 1's tangential velocity kept */
        0,   0,   0,    0,    -y02, x02,  /* ball 2's tangential velocity kept */
        x01, y01, -x01, -y01, 0,    0,    /* restitution along 0-1 */
        x02, y02, 0,    0,    -x02, -y02, /* restitution along 0-2 */
        m0,  0,   m1,   0,    m2,   0,    /* momentum x */
        0,   m0,  0,    m1,   0,    m2,   /* momentum y */
    };
    double rhs[6] = {0, 0, B01, B02, 0, 0};
    gsl_matrix_view Av = gsl_matrix_view_array(A, 6, 6);
    gsl_vector_view bv = gsl_vector_view_array(rhs, 6);
    gsl_vector_view xv = gsl_vector_view_array(u, 6);
    gsl_permutation *perm = gsl_permutation_alloc(6);
    int sgn, st = gsl_linalg_LU_decomp(&Av.matrix, perm, &sgn);
    if (st == GSL_SUCCESS)
        st = gsl_linalg_LU_solve(&Av.matrix, perm, &bv.vector, &xv.vector);
    gsl_permutation_free(perm);
    return st;
}

/* relcol's K-contact solver on the same three balls (classical when inv_c2 = 0);
 * velocities out in vout[3][2], impulses in J[2]. */
static int engine2(const Ball b[3], double eps, double inv_c2, double vout[3][2], double J[2])
{
    rc_particle P[3];
    for (int i = 0; i < 3; i++) {
        P[i].m = pow(b[i].radius, 3);
        int st = rc_momentum_from_velocity(P[i].m, rc_v3(b[i].v, b[i].w, 0), inv_c2, &P[i].p);
        if (st != RC_OK)
            return st;
    }
    rc_contact C[2];
    for (int k = 0; k < 2; k++) {
        rc_vec3 d = rc_v3(b[k + 1].x - b[0].x, b[k + 1].y - b[0].y, 0);
        C[k] = (rc_contact){0, k + 1, rc_v3_scale(1 / rc_v3_norm(d), d), eps, 0.0, {0, 0, 0}};
    }
    int st = rc_contacts_resolve(inv_c2, 3, P, 2, C, J);
    for (int i = 0; i < 3; i++) {
        rc_vec3 v = rc_velocity(P[i].m, P[i].p, inv_c2);
        vout[i][0] = v.x;
        vout[i][1] = v.y;
    }
    return st;
}

/* ball i at distance (r0 + ri) from ball 0 at angle ang: touching */
static Ball touching(const Ball *b0, double r, double ang, double v, double w)
{
    Ball b = {b0->x + (b0->radius + r) * cos(ang), b0->y + (b0->radius + r) * sin(ang), v, w, r};
    return b;
}

static void one(void)
{
    nb_section("one");
    const double eps = 0.9, deg = M_PI / 180;
    Ball b[3];
    b[0] = (Ball){0, 0, 1.0, 0.2, 1.0};
    b[1] = touching(&b[0], 0.8, 35 * deg, -0.1, 0.05);
    b[2] = touching(&b[0], 1.2, -50 * deg, 0.0, 0.1);
    double u[6], vout[3][2], J[2];
    int st6 = solve6(b, eps, u);
    Ball ref[3] = {b[0], b[1], b[2]};
    seed000_collide2(&ref[0], &ref[1], &ref[2], eps);
    int ste = engine2(b, eps, 0.0, vout, J);
    printf("ball   GSL 6x6 (v', w')            collide2 (v', w')           rc_contacts_resolve\n");
    double worst = 0;
    for (int i = 0; i < 3; i++) {
        double v6 = b[i].v + u[2 * i], w6 = b[i].w + u[2 * i + 1];
        printf("%d   (%11.8f, %11.8f)   (%11.8f, %11.8f)   (%11.8f, %11.8f)\n", i, v6, w6, ref[i].v,
               ref[i].w, vout[i][0], vout[i][1]);
        worst = fmax(worst, fmax(fabs(v6 - ref[i].v), fabs(w6 - ref[i].w)));
        worst = fmax(worst, fmax(fabs(vout[i][0] - ref[i].v), fabs(vout[i][1] - ref[i].w)));
    }
    printf("impulses J01 = %.10f, J02 = %.10f; largest difference %.2g\n", J[0], J[1], worst);
    NB_CHECK(st6 == GSL_SUCCESS && ste == RC_OK, "both solvers succeed");
    NB_CHECK(J[0] > 0 && J[1] > 0, "both contacts push");
    /* O(10) operations on O(1) velocities: a few 1e-16 each */
    NB_CHECK(worst < 1e-14, "GSL, collide2 and rc_contacts_resolve agree to round-off (%.2g)", worst);
}

/*md
## Random geometries and masses

20000 random draws: radii in [0.5, 1.5] (masses `r³` from 0.125 to 3.4, a factor 27),
contact angles uniform (rejecting placements where balls 1 and 2 overlap), velocities
uniform in [−1, 1]², `ε` uniform in [0, 1]; kept are the draws where ball 0 approaches both
balls (otherwise there is no double collision). The six equations and `collide2` impose both
restitution conditions whatever the signs of the impulses; `rc_contacts_resolve` refuses a
pulling impulse (it drops that contact and re-solves), so it is compared with the others only
where both impulses push.
@output random
*/
static void random_cases(void)
{
    nb_section("random");
    unsigned long long s = 3;
    int n = 0, both_push = 0, pulling = 0, fails = 0, not_approaching = 0;
    double worst6 = 0, worste = 0, worst_cond = 0, worst_ulps = 0;
    for (int t = 0; t < 20000; t++) {
        Ball b[3];
        b[0] = (Ball){0, 0, 2 * urand(&s) - 1, 2 * urand(&s) - 1, 0.5 + urand(&s)};
        for (int k = 1; k < 3; k++)
            b[k] = touching(&b[0], 0.5 + urand(&s), 2 * M_PI * urand(&s), 2 * urand(&s) - 1,
                            2 * urand(&s) - 1);
        if (hypot(b[2].x - b[1].x, b[2].y - b[1].y) < b[1].radius + b[2].radius)
            continue;
        double eps = urand(&s);
        /* the double collision is an event only if ball 0 approaches both */
        int appr = 1;
        for (int k = 1; k < 3; k++)
            if ((b[0].v - b[k].v) * (b[k].x - b[0].x) + (b[0].w - b[k].w) * (b[k].y - b[0].y) <= 0)
                appr = 0;
        if (!appr) {
            not_approaching++;
            continue;
        }
        n++;
        double u[6], vout[3][2], J[2];
        Ball ref[3] = {b[0], b[1], b[2]};
        seed000_collide2(&ref[0], &ref[1], &ref[2], eps);
        if (solve6(b, eps, u) != GSL_SUCCESS || engine2(b, eps, 0.0, vout, J) != RC_OK) {
            fails++;
            continue;
        }
        /* the 2x2 Delassus matrix's condition: 1/(1 - cos^2 of the normals' angle) at worst */
        double c01 = ((b[1].x - b[0].x) * (b[2].x - b[0].x) + (b[1].y - b[0].y) * (b[2].y - b[0].y)) /
                     (hypot(b[1].x - b[0].x, b[1].y - b[0].y) * hypot(b[2].x - b[0].x, b[2].y - b[0].y));
        double cond = 1 / (1 - c01 * c01);
        worst_cond = fmax(worst_cond, cond);
        double vscale = 0;
        for (int i = 0; i < 3; i++)
            vscale = fmax(vscale, hypot(b[i].v, b[i].w));
        for (int i = 0; i < 3; i++) {
            double e6 = fmax(fabs(b[i].v + u[2 * i] - ref[i].v), fabs(b[i].w + u[2 * i + 1] - ref[i].w));
            worst6 = fmax(worst6, e6 / vscale);
            worst_ulps = fmax(worst_ulps, e6 / vscale / (cond * 0x1.0p-52));
        }
        if (!(J[0] > 0 && J[1] > 0)) {
            pulling++;
            continue;
        }
        both_push++;
        for (int i = 0; i < 3; i++) {
            double ee = fmax(fabs(vout[i][0] - ref[i].v), fabs(vout[i][1] - ref[i].w));
            worste = fmax(worste, ee / vscale);
            worst_ulps = fmax(worst_ulps, ee / vscale / (cond * 0x1.0p-52));
        }
    }
    printf("%d approaching double collisions (%d not approaching both were skipped)\n", n, not_approaching);
    printf("both impulses push in %d; in %d the linear solution needs a pulling impulse\n", both_push, pulling);
    printf("largest |GSL 6x6 - collide2| / max|v|            = %.2g (all %d)\n", worst6, n);
    printf("largest |rc_contacts_resolve - collide2| / max|v| = %.2g (the %d pushing)\n", worste, both_push);
    printf("largest 1/(1 - cos^2 angle between the normals)   = %.3g\n", worst_cond);
    printf("largest difference in units of that factor times DBL_EPSILON: %.3g\n", worst_ulps);
    NB_CHECK(fails == 0, "every solve succeeded");
    /* Nearly opposite normals (ball 0 squeezed between 1 and 2) make the system nearly
     * singular: a solve's error is bounded by ~(number of operations, O(30)) x DBL_EPSILON x
     * the condition factor 1/(1 - cos^2) of the two normals. We check that bound per case
     * with the 30 (in practice the error is a few ulps, far below it). */
    NB_CHECK(worst_ulps < 30, "the three agree to round-off on every comparable case (%.3g of the bound)",
             worst_ulps / 30);
    NB_CHECK(both_push > n / 2 && pulling > 0, "both kinds of case occur (%d pushing, %d pulling)", both_push, pulling);
}

/*md
## Straight back

A ball moving along `x` into two equal balls at rest, touching them at ±30°: by symmetry
the two impulses are equal, their `y` parts cancel and ball 0 moves off along `x`. With the
classical solver the two conditions give `J (1 + 2 cos²30°) = (1 + ε) v cos 30°` (unit
masses), so `v₀' = (0.4 − 0.6 ε) v`: ball 0 comes straight **back** when `ε > 2/3`
(elastic: `−v/5`) and follows straight on when `ε < 2/3`. Resolving the two contacts one
after the other with the pair law instead (what an engine without grouping does) sends it
off at an angle, and the angle depends on which contact goes first.
@output straight
*/
static void sequential(const Ball b[3], double eps, int first, double out[2])
{
    rc_particle P[3];
    for (int i = 0; i < 3; i++)
        P[i] = (rc_particle){pow(b[i].radius, 3), rc_v3(pow(b[i].radius, 3) * b[i].v, pow(b[i].radius, 3) * b[i].w, 0)};
    rc_collision_params prm = rc_collision_params_default();
    prm.c = INFINITY;
    prm.eps = eps;
    for (int r = 0; r < 2; r++) {
        int k = r == 0 ? first : 3 - first;
        rc_vec3 d = rc_v3(b[k].x - b[0].x, b[k].y - b[0].y, 0);
        /* rc_collide leaves a separating pair alone */
        rc_collide(&rc_law_zmf, &prm, &P[0], &P[k], rc_v3_scale(1 / rc_v3_norm(d), d));
    }
    out[0] = P[0].p.x / P[0].m;
    out[1] = P[0].p.y / P[0].m;
}

static void straight_back(void)
{
    nb_section("straight");
    const double deg = M_PI / 180, v = 1.0;
    double worst_y = 0, worst_x = 0;
    printf("  eps   group v0' = (x, y)           predicted x   1 then 2: angle   2 then 1: angle\n");
    for (int e = 0; e <= 4; e++) {
        double eps = 0.25 * e;
        Ball b[3];
        b[0] = (Ball){0, 0, v, 0, 1};
        b[1] = touching(&b[0], 1, 30 * deg, 0, 0);
        b[2] = touching(&b[0], 1, -30 * deg, 0, 0);
        double vout[3][2], J[2], s12[2], s21[2];
        engine2(b, eps, 0.0, vout, J);
        sequential(b, eps, 1, s12);
        sequential(b, eps, 2, s21);
        double pred = (0.4 - 0.6 * eps) * v;
        printf("  %.2f  (%12.9f, %9.2g)   %12.9f   %8.3f deg       %8.3f deg\n", eps, vout[0][0], vout[0][1],
               pred, atan2(s12[1], s12[0]) / deg, atan2(s21[1], s21[0]) / deg);
        worst_y = fmax(worst_y, fabs(vout[0][1]));
        worst_x = fmax(worst_x, fabs(vout[0][0] - pred));
    }
    /* cos 30 deg is not exact in binary but enters both contacts identically: the y parts
     * cancel to a few ulps of v */
    NB_CHECK(worst_y < 1e-15 * v && worst_x < 1e-15 * v,
             "group: straight along x, v0' = (0.4 - 0.6 eps) v (worst y %.2g, worst x error %.2g)", worst_y, worst_x);

    /* relativistic: symmetric at 0.6 c too */
    double wy = 0;
    for (int e = 0; e <= 4; e++) {
        Ball b[3];
        b[0] = (Ball){0, 0, 0.6, 0, 1};
        b[1] = touching(&b[0], 1, 30 * deg, 0, 0);
        b[2] = touching(&b[0], 1, -30 * deg, 0, 0);
        double vout[3][2], J[2];
        engine2(b, 0.25 * e, 1.0, vout, J);
        wy = fmax(wy, fabs(vout[0][1]) + fabs(vout[1][1] + vout[2][1]) + fabs(J[0] - J[1]) / J[0]);
        if (e == 4)
            printf("at |v| = 0.6 c, eps = 1: v0' = (%.12f, %.2g) c, J = %.12f, %.12f\n", vout[0][0], vout[0][1],
                   J[0], J[1]);
    }
    NB_CHECK(wy < 1e-14, "at 0.6 c the group is symmetric too (asymmetry %.2g)", wy);
}

/*md
## Order independence

The group's equations are a set: listing the contacts in the other order, or numbering the
balls differently, changes only LU's pivot order. For each of 1000 random double collisions
we solve with contacts (01, 02), with (02, 01), and with the balls relabelled (2, 0, 1), at
`c = ∞` and at `c = 1` (speeds up to 0.8 c), and record the largest velocity difference.
The sequential pair rule, for contrast, gives results that depend on the order at O(1).
At `c = 1` we also check the rest-mass step of the rule (`papers/simultaneous-contacts.md`,
"Rest masses"): no ball's rest mass falls, the same groups made elastic keep every rest mass,
and we count the groups for which no such outcome exists (the engine then resolves the
contacts one at a time).
@output order
*/
static int solve_perm(const rc_particle in[3], const int lab[3], int swap, double inv_c2, double eps,
                      const rc_vec3 n[2], rc_particle out[3])
{
    /* ball i of the problem is slot lab[i] of the array */
    rc_particle P[3];
    for (int i = 0; i < 3; i++)
        P[lab[i]] = in[i];
    rc_contact C[2] = {{lab[0], lab[1], n[0], eps, 0.0, {0, 0, 0}},
                       {lab[0], lab[2], n[1], eps, 0.0, {0, 0, 0}}};
    if (swap) {
        rc_contact t = C[0];
        C[0] = C[1];
        C[1] = t;
    }
    double J[2];
    int st = rc_contacts_resolve(inv_c2, 3, P, 2, C, J);
    for (int i = 0; i < 3; i++)
        out[i] = P[lab[i]];
    return st;
}

static void order(void)
{
    nb_section("order");
    unsigned long long s = 17;
    double worst[2] = {0, 0}, seq_diff = 0, worst_m = 0;
    int fails = 0, infeasible = 0, heat_ok = 1;
    for (int t = 0; t < 1000; t++) {
        double ang1 = 2 * M_PI * urand(&s), ang2 = ang1 + (M_PI / 3 + (4 * M_PI / 3) * urand(&s));
        rc_vec3 n[2] = {rc_v3(cos(ang1), sin(ang1), 0), rc_v3(cos(ang2), sin(ang2), 0)};
        double eps = urand(&s);
        for (int rel = 0; rel < 2; rel++) {
            double k = rel ? 1.0 : 0.0;
            rc_particle in[3];
            for (int i = 0; i < 3; i++) {
                rc_vec3 v;
                do
                    v = rc_v3(1.6 * urand(&s) - 0.8, 1.6 * urand(&s) - 0.8, 0);
                while (rc_v3_norm(v) > 0.8);
                in[i].m = 0.5 + 2 * urand(&s);
                rc_momentum_from_velocity(in[i].m, v, k, &in[i].p);
            }
            rc_particle ref[3], a[3], b[3];
            int lab0[3] = {0, 1, 2}, lab1[3] = {2, 0, 1};
            int st0 = solve_perm(in, lab0, 0, k, eps, n, ref);
            int st1 = solve_perm(in, lab0, 1, k, eps, n, a);
            int st2 = solve_perm(in, lab1, 0, k, eps, n, b);
            if (st0 == RC_ENOCONVERGE && st1 == st0 && st2 == st0 && rel) {
                infeasible++; /* no rest-mass restoration: the engine goes one by one */
                continue;
            }
            if (st0 != RC_OK || st1 != RC_OK || st2 != RC_OK) {
                fails++;
                continue;
            }
            for (int i = 0; i < 3; i++) /* heat is never negative */
                heat_ok &= ref[i].m >= in[i].m * (1.0 - 1e-14);
            if (rel) { /* the same group elastic keeps every rest mass */
                rc_particle el[3];
                if (solve_perm(in, lab0, 0, k, 1.0, n, el) != RC_OK)
                    fails++;
                else
                    for (int i = 0; i < 3; i++)
                        worst_m = fmax(worst_m, fabs(el[i].m - in[i].m) / in[i].m);
            }
            for (int i = 0; i < 3; i++) {
                rc_vec3 v0 = rc_velocity(ref[i].m, ref[i].p, k);
                double da = rc_v3_norm(rc_v3_sub(rc_velocity(a[i].m, a[i].p, k), v0));
                double db = rc_v3_norm(rc_v3_sub(rc_velocity(b[i].m, b[i].p, k), v0));
                worst[rel] = fmax(worst[rel], fmax(da, db));
            }
            if (!rel) {
                Ball bb[3];
                for (int i = 0; i < 3; i++)
                    bb[i] = (Ball){0, 0, in[i].p.x / in[i].m, in[i].p.y / in[i].m, cbrt(in[i].m)};
                bb[1].x = n[0].x, bb[1].y = n[0].y, bb[2].x = n[1].x, bb[2].y = n[1].y;
                double s12[2], s21[2];
                sequential(bb, eps, 1, s12);
                sequential(bb, eps, 2, s21);
                seq_diff = fmax(seq_diff, hypot(s12[0] - s21[0], s12[1] - s21[1]));
            }
        }
    }
    printf("largest velocity change on reordering: classical %.2g, c = 1: %.2g (speeds <= 0.8)\n", worst[0],
           worst[1]);
    printf("sequential pair rule, 1-then-2 vs 2-then-1: ball 0 differs by up to %.3g\n", seq_diff);
    printf("c = 1: %d of 1000 groups cannot keep every rest mass from falling (the engine "
           "resolves those one contact at a time); elastic groups keep rest masses to %.1g\n",
           infeasible, worst_m);
    NB_CHECK(fails == 0, "all other solves succeeded, elastic ones included");
    NB_CHECK(infeasible < 50, "groups without a rest-mass-keeping outcome are rare (%d)",
             infeasible);
    NB_CHECK(heat_ok, "no ball's rest mass falls (no negative heat)");
    /* round-off of the ZMF round trip and of the energy match (8 ulps of the sum) */
    NB_CHECK(worst_m < 1e-13, "elastic groups keep every rest mass (%.2g)", worst_m);
    /* round-off of a 2x2 LU (classical) or ~5 Newton steps (c = 1) on O(1) velocities */
    NB_CHECK(worst[0] < 1e-14 && worst[1] < 1e-13, "order independent to round-off");
    NB_CHECK(seq_diff > 0.1, "the sequential rule is order dependent (%.3g)", seq_diff);
}

/*md
## The relativistic rule at finite `c`

At finite `c` each contact applies the four-impulse `J q`, `q = (u·n/c², n)`, with `u` its
pair's ZMF velocity, and Newton's method solves the two ZMF restitution conditions, quadratic
in `J` (`papers/simultaneous-contacts.md`). An independent check first: the same two
conditions solved by GSL's `multiroot` hybrid solver from the classical impulses, against
`rc_contacts_resolve`. Then the classical limit: for the example above (speeds scaled so that
the fastest ball moves at `v`) the relative velocity deviation from the classical solver,
against `v/c` over four decades, with the slope fitted by least squares on `log–log` axes.
@output rel
*/
typedef struct {
    rc_particle in[3];
    rc_vec3 n[2];
    double eps, k;
} relprob;

/* post-group states for impulses J: contact j gives ball j+1 +J q_j and ball 0 -J q_j */
static void apply(const relprob *q, const double J[2], double M[3], rc_vec3 p[3])
{
    for (int i = 0; i < 3; i++) {
        M[i] = rc_mass_rel(q->in[i].m, q->in[i].p, q->k);
        p[i] = q->in[i].p;
    }
    double M0 = M[0];
    rc_vec3 p0 = p[0];
    for (int j = 0; j < 2; j++) {
        double Mb = rc_mass_rel(q->in[j + 1].m, q->in[j + 1].p, q->k);
        rc_vec3 u = rc_v3_scale(1 / (M0 + Mb), rc_v3_add(p0, q->in[j + 1].p));
        double qt = rc_v3_dot(u, q->n[j]) * q->k; /* time part, as mass */
        M[0] -= J[j] * qt;
        p[0] = rc_v3_axpy(p[0], -J[j], q->n[j]);
        M[j + 1] += J[j] * qt;
        p[j + 1] = rc_v3_axpy(p[j + 1], J[j], q->n[j]);
    }
}

static int rel_f(const gsl_vector *x, void *params, gsl_vector *f)
{
    const relprob *q = params;
    double J[2] = {gsl_vector_get(x, 0), gsl_vector_get(x, 1)}, M[3];
    rc_vec3 p[3];
    apply(q, J, M, p);
    double M0 = rc_mass_rel(q->in[0].m, q->in[0].p, q->k);
    for (int j = 0; j < 2; j++) {
        double Mb = rc_mass_rel(q->in[j + 1].m, q->in[j + 1].p, q->k);
        /* a = (M_b p_a.n - M_a p_b.n)/(M_a + M_b) before; a' after; a' = -eps a */
        double a = (Mb * rc_v3_dot(q->in[0].p, q->n[j]) - M0 * rc_v3_dot(q->in[j + 1].p, q->n[j])) / (M0 + Mb);
        double a1 = (M[j + 1] * rc_v3_dot(p[0], q->n[j]) - M[0] * rc_v3_dot(p[j + 1], q->n[j])) / (M[0] + M[j + 1]);
        gsl_vector_set(f, (size_t)j, a1 + q->eps * a);
    }
    return GSL_SUCCESS;
}

static int multiroot2(relprob *q, const double J0[2], double J[2])
{
    gsl_multiroot_fsolver *s = gsl_multiroot_fsolver_alloc(gsl_multiroot_fsolver_hybrids, 2);
    gsl_multiroot_function F = {rel_f, 2, q};
    double x0[2] = {J0[0], J0[1]};
    gsl_vector_view xv = gsl_vector_view_array(x0, 2);
    gsl_multiroot_fsolver_set(s, &F, &xv.vector);
    int st = GSL_CONTINUE;
    for (int it = 0; it < 200 && st == GSL_CONTINUE; it++) {
        st = gsl_multiroot_fsolver_iterate(s);
        if (st)
            break;
        st = gsl_multiroot_test_residual(s->f, 1e-15);
    }
    J[0] = gsl_vector_get(s->x, 0);
    J[1] = gsl_vector_get(s->x, 1);
    gsl_multiroot_fsolver_free(s);
    return st;
}

static void relativistic(void)
{
    nb_section("rel");
    const double deg = M_PI / 180, eps = 0.9;
    /* the one-example geometry, masses radius^3 */
    Ball b[3];
    b[0] = (Ball){0, 0, 1.0, 0.2, 1.0};
    b[1] = touching(&b[0], 0.8, 35 * deg, -0.1, 0.05);
    b[2] = touching(&b[0], 1.2, -50 * deg, 0.0, 0.1);
    double vmax = hypot(1.0, 0.2);

    /* independent check at v = 0.8 c */
    {
        double k = 1 / (vmax / 0.8 * vmax / 0.8);
        relprob q;
        q.eps = eps;
        q.k = k;
        for (int i = 0; i < 3; i++) {
            q.in[i].m = pow(b[i].radius, 3);
            rc_momentum_from_velocity(q.in[i].m, rc_v3(b[i].v, b[i].w, 0), k, &q.in[i].p);
        }
        for (int j = 0; j < 2; j++) {
            rc_vec3 d = rc_v3(b[j + 1].x, b[j + 1].y, 0);
            q.n[j] = rc_v3_scale(1 / rc_v3_norm(d), d);
        }
        double vout[3][2], Jc[2], Jr[2], Jm[2];
        engine2(b, eps, 0.0, vout, Jc);
        engine2(b, eps, k, vout, Jr);
        int st = multiroot2(&q, Jc, Jm);
        double M[3];
        rc_vec3 p[3];
        apply(&q, Jr, M, p);
        double E0 = 0, E1 = 0;
        rc_vec3 P0 = rc_v3(0, 0, 0), P1 = rc_v3(0, 0, 0);
        for (int i = 0; i < 3; i++) {
            E0 += rc_mass_rel(q.in[i].m, q.in[i].p, k);
            E1 += M[i];
            P0 = rc_v3_add(P0, q.in[i].p);
            P1 = rc_v3_add(P1, p[i]);
        }
        printf("fastest ball at 0.8 c: classical J = (%.10f, %.10f)\n", Jc[0], Jc[1]);
        printf("  rc_contacts_resolve   J = (%.12f, %.12f)\n", Jr[0], Jr[1]);
        printf("  GSL multiroot         J = (%.12f, %.12f)  (%s)\n", Jm[0], Jm[1], gsl_strerror(st));
        printf("  energy change %.2g, momentum change %.2g (of E = %.4f)\n", E1 - E0,
               rc_v3_norm(rc_v3_sub(P1, P0)), E0);
        NB_CHECK(st == GSL_SUCCESS, "multiroot converged");
        /* residual test 1e-15 on O(1) conditions with an O(1) Jacobian: J to ~1e-14 */
        NB_CHECK(fabs(Jm[0] - Jr[0]) < 1e-13 * Jr[0] && fabs(Jm[1] - Jr[1]) < 1e-13 * Jr[1],
                 "rc_contacts_resolve solves the relativistic conditions (multiroot agrees)");
        NB_CHECK(fabs(E1 - E0) < 1e-14 * E0 && rc_v3_norm(rc_v3_sub(P1, P0)) < 1e-14 * E0,
                 "four-momentum conserved");
        NB_CHECK(fabs(Jr[0] - Jc[0]) > 1e-3 * Jc[0], "at 0.8 c the impulses differ from the classical ones");
    }

    double cl[3][2], Jc[2];
    engine2(b, eps, 0.0, cl, Jc);
    FILE *d = nb_figure_begin("double-collision-limit");
    double xs[64], ys[64];
    int nfit = 0;
    for (int i = 0; i <= 32; i++) {
        double beta = pow(10.0, -0.125 * i) * 0.9; /* v/c from 0.9 down to 9e-5 */
        double c = vmax / beta;
        double vout[3][2], J[2];
        engine2(b, eps, 1 / (c * c), vout, J);
        double dev = 0;
        for (int k = 0; k < 3; k++)
            dev = fmax(dev, hypot(vout[k][0] - cl[k][0], vout[k][1] - cl[k][1]) / vmax);
        if (d)
            fprintf(d, "%.6g %.6g %.6g\n", beta, dev, beta * beta);
        if (beta <= 1e-2 && nfit < 64) { /* the asymptotic range, above round-off (dev >~ 1e-9) */
            xs[nfit] = log10(beta);
            ys[nfit] = log10(dev);
            nfit++;
        }
        if (i == 0 || i == 8 || i == 16 || i == 24 || i == 32)
            printf("v/c = %-9.3g  max |v'(c) - v'(inf)| / v = %.4g   ratio to (v/c)^2 = %.4f\n", beta, dev,
                   dev / (beta * beta));
    }
    double c0, c1, cov00, cov01, cov11, sumsq;
    gsl_fit_linear(xs, 1, ys, 1, (size_t)nfit, &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
    printf("least-squares slope of log dev vs log(v/c) over v/c in [9e-5, 1e-2] (%d points): %.5f\n", nfit, c1);
    nb_figure_end(d, "double-collision-limit",
                  "set logscale xy\nset format y '10^{%L}'\nset format x '10^{%L}'\n"
                  "set xlabel 'v / c (fastest ball)'\n"
                  "set ylabel 'max velocity deviation from the classical solver / v'\n"
                  "set key top left\nset grid\n"
                  "plot datafile u 1:2 w lp pt 7 t 'rc\\_contacts\\_resolve, double collision, ε = 0.9', "
                  "'' u 1:3 w l dt 2 t '(v/c)^2'\n");
    /* (v/c)^2 leading term, next term (v/c)^4: over this range the slope is 2 to ~1e-4; the
     * tolerance leaves room for round-off at the small end (dev ~ 1e-8, errors ~1e-15) */
    NB_CHECK(fabs(c1 - 2) < 0.01, "deviation falls as (v/c)^2 (fitted slope %.4f)", c1);
}

int main(int argc, char **argv)
{
    nb_init(argc, argv);
    gsl_set_error_handler_off();
    one();
    random_cases();
    straight_back();
    order();
    relativistic();
    return nb_finish();
}
