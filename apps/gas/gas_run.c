/* gas_run.c — relcol-gas's runs (gas_run.h): the start far from equilibrium, the engine
 * or the exact 1-D gas stepped to each snapshot, and the snapshots' read-out. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "gas_run.h"
#include "juttner.h"

static const char *const prog = GAS_PROG;

const double gas_mix_mass[MAXSPEC] = {1.0, 2.0};
/* A unit vector uniform on the circle / sphere. */
static rc_vec3 random_direction(int dim, rc_rng *r)
{
    if (dim == 2) {
        const double a = 2.0 * M_PI * rc_rng_uniform(r);
        return rc_v3(cos(a), sin(a), 0.0);
    }
    const double z = 2.0 * rc_rng_uniform(r) - 1.0, a = 2.0 * M_PI * rc_rng_uniform(r);
    const double s = sqrt((1.0 - z) * (1.0 + z));
    return rc_v3(s * cos(a), s * sin(a), z);
}


/* 1-D: the common starting gamma whose total energy is the canonical one at kT =
 * theta x the light mass for count[s] particles of species s. */
static double start_gamma_mixture(double theta, const size_t *count)
{
    const double kT = theta * gas_mix_mass[0];
    double e = 0.0, msum = 0.0;
    for (int s = 0; s < MAXSPEC; s++) {
        msum += (double)count[s] * gas_mix_mass[s];
        e += (double)count[s] * gas_mix_mass[s] * jt_mean_gamma(1, kT / gas_mix_mass[s]);
    }
    return e / msum;
}

/* 1-D: the kT (in units of the light mass) whose canonical energy is that of count[s]
 * particles of species s all at gamma0 -- where the gas settles, up to O(1/N): the
 * inverse of start_gamma_mixture, by bisection in log theta (<gamma> rises with theta). */
static double theta_of_energy_1d(const size_t *count, double gamma0)
{
    double lo = log(JT_THETA_MIN), hi = log(JT_THETA_MAX);
    for (int k = 0; k < 200 && hi - lo > 1e-15 * fmax(1.0, fabs(lo)); k++) {
        const double mid = 0.5 * (lo + hi);
        if (start_gamma_mixture(exp(mid), count) < gamma0)
            lo = mid;
        else
            hi = mid;
    }
    return exp(0.5 * (lo + hi));
}

/* Starting gamma: from --v-rms, or the canonical energy at theta_start (1-D: for a
 * mixture, the common gamma whose total energy is the canonical one at kT = theta_start
 * x the light mass, so that the gas settles there up to O(1/N)). */
double gas_start_gamma(const options *o)
{
    if (o->v_given) {
        const double b = o->v_start / o->c;
        return 1.0 / sqrt((1.0 - b) * (1.0 + b));
    }
    if (o->dim != 1)
        return jt_mean_gamma(o->dim, o->theta_start);
    const size_t half[MAXSPEC] = {1, 1}; /* (until the species are drawn) */
    return start_gamma_mixture(o->theta_start, half);
}

/* The engine with the run's start (the same for every call: positions, directions and
 * speeds from the seed). */
int gas_sim_start(const options *o, samples *S, rc_sim **out, char *err)
{
    const size_t n = S->n;
    rc_sim_ball *b = malloc(n * sizeof *b);
    if (!b) {
        app_errf(err, "out of memory");
        return -1;
    }
    rc_sim_gas_def g = {o->dim, n, 0.5, o->packing, 0.0, o->c, 8.0, o->seed};
    rc_vec3 box;
    int st = rc_sim_gas_init(&g, &box, b);
    if (st != RC_OK) {
        app_errf(err, "--packing: cannot place %zu balls at packing %g: %s", n, o->packing,
                 rc_strerror(st));
        free(b);
        return -1;
    }
    S->box = box.x;
    S->boxv = box;
    /* every ball m = 1 (density 8 x r^3), |p| = m c sqrt(gamma0^2 - 1), random direction */
    const double p0 = o->c * sqrt((S->gamma0 - 1.0) * (S->gamma0 + 1.0));
    rc_rng R = {o->seed ^ 0x6a5ULL};
    for (size_t i = 0; i < n; i++) {
        b[i].p = rc_v3_scale(p0, random_direction(o->dim, &R));
        b[i].m = 1.0;
        b[i].image[0] = b[i].image[1] = b[i].image[2] = 0;
        S->spec[i] = 0;
    }
    /* periodic: no wall takes momentum, so the start has none -- pairs of opposite
     * momenta (an odd n: the last three at 120 degrees in the xy plane), every speed
     * still the same */
    for (size_t i = 1; o->periodic && i + (n % 2 ? 2 : 0) < n; i += 2)
        b[i].p = rc_v3_scale(-1.0, b[i - 1].p);
    if (o->periodic && n % 2) {
        const double a = 2.0 * M_PI * rc_rng_uniform(&R);
        for (size_t k = 0; k < 3; k++) {
            const double ak = a + 2.0 * M_PI * (double)k / 3.0;
            b[n - 3 + k].p = rc_v3(p0 * cos(ak), p0 * sin(ak), 0.0);
        }
    }
    rc_sim_def d = rc_sim_def_default();
    d.dim = o->dim;
    d.box = box;
    d.c = o->c;
    d.frame = o->frame;
    d.groups = o->groups;
    if (o->sens_move != 0.0)
        app_sens_move(b, n, o->dim, o->sens_move);
    for (int k = 0; k < 3; k++)
        d.boundary[k] = o->periodic ? RC_SIM_PERIODIC : RC_SIM_WALLS;
    rc_sim *s = NULL;
    st = rc_sim_create(&d, &s);
    if (st == RC_OK)
        st = rc_sim_set_balls(s, n, b, NULL);
    free(b);
    if (st != RC_OK) {
        rc_sim_free(&s);
        app_errf(err, "engine: %s", rc_strerror(st));
        return -1;
    }
    *out = s;
    return 0;
}

/* --readout slice: a slice read is held a further W (its t_final - ts, as bounded now)
 * before it is released, and whether it changed after the read is counted then: W bounds
 * a single contact's reach and a tube conflict's undo, not an undo for an overlap the
 * frame reported (relcol/sim.h), so a snapshot read final can still be off, and the run
 * says how many were (rather than trusting W). Releases the held slices below *held that
 * are due (all: everything), counting their late changes. */
static int release_slices(rc_sim *s, samples *S, const uint32_t *sid, size_t *held,
                          size_t next, int all)
{
    while (*held < next) {
        rc_sim_slice_info in;
        const int r = rc_sim_slice_ready(s, sid[*held], &in);
        if (r < 0)
            return r;
        if (!all && !(rc_sim_time(s) >= in.t_final + (in.t_final - in.ts)))
            break;
        S->slices_late += in.late > 0;
        rc_sim_slice_release(s, sid[*held]);
        (*held)++;
    }
    return RC_OK;
}

/* --readout slice: read every slice asked for (snapshots up to last) that is final, in
 * order (snapshot j's u into row j - 1); *next: the first not read yet. Read slices stay
 * held (release_slices). */
static int read_slices(rc_sim *s, samples *S, const uint32_t *sid, size_t *next, size_t last,
                       double inv_c2)
{
    const size_t n = S->n;
    while (*next <= last) {
        const int r = rc_sim_slice_ready(s, sid[*next], NULL);
        if (r != 1)
            return r;
        for (size_t i = 0; i < n; i++) {
            rc_sim_ball q;
            const int st = rc_sim_slice_get(s, sid[*next], i, &q);
            if (st != RC_OK)
                return st;
            S->u[(*next - 1) * n + i] = rc_v3_norm2(q.p) * inv_c2 / (q.m * q.m);
        }
        S->slices_read++;
        (*next)++;
    }
    return RC_OK;
}

int gas_run_sim(const options *o, samples *S, char *err)
{
    const size_t n = S->n;
    rc_sim *s = NULL;
    if (gas_sim_start(o, S, &s, err) != 0)
        return -1;
    int st = RC_OK;
    const double inv_c2 = 1.0 / (o->c * o->c);
    /* per_ball frames: the snapshots' read-out (every other frame reads each ball's latest
     * segment, the same as the others there); slice: snapshot j >= 1 from the delayed
     * slice asked for before the engine reaches its time, read once final (the energy
     * check still sums the latest segments, the conserved ones: a slice's sum is not) */
    const int readout = o->frame->per_ball ? o->readout : READ_LATEST;
    uint32_t *sid = readout == READ_SLICE ? malloc((S->ns + 1) * sizeof *sid) : NULL;
    size_t next = 1, held = 1;
    if (readout == READ_SLICE && !sid) {
        rc_sim_free(&s);
        app_errf(err, "out of memory");
        return -1;
    }
    double e0 = 0.0;
    app_progress bar;
    app_progress_init(&bar, prog, S->ns);
    for (size_t j = 0; j <= S->ns && st == RC_OK; j++) {
        const double t = o->t_equil + o->t_sample * (double)j / (double)S->ns;
        if (sid && j > 0 && (st = rc_sim_slice_request(s, t, &sid[j])) == RC_EINVAL) {
            /* (t >= the engine's time here: the one other reason, relcol/sim.h) */
            app_errf(err, "--readout slice: at t = %.9g a ball had more kinks ahead of the "
                          "engine than it records, so its line at the snapshot is not known "
                          "(a dense hot gas): use --readout latest or now", t);
            rc_sim_free(&s);
            free(sid);
            return -1;
        }
        if (st == RC_OK)
            st = rc_sim_advance(s, t, 0);
        if (st == RC_OK && j % (S->ns / NBLOCK) == 0)
            st = pb_mark(s, o->periodic, S->boxv, &S->pres);
        double e = 0.0;
        for (size_t i = 0; i < n && st == RC_OK; i++) {
            /* each ball's latest segment: in the covariant frame every change at its
             * contact event's table time, the read-out papers/finite-density.md's
             * numbers are made with (rc_sim_get_ball applies a kink after its contact
             * event at the kink but one before it at the contact event, which selects
             * balls by the sign of their kink's lead: papers/covariant-frame.md section 1);
             * in every other frame the same as rc_sim_get_ball */
            rc_sim_ball q;
            st = rc_sim_get_ball_latest(s, i, &q);
            const double u = rc_v3_norm2(q.p) * inv_c2 / (q.m * q.m);
            e += q.m * sqrt(1.0 + u);
            S->mass_drift = fmax(S->mass_drift, fabs(q.m - 1.0));
            if (j > 0 && readout == READ_LATEST)
                S->u[(j - 1) * n + i] = u;
            if (j > 0 && readout == READ_NOW && st == RC_OK &&
                (st = rc_sim_get_ball(s, i, &q)) == RC_OK)
                S->u[(j - 1) * n + i] = rc_v3_norm2(q.p) * inv_c2 / (q.m * q.m);
        }
        if (sid && st == RC_OK && (st = read_slices(s, S, sid, &next, j, inv_c2)) > 0)
            st = RC_OK;
        if (sid && st == RC_OK)
            st = release_slices(s, S, sid, &held, next, 0);
        if (j == 0) /* the energy at the end of the equilibration (exact since t = 0) */
            e0 = e;
        rc_sim_diag dj;
        if (st == RC_OK && (st = rc_sim_diagnostics(s, &dj)) == RC_OK)
            S->coll[j] = dj.collisions;
        S->energy_drift = fmax(S->energy_drift, fabs(e - e0) / e0);
        app_progress_update(&bar, j);
    }
    app_progress_done(&bar);
    rc_sim_diag dg;
    if (st == RC_OK && (st = rc_sim_diagnostics(s, &dg)) == RC_OK) {
        S->events = dg.collisions;
        S->overlaps = dg.overlaps;
        S->end = dg;
        S->have_end = 1;
        app_validity_note(s); /* (the run as measured: the slices' further W after) */
        /* the energy at t = 0 is n m gamma0 exactly: compare with the end too */
        const double e_start = (double)n * S->gamma0;
        S->energy_drift = fmax(S->energy_drift, fabs(dg.mass_rel - e_start) / e_start);
    }
    /* the slices still held: the engine run on until each is final (past the sample: the
     * counts above are the sample's) */
    while (sid && st == RC_OK && next <= S->ns) {
        rc_sim_slice_info in;
        const int r = rc_sim_slice_ready(s, sid[next], &in);
        st = r < 0 ? r : r == 0 ? rc_sim_advance(s, in.t_final, 0) : RC_OK;
        if (st == RC_OK && (st = read_slices(s, S, sid, &next, S->ns, inv_c2)) > 0)
            st = RC_OK;
    }
    /* the last ones held their further W too, then every late change counted */
    if (sid && st == RC_OK && held <= S->ns) {
        rc_sim_slice_info in;
        const int r = rc_sim_slice_ready(s, sid[S->ns], &in);
        st = r < 0 ? r : rc_sim_advance(s, in.t_final + (in.t_final - in.ts), 0);
    }
    if (sid && st == RC_OK)
        st = release_slices(s, S, sid, &held, next, 1);
    free(sid);
    rc_sim_free(&s);
    if (st != RC_OK) {
        app_errf(err, "engine: %s", rc_strerror(st));
        return -1;
    }
    return 0;
}

/* 1-D: n points on [0, n], one per unit cell in its middle 80 %, species at random, every
 * |v| equal (gamma0) with a random sign (the set-up of tests/gas/, Cubero et al. 2007): the
 * gas at t = 0 (the same for every call), the species in S->spec, S->gamma0 and
 * S->theta_energy set, the start's energy in *e0. */
int gas_1d_start(const options *o, samples *S, rc_gas1d **out, double *e0, char *err)
{
    const size_t n = S->n;
    double *x = malloc(n * sizeof *x), *m = malloc(n * sizeof *m), *p = malloc(n * sizeof *p);
    int rc = -1;
    if (!x || !m || !p) {
        app_errf(err, "out of memory");
        goto out;
    }
    rc_rng R = {o->seed};
    size_t count[MAXSPEC] = {0, 0};
    for (size_t i = 0; i < n; i++) {
        x[i] = (double)i + 0.1 + 0.8 * rc_rng_uniform(&R);
        S->spec[i] = rc_rng_uniform(&R) < 0.5;
        count[S->spec[i]]++;
        m[i] = gas_mix_mass[S->spec[i]];
        p[i] = rc_rng_uniform(&R) < 0.5 ? -1.0 : 1.0; /* the direction; the size below */
    }
    /* the species are drawn at random, so the start's energy is that of the counts drawn,
     * not of a 50/50 mixture: the gas then settles at theta_start */
    if (!o->v_given)
        S->gamma0 = start_gamma_mixture(o->theta_start, count);
    S->theta_energy = theta_of_energy_1d(count, S->gamma0);
    const double beta = sqrt((S->gamma0 - 1.0) * (S->gamma0 + 1.0)) / S->gamma0;
    *e0 = 0.0;
    for (size_t i = 0; i < n; i++) {
        p[i] *= m[i] * S->gamma0 * beta * o->c; /* p = m gamma v */
        *e0 += m[i] * S->gamma0;
    }
    rc_gas1d_def d = rc_gas1d_def_default();
    d.n = n;
    d.length = (double)n;
    d.c = o->c;
    d.x = x;
    d.m = m;
    d.p = p;
    int st = rc_gas1d_create(&d, out, NULL);
    S->box = (double)n;
    if (st != RC_OK)
        app_errf(err, "1-D gas: %s", rc_strerror(st));
    else
        rc = 0;
out:
    free(x), free(m), free(p);
    return rc;
}

int gas_run_1d(const options *o, samples *S, char *err)
{
    const size_t n = S->n;
    double *m = malloc(n * sizeof *m), *p = malloc(n * sizeof *p);
    int rc = -1;
    rc_gas1d *g = NULL;
    if (!m || !p) {
        app_errf(err, "out of memory");
        goto out;
    }
    double e0;
    if (gas_1d_start(o, S, &g, &e0, err) != 0)
        goto out;
    const double inv_c2 = rc_inv_c2_of(o->c);
    rc_gas1d_stats gs;
    int st = rc_gas1d_advance(g, o->t_equil, 0);
    if (st == RC_OK && (st = rc_gas1d_stats_get(g, &gs)) == RC_OK)
        S->coll[0] = gs.pair_events;
    app_progress bar;
    app_progress_init(&bar, prog, S->ns);
    for (size_t j = 1; j <= S->ns && st == RC_OK; j++) {
        st = rc_gas1d_advance(g, o->t_equil + o->t_sample * (double)j / (double)S->ns, 0);
        if (st == RC_OK)
            st = rc_gas1d_get(g, NULL, m, p);
        double e = 0.0;
        for (size_t i = 0; i < n && st == RC_OK; i++) {
            const double u = p[i] * p[i] * inv_c2 / (m[i] * m[i]);
            S->u[(j - 1) * n + i] = u;
            e += m[i] * sqrt(1.0 + u);
            S->mass_drift = fmax(S->mass_drift, fabs(m[i] - gas_mix_mass[S->spec[i]]) /
                                                    gas_mix_mass[S->spec[i]]);
        }
        S->energy_drift = fmax(S->energy_drift, fabs(e - e0) / e0);
        if (st == RC_OK && (st = rc_gas1d_stats_get(g, &gs)) == RC_OK)
            S->coll[j] = gs.pair_events;
        app_progress_update(&bar, j);
    }
    app_progress_done(&bar);
    if (st == RC_OK && (st = rc_gas1d_stats_get(g, &gs)) == RC_OK)
        S->events = gs.pair_events + gs.wall_events[0] + gs.wall_events[1];
    if (st != RC_OK)
        app_errf(err, "1-D gas: %s", rc_strerror(st));
    else
        rc = 0;
out:
    rc_gas1d_free(&g);
    free(m), free(p);
    return rc;
}
