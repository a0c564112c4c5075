/* sphere.c: ray/sphere intersection and surface geometry (see sphere.h). */
#include "geometry/sphere.h"

#include <float.h>
#include <math.h>

#include "math/angle.h"

/*
 * Relative error bound of sphere_surface_at()'s point, in the style of
 * pbrt's gamma(n) = n u / (1 - n u), u = REAL_EPSILON / 2.
 *
 * The point is centre + radius * n with n = v / |v|. Normalising leaves |n|
 * within about 3u of 1, the product radius * n_i adds u, the sum adds u of
 * |centre_i + radius * n_i|: each component is within roughly
 * 5u (|centre_i| + radius) of the exact surface. We take 16 in place of 5 so
 * that the offset ray_offset_origin() derives from this bound also covers the
 * rounding in the next intersection test (the sign of c = |f|^2 - r^2 and of
 * the discriminant need a margin of a few u * radius); the re-intersection
 * test in tests/test_sphere.c checks the margin at scales 1e-6 to 1e8.
 */
#define SPHERE_ERROR_ULPS 16.0

static real sphere_gamma(real n)
{
    real u = REAL_EPSILON / 2;
    return n * u / (1 - n * u);
}

int sphere_intersect(const Sphere *s, const Ray *ray, real tmin, real tmax, real *t)
{
    return sphere_hit(s->centre, s->radius, ray, tmin, tmax, t);
}

int sphere_crossings(const Sphere *s, const Ray *ray, real tmin, real tmax)
{
    real t, t2;

    if (!sphere_intersect(s, ray, tmin, tmax, &t))
        return 0;
    /* The second root, if it is in the interval, lies beyond the first. */
    return 1 + sphere_intersect(s, ray, t, tmax, &t2);
}

SurfacePoint sphere_surface_at(const Sphere *s, Vec3 p)
{
    SurfacePoint sp;
    Vec3 v = vec3_sub(p, s->centre);
    real len = vec3_length(v);
    real g = sphere_gamma(SPHERE_ERROR_ULPS);

    /* A hit at the centre (possible only when the radius is below the
     * resolution of the coordinates) has no direction: any unit one will do. */
    sp.normal = len > 0 ? vec3_scale(v, (real)1 / len) : vec3(0, 0, 1);
    sp.shading = sp.normal;
    sp.point = vec3_add(s->centre, vec3_scale(sp.normal, s->radius));
    sp.error = vec3_scale(vec3_add(vec3_abs(s->centre), vec3(s->radius, s->radius, s->radius)), g);
    return sp;
}

void sphere_uv(Vec3 n, double uv[2])
{
    uv[0] = 0.5 + angle_atan2(n.x, -n.z) / (2 * ANGLE_PI);
    uv[1] = 1 - angle_acos(n.y) / ANGLE_PI;
}
