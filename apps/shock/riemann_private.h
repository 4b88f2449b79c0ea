/* riemann_private.h — what the two Riemann solvers share: Brent's root in an interval. */
#ifndef RELCOL_SHOCK_RIEMANN_PRIVATE_H
#define RELCOL_SHOCK_RIEMANN_PRIVATE_H

/* the root of fn (a sign change in [lo, hi]) to 1e-14 relative; RS_ENOCONV otherwise */
int rs_brent_(double (*fn)(double, void *), void *prm, double lo, double hi, double *root);

#endif
