/* nb.h — the runtime of a relcol literate C notebook (header only).
 *
 * A notebook is a C file whose block comments opening with a line "md" are Markdown
 * cells; everything else is code. The program prints its output; nb_section("name")
 * starts the output that the renderer (nbrender) places where a Markdown cell says
 * "@output name"; nb_figure() writes a gnuplot script and runs it, and the renderer
 * shows the PNG. NB_CHECK asserts a claim of the notebook: the notebook's exit status is
 * the test result (the test suite runs every notebook). */
#ifndef RELCOL_NB_H
#define RELCOL_NB_H

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct nb_state {
    const char *outdir; /* where figures go (argv[1], default ".") */
    long checks, failed;
} nb_state;

static nb_state nb_g = {".", 0, 0};

static inline void nb_init(int argc, char **argv)
{
    if (argc > 1)
        nb_g.outdir = argv[1];
    setvbuf(stdout, NULL, _IOLBF, 0);
}

static inline void nb_section(const char *name) { printf("@@output %s\n", name); }

/* Record a checked claim; prints one line either way so the rendered page shows it. */
#define NB_CHECK(cond, ...)                                                        \
    do {                                                                          \
        nb_g.checks++;                                                            \
        int nb_ok_ = (cond) ? 1 : 0;                                              \
        if (!nb_ok_)                                                              \
            nb_g.failed++;                                                        \
        printf("check %s: ", nb_ok_ ? "ok" : "FAILED");                           \
        printf(__VA_ARGS__);                                                      \
        printf("\n");                                                             \
        if (!nb_ok_)                                                              \
            fprintf(stderr, "%s:%d: notebook check failed: %s\n", __FILE__, __LINE__, #cond); \
    } while (0)

/* Write NAME.dat (the caller fills it through the FILE*), NAME.gp (the script body,
 * with the terminal and output prepended) and run gnuplot when installed. Returns the
 * data file for writing, or NULL; call nb_figure_end() after writing the data. */
static inline FILE *nb_figure_begin(const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s.dat", nb_g.outdir, name);
    return fopen(path, "w");
}

static inline int nb_figure_end(FILE *data, const char *name, const char *script)
{
    if (data)
        fclose(data);
    char gp[1024], png[1024], dat[1024], cmd[4096];
    snprintf(gp, sizeof gp, "%s/%s.gp", nb_g.outdir, name);
    snprintf(png, sizeof png, "%s/%s.png", nb_g.outdir, name);
    snprintf(dat, sizeof dat, "%s/%s.dat", nb_g.outdir, name);
    FILE *f = fopen(gp, "w");
    if (!f)
        return -1;
    fprintf(f, "set terminal pngcairo size 800,560 enhanced font ',11'\n");
    fprintf(f, "set output '%s'\n", png);
    fprintf(f, "datafile = '%s'\n", dat);
    fputs(script, f);
    fclose(f);
    if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
        printf("(gnuplot not installed: script %s.gp written, no figure)\n", name);
        return 0;
    }
    snprintf(cmd, sizeof cmd, "gnuplot '%s'", gp);
    if (system(cmd) != 0) {
        printf("(gnuplot failed on %s.gp)\n", name);
        return -1;
    }
    printf("@@figure %s.png\n", name);
    return 0;
}

static inline int nb_finish(void)
{
    nb_section("summary");
    printf("%ld checks, %ld failed\n", nb_g.checks, nb_g.failed);
    return nb_g.failed == 0 && nb_g.checks > 0 ? 0 : 1;
}

#endif
