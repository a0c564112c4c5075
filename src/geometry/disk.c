/* disk.c: the disk (see disk.h). */
#include "geometry/disk.h"

#include <math.h>

int disk_make(Disk *d, Vec3 centre, Vec3 n, real radius, Material m)
{
    if (n.x == 0 && n.y == 0 && n.z == 0)
        return -1;
    d->centre = centre;
    d->given = n;
    shape_flat_frame(n, &d->normal, &d->axis_u, &d->axis_v);
    d->radius = radius;
    d->material = m;
    d->order = 0;
    return 0;
}

int disk_intersect(const Disk *d, const Ray *ray, real tmin, real tmax, real *t)
{
    real den = vec3_dot(d->normal, ray->dir), tt, u, v;
    Vec3 f, r;

    if (den == 0)
        return 0;
    f = vec3_sub(ray->origin, d->centre);
    tt = -vec3_dot(d->normal, f) / den;
    if (!(tt > tmin && tt < tmax))
        return 0;
    r = vec3_add(f, vec3_scale(ray->dir, tt));
    u = vec3_dot(r, d->axis_u);
    v = vec3_dot(r, d->axis_v);
    if (!(u * u + v * v <= d->radius * d->radius))
        return 0;
    *t = tt;
    return 1;
}

SurfacePoint disk_surface(const Disk *d, const Ray *ray, real t)
{
    return shape_flat_surface(ray_at(ray, t), d->centre, d->normal);
}

void disk_uv(const Disk *d, Vec3 p, Vec3 n, double uv[2])
{
    Vec3 r = vec3_sub(p, d->centre);

    (void)n;
    uv[0] = (vec3_dot(r, d->axis_u) / d->radius + 1) / 2;
    uv[1] = (vec3_dot(r, d->axis_v) / d->radius + 1) / 2;
}

/* Returns how far the disk reaches from its centre along an axis whose
 * normal component is c: radius sqrt(1 - c^2). */
static real disk_reach(const Disk *d, real c)
{
    real s = 1 - c * c;

    return d->radius * sqrt(s > 0 ? s : 0);
}

real disk_bounds(const Disk *d, real ulps, real lo[3], real hi[3])
{
    Vec3 e = vec3(disk_reach(d, d->normal.x), disk_reach(d, d->normal.y),
                  disk_reach(d, d->normal.z));

    shape_empty(lo, hi);
    shape_grow(lo, hi, vec3_sub(d->centre, e));
    shape_grow(lo, hi, vec3_add(d->centre, e));
    /* The reach and the inside test round by a few ulps of the radius. */
    return 2 * d->radius * REAL_EPSILON * ulps;
}

void disk_box(const Disk *d, Vec3 *lo, Vec3 *hi)
{
    shape_widen(lo, hi, d->centre, d->radius);
}

double disk_extent(const Disk *d)
{
    return fmax(vec3_max_abs(d->centre), d->radius);
}

void disk_scale(Disk *d, int k)
{
    d->centre = vec3_ldexp(d->centre, k);
    d->radius = ldexp(d->radius, k);
}

static const char *const disk_names[] = {"centre x", "centre y", "centre z", "normal x",
                                         "normal y", "normal z", "radius"};
static const ShapeNumber disk_kinds[] = {SHAPE_COORD, SHAPE_COORD, SHAPE_COORD, SHAPE_COORD,
                                         SHAPE_COORD, SHAPE_COORD, SHAPE_LENGTH};

static const char *disk_record_make(void *shape, const double *v, const Material *m, int *field)
{
    if (disk_make(shape, shape_point(v, 0), shape_point(v, 3), v[6], *m) == 0)
        return NULL;
    *field = 3;
    return "the disk's normal is the zero vector: it must give a direction";
}

static void disk_record_numbers(const void *shape, int k, double *v)
{
    const Disk *d = shape;

    shape_put(v, 0, d->centre, k);
    shape_put(v, 3, d->given, 0);
    v[6] = ldexp(d->radius, -k);
}

const ShapeRecord disk_record = {7, "cx cy cz nx ny nz radius", disk_names, disk_kinds,
                                 disk_record_make, disk_record_numbers};
