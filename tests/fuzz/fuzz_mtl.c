/* fuzz_mtl.c: libFuzzer target for the MTL reader (mtl.c): it reads any
 * text into the materials a mesh names without a fault, each material
 * left with numbers it can use. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scenefile/mtl.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[] = {"a", "b", "red paint"};
    MeshFile mesh;

    mesh_file_init(&mesh);
    mesh.materials = calloc(3, sizeof *mesh.materials);
    if (!mesh.materials)
        return 0;
    for (int k = 0; k < 3; k++) {
        char *name = malloc(strlen(names[k]) + 1);
        if (!name)
            abort();
        strcpy(name, names[k]);
        mesh_material_default(&mesh.materials[k], name);
        mesh.material_count++;
    }
    /* Named as a file in a folder of its own: its textures are looked for
     * there, and not found. */
    if (mtl_parse("fuzz-mtl-dir/fuzz.mtl", (const char *)data, size, &mesh) != 0)
        abort();
    for (size_t k = 0; k < mesh.material_count; k++) {
        const MeshMaterial *m = &mesh.materials[k];
        if (!(m->d >= 0 && m->d <= 1) || !(m->ni > 0) || m->illum > 10 ||
            (m->texture && !m->texture_at) || !isfinite(m->uv_scale[0]) ||
            !isfinite(m->uv_scale[1]) || !isfinite(m->uv_offset[0]) || !isfinite(m->uv_offset[1]))
            abort();
    }
    mesh_file_free(&mesh);
    return 0;
}
