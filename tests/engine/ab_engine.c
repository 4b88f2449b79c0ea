/* ab_engine.c — two builds of librelcol in one process, timed in alternating chunks on the
 * same gas: a speed ratio that the machine's drift between minutes (tens of per cent on a
 * shared machine) does not enter, unlike two separate runs. Each library is loaded into a
 * namespace of its own (dlmopen), so two builds with the same symbols coexist.
 *   ab_engine LIB_A LIB_B [N] [dim] [rounds] [c] [frame] [packing]
 * N (10000), dim 2 or 3 (3), rounds of alternation (10), c (inf; else the rms speed is
 * 0.5 c), frame (the engine's default, or a contact frame's name: table, zmf, covariant),
 * packing (bench_engine's: 0.45 in 3-D, 0.7 in 2-D; the covariant frame's glued tube is
 * defined in dilute gases, 0.1 say, where its undo and policy are rare). Both gases
 * are built alike and melted (7.5 events a ball; 3 with a frame) before timing; each round
 * times a chunk of events on both, the first one alternating. Prints each library's
 * collisions per CPU second and B/A. scripts/ab-revs.sh builds two revisions for it.
 * RELCOL_SIMD (avx512, avx2, scalar) and RELCOL_DEFER=0 force a path in both
 * (env_choices.h; libraries from before rc_sim_def.simd read the variables themselves). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE /* dlmopen */
#endif
#include <dlfcn.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "env_choices.h"
#include "relcol/relcol.h"

typedef struct lib {
    const char *path;
    void *h;
    rc_sim_def (*def_default)(void);
    int (*gas_init)(const rc_sim_gas_def *, rc_vec3 *, rc_sim_ball *);
    int (*create)(const rc_sim_def *, rc_sim **);
    int (*set_balls)(rc_sim *, size_t, const rc_sim_ball *, size_t *);
    int (*advance)(rc_sim *, double, uint64_t);
    int (*diagnostics)(const rc_sim *, rc_sim_diag *);
    void (*free_sim)(rc_sim **);
    const rc_toi_frame *(*frame_find)(const char *);
} lib;

static double cpu_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void *sym(const lib *l, const char *name)
{
    void *p = dlsym(l->h, name);
    if (!p) {
        fprintf(stderr, "ab_engine: %s: no symbol %s\n", l->path, name);
        exit(2);
    }
    return p;
}

static lib load(const char *path)
{
    lib l = {.path = path};
    l.h = dlmopen(LM_ID_NEWLM, path, RTLD_NOW | RTLD_LOCAL);
    if (!l.h) {
        fprintf(stderr, "ab_engine: cannot load %s: %s\n", path, dlerror());
        exit(2);
    }
    *(void **)&l.def_default = sym(&l, "rc_sim_def_default");
    *(void **)&l.gas_init = sym(&l, "rc_sim_gas_init");
    *(void **)&l.create = sym(&l, "rc_sim_create");
    *(void **)&l.set_balls = sym(&l, "rc_sim_set_balls");
    *(void **)&l.advance = sym(&l, "rc_sim_advance");
    *(void **)&l.diagnostics = sym(&l, "rc_sim_diagnostics");
    *(void **)&l.free_sim = sym(&l, "rc_sim_free");
    *(void **)&l.frame_find = sym(&l, "rc_toi_frame_find");
    return l;
}

/* The gas of bench_engine (radius 1/2, seed 2024), melted; exits with a message on failure. */
static rc_sim *make_gas(const lib *l, int dim, size_t n, double c, const char *frame,
                        double packing)
{
    rc_sim_gas_def g = {dim, n, 0.5, packing, isinf(c) ? 1.0 : 0.5 * c, c, 1.0, 2024};
    rc_sim_ball *b = calloc(n, sizeof *b);
    rc_sim_def d = l->def_default();
    env_choices(&d); /* (a library older than the fields reads the variables itself) */
    d.dim = dim;
    d.c = c;
    if (frame && !(d.frame = l->frame_find(frame))) {
        fprintf(stderr, "ab_engine: frame '%s': no such contact frame in %s\n", frame, l->path);
        exit(2);
    }
    rc_sim *s = NULL;
    int st = b ? l->gas_init(&g, &d.box, b) : RC_ENOMEM;
    if (st == RC_OK)
        st = l->create(&d, &s);
    if (st == RC_OK)
        st = l->set_balls(s, n, b, NULL);
    free(b);
    if (st == RC_OK)
        st = l->advance(s, INFINITY, (uint64_t)((frame ? 3.0 : 7.5) * (double)n));
    if (st != RC_OK) {
        fprintf(stderr, "ab_engine: %s: setting up the gas failed (status %d)\n", l->path, st);
        exit(2);
    }
    return s;
}

/* A whole positive number from argv, or exit with a message naming it. */
static double arg_number(const char *what, const char *text, double lo, double hi)
{
    char *end;
    errno = 0;
    const double v = strtod(text, &end);
    if (errno || end == text || *end || !(v >= lo && v <= hi) || v != floor(v)) {
        fprintf(stderr, "ab_engine: %s '%s': not a whole number in [%g, %g]\n", what, text, lo,
                hi);
        exit(2);
    }
    return v;
}

int main(int argc, char **argv)
{
    if (argc < 3 || argc > 9) {
        fprintf(stderr, "usage: ab_engine LIB_A LIB_B [N] [dim] [rounds] [c] [frame] [packing]\n");
        return 2;
    }
    const size_t n = argc > 3 ? (size_t)arg_number("N", argv[3], 2, 1e8) : 10000;
    const int dim = argc > 4 ? (int)arg_number("dim", argv[4], 2, 3) : 3;
    const int rounds = argc > 5 ? (int)arg_number("rounds", argv[5], 1, 1e6) : 10;
    double c = INFINITY;
    if (argc > 6 && strcmp(argv[6], "inf") != 0) {
        char *end;
        c = strtod(argv[6], &end);
        if (end == argv[6] || *end || !(c > 0.0)) {
            fprintf(stderr, "ab_engine: c '%s': not a positive number or inf\n", argv[6]);
            return 2;
        }
    }
    const char *frame = argc > 7 ? argv[7] : NULL;
    double packing = dim == 3 ? 0.45 : 0.70;
    if (argc > 8) {
        char *end;
        packing = strtod(argv[8], &end);
        if (end == argv[8] || *end || !(packing > 0.0 && packing < (dim == 3 ? 0.74 : 0.9))) {
            fprintf(stderr, "ab_engine: packing '%s': not a number in (0, %s)\n", argv[8],
                    dim == 3 ? "0.74" : "0.9");
            return 2;
        }
    }
    lib l[2] = {load(argv[1]), load(argv[2])};
    rc_sim *s[2] = {make_gas(&l[0], dim, n, c, frame, packing), make_gas(&l[1], dim, n, c, frame, packing)};
    /* chunks of ~0.1-0.5 s: many alternations, each long enough to leave the other's
     * cache footprint behind */
    const uint64_t chunk = frame ? 20000 : (n < 50000 ? 100000 : 200000);
    double secs[2] = {0, 0}, coll[2] = {0, 0};
    for (int r = 0; r < rounds; r++)
        for (int j = 0; j < 2; j++) {
            const int k = (r & 1) ? 1 - j : j;
            rc_sim_diag before, after;
            l[k].diagnostics(s[k], &before);
            const double t0 = cpu_s();
            const int st = l[k].advance(s[k], INFINITY, chunk);
            secs[k] += cpu_s() - t0;
            l[k].diagnostics(s[k], &after);
            if (st != RC_OK) {
                fprintf(stderr, "ab_engine: %s: advance failed (status %d)\n", l[k].path, st);
                return 1;
            }
            coll[k] += (double)(after.collisions - before.collisions);
        }
    const double ra = coll[0] / secs[0], rb = coll[1] / secs[1];
    printf("%dD N=%zu c=%g%s%s, %d rounds: A %.0f collisions/s, B %.0f collisions/s, B/A %.3f\n",
           dim, n, c, frame ? " frame=" : "", frame ? frame : "", rounds, ra, rb, rb / ra);
    for (int k = 0; k < 2; k++)
        l[k].free_sim(&s[k]);
    return 0;
}
