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

void sphere_uv(const Sphere *s, Vec3 p, Vec3 n, double uv[2])
{
    (void)s;
    (void)p;
    uv[0] = 0.5 + angle_atan2(n.x, -n.z) / (2 * ANGLE_PI);
    uv[1] = 1 - angle_acos(n.y) / ANGLE_PI;
}

real sphere_bounds(const Sphere *s, real ulps, real lo[3], real hi[3])
{
    shape_empty(lo, hi);
    shape_grow(lo, hi, s->centre);
    /* The radius, and the rounding of sphere_hit()'s discriminant. */
    return s->radius * (1 + REAL_EPSILON * (ulps / 16));
}

void sphere_box(const Sphere *s, Vec3 *lo, Vec3 *hi)
{
    shape_widen(lo, hi, s->centre, s->radius);
}

double sphere_extent(const Sphere *s)
{
    return fmax(vec3_max_abs(s->centre), s->radius);
}

void sphere_scale(Sphere *s, int k)
{
    s->centre = vec3_ldexp(s->centre, k);
    s->radius = ldexp(s->radius, k);
}

static const char *const sphere_names[] = {"centre x", "centre y", "centre z", "radius"};
static const ShapeNumber sphere_kinds[] = {SHAPE_COORD, SHAPE_COORD, SHAPE_COORD, SHAPE_LENGTH};

/* ShapeRecord.make: the material goes with the sphere into the scene. */
static const char *sphere_record_make(void *shape, const double *v, const Material *m, int *field)
{
    Sphere *s = shape;

    (void)m;
    (void)field;
    s->centre = shape_point(v, 0);
    s->radius = v[3];
    return NULL;
}

static void sphere_record_numbers(const void *shape, int k, double *v)
{
    const Sphere *s = shape;

    shape_put(v, 0, s->centre, k);
    v[3] = ldexp(s->radius, -k);
}

const ShapeRecord sphere_record = {4, "cx cy cz radius", sphere_names, sphere_kinds,
                                   sphere_record_make, sphere_record_numbers};
