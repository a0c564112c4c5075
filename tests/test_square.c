/* test_square.c: squares (geometry/square.h): hits inside their edges, on
 * both sides, and their axes. */
#include <math.h>

#include "geometry/square.h"
#include "solid.h"
#include "test.h"

static void square_hits_inside_its_edges_on_both_sides(void)
{
    Square s;
    Ray front = ray_from(0.9, -0.9, -5, 0, 0, 1), back = ray_from(0.2, 0.3, 7, 0, 0, -1);
    Ray outside = ray_from(1.1, 0, -5, 0, 0, 1), flat = ray_from(-5, 0, 0, 1, 0, 0);
    real t = 0;
    double uv[2];

    CHECK_INT(-1, square_make(&s, vec3(0, 0, 0), vec3(0, 0, 0), 1, solid_plain()));
    CHECK_INT(0, square_make(&s, vec3(0, 0, 0), vec3(0, 0, -3), 1, solid_plain()));
    /* A wall facing -z: u along +x, v along +y, as seen from in front. */
    CHECK(s.axis_u.x == 1 && s.axis_v.y == 1);
    CHECK(square_intersect(&s, &front, 0, INFINITY, &t));
    CHECK_NEAR(5, t, 0);
    CHECK(square_intersect(&s, &back, 0, INFINITY, &t));
    CHECK_NEAR(7, t, 0);
    CHECK(!square_intersect(&s, &outside, 0, INFINITY, &t));
    CHECK(!square_intersect(&s, &flat, 0, INFINITY, &t));
    square_uv(&s, vec3(0.5, -0.25, 0), s.normal, uv); /* in units from the centre */
    CHECK_NEAR(0.5, uv[0], 1e-15);
    CHECK_NEAR(-0.25, uv[1], 1e-15);
    /* A floor: u along +x, v along +z. */
    CHECK_INT(0, square_make(&s, vec3(0, -1, 0), vec3(0, 1, 0), 50, solid_plain()));
    CHECK(s.axis_u.x == 1 && s.axis_v.z == 1);
}

const TestCase square_tests[] = {
    {"square_hits_inside_its_edges_on_both_sides", square_hits_inside_its_edges_on_both_sides},
    {NULL, NULL},
};
