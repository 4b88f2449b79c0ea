/* soft_private.h — the state of one soft-sphere run, shared by the model (soft_model.c)
 * and the steppers (soft_cvode.c, soft_gsl.c): the steppers only see y, the right-hand
 * side, the overlap functions and the contact switches. */
#ifndef RELCOL_SOFT_PRIVATE_H
#define RELCOL_SOFT_PRIVATE_H

#include <stddef.h>
#include "relcol/soft.h"

/* Components per ball in y: position (3), momentum (3), internal energy U (1). */
#define RC_SOFT_NY 7

struct rc_soft_sys {
    size_t n;        /* balls */
    size_t npair;    /* n (n - 1) / 2, pairs i < j in row order */
    size_t ny;       /* RC_SOFT_NY n */
    double inv_c2, kappa, zeta, rtol, t_max;
    long max_steps;
    const double *m0; /* rest masses at the start */
    const double *r;  /* radii */
    int *on;          /* per pair: 1 while in contact (the force is switched by events, not
                       * by the sign of the overlap, so each segment's RHS is smooth) */
    double *y;        /* current state, integration frame */
    double t;         /* current integration time (0 at the start) */
    double *abs_scale;/* per component: absolute tolerance / rtol */
    double e0, e_scale, p_scale;
    /* diagnostics */
    int n_contacts, have_normal;
    rc_vec3 normal_zmf;
    double energy_error, momentum_error;
    long n_steps, n_rhs;
};

typedef struct rc_soft_sys rc_soft_sys;

/* dy/dt at y with the current contact switches. */
void rc_soft_rhs(rc_soft_sys *s, const double *y, double *dy);
/* Overlap delta = r_i + r_j - |x_j - x_i| of every pair (npair values). */
void rc_soft_overlap(const rc_soft_sys *s, const double *y, double *g);
/* 1 if pair q's centres approach at y: at a zero of its overlap the contact is on exactly
 * when they approach (decided from the state, not from a root's reported direction,
 * which is unreliable for a root found again at the restart point). */
int rc_soft_approaching(const rc_soft_sys *s, size_t q, const double *y);
/* Contact of pair q starts (start = 1) or ends (0) at state y. */
void rc_soft_switch(rc_soft_sys *s, size_t q, int start, const double *y);
/* Largest step that cannot carry an approaching pair that is not in contact through a
 * whole contact unseen: its gap over its closing speed (free flight), floored at rtol
 * times the radius crossing time; for a pair in contact, half its 1/omega.
 * INFINITY when no pair approaches or touches. */
double rc_soft_max_step(const rc_soft_sys *s, const double *y);
/* 1 when no pair is in contact and every pair is receding: nothing more can happen. */
int rc_soft_done(const rc_soft_sys *s, const double *y);
/* Record the conservation errors at y (after every accepted step and event). */
void rc_soft_observe(rc_soft_sys *s, const double *y);

#endif
