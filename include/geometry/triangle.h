/*
 * triangle.h: the triangle, two-sided, and a watertight ray intersection.
 *
 * The test is Möller and Trumbore's: the ray crosses the triangle when the
 * three scalar triple products that give its barycentric coordinates share a
 * sign. Each product belongs to one edge and is computed from vectors taken
 * from the ray's origin to the edge's two vertices, in an order fixed by the
 * vertices' coordinates, not by the triangle. Two triangles that share an
 * edge therefore compute the same number for it, bit for bit, with opposite
 * or equal signs as their windings say: a ray that hits the edge hits at
 * least one of them, never neither (no cracks). The front of a triangle is
 * the side (v1 - v0) x (v2 - v0) points to; shading lights both sides, and
 * refraction treats the back as the inside of a closed mesh.
 */
#ifndef RAYTRACE_TRIANGLE_H
#define RAYTRACE_TRIANGLE_H

#include "geometry/material.h"
#include "geometry/ray.h"
#include "geometry/shape.h"
#include "math/colour.h"
#include "math/vec3.h"

/* What a triangle's surface holds beyond its plane, kept apart (in the
 * scene's shading array) for the triangles that have it: a plain one has
 * the default texture coordinates and is flat. */
typedef struct {
    double uv[3][2];   /* texture coordinates of the vertices */
    Vec3 vn[3];        /* unit vertex normals, when smooth */
    int smooth;        /* 1: shade with the normal interpolated from vn */
    int coloured;      /* 1: the surface's colour is rgb's, blended */
    float rgb[3][3];   /* the vertices' colours, 0 to 255 a channel */
} TriangleShading;

#define TRIANGLE_PLAIN 0xffffffffu /* a triangle's shading when it has none */

typedef struct {
    Vec3 v[3];         /* vertices, scene units */
    Vec3 normal;       /* unit (v1 - v0) x (v2 - v0): the front */
    unsigned swapped;  /* bit k: edge k's vertices are taken in reverse */
    unsigned shading;  /* index in the scene's shading, or TRIANGLE_PLAIN */
    unsigned material; /* index in the scene's materials (a mesh's
                          triangles share one) */
    unsigned order;    /* position among the scene's objects, for ties */
} Triangle;

/* Makes the triangle v0 v1 v2, plain, with material 0; returns -1 when its
 * vertices are on one line (no area, no normal), else 0. */
int triangle_make(Triangle *tri, Vec3 v0, Vec3 v1, Vec3 v2);

/* Returns a plain triangle's shading: texture coordinates (0, 0), (1, 0),
 * (0, 1) and its normal at every vertex, flat. */
TriangleShading triangle_plain_shading(const Triangle *tri);

/* Finds where the ray crosses the triangle with tmin < t < tmax; returns 1
 * and stores t, or returns 0. */
int triangle_intersect(const Triangle *tri, const Ray *ray, real tmin, real tmax, real *t);

/* Crossings of the triangle (shape.h): once or never. */
static inline int triangle_crossings(const Triangle *tri, const Ray *ray, real tmin, real tmax)
{
    real t;

    return triangle_intersect(tri, ray, tmin, tmax, &t);
}

/* The triangle's box, its vertices' (shape.h). */
real triangle_bounds(const Triangle *tri, real ulps, real lo[3], real hi[3]);
void triangle_box(const Triangle *tri, Vec3 *lo, Vec3 *hi);
double triangle_extent(const Triangle *tri);
void triangle_scale(Triangle *tri, int k);

/* triangle: x0 y0 z0 x1 y1 z1 x2 y2 z2 (its material is the scene's) */
extern const ShapeRecord triangle_record;

/* Returns the point where the ray meets the triangle's plane, computed from
 * its barycentric coordinates, with the normal (and, on a smooth triangle,
 * the shading normal interpolated from the vertex normals) and error bound;
 * stores in uv the interpolated texture coordinates, and in *rgb (unless
 * NULL) on a coloured triangle its vertices' colours blended. sh is the
 * triangle's shading, NULL for a plain one. The ray must cross the
 * triangle. */
SurfacePoint triangle_surface_at(const Triangle *tri, const TriangleShading *sh, const Ray *ray,
                                 double uv[2], Colour *rgb);

#endif
