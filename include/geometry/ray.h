/*
 * ray.h: rays, and the one rule for where a secondary ray may start.
 *
 * A ray is the half-line origin + t * dir, t > 0. dir need not be unit
 * length; every intersection routine accepts any non-zero direction.
 */
#ifndef RAYTRACE_RAY_H
#define RAYTRACE_RAY_H

#include "math/vec3.h"

typedef struct {
    Vec3 origin; /* start point, scene units */
    Vec3 dir;    /* direction, any non-zero length */
} Ray;

/* A point on a surface, with what a secondary ray needs to leave it. */
typedef struct {
    Vec3 point;  /* on the surface, re-projected from the ray's hit */
    Vec3 normal;  /* the surface's outward unit normal at point */
    Vec3 shading; /* the unit normal shading uses: `normal`, except on a
                     smooth triangle (interpolated vertex normals) */
    Vec3 error;  /* per-component bound on |point - true surface point| */
} SurfacePoint;

/* Returns the point origin + t * dir. */
static inline Vec3 ray_at(const Ray *ray, real t)
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

/* Returns the mirror image of direction d about the unit normal n:
 * d - 2 (d . n) n. */
static inline Vec3 ray_reflect(Vec3 d, Vec3 n)
{
    return vec3_sub(d, vec3_scale(n, 2 * vec3_dot(d, n)));
}

/*
 * Bends direction d (any length) through a surface of unit normal n facing
 * it (d . n <= 0) by Snell and Descartes' law n1 sin i1 = n2 sin i2, eta =
 * n1 / n2 being the ratio of the indices on d's side and the far side;
 * stores the unit refracted direction in *out and returns 1, or returns 0
 * on total internal reflection (sin i2 would exceed 1).
 */
int ray_refract(Vec3 d, Vec3 n, real eta, Vec3 *out);

/*
 * Returns the share of unpolarised light a smooth dielectric surface
 * mirrors, by Fresnel's equations: d is the incoming direction (any
 * length), n the unit normal facing it (d . n <= 0), eta = n1 / n2 the
 * ratio of the indices on d's side and the far side. The average of the
 * s and p reflectances, ((eta c_i - c_t) / (eta c_i + c_t))^2 and
 * ((eta c_t - c_i) / (eta c_t + c_i))^2, with c_i and c_t the cosines of
 * incidence and refraction; 1 on total internal reflection.
 */
double ray_fresnel(Vec3 d, Vec3 n, real eta);

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
