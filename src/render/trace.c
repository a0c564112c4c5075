/* trace.c: the colour seen along a ray, mirror and refracted rays in turn
 * (see trace.h). */
#include "render/trace.h"

#include <math.h>

#include "render/cut.h"
#include "render/shade.h"
#include "render/visibility.h"

/* The colour along a ray of depth `depth`, reached with `weight` (the
 * product of the mirror and transparency weights from the primary ray),
 * leaving out the secondary rays t's cut-off allows: in a course scene,
 * whose weights are the same in every channel (trace_path()), and in a
 * scene of named materials, whose tinted mirrors and glass weigh the
 * channels apart (trace_named_path()). */
static Colour trace_path(const Tracer *t, const Ray *ray, int depth, double weight);
static Colour trace_named_path(const Tracer *t, const Ray *ray, int depth, Colour weight);

/* Counts a mirror or refracted ray (kind) as cast. */
static inline void trace_count_secondary(RayKind kind, RayCounts *counts)
{
    if (kind == RAY_REFRACTION)
        counts->refraction++;
    else
        counts->reflection++;
}

/* Says whether t's cut-off allows leaving out the ray of kind `kind`
 * leaving at depth `depth` along d->ray, reached with weight (whose largest
 * channel is most): its colour is at most the bound for its depth, so the
 * pixel lacks at most most x bound of it; keeps it when so. */
static inline int trace_cut_secondary(const Tracer *t, CutRay *d, RayKind kind, int depth,
                                      Colour weight, double most)
{
    d->kind = kind;
    d->depth = depth;
    d->tmax = INFINITY;
    d->weight = weight;
    d->lit = colour(0, 0, 0);
    return cut_leave_out(t->cut, most * cut_bound(t->cut, t->max_depth - depth), d);
}

/* Returns share times the colour seen along the ray of kind `kind` leaving
 * sh (facing normal n) in direction dir at depth `depth`, reached with
 * weight times share, or 0 when the cut-off allows leaving it out. */
static inline Colour trace_secondary(const Tracer *t, const Shade *sh, Vec3 n, Vec3 dir,
                                     RayKind kind, double share, int depth, double weight)
{
    CutRay d;

    weight *= share;
    d.ray.dir = dir;
    d.ray.origin = ray_offset_origin(sh->sp.point, sh->sp.error, n, dir);
    if (t->cut && trace_cut_secondary(t, &d, kind, depth, colour(weight, weight, weight), weight))
        return colour(0, 0, 0);
    trace_count_secondary(kind, t->counts);
    return colour_scale(trace_path(t, &d.ray, depth, weight), share);
}

/* trace_secondary() for a scene of named materials: the share and weight
 * channel by channel. */
static inline Colour trace_named_secondary(const Tracer *t, const Shade *sh, Vec3 n, Vec3 dir,
                                           RayKind kind, Colour share, int depth, Colour weight)
{
    CutRay d;

    weight = colour_mul(weight, share);
    d.ray.dir = dir;
    d.ray.origin = ray_offset_origin(sh->sp.point, sh->sp.error, n, dir);
    if (t->cut && trace_cut_secondary(t, &d, kind, depth, weight, colour_max(weight)))
        return colour(0, 0, 0);
    trace_count_secondary(kind, t->counts);
    return colour_mul(trace_named_path(t, &d.ray, depth, weight), share);
}

Colour trace_deferred(const Tracer *t, CutRay d)
{
    if (d.kind == RAY_SHADOW)
        return colour_mul(d.lit, colour_scale(d.weight, shade_light_share(t, &d.ray, d.tmax)));
    trace_count_secondary(d.kind, t->counts);
    if (t->scene->named_count > 0)
        return colour_mul(trace_named_path(t, &d.ray, d.depth, d.weight), d.weight);
    /* A course scene's weights are grey. */
    return colour_scale(trace_path(t, &d.ray, d.depth, d.weight.r), d.weight.r);
}

Colour trace_ray(const Tracer *t, const Ray *ray)
{
    if (t->scene->named_count > 0)
        return trace_named_path(t, ray, 0, colour(1, 1, 1));
    return trace_path(t, ray, 0, 1);
}

/* Returns the colour of the sky the ray sees: the background, or the
 * blend of the scene's sky and background by the direction's height. */
static Colour trace_background(const Scene *scene, const Ray *ray)
{
    double up;

    if (!scene->has_sky)
        return scene->background;
    up = 0.5 + 0.5 * (double)ray->dir.y / (double)vec3_length(ray->dir);
    return colour_add(colour_scale(scene->sky, up), colour_scale(scene->background, 1 - up));
}

/* Returns the colour of a named material's surface at sh (the ray arriving
 * along ray at depth `depth` with weight; n and ns its facing normals):
 * the local term of its model (shade.h) and the mirror and refracted rays
 * its model sends (docs/scene-format.md). */
static Colour trace_named(const Tracer *t, const Ray *ray, const Shade *sh, Vec3 n, Vec3 ns,
                          int depth, Colour weight)
{
    const NamedMaterial *pm = &t->scene->named[sh->material->named];
    const Material *m = sh->material;
    Vec3 view = vec3_normalize(vec3_neg(ray->dir));
    int entering = vec3_dot(ray->dir, sh->sp.normal) < 0, deeper = depth + 1 <= t->max_depth;
    double eta = entering ? 1 / m->ior : m->ior, f;
    Colour tint = colour_scale(sh->colour, 1.0 / 255), c, local;
    Vec3 bent;

    switch (pm->model) {
    case MODEL_MATTE:
        return shade_phong(t, sh, pm, n, ns, view, weight);
    case MODEL_PLASTIC:
        /* A clear coat over the diffuse surface: Fresnel's share mirrors,
         * the rest is the surface's own light. */
        f = ray_fresnel(ray->dir, ns, eta);
        local = shade_phong(t, sh, pm, n, ns, view, colour_scale(weight, 1 - f));
        c = colour_scale(local, 1 - f);
        if (deeper && f > 0)
            c = colour_add(c, trace_named_secondary(t, sh, n, ray_reflect(ray->dir, ns), RAY_REFLECTION,
                                              colour(f, f, f), depth + 1, weight));
        return c;
    case MODEL_METALLIC:
        /* A mirror tinted by its colour, and the highlights. */
        c = shade_phong(t, sh, pm, n, ns, view, weight);
        if (deeper)
            c = colour_add(c, trace_named_secondary(t, sh, n, ray_reflect(ray->dir, ns), RAY_REFLECTION,
                                              tint, depth + 1, weight));
        return c;
    case MODEL_DIELECTRIC:
        /* Fresnel's share mirrors, the rest enters, tinted; all of it
         * mirrors on total internal reflection. Highlights show on the
         * outer side only: inside, the surface is glass to glass. */
        c = entering ? shade_phong(t, sh, pm, n, ns, view, weight) : colour(0, 0, 0);
        if (!deeper)
            return c;
        f = ray_refract(ray->dir, ns, eta, &bent) ? ray_fresnel(ray->dir, ns, eta) : 1;
        if (f < 1)
            c = colour_add(c, trace_named_secondary(t, sh, n, bent, RAY_REFRACTION,
                                              colour_scale(tint, 1 - f), depth + 1, weight));
        if (f > 0)
            c = colour_add(c, trace_named_secondary(t, sh, n, ray_reflect(ray->dir, ns), RAY_REFLECTION,
                                              colour(f, f, f), depth + 1, weight));
        return c;
    default: { /* Blinn-Phong: Whitted's sum, the weights already scaling
                * the local term */
        double r = m->reflection, tr = m->transparency;
        c = shade_phong(t, sh, pm, n, ns, view, weight);
        if (!deeper)
            return c;
        if (tr > 0) {
            if (ray_refract(ray->dir, ns, eta, &bent))
                c = colour_add(c, trace_named_secondary(t, sh, n, bent, RAY_REFRACTION,
                                                  colour(tr, tr, tr), depth + 1, weight));
            else
                r += tr; /* total internal reflection: the share T is mirrored */
        }
        if (r > 0)
            c = colour_add(c, trace_named_secondary(t, sh, n, ray_reflect(ray->dir, ns), RAY_REFLECTION,
                                              colour(r, r, r), depth + 1, weight));
        return c;
    }
    }
}

static Colour trace_named_path(const Tracer *t, const Ray *ray, int depth, Colour weight)
{
    const Scene *scene = t->scene;
    Hit hit;
    Shade sh;
    Vec3 n;

    if (!visibility_nearest(scene, ray, INFINITY, &hit))
        return trace_background(scene, ray);
    sh = shade_at(scene, ray, &hit);
    n = ray_facing_normal(sh.sp.normal, ray->dir);
    return trace_named(t, ray, &sh, n,
                       vec3_dot(sh.sp.shading, n) < 0 ? vec3_neg(sh.sp.shading) : sh.sp.shading,
                       depth, weight);
}

/* The course's rule, for a ray of a course scene (trace.h). */
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
    own = own > 0 ? own : 0;
    c = colour_scale(shade_local(t, &sh, n, ns, weight * own), own);
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
