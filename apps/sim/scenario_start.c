/* scenario_start.c — an engine at a scenario's start: the checkpoint the scenario names,
 * checked against its balls, or its balls at its time. One place for relcol-sim and for
 * the Python package (relcol.Sim), so that both start a run, and refuse one, alike. */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "scenario.h"

unsigned char *scn_read_bytes(const char *path, size_t *bytes)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 1 << 20, n = 0;
    unsigned char *buf = malloc(cap);
    while (buf) {
        n += fread(buf + n, 1, cap - n, f);
        if (n < cap || ferror(f))
            break;
        unsigned char *nb = cap < ((size_t)1 << 40) ? realloc(buf, cap *= 2) : NULL;
        if (!nb) {
            free(buf);
            errno = ENOMEM;
        }
        buf = nb;
    }
    if (buf && ferror(f)) {
        free(buf);
        buf = NULL;
        errno = EIO;
    }
    fclose(f);
    *bytes = n;
    return buf;
}

/* Continue from the checkpoint the scenario names (beside the scenario file): the engine
 * takes the whole state it holds, which must be the state of the scenario's balls, to the
 * bit (the balls are the readable copy; the checkpoint alone carries the scheduled events
 * that make the continuation exact). 0, or -1 with the reason in err. */
static int load_checkpoint(rc_sim *sim, const scn_scenario *s, const char *file, char *err)
{
    const char *slash = strrchr(file, '/');
    char *dir = slash ? strndup(file, (size_t)(slash - file) + (slash == file)) : strdup(".");
    char *path = dir ? app_path_join(dir, s->checkpoint) : NULL;
    free(dir);
    if (!path) {
        app_errf(err, "out of memory");
        return -1;
    }
    size_t bytes = 0;
    unsigned char *buf = scn_read_bytes(path, &bytes);
    int r = -1;
    if (!buf) {
        app_errf(err, "%s: checkpoint: cannot read %s: %s", file, path, strerror(errno));
        goto done;
    }
    int st = rc_sim_checkpoint_read(sim, buf, bytes);
    if (st != RC_OK) {
        app_errf(err, "%s: checkpoint: %s: %s", file, path, rc_strerror(st));
        goto done;
    }
    if (rc_sim_count(sim) != s->n || rc_sim_time(sim) != s->time) {
        app_errf(err, "%s: checkpoint: %s holds %zu balls at t = %.17g, the scenario %zu at "
                 "t = %.17g: not this run's state", file, path, rc_sim_count(sim),
                 rc_sim_time(sim), s->n, s->time);
        goto done;
    }
    for (size_t i = 0; i < s->n; i++) {
        rc_sim_ball b;
        const rc_sim_ball *w = &s->balls[i];
        rc_sim_get_ball(sim, i, &b);
        if (memcmp(&b.x, &w->x, sizeof b.x) || memcmp(&b.p, &w->p, sizeof b.p) ||
            b.r != w->r || b.m != w->m || b.tau != w->tau) {
            app_errf(err, "%s: balls[%zu]: differs from the state in the checkpoint %s (edit "
                     "the balls and delete the \"checkpoint\" key to start afresh from them)",
                     file, i, path);
            goto done;
        }
    }
    r = 0;
done:
    free(buf);
    free(path);
    return r;
}

/* The bytes an engine of s's definition holds with the first k of its balls (0: it could
 * not be made). */
static size_t probe_bytes(const scn_scenario *s, size_t k)
{
    rc_sim_def def = scn_sim_def(s);
    rc_sim *p = NULL;
    size_t bad = 0, b = 0;
    if (rc_sim_create(&def, &p) == RC_OK && rc_sim_set_time(p, s->time) == RC_OK &&
        rc_sim_set_balls(p, k, s->balls, &bad) == RC_OK)
        b = rc_sim_bytes(p);
    rc_sim_free(&p);
    return b;
}

/* About the bytes the engine needs for s's n balls (rc_sim_bytes): measured on engines of
 * s's definition holding its first k and 2k balls -- what the box costs counted once, the
 * rest per ball -- and extrapolated to n. 0 if those cannot be made either. */
static size_t engine_bytes(const scn_scenario *s)
{
    const size_t k = s->n / 2 < 4096 ? s->n / 2 : 4096;
    const size_t b1 = k ? probe_bytes(s, k) : 0, b2 = b1 ? probe_bytes(s, 2 * k) : 0;
    if (!b2 || b2 < b1)
        return 0;
    const double need = (double)b1 + (double)(b2 - b1) / (double)k * (double)(s->n - k);
    return need < (double)SIZE_MAX ? (size_t)need : SIZE_MAX;
}

int scn_start(rc_sim *sim, const scn_scenario *s, const char *file, char *err)
{
    if (s->checkpoint)
        return load_checkpoint(sim, s, file, err);
    size_t bad = 0;
    int st = rc_sim_set_time(sim, s->time);
    if (st == RC_OK)
        st = rc_sim_set_balls(sim, s->n, s->balls, &bad);
    if (st == RC_OK)
        return 0;
    if (st == RC_ENOMEM) { /* (not a ball's fault: the whole set's size) */
        const size_t need = engine_bytes(s), have = s->n * sizeof *s->balls;
        if (need)
            app_errf(err, "%s: balls: out of memory for %zu balls: the engine needs about "
                     "%zu bytes (%.3g GiB) for them, beside the %zu bytes (%.3g GiB) of their "
                     "description", file, s->n, need, (double)need / 1073741824.0, have,
                     (double)have / 1073741824.0);
        else
            app_errf(err, "%s: balls: out of memory for %zu balls: their description alone "
                     "takes %zu bytes (%.3g GiB), and an engine for a few of them could not "
                     "be made", file, s->n, have, (double)have / 1073741824.0);
        return -1;
    }
    app_errf(err, "%s: balls[%zu]: %s", file, bad,
             st == RC_EOVERLAP ? "overlaps another ball"
             : st == RC_EINVAL ? "the ball's shape is not inside the box"
                               : rc_strerror(st));
    return -1;
}

/* name.ckpt: the engine's whole state (rc_sim_checkpoint_write), written atomically */
static int save_checkpoint(const char *path, const rc_sim *sim, char *err)
{
    size_t bytes = 0;
    unsigned char *buf = NULL;
    app_atomic a;
    int r = -1, st = rc_sim_checkpoint_size(sim, &bytes);
    if (st != RC_OK) {
        app_errf(err, "cannot make the checkpoint: %s", rc_strerror(st));
        goto done;
    }
    if (!(buf = malloc(bytes ? bytes : 1))) {
        app_errf(err, "cannot make the checkpoint: out of memory for its %zu bytes (%.3g GiB)",
                 bytes, (double)bytes / 1073741824.0);
        goto done;
    }
    if ((st = rc_sim_checkpoint_write(sim, buf, bytes)) != RC_OK) {
        app_errf(err, "cannot make the checkpoint: %s", rc_strerror(st));
        goto done;
    }
    if (app_atomic_open(&a, path, err))
        goto done;
    if (fwrite(buf, 1, bytes, a.f) != bytes) {
        app_atomic_abort(&a);
        app_errf(err, "cannot write %s", path);
        goto done;
    }
    r = app_atomic_commit(&a, err);
done:
    free(buf);
    return r;
}

int scn_save(const char *dir, const char *name, const scn_scenario *s, const rc_sim *sim,
             double t_end, char *err)
{
    const size_t len = strlen(name);
    char *ck = malloc(len + 6), *js = malloc(len + 6);
    char *ck_path = NULL, *js_path = NULL;
    size_t n = rc_sim_count(sim);
    rc_sim_ball *b = malloc((n ? n : 1) * sizeof *b);
    int r = -1;
    if (ck && js && b) {
        snprintf(ck, len + 6, "%s.ckpt", name);
        snprintf(js, len + 6, "%s.json", name);
        ck_path = app_path_join(dir, ck);
        js_path = app_path_join(dir, js);
    }
    if (!b) {
        app_errf(err, "cannot write %s.json: out of memory for a copy of its %zu balls "
                 "(%zu bytes, %.3g GiB)", name, n, n * sizeof *b,
                 (double)(n * sizeof *b) / 1073741824.0);
        goto done;
    }
    if (!ck_path || !js_path) {
        app_errf(err, "out of memory");
        goto done;
    }
    if (save_checkpoint(ck_path, sim, err))
        goto done;
    for (size_t i = 0; i < n; i++)
        rc_sim_get_ball(sim, i, &b[i]);
    scn_scenario next = *s;
    next.checkpoint = ck;
    app_atomic a;
    if (app_atomic_open(&a, js_path, err))
        goto done;
    if (scn_write(a.f, &next, rc_sim_time(sim), t_end, n, b)) {
        app_atomic_abort(&a);
        app_errf(err, "cannot write %s", js_path);
        goto done;
    }
    r = app_atomic_commit(&a, err);
done:
    free(b);
    free(ck);
    free(js);
    free(ck_path);
    free(js_path);
    return r;
}
