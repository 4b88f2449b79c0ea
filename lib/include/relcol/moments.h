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

/// An engine's moments at its time; tensors row-major 3 x 3, [3 a + b], z rows and columns 0 in 2-D.
typedef struct rc_sim_moments {
    double time;               ///< engine time
    size_t n;                  ///< balls
    int dim;                   ///< 2 or 3
    double volume;             ///< box area (2-D) or volume (3-D)
    double kinetic[9];         ///< sum_i p_i,a v_i,b: V times the kinetic pressure tensor now
    double energy;             ///< sum_i of kinetic energy (M_i - m_i) c^2
    double virial[9];          ///< rc_sim_diag.virial: collisional momentum transfer so far
    double virial_energy[3];   ///< rc_sim_diag.virial_energy: collisional energy transfer so far
    double helfand[9];         ///< Helfand moment G = sum_i x_i,a p_i,b + helfand_wrap (x unwrapped): (G(t2) - G(t1)) / (V (t2 - t1)) is the pressure tensor's time average, its off-diagonal variance growth the shear viscosity
    double helfand_energy[3];  ///< sum_i x_i,a E_i + helfand_wrap_energy (E kinetic): minus h position, the heat moment (Eckart) of the thermal conductivity
    double position[3];        ///< sum_i x_i,a (unwrapped)
} rc_sim_moments;

/// Read the moments of s at its time (O(N)); RC_EINVAL for NULL arguments, RC_EUNDEFINED in a
/// uniform field (its loop books no collisional transfer; papers/gravity.md, model limits).
int rc_sim_moments_get(const rc_sim *s, rc_sim_moments *out);

#ifdef __cplusplus
}
#endif
#endif
