/* square.c: the square (see square.h). */
#include "geometry/square.h"

#include <math.h>

int square_make(Square *s, Vec3 centre, Vec3 n, real half, Material m)
{
    if (n.x == 0 && n.y == 0 && n.z == 0)
        return -1;
    s->centre = centre;
    s->given = n;
    shape_flat_frame(n, &s->normal, &s->axis_u, &s->axis_v);
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
    return shape_flat_surface(p, s->centre, s->normal);
}

void square_uv(const Square *s, Vec3 p, Vec3 n, double uv[2])
{
    (void)n;
    Vec3 r = vec3_sub(p, s->centre);

    uv[0] = vec3_dot(r, s->axis_u);
    uv[1] = vec3_dot(r, s->axis_v);
}

real square_bounds(const Square *s, real ulps, real lo[3], real hi[3])
{
    Vec3 u = vec3_scale(s->axis_u, s->half), v = vec3_scale(s->axis_v, s->half);

    shape_empty(lo, hi);
    for (int k = 0; k < 4; k++)
        shape_grow(lo, hi, vec3_add(vec3_add(s->centre, k & 1 ? u : vec3_neg(u)),
                                    k & 2 ? v : vec3_neg(v)));
    /* The corners round by a few ulps of the square's size; the plane
     * test rounds as a triangle's. */
    return 2 * s->half * REAL_EPSILON * ulps;
}

void square_box(const Square *s, Vec3 *lo, Vec3 *hi)
{
    shape_widen(lo, hi, s->centre, s->half * (real)1.5);
}

double square_extent(const Square *s)
{
    return fmax(vec3_max_abs(s->centre), s->half);
}

void square_scale(Square *s, int k)
{
    s->centre = vec3_ldexp(s->centre, k);
    s->half = ldexp(s->half, k);
}

static const char *const square_names[] = {"centre x", "centre y", "centre z", "normal x",
                                           "normal y", "normal z", "half-edge"};
static const ShapeNumber square_kinds[] = {SHAPE_COORD, SHAPE_COORD, SHAPE_COORD, SHAPE_COORD,
                                           SHAPE_COORD, SHAPE_COORD, SHAPE_LENGTH};

static const char *square_record_make(void *shape, const double *v, const Material *m, int *field)
{
    if (square_make(shape, shape_point(v, 0), shape_point(v, 3), v[6], *m) == 0)
        return NULL;
    *field = 3;
    return "the square's normal is the zero vector: it must give a direction";
}

static void square_record_numbers(const void *shape, int k, double *v)
{
    const Square *s = shape;

    shape_put(v, 0, s->centre, k);
    shape_put(v, 3, s->given, 0);
    v[6] = ldexp(s->half, -k);
}

const ShapeRecord square_record = {7, "cx cy cz nx ny nz half-edge", square_names, square_kinds,
                                   square_record_make, square_record_numbers};
