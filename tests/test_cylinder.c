/* test_cylinder.c: infinite cylinders (geometry/cylinder.h): hits at known t,
 * none along the axis, tiny radii far away. */
#include <math.h>

#include "geometry/cylinder.h"
#include "solid.h"
#include "test.h"

static void cylinder_hits_at_known_t_and_not_along_its_axis(void)
{
    Cylinder c = {{0, 3, 0}, 1, solid_plain(), 0};
    Ray across = ray_from(-5, 100, 0, 1, 0, 0), along = ray_from(0.5, -5, 0, 0, 1, 0);
    Ray slanted = ray_from(-5, 0, 0, 1, 1, 0), tangent = ray_from(-5, 0, 1, 1, 0, 0);
    Ray inside = ray_from(0, 7, 0, 0, 0, 3);
    real t = 0;

    CHECK(cylinder_intersect(&c, &across, 0, INFINITY, &t));
    CHECK_NEAR(4, t, 0);
    CHECK_INT(2, cylinder_crossings(&c, &across, 0, INFINITY));
    CHECK(!cylinder_intersect(&c, &along, 0, INFINITY, &t));
    CHECK(cylinder_intersect(&c, &slanted, 0, INFINITY, &t));
    CHECK_NEAR(4, t, 0);
    CHECK(cylinder_intersect(&c, &tangent, 0, INFINITY, &t));
    CHECK_NEAR(5, t, 1e-15);
    CHECK(cylinder_intersect(&c, &inside, 0, INFINITY, &t));
    CHECK_NEAR(1.0 / 3, t, 1e-16);
    CHECK_INT(1, cylinder_crossings(&c, &inside, 0, INFINITY));
    /* Radius 10^-6 at 10^8: the discriminant keeps its digits. */
    c.centre = vec3(1e8, 0, 0);
    c.radius = 1e-6;
    across = ray_from(0, 0, 0.5e-6, 1, 0, 0);
    CHECK(cylinder_intersect(&c, &across, 0, INFINITY, &t));
    CHECK_NEAR(1e8 - sqrt(0.75) * 1e-6, t, 1e-8);
}

const TestCase cylinder_tests[] = {
    {"cylinder_hits_at_known_t_and_not_along_its_axis", cylinder_hits_at_known_t_and_not_along_its_axis},
    {NULL, NULL},
};
