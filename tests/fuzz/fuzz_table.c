/* fuzz_table.c — libFuzzer harness for the apps' CSV reader and ball rows (apps/common:
 * app_table_read, app_balls_parse, app_balls_particles): any bytes must be read or refused
 * with a message, never crash or hang; accepted balls must be finite, m > 0, and at c = 1
 * either slower than light or refused. Built and run by scripts/fuzz.sh table. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "app.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *f = fmemopen((void *)data, size, "rb");
    if (!f)
        return 0;
    app_table t;
    char err[APP_ERR_LEN] = "";
    const int st = app_table_read(f, &t, err);
    fclose(f);
    if (st != 0) {
        if (!err[0]) {
            fprintf(stderr, "table refused without a message\n");
            abort();
        }
        return 0;
    }
    static const char *const extra[] = {"r", "name", NULL};
    app_balls b;
    err[0] = '\0';
    if (app_balls_parse(&t, extra, 0, &b, err) == 0) {
        rc_particle *p = malloc((b.n ? b.n : 1) * sizeof *p);
        for (size_t i = 0; i < b.n; i++)
            if (!(b.m[i] > 0.0 && isfinite(b.m[i]) && rc_v3_isfinite(b.q[i]) &&
                  rc_v3_isfinite(b.x[i]))) {
                fprintf(stderr, "ball %zu accepted with a bad number\n", i);
                abort();
            }
        err[0] = '\0';
        if (p && app_balls_particles(&b, 1.0, p, err) == 0) {
            for (size_t i = 0; i < b.n; i++) /* |v| < c = 1 */
                if (!(rc_v3_norm2(p[i].p) < INFINITY && rc_particle_check(&p[i]) == RC_OK)) {
                    fprintf(stderr, "ball %zu: state accepted that the library refuses\n", i);
                    abort();
                }
        } else if (p && !err[0]) {
            fprintf(stderr, "balls refused without a message\n");
            abort();
        }
        free(p);
        app_balls_free(&b);
    } else if (!err[0]) {
        fprintf(stderr, "ball rows refused without a message\n");
        abort();
    }
    app_table_free(&t);
    return 0;
}
