/* bench_law.c — zmf-law evaluations per second in 3-D over 1e6 random approaching pairs
 * through rc_collide_batch, with same-process baselines printed as ratios: the classical
 * case (inv_c2 = 0, same code) and a plain copy of the same particle arrays (the memory
 * traffic floor). Usage: bench_law [n_pairs [repetitions]]. Prints figures; no verdict. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "law_util.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct {
    size_t n;
    rc_particle *a0, *b0, *a, *b;
    rc_vec3 *nrm;
    int *st;
} arrays;

/* Best-of-reps seconds for one batch of the law over fresh copies of the inputs (the
 * batch changes its inputs, so each repetition restores them first, outside the timer). */
static double time_batch(const arrays *x, const rc_law *law, double inv_c2, int reps,
                         size_t *hits)
{
    rc_collision_params prm = rc_collision_params_default();
    prm.c = rc_test_c_of(inv_c2);
    prm.eps = 0.8;
    double best = 1e300;
    for (int r = 0; r < reps; r++) {
        memcpy(x->a, x->a0, x->n * sizeof *x->a);
        memcpy(x->b, x->b0, x->n * sizeof *x->b);
        double t0 = now();
        *hits = rc_collide_batch(law, &prm, x->n, x->a, x->b, x->nrm, x->st);
        double t = now() - t0;
        if (t < best)
            best = t;
    }
    return best;
}

/* The same batch through rc_collide_many, the validating entry point over columns (what
 * the Python package calls): the inputs are split into columns outside the timer. */
static double time_many(const arrays *x, double inv_c2, int reps)
{
    rc_collision_params prm = rc_collision_params_default();
    prm.c = rc_test_c_of(inv_c2);
    prm.eps = 0.8;
    double *m0 = malloc(x->n * sizeof *m0), *m1 = malloc(x->n * sizeof *m1);
    rc_vec3 *p0 = malloc(x->n * sizeof *p0), *p1 = malloc(x->n * sizeof *p1);
    double best = 1e300;
    for (int r = 0; m0 && m1 && p0 && p1 && r < reps; r++) {
        for (size_t i = 0; i < x->n; i++) {
            m0[i] = x->a0[i].m, p0[i] = x->a0[i].p;
            m1[i] = x->b0[i].m, p1[i] = x->b0[i].p;
        }
        double t0 = now();
        rc_collide_many(&rc_law_zmf, &prm, x->n, m0, p0, m1, p1, x->nrm, x->st, NULL, NULL);
        double t = now() - t0;
        if (t < best)
            best = t;
    }
    free(m0), free(m1), free(p0), free(p1);
    return best;
}

/* Baseline: a plain loop that reads both balls and the normal of each pair and writes both
 * balls back (the bytes a batch must move, without the arithmetic). */
static double time_copy(const arrays *x, int reps)
{
    double best = 1e300;
    for (int r = 0; r < reps; r++) {
        double t0 = now();
        for (size_t i = 0; i < x->n; i++) {
            x->a[i] = x->a0[i];
            x->b[i] = x->b0[i];
            x->st[i] = x->nrm[i].x > 2.0; /* touch the normals: 0 */
        }
        double t = now() - t0;
        if (t < best)
            best = t;
    }
    return best;
}

int main(int argc, char **argv)
{
    size_t n = argc > 1 ? (size_t)strtoull(argv[1], NULL, 10) : 1000000;
    int reps = argc > 2 ? atoi(argv[2]) : 7;
    (void)rc_test_checks, (void)rc_test_failures; /* the harness is not used here */
    if (n == 0 || reps <= 0) {
        fprintf(stderr, "usage: bench_law [n_pairs [repetitions]]\n");
        return 2;
    }
    arrays x = {n, malloc(n * sizeof(rc_particle)), malloc(n * sizeof(rc_particle)),
                malloc(n * sizeof(rc_particle)), malloc(n * sizeof(rc_particle)),
                malloc(n * sizeof(rc_vec3)), malloc(n * sizeof(int))};
    if (!x.a0 || !x.b0 || !x.a || !x.b || !x.nrm || !x.st) {
        fprintf(stderr, "bench_law: out of memory\n");
        return 1;
    }
    /* c = 1, speeds below 0.95 c, masses in [0.1, 10], normals oriented so every pair
     * approaches (an engine calls the law only for approaching contacts) */
    const double inv_c2 = 1.0;
    rc_test_rng r = {2024};
    for (size_t i = 0; i < n; i++) {
        rc_vec3 v0 = lu_vec(&r, 3, 0.95), v1 = lu_vec(&r, 3, 0.95), nn = lu_unit(&r, 3);
        if (rc_v3_dot(rc_v3_sub(v0, v1), nn) < 0.0)
            nn = rc_v3_scale(-1.0, nn);
        x.a0[i].m = lu_logu(&r, 0.1, 10.0);
        x.b0[i].m = lu_logu(&r, 0.1, 10.0);
        rc_momentum_from_velocity(x.a0[i].m, v0, inv_c2, &x.a0[i].p);
        rc_momentum_from_velocity(x.b0[i].m, v1, inv_c2, &x.b0[i].p);
        x.nrm[i] = nn;
    }

    size_t hits_rel = 0, hits_cl = 0;
    double t_rel = time_batch(&x, &rc_law_zmf, inv_c2, reps, &hits_rel);
    double t_cl = time_batch(&x, &rc_law_zmf, 0.0, reps, &hits_cl);
    double t_copy = time_copy(&x, reps);
    size_t hits_cm = 0;
    double t_cm = time_batch(&x, &rc_law_cm_isotropic, inv_c2, reps, &hits_cm);
    double t_many = time_many(&x, inv_c2, reps);

    printf("bench_law: %zu pairs, 3-D, best of %d repetitions, one thread\n", n, reps);
    printf("  zmf, c = 1 (relativistic)   %8.2f M pairs/s  (%5.2f ns/pair, %zu collided)\n",
           1e-6 * (double)n / t_rel, 1e9 * t_rel / (double)n, hits_rel);
    printf("  zmf, c = inf (classical)    %8.2f M pairs/s  (%5.2f ns/pair)\n",
           1e-6 * (double)n / t_cl, 1e9 * t_cl / (double)n);
    printf("  plain copy of the pairs     %8.2f M pairs/s  (%5.2f ns/pair)\n",
           1e-6 * (double)n / t_copy, 1e9 * t_copy / (double)n);
    printf("  cm-isotropic, c = 1         %8.2f M pairs/s  (%5.2f ns/pair)\n",
           1e-6 * (double)n / t_cm, 1e9 * t_cm / (double)n);
    printf("  zmf, c = 1, rc_collide_many %8.2f M pairs/s  (%5.2f ns/pair: checked, columns)\n",
           1e-6 * (double)n / t_many, 1e9 * t_many / (double)n);
    printf("  ratios: zmf(c=1)/classical %.2f, zmf(c=1)/copy %.2f, cm-isotropic/zmf %.2f\n",
           t_cl / t_rel, t_copy / t_rel, t_rel / t_cm);
    printf("  target 30 M pairs/s: %s\n", 1e-6 * (double)n / t_rel >= 30.0 ? "met" : "NOT met");
    free(x.a0), free(x.b0), free(x.a), free(x.b), free(x.nrm), free(x.st);
    return 0;
}
