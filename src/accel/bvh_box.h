/*
 * bvh_box.h: the boxes the hierarchy's build works with, private to it:
 * each primitive's padded box (bvh_box.c, the padding rule in one place),
 * and the box helpers bvh_sah.c and bvh_collapse.c share.
 */
#ifndef RAYTRACE_BVH_BOX_H
#define RAYTRACE_BVH_BOX_H

#include <math.h>
#include <stdint.h>

#include "accel/bvh.h"

enum {
    BVH_TASK_MIN = 16384 /* fewer primitives: built by the thread at hand */
};

/* A box, as lo and hi corners, in the hierarchy's frame (bvh.h: scene
 * coordinates less centre, times scale) and in floats, as its nodes hold
 * them: the build holds half the bytes doubles would take. */
typedef struct {
    float lo[3], hi[3];
} Box;

/* The box helpers' loops are unrolled: they run per primitive and bin. */
static inline void box_empty(Box *b)
{
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        b->lo[a] = INFINITY;
        b->hi[a] = -INFINITY;
    }
}

/* Boxes never hold NaN (they come from finite coordinates), so plain
 * comparisons do what fmin() and fmax() would, without a call. */
static inline void box_grow(Box *b, const Box *c)
{
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        b->lo[a] = c->lo[a] < b->lo[a] ? c->lo[a] : b->lo[a];
        b->hi[a] = c->hi[a] > b->hi[a] ? c->hi[a] : b->hi[a];
    }
}

static inline void box_grow_point(Box *b, const float p[3])
{
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        b->lo[a] = p[a] < b->lo[a] ? p[a] : b->lo[a];
        b->hi[a] = p[a] > b->hi[a] ? p[a] : b->hi[a];
    }
}

/* Half the surface area of b (0 for an empty box). */
static inline float box_half_area(const Box *b)
{
    float dx = b->hi[0] - b->lo[0], dy = b->hi[1] - b->lo[1], dz = b->hi[2] - b->lo[2];
    return dx < 0 ? 0 : dx * dy + dy * dz + dz * dx;
}

/* What the build needs of each primitive: 28 bytes. */
typedef struct {
    Box box;         /* padded bounds, rounded outwards (bvh_prim_box()) */
    uint32_t ref;    /* primitive reference */
} BuildPrim;

/* A node of the binary tree the build makes first. Its box is not kept:
 * the wide nodes' boxes are gathered again from the leaves up. */
typedef struct {
    uint32_t index;  /* interior: the right child (the left is the next
                        node); leaf: the first of its primitives */
    uint32_t count;  /* primitives in a leaf; 0 for an interior node, until
                        bvh_plan() stores its plan there */
    uint32_t size;   /* primitives in its subtree (after bvh_plan(), for
                        a node of BVH_TASK_MIN or more, the wide nodes it
                        makes) */
} BuildNode;

/* Returns coordinate axis of the centre of p's box, its centroid. */
static inline float bvh_centroid(const BuildPrim *p, int axis)
{
    return 0.5f * p->box.lo[axis] + 0.5f * p->box.hi[axis];
}

/* Returns the padding of every box for shapes and the reach bvh_build()
 * is given: the largest coordinate of any of them times a few thousand
 * units of the real type's precision. */
real bvh_padding(const BvhShapes *shapes, real reach, int threads);

/* Stores in lo and hi the corners of the box of primitive ref of shapes,
 * padded by pad, in scene coordinates. */
void bvh_prim_bounds(const BvhShapes *shapes, uint32_t ref, real pad, real lo[3], real hi[3]);

/* Asks memory for what bvh_prim_bounds() reads of primitive ref of shapes,
 * without waiting for it. */
void bvh_prim_prefetch(const BvhShapes *shapes, uint32_t ref);

/* Stores in *p primitive ref of bvh's shapes and its box padded by pad
 * (bvh_prim_bounds()), in bvh's frame, rounded outwards to floats
 * (bvh_float_below() and bvh_float_above()). */
void bvh_prim_box(const Bvh *bvh, uint32_t ref, real pad, BuildPrim *p);

#endif
