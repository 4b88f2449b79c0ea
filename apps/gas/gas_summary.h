/* gas_summary.h — relcol-gas's summary.json: every measured quantity with its error and
 * the run's parameters, for programs (what the app prints for a person). */
#ifndef RELCOL_GAS_SUMMARY_H
#define RELCOL_GAS_SUMMARY_H

#include <stddef.h>
#include <stdint.h>

typedef struct gas_summary_species {
    double mass;
    size_t count;
    double theta_gamma, theta_gamma_err, theta_pv, theta_pv_err, theta_diff_err;
    double mean_gamma, mean_gamma_err; /* <gamma> */
    double mean_pv, mean_pv_err;       /* <p.v> / (m c^2) */
    double theta_micro;                /* NAN where there is none */
    int cells;
    double dof, phi, chi2_juttner, chi2_mb; /* chi2 already divided by phi */
    double tau;                             /* correlation time, snapshots */
} gas_summary_species;

typedef struct gas_summary {
    const char *prog;
    int dim;
    long n;
    double c;
    double theta_start, v_rms; /* the one given, the other NAN */
    double packing;            /* NAN in 1-D */
    double t_equil, t_sample;
    long snapshots;            /* used (whole blocks) */
    int blocks;
    uint64_t seed;
    const char *frame;         /* NULL in 1-D */
    const char *readout;       /* per_ball frames: the snapshots' read-out; else NULL */
    uint64_t slices_read, slices_late; /* --readout slice: read, changed after the read */
    int thermal;               /* gas_frame_thermal(), -1 in 1-D */
    const char *boundary;
    double gamma_start, box;
    double theta_energy;       /* 1-D: kT of the whole gas's energy; NAN otherwise */
    uint64_t collisions, overlaps;
    double mass_drift, energy_drift;
    double rate, rate_err;     /* collisions per unit table time over the sample */
    double pressure, pressure_err; /* block mean and error; NAN in 1-D */
    const char *pressure_kind; /* what was measured (walls' or the gas's momentum flux) */
    int nspec;
    gas_summary_species sp[2];
    /* --observer-velocity: the moving observer's sample */
    int observer;
    double obs_v, obs_chi2, obs_chi2_rest, obs_phi, obs_dof;
    uint64_t obs_sampled, obs_lost;
    int obs_nspec; /* 1-D: per species (the top level sums their chi2/phi; phi null) */
    double obs_tau; /* 1-D: correlation time of a hyperplane's energy, in hyperplanes */
    struct {
        double mass, theta, chi2, chi2_rest, phi, dof;
    } obs_sp[2];
} gas_summary;

/* Write s as JSON to path atomically (a temporary beside it, renamed); -1 with err
 * (APP_ERR_LEN) on failure. */
int gas_summary_write(const char *path, const gas_summary *s, char *err);

#endif
