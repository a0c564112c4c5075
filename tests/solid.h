/*
 * solid.h: what the tests of the solid shapes share (test_cube.c,
 * test_square.c, test_cylinder.c, test_cone.c, test_ray.c): a plain grey
 * material and a ray from six numbers.
 */
#ifndef RAYTRACE_TEST_SOLID_H
#define RAYTRACE_TEST_SOLID_H

#include "geometry/material.h"
#include "geometry/ray.h"

/* A plain grey material, no mirror, no texture. */
static inline Material solid_plain(void)
{
    Material m = {{200, 200, 200}, 0, 0, 1, -1, TEXTURE_NEAREST, -1, 0};
    return m;
}

/* The ray from (ox, oy, oz) along (dx, dy, dz), as given (not made unit). */
static inline Ray ray_from(double ox, double oy, double oz, double dx, double dy, double dz)
{
    Ray r = {{ox, oy, oz}, {dx, dy, dz}};
    return r;
}

#endif
