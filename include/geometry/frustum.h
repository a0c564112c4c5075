/*
 * frustum.h: the rays that leave one point, the apex, through a flat convex
 * quadrilateral (a pyramid of four side planes), and the spheres none of
 * them can meet.
 *
 * The proof holds for the rays as computed, not only as exact: each corner
 * of the quadrilateral, and each point a ray is aimed at, may be off by an
 * error the caller bounds; the margin also covers the rounding of the ray's
 * direction to real and of sphere_hit()'s test.
 */
#ifndef RAYTRACE_FRUSTUM_H
#define RAYTRACE_FRUSTUM_H

#include "math/vec3.h"

typedef struct {
    Vec3 apex;      /* where every ray starts */
    Vec3 normal[4]; /* the side planes' unit normals, pointing inwards */
    real slack;     /* the angle, radians, by which a ray may stray out */
} Frustum;

/* Makes f the pyramid from apex through the quadrilateral of corners, in
 * order around it, each corner and each point a ray is aimed at within err
 * of exact in every coordinate; returns 0, or -1 when the margin that
 * covers those errors is not small (the apex near the quadrilateral's
 * plane, an edge too short for its error): then f proves nothing. */
int frustum_make(Frustum *f, Vec3 apex, const Vec3 corner[4], real err);

/* Says whether no ray of f can meet the sphere of centre and radius:
 * 1 when proven, 0 when one may. */
int frustum_misses_sphere(const Frustum *f, Vec3 centre, real radius);

/* Says whether no ray of f can meet a point of the box [lo, hi] (lo <= hi
 * in every coordinate): 1 when proven, 0 when one may. */
int frustum_misses_box(const Frustum *f, Vec3 lo, Vec3 hi);

#endif
