/* pyrelcol.h — the package-side C of the Python package (compiled into relcol._relcol,
 * never part of librelcol): loops over balls and pairs that fill or read numpy arrays in
 * one call, so that no Python loop runs per ball or per pair. Prefix rcpy_. */
#ifndef RELCOL_PYRELCOL_H
#define RELCOL_PYRELCOL_H

#include <stddef.h>
#include <stdint.h>

#include "relcol/relcol.h"

/* Which state rcpy_sim_read reads: rc_sim_get_ball, rc_sim_get_ball_latest, or a slice
 * (rc_sim_slice_get). */
enum { RCPY_NOW = 0, RCPY_LATEST = 1, RCPY_SLICE = 2 };

/* Every ball of s into arrays (any may be NULL: not read): x, p and v (p / M, M the mass
 * rc_velocity forms at inv_c2 = 1/c^2) n x dim, row-major; r, m, tau n; tau_last n (NaN
 * for a ball that has not collided); image n x dim; ahead n (rc_sim_kink_ahead, RCPY_NOW
 * only). n must be rc_sim_count(s) (RC_EINVAL otherwise). On failure *bad names the ball. */
int rcpy_sim_read(rc_sim *s, int which, uint32_t slice, size_t n, int dim, double inv_c2,
                  double *x, double *p, double *v, double *r, double *m, double *tau,
                  double *tau_last, int32_t *image, int8_t *ahead, size_t *bad);

/* Every ball of s as an rc_sim_ball (n = rc_sim_count(s)), for scn_write and add(). */
int rcpy_sim_balls(const rc_sim *s, size_t n, rc_sim_ball *out, size_t *bad);

/* The pairs of relcol.collide, with rc_collide's checks and bits (shared c and eps:
 * rc_collide_columns, the checks a block at a time; per-pair c or eps: rc_collide), read from the caller's arrays and written to fresh ones
 * in the same pass: no packed copy. Quantity q of pair i is at q[i * q_stride] (a vector's
 * dim components from there; stride 0: one value shared by every pair); c and eps
 * likewise. Vectors have dim (1..3) components, the rest taken as 0; out: m0o, m1o n,
 * p0o, p1o n x dim. The first failing pair in *bad, its code returned (the pairs before it
 * written). */
int rcpy_collide(const rc_law *law, const rc_collision_params *prm, size_t n, int dim,
                 const double *c, size_t c_stride, const double *eps, size_t eps_stride,
                 const double *m0, size_t m0_stride, const double *p0, size_t p0_stride,
                 const double *m1, size_t m1_stride, const double *p1, size_t p1_stride,
                 const double *nrm, size_t n_stride, double *m0o, double *p0o, double *m1o,
                 double *p1o, int *status, size_t *hits, size_t *bad);

#endif
