/* visibility.c: nearest hits and shadow rays (see visibility.h). */
#include "render/visibility.h"

#include <math.h>
#include <stdint.h>

#include "accel/bvh.h"

/* Stores in *hit the object of kind, index and order crossed at t. */
static void visibility_set_hit(Hit *hit, real t, ShapeKind kind, size_t index, unsigned order)
{
    hit->t = t;
    hit->kind = kind;
    hit->index = index;
    hit->order = order;
}

/* Says whether a crossing at t of the object of position order beats *hit
 * (t is at most hit->t): it is nearer, or as near and listed first. */
static int visibility_beats(const Hit *hit, int found, real t, unsigned order)
{
    return !found || t < hit->t || order < hit->order;
}

/* Continues visibility_nearest() over planes, after *hit (when found); returns
 * whether any object is hit. */
static int visibility_nearest_planes(const Scene *scene, const Ray *ray, real tmax, Hit *hit,
                                int found)
{
    /* An exact tie with an earlier-listed object must be seen: the bound is
     * the next real above the best t. */
    real bound = found ? real_next(hit->t, 1) : tmax;

    for (size_t k = 0; k < scene->plane_count; k++) {
        const Plane *pl = &scene->planes[k];
        real t;
        if (plane_intersect(pl, ray, 0, bound, &t) && visibility_beats(hit, found, t, pl->order)) {
            visibility_set_hit(hit, t, SHAPE_PLANE, k, pl->order);
            found = 1;
            bound = real_next(t, 1);
        }
    }
    return found;
}

/* Continues visibility_nearest() over triangles, tested one by one. */
static int visibility_nearest_triangles(const Scene *scene, const Ray *ray, real tmax, Hit *hit,
                                   int found)
{
    real bound = found ? real_next(hit->t, 1) : tmax;

    for (size_t k = 0; k < scene->triangle_count; k++) {
        const Triangle *tri = &scene->triangles[k];
        real t;
        if (triangle_intersect(tri, ray, 0, bound, &t) &&
            visibility_beats(hit, found, t, tri->order)) {
            visibility_set_hit(hit, t, SHAPE_TRIANGLE, k, tri->order);
            found = 1;
            bound = real_next(t, 1);
        }
    }
    return found;
}

/* visibility_nearest() through the hierarchy, planes aside. */
static int visibility_nearest_accel(const Scene *scene, const Ray *ray, real tmax, Hit *hit)
{
    BvhHit bh;
    int found = bvh_nearest(scene->accel, ray, tmax, &bh);

    if (found)
        visibility_set_hit(hit, bh.t, bh.prim & BVH_TRIANGLE ? SHAPE_TRIANGLE : SHAPE_SPHERE,
                      bh.prim & ~BVH_TRIANGLE, bh.order);
    return scene->plane_count > 0 ? visibility_nearest_planes(scene, ray, tmax, hit, found) : found;
}

int visibility_nearest(const Scene *scene, const Ray *ray, real tmax, Hit *hit)
{
    int found = 0;
    size_t best = 0;

    if (scene->accel)
        return visibility_nearest_accel(scene, ray, tmax, hit);
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
        visibility_set_hit(hit, tmax, SHAPE_SPHERE, best, scene->spheres[best].order);
    if (scene->plane_count > 0)
        found = visibility_nearest_planes(scene, ray, tmax, hit, found);
    if (scene->triangle_count > 0)
        found = visibility_nearest_triangles(scene, ray, tmax, hit, found);
    return found;
}

int visibility_occluded(const Scene *scene, const Ray *ray, real tmax)
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
static int visibility_attenuate(double *share, const Material *m, int crossings)
{
    for (int i = 0; i < crossings; i++)
        *share *= m->transparency;
    return *share > 0;
}

/* Multiplies *share by the transparency of every plane the ray crosses at
 * 0 < t < tmax; returns 0 once nothing is left, else 1. */
static int visibility_attenuate_planes(const Scene *scene, const Ray *ray, real tmax,
                                  double *share)
{
    real t;

    for (size_t k = 0; k < scene->plane_count; k++) {
        const Plane *pl = &scene->planes[k];
        if (!visibility_attenuate(share, &pl->material, plane_intersect(pl, ray, 0, tmax, &t)))
            return 0;
    }
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

/* bvh_crossings()'s visit: keeps the crossing; returns -2 at an opaque
 * surface (no light passes) and -1 when the list is full. */
static int visibility_keep_crossing(void *ctx, uint32_t prim, int crossings)
{
    VisibilityCrossings *tc = ctx;
    const Scene *scene = tc->scene;
    const Material *m = prim & BVH_TRIANGLE
                            ? scene_material_of(scene, &scene->triangles[prim & ~BVH_TRIANGLE])
                            : &scene->spheres[prim].material;

    if (!(m->transparency > 0))
        return -2;
    if (tc->n == VISIBILITY_CROSSINGS_MAX)
        return -1;
    tc->c[tc->n].prim = prim;
    tc->c[tc->n].crossings = crossings;
    tc->n++;
    return 0;
}

/* visibility_transmittance() through the hierarchy: the crossings it lists are
 * sorted and multiplied in the order of the loop below (spheres, planes,
 * triangles, each by index), so the product has the very same bits.
 * Returns -1 when there are too many crossings to list. */
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
    /* Insertion sort by reference (spheres first: BVH_TRIANGLE is the top
     * bit): the lists are short. */
    for (int j = 1; j < n; j++) {
        VisibilityCrossing c = tc.c[j];
        int k = j;
        while (k > 0 && c.prim < tc.c[k - 1].prim) {
            tc.c[k] = tc.c[k - 1];
            k--;
        }
        tc.c[k] = c;
    }
    for (; i < n && !(tc.c[i].prim & BVH_TRIANGLE); i++)
        if (!visibility_attenuate(&share, &scene->spheres[tc.c[i].prim].material, tc.c[i].crossings))
            return 0;
    if (!visibility_attenuate_planes(scene, ray, tmax, &share))
        return 0;
    for (; i < n; i++)
        if (!visibility_attenuate(
                &share, scene_material_of(scene, &scene->triangles[tc.c[i].prim & ~BVH_TRIANGLE]),
                tc.c[i].crossings))
            return 0;
    return share;
}

double visibility_transmittance(const Scene *scene, const Ray *ray, real tmax)
{
    double share = 1;
    real t;

    if (scene->accel) {
        double s = visibility_transmittance_accel(scene, ray, tmax);
        if (s >= 0)
            return s;
    }
    for (size_t k = 0; k < scene->sphere_count; k++) {
        const Sphere *s = &scene->spheres[k];
        if (!visibility_attenuate(&share, &s->material, sphere_crossings(s, ray, 0, tmax)))
            return 0;
    }
    if (!visibility_attenuate_planes(scene, ray, tmax, &share))
        return 0;
    for (size_t k = 0; k < scene->triangle_count; k++) {
        const Triangle *tri = &scene->triangles[k];
        if (!visibility_attenuate(&share, scene_material_of(scene, tri),
                             triangle_intersect(tri, ray, 0, tmax, &t)))
            return 0;
    }
    return share;
}

