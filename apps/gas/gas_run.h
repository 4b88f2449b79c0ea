/* gas_run.h — relcol-gas's runs: the options it was given, the gases started far from
 * equilibrium (every speed equal) and stepped to each snapshot, and what they give back
 * (the samples). gas.c parses, analyses and writes; gas_run.c runs. */
#ifndef RELCOL_GAS_RUN_H
#define RELCOL_GAS_RUN_H

#include <stddef.h>
#include <stdint.h>

#include "relcol/relcol.h"
#include "pressure_blocks.h"

#define GAS_PROG "relcol-gas"

/* The snapshots are cut into NBLOCK consecutive blocks; the error bars are the standard
 * errors of the block means (gas.c's usage). At most MAXSPEC species. */
enum { NBLOCK = 10, MAXSPEC = 2 };

/* 1-D mixture (see data/reproductions/cubero2007.md: equal masses only swap momenta and
 * never thermalise): rest masses 1 and 2, each particle heavy with probability 1/2. */
extern const double gas_mix_mass[MAXSPEC];

/* per_ball frames (covariant): which state a snapshot reads (--readout) */
enum { READ_SLICE = 0, READ_LATEST, READ_NOW };

typedef struct options {
    int dim;
    long n, snapshots;
    double c, theta_start, v_start, packing, t_equil, t_sample;
    int theta_given, v_given, packing_given, frame_given, tequil_given, tsample_given;
    int periodic, boundary_given;
    int readout, readout_given; /* per_ball frames: READ_* */
    double v_obs;
    int obs_given;
    uint64_t seed;
    const rc_toi_frame *frame;
    const char *out;
    int sensitivity;   /* --sensitivity (apps/common/sensitivity.c) */
    int groups;        /* rule for simultaneous contacts (rc_group_rule; the default 0) */
    double sens_move;  /* positions moved by this much of a radius at the start */
} options;

/* What the run gives back: per snapshot and ball, the species and u = gamma^2 - 1
 * = |p|^2/(m c)^2 (gamma - 1 = u/(gamma + 1) then has no cancellation). */
typedef struct samples {
    size_t n, ns;
    unsigned char *spec; /* n species (1-D: by position order, which never changes) */
    double *u;           /* ns * n */
    uint64_t *coll;      /* ns + 1: collisions so far at the sample's start and snapshots */
    double gamma0;       /* the common starting gamma of the light species */
    double mass_drift, energy_drift;
    uint64_t events, overlaps;
    rc_sim_diag end;     /* the diagnostics at the end (all of the run: app_rules_warn) */
    int have_end;
    /* --readout slice: slices read, and changed after they were read (rc_sim_slice_info
     * late, checked while each is held a further W after its read) */
    uint64_t slices_read, slices_late;
    double box;          /* box edge */
    rc_vec3 boxv;        /* the box as the engine has it (2-D: z unused) */
    pb_acc pres;         /* pressure per block (apps/eos/pressure_blocks.h) */
    double theta_energy; /* 1-D: theta_of_energy_1d of the start (NAN otherwise) */
} samples;

/* The common starting gamma of the light species (from theta or v). */
double gas_start_gamma(const options *o);
/* The 2-D/3-D gas at its start (*out; S's species, box): 0, or -1 with err. */
int gas_sim_start(const options *o, samples *S, rc_sim **out, char *err);
/* The 1-D mixture at its start (*out, its energy *e0): 0, or -1 with err. */
int gas_1d_start(const options *o, samples *S, rc_gas1d **out, double *e0, char *err);
/* Run to t_equil, then take the snapshots into S: 0, or -1 with err. */
int gas_run_sim(const options *o, samples *S, char *err);
int gas_run_1d(const options *o, samples *S, char *err);

#endif
