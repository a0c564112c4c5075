/* test_disk.c: disks (geometry/disk.h): hits within their radius on both
 * sides, far from the origin, their texture coordinates and box. */
#include <math.h>

#include "geometry/disk.h"
#include "solid.h"
#include "test.h"

static void disk_hits_within_its_radius_on_both_sides(void)
{
    Disk d;
    Ray front = ray_from(0.7, 0.7, -5, 0, 0, 1), back = ray_from(0.2, -0.3, 7, 0, 0, -2);
    Ray corner = ray_from(0.75, 0.75, -5, 0, 0, 1), flat = ray_from(-5, 0, 0, 1, 0, 0);
    real t = 0;
    double uv[2];

    CHECK_INT(-1, disk_make(&d, vec3(0, 0, 0), vec3(0, 0, 0), 1, solid_plain()));
    CHECK_INT(0, disk_make(&d, vec3(0, 0, 0), vec3(0, 0, -3), 1, solid_plain()));
    CHECK(disk_intersect(&d, &front, 0, INFINITY, &t)); /* 0.99 from the centre */
    CHECK_NEAR(5, t, 0);
    CHECK(disk_intersect(&d, &back, 0, INFINITY, &t));
    CHECK_NEAR(3.5, t, 0);
    CHECK(!disk_intersect(&d, &corner, 0, INFINITY, &t)); /* inside its square, not it */
    CHECK(!disk_intersect(&d, &flat, 0, INFINITY, &t));
    CHECK(!disk_intersect(&d, &front, 5, INFINITY, &t)); /* the interval is open */
    CHECK_INT(1, disk_crossings(&d, &front, 0, INFINITY));
    disk_uv(&d, vec3_add(d.centre, d.axis_u), d.normal, uv); /* the right edge, halfway up */
    CHECK_NEAR(1, uv[0], 1e-15);
    CHECK_NEAR(0.5, uv[1], 1e-15);
}

static void disk_far_away_keeps_its_edge(void)
{
    /* 1e8 from the origin, radius 1: a ray 1e-7 inside its rim hits, one
     * 1e-7 outside misses (the origin relative to the centre keeps the
     * digits the absolute coordinates would lose). */
    Disk d;
    Ray in = ray_from(1e8 + 1 - 1e-7, 5e7, 3, 0, 0, -1), out = ray_from(1e8 + 1 + 1e-7, 5e7, 3, 0, 0, -1);
    real t, lo[3], hi[3], m;

    CHECK_INT(0, disk_make(&d, vec3(1e8, 5e7, 0), vec3(0, 0, 1), 1, solid_plain()));
    CHECK(disk_intersect(&d, &in, 0, INFINITY, &t));
    CHECK_NEAR(3, t, 1e-12);
    CHECK(!disk_intersect(&d, &out, 0, INFINITY, &t));
    /* Its box: the rim's reach along each axis, flat along the normal. */
    m = disk_bounds(&d, 0, lo, hi);
    CHECK_NEAR(1e8 - 1, lo[0], 1e-7);
    CHECK_NEAR(1e8 + 1, hi[0], 1e-7);
    CHECK_NEAR(0, lo[2], 0);
    CHECK_NEAR(0, hi[2], 0);
    CHECK_NEAR(0, m, 0);
}

const TestCase disk_tests[] = {
    {"disk_hits_within_its_radius_on_both_sides", disk_hits_within_its_radius_on_both_sides},
    {"disk_far_away_keeps_its_edge", disk_far_away_keeps_its_edge},
    {NULL, NULL},
};
