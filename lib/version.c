/* version.c — the library's own version string, fixed when it was built, so that a
 * program can tell the library it runs with from the headers it was compiled with. */
#include "relcol/version.h"

const char *rc_version(void)
{
    return RELCOL_VERSION;
}
