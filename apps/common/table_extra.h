/* table_extra.h — small additions to the app_table reader (apps/common/app.h): a column
 * with one constant value appended to a table, for optional columns with a default. */
#ifndef RELCOL_TABLE_EXTRA_H
#define RELCOL_TABLE_EXTRA_H

#include "app.h"

/* Append column `name` holding `value` in every row (the table stays freeable with
 * app_table_free). 0 on success, -1 (out of memory, or the column exists) with err. */
int app_table_add_const_col(app_table *t, const char *name, const char *value, char *err);

#endif
