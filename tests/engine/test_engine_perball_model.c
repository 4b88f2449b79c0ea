/* test_engine_perball_model.c — a per-ball frame and its model defined here, outside the
 * library: a contact frame entry that declares per_ball (its contact kernel the zmf
 * frame's event, counted) and an ops table (engine/model.h) whose every op counts its
 * calls and hands them on to the library's glued-tube model. The engine must reach the
 * model only through the table (every named point called, in 2-D and 3-D, walled and
 * periodic), and the run must be the built-in covariant frame's to the bit (final hash,
 * every diagnostic count). A second per-ball model is added the same way: its table
 * entry (here a frame) plus its ops (here the counting wrappers). White box: the ops
 * table is installed in the engine by hand, as the library's model table would. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine_util.h"
#include "../../lib/engine/model.h"

/* ---- the frame: the zmf frame's contact event, counted, declared per_ball ---------- */

static long toi_calls;

static int counted_zmf(const rc_toi_params *prm, const rc_toi_ball *a, const rc_toi_ball *b,
                       rc_toi_workspace *ws, rc_toi_contact *out)
{
    toi_calls++;
    return rc_toi_frame_zmf.toi(prm, a, b, ws, out);
}

static const rc_toi_frame frame_tubes = {
    .name = "test-tubes",
    .summary = "zmf's contact event, each ball's velocity changed at its own event (a test's)",
    .toi = counted_zmf,
    .wall_contracted = 1,
    .contracted = 1,
    .covariant = 1,
    .per_ball = 1,
};

/* ---- its model: every op counted, then the glued tubes' ---------------------------- */

enum {
    OP_EVENT_BEGIN, OP_EVENT_END, OP_CONTACT_EVENT, OP_GROUP_OF_MODEL, OP_BEFORE_RESOLVE,
    OP_UNDO_MEMBER, OP_RESOLVE_MEMBER, OP_MEMBER_BEFORE, OP_TAKE_BACK, OP_AFTER_RESOLVE,
    OP_GROUP_MEMBER, OP_BALL_AT, OP_PAIR_TIME, OP_CANDIDATE_ROWS, OP_EVENT_KEEP, OP_EVENT_RECALL,
    OP_SEGMENT_START, OP_SLICE_GAMMA, OP_N
};
static const char *const op_name[OP_N] = {
    "event_begin", "event_end", "contact_event", "group_of_model", "before_resolve",
    "undo_member", "resolve_member", "member_before", "take_back", "after_resolve",
    "group_member", "ball_at", "pair_time", "candidate_rows", "event_keep", "event_recall",
    "segment_start", "slice_gamma"};
static long op_calls[OP_N];

static void t_event_begin(rc_sim *s, int32_t i, int32_t bp)
{
    op_calls[OP_EVENT_BEGIN]++;
    eng_model_glued.event_begin(s, i, bp);
}
static void t_event_end(rc_sim *s)
{
    op_calls[OP_EVENT_END]++;
    eng_model_glued.event_end(s);
}
static int t_contact_event(rc_sim *s, int32_t i, int32_t bp, double T, eng_event_x *ev)
{
    op_calls[OP_CONTACT_EVENT]++;
    return eng_model_glued.contact_event(s, i, bp, T, ev);
}
static int t_group_of_model(rc_sim *s, int32_t i, int32_t bp, double T, const eng_event_x *ev)
{
    op_calls[OP_GROUP_OF_MODEL]++;
    return eng_model_glued.group_of_model(s, i, bp, T, ev);
}
static int t_before_resolve(rc_sim *s, size_t nm, const rc_particle *P, const rc_particle *Q,
                            const int *changed, const eng_event_x *ev, int undo_order)
{
    op_calls[OP_BEFORE_RESOLVE]++;
    return eng_model_glued.before_resolve(s, nm, P, Q, changed, ev, undo_order);
}
static int t_undo_member(rc_sim *s, int32_t w, int32_t k, double T, const eng_event_x *ev)
{
    op_calls[OP_UNDO_MEMBER]++;
    return eng_model_glued.undo_member(s, w, k, T, ev);
}
static void t_resolve_member(rc_sim *s, size_t j, const rc_particle *P, const rc_particle *Q,
                             int changed, const eng_event_x *ev)
{
    op_calls[OP_RESOLVE_MEMBER]++;
    eng_model_glued.resolve_member(s, j, P, Q, changed, ev);
}
static const eng_ball *t_member_before(const rc_sim *s, size_t j)
{
    op_calls[OP_MEMBER_BEFORE]++;
    return eng_model_glued.member_before(s, j);
}
static void t_take_back(rc_sim *s, size_t j)
{
    op_calls[OP_TAKE_BACK]++;
    eng_model_glued.take_back(s, j);
}
static void t_after_resolve(rc_sim *s, size_t nm, int32_t bp, const rc_particle *P,
                            const rc_vec3 *vold, const eng_event_x *ev, int tc)
{
    op_calls[OP_AFTER_RESOLVE]++;
    eng_model_glued.after_resolve(s, nm, bp, P, vold, ev, tc);
}
static void t_group_member(rc_sim *s, int32_t b, const rc_particle *in, const rc_particle *out)
{
    op_calls[OP_GROUP_MEMBER]++;
    eng_model_glued.group_member(s, b, in, out);
}
static int t_ball_at(const rc_sim *s, size_t i, double t, rc_sim_ball *o, const int32_t **img)
{
    op_calls[OP_BALL_AT]++;
    return eng_model_glued.ball_at(s, i, t, o, img);
}

static double t_pair_time(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                          double tref, double best, int parting, rc_vec3 *n)
{
    op_calls[OP_PAIR_TIME]++;
    return eng_model_glued.pair_time(s, bi, bk, dx, tref, best, parting, n);
}
static void t_candidate_rows(const rc_sim *s, eng_rows *rows)
{
    op_calls[OP_CANDIDATE_ROWS]++;
    eng_model_glued.candidate_rows(s, rows);
}
static void t_event_keep(rc_sim *s, int32_t i)
{
    op_calls[OP_EVENT_KEEP]++;
    eng_model_glued.event_keep(s, i);
}
static void t_event_recall(rc_sim *s, int32_t i)
{
    op_calls[OP_EVENT_RECALL]++;
    eng_model_glued.event_recall(s, i);
}
static double t_segment_start(const rc_sim *s, int32_t k)
{
    op_calls[OP_SEGMENT_START]++;
    return eng_model_glued.segment_start(s, k);
}
static double t_slice_gamma(const rc_sim *s)
{
    op_calls[OP_SLICE_GAMMA]++;
    return eng_model_glued.slice_gamma(s);
}

static const eng_model_ops model_counted = {
    .name = "test-counted-tubes",
    .per_ball = 1,
    .pair_time = t_pair_time,
    .candidate_rows = t_candidate_rows,
    .event_keep = t_event_keep,
    .event_recall = t_event_recall,
    .event_begin = t_event_begin,
    .event_end = t_event_end,
    .contact_event = t_contact_event,
    .group_of_model = t_group_of_model,
    .before_resolve = t_before_resolve,
    .undo_member = t_undo_member,
    .resolve_member = t_resolve_member,
    .member_before = t_member_before,
    .take_back = t_take_back,
    .after_resolve = t_after_resolve,
    .group_member = t_group_member,
    .ball_at = t_ball_at,
    .segment_start = t_segment_start,
    .slice_gamma = t_slice_gamma,
};

/* ---- runs -------------------------------------------------------------------------- */

/* A gas at c = 1 (rms 0.5 c) to t_end through frame (and, if model != NULL, that model
 * installed by hand); its hash, every ball read at the end (kinks ahead read through the
 * model), diagnostics. */
static uint64_t run(const rc_toi_frame *frame, const eng_model_ops *model, int dim, int periodic,
                    double eps, double packing, double v_rms, double t_end, rc_sim_diag *out,
                    uint64_t *slice_hash)
{
    rc_sim_def d = periodic ? util_covariant_periodic(dim) : rc_sim_def_default();
    d.dim = dim;
    d.c = 1.0;
    d.eps_ball = eps;
    d.frame = frame;
    rc_sim *s = util_gas(d, dim == 2 ? 300 : 343, packing, v_rms, 5);
    if (!s)
        return 0;
    ENSURE(s->model == &eng_model_glued); /* (chosen from the frame's per_ball) */
    if (model)
        s->model = model;
    /* a delayed slice at t_end / 4, kept by the model's hooks, read at the end */
    uint32_t id;
    ENSURE(rc_sim_slice_request(s, 0.25 * t_end, &id) == RC_OK);
    const int st = rc_sim_advance(s, t_end, 0);
    ENSURE_MSG(st == RC_OK, "advance: %s", rc_strerror(st));
    double sum = 0.0;
    for (size_t i = 0; i < rc_sim_count(s); i++) {
        rc_sim_ball b;
        ENSURE(rc_sim_get_ball(s, i, &b) == RC_OK);
        sum += b.tau;
    }
    ENSURE(isfinite(sum));
    rc_sim_diagnostics(s, out);
    const uint64_t h = rc_sim_hash(s);
    /* then on to the slice's final time (which a faster segment moves on) */
    rc_sim_slice_info in;
    for (int k = 0; k < 20 && rc_sim_slice_ready(s, id, &in) == 0; k++)
        ENSURE(rc_sim_advance(s, in.t_final, 0) == RC_OK);
    ENSURE(rc_sim_slice_ready(s, id, NULL) == 1);
    *slice_hash = 1469598103934665603ull; /* (FNV-1a over every ball's slice state) */
    for (size_t i = 0; i < rc_sim_count(s); i++) {
        rc_sim_ball b;
        const int sg = rc_sim_slice_get(s, id, i, &b);
        ENSURE_MSG(sg == RC_OK, "slice_get %zu: %s", i, rc_strerror(sg));
        const double v[5] = {b.x.x, b.x.y, b.x.z, b.p.x, b.tau};
        const unsigned char *c = (const unsigned char *)v;
        for (size_t q = 0; q < sizeof v; q++)
            *slice_hash = (*slice_hash ^ c[q]) * 1099511628211ull;
    }
    rc_sim_free(&s);
    return h;
}

static void test_through_ops(void)
{
    long total[OP_N] = {0};
    /* (the last: a dense hot 3-D gas, where the overlap policy decides contacts and finds
     * groups at one table time) */
    for (int run_k = 0; run_k < 9; run_k++) {
        const int dense = run_k == 8, dim = dense ? 3 : 2 + run_k / 4, periodic = run_k / 2 % 2;
        const double eps = run_k % 2 ? 0.5 : 1.0, t_end = dense ? 1.0 : dim == 2 ? 6.0 : 4.0;
        const double packing = dense ? 0.45 : 0.3, v_rms = dense ? 0.9 : 0.5;
        memset(op_calls, 0, sizeof op_calls);
        toi_calls = 0;
        rc_sim_diag dt, dc;
        uint64_t st_, sc_;
        const uint64_t ht = run(&frame_tubes, &model_counted, dim, periodic, eps, packing,
                                v_rms, t_end, &dt, &st_);
        const uint64_t hc = run(&rc_toi_frame_covariant, NULL, dim, periodic, eps, packing,
                                v_rms, t_end, &dc, &sc_);
        ENSURE_MSG(st_ == sc_, "%dD per %d eps %g: the slices differ", dim, periodic, eps);
        ENSURE_MSG(ht == hc, "%dD per %d eps %g: hash %016llx, covariant %016llx", dim,
                   periodic, eps, (unsigned long long)ht, (unsigned long long)hc);
        ENSURE(dt.collisions == dc.collisions && dt.overlaps == dc.overlaps &&
               dt.tube_conflicts == dc.tube_conflicts &&
               dt.order_conflicts == dc.order_conflicts && dt.rollbacks == dc.rollbacks &&
               dt.max_group == dc.max_group &&
               memcmp(dt.events, dc.events, sizeof dt.events) == 0);
        ENSURE(toi_calls > 0 && dt.collisions > 300);
        /* every event goes through the model: begun, ended, its contact placed */
        ENSURE(op_calls[OP_EVENT_BEGIN] >= (long)dt.events[RC_SIM_EV_BALL] &&
               op_calls[OP_CONTACT_EVENT] >= op_calls[OP_BEFORE_RESOLVE] / 2 &&
               op_calls[OP_BEFORE_RESOLVE] > 0 && op_calls[OP_RESOLVE_MEMBER] > 0 &&
               op_calls[OP_AFTER_RESOLVE] > 0 && op_calls[OP_EVENT_END] > 0);
        printf("  %dD %s packing %.2f eps %.1f: %llu collisions (%llu undone, %llu tube, %llu order "
               "conflicts), toi %ld\n", dim, periodic ? "periodic" : "walled", packing, eps,
               (unsigned long long)dt.collisions, (unsigned long long)dt.rollbacks,
               (unsigned long long)dt.tube_conflicts,
               (unsigned long long)dt.order_conflicts, toi_calls);
        for (int k = 0; k < OP_N; k++)
            total[k] += op_calls[k];
    }
    /* over all runs every named point was reached */
    for (int k = 0; k < OP_N; k++) {
        printf("  %-15s %ld\n", op_name[k], total[k]);
        ENSURE_MSG(total[k] > 0, "op %s never called", op_name[k]);
    }
}

/* The instant model (every op NULL) is what a one-instant frame gets, and a per_ball
 * frame at infinite c: the core has nothing to call. */
static void test_instant(void)
{
    ENSURE(eng_model_for(&rc_toi_frame_table, 1, 1.0) == &eng_model_instant);
    ENSURE(eng_model_for(&frame_tubes, 1, 0.0) == &eng_model_instant);
    ENSURE(eng_model_for(&frame_tubes, 1, 1.0) == &eng_model_glued);
    ENSURE(eng_model_for(NULL, 0, 1.0) == &eng_model_instant);
    const eng_model_ops *m = &eng_model_instant;
    ENSURE(!m->pair_time && !m->candidate_rows && !m->event_keep && !m->event_recall &&
           !m->segment_start && !m->slice_gamma);
    ENSURE(!m->per_ball && !m->event_begin && !m->event_end && !m->contact_event &&
           !m->group_of_model && !m->before_resolve && !m->undo_member && !m->resolve_member &&
           !m->member_before && !m->take_back && !m->after_resolve && !m->group_member &&
           !m->ball_at);
}

int main(void)
{
    RUN_TEST(test_instant);
    RUN_TEST(test_through_ops);
    RC_TEST_MAIN_END();
}
