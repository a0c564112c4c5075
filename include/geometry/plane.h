/*
 * plane.h: the infinite plane, two-sided, and its ray intersection.
 *
 * A plane is given by a point on it and a unit normal. Its front is the side
 * the normal points to; shading lights both sides alike, but refraction
 * treats the back as the inside of a solid (a half-space).
 */
#ifndef RAYTRACE_PLANE_H
#define RAYTRACE_PLANE_H

#include "geometry/material.h"
#include "geometry/ray.h"
#include "geometry/shape.h"
#include "math/vec3.h"

typedef struct {
    Vec3 point;        /* a point on the plane, scene units */
    Vec3 normal;       /* unit normal, pointing to the front */
    Vec3 given;        /* the normal as given to plane_make(), any length */
    Vec3 axis_u;       /* unit vector in the plane: the texture's u direction */
    Vec3 axis_v;       /* normal x axis_u: the texture's v direction */
    double tile;     /* texture repeat, scene units per image, > 0 */
    Material material; /* what the surface looks like */
    unsigned order;    /* position among the scene's objects, for ties */
} Plane;

/* Makes *pl the plane through point with normal direction n (any length)
 * and material m, its texture repeating every tile units; returns -1 when n
 * is the zero vector (no direction), else 0. */
int plane_make(Plane *pl, Vec3 point, Vec3 n, double tile, Material m);

/* Finds where the ray crosses the plane with tmin < t < tmax; returns 1 and
 * stores t, or returns 0 (a ray parallel to the plane never crosses it). */
int plane_intersect(const Plane *pl, const Ray *ray, real tmin, real tmax, real *t);

/* Crossings of the plane (shape.h): once or never. */
static inline int plane_crossings(const Plane *pl, const Ray *ray, real tmin, real tmax)
{
    real t;

    return plane_intersect(pl, ray, tmin, tmax, &t);
}

/* Re-projects p, a point near the plane, onto it and returns it with the
 * plane's normal and the point's error bound. */
SurfacePoint plane_surface_at(const Plane *pl, Vec3 p);

/* The surface point where the ray crosses pl at t (shape.h). */
static inline SurfacePoint plane_surface(const Plane *pl, const Ray *ray, real t)
{
    return plane_surface_at(pl, ray_at(ray, t));
}

/* The surface point for p, near hit (shape.h): flat, hit's own at p. */
static inline SurfacePoint plane_surface_near(const Plane *pl, const SurfacePoint *hit, Vec3 p)
{
    SurfacePoint sp = *hit;

    (void)pl;
    sp.point = p;
    return sp;
}

/* Returns in uv the texture coordinates of the point p of the plane:
 * distances from the plane's point along axis_u and axis_v, in tiles. */
void plane_uv(const Plane *pl, Vec3 p, Vec3 n, double uv[2]);

/* Widens the box by the plane's point (shape.h). */
void plane_box(const Plane *pl, Vec3 *lo, Vec3 *hi);
double plane_extent(const Plane *pl);
void plane_scale(Plane *pl, int k);

/* plane: px py pz nx ny nz (a point and a normal of any length); its
 * texture tiles every unit */
extern const ShapeRecord plane_record;

#endif
