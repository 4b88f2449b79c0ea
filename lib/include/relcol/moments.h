/* relcol/moments.h — what a statistical physicist reads off an engine: the momentum and
 * energy moments whose time derivatives are the fluxes of a hard-ball gas, from which the
 * pressure tensor, the equation of state and the transport coefficients follow
 * (papers/pressure.md, papers/transport.md). One call reads a snapshot; the caller owns
 * the loop, the differences between snapshots and their statistics. */
#ifndef RELCOL_MOMENTS_H
#define RELCOL_MOMENTS_H

#include <stddef.h>
#include "relcol/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Tensors are row-major 3 x 3, [3 a + b]; in 2-D the z rows and columns are 0. */
typedef struct rc_sim_moments {
    double time;
    size_t n;
    int dim;
    double volume;         /* box area (2-D) or volume (3-D) */
    double kinetic[9];     /* sum_i p_i,a v_i,b: V times the kinetic pressure tensor now */
    double energy;         /* sum_i of kinetic energy (M_i - m_i) c^2 */
    double virial[9];      /* rc_sim_diag.virial: collisional momentum transfer so far */
    double virial_energy[3];
    /* Helfand moments: G[3 a + b] = sum_i x_i,a p_i,b + rc_sim_diag.helfand_wrap, x the
     * unwrapped position (x + image L on periodic axes). In a periodic box
     * G(t2) - G(t1) = integral of V P_ab dt exactly (kinetic flux between collisions,
     * collisional transfer at them), so the pressure tensor's time average is
     * (G(t2) - G(t1)) / (V (t2 - t1)) and the shear viscosity comes from the growth of
     * its off-diagonal variance. */
    double helfand[9];
    /* sum_i x_i,a E_i + helfand_wrap_energy (E kinetic): the energy moment; with position
     * (sum_i x_i,a) and the enthalpy per ball h, helfand_energy - h position is the heat
     * moment (Eckart), whose variance gives the thermal conductivity. */
    double helfand_energy[3];
    double position[3];
} rc_sim_moments;

/* Read the moments of s at its time. RC_EINVAL for NULL arguments. O(N). */
int rc_sim_moments_get(const rc_sim *s, rc_sim_moments *out);

#ifdef __cplusplus
}
#endif
#endif
