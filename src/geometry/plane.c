/* plane.c: ray/plane intersection and surface geometry (see plane.h). */
#include "geometry/plane.h"

#include <float.h>
#include <math.h>

int plane_make(Plane *pl, Vec3 point, Vec3 n, double tile, Material m)
{
    /* The world axis least aligned with n seeds a tangent frame. */
    Vec3 a = fabs(n.x) <= fabs(n.y) && fabs(n.x) <= fabs(n.z) ? vec3(1, 0, 0)
             : fabs(n.y) <= fabs(n.z)                         ? vec3(0, 1, 0)
                                                              : vec3(0, 0, 1);

    if (n.x == 0 && n.y == 0 && n.z == 0)
        return -1;
    pl->point = point;
    pl->given = n;
    pl->normal = vec3_normalize(vec3_ldexp(n, vec3_unit_exponent(vec3_max_abs(n))));
    pl->axis_u = vec3_normalize(vec3_cross(a, pl->normal));
    pl->axis_v = vec3_cross(pl->normal, pl->axis_u);
    pl->tile = tile;
    pl->material = m;
    pl->order = 0;
    return 0;
}

int plane_intersect(const Plane *pl, const Ray *ray, real tmin, real tmax, real *t)
{
    real den = vec3_dot(pl->normal, ray->dir);
    real tt;

    if (den == 0)
        return 0;
    tt = vec3_dot(pl->normal, vec3_sub(pl->point, ray->origin)) / den;
    if (!(tt > tmin && tt < tmax))
        return 0;
    *t = tt;
    return 1;
}

SurfacePoint plane_surface_at(const Plane *pl, Vec3 p)
{
    return shape_flat_surface(p, pl->point, pl->normal);
}

void plane_uv(const Plane *pl, Vec3 p, Vec3 n, double uv[2])
{
    (void)n;
    Vec3 r = vec3_sub(p, pl->point);

    uv[0] = vec3_dot(r, pl->axis_u) / pl->tile;
    uv[1] = vec3_dot(r, pl->axis_v) / pl->tile;
}

void plane_box(const Plane *pl, Vec3 *lo, Vec3 *hi)
{
    shape_widen(lo, hi, pl->point, 0);
}

double plane_extent(const Plane *pl)
{
    return fmax(vec3_max_abs(pl->point), pl->material.texture >= 0 ? pl->tile : 0);
}

void plane_scale(Plane *pl, int k)
{
    pl->point = vec3_ldexp(pl->point, k);
    pl->tile = ldexp(pl->tile, k);
}

static const char *const plane_names[] = {"point x",  "point y",  "point z",
                                          "normal x", "normal y", "normal z"};
static const ShapeNumber plane_kinds[] = {SHAPE_COORD, SHAPE_COORD, SHAPE_COORD,
                                          SHAPE_COORD, SHAPE_COORD, SHAPE_COORD};

static const char *plane_record_make(void *shape, const double *v, const Material *m, int *field)
{
    if (plane_make(shape, shape_point(v, 0), shape_point(v, 3), 1, *m) == 0)
        return NULL;
    *field = 3;
    return "the plane's normal is the zero vector: it must give a direction";
}

static void plane_record_numbers(const void *shape, int k, double *v)
{
    const Plane *pl = shape;

    shape_put(v, 0, pl->point, k);
    shape_put(v, 3, pl->given, 0);
}

const ShapeRecord plane_record = {6, "px py pz nx ny nz", plane_names, plane_kinds,
                                  plane_record_make, plane_record_numbers};
