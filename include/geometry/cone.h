/*
 * cone.h: the infinite cone along the y axis, and its ray intersection.
 *
 * The MPL ray tracer's `Cone x y z r h` is the cone whose circle of radius r is
 * centred on (x, y, z), square to the y axis, and whose apex is h above
 * that centre (below it when h < 0): the half-angle theta has tan theta =
 * r / |h|. It is infinite, as the MPL ray tracer calls it: one nappe, from the apex
 * through the circle and on for ever (so a cone standing on a floor at
 * y looks as the MPL ray tracer's did). A ray's crossings solve a quadratic whose
 * discriminant is computed as k |fy D - dy F|^2 - (F x D)^2 (F and D the
 * horizontal parts of origin - apex and of the direction, k = tan^2 theta),
 * the form that does not subtract the squares of large numbers; roots on
 * the other nappe are left out. Closed: its inside is within the nappe.
 * Unbounded: it stays out of the bounding volume hierarchy. A finite cone
 * (the MPL ray tracer's, which MPL scenes mean) is the part of the nappe
 * between the circle and the apex, open at the circle.
 */
#ifndef RAYTRACE_CONE_H
#define RAYTRACE_CONE_H

#include "geometry/material.h"
#include "geometry/ray.h"
#include "geometry/shape.h"
#include "math/vec3.h"

typedef struct {
    Vec3 base;         /* the circle's centre, as given, scene units */
    real radius;       /* the circle's radius, > 0, as given */
    real height;       /* the apex's height above base, not 0, as given */
    Vec3 apex;         /* base + height along y */
    real k;            /* tan^2 of the half-angle: (radius / height)^2 */
    real sine, cosine; /* of the half-angle */
    real side;         /* +1: the nappe runs up from the apex; -1: down */
    int finite;        /* 1: only from the apex to the circle, within
                          |height| of the apex along y; 0: infinite */
    Material material; /* what the surface looks like */
    unsigned order;    /* position among the scene's objects, for ties */
} Cone;

/* Makes *c the infinite cone of circle centre base, radius (> 0) and
 * height (not 0) with material m (finite: set c->finite after). */
void cone_make(Cone *c, Vec3 base, real radius, real height, Material m);

/* Finds where the ray first crosses the cone with tmin < t < tmax; returns
 * 1 and stores t, or returns 0. */
int cone_intersect(const Cone *c, const Ray *ray, real tmin, real tmax, real *t);

/* Returns how many times the ray crosses the cone with tmin < t < tmax:
 * 0, 1 or 2. */
int cone_crossings(const Cone *c, const Ray *ray, real tmin, real tmax);

/* Re-projects p, a point near the cone, onto it (to the nearest point of
 * the generator through p) and returns it with its outward normal and
 * error bound. */
SurfacePoint cone_surface_at(const Cone *c, Vec3 p);

/* The surface point where the ray crosses c at t (shape.h). */
static inline SurfacePoint cone_surface(const Cone *c, const Ray *ray, real t)
{
    return cone_surface_at(c, ray_at(ray, t));
}

/* The surface point for p, near hit (shape.h): p put onto the cone. */
static inline SurfacePoint cone_surface_near(const Cone *c, const SurfacePoint *hit, Vec3 p)
{
    (void)hit;
    return cone_surface_at(c, p);
}

/* Returns in uv the texture coordinates of its point p: u around the axis
 * as on a cylinder, v = p.y - y of the circle's centre, the image
 * repeating every unit up the axis (as the MPL ray tracer shows it). */
void cone_uv(const Cone *c, Vec3 p, Vec3 n, double uv[2]);

/* Widens the box by its circle and apex (shape.h): the cone is unbounded. */
void cone_box(const Cone *c, Vec3 *lo, Vec3 *hi);
double cone_extent(const Cone *c);
void cone_scale(Cone *c, int k);

/* cone: x y z radius height (above) */
extern const ShapeRecord cone_record;

#endif
