/*
 * mapping.h: where a texture's image and the MPL ray tracer's stripes fall on each
 * shape: the texture coordinates of the scene's mapping (scene.h).
 *
 * SCENE_MAPPING_OURS is each shape's own (the *_uv() functions of the
 * geometry headers); SCENE_MAPPING_MPL, the MPL format's, is the MPL ray tracer's
 * program's, below. Both models of light (scene.h) lay textures by the
 * scene's mapping, so a file's texture falls where its format says.
 */
#ifndef RAYTRACE_MAPPING_H
#define RAYTRACE_MAPPING_H

#include <stddef.h>

#include "geometry/ray.h"
#include "scene/scene.h"

/*
 * Stores in uv the texture coordinates, by the MPL ray tracer's
 * conventions, of sp, a point of the shape of kind and index in scene (u
 * across the image, v up it, one image over [0, 1)), and in *stripe the coordinate its stripes alternate along: a stripe
 * of the colour where its fraction is below one half, a black one above.
 * Under the MPL model (scene.h) its program's rules hold whole; under
 * the physical model two of them are ours, as marked.
 *   sphere    u = 1 - (atan2(z, x) + pi) / 2 pi of the unit normal; v =
 *             (asin(y) + pi / 2) / pi = 1 - acos(y) / pi of the height y
 *             above the centre, not divided by the radius (a sphere of
 *             radius 0.6 shows the middle band of its image; beyond a
 *             height of 1, where the program's arcsine has no value, the
 *             top or bottom row); physical model: y of the unit normal,
 *             the whole image on any sphere; stripes 10 r u (30 r u below
 *             a radius of 1)
 *   cube      each face the whole image: (z, y) on the x faces, (x, z) on
 *             the y faces, (x, y) on the z faces, each (c / half + 1) / 2
 *             from the centre; stripes 10 u
 *   cylinder, cone  u = 1/2 - atan2(x, z) / 2 pi around the axis, v the
 *             height above the centre (the circle) modulo 1; stripes 10 u
 *   plane, square  u, v the fractions of x and y (of the world's on a
 *             plane, from the centre on a square), whatever way it faces:
 *             a floor's texture streaks towards the back, as the
 *             program drew it; physical model: the two coordinates
 *             along the surface, (x, y) when it faces z most, (x, z) when
 *             y, (z, y) when x; stripes u on planes, half / 10 u on a
 *             square of half-edge half
 *   triangle  the two coordinates along the surface, as a plane's under
 *             the physical model; stripes u
 * Coordinates are the scene file's (scene.h's length_exponent undone).
 * Returns 1 when v is the same over the whole surface (a floor under its
 * program's rules), to be read clamped (the one row its program read, not
 * the seam where the image repeats); else 0.
 */
int mapping_mpl(const Scene *scene, ShapeKind kind, size_t index, const SurfacePoint *sp,
                double uv[2], double *stripe);

/* Says whether the MPL ray tracer had a rule for shapes of kind (those it
 * drew); mapping_mpl() takes only those, the others keep their own. */
int mapping_mpl_covers(ShapeKind kind);

#endif
