/* gnuplot.c — run an app's gnuplot script when gnuplot is installed; without it the CSV
 * and the script are the product, so its absence is a note, not an error. The figure is
 * written under a temporary name and renamed, like every other output file. The apps'
 * PNG scripts open with the same lines, written here once (app_gnuplot_head). */
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app.h"

int app_have_gnuplot(void)
{
    const char *path = getenv("PATH");
    if (!path || !*path)
        return 0;
    char *copy = strdup(path);
    int found = 0;
    for (char *save = NULL, *d = strtok_r(copy, ":", &save); d && !found;
         d = strtok_r(NULL, ":", &save)) {
        char *f = app_path_join(*d ? d : ".", "gnuplot");
        struct stat st;
        found = f && stat(f, &st) == 0 && S_ISREG(st.st_mode) && access(f, X_OK) == 0;
        free(f);
    }
    free(copy);
    return found;
}

int app_gnuplot_run(const char *prog, const char *dir, const char *script_name,
                    const char *out_name, int *made, char *err)
{
    if (made)
        *made = 0;
    if (!app_have_gnuplot()) {
        fprintf(stderr, "%s: gnuplot is not on PATH, so no figure: wrote %s/%s (run it with "
                        "gnuplot in that folder to make %s)\n",
                prog, dir, script_name, out_name);
        return 0;
    }
    if (strchr(out_name, '\'') || strchr(out_name, '/')) {
        app_errf(err, "figure name %s must be a plain file name", out_name);
        return -1;
    }
    size_t len = strlen(out_name) + 16;
    char *tmpbase = malloc(len), *tmp = NULL, *final = app_path_join(dir, out_name);
    char *expr = malloc(len + 32);
    int rc = -1;
    if (!tmpbase || !final || !expr) {
        app_errf(err, "out of memory");
        goto out;
    }
    snprintf(tmpbase, len, ".%s.XXXXXX", out_name);
    tmp = app_path_join(dir, tmpbase);
    if (!tmp) {
        app_errf(err, "out of memory");
        goto out;
    }
    int fd = mkstemp(tmp);
    if (fd < 0) {
        app_errf(err, "cannot create a temporary file in %s: %s", dir, strerror(errno));
        free(tmp);
        tmp = NULL;
        goto out;
    }
    close(fd);
    snprintf(expr, len + 32, "outfile='%s'", strrchr(tmp, '/') + 1);
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        app_errf(err, "cannot start gnuplot: %s", strerror(errno));
        goto out;
    }
    if (pid == 0) {
        int devnull = open("/dev/null", O_RDONLY);
        if (devnull >= 0)
            dup2(devnull, STDIN_FILENO);
        /* gnuplot's own messages go to stderr; keep our stdout for our data */
        dup2(STDERR_FILENO, STDOUT_FILENO);
        if (chdir(dir) == 0)
            execlp("gnuplot", "gnuplot", "-e", expr, script_name, (char *)NULL);
        _exit(127);
    }
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) {
            app_errf(err, "waiting for gnuplot: %s", strerror(errno));
            goto out;
        }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        app_errf(err, "gnuplot failed on %s/%s (%s %d)", dir, script_name,
                 WIFEXITED(status) ? "exit status" : "signal",
                 WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status));
        goto out;
    }
    fd = open(tmp, O_RDONLY);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0 || st.st_size == 0) {
        app_errf(err, "gnuplot wrote no figure to %s", tmp);
        if (fd >= 0)
            close(fd);
        goto out;
    }
    (void)fsync(fd);
    close(fd);
    /* mkstemp made 0600; give the figure the usual 0666 & ~umask */
    mode_t um = umask(0);
    umask(um);
    (void)chmod(tmp, 0666 & ~um);
    if (rename(tmp, final) != 0) {
        app_errf(err, "cannot rename %s to %s: %s", tmp, final, strerror(errno));
        goto out;
    }
    free(tmp);
    tmp = NULL;
    if (made)
        *made = 1;
    rc = 0;
out:
    if (tmp)
        unlink(tmp);
    free(tmp);
    free(tmpbase);
    free(final);
    free(expr);
    return rc;
}

void app_gnuplot_head(FILE *f, const char *png_name, const char *terminal, int loglog)
{
    fprintf(f,
            "if (!exists(\"outfile\")) outfile = '%s'\n"
            "set encoding utf8\n"
            "set terminal pngcairo %s\n"
            "set output outfile\n"
            "set datafile separator ','\n",
            png_name, terminal);
    if (loglog)
        fprintf(f, "set logscale xy\n"
                   "set format x '10^{%%T}'\n"
                   "set format y '10^{%%T}'\n");
}
