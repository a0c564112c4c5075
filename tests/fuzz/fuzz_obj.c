/* fuzz_obj.c: libFuzzer target for the Wavefront OBJ reader (obj.c): every
 * mesh it accepts must have only in-range indices. */
#include <stdint.h>
#include <stdlib.h>

#include "scenefile/obj.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    MeshFile mesh;
    Error err;

    if (obj_parse("fuzz.obj", (const char *)data, size, 0, &mesh, &err) != 0)
        return 0;
    for (size_t i = 0; i < mesh.tri_count; i++)
        for (int k = 0; k < 3; k++) {
            const MeshCorner *c = &mesh.tri[i][k];
            if (c->v < 0 || (size_t)c->v >= mesh.v_count ||
                (c->vt >= 0 && (size_t)c->vt >= mesh.vt_count) ||
                (c->vn >= 0 && (size_t)c->vn >= mesh.vn_count))
                abort();
        }
    mesh_file_free(&mesh);
    return 0;
}
