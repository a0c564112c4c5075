/*
 * shape.h: what every kind of shape gives, whatever it is (the kinds are
 * listed in shape_list.h).
 *
 * A kind NAME of type T has, in geometry/NAME.h and NAME.c:
 *   int NAME_intersect(const T *, const Ray *, real tmin, real tmax, real *t)
 *       where the ray first crosses it, tmin < t < tmax;
 *   int NAME_crossings(const T *, const Ray *, real tmin, real tmax)
 *       how many times the ray crosses it there (a shadow ray's
 *       transmittance multiplies once per crossing);
 *   void NAME_box(const T *, Vec3 *lo, Vec3 *hi)
 *       widens the box [lo, hi] by the points that place it (its whole
 *       surface when bounded), for the scene's size;
 *   double NAME_extent(const T *) and void NAME_scale(T *, int k)
 *       the largest magnitude of its lengths and coordinates, and every
 *       length times 2^k (scale.h enlarges tiny scenes);
 *   extern const ShapeRecord NAME_record
 *       the numbers a scene file's record of it gives (below);
 * a bounded kind (one the hierarchy holds):
 *   real NAME_bounds(const T *, real ulps, real lo[3], real hi[3])
 *       the box around it, and the margin to widen it by so that every
 *       ray its intersection test accepts enters it, the test's rounding
 *       being taken as ulps units of the last place;
 * and every kind but the triangle (a mesh's shading is the scene's):
 *   SurfacePoint NAME_surface(const T *, const Ray *, real t)
 *       the point where the ray crosses it at t (from NAME_intersect()),
 *       on the surface, with its outward normal and error bound;
 *   SurfacePoint NAME_surface_near(const T *, const SurfacePoint *hit, Vec3 p)
 *       the surface point for p, a point of hit's tangent plane near it
 *       (the footprint of a pixel: flat kinds keep hit's normal);
 *   void NAME_uv(const T *, Vec3 p, Vec3 n, double uv[2])
 *       the texture coordinates of its point p of outward normal n.
 */
#ifndef RAYTRACE_SHAPE_H
#define RAYTRACE_SHAPE_H

#include <math.h>

#include "geometry/material.h"
#include "geometry/ray.h"
#include "math/vec3.h"

/* What a number of a shape's record may be. */
typedef enum {
    SHAPE_COORD, /* any finite value: a coordinate, a direction's component */
    SHAPE_LENGTH /* > 0: a radius, a half-edge */
} ShapeNumber;

/* A kind's record in the scene files: its numbers, after the record's word
 * (the kind's name), before its material. */
typedef struct {
    int count;                 /* numbers, at most SHAPE_NUMBERS_MAX */
    const char *syntax;        /* "cx cy cz radius", for messages */
    const char *const *names;  /* each number's name ("centre x") */
    const ShapeNumber *kinds;  /* and what it may be */
    /* Makes the shape of numbers v and material m (held when the kind
     * holds its material) in *shape; returns NULL, or why the numbers make
     * no shape with *field the number at fault (-1: the whole record). */
    const char *(*make)(void *shape, const double *v, const Material *m, int *field);
    /* Stores in v the numbers that made *shape, its lengths (and
     * coordinates) divided by 2^k exactly. */
    void (*numbers)(const void *shape, int k, double *v);
} ShapeRecord;

enum { SHAPE_NUMBERS_MAX = 9 }; /* the most numbers a record gives */

/* Returns the point of a record's numbers v from index i. */
static inline Vec3 shape_point(const double *v, int i)
{
    return vec3(v[i], v[i + 1], v[i + 2]);
}

/* Stores p's coordinates, divided by 2^k, in v from index i. */
static inline void shape_put(double *v, int i, Vec3 p, int k)
{
    v[i] = ldexp(p.x, -k);
    v[i + 1] = ldexp(p.y, -k);
    v[i + 2] = ldexp(p.z, -k);
}

/* Returns the least and the greatest of a and b, finite (comparisons: no
 * library call for NaNs there are none of). */
static inline real shape_min(real a, real b)
{
    return b < a ? b : a;
}
static inline real shape_max(real a, real b)
{
    return b > a ? b : a;
}

/* Widens the box [lo, hi] to hold p, grown by r on each axis. */
static inline void shape_widen(Vec3 *lo, Vec3 *hi, Vec3 p, real r)
{
    lo->x = shape_min(lo->x, p.x - r);
    lo->y = shape_min(lo->y, p.y - r);
    lo->z = shape_min(lo->z, p.z - r);
    hi->x = shape_max(hi->x, p.x + r);
    hi->y = shape_max(hi->y, p.y + r);
    hi->z = shape_max(hi->z, p.z + r);
}

/* Grows the box lo, hi (arrays, as the hierarchy keeps them) by the point p. */
static inline void shape_grow(real lo[3], real hi[3], Vec3 p)
{
    real c[3] = {p.x, p.y, p.z};

    for (int a = 0; a < 3; a++) {
        lo[a] = c[a] < lo[a] ? c[a] : lo[a];
        hi[a] = c[a] > hi[a] ? c[a] : hi[a];
    }
}

/* Stores in *normal the unit normal along n (any length, not zero), and
 * in *u and *v the unit axes of a flat shape's plane: v the world's up as
 * seen in the plane (+z for a floor or a ceiling), u = normal x v. */
static inline void shape_flat_frame(Vec3 n, Vec3 *normal, Vec3 *u, Vec3 *v)
{
    Vec3 up;

    *normal = vec3_normalize(vec3_ldexp(n, vec3_unit_exponent(vec3_max_abs(n))));
    up = fabs(normal->y) < 0.999999 ? vec3(0, 1, 0) : vec3(0, 0, 1);
    *v = vec3_normalize(vec3_sub(up, vec3_scale(*normal, vec3_dot(up, *normal))));
    *u = vec3_normalize(vec3_cross(*normal, *v));
}

/* Returns p, a point near the plane through origin of unit normal n, put
 * onto it, with n and its error bound: 16 u of |point| + |origin| per
 * component (the re-projection rounds a few times; 16 leaves the next
 * intersection test the margin to see an offset origin on its side). */
static inline SurfacePoint shape_flat_surface(Vec3 p, Vec3 origin, Vec3 n)
{
    SurfacePoint sp;
    real dist = vec3_dot(vec3_sub(p, origin), n);

    sp.point = vec3_sub(p, vec3_scale(n, dist));
    sp.normal = n;
    sp.shading = n;
    sp.error = vec3_scale(vec3_add(vec3_abs(sp.point), vec3_abs(origin)), real_gamma(16));
    return sp;
}

/* Makes lo, hi the empty box, which shape_grow() widens. */
static inline void shape_empty(real lo[3], real hi[3])
{
    for (int a = 0; a < 3; a++) {
        lo[a] = INFINITY;
        hi[a] = -INFINITY;
    }
}

#endif
