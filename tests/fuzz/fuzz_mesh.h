/*
 * fuzz_mesh.h: the checks shared by the mesh fuzz targets (fuzz_obj.c,
 * fuzz_ply.c, fuzz_stl.c): a mesh a reader accepts has faces cut without a
 * fault (mesh_file_cut(), the polygon cutter meeting every face a reader
 * lets through) and only corners that name what the file holds.
 */
#include <stdint.h>
#include <stdlib.h>

#include "scenefile/mesh_file.h"

static void fuzz_mesh(MeshFile *mesh)
{
    if (mesh_file_cut(mesh) != 0)
        abort();
    for (size_t i = 0; i < mesh->tri_count; i++) {
        if (mesh->tri_material && mesh->tri_material[i] >= mesh->material_count)
            abort();
        for (int k = 0; k < 3; k++) {
            const MeshCorner *c = &mesh->tri[i][k];
            if (c->v < 0 || (size_t)c->v >= mesh->v_count ||
                (c->vt >= 0 && (size_t)c->vt >= mesh->vt_count) ||
                (c->vn >= 0 && (size_t)c->vn >= mesh->vn_count))
                abort();
        }
    }
    mesh_file_free(mesh);
}
