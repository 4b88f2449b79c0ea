/* fuzz_engine.c — libFuzzer harness for the event-driven engine on small configurations
 * read from the bytes: up to 8 balls on a coarse grid (so that exact ties, touching
 * balls and simultaneous contacts — symmetric racks, head-on pairs, corners — come up
 * all the time), 2-D or 3-D, c = inf or a few c, any of the contact frames, restitution,
 * the TC model, each axis walled or periodic (a byte after the balls: 0, walls, for
 * inputs that end there). The engine must accept or refuse the balls with a documented status,
 * then run 300 events without crashing, hanging or leaving a bad number: every state
 * finite, inside the box, slower than light; energy (kinetic + heat) and momentum (with
 * the walls' impulse) conserved to 1e-9 relative; no heat lost; and a state written
 * after 150 events (rc_sim_sync, read out, loaded with restart = 1) continues bit for bit;
 * so does its checkpoint, read into a new engine, as the run that never stopped; and the
 * checkpoint with one byte changed by the input (its checksum made right again) is read
 * or refused with a documented status, never crashing. Built and run by
 * scripts/fuzz.sh engine. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "relcol/relcol.h"

/* Relative tolerance of the conservation checks: far above the ~1e-13 round-off of 300
 * collisions with compensated sums, far below any real leak (test_engine_conservation
 * holds 1e-10 over 1e6 collisions). */
#define CONS_TOL 1e-9

static uint64_t fnv(const unsigned char *p, size_t n)
{
    uint64_t h = 0xcbf29ce484222325ULL;
    for (size_t k = 0; k < n; k++) {
        h ^= p[k];
        h *= 0x100000001b3ULL;
    }
    return h;
}

typedef struct reader {
    const uint8_t *p;
    size_t n;
} reader;

static unsigned next(reader *r)
{
    if (r->n == 0)
        return 0;
    r->n--;
    return *r->p++;
}

static void fail(const char *what, int st)
{
    fprintf(stderr, "fuzz_engine: %s (status %d: %s)\n", what, st, rc_strerror(st));
    abort();
}

/* After s's first 150 events: its checkpoint continues as the run that never stopped (a
 * fresh engine from the same balls, 300 events), and one byte of it changed (resealed) is
 * read or refused. */
static void checkpoint_checks(const rc_sim_def *d, const rc_sim *s, size_t n,
                              const rc_sim_ball *b, reader *R)
{
    size_t bytes = 0;
    int st = rc_sim_checkpoint_size(s, &bytes);
    unsigned char *buf = st == RC_OK ? malloc(bytes) : NULL;
    if (!buf || (st = rc_sim_checkpoint_write(s, buf, bytes)) != RC_OK)
        fail("checkpoint write", st);
    rc_sim *c = NULL, *ref = NULL;
    if ((st = rc_sim_create(d, &c)) != RC_OK || (st = rc_sim_checkpoint_read(c, buf, bytes)) != RC_OK)
        fail("a checkpoint was refused", st);
    if ((st = rc_sim_create(d, &ref)) != RC_OK || (st = rc_sim_set_balls(ref, n, b, NULL)) != RC_OK)
        fail("the reference run", st);
    if ((st = rc_sim_advance(ref, INFINITY, 300)) != RC_OK || (st = rc_sim_advance(c, INFINITY, 150)) != RC_OK)
        fail("advance failed", st);
    if (rc_sim_hash(ref) != rc_sim_hash(c) || rc_sim_time(ref) != rc_sim_time(c))
        fail("a checkpoint did not continue as the run that never stopped", 0);
    rc_sim_free(&c);
    rc_sim_free(&ref);
    const size_t hi = next(R), lo = next(R);
    const size_t at = (hi << 8 | lo) % (bytes - 8);
    buf[at] ^= (unsigned char)(next(R) | 1u);
    const uint64_t h = fnv(buf, bytes - 8);
    memcpy(buf + bytes - 8, &h, 8);
    if ((st = rc_sim_create(d, &c)) != RC_OK)
        fail("create", st);
    st = rc_sim_checkpoint_read(c, buf, bytes);
    if (!(st == RC_OK || st == RC_ECORRUPT || st == RC_EMISMATCH))
        fail("a changed checkpoint: undocumented status", st);
    rc_sim_free(&c);
    free(buf);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    reader R = {data, size};
    rc_sim_def d = rc_sim_def_default();
    const unsigned h = next(&R);
    d.dim = (h & 1) ? 3 : 2;
    static const double cs[4] = {INFINITY, 1.0, 2.0, 10.0};
    d.c = cs[(h >> 1) & 3];
    static const char *const frames[4] = {"sphere", "table", "zmf", "sphere"};
    d.frame = rc_toi_frame_find(frames[(h >> 3) & 3]);
    d.eps_ball = (h & 0x20) ? 1.0 : (double)next(&R) / 255.0;
    d.eps_wall = (h & 0x40) ? 1.0 : (double)next(&R) / 255.0;
    d.t_c = (h & 0x80) ? 1e-3 : 0.0;
    double L = 4.0;
    const size_t n = 1 + next(&R) % 8;
    rc_sim_ball b[8];
    memset(b, 0, sizeof b);
    /* positions on a 1/16 grid, radii 0.25-0.5 in steps of 1/32 (exact), momenta on a
     * 1/8 grid up to +-2 (and scaled below c for finite c), masses 1/2-4 */
    for (size_t i = 0; i < n; i++) {
        b[i].x = rc_v3(next(&R) % 64 / 16.0, next(&R) % 64 / 16.0,
                       d.dim == 3 ? next(&R) % 64 / 16.0 : 0.0);
        b[i].r = 0.25 + (next(&R) % 9) / 32.0;
        b[i].m = 0.5 + (next(&R) % 8) / 2.0;
        b[i].p = rc_v3(((int)next(&R) - 128) / 64.0, ((int)next(&R) - 128) / 64.0,
                       d.dim == 3 ? ((int)next(&R) - 128) / 64.0 : 0.0);
    }
    /* periodic axes (bit d): the box grows to 4.5, room for four cells of the largest
     * diameter, 1 */
    const unsigned per = next(&R);
    for (int k = 0; k < d.dim; k++)
        d.boundary[k] = (per >> k & 1u) ? RC_SIM_PERIODIC : RC_SIM_WALLS;
    if (per & 7u)
        L = 4.5;
    d.box = rc_v3(L, L, d.dim == 3 ? L : 0.0);
    rc_sim *s = NULL;
    int st = rc_sim_create(&d, &s);
    if (st != RC_OK)
        fail("create refused a valid definition", st);
    size_t bad = 0;
    st = rc_sim_set_balls(s, n, b, &bad);
    if (st != RC_OK) {
        /* overlapping balls or a ball outside the box: documented refusals */
        if (!(st == RC_EOVERLAP || st == RC_EINVAL) || bad >= n)
            fail("set_balls: undocumented refusal", st);
        rc_sim_free(&s);
        return 0;
    }
    rc_sim_diag d0, d1;
    rc_sim_diagnostics(s, &d0);
    st = rc_sim_advance(s, INFINITY, 150);
    if (st != RC_OK)
        fail("advance failed", st);
    checkpoint_checks(&d, s, n, b, &R);
    /* restart identity: the state written now (sync, then the balls read out) continues in
     * a new engine bit for bit as this one does */
    if ((st = rc_sim_sync(s)) != RC_OK)
        fail("sync", st);
    rc_sim_def d2 = d;
    d2.restart = 1;
    rc_sim *s2 = NULL;
    rc_sim_ball w[8];
    for (size_t i = 0; i < n; i++)
        if ((st = rc_sim_get_ball(s, i, &w[i])) != RC_OK)
            fail("get_ball", st);
    if ((st = rc_sim_create(&d2, &s2)) != RC_OK || (st = rc_sim_set_time(s2, rc_sim_time(s))) != RC_OK ||
        (st = rc_sim_set_balls(s2, n, w, NULL)) != RC_OK)
        fail("a written state was refused on restart", st);
    if ((st = rc_sim_advance(s, INFINITY, 150)) != RC_OK || (st = rc_sim_advance(s2, INFINITY, 150)) != RC_OK)
        fail("advance failed", st);
    if (rc_sim_hash(s) != rc_sim_hash(s2) || rc_sim_time(s) != rc_sim_time(s2))
        fail("a restart did not continue bit for bit", 0);
    rc_sim_free(&s2);
    rc_sim_diagnostics(s, &d1);
    if (!isfinite(d1.time) || !(d1.time >= 0.0))
        fail("engine time not finite", 0);
    const double k = isinf(d.c) ? 0.0 : 1.0 / (d.c * d.c);
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball o;
        if (rc_sim_get_ball(s, i, &o) != RC_OK)
            fail("get_ball", 0);
        if (!rc_v3_isfinite(o.x) || !rc_v3_isfinite(o.p) || !(o.m > 0.0) || !isfinite(o.tau))
            fail("a ball's state is not finite", 0);
        const double slack = 1e-9 * L;
        if (o.x.x < -slack || o.x.x > L + slack || o.x.y < -slack || o.x.y > L + slack ||
            (d.dim == 3 && (o.x.z < -slack || o.x.z > L + slack)))
            fail("a ball's centre left the box", 0);
        rc_particle q = {o.m, o.p};
        if (rc_particle_check(&q) != RC_OK)
            fail("a ball's state is refused by the library", 0);
        (void)k;
    }
    const double escale = fabs(d0.energy) > 0.0 ? fabs(d0.energy) : 1.0;
    if (!(fabs(d1.energy - d0.energy) <= CONS_TOL * escale))
        fail("energy not conserved", 0);
    if (!(d1.heat >= -CONS_TOL * escale))
        fail("heat went negative", 0);
    const rc_vec3 dp = rc_v3_sub(rc_v3_add(d1.momentum, d1.wall_impulse),
                                 rc_v3_add(d0.momentum, d0.wall_impulse));
    const double pscale = d0.momentum_scale > 0.0 ? d0.momentum_scale : 1.0;
    if (!(rc_v3_norm(dp) <= CONS_TOL * (pscale + rc_v3_norm(d1.wall_impulse))))
        fail("momentum (with the walls') not conserved", 0);
    if (getenv("FUZZ_VERBOSE")) /* (what a replay exercised) */
        printf("%zu balls, %dD, c %g, frame %s: %llu collisions, %llu in groups\n", n, d.dim,
               d.c, d.frame ? d.frame->name : "sphere", (unsigned long long)d1.collisions,
               (unsigned long long)d1.events[RC_SIM_EV_MULTI]);
    rc_sim_free(&s);
    return 0;
}
