/*
 * light_buffer.h: a light buffer (Haines and Greenberg, "The Light Buffer:
 * A Shadow-Testing Accelerator", 1986) around a point: the directions from
 * the point cut into the cells of a cube's faces, each cell listing the
 * spheres that a ray from the point through it can meet, nearest first.
 *
 * Around a point light it answers shadow rays towards the light, around a
 * pinhole camera's eye the primary rays: a short list in place of a walk
 * of the hierarchy. Every list holds every sphere a ray in its cell could
 * cross (the cells' and the spheres' bounds are padded far beyond the
 * arithmetic's rounding), and a query applies the very sphere test and tie
 * rule of the loops over every sphere, so the answers are the same to the
 * bit. Only reads the spheres: safe on many threads at once.
 */
#ifndef RAYTRACE_LIGHT_BUFFER_H
#define RAYTRACE_LIGHT_BUFFER_H

#include <stddef.h>
#include <stdint.h>

#include "geometry/ray.h"
#include "geometry/sphere.h"
#include "math/vec3.h"

typedef struct LightBuffer {
    Vec3 centre;               /* the point: rays start or end there */
    const Sphere *spheres;     /* what it lists (not owned): must stay where
                                  it is, unchanged, while in use */
    int res;                   /* cells along a face's edge */
    uint32_t *first;           /* 6 res^2 + 1: cell c lists
                                  entries[first[c] .. first[c + 1]) */
    uint32_t *entries;         /* every cell's list of spheres (indices),
                                  nearest point first */
    size_t entry_count;
    double slack;              /* the padding of distances, scene units */
    int ahead;                 /* shadow queries ask memory for spheres
                                  ahead (they outgrow the caches) */
} LightBuffer;

/* Builds into *lb the light buffer of the count spheres around centre,
 * for about `rays` rays (no more cells than that), with up to threads
 * threads, unless it would take more than max_bytes: returns 0, -1 when
 * memory runs out, or 1 when the buffer would be too large to pay
 * (nothing allocated but for 0). */
int light_buffer_build(LightBuffer *lb, Vec3 centre, const Sphere *spheres, size_t count,
                       size_t rays, size_t max_bytes, int threads);

/* Releases what *lb owns. */
void light_buffer_free(LightBuffer *lb);

/* Returns the bytes *lb holds. */
size_t light_buffer_memory(const LightBuffer *lb);

/* Returns 1 when a sphere crosses the shadow ray at 0 < t < tmax, 0 when
 * none does, or -1 when the ray starts at the centre (no direction: ask
 * the hierarchy),
 * for a ray that ends at the centre (origin + tmax dir is the centre, to
 * rounding; tmax = 1 for the segment from the origin to it). *cache (a
 * sphere's index, or UINT32_MAX at first) is tried first and set to the
 * sphere found, as visibility.h's shadow cache. */
int light_buffer_occluded(const LightBuffer *lb, const Ray *ray, real tmax, uint32_t *cache);

/* Finds the sphere a ray starting at the centre (ray->origin equal to it)
 * crosses first at 0 < t < tmax, the one of least order on an exact tie:
 * returns 1 with *t and the sphere's index in *sphere, 0 when it crosses
 * none, or -1 when its direction is 0 or not finite (ask the hierarchy). */
int light_buffer_nearest(const LightBuffer *lb, const Ray *ray, real tmax, real *t,
                         size_t *sphere);

#endif
