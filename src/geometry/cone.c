/* cone.c: the infinite cone along y (see cone.h). */
#include "geometry/cone.h"

#include <math.h>

#include "math/angle.h"

/* The error bound of a surface point: 16 u of |apex| + |p - apex| per
 * component, as for the other quadrics. */
#define CONE_ERROR_ULPS 16.0

void cone_make(Cone *c, Vec3 base, real radius, real height, Material m)
{
    real l = sqrt(radius * radius + height * height);

    c->base = base;
    c->radius = radius;
    c->height = height;
    c->apex = vec3(base.x, base.y + height, base.z);
    c->k = (radius / height) * (radius / height);
    c->sine = radius / l;
    c->cosine = fabs(height) / l;
    c->side = height > 0 ? -1 : 1;
    c->finite = 0;
    c->material = m;
    c->order = 0;
}

/* Stores in t the roots of the ray's crossings with the nappe, ascending,
 * and returns how many there are (0, 1 or 2). */
static int cone_roots(const Cone *c, const Ray *ray, real t[2])
{
    real fx = ray->origin.x - c->apex.x, fy = ray->origin.y - c->apex.y;
    real fz = ray->origin.z - c->apex.z, dx = ray->dir.x, dy = ray->dir.y, dz = ray->dir.z;
    real a = dx * dx + dz * dz - c->k * dy * dy;
    real h = fx * dx + fz * dz - c->k * fy * dy;
    real cc = fx * fx + fz * fz - c->k * fy * fy;
    real cross = fx * dz - fz * dx, mx = fy * dx - dy * fx, mz = fy * dz - dy * fz;
    real disc = c->k * (mx * mx + mz * mz) - cross * cross; /* h^2 - a cc */
    real q, r[2];
    int n = 0;

    if (!(disc >= 0))
        return 0;
    q = -(h + copysign(sqrt(disc), h));
    if (q == 0) { /* the origin is on the surface and the line grazes it */
        r[0] = r[1] = 0;
    } else {
        r[0] = a != 0 ? q / a : INFINITY; /* a = 0: one root */
        r[1] = cc / q;
    }
    if (r[0] > r[1]) {
        real tmp = r[0];
        r[0] = r[1];
        r[1] = tmp;
    }
    for (int i = 0; i < 2; i++) {
        /* On this nappe: on the apex's `side`, or at the apex; a finite
         * cone's, no further from the apex than the circle. */
        real along = (fy + r[i] * dy) * c->side;
        if (isfinite(r[i]) && along >= 0 && (!c->finite || along <= fabs(c->height)) &&
            (n == 0 || r[i] != t[0]))
            t[n++] = r[i];
    }
    return n;
}

int cone_intersect(const Cone *c, const Ray *ray, real tmin, real tmax, real *t)
{
    real r[2];
    int n = cone_roots(c, ray, r);

    for (int i = 0; i < n; i++)
        if (r[i] > tmin && r[i] < tmax) {
            *t = r[i];
            return 1;
        }
    return 0;
}

int cone_crossings(const Cone *c, const Ray *ray, real tmin, real tmax)
{
    real r[2];
    int n = cone_roots(c, ray, r), k = 0;

    for (int i = 0; i < n; i++)
        k += r[i] > tmin && r[i] < tmax;
    return k;
}

SurfacePoint cone_surface_at(const Cone *c, Vec3 p)
{
    SurfacePoint sp;
    Vec3 d = vec3_sub(p, c->apex);
    real rho = sqrt(d.x * d.x + d.z * d.z), eta = c->side * d.y, ux, uz, s;

    /* (ux, uz): the unit direction away from the axis (any at the axis). */
    ux = rho > 0 ? d.x / rho : 1;
    uz = rho > 0 ? d.z / rho : 0;
    /* The nearest point of the generator through p, at s along it. */
    s = rho * c->sine + (eta > 0 ? eta : 0) * c->cosine;
    if (!(s > 0))
        s = 0;
    sp.point = vec3(c->apex.x + ux * (s * c->sine), c->apex.y + c->side * (s * c->cosine),
                    c->apex.z + uz * (s * c->sine));
    sp.normal = vec3(ux * c->cosine, -c->side * c->sine, uz * c->cosine);
    sp.shading = sp.normal;
    sp.error = vec3_scale(vec3_add(vec3_abs(c->apex), vec3_abs(d)), real_gamma(CONE_ERROR_ULPS));
    return sp;
}

void cone_uv(const Cone *c, Vec3 p, Vec3 n, double uv[2])
{
    (void)n;
    Vec3 d = vec3_sub(p, c->apex);

    uv[0] = 0.5 + angle_atan2(d.x, -d.z) / (2 * ANGLE_PI);
    uv[1] = p.y - c->base.y;
}

void cone_box(const Cone *c, Vec3 *lo, Vec3 *hi)
{
    shape_widen(lo, hi, c->base, c->radius);
    shape_widen(lo, hi, c->apex, 0);
}

double cone_extent(const Cone *c)
{
    return fmax(fmax(vec3_max_abs(c->base), vec3_max_abs(c->apex)),
                fmax(c->radius, fabs(c->height)));
}

/* The apex scales exactly with what it was made from; the angle stays. */
void cone_scale(Cone *c, int k)
{
    c->base = vec3_ldexp(c->base, k);
    c->apex = vec3_ldexp(c->apex, k);
    c->radius = ldexp(c->radius, k);
    c->height = ldexp(c->height, k);
}

static const char *const cone_names[] = {"x", "y", "z", "radius", "height"};
static const ShapeNumber cone_kinds[] = {SHAPE_COORD, SHAPE_COORD, SHAPE_COORD, SHAPE_LENGTH,
                                         SHAPE_COORD};

static const char *cone_record_make(void *shape, const double *v, const Material *m, int *field)
{
    if (v[4] == 0) {
        *field = 4;
        return "the cone's height must not be 0: its apex is that far above (or below) the "
               "centre of its circle";
    }
    cone_make(shape, shape_point(v, 0), v[3], v[4], *m);
    return NULL;
}

static void cone_record_numbers(const void *shape, int k, double *v)
{
    const Cone *c = shape;

    shape_put(v, 0, c->base, k);
    v[3] = ldexp(c->radius, -k);
    v[4] = ldexp(c->height, -k);
}

const ShapeRecord cone_record = {5, "x y z radius height", cone_names, cone_kinds,
                                 cone_record_make, cone_record_numbers};
