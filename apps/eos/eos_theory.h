/* eos_theory.h — the reference values relcol-eos and its tests compare against: hard-sphere
 * and hard-disc equations of state and the Enskog transport coefficients with the
 * dense-fluid correction of the literature. Formulas and sources: papers/pressure.md and
 * papers/transport.md. Units: diameter sigma, mass m, kT (k = 1). */
#ifndef RELCOL_EOS_THEORY_H
#define RELCOL_EOS_THEORY_H

#include <math.h>

/* Carnahan–Starling (1969), hard spheres, packing fraction eta. */
static inline double eos_z_cs(double eta)
{
    const double q = 1.0 - eta;
    return (1.0 + eta + eta * eta - eta * eta * eta) / (q * q * q);
}

/* Kolafa's correction of Carnahan–Starling (Boublík & Nezbeda 1986), within about 0.01 %
 * of the simulated fluid up to eta = 0.45. */
static inline double eos_z_kolafa(double eta)
{
    const double q = 1.0 - eta;
    return (1.0 + eta + eta * eta - 2.0 / 3.0 * eta * eta * eta * (1.0 + eta)) / (q * q * q);
}

/* Hard discs: the virial series with the exact B2..B4 and Clisby & McCoy's (2006) B5..B10
 * (reduced B_k / B_2^{k-1}; B_2 = 2 a, a the disc area), Z = 1 + sum_k b_k (2 eta)^{k-1}.
 * The omitted tail is below 1e-4 of Z for eta <= 0.3 and grows to about 1e-3 at 0.4. */
static inline double eos_z_disc_virial(double eta)
{
    static const double red[] = {1.0, 0.782004, 0.53223180, 0.33355604, 0.1988425,
                                 0.1148728, 0.0649930, 0.0362193, 0.0199537};
    double z = 1.0, y = 2.0 * eta, pw = 1.0;
    for (int k = 0; k < 9; k++) {
        pw *= y;
        z += red[k] * pw;
    }
    return z;
}

/* Hard discs, the fluid to its freezing (eta ~ 0.70): Luding's equation of state (S. Luding,
 * "Global equation of state of two-dimensional hard sphere systems", Phys. Rev. E 63,
 * 042201 (2001), his P_4), Henderson's (1975) with a fourth-order correction fitted to
 * simulations. The virial series above falls 0.5 % below it at eta 0.5 and 5.5 % at 0.65:
 * its tail is not small there. */
static inline double eos_z_disc(double eta)
{
    const double q = 1.0 - eta;
    return (1.0 + eta * eta / 8.0) / (q * q) - 0.043 * eta * eta * eta * eta / (q * q * q);
}

/* Santos, López de Haro & Yuste (1995) for hard discs: eta_cp = pi / (2 sqrt 3). */
static inline double eos_z_disc_shy(double eta)
{
    const double cp = M_PI / (2.0 * sqrt(3.0));
    return 1.0 / (1.0 - 2.0 * eta + (2.0 * cp - 1.0) / (cp * cp) * eta * eta);
}

/* Contact value of the pair distribution, chi = g(sigma): from Z = 1 + b n chi
 * (b n = 4 eta in 3-D, 2 eta in 2-D), with Kolafa's Z (3-D) or Luding's (2-D). */
static inline double eos_chi(int dim, double eta)
{
    return dim == 3 ? (eos_z_kolafa(eta) - 1.0) / (4.0 * eta)
                    : (eos_z_disc(eta) - 1.0) / (2.0 * eta);
}

/* Hard spheres (3-D), number density n, sigma = m = 1, temperature kT: the first
 * Chapman–Enskog (Sonine) approximations of the dilute gas (Chapman & Cowling) ... */
static inline double tr_d0(double n, double kT) { return 3.0 / (8.0 * n) * sqrt(kT / M_PI); }
static inline double tr_eta0(double kT) { return 5.0 / 16.0 * sqrt(kT / M_PI); }
static inline double tr_lambda0(double kT) { return 75.0 / 64.0 * sqrt(kT / M_PI); }
/* ... and Enskog's dense-gas theory (Chapman & Cowling ch. 16; b n = 2 pi n / 3). */
static inline double tr_d_enskog(double eta, double kT)
{
    const double n = 6.0 * eta / M_PI;
    return tr_d0(n, kT) / eos_chi(3, eta);
}
static inline double tr_eta_enskog(double eta, double kT)
{
    const double bn = 4.0 * eta, chi = eos_chi(3, eta);
    return tr_eta0(kT) * (1.0 / chi + 0.8 * bn + 0.7614 * bn * bn * chi);
}
static inline double tr_lambda_enskog(double eta, double kT)
{
    const double bn = 4.0 * eta, chi = eos_chi(3, eta);
    return tr_lambda0(kT) * (1.0 / chi + 1.2 * bn + 0.7574 * bn * bn * chi);
}
/* Self-diffusion of the hard-sphere fluid, Speedy (1987): a fit to the simulations of
 * Alder, Gass & Wainwright (1970) and later ones that includes the dense-fluid correction
 * D / D_E; n* = n sigma^3. The data it represents are those of systems of about 500
 * spheres, not the infinite system (Sigurgeirsson & Heyes 2003 find it fits their N ~ 500
 * runs, while D keeps rising with N): papers/transport.md, section 3. */
static inline double tr_d_speedy(double eta, double kT)
{
    const double n = 6.0 * eta / M_PI;
    return 3.0 / 8.0 * sqrt(kT / M_PI) / n * (1.0 - n / 1.09) * (1.0 + n * n * (0.4 - 0.83 * n * n));
}
/* What a periodic cube of edge L takes off the infinite system's self-diffusion
 * (Yeh & Hummer 2004: the hydrodynamic images), for shear viscosity eta_s. */
static inline double tr_d_finite_size(double kT, double eta_s, double L)
{
    return 2.837297 * kT / (6.0 * M_PI * eta_s * L);
}
/* Speedy's fit carried from the 500-sphere box it represents to a cube of edge L: the
 * Yeh-Hummer difference between the two boxes (zero at N = 500). */
enum { TR_SPEEDY_N = 500 };
static inline double tr_d_speedy_box(double eta, double kT, double eta_s, double L)
{
    const double l500 = cbrt((double)TR_SPEEDY_N * M_PI / (6.0 * eta));
    return tr_d_speedy(eta, kT) + tr_d_finite_size(kT, eta_s, l500) -
           tr_d_finite_size(kT, eta_s, L);
}

#endif
