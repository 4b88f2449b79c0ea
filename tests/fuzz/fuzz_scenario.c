/* fuzz_scenario.c — libFuzzer harness for relcol-sim's scenario reader (apps/sim/
 * scenario.c): any byte string must be parsed or refused with a message, never crash,
 * hang or leak (issue 4: "every malformed or impossible scenario is rejected with the path
 * of the offending value and the reason"); what it accepts must write back and read again
 * (a run's final state is itself a scenario). Built and run by scripts/fuzz.sh scenario. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "scenario.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    scn_scenario s;
    char err[APP_ERR_LEN];
    if (scn_parse(text, "fuzz", &s, err) == 0) {
        /* accepted: it must survive a write and a read back (up to 10^4 balls: a valid
         * gas of 10^5 or more is only slow to write and read under the sanitizers) */
        if (s.n > 10000) {
            scn_free(&s);
            free(text);
            return 0;
        }
        char *buf = NULL;
        size_t len = 0;
        FILE *f = open_memstream(&buf, &len);
        if (f) {
            const int wst = scn_write(f, &s, s.time, s.t_end, s.n, s.balls);
            fclose(f);
            scn_scenario back;
            if (wst == 0) {
                if (scn_parse(buf, "fuzz-written", &back, err) != 0) {
                    fprintf(stderr, "written scenario refused: %s\n", err);
                    abort();
                }
                scn_free(&back);
            }
            free(buf);
        }
        scn_free(&s);
    } else if (err[0] == '\0') {
        fprintf(stderr, "refused without a message\n");
        abort();
    }
    free(text);
    return 0;
}
