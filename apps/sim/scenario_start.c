/* scenario_start.c — an engine at a scenario's start: the checkpoint the scenario names,
 * checked against its balls, or its balls at its time. One place for relcol-sim and for
 * the Python package (relcol.Sim), so that both start a run, and refuse one, alike. */
#include <errno.h>
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
    if (st != RC_OK || !(buf = malloc(bytes ? bytes : 1))) {
        app_errf(err, "cannot make the checkpoint: %s", st != RC_OK ? rc_strerror(st) : "out of memory");
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
