/*
 * trace.h: following one ray through a scene: nearest hit, shadow test and
 * the course's recursive shading.
 *
 * The colour seen along a ray that hits sphere S at point P is
 *     C = (1 - R) * local + R * Cr
 *     local = E * max(0, N . L) * (Ci * Cs) / 255   (channel by channel)
 * with N the unit normal facing the ray, L the unit vector from P to the
 * light, E = 0 when any sphere's surface is crossed strictly between P and
 * the light (else 1), R and Ci the sphere's reflection and colour, Cs the
 * light's colour, and Cr the colour seen along the mirror ray d - 2 (d . N) N.
 * A ray that hits nothing sees the background. The primary ray has depth 0;
 * a reflected ray of depth k is traced only when k <= max_depth, otherwise
 * Cr = 0. Functions here are pure: safe to call from many threads at once.
 */
#ifndef RAYTRACE_TRACE_H
#define RAYTRACE_TRACE_H

#include "colour.h"
#include "ray.h"
#include "scene.h"

enum { TRACE_MAX_DEPTH_LIMIT = 1000 }; /* deepest max_depth accepted */

typedef struct {
    double t;             /* ray parameter of the crossing, > 0 */
    const Sphere *sphere; /* the sphere crossed */
} Hit;

/* Finds the sphere whose surface the ray crosses first at 0 < t < tmax, the
 * earliest-listed on an exact tie; returns 1 and fills *hit, or returns 0. */
int trace_nearest(const Scene *scene, const Ray *ray, double tmax, Hit *hit);

/* Returns 1 when some sphere's surface crosses the segment from ray->origin
 * to ray->origin + ray->dir (0 < t < 1, ends excluded), else 0. */
int trace_occluded(const Scene *scene, const Ray *segment);

/* Returns the colour seen along ray, a ray of reflection depth `depth`
 * (0 for primary rays), tracing reflections down to max_depth. */
Colour trace_ray(const Scene *scene, const Ray *ray, int depth, int max_depth);

#endif
