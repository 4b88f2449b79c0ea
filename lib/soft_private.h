/* soft_private.h — the state of one soft-sphere run, shared by the model (soft_model.c)
 * and its contact geometry (soft_shape.c). The steppers (soft_cvode.c, soft_gsl.c) see it
 * only through relcol/soft.h's rc_soft_sys functions, as an outside stepper would. */
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

/* Contact geometry of pair q = (i, j) at y (soft_shape.c): overlap depth *delta (> 0 when
 * the shapes overlap), unit normal *n from i to j, gauge *mu (the factor by which both
 * shapes must be scaled about their centres to touch). Spheres: delta = r_i + r_j - |d|,
 * n = d/|d|, mu = |d|/(r_i + r_j); contracted: delta = |d| (1 - mu)/mu and the
 * Perram-Wertheim normal. Updates the pair's warm start s->lam[q]. Returns 1 when the
 * Perram-Wertheim path was taken, 0 for the sphere formulas (always so for spheres, and
 * for contracted shapes that are exact spheres: c = inf). */
int rc_soft_geometry(rc_soft_sys *s, size_t q, size_t i, size_t j, const double *y,
                     double *delta, rc_vec3 *n, double *mu);

#endif
