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
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_SPHERE); i++) {
        const Sphere *sp = &scene_spheres(scene)[i];
        m = fmax(m, fmax(vec3_max_abs(sp->centre), sp->radius));
    }
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_PLANE); i++) {
        const Plane *pl = &scene_planes(scene)[i];
        m = fmax(m, fmax(vec3_max_abs(pl->point), pl->material.texture >= 0 ? pl->tile : 0));
    }
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_TRIANGLE); i++)
        m = fmax(m, scene_points_max(scene_triangles(scene)[i].v, 3));
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_CUBE); i++)
        m = fmax(m, fmax(vec3_max_abs(scene_cubes(scene)[i].centre), scene_cubes(scene)[i].half));
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_SQUARE); i++) {
        const Square *sq = &scene_squares(scene)[i];
        m = fmax(m, fmax(vec3_max_abs(sq->centre), sq->half));
    }
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_CYLINDER); i++) {
        const Cylinder *cy = &scene_cylinders(scene)[i];
        m = fmax(m, fmax(vec3_max_abs(cy->centre), cy->radius));
    }
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_CONE); i++) {
        const Cone *c = &scene_cones(scene)[i];
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
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_SPHERE); i++) {
        scene_spheres(scene)[i].centre = vec3_ldexp(scene_spheres(scene)[i].centre, k);
        scene_spheres(scene)[i].radius = ldexp(scene_spheres(scene)[i].radius, k);
    }
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_PLANE); i++) {
        scene_planes(scene)[i].point = vec3_ldexp(scene_planes(scene)[i].point, k);
        scene_planes(scene)[i].tile = ldexp(scene_planes(scene)[i].tile, k);
    }
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_TRIANGLE); i++)
        for (int j = 0; j < 3; j++)
            scene_triangles(scene)[i].v[j] = vec3_ldexp(scene_triangles(scene)[i].v[j], k);
    /* Corners, apexes and the rest scale exactly with what they were made
     * from; angles and unit vectors do not change. */
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_CUBE); i++) {
        Cube *c = &scene_cubes(scene)[i];
        c->centre = vec3_ldexp(c->centre, k);
        c->lo = vec3_ldexp(c->lo, k);
        c->hi = vec3_ldexp(c->hi, k);
        c->half = ldexp(c->half, k);
    }
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_SQUARE); i++) {
        scene_squares(scene)[i].centre = vec3_ldexp(scene_squares(scene)[i].centre, k);
        scene_squares(scene)[i].half = ldexp(scene_squares(scene)[i].half, k);
    }
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_CYLINDER); i++) {
        scene_cylinders(scene)[i].centre = vec3_ldexp(scene_cylinders(scene)[i].centre, k);
        scene_cylinders(scene)[i].radius = ldexp(scene_cylinders(scene)[i].radius, k);
    }
    for (size_t i = 0; i < scene_count_of(scene, SHAPE_CONE); i++) {
        Cone *c = &scene_cones(scene)[i];
        c->base = vec3_ldexp(c->base, k);
        c->apex = vec3_ldexp(c->apex, k);
        c->radius = ldexp(c->radius, k);
        c->height = ldexp(c->height, k);
    }
    scene->length_exponent = k;
}
