/* test_cone.c: cones (geometry/cone.h): one nappe, hits at known t, normals
 * and texture coordinates, upside down. */
#include <math.h>

#include "geometry/cone.h"
#include "solid.h"
#include "test.h"

static void cone_hits_its_nappe_only(void)
{
    Cone c;
    Ray across = ray_from(-5, 0.5, 0, 1, 0, 0), above = ray_from(-5, 2, 0, 1, 0, 0);
    Ray below = ray_from(-5, -3, 0, 1, 0, 0), down = ray_from(0.25, 5, 0, 0, -1, 0);
    Ray generator = ray_from(-3, -2.5, 0, 1, 1, 0); /* parallel to a generator */
    real t = 0;
    double uv[2];
    SurfacePoint sp;

    cone_make(&c, vec3(0, 0, 0), 1, 1, solid_plain()); /* apex at y = 1, widening downwards */
    CHECK(cone_intersect(&c, &across, 0, INFINITY, &t));
    CHECK_NEAR(4.5, t, 1e-15); /* radius 0.5 at y = 0.5 */
    CHECK_INT(2, cone_crossings(&c, &across, 0, INFINITY));
    CHECK(!cone_intersect(&c, &above, 0, INFINITY, &t)); /* the other nappe is not there */
    CHECK(cone_intersect(&c, &below, 0, INFINITY, &t)); /* infinite: radius 4 at y = -3 */
    CHECK_NEAR(1, t, 1e-15);
    CHECK(cone_intersect(&c, &down, 0, INFINITY, &t)); /* enters at y = 0.75 */
    CHECK_NEAR(4.25, t, 1e-15);
    CHECK_INT(1, cone_crossings(&c, &down, 0, INFINITY));
    CHECK(cone_intersect(&c, &generator, 0, INFINITY, &t)); /* one root: a = 0 */
    CHECK_NEAR(3.25, t, 1e-15);
    CHECK_INT(1, cone_crossings(&c, &generator, 0, INFINITY));
    sp = cone_surface_at(&c, vec3(0.5, 0.5, 0));
    CHECK_NEAR(sqrt(0.5), sp.normal.x, 1e-15); /* out and up, at 45 degrees */
    CHECK_NEAR(sqrt(0.5), sp.normal.y, 1e-15);
    cone_uv(&c, vec3(0, 0.25, -0.75), vec3(0, 0, -1), uv);
    CHECK_NEAR(0.5, uv[0], 1e-15);
    CHECK_NEAR(0.25, uv[1], 1e-15);
    /* Upside down: apex below, opening upwards. */
    cone_make(&c, vec3(0, 0, 0), 1, -1, solid_plain());
    above = ray_from(-5, 0.5, 0, 1, 0, 0);
    CHECK(cone_intersect(&c, &above, 0, INFINITY, &t));
    CHECK_NEAR(3.5, t, 1e-15); /* radius 1.5 at y = 0.5 */
}

const TestCase cone_tests[] = {
    {"cone_hits_its_nappe_only", cone_hits_its_nappe_only},
    {NULL, NULL},
};
