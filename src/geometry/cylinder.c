/* cylinder.c: the infinite cylinder along y (see cylinder.h). */
#include "geometry/cylinder.h"

#include <math.h>

#include "math/angle.h"

/* The error bound of a surface point, as for spheres (sphere.c): 16 u of
 * |centre| + radius across the axis, of |p.y| along it. */
#define CYLINDER_ERROR_ULPS 16.0

/* Finds the roots t0 <= t1 of the ray's shadow on the xz plane crossing
 * the circle; returns 0 when it misses it or runs parallel to the axis. */
static int cylinder_roots(const Cylinder *c, const Ray *ray, real *t0, real *t1)
{
    real fx = ray->origin.x - c->centre.x, fz = ray->origin.z - c->centre.z;
    real dx = ray->dir.x, dz = ray->dir.z;
    real a = dx * dx + dz * dz, h = fx * dx + fz * dz, r2 = c->radius * c->radius;
    real lx, lz, disc, cc, q;

    if (!(a > 0))
        return 0;
    /* (lx, lz) is f less its projection on d: the axis's distance to the
     * ray's line, so r2 - |l|^2 = (h^2 - a c) / a without cancellation. */
    lx = fx - dx * (h / a);
    lz = fz - dz * (h / a);
    disc = r2 - (lx * lx + lz * lz);
    if (!(disc >= 0))
        return 0;
    cc = fx * fx + fz * fz - r2;
    q = -(h + copysign(sqrt(a * disc), h));
    if (q == 0) {
        *t0 = *t1 = 0;
        return 1;
    }
    *t0 = q / a;
    *t1 = cc / q;
    if (*t0 > *t1) {
        real tmp = *t0;
        *t0 = *t1;
        *t1 = tmp;
    }
    return 1;
}

int cylinder_intersect(const Cylinder *c, const Ray *ray, real tmin, real tmax, real *t)
{
    real t0, t1;

    if (!cylinder_roots(c, ray, &t0, &t1))
        return 0;
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

int cylinder_crossings(const Cylinder *c, const Ray *ray, real tmin, real tmax)
{
    real t0, t1;

    if (!cylinder_roots(c, ray, &t0, &t1))
        return 0;
    return (t0 > tmin && t0 < tmax) + (t1 != t0 && t1 > tmin && t1 < tmax);
}

SurfacePoint cylinder_surface_at(const Cylinder *c, Vec3 p)
{
    SurfacePoint sp;
    Vec3 v = vec3(p.x - c->centre.x, 0, p.z - c->centre.z);
    real len = vec3_length(v), g = real_gamma(CYLINDER_ERROR_ULPS);

    sp.normal = len > 0 ? vec3_scale(v, (real)1 / len) : vec3(1, 0, 0);
    sp.shading = sp.normal;
    sp.point = vec3(c->centre.x + c->radius * sp.normal.x, p.y,
                    c->centre.z + c->radius * sp.normal.z);
    sp.error = vec3((fabs(c->centre.x) + c->radius) * g, fabs(p.y) * g,
                    (fabs(c->centre.z) + c->radius) * g);
    return sp;
}

void cylinder_uv(const Cylinder *c, Vec3 p, Vec3 n, double uv[2])
{
    uv[0] = 0.5 + angle_atan2(n.x, -n.z) / (2 * ANGLE_PI);
    uv[1] = p.y - c->centre.y;
}

void cylinder_box(const Cylinder *c, Vec3 *lo, Vec3 *hi)
{
    shape_widen(lo, hi, c->centre, c->radius);
}

double cylinder_extent(const Cylinder *c)
{
    return fmax(vec3_max_abs(c->centre), c->radius);
}

void cylinder_scale(Cylinder *c, int k)
{
    c->centre = vec3_ldexp(c->centre, k);
    c->radius = ldexp(c->radius, k);
}

static const char *const cylinder_names[] = {"centre x", "centre y", "centre z", "radius"};
static const ShapeNumber cylinder_kinds[] = {SHAPE_COORD, SHAPE_COORD, SHAPE_COORD,
                                             SHAPE_LENGTH};

static const char *cylinder_record_make(void *shape, const double *v, const Material *m,
                                        int *field)
{
    Cylinder c = {shape_point(v, 0), v[3], *m, 0};

    (void)field;
    *(Cylinder *)shape = c;
    return NULL;
}

static void cylinder_record_numbers(const void *shape, int k, double *v)
{
    const Cylinder *c = shape;

    shape_put(v, 0, c->centre, k);
    v[3] = ldexp(c->radius, -k);
}

const ShapeRecord cylinder_record = {4, "cx cy cz radius", cylinder_names, cylinder_kinds,
                                     cylinder_record_make, cylinder_record_numbers};
