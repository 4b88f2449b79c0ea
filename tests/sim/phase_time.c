/* phase_time.c — an LD_PRELOAD shim for the benchmark 'final' (bench_final.sh): the process
 * CPU and wall time from the temporary of snapshots/snap-*.csv or final.json being made
 * (mkstemp) to its rename into place, one line a file appended to $RELCOL_PHASE_LOG:
 * "NAME CPU_SECONDS WALL_SECONDS". Interposes calls the program makes itself, so the same
 * shim times any revision's relcol-sim, the writer inside it only. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#undef _FILE_OFFSET_BITS /* (mkstemp and mkstemp64 are two symbols here, both interposed) */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double cpu0[2], wall0[2];

static double now(clockid_t c)
{
    struct timespec t;
    clock_gettime(c, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* 0: a snapshot, 1: final.json, -1: another file (by the base name, a leading dot skipped) */
static int which(const char *path)
{
    const char *b = strrchr(path, '/');
    b = b ? b + 1 : path;
    b += *b == '.';
    return strncmp(b, "snap-", 5) == 0 ? 0 : strncmp(b, "final.json", 10) == 0 ? 1 : -1;
}

static void start(const char *template)
{
    int k = which(template);
    if (k >= 0) {
        cpu0[k] = now(CLOCK_PROCESS_CPUTIME_ID);
        wall0[k] = now(CLOCK_MONOTONIC);
    }
}

/* (with _FILE_OFFSET_BITS=64, as meson builds, the program calls mkstemp64) */
int mkstemp64(char *template)
{
    static int (*real)(char *);
    if (!real)
        *(void **)&real = dlsym(RTLD_NEXT, "mkstemp64"); /* (POSIX's idiom for a function) */
    start(template);
    return real(template);
}

int mkstemp(char *template)
{
    static int (*real)(char *);
    if (!real)
        *(void **)&real = dlsym(RTLD_NEXT, "mkstemp");
    start(template);
    return real(template);
}

int rename(const char *from, const char *to)
{
    static int (*real)(const char *, const char *);
    if (!real)
        *(void **)&real = dlsym(RTLD_NEXT, "rename");
    int k = which(to), r = real(from, to);
    const char *log = getenv("RELCOL_PHASE_LOG");
    if (k >= 0 && r == 0 && log && which(from) == k && wall0[k] > 0) {
        double c = now(CLOCK_PROCESS_CPUTIME_ID) - cpu0[k], w = now(CLOCK_MONOTONIC) - wall0[k];
        FILE *f = fopen(log, "a");
        if (f) {
            fprintf(f, "%s %.6f %.6f\n", k ? "final.json" : "snapshot", c, w);
            fclose(f);
        }
    }
    return r;
}
