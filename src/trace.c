/* trace.c: nearest hits, shadows and recursive shading (see trace.h). */
#include "trace.h"

#include <math.h>

int trace_nearest(const Scene *scene, const Ray *ray, double tmax, Hit *hit)
{
    int found = 0;

    for (size_t k = 0; k < scene->sphere_count; k++) {
        double t;
        /* The interval is open at tmax, so an exact tie keeps the earlier sphere. */
        if (sphere_intersect(&scene->spheres[k], ray, 0, tmax, &t)) {
            tmax = t;
            hit->t = t;
            hit->sphere = &scene->spheres[k];
            found = 1;
        }
    }
    return found;
}

int trace_occluded(const Scene *scene, const Ray *segment)
{
    for (size_t k = 0; k < scene->sphere_count; k++) {
        double t;
        if (sphere_intersect(&scene->spheres[k], segment, 0, 1, &t))
            return 1;
    }
    return 0;
}

/* Returns the light's direct contribution, E cos_a (Ci * Cs) / 255, at the
 * surface point sp of sphere s, whose normal facing the viewer is n. */
static Colour trace_direct(const Scene *scene, const Sphere *s, const SurfacePoint *sp, Vec3 n)
{
    const Light *light = &scene->light;
    Vec3 to_light = vec3_sub(light->position, sp->point);
    double cos_a = vec3_dot(n, vec3_normalize(to_light));
    Ray shadow;

    /* Facing away from the light (or the light on the point: NaN) means no
     * light, whatever E is: no shadow ray needed. */
    if (!(cos_a > 0))
        return colour(0, 0, 0);
    shadow.origin = ray_offset_origin(sp->point, sp->error, n, to_light);
    shadow.dir = vec3_sub(light->position, shadow.origin);
    if (trace_occluded(scene, &shadow))
        return colour(0, 0, 0);
    return colour(cos_a * (s->colour.r * light->colour.r / 255),
                  cos_a * (s->colour.g * light->colour.g / 255),
                  cos_a * (s->colour.b * light->colour.b / 255));
}

Colour trace_ray(const Scene *scene, const Ray *ray, int depth, int max_depth)
{
    Hit hit;
    const Sphere *s;
    SurfacePoint sp;
    Vec3 n;
    Colour c;

    if (!trace_nearest(scene, ray, INFINITY, &hit))
        return scene->background;
    s = hit.sphere;
    sp = sphere_surface_at(s, ray_at(ray, hit.t));
    n = ray_facing_normal(sp.normal, ray->dir);
    c = colour_scale(trace_direct(scene, s, &sp, n), 1 - s->reflection);
    if (s->reflection > 0 && depth + 1 <= max_depth) {
        Vec3 d = ray->dir;
        Ray mirror;

        mirror.dir = vec3_sub(d, vec3_scale(n, 2 * vec3_dot(d, n)));
        mirror.origin = ray_offset_origin(sp.point, sp.error, n, mirror.dir);
        c = colour_add(c, colour_scale(trace_ray(scene, &mirror, depth + 1, max_depth),
                                       s->reflection));
    }
    return c;
}
