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

#include "material.h"
#include "ray.h"
#include "vec3.h"

typedef struct {
    Vec3 centre;       /* scene units */
    real radius;     /* scene units, > 0 */
    Material material; /* what the surface looks like */
    unsigned order;    /* position among the scene's objects, for ties */
} Sphere;

/*
 * Finds where the ray first crosses s's surface with tmin < t < tmax (an open
 * interval); returns 1 and stores that t in *t, or returns 0. The ray's
 * direction may have any non-zero length; a tangent ray counts as crossing.
 */
int sphere_intersect(const Sphere *s, const Ray *ray, real tmin, real tmax, real *t);

/* Returns how many times the ray crosses s's surface with tmin < t < tmax:
 * 0, 1 or 2. */
int sphere_crossings(const Sphere *s, const Ray *ray, real tmin, real tmax);

/* Re-projects p, a point near s's surface, onto the surface and returns it
 * with its outward normal and error bound. */
SurfacePoint sphere_surface_at(const Sphere *s, Vec3 p);

/* Returns in uv the texture coordinates of the point of outward normal n:
 * u = 0.5 + atan2(n.x, -n.z) / (2 pi) around the y axis (0.5 facing -z), and
 * v = 1 - acos(n.y) / pi from the south pole (v = 0) to the north (v = 1). */
void sphere_uv(Vec3 n, double uv[2]);

#endif
