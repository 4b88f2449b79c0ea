/* riemann.h — exact Riemann solutions of ideal-fluid dynamics along x, the references
 * relcol-shock's profiles are held to (papers/shock-tube.md, sections 2-4):
 *   c = inf: the Euler equations of the ideal gas p = rho T / m with adiabatic index gamma
 *            (Toro's pressure function, sampled at xi = x/t);
 *   finite c: special-relativistic hydrodynamics (Marti & Mueller 1994) for an ideal gas
 *            p = n T whose specific enthalpy h(theta), theta = T/(m c^2), is an equation of
 *            state from rs_eos_ops: constant Gamma, or the Synge (Juttner) gas of balls in
 *            3-D (h = K3/K2(1/theta)) and of discs in 2-D (h = K_{5/2}/K_{3/2});
 *            rarefactions by quadrature of the Riemann invariant, shocks by the Taub
 *            adiabat, the contact by p and v continuity, all by GSL.
 * Functions return 0 or a negative RS_E* code; nothing here prints. */
#ifndef RELCOL_SHOCK_RIEMANN_H
#define RELCOL_SHOCK_RIEMANN_H

#include <math.h>

enum {
    RS_OK = 0,
    RS_EINVAL = -1,  /* a state that is not one: rho, p <= 0 or not finite, |v| >= c */
    RS_EVACUUM = -2, /* the two rarefactions leave a vacuum between them (no star state) */
    RS_ENOCONV = -3  /* a root or quadrature failed to converge (GSL's status) */
};
const char *rs_strerror(int code);

/* One side's fluid state in the table frame: rest-mass density, velocity along x,
 * pressure (any units; the relativistic solver takes c and scales to c = 1). */
typedef struct rs_state {
    double rho, v, p;
} rs_state;

/* ---- equations of state of an ideal gas p = rho theta (c = 1, m = 1) ----------------- */
typedef struct rs_eos rs_eos;
typedef struct rs_eos_ops {
    const char *name;
    /* h - 1, the specific enthalpy less the rest mass, without cancellation as theta -> 0 */
    double (*hm1)(const rs_eos *e, double theta);
    /* dh/dtheta (its limit at theta -> 0 is gamma/(gamma - 1), the classical gas's) */
    double (*dh)(const rs_eos *e, double theta);
} rs_eos_ops;
struct rs_eos {
    const rs_eos_ops *ops;
    double gamma; /* constant-Gamma gas: its Gamma; Synge gases: the classical 1 + 2/d */
    int dim;      /* Synge gases: 2 or 3 */
};
rs_eos rs_eos_ideal(double gamma); /* h = 1 + Gamma theta / (Gamma - 1) */
rs_eos rs_eos_synge(int dim);      /* the Juttner gas of hard balls (3) or discs (2) */
/* sound speed^2 / c^2 = theta h' / (h (h' - 1)) */
double rs_eos_cs2(const rs_eos *e, double theta);

/* ---- solutions ----------------------------------------------------------------------- */
enum { RS_RAREFACTION = 0, RS_SHOCK = 1 };
typedef struct rs_solution {
    /* inputs, scaled to the solver's units (c = 1 for the relativistic one) */
    rs_state L, R;
    double c;                 /* INFINITY: the Euler solution */
    rs_eos eos;
    double p_star, v_star;    /* the plateau: pressure and velocity (table units) */
    double rho_starL, rho_starR;
    int waveL, waveR;         /* RS_SHOCK or RS_RAREFACTION */
    /* x/t of the waves, table units: a shock's speed (head = tail), or a rarefaction's head
     * (the side's sound front) and tail (the plateau's sound front) */
    double headL, tailL, headR, tailR;
} rs_solution;

/* Solve the Riemann problem L | R at speed of light c (INFINITY: Euler, with the
 * equation of state's classical gamma). */
int rs_solve(const rs_eos *eos, double c, rs_state L, rs_state R, rs_solution *sol);
/* The state at xi = (x - x0)/t (table units). */
int rs_sample(const rs_solution *sol, double xi, rs_state *out);

/* The Euler solution itself (gamma > 1), for tests of the classical path. */
int rs_euler_solve(double gamma, rs_state L, rs_state R, rs_solution *sol);
int rs_euler_sample(const rs_solution *sol, double xi, rs_state *out);
/* The relativistic solution at c = 1 (|v| < 1). */
int rs_rel_solve(const rs_eos *eos, rs_state L, rs_state R, rs_solution *sol);
int rs_rel_sample(const rs_solution *sol, double xi, rs_state *out);

/* Relativistic shock adiabat from state a (c = 1) to pressure pb > pa, for tests and the
 * solver: the post-shock density and the shock-frame-free relative velocity
 * v_rel^2 = (pb - pa)(eb - ea) / ((ea + pb)(eb + pa)), e = rho h - p the energy density. */
int rs_rel_shock(const rs_eos *eos, rs_state a, double pb, double *rhob, double *vrel);

/* ---- c = inf, the dense hard-sphere gas: P = n T Z(phi), phi = n vball, e = 3/2 T ---- */
typedef struct rs_hs rs_hs;
struct rs_hs {
    double (*z)(const rs_hs *g, double phi);  /* the compressibility factor */
    double (*dz)(const rs_hs *g, double phi); /* its derivative */
    double (*zm1p)(const rs_hs *g, double phi); /* (Z - 1)/phi without cancellation */
    double vball;                             /* a ball's volume, (4/3) pi r^3 */
    double z0;                                /* rs_hs_constz's Z */
};
rs_hs rs_hs_kolafa(double vball);          /* Kolafa's Z (apps/eos/eos_theory.h) */
rs_hs rs_hs_constz(double vball, double z0); /* Z held at z0: the gamma-law, gamma = 1 + 2 z0/3 */
double rs_hs_cs2(const rs_hs *g, double n, double T); /* T (Z + phi Z' + 2/3 Z^2) */
typedef struct rs_hs_solution {
    double p_star, v_star, rho_starL, rho_starR, T_starL, T_starR;
    int waveL, waveR;
    double headL, tailL, headR, tailR;
} rs_hs_solution;
/* rho is the number density n (m = 1); each side's packing below 0.7 */
int rs_hs_solve(const rs_hs *g, rs_state L, rs_state R, rs_hs_solution *sol);

#endif
