/* covariance_plot.h — relcol-covariance's two gnuplot scripts (dp against density per c,
 * dp against c per frame), written from the rows the app measured. */
#ifndef RELCOL_COVARIANCE_PLOT_H
#define RELCOL_COVARIANCE_PLOT_H

#include "app.h"

/* What the figures show of a run: the same sweep as covariance.csv, whose columns 3, 5,
 * 10, 17 and 18 (c, density, v_rms, dp_frames, dp_roundoff) the scripts plot. */
typedef struct cov_plot {
    const rc_toi_frame *const *frames;
    int nframes;
    const double *density; /* sorted */
    int ndensity;
    const double *c; /* sorted: the finite values first, inf last */
    int nc;
    long n, dim;
    double boost, v_rms;
} cov_plot;

/* One row of covariance.csv, in its order: density by density, then c, then frame. */
typedef struct cov_plot_row {
    int have;               /* the differences were measured */
    double dp_frames, dp_roundoff;
    const char *note;       /* why not, when !have */
} cov_plot_row;

/* A frame difference within this factor of its round-off control is not told apart from
 * round-off: the control is one draw of how the dynamics amplifies a 1e-15 change, and
 * the controls of neighbouring densities scatter by a decade. */
#define COV_PLOT_RESOLVED 10.0

/* covariance.gp: one panel per c, dp against density, one colour per frame. 0, or -1
 * with the reason in err. */
int cov_plot_density(const char *path, const cov_plot *p, const cov_plot_row *rows,
                     char *err);
/* covariance-c.gp: one panel per frame, dp against c / v_rms over the nfin finite c
 * (nfin >= 2), one colour per density. */
int cov_plot_c(const char *path, const cov_plot *p, const cov_plot_row *rows, int nfin,
               char *err);

#endif
