/* test_engine_audit.c — an all-pairs audit of the engine's contacts in a 2-D gas of
 * Lorentz-contracted discs (table frame, c = 1), independent of the library's contact code:
 * the engine is stepped one event at a time, and after every event every pair is checked
 * with this file's own Perram–Wertheim overlap factor mu (both shapes scaled by mu about
 * their centres just touch; mu < 1: overlapping):
 *  - free flight never makes two shapes interpenetrate (a missed contact);
 *  - a ball-ball collision happens at touching shapes (|mu - 1| small) unless the engine
 *    counted it as an overlap it resolved (the shape-change policy);
 *  - the impulse is along the contact normal of the shapes before the collision;
 *  - no shape crosses a wall.
 * The audit found the engine's one missed-contact fault (pairs whose bounding circles
 * overlap while their centres part, test_engine_contracted: test_parting_bounding_spheres);
 * this test keeps watching the rest of the contact logic. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine_util.h"

/* Overlap at or beyond this (relative to 1, i.e. to the shapes' size) is an overlap: the
 * engine's overlap_tol. A collision must be within TOUCH of contact: the frame resolves
 * contacts to ~1e-13 (touch_tol 1e-12 in mu); 1e-8 leaves room for the positions having
 * been advanced to the event time. */
#define OVERLAP 1e-9
#define TOUCH 1e-8
/* impulse against the contact normal (rad): both come from the same root, to round-off */
#define ANGLE 1e-9

typedef struct sym2 {
    double a, b, c; /* [[a b][b c]] */
} sym2;

/* The table-frame shape of a disc, as the quadratic form P = r^2 (I - beta beta^T),
 * beta = p / (M c) (c = 1). */
static sym2 shape_of(const rc_sim_ball *B)
{
    const double M = sqrt(B->m * B->m + rc_v3_norm2(B->p));
    const double bx = B->p.x / M, by = B->p.y / M, r2 = B->r * B->r;
    return (sym2){r2 * (1.0 - bx * bx), -r2 * bx * by, r2 * (1.0 - by * by)};
}

/* F(l) = l (1 - l) d^T C^-1 d, C = (1 - l) P0 + l P1, and C^-1 d; mu^2 = max over l. */
static double pw_f(sym2 P0, sym2 P1, double dx, double dy, double l, double *ix, double *iy)
{
    const double a = (1 - l) * P0.a + l * P1.a, b = (1 - l) * P0.b + l * P1.b,
                 c = (1 - l) * P0.c + l * P1.c, det = a * c - b * b;
    *ix = (c * dx - b * dy) / det;
    *iy = (-b * dx + a * dy) / det;
    return l * (1 - l) * (dx * *ix + dy * *iy);
}

/* dF/dl = (1 - 2l) d.C^-1 d - l (1 - l) (C^-1 d).(P1 - P0)(C^-1 d); F is concave in l, so
 * its maximum is the root of dF/dl, found by bisection to round-off. */
static double pw_mu(sym2 P0, sym2 P1, double dx, double dy, double *nx, double *ny)
{
    double lo = 0.0, hi = 1.0, ix, iy;
    for (int it = 0; it < 200 && hi - lo > 1e-17; it++) {
        const double l = 0.5 * (lo + hi);
        pw_f(P0, P1, dx, dy, l, &ix, &iy);
        const double qa = P1.a - P0.a, qb = P1.b - P0.b, qc = P1.c - P0.c;
        const double quad = ix * (qa * ix + qb * iy) + iy * (qb * ix + qc * iy);
        if ((1 - 2 * l) * (dx * ix + dy * iy) - l * (1 - l) * quad > 0.0)
            lo = l;
        else
            hi = l;
    }
    const double F = pw_f(P0, P1, dx, dy, 0.5 * (lo + hi), &ix, &iy);
    const double q = hypot(ix, iy); /* the normal at contact: C^-1 d */
    *nx = ix / q;
    *ny = iy / q;
    return sqrt(F);
}

static void audit(size_t n, double packing, double theta, long events, uint64_t seed)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = 2;
    d.c = 1.0;
    d.frame = rc_toi_frame_find("table");
    const double g0 = (1 + 2 * theta + 2 * theta * theta) / (1 + theta);
    rc_sim_gas_def g = {2, n, 0.5, packing, sqrt(1 - 1 / (g0 * g0)), 1.0, 1.0, seed};
    rc_sim_ball *B = calloc(n, sizeof *B), *Bp = calloc(n, sizeof *Bp);
    rc_sim *s = NULL;
    ENSURE(rc_sim_gas_init(&g, &d.box, B) == RC_OK && rc_sim_create(&d, &s) == RC_OK &&
           rc_sim_set_balls(s, n, B, NULL) == RC_OK);
    if (!s) {
        free(B);
        free(Bp);
        return;
    }
    sym2 *P = malloc(n * sizeof *P);
    unsigned char *ov = calloc(n * n, 1), *moved = calloc(n, 1);
    const rc_vec3 box = d.box;
    for (size_t i = 0; i < n; i++)
        rc_sim_get_ball(s, i, &Bp[i]);
    rc_sim_diag dg;
    rc_sim_diagnostics(s, &dg);
    uint64_t overlaps_before = dg.overlaps;
    long missed = 0, false_contacts = 0, contacts = 0, wall_cross = 0;
    double worst_touch = 0.0, worst_angle = 0.0;
    for (long e = 0; e < events; e++) {
        if (rc_sim_advance(s, INFINITY, 1) != RC_OK)
            break;
        for (size_t i = 0; i < n; i++)
            rc_sim_get_ball(s, i, &B[i]);
        rc_sim_diagnostics(s, &dg);
        const int counted_overlap = dg.overlaps > overlaps_before;
        overlaps_before = dg.overlaps;
        size_t ch[2];
        int nch = 0;
        for (size_t i = 0; i < n; i++) {
            moved[i] = B[i].p.x != Bp[i].p.x || B[i].p.y != Bp[i].p.y;
            if (moved[i] && nch < 2)
                ch[nch] = i;
            nch += moved[i];
            P[i] = shape_of(&B[i]);
        }
        if (nch == 2 && !counted_overlap) { /* a ball-ball collision: the shapes before it */
            const size_t a = ch[0], b = ch[1];
            double nx, ny;
            const double mu = pw_mu(shape_of(&Bp[a]), shape_of(&Bp[b]), B[b].x.x - B[a].x.x,
                                    B[b].x.y - B[a].x.y, &nx, &ny);
            const rc_vec3 dp = rc_v3_sub(B[b].p, Bp[b].p);
            const double sine = fabs(dp.x * ny - dp.y * nx) / rc_v3_norm(dp);
            contacts++;
            worst_touch = fmax(worst_touch, fabs(mu - 1.0));
            worst_angle = fmax(worst_angle, asin(fmin(1.0, sine)));
            false_contacts += fabs(mu - 1.0) > TOUCH;
        }
        for (size_t i = 0; i < n; i++) {
            for (size_t j = i + 1; j < n; j++) {
                const double dx = B[j].x.x - B[i].x.x, dy = B[j].x.y - B[i].x.y;
                const double rr = B[i].r + B[j].r;
                unsigned char now = 0;
                if (dx * dx + dy * dy < rr * rr) {
                    double nx, ny;
                    now = pw_mu(P[i], P[j], dx, dy, &nx, &ny) < 1.0 - OVERLAP;
                    /* new, between two balls in free flight: a contact was missed */
                    missed += now && !ov[i * n + j] && !moved[i] && !moved[j];
                }
                ov[i * n + j] = now;
            }
            for (int k = 0; k < 2; k++) { /* support of the shape along the wall normal */
                const double h = sqrt(k == 0 ? P[i].a : P[i].c);
                const double x = k == 0 ? B[i].x.x : B[i].x.y, L = k == 0 ? box.x : box.y;
                wall_cross += !moved[i] && fmax(h - x, x + h - L) > OVERLAP * B[i].r &&
                              fmax(h - (k == 0 ? Bp[i].x.x : Bp[i].x.y),
                                   (k == 0 ? Bp[i].x.x : Bp[i].x.y) + h - L) <= OVERLAP * B[i].r;
            }
        }
        memcpy(Bp, B, n * sizeof *B);
    }
    ENSURE_MSG(contacts > events / 6, "too few contacts to mean anything (%ld)", contacts);
    ENSURE_MSG(missed == 0, "%ld contacts missed in free flight", missed);
    ENSURE_MSG(false_contacts == 0, "%ld collisions not at contact (worst |mu - 1| %.3g)",
               false_contacts, worst_touch);
    ENSURE_MSG(worst_angle < ANGLE, "impulse off the contact normal by %.3g rad", worst_angle);
    ENSURE_MSG(wall_cross == 0, "%ld shapes crossed a wall in free flight", wall_cross);
    printf("  n %zu packing %.2f theta %.2f: %ld events, %ld contacts audited (worst |mu-1| "
           "%.2g, angle %.2g rad), %llu overlaps counted, %ld missed\n",
           n, packing, theta, events, contacts, worst_touch, worst_angle,
           (unsigned long long)dg.overlaps, missed);
    free(B);
    free(Bp);
    free(P);
    free(ov);
    free(moved);
    rc_sim_free(&s);
}

static void test_contracted_gas(void) { audit(120, 0.25, 0.75, 6000, 1); }
static void test_contracted_hot_dense(void) { audit(100, 0.5, 2.0, 4000, 3); }

int main(void)
{
    RUN_TEST(test_contracted_gas);
    RUN_TEST(test_contracted_hot_dense);
    RC_TEST_MAIN_END();
}
