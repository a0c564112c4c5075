/* trace.c: the colour seen along a ray, mirror and refracted rays in turn
 * (see trace.h). */
#include "render/trace.h"

#include <math.h>

#include "render/cut.h"
#include "render/shade.h"
#include "render/visibility.h"

/* The colour along a ray of depth `depth`, reached with `weight` (the
 * product of the mirror and transparency weights from the primary ray),
 * leaving out the secondary rays t's cut-off allows. */
static Colour trace_path(const Tracer *t, const Ray *ray, int depth, double weight);

/* Counts a mirror or refracted ray (kind) as cast. */
static inline void trace_count_secondary(RayKind kind, RayCounts *counts)
{
    if (kind == RAY_REFRACTION)
        counts->refraction++;
    else
        counts->reflection++;
}

/* Returns share times the colour seen along the ray of kind `kind` leaving
 * sh (facing normal n) in direction dir at depth `depth`, reached with
 * weight times share, or 0 when the cut-off allows leaving it out: its
 * colour is at most the bound for its depth, so the pixel lacks at most
 * weight x share x bound of it. */
static inline Colour trace_secondary(const Tracer *t, const Shade *sh, Vec3 n, Vec3 dir,
                                     RayKind kind, double share, int depth, double weight)
{
    CutRay d;

    weight *= share;
    d.ray.dir = dir;
    d.ray.origin = ray_offset_origin(sh->sp.point, sh->sp.error, n, dir);
    if (t->cut) {
        d.kind = kind;
        d.depth = depth;
        d.tmax = INFINITY;
        d.weight = weight;
        d.lit = colour(0, 0, 0);
        if (cut_leave_out(t->cut, weight * cut_bound(t->cut, t->max_depth - depth), &d))
            return colour(0, 0, 0);
    }
    trace_count_secondary(kind, t->counts);
    return colour_scale(trace_path(t, &d.ray, depth, weight), share);
}

Colour trace_deferred(const Tracer *t, CutRay d)
{
    if (d.kind == RAY_SHADOW)
        return colour_scale(d.lit, d.weight * shade_light_share(t, &d.ray, d.tmax));
    trace_count_secondary(d.kind, t->counts);
    return colour_scale(trace_path(t, &d.ray, d.depth, d.weight), d.weight);
}

Colour trace_ray(const Tracer *t, const Ray *ray)
{
    return trace_path(t, ray, 0, 1);
}

static Colour trace_path(const Tracer *t, const Ray *ray, int depth, double weight)
{
    const Scene *scene = t->scene;
    Hit hit;
    Shade sh;
    Vec3 n, ns;
    Colour c;
    double r, tr, own;

    if (!visibility_nearest(scene, ray, INFINITY, &hit))
        return scene->background;
    sh = shade_at(scene, ray, &hit);
    /* n, the surface's normal facing the ray, decides where secondary rays
     * start; ns, the shading normal on n's side, how light and mirrors
     * behave. They are the same but on smooth triangles. */
    n = ray_facing_normal(sh.sp.normal, ray->dir);
    ns = vec3_dot(sh.sp.shading, n) < 0 ? vec3_neg(sh.sp.shading) : sh.sp.shading;
    r = sh.material->reflection;
    tr = sh.material->transparency;
    own = 1 - r - tr;
    if (sh.material->named >= 0)
        /* Whitted's sum: the Blinn-Phong weights already scale the local
         * term. */
        c = shade_phong(t, &sh, &scene->named[sh.material->named], n, ns,
                        vec3_normalize(vec3_neg(ray->dir)), weight);
    else
        c = colour_scale(shade_local(t, &sh, n, ns, weight * (own > 0 ? own : 0)),
                         own > 0 ? own : 0);
    if (depth + 1 > t->max_depth)
        return c;
    if (tr > 0) {
        /* Entering through the outer side, or leaving from inside. */
        int entering = vec3_dot(ray->dir, sh.sp.normal) < 0;
        double eta = entering ? 1 / sh.material->ior : sh.material->ior;
        Vec3 bent;

        if (ray_refract(ray->dir, ns, eta, &bent)) {
            c = colour_add(c, trace_secondary(t, &sh, n, bent, RAY_REFRACTION, tr, depth + 1,
                                              weight));
        } else {
            r += tr; /* total internal reflection: the share T is mirrored */
        }
    }
    if (r > 0)
        c = colour_add(c, trace_secondary(t, &sh, n, ray_reflect(ray->dir, ns), RAY_REFLECTION, r,
                                          depth + 1, weight));
    return c;
}
