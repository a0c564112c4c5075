/* test_polygon.c: polygons cut into triangles (geometry/polygon.h): stars,
 * combs, spirals and rings (a hole joined to the outside by an edge gone
 * along twice), in every orientation and both windings, cover what they
 * cover (their areas by the shoelace formula, and points sampled in and
 * out), each triangle turning the face's way; convex faces keep the fan;
 * faces that are not simple are cut without a fault. */
#include <math.h>
#include <stdlib.h>

#include "geometry/polygon.h"
#include "rng.h"
#include "test.h"

enum { POLY_MAX = 400 };
#define POLY_PI 3.14159265358979323846

/* A polygon in its own plane (x, y), and as placed in space. */
typedef struct {
    double x[POLY_MAX], y[POLY_MAX];
    size_t n;
} Poly;

static void poly_add(Poly *g, double x, double y)
{
    g->x[g->n] = x;
    g->y[g->n] = y;
    g->n++;
}

/* A star of k points, radii 1 and inner. */
static Poly poly_star(int k, double inner)
{
    Poly g = {{0}, {0}, 0};

    for (int i = 0; i < 2 * k; i++) {
        double a = POLY_PI * i / k, r = i % 2 ? inner : 1;
        poly_add(&g, r * cos(a), r * sin(a));
    }
    return g;
}

/* A comb of k teeth, each 0.6 wide and 3 long, on a spine 1 high. */
static Poly poly_comb(int k)
{
    Poly g = {{0}, {0}, 0};

    poly_add(&g, 0, 0);
    poly_add(&g, k, 0);
    for (int i = k; i > 0; i--) {
        poly_add(&g, i, 4);
        poly_add(&g, i - 0.6, 4);
        poly_add(&g, i - 0.6, 1);
        if (i > 1)
            poly_add(&g, i - 1, 1);
    }
    poly_add(&g, 0, 1);
    return g;
}

/* A spiral strip of `turns` turns and m steps a turn: out along its outer
 * edge, back along its inner one. */
static Poly poly_spiral(double turns, int m)
{
    Poly g = {{0}, {0}, 0};
    int steps = (int)(turns * m);

    for (int i = 0; i <= steps; i++) {
        double a = 2 * POLY_PI * i / m, r = 1 + a / (2 * POLY_PI);
        poly_add(&g, (r + 0.35) * cos(a), (r + 0.35) * sin(a));
    }
    for (int i = steps; i >= 0; i--) {
        double a = 2 * POLY_PI * i / m, r = 1 + a / (2 * POLY_PI);
        poly_add(&g, r * cos(a), r * sin(a));
    }
    return g;
}

/* A ring: the outer circle (radius 1, m corners) anticlockwise, an edge
 * in to the inner one (radius inner), the inner circle clockwise, and the
 * same edge back: as modelling tools write a face with a hole. */
static Poly poly_ring(int m, double inner)
{
    Poly g = {{0}, {0}, 0};

    for (int i = 0; i <= m; i++)
        poly_add(&g, cos(2 * POLY_PI * i / m), sin(2 * POLY_PI * i / m));
    for (int i = 0; i <= m; i++)
        poly_add(&g, inner * cos(-2 * POLY_PI * i / m), inner * sin(-2 * POLY_PI * i / m));
    return g;
}

/* Returns the polygon's signed area (shoelace). */
static double poly_area(const Poly *g)
{
    double a = 0;

    for (size_t i = 0; i < g->n; i++) {
        size_t j = (i + 1) % g->n;
        a += g->x[i] * g->y[j] - g->x[j] * g->y[i];
    }
    return a / 2;
}

/* Says whether (px, py) is inside g (even-odd rule). */
static int poly_inside(const Poly *g, double px, double py)
{
    int in = 0;

    for (size_t i = 0, j = g->n - 1; i < g->n; j = i++)
        if ((g->y[i] > py) != (g->y[j] > py) &&
            px < (g->x[j] - g->x[i]) * (py - g->y[i]) / (g->y[j] - g->y[i]) + g->x[i])
            in = !in;
    return in;
}

/* Returns the signed area of triangle a b c of g. */
static double poly_tri_area(const Poly *g, const unsigned t[3])
{
    return ((g->x[t[1]] - g->x[t[0]]) * (g->y[t[2]] - g->y[t[0]]) -
            (g->y[t[1]] - g->y[t[0]]) * (g->x[t[2]] - g->x[t[0]])) / 2;
}

/* Says whether (px, py) is inside triangle t of g (or on it). */
static int poly_in_tri(const Poly *g, const unsigned t[3], double px, double py)
{
    double s = poly_tri_area(g, t) < 0 ? -1 : 1;

    for (int k = 0; k < 3; k++) {
        unsigned a = t[k], b = t[(k + 1) % 3];
        double c = (g->x[b] - g->x[a]) * (py - g->y[a]) - (g->y[b] - g->y[a]) * (px - g->x[a]);
        if (s * c < 0)
            return 0;
    }
    return 1;
}

/* Places g in space: rotated about a random axis, moved, and the other
 * way round when reverse; cuts it and checks that the triangles cover g
 * exactly, each turning g's way. Returns the cut. */
static PolygonCut poly_check(Poly g, int reverse, const char *what)
{
    static Vec3 p[POLY_MAX];
    static unsigned tri[POLY_MAX][3];
    static char work[POLY_MAX * 64];
    Vec3 axis = rng_unit_vector(), u, v, o = vec3(rng_range(-50, 50), 3, rng_range(-1e3, 1e3));
    double area = 0, want, turn;
    int miss = 0;
    PolygonCut cut;

    if (reverse)
        for (size_t i = 0; i < g.n / 2; i++) {
            double x = g.x[i], y = g.y[i];
            g.x[i] = g.x[g.n - 1 - i], g.y[i] = g.y[g.n - 1 - i];
            g.x[g.n - 1 - i] = x, g.y[g.n - 1 - i] = y;
        }
    want = poly_area(&g);
    turn = want < 0 ? -1 : 1;
    u = vec3_normalize(vec3_cross(axis, fabs(axis.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0)));
    v = vec3_cross(axis, u);
    for (size_t i = 0; i < g.n; i++)
        p[i] = vec3_add(o, vec3_add(vec3_scale(u, g.x[i]), vec3_scale(v, g.y[i])));
    CHECK(polygon_work_size(g.n) <= sizeof work);
    cut = polygon_cut(p, g.n, tri, work);
    for (size_t t = 0; t + 2 < g.n; t++) {
        double a = poly_tri_area(&g, tri[t]);
        for (int k = 0; k < 3; k++)
            CHECK(tri[t][k] < g.n);
        /* Each triangle turns as the face (or has no area). */
        if (turn * a < -1e-12)
            test_fail(__FILE__, __LINE__, "%s: triangle %zu turns the other way (%g)", what, t,
                      a);
        area += a;
    }
    CHECK_NEAR(want, area, 1e-9 * fabs(want) + 1e-12);
    /* Points of the face's box: inside the face when inside a triangle. */
    for (int s = 0; s < 2000; s++) {
        double px = rng_range(-6, 6), py = rng_range(-6, 6);
        int in = 0;
        for (size_t t = 0; t + 2 < g.n && !in; t++)
            in = poly_in_tri(&g, tri[t], px, py);
        miss += in != poly_inside(&g, px, py);
    }
    if (miss > 0)
        test_fail(__FILE__, __LINE__, "%s: %d points of 2000 covered wrongly", what, miss);
    return cut;
}

static void polygon_concave_faces_cover_what_they_cover(void)
{
    for (int r = 0; r < 2; r++)
        for (int trial = 0; trial < 6; trial++) {
            CHECK_INT(POLYGON_EARS, poly_check(poly_star(5 + trial, 0.3 + 0.05 * trial), r, "star"));
            CHECK_INT(POLYGON_EARS, poly_check(poly_comb(3 + 4 * trial), r, "comb"));
            CHECK_INT(POLYGON_EARS, poly_check(poly_spiral(1.5 + trial, 24), r, "spiral"));
        }
}

static void polygon_rings_keep_their_hole(void)
{
    for (int r = 0; r < 2; r++)
        for (int m = 3; m < 40; m += 6) {
            CHECK_INT(POLYGON_EARS, poly_check(poly_ring(m, 0.5), r, "ring"));
            CHECK_INT(POLYGON_EARS, poly_check(poly_ring(m, 0.95), r, "thin ring"));
        }
}

/* Convex faces are fanned from their first corner, as they always were;
 * corners on a straight edge or repeated leave them convex. */
static void polygon_convex_faces_keep_the_fan(void)
{
    for (int k = 3; k < 60; k += 7) {
        Poly g = poly_star(k, cos(POLY_PI / k)); /* inner corners on the edges */
        static Vec3 p[POLY_MAX];
        unsigned tri[POLY_MAX][3];
        static char work[POLY_MAX * 64];

        poly_check(g, 0, "convex");
        for (size_t i = 0; i < g.n; i++)
            p[i] = vec3(g.x[i], g.y[i], 1);
        CHECK_INT(POLYGON_FAN, polygon_cut(p, g.n, tri, work));
        for (size_t t = 0; t + 2 < g.n; t++)
            CHECK(tri[t][0] == 0 && tri[t][1] == t + 1 && tri[t][2] == t + 2);
    }
    {
        Vec3 q[5] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        unsigned tri[3][3];
        CHECK_INT(POLYGON_FAN, polygon_cut(q, 5, tri, NULL));
    }
}

/* A concave quadrilateral is cut through its reflex corner, whichever it
 * is. */
static void polygon_concave_quads_cut_through_the_notch(void)
{
    static const double x[4] = {0, 2, 0, 0.7}, y[4] = {0, 1, 2, 1};

    for (int k = 0; k < 4; k++) {
        Poly g = {{0}, {0}, 0};
        for (int i = 0; i < 4; i++)
            poly_add(&g, x[(i + k) % 4], y[(i + k) % 4]);
        CHECK_INT(POLYGON_EARS, poly_check(g, k % 2, "dart"));
    }
}

/* Faces that are not simple: cut into n - 2 triangles of their corners,
 * said to be irregular, never a fault. */
static void polygon_faces_not_simple_are_cut_all_the_same(void)
{
    static const Vec3 line[5] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {4, 4, 4}};
    static const Vec3 bowtie[4] = {{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}};
    static const Vec3 twice[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                  {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    static char work[POLY_MAX * 64];
    unsigned tri[POLY_MAX][3];
    Poly pent = poly_star(5, 0.3);
    Vec3 p[POLY_MAX];

    CHECK_INT(POLYGON_IRREGULAR, polygon_cut(line, 5, tri, work));
    CHECK_INT(POLYGON_IRREGULAR, polygon_cut(bowtie, 4, tri, work));
    CHECK_INT(POLYGON_IRREGULAR, polygon_cut(twice, 8, tri, work));
    /* A pentagram: the five points, each joined to the second next. */
    for (int i = 0; i < 5; i++)
        p[i] = vec3(pent.x[(4 * i) % 10], pent.y[(4 * i) % 10], 0);
    CHECK_INT(POLYGON_IRREGULAR, polygon_cut(p, 5, tri, work));
    for (int t = 0; t < 3; t++)
        for (int k = 0; k < 3; k++)
            CHECK(tri[t][k] < 5);
    /* Random corners: never a fault, always indices of the face. */
    for (int trial = 0; trial < 200; trial++) {
        size_t n = 3 + (size_t)(rng_uniform() * 60);
        for (size_t i = 0; i < n; i++)
            p[i] = vec3(rng_range(-1, 1), rng_range(-1, 1), rng_range(-0.01, 0.01) * (trial % 3));
        polygon_cut(p, n, tri, work);
        for (size_t t = 0; t + 2 < n; t++)
            for (int k = 0; k < 3; k++)
                CHECK(tri[t][k] < n);
    }
}

const TestCase polygon_tests[] = {
    {"polygon_concave_faces_cover_what_they_cover", polygon_concave_faces_cover_what_they_cover},
    {"polygon_rings_keep_their_hole", polygon_rings_keep_their_hole},
    {"polygon_convex_faces_keep_the_fan", polygon_convex_faces_keep_the_fan},
    {"polygon_concave_quads_cut_through_the_notch", polygon_concave_quads_cut_through_the_notch},
    {"polygon_faces_not_simple_are_cut_all_the_same",
     polygon_faces_not_simple_are_cut_all_the_same},
    {NULL, NULL},
};
