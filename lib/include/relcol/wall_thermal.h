/* relcol/wall_thermal.h — the momentum a thermal wall re-emits a ball with: the
 * wall-flux Jüttner law at the wall's temperature, density ~ (p_n / E) e^(-E/kT) d^3p
 * for p_n > 0 along the wall's normal into the gas (classically v_n e^(-mv^2/2kT)).
 * In 3-D exactly, without rejection: the direction follows Lambert's cosine law and
 * the kinetic energy K = E - m c^2 has density ~ (K^2 + 2 m c^2 K) e^(-K/kT), a mixture
 * of Gamma(3, kT) (weight kT/(kT + m c^2)) and Gamma(2, kT). In 2-D (d^2p) the
 * direction's density is cos a / 2 and K's ~ p c e^(-K/kT), drawn by rejection from
 * (K + sqrt(2 m c^2 K)) e^(-K/kT) (acceptance >= 1/sqrt 2). papers/transport.md, section 8. */
#ifndef RELCOL_WALL_THERMAL_H
#define RELCOL_WALL_THERMAL_H

#include "relcol/rng.h"
#include "relcol/vec.h"

/* *p_out: a re-emitted momentum in dim = 2 (the z components of normal and result are 0)
 * or 3, for rest mass m > 0 at temperature kT > 0 (finite), c > 0 (INFINITY: classical),
 * normal a nonzero finite vector into the gas (its direction is used). RC_OK, or
 * RC_EMASS, RC_ESPEEDOFLIGHT, RC_ENONFINITE (kT or normal not finite), RC_EINVAL (kT <= 0,
 * dim not 2 or 3, a 2-D normal with a z part), RC_EZERONORMAL; *p_out is untouched on
 * error. */
int rc_wall_thermal_emit(rc_rng *r, int dim, double m, double c, double kT, rc_vec3 normal,
                         rc_vec3 *p_out);

#endif
