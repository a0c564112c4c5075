/* scene.c: the scene's storage (see scene.h). */
#include "scene.h"

#include <math.h>
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

void scene_fit_scale(Scene *scene)
{
    Camera *cam = &scene->camera;
    double m = fmax(fmax(vec3_max_abs(cam->eye), vec3_max_abs(cam->top_left)),
                    fmax(vec3_max_abs(cam->u), vec3_max_abs(cam->v)));
    int e;

    m = fmax(m, vec3_max_abs(scene->light.position));
    for (size_t k = 0; k < scene->sphere_count; k++)
        m = fmax(m, fmax(vec3_max_abs(scene->spheres[k].centre), scene->spheres[k].radius));
    if (!(m > 0 && m < SCENE_TINY))
        return;
    frexp(m, &e);
    cam->eye = vec3_ldexp(cam->eye, -e);
    cam->top_left = vec3_ldexp(cam->top_left, -e);
    cam->u = vec3_ldexp(cam->u, -e);
    cam->v = vec3_ldexp(cam->v, -e);
    scene->light.position = vec3_ldexp(scene->light.position, -e);
    for (size_t k = 0; k < scene->sphere_count; k++) {
        scene->spheres[k].centre = vec3_ldexp(scene->spheres[k].centre, -e);
        scene->spheres[k].radius = ldexp(scene->spheres[k].radius, -e);
    }
    scene->length_exponent = -e;
}
