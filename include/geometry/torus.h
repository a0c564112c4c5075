/*
 * torus.h: the ring torus, and a ray intersection that keeps its digits.
 *
 * A torus of centre c, unit axis n, major radius R and tube radius r
 * (R / 10^4 <= r < R) holds the points at distance r from its core, the circle of
 * radius R around c square to n. A ray meets it where a quartic vanishes,
 * the classic case of cancellation. Here the ray is first taken relative
 * to c, in the torus's frame (its axis along z), in units of R, with a
 * unit direction, and from the point of its line nearest to c: the
 * quartic's coefficients are then all of the order of 1 whatever the
 * scene's scale and however far the ray comes from, and its cubic term
 * vanishes. Its roots are isolated by those of its derivatives (between
 * two roots of the derivative the quartic is monotonic: at most one root
 * there) and each is found by Newton's steps kept inside its bracket,
 * then placed by the sign of the distance to the tube (which the quartic
 * shares, as a factor of it) where the quartic's own rounding could not
 * tell. A ray along the axis through the hole meets nothing; a tangent
 * ray counts as crossing when its rounding says so. Closed: its inside is
 * the tube's. Bounded: the hierarchy holds it.
 */
#ifndef RAYTRACE_TORUS_H
#define RAYTRACE_TORUS_H

#include "geometry/material.h"
#include "geometry/ray.h"
#include "geometry/shape.h"
#include "math/vec3.h"

typedef struct {
    Vec3 centre;       /* scene units */
    Vec3 axis;         /* unit axis n */
    Vec3 given;        /* the axis as given, any length */
    Vec3 axis_u;       /* unit, square to the axis: with axis_v and axis, */
    Vec3 axis_v;       /* the torus's frame (axis_v = axis x axis_u) */
    real major;        /* R, > minor */
    real minor;        /* r, > 0 */
    Material material; /* what the surface looks like */
    unsigned order;    /* position among the scene's objects, for ties */
} Torus;

/* Makes *t the torus of centre, axis direction n (any length), major
 * radius R and tube radius r with material m; returns 0, or -1 when n is
 * the zero vector, or -2 unless R / 10^4 <= r < R. */
int torus_make(Torus *t, Vec3 centre, Vec3 n, real major, real minor, Material m);

/* Finds where the ray first crosses the torus with tmin < t < tmax;
 * returns 1 and stores t, or returns 0. */
int torus_intersect(const Torus *tor, const Ray *ray, real tmin, real tmax, real *t);

/* Returns how many times the ray crosses the torus with tmin < t < tmax:
 * 0 to 4. */
int torus_crossings(const Torus *tor, const Ray *ray, real tmin, real tmax);

/* Re-projects p, a point near the torus, onto it (along the line from the
 * nearest point of its core) and returns it with its outward normal and
 * error bound. */
SurfacePoint torus_surface_at(const Torus *tor, Vec3 p);

/* The surface point where the ray crosses tor at t (shape.h). */
static inline SurfacePoint torus_surface(const Torus *tor, const Ray *ray, real t)
{
    return torus_surface_at(tor, ray_at(ray, t));
}

/* The surface point for p, near hit (shape.h): p put onto the torus. */
static inline SurfacePoint torus_surface_near(const Torus *tor, const SurfacePoint *hit, Vec3 p)
{
    (void)hit;
    return torus_surface_at(tor, p);
}

/* Returns in uv the texture coordinates of its point p: u = 0.5 +
 * atan2(y, x) / 2 pi around the axis (x along axis_u, y along axis_v), v =
 * 0.5 + atan2(z, rho - R) / 2 pi around the tube (0.5 on the outer
 * equator, 0 and 1 on the inner one); both repeat. */
void torus_uv(const Torus *tor, Vec3 p, Vec3 n, double uv[2]);

/* The torus's box, exact along each axis (shape.h). */
real torus_bounds(const Torus *tor, real ulps, real lo[3], real hi[3]);
void torus_box(const Torus *tor, Vec3 *lo, Vec3 *hi);
double torus_extent(const Torus *tor);
void torus_scale(Torus *tor, int k);

/* torus: cx cy cz nx ny nz R r (R around the axis n, r < R) */
extern const ShapeRecord torus_record;

#endif
