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
    int k;

    m = fmax(m, vec3_max_abs(scene->light.position));
    for (size_t i = 0; i < scene->sphere_count; i++)
        m = fmax(m, fmax(vec3_max_abs(scene->spheres[i].centre), scene->spheres[i].radius));
    if (!(m > 0 && m < SCENE_TINY))
        return;
    k = vec3_unit_exponent(m);
    cam->eye = vec3_ldexp(cam->eye, k);
    cam->top_left = vec3_ldexp(cam->top_left, k);
    cam->u = vec3_ldexp(cam->u, k);
    cam->v = vec3_ldexp(cam->v, k);
    scene->light.position = vec3_ldexp(scene->light.position, k);
    for (size_t i = 0; i < scene->sphere_count; i++) {
        scene->spheres[i].centre = vec3_ldexp(scene->spheres[i].centre, k);
        scene->spheres[i].radius = ldexp(scene->spheres[i].radius, k);
    }
    scene->length_exponent = k;
}
