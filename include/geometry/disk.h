/*
 * disk.h: the disk, two-sided, and its ray intersection.
 *
 * A disk lies in the plane through its centre square to its unit normal
 * and holds the points of that plane within `radius` of the centre. The
 * ray meets its plane as a plane's (plane.h), from the ray's origin
 * taken relative to the centre (so that a disk far from the origin of
 * the coordinates keeps its digits); the hit is inside when its two
 * coordinates along the plane's axes (chosen as a square's, square.h)
 * are within the radius. Its front is the side the normal points to;
 * refraction treats the back as inside. Bounded: the hierarchy holds it.
 */
#ifndef RAYTRACE_DISK_H
#define RAYTRACE_DISK_H

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
    real radius;       /* > 0 */
    Material material; /* what the surface looks like */
    unsigned order;    /* position among the scene's objects, for ties */
} Disk;

/* Makes *d the disk of centre, normal direction n (any length) and radius
 * (> 0) with material m; returns -1 when n is the zero vector, else 0. */
int disk_make(Disk *d, Vec3 centre, Vec3 n, real radius, Material m);

/* Finds where the ray crosses the disk with tmin < t < tmax; returns 1 and
 * stores t, or returns 0 (a ray in its plane never crosses it). */
int disk_intersect(const Disk *d, const Ray *ray, real tmin, real tmax, real *t);

/* Crossings of the disk (shape.h): once or never. */
static inline int disk_crossings(const Disk *d, const Ray *ray, real tmin, real tmax)
{
    real t;

    return disk_intersect(d, ray, tmin, tmax, &t);
}

/* The surface point where the ray crosses d at t (shape.h): put onto its
 * plane, with the normal and its error bound. */
SurfacePoint disk_surface(const Disk *d, const Ray *ray, real t);

/* The surface point for p, near hit (shape.h): flat, hit's own at p. */
static inline SurfacePoint disk_surface_near(const Disk *d, const SurfacePoint *hit, Vec3 p)
{
    SurfacePoint sp = *hit;

    (void)d;
    sp.point = p;
    return sp;
}

/* Returns in uv the texture coordinates of its point p: the image spans
 * the square around the disk, upright along axis_v, from (0, 0) at
 * centre - radius (axis_u + axis_v) to (1, 1) at centre + radius
 * (axis_u + axis_v). */
void disk_uv(const Disk *d, Vec3 p, Vec3 n, double uv[2]);

/* The disk's box, exact along each axis (shape.h). */
real disk_bounds(const Disk *d, real ulps, real lo[3], real hi[3]);
void disk_box(const Disk *d, Vec3 *lo, Vec3 *hi);
double disk_extent(const Disk *d);
void disk_scale(Disk *d, int k);

/* disk: cx cy cz nx ny nz radius */
extern const ShapeRecord disk_record;

#endif
