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
        return -1;
    }
    src->meshes[src->mesh_count++] = *mesh;
    return 0;
}
