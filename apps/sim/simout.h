/* simout.h — relcol-sim's outputs: snapshots, extended XYZ, summary, final state, figures.
 * Written atomically: each file appears whole or not at all. */
#ifndef RELCOL_SIM_SIMOUT_H
#define RELCOL_SIM_SIMOUT_H

#include "app.h"
#include "scenario.h"
#include "h5md.h"
#include "profiles.h"

/* The run's final state: final.json, naming the engine's state final.ckpt (scn_save). */
#define SIMOUT_FINAL "final"

typedef struct sim_output {
    const scn_scenario *s;
    char *dir;            /* where the files are written: the staging folder in s->out.dir */
    int failed;           /* an output could not be written: the run publishes nothing */
    const char *prog;
    size_t next_snap;     /* index of the next snapshot time */
    double next_frame;    /* time of the next XYZ frame (INFINITY if none) */
    double frame_k;       /* its place on the grid: next_frame = xyz_from + frame_k xyz_every */
    double first_frame;   /* the time of the first frame (of the GIF's too) */
    size_t frame_no;      /* frames written */
    app_atomic xyz;       /* trajectory.xyz, committed at the end */
    app_atomic frames;    /* frames.dat (x y r per ball, one block per frame) for figures */
    int have_xyz;
    double next_h5;       /* time of the next H5MD frame (INFINITY if none) */
    double h5_k;          /* its place on the grid: next_h5 = xyz_from + h5_k h5md_every */
    sim_h5md *h5;         /* trajectory.h5, committed at the end */
    size_t gif_stride;    /* keep every k-th frame in the GIF */
    size_t gif_frames;    /* frames written to frames.dat */
    size_t n_balls;
    rc_sim_diag d0;       /* diagnostics at the start */
    int have_d0;
    char line[256];       /* one-line result for stdout */
    sim_profiles *prof;   /* a field's profiles (profiles.c), NULL without one */
    double fe0;           /* a field: its conserved energy at the start (rc_sim_field_energy's h - booked) */
} sim_output;

/* Open the outputs: files are written into a staging folder and appear in s->out.dir
 * together when simout_close succeeds (simout_publish.c). */
int simout_open(sim_output *o, const scn_scenario *s, const char *prog, char *err);
/* The next time at which something is due (a snapshot, a frame, or t_end), > t. */
double simout_next_time(const sim_output *o, double t);
/* Write whatever is due at the engine's current time. */
int simout_at(sim_output *o, const rc_sim *sim, char *err);
/* Finish: final.json, summary.txt, trajectory.xyz, trajectory.h5,
 * figures; then move them into the
 * output folder, replacing the previous run's. If any output failed (here or in
 * simout_at), nothing is moved, the previous run's files stay, and err says so. */
int simout_close(sim_output *o, const rc_sim *sim, double wall_seconds, int interrupted,
                 char *err);

/* simout_publish.c: the staging folder (malloc'ed path) in dir, after removing the
 * staging folders of killed runs; its files published in dir by one rename (dir/NAME are
 * links through dir/.relcol-run, switched to the run's folder), the previous run's folder
 * removed after (a failure there: 0, with the reason in warn, of APP_ERR_LEN); and the
 * folder removed without publishing anything. publish and discard free stage. */
int simout_stage_open(const char *dir, char **stage, char *err);
int simout_stage_publish(const char *dir, char *stage, char *err, char *warn);
void simout_stage_discard(char *stage);

#endif
