/*
 * replay.c: runs a fuzz target's LLVMFuzzerTestOneInput on each file named
 * on the command line, without libFuzzer, so that `make test` replays the
 * corpora and every input a fuzzer ever crashed on (tests/fuzz/regress)
 * with the ordinary compiler, and under the sanitizers in CI.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        char *data;
        size_t len;
        Error err;
        if (file_read_all(argv[i], &data, &len, &err) != 0) {
            fprintf(stderr, "replay: %s: %s\n", err.file, err.message);
            return 2;
        }
        LLVMFuzzerTestOneInput((const uint8_t *)data, len);
        free(data);
    }
    printf("replay: %d input%s, no crash\n", argc - 1, argc == 2 ? "" : "s");
    return 0;
}
