/*
 * bvh_query.h: the two builds of bvh_query.c, private to it.
 *
 * bvh_query.c is compiled once for every processor of the architecture
 * (its functions end in _base) and, on x86, once more for processors with
 * AVX2 and FMA (_avx2: the Makefile then defines RAYTRACE_AVX2). The two
 * builds test boxes differently (docs/design.md) and find the same hits;
 * the base build also answers bvh.h's queries, each with the build
 * Bvh.avx2 names.
 */
#ifndef RAYTRACE_BVH_QUERY_H
#define RAYTRACE_BVH_QUERY_H

#include "accel/bvh.h"

/* Traversal stack: a node visit pops one entry and pushes at most
 * BVH_WIDTH, and nodes are at most BVH_DEPTH_MAX deep. */
enum { BVH_STACK = (BVH_WIDTH - 1) * BVH_DEPTH_MAX + BVH_WIDTH };

/* bvh.h's queries, as each build of bvh_query.c answers them. */
int bvh_nearest_base(const Bvh *bvh, const Ray *ray, real tmax, BvhHit *hit);
int bvh_occluder_base(const Bvh *bvh, const Ray *ray, real tmax, uint32_t *slot);
int bvh_crossings_base(const Bvh *bvh, const Ray *ray, real tmax, BvhVisit visit, void *ctx);
int bvh_nearest_avx2(const Bvh *bvh, const Ray *ray, real tmax, BvhHit *hit);
int bvh_occluder_avx2(const Bvh *bvh, const Ray *ray, real tmax, uint32_t *slot);
int bvh_crossings_avx2(const Bvh *bvh, const Ray *ray, real tmax, BvhVisit visit, void *ctx);

#endif
