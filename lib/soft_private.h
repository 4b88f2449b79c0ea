/* soft_private.h — the state of one soft-sphere run, shared by the model (soft_model.c)
 * and the steppers (soft_cvode.c, soft_gsl.c): the steppers only see y, the right-hand
 * side, the overlap functions and the contact switches. */
#ifndef RELCOL_SOFT_PRIVATE_H
#define RELCOL_SOFT_PRIVATE_H

#include <stddef.h>
#include "relcol/soft.h"
#include "relcol/toi.h"

/* Components per ball in y: position (3), momentum (3), internal energy U (1). */
#define RC_SOFT_NY 7

struct rc_soft_sys {
    size_t n;        /* balls */
    size_t npair;    /* n (n - 1) / 2, pairs i < j in row order */
    size_t ny;       /* RC_SOFT_NY n */
    double inv_c2, kappa, zeta, rtol, t_max;
    long max_steps;
    rc_soft_shape shape;
    const double *m0; /* rest masses at the start */
    const double *r;  /* radii */
    int *on;          /* per pair: 1 while in contact (the force is switched by events, not
                       * by the sign of the overlap, so each segment's RHS is smooth) */
    double *lam;      /* per pair: last Perram-Wertheim maximiser (contracted shapes), the
                       * warm start of the next evaluation; NAN before the first */
    rc_toi_shape *frozen; /* per pair, 2 each: the shapes at contact start, used instead of
                           * the current ones while held[q] (RC_SOFT_CONTRACTED_FROZEN) */
    int *held;        /* per pair: 1 from a contact's start until the pair is apart in its
                       * current shapes as well as in the frozen ones */
    int *ghost;       /* per pair: 1 while it overlaps out of contact (a shape change) */
    double *y;        /* current state, integration frame */
    double t;         /* current integration time (0 at the start) */
    double *abs_scale;/* per component: absolute tolerance / rtol */
    double e0, e_scale, p_scale;
    /* diagnostics */
    int n_contacts, have_normal, n_shape_overlaps;
    rc_vec3 normal_zmf;
    double energy_error, momentum_error;
    long n_steps, n_rhs, n_pw;
};

typedef struct rc_soft_sys rc_soft_sys;

/* Contact geometry of pair q = (i, j) at y (soft_shape.c): overlap depth *delta (> 0 when
 * the shapes overlap), unit normal *n from i to j, gauge *mu (the factor by which both
 * shapes must be scaled about their centres to touch). Spheres: delta = r_i + r_j - |d|,
 * n = d/|d|, mu = |d|/(r_i + r_j); contracted: delta = |d| (1 - mu)/mu and the
 * Perram-Wertheim normal. Updates the pair's warm start s->lam[q]. Returns 1 when the
 * Perram-Wertheim path was taken, 0 for the sphere formulas (always so for spheres, and
 * for contracted shapes that are exact spheres: c = inf). */
int rc_soft_geometry(rc_soft_sys *s, size_t q, size_t i, size_t j, const double *y,
                     double *delta, rc_vec3 *n, double *mu);
/* dy/dt at y with the current contact switches. */
void rc_soft_rhs(rc_soft_sys *s, const double *y, double *dy);
/* Overlap delta of every pair (npair values): the root functions. */
void rc_soft_overlap(rc_soft_sys *s, const double *y, double *g);
/* 1 if pair q's centres approach at y: at a zero of its overlap the contact is on exactly
 * when they approach (decided from the state, not from a root's reported direction,
 * which is unreliable for a root found again at the restart point). */
int rc_soft_approaching(rc_soft_sys *s, size_t q, const double *y);
/* Contracted shapes change with the momenta, so a pair out of contact can come to
 * overlap without approaching (another contact changed a ball's shape). Such a pair feels
 * no force until its overlap has ended (switching it on would release at once an elastic
 * energy kappa delta^2/2 that was never stored); count each such episode in
 * s->n_shape_overlaps (called after every accepted step and event). */
void rc_soft_shape_overlaps(rc_soft_sys *s, const double *y);
/* Contact of pair q starts (start = 1) or ends (0) at state y. */
void rc_soft_switch(rc_soft_sys *s, size_t q, int start, const double *y);
/* Largest step that cannot carry an approaching pair that is not in contact through a
 * whole contact unseen: its gap over its closing speed (free flight), floored at rtol
 * times the radius crossing time; for a pair in contact, half its 1/omega.
 * INFINITY when no pair approaches or touches. */
double rc_soft_max_step(rc_soft_sys *s, const double *y);
/* 1 when no pair is in contact and every pair is receding: nothing more can happen. */
int rc_soft_done(rc_soft_sys *s, const double *y);
/* Record the conservation errors at y and release the frozen shapes of pairs that are
 * apart in their current shapes too (after every accepted step and event). */
void rc_soft_observe(rc_soft_sys *s, const double *y);

#endif
