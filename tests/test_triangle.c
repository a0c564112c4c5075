/* test_triangle.c: triangles (geometry/triangle.h): hits, barycentric
 * coordinates, edges and vertices, shared edges without cracks. */
#include <math.h>

#include "geometry/triangle.h"
#include "rng.h"
#include "test.h"

static Triangle triangle_of(Vec3 a, Vec3 b, Vec3 c)
{
    Triangle t;
    CHECK_INT(0, triangle_make(&t, a, b, c));
    return t;
}

/* The OCaml course project's Moller-Trumbore, written as it gives it: vectors from v0,
 * so two triangles sharing an edge round it differently. For comparison. */
static int naive_hit(const Triangle *tri, const Ray *r)
{
    Vec3 e1 = vec3_sub(tri->v[1], tri->v[0]), e2 = vec3_sub(tri->v[2], tri->v[0]);
    Vec3 p = vec3_cross(r->dir, e2), o = vec3_sub(r->origin, tri->v[0]), q;
    double m = vec3_dot(p, e1), u, v;

    if (m == 0)
        return 0;
    u = vec3_dot(o, p) / m;
    if (u < 0 || u > 1)
        return 0;
    q = vec3_cross(o, e1);
    v = vec3_dot(r->dir, q) / m;
    if (v < 0 || u + v > 1)
        return 0;
    return vec3_dot(e2, q) / m > 0;
}

static void triangle_hit_gives_point_and_barycentric_uv(void)
{
    Triangle tri = triangle_of(vec3(0, 0, 5), vec3(1, 0, 5), vec3(0, 1, 5));
    Ray r = {{0, 0, 0}, {0.25, 0.5, 5}};
    double t = 0, uv[2];
    SurfacePoint sp;

    CHECK(triangle_intersect(&tri, &r, 0, INFINITY, &t));
    CHECK_NEAR(1, t, 1e-15);
    sp = triangle_surface_at(&tri, NULL, &r, uv, NULL);
    CHECK_NEAR(0.25, sp.point.x, 1e-15);
    CHECK_NEAR(0.5, sp.point.y, 1e-15);
    CHECK_NEAR(5, sp.point.z, 0);
    CHECK_NEAR(1, sp.normal.z, 0);
    CHECK_NEAR(0.25, uv[0], 1e-15);
    CHECK_NEAR(0.5, uv[1], 1e-15);
    r.dir = vec3(-0.25, 0.5, 5); /* outside, beyond the edge x = 0 */
    CHECK(!triangle_intersect(&tri, &r, 0, INFINITY, &t));
    r.origin = vec3(0.25, 0.25, 9); /* from the back: two-sided */
    r.dir = vec3(0, 0, -1);
    CHECK(triangle_intersect(&tri, &r, 0, INFINITY, &t));
    CHECK_NEAR(4, t, 0);
    r.dir = vec3(1, 0, 0); /* in a plane parallel to the triangle */
    CHECK(!triangle_intersect(&tri, &r, 0, INFINITY, &t));
}

static void triangle_edges_and_vertices_count_as_hits(void)
{
    Triangle tri = triangle_of(vec3(0, 0, 5), vec3(1, 0, 5), vec3(0, 1, 5));
    Ray edge = {{0.5, 0.5, 0}, {0, 0, 1}}, corner = {{1, 0, 0}, {0, 0, 1}};
    Ray side = {{0.25, 0, 0}, {0, 0, 1}}, out = {{0.5, nextafter(0.5, 1), 0}, {0, 0, 1}};
    double t;

    CHECK(triangle_intersect(&tri, &edge, 0, INFINITY, &t)); /* on the hypotenuse */
    CHECK(triangle_intersect(&tri, &corner, 0, INFINITY, &t));
    CHECK(triangle_intersect(&tri, &side, 0, INFINITY, &t));
    CHECK(!triangle_intersect(&tri, &out, 0, INFINITY, &t)); /* one ulp outside */
}

static void triangle_make_rejects_only_zero_area(void)
{
    Triangle tri;
    double s = 1e-200;

    CHECK_INT(-1, triangle_make(&tri, vec3(0, 0, 0), vec3(1, 1, 1), vec3(2, 2, 2)));
    CHECK_INT(-1, triangle_make(&tri, vec3(1, 2, 3), vec3(1, 2, 3), vec3(0, 0, 0)));
    CHECK_INT(0, triangle_make(&tri, vec3(0, 0, 0), vec3(s, 0, 0), vec3(0, s, 0)));
    CHECK_NEAR(1, tri.normal.z, 0);
    CHECK_INT(0, triangle_make(&tri, vec3(0, 0, 0), vec3(1, 0, 0), vec3(2, 1e-9, 0)));
}

static void triangle_shared_edges_have_no_cracks(void)
{
    /* Pairs of triangles sharing an edge b-c, wound alike or not, at scales
     * 1e-3 to 1e6; rays from random places aimed at points of the edge. Our
     * test must hit at least one triangle every time; the naive form misses
     * both now and then, which shows the test can tell. */
    int rays = 0, cracks = 0, naive_cracks = 0;

    for (int i = 0; i < 3000; i++) {
        double s = rng_log_scale(-3, 6);
        Vec3 base = vec3_scale(rng_unit_vector(), s * rng_log_scale(0, 3));
        Vec3 a = vec3_add(base, vec3_scale(rng_unit_vector(), s));
        Vec3 b = vec3_add(base, vec3_scale(rng_unit_vector(), s));
        Vec3 c = vec3_add(base, vec3_scale(rng_unit_vector(), s));
        Vec3 d = vec3_add(base, vec3_scale(rng_unit_vector(), s));
        Triangle t1, t2;

        if (triangle_make(&t1, a, b, c) != 0 ||
            triangle_make(&t2, b, i % 2 ? d : c, i % 2 ? c : d) != 0)
            continue;
        for (int j = 0; j < 30; j++) {
            Vec3 p = vec3_add(b, vec3_scale(vec3_sub(c, b), rng_uniform()));
            Ray r;
            double t;

            r.origin = vec3_add(p, vec3_scale(rng_unit_vector(), s * rng_log_scale(0, 2)));
            r.dir = vec3_sub(p, r.origin);
            /* Only rays that cross the surface the pair forms count: seen
             * along the ray, a and d lie on opposite sides of the edge (on
             * a silhouette, both triangles are on one side and a ray just
             * past the edge rightly misses both). Rays nearly in either
             * plane are skipped too. */
            if (vec3_dot(r.dir, vec3_cross(vec3_sub(c, b), vec3_sub(a, b))) *
                        vec3_dot(r.dir, vec3_cross(vec3_sub(c, b), vec3_sub(d, b))) >=
                    0 ||
                fabs(vec3_dot(vec3_normalize(r.dir), t1.normal)) < 1e-3 ||
                fabs(vec3_dot(vec3_normalize(r.dir), t2.normal)) < 1e-3)
                continue;
            rays++;
            if (!triangle_intersect(&t1, &r, 0, INFINITY, &t) &&
                !triangle_intersect(&t2, &r, 0, INFINITY, &t))
                cracks++;
            if (!naive_hit(&t1, &r) && !naive_hit(&t2, &r))
                naive_cracks++;
        }
    }
    CHECK(rays > 20000);
    CHECK_INT(0, cracks);
    CHECK(naive_cracks > 0);
}

const TestCase triangle_tests[] = {
    {"triangle_hit_gives_point_and_barycentric_uv", triangle_hit_gives_point_and_barycentric_uv},
    {"triangle_edges_and_vertices_count_as_hits", triangle_edges_and_vertices_count_as_hits},
    {"triangle_make_rejects_only_zero_area", triangle_make_rejects_only_zero_area},
    {"triangle_shared_edges_have_no_cracks", triangle_shared_edges_have_no_cracks},
    {NULL, NULL},
};
