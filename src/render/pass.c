/* pass.c: the data passes' values (see pass.h). */
#include "render/pass.h"

#include "render/visibility.h"
#include "scene/camera.h"

double pass_depth_scale(const Scene *scene)
{
    const Camera *cam = &scene->camera;
    Ray ray = camera_ray(cam, 0.5 * cam->width, 0.5 * cam->height);
    Hit hit;

    if (visibility_nearest(scene, &ray, INFINITY, &hit))
        return (double)(hit.t * vec3_length(ray.dir));
    return (double)vec3_length(vec3_sub(
        vec3_add(cam->top_left, vec3_scale(vec3_add(cam->u, cam->v), 0.5)), cam->eye));
}

Colour pass_value(const Tracer *t, const Ray *ray, real t_hit, const Shade *sh, Vec3 ns,
                  double ao_share)
{
    double s = t->depth_scale, d, grey;

    switch (t->pass) {
    case TRACE_PASS_AO:
        return colour(255 * ao_share, 255 * ao_share, 255 * ao_share);
    case TRACE_PASS_ALBEDO:
        return sh->colour;
    case TRACE_PASS_NORMAL:
        return colour(127.5 * (ns.x + 1), 127.5 * (ns.y + 1), 127.5 * (ns.z + 1));
    default: /* TRACE_PASS_DEPTH */
        d = (double)(t_hit * vec3_length(ray->dir));
        grey = 255 * s / (s + d);
        return colour(grey, grey, grey);
    }
}
