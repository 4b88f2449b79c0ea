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

/* Is the figure gnuplot left at path whole? gnuplot can exit 0 with a figure cut short (a
 * full disk: cairo's write errors are not its exit status), so the file is read back:
 * a PNG must end with its IEND chunk, a GIF with its trailer byte, an SVG with </svg>;
 * any other kind, non-empty. 0 or -1 with the reason in err. */
static int figure_whole(const char *path, const char *name, char *err)
{
    static const unsigned char png_sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char png_end[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    const char *ext = strrchr(name, '.');
    FILE *f = fopen(path, "rb");
    unsigned char head[8] = {0}, tail[16] = {0};
    long size = -1;
    if (f && fseek(f, 0, SEEK_END) == 0)
        size = ftell(f);
    if (size > 0 && fseek(f, 0, SEEK_SET) == 0 && fread(head, 1, sizeof head, f) &&
        fseek(f, size >= 16 ? size - 16 : 0, SEEK_SET) == 0)
        (void)!fread(tail + (size >= 16 ? 0 : 16 - size), 1, size >= 16 ? 16 : (size_t)size, f);
    if (f)
        fclose(f);
    const char *why = NULL;
    if (size <= 0)
        why = "it is empty";
    else if (ext && !strcmp(ext, ".png") &&
             (size < 20 || memcmp(head, png_sig, 8) || memcmp(tail + 4, png_end, 12)))
        why = "the PNG does not end with its IEND chunk (cut short: a full disk?)";
    else if (ext && !strcmp(ext, ".gif") && (memcmp(head, "GIF8", 4) || tail[15] != 0x3b))
        why = "the GIF does not end with its trailer (cut short: a full disk?)";
    else if (ext && !strcmp(ext, ".svg")) {
        const char *t = (const char *)tail;
        if (!memmem(t, 16, "</svg>", 6))
            why = "the SVG does not end with </svg> (cut short: a full disk?)";
    }
    if (why) {
        app_errf(err, "gnuplot's %s is not whole: %s; not renamed into place (a previous %s, if any, is kept)", name, why, name);
        return -1;
    }
    return 0;
}

/* Read gnuplot's messages to the end, line by line, and print those that are not its
 * progress notes ("201 frames in animation sequence", the GIF terminal's count). */
static void pass_messages(int fd, const char *prog, const char *script)
{
    FILE *f = fdopen(dup(fd), "r");
    if (!f)
        return;
    char line[1024];
    while (fgets(line, sizeof line, f)) {
        if (strstr(line, "frames in animation sequence"))
            continue;
        fprintf(stderr, "%s: gnuplot (%s): %s%s", prog, script, line,
                strchr(line, '\n') ? "" : "\n");
    }
    fclose(f);
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
    /* (room for outfile='.NAME.relcol-PID.XXXXXX') */
    const size_t len = strlen(out_name) + 64;
    char *tmp = NULL, *final = app_path_join(dir, out_name);
    char *expr = malloc(len);
    int rc = -1;
    if (!final || !expr) {
        app_errf(err, "out of memory");
        goto out;
    }
    app_clean_stale(dir, out_name);
    tmp = app_temp_template(dir, out_name);
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
    snprintf(expr, len, "outfile='%s'", strrchr(tmp, '/') + 1);
    fflush(NULL);
    /* gnuplot's messages come through a pipe: its progress notes are dropped, anything
     * else (a warning, an error) is passed on prefixed with the script's name */
    int pfd[2];
    if (pipe(pfd) != 0) {
        app_errf(err, "cannot start gnuplot: %s", strerror(errno));
        goto out;
    }
    pid_t pid = fork();
    if (pid < 0) {
        app_errf(err, "cannot start gnuplot: %s", strerror(errno));
        close(pfd[0]);
        close(pfd[1]);
        goto out;
    }
    if (pid == 0) {
        int devnull = open("/dev/null", O_RDONLY);
        if (devnull >= 0)
            dup2(devnull, STDIN_FILENO);
        /* gnuplot's own messages (stdout and stderr) into the pipe; our stdout is data */
        dup2(pfd[1], STDOUT_FILENO);
        dup2(pfd[1], STDERR_FILENO);
        close(pfd[0]);
        close(pfd[1]);
        /* the scripts are UTF-8 (set encoding utf8): under the C locale gnuplot cannot
         * convert their degree signs and Greek letters and warns */
        setenv("LC_ALL", "C.UTF-8", 1);
        if (chdir(dir) == 0)
            execlp("gnuplot", "gnuplot", "-e", expr, script_name, (char *)NULL);
        _exit(127);
    }
    close(pfd[1]);
    pass_messages(pfd[0], prog, script_name);
    close(pfd[0]);
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
    if (figure_whole(tmp, out_name, err))
        goto out; /* (the old figure, if any, stays) */
    fd = open(tmp, O_RDONLY);
    if (fd < 0) {
        app_errf(err, "gnuplot's figure %s cannot be read back: %s", tmp, strerror(errno));
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
