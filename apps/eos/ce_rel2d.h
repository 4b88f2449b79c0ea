/* ce_rel2d.h — Chapman–Enskog shear viscosity, heat conductivity and bulk viscosity of the
 * dilute relativistic gas in two space dimensions (2+1), invariant Boltzmann equation
 * (Møller flux), by deterministic quadrature (GSL): the 2-D counterpart of ce_rel.h.
 * papers/transport-2d.md. The angular law in the pair's CM frame is a table
 * entry: isotropic (constant differential cross-section per angle) or the hard-disc law
 * (uniform impact parameter, (sigma/2)|sin(chi/2)|) — in 3-D the two coincide, in 2-D
 * they do not. Units: kT = c = 1 and sigma_T (the total cross-section, a length; 2 sigma
 * for discs of diameter sigma) = 1: eta and zeta in kT/(sigma_T c), lambda in k c/sigma_T;
 * z = m c^2 / kT (0 is the massless gas). */
#ifndef RELCOL_CE_REL2D_H
#define RELCOL_CE_REL2D_H

#include "ce_rel.h" /* ce_rel_coeffs, ce_rel_juttner: the same quantities */

/* Most trial functions per coefficient (as in 3-D). */
#define CE_REL2D_MAX_ORDER 16

/* The CM-frame angular laws. */
typedef enum { CE_REL2D_ISOTROPIC, CE_REL2D_HARD_DISC, CE_REL2D_NLAW } ce_rel2d_law;

/* Quadrature sizes: Gauss–Laguerre in the pair's kinetic invariant mass u = sqrt(s) - 2m
 * and its boost w = sqrt(s)(cosh chi - 1), the trapezoid rule on the CM circle (exact for
 * the trial functions' trigonometric polynomials when n_ang > 2 (order + 2); n_ang = 0
 * takes 2 (order + 2) + 2). */
typedef struct {
    int n_u, n_w, n_ang;
} ce_rel2d_quad;

/* The defaults: every figure of papers/transport-2d.md is converged in them (the test
 * doubles them). */
ce_rel2d_quad ce_rel2d_quad_default(void);

/* The law's name ("isotropic", "hard-disc"), or NULL for an unknown law. */
const char *ce_rel2d_law_name(ce_rel2d_law law);

/* Jüttner moments per particle in 2-D, closed forms: Z e^z = 2 pi (1 + z),
 * <K> = (z + 2)/(z + 1), var K = c_v/k = (z^2 + 4 z + 2)/(z + 1)^2. 0, or -1 with a reason
 * in *why (a static string) if z is not finite and >= 0. */
int ce_rel2d_juttner_moments(double z, ce_rel_juttner *out, const char **why);

/* 0, or -1 with a reason in *why: z not finite and >= 0, order outside
 * 1..CE_REL2D_MAX_ORDER, an unknown law, quadrature sizes outside 4..400 (n_u, n_w) or
 * n_ang (unless 0) outside 2 (order + 2) + 1 .. 400, or a bracket matrix not positive definite. */
int ce_rel2d_compute(double z, int order, ce_rel2d_law law, const ce_rel2d_quad *q,
                     ce_rel_coeffs *out, const char **why);

#endif
