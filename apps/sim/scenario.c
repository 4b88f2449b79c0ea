/* scenario.c — scenario JSON in and out (schema in apps/sim/SCENARIO.md). Every value is
 * checked where it is read, and an error names its JSON path: "balls[3].v: |v| = 1.2 >=
 * c = 1", "restitution.wall: must be in [0, 1]", "outputs.snapshot: unknown key". */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "app.h"
#include "scenario.h"

/* ---- laws and frames: the library's tables, then the caller's --------------------- */

static const rc_law *find_law(const scn_tables *x, const char *name)
{
    const rc_law *l = rc_law_find(name);
    for (size_t i = 0; !l && x && x->laws && x->laws[i]; i++)
        if (strcmp(x->laws[i]->name, name) == 0)
            l = x->laws[i];
    return l;
}

static const rc_toi_frame *find_frame(const scn_tables *x, const char *name)
{
    const rc_toi_frame *f = rc_toi_frame_find(name);
    for (size_t i = 0; !f && x && x->frames && x->frames[i]; i++)
        if (strcmp(x->frames[i]->name, name) == 0)
            f = x->frames[i];
    return f;
}

/* "a, b, c": the names of the library's laws (frames 0) or frames (1), then the caller's */
static const char *name_list(const scn_tables *x, int frames, char *buf, size_t n)
{
    buf[0] = '\0';
    for (int t = 0; t < 2; t++)
        for (size_t i = 0;; i++) {
            const char *nm = NULL;
            if (frames) {
                const rc_toi_frame *const *tab = t ? (x ? x->frames : NULL) : rc_toi_frames;
                nm = tab && tab[i] ? tab[i]->name : NULL;
            } else {
                const rc_law *const *tab = t ? (x ? x->laws : NULL) : rc_laws;
                nm = tab && tab[i] ? tab[i]->name : NULL;
            }
            if (!nm)
                break;
            size_t l = strlen(buf);
            snprintf(buf + l, n - l, "%s%s", l ? ", " : "", nm);
        }
    return buf;
}

/* ---- small checked readers ------------------------------------------------------- */

typedef struct ctx {
    const char *name;
    char *err;
} ctx;

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static int bad(const ctx *c, const char *path, const char *fmt, ...)
{
    char msg[APP_ERR_LEN];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    app_errf(c->err, "%s: %s: %s", c->name, path, msg);
    return -1;
}

/* Reject keys of obj not in the NULL-terminated list, and keys given twice (the reader
 * would silently take the first). */
static int only_keys(const ctx *c, const cJSON *obj, const char *path, const char *const *keys)
{
    for (const cJSON *it = obj->child; it; it = it->next) {
        for (const cJSON *e = obj->child; e != it; e = e->next)
            if (strcmp(e->string, it->string) == 0) {
                char p[256];
                snprintf(p, sizeof p, "%s%s%s", path, *path ? "." : "", it->string);
                return bad(c, p, "given twice");
            }
        int ok = 0;
        for (size_t i = 0; keys[i]; i++)
            ok |= strcmp(it->string, keys[i]) == 0;
        if (!ok) {
            char list[256] = "";
            for (size_t i = 0; keys[i]; i++) {
                strncat(list, keys[i], sizeof list - strlen(list) - 1);
                if (keys[i + 1])
                    strncat(list, ", ", sizeof list - strlen(list) - 1);
            }
            char p[256];
            snprintf(p, sizeof p, "%s%s%s", path, *path ? "." : "", it->string);
            return bad(c, p, "unknown key (expected one of: %s)", list);
        }
    }
    return 0;
}

static void subpath(char *out, size_t n, const char *path, const char *key)
{
    snprintf(out, n, "%s%s%s", path, *path ? "." : "", key);
}

/* Number at obj[key]; missing: *out = def (or error if required). allow_inf accepts the
 * string "inf". */
static int get_num(const ctx *c, const cJSON *obj, const char *path, const char *key,
                   int required, double def, int allow_inf, double *out)
{
    char p[256];
    subpath(p, sizeof p, path, key);
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!v) {
        if (required)
            return bad(c, p, "missing (required)");
        *out = def;
        return 0;
    }
    if (allow_inf && cJSON_IsString(v) && strcmp(v->valuestring, "inf") == 0) {
        *out = INFINITY;
        return 0;
    }
    if (!cJSON_IsNumber(v))
        return bad(c, p, "must be a number%s", allow_inf ? " or \"inf\"" : "");
    if (!isfinite(v->valuedouble))
        return bad(c, p, "not a finite number");
    *out = v->valuedouble;
    return 0;
}

static int get_bool(const ctx *c, const cJSON *obj, const char *path, const char *key, int def,
                    int *out)
{
    char p[256];
    subpath(p, sizeof p, path, key);
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!v) {
        *out = def;
        return 0;
    }
    if (!cJSON_IsBool(v))
        return bad(c, p, "must be true or false");
    *out = cJSON_IsTrue(v);
    return 0;
}

static int get_str(const ctx *c, const cJSON *obj, const char *path, const char *key,
                   const char *def, const char **out)
{
    char p[256];
    subpath(p, sizeof p, path, key);
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!v) {
        *out = def;
        return 0;
    }
    if (!cJSON_IsString(v))
        return bad(c, p, "must be a string");
    *out = v->valuestring;
    return 0;
}

/* A vector of exactly dim finite numbers. */
static int get_vec(const ctx *c, const cJSON *v, const char *p, int dim, rc_vec3 *out)
{
    if (!cJSON_IsArray(v))
        return bad(c, p, "must be an array of %d numbers", dim);
    int n = cJSON_GetArraySize(v);
    if (n != dim)
        return bad(c, p, "has %d components, the scenario is %d-D", n, dim);
    *out = rc_v3(0, 0, 0);
    int i = 0;
    for (const cJSON *e = v->child; e; e = e->next, i++) {
        if (!cJSON_IsNumber(e) || !isfinite(e->valuedouble))
            return bad(c, p, "component %d is not a finite number", i);
        rc_v3_set(out, i, e->valuedouble);
    }
    return 0;
}

/* ---- sections -------------------------------------------------------------------- */

/* A ball's image counters: dim whole numbers, 0 on a walled axis. */
static int get_image(const ctx *c, const cJSON *v, const char *p, const scn_scenario *s,
                     int32_t image[3])
{
    if (!cJSON_IsArray(v) || cJSON_GetArraySize(v) != s->dim)
        return bad(c, p, "must be an array of %d whole numbers (periodic wraps per axis)",
                   s->dim);
    int d = 0;
    for (const cJSON *e = v->child; e; e = e->next, d++) {
        const double x = cJSON_IsNumber(e) ? e->valuedouble : NAN;
        if (!(x == floor(x) && fabs(x) <= 2147483647.0))
            return bad(c, p, "component %d is not a whole number in 32 bits", d);
        if (x != 0 && s->boundary[d] != RC_SIM_PERIODIC)
            return bad(c, p, "component %d must be 0: axis %d has walls", d, d);
        image[d] = (int32_t)x;
    }
    return 0;
}

/* boundary: "walls" / "periodic" for every axis, or a list of dim of them. */
static int boundary_of(const ctx *c, const cJSON *v, const char *p, int *out)
{
    if (!cJSON_IsString(v))
        return bad(c, p, "must be \"walls\" or \"periodic\"");
    if (strcmp(v->valuestring, "walls") == 0)
        *out = RC_SIM_WALLS;
    else if (strcmp(v->valuestring, "periodic") == 0)
        *out = RC_SIM_PERIODIC;
    else
        return bad(c, p, "unknown boundary '%s' (expected walls or periodic)", v->valuestring);
    return 0;
}

static int parse_boundary(const ctx *c, const cJSON *v, scn_scenario *s)
{
    if (cJSON_IsString(v)) {
        int b = RC_SIM_WALLS;
        if (boundary_of(c, v, "boundary", &b))
            return -1;
        for (int d = 0; d < s->dim; d++)
            s->boundary[d] = b;
        return 0;
    }
    if (!cJSON_IsArray(v))
        return bad(c, "boundary", "must be \"walls\", \"periodic\" or a list of %d of them",
                   s->dim);
    const int n = cJSON_GetArraySize(v);
    if (n != s->dim)
        return bad(c, "boundary", "has %d entries, the scenario is %d-D", n, s->dim);
    int d = 0;
    char p[32];
    for (const cJSON *e = v->child; e; e = e->next, d++) {
        snprintf(p, sizeof p, "boundary[%d]", d);
        if (boundary_of(c, e, p, &s->boundary[d]))
            return -1;
    }
    return 0;
}

const char *const scn_wall_names[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};

/* walls: {"x-": WALL, ...} per wall of a walled axis, WALL "reflecting" (the default: the
 * hard wall of restitution.wall) or {"rule": "thermal", "kT": t} (relcol/wall.h). */
static int parse_walls(const ctx *c, const cJSON *v, scn_scenario *s)
{
    if (!cJSON_IsObject(v))
        return bad(c, "walls", "must be an object {\"x-\": {\"rule\": \"thermal\", \"kT\": 1}, ...}");
    const char *keys[7] = {NULL};
    for (int w = 0; w < 2 * s->dim; w++)
        keys[w] = scn_wall_names[w];
    if (only_keys(c, v, "walls", keys))
        return -1;
    for (int w = 0; w < 2 * s->dim; w++) {
        const cJSON *e = cJSON_GetObjectItemCaseSensitive(v, scn_wall_names[w]);
        if (!e)
            continue;
        char p[32];
        snprintf(p, sizeof p, "walls.%s", scn_wall_names[w]);
        const char *name = NULL;
        if (cJSON_IsString(e)) {
            name = e->valuestring;
        } else if (cJSON_IsObject(e)) {
            static const char *const wk[] = {"rule", "kT", NULL};
            if (only_keys(c, e, p, wk) || get_str(c, e, p, "rule", NULL, &name))
                return -1;
            if (!name)
                return bad(c, p, "needs a \"rule\" (reflecting or thermal)");
        } else {
            return bad(c, p, "must be \"reflecting\" or {\"rule\": \"thermal\", \"kT\": t}");
        }
        const rc_wall_rule *r = rc_wall_rule_find(name);
        if (!r) {
            char list[128] = "";
            for (size_t k = 0; rc_wall_rules[k]; k++)
                snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", k ? ", " : "",
                         rc_wall_rules[k]->name);
            return bad(c, p, "unknown wall rule '%s' (expected %s)", name, list);
        }
        const cJSON *jt = cJSON_IsObject(e) ? cJSON_GetObjectItemCaseSensitive(e, "kT") : NULL;
        if (r->temperature) {
            if (!jt)
                return bad(c, p, "a %s wall needs its temperature \"kT\"", r->name);
            double kT;
            if (get_num(c, e, p, "kT", 1, 0, 0, &kT))
                return -1;
            if (!(kT > 0))
                return bad(c, p, "kT = %g: a wall's temperature must be > 0", kT);
            s->wall_kT[w] = kT;
        } else if (jt) {
            return bad(c, p, "a %s wall has no temperature: drop \"kT\"", r->name);
        }
        if (!r->rigid && s->boundary[w / 2] == RC_SIM_PERIODIC)
            return bad(c, p, "axis %d is periodic (boundary): it has no wall to be %s", w / 2, r->name);
        s->wall_rule[w] = r == &rc_wall_reflecting ? NULL : r;
    }
    return 0;
}

/* A periodic axis needs four cells of at least a largest diameter (relcol/sim.h). */
static int check_periodic_room(const ctx *c, const scn_scenario *s)
{
    double rmax = 0;
    for (size_t i = 0; i < s->n; i++)
        rmax = s->balls[i].r > rmax ? s->balls[i].r : rmax;
    for (int d = 0; d < s->dim; d++) {
        const double L = rc_v3_get(s->box, d), need = 8 * rmax * (1 + 1e-7);
        if (s->boundary[d] == RC_SIM_PERIODIC && !(L >= need))
            return bad(c, "boundary", "axis %d is periodic, so its box edge %g must be at "
                                      "least 4 largest ball diameters (%.9g)", d, L, need);
    }
    return 0;
}

/* Each component within app_check_scale's range, the error naming path[d]. */
static int scaled_vec(const ctx *c, const char *path, rc_vec3 v, int dim)
{
    char why[APP_ERR_LEN], q[96];
    for (int d = 0; d < dim; d++)
        if (app_check_scale(rc_v3_get(v, d), 0, why)) {
            snprintf(q, sizeof q, "%s[%d]", path, d);
            return bad(c, q, "%s", why);
        }
    return 0;
}

/* The balls a generator made, within app_check_scale's range like balls given one by one
 * (a gas of radius 1e67 has masses density r^3 of 1e202, whose squares overflow): the
 * error names the generator's key and the ball. */
static int scaled_generated(const ctx *c, const scn_scenario *s, const char *key)
{
    char why[APP_ERR_LEN];
    for (size_t i = 0; i < s->n; i++) {
        const rc_sim_ball *b = &s->balls[i];
        const double v[2] = {b->r, b->m};
        static const char *const what[2] = {"radius", "rest mass"};
        for (int k = 0; k < 2; k++)
            if (app_check_scale(v[k], 1, why))
                return bad(c, key, "gives ball %zu a %s out of range: %s", i, what[k], why);
        for (int d = 0; d < s->dim; d++)
            if (app_check_scale(rc_v3_get(b->x, d), 0, why) ||
                app_check_scale(rc_v3_get(b->p, d), 0, why))
                return bad(c, key, "gives ball %zu a position or momentum out of range: %s",
                           i, why);
    }
    return 0;
}

static int parse_balls(const ctx *c, const cJSON *arr, scn_scenario *s)
{
    static const char *const keys[] = {"r", "m", "x", "v", "p", "tau", "tau_last", "image", NULL};
    if (!cJSON_IsArray(arr))
        return bad(c, "balls", "must be an array of ball objects");
    s->n = (size_t)cJSON_GetArraySize(arr);
    if (s->n == 0)
        return bad(c, "balls", "is empty");
    s->balls = calloc(s->n, sizeof *s->balls);
    if (!s->balls)
        return bad(c, "balls", "out of memory");
    double k = isinf(s->c) ? 0.0 : 1.0 / (s->c * s->c);
    size_t i = 0;
    char p[64], q[80];
    for (const cJSON *b = arr->child; b; b = b->next, i++) {
        snprintf(p, sizeof p, "balls[%zu]", i);
        if (!cJSON_IsObject(b))
            return bad(c, p, "must be an object");
        if (only_keys(c, b, p, keys))
            return -1;
        rc_sim_ball *o = &s->balls[i];
        if (get_num(c, b, p, "r", 1, 0, 0, &o->r) || get_num(c, b, p, "m", 0, 0, 0, &o->m) ||
            get_num(c, b, p, "tau", 0, 0, 0, &o->tau))
            return -1;
        /* TC-model memory: the proper time of the ball's last collision, if any */
        o->collided = cJSON_GetObjectItemCaseSensitive(b, "tau_last") != NULL;
        if (get_num(c, b, p, "tau_last", 0, 0, 0, &o->tau_last))
            return -1;
        if (!(o->r > 0)) {
            snprintf(q, sizeof q, "%s.r", p);
            return bad(c, q, "radius must be > 0");
        }
        const cJSON *jm = cJSON_GetObjectItemCaseSensitive(b, "m");
        if (jm && !(o->m > 0)) {
            snprintf(q, sizeof q, "%s.m", p);
            return bad(c, q, "rest mass must be > 0");
        }
        if (!jm)
            o->m = o->r * o->r * o->r; /* equal density (DESIGN.md: m proportional to r^3) */
        char why[APP_ERR_LEN];
        snprintf(q, sizeof q, "%s.r", p);
        if (app_check_scale(o->r, 1, why))
            return bad(c, q, "%s", why);
        snprintf(q, sizeof q, "%s.m", p);
        if (app_check_scale(o->m, 1, why))
            return bad(c, q, "%s%s", why, jm ? "" : " (the default m = r^3)");
        const cJSON *jx = cJSON_GetObjectItemCaseSensitive(b, "x");
        snprintf(q, sizeof q, "%s.x", p);
        if (!jx)
            return bad(c, q, "missing (required)");
        if (get_vec(c, jx, q, s->dim, &o->x) || scaled_vec(c, q, o->x, s->dim))
            return -1;
        /* the centre in the box here; whether the whole (possibly contracted) shape is
         * inside is the engine's check, in the contact frame's geometry (a periodic axis:
         * the centre in [0, L), the shape may reach across the face) */
        for (int d = 0; d < s->dim; d++) {
            double xd = rc_v3_get(o->x, d), L = rc_v3_get(s->box, d);
            if (s->boundary[d] == RC_SIM_PERIODIC && !(xd >= 0 && xd < L))
                return bad(c, q, "the centre is not inside the box along periodic axis %d: "
                                 "%.17g not in [0, %g)", d, xd, L);
            if (s->boundary[d] != RC_SIM_PERIODIC && !(xd > 0 && xd < L))
                return bad(c, q, "the centre is not inside the box along axis %d: %.17g not "
                                 "in (0, %g)", d, xd, L);
        }
        const cJSON *ji = cJSON_GetObjectItemCaseSensitive(b, "image");
        snprintf(q, sizeof q, "%s.image", p);
        if (ji && get_image(c, ji, q, s, o->image))
            return -1;
        const cJSON *jv = cJSON_GetObjectItemCaseSensitive(b, "v");
        const cJSON *jp = cJSON_GetObjectItemCaseSensitive(b, "p");
        if (jv && jp)
            return bad(c, p, "give either v or p, not both");
        if (!jv && !jp) {
            o->p = rc_v3(0, 0, 0);
        } else if (jp) {
            snprintf(q, sizeof q, "%s.p", p);
            if (get_vec(c, jp, q, s->dim, &o->p) || scaled_vec(c, q, o->p, s->dim))
                return -1;
        } else {
            snprintf(q, sizeof q, "%s.v", p);
            rc_vec3 v;
            if (get_vec(c, jv, q, s->dim, &v) || scaled_vec(c, q, v, s->dim))
                return -1;
            if (rc_momentum_from_velocity(o->m, v, k, &o->p) != RC_OK)
                return bad(c, q, "|v| = %.17g >= c = %g", rc_v3_norm(v), s->c);
        }
    }
    return 0;
}

static int parse_generate(const ctx *c, const cJSON *g, const cJSON *jbox, scn_scenario *s)
{
    if (!cJSON_IsObject(g))
        return bad(c, "generate", "must be an object");
    const char *kind = NULL;
    if (get_str(c, g, "generate", "kind", NULL, &kind))
        return -1;
    if (!kind)
        return bad(c, "generate.kind", "missing (required: \"rack\" or \"gas\")");
    if (strcmp(kind, "gas") == 0) {
        static const char *const keys[] = {"kind", "n", "radius", "packing", "v_rms", "density", NULL};
        if (only_keys(c, g, "generate", keys))
            return -1;
        if (jbox)
            return bad(c, "box", "must not be given with generate.kind = gas (the box follows "
                                 "from n and packing)");
        double n = 0, radius = 0, packing = 0, v_rms = 0, density = 0;
        if (get_num(c, g, "generate", "n", 1, 0, 0, &n) ||
            get_num(c, g, "generate", "radius", 0, 1.0, 0, &radius) ||
            get_num(c, g, "generate", "packing", 1, 0, 0, &packing) ||
            get_num(c, g, "generate", "v_rms", 1, 0, 0, &v_rms) ||
            get_num(c, g, "generate", "density", 0, 1.0, 0, &density))
            return -1;
        if (!(n >= 1 && n <= 1e8 && n == floor(n)))
            return bad(c, "generate.n", "must be a whole number in [1, 1e8]");
        if (!(radius > 0))
            return bad(c, "generate.radius", "must be > 0");
        double pmax = s->dim == 2 ? 0.7 : 0.45;
        if (!(packing > 0 && packing <= pmax))
            return bad(c, "generate.packing", "must be in (0, %g] in %d-D", pmax, s->dim);
        if (!(v_rms >= 0 && v_rms < s->c))
            return bad(c, "generate.v_rms", "must be in [0, c) (c = %g)", s->c);
        if (!(density > 0))
            return bad(c, "generate.density", "must be > 0");
        if (n == 1 && v_rms > 0)
            return bad(c, "generate.v_rms", "must be 0 for a gas of one ball (its total "
                                            "momentum is zero: it is at rest)");
        rc_sim_gas_def gd = {s->dim, (size_t)n, radius, packing, v_rms, s->c, density, s->seed};
        s->n = (size_t)n;
        s->balls = calloc(s->n, sizeof *s->balls);
        if (!s->balls)
            return bad(c, "generate.n", "out of memory for %zu balls: their description "
                       "alone needs %zu bytes (%.3g GiB), before the engine's own",
                       s->n, s->n * sizeof *s->balls,
                       (double)(s->n * sizeof *s->balls) / (1024.0 * 1024.0 * 1024.0));
        int st = rc_sim_gas_init(&gd, &s->box, s->balls);
        if (st == RC_ENONFINITE)
            return bad(c, "generate.v_rms", "too large: the momenta would overflow");
        if (st == RC_ENOMEM) {
            const size_t need = rc_sim_gas_bytes(&gd);
            return bad(c, "generate.n", "out of memory for %zu balls: placing them needs %zu "
                       "bytes (%.3g GiB) beside the %zu bytes (%.3g GiB) of their description",
                       s->n, need, (double)need / 1073741824.0, s->n * sizeof *s->balls,
                       (double)(s->n * sizeof *s->balls) / 1073741824.0);
        }
        if (st != RC_OK)
            return bad(c, "generate", "cannot make the gas: %s", rc_strerror(st));
        if (scaled_generated(c, s, "generate.radius"))
            return -1;
        snprintf(s->generator, sizeof s->generator, "gas");
        return 0;
    }
    if (strcmp(kind, "rack") == 0) {
        static const char *const keys[] = {"kind", "radius", "speed", "aim", "gap", NULL};
        if (only_keys(c, g, "generate", keys))
            return -1;
        if (s->dim != 2)
            return bad(c, "dim", "generate.kind = rack is a 2-D table");
        double r = 0, speed = 0, aim = 0, gap = 0;
        if (get_num(c, g, "generate", "radius", 0, 0.028575, 0, &r) ||
            get_num(c, g, "generate", "speed", 0, 5.0, 0, &speed) ||
            get_num(c, g, "generate", "aim", 0, 0.0, 0, &aim) ||
            get_num(c, g, "generate", "gap", 0, 1e-6, 0, &gap))
            return -1;
        if (!(r > 0))
            return bad(c, "generate.radius", "must be > 0");
        if (!(speed >= 0 && speed < s->c))
            return bad(c, "generate.speed", "must be in [0, c) (c = %g)", s->c);
        if (!(gap >= 0))
            return bad(c, "generate.gap", "must be >= 0");
        double L = s->box.x, W = s->box.y;
        double pitch = 2 * r * (1 + gap); /* centre spacing; gap in radii avoids touching */
        double x0 = 0.75 * L, y0 = 0.5 * W;
        if (x0 + 4 * pitch * sqrt(3) / 2 + r > L || 5 * pitch > W || 0.25 * L - r < 0)
            return bad(c, "box", "too small for a rack of balls of radius %g", r);
        s->n = 16;
        s->balls = calloc(s->n, sizeof *s->balls);
        if (!s->balls)
            return bad(c, "generate", "out of memory");
        double k = isinf(s->c) ? 0.0 : 1.0 / (s->c * s->c);
        rc_sim_ball *b = s->balls;
        b[0].r = r;
        b[0].m = r * r * r;
        b[0].x = rc_v3(0.25 * L, y0, 0);
        rc_vec3 v = rc_v3(speed * cos(aim), speed * sin(aim), 0);
        if (rc_momentum_from_velocity(b[0].m, v, k, &b[0].p) != RC_OK)
            return bad(c, "generate.speed", "speed >= c");
        size_t i = 1;
        for (int row = 0; row < 5; row++)
            for (int j = 0; j <= row; j++, i++) {
                b[i].r = r;
                b[i].m = r * r * r;
                b[i].x = rc_v3(x0 + row * pitch * sqrt(3) / 2, y0 + (j - row / 2.0) * pitch, 0);
            }
        if (scaled_generated(c, s, "generate.radius"))
            return -1;
        snprintf(s->generator, sizeof s->generator, "rack");
        return 0;
    }
    return bad(c, "generate.kind", "unknown generator '%s' (expected rack or gas)", kind);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

const char *const scn_h5md_names[SCN_H5MD_N] = {"position", "velocity", "mass", "rest_mass",
                                                "momentum", "proper_time", "image"};

/* outputs.h5md: {"fields": [names of scn_h5md_names], "precision": "float64" | "float32",
 * "scenario": true | false}, what trajectory.h5 holds; read after h5md_every, which it
 * needs. */
static int parse_h5md(const ctx *c, const cJSON *h, scn_scenario *s)
{
    scn_outputs *out = &s->out;
    int periodic = 0;
    for (int d = 0; d < s->dim; d++)
        periodic |= s->boundary[d] == RC_SIM_PERIODIC;
    out->h5md_fields = (1u << SCN_H5MD_N) - 1u;
    if (!periodic)
        out->h5md_fields &= ~(1u << SCN_H5MD_IMAGE);
    out->h5md_float32 = 0;
    out->h5md_scenario = 1;
    if (!h)
        return 0;
    static const char *const keys[] = {"fields", "precision", "scenario", NULL};
    if (!cJSON_IsObject(h))
        return bad(c, "outputs.h5md", "must be an object {\"fields\": [...], \"precision\": "
                   "\"float64\" or \"float32\", \"scenario\": true or false}");
    if (only_keys(c, h, "outputs.h5md", keys))
        return -1;
    if (!(out->h5md_every > 0))
        return bad(c, "outputs.h5md", "says what trajectory.h5 holds, but outputs.h5md_every "
                   "is not > 0: no trajectory.h5 is written");
    const char *prec = "float64";
    if (get_str(c, h, "outputs.h5md", "precision", prec, &prec) ||
        get_bool(c, h, "outputs.h5md", "scenario", 1, &out->h5md_scenario))
        return -1;
    if (strcmp(prec, "float32") == 0)
        out->h5md_float32 = 1;
    else if (strcmp(prec, "float64") != 0)
        return bad(c, "outputs.h5md.precision", "unknown precision '%s' (expected float64 or "
                   "float32)", prec);
    const cJSON *f = cJSON_GetObjectItemCaseSensitive(h, "fields");
    if (!f)
        return 0;
    char names[160] = "";
    for (int e = 0; e < SCN_H5MD_N; e++)
        snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", e ? ", " : "",
                 scn_h5md_names[e]);
    if (!cJSON_IsArray(f) || !f->child)
        return bad(c, "outputs.h5md.fields", "must be a non-empty list of names (of: %s)", names);
    out->h5md_fields = 0;
    int i = 0;
    for (const cJSON *e = f->child; e; e = e->next, i++) {
        char p[64];
        snprintf(p, sizeof p, "outputs.h5md.fields[%d]", i);
        if (!cJSON_IsString(e))
            return bad(c, p, "must be a name (one of: %s)", names);
        int k = 0;
        while (k < SCN_H5MD_N && strcmp(e->valuestring, scn_h5md_names[k]) != 0)
            k++;
        if (k == SCN_H5MD_N)
            return bad(c, p, "unknown field '%s' (expected one of: %s)", e->valuestring, names);
        if (out->h5md_fields >> k & 1u)
            return bad(c, p, "'%s' given twice", e->valuestring);
        if (k == SCN_H5MD_IMAGE && !periodic)
            return bad(c, p, "image (the periodic wraps) needs a periodic axis: every axis "
                       "has walls");
        out->h5md_fields |= 1u << k;
    }
    return 0;
}

static int parse_outputs(const ctx *c, const cJSON *o, scn_scenario *s)
{
    static const char *const keys[] = {"dir", "snapshots", "xyz_every", "xyz_from", "h5md_every",
                                       "h5md", "plots", "gif", "summary", NULL};
    scn_outputs *out = &s->out;
    out->plots = 1;
    out->xyz_from = s->time;
    out->gif = s->dim == 2;
    out->summary = 1;
    parse_h5md(c, NULL, s); /* (the defaults) */
    const char *dir = "out/sim";
    if (o) {
        if (!cJSON_IsObject(o))
            return bad(c, "outputs", "must be an object");
        if (only_keys(c, o, "outputs", keys))
            return -1;
        if (get_str(c, o, "outputs", "dir", dir, &dir) ||
            get_num(c, o, "outputs", "xyz_every", 0, 0, 0, &out->xyz_every) ||
            get_num(c, o, "outputs", "xyz_from", 0, s->time, 0, &out->xyz_from) ||
            get_num(c, o, "outputs", "h5md_every", 0, 0, 0, &out->h5md_every) ||
            get_bool(c, o, "outputs", "plots", 1, &out->plots) ||
            get_bool(c, o, "outputs", "gif", s->dim == 2, &out->gif) ||
            get_bool(c, o, "outputs", "summary", 1, &out->summary))
            return -1;
        if (!*dir)
            return bad(c, "outputs.dir", "is empty");
        if (out->xyz_every < 0)
            return bad(c, "outputs.xyz_every", "must be >= 0 (0: no trajectory)");
        if (out->xyz_every > 0 && (s->t_end - s->time) / out->xyz_every > SCN_MAX_FRAMES)
            return bad(c, "outputs.xyz_every", "gives %.3g frames from %g to %g, more than %d",
                       (s->t_end - s->time) / out->xyz_every, s->time, s->t_end,
                       SCN_MAX_FRAMES);
        if (out->h5md_every < 0)
            return bad(c, "outputs.h5md_every", "must be >= 0 (0: no H5MD trajectory)");
        if (out->h5md_every > 0 && (s->t_end - s->time) / out->h5md_every > SCN_MAX_FRAMES)
            return bad(c, "outputs.h5md_every", "gives %.3g frames from %g to %g, more than %d",
                       (s->t_end - s->time) / out->h5md_every, s->time, s->t_end,
                       SCN_MAX_FRAMES);
        if (parse_h5md(c, cJSON_GetObjectItemCaseSensitive(o, "h5md"), s))
            return -1;
        if (!(out->xyz_from <= s->time))
            return bad(c, "outputs.xyz_from", "must be <= the start time %.17g (the grid's "
                       "origin)", s->time);
        if (out->gif && s->dim != 2)
            return bad(c, "outputs.gif", "the animated table is for 2-D runs");
        const cJSON *sn = cJSON_GetObjectItemCaseSensitive(o, "snapshots");
        if (sn && cJSON_IsArray(sn)) {
            int i = 0;
            for (const cJSON *e = sn->child; e; e = e->next, i++) {
                char p[64];
                snprintf(p, sizeof p, "outputs.snapshots[%d]", i);
                if (i >= SCN_MAX_SNAPSHOTS)
                    return bad(c, p, "more than %d snapshots", SCN_MAX_SNAPSHOTS);
                if (!cJSON_IsNumber(e) || !isfinite(e->valuedouble))
                    return bad(c, p, "must be a finite number");
                if (e->valuedouble < s->time || e->valuedouble > s->t_end)
                    return bad(c, p, "time %g is outside the run [%g, %g]", e->valuedouble,
                               s->time, s->t_end);
                out->snap[out->n_snap++] = e->valuedouble;
            }
            qsort(out->snap, out->n_snap, sizeof out->snap[0], cmp_double);
        } else if (sn && cJSON_IsObject(sn)) {
            static const char *const ek[] = {"every", NULL};
            if (only_keys(c, sn, "outputs.snapshots", ek))
                return -1;
            double every = 0;
            if (get_num(c, sn, "outputs.snapshots", "every", 1, 0, 0, &every))
                return -1;
            if (!(every > 0))
                return bad(c, "outputs.snapshots.every", "must be > 0");
            double span = s->t_end - s->time;
            if (span / every > SCN_MAX_SNAPSHOTS)
                return bad(c, "outputs.snapshots.every", "gives more than %d snapshots",
                           SCN_MAX_SNAPSHOTS);
            /* (the count bounded too: near a large t_end the tolerance may admit more
             * steps than span / every) */
            const double lim = s->t_end + fabs(s->t_end) * 1e-15;
            for (size_t k = 1; out->n_snap < SCN_MAX_SNAPSHOTS && s->time + every * (double)k <= lim;
                 k++)
                out->snap[out->n_snap++] = fmin(s->time + every * (double)k, s->t_end);
        } else if (sn) {
            return bad(c, "outputs.snapshots", "must be an array of times or {\"every\": dt}");
        }
    }
    out->dir = strdup(dir);
    return out->dir ? 0 : bad(c, "outputs.dir", "out of memory");
}

int scn_parse(const char *text, const char *name, scn_scenario *s, char *err)
{
    return scn_parse_ext(text, name, NULL, s, err);
}

/* The line and column (from 1) of at in text. */
static void line_col(const char *text, const char *at, long *line, long *col)
{
    *line = 1;
    *col = 1;
    for (const char *p = text; p < at; p++, (*col)++)
        if (*p == '\n') {
            (*line)++;
            *col = 0;
        }
}

/* The first \u0000 escape inside a JSON string (a key or a value), or NULL: cJSON decodes
 * it to a NUL and so cuts the string there ("zmf\u0000x" would read as "zmf"). */
static const char *nul_escape(const char *text)
{
    int in_str = 0;
    for (const char *p = text; *p; p++) {
        if (!in_str) {
            in_str = *p == '"';
        } else if (*p == '"') {
            in_str = 0;
        } else if (*p == '\\') {
            if (p[1] == 'u' && strncmp(p + 2, "0000", 4) == 0)
                return p;
            if (p[1])
                p++;
        }
    }
    return NULL;
}

/* gravity: {"g": g > 0, "coupling": "newtonian" | "equivalence"}; the field points along
 * -z (the last axis), whose boundary must be walls (its floor and ceiling) */
static int parse_gravity(const ctx *c, const cJSON *v, scn_scenario *s)
{
    static const char *const gk[] = {"g", "coupling", NULL};
    if (!cJSON_IsObject(v))
        return bad(c, "gravity", "must be an object {\"g\": g, \"coupling\": "
                   "\"newtonian\" or \"equivalence\"}");
    double g = 0;
    const char *name = NULL;
    if (only_keys(c, v, "gravity", gk) || get_num(c, v, "gravity", "g", 1, 0, 0, &g) ||
        get_str(c, v, "gravity", "coupling", NULL, &name))
        return -1;
    if (!(g > 0))
        return bad(c, "gravity.g", "must be > 0 (the acceleration at the floor z = 0)");
    if (!name)
        return bad(c, "gravity.coupling", "is required: \"newtonian\" or \"equivalence\"");
    if (!(s->gravity = rc_gravity_find(name)))
        return bad(c, "gravity.coupling", "unknown coupling '%s' (expected newtonian or "
                   "equivalence)", name);
    if (s->boundary[s->dim - 1] == RC_SIM_PERIODIC)
        return bad(c, "gravity", "the field's axis (%s, the last) must have walls, its floor "
                   "and ceiling: boundary is periodic there", s->dim == 3 ? "z" : "y");
    s->g = g;
    return 0;
}

int scn_parse_ext(const char *text, const char *name, const scn_tables *extra,
                  scn_scenario *s, char *err)
{
    static const char *const keys[] = {"relcol", "dim", "box", "boundary", "walls", "c", "law",
                                       "restitution", "contact_frame", "groups", "tc", "seed",
                                       "time", "gravity",
                                       "t_end", "restart", "checkpoint", "balls", "generate",
                                       "outputs", NULL};
    memset(s, 0, sizeof *s);
    ctx c = {name, err};
    /* a UTF-8 byte order mark (editors and spreadsheets write one) is not JSON: skipped */
    const char *body = strncmp(text, "\xef\xbb\xbf", 3) == 0 ? text + 3 : text;
    const char *nul = nul_escape(body);
    if (nul) {
        long line, col;
        line_col(text, nul, &line, &col);
        bad(&c, "(document)", "line %ld, column %ld: a string holds \\u0000 (a NUL "
            "character), which no key, name or path can contain", line, col);
        return -1;
    }
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithOpts(body, &end, 0);
    int rc = -1;
    if (root && end) {
        /* one scenario a file: text after it (a second object, a stray word) is refused,
         * not silently dropped */
        while (*end == ' ' || *end == '\t' || *end == '\n' || *end == '\r')
            end++;
        if (*end) {
            long line, col;
            line_col(text, end, &line, &col);
            bad(&c, "(document)", "text after the scenario's closing brace at line %ld, "
                "column %ld", line, col);
            goto done;
        }
    }
    if (!root) {
        const char *where = cJSON_GetErrorPtr();
        long line = 1;
        for (const char *p = text; where && p < where; p++)
            line += *p == '\n';
        bad(&c, "(document)", "malformed JSON near line %ld", line);
        goto done;
    }
    if (!cJSON_IsObject(root)) {
        bad(&c, "(document)", "must be a JSON object");
        goto done;
    }
    if (only_keys(&c, root, "", keys))
        goto done;
    double ver = 1, dim = 0, eps_b = 1, eps_w = 1, seed = 1;
    if (get_num(&c, root, "", "relcol", 0, 1, 0, &ver) || get_num(&c, root, "", "dim", 1, 0, 0, &dim))
        goto done;
    if (ver != 1) {
        bad(&c, "relcol", "unsupported scenario format version %g (this relcol reads 1)", ver);
        goto done;
    }
    if (dim != 2 && dim != 3) {
        bad(&c, "dim", "must be 2 or 3");
        goto done;
    }
    s->dim = (int)dim;
    const cJSON *jbnd = cJSON_GetObjectItemCaseSensitive(root, "boundary");
    if (jbnd && parse_boundary(&c, jbnd, s))
        goto done;
    const cJSON *jwalls = cJSON_GetObjectItemCaseSensitive(root, "walls");
    if (jwalls && parse_walls(&c, jwalls, s))
        goto done;
    if (get_num(&c, root, "", "c", 0, INFINITY, 1, &s->c))
        goto done;
    if (!(s->c > 0)) {
        bad(&c, "c", "must be > 0 (or \"inf\")");
        goto done;
    }
    const char *law = NULL;
    if (get_str(&c, root, "", "law", "zmf", &law))
        goto done;
    if (!(s->law = find_law(extra, law))) {
        char list[256];
        bad(&c, "law", "unknown collision law '%s' (expected %s)", law,
            name_list(extra, 0, list, sizeof list));
        goto done;
    }
    const cJSON *rest = cJSON_GetObjectItemCaseSensitive(root, "restitution");
    if (rest) {
        static const char *const rk[] = {"ball", "wall", NULL};
        if (!cJSON_IsObject(rest)) {
            bad(&c, "restitution", "must be an object {\"ball\": e, \"wall\": e}");
            goto done;
        }
        if (only_keys(&c, rest, "restitution", rk) ||
            get_num(&c, rest, "restitution", "ball", 0, 1, 0, &eps_b) ||
            get_num(&c, rest, "restitution", "wall", 0, 1, 0, &eps_w))
            goto done;
        if (!(eps_b >= 0 && eps_b <= 1)) {
            bad(&c, "restitution.ball", "must be in [0, 1]");
            goto done;
        }
        if (!(eps_w >= 0 && eps_w <= 1)) {
            bad(&c, "restitution.wall", "must be in [0, 1]");
            goto done;
        }
    }
    s->eps_ball = eps_b;
    s->eps_wall = eps_w;
    const cJSON *jgrav = cJSON_GetObjectItemCaseSensitive(root, "gravity");
    if (jgrav && parse_gravity(&c, jgrav, s))
        goto done;
    const char *frame = NULL;
    /* (in a field the default frame is the one-instant sphere: papers/gravity.md) */
    if (get_str(&c, root, "", "contact_frame", s->gravity ? "sphere" : "table", &frame))
        goto done;
    if (!(s->frame = find_frame(extra, frame))) {
        char list[256];
        bad(&c, "contact_frame", "unknown frame '%s' (expected %s)", frame,
            name_list(extra, 1, list, sizeof list));
        goto done;
    }
    for (int w = 0; w < 6; w++)
        if (s->wall_rule[w] && !s->wall_rule[w]->rigid && s->frame->per_ball) {
            char p[32];
            snprintf(p, sizeof p, "walls.%s", scn_wall_names[w]);
            bad(&c, p, "a %s wall cannot go with contact_frame '%s' (its rollbacks would take "
                "back the wall's draws)", s->wall_rule[w]->name, s->frame->name);
            goto done;
        }
    if (s->gravity && (s->frame->contracted || s->frame->pointlike || s->frame->per_ball ||
                       s->frame->wall_contracted)) {
        bad(&c, "contact_frame", "frame '%s' is not defined in a field (the field takes "
            "one-instant uncontracted frames: sphere; papers/gravity.md, model limits)", frame);
        goto done;
    }
    for (int w = 0; w < 6 && s->gravity; w++)
        if (s->wall_rule[w] && s->wall_rule[w] != &rc_wall_reflecting) {
            char p[32];
            snprintf(p, sizeof p, "walls.%s", scn_wall_names[w]);
            bad(&c, p, "a %s wall in a field is not built (the field's walls are reflecting; "
                "papers/gravity.md, model limits)", s->wall_rule[w]->name);
            goto done;
        }
    const char *groups = NULL;
    if (get_str(&c, root, "", "groups", "simultaneous", &groups))
        goto done;
    if ((s->groups = rc_group_rule_find(groups)) < 0) {
        char list[128] = "";
        for (int r = 0; rc_group_rule_name(r); r++)
            snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", r ? ", " : "",
                     rc_group_rule_name(r));
        bad(&c, "groups", "unknown rule for simultaneous contacts '%s' (expected %s)", groups,
            list);
        goto done;
    }
    if (get_num(&c, root, "", "tc", 0, 0, 0, &s->t_c) || get_num(&c, root, "", "seed", 0, 1, 0, &seed) ||
        get_num(&c, root, "", "time", 0, 0, 0, &s->time) ||
        get_num(&c, root, "", "t_end", 1, 0, 0, &s->t_end))
        goto done;
    if (s->t_c < 0) {
        bad(&c, "tc", "must be >= 0 (0: no collapse protection)");
        goto done;
    }
    if (!(seed >= 0 && seed <= 9007199254740992.0 && seed == floor(seed))) {
        bad(&c, "seed", "must be a whole number in [0, 2^53]");
        goto done;
    }
    s->seed = (uint64_t)seed;
    if (get_bool(&c, root, "", "restart", 0, &s->restart))
        goto done;
    const char *ck = NULL;
    if (get_str(&c, root, "", "checkpoint", NULL, &ck))
        goto done;
    if (ck) {
        if (!*ck || strchr(ck, '/')) {
            bad(&c, "checkpoint", "must be a file name beside the scenario (no folder)");
            goto done;
        }
        if (!s->restart) {
            bad(&c, "checkpoint", "belongs to a restart file (\"restart\": true)");
            goto done;
        }
        if (!(s->checkpoint = strdup(ck))) {
            bad(&c, "checkpoint", "out of memory");
            goto done;
        }
    }
    if (!(s->t_end > s->time)) {
        bad(&c, "t_end", "must be later than the start time %g", s->time);
        goto done;
    }
    const cJSON *jbox = cJSON_GetObjectItemCaseSensitive(root, "box");
    const cJSON *jballs = cJSON_GetObjectItemCaseSensitive(root, "balls");
    const cJSON *jgen = cJSON_GetObjectItemCaseSensitive(root, "generate");
    if (jballs && jgen) {
        bad(&c, "generate", "give either balls or generate, not both");
        goto done;
    }
    if (!jballs && !jgen) {
        bad(&c, "balls", "missing: give balls (a list) or generate (rack or gas)");
        goto done;
    }
    int gas = jgen && cJSON_IsObject(jgen) &&
              cJSON_IsString(cJSON_GetObjectItemCaseSensitive(jgen, "kind")) &&
              strcmp(cJSON_GetObjectItemCaseSensitive(jgen, "kind")->valuestring, "gas") == 0;
    if (!gas) {
        if (!jbox) {
            bad(&c, "box", "missing (required: %d edge lengths)", s->dim);
            goto done;
        }
        if (get_vec(&c, jbox, "box", s->dim, &s->box))
            goto done;
        for (int d = 0; d < s->dim; d++)
            if (!(rc_v3_get(s->box, d) > 0)) {
                bad(&c, "box", "edge %d must be > 0", d);
                goto done;
            }
    }
    if (jballs ? parse_balls(&c, jballs, s) : parse_generate(&c, jgen, jbox, s))
        goto done;
    if (check_periodic_room(&c, s))
        goto done;
    if (parse_outputs(&c, cJSON_GetObjectItemCaseSensitive(root, "outputs"), s))
        goto done;
    rc = 0;
done:
    cJSON_Delete(root);
    if (rc)
        scn_free(s);
    return rc;
}

int scn_load(const char *path, scn_scenario *s, char *err)
{
    return scn_load_ext(path, NULL, s, err);
}

int scn_load_ext(const char *path, const scn_tables *extra, scn_scenario *s, char *err)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        app_errf(err, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    for (;;) {
        if (!buf) {
            fclose(f);
            app_errf(err, "%s: out of memory", path);
            return -1;
        }
        n += fread(buf + n, 1, cap - n - 1, f);
        if (n < cap - 1)
            break;
        cap *= 2;
        char *nb = realloc(buf, cap);
        if (!nb)
            free(buf);
        buf = nb;
    }
    int rerr = ferror(f);
    fclose(f);
    if (rerr) {
        free(buf);
        app_errf(err, "%s: read error", path);
        return -1;
    }
    buf[n] = '\0';
    if (strlen(buf) != n) {
        free(buf);
        app_errf(err, "%s: (document): contains a NUL byte: not a JSON text file", path);
        return -1;
    }
    int rc = scn_parse_ext(buf, path, extra, s, err);
    free(buf);
    return rc;
}

int scn_builtin(const char *name, scn_scenario *s, char *err)
{
    /* Keep these identical to data/scenarios/{rack,gas}.json (a test compares them). */
    static const char rack[] =
        "{\"relcol\": 1, \"dim\": 2, \"box\": [2.54, 1.27], \"c\": \"inf\",\n"
        " \"restitution\": {\"ball\": 0.95, \"wall\": 0.8}, \"contact_frame\": \"table\",\n"
        " \"seed\": 1, \"t_end\": 4,\n"
        " \"generate\": {\"kind\": \"rack\", \"radius\": 0.028575, \"speed\": 5, \"aim\": 0.002},\n"
        " \"outputs\": {\"dir\": \"out/sim/rack\", \"snapshots\": {\"every\": 1}, \"xyz_every\": 0.02}}\n";
    static const char gas[] =
        "{\"relcol\": 1, \"dim\": 2, \"c\": 1, \"restitution\": {\"ball\": 1, \"wall\": 1},\n"
        " \"contact_frame\": \"table\", \"seed\": 1, \"t_end\": 200,\n"
        " \"generate\": {\"kind\": \"gas\", \"n\": 400, \"radius\": 1, \"packing\": 0.2,\n"
        "              \"v_rms\": 0.5},\n"
        " \"outputs\": {\"dir\": \"out/sim/gas\", \"snapshots\": {\"every\": 50}, \"xyz_every\": 1}}\n";
    if (strcmp(name, "rack") == 0)
        return scn_parse(rack, "builtin rack", s, err);
    if (strcmp(name, "gas") == 0)
        return scn_parse(gas, "builtin gas", s, err);
    app_errf(err, "unknown built-in scenario '%s' (expected rack or gas)", name);
    return -1;
}

rc_sim_def scn_sim_def(const scn_scenario *s)
{
    rc_sim_def def = rc_sim_def_default();
    def.dim = s->dim;
    def.box = s->box;
    def.c = s->c;
    def.eps_ball = s->eps_ball;
    def.eps_wall = s->eps_wall;
    def.t_c = s->t_c;
    def.law = s->law;
    def.restart = s->restart;
    def.frame = s->frame;
    def.groups = s->groups;
    for (int d = 0; d < 3; d++)
        def.boundary[d] = s->boundary[d];
    for (int w = 0; w < 6; w++) {
        def.wall_rule[w] = s->wall_rule[w];
        def.wall_kT[w] = s->wall_kT[w];
    }
    /* the walls' stream: the scenario's seed, hashed so that it is not the generator's
     * stream shifted (splitmix64 of seed ^ "thermal") */
    rc_rng r = {s->seed ^ 0x7468657266616cULL};
    def.wall_seed = rc_rng_next(&r);
    def.gravity = s->gravity;
    def.g = s->gravity ? s->g : 0.0;
    def.g_axis = -1;
    return def;
}

void scn_free(scn_scenario *s)
{
    free(s->balls);
    free(s->out.dir);
    free(s->checkpoint);
    memset(s, 0, sizeof *s);
}
