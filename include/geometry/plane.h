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

/* Re-projects p, a point near the plane, onto it and returns it with the
 * plane's normal and the point's error bound. */
SurfacePoint plane_surface_at(const Plane *pl, Vec3 p);

/* Returns in uv the texture coordinates of the point p of the plane:
 * distances from the plane's point along axis_u and axis_v, in tiles. */
void plane_uv(const Plane *pl, Vec3 p, double uv[2]);

#endif
