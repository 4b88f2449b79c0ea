/* table_extra.c — append a constant column to an app_table: how an app gives an optional
 * input column (e.g. m for velocity input, where only v matters) its default. */
#include <stdlib.h>
#include <string.h>

#include "table_extra.h"

int app_table_add_const_col(app_table *t, const char *name, const char *value, char *err)
{
    if (app_table_col(t, name) >= 0) {
        app_errf(err, "column %s already present", name);
        return -1;
    }
    const int nc = t->ncols + 1;
    char **names = realloc(t->names, (size_t)nc * sizeof *names);
    if (!names) {
        app_errf(err, "out of memory");
        return -1;
    }
    t->names = names;
    names[nc - 1] = strdup(name);
    char **cells = calloc(t->nrows * (size_t)nc + 1, sizeof *cells);
    if (!names[nc - 1] || !cells) {
        free(names[nc - 1]);
        free(cells);
        app_errf(err, "out of memory");
        return -1;
    }
    for (size_t r = 0; r < t->nrows; r++) {
        for (int c = 0; c < t->ncols; c++)
            cells[r * (size_t)nc + (size_t)c] = t->cells[r * (size_t)t->ncols + (size_t)c];
        cells[r * (size_t)nc + (size_t)t->ncols] = strdup(value);
        if (!cells[r * (size_t)nc + (size_t)t->ncols]) {
            for (size_t q = 0; q < r; q++)
                free(cells[q * (size_t)nc + (size_t)t->ncols]);
            free(cells);
            free(names[nc - 1]);
            app_errf(err, "out of memory");
            return -1;
        }
    }
    free(t->cells);
    t->cells = cells;
    t->ncols = nc;
    return 0;
}
