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

#include <math.h>
#include <stdint.h>

#include "geometry/material.h"
#include "geometry/ray.h"
#include "geometry/shape.h"
#include "math/vec3.h"

/* A sphere: 48 bytes, as a scene may hold millions. Most spheres' material
 * is plain (sphere_plain()): its mirror weight and colour are held here;
 * any other is in the scene's table of materials (sphere_material_index()). */
typedef struct {
    Vec3 centre;       /* scene units */
    real radius;       /* scene units, > 0 */
    union {
        double reflection; /* plain: the material's mirror weight R */
        int index;         /* else: its index in the scene's materials
                              (scene.h: scene_material()) */
    } material;
    unsigned order;    /* position among the scene's objects, for ties */
    uint8_t rgb[3];    /* plain: the material's colour Ci */
    uint8_t plain;     /* 1: the material is plain, held here; 0: indexed */
} Sphere;

/* Returns the index of sphere s's material in the scene's materials, or
 * -1 when s holds it itself (plain). */
static inline int sphere_material_index(const Sphere *s)
{
    return s->plain ? -1 : s->material.index;
}

/* Gives sphere s the material of index k in the scene's materials. */
static inline void sphere_set_material_index(Sphere *s, int k)
{
    s->material.index = k;
    s->plain = 0;
}

/* Returns 1 when a sphere holds material m itself: m is plain
 * (material_is_plain()) and its colour's channels are whole numbers from 0
 * to 255, as the course's scenes write them; else 0. */
static inline int sphere_plain(const Material *m)
{
    const double c[3] = {m->colour.r, m->colour.g, m->colour.b};

    for (int k = 0; k < 3; k++)
        if (!(c[k] >= 0 && c[k] <= 255 && c[k] == floor(c[k])) || signbit(c[k]))
            return 0;
    return material_is_plain(m);
}

/* Returns the plain material sphere s holds (sphere_plain()). */
static inline Material sphere_material(const Sphere *s)
{
    return material_plain(colour(s->rgb[0], s->rgb[1], s->rgb[2]), s->material.reflection);
}

/* Gives sphere s the plain material m (sphere_plain(m)). */
static inline void sphere_set_plain(Sphere *s, const Material *m)
{
    s->material.reflection = m->reflection;
    s->plain = 1;
    s->rgb[0] = (uint8_t)m->colour.r;
    s->rgb[1] = (uint8_t)m->colour.g;
    s->rgb[2] = (uint8_t)m->colour.b;
}

/*
 * Finds where the ray first crosses the surface of the sphere of centre and
 * radius with tmin < t < tmax (an open interval); returns 1 and stores that
 * t in *t, or returns 0. The ray's direction may have any non-zero length; a
 * tangent ray counts as crossing. Inline: the loops over every sphere and
 * the hierarchy's leaves call it.
 */
static inline int sphere_hit(Vec3 centre, real radius, const Ray *ray, real tmin, real tmax,
                             real *t)
{
    Vec3 f = vec3_sub(ray->origin, centre);
    Vec3 d = ray->dir;
    real a = vec3_dot(d, d);
    real h = vec3_dot(f, d); /* half of the quadratic's b */
    real r2 = radius * radius;
    /* l is f minus its projection on d: its length is the centre's distance
     * to the line, so r2 - |l|^2 = (h^2 - a c) / a without cancellation. */
    Vec3 l = vec3_sub(f, vec3_scale(d, h / a));
    real disc = r2 - vec3_dot(l, l);
    real c, q, t0, t1;

    if (!(disc >= 0))
        return 0;
    c = vec3_dot(f, f) - r2;
    q = -(h + copysign(sqrt(a * disc), h));
    if (q == 0) {
        /* h = 0 and disc = 0: the origin is the tangent point, t = 0 twice. */
        t0 = t1 = 0;
    } else {
        t0 = q / a;
        t1 = c / q;
        if (t0 > t1) {
            real tmp = t0;
            t0 = t1;
            t1 = tmp;
        }
    }
    if (t0 > tmin && t0 < tmax) {
        *t = t0;
        return 1;
    }
    if (t1 > tmin && t1 < tmax) {
        *t = t1;
        return 1;
    }
    return 0;
}

/* sphere_hit() on sphere s. */
static inline int sphere_intersect(const Sphere *s, const Ray *ray, real tmin, real tmax, real *t)
{
    return sphere_hit(s->centre, s->radius, ray, tmin, tmax, t);
}

/* Returns how many times the ray crosses s's surface with tmin < t < tmax:
 * 0, 1 or 2. */
int sphere_crossings(const Sphere *s, const Ray *ray, real tmin, real tmax);

/* Re-projects p, a point near s's surface, onto the surface and returns it
 * with its outward normal and error bound. */
SurfacePoint sphere_surface_at(const Sphere *s, Vec3 p);

/* The surface point where the ray crosses s at t (shape.h). */
static inline SurfacePoint sphere_surface(const Sphere *s, const Ray *ray, real t)
{
    return sphere_surface_at(s, ray_at(ray, t));
}

/* The surface point for p, near hit (shape.h): p put onto the sphere. */
static inline SurfacePoint sphere_surface_near(const Sphere *s, const SurfacePoint *hit, Vec3 p)
{
    (void)hit;
    return sphere_surface_at(s, p);
}

/* Returns in uv the texture coordinates of the point of outward normal n
 * (any sphere's, p aside): u = 0.5 + atan2(n.x, -n.z) / (2 pi) around the
 * y axis (0.5 facing -z), and v = 1 - acos(n.y) / pi from the south pole
 * (v = 0) to the north (v = 1). */
void sphere_uv(const Sphere *s, Vec3 p, Vec3 n, double uv[2]);

/* The sphere's box, its centre widened by its radius (shape.h). */
real sphere_bounds(const Sphere *s, real ulps, real lo[3], real hi[3]);
void sphere_box(const Sphere *s, Vec3 *lo, Vec3 *hi);
double sphere_extent(const Sphere *s);
void sphere_scale(Sphere *s, int k);

/* sphere: cx cy cz radius */
extern const ShapeRecord sphere_record;

#endif
