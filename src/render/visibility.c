/* visibility.c: nearest hits and shadow rays (see visibility.h). */
#include "render/visibility.h"

#include <math.h>
#include <stdint.h>

#include "accel/bvh.h"
#include "accel/light_buffer.h"

/* Finds where the ray first crosses shape k of kind with 0 < t < tmax;
 * returns 1 with *t, or 0. */
static int visibility_hit(const Scene *scene, ShapeKind kind, size_t k, const Ray *ray, real tmax,
                          real *t)
{
    return shape_intersect(kind, scene_items(scene, kind), k, ray, 0, tmax, t);
}

/* Returns how many times the ray crosses shape k of kind at 0 < t < tmax. */
static int visibility_crossings(const Scene *scene, ShapeKind kind, size_t k, const Ray *ray,
                                real tmax)
{
    return shape_crossings(kind, scene_items(scene, kind), k, ray, 0, tmax);
}

/* Stores in *hit the object of kind, index and order crossed at t. */
static void visibility_set_hit(Hit *hit, real t, ShapeKind kind, size_t index, unsigned order)
{
    hit->t = t;
    hit->kind = kind;
    hit->index = index;
    hit->order = order;
}

/* Continues visibility_nearest() over the shapes of kind, one by one,
 * after *hit (when found); returns whether any object is hit. */
static int visibility_nearest_of(const Scene *scene, ShapeKind kind, const Ray *ray, real tmax,
                                 Hit *hit, int found)
{
    /* An exact tie with an earlier-listed object must be seen: the bound is
     * the next real above the best t. */
    real bound = found ? real_next(hit->t, 1) : tmax;
    size_t n = scene_count_of(scene, kind);

    for (size_t k = 0; k < n; k++) {
        real t;
        unsigned order;
        if (!visibility_hit(scene, kind, k, ray, bound, &t))
            continue;
        /* t is at most hit->t: it wins when nearer, or as near and listed
         * first. */
        order = scene_order_of(scene, kind, k);
        if (!found || t < hit->t || order < hit->order) {
            visibility_set_hit(hit, t, kind, k, order);
            found = 1;
            bound = real_next(t, 1);
        }
    }
    return found;
}

/* The unbounded kinds, which the hierarchy leaves to the loops, and the
 * bounded ones, as masks of Scene.kinds. */
#define VISIBILITY_BOUNDED SHAPE_BOUNDED
#define VISIBILITY_UNBOUNDED ((1u << SHAPE_KINDS) - 1 - VISIBILITY_BOUNDED)

/* Returns the first kind of mask (not 0), which the caller then clears. */
static inline ShapeKind visibility_first(unsigned mask)
{
    return (ShapeKind)__builtin_ctz(mask);
}

/* visibility_nearest() through the hierarchy, the unbounded shapes of
 * the kinds in mask aside. */
static inline __attribute__((always_inline)) int
visibility_nearest_accel(const Scene *scene, const Ray *ray, real tmax, unsigned mask, Hit *hit)
{
    BvhHit bh;
    int found = bvh_nearest(scene->accel, ray, tmax, &bh);

    if (found)
        visibility_set_hit(hit, bh.t, (ShapeKind)bvh_kind(bh.prim), bvh_index(bh.prim), bh.order);
    for (unsigned m = scene->kinds & VISIBILITY_UNBOUNDED & mask; m != 0; m &= m - 1)
        found = visibility_nearest_of(scene, visibility_first(m), ray, tmax, hit, found);
    return found;
}

/* Says whether the ray crosses sphere k at 0 < t < *tmax, and then
 * lowers *tmax to t and sets *best to k. The interval is open at *tmax:
 * the spheres tested in the file's order, an exact tie keeps the
 * earlier. */
static inline int visibility_sphere_nearer(const Scene *scene, size_t k, const Ray *ray,
                                           real *tmax, size_t *best)
{
    const Sphere *s = &scene_spheres(scene)[k];
    real t;

    if (!sphere_hit(s->centre, s->radius, ray, 0, *tmax, &t))
        return 0;
    *tmax = t;
    *best = k;
    return 1;
}

/* visibility_nearest() without the eye's light buffer, over the bounded
 * shapes and the unbounded ones of the kinds in mask. Inline: the course
 * scene's every ray comes here. */
static inline __attribute__((always_inline)) int
visibility_nearest_in(const Scene *scene, const Ray *ray, real tmax, unsigned mask, Hit *hit);

int visibility_nearest_among(const Scene *scene, const Ray *ray, real tmax, unsigned kinds,
                             Hit *hit)
{
    return visibility_nearest_in(scene, ray, tmax, kinds | VISIBILITY_BOUNDED, hit);
}

int visibility_nearest(const Scene *scene, const Ray *ray, real tmax, Hit *hit)
{
    /* A primary ray of a pinhole camera asks the eye's light buffer, a
     * scene of spheres alone having one. */
    if (scene->eye_buffer && vec3_equal(ray->origin, scene->eye_buffer->centre)) {
        real t;
        size_t k;
        int rc = light_buffer_nearest(scene->eye_buffer, ray, tmax, &t, &k);
        if (rc >= 0) {
            if (rc)
                visibility_set_hit(hit, t, SHAPE_SPHERE, k, scene_spheres(scene)[k].order);
            return rc;
        }
    }
    return visibility_nearest_in(scene, ray, tmax, ~0u, hit);
}

static inline __attribute__((always_inline)) int
visibility_nearest_in(const Scene *scene, const Ray *ray, real tmax, unsigned mask, Hit *hit)
{
    int found = 0;
    size_t best = 0;

    if (scene->accel)
        return visibility_nearest_accel(scene, ray, tmax, mask, hit);
    /* sphere_hit() is inline: this loop is the course scene's hottest. */
    for (size_t k = 0; k < scene_count_of(scene, SHAPE_SPHERE); k++)
        if (visibility_sphere_nearer(scene, k, ray, &tmax, &best))
            found = 1;
    if (found)
        visibility_set_hit(hit, tmax, SHAPE_SPHERE, best, scene_spheres(scene)[best].order);
    for (unsigned m = scene->kinds & mask & ~(1u << SHAPE_SPHERE); m != 0; m &= m - 1)
        found = visibility_nearest_of(scene, visibility_first(m), ray, tmax, hit, found);
    return found;
}

/* The most spheres visibility_frustum_clear() names in its skip. */
enum { VISIBILITY_SKIP_MAX = 64 };

int visibility_frustum_clear(const Scene *scene, const Frustum *f, uint64_t *skip)
{
    size_t n = scene_count_of(scene, SHAPE_SPHERE);
    int clear = 1;

    *skip = 0;
    if ((scene->kinds & VISIBILITY_UNBOUNDED) != 0)
        return 0;
    if (scene->accel)
        return bvh_frustum_clear(scene->accel, f);
    if ((scene->kinds & ~(1u << SHAPE_SPHERE)) != 0)
        return 0;
    /* Past VISIBILITY_SKIP_MAX spheres, only whether all are missed. */
    for (size_t k = 0; k < n && (clear || n <= VISIBILITY_SKIP_MAX); k++) {
        const Sphere *s = &scene_spheres(scene)[k];
        if (!frustum_misses_sphere(f, s->centre, s->radius))
            clear = 0;
        else if (n <= VISIBILITY_SKIP_MAX)
            *skip |= UINT64_C(1) << k;
    }
    if (clear)
        *skip = 0;
    return clear;
}

int visibility_nearest_skipping(const Scene *scene, const Ray *ray, uint64_t skip, Hit *hit)
{
    size_t n = scene_count_of(scene, SHAPE_SPHERE), best = 0;
    uint64_t keep = n < VISIBILITY_SKIP_MAX ? (UINT64_C(1) << n) - 1 : ~UINT64_C(0);
    real tmax = INFINITY;
    int found = 0;

    /* As visibility_nearest_in()'s loop, in the same order. */
    for (keep &= ~skip; keep != 0; keep &= keep - 1)
        if (visibility_sphere_nearer(scene, (size_t)__builtin_ctzll(keep), ray, &tmax, &best))
            found = 1;
    if (found)
        visibility_set_hit(hit, tmax, SHAPE_SPHERE, best, scene_spheres(scene)[best].order);
    return found;
}

/* Says whether some shape of kind crosses the ray at 0 < t < tmax. */
static int visibility_occluded_by(const Scene *scene, ShapeKind kind, const Ray *ray, real tmax)
{
    size_t n = scene_count_of(scene, kind);
    real t;

    for (size_t k = 0; k < n; k++)
        if (visibility_hit(scene, kind, k, ray, tmax, &t))
            return 1;
    return 0;
}

int visibility_occluded(const Scene *scene, const Ray *ray, real tmax)
{
    uint32_t cache = BVH_NO_SLOT;

    return visibility_occluded_cached(scene, ray, tmax, &cache);
}

int visibility_occluded_cached(const Scene *scene, const Ray *ray, real tmax, uint32_t *cache)
{
    /* Any crossing will do, so the cached one may be tried first. */
    if (scene->accel && bvh_slot_occludes(scene->accel, *cache, ray, tmax))
        return 1;
    for (unsigned m = scene->kinds & VISIBILITY_UNBOUNDED; m != 0; m &= m - 1)
        if (visibility_occluded_by(scene, visibility_first(m), ray, tmax))
            return 1;
    if (scene->accel)
        return bvh_occluder(scene->accel, ray, tmax, cache);
    /* Spheres first, inline: the course scene's shadow rays meet nothing
     * else. */
    for (size_t k = 0; k < scene_count_of(scene, SHAPE_SPHERE); k++) {
        real t;
        if (sphere_hit(scene_spheres(scene)[k].centre, scene_spheres(scene)[k].radius, ray, 0, tmax,
                       &t))
            return 1;
    }
    for (unsigned m = scene->kinds & VISIBILITY_BOUNDED & ~(1u << SHAPE_SPHERE); m != 0; m &= m - 1)
        if (visibility_occluded_by(scene, visibility_first(m), ray, tmax))
            return 1;
    return 0;
}

int visibility_light_occluded(const Scene *scene, size_t light, const Ray *ray, real tmax,
                              uint32_t *cache)
{
    uint32_t none = BVH_NO_SLOT;

    if (!cache)
        cache = &none;
    if (scene->light_buffers && scene->light_buffers[light].first) {
        int rc = light_buffer_occluded(&scene->light_buffers[light], ray, tmax, cache);
        if (rc >= 0)
            return rc;
        /* The cache names a sphere, not the hierarchy's slot. */
        cache = &none;
    }
    return visibility_occluded_cached(scene, ray, tmax, cache);
}

/* Multiplies *share by a material's transparency once per crossing
 * (crossings of them); returns 0 once nothing is left, else 1. */
static int visibility_attenuate(double *share, double transparency, int crossings)
{
    for (int i = 0; i < crossings; i++)
        *share *= transparency;
    return *share > 0;
}

/* Multiplies *share by the transparency of every shape of kind the ray
 * crosses at 0 < t < tmax, by index; returns 0 once nothing is left. */
static int visibility_attenuate_by(const Scene *scene, ShapeKind kind, const Ray *ray, real tmax,
                                   double *share)
{
    size_t n = scene_count_of(scene, kind);

    for (size_t k = 0; k < n; k++)
        if (!visibility_attenuate(share, scene_material(scene, kind, k).transparency,
                                  visibility_crossings(scene, kind, k, ray, tmax)))
            return 0;
    return 1;
}

enum { VISIBILITY_CROSSINGS_MAX = 64 }; /* crossings listed before giving up */

/* A surface a shadow ray crosses, and how many times. */
typedef struct {
    uint32_t prim; /* the hierarchy's primitive reference */
    int crossings; /* 1 or 2 */
} VisibilityCrossing;

/* The crossings of a shadow ray the hierarchy lists. */
typedef struct {
    const Scene *scene;
    VisibilityCrossing c[VISIBILITY_CROSSINGS_MAX];
    int n;
} VisibilityCrossings;

/* Returns the transparency of the hierarchy's primitive prim. */
static double visibility_transparency_of(const Scene *scene, uint32_t prim)
{
    return scene_material(scene, (ShapeKind)bvh_kind(prim), bvh_index(prim)).transparency;
}

/* bvh_crossings()'s visit: keeps the crossing; returns -2 at an opaque
 * surface (no light passes) and -1 when the list is full. */
static int visibility_keep_crossing(void *ctx, uint32_t prim, int crossings)
{
    VisibilityCrossings *tc = ctx;

    if (!(visibility_transparency_of(tc->scene, prim) > 0))
        return -2;
    if (tc->n == VISIBILITY_CROSSINGS_MAX)
        return -1;
    tc->c[tc->n].prim = prim;
    tc->c[tc->n].crossings = crossings;
    tc->n++;
    return 0;
}

/* visibility_transmittance() through the hierarchy: the crossings it lists
 * are sorted and multiplied in the order of the loops below (ShapeKind's,
 * each kind by index), so the product has the very same bits. Returns -1
 * when there are too many crossings to list. */
static double visibility_transmittance_accel(const Scene *scene, const Ray *ray, real tmax)
{
    VisibilityCrossings tc;
    int rc, i = 0, n;
    double share = 1;

    tc.scene = scene;
    tc.n = 0;
    rc = bvh_crossings(scene->accel, ray, tmax, visibility_keep_crossing, &tc);
    if (rc == -2)
        return 0;
    if (rc < 0)
        return -1;
    n = tc.n;
    /* Insertion sort by reference (by kind, spheres first, then by index):
     * the lists are short. */
    for (int j = 1; j < n; j++) {
        VisibilityCrossing c = tc.c[j];
        int k = j;
        while (k > 0 && c.prim < tc.c[k - 1].prim) {
            tc.c[k] = tc.c[k - 1];
            k--;
        }
        tc.c[k] = c;
    }
    /* Kind by kind, in ShapeKind's order: the bounded ones' crossings
     * from the list, the unbounded ones' by their loops. */
    for (int kind = 0; kind < SHAPE_KINDS; kind++) {
        if (!(VISIBILITY_BOUNDED >> kind & 1)) {
            if (!visibility_attenuate_by(scene, (ShapeKind)kind, ray, tmax, &share))
                return 0;
            continue;
        }
        for (; i < n && bvh_kind(tc.c[i].prim) == (unsigned)kind; i++)
            if (!visibility_attenuate(&share, visibility_transparency_of(scene, tc.c[i].prim),
                                      tc.c[i].crossings))
                return 0;
    }
    return share;
}

double visibility_transmittance(const Scene *scene, const Ray *ray, real tmax)
{
    double share = 1;

    if (scene->accel) {
        double s = visibility_transmittance_accel(scene, ray, tmax);
        if (s >= 0)
            return s;
    }
    /* Kind by kind, in ShapeKind's order (the lowest bit first), spheres
     * inline. */
    for (size_t k = 0; k < scene_count_of(scene, SHAPE_SPHERE); k++) {
        const Sphere *s = &scene_spheres(scene)[k];
        if (!visibility_attenuate(&share, scene_material(scene, SHAPE_SPHERE, k).transparency,
                                  sphere_crossings(s, ray, 0, tmax)))
            return 0;
    }
    for (unsigned m = scene->kinds & ~(1u << SHAPE_SPHERE); m != 0; m &= m - 1)
        if (!visibility_attenuate_by(scene, visibility_first(m), ray, tmax, &share))
            return 0;
    return share;
}
