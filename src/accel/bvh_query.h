/*
 * bvh_query.h: what bvh.c, which builds the hierarchy, shares with
 * bvh_query.c, which answers bvh.h's queries.
 *
 * bvh_query.c is compiled once for every processor of the architecture
 * (its functions end in _base) and, on x86, once more for processors with
 * AVX2 and FMA (_avx2: the Makefile then defines RAYTRACE_AVX2). The two
 * builds test boxes differently (docs/design.md) and find the same hits;
 * bvh.c answers each query with the one Bvh.avx2 names.
 */
#ifndef RAYTRACE_BVH_QUERY_H
#define RAYTRACE_BVH_QUERY_H

#include <math.h>

#include "accel/bvh.h"

enum {
    BVH_SAH_DEPTH = 48, /* below this depth, splits halve the count */
    BVH_DEPTH_MAX = BVH_SAH_DEPTH + 32, /* deepest binary node: from
                                           BVH_SAH_DEPTH on, splits halve
                                           fewer than 2^32 primitives */
    /* Traversal stack: a node visit pops one entry and pushes at most
     * BVH_WIDTH, and nodes are at most BVH_DEPTH_MAX deep. */
    BVH_STACK = (BVH_WIDTH - 1) * BVH_DEPTH_MAX + BVH_WIDTH
};

/* Returns x's margin, for x a finite double: x - m and x + m rounded to
 * floats are below and above x by half a float unit or more (m is two float
 * units of x, or a subnormal float's), and so are below and above the value
 * x approximates to a double's precision. */
static inline double bvh_margin(double x)
{
    return fabs(x) * 0x1p-22 + 0x1p-149;
}

/* Returns a float below x, a double, by half a float unit or more;
 * infinities stay. */
static inline float bvh_float_below(double x)
{
    return isinf(x) ? (float)x : (float)(x - bvh_margin(x));
}

/* Returns a float above x by half a float unit or more; infinities stay. */
static inline float bvh_float_above(double x)
{
    return isinf(x) ? (float)x : (float)(x + bvh_margin(x));
}

/* bvh.h's queries, as each build of bvh_query.c answers them. */
int bvh_nearest_base(const Bvh *bvh, const Ray *ray, real tmax, BvhHit *hit);
int bvh_occluded_base(const Bvh *bvh, const Ray *ray, real tmax);
int bvh_crossings_base(const Bvh *bvh, const Ray *ray, real tmax, BvhVisit visit, void *ctx);
int bvh_nearest_avx2(const Bvh *bvh, const Ray *ray, real tmax, BvhHit *hit);
int bvh_occluded_avx2(const Bvh *bvh, const Ray *ray, real tmax);
int bvh_crossings_avx2(const Bvh *bvh, const Ray *ray, real tmax, BvhVisit visit, void *ctx);

#endif
