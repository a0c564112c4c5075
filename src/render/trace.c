/* trace.c: the colour seen along a ray, mirror and refracted rays in turn
 * (see trace.h). */
#include "render/trace.h"

#include <math.h>
#include <stdint.h>

#include "base/grow.h"
#include "math/angle.h"
#include "render/gicache.h"
#include "render/cut.h"
#include "render/pass.h"
#include "render/sampler.h"
#include "render/shade.h"
#include "render/visibility.h"

/* Where a ray is on its way from the camera: the key its indirect rays
 * draw their directions from (sampler.h; 0 when there are none), the
 * diffuse bounces (gathering rays) taken so far, its differentials
 * (geometry/ray.h; NULL when the scene reads nothing over a footprint),
 * and where to say what it meets, or NULL (set for a gathering ray of the
 * irradiance cache's, not for those it sends on). */
typedef struct {
    uint64_t key;
    int bounce;
    const RayDiff *diff;
    TraceMet *met;
} TracePath;

/* The colour along a ray of depth `depth`, reached with `weight` (the
 * product of the mirror and transparency weights from the primary ray),
 * leaving out the secondary rays t's cut-off allows: in a course scene,
 * whose weights are the same in every channel (trace_path()), and in a
 * scene of named materials, whose tinted mirrors and glass weigh the
 * channels apart (trace_named_path()). */
static Colour trace_path(const Tracer *t, const Ray *ray, int depth, double weight,
                         TracePath path);
static Colour trace_named_path(const Tracer *t, const Ray *ray, int depth, Colour weight,
                               TracePath path);

/* Returns the path of the ray taking branch from path: its key follows
 * only when there are gathering rays to draw. */
static inline TracePath trace_branch(const Tracer *t, TracePath path, unsigned branch)
{
    if (t->indirect.gi_samples > 0)
        path.key = sampler_branch(path.key, branch);
    return path;
}

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

/* Stores in *out the differentials of the ray of kind `kind` leaving sh
 * in direction dir, for the ray `ray` that met it with differentials
 * diff: the mirror's about, or the refraction's through, sh's shading
 * normal facing the ray (as the tracer bends them). */
static void trace_child_diff(const Ray *ray, const Shade *sh, Vec3 n, RayKind kind, Vec3 dir,
                             const RayDiff *diff, RayDiff *out)
{
    const ShadeFootprint *fp = sh->footprint;
    int flip = vec3_dot(sh->sp.shading, n) < 0;
    Vec3 ns = flip ? vec3_neg(sh->sp.shading) : sh->sp.shading;
    Vec3 dn[2];

    shade_footprint_dn(fp, flip, dn);
    if (kind == RAY_REFRACTION) {
        int entering = vec3_dot(ray->dir, sh->sp.normal) < 0;
        real eta = entering ? 1 / sh->material.ior : sh->material.ior;
        ray_diff_refract(ray->dir, diff, ns, dn, fp->dp, eta, dir, out);
    } else {
        ray_diff_reflect(ray->dir, diff, ns, dn, fp->dp, out);
    }
}

/* Stores in d the ray of kind `kind` leaving sh (facing normal n; ray the
 * ray that met it, on path) in direction dir, with its differentials when
 * path carries some, and returns the new ray's path (its differentials
 * d's). */
static inline TracePath trace_child(const Tracer *t, const Ray *ray, const Shade *sh, Vec3 n,
                                    Vec3 dir, RayKind kind, TracePath path, CutRay *d)
{
    TracePath next = trace_branch(t, path, kind);

    next.met = NULL;
    d->ray.dir = dir;
    d->ray.origin = ray_offset_origin(sh->sp.point, sh->sp.error, sh->back, n, dir);
    d->has_diff = path.diff && sh->footprint;
    if (d->has_diff)
        trace_child_diff(ray, sh, n, kind, dir, path.diff, &d->diff);
    next.diff = d->has_diff ? &d->diff : NULL;
    return next;
}

/* Returns share times the colour seen along the ray of kind `kind` leaving
 * sh (facing normal n; ray the ray that met it) in direction dir at depth
 * `depth`, reached with weight times share, or 0 when the cut-off allows
 * leaving it out. */
static inline Colour trace_secondary(const Tracer *t, const Ray *ray, const Shade *sh, Vec3 n,
                                     Vec3 dir, RayKind kind, double share, int depth,
                                     double weight, TracePath path)
{
    CutRay d;
    TracePath next = trace_child(t, ray, sh, n, dir, kind, path, &d);

    weight *= share;
    if (t->cut && trace_cut_secondary(t, &d, kind, depth, colour(weight, weight, weight), weight))
        return colour(0, 0, 0);
    trace_count_secondary(kind, t->counts);
    return colour_scale(trace_path(t, &d.ray, depth, weight, next), share);
}

/* trace_secondary() for a scene of named materials: the share and weight
 * channel by channel. */
static inline Colour trace_named_secondary(const Tracer *t, const Ray *ray, const Shade *sh,
                                           Vec3 n, Vec3 dir, RayKind kind, Colour share,
                                           int depth, Colour weight, TracePath path)
{
    CutRay d;
    TracePath next = trace_child(t, ray, sh, n, dir, kind, path, &d);

    weight = colour_mul(weight, share);
    if (t->cut && trace_cut_secondary(t, &d, kind, depth, weight, colour_max(weight)))
        return colour(0, 0, 0);
    trace_count_secondary(kind, t->counts);
    return colour_mul(trace_named_path(t, &d.ray, depth, weight, next), share);
}

/* Says whether a point of a course scene receives ambient light (for
 * its occlusion to darken). */
static inline int trace_course_ambient(const Scene *scene)
{
    return scene->has_ambient && colour_max(scene->ambient) > 0;
}

/* Says whether a point of named material pm receives ambient light. */
static inline int trace_named_ambient(const Scene *scene, const NamedMaterial *pm)
{
    return pm->ka > 0 && colour_max(scene->ambient) > 0;
}

int trace_has_ambient(const Scene *scene)
{
    for (size_t k = 0; k < scene->named_count; k++)
        if (trace_named_ambient(scene, &scene->named[k]))
            return 1;
    return scene->named_count == 0 && trace_course_ambient(scene);
}

Colour trace_deferred(const Tracer *t, CutRay d)
{
    /* The cut-off is off under global illumination (render.c), so a
     * deferred ray's path draws nothing. */
    TracePath none = {0, 0, d.has_diff ? &d.diff : NULL, NULL};

    if (d.kind == RAY_SHADOW)
        return colour_mul(d.lit, colour_scale(d.weight, shade_light_share(t, &d.ray, d.tmax, NULL)));
    trace_count_secondary(d.kind, t->counts);
    if (t->named)
        return colour_mul(trace_named_path(t, &d.ray, d.depth, d.weight, none), d.weight);
    /* A course scene's weights are grey. */
    return colour_scale(trace_path(t, &d.ray, d.depth, d.weight.r, none), d.weight.r);
}

void gather_points_add(GatherPoints *list, const GatherPoint *p)
{
    void *items = list->items;

    if (grow_reserve(&items, &list->capacity, list->count, sizeof *list->items) != 0) {
        list->failed = 1;
        return;
    }
    list->items = items;
    list->items[list->count++] = *p;
}

Colour trace_gathered(const Tracer *t, const Ray *ray, int bounce, uint64_t key, TraceMet *met)
{
    TracePath path = {key, bounce, NULL, met};

    met->t = INFINITY;
    met->behind = 0;
    if (t->named)
        return trace_named_path(t, ray, 0, colour(1, 1, 1), path);
    return trace_path(t, ray, 0, 1, path);
}

Colour trace_ray(const Tracer *t, const Ray *ray)
{
    return trace_ray_diff(t, ray, NULL);
}

Colour trace_ray_diff(const Tracer *t, const Ray *ray, const RayDiff *diff)
{
    TracePath primary = {0, 0, diff, NULL};

    if (t->named)
        return trace_named_path(t, ray, 0, colour(1, 1, 1), primary);
    return trace_path(t, ray, 0, 1, primary);
}

Colour trace_miss(const Tracer *t, const Ray *ray)
{
    /* As trace_named_path() and trace_path() answer at depth 0. */
    if (!pass_shows_own(t, 0))
        return colour(0, 0, 0);
    return t->named ? trace_background(t->scene, ray) : t->scene->background;
}

int trace_miss_uniform(const Tracer *t)
{
    return !t->named || !t->scene->has_sky;
}

/* Returns the share of the hemisphere over sh (n and ns its facing
 * normals) that nothing nearer than the occlusion distance hides, seen
 * through t's occlusion rays: cosine-weighted and stratified over the
 * pixel's samples (sampler_hemisphere()); a direction below the surface
 * (smooth shading) counts as hidden. */
static double trace_occlusion(const Tracer *t, const Shade *sh, Vec3 n, Vec3 ns)
{
    const TraceSample *s = t->sample;
    unsigned rays = (unsigned)t->indirect.ao_samples, open = 0;
    uint64_t key = sampler_branch(0, TRACER_OCCLUSION);

    for (unsigned i = 0; i < rays; i++) {
        double d[3];
        Ray r;

        sampler_hemisphere(&t->ao_grid, s->x, s->y, s->k * rays + i, key, d);
        r.dir = vec3_from_frame(ns, d[0], d[1], d[2]);
        if (!(vec3_dot(r.dir, n) > 0))
            continue;
        r.origin = ray_offset_origin(sh->sp.point, sh->sp.error, sh->back, n, r.dir);
        t->counts->occlusion++;
        open += !visibility_occluded(t->scene, &r, t->indirect.ao_distance);
    }
    return (double)open / rays;
}

/* Says whether the point of a ray on path gathers diffuse light. */
static inline int trace_gathers(const Tracer *t, TracePath path)
{
    return t->indirect.gi_samples > 0 && path.bounce < t->indirect.gi_bounces;
}

/* Returns the differentials the hit `hit` of a ray on path (at depth
 * `depth`) takes its footprint from: path's when the surface's colour
 * averages over the footprint or it sends rays that carry differentials
 * on (gathering, mirror, refraction), else NULL, so that a plain matte
 * surface in a scene that filters elsewhere pays nothing for it (and a
 * scene that filters nothing, not even the material's lookup). */
static inline const RayDiff *trace_footprint_diff(const Tracer *t, const Hit *hit, int depth,
                                                  TracePath path)
{
    Material m;
    int sends;

    if (!path.diff)
        return NULL;
    m = scene_material(t->scene, hit->kind, hit->index);
    if (material_averages(&m) || trace_gathers(t, path))
        return path.diff;
    if (depth + 1 > t->max_depth)
        return NULL;
    if (m.named >= 0 && t->scene->named[m.named].model != MODEL_PHONG)
        sends = t->scene->named[m.named].model != MODEL_MATTE;
    else
        sends = m.reflection > 0 || m.transparency > 0;
    return sends ? path.diff : NULL;
}

/* Stores in *out the differentials given a gathering ray in direction dir
 * (unit), one of `rays` leaving a point of footprint fp: an estimate, as
 * its neighbours are no pixel's: it starts where the point's footprint
 * spans, and spreads as the rays share the hemisphere, each the angle
 * sqrt(pi / rays) apart from the next (Igehy's differentials are for
 * mirrors; pbrt-v4 estimates diffuse rays' likewise). */
static void trace_gather_diff(const ShadeFootprint *fp, Vec3 dir, unsigned rays, RayDiff *out)
{
    real spread = (real)sqrt(ANGLE_PI / rays);
    Vec3 a = fabs((double)dir.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0);
    Vec3 u = vec3_normalize(vec3_cross(dir, a)), v = vec3_cross(dir, u);

    out->dodx = fp->dp[0];
    out->dody = fp->dp[1];
    out->dddx = vec3_scale(u, spread);
    out->dddy = vec3_scale(v, spread);
}

/* Returns the mean colour seen from sh (n and ns its facing normals, the
 * ray at depth `depth` with weight) along its gathering rays: at the
 * first bounce t's gi_samples rays, after it one (a path), cosine-weighted
 * and stratified over the pixel's samples. Each is traced as any ray is
 * (its own direct light, mirrors, and its gathering while bounces remain),
 * at the same depth; one that meets nothing brings nothing (the
 * background lights nothing). */
static Colour trace_gather(const Tracer *t, const Shade *sh, Vec3 n, Vec3 ns, int depth,
                           Colour weight, TracePath path)
{
    const TraceSample *s = t->sample;
    int first = path.bounce == 0;
    unsigned rays = first ? (unsigned)t->indirect.gi_samples : 1;
    const SamplerGrid *g = first ? &t->gi_grid : &t->path_grid;
    uint64_t key = sampler_branch(path.key, TRACER_GATHER);
    Colour sum = colour(0, 0, 0);

    for (unsigned i = 0; i < rays; i++) {
        TracePath next = {sampler_branch(path.key, TRACER_GATHERED + i), path.bounce + 1, NULL,
                          NULL};
        RayDiff spread;
        double d[3];
        Ray r;

        sampler_hemisphere(g, s->x, s->y, s->k * rays + i, key, d);
        r.dir = vec3_from_frame(ns, d[0], d[1], d[2]);
        if (!(vec3_dot(r.dir, n) > 0))
            continue;
        r.origin = ray_offset_origin(sh->sp.point, sh->sp.error, sh->back, n, r.dir);
        if (path.diff && sh->footprint) {
            trace_gather_diff(sh->footprint, r.dir, rays, &spread);
            next.diff = &spread;
        }
        t->counts->gather++;
        sum = colour_add(sum, t->named
                                  ? trace_named_path(t, &r, depth, weight, next)
                                  : trace_path(t, &r, depth, weight.r, next));
    }
    return colour_scale(sum, 1.0 / rays);
}

/* Looks the light gathered at x (shading normal ns) up in t's cache under
 * its accuracy times reach: the camera's points (bounce 0) blend every
 * valid record, a gathering ray's hit takes one (t's hint first). */
static int trace_look_up(const Tracer *t, int bounce, double reach, Vec3 x, Vec3 ns, Colour *g)
{
    if (bounce == 0)
        return gicache_lookup(t->gicache, 0, reach, x, ns, g);
    return gicache_any(t->gicache, bounce, reach, x, ns, t->gicache_hint, g);
}

/* Returns the light a diffuse surface of colour C (sh's) and weight kd
 * reflects of what its gathering rays bring: kd C * mean / 255. */
static Colour trace_indirect(const Tracer *t, const Shade *sh, Vec3 n, Vec3 ns, int depth,
                             Colour weight, TracePath path, double kd)
{
    Colour g;

    if (!pass_shows_gathered(t, path.bounce))
        return colour(0, 0, 0);
    if (t->collect) { /* the irradiance cache's pre-pass: where, not how much */
        GatherPoint p = {sh->sp.point, sh->sp.error, sh->back, n, ns, path.bounce};
        gather_points_add(t->collect, &p);
        return colour(0, 0, 0);
    }
    if (t->gicache) {
        /* The camera's points blend the records (the picture shows their
         * seams otherwise); a gathering ray's hit, in the cache's pre-pass,
         * takes the first valid one (its light is averaged over the rays
         * of the record that cast it). */
        t->counts->lookups++;
        if (trace_look_up(t, path.bounce, 1, sh->sp.point, ns, &g) ||
            trace_look_up(t, path.bounce, GICACHE_FALLBACK_REACH, sh->sp.point, ns, &g))
            t->counts->served++;
        else
            g = trace_gather(t, sh, n, ns, depth, weight, path);
    } else {
        g = trace_gather(t, sh, n, ns, depth, weight, path);
    }

    return colour(kd * (sh->colour.r * g.r / 255), kd * (sh->colour.g * g.g / 255),
                  kd * (sh->colour.b * g.b / 255));
}

Colour trace_background(const Scene *scene, const Ray *ray)
{
    double up;

    if (!scene->has_sky)
        return scene->background;
    up = 0.5 + 0.5 * (double)ray->dir.y / (double)vec3_length(ray->dir);
    return colour_add(colour_scale(scene->sky, up), colour_scale(scene->background, 1 - up));
}

/* Returns shade_phong() when t's pass shows the own light of a point of
 * path (pass.h), else black. */
static inline Colour trace_own_phong(const Tracer *t, TracePath path, const Shade *sh,
                                     const NamedMaterial *pm, Vec3 n, Vec3 ns, Vec3 view,
                                     Colour weight)
{
    if (!pass_shows_own(t, path.bounce))
        return colour(0, 0, 0);
    return shade_phong(t, sh, pm, n, ns, view, weight);
}

/* Returns the colour of t's data pass (pass.h) at sh, the first surface
 * the camera's ray met (hit; n and ns its facing normals). */
static Colour trace_pass(const Tracer *t, const Ray *ray, const Hit *hit, const Shade *sh, Vec3 n,
                         Vec3 ns)
{
    double share = t->indirect.ao_samples > 0 ? trace_occlusion(t, sh, n, ns) : 1;

    return pass_value(t, ray, hit->t, sh, ns, share);
}

/* Returns the colour of a named material's surface at sh (the ray arriving
 * along ray at depth `depth` with weight; n and ns its facing normals):
 * the local term of its model (shade.h) and the mirror and refracted rays
 * its model sends (docs/scene-format.md). */
static Colour trace_named(const Tracer *t, const Ray *ray, const Shade *sh, Vec3 n, Vec3 ns,
                          int depth, Colour weight, TracePath path)
{
    const NamedMaterial *pm = &t->scene->named[sh->material.named];
    const Material *m = &sh->material;
    Vec3 view = vec3_normalize(vec3_neg(ray->dir));
    int entering = vec3_dot(ray->dir, sh->sp.normal) < 0, deeper = depth + 1 <= t->max_depth;
    double eta = entering ? 1 / m->ior : m->ior, f;
    Colour tint = colour_scale(sh->colour, 1.0 / 255), c, local;
    Vec3 bent;

    switch (pm->model) {
    case MODEL_MATTE:
        c = trace_own_phong(t, path, sh, pm, n, ns, view, weight);
        if (trace_gathers(t, path))
            c = colour_add(c, trace_indirect(t, sh, n, ns, depth, weight, path, pm->kd));
        return c;
    case MODEL_PLASTIC:
        /* A clear coat over the diffuse surface: Fresnel's share mirrors,
         * the rest is the surface's own light. */
        f = ray_fresnel(ray->dir, ns, eta);
        local = trace_own_phong(t, path, sh, pm, n, ns, view, colour_scale(weight, 1 - f));
        if (trace_gathers(t, path))
            local = colour_add(local, trace_indirect(t, sh, n, ns, depth,
                                                     colour_scale(weight, 1 - f), path, pm->kd));
        c = colour_scale(local, 1 - f);
        if (deeper && f > 0)
            c = colour_add(c, trace_named_secondary(t, ray, sh, n, ray_reflect(ray->dir, ns), RAY_REFLECTION,
                                              colour(f, f, f), depth + 1, weight, path));
        return c;
    case MODEL_METALLIC:
        /* A mirror tinted by its colour, and the highlights. */
        c = trace_own_phong(t, path, sh, pm, n, ns, view, weight);
        if (deeper)
            c = colour_add(c, trace_named_secondary(t, ray, sh, n, ray_reflect(ray->dir, ns), RAY_REFLECTION,
                                              tint, depth + 1, weight, path));
        return c;
    case MODEL_DIELECTRIC:
        /* Fresnel's share mirrors, the rest enters, tinted; all of it
         * mirrors on total internal reflection. Highlights show on the
         * outer side only: inside, the surface is glass to glass. */
        c = entering ? trace_own_phong(t, path, sh, pm, n, ns, view, weight) : colour(0, 0, 0);
        if (!deeper)
            return c;
        f = ray_refract(ray->dir, ns, eta, &bent) ? ray_fresnel(ray->dir, ns, eta) : 1;
        if (f < 1)
            c = colour_add(c, trace_named_secondary(t, ray, sh, n, bent, RAY_REFRACTION,
                                              colour_scale(tint, 1 - f), depth + 1, weight, path));
        if (f > 0)
            c = colour_add(c, trace_named_secondary(t, ray, sh, n, ray_reflect(ray->dir, ns), RAY_REFLECTION,
                                              colour(f, f, f), depth + 1, weight, path));
        return c;
    default: { /* Blinn-Phong: Whitted's sum, the weights already scaling
                * the local term */
        double r = m->reflection, tr = m->transparency;
        c = trace_own_phong(t, path, sh, pm, n, ns, view, weight);
        if (pm->kd > 0 && trace_gathers(t, path))
            c = colour_add(c, trace_indirect(t, sh, n, ns, depth, weight, path, pm->kd));
        if (!deeper)
            return c;
        if (tr > 0) {
            if (ray_refract(ray->dir, ns, eta, &bent))
                c = colour_add(c, trace_named_secondary(t, ray, sh, n, bent, RAY_REFRACTION,
                                                  colour(tr, tr, tr), depth + 1, weight, path));
            else
                r += tr; /* total internal reflection: the share T is mirrored */
        }
        if (r > 0)
            c = colour_add(c, trace_named_secondary(t, ray, sh, n, ray_reflect(ray->dir, ns), RAY_REFLECTION,
                                              colour(r, r, r), depth + 1, weight, path));
        return c;
    }
    }
}

/* Finds the object the ray meets first (visibility_nearest()); a primary
 * ray, at depth 0 of a path without a bounce, leaves untested the spheres
 * t proves out of its reach (render.c). */
static inline int trace_nearest(const Tracer *t, const Ray *ray, int depth, TracePath path,
                                Hit *hit)
{
    if (t->primary_skip != 0 && depth == 0 && path.bounce == 0)
        return visibility_nearest_skipping(t->scene, ray, t->primary_skip, hit);
    return visibility_nearest(t->scene, ray, INFINITY, hit);
}

static Colour trace_named_path(const Tracer *t, const Ray *ray, int depth, Colour weight,
                               TracePath path)
{
    const Scene *scene = t->scene;
    ShadeFootprint fp;
    Hit hit;
    Shade sh;
    Vec3 n, ns;

    if (!trace_nearest(t, ray, depth, path, &hit))
        return path.bounce == 0 && pass_shows_own(t, 0) ? trace_background(scene, ray)
                                                        : colour(0, 0, 0);
    sh = shade_at_footprint(scene, ray, &hit, trace_footprint_diff(t, &hit, depth, path), &fp);
    if (path.met) {
        path.met->t = (double)hit.t;
        path.met->behind = vec3_dot(ray->dir, sh.sp.normal) > 0;
    }
    n = ray_facing_normal(sh.sp.normal, ray->dir);
    ns = vec3_dot(sh.sp.shading, n) < 0 ? vec3_neg(sh.sp.shading) : sh.sp.shading;
    if (depth == 0 && path.bounce == 0 && pass_is_data(t->pass))
        return trace_pass(t, ray, &hit, &sh, n, ns);
    /* Ambient occlusion at the points the camera sees, where there is
     * ambient light to hide. */
    if (t->indirect.ao_samples > 0 && depth == 0 && path.bounce == 0 &&
        trace_named_ambient(scene, &scene->named[sh.material.named]))
        sh.ambient = trace_occlusion(t, &sh, n, ns);
    return trace_named(t, ray, &sh, n, ns, depth, weight, path);
}

/* The course's rule, for a ray of a course scene (trace.h). */
static Colour trace_path(const Tracer *t, const Ray *ray, int depth, double weight,
                         TracePath path)
{
    const Scene *scene = t->scene;
    ShadeFootprint fp;
    Hit hit;
    Shade sh;
    Vec3 n, ns;
    Colour c;
    double r, tr, own;

    if (!trace_nearest(t, ray, depth, path, &hit))
        return path.bounce == 0 && pass_shows_own(t, 0) ? scene->background : colour(0, 0, 0);
    sh = shade_at_footprint(scene, ray, &hit, trace_footprint_diff(t, &hit, depth, path), &fp);
    if (path.met) {
        path.met->t = (double)hit.t;
        path.met->behind = vec3_dot(ray->dir, sh.sp.normal) > 0;
    }
    /* n, the surface's normal facing the ray, decides where secondary rays
     * start; ns, the shading normal on n's side, how light and mirrors
     * behave. They are the same but on smooth triangles. */
    n = ray_facing_normal(sh.sp.normal, ray->dir);
    ns = vec3_dot(sh.sp.shading, n) < 0 ? vec3_neg(sh.sp.shading) : sh.sp.shading;
    r = sh.material.reflection;
    tr = sh.material.transparency;
    own = 1 - r - tr;
    own = own > 0 ? own : 0;
    if (depth == 0 && path.bounce == 0 && pass_is_data(t->pass))
        return trace_pass(t, ray, &hit, &sh, n, ns);
    if (own > 0 && t->indirect.ao_samples > 0 && depth == 0 && path.bounce == 0 &&
        trace_course_ambient(scene))
        sh.ambient = trace_occlusion(t, &sh, n, ns);
    c = pass_shows_own(t, path.bounce) ? shade_local(t, &sh, n, ns, weight * own)
                                        : colour(0, 0, 0);
    if (own > 0 && trace_gathers(t, path))
        c = colour_add(c, trace_indirect(t, &sh, n, ns, depth, colour(weight * own, weight * own,
                                                                      weight * own),
                                         path, 1));
    c = colour_scale(c, own);
    if (depth + 1 > t->max_depth)
        return c;
    if (tr > 0) {
        /* Entering through the outer side, or leaving from inside. */
        int entering = vec3_dot(ray->dir, sh.sp.normal) < 0;
        double eta = entering ? 1 / sh.material.ior : sh.material.ior;
        Vec3 bent;

        if (ray_refract(ray->dir, ns, eta, &bent)) {
            c = colour_add(c, trace_secondary(t, ray, &sh, n, bent, RAY_REFRACTION, tr, depth + 1,
                                              weight, path));
        } else {
            r += tr; /* total internal reflection: the share T is mirrored */
        }
    }
    if (r > 0)
        c = colour_add(c, trace_secondary(t, ray, &sh, n, ray_reflect(ray->dir, ns), RAY_REFLECTION, r,
                                          depth + 1, weight, path));
    return c;
}
