/* scene.c: the scene's storage (see scene.h). */
#include "scene.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void scene_init(Scene *scene)
{
    memset(scene, 0, sizeof *scene);
    scene->spheres = NULL;
}

void scene_free(Scene *scene)
{
    free(scene->spheres);
    scene_init(scene);
}

int scene_add_sphere(Scene *scene, const Sphere *s)
{
    if (scene->sphere_count == scene->sphere_capacity) {
        size_t cap = scene->sphere_capacity ? 2 * scene->sphere_capacity : 16;
        Sphere *grown;

        if (cap > SIZE_MAX / sizeof *grown)
            return -1;
        grown = realloc(scene->spheres, cap * sizeof *grown);
        if (!grown)
            return -1;
        scene->spheres = grown;
        scene->sphere_capacity = cap;
    }
    scene->spheres[scene->sphere_count++] = *s;
    return 0;
}
