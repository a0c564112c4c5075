/*
 * cylinder.h: the infinite cylinder along the y axis, and its ray
 * intersection.
 *
 * The cylinder of radius r around the vertical line through (cx, cz) is
 * the set of points whose distance to that line is r (the MPL ray tracer's
 * `Cylinder cx cy cz r`; cy only anchors the texture). Seen from above it
 * is a circle, so a ray's crossings are those of the ray's shadow on the
 * xz plane with that circle, computed as the sphere's are (sphere.h:
 * Haines, Günther and Akenine-Möller's form, without cancellation). A ray
 * parallel to the axis never crosses it. Closed: its inside is within r of
 * the axis. Unbounded: it stays out of the bounding volume hierarchy.
 */
#ifndef RAYTRACE_CYLINDER_H
#define RAYTRACE_CYLINDER_H

#include "geometry/material.h"
#include "geometry/ray.h"
#include "geometry/shape.h"
#include "math/vec3.h"

typedef struct {
    Vec3 centre;       /* a point of the axis, scene units */
    real radius;       /* > 0 */
    Material material; /* what the surface looks like */
    unsigned order;    /* position among the scene's objects, for ties */
} Cylinder;

/* Finds where the ray first crosses the surface with tmin < t < tmax;
 * returns 1 and stores t, or returns 0. A tangent ray crosses it. */
int cylinder_intersect(const Cylinder *c, const Ray *ray, real tmin, real tmax, real *t);

/* Returns how many times the ray crosses the surface with tmin < t < tmax:
 * 0, 1 or 2. */
int cylinder_crossings(const Cylinder *c, const Ray *ray, real tmin, real tmax);

/* Re-projects p, a point near the surface, onto it (along the normal) and
 * returns it with its outward normal and error bound. */
SurfacePoint cylinder_surface_at(const Cylinder *c, Vec3 p);

/* The surface point where the ray crosses c at t (shape.h). */
static inline SurfacePoint cylinder_surface(const Cylinder *c, const Ray *ray, real t)
{
    return cylinder_surface_at(c, ray_at(ray, t));
}

/* The surface point for p, near hit (shape.h): p put onto the cylinder. */
static inline SurfacePoint cylinder_surface_near(const Cylinder *c, const SurfacePoint *hit,
                                                 Vec3 p)
{
    (void)hit;
    return cylinder_surface_at(c, p);
}

/* Returns in uv the texture coordinates of the point p of outward normal
 * n: u = 0.5 + atan2(n.x, -n.z) / (2 pi) around the axis (as on a
 * sphere), v = p.y - cy, so that the image repeats every unit up the
 * axis (as the MPL ray tracer shows it). */
void cylinder_uv(const Cylinder *c, Vec3 p, Vec3 n, double uv[2]);

/* Widens the box by the circle's (shape.h): the cylinder is unbounded. */
void cylinder_box(const Cylinder *c, Vec3 *lo, Vec3 *hi);
double cylinder_extent(const Cylinder *c);
void cylinder_scale(Cylinder *c, int k);

/* cylinder: cx cy cz radius (infinite, along y) */
extern const ShapeRecord cylinder_record;

#endif
