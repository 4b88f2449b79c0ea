/* ce_rel.h — Chapman–Enskog shear viscosity, heat conductivity and bulk viscosity of the
 * dilute relativistic gas with a constant (isotropic) differential cross-section in the
 * invariant Boltzmann equation (Møller flux): the reference model of kinetic theory,
 * computed by deterministic quadrature (GSL), independent of the engine and of the
 * sphere kernel's Monte Carlo (tr_shear_heat.h). papers/transport.md, section 6.
 * Units: kT = c = 1 and sigma_T (the total cross-section) = 1, so eta and zeta come in
 * kT / (sigma_T c), lambda in k c / sigma_T; z = m c^2 / kT (0 is the massless gas). */
#ifndef RELCOL_CE_REL_H
#define RELCOL_CE_REL_H

/* Most trial functions per coefficient: the default quadrature integrates their
 * polynomial brackets exactly up to here (papers/transport.md, section 6). */
#define CE_REL_MAX_ORDER 16

/* Quadrature sizes: Gauss–Laguerre in the pair's kinetic invariant mass u = sqrt(s) - 2m
 * and its boost w = sqrt(s)(cosh chi - 1), Gauss–Legendre in the CM angle. */
typedef struct {
    int n_u, n_w, n_cos;
} ce_rel_quad;

/* The defaults: every figure of section 6 is converged in them to 1e-9 (64 -> 128). */
ce_rel_quad ce_rel_quad_default(void);

typedef struct {
    double eta, lambda, zeta; /* order-th approximation */
} ce_rel_coeffs;

/* Jüttner moments by adaptive quadrature, per particle: <K> and var K (= c_v / k) with
 * K = E - m the kinetic energy, and the scaled partition function Z e^z = int d^3p
 * e^-(E - m). */
typedef struct {
    double mean_k, var_k, z_scaled;
} ce_rel_juttner;

/* 0, or -1 with a reason in *why (a static string): z not finite and >= 0, order outside
 * 1..CE_REL_MAX_ORDER, a quadrature size outside 4..400, or a quadrature that failed. */
int ce_rel_juttner_moments(double z, ce_rel_juttner *out, const char **why);
int ce_rel_compute(double z, int order, const ce_rel_quad *q, ce_rel_coeffs *out,
                   const char **why);

/* Jüttner pair averages (independent balls at kT = c = 1): the Møller speed
 * <v_M> = <sqrt((p0.p1)^2 - m^4)/(E0 E1)>, whose sigma_T n^2/2 is the invariant collision
 * rate, and the table-frame relative speed <|v0 - v1|>; 0, or -1 with a reason. */
int ce_rel_pair_speeds(double z, const ce_rel_quad *q, double *v_moller, double *v_rel,
                       const char **why);

#endif
