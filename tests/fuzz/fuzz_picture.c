/* fuzz_picture.c: libFuzzer target for raytrace-diff's image readers
 * (compare.c: PPM, PFM, PNG and the inflater behind it). */
#include <stdint.h>

#include "image/compare.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Picture pic;
    Error err;

    if (picture_parse("fuzz", (const char *)data, size, &pic, &err) == 0) {
        Comparison c = compare_pictures(&pic, &pic, 0);
        (void)c;
        picture_free(&pic);
    }
    return 0;
}
