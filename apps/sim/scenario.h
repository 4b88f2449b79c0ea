/* scenario.h — relcol-sim's scenario files (JSON): what a run is — box, balls or a
 * generator, c, restitutions, law, contact frame, seed, end time, outputs — read with
 * every malformed or impossible value rejected by its JSON path and the reason, and
 * written back (a run's final state is itself a scenario). Schema: apps/sim/SCENARIO.md. */
#ifndef RELCOL_SIM_SCENARIO_H
#define RELCOL_SIM_SCENARIO_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "relcol/relcol.h"

#define SCN_MAX_SNAPSHOTS 4096
/* Trajectory frames a run may write: bounds the output (a frame of 10^4 balls is ~1 MB) */
#define SCN_MAX_FRAMES 100000

/* The H5MD trajectory's per-frame elements (outputs.h5md.fields), in the order written;
 * their names are scn_h5md_names'. image exists only with a periodic axis. */
enum { SCN_H5MD_POSITION, SCN_H5MD_VELOCITY, SCN_H5MD_MASS, SCN_H5MD_REST_MASS,
       SCN_H5MD_MOMENTUM, SCN_H5MD_PROPER_TIME, SCN_H5MD_IMAGE, SCN_H5MD_N };
extern const char *const scn_h5md_names[SCN_H5MD_N];

typedef struct scn_outputs {
    char *dir;                 /* output folder */
    size_t n_snap;             /* snapshot times (CSV), ascending */
    double snap[SCN_MAX_SNAPSHOTS];
    double xyz_every;          /* extended-XYZ frame interval; 0 = no trajectory */
    double xyz_from;           /* frames at xyz_from + k xyz_every, those >= time (a
                                  continued run keeps the grid of the run it continues) */
    double h5md_every;         /* H5MD frame interval (frames at xyz_from + k h5md_every);
                                  0 = no trajectory.h5 */
    unsigned h5md_fields;      /* bit (1u << SCN_H5MD_*) per element written; default all
                                  (image only with a periodic axis) */
    int h5md_float32;          /* per-frame values stored as float32 (else float64) */
    int h5md_scenario;         /* the scenario's JSON text in parameters/scenario */
    int plots;                 /* trajectory PNG (and GIF for 2-D) when gnuplot exists */
    int gif;                   /* animated GIF for 2-D runs */
    int summary;               /* summary.txt */
} scn_outputs;

typedef struct scn_scenario {
    int dim;                   /* 2 or 3 */
    rc_vec3 box;               /* edge lengths */
    int boundary[3];           /* per axis: RC_SIM_WALLS or RC_SIM_PERIODIC */
    double c;                  /* INFINITY classical */
    const rc_law *law;
    double eps_ball, eps_wall;
    const rc_wall_rule *wall_rule[6]; /* "walls": wall w = 2 d + side's rule (NULL: the hard
                                         wall, restitution eps_wall) ... */
    double wall_kT[6];         /* ... and its temperature kT where the rule reads one */
    const rc_toi_frame *frame; /* contact frame (the library's or the caller's table) */
    int groups;                /* rule for simultaneous contacts (rc_group_rule) */
    double t_c;                /* TC model, proper time; 0 off */
    const rc_gravity_coupling *gravity; /* a uniform field along -z (the last axis), NULL none */
    double g;                  /* its acceleration at the floor z = 0 */
    uint64_t seed;
    double time;               /* start time (a restart carries the time it stopped at) */
    double t_end;
    int restart;               /* the balls are a state relcol-sim wrote (final.json) */
    char *checkpoint;          /* the engine's whole state, a file relative to the
                                  scenario's folder (final.json names final.ckpt); NULL:
                                  none, events are planned afresh from the balls */
    size_t n;                  /* balls */
    rc_sim_ball *balls;        /* n balls (momentum, rest mass resolved) */
    char generator[16];        /* "" (explicit balls), "rack" or "gas": how balls were made */
    scn_outputs out;
} scn_scenario;

/* Laws and contact frames a reader accepts by name beside the library's tables (rc_laws,
 * rc_toi_frames), given by its caller -- a program or a test with models of its own; the
 * library keeps no registry. NULL-terminated tables; either may be NULL. A name is looked
 * up in the library's table first, then in the caller's. */
typedef struct scn_tables {
    const rc_law *const *laws;
    const rc_toi_frame *const *frames;
} scn_tables;

/* Parse JSON text (name is used in messages). On failure returns -1 with
 * "NAME: PATH: reason" in err (APP_ERR_LEN) and leaves *s empty. extra: the caller's
 * laws and frames (NULL: the library's only). */
int scn_parse_ext(const char *text, const char *name, const scn_tables *extra,
                  scn_scenario *s, char *err);
int scn_parse(const char *text, const char *name, scn_scenario *s, char *err);
/* Read and parse a file. */
int scn_load_ext(const char *path, const scn_tables *extra, scn_scenario *s, char *err);
int scn_load(const char *path, scn_scenario *s, char *err);
/* A built-in scenario: "rack" or "gas" with its defaults (the same as the files in
 * data/scenarios/). */
int scn_builtin(const char *name, scn_scenario *s, char *err);
void scn_free(scn_scenario *s);

/* The engine's definition of the run s describes (everything else default): written once,
 * for relcol-sim and for the tests that run a scenario as relcol-sim does. */
rc_sim_def scn_sim_def(const scn_scenario *s);
/* The walls' names in the scenario and summary.json, wall w = 2 d + side: x-, x+, y-, ... */
extern const char *const scn_wall_names[6];

/* The engine sim (made from scn_sim_def(s)) at the scenario's start: the checkpoint it
 * names, read from the folder of file (the scenario's path) and checked to hold the
 * scenario's balls to the bit, or else its balls at its time. 0, or -1 with "FILE:
 * balls[3]: overlaps another ball" (or the checkpoint's failure) in err (APP_ERR_LEN). */
int scn_start(rc_sim *sim, const scn_scenario *s, const char *file, char *err);
/* The run's state in dir as a scenario to be continued until t_end (name.json: s with
 * the engine's balls and time, "restart": true, naming name.ckpt, the engine's whole
 * state): reading it back with scn_load and scn_start continues the run bit for bit. Each
 * file written atomically. 0, or -1 with the reason in err. */
int scn_save(const char *dir, const char *name, const scn_scenario *s, const rc_sim *sim,
             double t_end, char *err);
/* The whole file at path, malloc'ed (*bytes its length); NULL with errno on failure. */
unsigned char *scn_read_bytes(const char *path, size_t *bytes);

/* The output folder of a run continued from one that wrote into dir: "dir.1", and after
 * "dir.K" "dir.K+1" -- so that continuing from final.json never writes over the files of
 * the run it continues. NULL if out of memory (free the result). */
char *scn_next_dir(const char *dir);

/* Write s with the given balls at time t, to be run until t_end, as a scenario to f,
 * numbers in %.17g so that reading it back gives the same bits (one ball a line). */
int scn_write(FILE *f, const scn_scenario *s, double t, double t_end, size_t n,
              const rc_sim_ball *balls);

#endif
