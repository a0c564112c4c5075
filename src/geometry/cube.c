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

/* Where a ray's line crosses the box: it enters at t0 through the face of
 * axis enter_axis and leaves at t1 through that of leave_axis (the slab
 * crossed last and first; on a tie, the lower axis: x, then y, then z). */
typedef struct {
    real t0, t1;
    int enter_axis, leave_axis;
} CubeSpan;

/* Stores in *s where the ray's line enters and leaves the box (t0 <= t1);
 * returns 0 when the line misses it. A line parallel to a pair of faces
 * and within their slab (in a face's plane included) is inside it: the
 * box is closed. */
static int cube_slabs(const Cube *c, const Ray *ray, CubeSpan *s)
{
    real enter = -INFINITY, leave = INFINITY;
    int ea = -1, la = -1;

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
        if (n > enter) {
            enter = n;
            ea = a;
        }
        if (f < leave) {
            leave = f;
            la = a;
        }
    }
    if (!(enter <= leave))
        return 0;
    s->t0 = enter;
    s->t1 = leave;
    s->enter_axis = ea;
    s->leave_axis = la;
    return 1;
}

int cube_intersect(const Cube *c, const Ray *ray, real tmin, real tmax, real *t)
{
    CubeSpan s;

    if (!cube_slabs(c, ray, &s))
        return 0;
    if (s.t0 > tmin && s.t0 < tmax) {
        *t = s.t0;
        return 1;
    }
    if (s.t1 > tmin && s.t1 < tmax) {
        *t = s.t1;
        return 1;
    }
    return 0;
}

int cube_crossings(const Cube *c, const Ray *ray, real tmin, real tmax)
{
    CubeSpan s;

    if (!cube_slabs(c, ray, &s))
        return 0;
    return (s.t0 > tmin && s.t0 < tmax) + (s.t1 != s.t0 && s.t1 > tmin && s.t1 < tmax);
}

SurfacePoint cube_surface(const Cube *c, const Ray *ray, real t)
{
    Vec3 p = ray_at(ray, t);
    real q[3] = {p.x, p.y, p.z}, lo[3] = {c->lo.x, c->lo.y, c->lo.z};
    real hi[3] = {c->hi.x, c->hi.y, c->hi.z}, n[3] = {0, 0, 0};
    int axis = -1, side = -1;
    CubeSpan s;
    SurfacePoint sp;

    /* The face the ray enters at t0 (the slab it enters last), or leaves
     * at t1, whatever face p rounds nearest to: an edge belongs to the
     * face the ray crosses there, never to one it runs along. */
    if (cube_slabs(c, ray, &s) && (t == s.t0 || t == s.t1)) {
        axis = t == s.t0 ? s.enter_axis : s.leave_axis;
        if (axis >= 0) {
            int toward_hi = cube_at(ray->dir, axis) > 0;
            side = (t == s.t0) == toward_hi ? -1 : 1;
        }
    }
    if (axis < 0) {
        /* Not one of the ray's crossings: the face nearest to p. */
        real best = INFINITY;
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
    }
    /* p on that face, within the other two slabs. */
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

real cube_bounds(const Cube *c, real ulps, real lo[3], real hi[3])
{
    (void)ulps;
    shape_empty(lo, hi);
    shape_grow(lo, hi, c->lo);
    shape_grow(lo, hi, c->hi);
    return 0;
}

void cube_box(const Cube *c, Vec3 *lo, Vec3 *hi)
{
    shape_widen(lo, hi, c->lo, 0);
    shape_widen(lo, hi, c->hi, 0);
}

double cube_extent(const Cube *c)
{
    return fmax(vec3_max_abs(c->centre), c->half);
}

/* Its corners scale exactly with what they were made from. */
void cube_scale(Cube *c, int k)
{
    c->centre = vec3_ldexp(c->centre, k);
    c->lo = vec3_ldexp(c->lo, k);
    c->hi = vec3_ldexp(c->hi, k);
    c->half = ldexp(c->half, k);
}

static const char *const cube_names[] = {"centre x", "centre y", "centre z", "half-edge"};
static const ShapeNumber cube_kinds[] = {SHAPE_COORD, SHAPE_COORD, SHAPE_COORD, SHAPE_LENGTH};

static const char *cube_record_make(void *shape, const double *v, const Material *m, int *field)
{
    (void)field;
    cube_make(shape, shape_point(v, 0), v[3], *m);
    return NULL;
}

static void cube_record_numbers(const void *shape, int k, double *v)
{
    const Cube *c = shape;

    shape_put(v, 0, c->centre, k);
    v[3] = ldexp(c->half, -k);
}

const ShapeRecord cube_record = {4, "cx cy cz half-edge", cube_names, cube_kinds,
                                 cube_record_make, cube_record_numbers};
