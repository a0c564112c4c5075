/* source.c: a scene file's words kept for writing it back (see source.h). */
#include "scenefile/source.h"

#include <stdlib.h>
#include <string.h>

#include "base/grow.h"

void source_init(SceneSource *src)
{
    memset(src, 0, sizeof *src);
    src->meshes = NULL;
}

void source_free(SceneSource *src)
{
    for (size_t i = 0; i < src->mesh_count; i++) {
        free(src->meshes[i].path);
        free(src->meshes[i].opened);
        for (size_t k = 0; k < src->meshes[i].library_count; k++)
            free(src->meshes[i].libraries[k]);
        free(src->meshes[i].libraries);
    }
    free(src->meshes);
    source_init(src);
}

int source_add_mesh(SceneSource *src, SceneMesh *mesh)
{
    if (grow_reserve((void **)&src->meshes, &src->mesh_capacity, src->mesh_count, sizeof *mesh) !=
        0) {
        free(mesh->path);
        free(mesh->opened);
        for (size_t k = 0; k < mesh->library_count; k++)
            free(mesh->libraries[k]);
        free(mesh->libraries);
        return -1;
    }
    src->meshes[src->mesh_count++] = *mesh;
    return 0;
}
