/*
 * square.h: the square, two-sided, and its ray intersection.
 *
 * A square lies in the plane through its centre with a unit normal, its
 * edges along two unit axes of that plane (square_make() chooses them: v
 * along the world's +y seen in the plane, or +z when the normal is
 * vertical, and u = normal x v), and reaches `half` from the centre along
 * each (the MPL ray tracer's `Square ... size` takes size as half the edge). The
 * ray meets its plane as a plane's (plane.h); the hit is inside when both
 * coordinates along the axes are within [-half, half]. Its front is the
 * side the normal points to; refraction treats the back as inside.
 */
#ifndef RAYTRACE_SQUARE_H
#define RAYTRACE_SQUARE_H

#include "geometry/material.h"
#include "geometry/ray.h"
#include "geometry/shape.h"
#include "math/vec3.h"

typedef struct {
    Vec3 centre;       /* scene units */
    Vec3 normal;       /* unit normal, the front */
    Vec3 given;        /* the normal as given, any length */
    Vec3 axis_u;       /* unit, in the plane: the texture's u */
    Vec3 axis_v;       /* unit, in the plane: the texture's v */
    real half;         /* half the edge, > 0 */
    Material material; /* what the surface looks like */
    unsigned order;    /* position among the scene's objects, for ties */
} Square;

/* Makes *s the square of centre, normal direction n (any length) and
 * half-edge half (> 0) with material m; returns -1 when n is the zero
 * vector, else 0. */
int square_make(Square *s, Vec3 centre, Vec3 n, real half, Material m);

/* Finds where the ray crosses the square with tmin < t < tmax; returns 1
 * and stores t, or returns 0 (a ray in its plane never crosses it). */
int square_intersect(const Square *s, const Ray *ray, real tmin, real tmax, real *t);

/* Crossings of the square (shape.h): once or never. */
static inline int square_crossings(const Square *s, const Ray *ray, real tmin, real tmax)
{
    real t;

    return square_intersect(s, ray, tmin, tmax, &t);
}

/* Re-projects p, a point near the square, onto its plane and returns it
 * with the normal and the point's error bound. */
SurfacePoint square_surface_at(const Square *s, Vec3 p);

/* The surface point where the ray crosses s at t (shape.h). */
static inline SurfacePoint square_surface(const Square *s, const Ray *ray, real t)
{
    return square_surface_at(s, ray_at(ray, t));
}

/* The surface point for p, near hit (shape.h): flat, hit's own at p. */
static inline SurfacePoint square_surface_near(const Square *s, const SurfacePoint *hit, Vec3 p)
{
    SurfacePoint sp = *hit;

    (void)s;
    sp.point = p;
    return sp;
}

/* Returns in uv the texture coordinates of its point p: its distances
 * from the centre along axis_u and axis_v, in scene units, so that the
 * image repeats every unit (as the MPL ray tracer shows textures on
 * squares). */
void square_uv(const Square *s, Vec3 p, Vec3 n, double uv[2]);

/* The square's box, its corners (shape.h). */
real square_bounds(const Square *s, real ulps, real lo[3], real hi[3]);
void square_box(const Square *s, Vec3 *lo, Vec3 *hi);
double square_extent(const Square *s);
void square_scale(Square *s, int k);

/* square: cx cy cz nx ny nz half (the edge is 2 half) */
extern const ShapeRecord square_record;

#endif
