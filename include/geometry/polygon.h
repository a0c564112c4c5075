/*
 * polygon.h: a face of more than three corners (a mesh file's polygon)
 * cut into the triangles that cover exactly it.
 *
 * The polygon is a closed loop of corners in space, about plane. It is
 * projected on the plane of the two axes its normal (Newell's: the sum of
 * its edges' cross products, which a concave or warped polygon still has)
 * leans on least, turned so that it runs anticlockwise there. A convex
 * polygon is cut as a fan from its first corner; any other by ear
 * clipping: a corner whose two neighbours make, with it, a triangle that
 * turns the polygon's way and holds no other corner is cut off, until
 * three are left. Concave faces keep their notches, and a ring written as
 * one face (its outer and inner loops joined by an edge gone along twice)
 * keeps its hole. Every triangle keeps the face's winding.
 *
 * A face that is not simple (edges crossing, all corners on a line, a
 * loop folded on itself) is still cut into n - 2 triangles, as well as the
 * rule allows: when no corner is an ear, the most convex one is cut off.
 * Triangles without area that this leaves are the mesh reader's to drop.
 */
#ifndef RAYTRACE_POLYGON_H
#define RAYTRACE_POLYGON_H

#include <stddef.h>

#include "math/vec3.h"

/* How a polygon was cut. */
typedef enum {
    POLYGON_FAN,      /* convex: a fan from its first corner */
    POLYGON_EARS,     /* simple and concave: by ear clipping */
    POLYGON_IRREGULAR /* not simple, or of more than POLYGON_CLIP_MAX
                         corners: as well as the rule allows */
} PolygonCut;

/* The most corners polygon_cut() looks at (ear clipping costs about the
 * square of their number); a larger polygon is fanned, and irregular. */
enum { POLYGON_CLIP_MAX = 16384 };

/* Returns the bytes of work room polygon_cut() needs for n corners (n at
 * most POLYGON_CLIP_MAX: a larger polygon needs none). */
size_t polygon_work_size(size_t n);

/* Cuts the polygon of n >= 3 corners p[0..n-1] into n - 2 triangles, each
 * three indices in p, written to tri (room for n - 2); work is room for
 * polygon_work_size(n) bytes (unused for n <= 4: may be NULL then).
 * Returns how it was cut. */
PolygonCut polygon_cut(const Vec3 *p, size_t n, unsigned (*tri)[3], void *work);

#endif
