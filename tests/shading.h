/*
 * shading.h: a triangle's texture coordinates and vertex normals as the
 * tests read them, whether the scene keeps them or the triangle is plain.
 */
#ifndef RAYTRACE_TEST_SHADING_H
#define RAYTRACE_TEST_SHADING_H

#include "scene/scene.h"

/* Returns triangle i's shading in sc, a plain one's made up. */
static inline TriangleShading shading_of(const Scene *sc, size_t i)
{
    const TriangleShading *sh = scene_shading_of(sc, &scene_triangles(sc)[i]);

    return sh ? *sh : triangle_plain_shading(&scene_triangles(sc)[i]);
}

#endif
