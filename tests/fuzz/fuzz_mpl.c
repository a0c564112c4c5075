/* fuzz_mpl.c: libFuzzer target for the MPL ray tracer's scene format (mpl.c), its
 * texture files included (names resolve in the fuzzer's directory). */
#include "fuzz_scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fuzz_scene(data, size, SCENE_MPL);
}
