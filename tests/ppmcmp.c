/*
 * ppmcmp.c: compares two PPM images channel by channel.
 *
 * Usage: ppmcmp [--max-diff N] [--max-fraction F] REFERENCE IMAGE
 * A channel "differs" when its values are more than N levels apart
 * (default 0). Prints the size, the largest difference with its pixel and
 * both values, and the count of differing channels; exits 0 when at most a
 * fraction F of all channels differ (default 0), 1 when more do, 2 when an
 * image cannot be read or the two have different sizes.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ppm.h"

static int ppmcmp_usage(void)
{
    fprintf(stderr, "usage: ppmcmp [--max-diff N] [--max-fraction F] REFERENCE IMAGE\n");
    return 2;
}

int main(int argc, char **argv)
{
    long max_diff = 0;
    double max_fraction = 0;
    const char *paths[2];
    int npaths = 0, worst = 0;
    size_t worst_at = 0, over = 0, count;
    PpmImage a, b;
    Error err;

    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--max-diff") == 0 && i + 1 < argc)
            max_diff = strtol(argv[++i], NULL, 10);
        else if (strcmp(argv[i], "--max-fraction") == 0 && i + 1 < argc)
            max_fraction = strtod(argv[++i], NULL);
        else if (argv[i][0] == '-' || npaths == 2)
            return ppmcmp_usage();
        else
            paths[npaths++] = argv[i];
    }
    if (npaths != 2)
        return ppmcmp_usage();
    for (int k = 0; k < 2; k++) {
        if (ppm_read(paths[k], k ? &b : &a, &err) != 0) {
            if (err.line)
                fprintf(stderr, "ppmcmp: %s:%d:%d: %s\n", err.file, err.line, err.column,
                        err.message);
            else
                fprintf(stderr, "ppmcmp: %s: %s\n", err.file, err.message);
            if (k)
                ppm_free(&a);
            return 2;
        }
    }
    if (a.width != b.width || a.height != b.height || a.maxval != b.maxval) {
        fprintf(stderr, "ppmcmp: size mismatch: %s is %d x %d (maxval %d), %s is %d x %d (maxval %d)\n",
                paths[0], a.width, a.height, a.maxval, paths[1], b.width, b.height, b.maxval);
        ppm_free(&a);
        ppm_free(&b);
        return 2;
    }
    count = 3 * (size_t)a.width * (size_t)a.height;
    for (size_t k = 0; k < count; k++) {
        int d = abs((int)a.samples[k] - (int)b.samples[k]);
        if (d > worst) {
            worst = d;
            worst_at = k;
        }
        over += d > max_diff;
    }
    printf("%d x %d; largest difference %d", a.width, a.height, worst);
    if (worst > 0)
        printf(" at pixel (%zu, %zu) channel %zu: %d vs %d", worst_at / 3 % (size_t)a.width,
               worst_at / 3 / (size_t)a.width, worst_at % 3, a.samples[worst_at],
               b.samples[worst_at]);
    printf("; %zu of %zu channels (%.4f%%) differ by more than %ld\n", over, count,
           100.0 * (double)over / (double)count, max_diff);
    ppm_free(&a);
    ppm_free(&b);
    return (double)over <= max_fraction * (double)count ? 0 : 1;
}
