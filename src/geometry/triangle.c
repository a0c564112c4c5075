/* triangle.c: ray/triangle intersection and surface geometry (see triangle.h). */
#include "geometry/triangle.h"

#include <float.h>
#include <math.h>

/*
 * Error bound of triangle_surface_at()'s point, as a multiple of u =
 * REAL_EPSILON / 2 of the largest vertex magnitude per component. The point is
 * a barycentric blend b0 v0 + b1 v1 + b2 v2 (pbrt-v4 bounds it by 7u of
 * sum |b_i v_i|); bounding by the vertices' magnitude with 16u also covers the
 * rounding of the next ray's triple products, which are computed from
 * vertex - origin (tests/test_ray.c checks it at scales 1e-6 to 1e8).
 */
#define TRIANGLE_ERROR_ULPS 16.0

/* Says whether vertex a comes before vertex b in the fixed vertex order:
 * lexicographic on (x, y, z). */
static int triangle_vertex_before(Vec3 a, Vec3 b)
{
    if (a.x != b.x)
        return a.x < b.x;
    if (a.y != b.y)
        return a.y < b.y;
    return a.z < b.z;
}

int triangle_make(Triangle *tri, Vec3 v0, Vec3 v1, Vec3 v2)
{
    Vec3 e1 = vec3_sub(v1, v0), e2 = vec3_sub(v2, v0);
    real scale = fmax(vec3_max_abs(e1), vec3_max_abs(e2));
    Vec3 n;

    /* The normal of scaled edges: a tiny triangle's cross product would
     * underflow. */
    if (scale > 0 && scale <= REAL_MAX) {
        int k = vec3_unit_exponent(scale);
        n = vec3_cross(vec3_ldexp(e1, k), vec3_ldexp(e2, k));
    } else {
        n = vec3(0, 0, 0);
    }
    if (!(vec3_length(n) > 0))
        return -1;
    tri->v[0] = v0;
    tri->v[1] = v1;
    tri->v[2] = v2;
    tri->normal = vec3_normalize(n);
    /* Edge k joins the two vertices other than k, from k+1 to k+2. */
    tri->swapped = 0;
    for (unsigned k = 0; k < 3; k++)
        if (triangle_vertex_before(tri->v[(k + 2) % 3], tri->v[(k + 1) % 3]))
            tri->swapped |= 1u << k;
    tri->shading = TRIANGLE_PLAIN;
    tri->material = 0;
    tri->order = 0;
    return 0;
}

TriangleShading triangle_plain_shading(const Triangle *tri)
{
    TriangleShading sh = {{{0, 0}, {1, 0}, {0, 1}}, {tri->normal, tri->normal, tri->normal}, 0, 0,
                          {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}};

    return sh;
}

/* Returns d . (p x q), the weight of the vertex opposite an edge whose
 * vertices lie at p and q from the ray origin; computed as -(d . (q x p))
 * when the edge is swapped, so that every triangle gets the same bits. */
static real triangle_edge(Vec3 d, Vec3 p, Vec3 q, int swapped)
{
    return swapped ? -vec3_dot(d, vec3_cross(q, p)) : vec3_dot(d, vec3_cross(p, q));
}

/* Computes the three barycentric weights (not yet divided by their sum) of
 * the ray's line in w, and the vertices relative to the origin in rel;
 * returns their sum, or 0 when the line misses the triangle or runs in its
 * plane. */
static real triangle_weights(const Triangle *tri, const Ray *ray, real w[3], Vec3 rel[3])
{
    real det;

    for (int k = 0; k < 3; k++)
        rel[k] = vec3_sub(tri->v[k], ray->origin);
    for (int k = 0; k < 3; k++)
        w[k] = triangle_edge(ray->dir, rel[(k + 1) % 3], rel[(k + 2) % 3],
                             (int)(tri->swapped >> k & 1));
    if ((w[0] < 0 || w[1] < 0 || w[2] < 0) && (w[0] > 0 || w[1] > 0 || w[2] > 0))
        return 0;
    det = w[0] + w[1] + w[2];
    return det;
}

int triangle_intersect(const Triangle *tri, const Ray *ray, real tmin, real tmax, real *t)
{
    real w[3], det, den, tt;
    Vec3 rel[3];

    det = triangle_weights(tri, ray, w, rel);
    if (det == 0 || isnan(det))
        return 0;
    /* t from the triangle's plane, through v0: a barycentric blend of the
     * vertices would round with the triangle's size over the cosine of the
     * ray's angle to the normal, and a ray leaving the surface could see
     * itself cross it again. */
    den = vec3_dot(tri->normal, ray->dir);
    if (den == 0)
        return 0;
    tt = vec3_dot(tri->normal, rel[0]) / den;
    if (!(tt > tmin && tt < tmax))
        return 0;
    *t = tt;
    return 1;
}

SurfacePoint triangle_surface_at(const Triangle *tri, const TriangleShading *sh, const Ray *ray,
                                 double uv[2], Colour *rgb)
{
    TriangleShading plain;
    SurfacePoint sp;
    real w[3], b[3], det, u = REAL_EPSILON / 2;
    real g = TRIANGLE_ERROR_ULPS * u / (1 - TRIANGLE_ERROR_ULPS * u);
    Vec3 rel[3], m;

    det = triangle_weights(tri, ray, w, rel);
    for (int k = 0; k < 3; k++)
        b[k] = det != 0 ? w[k] / det : 1.0 / 3;
    sp.point = vec3_add(vec3_add(vec3_scale(tri->v[0], b[0]), vec3_scale(tri->v[1], b[1])),
                        vec3_scale(tri->v[2], b[2]));
    sp.normal = tri->normal;
    sp.shading = tri->normal;
    if (!sh) {
        plain = triangle_plain_shading(tri);
        sh = &plain;
    }
    if (sh->smooth) {
        Vec3 ns = vec3_add(vec3_add(vec3_scale(sh->vn[0], b[0]), vec3_scale(sh->vn[1], b[1])),
                           vec3_scale(sh->vn[2], b[2]));
        if (vec3_length(ns) > 0)
            sp.shading = vec3_normalize(ns);
    }
    m = vec3_abs(tri->v[0]);
    for (int k = 1; k < 3; k++) {
        Vec3 a = vec3_abs(tri->v[k]);
        m = vec3(fmax(m.x, a.x), fmax(m.y, a.y), fmax(m.z, a.z));
    }
    sp.error = vec3_scale(m, g);
    uv[0] = b[0] * sh->uv[0][0] + b[1] * sh->uv[1][0] + b[2] * sh->uv[2][0];
    uv[1] = b[0] * sh->uv[0][1] + b[1] * sh->uv[1][1] + b[2] * sh->uv[2][1];
    if (rgb && sh->coloured)
        *rgb = colour(b[0] * sh->rgb[0][0] + b[1] * sh->rgb[1][0] + b[2] * sh->rgb[2][0],
                      b[0] * sh->rgb[0][1] + b[1] * sh->rgb[1][1] + b[2] * sh->rgb[2][1],
                      b[0] * sh->rgb[0][2] + b[1] * sh->rgb[1][2] + b[2] * sh->rgb[2][2]);
    return sp;
}

real triangle_bounds(const Triangle *tri, real ulps, real lo[3], real hi[3])
{
    (void)ulps;
    shape_empty(lo, hi);
    for (int k = 0; k < 3; k++)
        shape_grow(lo, hi, tri->v[k]);
    return 0;
}

void triangle_box(const Triangle *tri, Vec3 *lo, Vec3 *hi)
{
    for (int k = 0; k < 3; k++)
        shape_widen(lo, hi, tri->v[k], 0);
}

double triangle_extent(const Triangle *tri)
{
    double m = 0;

    for (int k = 0; k < 3; k++)
        m = fmax(m, vec3_max_abs(tri->v[k]));
    return m;
}

void triangle_scale(Triangle *tri, int k)
{
    for (int j = 0; j < 3; j++)
        tri->v[j] = vec3_ldexp(tri->v[j], k);
}

static const char *const triangle_names[] = {"x0", "y0", "z0", "x1", "y1",
                                             "z1", "x2", "y2", "z2"};
static const ShapeNumber triangle_kinds[] = {SHAPE_COORD, SHAPE_COORD, SHAPE_COORD,
                                             SHAPE_COORD, SHAPE_COORD, SHAPE_COORD,
                                             SHAPE_COORD, SHAPE_COORD, SHAPE_COORD};

/* ShapeRecord.make: the material goes with the triangle into the scene. */
static const char *triangle_record_make(void *shape, const double *v, const Material *m,
                                        int *field)
{
    (void)m;
    if (triangle_make(shape, shape_point(v, 0), shape_point(v, 3), shape_point(v, 6)) == 0)
        return NULL;
    *field = -1; /* the record itself */
    return "the triangle's three vertices lie on one line: it has no area";
}

static void triangle_record_numbers(const void *shape, int k, double *v)
{
    const Triangle *tri = shape;

    for (int j = 0; j < 3; j++)
        shape_put(v, 3 * j, tri->v[j], k);
}

const ShapeRecord triangle_record = {9, "x0 y0 z0 x1 y1 z1 x2 y2 z2", triangle_names,
                                     triangle_kinds, triangle_record_make,
                                     triangle_record_numbers};
