/*
 * ray.h: rays, and the one rule for where a secondary ray may start.
 *
 * A ray is the half-line origin + t * dir, t > 0. dir need not be unit
 * length; every intersection routine accepts any non-zero direction.
 */
#ifndef RAYTRACE_RAY_H
#define RAYTRACE_RAY_H

#include "vec3.h"

typedef struct {
    Vec3 origin; /* start point, scene units */
    Vec3 dir;    /* direction, any non-zero length */
} Ray;

/* Returns the point origin + t * dir. */
static inline Vec3 ray_at(const Ray *ray, double t)
{
    return vec3_add(ray->origin, vec3_scale(ray->dir, t));
}

/* Returns the unit normal n turned to face the ray direction dir: n itself
 * when the ray meets the surface from outside, -n when from inside
 * (n . dir > 0). Every shading rule uses the facing normal. */
static inline Vec3 ray_facing_normal(Vec3 n, Vec3 dir)
{
    return vec3_dot(n, dir) > 0 ? vec3_neg(n) : n;
}

/*
 * Returns a start point for a ray leaving the surface point p in direction
 * w, safe from re-hitting the surface it leaves: p is moved along the unit
 * normal n, to the side w points to, by the projection of p's error bound
 * perr (each component of the computed p is within perr of the true surface
 * point) onto n, and each moved component is then rounded one more ulp away
 * from p. This is the method of pbrt-v4 (Pharr, Jakob, Humphreys, 4th ed.,
 * section 6.8.6), applied to world-space points.
 */
Vec3 ray_offset_origin(Vec3 p, Vec3 perr, Vec3 n, Vec3 w);

#endif
