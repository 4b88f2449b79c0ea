/* relcol/toi.h — time of impact of Lorentz-contracted balls and walls: contact time,
 * point and normal, in a contact frame chosen as a table entry (rc_toi_frame). A ball of
 * rest radius r at velocity v is the spheroid P = r^2 (I - beta beta^T), support
 * h(n) = r sqrt(1 - (v.n)^2/c^2); at c = INFINITY every routine returns the sphere
 * routine's bits. Every entry point: RC_OK (contact at t >= 0), RC_MISS (none ahead,
 * touching-but-separating or grazing by touch_tol / graze_tol), RC_EOVERLAP (overlap
 * beyond touch_tol at t = 0), negative codes for bad input. Derivations and tolerances:
 * papers/time-of-impact.md; adding a frame: README "Adding a contact frame". */
#ifndef RELCOL_TOI_H
#define RELCOL_TOI_H

#include "relcol/kinematics.h"
#include "relcol/vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/// A ball at table time t = 0.
typedef struct rc_toi_ball {
    rc_vec3 x; ///< centre
    double r;  ///< rest radius > 0
    double m;  ///< rest mass > 0
    rc_vec3 p; ///< momentum (only v = p/M enters the contact geometry)
} rc_toi_ball;

/// Shape of a contracted ball, P = r^2 (g2 I + beta^2 I - beta beta^T): no entry computes 1 - beta^2 by subtraction.
typedef struct rc_toi_shape {
    double r;     ///< rest radius
    double g;     ///< 1/gamma = m/M
    double g2;    ///< 1/gamma^2 = 1 - beta^2, computed as (m/M)^2
    rc_vec3 beta; ///< v/c = p sqrt(inv_c2)/M; exactly 0 when inv_c2 = 0
} rc_toi_shape;

/// Tolerances and solver settings: make one with rc_toi_params_default().
typedef struct rc_toi_params {
    double c;          ///< speed of light, > 0; INFINITY (the default) is classical
    double touch_tol;  ///< touching at t = 0: |mu - 1| <= touch_tol, mu the scale of both shapes about their centres that makes them touch (default 1e-12, ~4500 ulp: room for computed positions)
    double graze_tol;  ///< grazing, not a collision: normal approach speed -w.n <= graze_tol |w| (default 1e-9: below it hit or miss is round-off, the time being known to ~eps/angle)
    double lambda_tol; ///< Brent bracket on the Perram-Wertheim lambda narrower than this: time error O(lambda_tol^2), normal O(lambda_tol) (default 1e-14)
    int max_iter;      ///< Brent iterations before RC_ENOCONVERGE (default 100)
} rc_toi_params;

/// The default tolerances (classical c).
rc_toi_params rc_toi_params_default(void);

/// A ball-ball contact in the table frame.
typedef struct rc_toi_contact {
    double t;  ///< event time
    rc_vec3 x; ///< contact point
    rc_vec3 n; ///< unit normal from ball 0 to ball 1
} rc_toi_contact;

/// Workspace of the contracted root finder (kept for the API; the hand-written Brent needs no state).
typedef struct rc_toi_workspace rc_toi_workspace;
/// *out: a new workspace (RC_OK), or NULL with RC_ENOMEM; RC_EINVAL if out is NULL.
int rc_toi_workspace_create(rc_toi_workspace **out);
/// Frees the workspace and sets *ws = NULL.
void rc_toi_workspace_free(rc_toi_workspace **ws);

/* ---- building blocks (relative coordinates: ball 1 minus ball 0) ---- */

/// Shape of a ball state (m, p) of rest radius r.
rc_toi_shape rc_toi_shape_of(double r, double m, rc_vec3 p, double inv_c2);
/// Support distance h(n) = r sqrt(1 - (beta.n)^2) along unit n, computed as r sqrt(g2 + |beta x n|^2) (cancellation-free).
double rc_toi_support(const rc_toi_shape *s, rc_vec3 n);

/// Uncontracted spheres: first t >= 0 with |d + w t| = R (the cancellation-free root), *n = (d + w t)/|d + w t|; trusted input (finite, R > 0).
int rc_toi_sphere_rel(double R, rc_vec3 d, rc_vec3 w, const rc_toi_params *prm,
                      double *t, rc_vec3 *n);

/// Two contracted shapes (separation d, relative velocity w at t = 0): first contact *t, point *y0 from shape 0's centre then (may be NULL: same t, n), normal *n out of shape 0; Brent on the Perram-Wertheim parameter, exact spheres give rc_toi_sphere_rel's bits; trusted input.
int rc_toi_shapes_rel(const rc_toi_shape *s0, const rc_toi_shape *s1, rc_vec3 d,
                      rc_vec3 w, const rc_toi_params *prm, rc_toi_workspace *ws,
                      double *t, rc_vec3 *y0, rc_vec3 *n);

/* ---- contact frames ---- */

/// Frame kernel: first contact of balls a and b (validated input).
typedef int (*rc_toi_frame_fn)(const rc_toi_params *prm, const rc_toi_ball *a,
                               const rc_toi_ball *b, rc_toi_workspace *ws,
                               rc_toi_contact *out);

/// Direct solver of a frame whose contact is the table-frame shapes': rc_toi_shapes_rel's signature (y0 may be NULL).
typedef int (*rc_toi_shapes_fn)(const rc_toi_shape *s0, const rc_toi_shape *s1, rc_vec3 d,
                                rc_vec3 w, const rc_toi_params *prm, rc_toi_workspace *ws,
                                double *t, rc_vec3 *y0, rc_vec3 *n);

/// A contact frame: its kernel and its declared properties (fields an initialiser leaves out are 0 / NULL: the conservative choice).
typedef struct rc_toi_frame {
    const char *name;    ///< as on the command line
    const char *summary; ///< one line for --help
    rc_toi_frame_fn toi; ///< the kernel
    int wall_contracted; ///< walls see the contracted shape (a wall's rest frame is the table and the ball-wall ZMF: table and zmf say 1)
    int contracted;      ///< pairs see contracted shapes at finite c; 0: toi is the spheres' contact, and the engine uses its own exact sphere kernel instead (sphere)
    int covariant;       ///< the contact event is the same whichever inertial frame the balls are given in (zmf); informational, read by apps
    int deferrable;      ///< a pair's contact comes no earlier than its bounding spheres' (one table instant between shapes inside them: table), so the engine may defer the root find
    rc_toi_shapes_fn shapes; ///< optional: the contact is the table-frame shapes' at one table time, found by this with toi's bits from the stored states (the engine then prunes and settles by those shapes' bounds; table: rc_toi_shapes_rel)
    int pointlike;       ///< toi decides contact between points by its own criterion (transport); the engine asks it about every pair whose bounding spheres can meet
    int per_ball;        ///< each ball changes velocity at its own event, where the hyperplane through the contact event X with normal u_in + u_out meets its worldline (glued world tubes, papers/shape-change.md; covariant); toi must return X
} rc_toi_frame;

/// Contact of the table-frame shapes.
extern const rc_toi_frame rc_toi_frame_table;
/// Contact found in the pair's ZMF, event and normal transformed back.
extern const rc_toi_frame rc_toi_frame_zmf;
/// The zmf frame's contact, each ball's velocity changed at its own event on its glued world tube (per_ball).
extern const rc_toi_frame rc_toi_frame_covariant;
/// Contraction ignored (the naive model).
extern const rc_toi_frame rc_toi_frame_sphere;
/// Transport codes' criterion: points, closest approach in the pair's CM frame with transverse distance d_T < r0 + r1.
extern const rc_toi_frame rc_toi_frame_transport;
/// The built-in frames, NULL-terminated.
extern const rc_toi_frame *const rc_toi_frames[];
/// The built-in frame of that name, or NULL.
const rc_toi_frame *rc_toi_frame_find(const char *name);

/// Validating entry point: checks params (c as rc_inv_c2, tolerances >= 0), balls (finite, r > 0, m > 0) and ws, then calls frame->toi.
int rc_toi(const rc_toi_frame *frame, const rc_toi_params *prm, const rc_toi_ball *a,
           const rc_toi_ball *b, rc_toi_workspace *ws, rc_toi_contact *out);

/// The transport frame's impact parameter: *dT2 the squared centre distance at closest approach in the pair's CM frame (|d|^2 if they do not part there), *tcm (may be NULL) its CM time (0 at the table event (0, 0)); validating as rc_toi.
int rc_toi_transport_impact(const rc_toi_params *prm, const rc_toi_ball *a,
                            const rc_toi_ball *b, double *dT2, double *tcm);

/* ---- walls ---- */

/// Ball (on the side n.x < offset) against the plane n.x = offset, n unit into the wall: the centre meets offset - h(n) (contracted, or r); *t, *x the support point; validating.
int rc_toi_wall(const rc_toi_params *prm, int contracted, const rc_toi_ball *a,
                rc_vec3 n, double offset, double *t, rc_vec3 *x);

/// Ball inside the box lo[i] <= x_i <= hi[i], i < dim: first wall contact, *side 2 i (lo) or 2 i + 1 (hi; ties to the lowest), *n outward, *t, *x; RC_EOVERLAP sticking out, RC_EINVAL lo >= hi.
int rc_toi_box(const rc_toi_params *prm, int contracted, const rc_toi_ball *a, int dim,
               const double lo[], const double hi[], double *t, int *side, rc_vec3 *n,
               rc_vec3 *x);

/* ---- shape change through a collision (papers/shape-change.md) ---- */

/// One ball's world tube through one collision: incoming and outgoing cylinders glued on the hyperplane H (t - t_x = kappa . (y - x), normal u_in + u_out) through the contact event X; with inv_c2 = 0 every time is t_x.
typedef struct rc_glue {
    double inv_c2;          ///< 1/c^2
    double r;               ///< rest radius
    rc_toi_shape in, out;   ///< the table-frame shapes before and after
    rc_vec3 v_in, v_out;    ///< velocities before and after
    double t_x;             ///< contact event X: time ...
    rc_vec3 x;              ///< ... and point
    rc_vec3 kappa;          ///< H: t - t_x = kappa . (y - x), |kappa| < 1/c
    double t_c;             ///< the centre's event on H: time ...
    rc_vec3 x_c;            ///< ... and position
    double t_first, t_last; ///< H sweeps the ball's section in [t_first, t_last]
} rc_glue;

/// The glued tube of a ball (rest radius r) going from `in` to `out` through the event (t_x, X), its centre xc at t_x on the incoming line (X need not be on the surface); RC_EINVAL, or the particle checks' codes.
int rc_glue_make(double inv_c2, double r, const rc_particle *in, const rc_particle *out,
                 double t_x, rc_vec3 xc, rc_vec3 X, rc_glue *g);

/// 1 if the point y belongs to the ball's table-frame section at time t (incoming cylinder before H, outgoing after), else 0.
int rc_glue_inside(const rc_glue *g, double t, rc_vec3 y);

/// The ball's centre at time t: on the incoming worldline before t_c, the outgoing after.
rc_vec3 rc_glue_centre(const rc_glue *g, double t);

/// First contact at t >= t_from of the glued tube g with a rigid contracted ball k (centre at t_from): *t, point *y, normal *n from g to k (on H k's own), *piece 0 incoming, 1 outgoing, 2 on H; RC_OK, RC_MISS, RC_EOVERLAP at t_from, or a bad-input code.
int rc_glue_toi(const rc_glue *g, const rc_toi_params *prm, rc_toi_workspace *ws,
                double t_from, const rc_toi_ball *k, double *t, rc_vec3 *y, rc_vec3 *n,
                int *piece);

/// First contact at t >= t_from of two glued tubes (one coordinate system; papers/shape-change.md section 10): *t, *y, normal *n from 1 to 2 (creases: the other's, both: averaged), *piece1, *piece2 as rc_glue_toi's; RC_OK, RC_MISS, RC_EOVERLAP at t_from, or a bad-input code (RC_EINVAL also for tubes of different c).
int rc_glue_toi2(const rc_glue *g1, const rc_glue *g2, const rc_toi_params *prm,
                 rc_toi_workspace *ws, double t_from, double *t, rc_vec3 *y, rc_vec3 *n,
                 int *piece1, int *piece2);

#ifdef __cplusplus
}
#endif
#endif
