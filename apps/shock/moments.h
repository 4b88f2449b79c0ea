/* moments.h — the lab-frame densities a profile bin holds and the named fluid variables
 * made from them (papers/shock-tube.md, section 5), shared by the measurement, the
 * free-streaming reference and the ideal-fluid reference, so that all three pass through
 * the same formulas. Units: m = 1, k_B = 1, positions and times in table units. */
#ifndef RELCOL_SHOCK_MOMENTS_H
#define RELCOL_SHOCK_MOMENTS_H

#include "riemann.h"

/* densities per unit volume (d-volume), table frame */
typedef struct sh_mom {
    double N0;  /* balls */
    double Nx;  /* particle flux, sum v_x */
    double g;   /* momentum density sum p_x (= T^0x / c) */
    double K;   /* kinetic energy density sum (E - m c^2) (T^00 less the rest energy) */
    double Pxx; /* momentum flux sum p_x v_x (T^xx) */
    double Pyy; /* transverse momentum flux sum p_y v_y (T^yy) */
} sh_mom;

/* the named variables: Eckart flow velocity v = Nx/N0, rest density n = N0/W, pressure
 * from the momentum flux p = Pxx - v g, transverse p_perp = Pyy, T_p = p/n, T_e from the
 * rest-frame internal energy per ball through the Juttner (Maxwell) law */
enum { SH_N = 0, SH_V, SH_P, SH_PPERP, SH_TP, SH_TE, SH_NDERIVED };
extern const char *const sh_derived_names[SH_NDERIVED];

/* derived[SH_NDERIVED] from m (NAN where N0 = 0); dim 2 or 3, c may be INFINITY */
void sh_derive(int dim, double c, const sh_mom *m, double *derived);

/* the moments of an ideal fluid state (rho = n, p = n T) under equation of state e */
void sh_fluid_moments(int dim, double c, const rs_eos *e, rs_state s, sh_mom *m);

/* the average of at(x) over [xa, xb] (Gauss-Legendre, 8 points): the references' bins */
typedef int (*sh_mom_at)(double x, void *ctx, sh_mom *out);
int sh_mom_bin(sh_mom_at at, void *ctx, double xa, double xb, sh_mom *out);

/* T from the internal energy per ball eint (m = 1) of the d-D Juttner gas at c (Maxwell
 * at c = inf: T = 2 eint / d) */
double sh_T_from_eint(int dim, double c, double eint);

#endif
