/* fuzz_jpeg.c: libFuzzer target for the JPEG reader behind textures and
 * raytrace-diff (jpeg.c), with a 64 MiB budget as --memory-limit would set:
 * an accepted image has a size that fits the budget, and its every pixel
 * can be read. */
#include <stdint.h>
#include <stdlib.h>

#include "image/jpeg.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const size_t budget = (size_t)64 << 20;
    JpegImage img;
    Error err;
    unsigned sum = 0;

    if (jpeg_parse("fuzz.jpg", data, size, budget, &img, &err) != 0)
        return 0;
    if (img.width < 1 || img.height < 1 || (img.channels != 1 && img.channels != 3) ||
        3 * (size_t)img.width * (size_t)img.height > budget)
        abort();
    for (size_t k = 0; k < 3 * (size_t)img.width * (size_t)img.height; k++)
        sum += img.rgb[k];
    jpeg_free(&img);
    return (int)(sum & 0); /* the loop reads every byte (ASan checks it) */
}
