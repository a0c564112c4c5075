/*
 * mapping.h: where a texture's image and seed 001's stripes fall on each
 * shape: the texture coordinates of the scene's mapping (scene.h).
 *
 * SCENE_MAPPING_OURS is each shape's own (the *_uv() functions of the
 * geometry headers); SCENE_MAPPING_SEED001, the MPL format's, is seed 001's
 * program's, below. Both models of light (scene.h) lay textures by the
 * scene's mapping, so a file's texture falls where its format says.
 */
#ifndef RAYTRACE_MAPPING_H
#define RAYTRACE_MAPPING_H

#include <stddef.h>

#include "geometry/ray.h"
#include "scene/scene.h"

/*
 * Stores in uv the texture coordinates, by seed 001's program's
 * conventions, of sp, a point of the shape of kind and index in scene (u
 * across the image, v up it, one image over [0, 1)), and in *stripe the coordinate its stripes alternate along: a stripe
 * of the colour where its fraction is below one half, a black one above.
 *   sphere    u = 1 - (atan2(z, x) + pi) / 2 pi, v = 1 - acos(y) / pi of the
 *             unit normal; stripes 10 r u (30 r u below a radius of 1)
 *   cube      each face the whole image: (z, y) on the x faces, (x, z) on
 *             the y faces, (x, y) on the z faces, each (c / half + 1) / 2
 *             from the centre; stripes 10 u
 *   cylinder, cone  u = 1/2 - atan2(x, z) / 2 pi around the axis, v the
 *             height above the centre (the circle) modulo 1; stripes 10 u
 *   plane, triangle, square  u, v the fractions of the two world
 *             coordinates along the surface: (x, y) when it faces z
 *             most, (x, z) when y, (z, y) when x (the program always took
 *             (x, y), which smears a texture on a floor into its bottom
 *             row); stripes u on planes and triangles, half / 10 u on a
 *             square of half-edge half
 * Coordinates are the scene file's (scene.h's length_exponent undone).
 */
void mapping_seed001(const Scene *scene, ShapeKind kind, size_t index, const SurfacePoint *sp,
                     double uv[2], double *stripe);

#endif
