/*
 * shape_list.h: the kinds of shape, in one list, and what every part of
 * the program asks of a shape of any kind, made from that list.
 *
 * SHAPE_LIST(X) calls X(KIND, Type, name, bounded, holds, clamp_v, mesh)
 * once for each kind:
 *   KIND     SHAPE_KIND is its ShapeKind
 *   Type     its struct, which has `unsigned order` (its position among
 *            the scene's objects, for ties)
 *   name     the prefix of its functions (shape.h lists them) and its
 *            records' word in the scene files
 *   bounded  1: it has a box, and the hierarchy holds it (accel/bvh.h);
 *            0: it is infinite, and every ray tests it
 *   holds    1: Type holds its Material as `material`; 0: the scene does
 *            (a sphere's, a triangle's: scene.h)
 *   clamp_v  1: its own texture coordinates span the image once up (a
 *            sphere's, pole to pole), read without repeating
 *   mesh     1: the triangle, whose surface is shaded by the scene's
 *            shading (vertex normals, texture coordinates and colours)
 * The order is ShapeKind's: the order of the scene's arrays, of the loops
 * over them and of the factors of a shadow ray's transmittance, so a new
 * kind goes last (renders of the others keep their bytes). A new kind
 * takes its own geometry/NAME.h and NAME.c (shape.h says what they give)
 * and one line here.
 */
#ifndef RAYTRACE_SHAPE_LIST_H
#define RAYTRACE_SHAPE_LIST_H

#include <stddef.h>

#include "geometry/cone.h"
#include "geometry/cube.h"
#include "geometry/cylinder.h"
#include "geometry/disk.h"
#include "geometry/plane.h"
#include "geometry/shape.h"
#include "geometry/sphere.h"
#include "geometry/square.h"
#include "geometry/torus.h"
#include "geometry/triangle.h"

#define SHAPE_LIST(X)                                                                          \
    X(SPHERE, Sphere, sphere, 1, 0, 1, 0)                                                      \
    X(PLANE, Plane, plane, 0, 1, 0, 0)                                                         \
    X(TRIANGLE, Triangle, triangle, 1, 0, 0, 1)                                                \
    X(CUBE, Cube, cube, 1, 1, 0, 0)                                                            \
    X(SQUARE, Square, square, 1, 1, 0, 0)                                                      \
    X(CYLINDER, Cylinder, cylinder, 0, 1, 0, 0)                                                \
    X(CONE, Cone, cone, 0, 1, 0, 0)                                                            \
    X(DISK, Disk, disk, 1, 1, 0, 0)                                                            \
    X(TORUS, Torus, torus, 1, 1, 0, 0)

#define SHAPE_ENUM(K, ...) SHAPE_##K,
typedef enum { SHAPE_LIST(SHAPE_ENUM) SHAPE_KINDS } ShapeKind;
#undef SHAPE_ENUM

/* SHAPE_IF(flag, ...) is what follows flag when flag is 1, nothing when it
 * is 0; SHAPE_UNLESS the other way round (flag a list's 0 or 1). */
#define SHAPE_IF(flag, ...) SHAPE_IF_##flag(__VA_ARGS__)
#define SHAPE_IF_0(...)
#define SHAPE_IF_1(...) __VA_ARGS__
#define SHAPE_UNLESS(flag, ...) SHAPE_UNLESS_##flag(__VA_ARGS__)
#define SHAPE_UNLESS_0(...) __VA_ARGS__
#define SHAPE_UNLESS_1(...)

/* The kinds whose flag (bounded, holds, clamp_v) is 1, as a mask of bits
 * 1 << kind. */
#define SHAPE_BIT_BOUNDED(K, T, n, bounded, holds, clamp_v, mesh) | (bounded##u << SHAPE_##K)
#define SHAPE_BIT_HOLDS(K, T, n, bounded, holds, clamp_v, mesh) | (holds##u << SHAPE_##K)
#define SHAPE_BIT_CLAMPS(K, T, n, bounded, holds, clamp_v, mesh) | (clamp_v##u << SHAPE_##K)
#define SHAPE_BOUNDED (0u SHAPE_LIST(SHAPE_BIT_BOUNDED))
#define SHAPE_HOLDS (0u SHAPE_LIST(SHAPE_BIT_HOLDS))
#define SHAPE_CLAMPS_V (0u SHAPE_LIST(SHAPE_BIT_CLAMPS))

/* Room for one shape of any kind. */
#define SHAPE_MEMBER(K, T, name, ...) T name;
typedef union {
    SHAPE_LIST(SHAPE_MEMBER)
} ShapeAny;
#undef SHAPE_MEMBER

/* Each kind's record (shape.h) and word ("sphere", "cone", ...), by kind. */
extern const ShapeRecord *const shape_records[SHAPE_KINDS];
extern const char *const shape_words[SHAPE_KINDS];

/* Returns the bytes of a shape of kind. */
static inline size_t shape_size(ShapeKind kind)
{
#define SHAPE_SIZE(K, T, ...) sizeof(T),
    static const size_t size[SHAPE_KINDS] = {SHAPE_LIST(SHAPE_SIZE)};
#undef SHAPE_SIZE
    return size[kind];
}

/* Returns where a shape of kind holds its order. */
static inline size_t shape_order_offset(ShapeKind kind)
{
#define SHAPE_OFFSET(K, T, ...) offsetof(T, order),
    static const size_t offset[SHAPE_KINDS] = {SHAPE_LIST(SHAPE_OFFSET)};
#undef SHAPE_OFFSET
    return offset[kind];
}

/* Returns where a shape of kind holds its material (holds), or -1. */
static inline long shape_material_offset(ShapeKind kind)
{
#define SHAPE_OFFSET(K, T, n, bounded, holds, ...)                                             \
    SHAPE_IF(holds, (long)offsetof(T, material)) SHAPE_UNLESS(holds, -1),
    static const long offset[SHAPE_KINDS] = {SHAPE_LIST(SHAPE_OFFSET)};
#undef SHAPE_OFFSET
    return offset[kind];
}

/* Shape i of kind among items, an array of them. */
#define SHAPE_ITEM(T, items, i) (&((const T *)(items))[i])

/* Returns the position among the scene's objects of shape i of kind. */
static inline unsigned shape_order(ShapeKind kind, const void *items, size_t i)
{
    switch (kind) {
#define SHAPE_CASE(K, T, ...)                                                                  \
    case SHAPE_##K:                                                                            \
        return SHAPE_ITEM(T, items, i)->order;
        SHAPE_LIST(SHAPE_CASE)
#undef SHAPE_CASE
    default:
        return 0;
    }
}

/* NAME_intersect() of shape i of kind among items. */
static inline int shape_intersect(ShapeKind kind, const void *items, size_t i, const Ray *ray,
                                  real tmin, real tmax, real *t)
{
    switch (kind) {
#define SHAPE_CASE(K, T, name, ...)                                                            \
    case SHAPE_##K:                                                                            \
        return name##_intersect(SHAPE_ITEM(T, items, i), ray, tmin, tmax, t);
        SHAPE_LIST(SHAPE_CASE)
#undef SHAPE_CASE
    default:
        return 0;
    }
}

/* NAME_crossings() of shape i of kind among items. */
static inline int shape_crossings(ShapeKind kind, const void *items, size_t i, const Ray *ray,
                                  real tmin, real tmax)
{
    switch (kind) {
#define SHAPE_CASE(K, T, name, ...)                                                            \
    case SHAPE_##K:                                                                            \
        return name##_crossings(SHAPE_ITEM(T, items, i), ray, tmin, tmax);
        SHAPE_LIST(SHAPE_CASE)
#undef SHAPE_CASE
    default:
        return 0;
    }
}

/* NAME_bounds() of shape i of kind among items, a bounded kind; an
 * unbounded one's box is all of space. */
static inline real shape_bounds(ShapeKind kind, const void *items, size_t i, real ulps,
                                real lo[3], real hi[3])
{
    switch (kind) {
#define SHAPE_CASE(K, T, name, bounded, ...)                                                   \
    SHAPE_IF(bounded, case SHAPE_##K:                                                          \
             return name##_bounds(SHAPE_ITEM(T, items, i), ulps, lo, hi);)
        SHAPE_LIST(SHAPE_CASE)
#undef SHAPE_CASE
    default:
        for (int a = 0; a < 3; a++) {
            lo[a] = -INFINITY;
            hi[a] = INFINITY;
        }
        return 0;
    }
}

/* NAME_box() of shape i of kind among items. */
static inline void shape_box(ShapeKind kind, const void *items, size_t i, Vec3 *lo, Vec3 *hi)
{
    switch (kind) {
#define SHAPE_CASE(K, T, name, ...)                                                            \
    case SHAPE_##K:                                                                            \
        name##_box(SHAPE_ITEM(T, items, i), lo, hi);                                           \
        break;
        SHAPE_LIST(SHAPE_CASE)
#undef SHAPE_CASE
    default:
        break;
    }
}

/* NAME_extent() of shape i of kind among items. */
static inline double shape_extent(ShapeKind kind, const void *items, size_t i)
{
    switch (kind) {
#define SHAPE_CASE(K, T, name, ...)                                                            \
    case SHAPE_##K:                                                                            \
        return name##_extent(SHAPE_ITEM(T, items, i));
        SHAPE_LIST(SHAPE_CASE)
#undef SHAPE_CASE
    default:
        return 0;
    }
}

/* NAME_scale() of shape i of kind among items (writable). */
static inline void shape_scale(ShapeKind kind, void *items, size_t i, int k)
{
    switch (kind) {
#define SHAPE_CASE(K, T, name, ...)                                                            \
    case SHAPE_##K:                                                                            \
        name##_scale(&((T *)items)[i], k);                                                     \
        break;
        SHAPE_LIST(SHAPE_CASE)
#undef SHAPE_CASE
    default:
        break;
    }
}

/* NAME_surface() of shape i of kind among items, not a mesh's triangle;
 * stores its own texture coordinates in uv unless uv is NULL. */
static inline SurfacePoint shape_surface(ShapeKind kind, const void *items, size_t i,
                                         const Ray *ray, real t, double *uv)
{
    SurfacePoint sp = {{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 0}};

    switch (kind) {
#define SHAPE_CASE(K, T, name, bounded, holds, clamp_v, mesh)                                  \
    SHAPE_UNLESS(mesh, case SHAPE_##K:                                                         \
                 sp = name##_surface(SHAPE_ITEM(T, items, i), ray, t);                         \
                 if (uv) name##_uv(SHAPE_ITEM(T, items, i), sp.point, sp.normal, uv);          \
                 break;)
        SHAPE_LIST(SHAPE_CASE)
#undef SHAPE_CASE
    default:
        break;
    }
    return sp;
}

/* NAME_surface_near() of shape i of kind among items, not a mesh's
 * triangle, for the point p near hit; stores its own texture coordinates
 * at p in uv unless uv is NULL. */
static inline SurfacePoint shape_surface_near(ShapeKind kind, const void *items, size_t i,
                                              const SurfacePoint *hit, Vec3 p, double *uv)
{
    SurfacePoint sp = *hit;

    switch (kind) {
#define SHAPE_CASE(K, T, name, bounded, holds, clamp_v, mesh)                                  \
    SHAPE_UNLESS(mesh, case SHAPE_##K:                                                         \
                 sp = name##_surface_near(SHAPE_ITEM(T, items, i), hit, p);                    \
                 if (uv) name##_uv(SHAPE_ITEM(T, items, i), p, sp.normal, uv);                 \
                 break;)
        SHAPE_LIST(SHAPE_CASE)
#undef SHAPE_CASE
    default:
        break;
    }
    return sp;
}

#endif
