/* torus.c: the ring torus (see torus.h). */
#include "geometry/torus.h"

#include <float.h>
#include <math.h>

#include "math/angle.h"

/* The error bound of a surface point, in units of u of |centre| + (R + r)
 * R / r per component: the point is rounded from the centre and the frame
 * (16 u, as a sphere's), and a root of a thin tube's quartic is placed
 * within a few u of R over r / R (the quartic's slope at a root is of
 * the order of r / R): the offset of a ray leaving the surface must
 * clear it. tests/test_torus.c checks it from 1e-6 to 1e8. */
#define TORUS_ERROR_ULPS 16.0

/* The thinnest tube, as a share of R: the error bound above grows as R / r,
 * and a wire a ten-thousandth of its ring keeps it below 10^-10 of R. */
#define TORUS_THINNEST 1e-4

int torus_make(Torus *t, Vec3 centre, Vec3 n, real major, real minor, Material m)
{
    /* The world axis least aligned with n seeds the frame (as a plane's). */
    Vec3 a;

    if (n.x == 0 && n.y == 0 && n.z == 0)
        return -1;
    if (!(minor >= major * TORUS_THINNEST && minor < major))
        return -2;
    t->centre = centre;
    t->given = n;
    t->axis = vec3_normalize(vec3_ldexp(n, vec3_unit_exponent(vec3_max_abs(n))));
    a = fabs(t->axis.x) <= fabs(t->axis.y) && fabs(t->axis.x) <= fabs(t->axis.z) ? vec3(1, 0, 0)
        : fabs(t->axis.y) <= fabs(t->axis.z)                                     ? vec3(0, 1, 0)
                                                                                 : vec3(0, 0, 1);
    t->axis_u = vec3_normalize(vec3_cross(a, t->axis));
    t->axis_v = vec3_cross(t->axis, t->axis_u);
    t->major = major;
    t->minor = minor;
    t->material = m;
    t->order = 0;
    return 0;
}

/* A ray in the torus's frame (x along axis_u, y along axis_v, z along the
 * axis), in units of R, with a unit direction d, from p, the point of its
 * line nearest to the centre (p . d = 0): the point at s is p + s d, which
 * the ray reaches at t = (s0 + s) scale. */
typedef struct {
    double p[3], d[3];
    double s0, scale;
    double k; /* r / R */
} TorusRay;

/* Returns the components of w in the torus's frame, divided by div. */
static void torus_local(const Torus *tor, Vec3 w, double div, double out[3])
{
    out[0] = vec3_dot(w, tor->axis_u) / div;
    out[1] = vec3_dot(w, tor->axis_v) / div;
    out[2] = vec3_dot(w, tor->axis) / div;
}

/* Stores in *tr the ray in the torus's frame. */
static void torus_ray(const Torus *tor, const Ray *ray, TorusRay *tr)
{
    double f[3], len = vec3_length(ray->dir), dl = 0, pd = 0;

    torus_local(tor, vec3_sub(ray->origin, tor->centre), tor->major, f);
    torus_local(tor, ray->dir, len, tr->d);
    for (int a = 0; a < 3; a++)
        dl += tr->d[a] * tr->d[a];
    dl = sqrt(dl);
    for (int a = 0; a < 3; a++) {
        tr->d[a] /= dl;
        pd += f[a] * tr->d[a];
    }
    tr->s0 = -pd;
    for (int a = 0; a < 3; a++)
        tr->p[a] = f[a] + tr->s0 * tr->d[a];
    tr->scale = tor->major / (len * dl);
    tr->k = tor->minor / tor->major;
}

/* Returns the sign of the distance from the point p + s d to the tube (the
 * sign of the quartic, whose other factor is positive): -1 inside, 0 on,
 * +1 outside. */
static int torus_side(const TorusRay *tr, double s)
{
    double x = tr->p[0] + s * tr->d[0], y = tr->p[1] + s * tr->d[1], z = tr->p[2] + s * tr->d[2];
    double w = hypot(x, y) - 1, g = hypot(w, z) - tr->k;

    return (g > 0) - (g < 0);
}

/* Returns the polynomial c[0] + c[1] s + ... + c[n] s^n at s. */
static double torus_poly(const double *c, int n, double s)
{
    double v = c[n];

    for (int i = n - 1; i >= 0; i--)
        v = v * s + c[i];
    return v;
}

/* Returns the root in [a, b] of the polynomial c of degree n, monotonic
 * there, whose value fa at a differs in sign from its value at b:
 * Newton's steps while they stay inside the bracket, halving otherwise,
 * to the last bits (the roots are of the order of 1). */
static double torus_root(const double *c, int n, double a, double b, double fa)
{
    double dc[4], s = 0.5 * (a + b);

    for (int i = 1; i <= n; i++)
        dc[i - 1] = i * c[i];
    for (int iter = 0; iter < 100; iter++) {
        double f = torus_poly(c, n, s), next, tol = 2 * DBL_EPSILON * fmax(fabs(s), 1);
        if (f == 0)
            return s;
        if ((f < 0) == (fa < 0))
            a = s;
        else
            b = s;
        next = s - f / torus_poly(dc, n - 1, s);
        if (!(next > a && next < b))
            next = 0.5 * (a + b);
        if (fabs(next - s) <= tol || b - a <= tol)
            return next;
        s = next;
    }
    return s;
}

/* Stores in r the roots in [lo, hi] of the polynomial c of degree n (2, 3
 * or 4, c[n] > 0), ascending; returns how many (a root of even order is
 * found when the rounding shows a change of sign). */
static int torus_roots(const double *c, int n, double lo, double hi, double *r)
{
    double dc[4], cut[5];
    int m = 0, found = 0;

    for (int i = 1; i <= n; i++)
        dc[i - 1] = i * c[i];
    cut[m++] = lo;
    if (n == 2) {
        /* The parabola's vertex splits it into two monotonic halves. */
        double v = -c[1] / (2 * c[2]);
        if (v > lo && v < hi)
            cut[m++] = v;
    } else {
        double d[3];
        int k = torus_roots(dc, n - 1, lo, hi, d);
        for (int i = 0; i < k; i++)
            if (d[i] > cut[m - 1])
                cut[m++] = d[i];
    }
    if (hi > cut[m - 1])
        cut[m++] = hi;
    for (int i = 0; i + 1 < m; i++) {
        double fa = torus_poly(c, n, cut[i]), fb = torus_poly(c, n, cut[i + 1]);
        if (fa == 0 && (found == 0 || r[found - 1] < cut[i]))
            r[found++] = cut[i];
        else if ((fa < 0) != (fb < 0) && fb != 0)
            r[found++] = torus_root(c, n, cut[i], cut[i + 1], fa);
    }
    if (m >= 2 && torus_poly(c, n, cut[m - 1]) == 0 && (found == 0 || r[found - 1] < cut[m - 1]))
        r[found++] = cut[m - 1];
    return found;
}

/* Moves root s of the quartic to where the sign of the distance to the
 * tube changes near it (within the quartic's own rounding, which grows as
 * the tube thins), when the two ends of that span show a change: the
 * distance keeps its digits nearer the surface than the quartic does. */
static double torus_polish(const TorusRay *tr, double s)
{
    double ulp = DBL_EPSILON * fmax(fabs(s), 1), step = 8 * ulp * (1 + 1 / tr->k);
    double a = s - step, b = s + step;
    int sa = torus_side(tr, a), sb = torus_side(tr, b);

    if (sa == 0 || sb == 0 || sa == sb)
        return s;
    while (b - a > 2 * ulp) {
        double m = 0.5 * (a + b);
        int sm = torus_side(tr, m);
        if (sm == 0)
            return m;
        if (sm == sa)
            a = m;
        else
            b = m;
    }
    return 0.5 * (a + b);
}

/* Stores in t the ray parameters of its crossings of the torus with
 * tmin < t < tmax, ascending; returns how many (at most 4). */
static int torus_hits(const Torus *tor, const Ray *ray, real tmin, real tmax, real t[4])
{
    TorusRay tr;
    double h2, reach, g, q[5], s[4], a, c;
    int n, found = 0;

    torus_ray(tor, ray, &tr);
    h2 = tr.p[0] * tr.p[0] + tr.p[1] * tr.p[1] + tr.p[2] * tr.p[2];
    reach = (1 + tr.k) * (1 + tr.k) - h2; /* the bounding sphere's chord, squared half */
    if (!(reach > 0))
        return 0;
    reach = sqrt(reach) * (1 + 1e-9) + 4 * DBL_EPSILON;
    /* (|p + s d|^2 + 1 - k^2)^2 = 4 ((p + s d)_x^2 + (p + s d)_y^2), with
     * p . d = 0: s^4 + (2 g - 4 a) s^2 - 8 c s + g^2 - 4 (px^2 + py^2). */
    g = h2 + 1 - tr.k * tr.k;
    a = tr.d[0] * tr.d[0] + tr.d[1] * tr.d[1];
    c = tr.p[0] * tr.d[0] + tr.p[1] * tr.d[1];
    q[4] = 1;
    q[3] = 0;
    q[2] = 2 * g - 4 * a;
    q[1] = -8 * c;
    q[0] = g * g - 4 * (tr.p[0] * tr.p[0] + tr.p[1] * tr.p[1]);
    n = torus_roots(q, 4, -reach, reach, s);
    for (int i = 0; i < n; i++) {
        real tt = (real)((tr.s0 + torus_polish(&tr, s[i])) * tr.scale);
        if (tt > tmin && tt < tmax)
            t[found++] = tt;
    }
    return found;
}

int torus_intersect(const Torus *tor, const Ray *ray, real tmin, real tmax, real *t)
{
    real all[4];

    if (torus_hits(tor, ray, tmin, tmax, all) == 0)
        return 0;
    *t = all[0];
    return 1;
}

int torus_crossings(const Torus *tor, const Ray *ray, real tmin, real tmax)
{
    real all[4];

    return torus_hits(tor, ray, tmin, tmax, all);
}

SurfacePoint torus_surface_at(const Torus *tor, Vec3 p)
{
    SurfacePoint sp;
    double q[3], rho, w[2], len, n[3], core[2];
    real g = real_gamma(TORUS_ERROR_ULPS), reach = tor->major + tor->minor;

    torus_local(tor, vec3_sub(p, tor->centre), 1, q);
    rho = hypot(q[0], q[1]);
    /* The core's nearest point, any on the axis itself. */
    core[0] = rho > 0 ? q[0] / rho : 1;
    core[1] = rho > 0 ? q[1] / rho : 0;
    w[0] = rho - tor->major;
    w[1] = q[2];
    len = hypot(w[0], w[1]);
    if (!(len > 0)) {
        w[0] = 1;
        w[1] = 0;
        len = 1;
    }
    n[0] = core[0] * w[0] / len;
    n[1] = core[1] * w[0] / len;
    n[2] = w[1] / len;
    sp.normal = vec3_normalize(vec3_add(vec3_add(vec3_scale(tor->axis_u, n[0]),
                                                 vec3_scale(tor->axis_v, n[1])),
                                        vec3_scale(tor->axis, n[2])));
    sp.shading = sp.normal;
    sp.point = vec3_add(tor->centre,
                        vec3_add(vec3_add(vec3_scale(tor->axis_u, core[0] * tor->major +
                                                                      n[0] * tor->minor),
                                          vec3_scale(tor->axis_v, core[1] * tor->major +
                                                                      n[1] * tor->minor)),
                                 vec3_scale(tor->axis, n[2] * tor->minor)));
    reach *= tor->major / tor->minor;
    sp.error = vec3_scale(vec3_add(vec3_abs(tor->centre), vec3(reach, reach, reach)), g);
    return sp;
}

void torus_uv(const Torus *tor, Vec3 p, Vec3 n, double uv[2])
{
    double q[3];

    (void)n;
    torus_local(tor, vec3_sub(p, tor->centre), 1, q);
    uv[0] = 0.5 + angle_atan2(q[1], q[0]) / (2 * ANGLE_PI);
    uv[1] = 0.5 + angle_atan2(q[2], hypot(q[0], q[1]) - tor->major) / (2 * ANGLE_PI);
}

real torus_bounds(const Torus *tor, real ulps, real lo[3], real hi[3])
{
    const real c[3] = {tor->axis.x, tor->axis.y, tor->axis.z};
    real e[3];

    /* Along each world axis the core reaches R sqrt(1 - n_a^2), the tube
     * r further. */
    for (int a = 0; a < 3; a++) {
        real s = 1 - c[a] * c[a];
        e[a] = tor->major * sqrt(s > 0 ? s : 0) + tor->minor;
    }
    shape_empty(lo, hi);
    shape_grow(lo, hi, vec3_sub(tor->centre, vec3(e[0], e[1], e[2])));
    shape_grow(lo, hi, vec3_add(tor->centre, vec3(e[0], e[1], e[2])));
    /* The roots' placing, as the surface point's error (above). */
    return (tor->major + tor->minor) * (tor->major / tor->minor) * REAL_EPSILON * ulps;
}

void torus_box(const Torus *tor, Vec3 *lo, Vec3 *hi)
{
    shape_widen(lo, hi, tor->centre, tor->major + tor->minor);
}

double torus_extent(const Torus *tor)
{
    return fmax(vec3_max_abs(tor->centre), tor->major + tor->minor);
}

void torus_scale(Torus *tor, int k)
{
    tor->centre = vec3_ldexp(tor->centre, k);
    tor->major = ldexp(tor->major, k);
    tor->minor = ldexp(tor->minor, k);
}

static const char *const torus_names[] = {"centre x", "centre y", "centre z", "axis x",
                                          "axis y",   "axis z",   "major radius",
                                          "tube radius"};
static const ShapeNumber torus_kinds[] = {SHAPE_COORD, SHAPE_COORD, SHAPE_COORD,  SHAPE_COORD,
                                          SHAPE_COORD, SHAPE_COORD, SHAPE_LENGTH, SHAPE_LENGTH};

static const char *torus_record_make(void *shape, const double *v, const Material *m, int *field)
{
    int rc = torus_make(shape, shape_point(v, 0), shape_point(v, 3), v[6], v[7], *m);

    if (rc == 0)
        return NULL;
    *field = rc == -1 ? 3 : 7;
    return rc == -1 ? "the torus's axis is the zero vector: it must give a direction"
                    : "the torus's tube radius must be less than its major radius (a ring "
                      "torus: its hole open), and at least a ten-thousandth of it";
}

static void torus_record_numbers(const void *shape, int k, double *v)
{
    const Torus *tor = shape;

    shape_put(v, 0, tor->centre, k);
    shape_put(v, 3, tor->given, 0);
    v[6] = ldexp(tor->major, -k);
    v[7] = ldexp(tor->minor, -k);
}

const ShapeRecord torus_record = {8, "cx cy cz nx ny nz R r", torus_names, torus_kinds,
                                  torus_record_make, torus_record_numbers};
