/*
 * sphere.h: the sphere, its ray intersection and its surface geometry.
 *
 * Intersection follows Haines, Günther and Akenine-Möller, "Precision
 * Improvements for Ray/Sphere Intersection" (Ray Tracing Gems, ch. 7): the
 * discriminant is computed from the centre's distance to the ray's line,
 * which does not cancel catastrophically for small or distant spheres, and
 * the two roots come from the cancellation-free pair q / a and c / q.
 */
#ifndef RAYTRACE_SPHERE_H
#define RAYTRACE_SPHERE_H

#include "colour.h"
#include "ray.h"
#include "vec3.h"

typedef struct {
    Vec3 centre;       /* scene units */
    double radius;     /* scene units, > 0 */
    Colour colour;     /* diffuse colour Ci, 0..255 per channel */
    double reflection; /* mirror weight R, 0..1 */
    int line;          /* line of the sphere's record in its scene file */
} Sphere;

/* A point on a sphere's surface, with what a secondary ray needs to leave it. */
typedef struct {
    Vec3 point;  /* on the surface, re-projected from the ray's hit */
    Vec3 normal; /* outward unit normal at point */
    Vec3 error;  /* per-component bound on |point - true surface point| */
} SurfacePoint;

/*
 * Finds where the ray first crosses s's surface with tmin < t < tmax (an open
 * interval); returns 1 and stores that t in *t, or returns 0. The ray's
 * direction may have any non-zero length; a tangent ray counts as crossing.
 */
int sphere_intersect(const Sphere *s, const Ray *ray, double tmin, double tmax, double *t);

/* Re-projects p, a point near s's surface, onto the surface and returns it
 * with its outward normal and error bound. */
SurfacePoint sphere_surface_at(const Sphere *s, Vec3 p);

#endif
