/* sensitivity.c — the apps' --sensitivity mode (issue 36): the same scenario run again
 * (i) with every position moved by 1e-15 of a radius and (ii) under each alternative rule
 * the run's frame offers, and each observable's shift in units of its error. A shift
 * above three errors says the result depends on the model's rules, not only on the
 * physics.
 *
 * The error of an observable is sqrt(se^2 + d^2): se the app's own statistical error of
 * the base run (0 for a single deterministic outcome), d its shift under the 1e-15 move
 * (the run's own round-off growth: in a chaotic gas the moved run decorrelates and d is of
 * statistical size; in a few-ball scene it is the round-off), floored at 4 ulp of the value.
 * The rules offered: the other group rule (simultaneous / sequential) always; the other
 * contracted contact frames (table, zmf, covariant, transport: the ways of placing a
 * contact of contracted balls) when the run's frame is one of them at finite c. The sphere
 * frame (uncontracted) is a different body, not another rule, and is not offered; nor is
 * any order rule, which the engine does not expose as a choice. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"

size_t app_sens_variants(const rc_toi_frame *frame, int groups, double c, int dim,
                         app_sens_variant *v, size_t cap)
{
    size_t n = 0;
    if (n < cap)
        v[n++] = (app_sens_variant){"base", 0.0, groups, frame};
    if (n < cap)
        v[n++] = (app_sens_variant){"moved 1e-15", 1e-15, groups, frame};
    const int other = groups == RC_GROUPS_SEQUENTIAL ? RC_GROUPS_SIMULTANEOUS : RC_GROUPS_SEQUENTIAL;
    if (n < cap) {
        v[n] = (app_sens_variant){"", 0.0, other, frame};
        snprintf(v[n].name, sizeof v[n].name, "groups %s", rc_group_rule_name(other));
        n++;
    }
    if (frame && frame->contracted && isfinite(c) && dim >= 2)
        for (size_t f = 0; rc_toi_frames[f] && n < cap; f++) {
            const rc_toi_frame *g = rc_toi_frames[f];
            if (g == frame || !g->contracted)
                continue;
            v[n] = (app_sens_variant){"", 0.0, groups, g};
            snprintf(v[n].name, sizeof v[n].name, "frame %s", g->name);
            n++;
        }
    return n;
}

void app_sens_move(rc_sim_ball *b, size_t n, int dim, double move)
{
    /* each coordinate by +-move r, the signs a fixed pattern of the ball and the axis */
    for (size_t i = 0; i < n; i++)
        for (int d = 0; d < dim; d++) {
            const unsigned h = (unsigned)(i * 2654435761u) ^ (unsigned)(d * 40503u);
            const double s = (h >> 7) & 1u ? 1.0 : -1.0;
            rc_v3_set(&b[i].x, d, rc_v3_get(b[i].x, d) + s * move * b[i].r);
        }
}

static void json_num(FILE *f, double x)
{
    if (isfinite(x))
        fprintf(f, "%.17g", x);
    else
        fprintf(f, "null");
}

/* the shift of x under a variant in errors, and its flag */
static double in_errors(double shift, double err) { return err > 0.0 ? fabs(shift) / err : 0.0; }

int app_sensitivity(FILE *f, const char *dir, const app_sens_variant *v, size_t nv, size_t nobs,
                    const char *const *names, app_sens_run_fn run, void *ctx, char *err)
{
    if (nv < 2 || nobs == 0) {
        app_errf(err, "sensitivity: nothing to compare");
        return -1;
    }
    double *x = malloc(2 * nv * nobs * sizeof *x);
    double *er = malloc(nobs * sizeof *er);
    if (!x || !er) {
        free(x);
        free(er);
        app_errf(err, "out of memory");
        return -1;
    }
    double *se = x + nv * nobs;
    for (size_t k = 0; k < nv; k++) {
        fprintf(stderr, "sensitivity: run %zu of %zu (%s)\n", k + 1, nv, v[k].name);
        if (run(ctx, &v[k], x + k * nobs, se + k * nobs, err) != 0) {
            char e2[APP_ERR_LEN];
            snprintf(e2, sizeof e2, "%s", err);
            app_errf(err, "sensitivity run '%s': %s", v[k].name, e2);
            free(x);
            free(er);
            return -1;
        }
    }
    for (size_t j = 0; j < nobs; j++) {
        const double d = x[nobs + j] - x[j], s0 = se[j];
        const double floor_ = 4.0 * DBL_EPSILON * fabs(x[j]);
        const double e = sqrt(s0 * s0 + d * d);
        er[j] = e > floor_ ? e : floor_;
    }
    /* the table */
    size_t flagged = 0;
    fprintf(f, "sensitivity: shift of each observable under each variant, in units of its "
               "error (sqrt(se^2 + shift under the 1e-15 move^2)); * above 3\n");
    fprintf(f, "%-22s %14s %10s", "observable", "value", "error");
    for (size_t k = 1; k < nv; k++)
        fprintf(f, " %18s", v[k].name);
    fprintf(f, "\n");
    for (size_t j = 0; j < nobs; j++) {
        int any = 0;
        fprintf(f, "%-22s %14.7g %10.3g", names[j], x[j], er[j]);
        for (size_t k = 1; k < nv; k++) {
            const double z = in_errors(x[k * nobs + j] - x[j], er[j]);
            const int fl = z > 3.0;
            any |= fl;
            fprintf(f, " %17.3g%s", z, fl ? "*" : " ");
        }
        fprintf(f, "%s\n", any ? "  depends on the model's rules, not only on the physics" : "");
        flagged += (size_t)any;
    }
    fprintf(f, "sensitivity: %zu of %zu observables flagged; %zu runs\n", flagged, nobs, nv);
    /* the files */
    int rc = 0;
    static const char *const file[2] = {"sensitivity.csv", "sensitivity.json"};
    for (int w = 0; w < 2 && rc == 0; w++) {
        char *path = app_path_join(dir, file[w]);
        app_atomic a;
        if (!path) {
            app_errf(err, "out of memory");
            rc = -1;
            break;
        }
        if (app_atomic_open(&a, path, err) != 0) {
            free(path);
            rc = -1;
            break;
        }
        free(path);
        if (w == 0) {
            fprintf(a.f, "observable,value,error,variant,variant_value,shift,shift_in_errors,flag\n");
            for (size_t j = 0; j < nobs; j++)
                for (size_t k = 1; k < nv; k++) {
                    const double sh = x[k * nobs + j] - x[j], z = in_errors(sh, er[j]);
                    fprintf(a.f, "%s,%.17g,%.17g,%s,%.17g,%.17g,%.17g,%d\n", names[j], x[j],
                            er[j], v[k].name, x[k * nobs + j], sh, z, z > 3.0);
                }
        } else {
            fprintf(a.f, "{\n  \"threshold_errors\": 3,\n  \"flagged\": %zu,\n  \"variants\": [",
                    flagged);
            for (size_t k = 1; k < nv; k++)
                fprintf(a.f, "%s\"%s\"", k > 1 ? ", " : "", v[k].name);
            fprintf(a.f, "],\n  \"observables\": [\n");
            for (size_t j = 0; j < nobs; j++) {
                fprintf(a.f, "    {\"name\": \"%s\", \"value\": ", names[j]);
                json_num(a.f, x[j]);
                fprintf(a.f, ", \"se\": ");
                json_num(a.f, se[j]);
                fprintf(a.f, ", \"error\": ");
                json_num(a.f, er[j]);
                fprintf(a.f, ", \"shifts\": {");
                int any = 0;
                for (size_t k = 1; k < nv; k++) {
                    const double sh = x[k * nobs + j] - x[j], z = in_errors(sh, er[j]);
                    any |= z > 3.0;
                    fprintf(a.f, "%s\"%s\": {\"value\": ", k > 1 ? ", " : "", v[k].name);
                    json_num(a.f, x[k * nobs + j]);
                    fprintf(a.f, ", \"shift\": ");
                    json_num(a.f, sh);
                    fprintf(a.f, ", \"in_errors\": ");
                    json_num(a.f, z);
                    fprintf(a.f, "}");
                }
                fprintf(a.f, "}, \"flag\": %s}%s\n", any ? "true" : "false",
                        j + 1 < nobs ? "," : "");
            }
            fprintf(a.f, "  ]\n}\n");
        }
        if (app_atomic_commit(&a, err) != 0)
            rc = -1;
    }
    free(x);
    free(er);
    return rc == 0 ? (int)flagged : -1;
}

int app_sensitivity_main(const char *prog, const char *dir, const rc_toi_frame *frame, int groups,
                         double c, int dim, size_t nobs, const char *const *names,
                         app_sens_run_fn run, void *ctx)
{
    char err[APP_ERR_LEN];
    app_sens_variant v[16];
    const size_t nv = app_sens_variants(frame, groups, c, dim, v, 16);
    if (app_mkdir_p(dir, err) != 0)
        return app_fail(prog, 2, "--out: %s", err);
    if (app_sensitivity(stdout, dir, v, nv, nobs, names, run, ctx, err) < 0)
        return app_fail(prog, 1, "%s", err);
    printf("%s: wrote %s/sensitivity.csv, %s/sensitivity.json\n", prog, dir, dir);
    app_validity_warn(stderr, prog);
    return 0;
}
