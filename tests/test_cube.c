/* test_cube.c: cubes (geometry/cube.h): hits from outside, inside and along
 * axes, surface points on their face, edges given to the face crossed. */
#include <math.h>

#include "geometry/cube.h"
#include "solid.h"
#include "test.h"

static void cube_hits_from_outside_inside_and_along_axes(void)
{
    Cube c;
    Ray out = ray_from(-5, 0.3, 0.2, 1, 0, 0), in = ray_from(0.2, 0.1, 0, 0, 0, -2);
    Ray parallel = ray_from(0.5, 0.5, -5, 0, 0, 1), beside = ray_from(1.5, 0.5, -5, 0, 0, 1);
    Ray corner = ray_from(-3, -3, -3, 1, 1, 1), edge = ray_from(-5, 1, 1, 1, 0, 0);
    real t = 0;

    cube_make(&c, vec3(0, 0, 0), 1, solid_plain());
    CHECK(cube_intersect(&c, &out, 0, INFINITY, &t));
    CHECK_NEAR(4, t, 0);
    CHECK_INT(2, cube_crossings(&c, &out, 0, INFINITY));
    CHECK_INT(1, cube_crossings(&c, &out, 0, 5));
    CHECK(cube_intersect(&c, &in, 0, INFINITY, &t)); /* from inside, out through -z */
    CHECK_NEAR(0.5, t, 0);
    CHECK_INT(1, cube_crossings(&c, &in, 0, INFINITY));
    CHECK(cube_intersect(&c, &parallel, 0, INFINITY, &t));
    CHECK_NEAR(4, t, 0);
    CHECK(!cube_intersect(&c, &beside, 0, INFINITY, &t)); /* parallel, outside the slab */
    CHECK(cube_intersect(&c, &corner, 0, INFINITY, &t));  /* through two corners */
    CHECK_NEAR(2, t, 0);
    CHECK(cube_intersect(&c, &edge, 0, INFINITY, &t)); /* along an edge: touches it */
    CHECK_NEAR(4, t, 0);
    CHECK(!cube_intersect(&c, &out, 0, 4, &t)); /* the interval is open */
}

static void cube_surface_points_lie_on_their_face(void)
{
    Cube c;
    SurfacePoint sp;
    double uv[2];
    Ray down = ray_from(1e7 + 0.2, 10, 3.1, 0, -1, 0), ahead = ray_from(1e7 - 0.25, 2.25, -5, 0, 0, 1);
    real t = 0;

    cube_make(&c, vec3(1e7, 2, 3), 0.5, solid_plain());
    CHECK(cube_intersect(&c, &down, 0, INFINITY, &t));
    sp = cube_surface(&c, &down, t);
    CHECK(sp.normal.y == 1 && sp.normal.x == 0 && sp.normal.z == 0);
    CHECK(sp.point.y == c.hi.y);
    CHECK(sp.error.x > 0 && sp.error.y > 0 && sp.error.z > 0);
    cube_uv(&c, sp.point, sp.normal, uv);
    CHECK_NEAR(0.7, uv[0], 1e-9); /* top: +x to the right, +z up */
    CHECK_NEAR(0.6, uv[1], 1e-9);
    /* The -z face seen from in front: +x to the right, +y up. */
    CHECK(cube_intersect(&c, &ahead, 0, INFINITY, &t));
    sp = cube_surface(&c, &ahead, t);
    CHECK(sp.normal.z == -1);
    cube_uv(&c, sp.point, sp.normal, uv);
    CHECK_NEAR(0.25, uv[0], 1e-9);
    CHECK_NEAR(0.75, uv[1], 1e-9);
}

static void cube_edges_belong_to_the_face_the_ray_crosses(void)
{
    /* The cube of centre (0, 0, 2) and half-edge 1, from (0, 0, -3): rays
     * that meet its front face (z = 1) exactly on its top edge (y = 1),
     * its right edge (x = 1) and its corner leave the slabs of y and x
     * there and enter z's: the front face's normal, -z, however the
     * point rounds (a ray at 1/4 of the way across rounds nearer the top
     * face than the front). A ray that enters two slabs at once (through
     * an edge from outside both) takes the lower axis's face; a ray lying
     * in a face's plane touches the cube, at the face it then meets. */
    Cube c;
    Ray rays[] = {ray_from(0, 0, -3, 0, 1, 4), ray_from(0, 0, -3, 1, 0, 4),
                  ray_from(0, 0, -3, 1, 1, 4), ray_from(0, 0, -3, 0.25, 1, 4),
                  ray_from(-5, 3, 2, 4, -2, 0), ray_from(0, 1, -3, 0, 0, 1)};
    Vec3 want[] = {vec3(0, 0, -1), vec3(0, 0, -1), vec3(0, 0, -1), vec3(0, 0, -1),
                   vec3(-1, 0, 0), vec3(0, 0, -1)};
    real t = 0;

    cube_make(&c, vec3(0, 0, 2), 1, solid_plain());
    for (size_t i = 0; i < sizeof rays / sizeof rays[0]; i++) {
        SurfacePoint sp;
        if (!cube_intersect(&c, &rays[i], 0, INFINITY, &t)) {
            test_fail(__FILE__, __LINE__, "ray %zu misses the cube", i);
            continue;
        }
        sp = cube_surface(&c, &rays[i], t);
        if (!vec3_equal(sp.normal, want[i]))
            test_fail(__FILE__, __LINE__, "ray %zu: normal (%g, %g, %g), expected (%g, %g, %g)",
                      i, sp.normal.x, sp.normal.y, sp.normal.z, want[i].x, want[i].y, want[i].z);
    }
    /* Leaving from inside through an edge: the slab left first, outward. */
    {
        Ray out = ray_from(0, 0, 2, 0, 1, 1);
        CHECK(cube_intersect(&c, &out, 0, INFINITY, &t));
        CHECK(vec3_equal(cube_surface(&c, &out, t).normal, vec3(0, 1, 0)));
    }
}

const TestCase cube_tests[] = {
    {"cube_hits_from_outside_inside_and_along_axes", cube_hits_from_outside_inside_and_along_axes},
    {"cube_surface_points_lie_on_their_face", cube_surface_points_lie_on_their_face},
    {"cube_edges_belong_to_the_face_the_ray_crosses", cube_edges_belong_to_the_face_the_ray_crosses},
    {NULL, NULL},
};
