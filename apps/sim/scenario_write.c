/* scenario_write.c — a scenario written back as JSON (a run's final state is itself a
 * scenario: scn_write), and the folder a continued run writes into (scn_next_dir). Every
 * number is written with %.17g, so that reading it back gives the same bits. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* s as a JSON string: quotes, backslashes and control characters escaped (a folder name
 * may hold any of them; written raw, final.json would not read back). */
static void put_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\')
            fprintf(f, "\\%c", *p);
        else if (*p < 0x20)
            fprintf(f, "\\u%04x", *p);
        else
            fputc(*p, f);
    }
    fputc('"', f);
}

static void put_vec(FILE *f, rc_vec3 v, int dim)
{
    fputc('[', f);
    for (int d = 0; d < dim; d++)
        fprintf(f, "%s%.17g", d ? ", " : "", rc_v3_get(v, d));
    fputc(']', f);
}

int scn_write(FILE *f, const scn_scenario *s, double t, double t_end, size_t n,
              const rc_sim_ball *balls)
{
    fprintf(f, "{\"relcol\": 1, \"dim\": %d, \"box\": ", s->dim);
    put_vec(f, s->box, s->dim);
    int periodic = 0, mixed = 0;
    for (int d = 0; d < s->dim; d++) {
        periodic |= s->boundary[d] == RC_SIM_PERIODIC;
        mixed |= s->boundary[d] != s->boundary[0];
    }
    if (periodic && !mixed) /* (walls, the default, are not written) */
        fprintf(f, ", \"boundary\": \"periodic\"");
    for (int d = 0; periodic && mixed && d < s->dim; d++)
        fprintf(f, "%s\"%s\"%s", d ? ", " : ", \"boundary\": [",
                s->boundary[d] == RC_SIM_PERIODIC ? "periodic" : "walls",
                d + 1 < s->dim ? "" : "]");
    if (isinf(s->c))
        fprintf(f, ",\n \"c\": \"inf\"");
    else
        fprintf(f, ",\n \"c\": %.17g", s->c);
    fprintf(f, ", \"law\": \"%s\", \"restitution\": {\"ball\": %.17g, \"wall\": %.17g},\n",
            s->law->name, s->eps_ball, s->eps_wall);
    fprintf(f, " \"contact_frame\": \"%s\", \"tc\": %.17g, \"seed\": %llu,\n", s->frame->name, s->t_c,
            (unsigned long long)s->seed);
    fprintf(f, " \"time\": %.17g, \"t_end\": %.17g, \"restart\": true,\n", t, t_end);
    if (s->checkpoint) {
        fprintf(f, " \"checkpoint\": ");
        put_string(f, s->checkpoint);
        fprintf(f, ",\n");
    }
    fprintf(f, " \"outputs\": {\"dir\": ");
    put_string(f, s->out.dir);
    fprintf(f, ", \"xyz_every\": %.17g, \"plots\": %s, \"gif\": %s, \"summary\": %s",
            s->out.xyz_every, s->out.plots ? "true" : "false", s->out.gif ? "true" : "false",
            s->out.summary ? "true" : "false");
    if (s->out.h5md_every > 0)
        fprintf(f, ", \"h5md_every\": %.17g", s->out.h5md_every);
    if (s->out.xyz_every > 0 || s->out.h5md_every > 0)
        fprintf(f, ", \"xyz_from\": %.17g", s->out.xyz_from);
    /* the snapshot times still ahead (a run interrupted before them takes them along); at
     * the scenario's own start (--dump) one at t is ahead too, later it has been written */
    int first = 1;
    for (size_t k = 0; k < s->out.n_snap; k++)
        if ((s->out.snap[k] > t || (t == s->time && s->out.snap[k] == t)) &&
            s->out.snap[k] <= t_end) {
            fprintf(f, "%s%.17g", first ? ",\n  \"snapshots\": [" : ", ", s->out.snap[k]);
            first = 0;
        }
    fprintf(f, "%s},\n", first ? "" : "]");
    fprintf(f, " \"balls\": [\n");
    for (size_t i = 0; i < n; i++) {
        fprintf(f, "  {\"r\": %.17g, \"m\": %.17g, \"tau\": %.17g, ", balls[i].r, balls[i].m,
                balls[i].tau);
        if (balls[i].collided)
            fprintf(f, "\"tau_last\": %.17g, ", balls[i].tau_last);
        fprintf(f, "\"x\": ");
        put_vec(f, balls[i].x, s->dim);
        fprintf(f, ", \"p\": ");
        put_vec(f, balls[i].p, s->dim);
        if (periodic) /* (the wraps: x + image L is the unwrapped position) */
            fprintf(f, ", \"image\": [%d, %d%s", (int)balls[i].image[0], (int)balls[i].image[1],
                    s->dim == 3 ? "" : "]");
        if (periodic && s->dim == 3)
            fprintf(f, ", %d]", (int)balls[i].image[2]);
        fprintf(f, "}%s\n", i + 1 < n ? "," : "");
    }
    fprintf(f, " ]}\n");
    return ferror(f) ? -1 : 0;
}
