/* relcol_web.c — the page's glue to librelcol in WebAssembly: a "world" is a scenario (read
 * by relcol-sim's own reader, so built-ins and dropped files are the same JSON) and its
 * engine; the page asks it for the balls at the display time and draws what it gets. The
 * physics is the library's: rc_sim_advance brings every ball to the asked time (free
 * flight between events included), rc_sim_set_c changes c keeping momenta, shapes come
 * from rc_toi_shape_of, the tables of laws and frames from rc_laws and rc_toi_frames.
 * App code: it owns the read-outs (errors relative to a reference, histograms). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <emscripten/emscripten.h>

#include "relcol/relcol.h"
#include "scenario.h"

#define WEB_EXPORT EMSCRIPTEN_KEEPALIVE

/* values per ball in web_balls' array */
enum { WB_X, WB_Y, WB_PX, WB_PY, WB_R, WB_M, WB_TAU, WB_GAMMA, WB_SPEED, WB_A, WB_B,
       WB_ANGLE, WB_N };

/* values in web_diag's array */
enum { WD_TIME, WD_COLL, WD_ENERGY, WD_EERR, WD_PERR, WD_OVERLAPS, WD_OVSHARE, WD_MEANG,
       WD_VMAX, WD_C, WD_KINETIC, WD_HEAT, WD_GROUPSEQ, WD_MAXGROUP, WD_N, WD_BOXX, WD_BOXY,
       WD_PCLASS, WD_EPS, WD_FRAME, WD_LAW, WD_CONTRACTED, WD_GROUPS, WD_VERDICT, WD_PMODEL,
       WD_FIELD, WD_G, WD_COUPLING, WD_COUNT };

/* web_profile's array: WP_COLS columns of nb slabs, then WP_TAIL numbers (app.js, PROF) */
enum { WP_MAXBINS = 64, WP_COLS = 5, WP_TAIL = 6 };

typedef struct web_world {
    scn_scenario sc; /* as read: reset starts from it */
    rc_sim *s;
    double c; /* the engine's speed of light now (the scenario's, or the last web_set_c) */
    /* references of the conservation read-outs, taken at the start and at each change of
     * the model (c, eps, frame, law): the kinetic energy is a function of c */
    double e0, escale;
    rc_vec3 pw0; /* balls + walls momentum */
    double pscale;
    /* counters of engines replaced by a change of the model (diagnostics restart) */
    uint64_t coll_base, ov_base, seq_base;
    double *balls;
    double diag[WD_COUNT];
    double hist[4 * 256 + 4];
    /* the frame the scenario had before a field switched it to a one-instant sphere (the
     * engine defines no contracted or per-ball frame in a field), given back when it goes */
    const rc_toi_frame *frame_nofield;
    double prof[WP_MAXBINS * WP_COLS + WP_TAIL];
} web_world;

static char web_err[1024];

WEB_EXPORT const char *web_error(void) { return web_err; }

static double inv_c2_of(double c) { return isinf(c) ? 0.0 : 1.0 / (c * c); }

/* The energy the run conserves: without a field the balls' energy; in a field the
 * coupling's H summed over the balls minus what contacts booked (rc_sim_field_energy:
 * E + m g z for newtonian, (1 + g z/c^2) E for equivalence, rest energy subtracted), and
 * its scale for the relative error. */
static double conserved(const web_world *w, const rc_sim_diag *d, double *scale)
{
    double h = 0.0, booked = 0.0;
    if (w->sc.gravity && rc_sim_field_energy(w->s, &h, &booked) == RC_OK) {
        *scale = h != 0.0 ? fabs(h) : 1.0;
        return h - booked;
    }
    *scale = d->energy != 0.0 ? fabs(d->energy) : 1.0;
    return d->energy;
}

static void take_reference(web_world *w)
{
    rc_sim_diag d;
    rc_sim_diagnostics(w->s, &d);
    w->e0 = conserved(w, &d, &w->escale);
    w->pw0 = rc_v3_add(d.momentum, d.wall_impulse);
    w->pscale = d.momentum_scale > 0.0 ? d.momentum_scale : 1.0;
}

static void keep_counts(web_world *w)
{
    rc_sim_diag d;
    rc_sim_diagnostics(w->s, &d);
    w->coll_base += d.collisions;
    w->ov_base += d.overlaps;
    w->seq_base += d.group_sequential;
}

/* a new engine from the scenario's balls (the start, or a reset) */
static int start(web_world *w)
{
    rc_sim_free(&w->s);
    w->coll_base = w->ov_base = w->seq_base = 0;
    rc_sim_def def = scn_sim_def(&w->sc);
    w->c = def.c;
    size_t bad = 0;
    int st = rc_sim_create(&def, &w->s);
    if (st == RC_OK)
        st = rc_sim_set_time(w->s, w->sc.time);
    if (st == RC_OK)
        st = rc_sim_set_balls(w->s, w->sc.n, w->sc.balls, &bad);
    if (st != RC_OK) {
        snprintf(web_err, sizeof web_err, "cannot start the engine: %s (ball %zu)",
                 rc_strerror(st), bad);
        rc_sim_free(&w->s);
        return st;
    }
    take_reference(w);
    return RC_OK;
}

/* A world from a scenario's JSON text (builtin = 0) or a built-in's name (1); NULL with
 * web_error() saying why. */
WEB_EXPORT web_world *web_create(const char *text, int builtin)
{
    web_world *w = calloc(1, sizeof *w);
    if (!w) {
        snprintf(web_err, sizeof web_err, "out of memory");
        return NULL;
    }
    char err[1024] = "";
    int r = builtin ? scn_builtin(text, &w->sc, err) : scn_parse(text, "dropped file", &w->sc, err);
    if (r != 0) {
        snprintf(web_err, sizeof web_err, "%s", err);
        scn_free(&w->sc);
        free(w);
        return NULL;
    }
    if (w->sc.dim != 2) {
        snprintf(web_err, sizeof web_err, "the page shows 2-D tables (this scenario has dim %d)",
                 w->sc.dim);
        scn_free(&w->sc);
        free(w);
        return NULL;
    }
    w->balls = malloc((w->sc.n ? w->sc.n : 1) * WB_N * sizeof *w->balls);
    if (!w->balls || start(w) != RC_OK) {
        if (!w->balls)
            snprintf(web_err, sizeof web_err, "out of memory");
        free(w->balls);
        scn_free(&w->sc);
        free(w);
        return NULL;
    }
    return w;
}

WEB_EXPORT void web_free(web_world *w)
{
    if (!w)
        return;
    rc_sim_free(&w->s);
    free(w->balls);
    scn_free(&w->sc);
    free(w);
}

WEB_EXPORT int web_reset(web_world *w) { return start(w); }

/* The speed of light, momenta and rest masses kept (rc_sim_set_c). */
WEB_EXPORT int web_set_c(web_world *w, double c)
{
    int st = rc_sim_set_c(w->s, c);
    if (st != RC_OK) {
        snprintf(web_err, sizeof web_err, "c = %g: %s", c, rc_strerror(st));
        return st;
    }
    w->c = c;
    take_reference(w);
    return RC_OK;
}

/* The run goes on from its state now in a new engine of definition def (a restart of the
 * synced state); on failure the old engine runs on and web_error() says why (what names
 * the change). */
static int rebuild(web_world *w, rc_sim_def *def, const char *what)
{
    int st = rc_sim_sync(w->s);
    size_t n = rc_sim_count(w->s), bad = 0;
    rc_sim_ball *b = malloc((n ? n : 1) * sizeof *b);
    if (st != RC_OK || !b) {
        free(b);
        snprintf(web_err, sizeof web_err, "out of memory");
        return RC_ENOMEM;
    }
    for (size_t i = 0; i < n; i++) {
        rc_sim_get_ball(w->s, i, &b[i]);
        /* covariant frame: a kink still ahead is made now, as rc_sim_set_c does (the
         * latest momentum and rest mass at the true centre), so no momentum is lost */
        if (rc_sim_kink_ahead(w->s, i) > 0) {
            rc_sim_ball l;
            rc_sim_get_ball_latest(w->s, i, &l);
            b[i].p = l.p;
            b[i].m = l.m;
            b[i].collided = 1;
            b[i].tau_last = b[i].tau;
        }
    }
    /* a contracted frame's ball may lie closer to a wall than its rest radius; an
     * uncontracted frame (the field's sphere) takes it back to r from that wall */
    const int to_r = !(def->frame && def->frame->wall_contracted);
    for (size_t i = 0; to_r && i < n; i++)
        for (int k = 0; k < def->dim; k++)
            if (def->boundary[k] == RC_SIM_WALLS) {
                const double L = rc_v3_get(def->box, k), x = rc_v3_get(b[i].x, k);
                rc_v3_set(&b[i].x, k, fmin(fmax(x, b[i].r), L - b[i].r));
            }
    def->c = w->c;
    def->restart = 1;
    rc_sim *s = NULL;
    st = rc_sim_create(def, &s);
    if (st == RC_OK)
        st = rc_sim_set_time(s, rc_sim_time(w->s));
    if (st == RC_OK)
        st = rc_sim_set_balls(s, n, b, &bad);
    free(b);
    if (st != RC_OK) {
        if (st == RC_EOVERLAP && !(def->frame && def->frame->contracted))
            snprintf(web_err, sizeof web_err, "cannot %s here: ball %zu overlaps another as an "
                     "uncontracted sphere (the run's contracted shapes let them come that "
                     "close); reset the run, whose start has no overlap, and %s there", what,
                     bad, what);
        else
            snprintf(web_err, sizeof web_err, "cannot %s here: %s (ball %zu)", what,
                     rc_strerror(st), bad);
        rc_sim_free(&s);
        return st;
    }
    keep_counts(w);
    rc_sim_free(&w->s);
    w->s = s;
    return RC_OK;
}

/* Restitution, contact frame, law and group rule (indices into rc_toi_frames, rc_laws and
 * the rc_group_rule names; -1 keeps): the run goes on from its state now in a new engine.
 * In a field the frame must be one-instant and uncontracted (sphere): another is refused
 * by name. On failure the old engine runs on. */
WEB_EXPORT int web_set_model(web_world *w, double eps_ball, int frame, int law, int groups)
{
    size_t nf = 0, nl = 0;
    while (rc_toi_frames[nf])
        nf++;
    while (rc_laws[nl])
        nl++;
    rc_sim_def def = scn_sim_def(&w->sc);
    def.eps_ball = eps_ball;
    def.frame = frame >= 0 && (size_t)frame < nf ? rc_toi_frames[frame] : w->sc.frame;
    def.law = law >= 0 && (size_t)law < nl ? rc_laws[law] : w->sc.law;
    def.groups = rc_group_rule_name(groups) ? groups : w->sc.groups;
    if (w->sc.gravity && (def.frame->contracted || def.frame->per_ball ||
                          def.frame->pointlike || def.frame->wall_contracted)) {
        snprintf(web_err, sizeof web_err, "contact frame '%s' is not defined in a field (the "
                 "field takes the one-instant uncontracted frame: sphere); switch g to 0 first",
                 def.frame->name);
        return RC_EUNDEFINED;
    }
    const int st = rebuild(w, &def, "change the model");
    if (st != RC_OK)
        return st;
    w->sc.eps_ball = def.eps_ball;
    w->sc.frame = def.frame;
    w->sc.law = def.law;
    w->sc.groups = def.groups;
    take_reference(w);
    return RC_OK;
}

/* ---- a uniform field along -y (papers/gravity.md) ---------------------------------- */

WEB_EXPORT int web_coupling_count(void)
{
    int n = 0;
    while (rc_gravity_couplings[n])
        n++;
    return n;
}
WEB_EXPORT const char *web_coupling_name(int i) { return rc_gravity_couplings[i]->name; }
WEB_EXPORT const char *web_coupling_summary(int i) { return rc_gravity_couplings[i]->summary; }

static int index_of_coupling(const rc_gravity_coupling *cp)
{
    for (int i = 0; cp && rc_gravity_couplings[i]; i++)
        if (rc_gravity_couplings[i] == cp)
            return i;
    return -1;
}

static const rc_toi_frame *sphere_frame(void)
{
    for (int i = 0; rc_toi_frames[i]; i++) {
        const rc_toi_frame *f = rc_toi_frames[i];
        if (!f->contracted && !f->per_ball && !f->pointlike && !f->wall_contracted)
            return f;
    }
    return NULL;
}

/* The field: g >= 0 along -y (0: none), coupling an index into rc_gravity_couplings. The
 * floor is the wall y = 0 and the ceiling y = box: the y axis must have walls. The engine
 * defines the field's contacts at one instant of the coupling's clock with uncontracted
 * spheres, so a contracted or per-ball frame gives way to the sphere frame while the field
 * is on (and comes back when it goes). The run goes on from its state now; every bad
 * input is refused with web_error() naming it, the old engine running on. */
WEB_EXPORT int web_set_gravity(web_world *w, double g, int coupling)
{
    if (!isfinite(g)) {
        snprintf(web_err, sizeof web_err, "g = %g: must be a finite number", g);
        return RC_ENONFINITE;
    }
    if (g < 0.0) {
        snprintf(web_err, sizeof web_err, "g = %g: must be >= 0 (0 switches the field off; "
                 "the field points down, along -y)", g);
        return RC_EINVAL;
    }
    if (g > 0.0 && (coupling < 0 || coupling >= web_coupling_count())) {
        snprintf(web_err, sizeof web_err, "coupling %d: unknown (the library has %d)",
                 coupling, web_coupling_count());
        return RC_EUNKNOWN;
    }
    if (g > 0.0 && w->sc.boundary[w->sc.dim - 1] == RC_SIM_PERIODIC) {
        snprintf(web_err, sizeof web_err, "g = %g: the field needs walls along y (its floor "
                 "and ceiling), and this scenario is periodic along y", g);
        return RC_EINVAL;
    }
    for (int k = 0; k < 6 && g > 0.0; k++)
        if (w->sc.wall_rule[k] && w->sc.wall_rule[k] != &rc_wall_reflecting) {
            snprintf(web_err, sizeof web_err, "g = %g: a %s wall in a field is not built (the "
                     "field's walls are hard walls)", g, w->sc.wall_rule[k]->name);
            return RC_EUNDEFINED;
        }
    if (g > 0.0 && w->sc.t_c > 0.0) {
        snprintf(web_err, sizeof web_err, "g = %g: the TC model (tc > 0) is not defined in a "
                 "field", g);
        return RC_EUNDEFINED;
    }
    const rc_gravity_coupling *cp = g > 0.0 ? rc_gravity_couplings[coupling] : NULL;
    const rc_toi_frame *f0 = w->sc.frame, *nofield = w->frame_nofield;
    const rc_toi_frame *frame = f0;
    if (cp && (f0->contracted || f0->per_ball || f0->pointlike || f0->wall_contracted)) {
        frame = sphere_frame();
        nofield = f0;
    } else if (!cp && nofield) {
        frame = nofield;
        nofield = NULL;
    }
    const rc_gravity_coupling *cp0 = w->sc.gravity;
    const double g0 = w->sc.g;
    w->sc.gravity = cp;
    w->sc.g = g;
    w->sc.frame = frame;
    rc_sim_def def = scn_sim_def(&w->sc);
    def.eps_ball = w->sc.eps_ball;
    const int st = rebuild(w, &def, cp ? "switch the field on" : "switch the field off");
    if (st != RC_OK) {
        w->sc.gravity = cp0;
        w->sc.g = g0;
        w->sc.frame = f0;
        return st;
    }
    w->frame_nofield = nofield;
    take_reference(w);
    return RC_OK;
}

/* Every ball at time t (>= now): the engine processes the events up to t and brings the
 * balls to t along their free flights. Advancing in pieces gives the bits of one go. */
WEB_EXPORT int web_advance(web_world *w, double t)
{
    int st = rc_sim_advance(w->s, t, 0);
    if (st != RC_OK)
        snprintf(web_err, sizeof web_err, "advance to t = %g: %s", t, rc_strerror(st));
    return st;
}

/* Up to and including the next collision (bookkeeping events pass on the way). */
WEB_EXPORT int web_step_event(web_world *w)
{
    rc_sim_diag d0, d;
    rc_sim_diagnostics(w->s, &d0);
    for (int k = 0; k < 1000000; k++) {
        int st = rc_sim_advance(w->s, INFINITY, 1);
        if (st != RC_OK) {
            snprintf(web_err, sizeof web_err, "single event: %s", rc_strerror(st));
            return st;
        }
        rc_sim_diagnostics(w->s, &d);
        if (d.collisions != d0.collisions)
            return RC_OK;
    }
    return RC_OK;
}

WEB_EXPORT double web_time(const web_world *w) { return rc_sim_time(w->s); }
WEB_EXPORT int web_count(const web_world *w) { return (int)rc_sim_count(w->s); }

/* The balls as web_update last filled them (WB_N doubles each). */
WEB_EXPORT double *web_balls(web_world *w) { return w->balls; }

static int index_of_frame(const rc_toi_frame *f)
{
    for (int i = 0; rc_toi_frames[i]; i++)
        if (rc_toi_frames[i] == f)
            return i;
    return -1;
}

static int index_of_law(const rc_law *l)
{
    for (int i = 0; rc_laws[i]; i++)
        if (rc_laws[i] == l)
            return i;
    return -1;
}

/* Read-outs at the engine's time (WD_* order), and the balls, WB_N doubles each:
 * position, momentum, rest radius and mass, proper time, gamma, speed, and the shape the
 * contact frame sees -- semi-axes along the velocity and across it (r/gamma and r for a
 * contracted frame at finite c, r and r otherwise) and the velocity's angle. */
WEB_EXPORT double *web_update(web_world *w)
{
    const double c = w->c;
    rc_sim_diag d;
    rc_sim_diagnostics(w->s, &d);
    const size_t n = rc_sim_count(w->s);
    const double k2 = inv_c2_of(c);
    const rc_toi_frame *f = w->sc.frame;
    const int contracted = f && f->contracted && k2 > 0.0;
    double gsum = 0.0, vmax = 0.0, pclass = 0.0;
    for (size_t i = 0; i < n; i++) {
        rc_sim_ball b;
        rc_sim_get_ball(w->s, i, &b);
        double *o = &w->balls[i * WB_N];
        const rc_toi_shape sh = rc_toi_shape_of(b.r, b.m, b.p, k2);
        const double M = rc_mass_rel(b.m, b.p, k2);
        const double g = rc_gamma(b.m, b.p, k2);
        const double v = rc_v3_norm(b.p) / M;
        o[WB_X] = b.x.x;
        o[WB_Y] = b.x.y;
        o[WB_PX] = b.p.x;
        o[WB_PY] = b.p.y;
        o[WB_R] = b.r;
        o[WB_M] = b.m;
        o[WB_TAU] = b.tau;
        o[WB_GAMMA] = g;
        o[WB_SPEED] = v;
        /* the library's shape: semi-axis r sqrt(1 - beta^2) = r g along beta */
        o[WB_A] = contracted ? rc_toi_support(&sh, v > 0.0 ? rc_v3_scale(1.0 / rc_v3_norm(b.p), b.p)
                                                           : rc_v3(1, 0, 0))
                             : b.r;
        o[WB_B] = b.r;
        o[WB_ANGLE] = atan2(b.p.y, b.p.x);
        gsum += g;
        vmax = fmax(vmax, v);
        pclass = fmax(pclass, rc_v3_norm(b.p) / b.m);
    }
    const rc_vec3 pw = rc_v3_add(d.momentum, d.wall_impulse);
    const uint64_t coll = w->coll_base + d.collisions, ov = w->ov_base + d.overlaps;
    double *x = w->diag;
    x[WD_TIME] = d.time;
    x[WD_COLL] = (double)coll;
    double escale;
    const double e = conserved(w, &d, &escale);
    x[WD_ENERGY] = e;
    x[WD_EERR] = fabs(e - w->e0) / w->escale;
    /* (in a field the momentum along it is not conserved: the error is the one across) */
    rc_vec3 dp = rc_v3_sub(pw, w->pw0);
    if (w->sc.gravity)
        rc_v3_set(&dp, w->sc.dim - 1, 0.0);
    x[WD_PERR] = rc_v3_norm(dp) / w->pscale;
    x[WD_OVERLAPS] = (double)ov;
    x[WD_OVSHARE] = coll ? (double)ov / (double)coll : 0.0;
    x[WD_MEANG] = n ? gsum / (double)n : 1.0;
    x[WD_VMAX] = vmax;
    x[WD_C] = c;
    x[WD_KINETIC] = d.kinetic;
    x[WD_HEAT] = d.heat;
    x[WD_GROUPSEQ] = (double)(w->seq_base + d.group_sequential);
    x[WD_MAXGROUP] = (double)d.max_group;
    x[WD_N] = (double)n;
    x[WD_BOXX] = w->sc.box.x;
    x[WD_BOXY] = w->sc.box.y;
    x[WD_PCLASS] = pclass;
    x[WD_EPS] = w->sc.eps_ball;
    x[WD_FRAME] = index_of_frame(f);
    x[WD_LAW] = index_of_law(w->sc.law);
    x[WD_CONTRACTED] = contracted;
    x[WD_GROUPS] = w->sc.groups;
    /* the validity report of the engine as it stands (relcol/validity.h): rc_sim_verdict */
    rc_validity val;
    rc_sim_validity(w->s, &val);
    x[WD_VERDICT] = (double)val.verdict;
    x[WD_PMODEL] = val.p_model;
    x[WD_FIELD] = w->sc.gravity != NULL;
    x[WD_G] = w->sc.gravity ? w->sc.g : 0.0;
    x[WD_COUPLING] = index_of_coupling(w->sc.gravity);
    return x;
}

/* ---- the speed histogram against Juttner and Maxwell-Boltzmann ------------------- */

/* 2-D forms of apps/gas/juttner.h (there with GSL for any d; in 2-D they are closed):
 * theta = kT/(m c^2) from <gamma> = (1 + 2 theta + 2 theta^2)/(1 + theta); Juttner in gamma
 * f = gamma e^(-(gamma - 1)/theta) / (theta (1 + theta)); Maxwell-Boltzmann at the same kT
 * has (gamma^2 - 1)/(2 theta) exponentially distributed, f = (gamma/theta)
 * e^(-(gamma^2 - 1)/(2 theta)). In the speed v: f_v = f_gamma gamma^3 v / c^2. Classically
 * (c = inf) both are f_v = (v / s2) e^(-v^2 / (2 s2)), s2 = kT/m = <v^2>/2. */
static double theta_from_gamma2d(double g)
{
    if (!(g > 1.0))
        return NAN;
    const double s = sqrt(g * g + 4.0 * g - 4.0);
    return g >= 2.0 ? 0.25 * ((g - 2.0) + s) : 2.0 * (g - 1.0) / ((2.0 - g) + s);
}

/* nb bins on [0, vtop): hist[0..nb) the balls' speed density, [nb..2nb) Juttner,
 * [2nb..3nb) Maxwell-Boltzmann at the bin centres, hist[3nb] theta (NAN classically),
 * hist[3nb+1] vtop. Call after web_update (it reads the balls from there). */
WEB_EXPORT double *web_histogram(web_world *w, int nb, double vtop)
{
    if (nb < 1)
        nb = 1;
    if (nb > 256)
        nb = 256;
    const size_t n = rc_sim_count(w->s);
    const double k2 = inv_c2_of(w->c);
    double *h = w->hist;
    memset(h, 0, sizeof w->hist);
    if (!(vtop > 0.0) || n == 0)
        return h;
    const double dv = vtop / nb;
    double gsum = 0.0, v2sum = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double *o = &w->balls[i * WB_N];
        const int k = (int)(o[WB_SPEED] / dv);
        if (k >= 0 && k < nb)
            h[k] += 1.0 / ((double)n * dv);
        gsum += o[WB_GAMMA];
        v2sum += o[WB_SPEED] * o[WB_SPEED];
    }
    const double theta = k2 > 0.0 ? theta_from_gamma2d(gsum / (double)n) : NAN;
    const double s2 = 0.5 * v2sum / (double)n;
    for (int k = 0; k < nb; k++) {
        const double v = (k + 0.5) * dv;
        double fj, fm;
        if (k2 > 0.0 && theta > 0.0 && v * v * k2 < 1.0) {
            const double g = 1.0 / sqrt(1.0 - v * v * k2), jac = g * g * g * v * k2;
            fj = g * exp(-(g - 1.0) / theta) / (theta * (1.0 + theta)) * jac;
            fm = g / theta * exp(-(g * g - 1.0) / (2.0 * theta)) * jac;
        } else if (s2 > 0.0) {
            fj = fm = v / s2 * exp(-v * v / (2.0 * s2));
        } else {
            fj = fm = 0.0;
        }
        h[nb + k] = fj;
        h[2 * nb + k] = fm;
    }
    h[3 * nb] = theta;
    h[3 * nb + 1] = vtop;
    return h;
}

/* ---- the profile along the field against its equilibrium (papers/gravity.md s. 5) --- */

/* The dilute gas's equilibrium density along y, unnormalised, at height z: with the
 * newtonian coupling exp(-m g z/kT) at every c (the momentum integral does not depend on
 * z); with equivalence local Juttner at kT(z) = kT0/(1 + g z/c^2), whose 2-D
 * normalisation T (mc^2 + kT) exp(-mc^2/kT) is, over its value at the floor,
 * (1 + theta(z)) / ((1 + g z/c^2)(1 + theta0)) exp(-m g z/kT0), theta = kT/mc^2. */
static double dens_theory(int equiv, double z, double m, double g, double kt, double k2)
{
    const double a = 1.0 + g * z * k2, th0 = kt * k2 / m;
    const double bar = exp(-m * g * z / kt);
    return equiv ? bar * (1.0 + th0 / a) / (a * (1.0 + th0)) : bar;
}

/* nb slabs (1..64) of the box's height along y, from the balls as web_update last filled
 * them. Columns of nb values: [0] the balls' density along y (share of the balls per unit
 * height), [1] kT in the slab, <p.v>/d (kT in local Juttner or Maxwell equilibrium; NAN:
 * empty), [2] its standard error (NAN: fewer than two balls), [3] the theory's density
 * (share per unit height, centres on [r, H - r] with r the mean radius), [4] the theory's
 * kT at the slab's centre: uniform kT (newtonian, or no field) or kT0/(1 + g z/c^2)
 * (equivalence, Tolman-Ehrenfest). Then: the fitted kT (newtonian, no field: <p.v>/d over
 * every ball) or kT0 (equivalence: <(1 + g z/c^2) p.v>/d, Tolman's constant), the height
 * H, g, the coupling's index (-1: none), the mean rest mass (the theory takes one mass),
 * the balls counted. */
WEB_EXPORT double *web_profile(web_world *w, int nb)
{
    nb = nb < 1 ? 1 : nb > WP_MAXBINS ? WP_MAXBINS : nb;
    double *o = w->prof;
    for (size_t k = 0; k < sizeof w->prof / sizeof *o; k++)
        o[k] = NAN;
    const size_t n = rc_sim_count(w->s);
    const int d = w->sc.dim, equiv = w->sc.gravity == &rc_gravity_equivalence;
    const double H = rc_v3_get(w->sc.box, d - 1), dz = H / nb, k2 = inv_c2_of(w->c);
    const double g = w->sc.gravity ? w->sc.g : 0.0;
    double cnt[WP_MAXBINS] = {0}, s1[WP_MAXBINS] = {0}, s2[WP_MAXBINS] = {0};
    double fit = 0.0, msum = 0.0, rsum = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double *b = &w->balls[i * WB_N];
        const double z = d == 2 ? b[WB_Y] : NAN; /* (the page shows 2-D tables) */
        const double p2 = b[WB_PX] * b[WB_PX] + b[WB_PY] * b[WB_PY];
        const double pv = p2 / (b[WB_M] * b[WB_GAMMA]) / d; /* p.v/d, v = p/(gamma m) */
        int k = (int)(z / dz);
        k = k < 0 ? 0 : k >= nb ? nb - 1 : k;
        cnt[k]++;
        s1[k] += pv;
        s2[k] += pv * pv;
        fit += (equiv ? 1.0 + g * z * k2 : 1.0) * pv;
        msum += b[WB_M];
        rsum += b[WB_R];
    }
    if (n == 0)
        return o;
    fit /= (double)n;
    const double m = msum / (double)n, r = rsum / (double)n;
    /* the theory's shares: Simpson over each slab's part of [r, H - r] */
    double th[WP_MAXBINS], tot = 0.0;
    for (int k = 0; k < nb; k++) {
        const double lo = fmax(k * dz, r), hi = fmin((k + 1) * dz, H - r);
        th[k] = 0.0;
        if (hi > lo && fit > 0.0) {
            enum { SIMPSON = 16 };
            double sum = 0.0;
            for (int j = 0; j <= SIMPSON; j++)
                sum += (j == 0 || j == SIMPSON ? 1 : j % 2 ? 4 : 2) *
                       dens_theory(equiv, lo + (hi - lo) * j / SIMPSON, m, g, fit, k2);
            th[k] = sum * (hi - lo) / (3 * SIMPSON);
        }
        tot += th[k];
    }
    for (int k = 0; k < nb; k++) {
        const double zc = (k + 0.5) * dz, c = cnt[k];
        o[k] = c / ((double)n * dz);
        o[nb + k] = c > 0 ? s1[k] / c : NAN;
        o[2 * nb + k] = c > 1 ? sqrt(fmax(s2[k] / c - o[nb + k] * o[nb + k], 0.0) / (c - 1))
                              : NAN;
        o[3 * nb + k] = tot > 0.0 ? th[k] / (tot * dz) : NAN;
        o[4 * nb + k] = equiv ? fit / (1.0 + g * zc * k2) : fit;
    }
    double *t = &o[WP_COLS * nb];
    t[0] = fit;
    t[1] = H;
    t[2] = g;
    t[3] = index_of_coupling(w->sc.gravity);
    t[4] = m;
    t[5] = (double)n;
    return o;
}

/* ---- the library's tables, by name ------------------------------------------------ */

WEB_EXPORT int web_frame_count(void)
{
    int n = 0;
    while (rc_toi_frames[n])
        n++;
    return n;
}
WEB_EXPORT const char *web_frame_name(int i) { return rc_toi_frames[i]->name; }
WEB_EXPORT int web_frame_contracted(int i) { return rc_toi_frames[i]->contracted; }
WEB_EXPORT int web_law_count(void)
{
    int n = 0;
    while (rc_laws[n])
        n++;
    return n;
}
WEB_EXPORT const char *web_law_name(int i) { return rc_laws[i]->name; }
WEB_EXPORT const char *web_law_summary(int i) { return rc_laws[i]->summary; }
/* 1: the law resolves simultaneous contacts together; 0: one at a time, in order */
WEB_EXPORT int web_law_group(int i) { return rc_laws[i]->group != NULL; }
/* The rules for simultaneous contacts (relcol/law.h), for laws with a group solver */
WEB_EXPORT int web_group_count(void)
{
    int n = 0;
    while (rc_group_rule_name(n))
        n++;
    return n;
}
WEB_EXPORT const char *web_group_name(int i) { return rc_group_rule_name(i); }
WEB_EXPORT const char *web_group_summary(int i) { return rc_group_rule_summary(i); }

/* ---- engine speed in the page (bench_engine's set-up) ----------------------------- */

/* bench_engine's setup() and melt of run(dim, n, packing, c, frame, melt, ...): a gas of
 * radius 1/2, rms speed 1 (0.5 c relativistically), seed 2024, melted for melt collisions
 * a ball; NULL on failure. Timed apart (web_bench_run) so that the caller can read the
 * CPU time around the measured part only, as bench_engine does. */
WEB_EXPORT rc_sim *web_bench_setup(int dim, int n, double packing, double c, int frame,
                                   double melt)
{
    rc_sim_gas_def g = {dim, (size_t)n, 0.5, packing, isinf(c) ? 1.0 : 0.5 * c, c, 1.0, 2024};
    rc_sim_ball *b = calloc((size_t)n, sizeof *b);
    rc_sim_def d = rc_sim_def_default();
    d.dim = dim;
    d.c = c;
    if (frame >= 0 && frame < web_frame_count())
        d.frame = rc_toi_frames[frame];
    rc_sim *s = NULL;
    int st = b ? rc_sim_gas_init(&g, &d.box, b) : RC_ENOMEM;
    if (st == RC_OK)
        st = rc_sim_create(&d, &s);
    if (st == RC_OK)
        st = rc_sim_set_balls(s, (size_t)n, b, NULL);
    free(b);
    if (st != RC_OK) {
        snprintf(web_err, sizeof web_err, "bench set-up: %s", rc_strerror(st));
        rc_sim_free(&s);
        return NULL;
    }
    rc_sim_advance(s, INFINITY, (uint64_t)(melt * n * 1.5));
    return s;
}

/* bench_engine's measured part: measure collisions a ball (events ~1.5 per collision);
 * returns the collisions resolved. */
WEB_EXPORT double web_bench_run(rc_sim *s, double measure)
{
    rc_sim_diag d0, d1;
    rc_sim_diagnostics(s, &d0);
    rc_sim_advance(s, INFINITY, (uint64_t)(measure * (double)rc_sim_count(s) * 1.5));
    rc_sim_diagnostics(s, &d1);
    return (double)(d1.collisions - d0.collisions);
}

WEB_EXPORT void web_bench_free(rc_sim *s) { rc_sim_free(&s); }
