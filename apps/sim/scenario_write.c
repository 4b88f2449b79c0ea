/* scenario_write.c — a scenario written back as JSON (a run's final state is itself a
 * scenario: scn_write), and the folder a continued run writes into (scn_next_dir). Written
 * by cJSON's printer; every number with %.17g, so that reading it back gives the same bits. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "scenario.h"

char *scn_next_dir(const char *dir)
{
    size_t len = strlen(dir);
    while (len > 1 && dir[len - 1] == '/') /* (a trailing slash names the same folder) */
        len--;
    /* a trailing ".K" (K a whole number >= 1, no leading zero) is this folder's number */
    size_t dot = len;
    while (dot > 0 && dir[dot - 1] >= '0' && dir[dot - 1] <= '9')
        dot--;
    unsigned long long k = 0;
    int numbered = dot > 1 && dot < len && dir[dot - 1] == '.' && dir[dot] != '0' &&
                   len - dot <= 9 && dir[dot - 2] != '/';
    if (numbered)
        k = strtoull(dir + dot, NULL, 10);
    const size_t base = numbered ? dot - 1 : len;
    char *out = malloc(base + 24);
    if (out)
        snprintf(out, base + 24, "%.*s.%llu", (int)base, dir, k + 1);
    return out;
}

/* A double as JSON that reads back to the same bits: %.17g, raw. cJSON's own printer does
 * not: it keeps its 15-digit form whenever that reads back within an epsilon of the value
 * (0.1 + 0.2 comes out 0.3), and prints -0 as 0 (a ball's momentum of -0 must come back as
 * -0 for the checkpoint to match it). */
static cJSON *scn_json_number(double x)
{
    char b[32];
    snprintf(b, sizeof b, "%.17g", x);
    return cJSON_CreateRaw(b);
}

static cJSON *vec(rc_vec3 v, int dim)
{
    cJSON *a = cJSON_CreateArray();
    for (int d = 0; a && d < dim; d++)
        cJSON_AddItemToArray(a, scn_json_number(rc_v3_get(v, d)));
    return a;
}

static void put(cJSON *o, const char *key, cJSON *item) { cJSON_AddItemToObject(o, key, item); }

static void put_num(cJSON *o, const char *key, double x) { put(o, key, scn_json_number(x)); }

/* (cJSON_Add... on an object that failed to allocate is a no-op: a missing piece is found
 * by the print that fails) */
static cJSON *header(const scn_scenario *s, double t, double t_end, int periodic, int mixed)
{
    cJSON *j = cJSON_CreateObject(), *x;
    char b[32];
    put(j, "relcol", cJSON_CreateRaw("1"));
    snprintf(b, sizeof b, "%d", s->dim);
    put(j, "dim", cJSON_CreateRaw(b));
    put(j, "box", vec(s->box, s->dim));
    if (periodic && !mixed) /* (walls, the default, are not written) */
        put(j, "boundary", cJSON_CreateString("periodic"));
    if (periodic && mixed) {
        put(j, "boundary", x = cJSON_CreateArray());
        for (int d = 0; x && d < s->dim; d++)
            cJSON_AddItemToArray(x, cJSON_CreateString(s->boundary[d] == RC_SIM_PERIODIC
                                                           ? "periodic" : "walls"));
    }
    int ruled = 0; /* (hard walls, the default, are not written) */
    for (int w = 0; w < 6; w++)
        ruled |= s->wall_rule[w] != NULL;
    if (ruled) {
        put(j, "walls", x = cJSON_CreateObject());
        for (int w = 0; x && w < 2 * s->dim; w++) {
            const rc_wall_rule *r = s->wall_rule[w];
            if (!r)
                continue;
            cJSON *e = cJSON_CreateObject();
            put(x, scn_wall_names[w], e);
            put(e, "rule", cJSON_CreateString(r->name));
            if (r->temperature)
                put_num(e, "kT", s->wall_kT[w]);
        }
    }
    put(j, "c", isinf(s->c) ? cJSON_CreateString("inf") : scn_json_number(s->c));
    put(j, "law", cJSON_CreateString(s->law->name));
    put(j, "restitution", x = cJSON_CreateObject());
    put_num(x, "ball", s->eps_ball);
    put_num(x, "wall", s->eps_wall);
    put(j, "contact_frame", cJSON_CreateString(s->frame->name));
    if (s->gravity) { /* (the field, so that a continued run has it) */
        cJSON *gv;
        put(j, "gravity", gv = cJSON_CreateObject());
        put_num(gv, "g", s->g);
        put(gv, "coupling", cJSON_CreateString(s->gravity->name));
    }
    put(j, "groups", cJSON_CreateString(rc_group_rule_name(s->groups)));
    put_num(j, "tc", s->t_c);
    snprintf(b, sizeof b, "%llu", (unsigned long long)s->seed); /* (all 64 bits) */
    put(j, "seed", cJSON_CreateRaw(b));
    put_num(j, "time", t);
    put_num(j, "t_end", t_end);
    put(j, "restart", cJSON_CreateTrue());
    if (s->checkpoint)
        put(j, "checkpoint", cJSON_CreateString(s->checkpoint));
    put(j, "outputs", x = cJSON_CreateObject());
    put(x, "dir", cJSON_CreateString(s->out.dir));
    put_num(x, "xyz_every", s->out.xyz_every);
    if (s->out.h5md_every > 0)
        put_num(x, "h5md_every", s->out.h5md_every);
    if (s->out.h5md_every > 0) { /* (the choice of elements, when it is not the default) */
        unsigned all = (1u << SCN_H5MD_N) - 1u;
        int periodic = 0;
        for (int d = 0; d < s->dim; d++)
            periodic |= s->boundary[d] == RC_SIM_PERIODIC;
        if (!periodic)
            all &= ~(1u << SCN_H5MD_IMAGE);
        if (s->out.h5md_fields != all || s->out.h5md_float32 || !s->out.h5md_scenario) {
            cJSON *h = cJSON_CreateObject(), *f = h ? cJSON_CreateArray() : NULL;
            put(x, "h5md", h);
            if (f)
                put(h, "fields", f);
            for (int e = 0; f && e < SCN_H5MD_N; e++)
                if (s->out.h5md_fields >> e & 1u)
                    cJSON_AddItemToArray(f, cJSON_CreateString(scn_h5md_names[e]));
            if (h)
                put(h, "precision", cJSON_CreateString(s->out.h5md_float32 ? "float32"
                                                                            : "float64"));
            if (h)
                put(h, "scenario", cJSON_CreateBool(s->out.h5md_scenario));
        }
    }
    if (s->out.xyz_every > 0 || s->out.h5md_every > 0)
        put_num(x, "xyz_from", s->out.xyz_from);
    put(x, "plots", cJSON_CreateBool(s->out.plots));
    put(x, "gif", cJSON_CreateBool(s->out.gif));
    put(x, "summary", cJSON_CreateBool(s->out.summary));
    /* the snapshot times still ahead (a run interrupted before them takes them along); at
     * the scenario's own start (--dump) one at t is ahead too, later it has been written */
    cJSON *sn = NULL;
    for (size_t k = 0; k < s->out.n_snap; k++)
        if ((s->out.snap[k] > t || (t == s->time && s->out.snap[k] == t)) &&
            s->out.snap[k] <= t_end) {
            if (!sn)
                put(x, "snapshots", sn = cJSON_CreateArray());
            if (sn)
                cJSON_AddItemToArray(sn, scn_json_number(s->out.snap[k]));
        }
    return j;
}

/* One ball, printed straight into f: the bytes cJSON_PrintUnformatted made of the ball's
 * object of raw %.17g numbers (so -0 stays -0 and every double reads back to its bits),
 * without a tree of a dozen nodes and as many strings per ball (at 1e5 balls that tree
 * cost several times the printing). Keys in the order the reader names them. */
static void put_vec(FILE *f, const char *key, rc_vec3 v, int dim)
{
    fprintf(f, ",\"%s\":[", key);
    for (int d = 0; d < dim; d++)
        fprintf(f, d ? ",%.17g" : "%.17g", rc_v3_get(v, d));
    putc(']', f);
}

static void ball(FILE *f, const rc_sim_ball *b, int dim, int periodic)
{
    fprintf(f, "{\"r\":%.17g,\"m\":%.17g,\"tau\":%.17g", b->r, b->m, b->tau);
    if (b->collided)
        fprintf(f, ",\"tau_last\":%.17g", b->tau_last);
    put_vec(f, "x", b->x, dim);
    put_vec(f, "p", b->p, dim);
    if (periodic) { /* (the wraps: x + image L is the unwrapped position) */
        fputs(",\"image\":[", f);
        for (int d = 0; d < dim; d++)
            fprintf(f, d ? ",%d" : "%d", (int)b->image[d]);
        putc(']', f);
    }
    putc('}', f);
}

/* The header printed by cJSON (strings escaped by it, numbers as scn_json_number); the
 * balls streamed one a line by ball(), which holds only numbers, so a million balls make
 * no tree at all. */
int scn_write(FILE *f, const scn_scenario *s, double t, double t_end, size_t n,
              const rc_sim_ball *balls)
{
    int periodic = 0, mixed = 0;
    for (int d = 0; d < s->dim; d++) {
        periodic |= s->boundary[d] == RC_SIM_PERIODIC;
        mixed |= s->boundary[d] != s->boundary[0];
    }
    cJSON *h = header(s, t, t_end, periodic, mixed);
    char *text = h ? cJSON_PrintUnformatted(h) : NULL;
    cJSON_Delete(h);
    size_t len = text ? strlen(text) : 0;
    if (len < 2 || text[len - 1] != '}') { /* (out of memory) */
        free(text);
        return -1;
    }
    text[len - 1] = '\0'; /* the balls go inside the object */
    fprintf(f, "%s,\n \"balls\": [\n", text);
    free(text);
    for (size_t i = 0; i < n; i++) {
        fputs("  ", f);
        ball(f, &balls[i], s->dim, periodic);
        fputs(i + 1 < n ? ",\n" : "\n", f);
    }
    fprintf(f, " ]}\n");
    return ferror(f) ? -1 : 0;
}
