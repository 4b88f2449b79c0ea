/* gas_summary.c — relcol-gas's summary.json (cJSON), written like relcol-sim's: numbers in
 * round-trip precision, what JSON cannot hold (inf, nan) as null, through app_atomic so a
 * reader never sees half a file. Each measurement is {"value": x, "err": standard error};
 * chi-squares carry their dof and p-values (GSL). The top-level thermometers are species
 * 0's (in 1-D the light one, m = 1, whose theta is kT); "species" has every species. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "app.h"
#include "gas_stats.h"
#include "gas_summary.h"

static cJSON *num(double x) { return isfinite(x) ? cJSON_CreateNumber(x) : cJSON_CreateNull(); }

static void add(cJSON *o, const char *key, double x) { cJSON_AddItemToObject(o, key, num(x)); }

static void add_ve(cJSON *o, const char *key, double v, double e)
{
    cJSON *x = cJSON_CreateObject();
    add(x, "value", v);
    add(x, "err", e);
    cJSON_AddItemToObject(o, key, x);
}

static void add_thermometers(cJSON *o, const gas_summary_species *q)
{
    add_ve(o, "theta_gamma", q->theta_gamma, q->theta_gamma_err);
    add_ve(o, "theta_pv", q->theta_pv, q->theta_pv_err);
    add_ve(o, "theta_difference", q->theta_pv - q->theta_gamma, q->theta_diff_err);
    add_ve(o, "mean_gamma", q->mean_gamma, q->mean_gamma_err);
    add_ve(o, "mean_pv", q->mean_pv, q->mean_pv_err);
}

static cJSON *chi2_object(const gas_summary_species *q)
{
    cJSON *x = cJSON_CreateObject();
    add(x, "cells", q->cells);
    add(x, "dof", q->dof);
    add(x, "phi", q->phi);
    add(x, "juttner", q->chi2_juttner);
    add(x, "juttner_p", gs_chi2_p(q->chi2_juttner, q->dof));
    add(x, "maxwell_boltzmann", q->chi2_mb);
    add(x, "maxwell_boltzmann_p", gs_chi2_p(q->chi2_mb, q->dof));
    add(x, "bound_5sigma", gs_chi2_sigma_bound(q->dof, 5.0));
    return x;
}

int gas_summary_write(const char *path, const gas_summary *s, char *err)
{
    static const char *const thermal[] = {"no", "dilute limit only", "every density",
                                          "not shown in 3-D"};
    cJSON *j = cJSON_CreateObject(), *x;
    if (!j)
        goto nomem;
    add(j, "relcol", 1);
    cJSON_AddStringToObject(j, "program", s->prog);
    cJSON_AddItemToObject(j, "parameters", x = cJSON_CreateObject());
    add(x, "dim", s->dim);
    add(x, "n", (double)s->n);
    add(x, "c", s->c);
    add(x, "theta_start", s->theta_start);
    add(x, "v_rms", s->v_rms);
    add(x, "gamma_start", s->gamma_start);
    if (s->dim == 1)
        add(x, "theta_of_energy", s->theta_energy);
    add(x, "packing", s->packing);
    add(x, "box", s->box);
    cJSON_AddStringToObject(x, "boundary", s->boundary);
    if (s->frame)
        cJSON_AddStringToObject(x, "frame", s->frame);
    else
        cJSON_AddNullToObject(x, "frame");
    if (s->readout)
        cJSON_AddStringToObject(x, "readout", s->readout);
    if (s->readout && strcmp(s->readout, "slice") == 0) {
        add(x, "slices_read", (double)s->slices_read);
        add(x, "slices_changed_after_read", (double)s->slices_late);
    }
    add(x, "t_equil", s->t_equil);
    add(x, "t_sample", s->t_sample);
    add(x, "snapshots", (double)s->snapshots);
    add(x, "blocks", s->blocks);
    add(x, "seed", (double)s->seed);
    if (s->thermal >= 0 && s->thermal <= 3)
        cJSON_AddStringToObject(j, "frame_thermal", thermal[s->thermal]);
    add_thermometers(j, &s->sp[0]);
    add(j, "theta_microcanonical", s->sp[0].theta_micro);
    cJSON_AddItemToObject(j, "chi2", chi2_object(&s->sp[0]));
    add_ve(j, "collision_rate", s->rate, s->rate_err);
    add(j, "collision_rate_per_ball", 2.0 * s->rate / (double)s->n);
    /* (papers/pressure.md; not measured for the 1-D gas: null) */
    add_ve(j, "pressure", s->pressure, s->pressure_err);
    if (s->pressure_kind)
        cJSON_AddStringToObject(j, "pressure_kind", s->pressure_kind);
    cJSON_AddItemToObject(j, "species", x = cJSON_CreateArray());
    for (int q = 0; x && q < s->nspec; q++) {
        cJSON *o = cJSON_CreateObject();
        add(o, "mass", s->sp[q].mass);
        add(o, "count", (double)s->sp[q].count);
        add_thermometers(o, &s->sp[q]);
        add(o, "theta_microcanonical", s->sp[q].theta_micro);
        cJSON_AddItemToObject(o, "chi2", chi2_object(&s->sp[q]));
        add(o, "correlation_time_snapshots", s->sp[q].tau);
        cJSON_AddItemToArray(x, o);
    }
    if (s->observer) {
        /* the gas seen by an observer moving along x, on its simultaneity hyperplanes */
        cJSON *ob = cJSON_CreateObject();
        add(ob, "velocity", s->obs_v);
        add(ob, "sampled", (double)s->obs_sampled);
        add(ob, "lost", (double)s->obs_lost);
        add(ob, "dof", s->obs_dof);
        add(ob, "phi", s->obs_phi);
        add(ob, "chi2_boosted_juttner", s->obs_chi2);
        add(ob, "chi2_boosted_juttner_p", gs_chi2_p(s->obs_chi2, s->obs_dof));
        add(ob, "chi2_juttner_at_rest", s->obs_chi2_rest);
        if (s->obs_nspec > 0) {
            add(ob, "correlation_time_hyperplanes", s->obs_tau);
            cJSON *sa = cJSON_CreateArray();
            for (int q = 0; sa && q < s->obs_nspec; q++) {
                cJSON *o = cJSON_CreateObject();
                add(o, "mass", s->obs_sp[q].mass);
                add(o, "theta", s->obs_sp[q].theta);
                add(o, "dof", s->obs_sp[q].dof);
                add(o, "phi", s->obs_sp[q].phi);
                add(o, "chi2_boosted_juttner", s->obs_sp[q].chi2);
                add(o, "chi2_boosted_juttner_p", gs_chi2_p(s->obs_sp[q].chi2, s->obs_sp[q].dof));
                add(o, "chi2_juttner_at_rest", s->obs_sp[q].chi2_rest);
                cJSON_AddItemToArray(sa, o);
            }
            cJSON_AddItemToObject(ob, "species", sa);
        }
        cJSON_AddItemToObject(j, "observer", ob);
    }
    add(j, "collisions", (double)s->collisions);
    add(j, "overlaps", (double)s->overlaps);
    add(j, "rest_mass_drift", s->mass_drift);
    add(j, "energy_drift", s->energy_drift);
    char *text = cJSON_Print(j);
    cJSON_Delete(j);
    if (!text)
        goto nomem_text;
    app_atomic a;
    int r = -1;
    if (app_atomic_open(&a, path, err) == 0) {
        fprintf(a.f, "%s\n", text);
        r = app_atomic_commit(&a, err);
    }
    free(text);
    return r;
nomem:
    cJSON_Delete(j);
nomem_text:
    app_errf(err, "out of memory writing summary.json");
    return -1;
}
