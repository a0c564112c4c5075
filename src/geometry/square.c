/* square.c: the square (see square.h). */
#include "geometry/square.h"

#include <math.h>

/* The error bound of a surface point, as for planes (plane.c): 16 u of
 * |point| + |centre| per component. */
#define SQUARE_ERROR_ULPS 16.0

int square_make(Square *s, Vec3 centre, Vec3 n, real half, Material m)
{
    Vec3 up;

    if (n.x == 0 && n.y == 0 && n.z == 0)
        return -1;
    s->centre = centre;
    s->given = n;
    s->normal = vec3_normalize(vec3_ldexp(n, vec3_unit_exponent(vec3_max_abs(n))));
    /* v: the world's up as seen in the plane, or +z for a floor or ceiling. */
    up = fabs(s->normal.y) < 0.999999 ? vec3(0, 1, 0) : vec3(0, 0, 1);
    s->axis_v = vec3_normalize(vec3_sub(up, vec3_scale(s->normal, vec3_dot(up, s->normal))));
    s->axis_u = vec3_normalize(vec3_cross(s->normal, s->axis_v));
    s->half = half;
    s->material = m;
    s->order = 0;
    return 0;
}

int square_intersect(const Square *s, const Ray *ray, real tmin, real tmax, real *t)
{
    real den = vec3_dot(s->normal, ray->dir), tt;
    Vec3 r;

    if (den == 0)
        return 0;
    tt = vec3_dot(s->normal, vec3_sub(s->centre, ray->origin)) / den;
    if (!(tt > tmin && tt < tmax))
        return 0;
    r = vec3_sub(ray_at(ray, tt), s->centre);
    if (!(fabs(vec3_dot(r, s->axis_u)) <= s->half && fabs(vec3_dot(r, s->axis_v)) <= s->half))
        return 0;
    *t = tt;
    return 1;
}

SurfacePoint square_surface_at(const Square *s, Vec3 p)
{
    SurfacePoint sp;
    real dist = vec3_dot(vec3_sub(p, s->centre), s->normal);

    sp.point = vec3_sub(p, vec3_scale(s->normal, dist));
    sp.normal = s->normal;
    sp.shading = s->normal;
    sp.error = vec3_scale(vec3_add(vec3_abs(sp.point), vec3_abs(s->centre)),
                          real_gamma(SQUARE_ERROR_ULPS));
    return sp;
}

void square_uv(const Square *s, Vec3 p, double uv[2])
{
    Vec3 r = vec3_sub(p, s->centre);

    uv[0] = vec3_dot(r, s->axis_u);
    uv[1] = vec3_dot(r, s->axis_v);
}
