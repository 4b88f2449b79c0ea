/* test_engine_checkpoint.c — a run does not depend on what was read from it or on where it
 * was stopped and continued.
 * 1. Passive outputs: a run to T against the same run advanced in irregular pieces with
 *    balls, diagnostics and hashes read between them: the same bits.
 * 2. Exact restarts: the same run stopped at three points -- one of them in the middle of
 *    an event batch (max_events: where Ctrl-C stops relcol-sim) -- written with
 *    rc_sim_checkpoint_write, read into a new engine and continued: the same bits and the
 *    same diagnostics at T. 2-D and 3-D, classical and c = 1 in every frame, eps < 1 with
 *    the TC model.
 * 3. Refusals: a truncated or damaged checkpoint, one whose checksum was recomputed over a
 *    bad partner index or a doctored velocity, and one read under another definition. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine_util.h"

typedef struct config {
    int dim;
    double c;
    const char *frame;
    double eps, t_c;
} config;

static rc_sim_def def_of(const config *k)
{
    rc_sim_def d = rc_sim_def_default();
    d.dim = k->dim;
    d.c = k->c;
    d.eps_ball = k->eps;
    d.eps_wall = k->eps < 1.0 ? 0.95 : 1.0;
    d.t_c = k->t_c;
    d.frame = k->frame ? rc_toi_frame_find(k->frame) : NULL;
    return d;
}

/* A melted-from-the-lattice gas of the configuration; *box gets the gas's box. */
static rc_sim *start(const config *k, rc_vec3 *box)
{
    rc_sim_def d = def_of(k);
    const size_t n = k->dim == 2 ? 300 : 400;
    rc_sim_gas_def g = {k->dim, n, 0.5, 0.3, isinf(k->c) ? 1.0 : 0.6, k->c, 1.0, 7};
    rc_sim_ball *b = malloc(n * sizeof *b);
    rc_sim *s = NULL;
    ENSURE(b && rc_sim_gas_init(&g, &d.box, b) == RC_OK);
    ENSURE(rc_sim_create(&d, &s) == RC_OK && rc_sim_set_balls(s, n, b, NULL) == RC_OK);
    *box = d.box;
    free(b);
    return s;
}

/* Copy s through a checkpoint into a new engine of definition d. */
static rc_sim *through_checkpoint(const rc_sim *s, rc_sim_def d)
{
    size_t bytes = 0;
    ENSURE(rc_sim_checkpoint_size(s, &bytes) == RC_OK && bytes > 0);
    unsigned char *buf = malloc(bytes);
    rc_sim *t = NULL;
    ENSURE(buf && rc_sim_checkpoint_write(s, buf, bytes) == RC_OK);
    d.restart = 1; /* (irrelevant to a checkpoint: it is not re-validated as new balls) */
    ENSURE(rc_sim_create(&d, &t) == RC_OK);
    int st = rc_sim_checkpoint_read(t, buf, bytes);
    ENSURE_MSG(st == RC_OK, "reading a checkpoint: %s", rc_strerror(st));
    ENSURE(rc_sim_hash(t) == rc_sim_hash(s) && rc_sim_time(t) == rc_sim_time(s));
    /* the read-out too (the hash sees the stored lines; per_ball frames read a ball whose
     * kink lies ahead from the lines recorded before it, which the checkpoint carries) */
    for (size_t i = 0; t && i < rc_sim_count(s); i++) {
        rc_sim_ball x, y;
        rc_sim_get_ball(s, i, &x);
        rc_sim_get_ball(t, i, &y);
        ENSURE(memcmp(&x.x, &y.x, sizeof x.x) == 0 && memcmp(&x.p, &y.p, sizeof x.p) == 0 &&
               x.m == y.m && x.tau == y.tau && x.collided == y.collided &&
               x.tau_last == y.tau_last && rc_sim_kink_ahead(s, i) == rc_sim_kink_ahead(t, i));
    }
    free(buf);
    return t;
}

static void same_diag(const rc_sim *a, const rc_sim *b, const char *what)
{
    rc_sim_diag x, y;
    rc_sim_diagnostics(a, &x);
    rc_sim_diagnostics(b, &y);
    ENSURE_MSG(x.collisions == y.collisions && x.overlaps == y.overlaps &&
                   memcmp(x.events, y.events, sizeof x.events) == 0 && x.heat == y.heat &&
                   memcmp(&x.wall_impulse, &y.wall_impulse, sizeof x.wall_impulse) == 0 &&
                   memcmp(x.wall_impulse_by_wall, y.wall_impulse_by_wall,
                          sizeof x.wall_impulse_by_wall) == 0 &&
                   memcmp(x.overlaps_by_kind, y.overlaps_by_kind, sizeof x.overlaps_by_kind) == 0 &&
                   x.group_sequential == y.group_sequential && x.wall_shared == y.wall_shared && x.pinned == y.pinned &&
                   x.group_fallbacks == y.group_fallbacks && x.max_group == y.max_group &&
                   x.tube_conflicts == y.tube_conflicts &&
                   x.order_conflicts == y.order_conflicts && x.rollbacks == y.rollbacks &&
                   memcmp(x.virial, y.virial, sizeof x.virial) == 0 &&
                   memcmp(x.virial_energy, y.virial_energy, sizeof x.virial_energy) == 0 &&
                   memcmp(x.helfand_wrap, y.helfand_wrap, sizeof x.helfand_wrap) == 0 &&
                   memcmp(x.helfand_wrap_energy, y.helfand_wrap_energy,
                          sizeof x.helfand_wrap_energy) == 0,
               "%s: diagnostics differ (collisions %llu / %llu)", what,
               (unsigned long long)x.collisions, (unsigned long long)y.collisions);
}

static void check_config(const config *k)
{
    char what[128];
    snprintf(what, sizeof what, "%dD c %g %s eps %g", k->dim, k->c, k->frame ? k->frame : "-",
             k->eps);
    rc_vec3 box;
    const double T = 30.0;
    /* the reference: one go */
    rc_sim *ref = start(k, &box);
    if (!ref)
        return;
    ENSURE(rc_sim_advance(ref, T, 0) == RC_OK);
    rc_sim_diag dr;
    rc_sim_diagnostics(ref, &dr);
    ENSURE_MSG(dr.collisions > 2000, "%s: only %llu collisions", what,
               (unsigned long long)dr.collisions);
    /* (the per_ball undo records are part of the state: a run that undoes collisions) */
    if (k->frame && strcmp(k->frame, "covariant") == 0)
        ENSURE_MSG(dr.rollbacks > 10, "%s: only %llu rollbacks", what,
                   (unsigned long long)dr.rollbacks);

    /* 1. outputs read at irregular times */
    rc_sim *s = start(k, &box);
    const double outs[] = {0.0, 0.37, 1.0, 2.718281828, 7.5, 7.5000001, 19.0, 29.999};
    for (size_t j = 0; j < sizeof outs / sizeof *outs; j++) {
        ENSURE(rc_sim_advance(s, outs[j], 0) == RC_OK);
        rc_sim_ball b;
        for (size_t i = 0; i < rc_sim_count(s); i++)
            rc_sim_get_ball(s, i, &b);
        rc_sim_diag d;
        rc_sim_diagnostics(s, &d);
        (void)rc_sim_hash(s);
    }
    ENSURE(rc_sim_advance(s, T, 0) == RC_OK);
    ENSURE_MSG(rc_sim_hash(s) == rc_sim_hash(ref), "%s: outputs changed the run", what);
    same_diag(s, ref, what);
    rc_sim_free(&s);

    /* 2. stopped at 4.2 (after the batch), in the middle of a batch of events, and at 21 */
    rc_sim_def d = def_of(k);
    s = start(k, &box);
    d.box = box;
    ENSURE(rc_sim_advance(s, 4.2, 0) == RC_OK);
    rc_sim *t = through_checkpoint(s, d);
    rc_sim_free(&s);
    ENSURE(rc_sim_advance(t, T, 1234) == RC_OK); /* stops after 1234 events, mid-run */
    ENSURE(rc_sim_time(t) < T);
    s = through_checkpoint(t, d);
    rc_sim_free(&t);
    ENSURE(rc_sim_advance(s, 21.0, 0) == RC_OK);
    t = through_checkpoint(s, d);
    rc_sim_free(&s);
    ENSURE(rc_sim_advance(t, T, 0) == RC_OK);
    ENSURE_MSG(rc_sim_hash(t) == rc_sim_hash(ref), "%s: a continued run differs", what);
    same_diag(t, ref, what);
    rc_sim_free(&t);
    rc_sim_free(&ref);
}

static void test_identity(void)
{
    const config cs[] = {
        {2, INFINITY, NULL, 1.0, 0.0},      {3, INFINITY, NULL, 1.0, 0.0},
        {2, INFINITY, NULL, 0.8, 0.05},     {3, 1.0, "sphere", 1.0, 0.0},
        {2, 1.0, "table", 1.0, 0.0},        {3, 1.0, "table", 0.9, 0.05},
        {2, 1.0, "zmf", 0.9, 0.05},         {3, 1.0, "zmf", 1.0, 0.0},
        {2, 1.0, "covariant", 0.9, 0.05},   {3, 1.0, "covariant", 1.0, 0.0},
    };
    for (size_t j = 0; j < sizeof cs / sizeof *cs; j++)
        check_config(&cs[j]);
}

static uint64_t fnv(const unsigned char *p, size_t n)
{
    uint64_t h = 0xcbf29ce484222325ULL;
    for (size_t k = 0; k < n; k++) {
        h ^= p[k];
        h *= 0x100000001b3ULL;
    }
    return h;
}

/* the checksum of a doctored checkpoint made right again: only the checks of content stand */
static void reseal(unsigned char *buf, size_t bytes)
{
    const uint64_t h = fnv(buf, bytes - 8);
    memcpy(buf + bytes - 8, &h, 8);
}

static void test_refusals(void)
{
    const config k = {2, 1.0, "table", 0.9, 0.05};
    rc_vec3 box;
    rc_sim *s = start(&k, &box);
    if (!s)
        return;
    ENSURE(rc_sim_advance(s, 3.0, 0) == RC_OK);
    size_t bytes = 0;
    rc_sim_checkpoint_size(s, &bytes);
    unsigned char *buf = malloc(bytes), *bad = malloc(bytes);
    ENSURE(rc_sim_checkpoint_write(s, buf, bytes) == RC_OK);
    ENSURE(rc_sim_checkpoint_write(s, buf, bytes - 1) == RC_EINVAL);
    rc_sim_def d = def_of(&k);
    d.box = box;
    rc_sim *t = NULL;
    ENSURE(rc_sim_create(&d, &t) == RC_OK);
    /* truncated, and every 97th byte flipped in turn (the checksum) */
    ENSURE(rc_sim_checkpoint_read(t, buf, bytes - 8) == RC_ECORRUPT);
    ENSURE(rc_sim_checkpoint_read(t, buf, 10) == RC_ECORRUPT);
    int missed = 0;
    for (size_t j = 0; j < bytes; j += 97) {
        memcpy(bad, buf, bytes);
        bad[j] ^= 0x10;
        missed += rc_sim_checkpoint_read(t, bad, bytes) == RC_OK;
    }
    ENSURE_MSG(missed == 0, "%d damaged checkpoints read", missed);
    ENSURE(rc_sim_count(t) == 0);
    /* resealed content: the header's dimension, a ball's partner out of range, a velocity
     * that is not p / M, a count of balls larger than the bytes hold */
    const size_t header = 8 + 4 * 6 + 8 * 3 + 4 * 2;
    /* now, the renumbering clock, the bookkeeping: 20 sums, 24 transfer moments,
     * 21 + RC_SIM_EV_NKINDS counts, the 4 words of the progress check, the walls' 12
     * energy and 36 momentum sums and the wall stream's state */
    const size_t scalars = 8 * (2 + 20 + 24 + 21 + RC_SIM_EV_NKINDS + 4 + 12 + 36 + 1);
    const size_t n = rc_sim_count(s), ball0 = header + scalars, aux0 = ball0 + 64 * n;
    struct { size_t at; size_t len; unsigned char val[8]; int want; } cases[] = {
        {8 + 4 * 5, 4, {3, 0, 0, 0}, RC_EMISMATCH},             /* dim 3 */
        {8, 4, {4, 0, 0, 0}, RC_EMISMATCH}, /* format 4 (before the undo records) */
        {aux0 + 48, 4, {0xff, 0xff, 0xff, 0x7f}, RC_ECORRUPT},  /* ev_partner INT32_MAX */
        {ball0 + 24, 1, {0x01}, RC_ECORRUPT},                   /* v.x's last bit */
        {aux0 + 56, 4, {0xff, 0xff, 0, 0}, RC_ECORRUPT},        /* cell 65535 */
        {8 + 4 * 6 + 8, 8, {0xff, 0xff, 0xff, 0x0f}, RC_ECORRUPT}, /* n */
    };
    for (size_t j = 0; j < sizeof cases / sizeof *cases; j++) {
        memcpy(bad, buf, bytes);
        if (cases[j].len == 1)
            bad[cases[j].at] ^= cases[j].val[0];
        else
            memcpy(bad + cases[j].at, cases[j].val, cases[j].len);
        reseal(bad, bytes);
        int st = rc_sim_checkpoint_read(t, bad, bytes);
        ENSURE_MSG(st == cases[j].want, "case %zu: %s", j, rc_strerror(st));
    }
    rc_sim_free(&t);
    /* another definition: eps, c, frame */
    rc_sim_def o = d;
    o.eps_ball = 0.8;
    ENSURE(rc_sim_create(&o, &t) == RC_OK && rc_sim_checkpoint_read(t, buf, bytes) == RC_EMISMATCH);
    rc_sim_free(&t);
    o = d;
    o.frame = rc_toi_frame_find("zmf");
    ENSURE(rc_sim_create(&o, &t) == RC_OK && rc_sim_checkpoint_read(t, buf, bytes) == RC_EMISMATCH);
    rc_sim_free(&t);
    /* and the unchanged bytes still read */
    ENSURE(rc_sim_create(&d, &t) == RC_OK && rc_sim_checkpoint_read(t, buf, bytes) == RC_OK);
    ENSURE(rc_sim_hash(t) == rc_sim_hash(s));
    rc_sim_free(&t);
    rc_sim_free(&s);
    free(buf);
    free(bad);
}

int main(void)
{
    RUN_TEST(test_identity);
    RUN_TEST(test_refusals);
    RC_TEST_MAIN_END();
}
