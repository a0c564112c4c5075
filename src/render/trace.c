/* trace.c: nearest hits, shadows and recursive shading (see trace.h). */
#include "render/trace.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "accel/bvh.h"
#include "math/power.h"
#include "scene/texture.h"

/* Stores in *hit the object of kind, index and order crossed at t. */
static void trace_set_hit(Hit *hit, real t, ShapeKind kind, size_t index, unsigned order)
{
    hit->t = t;
    hit->kind = kind;
    hit->index = index;
    hit->order = order;
}

/* Says whether a crossing at t of the object of position order beats *hit
 * (t is at most hit->t): it is nearer, or as near and listed first. */
static int trace_beats(const Hit *hit, int found, real t, unsigned order)
{
    return !found || t < hit->t || order < hit->order;
}

/* Continues trace_nearest() over planes, after *hit (when found); returns
 * whether any object is hit. */
static int trace_nearest_planes(const Scene *scene, const Ray *ray, real tmax, Hit *hit,
                                int found)
{
    /* An exact tie with an earlier-listed object must be seen: the bound is
     * the next real above the best t. */
    real bound = found ? real_next(hit->t, 1) : tmax;

    for (size_t k = 0; k < scene->plane_count; k++) {
        const Plane *pl = &scene->planes[k];
        real t;
        if (plane_intersect(pl, ray, 0, bound, &t) && trace_beats(hit, found, t, pl->order)) {
            trace_set_hit(hit, t, SHAPE_PLANE, k, pl->order);
            found = 1;
            bound = real_next(t, 1);
        }
    }
    return found;
}

/* Continues trace_nearest() over triangles, tested one by one. */
static int trace_nearest_triangles(const Scene *scene, const Ray *ray, real tmax, Hit *hit,
                                   int found)
{
    real bound = found ? real_next(hit->t, 1) : tmax;

    for (size_t k = 0; k < scene->triangle_count; k++) {
        const Triangle *tri = &scene->triangles[k];
        real t;
        if (triangle_intersect(tri, ray, 0, bound, &t) &&
            trace_beats(hit, found, t, tri->order)) {
            trace_set_hit(hit, t, SHAPE_TRIANGLE, k, tri->order);
            found = 1;
            bound = real_next(t, 1);
        }
    }
    return found;
}

/* trace_nearest() through the hierarchy, planes aside. */
static int trace_find_accel(const Scene *scene, const Ray *ray, real tmax, Hit *hit)
{
    BvhHit bh;
    int found = bvh_nearest(scene->accel, ray, tmax, &bh);

    if (found)
        trace_set_hit(hit, bh.t, bh.prim & BVH_TRIANGLE ? SHAPE_TRIANGLE : SHAPE_SPHERE,
                      bh.prim & ~BVH_TRIANGLE, bh.order);
    return scene->plane_count > 0 ? trace_nearest_planes(scene, ray, tmax, hit, found) : found;
}

/* trace_nearest(), inlined into trace_ray(): its hottest caller. */
static inline int trace_find(const Scene *scene, const Ray *ray, real tmax, Hit *hit)
{
    int found = 0;
    size_t best = 0;

    if (scene->accel)
        return trace_find_accel(scene, ray, tmax, hit);
    for (size_t k = 0; k < scene->sphere_count; k++) {
        real t;
        const Sphere *s = &scene->spheres[k];
        /* The interval is open at tmax, so an exact tie keeps the earlier
         * sphere. sphere_hit() is inline: this loop is the course scene's
         * hottest. */
        if (sphere_hit(s->centre, s->radius, ray, 0, tmax, &t)) {
            tmax = t;
            best = k;
            found = 1;
        }
    }
    if (found)
        trace_set_hit(hit, tmax, SHAPE_SPHERE, best, scene->spheres[best].order);
    if (scene->plane_count > 0)
        found = trace_nearest_planes(scene, ray, tmax, hit, found);
    if (scene->triangle_count > 0)
        found = trace_nearest_triangles(scene, ray, tmax, hit, found);
    return found;
}

int trace_nearest(const Scene *scene, const Ray *ray, real tmax, Hit *hit)
{
    return trace_find(scene, ray, tmax, hit);
}

int trace_occluded(const Scene *scene, const Ray *ray, real tmax)
{
    real t;

    for (size_t k = 0; k < scene->plane_count; k++)
        if (plane_intersect(&scene->planes[k], ray, 0, tmax, &t))
            return 1;
    if (scene->accel)
        return bvh_occluded(scene->accel, ray, tmax);
    for (size_t k = 0; k < scene->sphere_count; k++)
        if (sphere_hit(scene->spheres[k].centre, scene->spheres[k].radius, ray, 0, tmax, &t))
            return 1;
    for (size_t k = 0; k < scene->triangle_count; k++)
        if (triangle_intersect(&scene->triangles[k], ray, 0, tmax, &t))
            return 1;
    return 0;
}

/* Multiplies *share by the transparency of material m once per crossing
 * (crossings of them); returns 0 once nothing is left, else 1. */
static int trace_attenuate(double *share, const Material *m, int crossings)
{
    for (int i = 0; i < crossings; i++)
        *share *= m->transparency;
    return *share > 0;
}

/* Multiplies *share by the transparency of every plane the ray crosses at
 * 0 < t < tmax; returns 0 once nothing is left, else 1. */
static int trace_attenuate_planes(const Scene *scene, const Ray *ray, real tmax,
                                  double *share)
{
    real t;

    for (size_t k = 0; k < scene->plane_count; k++) {
        const Plane *pl = &scene->planes[k];
        if (!trace_attenuate(share, &pl->material, plane_intersect(pl, ray, 0, tmax, &t)))
            return 0;
    }
    return 1;
}

enum { TRACE_CROSSINGS_MAX = 64 }; /* crossings listed before giving up */

/* A surface a shadow ray crosses, and how many times. */
typedef struct {
    uint32_t prim; /* the hierarchy's primitive reference */
    int crossings; /* 1 or 2 */
} TraceCrossing;

/* The crossings of a shadow ray the hierarchy lists. */
typedef struct {
    const Scene *scene;
    TraceCrossing c[TRACE_CROSSINGS_MAX];
    int n;
} TraceCrossings;

/* bvh_crossings()'s visit: keeps the crossing; returns -2 at an opaque
 * surface (no light passes) and -1 when the list is full. */
static int trace_keep_crossing(void *ctx, uint32_t prim, int crossings)
{
    TraceCrossings *tc = ctx;
    const Scene *scene = tc->scene;
    const Material *m = prim & BVH_TRIANGLE
                            ? scene_material_of(scene, &scene->triangles[prim & ~BVH_TRIANGLE])
                            : &scene->spheres[prim].material;

    if (!(m->transparency > 0))
        return -2;
    if (tc->n == TRACE_CROSSINGS_MAX)
        return -1;
    tc->c[tc->n].prim = prim;
    tc->c[tc->n].crossings = crossings;
    tc->n++;
    return 0;
}

/* trace_transmittance() through the hierarchy: the crossings it lists are
 * sorted and multiplied in the order of the loop below (spheres, planes,
 * triangles, each by index), so the product has the very same bits.
 * Returns -1 when there are too many crossings to list. */
static double trace_transmittance_accel(const Scene *scene, const Ray *ray, real tmax)
{
    TraceCrossings tc;
    int rc, i = 0, n;
    double share = 1;

    tc.scene = scene;
    tc.n = 0;
    rc = bvh_crossings(scene->accel, ray, tmax, trace_keep_crossing, &tc);
    if (rc == -2)
        return 0;
    if (rc < 0)
        return -1;
    n = tc.n;
    /* Insertion sort by reference (spheres first: BVH_TRIANGLE is the top
     * bit): the lists are short. */
    for (int j = 1; j < n; j++) {
        TraceCrossing c = tc.c[j];
        int k = j;
        while (k > 0 && c.prim < tc.c[k - 1].prim) {
            tc.c[k] = tc.c[k - 1];
            k--;
        }
        tc.c[k] = c;
    }
    for (; i < n && !(tc.c[i].prim & BVH_TRIANGLE); i++)
        if (!trace_attenuate(&share, &scene->spheres[tc.c[i].prim].material, tc.c[i].crossings))
            return 0;
    if (!trace_attenuate_planes(scene, ray, tmax, &share))
        return 0;
    for (; i < n; i++)
        if (!trace_attenuate(
                &share, scene_material_of(scene, &scene->triangles[tc.c[i].prim & ~BVH_TRIANGLE]),
                tc.c[i].crossings))
            return 0;
    return share;
}

double trace_transmittance(const Scene *scene, const Ray *ray, real tmax)
{
    double share = 1;
    real t;

    if (scene->accel) {
        double s = trace_transmittance_accel(scene, ray, tmax);
        if (s >= 0)
            return s;
    }
    for (size_t k = 0; k < scene->sphere_count; k++) {
        const Sphere *s = &scene->spheres[k];
        if (!trace_attenuate(&share, &s->material, sphere_crossings(s, ray, 0, tmax)))
            return 0;
    }
    if (!trace_attenuate_planes(scene, ray, tmax, &share))
        return 0;
    for (size_t k = 0; k < scene->triangle_count; k++) {
        const Triangle *tri = &scene->triangles[k];
        if (!trace_attenuate(&share, scene_material_of(scene, tri),
                             triangle_intersect(tri, ray, 0, tmax, &t)))
            return 0;
    }
    return share;
}

/* What shading needs to know about the point a ray hit. */
typedef struct {
    SurfacePoint sp;          /* the point, its outward normal and error */
    const Material *material; /* the object's material */
    Colour colour;            /* Ci: the material's colour or its texture's */
} Shade;

/* Returns the shading record of hit, crossed by ray. */
static inline Shade trace_shade(const Scene *scene, const Ray *ray, const Hit *hit)
{
    Shade sh;
    double uv[2] = {0, 0};
    int clamp_v = 0;

    switch (hit->kind) {
    case SHAPE_SPHERE: {
        const Sphere *s = &scene->spheres[hit->index];
        sh.sp = sphere_surface_at(s, ray_at(ray, hit->t));
        sh.material = &s->material;
        if (s->material.texture >= 0)
            sphere_uv(sh.sp.normal, uv);
        clamp_v = 1;
        break;
    }
    case SHAPE_PLANE: {
        const Plane *pl = &scene->planes[hit->index];
        sh.sp = plane_surface_at(pl, ray_at(ray, hit->t));
        sh.material = &pl->material;
        if (pl->material.texture >= 0)
            plane_uv(pl, sh.sp.point, uv);
        break;
    }
    default: {
        const Triangle *tri = &scene->triangles[hit->index];
        sh.sp = triangle_surface_at(tri, scene_shading_of(scene, tri), ray, uv);
        sh.material = scene_material_of(scene, tri);
        break;
    }
    }
    if (sh.material->texture >= 0)
        sh.colour = texture_lookup(&scene->textures[sh.material->texture], uv[0], uv[1],
                                   sh.material->filter, clamp_v);
    else
        sh.colour = sh.material->colour;
    return sh;
}

/* The largest channel of c. */
static double trace_max_channel(Colour c)
{
    return fmax(c.r, fmax(c.g, c.b));
}

/* Keeps d in cut; returns 1, or 0 when there is no memory for it. */
static int trace_defer(TraceCut *cut, const TraceDeferred *d)
{
    if (cut->deferred_count == cut->deferred_capacity) {
        size_t capacity = cut->deferred_capacity ? 2 * cut->deferred_capacity : 64;
        TraceDeferred *grown;

        if (capacity > SIZE_MAX / sizeof *grown ||
            !(grown = realloc(cut->deferred, capacity * sizeof *grown)))
            return 0;
        cut->deferred = grown;
        cut->deferred_capacity = capacity;
    }
    cut->deferred[cut->deferred_count++] = *d;
    return 1;
}

/* Says whether cut allows leaving out d, a ray whose colour adds at most
 * most to its sample: when most is below the cut-off and d could be kept,
 * most goes to cut->skipped (see render.c for how the pixel's bytes stay
 * exact). */
static int trace_cut_ray(TraceCut *cut, double most, const TraceDeferred *d)
{
    if (!cut || !(most < cut->cutoff) || !trace_defer(cut, d))
        return 0;
    cut->skipped += most;
    return 1;
}

/* Returns the shadow ray from the shaded point sh (whose surface normal n
 * faces the viewer) to the light in direction to_light (towards a point
 * light: the vector to it; a distant light: its unit to_light), and in
 * *tmax where it ends. */
static inline Ray trace_shadow_ray(const Shade *sh, Vec3 n, const Light *light, Vec3 to_light,
                                   real *tmax)
{
    Ray shadow;

    shadow.origin = ray_offset_origin(sh->sp.point, sh->sp.error, n, to_light);
    /* To a point light, the segment ends at the light (t = 1); towards a
     * distant one, the ray is unbounded. */
    shadow.dir = light->distant ? to_light : vec3_sub(light->position, shadow.origin);
    *tmax = light->distant ? INFINITY : 1;
    return shadow;
}

/* Returns the share E of the light that passes along shadow up to tmax,
 * casting it: 1 or 0 in opaque scenes, the product of the transparencies
 * crossed in others. */
static inline double trace_light_share(const Scene *scene, const Ray *shadow, real tmax,
                                       RayCounts *counts)
{
    counts->shadow++;
    if (scene->has_transparency)
        return trace_transmittance(scene, shadow, tmax);
    return trace_occluded(scene, shadow, tmax) ? 0 : 1;
}

/* Says whether cut allows leaving out the shadow ray from sh towards light
 * (see trace_shadow_ray()), the light adding lit (a colour, E = 1) to a ray
 * reached with weight: E is then taken as 0, and weight times lit's largest
 * channel is what the pixel may lack (E is in [0, 1]). */
static inline int trace_cut_shadow(TraceCut *cut, double weight, Colour lit, const Shade *sh,
                                   Vec3 n, const Light *light, Vec3 to_light)
{
    TraceDeferred d;
    double most;

    if (!cut)
        return 0;
    most = weight * trace_max_channel(lit);
    if (!(most < cut->cutoff))
        return 0;
    d.ray = trace_shadow_ray(sh, n, light, to_light, &d.tmax);
    d.kind = TRACE_SHADOW;
    d.depth = 0;
    d.weight = weight;
    d.lit = lit;
    return trace_cut_ray(cut, most, &d);
}

/* Returns the share E of the light that reaches the shaded point sh from
 * light (see trace_shadow_ray()), casting one shadow ray. */
static inline double trace_visibility(const Scene *scene, const Shade *sh, Vec3 n,
                                      const Light *light, Vec3 to_light, RayCounts *counts)
{
    real tmax;
    Ray shadow = trace_shadow_ray(sh, n, light, to_light, &tmax);

    return trace_light_share(scene, &shadow, tmax, counts);
}

/* Returns the light's direct contribution, E cos_a (Ci * Cs) / 255, at the
 * shaded point sh: ns is its shading normal and n its surface normal, both
 * facing the viewer; 0 when cut allows leaving out its shadow ray for a
 * term that reaches the pixel with weight. */
static inline Colour trace_direct(const Scene *scene, const Light *light, const Shade *sh, Vec3 n,
                                  Vec3 ns, double weight, TraceCut *cut, RayCounts *counts)
{
    Vec3 to_light = vec3_sub(light->position, sh->sp.point);
    double cos_a = vec3_dot(ns, vec3_normalize(to_light)), e;
    Colour ci = sh->colour, lit;

    /* Facing away from the light (or the light on the point: NaN) means no
     * light, whatever E is: no shadow ray needed. */
    if (!(cos_a > 0))
        return colour(0, 0, 0);
    lit = colour(cos_a * (ci.r * light->colour.r / 255), cos_a * (ci.g * light->colour.g / 255),
                 cos_a * (ci.b * light->colour.b / 255));
    if (trace_cut_shadow(cut, weight, lit, sh, n, light, to_light))
        return colour(0, 0, 0);
    e = trace_visibility(scene, sh, n, light, to_light, counts);
    if (!(e > 0))
        return colour(0, 0, 0);
    if (e != 1)
        return colour((cos_a * e) * (ci.r * light->colour.r / 255),
                      (cos_a * e) * (ci.g * light->colour.g / 255),
                      (cos_a * e) * (ci.b * light->colour.b / 255));
    return lit;
}

/* Returns what a light of colour Cs adds to a point of colour ci for
 * material pm per unit of E i: kd cos_a Ci Cs / 255 + ks max(0, N . H)^alpha
 * Cs, with ns the shading normal, l and view unit vectors towards the light
 * and the viewer. */
static inline Colour trace_phong_light(const PhongMaterial *pm, Colour ci, Colour cs, double cos_a,
                                       Vec3 ns, Vec3 l, Vec3 view)
{
    double nh = vec3_dot(ns, vec3_normalize(vec3_add(l, view)));
    double spec = nh > 0 ? pm->ks * power(nh < 1 ? nh : 1, pm->shininess) : 0;

    return colour(pm->kd * cos_a * (ci.r * cs.r / 255) + spec * cs.r,
                  pm->kd * cos_a * (ci.g * cs.g / 255) + spec * cs.g,
                  pm->kd * cos_a * (ci.b * cs.b / 255) + spec * cs.b);
}

/* Returns the Blinn-Phong local term of docs/scene-format.md at sh, for
 * material pm, seen from direction view (unit, towards the viewer), with
 * facing normals n and ns (see trace_direct()):
 *     ka Ia Ci / 255 + sum over lights of E i (kd max(0, N . L) Ci Cs / 255
 *                                              + ks max(0, N . H)^alpha Cs)
 * with H the unit vector halfway between L and view; leaves out the shadow
 * rays cut allows for a term that reaches the pixel with weight. */
static inline Colour trace_phong(const Scene *scene, const Shade *sh, const PhongMaterial *pm,
                                 Vec3 n, Vec3 ns, Vec3 view, double weight, TraceCut *cut,
                                 RayCounts *counts)
{
    Colour ci = sh->colour, c;

    c = colour(pm->ka * (scene->ambient.r * ci.r / 255), pm->ka * (scene->ambient.g * ci.g / 255),
               pm->ka * (scene->ambient.b * ci.b / 255));
    for (size_t i = 0; i < scene->light_count; i++) {
        const Light *light = &scene->lights[i];
        Vec3 to_light = light->distant ? light->to_light
                                       : vec3_sub(light->position, sh->sp.point);
        Vec3 l = light->distant ? to_light : vec3_normalize(to_light);
        double cos_a = vec3_dot(ns, l), e;
        Colour lit;
        int known = 0;

        if (!(cos_a > 0))
            continue;
        if (cut) {
            lit = trace_phong_light(pm, ci, light->colour, cos_a, ns, l, view);
            known = 1;
            if (trace_cut_shadow(cut, weight, colour_scale(lit, light->intensity), sh, n, light,
                                 to_light))
                continue;
        }
        e = trace_visibility(scene, sh, n, light, to_light, counts) * light->intensity;
        if (!(e > 0))
            continue;
        if (!known)
            lit = trace_phong_light(pm, ci, light->colour, cos_a, ns, l, view);
        c = colour_add(c, colour_scale(lit, e));
    }
    return c;
}

/* Returns the local term: the ambient light plus every light's direct
 * contribution, at sh with facing normals n and ns (see trace_direct(),
 * also for weight and cut). */
static inline Colour trace_local(const Scene *scene, const Shade *sh, Vec3 n, Vec3 ns,
                                 double weight, TraceCut *cut, RayCounts *counts)
{
    Colour c = trace_direct(scene, &scene->lights[0], sh, n, ns, weight, cut, counts);

    for (size_t i = 1; i < scene->light_count; i++)
        c = colour_add(c, trace_direct(scene, &scene->lights[i], sh, n, ns, weight, cut, counts));
    if (scene->has_ambient)
        c = colour_add(colour(scene->ambient.r * sh->colour.r / 255,
                              scene->ambient.g * sh->colour.g / 255,
                              scene->ambient.b * sh->colour.b / 255),
                       c);
    return c;
}

/* The colour along a ray of depth `depth`, reached with `weight` (the
 * product of the mirror and transparency weights from the primary ray),
 * leaving out the secondary rays cut may skip (cut NULL: none). */
static Colour trace_path(const Scene *scene, const Ray *ray, int depth, int max_depth,
                         double weight, TraceCut *cut, RayCounts *counts);

/* Counts a mirror or refracted ray (kind) as cast. */
static inline void trace_count_secondary(TraceRayKind kind, RayCounts *counts)
{
    if (kind == TRACE_REFRACTION)
        counts->refraction++;
    else
        counts->reflection++;
}

/* Returns share times the colour seen along the ray of kind `kind` leaving
 * sh in direction dir at depth `depth`, reached with weight times share, or
 * 0 when cut allows leaving it out: its colour is at most the bound for its
 * depth, so the pixel lacks at most weight x share x bound of it. */
static inline Colour trace_secondary(const Scene *scene, const Shade *sh, Vec3 n, Vec3 dir,
                                     TraceRayKind kind, double share, int depth, int max_depth,
                                     double weight, TraceCut *cut, RayCounts *counts)
{
    TraceDeferred d;

    weight *= share;
    d.ray.dir = dir;
    d.ray.origin = ray_offset_origin(sh->sp.point, sh->sp.error, n, dir);
    if (cut) {
        d.kind = kind;
        d.depth = depth;
        d.tmax = INFINITY;
        d.weight = weight;
        d.lit = colour(0, 0, 0);
        if (trace_cut_ray(cut, weight * trace_cut_bound(cut, max_depth - depth), &d))
            return colour(0, 0, 0);
    }
    trace_count_secondary(kind, counts);
    return colour_scale(trace_path(scene, &d.ray, depth, max_depth, weight, cut, counts), share);
}

Colour trace_deferred(const Scene *scene, TraceDeferred d, int max_depth, TraceCut *cut,
                      RayCounts *counts)
{
    if (d.kind == TRACE_SHADOW)
        return colour_scale(d.lit, d.weight * trace_light_share(scene, &d.ray, d.tmax, counts));
    trace_count_secondary(d.kind, counts);
    return colour_scale(trace_path(scene, &d.ray, d.depth, max_depth, d.weight, cut, counts),
                        d.weight);
}

Colour trace_ray(const Scene *scene, const Ray *ray, int depth, int max_depth,
                 RayCounts *counts)
{
    return trace_path(scene, ray, depth, max_depth, 1, NULL, counts);
}

Colour trace_ray_cut(const Scene *scene, const Ray *ray, int max_depth, TraceCut *cut,
                     RayCounts *counts)
{
    return trace_path(scene, ray, 0, max_depth, 1, cut, counts);
}

static Colour trace_path(const Scene *scene, const Ray *ray, int depth, int max_depth,
                         double weight, TraceCut *cut, RayCounts *counts)
{
    Hit hit;
    Shade sh;
    Vec3 n, ns;
    Colour c;
    double r, t, own;

    if (!trace_find(scene, ray, INFINITY, &hit))
        return scene->background;
    sh = trace_shade(scene, ray, &hit);
    /* n, the surface's normal facing the ray, decides where secondary rays
     * start; ns, the shading normal on n's side, how light and mirrors
     * behave. They are the same but on smooth triangles. */
    n = ray_facing_normal(sh.sp.normal, ray->dir);
    ns = vec3_dot(sh.sp.shading, n) < 0 ? vec3_neg(sh.sp.shading) : sh.sp.shading;
    r = sh.material->reflection;
    t = sh.material->transparency;
    own = 1 - r - t;
    if (sh.material->phong >= 0)
        /* Whitted's sum: the Blinn-Phong weights already scale the local
         * term. */
        c = trace_phong(scene, &sh, &scene->phong[sh.material->phong], n, ns,
                        vec3_normalize(vec3_neg(ray->dir)), weight, cut, counts);
    else
        c = colour_scale(trace_local(scene, &sh, n, ns, weight * (own > 0 ? own : 0), cut, counts),
                         own > 0 ? own : 0);
    if (depth + 1 > max_depth)
        return c;
    if (t > 0) {
        /* Entering through the outer side, or leaving from inside. */
        int entering = vec3_dot(ray->dir, sh.sp.normal) < 0;
        double eta = entering ? 1 / sh.material->ior : sh.material->ior;
        Vec3 bent;

        if (ray_refract(ray->dir, ns, eta, &bent)) {
            c = colour_add(c, trace_secondary(scene, &sh, n, bent, TRACE_REFRACTION, t, depth + 1,
                                              max_depth, weight, cut, counts));
        } else {
            r += t; /* total internal reflection: the share T is mirrored */
        }
    }
    if (r > 0)
        c = colour_add(c, trace_secondary(scene, &sh, n, ray_reflect(ray->dir, ns),
                                          TRACE_REFLECTION, r, depth + 1, max_depth, weight, cut,
                                          counts));
    return c;
}

void trace_cut_init(TraceCut *cut, const Scene *scene, double cutoff)
{
    double lights = 0, local = 0, bg = trace_max_channel(scene->background);

    cut->cutoff = cutoff;
    cut->skipped = 0;
    cut->deferred = NULL;
    cut->deferred_count = 0;
    cut->deferred_capacity = 0;
    for (size_t i = 0; i < scene->light_count; i++)
        lights += trace_max_channel(scene->lights[i].colour) *
                  (scene->phong_count > 0 ? scene->lights[i].intensity : 1);
    if (scene->phong_count == 0) {
        /* The course's rule: local <= Ca + sum of Cs (Ci <= 255, cos <= 1,
         * E <= 1), and C = (1 - R - T) local + R Cr + T Ct is a mean of
         * local, Cr and Ct (weights >= 0 adding to 1; on total internal
         * reflection too), so no ray sees more than max(background,
         * local) at any depth. */
        local = (scene->has_ambient ? trace_max_channel(scene->ambient) : 0) + lights;
        cut->base = fmax(bg, local);
        cut->per_level = 0;
        return;
    }
    /* Blinn-Phong: local <= ka Ia + sum of i (kd + ks) Cs, and C = local +
     * rho Cr + tau Ct with rho + tau <= 1: a ray that may still spawn k
     * levels of secondary rays sees at most max(background, local) +
     * k local. */
    for (size_t i = 0; i < scene->phong_count; i++) {
        const PhongMaterial *m = &scene->phong[i];
        local = fmax(local, m->ka * trace_max_channel(scene->ambient) + (m->kd + m->ks) * lights);
    }
    cut->base = fmax(bg, local);
    cut->per_level = local;
}

void trace_cut_free(TraceCut *cut)
{
    free(cut->deferred);
    cut->deferred = NULL;
    cut->deferred_count = 0;
    cut->deferred_capacity = 0;
}
