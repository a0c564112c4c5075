/* fuzz_obj.c: libFuzzer target for the Wavefront OBJ reader (obj.c): every
 * mesh it accepts must have only in-range indices, and its faces must cut
 * (fuzz_mesh.h). */
#include <stdint.h>

#include "fuzz_mesh.h"
#include "scenefile/obj.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    MeshFile mesh;
    Error err;

    if (obj_parse("fuzz.obj", (const char *)data, size, 1 << 26, &mesh, &err) == 0)
        fuzz_mesh(&mesh);
    return 0;
}
