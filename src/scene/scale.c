/* scale.c: enlarging tiny scenes (see scale.h). */
#include "scene/scale.h"

#include <math.h>

/* Returns the largest magnitude of every length in the scene, or some
 * magnitude of SCENE_TINY or more when there is one (the objects are then
 * not looked at: a scene of 10^6 triangles is seldom tiny). */
static double scene_max_length(const Scene *scene)
{
    const Camera *cam = &scene->camera;
    double m = fmax(fmax(vec3_max_abs(cam->eye), vec3_max_abs(cam->top_left)),
                    fmax(vec3_max_abs(cam->u), vec3_max_abs(cam->v)));

    m = fmax(m, fmax(cam->aperture, cam->aperture > 0 ? cam->focus : 0));
    if (m >= SCENE_TINY)
        return m;
    for (size_t i = 0; i < scene->light_count; i++)
        if (!scene->lights[i].distant) /* a direction, not a place */
            m = fmax(m, vec3_max_abs(scene->lights[i].position));
    for (int k = 0; k < SHAPE_KINDS; k++)
        for (size_t i = 0; i < scene_count_of(scene, (ShapeKind)k); i++)
            m = fmax(m, shape_extent((ShapeKind)k, scene_items(scene, (ShapeKind)k), i));
    return m;
}

void scene_fit_scale(Scene *scene)
{
    Camera *cam = &scene->camera;
    double m = scene_max_length(scene);
    int k;

    if (!(m > 0 && m < SCENE_TINY))
        return;
    k = vec3_unit_exponent(m);
    cam->eye = vec3_ldexp(cam->eye, k);
    cam->top_left = vec3_ldexp(cam->top_left, k);
    cam->u = vec3_ldexp(cam->u, k);
    cam->v = vec3_ldexp(cam->v, k);
    cam->aperture = ldexp(cam->aperture, k);
    cam->focus = ldexp(cam->focus, k);
    for (size_t i = 0; i < scene->light_count; i++) {
        Light *l = &scene->lights[i];
        if (l->distant)
            continue;
        l->position = vec3_ldexp(l->position, k);
        /* A light falling off as i / d^2 keeps its strength at every
         * point when i grows with d^2. */
        if (l->falloff) {
            l->intensity = ldexp(l->intensity, 2 * k);
            l->range = ldexp(l->range, k);
        }
    }
    /* Corners, apexes and the rest scale exactly with what they were made
     * from; angles and unit vectors do not change. */
    for (int kind = 0; kind < SHAPE_KINDS; kind++)
        for (size_t i = 0; i < scene_count_of(scene, (ShapeKind)kind); i++)
            shape_scale((ShapeKind)kind, scene_items(scene, (ShapeKind)kind), i, k);
    scene->length_exponent = k;
}
