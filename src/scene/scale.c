/* scale.c: enlarging tiny scenes (see scale.h). */
#include "scene/scale.h"

#include <math.h>

/* Returns the largest magnitude of the components of the n points at p. */
static double scene_points_max(const Vec3 *p, size_t n)
{
    double m = 0;

    for (size_t i = 0; i < n; i++)
        m = fmax(m, vec3_max_abs(p[i]));
    return m;
}

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
    for (size_t i = 0; i < scene->sphere_count; i++)
        m = fmax(m, fmax(vec3_max_abs(scene->spheres[i].centre), scene->spheres[i].radius));
    for (size_t i = 0; i < scene->plane_count; i++)
        m = fmax(m, fmax(vec3_max_abs(scene->planes[i].point),
                        scene->planes[i].material.texture >= 0 ? scene->planes[i].tile : 0));
    for (size_t i = 0; i < scene->triangle_count; i++)
        m = fmax(m, scene_points_max(scene->triangles[i].v, 3));
    for (size_t i = 0; i < scene->cube_count; i++)
        m = fmax(m, fmax(vec3_max_abs(scene->cubes[i].centre), scene->cubes[i].half));
    for (size_t i = 0; i < scene->square_count; i++)
        m = fmax(m, fmax(vec3_max_abs(scene->squares[i].centre), scene->squares[i].half));
    for (size_t i = 0; i < scene->cylinder_count; i++)
        m = fmax(m, fmax(vec3_max_abs(scene->cylinders[i].centre), scene->cylinders[i].radius));
    for (size_t i = 0; i < scene->cone_count; i++) {
        const Cone *c = &scene->cones[i];
        m = fmax(m, fmax(fmax(vec3_max_abs(c->base), vec3_max_abs(c->apex)),
                         fmax(c->radius, fabs(c->height))));
    }
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
    for (size_t i = 0; i < scene->sphere_count; i++) {
        scene->spheres[i].centre = vec3_ldexp(scene->spheres[i].centre, k);
        scene->spheres[i].radius = ldexp(scene->spheres[i].radius, k);
    }
    for (size_t i = 0; i < scene->plane_count; i++) {
        scene->planes[i].point = vec3_ldexp(scene->planes[i].point, k);
        scene->planes[i].tile = ldexp(scene->planes[i].tile, k);
    }
    for (size_t i = 0; i < scene->triangle_count; i++)
        for (int j = 0; j < 3; j++)
            scene->triangles[i].v[j] = vec3_ldexp(scene->triangles[i].v[j], k);
    /* Corners, apexes and the rest scale exactly with what they were made
     * from; angles and unit vectors do not change. */
    for (size_t i = 0; i < scene->cube_count; i++) {
        Cube *c = &scene->cubes[i];
        c->centre = vec3_ldexp(c->centre, k);
        c->lo = vec3_ldexp(c->lo, k);
        c->hi = vec3_ldexp(c->hi, k);
        c->half = ldexp(c->half, k);
    }
    for (size_t i = 0; i < scene->square_count; i++) {
        scene->squares[i].centre = vec3_ldexp(scene->squares[i].centre, k);
        scene->squares[i].half = ldexp(scene->squares[i].half, k);
    }
    for (size_t i = 0; i < scene->cylinder_count; i++) {
        scene->cylinders[i].centre = vec3_ldexp(scene->cylinders[i].centre, k);
        scene->cylinders[i].radius = ldexp(scene->cylinders[i].radius, k);
    }
    for (size_t i = 0; i < scene->cone_count; i++) {
        Cone *c = &scene->cones[i];
        c->base = vec3_ldexp(c->base, k);
        c->apex = vec3_ldexp(c->apex, k);
        c->radius = ldexp(c->radius, k);
        c->height = ldexp(c->height, k);
    }
    scene->length_exponent = k;
}
