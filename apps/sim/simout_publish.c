/* simout_publish.c — a run's files appear in its folder together, or not at all, by one
 * rename.
 *
 * relcol-sim writes everything into a hidden staging folder beside its outputs,
 * DIR/.run.relcol-PID.XXXXXX/ (a killed run's is removed by the next run: its pid is
 * gone). A run that ends with its state written is published under an exclusive flock on
 * DIR, so that two runs into one folder take turns:
 *   1. the staging folder is renamed DIR/.relcol-run.XXXXXX (the run's folder);
 *   2. each of its top-level names NAME gets the link DIR/NAME -> .relcol-run/NAME
 *      (symlinkat to a temporary name, renameat over NAME: never followed, so a link
 *      planted at NAME is replaced, not written through). While DIR/.relcol-run still
 *      points at the previous run's folder, these links show the previous run's files;
 *   3. the switch: DIR/.relcol-run, a link to the run's folder, is replaced by renameat —
 *      one step after which every name shows the new run's file;
 *   4. tidying: the previous run's folder and the links of names the new run does not
 *      have (which now lead nowhere) are removed. A kill or a failure here leaves only
 *      hidden folders and dangling links, removed by the next publish into DIR.
 * A failure before step 3 removes the run's folder: DIR shows the previous run whole.
 * Nothing under DIR is followed unless this file made it: the folders are opened with
 * O_NOFOLLOW | O_DIRECTORY from DIR's descriptor and files are unlinked, never opened.
 * A folder written by relcol-sim before this scheme (its files in DIR itself, listed in
 * DIR/.relcol_sim_outputs) is converted by the first publish, name by name. */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "simout.h"

#define CURRENT "relcol-run"             /* DIR/.relcol-run -> .relcol-run.XXXXXX */
#define RUNDIR_PREFIX ".relcol-run."     /* a run's folder: this and 6 characters */
#define OLD_MANIFEST ".relcol_sim_outputs" /* the outputs of the earlier scheme */

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

static int is_rundir_name(const char *s)
{
    return strncmp(s, RUNDIR_PREFIX, sizeof RUNDIR_PREFIX - 1) == 0 &&
           strlen(s) == sizeof RUNDIR_PREFIX - 1 + 6 && !strchr(s + 1, '/');
}

/* The run folder DIR/.relcol-run points at (into buf), or "" if none or not one of ours. */
static const char *current_run(int dfd, char *buf, size_t n)
{
    ssize_t k = readlinkat(dfd, "." CURRENT, buf, n - 1);
    buf[k > 0 ? k : 0] = '\0';
    if (!is_rundir_name(buf))
        buf[0] = '\0';
    return buf;
}

/* Whether DIR/name is a link made by step 2: its text is .relcol-run/name exactly. */
static int is_our_link(int dfd, const char *name)
{
    char buf[512], want[512];
    snprintf(want, sizeof want, "." CURRENT "/%s", name);
    ssize_t k = readlinkat(dfd, name, buf, sizeof buf - 1);
    if (k < 0)
        return 0;
    buf[k] = '\0';
    return strcmp(buf, want) == 0;
}

/* Remove the folder name under the folder fd, never following a link inside it. */
static int remove_tree_at(int fd, const char *name)
{
    int sub = openat(fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (sub < 0)
        return errno == ENOENT ? 0 : -1;
    DIR *d = fdopendir(sub);
    if (!d) {
        close(sub);
        return -1;
    }
    int r = 0;
    for (struct dirent *e; (e = readdir(d));) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        struct stat st;
        if (fstatat(sub, e->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISDIR(st.st_mode))
            r |= remove_tree_at(sub, e->d_name);
        else if (unlinkat(sub, e->d_name, 0) != 0 && errno != ENOENT)
            r = -1;
    }
    closedir(d);
    if (unlinkat(fd, name, AT_REMOVEDIR) != 0 && errno != ENOENT)
        r = -1;
    return r;
}

/* The names of the folder fd (without . and the hidden ones). */
static int list_names(int fd, names *out)
{
    int dup_fd = dup(fd);
    DIR *d = dup_fd >= 0 ? fdopendir(dup_fd) : NULL;
    if (!d) {
        if (dup_fd >= 0)
            close(dup_fd);
        return -1;
    }
    rewinddir(d);
    int r = 0;
    for (struct dirent *e; r == 0 && (e = readdir(d));)
        if (e->d_name[0] != '.')
            r = names_add(out, e->d_name);
    closedir(d);
    return r;
}

/* Step 4 (and the repair of a killed publish, at the start of the next): every run folder
 * but the current one, and every link of ours that leads nowhere. 0, or -1 with the first
 * failure in err. */
static int tidy(int dfd, const char *dir, char *err)
{
    char cur[256];
    current_run(dfd, cur, sizeof cur);
    names all = {0};
    int dup_fd = dup(dfd);
    DIR *d = dup_fd >= 0 ? fdopendir(dup_fd) : NULL;
    if (!d) {
        if (dup_fd >= 0)
            close(dup_fd);
        app_errf(err, "cannot list %s: %s", dir, strerror(errno));
        return -1;
    }
    rewinddir(d);
    for (struct dirent *e; (e = readdir(d));)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0 &&
            names_add(&all, e->d_name)) {
            closedir(d);
            names_free(&all);
            app_errf(err, "out of memory");
            return -1;
        }
    closedir(d);
    int r = 0;
    for (size_t i = 0; i < all.n; i++) {
        const char *n = all.v[i];
        struct stat st;
        int bad = 0;
        if (is_rundir_name(n) && strcmp(n, cur) != 0)
            bad = remove_tree_at(dfd, n) != 0;
        else if (is_our_link(dfd, n) && fstatat(dfd, n, &st, 0) != 0 && errno == ENOENT)
            bad = unlinkat(dfd, n, 0) != 0 && errno != ENOENT;
        if (bad && r == 0) {
            app_errf(err, "cannot remove %s/%s: %s", dir, n, strerror(errno));
            r = -1;
        }
    }
    names_free(&all);
    return r;
}

/* The earlier scheme's outputs (DIR/.relcol_sim_outputs: NAME or snapshots/NAME a line). */
static void read_old_manifest(int dfd, names *old)
{
    int fd = openat(dfd, OLD_MANIFEST, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    FILE *f = fd >= 0 ? fdopen(fd, "r") : NULL;
    if (!f) {
        if (fd >= 0)
            close(fd);
        return;
    }
    char line[1100];
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = '\0';
        const char *s = strncmp(line, "snapshots/", 10) == 0 ? line + 10 : line;
        /* a name or snapshots/NAME; anything else is ignored rather than followed */
        if (s[0] != '\0' && s[0] != '.' && !strchr(s, '/') && names_add(old, line))
            break;
    }
    fclose(f);
}

/* The earlier scheme's files under the folder name (DIR itself: ".") that its manifest
 * lists with prefix ("" or "snapshots/") and keep does not have; the folder removed if
 * that empties it (name != "."). */
static void remove_old_files(int dfd, const char *name, const char *prefix, const names *old,
                             const names *keep)
{
    int fd = strcmp(name, ".") == 0 ? dup(dfd)
                                    : openat(dfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0)
        return;
    const size_t k = strlen(prefix);
    for (size_t i = 0; i < old->n; i++) {
        const char *s = old->v[i];
        struct stat st;
        if (strncmp(s, prefix, k) != 0 || strchr(s + k, '/') || names_has(keep, s + k))
            continue;
        if (fstatat(fd, s + k, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode))
            unlinkat(fd, s + k, 0);
    }
    close(fd);
    if (strcmp(name, ".") != 0)
        unlinkat(dfd, name, AT_REMOVEDIR); /* (only if empty: a file of the user's stays) */
}

/* Step 2 for one name: DIR/name -> .relcol-run/name, replacing what was there (by rename:
 * a file, or a link, never followed). */
static int place_link(int dfd, const char *dir, const char *name, char *err)
{
    if (is_our_link(dfd, name))
        return 0;
    char target[512], tmp[600];
    snprintf(target, sizeof target, "." CURRENT "/%s", name);
    /* a temporary named as app_clean_stale removes it if this process is killed */
    static unsigned serial;
    snprintf(tmp, sizeof tmp, ".%s.relcol-%ld.L%05u", name, (long)getpid(), serial++ % 100000u);
    if (symlinkat(target, dfd, tmp) != 0 || renameat(dfd, tmp, dfd, name) != 0) {
        app_errf(err, "cannot link %s/%s to the run's file: %s", dir, name, strerror(errno));
        unlinkat(dfd, tmp, 0);
        return -1;
    }
    return 0;
}

/* Point DIR/.relcol-run at the run folder name: the one step that switches what DIR shows. */
static int switch_current(int dfd, const char *dir, const char *name, char *err)
{
    char tmp[128];
    snprintf(tmp, sizeof tmp, "." CURRENT ".relcol-%ld.S00000", (long)getpid());
    if (symlinkat(name, dfd, tmp) != 0 || renameat(dfd, tmp, dfd, "." CURRENT) != 0) {
        app_errf(err, "cannot switch %s/." CURRENT " to the run's folder: %s", dir, strerror(errno));
        unlinkat(dfd, tmp, 0);
        return -1;
    }
    (void)fsync(dfd);
    return 0;
}

/* A folder of the earlier scheme (its manifest lists files in DIR and DIR/snapshots, and
 * there is no DIR/.relcol-run) made one of this scheme's without a name showing other bytes
 * at any instant: its files hard-linked into a run folder, .relcol-run switched to it, each
 * file replaced by the link that leads to the same bytes, and snapshots/ exchanged with its
 * link (renameat2 RENAME_EXCHANGE). Refused, changing nothing, if snapshots/ holds a file the
 * manifest does not list (the user's). */
static int convert_old(int dfd, const char *dir, const names *old, char *err)
{
    struct stat st;
    if (!old->n || fstatat(dfd, "." CURRENT, &st, AT_SYMLINK_NOFOLLOW) == 0)
        return 0;
    int snapdir = fstatat(dfd, "snapshots", &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISDIR(st.st_mode);
    names in_snap = {0};
    if (snapdir) {
        int fd = openat(dfd, "snapshots", O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        int bad = fd < 0 || list_names(fd, &in_snap);
        for (size_t i = 0; !bad && i < in_snap.n; i++) {
            char rel[600];
            snprintf(rel, sizeof rel, "snapshots/%s", in_snap.v[i]);
            bad = !names_has(old, rel);
        }
        if (fd >= 0)
            close(fd);
        names_free(&in_snap);
        if (bad) {
            app_errf(err, "%s/snapshots holds files that are not a run's (its own, or "
                     "unreadable): move them away; nothing was changed", dir);
            return -1;
        }
    }
    char *t = app_path_join(dir, RUNDIR_PREFIX "XXXXXX");
    if (!t || !mkdtemp(t)) {
        app_errf(err, "cannot convert %s (written by an earlier relcol-sim): %s", dir,
                 t ? strerror(errno) : "out of memory");
        free(t);
        return -1;
    }
    const char *prev = strrchr(t, '/') + 1;
    int pfd = openat(dfd, prev, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    int r = pfd < 0 || (snapdir && mkdirat(pfd, "snapshots", 0777) != 0) ? -1 : 0;
    names top = {0};
    for (size_t i = 0; r == 0 && i < old->n; i++) {
        const char *s = old->v[i];
        if (fstatat(dfd, s, &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(st.st_mode))
            continue; /* (gone, or replaced by something not the run's) */
        if (strncmp(s, "snapshots/", 10) != 0 && names_add(&top, s))
            r = -1;
        else if (linkat(dfd, s, pfd, s, 0) != 0)
            r = -1;
    }
    if (r == 0)
        r = switch_current(dfd, dir, prev, err);
    else
        app_errf(err, "cannot convert %s (written by an earlier relcol-sim): %s", dir, strerror(errno));
    for (size_t i = 0; r == 0 && i < top.n; i++)
        r = place_link(dfd, dir, top.v[i], err);
    if (r == 0 && snapdir) {
        char tmp[128];
        snprintf(tmp, sizeof tmp, ".snapshots.relcol-%ld.X00000", (long)getpid());
        if (symlinkat("." CURRENT "/snapshots", dfd, tmp) != 0 ||
            renameat2(dfd, tmp, dfd, "snapshots", RENAME_EXCHANGE) != 0) {
            app_errf(err, "cannot convert %s/snapshots: %s", dir, strerror(errno));
            unlinkat(dfd, tmp, 0);
            r = -1;
        } else {
            remove_tree_at(dfd, tmp); /* (the old folder: only the run's files, checked above) */
        }
    }
    if (r == 0)
        unlinkat(dfd, OLD_MANIFEST, 0);
    else if (pfd >= 0 && fstatat(dfd, "." CURRENT, &st, AT_SYMLINK_NOFOLLOW) != 0)
        remove_tree_at(dfd, prev); /* (not switched: the folder is as it was) */
    if (pfd >= 0)
        close(pfd);
    names_free(&top);
    free(t);
    return r;
}

static int sync_folder_at(int dfd, const char *name)
{
    int fd = openat(dfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0)
        return errno == ENOENT ? 0 : -1;
    (void)fsync(fd); /* (some file systems refuse fsync on folders) */
    close(fd);
    return 0;
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
    /* mkdtemp makes 0700; the run's folder is read through DIR's links as DIR is */
    mode_t um = umask(0);
    umask(um);
    (void)chmod(t, 0777 & ~um);
    *stage = t;
    return 0;
}

void simout_stage_discard(char *stage)
{
    if (stage)
        app_remove_tree(stage);
    free(stage);
}

int simout_stage_publish(const char *dir, char *stage, char *err, char *warn)
{
    names now = {0}, old = {0};
    int r = -1, sfd = -1, locked = 0;
    char rundir[64] = "", cur[256];
    warn[0] = '\0';
    const char *base = strrchr(stage, '/') ? strrchr(stage, '/') + 1 : stage;
    int dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd < 0 || flock(dfd, LOCK_EX) != 0) {
        app_errf(err, "cannot open the output folder %s: %s", dir, strerror(errno));
        goto done;
    }
    locked = 1;
    /* what a publish killed after its switch left behind */
    if (tidy(dfd, dir, err))
        goto done;
    sfd = openat(dfd, base, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (sfd < 0 || list_names(sfd, &now)) {
        app_errf(err, "cannot list the run's files in %s: %s", stage, strerror(errno));
        goto done;
    }
    /* the entries of the run's folders on disk before the switch names them */
    sync_folder_at(sfd, "snapshots");
    (void)fsync(sfd);
    /* step 1 (the staging folder's random 6 characters, unique among DIR's names) */
    snprintf(rundir, sizeof rundir, RUNDIR_PREFIX "%s", base + strlen(base) - 6);
    if (renameat(dfd, base, dfd, rundir) != 0) {
        app_errf(err, "cannot rename %s to %s/%s: %s", stage, dir, rundir, strerror(errno));
        rundir[0] = '\0';
        goto done;
    }
    read_old_manifest(dfd, &old);
    if (convert_old(dfd, dir, &old, err))
        goto done;
    /* a folder at an output's name is the user's (an empty one is removed): refused before
     * anything is replaced */
    for (size_t i = 0; i < now.n; i++) {
        struct stat st;
        if (fstatat(dfd, now.v[i], &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISDIR(st.st_mode) &&
            unlinkat(dfd, now.v[i], AT_REMOVEDIR) != 0) {
            app_errf(err, "%s/%s is a folder holding files that are not a run's: move it "
                     "away (nothing was changed)", dir, now.v[i]);
            goto done;
        }
    }
    for (size_t i = 0; i < now.n; i++)
        if (place_link(dfd, dir, now.v[i], err))
            goto done;
    /* step 3 */
    if (switch_current(dfd, dir, rundir, err))
        goto done;
    r = 0;
    /* step 4: the run is published; what fails now is reported but changes nothing of it */
    if (old.n) {
        remove_old_files(dfd, ".", "", &old, &now);
        if (!names_has(&now, "snapshots"))
            remove_old_files(dfd, "snapshots", "snapshots/", &old, &now);
        unlinkat(dfd, OLD_MANIFEST, 0);
    }
    if (tidy(dfd, dir, warn)) {
        const size_t len = strlen(warn);
        snprintf(warn + len, APP_ERR_LEN - len, " (the run is published; the next run into "
                 "the folder removes what is left)");
    }
    (void)fsync(dfd);
done:
    if (r && rundir[0] && strcmp(current_run(dfd, cur, sizeof cur), rundir) != 0)
        remove_tree_at(dfd, rundir); /* (its links lead nowhere: tidy removes them) */
    if (r && locked) {
        char ignored[APP_ERR_LEN];
        tidy(dfd, dir, ignored);
    }
    if (sfd >= 0)
        close(sfd);
    if (dfd >= 0)
        close(dfd); /* (and the lock) */
    names_free(&now);
    names_free(&old);
    if (r && !rundir[0])
        simout_stage_discard(stage);
    else
        free(stage);
    return r;
}
