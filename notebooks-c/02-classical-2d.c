/*md
# 2. The classical 2-D collision: three seeds, one law

Three of the seeds derive the same thing, the outcome of a frictionless collision of two
discs in the plane, in three different ways:

- **seed 000, part 3** rotates into the frame of ball 2 aligned with the line of centres,
  solves the 1-D problem there and rotates back, ending with the symmetric form
  `v₁' = v₁ − m₂ a n̂`, `v₂' = v₂ + m₁ a n̂`, `a = (1 + c)/(m₁ + m₂) · (v₁ − v₂)·n̂`
  (its `c` is the restitution, our `ε`; its masses are `radius³`);
- **seed 001** (equal masses, elastic) projects the relative velocity on the line of
  centres with a dot product: `Δv = [(v₂ − v₁)·d / d²] d`, added to ball 1 and taken from
  ball 2, and only when that dot product says the balls approach;
- **seed 002** writes the outcome in terms of an *impact angle* `α` between the relative
  velocity and the line of centres, eqs. (8)–(13) with `a = tan(γ_v + α)`, and makes it
  inelastic by scaling the whole centre-of-mass velocity by `R`, eqs. (22)–(27).

The seeds' code is used as transcribed literally in `tests/law/seed_formulas.h` (the same
functions `test_law_seeds` runs). Here we check that the three forms agree with each other,
with relcol's `zmf` law at `c = ∞`, and (for seed 002 with its own `α`) with relcol's
`cm-isotropic` law; that the two inelastic generalisations are *different* laws, and by how
much; and finally where relativity departs from all of them.

Notation: our ball 0 is the seeds' ball 1, `n` the unit normal from ball 0 to ball 1,
`ε` the restitution.
*/
#include <math.h>
#include <stdio.h>

#include "nb.h"
#include "relcol/relcol.h"
#include "seed_formulas.h"

/*md
## Putting the seeds on one footing

Each form wants its input its own way: seed 000 positions (the normal is
`atan2(y₁ − y₂, x₁ − x₂)`) and radii (mass = radius³), seed 001 positions closer than a
diameter, seed 002 the impact angle. The helpers below place the balls at contact along a
given normal and hand each form what it asks for. For seed 002 the impact angle comes from
its own geometry, eqs. (14)–(16) at contact (`d = r₁ + r₂`), written with `atan2` where the
seed writes `arctan`: the seed's (7) and (9) only need `γ_v` modulo π, but (14) needs the
quadrant.
*/
typedef struct {
    double m[2]; /* masses: radius^3, as seed 000 wants */
    double r[2]; /* radii */
    rc_vec3 v[2];
    rc_vec3 n;   /* unit normal from ball 0 to ball 1 at contact */
} pair2d;

typedef struct {
    rc_vec3 v[2];
} outcome;

static pair2d make_pair(double r0, double r1, rc_vec3 v0, rc_vec3 v1, rc_vec3 n)
{
    pair2d P = {{pow(r0, 3), pow(r1, 3)}, {r0, r1}, {v0, v1}, n};
    return P;
}

static outcome by_seed000(const pair2d *P, double eps)
{
    double R = P->r[0] + P->r[1];
    Ball b0 = {0.0, 0.0, P->v[0].x, P->v[0].y, P->r[0]};
    Ball b1 = {R * P->n.x, R * P->n.y, P->v[1].x, P->v[1].y, P->r[1]};
    seed000_collide(&b0, &b1, eps);
    outcome o = {{rc_v3(b0.v, b0.w, 0), rc_v3(b1.v, b1.w, 0)}};
    return o;
}

/* Seed 001 only knows equal masses and eps = 1; the balls overlap by 0.1% of a diameter,
 * because the seed acts only when d^2 < diameter^2. */
static outcome by_seed001(const pair2d *P)
{
    double diameter = 2.0 * P->r[0];
    diameter2 = diameter * diameter;
    particles[0] = (particle001){0.0, 0.0, P->v[0].x, P->v[0].y};
    particles[1] = (particle001){0.999 * diameter * P->n.x, 0.999 * diameter * P->n.y, P->v[1].x,
                                 P->v[1].y};
    collision(0, 1);
    outcome o = {{rc_v3(particles[0].vx, particles[0].vy, 0), rc_v3(particles[1].vx, particles[1].vy, 0)}};
    return o;
}

/* Seed 002's impact angle from the positions at contact, eqs. (14)-(16) with atan2. */
static double seed002_alpha(const pair2d *P)
{
    double R = P->r[0] + P->r[1];
    double x2 = R * P->n.x, y2 = R * P->n.y; /* the seed's ball 2 (our 1); its ball 1 at 0 */
    double d = sqrt(x2 * x2 + y2 * y2);                             /* (15) */
    double gamma_xy = atan2(y2, x2);                                /* (16) */
    double gamma_v = atan2(P->v[0].y - P->v[1].y, P->v[0].x - P->v[1].x); /* (7) */
    return asin(d * sin(gamma_xy - gamma_v) / R);                   /* (14) */
}

static outcome by_seed002(const pair2d *P, double R)
{
    vel002 in = {P->v[0].x, P->v[0].y, P->v[1].x, P->v[1].y};
    vel002 out = seed002(P->m[0], P->m[1], in, seed002_alpha(P), R);
    outcome o = {{rc_v3(out.vx1, out.vy1, 0), rc_v3(out.vx2, out.vy2, 0)}};
    return o;
}

/* relcol: law at 1/c^2 = k, table-frame normal n (alpha = NAN) or the impact angle alpha. */
static outcome by_relcol(const rc_law *law, const pair2d *P, double eps, double k, double alpha,
                         int *status)
{
    rc_particle a = {P->m[0], {0, 0, 0}}, b = {P->m[1], {0, 0, 0}};
    rc_momentum_from_velocity(a.m, P->v[0], k, &a.p);
    rc_momentum_from_velocity(b.m, P->v[1], k, &b.p);
    rc_collision_params prm = rc_collision_params_default();
    prm.c = (k > 0.0 ? 1.0 / sqrt(k) : INFINITY) /* the c of 1/c^2 = k */;
    prm.eps = eps;
    prm.alpha = alpha;
    prm.azimuth = 0.0;
    int st = rc_collide(law, &prm, &a, &b, P->n);
    if (status)
        *status = st;
    outcome o = {{rc_velocity(a.m, a.p, k), rc_velocity(b.m, b.p, k)}};
    return o;
}

/* Largest velocity difference of two outcomes, over both balls and components. */
static double diff(outcome x, outcome y)
{
    return fmax(rc_v3_norm(rc_v3_sub(x.v[0], y.v[0])), rc_v3_norm(rc_v3_sub(x.v[1], y.v[1])));
}

static double vscale(const pair2d *P) { return fmax(rc_v3_norm(P->v[0]), rc_v3_norm(P->v[1])); }

/*md
## One collision, five ways

Two equal discs (radius 1, mass 1), ball 0 moving at `(0.8, 0.1)`, ball 1 at `(−0.2, 0.3)`,
touching along `n = (0.8, 0.6)`; elastic. Seed 001 applies, so all five agree:
@output one
*/
static void print_outcome(const char *name, outcome o)
{
    printf("%-28s (%+.15f, %+.15f)  (%+.15f, %+.15f)\n", name, o.v[0].x, o.v[0].y, o.v[1].x, o.v[1].y);
}

static void one(void)
{
    nb_section("one");
    pair2d P = make_pair(1.0, 1.0, rc_v3(0.8, 0.1, 0), rc_v3(-0.2, 0.3, 0), rc_v3(0.8, 0.6, 0));
    printf("impact angle from (14): alpha = %.15f rad\n", seed002_alpha(&P));
    printf("%-28s %-38s  %s\n", "form", "ball 0 after", "ball 1 after");
    outcome o0 = by_seed000(&P, 1.0), o1 = by_seed001(&P), o2 = by_seed002(&P, 1.0);
    outcome oz = by_relcol(&rc_law_zmf, &P, 1.0, 0.0, NAN, NULL);
    outcome oc = by_relcol(&rc_law_cm_isotropic, &P, 1.0, 0.0, seed002_alpha(&P), NULL);
    print_outcome("seed 000 part 3 collide", o0);
    print_outcome("seed 001 collision", o1);
    print_outcome("seed 002 (8)-(13),(22)-(27)", o2);
    print_outcome("relcol zmf, c = inf", oz);
    print_outcome("relcol cm-isotropic, alpha", oc);
    double worst = fmax(fmax(diff(o0, oz), diff(o1, oz)), fmax(diff(o2, oz), diff(oc, oz)));
    printf("largest difference from zmf: %.3g\n", worst);
    /* speeds ~1, each form a dozen roundings (seed 002 also a tan and an atan2): 1e-14 */
    NB_CHECK(worst < 1e-14, "the five outcomes agree to round-off");
}

/*md
## Random collisions, elastic and inelastic

20 000 random oblique collisions at `c = ∞`: radii in [0.5, 2] (masses over a factor 64),
speeds up to 1, random contact normal with the balls approaching along it, and `ε` in
[0, 1] (a tenth exactly 0, a tenth exactly 1). For each we compare

- seed 000 with relcol's `zmf` law (both: the normal relative velocity is scaled by `−ε`);
- seed 002 with relcol's `cm-isotropic` law given seed 002's `α` (both: the whole ZMF
  velocity is scaled by `R = ε`);
- seed 000 with seed 002 when `ε = 1` (elastic: the two generalisations coincide), and
  head-on (all the ZMF velocity is normal: they coincide at every `ε`);
- equal-mass elastic pairs: seed 001 with seed 000 and `zmf`.

For `ε < 1` the two generalisations differ. In the ZMF ball 0 moves at `w = w_n + w_t`;
seed 000 returns `w_t − ε w_n`, seed 002 `R(w_t − w_n)`. Their difference is
`(R − 1) w_t` for ball 0 (and the mass-weighted opposite for ball 1), which we also check.
Seed 002 is ill-conditioned in two places. Its `a = tan(γ_v + α)` loses digits as the
normal approaches the y axis (`a → ∞`), and its (14), `α = arcsin(…)`, near grazing: a
round-off `δ` in `sin α` moves `α` by `δ/cos α`, and the outcome by `|w| δ/cos α` (at
`cos α = 1.6·10⁻⁴` we saw `7·10⁻¹³`). So its cases keep `|cos θ| ≥ 0.01` (as
`test_law_seeds` does) and `cos α ≥ 0.01`; `cm-isotropic` fed the same `α` shares the
second loss, so it agrees with seed 002 even there.
Differences are relative to the largest speed.
@output random
*/
/* relcol's generator (relcol/rng.h), on the notebook's seed variable */
static double urand(unsigned long long *s)
{
    rc_rng r = {*s};
    const double u = rc_rng_uniform(&r);
    *s = r.state;
    return u;
}

static rc_vec3 rdisc(unsigned long long *s)
{
    rc_vec3 v;
    do {
        v = rc_v3(2 * urand(s) - 1, 2 * urand(s) - 1, 0);
    } while (rc_v3_norm2(v) > 1);
    return v;
}

static void random_cases(void)
{
    nb_section("random");
    unsigned long long s = 2002;
    double w_000_zmf = 0, w_002_cm = 0, w_000_002_el = 0, w_000_002_ho = 0, w_split = 0;
    double w_001 = 0, gap_inel = 0;
    long n_002 = 0, n_el = 0, n_ho = 0, n_001 = 0, n_inel = 0;
    for (int i = 0; i < 20000; i++) {
        double r0 = 0.5 * pow(4.0, urand(&s)), r1 = 0.5 * pow(4.0, urand(&s));
        if (i % 4 == 3)
            r1 = r0; /* equal masses, for seed 001 */
        rc_vec3 v0 = rdisc(&s), v1 = rdisc(&s), w = rc_v3_sub(v0, v1);
        if (rc_v3_norm(w) < 1e-3)
            continue;
        rc_vec3 n;
        int head_on = i % 20 == 7;
        if (head_on) {
            n = rc_v3_scale(1.0 / rc_v3_norm(w), w);
        } else {
            double phi = 2 * M_PI * urand(&s);
            n = rc_v3(cos(phi), sin(phi), 0);
            if (rc_v3_dot(w, n) < 0)
                n = rc_v3_scale(-1.0, n);
        }
        double u = urand(&s), eps = u < 0.1 ? 0.0 : (u < 0.2 ? 1.0 : urand(&s));
        pair2d P = make_pair(r0, r1, v0, v1, n);
        double sc = vscale(&P);
        int st;
        outcome o0 = by_seed000(&P, eps), oz = by_relcol(&rc_law_zmf, &P, eps, 0.0, NAN, &st);
        if (st != RC_OK)
            continue; /* grazing to round-off: no collision */
        w_000_zmf = fmax(w_000_zmf, diff(o0, oz) / sc);
        if (i % 4 == 3 && eps == 1.0) {
            outcome o1 = by_seed001(&P);
            w_001 = fmax(w_001, fmax(diff(o1, o0), diff(o1, oz)) / sc);
            n_001++;
        }
        double theta = atan2(n.y, n.x);
        if (fabs(cos(theta)) < 0.01 || rc_v3_dot(w, n) < 0.01 * rc_v3_norm(w))
            continue;
        n_002++;
        double alpha = seed002_alpha(&P);
        outcome o2 = by_seed002(&P, eps), oc = by_relcol(&rc_law_cm_isotropic, &P, eps, 0.0, alpha, NULL);
        w_002_cm = fmax(w_002_cm, diff(o2, oc) / sc);
        if (eps == 1.0) {
            w_000_002_el = fmax(w_000_002_el, diff(o0, o2) / sc);
            n_el++;
        }
        if (head_on) {
            w_000_002_ho = fmax(w_000_002_ho, diff(o0, o2) / sc);
            n_ho++;
        }
        /* (R - 1) w_t for ball 0: w = v0 - v_cm, w_t its part across n */
        rc_vec3 vcm = rc_v3_scale(1.0 / (P.m[0] + P.m[1]), rc_v3_add(rc_v3_scale(P.m[0], v0), rc_v3_scale(P.m[1], v1)));
        rc_vec3 w0 = rc_v3_sub(v0, vcm), wt = rc_v3_axpy(w0, -rc_v3_dot(w0, n), n);
        rc_vec3 pred = rc_v3_scale(eps - 1.0, wt);
        w_split = fmax(w_split, rc_v3_norm(rc_v3_sub(rc_v3_sub(o2.v[0], o0.v[0]), pred)) / sc);
        if (eps < 0.9 && !head_on) {
            gap_inel = fmax(gap_inel, diff(o0, o2) / sc);
            n_inel++;
        }
    }
    printf("cases: %ld with seed 002, %ld elastic, %ld head-on, %ld seed 001, %ld with eps < 0.9\n",
           n_002, n_el, n_ho, n_001, n_inel);
    printf("max |seed 000 - zmf|                 = %.3g\n", w_000_zmf);
    printf("max |seed 001 - seed 000, zmf|       = %.3g\n", w_001);
    printf("max |seed 002 - cm-isotropic(alpha)| = %.3g\n", w_002_cm);
    printf("max |seed 000 - seed 002|, elastic   = %.3g\n", w_000_002_el);
    printf("max |seed 000 - seed 002|, head-on   = %.3g\n", w_000_002_ho);
    printf("max |(002 - 000) - (R - 1) w_t|      = %.3g\n", w_split);
    printf("but max |seed 000 - seed 002| with eps < 0.9, oblique = %.3g: different laws\n", gap_inel);
    /* speeds <= 1, a dozen roundings each: 1e-14 (~45 ulp). Seed 002 goes through
     * tan(gamma_v + alpha) with |a| up to 100 (|cos theta| >= 0.01): ~eps |a| relative,
     * hence 1e-13 where it is involved (as test_law_seeds). */
    NB_CHECK(w_000_zmf < 1e-14, "seed 000 = zmf at c = inf, every eps");
    /* (seed 001 cases: a quarter of 20000 have equal masses, a tenth of those are elastic,
     * so 500 +- 21 expected; 400 is five deviations below) */
    NB_CHECK(n_001 > 400 && w_001 < 1e-14, "seed 001 = seed 000 = zmf (equal masses, elastic)");
    NB_CHECK(n_002 > 15000 && w_002_cm < 1e-13, "seed 002 = cm-isotropic with seed 002's alpha");
    NB_CHECK(n_el > 1000 && w_000_002_el < 1e-13, "seed 000 = seed 002 when elastic");
    NB_CHECK(n_ho > 500 && w_000_002_ho < 1e-13, "seed 000 = seed 002 head-on, every eps");
    NB_CHECK(w_split < 1e-13, "inelastic: seed 002 - seed 000 = (R - 1) w_t exactly");
    NB_CHECK(gap_inel > 0.1, "the inelastic generalisations are different laws");
}

/*md
## Deflection against impact parameter, and where relativity departs

Ball 1 (radius 1, mass 1) at rest; ball 0, the same, arrives along `x` at speed `v` with
impact parameter `b`, so at contact `n = (√(1 − s²), s)`, `s = b/(r₀ + r₁)`. Ball 0 is
deflected by the angle `θ₀` below the `x` axis.

Classically, for equal elastic discs the two balls leave at right angles: `θ₀ = 90° −
arcsin s`, whatever the form. For `ε < 1` seed 000 (and `zmf`) keep ball 0's tangential
velocity and return only part of the normal one; seed 002 (and `cm-isotropic`) shrink both,
so its ball 0 is deflected less.

Relativistically (`zmf` law, same table-frame normal) the opening angle closes: for an
elastic collision of equal rest masses with one at rest, energy–momentum conservation gives
`tan θ₀ tan θ₁ = 2/(γ + 1)` (γ of the incoming ball), which we check to round-off at
`c = 2v` (`γ = 1.1547`). The normal is held fixed here so that only the law is
relativistic; the contracted contact geometry moves the normal itself at order `(v/c)²`
(notebook 5).
@output deflection
*/
static double deflection0(outcome o) { return -atan2(o.v[0].y, o.v[0].x) * 180.0 / M_PI; }

static void deflection(void)
{
    nb_section("deflection");
    const double v = 0.5;
    FILE *d = nb_figure_begin("classical-2d-deflection");
    double worst_classic = 0, worst_tan = 0, worst_forms = 0;
    double k2 = 1.0 / (4 * v * v); /* c = 2v */
    double gam = 1.0 / sqrt(1.0 - v * v * k2);
    for (int j = 1; j <= 99; j++) {
        double sj = j / 100.0;
        pair2d P = make_pair(1.0, 1.0, rc_v3(v, 0, 0), rc_v3(0, 0, 0), rc_v3(sqrt(1 - sj * sj), sj, 0));
        outcome e0 = by_seed000(&P, 1.0), e1 = by_seed001(&P), e2 = by_seed002(&P, 1.0);
        outcome ez = by_relcol(&rc_law_zmf, &P, 1.0, 0.0, NAN, NULL);
        outcome i0 = by_seed000(&P, 0.5), i2 = by_seed002(&P, 0.5);
        outcome iz = by_relcol(&rc_law_zmf, &P, 0.5, 0.0, NAN, NULL);
        outcome ic = by_relcol(&rc_law_cm_isotropic, &P, 0.5, 0.0, seed002_alpha(&P), NULL);
        outcome rz = by_relcol(&rc_law_zmf, &P, 1.0, k2, NAN, NULL);
        outcome rzi = by_relcol(&rc_law_zmf, &P, 0.5, k2, NAN, NULL);
        double want = 90.0 - asin(sj) * 180.0 / M_PI;
        worst_classic = fmax(worst_classic, fmax(fabs(deflection0(e0) - want),
                                                 fmax(fabs(deflection0(e1) - want), fabs(deflection0(e2) - want))));
        worst_forms = fmax(worst_forms, fmax(fabs(deflection0(i0) - deflection0(iz)),
                                             fabs(deflection0(i2) - deflection0(ic))));
        double t0 = -rz.v[0].y / rz.v[0].x, t1 = rz.v[1].y / rz.v[1].x;
        worst_tan = fmax(worst_tan, fabs(t0 * t1 - 2.0 / (gam + 1.0)) / (2.0 / (gam + 1.0)));
        if (d)
            fprintf(d, "%.4f %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g %.10g\n", sj,
                    deflection0(e0), deflection0(e1), deflection0(e2), deflection0(ez), deflection0(i0),
                    deflection0(iz), deflection0(i2), deflection0(ic), deflection0(rz), deflection0(rzi));
        if (j == 50)
            printf("s = 0.50, eps = 1:   theta0 = %.6f deg classically, %.6f deg at c = 2v\n"
                   "s = 0.50, eps = 0.5: theta0 = %.6f (seed 000), %.6f (seed 002) classically, "
                   "%.6f deg (zmf) at c = 2v\n",
                   deflection0(ez), deflection0(rz), deflection0(i0), deflection0(i2), deflection0(rzi));
    }
    printf("elastic, c = inf: max |theta0 - (90 - asin s)| over the three seeds = %.3g deg\n", worst_classic);
    printf("eps = 0.5: max |seed 000 - zmf|, |seed 002 - cm-isotropic| = %.3g deg\n", worst_forms);
    printf("c = 2v: max relative error of tan(theta0) tan(theta1) = 2/(gamma+1) = %.6f: %.3g\n",
           2.0 / (gam + 1.0), worst_tan);
    /* Ball 0's outgoing velocity is v minus an O(v) impulse: at s = 0.01 it is ~ s v and its
     * x component ~ s^2 v, so its direction carries ~ DBL_EPSILON / s^2 = 2e-12 relative
     * round-off: allow 1e-11 (degrees, and relative for the tangent product). */
    NB_CHECK(worst_classic < 1e-11, "classical elastic: right-angle rule for all three seeds");
    NB_CHECK(worst_forms < 1e-11, "inelastic deflections: seed 000 = zmf, seed 002 = cm-isotropic");
    NB_CHECK(worst_tan < 1e-11, "relativistic elastic: tan(theta0) tan(theta1) = 2/(gamma + 1)");
    nb_figure_end(d, "classical-2d-deflection",
                  "set terminal pngcairo size 1100,480 enhanced font ',11'\n"
                  "set multiplot layout 1,2\n"
                  "set xlabel 'impact parameter b / (r_0 + r_1)'\nset ylabel 'deflection of ball 0, θ_0 (degrees)'\n"
                  "set grid\nset key top right font ',10' spacing 1.1\nset yrange [0:140]\nset ytics 0,10,90\n"
                  "set title 'c = ∞: the three seeds and relcol'\n"
                  "plot datafile u 1:5 w l lw 6 lc rgb '#bbbbbb' t 'relcol zmf, ε = 1 and 0.5', "
                  "'' every 6 u 1:2 w p pt 6 ps 1.2 lc rgb '#1f77b4' t 'seed 000 collide', "
                  "'' every 6::2 u 1:3 w p pt 4 ps 1.2 lc rgb '#d62728' t 'seed 001 collision', "
                  "'' every 6::4 u 1:4 w p pt 8 ps 1.2 lc rgb '#2ca02c' t 'seed 002 (8)-(13)', "
                  "'' u 1:7 w l lw 6 lc rgb '#bbbbbb' dt 1 notitle, "
                  "'' every 6 u 1:6 w p pt 7 ps 0.9 lc rgb '#1f77b4' t 'seed 000, ε = 0.5 (= zmf)', "
                  "'' u 1:9 w l lw 2 lc rgb '#2ca02c' dt 2 t 'relcol cm-isotropic, R = 0.5', "
                  "'' every 6::3 u 1:8 w p pt 9 ps 1.2 lc rgb '#2ca02c' t 'seed 002, R = 0.5'\n"
                  "set key top right font ',11'\nset yrange [0:95]\n"
                  "set title 'relcol zmf law: c = ∞ against c = 2v (same normal)'\n"
                  "plot datafile u 1:5 w l lw 2 lc rgb '#1f77b4' t 'c = ∞, ε = 1', "
                  "'' u 1:10 w l lw 2 lc rgb '#d62728' t 'c = 2v, ε = 1', "
                  "'' u 1:7 w l lw 2 dt 2 lc rgb '#1f77b4' t 'c = ∞, ε = 0.5', "
                  "'' u 1:11 w l lw 2 dt 2 lc rgb '#d62728' t 'c = 2v, ε = 0.5'\n"
                  "unset multiplot\n");
}

/*md
## How fast relativity fades

The change of `θ₀` from its classical value, at `s = 0.5`, against `c/v`. The law's
corrections are even in `1/c`, so the change should vanish as `(v/c)²`; the fitted slope
over `c/v ∈ [10, 1000]` checks it.
@output limit
*/
static void limit(void)
{
    nb_section("limit");
    const double v = 0.5, sj = 0.5;
    pair2d P = make_pair(1.0, 1.0, rc_v3(v, 0, 0), rc_v3(0, 0, 0), rc_v3(sqrt(1 - sj * sj), sj, 0));
    double th_inf[2] = {deflection0(by_relcol(&rc_law_zmf, &P, 1.0, 0.0, NAN, NULL)),
                        deflection0(by_relcol(&rc_law_zmf, &P, 0.5, 0.0, NAN, NULL))};
    FILE *d = nb_figure_begin("classical-2d-limit");
    double sx = 0, sy[2] = {0, 0}, sxx = 0, sxy[2] = {0, 0};
    int n = 0;
    printf("   c/v     dtheta0 (eps = 1)   dtheta0 (eps = 0.5)   [degrees]\n");
    for (int j = 0; j <= 30; j++) {
        double cv = pow(10.0, 0.1 * j + 0.1); /* 1.26 .. 1260 */
        double c = cv * v, k = 1.0 / (c * c), dth[2];
        for (int e = 0; e < 2; e++)
            dth[e] = fabs(deflection0(by_relcol(&rc_law_zmf, &P, e ? 0.5 : 1.0, k, NAN, NULL)) - th_inf[e]);
        if (d)
            fprintf(d, "%.6g %.10g %.10g\n", cv, dth[0], dth[1]);
        if (j % 5 == 0)
            printf("%8.2f  %16.6e  %18.6e\n", cv, dth[0], dth[1]);
        if (cv >= 10 && cv <= 1000) {
            double x = log(cv);
            sx += x;
            sxx += x * x;
            for (int e = 0; e < 2; e++) {
                sy[e] += log(dth[e]);
                sxy[e] += x * log(dth[e]);
            }
            n++;
        }
    }
    double slope[2];
    for (int e = 0; e < 2; e++)
        slope[e] = (n * sxy[e] - sx * sy[e]) / (n * sxx - sx * sx);
    printf("fitted slope of log dtheta0 against log(c/v), c/v in [10, 1000]: %.4f (eps = 1), %.4f (eps = 0.5)\n",
           slope[0], slope[1]);
    /* the next term is (v/c)^4, 1% of the leading one at c = 10v: slopes within 0.02 of -2 */
    NB_CHECK(fabs(slope[0] + 2) < 0.02 && fabs(slope[1] + 2) < 0.02, "relativistic change vanishes as (v/c)^2");
    nb_figure_end(d, "classical-2d-limit",
                  "set logscale xy\nset format y '10^{%L}'\nset format x '10^{%L}'\n"
                  "set xrange [1:2000]\nset xlabel 'c / v'\nset ylabel '|θ_0(c) - θ_0(∞)| (degrees)'\nset grid\nset key top right\n"
                  "plot datafile u 1:2 w lp pt 7 lw 2 t 'zmf, ε = 1', '' u 1:3 w lp pt 5 lw 2 t 'zmf, ε = 0.5', "
                  "'' u 1:(30*($1)**-2) w l dt 2 lc rgb 'black' t '∝ (v/c)^2'\n");
}

int main(int argc, char **argv)
{
    nb_init(argc, argv);
    one();
    random_cases();
    deflection();
    limit();
    return nb_finish();
}
