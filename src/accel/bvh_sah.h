/*
 * bvh_sah.h: the hierarchy's binary tree, split by the surface area
 * heuristic (bvh_sah.c), private to the build.
 */
#ifndef RAYTRACE_BVH_SAH_H
#define RAYTRACE_BVH_SAH_H

#include <stddef.h>

#include "bvh_box.h"

/* A piece of work: build the subtree of prims[start..end) at depth, its
 * root at node. A subtree of m primitives takes nodes node .. node + 2m - 2
 * (fewer when leaves hold several): its left child is node + 1, its right
 * node + 2 m_left, so the tree is the same whichever thread builds what. */
typedef struct {
    size_t start, end;
    int depth;
    size_t node;
} BuildTask;

/* Builds the binary subtree of task into nodes (see BuildTask), reordering
 * prims[task.start..task.end) by leaf; in an OpenMP parallel region, right
 * subtrees of BVH_TASK_MIN primitives or more become tasks. */
void bvh_build_subtree(BuildPrim *prims, BuildNode *nodes, BuildTask root);

#endif
