/* front.h — where a shock front is in a density profile (papers/shock-tube.md, section 6):
 * the logistic step n(x) = n_b + (n_a - n_b) / (1 + exp((x - x_s)/w)) with its two levels
 * given (the states the fluid solution's shock joins) fitted by least squares to the bins
 * in a window, for x_s and w: the front's mid-level point, which a steady shock structure
 * of any width carries at the shock speed. */
#ifndef RELCOL_SHOCK_FRONT_H
#define RELCOL_SHOCK_FRONT_H

typedef struct sh_front {
    double na, nb;      /* the levels behind (x < x_s) and ahead of the front */
    double xlo, xhi;    /* the window: bins whose centres lie inside are fitted */
    double x_guess, w_guess;
} sh_front;

/* x_s (and the width w, if w != NULL) from nb bins at centres xc with densities n and
 * weights wt (1/variance, > 0). Returns 0, or -1 (fewer than 4 bins in the window, or the
 * fit did not converge: *xs = NAN). */
int sh_front_fit(const sh_front *f, const double *xc, const double *n, const double *wt,
                 int nb, double *xs, double *w);

#endif
