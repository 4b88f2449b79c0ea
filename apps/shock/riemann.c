/* riemann.c — one entry for both Riemann solvers: c = inf is the Euler solution with the
 * equation of state's classical gamma, finite c the relativistic one in units c = 1
 * (velocities / c, pressures / c^2), its answer scaled back to table units. */
#include <math.h>

#include "riemann.h"

const char *rs_strerror(int code)
{
    switch (code) {
    case RS_OK: return "ok";
    case RS_EINVAL: return "not a fluid state (rho, p must be > 0 and finite, |v| < c)";
    case RS_EVACUUM: return "the two rarefactions open a vacuum (no plateau)";
    case RS_ENOCONV: return "a root or quadrature did not converge";
    default: return "unknown error";
    }
}

int rs_solve(const rs_eos *eos, double c, rs_state L, rs_state R, rs_solution *sol)
{
    if (!(c > 0.0))
        return RS_EINVAL;
    if (isinf(c)) {
        int rc = rs_euler_solve(eos->gamma, L, R, sol);
        sol->eos = *eos;
        return rc;
    }
    const double c2 = c * c;
    rs_state l = {L.rho, L.v / c, L.p / c2}, r = {R.rho, R.v / c, R.p / c2};
    int rc = rs_rel_solve(eos, l, r, sol);
    if (rc)
        return rc;
    sol->c = c;
    sol->p_star *= c2;
    sol->v_star *= c;
    sol->headL *= c;
    sol->tailL *= c;
    sol->headR *= c;
    sol->tailR *= c;
    return RS_OK;
}

int rs_sample(const rs_solution *sol, double xi, rs_state *out)
{
    if (isinf(sol->c))
        return rs_euler_sample(sol, xi, out);
    const double c = sol->c;
    rs_solution s = *sol;
    s.p_star /= c * c;
    s.v_star /= c;
    s.headL /= c;
    s.tailL /= c;
    s.headR /= c;
    s.tailR /= c;
    int rc = rs_rel_sample(&s, xi / c, out);
    out->v *= c;
    out->p *= c * c;
    return rc;
}
