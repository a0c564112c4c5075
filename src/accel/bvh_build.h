/*
 * bvh_build.h: what the steps of building the hierarchy share, private to
 * them: bvh_build.c (the boxes, the frame and the steps in order), bvh_sah.c
 * (the binary tree, by the surface area heuristic) and bvh_collapse.c (its
 * nodes gathered into the wide nodes of bvh.h).
 */
#ifndef RAYTRACE_BVH_BUILD_H
#define RAYTRACE_BVH_BUILD_H

#include <math.h>
#include <stdint.h>

#include "accel/bvh.h"

enum {
    BVH_TASK_MIN = 16384 /* fewer primitives: built by the thread at hand */
};

/* A box, as lo and hi corners. */
typedef struct {
    real lo[3], hi[3];
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

static inline void box_grow_point(Box *b, const real p[3])
{
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        b->lo[a] = p[a] < b->lo[a] ? p[a] : b->lo[a];
        b->hi[a] = p[a] > b->hi[a] ? p[a] : b->hi[a];
    }
}

/* Half the surface area of b (0 for an empty box). */
static inline real box_half_area(const Box *b)
{
    real dx = b->hi[0] - b->lo[0], dy = b->hi[1] - b->lo[1], dz = b->hi[2] - b->lo[2];
    return dx < 0 ? 0 : dx * dy + dy * dz + dz * dx;
}

/* What the build needs of each primitive. */
typedef struct {
    Box box;         /* padded bounds */
    uint32_t ref;    /* primitive reference */
} BuildPrim;

/* A node of the binary tree the build makes first. Its box is not kept:
 * the wide nodes' boxes are gathered again from the leaves up. */
typedef struct {
    uint32_t index;  /* interior: the right child (the left is the next
                        node); leaf: the first of its primitives */
    uint32_t count;  /* primitives in a leaf; 0 for an interior node */
    uint32_t size;   /* primitives in its subtree */
} BuildNode;

/* Returns coordinate axis of the centre of p's box, its centroid. */
static inline real bvh_centroid(const BuildPrim *p, int axis)
{
    return 0.5 * p->box.lo[axis] + 0.5 * p->box.hi[axis];
}

/* A piece of work: build the subtree of prims[start..end) at depth, its
 * root at node. A subtree of m primitives takes nodes node .. node + 2m - 2
 * (fewer when leaves hold several): its left child is node + 1, its right
 * node + 2 m_left, so the tree is the same whichever thread builds what. */
typedef struct {
    size_t start, end;
    int depth;
    size_t node;
} BuildTask;

/* Stores in *p the box of primitive ref of shapes, padded by pad. */
void bvh_prim_box(const BvhShapes *shapes, uint32_t ref, real pad, BuildPrim *p);

/* Builds the binary subtree of task into nodes (see BuildTask), reordering
 * prims[task.start..task.end) by leaf; in an OpenMP parallel region, right
 * subtrees of BVH_TASK_MIN primitives or more become tasks (bvh_sah.c). */
void bvh_build_subtree(BuildPrim *prims, BuildNode *nodes, BuildTask root);

/* Moves the binary tree's nodes to the front of nodes in depth-first
 * order, closing the gaps the fixed offsets leave; returns how many there
 * are (bvh_sah.c). */
size_t bvh_compact(BuildNode *nodes);

/* Returns how many wide nodes collapsing binary node id's subtree makes
 * (bvh_collapse.c). */
size_t bvh_collapsed_count(const BuildNode *nodes, uint32_t id);

/* Writes the wide node made from binary node id, and its subtree's, into
 * bvh->nodes from self on; stores their bounds in *bounds and the depth of
 * the deepest in *deepest; returns how many it wrote (bvh_collapse.c). */
size_t bvh_collapse(const BuildNode *nodes, uint32_t id, size_t self, int depth, real pad,
                    Bvh *bvh, Box *bounds, int *deepest);

#endif
