/* mpl_light.c: the MPL ray tracer's picture rules and texture coordinates
 * (see mpl_light.h). */
#include "render/mpl_light.h"

#include <math.h>
#include <stdint.h>

#include "math/angle.h"
#include "math/power.h"
#include "render/pass.h"
#include "render/sampler.h"
#include "render/shade.h"
#include "render/trace.h"
#include "scene/mapping.h"

/* Returns the ray parameter at which the program put the ray's hit on
 * the infinite cylinder c, or 0 when it found none: it measured the
 * distance to the nearer crossing across the ground (in the xz plane,
 * along the ray's horizontal direction made unit) and went that distance
 * along the ray itself, so its point falls short of the surface, in front
 * of it, the more so the steeper the ray. Only the nearer crossing, in
 * front of the origin, counts. */
static real mpl_light_cylinder_t(const Cylinder *c, const Ray *ray)
{
    double dx = ray->dir.x, dz = ray->dir.z, across = sqrt(dx * dx + dz * dz);
    double fx = (double)(ray->origin.x - c->centre.x), fz = (double)(ray->origin.z - c->centre.z);
    double b, disc, d;

    if (!(across > 0))
        return 0;
    b = (fx * dx + fz * dz) / across;
    disc = b * b - (fx * fx + fz * fz - (double)c->radius * (double)c->radius);
    if (!(disc >= 0))
        return 0;
    d = -b - sqrt(disc);
    return d > 0 ? (real)(d / vec3_length(ray->dir)) : 0;
}

/* Finds the nearest hit along ray with 0 < t < tmax as the program found
 * it: visibility_nearest(), but for its infinite cylinders' distances
 * (mpl_light_cylinder_t()). */
static int mpl_light_nearest(const Scene *scene, const Ray *ray, real tmax, Hit *hit)
{
    int found;

    if (scene_count_of(scene, SHAPE_CYLINDER) == 0)
        return visibility_nearest(scene, ray, tmax, hit);
    found = visibility_nearest_among(scene, ray, tmax, ~(1u << SHAPE_CYLINDER), hit);
    for (size_t k = 0; k < scene_count_of(scene, SHAPE_CYLINDER); k++) {
        const Cylinder *c = &((const Cylinder *)scene_items(scene, SHAPE_CYLINDER))[k];
        real t = mpl_light_cylinder_t(c, ray);
        if (t > 0 && t < tmax && (!found || t < hit->t || (t == hit->t && c->order < hit->order))) {
            hit->t = t;
            hit->kind = SHAPE_CYLINDER;
            hit->index = k;
            hit->order = c->order;
            found = 1;
        }
    }
    return found;
}

/* Returns the shading record of hit, crossed by ray with differentials
 * diff (NULL: none; fp receives the footprint): shade_at_footprint()'s,
 * but on an infinite cylinder the program's point (mpl_light_cylinder_t())
 * with its normal, the point's offset from the axis (not of unit length),
 * and the colour there, read at the point (no footprint: the point is off
 * the surface). */
static Shade mpl_light_shade(const Scene *scene, const Ray *ray, const Hit *hit, const RayDiff *diff,
                           ShadeFootprint *fp)
{
    const Cylinder *c;
    Shade sh;
    double uv[2], stripe;

    if (hit->kind != SHAPE_CYLINDER)
        return shade_at_footprint(scene, ray, hit, diff, fp);
    c = &((const Cylinder *)scene_items(scene, SHAPE_CYLINDER))[hit->index];
    sh.material = c->material;
    sh.ambient = 1;
    sh.footprint = NULL;
    sh.sp.point = ray_at(ray, hit->t);
    sh.sp.normal = vec3(sh.sp.point.x - c->centre.x, 0, sh.sp.point.z - c->centre.z);
    sh.sp.shading = sh.sp.normal;
    sh.sp.error = vec3_scale(vec3_abs(sh.sp.point), real_gamma(8));
    sh.back = shade_back_step(scene, ray, hit->t, &sh.sp);
    mapping_mpl(scene, hit->kind, hit->index, &sh.sp, uv, &stripe);
    sh.colour = shade_texel(scene, &sh.material, uv, stripe, 0);
    return sh;
}

/* Returns direction k of the program's distribution over the half-space
 * of the unit normal n, for the point of path `key` in the pixel's sample
 * t->sample: point k of the multi-jittered pattern of grid g, spread over
 * the six faces of the cube [-1, 1]^3 (a sixth of the square each, in
 * strips), made a unit vector and turned into n's half-space. A point
 * uniform on the cube's surface has the direction of one uniform in its
 * volume, which is what the program normalised. */
static Vec3 mpl_light_direction(const Tracer *t, const SamplerGrid *g, unsigned k, uint64_t key,
                              Vec3 n)
{
    const TraceSample *s = t->sample;
    double xy[2], f, a, b, c[3];
    int face, axis;
    Vec3 d;

    sampler_square(g, s->x, s->y, k, key, xy);
    f = xy[0] * 6;
    face = (int)f;
    if (face > 5)
        face = 5;
    a = 2 * (f - face) - 1;
    b = 2 * xy[1] - 1;
    axis = face / 2;
    c[axis] = face % 2 ? -1 : 1;
    c[(axis + 1) % 3] = a;
    c[(axis + 2) % 3] = b;
    d = vec3_normalize(vec3(c[0], c[1], c[2]));
    return vec3_dot(d, n) >= 0 ? d : vec3_neg(d);
}

/* Returns ray i of the `rays` that the point sh (n its normal facing the
 * ray) casts on path key from grid g: the program's direction
 * (mpl_light_direction()), started off the surface. */
static Ray mpl_light_indirect_ray(const Tracer *t, const SamplerGrid *g, unsigned rays, unsigned i,
                                uint64_t key, const Shade *sh, Vec3 n)
{
    Ray r;

    r.dir = mpl_light_direction(t, g, t->sample->k * rays + i, key, n);
    r.origin = ray_offset_origin(sh->sp.point, sh->sp.error, sh->back, n, r.dir);
    return r;
}

/* Returns the program's occlusion factor A at the point sh (n its normal
 * facing the ray) on path key: the mean over t's occlusion rays of the
 * distance to what each meets over the occlusion distance, at most 1. */
static double mpl_light_occlusion(const Tracer *t, const Shade *sh, Vec3 n, uint64_t key)
{
    unsigned rays = (unsigned)t->indirect.ao_samples;
    real reach = (real)t->indirect.ao_distance;
    double sum = 0;

    key = sampler_branch(key, TRACER_OCCLUSION);
    for (unsigned i = 0; i < rays; i++) {
        Ray r = mpl_light_indirect_ray(t, &t->ao_grid, rays, i, key, sh, n);
        Hit hit;

        t->counts->occlusion++;
        sum += mpl_light_nearest(t->scene, &r, reach, &hit) ? (double)(hit.t / reach) : 1;
    }
    return sum / rays;
}

/* Returns the program's gathered colour G at the point sh (n its normal
 * facing the ray) on path key: the mean over t's gathering rays of the
 * colour (0..1) of what each meets, 0 for the sky. */
static Colour mpl_light_gather(const Tracer *t, const Shade *sh, Vec3 n, uint64_t key)
{
    unsigned rays = (unsigned)t->indirect.gi_samples;
    Colour sum = colour(0, 0, 0);

    key = sampler_branch(key, TRACER_GATHER);
    for (unsigned i = 0; i < rays; i++) {
        Ray r = mpl_light_indirect_ray(t, &t->gi_grid, rays, i, key, sh, n);
        Hit hit;

        t->counts->gather++;
        if (mpl_light_nearest(t->scene, &r, INFINITY, &hit))
            sum = colour_add(sum, mpl_light_shade(t->scene, &r, &hit, NULL, NULL).colour);
    }
    return colour_scale(sum, 1.0 / (255.0 * rays));
}

/* Returns the light the scene's lights bring to the point sh (n its
 * normal facing the ray along unit direction v), of colour a (0..1) and
 * glossiness g: the sum of E_i L_i (mpl_light.h). */
static Colour mpl_light_lights(const Tracer *t, const Shade *sh, Vec3 n, Vec3 v, Colour a,
                             double g)
{
    const Scene *scene = t->scene;
    double nv = vec3_dot(n, v), cos2 = 2 * nv * nv - 1;
    double spec = g > 0 && cos2 > 0 ? power(cos2 < 1 ? cos2 : 1, g) : 0;
    Colour sum = colour(0, 0, 0);

    if (!pass_shows_own(t, 0))
        return sum;
    for (size_t i = 0; i < scene->light_count; i++) {
        const Light *light = &scene->lights[i];
        double w = light->intensity, cosine, e;
        Vec3 l;
        Colour d;

        if (light->distant) {
            l = light->to_light;
        } else {
            Vec3 to = vec3_sub(light->position, sh->sp.point);
            double d2 = vec3_dot(to, to);
            if (light->range > 0 && !(d2 < light->range * light->range))
                continue;
            w /= d2;
            l = vec3_normalize(to);
        }
        /* A normal longer than 1 (the program's cylinder) lights at most
         * fully. */
        cosine = vec3_dot(n, l);
        if (!(cosine > 0) || !(w > 0))
            continue;
        if (cosine > 1)
            cosine = 1;
        e = shade_light_reach(t, sh, n, light);
        if (!(e > 0))
            continue;
        d = colour_scale(colour_mul(a, light->colour), w * cosine / 255);
        if (g > 0) {
            Colour s = colour_scale(light->colour, w * spec / 255);
            d = colour_mul(d, colour_add(d, s));
        }
        sum = colour_add(sum, colour_scale(d, e));
    }
    return sum;
}

/* Returns the background (0..1) ray sees when t's pass shows it (pass.h),
 * else black. */
static Colour mpl_light_background(const Tracer *t, const Ray *ray)
{
    if (!pass_shows_own(t, 0))
        return colour(0, 0, 0);
    return colour_scale(trace_background(t->scene, ray), 1.0 / 255);
}

/* Returns the colour (0..1) seen along ray, with differentials diff
 * (NULL: none), of depth `depth`, on path key. */
static Colour mpl_light_path(const Tracer *t, const Ray *ray, const RayDiff *diff, int depth,
                           uint64_t key);

/* Returns the colour (0..1) along the ray of kind `kind` leaving sh (n its
 * normal facing the arriving ray `ray`, of unit direction v and
 * differentials diff) in direction dir, bent by eta when refracted, one
 * deeper than depth. */
static Colour mpl_light_secondary(const Tracer *t, const Ray *ray, Vec3 v, const RayDiff *diff,
                                const Shade *sh, Vec3 n, Vec3 dir, RayKind kind, real eta,
                                int depth, uint64_t key)
{
    RayDiff unit, child;
    Ray r;

    r.dir = dir;
    r.origin = ray_offset_origin(sh->sp.point, sh->sp.error, sh->back, n, dir);
    if (depth + 1 > t->max_depth)
        return mpl_light_background(t, &r);
    if (kind == RAY_REFRACTION)
        t->counts->refraction++;
    else
        t->counts->reflection++;
    if (diff && sh->footprint) {
        /* The program bends the unit direction v about the normal n facing
         * it: the differentials of v, then the rules of ray.h. */
        const ShadeFootprint *fp = sh->footprint;
        Vec3 dn[2];

        shade_footprint_dn(fp, vec3_dot(sh->sp.normal, n) < 0, dn);
        ray_diff_unit(ray->dir, diff, &unit);
        if (kind == RAY_REFRACTION)
            ray_diff_refract(v, &unit, n, dn, fp->dp, eta, dir, &child);
        else
            ray_diff_reflect(v, &unit, n, dn, fp->dp, &child);
    }
    return mpl_light_path(t, &r, diff && sh->footprint ? &child : NULL, depth + 1,
                        sampler_branch(key, kind));
}

static Colour mpl_light_path(const Tracer *t, const Ray *ray, const RayDiff *diff, int depth,
                           uint64_t key)
{
    const Scene *scene = t->scene;
    const NamedMaterial *pm;
    ShadeFootprint fp;
    Hit hit;
    Shade sh;
    Vec3 n, v;
    Colour a, c;
    real eta;

    if (!mpl_light_nearest(scene, ray, INFINITY, &hit))
        return mpl_light_background(t, ray);
    sh = mpl_light_shade(scene, ray, &hit, diff, &fp);
    pm = &scene->named[sh.material.named];
    v = vec3_normalize(ray->dir);
    n = ray_facing_normal(sh.sp.normal, v);
    if (depth == 0 && pass_is_data(t->pass))
        return colour_scale(pass_value(t, ray, hit.t, &sh, n,
                                       t->indirect.ao_samples > 0
                                           ? mpl_light_occlusion(t, &sh, n, key)
                                           : 1),
                            1.0 / 255);
    a = colour_scale(sh.colour, 1.0 / 255);
    switch (pm->model) {
    case MODEL_METALLIC:
    case MODEL_PLASTIC: {
        Colour mirror = mpl_light_secondary(t, ray, v, diff, &sh, n, ray_reflect(v, n),
                                          RAY_REFLECTION, 1, depth, key);
        double f = pm->model == MODEL_PLASTIC
                       ? ray_fresnel(v, n, vec3_dot(v, sh.sp.normal) < 0 ? 1 / sh.material.ior
                                                                         : sh.material.ior)
                       : 1;
        c = colour_add(colour_scale(colour_mul(a, mirror), f),
                       mpl_light_lights(t, &sh, n, v, a, pm->shininess));
        break;
    }
    case MODEL_DIELECTRIC: {
        int entering = vec3_dot(v, sh.sp.normal) < 0;
        Vec3 bent;
        eta = entering ? 1 / sh.material.ior : sh.material.ior;
        if (ray_refract(v, n, eta, &bent))
            c = mpl_light_secondary(t, ray, v, diff, &sh, n, bent, RAY_REFRACTION, eta, depth, key);
        else
            c = mpl_light_secondary(t, ray, v, diff, &sh, n, ray_reflect(v, n), RAY_REFLECTION, 1,
                                  depth, key);
        break;
    }
    default: /* MATTE */
        c = mpl_light_lights(t, &sh, n, v, a, pm->shininess);
        if (t->indirect.gi_samples > 0 && pass_shows_gathered(t, 0))
            c = colour_add(c, mpl_light_gather(t, &sh, n, key));
        c = colour_scale(colour_mul(c, a), 1 / ANGLE_PI);
        break;
    }
    if (t->indirect.ao_samples > 0)
        c = colour_scale(c, mpl_light_occlusion(t, &sh, n, key));
    return c;
}

Colour mpl_light_trace(const Tracer *t, const Ray *ray)
{
    return mpl_light_trace_diff(t, ray, NULL);
}

Colour mpl_light_miss(const Tracer *t, const Ray *ray)
{
    /* As mpl_light_path() answers, on mpl_light_trace_diff()'s scale. */
    return colour_scale(mpl_light_background(t, ray), 255);
}

int mpl_light_miss_uniform(const Tracer *t)
{
    return !t->scene->has_sky;
}

Colour mpl_light_trace_diff(const Tracer *t, const Ray *ray, const RayDiff *diff)
{
    return colour_scale(mpl_light_path(t, ray, diff, 0, 0), 255);
}
