/* relcol/toi.h — time of impact of Lorentz-contracted balls and walls, with the contact
 * point, the contact normal and the frame in which contact is decided as an option.
 *
 * Shapes. A ball of rest radius r moving at v is, in any frame where it moves at v, the
 * ellipse (2-D) / spheroid (3-D) with semi-axis r/gamma along v and r across it:
 *     P = r^2 (I - beta beta^T),  beta = v/c,   support h(n) = sqrt(n^T P n) (|n| = 1),
 * so h(n) = r sqrt(1 - (v.n)^2/c^2). With c = INFINITY (inv_c2 = 0) P = r^2 I exactly
 * and every routine below returns bit for bit what the uncontracted-sphere routine
 * returns (the bracket built from the bounding and inscribed spheres has zero width).
 *
 * Contact frames are `const rc_toi_frame` objects (GSL style, like rc_law): "table"
 * finds contact between the table-frame shapes, "zmf" finds it in the pair's
 * zero-momentum frame and transforms the event and the normal back, "sphere" ignores
 * the contraction, "transport" takes the balls as points with the transport codes'
 * criterion (closest approach in the pair's CM frame, impact parameter below r0 + r1;
 * never RC_EOVERLAP), "covariant" finds zmf's contact event and has the engine change each
 * ball's velocity at its own event of its glued world tube (per_ball). A frame is one table entry with declared properties (below); the
 * engine and the apps read the properties and never name a frame. A frame need not live
 * in the library: any `const rc_toi_frame` can be given to rc_toi() and rc_sim_def.frame
 * (README "Adding a contact frame"); to make it built-in, define it in a new lib/toi_*.c,
 * declare it here and add it to rc_toi_frames[] in lib/toi_frames.c. The derivation
 * and every tolerance decision are in papers/time-of-impact.md.
 *
 * Outcomes (every entry point): RC_OK with a contact at t >= 0; RC_MISS when there is
 * no contact in the future — including "touching but separating" (touching within
 * touch_tol at t = 0 with the normal approach speed not above graze_tol |w|) and
 * grazing (first contact with normal approach speed <= graze_tol |w|: the shapes only
 * touch tangentially and no law would transfer an impulse); RC_EOVERLAP when the
 * shapes overlap by more than touch_tol at t = 0; negative codes for invalid input. */
#ifndef RELCOL_TOI_H
#define RELCOL_TOI_H

#include "relcol/kinematics.h"
#include "relcol/vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A ball at table time t = 0: centre x, rest radius r > 0, rest mass m > 0 and
 * momentum p (only v = p/M enters the contact geometry). */
typedef struct rc_toi_ball {
    rc_vec3 x;
    double r;
    double m;
    rc_vec3 p;
} rc_toi_ball;

/* Shape of a contracted ball, P = r^2 (g2 I + beta^2 I - beta beta^T), g2 = 1/gamma^2 =
 * (m/M)^2: every entry of P is a sum of non-negative terms or a single product, so
 * nothing computes 1 - beta^2 by subtraction. */
typedef struct rc_toi_shape {
    double r;
    double g;     /* 1/gamma = m/M */
    double g2;    /* 1/gamma^2 = 1 - beta^2, computed as (m/M)^2 */
    rc_vec3 beta; /* v/c = p sqrt(inv_c2)/M; exactly 0 when inv_c2 = 0 */
} rc_toi_shape;

/* Tolerances and solver settings. Make one with rc_toi_params_default(). */
typedef struct rc_toi_params {
    double c;          /* speed of light, > 0; INFINITY (the default) is classical */
    /* Touching at t = 0 means |mu - 1| <= touch_tol, with mu the factor by which both
     * shapes must be scaled about their centres to touch (dimensionless). Default
     * 1e-12: ~4500 ulp, room for positions that were themselves computed. */
    double touch_tol;
    /* A contact whose normal approach speed -w.n is <= graze_tol |w| is grazing, not a
     * collision (dimensionless: sine of the angle between w and the tangent plane).
     * Default 1e-9: the time of a contact at angle theta is only determined to
     * ~eps/theta relative, so below ~1e-9 the hit/miss decision is round-off. */
    double graze_tol;
    /* Root finding on the Perram-Wertheim parameter lambda in (0, 1) (dimensionless):
     * stop when the Brent bracket is narrower than lambda_tol. The time is
     * stationary in lambda, so its error is O(lambda_tol^2); the normal's is
     * O(lambda_tol). Default 1e-14. */
    double lambda_tol;
    int max_iter; /* Brent iterations before RC_ENOCONVERGE (default 100) */
} rc_toi_params;

rc_toi_params rc_toi_params_default(void);

/* Result of a ball-ball contact: table-frame event time t and point x of the contact,
 * unit normal n from ball 0 to ball 1 in the table frame. */
typedef struct rc_toi_contact {
    double t;
    rc_vec3 x;
    rc_vec3 n;
} rc_toi_contact;

/* Workspace of the contracted root finder (kept for the API; the hand-written Brent
 * needs no state). */
typedef struct rc_toi_workspace rc_toi_workspace;
/* *out: a new workspace (RC_OK), or NULL with RC_ENOMEM; RC_EINVAL if out is NULL. */
int rc_toi_workspace_create(rc_toi_workspace **out);
void rc_toi_workspace_free(rc_toi_workspace **ws); /* frees and sets *ws = NULL */

/* ---- building blocks (relative coordinates: ball 1 minus ball 0) ---- */

/* Shape of a ball state (m, p) of rest radius r. */
rc_toi_shape rc_toi_shape_of(double r, double m, rc_vec3 p, double inv_c2);
/* Support distance h(n) = r sqrt(1 - (beta.n)^2) of a shape along unit n, computed as
 * r sqrt(g2 + |beta x n|^2) (cancellation-free). */
double rc_toi_support(const rc_toi_shape *s, rc_vec3 n);

/* Uncontracted spheres: first t >= 0 with |d + w t| = R, with the cancellation-free
 * root t = (d.d - R^2) / (-d.w + sqrt(w.w R^2 - |d x w|^2)). *n = (d + w t)/|d + w t|.
 * Trusted input (finite, R > 0). Outcomes as in the file comment. */
int rc_toi_sphere_rel(double R, rc_vec3 d, rc_vec3 w, const rc_toi_params *prm,
                      double *t, rc_vec3 *n);

/* Two contracted shapes, centre separation d at t = 0 (ball 1 minus ball 0) moving
 * apart at w: first contact time *t, contact point relative to ball 0's centre at that
 * time *y0, and the common unit normal *n (outward from shape 0). Root finding with
 * Brent's method on the Perram-Wertheim parameter; shapes that are exact spheres (inv_c2 =
 * 0 or both at rest) give rc_toi_sphere_rel's result bit for bit. Trusted input. y0 may
 * be NULL: the contact point is then not computed (t and n are the same bits). */
int rc_toi_shapes_rel(const rc_toi_shape *s0, const rc_toi_shape *s1, rc_vec3 d,
                      rc_vec3 w, const rc_toi_params *prm, rc_toi_workspace *ws,
                      double *t, rc_vec3 *y0, rc_vec3 *n);

/* ---- contact frames ---- */

/* Frame kernel: first contact of balls a and b (validated input). */
typedef int (*rc_toi_frame_fn)(const rc_toi_params *prm, const rc_toi_ball *a,
                               const rc_toi_ball *b, rc_toi_workspace *ws,
                               rc_toi_contact *out);

/* Direct solver of a frame whose contact is that of the two table-frame shapes: the
 * signature of rc_toi_shapes_rel (shapes and relative coordinates; y0 may be NULL). */
typedef int (*rc_toi_shapes_fn)(const rc_toi_shape *s0, const rc_toi_shape *s1, rc_vec3 d,
                                rc_vec3 w, const rc_toi_params *prm, rc_toi_workspace *ws,
                                double *t, rc_vec3 *y0, rc_vec3 *n);

/* A contact frame: its kernel and its declared properties. Fields after toi that an
 * initialiser leaves out are 0 / NULL: the conservative choice for each. */
typedef struct rc_toi_frame {
    const char *name;    /* as on the command line */
    const char *summary; /* one line for --help */
    rc_toi_frame_fn toi;
    /* Whether walls see the contracted shape. A wall is infinitely massive, so its
     * rest frame is both the table and the ball-wall ZMF: table and zmf say 1. */
    int wall_contracted;
    /* Whether pairs see contracted shapes at finite c. 0 declares that toi finds the
     * contact of the uncontracted spheres of rest radius r: the engine then uses its
     * own exact sphere kernel and never calls toi (sphere says 0). */
    int contracted;
    /* Whether the contact event is frame independent: the same event whichever
     * inertial frame the balls are given in (zmf says 1; table and sphere decide
     * contact at one table-frame instant and say 0). Informational: read by apps. */
    int covariant;
    /* Whether the engine may defer this frame's root finds: the contact of a pair can
     * come no earlier than the contact of its bounding spheres of radius r (true when
     * contact is decided between shapes inside those spheres at one table instant:
     * table). Not for zmf, whose contact is simultaneous in the pair's frame. */
    int deferrable;
    /* Optional (NULL: none). Non-NULL declares that the frame's contact is exactly the
     * first contact of the two shapes contracted along their table-frame velocities
     * (rc_toi_shape_of) at one table time, and that this function finds it from the
     * shapes and relative coordinates with the same bits as toi: the engine then calls
     * it directly on its stored states, and may prune and settle pairs with bounds of
     * those table-frame shapes (centre-line separating axis, overlap certificate).
     * table says rc_toi_shapes_rel. */
    rc_toi_shapes_fn shapes;
    /* Whether toi decides contact by its own criterion between points rather than
     * between shapes (transport says 1: a cross-section criterion, contracted 0 as it
     * contracts nothing). The engine then asks toi about every pair whose bounding
     * spheres of radius r can meet, as it does for a contracted frame. */
    int pointlike;
    /* Whether each ball of a pair changes velocity at its own event rather than both at
     * one table time (covariant says 1): the event E where the hyperplane H through the
     * contact event X with normal u_in + u_out of that ball meets its incoming worldline
     * (rc_glue's t_c, x_c; papers/shape-change.md), so that its world tube is the glued
     * one. The engine then keeps per ball the hyperplane that began its current segment,
     * refuses as a contact of the model a predicted contact on the incoming side of
     * either ball's hyperplane, and keeps every ball's kinks ordered along its worldline
     * (relcol/sim.h, rc_sim_diag). Needs toi to return the contact event's point. */
    int per_ball;
} rc_toi_frame;

extern const rc_toi_frame rc_toi_frame_table;  /* contact of the table-frame shapes */
extern const rc_toi_frame rc_toi_frame_zmf;    /* contact found in the pair's ZMF */
/* the zmf frame's contact, each ball's velocity changed at its own event on its glued
 * world tube (per_ball) */
extern const rc_toi_frame rc_toi_frame_covariant;
extern const rc_toi_frame rc_toi_frame_sphere; /* contraction ignored (naive model) */
/* transport codes' criterion: points, closest approach in the pair's CM frame with
 * transverse distance d_T < r0 + r1 (papers/time-of-impact.md) */
extern const rc_toi_frame rc_toi_frame_transport;
extern const rc_toi_frame *const rc_toi_frames[]; /* NULL-terminated */
const rc_toi_frame *rc_toi_frame_find(const char *name); /* NULL if unknown */

/* Validating entry point: checks params (c as rc_inv_c2 does, tolerances >= 0), balls
 * (finite, r > 0, m > 0) and ws, then calls frame->toi. */
int rc_toi(const rc_toi_frame *frame, const rc_toi_params *prm, const rc_toi_ball *a,
           const rc_toi_ball *b, rc_toi_workspace *ws, rc_toi_contact *out);

/* The transport frame's impact parameter: *dT2 = d_T^2, the squared distance of the two
 * centres at their closest approach in the pair's centre-of-momentum frame (|d|^2 if
 * they do not move apart there), and *tcm (may be NULL) the CM time of that approach
 * (the CM clock reads 0 at the table event (0, 0)). Frame-independent; whether the
 * approach lies ahead is rc_toi's answer. Validating as rc_toi. */
int rc_toi_transport_impact(const rc_toi_params *prm, const rc_toi_ball *a,
                            const rc_toi_ball *b, double *dT2, double *tcm);

/* ---- walls ---- */

/* Ball against the plane n.x = offset (n unit, pointing from the ball into the wall;
 * the ball is on the side n.x < offset). Closed form: the centre meets the plane
 * offset - h(n) with h(n) = r sqrt(1 - (v.n)^2/c^2) (contracted) or r. *t: time;
 * *x: contact point (the support point of the shape along n). Validating. */
int rc_toi_wall(const rc_toi_params *prm, int contracted, const rc_toi_ball *a,
                rc_vec3 n, double offset, double *t, rc_vec3 *x);

/* Ball inside the box lo[i] <= x_i <= hi[i], i < dim (dim 1..3): first wall contact.
 * Sides are numbered 2 i (the lo wall of axis i, normal -e_i) and 2 i + 1 (hi wall,
 * +e_i); ties go to the lowest side number. *side, *n (outward normal), *t, *x.
 * RC_EOVERLAP if the ball sticks out of the box, RC_EINVAL if lo >= hi. */
int rc_toi_box(const rc_toi_params *prm, int contracted, const rc_toi_ball *a, int dim,
               const double lo[], const double hi[], double *t, int *side, rc_vec3 *n,
               rc_vec3 *x);

/* ---- shape change through a collision (papers/shape-change.md) ---- */

/* The world tube of one ball through one collision: its incoming and outgoing world
 * cylinders (same rest radius r) glued on the hyperplane H through the contact event X
 * with normal u_in + u_out, where their sections coincide. In the table frame H is the
 * plane t - t_x = kappa . (y - x), which sweeps the ball's section (|kappa| < 1/c, so
 * faster than light) in [t_first, t_last]; the centre changes velocity where H meets its
 * worldline, (t_c, x_c). Before H a point of the ball belongs to the incoming cylinder,
 * after it to the outgoing one. With inv_c2 = 0 kappa = 0 and every time is t_x. */
typedef struct rc_glue {
    double inv_c2;
    double r;
    rc_toi_shape in, out; /* the table-frame shapes before and after */
    rc_vec3 v_in, v_out;
    double t_x;           /* contact event X */
    rc_vec3 x;
    rc_vec3 kappa;        /* H: t - t_x = kappa . (y - x) */
    double t_c;           /* the centre's event on H */
    rc_vec3 x_c;
    double t_first, t_last;
} rc_glue;

/* The glued tube of a ball of rest radius r whose state goes from `in` to `out` through
 * the contact event (t_x, X), its centre at time t_x on the incoming worldline being xc
 * (X need not lie on the ball's surface: any event fixes one H). RC_EINVAL for a bad
 * argument, the particle checks' codes for a bad state. */
int rc_glue_make(double inv_c2, double r, const rc_particle *in, const rc_particle *out,
                 double t_x, rc_vec3 xc, rc_vec3 X, rc_glue *g);

/* 1 if the point y belongs to the ball's table-frame section at time t (the incoming
 * cylinder's part before H, the outgoing one's after it), else 0. */
int rc_glue_inside(const rc_glue *g, double t, rc_vec3 y);

/* The ball's centre at time t: on the incoming worldline before t_c, the outgoing after. */
rc_vec3 rc_glue_centre(const rc_glue *g, double t);

/* First contact at a time >= t_from of the glued tube g with a rigid contracted ball k
 * (k->x its centre at t_from), from the convex pieces of the tube: the incoming cylinder
 * before H and the outgoing one after it, each met either where its own contact with k
 * lies on its side of H, or on H itself (papers/shape-change.md). *t the time, *y the
 * contact point, *n the unit normal from the glued ball to k (on H, where the tube has a
 * crease, k's own normal), *piece 0 incoming, 1 outgoing, 2 on H. Outcomes as rc_toi's:
 * RC_OK, RC_MISS, RC_EOVERLAP (k overlaps the tube's section at t_from), or a negative
 * code for invalid input. */
int rc_glue_toi(const rc_glue *g, const rc_toi_params *prm, rc_toi_workspace *ws,
                double t_from, const rc_toi_ball *k, double *t, rc_vec3 *y, rc_vec3 *n,
                int *piece);

/* First contact at a time >= t_from of two glued tubes g1 and g2 (both in one coordinate
 * system), each the union of its incoming cylinder before its H and its outgoing one after
 * it (papers/shape-change.md section 10): the least table time over the four
 * intersections of a piece of one with a piece of the other. *t the time, *y the
 * contact point, *n the unit normal from ball 1 to ball 2 (on a crease the other ball's
 * normal; on both creases the two averaged), *piece1 and *piece2 where it lies on each
 * tube: 0 incoming, 1 outgoing, 2 on its H. RC_OK, RC_MISS, RC_EOVERLAP (the tubes'
 * sections overlap at t_from by more than touch_tol of the radii), or a negative code
 * for invalid input (RC_EINVAL also for tubes of different c). */
int rc_glue_toi2(const rc_glue *g1, const rc_glue *g2, const rc_toi_params *prm,
                 rc_toi_workspace *ws, double t_from, double *t, rc_vec3 *y, rc_vec3 *n,
                 int *piece1, int *piece2);

#ifdef __cplusplus
}
#endif
#endif
