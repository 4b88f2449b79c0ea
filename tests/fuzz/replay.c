/* replay.c — runs the fuzz harness (fuzz_scenario.c) on given files without libFuzzer:
 * the seed scenarios and every input fuzzing once broke (tests/fuzz/regress/) replay in
 * the test suite, so the harness keeps compiling and old failures stay fixed. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        FILE *f = fopen(argv[i], "rb");
        if (!f) {
            fprintf(stderr, "replay: cannot open %s\n", argv[i]);
            return 2;
        }
        uint8_t *buf = NULL;
        size_t n = 0, cap = 0, got;
        do {
            if (n == cap) {
                cap = cap ? 2 * cap : 4096;
                uint8_t *nb = realloc(buf, cap);
                if (!nb) {
                    fprintf(stderr, "replay: out of memory reading %s\n", argv[i]);
                    free(buf);
                    fclose(f);
                    return 2;
                }
                buf = nb;
            }
            got = fread(buf + n, 1, cap - n, f);
            n += got;
        } while (got > 0);
        fclose(f);
        LLVMFuzzerTestOneInput(buf, n); /* (aborts on a failure) */
        free(buf);
        printf("ok: %s\n", argv[i]);
    }
    return 0;
}
