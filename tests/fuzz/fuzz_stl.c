/* fuzz_stl.c: libFuzzer target for the STL reader (stl.c): every mesh it
 * accepts must have only in-range indices, and its faces must cut
 * (fuzz_mesh.h). */
#include <stdint.h>

#include "fuzz_mesh.h"
#include "scenefile/stl.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    MeshFile mesh;
    Error err;

    if (stl_parse("fuzz.stl", (const char *)data, size, 1 << 26, &mesh, &err) == 0)
        fuzz_mesh(&mesh);
    return 0;
}
