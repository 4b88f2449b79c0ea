/* simout.c — relcol-sim's files. Snapshots (CSV), the extended-XYZ trajectory and the
 * figure data are streamed into temporary files and renamed into place when complete;
 * final.json and summary.txt are written whole at the end (or at Ctrl-C). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "simout.h"

static const char *const axes = "xyz";

/* The first point of the frame grid xyz_from + k dt at or after the start (INFINITY if
 * none, or dt = 0), by the same expression that places every later frame, so that a
 * continued run's frames lie on the uninterrupted run's; *k gets its index. */
static double grid_start(const scn_scenario *s, double dt, double *k_out)
{
    *k_out = 0.0;
    if (!(dt > 0))
        return INFINITY;
    const double from = s->out.xyz_from;
    double k = fmax(0.0, ceil((s->time - from) / dt));
    while (k > 0.0 && from + dt * (k - 1.0) >= s->time)
        k -= 1.0;
    while (from + dt * k < s->time)
        k += 1.0;
    *k_out = k;
    return from + dt * k <= s->t_end ? from + dt * k : INFINITY;
}

/* The next point of that grid after index *k (advanced), INFINITY past t_end. */
static double grid_next(const scn_scenario *s, double dt, double *k)
{
    *k += 1.0;
    double t = s->out.xyz_from + dt * *k;
    return t > s->t_end ? INFINITY : t;
}

/* Give up the run's outputs: the open streams closed and their temporaries removed, the
 * staging folder with everything in it removed (the output folder keeps what it had). */
static void abort_all(sim_output *o)
{
    if (o->h5) {
        char ignored[APP_ERR_LEN];
        h5md_close(&o->h5, 0, ignored);
    }
    if (o->have_xyz) {
        app_atomic_abort(&o->xyz);
        app_atomic_abort(&o->frames);
        o->have_xyz = 0;
    }
    simout_stage_discard(o->dir);
    o->dir = NULL;
}

int simout_open(sim_output *o, const scn_scenario *s, const char *prog, char *err)
{
    memset(o, 0, sizeof *o);
    o->s = s;
    o->prog = prog;
    o->next_frame = grid_start(s, s->out.xyz_every, &o->frame_k);
    o->first_frame = s->out.xyz_from + s->out.xyz_every * o->frame_k;
    o->next_h5 = grid_start(s, s->out.h5md_every, &o->h5_k);
    if (simout_stage_open(s->out.dir, &o->dir, err))
        return -1;
    if (s->out.n_snap) {
        char *d = app_path_join(o->dir, "snapshots");
        int r = d ? app_mkdir_p(d, err) : -1;
        free(d);
        if (r) {
            abort_all(o);
            return -1;
        }
    }
    if (s->out.xyz_every > 0) {
        char *p = app_path_join(o->dir, "trajectory.xyz");
        char *q = app_path_join(o->dir, "frames.dat");
        int r = (!p || !q) ? -1 : app_atomic_open(&o->xyz, p, err);
        if (!r) {
            r = app_atomic_open(&o->frames, q, err);
            if (r)
                app_atomic_abort(&o->xyz);
        }
        free(p);
        free(q);
        if (r) {
            abort_all(o);
            return -1;
        }
        o->have_xyz = 1;
        double nframes = (s->t_end - s->time) / s->out.xyz_every + 1;
        o->gif_stride = nframes > 300 ? (size_t)ceil(nframes / 300) : 1;
    }
    if (s->out.h5md_every > 0) {
        char *p = app_path_join(o->dir, "trajectory.h5");
        int r = p ? h5md_open(&o->h5, p, s, s->n, prog, err) : -1;
        if (!p)
            app_errf(err, "out of memory");
        free(p);
        if (r) {
            abort_all(o);
            return -1;
        }
    }
    return 0;
}

double simout_next_time(const sim_output *o, double t)
{
    double next = o->s->t_end;
    if (o->next_snap < o->s->out.n_snap)
        next = fmin(next, o->s->out.snap[o->next_snap]);
    next = fmin(next, fmin(o->next_frame, o->next_h5));
    return next > t ? next : fmin(o->s->t_end, nextafter(t, INFINITY));
}

static int write_snapshot(const sim_output *o, const rc_sim *sim, size_t k, char *err)
{
    const scn_scenario *s = o->s;
    char name[64];
    snprintf(name, sizeof name, "snapshots/snap-%04zu.csv", k);
    char *path = app_path_join(o->dir, name);
    app_atomic a;
    if (!path || app_atomic_open(&a, path, err)) {
        free(path);
        return -1;
    }
    free(path);
    double k2 = isinf(s->c) ? 0.0 : 1.0 / (s->c * s->c);
    /* the header is the first line (no comment before it: csv.DictReader, pandas and
     * numpy.genfromtxt(names=True) take the first line for the names); the time is the
     * t column */
    fprintf(a.f, "ball,t");
    for (int d = 0; d < s->dim; d++)
        fprintf(a.f, ",%c", axes[d]);
    for (int d = 0; d < s->dim; d++)
        fprintf(a.f, ",p%c", axes[d]);
    for (int d = 0; d < s->dim; d++)
        fprintf(a.f, ",v%c", axes[d]);
    fprintf(a.f, ",m,r,tau,gamma");
    int periodic = 0; /* periodic axes: each axis's wrap count, x + image L unwrapped */
    for (int d = 0; d < s->dim; d++)
        periodic |= s->boundary[d] == RC_SIM_PERIODIC;
    for (int d = 0; periodic && d < s->dim; d++)
        fprintf(a.f, ",image_%c", axes[d]);
    fprintf(a.f, "\n");
    size_t n = rc_sim_count(sim);
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball b;
        rc_sim_get_ball(sim, i, &b);
        rc_vec3 v = rc_velocity(b.m, b.p, k2);
        fprintf(a.f, "%zu,%.17g", i, rc_sim_time(sim));
        for (int d = 0; d < s->dim; d++)
            fprintf(a.f, ",%.17g", rc_v3_get(b.x, d));
        for (int d = 0; d < s->dim; d++)
            fprintf(a.f, ",%.17g", rc_v3_get(b.p, d));
        for (int d = 0; d < s->dim; d++)
            fprintf(a.f, ",%.17g", rc_v3_get(v, d));
        fprintf(a.f, ",%.17g,%.17g,%.17g,%.17g", b.m, b.r, b.tau, rc_gamma(b.m, b.p, k2));
        for (int d = 0; periodic && d < s->dim; d++)
            fprintf(a.f, ",%d", (int)b.image[d]);
        fprintf(a.f, "\n");
    }
    return app_atomic_commit(&a, err);
}

static void write_frame(sim_output *o, const rc_sim *sim)
{
    const scn_scenario *s = o->s;
    size_t n = rc_sim_count(sim);
    double k2 = isinf(s->c) ? 0.0 : 1.0 / (s->c * s->c);
    double Lz = s->dim == 3 ? s->box.z : 0.0;
    /* column names as ASE's extxyz reader maps them: momenta and masses become
     * get_momenta() and get_masses(), so get_velocities() = momenta / masses is v; masses
     * is the relativistic mass M = gamma m (p = M v), rest_mass is m; velo is v for OVITO.
     * ASE applies no units: the numbers are relcol's, in the units of c. */
    fprintf(o->xyz.f, "%zu\nLattice=\"%.17g 0 0 0 %.17g 0 0 0 %.17g\" Origin=\"0 0 0\" "
                      "Properties=species:S:1:pos:R:3:velo:R:3:momenta:R:3:masses:R:1:"
                      "rest_mass:R:1:radius:R:1:gamma:R:1 Time=%.17g pbc=\"%c %c %c\"\n",
            n, s->box.x, s->box.y, Lz, rc_sim_time(sim),
            s->boundary[0] == RC_SIM_PERIODIC ? 'T' : 'F',
            s->boundary[1] == RC_SIM_PERIODIC ? 'T' : 'F',
            s->dim == 3 && s->boundary[2] == RC_SIM_PERIODIC ? 'T' : 'F');
    int in_gif = o->frame_no % o->gif_stride == 0;
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball b;
        rc_sim_get_ball(sim, i, &b);
        rc_vec3 v = rc_velocity(b.m, b.p, k2);
        const double g = rc_gamma(b.m, b.p, k2);
        /* species X: ASE's (and OVITO's) placeholder for a particle that is no element
         * (atomic number 0), where B read as boron; %.17g reads back to the same double */
        fprintf(o->xyz.f,
                "X %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
                b.x.x, b.x.y, b.x.z, v.x, v.y, v.z, b.p.x, b.p.y, b.p.z, g * b.m, b.m, b.r, g);
        /* figure data: ball, x, y, radius, contracted semi-axis along v, angle of v */
        if (in_gif) {
            fprintf(o->frames.f, "%zu %.8g %.8g %.8g %.8g %.8g\n", i, b.x.x, b.x.y, b.r, b.r / g,
                    atan2(v.y, v.x) * 180 / M_PI);
        }
    }
    if (in_gif) {
        fprintf(o->frames.f, "\n\n");
        o->gif_frames++;
    }
    o->frame_no++;
}

int simout_at(sim_output *o, const rc_sim *sim, char *err)
{
    double t = rc_sim_time(sim);
    const scn_scenario *s = o->s;
    if (s->gravity && !o->prof && !(o->prof = calloc(1, sizeof *o->prof))) {
        app_errf(err, "out of memory");
        o->failed = 1;
        return -1;
    }
    if (o->prof) /* (a field: its profiles at every output time) */
        profiles_sample(o->prof, s, sim);
    if (!o->have_d0) {
        rc_sim_diagnostics(sim, &o->d0);
        o->have_d0 = 1;
        double h, w;
        o->fe0 = rc_sim_field_energy(sim, &h, &w) == RC_OK ? h - w : NAN;
    }
    while (o->next_snap < s->out.n_snap && s->out.snap[o->next_snap] <= t) {
        if (write_snapshot(o, sim, o->next_snap, err)) {
            o->failed = 1;
            return -1;
        }
        o->next_snap++;
    }
    if (o->have_xyz && o->next_frame <= t) {
        write_frame(o, sim);
        o->next_frame = grid_next(s, s->out.xyz_every, &o->frame_k);
    }
    if (o->h5 && o->next_h5 <= t) {
        if (h5md_frame(o->h5, sim, (long long)o->h5_k, err)) {
            o->failed = 1;
            return -1;
        }
        o->next_h5 = grid_next(s, s->out.h5md_every, &o->h5_k);
    }
    return 0;
}

/* final.json and final.ckpt (scn_save): continuing from them changes no bit of the run */
static int write_final(const sim_output *o, const rc_sim *sim, int interrupted, char *err)
{
    const scn_scenario *s = o->s;
    /* interrupted: continue to the same end; finished: continue for as long again */
    const double t = rc_sim_time(sim), t_end = interrupted ? s->t_end : t + (s->t_end - s->time);
    /* the continuation writes into a folder of its own (scn_next_dir) */
    scn_scenario next = *s;
    char *next_dir = scn_next_dir(s->out.dir);
    if (!next_dir) {
        app_errf(err, "out of memory");
        return -1;
    }
    next.out.dir = next_dir;
    int r = scn_save(o->dir, SIMOUT_FINAL, &next, sim, t_end, err);
    free(next_dir);
    return r;
}

/* summary.json: the run's results for programs (what summary.txt says to a person), numbers
 * in round-trip precision: %.17g, raw (cJSON's own printer takes its 15-digit form whenever
 * that reads back within an epsilon of the value, not to the bit: 0.1 + 0.2 would be
 * printed 0.3); counts and impulses are this run's, from its start time to t. */
static cJSON *num(double x)
{
    char b[32];
    snprintf(b, sizeof b, "%.17g", x);
    /* (JSON has no infinity or NaN: c = inf as in a scenario, an undefined ratio as null) */
    return isinf(x) && x > 0 ? cJSON_CreateString("inf")
           : isfinite(x)     ? cJSON_CreateRaw(b)
                             : cJSON_CreateNull();
}

static void add(cJSON *o, const char *key, double x) { cJSON_AddItemToObject(o, key, num(x)); }

static int write_summary_json(const sim_output *o, const rc_sim *sim, const rc_sim_diag *d,
                              double dE, double dPrel, double wall, int interrupted, char *err)
{
    const scn_scenario *s = o->s;
    const rc_sim_diag *d0 = &o->d0;
    static const char *const ev[RC_SIM_EV_NKINDS] = {"ball", "wall", "group", "cell", "stale", "tc"};
    static const char *const walls[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};
    cJSON *j = cJSON_CreateObject(), *x;
    if (!j)
        goto nomem;
    add(j, "relcol", 1);
    cJSON_AddStringToObject(j, "program", o->prog);
    cJSON_AddBoolToObject(j, "interrupted", interrupted);
    add(j, "dim", s->dim);
    add(j, "n", (double)rc_sim_count(sim));
    cJSON_AddItemToObject(j, "box", x = cJSON_CreateArray());
    for (int k = 0; x && k < s->dim; k++)
        cJSON_AddItemToArray(x, num(rc_v3_get(s->box, k)));
    add(j, "c", s->c);
    cJSON_AddStringToObject(j, "law", s->law->name);
    cJSON_AddStringToObject(j, "contact_frame", s->frame->name);
    cJSON_AddItemToObject(j, "restitution", x = cJSON_CreateObject());
    add(x, "ball", s->eps_ball);
    add(x, "wall", s->eps_wall);
    add(j, "tc", s->t_c);
    add(j, "t_start", s->time);
    add(j, "t", rc_sim_time(sim));
    /* collisions: events resolved alone (ball, wall), groups resolved together, and the
     * contacts of all of them */
    cJSON_AddItemToObject(j, "collisions", x = cJSON_CreateObject());
    for (int k = RC_SIM_EV_BALL; k <= RC_SIM_EV_MULTI; k++)
        add(x, ev[k], (double)(d->events[k] - d0->events[k]));
    add(x, "contacts", (double)(d->collisions - d0->collisions));
    add(x, "largest_group", (double)d->max_group);
    add(x, "group_fallbacks", (double)(d->group_fallbacks - d0->group_fallbacks));
    cJSON_AddItemToObject(j, "overlaps_resolved", x = cJSON_CreateObject());
    static const char *const okind[3] = {"ball", "wall", "group"};
    for (int k = 0; k < 3; k++)
        add(x, okind[k], (double)(d->overlaps_by_kind[k] - d0->overlaps_by_kind[k]));
    add(x, "total", (double)(d->overlaps - d0->overlaps));
    /* per_ball frames (covariant): contacts with the incoming piece of a glued tube (in
     * overlaps_resolved too), kinks put at the ball's previous one, and tube conflicts
     * resolved by undoing a collision and solving the two contacts together -- not by
     * the policy, so not in its total (relcol/sim.h) */
    add(x, "tube_conflicts", (double)(d->tube_conflicts - d0->tube_conflicts));
    add(x, "order_conflicts", (double)(d->order_conflicts - d0->order_conflicts));
    add(x, "rollbacks", (double)(d->rollbacks - d0->rollbacks));
    /* (relative; null without energy at the start, whose change is then absolute) */
    add(j, "energy_error", d0->energy > 0.0 ? dE : NAN);
    add(j, "energy_change", d->energy - d0->energy);
    add(j, "momentum_error", dPrel);
    add(j, "energy", d->energy);
    add(j, "kinetic_energy", d->kinetic);
    add(j, "heat", d->heat - d0->heat);
    add(j, "rest_mass_total", d->rest_mass);
    add(j, "rest_mass_start", d0->rest_mass);
    cJSON_AddItemToObject(j, "wall_impulse", x = cJSON_CreateObject());
    for (int w = 0; w < 2 * s->dim; w++)
        add(x, walls[w], d->wall_impulse_by_wall[w] - d0->wall_impulse_by_wall[w]);
    /* the energy each wall took from the balls (a thermal wall's heat; < 0: it heated
     * them) and, for the thermal ones, their temperature */
    cJSON_AddItemToObject(j, "wall_heat", x = cJSON_CreateObject());
    for (int w = 0; w < 2 * s->dim; w++)
        add(x, walls[w], d->wall_heat_by_wall[w] - d0->wall_heat_by_wall[w]);
    cJSON_AddItemToObject(j, "wall_kT", x = cJSON_CreateObject());
    for (int w = 0; x && w < 2 * s->dim; w++)
        if (s->wall_rule[w] && s->wall_rule[w]->temperature)
            add(x, walls[w], s->wall_kT[w]);
    add(j, "wall_shared", (double)(d->wall_shared - d0->wall_shared));
    add(j, "pinned", (double)(d->pinned - d0->pinned));
    add(j, "cell_crossings", (double)(d->events[RC_SIM_EV_CELL] - d0->events[RC_SIM_EV_CELL]));
    cJSON_AddItemToObject(j, "events", x = cJSON_CreateObject());
    for (int k = 0; k < RC_SIM_EV_NKINDS; k++)
        add(x, ev[k], (double)(d->events[k] - d0->events[k]));
    /* where the run stands against the rigid-ball model's regime (relcol/validity.h): the
     * whole run since its balls were set, carried through checkpoints */
    rc_validity v;
    if (rc_sim_validity(sim, &v) == RC_OK) {
        cJSON_AddItemToObject(j, "model", x = cJSON_CreateObject());
        cJSON_AddStringToObject(x, "verdict", v.verdict_name);
        add(x, "threshold_p_model", v.threshold);
        cJSON_AddBoolToObject(x, "covariant", v.covariant);
        add(x, "p_model", v.p_model);
        add(x, "p_all", v.p_all);
        add(x, "largest_cluster", v.largest_model);
        add(x, "largest_cluster_all", v.largest_all);
        add(x, "nu_r_c", v.nu_r_c);
        add(x, "policy_share", v.policy_share);
        add(x, "policy", (double)v.policy);
        add(x, "collisions", (double)v.collisions);
        add(x, "tube_conflicts", (double)v.tube_conflicts);
        add(x, "order_conflicts", (double)v.order_conflicts);
        add(x, "undone", (double)v.undone);
        add(x, "kink_events", (double)v.kink_events);
        add(x, "kink_pairs", (double)v.kink_pairs);
        add(x, "kink_pairs_model", (double)v.kink_pairs_model);
        add(x, "crossing", (double)v.crossing);
        add(x, "crossing_model", (double)v.crossing_model);
    }
    add(j, "wall_clock_seconds", wall);
    char *text = cJSON_Print(j);
    cJSON_Delete(j);
    if (!text)
        goto nomem;
    char *path = app_path_join(o->dir, "summary.json");
    app_atomic a;
    int r = -1;
    if (path && !app_atomic_open(&a, path, err)) {
        fprintf(a.f, "%s\n", text);
        r = app_atomic_commit(&a, err);
    } else if (!path) {
        app_errf(err, "out of memory");
    }
    free(path);
    free(text);
    return r;
nomem:
    cJSON_Delete(j);
    app_errf(err, "out of memory writing summary.json");
    return -1;
}

static int write_summary(sim_output *o, const rc_sim *sim, double wall, int interrupted,
                         char *err)
{
    const scn_scenario *s = o->s;
    rc_sim_diag d;
    rc_sim_diagnostics(sim, &d);
    const rc_sim_diag *d0 = &o->d0;
    /* relative to the energy at the start; with none (every ball at rest) there is no
     * scale, and the change is given as it is (absolute), never as a NaN */
    const int erel = d0->energy > 0.0;
    double dE = erel ? (d.energy - d0->energy) / d0->energy : d.energy - d0->energy;
    rc_vec3 dP = rc_v3_sub(rc_v3_add(d.momentum, d.wall_impulse),
                           rc_v3_add(d0->momentum, d0->wall_impulse));
    double h, w;
    if (s->gravity && rc_sim_field_energy(sim, &h, &w) == RC_OK) {
        /* a field: its conserved energy (papers/gravity.md section 4), and the momentum
         * across it (the field pushes along it) */
        dE = erel ? (h - w - o->fe0) / fabs(o->fe0) : h - w - o->fe0;
        rc_v3_set(&dP, s->dim - 1, 0.0);
    }
    double pscale = fmax(d.momentum_scale, d0->momentum_scale);
    double dPrel = pscale > 0 ? rc_v3_norm(dP) / pscale : 0.0;
    size_t n = rc_sim_count(sim);
    double tau_min = INFINITY, tau_max = -INFINITY, tau_sum = 0;
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball b;
        rc_sim_get_ball(sim, i, &b);
        tau_min = fmin(tau_min, b.tau);
        tau_max = fmax(tau_max, b.tau);
        tau_sum += b.tau;
    }
    uint64_t coll = d.collisions - d0->collisions;
    snprintf(o->line, sizeof o->line, "%llu collisions, energy error %.2g%s, momentum error %.2g%s",
             (unsigned long long)coll, dE, erel ? "" : " (absolute: no energy at the start)",
             dPrel, interrupted ? " (interrupted)" : "");
    if (!s->out.summary)
        return 0;
    char *path = app_path_join(o->dir, "summary.txt");
    app_atomic a;
    if (!path || app_atomic_open(&a, path, err)) {
        free(path);
        return -1;
    }
    free(path);
    FILE *f = a.f;
    fprintf(f, "relcol-sim summary%s\n", interrupted ? " (interrupted: final.json continues the run)" : "");
    fprintf(f, "balls            %zu (%d-D, box", n, s->dim);
    for (int k = 0; k < s->dim; k++)
        fprintf(f, " %g", rc_v3_get(s->box, k));
    fprintf(f, ")%s%s", *s->generator ? ", generated: " : "", s->generator);
    for (int k = 0, first = 1; k < s->dim; k++)
        if (s->boundary[k] == RC_SIM_PERIODIC) {
            fprintf(f, "%s%c", first ? ", periodic in " : " ", "xyz"[k]);
            first = 0;
        }
    fprintf(f, "\n");
    if (isinf(s->c))
        fprintf(f, "c                inf (classical)\n");
    else
        fprintf(f, "c                %.17g\n", s->c);
    fprintf(f, "law              %s, restitution ball %g wall %g, contact frame %s, t_c %g\n",
            s->law->name, s->eps_ball, s->eps_wall, s->frame->name, s->t_c);
    fprintf(f, "time             %.17g -> %.17g\n", s->time, rc_sim_time(sim));
    fprintf(f, "collisions       %llu (largest simultaneous group %zu)\n", (unsigned long long)coll,
            d.max_group);
    static const char *const kinds[RC_SIM_EV_NKINDS] = {"ball", "wall", "multi", "cell", "stale", "tc"};
    fprintf(f, "events           ");
    for (int k = 0; k < RC_SIM_EV_NKINDS; k++)
        fprintf(f, "%s %llu%s", kinds[k], (unsigned long long)(d.events[k] - d0->events[k]),
                k + 1 < RC_SIM_EV_NKINDS ? ", " : "\n");
    if (d.group_sequential > d0->group_sequential) /* (only a law without a group solver) */
        fprintf(f, "groups one by one %llu (law %s has no group solver: order-dependent)\n",
                (unsigned long long)(d.group_sequential - d0->group_sequential), s->law->name);
    fprintf(f, "energy           kinetic + heat %.17g, %s change %.3g\n", d.energy,
            erel ? "relative" : "absolute (no energy at the start)", dE);
    fprintf(f, "kinetic energy   %.17g (heat made so far %.17g)\n", d.kinetic, d.heat);
    if (!isinf(s->c))
        fprintf(f, "sum E/c^2        %.17g (start %.17g)\n", d.mass_rel, d0->mass_rel);
    fprintf(f, "rest mass        %.17g (start %.17g)\n", d.rest_mass, d0->rest_mass);
    fprintf(f, "momentum         balls + walls, relative change %.3g (wall impulse %.9g %.9g %.9g)\n",
            dPrel, d.wall_impulse.x, d.wall_impulse.y, d.wall_impulse.z);
    if (isnan(d.max_overlap))
        fprintf(f, "overlaps         %llu found (contracted shapes: bounding spheres may overlap)\n",
                (unsigned long long)d.overlaps);
    else
        fprintf(f, "overlaps         %llu found (deepest now %.3g of ri + rj)\n",
                (unsigned long long)d.overlaps, d.max_overlap);
    fprintf(f, "proper time      min %.9g, mean %.9g, max %.9g\n", tau_min, tau_sum / (double)n, tau_max);
    fprintf(f, "wall clock       %.3f s, %.4g collisions/s\n", wall, wall > 0 ? (double)coll / wall : 0.0);
    if (app_atomic_commit(&a, err))
        return -1;
    return write_summary_json(o, sim, &d, dE, dPrel, wall, interrupted, err);
}

/* paths.dat: frames.dat regrouped by ball (one block per ball), for the trajectory lines. */
static int write_paths(const sim_output *o, char *err)
{
    size_t n = o->n_balls, nf = o->gif_frames;
    char *fp = app_path_join(o->dir, "frames.dat"), *pp = app_path_join(o->dir, "paths.dat");
    double *xy = (n && nf && n * nf < 50000000) ? malloc(2 * n * nf * sizeof *xy) : NULL;
    FILE *in = fp ? fopen(fp, "r") : NULL;
    app_atomic a;
    int r = -1;
    if (!fp || !pp || !in || !xy) {
        app_errf(err, "cannot regroup %s into paths.dat (%s)", fp ? fp : "frames.dat",
                 !xy ? "too many balls x frames" : "cannot read it");
        goto done;
    }
    size_t i, f = 0, k = 0;
    double x, y, rr, ra, ang;
    while (fscanf(in, "%zu %lf %lf %lf %lf %lf", &i, &x, &y, &rr, &ra, &ang) == 6) {
        if (i < n && f < nf) {
            xy[2 * (i * nf + f)] = x;
            xy[2 * (i * nf + f) + 1] = y;
        }
        if (++k == n) {
            k = 0;
            f++;
        }
    }
    if (f != nf) {
        app_errf(err, "%s: %zu frames read, %zu written", fp, f, nf);
        goto done;
    }
    if (app_atomic_open(&a, pp, err))
        goto done;
    for (i = 0; i < n; i++) {
        for (f = 0; f < nf; f++)
            fprintf(a.f, "%.8g %.8g\n", xy[2 * (i * nf + f)], xy[2 * (i * nf + f) + 1]);
        fprintf(a.f, "\n\n");
    }
    r = app_atomic_commit(&a, err);
done:
    if (in)
        fclose(in);
    free(xy);
    free(fp);
    free(pp);
    return r;
}

static int write_figures(sim_output *o, char *err)
{
    const scn_scenario *s = o->s;
    if (!s->out.plots || !o->have_xyz)
        return 0;
    char *gp = app_path_join(o->dir, "trajectories.gp");
    app_atomic a;
    if (!gp || app_atomic_open(&a, gp, err)) {
        free(gp);
        return -1;
    }
    free(gp);
    char cbuf[APP_FMT_LEN];
    /* The trajectories and the GIF share their colours: one per ball from the same
     * palette, keyed by ball number (the colour box), and both draw the balls as the
     * shapes the run has, contracted along the velocity at finite c. */
    size_t n = o->n_balls;
    double shift = 0.0; /* ball k's colour value is k + shift */
    const char *cs = isinf(s->c) ? "inf" : app_fmt(s->c, cbuf);
    char shapes[160];
    snprintf(shapes, sizeof shapes, "%s",
             isinf(s->c) ? "c = ∞: no contraction, every ball its rest shape"
                         : "each ball Lorentz-contracted along its velocity (semi-axis r/γ)");
    /* up to 20 balls, a colour of their own each (a step palette: band k of [0, n] in
     * colour k, the dark ten first); more, a continuous ramp */
    static const char *const own[20] = {
        "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
        "#7f7f7f", "#bcbd22", "#17becf", "#aec7e8", "#ffbb78", "#98df8a", "#ff9896",
        "#c5b0d5", "#c49c94", "#f7b6d2", "#c7c7c7", "#dbdb8d", "#9edae5"};
    char palette[1200];
    int pl = 0;
    if (n >= 1 && n <= 20) {
        pl = snprintf(palette, sizeof palette, "set palette defined (");
        for (size_t k = 0; k < n; k++)
            pl += snprintf(palette + pl, sizeof palette - (size_t)pl, "%s%zu '%s', %zu '%s'",
                           k ? ", " : "", k, own[k], k + 1, own[k]);
        pl += snprintf(palette + pl, sizeof palette - (size_t)pl,
                       ")\nset cbrange [0:%zu]\nset cbtics ('0' 0.5", n);
        for (size_t k = 1; k < n; k++)
            pl += snprintf(palette + pl, sizeof palette - (size_t)pl, ", '%zu' %zu.5", k, k);
        snprintf(palette + pl, sizeof palette - (size_t)pl, ")\nset cblabel 'ball number' offset 1,0\n");
        shift = 0.5;
    } else {
        snprintf(palette, sizeof palette,
                 "set palette defined (0 '#1f77b4', 1 '#2ca02c', 2 '#ff7f0e', 3 '#d62728')\n"
                 "set cbrange [-0.5:%zu.5]\nset cblabel 'ball number' offset 1,0\n", n ? n - 1 : 0);
    }
    /* each ball's path: paths.dat holds one block per ball; the last frame's balls over
     * them, filled in their colour */
    fprintf(a.f,
            "# relcol-sim: ball trajectories (x-y%s), one colour per ball (the GIF's); the\n"
            "# balls at the end as their shapes\n"
            "if (!exists(\"outfile\")) outfile = 'trajectories.png'\n"
            "set encoding utf8\n"
            "set terminal pngcairo size 1080,%d enhanced font ',11'\n"
            "set output outfile\nset size ratio -1\nunset key\n"
            "set xrange [0:%.17g]\nset yrange [0:%.17g]\n"
            "set xlabel 'x (the scenario''s length unit)'\nset ylabel 'y'\n"
            "set title \"relcol-sim: %zu balls, t = %g to %g, c = %s, restitution %g%s\\n"
            "{/*0.85 lines: each ball's path;  filled: the balls at t = %g, %s}\"\n"
            "%s"
            "plot for [i=0:%zu] 'paths.dat' index i u 1:2:(i + %g) w l lw 1.6 lc palette, \\\n"
            "     'frames.dat' index %zu u 2:3:(2*$5):(2*$4):6:($1 + %g) w ellipses lc palette "
            "fs transparent solid 0.65 border lc rgb '#202020'\n",
            s->dim == 3 ? " projection" : "", (int)(1000 * s->box.y / s->box.x) + 110, s->box.x,
            s->box.y, n, s->time, s->t_end, cs, s->eps_ball,
            s->dim == 3 ? "\\n3-D run seen along z: x-y projection, z not shown" : "",
            s->t_end, shapes, palette, n ? n - 1 : 0, shift,
            o->gif_frames ? o->gif_frames - 1 : 0, shift);
    if (app_atomic_commit(&a, err))
        return -1;
    int made = 0;
    if (write_paths(o, err) ||
        app_gnuplot_run(o->prog, o->dir, "trajectories.gp", "trajectories.png", &made, err))
        return -1;
    if (!s->out.gif || s->dim != 2)
        return 0;
    char *gg = app_path_join(o->dir, "table.gp");
    if (!gg || app_atomic_open(&a, gg, err)) {
        free(gg);
        return -1;
    }
    free(gg);
    fprintf(a.f,
            "# relcol-sim: animation of the table; each ball drawn as its Lorentz-contracted\n"
            "# ellipse (semi-axis r/gamma along v, r across), coloured by ball number as in\n"
            "# trajectories.png\n"
            "if (!exists(\"outfile\")) outfile = 'table.gif'\n"
            "set encoding utf8\n"
            "# (the GIF terminal has no transparency: fs solid 1 with a border, on white)\n"
            "set terminal gif animate delay 4 size 900,%d background '#ffffff' font ',11'\n"
            "set output outfile\nset size ratio -1\nunset key\n"
            "set xrange [0:%.17g]\nset yrange [0:%.17g]\n"
            "set xlabel 'x (the scenario''s length unit)'\nset ylabel 'y'\n"
            "%s"
            "t0 = %.17g; dt = %.17g\n"
            "do for [i=0:%zu] {\n"
            "  set title sprintf(\"relcol-sim: %zu balls, c = %s    t = %%.3f (the scenario's "
            "time unit)\\n%s\", t0 + i * dt)\n"
            "  plot 'frames.dat' index i u 2:3:(2*$5):(2*$4):6:($1 + %g) w ellipses lc palette "
            "fs solid 1 border lc rgb '#202020'\n"
            "}\n",
            (int)(800 * s->box.y / s->box.x) + 100, s->box.x, s->box.y, palette,
            o->first_frame, s->out.xyz_every * (double)o->gif_stride,
            o->gif_frames ? o->gif_frames - 1 : 0, n, cs, shapes, shift);
    if (app_atomic_commit(&a, err))
        return -1;
    return app_gnuplot_run(o->prog, o->dir, "table.gp", "table.gif", &made, err);
}

int simout_close(sim_output *o, const rc_sim *sim, double wall, int interrupted, char *err)
{
    int r = 0;
    if (!o->have_d0) {
        rc_sim_diagnostics(sim, &o->d0);
        o->have_d0 = 1;
        double h, w;
        o->fe0 = rc_sim_field_energy(sim, &h, &w) == RC_OK ? h - w : NAN;
    }
    if (o->failed)
        goto out;
    o->n_balls = rc_sim_count(sim);
    if (o->have_xyz) {
        if (app_atomic_commit(&o->xyz, err)) {
            app_atomic_abort(&o->frames); /* (its temporary goes too) */
            r = -1;
        } else if (app_atomic_commit(&o->frames, err)) {
            r = -1;
        }
        o->have_xyz = r == 0;
    }
    if (o->h5 && h5md_close(&o->h5, r == 0, err))
        r = -1;
    if (!r)
        r = write_final(o, sim, interrupted, err);
    if (!r)
        r = write_summary(o, sim, wall, interrupted, err);
    if (!r)
        r = write_figures(o, err);
    if (!r && o->prof)
        r = profiles_write(o->prof, o->s, o->prog, o->dir, err);
out:
    free(o->prof);
    o->prof = NULL;
    if (r || o->failed) {
        /* (err already holds the failure's reason) */
        abort_all(o);
        if (!r) {
            app_errf(err, "nothing of this run was kept: the files in %s are the previous "
                     "run's", o->s->out.dir);
        } else {
            const size_t len = strlen(err);
            snprintf(err + len, APP_ERR_LEN - len, "; nothing of this run was kept: the files "
                     "in %s are the previous run's", o->s->out.dir);
        }
        return -1;
    }
    char warn[APP_ERR_LEN];
    r = simout_stage_publish(o->s->out.dir, o->dir, err, warn);
    o->dir = NULL;
    if (!r && warn[0])
        fprintf(stderr, "%s: warning: %s\n", o->prog, warn);
    return r;
}
