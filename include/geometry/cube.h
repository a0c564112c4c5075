/*
 * cube.h: the axis-aligned cube, and its ray intersection by slabs.
 *
 * A cube of centre c and half-edge h is the box [c - h, c + h] on each
 * axis (the MPL ray tracer's `Cube cx cy cz size` takes size as h, so its edge is
 * 2 size). Its corners are computed once, by cube_make(): the box between
 * them is the surface every test and every surface point agree on. The
 * slab distances (b - o) / d are each one subtraction and one division, so
 * a hit is within a few ulps of the exact one at any scale; a zero
 * direction component means the ray runs parallel to two faces, inside
 * their slab or not. Closed: refraction enters from outside.
 */
#ifndef RAYTRACE_CUBE_H
#define RAYTRACE_CUBE_H

#include "geometry/material.h"
#include "geometry/ray.h"
#include "geometry/shape.h"
#include "math/vec3.h"

typedef struct {
    Vec3 lo, hi;       /* the corners: the box holds lo <= p <= hi */
    Vec3 centre;       /* as given, scene units */
    real half;         /* half the edge, > 0 */
    Material material; /* what the surface looks like */
    unsigned order;    /* position among the scene's objects, for ties */
} Cube;

/* Makes *c the cube of centre and half-edge half (> 0) with material m. */
void cube_make(Cube *c, Vec3 centre, real half, Material m);

/* Finds where the ray first crosses the cube's surface with tmin < t <
 * tmax; returns 1 and stores t, or returns 0. A ray that only touches an
 * edge or a corner crosses it there. */
int cube_intersect(const Cube *c, const Ray *ray, real tmin, real tmax, real *t);

/* Returns how many times the ray crosses the surface with tmin < t < tmax:
 * 0, 1 or 2. */
int cube_crossings(const Cube *c, const Ray *ray, real tmin, real tmax);

/* Returns the point of the ray at t, where it crosses the cube's surface
 * (t from cube_intersect()), put onto the face it crosses there, with that
 * face's outward normal and its error bound. The face is the one whose
 * slab the ray enters last (at the entry) or leaves first (at the exit),
 * the lower axis (x, then y, then z) when it crosses two or three at once
 * (an edge or a corner), whatever face the rounded point lies nearest to;
 * for any other t, the face nearest to the point. */
SurfacePoint cube_surface(const Cube *c, const Ray *ray, real t);

/* Returns in uv the texture coordinates of the surface point p of outward
 * normal n: each face holds the whole image, upright (v along +y on the
 * sides, along +z on the top and bottom) and unmirrored seen from outside. */
void cube_uv(const Cube *c, Vec3 p, Vec3 n, double uv[2]);

/* The surface point for p, near hit (shape.h): flat, hit's own at p. */
static inline SurfacePoint cube_surface_near(const Cube *c, const SurfacePoint *hit, Vec3 p)
{
    SurfacePoint sp = *hit;

    (void)c;
    sp.point = p;
    return sp;
}

/* The cube's box, its corners (shape.h). */
real cube_bounds(const Cube *c, real ulps, real lo[3], real hi[3]);
void cube_box(const Cube *c, Vec3 *lo, Vec3 *hi);
double cube_extent(const Cube *c);
void cube_scale(Cube *c, int k);

/* cube: cx cy cz half (the edge is 2 half) */
extern const ShapeRecord cube_record;

#endif
