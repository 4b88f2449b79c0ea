/* simout_publish.c — a run's files appear in its folder together, or not at all.
 *
 * relcol-sim writes everything into a hidden staging folder beside its outputs,
 * DIR/.run.relcol-PID.XXXXXX/. When the run ends with its state written (done, stalled,
 * interrupted, or an engine failure whose state is whole) the staged files are moved into
 * DIR by rename, and the files the previous run published there that this run does not
 * replace are removed: DIR then holds this run's files and no others of a run. When an
 * output could not be written (a full disk, a folder taken away) the staging folder is
 * removed and DIR keeps the previous run's files untouched. A run killed outright leaves
 * its staging folder, which the next run into DIR removes (its pid is gone).
 *
 * What a run published is listed in DIR/.relcol_sim_outputs, one relative path a line: a
 * later run removes only those, never a file of the user's that shares a name with an
 * output. The moves are renames within one file system, microseconds each; a kill during
 * them is the one moment a folder can hold parts of two runs. */
#include <dirent.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "simout.h"

#define MANIFEST ".relcol_sim_outputs"

typedef struct names {
    char **v;
    size_t n, cap;
} names;

static int names_add(names *l, const char *s)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 32;
        char **v = realloc(l->v, cap * sizeof *v);
        if (!v)
            return -1;
        l->v = v;
        l->cap = cap;
    }
    if (!(l->v[l->n] = strdup(s)))
        return -1;
    l->n++;
    return 0;
}

static void names_free(names *l)
{
    for (size_t i = 0; i < l->n; i++)
        free(l->v[i]);
    free(l->v);
    memset(l, 0, sizeof *l);
}

static int names_has(const names *l, const char *s)
{
    for (size_t i = 0; i < l->n; i++)
        if (strcmp(l->v[i], s) == 0)
            return 1;
    return 0;
}

/* The regular files of dir (prefix + name each), hidden ones (temporaries) left out. */
static int list_files(const char *dir, const char *prefix, names *out)
{
    DIR *d = opendir(dir);
    if (!d)
        return errno == ENOENT ? 0 : -1;
    int r = 0;
    for (struct dirent *e; r == 0 && (e = readdir(d));) {
        if (e->d_name[0] == '.')
            continue;
        char *p = app_path_join(dir, e->d_name);
        struct stat st;
        if (!p) {
            r = -1;
        } else if (stat(p, &st) == 0 && S_ISREG(st.st_mode)) {
            char rel[1024];
            snprintf(rel, sizeof rel, "%s%s", prefix, e->d_name);
            r = names_add(out, rel);
        }
        free(p);
    }
    closedir(d);
    return r;
}

/* A manifest line is an output's path: a name, or snapshots/NAME; anything else (an
 * edited or foreign file) is ignored rather than followed out of the folder. */
static int plain_output(const char *s)
{
    if (strncmp(s, "snapshots/", 10) == 0)
        s += 10;
    return s[0] != '\0' && s[0] != '.' && !strchr(s, '/');
}

static void read_manifest(const char *dir, names *old)
{
    char *p = app_path_join(dir, MANIFEST);
    FILE *f = p ? fopen(p, "r") : NULL;
    free(p);
    if (!f)
        return;
    char line[1100];
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = '\0';
        if (plain_output(line) && names_add(old, line))
            break;
    }
    fclose(f);
}

static int write_manifest(const char *dir, const names *now, char *err)
{
    char *p = app_path_join(dir, MANIFEST);
    app_atomic a;
    if (!p || app_atomic_open(&a, p, err)) {
        if (!p)
            app_errf(err, "out of memory");
        free(p);
        return -1;
    }
    for (size_t i = 0; i < now->n; i++)
        fprintf(a.f, "%s\n", now->v[i]);
    free(p);
    return app_atomic_commit(&a, err);
}

int simout_stage_open(const char *dir, char **stage, char *err)
{
    *stage = NULL;
    if (app_mkdir_p(dir, err))
        return -1;
    /* the staging folders (and temporaries) of killed runs into this folder */
    app_clean_stale(dir, NULL);
    char *t = app_temp_template(dir, "run");
    if (!t || !mkdtemp(t)) {
        app_errf(err, "cannot create a staging folder in %s: %s", dir,
                 t ? strerror(errno) : "out of memory");
        free(t);
        return -1;
    }
    *stage = t;
    return 0;
}

void simout_stage_discard(char *stage)
{
    if (stage)
        app_remove_tree(stage);
    free(stage);
}

int simout_stage_publish(const char *dir, char *stage, char *err)
{
    names now = {0}, old = {0};
    int r = -1;
    char *snapdir = app_path_join(stage, "snapshots");
    if (!snapdir || list_files(stage, "", &now) || list_files(snapdir, "snapshots/", &now)) {
        app_errf(err, "cannot list the run's files in %s: %s", stage, strerror(errno));
        goto done;
    }
    read_manifest(dir, &old);
    /* the previous run's files this run does not replace */
    for (size_t i = 0; i < old.n; i++) {
        if (names_has(&now, old.v[i]))
            continue;
        char *p = app_path_join(dir, old.v[i]);
        if (p && unlink(p) != 0 && errno != ENOENT) {
            app_errf(err, "cannot remove the previous run's %s: %s", p, strerror(errno));
            free(p);
            goto done;
        }
        free(p);
    }
    int snaps = 0;
    for (size_t i = 0; i < now.n; i++)
        snaps |= strncmp(now.v[i], "snapshots/", 10) == 0;
    if (snaps) {
        char *d = app_path_join(dir, "snapshots");
        int bad = !d || app_mkdir_p(d, err);
        free(d);
        if (bad)
            goto done;
    } else {
        char *d = app_path_join(dir, "snapshots");
        if (d)
            rmdir(d); /* (only if it is empty: a folder of the user's stays) */
        free(d);
    }
    for (size_t i = 0; i < now.n; i++) {
        char *from = app_path_join(stage, now.v[i]), *to = app_path_join(dir, now.v[i]);
        int bad = !from || !to || rename(from, to) != 0;
        if (bad)
            app_errf(err, "cannot move %s into %s: %s", now.v[i], dir,
                     from && to ? strerror(errno) : "out of memory");
        free(from);
        free(to);
        if (bad)
            goto done;
    }
    if (write_manifest(dir, &now, err))
        goto done;
    app_fsync_dir(dir);
    r = 0;
done:
    names_free(&now);
    names_free(&old);
    free(snapdir);
    simout_stage_discard(stage); /* (empty once every file moved) */
    return r;
}
