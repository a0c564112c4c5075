/* test_plane.c: planes (geometry/plane.h): hits from both sides, the normal, texture axes. */
#include <math.h>

#include "geometry/plane.h"
#include "test.h"

static const Material white = {{255, 255, 255}, 0, 0, 1, -1, TEXTURE_NEAREST, -1, 0};

static void plane_hits_both_sides_and_misses_parallel(void)
{
    Plane pl;
    Ray down = {{1, 5, 2}, {0, -1, 0}}, up = {{1, -3, 2}, {0, 0.5, 0}}, flat = {{0, 1, 0}, {1, 0, 0}};
    double t = 0;

    CHECK_INT(0, plane_make(&pl, vec3(0, 0, 0), vec3(0, 2, 0), 1, white));
    CHECK_NEAR(1, vec3_length(pl.normal), 1e-15);
    CHECK(plane_intersect(&pl, &down, 0, INFINITY, &t));
    CHECK_NEAR(5, t, 0);
    CHECK(plane_intersect(&pl, &up, 0, INFINITY, &t)); /* the back side too */
    CHECK_NEAR(6, t, 0);
    CHECK(!plane_intersect(&pl, &up, 0, 6, &t)); /* open interval */
    CHECK(!plane_intersect(&pl, &flat, 0, INFINITY, &t));
    down.dir.y = 1; /* pointing away */
    CHECK(!plane_intersect(&pl, &down, 0, INFINITY, &t));
}

static void plane_make_rejects_only_the_zero_normal(void)
{
    Plane pl;

    CHECK_INT(-1, plane_make(&pl, vec3(1, 2, 3), vec3(0, 0, 0), 1, white));
    CHECK_INT(-1, plane_make(&pl, vec3(1, 2, 3), vec3(-0.0, 0, -0.0), 1, white));
    /* The least and the largest lengths still give a unit normal. */
    CHECK_INT(0, plane_make(&pl, vec3(0, 0, 0), vec3(0, -0x1p-1074, 0), 1, white));
    CHECK_NEAR(-1, pl.normal.y, 0);
    CHECK_INT(0, plane_make(&pl, vec3(0, 0, 0), vec3(1e308, 1e308, 0), 1, white));
    CHECK_NEAR(1, vec3_dot(pl.normal, pl.normal), 1e-15);
}

static void plane_texture_axes_are_orthonormal(void)
{
    Plane pl;
    double uv[2];

    CHECK_INT(0, plane_make(&pl, vec3(1, 2, 3), vec3(1, -2, 0.5), 2, white));
    CHECK_NEAR(0, vec3_dot(pl.normal, pl.axis_u), 1e-15);
    CHECK_NEAR(0, vec3_dot(pl.normal, pl.axis_v), 1e-15);
    CHECK_NEAR(0, vec3_dot(pl.axis_u, pl.axis_v), 1e-15);
    CHECK_NEAR(1, vec3_length(pl.axis_u), 1e-15);
    plane_uv(&pl, vec3_add(pl.point, vec3_add(vec3_scale(pl.axis_u, 3), pl.axis_v)), pl.normal, uv);
    CHECK_NEAR(1.5, uv[0], 1e-15);
    CHECK_NEAR(0.5, uv[1], 1e-15);
}

const TestCase plane_tests[] = {
    {"plane_hits_both_sides_and_misses_parallel", plane_hits_both_sides_and_misses_parallel},
    {"plane_make_rejects_only_the_zero_normal", plane_make_rejects_only_the_zero_normal},
    {"plane_texture_axes_are_orthonormal", plane_texture_axes_are_orthonormal},
    {NULL, NULL},
};
