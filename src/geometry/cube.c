/* cube.c: the axis-aligned cube (see cube.h). */
#include "geometry/cube.h"

#include <math.h>

/* The error bound of a surface point, in units of u of |p| + |centre| +
 * half per component: on the face's axis the point is the face's own
 * coordinate; along the face it is o + t d, a few roundings off, which no
 * offset along the normal depends on. 16, as for the other shapes, leaves
 * room for the next test's subtraction. */
#define CUBE_ERROR_ULPS 16.0

void cube_make(Cube *c, Vec3 centre, real half, Material m)
{
    Vec3 h = vec3(half, half, half);

    c->centre = centre;
    c->half = half;
    c->lo = vec3_sub(centre, h);
    c->hi = vec3_add(centre, h);
    c->material = m;
    c->order = 0;
}

/* Returns component a of v. */
static inline real cube_at(Vec3 v, int a)
{
    return a == 0 ? v.x : a == 1 ? v.y : v.z;
}

/* Stores in *t0 and *t1 where the ray's line enters and leaves the box
 * (t0 <= t1); returns 0 when the line misses it. */
static int cube_slabs(const Cube *c, const Ray *ray, real *t0, real *t1)
{
    real enter = -INFINITY, leave = INFINITY;

    for (int a = 0; a < 3; a++) {
        real o = cube_at(ray->origin, a), d = cube_at(ray->dir, a);
        real lo = cube_at(c->lo, a), hi = cube_at(c->hi, a), n, f;
        if (d == 0) {
            /* Parallel to this axis's faces: inside their slab or never. */
            if (o < lo || o > hi)
                return 0;
            continue;
        }
        n = (lo - o) / d;
        f = (hi - o) / d;
        if (d < 0) {
            real tmp = n;
            n = f;
            f = tmp;
        }
        enter = n > enter ? n : enter;
        leave = f < leave ? f : leave;
    }
    if (!(enter <= leave))
        return 0;
    *t0 = enter;
    *t1 = leave;
    return 1;
}

int cube_intersect(const Cube *c, const Ray *ray, real tmin, real tmax, real *t)
{
    real t0, t1;

    if (!cube_slabs(c, ray, &t0, &t1))
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

int cube_crossings(const Cube *c, const Ray *ray, real tmin, real tmax)
{
    real t0, t1;

    if (!cube_slabs(c, ray, &t0, &t1))
        return 0;
    return (t0 > tmin && t0 < tmax) + (t1 != t0 && t1 > tmin && t1 < tmax);
}

SurfacePoint cube_surface_at(const Cube *c, Vec3 p)
{
    real q[3] = {p.x, p.y, p.z}, lo[3] = {c->lo.x, c->lo.y, c->lo.z};
    real hi[3] = {c->hi.x, c->hi.y, c->hi.z}, n[3] = {0, 0, 0}, best = INFINITY;
    int axis = 0, side = -1;
    SurfacePoint sp;

    /* The face nearest to p, then p on it and within the other two slabs. */
    for (int a = 0; a < 3; a++) {
        real dl = fabs(q[a] - lo[a]), dh = fabs(q[a] - hi[a]);
        if (dl < best) {
            best = dl;
            axis = a;
            side = -1;
        }
        if (dh < best) {
            best = dh;
            axis = a;
            side = 1;
        }
    }
    for (int a = 0; a < 3; a++)
        q[a] = q[a] < lo[a] ? lo[a] : q[a] > hi[a] ? hi[a] : q[a];
    q[axis] = side < 0 ? lo[axis] : hi[axis];
    n[axis] = side;
    sp.point = vec3(q[0], q[1], q[2]);
    sp.normal = vec3(n[0], n[1], n[2]);
    sp.shading = sp.normal;
    sp.error = vec3_scale(vec3_add(vec3_add(vec3_abs(sp.point), vec3_abs(c->centre)),
                                   vec3(c->half, c->half, c->half)),
                          real_gamma(CUBE_ERROR_ULPS));
    return sp;
}

void cube_uv(const Cube *c, Vec3 p, Vec3 n, double uv[2])
{
    double e = 2 * (double)c->half;
    double x = (p.x - c->lo.x) / e, y = (p.y - c->lo.y) / e, z = (p.z - c->lo.z) / e;

    if (n.x != 0) { /* seen from +x, +z is on the right; from -x, -z */
        uv[0] = n.x > 0 ? z : 1 - z;
        uv[1] = y;
    } else if (n.z != 0) { /* from -z, +x on the right; from +z, -x */
        uv[0] = n.z < 0 ? x : 1 - x;
        uv[1] = y;
    } else { /* top and bottom: +z up, +x right from above */
        uv[0] = n.y > 0 ? x : 1 - x;
        uv[1] = z;
    }
}
