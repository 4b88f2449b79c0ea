/* test_gas1d_mechanics.c — the 1-D gas engine: input checks, conservation bookkeeping
 * over >= 1e6 collisions, every event against a brute-force all-pairs prediction, the
 * classical limit, equal masses only exchanging momenta, ties, determinism, and the
 * worldline segments that rebuild every particle's path. */
#include <stdlib.h>
#include <string.h>

#include "gas1d_util.h"

/* ---------------------------------------------------------------- helpers */

static double energy(size_t n, const double *m, const double *p, double inv_c2)
{
    /* sum of kinetic energies: finite at c = inf, and for c = 1 it is E - sum m with the
     * rest masses constant (elastic), so the relative error is not diluted by m c^2 */
    double e = 0.0;
    for (size_t i = 0; i < n; i++)
        e += rc_kinetic_energy(m[i], rc_v3(p[i], 0, 0), inv_c2);
    return e;
}

static double vel(double m, double p, double inv_c2)
{
    return p / sqrt(m * m + p * p * inv_c2);
}

/* ---------------------------------------------------------------- input checks */

static void test_validation(void)
{
    double x[3] = {0.0, 0.5, 1.0}, m[3] = {1, 2, 1}, p[3] = {0.3, -0.2, 0.1};
    rc_gas1d_def d = rc_gas1d_def_default();
    d.n = 3;
    d.length = 1.0;
    d.c = 1.0;
    d.x = x;
    d.m = m;
    d.p = p;
    rc_gas1d *g = (rc_gas1d *)&d; /* must be reset to NULL on failure */
    size_t bad = 99;
    ENSURE(rc_gas1d_create(&d, &g, &bad) == RC_OK && g != NULL && bad == 0);
    rc_gas1d_free(&g);
    ENSURE(g == NULL);
    rc_gas1d_free(&g); /* NULL is fine */
    rc_gas1d_free(NULL);

    struct {
        int what;
        double val;
        size_t idx;
        int code;
    } cases[] = {
        {0, 1.5, 2, RC_EINVAL},       /* x outside [0, L] */
        {0, -1e-300, 0, RC_EINVAL},   /* x below 0 */
        {0, 0.0, 1, RC_EINVAL},       /* x[1] == x[0]: not strictly increasing */
        {0, NAN, 1, RC_ENONFINITE},
        {1, 0.0, 2, RC_EMASS},
        {1, -1.0, 0, RC_EMASS},
        {1, INFINITY, 1, RC_ENONFINITE},
        {2, NAN, 2, RC_ENONFINITE},
        {2, -INFINITY, 0, RC_ENONFINITE},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        double xx[3], mm[3], pp[3];
        memcpy(xx, x, sizeof x);
        memcpy(mm, m, sizeof m);
        memcpy(pp, p, sizeof p);
        double *arr = cases[k].what == 0 ? xx : (cases[k].what == 1 ? mm : pp);
        arr[cases[k].idx] = cases[k].val;
        rc_gas1d_def e = d;
        e.x = xx;
        e.m = mm;
        e.p = pp;
        g = (rc_gas1d *)&d;
        bad = 99;
        int st = rc_gas1d_create(&e, &g, &bad);
        ENSURE_MSG(st == cases[k].code && g == NULL && bad == cases[k].idx,
                   "case %zu: status %d (%s), bad %zu", k, st, rc_strerror(st), bad);
    }
    rc_gas1d_def e = d;
    e.n = 0;
    ENSURE(rc_gas1d_create(&e, &g, NULL) == RC_EINVAL);
    e = d;
    e.length = 0.0;
    ENSURE(rc_gas1d_create(&e, &g, NULL) == RC_EINVAL);
    e.length = INFINITY;
    ENSURE(rc_gas1d_create(&e, &g, NULL) == RC_ENONFINITE);
    e = d;
    e.c = -1.0;
    ENSURE(rc_gas1d_create(&e, &g, NULL) == RC_ESPEEDOFLIGHT);
    e.c = NAN;
    ENSURE(rc_gas1d_create(&e, &g, NULL) == RC_ESPEEDOFLIGHT);
    e = d;
    e.t0 = NAN;
    ENSURE(rc_gas1d_create(&e, &g, NULL) == RC_ENONFINITE);
    e = d;
    e.p = NULL;
    ENSURE(rc_gas1d_create(&e, &g, NULL) == RC_EINVAL);
    ENSURE(rc_gas1d_create(&d, NULL, NULL) == RC_EINVAL);

    /* both ends may sit on the walls */
    ENSURE(rc_gas1d_create(&d, &g, NULL) == RC_OK);
    ENSURE(rc_gas1d_advance(g, -1.0, 0) == RC_EINVAL); /* before the gas's time */
    ENSURE(rc_gas1d_advance(g, NAN, 0) == RC_EINVAL);
    ENSURE(rc_gas1d_advance(g, 2.0, 0) == RC_OK && rc_gas1d_time(g) == 2.0);
    ENSURE(rc_gas1d_count(g) == 3);
    rc_gas1d_free(&g);
}

/* ---------------------------------------------------------------- step / advance */

/* One particle between the walls: hits at exactly known times, impulses -2p and +2p,
 * at c = inf and at c = 1 (v = p / sqrt(m^2 + p^2)); a resting particle has no events. */
static void test_single_particle(void)
{
    for (int rel = 0; rel < 2; rel++) {
        double x = 0.25, m = 1.0, p = 0.75; /* binary fractions: exact arithmetic */
        rc_gas1d_def d = rc_gas1d_def_default();
        d.n = 1;
        d.length = 1.0;
        d.c = rel ? 1.0 : INFINITY;
        d.x = &x;
        d.m = &m;
        d.p = &p;
        rc_gas1d *g;
        ENSURE(rc_gas1d_create(&d, &g, NULL) == RC_OK);
        const double v = rel ? 0.75 / 1.25 : 0.75; /* sqrt(1 + 0.5625) = 1.25 */
        rc_gas1d_event ev;
        for (int k = 0; k < 6; k++) {
            ENSURE(rc_gas1d_step(g, INFINITY, &ev) == RC_OK);
            /* the k-th hit (right wall first) after travelling 0.75 + k */
            ENSURE_REL(ev.t, (0.75 + k) / v, 1e-15);
            ENSURE(ev.kind == (k % 2 == 0 ? RC_GAS1D_WALL_RIGHT : RC_GAS1D_WALL_LEFT));
            ENSURE(ev.x == (k % 2 == 0 ? 1.0 : 0.0));
        }
        rc_gas1d_stats st;
        rc_gas1d_stats_get(g, &st);
        ENSURE(st.wall_events[0] == 3 && st.wall_events[1] == 3 && st.pair_events == 0);
        ENSURE(st.wall_impulse[0] == 3 * 1.5 && st.wall_impulse[1] == -3 * 1.5);
        /* step stops before an event later than t_end and moves the clock there */
        const double t6 = ev.t;
        ENSURE(rc_gas1d_step(g, t6 + 0.5, &ev) == RC_MISS);
        ENSURE(rc_gas1d_time(g) == t6 + 0.5);
        double xs, ps;
        rc_gas1d_get(g, &xs, NULL, &ps);
        ENSURE_CLOSE(xs, 0.5 * v, 1e-15, 1.0);
        ENSURE(ps == 0.75);
        /* max_events: exactly that many, then the clock is at the last event */
        ENSURE(rc_gas1d_advance(g, INFINITY, 4) == RC_OK);
        rc_gas1d_stats_get(g, &st);
        ENSURE(st.wall_events[0] + st.wall_events[1] == 10);
        ENSURE_REL(rc_gas1d_time(g), (0.75 + 9) / v, 1e-15);
        rc_gas1d_free(&g);
    }
    /* at rest: no event ever; +inf leaves the clock alone */
    double x = 0.5, m = 1.0, p = 0.0;
    rc_gas1d_def d = rc_gas1d_def_default();
    d.n = 1;
    d.x = &x;
    d.m = &m;
    d.p = &p;
    rc_gas1d *g;
    ENSURE(rc_gas1d_create(&d, &g, NULL) == RC_OK);
    ENSURE(rc_gas1d_step(g, 3.0, NULL) == RC_MISS && rc_gas1d_time(g) == 3.0);
    ENSURE(rc_gas1d_advance(g, INFINITY, 10) == RC_OK && rc_gas1d_time(g) == 3.0);
    rc_gas1d_free(&g);
}

/* ---------------------------------------------------------------- conservation */

/* Energy conserved to 1e-12 relative over >= 1e6 pair collisions; the total momentum
 * changes only by the wall impulses the engine accounts for. */
static void conservation_run(double inv_c2, double speed)
{
    gas_setup s;
    ENSURE(gas_setup_mixture(&s, 100, inv_c2, 1.0, 2.0, 0.5, speed, 11) == RC_OK);
    rc_gas1d *g;
    ENSURE(gas_setup_create(&s, &g) == RC_OK);
    const size_t n = s.n;
    double *x = malloc(n * sizeof(double)), *m = malloc(n * sizeof(double)),
           *p = malloc(n * sizeof(double));
    const double e0 = energy(n, s.m, s.p, inv_c2);
    double p0 = 0.0, pscale = 0.0;
    for (size_t i = 0; i < n; i++) {
        p0 += s.p[i];
        pscale += fabs(s.p[i]);
    }
    rc_gas1d_stats st;
    double t = 0.0, worst_e = 0.0, worst_p = 0.0;
    int ordered = 1, masses_kept = 1;
    do {
        t += 500.0;
        ENSURE(rc_gas1d_advance(g, t, 0) == RC_OK);
        rc_gas1d_get(g, x, m, p);
        rc_gas1d_stats_get(g, &st);
        double ptot = 0.0;
        for (size_t i = 0; i < n; i++) {
            ptot += p[i];
            if (i > 0 && !(x[i] >= x[i - 1]))
                ordered = 0;
            if (!(x[i] >= 0.0 && x[i] <= s.L))
                ordered = 0;
            if (m[i] != s.m[i]) /* elastic: rest masses exactly kept */
                masses_kept = 0;
        }
        const double de = fabs(energy(n, m, p, inv_c2) - e0) / e0;
        const double dp = fabs(ptot - (p0 + st.wall_impulse[0] + st.wall_impulse[1])) / pscale;
        worst_e = fmax(worst_e, de);
        worst_p = fmax(worst_p, dp);
    } while (st.pair_events < 1000000 && t < 1e5); /* ~2e4 suffice: the guard ends a
                                                        broken engine's endless run */
    ENSURE(st.pair_events >= 1000000);
    printf("  inv_c2 %g: %llu pair + %llu wall events to t = %g, max |dE|/E %.2e, "
           "max |dP - I_walls| / sum|p| %.2e, declined %llu\n",
           inv_c2, (unsigned long long)st.pair_events,
           (unsigned long long)(st.wall_events[0] + st.wall_events[1]), t, worst_e, worst_p,
           (unsigned long long)st.declined);
    /* 1e-12: each collision rounds the pair's energy at ~1e-16 of the pair energy; a
     * random walk over 1e6 collisions gives ~1e-13 of one pair's energy, far below */
    ENSURE_MSG(worst_e <= 1e-12, "energy drift %.3g", worst_e);
    /* the wall impulses are compensated sums; the particles' momenta take ~1e-16 |p|
     * round-off per collision: 1e-12 of sum |p| leaves a factor 100 of margin */
    ENSURE_MSG(worst_p <= 1e-12, "momentum bookkeeping %.3g", worst_p);
    /* the walls really act (momentum bookkeeping is not trivially 0 = 0) */
    ENSURE(fabs(st.wall_impulse[0]) > 0.0 && fabs(st.wall_impulse[1]) > 0.0);
    ENSURE(st.wall_impulse[0] > 0.0 && st.wall_impulse[1] < 0.0);
    ENSURE(ordered);
    ENSURE(masses_kept);
    free(x);
    free(m);
    free(p);
    rc_gas1d_free(&g);
    gas_setup_free(&s);
}

static void test_conservation_relativistic(void) { conservation_run(1.0, 0.9); }
static void test_conservation_classical(void) { conservation_run(0.0, 0.9); }

/* ---------------------------------------------------------------- brute force */

/* Before every event, predict it from the current state by brute force over ALL pairs
 * (not only neighbours) and all particles against both walls; the engine's event must
 * be the same one at the same time, and its outcome what rc_collide / rc_collide_wall
 * give on the same state. */
static void brute_force_run(double inv_c2, uint64_t seed)
{
    enum { N = 7, STEPS = 20000 };
    rc_test_rng r = {seed};
    double x[N], m[N], p[N];
    const double L = 3.0;
    for (int i = 0; i < N; i++) {
        x[i] = L * (i + 0.2 + 0.6 * rc_test_uniform(&r)) / N;
        m[i] = rc_test_range(&r, 0.5, 3.0);
        p[i] = rc_test_range(&r, -2.0, 2.0);
    }
    rc_gas1d_def d = rc_gas1d_def_default();
    d.n = N;
    d.length = L;
    d.c = rc_test_c_of(inv_c2);
    d.x = x;
    d.m = m;
    d.p = p;
    rc_gas1d *g;
    ENSURE(rc_gas1d_create(&d, &g, NULL) == RC_OK);
    rc_collision_params prm = rc_collision_params_default();
    prm.c = rc_test_c_of(inv_c2);
    long mismatched = 0, near_ties = 0, wrong_outcome = 0, bad_time = 0, bad_pos = 0;
    for (int step = 0; step < STEPS; step++) {
        const double t = rc_gas1d_time(g);
        rc_gas1d_get(g, x, m, p);
        double v[N];
        for (int i = 0; i < N; i++)
            v[i] = vel(m[i], p[i], inv_c2);
        /* candidates: (dt, kind, a, b) */
        double best = INFINITY, second = INFINITY;
        int kind = -1, ia = -1, ib = -1;
        for (int a = 0; a < N; a++) {
            for (int b = a + 1; b < N; b++) {
                if (!(v[a] > v[b]))
                    continue;
                double dt = (x[b] - x[a]) / (v[a] - v[b]);
                if (dt < best) {
                    second = best;
                    best = dt, kind = RC_GAS1D_PAIR, ia = a, ib = b;
                } else if (dt < second) {
                    second = dt;
                }
            }
            double dw = INFINITY;
            int wk = -1;
            if (v[a] < 0)
                dw = x[a] / -v[a], wk = RC_GAS1D_WALL_LEFT;
            else if (v[a] > 0)
                dw = (L - x[a]) / v[a], wk = RC_GAS1D_WALL_RIGHT;
            if (dw < best) {
                second = best;
                best = dw, kind = wk, ia = a, ib = -1;
            } else if (dw < second) {
                second = dw;
            }
        }
        rc_gas1d_event ev;
        if (!(rc_gas1d_step(g, INFINITY, &ev) == RC_OK)) {
            ENSURE_MSG(0, "no event at step %d", step);
            break;
        }
        /* time scale of the state: a crossing of the box at the fastest speed */
        double vmax = 0.0;
        for (int i = 0; i < N; i++)
            vmax = fmax(vmax, fabs(v[i]));
        const double tscale = L / vmax;
        /* positions read back carry ~1e-16 L round-off, so predicted times carry
         * ~1e-16 L / |dv|; 1e-9 of the crossing time leaves room for slow approaches */
        const double ttol = 1e-9 * tscale;
        if (second - best < ttol) {
            near_ties++;
            continue;
        }
        const int same = ev.kind == kind && (int)ev.i == ia &&
                         (kind != RC_GAS1D_PAIR || ib == ia + 1);
        if (!same) {
            if (mismatched++ < 5)
                fprintf(stderr, "step %d: engine kind %d i %zu, brute force kind %d %d %d\n",
                        step, ev.kind, ev.i, kind, ia, ib);
            continue;
        }
        if (!(fabs(ev.t - (t + best)) <= ttol))
            bad_time++;
        /* outcome: same kernels on the same state give the same bits */
        double pn[N], mn[N], xn[N];
        rc_gas1d_get(g, xn, mn, pn);
        if (kind == RC_GAS1D_PAIR) {
            rc_particle A = {m[ia], rc_v3(p[ia], 0, 0)}, B = {m[ib], rc_v3(p[ib], 0, 0)};
            ENSURE(rc_collide(&rc_law_zmf, &prm, &A, &B, rc_v3(1, 0, 0)) == RC_OK);
            if (!(pn[ia] == A.p.x && pn[ib] == B.p.x && mn[ia] == A.m && mn[ib] == B.m))
                wrong_outcome++;
            const double xc = x[ia] + v[ia] * best;
            if (!(fabs(xn[ia] - xc) <= 1e-12 * L && xn[ia] == xn[ib]))
                bad_pos++;
        } else {
            rc_particle A = {m[ia], rc_v3(p[ia], 0, 0)};
            rc_vec3 nrm = rc_v3(kind == RC_GAS1D_WALL_LEFT ? -1.0 : 1.0, 0, 0);
            ENSURE(rc_collide_wall(inv_c2, 1.0, &A, nrm) == RC_OK);
            if (!(pn[ia] == A.p.x && pn[ia] == -p[ia]))
                wrong_outcome++;
            if (!(xn[ia] == (kind == RC_GAS1D_WALL_LEFT ? 0.0 : L)))
                bad_pos++;
        }
        /* the others did not move in momentum */
        for (int i = 0; i < N; i++)
            if (i != ia && i != ib && pn[i] != p[i])
                wrong_outcome++;
    }
    printf("  inv_c2 %g: %d events, %ld near ties skipped\n", inv_c2, STEPS, near_ties);
    ENSURE_MSG(mismatched == 0, "%ld events differ from the brute force", mismatched);
    ENSURE_MSG(bad_time == 0, "%ld event times off", bad_time);
    ENSURE_MSG(wrong_outcome == 0, "%ld outcomes differ", wrong_outcome);
    ENSURE_MSG(bad_pos == 0, "%ld event positions off", bad_pos);
    /* near ties are rare: the comparison covered almost every event */
    ENSURE(near_ties < STEPS / 100);
    rc_gas1d_free(&g);
}

static void test_brute_force_relativistic(void) { brute_force_run(1.0, 5); }
static void test_brute_force_classical(void) { brute_force_run(0.0, 6); }

/* ---------------------------------------------------------------- classical limit */

/* c = inf: each pair event is the classical elastic collision
 * v_i' = ((m_i - m_j) v_i + 2 m_j v_j) / (m_i + m_j); and a large finite c follows the
 * classical run event by event with times differing at O(v^2/c^2). */
static void test_classical(void)
{
    gas_setup s;
    ENSURE(gas_setup_mixture(&s, 20, 0.0, 1.0, 2.6, 0.5, 1.0, 21) == RC_OK);
    for (size_t i = 0; i < s.n; i++) /* spread of speeds so the check is not degenerate */
        s.p[i] *= 0.5 + (double)(i % 5) * 0.3;
    rc_gas1d *g, *h;
    ENSURE(gas_setup_create(&s, &g) == RC_OK);
    s.inv_c2 = 1e-12; /* c = 1e6, speeds ~1: v^2/c^2 ~ 1e-12 */
    ENSURE(gas_setup_create(&s, &h) == RC_OK);
    double m[20], p[20], ph[20];
    long bad_law = 0, bad_seq = 0, bad_t = 0;
    double worst_t = 0.0;
    for (int k = 0; k < 2000; k++) {
        rc_gas1d_get(g, NULL, m, p);
        rc_gas1d_event e, f;
        ENSURE(rc_gas1d_step(g, INFINITY, &e) == RC_OK);
        ENSURE(rc_gas1d_step(h, INFINITY, &f) == RC_OK);
        rc_gas1d_get(g, NULL, NULL, ph);
        if (e.kind == RC_GAS1D_PAIR) {
            const size_t i = e.i, j = e.i + 1;
            const double vi = p[i] / m[i], vj = p[j] / m[j], mt = m[i] + m[j];
            const double vi2 = ((m[i] - m[j]) * vi + 2.0 * m[j] * vj) / mt;
            const double vj2 = ((m[j] - m[i]) * vj + 2.0 * m[i] * vi) / mt;
            /* a few roundings of velocities of size <= |vi| + |vj| */
            const double tol = 1e-14 * (fabs(vi) + fabs(vj));
            if (!(fabs(ph[i] / m[i] - vi2) <= tol && fabs(ph[j] / m[j] - vj2) <= tol))
                bad_law++;
        } else if (ph[e.i] != -p[e.i]) {
            bad_law++;
        }
        /* the two runs separate exponentially (the mixture is chaotic), so compare the
         * first 200 events only */
        if (k < 200) {
            if (e.kind != f.kind || e.i != f.i)
                bad_seq++;
            const double dt = fabs(e.t - f.t) / fmax(e.t, 1.0);
            worst_t = fmax(worst_t, dt);
            /* 1e-12 relative difference per event, amplified by the chaos over 200
             * events: 1e-6 is still far below any difference of sequence */
            if (!(dt <= 1e-6))
                bad_t++;
        }
    }
    printf("  c = 1e6 vs c = inf, first 200 events: max relative time difference %.2e\n",
           worst_t);
    ENSURE(bad_law == 0);
    ENSURE(bad_seq == 0);
    ENSURE(bad_t == 0);
    /* the difference is there (the runs are not the same code path by accident) */
    ENSURE(worst_t > 0.0);
    rc_gas1d_free(&g);
    rc_gas1d_free(&h);
    gas_setup_free(&s);
}

/* ---------------------------------------------------------------- equal masses */

/* In 1-D an elastic collision of equal masses exchanges the momenta (seed 000's law
 * with m0 = m1, at any c), and a wall flips a sign: the multiset of |p| never changes.
 * This is why a one-species 1-D gas cannot thermalise. */
static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void test_equal_masses_swap(void)
{
    gas_setup s;
    ENSURE(gas_setup_mixture(&s, 50, 1.0, 1.0, 1.0, 0.0, 0.5, 31) == RC_OK);
    for (size_t i = 0; i < s.n; i++)
        s.p[i] *= 1.0 + 0.1 * (double)i; /* all different */
    rc_gas1d *g;
    ENSURE(gas_setup_create(&s, &g) == RC_OK);
    ENSURE(rc_gas1d_advance(g, INFINITY, 100000) == RC_OK);
    double a[50], b[50];
    rc_gas1d_get(g, NULL, NULL, b);
    for (size_t i = 0; i < s.n; i++) {
        a[i] = fabs(s.p[i]);
        b[i] = fabs(b[i]);
    }
    qsort(a, s.n, sizeof(double), cmp_double);
    qsort(b, s.n, sizeof(double), cmp_double);
    double worst = 0.0;
    for (size_t i = 0; i < s.n; i++)
        worst = fmax(worst, fabs(a[i] - b[i]) / a[i]);
    /* each swap through the zmf kernel rounds at ~1e-16; 1e5 events random-walk to
     * ~1e-13 at most */
    ENSURE_MSG(worst <= 1e-12, "|p| multiset moved by %.3g", worst);
    rc_gas1d_free(&g);
    gas_setup_free(&s);
}

/* ---------------------------------------------------------------- ties */

/* Mirror-symmetric start: both wall hits at the same time (left first), then both
 * inner pairs at the same time (left first); the fixed order makes the run symmetric. */
static void test_ties(void)
{
    double x[4] = {0.25, 0.375, 0.625, 0.75}, m[4] = {1, 2, 2, 1}, p[4] = {-1, 0.5, -0.5, 1};
    rc_gas1d_def d = rc_gas1d_def_default();
    d.n = 4;
    d.length = 1.0;
    d.c = 1.0;
    d.x = x;
    d.m = m;
    d.p = p;
    rc_gas1d *g;
    ENSURE(rc_gas1d_create(&d, &g, NULL) == RC_OK);
    rc_gas1d_event ev[4];
    for (int k = 0; k < 4; k++)
        ENSURE(rc_gas1d_step(g, INFINITY, &ev[k]) == RC_OK);
    /* (positions are binary fractions so that the mirror images are exact.) v of
     * p = 0.5, m = 2 at c = 1 is 0.5/sqrt(4.25); the inner pair meets at x = 0.5 after
     * 0.125 / v; the outer particles (v = 1/sqrt 2) reach the walls at 0.25 sqrt 2 */
    const double t_in = 0.125 * sqrt(4.25) / 0.5, t_wall = 0.25 * sqrt(2.0);
    ENSURE(t_wall < t_in);
    ENSURE(ev[0].kind == RC_GAS1D_WALL_LEFT && ev[1].kind == RC_GAS1D_WALL_RIGHT);
    ENSURE(ev[0].t == ev[1].t);
    ENSURE_REL(ev[0].t, t_wall, 1e-15);
    ENSURE(ev[2].kind == RC_GAS1D_PAIR && ev[2].i == 1);
    ENSURE_REL(ev[2].t, t_in, 1e-15);
    ENSURE_CLOSE(ev[2].x, 0.5, 1e-15, 1.0);
    /* after the walls, particles 0 and 3 are mirror images: run on and check symmetry */
    ENSURE(rc_gas1d_advance(g, 10.0, 0) == RC_OK);
    double xs[4], ps[4];
    rc_gas1d_get(g, xs, NULL, ps);
    for (int i = 0; i < 2; i++) {
        ENSURE_CLOSE(xs[i], 1.0 - xs[3 - i], 1e-12, 1.0);
        ENSURE_CLOSE(ps[i], -ps[3 - i], 1e-12, 1.0);
    }
    rc_gas1d_free(&g);

    /* Ties that arise after updates (not only in the initial tree): two particles
     * bouncing symmetrically, classical with binary fractions so every time is exact:
     * walls together at 0.5, pair at 1.5, walls together at 2.5, ... left wall first. */
    double x2[2] = {0.25, 0.75}, m2[2] = {1, 1}, p2[2] = {-0.5, 0.5};
    d.n = 2;
    d.c = INFINITY;
    d.x = x2;
    d.m = m2;
    d.p = p2;
    ENSURE(rc_gas1d_create(&d, &g, NULL) == RC_OK);
    for (int k = 0; k < 30; k++) {
        rc_gas1d_event e;
        ENSURE(rc_gas1d_step(g, INFINITY, &e) == RC_OK);
        const int phase = k % 3; /* L, R, pair */
        const int want = phase == 0 ? RC_GAS1D_WALL_LEFT
                                    : (phase == 1 ? RC_GAS1D_WALL_RIGHT : RC_GAS1D_PAIR);
        ENSURE_MSG(e.kind == want, "event %d kind %d", k, e.kind);
        ENSURE(e.t == 0.5 + 2.0 * (k / 3) + (phase == 2 ? 1.0 : 0.0));
    }
    rc_gas1d_free(&g);
}

/* ---------------------------------------------------------------- determinism */

static uint64_t hash_state(const rc_gas1d *g)
{
    size_t n = rc_gas1d_count(g);
    double *buf = malloc(2 * n * sizeof(double));
    rc_gas1d_get(g, buf, NULL, buf + n);
    uint64_t h = 1469598103934665603ULL;
    const unsigned char *c = (const unsigned char *)buf;
    for (size_t k = 0; k < 2 * n * sizeof(double); k++)
        h = (h ^ c[k]) * 1099511628211ULL;
    free(buf);
    return h;
}

/* Reading the state never changes the trajectory: one advance to t equals 997 small
 * advances with reads in between, bit for bit; and two runs are identical. */
static void test_determinism(void)
{
    gas_setup s;
    ENSURE(gas_setup_mixture(&s, 300, 1.0, 1.0, 2.0, 0.5, 0.8, 41) == RC_OK);
    rc_gas1d *a, *b, *c;
    ENSURE(gas_setup_create(&s, &a) == RC_OK);
    ENSURE(gas_setup_create(&s, &b) == RC_OK);
    ENSURE(gas_setup_create(&s, &c) == RC_OK);
    const double T = 400.0;
    ENSURE(rc_gas1d_advance(a, T, 0) == RC_OK);
    ENSURE(rc_gas1d_advance(c, T, 0) == RC_OK);
    double tmp[300];
    for (int k = 1; k <= 997; k++) {
        ENSURE(rc_gas1d_advance(b, T * k / 997.0, 0) == RC_OK);
        rc_gas1d_get(b, tmp, NULL, NULL);
    }
    rc_gas1d_stats sa, sb;
    rc_gas1d_stats_get(a, &sa);
    rc_gas1d_stats_get(b, &sb);
    printf("  %llu pair events, state hash %016llx\n", (unsigned long long)sa.pair_events,
           (unsigned long long)hash_state(a));
    ENSURE(sa.pair_events > 10000);
    ENSURE(sa.pair_events == sb.pair_events);
    ENSURE(hash_state(a) == hash_state(b));
    ENSURE(hash_state(a) == hash_state(c));
    rc_gas1d_free(&a);
    rc_gas1d_free(&b);
    rc_gas1d_free(&c);
    gas_setup_free(&s);
}

/* The worldline record (rc_gas1d_segment_get): read after every event for the particles
 * it names, the segments are continuous (the old line reaches the event), start at the
 * event, leave the other particles' segments alone, and give the state rc_gas1d_get
 * reports at any later time; bad indices are refused. */
static void test_segments(void)
{
    enum { NP = 200 };
    gas_setup s;
    ENSURE(gas_setup_mixture(&s, NP, 1.0, 1.0, 2.0, 0.5, 0.8, 43) == RC_OK);
    rc_gas1d *g;
    ENSURE(gas_setup_create(&s, &g) == RC_OK);
    rc_gas1d_segment seg[NP], q;
    for (size_t i = 0; i < NP; i++) {
        ENSURE(rc_gas1d_segment_get(g, i, &seg[i]) == RC_OK);
        ENSURE(seg[i].t == 0.0 && seg[i].x == s.x[i] && seg[i].p == s.p[i] &&
               seg[i].m == s.m[i]);
    }
    ENSURE(rc_gas1d_segment_get(g, NP, &q) == RC_EINVAL);
    ENSURE(rc_gas1d_segment_get(NULL, 0, &q) == RC_EINVAL);
    ENSURE(rc_gas1d_segment_get(g, 0, NULL) == RC_EINVAL);
    /* round-off of a position carried over many events, in units of the box (the event
     * point is the mean of two lines that meet exactly in exact arithmetic) */
    const double tol = 1e-11 * s.L;
    double worst = 0.0, x[NP];
    uint64_t events = 0;
    int bad_start = 0, bad_other = 0, bad_get = 0;
    for (int k = 1; k <= 200; k++) {
        const double t_end = 2.0 * k;
        rc_gas1d_event ev;
        while (rc_gas1d_step(g, t_end, &ev) == RC_OK) {
            events++;
            const size_t i1 = ev.kind == RC_GAS1D_PAIR ? ev.i + 1 : ev.i;
            for (size_t i = ev.i; i <= i1; i++) {
                const double reach = seg[i].x + seg[i].v * (ev.t - seg[i].t);
                worst = fmax(worst, fabs(reach - ev.x));
                rc_gas1d_segment_get(g, i, &seg[i]);
                bad_start |= seg[i].t != ev.t || seg[i].x != ev.x ||
                             seg[i].v != vel(seg[i].m, seg[i].p, 1.0);
            }
            /* a neighbour the event does not name keeps its segment */
            const size_t j = i1 + 1 < NP ? i1 + 1 : (ev.i > 0 ? ev.i - 1 : NP);
            if (j < NP) {
                rc_gas1d_segment_get(g, j, &q);
                bad_other |= memcmp(&q, &seg[j], sizeof q) != 0;
            }
        }
        rc_gas1d_get(g, x, NULL, NULL);
        for (size_t i = 0; i < NP; i++) {
            double xi = seg[i].x + seg[i].v * (t_end - seg[i].t);
            xi = xi < 0.0 ? 0.0 : (xi > s.L ? s.L : xi);
            bad_get |= xi != x[i];
        }
    }
    printf("  %llu events: worldlines continuous to %.2g (box %g)\n",
           (unsigned long long)events, worst, s.L);
    ENSURE(events > 10000);
    ENSURE_MSG(worst <= tol, "a segment misses its event by %g", worst);
    ENSURE(!bad_start);
    ENSURE(!bad_other);
    ENSURE(!bad_get);
    rc_gas1d_free(&g);
    gas_setup_free(&s);
}

int main(void)
{
    RUN_TEST(test_validation);
    RUN_TEST(test_single_particle);
    RUN_TEST(test_conservation_relativistic);
    RUN_TEST(test_conservation_classical);
    RUN_TEST(test_brute_force_relativistic);
    RUN_TEST(test_brute_force_classical);
    RUN_TEST(test_classical);
    RUN_TEST(test_equal_masses_swap);
    RUN_TEST(test_ties);
    RUN_TEST(test_determinism);
    RUN_TEST(test_segments);
    RC_TEST_MAIN_END();
}
