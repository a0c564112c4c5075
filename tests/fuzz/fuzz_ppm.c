/* fuzz_ppm.c: libFuzzer target for the PPM reader behind textures (ppm.c):
 * an accepted image has every sample within its maxval. */
#include <stdint.h>
#include <stdlib.h>

#include "image/ppm.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    PpmImage img;
    Error err;

    if (ppm_parse("fuzz.ppm", (const char *)data, size, &img, &err) != 0)
        return 0;
    for (size_t k = 0; k < 3 * (size_t)img.width * (size_t)img.height; k++)
        if (img.samples[k] > img.maxval)
            abort();
    ppm_free(&img);
    return 0;
}
