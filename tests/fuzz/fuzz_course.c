/* fuzz_course.c: libFuzzer target for the course format (parse.c). */
#include "fuzz_scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fuzz_scene(data, size, SCENE_COURSE);
}
