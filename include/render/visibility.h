/*
 * visibility.h: which object a ray meets first, and how much of a light's
 * light passes along a shadow ray.
 *
 * Through the bounding volume hierarchy when the scene has one (planes,
 * unbounded, always one by one), else object by object: the answers are
 * the same to the bit. Exact ties go to the object listed first in the
 * scene file. Only reads the scene: safe on many threads at once.
 */
#ifndef RAYTRACE_VISIBILITY_H
#define RAYTRACE_VISIBILITY_H

#include <stddef.h>

#include "geometry/frustum.h"
#include "geometry/ray.h"
#include "scene/scene.h"


typedef struct {
    real t;         /* ray parameter of the crossing, > 0 */
    ShapeKind kind; /* which array the object is in */
    size_t index;   /* its index there */
    unsigned order; /* its position among all objects */
} Hit;

/* Finds the object whose surface the ray crosses first at 0 < t < tmax, the
 * earliest-listed on an exact tie; returns 1 and fills *hit, or returns 0. */
int visibility_nearest(const Scene *scene, const Ray *ray, real tmax, Hit *hit);

/* visibility_nearest() over the bounded shapes (spheres, triangles, cubes,
 * squares) and those unbounded ones whose kinds are in the mask kinds
 * (bit k for ShapeKind k), the others left out. */
int visibility_nearest_among(const Scene *scene, const Ray *ray, real tmax, unsigned kinds,
                             Hit *hit);

/* Says whether no ray of f can meet an object of the scene: 1 when
 * proven, 0 when one may. Proven for scenes of bounded shapes alone:
 * through the hierarchy (bvh_frustum_clear()), or without one for
 * spheres, tested one by one; any other may. Stores in *skip the spheres
 * no ray of f can meet (bit k: sphere k) in a scene of at most 64 spheres
 * alone without hierarchy, else 0. */
int visibility_frustum_clear(const Scene *scene, const Frustum *f, uint64_t *skip);

/* visibility_nearest() with tmax infinite in a scene of at most 64
 * spheres alone without hierarchy, the spheres of skip (bit k: sphere k)
 * left untested: the same answer for a ray none of them can meet. */
int visibility_nearest_skipping(const Scene *scene, const Ray *ray, uint64_t skip, Hit *hit);

/* Returns 1 when some object's surface crosses the ray at 0 < t < tmax,
 * else 0: tmax = 1 tests the segment from ray->origin to ray->origin +
 * ray->dir (ends excluded), tmax = INFINITY the whole ray. */
int visibility_occluded(const Scene *scene, const Ray *ray, real tmax);

/* visibility_occluded() with a shadow cache: *cache (BVH_NO_SLOT at first)
 * names the last primitive of the hierarchy that occluded a ray like this
 * one, which is tried first, and is set to the one found. The answer is the
 * same; neighbouring shadow rays towards one light are often stopped by one
 * object, and then skip the walk. */
int visibility_occluded_cached(const Scene *scene, const Ray *ray, real tmax, uint32_t *cache);

/* visibility_occluded_cached() for a shadow ray towards light number
 * light of the scene (a point light's ending there, tmax = 1): asks the
 * light's light buffer (light_buffer.h) when it has one, whose *cache then
 * names a sphere; cache may be NULL (none). */
int visibility_light_occluded(const Scene *scene, size_t light, const Ray *ray, real tmax,
                              uint32_t *cache);

/* Returns the share of light that passes along the ray from t = 0 to tmax:
 * the product of the transparency T of every surface crossing there, in
 * the order of ShapeKind, each kind by index (so the same bits with or
 * without the hierarchy). */
double visibility_transmittance(const Scene *scene, const Ray *ray, real tmax);

#endif
