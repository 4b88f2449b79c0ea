/* files.c — output files that are never seen half-written: write beside the target under
 * a temporary name, fsync, rename over it (atomic on POSIX), fsync the folder. */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app.h"

char *app_path_join(const char *dir, const char *name)
{
    size_t a = strlen(dir), b = strlen(name);
    char *s = malloc(a + b + 2);
    if (!s)
        return NULL;
    memcpy(s, dir, a);
    size_t k = a;
    if (a > 0 && dir[a - 1] != '/')
        s[k++] = '/';
    memcpy(s + k, name, b + 1);
    return s;
}

/* The folder part of path ("." if none), malloc'ed. */
static char *dir_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        return strdup(".");
    if (slash == path)
        return strdup("/");
    return strndup(path, (size_t)(slash - path));
}

int app_mkdir_p(const char *dir, char *err)
{
    char *s = strdup(dir);
    if (!s) {
        app_errf(err, "out of memory");
        return -1;
    }
    for (char *p = s + 1;; p++) {
        if (*p == '/' || *p == '\0') {
            char save = *p;
            *p = '\0';
            if (mkdir(s, 0777) != 0 && errno != EEXIST) {
                app_errf(err, "cannot create folder %s: %s", s, strerror(errno));
                free(s);
                return -1;
            }
            *p = save;
            if (save == '\0')
                break;
        }
    }
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        app_errf(err, "%s exists and is not a folder", dir);
        free(s);
        return -1;
    }
    free(s);
    return 0;
}

char *app_temp_template(const char *dir, const char *base)
{
    char pid[32];
    snprintf(pid, sizeof pid, "%ld", (long)getpid());
    char *t = malloc(strlen(dir) + strlen(base) + strlen(pid) + 32);
    if (t)
        sprintf(t, "%s/.%s.relcol-%s.XXXXXX", dir, base, pid);
    return t;
}

void app_fsync_dir(const char *dir)
{
    /* (some file systems refuse fsync on folders: then the rename is as durable as they make it) */
    int dfd = open(dir, O_RDONLY | O_DIRECTORY);
    if (dfd >= 0) {
        (void)fsync(dfd);
        close(dfd);
    }
}

void app_remove_tree(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return;
    if (S_ISDIR(st.st_mode)) {
        DIR *d = opendir(path);
        if (d) {
            for (struct dirent *e; (e = readdir(d));) {
                if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
                    continue;
                char *p = app_path_join(path, e->d_name);
                if (p)
                    app_remove_tree(p);
                free(p);
            }
            closedir(d);
        }
        rmdir(path);
    } else {
        unlink(path);
    }
}

void app_clean_stale(const char *dir, const char *base)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    const size_t nb = base ? strlen(base) : 0;
    for (struct dirent *e; (e = readdir(d));) {
        /* .BASE.relcol-PID.XXXXXX (any BASE without base), and nothing else */
        const char *n = e->d_name, *tag = base ? n + 1 + nb : strstr(n, ".relcol-");
        if (n[0] != '.' || (base && strncmp(n + 1, base, nb) != 0) || !tag ||
            strncmp(tag, ".relcol-", 8) != 0)
            continue;
        char *end = NULL;
        errno = 0;
        const long pid = strtol(tag + 8, &end, 10);
        if (errno || pid <= 0 || *end != '.' || strlen(end + 1) != 6)
            continue;
        /* its writer is gone (killed, or the machine stopped): no run will finish it */
        if (pid != (long)getpid() && kill((pid_t)pid, 0) != 0 && errno == ESRCH) {
            char *f = app_path_join(dir, n);
            if (f)
                app_remove_tree(f); /* a temporary, or a run's staging folder */
            free(f);
        }
    }
    closedir(d);
}

/* The stale temporaries of every name in dir, once per folder in a run of folders (the
 * snapshots of a run share one: a scan each would be quadratic in their number). */
static void clean_once(const char *dir)
{
    static char last[4096];
    if (strlen(dir) < sizeof last && strcmp(dir, last) == 0)
        return;
    app_clean_stale(dir, NULL);
    snprintf(last, sizeof last, "%s", dir);
}

int app_atomic_open(app_atomic *a, const char *path, char *err)
{
    memset(a, 0, sizeof *a);
    char *dir = dir_of(path);
    const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    a->path = strdup(path);
    a->tmp = dir ? app_temp_template(dir, base) : NULL;
    if (!a->path || !a->tmp) {
        free(dir);
        app_atomic_abort(a);
        app_errf(err, "out of memory");
        return -1;
    }
    /* hidden, in the same folder: rename() is atomic only within one file system; named
     * with our pid, so that a later run can tell a killed writer's temporary from a live
     * one's and remove it */
    clean_once(dir);
    free(dir);
    int fd = mkstemp(a->tmp);
    if (fd < 0) {
        app_errf(err, "cannot create a temporary file for %s: %s", path, strerror(errno));
        free(a->tmp);
        a->tmp = NULL;
        app_atomic_abort(a);
        return -1;
    }
    app_interrupt_guard(a->tmp);
    /* mkstemp makes 0600; give the final file the usual 0666 & ~umask */
    mode_t um = umask(0);
    umask(um);
    if (fchmod(fd, 0666 & ~um) != 0 || !(a->f = fdopen(fd, "w"))) {
        app_errf(err, "cannot open %s: %s", a->tmp, strerror(errno));
        close(fd);
        app_atomic_abort(a);
        return -1;
    }
    return 0;
}

void app_atomic_abort(app_atomic *a)
{
    if (a->f)
        fclose(a->f);
    if (a->tmp)
        unlink(a->tmp);
    app_interrupt_forget(a->tmp);
    free(a->tmp);
    free(a->path);
    memset(a, 0, sizeof *a);
}

int app_atomic_commit(app_atomic *a, char *err)
{
    if (fflush(a->f) != 0 || ferror(a->f) || fsync(fileno(a->f)) != 0) {
        app_errf(err, "cannot write %s: %s", a->path, strerror(errno));
        app_atomic_abort(a);
        return -1;
    }
    FILE *f = a->f;
    a->f = NULL;
    if (fclose(f) != 0) {
        app_errf(err, "cannot write %s: %s", a->path, strerror(errno));
        app_atomic_abort(a);
        return -1;
    }
    if (rename(a->tmp, a->path) != 0) {
        app_errf(err, "cannot rename %s to %s: %s", a->tmp, a->path, strerror(errno));
        app_atomic_abort(a);
        return -1;
    }
    /* make the rename itself durable */
    app_interrupt_forget(a->tmp);
    char *dir = dir_of(a->path);
    if (dir)
        app_fsync_dir(dir);
    free(dir);
    free(a->tmp);
    a->tmp = NULL;
    app_atomic_abort(a); /* frees path; tmp is gone, so nothing is unlinked */
    return 0;
}

int app_atomic_open_in(app_atomic *a, const char *dir, const char *name, char *err)
{
    char *path = app_path_join(dir, name);
    if (!path) {
        app_errf(err, "out of memory");
        return -1;
    }
    int rc = app_atomic_open(a, path, err);
    free(path);
    return rc;
}
