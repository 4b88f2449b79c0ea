"""Emits the C source of relcol._relcol, the compiled cffi module over librelcol.

API (out-of-line) mode: the declarations below are checked against the library's own
headers when the emitted source is compiled (a field of the wrong type or a struct of
another size is a compile error, not a wrong number), and meson compiles and links it
against librelcol like any other target. Usage: python3 _cffi_build.py OUT.c
Only what the package uses is declared; `...;` leaves the rest of a struct to the
compiler.
"""
import os
import sys

import cffi

CDEF = r"""
const char *rc_version(void);
const char *rc_strerror(int status);
enum rc_status { RC_OK = 0, RC_NO_COLLISION = 1, RC_MISS = 2, RC_EOVERLAP = -8, ... };

typedef struct rc_vec3 { double x, y, z; } rc_vec3;
typedef struct rc_particle { double m; rc_vec3 p; } rc_particle;

int rc_inv_c2(double c, double *inv_c2);
int rc_particle_check(const rc_particle *b);
int rc_momentum_from_velocity(double m, rc_vec3 v, double inv_c2, rc_vec3 *p);

/* laws */
typedef struct rc_collision_params {
    double c; double eps; double alpha; double azimuth; ...;
} rc_collision_params;
typedef struct rc_law {
    const char *name; const char *summary; int uses_angle; int keeps_zmf_energy; ...;
} rc_law;
extern const rc_law *const rc_laws[];
const rc_law *rc_law_find(const char *name);
rc_collision_params rc_collision_params_default(void);
const char *rc_group_rule_name(int rule);
int rc_group_rule_find(const char *name);
int rc_collide(const rc_law *law, const rc_collision_params *prm, rc_particle *a,
               rc_particle *b, rc_vec3 n);
int rc_collide_many(const rc_law *law, const rc_collision_params *prm, size_t n_pairs,
                    double *m0, rc_vec3 *p0, double *m1, rc_vec3 *p1, const rc_vec3 *n,
                    int *status, size_t *hits, size_t *bad);
double rc_pair_heat(const rc_particle before[2], const rc_particle after[2], double inv_c2,
                    double q_ball[2]);

/* time of impact */
typedef struct rc_toi_ball { rc_vec3 x; double r; double m; rc_vec3 p; } rc_toi_ball;
typedef struct rc_toi_params {
    double c; double touch_tol; double graze_tol; double lambda_tol; int max_iter; ...;
} rc_toi_params;
typedef struct rc_toi_contact { double t; rc_vec3 x; rc_vec3 n; } rc_toi_contact;
typedef struct rc_toi_workspace rc_toi_workspace;
typedef struct rc_toi_frame {
    const char *name; const char *summary; int wall_contracted; int contracted;
    int covariant; int deferrable; int per_ball; int pointlike; ...;
} rc_toi_frame;
extern const rc_toi_frame *const rc_toi_frames[];
const rc_toi_frame *rc_toi_frame_find(const char *name);
rc_toi_params rc_toi_params_default(void);
int rc_toi_workspace_create(rc_toi_workspace **out);
void rc_toi_workspace_free(rc_toi_workspace **ws);
int rc_toi(const rc_toi_frame *frame, const rc_toi_params *prm, const rc_toi_ball *a,
           const rc_toi_ball *b, rc_toi_workspace *ws, rc_toi_contact *out);

/* soft-sphere reference */
typedef int... rc_soft_shape;
typedef struct rc_soft_params {
    double c; double stiffness; double eps; double rtol; double t_max; long max_steps;
    rc_soft_shape shape; ...;
} rc_soft_params;
typedef struct rc_soft_result {
    int n_contacts; int n_shape_overlaps; int finished; rc_vec3 normal; double t_end;
    double energy_error; double momentum_error; long n_steps; long n_rhs; long n_pw; ...;
} rc_soft_result;
typedef struct rc_soft_stepper { const char *name; const char *summary; ...; } rc_soft_stepper;
extern const rc_soft_stepper *const rc_soft_steppers[];
const rc_soft_stepper *rc_soft_stepper_find(const char *name);
rc_soft_params rc_soft_params_default(void);
int rc_soft_collide(const rc_soft_stepper *stepper, const rc_soft_params *prm, size_t n,
                    rc_particle *b, rc_vec3 *x, const double *r, double *u_int,
                    rc_soft_result *res);

/* a uniform field (relcol/gravity.h) */
typedef struct rc_gravity_coupling { const char *name; const char *summary; ...; }
    rc_gravity_coupling;
extern const rc_gravity_coupling *const rc_gravity_couplings[];
const rc_gravity_coupling *rc_gravity_find(const char *name);

/* event-driven engine */
typedef struct rc_sim rc_sim;
typedef int... rc_sim_simd;
typedef int... rc_sim_defer;
typedef struct rc_sim_def {
    int dim; rc_vec3 box; double c; double eps_ball; double eps_wall; double t_c;
    const rc_law *law; const rc_toi_frame *frame; rc_toi_params toi; double sim_tol;
    double approach_tol; double overlap_tol; double cell_size; double density; int restart;
    int boundary[3]; int groups; const rc_gravity_coupling *gravity; double g; int g_axis;
    ...;
} rc_sim_def;
typedef struct rc_sim_ball {
    rc_vec3 x; rc_vec3 p; double r; double m; double tau; int collided; double tau_last;
    int32_t image[3]; ...;
} rc_sim_ball;
typedef struct rc_sim_diag {
    double time; double mass_rel; double kinetic; double heat; double energy;
    double rest_mass; rc_vec3 momentum; rc_vec3 wall_impulse;
    double wall_impulse_by_wall[6]; double momentum_scale; double max_overlap;
    uint64_t overlaps; uint64_t overlaps_by_kind[3]; uint64_t collisions; uint64_t events[6];
    size_t max_group; uint64_t group_fallbacks; uint64_t group_sequential;
    uint64_t tube_conflicts; uint64_t order_conflicts; uint64_t rollbacks;
    int64_t stall_ball; int64_t stall_partner; ...;
} rc_sim_diag;
enum { RC_SIM_WALLS = 0, RC_SIM_PERIODIC = 1 };
rc_sim_def rc_sim_def_default(void);
int rc_sim_create(const rc_sim_def *def, rc_sim **out);
void rc_sim_free(rc_sim **s);
int rc_sim_set_time(rc_sim *s, double t);
int rc_sim_set_balls(rc_sim *s, size_t n, const rc_sim_ball *balls, size_t *bad);
int rc_sim_advance(rc_sim *s, double t_end, uint64_t max_events);
size_t rc_sim_count(const rc_sim *s);
double rc_sim_time(const rc_sim *s);
int rc_sim_get_ball(const rc_sim *s, size_t i, rc_sim_ball *out);
int rc_sim_get_ball_latest(const rc_sim *s, size_t i, rc_sim_ball *out);
int rc_sim_get_positions(const rc_sim *s, size_t n, int dim, double *x, int latest);
int rc_sim_kink_ahead(const rc_sim *s, size_t i);
typedef struct rc_sim_slice_info {
    double ts; double t_final; int final; uint64_t late; double reach;
} rc_sim_slice_info;
int rc_sim_slice_request(rc_sim *s, double ts, uint32_t *id);
int rc_sim_slice_ready(const rc_sim *s, uint32_t id, rc_sim_slice_info *info);
int rc_sim_slice_get(rc_sim *s, uint32_t id, size_t i, rc_sim_ball *out);
int rc_sim_slice_release(rc_sim *s, uint32_t id);
int rc_sim_diagnostics(const rc_sim *s, rc_sim_diag *d);
int rc_sim_field_energy(const rc_sim *s, double *h, double *booked);
typedef enum { RC_VERDICT_DEFINED = 0, RC_VERDICT_OUTSIDE = 1,
               RC_VERDICT_NON_COVARIANT = 2 } rc_sim_verdict;
typedef struct rc_validity {
    uint64_t collisions; uint64_t policy; double policy_share;
    uint64_t tube_conflicts; uint64_t order_conflicts; uint64_t undone;
    uint64_t kink_events; uint64_t kink_pairs; uint64_t kink_pairs_model;
    uint64_t crossing; uint64_t crossing_model; uint64_t kinks_popped;
    double p_all; double p_model; double largest_all; double largest_model;
    double nu_r_c; double threshold; int covariant; rc_sim_verdict verdict;
    const char *verdict_name;
} rc_validity;
int rc_sim_validity(const rc_sim *s, rc_validity *out);
uint64_t rc_sim_hash(const rc_sim *s);
int rc_sim_set_c(rc_sim *s, double c);
int rc_sim_checkpoint_size(const rc_sim *s, size_t *bytes);
int rc_sim_checkpoint_write(const rc_sim *s, void *buf, size_t bytes);
int rc_sim_checkpoint_read(rc_sim *s, const void *buf, size_t bytes);
typedef struct rc_sim_gas_def {
    int dim; size_t n; double radius; double packing; double v_rms; double c;
    double density; uint64_t seed; ...;
} rc_sim_gas_def;
int rc_sim_gas_init(const rc_sim_gas_def *g, rc_vec3 *box, rc_sim_ball *balls);

/* 1-D gas */
typedef struct rc_gas1d rc_gas1d;
typedef struct rc_gas1d_def {
    size_t n; double length; double c; double t0; const double *x; const double *m;
    const double *p; const rc_law *law; ...;
} rc_gas1d_def;
typedef struct rc_gas1d_stats {
    uint64_t pair_events; uint64_t wall_events[2]; uint64_t declined;
    double wall_impulse[2]; ...;
} rc_gas1d_stats;
rc_gas1d_def rc_gas1d_def_default(void);
int rc_gas1d_create(const rc_gas1d_def *def, rc_gas1d **out, size_t *bad);
void rc_gas1d_free(rc_gas1d **g);
int rc_gas1d_advance(rc_gas1d *g, double t_end, uint64_t max_events);
size_t rc_gas1d_count(const rc_gas1d *g);
double rc_gas1d_time(const rc_gas1d *g);
int rc_gas1d_get(const rc_gas1d *g, double *x, double *m, double *p);
int rc_gas1d_stats_get(const rc_gas1d *g, rc_gas1d_stats *s);
typedef struct rc_gas1d_event { double t; double x; int kind; size_t i; ...; } rc_gas1d_event;
int rc_gas1d_step(rc_gas1d *g, double t_end, rc_gas1d_event *ev);
typedef struct rc_gas1d_segment { double t; double x; double m; double p; double v; ...; }
    rc_gas1d_segment;
int rc_gas1d_segment_get(const rc_gas1d *g, size_t i, rc_gas1d_segment *out);

/* relcol-sim's scenario reader, writer and start (apps/sim/scenario.h): the one place of
   the scenario rules, linked into this module */
typedef struct scn_scenario {
    int dim; rc_vec3 box; int boundary[3]; double c; const rc_law *law;
    double eps_ball; double eps_wall; const rc_toi_frame *frame; int groups; double t_c;
    const rc_gravity_coupling *gravity; double g; uint64_t seed; double time; double t_end; int restart; char *checkpoint; size_t n;
    rc_sim_ball *balls; char generator[16]; ...;
} scn_scenario;
#define APP_ERR_LEN ...
int scn_parse(const char *text, const char *name, scn_scenario *s, char *err);
int scn_load(const char *path, scn_scenario *s, char *err);
void scn_free(scn_scenario *s);
rc_sim_def scn_sim_def(const scn_scenario *s);
int scn_start(rc_sim *sim, const scn_scenario *s, const char *file, char *err);
int scn_save(const char *dir, const char *name, const scn_scenario *s, const rc_sim *sim,
             double t_end, char *err);

"""


def pyrelcol_cdef():
    """The package-side declarations, read from pyrelcol.h itself (its preprocessor lines
    dropped: cffi's cdef takes declarations only), so that they are written once."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "pyrelcol.h")
    with open(path, encoding="utf-8") as f:
        return "".join(line for line in f if not line.lstrip().startswith("#"))


def main(out):
    ffi = cffi.FFI()
    ffi.cdef(CDEF + pyrelcol_cdef())
    ffi.set_source("relcol._relcol", '#include "relcol/relcol.h"\n#include "app.h"\n'
                   '#include "scenario.h"\n#include "pyrelcol.h"\n')
    ffi.emit_c_code(out)


if __name__ == "__main__":
    main(sys.argv[1])
