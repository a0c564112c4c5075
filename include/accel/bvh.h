/*
 * bvh.h: a bounding volume hierarchy over a scene's spheres and triangles,
 * built with the surface area heuristic on binned centroids.
 *
 * Planes are unbounded and stay outside it. The binary tree the heuristic
 * builds is then collapsed into nodes of BVH_WIDTH children, whose boxes a
 * ray is tested against together (GNU C vector extensions: gcc and clang
 * turn them into SIMD instructions). Each box is padded so that every ray
 * the exact primitive tests accept also enters the boxes around the
 * primitive; a query visits the boxes the ray crosses, nearest first, and
 * applies the same primitive tests and the same tie rule as a loop over
 * every object, so renders are the same to the byte with or without it.
 */
#ifndef RAYTRACE_BVH_H
#define RAYTRACE_BVH_H

#include <stddef.h>
#include <stdint.h>

#include "geometry/ray.h"

struct Scene;

enum {
    BVH_WIDTH = 8,           /* children of a node */
    BVH_LEAF_MAX = 4,        /* most primitives in a leaf */
    BVH_MIN_PRIMITIVES = 16  /* scenes with fewer are not worth a hierarchy */
};

/* A primitive reference: BVH_TRIANGLE set for a triangle, the index below. */
#define BVH_TRIANGLE 0x80000000u

/* A node: up to BVH_WIDTH children, each a node or a leaf (a run of
 * primitive references), their boxes laid out by coordinate so that one
 * vector holds a coordinate of every child's box. The boxes are floats in
 * the hierarchy's frame (centre and scale below), rounded outwards, so
 * that they hold the scene's boxes; 256 bytes, four cache lines. An unused
 * child has the box lo = +inf, hi = -inf, which no ray meets. */
typedef struct {
    _Alignas(64) float box[6][BVH_WIDTH]; /* box[c][k]: child k's lo x y z
                                             (c < 3), then hi x y z */
    uint32_t child[BVH_WIDTH];   /* a node's index, or a leaf's first
                                    primitive reference */
    uint8_t count[BVH_WIDTH];    /* a leaf's primitives; 0: a node (or an
                                    unused child) */
} BvhNode;

typedef struct Bvh {
    BvhNode *nodes;      /* the root first */
    size_t node_count;
    uint32_t *prims;     /* primitive references, grouped by leaf */
    real (*balls)[4];    /* balls[k]: when prims[k] is a sphere, its centre
                            x y z and radius, copied so that queries read
                            them in leaf order; NULL without spheres */
    size_t prim_count;
    int depth;           /* deepest node, the root at 0 */
    double centre[3];    /* the frame: a node's box coordinate is that of */
    double scale;        /* the scene less centre, times scale (a power of
                            two that brings the scene within +-4) */
    int avx2;            /* queries run their AVX2 and FMA build
                            (bvh_query.h): bvh_build() sets it when the
                            processor has them; 0 runs the other */
} Bvh;

/* Builds the hierarchy of scene's spheres and triangles into *bvh in
 * O(n log n), with up to threads threads (in OpenMP builds; the hierarchy
 * is the same whatever their number); returns 0, or -1 (nothing allocated)
 * when memory runs out or the scene holds 2^31 objects of a kind or of
 * both. */
int bvh_build(Bvh *bvh, const struct Scene *scene, int threads);

/* Releases what *bvh owns. */
void bvh_free(Bvh *bvh);

/* Returns the most bytes bvh_build() allocates at once for n primitives. */
size_t bvh_build_memory(size_t n);

/* Returns the bytes *bvh holds. */
size_t bvh_memory(const Bvh *bvh);

/* The nearest crossing a query found. */
typedef struct {
    real t;       /* ray parameter */
    uint32_t prim;  /* primitive reference */
    unsigned order; /* the object's position among all objects */
} BvhHit;

/* Finds the sphere or triangle the ray crosses first at 0 < t < tmax (the
 * earliest-listed on an exact tie); returns 1 with *hit set, or 0. */
int bvh_nearest(const Bvh *bvh, const struct Scene *scene, const Ray *ray, real tmax,
                BvhHit *hit);

/* Returns 1 when some sphere or triangle crosses the ray at 0 < t < tmax
 * (tmax = 1: the segment from ray->origin to ray->origin + ray->dir), else 0. */
int bvh_occluded(const Bvh *bvh, const struct Scene *scene, const Ray *ray, real tmax);

/* A surface crossed by a shadow ray, and how many times. */
typedef struct {
    uint32_t prim;  /* primitive reference */
    int crossings;  /* 1 or 2 */
} BvhCrossing;

/* Lists in out (room for max) the spheres and triangles the ray crosses at
 * 0 < t < tmax, sorted spheres first, each kind by index; returns
 * how many, -1 when more than max, or -2 as soon as an opaque one (T = 0) is
 * crossed. */
int bvh_crossings(const Bvh *bvh, const struct Scene *scene, const Ray *ray, real tmax,
                  BvhCrossing *out, int max);

#endif
