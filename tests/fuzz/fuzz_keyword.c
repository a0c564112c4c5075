/* fuzz_keyword.c: libFuzzer target for the keyword format (keyword.c), its
 * mesh and texture lines included (paths resolve in the fuzzer's directory). */
#include "fuzz_scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fuzz_scene(data, size, SCENE_KEYWORD);
}
