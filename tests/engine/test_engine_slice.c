/* test_engine_slice.c — delayed table-time slices (rc_sim_slice_*, relcol/sim.h): in the
 * frames whose velocity changes come at their events' table times a slice is exactly what
 * rc_sim_get_ball gives with the engine's time at ts; asking for and reading slices never
 * changes a run (covariant included); every bad input and every dropped slice has its
 * error. The covariant slices against worldlines rebuilt independently of the engine:
 * test_engine_audit_covariant. */
#include <math.h>
#include <string.h>

#include "engine_util.h"

static int same_ball(const rc_sim_ball *a, const rc_sim_ball *b)
{
    return memcmp(&a->x, &b->x, sizeof a->x) == 0 && memcmp(&a->p, &b->p, sizeof a->p) == 0 &&
           a->r == b->r && a->m == b->m && a->tau == b->tau && a->collided == b->collided &&
           a->tau_last == b->tau_last && memcmp(a->image, b->image, sizeof a->image) == 0;
}

static rc_sim *gas(int dim, const rc_toi_frame *f, int periodic, double c, double packing,
                   uint64_t seed)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    d.c = c;
    d.frame = f;
    d.eps_ball = 0.8;
    for (int k = 0; k < 3; k++)
        d.boundary[k] = periodic ? RC_SIM_PERIODIC : RC_SIM_WALLS;
    return util_gas(d, 60, packing, 0.6, seed);
}

/* (b) Every frame but the per_ball one at finite c: slices at a few times, asked for at
 * the start and read at the end, are bit for bit the balls rc_sim_get_ball gives in a
 * second engine advanced to each time (advancing in pieces gives the same bits as in one
 * go: relcol/sim.h); and the two runs end with the same state hash. The covariant frame
 * at c = infinity is the one-instant model, so it belongs here too. */
static void test_equals_get_ball(void)
{
    const double ts[5] = {0.0, 0.75, 3.1, 7.0, 21.5};
    for (size_t f = 0; rc_toi_frames[f]; f++) {
        for (int per = 0; per < 4; per++) {
            const rc_toi_frame *fr = rc_toi_frames[f];
            const int dim = 2 + per / 2;
            const double c = fr->per_ball ? INFINITY : 1.0;
            rc_sim *a = gas(dim, fr, per % 2, c, 0.15, 3), *b = gas(dim, fr, per % 2, c, 0.15, 3);
            if (!a || !b) {
                rc_sim_free(&a);
                rc_sim_free(&b);
                continue;
            }
            uint32_t id[5];
            for (int q = 0; q < 5; q++)
                ENSURE(rc_sim_slice_request(b, ts[q], &id[q]) == RC_OK);
            ENSURE(rc_sim_advance(b, 30.0, 0) == RC_OK);
            size_t diff = 0;
            for (int q = 0; q < 5; q++) {
                ENSURE(rc_sim_advance(a, ts[q], 0) == RC_OK);
                rc_sim_slice_info in;
                ENSURE(rc_sim_slice_ready(b, id[q], &in) == 1 && in.t_final == ts[q] &&
                       in.late == 0);
                for (size_t i = 0; i < rc_sim_count(a); i++) {
                    rc_sim_ball x, y;
                    ENSURE(rc_sim_get_ball(a, i, &x) == RC_OK);
                    ENSURE(rc_sim_slice_get(b, id[q], i, &y) == RC_OK);
                    diff += !same_ball(&x, &y);
                }
            }
            ENSURE(rc_sim_advance(a, 30.0, 0) == RC_OK);
            rc_sim_diag da, db;
            rc_sim_diagnostics(a, &da);
            rc_sim_diagnostics(b, &db);
            ENSURE_MSG(diff == 0 && rc_sim_hash(a) == rc_sim_hash(b) && da.collisions > 150 &&
                       da.collisions == db.collisions,
                       "frame %s %d-D periodic %d: %zu balls differ, %llu collisions", fr->name, dim, per % 2,
                       diff, (unsigned long long)da.collisions);
            rc_sim_free(&a);
            rc_sim_free(&b);
        }
    }
}

/* The covariant frame at c = 1, 2-D and 3-D: a run that asks for slices, keeps them, reads
 * them and releases them ends in the same state, bit for bit, as the run that does not,
 * with the same counts (rollbacks and conflicts included: the hooks see kinks placed and
 * undone, and must change nothing); the slices come final at t_final and are refused
 * before; a ball read final on its latest segment is where that segment puts it. (The
 * slice's sums are not compared with the conserved ones: relcol/sim.h.) */
static void test_covariant_run_unchanged(void)
{
    for (int per = 0; per < 4; per++) {
        const int dim = 2 + per / 2;
        const double pk = dim == 2 ? 0.35 : 0.25;
        rc_sim *a = gas(dim, &rc_toi_frame_covariant, per % 2, 1.0, pk, 5),
               *b = gas(dim, &rc_toi_frame_covariant, per % 2, 1.0, pk, 5);
        if (!a || !b) {
            rc_sim_free(&a);
            rc_sim_free(&b);
            continue;
        }
        ENSURE(rc_sim_advance(a, 50.0, 0) == RC_OK);
        uint32_t id[64];
        double ts[64];
        int nq = 0, reads = 0, refused = 0;
        long on_line = 0;
        for (int step = 1; step <= 200; step++) {
            const double t = 0.25 * step;
            if (nq < 64 && step % 3 == 0) {
                ts[nq] = rc_sim_time(b) + 0.4;
                ENSURE(rc_sim_slice_request(b, ts[nq], &id[nq]) == RC_OK);
                nq++;
            }
            ENSURE(rc_sim_advance(b, t, 0) == RC_OK);
            for (int q = 0; q < nq; q++) {
                rc_sim_slice_info in;
                const int r = rc_sim_slice_ready(b, id[q], &in);
                rc_sim_ball y;
                if (r == 0) {
                    refused += rc_sim_slice_get(b, id[q], 0, &y) == RC_ENOTREADY;
                    ENSURE(rc_sim_time(b) < in.t_final && in.t_final > ts[q]);
                    continue;
                }
                ENSURE(r == 1 && rc_sim_time(b) >= in.t_final && in.late == 0);
                for (size_t i = 0; i < rc_sim_count(b); i++) {
                    ENSURE(rc_sim_slice_get(b, id[q], i, &y) == RC_OK);
                    /* walls: a ball whose latest kink (its glued tube's centre event) lies
                     * at or before ts is on its latest segment there: the latest read-out
                     * taken back along it, to 1e-9 of r and relative in proper time (the
                     * same line from two of its points: round-off ~1e-14) */
                    rc_glue g;
                    rc_sim_ball w;
                    if (per % 2 || rc_sim_get_glue(b, i, &g) != RC_OK || !(g.r > 0.0) ||
                        !(g.t_c <= ts[q]) || rc_sim_kink_ahead(b, i) != 0)
                        continue;
                    ENSURE(rc_sim_get_ball_latest(b, i, &w) == RC_OK);
                    const double M = sqrt(w.m * w.m + rc_v3_norm2(w.p)), h = ts[q] - rc_sim_time(b);
                    const rc_vec3 x = rc_v3_axpy(w.x, h / M, w.p);
                    const double tau = w.tau + h * w.m / M;
                    on_line++;
                    ENSURE_MSG(rc_v3_norm(rc_v3_sub(x, y.x)) <= 1e-9 * w.r &&
                                   fabs(tau - y.tau) <= 1e-9 * fabs(tau) &&
                                   memcmp(&w.p, &y.p, sizeof w.p) == 0 && w.m == y.m,
                               "%d-D ball %zu: off its latest segment by %g", dim, i,
                               rc_v3_norm(rc_v3_sub(x, y.x)));
                }
                reads++;
                if (q % 2 == 0) { /* (half released at once, half kept a while) */
                    ENSURE(rc_sim_slice_release(b, id[q]) == RC_OK);
                    id[q] = id[nq - 1];
                    ts[q] = ts[nq - 1];
                    nq--;
                    q--;
                }
            }
        }
        rc_sim_diag da, db;
        rc_sim_diagnostics(a, &da);
        rc_sim_diagnostics(b, &db);
        ENSURE_MSG(rc_sim_hash(a) == rc_sim_hash(b) && memcmp(&da, &db, sizeof da) == 0,
                   "%d-D periodic %d: the run changed with slices asked for", dim, per % 2);
        ENSURE_MSG(per % 2 || on_line > 30, "%ld on their latest segment", on_line);
        ENSURE_MSG(reads > 20 && refused > 10 && da.collisions > 500 && da.rollbacks > 10,
                   "%d reads, %d refused, %llu collisions, %llu rollbacks", reads, refused,
                   (unsigned long long)da.collisions, (unsigned long long)da.rollbacks);
        rc_sim_free(&a);
        rc_sim_free(&b);
    }
}

/* Bad input, unknown ids, reading before final, and the calls that drop every slice. */
static void test_errors(void)
{
    rc_sim *s = gas(2, &rc_toi_frame_covariant, 0, 1.0, 0.15, 7);
    if (!s)
        return;
    uint32_t id = 0, id2 = 0;
    rc_sim_ball y;
    rc_sim_slice_info in;
    ENSURE(rc_sim_advance(s, 1.0, 0) == RC_OK);
    ENSURE(rc_sim_slice_request(NULL, 2.0, &id) == RC_EINVAL);
    ENSURE(rc_sim_slice_request(s, 2.0, NULL) == RC_EINVAL);
    ENSURE(rc_sim_slice_request(s, NAN, &id) == RC_EINVAL);
    ENSURE(rc_sim_slice_request(s, INFINITY, &id) == RC_EINVAL);
    ENSURE(rc_sim_slice_request(s, 0.5, &id) == RC_EINVAL); /* (before the engine's time) */
    ENSURE(rc_sim_slice_request(s, 2.0, &id) == RC_OK);
    ENSURE(rc_sim_slice_ready(NULL, id, &in) == RC_EINVAL);
    ENSURE(rc_sim_slice_ready(s, id + 100, &in) == RC_ENOSLICE);
    ENSURE(rc_sim_slice_ready(s, id, &in) == 0 && in.ts == 2.0 && in.final == 0);
    ENSURE(rc_sim_slice_get(s, id, 0, &y) == RC_ENOTREADY);
    ENSURE(rc_sim_slice_get(s, id + 100, 0, &y) == RC_ENOSLICE);
    ENSURE(rc_sim_slice_get(s, id, 0, NULL) == RC_EINVAL);
    ENSURE(rc_sim_slice_get(NULL, id, 0, &y) == RC_EINVAL);
    ENSURE(rc_sim_advance(s, in.t_final, 0) == RC_OK);
    ENSURE(rc_sim_slice_ready(s, id, &in) == 1);
    ENSURE(rc_sim_slice_get(s, id, rc_sim_count(s), &y) == RC_EINVAL);
    ENSURE(rc_sim_slice_get(s, id, 0, &y) == RC_OK);
    ENSURE(rc_sim_slice_release(s, id) == RC_OK);
    ENSURE(rc_sim_slice_release(s, id) == RC_ENOSLICE);
    ENSURE(rc_sim_slice_release(NULL, id) == RC_EINVAL);
    ENSURE(rc_sim_slice_get(s, id, 0, &y) == RC_ENOSLICE);
    /* a checkpoint does not carry slices; reading one drops the reader's */
    size_t bytes = 0;
    ENSURE(rc_sim_slice_request(s, rc_sim_time(s) + 1.0, &id) == RC_OK);
    ENSURE(rc_sim_checkpoint_size(s, &bytes) == RC_OK);
    void *buf = malloc(bytes);
    ENSURE(buf && rc_sim_checkpoint_write(s, buf, bytes) == RC_OK);
    ENSURE(rc_sim_slice_ready(s, id, NULL) == 0); /* (writing keeps them) */
    ENSURE(buf && rc_sim_checkpoint_read(s, buf, bytes) == RC_OK);
    ENSURE(rc_sim_slice_ready(s, id, NULL) == RC_ENOSLICE);
    free(buf);
    /* set_c and set_balls drop them too; sync keeps them */
    ENSURE(rc_sim_slice_request(s, rc_sim_time(s) + 1.0, &id) == RC_OK);
    ENSURE(rc_sim_sync(s) == RC_OK && rc_sim_slice_ready(s, id, NULL) == 0);
    ENSURE(rc_sim_set_c(s, 2.0) == RC_OK && rc_sim_slice_ready(s, id, NULL) == RC_ENOSLICE);
    ENSURE(rc_sim_slice_request(s, rc_sim_time(s) + 1.0, &id2) == RC_OK && id2 != id);
    rc_sim_ball one[1];
    ENSURE(rc_sim_get_ball(s, 0, &one[0]) == RC_OK);
    ENSURE(rc_sim_set_balls(s, 1, one, NULL) == RC_OK);
    ENSURE(rc_sim_slice_ready(s, id2, NULL) == RC_ENOSLICE);
    ENSURE(strlen(rc_strerror(RC_ENOTREADY)) > 10 && strlen(rc_strerror(RC_ENOSLICE)) > 10 &&
           strcmp(rc_strerror(RC_ENOSLICE), rc_strerror(-99)) != 0);
    rc_sim_free(&s);
    /* no balls: nothing to slice */
    rc_sim_def d = rc_sim_def_default();
    ENSURE(rc_sim_create(&d, &s) == RC_OK);
    ENSURE(rc_sim_slice_request(s, 1.0, &id) == RC_EINVAL);
    rc_sim_free(&s);
}

int main(void)
{
    RUN_TEST(test_equals_get_ball);
    RUN_TEST(test_covariant_run_unchanged);
    RUN_TEST(test_errors);
    RC_TEST_MAIN_END();
}
